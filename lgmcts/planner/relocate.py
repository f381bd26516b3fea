"""Relocation: moving an obstacle out of the way, and the geometry behind it.

:func:`relocate` is the transition that parks an obstacle on a free table
pose. Where it can be parked (:func:`clear_centres`), how much a spot is in
the way of goals still to be filled (:func:`region_scores`) and which spot
is snuggest (:func:`snuggest`) are pure functions of a scene, a world state
and candidate poses.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import replace

import numpy as np
import shapely

from ..scene import TABLE, Scene, State
from .base import Transition
from .placement import StepOptions, free_mask, make_action, pickable, reachable, wrapped
from .problem import Problem, SearchState, uncommit

__all__ = ["GRID_STEP", "MAX_GRID_CELLS", "clear_centres", "grid_step", "region_scores", "relocate", "snuggest"]

#: Spacing of the grid on which :func:`clear_centres` looks for room (m).
GRID_STEP = 0.01
#: Most points of that grid: a workspace larger than about 5 m x 5 m gets a
#: coarser grid (still conservative, only sparser), so that a huge but legal
#: workspace (the format allows +-1,000 m) costs megabytes, not gigabytes.
MAX_GRID_CELLS = 2**18
#: Largest (objects x grid points) tested in one vectorised pass; beyond it
#: each object clears only the window of points within its reach, which is
#: faster from a few tens of objects on (30 boxes on a 1 m table: 0.8 ms
#: against 1.9 ms) and bounded in memory whatever the workspace.
DENSE_WORK = 150_000


def _points(lo: float, hi: float, step: float) -> int:
    """Length of ``np.arange(lo, hi + 1e-12, step)`` without building it."""
    return max(0, math.ceil((hi + 1e-12 - lo) / step))


def grid_step(xlo: float, xhi: float, ylo: float, yhi: float) -> float:
    """Spacing (m) of the grid of centres over ``[xlo, xhi] x [ylo, yhi]``:
    :data:`GRID_STEP`, or the smallest coarser one (to 1 %) that keeps it
    within :data:`MAX_GRID_CELLS` points."""
    step = GRID_STEP
    if _points(xlo, xhi, step) * _points(ylo, yhi, step) <= MAX_GRID_CELLS:
        return step
    step = max(step, math.sqrt(max(xhi - xlo, 0.0) * max(yhi - ylo, 0.0) / MAX_GRID_CELLS))
    while _points(xlo, xhi, step) * _points(ylo, yhi, step) > MAX_GRID_CELLS:
        step *= 1.01
    return step


def clear_centres(scene: Scene, world: State, b: int, clearance: float) -> np.ndarray:
    """Grid points ``(k, 2)`` where object ``b`` fits at any yaw, judged by
    circumscribed circles, in row-major order (y, then x).

    Conservative: a point is kept only when ``b``'s circumscribed circle
    clears every other object's by ``clearance`` (and the workspace edge by
    half of it), so the footprints there are free without an exact test. On
    a crowded table this finds room that uniform sampling over the workspace
    rarely hits. The grid has :data:`GRID_STEP` spacing and at most
    :data:`MAX_GRID_CELLS` points (:func:`grid_step`); its cost is bounded
    by that, whatever the workspace: every temporary is a window around one
    object, or a chunk of about 2 MB.
    """
    xmin, xmax, ymin, ymax = scene.bounds
    r = float(scene.radii[b]) + clearance / 2
    if xmax - xmin < 2 * r or ymax - ymin < 2 * r:
        return np.empty((0, 2))
    step = grid_step(xmin + r, xmax - r, ymin + r, ymax - r)
    gx = np.arange(xmin + r, xmax - r + 1e-12, step)
    gy = np.arange(ymin + r, ymax - r + 1e-12, step)
    others = np.flatnonzero(np.arange(scene.n) != b)
    cx, cy = world.poses[others, 0], world.poses[others, 1]
    reach2 = (scene.radii[others] + scene.radii[b] + clearance + 1e-9) ** 2
    free = np.ones((len(gy), len(gx)), dtype=bool)
    if len(others) * free.size <= DENSE_WORK:
        dx2 = (gx[None, :] - cx[:, None]) ** 2
        dy2 = (gy[None, :] - cy[:, None]) ** 2
        # All objects at once, in chunks that keep the temporary under ~2 MB.
        chunk = max(1, 250_000 // max(1, free.size))
        for k in range(0, len(others), chunk):
            s = slice(k, k + chunk)
            free &= ((dy2[s, :, None] + dx2[s, None, :]) > reach2[s, None, None]).all(axis=0)
    else:
        _clear_windows(free, gx, gy, cx, cy, reach2, step)
    jj, ii = np.nonzero(free)
    return np.stack([gx[ii], gy[jj]], axis=1)


def _clear_windows(free: np.ndarray, gx: np.ndarray, gy: np.ndarray, cx: np.ndarray, cy: np.ndarray,
                   reach2: np.ndarray, step: float) -> None:
    """Clear, in ``free`` ``(len(gy), len(gx))``, the points within the reach
    of each object (centres ``cx, cy``, squared reaches ``reach2``).

    Each object rules out, on each grid row its reach crosses, one run of
    points: the run is first estimated from the circle's half-chord, then
    its two ends are settled by the arithmetic of the dense test (a point
    is ruled out when ``dy^2 + dx^2 <= reach^2``, which holds on a run of
    consecutive points of a row), so the same points are kept. The runs are
    marked in a difference array and summed along each row: the work grows
    with the rows crossed, not with the points covered. Objects are taken
    in chunks of about 250,000 (object, row) pairs.
    """
    w = len(gx)
    if not w or not len(gy):
        return
    half = np.sqrt(reach2) + step
    y0, y1 = np.searchsorted(gy, cy - half), np.searchsorted(gy, cy + half, side="right")
    live = np.flatnonzero((y1 > y0) & (cx + half >= gx[0]) & (cx - half <= gx[-1]))
    if not len(live):
        return
    marks = np.zeros(len(gy) * (w + 1), dtype=np.int64)
    hmax = int((y1 - y0)[live].max())
    per = max(1, 250_000 // hmax)
    for c in range(0, len(live), per):
        m = live[c:c + per]
        rows = y0[m, None] + np.arange(hmax)
        valid = rows < y1[m, None]
        obj = np.broadcast_to(m[:, None], rows.shape)[valid]
        row = rows[valid]
        dy2 = (gy[row] - cy[obj]) ** 2
        room = reach2[obj] - dy2
        ok = room >= 0
        obj, row, dy2 = obj[ok], row[ok], dy2[ok]
        half_chord = np.sqrt(room[ok])
        ox, r2 = cx[obj], reach2[obj]
        a = np.searchsorted(gx, ox - half_chord)
        b = np.searchsorted(gx, ox + half_chord, side="right")

        def hit(i: np.ndarray, ox: np.ndarray = ox, dy2: np.ndarray = dy2, r2: np.ndarray = r2) -> np.ndarray:
            inside = (i >= 0) & (i < w)
            ic = np.clip(i, 0, w - 1)
            return inside & (dy2 + (gx[ic] - ox) ** 2 <= r2)

        # Settle the ends: a is the first point ruled out, b one past the last (a == b: none on this row).
        while True:
            grow = hit(a - 1)
            a = a - grow
            shrink = (a < b) & ~hit(a)
            a = a + shrink
            if not (grow.any() or shrink.any()):
                break
        while True:
            grow = hit(b)
            b = b + grow
            shrink = (b > a) & ~hit(b - 1)
            b = b - shrink
            if not (grow.any() or shrink.any()):
                break
        run = a < b
        base = row[run] * (w + 1)
        marks += np.bincount(base + a[run], minlength=len(marks))
        marks -= np.bincount(base + b[run], minlength=len(marks))
    covered = np.cumsum(marks.reshape(len(gy), w + 1), axis=1)[:, :w]
    free &= covered == 0


def region_scores(regions: np.ndarray, theirs: np.ndarray, xy: np.ndarray, r: float) -> np.ndarray:
    """Per parking centre in ``xy`` ``(k, 2)``, how much it is in the way of
    the goal regions still to be filled (lower is better).

    Each candidate is judged by its circle of radius ``r`` (the parked
    object's circumscribed circle), whatever its yaw: one point per region
    it meets, plus ``len(regions)`` when it meets a region of the object it
    makes room for (``theirs``), so that one is avoided above all.
    """
    rr = r + 1e-9
    rb = shapely.bounds(regions)
    near = ((xy[:, None, 0] + rr >= rb[None, :, 0]) & (xy[:, None, 0] - rr <= rb[None, :, 2])
            & (xy[:, None, 1] + rr >= rb[None, :, 1]) & (xy[:, None, 1] - rr <= rb[None, :, 3]))
    hit = np.zeros(near.shape, dtype=bool)
    pi, ri = np.nonzero(near)
    if len(pi):
        hit[pi, ri] = shapely.dwithin(regions[ri], shapely.points(xy[pi]), rr)
    return hit.sum(axis=1) + len(regions) * hit[:, theirs].any(axis=1)


def snuggest(scene: Scene, world: State, b: int, xy: np.ndarray) -> int:
    """Index of the centre in ``xy`` ``(k, 2)`` nearest to a neighbour of
    ``b`` or to the workspace edge.

    Parking snugly keeps the free space in one piece, so two objects standing
    on each other's targets later find room to pass.
    """
    xmin, xmax, ymin, ymax = scene.bounds
    others = np.flatnonzero(np.arange(scene.n) != b)
    px, py = xy[:, 0], xy[:, 1]
    gap = np.hypot(px[:, None] - world.poses[others, 0][None, :], py[:, None] - world.poses[others, 1][None, :])
    slack = (gap - scene.radii[others][None, :]).min(axis=1, initial=np.inf)
    slack = np.minimum.reduce([slack, px - xmin, xmax - px, py - ymin, ymax - py])
    return int(np.argmin(slack))


def _goal_regions(problem: Problem, ss: SearchState, mover: int = -1, avoid: int = -1) -> tuple[np.ndarray, np.ndarray]:
    """Regions where the remaining goal objects will go, as a shapely array
    (may be empty), and which of them belong to a goal of ``avoid``.

    A goal of ``mover`` alone is left out: parked over its own target, an
    object is in nobody's way but its own, and it is the next to move there.
    """
    parts, theirs = [], []
    static = problem.static_regions
    for k, g in enumerate(problem.goals):
        if len(ss.progress[k].placed) == len(g.objects) or g.objects == (mover,):
            continue
        reg = static[k] if k in static else problem.patterns[k].region(ss.ctx(problem, k))
        if reg is not None:
            parts.append(reg)
            theirs.append(avoid in g.objects)
    out = np.empty(len(parts), dtype=object)
    out[:] = parts
    return out, np.asarray(theirs, dtype=bool)


def relocate(problem: Problem, ss: SearchState, b: int, rng: np.random.Generator, opts: StepOptions, purpose: str,
             avoid: int = -1) -> Transition | None:
    """Move obstacle ``b`` to a free table pose, outside remaining goal regions when possible.

    ``avoid`` is the object ``b`` is moved for: a pose in the way of its
    goals is taken only when there is no other.
    """
    scene, world = problem.scene, ss.world
    if not pickable(problem, world, b, opts):
        return None
    xmin, xmax, ymin, ymax = scene.bounds
    r = float(scene.radii[b])
    check = replace(opts, obstacles="all")
    target = _off_target(problem, b, avoid)

    def off(poses: np.ndarray) -> np.ndarray:
        return target(poses) & reachable(problem, world, b, poses, opts)

    # Candidates from the grid of clear centres first, then, if it has none
    # (elongated neighbours make it pessimistic), larger uniform batches.
    room = clear_centres(scene, world, b, opts.clearance)
    batches = [2 * opts.samples, 16 * opts.samples]
    if len(room):
        batches.insert(0, -1)
    for n in batches:
        grid = n < 0
        if grid:
            k = 4 * opts.samples
            pick = room[rng.choice(len(room), size=min(len(room), k), replace=False)]
            poses = np.empty((len(pick), 3))
            poses[:, :2] = pick
            n = len(pick)
        else:
            poses = np.empty((n, 3))
            poses[:, 0] = rng.uniform(xmin + r, max(xmin + r, xmax - r), n)
            poses[:, 1] = rng.uniform(ymin + r, max(ymin + r, ymax - r), n)
        poses[:, 2] = np.where(rng.random(n) < 0.5, world.poses[b, 2], rng.uniform(-math.pi, math.pi, n))
        if grid:
            # Circumscribed circles apart by the clearance: free at any yaw.
            free = off(poses)
            if free.any():
                break
            continue
        free = free_mask(problem, ss, b, poses, check) & off(poses)
        if free.any():
            break
    else:
        # No room with the clearance anywhere: park touching neighbours.
        poses = _contact_spots(problem, ss, b, rng, check, off)
        if not len(poses):
            return None
        free = np.ones(len(poses), dtype=bool)
    idx = np.flatnonzero(free)
    regions, theirs = _goal_regions(problem, ss, b, avoid)
    if len(regions):
        # The free pose that overlaps the fewest regions still to be filled
        # (none, when there is one), so the obstacle is not in the way again;
        # above all not in the way of the object it makes room for.
        score = region_scores(regions, theirs, poses[idx, :2], r)
        idx = idx[score == score.min()]
    if len(idx) > 1:
        # Of the best, the snuggest (see :func:`.relocate.snuggest`).
        idx = idx[[snuggest(scene, world, b, poses[idx, :2])]]
    pose = wrapped(poses[idx[0]])
    new_world = world.moved(b, pose, TABLE)
    act = make_action(scene, b, pose, None, purpose)
    return Transition(act, SearchState(new_world, uncommit(problem, ss.progress, b)))


def _off_target(problem: Problem, b: int, avoid: int) -> Callable[[np.ndarray], np.ndarray]:
    """A mask function over poses ``(k, 3)`` of ``b``: whether ``b`` there
    leaves ``avoid``'s fixed target free (its circle, or its circumscribed
    circle for other shapes, at most touching the target's). All true when
    ``avoid`` has no fixed target: parking on a fixed target would not make
    the room the move is for, so such a spot is never taken."""
    if avoid not in problem.fixed:
        return lambda poses: np.ones(len(poses), dtype=bool)
    sc = problem.scene
    t = problem.fixed[avoid][:2]
    both = sc.discs[b] > 0 and sc.discs[avoid] > 0
    reach = float(sc.discs[b] + sc.discs[avoid]) if both else float(sc.radii[b] + sc.radii[avoid])
    return lambda poses: np.hypot(poses[:, 0] - t[0], poses[:, 1] - t[1]) >= reach - 1e-9


def _contact_spots(problem: Problem, ss: SearchState, b: int, rng: np.random.Generator, opts: StepOptions,
                   keep) -> np.ndarray:
    """Poses ``(k, 3)`` where ``b`` fits at most touching other objects and
    the workspace edge, and that pass the mask function ``keep``: grid
    centres whose circumscribed circles do not overlap, else uniform draws
    that pass the contact test."""
    scene, world = problem.scene, ss.world
    xmin, xmax, ymin, ymax = scene.bounds
    r = float(scene.radii[b])
    room = clear_centres(scene, world, b, 0.0)
    if len(room):
        poses = np.empty((len(room), 3))
        poses[:, :2] = room
        poses[:, 2] = world.poses[b, 2]
        poses = poses[keep(poses)]
        if len(poses):
            return poses[rng.choice(len(poses), size=min(len(poses), 4 * opts.samples), replace=False)]
    n = 16 * opts.samples
    poses = np.empty((n, 3))
    poses[:, 0] = rng.uniform(xmin + r, max(xmin + r, xmax - r), n)
    poses[:, 1] = rng.uniform(ymin + r, max(ymin + r, ymax - r), n)
    poses[:, 2] = world.poses[b, 2]
    keep_mask = keep(poses)
    poses = poses[keep_mask]
    return poses[free_mask(problem, ss, b, poses, opts, contact=True)] if len(poses) else poses

