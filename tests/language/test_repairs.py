"""Spoken repairs, restarts and echoes (lgmcts.language.repairs), at their stage and end to end."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from lgmcts.formats import parse_scene
from lgmcts.language.repairs import echoes, repaired, restarts, typed_repairs
from lgmcts.formats import to_dict
from lgmcts.language.matcher import default_matcher
from lgmcts.language.rules import parse_rules

FILE = Path(__file__).with_name("fresh_cases.jsonl")
SCENES = {r["scene_id"]: parse_scene(r["scene"]) for r in map(json.loads, FILE.read_text().splitlines())
          if "scene_id" in r}


@pytest.mark.parametrize(("said", "read"), [
    # a place replaces the last place
    ("a circle in the near right corner. No, the far right corner.", "a circle in the far right corner."),
    ("Put the cups in the back left. Actually, the front right.", "Put the cups in the front right."),
    # a facing replaces the last facing, whatever lies between
    ("in a row, facing away from me, so they read well... no wait, facing me.", "in a row, facing me, so they read well."),
    # a measure's number alone keeps the unit of the measure it corrects
    ("a circle about 30 centimetres across? Actually no, make it 40 across.", "a circle about 40 centimetres across."),
    ("a 30 cm line of the cans, no, 20", "a 20 cm line of the cans"),
    # a whole measure replaces the whole measure
    ("a line 30 cm long, sorry, 25 mm", "a line 25 mm"),
])
def test_typed_repair_replaces_the_last_thing_of_its_kind(said: str, read: str) -> None:
    assert typed_repairs(said) == read


@pytest.mark.parametrize("said", [
    "put the cups in a circle, no wait, in a line",          # a shape: left to the later stages
    "put the red block on the blue one, no, the green one",  # a reference: left to the later stages
    "No bowls on the left, put them at the back.",           # "no" as a word of the request
    "facing me, no, 40 across",                              # nothing of the fragment's kind before it
])
def test_typed_repair_leaves_other_fragments(said: str) -> None:
    assert typed_repairs(said) == said


def test_restart_joins_a_relation_said_twice() -> None:
    assert restarts("put the mug right. right of the bowl") == "put the mug right of the bowl"
    assert restarts("put the mug right. left of the bowl") == "put the mug right. left of the bowl"


@pytest.mark.parametrize(("said", "read"), [
    ("put it on the green block. On the green block.", "put it on the green block."),
    ("a circle, facing west. West, the left.", "a circle, facing west."),
    ("make it 40 across. Yeah. Forty.", "make it 40 across."),
    ("in the far right corner. The far one.", "in the far right corner."),
    ("stand it on the plate. On it, yeah.", "stand it on the plate."),
    ("in a circle in the back middle. Far side of the table, in the middle of it.", "in a circle in the back middle."),
    ("The third can from the left-- hmm, from the left, yeah-- put it behind the bowl.",
     "The third can from the left, put it behind the bowl."),
])
def test_echo_goes(said: str, read: str) -> None:
    assert echoes(said) == read


@pytest.mark.parametrize("said", [
    "cup: left of bottle. bottle: left of cup.",          # the same words in another order: a contradiction
    "Stack the red, blue and green blocks. Red on blue.",  # a relation the first sentence did not say
    "Put the cups in a row. The bowls too.",               # a new object
    "Put the cups in a row. Put the cups in a row.",       # a verb of its own: read, not dropped
    "Put the cups -- the blue ones -- in a row",           # an aside with a new word
])
def test_echo_keeps_what_says_something(said: str) -> None:
    assert echoes(said) == said


_WORDS = st.sampled_from(["put", "the", "red", "blue", "cup", "bowl", "in", "a", "row", "circle", "left", "of",
                          "on", "back", "right", "corner", "facing", "me", "30", "cm"])


@settings(max_examples=150, deadline=None)
@given(st.lists(_WORDS, min_size=1, max_size=12))
def test_one_sentence_without_a_marker_is_unchanged(words: list[str]) -> None:
    text = " ".join(words) + "."
    assert repaired(text) == text


@pytest.mark.slow
@pytest.mark.parametrize(("scene", "said", "goals"), [
    ("blocks", "So the blue, green and purple blocks, a circle, um, in the near right corner. No, the far right corner.",
     [{"pattern": "circle", "objects": [2, 3, 6], "region": "top right"}]),
    ("home", "Put the three cans in a circle about 30 cm across. Actually no, make it 40 across. Yeah. Forty.",
     [{"pattern": "circle", "objects": [12, 13, 14], "size": 0.2}]),
])
def test_end_to_end(scene: str, said: str, goals: list[dict]) -> None:
    got = to_dict(parse_rules(SCENES[scene], said, matcher=default_matcher()))["goals"]
    assert sorted(got, key=str) == sorted(goals, key=str)
