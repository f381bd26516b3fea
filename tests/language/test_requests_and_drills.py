"""Requests said as the end state wanted, as polite wonders, in a coach's drill words (issue 24, round 17), by a
fed-up user, in a warehouse's words and in a German speaker's English (round 18).

End to end through :func:`lgmcts.language.rules.parse_rules` on the ``home`` and ``toys`` scenes of
``fresh17_cases.jsonl``: each case a sentence of the kind the round's writers used (none of theirs) with the
goals it must give, or None where it must be refused; then the cases the new rows must leave alone.
"""

from __future__ import annotations

import pytest

from lgmcts.errors import InputError
from lgmcts.language.matcher import default_matcher
from lgmcts.language.rules import parse_rules
from tables import assert_reads, scenes_of

_SCENES = scenes_of("fresh17_cases.jsonl")  # (fresh18_cases.jsonl has the same five scenes)

# home: 1 red mug, 2 blue mug, 3 white bowl, 5 blue bowl, 7 blue bottle, 8 white plate, 9 fork, 10 knife,
# 11 spoon, 12 red can, 13 white can, 14 green can; toys: letters 1-4 (A, R, T, E), blocks 5-8 (red, blue, yellow,
# green); pantry: cans 1-4, bowls 5-7.
_CASES = [
    # the end state, said as what the speaker comes back to or expects
    ("home", "I'd like to come back to a table where the cans are in a row along the back.",
     [{"pattern": "line", "objects": [12, 13, 14], "region": "top"}]),
    ("home", "When I'm back, the red can should be sitting behind the white can.",
     [{"pattern": "behind", "objects": [12], "anchor": 13}]),
    ("home", "The green can shouldn't move. The red can should end up behind it.",
     [{"pattern": "behind", "objects": [12], "anchor": 14}]),
    ("home", "The cans in a row, 10 cm apart from one another.",
     [{"pattern": "line", "objects": [12, 13, 14], "size": 0.2}]),
    # polite wonders
    ("home", "Would it be all right to put the red can behind the white can?",
     [{"pattern": "behind", "objects": [12], "anchor": 13}]),
    ("home", "I was wondering whether the robot might put the red mug behind the white bowl?",
     [{"pattern": "behind", "objects": [1], "anchor": 3}]),
    ("home", "If at all possible, could the mugs go in a line? No rush at all.",
     [{"pattern": "line", "objects": [1, 2]}]),
    # a coach's words
    ("home", "Cans, line abreast along the back edge!", [{"pattern": "line", "objects": [12, 13, 14], "region": "top"}]),
    ("home", "Knife, fork and spoon in a huddle, come on, bring it in!",
     [{"pattern": "circle", "objects": [10, 9, 11]}]),
    ("toys", "Square the letters up out on the left wing.",
     [{"pattern": "rectangle", "objects": [1, 2, 3, 4], "region": "left"}]),
    # references
    ("home", "The can that matches the red mug goes in front of that mug.",
     [{"pattern": "front", "objects": [12], "anchor": 1}]),
    ("home", "Whatever's the same colour as the blue mug, put it behind the plate.",
     [{"pattern": "behind", "objects": [5, 7], "anchor": 8}]),
    ("home", "The red can and the white can in a line with the green can between them.",
     [{"pattern": "line", "objects": [12, 14, 13]}]),
    # a fed-up user: the request said again, and asides that ask nothing
    ("home", "Line up the three cans. A straight line. Is that so hard?", [{"pattern": "line", "objects": [12, 13, 14]}]),
    ("home", "The bowls in a circle. Not a square. A circle.", [{"pattern": "circle", "objects": [3, 4, 5]}]),
    ("home", "Put all the cutlery to the left of the plate, apart from the knife. Leave the damn knife.",
     [{"pattern": "left", "objects": [9, 11], "anchor": 8}]),
    # a warehouse's words
    ("pantry", "Get the four cans into one lane for me.", [{"pattern": "line", "objects": [1, 2, 3, 4]}]),
    ("pantry", "Four cans, one in each corner of a square.", [{"pattern": "rectangle", "objects": [1, 2, 3, 4]}]),
    ("pantry", "Stage the three bowls in a lane with 10 cm between each slot.",
     [{"pattern": "line", "objects": [5, 6, 7], "size": 0.2}]),
    ("home", "Put the red mug behind the plate with its handle facing east.",
     [{"pattern": "behind", "objects": [1], "anchor": 8, "facing": "east"}]),
    ("toys", "Stack the four blocks two high - red on blue, yellow on green.",
     [{"pattern": "tower", "objects": [6, 5]}, {"pattern": "tower", "objects": [8, 7]}]),
    ("toys", "Red block in front of the granite bowl, and the blue one in front of that.",
     [{"pattern": "front", "objects": [5], "anchor": 9}, {"pattern": "front", "objects": [6], "anchor": 5}]),
    ("toys", "Put the red block in front of the granite bowl, and the blue block behind that same bowl.",
     [{"pattern": "front", "objects": [5], "anchor": 9}, {"pattern": "behind", "objects": [6], "anchor": 9}]),
    # a German speaker's English
    ("pantry", "The cans shall build a rectangle, 40 times 20 cm.",
     [{"pattern": "rectangle", "objects": [1, 2, 3, 4], "size": 0.4}]),
    ("home", "Put both mugs right from the plate.", [{"pattern": "right", "objects": [1, 2], "anchor": 8}]),
    ("toys", "Make a circle from all letters, only the E not.", [{"pattern": "circle", "objects": [1, 2, 3]}]),
    # pouring is no goal
    ("home", "Pour the blue bottle into the red mug.", None),
    ("home", "Would you mind pouring the blue bottle into the white bowl?", None),
]


@pytest.mark.parametrize("scene, said, goals", _CASES, ids=[c[1][:40] for c in _CASES])
def test_reads(scene: str, said: str, goals: list[dict] | None) -> None:
    assert_reads(_SCENES[scene], said, goals)


def test_pouring_said_as_a_purpose_is_no_refusal() -> None:
    """"so I can pour the tea" tells why; only a pouring asked for is refused."""
    assert_reads(_SCENES["home"], "Could you put the red mug left of the plate so I can pour the tea?",
                 [{"pattern": "left", "objects": [1], "anchor": 8}])
    with pytest.raises(InputError, match="pouring"):
        parse_rules(_SCENES["home"], "Pour the blue bottle into the red mug.", matcher=default_matcher())


def test_the_reference_is_kept_where_whatever_is_the_object() -> None:
    """As an object ("stack up whatever is the same colour as X") the group keeps X, as older sets want."""
    got = parse_rules(_SCENES["home"], "Stack up whatever is the same colour as the blue mug.", matcher=default_matcher())
    assert sorted(got.goals[0].objects) == [2, 5, 7]


def test_a_circle_said_with_up_before_a_place_is_no_huddle() -> None:
    """"a little circle up in the far right corner": a small circle there, not "circle up"."""
    assert_reads(_SCENES["home"], "the bowls in a little circle up in the far right corner",
                 [{"pattern": "circle", "objects": [3, 4, 5], "region": "top right", "size": "small"}])
