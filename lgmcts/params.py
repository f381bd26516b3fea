"""Where, how big and which way: the optional parameters of a pattern goal.

A goal may carry ``region`` (where on the table its objects go), ``size``
(how large the arrangement is) and ``facing`` (which way it faces). This
module says what the values mean, once, for the priors and the validator
alike: :func:`resolve` turns a goal's raw values into numbers (a box in
metres, a band of lengths, a heading in radians and its tolerance) for a
given workspace and objects. It is part of the goal format's definition
(``docs/formats.md``), not of any sampler.

Table frame: +x right (east), +y away from the viewer (north, "top"), yaw
counter-clockwise from +x.

Region
    The workspace is cut into a 3 x 3 grid of equal cells. Rows are
    ``bottom`` (front, nearest the viewer, smallest y), ``middle``, ``top``;
    columns ``left`` (smallest x), ``center``, ``right``. ``"<row> <col>"``
    names one cell; a row word alone (or ``"<row> row"``) names the whole row
    (three cells), a column word alone (or ``"<col> column"``) the whole
    column, and ``"center"`` or ``"middle"`` alone the centre cell (``"middle
    center"``), as "the middle of the table" reads in English; the middle
    row and the centre column are ``"middle row"`` and ``"center column"``. A box
    ``[xmin, xmax, ymin, ymax]`` (m) may be given instead of a name. The goal
    holds when every one of its objects' centres lies in the box, up to
    :data:`REGION_TOL` outside it (a relation's anchor is not one of its objects).
Size
    ``"small"``, ``"medium"``, ``"large"`` or a length in metres, compared to
    the arrangement's characteristic length L: a circle's fitted radius, a
    line's length (the spread of its centres along the fitted line), a
    rectangle's longer side (of the minimum-area rectangle around the
    centres). A tower has no size of its own (its footprint is its base
    object's): a size on a tower goal is accepted and ignored. Named sizes
    cut the range [L_min, L_max] into thirds, where L_min is the tightest
    arrangement of the goal's objects and L_max the largest whose centres fit
    in the room (the region, or the workspace, with the largest object's
    circumradius kept from the workspace edge); see :func:`size_range`.
    ``small`` is L <= the first third, ``large`` L >= the second, ``medium``
    between; each edge has a slack of :data:`SIZE_TOL`. A number s asks for
    |L - s| <= :data:`SIZE_TOL`.
Facing
    ``"north"`` (+y), ``"east"`` (+x), ``"south"`` (-y), ``"west"`` (-x) or a
    heading in radians. Every object of the goal ends with its yaw (its
    object-frame +x axis) within the tolerance of the heading: within pi/8 of
    a named direction (so "north" never accepts north-east), within
    :data:`FACING_TOL` of a number. A line also runs across the heading (a
    row of objects facing north runs east-west), and a rectangle's sides run
    along and across it, both to the same tolerance. A circle and a tower
    have no front of their own: facing turns only their objects.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

__all__ = [
    "COLUMNS",
    "FACING_TOL",
    "HEADINGS",
    "NAMED_FACING_TOL",
    "REGION_NAMES",
    "REGION_TOL",
    "ROWS",
    "SIZES",
    "SIZE_TOL",
    "GoalParams",
    "conflict",
    "heading_of",
    "region_box",
    "region_name",
    "resolve",
    "size_range",
    "sized_pattern",
    "turn_relation",
]

#: Rows bottom to top and columns left to right, each a third of the workspace.
ROWS: tuple[str, ...] = ("bottom", "middle", "top")
COLUMNS: tuple[str, ...] = ("left", "center", "right")
SIZES: tuple[str, ...] = ("small", "medium", "large")
#: Heading of each named facing (rad).
HEADINGS: dict[str, float] = {"east": 0.0, "north": math.pi / 2, "west": math.pi, "south": -math.pi / 2}
#: Every region name the format accepts.
REGION_NAMES: tuple[str, ...] = (
    *(f"{r} {c}" for r in ROWS for c in COLUMNS),
    *ROWS,
    *COLUMNS,
    *(f"{r} row" for r in ROWS),
    *(f"{c} column" for c in COLUMNS),
)

#: How far outside its region an object's centre may end (m).
REGION_TOL = 0.015
#: Slack on a size band's edges, and on a size given in metres (m).
SIZE_TOL = 0.015
#: Heading tolerance of a facing given in radians (rad).
FACING_TOL = 0.1
#: Heading tolerance of a named facing (rad): half an eight-point compass sector.
NAMED_FACING_TOL = math.pi / 8



def _norm(name: str) -> str:
    return " ".join(name.lower().split())


def region_box(region: str | Sequence[float], bounds: Sequence[float]) -> tuple[float, float, float, float]:
    """``(xmin, xmax, ymin, ymax)`` of a region name or box in a workspace ``bounds``.

    Raises ``ValueError`` for an unknown name or a malformed box.
    """
    if not isinstance(region, str):
        box = tuple(float(v) for v in region)
        if len(box) != 4 or not all(math.isfinite(v) for v in box) or not (box[0] < box[1] and box[2] < box[3]):
            raise ValueError("a region box is [xmin, xmax, ymin, ymax] with min < max")
        return box[0], box[1], box[2], box[3]
    xmin, xmax, ymin, ymax = (float(v) for v in bounds)
    words = _norm(region).split()
    if words in (["center"], ["middle"]):
        words = ["middle", "center"]
    elif len(words) == 2 and words[1] == "row" and words[0] in ROWS:
        words = words[:1]  # "middle row": the band, as a row word alone
    elif len(words) == 2 and words[1] == "column" and words[0] in COLUMNS:
        words = words[:1]
    row = col = None
    if len(words) == 2:
        row, col = words
        if row not in ROWS or col not in COLUMNS:
            raise ValueError(
                f"unknown region '{region}' (a '<row> <col>' with row in {'|'.join(ROWS)}, col in {'|'.join(COLUMNS)})"
            )
    elif len(words) == 1 and words[0] in ROWS:
        row = words[0]
    elif len(words) == 1 and words[0] in COLUMNS:
        col = words[0]
    else:
        raise ValueError(
            f"unknown region '{region}' (a '<row> <col>' with row in {'|'.join(ROWS)}, col in {'|'.join(COLUMNS)})"
        )
    wx, wy = (xmax - xmin) / 3, (ymax - ymin) / 3
    x0, x1 = (xmin, xmax) if col is None else (xmin + COLUMNS.index(col) * wx, xmin + (COLUMNS.index(col) + 1) * wx)
    y0, y1 = (ymin, ymax) if row is None else (ymin + ROWS.index(row) * wy, ymin + (ROWS.index(row) + 1) * wy)
    # The outer edges are the workspace's own, exactly.
    x1 = xmax if col in (None, "right") else x1
    y1 = ymax if row in (None, "top") else y1
    return (x0, x1, y0, y1)


def region_name(x: float, y: float, bounds: Sequence[float]) -> str:
    """The ``"<row> <col>"`` cell holding point ``(x, y)`` (points on a shared edge go up / right)."""
    xmin, xmax, ymin, ymax = (float(v) for v in bounds)
    c = min(2, max(0, int((x - xmin) / ((xmax - xmin) / 3))))
    r = min(2, max(0, int((y - ymin) / ((ymax - ymin) / 3))))
    return f"{ROWS[r]} {COLUMNS[c]}"


def heading_of(facing: str | float) -> tuple[float, float]:
    """Heading (rad) and its tolerance (rad) of a facing name or angle."""
    if isinstance(facing, str):
        key = _norm(facing)
        if key not in HEADINGS:
            raise ValueError(f"unknown facing '{facing}' (north|east|south|west or an angle in radians)")
        return HEADINGS[key], NAMED_FACING_TOL
    a = float(facing)
    if not math.isfinite(a):
        raise ValueError("a facing angle must be a finite number")
    return math.atan2(math.sin(a), math.cos(a)), FACING_TOL


def _shrunk(box: Sequence[float], bounds: Sequence[float], margin: float) -> tuple[float, float, float, float]:
    """``box`` intersected with the workspace shrunk by ``margin`` (may be empty: min > max)."""
    return (
        max(box[0], bounds[0] + margin),
        min(box[1], bounds[1] - margin),
        max(box[2], bounds[2] + margin),
        min(box[3], bounds[3] - margin),
    )


def sized_pattern(name: str) -> Any:
    """The registered pattern ``name`` when it measures a size (its
    ``size_word`` is set), else ``None`` (no such pattern, no size, or a size
    accepted and ignored, as a tower's)."""
    from .patterns.base import registry

    pat = registry().get(name)
    return pat if pat is not None and pat.size_word is not None else None


def size_range(
    pattern: str, n: int, rmax: float, room: Sequence[float], size: str | float, heading: float | None = None
) -> tuple[float, float]:
    """The lengths L (m) a goal's ``size`` accepts, edges exact (no slack).

    ``n`` objects of largest circumradius ``rmax``; ``room`` the box their
    centres may take (region and workspace, see :func:`resolve`). Named sizes
    split [L_min, L_max] into thirds:

    [L_min, L_max] is the pattern's own (its ``size_band``):

    * circle: L_min = max(0.05, rmax / sin(pi / n)) (neighbours' circles
      touch), L_max = half the room's shorter side;
    * line: L_min = 2 rmax (n - 1), L_max = the room's extent along the
      line's direction when ``heading`` fixes it (the line runs across it),
      else its longer side;
    * rectangle: L_min = max(0.05, n rmax / 2), L_max = the room's longer side.

    ``small`` is (0, L1], ``medium`` [L1, L2], ``large`` [L2, inf), with
    L1, L2 the thirds (both L_min when the room is smaller than L_min).
    """
    if not isinstance(size, str):
        s = float(size)
        return s, s
    pat = sized_pattern(pattern)
    if pat is None:
        raise ValueError(f"a {pattern} goal has no size")
    r = (float(room[0]), float(room[1]), float(room[2]), float(room[3]))
    lo, hi = pat.size_band(n, rmax, r, heading)
    hi = max(hi, lo)
    a, b = lo + (hi - lo) / 3, lo + 2 * (hi - lo) / 3
    key = _norm(size)
    if key == "small":
        return 0.0, a
    if key == "medium":
        return a, b
    if key == "large":
        return b, math.inf
    raise ValueError(f"unknown size '{size}' (small|medium|large or a length in metres)")


@dataclass(frozen=True)
class GoalParams:
    """A goal's parameters in numbers, for one workspace and set of objects.

    Attributes
    ----------
    box : ``(xmin, xmax, ymin, ymax)`` the objects' centres must lie in, or
        ``None`` for no region.
    room : the box intersected with the workspace shrunk by the largest
        object's circumradius: where centres can go (may be empty, min > max).
    size : ``(lo, hi)`` accepted characteristic lengths (m) before the
        :data:`SIZE_TOL` slack, or ``None`` (no size, or a tower's).
    heading : the facing heading (rad) or ``None``.
    heading_tol : its tolerance (rad).
    """

    box: tuple[float, float, float, float] | None = None
    room: tuple[float, float, float, float] | None = None
    size: tuple[float, float] | None = None
    heading: float | None = None
    heading_tol: float = FACING_TOL

    @property
    def empty(self) -> bool:
        return self.box is None and self.size is None and self.heading is None


def _raw(goal: Any, key: str) -> Any:
    return goal.get(key) if isinstance(goal, dict) else getattr(goal, key, None)


def resolve(goal: Any, bounds: Sequence[float], radii: Sequence[float]) -> GoalParams:
    """Numbers for ``goal``'s ``region``, ``size`` and ``facing``.

    ``goal`` is a :class:`lgmcts.formats.Goal` (or a dict with those keys),
    ``bounds`` the workspace ``(xmin, xmax, ymin, ymax)`` and ``radii`` the
    circumradii of the goal's objects. Raises ``ValueError`` for a value the
    format does not know.
    """
    region, size, facing = _raw(goal, "region"), _raw(goal, "size"), _raw(goal, "facing")
    pattern = _raw(goal, "pattern")
    objects = _raw(goal, "objects") or ()
    if region is None and size is None and facing is None:
        return GoalParams()
    rmax = float(max(radii)) if len(radii) else 0.0
    bounds = tuple(float(v) for v in bounds)
    box = None if region is None else region_box(region, bounds)
    room = _shrunk(box if box is not None else bounds, bounds, rmax)
    heading, tol = (None, FACING_TOL) if facing is None else heading_of(facing)
    band = None
    if size is not None and sized_pattern(pattern) is not None:
        band = size_range(pattern, len(objects), rmax, room, size, heading)
    return GoalParams(box, room, band, heading, tol)


def turn_relation(relation: str, facing: str | float) -> str:
    """A relation said from the point of view of someone facing ``facing``,
    as the table-frame relation it means (the nearest of the eight).

    The viewer stands at the front edge facing north, so for ``"north"`` a
    relation is unchanged; facing south, "left" is the table's ``"right"``
    and "front" its ``"behind"``. A composite setting that faces a way (a
    dinner setting's cutlery "left of the plate") turns its relations so.
    """
    from .formats import RELATIONS

    if relation not in RELATIONS:
        raise ValueError(f"unknown relation '{relation}'")
    h, _ = heading_of(facing)
    a = math.atan2(RELATIONS[relation][1], RELATIONS[relation][0]) + h - math.pi / 2
    best = min(
        RELATIONS, key=lambda r: abs(math.remainder(math.atan2(RELATIONS[r][1], RELATIONS[r][0]) - a, 2 * math.pi))
    )
    return best


def conflict(goals: Sequence[Any], bounds: Sequence[float]) -> str | None:
    """Why no arrangement can meet ``goals``' parameters together, or ``None``.

    An object in two goals cannot face two headings further apart than both
    tolerances, nor lie in two regions that do not meet (each grown by
    :data:`REGION_TOL`). Only these direct contradictions are found.
    """
    seen: dict[int, list[tuple[int, Any]]] = {}
    for k, g in enumerate(goals):
        for o in _raw(g, "objects") or ():
            seen.setdefault(o, []).append((k, g))
    for o, gs in sorted(seen.items()):
        for i in range(len(gs)):
            for j in range(i + 1, len(gs)):
                (ka, a), (kb, b) = gs[i], gs[j]
                fa, fb = _raw(a, "facing"), _raw(b, "facing")
                if fa is not None and fb is not None:
                    (ha, ta), (hb, tb) = heading_of(fa), heading_of(fb)
                    if abs(math.remainder(ha - hb, 2 * math.pi)) > ta + tb:
                        return f"object {o} must face both {fa!r} (goal {ka}) and {fb!r} (goal {kb})"
                ra, rb = _raw(a, "region"), _raw(b, "region")
                if ra is not None and rb is not None:
                    xa, xb = region_box(ra, bounds), region_box(rb, bounds)
                    e = 2 * REGION_TOL
                    if xa[0] > xb[1] + e or xb[0] > xa[1] + e or xa[2] > xb[3] + e or xb[2] > xa[3] + e:
                        return f"object {o} must lie both in {ra!r} (goal {ka}) and in {rb!r} (goal {kb})"
    return None
