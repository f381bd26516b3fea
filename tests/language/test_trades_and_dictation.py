"""A carpenter's words (inches and fractions, "on centre", "per the drawing", shop remarks) and a phone's
speech-to-text (homophones, punctuation said aloud, repairs and remarks dictated without punctuation), each
read end to end on a small table; the unclear ones are refused."""

from __future__ import annotations

import pytest

from lgmcts.errors import InputError
from tables import cylinders as _table, goals_of




#: 1 plate; 2-4 bowls (red at the back left, blue at the front, white at the back); 5-7 knife, fork, spoon;
#: 8-9 mugs (red, blue); 10 box; 11-13 blocks (orange, purple, green).
_SCENE = [("plate", "white", 0.25, -0.2), ("bowl", "red", -0.25, 0.2), ("bowl", "blue", -0.05, -0.2),
          ("bowl", "white", 0.1, 0.15), ("knife", "silver", 0.3, 0.1), ("fork", "silver", 0.2, 0.22),
          ("spoon", "silver", -0.3, -0.05), ("mug", "red", -0.15, 0.05), ("mug", "blue", 0.0, 0.25),
          ("box", "brown", 0.32, -0.08), ("block", "orange", -0.35, -0.22), ("block", "purple", -0.2, -0.25),
          ("block", "green", 0.05, 0.0)]


def _goals(said: str, scene=None) -> list[dict]:
    return goals_of(scene or _table(_SCENE), said)


@pytest.mark.slow
@pytest.mark.parametrize("said, goals", [
    # sizes kept to a tenth of a millimetre and rounded once: half of 9 inches is 0.1143 (not half of 0.229)
    ("Bowls in a ring about 9 inches across.", [{"pattern": "circle", "objects": [2, 3, 4], "size": 0.1143}]),
    # fractions with a slash, "in." with its full stop, spacing "on centre" / "o.c." (times the two gaps)
    ("Bowls in a row, 4 1/2 in. o.c.", [{"pattern": "line", "objects": [2, 3, 4], "size": 0.2286}]),
    ("Bowls and plate in a rectangle, 7 1/4 by 11 1/2 in.",
     [{"pattern": "rectangle", "objects": [2, 3, 4, 1], "size": 0.2921}]),
    ("Red, white, blue bowls in a line, 100 mm o.c.", [{"pattern": "line", "objects": [2, 4, 3], "size": 0.2}]),
    # a spacing in a sentence of its own; "square it up" after an arrangement asks for no square
    ("Run the bowls in a line along the front edge. 8 in. on centre. Square it up.",
     [{"pattern": "line", "objects": [2, 3, 4], "region": "bottom", "size": 0.4064}]),
    # "per the drawing": as drawn, nothing on the table
    ("Three bowls, circle 250 mm across per the drawing. Front right.",
     [{"pattern": "circle", "objects": [2, 3, 4], "region": "bottom right", "size": 0.125}]),
    # "pointed" says a facing as "pointing" does; "every one of 'em"; the bench is the table
    ("Knife and fork in a line, pointed away from me.", [{"pattern": "line", "objects": [5, 6], "facing": "north"}]),
    ("Bowls in a circle, every one of 'em pointed at the left end of the bench.",
     [{"pattern": "circle", "objects": [2, 3, 4], "facing": "west"}]),
    # a line running across the table along a row said
    ("Bowls in a line, halfway back, running clean across the table.",
     [{"pattern": "line", "objects": [2, 3, 4], "region": "middle row"}]),
    ("Three pieces of silverware in a row", [{"pattern": "line", "objects": [5, 6, 7]}]),
    # shop remarks that ask nothing
    ("Don't worry about the box, it ships tomorrow. Blue bowl in front of the red mug.",
     [{"pattern": "front", "objects": [3], "anchor": 8}]),
    ("Gonna want the orange and purple blocks stacked, purple on top, before the glue sets.",
     [{"pattern": "tower", "objects": [11, 12]}]),
    # a place from the table's centre said in two distances and a turn said after it in a sentence of its own
    ("Box: 250 mm right of centre, 100 mm toward me. Give it a quarter turn counterclockwise.",
     [{"pattern": "pose", "objects": [10], "pose": (0.25, -0.1, 1.5707963267948966)}]),
    # a side left to the robot: either does what was asked, the left is taken
    ("Spoon next to the box. Either side, don't matter.", [{"pattern": "left", "objects": [7], "anchor": 10}]),
    # "next to" with no side said: either side, the left taken, as when "either side" is said
    ("Spoon next to the box.", [{"pattern": "left", "objects": [7], "anchor": 10}]),
])
def test_a_carpenters_words(said, goals):
    assert _goals(said) == goals


