"""Misspellings and informal spellings (lgmcts.language.spelling), corrected at their own stage."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from hypothesis import given
from hypothesis import strategies as st

from lgmcts.formats import parse_scene
from lgmcts.language.rules import goal_dicts
from lgmcts.language.spelling import Corrector, edit_distance, english_rank

_SCENE = {"dish", "mug", "mugs", "bowl", "bowls", "box", "boxes", "heart", "hearts", "fork", "forks", "plate", "plates",
          "red", "blue", "green", "purple", "orange", "yellow", "white", "star", "stars", "can", "cans", "letter",
          "letters"}
_LEX = {"behind", "front", "left", "right", "stack", "circle", "rectangle", "line", "row", "radius", "put", "place",
        "the", "in", "on", "of", "top", "bottom", "next", "square", "ring", "centre", "center", "move", "between",
        "side", "edge", "meter", "lay", "table", "label"}
_NOUNS = {"circle", "line", "row", "ring", "rectangle", "square"}


def _fix(text: str) -> str:
    return Corrector(_SCENE, _LEX, _NOUNS, protect={"great", "please", "shall", "placed"},
                     colours={"red", "blue", "green", "purple", "orange", "yellow", "white"},
                     read={"required", "respectively", "piles"}).text(text)


@pytest.mark.parametrize("text, fixed", [
    ("put the forks in a rectngle", "put the forks in a rectangle"),   # a letter left out
    ("put the mug behidn the plate", "put the mug behind the plate"),  # two letters swapped
    ("the yelow mug on the plaet", "the yellow mug on the plate"),
    ("move the purpel box", "move the purple box"),
    ("a cirlce of the mugs", "a circle of the mugs"),
    ("stck the mugs", "stack the mugs"),
    ("the hearts in a rinng", "the hearts in a ring"),
    ("the lettres in a row", "the letters in a row"),
    ("put teh fork infront of the box", "put the fork in front of the box"),
    ("Plaet on the left", "Plate on the left"),
    ("the blu mug on the box", "the blue mug on the box"),             # a rare word, a letter short of a colour
    ("a 10 cm raduis", "a 10 cm radius"),
    ("the orng mug behnd the box", "the orange mug behind the box"),   # vowels left out of a colour
    ("a prpl star", "a purple star"),
    ("stak the 3 bowlz", "stack the 3 bowls"),                        # a plural said with a z
    ("cud u put the fork rite of the box", "could you put the fork right of the box"),  # informal spellings
    ("put the mug thats red behind the box, doesnt matter how", "put the mug that's red behind the box, doesn't matter how"),
    ("stack em", "stack them"),                                        # contractions without their apostrophe
    ("the mug left of the plait", "the mug left of the plate"),       # sounds like a name the scene has
    ("put the read mug write of the box", "put the red mug right of the box"),  # homophones read by their neighbours
    ("stack the read mug on the blew mug", "stack the red mug on the blue mug"),
    ("put too mugs on the plate", "put two mugs on the plate"),
    ("put for cans in a row", "put four cans in a row"),
    ("the mug closest 2 me, n the box", "the mug closest to me, and the box"),   # texting
    ("the thre mugs on the plait", "the three mugs on the plate"),
    ("the fork left of the bowll", "the fork left of the bowl"),       # a letter typed twice: not 'bowls'
    ("put the forc behind the box", "put the fork behind the box"),   # a tie broken by the scene's own word
    ("the 2nd mug from the left", "the second mug from the left"),    # an ordinal in figures
    ("the mugs that share a color w the box", "the mugs that share a color with the box"),   # texting
    ("the red mug and the blue myg", "the red mug and the blue mug"),   # a neighbouring key in a three-letter name
    ("cans in a sirkle", "cans in a circle"),                            # spelt as it sounds
    ("the mugs in a cirkel", "the mugs in a circle"),
    ("all the letters exc the box", "all the letters except the box"),  # shorthand
    ("the bloo mug on the rde box", "the blue mug on the red box"),     # a colour's vowels spelt otherwise
    ("turn the mug 1.5 rad", "turn the mug 1.5 rad"),                  # three letters: only two swapped
    ("the heart in frontof the box", "the heart in front of the box"),   # two known words without the space
    ("the mug leftof the plate", "the mug left of the plate"),
    # two words without the space: one cut into two words the parser knows, one of them its own
    ("putthe redmug on the box", "put the red mug on the box"),
    ("the mugs along the frontedge", "the mugs along the front edge"),
    ("the redfrk on the box", "the red fork on the box"),              # a colour, then a name with a letter left out
    ("the mugs along the back of the tabel", "the mugs along the back of the table"),  # swapped before struck ('label')
    ("the leter A next to the box", "the letter A next to the box"),    # a letter left out: never 'leter' of 'let'
    ("the red mgu on the box", "the red mug on the box"),             # two letters swapped in a three-letter name
    ("the mugs either sde of the box", "the mugs either side of the box"),   # a letter left out of a word of three
    # the parser's words read by the commonest slips only
    ("it is requred that the mug is behind the box", "it is required that the mug is behind the box"),
    ("the mug and the box left and right of the plate, respectivly",
     "the mug and the box left and right of the plate, respectively"),
    ("the mug shal be plcaed on the box", "the mug shall be placed on the box"),
])
def test_a_misspelt_word_is_corrected(text, fixed):
    assert _fix(text) == fixed


@pytest.mark.parametrize("text", [
    "put the bowl on the box",            # known words never change
    "start with the mug",                 # a common English word is no slip of 'star'
    "the kids want the mug on the plate",
    "put the bowx on the plate",          # one edit from both 'bowl' and 'box': left as it is
    "the letter R next to the letter T",
    "put 3 forks in a row",
    "after lunch, the mug behind the plate",
    "a 10 cm radios",                     # an English word, however unlikely here
    "put the mugs in the middle-ish",     # a three-letter word never becomes an object's name ('dish')
    "the bx next to the mug",             # two letters: left alone
    "stack 'em up",                       # said with its apostrophe
    "read the letters, then put the mug on the box",  # "read" before no object is the verb
    "the tower should read orange, purple, yellow",    # ... and before a colour too
    "put the mug on the box for me",      # "for" before no plural of the scene
    "put the nife behind the box",        # a sound-alike of a name the scene lacks (no knife here)
    "1) stack the mugs 2) put the box on the dish",   # a numbered step is no "to"
    "the mugs in a row w/ the box",                   # "w/" is read by the rewrite table
    "put the mug in the mux",                         # 'x' is no neighbour of 'g' on the keyboard
    "the mug like the inlay on the box",              # a cut into a word of two letters ('in lay') is no reading
    "put the gmu on the box",                         # no two neighbouring letters of 'mug' swapped
    "ples put the mug on the box",                    # 'piles' is read, but the commoner 'poles' is as near
    "the ish on the box",                             # three letters: never an object's name ('dish')
])
def test_what_is_not_sure_is_left_as_it_is(text):
    assert _fix(text) == text


def test_a_struck_letter_is_no_correction_where_a_common_word_is_as_near():
    # Without letters on the table 'leter' is one letter from the unit 'meter' and from 'later' alike.
    no_letters = Corrector({"mug", "mugs", "box"}, _LEX, _NOUNS)
    assert no_letters.text("put the mug on the box, the rest leter") == "put the mug on the box, the rest leter"
    assert _fix("put the leter A on the box") == "put the letter A on the box"   # the scene's word, a letter left out


def test_an_inflection_doubles_the_end_of_a_short_base():
    assert english_rank("leter") is None and english_rank("letter") is not None
    assert english_rank("putting") is not None and english_rank("puting") is None
    assert english_rank("repositioned") is not None   # a word said again is English


def test_a_command_typed_fast_is_read_end_to_end(matcher):
    rows = map(json.loads, Path(__file__).with_name("fresh_cases.jsonl").read_text().splitlines())
    scenes = {r["scene_id"]: parse_scene(r["scene"]) for r in rows if "scene_id" in r}
    said = "putthe greencan infront of the whitebowl"
    assert goal_dicts(scenes["home"], said, matcher=matcher) == [{"pattern": "front", "objects": [14], "anchor": 3}]
    said = "it is requred that the leter R shal be plcaed behnid the granite bowl"
    assert goal_dicts(scenes["toys"], said, matcher=matcher) == [{"pattern": "behind", "objects": [2], "anchor": 9}]


def test_a_word_is_never_corrected_into_another_object_of_the_scene():
    # 'bowl' is a word of the scene's vocabulary in one scene and not in the other; it
    # never turns into 'box' either way, being an English word.
    only_box = Corrector({"box", "boxes", "mug"}, _LEX, _NOUNS)
    assert only_box.text("put the bowl on the box") == "put the bowl on the box"


@given(st.sampled_from(sorted(_SCENE | _LEX)))
def test_known_words_are_fixed_points(word):
    assert _fix(f"the {word} please") == f"the {word} please"


@given(st.text(alphabet="abcdefghij", max_size=8), st.text(alphabet="abcdefghij", max_size=8))
def test_edit_distance_is_symmetric_and_zero_only_on_equal(a, b):
    assert edit_distance(a, b, 20) == edit_distance(b, a, 20)
    assert (edit_distance(a, b, 20) == 0) == (a == b)
