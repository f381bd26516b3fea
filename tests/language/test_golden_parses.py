"""The offline parser's output on every labelled command equals the committed golden digests
(``tests/data/golden_parses.json``; see ``tests/language/golden_parse.py``)."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

sys.path.insert(0, str(Path(__file__).parent))
import golden_parse


def test_reason_drops_quoted_words_and_numbers():
    a = golden_parse.reason("'the red cup' names no object in the scene")
    b = golden_parse.reason("'a blue 3 plate'   names no object in the scene")
    assert a == b == "'…' names no object in the scene"
    assert golden_parse.reason("a tower needs at least 2 objects") != golden_parse.reason("'x' names no object")
    assert golden_parse.digest_of(None, "'x' is unclear") != golden_parse.digest_of(None, "'x' names nothing")
    assert golden_parse.digest_of({"goals": []}, None) != golden_parse.digest_of({"goals": [{}]}, None)


@pytest.mark.slow
def test_every_labelled_command_parses_as_the_golden_says(matcher):
    old = golden_parse.load()
    now = golden_parse.compute()
    assert set(now) == set(old), "case files added or removed: run `make golden-parse`"
    diff = golden_parse.changes(now, old)
    assert not diff, f"{len(diff)} parses differ from the golden (first ones: {diff[:10]}); " \
                     "run `python tests/language/golden_parse.py` to see them"
