"""The readings of a clause (lgmcts/language/readings.py): registered in a fixed order, each one answering
(or, for an adjustment, changing the frame for) labelled commands of its kind."""

from __future__ import annotations

import copy
from pathlib import Path

import pytest

from lgmcts.errors import InputError
from lgmcts.language import readings
from lgmcts.language.evaluate import load_cases
from lgmcts.language.rules import RulesOptions, _Parser

ROOT = Path(__file__).resolve().parents[2]

#: For each reading, labelled commands ("case file:case id", from dev splits only) it takes part in: an early
#: handler or a reading answers them (or refuses them), an adjustment changes their frame.
EXAMPLES: dict[str, tuple[str, ...]] = {
    "pose": ("tests/language/fresh8_cases.jsonl:fresh8a-measure-005",),
    "not-a-goal": ("tests/language/fresh_cases.jsonl:freshH-refusal-002",),
    "itself": ("data/parse_cases.jsonl:refusal-028",),
    "so-that": ("data/paraphrase_cases.jsonl:reference-inverted-002",),
    "params-of-last-arrangement": ("tests/language/fresh_cases.jsonl:freshM2-where-how-big-001",),
    "order-of-last-stack": ("tests/language/fresh_cases.jsonl:freshM-stack-order-002",),
    "no-object": ("tests/language/fresh_cases.jsonl:freshC-pattern-words-003",),
    "selection-verb": ("tests/language/issue9_cases.jsonl:peer_selection-012",),
    "roles-in-last-stack": ("tests/language/fresh_cases.jsonl:fresh3c-stack-order-005",),
    "next-in-last-stack": ("tests/language/fresh_cases.jsonl:freshA-stack-order-004",),
    "roles-make-a-stack": ("tests/language/fresh_cases.jsonl:fresh3g-pattern-words-006",),
    "order-makes-a-stack": ("tests/language/fresh_cases.jsonl:freshB-stack-order-003",),
    "each-other-line": ("tests/language/fresh_cases.jsonl:fresh5d-pattern-words-001",),
    "vertical-pair": ("tests/language/fresh_cases.jsonl:freshC-vertical-025",),
    "header-objects": ("tests/language/fresh_cases.jsonl:fresh3g-pattern-words-009",),
    "continue-last-stack": ("tests/language/fresh_cases.jsonl:fresh6a-stack-order-009",),
    "phrase-and-choices": ("tests/language/probe_cases.jsonl:probe-refusal-018",),
    "relation-and-arrangement": ("tests/language/fresh_cases.jsonl:fresh3g-dinner-006",),
    "selection-on-or-under": ("tests/language/fresh_cases.jsonl:fresh3g-vertical-008",),
    "put-down-first": ("tests/language/fresh_cases.jsonl:fresh3c-dinner-010",),
    "objects-for-next-clause": ("tests/language/fresh_cases.jsonl:freshP-casual-007",),
    "arrangement": ("data/paraphrase_cases.jsonl:pattern-words-028",),
}


def _state(f: readings.Frame) -> dict:
    return {k: copy.copy(v) for k, v in vars(f).items()}


def _watched(seen: list[str], name: str, fn: readings.Handler, adjusts: bool) -> readings.Handler:
    def run(parser, f):
        before = _state(f) if adjusts else None
        try:
            got = fn(parser, f)
        except InputError:
            seen.append(name)
            raise
        if got is not None or (before is not None and _state(f) != before):
            seen.append(name)
        return got
    return run


@pytest.fixture()
def seen(monkeypatch):
    """The names of the handlers that took part in the parses of the test, in order."""
    out: list[str] = []
    adjusting = readings.ADJUSTS
    monkeypatch.setattr(readings, "EARLY", [(n, _watched(out, n, fn, False)) for n, fn in readings.EARLY])
    monkeypatch.setattr(readings, "READINGS", [(n, _watched(out, n, fn, n in adjusting)) for n, fn in readings.READINGS])
    return out


_CASES: dict[str, dict] = {}


def _case(ref: str):
    file, cid = ref.split(":")
    if file not in _CASES:
        _CASES[file] = {c.id: c for c in load_cases(ROOT / file)}
    return _CASES[file][cid]


