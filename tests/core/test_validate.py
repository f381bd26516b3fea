"""The acceptance rules, on crafted plans that obey or break each one."""

from __future__ import annotations

import math

import pytest
from core_helpers import box, can, goals, scene
from hypothesis import given, settings
from hypothesis import strategies as st

from lgmcts import check


def act(o, x, y, t=0.0, on=None, purpose="goal"):
    return {"object": o, "to": [x, y, t], "on": on, "purpose": purpose}


def plan(*actions):
    return {"solved": True, "actions": list(actions)}


ROW = scene(box(1, -0.3, -0.2), box(2, 0.0, 0.2), box(3, 0.3, -0.2), box(4, 0.3, 0.2))


def test_empty_plan_meets_goal_already_met():
    sc = scene(box(1, -0.1, 0.0), box(2, 0.0, 0.0), box(3, 0.1, 0.0))
    assert check(sc, goals({"pattern": "line", "objects": [1, 2, 3]}), plan()).valid


@pytest.mark.parametrize("offset,valid", [(0.0, True), (0.0149, True), (0.02, False)])
def test_line_tolerance(offset, valid):
    # Three centres with the middle off the line by `offset`; the total-least-squares
    # line splits the error, so only the residual against the fitted line counts.
    sc = scene(box(1, -0.2, 0.0), box(2, 0.0, 0.1), box(3, 0.2, 0.0))
    p = plan(act(2, 0.0, offset * 1.5))  # fitted-line residual of the middle point = 2/3 of its offset
    v = check(sc, goals({"pattern": "line", "objects": [1, 2, 3]}), p)
    assert v.valid is valid, v.reasons


def test_overlap_and_workspace_rules():
    g = goals({"pattern": "line", "objects": [1, 2]})
    v = check(ROW, g, plan(act(1, 0.0, 0.21)))
    assert not v.valid and any("overlaps object 2" in r for r in v.reasons)
    v = check(ROW, g, plan(act(1, 0.39, 0.0)))
    assert not v.valid and any("outside the workspace" in r for r in v.reasons)
    # Touching edges (zero overlap area) are allowed.
    assert check(ROW, g, plan(act(1, 0.04, 0.2))).valid


def test_pick_of_covered_object_and_stacking_rules():
    sc = scene(box(1, 0.0, 0.0), box(2, 0.0, 0.0, on=1), box(3, 0.2, 0.0), box(4, -0.2, 0.0))
    tower = goals({"pattern": "tower", "objects": [3, 1]})
    v = check(sc, tower, plan(act(1, 0.2, 0.0, on=3)))
    assert not v.valid and any("not clear" in r for r in v.reasons)
    good = plan(act(2, -0.2, 0.2, purpose="unstack"), act(1, 0.2, 0.0, on=3))
    assert check(sc, tower, good).valid
    off = plan(act(2, -0.2, 0.2, purpose="unstack"), act(1, 0.25, 0.0, on=3))
    v = check(sc, tower, off)
    assert not v.valid and any("not over support" in r or "off-centre" in r for r in v.reasons)
    # Stacking onto an object that has something on it.
    v = check(sc, goals({"pattern": "tower", "objects": [1, 3]}), plan(act(3, 0.0, 0.0, on=1)))
    assert not v.valid and any("support 1 is not clear" in r for r in v.reasons)


def _ring(n, r, c=(0.0, 0.0), gap_from=None):
    out = []
    for k in range(n):
        a = 2 * math.pi * k / n if gap_from is None else gap_from * k / (n - 1)
        out.append((c[0] + r * math.cos(a), c[1] + r * math.sin(a)))
    return out


@pytest.mark.parametrize("n,r,spread,valid", [
    (4, 0.12, None, True),
    (3, 0.04, None, False),           # radius below 0.05 m
    (4, 0.12, math.pi * 0.9, False),  # all on a half circle: gap over 180 degrees
    (5, 0.15, math.pi * 1.2, True),
])
def test_circle_rule(n, r, spread, valid):
    pts = _ring(n, r, gap_from=spread)
    objs = [can(i + 1, -0.35 + 0.05 * i, -0.25, r=0.015) for i in range(n)]
    sc = scene(*objs)
    p = plan(*[act(i + 1, x, y) for i, (x, y) in enumerate(pts)])
    v = check(sc, goals({"pattern": "circle", "objects": list(range(1, n + 1))}), p)
    assert v.valid is valid, v.reasons


