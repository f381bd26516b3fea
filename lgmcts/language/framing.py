"""One clause read into pending goals: its frame (references, stack roles, place, size and facing words, the
words between references), the readings of :mod:`.readings` tried on it, relations with their anchor,
exceptions said apart from their set and "so that" (:class:`_Framing`, mixed into :class:`.rules._Parser`).
"""

from __future__ import annotations

import re
from typing import TYPE_CHECKING, cast

from . import stages
from ..errors import InputError
from .assembly import _Pending
from .clauses import _DIR_WORDS, _LEADING, _VERT_WORDS, _groups, _is_number, _on_pairs_split, _stacking, _weak_split
from .grounding import Choice, Mention, NUMBERS
from .matcher import FILLERS, STOPWORDS
from .selection import _COMPASS_LEFT, _FACING_CUES
from .shapes import SIZES, stack_roles, take_params

#: Words of a place or size that a clause may say with no arrangement word ("put the bowl on the plate, dead
#: centre"): their clause's parameters are read (never left unread).
_PLACE_OR_SIZE = frozenset({"centre", "center", "corner"}) | frozenset(SIZES)


if TYPE_CHECKING:
    from .host import ParserHost
else:
    ParserHost = object

if TYPE_CHECKING:
    from .readings import Frame
    from .rules import _Parser


_INVERSE = {"left": "right", "right": "left", "front": "behind", "behind": "front", "left_front": "right_behind",
            "right_behind": "left_front", "left_behind": "right_front", "right_front": "left_behind"}


#: Size adjectives that, right before an object reference, would pick objects by size.
_OBJECT_SIZE_WORDS = frozenset({"big", "bigger", "large", "larger", "small", "smaller", "little", "tiny", "huge",
                                "tall", "taller", "short", "shorter", "long", "wide", "giant", "mini", "medium"})


#: Where a stack role phrase stood once it has been read.
_ROLE_MARK = "|"


