"""Places and facings said freely: by the table's edges, its corners and the viewer.

A pure stage over lower-cased tokens, read by the parameter reader
(:func:`.shapes.take_params`) before its own place words:

* :func:`read_facing` reads a facing said by an edge, a wall or the viewer
  ("facing the back wall" north; "turned toward the near edge", "pointing
  toward me", "facing the viewer" south; "facing away" north; "pointing at
  the right edge" east), also with the part that points ("tines toward the
  right edge", "handles to the left");
* :func:`read_place` reads a place said freely: "the near right corner"
  (bottom right), "dead centre" (middle center), "partway back on the
  right" (middle right: the cell, not the column), "the centre of the left
  side" (middle left), "a strip along the front" (the bottom row), "a band
  across the middle" (the middle row), "centred left to right" (the center
  column), "the middle row", "the left column".

The viewer stands at the table's front (south) edge looking north: what
faces the viewer faces south, what faces away faces north. A place word for
a cell never widens to a row or column; a band (a strip, a row, a column) is
the whole row or column, and only a band word makes one.
"""

from __future__ import annotations

from dataclasses import dataclass

from . import lexicon

#: The words for the table ("of the table", "of the workspace").
_TABLE = lexicon.TABLE_WORDS

__all__ = ["BAND_MARKS", "FACE_VERBS", "POINTING_PARTS", "Place", "read_facing", "read_place", "side_anchor"]

#: The lexicon's facing verbs and their other forms.
FACE_VERBS = lexicon.FACE_VERBS | {"point", "points", "turn", "aim", "aiming", "directed"}
#: Parts of an object that say which way it points ("tines toward the right edge").
POINTING_PARTS = frozenset({"tines", "tine", "handles", "handle", "tips", "tip", "blades", "blade", "spout", "spouts",
                            "labels", "label", "openings", "opening", "heads", "head", "noses", "nose", "prongs",
                            "logos", "logo", "lettering", "branding", "barcodes", "barcode", "fronts"})
_TOWARD = ("toward", "towards", "to", "at", "in", "into", "the", "direction", "of", "facing", "face", "out", "straight", "off",
           "directly", "round", "around", "so", "they", "it", "that", "all", "are", "is", "as")
_SIDE_NOUNS = frozenset({"edge", "side", "wall", "end", "border", "rim"})
#: Which way a thing faces when it faces that edge (or the viewer).
_EDGES = {"back": "north", "far": "north", "rear": "north", "top": "north", "north": "north",
          "front": "south", "near": "south", "bottom": "south", "south": "south",
          "left": "west", "west": "west", "right": "east", "east": "east"}
_VIEWER = lexicon.VIEWER_WORDS | {"person"}


def read_facing(words: tuple[str, ...], i: int) -> tuple[str, int] | None:
    """A facing said by an edge or the viewer, starting at ``i`` (a facing verb or a pointing
    part): ``(compass direction, end)``, or None."""
    n = len(words)
    if i >= n or (words[i] not in FACE_VERBS and words[i] not in POINTING_PARTS):
        return None
    j = i + 1
    if words[i] in POINTING_PARTS:
        # "tines toward ...", "handles pointing to ...": the part, then a facing verb or "toward"
        while j < n and words[j] in ("all", "are", "is", "should", "be"):
            j += 1
        if j < n and words[j] in FACE_VERBS:
            j += 1
        elif not (j < n and words[j] in ("toward", "towards", "to", "at")):
            return None
    while j < n and words[j] in _TOWARD:
        j += 1
    if j < n and words[j] == "away":
        k = j + 1
        while k < n and words[k] in ("from", "the"):
            k += 1
        if k < n and words[k] in _VIEWER:
            return "north", k + 1
        if k + 1 < n and words[k] in _EDGES and words[k + 1] in _SIDE_NOUNS:
            return {"north": "south", "south": "north", "east": "west", "west": "east"}[_EDGES[words[k]]], k + 2
        return "north", j + 1
    if j < n and words[j] in _VIEWER:
        return "south", j + 1
    hand = j + 2 < n and words[j] in ("left", "right") and words[j + 1] == "hand"  # "the right-hand side"
    if j + 1 + hand < n and words[j] in _EDGES and words[j + 1 + hand] in _SIDE_NOUNS:
        k = j + 2 + hand
        if k + 1 < n and words[k] == "of" and (words[k + 1] == "the" or words[k + 1] in _TABLE):
            k += 2 + (words[k + 1] == "the" and k + 2 < n and words[k + 2] in _TABLE)
        return _EDGES[words[j]], k
    if j < n and words[j] in ("back", "front", "rear", "far") and j > i + 1 and words[j - 1] == "the":
        return _EDGES[words[j]], _of_table(words, j + 1)  # "facing the back", "toward the rear of the table"
    if j < n and words[j] in ("left", "right") and j > i + 1 and words[j - 1] == "the" \
            and words[j + 1 : j + 2] != ("of",):
        return _EDGES[words[j]], j + 1  # "facing to the left", "turned toward the right" (not "... of the bowl")
    return None


