"""Measures said in numbers (lgmcts.language.measures), read at their own stage."""

from __future__ import annotations

import pytest
from hypothesis import given
from hypothesis import strategies as st

from lgmcts.errors import InputError
from lgmcts.formats import parse_goals
from lgmcts.language.measures import find_measures, size_for
from lgmcts.language.stages import mark_measures


@pytest.mark.parametrize("text, metres, role, said", [
    ("make a 40 cm line of the cans", 0.4, "plain", "40 cm"),
    ("silverware in a row; 20 cm from the first piece to the last.", 0.2, "length",
     "20 cm from the first piece to the last"),
    ("the cans in a row, 30 cm from first to last", 0.3, "length", "30 cm from first to last"),
    ("a loop of the mugs with a 12 cm radius", 0.12, "radius", "12 cm radius"),
    ("a loop with radius 8 cm", 0.08, "radius", "radius 8 cm"),
    ("the bowls in a ring 24 cm across", 0.24, "across", "24 cm across"),
    ("a circle 50 cm in diameter", 0.5, "across", "50 cm in diameter"),
    ("a square 15 cm a side", 0.15, "side", "15 cm a side"),
    ("a square with sides of 22 cm", 0.22, "side", "sides of 22 cm"),
    ("a 50 by 30 cm rectangle of blocks", 0.5, "long_side", "50 by 30 cm"),
    ("a rectangle 20 x 35 cm", 0.35, "long_side", "20 x 35 cm"),
    ("a rectangle with its long side 0.3 m", 0.3, "long_side", "long side 0.3 m"),
    ("a row 450 mm long", 0.45, "length", "450 mm long"),
    ("a row a quarter of a metre long", 0.25, "length", "a quarter of a metre long"),
    ("a line half a metre end to end", 0.5, "length", "half a metre end to end"),
    ("a line ten inches long", 0.254, "length", "ten inches long"),
    ("a line of forty-five centimetres", 0.45, "plain", "forty-five centimetres"),
    ("cans in a row spaced 10 cm apart", 0.1, "spacing", "spaced 10 cm apart"),
    ("a row with the centres 9 cm apart", 0.09, "spacing", "with the centres 9 cm apart"),
    ("a circle roughly 0.2 m across", 0.2, "across", "roughly 0.2 m across"),
    ("a line of 1 ft", 0.3048, "plain", "1 ft"),
    ("a line point three metres long", 0.3, "length", "point three metres long"),      # decimals said aloud
    ("a ring, radius nought point one five m", 0.15, "radius", "radius nought point one five m"),
    ("a line one point two metres long", 1.2, "length", "one point two metres long"),
    ("a rectangle 0,3 m by 0,2 m", 0.3, "long_side", "0,3 m by 0,2 m"),                # a decimal comma
    # how it was measured, said after the role, goes with it (never read as a place at the centre)
    ("mugs in a line 25cm apart center to center", 0.25, "spacing", "25cm apart center to center"),
    ("in a square 18 cm each side, centre-to-centre.", 0.18, "side", "18 cm each side, centre-to-centre"),
    ("a line 30 cm long, measured centre-to-centre from the first can to the last", 0.3, "length",
     "30 cm long, measured centre-to-centre from the first can to the last"),
    ("cans in a 20 cm square, back left", 0.2, "side", "20 cm"),     # "a 20 cm square": the noun stays
    ("a circle with a circumference of roughly 60 cm", 0.6, "circumference", "a circumference of roughly 60 cm"),
    ("the cans in a row, each 15 cm from the next", 0.15, "spacing", "15 cm from the next"),
    # the two sides of one rectangle, said with two side words: one measure, its longer side
    ("a rectangle 30 cm wide and 15 cm deep", 0.3, "long_side", "30 cm wide and 15 cm deep"),
    ("a rectangle 0.2 m long and 0.12 m deep", 0.2, "long_side", "0.2 m long and 0.12 m deep"),
])
def test_a_quantity_is_read_with_its_role_and_span(text, metres, role, said):
    (m,) = find_measures(text)
    assert (round(m.metres, 4), m.role, m.text) == (metres, role, said)
    assert text[m.start : m.end] == said


