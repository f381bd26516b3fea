"""Object catalogues of the benchmark suites.

Two families of objects, each a category noun with a footprint shape:

* VIMA-like tabletop shapes for the ELGR-style suite (blocks, bowls, letters,
  flat tiles cut as hearts, stars, crosses...) with plain colours and VIMA's
  textures ("red swirl", "granite", ...);
* household objects for the StructFormer-style suite (mugs, plates, bowls,
  cutlery...).

Sizes are metres. Footprints are convex because the scene format's polygon
shape is convex; a heart or a star is its convex hull.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

__all__ = ["HOUSEHOLD_KINDS", "PLAIN_COLORS", "VIMA_COLORS", "VIMA_KINDS", "Kind", "color_words", "kind"]


def _regular(r: float, m: int, phase: float = 0.0) -> list[list[float]]:
    return [
        [round(r * math.cos(phase + 2 * math.pi * k / m), 5), round(r * math.sin(phase + 2 * math.pi * k / m), 5)]
        for k in range(m)
    ]


def _scaled(points: list[list[float]], s: float) -> list[list[float]]:
    return [[round(x * s, 5), round(y * s, 5)] for x, y in points]


@dataclass(frozen=True)
class Kind:
    """One object category.

    Attributes
    ----------
    name : the noun used in scenes and instructions ("block", "letter A").
    plural : its plural ("blocks"); empty when "all <plural>" would read badly.
    make : ``make(scale) -> shape dict`` in the scene format (m).
    """

    name: str
    plural: str
    make: Callable[[float], dict]


def _box(sx: float, sy: float, sz: float) -> Callable[[float], dict]:
    return lambda s: {"type": "box", "size": [round(sx * s, 5), round(sy * s, 5), round(sz * s, 5)]}


def _cyl(r: float, h: float) -> Callable[[float], dict]:
    return lambda s: {"type": "cylinder", "radius": round(r * s, 5), "height": round(h * s, 5)}


def _poly(points: list[list[float]], h: float) -> Callable[[float], dict]:
    return lambda s: {"type": "polygon", "points": _scaled(points, s), "height": round(h * s, 5)}


#: VIMA-like categories. Letters have no plural: "all letter As" is not English.
VIMA_KINDS: tuple[Kind, ...] = (
    Kind("block", "blocks", _box(0.04, 0.04, 0.035)),
    Kind("bowl", "bowls", _cyl(0.034, 0.03)),
    Kind("pan", "pans", _cyl(0.04, 0.02)),
    Kind("letter A", "", _poly([[-0.03, -0.03], [0.03, -0.03], [0.008, 0.03], [-0.008, 0.03]], 0.015)),
    Kind("letter R", "", _poly([[-0.025, -0.03], [0.025, -0.03], [0.025, 0.015], [0.01, 0.03], [-0.025, 0.03]], 0.015)),
    Kind(
        "letter T",
        "",
        _poly([[-0.03, 0.03], [-0.03, 0.018], [-0.008, -0.03], [0.008, -0.03], [0.03, 0.018], [0.03, 0.03]], 0.015),
    ),
    Kind(
        "heart",
        "hearts",
        _poly(
            [[0.0, -0.032], [0.03, 0.0], [0.028, 0.02], [0.015, 0.03], [-0.015, 0.03], [-0.028, 0.02], [-0.03, 0.0]],
            0.015,
        ),
    ),
    Kind("triangle", "triangles", _poly(_regular(0.036, 3, math.pi / 2), 0.015)),
    Kind("flower", "flowers", _poly(_regular(0.032, 8), 0.015)),
    Kind("star", "stars", _poly(_regular(0.035, 5, math.pi / 2), 0.015)),
    Kind("hexagon", "hexagons", _poly(_regular(0.032, 6), 0.015)),
    Kind("pentagon", "pentagons", _poly(_regular(0.032, 5, -math.pi / 2), 0.015)),
    Kind(
        "cross",
        "crosses",
        _poly(
            [
                [0.01, 0.03],
                [-0.01, 0.03],
                [-0.03, 0.01],
                [-0.03, -0.01],
                [-0.01, -0.03],
                [0.01, -0.03],
                [0.03, -0.01],
                [0.03, 0.01],
            ],
            0.015,
        ),
    ),
    Kind("diamond", "diamonds", _poly([[0.0, 0.036], [-0.025, 0.0], [0.0, -0.036], [0.025, 0.0]], 0.015)),
)

#: Plain colours: safe for "all <colour> objects".
PLAIN_COLORS: tuple[str, ...] = ("red", "green", "blue", "yellow", "purple", "white", "orange", "pink", "cyan")

#: Plain colours and VIMA's textures.
VIMA_COLORS: tuple[str, ...] = (
    *PLAIN_COLORS,
    "red swirl",
    "green and blue stripe",
    "red and green polka dot",
    "granite",
    "tiger",
    "rainbow",
    "wooden",
)

#: Household objects of the StructFormer-style suite.
HOUSEHOLD_KINDS: tuple[Kind, ...] = (
    Kind("mug", "mugs", _cyl(0.04, 0.08)),
    Kind("cup", "cups", _cyl(0.033, 0.07)),
    Kind("can", "cans", _cyl(0.03, 0.1)),
    Kind("bowl", "bowls", _cyl(0.05, 0.045)),
    Kind("box", "boxes", _box(0.07, 0.05, 0.05)),
    Kind("block", "blocks", _box(0.045, 0.045, 0.045)),
    Kind("bottle", "bottles", _cyl(0.03, 0.12)),
    Kind("plate", "plates", _cyl(0.075, 0.015)),
    Kind("fork", "forks", _box(0.17, 0.022, 0.01)),
    Kind("knife", "knives", _box(0.19, 0.02, 0.01)),
    Kind("spoon", "spoons", _box(0.16, 0.03, 0.01)),
)


def kind(name: str, family: tuple[Kind, ...] = VIMA_KINDS + HOUSEHOLD_KINDS) -> Kind:
    """The category called ``name``."""
    for k in family:
        if k.name == name:
            return k
    raise KeyError(name)


def color_words(color: str) -> frozenset[str]:
    """Content words of a colour or texture: "red and green polka dot" -> {red, green, polka, dot}."""
    return frozenset(w for w in color.lower().split() if w != "and")


def scale(rng: np.random.Generator) -> float:
    """Random size factor of one object (dimensionless)."""
    return float(rng.uniform(0.85, 1.12))
