"""References by position (lgmcts.language.positions): the phrases and the ranking, at their own stage."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from lgmcts.errors import InputError
from lgmcts.language.grounding import tokenize
from lgmcts.language.positions import TOO_CLOSE, Key, find_position_refs, pick


def _refs(text: str):
    ws = tuple(t.text for t in tokenize(text))
    return [(ws[r.start : r.end], r.head, r.key, r.count, r.rank, r.of) for r in find_position_refs(ws)]


@pytest.mark.parametrize("text, phrase, head, key, count, rank, of", [
    ("put the leftmost bowl behind the mug", "the leftmost bowl", ("bowl",), Key("x", 1), 1, 0, None),
    ("line up the three frontmost cans", "the three frontmost cans", ("cans",), Key("y", 1), 3, 0, None),
    ("the backmost one goes on the plate", "the backmost one", ("one",), Key("y", -1), 1, 0, None),
    ("put the second cup from the right on the box", "the second cup from the right", ("cup",), Key("x", -1), 1, 1,
     None),
    ("fourth can from the front, behind the mug", "fourth can from the front", ("can",), Key("y", 1), 1, 3, None),
    ("the bowl closest to me goes left of the pan", "the bowl closest to me", ("bowl",), Key("y", 1), 1, 0, None),
    ("the mug nearest the back wall, in front of the box", "the mug nearest the back wall", ("mug",), Key("y", -1), 1,
     0, None),
    ("the box nearest to the right edge goes on the plate", "the box nearest to the right edge", ("box",),
     Key("x", -1), 1, 0, None),
    ("the fork farthest from me goes behind the plate", "the fork farthest from me", ("fork",), Key("y", -1), 1, 0,
     None),
    ("the cup furthest to the left goes behind the box", "the cup furthest to the left", ("cup",), Key("x", 1), 1, 0,
     None),
    ("bottle furthest back goes left of the box", "bottle furthest back", ("bottle",), Key("y", -1), 1, 0, None),
    ("the spoon nearest the red bowl goes on the plate", "the spoon nearest the red bowl", ("spoon",),
     Key("near", 1, ("the", "red", "bowl")), 1, 0, None),
    ("the two mugs furthest from the plate in a row", "the two mugs furthest from the plate", ("mugs",),
     Key("far", 1, ("the", "plate")), 2, 0, None),
    ("whatever sits nearest the box goes behind it", "whatever sits nearest the box", (),
     Key("near", 1, ("the", "box")), 1, 0, None),
    ("whichever can is furthest left goes first", "whichever can is furthest left", ("can",), Key("x", 1), 1, 0, None),
    ("the centre one of the three forks goes left of the plate", "the centre one of the three forks", ("forks",),
     Key("middle"), 1, 0, 3),
    ("the nearer of the two cups goes on the plate", "the nearer of the two cups", ("cups",), Key("y", 1), 1, 0, 2),
    ("the cup on the far right goes behind the box", "the cup on the far right", ("cup",), Key("x", -1), 1, 0, None),
    ("the can closest to the middle of the table", "the can closest to the middle of the table", ("can",),
     Key("near"), 1, 0, None),
    ("the utensil all the way on the left goes in front", "the utensil all the way on the left", ("utensil",),
     Key("x", 1), 1, 0, None),
    ("utensil most right, put on plate", "utensil most right", ("utensil",), Key("x", -1), 1, 0, None),
    ("the cup most to the back goes left of the box", "the cup most to the back", ("cup",), Key("y", -1), 1, 0, None),
    # said without articles, as by a speaker whose language has none
    ("third block from left goes on the plate", "third block from left", ("block",), Key("x", 1), 1, 2, None),
    ("put it on rightmost block", "rightmost block", ("block",), Key("x", -1), 1, 0, None),
    # a verb before the head is no part of it; a kind said after "piece of"; "is lying"
    ("take the piece of cutlery closest to me and lay it down", "the piece of cutlery closest to me",
     ("piece", "of", "cutlery"), Key("y", 1), 1, 0, None),
    ("whichever piece of cutlery is lying nearest the box, on the plate", "whichever piece of cutlery is lying nearest "
     "the box", ("piece", "of", "cutlery"), Key("near", 1, ("the", "box")), 1, 0, None),
    ("the can closest to the customers goes left", "the can closest to the customers", ("can",), Key("y", 1), 1, 0,
     None),
    ("the one more to the back goes on the plate", "the one more to the back", ("one",), Key("y", -1), 1, 0, 2),
    ("utensil most far from me, put it on the plate", "utensil most far from me", ("utensil",), Key("y", -1), 1, 0,
     None),
    ("whatever is currently nearest the box goes left", "whatever is currently nearest the box", (),
     Key("near", 1, ("the", "box")), 1, 0, None),
])
def test_a_position_phrase_is_read(text, phrase, head, key, count, rank, of):
    (got,) = _refs(text)
    assert got == (tuple(t.text for t in tokenize(phrase)), head, key, count, rank, of)


@pytest.mark.parametrize("text", [
    "put the red block left of the bowl", "the mug is nearest the plate", "stack the cans",
    "put the bowl to the right of the plate", "the cans in a row at the front", "line up the blocks from the left",
])
def test_no_position_phrase(text):
    assert _refs(text) == []


_ROW = {1: (-0.3, 0.0), 2: (-0.1, 0.05), 3: (0.1, -0.1), 4: (0.25, 0.2)}


@pytest.mark.parametrize("text, ids", [
    ("the leftmost block", (1,)), ("the rightmost block", (4,)), ("the two rightmost blocks", (4, 3)),
    ("the frontmost block", (3,)), ("the backmost block", (4,)), ("the second block from the left", (2,)),
    ("the third block from the right", (2,)),
])
def test_pick_ranks_on_the_key(text, ids):
    (ref,) = find_position_refs(tuple(t.text for t in tokenize(text)))
    assert pick(ref, _ROW, said=text) == ids


def test_nearest_another_object_and_the_middle_of_three():
    (near,) = find_position_refs(tuple(t.text for t in tokenize("the block nearest the mug")))
    assert pick(near, _ROW, anchor_xy=(0.2, 0.15)) == (4,)
    (mid,) = find_position_refs(tuple(t.text for t in tokenize("the middle one of the three blocks")))
    assert pick(mid, {1: (-0.2, 0.0), 2: (0.3, 0.0), 3: (0.05, 0.1)}) == (3,)
    with pytest.raises(InputError, match="speaks of 3"):
        pick(mid, _ROW)


def test_nearest_without_a_reference_position_is_refused():
    (near,) = find_position_refs(tuple(t.text for t in tokenize("the block nearest the giraffe")))
    with pytest.raises(InputError, match="nearest to what"):
        pick(near, _ROW, said="the block nearest the giraffe")


def test_too_close_to_tell_is_refused_and_says_so():
    (ref,) = find_position_refs(tuple(t.text for t in tokenize("the leftmost block")))
    with pytest.raises(InputError, match="within 2 cm"):
        pick(ref, {1: (-0.30, 0.0), 2: (-0.29, 0.2), 3: (0.2, 0.0)}, said="the leftmost block")
    (two,) = find_position_refs(tuple(t.text for t in tokenize("the two leftmost blocks")))
    # the first two are close to each other but clear of the third: no doubt which two
    assert set(pick(two, {1: (-0.30, 0.0), 2: (-0.29, 0.2), 3: (0.2, 0.0)})) == {1, 2}


@given(st.lists(st.floats(min_value=-0.4, max_value=0.4, allow_nan=False), min_size=2, max_size=8, unique=True))
def test_leftmost_is_the_smallest_x_or_a_refusal(xs):
    cands = {k + 1: (x, 0.0) for k, x in enumerate(xs)}
    (ref,) = find_position_refs(("the", "leftmost", "block"))
    srt = sorted(xs)
    try:
        (got,) = pick(ref, cands)
    except InputError:
        assert srt[1] - srt[0] < TOO_CLOSE
        return
    assert cands[got][0] == srt[0] and srt[1] - srt[0] >= TOO_CLOSE


def _kitchen(names: list[tuple[str, str, float, float]]):
    from lgmcts.formats import parse_scene

    return parse_scene({"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}, "objects": [
        {"id": k + 1, "name": n, "color": c, "shape": {"type": "cylinder", "radius": 0.03, "height": 0.05},
         "pose": [x, y, 0.0]} for k, (n, c, x, y) in enumerate(names)]})


def test_a_synonym_head_does_not_choose_among_several_objects():
    """"cup" names the mugs of a scene without a cup only through the synonym table: like "the
    cup" alone, "the cup furthest from the kettle" is refused among two mugs (never a guess),
    while the scene's own noun is read and a lone mug is still named by the synonym."""
    from lgmcts.language import parse

    two = _kitchen([("mug", "red", -0.3, 0.0), ("mug", "green", 0.3, 0.0), ("kettle", "black", 0.25, 0.1),
                    ("tray", "white", 0.0, -0.2)])
    with pytest.raises(InputError, match="no cup"):
        parse(two, "put the cup furthest from the kettle on the left of the tray")
    with pytest.raises(InputError):
        parse(two, "put the cup on the left of the tray")
    got = parse(two, "put the mug furthest from the kettle on the left of the tray")
    assert [(g.pattern, list(g.objects), g.anchor) for g in got.goals] == [("left", [1], 4)]
    one = _kitchen([("mug", "red", -0.3, 0.0), ("kettle", "black", 0.25, 0.1), ("tray", "white", 0.0, -0.2)])
    got = parse(one, "put the cup on the left of the tray")
    assert [(g.pattern, list(g.objects), g.anchor) for g in got.goals] == [("left", [1], 3)]


