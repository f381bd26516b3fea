"""References by position: objects picked by where the scene's poses put them.

A pure stage in two halves:

* :func:`find_position_refs` reads the phrases that pick objects by where
  they stand, over lower-cased tokens: "the leftmost can", "the two rightmost
  blocks", "the third cup from the left", "the block nearest the white
  bowl", "the can furthest to the right", "whatever is closest to the mug",
  "whichever mug sits furthest right", "the middle one of the three bowls",
  "the farther of the two bottles", "the bottle closest to the front edge";
* :func:`pick` ranks the candidates (the objects the head noun names, found
  by the caller's grounding) on the phrase's key and returns the ones asked
  for.

Keys, in the table frame (+x right, +y away from the viewer): left/right
compare x, front/back (and "nearest me", "closest to the viewer") compare y,
"nearest X" / "furthest from X" compare the distance between centres in the
table plane, "nearest the centre" the distance to the workspace centre.

**How close is too close.** When the objects asked for and the next one
differ by less than :data:`TOO_CLOSE` (2 cm) on the compared quantity, the
reading is refused with a line that says so: the answer would turn on
where an object stands within a hand's width, which is not what a speaker
can see. For an ordinal ("the third from the left") both neighbours count.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace
from typing import Literal

from ..errors import InputError
from .ir import scan
from . import lexicon

__all__ = ["TOO_CLOSE", "Key", "PositionRef", "find_position_refs", "pick"]

#: Two candidates closer than this on the compared quantity cannot be told apart (m).
TOO_CLOSE = 0.02

KeyKind = Literal["x", "y", "near", "far", "centre", "middle"]


@dataclass(frozen=True)
class Key:
    """What a position phrase compares: ``x`` or ``y`` with a sign (+1: smallest first),
    ``near``/``far`` of an ``anchor`` (words naming another object) or of the
    workspace centre (``anchor`` None), ``middle`` of a run ordered by x."""

    kind: KeyKind
    sign: int = 1
    anchor: tuple[str, ...] | None = None


@dataclass(frozen=True)
class PositionRef:
    """One phrase that picks objects by where they stand.

    ``start``/``end``: the token span of the whole phrase (what a caller
    replaces by the ids); ``head``: the words naming the candidates ("blocks",
    "piece of silverware"; "one"/"ones" for the noun said before; () for
    anything); ``count`` objects are taken from ``rank`` on; ``of``: the number
    of candidates the phrase states ("of the three", "of the two")."""

    start: int
    end: int
    head: tuple[str, ...]
    key: Key
    count: int = 1
    rank: int = 0
    of: int | None = None
    #: Said as a count and the side of the table they stand on ("the two cans on the left"): a place instead
    #: where the count takes every object of the kind.
    side_said: bool = False


_COUNTS = {"two": 2, "three": 3, "four": 4, "five": 5, "2": 2, "3": 3, "4": 4, "5": 5}
_ORDINALS = {"first": 0, "second": 1, "third": 2, "fourth": 3, "fifth": 4, "1st": 0, "2nd": 1, "3rd": 2, "4th": 3,
             "5th": 4, "last": -1}
#: One-word superlatives of a side.
_MOST = {
    "leftmost": Key("x", 1), "left-most": Key("x", 1), "rightmost": Key("x", -1), "right-most": Key("x", -1),
    "frontmost": Key("y", 1), "front-most": Key("y", 1), "foremost": Key("y", 1), "backmost": Key("y", -1),
    "rearmost": Key("y", -1), "hindmost": Key("y", -1), "back-most": Key("y", -1),
}
_NEAR = frozenset({"nearest", "closest"})
_FAR = frozenset({"furthest", "farthest"})
#: Sides of the table a "nearest/furthest" phrase may name, as a key of the near end.
_SIDES = {**{w: Key("y", 1) for w in lexicon.VIEWER_WORDS}, "front": Key("y", 1), "near": Key("y", 1), "back": Key("y", -1),
          "far": Key("y", -1), "rear": Key("y", -1), "left": Key("x", 1), "right": Key("x", -1),
          "center": Key("centre", 1), "centre": Key("centre", 1), "middle": Key("centre", 1)}
_SIDE_NOUNS = frozenset({"edge", "side", "end", "wall", "border", "corner", "of", "the", "table", "hand"})
_FORWARD = {"right": Key("x", -1), "left": Key("x", 1), "back": Key("y", -1), "forward": Key("y", 1),
            "front": Key("y", 1), "away": Key("y", -1), "backward": Key("y", -1), "rear": Key("y", -1)}
#: Words that end a noun phrase (a reference object or a head).
_STOP = frozenset({
    ",", ".", ";", ":", "!", "?", "and", "then", "on", "onto", "in", "into", "behind", "under", "underneath", "beneath",
    "below", "above", "over", "to", "at", "with", "next", "beside", "by", "so", "goes", "go", "is", "are", "sits", "sit",
    "should", "must", "needs", "put", "move", "place", "set", "stack", "make", "left", "right", "front", "near",
    "nearest", "closest", "furthest", "farthest", "from", "please", "it", "them", "one", "that", "which", "who",
    "ends", "end", "stays", "has", "have", "will", "would", "up", "out", "as", "for", "of", "except", "but",
    "going", "counting", "gets", "get", "be", "most", "all", "could", "might", "shall", "let's", "lets", "okay", "ok",
}) | lexicon.COMMAND_VERBS | {"take", "grab", "pick", "bring", "slide", "shift", "push", "pull", "position", "carry"}
_ARTICLES = frozenset({"the", "a", "an"})
_WHATEVER = frozenset({"whatever", "whichever", "whoever"})
#: Adverbs of time after "is" in a reference ("whatever is currently nearest the plate").
_NOW = frozenset({"currently", "now", "presently", "still"})
#: Head nouns that take their kind after "of" ("piece of cutlery", "items of silverware").
_PIECES = frozenset({"piece", "pieces", "item", "items", "bit", "bits"})
_BE = frozenset({"is", "sits", "stands", "lies", "sitting", "standing", "lying", "are", "'s", "happens"})


def _np(ws: tuple[str, ...], i: int, limit: int = 6) -> int:
    """The end of a noun phrase starting at ``i`` (an article, then words up to a stop word)."""
    j = i
    if j < len(ws) and ws[j] in _ARTICLES:
        j += 1
    k = j
    while k < len(ws) and k - j < limit and ws[k] not in _STOP:
        k += 1
    # "piece of silverware", "pieces of cutlery": "of" inside a head
    if k + 1 < len(ws) and ws[k] == "of" and k > j and ws[k - 1] in _PIECES:
        k = _np(ws, k + 1, limit)
    return k if k > j else i


def _side_key(ws: tuple[str, ...], i: int) -> tuple[Key, int] | None:
    """"the front (edge)", "me", "the viewer", "the left side of the table", "the centre": a side's key."""
    j = i
    if j < len(ws) and ws[j] in ("to", "from"):
        j += 1
    if j < len(ws) and ws[j] in ("the", "my", "your", "our"):
        j += 1
    if j < len(ws) and ws[j] in _SIDES:
        key = _SIDES[ws[j]]
        k = j + 1
        if ws[j] in ("near", "far") and not (k < len(ws) and ws[k] in ("edge", "side", "end", "wall")):
            return None
        while k < len(ws) and ws[k] in _SIDE_NOUNS:
            if ws[k] == "of" and not (k + 1 < len(ws) and ws[k + 1] in ("the", "table")):
                break
            k += 1
        while k > j + 1 and ws[k - 1] in ("of", "the"):
            k -= 1
        if ws[j] in ("left", "right") and not (j > i and ws[j - 1] == "the"):
            return None  # "nearest left": not a side of the table
        return key, k
    return None


