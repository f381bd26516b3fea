"""Cutting a command's words into clauses (:func:`split_clauses` and the splitters the parser applies to each
clause), and the word sets the splitting and the readings share.

Every function works on lower-cased token tuples (:func:`.grounding.tokenize`); none reads the scene but
through the references (:class:`.grounding.Mention`) it is given.
"""

from __future__ import annotations

import re

from . import lexicon
from .grounding import Mention
from .lexicon import HUES as _HUES
from .matcher import FILLERS, STOPWORDS, _forms, _stem
from .shapes import COLS, REGION_NOUNS, ROWS

__all__ = ["split_clauses"]


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
     "use", "find", "stick", "pop", "plonk", "shove", "chuck", "station", "whack", "slap", "park", "plant"}
)


_VERT_SKIP = frozenset({"goes", "go", "sits", "sit", "is", "are", "be", "should", "placed", "put", "stands", "rests",
                        "directly", "right", "just", "then", "lies", "ends", "up", "will", "must", "sitting",
                        "resting", "standing", "lying", "stacked", "set", "neatly", "squarely", "centred", "centered"})


_VERT_ON = frozenset({("on",), ("onto",), ("on", "top", "of"), ("atop",), ("upon",), ("above",), ("over",),
                      ("on", "to"), ("top", "of")})


_VERT_UNDER = frozenset({("under",), ("below",), ("beneath",), ("underneath",), ("under", "neath")})


_VERT_WORDS = frozenset(w for s in _VERT_ON | _VERT_UNDER for w in s)


_ON_WORDS = (("on", "top", "of"), ("onto",), ("on",), ("atop",), ("upon",))


#: Words never counted as naming an arrangement when deciding where to split.
_NOT_PATTERN = frozenset({"other", "top", "exactly", "position", "coordinate", "shape", "pose", "this", "single"})


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
        if w in _HUES and _ordered_set(parts[-1], nouns) and ("then" in words[i + 1 : i + 3]):
            # "stack the cans white(,) then blue then red": the set, then its order colour by colour (as after ":").
            parts.append([])
        bare = bool(parts[-1]) and parts[-1][0] in _HUES and not any(x in _OBJECT_START for x in parts[-1])
        if (w == "," and words[i + 1 : i + 2] in (("and",), ("plus",)) and _asks_after_object(parts[-1], nouns, hues=bare)
                and _asks_after_object(list(words[i + 2 : _next_stop(words, i + 2)]), nouns, start=True, hues=bare,
                                       noun_after_hue=words[i - 1] not in _HUES)):
            # "the bowl on the plate, and the mug, cup and bottle in a row": two goals said without verbs.
            parts.append([])
            i += 2
            continue
        if (w == "," and words[i + 1 : i + 2] and words[i + 1] in _HUES and words[i + 2 : i + 3] in _LIST_END
                and _stack_role_said(parts[-1])):
            # "orange on the bottom, purple, then green": the next of a stack said colour by colour
            parts.append([])
            i += 1
            continue
        if (w == "and" and "of" in parts[-1] and parts[-1][-1] not in ("it", "them", "its", "their")
                and "so" not in parts[-1] and "such" not in parts[-1] and _asks_after_object(parts[-1], nouns)) and _of_it(
                list(words[i + 1 : _next_stop(words, i + 1, comma=True)]), nouns):
            # "A front right of B and C back right of it": a second relation whose "it" is the first's anchor
            # (not after "so that", where every "it" is the object that moves).
            parts.append([])
            i += 1
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
                words[i + 1 : i + 1 + len(x)] == x for x in _SAME_START) or (
                # "... in a line and have them facing me", "and turn it to face the wall"
                words[nxt_k] in _VERBS_OF_PRONOUN and words[nxt_k + 1 : nxt_k + 2] in (("them",), ("it",))))
                and parts[-1]
                and not _fronted(parts[-1])):
            # "stack the blocks and put the bowls in a line": two commands.
            parts.append([])
            i += 1
            continue
        if (_command_verb(w) and words[i + 1 : i + 2] in (("it",), ("them",)) and parts[-1]
                and parts[-1][0] in _TAKING and len(parts[-1]) > 1):
            parts.append([])  # "take the red block put it on the yellow one": said without "and"
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