@dataclass(frozen=True)
class Place:
    """A place said freely: ``row`` (top/middle/bottom) and ``col`` (left/center/right), either
    may be None; ``band`` marks a whole row or column ("a strip along the front")."""

    row: str | None
    col: str | None
    band: bool = False

    @property
    def region(self) -> str:
        """The goal's ``region`` value (docs/formats.md)."""
        if self.row and self.col:
            return f"{self.row} {self.col}"
        if self.row:
            return "middle row" if self.row == "middle" else self.row
        if self.col:
            return "center column" if self.col == "center" else self.col
        raise ValueError("a place with neither row nor column")


#: Marker words for the middle row, the center column and each cell (written by .stages.said_places, so that
#: no later rewrite widens them): "middleband", "centreband", "middleleftcell" ...
BAND_MARKS = {"middleband": Place("middle", None, True), "centreband": Place(None, "center", True),
              "leftband": Place(None, "left", True), "rightband": Place(None, "right", True),
              **{f"{r}{c}cell": Place(r, c) for r in ("top", "middle", "bottom") for c in ("left", "center", "right")}}
_ROWS = {"back": "top", "far": "top", "rear": "top", "top": "top", "upper": "top", "front": "bottom",
         "near": "bottom", "bottom": "bottom", "lower": "bottom", "middle": "middle", "centre": "middle",
         "center": "middle"}
_COLS = {"left": "left", "right": "right", "middle": "center", "centre": "center", "center": "center"}
_CENTRE = frozenset({"centre", "center", "middle"})
_BANDS = frozenset({"strip", "band", "stripe", "belt", "lane"})
_PARTWAY = frozenset({"partway", "halfway", "midway", "part-way", "half-way"})


