"""Phrases for a goal's region, size and facing (lgmcts.language.placement)."""

from __future__ import annotations

import pytest

from lgmcts.formats import parse_goals
from lgmcts.language.placement import find_params


@pytest.mark.parametrize("text, region, size, facing, rest", [
    ("make a big circle in the top-left corner facing north", "top left", "large", "north", "make a circle"),
    ("small circle in the bottom left of the table facing east", "bottom left", "small", "east", "circle"),
    ("large line in the middle center of the table facing south", "middle center", "large", "south", "line"),
    ("medium tower in the top right of the table facing west", "top right", "medium", "west", "tower"),
    ("a short line near the front edge", "bottom", "small", None, "a line"),
    ("arrange the cans in a row on the right side of the table", "right", None, None, "arrange the cans in a row"),
    ("stack them in the center of the table", "center", None, None, "stack them"),
    ("put all blocks in a circle in the middle", "center", None, None, "put all blocks in a circle"),
    ("put the red blocks in a large ring in the upper right", "top right", "large", None, "put the red blocks in a ring"),
    ("line up the blocks at the back of the table pointing towards me", "top", None, "south", "line up the blocks"),
    ("build a small structure facing west", None, "small", "west", "build a structure"),
])
def test_phrases(text, region, size, facing, rest):
    f = find_params(text)
    assert (f.region, f.size, f.facing, f.rest) == (region, size, facing, rest)
    # Whatever is found is a value the goal format accepts.
    goal = {"pattern": "circle", "objects": [1, 2, 3]}
    goal.update({k: v for k, v in (("region", f.region), ("size", f.size), ("facing", f.facing)) if v is not None})
    parse_goals([goal])


@pytest.mark.parametrize("text", [
    "put the big bowl to the left of the mug",  # a big object, a relation
    "put the blocks to the left of the bowl",
    "put the mug in front of the bowl",
    "move the left block behind the bowl",
    "a row facing the bowl",  # facing an object is not a compass direction
    "put the long pencil on the plate",
])
def test_no_params_where_none_are_said(text):
    f = find_params(text)
    assert (f.region, f.size, f.facing, f.rest) == (None, None, None, " ".join(text.split()))