@pytest.mark.parametrize("text", [
    "put 3 in a line", "stack the two mugs", "object 7 in a row", "put blocks 4, 5 and 6 in a circle",
    "a line of the ten blocks", "1. put the mug in front", "in a minute, please", "a metric line",
])
def test_numbers_without_a_unit_are_no_measure(text):
    assert find_measures(text) == []


def test_two_measures_in_one_command_are_both_found():
    got = find_measures("a ring of 10 cm radius and a row 30 cm long")
    assert [(round(m.metres, 4), m.role) for m in got] == [(0.1, "radius"), (0.3, "length")]
    got = find_measures("a row 30 cm long and 40 cm long")      # one side word twice: two measures, not sides
    assert [(round(m.metres, 4), m.role) for m in got] == [(0.3, "length"), (0.4, "length")]


@pytest.mark.parametrize("text, marked, kept", [
    ("a ring 30 cm across, thirty centimetres across yeah", "a ring sizemarka,  yeah", [0.3]),
    ("a row half a metre long, um, fifty centimetres", "a row sizemarka, um, ", [0.5]),
    ("a ring 30 cm across, 20 cm across", "a ring sizemarka, sizemarkb", [0.3, 0.2]),   # two: left to be refused
    ("a ring of 10 cm radius and a row 10 cm long", "a ring of sizemarka and a row sizemarkb", [0.1, 0.1]),
    # said again in other units, hedged, within 3 %: one measure, the first
    ("a line 8 inches long -- approximately 20 cm", "a line sizemarka -- ", [0.2032]),
    ("a line 8 inches long -- 20 cm", "a line sizemarka -- sizemarkb", [0.2032, 0.2]),   # not hedged: two
    ("a line 8 inches long -- approximately 25 cm", "a line sizemarka -- sizemarkb", [0.2032, 0.25]),
])
def test_a_measure_said_again_right_after_itself_is_one(text, marked, kept):
    out, found = mark_measures(text)
    assert out == marked and [round(m.metres, 4) for m in found] == kept


@pytest.mark.parametrize("pattern, text, n, size", [
    ("circle", "a 15 cm radius", 4, 0.15),
    ("circle", "a circumference of 62.8 cm", 4, 0.0999),
    ("circle", "36 cm wide", 4, 0.18),
    ("circle", "a 30 cm circle", 4, 0.15),
    ("line", "25 cm", 3, 0.25),
    ("line", "12 cm apart", 3, 0.24),
    ("line", "12 cm apart", 5, 0.48),
    ("rectangle", "18 cm each side", 4, 0.18),
    ("rectangle", "40 by 20 cm", 4, 0.4),
    ("rectangle", "a third of a metre", 4, 0.3333),
    # kept to a tenth of a millimetre and rounded once: half of 9 inches is 0.1143, not half of a rounded 0.229
    ("circle", "9 inches across", 3, 0.1143),
    ("line", "4.5 in apart", 3, 0.2286),
    ("rectangle", "a foot each side", 4, 0.3048),
])
def test_size_follows_the_pattern(pattern, text, n, size):
    (m,) = find_measures(text)
    assert size_for(pattern, m, n) == size
    parse_goals({"goals": [{"pattern": pattern, "objects": list(range(1, n + 1)), "size": size}]})


@pytest.mark.parametrize("pattern, text", [
    ("tower", "30 cm tall"), ("left", "10 cm"), ("behind", "5 cm apart"),
    ("circle", "20 cm each side"), ("line", "a 10 cm radius"), ("rectangle", "10 cm radius"),
    ("circle", "10 cm apart"),
])
def test_a_measure_with_nothing_to_set_is_refused_quoting_it(pattern, text):
    (m,) = find_measures(text)
    with pytest.raises(InputError) as exc:
        size_for(pattern, m, 3)
    assert f"'{m.text}'" in str(exc.value)


@given(st.integers(min_value=1, max_value=999), st.sampled_from([("cm", 0.01), ("mm", 0.001), ("m", 1.0)]))
def test_any_whole_number_with_a_unit_is_read_in_metres(n, unit):
    (m,) = find_measures(f"a line {n} {unit[0]} long")
    assert round(m.metres, 4) == round(n * unit[1], 4)
    assert m.role == "length"
