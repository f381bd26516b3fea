"""Goals that are jointly impossible in an obvious way, refused before any search.

:func:`precheck` runs a few cheap, sound tests: each refusal is a proof that
no plan can meet the goals (for a planner that puts pose-goal objects on the
table), so a refused input could never have been solved; what it lets
through may still be unsolvable, and the search then ends unsolved as before.

The tests rest on one fact: the footprint of an object contains the disc of
radius ``rho`` (its *inradius about its centre*: the distance from the pose
centre to the nearest edge) about its centre, and the footprints of objects
on the table are disjoint, so these discs are too.

* a pose goal's centre must lie inside the workspace;
* two pose goals whose footprints overlap (beyond the validator's
  ``OVERLAP_AREA``) can only be met by stacking one object on the other,
  which only a tower goal asks for: refused unless both objects are in
  tower goals;
* the objects that must end on the table (those of line, circle, rectangle
  and spatial goals, tower bases) need no more area than the workspace has;
* a line of n objects spans, along the line, at least
  ``sum(f(2 q_k), k < n - 1)`` with ``f(s) = sqrt(max(0, s^2 - (2 TOL)^2))``
  and ``q`` the inradii sorted ascending, each listed twice: two centres at
  most ``2 TOL`` apart across the line are at least ``rho_i + rho_j`` apart,
  and each object is the smaller of at most two neighbouring pairs. The span
  must fit in the workspace's diagonal;
* the objects placed in one direction of one anchor have their centres in a
  90-degree sector of radius ``MAX_RELATION_DIST`` about the anchor; their
  discs must fit in that sector grown by the largest ``rho``.
"""

from __future__ import annotations

import math

import numpy as np
import shapely

from . import geometry as geo
from .errors import InputError
from .formats import RELATIONS, GoalSpec, SceneSpec, pattern_format
from .scene import Scene
from .validate import MAX_RELATION_DIST as _MAX_RELATION_DIST
from .validate import OVERLAP_AREA as _OVERLAP_AREA
from .validate import TOL as _TOL

__all__ = ["inradius", "precheck"]

def inradius(local: np.ndarray) -> float:
    """Distance from the object-frame origin (the pose centre) to the footprint's boundary; 0 if outside."""
    poly = shapely.Polygon(local)
    origin = shapely.Point(0.0, 0.0)
    if not poly.contains(origin):
        return 0.0
    return float(poly.exterior.distance(origin))


def _line_span(rho: list[float]) -> float:
    """A lower bound (m) on the extent along their line of disjoint discs of radii ``rho``."""
    q = [r for r in sorted(rho) for _ in (0, 1)][: max(len(rho) - 1, 0)]
    return sum(math.sqrt(max(0.0, (2 * r) ** 2 - (2 * _TOL) ** 2)) for r in q)


def precheck(scene: Scene | SceneSpec, goals: GoalSpec) -> None:
    """Raise :class:`InputError` (one line) when ``goals`` obviously cannot be met in ``scene``.

    ``goals`` must already refer only to objects of ``scene``
    (:meth:`GoalSpec.check_against`). Cost: about n log n in the objects.
    """
    sc = scene if isinstance(scene, Scene) else Scene.from_spec(scene)
    xmin, xmax, ymin, ymax = sc.bounds
    in_tower: set[int] = set()
    on_table: set[int] = set()
    for g in goals.goals:
        if g.pattern == "tower":
            in_tower.update(g.objects)
            on_table.add(g.objects[0])
        fmt = pattern_format(g.pattern)
        if fmt is not None and fmt.on_table:
            on_table.update(g.objects)
    _pose_goals(sc, goals, in_tower, (xmin, xmax, ymin, ymax))
    area = {i: float(shapely.area(shapely.Polygon(sc.local[sc.index[i]]))) for i in on_table}
    need = sum(area.values())
    have = (xmax - xmin) * (ymax - ymin)
    if need > have:
        raise InputError(
            f"the {len(on_table)} objects that must stand on the table cover {need:.3f} m^2, "
            f"more than the workspace's {have:.3f} m^2"
        )
    diagonal = math.hypot(xmax - xmin, ymax - ymin)
    rho_cache: dict[int, float] = {}

    def rho(i: int) -> float:
        if i not in rho_cache:
            rho_cache[i] = inradius(sc.local[sc.index[i]])
        return rho_cache[i]

    sectors: dict[tuple[int, str], list[int]] = {}
    for k, g in enumerate(goals.goals):
        if g.pattern == "line" and len(g.objects) >= 2:
            r = [rho(i) for i in g.objects]
            span = _line_span(r)
            if span > diagonal:
                raise InputError(
                    f"goal {k} (line of {len(r)} objects) needs at least {span:.3f} m along the line; "
                    f"the workspace's diagonal is {diagonal:.3f} m"
                )
        if g.anchor is not None and g.pattern in RELATIONS:
            sectors.setdefault((g.anchor, g.pattern), []).extend(g.objects)
    for (anchor, rel), objs in sectors.items():
        objs = sorted(set(objs))
        r = [rho(i) for i in objs]
        grow = max(r)
        radius = _MAX_RELATION_DIST
        sector_area = math.pi / 4 * radius**2
        perimeter = 2 * radius + math.pi / 2 * radius
        room = sector_area + perimeter * grow + math.pi * grow**2
        need = math.pi * sum(x * x for x in r)
        if need > room:
            raise InputError(
                f"{len(objs)} objects cannot all be '{rel}' of anchor {anchor} within {radius} m "
                f"(they need {need:.3f} m^2, the region holds {room:.3f} m^2)"
            )


def _pose_goals(sc: Scene, goals: GoalSpec, in_tower: set[int], bounds: tuple[float, float, float, float]) -> None:
    xmin, xmax, ymin, ymax = bounds
    ids: list[int] = []
    poses: list[tuple[float, float, float]] = []
    for k, g in enumerate(goals.goals):
        if g.pattern != "pose" or g.pose is None:
            continue
        x, y, _ = g.pose
        if not (xmin <= x <= xmax and ymin <= y <= ymax):
            raise InputError(f"goal {k} (pose) puts object {g.objects[0]} outside the workspace")
        if g.objects[0] in ids:
            continue  # the same pose twice (check_against refuses two different ones)
        ids.append(g.objects[0])
        poses.append(g.pose)
    if len(ids) < 2:
        return
    idx = [sc.index[i] for i in ids]
    polys = np.array(
        [shapely.Polygon(sc.footprint(k, np.asarray(p, dtype=float))) for k, p in zip(idx, poses)], dtype=object
    )
    # Two cylinders may touch, as the validator allows: judged on their circles.
    a, b, areas = geo.overlap_pairs(polys, sc.discs[idx], np.array([p[:2] for p in poses], dtype=float))
    for pair in np.flatnonzero(areas > _OVERLAP_AREA):
        i, j = ids[int(a[pair])], ids[int(b[pair])]
        if i in in_tower and j in in_tower:
            continue
        raise InputError(
            f"objects {i} and {j} have pose goals whose footprints overlap by {areas[pair] * 1e4:.2f} cm^2 "
            "(only a tower goal stacks objects)"
        )
