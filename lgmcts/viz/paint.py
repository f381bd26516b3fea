"""Turn an object's free-text colour into something a picture can fill with.

Scene files describe colours the way a person or a colour detector would:
``"red"``, ``"light blue"``, ``"red and green polka dot"``, ``"wooden"``.
:func:`paint` reads such text into a :class:`Paint`: a main fill colour, an
optional second colour and an optional texture (dots, stripes, checks,
speckles, grain) that the renderers draw as a hatch in the second colour.

Pure Python, no plotting library: the HTML viewer receives the same paints.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

__all__ = ["NAMED_COLORS", "TEXTURES", "Paint", "hex_color", "luminance", "paint"]

#: Colour words understood in scene files, as RGB in [0, 1].
NAMED_COLORS: dict[str, tuple[float, float, float]] = {
    "red": (0.84, 0.15, 0.16),
    "green": (0.17, 0.63, 0.17),
    "blue": (0.12, 0.35, 0.80),
    "yellow": (0.98, 0.84, 0.10),
    "orange": (1.00, 0.50, 0.05),
    "purple": (0.50, 0.25, 0.70),
    "violet": (0.56, 0.36, 0.85),
    "pink": (0.97, 0.53, 0.73),
    "magenta": (0.85, 0.10, 0.65),
    "cyan": (0.10, 0.75, 0.85),
    "teal": (0.00, 0.50, 0.50),
    "brown": (0.55, 0.34, 0.16),
    "tan": (0.82, 0.71, 0.55),
    "beige": (0.93, 0.88, 0.75),
    "white": (0.97, 0.97, 0.95),
    "black": (0.12, 0.12, 0.12),
    "gray": (0.55, 0.55, 0.55),
    "grey": (0.55, 0.55, 0.55),
    "silver": (0.75, 0.75, 0.78),
    "gold": (0.85, 0.65, 0.13),
    "olive": (0.50, 0.50, 0.10),
    "navy": (0.10, 0.15, 0.45),
    "maroon": (0.50, 0.05, 0.10),
    "lime": (0.55, 0.85, 0.20),
    "turquoise": (0.25, 0.80, 0.75),
    "indigo": (0.29, 0.10, 0.55),
    "cream": (0.99, 0.96, 0.85),
    "khaki": (0.76, 0.69, 0.45),
    "transparent": (0.85, 0.92, 0.95),
    "clear": (0.85, 0.92, 0.95),
}

#: Texture words and the texture they name. Materials also imply a colour
#: when the text names none (see ``_MATERIAL_COLORS``).
TEXTURES: dict[str, str] = {
    "polka": "dots",
    "dot": "dots",
    "dots": "dots",
    "dotted": "dots",
    "spotted": "dots",
    "stripe": "stripes",
    "stripes": "stripes",
    "striped": "stripes",
    "checker": "checks",
    "checkered": "checks",
    "checkerboard": "checks",
    "plaid": "checks",
    "tiles": "checks",
    "tiled": "checks",
    "granite": "speckles",
    "marble": "speckles",
    "speckled": "speckles",
    "wood": "grain",
    "wooden": "grain",
    "swirl": "waves",
    "paisley": "waves",
    "rainbow": "stripes",
}

_MATERIAL_COLORS: dict[str, tuple[float, float, float]] = {
    "wood": (0.72, 0.53, 0.32),
    "wooden": (0.72, 0.53, 0.32),
    "granite": (0.60, 0.58, 0.56),
    "marble": (0.92, 0.91, 0.88),
    "metal": (0.70, 0.72, 0.75),
    "metallic": (0.70, 0.72, 0.75),
    "steel": (0.70, 0.72, 0.75),
    "plastic": (0.80, 0.80, 0.80),
    "rainbow": (0.90, 0.30, 0.30),
}

_RAINBOW_SECOND = (0.20, 0.45, 0.90)

#: Fill used when the text names no colour at all.
UNKNOWN = (0.78, 0.78, 0.76)


@dataclass(frozen=True)
class Paint:
    """How to fill one object's footprint.

    Attributes
    ----------
    fill : (3,) RGB in [0, 1], the main colour.
    second : (3,) RGB in [0, 1] or None, the colour of the texture marks.
    texture : one of ``"dots"``, ``"stripes"``, ``"checks"``, ``"speckles"``,
        ``"grain"``, ``"waves"``, or None for a plain fill.
    text : the colour text it was read from.
    known : False when no colour word was recognised (the fill is a neutral grey).
    """

    fill: tuple[float, float, float]
    second: tuple[float, float, float] | None = None
    texture: str | None = None
    text: str = ""
    known: bool = True

    @property
    def mark(self) -> tuple[float, float, float]:
        """Colour for texture marks: the second colour, else a contrasting shade."""
        if self.second is not None:
            return self.second
        return _shade(self.fill, -0.45) if luminance(self.fill) > 0.35 else _shade(self.fill, 0.55)

    @property
    def ink(self) -> tuple[float, float, float]:
        """Black or white, whichever reads better on top of :attr:`fill`."""
        return (0.08, 0.08, 0.08) if luminance(self.fill) > 0.45 else (1.0, 1.0, 1.0)

    @property
    def edge(self) -> tuple[float, float, float]:
        """A darker shade of the fill for the outline (grey for very dark fills)."""
        return _shade(self.fill, -0.5) if luminance(self.fill) > 0.12 else (0.45, 0.45, 0.45)

    def to_json(self) -> dict:
        """JSON-ready form for the HTML viewer (hex colours)."""
        return {
            "fill": hex_color(self.fill),
            "second": None if self.second is None else hex_color(self.second),
            "mark": hex_color(self.mark),
            "ink": hex_color(self.ink),
            "edge": hex_color(self.edge),
            "texture": self.texture,
        }


def luminance(rgb: tuple[float, float, float]) -> float:
    """Relative luminance (sRGB weights) of an RGB colour in [0, 1]."""
    r, g, b = rgb
    return 0.2126 * r + 0.7152 * g + 0.0722 * b


def hex_color(rgb: tuple[float, float, float]) -> str:
    """``#rrggbb`` of an RGB colour in [0, 1]."""
    return "#" + "".join(f"{round(max(0.0, min(1.0, c)) * 255):02x}" for c in rgb)


