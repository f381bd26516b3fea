"""References through another object's colour: "the cans that share a colour with one of the bowls".

A pure stage in two halves, like :mod:`.positions`:

* :func:`find_colour_refs` reads, over lower-cased tokens, a head noun phrase
  followed by a relative clause that compares its colour with other objects:
  "the cans that share a colour with one of the bowls", "the mug whose colour
  matches one of the bottles", "the cans that match any of the bowls in
  colour", "the cups that don't match any can's colour", "the cans that don't
  share a colour with either mug", "the mugs that aren't the colour of the
  phone", "the letters that have a block of the same colour";
* :func:`find_matched_pairs` reads two objects named together and then said to
  share a colour: "the mug and the bowl that are the same colour", "the cup and
  plate that match", "the can and the block of the same colour";
* :func:`select` keeps the head's candidates whose colour is (or, negated, is
  not) the colour of some object the reference names.

A comparison with one object said plainly ("the things that are the same
colour as the blue bowl") is left to the grounding's attribute grammar where
that grammar reads it; this stage reads what it does not: a reference said
with a quantifier, a negation, "has a block of the same colour".

"One of / any of / either of / any / either" mean *some* of them: the colours
of the reference objects are pooled ("the cans that share a colour with one
of the bowls" are the cans whose colour any bowl has); negated, none of them
("the cans that don't share a colour with either mug"). A colour is an
object's whole colour string, as the grounding compares colours.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass

from .ir import scan

__all__ = ["ColourRef", "MatchedPair", "find_colour_refs", "find_matched_pairs", "select"]


@dataclass(frozen=True)
class ColourRef:
    """A head whose colour is compared with a reference's: the token span of the whole phrase, the
    head's words, the reference's words and whether the comparison is negated."""

    start: int
    end: int
    head: tuple[str, ...]
    ref: tuple[str, ...]
    negated: bool
    #: The reference was said as "one of / any of / either ..." (or "a block of the same colour").
    quantified: bool = False


_REL = frozenset({"that", "which", "who"})
_NEG = (("do", "not"), ("does", "not"), ("don't",), ("doesn't",), ("are", "not"), ("is", "not"), ("aren't",),
        ("isn't",), ("not",))
_COLOUR = frozenset({"colour", "color", "colours", "colors"})
_VERBS = frozenset({"share", "shares", "match", "matches", "are", "is", "have", "has", "sharing", "matching"})
_ANY = (("one", "of"), ("any", "of"), ("either", "of"), ("some", "of"), ("any",), ("either",), ("some",))
#: Words that end a noun phrase.
_STOP = frozenset({",", ".", ";", ":", "!", "?", "and", "then", "on", "onto", "in", "into", "behind", "under", "to",
                   "at", "with", "next", "beside", "so", "goes", "go", "is", "are", "should", "must", "put", "move",
                   "place", "stack", "make", "left", "right", "front", "that", "which", "who", "whose", "out",
                   "up", "as", "for", "of", "in", "from", "colour", "color", "it", "them", "please", "together",
                   "where", "near", "above", "below", "over", "beneath", "underneath", "has", "have", "line",
                   # a place said after the reference ("... one of the bowls, along the back of the table")
                   "along", "across", "by", "around", "toward", "towards", "alongside", "back", "rear", "middle",
                   "centre", "center", "corner", "edge", "side"})


def _np(ws: tuple[str, ...], i: int, limit: int = 5) -> int:
    j = i + (i < len(ws) and ws[i] in ("the", "a", "an"))
    k = j
    while k < len(ws) and k - j < limit and ws[k] not in _STOP:
        k += 1
    return k if k > j else i


def _seq(ws: tuple[str, ...], i: int, seqs) -> int:
    """The end of the first of ``seqs`` found at ``i``, or ``i``."""
    for s in seqs:
        if ws[i : i + len(s)] == s:
            return i + len(s)
    return i


def _reference(ws: tuple[str, ...], i: int) -> tuple[tuple[str, ...], int, bool] | None:
    """"one of the bowls", "either mug", "any can's colour", "the phone": the reference's words and end."""
    j = _seq(ws, i, _ANY)
    quant = j > i
    if not quant and i < len(ws) and ws[i] in ("a", "an"):
        quant, j = True, i + 1  # "the colour of a bowl": of some bowl
    if quant and j < len(ws) and ws[j] not in ("the", "a", "an", "these", "those") and ws[j - 1] == "of":
        return None
    end = _np(ws, j)
    if end == j:
        return None
    while not quant and ws[end : end + 2] in (("and", "the"), ("or", "the")) and _np(ws, end + 1) > end + 2:
        # "the blocks that match the letter A and the letter E": the colours of both, pooled
        end, quant = _np(ws, end + 1), True
        if ws[j - 1 : j] != ("the",) and ws[j : j + 1] != ("the",):
            break
    words = tuple(ws[j:end])
    if words[-1].endswith("'s"):
        words = words[:-1] + (words[-1][:-2],)
        if end < len(ws) and ws[end] in _COLOUR:
            end += 1
    if quant and words[0] not in ("the", "these", "those"):
        # "either mug", "any can": every object the noun names
        last = words[-1]
        words = ("the",) + words[:-1] + ((last if last.endswith("s") else last + "s"),)
    elif quant and "and" not in words and "or" not in words:
        last = words[-1]
        words = words[:-1] + ((last if last.endswith("s") else last + "s"),)
    return words, end, quant


