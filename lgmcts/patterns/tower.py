"""Tower: objects[0] on the table, each next object centred on the previous.

An ordered pattern: object k may only be placed once object k-1 is placed
in this branch; its pose is the support's centre and heading. A region
holds the base's centre (and so the tower's); a facing is the base's yaw,
which every object above takes from its support. A tower has no size.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass

import numpy as np

from ..scene import TABLE
from ..tolerances import TOWER_TOL
from .base import BasePattern, Context, GoalProgress, box_region, goal_xy, params_mask, register, start_poses

#: How far off the support's centre an object may already rest and still
#: count as stacked (m); the acceptance rule allows 0.02 m. New placements
#: are always exactly centred.
CENTRE_TOL = 0.01


@dataclass(frozen=True)
class Tower(BasePattern):
    name = "tower"
    keys = (
        "tower", "stack", "stack up", "pile", "pile up", "on top of each other", "build a tower", "stack them",
        "one on top of another", "vertical stack", "heap", "heap up", "layer", "layer them",
    )
    description = "objects[0] stands on the table and each next object rests centred on the previous one"
    min_objects = 2
    ordered = True
    on_table = False
    # A tower's footprint is its base object's: a size is accepted and ignored.
    size_ignored = True

    def _position(self, ctx: Context, obj: int) -> int:
        return ctx.goal.objects.index(obj)

    def ready(self, ctx: Context, obj: int, settled: frozenset[int]) -> bool:
        k = self._position(ctx, obj)
        return k == 0 or ctx.goal.objects[k - 1] in ctx.progress.placed

    def support(self, ctx: Context, obj: int) -> int:
        k = self._position(ctx, obj)
        return TABLE if k == 0 else ctx.goal.objects[k - 1]

    def sample(self, ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
        k = self._position(ctx, obj)
        if k == 0:
            return start_poses(ctx, obj, rng, n)
        return np.asarray(ctx.state.poses[ctx.goal.objects[k - 1]], dtype=float).reshape(1, 3).copy()

    def density(self, ctx: Context, obj: int, poses: np.ndarray) -> np.ndarray:
        poses = np.asarray(poses, dtype=float).reshape(-1, 3)
        k = self._position(ctx, obj)
        if k == 0:
            return params_mask(ctx, obj, poses).astype(float)
        base = ctx.state.poses[ctx.goal.objects[k - 1], :2]
        ok = np.hypot(*(poses[:, :2] - base).T) <= CENTRE_TOL
        if ctx.goal.params.heading is not None:
            ok &= params_mask(ctx, obj, poses)
        return ok.astype(float)

    def commit(self, ctx: Context, obj: int, pose: np.ndarray, rng: np.random.Generator) -> GoalProgress:
        return ctx.progress.add(obj)

    def region(self, ctx: Context):
        return box_region(ctx) if not ctx.progress.placed else None

    def describe(self, goal) -> str:
        return "tower " + " < ".join(str(i) for i in goal.objects)

    def rank(self, goal, progress, obj) -> int:
        # An upper level's pose is its support's; a base goes after the other priors.
        return 1 if goal.objects.index(obj) > 0 else 5

    # The finished arrangement (the acceptance rule and what to draw).
    def accept(self, goal, scene, poses, on) -> str | None:
        idx = [scene.index[i] for i in goal.objects]
        if on[idx[0]] != TABLE:
            return f"tower base {goal.objects[0]} is not on the table"
        for a, b in itertools.pairwise(idx):
            if on[b] != a:
                return f"object {scene.ids[b]} is not on object {scene.ids[a]}"
            if math.hypot(*(poses[b, :2] - poses[a, :2])) > TOWER_TOL:
                return f"object {scene.ids[b]} is off-centre on object {scene.ids[a]}"
        return None

    def shape(self, goal, scene, poses) -> tuple[str, dict]:
        return "tower", {"centre": goal_xy(goal, scene, poses)[0], "levels": list(goal.objects)}


register(Tower())
