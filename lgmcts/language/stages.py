"""Where the reading stages meet the offline parser.

Each stage is a pure module with its own tests (:mod:`.spelling`,
:mod:`.measures`, :mod:`.positions`, :mod:`.places`, :mod:`.context`); this
module builds what each needs from the scene and the parser's word lists and
is called from a few points of :mod:`.rules`:

* before anything else reads the text: :func:`spell` (misspellings),
  :func:`mark_measures` (each quantity with a unit becomes one marker word,
  so that the clause it belongs to carries it to the parameter reader) and
  :func:`said_facings` (a facing said by an edge or the viewer becomes its
  compass direction), :func:`said_places` (places later steps would cut,
  said plainly);
* on the text, before grounding: :func:`by_position` (objects picked by where
  they stand become "object N");
* on the tokens, before clauses are cut: :func:`without_context`;
* when a goal is written: :func:`measured_size` (the marker's measure as the
  goal's ``size``, or a refusal that quotes it).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Collection, Iterable, Mapping, Sequence
from typing import TYPE_CHECKING, Any

from ..errors import InputError
from .colour_refs import find_colour_refs, find_matched_pairs, select
from .context import drop_context
from .grounding import COLOUR_WORDS, Token, tokenize
from .measures import APPROXIMATE, Measure, find_measures, size_for
from . import lexicon
from .lexicon import TABLE_WORDS
from .places import POINTING_PARTS, read_facing, side_anchor
from .positions import find_position_refs, pick
from .spelling import Corrector

if TYPE_CHECKING:
    from .grounding import Vocabulary

__all__ = ["MARK", "by_colour", "by_position", "is_mark", "mark_measures", "measured_size", "letters_named", "named_before", "other_side", "partitive", "pronoun_facings", "said_facings", "said_places", "same_again", "spell", "spelled", "unmark", "without_context"]

#: Marker words standing for the measures of a command ("sizemarka", "sizemarkb" ...).
MARK = "sizemark"


def is_mark(word: str) -> bool:
    """Whether a token is a measure's marker."""
    return len(word) == len(MARK) + 1 and word.startswith(MARK) and "a" <= word[-1] <= "z"


def _plural(word: str) -> str:
    if word.endswith(("s", "x", "z", "ch", "sh")):
        return word + "es"
    if word.endswith("y") and len(word) > 1 and word[-2] not in "aeiou":
        return word[:-1] + "ies"
    if word.endswith("fe"):
        return word[:-2] + "ves"
    return word + "s"


def spell(text: str, vocab: Vocabulary, lexicon: Iterable[str], nouns: Iterable[str], protect: Iterable[str],
          read: Iterable[str] = (), slips: bool = False) -> str:
    """``text`` with misspellings corrected against the scene's words and the parser's words (.spelling)."""
    scene: set[str] = set()
    for key in vocab.categories:
        scene.update(key)
        scene.add(_plural(key[-1]))
    scene.update(vocab.color_words)
    return Corrector(scene, set(lexicon), set(nouns), protect=set(protect),
                     colours=set(vocab.color_words) | COLOUR_WORDS, read=set(read), slips=slips).text(text)


#: Words that may stand between a measure and the same measure said again ("30 cm across, i mean thirty
#: centimetres", "half a metre long, um, fifty centimetres").
_RESTATING = frozenset({"i", "mean", "yeah", "yes", "so", "or", "like", "that's", "thats", "is", "that", "about",
                        "roughly", "exactly", "say", "call", "it", "um", "umm", "uh", "er", "erm", "hmm", "well", "oh",
                        "ok", "okay", "ah"})


def _restated(text: str, before: Measure, m: Measure) -> bool:
    """Whether ``m`` says ``before`` again right after it ("half a metre long, fifty centimetres"): the same
    quantity to the millimetre, of the same role (or none said), only fillers between; or said again in other units, hedged, in
    brackets or after "i.e.", within 3 % ("8 inches long -- approximately 20 cm", "15 centimetres (6 inches)",
    "20 cm by 10 cm, i.e. the longer side 20 cm")."""
    between = text[before.end : m.start]
    restating = lexicon.says(between, "that_is")
    # the same quantity to the millimetre it is said to ("a foot across -- call it 30.5 cm": 0.3048 and 0.305)
    same = abs(m.metres - before.metres) < 5e-4 or (
        (any(w in APPROXIMATE for w in lexicon.words(m.text)) or "(" in between or restating)
        and abs(m.metres - before.metres) <= 0.03 * before.metres)
    return (same and (m.role == before.role or "plain" in (m.role, before.role))
            and (restating or all(w in _RESTATING for w in lexicon.words(between))))



def unmark(message: str, measures: list[Measure]) -> str:
    """``message`` with each measure marker ("sizemarka") said as the words it stands for ("30 cm long")."""
    for k, m in enumerate(measures[:26]):
        message = message.replace(f"{MARK}{chr(97 + k)}", m.text)
    return message


def mark_measures(text: str) -> tuple[str, list[Measure]]:
    """``text`` with each measure replaced by a marker word, and the measures in order. A measure said again
    right after itself is one measure (its repeat is left out)."""
    out: list[str] = []
    at = 0
    kept: list[Measure] = []
    for m in find_measures(text):
        out.append(text[at : m.start])
        at = m.end
        if kept and _restated(text, kept[-1], m):
            continue
        if len(kept) < 26:
            out.append(f"{MARK}{chr(97 + len(kept))}")
        kept.append(m)
    out.append(text[at:])
    return "".join(out), kept[:26]


