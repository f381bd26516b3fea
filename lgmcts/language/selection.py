"""What a reference selects in the scene as the parser reads a command: pronouns and "the other one" from
what was named before, a definite reference narrowed to the object named earlier, the nouns noted for later
bare colours (:class:`_Selecting`, mixed into :class:`.rules._Parser`), and the word tests built on them.
"""

from __future__ import annotations

from dataclasses import replace
import re

from . import lexicon, poses, stages
from ..errors import InputError
from .clauses import _COMMAND_VERBS, _DIR_WORDS, _is_number
from .grounding import COLOUR_WORDS, Choice, GROUPS, Mention, NUMBERS, candidates, find_mentions, select
from .matcher import FILLERS, STOPWORDS, _stem
from .places import BAND_MARKS
from .shapes import COLS, FACINGS, REGION_NOUNS, ROWS, SIZES
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .host import ParserHost
    from .assembly import _Pending
else:
    ParserHost = object


_DET_WORDS = frozenset({"the", "all", "every", "each", "both", "these", "those", "my"})


_ALLOWED_EXTRA = frozenset(
    {"another", "second", "first", "new", "neat", "big", "large", "small", "tidy", "nice", "perfect", "bottom",
     "pattern", "shape", "formation", "well", "too", "again", "afterward", "there", "following", "order", "straight",
     "please", "robot", "scene", "arrangement", "proper", "standard", "usual", "normal", "full", "complete", "basic",
     "simple", "meal", "lunch", "breakfast", "supper", "setup", "restaurant", "person"}
)


#: Direction words left in a clause once its facing has been read.
_COMPASS_LEFT = frozenset({"north", "south", "east", "west", "northward", "southward", "eastward", "westward",
                           "northwards", "southwards", "eastwards", "westwards", "northeast", "northwest",
                           "southeast", "southwest", "diagonal", "diagonally"})


_TABLE_WORDS = frozenset({"table", "tabletop", "workspace", "desk", "dinner", "setting", "place", "side", "way",
                          "end", "rest"})


#: Words that start a facing ("facing", "pointing", "tines" ...): a clause with one reads its parameters.
_FACING_CUES = frozenset({"facing", "pointing", "oriented", "orientated", "turned", "aimed", "faces", "face", "points"})


_DINNER_CUES = frozenset({"dinner", "setting", "laid", "lay", "meal", "lunch", "breakfast", "supper"})


#: Words of stack roles and orders, which a remark never has.
_ROLE_WORDS = lexicon.ROLE_WORDS


#: Words that keep a comma-separated part of a command from being an aside.
_ASIDE_KEEP = frozenset({"order", "first", "then", "last", "next", "top", "bottom", "base", "middle", "between",
                         "each", "other", "one", "ones", "former", "latter", "both", "all", "every", "except",
                         "table", "facing", "pointing", "turned", "oriented", "orientated", "aimed", "faces", "face",
                         "on", "onto", "under", "below", "above", "beneath",
                         "underneath", "atop", "upon"})


