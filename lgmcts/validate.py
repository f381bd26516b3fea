"""The acceptance rules, implemented once and independently of the planner.

:func:`check` replays a plan on a scene with exact polygon geometry (shapely)
and judges the final state against every goal. It shares no code with the
samplers or the search: only the footprint definitions of :mod:`lgmcts.scene`.

Rules (tolerance ``TOL = 0.015`` m unless said otherwise):

* every pick is of a clear object (nothing rests on it);
* a target pose is finite, within ``lgmcts.limits.MAX_COORD`` m and
  ``MAX_ANGLE`` rad (checked before any geometry);
* a table placement keeps the footprint inside the workspace (centre inside,
  no vertex more than ``EDGE_TOL = 1e-3`` m outside, at most ``1e-6`` m²
  outside) and overlaps no other table-level footprint by more than
  ``1e-6`` m² (between two cylinders, the overlap of their true circles, so
  cylinders may touch);
* a placement ``on`` another object needs that object clear and the centre
  over its footprint;
* line: every centre within TOL of the total-least-squares line;
* circle: n ≥ 3, fitted radius ≥ 0.05 m, every centre within TOL of the circle,
  largest angular gap between consecutive objects < 180°;
* rectangle: n ≥ 4, every centre within TOL of the perimeter of the
  minimum-area rectangle around the centres, both sides ≥ 0.05 m, every side
  holding at least one centre;
* tower: objects[0] on the table, objects[i+1] on objects[i], xy within 0.02 m;
* spatial relations: the anchor-to-object vector within 45° of the relation's
  direction and 0 < length ≤ 0.30 m;
* pose: within TOL and 0.1 rad;
* objects of line, circle, rectangle and spatial goals end on the table;
* a goal's optional ``region``, ``size`` and ``facing`` hold as
  :mod:`lgmcts.params` defines them (centres within 0.015 m of the region,
  the characteristic length within 0.015 m of its band, every yaw and a
  line's or rectangle's direction within pi/8 of a named facing or 0.1 rad
  of an angle).

A pattern added outside this module brings its own rule
(:func:`register_rule`), written apart from its sampler.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field

import numpy as np
import shapely

from . import geometry as geo
from . import limits
from .errors import InputError
from .formats import (
    PATTERN_NAMES,
    RELATIONS,
    Goal,
    GoalSpec,
    PlanSpec,
    SceneSpec,
    load_goals,
    load_plan,
    load_scene,
    pattern_format,
)
from .params import REGION_TOL, SIZE_TOL
from .params import resolve as resolve_params
from .scene import TABLE, Scene

__all__ = ["Verdict", "check", "goal_satisfied", "register_rule", "TOL", "OVERLAP_AREA", "TOWER_TOL", "MAX_RELATION_DIST"]

TOL = 0.015
OVERLAP_AREA = 1e-6
TOWER_TOL = 0.02
MAX_RELATION_DIST = 0.30
RELATION_HALF_ANGLE = math.pi / 4
POSE_ANGLE_TOL = 0.1
MIN_CIRCLE_RADIUS = 0.05
MIN_RECT_SIDE = 0.05
#: A footprint vertex this far (m) outside the workspace is a violation
#: whatever the area outside.
EDGE_TOL = 1e-3


def _pose_out_of_bounds(pose: np.ndarray) -> str | None:
    """Why a target pose is unacceptable before any geometry, or ``None``.

    Non-finite values, coordinates beyond :data:`lgmcts.limits.MAX_COORD` and
    yaws beyond :data:`lgmcts.limits.MAX_ANGLE` are refused here (the plan
    format refuses them too; this holds for plans built in code), so that the
    polygon tests only ever run at magnitudes where a footprint keeps its
    shape.
    """
    if pose.shape != (3,) or not np.isfinite(pose).all():
        return "has a non-finite target pose"
    if abs(pose[0]) > limits.MAX_COORD or abs(pose[1]) > limits.MAX_COORD or abs(pose[2]) > limits.MAX_ANGLE:
        return "placed outside the workspace (target beyond the coordinate bounds)"
    return None


#: ``rule(goal, scene, poses, on)``: ``None`` when the goal holds, else why not.
Rule = Callable[[Goal, Scene, np.ndarray, tuple[int, ...]], "str | None"]
_RULES: dict[str, Rule] = {}


def register_rule(name: str, rule: Rule) -> Rule:
    """Give declared pattern ``name`` its acceptance rule.

    The pattern must first be declared with
    :func:`lgmcts.formats.declare_pattern`; the built-in rules cannot be
    replaced. The on-table requirement of the pattern's format is checked
    before ``rule`` is called.
    """
    if pattern_format(name) is None:
        raise ValueError(f"declare pattern '{name}' (lgmcts.formats.declare_pattern) before its rule")
    if name in PATTERN_NAMES:
        raise ValueError(f"'{name}' is a built-in pattern; its rule cannot be replaced")
    _RULES[name] = rule
    return rule


@dataclass(frozen=True)
class Verdict:
    """Outcome of :func:`check`.

    ``valid`` holds when every action is legal and every goal is met;
    ``reasons`` lists each violation in words; ``goals`` says per goal whether
    it holds in the final state.
    """

    valid: bool
    reasons: tuple[str, ...] = ()
    goals: tuple[bool, ...] = field(default=())

    def __bool__(self) -> bool:
        return self.valid


# ---------------------------------------------------------------- shape fits


def line_residuals(xy: np.ndarray) -> np.ndarray:
    """Distances of points to their total-least-squares line."""
    c = xy - xy.mean(axis=0)
    if len(xy) < 3:
        return np.zeros(len(xy))
    _, _, vt = np.linalg.svd(c, full_matrices=False)
    normal = vt[-1]
    return np.abs(c @ normal)


def fit_circle(xy: np.ndarray) -> tuple[np.ndarray, float]:
    """Geometric least-squares circle: centre ``(2,)`` and radius (m)."""
    x, y = xy[:, 0], xy[:, 1]
    a = np.stack([2 * x, 2 * y, np.ones_like(x)], axis=1)
    b = x**2 + y**2
    sol, *_ = np.linalg.lstsq(a, b, rcond=None)
    c0 = sol[:2]
    r0 = math.sqrt(max(sol[2] + c0 @ c0, 1e-12))

    from scipy.optimize import least_squares  # imported on first use: it costs 0.6 s at start-up

    def resid(p: np.ndarray) -> np.ndarray:
        return np.hypot(x - p[0], y - p[1]) - p[2]

    res = least_squares(resid, np.array([c0[0], c0[1], r0]), method="lm")
    cx, cy, r = res.x
    return np.array([cx, cy]), abs(float(r))


def _circle_ok(xy: np.ndarray) -> str | None:
    if len(xy) < 3:
        return "a circle needs at least 3 objects"
    centre, r = fit_circle(xy)
    if not math.isfinite(r) or r < MIN_CIRCLE_RADIUS:
        return f"fitted radius {r:.3f} m is below {MIN_CIRCLE_RADIUS} m"
    err = np.abs(np.hypot(*(xy - centre).T) - r)
    if err.max() > TOL:
        return f"a centre is {err.max():.3f} m off the fitted circle"
    ang = np.sort(np.arctan2(xy[:, 1] - centre[1], xy[:, 0] - centre[0]))
    gaps = np.diff(np.concatenate([ang, ang[:1] + 2 * math.pi]))
    if gaps.max() >= math.pi:
        return f"largest angular gap {math.degrees(gaps.max()):.0f} deg is not below 180 deg"
    return None


def _rectangle_ok(xy: np.ndarray) -> str | None:
    if len(xy) < 4:
        return "a rectangle needs at least 4 objects"
    rect = shapely.MultiPoint(xy).minimum_rotated_rectangle
    if rect.geom_type != "Polygon":
        return "centres are collinear"
    corners = np.asarray(rect.exterior.coords)[:4]
    sides = np.linalg.norm(np.roll(corners, -1, axis=0) - corners, axis=1)
    if sides.min() < MIN_RECT_SIDE:
        return f"rectangle side {sides.min():.3f} m is below {MIN_RECT_SIDE} m"
    segs = [shapely.LineString([corners[k], corners[(k + 1) % 4]]) for k in range(4)]
    pts = shapely.points(xy)
    d = np.stack([shapely.distance(pts, s) for s in segs], axis=1)  # (n, 4)
    if d.min(axis=1).max() > TOL:
        return f"a centre is {d.min(axis=1).max():.3f} m off the rectangle's perimeter"
    if not (d <= TOL).any(axis=0).all():
        return "a side of the rectangle holds no object"
    return None


def _line_direction(xy: np.ndarray) -> np.ndarray:
    """Unit direction of the total-least-squares line through ``xy``."""
    c = xy - xy.mean(axis=0)
    _, _, vt = np.linalg.svd(c, full_matrices=False)
    return vt[0]


def _off(a: float, b: float, period: float) -> float:
    """Distance between angles ``a`` and ``b`` modulo ``period`` (rad)."""
    d = (a - b) % period
    return min(d, period - d)


def _params_ok(goal: Goal, scene: Scene, poses: np.ndarray, idx: list[int]) -> str | None:
    """Why ``goal``'s region, size or facing does not hold, or ``None`` (rules in :mod:`lgmcts.params`)."""
    if goal.region is None and goal.size is None and goal.facing is None:
        return None
    gp = resolve_params(goal, scene.bounds, scene.radii[idx])
    xy = poses[idx, :2]
    if gp.box is not None:
        x0, x1, y0, y1 = gp.box
        out = np.maximum.reduce([x0 - xy[:, 0], xy[:, 0] - x1, y0 - xy[:, 1], xy[:, 1] - y1, np.zeros(len(xy))])
        k = int(np.argmax(out))
        if out[k] > REGION_TOL:
            where = f"'{goal.region}'" if isinstance(goal.region, str) else f"box {list(goal.region)}"
            return f"object {scene.ids[idx[k]]} is {out[k]:.3f} m outside region {where}"
    p = goal.pattern
    if gp.heading is not None:
        h, tol = gp.heading, gp.heading_tol
        for i in idx:
            d = _off(float(poses[i, 2]), h, 2 * math.pi)
            if d > tol + 1e-9:
                return f"object {scene.ids[i]} faces {math.degrees(d):.0f} deg off facing '{goal.facing}'"
        if p == "line" and len(xy) >= 2:
            u = _line_direction(xy)
            d = _off(math.atan2(u[1], u[0]), h + math.pi / 2, math.pi)
            if d > tol + 1e-9:
                return f"the line runs {math.degrees(d):.0f} deg off across facing '{goal.facing}'"
        if p == "rectangle":
            rect = shapely.MultiPoint(xy).minimum_rotated_rectangle
            if rect.geom_type == "Polygon":
                cs = np.asarray(rect.exterior.coords)[:2]
                e = cs[1] - cs[0]
                d = _off(math.atan2(e[1], e[0]), h, math.pi / 2)
                if d > tol + 1e-9:
                    return f"the rectangle's sides are {math.degrees(d):.0f} deg off facing '{goal.facing}'"
    if gp.size is not None:
        if p == "circle":
            length = fit_circle(xy)[1]
        elif p == "line":
            t = (xy - xy.mean(axis=0)) @ _line_direction(xy)
            length = float(t.max() - t.min())
        else:
            rect = shapely.MultiPoint(xy).minimum_rotated_rectangle
            cs = np.asarray(rect.exterior.coords)[:4] if rect.geom_type == "Polygon" else xy[:1]
            length = float(np.linalg.norm(np.roll(cs, -1, axis=0) - cs, axis=1).max(initial=0.0))
        lo, hi = gp.size
        if not lo - SIZE_TOL <= length <= hi + SIZE_TOL:
            what = {"circle": "radius", "line": "length", "rectangle": "longer side"}[p]
            want = f"{lo:.3f}..{hi:.3f}" if hi < math.inf else f">= {lo:.3f}"
            return f"{what} {length:.3f} m is not {goal.size!r} ({want} m, tolerance {SIZE_TOL} m)"
    return None


