"""Compass points, clock positions and headings said plainly, as the viewer's own words.

The table's compass is fixed by the viewer at its front edge: north is away from
the viewer (behind, ``+y``), east is the viewer's right (``+x``). A navigator's
words for places, references and relations are said here in those terms, by the
replacement functions of rows of the ``[[plain]]`` table of ``data/rewrites.toml``:

* places: "the north-west corner" is the back left corner, "the western third"
  the left third, "down in the south-east" the front right;
* superlatives: "the easternmost" is the rightmost, "the southernmost" the
  frontmost;
* relations to an object: "at the bowl's three o'clock" is to its right, "at
  its half past four" to its front right, "to the heart's south-east" to its
  front right (twelve o'clock is behind the object, three o'clock its right);
* headings: "heading 000" is facing north, "pointing 090" facing east.

A clock position between two of the eight sides ("two o'clock", 60 degrees
from twelve) is the nearest side; no whole or half hour is equally near two.
"""

from __future__ import annotations

import re

from .lexicon import COMPASS
from .measures import _NUMBER_WORDS
from .normalise import replacer

__all__ = ["SIDE_OF", "clock_side", "heading_facing"]

#: The viewer's word for each compass point (as a place and as a side: the lexicon's).
_PLACE = {p: COMPASS[p] for p in ("north", "south", "east", "west")}
#: "(the can) farthest north": the same key said after the noun; the front is said by nearness.
_FARTHEST = {p: "nearest the front" if side == "front" else f"farthest {side}" for p, side in _PLACE.items()}
_MOST = {p: f"{side}most" for p, side in _PLACE.items()}

#: How each of the eight sides is said before an object ("... of the bowl").
SIDE_OF = {0: "behind", 45: "back right of", 90: "to the right of", 135: "front right of", 180: "in front of",
           225: "front left of", 270: "to the left of", 315: "back left of"}

#: Digits said one by one in a heading ("zero nine zero"), radio words included; the hours of a clock.
_DIGITS = {w: v for w, v in _NUMBER_WORDS.items() if v < 10} | {"oh": 0, "niner": 9}
_HOURS = {w: v for w, v in _NUMBER_WORDS.items() if 1 <= v <= 12}


def _hour(word: str) -> int | None:
    w = word.lower()
    if w.isdigit() and 1 <= int(w) <= 12:
        return int(w)
    return _HOURS.get(w)


def clock_side(hour: int, half: bool = False) -> int:
    """The side (degrees clockwise from behind: 0, 45, ... 315) nearest a clock position.

    >>> clock_side(3), clock_side(4, half=True), clock_side(2), clock_side(12)
    (90, 135, 45, 0)
    """
    angle = (hour % 12) * 30 + (15 if half else 0)
    return round(angle / 45) * 45 % 360


def heading_facing(degrees: int) -> str | None:
    """The facing of a heading in degrees from north, clockwise ("heading 090" is east); None between them.

    >>> heading_facing(0), heading_facing(270), heading_facing(45)
    ('north', 'west', None)
    """
    return {0: "north", 90: "east", 180: "south", 270: "west"}.get(degrees % 360)


def _viewer(point: str, second: str | None) -> str:
    """"north", "west" -> "back left"; a single point -> its side word."""
    p = _PLACE[point.lower()]
    return f"{p} {_PLACE[second.lower()]}" if second else p


@replacer("compass-place")
def _compass_place(m: re.Match[str]) -> str:
    """"the north-west corner" -> "the back left corner", "the western third" -> "the left third"."""
    return f"{m.group(1) or ''}{_viewer(m.group(2), m.group(3))} {m.group(4)}"


@replacer("compass-area")
def _compass_area(m: re.Match[str]) -> str:
    """"in the south-east" (a corner said without the word) -> "in the front right corner"."""
    return f"{m.group(1)} the {_viewer(m.group(2), m.group(3))} corner"


@replacer("compass-most")
def _compass_most(m: re.Match[str]) -> str:
    """"easternmost" -> "rightmost"; "the western bowl" -> "the leftmost bowl"."""
    return _MOST[m.group(1).lower()] + (" " if m.group(0).endswith(" ") else "")


@replacer("compass-farthest")
def _compass_farthest(m: re.Match[str]) -> str:
    """"(the can) farthest north" -> "farthest back", "(the) most easterly (can)" -> "rightmost"."""
    if m.group(1):
        return _FARTHEST[m.group(1).lower()]
    return _MOST[m.group(2).lower()]


def _anchor(said: str) -> str:
    """The object a position is said of: "its" -> "it", "their" -> "them", "the bowl's" -> "the bowl"."""
    low = said.lower()
    if low in ("its", "it"):
        return "it"
    if low in ("their", "them"):
        return "them"
    if low.endswith("'s"):
        return said[:-2]
    return said[:-1] if low.endswith(("s'", "s")) else said  # "the white bowls 9 oclock"


@replacer("compass-of-object")
def _compass_of_object(m: re.Match[str]) -> str:
    """"to its south-east" -> "front right of it", "at the heart's north" -> "behind the heart"."""
    a, b = m.group(2).lower(), (m.group(3) or "").lower()
    angle = {"north": 0, "east": 90, "south": 180, "west": 270}[a]
    if b:
        angle = {("north", "east"): 45, ("south", "east"): 135, ("south", "west"): 225,
                 ("north", "west"): 315}[(a, b)]
    return f"{SIDE_OF[angle]} {_anchor(m.group(1))}"


@replacer("clock-of-object")
def _clock_of_object(m: re.Match[str]) -> str:
    """"at its half past four" -> "front right of it", "at the bowl's three o'clock" -> "to the right of the
    bowl", "at three o'clock from the bowl" -> the same. Left as said where the hour is not one."""
    said = m.groupdict()
    hour = _hour(said.get("h") or said.get("h2") or "")
    if hour is None:
        return m.group(0)
    half = bool(said.get("half") or said.get("thirty"))
    side = SIDE_OF[clock_side(hour, half)]
    if said.get("whose"):
        return f"{side} {_anchor(said['whose'])}"
    return f"{side} {said.get('of') or ''}"  # "at three o'clock from the bowl": the object follows


@replacer("heading")
def _heading(m: re.Match[str]) -> str:
    """"heading 000", "on a heading of 270", "pointing 090" -> "facing north/west/east"; left as said
    between the four points (refused later as a facing it cannot read)."""
    said = m.group(1).lower()
    if not said.isdigit():  # "zero nine zero": one digit a word
        said = "".join(str(_DIGITS[w]) for w in said.replace("-", " ").split())
    facing = heading_facing(int(said))
    return f"facing {facing}" if facing else f"heading {said}"  # refused later, quoted, as a facing not read