@pytest.mark.parametrize("said", ["put the cup nearest the kettle on the left of the tray",
                                  "put the mug nearest the kettle on the left of the tray",
                                  "put the mug furthest from the kettle on the left of the tray"])
def test_one_object_and_a_reference_object_is_that_object_alone(said):
    """With one mug, "the mug nearest the kettle" is the mug: the kettle only says where it stands
    and is no object of the goal (it used to be added to it)."""
    from lgmcts.language import parse

    one = _kitchen([("mug", "red", -0.3, 0.0), ("kettle", "black", 0.25, 0.1), ("tray", "white", 0.0, -0.2)])
    got = parse(one, said)
    assert [(g.pattern, list(g.objects), g.anchor) for g in got.goals] == [("left", [1], 3)]


@pytest.mark.parametrize("said", [
    "move one of the mugs behind the tray and the remaining mug in front of the kettle",
    "move one of the mugs behind the tray and the other mug in front of the kettle",
    "put one mug behind the tray and the other one in front of the kettle",
])
def test_the_other_of_two_is_the_one_the_first_did_not_take(said):
    """"one of the mugs ... the remaining mug": with two mugs, the second reference is the other one
    (it was refused as ambiguous when it said its noun)."""
    from lgmcts.language import parse

    two = _kitchen([("mug", "red", -0.3, 0.0), ("mug", "green", 0.3, 0.0), ("kettle", "black", 0.25, 0.1),
                    ("tray", "white", 0.0, -0.2)])
    got = parse(two, said)
    (a, b) = got.goals
    assert (a.pattern, a.anchor, b.pattern, b.anchor) == ("behind", 4, "front", 3)
    assert sorted([*a.objects, *b.objects]) == [1, 2]


