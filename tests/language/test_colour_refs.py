"""References through another object's colour (lgmcts.language.colour_refs), at their own stage."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from lgmcts.language.colour_refs import find_colour_refs, select
from lgmcts.language.grounding import tokenize


def _refs(text: str):
    ws = tuple(t.text for t in tokenize(text))
    return [(" ".join(ws[r.start : r.end]), r.head, r.ref, r.negated) for r in find_colour_refs(ws)]


def test_a_quantified_reference_is_marked():
    (one,) = find_colour_refs(tuple(t.text for t in tokenize("the cans that match one of the bowls")))
    (the,) = find_colour_refs(tuple(t.text for t in tokenize("the cans that match the red bowl")))
    (both,) = find_colour_refs(tuple(t.text for t in tokenize("the cans that match the red bowl and the box")))
    assert one.quantified and both.quantified and not the.quantified


@pytest.mark.parametrize("text, phrase, head, ref, negated", [
    ("line up the cups that share a colour with one of the cans", "the cups that share a colour with one of the cans",
     ("cups",), ("the", "cans"), False),
    ("the bowl whose colour matches one of the mugs goes left", "the bowl whose colour matches one of the mugs",
     ("bowl",), ("the", "mugs"), False),
    ("put the cans that don't share a colour with either cup behind the box",
     "the cans that don't share a colour with either cup", ("cans",), ("the", "cups"), True),
    ("stack the bowls that do not match any can's colour", "the bowls that do not match any can's colour",
     ("bowls",), ("the", "cans"), True),
    ("the cups that aren't the colour of the box, in a row", "the cups that aren't the colour of the box",
     ("cups",), ("the", "box"), True),
    ("the cans that match any of the bowls in colour, in a row", "the cans that match any of the bowls in colour",
     ("cans",), ("the", "bowls"), False),
    ("put every bowl that has a can of the same colour in a row", "every bowl that has a can of the same colour",
     ("bowl",), ("the", "cans"), False),
    ("whichever cup matches the colour of object 3 goes behind the box",
     "whichever cup matches the colour of object 3", ("cup",), ("object", "3"), False),
    # with a preposition, and without articles, as a speaker whose language has none says it
    ("the cup with the colour of the bottle, put it behind the box", "the cup with the colour of the bottle",
     ("cup",), ("the", "bottle"), False),
    ("block in same colour as letter t, put on top of red block", "block in same colour as letter t",
     ("block",), ("letter", "t"), False),
    # a list of reference objects, and "the colours of" a group: their colours pooled
    ("the blocks that match the letter a and the letter e, line them up",
     "the blocks that match the letter a and the letter e", ("blocks",), ("the", "letter", "a", "and", "the", "letter",
                                                                        "e"), False),
    ("the cans that match the colors of the mugs go behind the box", "the cans that match the colors of the mugs",
     ("cans",), ("the", "mugs"), False),
])
def test_a_colour_comparison_is_read(text, phrase, head, ref, negated):
    assert _refs(text) == [(phrase, head, ref, negated)]


@pytest.mark.parametrize("text", [
    "put the red can on the box", "the cans that are red", "objects whose color is equal to the red can",
    "select objects that have the same color as the red can", "everything else of its colour",
    "arrange the cans in a row", "cans in a row, in the colour order of the rainbow",
])
def test_left_to_the_grounding(text):
    assert _refs(text) == []


def test_select_pools_the_colours_of_the_reference():
    colour = {1: "red", 2: "blue", 3: "green", 4: "red", 5: "blue"}
    assert select([1, 2, 3], [4, 5], colour, False) == [1, 2]
    assert select([1, 2, 3], [4, 5], colour, True) == [3]
    assert select([1, 4], [4], colour, False) == [1, 4]   # the reference counts when the head names it too


@given(st.lists(st.sampled_from(["red", "blue", "green"]), min_size=2, max_size=8))
def test_select_and_its_negation_split_the_candidates(colours):
    colour = dict(enumerate(colours))
    cand, ref = list(colour)[: len(colour) // 2], list(colour)[len(colour) // 2 :]
    yes, no = select(cand, ref, colour, False), select(cand, ref, colour, True)
    assert sorted(yes + no) == sorted(cand) and not set(yes) & set(no)


def test_else_leaves_the_reference_object_out():
    """"whatever else / everything else" of an object's colour: the other objects of that colour,
    never the reference itself; without "else" the reference is one of them."""
    from lgmcts.formats import parse_scene
    from lgmcts.language import parse

    scene = parse_scene({"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}, "objects": [
        {"id": k + 1, "name": n, "color": c, "shape": {"type": "box", "size": [0.05, 0.05, 0.05]},
         "pose": [-0.3 + 0.12 * k, 0.0, 0.0]}
        for k, (n, c) in enumerate([("jug", "yellow"), ("tray", "grey"), ("sponge", "yellow"), ("pear", "yellow"),
                                    ("kettle", "black")])]})

    def objs(text: str) -> list[list[int]]:
        return [sorted(g.objects) for g in parse(scene, text).goals]

    assert objs("whatever else shares the jug's colour, put it in a line") == [[3, 4]]
    assert objs("everything else with the same colour as the jug goes left of the tray") == [[3, 4]]
    assert objs("everything else that is the same colour as the pear goes left of the tray") == [[1, 3]]
    assert objs("whatever shares the jug's colour goes behind the kettle") == [[1, 3, 4]]


@pytest.mark.parametrize("text, phrase", [
    ("line up the cans that share a colour with one of the bowls along the back of the table",
     "the cans that share a colour with one of the bowls"),
    ("put the mugs that match the red bowl by the front edge", "the mugs that match the red bowl"),
    ("stack the cans that are the same colour as the plate in the corner",
     "the cans that are the same colour as the plate"),
])
def test_a_place_after_the_reference_is_not_part_of_it(text, phrase):
    """The reference object's noun phrase ends where a place begins, which is left for the place reader
    (it used to take "along the back" with it and leave "of the table", and the place was lost)."""
    ws = tuple(t.text for t in tokenize(text))
    (r,) = find_colour_refs(ws)
    assert ws[r.start : r.end] == tuple(t.text for t in tokenize(phrase))


def test_a_reference_said_with_a_or_an_is_any_of_them():
    # "the cans that match the colour of a bowl": the colour of some bowl, as "one of the bowls".
    (ref,) = find_colour_refs(tuple("the cans that match the colour of a bowl".split()))
    assert ref.quantified and ref.ref[-1] in ("bowl", "bowls")
