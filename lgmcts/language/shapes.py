"""Sentence shapes around the object references: register, parameters, roles.

The offline parser reads a command as a few sentence shapes (selection,
pattern, relation, stacking, parameters); this module holds the closed-class
parts of that grammar, the words that are not matched against the scene or
the pattern database:

* :func:`normalise`: casual register (abbreviations, greetings, trailing
  politeness, "could you", "would you mind") and possessive relations ("on
  the mug's right" -> "on the right of the mug", "on its left" -> "on the
  left of it");
* :func:`take_params`: where, how big and facing ("a large circle in the
  top left of the table facing north", "a short line near the front edge");
* :func:`stack_roles`: the place of an object in a stack ("as the base",
  "at the bottom", "on top", "in the middle").

Every function works on lower-cased token tuples (:func:`.grounding.tokenize`).
"""

from __future__ import annotations

from collections.abc import Callable

from ..errors import InputError
from . import lexicon
from .places import POINTING_PARTS, read_facing, read_place

__all__ = ["normalise", "take_params", "stack_roles", "SIZES", "ROWS", "COLS", "FACINGS", "REGION_NOUNS"]

# ---------------------------------------------------------------- register
_ABBREV = {
    "u": ("you",), "pls": ("please",), "plz": ("please",), "pleas": ("please",), "thx": ("thanks",),
    "ty": ("thanks",), "r": ("are",), "ur": ("your",), "wanna": ("want", "to"), "gonna": ("going", "to"),
    "gimme": ("give", "me"), "lemme": ("let", "me"), "n": ("and",), "w": ("with",), "btw": (), "asap": (),
    "thru": ("through",), "obj": ("object",), "objs": ("objects",), "that's": ("that", "is"),
    "it's": ("it", "is"), "they're": ("they", "are"), "aren't": ("are", "not"), "isn't": ("is", "not"),
    "don't": ("do", "not"), "doesn't": ("does", "not"), "what's": ("what", "is"), "there's": ("there", "is"),
}
#: Words of greeting, politeness and hesitation that never carry an
#: arrangement or an object (dropped anywhere in the command).
_CHATTER = frozenset(
    """hey hi hello yo hiya howdy ok okay alright basically thanks thank cheers please kindly robot buddy mate pal
    um uh hmm er erm oh great awesome cool nice-to-have lol appreciated sir ta""".split()
)
_CHATTER_SEQ = (
    ("would", "it", "be", "possible", "to"), ("would", "it", "be", "all", "right", "to"), ("would", "it", "be", "alright", "to"),
    ("would", "it", "be", "okay", "to"), ("would", "it", "be", "ok", "to"), ("would", "it", "be", "fine", "to"),
    ("is", "it", "okay", "to"), ("is", "it", "ok", "to"), ("is", "it", "alright", "if"), ("is", "it", "okay", "if"),
    ("is", "it", "ok", "if"), ("is", "it", "all", "right", "if"), ("is", "it", "alright", "to"), ("is", "it", "all", "right", "to"),
    ("would", "it", "be", "all", "right", "for"), ("would", "it", "be", "alright", "for"), ("would", "it", "be", "okay", "for"),
    ("would", "it", "be", "ok", "for"), ("is", "it", "okay", "for"), ("is", "it", "ok", "for"), ("i'd", "love", "it", "if"), ("i'd", "like", "it", "if"),
    ("it", "would", "be", "great", "if"), ("it", "would", "be", "nice", "if"),
    ("might", "it", "be", "possible", "to"), ("would", "it", "be", "too", "much", "trouble", "to"),
    ("would", "it", "be", "too", "much", "bother", "to"), ("is", "it", "possible", "for"), ("would", "it", "be", "possible", "for"),
    ("might", "it", "be", "possible", "for"), ("i'd", "really", "appreciate", "it", "if"), ("i'd", "appreciate", "it", "if"), ("i", "would", "appreciate", "it", "if"),
    ("i'd", "be", "grateful", "if"), ("would", "it", "trouble", "you", "too", "much", "to"), ("would", "it", "trouble", "you", "to"),
    ("would", "you", "mind", "terribly"), ("would", "you", "mind", "awfully"), ("would", "you", "mind"), ("do", "you", "mind"), ("thank", "you"), ("if", "you", "can"), ("if", "you", "could"),
    ("when", "you", "can"), ("for", "me"), ("i", "want"), ("i'd", "like"), ("i", "would", "like"), ("i", "need"),
    ("i'd", "love"), ("i", "wanna"), ("go", "ahead", "and"), ("be", "a", "dear", "and"), ("be", "a", "love", "and"), ("how", "about"),
    ("is", "it", "possible", "to"), ("are", "you", "able", "to"), ("you", "should"), ("let's",), ("we", "need", "to"),
    ("ok", "so"), ("so", "basically"), ("much", "appreciated"), ("good", "morning"), ("good", "afternoon"),
    ("good", "evening"), ("quick", "one"), ("if", "that", "is", "ok"), ("if", "that", "is", "okay"),
    ("nothing", "else"), ("when", "you", "get", "a", "chance"), ("a", "lot"), ("so", "much"), ("in", "advance"),
    ("a", "bit"), ("a", "little", "bit"), ("i'm", "thinking"), ("i", "am", "thinking"), ("i", "was", "thinking"),
    ("i", "think"), ("honestly",), ("slightly",), ("could", "you", "possibly"), ("shall", "we"),
    ("do", "take", "your", "time"), ("take", "your", "time"), ("mind",), ("real", "quick"), ("real", "quickly"),
    ("right", "then"), ("in", "the", "final", "scene"), ("in", "the", "end"), ("at", "the", "end"), ("final", "state"),
    ("end", "state"), ("goal", "state"), ("target", "state"), ("and", "that", "is", "it"), ("that", "is", "it"), ("that", "is", "all"), ("so", "yeah"), ("you", "know"),
)
_SIDES = frozenset({"left", "right", "front", "back", "top"})


