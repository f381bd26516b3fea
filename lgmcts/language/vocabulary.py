"""What grounding reads a command against: its tokens (:func:`tokenize`), the scene's own words
(:class:`Vocabulary`: names with plurals and synonyms, colours, measures), the word tables of object
references (synonyms, group nouns, generic nouns, numbers) and the two forms a reference takes
(:class:`Mention`, :class:`Choice`), with the colour readers both the mentions and their qualifiers use.
"""

from __future__ import annotations

from dataclasses import dataclass
import re

from . import lexicon
from ..formats import SceneSpec
from .ir import Token


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
#: Group nouns that name all their objects said in the singular ("the silverware", "the cutlery").
_MASS = frozenset({"silverware", "cutlery", "flatware", "dishware", "crockery", "tableware", "drinkware"})


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
                    # "the container matching the cup" is one object; "the silverware" (a mass noun) all of it
                    add(form, next(iter(hit)), form != gw or group in _MASS)
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


_COORD = frozenset({"and", ",", "or", "&", "plus"})


def _starts(words: tuple[str, ...], i: int, seq: tuple[str, ...]) -> bool:
    return words[i : i + len(seq)] == seq


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
