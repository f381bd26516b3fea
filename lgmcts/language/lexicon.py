"""The closed-class words of the offline parser, defined once in ``data/lexicon.toml``.

Colours, arrangement nouns, sizes, table places, facings, directions, count
words, length units, fillers, command verbs and stack-role words. The other
modules of the language package take their word sets from here, and the
rewrite table (:mod:`.normalise`) writes ``{HUE}`` or ``{SHAPE}`` in a pattern
instead of spelling the alternation out:

>>> import re; bool(re.fullmatch(MACROS["HUE"], "grey"))
True
>>> "ring" in SHAPE_NOUNS["circle"]
True
>>> UNITS["cm"]
0.01
"""

from __future__ import annotations

import re
import tomllib
from collections.abc import Iterator, Sequence
from pathlib import Path
from typing import Any

__all__ = [
    "COLOUR_WORDS",
    "COLS",
    "COMMAND_VERBS",
    "COMPASS",
    "DIRECTIONS",
    "ECHO_NEUTRAL",
    "FACE_VERBS",
    "FACINGS",
    "FILLER_WORDS",
    "FORMAL",
    "HESITATIONS",
    "HUES",
    "MACROS",
    "NUMBERS",
    "QUESTION_TAGS",
    "REGION_NOUNS",
    "REPAIR_MARKERS",
    "ROLE_WORDS",
    "ROWS",
    "SAME_WORD",
    "SHAPE_NOUNS",
    "SIDE_FACINGS",
    "SIZES",
    "STOPWORDS",
    "TABLE_WORDS",
    "UNITS",
    "VIEWER_WORDS",
    "alternation",
    "check_shape_nouns",
    "context_words",
    "phrase_spans",
    "says",
    "words",
]

FILE = Path(__file__).with_name("data") / "lexicon.toml"

with FILE.open("rb") as _f:
    _DATA: dict[str, Any] = tomllib.load(_f)

_C = _DATA["colours"]
#: Colour words read as an object's colour.
HUES: frozenset[str] = frozenset(_C["hues"])
#: Every colour, texture and material word (a reference with one the scene lacks names nothing).
COLOUR_WORDS: frozenset[str] = frozenset([*_C["hues"], *_C["more"], *_C["textures"]])
#: Pattern name -> the nouns that name it in the rewrite rules (each one of the pattern's keys).
SHAPE_NOUNS: dict[str, tuple[str, ...]] = {k: tuple(v) for k, v in _DATA["shapes"].items()}
#: Every arrangement noun, of any pattern ("line", "row", "ring", "stack" ...).
ARRANGEMENT_NOUNS: frozenset[str] = frozenset(w for nouns in SHAPE_NOUNS.values() for w in nouns)
#: Size word -> small / medium / large.
SIZES: dict[str, str] = {w: size for size, words in _DATA["sizes"].items() for w in words}
_R = _DATA["regions"]
#: Row word -> bottom / middle / top; column word -> left / center / right.
ROWS: dict[str, str] = dict(_R["rows"])
COLS: dict[str, str] = dict(_R["cols"])
REGION_NOUNS: frozenset[str] = frozenset(_R["nouns"])
TABLE_WORDS: frozenset[str] = frozenset(_R["table"])
VIEWER_WORDS: frozenset[str] = frozenset(_R["viewer"])
_F = _DATA["facing"]
#: Facing word -> north / east / south / west.
FACINGS: dict[str, str] = dict(_F["words"])
SIDE_FACINGS: dict[str, str] = dict(_F["sides"])
FACE_VERBS: frozenset[str] = frozenset(_F["verbs"])
#: Direction word -> a unit step (x right, y away from the viewer).
DIRECTIONS: dict[str, tuple[int, int]] = {k: (int(v[0]), int(v[1])) for k, v in _DATA["directions"].items()
                                          if isinstance(v, list)}
#: Compass word -> the side of the table it names.
COMPASS: dict[str, str] = dict(_DATA["directions"]["compass"])
#: Count word (or phrase) -> count.
NUMBERS: dict[str, int] = dict(_DATA["numbers"]["words"])
#: Length unit -> metres.
UNITS: dict[str, float] = {k: float(v) for k, v in _DATA["units"]["metres"].items()}
_W = _DATA["words"]
STOPWORDS: frozenset[str] = frozenset(_W["stopwords"])
#: Verbs and fillers that ask for a rearrangement without naming one (in order, as written).
FILLER_WORDS: tuple[str, ...] = tuple(_W["fillers"])
COMMAND_VERBS: frozenset[str] = frozenset(_W["commands"])
ROLE_WORDS: frozenset[str] = frozenset(_W["roles"])
_P = _DATA["repairs"]
#: Spoken repairs and echoes (:mod:`.repairs`): the marker phrases (as word tuples, longest first), the hesitations
#: around them, the words an echo may add, the question tags and the words an echo reads as another.
REPAIR_MARKERS: tuple[tuple[str, ...], ...] = tuple(sorted((tuple(p.split()) for p in _P["markers"]), key=len,
                                                           reverse=True))