def normalise(words: tuple[str, ...]) -> tuple[str, ...]:
    """Casual register and possessive relations, token by token."""
    out: list[str] = []
    for k, w in enumerate(words):
        # "letter R", "letter U": a one-letter word after "letter" is a name.
        out.extend(_ABBREV.get(w, (w,)) if not (k and words[k - 1] == "letter" and len(w) == 1) else (w,))
    words = tuple(out)
    out = []
    i = 0
    while i < len(words):
        seq = next((s for s in _CHATTER_SEQ if words[i : i + len(s)] == s), None)
        if seq is not None:
            i += len(seq)
            continue
        w = words[i]
        if w in _CHATTER or (w == "so" and i + 1 < len(words) and words[i + 1] not in ("that", "it", "the", "they")):
            i += 1
            continue
        out.append(w)
        i += 1
    # Distributive "one X at each corner": every X, one per place.
    for k in range(len(out) - 3):
        if out[k] == "one" and any(out[m : m + 2] in (["at", "each"], ["at", "every"], ["on", "each"], ["in", "each"])
                                   for m in range(k + 2, min(k + 5, len(out) - 1))):
            out[k] = "every"
    # Possessive relations: "on the mug's right (side)" -> "on the right of the mug";
    # "on its left" -> "on the left of it".
    res: list[str] = []
    i = 0
    while i < len(out):
        w = out[i]
        if w.endswith("'s") and i + 1 < len(out) and out[i + 1] in _SIDES:
            # find the start of the possessor's noun phrase in res
            head = w[:-2]
            k = len(res)
            while k > 0 and res[k - 1] not in ("on", "to", "at", "in", "is", "be", "up", "ends", "sits", "lies", ","):
                k -= 1
            np_words = res[k:] + [head]
            side = out[i + 1]
            j = i + 2
            if j < len(out) and out[j] in ("side", "hand"):
                j += 1
            res = res[:k] + ["the", side, "of"] + (np_words if np_words[0] in ("the", "a", "an") else ["the"] + np_words)
            i = j
            continue
        if w in ("its", "their") and i + 1 < len(out) and out[i + 1] in _SIDES:
            side = out[i + 1]
            j = i + 2
            if j < len(out) and out[j] in ("side", "hand"):
                j += 1
            res += ["the", side, "of", "it" if w == "its" else "them"]
            i = j
            continue
        res.append(w)
        i += 1
    return tuple(res)


