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

A goal's facing sets every object's yaw and turns the first side along or
across the heading; a size draws the first side from its band (the other
side no longer than it, so the first is the longer); a region keeps the
corners inside it.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely

from ..tolerances import MIN_RECT_SIDE, TOL
from .base import (
    BAND,
    CLEARANCE,
    EDGE_EPS,
    BasePattern,
    Context,
    GoalProgress,
    box_region,
    goal_xy,
    params_mask,
    register,
    start_poses,
    uniform_poses,
    with_heading,
)
from .line import fit_line

#: How far inside a named size band the longer side stays (m).
SIZE_MARGIN = 0.004
#: Largest angle off the heading's axes of the second object's direction, for an object already there (rad).
DIR_EPS = 0.02

#: Corner positions in units of (w/2, h/2), counter-clockwise from front-left.
_CORNERS = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])


def _rot(phi: float) -> np.ndarray:
    c, s = math.cos(phi), math.sin(phi)
    return np.array([[c, -s], [s, c]])


def corners(params: RectangleParams) -> np.ndarray:
    """``(4, 2)`` corner positions of rectangle ``params``, counter-clockwise from corner 0."""
    (cx, cy), w, h, phi = params.centre, params.width, params.height, params.angle
    return np.array([cx, cy]) + (_CORNERS * [w / 2, h / 2]) @ _rot(phi).T


# ---------------------------------------------------------------- kappa and the finished rectangle


@dataclass(frozen=True)
class RectangleParams:
    """kappa of a rectangle: its ``centre``, ``width`` (the first side, from
    corner 0 to corner 1), ``height`` and the first side's ``angle`` (rad)."""

    centre: tuple[float, float]
    width: float
    height: float
    angle: float

    @property
    def corners(self) -> np.ndarray:
        return corners(self)


def _shapely_corners(xy: np.ndarray) -> np.ndarray | None:
    """``(4, 2)`` corners of the minimum-area rectangle around ``xy``, ``None`` when collinear."""
    rect = shapely.MultiPoint(np.asarray(xy, dtype=float)).minimum_rotated_rectangle
    if rect.geom_type != "Polygon":
        return None
    return np.asarray(rect.exterior.coords)[:4]


def fit_rectangle(xy: np.ndarray) -> RectangleParams | None:
    """The minimum-area rectangle around ``(n, 2)`` centres, ``None`` when they are collinear."""
    cs = _shapely_corners(xy)
    if cs is None:
        return None
    e1, e2 = cs[1] - cs[0], cs[2] - cs[1]
    ctr = cs.mean(axis=0)
    return RectangleParams(
        (float(ctr[0]), float(ctr[1])), float(np.hypot(*e1)), float(np.hypot(*e2)), math.atan2(e1[1], e1[0])
    )


