"""Phrasings that used to give a wrong goal (goals other than what was said), each read end to end on a small
table: an exception said after a group of two kinds, a size said after the arrangement or on a tower, roles that
turn round a pair said with "on", stack orders said by an arrow, "top first", "the peak" or "sandwiched in
between", objects added by a sentence of their own, a request taken back at its end, a place refined after
"um", and "non-" after "of the". Where no sound reading exists the command is refused with the words quoted."""

from __future__ import annotations

import pytest

from lgmcts.errors import InputError
from tables import cylinders as _table, goals_of




#: 1 plate, 2-4 bowls (white, red, blue), 5-6 cups (yellow, orange), 7-10 blocks (red, blue, green, yellow),
#: 11-12 bottles (white, blue).
_SCENE = [("plate", "white", 0.3, -0.2), ("bowl", "white", -0.3, 0.2), ("bowl", "red", -0.1, 0.2),
          ("bowl", "blue", 0.1, 0.2), ("cup", "yellow", 0.3, 0.2), ("cup", "orange", 0.3, 0.0),
          ("block", "red", -0.3, -0.2), ("block", "blue", -0.15, -0.2), ("block", "green", 0.0, -0.2),
          ("block", "yellow", 0.15, -0.2), ("bottle", "white", -0.3, 0.0), ("bottle", "blue", -0.1, 0.0)]


def _goals(said: str) -> list[dict]:
    return goals_of(_table(_SCENE), said)


def _refusal(said: str) -> str:
    with pytest.raises(InputError) as e:
        _goals(said)
    return str(e.value)


@pytest.mark.slow
@pytest.mark.parametrize("said, pattern, objects", [
    # the noun of the exception is one of the group's nouns: an exception, never dropped
    ("put the cups and the bowls, but not the red bowl, in a ring", "circle", {2, 4, 5, 6}),
    ("all of the bowls and cups, not the white bowl though, in a rectangle", "rectangle", {3, 4, 5, 6}),
    ("arrange all bowls and cups, but not the blue bowl, into a rectangle", "rectangle", {2, 3, 5, 6}),
])
def test_an_exception_after_a_group_of_two_kinds_leaves_it_out(said, pattern, objects):
    (goal,) = _goals(said)
    assert goal["pattern"] == pattern and set(goal["objects"]) == objects


@pytest.mark.slow
def test_only_one_object_not_the_other_stays_a_contrast():
    # a singular before ", not the X," still names the one that moves
    assert _goals("put only the red block, not the blue block, behind the plate") == [
        {"pattern": "behind", "objects": [7], "anchor": 1}]


@pytest.mark.slow
@pytest.mark.parametrize("said, size", [
    ("put the blocks in a row facing west, small", "small"),
    ("put the blocks into a rectangle of medium size", "medium"),
    ("the blocks in a circle, not too big, not too small, at the back", "medium"),
    ("the blocks in a circle, neither too big nor too small", "medium"),
])
def test_a_size_said_after_the_arrangement_is_its_size(said, size):
    (goal,) = _goals(said)
    assert goal["size"] == size


@pytest.mark.slow
@pytest.mark.parametrize("said", ["stack all four blocks into one big tower, any order",
                                  "put every block in one big pile", "make one tall stack of the blocks"])
def test_a_tower_said_big_has_no_size(said):
    (goal,) = _goals(said)
    assert goal["pattern"] == "tower" and sorted(goal["objects"]) == [7, 8, 9, 10] and "size" not in goal


@pytest.mark.slow
def test_a_small_tower_keeps_its_size():
    (goal,) = _goals("build a small tower of the four blocks")
    assert goal["size"] == "small"


@pytest.mark.slow
@pytest.mark.parametrize("said", ["stack the plate on the white bowl with the bowl on top",
                                  "stack the red block on the blue block so that the blue one ends up on top"])
def test_roles_that_turn_a_said_pair_round_are_refused(said):
    assert "disagree" in _refusal(said)


@pytest.mark.slow
@pytest.mark.parametrize("said, objects", [
    ("stack the white bowl on the plate with the bowl on top", [1, 2]),
    ("stack the red block on the blue block, with the green block on top", [8, 7, 9]),
])
def test_roles_that_agree_with_the_pair_are_read(said, objects):
    assert _goals(said) == [{"pattern": "tower", "objects": objects}]


@pytest.mark.slow
@pytest.mark.parametrize("said, objects", [
    ("stack bottom->top: red block, blue block, green block", [7, 8, 9]),
    ("stack, top first: green block, blue block, red block", [7, 8, 9]),
    ("stack, bottom first: green block, blue block, red block", [9, 8, 7]),
    ("stack the red, blue and green blocks! The green one is the foundation, the red one is the peak, "
     "and the blue one gets sandwiched in between!", [9, 8, 7]),
])
def test_a_stack_order_said_by_arrow_first_peak_or_sandwich(said, objects):
    assert _goals(said) == [{"pattern": "tower", "objects": objects}]


@pytest.mark.slow
def test_either_one_on_top_leaves_the_order_open_and_names_no_place():
    (goal,) = _goals("the goal is the two cups stacked, either one on top")
    assert goal["pattern"] == "tower" and sorted(goal["objects"]) == [5, 6] and "region" not in goal