# ---------------------------------------------------------------- parameters
#: Size words -> the goal's ``size``.
SIZES = lexicon.SIZES
#: Row words (the table's y direction: bottom is the side nearest the robot's
#: viewer, "front") and column words.
ROWS = lexicon.ROWS
COLS = lexicon.COLS
FACINGS = lexicon.FACINGS
REGION_NOUNS = lexicon.REGION_NOUNS
_TABLE = lexicon.TABLE_WORDS
_REGION_PREP = frozenset({"in", "at", "on", "near", "along", "toward", "towards", "by", "to", "into", "onto",
                          "around", "over", "across", "within", "against", "close"})
_VIEWER = lexicon.VIEWER_WORDS
_SIDE_FACINGS = lexicon.SIDE_FACINGS
_FACE_VERBS = lexicon.FACE_VERBS


def merged_region(old: str, new: str) -> str | None:
    """Two places said for one arrangement as one region, or None where they differ: a row band and a
    column band are the region where they cross ("along the front edge, on the left" -> "bottom left")."""
    if old == new:
        return old
    bands = {"middle row": "middle", "center column": "center"}  # a whole band crossed by another band
    if (old in bands) != (new in bands) and {bands.get(old, old), bands.get(new, new)} not in ({"middle"}, {"center"}):
        old, new = bands.get(old, old), bands.get(new, new)
        if {old, new} == {"middle", "center"}:
            return None
        if old == "center" or new == "center":
            other = new if old == "center" else old
            return f"{other} center" if other in ("top", "middle", "bottom") else None
    a, b = old.split(), new.split()
    if len(a) == 1 and len(b) == 1:
        rows = [x for x in (a[0], b[0]) if x in ("top", "middle", "bottom")]
        cols = [x for x in (a[0], b[0]) if x in ("left", "center", "right")]
        if len(rows) == 1 and len(cols) == 1:
            return f"{rows[0]} {cols[0]}"
    return None


def _region_run(words: tuple[str, ...], i: int, stack: bool = False):
    """A region phrase starting at ``i``: ``(row, col, end)`` or None."""
    n = len(words)
    j = i
    if j < n and words[j] in _REGION_PREP:
        j += 1
        if j < n and words[j] in ("to", "the"):
            j += 1
    if j < n and words[j] == "the":
        j += 1
    pos: list[str] = []
    while j < n and (words[j] in ROWS or words[j] in COLS) and len(pos) < 2:
        pos.append(words[j])
        j += 1
    if not pos:
        return None
    noun = j < n and words[j] in REGION_NOUNS
    if noun:
        j += 1
    of_table = False
    if j + 1 < n and words[j] == "of" and (words[j + 1] in _TABLE or (words[j + 1] == "the" and j + 2 < n and words[j + 2] in _TABLE)):
        of_table = True
        j += 3 if words[j + 1] == "the" else 2
    elif j < n and words[j] == "of":
        return None  # "left of the plate", "the left side of the plate": a relation
    if not (of_table or noun or len(pos) == 2 or pos[0] in ("middle", "center", "centre", "central")
            or (i < j and words[i] in _REGION_PREP)):
        return None
    if stack and not (of_table or noun or len(pos) == 2):
        return None  # "at the bottom", "on top", "in the middle" of a stack are places in it
    row = col = None
    for p in pos:
        if len(pos) == 2 and p in ("middle", "center", "centre", "central"):
            if row is None and pos.index(p) == 0:
                row = "middle"
            else:
                col = "center"
        elif p in ("left", "right", "leftmost", "rightmost"):
            col = COLS[p]
        elif p in ROWS and p not in ("middle", "center", "centre", "central"):
            row = ROWS[p]
        elif p in ("middle", "center", "centre", "central"):
            row, col = row or "middle", col or "center"
    if j < n and words[j] == "of" and j + 1 < n and words[j + 1] in _TABLE:
        j += 2
    return row, col, j


