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
"""

from __future__ import annotations

import re
from dataclasses import dataclass, replace

from ..errors import InputError
from ..formats import SceneSpec
from . import lexicon
from .ir import Token
from .matcher import STOPWORDS

__all__ = [
    "SYNONYMS",
    "Token",
    "tokenize",
    "Vocabulary",
    "Mention",
    "Choice",
    "find_mentions",
    "candidates",
    "select",
    "describe",
]

#: Words that may name a scene category. A synonym applies only when the
#: scene has an object of the canonical category and none named like the
#: synonym itself (the scene's own names always win).
SYNONYMS: dict[str, tuple[str, ...]] = {
    "block": ("cube", "box", "brick"),
    "mug": ("cup",),
    "cup": ("mug",),
    "bowl": ("dish",),
    "plate": ("dish",),
    "phone": ("cellphone", "smartphone", "cell phone", "mobile phone", "mobile", "handset"),
    "pan": ("frying pan", "skillet"),
    "bottle": ("flask",),
    "flower": ("blossom",),
    "can": ("tin", "soda can", "tin can"),
    "letter": ("character",),
}

#: Group nouns: words for a kind of thing that is no object's name ("the
#: silverware", "the dishes"). A group noun selects every scene object whose
#: category is one of its members (and is refused when there is none); the
#: scene's own names always win over this table.
GROUPS: dict[str, tuple[str, ...]] = {
    "silverware": ("fork", "knife", "spoon", "chopstick", "spatula", "ladle"),
    "cutlery": ("fork", "knife", "spoon", "chopstick"),
    "flatware": ("fork", "knife", "spoon"),
    "utensil": ("fork", "knife", "spoon", "spatula", "ladle", "whisk", "chopstick"),
    "dish": ("plate", "bowl", "saucer"),
    "dishware": ("plate", "bowl", "saucer", "mug", "cup"),
    "crockery": ("plate", "bowl", "saucer", "mug", "cup"),
    "tableware": ("plate", "bowl", "saucer", "mug", "cup", "fork", "knife", "spoon", "glass"),
    "drinkware": ("mug", "cup", "glass", "bottle", "can"),
    "container": ("bowl", "mug", "cup", "bottle", "can", "box", "jar", "glass", "basket"),
    "drink": ("bottle", "can"),
    "beverage": ("bottle", "can"),
    "letter": ("letter",),
    "toy": ("block", "ball", "letter"),
    "shape": ("triangle", "square", "pentagon", "hexagon", "heart", "star", "cross", "ring", "flower", "diamond",
              "circle"),
}

_PLURAL_ONLY = frozenset({"shape", "letter", "toy"})

#: Words that name an object without a category.
GENERIC = frozenset({"object", "objects", "thing", "things", "item", "items", "piece", "pieces", "one", "ones", "stuff"})

#: Colour and texture words used only to recognise a reference to an object
#: the scene does not have ("the purple giraffe").
COLOUR_WORDS = lexicon.COLOUR_WORDS

NUMBERS = lexicon.NUMBERS

#: Tokens before a pattern noun: "in a square", "into a ring", "form a cross".
PATTERN_LEAD = frozenset({"in", "into", "as", "form", "forming", "forms", "make", "making", "like", "shape"})
_SHAPE_ADJ = frozenset({"a", "an", "single", "big", "large", "small", "neat", "perfect", "nice", "tidy", "straight"})


def _pattern_context(words: tuple[str, ...], i: int) -> bool:
    """Whether position ``i`` follows "in a", "into a", "form a", "shape of a"..."""
    j, skipped = i - 1, 0
    while j >= 0 and words[j] in _SHAPE_ADJ:
        j, skipped = j - 1, skipped + 1
    if j >= 1 and words[j] == "of" and words[j - 1] == "shape":
        return True
    if j < 0:
        return False
    if words[j] in ("into", "form", "forming", "forms"):
        return True
    return words[j] in ("in", "as", "like", "make", "making") and skipped > 0


_TOKEN_RE = re.compile(r"-?\d+(?:\.\d+)?|[a-z]+(?:'[a-z]+)?|[;,.!?#()&:]")


def tokenize(text: str) -> tuple[Token, ...]:
    """Lower-case words, numbers and punctuation of ``text``, each with its span in ``text`` (:class:`.ir.Token`)."""
    low = text.lower().replace("\u2019", "'").replace("\u2018", "'")
    low = re.sub(r"(?<=[a-z])-(?=[a-z])", " ", low)
    return tuple(Token(m.group(0), m.start(), m.end(), Token.kind_of(m.group(0))) for m in _TOKEN_RE.finditer(low))


_COLOUR_FORMS = {"striped": "stripe", "stripes": "stripe", "dots": "dot", "dotted": "dot", "swirls": "swirl",
                 "swirled": "swirl", "gray": "grey"}


def colour_words(color: str) -> tuple[str, ...]:
    """The words of a colour, normalised ("striped" -> "stripe", "gray" -> "grey"), without "and"/"or"."""
    return tuple(_COLOUR_FORMS.get(w, w) for w in _words(color) if w.isalpha() and w not in ("and", "or"))


def _plural(word: str) -> str:
    if word.endswith(("s", "x", "z", "ch", "sh")):
        return word + "es"
    if word.endswith("y") and len(word) > 1 and word[-2] not in "aeiou":
        return word[:-1] + "ies"
    if word.endswith("fe"):
        return word[:-2] + "ves"
    if word.endswith("f") and not word.endswith("ff"):
        return word[:-1] + "ves"
    return word + "s"


def _measure(shape) -> tuple[float, float, float]:
    """(height, volume, width) of a scene shape (m, m^3, m)."""
    import math

    t = getattr(shape, "type", "")
    if t == "box":
        x, y, z = shape.size
        return z, x * y * z, max(x, y)
    if t == "cylinder":
        return shape.height, math.pi * shape.radius**2 * shape.height, 2 * shape.radius
    pts = [(p[0], p[1]) for p in getattr(shape, "points", [])]
    if pts:
        from shapely import MultiPoint

        hull = MultiPoint(pts).convex_hull
        if t == "points":
            zs = [p[2] for p in shape.points]
            h = max(zs) - min(zs)
        else:
            h = float(shape.height)
        x0, y0, x1, y1 = hull.bounds
        return h, hull.area * h, max(x1 - x0, y1 - y0)
    return 0.0, 0.0, 0.0


def _words(text: str) -> tuple[str, ...]:
    return tuple(t.text for t in tokenize(text))


@dataclass(frozen=True)
class Vocabulary:
    """The scene's categories and colours as token sequences.

    ``categories`` maps a token tuple to ``(names, plural)``: the canonical
    scene names it selects and whether the form is plural. ``colors`` maps a
    token tuple to the canonical (lower-cased) scene colour.
    """

    categories: dict[tuple[str, ...], tuple[frozenset[str], bool]]
    colors: dict[tuple[str, ...], str]
    objects: tuple[tuple[int, str, str], ...]  # (id, name, color), lower-cased
    #: Single words of the scene's colours ("swirl", "polka", "dot"), normalised
    #: by :func:`colour_words`, for colours given in part ("the swirl flower").
    color_words: frozenset[str] = frozenset()
    #: (height, volume, width) of each object's shape, by id, for "greater
    #: height than the X" and "smaller than the X".
    measures: tuple[tuple[int, float, float, float], ...] = ()
    #: Category forms that name a scene kind only through :data:`SYNONYMS`
    #: ("cup" and "cups" in a scene of mugs and no cup), each with the name it stands for.
    borrowed: tuple[tuple[tuple[str, ...], str], ...] = ()

    @classmethod
    def from_scene(cls, scene: SceneSpec) -> "Vocabulary":
        objs = tuple((o.id, " ".join(o.name.lower().split()), " ".join(o.color.lower().split())) for o in scene.objects)
        names = {n for _, n, _ in objs}
        cats: dict[tuple[str, ...], tuple[set[str], bool]] = {}

        def add(form: tuple[str, ...], name: str, plural: bool) -> None:
            if not form:
                return
            entry = cats.setdefault(form, (set(), plural))
            entry[0].add(name)

        for n in sorted(names):
            w = _words(n)
            add(w, n, False)
            if len(w[-1]) == 1 and len(w) > 1:  # "letter a" -> "letters a"
                add((_plural(w[0]),) + w[1:], n, True)
            else:
                add(w[:-1] + (_plural(w[-1]),), n, True)
            if len(w) > 1 and len(w[-1]) == 1:  # "letters" selects every "letter x"
                add((_plural(w[0]),), n, True)
                add((w[0],), n, False)  # "every letter" (the longest form still wins: "letter a")
                if w[-1] not in ("a", "i", "u", "r", "n", "w", "o"):
                    add((w[-1],), n, False)  # "the yellow T"
        real = set(cats)
        borrowed: list[tuple[tuple[str, ...], str]] = []
        for canon, syns in SYNONYMS.items():
            if canon not in names:
                continue
            for s in syns:
                if s in names:
                    continue
                sw = _words(s)
                if sw in real:
                    continue
                add(sw, canon, False)
                add(sw[:-1] + (_plural(sw[-1]),), canon, True)
                borrowed.extend(((sw, canon), (sw[:-1] + (_plural(sw[-1]),), canon)))
        colors: dict[tuple[str, ...], str] = {}
        for c in sorted({c for _, _, c in objs if c}):
            w = _words(c)
            variants = {w}
            last = w[-1]
            for a, bs in (("stripe", ("stripes", "striped")), ("dot", ("dots", "dotted")), ("swirl", ("swirls", "swirled"))):
                if last == a:
                    variants.update(w[:-1] + (b,) for b in bs)
            if "grey" in w or "gray" in w:
                variants.add(tuple("gray" if x == "grey" else "grey" if x == "gray" else x for x in w))
            for v in variants:
                colors.setdefault(v, c)
        real = set(cats)
        for group, members in GROUPS.items():
            hit = {n for n in names if any(n == m or n.startswith(m + " ") for m in members)}
            gw = _words(group)
            if not hit or gw in real:
                continue
            # "shape" alone is a word of patterns ("in a star shape"): only "shapes" is a group.
            forms = (gw[:-1] + (_plural(gw[-1]),),) if group in _PLURAL_ONLY else (gw, gw[:-1] + (_plural(gw[-1]),))
            for form in forms:
                if form not in real:
                    add(form, next(iter(hit)), True)
                    cats[form][0].update(hit)
        frozen = {k: (frozenset(v[0]), v[1]) for k, v in cats.items()}
        heads = {k[0] for k in frozen}
        cwords = frozenset(w for _, _, c in objs for w in colour_words(c) if w not in heads)
        return cls(frozen, colors, objs, cwords, tuple((o.id, *_measure(o.shape)) for o in scene.objects),
                   tuple(borrowed))

    def longest(self, table: dict, words: tuple[str, ...], i: int) -> tuple[tuple[str, ...], int] | None:
        """Longest key of ``table`` starting at ``words[i]``; returns (key, end)."""
        best = None
        for k in table:
            n = len(k)
            if words[i : i + n] == k and (best is None or n > len(best)):
                best = k
        return (best, i + len(best)) if best is not None else None

    def label(self, oid: int) -> str:
        for i, n, c in self.objects:
            if i == oid:
                return f"{c} {n}".strip()
        return f"object {oid}"


@dataclass(frozen=True)
class Mention:
    """One object reference; ``start``/``end`` are token indices (end exclusive).

    ``det`` is one of ``all``, ``the``, ``both``, ``one`` (any one), ``count``
    (any ``count``), ``other`` (those not named before), ``another`` (any one
    not named before), ``ids`` (explicit ids) or ``pronoun``.
    """

    start: int
    end: int
    text: str
    det: str
    plural: bool
    names: frozenset[str] | None = None  # None: any category
    colors: tuple[str, ...] | None = None
    color_order: tuple[str, ...] = ()
    ids: tuple[int, ...] = ()
    count: int | None = None
    same_color_as: "Mention | None" = None
    excluding: tuple["Mention", ...] = ()
    #: ``"elided"``: colours with the noun left out ("the red" in "the red and
    #: the blue blocks"); ``"one"``: "the red one". Both take the category of
    #: a coordinated neighbour (see :func:`find_mentions`).
    head: str = ""
    #: Attribute filters ``(attribute, op, reference)``: attribute one of
    #: ``color``, ``name``, ``height``, ``volume``, ``width`` or ``value``
    #: (the reference is then a mention whose matches are kept or removed),
    #: op one of ``eq``, ``ne``, ``lt``, ``gt``.
    filters: tuple[tuple[str, str, "Mention"], ...] = ()
    #: "two of the three cans": the number of matches the phrase states.
    of_count: int | None = None
    #: An everyday generic noun ("the red things", "every red item"): a colour
    #: also takes the objects whose colour starts with it ("red swirl").
    loose: bool = False


@dataclass(frozen=True)
class Choice:
    """``k`` objects to be chosen later from ``options`` (any choice is right)."""

    options: tuple[int, ...]
    k: int
    text: str
    fresh: bool = False


_DETS: tuple[tuple[tuple[str, ...], str], ...] = tuple(
    sorted(
        [
            (("all", "of", "the"), "all"), (("all", "the"), "all"), (("all",), "all"), (("every",), "all"),
            (("each", "of", "the"), "all"), (("each",), "all"), (("both", "of", "the"), "both"),
            (("both", "the"), "both"), (("both",), "both"), (("the", "other"), "other"), (("the", "remaining"), "other"),
            (("the", "rest", "of", "the"), "other"), (("all", "other"), "other"), (("all", "the", "other"), "other"),
            (("all", "remaining"), "other"), (("remaining",), "other"), (("other",), "other"), (("another",), "another"),
            (("the",), "the"), (("a",), "one"), (("an",), "one"), (("any",), "one"), (("one", "of", "the"), "one"),
            (("any", "one", "of", "the"), "one"), (("a", "single"), "one"), (("one",), "one"), (("some", "of", "the"), "vague"),
            (("some",), "vague"), (("a", "few"), "vague"), (("several",), "vague"), (("most", "of", "the"), "vague"),
            (("most",), "vague"), (("half", "of", "the"), "half"), (("half", "the"), "half"), (("half",), "half"),
            (("those",), "all"), (("these",), "all"),
        ],
        key=lambda kv: -len(kv[0]),
    )
)

_SAME_COLOR = tuple(
    tuple(s.split())
    for s in sorted(
        [
            "whose color is same as", "whose color is the same as", "whose colour is same as",
            "whose colour is the same as", "whose color matches", "whose colour matches", "with the same color as",
            "with the same colour as", "with same color as", "of the same color as", "of the same colour as",
            "of same color as", "in the same color as", "in the same colour as", "that have the same color as",
            "that has the same color as", "which have the same color as", "which has the same color as",
            "that are the same color as", "that is the same color as", "which are the same color as",
            "having the same color as", "sharing the color of", "sharing the colour of", "matching the color of",
            "matching the colour of", "that have the same colour as", "that are the same colour as",
            "the same color as", "the same colour as", "same color as", "same colour as", "colored like",
            "coloured like", "shares the same colour as", "shares the same color as", "share the same colour as",
            "share the same color as", "sharing the same colour as", "sharing the same color as",
            "that shares the same colour as", "that shares the same color as", "that share the same colour as",
            "that share the same color as",
        ],
        key=lambda s: -len(s),
    )
)

_EXCEPT = tuple(
    tuple(s.split())
    for s in sorted(
        ["except for", "except", "but not", "other than", "excluding", "apart from", "but", "save for", "without", "minus",
         "leaving out", "not counting", "with the exception of", "aside from", "barring"],
        key=lambda s: -len(s),
    )
)

# ---------------------------------------------------------------- attributes
#: Relative-clause openers before an attribute ("whose", "with", "that have").
_REL_OPEN = frozenset({"whose", "with", "of", "that", "which", "having", "has", "have", "are", "is", "who"})
_ATTRS = {"color": "color", "colour": "color", "colors": "color", "colours": "color", "shape": "name",
          "type": "name", "kind": "name", "category": "name", "class": "name", "size": "volume",
          "volume": "volume", "volumn": "volume", "shapes": "name", "sizes": "volume", "height": "height", "width": "width"}
#: Comparison words: (words, op). "not" before any of them negates eq.
_CMP = tuple(
    (tuple(w.split()), op)
    for w, op in sorted(
        [
            ("equal to", "eq"), ("equal", "eq"), ("the same as", "eq"), ("same as", "eq"), ("identical to", "eq"),
            ("identical", "eq"), ("alike", "eq"), ("similar", "eq"), ("equivalent to", "eq"), ("similar to", "eq"), ("like", "eq"),
            ("matching", "eq"), ("matches", "eq"), ("match", "eq"), ("the same", "eq"), ("same", "eq"),
            ("different with", "ne"), ("different from", "ne"), ("different than", "ne"), ("different to", "ne"),
            ("different", "ne"), ("unlike", "ne"), ("not alike", "ne"),
            ("less than", "lt"), ("smaller than", "lt"), ("shorter than", "lt"), ("narrower than", "lt"),
            ("lower than", "lt"), ("smaller in size than", "lt"), ("smaller", "lt"), ("less", "lt"),
            ("greater than", "gt"), ("bigger than", "gt"), ("larger than", "gt"), ("taller than", "gt"),
            ("wider than", "gt"), ("higher than", "gt"), ("bigger in size than", "gt"), ("greater", "gt"),
            ("bigger", "gt"), ("larger", "gt"), ("more", "gt"),
        ],
        key=lambda x: -len(x[0].split()),
    )
)
#: Comparatives that imply their attribute ("taller than the bowl").
_IMPLIED = {"taller": "height", "shorter": "height", "higher": "height", "lower": "height", "wider": "width",
            "narrower": "width", "bigger": "volume", "larger": "volume", "smaller": "volume"}
_NEG = {"eq": "ne", "ne": "eq", "lt": "ge", "gt": "le"}
_PREP = frozenset({"to", "as", "from", "than", "with", "of"})
#: Relative tolerance within which two measures count as equal.
MEASURE_TOL = 0.05


def _skip(words: tuple[str, ...], i: int, vocab_words: frozenset[str]) -> int:
    while i < len(words) and words[i] in vocab_words:
        i += 1
    return i


def _cmp_at(words: tuple[str, ...], i: int) -> tuple[str, int] | None:
    neg = False
    if i < len(words) and words[i] in ("not", "isn't", "aren't", "n't"):
        neg, i = True, i + 1
    for seq, op in _CMP:
        if _starts(words, i, seq):
            return (_NEG[op] if neg else op), i + len(seq)
    return None


def _attr_qualifier(vocab: "Vocabulary", words: tuple[str, ...], i: int, pattern_words: frozenset[str]):
    """An attribute clause after a noun: ``((attribute, op, reference), end)`` or None.

    Shapes (LGMCTS-D and StructFormer wording and free variants)::

        [whose|with|that have ...] [the|a] ATTR [is|are] [not] CMP [to|as|from|than] REF
        [whose|with|that have ...] [the|a] CMP ATTR [as|to|from|than] REF
        [that|which] [is|are] [not] CMP-ADJ than REF       ("that are taller than the mug")
        [that|which] [is|are] [not] VALUE                   ("that are red", "that are mug", "that are not red")
    """
    n = len(words)
    j = i
    opened = 0
    while j < n and words[j] in _REL_OPEN and opened < 3:
        j, opened = j + 1, opened + 1
    if not opened:
        # "objects identical to color X", "objects different from color X"
        # (older LGMCTS-D wording): a comparison right before an attribute.
        # "objects smaller than the plate": a comparative with "than" right after the noun.
        got = _cmp_at(words, j)
        if got is None:
            return None
        implied = words[j] in _IMPLIED and words[got[1] - 1] == "than"
        if not implied and (got[1] >= n or words[got[1]] not in _ATTRS):
            return None
    k = j
    if k < n and words[k] in ("the", "a", "an"):
        k += 1
    op = attr = None
    # ATTR first
    if k < n and words[k] in _ATTRS:
        attr = _ATTRS[words[k]]
        k2 = k + 1
        while k2 < n and words[k2] in ("is", "are", "being"):
            k2 += 1
        got = _cmp_at(words, k2)
        if got is not None:
            op, k = got[0], got[1]
    else:
        got = _cmp_at(words, k)
        if got is not None:
            op0, k2 = got
            if k2 < n and words[k2] in _ATTRS:
                op, attr, k = op0, _ATTRS[words[k2]], k2 + 1
            elif words[k2 - 1] in _IMPLIED or (k2 >= 2 and words[k2 - 2] in _IMPLIED):
                imp = words[k2 - 1] if words[k2 - 1] in _IMPLIED else words[k2 - 2]
                op, attr, k = op0, _IMPLIED[imp], k2
    if op is not None and attr is not None:
        # StructFormer's "objects that have the same color as the X" / "equal
        # height as the X" leave the X out (it is the anchor of the query);
        # LGMCTS-D's "whose color is ... X", "with/of/has the same color as X"
        # put it in.
        if op == "eq" and words[i] in ("that", "which") and any(w in ("have", "has") for w in words[i:j]):
            op = "eqx"
        while k < n and words[k] in _PREP:
            k += 1
        ref = _mention_at(vocab, words, k, pattern_words, nested=True)
        if ref is None:
            raise InputError(f"'{' '.join(words[i:k + 2])}': the reference object names nothing in the scene")
        return (attr, op, ref), ref.end
    # [is|are] [not] VALUE: a colour or a category ("that are red", "that are mug").
    if words[j - 1] in ("is", "are") or (j < n and words[j] in ("is", "are")):
        k = j + (1 if j < n and words[j] in ("is", "are") else 0)
        neg = False
        if k < n and words[k] in ("not", "n't", "neither"):
            neg, k = True, k + 1
        if k < n and words[k] in ("a", "an"):
            k += 1
        cols = _colors(vocab, words, k)
        cat = None
        if cols is not None:
            k = cols[1]
        if k < n:
            cat = vocab.longest(vocab.categories, words, k)
        if cols is None and cat is None:
            return None
        names = None
        if cat is not None:
            names = vocab.categories[cat[0]][0]
            k = cat[1]
            while neg and cols is None:
                # "not a can or a bowl", "neither letters nor blocks", "not a can and not a bowl"
                k2 = k
                if k2 < n and words[k2] == ",":
                    k2 += 1
                if _starts(words, k2, ("and", "not")) or _starts(words, k2, ("or", "not")):
                    k2 += 2
                elif k2 < n and words[k2] in ("or", "nor"):
                    k2 += 1
                else:
                    break
                if k2 < n and words[k2] in ("a", "an", "the"):
                    k2 += 1
                more = vocab.longest(vocab.categories, words, k2) if k2 < n else None
                if more is None:
                    break
                names, k = names | vocab.categories[more[0]][0], more[1]
        elif k < n and words[k] in GENERIC:
            k += 1
        value = Mention(j, k, " ".join(words[j:k]), "all", True, names, cols[0] if cols else None,
                        cols[0] if cols else ())
        return ("value", "ne" if neg else "eq", value), k
    return None


_ID_HEADS = frozenset({"object", "objects", "obj", "id", "ids", "item", "items", "number", "no"})
_PRONOUNS = frozenset({"them", "it", "they", "those", "these"})
_COORD = frozenset({"and", ",", "or", "&", "plus"})


#: Words after "those" / "these" that show it stands alone ("put those in a row").
_AFTER_PRONOUN = frozenset({"in", "into", "up", "out", "on", "onto", "together", "around", "behind", "to", "next", "beside",
                            "along", "as", "and", ",", ".", "!", "?", ";", ":", "please", "for", "so", "side", "one",
                            "down", "over", "under", "at", "neatly", "too"})
_PUT_VERBS = lexicon.COMMAND_VERBS


def _starts(words: tuple[str, ...], i: int, seq: tuple[str, ...]) -> bool:
    return words[i : i + len(seq)] == seq


def _number(words: tuple[str, ...], i: int) -> tuple[int, int] | None:
    for phrase, n in NUMBERS.items():
        seq = tuple(phrase.split())
        if _starts(words, i, seq):
            return n, i + len(seq)
    if i < len(words) and re.fullmatch(r"\d+", words[i]):
        return int(words[i]), i + 1
    return None


def _ids(words: tuple[str, ...], i: int) -> tuple[tuple[int, ...], int] | None:
    """"object 7", "objects 3, 4 and 5", "#7", "object number 7"."""
    j = i
    if j < len(words) and words[j] == "the":
        j += 1
    if j < len(words) and words[j] in ("object", "objects", "obj", "item", "items") and j + 1 < len(words):
        j += 1
        if words[j:j + 2] in (("with", "id"), ("with", "ids")):
            j += 2
    elif j < len(words) and words[j] in ("id", "ids"):
        j += 1
    elif not (j < len(words) and words[j] == "#"):
        return None
    if j < len(words) and words[j] in ("number", "no", "#", "numbers"):
        j += 1
    ids: list[int] = []
    while j < len(words):
        if words[j] == "#":
            j += 1
        if j < len(words) and re.fullmatch(r"\d+", words[j]):
            ids.append(int(words[j]))
            j += 1
        else:
            break
        k = j
        while k < len(words) and words[k] in _COORD:
            k += 1
        if k > j and k < len(words) and (re.fullmatch(r"\d+", words[k]) or words[k] == "#"):
            j = k
            continue
        break
    return (tuple(ids), j) if ids else None


def _one_colour(vocab: Vocabulary, words: tuple[str, ...], i: int) -> tuple[str, int] | None:
    """One colour at ``i``: a scene colour, or words of one ("swirl", "polka dot").

    The scene's colours are matched longest first; a longer run of words that
    all occur in the scene's colours ("blue stripe" for "green and blue
    stripe") is kept as a partial colour, resolved in :func:`candidates`.
    """
    got = vocab.longest(vocab.colors, words, i)
    j = i
    while j < len(words) and _COLOUR_FORMS.get(words[j], words[j]) in vocab.color_words:
        j += 1
    if got is not None and got[1] >= j:
        return vocab.colors[got[0]], got[1]
    if j > i:
        return " ".join(_COLOUR_FORMS.get(w, w) for w in words[i:j]), j
    return None


def _colors(vocab: Vocabulary, words: tuple[str, ...], i: int) -> tuple[tuple[str, ...], int] | None:
    """A colour or a list of colours ("red, blue and green") starting at ``i``."""
    got = _one_colour(vocab, words, i)
    if got is None:
        return None
    out = [got[0]]
    j = got[1]
    while True:
        k = j
        while k < len(words) and words[k] in _COORD:
            k += 1
        if k == j:
            break
        nxt = _one_colour(vocab, words, k)
        if nxt is None or nxt[0] in out:
            break  # a colour named again starts another reference ("purple, red and green, purple lowest")
        out.append(nxt[0])
        j = nxt[1]
    if j < len(words) and words[j] in ("colored", "coloured", "color", "colour"):
        j += 1
    return tuple(out), j


def _mention_at(
    vocab: Vocabulary, words: tuple[str, ...], i: int, pattern_words: frozenset[str], *, nested: bool = False
) -> Mention | None:
    n = len(words)
    # Explicit ids.
    got = _ids(words, i)
    if got is not None:
        ids, j = got
        return Mention(i, j, " ".join(words[i:j]), "ids", len(ids) > 1, ids=ids)
    if not nested and i + 2 < n and words[i + 1] == "of" and words[i + 2] in ("them", "those", "these") and (
            words[i] == "one" or words[i] in NUMBERS):
        # "one of them", "two of those": a choice among what the pronoun refers to.
        k = 1 if words[i] == "one" else NUMBERS[words[i]]
        return Mention(i, i + 3, " ".join(words[i : i + 3]), "pronoun", k > 1, count=k)
    if not nested and (words[i] in ("those", "these") or (words[i] == "all" and i > 0 and words[i - 1] in _PUT_VERBS)) and (
            i + 1 == n or words[i + 1] in _AFTER_PRONOUN):
        # "put those in a row", "line these up", "put all in a line": what was named before.
        return Mention(i, i + 1, words[i], "pronoun", True)
    det, j = "", i
    for seq, kind in _DETS:
        if _starts(words, i, seq):
            det, j = kind, i + len(seq)
            break
    if det == "the" and j < n and words[j] == "same" and j + 1 < n and words[j + 1] not in ("color", "colour", "shape",
                                                                                        "size", "as"):
        j += 1  # "the same can": the can named before (resolved by the parser)
    non = None
    if j + 1 < n and words[j] == "non":
        got_c = _colors(vocab, words, j + 1)
        if got_c is not None:  # "the non-red cans": every can but the red ones
            non = got_c[0]
            j = got_c[1]
    count = None
    num = _number(words, j)
    if num is not None and det == "one" and words[j - 2 : j] == ("of", "the"):
        # "one of the three bowls": one, out of a group said to have three.
        of_count, j = num
        num = None
    if num is not None and (det in ("", "the", "all", "other", "another") or (det == "one" and words[i] == "a")):
        count, j = num
        of_count = None
        if _starts(words, j, ("of", "the")):
            j += 2
            got_n = _number(words, j)
            if got_n is not None:  # "two of the three cans"
                of_count, j = got_n
        elif det == "the" and not nested:
            of_count = count  # "the three cans" presupposes exactly three: refused when four match
        det = "count" if det in ("", "the", "one") else det
        if j < n and words[j] in ("other", "more", "additional", "different", "remaining", "new", "further"):
            j += 1  # "three other blocks": three not named before
            det = "fresh" if det == "count" else det
        if det == "all":  # "all three blocks" names them all
            count = None
        if det == "another":  # "another three blocks": three not named before
            det = "fresh"
    if det == "" and j < n and words[j] in _PRONOUNS and not nested:
        return Mention(i, j + 1, words[j], "pronoun", True)

    if det in ("the", "all", "other") and j < n and words[j] in ("rest", "others", "remaining"):
        end = j + 1
        return Mention(i, end, " ".join(words[i:end]), "other", True)
    everything = None
    if det == "" and _starts(words, j, ("everything", "else")):
        everything, det, end = "other", "other", j + 2
    elif det == "" and j < n and words[j] in ("everything", "anything"):
        everything, det, end = "all", "all", j + 1
    if everything and end < n and words[end] in COLOUR_WORDS and _one_colour(vocab, words, end) is None:
        # "everything purple" with nothing purple: not everything.
        raise InputError(f"nothing in the scene matches '{' '.join(words[i:end + 1])}' (no {words[end]} object)")
    head = ""
    loose = everything == "all"  # "everything red" takes the red swirl heart too
    cols = None if everything else _colors(vocab, words, j)
    colors, color_order = None, ()
    if cols is not None:
        colors, j = cols
        color_order = colors
    cat = vocab.longest(vocab.categories, words, j) if j < n and not everything else None
    names: frozenset[str] | None
    if everything:
        names, plural = None, True
    elif cat is not None:
        key, end = cat
        names, plural = vocab.categories[key]
        # "in a square", "into a ring": the word names a pattern, not an object.
        if colors is None and det in ("one", "") and _pattern_context(words, j):
            return None  # "in a square", "into a ring", "in a star shape": a shape, not an object
    elif j < n and words[j] in GENERIC:
        if words[j] in ("one", "ones") and colors is None and det not in ("the", "other", "another"):
            return None
        names, plural, end = None, words[j].endswith("s") or words[j] == "stuff", j + 1
        loose = words[j] in _LOOSE_NOUNS
        if words[j] in ("one", "ones") and (colors is not None or det == "other"):
            head = "one"
    elif colors is None and det == "other" and words[i] == "the" and not nested and (j >= n or words[j] not in _COORD):
        # "the other" with no noun: the other one of a pair named before it.
        names, plural, end, head = None, False, j, "one"
    elif colors is not None and det in ("all", "other"):
        names, plural, end = None, True, j
    elif colors is not None:
        # A colour followed by a word naming nothing here: "the purple giraffe".
        k = j
        while k < n and words[k] not in _COORD and words[k] not in pattern_words and k - j < 2 and words[k].isalpha():
            if words[k] in _NOT_NOUN or words[k] in STOPWORDS:
                break
            k += 1
        coordinated = (j < n and words[j] in _COORD) or (i > 0 and words[i - 1] in _COORD)
        if k == j and (coordinated or det == "the") and det in ("the", "all", "both", "other", "") and not nested:
            # "the red and the blue blocks", "the red block and the blue": the
            # noun is shared with a coordinated neighbour (resolved in find_mentions);
            # "..., then the yellow" takes the noun of the mentions around it.
            return Mention(i, j, " ".join(words[i:j]), det or "the", False, None, colors, color_order,
                           head="elided")
        if k == j and det == "" and not nested and len(colors) > 1 and all(
                sum(c == oc for _, _, oc in vocab.objects) == 1 for c in colors):
            # "purple, orange, yellow": each colour is the one object that has it.
            return Mention(i, j, " ".join(words[i:j]), "all", True, None, colors, color_order)
        if k == j and det == "" and not nested and not (j < n and words[j] in _COORD):
            # A bare colour standing for its object ("stack red on blue"): the
            # one object of that colour; where more objects have it, the noun
            # comes from the rest of the command ("stack the cans: green first").
            several = len(colors) > 1  # "red, blue, white": one object per colour
            m = Mention(i, j, " ".join(words[i:j]), "all" if several else "the", several, None, colors, color_order)
            if several:
                return m if len(_colour_only(vocab, m)) == len(colors) else replace(m, head="elided")
            return m if len(_colour_only(vocab, m)) <= 1 else replace(m, head="elided")
        phrase = " ".join(words[i:k])
        raise InputError(f"'{phrase}' names nothing in the scene")
    else:
        return None
    if det == "vague":
        raise InputError(f"'{' '.join(words[i:end])}' does not say how many; name them, give a number or say all")
    if det == "both" and not plural:
        det = "the"
    if det == "" or (det == "the" and plural):
        det = "all" if plural else "the"
    if det == "count" and count == 1:
        det = "one"
    m = Mention(i, end, " ".join(words[i:end]), det, plural, names, colors, color_order, count=count, head=head,
                of_count=locals().get("of_count"), loose=loose)
    if non is not None:
        m = replace(m, filters=(("value", "ne", Mention(i, end, "non " + " ".join(non), "all", True, None, non, non)),))
    if (names is None and words[end - 1] in ("piece", "pieces", "item", "items", "bit", "bits") and end + 1 < n
            and words[end] == "of" and words[end + 1].isalpha()
            and words[end + 1] not in _OF_OK and _COLOUR_FORMS.get(words[end + 1], words[end + 1]) not in vocab.color_words
            and vocab.longest(vocab.categories, words, end + 1) is None):
        # "every piece of fruit": a kind the scene does not have (not every object).
        raise InputError(f"'{' '.join(words[i:end + 2])}' names nothing in the scene")
    # Qualifiers.
    while end < n:
        if everything is not None and m.colors is None and not m.filters:
            cols2 = _colors(vocab, words, end)  # "anything blue", "everything white"
            if cols2 is not None:
                end = cols2[1]
                m = replace(m, end=end, text=" ".join(words[i:end]), colors=cols2[0], color_order=cols2[0])
                continue
        aq = _attr_qualifier(vocab, words, end, pattern_words) if not nested else None
        if aq is not None:
            f, end = aq
            if m.det == "other" and f[1] == "eq":
                f = (f[0], "eqx", f[2])  # "everything else that is the same colour as the X": not the X
            m = replace(m, end=end, text=" ".join(words[i:end]), filters=m.filters + (f,))
            continue
        q = next((s for s in _SAME_COLOR if _starts(words, end, s)), None)
        if q is not None:
            ref = _mention_at(vocab, words, end + len(q), pattern_words, nested=True)
            if ref is None:
                raise InputError(f"'{' '.join(words[i:end + len(q) + 2])}': the colour reference names nothing in the scene")
            end = ref.end
            m = replace(m, end=end, text=" ".join(words[i:end]), same_color_as=ref)
            continue
        q = next((s for s in _EXCEPT if _starts(words, end, s)), None)
        if q is None and not nested and m.plural and end + 1 < n and words[end] == ",":
            # "the cans, minus the green one, in a line": the exception set off by commas.
            q = next((s for s in _EXCEPT if s not in (("but",), ("without",)) and _starts(words, end + 1, s)), None)
            if q is not None:
                end += 1
        if q is not None:
            k = end + len(q)
            excl: list[Mention] = []
            while True:
                e = _bare_excluded(vocab, words, k, m) or _mention_at(vocab, words, k, pattern_words, nested=True)
                if e is None:
                    break
                excl.append(e)
                k = e.end
                kk = k
                while kk < n and words[kk] in _COORD:
                    kk += 1
                if kk == k:
                    break
                e2 = _bare_excluded(vocab, words, kk, m) or _mention_at(vocab, words, kk, pattern_words, nested=True)
                if e2 is None:
                    break
                if m.names and e2.names and not set(m.names) & set(e2.names):
                    # "the bowls except the white one, and the phone": nothing of another kind is left out
                    # of the bowls, so the phone is one more object of the list.
                    break
                k = kk
            if not excl:
                if q[0] in ("but", "without"):
                    break
                raise InputError(f"'{' '.join(words[i:k + 2])}': cannot tell what to leave out")
            end = k
            m = replace(m, end=end, text=" ".join(words[i:end]), excluding=m.excluding + tuple(excl))
            continue
        break
    if (not nested and m.det in ("all", "other") and m.plural and end < n
            and words[end] in ("that", "which", "whose", "matching", "sharing", "shares", "share", "matches", "match")
            and not (words[end] == "that" and end + 1 < n and words[end + 1] in ("way", "is", "it", "order"))):
        # "all the blocks that aren't, like, red": a qualifier not read would select them all.
        raise InputError(f"'{' '.join(words[i:min(n, end + 4)])}': cannot tell which objects the words after "
                         f"'{words[end - 1]}' select")
    return m


def _bare_excluded(vocab: Vocabulary, words: tuple[str, ...], k: int, outer: Mention) -> Mention | None:
    """"all the blocks except the purple and the orange (ones)": a colour with no noun after an
    exception takes the noun of the objects it is left out of."""
    if outer.names is None:
        return None
    j = k + (1 if k < len(words) and words[k] == "the" else 0)
    got = _colors(vocab, words, j)
    if got is None:
        return None
    colors, end = got
    if end < len(words) and words[end] in ("one", "ones"):
        end += 1
    elif end < len(words) and words[end] not in _COORD and words[end].isalpha() and words[end] not in _NOT_NOUN \
            and words[end] not in ("go", "goes", "in", "into", "should", "are", "is"):
        return None  # "except the red block": an ordinary reference
    return Mention(k, end, " ".join(words[k:end]), "all", True, outer.names, colors, colors)


def find_mentions(vocab: Vocabulary, words: tuple[str, ...], pattern_words: frozenset[str],
                  context: tuple[frozenset[str], ...] = ()) -> list[Mention]:
    """Every object reference in ``words``, left to right, non-overlapping.

    ``context``: the object nouns of the command's earlier clauses, latest
    first; a bare colour with no noun in its own clause takes the first of
    them that some object of that colour has ("stack the cans: green first,
    then white").
    """
    out: list[Mention] = []
    i = 0
    while i < len(words):
        m = _mention_at(vocab, words, i, pattern_words)
        if m is not None and m.end > i:
            out.append(m)
            i = m.end
        else:
            i += 1
    return _shared_exception(words, _share_heads(vocab, words, out, context))


def _shared_exception(words: tuple[str, ...], mentions: list[Mention]) -> list[Mention]:
    """"all the cans and bowls, except for the white ones": an exception said
    after a list of plural references leaves its colour out of every one of
    them when the last reference shares the list's determiner or a comma sets
    the exception off; otherwise it belongs to the last reference alone."""
    out = list(mentions)
    for run in _coordinated_runs(words, mentions):
        k, j = run[0], run[-1]
        last = out[j]
        bare = [e for e in last.excluding if e.names is last.names and e.names is not None and e.det == "all"
                and not e.excluding]
        if j > k and bare and len(bare) == len(last.excluding) and all(
                m.plural and m.det in ("all", "the") and not m.excluding and m.names is not None
                for m in out[k:j]) and (
                words[last.start] not in ("the", "all", "every", "each", "both")
                or "," in words[last.start : last.excluding[0].start]):
            for t in range(k, j):
                m = out[t]
                out[t] = replace(m, excluding=tuple(replace(e, names=m.names) for e in bare))
    return out


def _coordinated(words: tuple[str, ...], a: Mention, b: Mention) -> bool:
    between = words[a.end : b.start]
    return bool(between) and all(w in _COORD for w in between)


def _coordinated_runs(words: tuple[str, ...], mentions: list[Mention]) -> list[list[int]]:
    """Indices of ``mentions`` grouped into runs joined only by "and", commas, "or" ("the cans and bowls")."""
    groups: list[list[int]] = []
    for k, m in enumerate(mentions):
        if groups and _coordinated(words, mentions[groups[-1][-1]], m):
            groups[-1].append(k)
        else:
            groups.append([k])
    return groups


def _share_heads(vocab: Vocabulary, words: tuple[str, ...], mentions: list[Mention],
                 context: tuple[frozenset[str], ...] = ()) -> list[Mention]:
    """Give elided and "one" mentions the category of a coordinated neighbour.

    An elided mention ("the red" in "the red and the blue blocks") takes the
    noun of the next mention of its list that has one, else of the previous
    one ("the red block and the blue"); "the green one" looks back first
    ("the red block and the green one"), then ahead ("the red one and the
    green block"). A plural noun makes "the red" plural ("the red and the
    blue blocks": every red block and every blue block). A neighbour whose
    noun selects nothing with these colours is passed over ("the red one and
    the blue one and the green bowl": the red one is not a bowl); "the red
    one" with no such neighbour keeps any category. An elided mention with
    no noun in its list names nothing.
    """
    groups = _coordinated_runs(words, mentions)
    out = list(mentions)
    for g in groups:
        for pos, k in enumerate(g):
            m = mentions[k]
            if not m.head:
                continue
            # A neighbour with a noun; for a bare colour also a generic one ("the
            # red and the white objects": every red object and every white one).
            def nouned(x: Mention) -> bool:
                return not x.head and (x.names is not None or (m.head == "elided" and x.plural and x.det == "all"
                                                                and not x.ids and x.colors is not None))

            later = [mentions[x] for x in g[pos + 1 :] if nouned(mentions[x])]
            earlier = [mentions[x] for x in reversed(g[:pos]) if nouned(mentions[x])]
            order = later + earlier if m.head == "elided" else earlier + later
            if not order and m.head == "one":
                # "stack the red block on the blue one": the nearest noun before it,
                # else one named in an earlier clause ("there are two bottles. the white one ...").
                order = [x for x in reversed(mentions[:k]) if not x.head and x.names is not None]
                if not order and m.det not in ("other", "another"):
                    order = [replace(m, names=n, head="") for n in context if _any_match(vocab, replace(m, names=n))][:1]
            if not order and m.head == "elided":
                # "the red, green and blue blocks with red at the bottom and blue on
                # top": a bare colour takes the noun of the nearest mention before it
                # that has one (else after it), when some object has both.
                order = [x for x in reversed(mentions[:k]) if not x.head and x.names is not None] + [
                    x for x in mentions[k + 1:] if not x.head and x.names is not None]
                order = [x for x in order if _any_match(vocab, replace(m, names=x.names))][:1]
                if not order:
                    order = [replace(m, names=n, head="") for n in context
                             if _any_match(vocab, replace(m, names=n))][:1]
                if not order and not m.plural and m.count is None and len(_colour_only(vocab, m)) == 1:
                    # "yellow first, then orange": a colour that only one object has.
                    order = [replace(m, names=None, head="")]
            if not order:
                if m.head == "elided" and m.det == "the" and len(_colour_only(vocab, m)) > 1:
                    hits = _colour_only(vocab, m)
                    raise InputError(f"'{m.text}' is ambiguous: it matches objects {describe(vocab, hits)}")
                if m.head == "elided":
                    raise InputError(f"'{m.text}' names nothing in the scene (no object noun goes with it)")
                continue
            options = []
            for src in order:
                plural = m.plural or (m.head == "elided" and src.plural)
                det = "all" if plural and m.det == "the" else m.det
                options.append(Mention(m.start, m.end, m.text, det, plural, src.names, m.colors, m.color_order,
                                       count=m.count, same_color_as=m.same_color_as, excluding=m.excluding,
                                       head=m.head))
            fits = [o for o in options if _any_match(vocab, o)]
            if fits:
                out[k] = fits[0]
            elif m.head == "elided":
                out[k] = options[0]  # refused later: "nothing in the scene matches 'the red'"
    return out


#: Words after a colour that are no noun of it ("red first", "purple as the base").
_NOT_NOUN = frozenset({"to", "in", "into", "on", "of", "at", "behind", "and", "as", "first", "then", "last", "next",
                       "second", "third", "goes", "go", "should", "is", "are", "be", "up", "down", "under", "below",
                       "above", "beneath", "underneath", "with", "lowest", "highest", "bottom", "top", "base", "onto",
                       "over", "atop", "upon", "so", "must", "will", "sits", "comes", "left", "right", "front",
                       "crowning", "next", "finally", "lowest", "highest"})


#: Generic nouns of everyday speech (not the peers' "objects").
#: Words after "pieces of" that do not name a kind ("pieces of the set", "items of the same colour").
_OF_OK = frozenset({"the", "a", "an", "all", "each", "every", "these", "those", "them", "it", "my", "your", "our", "one",
                    "two", "three", "four", "five", "six", "same", "any", "its", "their", "this", "that", "colour", "color"})
_LOOSE_NOUNS = frozenset({"things", "thing", "items", "item", "stuff", "ones", "pieces", "piece"})


def _colour_only(vocab: Vocabulary, m: Mention) -> list[int]:
    """The objects with the mention's colours, of any category."""
    try:
        return list(candidates(vocab, replace(m, names=None, head="", same_color_as=None, excluding=(), det="all")))
    except InputError:
        return []


def _any_match(vocab: Vocabulary, m: Mention) -> bool:
    """Whether some object has the mention's category and colours (exactly or in part)."""
    try:
        return bool(candidates(vocab, replace(m, same_color_as=None, excluding=(), det="all")))
    except InputError:
        return False


def describe(vocab: Vocabulary, ids: list[int] | tuple[int, ...]) -> str:
    """"5 (white bottle), 10 (blue bottle)"."""
    return ", ".join(f"{i} ({vocab.label(i)})" for i in ids)


def candidates(vocab: Vocabulary, m: Mention, *, named: frozenset[int] = frozenset(), inherit: frozenset[str] | None = None) -> list[int]:
    """Ids the mention's category, colours and qualifiers allow (before quantity)."""
    known = {i for i, _, _ in vocab.objects}
    if m.det == "ids":
        bad = [i for i in m.ids if i not in known]
        if bad:
            raise InputError(f"'{m.text}': the scene has no object with id {bad[0]}")
        return list(m.ids)
    names = m.names if m.names is not None else inherit
    out = [
        i for i, n, c in vocab.objects
        if (names is None or n in names) and (m.colors is None or c in m.colors)
    ]
    if out and m.colors is not None and m.loose and (m.plural or m.det == "all"):
        # "all the red things": everyday words take the red swirl heart too;
        # "red objects" (the peers' word) keeps exact colours.
        firsts = {colour_words(c)[0] for c in m.colors if len(colour_words(c)) == 1}
        out = sorted(set(out) | {i for i, n, c in vocab.objects if (names is None or n in names)
                                 and len(colour_words(c)) > 1 and colour_words(c)[0] in firsts})
    if not out and m.colors is not None:
        # No exact colour: the colour words given may be part of the object's
        # colour ("the swirl flower" for a red swirl flower; every word given
        # must be in it).
        wanted = [set(colour_words(c)) for c in m.colors]
        out = [
            i for i, n, c in vocab.objects
            if (names is None or n in names) and any(w <= set(colour_words(c)) for w in wanted)
        ]
    if m.same_color_as is not None:
        ref = select(vocab, m.same_color_as, named=named)
        if isinstance(ref, Choice):
            raise InputError(f"'{m.same_color_as.text}' must name a definite object to compare colours with")
        ref_colors = {c for i, _, c in vocab.objects if i in ref}
        if len(ref_colors) != 1:
            raise InputError(f"'{m.same_color_as.text}' has several colours ({', '.join(sorted(ref_colors))})")
        (rc,) = ref_colors
        # As in the peers' object selectors, the reference object itself is
        # one of "the objects whose color is the same as X".
        out = [i for i in out if any(c == rc for j, _, c in vocab.objects if j == i)]
        if m.det == "other":
            # "everything else with the bottle's colour", "the other things of its colour": "else"
            # and "other" leave the reference object out.
            out = [i for i in out if i not in ref]
    for f in m.filters:
        out = _apply_filter(vocab, f, out, named)
    for e in m.excluding:
        ex = candidates(vocab, e, named=named, inherit=names)
        out = [i for i in out if i not in ex]
    if m.det in ("other", "another", "fresh"):
        out = [i for i in out if i not in named]
    if m.color_order and len(m.color_order) > 1:
        rank = {c: k for k, c in enumerate(m.color_order)}
        color = {i: c for i, _, c in vocab.objects}
        out.sort(key=lambda i: (rank.get(color[i], 99), i))
    return out


def _apply_filter(vocab: Vocabulary, f: tuple, out: list[int], named: frozenset[int]) -> list[int]:
    attr, op, ref = f
    if attr == "value":
        vals = set(candidates(vocab, ref, named=named)) if _any_match(vocab, ref) else set()
        return [i for i in out if (i in vals) == (op == "eq")]
    if attr in ("color", "name"):
        # "the same shape as heart" with several hearts: they share the value.
        col = 2 if attr == "color" else 1
        refs = candidates(vocab, ref, named=named)
        if not refs:
            raise InputError(f"nothing in the scene matches '{ref.text}'")
        values = {o[col] for o in vocab.objects if o[0] in refs}
        if len(values) != 1:
            raise InputError(f"'{ref.text}' is ambiguous: it matches objects {describe(vocab, refs)} "
                             f"of different {'colours' if attr == 'color' else 'kinds'}")
        (rv,) = values
        same = {o[0] for o in vocab.objects if o[col] == rv}
        if op == "eqx":
            return [i for i in out if i in same and i not in refs]
        return [i for i in out if (i in same) == (op == "eq")]
    sel = select(vocab, ref, named=named)
    if isinstance(sel, Choice) or len(sel) != 1:
        raise InputError(f"'{ref.text}' must name one definite object to compare with")
    (r,) = sel
    if op == "eqx":
        out = [i for i in out if i != r]
        op = "eq"
    k = {"height": 1, "volume": 2, "width": 3}[attr]
    meas = {x[0]: x[k] for x in vocab.measures}
    rv = meas.get(r, 0.0)

    def rel(v: float) -> str:
        if abs(v - rv) <= MEASURE_TOL * max(abs(v), abs(rv), 1e-9):
            return "eq"
        return "lt" if v < rv else "gt"

    keep = {"eq": ("eq",), "ne": ("lt", "gt"), "lt": ("lt",), "gt": ("gt",), "le": ("lt", "eq"), "ge": ("gt", "eq")}[op]
    return [i for i in out if rel(meas.get(i, 0.0)) in keep]


def select(vocab: Vocabulary, m: Mention, *, named: frozenset[int] = frozenset()) -> list[int] | Choice:
    """Resolve a mention to fixed ids, or to a :class:`Choice` for "one X"/"three X".

    Raises
    ------
    InputError
        Empty selection, ambiguity ("the bottle" with two bottles) or too few
        objects for a count.
    """
    if m.det == "pronoun":
        raise InputError(f"'{m.text}' refers to nothing before it")
    ids = candidates(vocab, m, named=named)
    if not ids:
        raise InputError(f"nothing in the scene matches '{m.text}'")
    if m.of_count is not None and len(ids) != m.of_count:
        raise InputError(f"'{m.text}' speaks of {m.of_count}, but {len(ids)} objects match: {describe(vocab, ids)}")
    if m.det in ("all", "ids"):
        return ids
    if m.det == "other":
        if m.plural:
            return ids
        if len(ids) > 1:
            raise InputError(f"'{m.text}' is ambiguous: it matches objects {describe(vocab, ids)}")
        return ids
    if m.det in ("the", "") and m.colors is not None and len(m.colors) == len(ids) > 1 and len({
            c for i, _, c in vocab.objects if i in ids}) == len(ids):
        # "the red, blue and green block": one block of each colour named.
        return ids
    if m.det == "the":
        if len(ids) > 1:
            raise InputError(
                f"'{m.text}' is ambiguous: it matches objects {describe(vocab, ids)}; say which one (e.g. by colour or id)"
            )
        return ids
    if m.det == "both":
        if len(ids) != 2:
            raise InputError(f"'{m.text}' says both, but {len(ids)} objects match: {describe(vocab, ids)}")
        return ids
    if m.det == "half":
        if len(ids) % 2:
            raise InputError(f"'{m.text}': half of {len(ids)} objects is not a whole number")
        return Choice(tuple(ids), len(ids) // 2, m.text)
    k = 1 if m.det in ("one", "another") else int(m.count or 1)
    fresh = m.det in ("another", "fresh")
    if k < 1:
        raise InputError(f"'{m.text}' asks for no object")
    if len(ids) < k:
        raise InputError(f"'{m.text}' asks for {k} objects but only {len(ids)} match: {describe(vocab, ids)}")
    if len(ids) == k and not fresh:
        return ids
    return Choice(tuple(ids), k, m.text, fresh)
