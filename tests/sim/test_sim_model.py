"""Building the MuJoCo model: every shape type, stacks, read-back."""

from __future__ import annotations

import math

import mujoco
import numpy as np
import pytest
import shapely
from sim_scenes import ALL_SHAPES

from lgmcts.formats import parse_scene
from lgmcts.scene import TABLE, Scene
from lgmcts.sim import ModelOptions, build_model, physics
from lgmcts.sim.executor import Executor

pytestmark = pytest.mark.slow


def _single(obj: dict) -> dict:
    o = {**obj, "on": None}
    if o["shape"]["type"] != "points":
        o["pose"] = [0.0, 0.0, 0.3]
    return {"workspace": ALL_SHAPES["workspace"], "objects": [o]}


@pytest.mark.parametrize("obj", ALL_SHAPES["objects"][:4], ids=lambda o: o["shape"]["type"])
def test_every_shape_builds_and_rests_where_it_stands(obj):
    spec = parse_scene(_single(obj))
    sim = build_model(spec)
    assert sim.model.ngeom >= 3  # floor, table, gripper cup, the object
    ex = Executor(sim)
    before = physics.poses(sim, ex.data)
    ex.step(100)
    after = physics.poses(sim, ex.data)
    assert np.allclose(before, after, atol=1e-3)
    assert physics.tilts(sim, ex.data)[0] < math.radians(1)
    assert physics.supports(sim, ex.data) == (TABLE,)
    # Resting on the table top: bottom at z = 0 (within the contact softness).
    z = ex.data.xpos[sim.body[0], 2]
    assert z == pytest.approx(sim.heights[0] / 2, abs=1e-3)


def test_geom_types_and_masses(all_shapes):
    sim = build_model(all_shapes, options=ModelOptions(density=1000.0))
    types = [int(sim.model.geom_type[g]) for g in sim.geom]
    mesh = int(mujoco.mjtGeom.mjGEOM_MESH)
    assert types == [int(mujoco.mjtGeom.mjGEOM_BOX), int(mujoco.mjtGeom.mjGEOM_CYLINDER), mesh, mesh,
                     int(mujoco.mjtGeom.mjGEOM_BOX), int(mujoco.mjtGeom.mjGEOM_BOX)]
    mass = sim.model.body_mass[sim.body]
    assert mass[0] == pytest.approx(1000 * 0.06 * 0.04 * 0.05, rel=1e-6)
    assert mass[1] == pytest.approx(1000 * math.pi * 0.03**2 * 0.08, rel=1e-6)
    sc = Scene.from_spec(all_shapes)
    for k in (2, 3):  # extrusions: footprint area times height
        area = shapely.Polygon(sc.local[k]).area
        assert mass[k] == pytest.approx(1000 * area * sc.heights[k], rel=1e-3)


def test_mesh_extrusions_match_the_footprint(all_shapes):
    sim = build_model(all_shapes)
    data = mujoco.MjData(sim.model)
    mujoco.mj_forward(sim.model, data)
    sc = Scene.from_spec(all_shapes)
    for k in (2, 3):
        g = sim.geom[k]
        mid = sim.model.geom_dataid[g]
        a, n = sim.model.mesh_vertadr[mid], sim.model.mesh_vertnum[mid]
        local = sim.model.mesh_vert[a : a + n]
        world = local @ data.geom_xmat[g].reshape(3, 3).T + data.geom_xpos[g]
        got = shapely.MultiPoint(world[:, :2]).convex_hull
        want = sc.initial.polys[k]
        iou = got.intersection(want).area / got.union(want).area
        assert iou > 0.999
        # Bottom on the table, top at the object's height.
        assert world[:, 2].min() == pytest.approx(0.0, abs=1e-6)
        assert world[:, 2].max() == pytest.approx(sc.heights[k], abs=1e-6)


def test_stack_starts_on_its_support_and_reads_back(all_shapes):
    sim = build_model(all_shapes)
    ex = Executor(sim)
    # Object 6 (index 5) sits on object 5 (index 4), whose top is at 0.04 m.
    assert ex.data.xpos[sim.body[5], 2] == pytest.approx(0.04 + 0.02)
    ex.settle()
    poses, sup = ex.state()
    sc = Scene.from_spec(all_shapes)
    assert sup == sc.initial.on
    assert np.allclose(poses[:, :2], sc.initial.poses[:, :2], atol=1e-3)
    yaw_err = (poses[:, 2] - sc.initial.poses[:, 2] + math.pi) % (2 * math.pi) - math.pi
    assert np.abs(yaw_err).max() < 1e-2


def test_unknown_friction_cone_is_rejected(all_shapes):
    with pytest.raises(ValueError, match="friction cone"):
        build_model(all_shapes, options=ModelOptions(cone="round"))


def test_supports_read_back_while_objects_sleep(all_shapes):
    # Objects at rest fall asleep and then report no contacts; the read-back
    # must still see the stack, and a covered object must still be covered.
    sim = build_model(all_shapes)
    ex = Executor(sim)
    ex.step(500)
    assert ex.data.ncon == 0  # everything sleeps
    assert physics.supports(sim, ex.data) == Scene.from_spec(all_shapes).initial.on
    out = ex.pick_and_place(4, np.array([0.0, 0.12, 0.0]), None, index=1)
    assert not out.ok and "covered by object 6" in out.message


def test_contacts_decide_support_when_awake(all_shapes):
    sim = build_model(all_shapes, options=ModelOptions(sleep=False))
    ex = Executor(sim)
    ex.step(100)
    assert ex.data.ncon > 0
    assert physics.supports(sim, ex.data) == Scene.from_spec(all_shapes).initial.on


@pytest.mark.parametrize("sleep", [True, False])
def test_snapshot_restore_replays_an_action_exactly(all_shapes, sleep):
    sim = build_model(all_shapes, options=ModelOptions(sleep=sleep))
    ex = Executor(sim)
    ex.settle()
    snap = ex.snapshot()
    first = ex.pick_and_place(0, np.array([0.0, 0.1, 1.0]), None)
    after_first = ex.data.qpos.copy()
    ex.restore(snap)
    assert np.array_equal(ex.data.qpos, snap.qpos)
    second = ex.pick_and_place(0, np.array([0.0, 0.1, 1.0]), None)
    assert first.ok and first == second
    assert np.array_equal(ex.data.qpos, after_first)
