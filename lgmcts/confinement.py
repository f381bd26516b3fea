"""A proof that an object can never reach its pose goal by table placements.

:func:`confined` decides, for scenes where every object stands on the table
and every goal is a ``pose`` goal, whether some object is *confined*: the
centres it can ever occupy, over every sequence of pick-and-place actions
that keeps all objects on the table, stay farther than the pose rule's
``TOL`` from its target. Then no plan of that kind exists, and the planner
says so at once instead of searching to its budget. The planner stacks
objects only where a goal asks for it, so for such scenes it could never
find a plan either.

The argument. Give each object ``i`` a disc of radius ``rho_i`` inside its
footprint (the cylinder's own circle, or the largest disc about the centre),
a region ``C_i`` of centres that keep the footprint inside the workspace
(the box shrunk by ``rho_i`` less the validator's ``EDGE_TOL``), and a least
centre distance ``d_ij`` below which the two discs overlap by more than the
validator's ``OVERLAP_AREA`` (so the footprints do too). Suppose regions
``W_j`` hold every object's centre. Object ``i`` can then only be put where
it is at least ``d_ij`` from wherever ``j`` stands, so never in
``core_j = {p : |p - q| < d_ij for every q in W_j}``, the points within
``d_ij`` of all of ``W_j`` (of all corners of its convex hull). If, for
every ``i``, ``C_i`` minus the union of the other cores lies inside ``W_i``,
and every object starts in its ``W_i``, then by induction over the actions
no object ever leaves its ``W_i``. Such regions are found by growing them
from the start positions to a fixed point; an object whose region stays more
than ``TOL`` from its target can never satisfy its goal.

Every approximation errs on the safe side: a core is cut with discs drawn as
inscribed polygons (smaller cores, larger regions), regions are widened by a
nanometre each round, ``d_ij`` uses the smallest ``rho`` of the other objects,
regions are convex polygons with 32 fixed side directions enclosing what
they must hold, and the closure is checked on support numbers before a
refusal.
"""

from __future__ import annotations

import math
import time

import numpy as np
import shapely

from . import geometry as geo
from .formats import GoalSpec
from .scene import TABLE, Scene
from .tolerances import OVERLAP_AREA, TOL

__all__ = ["confined", "contact_distance"]

#: Validator's allowance (m) of a footprint vertex beyond the workspace edge.
_EDGE_TOL = 1e-3
#: Each round's widening of the regions (m): keeps the closure test robust to rounding.
_GROW = 1e-9
_ROUNDS = 60


def contact_distance(r1: float, r2: float) -> float:
    """Smallest centre distance (m) at which discs of radii ``r1``, ``r2`` overlap by at most ``OVERLAP_AREA``.

    Rounded down (bisection to 1e-12 m), so a pair closer than this overlaps
    by more than the allowance.
    """
    lo, hi = 0.0, r1 + r2
    if geo.lens_area(r1, r2, lo) <= OVERLAP_AREA:
        return 0.0
    while hi - lo > 1e-12:
        mid = (lo + hi) / 2
        if geo.lens_area(r1, r2, mid) > OVERLAP_AREA:
            lo = mid
        else:
            hi = mid
    return lo


def _rho(sc: Scene, i: int) -> float:
    if sc.discs[i] > 0:
        return float(sc.discs[i])
    poly = shapely.Polygon(sc.local[i])
    origin = shapely.Point(0.0, 0.0)
    return float(poly.exterior.distance(origin)) if poly.contains(origin) else 0.0


#: Directions of the support lines that bound every region (a convex polygon with 2 x 16 sides).
_DIRS = np.stack([np.cos(np.arange(32) * math.pi / 16), np.sin(np.arange(32) * math.pi / 16)], axis=1)


def _support(geom) -> np.ndarray:
    """Support of ``geom`` along each of :data:`_DIRS` (``-inf`` when empty)."""
    pts = shapely.get_coordinates(geom)
    if not len(pts):
        return np.full(len(_DIRS), -np.inf)
    return (pts @ _DIRS.T).max(axis=0)


def _corners(h: np.ndarray) -> np.ndarray:
    """Corners of the polygon ``{x : x . u_k <= h_k for every k}`` (it contains every set of support ``<= h``)."""
    u, v = _DIRS, np.roll(_DIRS, -1, axis=0)
    hv = np.roll(h, -1)
    det = u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0]
    x = (h * v[:, 1] - hv * u[:, 1]) / det
    y = (u[:, 0] * hv - v[:, 0] * h) / det
    return np.stack([x, y], axis=1)


def _core(h: np.ndarray, d: float):
    """Points within ``d`` of every point of the polygon of support ``h``, as a polygon inside that set; or ``None``."""
    pts = _corners(h)
    span = float(np.sqrt(((pts[:, None, :] - pts[None, :, :]) ** 2).sum(-1)).max())
    if span >= 2 * d:
        return None
    if span < 1e-6:
        # A point, to rounding: the disc about it, shrunk by the span, is inside the core.
        return shapely.Point(pts.mean(axis=0)).buffer(d - span, quad_segs=16)
    core = shapely.intersection_all(shapely.buffer(shapely.points(pts), d, quad_segs=16))
    return None if core.is_empty else core


