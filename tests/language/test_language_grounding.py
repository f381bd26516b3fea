"""Grounding rules: object references resolved against a scene (no model needed)."""

from __future__ import annotations

import pytest

from lgmcts.errors import InputError
from lgmcts.language.grounding import Choice, Vocabulary, find_mentions, select, tokenize
from lgmcts.language.matcher import key_vocabulary


def _resolve(scene, text):
    vocab = Vocabulary.from_scene(scene)
    words = tuple(t.text for t in tokenize(text))
    ms = find_mentions(vocab, words, key_vocabulary())
    assert ms, f"no mention in {text!r}"
    return select(vocab, ms[0])


@pytest.mark.parametrize(
    "text, ids",
    [
        ("all blocks", [1, 2, 3, 4]),
        ("the blocks", [1, 2, 3, 4]),
        ("the cubes", [1, 2, 3, 4]),
        ("boxes", [1, 2, 3, 4]),
        ("the cup", [7]),
        ("the mugs", [7]),
        ("the red and green polka dot letter A", [8]),
        ("red and green polka dot letter a", [8]),
        ("all blocks except the red one", [2, 3, 4]),
        ("all blocks but not the green one and the yellow one", [1, 2]),
        ("the red, blue and green blocks", [1, 2, 3]),
        ("object 7", [7]),
        ("objects 3, 4 and 5", [3, 4, 5]),
        ("object #9", [9]),
        ("everything except the blocks", [5, 6, 7, 8, 9]),
    ],
)
def test_references_select_the_right_objects(tabletop, text, ids):
    assert _resolve(tabletop, text) == ids


def test_colour_list_keeps_the_order_it_was_named_in(tabletop):
    assert _resolve(tabletop, "the yellow, red and blue blocks") == [4, 1, 2]


def test_same_colour_set_holds_its_reference_in_lgmcts_wording_not_in_structformer_wording(scenes):
    # vima_b: the triangle is red; the red pentagon and red hexagon share its colour.
    # LGMCTS-D's selector puts the reference in its "equal" set ...
    assert _resolve(scenes["vima_b"], "objects whose color is the same as the triangle") == [1, 3, 11]
    # ... StructFormer's "objects that have the same color as the X" leaves the X out.
    assert _resolve(scenes["vima_b"], "objects that have the same color as the triangle") == [1, 11]
    # "red" does not select "red swirl" while some object is plain red.
    assert 5 not in _resolve(scenes["vima_b"], "all red objects")


def test_scene_names_win_over_synonyms(scenes):
    # The kitchen has mugs and no cups: "cups" means the mugs.
    assert _resolve(scenes["kitchen"], "the cups") == [1, 2]
    # "dish" is a synonym of both bowl and plate: two white dishes are ambiguous.
    with pytest.raises(InputError, match="ambiguous"):
        _resolve(scenes["kitchen"], "the white dish")


def test_a_count_or_one_x_is_a_choice(scenes):
    got = _resolve(scenes["kitchen"], "three blocks")
    assert isinstance(got, Choice) and got.k == 3 and set(got.options) == {9, 10, 11, 12}
    one = _resolve(scenes["kitchen"], "one bottle")
    assert isinstance(one, Choice) and one.k == 1 and set(one.options) == {5, 6}


def test_ambiguous_singular_lists_every_match(scenes):
    with pytest.raises(InputError) as err:
        _resolve(scenes["kitchen"], "the bottle")
    msg = str(err.value)
    assert "ambiguous" in msg and "5 (white bottle)" in msg and "6 (blue bottle)" in msg
    assert "\n" not in msg


@pytest.mark.parametrize(
    "text, needle",
    [
        ("all green mugs", "nothing in the scene matches"),
        ("five blocks", "only 4"),
        ("objects 1 and 99", "99"),
        ("both mugs", "both"),
    ],
)
def test_bad_references_are_refused_in_one_line(scenes, text, needle):
    scene = scenes["kitchen"] if "mugs" not in text else scenes["blocks8"]
    with pytest.raises(InputError) as err:
        _resolve(scene, text)
    assert needle in str(err.value) and "\n" not in str(err.value)


def test_unknown_colour_and_noun_is_refused(tabletop):
    vocab = Vocabulary.from_scene(tabletop)
    words = tuple(t.text for t in tokenize("put the purple giraffe in a line"))
    with pytest.raises(InputError, match="purple giraffe"):
        find_mentions(vocab, words, key_vocabulary())


