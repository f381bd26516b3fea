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
from dataclasses import dataclass

__all__ = ["MARK", "SaidPose", "find_poses", "is_mark", "mark_poses"]

#: Marker words standing for the poses of a command ("posemarka", "posemarkb" ...).
MARK = "posemark"

_NUM = r"[-+−]?(?:\d+(?:\.\d+)?|\.\d+)"
_UNIT = r"(?:mm|cm|m|millimet(?:re|er)s?|centimet(?:re|er)s?|met(?:re|er)s?)\b"
_ANGLE = rf"(?:(?:{_NUM})?\s*\*?\s*pi(?:\s*/\s*\d+)?|{_NUM})"
_ANGLE_UNIT = r"(?:rad(?:ians?)?\b|deg(?:rees?)?\b|°)"
_YAW = (rf"(?:\s*(?:,|and|with)?\s*(?:yaw|theta|heading|rotation|angle|rotated|turned)\s*(?:of|by|to)?\s*[=:]?\s*"
        rf"(?P<yaw>{_ANGLE})\s*(?P<yu>{_ANGLE_UNIT})?)?")
#: "x = 0.1 m, y = -5 cm (, yaw 90 deg)" or "at (10 cm, -5 cm(, pi/2))": the second form's groups end in "p".
_POSE = re.compile(
    rf"(?i)\bx\s*[=:]?\s*(?P<x>{_NUM})\s*(?P<xu>{_UNIT})?\s*(?:,|and)?\s*\by\s*[=:]?\s*(?P<y>{_NUM})\s*(?P<yu_>{_UNIT})?"
    + _YAW
    + rf"|(?<=\b(?:at|to)\s)\s*\(\s*(?P<xp>{_NUM})\s*(?P<xup>{_UNIT})?\s*,\s*(?P<yp>{_NUM})\s*(?P<yu_p>{_UNIT})?"
    rf"(?:\s*,\s*(?P<yawp>{_ANGLE})\s*(?P<yup>{_ANGLE_UNIT})?)?\s*\)"
    + _YAW.replace("?P<yaw>", "?P<yaw2>").replace("?P<yu>", "?P<yu2>"))
_SCALE = {"mm": 0.001, "cm": 0.01, "m": 1.0}


@dataclass(frozen=True)
class SaidPose:
    """One pose said in numbers: its character span, x and y in metres, yaw in radians (None: not said)."""

    start: int
    end: int
    x: float
    y: float
    yaw: float | None


def is_mark(word: str) -> bool:
    """Whether a token is a pose's marker."""
    return len(word) == len(MARK) + 1 and word.startswith(MARK) and "a" <= word[-1] <= "z"


def _scale(unit: str | None) -> float | None:
    if not unit:
        return None
    u = unit.lower()
    if u.startswith("milli") or u == "mm":
        return _SCALE["mm"]
    if u.startswith("centi") or u == "cm":
        return _SCALE["cm"]
    return _SCALE["m"]


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


def _pose(m: re.Match) -> SaidPose:
    g = m.groupdict()
    p = "" if g["x"] is not None else "p"
    xs, ys = _scale(g["xu" + p]), _scale(g["yu_" + p])
    xs, ys = xs or ys or 1.0, ys or xs or 1.0
    yaw_s = g.get("yaw" + p) or g.get("yaw2")
    yaw_u = g.get("yu" + p) or g.get("yu2")
    yaw = _angle(yaw_s, yaw_u) if yaw_s else None
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


def mark_poses(text: str) -> tuple[str, list[SaidPose]]:
    """``text`` with each pose said in numbers replaced by a marker word, and the poses in order."""
    found = find_poses(text)[:26]
    out: list[str] = []
    at = 0
    for k, p in enumerate(found):
        out.append(text[at : p.start])
        out.append(f" {MARK}{chr(97 + k)} ")
        at = p.end
    out.append(text[at:])
    return "".join(out), found