def test_readings_are_registered_once_in_their_order_each_with_an_example():
    names = [n for n, _ in readings.EARLY] + [n for n, _ in readings.READINGS]
    assert names == list(EXAMPLES)
    assert all(EXAMPLES[n] for n in names)
    assert readings.READINGS[-1][0] == "arrangement"


@pytest.mark.slow
@pytest.mark.parametrize("name, ref", [(n, r) for n, refs in EXAMPLES.items() for r in refs])
def test_reading_takes_its_examples(name, ref, seen, matcher):
    case = _case(ref)
    assert case.split != "test"
    parser = _Parser(case.scene, matcher, RulesOptions())
    try:
        parser.command(case.instruction)
    except InputError:
        pass
    assert name in seen, f"{case.instruction!r}: {seen}"


_CUBES = ["jade", "blue", "cream", "amber", "grey"]


def _stacked_cubes(text: str) -> list[str]:
    """The colours, bottom up, of the one tower ``text`` asks for on a row of five cubes (:data:`_CUBES`)."""
    from lgmcts.formats import parse_scene
    from lgmcts.language import parse

    scene = parse_scene({"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}, "objects": [
        {"id": k + 1, "name": "cube", "color": c, "shape": {"type": "box", "size": [0.04, 0.04, 0.04]},
         "pose": [-0.3 + 0.12 * k, 0.1, 0.0]} for k, c in enumerate(_CUBES)]})
    (goal,) = parse(scene, text).goals
    assert goal.pattern == "tower"
    return [_CUBES[i - 1] for i in goal.objects]


@pytest.mark.parametrize("text, want", [
    ("tower: jade at the bottom, then blue, then cream, amber on top", ["jade", "blue", "cream", "amber"]),
    ("build a stack with the amber cube at the base, then cream, then jade, and the blue one at the top",
     ["amber", "cream", "jade", "blue"]),
    ("make a tower, blue as the base, then amber, then jade, then cream", ["blue", "amber", "jade", "cream"]),
])
def test_a_stack_said_base_to_top_keeps_every_object_in_order(text, want):
    """Objects named one by one after the base ("then blue, then cream") are part of the stack,
    in the order said, also when the last one is given a role ("amber on top")."""
    assert _stacked_cubes(text) == want


@pytest.mark.parametrize("text, want", [
    ("stack the cubes, from top to bottom: amber, jade, blue", ["blue", "jade", "amber"]),
    ("make a tower of the cubes; top to bottom: cream, blue", ["blue", "cream"]),
    ("stack the cubes, from the bottom up: grey, jade, amber", ["grey", "jade", "amber"]),
])
def test_an_order_that_names_some_of_a_group_is_read_as_said(text, want):
    """"stack the cubes, top to bottom: amber, jade, blue" with five cubes is the three the order names:
    the two it leaves out are not filled in on top (their place would be a guess)."""
    assert _stacked_cubes(text) == want


def test_a_trailing_not_is_an_exception_or_a_refusal_never_dropped():
    """", not the purple one" after a group leaves that object out; after a group that does not hold
    it the words are refused, quoted; after one object it stays a contrast."""
    from lgmcts.formats import parse_scene
    from lgmcts.language import parse

    items = [("cube", "jade"), ("cube", "purple"), ("cube", "cream"), ("tray", "white"), ("jar", "purple"), ("cube", "amber")]
    scene = parse_scene({"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}, "objects": [
        {"id": k + 1, "name": n, "color": c, "shape": {"type": "box", "size": [0.04, 0.04, 0.04]},
         "pose": [-0.35 + 0.13 * k, 0.1, 0.0]} for k, (n, c) in enumerate(items)]})
    (goal,) = parse(scene, "put the cubes in a circle, not the purple one").goals
    assert sorted(goal.objects) == [1, 3, 6]
    (goal,) = parse(scene, "stack the cubes, not the purple one").goals
    assert sorted(goal.objects) == [1, 3, 6]
    with pytest.raises(InputError, match="'not the purple jar'"):
        parse(scene, "put the cubes in a line, not the purple jar")
    (goal,) = parse(scene, "put the jade cube on the tray, not the purple one").goals
    assert (goal.pattern, list(goal.objects)) == ("tower", [4, 1])