def _near_far(ws: tuple[str, ...], j: int, near: bool, anchor_ok: bool) -> tuple[Key, int] | None:
    """What follows "nearest"/"furthest" at ``j``: a side ("the front edge", "me"), a direction
    ("furthest to the right", "furthest back") or another object ("nearest the phone")."""
    if not near:
        k = j + (j < len(ws) and ws[j] == "to")
        k += k < len(ws) and ws[k] == "the" and k > j
        diagonal = (k == j and ws[k : k + 1] in (("front",), ("back",)) and ws[k + 1 : k + 2] in (("right",), ("left",))
                    ) or (k > j and ws[k + 1 : k + 2] == ("of",) and ws[k + 2 : k + 4] not in (("the", "table"),))
        if k < len(ws) and ws[k] in _FORWARD and (ws[k] not in ("left", "right") or k > j or ws[j:j + 1] != ("the",)) \
                and not diagonal:  # "the farther cup front right of ...": a side of another object follows
            return _FORWARD[ws[k]], k + 1  # "furthest right", "furthest to the right", "furthest back"
    side = _side_key(ws, j)
    if side is not None and (near or ws[j] == "from"):
        key, end = side
        if key.kind == "centre":
            return Key("near" if near else "far"), end
        return (key if near else Key(key.kind, -key.sign)), end
    if not anchor_ok:
        return None
    k = j + (j < len(ws) and ws[j] in ("to", "from"))
    end = _np(ws, k)
    if end > k:
        return Key("near" if near else "far", 1, tuple(ws[k:end])), end
    return None