_EDGE_WORDS = frozenset({"edge", "side", "wall", "end", "border", "rim", "back", "front"})


#: Words before the verb "face" that make it a facing of objects named before ("turn them to face me",
#: "so they face the viewer").
_BEFORE_FACE = frozenset({"to", "they", "it", "all", "both", "each", "so", "will", "should", "must", "them"})


#: Words of a clause that only turns the objects just arranged ("..., but turn them to face the back wall",
#: "..., they should all point left"): joining words, verbs of turning, pronouns and modals.
_BE_WORDS = frozenset({"are", "is", "'re", "they're", "it's", "'s", "be", "all"})
_TURNING = frozenset({"but", "and", "then", "so", "also", "turn", "make", "have", "get", "set", "rotate", "spin",
                      "should", "must", "will", "all", "both", "each", "need", "needs", "to", "please", "just",
                      "with", "and", "can", "could", "you"})
_PRONOUNS = frozenset({"them", "they", "it", "those", "these", "they're", "it's"})
_COMPASS_WORDS = frozenset({"north", "east", "south", "west"})
#: Words of a facing said by the viewer ("pointing toward me", "facing away from us").
_AT_VIEWER = frozenset({"toward", "towards", "at", "to", "away", "from", "the"}) | lexicon.VIEWER_WORDS


def pronoun_facings(text: str) -> str:
    """``text`` with a last clause that only turns the objects of the clause before by a pronoun
    (", but turn them facing north", ", they facing west", once :func:`said_facings` has said the facing
    by its compass point) said as that clause's facing (", facing north")."""
    toks = tokenize(text)
    words = tuple(t.text for t in toks)
    for k, w in enumerate(words):
        if w != "," and not (w == "so" and words[k + 1 : k + 2] and words[k + 1] in _PRONOUNS):
            continue  # ", but turn them ...", "so they're all pointing toward me"
        j = k + 1
        said: set[str] = set()
        while j < len(words) and (words[j] in _TURNING or words[j] in _PRONOUNS or words[j] in _BE_WORDS):
            said.add(words[j])
            j += 1
        if (said & _PRONOUNS and words[j : j + 2] in (("facing", ","), ("pointing", ","))
                and "facing" in words[j + 2 : j + 6]):
            return text[: toks[k].pos].rstrip() + text[toks[j + 1].pos :]  # "so it's pointing, like, facing north"
        end = next((e for e in range(j, len(words)) if words[e] in (".", "!", ";")), len(words))
        said_how = words[j + 1 : end]
        if (said & _PRONOUNS and words[j : j + 1] in (("facing",), ("pointing",)) and said_how
                and ((len(said_how) == 1 and said_how[0] in _COMPASS_WORDS) or (
                    all(w in _AT_VIEWER for w in said_how) and any(w in lexicon.VIEWER_WORDS for w in said_how)))):
            return text[: toks[k + 1].pos] + text[toks[j].pos :] if w == "," else \
                text[: toks[k].pos].rstrip() + ", " + text[toks[j].pos :]
    return text


def said_facings(text: str) -> str:
    """``text`` with each facing said by an edge or the viewer ("tines toward the right edge",
    "turned to face the viewer") said by its compass direction ("facing east"), so that no
    edge is grounded as an object and every goal kind reads it the same way."""
    toks = tokenize(text)
    words = tuple(t.text for t in toks)
    out: list[str] = []
    at = 0
    i = 0
    while i < len(words):
        got = read_facing(words, i)
        if got is None or not (words[i] in POINTING_PARTS or any(w in _EDGE_WORDS for w in words[i : got[1]])
                               or words[got[1] - 2 : got[1]] in (("the", "left"), ("the", "right"))
                               or (words[i] in ("face", "faces", "point", "points")
                                   and (not i or words[i - 1] in _BEFORE_FACE | {",", "and"}))):
            i += 1  # facing the viewer or away: read where it stands by the parameter reader
            continue
        start = i
        if words[i] in ("face", "faces"):
            # "turn them to face me", "rotate them so (that) they face me": the whole purpose is the facing
            for lead in (("so", "that", "they"), ("so", "that", "it"), ("so", "they"), ("so", "it"), ("to",)):
                if words[max(0, i - len(lead)) : i] == lead:
                    start = i - len(lead)
                    break
        lo, hi = toks[start].pos, _end(text, toks[got[1] - 1])
        out.append(text[at:lo] + "facing " + got[0])
        at = hi
        i = got[1]
    out.append(text[at:])
    return "".join(out)


_PARTWAY = frozenset({"partway", "halfway", "midway"})
#: Column words and the mark of their whole column ("the centre column", "the left-hand column").
_COLUMN_MARKS = {"centre": "centreband", "center": "centreband", "middle": "centreband", "central": "centreband",
                 "left": "leftband", "right": "rightband"}
_SIDE_CELLS = {"left": "middleleft", "right": "middleright", "front": "bottomcenter", "near": "bottomcenter",
               "back": "topcenter", "far": "topcenter", "rear": "topcenter"}