HESITATIONS: frozenset[str] = frozenset(_P["hesitations"])
ECHO_NEUTRAL: frozenset[str] = frozenset(_P["echo_neutral"])
QUESTION_TAGS: tuple[tuple[str, ...], ...] = tuple(tuple(p.split()) for p in _P["tags"])
SAME_WORD: dict[str, str] = dict(_P["same"])
#: Words of a dialect with one reading each ("pit": put, "tae": to), read by the spelling stage (:mod:`.spelling`).
DIALECT: dict[str, str] = dict(_DATA["dialect"])
#: The colour of things of the world ("a banana": yellow), for a colour said by comparison (:mod:`.rewrite`).
WORLD_COLOURS: dict[str, str] = {k.replace("_", " "): v for k, v in _DATA["world_colours"].items()}
#: Verbs of a step that only picks objects out (:mod:`.steps`), as word tuples, longest first.
FINDING_VERBS: tuple[tuple[str, ...], ...] = tuple(sorted((tuple(p.split()) for p in _DATA["steps"]["selecting"]),
                                                          key=len, reverse=True))
#: Words that open a bracketed aside explaining what was said (:mod:`.asides`), as word tuples.
ASIDE_EXPLAINING: tuple[tuple[str, ...], ...] = tuple(tuple(p.split()) for p in _DATA["asides"]["explaining"])
_L = _DATA["formal"]
#: A specification's words (:mod:`.formal`): each list of ``[formal]`` as word tuples (longest first), and ``verbs``
#: as participle words -> the verb the parser reads.
FORMAL: dict[str, Any] = {
    **{name: tuple(sorted((tuple(p.split()) for p in ps), key=len, reverse=True))
       for name, ps in _L.items() if isinstance(ps, list)},
    "verbs": {tuple(k.split()): v for k, v in _L["verbs"].items()},
}
_WORD = re.compile(r"\w+")


def words(text: str) -> list[str]:
    """The lower-case words of ``text``, cut where a regular expression's ``\\b`` cuts ("it's" is "it", "s").

    >>> words("Stack them, then the cups! It's done")
    ['stack', 'them', 'then', 'the', 'cups', 'it', 's', 'done']
    """
    return _WORD.findall(text.lower())


#: Named cue lists (``[cues]``): each a tuple of phrases, a phrase a tuple of words as :func:`words` cuts them.
CUES: dict[str, tuple[tuple[str, ...], ...]] = {
    name: tuple(tuple(words(p)) for p in phrases) for name, phrases in _DATA["cues"].items()}


def context_words() -> dict[str, frozenset[str]]:
    """The word lists of ``[context]``: the subjects, asking words and place neighbours of a remark."""
    return {name: frozenset(ws) for name, ws in _DATA["context"].items()}


def says(text: str, *cues: str) -> bool:
    """Whether ``text`` has, as whole words, a phrase of any of the cue lists named (``[cues]`` of the lexicon).

    >>> says("so the kids can reach the top shelf", "goal")
    True
    >>> says("so the kids can reach it", "goal")
    False
    """
    return next(phrase_spans(words(text), *cues), None) is not None


def phrase_spans(tokens: Sequence[str], *cues: str) -> Iterator[tuple[int, int, str]]:
    """Where the phrases of the cue lists named stand in ``tokens`` (lower-case words, however the caller cut
    them): ``(start, end, cue list)`` for each occurrence, list by list, phrase by phrase, left to right.

    >>> list(phrase_spans(["the", "cans", "upside", "down"], "tilt"))
    [(2, 4, 'tilt')]
    """
    for name in cues:
        for phrase in CUES[name]:
            n = len(phrase)
            for i in range(len(tokens) - n + 1):
                if tuple(tokens[i : i + n]) == phrase:
                    yield i, i + n, name


def alternation(words: tuple[str, ...] | list[str] | frozenset[str]) -> str:
    """A non-capturing regex group matching any of ``words`` (longest first, so no word shadows a longer one)."""
    ordered = sorted(words, key=lambda w: (-len(w), w)) if isinstance(words, frozenset) else \
        sorted(words, key=lambda w: -len(w))  # stable: the file's order among words of one length
    return "(?:" + "|".join(re.escape(w) for w in ordered) + ")"


#: Regex macros for the rewrite table: ``{HUE}`` any colour of :data:`HUES`, ``{SHAPE}`` any arrangement noun,
#: ``{CIRCLE}`` ... one pattern's nouns.
MACROS: dict[str, str] = {
    "HUE": alternation(_C["hues"]),
    "SHAPE": alternation([w for nouns in SHAPE_NOUNS.values() for w in nouns]),
    # One pattern's nouns: {CIRCLE}, {RECTANGLE}, {LINE}, {TOWER}.
    **{name.upper(): alternation(nouns) for name, nouns in SHAPE_NOUNS.items()},
}


def check_shape_nouns() -> list[str]:
    """Problems with :data:`SHAPE_NOUNS` against the pattern registry (empty when every noun is a key of its pattern)."""
    from ..patterns import registry

    reg = registry()
    out: list[str] = []
    for name, nouns in SHAPE_NOUNS.items():
        if name not in reg:
            out.append(f"no pattern '{name}' is registered")
            continue
        keys = {w for k in reg[name].keys for w in k.lower().split()}
        out += [f"'{n}' is not a word of the keys of '{name}'" for n in nouns if n not in keys]
    return out
