"""A pattern added in one module: ``column``, centres on one front-to-back line.

Importing this module is all it takes for goal files, the validator, the
planner and the language matcher to know the pattern::

    import lgmcts
    import column  # this file, on the Python path

    lgmcts.plan(scene, {"goals": [{"pattern": "column", "objects": [1, 2, 3]}]})

The module makes one registration, ``register(Column())``: from the class
it derives the goal format (``min_objects``, no anchor, on the table, a
``size`` because it has a ``size_word``), the validator's rule (``accept``,
written apart from the sampler, as the built-in rules are), the size rule
(``size``, ``size_band``), the drawing (``shape``) and the language keys
(``keys``).

A goal may say how long the column is: ``"size": "small" | "medium" |
"large"`` (thirds of the lengths from objects side by side to the room's
depth, :meth:`Column.size_band`) or a length in metres, the distance from
the front-most centre to the back-most.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import shapely

from lgmcts.patterns import register
from lgmcts.patterns.base import BAND, EDGE_EPS, BasePattern, Context, GoalProgress, goal_xy, room, uniform_poses
from lgmcts.tolerances import TOL


@dataclass(frozen=True)
class ColumnFit:
    """A finished column: its x and the y of its front-most and back-most centres (m)."""

    x: float
    front: float
    back: float


@dataclass(frozen=True)
class Column(BasePattern):
    """Prior: the first object anywhere; the rest at its x (Gaussian noise
    clipped to the band), turned to face along the column. Without a size the
    rest go anywhere in y; with one, the second goes a length from the size's
    band away from the first, in front or behind, and the others between the
    two, so the column's length is the second's distance."""

    name = "column"
    keys = ("column", "in a column", "one behind the other", "front to back line")
    description = "the objects' centres lie on one front-to-back line"
    min_objects = 2
    size_word = "length"

    def _placed_y(self, ctx: Context) -> list[float]:
        return [float(ctx.state.poses[i, 1]) for i in ctx.progress.placed]

    def _x0(self, ctx: Context) -> float | None:
        placed = ctx.progress.placed
        return None if not placed else float(ctx.state.poses[placed[0], 0])

    def _y_span(self, ctx: Context, obj: int) -> list[tuple[float, float]]:
        """The y intervals the next object may take, given a size (none: anywhere)."""
        size = ctx.goal.params.size
        _, _, ylo, yhi = room(ctx, obj)
        ys = self._placed_y(ctx)
        if size is None or not ys:
            return [(ylo, yhi)]
        if len(ys) >= 2:  # between the first two: the length stays theirs
            return [(min(ys[:2]), max(ys[:2]))]
        lo, hi = size
        y0 = ys[0]
        spans = [(max(y0 - hi, ylo), y0 - lo), (y0 + lo, min(y0 + hi, yhi))]
        return [(a, b) for a, b in spans if a <= b]

    def sample(self, ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
        poses = uniform_poses(ctx.scene, obj, rng, n)
        x0 = self._x0(ctx)
        if x0 is not None:
            poses[:, 0] = x0 + np.clip(rng.normal(0.0, BAND / 2, n), -BAND, BAND)
            poses[:, 2] = np.pi / 2
            if ctx.goal.params.size is not None:
                spans = self._y_span(ctx, obj)
                if not spans:
                    return np.empty((0, 3))
                pick = rng.integers(len(spans), size=n)
                a = np.array([spans[k][0] for k in pick])
                b = np.array([spans[k][1] for k in pick])
                poses[:, 1] = a + (b - a) * rng.random(n)
        return poses

    def density(self, ctx: Context, obj: int, poses: np.ndarray) -> np.ndarray:
        poses = np.asarray(poses, dtype=float).reshape(-1, 3)
        x0 = self._x0(ctx)
        if x0 is None:
            return np.ones(len(poses))
        ok = np.abs(poses[:, 0] - x0) <= BAND + EDGE_EPS
        if ctx.goal.params.size is not None:
            y = poses[:, 1]
            inside = np.zeros(len(y), dtype=bool)
            for a, b in self._y_span(ctx, obj):
                inside |= (y >= a - EDGE_EPS) & (y <= b + EDGE_EPS)
            ok &= inside
        return ok.astype(float)

    def commit(self, ctx: Context, obj: int, pose: np.ndarray, rng: np.random.Generator) -> GoalProgress:
        return ctx.progress.add(obj)

    def region(self, ctx: Context):
        x0 = self._x0(ctx)
        if x0 is None:
            return None
        _, _, ymin, ymax = ctx.scene.bounds
        half = ctx.max_radius + BAND
        return shapely.box(x0 - half, ymin, x0 + half, ymax)

    # The finished arrangement: the acceptance rule, the size and what to draw.

    def fit(self, xy: np.ndarray) -> ColumnFit:
        """The column's x (the mean of the centres' x) and its ends in y."""
        return ColumnFit(float(np.mean(xy[:, 0])), float(xy[:, 1].min()), float(xy[:, 1].max()))

    def accept(self, goal, scene, poses, on) -> str | None:
        """Every centre within TOL of the mean x of the goal's centres."""
        xs = goal_xy(goal, scene, poses)[:, 0]
        off = float(np.abs(xs - xs.mean()).max())
        if off > TOL:
            return f"a centre is {off:.3f} m off the column"
        return None

    def size(self, fitted: ColumnFit) -> float:
        """The column's length: from the front-most centre to the back-most (m)."""
        return fitted.back - fitted.front

    def size_band(self, n, rmax, room, heading) -> tuple[float, float]:
        """Objects side by side at the shortest; the room's depth at the longest."""
        return 2 * rmax * (max(n, 2) - 1), max(room[3] - room[2], 0.0)

    def shape(self, goal, scene, poses) -> tuple[str, dict]:
        """Drawn as a line at the column's x, from the front-most centre to the back-most."""
        f = self.fit(goal_xy(goal, scene, poses))
        return "line", {"points": np.array([[f.x, f.front], [f.x, f.back]])}


register(Column())