def _stack_orders(words: tuple[str, ...], protected: dict[int, int]) -> None:
    """Protect the words of an order along a stack ("from top to bottom", "bottom up"): no place."""
    for k in range(len(words)):
        # "from top to bottom", "bottom up": an order along a stack, not a place.
        for seq in (("top", "to", "bottom"), ("bottom", "to", "top"), ("bottom", "up"), ("top", "down"),
                    ("the", "top", "down"), ("from", "the", "top"), ("from", "the", "bottom")):
            if words[k : k + len(seq)] == seq:
                protected[k] = max(protected.get(k, k), k + len(seq))


def _facing_at(words: tuple[str, ...], i: int, put: Callable[[str, str | int, str], None]) -> int | None:
    """A facing said at ``i`` ("facing north", "facing me", "pointing away", "tines toward the right edge"),
    given to ``put``; the index after its words, or None where no facing is said there. A facing towards
    anything but a direction, an edge or the viewer is refused."""
    n = len(words)
    w = words[i]
    if w in _FACE_VERBS or w in POINTING_PARTS:
        face = read_facing(words, i)  # by an edge or the viewer: "facing the back wall", "tines toward me"
        if face is not None:
            put("facing", face[0], " ".join(words))
            return face[1]
    if w in _FACE_VERBS:
        j = i + 1
        while j < n and (words[j] in ("to", "the", "toward", "towards", "in", "direction", "of", ",", "like")
                         or words[j] in _FACE_VERBS):
            j += 1  # "facing, uh, north": the pause left by a filler
        if j < n and words[j] in FACINGS:
            put("facing", FACINGS[words[j]], " ".join(words))
            i = j + 1
            if i < n and words[i] == "direction":
                i += 1
            return i
        # The viewer stands at the table's south edge: "facing me" is south,
        # "pointing away from us" north, "turned left" west.
        k = j + 1
        if j < n and words[j] == "away":
            while k < n and words[k] in ("from", "the"):
                k += 1
            if k < n and words[k] in _VIEWER:
                k += 1
            put("facing", "north", " ".join(words))
            return k
        if j < n and (words[j] in _VIEWER or words[j] in _SIDE_FACINGS):
            put("facing", "south" if words[j] in _VIEWER else _SIDE_FACINGS[words[j]], " ".join(words))
            return j + 1
        raise InputError(
            f"'{' '.join(words[i:j + 2])}': facing can be north, east, south or west only, not towards an object")
    return None


def _size_at(words: tuple[str, ...], i: int, pattern_nouns, put: Callable[[str, str | int, str], None]) -> int | None:
    """A size word right before a pattern noun ("a big circle", "a big round shape"), given to ``put``; the
    index after it, or None where the word sizes no arrangement (the caller reads it on)."""
    n = len(words)
    w = words[i]
    j = i + 1
    while j < n and (words[j] in ("straight", "neat", "tidy", "nice", "single", "round", "and", ",", "sized",
                                  "size", "scale", "scaled")
                     or words[j] in SIZES):
        j += 1
    if j < n and (pattern_nouns(words[j]) or (
            words[j] in ("shape", "formation", "pattern", "arrangement") and pattern_nouns(words[j - 1]))):
        # "a big circle"; "a big round shape" (the shape named by the word before the generic noun)
        if not (w in ("little", "tiny", "big", "large", "huge", "giant", "tall")
                and words[j] in ("tower", "stack", "pile", "column")):
            # a tower has no size: "a little tower" is a short one, "one big pile" all the objects in one
            put("size", SIZES[w], " ".join(words))
        return i + 1
    return None