def _after_head(ws: tuple[str, ...], i: int) -> tuple[Key, int] | None:
    """The key said after a head noun (or after "whatever is"), starting at ``i``."""
    if i >= len(ws):
        return None
    w = ws[i]
    if w in _MOST:
        return _MOST[w], i + 1
    if w in ("on", "at") and i + 2 < len(ws) and ws[i + 1] == "the" and ws[i + 2] in ("far", "very") and i + 3 < len(ws) \
            and ws[i + 3] in ("left", "right"):
        return Key("x", 1 if ws[i + 3] == "left" else -1), i + 4  # "the cup on the far left"
    if w in _NEAR or w in _FAR:
        return _near_far(ws, i + 1, w in _NEAR, anchor_ok=True)
    if w == "most" and i + 1 < len(ws) and ws[i + 1] in ("far", "near", "close"):
        return _near_far(ws, i + 2, ws[i + 1] != "far", anchor_ok=True)  # "the utensil most far from me"
    if w == "most" and i + 1 < len(ws):
        return _near_far(ws, i + 1, False, anchor_ok=False)  # "the utensil most right", "most to the left"
    if ws[i : i + 3] == ("all", "the", "way"):
        # "the utensil all the way on the left", "the cup all the way to the back": the furthest that way
        k = i + 3 + (i + 3 < len(ws) and ws[i + 3] == "over")
        if k < len(ws) and ws[k] in ("on", "at", "to"):
            k += 1
            if k < len(ws) and ws[k] == "the" and k + 1 < len(ws) and ws[k + 1] in _FORWARD:
                return _FORWARD[ws[k + 1]], k + 2
        elif k < len(ws) and ws[k] in _FORWARD and ws[k] not in ("left", "right"):
            return _FORWARD[ws[k]], k + 1  # "all the way back"
    return None


#: Comparatives read as the superlative over exactly two candidates ("whichever mug is further to the left",
#: "the one farther from me", "the cup nearer to me").
_COMPARATIVES = {"further": "furthest", "farther": "farthest", "nearer": "nearest", "closer": "closest",
                 "more": "most"}  # "the one more to the back"
#: Verbs after which "the cup closer to the plate" asks to move the cup, not to pick it.
_PLACING = frozenset({"put", "move", "place", "set", "push", "pull", "bring", "shift", "slide", "get", "nudge",
                      "pop", "stick", "drag", "take"})


def _said_apart(ws: tuple[str, ...], k: int) -> bool:
    """Whether the comparative at ``k`` is read otherwise: "the farther of the two" (read as it stands) or
    "nearer the viewer than the red can" (a relation between two objects, not a reference)."""
    if ws[k + 1 : k + 2] == ("of",) or (ws[k + 1 : k + 2] and ws[k + 1] in _FORWARD and ws[k + 2 : k + 3] == ("of",)):
        return True  # "the farther of the two", "the farther back of the two"
    for w in ws[k + 1 :]:
        if w == "than":
            return True
        if w in (",", ".", ";", ":", "!", "?", "and", "then"):
            return False
    return False