@pytest.mark.slow
@pytest.mark.parametrize("said, goals", [
    # homophones: "centimetre" heard as words (never "a meter": 1 m), colours by the next word
    ("put the bowls in a circle with a fifteen sent a meter radius",
     [{"pattern": "circle", "objects": [2, 3, 4], "size": 0.15}]),
    ("put the bowls in a row thirty centa meters long", [{"pattern": "line", "objects": [2, 3, 4], "size": 0.3}]),
    ("stack the read mug on the blew mug", [{"pattern": "tower", "objects": [9, 8]}]),
    ("put the spoon behind the blew bowl", [{"pattern": "behind", "objects": [7], "anchor": 3}]),
    # punctuation said aloud
    ("okay so dinner's in ten minutes comma the knife should be right of the plate period",
     [{"pattern": "right", "objects": [5], "anchor": 1}]),
    # repairs dictated without commas
    ("put the spoon in front of the red bowl scratch that the white bowl",
     [{"pattern": "front", "objects": [7], "anchor": 4}]),
    ("stack the red mug on the blue no wait I mean the red mug under the blue mug",
     [{"pattern": "tower", "objects": [8, 9]}]),
    # remarks said in the same breath as the request
    ("it's been a long day haha put the spoon in front of the box thanks",
     [{"pattern": "front", "objects": [7], "anchor": 10}]),
    ("honestly it looks fine but I'd like the spoon to be behind the box by the time my wife gets home",
     [{"pattern": "behind", "objects": [7], "anchor": 10}]),
    ("I keep going back and fourth on this but okay put the fork in front of the knife",
     [{"pattern": "front", "objects": [6], "anchor": 5}]),
    ("my daughter built a tower earlier and knocked it over um when you get a chance the purple block goes on "
     "the orange block and the green on the purple", [{"pattern": "tower", "objects": [11, 12, 13]}]),
    # a topic, then "those"; a place after the line's own list of objects is the line's
    ("so like all the bowls except for the white one put those in a line", [{"pattern": "line", "objects": [2, 3]}]),
    ("make a line of the mugs and the spoon at the back in the middle facing the near edge",
     [{"pattern": "line", "objects": [8, 9, 7], "region": "top center", "facing": "south"}]),
    ("make a line of the mugs and the spoon, far from me in the middle",
     [{"pattern": "line", "objects": [8, 9, 7], "region": "top center"}]),
    # a stack ordered by colour pairs that chain and name the whole group
    ("stack the bowls with blue under red and red under white", [{"pattern": "tower", "objects": [3, 2, 4]}]),
])
def test_dictated_by_phone(said, goals):
    assert _goals(said) == goals


@pytest.mark.slow
@pytest.mark.parametrize("said, goals", [
    # a pair said first: "first one", "the other one" (the one of the two the sentence has not named)
    ("Grab the knife and the fork. First one goes left of the plate, the other one right of it.",
     [{"pattern": "left", "objects": [5], "anchor": 1}, {"pattern": "right", "objects": [6], "anchor": 1}]),
    ("Red mug and blue mug. Blue one in front of the box, the other one behind it.",
     [{"pattern": "front", "objects": [9], "anchor": 10}, {"pattern": "behind", "objects": [8], "anchor": 10}]),
    # "the front bowl": the bowl furthest to the front
    ("put the front bowl behind the box", [{"pattern": "behind", "objects": [3], "anchor": 10}]),
    # "any X that ..." taken up by "'em" is every such X; by "it", a free choice of one
    ("Any mug that's the same colour as one of the bowls, line 'em up.", [{"pattern": "line", "objects": [8, 9]}]),
    ("Any mug that's the same colour as one of the bowls, put it behind the box.",
     [{"pattern": "behind", "objects": [8], "anchor": 10}]),
])
def test_references_by_a_pair_a_side_and_any(said, goals):
    assert _goals(said) == goals


@pytest.mark.slow
@pytest.mark.parametrize("said, why", [
    # a line running across the table with no row said: the words are not read past
    ("Bowls in a line, running clean across the table.", "no pattern in the database matches"),
    # "the other one" where the sentence named both of the pair: not guessed
    ("Red mug and blue mug. The mug goes in front of the box, the other one behind it.", "ambiguous"),
    # one colour pair for three bowls: which goes where is not guessed
    ("stack the bowls with blue under red", "named twice"),
    # the middle after the last of an arrangement's list may be that object's place (inside the circle): not guessed
    ("make a circle of the bowls and the spoon in the middle", "'the middle' names nothing"),
    # "square them up" with no arrangement named stays unread
    ("the bowls and the plate, square them up", "refers to nothing"),
])
def test_unclear_ones_are_refused(said, why):
    with pytest.raises(InputError, match=why):
        _goals(said)


@pytest.mark.slow
def test_the_front_bowl_is_refused_when_two_stand_within_two_centimetres():
    scene = _table([("bowl", "red", -0.2, -0.1), ("bowl", "blue", 0.2, -0.11), ("box", "brown", 0.0, 0.2)])
    with pytest.raises(InputError, match="within 2 cm"):
        _goals("put the front bowl behind the box", scene)
    assert _goals("put the left bowl behind the box", scene) == [{"pattern": "behind", "objects": [1], "anchor": 3}]
