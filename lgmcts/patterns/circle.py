"""Circle: objects' centres evenly around one circle.

kappa is the centre c, the radius R and the angle a0 of the first object
about c; object slots sit at gamma(s / n) = c + R (cos, sin)(a0 + 2 pi s / n).
As in the paper, kappa is a function of the first two placements p0, p1:
the second object goes at a chord's length from the first, d = 2 R sin(k pi / n)
for some slot offset k, and (p0, p1, k) then fix the circle. The radius range
adapts to the objects' sizes (neighbouring slots must not collide) and a
circle is only proposed where it fits in the workspace. Because the second
object may be anywhere at an admissible distance from the first, two objects
that already stand at such a distance can both stay where they are.

A goal's size narrows the radius range to its band, a region keeps the
circle (with its band) inside it and starts the first object on a circle
that fits there, and a facing sets every object's yaw.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely

from ..geometry import wrap_angle
from ..tolerances import MIN_CIRCLE_RADIUS, TOL
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
    register,
    start_poses,
    uniform_poses,
    with_heading,
)

#: Largest angular deviation from a slot, as a fraction of half the slot pitch.
SLOT_SPREAD = 0.3
#: How far inside a named size band the proposed radii stay (m).
SIZE_MARGIN = 0.004


def _band(ctx: Context) -> float:
    """Radial noise of the slots (m): :data:`BAND`, a quarter of it in a region
    (small regions then hold more objects)."""
    return BAND if ctx.goal.params.box is None else BAND / 4


def _spread(ctx: Context, r: float, k: float) -> float:
    """Angular noise of the slots (rad); in a region at most 2 band widths along the circle."""
    spread = SLOT_SPREAD * math.pi / k
    return spread if ctx.goal.params.box is None else min(spread, 2 * _band(ctx) / max(r, 1e-9))


def radius_range(ctx: Context) -> tuple[float, float]:
    """Smallest radius at which neighbours clear each other, and the largest proposed (m).

    A goal's size narrows the range to its band (kept :data:`SIZE_MARGIN`
    inside a named band); a region caps it at what the region holds.
    """
    n, rmax = ctx.n, ctx.max_radius
    xmin, xmax, ymin, ymax = ctx.scene.bounds
    lo = max(0.06, (2 * rmax + 2 * CLEARANCE + 2 * _band(ctx)) / (2 * math.sin(math.pi / n)))
    top = min(xmax - xmin, ymax - ymin) / 2 - rmax - 0.002
    gp = ctx.goal.params
    if gp.box is not None:
        x0, x1, y0, y1 = gp.box
        top = min(top, min(x1 - x0, y1 - y0) / 2 - _band(ctx) - 0.001)
    if gp.size is None:
        hi = min(top, 1.5 * lo + 0.05)
        return lo, max(lo, hi)
    blo, bhi = gp.size
    m = 0.0 if blo == bhi else min(SIZE_MARGIN, (bhi - blo) / 4)
    lo2, hi2 = max(lo, blo + m), min(top, bhi - m)
    if lo2 > hi2:  # the band and what fits do not meet: the nearest that fits
        lo2 = hi2 = max(lo, min(blo, top))
    return lo2, hi2


def _fits(ctx: Context, c: np.ndarray, r: np.ndarray | float) -> np.ndarray:
    """Whether circles of centres ``c`` (``(m, 2)``) and radii ``r`` fit in the workspace
    (and their centres, with the band around them, in the goal's region)."""
    xmin, xmax, ymin, ymax = ctx.scene.bounds
    m = np.asarray(r) + ctx.max_radius + _band(ctx)
    c = np.asarray(c).reshape(-1, 2)
    ok = (xmin + m <= c[:, 0]) & (c[:, 0] <= xmax - m) & (ymin + m <= c[:, 1]) & (c[:, 1] <= ymax - m)
    box = ctx.goal.params.box
    if box is not None:
        e = np.asarray(r) + _band(ctx)
        ok &= (box[0] + e <= c[:, 0]) & (c[:, 0] <= box[1] - e) & (box[2] + e <= c[:, 1]) & (c[:, 1] <= box[3] - e)
    return ok


def _first(ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
    """Poses for the first object of a goal with a region or size: on a circle
    of an admissible radius whose centre lets it fit."""
    lo, hi = radius_range(ctx)
    r = rng.uniform(lo, hi, n)
    xmin, xmax, ymin, ymax = ctx.scene.bounds
    m = r + ctx.max_radius + _band(ctx)
    x0, x1, y0, y1 = xmin + m, xmax - m, ymin + m, ymax - m
    box = ctx.goal.params.box
    if box is not None:
        e = r + _band(ctx)
        x0, x1 = np.maximum(x0, box[0] + e), np.minimum(x1, box[1] - e)
        y0, y1 = np.maximum(y0, box[2] + e), np.minimum(y1, box[3] - e)
    ok = (x0 <= x1) & (y0 <= y1)
    if not ok.any():
        return start_poses(ctx, obj, rng, n)
    r, x0, x1, y0, y1 = r[ok], x0[ok], x1[ok], y0[ok], y1[ok]
    c = np.column_stack([rng.uniform(x0, x1), rng.uniform(y0, y1)])
    a = rng.uniform(-math.pi, math.pi, len(r))
    out = np.column_stack([c[:, 0] + r * np.cos(a), c[:, 1] + r * np.sin(a), rng.uniform(-math.pi, math.pi, len(r))])
    return with_heading(ctx, out)


def _centres(p0: np.ndarray, p1: np.ndarray, r: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The two centres of circles of radii ``r`` through ``p0`` and ``p1`` (rows)."""
    p1 = np.asarray(p1).reshape(-1, 2)
    v = p1 - p0
    d = np.hypot(v[:, 0], v[:, 1])
    mid = (p0 + p1) / 2
    h = np.sqrt(np.maximum(r**2 - (d / 2) ** 2, 0.0))
    nrm = np.stack([-v[:, 1], v[:, 0]], axis=1) / np.maximum(d, 1e-12)[:, None]
    return mid + h[:, None] * nrm, mid - h[:, None] * nrm


def _chord_ks(ctx: Context, d: float, lo: float, hi: float) -> list[tuple[int, float]]:
    """Slot offsets k (and radii) for which a chord of length ``d`` spans k slots."""
    n = ctx.n
    out = []
    for k in range(1, n // 2 + 1):
        r = d / (2 * math.sin(k * math.pi / n))
        if lo - EDGE_EPS <= r <= hi + EDGE_EPS:
            out.append((k, r))
    return out


# ---------------------------------------------------------------- kappa and the finished circle


@dataclass(frozen=True)
class CircleParams:
    """kappa of a circle: ``centre``, ``radius``, the angle about the centre
    of slot 0 (the first object placed, ``start_angle``) and the number of
    evenly spaced slots (``count``, the goal's object count). Fitted to final
    centres it is the least-squares circle, slot 0 at the first object."""

    centre: tuple[float, float]
    radius: float
    start_angle: float
    count: int


def fit_circle(xy: np.ndarray) -> tuple[np.ndarray, float]:
    """Geometric least-squares circle: centre ``(2,)`` and radius (m)."""
    x, y = xy[:, 0], xy[:, 1]
    a = np.stack([2 * x, 2 * y, np.ones_like(x)], axis=1)
    b = x**2 + y**2
    sol, *_ = np.linalg.lstsq(a, b, rcond=None)
    c0 = sol[:2]
    r0 = math.sqrt(max(sol[2] + c0 @ c0, 1e-12))

    from scipy.optimize import least_squares  # imported on first use: it costs 0.6 s at start-up

    def resid(p: np.ndarray) -> np.ndarray:
        return np.hypot(x - p[0], y - p[1]) - p[2]

    res = least_squares(resid, np.array([c0[0], c0[1], r0]), method="lm")
    cx, cy, r = res.x
    return np.array([cx, cy]), abs(float(r))


def circle_params(xy: np.ndarray) -> CircleParams:
    """:class:`CircleParams` of ``(n, 2)`` centres (radius 0 at their mean for fewer than 3)."""
    xy = np.asarray(xy, dtype=float)
    if len(xy) >= 3:
        c, r = fit_circle(xy)
        r = r if math.isfinite(r) else 0.0
    else:
        c, r = xy.mean(axis=0), 0.0
    a0 = math.atan2(xy[0, 1] - c[1], xy[0, 0] - c[0]) if len(xy) else 0.0
    return CircleParams((float(c[0]), float(c[1])), float(r), a0, len(xy))


@dataclass(frozen=True)
class Circle(BasePattern):
    name = "circle"
    keys = (
        "circle", "in a circle", "into a circle", "ring", "in a ring", "circular", "round shape", "around a circle",
        "circle formation", "arrange in a circle", "form a circle", "on a circle", "loop", "hoop", "O shape", "wreath",
        "halo",
    )
    description = "the objects' centres lie evenly spaced on one circle"
    min_objects = 3

    def _slot_angles(self, ctx: Context) -> tuple[np.ndarray, np.ndarray]:
        kappa = ctx.progress.params
        a0, n = kappa.start_angle, kappa.count
        used = set(ctx.progress.slots)
        free = np.array([s for s in range(int(n)) if s not in used], dtype=int)
        return free, a0 + 2 * math.pi * free / n

    def _second(self, ctx: Context, rng: np.random.Generator, n: int) -> np.ndarray:
        """Poses for the second object: a chord away from the first, on a circle that fits."""
        p0 = ctx.state.poses[ctx.progress.placed[0], :2]
        lo, hi = radius_range(ctx)
        m = 4 * n
        k = rng.integers(1, ctx.n // 2 + 1, m)
        r = rng.uniform(lo, hi, m)
        beta = rng.uniform(-math.pi, math.pi, m)
        d = 2 * r * np.sin(k * math.pi / ctx.n)
        p1 = p0 + d[:, None] * np.stack([np.cos(beta), np.sin(beta)], axis=1)
        c1, c2 = _centres(p0, p1, r)
        ok1, ok2 = _fits(ctx, c1, r), _fits(ctx, c2, r)
        keep = ok1 | ok2
        c = np.where(ok1[:, None], c1, c2)
        p1, c = p1[keep][:n], c[keep][:n]
        theta = np.arctan2(p1[:, 1] - c[:, 1], p1[:, 0] - c[:, 0]) + math.pi / 2
        return with_heading(ctx, np.column_stack([p1, theta]))

    def sample(self, ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
        if not ctx.progress.placed:
            if ctx.goal.params.box is None and ctx.goal.params.size is None:
                return with_heading(ctx, uniform_poses(ctx.scene, obj, rng, n))
            return _first(ctx, obj, rng, n)
        if ctx.progress.params is None:
            return self._second(ctx, rng, n)
        kappa = ctx.progress.params
        (cx, cy), r, k = kappa.centre, kappa.radius, kappa.count
        free, angles = self._slot_angles(ctx)
        if len(free) == 0:
            return np.empty((0, 3))
        spread, band = _spread(ctx, r, k), _band(ctx)
        a = rng.choice(angles, n) + np.clip(rng.normal(0, spread / 2, n), -spread, spread)
        rr = r + np.clip(rng.normal(0, band / 2, n), -band, band)
        return with_heading(ctx, np.column_stack([cx + rr * np.cos(a), cy + rr * np.sin(a), a + math.pi / 2]))

    def _density(self, ctx: Context, obj: int, poses: np.ndarray) -> np.ndarray:
        if not ctx.progress.placed:
            return np.ones(len(poses))
        if ctx.progress.params is None:
            p0 = ctx.state.poses[ctx.progress.placed[0], :2]
            lo, hi = radius_range(ctx)
            d = np.hypot(*(poses[:, :2] - p0).T)
            ok = np.zeros(len(poses), dtype=bool)
            for k in range(1, ctx.n // 2 + 1):
                s = 2 * math.sin(k * math.pi / ctx.n)
                r = d / s
                inside = (r >= lo - EDGE_EPS) & (r <= hi + EDGE_EPS)
                if inside.any():
                    c1, c2 = _centres(p0, poses[:, :2], r)
                    ok |= inside & (_fits(ctx, c1, r) | _fits(ctx, c2, r))
            return ok.astype(float)
        kappa = ctx.progress.params
        (cx, cy), r, k = kappa.centre, kappa.radius, kappa.count
        free, angles = self._slot_angles(ctx)
        if len(free) == 0:
            return np.zeros(len(poses))
        d = np.hypot(poses[:, 0] - cx, poses[:, 1] - cy) - r
        a = np.arctan2(poses[:, 1] - cy, poses[:, 0] - cx)
        da = np.abs(wrap_angle(a[:, None] - angles[None, :])).min(axis=1)
        spread, band = _spread(ctx, r, k), _band(ctx)
        ok = (np.abs(d) <= band + EDGE_EPS) & (da <= spread + EDGE_EPS)
        return np.where(ok, np.exp(-0.5 * (d / (band / 2)) ** 2 - 0.5 * (da / (spread / 2)) ** 2), 0.0)

    def commit(self, ctx: Context, obj: int, pose: np.ndarray, rng: np.random.Generator) -> GoalProgress:
        prog = ctx.progress
        if not prog.placed:
            return prog.add(obj, slot=0)
        if prog.params is None:
            first = prog.placed[0]
            p0 = ctx.state.poses[first, :2]
            p1 = np.asarray(pose[:2], dtype=float)
            lo, hi = radius_range(ctx)
            d = float(np.hypot(*(p1 - p0)))
            choices = []
            for k, r in _chord_ks(ctx, d, lo, hi):
                for c in _centres(p0, p1[None], np.array([r])):
                    choices.append((bool(_fits(ctx, c, r)[0]), k, r, c[0]))
            if not choices:  # outside the prior's support: the nearest admissible radius
                k = 1
                r = max(d / (2 * math.sin(math.pi / ctx.n)), lo)
                choices = [(False, k, r, c[0]) for c in _centres(p0, p1[None], np.array([r]))]
            fitting = [ch for ch in choices if ch[0]] or choices
            _, k, r, c = fitting[int(rng.integers(len(fitting)))]
            a0 = math.atan2(p0[1] - c[1], p0[0] - c[0])
            a1 = math.atan2(p1[1] - c[1], p1[0] - c[0])
            step = round(((a1 - a0) % (2 * math.pi)) / (2 * math.pi / ctx.n)) % ctx.n
            params = CircleParams((float(c[0]), float(c[1])), float(r), float(a0), ctx.n)
            return GoalProgress((first, obj), (0, int(step)), params)
        free, angles = self._slot_angles(ctx)
        cx, cy = prog.params.centre
        a = math.atan2(pose[1] - cy, pose[0] - cx)
        da = np.abs(wrap_angle(a - angles))
        return prog.add(obj, slot=int(free[int(np.argmin(da))]))

    def region(self, ctx: Context):
        if ctx.progress.params is None:
            return box_region(ctx)
        (cx, cy), r = ctx.progress.params.centre, ctx.progress.params.radius
        w = ctx.max_radius + BAND
        return shapely.Point(cx, cy).buffer(r + w).difference(shapely.Point(cx, cy).buffer(max(r - w, 0.0)))

    def recover(self, goal, placed, poses, final) -> GoalProgress:
        # kappa fitted to the goal's final centres, slots read from the positions.
        if not placed:
            return GoalProgress()
        c, r = fit_circle(final[list(goal.objects), :2])
        n = len(goal.objects)
        a0 = math.atan2(final[placed[0], 1] - c[1], final[placed[0], 0] - c[0])
        slots = []
        for p in placed:
            a = math.atan2(poses[p, 1] - c[1], poses[p, 0] - c[0])
            slots.append(round(((a - a0) % (2 * math.pi)) / (2 * math.pi / n)) % n)
        params = CircleParams((float(c[0]), float(c[1])), float(r), float(a0), n)
        return GoalProgress(tuple(placed), tuple(slots), params)

    # The finished arrangement (the acceptance rule and what to draw).
    size_word = "radius"

    def size_band(
        self, n: int, rmax: float, room: tuple[float, float, float, float], heading: float | None
    ) -> tuple[float, float]:
        # Neighbours' circles touch at the smallest radius; the largest fits the room.
        w, h = max(room[1] - room[0], 0.0), max(room[3] - room[2], 0.0)
        return max(MIN_CIRCLE_RADIUS, rmax / math.sin(math.pi / max(n, 3))), min(w, h) / 2

    def fit(self, xy: np.ndarray) -> CircleParams:
        return circle_params(xy)

    def accept(self, goal, scene, poses, on) -> str | None:
        xy = goal_xy(goal, scene, poses)
        if len(xy) < 3:
            return "a circle needs at least 3 objects"
        centre, r = fit_circle(xy)
        if not math.isfinite(r) or r < MIN_CIRCLE_RADIUS:
            return f"fitted radius {r:.3f} m is below {MIN_CIRCLE_RADIUS} m"
        err = np.abs(np.hypot(*(xy - centre).T) - r)
        if err.max() > TOL:
            return f"a centre is {err.max():.3f} m off the fitted circle"
        ang = np.sort(np.arctan2(xy[:, 1] - centre[1], xy[:, 0] - centre[0]))
        gaps = np.diff(np.concatenate([ang, ang[:1] + 2 * math.pi]))
        if gaps.max() >= math.pi:
            return f"largest angular gap {math.degrees(gaps.max()):.0f} deg is not below 180 deg"
        return None

    def shape(self, goal, scene, poses) -> tuple[str, dict]:
        xy = goal_xy(goal, scene, poses)
        fitted = fit_json(circle_params(xy))
        if fitted is None:  # a fit that did not converge: nothing to draw but the centres' mean
            return "circle", {"centre": xy.mean(axis=0), "radius": 0.0}
        return self.draw(fitted)

    def draw(self, fitted: dict) -> tuple[str, dict]:
        return "circle", {"centre": np.asarray(fitted["centre"], dtype=float), "radius": float(fitted["radius"])}

    def size(self, fitted: CircleParams) -> float:
        return fitted.radius


register(Circle())
