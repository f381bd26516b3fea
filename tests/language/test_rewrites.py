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


def test_literal_needs_reads_the_words_a_pattern_cannot_do_without():
    needs = normalise.literal_needs
    assert needs(re.compile(r"(?i)\bin (?:the )?foreground\b")) == {"foreground"}
    assert needs(re.compile(r"(?i)\b(handles?|labels?) to")) == {"handle", "label"}
    assert needs(re.compile(r"(?i)(?<=facing )left")) == {"facing "}
    assert needs(re.compile(r"(?:fore|back)(?:ground)+")) == {"ground"}
    # nothing is needed where a part may be missing, a lookaround must fail, or a class stands alone
    assert needs(re.compile(r"(?:the )?x")) == {"x"}
    assert needs(re.compile(r"(?:left|)")) == frozenset()
    assert needs(re.compile(r"[a-z]+(?! of)")) == frozenset()


@pytest.mark.parametrize("said", [
    "Put the BLUE Block in the FOREGROUND please", "stack the red on teh blue", "mugs at the front, handles left",
    "put the cups in a row at the front, the row facing west", "Stack purple, red and green so that purple is lowest",
    "square them up", "line them up, café style",  # a text that is not plain ASCII is always searched
])
def test_the_quick_test_never_skips_a_row_that_would_change_the_text(said):
    import dataclasses

    for table in normalise.TABLES:
        text = said
        for rule in normalise.rules(table):
            searched = dataclasses.replace(rule, needs=())(text)
            assert rule(text) == searched, rule.id
            if searched != text:
                assert rule.could_match(text)
            text = searched


def test_every_example_is_read_the_same_with_and_without_the_quick_test():
    import dataclasses

    for rule in RULES:
        plain = dataclasses.replace(rule, needs=())
        for said, _ in rule.examples:
            for upper in (said, said.upper()):
                assert rule(upper) == plain(upper), (rule.id, upper)
