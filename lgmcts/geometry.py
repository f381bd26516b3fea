"""Pure, vectorised 2-D geometry of footprints (metres, radians).

A footprint is a convex polygon given in the object frame as an ``(k, 2)``
array of counter-clockwise vertices around the footprint centre. Poses are
``(x, y, theta)``. Functions take batches where that pays: ``(m, 3)`` poses
give ``(m, k, 2)`` vertex arrays and shapely 2 geometry arrays, so collision
and containment of many candidate placements cost one vectorised call.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from functools import lru_cache

import numpy as np
import shapely
from shapely import STRtree

__all__ = [
    "CIRCLE_SEGMENTS",
    "box_footprint",
    "circle_footprint",
    "colliding",
    "colliding_near",
    "convex_footprint",
    "inside_workspace",
    "lens_area",
    "overlap_pairs",
    "overlapping",
    "place_each",
    "polygons",
    "radius_of",
    "transform",
    "wrap_angle",
]

#: A cylinder's footprint is the regular polygon of this many sides that
#: circumscribes its circle, so the polygon is never smaller than the object.
CIRCLE_SEGMENTS = 24
#: Rounding allowance (m) of :func:`inside_workspace`.
EDGE_EPS = 1e-9


def box_footprint(sx: float, sy: float) -> np.ndarray:
    """Corners of an ``sx`` by ``sy`` rectangle centred at the origin, CCW."""
    hx, hy = sx / 2.0, sy / 2.0
    return np.array([[-hx, -hy], [hx, -hy], [hx, hy], [-hx, hy]], dtype=float)


def circle_footprint(radius: float, segments: int = CIRCLE_SEGMENTS) -> np.ndarray:
    """Regular polygon circumscribing a circle of ``radius``, CCW (read-only: scenes of equal discs share it)."""
    return _circle(float(radius), int(segments))


@lru_cache(maxsize=1024)
def _circle(radius: float, segments: int) -> np.ndarray:
    a = np.arange(segments) * (2 * math.pi / segments) + math.pi / segments
    r = radius / math.cos(math.pi / segments)
    out = np.stack([r * np.cos(a), r * np.sin(a)], axis=1)
    out.setflags(write=False)
    return out


def convex_footprint(points: np.ndarray) -> np.ndarray:
    """Convex hull of ``(n, 2)`` points as CCW vertices (no repeated end)."""
    hull = shapely.MultiPoint(np.asarray(points, dtype=float)[:, :2]).convex_hull
    hull = (
        shapely.orient_polygons(hull) if hasattr(shapely, "orient_polygons") else shapely.geometry.polygon.orient(hull)
    )
    return np.asarray(hull.exterior.coords, dtype=float)[:-1]


def transform(local: np.ndarray, poses: np.ndarray) -> np.ndarray:
    """Place object-frame vertices at poses.

    Parameters
    ----------
    local : (k, 2) vertices in the object frame; with ``(m, 3)`` poses also
        ``(m, k, 2)``, one footprint per pose.
    poses : (3,) or (m, 3) poses ``(x, y, theta)``.

    Returns
    -------
    (k, 2) or (m, k, 2) vertices in the table frame.
    """
    poses = np.asarray(poses, dtype=float)
    if poses.ndim == 1:
        # One pose (the common case when a state moves an object): a 2x2 product.
        c, s = math.cos(poses[2]), math.sin(poses[2])
        return local @ np.array([[c, s], [-s, c]]) + poses[:2]
    p = poses.reshape(-1, 3)
    c, s = np.cos(p[:, 2])[:, None], np.sin(p[:, 2])[:, None]
    lx, ly = local[..., 0], local[..., 1]
    return np.stack([c * lx - s * ly + p[:, 0:1], s * lx + c * ly + p[:, 1:2]], axis=-1)


def place_each(local: Sequence[np.ndarray], poses: np.ndarray) -> tuple[list[np.ndarray], np.ndarray]:
    """Footprint ``local[k]`` at ``poses[k]`` for every ``k``: the table-frame
    vertices and the shapely polygons (an object array), built in one
    vectorised pass per vertex count."""
    poses = np.asarray(poses, dtype=float).reshape(-1, 3)
    verts: list[np.ndarray] = [np.empty((0, 2))] * len(local)
    polys = np.empty(len(local), dtype=object)
    groups: dict[int, list[int]] = {}
    for k, lf in enumerate(local):
        groups.setdefault(len(lf), []).append(k)
    for ks in groups.values():
        v = transform(np.stack([local[k] for k in ks]), poses[ks])  # (m, v, 2)
        polys[ks] = shapely.polygons(v)
        for j, k in enumerate(ks):
            verts[k] = v[j]
    return verts, polys


def polygons(vertices: np.ndarray) -> np.ndarray:
    """Shapely polygons from ``(m, k, 2)`` vertex arrays (one call)."""
    return shapely.polygons(np.asarray(vertices, dtype=float))


def inside_workspace(vertices: np.ndarray, bounds: Sequence[float], margin: float = 0.0) -> np.ndarray:
    """Whether every vertex lies in ``bounds = (xmin, xmax, ymin, ymax)`` shrunk by ``margin``.

    ``vertices`` is ``(m, k, 2)``; returns a boolean ``(m,)``. Because the
    workspace is convex, a convex footprint is inside it exactly when all its
    vertices are. A vertex within :data:`EDGE_EPS` of the edge counts as on it
    (rounding of the footprint's vertices; a disc whose circle touches the
    edge is inside).
    """
    v = np.asarray(vertices)
    xmin, xmax, ymin, ymax = bounds
    x, y = v[..., 0], v[..., 1]
    m = margin - EDGE_EPS
    ok = (x >= xmin + m) & (x <= xmax - m) & (y >= ymin + m) & (y <= ymax - m)
    return np.asarray(ok.all(axis=-1))


def radius_of(local: np.ndarray) -> float:
    """Largest distance from the footprint centre to a vertex (m)."""
    return float(np.sqrt((np.asarray(local) ** 2).sum(axis=1)).max())


def wrap_angle(a: np.ndarray | float) -> np.ndarray | float:
    """Wrap angles to ``[-pi, pi)``."""
    return (np.asarray(a) + math.pi) % (2 * math.pi) - math.pi


def colliding(tree: STRtree, candidates: np.ndarray, clearance: float) -> tuple[np.ndarray, np.ndarray]:
    """Pairs ``(candidate index, obstacle index)`` closer than ``clearance``.

    ``tree`` indexes the obstacle polygons; ``candidates`` is an array of
    shapely polygons. A ``clearance`` of 0 reports touching or overlapping
    pairs.
    """
    if clearance > 0:
        pairs = tree.query(candidates, predicate="dwithin", distance=clearance)
    else:
        pairs = tree.query(candidates, predicate="intersects")
    return pairs[0], pairs[1]


def colliding_near(
    candidates: np.ndarray | None,
    cand_xy: np.ndarray,
    cand_r: np.ndarray | float,
    obstacles: np.ndarray,
    obs_xy: np.ndarray,
    obs_r: np.ndarray,
    clearance: float,
    *,
    cand_disc: np.ndarray | float | None = None,
    obs_disc: np.ndarray | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """Pairs ``(candidate index, obstacle index)`` closer than ``clearance``, as
    :func:`colliding`, without an R-tree.

    Each shape comes with a bounding circle (centre ``*_xy``, radius
    ``*_r``); only the pairs whose circles come within ``clearance`` are
    tested exactly, elementwise. Cheaper than building a tree for a state
    queried a few times. Pairs are sorted by candidate, then obstacle.

    With ``cand_disc`` and ``obs_disc`` (true circle radii, 0 for shapes that
    are not discs), a pair of discs is decided on the circles themselves
    (centre distance at most the radii plus ``clearance``), without the
    polygons; ``candidates`` may then be ``None`` when every pair is one of
    discs.
    """
    cand_xy = np.asarray(cand_xy, dtype=float).reshape(-1, 2)
    d2 = (cand_xy[:, None, 0] - obs_xy[None, :, 0]) ** 2 + (cand_xy[:, None, 1] - obs_xy[None, :, 1]) ** 2
    reach = np.asarray(cand_r, dtype=float).reshape(-1, 1) + obs_r[None, :] + clearance + 1e-9
    ci, oi = np.nonzero(d2 <= reach**2)
    if len(ci) and cand_disc is not None and obs_disc is not None:
        cd = np.broadcast_to(np.asarray(cand_disc, dtype=float).reshape(-1), (len(cand_xy),))[ci]
        od = np.asarray(obs_disc, dtype=float)[oi]
        disc = (cd > 0) & (od > 0)
        if disc.any():
            hit = np.ones(len(ci), dtype=bool)
            hit[disc] = d2[ci[disc], oi[disc]] <= (cd[disc] + od[disc] + clearance + 1e-12) ** 2
            rest = np.flatnonzero(~disc)
            if len(rest):
                assert candidates is not None, "candidates are needed for pairs that are not both discs"
                if clearance > 0:
                    hit[rest] = shapely.dwithin(candidates[ci[rest]], obstacles[oi[rest]], clearance)
                else:
                    hit[rest] = shapely.intersects(candidates[ci[rest]], obstacles[oi[rest]])
            return ci[hit], oi[hit]
    if len(ci):
        assert candidates is not None, "candidates are needed for pairs that are not both discs"
        if clearance > 0:
            hit = shapely.dwithin(candidates[ci], obstacles[oi], clearance)
        else:
            hit = shapely.intersects(candidates[ci], obstacles[oi])
        ci, oi = ci[hit], oi[hit]
    return ci, oi


def overlapping(
    a_polys: np.ndarray,
    a_xy: np.ndarray,
    a_disc: np.ndarray,
    b_polys: np.ndarray,
    b_xy: np.ndarray,
    b_disc: np.ndarray,
    max_area: float,
) -> np.ndarray:
    """Elementwise, whether shape pairs overlap by more than legal contact.

    Pairs of discs (both ``*_disc`` radii > 0, m) overlap when their true
    circles do (centre distance below the sum of radii, less 1e-9 m); other
    pairs when their polygons' intersection is larger than ``max_area`` (m²).
    Touching shapes do not overlap. Arrays are ``(k,)`` (polygons, radii) and
    ``(k, 2)`` (centres).
    """
    a_xy, b_xy = np.asarray(a_xy, dtype=float).reshape(-1, 2), np.asarray(b_xy, dtype=float).reshape(-1, 2)
    a_disc, b_disc = np.asarray(a_disc, dtype=float), np.asarray(b_disc, dtype=float)
    out = np.zeros(len(a_xy), dtype=bool)
    discs = (a_disc > 0) & (b_disc > 0)
    if discs.any():
        d = np.hypot(*(a_xy[discs] - b_xy[discs]).T)
        out[discs] = d < a_disc[discs] + b_disc[discs] - 1e-9
    poly = np.flatnonzero(~discs)
    if len(poly):
        out[poly] = shapely.area(shapely.intersection(a_polys[poly], b_polys[poly])) > max_area
    return out


def circle_crossings(cen: np.ndarray, rad: np.ndarray, a: np.ndarray, b: np.ndarray
                     ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Where circles ``a[k]`` and ``b[k]`` (centres ``cen``, radii ``rad``) cross: ``(plus, minus, a, b)``, the two
    crossing points of each pair that crosses (one to each side of the line from ``a`` to ``b``) and those pairs.
    Pairs that are concentric, apart or nested have no crossing and are left out."""
    v = cen[b] - cen[a]
    dd = np.hypot(v[:, 0], v[:, 1])
    ra, rb = rad[a], rad[b]
    ok = (dd > 1e-12) & (dd < ra + rb) & (dd > np.abs(ra - rb))
    a, b, v, dd, ra, rb = a[ok], b[ok], v[ok], dd[ok], ra[ok], rb[ok]
    x = (dd * dd + ra * ra - rb * rb) / (2 * dd)
    h = np.sqrt(np.maximum(ra * ra - x * x, 0.0))
    u = v / dd[:, None]
    nrm = np.stack([-u[:, 1], u[:, 0]], axis=1) * h[:, None]
    base = cen[a] + u * x[:, None]
    return base + nrm, base - nrm, a, b


