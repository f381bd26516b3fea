"""Seeded random planning cases, solvable by construction.

Used by the planner benchmark (``benchmarks/planner.py``) and by the
property tests. A case is built backwards: first a final arrangement that
meets every goal (checked with the acceptance rules), then a start state
with the goal objects scattered, and either blockers stacked on goal objects
or clutter standing where goal objects must go.

Also the protocol of Labbé et al. (RA-L 2020): N discs of radius 3.75 cm
with random collision-free start and goal positions in a 0.5 m x 0.5 m
square, sampled as their public evaluator samples it
(:func:`labbe_protocol_case`), and this project's earlier, more spaced
variant of it (:func:`labbe_case`).
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from itertools import combinations, pairwise, product
from pathlib import Path

import numpy as np
import shapely

from . import geometry as geo
from .errors import InputError
from .formats import RELATIONS, GoalSpec, SceneSpec, parse_goals, parse_scene
from .scene import TABLE, Scene
from .validate import TOL, fit_circle, goal_satisfied, line_residuals

__all__ = ["Case", "random_case", "pack_clutter", "labbe_case", "labbe_protocol_case", "LABBE_VARIANTS", "lower_bound", "reference_count",
           "TrlbArrangement", "read_trlb_arrangement", "trlb_case", "trlb_pairs", "TRLB_UNIT"]

WORKSPACE = {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}
_COLORS = ("red", "green", "blue", "yellow", "purple", "white", "orange", "pink")


@dataclass(frozen=True)
class Case:
    """One planning case: scene, goals, kind, action lower bound and reference count."""

    scene: SceneSpec
    goals: GoalSpec
    kind: str
    lower_bound: int
    reference: int = 0


def _shape(rng: np.random.Generator) -> tuple[str, dict]:
    k = rng.integers(3)
    if k == 0:
        s = rng.uniform(0.03, 0.055)
        return "block", {
            "type": "box",
            "size": [float(s), float(rng.uniform(0.03, 0.055)), float(rng.uniform(0.03, 0.06))],
        }
    if k == 1:
        return "can", {
            "type": "cylinder",
            "radius": float(rng.uniform(0.016, 0.03)),
            "height": float(rng.uniform(0.04, 0.1)),
        }
    r = rng.uniform(0.02, 0.032)
    m = int(rng.integers(3, 7))
    a = np.arange(m) * 2 * math.pi / m
    pts = [[float(r * math.cos(t)), float(r * math.sin(t))] for t in a]
    return "tile", {"type": "polygon", "points": pts, "height": float(rng.uniform(0.01, 0.04))}


class _Placer:
    """Rejection sampler of non-overlapping footprints (exact polygons)."""

    def __init__(self, scene: Scene, gap: float = 0.004):
        self.scene, self.gap = scene, gap
        self.polys: dict[int, shapely.Polygon] = {}

    def fits(self, i: int, pose: np.ndarray) -> bool:
        v = self.scene.footprint(i, pose)
        xmin, xmax, ymin, ymax = self.scene.bounds
        if (
            v[:, 0].min() < xmin + 0.003
            or v[:, 0].max() > xmax - 0.003
            or v[:, 1].min() < ymin + 0.003
            or v[:, 1].max() > ymax - 0.003
        ):
            return False
        p = shapely.Polygon(v)
        return all(p.distance(q) > self.gap for q in self.polys.values())

    def put(self, i: int, pose: np.ndarray) -> None:
        self.polys[i] = shapely.Polygon(self.scene.footprint(i, pose))

    def random(self, i: int, rng: np.random.Generator, tries: int = 400) -> np.ndarray | None:
        xmin, xmax, ymin, ymax = self.scene.bounds
        for _ in range(tries):
            p = np.array([rng.uniform(xmin, xmax), rng.uniform(ymin, ymax), rng.uniform(-math.pi, math.pi)])
            if self.fits(i, p):
                self.put(i, p)
                return p
        return None


def _pattern_poses(
    kind: str, objs: list[int], scene: Scene, rng: np.random.Generator, anchor_pose=None
) -> list[np.ndarray]:
    rmax = float(scene.radii[objs].max())
    n = len(objs)
    c = np.array([rng.uniform(-0.25, 0.25), rng.uniform(-0.17, 0.17)])
    if kind == "line":
        phi = rng.uniform(-math.pi, math.pi)
        u = np.array([math.cos(phi), math.sin(phi)])
        step = 2 * rmax + 0.015
        return [np.array([*(c + (k - (n - 1) / 2) * step * u), phi]) for k in range(n)]
    if kind == "circle":
        r = max(0.06, (2 * rmax + 0.02) / (2 * math.sin(math.pi / n)))
        a0 = rng.uniform(-math.pi, math.pi)
        return [
            np.array(
                [
                    c[0] + r * math.cos(a0 + 2 * math.pi * k / n),
                    c[1] + r * math.sin(a0 + 2 * math.pi * k / n),
                    a0 + 2 * math.pi * k / n + math.pi / 2,
                ]
            )
            for k in range(n)
        ]
    if kind == "rectangle":
        side = max(0.07, 2 * rmax + 0.02)
        w = side * (1 + (n > 4))
        h = side
        mids = [(0.0, -h / 2), (0.0, h / 2)][: n - 4]
        pts = [(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2), *mids]
        return [np.array([c[0] + x, c[1] + y, 0.0]) for x, y in pts]
    if kind == "tower":
        return [np.array([c[0], c[1], 0.0]) for _ in objs]
    raise ValueError(kind)


def random_case(seed: int, *, n_objects: int | None = None, kind: str | None = None, dense: bool = False) -> Case:
    """A random case with 6-16 objects and 1-2 goals; ``kind`` is ``"blockers"`` or ``"clutter"``.

    ``dense=True`` gives the dense variant of the same case: the case drawn
    for ``seed`` without it, plus 4-10 extra clutter objects packed edge to
    edge around the goal region (see :func:`_pack_clutter`); its ``kind``
    gets a ``"dense-"`` prefix.
    """
    rng = np.random.default_rng(seed)
    for _ in range(200):
        case = _try_case(rng, n_objects, kind, np.random.default_rng([seed, 1]) if dense else None)
        if case is not None:
            return case
    raise RuntimeError(f"could not build a case for seed {seed}")  # pragma: no cover


#: Step and bisection depth of the search for contact along a ray (m, count).
_PACK_STEP, _PACK_BISECT = 0.003, 10


def _pack_clutter(
    scene: Scene, objects: list[dict], goal_feet: list, other_feet: list, rng: np.random.Generator
) -> list[dict]:
    """Extra clutter objects (4-10, shapes as in the base cases) packed in
    contact around the goal region (see :func:`pack_clutter`)."""
    n0 = len(objects)
    specs = []
    for e in range(int(rng.integers(4, 11))):
        name, shape = _shape(rng)
        specs.append({"id": n0 + e + 1, "name": name, "color": _COLORS[(n0 + e) % len(_COLORS)], "shape": shape})
    return pack_clutter(scene.bounds, specs, goal_feet, other_feet, rng)


def pack_clutter(
    bounds: tuple[float, float, float, float],
    specs: list[dict],
    goal_feet: list,
    other_feet: list,
    rng: np.random.Generator,
) -> list[dict]:
    """Object ``specs`` (dicts with id, name, color, shape) packed edge to
    edge around the goal region; returns those placed, with ``pose`` and
    ``on`` set, in order.

    Nothing may overlap ``goal_feet`` (footprint polygons of the goal
    objects where the goals put them) nor ``other_feet`` (any other polygons
    to keep clear, such as the start footprints). Each object starts at the
    centre of a random goal footprint, at a random yaw, and slides outward
    along a random ray to the first pose where it overlaps nothing; a
    bisection brings it to within about 3 um of that contact. A pose stopped
    by the workspace edge (``bounds = (xmin, xmax, ymin, ymax)``, 3 mm
    margin) rather than by a neighbour is redrawn, up to 30 times; an object
    that finds none is left out. The goal footprints stay free, so the goal
    arrangement remains legal.
    """
    xmin, xmax, ymin, ymax = bounds
    goal_centres = [np.array(shapely.get_coordinates(shapely.centroid(f))[0]) for f in goal_feet]
    placed = list(goal_feet) + list(other_feet)
    out: list[dict] = []
    if not goal_centres:
        return out
    for spec in specs:
        full = {**spec, "pose": [0.0, 0.0, 0.0], "on": None}
        local = Scene.from_spec(
            parse_scene(
                {
                    "workspace": {"x": [xmin, xmax], "y": [ymin, ymax]},
                    "objects": [{**full, "pose": [(xmin + xmax) / 2, (ymin + ymax) / 2, 0.0]}],
                }
            )
        ).local[0]

        def poly_at(p, local=local):
            return shapely.polygons(geo.transform(local, p))

        def fits(p, local=local) -> bool:
            v = geo.transform(local, p)
            if (
                v[:, 0].min() < xmin + 0.003
                or v[:, 0].max() > xmax - 0.003
                or v[:, 1].min() < ymin + 0.003
                or v[:, 1].max() > ymax - 0.003
            ):
                return False
            arr = np.empty(len(placed), dtype=object)
            arr[:] = placed
            return not bool(shapely.intersects(shapely.polygons(v), arr).any())

        for _ in range(30):
            c = goal_centres[int(rng.integers(len(goal_centres)))]
            phi, yaw = rng.uniform(-math.pi, math.pi, 2)
            u = np.array([math.cos(phi), math.sin(phi)])
            t_hit = None
            for t in np.arange(_PACK_STEP, 0.35, _PACK_STEP):
                if fits(np.array([*(c + t * u), yaw])):
                    t_hit = float(t)
                    break
            if t_hit is None:
                continue
            lo, hi = t_hit - _PACK_STEP, t_hit
            for _ in range(_PACK_BISECT):
                mid = (lo + hi) / 2
                if fits(np.array([*(c + mid * u), yaw])):
                    hi = mid
                else:
                    lo = mid
            pose = np.array([*(c + hi * u), yaw])
            arr = np.empty(len(placed), dtype=object)
            arr[:] = placed
            if shapely.distance(poly_at(pose), arr).min() > 1e-4:
                continue  # stopped by the workspace edge, not by a neighbour: not packed
            placed.append(poly_at(pose))
            out.append({**full, "pose": [float(v) for v in pose]})
            break
    return out


def _try_case(
    rng: np.random.Generator, n_objects: int | None, kind: str | None, dense_rng: np.random.Generator | None = None
) -> Case | None:
    n = int(n_objects or rng.integers(6, 17))
    kind = kind or ("blockers" if rng.random() < 0.5 else "clutter")
    objects = []
    for i in range(n):
        name, shape = _shape(rng)
        objects.append(
            {
                "id": i + 1,
                "name": name,
                "color": _COLORS[i % len(_COLORS)],
                "shape": shape,
                "pose": [0.0, 0.0, 0.0],
                "on": None,
            }
        )
    scene = Scene.from_spec(parse_scene({"workspace": WORKSPACE, "objects": objects}), overlap_ok=True)
    order = list(rng.permutation(n))
    n_goals = int(rng.integers(1, 3))
    final = _Placer(scene)
    goals: list[dict] = []
    final_pose: dict[int, np.ndarray] = {}
    final_on: dict[int, int] = {}
    used: list[int] = []
    for _ in range(n_goals):
        pat = str(rng.choice(["line", "circle", "rectangle", "tower", "relation"]))
        if pat == "relation":
            anchor_pool = used or order[:1]
            anchor = int(anchor_pool[int(rng.integers(len(anchor_pool)))])
            if anchor not in final_pose:
                p = final.random(anchor, rng)
                if p is None:
                    return None
                final_pose[anchor] = p
                used.append(anchor)
                order.remove(anchor)
            if not order:
                return None
            obj = order.pop()
            rel = str(rng.choice(list(RELATIONS)))
            d = np.asarray(RELATIONS[rel])
            a = math.atan2(d[1], d[0]) + rng.uniform(-0.5, 0.5)
            rho = rng.uniform(scene.radii[anchor] + scene.radii[obj] + 0.01, 0.27)
            p = np.array([*(final_pose[anchor][:2] + rho * np.array([math.cos(a), math.sin(a)])), rng.uniform(-3, 3)])
            if not final.fits(obj, p):
                return None
            final.put(obj, p)
            final_pose[obj] = p
            used.append(obj)
            goals.append({"pattern": rel, "objects": [scene.ids[obj]], "anchor": scene.ids[anchor]})
            continue
        size = {"line": (3, 6), "circle": (3, 7), "rectangle": (4, 7), "tower": (2, 4)}[pat]
        m = int(rng.integers(*size))
        if len(order) < m + 2:
            return None
        objs = [order.pop() for _ in range(m)]
        poses = _pattern_poses(pat, objs, scene, rng)
        if pat == "tower":
            if not final.fits(objs[0], poses[0]):
                return None
            final.put(objs[0], poses[0])
            for k, o in enumerate(objs):
                final_pose[o] = poses[k]
                if k:
                    final_on[o] = objs[k - 1]
        else:
            for o, p in zip(objs, poses):
                if not final.fits(o, p):
                    return None
                final.put(o, p)
                final_pose[o] = p
        used.extend(objs)
        goals.append({"pattern": pat, "objects": [scene.ids[o] for o in objs]})
    others = [o for o in range(n) if o not in final_pose]
    for o in others:
        p = final.random(o, rng)
        if p is None:
            return None
        final_pose[o] = p
    gspec = parse_goals({"goals": goals})
    final_poses = np.array([final_pose[o] for o in range(n)])
    on = tuple(final_on.get(o, TABLE) for o in range(n))
    for g in gspec.goals:
        if goal_satisfied(g, scene, final_poses, on) is not None:
            return None
    # Start state: goal targets scattered, non-goal objects as blockers or clutter.
    targets = sorted({scene.index[i] for g in gspec.goals for i in g.objects})
    start = _Placer(scene)
    spose: dict[int, np.ndarray] = {}
    son: dict[int, int] = {}
    blockers = 0
    free_others = [o for o in others if o not in used]
    rng.shuffle(free_others)
    if kind == "clutter":
        # Clutter stands on the final spots of goal objects.
        for o, t in zip(free_others[: max(1, len(free_others) // 2)], targets):
            p = np.array([*final_pose[t][:2], rng.uniform(-3, 3)])
            if start.fits(o, p):
                start.put(o, p)
                spose[o] = p
    for o in range(n):
        if o in spose:
            continue
        if o in targets or o in used or kind == "clutter" or o not in free_others[:2]:
            p = start.random(o, rng)
            if p is None:
                return None
            spose[o] = p
    if kind == "blockers":
        for o in free_others[:2]:
            bases = [t for t in targets if t not in son.values()]
            base = int(rng.choice(bases)) if bases else -1
            if base < 0 or scene.radii[o] > 1.3 * scene.radii[base]:
                p = start.random(o, rng)
                if p is None:
                    return None
                spose[o] = p
                continue
            spose[o] = np.array([*spose[base][:2], spose[base][2]])
            son[o] = base
            blockers += 1
    if kind == "blockers" and not blockers:
        return None  # a blockers case must really bury a goal object
    objs_out = []
    for k, ob in enumerate(objects):
        objs_out.append({**ob, "pose": [float(v) for v in spose[k]], "on": None if k not in son else scene.ids[son[k]]})
    if dense_rng is not None:
        goal_feet = [shapely.polygons(scene.footprint(t, final_pose[t])) for t in targets if t not in final_on]
        other_feet = [shapely.polygons(scene.footprint(o, spose[o])) for o in range(n) if o not in son]
        objs_out += _pack_clutter(scene, objs_out, goal_feet, other_feet, dense_rng)
        kind = f"dense-{kind}"
    sspec = parse_scene({"workspace": WORKSPACE, "objects": objs_out})
    return Case(sspec, gspec, kind, lower_bound(sspec, gspec), reference_count(sspec, gspec))


def _fits_some_shape(pattern: str, xy: np.ndarray, max_radius: float) -> bool:
    """Whether centres ``xy`` could all stay for a line, circle or rectangle goal.

    Deliberately generous (twice the acceptance tolerance, no radius or gap
    rule) so that the bound below never exceeds the true optimum.
    """
    if len(xy) <= 2:
        return True
    if pattern == "line":
        return bool(line_residuals(xy).max() <= 2 * TOL)
    if pattern == "circle":
        # The rest of the circle's objects must spread over more than half of
        # it, so the circle cannot be much larger than the table.
        c, r = fit_circle(xy)
        return bool(
            np.isfinite(r) and 0.05 - TOL <= r <= max_radius and np.abs(np.hypot(*(xy - c).T) - r).max() <= 2 * TOL
        )
    if pattern == "rectangle":
        # Kept centres lie inside the final rectangle, so one deeper than the
        # tolerance inside their own convex hull is off its perimeter.
        hull = shapely.convex_hull(shapely.MultiPoint(xy))
        edge = hull.exterior if isinstance(hull, shapely.Polygon) else hull
        return bool(shapely.distance(edge, shapely.points(xy)).max() <= 2 * TOL)
    return False


def _keep_options(g, sc: Scene, st) -> list[frozenset[int]]:
    """Sets of a goal's objects that some plan might leave where they are."""
    idx = [sc.index[i] for i in g.objects]
    on_table = [i for i in idx if st.on[i] == TABLE]
    xmin, xmax, ymin, ymax = sc.bounds
    diag = float(np.hypot(xmax - xmin, ymax - ymin))
    if g.pattern in ("line", "circle", "rectangle"):
        best: list[frozenset[int]] = [frozenset(c) for c in combinations(on_table, min(2, len(on_table)))]
        for k in range(3, len(on_table) + 1):
            more = [
                frozenset(c)
                for c in combinations(on_table, k)
                if _fits_some_shape(g.pattern, st.poses[list(c), :2], diag / 2)
            ]
            if not more:
                break
            best = more
        return best or [frozenset()]
    if g.pattern == "tower":
        keep: list[int] = []
        if st.on[idx[0]] == TABLE:
            keep.append(idx[0])
            for a, b in pairwise(idx):
                if st.on[b] != a:
                    break
                keep.append(b)
        return [frozenset(keep)]
    if g.pattern in RELATIONS:
        ok = frozenset(
            i for i in idx if goal_satisfied(g.model_copy(update={"objects": [sc.ids[i]]}), sc, st.poses, st.on) is None
        )
        return [ok]
    return [frozenset()]


