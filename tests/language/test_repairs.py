"""Spoken repairs, restarts and echoes (lgmcts.language.repairs), at their stage and end to end."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from lgmcts.formats import parse_scene
from lgmcts.language.repairs import echoes, repaired, restarts, typed_repairs
from tables import assert_reads

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
    # "the same" with a place of its own: the place replaces the one said before (it was dropped)
    ("pantry", "The bowls, put them in a row in the back right. Same for the cups but front left.",
     [{"pattern": "line", "objects": [5, 6, 7], "region": "top right"},
      {"pattern": "line", "objects": [8, 9], "region": "bottom left"}]),
    # ... or joins the goal where none was said before
    ("pantry", "The bowls, put them in a row. Same for the cups but front left.",
     [{"pattern": "line", "objects": [5, 6, 7]}, {"pattern": "line", "objects": [8, 9], "region": "bottom left"}]),
    # "X, same thing" is "the same for X" (it was dropped)
    ("pantry", "The bowls in a row in the back right. The cups, same thing.",
     [{"pattern": "line", "objects": [5, 6, 7], "region": "top right"},
      {"pattern": "line", "objects": [8, 9], "region": "top right"}]),
    # one object on each side of another, as named
    ("dinner", "put the fork and the knife on either side of the plate",
     [{"pattern": "left", "objects": [3], "anchor": 1}, {"pattern": "right", "objects": [4], "anchor": 1}]),
    ("blocks", "Flank the white bowl with the red block and the blue block, one each side.",
     [{"pattern": "left", "objects": [1], "anchor": 7}, {"pattern": "right", "objects": [2], "anchor": 7}]),
    # "the one matching the T": one object, never the T itself; a plural takes the T along, as labelled before
    ("toys", "put the one matching the T behind the pan", [{"pattern": "behind", "objects": [7], "anchor": 12}]),
    ("toys", "put the things matching the T behind the pan", [{"pattern": "behind", "objects": [3, 7], "anchor": 12}]),
    # "in the same colour as": the comparison is read (it was read past, every object lined up: a wrong goal)
    ("blocks", "The blocks in the same colour as the white bowl, line them up.", None),
    # a second exception joined by "and ... too" (it was dropped: a wrong goal)
    ("home", "Put all the bowls except the white one, and except the green one too, in a row.", None),
])
def test_end_to_end(scene: str, said: str, goals: list[dict] | None) -> None:
    assert_reads(SCENES[scene], said, goals)


def test_other_side_across_sentences_takes_the_object_of_the_side_said() -> None:
    """"The spoon, put it right of the bowl. And the fork, put it on its other side": left of the bowl, not of
    the fork (the "it" of the second sentence)."""
    from lgmcts.language.stages import other_side

    said = "The spoon, put it right of the bowl. And the fork, put it on its other side."
    assert other_side(said) == "The spoon, put it right of the bowl. And the fork, put it to the left of the bowl."
    # the whole reference up to the stop
    said = "put it right of the bowl nearest the phone. The fork on its other side"
    assert other_side(said).endswith("The fork to the left of the bowl nearest the phone")
    # within one sentence, and for a reference that runs on past five words, "it" as before
    assert other_side("the spoon right of the bowl, the fork on its other side").endswith("the fork to the left of it")
    said = "put it right of the bowl that is nearest to the phone on the table. The fork on its other side"
    assert other_side(said).endswith("The fork to the left of it")