def _shade(rgb: tuple[float, float, float], amount: float) -> tuple[float, float, float]:
    """Mix towards white (amount > 0) or black (amount < 0)."""
    if amount >= 0:
        return tuple(c + (1.0 - c) * amount for c in rgb)  # type: ignore[return-value]
    return tuple(c * (1.0 + amount) for c in rgb)  # type: ignore[return-value]


def _hex(word: str) -> tuple[float, float, float] | None:
    m = re.fullmatch(r"#?([0-9a-f]{6})", word)
    if not m:
        return None
    h = m.group(1)
    return tuple(int(h[k : k + 2], 16) / 255.0 for k in (0, 2, 4))  # type: ignore[return-value]


def paint(text: str | None) -> Paint:
    """Read a free-text colour description.

    Parameters
    ----------
    text : str or None
        E.g. ``"red"``, ``"dark green"``, ``"red and green polka dot"``,
        ``"blue stripe"``, ``"wooden"``, ``"#3366cc"``.

    Returns
    -------
    Paint
        The first colour word gives the fill, a second one the texture
        colour; ``light``/``pale``/``dark`` shade the colour word that follows.
        A texture word with only one colour draws its marks in a contrasting
        shade of the fill. Unrecognised text gives a neutral grey with
        ``known=False``; it never fails.
    """
    raw = (text or "").strip()
    words = re.findall(r"#[0-9a-fA-F]{6}|[a-zA-Z]+", raw.lower())
    colors: list[tuple[float, float, float]] = []
    texture: str | None = None
    material: tuple[float, float, float] | None = None
    shade = 0.0
    for w in words:
        if w in ("light", "pale", "bright"):
            shade = 0.45 if w != "bright" else 0.15
            continue
        if w in ("dark", "deep"):
            shade = -0.4
            continue
        rgb = NAMED_COLORS.get(w) or _hex(w)
        if rgb is None and w.endswith("ish"):
            rgb = NAMED_COLORS.get(w[:-3])
        if rgb is not None:
            colors.append(_shade(rgb, shade) if shade else rgb)
            shade = 0.0
            continue
        if w in TEXTURES and texture is None:
            texture = TEXTURES[w]
        if w in _MATERIAL_COLORS and material is None:
            material = _MATERIAL_COLORS[w]
    if not colors and material is not None:
        colors.append(material)
        if "rainbow" in words:
            colors.append(_RAINBOW_SECOND)
    if not colors:
        return Paint(UNKNOWN, None, texture, raw, known=False)
    second = colors[1] if len(colors) > 1 else None
    if second is not None and texture is None:
        texture = "stripes"  # two colours with no pattern word: show both as stripes
    return Paint(colors[0], second, texture, raw, known=True)