def reference_count(scene: SceneSpec, goals: GoalSpec) -> int:
    """The plan-length reference of the planner benchmark's specification.

    Goal objects not already satisfied plus the objects that must be
    unstacked to reach them: every object of an open line, circle or
    rectangle goal; the objects of a relation that do not yet stand in it;
    the objects of a tower above its correctly stacked base part; and every
    object resting, directly or not, on one of those. Unlike
    :func:`lower_bound` this is not a bound: a plan may leave some objects of
    an open goal where they stand.
    """
    sc = Scene.from_spec(scene)
    st = sc.initial
    moving: set[int] = set()
    for g in goals.goals:
        if goal_satisfied(g, sc, st.poses, st.on) is None:
            continue
        idx = [sc.index[i] for i in g.objects]
        if g.pattern in RELATIONS or g.pattern == "tower":
            keep = _keep_options(g, sc, st)[0]
            moving.update(i for i in idx if i not in keep)
        else:
            moving.update(idx)
    above = {k for i in moving for k in st.above(i)} - moving
    return len(moving) + len(above)


def lower_bound(scene: SceneSpec, goals: GoalSpec) -> int:
    """Fewest actions any plan needs, counted generously so it is a true bound.

    A goal that already holds costs nothing. Otherwise each goal object must
    move unless a plan could leave it where it stands: for a line or circle
    or rectangle the largest set of its objects that could already lie on
    one (at least two, since two points lie on some line and some circle;
    for a rectangle, any set whose centres all lie on their convex hull's
    boundary), for a tower the part already stacked correctly from the base. Every
    object resting, directly or not, on an object that must move adds one
    action. Keep sets are chosen jointly over the goals to minimise the sum.
    A relation's objects standing on the table may all stay if its anchor moves:
    such a relation costs nothing when the anchor must move anyway, and at
    least one action otherwise (the anchor or one of its objects). All such
    relations together count at most one action, since one anchor move may
    serve several of them.
    """
    sc = Scene.from_spec(scene)
    st = sc.initial
    open_goals = [g for g in goals.goals if goal_satisfied(g, sc, st.poses, st.on) is not None]
    options = [_keep_options(g, sc, st) for g in open_goals]
    best = None
    for choice in product(*options):
        must: set[int] = set()
        loose: list[tuple[int, list[int]]] = []
        for g, keep in zip(open_goals, choice):
            idx = [sc.index[i] for i in g.objects]
            moving = [i for i in idx if i not in keep]
            if g.pattern in RELATIONS and moving:
                # Objects off the table must move; the rest might stay put.
                must.update(i for i in moving if st.on[i] != TABLE)
                standing = [i for i in moving if st.on[i] == TABLE]
                if standing:
                    loose.append((sc.index[g.anchor], standing))  # type: ignore[index]
                continue
            must.update(moving)
        above = {k for i in must for k in st.above(i)} - must
        # A loose relation is served for free when its anchor or one of its
        # objects moves anyway; otherwise something must still move for it.
        extra = 1 if any(a not in must and not (set(m) & must) for a, m in loose) else 0
        cost = len(must) + len(above) + extra
        best = cost if best is None else min(best, cost)
    return best or 0