def said_places(text: str) -> str:
    """``text`` with the free places that later steps would cut or widen marked for the place
    reader (:func:`.places.read_place`): "centred left to right" is the center column, "centred
    front to back" the middle row, and "halfway back" (also "partway", "midway"; "up", "along",
    "down") the middle row, which a side said with it narrows to its cell ("halfway back on
    the right": middle right)."""
    toks = tokenize(text)
    words = tuple(t.text for t in toks)
    out: list[str] = []
    at = 0
    i = 0
    while i < len(words):
        w = words[i]
        end, say = i, ""
        if w in ("centred", "centered", "centrally") and words[i + 1 : i + 4] in (
                ("left", "to", "right"), ("right", "to", "left")):
            end, say = i + 4, "in centreband"
        elif w in ("centred", "centered", "centrally") and words[i + 1 : i + 4] in (
                ("front", "to", "back"), ("back", "to", "front")):
            end, say = i + 4, "in middleband"
        elif (w in _PARTWAY or (w in ("part", "half") and words[i + 1 : i + 2] == ("way",))):
            k = i + 1 + (w in ("part", "half"))
            if words[k : k + 1] in (("back",), ("up",), ("along",), ("down",), ("across",)):
                end, say = k + 1, "in middleband"
                if words[end : end + 1] == ("the",) and words[end + 1 : end + 2] and words[end + 1] in TABLE_WORDS:
                    end += 2
        elif w in _COLUMN_MARKS and (words[i + 1 : i + 2] == ("column",) or words[i + 1 : i + 3] == ("hand", "column")):
            # "the centre column", "down the right-hand column of the workspace": the whole column, never its
            # middle cell and never a line (the rewrite that makes any other "column" a line comes later)
            end = i + 2 + (words[i + 1] == "hand")
            if words[end : end + 2] == ("of", "the") and words[end + 2 : end + 3] and words[end + 2] in TABLE_WORDS:
                end += 3
            if i and words[i - 1] == "the":
                i -= 1
                say = f"the {_COLUMN_MARKS[w]}"
            else:
                say = f"in the {_COLUMN_MARKS[w]}"
        elif w in ("centre", "center", "middle") and words[i + 1 : i + 2] == ("of",) and (
                (i and words[i - 1] == "the") or not i or words[i - 1] in (",", ";", ":", "-")):
            # "the centre of the left side", "the middle of the front edge": the cell halfway along that side
            # (said bare after a comma too: "..., middle of the right side of frame")
            k = i + 2 + (words[i + 2 : i + 3] == ("the",))
            k += words[k : k + 1] == ("table's",)
            side = words[k] if k < len(words) else ""
            hand = words[k + 1 : k + 2] == ("hand",)
            noun = words[k + 1 + hand : k + 2 + hand] in (("side",), ("edge",), ("end",), ("half",), ("wall",))
            # "in the middle of the back" said with no noun: the clause ends there or the table is named
            bare = not hand and (words[k + 1 : k + 2] in ((), (",",), (".",), (";",), ("!",), ("and",)) or bool(
                words[k + 1 : k + 3] == ("of", "the") and words[k + 3 : k + 4] and words[k + 3] in TABLE_WORDS))
            if side in _SIDE_CELLS and (noun or bare):
                end = k + 1 + hand + noun
                if words[end : end + 2] == ("of", "the") and words[end + 2 : end + 3] and words[end + 2] in TABLE_WORDS:
                    end += 3
                i -= words[i - 1] == "the"  # the article goes too
                if i >= 2 and words[i - 1] == "in" and words[i - 2] in ("right", "smack", "dead", "bang", "slap"):
                    i -= 2  # "right in the middle of the back edge": the intensifier and "in" too
                say = f"in the {_SIDE_CELLS[side]}cell"
        if end == i:
            i += 1
            continue
        out.append(text[at : toks[i].pos] + say)
        at = _end(text, toks[end - 1])
        i = end
    out.append(text[at:])
    return "".join(out)


_OPPOSITE = {"left": "to the right of", "right": "to the left of", "front": "behind", "behind": "in front of",
             "back": "in front of"}


def other_side(text: str) -> str:
    """"the fork left of the plate, the knife on its other side": the side opposite the one said
    last before it, of the same reference object ("the knife to the right of it"; "on the plate's
    other side", "on the other side of the plate"). Left as said where no side came before."""
    toks = tokenize(text)
    words = tuple(t.text for t in toks)
    out: list[str] = []
    at = 0
    for k in range(1, len(words) - 1):
        if words[k] not in ("other", "opposite") or words[k + 1] != "side":
            continue
        lo = k - 1
        owner = "it"
        if words[lo] in ("its", "their"):
            owner = "it" if words[lo] == "its" else "them"
        elif words[lo].endswith("'s"):
            j = lo
            while j > 0 and words[j - 1] not in ("on", "to", "at", ",", "goes", "go", "is", "be", "sits"):
                j -= 1
            owner = text[toks[j].pos : toks[lo].pos] + words[lo][:-2]
            lo = j
        elif words[lo] == "the":
            owner = "" if words[k + 2 : k + 3] == ("of",) else "it"  # "on the other side": of the same object
        elif words[lo] in ("on", "to", "at"):
            owner, lo = "it", lo + 1  # "orange block on other side", said without an article
        else:
            continue
        if lo > 0 and words[lo - 1] in ("on", "to", "at"):
            lo -= 1
        hi = k + 2
        if not owner:
            if words[hi : hi + 1] != ("of",):
                continue
            j = hi + 1
            while j < len(words) and words[j] not in (",", ".", ";", "!", "?", "and"):
                j += 1
            owner = text[toks[hi + 1].pos : _end(text, toks[j - 1])]
            hi = j
        said = [n for n, w in enumerate(words[:lo]) if w in _OPPOSITE]
        if not said or lo < at:
            continue
        ref = side_anchor(words, said[-1]) if owner == "it" and any(  # "right of the bowl. ... its other side"
            w in (".", "!", "?") for w in words[said[-1] : lo]) else None
        owner = text[toks[ref[0]].pos : _end(text, toks[ref[1] - 1])] if ref else owner
        out.append(text[at : toks[lo].pos] + f"{_OPPOSITE[words[said[-1]]]} {owner}")
        at = _end(text, toks[hi - 1])
    out.append(text[at:])
    return "".join(out)


