"""Words for where, how big and which way: phrases to a goal's ``region``,
``size`` and ``facing`` (their meaning is in :mod:`lgmcts.params`).

:func:`find_params` reads the three from one clause and returns the clause
without the words it used, so that a parser can read the rest as before:

>>> f = find_params("make a big circle in the top-left corner facing north")
>>> (f.region, f.size, f.facing, f.rest)
('top left', 'large', 'north', 'make a circle')

It is deliberately cautious, since a wrong goal is worse than a refusal:

* a size word counts only right before a pattern noun ("a big circle", "a
  short line"), never before an object ("the big bowl" is a bowl);
* a side word counts as a region only when it is plainly about the table:
  two of them together ("top left", "front-right"), or one with "corner",
  "side", "edge", "half", "part", "area", "end" or "of the table", or "in the
  middle" / "in the centre" closing a clause; "to the left of the bowl"
  stays a relation for the parser;
* a facing needs a verb of facing or pointing before the direction.

Side words: top / upper / back / far / rear / behind → ``top``; bottom /
lower / front / near → ``bottom``; middle / centre / center → ``middle`` as a
row and ``center`` as a column. Facing: north / east / south / west, also
"away (from me)" / "back" / "forward" (north), "me" / "the front" /
"towards the viewer" (south), "left" (west), "right" (east).
"""

from __future__ import annotations

import re
from dataclasses import dataclass

__all__ = ["Found", "find_params", "PATTERN_NOUNS"]

#: Nouns that name an arrangement; a size word before one of them is the arrangement's size.
PATTERN_NOUNS = (
    "circle", "ring", "loop", "round", "line", "row", "column", "file", "queue", "rectangle", "square", "box",
    "frame", "border", "tower", "stack", "pile", "structure", "shape", "arrangement", "formation", "pattern",
)

_SIZES = {
    "small": "small", "little": "small", "tiny": "small", "short": "small", "compact": "small", "tight": "small",
    "mini": "small", "smaller": "small",
    "medium": "medium", "medium-sized": "medium", "mid-sized": "medium", "midsize": "medium", "moderate": "medium",
    "average": "medium", "middle-sized": "medium", "normal": "medium", "regular": "medium",
    "large": "large", "big": "large", "huge": "large", "long": "large", "wide": "large", "giant": "large",
    "large-sized": "large", "bigger": "large", "larger": "large", "longer": "large", "spacious": "large", "broad": "large",
}

_ROW = {"top": "top", "upper": "top", "back": "top", "far": "top", "rear": "top",
        "bottom": "bottom", "lower": "bottom", "front": "bottom", "near": "bottom",
        "middle": "middle", "centre": "middle", "center": "middle"}
_COL = {"left": "left", "right": "right", "center": "center", "centre": "center", "middle": "center"}

_AREA = r"(?:corner|side|edge|half|part|area|region|end|portion|section|quadrant)"
_SIDE = r"(?:top|upper|back|far|rear|bottom|lower|front|near|middle|centre|center|left|right)"

# "in the top left corner of the table", "at the front-right", "on the upper left part"
_TWO = re.compile(
    rf"\b(?:in|on|at|to|into|onto|toward|towards|near|over|by)\s+(?:the\s+)?(?P<a>{_SIDE})[\s-]+(?P<b>{_SIDE})"
    rf"(?:\s+{_AREA})?(?:\s+(?:of|on)\s+the\s+(?:table|workspace|surface))?\b"
)
# "on the left side of the table", "in the middle of the table", "near the front edge", "at the back of the table"
_ONE = re.compile(
    rf"\b(?:in|on|at|to|into|onto|toward|towards|near|over|by)\s+(?:the\s+)?(?P<a>{_SIDE})"
    rf"(?:(?:\s+{_AREA})(?:\s+(?:of|on)\s+the\s+(?:table|workspace|surface))?"
    rf"|\s+(?:of|on)\s+the\s+(?:table|workspace|surface))\b"
)
# "in the middle", "at the centre" closing a clause
_MID = re.compile(r"\b(?:in|on|at|to|into|onto|toward|towards)\s+the\s+(?P<a>middle|centre|center)(?=\s*(?:$|[,.;!]|and\b|then\b))")
_FACING = re.compile(
    r"\b(?:facing|faces|face|that\s+faces|pointing|points|point|pointed|oriented|orientated|turned|aimed|looking)"
    r"(?:\s+(?:to|towards?|at|in\s+the\s+direction\s+of))?\s+(?:the\s+)?"
    r"(?P<d>north|east|south|west|away(?:\s+from\s+(?:me|the\s+viewer|us))?|forwards?|back|me|us|the\s+viewer|viewer|front|left|right)"
    r"(?:wards?|\s+direction|\s+side)?\b"
)
_DIRECTION = {"north": "north", "east": "east", "south": "south", "west": "west", "forward": "north",
              "forwards": "north", "back": "north", "me": "south", "us": "south", "viewer": "south",
              "the viewer": "south", "front": "south", "left": "west", "right": "east"}
_SIZE_BEFORE = re.compile(
    r"\b(?P<s>" + "|".join(sorted(map(re.escape, _SIZES), key=len, reverse=True)) + r")"
    r"(?P<mid>(?:\s+(?:and\s+)?(?:neat|tidy|straight|round|circular|rectangular|square|perfect|vertical|nice|even))?)"
    r"\s+(?=(?:" + "|".join(PATTERN_NOUNS) + r")s?\b)"
)


@dataclass(frozen=True)
class Found:
    """What :func:`find_params` read: each ``None`` when not said, and the clause without those words."""

    region: str | None
    size: str | None
    facing: str | None
    rest: str


def _cell(a: str, b: str | None) -> str | None:
    """The region name for side words ``a`` (and ``b``), in either order."""
    if b is None:
        if a in ("middle", "centre", "center"):
            return "center"
        if a in _COL and a not in ("center", "centre", "middle"):
            return _COL[a]
        return _ROW.get(a)
    for r, c in ((a, b), (b, a)):
        if r in _ROW and c in _COL:
            row, col = _ROW[r], _COL[c]
            if (r, c) == (b, a) and a in _ROW and b in _COL and a not in _COL:
                continue  # "top left" is read with the row first
            return f"{row} {col}"
    return None


def _cut(text: str, m: re.Match) -> str:
    return " ".join((text[: m.start()] + " " + text[m.end():]).split())


def find_params(text: str) -> Found:
    """Region, size and facing named in ``text`` (one clause), and the rest of it."""
    rest = " ".join(text.split())
    low = rest.lower()
    facing = None
    m = _FACING.search(low)
    if m:
        d = " ".join(m.group("d").split())
        facing = "north" if d.startswith("away") else _DIRECTION.get(d)
        if facing is not None:
            rest, low = _cut(rest, m), _cut(low, m)
    region = None
    m = _TWO.search(low)
    if m and _cell(m.group("a"), m.group("b")):
        region = _cell(m.group("a"), m.group("b"))
    else:
        m = _ONE.search(low) or _MID.search(low)
        if m:
            region = _cell(m.group("a"), None)
    if region is not None and m is not None:
        rest, low = _cut(rest, m), _cut(low, m)
    size = None
    m = _SIZE_BEFORE.search(low)
    if m:
        size = _SIZES[m.group("s")]
        start, end = m.start("s"), m.end("s")
        rest = " ".join((rest[:start] + rest[end:]).split())
    return Found(region, size, facing, rest)