def confined(scene: Scene, goals: GoalSpec, *, budget_s: float = 0.5) -> str | None:
    """One line saying why no table-only plan can meet ``goals``, or ``None`` when none is proved.

    Applies only when every goal is a ``pose`` goal and every object starts
    on the table; ``None`` otherwise, or when ``budget_s`` runs out first
    (the answer is then only "not proved"). Cost: a few rounds of polygon
    operations over the objects whose regions are still small.
    """
    sc = scene
    if not goals.goals or any(g.pattern != "pose" or g.pose is None for g in goals.goals):
        return None
    if any(o != TABLE for o in sc.initial.on):
        return None
    t0 = time.perf_counter()
    n = sc.n
    targets = {sc.index[g.objects[0]]: np.asarray(g.pose[:2], dtype=float) for g in goals.goals if g.pose is not None}
    start = sc.initial.poses[:, :2]
    if all(math.dist(start[i], t) <= TOL for i, t in targets.items()):
        return None
    rho = np.array([_rho(sc, i) for i in range(n)])
    if n < 2 or (rho <= 0).any():
        return None
    xmin, xmax, ymin, ymax = sc.bounds
    order = np.argsort(rho)
    d = np.empty(n)
    known: dict[tuple[float, float], float] = {}
    for j in range(n):
        pair = (float(rho[order[0] if order[0] != j else order[1]]), float(rho[j]))
        if pair not in known:
            known[pair] = contact_distance(*pair)
        d[j] = known[pair]
    boxes: list = []
    by_rho: dict[float, object] = {}
    for i in range(n):
        if float(rho[i]) in by_rho:
            boxes.append(by_rho[float(rho[i])])
            continue
        m = rho[i] - _EDGE_TOL
        lo_x, hi_x = max(xmin, xmin + m), min(xmax, xmax - m)
        lo_y, hi_y = max(ymin, ymin + m), min(ymax, ymax - m)
        if lo_x > hi_x or lo_y > hi_y:
            return None
        boxes.append(shapely.box(lo_x, lo_y, hi_x, hi_y))
        by_rho[float(rho[i])] = boxes[-1]
    # Each region is the convex polygon of its support numbers along _DIRS.
    regions = [_support(shapely.Point(start[i])) + _GROW for i in range(n)]
    dmax = float(d.max())
    for rnd in range(_ROUNDS):
        if time.perf_counter() - t0 > budget_s:
            return None
        if rnd == 0:
            cores = [shapely.Point(start[j]).buffer(float(d[j]), quad_segs=16) for j in range(n)]
        else:
            cores = [_core(h, float(d[j])) for j, h in enumerate(regions)]
        live = [j for j in range(n) if cores[j] is not None]
        if not live:
            return None  # nothing is kept anywhere: every region becomes its whole box
        union = shapely.union_all([cores[j] for j in live])
        tree = shapely.STRtree([cores[j] for j in live])
        if rnd == 0:
            # Room left by every core joins every region; wide room empties every core.
            room = _support(boxes[int(order[-1])].difference(union))
            if (room + np.roll(room, len(_DIRS) // 2)).max() >= 2 * dmax:
                return None
        grown = False
        new = []
        shared: dict[int, np.ndarray] = {}
        for i in range(n):
            if time.perf_counter() - t0 > budget_s:
                return None
            key = id(boxes[i])
            if key not in shared:
                shared[key] = _support(boxes[i].difference(union))
            h = shared[key]
            if cores[i] is not None:
                # Points of i's own core are open to i unless another core covers them.
                near = [live[k] for k in tree.query(cores[i]) if live[k] != i]
                mine = boxes[i].intersection(cores[i])
                if near:
                    mine = mine.difference(shapely.union_all([cores[j] for j in near]))
                h = np.maximum(h, _support(mine))
            if (h > regions[i]).any():
                grown = True
                new.append(np.maximum(regions[i], h + _GROW))
            else:
                new.append(regions[i])
        regions = new
        polys = {i: shapely.Polygon(_corners(regions[i])) for i in targets}
        if all(polys[i].distance(shapely.Point(t)) <= TOL for i, t in targets.items()):
            return None
        if not grown:
            far = [i for i, t in targets.items() if polys[i].distance(shapely.Point(t)) > TOL]
            i = min(far, key=lambda k: sc.ids[k])
            gap = polys[i].distance(shapely.Point(targets[i]))
            return (f"no plan keeping the objects on the table exists: object {sc.ids[i]} can never come within "
                    f"{TOL * 1000:.0f} mm of its pose goal (every place it could ever be put lies in "
                    f"{polys[i].area * 1e4:.1f} cm^2 about its start, {gap:.3f} m from the goal; "
                    f"{len(far)} of {len(targets)} goal objects are so confined)")
    return None