def measured_size(pattern: str, params: dict, measures: list[Measure], n_objects: int, anchored: bool) -> dict:
    """``params`` with a measure's marker (``params["measure"]``) turned into the goal's size."""
    if "measure" not in params:
        return params
    out = dict(params)
    m = measures[out.pop("measure")]
    if anchored:
        raise InputError(f"'{m.text}': a relation takes no size or distance in numbers")
    size = size_for(pattern, m, n_objects)
    if isinstance(out.get("size"), (int, float)) and out["size"] != size:
        raise InputError(f"'{m.text}': two different sizes for one arrangement ({out['size']}, {size})")
    # A size word said with a number ("a little rectangle, 18 cm each side") describes it loosely: the number holds.
    out["size"] = size
    return out


#: Sides said with "-most" after a hyphen ("front-most", "right - most"), which read as one word.
_HYPHEN_MOST = tuple((f"{side}{dash}most", f"{side}most") for w in ("left", "right", "front", "back", "rear", "hind")
                     for side in (w, w.capitalize(), w.upper()) for dash in ("-", " - ", " -", "- "))


def by_position(text: str, find: Callable[[tuple[str, ...]], list], ids_of: Callable[[Any], list[int]],
                pose_of: Callable[[int], tuple[float, float] | None], centre: tuple[float, float],
                nouns: frozenset[str] = frozenset(),
                borrowed: Mapping[tuple[str, ...], str] | None = None, group: Sequence[int] = ()) -> str:
    """``text`` with each phrase that picks objects by where they stand replaced by their ids.

    ``find(words)`` grounds a noun phrase (the parser's mention finder); ``ids_of(mention)``
    gives every object it may name; ``pose_of(id)`` the object's table position (None for
    an object standing on another); ``nouns``: the scene's category words, for "the one" after a
    noun ("every can except the one nearest the phone"). A phrase whose head or reference object names nothing
    is left as it is for the parser to refuse; an unclear answer is refused here.

    ``borrowed``: head forms that name a scene kind only through the synonym table, with the
    name they stand for ("cup" -> "mug" in a scene of mugs and no cup). As in the grounding, such
    a head may name the one object of that kind; a position phrase never chooses among several
    of them ("the cup nearest the phone" among two mugs is refused, as "the cup" is)."""
    for said, word in _HYPHEN_MOST:  # "front-most", "right - most": one word
        text = text.replace(said, word)
    toks: tuple[Token, ...] = tokenize(text)
    words = tuple(t.text for t in toks)
    refs = find_position_refs(words)
    if not refs:
        return text
    said_heads: list[tuple[str, ...]] = []
    picked: list[int] = list(group)  # "of the two green things, ... the one farther from me": of those two
    out: list[str] = []
    at = 0
    for ref in refs:
        head = ref.head
        if head in (("one",), ("ones",)) and ref.of is not None and ref.of == len(picked):
            # "the two leftmost cans in a stack, the one nearer the front at the bottom": of those two
            cands_of = {i: xy for i in picked if (xy := pose_of(i)) is not None}
            lo, hi = toks[ref.start].pos, _end(text, toks[ref.end - 1])
            got = pick(ref, cands_of, anchor_xy=None, centre=centre, said=text[lo:hi])
            out.append(text[at:lo] + _said_ids(got))
            at = hi
            continue
        if head in (("one",), ("ones",)):
            before = [w for w in words[: ref.start] if w in nouns or (w.endswith("s") and w[:-1] in nouns)]
            head = said_heads[-1] if said_heads else (before[-1],) if before else ()
        elif head:
            said_heads.append(head)
        while head[:1] in (("piece",), ("pieces",), ("item",), ("items",), ("bit",), ("bits",)) and head[1:2] == ("of",):
            head = head[2:]  # "the leftmost piece of silverware"
        ids = _ids(("the",) + head if head else ("everything",), find, ids_of)
        if ids is None or (ref.side_said and ref.count >= len(ids)):
            continue  # names nothing (left for the parser to refuse), or all of them: a place ("the two mugs on the left")
        single = len(ids) == 1 and ref.count == 1 and ref.of is None
        if single and ref.key.anchor is None and ref.rank in (0, -1) and "from" not in words[ref.start : ref.end]:
            continue  # one object already: "the side of the white bowl nearest me" (not "the first bowl from ...")
        # One object and a reference object ("the mug nearest the kettle" with one mug): the phrase is that
        # object; its reference object is no object of the goal.
        lent = next(((head[k:], borrowed[head[k:]]) for k in range(len(head)) if borrowed and head[k:] in borrowed), None)
        if lent is not None and not single:
            said = text[toks[ref.start].pos:_end(text, toks[ref.end - 1])]
            raise InputError(f"'{said}': the scene has no {' '.join(lent[0])}, and a position does not choose "
                             f"among objects named otherwise ({lent[1]}); say which {lent[1]} (e.g. by colour or id)")
        anchor_xy = None
        if ref.key.anchor is not None:
            aid = _ids(ref.key.anchor, find, ids_of)
            if aid is None or len(aid) != 1:
                continue
            anchor_xy = pose_of(aid[0])
            ids = [i for i in ids if i != aid[0]]
        cands = {i: xy for i in ids if (xy := pose_of(i)) is not None}
        lo, hi = toks[ref.start].pos, _end(text, toks[ref.end - 1])
        said = text[lo:hi]
        got = pick(ref, cands, anchor_xy=anchor_xy, centre=centre, said=said)
        picked = list(got)
        out.append(text[at:lo])
        out.append(_said_ids(got))
        at = hi
    out.append(text[at:])
    return "".join(out)


