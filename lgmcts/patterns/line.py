"""Line: objects' centres on one straight line.

kappa(p0, p1) is the point p0 and the unit direction from p0 to p1; later
objects go on gamma(t) = p0 + t u, t along the part of the line inside the
workspace, with Gaussian noise across the line clipped to :data:`BAND`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import shapely

from .base import BAND, CLEARANCE, EDGE_EPS, BasePattern, Context, GoalProgress, register, uniform_poses

#: Largest distance of the second object from the first (m).
DELTA = 0.35


def _chord(ctx: Context, obj: int, p0: np.ndarray, u: np.ndarray) -> tuple[float, float]:
    """Range of t for which p0 + t u keeps object ``obj`` inside the workspace."""
    xmin, xmax, ymin, ymax = ctx.scene.bounds
    r = ctx.radius(obj)
    lo, hi = -np.inf, np.inf
    for c, a, b in ((0, xmin + r, xmax - r), (1, ymin + r, ymax - r)):
        if abs(u[c]) < 1e-12:
            if not a <= p0[c] <= b:
                return 1.0, -1.0
            continue
        t1, t2 = (a - p0[c]) / u[c], (b - p0[c]) / u[c]
        lo, hi = max(lo, min(t1, t2)), min(hi, max(t1, t2))
    return lo, hi


@dataclass(frozen=True)
class Line(BasePattern):
    name = "line"
    keys = (
        "line", "in a line", "into a line", "in a row", "row", "straight line", "line up", "align in a line",
        "arrange in a line", "put in a row", "single file", "queue", "in a straight row",
    )
    description = "the objects' centres lie on one straight line"
    min_objects = 2

    def _params(self, ctx: Context) -> tuple[np.ndarray, np.ndarray] | None:
        if ctx.progress.params is None:
            return None
        x, y, ux, uy = ctx.progress.params
        return np.array([x, y]), np.array([ux, uy])

    def sample(self, ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
        placed = ctx.progress.placed
        if not placed:
            return uniform_poses(ctx.scene, obj, rng, n)
        st = ctx.state
        if len(placed) == 1:
            p0 = st.poses[placed[0], :2]
            d_min = ctx.radius(placed[0]) + ctx.radius(obj) + CLEARANCE
            r = d_min + rng.uniform(0.0, 1.0, n) ** 2 * max(0.02, min(DELTA, 2.5 * d_min) - d_min)
            # Half the proposals continue the first object's heading, so rows look tidy.
            a = np.where(rng.random(n) < 0.5, st.poses[placed[0], 2] + rng.choice([0.0, np.pi], n), rng.uniform(-np.pi, np.pi, n))
            xy = p0 + r[:, None] * np.stack([np.cos(a), np.sin(a)], axis=1)
            return np.column_stack([xy, a])
        p0, u = self._params(ctx)  # type: ignore[misc]
        lo, hi = _chord(ctx, obj, p0, u)
        if lo > hi:
            return np.empty((0, 3))
        ts = np.array([float(np.dot(st.poses[k, :2] - p0, u)) for k in placed])
        step = ctx.radius(obj) + ctx.max_radius + CLEARANCE + 0.002
        t = rng.uniform(lo, hi, n)
        near = rng.random(n) < 0.6
        ends = np.where(rng.random(n) < 0.5, ts.max() + step, ts.min() - step) + rng.uniform(0, 0.01, n)
        t = np.where(near, np.clip(ends, lo, hi), t)
        normal = np.array([-u[1], u[0]])
        e = np.clip(rng.normal(0.0, BAND / 2, n), -BAND, BAND)
        xy = p0 + t[:, None] * u + e[:, None] * normal
        theta = np.full(n, np.arctan2(u[1], u[0]))
        return np.column_stack([xy, theta])

    def density(self, ctx: Context, obj: int, poses: np.ndarray) -> np.ndarray:
        placed = ctx.progress.placed
        poses = np.asarray(poses, dtype=float).reshape(-1, 3)
        if not placed:
            return np.ones(len(poses))
        if len(placed) == 1:
            d = np.hypot(*(poses[:, :2] - ctx.state.poses[placed[0], :2]).T)
            return (d <= DELTA + EDGE_EPS).astype(float)
        p0, u = self._params(ctx)  # type: ignore[misc]
        normal = np.array([-u[1], u[0]])
        e = (poses[:, :2] - p0) @ normal
        return np.where(np.abs(e) <= BAND + EDGE_EPS, np.exp(-0.5 * (e / (BAND / 2)) ** 2), 0.0)

    def commit(self, ctx: Context, obj: int, pose: np.ndarray, rng: np.random.Generator) -> GoalProgress:
        prog = ctx.progress
        # The second object fixes kappa, also when an earlier kappa is left
        # from objects that have moved off the line since (one object alone
        # lies on every line through it).
        if len(prog.placed) == 1:
            p0 = ctx.state.poses[prog.placed[0], :2]
            v = np.asarray(pose[:2]) - p0
            norm = float(np.hypot(*v)) or 1.0
            return prog.add(obj, params=(float(p0[0]), float(p0[1]), float(v[0] / norm), float(v[1] / norm)))
        return prog.add(obj)

    def region(self, ctx: Context):
        pr = self._params(ctx)
        if pr is None:
            return None
        p0, u = pr
        lo, hi = _chord(ctx, ctx.goal.objects[0], p0, u)
        if lo > hi:
            return None
        seg = shapely.LineString([p0 + lo * u, p0 + hi * u])
        return seg.buffer(ctx.max_radius + BAND)


register(Line())
