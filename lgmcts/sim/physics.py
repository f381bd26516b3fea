"""Reading a simulated scene back: poses, tilts and supports from ``MjData``.

These functions only read ``data``; they never step it.
"""

from __future__ import annotations

import math

import mujoco
import numpy as np

from ..scene import TABLE
from .model import SimModel

__all__ = ["FLOOR", "bottom_contact", "landing", "poses", "speeds", "supports", "tilts", "tops"]

#: Support value meaning "lying on the floor, off the table".
FLOOR = -2
# Contact partner that is neither an object, the table nor the floor.
_OTHER = -3

# A contact counts as "resting on" when its normal is within ~45 deg of vertical.
_VERTICAL = math.cos(math.radians(45.0))


def poses(sim: SimModel, data: mujoco.MjData) -> np.ndarray:
    """``(n, 3)`` footprint pose ``[x, y, yaw]`` of every object (m, rad)."""
    xpos = data.xpos[sim.body]
    xmat = data.xmat[sim.body].reshape(-1, 3, 3)
    yaw = np.arctan2(xmat[:, 1, 0], xmat[:, 0, 0])
    return np.column_stack([xpos[:, 0], xpos[:, 1], yaw])


def tilts(sim: SimModel, data: mujoco.MjData) -> np.ndarray:
    """``(n,)`` angle between each object's up axis and the world's +z (rad)."""
    zz = data.xmat[sim.body][:, 8]
    return np.arccos(np.clip(zz, -1.0, 1.0))


def tops(sim: SimModel, data: mujoco.MjData) -> np.ndarray:
    """``(n,)`` upper bound of each object's highest point (m).

    Exact for upright objects; for tilted ones the bounding sphere of the
    object about its centre keeps the bound safe.
    """
    z = data.xpos[sim.body][:, 2]
    up = tilts(sim, data) < 1e-3
    half = sim.heights / 2
    sphere = np.hypot(half, sim.scene.radii)
    return z + np.where(up, half, sphere)


def speeds(sim: SimModel, data: mujoco.MjData) -> np.ndarray:
    """``(n,)`` largest of linear speed (m/s) and angular speed times 0.05 m."""
    out = np.empty(len(sim.body))
    for k, a in enumerate(sim.qvel_adr):
        v = data.qvel[a : a + 6]
        out[k] = max(math.sqrt(v[0] ** 2 + v[1] ** 2 + v[2] ** 2), 0.05 * math.sqrt(v[3] ** 2 + v[4] ** 2 + v[5] ** 2))
    return out


def _contacts(sim: SimModel, data: mujoco.MjData) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Active contacts as arrays ``(a, b, normal_z)``: ``a``/``b`` are object
    indices, :data:`TABLE` for the table, :data:`FLOOR` for the floor and
    :data:`_OTHER` for anything else."""
    c = data.contact
    if data.ncon == 0:
        empty = np.zeros(0, dtype=int)
        return empty, empty, np.zeros(0)
    keep = c.dist <= 1e-3
    who = sim.geom_who
    return who[c.geom1[keep]], who[c.geom2[keep]], c.frame[keep, 2]


def bottom_contact(sim: SimModel, data: mujoco.MjData, k: int) -> bool:
    """Whether object index ``k`` touches anything below it through a roughly
    horizontal contact surface (the moment a lowered object lands)."""
    a, b, nz = _contacts(sim, data)
    sel = (np.abs(nz) >= _VERTICAL) & ((a == k) | (b == k))
    if not sel.any():
        return False
    other = np.where(a[sel] == k, b[sel], a[sel])
    zk = data.xpos[sim.body[k], 2]
    for j in other.tolist():
        if j in (TABLE, FLOOR) or (j >= 0 and data.xpos[sim.body[j], 2] < zk):
            return True
    return False


def landing(sim: SimModel, data: mujoco.MjData, k: int) -> list[tuple[int, np.ndarray]]:
    """What object index ``k`` touches below it through a roughly horizontal
    contact surface: ``(partner, contact point)`` pairs, the partner an object
    index, :data:`TABLE` or :data:`FLOOR` (the contacts that make
    :func:`bottom_contact` true)."""
    c = data.contact
    if data.ncon == 0:
        return []
    keep = np.flatnonzero(c.dist <= 1e-3)
    who = sim.geom_who
    zk = data.xpos[sim.body[k], 2]
    out = []
    for i in keep.tolist():
        a, b = int(who[c.geom1[i]]), int(who[c.geom2[i]])
        if abs(c.frame[i, 2]) < _VERTICAL or k not in (a, b):
            continue
        j = b if a == k else a
        if j in (TABLE, FLOOR) or (j >= 0 and data.xpos[sim.body[j], 2] < zk):
            out.append((j, np.array(c.pos[i], dtype=float)))
    return out


def supports(sim: SimModel, data: mujoco.MjData) -> tuple[int, ...]:
    """What each object rests on: an object index, :data:`TABLE` or :data:`FLOOR`.

    An object rests on whatever it touches through a roughly horizontal
    contact surface below its centre; when it touches several things, the
    object whose footprint holds its centre wins, then the highest one. An
    object touching nothing below it (still falling) counts as on the table
    when above it and on the floor when below the table top.
    """
    n = len(sim.body)
    z = data.xpos[sim.body][:, 2]
    below: list[set[int]] = [set() for _ in range(n)]
    ca, cb, cnz = _contacts(sim, data)
    for a, b, nz in zip(ca.tolist(), cb.tolist(), cnz.tolist()):
        if abs(nz) < _VERTICAL or a == _OTHER or b == _OTHER:
            continue
        for up, down in ((a, b), (b, a)):
            if up < 0:
                continue
            if down in (TABLE, FLOOR) or z[down] < z[up]:
                below[up].add(down)
    xy = data.xpos[sim.body][:, :2]
    pose = poses(sim, data)
    out = []
    for k in range(n):
        cand = below[k]
        if not cand:
            out.append(_support_by_geometry(sim, k, z, pose))
            continue
        if len(cand) == 1:
            out.append(next(iter(cand)))
            continue
        objs = [j for j in cand if j >= 0]
        holding = [j for j in objs if _contains(sim, j, pose[j], xy[k])]
        if holding:
            out.append(max(holding, key=lambda j: z[j]))
        elif objs:
            out.append(max(objs, key=lambda j: z[j]))
        else:
            out.append(TABLE if TABLE in cand else FLOOR)
    return tuple(out)


def _support_by_geometry(sim: SimModel, k: int, z: np.ndarray, pose: np.ndarray, tol: float = 0.005) -> int:
    h = sim.heights
    bottom = z[k] - h[k] / 2
    best, best_top = TABLE if bottom > -tol else FLOOR, -math.inf
    for j in range(len(z)):
        if j == k:
            continue
        top = z[j] + h[j] / 2
        if abs(top - bottom) < tol and top > best_top and _contains(sim, j, pose[j], pose[k, :2]):
            best, best_top = j, top
    return best


def _contains(sim: SimModel, j: int, pose: np.ndarray, xy: np.ndarray) -> bool:
    verts = sim.scene.footprint(j, pose)
    # Point-in-convex-polygon: the point is left of every counter-clockwise edge.
    e = np.roll(verts, -1, axis=0) - verts
    d = xy - verts
    cross = e[:, 0] * d[:, 1] - e[:, 1] * d[:, 0]
    return bool((cross >= -1e-9).all() or (cross <= 1e-9).all())