def _said_ids(ids: Sequence[int]) -> str:
    """Objects picked by a stage, said by id for the parser: "object 3", "objects 1, 4 and 5"."""
    if len(ids) == 1:
        return f"object {ids[0]}"
    return "objects " + ", ".join(str(i) for i in ids[:-1]) + f" and {ids[-1]}"


def _end(text: str, tok: Token) -> int:
    """The character end of a token in ``text`` (tokens are lower-cased copies of the text)."""
    low = text.lower()
    k = low.find(tok.text, tok.pos)
    return (k if k >= 0 else tok.pos) + len(tok.text)


def _ids(words: tuple[str, ...], find: Callable[[tuple[str, ...]], list], ids_of: Callable[[Any], list[int]],
         several: bool = False) -> list[int] | None:
    """Every object the one reference ``words`` may name (with ``several``, the references of a list joined by
    "and": "the letter A and the letter E"); None where they name nothing or are no such reference."""
    try:
        found = [m for m in find(words) if getattr(m, "det", None) != "pronoun"]
    except InputError:
        return None
    if several and len(found) > 1 and found[0].start == 0 and found[-1].end == len(words) and all(
            words[a.end : b.start] in (("and",), ("or",), (",",)) for a, b in zip(found, found[1:])):
        return [i for m in found for i in ids_of(m)]
    if len(found) != 1:
        return None
    return list(ids_of(found[0]))


def letters_named(text: str, letters: Collection[str]) -> str:
    """``text`` with "the letters A and T" ("letters R, T, E") said as each letter ("the letter A and the letter T"),
    so that the plural does not take every letter of the scene. Only capitals the scene has as letters."""
    toks = tokenize(text)
    out: list[str] = []
    at = 0
    for k, t in enumerate(toks):
        if t.text not in ("letters", "leters", "lettres") or k + 1 >= len(toks):
            continue
        named: list[int] = []
        j = k + 1
        while j < len(toks):
            raw = text[toks[j].pos : toks[j].pos + len(toks[j].text)]
            if len(raw) == 1 and raw.isupper() and raw in letters:
                named.append(j)
            elif toks[j].text not in (",", "and", "&"):
                break
            j += 1
        if len(named) < 2 or toks[named[-1]].text in (",", "and"):
            continue
        said = [f"letter {text[toks[i].pos]}" for i in named]
        joined = ", ".join(said[:-1]) + f" and {said[-1]}"
        out.append(text[at : t.pos] + joined)
        at = _end(text, toks[named[-1]])
    out.append(text[at:])
    return "".join(out)


_COUNT_WORDS = {"two": 2, "three": 3, "four": 4, "five": 5, "both": 2}


