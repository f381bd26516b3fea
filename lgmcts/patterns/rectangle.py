"""Rectangle: objects' centres on the perimeter of a rectangle.

kappa is the rectangle (centre, width w, height h, heading phi), a function
of the first two placements as in the paper: the first object marks one
corner, the second the adjacent corner at a side's length from it (so two
objects standing at such a distance can both stay), and the other side's
length and the rectangle's side of that edge are drawn so that it fits in
the workspace. The next objects fill the other two corners exactly (so the
minimum-area rectangle around the centres is this one) and any further
objects go along the sides, pulled inwards by at most :data:`BAND` so they
never widen it. Sides adapt to the object sizes so that the perimeter holds
every object.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely

from .base import BAND, CLEARANCE, EDGE_EPS, BasePattern, Context, GoalProgress, register, uniform_poses

#: Corner positions in units of (w/2, h/2), counter-clockwise from front-left.
_CORNERS = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])


def _rot(phi: float) -> np.ndarray:
    c, s = math.cos(phi), math.sin(phi)
    return np.array([[c, -s], [s, c]])


def corners(params: tuple[float, ...]) -> np.ndarray:
    """``(4, 2)`` corner positions of rectangle ``params = (cx, cy, w, h, phi)``."""
    cx, cy, w, h, phi = params[:5]
    return np.array([cx, cy]) + (_CORNERS * [w / 2, h / 2]) @ _rot(phi).T


@dataclass(frozen=True)
class Rectangle(BasePattern):
    name = "rectangle"
    keys = (
        "rectangle", "in a rectangle", "into a rectangle", "rectangular", "square", "square border", "box shape",
        "rectangular frame", "perimeter of a rectangle", "border of a square", "arrange in a rectangle",
    )
    description = "the objects' centres lie on the perimeter of one rectangle, at least one on every side"
    min_objects = 4

    def _state(self, ctx: Context) -> tuple[list[int], int]:
        used = set(ctx.progress.slots)
        free_corners = [s for s in range(4) if s not in used]
        extras_left = (ctx.n - 4) - sum(1 for s in ctx.progress.slots if s >= 4)
        return free_corners, extras_left

    def _sizes(self, ctx: Context) -> tuple[float, float, float]:
        """Shortest side, longest first side and least perimeter (m) for the goal's objects."""
        pitch = 2 * ctx.max_radius + CLEARANCE + 2 * BAND + 0.004
        side_min = max(0.06, pitch)
        per_min = ctx.n * pitch
        xmin, xmax, ymin, ymax = ctx.scene.bounds
        room = max(xmax - xmin, ymax - ymin) - 2 * ctx.max_radius
        side_max = min(max(1.5 * side_min + 0.05, per_min / 2 - side_min), room)
        return side_min, max(side_min, side_max), per_min

    def sample(self, ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
        if not ctx.progress.placed:
            out = uniform_poses(ctx.scene, obj, rng, n)
            out[rng.random(n) < 0.5, 2] = 0.0
            return out
        if ctx.progress.params is None:
            first = ctx.state.poses[ctx.progress.placed[0]]
            lo, hi, _ = self._sizes(ctx)
            d = rng.uniform(lo, hi, n)
            a = np.where(rng.random(n) < 0.5, first[2] + rng.integers(0, 4, n) * (math.pi / 2), rng.uniform(-math.pi, math.pi, n))
            xy = first[:2] + d[:, None] * np.stack([np.cos(a), np.sin(a)], axis=1)
            return np.column_stack([xy, a])
        cx, cy, w, h, phi = ctx.progress.params
        free, extras = self._state(ctx)
        rows = []
        cs = corners(ctx.progress.params)
        for _ in range(n):
            if free and (extras <= 0 or rng.random() < 0.5):
                s = int(rng.choice(free))
                rows.append([*cs[s], phi])
            elif extras > 0:
                # A point on the perimeter, pushed inwards by up to BAND.
                side = int(rng.integers(4))
                length = w if side % 2 == 0 else h
                margin = min(length / 2, ctx.max_radius + ctx.radius(obj) + CLEARANCE)
                t = rng.uniform(-length / 2 + margin, length / 2 - margin) if length / 2 > margin else 0.0
                inset = rng.uniform(0.0, BAND)
                if side == 0:
                    local = (t, -h / 2 + inset)
                elif side == 1:
                    local = (w / 2 - inset, t)
                elif side == 2:
                    local = (t, h / 2 - inset)
                else:
                    local = (-w / 2 + inset, t)
                xy = np.array([cx, cy]) + _rot(phi) @ np.asarray(local)
                rows.append([*xy, phi + (0.0 if side % 2 == 0 else math.pi / 2)])
        return np.asarray(rows, dtype=float).reshape(-1, 3)

    def _local(self, ctx: Context, poses: np.ndarray) -> np.ndarray:
        cx, cy, w, h, phi = ctx.progress.params  # type: ignore[misc]
        return (poses[:, :2] - [cx, cy]) @ _rot(phi)

    def density(self, ctx: Context, obj: int, poses: np.ndarray) -> np.ndarray:
        poses = np.asarray(poses, dtype=float).reshape(-1, 3)
        if not ctx.progress.placed:
            return np.ones(len(poses))
        if ctx.progress.params is None:
            lo, hi, _ = self._sizes(ctx)
            d = np.hypot(*(poses[:, :2] - ctx.state.poses[ctx.progress.placed[0], :2]).T)
            return ((d >= lo - EDGE_EPS) & (d <= hi + EDGE_EPS)).astype(float)
        cx, cy, w, h, phi = ctx.progress.params
        free, extras = self._state(ctx)
        out = np.zeros(len(poses))
        cs = corners(ctx.progress.params)
        for s in free:
            out = np.maximum(out, (np.hypot(*(poses[:, :2] - cs[s]).T) <= 1e-3).astype(float))
        if extras > 0:
            loc = self._local(ctx, poses)
            inside = (np.abs(loc[:, 0]) <= w / 2 + 1e-9) & (np.abs(loc[:, 1]) <= h / 2 + 1e-9)
            to_edge = np.minimum(w / 2 - np.abs(loc[:, 0]), h / 2 - np.abs(loc[:, 1]))
            out = np.maximum(out, (inside & (to_edge <= BAND + EDGE_EPS)).astype(float))
        return out

    def commit(self, ctx: Context, obj: int, pose: np.ndarray, rng: np.random.Generator) -> GoalProgress:
        prog = ctx.progress
        if not prog.placed:
            return prog.add(obj, slot=-1)
        if prog.params is None:
            first = prog.placed[0]
            p0 = ctx.state.poses[first, :2]
            p1 = np.asarray(pose[:2], dtype=float)
            lo, hi, per_min = self._sizes(ctx)
            w = float(np.clip(np.hypot(*(p1 - p0)), lo, hi))
            u = (p1 - p0) / max(float(np.hypot(*(p1 - p0))), 1e-12)
            phi = math.atan2(u[1], u[0])
            h_lo = max(lo, per_min / 2 - w)
            xmin, xmax, ymin, ymax = ctx.scene.bounds
            m = ctx.max_radius + 0.001
            best = None
            for attempt in range(24):
                h = rng.uniform(h_lo, h_lo + 0.05) if attempt < 16 else h_lo
                side = 1.0 if rng.random() < 0.5 else -1.0
                v = side * np.array([-u[1], u[0]])
                c = p0 + (w / 2) * u + (h / 2) * v
                params = (float(c[0]), float(c[1]), float(w), float(h), float(phi))
                cs = corners(params)
                slots = (0, 1) if side > 0 else (3, 2)
                best = (params, slots)
                if ((cs[:, 0] >= xmin + m) & (cs[:, 0] <= xmax - m) & (cs[:, 1] >= ymin + m) & (cs[:, 1] <= ymax - m)).all():
                    break
            params, slots = best  # type: ignore[misc]
            return GoalProgress((first, obj), slots, params)
        free, extras = self._state(ctx)
        cs = corners(prog.params)
        for s in free:
            if math.hypot(*(np.asarray(pose[:2]) - cs[s])) <= 1e-3:
                return prog.add(obj, slot=s)
        return prog.add(obj, slot=4 + len(prog.placed))

    def region(self, ctx: Context):
        if ctx.progress.params is None:
            return None
        ring = shapely.LinearRing(corners(ctx.progress.params))
        return ring.buffer(ctx.max_radius + BAND)


register(Rectangle())
