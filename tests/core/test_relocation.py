"""Relocation geometry (lgmcts.planner.relocate): where an obstacle can be
parked and which spot is best, as pure functions of a scene and a state."""

from __future__ import annotations

import numpy as np
import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from lgmcts.formats import parse_scene
from lgmcts.planner.relocate import GRID_STEP, MAX_GRID_CELLS, clear_centres, grid_step, region_scores, snuggest
from lgmcts.scene import Scene


def _scene(boxes, ws=((-0.3, 0.3), (-0.2, 0.2))) -> Scene:
    objs = [{"id": k + 1, "name": "block", "color": "red", "shape": {"type": "box", "size": [s, s, 0.04]},
             "pose": [x, y, t], "on": None} for k, (x, y, t, s) in enumerate(boxes)]
    return Scene.from_spec(parse_scene({"workspace": {"x": list(ws[0]), "y": list(ws[1])}, "objects": objs}))


def test_clear_centres_on_an_empty_table_fill_the_room():
    sc = _scene([(0.0, 0.0, 0.0, 0.04)])
    xy = clear_centres(sc, sc.initial, 0, 0.002)
    r = float(sc.radii[0]) + 0.001
    xmin, xmax, ymin, ymax = sc.bounds
    assert len(xy) == len(np.arange(xmin + r, xmax - r + 1e-12, GRID_STEP)) * len(
        np.arange(ymin + r, ymax - r + 1e-12, GRID_STEP)
    )
    assert (xy[:, 0] >= xmin + r).all() and (xy[:, 0] <= xmax - r + 1e-12).all()


def test_no_room_in_a_workspace_smaller_than_the_object():
    sc = _scene([(0.0, 0.0, 0.0, 0.05)], ws=((-0.03, 0.03), (-0.03, 0.03)))
    assert clear_centres(sc, sc.initial, 0, 0.002).shape == (0, 2)


boxes = st.lists(
    st.tuples(st.floats(-0.25, 0.25), st.floats(-0.15, 0.15), st.floats(-3.1, 3.1), st.floats(0.02, 0.06)),
    min_size=2,
    max_size=6,
)