def partitive(text: str, find: Callable[[tuple[str, ...]], list], ids_of: Callable[[Any], list[int]]
              ) -> tuple[str, list[int]]:
    """A group said first and apart ("of the two green things, put the cup on the plate and the other one ...",
    "out of the three bowls, ..."): the text without it and the group's objects, which "the other one" and
    "the one farther from me" then choose among. Left as said (and no group) where the phrase names a
    different number of objects than it says."""
    toks = tokenize(text)
    words = tuple(t.text for t in toks)
    i = 0
    while i < len(words) and words[i] in ("ok", "okay", "so", "now", "right", "well", ","):
        i += 1
    i += words[i : i + 2] == ("out", "of")
    ends: tuple[str, ...] = (",",)
    if words[i : i + 2] in (("there", "is"), ("there", "are"), ("there", "'s")) and i + 3 < len(words):
        # "there are two bowls; the white one ...", "there is two mugs. red one ... the other one ..."
        ends, lead = (",", ".", ";", ":"), i + 2
    elif i + 1 < len(words) and (words[i] in _COUNT_WORDS or (words[i] == "the" and words[i + 1] in _COUNT_WORDS)):
        ends, lead = (".", ";", ":"), i  # "Two mugs. The one closer to me goes ...": a group said as a sentence
    elif i + 2 < len(words) and words[i] in ("from", "among") and (words[i + 1] in _COUNT_WORDS or (
            words[i + 1] == "the" and words[i + 2] in _COUNT_WORDS)):
        lead = i + 1  # "From two bottles, the one farther from me ..." (not "from the bottom up: ...")
    elif words[i : i + 1] != ("of",) or i + 1 >= len(words):
        return _listed_group(text, toks, i, find, ids_of)
    else:
        lead = i + 1
    j = lead + (words[lead] in ("the", "these"))
    if j == lead and words[j] not in _COUNT_WORDS:
        return text, []  # "of two green things" (said without an article) is one too
    comma = next((k for k in range(j, min(len(words), i + 8)) if words[k] in ends), None)
    if comma is None or comma + 1 >= len(words):
        return text, []
    count = _COUNT_WORDS.get(words[j])
    said = ("the",) + tuple(w for w in words[j + (count is not None) : comma])
    ids = _ids(said, find, ids_of)
    if not ids or (count is not None and len(ids) != count):
        return text, []
    rest = text[_end(text, toks[comma]) :]
    noun = words[comma - 1]
    one = noun[:-1] if noun.endswith("s") and _ids(("the", noun[:-1]), find, ids_of) else noun
    if ends != (",",):
        # "there are two bowls; ...", "Two mugs. The one closer to me ...": the group said as a sentence of its
        # own is taken out where something after it picks among it ("the other one", "red one", "the one ...");
        # otherwise the sentence stays, for the stages after to read as before
        after = words[comma + 1 :]
        if not _reads_whole(said, find) or not ("other" in after or any(
                a == "the" and b == "one" and c != "of" for a, b, c in zip(after, after[1:], after[2:] + ("",)))):
            return text, []
        return _one_of(rest.lstrip(), one, ids, find, ids_of), ids
    return text[: toks[i - (words[i - 1 : i] == ("out",))].pos if i else 0] + _one_of(rest, one, ids, find,
                                                                                     ids_of), ids


#: Words after which a clause starts ("... two mugs. red one put left of the plate").
_CLAUSE_EDGE = frozenset({".", ",", ";", ":", "and", "then", "!"})


_ORDINAL_ONES = {"first": 0, "second": 1, "third": 2, "last": -1}


def _listed_group(text: str, toks: Sequence[Token], i: int, find: Callable[[tuple[str, ...]], list],
                  ids_of: Callable[[Any], list[int]]) -> tuple[str, list[int]]:
    """A list said first, before a colon ("red can and blue can: the first one ..., the other one ..."): the text
    after the colon with "the first one" (the second, the last) said as that object of the list, and the list's
    objects as the group "the other one" chooses among. Left as said where nothing after it picks among them."""
    words = tuple(t.text for t in toks)
    colon = next((k for k in range(i + 1, min(len(words), i + 10)) if words[k] == ":"), None)
    if colon is None or colon + 2 >= len(words):
        return text, []
    said = words[i:colon]
    ids = _ids(said if said[0] == "the" else ("the",) + said, find, ids_of, several=True)
    after = words[colon + 1 :]
    picks = [(a, c) for a, b, c in zip(after, after[1:], after[2:]) if a == "the" and c == "one"
             and (b == "other" or b in _ORDINAL_ONES)]
    if not ids or len(ids) < 2 or len(set(ids)) != len(ids) or not picks:
        return text, []  # "the yellow block and the red one: stack one on the other" keeps its list
    out, at = [], _end(text, toks[colon])
    for k in range(colon + 1, len(toks) - 2):
        pick = _ORDINAL_ONES.get(words[k + 1])
        if words[k] == "the" and words[k + 2] == "one" and pick is not None and pick < len(ids):
            out.append(text[at : toks[k].pos] + _said_ids([ids[pick]]))
            at = _end(text, toks[k + 2])
    return ("".join(out) + text[at:]).lstrip(), ids


def _one_of(text: str, noun: str, group: Sequence[int], find: Callable[[tuple[str, ...]], list],
            ids_of: Callable[[Any], list[int]]) -> str:
    """``text`` with "the blue one" said of a group taken out before it ("of the two bottles, put the blue one
    ...") said with the group's noun ("the blue bottle"), where that names one object of the group."""
    toks = tokenize(text)
    out: list[str] = []
    at = 0
    for k, t in enumerate(toks):
        if t.text != "one" or k < 1 or not toks[k - 1].text.isalpha() or (
                k >= 2 and toks[k - 2].text != "the" and toks[k - 2].text not in _CLAUSE_EDGE) or (
                k == 1 and toks[0].text == "the"):
            continue  # "the blue one", or "red one" said without the article at the start of a clause
        if toks[k - 1].text in ("other", "same"):
            continue
        got = _ids(("the", toks[k - 1].text, noun), find, ids_of)
        if got is not None and len(got) == 1 and got[0] in group:
            out.append(text[at : t.pos] + noun)
            at = _end(text, t)
            continue
        kind = [i for i in _ids(("the", toks[k - 1].text), find, ids_of) or () if i in group]
        if len(kind) == 1 and k >= 2 and toks[k - 2].text == "the":
            # "there are two blue pieces. put the letter one ...": the one letter of the group
            out.append(text[at : toks[k - 2].pos] + _said_ids(kind))
            at = _end(text, t)
    out.append(text[at:])
    return "".join(out)


