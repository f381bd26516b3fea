"""Instructions written as steps, asides in brackets, reported speech and dialect words (issue 24, round 16).

Each stage is tested on its own (a case it reads and one it must leave alone), then end to end through
:func:`lgmcts.language.rules.parse_rules` on the scenes of ``fresh16_cases.jsonl``.
"""

from __future__ import annotations

import pytest

from lgmcts.language.asides import bracketed
from lgmcts.language.context import _reported
from lgmcts.language.steps import finding_steps
from tables import assert_reads, scenes_of

_SCENES = scenes_of("fresh16_cases.jsonl")
_OBJ = {"mugs", "mug", "bowl", "can", "red", "cans", "star", "pan", "plate"}.__contains__
_REQ = {"line", "back", "middle", "edge", "long", "order", "any", "behind", "left"}.__contains__


# -- asides -------------------------------------------------------------------------------------------------

def test_aside_that_explains_goes() -> None:
    assert bracketed("a circle of the cans, radius 15 cm (that's from the middle to the edge!).", _OBJ, _REQ) == \
        "a circle of the cans, radius 15 cm."


def test_aside_that_repeats_a_number_goes_and_a_new_number_stays() -> None:
    assert bracketed("a rectangle 30 by 20 cm. (Remember: the LONG side is 30 cm.)", _OBJ, _REQ) == \
        "a rectangle 30 by 20 cm."
    assert bracketed("the cans in a line (40 cm long)", _OBJ, _REQ) == "the cans in a line (40 cm long)"


def test_aside_with_a_new_place_or_order_stays() -> None:
    for text in ("the cans in a line (at the back)", "stack the cans (any order)"):
        assert bracketed(text, _OBJ, _REQ) == text


def test_aside_makes_a_pronoun_plain() -> None:
    assert bracketed("put the pan behind it (the star, I mean).", _OBJ, _REQ) == "put the pan behind the star."
    # an object in brackets after a noun, not a pronoun, is left to the parser
    text = "put the can (the red one) behind the plate"
    assert bracketed(text, _OBJ, _REQ) == text


# -- finding steps ------------------------------------------------------------------------------------------

def test_finding_step_becomes_the_topic() -> None:
    assert finding_steps("1. Find the two mugs. 2. Put the red one behind the bowl.", _OBJ) == \
        "the two mugs: Put the red one behind the bowl."


def test_finding_step_completes_an_open_comparison() -> None:
    got = finding_steps("Look at the red bowl. Find the can that is the same colour. Put that can behind the plate.",
                        _OBJ)
    assert got == "Find the can that is the same colour as the red bowl. Put that can behind the plate."


def test_finding_step_that_does_more_or_ends_the_command_is_kept() -> None:
    for text in ("Find the cans and put them in a line.", "Put the mug behind the bowl. Find the plate."):
        assert finding_steps(text, _OBJ) == text


# -- reported speech ----------------------------------------------------------------------------------------

def test_reported_speech() -> None:
    assert _reported("my mum always said a proper table has the knife on the right of the plate".split())
    assert _reported("our jamie reckons you can't do a ring".split())
    assert not _reported("my wife says the cans should go in a line".split())  # a wish relayed
    assert not _reported("put the knife right of the plate".split())


# -- end to end ---------------------------------------------------------------------------------------------

