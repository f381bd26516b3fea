"""The proof that an object can never reach its pose goal (lgmcts.confinement), and the planner's use of it."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from lgmcts import check, plan
from lgmcts import geometry as geo
from lgmcts.confinement import confined, contact_distance
from lgmcts.formats import parse_goals, parse_scene
from lgmcts.planner.search import SearchOptions
from lgmcts.scene import Scene
from lgmcts.tolerances import OVERLAP_AREA

# Five discs jammed in a 1 m square (TRLB's D = 0.6, n = 5): four in the
# corners and one in the middle, each with a few centimetres of play.
JAMMED = [(0.798, 0.798), (0.501, 0.482), (0.798, 0.204), (0.204, 0.204), (0.241, 0.798)]
R_JAMMED = 0.195441


def _case(start, goal, r, shape="cylinder"):
    sh = {"type": "cylinder", "radius": r, "height": 0.02} if shape == "cylinder" else {
        "type": "box", "size": [2 * r, 2 * r, 0.02]}
    objs = [{"id": i + 1, "name": "disc", "color": "red", "shape": sh, "pose": [x, y, 0.0], "on": None}
            for i, (x, y) in enumerate(start)]
    goals = [{"pattern": "pose", "objects": [i + 1], "pose": [x, y, 0.0]} for i, (x, y) in enumerate(goal)]
    return parse_scene({"workspace": {"x": [0, 1], "y": [0, 1]}, "objects": objs}), parse_goals({"goals": goals})


def _swap(pts, a, b):
    out = list(pts)
    out[a], out[b] = out[b], out[a]
    return out


def test_contact_distance_is_where_the_overlap_reaches_the_allowance():
    d = contact_distance(0.1, 0.1)
    assert d < 0.2
    assert geo.lens_area(0.1, 0.1, d) > OVERLAP_AREA >= geo.lens_area(0.1, 0.1, d + 1e-9)
    assert contact_distance(0.0, 0.1) == 0.0


def test_two_corner_discs_of_a_jammed_square_cannot_trade_places():
    scene, goals = _case(JAMMED, _swap(JAMMED, 3, 4), R_JAMMED)
    why = confined(Scene.from_spec(scene), goals, budget_s=30)
    assert why is not None and "\n" not in why
    assert why.startswith("no plan keeping the objects on the table exists: object 4 ")
    assert "2 of 5 goal objects" in why


def test_the_middle_disc_is_free_to_wiggle_but_not_to_leave():
    # Moving the middle disc by 3 cm is within its play; to a corner it is not.
    goal = list(JAMMED)
    goal[1] = (0.52, 0.5)
    scene, goals = _case(JAMMED, goal, R_JAMMED)
    assert confined(Scene.from_spec(scene), goals, budget_s=30) is None
    p = plan(scene, goals, seed=0, max_iter=200)
    assert p.solved and check(scene, goals, p).valid


def test_smaller_discs_in_the_same_places_are_not_confined():
    scene, goals = _case(JAMMED, _swap(JAMMED, 3, 4), 0.15)
    assert confined(Scene.from_spec(scene), goals, budget_s=30) is None
    p = plan(scene, goals, seed=0)
    assert p.solved and check(scene, goals, p).valid


def test_only_pose_goals_on_the_table_are_judged():
    scene, goals = _case(JAMMED, _swap(JAMMED, 3, 4), R_JAMMED)
    line = parse_goals({"goals": [*[g.model_dump() for g in goals.goals], {"pattern": "line", "objects": [1, 2]}]})
    assert confined(Scene.from_spec(scene), line, budget_s=30) is None
    assert confined(Scene.from_spec(scene), goals, budget_s=0.0) is None  # out of time: not proved


def test_planner_answers_at_once_with_the_reason():
    scene, goals = _case(JAMMED, _swap(JAMMED, 3, 4), R_JAMMED)
    p = plan(scene, goals, seed=0, max_iter=10_000)
    assert not p.solved and p.stats["infeasible"] is True
    assert p.stats["reason"].startswith("no plan keeping the objects on the table exists")
    assert p.stats["iterations"] <= SearchOptions().proof_after
    g = plan(scene, goals, method="greedy", seed=0, max_iter=10_000)
    assert not g.solved and g.stats.get("infeasible") is True


def test_without_the_proof_the_search_runs_its_budget():
    from lgmcts.planner.policies import plan as run_plan

    scene, goals = _case(JAMMED, _swap(JAMMED, 3, 4), R_JAMMED)
    # (The corner search of lgmcts.planner.dense is off: it would only add its states to what was tried.)
    p = run_plan(scene, goals, seed=0, max_iter=60, options=SearchOptions(proof_after=0, dense=False))
    assert not p.solved and "infeasible" not in p.stats and p.stats["iterations"] == 60
    # The one line says what was tried.
    reason = p.stats["reason"]
    assert reason.startswith("iteration budget exhausted after 60 iterations") and "\n" not in reason
    assert "of 5 goals" in reason and reason.endswith("no proof was found that no plan exists")


@settings(max_examples=25, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(n=st.integers(2, 5), r=st.floats(0.12, 0.2), seed=st.integers(0, 10_000),
       shape=st.sampled_from(["cylinder", "box"]))
def test_never_refuses_what_the_planner_solves(n, r, seed, shape):
    # Soundness: a proof of confinement and a valid plan cannot both exist.
    rng = np.random.default_rng(seed)
    reach = 2 * r * (math.sqrt(2) if shape == "box" else 1.0)

    def config():
        pts: list[np.ndarray] = []
        for _ in range(4000):
            p = rng.uniform(r * 1.5, 1 - r * 1.5, 2)
            if all(np.hypot(*(p - q)) >= reach + 1e-3 for q in pts):
                pts.append(p)
                if len(pts) == n:
                    return [tuple(map(float, q)) for q in pts]
        return None

    start, goal = config(), config()
    if start is None or goal is None:
        return
    scene, goals = _case(start, goal, r, shape)
    from lgmcts.planner.policies import plan as run_plan

    p = run_plan(scene, goals, seed=0, max_iter=300, options=SearchOptions(proof_after=0))
    if p.solved and check(scene, goals, p).valid:
        assert confined(Scene.from_spec(scene), goals, budget_s=30) is None


@pytest.mark.slow
def test_cli_says_in_one_line_that_no_plan_exists(tmp_path):
    import json
    import subprocess
    import sys

    from lgmcts import save_json

    scene, goals = _case(JAMMED, _swap(JAMMED, 3, 4), R_JAMMED)
    save_json(scene, tmp_path / "scene.json")
    save_json(goals, tmp_path / "goals.json")
    r = subprocess.run([sys.executable, "-m", "lgmcts", "plan", str(tmp_path / "scene.json"), "--goal",
                        str(tmp_path / "goals.json"), "-o", str(tmp_path / "plan.json")],
                       capture_output=True, text=True, check=False)
    assert r.returncode == 1
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("not solved (no plan keeping the objects on the table exists")
    plan_json = json.loads((tmp_path / "plan.json").read_text())
    assert plan_json["solved"] is False and plan_json["stats"]["infeasible"] is True


@settings(max_examples=50, deadline=None)
@given(seed=st.integers(0, 10_000), slack=st.floats(0.0, 0.2))
def test_region_corners_hold_the_region_even_with_redundant_sides(seed, slack):
    import shapely

    from lgmcts.confinement import _DIRS, _corners, _support

    rng = np.random.default_rng(seed)
    pts = rng.uniform(0, 1, (int(rng.integers(1, 12)), 2))
    h = _support(shapely.MultiPoint(pts)) + rng.uniform(0, slack, len(_DIRS))  # some sides no longer touch
    hull = shapely.MultiPoint(_corners(h)).convex_hull
    # Points of the region {x : x . u_k <= h_k}: the given ones and random ones that pass every side.
    probe = rng.uniform(-0.5, 1.5, (4000, 2))
    inside = probe[(probe @ _DIRS.T <= h).all(axis=1)]
    for p in np.vstack([pts, inside]):
        assert hull.buffer(1e-9).covers(shapely.Point(p))
