"""The lexicon (lgmcts/language/data/lexicon.toml) is the one source of the parser's closed-class words."""

from __future__ import annotations

import re

from lgmcts.language import grounding, lexicon, rewrite, rules, shapes


def test_shape_nouns_are_keys_of_their_registered_patterns():
    assert lexicon.check_shape_nouns() == []


def test_modules_take_their_words_from_the_lexicon():
    assert rules._HUES is lexicon.HUES
    assert grounding.COLOUR_WORDS is lexicon.COLOUR_WORDS
    assert lexicon.HUES < lexicon.COLOUR_WORDS
    assert lexicon.HUES <= rewrite._NOUN_BEFORE


def test_macros_match_exactly_their_words():
    hue, shape = lexicon.MACROS["HUE"], lexicon.MACROS["SHAPE"]
    for w in lexicon.HUES:
        assert re.fullmatch(hue, w)
    for w in ("silver", "re", "reds", "greyish"):
        assert not re.fullmatch(hue, w)
    nouns = {n for ns in lexicon.SHAPE_NOUNS.values() for n in ns}
    assert {w for w in nouns if re.fullmatch(shape, w)} == nouns
    assert not re.fullmatch(shape, "lines")
    for name, words in lexicon.SHAPE_NOUNS.items():
        assert all(re.fullmatch(lexicon.MACROS[name.upper()], w) for w in words)
        assert not any(re.fullmatch(lexicon.MACROS[name.upper()], w) for w in nouns - set(words))


def test_alternation_puts_longer_words_first():
    alt = lexicon.alternation(["row", "rows"])
    assert re.match(alt, "rows").group(0) == "rows"


def test_tables_are_consistent():
    assert set(lexicon.SIZES.values()) == {"small", "medium", "large"}
    assert set(lexicon.ROWS.values()) == {"top", "middle", "bottom"}
    assert set(lexicon.COLS.values()) == {"left", "center", "right"}
    assert set(lexicon.FACINGS.values()) == {"north", "east", "south", "west"}
    assert set(lexicon.COMPASS.values()) == {"front", "back", "left", "right"}
    assert all(abs(dx) + abs(dy) == 1 for dx, dy in lexicon.DIRECTIONS.values())
    assert lexicon.UNITS["mm"] == 0.001 and lexicon.UNITS["metre"] == 1.0
    assert lexicon.NUMBERS["a couple of"] == 2
    assert shapes.SIZES == lexicon.SIZES