@pytest.mark.parametrize("scene,text,expected", [
    ("home", "1. Find the two mugs. 2. Put the red one behind the white plate. 3. Put the other one in front of "
             "the plate.", [{"pattern": "behind", "objects": [1], "anchor": 8},
                            {"pattern": "front", "objects": [2], "anchor": 8}]),
    ("pantry", "1. Look at the red bowl. 2. Find the can that is the same colour. 3. Put that can behind the box.",
     [{"pattern": "behind", "objects": [1], "anchor": 10}]),
    ("toys", "Find letter A and letter E. Put them in a line with the star, and then put the pan behind it (the "
             "star, I mean).", [{"pattern": "line", "objects": [1, 4, 10]},
                                {"pattern": "behind", "objects": [12], "anchor": 10}]),
    ("home", "Put the red, green and white cans in a line. Make the line 30 cm long (use your ruler!).",
     [{"pattern": "line", "objects": [12, 14, 13], "size": 0.3}]),
    ("dinner", "My mum always said a proper table has the knife on the right of the plate. So please put the "
               "knife to the right of the plate.", [{"pattern": "right", "objects": [4], "anchor": 1}]),
    ("toys", "Our Jamie reckons you can't do a ring. Prove him wrong, put the star, the heart and the pan in a "
             "circle.", [{"pattern": "circle", "objects": [10, 11, 12]}]),
    ("home", "Could you be a love and pop them three cans in a row for us?",
     [{"pattern": "line", "objects": [12, 13, 14]}]),
    ("pantry", "Them two cups, bung 'em in a row with the box.", [{"pattern": "line", "objects": [8, 9, 10]}]),
    ("blocks", "Shove the red block round the back of the black bowl, ta.",
     [{"pattern": "behind", "objects": [1], "anchor": 8}]),
    ("home", "Put the can what's the same colour as the green bowl in front of the white bottle.",
     [{"pattern": "front", "objects": [14], "anchor": 6}]),
    ("pantry", "Put the cans that are the same colour as the bowls in a line.",
     [{"pattern": "line", "objects": [1, 2, 3]}]),
    ("blocks", "Put all the blocks in a circle. Every block should face north.",
     [{"pattern": "circle", "objects": [1, 2, 3, 4, 5, 6], "facing": "north"}]),
    ("toys", "Pop the star next to the pan, please.", [{"pattern": "left", "objects": [10], "anchor": 12}]),
    ("toys", "Put the letters in a row facing north... oh no, forget it. Put the letters in a circle.",
     [{"pattern": "circle", "objects": [1, 2, 3, 4]}]),
    ("home", "Put the white bottle in front of the red mug. Mind the bowl, mind.",
     [{"pattern": "front", "objects": [6], "anchor": 1}]),
    ("home", "cud u pop the red mug behnd the blu bottle ta", [{"pattern": "behind", "objects": [1], "anchor": 7}]),
    ("blocks", "Put the block that is the same colour as a banana to the right of the black bowl.",
     [{"pattern": "right", "objects": [4], "anchor": 8}]),
    ("pantry", "Put the two cans on the left and the bowl on the far right in a ring.",
     [{"pattern": "circle", "objects": [4, 3, 6]}]),
    ("pantry", "Pick up the yellow cup. Put it on the right of the red bowl. Now do the same with the orange cup, "
               "but put it on the left.", [{"pattern": "right", "objects": [8], "anchor": 6},
                                           {"pattern": "left", "objects": [9], "anchor": 6}]),
    ("pantry", "Put the yellow cup behind the red bowl. Now do the same with the orange cup, but in front.",
     [{"pattern": "behind", "objects": [8], "anchor": 6}, {"pattern": "front", "objects": [9], "anchor": 6}]),
    ("home", "Put the can of the same colour as the green bowl behind the bowl whose colour matches that of the "
             "plate.", [{"pattern": "behind", "objects": [14], "anchor": 3}]),
    ("pantry", "Those cans whose colours correspond to the colours of the bowls shall be arranged on a circle.",
     [{"pattern": "circle", "objects": [1, 2, 3]}]),
    ("pantry", "Stack the three bowls with the red bowl at the bottom, then the blue bowl, the white bowl on top.",
     [{"pattern": "tower", "objects": [6, 7, 5]}]),
    ("pantry", "Put the red bowl next to the red can so they can see that they match.",
     [{"pattern": "left", "objects": [6], "anchor": 1}]),
    ("home", "In preparation for this afternoon's inspection, and given that the cleaning staff have left the items "
             "somewhat scattered, the two mugs are to be placed side by side in a line.",
     [{"pattern": "line", "objects": [1, 2]}]),
    ("pantry", "All containers on the table, with the exception of the cans and the brown box, are to be positioned "
               "on a circle.", [{"pattern": "circle", "objects": [5, 6, 7, 8, 9]}]),
    ("dinner", "The fork, the knife and the spoon are to be arranged in a line such that adjacent items are 80 mm "
               "apart.", [{"pattern": "line", "objects": [3, 4, 5], "size": 0.16}]),
    ("home", "The three cans shall be arranged in a line having a length of 0.3 m, measured from the centre of the "
             "first can to the centre of the last.", [{"pattern": "line", "objects": [12, 13, 14], "size": 0.3}]),
    ("blocks", "A rectangle measuring 30 cm by 20 cm shall be formed by the red, yellow, orange and purple blocks, "
               "one block at each corner.", [{"pattern": "rectangle", "objects": [1, 4, 5, 6], "size": 0.3}]),
    ("blocks", "Make a tower with all six blocks. Reading from the top down it should go: red, orange, yellow, green, "
               "blue, purple.", [{"pattern": "tower", "objects": [6, 2, 3, 4, 5, 1]}]),
    ("dinner", "Lunchtime is nearly over and the dinner ladies want everything tidy. Stack the bowl on the plate "
               "(it saves space!) and put the mug right behind the cup.",
     [{"pattern": "tower", "objects": [1, 2]}, {"pattern": "behind", "objects": [6], "anchor": 7}]),
    ("blocks", "Build a tower: purple first, then orange, then green, and finish off with the yellow.",
     [{"pattern": "tower", "objects": [6, 5, 3, 4]}]),
    ("home", "The fork, the knife and the spoon are to be arranged in a row, such row to be situated at the middle "
             "of the right-hand side of the table.", [{"pattern": "line", "objects": [9, 10, 11],
                                                     "region": "middle right"}]),
    ("home", "The white objects, the plate excepted, must be arranged in a line.",
     [{"pattern": "line", "objects": [3, 6, 13]}]),
    ("home", "Of the two bottles, the one nearer to the right-hand edge shall be placed in front of the leftmost mug.",
     [{"pattern": "front", "objects": [7], "anchor": 1}]),
    ("dinner", "The container matching the cup in colour shall be placed to the left of the mug.",
     [{"pattern": "left", "objects": [8], "anchor": 6}]),
    ("dinner", "First, find the middle one of the three silver things (counting from left to right). Next, put it "
               "on the right of the mug.", [{"pattern": "right", "objects": [5], "anchor": 6}]),
])
def test_reads(scene: str, text: str, expected: list[dict]) -> None:
    assert_reads(_SCENES[scene], text, expected)


@pytest.mark.parametrize("scene,text", [
    ("toys", "Arrange the blocks in a heart shape next to the heart."),  # no heart shape in the database
    ("pantry", "Put the can that is the same colour as the bowls in front of the box."),  # which can?
    ("home", "Put the mugs in a line. The red mug should face north."),  # a facing for one object of a line
    ("toys", "Put the letters in a row facing north... oh no, forget it. Leave the letters alone today, please."),
    ("blocks", "Put the block that is the same colour as the banana to the right of the black bowl."),  # no banana
    ("home", "Pop the two mugs in a line facing west... actually no, leave it, never mind, I'll sort it meself."),
    ("dinner", "As discussed at this morning's review, the two bottles were to be placed behind the plate. On "
               "reflection, however, this requirement is hereby withdrawn in its entirety and no action is to be "
               "taken."),
    # the bottom, then the top in a later sentence: a contradiction, never the last one said
    ("pantry", "Stack the three bowls with the red bowl at the bottom. The red bowl must be on top."),
])
def test_refuses(scene: str, text: str) -> None:
    assert_reads(_SCENES[scene], text, None)