def _merged_place(words: tuple[str, ...], row: str | None, col: str | None, r: str | None,
                  c: str | None) -> tuple[str | None, str | None]:
    """The row and column said so far with a place read next (row ``r``, column ``c``): a middle said
    after a band or a side is the middle of it; two different rows or columns are refused."""
    if r is not None and row is not None and row != r and r == "middle" and c in (None, "center") and col is None:
        # "at the back of the table, in the middle": the middle of that band.
        r, c = None, "center"
    if row == "middle" and col == "center" and r is None and c in ("left", "right"):
        # "in the middle of the table, on the right side": halfway along that side.
        col = None
    if c == "center" and r in (None, "middle") and col not in (None, "center") and row is None:
        # "on the left side, in the middle": halfway along that side.
        r, c = "middle", None
    if r is not None:
        if row is not None and row != r:
            raise InputError(f"'{' '.join(words)}': two different places for one arrangement")
        row = r
    if c is not None:
        if col is not None and col != c:
            raise InputError(f"'{' '.join(words)}': two different places for one arrangement")
        col = c
    return row, col


def take_params(words: tuple[str, ...], pattern_nouns, protected: dict[int, int] | None = None,
                stack: bool = False) -> tuple[dict, tuple[str, ...]]:
    """Pull where / how big / facing out of a clause that names an arrangement.

    ``pattern_nouns(word)`` says whether a word names a pattern (a size word
    counts only right before one: "a large circle", not "the large bowl").
    ``stack``: the clause is about a stack, whose "bottom", "top" and
    "middle" are places in the stack, not on the table (only "of the table",
    a corner or a two-word place is a region then).
    ``protected`` maps the start of each object reference to its end: those
    words are kept as they are, and a place named right after an object
    listed after the arrangement ("a line and the phone in the middle") is
    that object's place, not the arrangement's, and is left in the clause.
    Returns the parameters (``region`` "<row> <col>", ``size``, ``facing``)
    and the clause without their words. Two different values of one
    parameter are refused.
    """
    protected = dict(protected or {})
    _stack_orders(words, protected)
    seen_pattern = False
    blocked = False
    own_list = False  # the objects said after the pattern noun and "of" ("a line of the cups and ...")
    band = False
    params: dict[str, str | int] = {}
    keep: list[str] = []
    row = col = None
    n = len(words)
    i = 0

    def put(key: str, val: str | int, text: str) -> None:
        if key in params and params[key] != val:
            both = "" if key == "measure" else f" ({params[key]}, {val})"  # a measure is said in the quote
            raise InputError(f"'{text}': two different {key}s{both} for one arrangement")
        params[key] = val

    while i < n:
        w = words[i]
        if i in protected:
            end = protected[i]
            if seen_pattern and i > 0 and words[i - 1] in ("and", ",", "&", "while", "plus"):
                blocked = True
            own_list = own_list or (seen_pattern and i > 0 and words[i - 1] == "of")
            run = _region_run(words, end) if end < n else None
            if seen_pattern and i > 0 and words[i - 1] == "with" and run is not None \
                    and any(words[x] in ("middle", "center", "centre") for x in range(end, min(end + 4, n))) \
                    and not any(words[x] in _TABLE for x in range(end, min(run[2] + 3, n))):
                blocked = True  # "a circle with the plate in the middle": the plate's place, not the circle's
            keep.extend(words[i:end])
            i = end
            continue
        if pattern_nouns(w):
            seen_pattern, blocked, own_list = True, False, False
        if w.startswith("sizemark") and len(w) == 9:
            put("measure", ord(w[-1]) - 97, " ".join(words))  # a measure in numbers (.stages.mark_measures)
            i += 1
            continue
        got_i = _facing_at(words, i, put)
        if got_i is not None:
            i = got_i
            continue
        got_i = _size_at(words, i, pattern_nouns, put) if w in SIZES and i + 1 < n else None
        if got_i is not None:
            i = got_i
            continue
        free = read_place(words, i)  # said freely: "dead centre", "partway back on the right", "a strip along the front"
        got = (free[0].row, free[0].col, free[1]) if free is not None else _region_run(words, i, stack)
        if free is not None and not seen_pattern:
            # "in a strip along the front": "strip" names the line as well as the band it lies in
            noun = next((k for k in range(i, free[1]) if words[k] in ("strip", "band") and pattern_nouns(words[k])
                         and words[k - 2 : k] in (("in", "a"), ("into", "a"), ("as", "a"), ("form", "a"))), None)
            if noun is not None:
                keep.extend(words[i : noun + 1])
                seen_pattern = True
        if blocked and got is not None and free is None and not (
                any(words[x] in _TABLE or words[x] in REGION_NOUNS for x in range(i, got[2]))
                or sum(words[x] in ROWS or words[x] in COLS for x in range(i, got[2])) >= 2):
            if own_list and not any(words[x] in ("middle", "centre", "center") for x in range(i, got[2])):
                blocked = False  # "a line of the cups and the box at the back (in the middle)": the line's own list
            else:
                got = None  # a place right after an object listed last is that object's ("..., the centre of the table" is not)
        if got is not None and any(k in protected for k in range(i, got[2])):
            got = None
        if got is not None:
            r, c, j = got
            band = band or (free is not None and free[0].band)
            row, col = _merged_place(words, row, col, r, c)
            i = j
            continue
        keep.append(w)
        i += 1
    if row is not None and col is not None:
        params["region"] = f"{row} {col}"
    elif row is not None or col is not None:
        params["region"] = str(row or col)  # one band of the table: "bottom", "left"
        if band and params["region"] in ("middle", "center"):
            params["region"] = "middle row" if row else "center column"  # never the centre cell
    return params, tuple(keep)