def find_colour_refs(words: tuple[str, ...]) -> list[ColourRef]:
    """Every head with a colour comparison to another reference in ``words``, left to right."""
    return scan(tuple(words), _at)


#: A comparison said with a preposition rather than a relative clause ("the cup with the colour of the bottle",
#: "block in same colour as letter T").
_PREPOSITIONAL = tuple(
    (prep,) + art + cmp
    for prep in ("in", "with", "of")
    for art in (("the",), ())
    for cmp in (("same", "colour", "as"), ("same", "color", "as"), ("colour", "of"), ("color", "of")))
_OPENING = frozenset({",", ".", ";", ":", "!", "?"})


def _at(ws: tuple[str, ...], i: int) -> ColourRef | None:
    det = ws[i]
    bare = (not i or ws[i - 1] in _OPENING) and det.isalpha() and det not in _STOP and det not in _VERBS
    if det not in ("the", "every", "all", "each", "any", "whichever", "whatever") and not bare:
        return None
    j = i if det not in ("the", "every", "all", "each", "any", "whichever", "whatever") else \
        i + 1 + (det == "all" and ws[i + 1 : i + 2] == ("the",))
    end = j
    while end < len(ws) and end - j < 4 and ws[end] not in _STOP and ws[end] not in _VERBS:
        end += 1
    if end == j and det not in ("whichever", "whatever"):
        return None
    head = tuple(ws[j:end])
    if head in (("one",), ("ones",)):
        return None  # "the ones that match the red bowl": the noun is elsewhere; left to the grounding
    k = end
    if k < len(ws) and ws[k] in ("else", "other"):
        return None  # "everything else of its colour" is read elsewhere
    negated = False
    if k < len(ws) and ws[k] == "whose" and ws[k + 1 : k + 2] and ws[k + 1] in _COLOUR:
        k += 2  # "whose colour matches one of the bottles"
        k2 = _seq(ws, k, _NEG)
        negated, k = k2 > k, k2
        k3 = _seq(ws, k, (("matches",), ("match",)))
        if k3 == k:
            return None
        k = k3
    elif _seq(ws, k, _PREPOSITIONAL) > k:
        k = _seq(ws, k, _PREPOSITIONAL)  # "the cup with the colour of the bottle"
    else:
        if k < len(ws) and ws[k] in _REL:
            k += 1
        elif ws[i] not in ("whichever", "whatever"):
            return None
        k2 = _seq(ws, k, _NEG)
        negated, k = k2 > k, k2
        verb = _seq(ws, k, (
            ("share", "a", "colour", "with"), ("share", "a", "color", "with"), ("shares", "a", "colour", "with"),
            ("shares", "a", "color", "with"), ("share", "the", "colour", "of"), ("shares", "the", "colour", "of"),
            ("share", "the", "same", "colour", "as"), ("shares", "the", "same", "colour", "as"),
            ("share", "colours", "with"), ("share", "colour", "with"), ("share", "their", "colour", "with"),
            ("match", "the", "colour", "of"), ("matches", "the", "colour", "of"), ("match", "the", "color", "of"),
            ("matches", "the", "color", "of"), ("match", "the", "colours", "of"), ("match", "the", "colors", "of"),
            ("matches", "the", "colours", "of"), ("matches", "the", "colors", "of"), ("match", "in", "colour"),
            ("match",), ("matches",),
            ("are", "the", "same", "colour", "as"), ("is", "the", "same", "colour", "as"),
            ("are", "the", "same", "colours", "as"), ("are", "the", "same", "colors", "as"),
            ("the", "same", "colour", "as"), ("the", "colour", "of"), ("the", "color", "of"),
            ("are", "the", "colour", "of"), ("is", "the", "colour", "of"),
        ))
        if verb == k and ws[k : k + 1] in (("has",), ("have",)) and ws[k + 1 : k + 2] in (("a",), ("an",), ("any",)):
            # "every letter that has a block of the same colour"
            j = k + 2
            noun_end = j
            while noun_end < len(ws) and noun_end - j < 3 and ws[noun_end] not in _STOP:
                noun_end += 1
            tail = _seq(ws, noun_end, (("of", "the", "same", "colour"), ("of", "the", "same", "color"),
                                       ("in", "the", "same", "colour"), ("of", "its", "own", "colour"),
                                       ("of", "its", "own", "color"), ("of", "their", "own", "colour"),
                                       ("of", "its", "colour"), ("of", "their", "colour"), ("the", "same", "colour"),
                                       ("of", "its", "color"), ("in", "its", "colour"), ("in", "its", "own", "colour")))
            if noun_end == j or tail == noun_end:
                return None
            last = ws[noun_end - 1]
            ref = ("the",) + tuple(ws[j : noun_end - 1]) + ((last if last.endswith("s") else last + "s"),)
            return ColourRef(i, tail, head, ref, negated, True)
        if verb == k:
            return None
        k = verb
    got = _reference(ws, k)
    if got is None:
        return None
    ref, end, quant = got
    quant = quant or ws[k - 2 : k - 1] in (("colours",), ("colors",))  # "the colours of the mugs": pooled
    end = _seq(ws, end, (("in", "colour"), ("in", "color"), ("colour", "wise"), ("'s", "colour"), ("by", "colour")))
    return ColourRef(i, end, head, ref, negated, quant)


