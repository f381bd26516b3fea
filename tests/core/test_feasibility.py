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
        precheck(sc, parse_goals({"goals": [{"pattern": "pose", "objects": [1], "pose": [0.25, 0.25, 0.0]},
                                            {"pattern": "pose", "objects": [2], "pose": overlap}]}))


# ------------------------------------------------------------ order cycles

_TWO = [box(1, -0.1, 0.0), box(2, 0.1, 0.0), box(3, 0.0, 0.2), box(4, 0.0, -0.2)]


@pytest.mark.parametrize("gs, shown", [
    # 1 carries 2, and 2 is the anchor 1 is placed beside.
    ([{"pattern": "tower", "objects": [1, 2]}, {"pattern": "right", "objects": [1], "anchor": 2}],
     ["1 after 2", "2 after 1"]),
    ([{"pattern": "tower", "objects": [1, 2, 3]}, {"pattern": "left", "objects": [1], "anchor": 3}],
     ["1 after 3", "3 after 2", "2 after 1"]),
    # Through a relation between two other objects: 1 after 3 after 2 after 1.
    ([{"pattern": "tower", "objects": [1, 2]}, {"pattern": "behind", "objects": [3], "anchor": 2},
      {"pattern": "front", "objects": [1], "anchor": 3}], ["1 after 3", "3 after 2", "2 after 1"]),
], ids=["tower-and-relation", "three-high", "through-a-third-object"])
def test_a_tower_and_relations_that_wait_for_each_other_are_refused(gs, shown):
    with pytest.raises(InputError, match="order objects in a cycle") as err:
        precheck(parse_scene(scene(*_TWO)), parse_goals(goals(*gs)))
    msg = str(err.value)
    assert "\n" not in msg and all(s in msg for s in shown), msg


@pytest.mark.parametrize("gs", [
    [{"pattern": "tower", "objects": [1, 2]}, {"pattern": "right", "objects": [3], "anchor": 2}],
    [{"pattern": "tower", "objects": [1, 2]}, {"pattern": "right", "objects": [1], "anchor": 3}],
    [{"pattern": "tower", "objects": [3, 4]}, {"pattern": "left", "objects": [1, 2], "anchor": 3},
     {"pattern": "line", "objects": [1, 2, 3]}],
])
def test_orders_without_a_cycle_pass_and_are_solved(gs):
    sc, g = parse_scene(scene(*_TWO)), parse_goals(goals(*gs))
    precheck(sc, g)
    assert plan(sc, g, max_iter=2000).solved


@pytest.mark.timeout(60)
@pytest.mark.parametrize("method", ["lgmcts", "greedy", "pmcts"])
def test_every_method_ends_with_its_budget_on_goals_it_cannot_order(method):
    """Past the pre-check (called directly), no object is ever ready: each
    method must still stop at its budget; greedy and pmcts ran for ever."""
    import numpy as np

    from lgmcts.planner import METHODS, SearchOptions
    from lgmcts.planner.problem import Problem

    sc = Scene.from_spec(parse_scene(scene(*_TWO)))
    g = parse_goals(goals({"pattern": "tower", "objects": [1, 2]}, {"pattern": "right", "objects": [1], "anchor": 2}))
    res, _ = METHODS[method](Problem.build(sc, g), np.random.default_rng(0), SearchOptions(max_iter=5))
    assert not res.solved and not res.actions


@pytest.mark.slow
@pytest.mark.timeout(120)
@pytest.mark.parametrize("method", ["lgmcts", "greedy", "pmcts"])
def test_the_cli_refuses_a_tower_that_contradicts_a_relation(method, tmp_path):
    import json
    import subprocess
    import sys

    (tmp_path / "s.json").write_text(json.dumps(scene(*_TWO)))
    (tmp_path / "g.json").write_text(json.dumps(goals({"pattern": "tower", "objects": [1, 2]},
                                                      {"pattern": "right", "objects": [1], "anchor": 2})))
    r = subprocess.run([sys.executable, "-m", "lgmcts", "plan", str(tmp_path / "s.json"), "--goal",
                        str(tmp_path / "g.json"), "--method", method, "--max-iter", "5"],
                       capture_output=True, text=True, timeout=100)
    assert r.returncode == 2 and r.stdout == ""
    assert r.stderr.count("\n") == 1 and "order objects in a cycle" in r.stderr, r.stderr


# ------------------------------------------- sizes, directions, lines, stacks

def _row(n: int, size: float = 0.04, y: float = 0.0) -> list[dict]:
    return [box(i + 1, -0.33 + 0.09 * i, y, size=size) for i in range(n)]


def _plan_to(poses: dict[int, tuple[float, float, float]]) -> dict:
    """A plan that moves each object straight to its pose (the poses clear of the start scene)."""
    return {"solved": True, "actions": [{"object": o, "to": list(p), "on": None} for o, p in poses.items()]}