def lens_area(r1: float, r2: float, d: float) -> float:
    """Area (m²) shared by two circles of radii ``r1``, ``r2`` whose centres are ``d`` apart.

    Cylinder footprints are polygons circumscribing the circle, so two touching
    cylinders overlap as polygons by a sliver; their contact is judged here.
    """
    if d >= r1 + r2:
        return 0.0
    if d <= abs(r1 - r2):
        return math.pi * min(r1, r2) ** 2
    a1 = r1 * r1 * math.acos(max(-1.0, min(1.0, (d * d + r1 * r1 - r2 * r2) / (2 * d * r1))))
    a2 = r2 * r2 * math.acos(max(-1.0, min(1.0, (d * d + r2 * r2 - r1 * r1) / (2 * d * r2))))
    k = 0.5 * math.sqrt(max(0.0, (-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2)))
    return a1 + a2 - k


def overlap_pairs(polys: np.ndarray, discs: np.ndarray, xy: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Pairs ``a < b`` of footprints that meet, and the area each pair shares (m²).

    ``polys`` is an object array of polygons, ``discs`` each one's true circle
    radius (m, 0 for a non-cylinder) and ``xy`` its ``(n, 2)`` centre. Two
    cylinders are judged on their circles (:func:`lens_area`), as the validator
    judges them, so cylinders in contact share nothing. An R-tree finds the
    candidate pairs, so the cost is about n log n.
    """
    polys = np.asarray(polys, dtype=object)
    a, b = STRtree(polys).query(polys, predicate="intersects")
    keep = a < b
    a, b = a[keep], b[keep]
    areas = np.array(shapely.area(shapely.intersection(polys[a], polys[b])), dtype=float) if len(a) else np.empty(0)
    for k in np.flatnonzero((discs[a] > 0) & (discs[b] > 0)):
        areas[k] = lens_area(float(discs[a[k]]), float(discs[b[k]]), float(np.hypot(*(xy[a[k]] - xy[b[k]]))))
    return a, b, areas