@dataclass(frozen=True)
class Rectangle(BasePattern):
    name = "rectangle"
    keys = (
        "rectangle",
        "in a rectangle",
        "into a rectangle",
        "rectangular",
        "square",
        "square border",
        "box shape",
        "rectangular frame",
        "perimeter of a rectangle",
        "border of a square",
        "arrange in a rectangle",
        "oblong",
        "corners of a rectangle",
        "corners of a square",
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
        gp = ctx.goal.params
        if gp.box is not None:
            x0, x1, y0, y1 = gp.box
            side_max = min(side_max, max(x1 - x0, y1 - y0))
        if gp.size is not None:
            # The first side is the longer one: drawn from the size band.
            blo, bhi = gp.size
            m = 0.0 if blo == bhi else min(SIZE_MARGIN, (bhi - blo) / 4) if math.isfinite(bhi) else SIZE_MARGIN
            top = min(max(x1 - x0, y1 - y0) if gp.box is not None else room, room)
            lo2, hi2 = max(side_min, blo + m), min(top, bhi - m)
            if lo2 > hi2:
                lo2 = hi2 = max(side_min, min(blo, top))
            return lo2, hi2, per_min
        return side_min, max(side_min, side_max), per_min

    def _fits_second(self, ctx: Context, p0: np.ndarray, p1: np.ndarray) -> np.ndarray:
        """Whether, with the first corner at ``p0`` and the second at each of
        ``p1`` (``(m, 2)``), the rectangle of least other side fits in the
        room on one side of that edge (used with a region)."""
        _lo, _hi, per_min = self._sizes(ctx)
        side_min = max(0.06, 2 * ctx.max_radius + CLEARANCE + 2 * BAND + 0.004)
        x0, x1, y0, y1 = self._room(ctx)
        e = p1 - p0
        w = np.hypot(e[:, 0], e[:, 1])
        u = e / np.maximum(w, 1e-12)[:, None]
        h = np.maximum(side_min, per_min / 2 - w)
        ok = np.zeros(len(p1), dtype=bool)
        for side in (1.0, -1.0):
            v = side * np.stack([-u[:, 1], u[:, 0]], axis=1)
            cs = np.stack([p0 + h[:, None] * v, p1 + h[:, None] * v], axis=1)
            ok |= (
                (cs[..., 0] >= x0 - EDGE_EPS)
                & (cs[..., 0] <= x1 + EDGE_EPS)
                & (cs[..., 1] >= y0 - EDGE_EPS)
                & (cs[..., 1] <= y1 + EDGE_EPS)
            ).all(axis=1)
        return ok

    def _room(self, ctx: Context) -> tuple[float, float, float, float]:
        """Where corners may go: the workspace less the largest radius, cut to the region."""
        xmin, xmax, ymin, ymax = ctx.scene.bounds
        m = ctx.max_radius + 0.001
        x0, x1, y0, y1 = xmin + m, xmax - m, ymin + m, ymax - m
        box = ctx.goal.params.box
        if box is not None:
            x0, x1, y0, y1 = max(x0, box[0]), min(x1, box[1]), max(y0, box[2]), min(y1, box[3])
        return x0, x1, y0, y1

    def _first(self, ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
        """Poses for the first object of a goal with a region or size: a corner
        of a rectangle of admissible sides that fits in the room."""
        lo, hi, per_min = self._sizes(ctx)
        side_min = max(0.06, 2 * ctx.max_radius + CLEARANCE + 2 * BAND + 0.004)
        x0, x1, y0, y1 = self._room(ctx)
        heading = ctx.goal.params.heading
        w = rng.uniform(lo, hi, n)
        h = np.maximum(side_min, per_min / 2 - w)
        if heading is not None:
            phi = heading + rng.integers(0, 4, n) * (math.pi / 2)
        else:
            phi = np.where(
                rng.random(n) < 0.5, rng.integers(0, 4, n) * (math.pi / 2), rng.uniform(-math.pi, math.pi, n)
            )
        side = np.where(rng.random(n) < 0.5, 1.0, -1.0)
        u = np.stack([np.cos(phi), np.sin(phi)], axis=1)
        v = side[:, None] * np.stack([-u[:, 1], u[:, 0]], axis=1)
        offs = np.stack([np.zeros_like(u), w[:, None] * u, w[:, None] * u + h[:, None] * v, h[:, None] * v], axis=1)
        sx0, sx1 = x0 - offs[:, :, 0].min(axis=1), x1 - offs[:, :, 0].max(axis=1)
        sy0, sy1 = y0 - offs[:, :, 1].min(axis=1), y1 - offs[:, :, 1].max(axis=1)
        ok = (sx0 <= sx1) & (sy0 <= sy1)
        if not ok.any():
            return start_poses(ctx, obj, rng, n)
        xy = np.column_stack([rng.uniform(sx0[ok], sx1[ok]), rng.uniform(sy0[ok], sy1[ok])])
        return with_heading(ctx, np.column_stack([xy, phi[ok]]))

    def sample(self, ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
        gp = ctx.goal.params
        if not ctx.progress.placed:
            if gp.box is not None or gp.size is not None:
                return self._first(ctx, obj, rng, n)
            if gp.empty:
                out = uniform_poses(ctx.scene, obj, rng, n)
                out[rng.random(n) < 0.5, 2] = 0.0
                return out
            out = start_poses(ctx, obj, rng, n)
            if gp.heading is None:
                out[rng.random(len(out)) < 0.5, 2] = 0.0
            return out
        if ctx.progress.params is None:
            first = ctx.state.poses[ctx.progress.placed[0]]
            lo, hi, _ = self._sizes(ctx)
            d = rng.uniform(lo, hi, n)
            if gp.heading is not None:
                a = gp.heading + rng.integers(0, 4, n) * (math.pi / 2)
            else:
                a = np.where(
                    rng.random(n) < 0.5,
                    first[2] + rng.integers(0, 4, n) * (math.pi / 2),
                    rng.uniform(-math.pi, math.pi, n),
                )
            xy = first[:2] + d[:, None] * np.stack([np.cos(a), np.sin(a)], axis=1)
            out = with_heading(ctx, np.column_stack([xy, a]))
            if gp.box is None:
                return out
            return out[params_mask(ctx, obj, out) & self._fits_second(ctx, first[:2], out[:, :2])]
        kappa = ctx.progress.params
        (cx, cy), w, h, phi = kappa.centre, kappa.width, kappa.height, kappa.angle
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
        return with_heading(ctx, np.asarray(rows, dtype=float).reshape(-1, 3))

    def _local(self, ctx: Context, poses: np.ndarray) -> np.ndarray:
        kappa = ctx.progress.params
        (cx, cy), phi = kappa.centre, kappa.angle
        return (poses[:, :2] - [cx, cy]) @ _rot(phi)

    def _density(self, ctx: Context, obj: int, poses: np.ndarray) -> np.ndarray:
        if not ctx.progress.placed:
            return np.ones(len(poses))
        if ctx.progress.params is None:
            lo, hi, _ = self._sizes(ctx)
            v = poses[:, :2] - ctx.state.poses[ctx.progress.placed[0], :2]
            d = np.hypot(*v.T)
            ok = (d >= lo - EDGE_EPS) & (d <= hi + EDGE_EPS)
            heading = ctx.goal.params.heading
            if heading is not None:
                a = np.arctan2(v[:, 1], v[:, 0])
                off = (a - heading) % (math.pi / 2)
                ok &= np.minimum(off, math.pi / 2 - off) <= DIR_EPS
            if ctx.goal.params.box is not None:
                ok &= self._fits_second(ctx, ctx.state.poses[ctx.progress.placed[0], :2], poses[:, :2])
            return ok.astype(float)
        kappa = ctx.progress.params
        (_cx, _cy), w, h, _phi = kappa.centre, kappa.width, kappa.height, kappa.angle
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
            side_min = max(0.06, 2 * ctx.max_radius + CLEARANCE + 2 * BAND + 0.004)
            h_lo = max(side_min if ctx.goal.params.size is not None else lo, per_min / 2 - w)
            h_hi = min(h_lo + 0.05, w) if ctx.goal.params.size is not None else h_lo + 0.05
            xmin, xmax, ymin, ymax = ctx.scene.bounds
            m = ctx.max_radius + 0.001
            box = ctx.goal.params.box
            if box is not None:
                xmin, xmax = max(xmin, box[0] - m), min(xmax, box[1] + m)
                ymin, ymax = max(ymin, box[2] - m), min(ymax, box[3] + m)
            best = None
            for attempt in range(26):
                h = rng.uniform(h_lo, max(h_lo, h_hi)) if attempt < 16 else h_lo
                side = 1.0 if rng.random() < 0.5 else -1.0
                if attempt >= 24:  # last, both sides at the least other side
                    side = 1.0 if attempt == 24 else -1.0
                v = side * np.array([-u[1], u[0]])
                c = p0 + (w / 2) * u + (h / 2) * v
                params = RectangleParams((float(c[0]), float(c[1])), float(w), float(h), float(phi))
                cs = corners(params)
                slots = (0, 1) if side > 0 else (3, 2)
                best = (params, slots)
                if (
                    (cs[:, 0] >= xmin + m) & (cs[:, 0] <= xmax - m) & (cs[:, 1] >= ymin + m) & (cs[:, 1] <= ymax - m)
                ).all():
                    break
            params, slots = best  # type: ignore[misc]
            return GoalProgress((first, obj), slots, params)
        free, _extras = self._state(ctx)
        cs = corners(prog.params)
        for s in free:
            if math.hypot(*(np.asarray(pose[:2]) - cs[s])) <= 1e-3:
                return prog.add(obj, slot=s)
        return prog.add(obj, slot=4 + len(prog.placed))

    def region(self, ctx: Context):
        if ctx.progress.params is None:
            return box_region(ctx)
        ring = shapely.LinearRing(corners(ctx.progress.params))
        return ring.buffer(ctx.max_radius + BAND)

    def recover(self, goal, placed, poses, final) -> GoalProgress:
        # kappa fitted to the goal's final centres; a placed object near a corner holds it.
        params = fit_rectangle(final[list(goal.objects), :2])
        if not placed or params is None:
            return super().recover(goal, placed, poses, final)
        at = corners(params)
        slots = []
        for j, p in enumerate(placed):
            d = np.hypot(*(at - poses[p, :2]).T)
            slots.append(int(np.argmin(d)) if d.min() <= 0.01 else 4 + j)
        return GoalProgress(tuple(placed), tuple(slots), params)

    # The finished arrangement (the acceptance rule and what to draw).
    size_word = "longer side"

    def size_band(
        self, n: int, rmax: float, room: tuple[float, float, float, float], heading: float | None
    ) -> tuple[float, float]:
        # The perimeter holds all n objects at the shortest; the room's longer side at the longest.
        w, h = max(room[1] - room[0], 0.0), max(room[3] - room[2], 0.0)
        return max(MIN_RECT_SIDE, n * rmax / 2), max(w, h)

    def fit(self, xy: np.ndarray) -> RectangleParams | None:
        return fit_rectangle(xy)

    def accept(self, goal, scene, poses, on) -> str | None:
        xy = goal_xy(goal, scene, poses)
        if len(xy) < 4:
            return "a rectangle needs at least 4 objects"
        cs = _shapely_corners(xy)
        if cs is None:
            return "centres are collinear"
        sides = np.linalg.norm(np.roll(cs, -1, axis=0) - cs, axis=1)
        if sides.min() < MIN_RECT_SIDE:
            return f"rectangle side {sides.min():.3f} m is below {MIN_RECT_SIDE} m"
        segs = [shapely.LineString([cs[k], cs[(k + 1) % 4]]) for k in range(4)]
        pts = shapely.points(xy)
        d = np.stack([shapely.distance(pts, s) for s in segs], axis=1)  # (n, 4)
        if d.min(axis=1).max() > TOL:
            return f"a centre is {d.min(axis=1).max():.3f} m off the rectangle's perimeter"
        if not (d <= TOL).any(axis=0).all():
            return "a side of the rectangle holds no object"
        return None

    def shape(self, goal, scene, poses) -> tuple[str, dict]:
        xy = goal_xy(goal, scene, poses)
        cs = _shapely_corners(xy)
        if cs is not None:
            return "rectangle", {"corners": cs}
        # Collinear centres: the degenerate rectangle drawn as their segment.
        a, b = np.asarray(fit_line(xy).ends)
        return "rectangle", {"corners": np.stack([a, b, b, a])}

    def draw(self, fitted: dict) -> tuple[str, dict] | None:
        p = RectangleParams(tuple(fitted["centre"]), fitted["width"], fitted["height"], fitted["angle"])
        return "rectangle", {"corners": corners(p)}

    def size(self, fitted: RectangleParams | None) -> float:
        return 0.0 if fitted is None else max(fitted.width, fitted.height)

    def facing_axis(self, fitted: RectangleParams | None) -> tuple[float, float, str] | None:
        if fitted is None:
            return None
        return fitted.angle, math.pi / 2, "the rectangle's sides are {deg:.0f} deg off facing '{facing}'"


register(Rectangle())
