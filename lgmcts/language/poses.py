"""Poses said in numbers: "the mug to x = 0.10 m, y = -0.05 m, yaw 0 rad", "the cup at (10 cm, -5 cm)".

A pure text stage. :func:`find_poses` reads the coordinates of a point of the
table frame (metres unless a unit is said; a unit said on one coordinate holds
for the other) and an optional yaw (radians unless degrees are said; ``pi``,
``pi/2``, ``3pi/4`` are read); :func:`mark_poses` puts a marker word in their
place, which the parser's ``pose`` reading turns into a ``pose`` goal for the
one object its clause names. A yaw not said is the object's own (it keeps its
heading).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, replace

from . import lexicon

from .measures import UNITS, _number as _number_at, _tokens, _unit

__all__ = ["MARK", "SaidPose", "find_offsets", "find_poses", "is_mark", "mark_poses"]

#: Marker words standing for the poses of a command ("posemarka", "posemarkb" ...).
MARK = "posemark"

_NUM = r"[-+−]?(?:\d+(?:\.\d+)?|\.\d+)"
_UNIT = r"(?:mm|cm|m|millimet(?:re|er)s?|centimet(?:re|er)s?|met(?:re|er)s?)\b"
_ANGLE = rf"(?:(?:{_NUM})?\s*\*?\s*pi(?:\s*/\s*\d+)?|{_NUM})"
_ANGLE_UNIT = r"(?:rad(?:ians?)?\b|deg(?:rees?)?\b|°)"
_YAW = (rf"(?:(?:\s*(?:,|and|with|i\.e\.))*\s*(?:a\s+)?(?:yaw|theta|heading|rotation|angle|rotated|turned)\s*(?:of|by|to)?"
        rf"\s*[=:]?\s*(?:(?:about|approximately|approx\.?|roughly|around|exactly)\s+)?(?P<yaw>{_ANGLE})\s*"
        rf"(?P<yu>{_ANGLE_UNIT})?(?:\s*(?P<yd>anti-?clockwise|counter-?clockwise|clockwise|ccw|cw)\b)?)?")
#: "x = 0.1 m, y = -5 cm (, yaw 90 deg)" or "at (10 cm, -5 cm(, pi/2))": the second form's groups end in "p".
_POSE = re.compile(
    rf"(?i)\bx\s*[=:]?\s*(?P<x>{_NUM})\s*(?P<xu>{_UNIT})?\s*(?:,|and)?\s*\by\s*[=:]?\s*(?P<y>{_NUM})\s*(?P<yu_>{_UNIT})?"
    + _YAW
    + rf"|(?<=\b(?:at|to)\s)\s*\(\s*(?P<xp>{_NUM})\s*(?P<xup>{_UNIT})?\s*,\s*(?P<yp>{_NUM})\s*(?P<yu_p>{_UNIT})?"
    rf"(?:\s*,\s*(?P<yawp>{_ANGLE})\s*(?P<yup>{_ANGLE_UNIT})?)?\s*\)"
    + _YAW.replace("?P<yaw>", "?P<yaw2>").replace("?P<yu>", "?P<yu2>").replace("?P<yd>", "?P<yd2>"))


@dataclass(frozen=True)
class SaidPose:
    """One pose said in numbers: its character span, x and y in metres, yaw in radians (None: not said), and
    the frame of x and y: ``"table"`` (the table frame), ``"offset"`` (from where the object stands now:
    "slide the bowl 10 cm further back") or ``"centre"`` (from the workspace's centre: "10 cm right of the
    table centre")."""

    start: int
    end: int
    x: float
    y: float
    yaw: float | None
    frame: str = "table"
    square: bool = False

    def resolved(self, own: tuple[float, ...] | None, centre: tuple[float, float]) -> tuple[float, float, float]:
        """The pose in the table frame for an object now at ``own`` (x, y, yaw; None: not on the table), the
        workspace's centre at ``centre``: a yaw not said is the object's own (the nearest quarter turn to it
        when said square to the table). ValueError for a move of an object with no place."""
        yaw = self.yaw if self.yaw is not None else (float(own[2]) if own is not None else 0.0)
        if self.square and self.yaw is None:
            yaw = round(yaw / (math.pi / 2)) * (math.pi / 2)
        x, y = self.x, self.y
        if self.frame == "offset":
            if own is None:
                raise ValueError("has no place on the table to move it from")
            x, y = float(own[0]) + x, float(own[1]) + y
        elif self.frame == "centre":
            x, y = centre[0] + x, centre[1] + y
        return round(x, 6), round(y, 6), yaw


def is_mark(word: str) -> bool:
    """Whether a token is a pose's marker."""
    return len(word) == len(MARK) + 1 and word.startswith(MARK) and "a" <= word[-1] <= "z"


def _scale(unit: str | None) -> float | None:
    """Metres per unit of a unit said with a coordinate (every spelling ``_UNIT`` matches is one of ``UNITS``)."""
    return UNITS[unit.lower()] if unit else None


def _number(s: str) -> float:
    return float(s.replace("−", "-"))


def _angle(s: str, unit: str | None) -> float:
    s = s.replace(" ", "").replace("*", "").lower()
    if "pi" in s:
        coef, _, den = s.partition("pi")
        value = (_number(coef) if coef not in ("", "+", "-", "−") else (-1.0 if coef in ("-", "−") else 1.0)) * math.pi
        if den:
            value /= float(den.lstrip("/"))
        return value
    value = _number(s)
    return math.radians(value) if unit and unit.lower()[0] in "d°" else value


#: A turn said clockwise: its yaw is negative (yaw is counter-clockwise).
_CLOCKWISE = frozenset({"clockwise", "cw"})


def _pose(m: re.Match) -> SaidPose:
    g = m.groupdict()
    p = "" if g["x"] is not None else "p"
    xs, ys = _scale(g["xu" + p]), _scale(g["yu_" + p])
    xs, ys = xs or ys or 1.0, ys or xs or 1.0
    yaw_s = g.get("yaw" + p) or g.get("yaw2")
    yaw_u = g.get("yu" + p) or g.get("yu2")
    yaw = _angle(yaw_s, yaw_u) if yaw_s else None
    turn = (g.get("yd") or g.get("yd2") or "").lower()
    if yaw is not None and turn in _CLOCKWISE:
        yaw = -yaw  # yaw is counter-clockwise: "90 degrees clockwise" is -pi/2
    return SaidPose(m.start(), m.end(), _number(g["x" + p]) * xs, _number(g["y" + p]) * ys, yaw)


def find_poses(text: str) -> list[SaidPose]:
    """Every pose said in numbers in ``text``, left to right.

    >>> p = find_poses("mug to x = 0.10 m, y = -5 cm, yaw 90 deg")[0]
    >>> round(p.x, 3), round(p.y, 3), round(p.yaw, 4)
    (0.1, -0.05, 1.5708)
    >>> find_poses("the cup at (10 cm, -5 cm)")[0].y
    -0.05
    """
    return [_pose(m) for m in _POSE.finditer(text)]


#: Verbs that move an object by a distance ("slide the bowl 10 cm further back").
_MOVES = frozenset({"move", "slide", "shift", "nudge", "push", "pull", "scoot", "budge", "bring", "drag", "take",
                    "position", "reposition", "relocate", "displace", "translate", "offset"})
#: Directions of a move, as unit steps in the table frame (+x right, +y away from the viewer).
_STEPS = {"left": (-1.0, 0.0), "right": (1.0, 0.0), "back": (0.0, 1.0), "rightward": (1.0, 0.0),
          "east": (1.0, 0.0), "west": (-1.0, 0.0), "north": (0.0, 1.0), "south": (0.0, -1.0),
          "leftward": (-1.0, 0.0), "rightwards": (1.0, 0.0), "leftwards": (-1.0, 0.0)}
_TOWARD_FRONT = frozenset({"me", "us", "you", "viewer", "front", "near"})
_FILL = ("further", "farther", "more", "over", "to", "the", "toward", "towards", "in", "a", "bit", "its", "direction")
_CENTRE_WORDS = frozenset({"centre", "center", "middle"})
_HERE = (("from", "where", "it", "sits", "now"), ("from", "where", "it", "is", "now"), ("from", "where", "it", "is"),
         ("from", "where", "it", "sits"), ("from", "its", "current", "spot"), ("from", "its", "current", "place"),
         ("from", "its", "current", "position"), ("from", "where", "it", "stands"), ("from", "here"))


def _step(ws: list[str], i: int) -> tuple[float, float, int, bool] | None:
    """A distance and its direction at ``i`` ("10 cm further back", "8 cm to the left", "5 cm toward me", "10 cm
    right of the table centre"): (dx, dy, end, from the centre), or None (also for a distance from an object:
    "10 cm left of the plate" is not a move)."""
    got = _number_at(ws, i)
    if got is None:
        return None
    value, j = got
    unit = _unit(ws, j)
    if unit is None:
        return None
    metres, k = value * unit[0], unit[1]
    start_k = k
    while k < len(ws) and ws[k] in _FILL:
        k += 1
    if k >= len(ws):
        return None
    w = ws[k]
    toward = any(x in ("toward", "towards") for x in ws[start_k:k])
    if w in _STEPS and (w != "back" or "front" not in ws[start_k:k]):
        dx, dy = _STEPS[w]
    elif toward and w in _TOWARD_FRONT:
        dx, dy = 0.0, -1.0
    elif w == "away" and ws[k + 1 : k + 3] in (["from", "me"], ["from", "you"], ["from", "us"]):
        dx, dy, k = 0.0, 1.0, k + 2
    else:
        return None
    k += 1
    if k < len(ws) and ws[k] in ("edge", "side", "wall"):
        return None  # "5 cm toward the back edge": a place by the table's edge, not a move
    centre = False
    if k < len(ws) and ws[k] == "of":
        rest = ws[k + 1 : k + 6]
        if rest[:1] == ["the"]:
            rest = rest[1:]
        if rest[:1] in (["dead"], ["exact"], ["very"]) and rest[1:2] and rest[1] in _CENTRE_WORDS:
            # "6 inches left of (the) dead centre"
            return dx * metres, dy * metres, k + 1 + (ws[k + 1] == "the") + 2, True
        if rest[:2] in (["table", "centre"], ["table", "center"], ["table's", "centre"], ["table's", "center"]):
            centre, k = True, k + 1 + (ws[k + 1] == "the") + 2
        elif rest[:1] and rest[0] in _CENTRE_WORDS:
            centre, k = True, k + 1 + (ws[k + 1] == "the") + 1
            if ws[k : k + 2] == ["of", "the"] and k + 2 < len(ws) and ws[k + 2] in ("table", "workspace"):
                k += 3
        else:
            return None  # "10 cm left of the plate": a distance from an object
    return dx * metres, dy * metres, k, centre


_TURN_WORDS = frozenset({"rotated", "turned", "yaw", "rotation", "heading", "angle"})
_DEGREES = frozenset({"degrees", "degree", "deg", "\u00b0"})
_RADIANS = frozenset({"rad", "rads", "radian", "radians"})


def _turn_after(ws: list[str], k: int) -> tuple[float, int] | None:
    """A yaw said right after a move ("..., rotated 90 degrees counterclockwise", "with a yaw of 1.57 rad"):
    (radians, counter-clockwise; the end of its words), or None."""
    j = k
    while j < len(ws) and ws[j] in (",", "and", "with", "a", "then"):
        j += 1
    if j >= len(ws) or ws[j] not in _TURN_WORDS:
        return None
    j += 1
    while j < len(ws) and ws[j] in ("by", "to", "of", "about", "approximately", "roughly", "exactly"):
        j += 1
    got = _number_at(ws, j)
    if got is None:
        return None
    yaw, j = got
    if j < len(ws) and ws[j] in _DEGREES:
        yaw, j = math.radians(yaw), j + 1
    elif j < len(ws) and ws[j] in _RADIANS:
        j += 1
    if j < len(ws) and ws[j] in _CLOCKWISE:
        return -yaw, j + 1  # yaw is counter-clockwise: "90 degrees clockwise" is -pi/2
    if j < len(ws) and ws[j] in ("counterclockwise", "anticlockwise", "ccw"):
        return yaw, j + 1
    if ws[j : j + 3] in (["counter", "-", "clockwise"], ["anti", "-", "clockwise"]):
        return yaw, j + 3
    return yaw, j


#: A side of "it" said after a distance from the table's centre ("and 10 cm behind it").
_OF_IT = {("behind", "it"): (0.0, 1.0), ("in", "front", "of", "it"): (0.0, -1.0), ("left", "of", "it"): (-1.0, 0.0),
          ("right", "of", "it"): (1.0, 0.0), ("to", "the", "left", "of", "it"): (-1.0, 0.0),
          ("to", "the", "right", "of", "it"): (1.0, 0.0), ("north", "of", "it"): (0.0, 1.0),
          ("south", "of", "it"): (0.0, -1.0), ("east", "of", "it"): (1.0, 0.0), ("west", "of", "it"): (-1.0, 0.0)}


def _step_of_it(ws: list[str], i: int) -> tuple[float, float, int, bool] | None:
    """A distance to one side of "it" at ``i`` ("10 cm behind it"), said after a distance from the centre."""
    got = _number_at(ws, i)
    unit = _unit(ws, got[1]) if got is not None else None
    if got is None or unit is None:
        return None
    k = unit[1]
    side = next((s for s in _OF_IT if tuple(ws[k : k + len(s)]) == s), None)
    if side is None:
        return None
    dx, dy = _OF_IT[side]
    metres = got[0] * unit[0]
    return dx * metres, dy * metres, k + len(side), True


def find_offsets(text: str) -> list[SaidPose]:
    """Every move said as a distance in ``text``, left to right: after a verb of moving in the same
    sentence, from where the object stands ("slide the black bowl 10 cm further back", "move the star 8 cm
    to the left"); anywhere, from the table's centre ("the phone 10 cm right of the table centre and 5 cm
    toward the back"). Two distances joined by "and" or a comma make one move.

    >>> p = find_offsets("slide the bowl 10 cm further back from where it sits now")[0]
    >>> (p.frame, round(p.x, 3), round(p.y, 3))
    ('offset', 0.0, 0.1)
    >>> p = find_offsets("put the phone 10 cm right of the table centre and 5 cm toward the back")[0]
    >>> (p.frame, round(p.x, 3), round(p.y, 3))
    ('centre', 0.1, 0.05)
    >>> find_offsets("put the mug 10 cm left of the plate")
    []
    """
    toks = _tokens(text)
    ws = [t[0] for t in toks]
    out: list[SaidPose] = []
    moved = False
    i = 0
    while i < len(ws):
        if ws[i] in (".", ";", "!", "?"):
            moved = False
        elif ws[i] in _MOVES:
            moved = True
        got = _step(ws, i)
        if got is None:
            i += 1
            continue
        dx, dy, k, centre = got
        join = k + (ws[k : k + 1] == [","])
        join += ws[join : join + 1] == ["and"]
        if join > k:
            # "... and 5 cm toward the back", ", 100 mm toward me", "... and 10 cm behind it" (it: the centre)
            more = _step(ws, join) or (_step_of_it(ws, join) if centre else None)
            if more is not None and (more[0] == 0.0) != (dx == 0.0):
                dx, dy, k, centre = dx + more[0], dy + more[1], more[2], centre or more[3]
        here = next((h for h in _HERE if tuple(ws[k : k + len(h)]) == h), None)
        if here is not None:
            k += len(here)
        if centre or moved:
            turn = _turn_after(ws, k)  # "..., rotated 90 degrees counterclockwise": the yaw, never read past
            yaw, k = turn if turn is not None else (None, k)
            out.append(SaidPose(toks[i][1], toks[k - 1][2], dx, dy, yaw, "centre" if centre else "offset"))
        i = k
    return out


def _without_heading_words(text: str, found: list[SaidPose]) -> tuple[str, bool]:
    """``text`` with the words that say the posed objects keep their heading ("no rotation", "keep its angle as
    is") or end square to the table blanked (kept the same length, so that the poses' spans hold), and whether
    the latter was said."""
    toks = _tokens(text)
    ws = [t[0] for t in toks]
    cut: list[tuple[int, int]] = []
    square = False
    for i, end, name in lexicon.phrase_spans(ws, "same_heading", "square_heading"):
        if not any(a < toks[i][2] and toks[i][1] < b for a, b in cut):
            cut.append((toks[i][1], toks[end - 1][2]))
            square = square or name == "square_heading"
    for a, b in cut:
        if not any(p.start < b and a < p.end for p in found):
            text = text[:a] + " " * (b - a) + text[b:]
    return text, square


def mark_poses(text: str) -> tuple[str, list[SaidPose]]:
    """``text`` with each pose said in numbers (:func:`find_poses`) or as a move (:func:`find_offsets`) replaced
    by a marker word, and the poses in order."""
    said = find_poses(text)
    taken = [(p.start, p.end) for p in said]
    said += [p for p in find_offsets(text) if not any(a < p.end and p.start < b for a, b in taken)]
    found = sorted(said, key=lambda p: p.start)[:26]
    if found:
        text, square = _without_heading_words(text, found)
        if square:
            found = [replace(p, square=True) for p in found]
    out: list[str] = []
    at = 0
    for k, p in enumerate(found):
        out.append(text[at : p.start])
        out.append(f" {MARK}{chr(97 + k)} ")
        at = p.end
    out.append(text[at:])
    return "".join(out), found