#: The Labbé et al. protocol's disc radius (m) and the square its evaluator
#: samples disc centres in, ``((xmin, ymin), (xmax, ymax))`` (m).
LABBE_RADIUS = 0.0375
LABBE_SQUARE = ((0.25, -0.25), (0.75, 0.25))
#: Darts one random sequential addition may throw before it starts afresh,
#: and how many fresh starts are allowed (the evaluator's 2 s timeout and 50
#: retries, as a count so that a seed gives the same case on any machine).
LABBE_DARTS, LABBE_RESTARTS = 200_000, 50


def _rsa(n: int, rng: np.random.Generator, lo: np.ndarray, hi: np.ndarray, dist: float) -> np.ndarray:
    """Random sequential addition: ``n`` centres ``(n, 2)``, uniform in the box
    ``lo``-``hi``, each kept when at least ``dist`` from every centre kept before.

    Darts are drawn in batches and the first acceptable one of a batch is
    kept (the rest are thrown away unused), which is the same process as
    drawing them one at a time.
    """
    batch = 1024
    for _ in range(LABBE_RESTARTS + 1):
        pts = np.empty((0, 2))
        darts = 0
        while len(pts) < n and darts < LABBE_DARTS:
            d = rng.uniform(lo, hi, (batch, 2))
            if len(pts):
                ok = ((d[:, None, :] - pts[None, :, :]) ** 2).sum(axis=-1).min(axis=1) >= dist * dist
                k = np.flatnonzero(ok)
            else:
                k = np.zeros(1, dtype=int)
            if not len(k):
                darts += batch
                continue
            darts += int(k[0]) + 1
            pts = np.vstack([pts, d[k[0]]])
        if len(pts) == n:
            return pts
    raise RuntimeError(f"random sequential addition could not place {n} discs")  # pragma: no cover


