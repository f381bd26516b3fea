"""The pose fields of the paper's Fig. 5: f_prior, f_free and f = f_prior x f_free
for the object moved at one step of a plan, on a grid over the workspace.

The plan does not record the curve parameters the search fixed, so each
goal's pattern recovers them from the plan (its ``recover``: a circle or
rectangle fitted to the goal's final centres, a line from its first two
placed objects); goal objects the plan never moves count as placed from the
start.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import shapely

from .. import geometry as geo
from ..formats import Action, GoalSpec
from ..patterns import CLEARANCE, Context
from ..planner.problem import Problem
from ..scene import Scene, replay

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


#: Most grid cells along a side of the workspace in :func:`pose_fields`.
MAX_FIELD_CELLS = 400


def pose_fields(
    scene: Scene, goals: GoalSpec, actions: list[Action], step: int, *, resolution: float = 0.005
) -> Fields:
    """Fields for the object moved by ``actions[step]`` (0-based), in the state before it."""
    if not 0 <= step < len(actions):
        raise IndexError(f"step {step} is outside the plan's {len(actions)} actions")
    problem = Problem.build(scene, goals)
    states = replay(scene, actions)
    world, final = states[step], states[-1]
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
            prog = problem.patterns[k].recover(g, tuple(placed), world.poses, final.poses)
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