class _Framing(ParserHost):
    """Reading one clause: frame, readings, relations."""

    def _roles(self, words: tuple[str, ...], mentions: list[Mention]):
        """Stack roles right after mentions ("the blue block as the base"); words without them.

        Read only in a clause about stacking (a tower word, a tower named
        before, or two role phrases): elsewhere "in the middle" is a place.
        """
        roles: dict[int, str] = {}
        drop: set[int] = set()
        spans: dict[int, range] = {}
        for m in mentions:
            if m.start in drop:
                continue
            got = stack_roles(words, m.end)
            if got is None:
                continue
            role, end = got
            if role == "next" and any(m2.start == end and m2.det != "pronoun" for m2 in mentions):
                continue  # "the purple one goes above the red one": a pair, not a step on the stack before
            roles[m.start] = role
            spans[m.start] = range(m.end, end)
            drop.update(spans[m.start])
        if roles and all(r == "next_it" for r in roles.values()) and self.state.tower is None:
            # "stack the green block on it": a stacking step, not a role among others.
            return None, words
        # "(put the green block down first,) then the purple one on it, and the red one on
        # top": "it" is what the clause before named, below the first object here.
        self._below_first = (roles.get(mentions[0].start) == "next_it" and bool(self.state.last)
                             and all(isinstance(x, int) for x in self.state.last)) if mentions else False
        for k, r in roles.items():
            if r == "next_it":
                roles[k] = "next"  # "with the red block at the base and the yellow block above it"
        if not drop:
            return None, words
        towerish = any(_stacking(w) for w in words) or len(roles) >= 2 \
            or (self.state.header is not None and self.state.header[0] == "tower") or self.state.tower is not None
        if not towerish:
            return None, words
        # Each role phrase leaves a mark, so that the references around it do
        # not run together ("purple as the base and orange on top").
        out: list[str] = []
        new_pos: dict[int, int] = {}
        for k, w in enumerate(words):
            if k in drop:
                if k - 1 not in drop:
                    out.append(_ROLE_MARK)
                continue
            new_pos[k] = len(out)
            out.append(w)
        return {new_pos[s]: r for s, r in roles.items()}, tuple(out)

    _DETACHED_EXCEPT = (("except", "for"), ("except",), ("excluding",), ("apart", "from"), ("other", "than"),
                        ("but", "not"), ("save", "for"), ("leaving", "out"), ("minus",))

    def _detached_exception(self, words: tuple[str, ...], mentions: list[Mention]) -> tuple[str, ...] | None:
        """"put the red things in a line except the block": the exception moved next to its set."""
        trailing = self._trailing_not(words, mentions)
        if trailing is not None:
            return trailing
        for k in range(1, len(mentions)):
            m2, m1 = mentions[k], mentions[k - 1]
            seq = next((q for q in self._DETACHED_EXCEPT if words[m2.start - len(q) : m2.start] == q), None)
            if seq is None or m1.end >= m2.start - len(seq) or not m1.plural:
                continue
            if any(w not in (",", ".", "!", "?", "please") for w in words[m2.end :]):
                continue  # "... except for the red can which goes behind the plate": not a bare exception
            try:
                from .grounding import candidates as _cands

                inner = set(_cands(self.vocab, m2)) & set(_cands(self.vocab, m1))
            except InputError:
                continue
            if not inner:
                continue
            lo = m2.start - len(seq)
            block = words[lo : m2.end]
            rest = words[: m1.end] + block + words[m1.end : lo] + words[m2.end :]
            return tuple(rest)
        return None

    def _trailing_not(self, words: tuple[str, ...], mentions: list[Mention]) -> tuple[str, ...] | None:
        """"put the blocks in a circle, not the purple one": a reference after ", not" at the end of
        a clause leaves its objects out of the group named before that holds them (read as "except");
        where the group named right before does not hold them, the words are refused, quoted, never dropped."""
        if not mentions:
            return None
        m2 = mentions[-1]
        if m2.start < 2 or words[m2.start - 2 : m2.start] != (",", "not") or m2.det == "pronoun":
            return None
        if any(w not in (",", ".", "!", "?", "please") for w in words[m2.end :]):
            return None
        from .grounding import candidates as _cands

        said = " ".join(words[m2.start - 1 : m2.end])
        try:
            out = set(_cands(self.vocab, m2))
        except InputError:
            out = set()
        for m1 in reversed(mentions[:-1]):
            if not m1.plural:
                continue
            try:
                held = set(_cands(self.vocab, m1))
            except InputError:
                continue
            if out and out <= held:
                return words[: m1.end] + ("except",) + words[m2.start : m2.end] + words[m1.end : m2.start - 2] \
                    + words[m2.end :]
        if not mentions[-2:-1] or not mentions[-2].plural:
            return None  # "move the spoon, not the fork": a contrast with the one object named before
        raise InputError(f"'{said}': no group named before it holds what it leaves out; "
                         f"say what to leave out of which objects (e.g. \"all the blocks except the red one\")")

    def _so_that(self, words: tuple[str, ...], k: int, n_skip: int) -> list[_Pending]:
        """"move A so that B ends up REL of A": the goal is stated from the anchor's side."""
        main, sub = words[:k], words[k + n_skip :]
        text = " ".join(words)
        mentions = self._find(main)
        if not mentions:
            raise InputError(f"'{text}': say which object to move")
        movers: list[int | Choice] = []
        for m in mentions:
            sel = self._select(m)
            movers.extend(sel if isinstance(sel, list) else [sel])
        out = []
        for part in _weak_split(sub, self._find(sub), self.key_vocab, self._word_kinds()[0]):
            # Every pronoun after "so that" is the object to move ("... the bowl
            # in front of it and the can on its left").
            self.state.last = list(movers)
            self.state.it_pair = None
            self.state.last_tower = False
            out.extend(self.clause(part))
        res = []
        for p in out:
            if any(o in movers for o in p.objects):
                res.append(p)
            elif p.anchor is not None and p.anchor in movers and p.pattern in _INVERSE and len(p.objects) == 1:
                inv = _INVERSE[p.pattern]
                same = next((q for q in res if q.pattern == inv and q.anchor == p.objects[0]), None)
                if same is not None:
                    same.objects.append(p.anchor)  # "move both bowls so that the block is in front of them"
                else:
                    res.append(_Pending(inv, [p.anchor], p.objects[0], None, text))
            elif p.pattern == "tower" and any(o in movers for o in p.objects):
                res.append(p)
            else:
                raise InputError(f"'{text}': the goal after 'so that' does not involve the object to move")
        return res

    def clause(self, words: tuple[str, ...]) -> list[_Pending]:
        """The pending goals one clause asks for: the early handlers of :mod:`.readings` on its words, then
        its frame (:meth:`_frame`), then the readings in their registered order; the first that answers
        gives the result. ``self.fired`` records the name of each reading that answered."""
        from .readings import EARLY, READINGS, Frame

        words = self._arrangement_refs(words)
        if not words:
            return []
        f = Frame(words, " ".join(words))
        parser = cast("_Parser", self)  # the assembled parser, which this part is a part of
        for name, handler in EARLY:
            got = handler(parser, f)
            if got is not None:
                self.fired.append(name)
                return got
        f = self._frame(f.words, f.text)
        for name, handler in READINGS:
            got = handler(parser, f)
            if got is not None:
                self.fired.append(name)
                return got
        raise AssertionError("the last reading answers every clause")

    def _frame(self, words: tuple[str, ...], text: str) -> Frame:
        """A clause's references, stack roles, parameters and the words between its references (see
        :class:`.readings.Frame`); refuses what no reading can take (an object size word, a count of
        groups, a compass direction that is no facing, an exception with nothing to leave out)."""
        from .readings import Frame

        mentions = self._find(words)
        role_at, reduced = self._roles(words, mentions)
        if role_at is not None:
            words = reduced
            mentions = self._find(words)
            if any(m.start < s < m.end for m in mentions for s in role_at):
                # Without their role words two references ran together ("red at the
                # bottom and blue on top" -> "red and blue"): which role is whose is lost.
                raise InputError(f"'{text}': cannot tell which object each stack position belongs to; "
                                 f"name each object with its noun (\"the red block at the bottom\")")
        moved = self._detached_exception(words, mentions)
        if moved is not None:
            words = moved
            text = " ".join(words)
            mentions = self._find(words)
        params: dict = {}
        inside = {k for m in mentions for k in range(m.start, m.end)}
        if self.state.header is not None or (not mentions and self.state.last_shape is not None) or any(
                self._free_word(w) or stages.is_mark(w) or w in _FACING_CUES or w in _PLACE_OR_SIZE
                for k, w in enumerate(words) if k not in inside) or (not mentions and self._last_read is not None):
            stackish = any(_stacking(w) for w in words) or (
                self.state.header is not None and self.state.header[0] == "tower")
            order_by = None
            sup = re.search(r"\b(largest|biggest|widest|heaviest|tallest|smallest|lightest|narrowest)( one| ones)? "
                            r"(at the bottom|on the bottom|at the base|as the base|on top|at the top)\b", " ".join(words))
            if stackish and sup:
                big = sup.group(1) in ("largest", "biggest", "widest", "heaviest", "tallest")
                order_by = "desc" if big == ("bottom" in sup.group(3) or "base" in sup.group(3)) else "asc"
                cut = set(range(len(" ".join(words)[: sup.start()].split()),
                                len(" ".join(words)[: sup.end()].split())))
                words = tuple(w for k, w in enumerate(words) if k not in cut)
                mentions = self._find(words)
            self._order_by = order_by
            params, words2 = take_params(words, self._free_word, {m.start: m.end for m in mentions}, stack=stackish)
            if words2 != words:
                by_index = [role_at.get(m.start) for m in mentions] if role_at is not None else None
                words = words2
                mentions = self._find(words)
                if by_index is not None:
                    # The place words are out; the references and their roles are the same, in order.
                    role_at = ({m.start: r for m, r in zip(mentions, by_index) if r is not None}
                               if len(mentions) == len(by_index) else None)
        keep = re.search(r"\b(?:while |and )?(?:keep|keeping|make|making) (?:the|that|it|them) (?:(?:circle|ring|line|row|"
                         r"rectangle|square|stack|tower|pile) )?(" + "|".join(SIZES) + r")\b", " ".join(words))
        if keep is not None:
            # "..., keeping the circle small": the size of the arrangement of this clause.
            if params.get("size", SIZES[keep.group(1)]) != SIZES[keep.group(1)]:
                raise InputError(f"'{text}': two different sizes for one arrangement")
            params["size"] = SIZES[keep.group(1)]
            lo = len(" ".join(words)[: keep.start()].split())
            hi = len(" ".join(words)[: keep.end()].split())
            words = words[:lo] + words[hi:]
            mentions = self._find(words)
        for mm in mentions:
            if mm.start > 0 and words[mm.start - 1] in _OBJECT_SIZE_WORDS:
                # "the large cans": a size that picks objects, which no selection here reads.
                raise InputError(f"'{words[mm.start - 1]} {mm.text}': objects are not told apart by a size word; "
                                 f"name them by colour or id")
        roles = [role_at.get(m.start) for m in mentions] if role_at else None
        text = " ".join(words)
        groups, gaps = _groups(words, mentions)
        rest = [k for lo, hi in gaps for k in range(lo, hi) if words[k] not in (",", "#", "(", ")", "&", _ROLE_MARK)]
        while rest and words[rest[0]] in _LEADING:
            rest = rest[1:]
        phrase_words = [words[k] for k in rest]
        self._unknown_objects(words, rest, mentions)
        for k in rest[:-1]:
            nxt = words[k + 1] if k + 1 < len(words) else ""
            part_of = nxt in ("corners", "sides", "edges", "ends", "points", "vertices") and words[k + 2 : k + 4] in (
                ("of", "a"), ("of", "the"), ("of", "one"))
            if (words[k] in NUMBERS or words[k] in ("several", "multiple", "separate")) and nxt.endswith("s") \
                    and self._free_word(nxt) and not part_of:  # "the four corners of a rectangle" is one
                raise InputError(f"'{text}': {words[k]} {nxt} need their objects named one by one "
                                 f"(say which objects go in each)")
        meaningful = [w for w in phrase_words if w not in STOPWORDS and w not in FILLERS and not _is_number(w)]
        loose = [w for w in phrase_words if w in _COMPASS_LEFT]
        if loose:
            # A compass direction that is no "facing ..." ("running north to south",
            # "diagonally"): a direction the goal would silently drop.
            raise InputError(f"'{text}': the direction '{loose[0]}' is not read; a pattern can only be "
                             f"'facing north', 'east', 'south' or 'west'")
        if any(w in ("except", "excluding", "minus") for w in phrase_words):
            raise InputError(f"'{text}': cannot tell what to leave out")
        return Frame(words=words, text=text, mentions=mentions, params=params, meaningful=meaningful,
                     phrase_words=phrase_words, roles=roles, groups=groups, gaps=gaps, rest=rest)

    def _relation(self, pattern: str, groups, sels, p: int, text: str) -> list[_Pending]:
        words_rel = pattern.replace("_", " and ")
        last = self._last_read
        if p >= len(groups) and len(groups) == 1 and last is not None and isinstance(last.anchor, int) \
                and _OTHER_SIDE.get(last.pattern) == pattern:
            # "the knife on the right of the plate, the fork on the left": the other side of the same object
            anchor_sel: list = [last.anchor]
        elif p >= len(groups):
            raise InputError(f"'{text}': {words_rel} of what? name the reference object")
        else:
            anchor_sel = [x for s in sels[p] for x in (s if isinstance(s, list) else [s])]
        tower = self.state.tower.objects if self.state.tower is not None else []
        if (len(anchor_sel) == 1 and tower and anchor_sel[0] == tower[-1] and isinstance(tower[0], int)
                and p < len(groups)
                and any(isinstance(mm, Mention) and mm.det == "pronoun" and mm.text == "it" for mm in groups[p])):
            # "put the bowl on the plate and the cutlery beside it": beside the stack, named by its base.
            anchor_sel = [tower[0]]
        elif (len(anchor_sel) > 1 and tower and set(anchor_sel) == set(tower) and isinstance(tower[0], int)
              and p < len(groups)
              and any(isinstance(mm, Mention) and mm.det == "pronoun" and mm.text in ("them", "those")
                      for mm in groups[p])):
            # "bowl on the plate, then the mug to the right of them": of the stack, named by its base.
            anchor_sel = [tower[0]]
        target_sel: list[int | Choice] = []
        for g, s in enumerate(sels):
            if g == p:
                continue
            for y in s:
                for x in y if isinstance(y, list) else [y]:
                    if x not in target_sel:
                        target_sel.append(x)
        if not target_sel and self.state.selection is not None:
            target_sel = list(self.state.selection)  # "box: behind the red bowl"
            self.state.selection = None
        if not target_sel and self._implicit is not None:
            target_sel = [self._implicit[0]]  # "..., and a bit to the left of it"
        if not target_sel:
            raise InputError(f"'{text}': nothing to put {words_rel} of the reference object")
        for a in anchor_sel:
            if isinstance(a, Choice) and a.k > 1:
                raise InputError(f"'{a.text}': a relation needs one reference object")
        fixed_anchor = {a for a in anchor_sel if isinstance(a, int)}
        targets = [t for t in target_sel if not (isinstance(t, int) and t in fixed_anchor)]
        if not targets:
            raise InputError(f"'{text}': an object cannot be {words_rel} of itself")
        self.state.last = targets
        self.state.last_tower = False
        self.state.tower = None
        self.state.last_anchor = anchor_sel[0] if len(anchor_sel) == 1 else None
        self.state.it_pair = (targets[0], anchor_sel[0]) if len(targets) == 1 and len(anchor_sel) == 1 else None
        if len(anchor_sel) == 1 and isinstance(anchor_sel[0], int) and p < len(groups) and any(
                isinstance(mm, Mention) and mm.det == "pronoun" and mm.text == "it" for mm in groups[p]):
            self.state.it_chain = anchor_sel[0]
        return [_Pending(pattern, list(targets), a, None, text) for a in anchor_sel]

    def _read_clause(self, clause: tuple[str, ...], pending: list[_Pending]) -> None:
        """Read one clause (cut further where it names two arrangements or two
        stacking steps) into ``pending``, remembering the nouns it names."""
        # "it" as a relation's reference object, again in the next clause: the same object
        # ("the fork is fine. put the knife to its right and the spoon to its left").
        mentions = self._find(clause)
        so_that = any(clause[x : x + 2] in (("so", "that"), ("such", "that")) for x in range(len(clause)))
        parts = [clause] if so_that else _weak_split(clause, mentions, self.key_vocab, self._word_kinds()[0])
        for part in parts:
            for sub in ([part] if so_that else _on_pairs_split(part, self._find(part))):
                while sub and sub[0] in _LEADING:
                    sub = sub[1:]
                if not sub:
                    continue
                self._chain, self.state.it_chain = self.state.it_chain, None
                # "E in front of R, and a bit to the left of it": no object of its own but "it",
                # so the object placed before is still the subject and "it" is its reference object.
                self._implicit = None
                pair = self.state.it_pair
                try:
                    own = self._find(sub)
                except InputError:
                    own = []
                if (pair is not None and all(isinstance(x, int) for x in pair) and len(own) == 1
                        and own[0].det == "pronoun" and own[0].text == "it" and any(w in _DIR_WORDS for w in sub)
                        and not any(w in _VERT_WORDS - {"to", "of"} for w in sub)):
                    self._implicit = pair
                # "put the phone left of the mug and the knife to its right": "it" as the reference object of
                # a side or depth is the reference object of the relation before (the mug).
                self._it_beside = (pair is not None and isinstance(pair[1], int) and any(w in _DIR_WORDS for w in sub)
                                   and not any(w in _VERT_WORDS - {"to", "of"} and not _on_a_side(sub, k)
                                               for k, w in enumerate(sub)))
                self._first = None
                if not self.state.last and own and own[0].det == "the" and not own[0].plural and any(
                        m.det == "pronoun" and m.text in ("it", "its") for m in own[2:]) and not any(
                        w in _DIR_WORDS or w in _VERT_WORDS - {"to", "of"} for w in sub[own[0].end : own[1].start]):
                    self._first = own[0]
                said = next((k for k, m in enumerate(own) if m.det == "pronoun"), len(own))
                # "set the red, the blue and the yellow block in a row with them four inches apart": "with them"
                # after the objects of its own part, where nothing was named before, is those objects again.
                self._them_again = not self.state.last and 2 <= said < len(own) and own[said].text in (
                    "them", "they") and sub[own[said].start - 1 : own[said].start] == ("with",) and not any(
                    m.det == "pronoun" for m in own[said + 1 :])
                read = self.clause(sub)
                pending.extend(read)
                if read:
                    self._last_read = read[-1]
                self._implicit = None
                self._first = None
                self._them_again = False
                try:
                    named = self._find(sub)
                except InputError:
                    named = []
                self._note_nouns(reversed(named))
                self._named_in.append((sub, named))


def _on_a_side(words: tuple[str, ...], k: int) -> bool:
    """Whether "on" at ``k`` says a side ("on the right of it", "on its left"), not that one object stands on
    another."""
    nxt = words[k + 1 : k + 3]
    return words[k] == "on" and len(nxt) == 2 and nxt[0] in ("the", "its", "their") and nxt[1] in _DIR_WORDS


#: A side and the side opposite it, of one reference object.
_OTHER_SIDE = {"left": "right", "right": "left", "front": "behind", "behind": "front"}