_CONTRASTED = frozenset({"than", "not", "instead", "never"})
#: Words after "the bowl" that leave it a whole reference (a place or a side follows, or the clause ends).
_AFTER_BARE = frozenset({".", ",", ";", "!", "?", "and", "then", "please", ":"})
#: Words before "the bowl" that make it the object of a relation ("front left of the bowl", "on the bowl").
_BEFORE_BARE = frozenset({"of", "on", "onto", "behind", "under", "beside", "near", "by", "to", "from", "with",
                          "above", "below", "beneath", "atop"})


def _longer_mention(words: tuple[str, ...], find: Callable[[tuple[str, ...]], list]) -> bool:
    """Whether the grounding reads ``words`` ("the green and blue stripe block") as one reference longer than
    its first two words."""
    try:
        found = find(words)
    except InputError:
        return False
    return bool(found) and found[0].start == 0 and found[0].end > 2


def _one_named(words: tuple[str, ...], kind: list[int], find: Callable[[tuple[str, ...]], list],
               ids_of: Callable[[Any], list[int]], single: bool = False) -> int | None:
    """The one object of ``kind`` that the references of ``words`` name (with ``single``, counting only
    references to one object each), or None where they name none or several."""
    try:
        before = [m for m in find(words) if getattr(m, "det", None) != "pronoun"]
    except InputError:
        return None
    named = {i for m in before if set(ids := list(ids_of(m))) <= set(kind) and (not single or len(ids) == 1)
             for i in ids}
    return named.pop() if len(named) == 1 else None


def named_before(text: str, find: Callable[[tuple[str, ...]], list], ids_of: Callable[[Any], list[int]]) -> str:
    """``text`` with "the bowl" (a kind the scene has several of, said bare as the object of a relation or at
    the end of its clause) replaced by the one object of that kind the command named before it ("the can
    closest to the white bowl: put it front left of the bowl": the white bowl). Left as said where no
    object or two objects of that kind were named before."""
    toks = tokenize(text)
    words = tuple(t.text for t in toks)
    out: list[str] = []
    at = 0
    for k in range(2, len(words)):
        if words[k - 1] != "the" or words[k - 2] not in _BEFORE_BARE or (
                k + 1 < len(words) and words[k + 1] not in _AFTER_BARE) or _CONTRASTED & set(words[max(0, k - 4) : k - 2]):
            continue  # "..., rather than on the bowl": the words that contrast read it as said
        if words[k] in COLOUR_WORDS and _longer_mention(words[k - 1 : k + 6], find):
            continue  # "of the green and blue stripe block": a colour of a longer name, not a kind
        kind = _ids(("every", words[k]), find, ids_of)
        if not kind or len(kind) < 2 or words[k].endswith("s"):
            continue
        named = _one_named(words[: k - 1], kind, find, ids_of, single=True)
        if named is None:
            continue  # none, or two bowls named before: which one is "the bowl" is not guessed
        out.append(text[at : toks[k - 1].pos] + f"object {named}")
        at = _end(text, toks[k])
    out.append(text[at:])
    return "".join(out)


def same_again(text: str, find: Callable[[tuple[str, ...]], list], ids_of: Callable[[Any], list[int]]) -> str:
    """``text`` with "that same block" ("the same bowl", "this same cup") replaced by the one object of that
    kind named before it ("put it behind the green block; the yellow piece goes in front of that same
    block": object 8). Left as said where the words before name no single object of that kind, or where
    "same" compares ("the same colour as")."""
    toks = tokenize(text)
    words = tuple(t.text for t in toks)
    out: list[str] = []
    at = 0
    for k in range(1, len(words) - 1):
        if words[k] != "same" or words[k - 1] not in ("that", "the", "this") or k < 2:
            continue
        kind = _ids(("the", words[k + 1]), find, ids_of) if words[k + 2 : k + 3] != ("as",) else None
        if not kind:
            continue
        named = _one_named(words[: k - 1], kind, find, ids_of)
        if named is None:
            continue  # none, or two plates named before: which one is "that same plate" is not guessed
        out.append(text[at : toks[k - 1].pos] + f"object {named}")
        at = _end(text, toks[k + 1])
    out.append(text[at:])
    return "".join(out)


def by_colour(text: str, find: Callable[[tuple[str, ...]], list], ids_of: Callable[[Any], list[int]],
              colour_of: Mapping[int, str]) -> str:
    """``text`` with each reference through another object's colour ("the cans that share a colour
    with one of the bowls") replaced by the ids it selects (:mod:`.colour_refs`). A phrase whose head
    or reference names nothing is left as said; one that selects nothing is refused."""
    text = _matched_pairs(text, find, ids_of, colour_of)
    toks = tokenize(text)
    words = tuple(t.text for t in toks)
    refs = find_colour_refs(words)
    out: list[str] = []
    at = 0
    for ref in refs:
        plural = not ref.head or ref.head[-1].endswith("s") or ref.head[-1] in ("stuff", "everything", "anything")
        if not (ref.negated or ref.quantified) and (plural or _reads_whole(words[ref.start : ref.end], find)):
            continue  # "the things that are the same colour as the blue bowl": the grounding reads it
        head = _ids(("the",) + ref.head if ref.head else ("everything",), find, ids_of)
        other = _ids(ref.ref, find, ids_of, several=True)
        if head is None or other is None:
            continue
        lo, hi = toks[ref.start].pos, _end(text, toks[ref.end - 1])
        got = select(head, other, colour_of, ref.negated)
        if not got:
            raise InputError(f"'{text[lo:hi]}' selects nothing: no such object has that colour")
        out.append(text[at:lo])
        out.append(_said_ids(got))
        at = hi
    out.append(text[at:])
    return "".join(out)


