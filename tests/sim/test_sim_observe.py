"""Perception: depth back-projection, observed clouds, footprint IoU, and
planning on the observed scene then executing on the true one."""

from __future__ import annotations

import math

import numpy as np
import pytest

import lgmcts
from lgmcts.formats import load_goals, load_scene, parse_scene
from lgmcts.sim import CameraOptions, execute_plan, footprint_iou, observe
from lgmcts.sim.render import backproject

pytestmark = pytest.mark.slow

#: On the example the lowest footprint IoU measured is 0.986 (the cylinders,
#: whose reference footprint is a 32-gon) and the mean 0.995 (docs/sim.md).
MIN_IOU = 0.97
MEAN_IOU = 0.99


def test_backproject_flat_table_from_above():
    # A camera 1 m above the origin looking down sees the plane z = 0 at depth 1.
    depth = np.ones((6, 8))
    cam_mat = np.eye(3)  # camera axes = world axes: it looks along -z
    pts = backproject(depth, np.array([0.0, 0.0, 1.0]), cam_mat, fovy_deg=90.0)
    assert np.allclose(pts[..., 2], 0.0)
    # fovy 90 deg: the image spans y in [-1, 1] at depth 1; row 0 is the top (+y).
    f = 3 / math.tan(math.radians(45))
    assert pts[0, 0, 1] == pytest.approx(2.5 / f)
    assert pts[-1, 0, 1] == pytest.approx(-2.5 / f)
    assert pts[0, 0, 0] == pytest.approx(-3.5 / f)


@pytest.fixture(scope="module")
def observed_example(render_ok, example_scene):
    return observe(example_scene)


def test_observed_scene_carries_labels_and_small_clouds(observed_example, example_scene):
    true = load_scene(example_scene)
    seen = {o.id: o for o in observed_example.objects}
    assert set(seen) == {o.id for o in true.objects}
    for o in true.objects:
        s = seen[o.id]
        assert s.shape.type == "points"
        assert 3 <= len(s.shape.points) <= 400
        assert (s.name, s.color, s.on) == (o.name, o.color, o.on)
    # Heights come out right: the bottle is 0.2 m tall, the block on block 2
    # spans 0.05-0.10 m.
    z = np.asarray(seen[5].shape.points)[:, 2]
    assert z.max() - z.min() == pytest.approx(0.2, abs=0.005)
    z3 = np.asarray(seen[3].shape.points)[:, 2]
    assert z3.min() == pytest.approx(0.05, abs=0.005) and z3.max() == pytest.approx(0.10, abs=0.005)


def test_footprint_iou_against_ground_truth(observed_example, example_scene):
    iou = footprint_iou(example_scene, observed_example)
    assert min(iou.values()) >= MIN_IOU, iou
    assert np.mean(list(iou.values())) >= MEAN_IOU


def test_footprint_iou_scores_a_wrong_scene_low(example_scene):
    true = load_scene(example_scene)
    moved = parse_scene(
        {
            "workspace": true.workspace.model_dump(),
            "objects": [
                o.model_copy(update={"pose": (o.pose[0] + 0.03, o.pose[1], o.pose[2])}).model_dump()
                for o in true.objects
            ],
        }
    )
    iou = footprint_iou(true, moved)
    assert iou[1] < 0.5  # a 5 cm block shifted 3 cm
    missing = parse_scene({"workspace": true.workspace.model_dump(), "objects": [true.objects[0].model_dump()]})
    assert footprint_iou(true, missing)[2] == 0.0


def test_plan_on_observed_then_execute_on_true(observed_example, example_scene, example_goals):
    goals = load_goals(example_goals)
    plan = lgmcts.plan(observed_example, goals, seed=0)
    assert plan.solved
    result = execute_plan(example_scene, plan, goals, plan_scene=observed_example)
    assert result.success, result.reasons


def test_observe_with_the_overhead_camera_only_misses_a_hidden_block(render_ok, example_scene):
    # Block 2 lies under block 3 of the same size: only the angled cameras see it.
    seen = observe(example_scene, options=CameraOptions(cameras=("overhead",), width=320, height=240))
    ids = {o.id for o in seen.objects}
    assert 2 not in ids and 3 in ids
    assert {o.id: o.on for o in seen.objects}[3] is None


def test_video_is_written(render_ok, all_shapes, tmp_path):
    import imageio.v2 as imageio

    out = tmp_path / "run.mp4"
    plan = {"solved": True, "actions": [{"object": 1, "to": [-0.05, 0.0, 0.0], "on": None}]}
    result = execute_plan(
        all_shapes, plan, {"goals": [{"pattern": "pose", "objects": [1], "pose": [-0.05, 0.0, 0.0]}]}, video=out
    )
    assert result.success, result.reasons
    frames = imageio.mimread(out, memtest=False)
    # One frame per 1/25 s of simulated time.
    assert abs(len(frames) - round(result.sim_time * 25)) <= 2
    assert frames[0].shape == (480, 640, 3)


def test_observe_rejects_an_unknown_camera(render_ok, example_scene):
    from lgmcts.errors import InputError

    with pytest.raises(InputError, match="unknown camera 'ceiling'"):
        observe(example_scene, options=CameraOptions(cameras=("ceiling",), width=64, height=48))


def test_plan_scene_must_hold_the_same_objects(observed_example, example_scene, example_goals):
    from lgmcts.errors import InputError

    fewer = parse_scene(
        {
            "workspace": observed_example.workspace.model_dump(),
            "objects": [o.model_dump() for o in observed_example.objects[:3]],
        }
    )
    with pytest.raises(InputError, match="same object ids"):
        execute_plan(example_scene, {"solved": True, "actions": []}, example_goals, plan_scene=fewer)