class _Selecting(ParserHost):
    """Resolving references against the scene and what the command named before."""

    def _select_group(self, group: list[Mention]) -> list:
        """Resolve a list of mentions; a description repeated in the list as many times as it has
        matches names each of them once ("white triangle, blue triangle, white triangle" with two
        white triangles)."""
        out: list = []
        done: set[str] = set()
        for mm in group:
            try:
                out.append(self._select(mm))
            except InputError as exc:
                key = mm.text.removeprefix("the ").strip()
                same = [x for x in group if x.text.removeprefix("the ").strip() == key]
                if "ambiguous" not in str(exc) or len(same) < 2:
                    raise
                ids = candidates(self.vocab, mm)
                if len(ids) != len(same):
                    raise
                if key not in done:
                    done.add(key)
                    self.state.named.update(ids)
                    out.append(list(ids))
        # "all the bowls and cups except the red bowl": an exception that removes
        # nothing from its own item is the whole list's.
        for mm in group:
            for e in mm.excluding:
                try:
                    ex = set(candidates(self.vocab, replace(e, det="all")))
                except InputError:
                    continue
                try:
                    own = set(candidates(self.vocab, replace(mm, excluding=(), det="all")))
                except InputError:
                    own = set()
                if ex and (not ex & own or e.text.split()[:1] in (["anything"], ["everything"], ["any"], ["all"])):
                    # also "the cans and bowls except anything red": said of anything, the whole list's
                    out = [[x for x in got if x not in ex] if isinstance(got, list) else got for got in out]
        return out

    def _select(self, m: Mention) -> list[int] | Choice:
        if m.det == "pronoun":
            if not self.state.last and self._first is not None and m.text in ("it", "its"):
                got = self._select(self._first)
                if isinstance(got, list) and len(got) == 1:
                    return got
            if not self.state.last and self._them_again and m.text in ("them", "they"):
                return []
            if not self.state.last:
                raise InputError(f"'{m.text}' refers to nothing named before it")
            last = self.state.last
            if m.count:
                # "one of them": any one of the objects "them" refers to.
                opts = tuple(x for x in last if isinstance(x, int))
                if len(opts) < m.count or len(opts) != len(last):
                    raise InputError(f"'{m.text}' is unclear: it refers to {len(opts)} fixed objects")
                choice = Choice(opts, m.count, m.text)
                self.state.choices.append(choice)  # "... and the other one ..."
                return choice
            pair = self.state.it_pair
            if m.text == "it" and self._chain is not None:
                return [self._chain]
            if m.text == "it" and self._implicit is not None:
                return [self._implicit[1]]
            if m.text == "it" and pair is not None and self._it_beside:
                return [pair[1]]
            if m.text == "it" and pair is not None and all(isinstance(x, (int, Choice)) for x in pair):
                # "put the cup left of the plate and the bottle behind it": the cup or the plate? ("one of
                # the mugs left of the phone and the other one right of it": the chosen mug or the phone?)
                said = [f"object {x}" if isinstance(x, int) else f"'{x.text}'" for x in pair]
                raise InputError(f"'{m.text}' is unclear: it may be {said[0]} or {said[1]}, both named "
                                 f"in the clause before; name the one you mean")
            if m.text == "it" and self.state.last_tower and isinstance(last[-1], int):
                return [last[-1]]  # "put A on B, then put C on top of it": it is A, the top
            if m.text == "it" and len(last) > 1 and self.state.mass:
                return [x for x in last if isinstance(x, int)]  # "grab all the red stuff and stack it"
            if m.text == "it" and len(last) > 1 and not self.state.last_tower:
                # "it" is one object: with several placed before, it is the one they were placed by.
                if isinstance(self.state.last_anchor, int):
                    return [self.state.last_anchor]
                raise InputError(f"'{m.text}' is unclear: the clause before it places {len(last)} objects")
            if len(last) == 1 and isinstance(last[0], Choice):
                return last[0]
            if any(isinstance(x, Choice) for x in last):
                raise InputError(f"'{m.text}' is unclear: the objects it refers to are not fixed yet")
            return [x for x in last if isinstance(x, int)]
        self.state.mass = bool(re.search(r"\b(stuff|everything|anything|cutlery|silverware|flatware|crockery|"
                                         r"tableware|dishware)\b", m.text))
        if m.det == "other" and m.plural and m.names is None and self.state.group:
            # "of the cans, put the red one on the plate and the rest in a row": the rest of the group
            rest = [x for x in self.state.group if x not in self.state.named]
            if rest:
                self.state.named.update(rest)
                return rest
        if m.det == "other" and not m.plural and self.state.group:
            # "of the two green things, put the cup on the plate and the other one ...": the one of the group
            # that no goal has named yet
            rest = [x for x in self.state.group if x not in self.state.named]
            if len(rest) == 1:
                self.state.named.add(rest[0])
                return rest
        if m.det == "other" and not m.plural and self.state.choices:
            # "one mug ... the other one", "one of the mugs ... the remaining mug": the one of two that
            # the first did not take (a noun must name the same two objects).
            prev = self.state.choices[-1]
            if prev.k == 1 and len(prev.options) == 2 and (m.names is None or set(
                    candidates(self.vocab, m, named=frozenset(self.state.named))) == set(prev.options)):
                return Choice(prev.options, 1, m.text, fresh=True)
        try:
            sel = select(self.vocab, m, named=frozenset(self.state.named))
        except InputError as exc:
            # A definite reference that fits several objects but exactly one
            # named before it in the command means that one ("move the red mug
            # so that the plate ends up on the mug's right").
            if m.det != "the" or "ambiguous" not in str(exc):
                raise
            earlier = [i for i in candidates(self.vocab, m) if i in self.state.named]
            if len(earlier) != 1:
                raise
            sel = earlier
        if isinstance(sel, list):
            self.state.named.update(sel)
        else:
            self.state.choices.append(sel)
        return sel

    def _unknown_objects(self, words: tuple[str, ...], rest: list[int], mentions: list[Mention]) -> None:
        """Refuse a determiner followed by a word that names nothing here."""
        restset = set(rest)
        for k in rest:
            w = words[k]
            if not w.isalpha() or w in STOPWORDS or w in FILLERS or w in _ALLOWED_EXTRA or w in NUMBERS:
                continue
            if _stem(w) in self.key_vocab or self._pattern_word(w):
                continue
            nxt = [words[x] for x in range(k + 1, min(k + 4, len(words)))]
            if nxt[:1] == ["of"] and any(_stem(x) in self.key_vocab or self._free_word(x) for x in nxt[1:]):
                continue  # "each corner of a square", "the perimeter of a circle": a part of the shape
            j = k - 1
            while j >= 0 and j in restset and words[j] not in _DET_WORDS and words[j].isalpha() and words[j] not in STOPWORDS:
                j -= 1
            if j >= 0 and j in restset and words[j] in _DET_WORDS:
                end = k + 1
                while (end < len(words) and end in restset and words[end].isalpha() and words[end] not in STOPWORDS
                       and _stem(words[end]) not in self.key_vocab):
                    end += 1
                if w in COLOUR_WORDS:
                    # "all purple bowls" with no purple object: show the whole phrase.
                    said_next = next((mm for mm in mentions if mm.start == end), None)
                    if said_next is not None:
                        end = said_next.end
                    raise InputError(f"nothing in the scene matches '{' '.join(words[j:end])}' (no {w} object)")
                raise InputError(f"'{' '.join(words[j:end])}' names nothing in the scene")

    def _pattern_word(self, w: str) -> bool:
        """Whether ``w``, in no key, still names a pattern by its embedding ("perimeter")."""
        if not w.isalpha() or len(w) < 3:
            return False
        p, _, unsupported = self.matcher.word_pattern(w)
        return p is not None

    def _find(self, words: tuple[str, ...], key_vocab=None) -> list[Mention]:
        """The object references of ``words``, bare colours completed by the nouns named before."""
        return find_mentions(self.vocab, words, self.key_vocab if key_vocab is None else key_vocab,
                             tuple(self.state.nouns))

    def _every_match(self, m: Mention) -> list[int]:
        """Every object a reference may name, whatever its number ("the block": every block; ids as said)."""
        return candidates(self.vocab, m if m.det == "ids" else replace(m, det="all", plural=True))

    def _table_xy(self, oid: int) -> tuple[float, float] | None:
        """Where an object stands on the table (None when it stands on another object)."""
        o = self.spec.object(oid)
        return None if o.pose is None or o.on is not None else (o.pose[0], o.pose[1])

    @property
    def _centre(self) -> tuple[float, float]:
        ws = self.spec.workspace
        return ((ws.x[0] + ws.x[1]) / 2, (ws.y[0] + ws.y[1]) / 2)

    def _names_shape(self, m: Mention, shape: _Pending) -> bool:
        """Whether ``m`` names every object of the arrangement ``shape`` just read and only them: "it" / "them" /
        "they" for what was named last, or "every block", "all of the blocks", "each can" that select them."""
        objs = set(shape.objects)
        if m.det == "pronoun":
            return m.text in ("it", "them", "they") and set(self.state.last) == objs
        if m.det != "all" or m.excluding:
            return False
        try:
            return set(candidates(self.vocab, m)) == objs
        except InputError:
            return False

    def _object_word(self, w: str) -> bool:
        """Whether ``w`` names objects of the scene (a name, a colour, a group, an id)."""
        return (w in self.vocab.color_words or w in self._cat_words or _stem(w) in self._cat_words or w in GROUPS
                or w.startswith("#") or w in ("object", "objects", "everything", "anything"))

    def _request_word(self, w: str) -> bool:
        """Whether ``w`` may ask for a goal: a pattern, direction, place, facing or stack word, a command verb."""
        st = _stem(w)
        return ((st in self.key_vocab and st not in FILLERS) or w in _DIR_WORDS or w in _COMPASS_LEFT
                or w in _COMMAND_VERBS or w in ROWS or w in COLS or w in FACINGS or w in REGION_NOUNS
                or w in _ROLE_WORDS or w in _FACING_CUES or w in _DINNER_CUES or w in BAND_MARKS
                or w in ("on", "onto", "under", "below", "above", "atop", "upon", "stacked", "piled", "lined", "order"))

    def _content_word(self, w: str) -> bool:
        """Whether ``w`` may carry part of a goal: an object, colour or id word, a
        pattern or direction word, a place, size or order word, a number."""
        st = _stem(w)
        if _is_number(w) or w.startswith("#") or stages.is_mark(w) or poses.is_mark(w) or w in BAND_MARKS:
            return True
        if w in self.vocab.color_words or w in COLOUR_WORDS or w in self._cat_words or st in self._cat_words:
            return True
        if (st in self.key_vocab and st not in FILLERS) or w in _DIR_WORDS or w in _COMPASS_LEFT or w in _ASIDE_KEEP:
            return True
        return (w in _COMMAND_VERBS or w in SIZES or w in ROWS or w in COLS or w in FACINGS or w in REGION_NOUNS
                or w in ("stacked", "piled", "lined"))

    def _select_noting(self, mentions) -> list[int | Choice]:
        """What ``mentions`` select, in order and once each, their nouns noted for later references."""
        got: list[int | Choice] = []
        for m in mentions:
            sel = self._select(m)
            got.extend(x for x in (sel if isinstance(sel, list) else [sel]) if x not in got)
            self._note_nouns([m])
        return got

    def _names_objects(self, part: list[str]) -> bool:
        try:
            return bool(self._find(tuple(part)))
        except InputError:
            return True

    def _note_nouns(self, mentions) -> None:
        """Put the object nouns of ``mentions`` (in that order) at the front of the
        nouns named so far, for later bare colours and "the white one"."""
        for m in mentions:
            if m.names is not None and not m.head and m.names not in self.state.nouns:
                self.state.nouns.insert(0, m.names)

    def _unknown_nouns(self, words: tuple[str, ...], mentions: list[Mention]) -> list[str]:
        """Words after "the"/"a" outside the references that name nothing here ("the napkin")."""
        inside = {k for m in mentions for k in range(m.start, m.end)}
        return [w for k, w in enumerate(words) if k not in inside and k > 0 and words[k - 1] in ("the", "a", "an")
                and w.isalpha() and not self._content_word(w) and w not in STOPWORDS and _stem(w) not in FILLERS
                and w not in _ALLOWED_EXTRA and w not in _TABLE_WORDS]