def _disc_case(start: np.ndarray, goal: np.ndarray, r: float, ws: dict, kind: str, height: float = 0.02) -> Case:
    n = len(start)
    objs = [
        {"id": i + 1, "name": "disc", "color": _COLORS[i % len(_COLORS)], "shape": {"type": "cylinder", "radius": r, "height": height},
         "pose": [float(start[i, 0]), float(start[i, 1]), 0.0], "on": None}
        for i in range(n)
    ]
    goals = [
        {"pattern": "pose", "objects": [i + 1], "pose": [float(goal[i, 0]), float(goal[i, 1]), 0.0]} for i in range(n)
    ]
    sspec = parse_scene({"workspace": ws, "objects": objs})
    gspec = parse_goals({"goals": goals})
    return Case(sspec, gspec, kind, lower_bound(sspec, gspec), reference_count(sspec, gspec))


def labbe_protocol_case(n: int, seed: int) -> Case:
    """The Labbé et al. (RA-L 2020) protocol as its public evaluator samples it.

    Task: N discs of radius 3.75 cm, a ``pose`` goal for each (yaw 0).
    Randomisations: start and goal are independent random sequential
    additions of N centres, uniform in the evaluator's 0.5 m x 0.5 m square
    ``LABBE_SQUARE``, each accepted when its distance to every centre already
    placed is at least 2R (discs may touch); an addition that jams starts
    afresh (:data:`LABBE_DARTS`, :data:`LABBE_RESTARTS`). Works up to N = 37.
    Success: every disc at its goal with no overlap on the way.

    Deviations, and why: the evaluator bounds disc *centres* by the square,
    while an lgmcts workspace bounds *footprints*; the workspace here is the
    square grown by the footprint's circumradius (R / cos(pi / 24), the
    24-gon that stands for a disc), so a centre is legal exactly where the
    evaluator allows it. The evaluator seeds numpy's global generator and
    caps an addition by time; here a ``np.random.Generator`` seeded with
    ``seed`` and a dart count, so a seed gives the same case anywhere (the
    instances differ from the evaluator's, the distribution does not).
    The evaluator counts a disc placed within 1 mm of its target; the
    validator's pose rule allows 15 mm, and the planner places discs on
    their targets exactly.
    """
    rng = np.random.default_rng(seed)
    r = LABBE_RADIUS
    lo, hi = np.asarray(LABBE_SQUARE[0], dtype=float), np.asarray(LABBE_SQUARE[1], dtype=float)
    grow = r / math.cos(math.pi / geo.CIRCLE_SEGMENTS)
    ws = {"x": [float(lo[0] - grow), float(hi[0] + grow)], "y": [float(lo[1] - grow), float(hi[1] + grow)]}
    start = _rsa(n, rng, lo, hi, 2 * r)
    goal = _rsa(n, rng, lo, hi, 2 * r)
    return _disc_case(start, goal, r, ws, "labbe")


