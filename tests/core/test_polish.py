"""Polishing as the search's accept step, and the geometry shortcuts the planner relies on."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from lgmcts import check, plan
from lgmcts import geometry as geo
from lgmcts.casegen import labbe_case, random_case
from lgmcts.planner import SearchOptions
from lgmcts.planner import polish as pol
from lgmcts.planner.search import mcts
from lgmcts.planner.step import Problem
from lgmcts.scene import Scene


def _raw(case, seed):
    """A problem and the plan the search finds for it, unpolished."""
    problem = Problem.build(Scene.from_spec(case.scene), case.goals)
    res = mcts(problem, np.random.default_rng(seed), SearchOptions(polish=False))
    assert res.solved
    return problem, list(res.actions)


@pytest.mark.parametrize("case,seed,shortens", [(labbe_case(25, 25014), 14, True), (labbe_case(25, 25002), 2, False),
                                                (labbe_case(20, 5), 0, False), (random_case(11), 0, False),
                                                (random_case(40), 0, False)],
                         ids=["labbe25a", "labbe25b", "labbe20", "random11", "random40"])
def test_polish_stops_early_without_changing_the_result(case, seed, shortens, monkeypatch):
    problem, actions = _raw(case, seed)
    fast = pol.polished(problem, actions)
    # Never rejoining the original plan means replaying every rewrite to the end.
    monkeypatch.setattr(pol, "_same", lambda a, b: False)
    slow = pol.polished(problem, actions)
    assert fast == slow
    assert len(fast) <= len(actions)
    if shortens:
        assert len(fast) < len(actions)  # rewrites were found, so the early stop was exercised
    assert check(case.scene, case.goals, {"solved": True, "actions": [a.model_dump() for a in fast]}).valid


def test_polished_plans_are_shorter_and_reported():
    c = labbe_case(25, 25014)
    p = plan(c.scene, c.goals, seed=14)
    raw = plan(c.scene, c.goals, seed=14, options=SearchOptions(polish=False))
    assert p.solved and raw.solved and check(c.scene, c.goals, p).valid
    assert len(p.actions) < len(raw.actions)
    assert p.stats["actions_before_polish"] == len(raw.actions)


def test_accept_rejects_a_plan_that_misses_a_goal():
    c = labbe_case(6, 1)
    problem, actions = _raw(c, 0)
    assert pol.polished(problem, actions) is not None
    assert pol.polished(problem, actions[:-1]) is None


_polys = st.lists(
    st.tuples(st.floats(-0.3, 0.3), st.floats(-0.3, 0.3), st.floats(-3.2, 3.2), st.floats(0.01, 0.08), st.floats(0.01, 0.08)),
    min_size=1, max_size=12,
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
@given(st.floats(0.01, 0.05), st.floats(0.01, 0.05), st.floats(-0.01, 0.01), st.floats(0, 2 * np.pi),
       st.floats(-0.5, 0.5), st.booleans())
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
@given(st.lists(st.tuples(st.floats(-0.2, 0.2), st.floats(-0.2, 0.2), st.floats(0.01, 0.05)), min_size=1, max_size=6),
       st.floats(-0.2, 0.2), st.floats(-0.2, 0.2), st.floats(0.01, 0.05), st.sampled_from([0.0, 0.002]))
def test_colliding_near_decides_disc_pairs_on_circles(obs, x, y, r, clearance):
    xy = np.array([[a, b] for a, b, _ in obs])
    radii = np.array([c for _, _, c in obs])
    polys = np.array([shapely.polygons(geo.circle_footprint(c) + (a, b)) for a, b, c in obs])
    rr = radii / np.cos(np.pi / geo.CIRCLE_SEGMENTS)
    me = shapely.polygons(geo.circle_footprint(r) + (x, y))
    _, oi = geo.colliding_near(np.array([me]), np.array([[x, y]]), r / np.cos(np.pi / geo.CIRCLE_SEGMENTS), polys, xy, rr,
                               clearance, cand_disc=r, obs_disc=radii)
    want = np.flatnonzero(np.hypot(*(xy - (x, y)).T) <= r + radii + clearance + 1e-12)
    assert sorted(oi.tolist()) == want.tolist()


def test_replay_keeps_the_clearance_except_for_fixed_targets():
    # A pose goal's fixed target 1.1 mm from a box may be reached in contact;
    # a move for a sampled goal (here a relation) may not come that close.
    from lgmcts.formats import Action, parse_goals, parse_scene

    def box(i, x, y):
        return {"id": i, "name": "block", "color": "red", "shape": {"type": "box", "size": [0.04, 0.04, 0.04]},
                "pose": [x, y, 0.0], "on": None}

    sc = Scene.from_spec(parse_scene({"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]},
                                      "objects": [box(1, 0.2, 0.2), box(2, -0.2, 0.0), box(3, 0.0, 0.0)]}))
    gs = parse_goals({"goals": [{"pattern": "pose", "objects": [1], "pose": [0.0411, 0.0, 0.0]},
                                {"pattern": "left", "objects": [2], "anchor": 3}]})
    problem = Problem.build(sc, gs)
    ref = np.array(sc.initial.poses)
    to_target = Action(object=1, to=(0.0411, 0.0, 0.0), purpose="goal")
    too_close = Action(object=2, to=(-0.0411, 0.0, 0.0), purpose="goal")
    assert pol._replay(problem, [to_target], 0, sc.initial, ref) is not None
    assert pol._replay(problem, [to_target, too_close], 0, sc.initial, ref) is None
