"""Finding the object references of a clause (:func:`find_mentions`): one mention at a word
(:func:`_mention_at`: ids, pronouns, determiner and count, colours and category, qualifiers and
exceptions), then nouns shared by coordinated colours and exceptions shared by a list.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
import re

from . import lexicon
from ..errors import InputError
from .matcher import STOPWORDS
from .qualifiers import _attr_qualifier
from .resolve import _any_match, _colour_only, describe
from .vocabulary import (
    COLOUR_WORDS,
    GENERIC,
    Mention,
    NUMBERS,
    Vocabulary,
    _COLOUR_FORMS,
    _COORD,
    _colors,
    _one_colour,
    _pattern_context,
    _starts,
)


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
         "leaving out", "not counting", "with the exception of", "aside from", "barring", "bar", "but for"],
        key=lambda s: -len(s),
    )
)


_PRONOUNS = frozenset({"them", "it", "they", "those", "these"})


#: Words after "those" / "these" that show it stands alone ("put those in a row").
_AFTER_PRONOUN = frozenset({"in", "into", "up", "out", "on", "onto", "together", "around", "behind", "to", "next", "beside",
                            "along", "as", "and", ",", ".", "!", "?", ";", ":", "please", "for", "so", "side", "one",
                            "down", "over", "under", "at", "neatly", "too"})


_PUT_VERBS = lexicon.COMMAND_VERBS


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


def _standalone(words: tuple[str, ...], i: int, nested: bool) -> Mention | None:
    """A reference that stands alone at ``i``: ids ("object 7", "objects 3, 4 and 5"), "one of them" / "two of
    those" and a bare "those" / "these" / "all" after a verb; None where none starts there."""
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
    return None


def _quantity(vocab: Vocabulary, words: tuple[str, ...], i: int,
              nested: bool) -> tuple[str, int, tuple[str, ...] | None, int | None, int | None]:
    """The determiner at ``i`` and the count after it: ``(det, j, non, count, of_count)`` with ``j`` the
    first word after them, ``non`` the colours of "non-red", ``count`` a number said ("three blocks") and
    ``of_count`` the size of the group it is taken from ("two of the three cans", "the three cans")."""
    n = len(words)
    of_count: int | None = None
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
            if non is None and j + 1 < n and words[j] == "non":
                got_c = _colors(vocab, words, j + 1)
                if got_c is not None:  # "any four of the non-green blocks"
                    non, j = got_c
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
    return det, j, non, count, of_count


@dataclass(frozen=True)
class _Head:
    """The head of a reference: its determiner once "everything" has set it, its category (``names``, None
    for any), number, end, ``head`` ("one", "elided" or ""), loose colour matching, colours and "everything"."""

    det: str
    names: frozenset[str] | None
    plural: bool
    end: int
    head: str
    loose: bool
    colors: tuple[str, ...] | None
    color_order: tuple[str, ...]
    everything: str | None


def _head(vocab: Vocabulary, words: tuple[str, ...], i: int, j: int, det: str, pattern_words: frozenset[str],
          nested: bool) -> _Head | Mention | None:
    """The head at ``j`` after the determiner: "everything (else)", colours, then a category, a generic noun
    or none; a mention already complete (a colour without a noun), or None where no reference starts."""
    n = len(words)
    end = j
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
    colors = None
    color_order: tuple[str, ...] = ()
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
        return _colour_without_noun(vocab, words, i, j, det, colors, color_order, pattern_words, nested)
    else:
        return None
    return _Head(det, names, plural, end, head, loose, colors, color_order, everything)


def _colour_without_noun(vocab: Vocabulary, words: tuple[str, ...], i: int, j: int, det: str, colors: tuple[str, ...],
                         color_order: tuple[str, ...], pattern_words: frozenset[str], nested: bool) -> Mention:
    """Colours with no noun after them: a noun shared with a coordinated neighbour, one object per colour,
    a bare colour standing for its object; a colour before a word that names nothing here is refused."""
    n = len(words)
    # A colour followed by a word naming nothing here: "the purple giraffe".
    k = j
    while k < n and words[k] not in _COORD and words[k] not in pattern_words and k - j < 2 and words[k].isalpha():
        if words[k] in _NOT_NOUN or words[k] in STOPWORDS:
            break
        k += 1
    # a comma after a list of colours ends it where no colour, article or noun follows ("line up red blue
    # green, 10 cm apart", "red yellow orange, all facing me")
    ends = j < n and words[j] == "," and len(colors) > 1 and (j + 1 >= n or not (
        words[j + 1] in COLOUR_WORDS or words[j + 1] in ("the", "a", "and") or (words[j + 1],) in vocab.categories))
    coordinated = (j < n and words[j] in _COORD and not ends) or (i > 0 and words[i - 1] in _COORD)
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
    if k == j and det == "" and not nested and not (j < n and words[j] in _COORD and not ends):
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


def _excepted(vocab: Vocabulary, words: tuple[str, ...], k: int, m: Mention,
              pattern_words: frozenset[str]) -> tuple[list[Mention], int]:
    """The references left out of ``m`` after an exception word ending at ``k`` ("except the red one and
    the blue one"), and the word after them; a reference of another kind after them is no exception."""
    n = len(words)
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
    return excl, k