def _goal_after(ws: tuple[str, ...], k: int) -> bool:
    """Whether the clause goes on after ``k`` with where to put the object ("put the one farther from me to
    the left of the mug": the comparative picked the object)."""
    for x, w in enumerate(ws[k:], start=k):
        if w == "and" and ws[x + 1 : x + 2] and ws[x + 1] in _PLACING and ws[x + 2 : x + 3] in (("it",), ("them",)):
            return True  # "take the farther one and put it ...": the comparative picked the object
        if w in (",", ".", ";", ":", "!", "?", "and", "then"):
            return False
        if w in ("left", "right", "behind", "front", "on", "onto", "under", "beside", "next", "in", "into", "atop"):
            return True
    return False


def find_position_refs(words: tuple[str, ...]) -> list[PositionRef]:
    """Every phrase of ``words`` that picks objects by where they stand, left to right.

    A comparative is read as its superlative over two candidates (the phrase then speaks of two, as "the
    farther of the two" does), except right after a verb of placing, where it says where to move."""
    ws = tuple(words)
    compared = {k for k, w in enumerate(ws) if w in _COMPARATIVES and not _said_apart(ws, k)}
    if not compared:
        return [_of_one(ws, ref) for ref in scan(ws, _ref_at)]
    mapped = tuple(_COMPARATIVES.get(w, w) for w in ws)
    out: list[PositionRef] = []
    for ref in scan(mapped, _ref_at):
        said = [k for k in compared if ref.start <= k < ref.end]
        if not said:
            out.append(ref)
        elif ((ref.start > 0 and ws[ref.start - 1] in _PLACING) or ws[ref.start] in _PLACING) and ref.count == 1 \
                and not _goal_after(ws, ref.end):
            continue  # "move the cup closer to the plate": a placing, left for the parser
        else:
            out.append(ref if ref.of is not None else replace(ref, of=2))
    return [_of_one(ws, ref) for ref in out]


def _of_one(ws: tuple[str, ...], ref: PositionRef) -> PositionRef:
    """``ref`` with the head "one" where it is said after "the one that is" ("the block nearest me and the one
    that's second closest": a block, as the noun said before), the phrase from "the one" on, else ``ref``."""
    lead = " ".join(ws[max(0, ref.start - 3) : ref.start]).replace("that's", "that is").split()[-3:]
    if not ref.head and len(lead) == 3 and lead[0] in ("one", "ones") and lead[1] == "that" and lead[2] in ("is", "are"):
        one = max(k for k in range(max(0, ref.start - 3), ref.start) if ws[k] == lead[0])
        start = one - 1 if one and ws[one - 1] == "the" else one  # the whole phrase is the object picked
        return replace(ref, start=start, head=(lead[0],))
    return ref


def _whatever_ref(ws: tuple[str, ...], i: int) -> PositionRef | None:
    """"whatever is closest to the mug", "whichever mug sits furthest right": a reference by position
    that opens with "whatever" / "whichever"."""
    head: tuple[str, ...]
    j = i + 1
    head_end = j
    while head_end < len(ws) and ws[head_end] not in _BE and ws[head_end] not in _STOP and head_end - j < 4:
        head_end += 1
    if head_end > j and ws[head_end : head_end + 1] == ("of",) and ws[head_end - 1] in _PIECES:
        head_end = _np(ws, head_end + 1, 3)  # "whichever piece of cutlery lies nearest the front"
    head = tuple(ws[j:head_end])
    k = head_end
    if head and head[-1].endswith("'s") and k < len(ws) and (ws[k] in _NEAR or ws[k] in _FAR or ws[k] in _MOST):
        head = head[:-1] + (head[-1][:-2],)  # "whichever bowl's nearest the phone": "'s" is "is"
    while k < len(ws) and (ws[k] in _BE or (k > head_end and ws[k] in _NOW)) and k - head_end < 3:
        k += 1  # "is", "is lying", "is currently"
    if head and ws[k : k + 3] in (("in", "the", "middle"), ("in", "the", "centre"), ("in", "the", "center")):
        # "whichever utensil is in the middle (going left to right)": the middle one of them by x
        return PositionRef(i, _skip_reading_order(ws, k + 3), head, Key("middle"))
    if k < len(ws) and ws[k] in ("the", "most"):
        k += 1
    got = _after_head(ws, k)
    if got is None:
        return None
    return PositionRef(i, got[1], head, got[0])


