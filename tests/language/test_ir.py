"""The typed intermediate forms (lgmcts/language/ir.py) at the stage boundaries that use them."""

from __future__ import annotations

import itertools

import pytest
from hypothesis import given
from hypothesis import strategies as st

from lgmcts.errors import InputError
from lgmcts.formats import load_scene
from lgmcts.language.grounding import Vocabulary, find_mentions, tokenize
from lgmcts.language.matcher import key_vocabulary
from lgmcts.language.ir import Measure, Order, Ref, Relation


def test_tokens_carry_their_spans_and_kinds():
    text = "Put the red-swirl Block, 25 cm left!"
    toks = tokenize(text)
    assert [t.text for t in toks] == ["put", "the", "red", "swirl", "block", ",", "25", "cm", "left", "!"]
    for t in toks:
        assert text[t.start:t.end].lower() == t.text
        assert t.pos == t.start
    assert [t.kind for t in toks if t.text in ("25", ",", "red")] == ["word", "punct", "number"]


@given(st.text(alphabet="abcXYZ -',.;0123456789\u2019", max_size=40))
def test_token_spans_cover_their_text(text):
    toks = tokenize(text)
    assert all(0 <= a.start < a.end <= len(text) for a in toks)
    assert all(a.end <= b.start for a, b in itertools.pairwise(toks))
    for t in toks:
        assert text[t.start:t.end].lower().replace("\u2019", "'") == t.text


@pytest.mark.parametrize("value, unit, metres", [(25, "cm", 0.25), (300, "mm", 0.3), (0.5, "m", 0.5),
                                                 (36, "centimetres", 0.36), (1, "inch", 0.0254)])
def test_measures_are_in_metres(value, unit, metres):
    assert Measure.said(value, unit).metres == pytest.approx(metres)


def test_unknown_unit_or_negative_length_is_refused():
    with pytest.raises(InputError, match="unknown unit"):
        Measure.said(3, "furlongs")
    with pytest.raises(InputError, match="negative"):
        Measure.said(-3, "cm")


def test_refs_compose():
    tray = Ref("the tray", "the", frozenset({"tray"}))
    mug = Ref("the mug on the tray", "the", frozenset({"mug"}), relation=Relation("on", tray))
    left = Ref("the two leftmost blocks", "count", frozenset({"block"}), count=2, order=Order("x", 1, 2))
    assert mug.relation is not None and mug.relation.other is tray
    assert left.order == Order("x", 1, 2)


def test_ref_from_a_grounded_mention():
    scene = load_scene("examples/tabletop.json")
    vocab = Vocabulary.from_scene(scene)
    words = tuple(t.text for t in tokenize("put all blocks except the red one in a row"))
    ms = find_mentions(vocab, words, key_vocabulary())
    refs = [Ref.from_mention(m) for m in ms]
    assert refs and refs[0].det == "all" and refs[0].span == (ms[0].start, ms[0].end)
    assert all(isinstance(x, Ref) for r in refs for x in r.exclusions)