def select(candidates: list[int], reference: list[int], colour_of: Mapping[int, str], negated: bool) -> list[int]:
    """The candidates whose colour one of the reference objects has (none of them, ``negated``). A
    reference object the head names too is one of them ("the things that share a colour with the
    blue bowl" include the blue bowl), as the free-form writers label it."""
    pool = {colour_of[r] for r in reference}
    return [c for c in candidates if (colour_of[c] in pool) != negated]


@dataclass(frozen=True)
class MatchedPair:
    """Two heads said to share a colour ("the mug and the bowl that are the same colour"): the token span
    of the whole phrase and each head's words."""

    start: int
    end: int
    first: tuple[str, ...]
    second: tuple[str, ...]


_SAID_SAME = frozenset({"sharing", "matching", "match", "share", "same"})
#: What says that the two objects named before it share a colour.
_SAME = tuple(
    rel + cmp
    for rel in (("that", "are"), ("which", "are"), ("that",), ("which",), ())
    for cmp in (("the", "same", "colour"), ("the", "same", "color"), ("same", "colour"), ("same", "color"),
                ("of", "the", "same", "colour"), ("of", "the", "same", "color"), ("in", "the", "same", "colour"),
                ("in", "the", "same", "color"), ("share", "a", "colour"), ("share", "a", "color"),
                ("match", "in", "colour"), ("match", "in", "color"), ("match",), ("matching", "in", "colour"),
                ("sharing", "a", "colour"), ("sharing", "a", "color"))
    if rel or cmp[0] in ("of", "in", "sharing", "matching"))


def find_matched_pairs(words: tuple[str, ...]) -> list[MatchedPair]:
    """Every "the A and (the) B that are the same colour" in ``words``, left to right."""
    return scan(tuple(words), _pair_at)


def _pair_at(ws: tuple[str, ...], i: int) -> MatchedPair | None:
    if ws[i] != "the":
        return None
    a_end = _np(ws, i, limit=3)
    if a_end == i + 1 or ws[a_end : a_end + 1] != ("and",):
        return None
    b_start = a_end + 1 + (ws[a_end + 1 : a_end + 2] == ("the",))
    b_end = b_start
    while b_end < len(ws) and b_end - b_start < 3 and ws[b_end] not in _STOP and ws[b_end] not in _SAID_SAME:
        b_end += 1
    if b_end == b_start:
        return None
    end = _seq(ws, b_end, _SAME)
    if end == b_end:
        return None
    end = _seq(ws, end, (("as", "each", "other"), ("each", "other"), ("as", "one", "another")))
    return MatchedPair(i, end, tuple(ws[i + 1 : a_end]), tuple(ws[b_start:b_end]))
