"""The second reading without a backdrop sentence (:mod:`lgmcts.language.backdrop`) and the requests about an
object the scene lacks that are never background (:func:`lgmcts.language.context.moves_unknown`)."""

from __future__ import annotations

import pytest

from lgmcts.language import backdrop, context
from lgmcts.language.clauses import _command_verb

_OBJECTS = frozenset({"pan", "tiger", "heart", "star", "cans", "can", "red", "mug", "mugs", "blue"})


def _said(w: str) -> bool:
    return w in _OBJECTS


def test_sentences_keep_titles_and_decimals_whole() -> None:
    assert backdrop.sentences("Mrs. Patel is in at 3.30 today. Put the cans in a row!") == [
        "Mrs. Patel is in at 3.30 today.", " Put the cans in a row!"]
    assert backdrop.sentences("no full stop at all") == ["no full stop at all"]


def test_a_blamed_story_goes_and_its_objects_stay_for_a_pronoun() -> None:
    text = "That tiger pan was my late wife's, won it at the county fair in '78. Set the heart behind it."
    again = backdrop.without_backdrop(text, "'the county fair' names nothing in the scene", _said, _command_verb)
    assert again == " the tiger pan. Set the heart behind it."


def test_a_blamed_story_with_no_pronoun_after_it_goes_whole() -> None:
    text = "My grandson set you up this morning and swore you could tidy. Put the cans in a row."
    again = backdrop.without_backdrop(text, "'my grandson set' names nothing in the scene", _said, _command_verb)
    assert again == " Put the cans in a row."


@pytest.mark.parametrize("text, refusal", [
    # the blamed sentence asks: it is the request, and its refusal stands
    ("The teapot should go by the window. Put the cans in a row.", "'the teapot' names nothing in the scene"),
    ("Could you put the teapot on the tray? My wife was out.", "'the teapot' names nothing in the scene"),
    ("Put the teapot on the tray. I was out.", "'the teapot' names nothing in the scene"),
    # no other sentence asks
    ("My grandson set you up this morning. He was proud.", "'my grandson set' names nothing in the scene"),
    # one sentence only
    ("my grandson set the cans in a row", "'my grandson set' names nothing in the scene"),
    # the words quoted are not the sentence's
    ("My grandson was here. Put the cans in a spiral.", "'put the cans in a spiral': no pattern matches"),
    # no words quoted at all
    ("My grandson was here. Put the cans in a row.", "the instruction is empty"),
])
def test_no_second_reading(text: str, refusal: str) -> None:
    assert backdrop.without_backdrop(text, refusal, _said, _command_verb) is None


def test_a_request_about_a_missing_object_is_never_a_remark() -> None:
    unknown = frozenset({"teapot", "window", "tray", "props", "third"})
    assert context.moves_unknown("put the teapot by the window".split(), unknown)
    assert context.moves_unknown("the teapot should go on the tray".split(), unknown)
    assert not context.moves_unknown("set the props".split(), unknown)
    assert not context.moves_unknown("leave the third alone".split(), unknown)
    assert context.wishes("the teapot should go by the window".split())
    assert not context.wishes("i'm not sure which one should go first".split())