def _qualified(vocab: Vocabulary, words: tuple[str, ...], i: int, end: int, m: Mention, everything: str | None,
               pattern_words: frozenset[str], nested: bool) -> tuple[Mention, int]:
    """``m`` with the qualifiers after it: colours after "anything", attribute clauses (:mod:`.qualifiers`),
    "the same colour as X" and exceptions; and the word where they end."""
    n = len(words)
    while end < n:
        if everything is not None and m.colors is None and not m.filters:
            cols2 = _colors(vocab, words, end)  # "anything blue", "everything white"
            if cols2 is not None:
                end = cols2[1]
                m = replace(m, end=end, text=" ".join(words[i:end]), colors=cols2[0], color_order=cols2[0])
                continue
        aq = _attr_qualifier(vocab, words, end, pattern_words, _mention_at) if not nested else None
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
        if q is None and m.excluding:
            # a further exception joined to the first: "except the red one, and except the white one too"
            k = end
            while k < n and words[k] in (",", "and", "also", "hmm", "um", "uh", "or"):
                k += 1
            q = next((s for s in (*_EXCEPT, ("not",), ("nor",)) if s not in (("but",), ("without",))
                      and _starts(words, k, s)), None)
            if q is not None:
                end = k
        if q is not None:
            k = end + len(q)
            excl, k = _excepted(vocab, words, k, m, pattern_words)
            if excl and k < n and words[k] in ("too", "either"):
                k += 1
            if not excl:
                if q[0] in ("but", "without"):
                    break
                raise InputError(f"'{' '.join(words[i:k + 2])}': cannot tell what to leave out")
            end = k
            m = replace(m, end=end, text=" ".join(words[i:end]), excluding=m.excluding + tuple(excl))
            continue
        break
    return m, end


def _mention_at(
    vocab: Vocabulary, words: tuple[str, ...], i: int, pattern_words: frozenset[str], *, nested: bool = False
) -> Mention | None:
    """The object reference starting at word ``i`` (see the grammar of :mod:`.grounding`), or None where none
    starts there. ``nested``: a reference inside another (after "except", "the same colour as", a
    comparison), which takes no pronoun, no qualifier of its own and no shared noun."""
    n = len(words)
    early = _standalone(words, i, nested)
    if early is not None:
        return early
    if i + 1 < n and words[i] == "them" and (words[i + 1] in NUMBERS or vocab.longest(vocab.categories, words, i + 1)):
        # "them three cans", "them cups" (said for "those" in many dialects): a determiner, not a pronoun
        words = words[:i] + ("those",) + words[i + 1 :]
    det, j, non, count, of_count = _quantity(vocab, words, i, nested)
    if det == "" and j < n and words[j] in _PRONOUNS and not nested:
        return Mention(i, j + 1, words[j], "pronoun", True)
    if det in ("the", "all", "other") and j < n and words[j] in ("rest", "others", "remaining"):
        end = j + 1
        return Mention(i, end, " ".join(words[i:end]), "other", True)
    got = _head(vocab, words, i, j, det, pattern_words, nested)
    if not isinstance(got, _Head):
        return got
    det, names, plural, end, head, loose = got.det, got.names, got.plural, got.end, got.head, got.loose
    colors, color_order, everything = got.colors, got.color_order, got.everything
    if det == "vague":
        raise InputError(f"'{' '.join(words[i:end])}' does not say how many; name them, give a number or say all")
    if det == "both" and not plural:
        det = "the"
    if det == "" or (det == "the" and plural):
        det = "all" if plural else "the"
    if det == "count" and count == 1:
        det = "one"
    m = Mention(i, end, " ".join(words[i:end]), det, plural, names, colors, color_order, count=count, head=head,
                of_count=of_count, loose=loose)
    if non is not None:
        m = replace(m, filters=(("value", "ne", Mention(i, end, "non " + " ".join(non), "all", True, None, non, non)),))
    if (names is None and words[end - 1] in ("piece", "pieces", "item", "items", "bit", "bits") and end + 1 < n
            and words[end] == "of" and words[end + 1].isalpha()
            and words[end + 1] not in _OF_OK and _COLOUR_FORMS.get(words[end + 1], words[end + 1]) not in vocab.color_words
            and vocab.longest(vocab.categories, words, end + 1) is None):
        # "every piece of fruit": a kind the scene does not have (not every object).
        raise InputError(f"'{' '.join(words[i:end + 2])}' names nothing in the scene")
    m, end = _qualified(vocab, words, i, end, m, everything, pattern_words, nested)
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
                if not any(_any_match(vocab, replace(m, names=x.names)) for x in order) and m.det not in (
                        "other", "another"):
                    # none of them has one of this colour: a noun of an earlier clause ("the yellow cup into the
                    # red bowl and the orange cup into the blue one": the bowl)
                    order += [replace(m, names=n, head="") for n in context
                              if _any_match(vocab, replace(m, names=n))][:1]
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
