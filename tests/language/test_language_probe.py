"""The probe set of free-form commands (tests/language/probe_cases.jsonl, written
by make_probe_cases.py before the parser changes it measures) and the refusals
added for it: commands whose goal the parser cannot be sure of are refused."""

from __future__ import annotations

from pathlib import Path

import pytest

from lgmcts.errors import InputError
from lgmcts.language.evaluate import evaluate, load_cases
from lgmcts.language.rules import goal_dicts, parse_rules

CASES = load_cases(Path(__file__).with_name("probe_cases.jsonl"))

#: Probe cases the parser does not answer as labelled (docs/language.md, "What
#: does not work"): "it" after a two-object stack is read as its top ("stack
#: the red block on the blue block and put the green block left of it"), which
#: the probe labels as ambiguous. ("it" after "A left of B" is refused.) "put the red can in the blue bowl"
#: is labelled a refusal here, but containment is read as a stack (docs/language.md: "into the bowl",
#: "sitting in the black bowl"), as every writer's set labels "put X in the bowl" (fresh7b-ref-position-052,
#: w10a-stack-074, w12a-plain-068 ...): the parser follows the documented convention.
KNOWN = {"probe-refusal-011", "probe-refusal-025"}


def _scene(name: str):
    import json

    for line in Path(__file__).with_name("probe_cases.jsonl").read_text().splitlines():
        row = json.loads(line)
        if row.get("scene_id") == name:
            from lgmcts.formats import parse_scene

            return parse_scene(row["scene"])
    raise KeyError(name)


def test_probe_set_shape():
    assert len(CASES) >= 120
    assert sum(c.refuse is not None for c in CASES) >= 20


@pytest.mark.slow
def test_probe_set_no_unexpected_wrong_goals(matcher):
    report = evaluate(CASES, lambda s, t: parse_rules(s, t, matcher=matcher))
    wrong = [r.case.id for r in report.results if not r.ok and r.got is not None]
    assert set(wrong) <= KNOWN, wrong
    assert report.accuracy >= 0.93


@pytest.mark.slow
@pytest.mark.parametrize("scene, text, why", [
    ("blocks", "put the blue things on top of each other in a circle", "more than one arrangement"),
    ("home", "line the cans up in a circle", "more than one arrangement"),
    ("pantry", "stack the cans in a row", "more than one arrangement"),
    ("blocks", "stack the blocks in order of size", "stacking order"),
    ("blocks", "pile the blocks from smallest to largest", "stacking order"),
    ("pantry", "stack the bowls sorted by colour", None),  # refused either way
])
def test_unsure_commands_are_refused_with_the_reason(scene, text, why, matcher):
    with pytest.raises(InputError, match=why):
        goal_dicts(_scene(scene), text, matcher=matcher)


@pytest.mark.slow
@pytest.mark.parametrize("scene, text, pattern", [
    ("blocks", "line the blocks up in order of size", "line"),  # a line carries no order
    ("pantry", "stack the bowls, any order", "tower"),
    ("blocks", "build a tower out of the blocks", "tower"),
    ("blocks", "put the blocks in a ring", "circle"),
])
def test_one_arrangement_still_read(scene, text, pattern, matcher):
    got = goal_dicts(_scene(scene), text, matcher=matcher)
    assert [g["pattern"] for g in got] == [pattern]


@pytest.mark.slow
def test_stack_roles_keep_their_references_apart(matcher):
    # "red at the bottom and blue on top": each role phrase leaves a mark, so
    # "red" and "blue" stay two references, each with its own role.
    got = goal_dicts(_scene("blocks"), "stack the red, green and blue blocks with red at the bottom and blue on top",
                     matcher=matcher)
    assert got == [{"pattern": "tower", "objects": [1, 3, 2]}]
    got = goal_dicts(_scene("blocks"), "stack the red, green and blue blocks with the red one at the bottom and "
                                       "the blue one on top", matcher=matcher)
    assert got == [{"pattern": "tower", "objects": [1, 3, 2]}]


@pytest.mark.slow
def test_bare_colour_takes_the_noun_of_an_earlier_reference(matcher):
    got = goal_dicts(_scene("blocks"), "put the red block in front of the white bowl and blue behind the black bowl",
                     matcher=matcher)
    assert {"pattern": "behind", "objects": [2], "anchor": 8} in got
    # The noun of the parallel reference ("the red mug ... and blue"): the blue mug.
    got = goal_dicts(_scene("home"), "put the red mug left of the plate and blue behind the plate", matcher=matcher)
    assert {"pattern": "behind", "objects": [2], "anchor": 8} in got
    # A colour that several kinds of object share, none of them named before, stays ambiguous.
    with pytest.raises(InputError, match="ambiguous"):
        goal_dicts(_scene("home"), "put the red mug left of the plate and green behind the plate", matcher=matcher)


@pytest.mark.slow
def test_a_definite_count_must_match_the_scene(matcher):
    # "the three cans" with four cans: which three is not said.
    with pytest.raises(InputError, match="speaks of 3"):
        goal_dicts(_scene("pantry"), "put the three cans in a line", matcher=matcher)
    assert goal_dicts(_scene("pantry"), "put the four cans in a line", matcher=matcher) == [
        {"pattern": "line", "objects": [1, 2, 3, 4]}]
    got = goal_dicts(_scene("pantry"), "put three cans in a line", matcher=matcher)  # any three
    assert got[0]["pattern"] == "line" and len(got[0]["objects"]) == 3


@pytest.mark.slow
@pytest.mark.parametrize("text", ["put the cans in a line running north to south", "put the cans in a diagonal line"])
def test_a_direction_that_is_no_facing_is_refused(text, matcher):
    with pytest.raises(InputError, match="direction"):
        goal_dicts(_scene("pantry"), text, matcher=matcher)
    got = goal_dicts(_scene("pantry"), "put the cans in a line facing north", matcher=matcher)
    assert got == [{"pattern": "line", "objects": [1, 2, 3, 4], "facing": "north"}]


@pytest.mark.slow
@pytest.mark.parametrize("text, goal", [
    ("have the phone to the left of the plate", {"pattern": "left", "objects": [15], "anchor": 8}),
    ("make sure the red mug is behind the plate", {"pattern": "behind", "objects": [1], "anchor": 8}),
])
def test_register_verbs_that_ask_for_an_outcome(text, goal, matcher):
    assert goal_dicts(_scene("home"), text, matcher=matcher) == [goal]


@pytest.mark.slow
@pytest.mark.parametrize("text", ["put the large cans in a line", "put a small can behind the box"])
def test_a_size_word_that_picks_objects_is_refused(text, matcher):
    with pytest.raises(InputError, match="size word"):
        goal_dicts(_scene("pantry"), text, matcher=matcher)
    # Before the arrangement's noun it is the arrangement's size.
    got = goal_dicts(_scene("pantry"), "make a large circle of the cans", matcher=matcher)
    assert got == [{"pattern": "circle", "objects": [1, 2, 3, 4], "size": "large"}]


@pytest.mark.slow
def test_stack_order_words(matcher):
    b = _scene("blocks")
    # "top to bottom" lists the top first; "top" here is no role of "green".
    assert goal_dicts(b, "stack red, blue, green top to bottom", matcher=matcher) == [
        {"pattern": "tower", "objects": [3, 2, 1]}]
    # A second mention whose place in the order is not read is refused, not dropped.
    with pytest.raises(InputError, match="named twice"):
        goal_dicts(b, "stack the red, blue and green blocks starting with green", matcher=matcher)
