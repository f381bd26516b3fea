"""Pose: one object at a fixed pose (the goals of the PMCTS baseline)."""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import lru_cache

import numpy as np
import shapely

from ..geometry import wrap_angle
from ..tolerances import POSE_ANGLE_TOL, TOL
from .base import BasePattern, Context, GoalProgress, register

#: How close to the target the planner's placement must be (m, rad); the
#: acceptance rule allows 0.015 m and 0.1 rad.
XY_TOL, YAW_TOL = 0.003, 0.03


_ANGLES = np.arange(32) * (2 * np.pi / 32)
_UNIT = np.stack([np.cos(_ANGLES), np.sin(_ANGLES)], axis=1)


@lru_cache(maxsize=4096)
def _disc(x: float, y: float, r: float):
    """The target's disc (a 32-gon); goals ask for it at every relocation, so it is built once."""
    return shapely.polygons(_UNIT * r + (x, y))


@dataclass(frozen=True)
class Pose(BasePattern):
    name = "pose"
    keys = ("at the pose", "at exactly this position", "move to the coordinates", "place at position")
    description = "one object at a given pose [x, y, theta]"
    min_objects = 1
    on_table = False
    needs_pose = True
    deterministic = True

    def sample(self, ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
        return np.asarray(ctx.goal.pose, dtype=float).reshape(1, 3)

    def density(self, ctx: Context, obj: int, poses: np.ndarray) -> np.ndarray:
        poses = np.asarray(poses, dtype=float).reshape(-1, 3)
        t = np.asarray(ctx.goal.pose)
        dth = np.abs(wrap_angle(poses[:, 2] - t[2]))
        return ((np.hypot(*(poses[:, :2] - t[:2]).T) <= XY_TOL) & (dth <= YAW_TOL)).astype(float)

    def commit(self, ctx: Context, obj: int, pose: np.ndarray, rng: np.random.Generator) -> GoalProgress:
        return ctx.progress.add(obj)

    def region(self, ctx: Context):
        if ctx.goal.objects[0] in ctx.progress.placed:
            return None
        x, y, _ = ctx.goal.pose  # type: ignore[misc]
        return _disc(float(x), float(y), ctx.max_radius)

    def describe(self, goal) -> str:
        x, y, t = goal.pose
        return f"{goal.objects[0]} to ({x:.2f}, {y:.2f}, {t:.2f})"

    def rank(self, goal, progress, obj) -> int:
        return 0  # a fixed target: it samples, the other priors filter

    # The finished arrangement (the acceptance rule and what to draw).
    def accept(self, goal, scene, poses, on) -> str | None:
        tgt = np.asarray(goal.pose)
        cur = poses[scene.index[goal.objects[0]]]
        if math.hypot(*(cur[:2] - tgt[:2])) > TOL:
            return f"object {goal.objects[0]} is {math.hypot(*(cur[:2] - tgt[:2])):.3f} m from its goal pose"
        dth = float(wrap_angle(cur[2] - tgt[2]))
        if abs(dth) > POSE_ANGLE_TOL:
            return f"object {goal.objects[0]} is {abs(dth):.2f} rad off its goal yaw"
        return None

    def shape(self, goal, scene, poses) -> tuple[str, dict]:
        return "pose", {"target": np.asarray(goal.pose, dtype=float)}


register(Pose())
