"""The default offline parser: clauses, object grounding, pattern choice.

Pipeline for one command:

1. **Split** into clauses at sentence ends, ";", the connectives
   "then", "while", "also", "after that", "meanwhile", and an "and" or ","
   right before a command verb ("stack the blocks and put the bowls in a
   line"), never inside a list "A, B and C"; split "A on B and C on D"
   into two stacking steps (chained into one tower later); then split a clause
   that names two arrangements at the "and" (or ",") between them
   ("put all blocks in a circle and the white bottle behind one block").
2. **Ground** the object references of each clause (:mod:`.grounding`).
3. **Choose the pattern** of each clause by Sentence-BERT similarity between
   what is left of the clause once its object references are removed
   ("put ... in a line pattern") and the keys of the pattern database
   (:mod:`.matcher`).
4. **Assemble goals**: a pattern with an anchor (the spatial relations) takes
   the objects named before the relation phrase as targets and the object
   named right after it as anchor ("X left of Y"); other patterns take every
   object the clause names. Towers keep the order of naming (first named at
   the bottom) except after "on"/"onto" ("stack A on B": B is below A), and
   "from top to bottom" reverses it; towers where the top of one is the
   bottom of another are joined ("put A on B, then put C on A": [B, A, C]).
5. **Resolve choices**: "one X" as a target prefers objects no other goal
   uses; as an anchor it prefers an object of another goal of the same
   command (the paper's "behind one block" next to "all blocks in a circle").
6. **Check** the result: too few objects for a pattern, contradicting
   relations, cycles and other impossible combinations are refused with one
   line, never turned into a silently wrong goal.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field, replace
from typing import TYPE_CHECKING

from ..errors import InputError
from ..formats import RELATIONS, GoalSpec, SceneSpec, parse_goals
from . import lexicon
from .grounding import _ATTRS, COLOUR_WORDS, GROUPS, NUMBERS, Choice, candidates, Mention, Vocabulary, describe, find_mentions, select, tokenize
from .lexicon import HUES, MACROS
from .matcher import FILLERS, STOPWORDS, PatternMatcher, _forms, _stem
from .rewrite import ASKS_TO_ACT, FREE_ORDER, QUESTION, rewrite, unframe
from .shapes import COLS, FACINGS, REGION_NOUNS, ROWS, SIZES, merged_region, normalise, stack_roles, take_params
from . import stages
from .measures import UNITS
from .places import BAND_MARKS, POINTING_PARTS

if TYPE_CHECKING:
    from .readings import Frame

__all__ = ["RulesOptions", "parse_rules", "split_clauses", "goal_dicts"]

_STRONG_WORDS = frozenset({"then", "while", "also", "afterwards", "meanwhile", "additionally", "furthermore", "whereas"})
_STRONG_SEQ = (("after", "that"), ("and", "then"), ("and", "also"), ("as", "well", "as", "that"),
               ("at", "the", "same", "time"), ("once", "that", "is", "done"), ("when", "that", "is", "done"),
               ("once", "you", "are", "done"), ("when", "you", "are", "done"))
#: How "the same for X" starts (split off the clause before it).
_SAME_START = (("the", "same", "for"), ("the", "same", "with"), ("the", "same", "goes"), ("same", "for"),
               ("same", "with"), ("do", "the", "same"), ("do", "not", "touch"), ("do", "not", "move"),
               ("don't", "touch"), ("don't", "move"), ("leave",))
_PUNCT_END = frozenset({";", ".", "!", "?", ":"})
_LEADING = frozenset(
    {"and", ",", "but", "then", "like", "also", "finally", "first", "firstly", "secondly", "thirdly", "lastly", "please",
     "next", "now", "after", "that", "so", "meanwhile", "additionally", "furthermore", "plus", "kindly", "can", "could",
     "you", "would", "will", "whereas", "while", "afterwards"}
)
_COORD = frozenset({"and", ",", "&", "plus"})
#: Where a clause naming two arrangements may be cut ("a line but the bottle behind the plate").
_CUT = _COORD | {"but"}
#: Verbs that start a new command after "and" or a comma ("stack the blocks
#: and put the bowls in a line"); a list of objects never continues with one.
_FRONTED = frozenset(
    {"to", "on", "in", "at", "behind", "left", "right", "front", "back", "beside", "into", "onto", "with", "using",
     "from", "for", "out"}
)
_COMMAND_VERBS = frozenset(
    {"put", "place", "move", "set", "stack", "arrange", "line", "make", "build", "form", "pile", "align",
     "position", "lay", "gather", "organize", "organise", "create", "sort", "bring", "group", "leave", "keep",
     "get", "take", "slide", "push", "shift", "rearrange", "drop", "stand", "select", "pick", "choose", "grab",
     "use", "find", "stick", "pop", "plonk", "shove", "chuck"}
)
#: Where an object said without its article may start: a sentence's start or a command verb.
_ARTICLE_AT = re.compile(rf"(?i)((?:^|[.;!?:]|\b(?:{'|'.join(sorted(_COMMAND_VERBS))}))\s+|^)((?:[a-z]+ ){{0,2}}[a-z]+)\b"
                         rf"(?=(?:\s+[a-z]+)?)")
#: Verbs of a selection clause: it names objects for the next clause ("select
#: objects that are red. circle"; "take the red mug and put it ...").
_SELECT_VERBS = frozenset({"select", "pick", "choose", "take", "grab", "get", "find", "use", "consider", "fetch",
                           "see", "spot", "notice", "locate", "look"})
_VERT_SKIP = frozenset({"goes", "go", "sits", "sit", "is", "are", "be", "should", "placed", "put", "stands", "rests",
                        "directly", "right", "just", "then", "lies", "ends", "up", "will", "must", "sitting",
                        "resting", "standing", "lying", "stacked", "set", "neatly", "squarely", "centred", "centered"})
_VERT_ON = frozenset({("on",), ("onto",), ("on", "top", "of"), ("atop",), ("upon",), ("above",), ("over",),
                      ("on", "to"), ("top", "of")})
_VERT_UNDER = frozenset({("under",), ("below",), ("beneath",), ("underneath",), ("under", "neath")})
_VERT_WORDS = frozenset(w for s in _VERT_ON | _VERT_UNDER for w in s)
#: Words that may stand between the object lists of one arrangement.
_JOIN_OK = frozenset({"and", ",", "&", "plus", "or", "with", "of", "using", "from", "in", "into", "a", "an", "the", "as",
                      "to", "up", "out", "together", "along", "all", "them", "form", "forming", "shape", "pattern",
                      "then", "also", "too", "both", "each", "every", "neat", "tidy", "nice", "straight", "single",
                      "perfect", "well", "please", "made", "make", "making", "by", "for", "is", "are", "be"})
_NOT_JOIN = frozenset({"around", "next", "near", "beside", "behind", "between", "under", "above", "beneath", "below",
                       "alongside", "inside", "outside", "across", "against", "toward", "towards", "past", "except",
                       "excluding", "minus", "which", "that", "where", "while", "but"})
_MEASURE_WORDS = frozenset({"cm", "mm", "centimeters", "centimetres", "meters", "metres", "inches", "inch", "radius",
                            "diameter", "spacing", "apart", "degrees"})
_INVERSE = {"left": "right", "right": "left", "front": "behind", "behind": "front", "left_front": "right_behind",
            "right_behind": "left_front", "left_behind": "right_front", "right_front": "left_behind"}
_ON_WORDS = (("on", "top", "of"), ("onto",), ("on",), ("atop",), ("upon",))
#: Words never counted as naming an arrangement when deciding where to split.
_NOT_PATTERN = frozenset({"other", "top", "exactly", "position", "coordinate", "shape", "pose", "this", "single"})
_DET_WORDS = frozenset({"the", "all", "every", "each", "both", "these", "those", "my"})
_ALLOWED_EXTRA = frozenset(
    {"another", "second", "first", "new", "neat", "big", "large", "small", "tidy", "nice", "perfect", "bottom",
     "pattern", "shape", "formation", "well", "too", "again", "afterward", "there", "following", "order", "straight",
     "please", "robot", "scene", "arrangement", "proper", "standard", "usual", "normal", "full", "complete", "basic",
     "simple", "meal", "lunch", "breakfast", "supper", "setup", "restaurant", "person"}
)


@dataclass(frozen=True)
class RulesOptions:
    """Options of the rule-based parser.

    Attributes
    ----------
    prefer_anchor_from_other_goal : bool
        Resolve "one X" as a relation anchor to an object of another goal of
        the same command when there is one (the paper's reading).
    """

    prefer_anchor_from_other_goal: bool = True


@dataclass
class _Pending:
    pattern: str
    objects: list[int | Choice]
    anchor: int | Choice | None
    pose: tuple[float, float, float] | None
    clause: str
    params: dict = field(default_factory=dict)
    #: A tower's objects whose place in it was said ("red at the bottom", "then blue"): their roles.
    said: dict = field(default_factory=dict)


#: Words of pattern keys too general to name one arrangement by themselves.
_GENERIC_KEY_WORDS = frozenset({"arrange", "form", "formation", "shape", "put", "build", "another", "other", "top",
                                "around", "single", "border", "file", "round", "straight", "vertical", "box"})

#: Size adjectives that, right before an object reference, would pick objects by size.
_OBJECT_SIZE_WORDS = frozenset({"big", "bigger", "large", "larger", "small", "smaller", "little", "tiny", "huge",
                                "tall", "taller", "short", "shorter", "long", "wide", "giant", "mini", "medium"})

#: Direction words left in a clause once its facing has been read.
_COMPASS_LEFT = frozenset({"north", "south", "east", "west", "northward", "southward", "eastward", "westward",
                           "northwards", "southwards", "eastwards", "westwards", "northeast", "northwest",
                           "southeast", "southwest", "diagonal", "diagonally"})

#: A stacking order given by an attribute or a sort, which the parser does not read.
_ORDER_BY = re.compile(
    r"(?i)\b(in (ascending |descending |increasing |decreasing )?order of|ordered by|sorted by|sort(ed)? them|"
    r"in (size|height|colou?r|alphabetical|rainbow|reverse alphabetical|reverse) order|(in|by) the order of the (rainbow|alphabet)|by (size|height|colou?r|volume|weight)|"
    r"(from|by) (the )?(shortest|smallest|tallest|largest|biggest|lightest|darkest|heaviest) to (the )?"
    r"(shortest|smallest|tallest|largest|biggest|lightest|darkest|heaviest))\b")


@dataclass
class _State:
    named: set[int] = field(default_factory=set)
    last: list[int | Choice] = field(default_factory=list)
    #: The anchor of the previous clause's relation, if it had one.
    last_anchor: "int | Choice | None" = None
    #: The previous clause built a tower: "it" then means its top object.
    last_tower: bool = False
    #: Objects chosen by a selection clause ("select objects that are red.").
    selection: list[int | Choice] | None = None
    #: A pattern named before its objects ("make a tower: ...").
    header: tuple[str, dict, str] | None = None
    #: "one X" choices made so far ("the other one" takes the one left).
    choices: list = field(default_factory=list)
    #: The tower of the previous clause, which "then the red block" extends.
    tower: "_Pending | None" = None
    #: The object a stack role just placed in that tower: "then green" goes right above it.
    tower_prev: int | None = None
    #: The object a role just put at the top of that tower: "then yellow" goes right below it.
    tower_down: int | None = None
    #: That tower's order was said by "A on B" / "A under B": a role may not reverse it.
    tower_fixed: bool = False
    #: The last reference selected was a mass ("all the red stuff"): "it" is all of it.
    mass: bool = False
    #: After "put A left of B": (A, B), either of which a following "it" may mean.
    it_pair: "tuple | None" = None
    #: "it" was the reference object of the clause just read: the next clause's "it" is the same.
    it_chain: int | None = None
    #: The last arrangement read (a place said after it is its place).
    last_shape: "_Pending | None" = None
    #: The tower of the previous clause is listed from the top down.
    downward: bool = False
    #: Object nouns named so far, latest first ("stack the cans: green first").
    nouns: list = field(default_factory=list)


def split_clauses(words: tuple[str, ...], nouns: frozenset[str] = frozenset()) -> list[tuple[str, ...]]:
    """Split at sentence ends, ";", connectives and "and"/"," before a verb; drop leading connectors."""
    parts: list[list[str]] = [[]]
    i = 0
    while i < len(words):
        w = words[i]
        seq = next((s for s in _STRONG_SEQ if words[i : i + len(s)] == s), None)
        if seq is not None:
            parts.append([])
            i += len(seq)
            continue
        if w in _PUNCT_END or w in _STRONG_WORDS:
            parts.append([])
            i += 1
            continue
        bare = bool(parts[-1]) and parts[-1][0] in _HUES and not any(x in _OBJECT_START for x in parts[-1])
        if (w == "," and words[i + 1 : i + 2] in (("and",), ("plus",)) and _asks_after_object(parts[-1], nouns, hues=bare)
                and _asks_after_object(list(words[i + 2 : _next_stop(words, i + 2)]), nouns, start=True, hues=bare)):
            # "the bowl on the plate, and the mug, cup and bottle in a row": two goals said without verbs.
            parts.append([])
            i += 2
            continue
        if (w == "," and _asks_after_object(parts[-1], nouns, hues=bare) and words[i + 1 : i + 2] != ("and",)
                and _asks_after_object(list(words[i + 1 : _next_stop(words, i + 1, comma=True)]), nouns, start=True,
                                       hues=bare)):
            # "the blocks in a line, the yellow block on the orange one, and ...": a list of such goals.
            parts.append([])
            i += 1
            continue
        if w == "," and words[i + 1 : i + 2] == ("but",) and i + 2 < len(words) and words[i + 2] in _COMMAND_VERBS \
                and parts[-1]:
            parts.append([])  # "stack A on B, but keep B on top": a second request (here refused as contradicting)
            i += 2
            continue
        if w == "," and words[i + 1 : i + 2] == ("so",) and i + 2 < len(words) and _command_verb(words[i + 2]) \
                and parts[-1]:
            parts.append([])  # "the cans are everywhere, so put them in a row": the request after the remark
            i += 2
            continue
        if words[i : i + 3] == ("as", "well", "as") and i + 3 < len(words) and _command_verb(words[i + 3]) and parts[-1]:
            parts.append([])  # "put the mug ... in a ring, as well as lining the cutlery up": two requests
            i += 3
            continue
        nxt_k = i + 1
        while nxt_k < len(words) - 1 and words[nxt_k] in ("finally", "lastly", "then", "next", "also", "additionally"):
            nxt_k += 1  # ", and finally put the star below the pan"
        if (w in (",", "and", "plus") and nxt_k < len(words) and (_command_verb(words[nxt_k]) or any(
                words[i + 1 : i + 1 + len(x)] == x for x in _SAME_START)) and parts[-1]
                and not _fronted(parts[-1])):
            # "stack the blocks and put the bowls in a line": two commands.
            parts.append([])
            i += 1
            continue
        parts[-1].append(w)
        i += 1
    out = []
    for p in parts:
        while p and p[0] in _LEADING:
            p = p[1:]
        while p and p[-1] in (",", "and"):
            p = p[:-1]
        if p:
            out.append(tuple(p))
    return out


#: Words that give an arrangement or a relation after the objects ("the bowl on the plate").
_GOAL_WORDS = frozenset({"on", "onto", "under", "underneath", "below", "beneath", "above", "behind", "front", "left",
                         "right", "line", "row", "circle", "ring", "loop", "stack", "stacked", "pile", "piled", "tower",
                         "rectangle", "square", "top", "lined", "next", "beside"})
_OBJECT_START = frozenset({"the", "a", "an", "all", "every", "each", "both", "everything", "one", "two", "three", "four"})


def _next_stop(words: tuple[str, ...], i: int, comma: bool = False) -> int:
    """Where the stretch of ``words`` from ``i`` ends (at ", and", or at any comma with ``comma``)."""
    j = i
    while j < len(words) and words[j] not in (";", ".", "!", "?") and words[j : j + 2] != (",", "and") and not (
            comma and words[j] == ","):
        j += 1
    return j


def _asks_after_object(part: list[str], nouns: frozenset[str] = frozenset(), start: bool = False,
                       hues: bool = False) -> bool:
    """Whether ``part`` names objects and then an arrangement or relation for them (``start``: and
    begins with the objects). ``nouns``: the scene's category words ("the green ring" is an object).
    ``hues``: a bare colour may begin the part ("red on blue, and green left of yellow")."""
    first = next((k for k, w in enumerate(part) if w in _OBJECT_START or (hues and k == 0 and w in _HUES)), None)
    if first is None or (start and first != 0):
        return False
    if start and len(part) > first + 1 and part[first + 1] in _GOAL_WORDS and part[first + 1] not in nouns \
            and part[first] not in _HUES:
        return False  # ", the row facing west": the arrangement itself, not objects
    return any(w in _GOAL_WORDS and w not in nouns for w in part[first + 1 :])


_LIST_WORDS = frozenset({"then", "and", "on", "at", "under", "below", "above", "goes", "is", "last", "first", "next",
                         "highest", "lowest", "onto", "over", "beneath", "underneath"})


def _bare_letter(m: re.Match, letters: set[str]) -> str:
    """"the letter R" for a capital R said bare, where the scene has that letter."""
    x = m.group(1)
    before = m.string[: m.start()].rstrip()
    after = m.string[m.end():].lstrip()
    prev = re.findall(r"[A-Za-z]+|[,;:]", before)[-1:] or [""]
    nxt = re.findall(r"[A-Za-z]+|[,;:.!?]", after)[:1] or [""]
    if x not in letters or x == "I" or prev[0].lower() in ("the", "letter", "a", "an"):
        return x
    if prev[0].lower() in _HUES:
        return f"letter {x}"  # "the red A": the red letter A
    if x == "A" and not (prev[0].lower() in ("then", "and", ",") or nxt[0] in (",", ";", ".", "!", "?", "")
                         or nxt[0].lower() in _LIST_WORDS):
        return x
    return f"the letter {x}"


def _command_verb(w: str) -> bool:
    """A command verb, or its -ing form ("... and lining up the cans")."""
    if w in _COMMAND_VERBS:
        return True
    if not w.endswith("ing") or len(w) < 6:
        return False
    base = w[:-3]
    return any(b in _ARRANGE_VERBS for b in (base, base + "e", base[:-1] if base[-1:] == base[-2:-1] else base))


#: Verbs whose -ing form starts a command of its own ("leaving out", "using" do not).
_ARRANGE_VERBS = frozenset({"put", "place", "move", "set", "stack", "arrange", "line", "pile", "align", "position", "lay",
                            "gather", "organize", "organise", "build", "form", "create", "group", "slide", "push",
                            "shift", "rearrange"})


def _fronted(part: list[str]) -> bool:
    """Whether ``part`` is a phrase put before its verb ("to the left of the bowl, line up ...")."""
    k = 0
    while k < len(part) and part[k] in _LEADING:
        k += 1
    return k < len(part) and part[k] in _FRONTED and not any(w in _COMMAND_VERBS for w in part[k:])


def _cut(words: tuple[str, ...], cuts: list[tuple[int, int]]) -> list[tuple[str, ...]]:
    """``words`` in the pieces around the spans ``cuts`` (left to right, the spans dropped)."""
    if not cuts:
        return [words]
    out, prev = [], 0
    for lo, hi in cuts:
        out.append(words[prev:lo])
        prev = hi
    out.append(words[prev:])
    return [tuple(x) for x in out if x]


def _gaps(words: tuple[str, ...], mentions: list[Mention]) -> list[tuple[int, int]]:
    """Token ranges between mentions: before the first, between, after the last."""
    out, prev = [], 0
    for m in mentions:
        out.append((prev, m.start))
        prev = m.end
    out.append((prev, len(words)))
    return out


def _table_place(words: tuple[str, ...], k: int) -> bool:
    """Whether ``words[k]`` is part of a place on the table ("the top right corner",
    "the left of the table"), not a relation or pattern word."""
    w = words[k]
    pos = set(ROWS) | set(COLS)
    nxt, prev = words[k + 1] if k + 1 < len(words) else "", words[k - 1] if k else ""
    if w in REGION_NOUNS:
        return prev in pos
    if w not in pos:
        return False
    return (nxt in pos or nxt in REGION_NOUNS or prev in pos
            or words[k + 1 : k + 4] in (("of", "the", "table"), ("of", "the", "workspace")))


def _pattern_positions(words: tuple[str, ...], lo: int, hi: int, vocab: frozenset[str]) -> list[int]:
    return [
        k for k in range(lo, hi)
        if words[k] not in STOPWORDS and words[k] not in FILLERS
        and (_stem(words[k]) in vocab or words[k] in ("stacked", "piled"))
        and _stem(words[k]) not in _NOT_PATTERN and not _table_place(words, k)
    ]


#: Stems of words that name a stack (a stacking step beside one belongs to it).
_TOWER_STEMS = frozenset({"stack", "stacked", "pile", "piled", "tower", "heap", "column", "layer"})
#: Words of a stacking step said between two objects ("on top of", "under").
_VERTICAL_REL = frozenset({"on", "onto", "atop", "upon", "above", "over", "under", "underneath", "below", "beneath",
                           "top"})
_STACK_GAP = _VERTICAL_REL | {"of", "the", "a", "right", "directly", "just"}


def _regions(words: tuple[str, ...], gaps: list[tuple[int, int]], vocab: frozenset[str], rel_words: frozenset[str]):
    """Pattern phrases of a clause as (gap index, positions) runs.

    A gap holding two arrangements of the non-relational kind joined by "and"
    ("in a line and another line of") gives two runs; relation words joined
    by "and" ("to the left and behind") stay one run.
    """
    out = []
    # "... in a circle and the red block on the green block": beside an arrangement, a stacking step
    # between two objects is a phrase of its own.
    free = any(any(_stem(words[k]) not in _TOWER_STEMS for k in _pattern_positions(words, lo, hi, vocab))
               and not any(words[k] in rel_words for k in range(lo, hi)) for lo, hi in gaps)
    for g, (lo, hi) in enumerate(gaps):
        pos = _pattern_positions(words, lo, hi, vocab)
        if not pos and free and 0 < g < len(gaps) - 1 and hi > lo and all(
                w in _STACK_GAP for w in words[lo:hi]) and any(w in _VERTICAL_REL for w in words[lo:hi]) \
                and words[hi] not in ("everything", "it", "them", "all", "each", "that", "this", "those"):
            pos = [k for k in range(lo, hi) if words[k] in _VERTICAL_REL]
        if not pos:
            continue
        run = [pos[0]]
        for k in pos[1:]:
            coord = any(words[j] in _COORD for j in range(run[-1] + 1, k))
            free_both = not any(words[j] in rel_words for j in run) and words[k] not in rel_words
            if coord and free_both:
                out.append((g, run))
                run = [k]
            else:
                run.append(k)
        out.append((g, run))
    return out


def _weak_split(
    words: tuple[str, ...], mentions: list[Mention], vocab: frozenset[str], rel_words: frozenset[str] = frozenset()
) -> list[tuple[str, ...]]:
    """Split a clause naming two arrangements at the "and" between them.

    A cut is made at an "and" (or ",") that shares a gap with a pattern
    phrase: after it ("X in a circle and Y behind Z") or before it ("a line
    with X and a circle with Y"). A pattern phrase that fills its gap alone
    ("line up X, Y and Z to the left of W", "stack X, Y and Z into a
    tower") is not cut, except after the anchor of a relation ("X left of
    Y and the Zs in a circle"). A relation put first ("to the left of the
    bowl, line up X and Y") is not cut from the phrase after its anchor.
    """
    gaps = _gaps(words, mentions)
    pat = _regions(words, gaps, vocab, rel_words)
    if len(pat) < 2:
        return [words]
    cuts: list[int] = []
    for (p, ppos), (q, qpos) in zip(pat, pat[1:]):
        if p == 0 and q == 1 and any(words[k] in rel_words for k in ppos):
            continue  # "to the left of the bowl, line up A and B": a fronted relation, its targets follow
        cut = None
        _, hi = gaps[p]
        after = [k for k in range(ppos[-1] + 1, min(hi, qpos[0])) if words[k] in _CUT]
        if after:
            cut = after[0]
        else:
            qlo, _ = gaps[q]
            before = [k for k in range(max(qlo, ppos[-1] + 1), qpos[0]) if words[k] in _CUT]
            if before:
                cut = before[-1]
            elif any(words[k] in rel_words for k in ppos) and q > p + 1:
                alo, ahi = gaps[p + 1]
                if ahi > alo and all(words[k] in _CUT for k in range(alo, ahi)):
                    cut = alo
        if cut is not None and (not cuts or cut > cuts[-1]):
            cuts.append(cut)
    return _cut(words, [(c, c + 1) for c in cuts])


#: Verbs that follow a subject in a statement of the goal ("the heart goes on the bowl").
_PREDICATES = frozenset({"is", "are", "goes", "go", "sits", "sit", "should", "must", "stays", "stay", "stands",
                         "ends", "will", "rests", "lies", "belongs", "needs", "has", "gets", "can"})


_EVERYTHING = frozenset({"everything", "all", "all of it", "it all", "the lot", "things", "stuff"})
_TABLE_WORDS = frozenset({"table", "tabletop", "workspace", "desk", "dinner", "setting", "place", "side", "way",
                          "end", "rest"})
def _sentences(words: tuple[str, ...], ends: tuple[str, ...]) -> list[tuple[str, ...]]:
    """``words`` cut after each of ``ends``, each sentence keeping its end mark."""
    out: list[tuple[str, ...]] = []
    start = 0
    for k, w in enumerate(words):
        if w in ends:
            out.append(words[start : k + 1])
            start = k + 1
    if start < len(words):
        out.append(words[start:])
    return out


def _stacking(w: str) -> bool:
    """Whether ``w`` (in any inflection: "stacked", "piling") speaks of a stack."""
    return any(f in ("stack", "tower", "pile", "foundation", "base") for f in _forms(w))


_MOVE_VERBS = frozenset({"move", "shift", "reposition", "relocate", "slide", "push", "nudge"})


def _merged_moves(clauses: list[tuple[str, ...]]) -> list[tuple[str, ...]]:
    """"Move the purple block. After that, the bowl should be behind it.": the
    object to move, then the goal stated from another object's side, read as
    one "move X so that ..." clause."""
    out: list[tuple[str, ...]] = []
    k = 0
    while k < len(clauses):
        c = clauses[k]
        core = tuple(w for w in c if w not in ("only", "just", "please"))
        nxt = clauses[k + 1] if k + 1 < len(clauses) else ()
        named = core[1:]
        again = len(named) >= 2 and any(nxt[x : x + len(named)] == named for x in range(len(nxt)))
        if (k + 1 < len(clauses) and core and core[0] in _MOVE_VERBS and len(core) <= 6
                and not any(w in _DIR_WORDS or w in _VERT_WORDS or w in ("to", "into", "in") for w in core)
                and (any(w in ("it", "its", "them", "their") for w in nxt) or again)):
            out.append(core + ("so", "that") + clauses[k + 1])
            k += 2
            continue
        out.append(c)
        k += 1
    return out


def _predicate_split(words: tuple[str, ...], mentions: list[Mention], rel_words: frozenset[str],
                     free_words: frozenset[str] = frozenset()) -> list[tuple[str, ...]]:
    """Cut "A is on B, C is in front of B and D goes left of E" before each new
    subject: a reference right after "," or "and" followed by a verb of
    statement, when what comes before it already relates two objects."""
    cuts: list[tuple[int, int]] = []
    prev = 0
    for k, m in enumerate(mentions):
        if k < 1 or m.start == 0:
            continue
        lo = m.start
        while lo > 0 and words[lo - 1] in (",", "and"):
            lo -= 1
        if lo == m.start or lo <= prev:
            continue
        if not (m.end < len(words) and words[m.end] in _PREDICATES):
            continue
        before = [x for x in mentions if prev <= x.start and x.end <= lo]
        related = any((w in _VERT_WORDS and w not in ("to", "of", "top")) or _stem(w) in rel_words or w in _DIR_WORDS
                      for w in words[prev:lo])
        shaped = any(f in free_words for w in words[prev:lo] for f in _forms(w))
        if shaped and before and not related:
            related, before = True, before * 2  # "the bowls are to be lined up, the bottles ...": complete
        so_that = any(words[x : x + 2] in (("so", "that"), ("such", "that")) for x in range(prev, lo))
        if k >= 2 and mentions[k - 1].end == lo and mentions[k - 2].end < mentions[k - 1].start and all(
                w in (",", "and") for w in words[mentions[k - 2].end : mentions[k - 1].start]):
            continue  # "a ring of the mug, the cup and the bottle is to be made": the last item of a list
        if len(before) >= 2 and related and not so_that:
            cuts.append((lo, m.start))
            prev = m.start
    return _cut(words, cuts)


def _on_pairs_split(words: tuple[str, ...], mentions: list[Mention]) -> list[tuple[str, ...]]:
    """Cut "A on B and C on D" into "A on B" and "C on D" (two stacking steps)."""
    cuts = []
    if len(mentions) == 3:
        # "the bowl on the plate, the forks lined up on the left": a stacking
        # step, then a clause about the third object.
        a, b, c = mentions
        tail = [w for w in words[c.end:] if w not in _COORD]
        if (words[a.end : b.start] in _ON_WORDS and b.end < c.start and tail
                and all(w in _COORD for w in words[b.end : c.start])):
            cuts.append((b.end, c.start))
    for k in range(1, len(mentions) - 2):
        a, b, c = mentions[k - 1], mentions[k], mentions[k + 1]
        # "A on B and C on D", "A on B and C behind D", "A on B and C, D and E
        # in a row left of F": C (with the list it opens) starts a second step.
        e = k + 1
        while e + 1 < len(mentions) and mentions[e].end < mentions[e + 1].start and all(
                w in _COORD for w in words[mentions[e].end : mentions[e + 1].start]):
            e += 1
        if e + 1 >= len(mentions):
            continue
        last, d = mentions[e], mentions[e + 1]
        first_rel = words[a.end : b.start] in _ON_WORDS or tuple(
            w for w in words[a.end : b.start] if w not in _VERT_SKIP and w != "the") in _VERT_ON | _VERT_UNDER or (
            any(w in _DIR_WORDS for w in words[a.end : b.start])
            and tuple(w for w in words[last.end : d.start] if w != "the") in _VERT_ON | _VERT_UNDER)
        if (first_rel and last.end < d.start
                and not all(w in _COORD for w in words[last.end : d.start])
                and b.end < c.start and all(w in _COORD for w in words[b.end : c.start])):
            cuts.append((b.end, c.start))
    return _cut(words, cuts)


def _groups(words: tuple[str, ...], mentions: list[Mention]) -> tuple[list[list[Mention]], list[tuple[int, int]]]:
    """Merge mentions joined only by "and"/","/"as well as" into groups."""
    groups: list[list[Mention]] = []
    for m in mentions:
        if groups:
            prev = groups[-1][-1]
            between = words[prev.end : m.start]
            joined = " ".join(between)
            if between and (all(w in _COORD or w == "or" for w in between) or joined in ("as well as", ", as well as")):
                groups[-1].append(m)
                continue
        groups.append([m])
    gaps, prev = [], 0
    for g in groups:
        gaps.append((prev, g[0].start))
        prev = g[-1].end
    gaps.append((prev, len(words)))
    return groups, gaps


def _numbers(words: tuple[str, ...]) -> list[float]:
    return [float(w) for w in words if re.fullmatch(r"-?\d+(?:\.\d+)?", w)]


#: "(then) do the same with X", "same for X", "the same goes for X", "repeat that for X".
_SAME = re.compile(r"^(?:then |now |and |also )*(?:(?:please |you )?(?:do|repeat|apply) (?:the same|that|this)(?: thing)?"
                   r"(?: again)?|(?:and )?(?:the )?same(?: thing)?(?: goes)?) (?:for|with|to) (.+?)(?: too| as well)?$")

#: Words by which a sentence asks for something, so it does not only describe.
_DESCRIBES_NOT = re.compile(r"\b(should|must|need|needs|has to|have to|is to|are to|want|wants|would|'d|like|to be|"
                            r"end up|ends up|goes|go|belong|belongs|please|can you|could you|let)\b")
#: Verbs of a sentence that says how things are.
_STATE_VERB = re.compile(r"\b(is|are|am|'m|was|were|keep|keeps|'s|seem|seems|look|looks|has|have|got|getting|"
                         r"been)\b")

#: "(which one is immaterial)", "(any of them)": a choice left open.
_ANY_ONE = re.compile(r"^(?:which|whichever|any|either)(?: one| of them| of the \w+)?(?: is| will| would)?(?: \w+)?"
                      r"(?: immaterial| irrelevant| fine| do| ok| okay| matter| matters)?$")

#: Words before an object that is named without being arranged ("except the plate", "the same colour as the mug").
_NOT_USED_BEFORE = frozenset({"except", "excluding", "but", "not", "than", "as", "from", "without", "instead", "minus",
                              "besides", "leave", "touch", "move", "like", "unlike", "match", "matches", "matching",
                              "nor", "neither", "apart", "other", "besides", "alike", "to", "with", "of"})

#: "leave X where it is", "don't move X": X stays where it is.
_LEAVE = re.compile(r"^(?:so |and |but |just |please )*(?:leave|don't move|do not move|don't touch|do not touch|"
                    r"never mind|ignore) (.+?)(?: where (?:it is|they are|it's|they're)| alone| in place| be| as (?:it is|"
                    r"they are)| untouched| as is)?(?: please)?$")

#: Plain colour words, said one after another for one object each ("red orange yellow").
_HUES = HUES


class _Parser:
    def __init__(self, spec: SceneSpec, matcher: PatternMatcher, options: RulesOptions) -> None:
        self.spec = spec
        self.vocab = Vocabulary.from_scene(spec)
        self.matcher = matcher
        self.options = options
        self.infos = matcher.infos()
        self.key_vocab = matcher.vocabulary
        self.state = _State()
        #: The readings that answered, one per clause read (:mod:`.readings`).
        self.fired: list[str] = []
        #: Every word of the scene's category names ("letter", "a", "block" ...).
        self._cat_words = frozenset(x for key in self.vocab.categories for x in key)
        #: The clause being read starts "B on it": what the clause before named goes below B.
        self._below_first = False
        #: The object "it" means in the part being read when "it" named a reference object just before.
        self._chain: int | None = None
        #: (subject, reference) of the part before, where the part being read has no object but "it".
        self._implicit: tuple | None = None
        #: The part being read has a side or depth and no support word: its "it" after "A left of B" is B.
        self._it_beside = False
        #: The one object named first in the part being read, where nothing was named before it:
        #: what "it" later in the part means ("the brown box needs to end up with both white
        #: things in front of it").
        self._first: Mention | None = None
        #: Each part read with its references, for the check that every object named by itself is
        #: used; the rewritten text.
        self._named_in: list[tuple[tuple[str, ...], list[Mention]]] = []
        self._said = ""
        #: The measures said in numbers (.stages.mark_measures) and those a goal took.
        self._measures: list = []
        self._measured: set[int] = set()
        #: The last goal read from a clause (a later clause with only a facing may be its).
        self._last_read: _Pending | None = None

    # ------------------------------------------------------------ one clause
    def _word_kinds(self) -> tuple[frozenset[str], frozenset[str]]:
        """Key words found only in anchored patterns, and only in the others."""
        if not hasattr(self, "_kinds"):
            from .matcher import content_words

            rel: set[str] = set()
            free: set[str] = set()
            for info in self.infos.values():
                if info.needs_pose:
                    continue
                for k in info.keys:
                    (rel if info.anchored else free).update(content_words(k))
            skip = FILLERS | _NOT_PATTERN
            self._kinds = (frozenset(rel - free - skip), frozenset(free - rel - skip))
        return self._kinds

    def _arrangements_named(self, phrase_words) -> set[str]:
        """The arrangements that words of the clause name outright: a word found
        in the keys of exactly one arrangement (not a generic word such as
        "arrange" or "shape"), and "on top of each other" for a tower."""
        if not hasattr(self, "_own_words"):
            from .matcher import content_words

            owner: dict[str, set[str]] = {}
            for name, info in self.infos.items():
                if info.anchored or info.needs_pose:
                    continue
                for k in info.keys:
                    for w in content_words(k):
                        owner.setdefault(w, set()).add(name)
            self._own_words = {w: next(iter(ps)) for w, ps in owner.items()
                               if len(ps) == 1 and w not in _GENERIC_KEY_WORDS}
        found = set()
        for w in phrase_words:
            p = self._own_words.get(w) or self._own_words.get(_stem(w))
            if p is not None:
                found.add(p)
        if re.search(r"\b(on top of|atop) (each other|one another)\b", " ".join(phrase_words)):
            found.add("tower")
        return found

    def _match(self, phrase: str, text: str, allowed: frozenset[str]):
        dirs = {_DIR_WORDS[w] for w in re.findall(r"[a-z]+", phrase.lower()) if w in _DIR_WORDS}
        up, down = r"(?:on top of|on|onto|above|over|atop|upon)", r"(?:under|underneath|below|beneath)"
        if any((-x, -y) in dirs for x, y in dirs) or re.search(
                rf"\b(?:{up} and {down}|{down} and {up})\b", phrase.lower()):
            # "both in front of and behind the bowl", "on top of and underneath the green one"
            raise InputError(f"contradiction: '{phrase}' names opposite directions")
        m = self.matcher.match(phrase, allowed=allowed)
        if not m and m.reason != "no arrangement is named" and "'" not in m.reason:
            # Words before the first word of a pattern key are the verb and its
            # company ("balance ... on", "should end up below", "put down left
            # of"): match from that word on.
            pw = phrase.split()
            first = next((k for k, w in enumerate(pw) if (any(f in self.key_vocab and f not in FILLERS for f in _forms(w))
                                                          and w not in STOPWORDS) or w in _DIR_WORDS), None)
            if first is not None and first > 0:
                while first > 0 and pw[first - 1] in ("to", "the", "on", "in", "at", "of", "a", "an"):
                    first -= 1
                if first > 0:
                    m2 = self.matcher.match(" ".join(pw[first:]), allowed=allowed)
                    if m2:
                        m = m2
                        phrase = " ".join(pw[first:])
        if m and m.pattern in RELATIONS:
            # Directions compose: the direction words of the phrase fix the
            # relation exactly ("at the back right of" is right_behind even
            # where the sentence model puts it nearer "front right of").
            d = _direction(phrase)
            if d is not None and d != m.pattern and d in allowed:
                m = replace(m, pattern=d)
        if not m:
            known = ", ".join(sorted(self.infos))
            if m.reason == "no arrangement is named":
                raise InputError(f"'{text}' does not say how to arrange the objects (known patterns: {known})")
            hint = f"; closest is '{m.runner_up}' ({m.score:.2f})" if m.runner_up else ""
            why = f" ({m.reason})" if m.reason.startswith("'") else ""
            raise InputError(f"no pattern in the database matches '{phrase or text}'{why}{hint}; known patterns: {known}")
        return m

    def _free_word(self, w: str) -> bool:
        """Whether ``w`` names a pattern that takes no anchor (a shape), by its keys or its embedding."""
        rel, free = self._word_kinds()
        st = _stem(w)
        if st in free or (st in self.key_vocab and st not in rel and st not in FILLERS and st not in _NOT_PATTERN):
            return True
        if st in rel or st in STOPWORDS or st in FILLERS or not w.isalpha() or len(w) < 4:
            return False
        p, _, _ = self.matcher.word_pattern(w)
        return p is not None and not self.infos[p].anchored

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
        for name, handler in EARLY:
            got = handler(self, f)
            if got is not None:
                self.fired.append(name)
                return got
        f = self._frame(f.words, f.text)
        for name, handler in READINGS:
            got = handler(self, f)
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
                self._free_word(w) or stages.is_mark(w) or w in _FACING_CUES for k, w in enumerate(words)
                if k not in inside) or (not mentions and self._last_read is not None):
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
        if p >= len(groups):
            raise InputError(f"'{text}': {words_rel} of what? name the reference object")
        anchor_sel = [x for s in sels[p] for x in (s if isinstance(s, list) else [s])]
        tower = self.state.tower.objects if self.state.tower is not None else []
        if (len(anchor_sel) == 1 and tower and anchor_sel[0] == tower[-1] and isinstance(tower[0], int) and any(
                isinstance(mm, Mention) and mm.det == "pronoun" and mm.text == "it" for mm in groups[p])):
            # "put the bowl on the plate and the cutlery beside it": beside the stack, named by its base.
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
        if len(anchor_sel) == 1 and isinstance(anchor_sel[0], int) and any(
                isinstance(mm, Mention) and mm.det == "pronoun" and mm.text == "it" for mm in groups[p]):
            self.state.it_chain = anchor_sel[0]
        return [_Pending(pattern, list(targets), a, None, text) for a in anchor_sel]

    def _shape(self, pattern: str, sels, words, gaps, text: str, phrase_words, *, vertical: str | None = None,
               roles: dict | None = None, defer_min: bool = False) -> _Pending:
        info = self.infos[pattern]
        if info.ordered and len(sels) >= 2:
            flat = [{x for y in g for x in (y if isinstance(y, list) else [y]) if isinstance(x, int)} for g in sels]
            later = set().union(*flat[1:])
            if flat[0] and flat[0] == later and sum(len(f) for f in flat[1:]) == len(later):
                # "stack the cups, yellow on orange": the set first, then its order.
                sels, gaps = sels[1:], gaps[1:] if gaps else gaps
            elif isinstance(sels[0][0], list) and len(sels[0]) > 1:
                # The same where the list ran the set and the first of its members together.
                head = {x for x in sels[0][0] if isinstance(x, int)}
                rest = [x for g in [sels[0][1:], *sels[1:]] for y in g for x in (y if isinstance(y, list) else [y])]
                if len(head) > 1 and all(isinstance(x, int) for x in rest) and sorted(rest) == sorted(head):
                    sels = [sels[0][1:], *sels[1:]]
        order = list(range(len(sels)))
        if info.ordered and len(sels) > 1:
            if vertical == "on" or (vertical is None and any(
                    any(tuple(words[lo:hi])[-n:] in _ON_WORDS for n in (1, 2, 3)) for lo, hi in gaps[1:-1] if hi > lo)):
                order.reverse()
        objs: list[int | Choice] = []
        for g in order:
            for s in sels[g]:
                for x in s if isinstance(s, list) else [s]:
                    if x not in objs:
                        objs.append(x)
                    elif info.ordered and isinstance(x, int) and not (roles and x in roles) and len(objs) > 1:
                        # "stack the red, blue and green blocks starting with green": a
                        # second mention whose part in the order is not read.
                        raise InputError(f"'{text}': object {x} is named twice and its place in the stack is "
                                         f"unclear; list the objects from the bottom up")
        downward = info.ordered and bool(re.search(r"\b(top to (the )?bottom|from the top|top down)\b", text))
        if downward:
            objs.reverse()
        if info.ordered and getattr(self, "_order_by", None) and all(isinstance(x, int) for x in objs):
            # "largest at the bottom": by volume, largest first (or smallest first).
            vol = {x[0]: x[2] for x in self.vocab.measures}
            objs = sorted(objs, key=lambda x: (-vol.get(x, 0.0) if self._order_by == "desc" else vol.get(x, 0.0), x))
            self._order_by = None
        if roles and pattern == "tower" and self._below_first:
            below = [x for x in self.state.last if x not in objs]
            objs = below + objs
            roles = {**roles, **{x: "bottom" for x in below}}
            self._below_first = False
        if roles:
            # Stack roles: bottom first, then "goes on it"/"next" in order, the
            # middle, the objects without a role, the top last.
            rank = {"bottom": 0, "next": 1, "middle": 2, None: 3, "top": 4}
            given = set(roles.values())
            if "middle" in given and "bottom" not in given:
                rank[None] = 1.5  # "B in the middle and C on top": the one left is at the bottom
            objs = sorted(objs, key=lambda x: rank.get(roles.get(x), 3))
            said = list(roles)
            for k, x in enumerate(said):
                if roles[x] == "under_it" and k and said[k - 1] in objs and x in objs:
                    # "purple on top, orange under it": right below the object named before it.
                    objs.remove(x)
                    objs.insert(objs.index(said[k - 1]), x)
            placed = [x for x in objs if roles.get(x) in ("bottom", "next")]
            self.state.tower_prev = placed[-1] if placed and pattern == "tower" else None
        n = sum(x.k if isinstance(x, Choice) else 1 for x in objs)
        if n < info.min_objects and not (pattern == "tower" and defer_min):
            noun = "object" if n == 1 else "objects"
            raise InputError(f"'{text}': a {pattern} needs at least {info.min_objects} objects, this names {n} {noun}")
        pose = None
        if info.needs_pose:
            nums = _numbers(tuple(phrase_words))
            if len(objs) != 1 or not isinstance(objs[0], int):
                raise InputError(f"'{text}': a {pattern} goal takes exactly one definite object")
            cur = self.spec.object(objs[0]).pose
            yaw = nums[2] if len(nums) > 2 else float(cur[2] if cur else 0.0)
            pose = (nums[0], nums[1], yaw)
        self.state.last = objs
        self.state.it_pair = None
        self.state.last_tower = pattern == "tower"
        self.state.last_anchor = None
        out = _Pending(pattern, objs, None, pose, text)
        if roles and pattern == "tower":
            out.said = {x: r for x, r in roles.items() if x in objs}
        self.state.tower = out if pattern == "tower" else None
        self.state.tower_fixed = pattern == "tower" and vertical is not None  # "A on B": that order is said
        self.state.last_shape = out
        self.state.downward = pattern == "tower" and downward
        return out

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
                if ex and not ex & own:
                    out = [[x for x in got if x not in ex] if isinstance(got, list) else got for got in out]
        return out

    def _select(self, m: Mention) -> list[int] | Choice:
        if m.det == "pronoun":
            if not self.state.last and self._first is not None and m.text in ("it", "its"):
                got = self._select(self._first)
                if isinstance(got, list) and len(got) == 1:
                    return got
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
        if m.det == "other" and m.names is None and not m.plural and self.state.choices:
            # "one mug ... the other one": the one of two that the first did not take.
            prev = self.state.choices[-1]
            if prev.k == 1 and len(prev.options) == 2:
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
                    nxt = next((mm for mm in mentions if mm.start == end), None)
                    if nxt is not None:
                        end = nxt.end
                    raise InputError(f"nothing in the scene matches '{' '.join(words[j:end])}' (no {w} object)")
                raise InputError(f"'{' '.join(words[j:end])}' names nothing in the scene")

    def _pattern_word(self, w: str) -> bool:
        """Whether ``w``, in no key, still names a pattern by its embedding ("perimeter")."""
        if not w.isalpha() or len(w) < 3:
            return False
        p, _, unsupported = self.matcher.word_pattern(w)
        return p is not None

    # ------------------------------------------------------------ the command
    def _find(self, words: tuple[str, ...], key_vocab=None) -> list[Mention]:
        """The object references of ``words``, bare colours completed by the nouns named before."""
        return find_mentions(self.vocab, words, self.key_vocab if key_vocab is None else key_vocab,
                             tuple(self.state.nouns))

    def _category_ids(self, text: str) -> str:
        """"blocks 4, 5 and 6", "the bowl 7": ids given after their category, read as
        "objects 4, 5 and 6" when every number is the id of an object of that category."""
        def ids(m: re.Match) -> str:
            noun, nums = m.group(1).lower(), [int(x) for x in re.findall(r"\d+", m.group(2))]
            kinds = {i: n for i, n, _ in self.vocab.objects}
            if all(i in kinds and kinds[i] in (noun, _stem(noun)) for i in nums):
                return ("objects " if len(nums) > 1 else "object ") + m.group(2)
            return m.group(0)

        return re.sub(r"(?i)\b([a-z]+) (\d+(?:\s*,\s*\d+)*(?:,?\s+and\s+\d+)?)\b(?!\s*(?:cm|mm|m|centimet|metre|meter|inch|%))",
                      ids, text)

    def _spoken_lists(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """Lists said without commas ("the red the blue and the orange blocks") get
        them; "toy" before a category ("the toy blocks") is dropped."""
        colour = lambda w: w in self.vocab.color_words or w in COLOUR_WORDS  # noqa: E731
        out: list[str] = []
        for k, w in enumerate(words):
            if w == "the" and out and colour(out[-1]):
                out.append(",")
            if (w in _HUES and out and out[-1] in _HUES
                    and not any(f"{out[-1]} {w}" in c for c in self.vocab.colors.values())):
                out.append(",")  # "bottom to top red orange yellow": one object per colour
            if (w == "and" and k >= 2 and words[k - 2] in ("every", "each", "all") and k + 1 < len(words)
                    and words[k - 1] in self._cat_words and words[k + 1] in self._cat_words):
                out.extend(["and", words[k - 2]])  # "every cup and bowl": every cup and every bowl
                continue
            if w == "toy" and k + 1 < len(words) and (words[k + 1] in self._cat_words
                                                     or _stem(words[k + 1]) in self._cat_words):
                continue
            out.append(w)
        return tuple(out)

    def _bare_colour_sets(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """Colours standing for objects after a negation: "neither purple nor orange"
        -> "not purple or orange"; "not red and not blue" -> "not red or blue";
        "except yellow and orange" -> "except the yellow and orange ones"."""
        colour = lambda w: w in self.vocab.color_words or w in COLOUR_WORDS  # noqa: E731
        out = list(words)
        k = 0
        while k < len(out):
            if out[k] == "neither" and k + 1 < len(out) and colour(out[k + 1]):
                out[k] = "not"
            if out[k] == "nor" and k > 0 and colour(out[k - 1]):
                out[k] = "or"
            if out[k : k + 2] == ["and", "not"] and k > 0 and colour(out[k - 1]) and k + 2 < len(out) \
                    and colour(out[k + 2]) and any(out[j] == "not" for j in range(max(0, k - 4), k)):
                out[k : k + 2] = ["or"]
            k += 1
        res: list[str] = []
        k = 0
        while k < len(out):
            res.append(out[k])
            lead = out[k] in ("except", "excluding", "minus") or tuple(out[max(0, k - 1) : k + 1]) in (
                ("apart", "from"), ("other", "than"), ("except", "for"), ("but", "not"))
            if lead and k + 1 < len(out) and colour(out[k + 1]):
                j = k + 1
                while j < len(out) and (colour(out[j]) or out[j] in (",", "and", "or")):
                    j += 1
                while out[j - 1] in (",", "and", "or"):
                    j -= 1
                nxt = out[j] if j < len(out) else ""
                if not self._content_word(nxt) or nxt in _ASIDE_KEEP or nxt in _DIR_WORDS or nxt in self.key_vocab:
                    res.extend(["the", *out[k + 1 : j], "ones"])
                    k = j
                    continue
            k += 1
        return tuple(res)

    def _arrangement_refs(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """"put that row to the left of the plate", "do it at the front, keep it
        small": an arrangement read before, named by its pattern word or "it"."""
        shape = self.state.last_shape
        if shape is None or not all(isinstance(x, int) for x in shape.objects):
            return words
        nouns = {"line": ("line", "row", "file", "queue"), "circle": ("circle", "ring", "loop"),
                 "rectangle": ("rectangle", "square", "box"), "tower": ("tower", "stack", "pile")}.get(shape.pattern, ())
        out = list(words)
        for k in range(len(out) - 1):
            if out[k] in ("that", "this", "the") and out[k + 1] in nouns and not (
                    k > 0 and out[k - 1] in ("in", "into", "as", "form", "make", "a", "behind", "of", "beside", "to",
                                             "near", "on", "onto", "above", "under", "below", "around", "with")):
                out[k : k + 2] = ["them", ""]
        out = [w for w in out if w]
        if tuple(out) != words:
            self.state.last, self.state.last_tower = list(shape.objects), False
            self.state.it_pair = None
        # "do it at the front of the table", "keep it small": its place or size.
        rest = [w for w in out if w not in ("do", "keep", "make", "it", "them", "please", "put", "place", "have", "move",
                                            "set", "all")]
        if rest and out[0] in ("do", "keep", "make", "put", "place", "move", "set", "have") and any(
                w in ("it", "them") for w in out[:3]) and list(self.state.last) == list(shape.objects):
            size = next((SIZES[w] for w in rest if w in SIZES), None)
            params, left = take_params(tuple(rest), lambda w: False)
            if size is not None:
                params["size"] = size
                left = tuple(w for w in left if w not in SIZES)
            if params and not [w for w in left if w not in STOPWORDS and w != ","]:
                _add_params(shape, params, " ".join(words))
                return ()
        return tuple(out)

    def _spelled(self, text: str, letters: set[str]) -> str:
        """"stack the letters so that, read from the bottom up, they spell RATE": the
        stack of those letters in that order. Without the direction the reading is
        open (a word on a stack reads either way), so it is refused."""
        parts = re.split(r"(?<=[.;!?])\s+", text)
        for k, sent in enumerate(parts):
            m = re.search(r"\b(?i:spell|spells|spelling|spelt|reads?|reading|say|says)(?i: out)?(?i: the word)?\s*:?\s*"
                          r"([A-Z](?:\s+[A-Z]){1,9}|[A-Z]{2,10})\b", sent)
            if m is None or not re.search(r"(?i)\b(?:stack|stacked|tower|pile|piled)\b", sent):
                continue
            word = re.sub(r"\s", "", m.group(1)).upper()
            if not (len(set(word)) == len(word) and set(word) <= letters):
                continue
            up = re.search(r"(?i)\b(?:bottom up|bottom upwards?|from (?:the )?bottom|bottom to top|upwards?|going up)\b", sent)
            down = re.search(r"(?i)\b(?:top down|top downwards?|from (?:the )?top|top to bottom|downwards?|going down)\b", sent)
            if bool(up) == bool(down):
                raise InputError(f"'{sent.strip()}': say whether '{word}' reads from the bottom up or from the top down")
            order = word if up else word[::-1]
            named = [f"the letter {c}" for c in order]
            parts[k] = "stack " + ", ".join(named[:-1]) + f" and {named[-1]}, from the bottom up."
        return " ".join(parts)

    def _articles(self, text: str) -> str:
        """"red can should have the blue bowl behind it", "move blue mug so red mug sits
        on its left": a singular object named without its article, at the start of a
        sentence or right after a command verb, is read as if "the" were said ("can"
        and "a" only after a colour)."""
        colours = _HUES | set(self.vocab.color_words)

        def one(m: re.Match) -> str:
            ws = m.group(2).split()
            k = 0
            while k < len(ws) and ws[k].lower() in colours:
                k += 1
            noun = ws[k].lower() if k < len(ws) else ""
            if noun in self._cat_words and not noun.endswith("s") and len(noun) > 1 and (
                    k > 0 or (noun not in STOPWORDS and noun not in ("can", "a", "i"))) and (
                    k + 1 == len(ws) or ws[k + 1].lower() not in self._cat_words):
                return f"{m.group(1)}the {m.group(2)}"
            return m.group(0)
        return _ARTICLE_AT.sub(one, text)

    def _former_latter(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """"take the spoon and the fork; put the former in front of the latter":
        "the former" / "the latter" replaced by the two references named before."""
        # "the first one" / "the second one" after two references mean the same ("put the first one on
        # top of the second one"), where they are not stack roles ("the first one goes at the bottom").
        ordinal = {"first": "former", "second": "latter"}
        words = tuple(w for k, w in enumerate(words) if not (w == "one" and k >= 2 and words[k - 1] in ordinal
                                                             and words[k - 2] == "the"))
        words = tuple(ordinal.get(w, w) if k and words[k - 1] == "the" and (
            k + 1 >= len(words) or words[k + 1] in ("on", "onto", "under", "in", "behind", "to", "next", "left",
                                                   "right", "beside", "below", "above", "of", "and", ",", ".")) else w
            for k, w in enumerate(words))
        at = [k for k in range(len(words) - 1) if words[k] == "the" and words[k + 1] in ("former", "latter")]
        if not at:
            return words
        try:
            named = [m for m in self._find(words[: at[0]]) if m.det not in ("pronoun",)]
        except InputError:
            return words
        if len(named) < 2:
            return words
        pair = {"former": words[named[-2].start : named[-2].end], "latter": words[named[-1].start : named[-1].end]}
        out: list[str] = []
        k = 0
        while k < len(words):
            if k in at:
                ref = pair[words[k + 1]]
                out.extend(ref if ref[0] in ("the", "a", "an") else ("the",) + ref)
                k += 2
                continue
            out.append(words[k])
            k += 1
        return tuple(out)

    def _spelled_right(self, text: str) -> str:
        """The text with misspellings corrected against the scene and the parser's words (.spelling)."""
        lexicon = (set(self.key_vocab) | _COMMAND_VERBS | set(_DIR_WORDS) | set(ROWS) | set(COLS) | set(FACINGS)
                   | REGION_NOUNS | set(SIZES) | COLOUR_WORDS | set(GROUPS) | _ROLE_WORDS | _SUPERLATIVE
                   | _MEASURE_WORDS | _FACING_CUES | POINTING_PARTS | frozenset(UNITS) | _PLACE_WORDS | {"behind", "between", "beside", "next", "above", "below", "under", "onto",
                                       "everything", "object", "objects", "please", "square", "center", "centre"})
        nouns = {w for w in self.key_vocab if w.isalpha() and len(w) > 2} - STOPWORDS - FILLERS
        protect = STOPWORDS | FILLERS | NUMBERS.keys() | _SHAPES_PROTECT | _ATTRS.keys()
        return stages.spell(text, self.vocab, lexicon, nouns, protect)

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
        if _is_number(w) or w.startswith("#") or stages.is_mark(w) or w in BAND_MARKS:
            return True
        if w in self.vocab.color_words or w in COLOUR_WORDS or w in self._cat_words or st in self._cat_words:
            return True
        if (st in self.key_vocab and st not in FILLERS) or w in _DIR_WORDS or w in _COMPASS_LEFT or w in _ASIDE_KEEP:
            return True
        return (w in _COMMAND_VERBS or w in SIZES or w in ROWS or w in COLS or w in FACINGS or w in REGION_NOUNS
                or w in ("stacked", "piled", "lined"))

    def _topic_split(self, clause: tuple[str, ...]) -> list[tuple[str, ...]]:
        """"the bowls, stack them with the white one at the bottom", "the green can
        move it so ...": a reference put first, then a command about it by a pronoun."""
        start = 2 if clause[:2] == ("you", "know") else 0
        try:
            ms = self._find(clause[start:])
        except InputError:
            return [clause]
        if not ms or ms[0].start != 0 or ms[0].det == "pronoun":
            return [clause]
        j = start + ms[0].end
        while j < len(clause) and clause[j] in (",", "and", "so", "then"):
            j += 1
        while j < len(clause) and clause[j] in ("just", "please", "now", "then", "can", "could", "you"):
            j += 1
        rest = clause[j:]
        if (rest and (rest[0] in _COMMAND_VERBS or rest[0] in ("it", "they", "them") or (
                rest[0].isalpha() and rest[0] not in STOPWORDS and rest[0] not in _GOAL_WORDS
                and rest[0] not in _NOT_JOIN and rest[1:2] in (("it",), ("them",))))
                and any(w in ("it", "them", "they") for w in rest[:6])):
            return [clause[start : start + ms[0].end], rest]
        if (clause[start + ms[0].end : start + ms[0].end + 1] == (",",) and rest
                and any(w in ("it", "them", "they", "those", "these") for w in rest)):
            # "the tiger pan, the star must be sitting on top of it", "the plate, you
            # are putting the spoon next to it": a topic, then a sentence about it.
            return [clause[start : start + ms[0].end], rest]
        return [clause]

    def _select_noting(self, mentions) -> list[int | Choice]:
        """What ``mentions`` select, in order and once each, their nouns noted for later references."""
        got: list[int | Choice] = []
        for m in mentions:
            sel = self._select(m)
            got.extend(x for x in (sel if isinstance(sel, list) else [sel]) if x not in got)
            self._note_nouns([m])
        return got

    def _remember(self, clause: tuple[str, ...]) -> None:
        """Let later pronouns and bare colours refer to what a dropped remark names."""
        try:
            got = self._select_noting(self._find(clause))
        except InputError:
            return
        if got:
            self.state.last, self.state.last_tower = got, False
            self.state.it_pair = None

    def _remark(self, clause: tuple[str, ...]) -> bool:
        """A sentence that asks for nothing: no pattern, direction, stacking, place,
        size or order word and no command verb, but words besides its object
        references ("the bottles are a mess", "I find it easier to reach")."""
        lead = next((w for w in clause if w not in _LEADING and w not in STOPWORDS), "")
        try:
            named = [m for m in self._find(clause) if m.det != "pronoun"]
        except InputError:
            named = [None]
        counted = {k for m in named if m is not None for k in range(m.start, m.end)}  # "the three cans"
        goal = ((lead in _COMMAND_VERBS or lead in _SELECT_VERBS) and bool(named)) or any(
            (any(f in self.key_vocab and f not in FILLERS for f in _forms(w)) and w not in STOPWORDS)
            or w in _DIR_WORDS or w in _COMPASS_LEFT or w in _VERT_WORDS - {"to", "of"} or w in SIZES or w in ROWS
            or w in COLS or w in FACINGS or w in ("order", "first", "last", "then", "facing")
            or (_is_number(w) and k not in counted)
            for k, w in enumerate(clause))
        if goal:
            return False
        try:
            ms = self._find(clause)
        except InputError:
            ms = []
        inside = {k for m in ms for k in range(m.start, m.end)}
        return any(w.isalpha() and k not in inside and w not in STOPWORDS and _stem(w) not in FILLERS
                   and not self._content_word(w) and w not in _ROLE_WORDS for k, w in enumerate(clause))

    def _without_asides(self, clause: tuple[str, ...]) -> tuple[str, ...]:
        if clause[:2] in (("there", "are"), ("there", "is"), ("we", "have"), ("you", "have"), ("i", "have")) and not any(
                (_stem(w) in self.key_vocab and _stem(w) not in FILLERS) or w in _DIR_WORDS for w in clause):
            self._remember(clause)  # "there are two bottles": a remark whose noun "the white one" may take
            return ()
        """``clause`` without its comma-separated asides: a part that names no
        object, pattern, direction, place, size or order ("ok robot", "here is
        the plan", "if it is not too much trouble", "could you do that")."""
        if self._remark(clause):
            self._remember(clause)  # "the bottles are a mess. could you stick them ...": them
            return ()
        parts: list[list[str]] = [[]]
        for w in clause:
            if w == ",":
                parts.append([])
            else:
                parts[-1].append(w)
        if len(parts) == 1 and not any(self._content_word(w) for w in parts[0]):
            return ()
        kept = [p for p in parts if any(self._content_word(w) for w in p) and not (len(parts) > 1 and self._free_order(tuple(p)))]
        if len(kept) > 1:
            # ", just a straight row is fine", ", single file": a part naming again, with no object,
            # the arrangement another part already names.
            said = [self._part_patterns(p) for p in kept]
            kept = [p for k, p in enumerate(kept) if not (
                said[k] and not self._names_objects(p)
                and not any(w in SIZES or w in ROWS or w in COLS or w in FACINGS or w in REGION_NOUNS
                            or w in _COMPASS_LEFT or w in ("facing", "pointing", "little", "tiny", "big") for w in p)
                and said[k] <= set().union(*(said[j] for j in range(len(kept)) if j != k)))]
        if len(kept) == len(parts):
            return clause
        out: list[str] = []
        for p in kept:
            out.extend(([","] if out else []) + p)
        return tuple(out)

    def command(self, text: str) -> GoalSpec:
        # A stack ordered by an attribute ("in order of size"): which object goes
        # lowest is not fixed by the words read here; refused below if a stack results.
        text = self._spelled_right(text)
        text, self._measures = stages.mark_measures(text)
        text = stages.other_side(stages.said_places(stages.said_facings(text)))
        text = unframe(text)
        order_by = _ORDER_BY.search(text)
        # The order along a line ("from left to right") is not part of any goal.
        text = re.sub(r"(?i)\b(from )?(the )?(left to( the)? right|right to( the)? left|front to( the)? back|back to( the)? front)\b", " ", text)
        text = re.sub(r"(?i)\b(from|by) (the )?(shortest|smallest|tallest|largest|biggest|lightest|darkest) to (the )?"
                      r"(shortest|smallest|tallest|largest|biggest|lightest|darkest)\b", " ", text)
        bare = re.sub(r"(?i)^\s*(?:(?:hmm+|um+|uh+|so|well|ok(?:ay)?|hey|hi|oh|right|now)\b[,\s]*)+", "", text)
        question = QUESTION.match(bare) or re.search(r"(?i)\b(?:do|don't) you think\s*\?\s*$", bare)
        cond = re.match(r"(?i)^\s*(?:if|unless|in case|when(?:ever)?)\s+(?:the|a|an|any|there|all|both|every|no|it|they)\b"
                        r"(?!\s*(?:is|'s|isn't|is not)?\s*(?:not )?(?:too much|possible|ok|okay|alright|convenient|no)"
                        r"\b)", bare)
        if cond is not None:
            raise InputError(f"'{text.strip()}': a command that depends on a condition is not read; "
                             f"say what to arrange")
        if question is not None and not ASKS_TO_ACT.match(bare):
            raise InputError(f"'{text.strip()}' is a question about the scene, not a command; say what to arrange")
        text = stages.by_position(text, self._find, self._every_match, self._table_xy, self._centre, self._cat_words,
                                  dict(self.vocab.borrowed))
        text = stages.by_colour(text, self._find, self._every_match, {o.id: o.color for o in self.spec.objects})
        text = rewrite(self._articles(text))
        self._said = text
        text = self._category_ids(text)
        letters = {n.split()[1].upper() for _, n, _ in self.vocab.objects if n.startswith("letter ") and len(n.split()) == 2}
        if letters:
            text = self._spelled(text, letters)
        if letters:
            # "the T", "the A": a capital letter standing for the letter the scene has.
            text = re.sub(r"\b([Tt]he) ([A-Z])\b(?!')", lambda m: f"{m.group(1)} letter {m.group(2)}"
                          if m.group(2) in letters else m.group(0), text)
            # "A then R then T then E", "R, T, E": capitals said bare ("A" only where it cannot be
            # the article: after a list word, or before one or the end).
            text = re.sub(r"\b([A-Z])\b(?!')", lambda m: _bare_letter(m, letters), text)
        words = normalise(tuple(t.text for t in tokenize(text)))
        if not any(w.isalnum() for w in words):
            raise InputError("the instruction is empty")
        words = self._spoken_lists(words)
        for k, w in enumerate(words[:-1]):
            nxt = words[k + 1]
            if (w == "no" and (nxt in ("objects", "object", "things", "thing", "items", "item") or (
                    nxt not in ("particular", "order", "matter", "wait") and (
                        nxt in self._cat_words or _stem(nxt) in self._cat_words or nxt in COLOUR_WORDS)))) or (
                    w == "none" and nxt == "of"):
                raise InputError(f"'{w} {nxt}': a reference to no object selects nothing to arrange")
        words = self._parentheses(words)
        words = stages.without_context(words, self._object_word, self._request_word)
        words = self._context_sentences(words)
        words = self._trailing_remarks(words)
        words = self._former_latter(words)
        words = self._bare_colour_sets(words)
        # Words that may be read by their own embedding, encoded in one batch
        # (one forward pass for all of them instead of one per word).
        cand = [w for w in dict.fromkeys(words) if w.isalpha() and len(w) >= 4 and _stem(w) not in self.key_vocab
                and not stages.is_mark(w)
                and _stem(w) not in STOPWORDS and _stem(w) not in FILLERS and w not in STOPWORDS
                and (w,) not in self.vocab.categories and w not in self.vocab.color_words and w not in COLOUR_WORDS]
        if cand:
            self.matcher.prefetch(cand)
        dinner = self._dinner(words)
        if dinner is not None:
            return self._finish(dinner)
        clauses = split_clauses(words, self._cat_words)
        pending: list[_Pending] = []
        if self._dinner_at(words) is not None:
            # "set the table, and put the mug behind the plate as well": the
            # setting from the clauses about it, the other clauses as usual.
            # Where the scene has no setting to lay, "set the table" only
            # introduces what follows ("set the table: stack the bowl on the plate ...").
            own = [c for c in clauses if self._dinner_at(c) is not None or self._setting_only(c)]
            try:
                dinner = self._dinner(tuple(w for c in own for w in c + (",",))[:-1])
            except InputError:
                dinner = []
            if dinner is None:
                # "the table laid for a meal, and the mug should be behind the plate": the
                # setting up to the first break after it, the rest a clause of its own.
                at = next(c for c in clauses if self._dinner_at(c) is not None)
                k = self._dinner_at(at)
                cut = next((j for j in range(k + 1, len(at)) if at[j] in (",", "and", "plus", "with", "but")), None)
                if cut is not None:
                    head, tail = at[:cut], at[cut:]
                    while tail and tail[0] in (",", "and", "plus", "with", "but", "also"):
                        tail = tail[1:]
                    try:
                        alone = self._dinner(head) if tail and not self._setting_only(tail) else None
                    except InputError:
                        alone = None
                    if alone:
                        dinner, own = alone, [c for c in own if c is not at]
                        clauses = [tail if c is at else c for c in clauses]
            if dinner is None:
                raise InputError(f"'{' '.join(words)}': cannot tell which parts belong to the place setting")
            if dinner:
                pending.extend(dinner)
                clauses = [c for c in clauses if c not in own]
        kept = [c for c in (c if _SAME.match(" ".join(c)) else self._without_asides(c) for c in clauses)
                if c and not self._free_order(c) and not self._left_alone(c)]
        if clauses and not kept:
            raise InputError(f"'{' '.join(words)}' names no object in the scene and no arrangement")
        kept = _merged_moves([c for k in kept for c in self._topic_split(k)])
        last: tuple[str, ...] = ()
        for whole in kept:
            try:
                stated = _predicate_split(whole, self._find(whole), *self._word_kinds())
            except InputError:
                stated = [whole]
            for clause in stated:
                before = len(pending)
                self._read_clause(self._same_as_before(clause, last), pending)
                if len(pending) > before:
                    last = clause
        setting = dinner if isinstance(dinner, list) else []
        side = next((p for p in setting if p.pattern in ("left", "right")), None)
        stack = set(next((p.objects for p in setting if p.pattern == "tower"), []))
        if side is not None and any(p is not side and p.pattern in RELATIONS and set(p.objects) == set(side.objects)
                                    and p.anchor in stack | {side.anchor} for p in pending):
            # "get dinner ready: the bowl on the plate and the cutlery on the right of it": the side said.
            pending.remove(side)
        if self.state.header is not None and self.state.header[0] == "tower" and any(
                p.pattern == "tower" for p in pending):
            # "build a single tower: A on B, and B on C": the steps built it.
            hparams = self.state.header[1]
            for p in pending:
                if p.pattern == "tower":
                    p.params = {**hparams, **p.params}
            self.state.header = None
        if self.state.header is not None:
            raise InputError(f"'{self.state.header[2]}' names no object in the scene")
        if order_by is not None and any(p.pattern == "tower" for p in pending):
            raise InputError(f"'{order_by.group(0)}': a stacking order by size, colour or sorting is not read; "
                             f"name the objects from the bottom up")
        if not pending:
            if self.state.selection is not None:
                raise InputError("the instruction selects objects but does not say how to arrange them")
            raise InputError("the instruction names nothing to arrange")
        return self._finish(pending)

    # ------------------------------------------------------------ dinner
    _DINNER = (("set", "the", "table"), ("set", "a", "table"), ("lay", "the", "table"), ("set", "up", "the", "table"),
               ("dinner",), ("place", "setting"), ("table", "setting"), ("set", "a", "place"), ("plate", "setting"),
               ("lay", "a", "place"), ("table", "set"), ("setting", "for", "one"), ("cover", "for", "one"),
               ("place", "is", "laid"), ("place", "laid"), ("table", "laid"), ("table", "should", "be", "set"),
               ("table", "is", "set"), ("place", "settings"))

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
                                   and not any(w in _VERT_WORDS - {"to", "of"} for w in sub))
                self._first = None
                if not self.state.last and own and own[0].det == "the" and not own[0].plural and any(
                        m.det == "pronoun" and m.text in ("it", "its") for m in own[2:]) and not any(
                        w in _DIR_WORDS or w in _VERT_WORDS - {"to", "of"} for w in sub[own[0].end : own[1].start]):
                    self._first = own[0]
                read = self.clause(sub)
                pending.extend(read)
                if read:
                    self._last_read = read[-1]
                self._implicit = None
                self._first = None
                try:
                    named = self._find(sub)
                except InputError:
                    named = []
                self._note_nouns(reversed(named))
                self._named_in.append((sub, named))

    def _same_as_before(self, clause: tuple[str, ...], last: tuple[str, ...]) -> tuple[str, ...]:
        """"do the same with the yellow letter and the yellow block", "same for the
        mugs": the clause before, its first references replaced by the new ones
        (all of them where as many are named; else the objects placed, so the
        reference object stays)."""
        m = _SAME.match(" ".join(clause))
        if m is None:
            return clause
        if not last:
            raise InputError(f"'{' '.join(clause)}': the same as what? nothing was asked before it")
        rest = tuple(m.group(1).split())
        new = self._find(rest)
        old = self._find(last)
        if not new or len(new) > len(old):
            raise InputError(f"'{' '.join(clause)}': cannot tell which objects take the places of which")
        out = list(last)
        for a, b in reversed(list(zip(old, new))):
            out[a.start : a.end] = rest[b.start : b.end]
        return tuple(out)

    def _parentheses(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """Parentheses that add nothing are dropped ("(which one is immaterial)",
        "(order immaterial)"); parentheses that list the objects of the phrase
        before them ("the dishes (the plate and the three bowls)", "cans (red,
        white, green)") are dropped where they name the same objects and replace
        the phrase where they name some of them. Others stay, and are refused."""
        out = list(words)
        while "(" in out and ")" in out[out.index("(") :]:
            a = out.index("(")
            b = out.index(")", a)
            inner = tuple(out[a + 1 : b])
            if (not inner or self._free_order(inner) or _ANY_ONE.match(" ".join(inner))
                    or not any(self._content_word(w) for w in inner)
                    or (self._dinner_at(inner) is not None and self._dinner_at(tuple(out[:a])) is not None
                        and not self._find(inner))):
                out[a : b + 1] = []
                continue
            before = tuple(out[:a])
            try:
                outer = next((m for m in self._find(before) if m.end == a and m.det != "pronoun"), None)
                if outer is None:
                    break
                own = find_mentions(self.vocab, inner, self.key_vocab,
                                    (outer.names,) if outer.names is not None else ())
                inside = {k for m in own for k in range(m.start, m.end)}
                if not own or any(k not in inside and w not in (",", "and", "all", "both") and not _is_number(w)
                                  for k, w in enumerate(inner)):
                    break
                whole = set(candidates(self.vocab, replace(outer, det="all", plural=True)))
                named = {o for m in own for o in candidates(self.vocab, replace(m, det="all", plural=True))}
            except InputError:
                break
            if named == whole or (outer.det == "all" and named == set(candidates(self.vocab, outer))):
                out[a : b + 1] = []
            elif named < whole:
                self._note_nouns([outer])
                out[outer.start : b + 1] = list(inner)
            else:
                break
        return tuple(out)

    def _context_sentences(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """Sentences before the request that only describe how things are ("the
        white bowl is in my way.", "i keep knocking the blue mug over.", "the mug,
        the cup and the bottle are crowding the plate.") ask for nothing: they are
        dropped, and what their subject names is what a later "it"/"them" means."""
        sentences = _sentences(words, (".", "!", "?", ";"))
        dropped = 0
        for sent in sentences[:-1]:
            if not self._describes(sent[:-1]):
                break
            self._remember_subject(sent[:-1])
            dropped += len(sent)
        return words[dropped:]

    def _trailing_remarks(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """Sentences after the request that name no object and only remark on it
        ("I'm clearing up, you see.", "Which goes where is totally up to you!",
        "Remember, a square is just a rectangle with equal sides.", "Go!") ask for
        nothing: they are dropped. A sentence with a place, size, facing or order
        word ("At the front.", "Any order.") is kept."""
        sentences = _sentences(words, (".", "!", "?"))
        if len(sentences) < 2:
            return words
        out: list[str] = []
        asked = False
        for sent in sentences:
            body = [w for w in sent if w not in (",", ".", "!", "?", "'")]
            while body and body[0] in _LEADING:
                body = body[1:]
            try:
                named = self._find(tuple(body)) if body else []
            except InputError:
                named = [None]
            if asked and body and not named and not _command_verb(body[0]) and not any(
                    w in SIZES or w in ROWS or w in COLS or w in _ROLE_WORDS or w in _DIR_WORDS
                    or w in ("order", "first", "last", "then", "facing", "instead", "too", "also") for w in body) and (
                    _STATE_VERB.search(" ".join(body)) or re.search(
                        r"\b(?:go|see|mean|mind|care|know|think|remember|wins?|done|cheers|thanks|thank|please)\b",
                        " ".join(body))):
                continue
            asked = asked or bool(named)
            out.extend(sent)
        return tuple(out)

    def _describes(self, sent: tuple[str, ...]) -> bool:
        """Whether ``sent`` states how things are rather than asking for anything."""
        body = [w for w in sent if w not in (",", "'")]
        while body and body[0] in _LEADING:
            body = body[1:]
        if len(body) < 2 or _command_verb(body[0]) or body[0] in ("let", "lets", "let's", "go", "i'd", "we'd"):
            return False
        text = " ".join(body)
        if _DESCRIBES_NOT.search(text) or any(cue.search(text) for cue, _ in _CUES):
            return False
        if not (_STATE_VERB.search(text) or body[0] in ("i", "i'm", "we", "time", "there", "it's", "this", "that")):
            return False
        try:
            inside = {k for m in self._find(tuple(body)) for k in range(m.start, m.end)}
        except InputError:
            inside = set()
        for k, w in enumerate(body):
            if k in inside or w in STOPWORDS or w in ("before", "after", "until", "while", "when"):
                continue  # "before guests come over": a time, not a place
            nxt = body[k + 1] if k + 1 < len(body) else ""
            if w == "over" and nxt not in ("the", "a", "an", "it", "them") and k + 1 not in inside:
                continue  # "knocking the mug over", "all over the place" is below
            if w in ROWS or w in COLS:
                # "in the middle", "at the back" say where; "cluttering the middle" only describes.
                if k and (body[k - 1] in ("in", "at", "on", "to", "into") or (
                        body[k - 1] == "the" and k > 1 and body[k - 2] in ("in", "at", "on", "to", "into"))):
                    return False
                continue
            if (w in _VERT_WORDS - {"to", "of", "over"} or w in _DIR_WORDS or w in SIZES or _is_number(w)
                    or w in _ROLE_WORDS or w in ("order", "first", "last", "then", "facing")):
                return False
            st = _stem(w)
            if st in self.key_vocab and st not in FILLERS and st not in _GENERIC_KEY_WORDS:
                return False
        return True

    def _remember_subject(self, sent: tuple[str, ...]) -> None:
        """Remember what the subject of a describing sentence names (all its
        references where it starts with none: "there are two bottles")."""
        try:
            ms = [m for m in self._find(sent) if m.det != "pronoun"]
        except InputError:
            return
        lead: list = []
        for m in ms:
            gap = sent[lead[-1].end : m.start] if lead else sent[:m.start]
            if all(w in ("the", ",", "and", "both", "all") for w in gap) and (lead or all(w in _LEADING or w == "the"
                                                                                       for w in gap)):
                lead.append(m)
            else:
                break
        chosen = lead or ms
        if chosen:
            self._remember(sent[chosen[0].start : chosen[-1].end])

    def _unused_object(self, goals: list[dict]) -> None:
        """Refuse a command that names one object by itself ("the red mug") where no goal
        read from it uses that object: a part of the command was not read."""
        used = {o for g in goals for o in g["objects"]} | {g["anchor"] for g in goals if "anchor" in g}
        used |= {o for g in goals for o in g.get("anchor_any", ())}
        stacked = any(g["pattern"] == "tower" for g in goals)
        for clause, ms in self._named_in:
            for m in ms:
                group = m.plural and m.det in ("the", "all") and m.names is not None and not m.head
                bare = m.names is None and bool(m.colors) and stacked  # "then blue" said in a stack and lost
                if not group and (m.det != "the" or m.plural or (m.names is None and not bare) or m.head):
                    continue
                before = clause[max(0, m.start - 3) : m.start]
                if any(w in _NOT_USED_BEFORE for w in before):
                    continue
                try:
                    got = candidates(self.vocab, m)
                except InputError:
                    continue
                if group and got and not set(got) & used:
                    # "letters: column; blocks: square": the letters are named, and nothing is read for them.
                    raise InputError(f"'{m.text}' are named but no goal read from the command uses them; "
                                     f"say what to do with them")
                if len(got) == 1 and got[0] not in used:
                    raise InputError(f"'{m.text}' is named but no goal read from the command uses it; "
                                     f"say what to do with it")

    def _left_alone(self, clause: tuple[str, ...]) -> bool:
        """"leave the plate and the bowl where they are", "so leave it", "don't touch
        the phone": objects that stay put. Nothing to arrange; later pronouns may
        refer to them, and "everything else" leaves them out."""
        m = _LEAVE.match(" ".join(clause))
        if m is None:
            return False
        rest = tuple(m.group(1).split())
        try:
            ms = self._find(rest)
        except InputError:
            return False
        inside = {k for x in ms for k in range(x.start, x.end)}
        if not ms or any(k not in inside and w not in (",", "and", "both") for k, w in enumerate(rest)):
            return False
        # Unlike a remark's, these references must resolve: "leave the bowl" with three bowls is refused.
        got = [o for o in self._select_noting(ms) if isinstance(o, int)]
        self.state.last, self.state.last_tower, self.state.it_pair = list(got), False, None
        self.state.named.update(got)
        return True

    def _part_patterns(self, part: list[str]) -> set[str]:
        """The arrangements (not relations) the words of ``part`` name by themselves."""
        out = set()
        for w in part:
            if not w.isalpha() or len(w) < 3 or w in STOPWORDS or _stem(w) in FILLERS or w in _DIR_WORDS:
                continue
            p, _, _ = self.matcher.word_pattern(w)
            if p is not None and not self.infos[p].anchored:
                out.add(p)
        return out

    def _names_objects(self, part: list[str]) -> bool:
        try:
            return bool(self._find(tuple(part)))
        except InputError:
            return True

    def _free_order(self, clause: tuple[str, ...]) -> bool:
        """A clause that only leaves a stack's order open: "any order is fine",
        "the order is not important", "which one is under which does not matter"."""
        text = " ".join(clause)
        if FREE_ORDER.fullmatch(text):
            return True
        if re.fullmatch(r"(the )?(order|sequence) of .+ (is|is entirely|is totally) (your call|up to you|your choice|"
                        r"free|open|not important|unimportant|yours to pick|yours)", text):
            return True  # "the order of the other two is your call"
        if not re.search(r"\b(order|sequence|which way (round|up|around)|which (one |of them |of the two )?(is|goes|sits|ends up|comes|lands|sits) "
                         r"(under|on top|on|above|below|over|at the bottom|at the top|first|last|lowest|highest))\b",
                         text):
            return False
        if not re.search(r"\b(not|n't|no|any|whatever|fine|matters?|up to you|care|free|important|irrelevant|"
                         r"unimportant|open|ok|okay|decide|choose|immaterial|arbitrary|unspecified|yours)\b", text):
            return False
        try:
            return not self._find(clause)
        except InputError:
            return False

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

    def _dinner_at(self, words: tuple[str, ...]) -> int | None:
        """Where a place setting is asked for ("set the table", "dinner"), if it is."""
        return next((i for i in range(len(words)) for s in self._DINNER if words[i : i + len(s)] == s
                     and not (s == ("dinner",) and i and words[i - 1] in ("before", "after", "until", "till", "since"))),
                    None)

    def _setting_only(self, words: tuple[str, ...]) -> bool:
        """Whether a clause names only the setting's own objects (plate, bowls, cutlery)."""
        try:
            ms = self._find(words)
        except InputError:
            return False
        own = {"plate", "bowl", "fork", "knife", "spoon", "chopstick", "chopsticks", "cutlery", "silverware"}
        return bool(ms) and not self._unknown_nouns(words, ms) and all(
            m.names is not None and set(m.names) <= own and m.det != "pronoun" for m in ms)

    def _dinner(self, words: tuple[str, ...]) -> list[_Pending] | None:
        """"Set the table" / "a dinner in the middle": the plate with its bowls stacked on it and the cutlery
        lined up beside it (the StructFormer-style composite goal). Only when nothing else is asked.
        """
        k = self._dinner_at(words)
        if k is None:
            return None
        seq = next(s for s in self._DINNER if words[k : k + len(s)] == s)
        many = re.search(r"\bfor (two|three|four|five|six|[2-9]|\d\d+)(?: (people|persons|guests|diners|of us)|"
                         r"(?= , | \.| \?| !|$)| ,? like (?:two|three|four|five|six|\d+))\b|\b(?:two|three|four|five|six|[2-9]) "
                         r"(?:full )?place settings\b", " ".join(words))
        if many is not None:
            raise InputError(f"'{' '.join(words)}': a setting {many.group(0)} needs one plate each; "
                             f"set one place at a time")
        rest = words[:k] + words[k + len(seq):]
        # Objects named along with it must be the setting's own (plate, bowls,
        # cutlery: "set a place: bowl on the plate, silverware on the left");
        # anything else ("Set the table: put the mugs ...") is read by the
        # ordinary grammar.
        plates = {"plate"}
        cutlery = {"fork", "knife", "spoon", "chopstick", "chopsticks"}
        own = plates | {"bowl"} | cutlery
        named: dict[str, list[int]] = {"plate": [], "bowl": [], "cut": []}
        found = self._find(rest, self.key_vocab)
        if self._unknown_nouns(words, self._find(words)):
            return None  # "put the napkin left of the plate, then set the table": read (and refused) as usual
        for w, nxt in zip(words, words[1:]):
            if w in COLOUR_WORDS and w not in self.vocab.color_words and (nxt in self._cat_words
                                                                         or _stem(nxt) in self._cat_words):
                # "set the table using the black plate": the scene has no black plate.
                raise InputError(f"nothing in the scene matches 'the {w} {nxt}' (no {w} object)")
        for m in found:
            if m.names is None and m.det == "all" and m.colors is None and not m.ids and m.text in _EVERYTHING:
                continue  # "get everything ready for dinner"
            if m.names is None or not set(m.names) <= own or m.det == "pronoun":
                return None
            got = self._select(m)
            for x in got if isinstance(got, list) else []:
                nm = next(n for i, n, _ in self.vocab.objects if i == x)
                named["plate" if nm in plates else "bowl" if nm == "bowl" else "cut"].append(x)
        said = " ".join(rest)
        if re.search(r"\b(?:on|to) the left\b", said) and re.search(r"\b(?:on|to) the right\b", said) and not re.search(
                r"\b(?:or|either|whichever|any|one|other)\b", said):
            raise InputError(f"contradiction: '{said}' puts the cutlery both left and right of the plate")
        side = "left"
        for w, sd in (("right", "right"), ("left", "left")):
            if w in rest:
                side = sd
                # "the plate ends up to the right of the cutlery": the cutlery on the other side.
                k_side = rest.index(w)
                before = [m for m in self._find(rest[:k_side]) if m.names is not None]
                after = [m for m in self._find(rest[k_side:]) if m.names is not None]
                if before and after and set(before[-1].names) <= plates and not set(after[0].names) <= plates:
                    side = "left" if sd == "right" else "right"
        params, rest2 = take_params(rest, lambda w: True) if any(
            w in rest for w in ("small", "medium", "large", "big", "facing", "top", "bottom", "middle", "center")) else ({}, rest)
        by = {n: [i for i, nn, _ in self.vocab.objects if nn == n] for n in ("plate", "bowl")}
        cut = named["cut"] or [i for i, nn, _ in self.vocab.objects if nn in cutlery]
        if named["plate"]:
            by["plate"] = sorted(set(named["plate"]))
        if named["bowl"]:
            by["bowl"] = list(dict.fromkeys(named["bowl"]))
        if len(by["plate"]) != 1:
            raise InputError(f"'{' '.join(words)}': a dinner setting needs exactly one plate, the scene has {len(by['plate'])}")
        if len(cut) < 2:
            raise InputError(f"'{' '.join(words)}': a dinner setting needs at least two pieces of cutlery")
        plate = by["plate"][0]
        meas = {x[0]: x[2] for x in self.vocab.measures}
        bowls = sorted(by["bowl"], key=lambda i: (-meas.get(i, 0.0), i))
        text = " ".join(words)
        out = []
        # Where and which way the setting goes is said of the plate, its centre.
        if bowls:
            out.append(_Pending("tower", [plate, *bowls], None, None, text, dict(params)))
        out.append(_Pending("line", list(cut), None, None, text, {} if bowls else dict(params)))
        out.append(_Pending(side, list(cut), plate, None, text))
        return out

    def _finish(self, pending: list[_Pending]) -> GoalSpec:
        for p in pending:
            if p.pattern == "tower" and p.anchor is None:
                n = sum(x.k if isinstance(x, Choice) else 1 for x in p.objects)
                if n < self.infos["tower"].min_objects:
                    raise InputError(f"'{p.clause}': a tower needs at least {self.infos['tower'].min_objects} objects, "
                                     f"this names {n} object{'' if n == 1 else 's'}")
            said = set(p.said.values())
            if (p.pattern == "tower" and len(p.said) >= 3 and {"bottom", "top"} <= said
                    and not _WHOLE_GROUP.search(p.clause)):
                # "stack the blocks: purple on top, orange under it, yellow at the base": a stack
                # described from its bottom to its top is those objects, not the whole group.
                p.objects[:] = [x for x in p.objects if not isinstance(x, int) or x in p.said]
            # "stack three blocks: red at the bottom, then blue, then green": the
            # blocks named one by one are the three.
            if p.pattern == "tower":
                for c in [x for x in p.objects if isinstance(x, Choice)]:
                    if sum(1 for x in p.objects if isinstance(x, int) and x in c.options) >= c.k:
                        p.objects.remove(c)
        picked: dict[int, list[int]] = {}
        used: set[int] = set()
        for p in pending:
            for x in p.objects:
                if isinstance(x, int):
                    used.add(x)
        for p in pending:  # targets first: prefer objects no goal uses yet
            fixed = {x for x in p.objects if isinstance(x, int)}
            if isinstance(p.anchor, int):
                fixed.add(p.anchor)
            for x in p.objects:
                if isinstance(x, Choice) and id(x) not in picked:
                    free = [o for o in x.options if o not in used and o not in fixed]
                    rest = [] if x.fresh else [o for o in x.options if o not in free and o not in fixed]
                    got = (free + rest)[: x.k]
                    if len(got) < x.k:
                        noun = "object" if len(got) == 1 else "objects"
                        raise InputError(
                            f"'{x.text}': only {len(got)} matching {noun} left that no other goal uses, {x.k} needed"
                        )
                    picked[id(x)] = got
                    used.update(got)
                    fixed.update(got)
        goals: list[dict] = []
        resolved: list[tuple[_Pending, list[int]]] = []
        for p in pending:
            objs: list[int] = []
            for x in p.objects:
                for o in picked[id(x)] if isinstance(x, Choice) else [x]:
                    if o not in objs:
                        objs.append(o)
            resolved.append((p, objs))
        for k, (p, objs) in enumerate(resolved):
            anchor = p.anchor
            if isinstance(anchor, Choice):
                if id(anchor) in picked:
                    anchor = picked[id(anchor)][0]
                else:
                    others = {o for j, (_, ob) in enumerate(resolved) if j != k for o in ob}
                    opts = [o for o in anchor.options if o not in objs]
                    pref = [o for o in opts if o in others] if self.options.prefer_anchor_from_other_goal else []
                    if not opts:
                        raise InputError(f"'{anchor.text}': no object left to serve as reference")
                    choice = (pref or opts)[0]
                    picked[id(p.anchor)] = [choice]
                    anchor = choice
            if anchor is not None:
                objs = [o for o in objs if o != anchor]
                if not objs:
                    raise InputError(f"'{p.clause}': an object cannot be placed relative to itself")
            g: dict = {"pattern": p.pattern, "objects": objs}
            if anchor is not None:
                g["anchor"] = anchor
            if p.pose is not None:
                g["pose"] = list(p.pose)
            if p.params and p.pose is None:
                params = stages.measured_size(p.pattern, p.params, self._measures, len(objs), anchor is not None)
                self._measured.update([p.params["measure"]] if "measure" in p.params else [])
                g.update(params if anchor is None else {k: v for k, v in params.items() if k == "facing"})
            if g not in goals:
                goals.append(g)
        unread_measure = next((m for k, m in enumerate(self._measures) if k not in self._measured), None)
        if unread_measure is not None:
            raise InputError(f"'{unread_measure.text}': a size said in numbers that no goal read from the command "
                             f"takes; say which arrangement it is for")
        goals = _chain_towers(goals)
        goals = _same_goals_merged(goals)
        goals = _diagonals(_merge_relations(goals))
        self._contradictions(goals)
        self.goal_dicts = [dict(g) for g in goals]
        self._unused_object(goals)
        unread = _unread_cue(self._said, goals, self._cat_words)
        if unread is not None:
            raise InputError(f"'{unread}' is not part of any goal read from the command; say that part again on its own")
        if not _params_accepted():
            goals = [{k: v for k, v in g.items() if k not in _PARAM_KEYS} for g in goals]
        spec = parse_goals({"goals": goals})
        try:
            spec.check_against(self.spec)
        except InputError as exc:
            raise InputError(f"contradiction: {exc}") from None
        return spec

    def _contradictions(self, goals: list[dict]) -> None:
        rel = [g for g in goals if g["pattern"] in RELATIONS]
        for a_i, a in enumerate(rel):
            for b in rel[a_i + 1 :]:
                if a["anchor"] != b["anchor"]:
                    continue
                da, db = RELATIONS[a["pattern"]], RELATIONS[b["pattern"]]
                if da[0] * db[0] + da[1] * db[1] > 0:
                    continue
                common = set(a["objects"]) & set(b["objects"])
                if common:
                    o = min(common)
                    raise InputError(
                        f"contradiction: object {describe(self.vocab, [o])} cannot be both "
                        f"{a['pattern'].replace('_', ' and ')} and {b['pattern'].replace('_', ' and ')} of object "
                        f"{describe(self.vocab, [a['anchor']])}"
                    )
        above: dict[int, int] = {}
        below: dict[int, int] = {}
        for g in goals:
            if g["pattern"] != "tower":
                continue
            for lo, hi in zip(g["objects"], g["objects"][1:]):
                if above.get(lo, hi) != hi:
                    raise InputError(
                        f"contradiction: object {describe(self.vocab, [lo])} cannot carry both "
                        f"{describe(self.vocab, [above[lo]])} and {describe(self.vocab, [hi])}"
                    )
                if below.get(hi, lo) != lo:
                    raise InputError(
                        f"contradiction: object {describe(self.vocab, [hi])} cannot stand on both "
                        f"{describe(self.vocab, [below[hi]])} and {describe(self.vocab, [lo])}"
                    )
                above[lo], below[hi] = hi, lo
        pos: dict[int, tuple[float, float, float]] = {}
        for g in goals:
            if "pose" in g:
                o = g["objects"][0]
                if o in pos and tuple(pos[o]) != tuple(g["pose"]):
                    raise InputError(f"contradiction: object {o} is given two different poses")
                pos[o] = g["pose"]


def _with_facing(goals: list[_Pending], params: dict) -> list[_Pending]:
    """Relation goals with the facing (and any measure, refused when the goal is written) said in their clause."""
    own = {k: v for k, v in params.items() if k in ("facing", "measure")}
    for g in goals:
        g.params = {**g.params, **own}
    return goals


def _add_params(shape: _Pending, params: dict, text: str) -> None:
    """Give ``shape`` the place, size or facing said after it; a second, different one is refused."""
    for key, val in params.items():
        if shape.params.get(key, val) != val:
            if key == "region" and merged_region(shape.params[key], val) is not None:
                params = {**params, key: merged_region(shape.params[key], val)}
                continue
            raise InputError(f"'{text}': two different {key}s for one arrangement")
    shape.params.update(params)


def _chain_towers(goals: list[dict]) -> list[dict]:
    """Join towers where the top of one is the bottom of another.

    "Put the red block on the blue block, then put the green block on the red
    block" gives [blue, red] and [red, green]: one tower [blue, red, green]
    (bottom first). Towers that share any other object are left as they are
    (the consistency checks refuse them).
    """
    goals = [dict(g) for g in goals]
    below: set[tuple[int, int]] = set()
    for g in goals:
        if g["pattern"] == "tower" and not g.get("unordered"):
            objs = g["objects"]
            below.update((objs[i], objs[j]) for i in range(len(objs)) for j in range(i + 1, len(objs)))
    loop = next(((a, b) for a, b in below if (b, a) in below), None)
    if loop is not None:
        raise InputError(f"contradiction: the stacking puts object {loop[0]} both below and above object {loop[1]}")
    merged = True
    while merged:
        merged = False
        towers = [k for k, g in enumerate(goals) if g["pattern"] == "tower"]
        for a in towers:
            for b in towers:
                if a == b:
                    continue
                lo, hi = goals[a]["objects"], goals[b]["objects"]
                if lo[-1] == hi[0] and set(lo) & set(hi) == {lo[-1]}:
                    goals[a] = {**goals[a], "objects": lo + hi[1:]}
                    del goals[b]
                    merged = True
                    break
            if merged:
                break
    towers = [g["objects"] for g in goals if g["pattern"] == "tower"]

    def inside(small: list[int]) -> bool:
        n = len(small)
        return any(big is not small and len(big) > n and any(big[i : i + n] == small for i in range(len(big) - n + 1))
                   for big in towers)

    return [g for g in goals if g["pattern"] != "tower" or not inside(g["objects"])]


_PARAM_KEYS = ("region", "size", "facing")


def _params_accepted() -> bool:
    """Whether the goal format has the optional parameters region, size and facing."""
    from ..formats import Goal

    return all(k in Goal.model_fields for k in _PARAM_KEYS)


def goal_dicts(spec: SceneSpec, text: str, *, matcher: PatternMatcher, options: RulesOptions | None = None) -> list[dict]:
    """The goals the parser reads, as dicts with their parameters (region, size, facing) even where the
    goal format does not take them yet."""
    p = _Parser(spec, matcher, options or RulesOptions())
    p.command(text)
    return p.goal_dicts


def _same_goals_merged(goals: list[dict]) -> list[dict]:
    """One goal for each arrangement said twice ("put them in a circle, like a
    little loop"): the same pattern over the same objects (in the same order for
    a tower) and the same reference object; the place, size and facing said
    either time are the goal's (two different ones are refused)."""
    out: list[dict] = []
    for g in goals:
        same = None
        for h in out:
            if (h["pattern"] == g["pattern"] and h.get("anchor") == g.get("anchor")
                    and (h["objects"] == g["objects"] if g["pattern"] == "tower" else
                         sorted(h["objects"]) == sorted(g["objects"]))):
                same = h
                break
        if same is None:
            out.append(dict(g))
            continue
        for key in _PARAM_KEYS:
            if key in g:
                if key == "region" and key in same and merged_region(same[key], g[key]) is not None:
                    same[key] = merged_region(same[key], g[key])
                    continue
                if same.get(key, g[key]) != g[key]:
                    raise InputError(f"two different {key}s ({same[key]}, {g[key]}) for one {g['pattern']}")
                same[key] = g[key]
    return out


def _diagonals(goals: list[dict]) -> list[dict]:
    """A side and a depth said for the same objects and reference object ("E in front of R, and a bit
    to the left of it") are one diagonal relation (left and front), as "in front of R and to its left"."""
    out = [dict(g) for g in goals]
    k = 0
    while k < len(out):
        a = out[k]
        j = next((j for j in range(k + 1, len(out)) if out[j]["pattern"] in RELATIONS and a["pattern"] in RELATIONS
                  and out[j].get("anchor") == a.get("anchor") and a.get("anchor") is not None
                  and sorted(out[j]["objects"]) == sorted(a["objects"])
                  and {out[j]["pattern"], a["pattern"]} in ({"left", "front"}, {"left", "behind"},
                                                            {"right", "front"}, {"right", "behind"})), None)
        if j is None:
            k += 1
            continue
        side = a["pattern"] if a["pattern"] in ("left", "right") else out[j]["pattern"]
        depth = out[j]["pattern"] if side == a["pattern"] else a["pattern"]
        out[k] = {**a, **{x: y for x, y in out[j].items() if x not in ("pattern", "objects", "anchor")},
                  "pattern": f"{side}_{depth}"}
        del out[j]
    return out


def _merge_relations(goals: list[dict]) -> list[dict]:
    """Relation goals with one relation and one anchor whose objects together are exactly the
    objects of an arrangement of the same command become one goal: "put the spoon left of the plate;
    put the fork left of the plate; put the fork and the spoon in a line" is the line left of the
    plate (a relation holds object by object, so this changes nothing it asks). Other relation
    goals stay one per clause."""
    shapes = [set(g["objects"]) for g in goals if g["pattern"] not in RELATIONS]
    groups: dict[tuple, list[int]] = {}
    for k, g in enumerate(goals):
        if g["pattern"] in RELATIONS and "anchor" in g:
            groups.setdefault((g["pattern"], g["anchor"], tuple(sorted(set(g) - {"objects"}))), []).append(k)
    drop: set[int] = set()
    merged: dict[int, dict] = {}
    for ks in groups.values():
        if len(ks) < 2:
            continue
        union: list[int] = []
        for k in ks:
            union += [o for o in goals[k]["objects"] if o not in union]
        if set(union) in shapes:
            merged[ks[0]] = dict(goals[ks[0]], objects=union)
            drop.update(ks[1:])
    return [merged.get(k, g) for k, g in enumerate(goals) if k not in drop]


#: Words that start a facing ("facing", "pointing", "tines" ...): a clause with one reads its parameters.
_FACING_CUES = frozenset({"facing", "pointing", "oriented", "orientated", "turned", "aimed", "faces", "face", "points"})
#: Words of the free place and position readings (.places, .positions), known to the spelling corrector.
_PLACE_WORDS = frozenset({"strip", "band", "partway", "halfway", "midway", "dead", "centred", "centered", "corner",
                          "edge", "wall", "viewer", "nearest", "closest", "furthest", "farthest", "leftmost",
                          "rightmost", "frontmost", "backmost", "rearmost", "middle", "column", "across", "apart",
                          "wide", "long", "side", "each", "toward", "towards", "facing", "pointing", "turned"})
_DINNER_CUES = frozenset({"dinner", "setting", "laid", "lay", "meal", "lunch", "breakfast", "supper"})
_SHAPES_PROTECT = frozenset({"lol", "haha", "ok", "okay", "thanks", "thank", "hey", "hi", "hello", "yeah", "yes", "no",
                             "nope", "sure", "cheers", "please", "pls", "plz", "thx", "wanna", "gonna", "gimme",
                             "lemme", "btw", "asap", "thru", "obj", "objs"})
_DIR_WORDS = lexicon.DIRECTIONS

#: Words of stack roles and orders, which a remark never has.
_ROLE_WORDS = lexicon.ROLE_WORDS

#: Superlatives of a side, words the spelling corrector knows (read by :mod:`.positions`).
_SUPERLATIVE = frozenset({"leftmost", "rightmost", "frontmost", "nearest", "closest", "backmost", "rearmost", "farthest",
                          "furthest"})
#: Where a stack role phrase stood once it has been read.
_ROLE_MARK = "|"
#: Words that ask for a whole group or a number of it ("all the blocks", "the six blocks").
_WHOLE_GROUP = re.compile(r"\b(?:all|every|each|both|whole|entire|everything|\d+|two|three|four|five|six|seven|eight|"
                          r"nine|ten)\b")

#: Words that keep a comma-separated part of a command from being an aside.
_ASIDE_KEEP = frozenset({"order", "first", "then", "last", "next", "top", "bottom", "base", "middle", "between",
                         "each", "other", "one", "ones", "former", "latter", "both", "all", "every", "except",
                         "table", "facing", "pointing", "turned", "oriented", "orientated", "aimed", "faces", "face",
                         "on", "onto", "under", "below", "above", "beneath",
                         "underneath", "atop", "upon"})

def _direction(phrase: str) -> str | None:
    """The relation the direction words of ``phrase`` compose to, or None."""
    words = set(re.findall(r"[a-z]+", phrase.lower()))
    hit = [_DIR_WORDS[w] for w in words if w in _DIR_WORDS]
    if not hit:
        return None
    xs, ys = {h[0] for h in hit if h[0]}, {h[1] for h in hit if h[1]}
    if len(xs) > 1 or len(ys) > 1:
        return None  # "left and right": a contradiction, left to the checks
    x, y = (xs.pop() if xs else 0), (ys.pop() if ys else 0)
    name = {(-1, 0): "left", (1, 0): "right", (0, -1): "front", (0, 1): "behind", (-1, -1): "left_front",
            (-1, 1): "left_behind", (1, -1): "right_front", (1, 1): "right_behind"}[(x, y)]
    return name if name in RELATIONS else None


#: Words that ask for a kind of goal whatever else the sentence says, with the
#: patterns of the goals that can carry them (a relation from either side:
#: "move the box so the can is in front of it" is the box behind the can).
_FRONT_BACK = ("front", "left_front", "right_front", "behind", "left_behind", "right_behind")
_LEFT_RIGHT = ("left", "left_front", "left_behind", "right", "right_front", "right_behind")
_CUES = (
    (re.compile(r"\b(in front of|ahead of|behind|in back of)\b"), _FRONT_BACK),
    (re.compile(r"\b(to the left of|to the right of|(?:left|right) of|to (?:its|their|the) (?:left|right)\b|"
                r"on the (?:left|right) of)"), _LEFT_RIGHT),
    (re.compile(r"\b(lin(?:e|es|ed|ing) (?:them |it |those |these )?up|(?:a|one|single|straight) (?:line|row)|in (?:a )?row)\b"),
     ("line",)),
    (re.compile(rf"\b({MACROS['CIRCLE']})\b"), ("circle",)),
    (re.compile(r"\b(rectangle|square|rectangular)\b"), ("rectangle",)),
    (re.compile(r"\b(stack(?:ed|ing|s)?|pil(?:e|es|ed|ing)|tower|on top of)\b"), ("tower",)),
)
#: Where a cue word describes a place on the table, not a relation between objects.
_TABLE_PLACE = re.compile(r"^\s*(?:the |this |that )?(?:table|workspace|tabletop|board|surface|counter|desk)\b")


def _unread_cue(text: str, goals: list[dict], nouns: frozenset[str] = frozenset()) -> str | None:
    """A phrase that asks for a relation, a line, a circle, a rectangle or a
    stack that no goal read from ``text`` has (the command's other words were
    read without it), or None. A goal that drops a part of the command is
    wrong; asking again is better. ``nouns``: the scene's category words
    ("ring", "square" name objects in some scenes)."""
    have = {g["pattern"] for g in goals}
    low = text.lower()
    for cue, patterns in _CUES:
        if have & set(patterns):
            continue
        for m in cue.finditer(low):
            if _TABLE_PLACE.match(low[m.end():]) or m.group(0) in nouns:
                continue  # "in front of the table": a place; "the rainbow ring": an object
            return m.group(0)
    return None


def _is_number(w: str) -> bool:
    return bool(re.fullmatch(r"-?\d+(?:\.\d+)?", w))


def parse_rules(
    spec: SceneSpec, text: str, *, matcher: PatternMatcher, options: RulesOptions | None = None
) -> GoalSpec:
    """Parse ``text`` against ``spec`` with the rule-based parser.

    Raises
    ------
    InputError
        With one line saying what was not understood.
    """
    return _Parser(spec, matcher, options or RulesOptions()).command(text)
