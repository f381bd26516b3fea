"""The typed forms between a command's text and its goal dicts.

* :class:`Token`: one lower-cased word, number or punctuation mark with its
  span in the text it was read from (``text[start:end]``, before lower-casing).
  :func:`.grounding.tokenize` returns these.
* :class:`Measure`: a number with a length unit, in metres ("25 cm" -> 0.25).
* :class:`Ref`: a reference to objects that composes: a head noun, attributes
  (colours, attribute filters), a count, exclusions, a relation to another
  :class:`Ref` ("the mug on the tray"), and a superlative or ordinal over a
  geometric key ("the leftmost one", "the third cup from the left").
  :meth:`Ref.from_mention` reads one from a grounded :class:`.grounding.Mention`.
* :class:`Reading`: what one clause asks for (a pattern over target
  references, an anchor, the optional parameters said).

The parser reads the first two today (tokens at the tokeniser, measures in
the lexicon's units); :class:`Ref` and :class:`Reading` are the forms the
later stages move to.

>>> Measure.said(25, "cm").metres
0.25
>>> Token("red", 4, 7, "word").pos
4
"""

from __future__ import annotations

from dataclasses import dataclass, field
from collections.abc import Callable
from typing import TYPE_CHECKING, Literal, Protocol, TypeVar

from ..errors import InputError
from . import lexicon

if TYPE_CHECKING:
    from .grounding import Mention

__all__ = ["Det", "Key", "Measure", "Order", "Reading", "Ref", "Relation", "Token", "TokenKind"]

TokenKind = Literal["word", "number", "punct"]
#: How a reference chooses among its matches (see :class:`.grounding.Mention`).
Det = Literal["all", "the", "both", "one", "count", "other", "another", "ids", "pronoun"]
#: A geometric key a superlative or ordinal ranks objects by.
Key = Literal["x", "-x", "y", "-y", "distance", "height", "width", "volume"]


@dataclass(frozen=True)
class Token:
    """One token: ``text`` lower-cased, ``start``/``end`` its character span in the text it was read from."""

    text: str
    start: int
    end: int
    kind: TokenKind = "word"

    @property
    def pos(self) -> int:
        """Where the token starts (the name older code reads)."""
        return self.start

    @staticmethod
    def kind_of(text: str) -> TokenKind:
        """``number`` for a numeral, ``word`` for letters, else ``punct``."""
        if text[:1].isdigit() or (text[:1] == "-" and text[1:2].isdigit()):
            return "number"
        return "word" if text[:1].isalpha() else "punct"


@dataclass(frozen=True)
class Measure:
    """A length said with a number and a unit; ``metres`` is its value in metres."""

    value: float
    unit: str
    metres: float

    @classmethod
    def said(cls, value: float, unit: str) -> Measure:
        """The measure of ``value`` ``unit`` (a unit of :data:`.lexicon.UNITS`); an unknown unit raises InputError."""
        per = lexicon.UNITS.get(unit.lower())
        if per is None:
            raise InputError(f"'{value:g} {unit}': unknown unit of length (known: cm, mm, m, inches)")
        if value < 0:
            raise InputError(f"'{value:g} {unit}': a length cannot be negative")
        return cls(float(value), unit.lower(), round(float(value) * per, 9))


@dataclass(frozen=True)
class Order:
    """A superlative or an ordinal over ``key``: ``rank`` 1 is the first by that key ("the leftmost" is
    ``Order("x", 1)``, "the third cup from the left" ``Order("x", 3)``); ``count`` objects from there on."""

    key: Key
    rank: int = 1
    count: int = 1


@dataclass(frozen=True)
class Relation:
    """A reference's relation to another one: ``on`` / ``under`` / a relation pattern name, and the other ``Ref``."""

    kind: str
    other: Ref


@dataclass(frozen=True)
class Ref:
    """A reference to objects. ``head``: the category words (empty: any object); ``colours``: colour words
    it requires; ``det`` how it chooses; ``count`` how many; ``exclusions`` references taken out;
    ``relation`` a relation its objects hold; ``order`` a rank by a geometric key; ``span`` token indices."""

    text: str
    det: Det
    head: frozenset[str] = frozenset()
    colours: tuple[str, ...] = ()
    count: int | None = None
    ids: tuple[int, ...] = ()
    exclusions: tuple[Ref, ...] = ()
    relation: Relation | None = None
    order: Order | None = None
    span: tuple[int, int] = (0, 0)

    @classmethod
    def from_mention(cls, m: Mention) -> Ref:
        """The reference a grounded mention makes (its exclusions too)."""
        det: Det = m.det  # type: ignore[assignment]
        return cls(m.text, det, frozenset(m.names or ()), tuple(m.colors or ()), m.count, tuple(m.ids),
                   tuple(cls.from_mention(x) for x in m.excluding), None, None, (m.start, m.end))


@dataclass(frozen=True)
class Reading:
    """What one clause asks for: ``pattern`` over ``targets``, with an ``anchor`` for a relation, and the
    optional parameters said (``size``/``region``/``facing`` as in the goal format; ``measures`` said in numbers)."""

    kind: Literal["shape", "relation", "stack", "stack_step", "selection", "header", "remark", "leave"]
    pattern: str | None
    targets: tuple[Ref, ...] = ()
    anchor: Ref | None = None
    params: dict[str, str] = field(default_factory=dict)
    measures: tuple[Measure, ...] = ()
    clause: tuple[Token, ...] = ()


class _Span(Protocol):
    @property
    def end(self) -> int: ...


_P = TypeVar("_P", bound=_Span)


def scan(words: tuple[str, ...], at: Callable[[tuple[str, ...], int], _P | None]) -> list[_P]:
    """Every phrase that ``at`` reads in ``words``, left to right, none overlapping.

    ``at(words, i)`` reads the phrase that starts at token ``i`` (or ``None``);
    the scan goes on after the phrase's ``end``.
    """
    out: list[_P] = []
    i = 0
    while i < len(words):
        got = at(words, i)
        if got is None:
            i += 1
            continue
        out.append(got)
        i = got.end
    return out
