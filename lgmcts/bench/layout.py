"""Placement helpers of the suite generators: exact non-overlapping footprints
and the arrangements that meet each pattern.

Everything here is rejection sampling with exact polygons (shapely), so an
arrangement the generator accepts is accepted by :mod:`lgmcts.validate`, which
the generators also run on the result.
"""

from __future__ import annotations

import math

import numpy as np
import shapely

from ..formats import RELATIONS, parse_scene
from ..scene import Scene

__all__ = ["Layout", "pattern_poses", "relation_pose", "scene_of"]


def scene_of(workspace: dict, objects: list[dict]) -> Scene:
    """A :class:`Scene` of ``objects`` (dicts with id/name/color/shape), all at the origin.

    Only its footprints and radii are used, never its poses.
    """
    cx = (workspace["x"][0] + workspace["x"][1]) / 2
    cy = (workspace["y"][0] + workspace["y"][1]) / 2
    objs = [{**o, "pose": [cx, cy, 0.0], "on": None} for o in objects]
    return Scene.from_spec(parse_scene({"workspace": workspace, "objects": objs}), overlap_ok=True)


class Layout:
    """Table-level footprints placed so far, kept at least ``gap`` apart (m).

    Parameters
    ----------
    scene : footprints and workspace bounds.
    gap : clearance between footprints (m).
    margin : clearance to the workspace border (m).
    """

    def __init__(self, scene: Scene, *, gap: float = 0.008, margin: float = 0.006) -> None:
        self.scene, self.gap, self.margin = scene, gap, margin
        self.polys: dict[int, shapely.Polygon] = {}
        self.poses: dict[int, np.ndarray] = {}

    def polygon(self, i: int, pose: np.ndarray) -> shapely.Polygon:
        """Footprint of object index ``i`` at ``pose``."""
        return shapely.Polygon(self.scene.footprint(i, np.asarray(pose, dtype=float)))

    def fits(self, i: int, pose: np.ndarray) -> bool:
        """Whether object ``i`` at ``pose`` stays inside and clear of every placed footprint."""
        v = self.scene.footprint(i, np.asarray(pose, dtype=float))
        xmin, xmax, ymin, ymax = self.scene.bounds
        m = self.margin
        if v[:, 0].min() < xmin + m or v[:, 0].max() > xmax - m or v[:, 1].min() < ymin + m or v[:, 1].max() > ymax - m:
            return False
        p = shapely.Polygon(v)
        return all(p.distance(q) > self.gap for k, q in self.polys.items() if k != i)

    def put(self, i: int, pose: np.ndarray) -> None:
        pose = np.asarray(pose, dtype=float)
        self.polys[i] = self.polygon(i, pose)
        self.poses[i] = pose

    def try_put(self, i: int, pose: np.ndarray) -> bool:
        """Place ``i`` at ``pose`` when it fits; report whether it did."""
        if self.fits(i, pose):
            self.put(i, pose)
            return True
        return False

    def random(self, i: int, rng: np.random.Generator, *, tries: int = 300) -> np.ndarray | None:
        """Place ``i`` at a uniformly random free pose; ``None`` when none was found."""
        xmin, xmax, ymin, ymax = self.scene.bounds
        r = float(self.scene.radii[i])
        for _ in range(tries):
            p = np.array(
                [rng.uniform(xmin + r, xmax - r), rng.uniform(ymin + r, ymax - r), rng.uniform(-math.pi, math.pi)]
            )
            if self.try_put(i, p):
                return p
        return None


def pattern_poses(
    kind: str, objs: list[int], scene: Scene, rng: np.random.Generator, *, centre: np.ndarray | None = None
) -> list[np.ndarray]:
    """Poses that put ``objs`` (indices) in a ``line``, ``circle``, ``rectangle`` or ``tower``.

    Spacing adapts to the largest footprint radius so neighbours never touch.
    The centre is random in the inner part of the workspace unless given.
    """
    xmin, xmax, ymin, ymax = scene.bounds
    rmax = float(scene.radii[objs].max())
    n = len(objs)
    if centre is None:
        cx, cy = (xmin + xmax) / 2, (ymin + ymax) / 2
        hw, hh = (xmax - xmin) / 2, (ymax - ymin) / 2
        centre = np.array([cx + rng.uniform(-0.6, 0.6) * hw, cy + rng.uniform(-0.6, 0.6) * hh])
    c = np.asarray(centre, dtype=float)
    yaw = lambda: float(rng.uniform(-math.pi, math.pi))  # noqa: E731
    if kind == "line":
        phi = rng.uniform(-math.pi, math.pi)
        u = np.array([math.cos(phi), math.sin(phi)])
        step = 2 * rmax + rng.uniform(0.015, 0.04)
        return [np.array([*(c + (k - (n - 1) / 2) * step * u), yaw()]) for k in range(n)]
    if kind == "circle":
        r = max(0.07, (2 * rmax + 0.025) / (2 * math.sin(math.pi / n))) * rng.uniform(1.0, 1.25)
        a0 = rng.uniform(-math.pi, math.pi)
        out = []
        for k in range(n):
            a = a0 + 2 * math.pi * k / n
            out.append(np.array([c[0] + r * math.cos(a), c[1] + r * math.sin(a), yaw()]))
        return out
    if kind == "rectangle":
        side = 2 * rmax + 0.03
        h = max(0.08, side) * rng.uniform(1.0, 1.3)
        w = max(0.08, side) * rng.uniform(1.0, 1.6)
        if n >= 5:
            w = max(w, 2 * side)
        if n >= 6:
            h = max(h, 2 * side)
        pts = [(-w / 2, -h / 2), (w / 2, -h / 2), (w / 2, h / 2), (-w / 2, h / 2), (0.0, -h / 2), (0.0, h / 2)][:n]
        if n > 6:
            raise ValueError("rectangles of more than 6 objects are not generated")
        phi = rng.uniform(-math.pi / 2, math.pi / 2)
        cs, sn = math.cos(phi), math.sin(phi)
        return [np.array([c[0] + cs * x - sn * y, c[1] + sn * x + cs * y, yaw()]) for x, y in pts]
    if kind == "tower":
        return [np.array([c[0], c[1], yaw()]) for _ in objs]
    raise ValueError(f"unknown pattern kind {kind}")


def relation_pose(
    relation: str, anchor_pose: np.ndarray, r_anchor: float, r_obj: float, rng: np.random.Generator
) -> np.ndarray:
    """A pose in direction ``relation`` of the anchor: within 26 deg of it, 0.02-0.26 m gap.

    The angular and distance margins keep the pose well inside the
    validator's 45 deg / 0.30 m rule.
    """
    d = RELATIONS[relation]
    a = math.atan2(d[1], d[0]) + rng.uniform(-0.45, 0.45)
    lo = r_anchor + r_obj + 0.02
    rho = rng.uniform(lo, max(lo + 0.01, 0.26))
    return np.array(
        [anchor_pose[0] + rho * math.cos(a), anchor_pose[1] + rho * math.sin(a), rng.uniform(-math.pi, math.pi)]
    )
