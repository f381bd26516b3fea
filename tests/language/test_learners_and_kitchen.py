"""End to end: a learner's English, a cook's shorthand, and requests built with a group said first.

Each case is read on a small table of cylinders (:func:`tables.cylinders`); the refusals check that a
phrasing read here never swallows what it cannot place.
"""

from __future__ import annotations

import pytest

from lgmcts.errors import InputError
from lgmcts.language import parse
from tables import cylinders, goals_of

#: 1 plate, 2-4 cans (red, white, blue), 5-6 mugs (red, blue), 7 box, 8-9 bowls (white, green).
_SCENE = cylinders([("plate", "white", 0.0, 0.0), ("can", "red", -0.25, 0.1), ("can", "white", -0.1, -0.2),
                    ("can", "blue", 0.3, -0.15), ("mug", "red", 0.15, 0.2), ("mug", "blue", -0.3, -0.15),
                    ("box", "brown", 0.1, -0.05), ("bowl", "white", 0.25, 0.1), ("bowl", "green", -0.1, 0.2)])


@pytest.mark.parametrize("said, goals", [
    # a learner's grammar: the object first, "him" for a thing, "apart of", "only not", "besides"
    ("the most left can, put him in front of the plate", [{"pattern": "front", "objects": [2], "anchor": 1}]),
    ("the red mug, put him right of the box, and the blue mug put in front of him",
     [{"pattern": "right", "objects": [5], "anchor": 7}, {"pattern": "front", "objects": [6], "anchor": 5}]),
    ("all cans apart of red one, in a line", [{"pattern": "line", "objects": [3, 4]}]),
    ("every can, only not white, make line", [{"pattern": "line", "objects": [2, 4]}]),
    ("all the cans besides the blue one, put them in one row", [{"pattern": "line", "objects": [2, 3]}]),
    ("all cans exept the white, put in line", [{"pattern": "line", "objects": [2, 4]}]),
    ("all white things, without the plate, make a line", [{"pattern": "line", "objects": [3, 8]}]),
    ("the cans put in one line, length of line 250 mm", [{"pattern": "line", "objects": [2, 3, 4], "size": 0.25}]),
    ("Put the cans in a row, the row is long 0.4 metre.", [{"pattern": "line", "objects": [2, 3, 4], "size": 0.4}]),
    ("the box put on the point x 20 cm, y minus 10 cm", [{"pattern": "pose", "objects": [7],
                                                          "pose": (0.2, -0.1, 0.0)}]),
    ("red mug put on right side of plate and more to front", [{"pattern": "right_front", "objects": [5],
                                                               "anchor": 1}]),
    ("the can which is most to right, put in front of plate", [{"pattern": "front", "objects": [4], "anchor": 1}]),
    ("the bowl who have colour of the red mug, put left of the box", None),   # no bowl is red: refused
    ("the second-leftmost can on the table, put it behind the box", [{"pattern": "behind", "objects": [3],
                                                                      "anchor": 7}]),
    ("third can from left side, place behind of the plate", [{"pattern": "behind", "objects": [4], "anchor": 1}]),
    # a cook: the pass is the near edge, "86" leaves out, "on the fly" asks nothing
    ("cans in a line facing the pass", [{"pattern": "line", "objects": [2, 3, 4], "facing": "south"}]),
    ("Cans. One line, 30 cm end to end, along the pass. Heard?", [{"pattern": "line", "objects": [2, 3, 4],
                                                                   "size": 0.3, "region": "bottom"}]),
    ("all cans, 86 the white one, line along the front", [{"pattern": "line", "objects": [2, 4],
                                                           "region": "bottom"}]),
    ("cans -- circle, radius 0.12 m. on the fly!", [{"pattern": "circle", "objects": [2, 3, 4], "size": 0.12}]),
    ("12-top coming in at eight. I need the cans lined up along the back.", [{"pattern": "line",
                                                                               "objects": [2, 3, 4], "region": "top"}]),
    ("When he gets here I want the cans in a row across the back.", [{"pattern": "line", "objects": [2, 3, 4],
                                                                      "region": "top"}]),
    ("line the cans up when you get a chance", [{"pattern": "line", "objects": [2, 3, 4]}]),
    ("Line up the cans -- no, wait, the mugs.", [{"pattern": "line", "objects": [5, 6]}]),
    ("the cans and the mugs each in their own line", [{"pattern": "line", "objects": [2, 3, 4]},
                                                      {"pattern": "line", "objects": [5, 6]}]),
    ("put the cans and the bowls in separate rows", [{"pattern": "line", "objects": [2, 3, 4]},
                                                     {"pattern": "line", "objects": [8, 9]}]),
    ("fire! mugs in a row at the pass, all day", [{"pattern": "line", "objects": [5, 6], "region": "bottom"}]),
    ("please make for me a circle with all cans, not so big", [{"pattern": "circle", "objects": [2, 3, 4],
                                                                "size": "small"}]),
    ("red can, white can, blue can. circle. small. go.", [{"pattern": "circle", "objects": [2, 3, 4],
                                                           "size": "small"}]),
    ("put the red mug near of the box, on his left side", [{"pattern": "left", "objects": [5], "anchor": 7}]),
    ("three cans (red, white, blue) make line in middle of table", [{"pattern": "line", "objects": [2, 3, 4],
                                                                     "region": "middle center"}]),
    ("all cans except of white make line", [{"pattern": "line", "objects": [2, 4]}]),
    ("mugs: stack, blue on bottom. heard?", [{"pattern": "tower", "objects": [6, 5]}]),
    ("86 the box, everything else in a big circle", [{"pattern": "circle", "objects": [1, 2, 3, 4, 5, 6, 8, 9],
                                                      "size": "large"}]),
    ("Could you stack the red, the white and the blue can? Blue down, red up.", [{"pattern": "tower",
                                                                                  "objects": [4, 3, 2]}]),
    ("Every can except the blue one, in a row, toward me.", [{"pattern": "line", "objects": [2, 3],
                                                              "facing": "south"}]),
    ("cans in row, between them 10 cm", [{"pattern": "line", "objects": [2, 3, 4], "size": 0.2}]),
    ("stack all three cans, rainbow order from the bottom", None),   # an order by colour is not read: refused
    ("Mugs. Line. Back right. Small.", [{"pattern": "line", "objects": [5, 6], "region": "top right",
                                         "size": "small"}]),
    ("Cans! Line! Front! Facing away!", [{"pattern": "line", "objects": [2, 3, 4], "region": "bottom",
                                          "facing": "north"}]),
    ("cans in a row. tight. back left.", [{"pattern": "line", "objects": [2, 3, 4], "region": "top left",
                                           "size": "small"}]),
    ("put the red mug in the front of the box, little bit to left", [{"pattern": "left_front", "objects": [5],
                                                                      "anchor": 7}]),
    ("put the blue mug behind the box, a bit more to the right", [{"pattern": "right_behind", "objects": [6],
                                                                   "anchor": 7}]),
    ("make the cans in line vertical, from front to back", [{"pattern": "line", "objects": [2, 3, 4]}]),
    ("it is necessary that the mugs stand one on other, red under", [{"pattern": "tower", "objects": [5, 6]}]),
    # after the one measurement of the test half
    ("mugs all two one on other, blue down, red up, the others how you like", [{"pattern": "tower",
                                                                                 "objects": [6, 5]}]),
    ("stack the cans, the red on bottom and the red also on top", None),   # one object, two places
    ("From two mugs, the one more far from me put left of the box", [{"pattern": "left", "objects": [5],
                                                                      "anchor": 7}]),
    ("the can most near to me and the can most far, make line with them and the box",
     [{"pattern": "line", "objects": [3, 2, 7]}]),
    ("knife fork spoon. middle row. line. go go go", None),   # no knife here: refused, not read past
    ("cans. middle row. line. go go go", [{"pattern": "line", "objects": [2, 3, 4], "region": "middle row"}]),
    ("Can all the cans form a line, everything facing the left edge?", [{"pattern": "line", "objects": [2, 3, 4],
                                                                        "facing": "west"}]),
    ("the can which have same colour like the mug red, put it right from the plate",
     [{"pattern": "right", "objects": [2], "anchor": 1}]),
    ("make tower: red in bottom, then white, then blue on the top", None),   # cans and mugs are red: unclear
    ("cans make circle and they look to the back wall", [{"pattern": "circle", "objects": [2, 3, 4],
                                                          "facing": "north"}]),
    ("mugs and cans in square, face them toward near edge", [{"pattern": "rectangle", "objects": [5, 6, 2, 3, 4],
                                                               "facing": "south"}]),
    ("Everything white on the table, ring it up, 15 cm radius.", [{"pattern": "circle", "objects": [1, 3, 8],
                                                                   "size": 0.15}]),
    ("the cans, three, make line, all of them pointing to left side of table",
     [{"pattern": "line", "objects": [2, 3, 4], "facing": "west"}]),
    ("Not the red mug, the other one. Put it in front of the box.", [{"pattern": "front", "objects": [6],
                                                                      "anchor": 7}]),
    ("the spun put in frunt of the bol", None),   # no spoon here
    ("cans, all but the rightmost, line.", [{"pattern": "line", "objects": [2, 3]}]),
    ("Make a circle out of the cans. I'd like it roughly 24 cm across, nothing bigger.",
     [{"pattern": "circle", "objects": [2, 3, 4], "size": 0.12}]),
    ("cans in a circle, small one", [{"pattern": "circle", "objects": [2, 3, 4], "size": "small"}]),
    ("cans in a cirlce, smal one", [{"pattern": "circle", "objects": [2, 3, 4], "size": "small"}]),
    ("a couple of the cans behind the plate", [{"pattern": "behind", "objects": [2, 3], "anchor": 1}]),
    ("the mugs, stack 'em, red one under the other", [{"pattern": "tower", "objects": [5, 6]}]),
    ("stack the cans: red, white, blue, bottom to top", [{"pattern": "tower", "objects": [2, 3, 4]}]),
    ("stack the cans: blue, white, red, bottom to top", [{"pattern": "tower", "objects": [4, 3, 2]}]),
])
def test_a_learner_and_a_cook(said, goals):
    if goals is None:
        with pytest.raises(InputError):
            parse(_SCENE, said)
        return
    assert goals_of(_SCENE, said) == goals


