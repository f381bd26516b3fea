"""Rectangle: objects' centres on the perimeter of a rectangle.

kappa is the rectangle (centre, width w, height h, heading phi), fixed when
the first object is placed: that object marks one corner. The next objects
fill the other three corners exactly (so the minimum-area rectangle around
the centres is this one) and any further objects go along the sides, pulled
inwards by at most :data:`BAND` so they never widen it. Sides adapt to the
object sizes so that the perimeter holds every object.
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

    def sample(self, ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
        if ctx.progress.params is None:
            out = uniform_poses(ctx.scene, obj, rng, n)
            out[rng.random(n) < 0.5, 2] = 0.0
            return out
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
        if ctx.progress.params is None:
            return np.ones(len(poses))
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
        if prog.params is None:
            n, rmax = ctx.n, ctx.max_radius
            pitch = 2 * rmax + CLEARANCE + 2 * BAND + 0.004
            side_min = max(0.06, pitch)
            per_min = n * pitch
            xmin, xmax, ymin, ymax = ctx.scene.bounds
            p = np.asarray(pose[:2], dtype=float)
            best = None
            for _ in range(32):
                w = rng.uniform(side_min, side_min * 1.5 + 0.05)
                h = rng.uniform(side_min, side_min * 1.5 + 0.05)
                if 2 * (w + h) < per_min:
                    scale = per_min / (2 * (w + h))
                    w, h = w * scale, h * scale
                phi = float(pose[2]) % (math.pi / 2)
                corner = int(rng.integers(4))
                c = p - _rot(phi) @ (_CORNERS[corner] * [w / 2, h / 2])
                params = (float(c[0]), float(c[1]), float(w), float(h), float(phi))
                cs = corners(params)
                m = rmax + 0.001
                best = (params, corner)
                if ((cs[:, 0] >= xmin + m) & (cs[:, 0] <= xmax - m) & (cs[:, 1] >= ymin + m) & (cs[:, 1] <= ymax - m)).all():
                    break
            params, corner = best  # type: ignore[misc]
            return prog.add(obj, slot=corner, params=params)
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
