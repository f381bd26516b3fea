"""Phrases for a goal's region, size and facing (lgmcts.language.shapes.take_params)."""

from __future__ import annotations

import pytest

from lgmcts.errors import InputError
from lgmcts.formats import parse_goals
from lgmcts.language.shapes import take_params

_NOUNS = frozenset({"circle", "line", "tower", "row", "ring", "structure", "rectangle"})


def _read(text: str):
    return take_params(tuple(text.replace("-", " ").split()), lambda w: w in _NOUNS)


@pytest.mark.parametrize("text, region, size, facing, rest", [
    ("make a big circle in the top-left corner facing north", "top left", "large", "north", "make a circle"),
    ("small circle in the bottom left of the table facing east", "bottom left", "small", "east", "circle"),
    ("large line in the middle center of the table facing south", "middle center", "large", "south", "line"),
    ("medium tower in the top right of the table facing west", "top right", "medium", "west", "tower"),
    ("a short line near the front edge", "bottom", "small", None, "a line"),
    ("arrange the cans in a row on the right side of the table", "right", None, None, "arrange the cans in a row"),
    ("stack them in the center of the table", "middle center", None, None, "stack them"),
    ("put all blocks in a circle in the middle", "middle center", None, None, "put all blocks in a circle"),
    ("put the red blocks in a large ring in the upper right", "top right", "large", None, "put the red blocks in a ring"),
    ("line up the blocks at the back of the table pointing towards me", "top", None, "south", "line up the blocks"),
    ("a row facing away from the viewer", None, None, "north", "a row"),
    ("a line of cans facing left", None, None, "west", "a line of cans"),
    ("build a small structure facing west", None, "small", "west", "build a structure"),
])
def test_phrases(text, region, size, facing, rest):
    params, words = _read(text)
    assert (params.get("region"), params.get("size"), params.get("facing"), " ".join(words)) == (
        region, size, facing, rest)
    # Whatever is found is a value the goal format accepts.
    goal = {"pattern": "circle", "objects": [1, 2, 3], **params}
    parse_goals([goal])


@pytest.mark.parametrize("text", [
    "put the big bowl to the left of the mug",  # a big object, a relation
    "put the blocks to the left of the bowl",
    "put the mug in front of the bowl",
    "move the left block behind the bowl",
    "put the long pencil on the plate",
])
def test_no_params_where_none_are_said(text):
    params, words = _read(text)
    assert (params, " ".join(words)) == ({}, text)


def test_facing_an_object_is_refused():
    with pytest.raises(InputError, match="facing"):
        _read("a row facing the bowl")
