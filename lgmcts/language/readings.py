"""The readings of one clause, as registered handlers tried in order (:meth:`.framing._Framing.clause`).

A clause is read in three parts. The *early* handlers look at its words alone
(a goal that must not hold, an object relative to itself, "so that"). Then
:meth:`.framing._Framing._frame` grounds its references and takes its stack roles
and its place, size and facing words into a :class:`Frame`. Then the
*readings* are tried in the order they are registered here: the first that
answers (a list of pending goals, empty for a clause that only adds to an
earlier one) gives the clause's reading; an *adjustment* (``adjusts=True``)
only changes the frame for the readings after it and answers nothing. Each
handler's docstring gives an example of what it reads;
``tests/language/test_readings.py`` parses labelled commands that each
reading answers and checks that it is the one that answers them.

To add a reading, write a handler with ``@reading("name")`` at the place in
this file where it must be tried (before the readings that would take its
clauses otherwise), with its example, and check ``python
tests/language/golden_parse.py``: only the commands meant to change may move.
The readings of a stack said over several clauses live in
:mod:`.stack_readings` and are registered here, in their place in the order,
with ``reading("name")(handler)``.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING, Any

from ..errors import InputError
from .grounding import Choice, Mention
from .lexicon import SHAPE_NOUNS, says
from .matcher import FILLERS, _forms, _stem
from .assembly import _Pending, _add_params, _with_facing
from .clauses import (
    _COMMAND_VERBS,
    _DIR_WORDS,
    _ON_WORDS,
    _VERT_ON,
    _VERT_SKIP,
    _VERT_UNDER,
    _VERT_WORDS,
    _is_number,
    _numbers,
    _on_pairs_split,
    _pattern_positions,
    _stacking,
    _weak_split,
)
from .pose_reading import read_pose
from .framing import _ROLE_MARK
from .passes import _MEASURE_WORDS, _NOT_JOIN, _SELECT_VERBS
from .selection import _ALLOWED_EXTRA
from .shapes import SIZES
from .stack_readings import (
    _ORDER_HEADERS,
    _read_continue_last_stack,
    _read_next_in_last_stack,
    _read_order_makes_a_stack,
    _read_order_of_last_stack,
    _read_roles_in_last_stack,
    _read_roles_make_a_stack,
    _read_vertical_pair,
)

if TYPE_CHECKING:
    from .rules import _Parser

#: Words that may stand between the object lists of one arrangement.
_JOIN_OK = frozenset({"and", ",", "&", "plus", "or", "with", "of", "using", "from", "in", "into", "a", "an", "the", "as",
                      "to", "up", "out", "together", "along", "all", "them", "form", "forming", "shape", "pattern",
                      "then", "also", "too", "both", "each", "every", "neat", "tidy", "nice", "straight", "single",
                      "perfect", "well", "please", "made", "make", "making", "by", "for", "is", "are", "be"})

__all__ = ["ADJUSTS", "EARLY", "READINGS", "Frame", "early", "reading"]

@dataclass
class Frame:
    """What the readings of one clause share: its words and text, its references (``mentions``), the
    parameters said (``params``), the stack role of each reference (``roles``), the references grouped
    (``groups``) with the word spans between them (``gaps``), the indices of the words outside references
    (``rest``), those words (``phrase_words``) and the ones that mean something (``meaningful``); the
    adjustments add the phrase to match, the usable patterns and the objects each reference selects."""

    words: tuple[str, ...]
    text: str
    mentions: list[Mention] = field(default_factory=list)
    params: dict[str, Any] = field(default_factory=dict)
    meaningful: list[str] = field(default_factory=list)
    phrase_words: list[str] = field(default_factory=list)
    roles: list[str | None] | None = None
    groups: list[list[Mention]] = field(default_factory=list)
    gaps: list[tuple[int, int]] = field(default_factory=list)
    rest: list[int] = field(default_factory=list)
    rel_pos: list[int] = field(default_factory=list)
    free_pos: list[int] = field(default_factory=list)
    anchored: frozenset[str] = frozenset()
    usable: frozenset[str] = frozenset()
    sels: list[Any] = field(default_factory=list)
    phrase: str = ""
    infos: dict[str, Any] = field(default_factory=dict)
    vertical: str | None = None


Handler = Callable[["_Parser", Frame], "list[_Pending] | None"]
#: The handlers on a clause's words, in order.
EARLY: list[tuple[str, Handler]] = []
#: The readings (and adjustments) on a clause's frame, in order.
READINGS: list[tuple[str, Handler]] = []
#: The names of the adjustments among :data:`READINGS`.
ADJUSTS: set[str] = set()


def early(name: str) -> Callable[[Handler], Handler]:
    """Register a handler on a clause's words, tried after those registered before it."""
    def add(fn: Handler) -> Handler:
        if any(n == name for n, _ in EARLY):
            raise ValueError(f"early reading {name!r} registered twice")
        EARLY.append((name, fn))
        return fn
    return add


