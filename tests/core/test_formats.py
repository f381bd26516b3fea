"""The three JSON formats: round trips and one-line errors for bad input."""

from __future__ import annotations

import json

import pytest
from core_helpers import box, can, goals, scene

from lgmcts import InputError, load_goals, load_plan, load_scene, save_json
from lgmcts.formats import parse_goals, parse_scene
from lgmcts.scene import Scene


def test_example_round_trip(example_scene, example_goals, tmp_path):
    sc = load_scene(example_scene)
    out = tmp_path / "scene.json"
    save_json(sc, out)
    assert load_scene(out) == sc
    gs = load_goals(example_goals)
    save_json(gs, tmp_path / "g.json")
    again = json.loads((tmp_path / "g.json").read_text())
    assert "anchor" not in again["goals"][0]  # unused keys are omitted
    assert load_goals(tmp_path / "g.json") == gs


def test_every_shape_type_builds_a_footprint():
    spec = parse_scene(
        scene(
            box(1, 0.0, 0.0),
            can(2, 0.2, 0.0),
            {
                "id": 3,
                "name": "tile",
                "shape": {"type": "polygon", "points": [[0, 0], [0.04, 0], [0, 0.04]], "height": 0.01},
                "pose": [-0.2, 0.0, 0.3],
            },
            {
                "id": 4,
                "name": "blob",
                "shape": {"type": "points", "points": [[0.1, 0.1, 0.0], [0.14, 0.1, 0.0], [0.12, 0.15, 0.05]]},
            },
        )
    )
    sc = Scene.from_spec(spec)
    assert sc.n == 4
    # A point cloud's pose is derived from its footprint centroid, its height from the z extent.
    x, y, _ = sc.initial.poses[3]
    assert x == pytest.approx(0.12, abs=1e-9) and y == pytest.approx(0.11667, abs=1e-4)
    assert sc.heights[3] == pytest.approx(0.05)
    # Footprint areas (the cylinder's polygon circumscribes its circle).
    areas = [p.area for p in sc.initial.polys]
    assert areas[0] == pytest.approx(0.0016)
    assert 3.1416 * 0.02**2 <= areas[1] <= 3.1416 * 0.02**2 * 1.02
    assert areas[2] == pytest.approx(0.0008)


BAD_SCENES = [
    (
        {"workspace": {"x": [0, 1], "y": [0, 1]}, "objects": [box(1, 0.5, 0.5), box(1, 0.2, 0.2)]},
        "duplicate object id 1",
    ),
    ({"workspace": {"x": [0, 1], "y": [0, 1]}, "objects": [box(1, 0.5, 0.5, on=2), box(2, 0.5, 0.5, on=1)]}, "cycle"),
    ({"workspace": {"x": [0, 1], "y": [0, 1]}, "objects": [box(1, 1.5, 0.5)]}, "outside the workspace"),
    (
        {
            "workspace": {"x": [0, 1], "y": [0, 1]},
            "objects": [
                {"id": 1, "name": "b", "shape": {"type": "box", "size": [0.1, -1, 0.1]}, "pose": [0.5, 0.5, 0]}
            ],
        },
        "box size must be positive",
    ),
    (
        {
            "workspace": {"x": [0, 1], "y": [0, 1]},
            "objects": [{"id": 1, "name": "b", "shape": {"type": "blob"}, "pose": [0.5, 0.5, 0]}],
        },
        "invalid scene",
    ),
    ({"workspace": {"x": [1, 0], "y": [0, 1]}, "objects": [box(1, 0.5, 0.5)]}, "min < max"),
    ({"workspace": {"x": [0, 1], "y": [0, 1]}, "objects": [box(1, 0.5, 0.5, on=7)]}, "unknown object 7"),
    (
        {
            "workspace": {"x": [0, 1], "y": [0, 1]},
            "objects": [
                {
                    "id": 1,
                    "name": "p",
                    "shape": {"type": "polygon", "points": [[0, 0], [1, 1], [2, 2]], "height": 0.1},
                    "pose": [0.5, 0.5, 0],
                }
            ],
        },
        "positive area",
    ),
    ({"workspace": {"x": [0, 1], "y": [0, 1]}, "objects": []}, "no objects"),
]


@pytest.mark.parametrize("data,needle", BAD_SCENES)
def test_bad_scene_is_one_line(data, needle):
    with pytest.raises(InputError) as err:
        Scene.from_spec(parse_scene(data))
    msg = str(err.value)
    assert needle in msg
    assert "\n" not in msg


BAD_GOALS = [
    (goals({"pattern": "line", "objects": [1]}), "a line needs at least 2 objects"),
    (goals({"pattern": "circle", "objects": [1, 2]}), "a circle needs at least 3 objects"),
    (goals({"pattern": "rectangle", "objects": [1, 2, 3]}), "at least 4"),
    (goals({"pattern": "left", "objects": [1]}), "needs an 'anchor'"),
    (goals({"pattern": "left", "objects": [1], "anchor": 1}), "also one of its objects"),
    (goals({"pattern": "spiral", "objects": [1, 2]}), "unknown pattern 'spiral'"),
    (goals({"pattern": "line", "objects": [1, 1]}), "lists an object twice"),
    (goals({"pattern": "pose", "objects": [1]}), "pose goal needs"),
]


@pytest.mark.parametrize("data,needle", BAD_GOALS)
def test_bad_goals_are_one_line(data, needle):
    with pytest.raises(InputError) as err:
        parse_goals(data)
    assert needle in str(err.value)
    assert "\n" not in str(err.value)


def test_goals_checked_against_scene():
    sc = parse_scene(scene(box(1, 0, 0), box(2, 0.1, 0), box(3, 0.2, 0)))
    with pytest.raises(InputError, match="unknown object id 9"):
        parse_goals(goals({"pattern": "line", "objects": [1, 9]})).check_against(sc)
    with pytest.raises(InputError, match="cycle"):
        parse_goals(
            goals({"pattern": "left", "objects": [1], "anchor": 2}, {"pattern": "left", "objects": [2], "anchor": 1})
        ).check_against(sc)
    with pytest.raises(InputError, match="on the table"):
        parse_goals(
            goals({"pattern": "tower", "objects": [1, 2]}, {"pattern": "line", "objects": [2, 3]})
        ).check_against(sc)
    with pytest.raises(InputError, match="two different pose goals"):
        parse_goals(
            goals(
                {"pattern": "pose", "objects": [1], "pose": [0, 0, 0]},
                {"pattern": "pose", "objects": [1], "pose": [0.1, 0, 0]},
            )
        ).check_against(sc)


def test_missing_and_malformed_files(tmp_path):
    with pytest.raises(InputError, match="not found"):
        load_scene(tmp_path / "nope.json")
    bad = tmp_path / "bad.json"
    bad.write_text("{not json")
    with pytest.raises(InputError) as err:
        load_plan(bad)
    assert "\n" not in str(err.value)
