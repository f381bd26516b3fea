"""The reading stages of issue 24 through the whole offline parser: measures, facings and places said freely,
references by position, misspellings, context that asks nothing. One crafted command per reading (none is a
command of the held-out sets), on the scenes of tests/language/fresh_cases.jsonl."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from lgmcts.errors import InputError
from lgmcts.formats import parse_scene
from lgmcts.language.positions import find_position_refs
from lgmcts.language.rules import goal_dicts

FILE = Path(__file__).with_name("fresh_cases.jsonl")
SCENES = {r["scene_id"]: parse_scene(r["scene"]) for r in map(json.loads, FILE.read_text().splitlines())
          if "scene_id" in r}


def _goals(scene: str, text: str, matcher) -> list[dict]:
    return goal_dicts(SCENES[scene], text, matcher=matcher)


@pytest.mark.parametrize("scene, text, expect", [
    # measures in numbers: the size of the goal by its pattern
    ("home", "put the cans in a ring with a 12 cm radius", [{"pattern": "circle", "objects": [12, 13, 14], "size": 0.12}]),
    ("home", "the three bowls in a circle 40 cm across", [{"pattern": "circle", "objects": [3, 4, 5], "size": 0.2}]),
    ("home", "the bowls in a row 45 cm long", [{"pattern": "line", "objects": [3, 4, 5], "size": 0.45}]),
    ("home", "the cans in a row, 300 mm long, facing away from me",
     [{"pattern": "line", "objects": [12, 13, 14], "facing": "north", "size": 0.3}]),
    ("pantry", "a square of the four cans, 20 cm each side",
     [{"pattern": "rectangle", "objects": [1, 2, 3, 4], "size": 0.2}]),
    ("pantry", "the cans in a 30 by 15 cm rectangle", [{"pattern": "rectangle", "objects": [1, 2, 3, 4], "size": 0.3}]),
    ("pantry", "line up the bowls with a gap of 12 cm between them",
     [{"pattern": "line", "objects": [5, 6, 7], "size": 0.24}]),
    ("home", "make a small circle of the cans, 20 cm across", [{"pattern": "circle", "objects": [12, 13, 14], "size": 0.1}]),
    # facing by edges and the viewer, on every goal kind
    ("home", "line up the cans facing the back wall", [{"pattern": "line", "objects": [12, 13, 14], "facing": "north"}]),
    ("home", "the fork left of the plate, tines pointing at the right edge",
     [{"pattern": "left", "objects": [9], "anchor": 8, "facing": "east"}]),
    ("home", "stack the mugs, handles toward me", [{"pattern": "tower", "objects": [1, 2], "facing": "south"}]),
    ("pantry", "put the box behind the red can, turned toward the near edge",
     [{"pattern": "behind", "objects": [10], "anchor": 1, "facing": "south"}]),
    # places said freely: a cell never widens
    ("home", "the cans in a row, dead centre", [{"pattern": "line", "objects": [12, 13, 14], "region": "middle center"}]),
    ("home", "the bowls in a line halfway back on the left",
     [{"pattern": "line", "objects": [3, 4, 5], "region": "middle left"}]),
    ("home", "the cans in a row on the right side of the table, halfway back",
     [{"pattern": "line", "objects": [12, 13, 14], "region": "middle right"}]),
    ("home", "the cans in a circle in the near left corner",
     [{"pattern": "circle", "objects": [12, 13, 14], "region": "bottom left"}]),
    ("toys", "the letters in a row, a band across the middle",
     [{"pattern": "line", "objects": [1, 2, 3, 4], "region": "middle row"}]),
    ("blocks", "the blocks in a line, centred left to right, at the front",
     [{"pattern": "line", "objects": [1, 2, 3, 4, 5, 6], "region": "bottom center"}]),
    ("home", "put the cans in a strip along the back", [{"pattern": "line", "objects": [12, 13, 14], "region": "top"}]),
    ("home", "the mugs in a line at the middle of the left edge",
     [{"pattern": "line", "objects": [1, 2], "region": "middle left"}]),
    # references by position, from the poses
    ("home", "put the can furthest to the left in front of the plate", [{"pattern": "front", "objects": [12], "anchor": 8}]),
    ("blocks", "line up the two blocks nearest the back", [{"pattern": "line", "objects": [2, 3]}]),
    ("blocks", "put the third block from the right behind the black bowl",
     [{"pattern": "behind", "objects": [2], "anchor": 8}]),
    ("home", "whatever is closest to the knife, put it left of the plate",
     [{"pattern": "left", "objects": [7], "anchor": 8}]),
    ("home", "the middle one of the three cans goes behind the phone",
     [{"pattern": "behind", "objects": [14], "anchor": 15}]),
    ("pantry", "put the cup nearest the box on the red bowl", [{"pattern": "tower", "objects": [6, 9]}]),
    ("pantry", "the two cans farthest from me in a row", [{"pattern": "line", "objects": [1, 3]}]),
    ("home", "line up every can except the one nearest the plate", [{"pattern": "line", "objects": [12, 13]}]),
    # misspellings, never into another object
    ("home", "put the fork behnd the plate", [{"pattern": "behind", "objects": [9], "anchor": 8}]),
    ("home", "pls make a circel with the cans", [{"pattern": "circle", "objects": [12, 13, 14]}]),
    ("blocks", "put the white bowl on the purple blok", [{"pattern": "tower", "objects": [6, 7]}]),
    ("pantry", "put the white bowl on the brwn box", [{"pattern": "tower", "objects": [10, 5]}]),
    # "its other side": the side opposite the one said before, of the same reference object
    ("home", "put the spoon left of the plate, the fork on its other side",
     [{"pattern": "left", "objects": [11], "anchor": 8}, {"pattern": "right", "objects": [9], "anchor": 8}]),
    ("home", "the red mug goes behind the plate; the blue mug goes on the plate's other side",
     [{"pattern": "behind", "objects": [1], "anchor": 8}, {"pattern": "front", "objects": [2], "anchor": 8}]),
    # references through another object's colour
    ("pantry", "put the cans that don't share a colour with either bowl behind the box",
     [{"pattern": "behind", "objects": [4], "anchor": 10}]),
    ("pantry", "the bowl that matches the blue can goes on the box", [{"pattern": "tower", "objects": [10, 7]}]),
    ("pantry", "the cans that match any of the bowls in colour, in a row", [{"pattern": "line", "objects": [1, 2, 3]}]),
    ("pantry", "put every bowl that has a can of the same colour in a row", [{"pattern": "line", "objects": [5, 6, 7]}]),
    ("home", "the mugs that are not the colour of the plate, in a row", [{"pattern": "line", "objects": [1, 2]}]),
    ("toys", "whichever block matches the colour of the letter nearest the pan goes behind the star",
     [{"pattern": "behind", "objects": [8], "anchor": 10}]),
    # context that asks nothing
    ("home", "my friends come over at six. line up the cans", [{"pattern": "line", "objects": [12, 13, 14]}]),
    ("home", "after lunch, put the fork behind the plate", [{"pattern": "behind", "objects": [9], "anchor": 8}]),
    ("home", "put the spoon in front of the plate before the guests arrive",
     [{"pattern": "front", "objects": [11], "anchor": 8}]),
    ("home", "once the kids are in bed, stack the mugs", [{"pattern": "tower", "objects": [1, 2]}]),
    ("home", "lunch is in ten minutes! put the spoon left of the plate",
     [{"pattern": "left", "objects": [11], "anchor": 8}]),
])
def test_a_reading(scene, text, expect, matcher):
    assert _goals(scene, text, matcher) == expect


@pytest.mark.parametrize("scene, text, says", [
    ("home", "stack the mugs, 30 cm tall", "'30 cm'"),                      # a stack has no size in numbers
    ("home", "put the phone 10 cm left of the plate", "'10 cm'"),           # nor a relation
    ("home", "the cans in a line with a 10 cm radius", "'10 cm radius'"),    # a line has no radius
    ("blocks", "put the leftmost block on the white bowl", "within 2 cm"),  # orange and purple stand 1 cm apart
    ("home", "the middle one of the four bowls goes behind the phone", "speaks of 4"),
    ("blocks", "put the white bowl on the bowx", "names nothing"),          # one edit from two words: left as said
    ("pantry", "line up the cups that share a colour with one of the cans", "selects nothing"),
])
def test_what_cannot_be_read_is_refused_and_quoted(scene, text, says, matcher):
    with pytest.raises(InputError) as exc:
        _goals(scene, text, matcher)
    assert says in str(exc.value)


def test_a_measure_is_never_dropped(matcher):
    # Whatever the parser answers for a command with a measure, the goal carries a number as its size.
    for text in ("the cans in a row 25 cm long", "a 25 cm row of the cans", "the cans in a line, about 25 cm"):
        (goal,) = _goals("home", text, matcher)
        assert goal["size"] == 0.25, text


@pytest.mark.parametrize("text, quoted", [
    ("line up the three cans, by the window", "'by the window'"),         # a place at something not on the table
    ("put the bowls in a circle, in a zigzag", "'in a zigzag'"),           # an arrangement no pattern has
    ("line up the cans, beside the window, thanks", "'beside the window'"),
    ("stack the mugs, under the lamp", "lamp"),
])
def test_an_aside_that_says_where_is_never_dropped(text, quoted, matcher):
    # An aside said apart by commas is dropped only where it asks nothing; one that says where or how with a
    # noun the parser cannot read is refused, quoted.
    with pytest.raises(InputError) as exc:
        _goals("home", text, matcher)
    assert quoted in str(exc.value)


@pytest.mark.parametrize("text", [
    "line up the three cans, by the way", "line up the three cans, in a minute", "line up the three cans, thanks",
    "line up the three cans, if you don't mind",
])
def test_an_aside_that_asks_nothing_is_dropped(text, matcher):
    assert _goals("home", text, matcher) == [{"pattern": "line", "objects": [12, 13, 14]}]


def test_a_place_after_a_reason_is_read(matcher):
    # The reason ends at the comma before a place: "..., since I count them, in the back left corner".
    assert _goals("home", "line up the cans, since I need to count them, in the back left corner", matcher) == [
        {"pattern": "line", "objects": [12, 13, 14], "region": "top left"}]


@pytest.mark.parametrize("scene, text, expect", [
    # a comparative over two candidates is their superlative; after a verb of placing it says where to move
    ("home", "whichever mug is further to the left goes behind the plate",
     [{"pattern": "behind", "objects": [1], "anchor": 8}]),
    ("home", "the bottle nearer to me goes left of the plate", [{"pattern": "left", "objects": [6], "anchor": 8}]),
    ("home", "the mug farther from me goes on the plate", [{"pattern": "tower", "objects": [8, 1]}]),
    # "front-most" said with a hyphen is one word
    ("blocks", "the two front-most blocks go left of the black bowl",
     [{"pattern": "left", "objects": [4, 5], "anchor": 8}]),
    # a match with no attribute said is a match of colour
    ("home", "the can matching the green bowl goes in front of the white bowl",
     [{"pattern": "front", "objects": [14], "anchor": 3}]),
    ("blocks", "rectangle of the red, blue, green and yellow blocks, pointed at the right edge of the table",
     [{"pattern": "rectangle", "objects": [1, 2, 3, 4], "facing": "east"}]),
    ("toys", "all the letters bar the T in a line", [{"pattern": "line", "objects": [1, 2, 4]}]),
    # a colour shared with any one of several objects ("any of the letters", "a bowl")
    ("toys", "arrange the blocks sharing a colour with any of the letters in a circle",
     [{"pattern": "circle", "objects": [5, 6, 7, 8]}]),
    ("pantry", "line up the cans that match one of the bowls in colour", [{"pattern": "line", "objects": [1, 2, 3]}]),
    # "it" after an arrangement, in a clause that only places it, is that arrangement
    ("pantry", "make a square of the three bowls and the box. centre it on the table",
     [{"pattern": "rectangle", "objects": [5, 6, 7, 10], "region": "middle center"}]),
    ("blocks", "all six blocks in a big rectangle, and it should be facing east",
     [{"pattern": "rectangle", "objects": [1, 2, 3, 4, 5, 6], "size": "large", "facing": "east"}]),
    # an ordinal after the head, the middle one after "whichever"
    ("pantry", "the can second from the left goes in front of the white bowl",
     [{"pattern": "front", "objects": [3], "anchor": 5}]),
    ("home", "whichever can is in the middle goes behind the plate", [{"pattern": "behind", "objects": [14], "anchor": 8}]),
    # a sentence that only names objects through a colour, then a request about "them"/"those"
    ("pantry", "The cans that share a colour with any of the bowls. Make a circle out of them.",
     [{"pattern": "circle", "objects": [1, 2, 3]}]),
    ("pantry", "The cans that match the colour of a bowl - put those in a row.",
     [{"pattern": "line", "objects": [1, 2, 3]}]),
    ("home", "the cans on a circle, r = 12 cm", [{"pattern": "circle", "objects": [12, 13, 14], "size": 0.12}]),
    ("home", "the cans in a circle, d = 30 cm", [{"pattern": "circle", "objects": [12, 13, 14], "size": 0.15}]),
])
def test_comparatives_and_matches(scene, text, expect, matcher):
    assert _goals(scene, text, matcher) == expect


@pytest.mark.parametrize("scene, text, says", [
    ("home", "the bowl nearer to me goes behind the plate", "speaks of 2"),   # three bowls: no comparative
])
def test_a_comparative_over_more_than_two_is_refused(scene, text, says, matcher):
    with pytest.raises(InputError) as exc:
        _goals(scene, text, matcher)
    assert says in str(exc.value)


@pytest.mark.parametrize("text", ["move the red mug closer to the plate", "bring the red mug nearer to the plate"])
def test_a_comparative_after_a_verb_of_placing_picks_no_object(text):
    # "bring the red mug nearer to the plate" says where to move the red mug, it does not pick one of two mugs.
    assert find_position_refs(tuple(text.split())) == []