def goal_satisfied(goal: Goal, scene: Scene, poses: np.ndarray, on: tuple[int, ...]) -> str | None:
    """``None`` when ``goal`` holds for ``poses``/``on``, else why it does not."""
    why = _shape_satisfied(goal, scene, poses, on)
    if why is not None:
        return why
    return _params_ok(goal, scene, poses, [scene.index[i] for i in goal.objects])


def _shape_satisfied(goal: Goal, scene: Scene, poses: np.ndarray, on: tuple[int, ...]) -> str | None:
    idx = [scene.index[i] for i in goal.objects]
    xy = poses[idx, :2]
    p = goal.pattern
    fmt = pattern_format(p)
    if fmt is not None and fmt.on_table:
        for i in idx:
            if on[i] != TABLE:
                return f"object {scene.ids[i]} is not on the table"
    if p == "line":
        r = line_residuals(xy)
        if r.max(initial=0.0) > TOL:
            return f"a centre is {r.max():.3f} m off the fitted line"
        return None
    if p == "circle":
        return _circle_ok(xy)
    if p == "rectangle":
        return _rectangle_ok(xy)
    if p == "tower":
        if on[idx[0]] != TABLE:
            return f"tower base {goal.objects[0]} is not on the table"
        for a, b in zip(idx, idx[1:]):
            if on[b] != a:
                return f"object {scene.ids[b]} is not on object {scene.ids[a]}"
            if math.hypot(*(poses[b, :2] - poses[a, :2])) > TOWER_TOL:
                return f"object {scene.ids[b]} is off-centre on object {scene.ids[a]}"
        return None
    if p in RELATIONS:
        d = np.asarray(RELATIONS[p])
        a = poses[scene.index[goal.anchor], :2]  # type: ignore[index]
        for i in idx:
            v = poses[i, :2] - a
            n = float(np.hypot(*v))
            if n <= 0 or n > MAX_RELATION_DIST:
                return f"object {scene.ids[i]} is {n:.3f} m from anchor {goal.anchor} (needs 0 < d <= {MAX_RELATION_DIST})"
            ang = math.acos(max(-1.0, min(1.0, float(v @ d) / n)))
            if ang > RELATION_HALF_ANGLE + 1e-9:
                return f"object {scene.ids[i]} is {math.degrees(ang):.0f} deg off '{p}' of anchor {goal.anchor}"
        return None
    if p == "pose":
        tgt = np.asarray(goal.pose)
        cur = poses[idx[0]]
        if math.hypot(*(cur[:2] - tgt[:2])) > TOL:
            return f"object {goal.objects[0]} is {math.hypot(*(cur[:2] - tgt[:2])):.3f} m from its goal pose"
        dth = (cur[2] - tgt[2] + math.pi) % (2 * math.pi) - math.pi
        if abs(dth) > POSE_ANGLE_TOL:
            return f"object {goal.objects[0]} is {abs(dth):.2f} rad off its goal yaw"
        return None
    rule = _RULES.get(p)
    if rule is not None:
        return rule(goal, scene, poses, on)
    raise InputError(f"pattern '{p}' has no acceptance rule (lgmcts.validate.register_rule)")