def _middle_ref(ws: tuple[str, ...], i: int, j: int) -> PositionRef | None:
    """"the middle/centre one (of the three bowls)", "the middle bowl of the three": the word at ``j`` is
    "middle" or "centre"."""
    head: tuple[str, ...]
    k = j + 1
    if ws[k] == "one":
        head, k = ("one",), k + 1
    else:
        end = _np(ws, k, 3)
        if end == k:
            return None
        head, k = tuple(ws[k:end]), end
    if ws[k : k + 2] == ("of", "the") and k + 2 < len(ws) and ws[k + 2] in _COUNTS:
        n = _COUNTS[ws[k + 2]]
        end = _np(ws, k + 3)
        if end > k + 3:
            head = tuple(ws[k + 3 : end])
            k = end
        else:
            k += 3
        k = _skip_reading_order(ws, k)
        return PositionRef(i, k, head, Key("middle"), of=n)
    if head != ("one",) and (k >= len(ws) or ws[k] in _STOP) and k < len(ws) and ws[k] not in ("of",):
        # "the middle bowl" (only with an odd number of them, checked by pick)
        return PositionRef(i, _skip_reading_order(ws, k), head, Key("middle"))
    return None


#: Sides said before a head ("the front bowl", "the left can"): the one furthest that way.
_SIDE_BEFORE = {"front": Key("y", 1), "back": Key("y", -1), "rear": Key("y", -1), "left": Key("x", 1),
                "right": Key("x", -1)}
#: Heads after a side that name a part of the table, not objects ("the front edge", "the back row").
_PLACE_HEADS = lexicon.REGION_NOUNS | lexicon.TABLE_WORDS | {"row", "rows", "column", "columns", "wall", "band",
                                                             "strip", "line", "of", "one", "ones", "hand", "cell"}


def _side_before_ref(ws: tuple[str, ...], i: int, j: int) -> PositionRef | None:
    """"the front bowl", "the left can": one object named with the side it stands furthest to, or None (a part
    of the table: "the front edge", "the back left corner"; a plural: "the back cans")."""
    end = _np(ws, j + 1, 3)
    head = tuple(ws[j + 1 : end])
    if not head or any(x in _PLACE_HEADS for x in head) or (head[-1].endswith("s") and not head[-1].endswith("ss")):
        return None
    return PositionRef(i, end, head, _SIDE_BEFORE[ws[j]])