def read_place(words: tuple[str, ...], i: int) -> tuple[Place, int] | None:
    """A place said freely at ``i``: ``(place, end)`` or None (the plain place words are left
    to the parameter reader)."""
    n = len(words)
    j = i
    while j < n and words[j] in ("in", "at", "on", "into", "to", "over", "toward", "towards", "a", "the", "out", "across",
                                 "along", "through", "down"):
        j += 1
    if j >= n:
        return None
    w = words[j]
    if w in BAND_MARKS:  # a band said freely and marked before rewriting (.stages.said_places)
        return BAND_MARKS[w], j + 1
    # "dead centre", "smack in the middle", "slap bang in the centre"
    if w in ("dead", "bang", "smack", "slap", "plumb", "bang-on", "exact", "exactly", "precise"):
        k = j + 1
        while k < n and words[k] in ("bang", "in", "the", "on"):
            k += 1
        if k < n and words[k] in _CENTRE:
            k += 1
            if k + 2 < n and words[k] == "of" and words[k + 1] == "the" and words[k + 2] in _TABLE:
                k += 3
            return Place("middle", "center"), k
        return None
    # "partway back on the right", "halfway up the left side"
    if w in _PARTWAY or (w in ("part", "half") and j + 1 < n and words[j + 1] == "way"):
        k = j + 1 + (w in ("part", "half"))
        if k < n and words[k] in ("back", "up", "along", "down", "across", "forward", "in"):
            k += 1
            got = _side_after(words, k)
            if got is not None:
                col, end = got
                return Place("middle", col), end
            return Place("middle", None), k
        return None
    # "a strip along the front (edge)", "a band across the middle", "a strip from front to back down the middle"
    if w in _BANDS:
        k = j + 1
        while k < n and words[k] in ("along", "across", "at", "by", "on", "in", "through", "down", "the", "of"):
            k += 1
        if k < n and words[k] in ("front", "back", "near", "far", "rear", "top", "bottom", "left", "right"):
            end = k + 1 + (k + 1 < n and words[k + 1] in _SIDE_NOUNS)
            if words[end : end + 1] == ("of",) and _of_table(words, end) == end:
                return None  # "a strip on the left of the plate": a relation, not a place on the table
            if words[k] in ("left", "right"):
                return Place(None, words[k], True), _of_table(words, end)
            return Place(_ROWS[words[k]], None, True), _of_table(words, end)
        if k < n and words[k] in _CENTRE:
            # "a band across the middle" runs left to right: the middle row; "down the middle" the column
            across = "across" in words[j + 1 : k] or "along" in words[j + 1 : k]
            return (Place("middle", None, True) if across else Place(None, "center", True)), _of_table(words, k + 1)
        return None
    # "the middle row", "the left column", "the front row of the table"
    if w in _ROWS and j + 1 < n and words[j + 1] == "row" and w not in ("left", "right") and (
            (j > i and words[j - 1] == "the") or (j == i and (i == 0 or words[i - 1] in (",", ";", ":")))):
        # "the middle row", ", top row" said apart
        return Place(_ROWS[w], None, True), _of_table(words, j + 2)
    if w in _COLS and j + 1 < n and words[j + 1] == "column" and j > i and words[j - 1] == "the":
        return Place(None, _COLS[w], True), _of_table(words, j + 2)
    # "centred left to right" (the center column), "centred front to back" (the middle row)
    if w in ("centred", "centered", "central"):
        k = j + 1
        if k < n and words[k] in ("from",):
            k += 1
        if words[k : k + 3] in (("left", "to", "right"), ("right", "to", "left")):
            return Place(None, "center", True), k + 3
        if words[k : k + 3] in (("front", "to", "back"), ("back", "to", "front")):
            return Place("middle", None, True), k + 3
        return None
    # "the centre of the left side", "the middle of the right edge", "the centre of the front edge"
    if w in _CENTRE and j > i and words[j - 1] == "the" and j + 2 < n and words[j + 1] == "of":
        k = j + 2 + (words[j + 2] == "the")
        k += k < n and words[k] == "table's"
        if k + 1 < n and words[k] in _EDGES and words[k + 1] in _SIDE_NOUNS | {"half"}:
            side = words[k]
            end = _of_table(words, k + 2)
            if side in ("left", "right"):
                return Place("middle", side), end
            if side in _ROWS:
                return Place(_ROWS[side], "center"), end
        return None
    # "front and centre": the middle of the front row
    if w in ("front", "back") and words[j + 1 : j + 2] == ("and",) and j + 2 < n and words[j + 2] in _CENTRE:
        return Place(_ROWS[w], "center"), j + 3
    # "the near right corner", "the far-left corner", "the back left corner"
    if w in ("near", "far", "front", "back", "rear") and j + 2 < n and words[j + 1] in ("left", "right") \
            and words[j + 2] == "corner":
        return Place(_ROWS[w], words[j + 1]), _of_table(words, j + 3)
    return None


def _side_after(words: tuple[str, ...], k: int) -> tuple[str, int] | None:
    """"on the right", "on the left side", ", right side" after a partway: the column and the end."""
    n = len(words)
    j = k
    while j < n and words[j] in (",", "on", "to", "the", "at", "of", "up", "along"):
        j += 1
    if j < n and words[j] in ("left", "right"):
        end = j + 1
        while end < n and words[end] in ("side", "hand", "edge"):
            end += 1
        return words[j], _of_table(words, end)
    return None


def _of_table(words: tuple[str, ...], k: int) -> int:
    if words[k : k + 2] == ("of", "the") and words[k + 2 : k + 3] and words[k + 2] in _TABLE:
        return k + 3
    if words[k : k + 1] == ("of",) and words[k + 1 : k + 2] and words[k + 1] in _TABLE:
        return k + 2
    return k


def side_anchor(words: tuple[str, ...], i: int) -> tuple[int, int] | None:
    """The reference object of a side said at ``i`` ("right of the bowl", "to the left of the red mug"): the token
    range of "the bowl", or None where no "of the ..." follows the side word (a place, or a pronoun: "left of it")."""
    j = i + 1 + (words[i + 1 : i + 2] == ("hand",)) + (words[i + 1 : i + 3] == ("side", "of"))
    if words[j : j + 1] != ("of",) or words[j + 1 : j + 2] not in (("the",), ("that",), ("this",)):
        return None
    k = j + 2
    while k < len(words) and k < j + 6 and words[k].isalpha() and words[k] not in ("and", "then", "but", "so"):
        k += 1
    if k < len(words) and words[k].isalpha() and words[k] not in ("and", "then", "but", "so"):
        return None  # a longer reference ("the bowl nearest the phone"): left to "it"
    return (j + 1, k) if k > j + 2 else None
