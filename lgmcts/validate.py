"""The acceptance rules, implemented once and independently of the search.

:func:`check` replays a plan on a scene with exact polygon geometry (shapely)
and judges the final state against every goal. Each pattern's own rule is the
``accept`` method of its module in :mod:`lgmcts.patterns` (with its fit, in
the module's "finished arrangement" section, written apart from its sampler);
this module applies the rules common to all goals and the optional region,
size and facing. It steps through a plan with :func:`lgmcts.scene.advance`,
the one replay step of the package, and shares no other code with the search.

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

A pattern added outside the package brings its rule in its own module
(``accept``, registered with the pattern by :func:`lgmcts.patterns.register`).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import shapely

from . import geometry as geo
from .errors import InputError
from .formats import (
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
from .patterns import registry
from .patterns.base import wrap_off
from .patterns.circle import fit_circle
from .patterns.line import line_residuals
from .scene import TABLE, Scene, State, advance
from .tolerances import (
    MAX_RELATION_DIST,
    MIN_CIRCLE_RADIUS,
    MIN_RECT_SIDE,
    OVERLAP_AREA,
    POSE_ANGLE_TOL,
    RELATION_HALF_ANGLE,
    TOL,
    TOWER_TOL,
)

__all__ = [
    "MAX_RELATION_DIST",
    "OVERLAP_AREA",
    "TOL",
    "TOWER_TOL",
    "Verdict",
    "check",
    "goal_satisfied",
    "register_rule",
]

# Re-exported for callers of this module: fit_circle, line_residuals and the
# tolerances (defined in lgmcts.patterns and lgmcts.tolerances).
_REEXPORTED = (
    fit_circle,
    line_residuals,
    MAX_RELATION_DIST,
    MIN_CIRCLE_RADIUS,
    MIN_RECT_SIDE,
    POSE_ANGLE_TOL,
    RELATION_HALF_ANGLE,
    TOL,
    TOWER_TOL,
)
#: A footprint vertex this far (m) outside the workspace is a violation
#: whatever the area outside.
EDGE_TOL = 1e-3


#: ``rule(goal, scene, poses, on)``: ``None`` when the goal holds, else why not.
Rule = Callable[[Goal, Scene, np.ndarray, tuple[int, ...]], "str | None"]
_RULES: dict[str, Rule] = {}


def register_rule(name: str, rule: Rule) -> Rule:
    """Give declared pattern ``name`` an acceptance rule apart from a prior.

    A pattern module needs none of this (its ``accept`` is its rule); this is
    for a goal format declared with :func:`lgmcts.formats.declare_pattern` and
    judged without a prior. The built-in rules cannot be replaced; a rule
    given here takes precedence over the prior's ``accept``. The on-table
    requirement of the pattern's format is checked before ``rule`` is called.
    """
    if pattern_format(name) is None:
        raise ValueError(f"declare pattern '{name}' (lgmcts.formats.declare_pattern) before its rule")
    built_in = registry().get(name)
    if built_in is not None and type(built_in).__module__.startswith(f"{__package__}.patterns."):
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


# ---------------------------------------------------------------- goal rules


def _params_ok(goal: Goal, scene: Scene, poses: np.ndarray, idx: list[int]) -> str | None:
    """Why ``goal``'s region, size or facing does not hold, or ``None`` (rules in :mod:`lgmcts.params`;
    the pattern says what its size measures and which way it runs)."""
    if goal.region is None and goal.size is None and goal.facing is None:
        return None
    gp = resolve_params(goal, scene.bounds, scene.radii[idx].tolist())
    xy = poses[idx, :2]
    if gp.box is not None:
        x0, x1, y0, y1 = gp.box
        out = np.maximum.reduce([x0 - xy[:, 0], xy[:, 0] - x1, y0 - xy[:, 1], xy[:, 1] - y1, np.zeros(len(xy))])
        k = int(np.argmax(out))
        if out[k] > REGION_TOL:
            where = f"'{goal.region}'" if isinstance(goal.region, str) else f"box {list(goal.region or ())}"
            return f"object {scene.ids[idx[k]]} is {out[k]:.3f} m outside region {where}"
    pattern = registry()[goal.pattern]
    fitted = pattern.fit(xy) if gp.size is not None or gp.heading is not None else None
    if gp.heading is not None:
        h, tol = gp.heading, gp.heading_tol
        for i in idx:
            d = wrap_off(float(poses[i, 2]), h, 2 * math.pi)
            if d > tol + 1e-9:
                return f"object {scene.ids[i]} faces {math.degrees(d):.0f} deg off facing '{goal.facing}'"
        axis = pattern.facing_axis(fitted) if len(xy) >= 2 else None
        if axis is not None:
            angle, period, message = axis
            d = wrap_off(angle, h, period)
            if d > tol + 1e-9:
                return message.format(deg=math.degrees(d), facing=goal.facing)
    if gp.size is not None and pattern.size_word is not None:
        length = pattern.size(fitted)
        lo, hi = gp.size
        if not lo - SIZE_TOL <= length <= hi + SIZE_TOL:
            want = f"{lo:.3f}..{hi:.3f}" if hi < math.inf else f">= {lo:.3f}"
            return f"{pattern.size_word} {length:.3f} m is not {goal.size!r} ({want} m, tolerance {SIZE_TOL} m)"
    return None


def goal_satisfied(goal: Goal, scene: Scene, poses: np.ndarray, on: tuple[int, ...]) -> str | None:
    """``None`` when ``goal`` holds for ``poses``/``on``, else why it does not."""
    why = _shape_satisfied(goal, scene, poses, on)
    if why is not None:
        return why
    return _params_ok(goal, scene, poses, [scene.index[i] for i in goal.objects])


def _shape_satisfied(goal: Goal, scene: Scene, poses: np.ndarray, on: tuple[int, ...]) -> str | None:
    p = goal.pattern
    fmt = pattern_format(p)
    if fmt is not None and fmt.on_table:
        for i in (scene.index[o] for o in goal.objects):
            if on[i] != TABLE:
                return f"object {scene.ids[i]} is not on the table"
    rule = _RULES.get(p)
    if rule is not None:
        return rule(goal, scene, poses, on)
    pattern = registry().get(p)
    if pattern is None:
        raise InputError(f"pattern '{p}' has no acceptance rule (register it: lgmcts.patterns.register)")
    return pattern.accept(goal, scene, poses, on)


# ---------------------------------------------------------------- replay


#: Judge a plan of cylinders placed on the table on their circles, without polygons (:func:`_disc_overlaps`; the
#: same verdicts); off: every placement through the polygons, for comparison.
CIRCLES = True


def _disc_overlaps(state: State, i: int, pose: np.ndarray, step: int) -> list[str]:
    """:func:`_overlaps` where object ``i`` and every object within its reach are cylinders on the table: judged on
    the circles alone. The footprint polygons circumscribe the circles, so two circles that share more than
    ``OVERLAP_AREA`` have polygons that meet, and those that share nothing are all the polygon test would leave out:
    the same verdicts and messages, without building or intersecting polygons."""
    sc = state.scene
    poses = state.poses
    reach = sc.radii[i] + sc.radii + 1e-9
    d = np.hypot(poses[:, 0] - pose[0], poses[:, 1] - pose[1])
    close = d <= reach
    close[i] = False
    ri = float(sc.discs[i])
    out = []
    # Only circles closer than their radii share any area.
    for k in np.flatnonzero(close & (d < ri + sc.discs)).tolist():
        area = geo.lens_area(ri, float(sc.discs[k]), math.hypot(*(poses[k, :2] - pose[:2])))
        if area > OVERLAP_AREA:
            out.append(f"action {step}: object {sc.ids[i]} overlaps object {sc.ids[k]} by {area * 1e4:.2f} cm^2")
    return out


def _overlaps(state: State, i: int, pose: np.ndarray, poly, step: int) -> list[str]:
    """Why placing object ``i`` on the table at ``pose`` (footprint ``poly``)
    in ``state`` overlaps another table-level footprint, if it does."""
    sc = state.scene
    poses = state.poses
    # Only footprints whose circumscribed circles meet can overlap.
    reach = sc.radii[i] + sc.radii + 1e-9
    close = np.hypot(poses[:, 0] - pose[0], poses[:, 1] - pose[1]) <= reach
    close[i] = False
    others = [int(k) for k in np.flatnonzero(close) if state.on[k] == TABLE]
    if not others:
        return []
    arr = np.empty(len(others), dtype=object)
    arr[:] = [state.polys[k] for k in others]
    touching = np.flatnonzero(shapely.intersects(poly, arr))
    if not len(touching):
        return []
    areas = np.asarray(shapely.area(shapely.intersection(poly, arr[touching])), dtype=float)
    if sc.discs[i] > 0:
        # Cylinder against cylinder: the circles' lens, not the polygons'.
        for t_k, t in enumerate(touching):
            k = others[int(t)]
            if sc.discs[k] > 0:
                d = math.hypot(*(poses[k, :2] - pose[:2]))
                areas[t_k] = geo.lens_area(float(sc.discs[i]), float(sc.discs[k]), d)
    return [
        f"action {step}: object {sc.ids[i]} overlaps object {sc.ids[others[int(t)]]} by {area * 1e4:.2f} cm^2"
        for t, area in zip(touching, areas)
        if area > OVERLAP_AREA
    ]


def check(
    scene: SceneSpec | Scene | dict | str | Path,
    goals: GoalSpec | dict | list | str | Path,
    plan: PlanSpec | dict | str | Path,
    *,
    robot: str | None = None,
) -> Verdict:
    """Replay ``plan`` on ``scene`` and judge it against ``goals``.

    With ``robot`` (``"ur5e"``, see :mod:`lgmcts.robot`) every pick and
    placement must also be within that robot's top-down reach.

    Raises :class:`InputError` only for inputs that are themselves malformed
    (unknown ids in the goals, a bad scene); an illegal plan is a verdict.
    """
    sc = scene if isinstance(scene, Scene) else Scene.from_spec(load_scene(scene))
    gs = load_goals(goals)
    gs.check_against(sc.spec)
    pl = load_plan(plan)
    if robot is not None:
        from .robot import load_robot

        load_robot(robot)  # an unknown robot is bad input
    xmin, xmax, ymin, ymax = sc.bounds
    ws = shapely.box(xmin, ymin, xmax, ymax)
    state = sc.initial
    reasons: list[str] = []
    replayed = 0
    # Cylinders only, all on the table and placed on the table: judged on their circles, no polygon built (the
    # same verdicts, see _disc_overlaps; a footprint's vertices are those its polygon would have).
    circles = (
        CIRCLES
        and bool(np.all(sc.discs > 0))
        and all(s == TABLE for s in state.on)
        and all(act.on is None for act in pl.actions)
    )
    for step, act in enumerate(pl.actions, start=1):
        try:
            # The shared step; it refuses only meaningless actions (unknown
            # ids, an object on itself, a pose beyond the coordinate bounds,
            # where geometry means nothing), which end the replay.
            after = advance(state, step, act, footprint=not circles)
        except InputError as e:
            reasons.append(str(e))
            break
        i = sc.index[act.object]
        on = state.on
        if i in on:
            reasons.append(
                f"action {step}: object {act.object} is not clear (object {sc.ids[on.index(i)]} rests on it)"
            )
        new_pose = after.poses[i]
        poly = after.polys[i]
        if act.on is None:
            # Every vertex in the box means the convex footprint is inside. A
            # centre off the workspace or a vertex beyond EDGE_TOL outside is
            # always a violation; a smaller excursion is one when the area
            # outside exceeds OVERLAP_AREA.
            verts = geo.transform(sc.local[i], new_pose) if poly is None else shapely.get_coordinates(poly)
            # The farthest vertex beyond a side (a difference is monotone in the vertex, so the extreme vertices
            # give the largest differences).
            low, high = verts.min(axis=0), verts.max(axis=0)
            excursion = float(max(xmin - low[0], high[0] - xmax, ymin - low[1], high[1] - ymax))
            centre_in = xmin <= new_pose[0] <= xmax and ymin <= new_pose[1] <= ymax
            if excursion > 0 and poly is None:
                poly = shapely.polygons(verts)
            if (
                not centre_in
                or excursion > EDGE_TOL
                or (excursion > 0 and shapely.area(shapely.difference(poly, ws)) > OVERLAP_AREA)
            ):
                reasons.append(f"action {step}: object {act.object} placed outside the workspace")
            if circles:
                reasons.extend(_disc_overlaps(state, i, new_pose, step))
            else:
                reasons.extend(_overlaps(state, i, new_pose, poly, step))
        else:
            j = sc.index[act.on]
            if on.count(j) > (on[i] == j):
                reasons.append(f"action {step}: support {act.on} is not clear")
            if not shapely.contains_xy(state.polys[j], new_pose[0], new_pose[1]):
                reasons.append(f"action {step}: centre of object {act.object} is not over support {act.on}")
        state = after
        replayed = step
    if robot is not None:
        from .robot import plan_reach_problems, robot_of

        reasons.extend(plan_reach_problems(sc, pl.actions[:replayed], robot_of(robot)))  # type: ignore[arg-type]
    results = []
    for k, g in enumerate(gs.goals):
        why = goal_satisfied(g, sc, state.poses, state.on)
        results.append(why is None)
        if why is not None:
            reasons.append(f"goal {k} ({g.pattern} {g.objects}): {why}")
    return Verdict(valid=not reasons, reasons=tuple(reasons), goals=tuple(results))
