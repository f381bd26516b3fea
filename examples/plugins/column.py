"""A pattern added in one module: ``column``, centres on one front-to-back line.

Importing this module is all it takes for goal files, the validator, the
planner and the language matcher to know the pattern::

    import lgmcts
    import column  # this file, on the Python path

    lgmcts.plan(scene, {"goals": [{"pattern": "column", "objects": [1, 2, 3]}]})

The module makes one registration, ``register(Column())``: from the class
it derives the goal format (``min_objects``, no anchor, on the table), the
validator's rule (``accept``, written apart from the sampler, as the built-in
rules are), the drawing (``shape``) and the language keys (``keys``).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import shapely

from lgmcts.patterns import register
from lgmcts.patterns.base import BAND, EDGE_EPS, BasePattern, Context, GoalProgress, goal_xy, uniform_poses
from lgmcts.tolerances import TOL


@dataclass(frozen=True)
class Column(BasePattern):
    """Prior: the first object anywhere; the rest at its x (Gaussian noise
    clipped to the band), anywhere in y, turned to face along the column."""

    name = "column"
    keys = ("column", "in a column", "one behind the other", "front to back line")
    description = "the objects' centres lie on one front-to-back line"
    min_objects = 2

    def _x0(self, ctx: Context) -> float | None:
        placed = ctx.progress.placed
        return None if not placed else float(ctx.state.poses[placed[0], 0])

    def sample(self, ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
        poses = uniform_poses(ctx.scene, obj, rng, n)
        x0 = self._x0(ctx)
        if x0 is not None:
            poses[:, 0] = x0 + np.clip(rng.normal(0.0, BAND / 2, n), -BAND, BAND)
            poses[:, 2] = np.pi / 2
        return poses

    def density(self, ctx: Context, obj: int, poses: np.ndarray) -> np.ndarray:
        poses = np.asarray(poses, dtype=float).reshape(-1, 3)
        x0 = self._x0(ctx)
        if x0 is None:
            return np.ones(len(poses))
        return (np.abs(poses[:, 0] - x0) <= BAND + EDGE_EPS).astype(float)

    def commit(self, ctx: Context, obj: int, pose: np.ndarray, rng: np.random.Generator) -> GoalProgress:
        return ctx.progress.add(obj)

    def region(self, ctx: Context):
        x0 = self._x0(ctx)
        if x0 is None:
            return None
        _, _, ymin, ymax = ctx.scene.bounds
        half = ctx.max_radius + BAND
        return shapely.box(x0 - half, ymin, x0 + half, ymax)

    # The finished arrangement: the acceptance rule and what to draw.

    def fit(self, xy: np.ndarray) -> float:
        """The column's x (the mean of the centres' x)."""
        return float(np.mean(xy[:, 0]))

    def accept(self, goal, scene, poses, on) -> str | None:
        """Every centre within TOL of the mean x of the goal's centres."""
        xs = goal_xy(goal, scene, poses)[:, 0]
        off = float(np.abs(xs - xs.mean()).max())
        if off > TOL:
            return f"a centre is {off:.3f} m off the column"
        return None

    def shape(self, goal, scene, poses) -> tuple[str, dict]:
        """Drawn as a line at the column's x, from the front-most centre to the back-most."""
        xy = goal_xy(goal, scene, poses)
        x = self.fit(xy)
        return "line", {"points": np.array([[x, xy[:, 1].min()], [x, xy[:, 1].max()]])}


register(Column())