# ---------------------------------------------------------------- stacking
#: Role phrases after an object in a stack, longest first: where it goes.
_ROLES = tuple(
    (tuple(p.split()), r)
    for p, r in sorted(
        [
            ("as the base", "bottom"), ("as a base", "bottom"), ("as the foundation", "bottom"),
            ("as the bottom", "bottom"), ("at the bottom", "bottom"), ("on the bottom", "bottom"),
            ("at the base", "bottom"), ("as the bottom layer", "bottom"), ("goes first", "bottom"),
            ("as the top", "top"), ("on top", "top"), ("at the top", "top"), ("on the top", "top"),
            ("goes on top", "top"), ("goes last", "top"), ("as the cap", "top"), ("in the middle", "middle"),
            ("in between", "middle"), ("in the centre", "middle"), ("in the center", "middle"),
            ("between them", "middle"), ("goes on it", "next"), ("goes on that", "next"), ("goes next", "next"),
            ("goes above", "next"), ("goes on top of it", "next"), ("goes on top of that", "next"),
            ("bottom", "bottom"), ("top", "top"), ("lowest", "bottom"), ("highest", "top"),
            ("goes in between", "middle"), ("goes in the middle", "middle"), ("at the summit", "top"),
            ("at the peak", "top"), ("at the very top", "top"), ("at the very bottom", "bottom"),
            ("on the very top", "top"), ("right at the top", "top"), ("in the middle of the stack", "middle"),
            ("goes down first", "bottom"), ("goes down last", "top"), ("first", "bottom"), ("last", "top"),
            ("to finish", "top"), ("to top it off", "top"), ("crowning it", "top"), ("as the bottom layer", "bottom"),
            ("underneath", "bottom"), ("beneath", "bottom"), ("on it", "next_it"), ("on top of it", "next_it"),
            ("above it", "next_it"), ("on that", "next_it"), ("on top of that", "next_it"), ("over it", "next_it"), ("goes in the middle", "middle"),
            ("under them all", "bottom"), ("down under them all", "bottom"), ("under everything", "bottom"),
            ("below everything", "bottom"), ("beneath everything", "bottom"), ("below them all", "bottom"),
            ("sandwiched between them", "middle"), ("sandwiched in between", "middle"), ("sandwiched in the middle", "middle"),
            ("finishes it off on the top", "top"), ("finishes it off", "top"), ("tops it off", "top"),
            ("caps it off", "top"), ("caps it", "top"), ("crowns it", "top"), ("on top of them all", "top"),
            ("on top of everything", "top"), ("above them all", "top"), ("above everything", "top"),
            ("last of all", "top"), ("next", "next"), ("after that", "next"), ("next up", "next"),
            ("directly above it", "next_it"), ("right above it", "next_it"), ("just above it", "next_it"),
            ("directly on top of it", "next_it"), ("right on top of it", "next_it"), ("directly on it", "next_it"),
            ("down first", "bottom"), ("carrying them all", "bottom"), ("carrying them", "bottom"),
            ("carrying everything", "bottom"), ("holding everything up", "bottom"),
            ("holding them up", "bottom"), ("holding both of them up", "bottom"), ("holds them up", "bottom"),
            ("holds both of them up", "bottom"), ("supporting them", "bottom"), ("supporting both of them", "bottom"),
            ("supports them", "bottom"), ("supports both of them", "bottom"), ("holding them all up", "bottom"),
            ("holds them all up", "bottom"), ("supporting them all", "bottom"), ("supports them all", "bottom"),
            ("under it", "under_it"), ("below it", "under_it"), ("beneath it", "under_it"),
            ("underneath it", "under_it"), ("under that", "under_it"), ("below that", "under_it"),
            ("right under it", "under_it"), ("just under it", "under_it"), ("right below it", "under_it"),
            ("just below it", "under_it"), ("directly under it", "under_it"), ("directly below it", "under_it"),
        ],
        key=lambda pr: -len(pr[0].split()),
    )
)