def test_pattern_nouns_are_not_objects(scenes):
    # vima_b has a square and a ring; "in a square"/"into a ring" name shapes.
    vocab = Vocabulary.from_scene(scenes["vima_b"])
    for text in ("arrange the blocks in a square", "move the blocks into a ring", "put them in a star shape"):
        words = tuple(t.text for t in tokenize(text))
        names = [m.names for m in find_mentions(vocab, words, key_vocabulary())]
        assert all(n is None or not ({"square", "ring", "star"} & set(n)) for n in names), text
    words = tuple(t.text for t in tokenize("put the square left of the ring"))
    assert len(find_mentions(vocab, words, key_vocabulary())) == 2


def _resolve_all(scene, text):
    vocab = Vocabulary.from_scene(scene)
    words = tuple(t.text for t in tokenize(text))
    return [select(vocab, m) for m in find_mentions(vocab, words, key_vocabulary())]


@pytest.mark.parametrize(
    "text, ids",
    [
        ("the red and the blue blocks", [[1], [2]]),
        ("the red, the blue and the green blocks", [[1], [2], [3]]),
        ("the red block and the blue", [[1], [2]]),
    ],
)
def test_elided_heads_take_the_noun_of_their_list(tabletop, text, ids):
    assert _resolve_all(tabletop, text) == ids


def test_elided_heads_with_a_plural_noun_select_every_match(scenes):
    # blocks8 has two red and two blue blocks: "the red and the blue blocks" means all four.
    assert _resolve_all(scenes["blocks8"], "the red and the blue blocks") == [[1, 2], [3, 4]]


def test_the_red_one_takes_the_category_of_its_neighbour(scenes):
    # The kitchen has a red mug and a red block, a green bowl and a green block.
    assert _resolve_all(scenes["kitchen"], "the red block and the green one") == [[9], [10]]
    assert _resolve_all(scenes["kitchen"], "the red one and the green block") == [[9], [10]]
    # Without a neighbour "the green one" is still any green object, hence ambiguous.
    with pytest.raises(InputError, match="ambiguous"):
        _resolve_all(scenes["kitchen"], "the green one")


def test_an_elided_head_without_a_noun_names_nothing(scenes):
    # Two objects are red and nothing names their noun: refused, naming both.
    with pytest.raises(InputError, match="'the red' is ambiguous: it matches objects 1 \\(red mug\\), 9 \\(red block\\)"):
        _resolve_all(scenes["kitchen"], "the red and the blue")


def test_clauses_split_before_a_verb_but_not_inside_a_list():
    from lgmcts.language.rules import split_clauses

    words = tuple(t.text for t in tokenize("stack the blocks and put the bowls in a line"))
    assert split_clauses(words) == [("stack", "the", "blocks"), ("put", "the", "bowls", "in", "a", "line")]
    words = tuple(t.text for t in tokenize("stack the red block, the blue block and the green block"))
    assert split_clauses(words) == [words]


def test_colour_words_given_in_part_select_the_one_object_that_has_them(scenes):
    vima_a = scenes["vima_a"]
    assert _resolve(vima_a, "the swirl flower") == [4]
    assert _resolve(vima_a, "the red flower") == [4]  # no plain red flower
    assert _resolve(vima_a, "the polka dot letter A") == [5]
    assert _resolve(vima_a, "the blue stripe block") == [3]
    assert _resolve(vima_a, "the red block") == [1]  # an exact colour wins
    with pytest.raises(InputError, match="nothing in the scene matches 'the swirl heart'"):
        _resolve(vima_a, "the swirl heart")


def test_colour_words_given_in_part_that_fit_two_objects_are_ambiguous():
    from lgmcts.formats import parse_scene

    box = {"type": "box", "size": [0.04, 0.04, 0.04]}
    scene = parse_scene({"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}, "objects": [
        {"id": 1, "name": "flower", "color": "red swirl", "shape": box, "pose": [0.0, 0.0, 0.0]},
        {"id": 2, "name": "flower", "color": "blue swirl", "shape": box, "pose": [0.1, 0.0, 0.0]},
        {"id": 3, "name": "block", "color": "red", "shape": box, "pose": [0.2, 0.0, 0.0]},
    ]})
    with pytest.raises(InputError, match=r"'the swirl flower' is ambiguous: it matches objects 1 \(red swirl flower\), 2"):
        _resolve(scene, "the swirl flower")
    assert _resolve(scene, "the red swirl flower") == [1]
    assert _resolve(scene, "all swirl flowers") == [1, 2]


def test_a_neighbour_whose_noun_fits_nothing_is_passed_over(tabletop):
    # "the red one" is not a bowl (there is no red bowl): it stays any red object.
    assert _resolve_all(tabletop, "the red one and the blue one and the green bowl") == [[1], [2], [6]]
    # An elided head takes the noun that follows it, not the one before.
    assert _resolve_all(tabletop, "the green bowl, the red and the blue blocks") == [[6], [1], [2]]