def _ref_at(ws: tuple[str, ...], i: int) -> PositionRef | None:
    """The phrase at ``i`` that picks objects by where they stand (:func:`find_position_refs`), or None."""
    w = ws[i]
    head: tuple[str, ...]
    if w in _WHATEVER:
        return _whatever_ref(ws, i)
    bare = (i == 0 or ws[i - 1] in (",", ".", ";", ":", "!", "?")) and w not in _STOP
    if w not in _ARTICLES and w not in _ORDINALS and w not in _MOST and not bare:  # "on rightmost block"
        return None
    j = i + (w in _ARTICLES)
    if j >= len(ws):
        return None
    # "the farther / nearer of the two bottles", "the farther back of the two"
    way = ws[j + 1] if ws[j] in ("farther", "further") and j + 1 < len(ws) and ws[j + 1] in _FORWARD else None
    k = j + 1 + (way is not None)
    if ws[j] in ("farther", "further", "nearer", "closer") and ws[k : k + 2] == ("of", "the") \
            and k + 2 < len(ws) and ws[k + 2] in _COUNTS:
        n = _COUNTS[ws[k + 2]]
        end = _np(ws, k + 3)
        head = tuple(ws[k + 3 : end]) or ("ones",)
        key = _FORWARD[way] if way is not None else Key("y", -1) if ws[j] in ("farther", "further") else Key("y", 1)
        return PositionRef(i, end, head, key, of=n)
    # "the middle/centre one (of the three bowls)", "the middle bowl of the three"
    if ws[j] in ("middle", "centre", "center", "central") and j + 1 < len(ws):
        return _middle_ref(ws, i, j)
    if w == "the" and ws[j] in _SIDE_BEFORE:
        return _side_before_ref(ws, i, j)
    count = 1
    if ws[j] in _COUNTS:
        count, j = _COUNTS[ws[j]], j + 1
    rank = 0
    if j < len(ws) and ws[j] in _ORDINALS and count == 1:
        rank, j = _ORDINALS[ws[j]], j + 1
    if j >= len(ws):
        return None
    # "the two rightmost blocks", "the second leftmost can", "the nearest block (to me)"
    if ws[j] in _MOST or ws[j] in _NEAR or ws[j] in _FAR:
        sup = ws[j]
        end = _np(ws, j + 1, 4)
        head = tuple(ws[j + 1 : end])
        if not head and ws[end : end + 1] in (("one",), ("ones",)):
            head, end = ("one",), end + 1
        if not head:
            head = ("ones",) if count > 1 else ()
        if len(head) == 1 and head[0] in _FORWARD and sup not in _MOST and ws[end : end + 1] in (("one",), ("ones",)):
            # "the farther back one", "the nearer front one": the direction is the key, "one" the head
            return PositionRef(i, end + 1, ("one",), _FORWARD[head[0]], count, rank)
        if sup in _MOST:
            key = _MOST[sup]
        else:
            got = _near_far(ws, end, sup in _NEAR, anchor_ok=ws[end : end + 1] in (("to",), ("from",)))
            if got is not None:
                key, end = got
            else:
                key = Key("y", 1 if sup in _NEAR else -1)  # "the nearest block": nearest the viewer
        if rank == -1:
            return None
        return PositionRef(i, end, head, key, count, rank)
    # "the third cup from the left", "the second from the right"
    if rank != 0 or (j > i and ws[j - 1] in ("first", "1st")):
        end = _np(ws, j, 3)
        head = tuple(ws[j:end])
        if ws[end : end + 1] == ("one",):
            head, end = ("one",), end + 1
        if ws[end : end + 1] == ("from",) or (ws[end : end + 1] == ("counting",) and ws[end + 1 : end + 2] == ("from",)):
            k = end + 1 + (ws[end] == "counting")
            side = _side_key(ws, k)
            if side is None and ws[k : k + 1] in (("left",), ("right",)):
                side = _SIDES[ws[k]], k + 1  # "the third block from left"
            if side is not None and side[0].kind in ("x", "y"):
                if rank == -1:
                    return None
                return PositionRef(i, side[1], head or ("one",), side[0], 1, rank)
        return None
    # "the block nearest the white bowl", "the two blocks nearest the front", "the can furthest to the right"
    end = _np(ws, j, 4)
    if end == j:
        if ws[j] in ("one", "ones"):
            end = j + 1
        else:
            return None
    cut = next((x for x in range(j + 1, end) if ws[x] in _ORDINALS and ws[x + 1 : x + 2] == ("from",)), None)
    if cut is not None:
        end = cut  # "the can second from the left": the head ends at the ordinal
    head = tuple(ws[j:end])
    if end < len(ws) and ws[end] in ("one", "ones") and head and head[-1] not in ("one", "ones"):
        return None
    k = end
    if k < len(ws) and ws[k] in ("that", "which") and k + 1 < len(ws) and ws[k + 1] in _BE:
        k += 2  # "the cup that is nearest the phone"
    elif k < len(ws) and ws[k] in _BE and k + 1 < len(ws) and (ws[k + 1] in _NEAR or ws[k + 1] in _FAR
                                                              or ws[k + 1] in _MOST):
        return None  # "the mug is nearest the plate": a statement, not a reference
    if k < len(ws) and ws[k] == "the" and k + 1 < len(ws) and (ws[k + 1] in _NEAR or ws[k + 1] in _FAR):
        k += 1
    k2 = k + (k < len(ws) and ws[k] == "the")
    if k2 + 1 < len(ws) and ws[k2] in _ORDINALS and _ORDINALS[ws[k2]] >= 0 and ws[k2 + 1] == "from":
        # "the can second from the left", "the cup that is third from the right": the ordinal after the head
        side = _side_key(ws, k2 + 2)
        if side is not None and side[0].kind in ("x", "y"):
            return PositionRef(i, side[1], head, side[0], 1, _ORDINALS[ws[k2]])
    if count > 1 and not (i and ws[i - 1] == "of") and ws[k : k + 2] in (("on", "the"), ("at", "the")) and k + 2 < len(ws) and ws[k + 2] in _FORWARD:
        # "the two cans on the left", "the three blocks at the back": a count of a kind said with the side of the
        # table they stand on (a count is never a place's: "put the two cans on the left" with four cans)
        e = k + 3
        while e < len(ws) and ws[e] in ("hand", "side", "end", "edge"):
            e += 1
        if not (ws[e : e + 1] == ("of",) and ws[e + 1 : e + 3] != ("the", "table")):
            return PositionRef(i, e, head, _FORWARD[ws[k + 2]], count, rank, side_said=True)
    got = _after_head(ws, k)
    if got is None or got[0].kind in ("middle",):
        return None
    return PositionRef(i, got[1], head, got[0], count, rank)