def _matched_pairs(text: str, find: Callable[[tuple[str, ...]], list], ids_of: Callable[[Any], list[int]],
                   colour_of: Mapping[int, str]) -> str:
    """``text`` with each "the A and the B that are the same colour" replaced by the two objects it names: the
    one A and the one B of a colour both kinds have. Refused where no colour or more than one pair fits."""
    toks = tokenize(text)
    words = tuple(t.text for t in toks)
    out: list[str] = []
    at = 0
    for pair in find_matched_pairs(words):
        firsts = _ids(("every",) + pair.first, find, ids_of)
        seconds = _ids(("every",) + pair.second, find, ids_of)
        if not firsts or not seconds:
            continue
        lo, hi = toks[pair.start].pos, _end(text, toks[pair.end - 1])
        fits = [(a, b) for a in firsts for b in seconds if a != b and colour_of[a] == colour_of[b]]
        if len(fits) != 1:
            why = "no two of them share a colour" if not fits else \
                f"{len(fits)} pairs share a colour ({', '.join(f'{a} and {b}' for a, b in fits)})"
            raise InputError(f"'{text[lo:hi]}' is unclear: {why}")
        out.append(text[at:lo])
        out.append(_said_ids(fits[0]))
        at = hi
    out.append(text[at:])
    return "".join(out)


def _reads_whole(words: tuple[str, ...], find: Callable[[tuple[str, ...]], list]) -> bool:
    """Whether the grounding reads ``words`` as one reference, every word of it."""
    try:
        found = find(words)
    except InputError:
        return False
    return len(found) >= 1 and found[0].start == 0 and found[0].end == len(words)


def without_context(words: tuple[str, ...], object_word: Callable[[str], bool],
                    request_word: Callable[[str], bool]) -> tuple[str, ...]:
    """The tokens without background sentences and time clauses (:func:`.context.drop_context`)."""
    return drop_context(words, lambda w: object_word(w) or is_mark(w), request_word)


#: What may come before "spell RATE" said as the request itself.
_SPELL_LEADS = frozenset({"", "please", "now", "ok", "okay", "can you", "could you", "would you", "please can you",
                          "next", "then", "and"})
#: The letters named after the word they spell ("spell RATE with the letters").
_SPELL_WITH = ("with the letters", "using the letters", "with the four letters", "using the four letters",
               "out of the letters", "with those letters", "with the letter blocks")


def spelled(text: str, letters: set[str]) -> str:
    """"stack the letters so that, read from the bottom up, they spell RATE": the
    stack of those letters in that order. Without the direction the reading is
    open (a word on a stack reads either way), so it is refused. Said with no stack
    ("Spell RATE with the letters"), those letters in a line (:func:`_spelled_in_line`)."""
    parts = re.split(r"(?<=[.;!?])\s+", text)
    for k, sent in enumerate(parts):
        m = re.search(r"\b(?i:spell|spells|spelling|spelt|reads?|reading|say|says)(?i: out)?(?i: the word)?\s*:?\s*"
                      r"([A-Z](?:\s+[A-Z]){1,9}|[A-Z]{2,10})\b", sent)
        if m is None:
            continue
        word = "".join(m.group(1).split()).upper()
        if not (len(set(word)) == len(word) and set(word) <= letters):
            continue
        if not re.search(r"(?i)\b(?:stack|stacked|tower|pile|piled)\b", sent):
            parts[k] = _spelled_in_line(sent, m.start(), m.end(), word)
            continue
        up = re.search(r"(?i)\b(?:bottom up|bottom upwards?|from (?:the )?bottom|bottom to top|upwards?|going up)\b", sent)
        down = re.search(r"(?i)\b(?:top down|top downwards?|from (?:the )?top|top to bottom|downwards?|going down)\b", sent)
        if bool(up) == bool(down):
            raise InputError(f"'{sent.strip()}': say whether '{word}' reads from the bottom up or from the top down")
        order = word if up else word[::-1]
        named = [f"the letter {c}" for c in order]
        parts[k] = "stack " + ", ".join(named[:-1]) + f" and {named[-1]}, from the bottom up."
    return " ".join(parts)


def _spelled_in_line(sent: str, start: int, end: int, word: str) -> str:
    """"Spell RATE with the letters, across the middle row", said as the request: those letters in a
    line (a line's order is not part of its goal). Left as said where "spell" is not the request."""
    lead = sent[:start].strip().lower().rstrip(",")
    if lead not in _SPELL_LEADS:
        return sent
    tail = sent[end:]
    low = tail.lower().lstrip()
    said = next((w for w in _SPELL_WITH if low.startswith(w)), None)
    if said is not None:
        tail = tail.lstrip()[len(said) :]
    named = [f"the letter {c}" for c in word]
    return f"{sent[:start]}put {', '.join(named[:-1])} and {named[-1]} in a line{tail}"