#: Generators of Labbé-style cases by name: ``protocol`` as the authors
#: sample it, ``spaced`` this project's earlier variant (see :func:`labbe_case`).
LABBE_VARIANTS = ("protocol", "spaced")


def labbe_case(n: int, seed: int, *, variant: str = "spaced") -> Case:
    """N discs (r = 3.75 cm) in 0.5 m x 0.5 m with random start and goal poses.

    ``variant="protocol"`` is :func:`labbe_protocol_case`. The default,
    ``"spaced"``, is an easier variant kept for comparison with earlier
    figures (and the golden plans): every pair of discs at least
    2R x 1.0087 + 4 mm apart (about 4.7 mm of clearance), centres at least
    R + 2 mm from the edge of a 0.5 m square workspace.

    Start and goal are each a random sequential addition of N discs: uniform
    darts for N <= 24; for N = 25-26, darts drawn among the grid points that
    still have room, retried until N fit. Random addition jams near 25-28
    discs here, so N > 26 uses a jittered hexagonal lattice of 37 sites
    (random sites, an easier problem: start and goal share the sites).
    """
    if variant == "protocol":
        return labbe_protocol_case(n, seed)
    if variant != "spaced":
        raise ValueError(f"unknown Labbé variant '{variant}' (known: {', '.join(LABBE_VARIANTS)})")
    rng = np.random.default_rng(seed)
    r = 0.0375
    ws = {"x": [0.0, 0.5], "y": [0.0, 0.5]}

    lo, hi, gap = r + 0.002, 0.5 - r - 0.002, 2 * r * 1.0087 + 0.004

    def config() -> np.ndarray:
        # Random sequential addition; near saturation, darts go only where
        # there is still room; beyond what that reaches, a jittered hex lattice.
        if n <= 24:
            for _ in range(100):
                pts: list[np.ndarray] = []
                for _ in range(3000):
                    p = rng.uniform(lo, hi, 2)
                    if all(np.hypot(*(p - q)) > gap for q in pts):
                        pts.append(p)
                        if len(pts) == n:
                            return np.array(pts)
        if n <= 26:
            g = np.arange(lo, hi, 0.002)
            grid_pts = np.stack(np.meshgrid(g, g), axis=-1).reshape(-1, 2)
            for _ in range(500):
                free = np.ones(len(grid_pts), dtype=bool)
                pts = []
                while free.any() and len(pts) < n:
                    p = np.clip(grid_pts[rng.choice(np.flatnonzero(free))] + rng.uniform(-0.001, 0.001, 2), lo, hi)
                    pts.append(p)
                    free &= np.hypot(*(grid_pts - p).T) > gap + 0.003
                if len(pts) == n:
                    return np.array(pts)
        cols, rows = 6, 7
        grid: list[tuple[float, float]] = []
        for j in range(rows):
            for i in range(cols):
                x = r + 0.003 + i * (2 * r + 0.006) + (j % 2) * (r + 0.003)
                y = r + 0.003 + j * 0.0685
                if x <= 0.5 - r - 0.003 and y <= 0.5 - r - 0.003:
                    grid.append((x, y))
        cells = np.array(grid)
        pick = rng.choice(len(cells), n, replace=False)
        return cells[pick] + rng.uniform(-0.0005, 0.0005, (n, 2))

    start, goal = config(), config()
    return _disc_case(start, goal, r, ws, "labbe")


