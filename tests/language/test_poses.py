"""Poses said in numbers (lgmcts.language.poses), at their stage and through the whole parser."""

from __future__ import annotations

import json
import math
from pathlib import Path

import pytest
from hypothesis import given, strategies as st

from lgmcts.errors import InputError
from lgmcts.formats import parse_scene
from lgmcts.language.poses import find_poses, mark_poses
from lgmcts.language.rules import goal_dicts

FILE = Path(__file__).with_name("fresh_cases.jsonl")
SCENES = {r["scene_id"]: parse_scene(r["scene"]) for r in map(json.loads, FILE.read_text().splitlines())
          if "scene_id" in r}


@pytest.mark.parametrize("text, x, y, yaw", [
    ("the mug to x = 0.10 m, y = -0.05 m, yaw 0 rad", 0.10, -0.05, 0.0),
    ("x=10cm, y=-5cm", 0.10, -0.05, None),
    ("x: 100 mm and y: 250 mm, yaw 90 deg", 0.10, 0.25, math.pi / 2),
    ("to x 0.2 y 0.1, rotated by pi/2", 0.2, 0.1, math.pi / 2),
    ("the cup at (10 cm, -5 cm)", 0.10, -0.05, None),
    ("put it at (0.1, 0.2, 3pi/4)", 0.1, 0.2, 3 * math.pi / 4),
    ("x = 12, y = 3 cm", 0.12, 0.03, None),          # a unit said once holds for both
    ("x = 10 cm, y = -20 cm, rotated 90 degrees clockwise", 0.10, -0.20, -math.pi / 2),   # yaw is anticlockwise
    ("x = 10 cm, y = -20 cm, rotated 90 degrees anticlockwise", 0.10, -0.20, math.pi / 2),
    ("x = 10 cm, y = -20 cm, with a yaw of approximately 1.571 rad", 0.10, -0.20, 1.571),
])
def test_find_poses(text, x, y, yaw):
    (p,) = find_poses(text)
    assert p.x == pytest.approx(x) and p.y == pytest.approx(y)
    assert (p.yaw is None) if yaw is None else p.yaw == pytest.approx(yaw)


@pytest.mark.parametrize("text", ["a 25 cm row", "the cans (all three of them) in a row", "stack 3 cups",
                                  "put the box at the back"])
def test_no_pose_is_found_where_none_is_said(text):
    assert find_poses(text) == []
    assert mark_poses(text) == (text, [])


@given(st.floats(-0.5, 0.5, allow_nan=False).map(lambda v: round(v, 3)),
       st.floats(-0.5, 0.5, allow_nan=False).map(lambda v: round(v, 3)))
def test_metres_and_centimetres_read_alike(x, y):
    a = find_poses(f"x = {x} m, y = {y} m")[0]
    b = find_poses(f"x = {round(x * 100, 1)} cm, y = {round(y * 100, 1)} cm")[0]
    assert (a.x, a.y) == pytest.approx((x, y)) and (b.x, b.y) == pytest.approx((x, y))


def test_a_pose_goal_through_the_parser(matcher):
    assert goal_dicts(SCENES["home"], "put the red mug at (10 cm, -5 cm) and stack the cans", matcher=matcher) == [
        {"pattern": "pose", "objects": [1], "pose": [0.1, -0.05, 0.0]},
        {"pattern": "tower", "objects": [12, 13, 14]}]
    (g,) = goal_dicts(SCENES["home"], "move the plate to x=0.2, y=0.1, yaw 90 deg", matcher=matcher)
    assert g["pose"] == pytest.approx([0.2, 0.1, math.pi / 2])


@pytest.mark.parametrize("text", ["the cans to x = 0.1, y = 0",        # a pose is for one object
                                  "the mug to x = 0.1, y = 0"])         # two mugs: which one?
def test_a_pose_for_no_single_object_is_refused(text, matcher):
    with pytest.raises(InputError):
        goal_dicts(SCENES["home"], text, matcher=matcher)


def _at(scene: str, oid: int) -> tuple[float, float, float]:
    pose = SCENES[scene].object(oid).pose
    assert pose is not None
    return float(pose[0]), float(pose[1]), float(pose[2])


@pytest.mark.parametrize("text, dx, dy", [
    ("slide the red mug 10 cm further back from where it sits now, don't turn it", 0.0, 0.1),
    ("move the red mug 8 cm to the left, keep its angle as is", -0.08, 0.0),
    ("nudge the red mug 5 cm toward me and 3 cm to the right", 0.03, -0.05),
    ("shift the red mug forty millimetres to the right", 0.04, 0.0),
])
def test_a_move_by_a_distance_is_a_pose_from_where_the_object_stands(text, dx, dy, matcher):
    x, y, yaw = _at("home", 1)
    (g,) = goal_dicts(SCENES["home"], text, matcher=matcher)
    assert g["pattern"] == "pose" and g["objects"] == [1]
    assert g["pose"] == pytest.approx([x + dx, y + dy, yaw], abs=1e-6)


def test_a_place_from_the_table_centre_and_two_poses_in_one_clause(matcher):
    (g,) = goal_dicts(SCENES["home"], "put the red mug 10 cm right of the table centre and 5 cm toward the back, "
                                      "square to the table with no rotation", matcher=matcher)
    assert g["pose"] == pytest.approx([0.1, 0.05, 0.0])
    got = goal_dicts(SCENES["home"], "put the red mug at x = 15 cm, y = -5 cm, and the plate at (-20 cm, 10 cm). "
                                     "No rotation on either of them.", matcher=matcher)
    assert [(g["objects"], g["pose"]) for g in got] == [([1], [0.15, -0.05, 0.0]), ([8], [-0.2, 0.1, 0.0])]


@pytest.mark.parametrize("text", ["put the red mug 10 cm left of the plate",   # a distance from an object
                                  "the red mug 10 cm to the left"])             # no verb of moving, no centre
def test_a_distance_that_is_no_move_is_no_pose(text):
    assert all(p.frame == "table" for p in mark_poses(text)[1])
    assert mark_poses(text)[1] == []


@pytest.mark.parametrize("text, x, y, yaw", [
    # two distances joined by a comma make one move; a turn said right after it is its yaw (never read past)
    ("box: 250 mm right of centre, 100 mm toward me", 0.25, -0.1, None),
    ("the box 25 cm right of the table centre and 10 cm toward me, rotated 90 degrees counterclockwise",
     0.25, -0.1, math.pi / 2),
    ("the box 25 cm right of centre, 10 cm toward me, turned 90 degrees clockwise", 0.25, -0.1, -math.pi / 2),
    ("slide the box 10 cm further back, rotated by 1.5 rad", 0.0, 0.1, 1.5),
])
def test_a_move_with_its_turn(text, x, y, yaw):
    from lgmcts.language.poses import find_offsets

    (p,) = find_offsets(text)
    assert (round(p.x, 4), round(p.y, 4)) == (x, y)
    assert (p.yaw is None and yaw is None) or abs(p.yaw - yaw) < 1e-9