@pytest.mark.parametrize("said, goals", [
    ("There is two mugs. Red one put left of the plate and the other one to right of it",
     [{"pattern": "left", "objects": [5], "anchor": 1}, {"pattern": "right", "objects": [6], "anchor": 1}]),
    ("Two mugs. The one closer to me goes right of the plate.", [{"pattern": "right", "objects": [6], "anchor": 1}]),
    ("red can and blue can: the first one behind the box, the other one in front of same box",
     [{"pattern": "behind", "objects": [2], "anchor": 7}, {"pattern": "front", "objects": [4], "anchor": 7}]),
    ("there are two bowls; the white one left of the box, and the other one right of it",
     [{"pattern": "left", "objects": [8], "anchor": 7}, {"pattern": "right", "objects": [9], "anchor": 7}]),
    # a group said first that nothing after it chooses among stays what it was
    ("The two mugs are by the sink. Take them and put them behind the box.",
     [{"pattern": "behind", "objects": [5, 6], "anchor": 7}]),
    ("Not the red one, the other mug. Put that one on the left side of the plate.",
     [{"pattern": "left", "objects": [6], "anchor": 1}]),
])
def test_a_group_said_first(said, goals):
    assert goals_of(_SCENE, said) == goals


@pytest.mark.parametrize("said, order", [
    ("stack the cans from the one closest to me at the bottom to the one furthest away at the top", [3, 4, 2]),
    ("stack the cans with the one furthest back at the bottom", [2, 4, 3]),
    ("stack the cans, leftmost at the bottom", [2, 3, 4]),
])
def test_a_stack_from_the_nearest_at_the_bottom(said, order):
    (goal,) = goals_of(_SCENE, said)
    assert goal["pattern"] == "tower" and goal["objects"] == order


def test_a_stack_by_place_too_close_to_tell_is_refused():
    close = cylinders([("can", "red", -0.2, 0.1), ("can", "green", -0.3, 0.11), ("can", "blue", 0.3, -0.2)])
    with pytest.raises(InputError, match="unclear"):
        parse(close, "stack the cans with the one nearest the front at the bottom")
