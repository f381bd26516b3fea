"""Measures said in numbers: "a 25 cm row", "a ring with a 15 cm radius", "half a metre".

A pure stage on the command's text, before it is tokenised for the rest of
the parser. :func:`find_measures` reads every quantity (a number, a fraction
or a number word, and a unit) together with the words that say what it
measures (its *role*: a radius, a width across, a side, a length, a spacing),
and returns them with their character spans. :func:`size_for` turns one
measure into the ``size`` of a goal (``docs/formats.md``): a circle's
radius, a line's length, a rectangle's longer side. A measure on a stack or
a relation has nothing to set and is refused with a line that quotes it, so
that a size said is never dropped from the goals.

Units: m, cm, mm, inches, feet (and their spellings); results are metres,
kept to a tenth of a millimetre (:data:`PLACES`) and rounded once: a size computed from a measure (half a width,
a spacing times the gaps) is computed from the measure as said, not from a rounded one ("9 inches across" is a
radius of 0.1143 m, not half of 0.229).
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from typing import Literal

from ..errors import InputError
from . import lexicon

__all__ = ["APPROXIMATE", "PLACES", "UNITS", "Measure", "Role", "find_measures", "size_for"]

#: Decimal places of metres a measure and a size are kept to (a tenth of a millimetre: "4 1/2 in." is 0.1143).
PLACES = 4

Role = Literal["radius", "across", "side", "long_side", "length", "spacing", "plain", "circumference"]

#: Unit words -> metres: the lexicon's length units, with the plural and short spellings people type.
UNITS: dict[str, float] = {
    **lexicon.UNITS, "cms": 0.01, "mms": 0.001, "mtr": 1.0, "mtrs": 1.0, '"': 0.0254, "ft": 0.3048, "foot": 0.3048,
    "feet": 0.3048,
}
_NUMBER_WORDS = {
    "zero": 0, "one": 1, "two": 2, "three": 3, "four": 4, "five": 5, "six": 6, "seven": 7, "eight": 8, "nine": 9,
    "ten": 10, "eleven": 11, "twelve": 12, "thirteen": 13, "fourteen": 14, "fifteen": 15, "sixteen": 16,
    "seventeen": 17, "eighteen": 18, "nineteen": 19, "twenty": 20, "thirty": 30, "forty": 40, "fifty": 50,
    "sixty": 60, "seventy": 70, "eighty": 80, "ninety": 90,
}
_TENS = frozenset({"twenty", "thirty", "forty", "fifty", "sixty", "seventy", "eighty", "ninety"})
_FRACTIONS = {"half": 0.5, "third": 1 / 3, "quarter": 0.25, "fifth": 0.2, "tenth": 0.1,
              "halves": 0.5, "thirds": 1 / 3, "quarters": 0.25, "fifths": 0.2, "tenths": 0.1}
#: Hedges before a quantity, taken with it ("about 30 cm").
_HEDGES = frozenset({"about", "around", "roughly", "approximately", "approx", "exactly", "some", "precisely", "just",
                     "circa", "~"})
#: Those of :data:`_HEDGES` that say a quantity is approximate ("approximately 20 cm"), not that it is exact.
APPROXIMATE = _HEDGES - {"exactly", "precisely", "just"}
#: Words after a quantity that say what it measures, longest first.
_AFTER: tuple[tuple[tuple[str, ...], Role], ...] = tuple(sorted((
    (("radius",), "radius"), (("in", "radius"), "radius"), (("of", "radius"), "radius"),
    (("wide",), "across"), (("across",), "across"), (("diameter",), "across"), (("in", "diameter"), "across"),
    (("in", "width"), "across"), (("width",), "across"), (("diam",), "across"),
    (("long",), "length"), (("in", "length"), "length"), (("deep",), "across"), (("in", "depth"), "across"), (("end", "to", "end"), "length"),
    (("from", "end", "to", "end"), "length"), (("in", "total"), "length"), (("total",), "length"),
    (("length",), "length"), (("from", "one", "end", "to", "the", "other"), "length"),
    (("apart",), "spacing"), (("between", "them"), "spacing"), (("between", "each"), "spacing"),
    (("between", "each", "one"), "spacing"), (("from", "each", "other"), "spacing"), (("spacing",), "spacing"),
    (("gap",), "spacing"), (("gaps",), "spacing"), (("gap", "between", "them"), "spacing"),
    (("from", "centre", "to", "centre"), "spacing"), (("from", "center", "to", "center"), "spacing"),
    (("from", "the", "next"), "spacing"), (("from", "the", "next", "one"), "spacing"),
    (("from", "its", "neighbour"), "spacing"), (("from", "its", "neighbor"), "spacing"),
    (("in", "circumference"), "circumference"), (("around",), "circumference"), (("round",), "circumference"),
    (("all", "the", "way", "round"), "circumference"), (("all", "the", "way", "around"), "circumference"),
    (("centre", "to", "centre"), "spacing"), (("center", "to", "center"), "spacing"),
    (("each", "side"), "side"), (("a", "side"), "side"), (("per", "side"), "side"), (("on", "each", "side"), "side"),
    (("on", "a", "side"), "side"), (("on", "every", "side"), "side"), (("to", "a", "side"), "side"),
    (("each", "way"), "side"), (("square",), "side"), (("on", "each", "edge"), "side"), (("each", "edge"), "side"),
    (("a", "side", "length"), "side"), (("sides",), "side"),
    (("on", "the", "long", "side"), "long_side"), (("on", "the", "longer", "side"), "long_side"),
    (("on", "its", "long", "side"), "long_side"), (("along", "the", "long", "side"), "long_side"),
), key=lambda pr: -len(pr[0])))
#: Words before a quantity that say what it measures, longest first (they end right before it).
_BEFORE: tuple[tuple[tuple[str, ...], Role], ...] = tuple(sorted((
    (("radius",), "radius"), (("radius", "of"), "radius"), (("a", "radius", "of"), "radius"),
    (("radius", "is"), "radius"), (("radius", ":"), "radius"), (("radius", "="), "radius"),
    (("r", "="), "radius"), (("r", ":"), "radius"), (("d", "="), "across"), (("diameter", "="), "across"),
    (("diameter",), "across"), (("diameter", "of"), "across"), (("a", "diameter", "of"), "across"),
    (("across",), "across"), (("width", "of"), "across"), (("a", "width", "of"), "across"),
    (("long", "side"), "long_side"), (("long", "side", "of"), "long_side"), (("longer", "side"), "long_side"),
    (("longer", "side", "of"), "long_side"), (("longest", "side"), "long_side"), (("long", "edge"), "long_side"),
    (("long", "sides"), "long_side"), (("long", "side", "is"), "long_side"), (("longer", "side", "is"), "long_side"),
    (("sides", "of"), "side"), (("side", "of"), "side"), (("side", "length", "of"), "side"), (("each", "side"), "side"),
    (("each", "side", "is"), "side"), (("sides",), "side"), (("side",), "side"), (("a", "side", "of"), "side"),
    (("length", "of"), "length"), (("a", "length", "of"), "length"), (("length",), "length"),
    (("circumference",), "circumference"), (("circumference", "of"), "circumference"),
    (("a", "circumference", "of"), "circumference"), (("circumference", "is"), "circumference"),
    (("spaced",), "spacing"), (("spaced", "out"), "spacing"), (("spaced", "by"), "spacing"),
    (("spacing", "of"), "spacing"), (("a", "spacing", "of"), "spacing"), (("gaps", "of"), "spacing"),
    (("a", "gap", "of"), "spacing"), (("spaced", "out", "by"), "spacing"), (("every",), "spacing"),
), key=lambda pr: -len(pr[0])))
#: "with their centres 15 cm apart": words before a spacing that belong to it.
_SPACING_LEAD = (("with", "their", "centres"), ("with", "their", "centers"), ("with", "the", "centres"),
                 ("with", "the", "centers"), ("their", "centres"), ("their", "centers"), ("centres",), ("centers",),
                 ("with",))

_TOKEN = re.compile(r"\d+(?:\.\d+)?|\.\d+|[a-z]+(?:'[a-z]+)?|\S")


@dataclass(frozen=True)
class Measure:
    """One quantity said in a command.

    ``start``/``end`` are character offsets of the whole phrase in the text
    (role words and hedges included); ``metres`` is the quantity as said,
    unrounded (for "A by B" the longer of the two), ``dims`` every number
    said, ``role`` what it measures ("plain" where no word says: "a 25 cm
    row"). :func:`size_for` rounds the size it gives to :data:`PLACES`.
    """

    start: int
    end: int
    text: str
    metres: float
    role: Role
    dims: tuple[float, ...]


def _tokens(text: str) -> list[tuple[str, int, int]]:
    low = text.lower().replace("\u2019", "'").replace("\u201d", '"').replace("\u2033", '"')
    toks = [(m.group(0), m.start(), m.end()) for m in _TOKEN.finditer(low)]
    out: list[tuple[str, int, int]] = []
    k = 0
    while k < len(toks):
        w, lo, hi = toks[k]
        if (w.isdigit() and k + 3 < len(toks) and toks[k + 1][0] == "," and toks[k + 1][1] == hi
                and toks[k + 2][0].isdigit() and toks[k + 2][1] == hi + 1 and toks[k + 3][0] in UNITS):
            # a decimal comma: "0,3 m", "12,5 cm" (digits on both sides, no space, a unit after)
            out.append((f"{w}.{toks[k + 2][0]}", lo, toks[k + 2][2]))
            k += 3
            continue
        out.append(toks[k])
        k += 1
    return out


def _number(ws: list[str], i: int) -> tuple[float, int] | None:
    """A number at ``i`` (digits, "twenty five", "twenty-five" as two words): (value, end)."""
    if i >= len(ws):
        return None
    w = ws[i]
    if re.fullmatch(r"\d+(?:\.\d+)?|\.\d+", w):
        frac = _slash_fraction(ws, i + 1) if w.isdigit() else None
        if frac is not None:
            return float(w) + frac[0], frac[1]  # a whole number and a fraction: "4 1/2 in", "11 1/2"
        frac = _slash_fraction(ws, i)
        if frac is not None:
            return frac  # "3/4 in"
        return float(w), i + 1
    if w in ("point", "nought", "oh", "zero") or (w in _NUMBER_WORDS and ws[i + 1 : i + 2] == ["point"]):
        # a decimal said aloud: "point three", "nought point two five", "one point five"
        whole = 0.0 if w in ("point", "nought", "oh", "zero") else float(_NUMBER_WORDS[w])
        j = i if w == "point" else i + 1
        if ws[j : j + 1] == ["point"]:
            digits = ""
            k = j + 1
            while k < len(ws) and ws[k] in _NUMBER_WORDS and _NUMBER_WORDS[ws[k]] < 10:
                digits += str(_NUMBER_WORDS[ws[k]])
                k += 1
            if digits:
                return whole + float("0." + digits), k
        if w in ("point", "nought", "oh"):
            return None
    if w in _NUMBER_WORDS:
        if 0 < _NUMBER_WORDS[w] < 10 and ws[i + 1 : i + 2] == ["hundred"]:
            # "three hundred", "one hundred and fifty", "two hundred twenty five"
            k = i + 2 + (ws[i + 2 : i + 3] == ["and"])
            rest = _number(ws, k) if k < len(ws) and ws[k] in _NUMBER_WORDS and ws[k] != "zero" else None
            if rest is not None and rest[0] < 100:
                return 100 * _NUMBER_WORDS[w] + rest[0], rest[1]
            return 100.0 * _NUMBER_WORDS[w], i + 2
        v = float(_NUMBER_WORDS[w])
        j = i + 1
        if w in _TENS and j < len(ws) and ws[j] == "-":
            j += 1
        if w in _TENS and j < len(ws) and ws[j] in _NUMBER_WORDS and 0 < _NUMBER_WORDS[ws[j]] < 10:
            return v + _NUMBER_WORDS[ws[j]], j + 1
        return v, i + 1
    return None


def _slash_fraction(ws: list[str], i: int) -> tuple[float, int] | None:
    """A fraction written with a slash at ``i`` ("1/2", "3 / 4": digits, "/", digits, the upper one smaller):
    (value, end), or None."""
    if i + 2 < len(ws) and ws[i].isdigit() and ws[i + 1] == "/" and ws[i + 2].isdigit():
        top, bottom = int(ws[i]), int(ws[i + 2])
        if 0 < top < bottom:
            return top / bottom, i + 3
    return None


def _unit(ws: list[str], i: int) -> tuple[float, int] | None:
    """A unit word at ``i``: (metres per unit, end). "in" counts only where no phrase follows it; a unit joined
    to its number by a hyphen ("a two-foot line", "a 30-cm row") counts as said."""
    if ws[i : i + 1] == ["-"] and i + 1 < len(ws) and ws[i + 1] in UNITS and ws[i + 1] != "in":
        i += 1
    if i >= len(ws) or ws[i] not in UNITS:
        return None
    if ws[i] == "in" and i + 1 < len(ws) and ws[i + 1] not in (",", ".", ";", "!", "?", "long", "wide", "across",
                                                             "apart", "radius", "diameter", "square", "each", "by",
                                                             "x", "on", "per"):
        return None  # "3 in a line": a preposition
    if ws[i] == "m" and i + 1 < len(ws) and ws[i + 1] == "'":
        return None
    return UNITS[ws[i]], i + 1


def _quantity(ws: list[str], i: int) -> tuple[tuple[float, ...], int] | None:
    """A quantity starting at ``i``: (values in metres, end)."""
    # Fractions of a unit: "half a metre", "a third of a metre", "two thirds of a metre", "a quarter metre".
    j = i
    count = 1.0
    if j < len(ws) and ws[j] in ("a", "an", "one") and j + 1 < len(ws) and ws[j + 1] in _FRACTIONS:
        j += 1
    elif j < len(ws) and ws[j] in _NUMBER_WORDS and j + 1 < len(ws) and ws[j + 1] in _FRACTIONS \
            and _NUMBER_WORDS[ws[j]] > 1:
        count = float(_NUMBER_WORDS[ws[j]])
        j += 1
    if j < len(ws) and ws[j] in _FRACTIONS:
        frac = _FRACTIONS[ws[j]] * count
        k = j + 1
        if k < len(ws) and ws[k] == "of":
            k += 1
        if k < len(ws) and ws[k] in ("a", "an", "one"):
            k += 1
        u = _unit(ws, k)
        if u is not None and ws[k] not in ("in", '"'):
            return (frac * u[0],), u[1]
        return None
    # "a metre", "a metre and a half", "one and a half metres"
    if i < len(ws) and ws[i] in ("a", "an") and i + 1 < len(ws) and ws[i + 1] in UNITS and ws[i + 1] not in ("in", "m", '"'):
        per = UNITS[ws[i + 1]]
        if ws[i + 2 : i + 5] == ["and", "a", "half"]:
            return (1.5 * per,), i + 5
        return (per,), i + 2
    got = _number(ws, i)
    if got is None:
        return None
    v, j = got
    if ws[j : j + 3] == ["and", "a", "half"]:
        v, j = v + 0.5, j + 3
    # "40 by 20 cm", "30 x 12 cm", "40 cm by 20 cm"
    u = _unit(ws, j)
    if j < len(ws) and ws[j] in ("by", "x", "\u00d7", "*"):
        second = _number(ws, j + 1)
        if second is not None:
            u2 = _unit(ws, second[1])
            if u2 is not None:
                return (v * u2[0], second[0] * u2[0]), u2[1]
        return None
    if u is None:
        return None
    k = u[1]
    if k < len(ws) and ws[k] in ("by", "x", "\u00d7", "*"):
        second = _number(ws, k + 1)
        if second is not None:
            u2 = _unit(ws, second[1])
            if u2 is not None:
                return (v * u[0], second[0] * u2[0]), u2[1]
            return (v * u[0], second[0] * u[0]), second[1]
    return (v * u[0],), k


#: "from the (centre of the) first (piece) to the (centre of the) last (one)": the first and last object of a
#: row, whatever noun is said.
_AT_ONE = ("the", "very", "centre", "center", "middle", "of")
_FIRST_TO_LAST = (("from",), _AT_ONE, ("first", "1st", "leftmost", "one"), ("to",), _AT_ONE,
                  ("last", "rightmost", "other"))


def _first_to_last(ws: list[str], j: int) -> int | None:
    """The end of "(, measured) from the first (noun) to the last (noun)" said at ``j`` (a line's length), or None."""
    k = j + (ws[j : j + 1] == [","])
    k += ws[k : k + 1] in (["measured"], ["taken"])
    for step, words in enumerate(_FIRST_TO_LAST):
        optional = words[0] in ("the",)
        while k < len(ws) and optional and ws[k] in words:
            k += 1
        if optional:
            continue
        if k >= len(ws) or ws[k] not in words:
            return None
        k += 1
        if step == 2 and k < len(ws) and ws[k] not in ("to",):
            k += 1  # a noun after "first": "from the first piece to the last"
    if k < len(ws) and ws[k].isalpha() and ws[k] not in ("and", "then", "in", "on", "at", "facing"):
        k += 1  # a noun after "last": "... to the last can"
    return k


_CENTRE_WORDS = frozenset({"centre", "center", "centres", "centers"})


def _centre_to_centre(ws: list[str], j: int) -> int | None:
    """The end of how a measure was taken, said after it: "(,) (measured) (from) centre(-)to(-)centre" and then
    "from the first (can) to the last"; None where it is not said at ``j``."""
    k = j + (ws[j : j + 1] == [","])
    k += ws[k : k + 1] == ["measured"]
    k += ws[k : k + 1] == ["from"]
    if k >= len(ws) or ws[k] not in _CENTRE_WORDS:
        return None
    k += 1
    k += ws[k : k + 1] == ["-"]
    if ws[k : k + 1] != ["to"]:
        return None
    k += 1
    k += ws[k : k + 1] == ["-"]
    if k >= len(ws) or ws[k] not in _CENTRE_WORDS:
        return None
    k += 1
    return _first_to_last(ws, k) or k


def _role_after(ws: list[str], j: int) -> tuple[Role, int] | None:
    for seq, role in _AFTER:
        if tuple(ws[j : j + len(seq)]) == seq:
            # "18 cm each side, centre-to-centre", "25 cm apart center to center": how it was measured goes with it
            end = j + len(seq)
            return role, _centre_to_centre(ws, end) or end
    last = _first_to_last(ws, j)
    if last is not None:
        return "length", last
    return None


def _role_before(ws: list[str], i: int) -> tuple[Role, int] | None:
    for seq, role in _BEFORE:
        if i - len(seq) >= 0 and tuple(ws[i - len(seq) : i]) == seq:
            return role, i - len(seq)
    return None


def find_measures(text: str) -> list[Measure]:
    """Every quantity with a unit in ``text``, with its role and its span."""
    toks = _tokens(text)
    ws = [t[0] for t in toks]
    out: list[Measure] = []
    i = 0
    while i < len(ws):
        got = _quantity(ws, i)
        if got is None:
            i += 1
            continue
        dims, j = got
        lo, hi = i, j
        role: Role = "plain"
        after = _role_after(ws, hi)
        if after is not None:
            role, hi = after
            if ws[hi - 1] == "square" and i and ws[i - 1] in ("a", "an", "one"):
                hi -= 1  # "a 20 cm square": the noun stays for the arrangement, the measure is its side
        k = lo
        while k > 0 and ws[k - 1] in _HEDGES:
            k -= 1
        before = _role_before(ws, k)
        if before is not None and (after is None or before[0] == role):
            role, k = before[0], before[1]
        lo = k
        while lo > 0 and ws[lo - 1] in _HEDGES:
            lo -= 1
        if role == "spacing":
            for seq in _SPACING_LEAD:
                if lo - len(seq) >= 0 and tuple(ws[lo - len(seq) : lo]) == seq:
                    lo -= len(seq)
                    break
        if len(dims) == 2 and role == "plain":
            role = "long_side"
        value = max(dims)
        if value <= 0:
            raise InputError(f"'{text[toks[i][1]:toks[j - 1][2]]}': a size must be more than zero")
        said = Measure(toks[lo][1], toks[hi - 1][2], text[toks[lo][1] : toks[hi - 1][2]], value, role, dims)
        if out and _two_sides(out[-1], said, text):
            # "30 cm wide and 15 cm deep", "0.2 m long and 0.12 m deep": the two sides of one rectangle
            first = out.pop()
            said = Measure(first.start, said.end, text[first.start : said.end], max(first.metres, said.metres),
                           "long_side", first.dims + said.dims)
        said, hi = _unit_said_once(ws, toks, text, said, lo, hi)
        out.append(said)
        i = hi
    return out


def _unit_said_once(ws: list[str], toks: list[tuple[str, int, int]], text: str, said: Measure, lo: int,
                    hi: int) -> tuple[Measure, int]:
    """``said`` with the other side of its rectangle where that side's number comes without a unit right
    after it ("36 cm long, 20 wide", "36 cm long by 20 wide": the unit said once), and the end of both."""
    last = said.text.lower().split()[-1]
    if said.role not in ("across", "length") or last not in _RECT_SIDES or len(said.dims) != 1:
        return said, hi
    k = hi
    while k < len(ws) and ws[k] in (",", "and", "by", "x"):
        k += 1
    got, first = _number(ws, k), _number(ws, lo)
    if got is None or first is None or not first[0] or got[1] >= len(ws) or ws[got[1]] not in _RECT_SIDES \
            or ws[got[1]] == last:
        return said, hi
    other = got[0] * said.dims[0] / first[0]
    end = got[1] + 1
    return Measure(said.start, toks[end - 1][2], text[said.start : toks[end - 1][2]], max(said.metres, other),
                   "long_side", (*said.dims, other)), end


_SIDE_WORDS = frozenset({"wide", "deep", "long", "high", "across"})
#: The side words of a rectangle's two sides ("across" restates a width: "36 cm wide, thirty-six across").
_RECT_SIDES = _SIDE_WORDS - {"across"}


def _two_sides(first: Measure, second: Measure, text: str) -> bool:
    """Whether ``second`` is the other side of the rectangle ``first`` measures: both said with a side word
    ("wide", "deep", "long"), joined only by "and" or "by"."""
    between = text[first.end : second.start].strip().lower()
    said = first.text.lower().split()[-1], second.text.lower().split()[-1]
    return (between in ("and", "by", "x", ", and") and first.role in ("across", "length")
            and second.role in ("across", "length") and said[0] in _SIDE_WORDS and said[1] in _SIDE_WORDS
            and said[0] != said[1])


_TOWERS = frozenset({"tower", "stack"})


def size_for(pattern: str, measure: Measure, n_objects: int) -> float:
    """The goal ``size`` (m) that ``measure`` asks of a ``pattern`` goal over ``n_objects`` objects.

    circle: the radius ("15 cm radius"; "36 cm wide/across", "a 30 cm circle" are
    diameters); line: the length from the first centre to the last ("a 25 cm row",
    "30 cm long"; "15 cm apart" times the gaps between n objects); rectangle: the
    longer side ("18 cm each side", "40 by 20 cm", "long side 0.26 m", "a 20 cm
    square"). Anything else is refused with a line that quotes the words.
    """
    said = f"'{measure.text}'"
    role, v = measure.role, measure.metres
    if pattern == "circle":
        if role == "radius":
            return round(v, PLACES)
        if role in ("across", "plain"):
            return round(v / 2, PLACES)
        if role == "circumference":
            return round(v / (2 * math.pi), PLACES)  # "a circumference of 60 cm": the radius it has
        raise InputError(f"{said}: a circle's size is its radius or its width across; say one of them")
    if pattern == "line":
        if role in ("length", "plain"):
            return round(v, PLACES)
        if role == "spacing":
            if n_objects < 2:
                raise InputError(f"{said}: a spacing needs at least two objects in the line")
            return round(v * (n_objects - 1), PLACES)
        raise InputError(f"{said}: a line's size is its length from end to end; say how long it is")
    if pattern == "rectangle":
        if role in ("side", "long_side", "plain", "length"):
            return round(v, PLACES)
        raise InputError(f"{said}: a rectangle's size is its longer side; say how long a side is")
    if pattern in _TOWERS:
        raise InputError(f"{said}: a stack has no size in numbers (its footprint is its base object's)")
    raise InputError(f"{said}: a {pattern} goal takes no size or distance in numbers")