@pytest.mark.parametrize("pattern, n, size, refused", [
    ("circle", 6, 0.02, True), ("circle", 6, 0.034, True), ("circle", 6, 0.036, False), ("circle", 3, 0.05, False),
    ("line", 4, 0.05, True), ("line", 4, 0.12, False), ("rectangle", 4, 0.02, True), ("rectangle", 4, 0.04, False),
])
def test_a_size_below_what_the_objects_allow_is_refused(pattern, n, size, refused):
    sc = parse_scene(scene(*_row(6)))
    g = parse_goals(goals({"pattern": pattern, "objects": list(range(1, n + 1)), "size": size}))
    if refused:
        with pytest.raises(InputError, match=f"goal 0 \\({pattern} of {n} objects\\) asks for a"):
            precheck(sc, g)
    else:
        precheck(sc, g)


@settings(max_examples=40, deadline=None)
@given(n=st.integers(3, 8), side=st.floats(0.02, 0.06), slack=st.floats(0.001, 0.03), yaw=st.floats(-3.1, 3.1))
def test_a_size_the_objects_can_take_is_never_refused(n, side, slack, yaw):
    """Soundness: boxes on a circle as tight as their circumscribed circles
    allow, and boxes side by side in a row, with the size they have: the
    validator accepts the arrangement, so the pre-check must let it through."""
    import math

    from lgmcts import check

    half = side / math.sqrt(2)
    radius = max(0.05, (half + slack / 2) / math.sin(math.pi / n))
    ring = {i + 1: (radius * math.cos(2 * math.pi * i / n), radius * math.sin(2 * math.pi * i / n), yaw)
            for i in range(n)}
    row = {i + 1: (-0.25 + i * (side + slack), 0.2, 0.0) for i in range(n)}
    for pattern, poses, size in (("circle", ring, radius), ("line", row, (n - 1) * (side + slack))):
        sc_dict = scene(*[box(i + 1, -0.35 + 0.09 * (i % 8), -0.27, size=side) for i in range(n)],
                        x=(-0.4, 0.4), y=(-0.3, 0.3))
        g = goals({"pattern": pattern, "objects": list(range(1, n + 1)), "size": round(size, 6)})
        if pattern == "line" and size > 0.6:
            continue
        verdict = check(sc_dict, g, _plan_to(poses))
        assert verdict.valid, verdict.reasons
        precheck(parse_scene(sc_dict), parse_goals(g))


@pytest.mark.parametrize("a, b, refused", [("left", "right", True), ("front", "behind", True),
                                           ("left_front", "right_behind", True), ("left", "right_front", True),
                                           ("left", "front", False), ("left", "left_front", False)])
def test_one_object_in_two_directions_of_one_anchor(a, b, refused):
    sc = parse_scene(scene(*_row(4)))
    g = parse_goals(goals({"pattern": a, "objects": [1], "anchor": 2}, {"pattern": b, "objects": [1], "anchor": 2}))
    if refused:
        with pytest.raises(InputError, match=f"object 1 cannot be both '{a}' \\(goal 0\\) and '{b}' \\(goal 1\\) of 2"):
            precheck(sc, g)
    else:
        precheck(sc, g)  # 'left' and 'front': only the ray between them meets both (45 deg each)
        if b == "left_front":
            assert plan(sc, g, max_iter=2000).solved


@pytest.mark.parametrize("n, size, refused", [(6, 0.04, True), (5, 0.04, True), (4, 0.06, True), (3, 0.06, True),
                                              (4, 0.04, False), (8, 0.02, False)])
def test_the_same_objects_in_a_line_and_a_circle(n, size, refused):
    sc = parse_scene(scene(*_row(8, size=size)))
    objs = list(range(1, n + 1))
    g = parse_goals(goals({"pattern": "line", "objects": objs}, {"pattern": "circle", "objects": objs}))
    if refused:
        with pytest.raises(InputError, match=f"the {n} objects of goal 1 \\(circle\\) cannot also stand in the line"):
            precheck(sc, g)
    else:
        precheck(sc, g)  # not provably impossible (small objects can stand in two tight clusters)


def test_a_circle_beside_a_line_of_other_objects_is_fine():
    sc = parse_scene(scene(*_row(8)))
    precheck(sc, parse_goals(goals({"pattern": "line", "objects": [1, 2, 3, 4]},
                                   {"pattern": "circle", "objects": [3, 4, 5, 6]})))


@pytest.mark.parametrize("targets, refused", [
    ([(-0.2, -0.2), (0.0, 0.2), (0.2, -0.2)], True),
    ([(-0.2, 0.0), (0.0, 0.07), (0.2, 0.0)], True),
    ([(-0.2, 0.0), (0.0, 0.05), (0.2, 0.0)], False),   # 5 cm off: each centre may give 1.5 cm, the line 1.5 cm
    ([(-0.2, 0.0), (0.0, 0.01), (0.2, 0.02)], False),
])
def test_a_line_through_pose_targets_that_no_line_can_pass(targets, refused):
    sc = parse_scene(scene(*_row(4)))
    gs = [{"pattern": "line", "objects": [1, 2, 3]}]
    gs += [{"pattern": "pose", "objects": [i + 1], "pose": [x, y, 0.0]} for i, (x, y) in enumerate(targets)]
    g = parse_goals(goals(*gs))
    if refused:
        with pytest.raises(InputError, match="goal 0 \\(line\\) holds objects 1, 2, 3 whose pose goals are"):
            precheck(sc, g)
    else:
        precheck(sc, g)