#: Metres per length unit of TRLB's instance files (their workspace is 1000 units square; here 1 m).
TRLB_UNIT = 1e-3
#: Height (m) given to TRLB's discs, which are flat shapes in their files.
TRLB_DISC_HEIGHT = 0.02


@dataclass(frozen=True)
class TrlbArrangement:
    """One TRLB arrangement file: disc centres in a ``width`` x ``height`` box (TRLB units)."""

    path: str
    density: float
    radius: float
    width: float
    height: float
    points: np.ndarray


def read_trlb_arrangement(path: str | Path) -> TrlbArrangement:
    """Read one of TRLB's ``disk_experiments/arrangements/D=<d>/n=<n>/<k>_<n>_<d>.json`` files.

    Raises :class:`~lgmcts.errors.InputError` (one line) for a file that is
    not such an arrangement.
    """
    p = Path(path)
    try:
        data = json.loads(p.read_text())
        pts = np.asarray(data["point_list"], dtype=float).reshape(-1, 2)
        arr = TrlbArrangement(str(p), float(data["Workspace_Density"]), float(data["Object_Radius"]),
                              float(data["Workspace_Width"]), float(data["Workspace_Height"]), pts)
    except (OSError, ValueError, KeyError, TypeError) as e:
        raise InputError(f"{p}: not a TRLB arrangement file ({type(e).__name__}: {e})") from None
    if data.get("Object_Shape", "disc") != "disc":
        raise InputError(f"{p}: only disc arrangements are supported, not '{data.get('Object_Shape')}'")
    if int(data.get("number_of_objects", len(pts))) != len(pts) or not len(pts):
        raise InputError(f"{p}: number_of_objects does not match point_list")
    if not (arr.radius > 0 and arr.width > 0 and arr.height > 0 and np.isfinite(pts).all()):
        raise InputError(f"{p}: radius, width and height must be positive and the points finite")
    return arr


