"""Circle: objects' centres evenly around one circle.

kappa is the centre c, the radius R and the angle a0 of the first object
about c; object slots sit at gamma(s / n) = c + R (cos, sin)(a0 + 2 pi s / n).
The radius adapts to the objects' sizes (neighbouring slots must not
collide) and the circle is placed so that it fits in the workspace.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely

from .base import BAND, CLEARANCE, EDGE_EPS, BasePattern, Context, GoalProgress, register, uniform_poses

#: Largest angular deviation from a slot, as a fraction of half the slot pitch.
SLOT_SPREAD = 0.3


def radius_range(ctx: Context) -> tuple[float, float]:
    """Smallest radius at which neighbours clear each other, and the largest that fits (m)."""
    n, rmax = ctx.n, ctx.max_radius
    xmin, xmax, ymin, ymax = ctx.scene.bounds
    lo = max(0.06, (2 * rmax + 2 * CLEARANCE + 2 * BAND) / (2 * math.sin(math.pi / n)))
    hi = min(xmax - xmin, ymax - ymin) / 2 - rmax - 0.002
    return lo, max(lo, hi)


def _fits(ctx: Context, c: np.ndarray, r: float) -> bool:
    xmin, xmax, ymin, ymax = ctx.scene.bounds
    m = r + ctx.max_radius + BAND
    return xmin + m <= c[0] <= xmax - m and ymin + m <= c[1] <= ymax - m


@dataclass(frozen=True)
class Circle(BasePattern):
    name = "circle"
    keys = (
        "circle", "in a circle", "into a circle", "ring", "in a ring", "circular", "round shape", "around a circle",
        "circle formation", "arrange in a circle", "form a circle", "on a circle",
    )
    description = "the objects' centres lie evenly spaced on one circle"
    min_objects = 3

    def _slot_angles(self, ctx: Context) -> tuple[np.ndarray, np.ndarray]:
        cx, cy, r, a0, n = ctx.progress.params  # type: ignore[misc]
        used = set(ctx.progress.slots)
        free = np.array([s for s in range(int(n)) if s not in used], dtype=int)
        return free, a0 + 2 * math.pi * free / n

    def sample(self, ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
        if ctx.progress.params is None:
            return uniform_poses(ctx.scene, obj, rng, n)
        cx, cy, r, a0, k = ctx.progress.params
        free, angles = self._slot_angles(ctx)
        if len(free) == 0:
            return np.empty((0, 3))
        spread = SLOT_SPREAD * math.pi / k
        a = rng.choice(angles, n) + np.clip(rng.normal(0, spread / 2, n), -spread, spread)
        rr = r + np.clip(rng.normal(0, BAND / 2, n), -BAND, BAND)
        return np.column_stack([cx + rr * np.cos(a), cy + rr * np.sin(a), a + math.pi / 2])

    def density(self, ctx: Context, obj: int, poses: np.ndarray) -> np.ndarray:
        poses = np.asarray(poses, dtype=float).reshape(-1, 3)
        if ctx.progress.params is None:
            return np.ones(len(poses))
        cx, cy, r, a0, k = ctx.progress.params
        free, angles = self._slot_angles(ctx)
        if len(free) == 0:
            return np.zeros(len(poses))
        d = np.hypot(poses[:, 0] - cx, poses[:, 1] - cy) - r
        a = np.arctan2(poses[:, 1] - cy, poses[:, 0] - cx)
        da = np.abs((a[:, None] - angles[None, :] + math.pi) % (2 * math.pi) - math.pi).min(axis=1)
        spread = SLOT_SPREAD * math.pi / k
        ok = (np.abs(d) <= BAND + EDGE_EPS) & (da <= spread + EDGE_EPS)
        return np.where(ok, np.exp(-0.5 * (d / (BAND / 2)) ** 2 - 0.5 * (da / (spread / 2)) ** 2), 0.0)

    def commit(self, ctx: Context, obj: int, pose: np.ndarray, rng: np.random.Generator) -> GoalProgress:
        prog = ctx.progress
        if prog.params is None:
            lo, hi = radius_range(ctx)
            hi = min(hi, 1.5 * lo + 0.03)
            p = np.asarray(pose[:2], dtype=float)
            best = None
            # Prefer a centre beside the object so that its heading is tangent.
            for attempt in range(32):
                r = rng.uniform(lo, max(lo, hi))
                side = rng.choice([-1.0, 1.0])
                beta = pose[2] + side * math.pi / 2 if attempt < 8 else rng.uniform(-math.pi, math.pi)
                c = p + r * np.array([math.cos(beta), math.sin(beta)])
                best = (c, r, beta)
                if _fits(ctx, c, r):
                    break
            c, r, beta = best  # type: ignore[misc]
            a0 = math.atan2(p[1] - c[1], p[0] - c[0])
            return prog.add(obj, slot=0, params=(float(c[0]), float(c[1]), float(r), float(a0), float(ctx.n)))
        free, angles = self._slot_angles(ctx)
        cx, cy = prog.params[0], prog.params[1]
        a = math.atan2(pose[1] - cy, pose[0] - cx)
        da = np.abs((a - angles + math.pi) % (2 * math.pi) - math.pi)
        return prog.add(obj, slot=int(free[int(np.argmin(da))]))

    def region(self, ctx: Context):
        if ctx.progress.params is None:
            return None
        cx, cy, r, _, _ = ctx.progress.params
        w = ctx.max_radius + BAND
        return shapely.Point(cx, cy).buffer(r + w).difference(shapely.Point(cx, cy).buffer(max(r - w, 0.0)))


register(Circle())
