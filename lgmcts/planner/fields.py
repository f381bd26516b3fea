"""The pose fields of the paper's Fig. 5: f_prior, f_free and f = f_prior x f_free
for the object moved at one step of a plan, on a grid over the workspace.

The plan does not record the curve parameters the search fixed, so they are
recovered from the plan itself: circle and rectangle parameters are fitted to
the goal's final centres, a line's from its first two placed objects; goal
objects the plan never moves count as placed from the start.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely

from .. import geometry as geo
from ..formats import Action, GoalSpec
from ..patterns import CLEARANCE, Context, GoalProgress
from ..scene import TABLE, Scene
from ..validate import fit_circle
from .step import Problem

__all__ = ["Fields", "pose_fields"]


@dataclass(frozen=True)
class Fields:
    """Grids over the workspace: ``prior`` (H, W) in [0, 1], ``free`` (H, W) bool."""

    xs: np.ndarray
    ys: np.ndarray
    prior: np.ndarray
    free: np.ndarray
    object_id: int
    step: int

    @property
    def product(self) -> np.ndarray:
        return self.prior * self.free


def _params(problem: Problem, k: int, final: np.ndarray, order: list[int]) -> tuple[float, ...] | None:
    g = problem.goals[k]
    xy = final[list(g.objects), :2]
    if g.pattern == "circle":
        c, r = fit_circle(xy)
        first = order[0] if order else g.objects[0]
        a0 = math.atan2(final[first, 1] - c[1], final[first, 0] - c[0])
        return (float(c[0]), float(c[1]), float(r), float(a0), float(len(g.objects)))
    if g.pattern == "rectangle":
        rect = shapely.MultiPoint(xy).minimum_rotated_rectangle
        if rect.geom_type != "Polygon":
            return None
        cs = np.asarray(rect.exterior.coords)[:4]
        e1, e2 = cs[1] - cs[0], cs[2] - cs[1]
        phi = math.atan2(e1[1], e1[0])
        ctr = cs.mean(axis=0)
        return (float(ctr[0]), float(ctr[1]), float(np.hypot(*e1)), float(np.hypot(*e2)), phi)
    return None


#: Most grid cells along a side of the workspace in :func:`pose_fields`.
MAX_FIELD_CELLS = 400


def pose_fields(scene: Scene, goals: GoalSpec, actions: list[Action], step: int, *, resolution: float = 0.005) -> Fields:
    """Fields for the object moved by ``actions[step]`` (0-based), in the state before it."""
    if not 0 <= step < len(actions):
        raise IndexError(f"step {step} is outside the plan's {len(actions)} actions")
    problem = Problem.build(scene, goals)
    world = scene.initial
    final = world
    for a in actions:
        final = final.moved(scene.index[a.object], a.to, TABLE if a.on is None else scene.index[a.on])
    for a in actions[:step]:
        world = world.moved(scene.index[a.object], a.to, TABLE if a.on is None else scene.index[a.on])
    last_goal_move = {scene.index[a.object]: t for t, a in enumerate(actions) if a.purpose == "goal"}
    act = actions[step]
    o = scene.index[act.object]
    xmin, xmax, ymin, ymax = scene.bounds
    # At most MAX_FIELD_CELLS cells a side: a huge workspace gets coarser cells, not a huge grid.
    resolution = max(resolution, max(xmax - xmin, ymax - ymin) / MAX_FIELD_CELLS)
    xs = np.arange(xmin + resolution / 2, xmax, resolution)
    ys = np.arange(ymin + resolution / 2, ymax, resolution)
    gx, gy = np.meshgrid(xs, ys)
    poses = np.column_stack([gx.ravel(), gy.ravel(), np.full(gx.size, act.to[2])])
    prior = np.ones(len(poses))
    if act.purpose == "goal":
        for k in problem.member.get(o, ()):
            g = problem.goals[k]
            placed = [p for p in g.objects if p != o and last_goal_move.get(p, -1) < step]
            placed.sort(key=lambda p: last_goal_move.get(p, -1))
            prog = GoalProgress(tuple(placed), tuple(-1 for _ in placed), None)
            params = _params(problem, k, final.poses, placed)
            if g.pattern == "line" and len(placed) >= 2:
                p0, p1 = world.poses[placed[0], :2], world.poses[placed[1], :2]
                u = (p1 - p0) / (np.hypot(*(p1 - p0)) or 1.0)
                params = (float(p0[0]), float(p0[1]), float(u[0]), float(u[1]))
            if params is not None and placed:
                prog = GoalProgress(tuple(placed), _slots(g.pattern, placed, params, world.poses), params)
            ctx = Context(scene, world, g, prog)
            prior = prior * problem.patterns[k].density(ctx, o, poses)
        if prior.max() > 0:
            prior = prior / prior.max()
    verts = scene.footprint(o, poses)
    inside = geo.inside_workspace(verts, scene.bounds)
    free = inside.copy()
    if act.on is None:
        obs = [k for k in world.table_level if k != o]
        if obs:
            tree = shapely.STRtree([world.polys[k] for k in obs])
            ci, _ = geo.colliding(tree, shapely.polygons(verts), CLEARANCE)
            free[np.unique(ci)] = False
    shape = gx.shape
    return Fields(xs, ys, prior.reshape(shape), free.reshape(shape), int(act.object), step)


def _slots(pattern: str, placed: list[int], params: tuple[float, ...], poses: np.ndarray) -> tuple[int, ...]:
    """Slot numbers of placed objects, recovered from their positions."""
    if pattern == "circle":
        cx, cy, _, a0, n = params
        out = []
        for p in placed:
            a = math.atan2(poses[p, 1] - cy, poses[p, 0] - cx)
            out.append(int(round(((a - a0) % (2 * math.pi)) / (2 * math.pi / n))) % int(n))
        return tuple(out)
    if pattern == "rectangle":
        from ..patterns.rectangle import corners

        cs = corners(params)
        out = []
        for j, p in enumerate(placed):
            d = np.hypot(*(cs - poses[p, :2]).T)
            out.append(int(np.argmin(d)) if d.min() <= 0.01 else 4 + j)
        return tuple(out)
    return tuple(-1 for _ in placed)
