"""The UR5e arm: inverse kinematics, the reachability map, execution with the
arm and the failures it names, and the command line with ``--robot``."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
from typer.testing import CliRunner

import lgmcts
from lgmcts.cli import app
from lgmcts.formats import load_goals, load_scene, parse_plan, parse_scene
from lgmcts.robot import load_robot
from lgmcts.sim import execute_plan
from lgmcts.sim.arm import UR5E, ArmIK, ArmSpec, _rot_error, branch_of, down_rotation

runner = CliRunner()


@pytest.fixture(scope="module")
def ik() -> ArmIK:
    return ArmIK()


def _random_reachable(n: int, seed: int) -> list[tuple[np.ndarray, float]]:
    robot = load_robot("ur5e")
    rng = np.random.default_rng(seed)
    out: list[tuple[np.ndarray, float]] = []
    while len(out) < n:
        r, z, b = rng.uniform(0.0, 1.0), rng.uniform(0.0, 0.4), rng.uniform(-math.pi, math.pi)
        if robot.reach_rz(np.array([r]), np.array([z]))[0]:
            out.append((np.array([-r * math.sin(b), r * math.cos(b), z]), float(rng.uniform(-math.pi, math.pi))))
    return out


def test_ik_accuracy_on_random_reachable_poses(ik):
    for pos, yaw in _random_reachable(60, seed=1):
        res = ik.solve(pos, yaw)
        assert res.ok, (pos, yaw, res)
        p, rot = ik.fk(res.q)
        assert np.linalg.norm(p - pos) <= 1e-3
        assert np.linalg.norm(_rot_error(rot, down_rotation(yaw))) <= 0.01
        assert np.all(res.q >= ik.lower - 1e-9) and np.all(res.q <= ik.upper + 1e-9)


def test_ik_free_yaw_points_straight_down(ik):
    res = ik.solve(np.array([0.2, 0.5, 0.1]), None)
    assert res.ok
    _, rot = ik.fk(res.q)
    assert rot[:, 2] @ np.array([0.0, 0.0, -1.0]) > 1 - 1e-6


# Beyond the arm's length, inside its base, and under the table (the cup gets
# there only with the wrist below the table top).
@pytest.mark.parametrize("pos", [[0.0, 1.2, 0.1], [0.9, 0.6, 0.0], [0.0, 0.02, 0.05], [0.0, 0.5, -0.3]])
def test_unreachable_pose_is_reported_not_solved(ik, pos):
    res = ik.solve(np.array(pos), 0.0)
    assert not res.ok
    assert res.reason in ("out of reach", "joint limit")


def test_far_pose_is_out_of_reach(ik):
    assert ik.solve(np.array([0.0, 1.3, 0.05]), 0.0).reason == "out of reach"


def test_joint_limit_is_named():
    # Wrist 3 limited to +-0.2 rad: a yaw of 1.5 rad is reachable only beyond it.
    lower = list(UR5E.lower)
    upper = list(UR5E.upper)
    lower[5], upper[5] = -0.2, 0.2
    narrow = ArmIK(ArmSpec(lower=tuple(lower), upper=tuple(upper)))
    res = narrow.solve(np.array([0.0, 0.5, 0.1]), 1.5)
    assert not res.ok and res.reason == "joint limit"


def test_branches_cover_near_and_far(ik):
    near = ik.solve(np.array([0.0, 0.2, 0.05]), None)
    far = ik.solve(np.array([0.0, 0.85, 0.05]), None)
    assert near.ok and far.ok
    assert branch_of(near.q) == 1 and branch_of(far.q) == 0


def _beyond_map(robot, r: float, z: float, gap: float) -> bool:
    """Whether ``r`` lies ``gap`` outside the map's raw interval at both grid
    heights around ``z``."""
    dz = float(robot.z[1] - robot.z[0])
    rows = [math.floor(z / dz), math.ceil(z / dz)]
    return bool(r > np.nanmax(robot.rmax[rows]) + gap or r < np.nanmin(robot.rmin[rows]) - gap)


def test_reach_map_agrees_with_ik(ik):
    robot = load_robot("ur5e")
    rng = np.random.default_rng(3)
    inside = outside = 0
    while inside < 30 or outside < 8:
        r, z = rng.uniform(0.0, 1.1), rng.uniform(0.0, 0.45)
        p = np.array([0.0, r, z])
        if robot.reach_rz(np.array([r]), np.array([z]))[0] and inside < 30:
            inside += 1
            # The whole approach column is reachable.
            assert ik.solve(p, None).ok and ik.solve(p + np.array([0.0, 0.0, robot.approach]), None).ok
        elif outside < 8 and _beyond_map(robot, r, z, 0.02):
            outside += 1
            assert not ik.solve(p, None, why=False).ok


# ------------------------------------------------------------------ physics

WIDE = {"x": [-0.7, 0.7], "y": [-0.3, 0.6]}


def _plan(actions: list[dict], goal_obj: int) -> dict:
    a = actions[-1]
    return {
        "solved": True,
        "actions": actions,
        "goals": {"goals": [{"pattern": "pose", "objects": [goal_obj], "pose": a["to"]}]},
    }


@pytest.mark.slow
def test_target_out_of_reach_fails_before_moving():
    # A wide table: its far corner is beyond the arm's reach, not the floating cup's.
    scene = parse_scene(
        {
            "workspace": WIDE,
            "objects": [
                {
                    "id": 1,
                    "name": "block",
                    "color": "red",
                    "shape": {"type": "box", "size": [0.05, 0.05, 0.05]},
                    "pose": [0.1, 0.1, 0.0],
                },
            ],
        }
    )
    plan = parse_plan(_plan([{"object": 1, "to": [0.62, 0.52, 0.0], "on": None}], 1))
    assert execute_plan(scene, plan).success
    # The planner neither goes there nor says the block is out of reach.
    assert not lgmcts.plan(scene, plan.goals, seed=0, max_iter=50, robot="ur5e").solved
    assert "out_of_reach" not in lgmcts.plan(scene, plan.goals, seed=0, max_iter=50, robot="ur5e").stats
    res = execute_plan(scene, plan, robot="ur5e")
    assert not res.success
    step = res.steps[0]
    assert not step.ok and step.reached is None
    assert step.message.startswith("out of reach: the place (0.620, 0.520)") and "nothing moved" in step.message
    assert res.final.objects[0].pose[:2] == pytest.approx((0.1, 0.1), abs=1e-3)
    # The planner and the checker know it too.
    verdict = lgmcts.check(scene, plan.goals, plan, robot="ur5e")
    assert not verdict.valid and any("out of the ur5e's reach" in r for r in verdict.reasons)
    assert lgmcts.check(scene, plan.goals, plan).valid


BOTTLE = {
    "workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]},
    "objects": [
        {
            "id": 1,
            "name": "block",
            "color": "red",
            "shape": {"type": "box", "size": [0.05, 0.05, 0.05]},
            "pose": [0.0, 0.1, 0.0],
        },
        {
            "id": 2,
            "name": "bottle",
            "color": "white",
            "shape": {"type": "cylinder", "radius": 0.03, "height": 0.35},
            "pose": [0.085, -0.1, 0.0],
        },
    ],
}


@pytest.mark.slow
def test_tall_bottle_in_the_forearms_path():
    scene = parse_scene(BOTTLE)
    plan = parse_plan(_plan([{"object": 1, "to": [0.25, 0.15, 0.5], "on": None}], 1))
    assert lgmcts.check(scene, plan.goals, plan, robot="ur5e").valid  # reachable: only the links collide
    assert execute_plan(scene, plan).success
    res = execute_plan(scene, plan, robot="ur5e")
    assert not res.success
    msg = res.steps[0].message
    assert "arm collision: the forearm touched object 2" in msg and "moved it" in msg


@pytest.mark.slow
def test_full_pick_and_place_with_the_arm():
    scene = parse_scene(BOTTLE)
    # The bottle moved out of the way first, then the block turned by 1 rad.
    plan = parse_plan(
        _plan([{"object": 2, "to": [-0.3, 0.2, 0.0], "on": None}, {"object": 1, "to": [0.2, 0.0, 1.0], "on": None}], 1)
    )
    res = execute_plan(scene, plan, robot="ur5e")
    assert res.success, res.reasons
    assert [s.ok for s in res.steps] == [True, True]
    x, y, th = res.steps[1].reached
    assert math.hypot(x - 0.2, y) < 0.005
    assert abs(math.remainder(th - 1.0, math.pi / 2)) < 0.03  # a cube: its yaw modulo a quarter turn
    assert res.sim_time > 3.0  # the arm takes real time


@pytest.mark.slow
def test_arm_is_driven_through_physics_and_drop_is_named():
    from lgmcts.sim.arm_exec import ArmExecutor, ArmOptions
    from lgmcts.sim.model import build_model

    scene = parse_scene(BOTTLE)
    sim = build_model(scene, robot="ur5e")
    # A cup that holds less than the block's weight (62.5 g).
    ex = ArmExecutor(sim, arm=ArmOptions(hold_force=0.3))
    q0 = ex.q
    out = ex.pick_and_place(0, np.array([-0.2, 0.15, 0.0]), None, index=1)
    assert not out.ok and "dropped in transfer" in out.message
    assert not np.allclose(ex.q, q0)
    # Joints move only through the actuators: targets stay within the limits.
    assert np.all(np.abs(ex.data.ctrl[sim.arm.actuators]) <= np.array(UR5E.upper) + 1e-9)


@pytest.mark.slow
def test_cli_plan_check_execute_with_robot(tmp_path, example_scene):
    plan_path = tmp_path / "plan.json"
    res = runner.invoke(
        app,
        [
            "plan",
            str(example_scene),
            "put the white bottle behind the red block",
            "--robot",
            "ur5e",
            "--seed",
            "0",
            "-o",
            str(plan_path),
        ],
    )
    assert res.exit_code == 0, res.output
    plan = json.loads(plan_path.read_text())
    assert plan["stats"]["robot"] == "ur5e"
    goals = tmp_path / "goals.json"
    goals.write_text(json.dumps(plan["goals"]))
    res = runner.invoke(app, ["check", str(example_scene), str(goals), str(plan_path), "--robot", "ur5e"])
    assert res.exit_code == 0, res.output
    res = runner.invoke(app, ["execute", str(example_scene), str(plan_path), "--robot", "ur5e"])
    assert res.exit_code == 0, res.output
    assert "success" in res.stdout
    for cmd in (
        ["execute", str(example_scene), str(plan_path)],
        ["check", str(example_scene), str(goals), str(plan_path)],
    ):
        res = runner.invoke(app, [*cmd, "--robot", "ur9"])
        assert res.exit_code == 2 and "unknown robot" in res.output


def test_plan_with_robot_keeps_every_pose_reachable():
    # Two blocks to go left of a bowl near the far right corner of a wide table:
    # much of that region is beyond the arm.
    box = {"type": "box", "size": [0.05, 0.05, 0.05]}
    scene = parse_scene(
        {
            "workspace": WIDE,
            "objects": [
                {"id": 1, "name": "block", "color": "red", "shape": box, "pose": [0.0, 0.0, 0.0]},
                {"id": 2, "name": "block", "color": "blue", "shape": box, "pose": [0.1, 0.0, 0.0]},
                {
                    "id": 3,
                    "name": "bowl",
                    "color": "green",
                    "shape": {"type": "cylinder", "radius": 0.05, "height": 0.04},
                    "pose": [0.45, 0.4, 0.0],
                },
            ],
        }
    )
    goals = {"goals": [{"pattern": "left", "objects": [1, 2], "anchor": 3}]}
    from lgmcts.robot import plan_reach_problems
    from lgmcts.scene import Scene

    sc = Scene.from_spec(scene)
    plain_out = 0
    for seed in range(6):
        plain = lgmcts.plan(scene, goals, seed=seed)
        plain_out += bool(plan_reach_problems(sc, plain.actions, "ur5e"))
        plan = lgmcts.plan(scene, goals, seed=seed, robot="ur5e")
        assert plan.solved
        assert plan_reach_problems(sc, plan.actions, "ur5e") == []
        assert lgmcts.check(scene, goals, plan, robot="ur5e").valid
    assert plain_out > 0  # without the robot some plans do leave its reach


def test_robot_does_not_change_plans_without_it(example_scene, example_goals):
    a = lgmcts.plan(load_scene(example_scene), load_goals(example_goals), seed=0)
    b = lgmcts.plan(load_scene(example_scene), load_goals(example_goals), seed=0, robot=None)
    assert [x.model_dump() for x in a.actions] == [x.model_dump() for x in b.actions]
    assert "robot" not in a.stats


def test_unknown_robot_is_bad_input(example_scene, example_goals):
    with pytest.raises(lgmcts.InputError, match="unknown robot"):
        lgmcts.plan(load_scene(example_scene), load_goals(example_goals), robot="ur9")


@pytest.mark.slow
def test_arm_execution_is_deterministic():
    scene = parse_scene(BOTTLE)
    plan = parse_plan(
        _plan([{"object": 2, "to": [-0.3, 0.2, 0.0], "on": None}, {"object": 1, "to": [0.2, 0.0, 1.0], "on": None}], 1)
    )
    a = execute_plan(scene, plan, robot="ur5e")
    b = execute_plan(scene, plan, robot="ur5e")
    assert [o.pose for o in a.final.objects] == [o.pose for o in b.final.objects]
    assert a.sim_time == b.sim_time


def test_plan_names_objects_out_of_reach():
    scene = parse_scene(
        {
            "workspace": WIDE,
            "objects": [
                {
                    "id": 1,
                    "name": "block",
                    "color": "red",
                    "shape": {"type": "box", "size": [0.05, 0.05, 0.05]},
                    "pose": [0.62, 0.52, 0.0],
                },
                {
                    "id": 2,
                    "name": "block",
                    "color": "blue",
                    "shape": {"type": "box", "size": [0.05, 0.05, 0.05]},
                    "pose": [0.0, 0.1, 0.0],
                },
            ],
        }
    )
    goals = {"goals": [{"pattern": "left", "objects": [1], "anchor": 2}]}
    plan = lgmcts.plan(scene, goals, seed=0, max_iter=50, robot="ur5e")
    assert not plan.solved and plan.stats["out_of_reach"] == [1]
    assert lgmcts.plan(scene, goals, seed=0, max_iter=50).solved