#: Verbs of taking an object up, after which a command on "it" starts a clause of its own.
_TAKING = frozenset({"take", "grab", "pick", "get", "lift", "fetch"})
#: Verbs that start a clause of their own when a pronoun follows ("and have them facing me").
_VERBS_OF_PRONOUN = frozenset({"have", "turn", "keep", "rotate", "spin", "orient", "point", "angle", "leave", "do"})

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
                       hues: bool = False, noun_after_hue: bool = False) -> bool:
    """Whether ``part`` names objects and then an arrangement or relation for them (``start``: and
    begins with the objects). ``nouns``: the scene's category words ("the green ring" is an object).
    ``hues``: a bare colour may begin the part ("red on blue, and green left of yellow"); ``noun_after_hue``: a
    colour and a noun may ("..., and green block behind the yellow block")."""
    first = next((k for k, w in enumerate(part) if w in _OBJECT_START or (k == 0 and w in _HUES and (
        hues or (noun_after_hue and len(part) > 1 and _stem(part[1]) in nouns)))), None)
    if first is None or (start and first != 0):
        return False
    if start and len(part) > first + 1 and part[first + 1] in _GOAL_WORDS and part[first + 1] not in nouns \
            and part[first] not in _HUES:
        return False  # ", the row facing west": the arrangement itself, not objects
    if start and part[first] in ("both", "all", "each") and part[first + 1 : first + 2] and part[first + 1] in _FACING_AFTER:
        return False  # ", both pointing right": a facing of the objects just named
    return any(w in _GOAL_WORDS and w not in nouns for w in part[first + 1 :])


def _stack_role_said(part: list[str]) -> bool:
    """Whether ``part`` gives an object its place in a stack ("orange on the bottom", "red at the base"), not an
    order along it ("top to bottom", "from red at the bottom through orange ...")."""
    if "through" in part or "to" in part:
        return False
    return any(part[k] in ("bottom", "base", "top") and part[k - 1] == "the" and part[k - 2] in ("on", "at")
               for k in range(2, len(part)))


#: What may follow a bare colour said as the next of a stack ("..., purple, then green").
_LIST_END = frozenset({(",",), ("then",), (".",), (";",), ("and",)})
#: Verbs of stacking, after which a group of objects may be followed by its order.
_STACKING = frozenset({"stack", "pile", "tower"})


def _ordered_set(part: list[str], nouns: frozenset[str]) -> bool:
    """Whether ``part`` is a verb of stacking and a plural group, with nothing after it but a comma
    ("stack the cans", "pile the blocks,")."""
    p = part[:-1] if part[-1:] == [","] else part
    return (len(p) >= 3 and any(w in _STACKING for w in p) and p[-2] in ("the", "all", "those", "these")
            and p[-1] != _stem(p[-1]) and _stem(p[-1]) in nouns)


def _of_it(part: list[str], nouns: frozenset[str]) -> bool:
    """Whether ``part`` is an object put on one side of "it"/"them" ("the letter A back right of it")."""
    if len(part) < 4:
        return False
    named = _asks_after_object(part, nouns, start=True) or (part[0] in nouns and _asks_after_object(["the", *part], nouns))
    return part[-2:] in (["of", "it"], ["of", "them"]) and named and any(
        w in _DIR_WORDS for w in part[:-2])  # ("letter A back right of it": a noun said without its article)


_FACING_AFTER = frozenset({"facing", "pointing", "turned", "oriented", "angled"})


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
    gaps: list[tuple[int, int]] = []
    at = 0
    for g in groups:
        gaps.append((at, g[0].start))
        at = g[-1].end
    gaps.append((at, len(words)))
    return groups, gaps


def _numbers(words: tuple[str, ...]) -> list[float]:
    return [float(w) for w in words if re.fullmatch(r"-?\d+(?:\.\d+)?", w)]


_DIR_WORDS = lexicon.DIRECTIONS


def _is_number(w: str) -> bool:
    return bool(re.fullmatch(r"-?\d+(?:\.\d+)?", w))