def trlb_case(start: str | Path | TrlbArrangement, goal: str | Path | TrlbArrangement) -> Case:
    """A case from two TRLB arrangement files, paired as TRLB's ``generate_instance`` pairs them.

    Disc ``k`` starts at the ``k``-th point of ``start`` and must end at the
    ``k``-th point of ``goal`` (a ``pose`` goal, yaw 0). Lengths are scaled
    by :data:`TRLB_UNIT` (1 m per 1000 units), the discs become cylinders of
    TRLB's radius and height :data:`TRLB_DISC_HEIGHT`, and the workspace is
    TRLB's box ``[0, width] x [0, height]``. The 24-gon that stands for a disc
    reaches exactly its radius along both axes, so a disc is inside the
    workspace exactly where TRLB has it inside.
    """
    a = start if isinstance(start, TrlbArrangement) else read_trlb_arrangement(start)
    b = goal if isinstance(goal, TrlbArrangement) else read_trlb_arrangement(goal)
    if len(a.points) != len(b.points) or a.radius != b.radius or (a.width, a.height) != (b.width, b.height):
        raise InputError(f"{a.path} and {b.path} are not a start/goal pair (different counts, radii or workspaces)")
    ws = {"x": [0.0, a.width * TRLB_UNIT], "y": [0.0, a.height * TRLB_UNIT]}
    return _disc_case(a.points * TRLB_UNIT, b.points * TRLB_UNIT, a.radius * TRLB_UNIT, ws, "trlb",
                      height=TRLB_DISC_HEIGHT)