def test_rectangle_rule():
    objs = [can(i + 1, -0.35 + 0.05 * i, -0.25, r=0.015) for i in range(6)]
    sc = scene(*objs)
    g = goals({"pattern": "rectangle", "objects": [1, 2, 3, 4, 5]})
    corners = [(-0.1, -0.05), (0.1, -0.05), (0.1, 0.05), (-0.1, 0.05)]
    ok = plan(*[act(i + 1, x, y) for i, (x, y) in enumerate(corners)], act(5, 0.0, 0.05))
    assert check(sc, g, ok).valid
    inside = plan(*[act(i + 1, x, y) for i, (x, y) in enumerate(corners)], act(5, 0.0, 0.0))
    v = check(sc, g, inside)
    assert not v.valid and any("perimeter" in r for r in v.reasons)
    thin = plan(*[act(i + 1, x, y * 0.3) for i, (x, y) in enumerate(corners)], act(5, 0.0, 0.015))
    assert not check(sc, g, thin).valid


@pytest.mark.parametrize("rel,dx,dy,valid", [
    ("left", -0.1, 0.0, True), ("left", -0.1, 0.09, True), ("left", -0.1, 0.11, False),
    ("behind", 0.0, 0.2, True), ("behind", 0.0, 0.31, False), ("front", 0.0, -0.1, True),
    ("right_behind", 0.1, 0.1, True), ("right_behind", 0.1, -0.01, False), ("left_front", -0.05, -0.2, True),
])
def test_spatial_rule(rel, dx, dy, valid):
    sc = scene(box(1, 0.0, 0.0, size=0.02), box(2, 0.3, -0.25, size=0.02))
    v = check(sc, goals({"pattern": rel, "objects": [2], "anchor": 1}), plan(act(2, dx, dy)))
    assert v.valid is valid, v.reasons


def test_pose_rule():
    sc = scene(box(1, 0.0, 0.0))
    g = goals({"pattern": "pose", "objects": [1], "pose": [0.1, 0.1, 0.5]})
    assert check(sc, g, plan(act(1, 0.11, 0.1, 0.55))).valid
    assert not check(sc, g, plan(act(1, 0.12, 0.1, 0.5))).valid
    assert not check(sc, g, plan(act(1, 0.1, 0.1, 0.7))).valid


def test_pattern_objects_must_end_on_table():
    sc = scene(box(1, -0.2, 0.0), box(2, 0.0, 0.0), box(3, 0.2, 0.0))
    v = check(sc, goals({"pattern": "line", "objects": [1, 3]}), plan(act(3, 0.0, 0.0, on=2)))
    assert not v.valid and any("not on the table" in r for r in v.reasons)


def test_verdict_reports_each_goal():
    sc = scene(box(1, -0.2, 0.0), box(2, 0.0, 0.0), box(3, 0.2, 0.0), box(4, 0.0, 0.2))
    g = goals({"pattern": "line", "objects": [1, 2, 3]}, {"pattern": "left", "objects": [4], "anchor": 1})
    v = check(sc, g, plan())
    assert v.goals == (True, False) and not v.valid


@pytest.mark.parametrize("yaw", [0.0, math.pi / 24, 0.3])
@pytest.mark.parametrize("gap,valid", [(0.0, True), (1e-5, True), (-0.001, False)])
def test_cylinders_may_touch_whatever_their_yaw(yaw, gap, valid):
    # Two discs of radius 3.75 cm: their 24-gons overlap by up to ~1.6 mm^2 when
    # the circles just touch, so contact is judged on the circles.
    r = 0.0375
    sc = scene(can(1, -0.2, 0.0, r=r), can(2, 0.0, 0.0, r=r))
    d = 2 * r + gap
    p = plan(act(1, d * math.cos(1.3), d * math.sin(1.3), yaw))
    g = goals({"pattern": "pose", "objects": [1], "pose": [d * math.cos(1.3), d * math.sin(1.3), yaw]})
    v = check(sc, g, p)
    assert v.valid is valid, v.reasons


def test_lens_area_matches_polygons():
    import shapely

    from lgmcts.geometry import lens_area as _lens_area

    for r1, r2, d in [(0.03, 0.03, 0.05), (0.02, 0.04, 0.05), (0.03, 0.01, 0.025), (0.02, 0.02, 0.05)]:
        a = shapely.Point(0, 0).buffer(r1, 512)
        b = shapely.Point(d, 0).buffer(r2, 512)
        assert _lens_area(r1, r2, d) == pytest.approx(a.intersection(b).area, rel=1e-3, abs=1e-9)


