"""Line: objects' centres on one straight line.

kappa(p0, p1) is the point p0 and the unit direction from p0 to p1; later
objects go on gamma(t) = p0 + t u, t along the part of the line inside the
workspace, with Gaussian noise across the line clipped to :data:`BAND`.

A goal's region cuts the line to the region; a facing turns the line across
the heading (the second object goes exactly across it from the first, and
the noise across the line shrinks to a quarter, so the fitted line keeps
the heading) and sets every object's yaw; a size bounds the second object's
distance and keeps the spread of the centres along the line in its band
(the last object to go stretches the line to the band when it is short).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely

from ..tolerances import TOL
from .base import (
    BAND,
    CLEARANCE,
    EDGE_EPS,
    BasePattern,
    Context,
    GoalProgress,
    box_region,
    fit_json,
    goal_xy,
    params_mask,
    register,
    room,
    start_poses,
    with_heading,
)

#: Largest distance of the second object from the first (m).
DELTA = 0.35
#: How far inside a named size band the line's length stays (m).
SIZE_MARGIN = 0.004
#: Largest angle between the second object's direction and the line a facing
#: asks for, for an object already there (rad).
DIR_EPS = 0.02


def _band(ctx: Context) -> tuple[float, float] | None:
    """The lengths the line may take, kept inside a named size band; ``None`` without a size."""
    size = ctx.goal.params.size
    if size is None:
        return None
    lo, hi = size
    m = 0.0 if lo == hi else min(SIZE_MARGIN, (hi - lo) / 4) if np.isfinite(hi) else SIZE_MARGIN
    return lo + m, hi - m


def _chord(ctx: Context, obj: int, p0: np.ndarray, u: np.ndarray) -> tuple[float, float]:
    """Range of t for which p0 + t u keeps object ``obj`` inside the workspace (and its centre in the region)."""
    x0, x1, y0, y1 = room(ctx, obj)
    lo, hi = -np.inf, np.inf
    for c, a, b in ((0, x0, x1), (1, y0, y1)):
        if abs(u[c]) < 1e-12:
            if not a <= p0[c] <= b:
                return 1.0, -1.0
            continue
        t1, t2 = (a - p0[c]) / u[c], (b - p0[c]) / u[c]
        lo, hi = max(lo, min(t1, t2)), min(hi, max(t1, t2))
    return lo, hi


# ---------------------------------------------------------------- kappa and the finished line


@dataclass(frozen=True)
class LineParams:
    """kappa of a line: a ``point`` on it and its unit ``direction``; in the
    search the first object and the direction to the second. Fitted to final
    centres: through their mean along the total-least-squares direction, with
    ``ends``, the extreme centres projected on it."""

    point: tuple[float, float]
    direction: tuple[float, float]
    ends: tuple[tuple[float, float], tuple[float, float]] | None = None

    @property
    def length(self) -> float:
        """Spread of the centres along the line (m); 0 before the line is finished."""
        if self.ends is None:
            return 0.0
        (x0, y0), (x1, y1) = self.ends
        return float(np.hypot(x1 - x0, y1 - y0))


def fit_line(xy: np.ndarray) -> LineParams:
    """Total-least-squares line through ``(n, 2)`` centres (any ``n >= 1``)."""
    xy = np.asarray(xy, dtype=float)
    c = xy.mean(axis=0)
    if len(xy) < 2:
        u = np.array([1.0, 0.0])
    else:
        _, _, vt = np.linalg.svd(xy - c, full_matrices=False)
        u = vt[0]
    t = (xy - c) @ u
    a, b = c + u * t.min(), c + u * t.max()
    return LineParams(
        (float(c[0]), float(c[1])), (float(u[0]), float(u[1])), ((float(a[0]), float(a[1])), (float(b[0]), float(b[1])))
    )


def line_residuals(xy: np.ndarray) -> np.ndarray:
    """Distances of points to their total-least-squares line."""
    c = xy - xy.mean(axis=0)
    if len(xy) < 3:
        return np.zeros(len(xy))
    _, _, vt = np.linalg.svd(c, full_matrices=False)
    return np.abs(c @ vt[-1])


@dataclass(frozen=True)
class Line(BasePattern):
    name = "line"
    keys = (
        "line",
        "in a line",
        "into a line",
        "in a row",
        "row",
        "straight line",
        "line up",
        "align in a line",
        "arrange in a line",
        "put in a row",
        "single file",
        "queue",
        "in a straight row",
        "strip",
        "straight strip",
        "band",
    )
    description = "the objects' centres lie on one straight line"
    min_objects = 2

    def _params(self, ctx: Context) -> tuple[np.ndarray, np.ndarray] | None:
        if ctx.progress.params is None:
            return None
        kappa = ctx.progress.params
        return np.array(kappa.point), np.array(kappa.direction)

    def _reach(self, ctx: Context, obj: int) -> tuple[float, float]:
        """Distances the second object may take from the first (m)."""
        d_min = ctx.radius(ctx.progress.placed[0]) + ctx.radius(obj) + CLEARANCE
        band = _band(ctx)
        if band is None:
            return d_min, DELTA
        lo, hi = band
        if ctx.n > 2:
            lo = 0.0  # the later objects stretch the line
        x0, x1, y0, y1 = room(ctx, obj)
        hi = min(hi, float(np.hypot(max(x1 - x0, 0.0), max(y1 - y0, 0.0))))
        return max(d_min, lo), max(max(d_min, lo), hi)

    def _room_for(self, ctx: Context, p0: np.ndarray, p1: np.ndarray) -> np.ndarray:
        """Whether the line through ``p0`` and each of ``p1`` (``(m, 2)``) has
        room, inside the region and workspace, for the length the size asks."""
        band = _band(ctx)
        need = 0.0 if band is None else band[0]
        x0, x1, y0, y1 = room(ctx, ctx.goal.objects[0], ctx.max_radius - ctx.radius(ctx.goal.objects[0]))
        v = p1 - p0
        d = np.hypot(v[:, 0], v[:, 1])
        u = v / np.maximum(d, 1e-12)[:, None]
        lo, hi = np.full(len(p1), -np.inf), np.full(len(p1), np.inf)
        for c, a, b in ((0, x0, x1), (1, y0, y1)):
            uc = np.where(np.abs(u[:, c]) < 1e-12, 1e-12, u[:, c])
            t1, t2 = (a - p0[c]) / uc, (b - p0[c]) / uc
            lo, hi = np.maximum(lo, np.minimum(t1, t2)), np.minimum(hi, np.maximum(t1, t2))
        return (hi - lo >= need - EDGE_EPS) & (lo <= EDGE_EPS) & (hi >= d - EDGE_EPS)

    def _allowed_t(self, ctx: Context, obj: int, ts: np.ndarray, t: np.ndarray) -> np.ndarray:
        """Whether positions ``t`` along the line keep its length in the size band."""
        band = _band(ctx)
        if band is None:
            return np.ones(len(t), dtype=bool)
        lo, hi = band
        a, b = ts.min(), ts.max()
        ok = (t >= b - hi - EDGE_EPS) & (t <= a + hi + EDGE_EPS)
        if len(ctx.progress.placed) == ctx.n - 1 and b - a < lo:  # the last object must stretch it
            ok &= (t <= b - lo + EDGE_EPS) | (t >= a + lo - EDGE_EPS)
        return ok

    def _first(self, ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
        """Poses for the first object of a sized line: one end of a segment of
        a length in the band that fits in the room (region and workspace)."""
        lo, hi = _band(ctx)  # type: ignore[misc]
        heading = ctx.goal.params.heading
        x0, x1, y0, y1 = room(ctx, obj, ctx.max_radius - ctx.radius(obj))
        if x0 > x1 or y0 > y1:
            return np.empty((0, 3))
        a = heading + rng.choice([-np.pi / 2, np.pi / 2], n) if heading is not None else rng.uniform(-np.pi, np.pi, n)
        u = np.stack([np.cos(a), np.sin(a)], axis=1)
        cap = float(np.hypot(x1 - x0, y1 - y0))
        short = max(lo, 2 * ctx.max_radius * (ctx.n - 1))
        length = rng.uniform(short, max(short, min(hi, cap)), n)
        d = length[:, None] * u
        sx0, sx1 = x0 - np.minimum(d[:, 0], 0), x1 - np.maximum(d[:, 0], 0)
        sy0, sy1 = y0 - np.minimum(d[:, 1], 0), y1 - np.maximum(d[:, 1], 0)
        ok = (sx0 <= sx1) & (sy0 <= sy1)
        if not ok.any():
            return start_poses(ctx, obj, rng, n)
        xy = np.column_stack([rng.uniform(sx0[ok], sx1[ok]), rng.uniform(sy0[ok], sy1[ok])])
        return with_heading(ctx, np.column_stack([xy, a[ok]]))

    def sample(self, ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
        placed = ctx.progress.placed
        heading = ctx.goal.params.heading
        if not placed:
            if _band(ctx) is not None:
                return self._first(ctx, obj, rng, n)
            return start_poses(ctx, obj, rng, n)
        st = ctx.state
        if len(placed) == 1:
            p0 = st.poses[placed[0], :2]
            r_lo, r_hi = self._reach(ctx, obj)
            if _band(ctx) is None:
                r = r_lo + rng.uniform(0.0, 1.0, n) ** 2 * max(0.02, min(r_hi, 2.5 * r_lo) - r_lo)
            else:
                r = rng.uniform(r_lo, r_hi, n)
            if heading is not None:
                a = heading + rng.choice([-np.pi / 2, np.pi / 2], n)
            else:
                # Half the proposals continue the first object's heading, so rows look tidy.
                a = np.where(
                    rng.random(n) < 0.5,
                    st.poses[placed[0], 2] + rng.choice([0.0, np.pi], n),
                    rng.uniform(-np.pi, np.pi, n),
                )
            xy = p0 + r[:, None] * np.stack([np.cos(a), np.sin(a)], axis=1)
            out = with_heading(ctx, np.column_stack([xy, a]))
            if ctx.goal.params.box is None and _band(ctx) is None:
                return out
            return out[params_mask(ctx, obj, out) & self._room_for(ctx, p0, out[:, :2])]
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
        band = _band(ctx)
        if band is not None:
            # Half the proposals uniform over the positions that keep the length in the band.
            a_, b_ = ts.min(), ts.max()
            w0, w1 = max(lo, b_ - band[1]), min(hi, a_ + band[1])
            wins = [(w0, w1)]
            if len(placed) == ctx.n - 1 and b_ - a_ < band[0]:
                wins = [(w0, min(w1, b_ - band[0])), (max(w0, a_ + band[0]), w1)]
            wins = [(x, y) for x, y in wins if x <= y]
            if wins:
                sizes = np.array([y - x for x, y in wins]) + 1e-12
                pick = rng.choice(len(wins), n, p=sizes / sizes.sum())
                lo_w, hi_w = np.array([wins[k][0] for k in pick]), np.array([wins[k][1] for k in pick])
                t = np.where(rng.random(n) < 0.5, rng.uniform(lo_w, hi_w), t)
            t = t[self._allowed_t(ctx, obj, ts, t)]
            n = len(t)
        normal = np.array([-u[1], u[0]])
        spread = BAND if heading is None else BAND / 4
        e = np.clip(rng.normal(0.0, spread / 2, n), -spread, spread)
        xy = p0 + t[:, None] * u + e[:, None] * normal
        theta = np.full(n, np.arctan2(u[1], u[0]))
        out = with_heading(ctx, np.column_stack([xy, theta]))
        return out if ctx.goal.params.box is None else out[params_mask(ctx, obj, out)]

    def _density(self, ctx: Context, obj: int, poses: np.ndarray) -> np.ndarray:
        placed = ctx.progress.placed
        if not placed:
            return np.ones(len(poses))
        if len(placed) == 1:
            v = poses[:, :2] - ctx.state.poses[placed[0], :2]
            d = np.hypot(*v.T)
            r_lo, r_hi = self._reach(ctx, obj) if not ctx.goal.params.empty else (0.0, DELTA)
            ok = (d <= r_hi + EDGE_EPS) & (d >= (r_lo if _band(ctx) is not None else 0.0) - EDGE_EPS)
            heading = ctx.goal.params.heading
            if heading is not None:
                a = np.arctan2(v[:, 1], v[:, 0])
                ok &= np.abs((a - heading) % np.pi - np.pi / 2) <= DIR_EPS
            if ctx.goal.params.box is not None or _band(ctx) is not None:
                ok &= self._room_for(ctx, ctx.state.poses[placed[0], :2], poses[:, :2])
            return ok.astype(float)
        p0, u = self._params(ctx)  # type: ignore[misc]
        normal = np.array([-u[1], u[0]])
        e = (poses[:, :2] - p0) @ normal
        spread = BAND if ctx.goal.params.heading is None else BAND / 4
        out = np.where(np.abs(e) <= spread + EDGE_EPS, np.exp(-0.5 * (e / (BAND / 2)) ** 2), 0.0)
        if _band(ctx) is not None:
            ts = np.array([float(np.dot(ctx.state.poses[k, :2] - p0, u)) for k in placed])
            out = out * self._allowed_t(ctx, obj, ts, (poses[:, :2] - p0) @ u)
        return out

    def commit(self, ctx: Context, obj: int, pose: np.ndarray, rng: np.random.Generator) -> GoalProgress:
        prog = ctx.progress
        # The second object fixes kappa, also when an earlier kappa is left
        # from objects that have moved off the line since (one object alone
        # lies on every line through it).
        if len(prog.placed) == 1:
            p0 = ctx.state.poses[prog.placed[0], :2]
            v = np.asarray(pose[:2]) - p0
            norm = float(np.hypot(*v)) or 1.0
            return prog.add(
                obj, params=LineParams((float(p0[0]), float(p0[1])), (float(v[0] / norm), float(v[1] / norm)))
            )
        return prog.add(obj)

    def region(self, ctx: Context):
        pr = self._params(ctx)
        if pr is None:
            return box_region(ctx)
        p0, u = pr
        lo, hi = _chord(ctx, ctx.goal.objects[0], p0, u)
        if lo > hi:
            return None
        seg = shapely.LineString([p0 + lo * u, p0 + hi * u])
        return seg.buffer(ctx.max_radius + BAND)

    def recover(self, goal, placed, poses, final) -> GoalProgress:
        # kappa is the first two placed objects' point and direction.
        if len(placed) < 2:
            return super().recover(goal, placed, poses, final)
        p0, p1 = poses[placed[0], :2], poses[placed[1], :2]
        u = (p1 - p0) / (np.hypot(*(p1 - p0)) or 1.0)
        return GoalProgress(
            tuple(placed),
            tuple(-1 for _ in placed),
            LineParams((float(p0[0]), float(p0[1])), (float(u[0]), float(u[1]))),
        )

    # The finished arrangement (the acceptance rule and what to draw).
    size_word = "length"

    def size_band(
        self, n: int, rmax: float, room: tuple[float, float, float, float], heading: float | None
    ) -> tuple[float, float]:
        # Objects side by side at the shortest; the room's extent along the
        # line (which runs across a facing) at the longest.
        w, h = max(room[1] - room[0], 0.0), max(room[3] - room[2], 0.0)
        lo = 2 * rmax * (max(n, 2) - 1)
        if heading is None:
            return lo, max(w, h)
        ux, uy = abs(math.sin(heading)), abs(math.cos(heading))  # the line's direction
        return lo, min(w / ux if ux > 1e-9 else math.inf, h / uy if uy > 1e-9 else math.inf)

    def fit(self, xy: np.ndarray) -> LineParams:
        return fit_line(xy)

    def accept(self, goal, scene, poses, on) -> str | None:
        r = line_residuals(goal_xy(goal, scene, poses))
        if r.max(initial=0.0) > TOL:
            return f"a centre is {r.max():.3f} m off the fitted line"
        return None

    def shape(self, goal, scene, poses) -> tuple[str, dict]:
        xy = goal_xy(goal, scene, poses)
        fitted = fit_json(fit_line(xy))
        drawn = self.draw(fitted) if fitted is not None else None
        return drawn if drawn is not None else ("points", {"points": xy})

    def draw(self, fitted: dict) -> tuple[str, dict] | None:
        if fitted.get("ends") is None:
            return None
        return "line", {"points": np.asarray(fitted["ends"], dtype=float)}

    def size(self, fitted: LineParams) -> float:
        return fitted.length

    def facing_axis(self, fitted: LineParams) -> tuple[float, float, str]:
        # A row facing north runs east-west: its direction is across the heading.
        ux, uy = fitted.direction
        return math.atan2(uy, ux) - math.pi / 2, math.pi, "the line runs {deg:.0f} deg off across facing '{facing}'"


register(Line())
