"""The geometry module: footprints, placement, workspace tests, angle wrapping
and the collision shortcuts the planner relies on."""

from __future__ import annotations

import math

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from lgmcts import geometry as geo


def approx(x):
    return pytest.approx(x, abs=1e-12)


def test_box_and_circle_footprints():
    b = geo.box_footprint(0.2, 0.1)
    assert b.shape == (4, 2) and shapely.Polygon(b).area == approx(0.02)
    assert shapely.Polygon(b).exterior.is_ccw
    c = geo.circle_footprint(0.05)
    assert c.shape == (geo.CIRCLE_SEGMENTS, 2)
    # The polygon circumscribes the circle: every edge is at least r from the centre.
    poly = shapely.Polygon(c)
    assert poly.exterior.distance(shapely.Point(0, 0)) >= 0.05 - 1e-12
    assert geo.radius_of(c) >= 0.05
    assert geo.radius_of(b) == approx(math.hypot(0.1, 0.05))


def test_convex_footprint_is_the_ccw_hull():
    pts = np.array([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.5], [0.2, 0.7]], dtype=float)
    hull = geo.convex_footprint(pts)
    assert len(hull) == 4 and shapely.Polygon(hull).exterior.is_ccw
    assert shapely.Polygon(hull).area == approx(1.0)


def test_transform_one_and_many_poses():
    local = geo.box_footprint(0.2, 0.1)
    one = geo.transform(local, np.array([1.0, 2.0, math.pi / 2]))
    # A quarter turn maps the local x axis onto y.
    assert np.allclose(one[1] - np.array([1.0, 2.0]), [0.05, 0.1])
    many = geo.transform(local, np.array([[1.0, 2.0, math.pi / 2], [0.0, 0.0, 0.0]]))
    assert many.shape == (2, 4, 2) and np.allclose(many[0], one) and np.allclose(many[1], local)


@settings(max_examples=30, deadline=None)
@given(st.floats(-0.5, 0.5), st.floats(-0.5, 0.5), st.floats(-10, 10))
def test_transform_keeps_distances_and_area(x, y, t):
    local = geo.box_footprint(0.3, 0.07)
    v = geo.transform(local, np.array([x, y, t]))
    assert np.allclose(np.linalg.norm(v - v.mean(axis=0), axis=1), np.linalg.norm(local, axis=1))
    assert shapely.Polygon(v).area == approx(shapely.Polygon(local).area)


def test_polygons_of_one_and_many():
    v = geo.transform(geo.box_footprint(0.1, 0.1), np.array([[0.0, 0.0, 0.0], [1.0, 0.0, 0.3]]))
    ps = geo.polygons(v)
    assert len(ps) == 2 and all(p.area == approx(0.01) for p in ps)
    assert geo.polygons(v[0]).area == approx(0.01)


def test_inside_workspace_is_every_vertex_with_margin():
    bounds = (-0.5, 0.5, -0.4, 0.4)
    local = geo.box_footprint(0.1, 0.1)
    v = geo.transform(local, np.array([[0.0, 0.0, 0.0], [0.45, 0.0, 0.0], [0.46, 0.0, 0.0], [0.0, 0.36, 0.0]]))
    assert geo.inside_workspace(v, bounds).tolist() == [True, True, False, False]
    assert geo.inside_workspace(v, bounds, margin=0.01).tolist() == [True, False, False, False]


@settings(max_examples=50, deadline=None)
@given(st.floats(-100, 100))
def test_wrap_angle_range_and_equivalence(a):
    w = float(geo.wrap_angle(a))
    assert -math.pi <= w < math.pi
    assert math.isclose(math.cos(w), math.cos(a), abs_tol=1e-9) and math.isclose(math.sin(w), math.sin(a), abs_tol=1e-9)


def test_wrap_angle_is_vectorised():
    out = geo.wrap_angle(np.array([0.0, math.pi, -math.pi, 3 * math.pi / 2]))
    assert np.allclose(out, [0.0, -math.pi, -math.pi, -math.pi / 2])


_polys = st.lists(
    st.tuples(
        st.floats(-0.3, 0.3), st.floats(-0.3, 0.3), st.floats(-3.2, 3.2), st.floats(0.01, 0.08), st.floats(0.01, 0.08)
    ),
    min_size=1,
    max_size=12,
)


