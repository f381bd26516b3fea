"""Reading free-text colours into fills and textures."""

from __future__ import annotations

import pytest

from lgmcts.viz.paint import NAMED_COLORS, hex_color, luminance, paint


def test_two_colours_and_a_pattern():
    p = paint("red and green polka dot")
    assert p.fill == NAMED_COLORS["red"] and p.second == NAMED_COLORS["green"]
    assert p.texture == "dots" and p.mark == NAMED_COLORS["green"] and p.known


@pytest.mark.parametrize("text", ["light blue", "pale blue"])
def test_light_is_lighter(text):
    assert luminance(paint(text).fill) > luminance(paint("blue").fill)


def test_dark_is_darker():
    assert luminance(paint("dark green").fill) < luminance(paint("green").fill)


@pytest.mark.parametrize(
    "text, texture",
    [
        ("blue stripe", "stripes"),
        ("wooden", "grain"),
        ("granite", "speckles"),
        ("checkerboard", "checks"),
        ("yellow", None),
    ],
)
def test_textures(text, texture):
    assert paint(text).texture == texture


def test_material_gives_a_colour():
    p = paint("wooden")
    assert p.known and p.fill != paint("").fill


def test_unknown_text_is_grey_not_an_error():
    for text in ("", None, "shiny", "###"):
        p = paint(text)
        assert not p.known and p.second is None


def test_hex_and_contrast():
    assert paint("#3366cc").fill == pytest.approx((0.2, 0.4, 0.8))
    assert hex_color((1, 0, 0)) == "#ff0000"
    assert paint("black").ink == (1.0, 1.0, 1.0) and paint("white").ink != (1.0, 1.0, 1.0)
    assert set(paint("red and green polka dot").to_json()) == {"fill", "second", "mark", "ink", "edge", "texture"}
