"""Object references in an instruction, found and resolved against a scene.

A *mention* is a noun phrase that selects scene objects::

    [determiner] [colour (, colour)* (and|or) colour] category [qualifier]*

where the determiner sets the quantity ("all", "the", "one", "three", "the
other", "another" ...), colours and categories come from the scene itself
(its ``color`` and ``name`` fields, with plurals and the synonym table
:data:`SYNONYMS`), and qualifiers narrow the selection ("except the red
one", "whose color is the same as the heart"). Ids are mentions too
("object 7", "objects 3, 4 and 5").

Resolution rules (documented in ``docs/language.md``):

* plural or "all"/"every"/"each": every match; none is an error;
* singular "the X" or a bare singular "X": exactly one match, otherwise the
  reference is ambiguous (refused, listing the matches) or empty;
* "a"/"an"/"one"/"any"/"another X": any one match, chosen later
  (:class:`Choice`), "another" excluding objects named earlier;
* a number k ("three blocks"): any k matches, chosen later;
* "the other X"/"the remaining X"/"the rest": matches not named earlier;
* colours match the scene's colour text exactly (case-insensitive): "red"
  does not select a "red swirl" object while some object is plain red;
  only when no object has the exact colour, the colour words given are
  matched as part of the object's colour ("the swirl flower" selects the
  red swirl flower; all given words must be in it).

The stage is cut by concern: :mod:`.vocabulary` (tokens, the scene's words, :class:`Mention` and
:class:`Choice`), :mod:`.mentions` (finding the mentions of a clause), :mod:`.qualifiers` (attribute
clauses after a noun) and :mod:`.resolve` (the ids a mention allows and the quantity it asks for). This
module is the stage's face: the rest of the parser imports its names from here.
"""

from __future__ import annotations

from .ir import Token
from .mentions import find_mentions
from .resolve import MEASURE_TOL, candidates, describe, select
from .vocabulary import COLOUR_WORDS, GENERIC, GROUPS, NUMBERS, SYNONYMS, Choice, Mention, Vocabulary, colour_words, tokenize

__all__ = [
    "COLOUR_WORDS",
    "GENERIC",
    "GROUPS",
    "MEASURE_TOL",
    "NUMBERS",
    "SYNONYMS",
    "Choice",
    "Mention",
    "Token",
    "Vocabulary",
    "candidates",
    "colour_words",
    "describe",
    "find_mentions",
    "select",
    "tokenize",
]
