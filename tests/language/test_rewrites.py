"""The rewrite table (lgmcts/language/data/rewrites.toml): every row has an id and its own examples,
and each example is what that row alone makes of its input."""

from __future__ import annotations

import re

import pytest

from lgmcts.language import normalise
from lgmcts.language.rewrite import rewrite, unframe

#: Every row of every table of the file.
RULES = tuple(r for table in normalise.TABLES for r in normalise.rules(table))


def test_every_row_has_a_unique_id_and_an_example():
    ids = [r.id for r in RULES]
    assert len(ids) == len(set(ids))
    assert all(re.fullmatch(r"[a-z0-9]+(?:-[a-z0-9]+)*", i) for i in ids), [i for i in ids if not re.fullmatch(
        r"[a-z0-9]+(?:-[a-z0-9]+)*", i)]
    assert [r.id for r in RULES if not r.examples] == []


@pytest.mark.parametrize("rule", RULES, ids=[r.id for r in RULES])
def test_row_examples(rule):
    for said, want in rule.examples:
        assert said != want, "an example must show the row changing something"
        assert rule(said) == want


def test_rewrite_is_the_table_in_order():
    text = "Stack them so that the blue block is at the top... the white one's the base, right?"
    out = text
    for r in normalise.rules():
        out = r(out)
    assert rewrite(text) == out == normalise.apply(text)
    steps = normalise.trace(text)
    assert steps and steps[-1][1] == out
    assert [i for i, _ in steps] == [r.id for r in normalise.rules() if r.id in {i for i, _ in steps}]


def test_unframe_is_the_frame_table_in_order():
    text = "Okay so, when it's all done, it would be great if the cans were in a row"
    assert unframe(text) == "the cans in a row"
    assert [i for i, _ in normalise.trace(text, "frame")] == ["opener", "wish", "when-it-is-done"]
    with pytest.raises(KeyError):
        normalise.rules("no-such-table")


def test_macros_expand_from_the_lexicon_and_unknown_ones_fail():
    assert re.fullmatch(normalise.expand("{HUE} {SHAPE}", {}), "grey ring")
    assert not re.fullmatch(normalise.expand("{HUE}", {}), "silver")
    assert normalise.expand("x{1,3}", {}) == "x{1,3}"
    with pytest.raises(KeyError):
        normalise.expand("{NO_SUCH_MACRO}", {})


def test_when_and_unless_guard_a_row():
    hue_on_table = next(r for r in RULES if r.id == "hue-on-the-table-in-a-stack")
    assert hue_on_table("stack them, red on the table") == "stack them, red at the bottom"
    assert hue_on_table("put them in a row, red on the table") == "put them in a row, red on the table"
    first = next(r for r in RULES if r.id == "stack-without-its-word")
    assert first("the plate on the bottom, then the bowl") == "build a tower with the plate on the bottom, then the bowl"
    assert first("stack: the plate on the bottom, then the bowl") == "stack: the plate on the bottom, then the bowl"
