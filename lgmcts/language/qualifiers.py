"""Attribute clauses after a noun ("whose colour is the same as the heart", "that are taller than the mug",
"that are not red"): a small grammar of attribute, comparison and reference (:func:`_attr_qualifier`).
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from ..errors import InputError
from .vocabulary import GENERIC, Mention, Vocabulary, _colors, _starts

if TYPE_CHECKING:
    from collections.abc import Callable


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


def _cmp_at(words: tuple[str, ...], i: int) -> tuple[str, int] | None:
    neg = False
    if i < len(words) and words[i] in ("not", "isn't", "aren't", "n't"):
        neg, i = True, i + 1
    for seq, op in _CMP:
        if _starts(words, i, seq):
            return (_NEG[op] if neg else op), i + len(seq)
    return None


#: Words of a match that may leave the attribute unsaid (then colour): "matching the green bowl".
_MATCH_WORDS = frozenset({"matching", "matches", "match"})


def _colour_match(words: tuple[str, ...], k: int) -> bool:
    """Whether ``words[k]`` is a match word followed right away by a reference ("matching the green bowl")."""
    return (k + 1 < len(words) and words[k] in _MATCH_WORDS
            and words[k + 1] in ("the", "a", "an", "any", "one", "either", "each", "some"))


def _attr_qualifier(vocab: Vocabulary, words: tuple[str, ...], i: int, pattern_words: frozenset[str],
                    reference: Callable[..., Mention | None]):
    """An attribute clause after a noun: ``((attribute, op, reference), end)`` or None. ``reference`` reads
    the reference object at a word (:func:`.mentions._mention_at`, called with ``nested=True``).

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
        if not implied and (got[1] >= n or words[got[1]] not in _ATTRS) and not _colour_match(words, j):
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
    implied_match = op is None and _colour_match(words, k)
    if implied_match:
        # "the can matching the green bowl", "the bowl that matches one of the mugs (in colour)": objects told
        # apart by colour only, so a match with no attribute said is a match of colour.
        op, attr, k = "eq", "color", k + 1
    if op is not None and attr is not None:
        # StructFormer's "objects that have the same color as the X" / "equal
        # height as the X" leave the X out (it is the anchor of the query);
        # LGMCTS-D's "whose color is ... X", "with/of/has the same color as X"
        # put it in.
        if op == "eq" and words[i] in ("that", "which") and any(w in ("have", "has") for w in words[i:j]):
            op = "eqx"
        while k < n and words[k] in _PREP:
            k += 1
        ref = reference(vocab, words, k, pattern_words, nested=True)
        if ref is None:
            raise InputError(f"'{' '.join(words[i:k + 2])}': the reference object names nothing in the scene")
        end = ref.end
        if attr == "color" and words[end : end + 2] in (("in", "colour"), ("in", "color")):
            end += 2
        if (implied_match and end + 1 < n and words[end] in ("and", "or") and words[end + 1] in ("the", "a", "an")
                and reference(vocab, words, end + 1, pattern_words, nested=True) is not None):
            # "the letters matching the red block and the green block": a second object to match, or a second
            # object to arrange? Either reading is a guess.
            raise InputError(f"'{' '.join(words[i:end + 4])}': cannot tell whether what follows '{words[end]}' is "
                             f"matched too or arranged too; say 'matching either of them' or name "
                             f"the objects")
        return (attr, op, ref), end
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
