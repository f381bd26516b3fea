"""What the planner knows about a robot arm: where it reaches a top-down grasp.

A :class:`Robot` holds a reachability map computed once from the arm's
inverse kinematics (``python -m lgmcts.sim.arm --write-reach``) and stored
with the package (``robot_ur5e.json``): for each height of the suction cup's
face above the table, the interval of horizontal distances from the base's
axis where the arm reaches a straight-down pose (the shoulder turns a full
circle, so the bearing does not matter). The base stands at the centre of the
workspace's front edge (``-y``, the viewer's side), ``base_gap`` in front of
it, as the simulator mounts it.

A grasp of an object is reachable when the cup can touch the object's top
and rise ``approach`` above it, ``margin`` inside the map's interval at every
height on the way. The planner keeps every pick and every placement
reachable (:func:`reach_mask`), and :func:`plan_reach_problems` names the
actions of a plan that are not.

Needs only numpy: planning never imports the simulator.
"""

from __future__ import annotations

import json
import math
from collections.abc import Sequence
from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

import numpy as np

from .errors import InputError

__all__ = ["ROBOTS", "Robot", "load_robot", "plan_reach_problems"]

#: The robots the planner and simulator know.
ROBOTS = ("ur5e",)
_HERE = Path(__file__).resolve().parent


@dataclass(frozen=True, eq=False)
class Robot:
    """A robot's top-down reach.

    Attributes
    ----------
    name : the robot's name.
    z : ``(m,)`` heights of the cup face above the table top (m), ascending.
    rmin, rmax : ``(m,)`` per height, the reachable interval of horizontal
        distance from the base axis (m); ``nan`` where nothing is reachable.
    base_gap : distance of the base's centre in front of the workspace's
        front edge (m).
    approach : height above an object's top that the cup must also reach
        (the start of the straight approach and the end of the retreat, m).
    margin : the map's intervals are shrunk by this (m), for the map's
        resolution and the arm's tracking error.
    """

    name: str
    z: np.ndarray
    rmin: np.ndarray
    rmax: np.ndarray
    base_gap: float
    approach: float = 0.05
    margin: float = 0.01

    def base(self, bounds: Sequence[float]) -> tuple[float, float]:
        """Table-frame ``(x, y)`` of the base for workspace ``bounds``."""
        xmin, xmax, ymin, _ = bounds
        return ((xmin + xmax) / 2, ymin - self.base_gap)

    def reach_rz(self, r: np.ndarray, z: np.ndarray) -> np.ndarray:
        """Whether a grasp at distance ``r`` from the base axis with the
        object's top at height ``z`` is reachable, approach included."""
        r = np.asarray(r, dtype=float)
        z = np.asarray(z, dtype=float)
        dz = float(self.z[1] - self.z[0])
        lo_i = np.floor(z / dz + 1e-9).astype(int)
        hi_i = np.ceil((z + self.approach) / dz - 1e-9).astype(int)
        ok = (lo_i >= 0) & (hi_i < len(self.z))
        lo_i = np.clip(lo_i, 0, len(self.z) - 1)
        hi_i = np.clip(hi_i, 0, len(self.z) - 1)
        # Tightest interval over the rows the approach passes through.
        need_min = np.full(r.shape, -np.inf)
        need_max = np.full(r.shape, np.inf)
        rmin = np.where(np.isnan(self.rmin), np.inf, self.rmin)
        rmax = np.where(np.isnan(self.rmax), -np.inf, self.rmax)
        for off in range(int((hi_i - lo_i).max(initial=0)) + 1):
            row = np.minimum(lo_i + off, hi_i)
            need_min = np.maximum(need_min, rmin[row])
            need_max = np.minimum(need_max, rmax[row])
        return ok & (r >= need_min + self.margin) & (r <= need_max - self.margin)

    def reachable(self, bounds: Sequence[float], xy: np.ndarray, top: np.ndarray) -> np.ndarray:
        """Mask over points ``xy`` ``(k, 2)`` (table frame) with object tops at
        heights ``top`` ``(k,)``: whether the arm reaches a top-down grasp
        there."""
        bx, by = self.base(bounds)
        xy = np.asarray(xy, dtype=float).reshape(-1, 2)
        r = np.hypot(xy[:, 0] - bx, xy[:, 1] - by)
        return self.reach_rz(r, np.broadcast_to(np.asarray(top, dtype=float), r.shape))

    def highest(self, r: float) -> float:
        """The highest cup-face height reachable at distance ``r`` (m), or
        ``-inf`` when none is."""
        ok = (self.rmin + self.margin <= r) & (r <= self.rmax - self.margin)
        return float(self.z[ok].max()) if ok.any() else -math.inf


@cache
def load_robot(name: str) -> Robot:
    """The :class:`Robot` called ``name`` (one of :data:`ROBOTS`), its map
    read from the package once."""
    if name not in ROBOTS:
        raise InputError(f"unknown robot {name!r} (known: {', '.join(ROBOTS)})")
    data = json.loads((_HERE / f"robot_{name}.json").read_text())
    rows = data["r"]
    rmin = np.array([math.nan if v is None else v[0] for v in rows])
    rmax = np.array([math.nan if v is None else v[1] for v in rows])
    return Robot(name=name, z=np.array(data["z"], dtype=float), rmin=rmin, rmax=rmax, base_gap=float(data["base_gap"]))


def robot_of(robot: str | Robot | None) -> Robot | None:
    """``robot`` as a :class:`Robot` (a name is loaded), or ``None``."""
    if robot is None or isinstance(robot, Robot):
        return robot
    return load_robot(str(robot))


def plan_reach_problems(scene: Any, actions: Sequence[Any], robot: str | Robot) -> list[str]:
    """One line per pick or placement of ``actions`` (plan actions) that
    ``robot`` cannot reach from above, replaying them on ``scene`` (a
    :class:`lgmcts.scene.Scene`)."""
    from .scene import TABLE

    rb = robot_of(robot)
    assert rb is not None
    sc = scene
    world = sc.initial
    out: list[str] = []
    for n, a in enumerate(actions, start=1):
        k = sc.index[a.object]
        top = world.base_z(k) + float(sc.heights[k])
        if not rb.reachable(sc.bounds, world.poses[k, :2][None], np.array([top]))[0]:
            out.append(
                f"action {n}: object {a.object} at ({world.poses[k, 0]:.3f}, {world.poses[k, 1]:.3f}) "
                f"is out of the {rb.name}'s reach"
            )
        on = TABLE if a.on is None else sc.index[a.on]
        world = world.moved(k, np.asarray(a.to, dtype=float), on)
        top = world.base_z(k) + float(sc.heights[k])
        if not rb.reachable(sc.bounds, np.asarray(a.to[:2], dtype=float)[None], np.array([top]))[0]:
            out.append(
                f"action {n}: the place ({a.to[0]:.3f}, {a.to[1]:.3f}) of object {a.object} "
                f"is out of the {rb.name}'s reach"
            )
    return out
