"""Relocation geometry: where an obstacle can be parked, and which parking
spot is best.

Pure functions of a scene, a world state and candidate poses; the
transition that moves the obstacle (:func:`lgmcts.planner.step.relocate`)
draws the candidates and builds the successor state.
"""

from __future__ import annotations

import numpy as np
import shapely

from ..scene import Scene, State

__all__ = ["GRID_STEP", "clear_centres", "region_scores", "snuggest"]

#: Spacing of the grid on which :func:`clear_centres` looks for room (m).
GRID_STEP = 0.01


def clear_centres(scene: Scene, world: State, b: int, clearance: float) -> np.ndarray:
    """Grid points ``(k, 2)`` where object ``b`` fits at any yaw, judged by
    circumscribed circles.

    Conservative: a point is kept only when ``b``'s circumscribed circle
    clears every other object's by ``clearance`` (and the workspace edge by
    half of it), so the footprints there are free without an exact test. On
    a crowded table this finds room that uniform sampling over the workspace
    rarely hits.
    """
    xmin, xmax, ymin, ymax = scene.bounds
    r = float(scene.radii[b]) + clearance / 2
    if xmax - xmin < 2 * r or ymax - ymin < 2 * r:
        return np.empty((0, 2))
    gx = np.arange(xmin + r, xmax - r + 1e-12, GRID_STEP)
    gy = np.arange(ymin + r, ymax - r + 1e-12, GRID_STEP)
    others = np.flatnonzero(np.arange(scene.n) != b)
    cx, cy = world.poses[others, 0], world.poses[others, 1]
    reach2 = (scene.radii[others] + scene.radii[b] + clearance + 1e-9) ** 2
    dx2 = (gx[None, :] - cx[:, None]) ** 2
    dy2 = (gy[None, :] - cy[:, None]) ** 2
    free = np.ones((len(gy), len(gx)), dtype=bool)
    # All objects at once, in chunks that keep the temporary under ~2 MB.
    step = max(1, 250_000 // max(1, free.size))
    for k in range(0, len(others), step):
        s = slice(k, k + step)
        free &= ((dy2[s, :, None] + dx2[s, None, :]) > reach2[s, None, None]).all(axis=0)
    jj, ii = np.nonzero(free)
    return np.stack([gx[ii], gy[jj]], axis=1)


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
