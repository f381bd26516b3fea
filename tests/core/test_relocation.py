"""Relocation geometry (lgmcts.planner.relocate): where an obstacle can be
parked and which spot is best, as pure functions of a scene and a state."""

from __future__ import annotations

import numpy as np
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st

from lgmcts.formats import parse_scene
from lgmcts.planner.relocate import GRID_STEP, clear_centres, region_scores, snuggest
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