# ---------------------------------------------------------------- replay


def check(scene: SceneSpec | Scene | dict | str, goals: GoalSpec | dict | list | str, plan: PlanSpec | dict | str) -> Verdict:
    """Replay ``plan`` on ``scene`` and judge it against ``goals``.

    Raises :class:`InputError` only for inputs that are themselves malformed
    (unknown ids in the goals, a bad scene); an illegal plan is a verdict.
    """
    sc = scene if isinstance(scene, Scene) else Scene.from_spec(load_scene(scene))
    gs = load_goals(goals)
    gs.check_against(sc.spec)
    pl = load_plan(plan)
    xmin, xmax, ymin, ymax = sc.bounds
    ws = shapely.box(xmin, ymin, xmax, ymax)
    poses = np.array(sc.initial.poses, dtype=float)
    on = list(sc.initial.on)
    polys = list(sc.initial.polys)
    reasons: list[str] = []
    for step, act in enumerate(pl.actions, start=1):
        if act.object not in sc.index:
            reasons.append(f"action {step}: unknown object {act.object}")
            break
        i = sc.index[act.object]
        if any(s == i for s in on):
            top = [sc.ids[k] for k, s in enumerate(on) if s == i]
            reasons.append(f"action {step}: object {act.object} is not clear (object {top[0]} rests on it)")
        new_pose = np.asarray(act.to, dtype=float)
        bad = _pose_out_of_bounds(new_pose)
        if bad is not None:
            # Bounds first: geometry at such magnitudes means nothing (a
            # footprint at x = 1e20 collapses to a point of zero area).
            reasons.append(f"action {step}: object {act.object} {bad}")
            break
        verts = sc.footprint(i, new_pose)
        poly = shapely.polygons(verts)
        if act.on is None:
            # Every vertex in the box means the convex footprint is inside. A
            # centre off the workspace or a vertex beyond EDGE_TOL outside is
            # always a violation; a smaller excursion is one when the area
            # outside exceeds OVERLAP_AREA.
            x, y = verts[:, 0], verts[:, 1]
            excursion = float(max((xmin - x).max(), (x - xmax).max(), (ymin - y).max(), (y - ymax).max()))
            centre_in = xmin <= new_pose[0] <= xmax and ymin <= new_pose[1] <= ymax
            if not centre_in or excursion > EDGE_TOL or (
                excursion > 0 and shapely.area(shapely.difference(poly, ws)) > OVERLAP_AREA
            ):
                reasons.append(f"action {step}: object {act.object} placed outside the workspace")
            # Only footprints whose circumscribed circles meet can overlap.
            reach = sc.radii[i] + sc.radii + 1e-9
            close = np.hypot(poses[:, 0] - new_pose[0], poses[:, 1] - new_pose[1]) <= reach
            others = [k for k, s in enumerate(on) if k != i and s == TABLE and close[k]]
            if others:
                arr = np.empty(len(others), dtype=object)
                arr[:] = [polys[k] for k in others]
                touching = np.flatnonzero(shapely.intersects(poly, arr))
                areas = shapely.area(shapely.intersection(poly, arr[touching])) if len(touching) else []
                if len(touching) and sc.discs[i] > 0:
                    # Cylinder against cylinder: the circles' lens, not the polygons'.
                    areas = np.asarray(areas, dtype=float)
                    for t_k, t in enumerate(touching):
                        k = others[int(t)]
                        if sc.discs[k] > 0:
                            d = math.hypot(*(poses[k, :2] - new_pose[:2]))
                            areas[t_k] = geo.lens_area(float(sc.discs[i]), float(sc.discs[k]), d)
                for t, area in zip(touching, areas):
                    if area > OVERLAP_AREA:
                        k = others[int(t)]
                        reasons.append(
                            f"action {step}: object {act.object} overlaps object {sc.ids[k]} by {area * 1e4:.2f} cm^2"
                        )
            new_on = TABLE
        else:
            if act.on not in sc.index:
                reasons.append(f"action {step}: unknown support {act.on}")
                break
            j = sc.index[act.on]
            if j == i:
                reasons.append(f"action {step}: object {act.object} placed on itself")
                break
            if any(s == j for k, s in enumerate(on) if k != i):
                reasons.append(f"action {step}: support {act.on} is not clear")
            if not shapely.contains_xy(polys[j], new_pose[0], new_pose[1]):
                reasons.append(f"action {step}: centre of object {act.object} is not over support {act.on}")
            new_on = j
        poses[i] = new_pose
        on[i] = new_on
        polys[i] = poly
    results = []
    for k, g in enumerate(gs.goals):
        why = goal_satisfied(g, sc, poses, tuple(on))
        results.append(why is None)
        if why is not None:
            reasons.append(f"goal {k} ({g.pattern} {g.objects}): {why}")
    return Verdict(valid=not reasons, reasons=tuple(reasons), goals=tuple(results))
