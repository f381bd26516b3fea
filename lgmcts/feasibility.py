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
  discs must fit in that sector grown by the largest ``rho``;
* a size in metres must be within ``SIZE_TOL`` of a length the objects can
  take (:func:`_min_length`);
* one object cannot be in two directions of one anchor more than twice the
  relation rule's half-angle apart;
* the objects of a circle that are all in one line goal must be small enough
  to stand in two tight clusters (:func:`_line_and_circle`);
* three or more pose targets in one line goal must fit in a strip ``4 TOL``
  wide;
* an object that must move, under objects that no goal places, needs the
  table to hold them all beside the ones already there (this planner parks
  what it unstacks on the table: a proof for this planner).

One test is about order rather than area: an ordered pattern places its
objects after something else (a tower level after the level below it, a
relation's objects after their anchor, which they are placed relative to).
When these orders form a cycle, as in a tower ``[1, 2]`` with "1 right of 2"
(1 carries 2, and 2 is the place 1 is put beside), no object of the cycle
can be placed first; the goal format already refuses cycles of towers alone
and of relations alone (:meth:`lgmcts.formats.GoalSpec.check_against`),
this test the mixed ones.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import shapely

from . import geometry as geo
from .errors import InputError
from .formats import RELATIONS, GoalSpec, SceneSpec, pattern_format
from .params import SIZE_TOL as _SIZE_TOL
from .patterns import registry
from .scene import TABLE, Scene
from .tolerances import MIN_CIRCLE_RADIUS as _MIN_CIRCLE_RADIUS
from .tolerances import MIN_RECT_SIDE as _MIN_RECT_SIDE
from .tolerances import RELATION_HALF_ANGLE as _RELATION_HALF_ANGLE
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
    _order(goals)
    _pose_goals(sc, goals, in_tower, (xmin, xmax, ymin, ymax))
    table = sorted(on_table)
    shapes = geo.place_each([sc.local[sc.index[i]] for i in table], np.zeros((len(table), 3)))[1]
    area = dict(zip(table, shapely.area(shapes).tolist()))
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
    _opposite_relations(goals)
    _sizes(goals, rho)
    _line_and_circle(goals, rho)
    _line_through_targets(goals)
    _unstacking(sc, goals, have)


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
        ids.append(g.objects[0])
        poses.append(g.pose)
    # The same pose twice counts once (check_against refuses two different ones).
    first = {i: k for k, i in reversed(list(enumerate(ids)))}
    ids, poses = [ids[k] for k in sorted(first.values())], [poses[k] for k in sorted(first.values())]
    if len(ids) < 2:
        return
    idx = [sc.index[i] for i in ids]
    polys = geo.place_each([sc.local[k] for k in idx], np.asarray(poses, dtype=float))[1]
    discs = sc.discs[idx]
    xy = np.array([p[:2] for p in poses], dtype=float)
    # Only a pair with an object outside every tower can be refused: those
    # objects are queried, a few hundred at a time, so that targets stacked
    # in towers (which may all overlap) cost no pairs, and the first overlap
    # found ends the test.
    tree = shapely.STRtree(polys)
    loose = np.array([k for k, i in enumerate(ids) if i not in in_tower], dtype=int)
    for c in range(0, len(loose), 256):
        src = loose[c:c + 256]
        qa, qb = tree.query(polys[src], predicate="intersects")
        qa = src[qa]
        keep = qa != qb
        qa, qb = qa[keep], qb[keep]
        for d in range(0, len(qa), 1024):  # the exact areas, a batch at a time, up to the first overlap
            a, b = qa[d:d + 1024], qb[d:d + 1024]
            areas = np.array(shapely.area(shapely.intersection(polys[a], polys[b])), dtype=float)
            # Two cylinders may touch, as the validator allows: judged on their circles.
            for k in np.flatnonzero((discs[a] > 0) & (discs[b] > 0)).tolist():
                areas[k] = geo.lens_area(float(discs[a[k]]), float(discs[b[k]]),
                                         float(np.hypot(*(xy[a[k]] - xy[b[k]]))))
            over = np.flatnonzero(areas > _OVERLAP_AREA)
            if len(over):
                hit = int(over[0])
                i, j = ids[min(a[hit], b[hit])], ids[max(a[hit], b[hit])]
                raise InputError(
                    f"objects {i} and {j} have pose goals whose footprints overlap by {areas[hit] * 1e4:.2f} cm^2 "
                    "(only a tower goal stacks objects)"
                )


def _order(goals: GoalSpec) -> None:
    """Refuse goals whose ordered patterns make objects wait for each other in a cycle."""
    reg = registry()
    after: dict[int, list[tuple[int, str]]] = {}  # object -> (object it is placed after, why)
    for k, g in enumerate(goals.goals):
        pattern = reg.get(g.pattern)
        if pattern is None or not getattr(pattern, "ordered", False):
            continue
        if g.anchor is not None:
            for o in g.objects:
                after.setdefault(o, []).append((g.anchor, f"goal {k} puts it '{g.pattern}' of {g.anchor}"))
        else:
            for a, b in zip(g.objects, g.objects[1:]):
                after.setdefault(b, []).append((a, f"goal {k}, a {g.pattern}, puts it on {a}"))
    cycle = _cycle(after)
    if cycle is not None:
        steps = "; ".join(f"{o} after {d} ({why})" for o, d, why in cycle)
        raise InputError(f"the goals order objects in a cycle, so none of them can be placed first: {steps}")


def _cycle(after: dict[int, list[tuple[int, str]]]) -> list[tuple[int, int, str]] | None:
    """A cycle of the graph ``after`` as its edges ``(node, successor, label)``, or ``None``.

    One iterative depth-first search: linear in nodes plus edges.
    """
    state: dict[int, int] = {}  # 1: on the current path, 2: done
    for root in sorted(after):
        if root in state:
            continue
        state[root] = 1
        path: list[tuple[int, int, str]] = []  # edges taken from the root to the current node
        stack = [(root, iter(after.get(root, ())))]
        while stack:
            node, edges = stack[-1]
            nxt = next(edges, None)
            if nxt is None:
                state[node] = 2
                stack.pop()
                if path:
                    path.pop()
                continue
            succ, why = nxt
            if state.get(succ) == 1:
                start = next((i for i, e in enumerate(path) if e[0] == succ), len(path))
                return [*path[start:], (node, succ, why)]
            if succ not in state:
                state[succ] = 1
                path.append((node, succ, why))
                stack.append((succ, iter(after.get(succ, ()))))
    return None


def _min_length(pattern: str, rho: list[float]) -> float | None:
    """A proven lower bound (m) on the size L of a ``pattern`` goal whose
    objects have inradii ``rho``, or ``None`` for a pattern without one.

    * line: L (the centres' spread along the fitted line) is at least
      :func:`_line_span`;
    * circle: sorted by angle about the fitted centre, two neighbouring
      centres are at most ``2 pi / n`` apart in angle and within ``TOL`` of
      the radius R, so at most ``sqrt(4 TOL^2 + 4 (R + TOL)^2 sin^2(pi / n))``
      apart, and at least the two smallest inradii apart: R is at least
      ``sqrt(d^2 - 4 TOL^2) / (2 sin(pi / n)) - TOL``; and the rule's 0.05 m;
    * rectangle: the discs lie in the centres' rectangle grown by the
      largest inradius, so its longer side L has ``(L + 2 rho_max)^2`` at
      least their area; and the rule's 0.05 m.
    """
    n = len(rho)
    if pattern == "line" and n >= 2:
        return _line_span(rho)
    if pattern == "circle" and n >= 3:
        q = sorted(rho)
        d = q[0] + q[1]
        bound = math.sqrt(max(0.0, d * d - (2 * _TOL) ** 2)) / (2 * math.sin(math.pi / n)) - _TOL
        return max(_MIN_CIRCLE_RADIUS, bound)
    if pattern == "rectangle" and n >= 1:
        return max(_MIN_RECT_SIDE, math.sqrt(math.pi * sum(r * r for r in rho)) - 2 * max(rho))
    return None


def _sizes(goals: GoalSpec, rho: Callable[[int], float]) -> None:
    """Refuse a size in metres that the goal's objects cannot come down to."""
    reg = registry()
    for k, g in enumerate(goals.goals):
        if not isinstance(g.size, (int, float)) or isinstance(g.size, bool):
            continue
        least = _min_length(g.pattern, [rho(i) for i in g.objects])
        if least is not None and float(g.size) + _SIZE_TOL < least - 1e-12:
            word = getattr(reg.get(g.pattern), "size_word", None) or "size"
            raise InputError(
                f"goal {k} ({g.pattern} of {len(g.objects)} objects) asks for a {word} of {float(g.size):.3f} m; "
                f"its objects cannot come closer than a {word} of {least:.3f} m (tolerance {_SIZE_TOL} m)"
            )


def _opposite_relations(goals: GoalSpec) -> None:
    """Refuse one object in two directions of one anchor more than twice the rule's half-angle apart."""
    seen: dict[tuple[int, int], dict[str, int]] = {}  # (object, anchor) -> relation -> its first goal
    for k, g in enumerate(goals.goals):
        if g.anchor is None or g.pattern not in RELATIONS:
            continue
        for o in g.objects:
            for rel, k2 in seen.get((o, g.anchor), {}).items():
                a = math.atan2(RELATIONS[rel][1], RELATIONS[rel][0])
                b = math.atan2(RELATIONS[g.pattern][1], RELATIONS[g.pattern][0])
                apart = abs(math.remainder(a - b, 2 * math.pi))
                if apart > 2 * _RELATION_HALF_ANGLE + 1e-9:
                    raise InputError(
                        f"object {o} cannot be both '{rel}' (goal {k2}) and '{g.pattern}' (goal {k}) of {g.anchor}: "
                        f"the directions are {math.degrees(apart):.0f} deg apart, each allows "
                        f"{math.degrees(_RELATION_HALF_ANGLE):.0f} deg"
                    )
            seen.setdefault((o, g.anchor), {}).setdefault(g.pattern, k)


def _line_and_circle(goals: GoalSpec, rho: Callable[[int], float]) -> None:
    """Refuse a circle whose objects are all in one line goal, when they cannot be both.

    Every angular gap of a circle is below 180 degrees, so its centre lies in
    the convex hull of its objects' centres and, with them, within ``TOL``
    of the line; the centres within ``TOL`` of both the line and the circle
    (radius R at least 0.05 m) then form two clusters, one on either side of
    the centre, each within a box ``2 TOL`` wide and
    ``R + TOL - sqrt((R - TOL)^2 - 4 TOL^2)`` long (longest at the smallest
    R). One cluster holds m = ceil(n / 2) of the n objects; cutting its box
    into m - 1 equal parts along its length puts two of them in one part,
    closer than the part's diagonal. Refused when the two smallest inradii
    need more than that.
    """
    lines: dict[int, list[tuple[int, frozenset[int]]]] = {}  # object -> the line goals holding it
    for k, g in enumerate(goals.goals):
        if g.pattern == "line":
            for o in g.objects:
                lines.setdefault(o, []).append((k, frozenset(g.objects)))
    if not lines:
        return
    r0, t = _MIN_CIRCLE_RADIUS, _TOL
    long = r0 + t - math.sqrt((r0 - t) ** 2 - 4 * t * t)
    for k, g in enumerate(goals.goals):
        if g.pattern != "circle" or len(g.objects) < 3:
            continue
        mine = set(g.objects)
        on_line = next((kl for kl, objs in lines.get(g.objects[0], []) if mine <= objs), None)
        if on_line is None:
            continue
        n = len(g.objects)
        m = (n + 1) // 2
        reach = math.hypot(long / (m - 1), 2 * t)
        q = sorted(rho(i) for i in g.objects)
        if q[0] + q[1] > reach + 1e-12:
            raise InputError(
                f"the {n} objects of goal {k} (circle) cannot also stand in the line of goal {on_line}: "
                f"within {t} m of a line a circle's objects stand in two clusters, so {m} of them would share "
                f"a {long:.3f} x {2 * t:.3f} m box (two at most {reach:.3f} m apart), and they need "
                f"{q[0] + q[1]:.3f} m"
            )


def _width(pts: np.ndarray) -> float:
    """Smallest extent (m) of the points ``(k, 2)`` across any direction (0 when collinear)."""
    hull = shapely.MultiPoint(pts).convex_hull
    if not isinstance(hull, shapely.Polygon):
        return 0.0
    ring = np.asarray(hull.exterior.coords)[:-1]
    best = math.inf
    for a, b in zip(ring, np.roll(ring, -1, axis=0)):
        e = b - a
        n = float(np.hypot(*e))
        if n > 0:
            across = e[0] * (ring[:, 1] - a[1]) - e[1] * (ring[:, 0] - a[0])
            best = min(best, float(np.abs(across).max()) / n)
    return best


def _line_through_targets(goals: GoalSpec) -> None:
    """Refuse a line goal through pose targets that no strip ``4 TOL`` wide holds
    (each centre within ``TOL`` of its target and of the fitted line)."""
    target = {g.objects[0]: g.pose for g in goals.goals if g.pattern == "pose" and g.pose is not None}
    if len(target) < 3:
        return
    for k, g in enumerate(goals.goals):
        if g.pattern != "line":
            continue
        fixed = [o for o in g.objects if o in target]
        if len(fixed) < 3:
            continue
        w = _width(np.array([target[o][:2] for o in fixed], dtype=float))
        if w > 4 * _TOL + 1e-12:
            shown = ", ".join(str(o) for o in fixed[:8]) + (", ..." if len(fixed) > 8 else "")
            raise InputError(
                f"goal {k} (line) holds objects {shown} whose pose goals are {w:.3f} m wide across every "
                f"direction; within {_TOL} m of their targets and of one line they can be at most {4 * _TOL:.3f} m"
            )


def _must_move(sc: Scene, goals: GoalSpec) -> set[int]:
    """Indices of goal objects that cannot meet their goals where they stand:
    a pose goal more than ``TOL`` away, a tower level on the wrong support, an
    object of an on-table pattern resting on another object."""
    out: set[int] = set()
    start = sc.initial
    for g in goals.goals:
        idx = [sc.index[i] for i in g.objects]
        if g.pattern == "pose" and g.pose is not None:
            if math.hypot(*(start.poses[idx[0], :2] - np.asarray(g.pose[:2]))) > _TOL:
                out.add(idx[0])
        elif g.pattern == "tower":
            out.update(b for a, b in zip([TABLE, *idx], idx) if start.on[b] != a)
        else:
            fmt = pattern_format(g.pattern)
            if fmt is not None and fmt.on_table:
                out.update(i for i in idx if start.on[i] != TABLE)
    return out


def _unstacking(sc: Scene, goals: GoalSpec, have: float) -> None:
    """Refuse goals whose buried objects need more table than the workspace has
    to unstack them (this planner parks what it unstacks on the table).

    An object that must move is picked only once nothing rests on it. The
    planner moves an object that no goal names only to the table, so when
    that object is picked, every such object that was above it stands on
    the table, beside those that stood there from the start; their
    footprints are disjoint, so their areas add up.
    """
    named = {sc.index[i] for g in goals.goals for i in g.objects}
    start = sc.initial
    movers = [o for o in sorted(_must_move(sc, goals)) if not start.clear(o)]
    if not movers:
        return
    area: dict[int, float] = {}

    def footprint(i: int) -> float:
        if i not in area:
            area[i] = float(shapely.area(shapely.Polygon(sc.local[i])))
        return area[i]

    resting = sum(footprint(i) for i in range(sc.n) if i not in named and start.on[i] == TABLE)
    # Area and count of the unnamed objects above each object, top down in one pass.
    level = _levels(start.on)
    carried = [0.0] * sc.n
    count = [0] * sc.n
    for i in sorted(range(sc.n), key=lambda j: -level[j]):
        below = start.on[i]
        if below != TABLE:
            own = 0.0 if i in named else footprint(i)
            carried[below] += carried[i] + own
            count[below] += count[i] + (i not in named)
    for o in movers:
        need = resting + carried[o]
        if need > have:
            raise InputError(
                f"object {sc.ids[o]} must move but carries {count[o]} objects that no goal places: this planner "
                f"parks them on the table, where with the objects already there they need {need:.3f} m^2, more than "
                f"the workspace's {have:.3f} m^2"
            )


def _levels(on: tuple[int, ...] | list[int]) -> list[int]:
    """How many objects each object rests on (0 on the table), in linear time."""
    level = [-1] * len(on)
    for start in range(len(on)):
        path = []
        i = start
        while i != TABLE and level[i] < 0:
            path.append(i)
            i = on[i]
        base = -1 if i == TABLE else level[i]
        for j in reversed(path):
            base += 1
            level[j] = base
    return level
