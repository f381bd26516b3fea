"""Compass points, clock positions and headings (``lgmcts.language.compass``): the sides a clock face and
the compass give, unit by unit, and commands that say them, read end to end on a small table."""

from __future__ import annotations

import pytest

from lgmcts.language.compass import SIDE_OF, clock_side, heading_facing
from tables import cylinders, goals_of


@pytest.mark.parametrize("hour, half, side", [
    (12, False, 0), (3, False, 90), (6, False, 180), (9, False, 270),
    (1, True, 45), (4, True, 135), (7, True, 225), (10, True, 315),
    # between two sides: the nearest (30 degrees from twelve is 15 from 45, 30 from 0)
    (1, False, 45), (2, False, 45), (4, False, 135), (5, False, 135), (12, True, 0), (2, True, 90),
])
def test_a_clock_position_is_the_nearest_of_the_eight_sides(hour, half, side):
    assert clock_side(hour, half) == side


def test_every_whole_and_half_hour_is_nearer_one_side_than_any_other():
    for hour in range(1, 13):
        for half in (False, True):
            angle = (hour % 12) * 30 + 15 * half
            dists = sorted(min(abs(angle - s), 360 - abs(angle - s)) for s in SIDE_OF)
            assert dists[0] < dists[1]
            assert min(abs(angle - clock_side(hour, half)), 360 - abs(angle - clock_side(hour, half))) == dists[0]


def test_headings_are_facings_only_at_the_four_points():
    assert [heading_facing(d) for d in (0, 90, 180, 270, 360)] == ["north", "east", "south", "west", "north"]
    assert heading_facing(45) is None and heading_facing(100) is None


#: 1 plate, 2-3 bowls (white at the back left, black in front), 4-6 blocks (red, blue, green from left to right).
_SCENE = [("plate", "white", 0.25, -0.2), ("bowl", "white", -0.25, 0.2), ("bowl", "black", -0.1, -0.05),
          ("block", "red", -0.3, -0.25), ("block", "blue", 0.0, -0.15), ("block", "green", 0.2, 0.05)]


def _goals(said: str) -> list[dict]:
    return goals_of(cylinders(_SCENE), said)


@pytest.mark.slow
@pytest.mark.parametrize("said, goals", [
    ("put the red block at the plate's three o'clock", [{"pattern": "right", "objects": [4], "anchor": 1}]),
    ("put the red block at the plate's half past four", [{"pattern": "right_front", "objects": [4], "anchor": 1}]),
    # "its" said again as the object it stands for
    ("put the red block at its ten-thirty, the plate I mean", [{"pattern": "left_behind", "objects": [4], "anchor": 1}]),
    ("the red block at three o'clock from the plate", [{"pattern": "right", "objects": [4], "anchor": 1}]),
    ("Look at the plate. The red block goes at its nine o'clock, the blue block at its three.",
     [{"pattern": "left", "objects": [4], "anchor": 1}, {"pattern": "right", "objects": [5], "anchor": 1}]),
    ("the red block to the plate's south-east", [{"pattern": "right_front", "objects": [4], "anchor": 1}]),
    ("the red block due north of the plate", [{"pattern": "behind", "objects": [4], "anchor": 1}]),
    ("the red block front right of the plate and the blue block back left of it",
     [{"pattern": "right_front", "objects": [4], "anchor": 1}, {"pattern": "left_behind", "objects": [5], "anchor": 1}]),
    ("the blocks in a line in the north-west corner", [{"pattern": "line", "objects": [4, 5, 6], "region": "top left"}]),
    ("the blocks in a line down in the south-east", [{"pattern": "line", "objects": [4, 5, 6], "region": "bottom right"}]),
    ("the blocks in a line along the western third", [{"pattern": "line", "objects": [4, 5, 6], "region": "left"}]),
    ("the blocks in a line on the starboard side", [{"pattern": "line", "objects": [4, 5, 6], "region": "right"}]),
    ("the easternmost block behind the black bowl", [{"pattern": "behind", "objects": [6], "anchor": 3}]),
    ("the blocks in a row, heading 090", [{"pattern": "line", "objects": [4, 5, 6], "facing": "east"}]),
    ("the blocks in a row on a heading of 270", [{"pattern": "line", "objects": [4, 5, 6], "facing": "west"}]),
    ("every block save the red one in a line", [{"pattern": "line", "objects": [5, 6]}]),
    ("the blocks in a row, heading zero nine zero", [{"pattern": "line", "objects": [4, 5, 6], "facing": "east"}]),
    ("the blocks in a row, facing due south", [{"pattern": "line", "objects": [4, 5, 6], "facing": "south"}]),
    ("the red block at two o'clock to the plate", [{"pattern": "right_behind", "objects": [4], "anchor": 1}]),
    ("the block farthest east goes behind the plate", [{"pattern": "behind", "objects": [6], "anchor": 1}]),
    ("the most westerly block goes behind the plate", [{"pattern": "behind", "objects": [4], "anchor": 1}]),
    ("the northern bowl goes behind the plate", [{"pattern": "behind", "objects": [2], "anchor": 1}]),
    ("Two bowls here. Put the red block at the white one's six o'clock",
     [{"pattern": "front", "objects": [4], "anchor": 2}]),
])
def test_compass_and_clock_words_read_end_to_end(said, goals):
    assert _goals(said) == goals


@pytest.mark.slow
def test_a_clock_position_of_nothing_named_is_refused():
    from lgmcts.errors import InputError

    with pytest.raises(InputError):
        _goals("put the red block at its ten-thirty")  # "its": nothing named before it


@pytest.mark.slow
def test_a_heading_between_the_four_points_is_refused_not_dropped():
    from lgmcts.errors import InputError

    with pytest.raises(InputError, match="045"):
        _goals("the blocks in a row, heading 045")
    with pytest.raises(InputError, match="135"):
        _goals("the blocks in a row, heading one three five")
