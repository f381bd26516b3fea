"""Obviously impossible goals are refused as bad input before any search."""

from __future__ import annotations

import time

import pytest

from lgmcts.errors import InputError
from lgmcts.feasibility import inradius, precheck
from lgmcts.formats import parse_goals, parse_scene
from lgmcts.planner import plan
from lgmcts.scene import Scene

from .core_helpers import box, goals, scene


def _scene(n: int, size: float = 0.04, **kw):
    objs = [box(i + 1, -0.35 + 0.06 * (i % 12), -0.25 + 0.06 * (i // 12), size=size) for i in range(n)]
    return parse_scene(scene(*objs, **kw))


def test_two_objects_with_one_pose_goal_are_refused_at_once():
    sc = _scene(3)
    g = goals({"pattern": "pose", "objects": [1], "pose": [0.1, 0.1, 0.0]},
              {"pattern": "pose", "objects": [2], "pose": [0.1, 0.1, 0.0]})
    t0 = time.perf_counter()
    with pytest.raises(InputError, match="objects 1 and 2 have pose goals"):
        plan(sc, g, max_iter=100_000)
    assert time.perf_counter() - t0 < 30  # refused before the search, not after its budget


def test_overlapping_pose_goals_in_a_tower_are_allowed():
    sc = _scene(3)
    g = parse_goals(goals({"pattern": "pose", "objects": [1], "pose": [0.1, 0.1, 0.0]},
                          {"pattern": "pose", "objects": [2], "pose": [0.1, 0.1, 0.0]},
                          {"pattern": "tower", "objects": [1, 2]}))
    precheck(sc, g)


def test_side_by_side_pose_goals_are_fine():
    sc = _scene(3)
    precheck(sc, parse_goals(goals({"pattern": "pose", "objects": [1], "pose": [0.1, 0.1, 0.0]},
                                   {"pattern": "pose", "objects": [2], "pose": [0.14, 0.1, 0.0]})))


def test_pose_goal_off_the_workspace_is_refused():
    with pytest.raises(InputError, match="outside the workspace"):
        precheck(_scene(2), parse_goals(goals({"pattern": "pose", "objects": [1], "pose": [0.9, 0.0, 0.0]})))


def test_line_longer_than_the_workspace_is_refused():
    # 40 blocks of 4 cm: 39 gaps of at least sqrt(0.04^2 - 0.03^2) = 2.6 cm, over the 1.0 m diagonal
    sc = _scene(40, size=0.04)
    with pytest.raises(InputError, match="line of 40 objects"):
        precheck(sc, parse_goals(goals({"pattern": "line", "objects": list(range(1, 41))})))
    precheck(sc, parse_goals(goals({"pattern": "line", "objects": list(range(1, 11))})))


def test_more_table_area_than_the_workspace_is_refused():
    objs = [box(i + 1, -0.3 + 0.2 * (i % 4), -0.2 + 0.2 * (i // 4), size=0.15) for i in range(12)]
    sc = parse_scene(scene(*objs, x=(-0.4, 0.4), y=(-0.3, 0.3)))
    # 12 boxes of 0.15 m fit the 0.8 x 0.6 m workspace (0.27 of 0.48 m^2) ...
    precheck(sc, parse_goals(goals({"pattern": "circle", "objects": list(range(1, 13))})))


def test_table_area_bound():
    # Four 0.3 m boxes need 0.36 m^2; the workspace holds 0.32 m^2 (0.8 x 0.4).
    objs = [box(i + 1, -0.25 + 0.5 * (i % 2), 0.0, size=0.3) for i in range(2)]
    objs += [box(i + 3, -0.25 + 0.5 * (i % 2), 0.0, size=0.3, on=i + 1) for i in range(2)]
    sc = parse_scene(scene(*objs, x=(-0.4, 0.4), y=(-0.2, 0.2)))
    with pytest.raises(InputError, match="must stand on the table"):
        precheck(sc, parse_goals(goals({"pattern": "rectangle", "objects": [1, 2, 3, 4]})))


def test_too_many_objects_on_one_side_of_an_anchor_are_refused():
    sc = _scene(60, size=0.05)
    with pytest.raises(InputError, match="cannot all be 'behind' of anchor 1"):
        precheck(sc, parse_goals(goals({"pattern": "behind", "objects": list(range(2, 61)), "anchor": 1})))
    precheck(sc, parse_goals(goals({"pattern": "behind", "objects": [2, 3, 4], "anchor": 1})))


def test_inradius():
    sc = Scene.from_spec(_scene(1, size=0.04))
    assert inradius(sc.local[0]) == pytest.approx(0.02)


@pytest.mark.slow
def test_bundled_and_generated_scenes_pass_the_start_rules_and_precheck():
    """The overlap rule and the pre-check refuse nothing that exists: bundled scenes, generated cases and suites."""
    import json

    from lgmcts.bench.suites import SUITES, generate
    from lgmcts.casegen import labbe_case, random_case
    from lgmcts.formats import load_goals, load_scene

    precheck(Scene.from_spec(load_scene("examples/tabletop.json")), load_goals("examples/goals.json"))
    for line in open("data/parse_cases.jsonl"):
        if line.strip() and not line.lstrip().startswith("//"):
            row = json.loads(line)
            if isinstance(row.get("scene"), dict):
                Scene.from_spec(parse_scene(row["scene"]))
    for seed in range(20):
        case = random_case(seed)
        precheck(Scene.from_spec(case.scene), case.goals)
    case = labbe_case(25, 0)
    precheck(Scene.from_spec(case.scene), case.goals)
    for suite in SUITES:
        for task in generate(suite, n=20, seed=0):
            sc = parse_scene(task.scene) if isinstance(task.scene, dict) else task.scene
            g = task.goals
            precheck(Scene.from_spec(sc), parse_goals(g) if isinstance(g, (dict, list)) else g)


from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as st  # noqa: E402


@settings(max_examples=30, deadline=None)
@given(seed=st.integers(min_value=1000, max_value=10**6))
def test_precheck_never_refuses_a_case_built_from_a_real_arrangement(seed):
    """random_case places the goal arrangement first, so its goals are satisfiable: the pre-check must let them be."""
    from lgmcts.casegen import random_case

    case = random_case(seed)
    precheck(Scene.from_spec(case.scene), case.goals)


def test_cylinder_pose_goals_in_contact_are_not_refused():
    """Touching pose targets are legal (the validator judges cylinders on their
    circles), so the pre-check must not call them infeasible at any yaw or bearing,
    while a real overlap of the circles is still refused."""
    import math

    r = 0.0375
    objs = [
        {
            "id": i + 1,
            "name": "disc",
            "color": "red",
            "shape": {"type": "cylinder", "radius": r, "height": 0.02},
            "pose": [0.1, 0.1 + 0.1 * i, 0.0],
            "on": None,
        }
        for i in range(2)
    ]
    sc = Scene.from_spec(parse_scene({"workspace": {"x": [0, 0.5], "y": [0, 0.5]}, "objects": objs}))
    for k in range(40):
        th = k * math.pi / 80
        for yaw in (0.0, 0.07, 0.13):
            target = [0.25 + 2 * r * math.cos(th), 0.25 + 2 * r * math.sin(th), yaw]
            precheck(
                sc,
                parse_goals(
                    {
                        "goals": [
                            {"pattern": "pose", "objects": [1], "pose": [0.25, 0.25, 0.0]},
                            {"pattern": "pose", "objects": [2], "pose": target},
                        ]
                    }
                ),
            )
    overlap = [0.25 + 1.9 * r, 0.25, 0.0]
    with pytest.raises(InputError, match="objects 1 and 2 have pose goals"):
        precheck(
            sc,
            parse_goals(
                {
                    "goals": [
                        {"pattern": "pose", "objects": [1], "pose": [0.25, 0.25, 0.0]},
                        {"pattern": "pose", "objects": [2], "pose": overlap},
                    ]
                }
            ),
        )