def trlb_pairs(root: str | Path, pairs: int = 5) -> list[tuple[float, int, tuple[Path, Path]]]:
    """The (density, count, (start file, goal file)) pairs under TRLB's ``arrangements`` folder ``root``.

    In each ``D=<d>/n=<n>`` folder, files ``2k_<n>_<d>.json`` (start) and
    ``2k+1_<n>_<d>.json`` (goal) for ``k < pairs`` form a pair, where both
    exist: two distinct files of one cell, as TRLB's ``generate_instance``
    takes them (it is given the two file numbers). Sorted by density, count
    and ``k``.
    """
    base = Path(root)
    if not base.is_dir():
        raise InputError(f"{base}: no such folder (TRLB's disk_experiments/arrangements)")
    out: list[tuple[float, int, tuple[Path, Path]]] = []
    for cell in base.glob("D=*/n=*"):
        try:
            d, n = float(cell.parent.name[2:]), int(cell.name[2:])
        except ValueError:
            continue
        tag = cell.parent.name[2:]
        for k in range(pairs):
            s, g = cell / f"{2 * k}_{n}_{tag}.json", cell / f"{2 * k + 1}_{n}_{tag}.json"
            if s.is_file() and g.is_file():
                out.append((d, n, (s, g)))
    if not out:
        raise InputError(f"{base}: no TRLB arrangement pairs found (expected D=<d>/n=<n>/<k>_<n>_<d>.json)")
    return sorted(out, key=lambda t: (t[0], t[1], str(t[2][0])))