def _tower(n: int, half: float, goal_top: bool = False) -> tuple:
    objs = [box(1, 0.0, 0.0)] + [box(i, 0.0, 0.0, on=i - 1) for i in range(2, n + 1)]
    sc = parse_scene(scene(*objs, x=(-half, half), y=(-half, half)))
    target = n if goal_top else 1
    g = parse_goals(goals({"pattern": "pose", "objects": [target], "pose": [0.2, 0.2, 0.0]}))
    return sc, g


def test_unstacking_onto_a_table_too_small_for_the_boxes_is_refused():
    sc, g = _tower(500, 0.3)  # 499 boxes of 16 cm^2 need 0.80 m^2; the table has 0.36 m^2
    with pytest.raises(InputError, match="object 1 must move but carries 499 objects that no goal places"):
        precheck(sc, g)
    precheck(*_tower(500, 0.3, goal_top=True))  # the top needs nothing unstacked
    precheck(*_tower(500, 0.5))  # 1 m^2 holds them
    precheck(*_tower(200, 0.3))  # 0.32 m^2


def test_an_object_already_on_its_pose_under_a_stack_need_not_move():
    objs = [box(1, 0.0, 0.0)] + [box(i, 0.0, 0.0, on=i - 1) for i in range(2, 301)]
    sc = parse_scene(scene(*objs, x=(-0.3, 0.3), y=(-0.3, 0.3)))
    precheck(sc, parse_goals(goals({"pattern": "pose", "objects": [1], "pose": [0.005, 0.0, 0.0]})))


@pytest.mark.slow
def test_the_cli_plan_has_a_default_time_limit_that_leaves_normal_plans_alone(example_scene, example_goals, tmp_path):
    import json
    import subprocess
    import sys

    from lgmcts.cli import PLAN_TIME_LIMIT

    out = tmp_path / "p.json"
    r = subprocess.run([sys.executable, "-m", "lgmcts", "plan", str(example_scene), "--goal", str(example_goals),
                        "-o", str(out)], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0, r.stderr
    got = json.loads(out.read_text())
    assert got["stats"]["time_limit"] == PLAN_TIME_LIMIT
    ref = plan(str(example_scene), str(example_goals))  # the library: no time limit
    assert got["actions"] == [a.model_dump(mode="json") for a in ref.actions]
    r = subprocess.run([sys.executable, "-m", "lgmcts", "plan", str(example_scene), "--goal", str(example_goals),
                        "--time-limit", "0", "-o", str(out)], capture_output=True, text=True, timeout=300)
    assert r.returncode == 0 and "time_limit" not in json.loads(out.read_text())["stats"]


@pytest.mark.slow
@pytest.mark.timeout(120)
def test_a_search_the_precheck_lets_through_ends_at_the_cli_time_limit(tmp_path):
    import json
    import subprocess
    import sys

    objs = _row(4)
    (tmp_path / "s.json").write_text(json.dumps(scene(*objs)))
    (tmp_path / "g.json").write_text(json.dumps(goals({"pattern": "line", "objects": [1, 2, 3, 4]},
                                                      {"pattern": "circle", "objects": [1, 2, 3, 4]})))
    r = subprocess.run([sys.executable, "-m", "lgmcts", "plan", str(tmp_path / "s.json"), "--goal",
                        str(tmp_path / "g.json"), "--time-limit", "3", "-o", str(tmp_path / "p.json")],
                       capture_output=True, text=True, timeout=100)
    assert r.returncode == 1 and "time limit reached" in r.stderr, r.stderr


@pytest.mark.timeout(60)
def test_thousands_of_pose_goals_on_one_spot_are_refused_without_testing_every_pair():
    """2,500 targets on one spot were 3 million overlapping pairs (two minutes of
    polygon intersections); the test stops at the first overlap it proves, and
    targets stacked in one tower (which may all overlap) cost no pairs."""
    n = 5000
    objs = [box(i + 1, 0.0, 0.0, on=i if i else None) for i in range(n)]
    sc = Scene.from_spec(parse_scene(scene(*objs, x=(-1.0, 1.0), y=(-1.0, 1.0))))
    spot = [0.5, 0.5, 0.0]
    with pytest.raises(InputError, match="have pose goals whose footprints overlap"):
        precheck(sc, parse_goals(goals(*[{"pattern": "pose", "objects": [i], "pose": spot} for i in range(1, n, 2)])))
    precheck(sc, parse_goals(goals(*[{"pattern": "pose", "objects": [i], "pose": spot} for i in range(1, n + 1)],
                                   {"pattern": "tower", "objects": list(range(1, n + 1))})))