def reading(name: str, adjusts: bool = False) -> Callable[[Handler], Handler]:
    """Register a reading on a clause's frame (``adjusts``: it only changes the frame), tried after those before it."""
    def add(fn: Handler) -> Handler:
        if any(n == name for n, _ in READINGS):
            raise ValueError(f"reading {name!r} registered twice")
        READINGS.append((name, fn))
        if adjusts:
            ADJUSTS.add(name)
        return fn
    return add


# ------------------------------------------------------------------ on the words


early("pose")(read_pose)  # a pose said in numbers (.pose_reading)


@early("not-a-goal")
def _read_not_a_goal(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"make sure the box is not behind the bowl": a goal that something must not hold is refused."""
    words = f.words
    text = f.text
    rel_words_ = self._word_kinds()[0]
    for k, w in enumerate(words):
        nxt = [x for x in words[k + 1 : k + 5] if x not in ("be", "end", "ends", "up", "placed", "put", "go", "sit",
                                                            "sitting", "stand", "standing", "to", "the")]
        if w in ("not", "never", "nowhere") and nxt and (
                nxt[0] in _DIR_WORDS or nxt[0] in _VERT_WORDS - {"of", "top"} or _stem(nxt[0]) in rel_words_
                or tuple(nxt[:2]) == ("in", "front")):
            # "make sure the box is not behind the bowl": a goal that something must not hold.
            raise InputError(f"'{text}': goals that something must not hold are not read; say where it should go")
    return None


@early("itself")
def _read_itself(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"put the cup next to itself": an object placed relative to itself is refused."""
    words = f.words
    text = f.text
    if any(w in ("itself", "themselves", "himself", "herself") for w in words):
        raise InputError(f"'{text}': an object cannot be placed relative to itself")
    return None


@early("so-that")
def _read_so_that(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"stack the cans so that ...", "shift A until B is on its left": the state the move must bring about."""
    words = f.words
    for k in range(1, len(words) - 1):
        if words[k : k + 2] in (("so", "that"), ("such", "that"), ("so", "it"), ("so", "they"), ("so", "the")):
            skip = 2 if words[k + 1] == "that" else 1
            sub_words = words[k + skip :]
            if any(_stacking(w) for w in words[:k]) and sum(w in _VERT_WORDS - {"to", "of", "top"}
                                                            for w in sub_words) >= 2:
                # "stack the cans so that the green one sits on the red one and the white one
                # sits on the green one": the stacking steps make the stack.
                out: list[_Pending] = []
                self._note_nouns(self._find(words[:k]))  # "the green one": a can
                for part in _weak_split(sub_words, self._find(sub_words), self.key_vocab, self._word_kinds()[0]):
                    for step in _on_pairs_split(part, self._find(part)):
                        out.extend(self.clause(tuple(w for w in step if w not in (",", "and"))
                                               if step[:1] in ((",",), ("and",)) else step))
                if out and all(p.pattern == "tower" for p in out):
                    return out
            if any(_stacking(w) for w in words[:k]) and not any(
                    w in ("it", "they", "them") for w in words[k + skip :]):
                # "stack the mugs so that the blue one is at the bottom": the
                # stack's roles, as "with the blue one at the bottom".
                sub = tuple(w for w in words[k + skip :] if w not in ("is", "are", "be", "should", "ends", "end",
                                                                     "up", "goes", "go", "sits", "will"))
                return self.clause(words[:k] + ("with",) + sub)
            return self._so_that(words, k, skip)
        if words[k : k + 2] in (("until", "the"), ("until", "it"), ("leaving", "the"), ("that", "leaves"),
                                ("where", "the")) and k > 1:
            # "shift A until B is on its left", "put A somewhere that leaves B on its left".
            after = words[k + 1 :] if words[k + 1] in ("the", "it") else words[k + 2 :]
            main = tuple(w for w in words[:k] if w not in ("somewhere", "anywhere"))
            return self._so_that(main + ("so", "that") + after, len(main), 2)
    return None


# ------------------------------------------------------------------ on the frame


@reading("params-of-last-arrangement")
def _read_params_of_last_arrangement(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"..., in the front right corner": a place, size or facing for the arrangement just read."""
    mentions = f.mentions
    params = f.params
    meaningful = f.meaningful
    text = f.text
    last = self._last_read
    if not mentions and params and not meaningful and last is not None and last.anchor is not None \
            and set(params) <= {"facing", "measure"}:
        # "fork left of the plate, tines toward the right edge": the facing of the relation just read.
        _add_params(last, params, text)
        return []
    shape = self.state.last_shape
    meaningful = [w for w in meaningful if w not in _HEDGE_WORDS]  # "..., middle right i guess"
    if (len(mentions) == 1 and params and shape is not None and len(shape.objects) > 1
            and self._names_shape(mentions[0], shape)
            and all(_restates(w, shape.pattern) or w in _MOVE_VERBS
                    or (w in _COMMAND_VERBS and not any(w in nouns for nouns in SHAPE_NOUNS.values()))
                    for w in meaningful)):
        # "make a square of the bowls and the box. centre it on the table": "it" is the arrangement just read.
        _add_params(shape, params, text)
        return []
    if not mentions and params and shape is not None and all(_restates(w, shape.pattern) for w in meaningful):
        # "..., red on top, in the front right corner": the place of the arrangement just read; also where
        # the clause names that arrangement again ("line up the cans, in a strip along the back").
        _add_params(shape, params, text)
        return []
    return None


#: Words of a hedge, which ask for nothing ("middle right i guess").
_HEDGE_WORDS = frozenset({"guess", "think", "suppose", "reckon", "probably", "maybe", "perhaps", "yeah", "mean"})
#: Verbs that move an arrangement already said to a place ("centre it on the table", "shift them to the back").
_MOVE_VERBS = frozenset({"centre", "center", "shift", "move", "slide", "push", "bring", "keep", "have", "want", "leave",
                         "do", "build", "make", "put", "set"})


def _restates(word: str, pattern: str) -> bool:
    """Whether ``word`` names the arrangement ``pattern`` again: one of its nouns, or a strip or band for a line."""
    return word in SHAPE_NOUNS.get(pattern, ()) or (pattern == "line" and word in ("strip", "band"))


reading("order-of-last-stack")(_read_order_of_last_stack)  # .stack_readings


@reading("no-object")
def _read_no_object(self: _Parser, f: Frame) -> list[_Pending] | None:
    """A clause that names no object: a stack's order as a header ("from the bottom up: ..."), a preamble
    ("set the table"), the arrangement of the objects selected before, an arrangement whose objects come
    next ("make a tower:"); else refused."""
    mentions = f.mentions
    text = f.text
    params = f.params
    meaningful = f.meaningful
    phrase_words = f.phrase_words
    words = f.words
    if not mentions:
        if text in _ORDER_HEADERS:
            # "from the bottom up: green, red, blue": a stack named by its order.
            self.state.header = ("tower", params, text)
            return []
        if not meaningful:
            return []  # a preamble such as "set the table" or "please"
        if self.state.selection is not None:
            # "select objects that are red. small circle in the top left": the
            # structure sentence takes the objects selected before it.
            sel = self.state.selection
            m = self._match(" ".join(phrase_words), text, frozenset(n for n, i in self.infos.items()
                                                                 if not i.anchored and not i.needs_pose))
            p = self._shape(m.pattern, [[sel]], words, [], text, phrase_words)
            p.params = params
            return [p]
        if any(self._free_word(w) for w in meaningful):
            m = self._match(" ".join(phrase_words), text, frozenset(n for n, i in self.infos.items()
                                                                 if not i.anchored and not i.needs_pose))
            self.state.header = (m.pattern, params, text)
            return []  # "make a tower:" names its objects in the next clause
        raise InputError(f"'{text}' names no object in the scene")
    return None


@reading("selection-verb")
def _read_selection_verb(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"select the red objects": objects chosen for the next clause (or for the header before)."""
    words = f.words
    roles = f.roles
    meaningful = f.meaningful
    groups = f.groups
    if words[0] in _SELECT_VERBS and roles is None and all(
            w in _SELECT_VERBS or w in ("up", "out", "only", "just") for w in meaningful):
        sel: list[int | Choice] = []
        for g in groups:
            for got in self._select_group(g):
                for x in got if isinstance(got, list) else [got]:
                    if x not in sel:
                        sel.append(x)
        self.state.selection = sel
        self.state.last = list(sel)
        self.state.it_pair = None
        self.state.last_tower = False
        if self.state.header is not None:
            # "small line in the top left. select objects that are mug.": the
            # structure sentence first, its objects selected after it.
            pat, hparams, htext = self.state.header
            self.state.header = None
            p = self._shape(pat, [[sel]], words, [], htext, [])
            p.params = dict(hparams)
            return [p]
        return []
    return None


reading("roles-in-last-stack")(_read_roles_in_last_stack)  # .stack_readings


reading("next-in-last-stack")(_read_next_in_last_stack)  # .stack_readings


reading("roles-make-a-stack", adjusts=True)(_read_roles_make_a_stack)  # .stack_readings


reading("order-makes-a-stack", adjusts=True)(_read_order_makes_a_stack)  # .stack_readings


@reading("each-other-line", adjusts=True)
def _read_each_other_line(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"the cans behind each other", "next to one another": one after the other, a line."""
    meaningful = f.meaningful
    phrase_words = f.phrase_words
    joined = " ".join(phrase_words)
    if says(joined, "each_other") and not says(joined, "on_top"):
        # "the cans behind each other", "next to one another": one after the other, a line.
        phrase_words = [w for w in phrase_words if w in _COMMAND_VERBS] + ["in", "a", "line"]
        meaningful = ["line"]
    f.meaningful = meaningful
    f.phrase_words = phrase_words
    return None


reading("vertical-pair", adjusts=True)(_read_vertical_pair)  # .stack_readings


@reading("header-objects")
def _read_header_objects(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"make a stack: plate, then white bowl": the objects of the arrangement named in the clause before."""
    sels = f.sels
    meaningful = f.meaningful
    groups = f.groups
    words = f.words
    gaps = f.gaps
    text = f.text
    phrase_words = f.phrase_words
    params = f.params
    if not meaningful and self.state.header is not None:
        pat, hparams, htext = self.state.header
        self.state.header = None
        sels = [self._select_group(g) for g in groups]
        # "make a stack: plate, then white bowl, then green bowl": the next clauses add to it.
        p = self._shape(pat, sels, words, gaps, f"{htext} {text}" if "top to" in htext else text, phrase_words,
                        defer_min=True)
        p.params = {**hparams, **params}
        return [p]
    f.sels = sels
    return None


reading("continue-last-stack")(_read_continue_last_stack)  # .stack_readings


@reading("phrase-and-choices", adjusts=True)
def _read_phrase_and_choices(self: _Parser, f: Frame) -> list[_Pending] | None:
    """The phrase to match against the pattern keys, the usable patterns, and the objects each reference selects."""
    rel_pos = f.rel_pos
    free_pos = f.free_pos
    anchored = f.anchored
    usable = f.usable
    sels = f.sels
    phrase = f.phrase
    infos = f.infos
    phrase_words = f.phrase_words
    meaningful = f.meaningful
    groups = f.groups
    gaps = f.gaps
    words = f.words
    rest = f.rest
    # Order and emphasis words ("the first one at the bottom", "another")
    # carry no pattern meaning: leave them out of the phrase to match.
    phrase = " ".join(w for w in phrase_words if w not in _ALLOWED_EXTRA or _stem(w) in self.key_vocab)
    if not meaningful and len(groups) >= 2:
        for lo, hi in gaps[1:-1]:
            if tuple(words[lo:hi]) in _ON_WORDS:
                phrase = "on top of each other"
                break
    infos = self.infos
    n_numbers = len(_numbers(tuple(phrase_words)))
    usable = frozenset(n for n, inf in infos.items() if not inf.needs_pose or n_numbers >= 2)
    anchored = frozenset(n for n in usable if infos[n].anchored)
    rel_words, free_words = self._word_kinds()
    rel_pos = [k for k in rest if _stem(words[k]) in rel_words]
    free_pos = [k for k in rest if any(f in free_words for f in _forms(words[k]))]
    sels = [self._select_group(g) for g in groups]
    if "using" in words and len(groups) >= 2:
        # "place the cans in a line using the red, white and blue can": the
        # objects after "using" are those of the arrangement, taken from the set before.
        u = words.index("using")
        before = [g for g, (lo, hi) in enumerate(gaps[1:]) if hi <= u or lo <= u < hi]
        after = [g for g in range(len(groups)) if g not in before]
        flat = lambda gs: {x for g in gs for s in sels[g] for x in (s if isinstance(s, list) else [s])  # noqa: E731
                           if isinstance(x, int)}
        if before and after and flat(after) and flat(after) < flat(before):
            sels = [[] if g in before else sels[g] for g in range(len(sels))]
    if says(phrase, "another"):
        # "another line": a second arrangement of objects no other goal uses.
        sels = [[replace(s, fresh=True) if isinstance(s, Choice) else s for s in g] for g in sels]
    f.rel_pos = rel_pos
    f.free_pos = free_pos
    f.anchored = anchored
    f.usable = usable
    f.sels = sels
    f.phrase = phrase
    f.infos = infos
    return None


@reading("relation-and-arrangement")
def _read_relation_and_arrangement(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"line up the forks to the left of the plate": one clause, a relation and an arrangement."""
    rel_pos = f.rel_pos
    free_pos = f.free_pos
    gaps = f.gaps
    words = f.words
    rest = f.rest
    text = f.text
    anchored = f.anchored
    usable = f.usable
    groups = f.groups
    sels = f.sels
    phrase_words = f.phrase_words
    params = f.params
    if rel_pos and free_pos:
        # One clause, two goals: "line up the forks to the left of the plate".
        k0 = rel_pos[0]
        g_rel = next(g for g, (lo, hi) in enumerate(gaps) if lo <= k0 < hi)
        lo, hi = gaps[g_rel]
        start = k0
        while start > lo and words[start - 1] in ("to", "the", "on", "in", "at", "and", "of", "towards", "toward"):
            start -= 1
        rel_phrase = " ".join(words[start:hi])
        shape_phrase = " ".join(words[k] for k in rest if not start <= k < hi)
        m_rel = self._match(rel_phrase, text, anchored)
        m_shape = self._match(shape_phrase, text, usable - anchored)
        out = _with_facing(self._relation(m_rel.pattern, groups, sels, g_rel, text), params)
        targets = out[0].objects
        out.append(self._shape(m_shape.pattern, [[targets]], words, [], text, phrase_words))
        out[-1].params = params
        return out
    return None


@reading("selection-on-or-under")
def _read_selection_on_or_under(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"heart: on the granite bowl": the selected objects on (or under) it."""
    groups = f.groups
    roles = f.roles
    words = f.words
    gaps = f.gaps
    sels = f.sels
    text = f.text
    if self.state.selection is not None and len(groups) == 1 and roles is None:
        lead = tuple(w for w in words[gaps[0][0] : gaps[0][1]] if w not in _VERT_SKIP and w not in _COMMAND_VERBS
                     and w != "the")
        if lead in _VERT_ON or lead in _VERT_UNDER:
            # "heart: on the granite bowl": the selected objects on (or under) it.
            sel, self.state.selection = list(self.state.selection), None
            base = [x for y in sels[0] for x in (y if isinstance(y, list) else [y])]
            objs = base + sel if lead in _VERT_ON else sel + base
            self.state.last, self.state.last_tower = sel, True
            self.state.it_pair = None
            return [self._shape("tower", [[objs]], words, [], text, ["stack"])]
    return None


@reading("put-down-first", adjusts=True)
def _read_put_down_first(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"first put down the yellow block, then stack ...": "down" and "first" ask for nothing."""
    phrase = f.phrase
    meaningful = f.meaningful
    rel_pos = f.rel_pos
    free_pos = f.free_pos
    roles = f.roles
    if meaningful and set(meaningful) <= {"down", "first"} and "down" in meaningful and not rel_pos and not free_pos \
            and roles is None:
        meaningful, phrase = [], ""  # "first put down the yellow block, (then) stack the green block on it"
    f.meaningful = meaningful
    f.phrase = phrase
    return None


@reading("objects-for-next-clause")
def _read_objects_for_next_clause(self: _Parser, f: Frame) -> list[_Pending] | None:
    """"cans: line", "the knife, the fork and the spoon. make a circle with them": objects named on their own."""
    meaningful = f.meaningful
    roles = f.roles
    rel_pos = f.rel_pos
    free_pos = f.free_pos
    phrase = f.phrase
    sels = f.sels
    if not meaningful and roles is None and not rel_pos and not free_pos and phrase.strip() == "":
        # "cans: line", "the knife, the fork and the spoon. make a circle with
        # them": objects named on their own are those of the next clause.
        sel: list[int | Choice] = []
        for g in sels:
            for y in g:
                for x in y if isinstance(y, list) else [y]:
                    if x not in sel:
                        sel.append(x)
        shape = self.state.last_shape
        if f.params and shape is not None and set(sel) == set(shape.objects):
            # "letters in a rectangle: A, R, T, E, facing right": the arrangement's objects said again, with its
            # facing (or place, or size)
            _add_params(shape, f.params, f.text)
            return []
        self.state.selection = sel
        self.state.last = list(sel)
        self.state.it_pair = None
        self.state.last_tower = False
        return []
    return None


#: Words by which one object stands on or in another.
_SUPPORT_WORDS = frozenset({"on", "onto", "atop", "upon", "in", "into"})


@reading("arrangement")
def _read_arrangement(self: _Parser, f: Frame) -> list[_Pending] | None:
    """The arrangement or relation the phrase matches best, over the objects of the clause."""
    phrase_words = f.phrase_words
    text = f.text
    phrase = f.phrase
    usable = f.usable
    infos = f.infos
    gaps = f.gaps
    rel_pos = f.rel_pos
    words = f.words
    groups = f.groups
    sels = f.sels
    roles = f.roles
    mentions = f.mentions
    vertical = f.vertical
    params = f.params
    named = self._arrangements_named(phrase_words)
    if len(named) >= 2:
        raise InputError(f"'{text}' names more than one arrangement ({' and '.join(sorted(named))}) "
                         f"for the same objects")
    m = self._match(phrase, text, usable)
    if infos[m.pattern].anchored:
        counts = [len([k for k in rel_pos if lo <= k < hi]) for lo, hi in gaps]
        if not any(counts):
            counts = [len(_pattern_positions(words, lo, hi, self.key_vocab)) for lo, hi in gaps]
        p = max(range(len(counts)), key=lambda g: (counts[g], -g)) if any(counts) else 0
        for lo, hi in gaps[1:p]:
            # "the mug on the plate goes behind the bowl": a support said between the objects that move is no
            # joining word; reading them all behind the bowl would drop it
            said = [w for w in words[lo:hi] if w not in ("the", "a", "an")]
            if len(said) == 1 and said[0] in _SUPPORT_WORDS:
                raise InputError(f"'{text}': cannot tell what '{' '.join(words[lo:hi])}' asks of the objects "
                                 f"around it")
        return _with_facing(self._relation(m.pattern, groups, sels, p, text), params)
    if m.pattern != "tower" and not infos[m.pattern].needs_pose and len(groups) >= 2:
        # Objects of one arrangement are joined by "and", "with", "of", "using" or the
        # pattern phrase itself; any other word between them ("in a line next to the
        # plate", "a circle around the bottle", "in a row beside them") relates them in a
        # way no goal here expresses: refuse rather than put them all in the arrangement.
        for lo, hi in gaps[1:-1]:
            odd = [w for w in words[lo:hi] if w in _NOT_JOIN or (
                w not in _JOIN_OK and not self._free_word(w) and _stem(w) not in FILLERS
                and w not in _COMMAND_VERBS and w not in SIZES)]
            if odd:
                raise InputError(f"'{text}': cannot tell what '{' '.join(words[lo:hi])}' asks of the objects "
                                 f"around it")
    if any(_is_number(w) or w in _MEASURE_WORDS for w in phrase_words) and not infos[m.pattern].needs_pose:
        raise InputError(f"'{text}': sizes and distances in numbers are not read; use small, medium or large")
    role_of: dict = {}
    if roles is not None:
        for mm, r in zip(mentions, roles):
            if r is not None:
                got = self._select(mm)
                for x in got if isinstance(got, list) else [got]:
                    if role_of.get(x, r) != r:
                        raise InputError(f"'{text}': object {x} is given two places in the stack "
                                         f"({role_of[x]} and {r}); list the objects from the bottom up")
                    role_of[x] = r
    # A tower may grow over the next clauses ("green at the bottom, then red"):
    # its size is checked once the command is read.
    shape = self._shape(m.pattern, sels, words, gaps, text, phrase_words, vertical=vertical, roles=role_of,
                        defer_min=m.pattern == "tower")
    shape.params = params
    return [shape]