@settings(max_examples=25, deadline=None)
@given(boxes, st.sampled_from([0.0, 0.002, 0.01]), st.floats(-3.1, 3.1))
def test_clear_centres_are_free_at_any_yaw(rows, clearance, yaw):
    # Start scenes may not overlap: keep rows whose footprints stay apart.
    kept = []
    for row in rows:
        if all(np.hypot(row[0] - k[0], row[1] - k[1]) > (row[3] + k[3]) * 0.75 for k in kept):
            kept.append(row)
    if len(kept) < 2:
        return
    sc = _scene(kept)
    xy = clear_centres(sc, sc.initial, 0, clearance)
    others = np.array([sc.initial.polys[k] for k in range(1, sc.n)], dtype=object)
    for x, y in xy[:: max(1, len(xy) // 40)]:
        fp = shapely.polygons(sc.footprint(0, np.array([x, y, yaw])))
        assert (shapely.distance(fp, others) >= clearance - 1e-9).all()
        assert shapely.box(sc.bounds[0], sc.bounds[2], sc.bounds[1], sc.bounds[3]).contains(fp)


def test_region_scores_count_regions_and_avoid_theirs_above_all():
    regions = np.array([shapely.box(-0.2, -0.1, -0.1, 0.0), shapely.box(0.1, 0.0, 0.2, 0.1)], dtype=object)
    xy = np.array([[-0.15, -0.05], [0.15, 0.05], [0.0, 0.15], [-0.095, -0.05]])
    got = region_scores(regions, np.array([False, True]), xy, 0.01)
    # In region 0 (1 point); in region 1, the one we make room for (1 + 2); clear (0); just touching region 0 (1).
    assert got.tolist() == [1, 3, 0, 1]


def test_snuggest_parks_next_to_a_neighbour_or_the_edge():
    sc = _scene([(0.0, 0.0, 0.0, 0.04), (0.1, 0.0, 0.0, 0.04)])
    xy = np.array([[-0.1, 0.1], [0.16, 0.0], [0.0, 0.1]])
    assert snuggest(sc, sc.initial, 0, xy) == 1  # nearest its neighbour (object 2)
    xy = np.array([[-0.1, 0.1], [-0.29, 0.0]])
    assert snuggest(sc, sc.initial, 0, xy) == 1  # against the left edge


# ------------------------------------------------- bounded grid of centres

@settings(max_examples=25, deadline=None)
@given(boxes, st.sampled_from([0.0, 0.002, 0.01]))
def test_the_window_per_object_keeps_the_same_points_as_the_dense_test(rows, clearance):
    import lgmcts.planner.relocate as rel

    kept = []
    for row in rows:
        if all(np.hypot(row[0] - k[0], row[1] - k[1]) > (row[3] + k[3]) * 0.75 for k in kept):
            kept.append(row)
    sc = _scene(kept)
    old = rel.DENSE_WORK
    try:
        rel.DENSE_WORK = 10**18
        dense = clear_centres(sc, sc.initial, 0, clearance)
        rel.DENSE_WORK = 0
        window = clear_centres(sc, sc.initial, 0, clearance)
    finally:
        rel.DENSE_WORK = old
    assert np.array_equal(dense, window)


@pytest.mark.parametrize("x, y", [((-0.4, 0.4), (-0.3, 0.3)), ((-5.0, 5.0), (-5.0, 5.0)),
                                  ((-1000.0, 1000.0), (-1000.0, 1000.0)), ((-1000.0, 1000.0), (0.0, 0.2)),
                                  ((0.0, 0.05), (-1000.0, 1000.0))])
def test_the_grid_of_centres_is_capped_in_points(x, y):
    step = grid_step(x[0], x[1], y[0], y[1])
    nx = len(np.arange(x[0], x[1] + 1e-12, step))
    ny = len(np.arange(y[0], y[1] + 1e-12, step))
    assert nx * ny <= MAX_GRID_CELLS
    if (x[1] - x[0]) * (y[1] - y[0]) <= 1.0:
        assert step == GRID_STEP  # tables keep the 1 cm grid (and their plans)
    else:
        assert nx * ny > MAX_GRID_CELLS / 1.1  # no coarser than it must be


@pytest.mark.parametrize("half", [100.0, 1000.0])
def test_clear_centres_on_a_huge_workspace_stay_free_and_small(half):
    sc = _scene([(-0.1, 0.0, 0.0, 0.05), (0.1, 0.0, 0.3, 0.05)], ws=((-half, half), (-half, half)))
    xy = clear_centres(sc, sc.initial, 0, 0.002)
    assert 0 < len(xy) <= MAX_GRID_CELLS
    fp_ok = [shapely.distance(shapely.polygons(sc.footprint(0, np.array([x, y, 1.0]))), sc.initial.polys[1]) >= 0.002
             for x, y in xy[:: max(1, len(xy) // 200)]]
    assert all(fp_ok)
    assert (np.abs(xy) <= half).all()


@pytest.mark.parametrize("method", ["lgmcts", "greedy", "pmcts"])
@pytest.mark.parametrize("half", [100.0, 1000.0])
def test_a_relocation_on_a_huge_workspace_costs_little_memory(method, half):
    """Two 5 cm blocks and a pose goal on block 2's spot: block 2 must be
    parked. The grid of parking spots used to cover the workspace at 1 cm
    with float64 temporaries (9.8 GB at +-100 m, 37 GiB at +-1,000 m)."""
    import tracemalloc

    from lgmcts import check, plan

    objs = [{"id": i, "name": "block", "color": "red", "shape": {"type": "box", "size": [0.05, 0.05, 0.05]},
             "pose": [x, 0.0, 0.0], "on": None} for i, x in ((1, -0.1), (2, 0.1))]
    scene = {"workspace": {"x": [-half, half], "y": [-half, half]}, "objects": objs}
    goals = {"goals": [{"pattern": "pose", "objects": [1], "pose": [0.1, 0.0, 0.0]}]}
    tracemalloc.start()
    try:
        p = plan(scene, goals, method=method, max_iter=1000)
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 200 * 2**20, f"{peak / 2**20:.0f} MiB"
    assert p.solved and check(scene, goals, p).valid
    assert [a.purpose for a in p.actions] == ["relocate", "goal"]


def _clear_centres_dense(scene, world, b, clearance):
    # The plain definition: every grid point against every other object.
    xmin, xmax, ymin, ymax = scene.bounds
    r = float(scene.radii[b]) + clearance / 2
    gx = np.arange(xmin + r, xmax - r + 1e-12, GRID_STEP)
    gy = np.arange(ymin + r, ymax - r + 1e-12, GRID_STEP)
    others = np.flatnonzero(np.arange(scene.n) != b)
    reach2 = (scene.radii[others] + scene.radii[b] + clearance + 1e-9) ** 2
    d2 = (gy[None, :, None] - world.poses[others, 1][:, None, None]) ** 2 + (
        gx[None, None, :] - world.poses[others, 0][:, None, None]) ** 2
    free = (d2 > reach2[:, None, None]).all(axis=0)
    jj, ii = np.nonzero(free)
    return np.stack([gx[ii], gy[jj]], axis=1)


@pytest.mark.parametrize("seed", range(6))
def test_clear_centres_matches_the_dense_definition(seed):
    from lgmcts.casegen import random_case

    case = random_case(seed, dense=True)
    sc = Scene.from_spec(case.scene)
    for b in range(0, sc.n, 3):
        for clearance in (0.0, 0.004, 0.02):
            np.testing.assert_array_equal(clear_centres(sc, sc.initial, b, clearance),
                                          _clear_centres_dense(sc, sc.initial, b, clearance))