def _boxes(rows):
    xy = np.array([[r[0], r[1]] for r in rows])
    local = [np.array([[-a, -b], [a, -b], [a, b], [-a, b]]) / 2 for *_, a, b in rows]
    poses = np.array([[r[0], r[1], r[2]] for r in rows])
    verts, polys = geo.place_each(local, poses)
    radii = np.array([geo.radius_of(lf) for lf in local])
    return xy, verts, polys, radii, local, poses


@settings(max_examples=40, deadline=None)
@given(cand=_polys, obs=_polys, clearance=st.sampled_from([0.0, 0.002, 0.02]))
def test_colliding_near_matches_an_rtree(cand, obs, clearance):
    cxy, _, cpolys, cr, _, _ = _boxes(cand)
    oxy, _, opolys, orad, _, _ = _boxes(obs)
    ci, oi = geo.colliding_near(cpolys, cxy, cr, opolys, oxy, orad, clearance)
    ti, tj = geo.colliding(shapely.STRtree(list(opolys)), cpolys, clearance)
    assert sorted(zip(ci.tolist(), oi.tolist())) == sorted(zip(ti.tolist(), tj.tolist()))


@settings(max_examples=20, deadline=None)
@given(rows=_polys)
def test_place_each_matches_transform(rows):
    _, verts, polys, _, local, poses = _boxes(rows)
    for k in range(len(rows)):
        expect = geo.transform(local[k], poses[k])
        assert np.allclose(verts[k], expect, atol=1e-12)
        assert shapely.equals_exact(polys[k], shapely.polygons(expect), tolerance=1e-12)


@settings(max_examples=60, deadline=None)
@given(
    st.floats(0.01, 0.05),
    st.floats(0.01, 0.05),
    st.floats(-0.01, 0.01),
    st.floats(0, 2 * np.pi),
    st.floats(-0.5, 0.5),
    st.booleans(),
)
def test_overlapping_matches_exact_shapes(r1, r2, gap, ang, yaw, discs):
    # Discs against their circles' overlap; boxes against shapely's intersection area.
    d = r1 + r2 + gap
    if discs:
        a, b = geo.circle_footprint(r1), geo.circle_footprint(r2)
        da, db = np.array([r1]), np.array([r2])
    else:
        a, b = geo.box_footprint(2 * r1, r1), geo.box_footprint(r2, 2 * r2)
        da = db = np.zeros(1)
    pa = shapely.polygons(geo.transform(a, np.array([0.0, 0.0, yaw])))
    xy = np.array([d * np.cos(ang), d * np.sin(ang)])
    pb = shapely.polygons(geo.transform(b, np.array([xy[0], xy[1], -yaw])))
    got = geo.overlapping(np.array([pa]), np.zeros((1, 2)), da, np.array([pb]), xy[None], db, 0.5e-6)[0]
    want = d < r1 + r2 - 1e-9 if discs else shapely.area(shapely.intersection(pa, pb)) > 0.5e-6
    assert got == want


@settings(max_examples=60, deadline=None)
@given(
    st.lists(st.tuples(st.floats(-0.2, 0.2), st.floats(-0.2, 0.2), st.floats(0.01, 0.05)), min_size=1, max_size=6),
    st.floats(-0.2, 0.2),
    st.floats(-0.2, 0.2),
    st.floats(0.01, 0.05),
    st.sampled_from([0.0, 0.002]),
)
def test_colliding_near_decides_disc_pairs_on_circles(obs, x, y, r, clearance):
    xy = np.array([[a, b] for a, b, _ in obs])
    radii = np.array([c for _, _, c in obs])
    polys = np.array([shapely.polygons(geo.circle_footprint(c) + np.array([a, b])) for a, b, c in obs])
    rr = radii / np.cos(np.pi / geo.CIRCLE_SEGMENTS)
    me = shapely.polygons(geo.circle_footprint(r) + np.array([x, y]))
    _, oi = geo.colliding_near(
        np.array([me]),
        np.array([[x, y]]),
        r / np.cos(np.pi / geo.CIRCLE_SEGMENTS),
        polys,
        xy,
        rr,
        clearance,
        cand_disc=r,
        obs_disc=radii,
    )
    want = np.flatnonzero(np.hypot(*(xy - (x, y)).T) <= r + radii + clearance + 1e-12)
    assert sorted(oi.tolist()) == want.tolist()