#: What "on top of" / "at the bottom of" may name and still be a place in the stack.
_OF_STACK = frozenset({("it",), ("that",), ("them",), ("those",), ("the", "stack"), ("the", "tower"), ("the", "pile"),
                       ("a", "stack"), ("a", "tower"), ("a", "pile"),
                       ("the", "heap"), ("everything",), ("all",)})


def stack_roles(words: tuple[str, ...], i: int) -> tuple[str, int] | None:
    """The role phrase at ``i`` (right after an object reference) and its end."""
    j = i
    if j < len(words) and words[j] == ",":
        j += 1
    # "goes"/"should go"/"sits" before a role phrase are one verb: "goes on it".
    k = j
    while k < len(words) and words[k] in ("should", "will", "must", "can"):
        k += 1
    if k < len(words) and words[k] in ("go", "goes", "sits", "sit", "comes", "come", "is", "be", "stands", "belongs",
                                       "ends", "rests"):
        cand = ("goes",) + words[k + 1 :]
        for seq, role in _ROLES:
            if seq[0] == "goes" and cand[: len(seq)] == seq:
                end = k + len(seq)
                if seq[-1] != "of" and words[end : end + 1] == ("of",) and words[end + 1 : end + 2] not in _OF_STACK \
                        and words[end + 1 : end + 3] not in _OF_STACK:
                    return None  # "goes on top of the red one": a relation to another object
                return role, end
        # "the red one goes at the bottom", "the white one is on top"
        at = k + 1 + (words[k + 1 : k + 2] == ("up",))
        for seq, role in _ROLES:
            if seq[0] != "goes" and len(seq) > 1 and words[at : at + len(seq)] == seq:
                end = at + len(seq)
                if words[end : end + 1] == ("of",) and words[end + 1 : end + 2] not in _OF_STACK \
                        and words[end + 1 : end + 3] not in _OF_STACK:
                    return None
                return role, end
    for seq, role in _ROLES:
        if words[j : j + len(seq)] == seq:
            if seq in (("underneath",), ("beneath",)) and words[j + 1 : j + 2] not in ((), (",",), ("and",), (".",)):
                return None  # "the bowl underneath the plate": a relation; "with the bowl underneath": the bottom
            if seq in (("top",), ("bottom",)) and words[j + 1 : j + 2] in (("to",), ("down",), ("up",)):
                return None  # "top to bottom", "bottom up": an order of the list, not a role
            if seq == ("next",) and words[j + 1 : j + 2] in (("to",), ("door",)):
                return None  # "next to": a relation
            end = j + len(seq)
            if words[end : end + 1] == ("of",) and words[end + 1 : end + 2] not in _OF_STACK \
                    and words[end + 1 : end + 3] not in _OF_STACK:
                return None  # "on top of the fork": a relation to another object, not a place in a stack
            return role, end
    return None