@pytest.mark.slow
def test_the_base_of_a_place_setting_is_no_region():
    goals = _goals("the plate serves as the base with the white bowl on it")
    assert goals == [{"pattern": "tower", "objects": [1, 2]}]


@pytest.mark.slow
@pytest.mark.parametrize("said", ["line up the blocks. Hmm, and the red bowl as well.",
                                  "line up the blocks. and the red bowl too."])
def test_objects_added_in_a_sentence_of_their_own_are_never_dropped(said):
    assert "red bowl" in _refusal(said)


@pytest.mark.slow
@pytest.mark.parametrize("said, quoted", [
    ("stack the bottles, wait no, never mind, don't do anything, thanks", "never mind, don't do anything"),
    ("put the cups in a line. forget it.", "forget it"),
])
def test_a_request_taken_back_at_its_end_is_refused(said, quoted):
    assert quoted in _refusal(said)


@pytest.mark.slow
def test_never_mind_said_about_objects_keeps_the_request():
    assert _goals("never mind the cups, stack the bottles") == [{"pattern": "tower", "objects": [11, 12]}]


@pytest.mark.slow
def test_a_place_refined_at_the_end_with_actually():
    (goal,) = _goals("the blocks in a long line at the back of the table, um, back right actually")
    assert goal["region"] == "top right"


@pytest.mark.slow
def test_a_count_of_the_non_coloured_group():
    (goal,) = _goals("put any two of the non-green blocks in a line")
    assert goal["pattern"] == "line" and len(goal["objects"]) == 2 and set(goal["objects"]) <= {7, 8, 10}


@pytest.mark.slow
def test_adjacent_to_an_object_on_its_left_is_left_of_that_object():
    assert _goals("position the red block adjacent to the blue block on its left") == [
        {"pattern": "left", "objects": [7], "anchor": 8}]


@pytest.mark.slow
def test_a_relation_to_any_of_them_takes_one_anchor():
    goals = _goals("line up the blocks, and put the yellow cup in front of any of them")
    fronts = [g for g in goals if g["pattern"] == "front"]
    assert len(fronts) == 1 and fronts[0]["objects"] == [5] and fronts[0]["anchor"] in (7, 8, 9, 10)


@pytest.mark.slow
@pytest.mark.parametrize("said, pattern", [
    ("Put the three bowls in a circle. Actually, no, a straight line is better.", "line"),
    ("put the three bowls in a line, no wait, a circle", "circle"),
])
def test_an_arrangement_corrected_keeps_only_the_second(said, pattern):
    assert _goals(said) == [{"pattern": pattern, "objects": [2, 3, 4]}]


@pytest.mark.slow
def test_the_same_for_taken_back_leaves_those_objects():
    goals = _goals("blocks in a line, bowls in a circle. The same for the cups? No, leave the cups where they are.")
    assert [g["pattern"] for g in goals] == ["line", "circle"]


@pytest.mark.slow
def test_a_list_ending_in_as_well_is_one_list():
    assert _goals("line up the white bottle, the blue bottle and the red block as well") == [
        {"pattern": "line", "objects": [11, 12, 7]}]


@pytest.mark.slow
def test_a_setting_that_must_not_hold_is_refused():
    from lgmcts.formats import parse_scene
    from lgmcts.language import parse

    scene = parse_scene({"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}, "objects": [
        {"id": k + 1, "name": n, "color": c, "shape": {"type": "cylinder", "radius": 0.03, "height": 0.05},
         "pose": [0.2 * k - 0.4, 0.0, 0.0]}
        for k, (n, c) in enumerate([("plate", "white"), ("bowl", "blue"), ("fork", "silver"), ("knife", "silver"),
                                    ("spoon", "silver")])]})
    with pytest.raises(InputError, match="must not hold"):
        parse(scene, "Dinner time! Set a place, but don't put the cutlery on the left of the plate.")
    goals = parse(scene, "set a place with the cutlery on the right").goals
    assert [(g.pattern, g.anchor) for g in goals][-1] == ("right", 1)


@pytest.mark.slow
def test_on_top_from_is_on_top_of():
    assert _goals("put the white bowl on top from the red bowl") == [{"pattern": "tower", "objects": [3, 2]}]


@pytest.mark.slow
def test_from_the_group_take_a_count():
    (goal,) = _goals("from the four blocks take only three and put them in a circle")
    assert goal["pattern"] == "circle" and len(goal["objects"]) == 3 and set(goal["objects"]) <= {7, 8, 9, 10}


@pytest.mark.slow
def test_the_ones_after_a_topic_are_of_that_topic():
    (goal,) = _goals("the blocks: take the ones that aren't green and put them in a row")
    assert goal["pattern"] == "line" and sorted(goal["objects"]) == [7, 8, 10]


@pytest.mark.slow
def test_a_facing_said_again_by_its_edge_is_no_place():
    assert _goals("arrange the two bottles in a line that faces west, toward the left edge") == [
        {"pattern": "line", "objects": [11, 12], "facing": "west"}]


@pytest.mark.slow
def test_it_named_after_a_dash_with_i_mean():
    goals = _goals("put the yellow cup behind the orange cup, then put the red bowl right of it \u2014 of the yellow cup I mean")
    assert goals[-1] == {"pattern": "right", "objects": [3], "anchor": 5}