def _skip_reading_order(ws: tuple[str, ...], k: int) -> int:
    """", going left to right", "(counting from the left)" after a middle one: part of the phrase."""
    j = k + (k < len(ws) and ws[k] == ",")
    for seq in (("going", "left", "to", "right"), ("going", "from", "left", "to", "right"), ("from", "left", "to", "right"),
                ("left", "to", "right"), ("counting", "from", "the", "left")):
        if ws[j : j + len(seq)] == seq:
            j += len(seq)
            return j + (j < len(ws) and ws[j] == ",")
    return k


def _value(key: Key, xy: tuple[float, float], anchor_xy: tuple[float, float] | None,
           centre: tuple[float, float]) -> float:
    if key.kind == "x":
        return key.sign * xy[0]
    if key.kind in ("y",):
        return key.sign * xy[1]
    if key.kind == "middle":
        return xy[0]
    ref = anchor_xy if anchor_xy is not None else centre
    d = math.hypot(xy[0] - ref[0], xy[1] - ref[1])
    return d if key.kind == "near" else -d


def pick(ref: PositionRef, candidates: Mapping[int, tuple[float, float]], *, anchor_xy: tuple[float, float] | None = None,
         centre: tuple[float, float] = (0.0, 0.0), said: str = "") -> tuple[int, ...]:
    """The ids ``ref`` asks for among ``candidates`` (id -> table position x, y), best first.

    Refused with one line when there are too few candidates, when a stated number
    of them ("of the three") is not the number there is, and when the objects
    asked for are within :data:`TOO_CLOSE` of the next on the compared quantity.
    """
    said = said or "the objects named"
    if ref.key.kind in ("near", "far") and ref.key.anchor is not None and anchor_xy is None:
        raise InputError(f"'{said}': nearest to what? the reference object names nothing in the scene")
    if ref.of is not None and len(candidates) != ref.of:
        raise InputError(f"'{said}' speaks of {ref.of}, but {len(candidates)} objects match")
    ranked = sorted(((_value(ref.key, xy, anchor_xy, centre), i) for i, xy in candidates.items()))
    if ref.key.kind == "middle":
        if len(ranked) % 2 == 0 or len(ranked) < 3:
            raise InputError(f"'{said}': there is no middle one of {len(ranked)} objects")
        mid = len(ranked) // 2
        if ranked[mid][0] - ranked[mid - 1][0] < TOO_CLOSE or ranked[mid + 1][0] - ranked[mid][0] < TOO_CLOSE:
            raise InputError(f"'{said}': two of them stand within {TOO_CLOSE * 100:.0f} cm left to right; "
                             f"say which one by colour or id")
        return (ranked[mid][1],)
    rank = ref.rank if ref.rank >= 0 else len(ranked) - ref.count
    if len(ranked) < rank + ref.count:
        raise InputError(f"'{said}': only {len(ranked)} objects match")
    lo, hi = rank, rank + ref.count
    gaps = []
    if hi < len(ranked):
        gaps.append(ranked[hi][0] - ranked[hi - 1][0])
    if lo > 0:
        gaps.append(ranked[lo][0] - ranked[lo - 1][0])
    if gaps and min(gaps) < TOO_CLOSE:
        raise InputError(f"'{said}': two candidates stand within {TOO_CLOSE * 100:.0f} cm of each other on that "
                         f"measure; say which one by colour or id")
    return tuple(i for _, i in ranked[lo:hi])