@pytest.mark.parametrize("said, tower", [
    ("the two leftmost cans go in a stack with the one nearer the front at the bottom", [3, 1]),
    ("the two leftmost cans into a stack, the farther-back one on the bottom", [1, 3]),
])
def test_a_comparative_one_of_the_two_just_picked(said, tower):
    """"the two leftmost cans ..., the one nearer the front at the bottom": "one" of those two, not of every can."""
    from lgmcts.formats import parse_scene
    from lgmcts.language import parse

    cans = [("red", -0.3, 0.1), ("blue", 0.3, 0.0), ("green", -0.25, -0.1), ("white", 0.1, 0.2)]
    scene = parse_scene({"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}, "objects": [
        {"id": k + 1, "name": "can", "color": c, "shape": {"type": "cylinder", "radius": 0.03, "height": 0.1},
         "pose": [x, y, 0.0]} for k, (c, x, y) in enumerate(cans)]})
    (goal,) = parse(scene, said).goals
    assert (goal.pattern, list(goal.objects)) == ("tower", tower)


@pytest.mark.parametrize("said", ["of the two cans, ", "Of two cans, ", "out of the two cans, "])
def test_a_group_said_first_is_taken_out_with_its_objects(said):
    from lgmcts.language.stages import partitive

    ids = {("the", "cans"): [3, 4]}
    rest, group = partitive(said + "the one nearer me goes left", lambda ws: [ws] if ws in ids else [],
                            lambda m: ids[m])
    assert rest.strip() == "the one nearer me goes left" and group == [3, 4]


def test_the_colour_one_of_a_group_said_first_takes_its_noun():
    from lgmcts.language.stages import partitive

    named = {("the", "bottles"): [6, 7], ("the", "bottle"): [6, 7], ("the", "blue", "bottle"): [7],
             ("the", "blue", "bowl"): [5]}
    rest, group = partitive("of the two bottles, put the blue one left of the knife and the other one right of it",
                            lambda ws: [ws] if ws in named else [], lambda m: named[m])
    assert group == [6, 7] and rest.strip() == "put the blue bottle left of the knife and the other one right of it"