def test_validator_steps_through_the_shared_replay(monkeypatch):
    # The validator's states are scene.advance's: a meaningless action is
    # refused with advance's own message and ends the replay, and every step
    # of a legal plan goes through advance once.
    import lgmcts.scene as scene_mod
    import lgmcts.validate as validate_mod
    from lgmcts.errors import InputError
    from lgmcts.formats import load_scene
    from lgmcts.scene import Scene, advance, replay

    sc = Scene.from_spec(load_scene(ROW))
    g = goals({"pattern": "line", "objects": [1, 2, 3]})
    bad = plan(act(1, -0.3, 0.0), act(99, 0.0, 0.0), act(2, 0.0, 0.0))
    with pytest.raises(InputError) as err:
        replay(sc, load_plan_actions(bad))
    v = check(ROW, g, bad)
    assert not v.valid and v.reasons[0] == str(err.value) == "action 2: unknown object id 99"
    calls = []

    def counting(state, number, action, **kw):
        calls.append(number)
        return advance(state, number, action, **kw)

    monkeypatch.setattr(validate_mod, "advance", counting)
    good = plan(act(1, -0.3, 0.0), act(2, 0.0, 0.0), act(3, 0.3, 0.0))
    assert check(ROW, g, good).valid and calls == [1, 2, 3]
    final = replay(sc, load_plan_actions(good))[-1]
    assert scene_mod.TABLE == final.on[0] and final.poses[1].tolist() == [0.0, 0.0, 0.0]


def load_plan_actions(p):
    from lgmcts.formats import load_plan

    return list(load_plan(p).actions)


@settings(max_examples=80, deadline=None)
@given(st.integers(0, 2**32 - 1), st.integers(2, 9), st.integers(1, 12))
def test_cylinder_plans_judged_on_circles_as_through_polygons(seed, n, steps):
    # A plan of cylinders placed on the table is judged on the circles alone (validate.CIRCLES); the verdict,
    # reasons and goals must be those of the polygon path: placements that overlap by much or by a sliver, that
    # just touch, that lie a little or far outside the workspace, at any yaw.
    import numpy as np

    import lgmcts.validate as validate_mod

    rng = np.random.default_rng(seed)
    r = rng.uniform(0.02, 0.08, n)
    # A start scene the validator accepts: one disc per cell of a grid 0.18 m apart, a little off its centre.
    cells = rng.permutation(12)[:n]
    objs = [can(i + 1, -0.3 + 0.18 * float(cells[i] % 4) + float(rng.uniform(-0.005, 0.005)),
                -0.18 + 0.18 * float(cells[i] // 4) + float(rng.uniform(-0.005, 0.005)), r=float(r[i]))
            for i in range(n)]
    sc = scene(*objs)
    xy = np.array([o["pose"][:2] for o in objs])
    actions = []
    for _ in range(steps):
        i = int(rng.integers(n))
        k = int(rng.integers(n))
        kind = rng.integers(4)
        if kind == 0 or k == i:  # anywhere, the edge included
            to = rng.uniform([-0.45, -0.35], [0.45, 0.35])
        else:  # near another disc: touching, a sliver in, a sliver off, or well in
            a = rng.uniform(0, 2 * math.pi)
            gap = [0.0, -1e-5, 1e-5, -0.01, -2e-4, -3e-4, -5e-4][int(rng.integers(7))]
            to = xy[k] + (r[i] + r[k] + gap) * np.array([math.cos(a), math.sin(a)])
        xy[i] = to
        actions.append(act(i + 1, float(to[0]), float(to[1]), float(rng.uniform(-math.pi, math.pi))))
    g = goals({"pattern": "pose", "objects": [1], "pose": [*map(float, xy[0]), 0.0]},
              {"pattern": "line", "objects": [o["id"] for o in objs[:3]]})
    fast = check(sc, g, plan(*actions))
    validate_mod.CIRCLES = False
    try:
        slow = check(sc, g, plan(*actions))
    finally:
        validate_mod.CIRCLES = True
    assert (fast.valid, fast.reasons, fast.goals) == (slow.valid, slow.reasons, slow.goals)
