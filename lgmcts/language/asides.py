"""Asides said in brackets, read by what they say.

People who write instructions put remarks in brackets: a reminder ("(use your ruler!)", "(Remember: the back is
the side FURTHEST from you!)"), an explanation of a word said before ("(that's from the middle to the edge!)",
"(i.e. midway between the left and right edges)"), a cross-reference ("(refer to step 3)"), a label of an
enumeration ("(a)"), or the object a pronoun means ("put the pan behind it (the star, I mean)"). This stage reads
each bracketed span once, after spelling and before every other reading, by the kind of thing it says:

* **a pronoun made plain**: a bracket right after "it" / "them" / "that one" whose words name an object, with or
  without "I mean" ("(the star, I mean)", "(I mean the star)"), replaces the pronoun;
* **an aside that adds nothing**: a bracket that names no object of the scene and either opens with a word of
  explanation (the lexicon's ``[asides] explaining``: "that's", "i.e.", "remember", "refer to" ...) and says no
  number that was not said before it, or whose every number and every word that could ask for a goal (a
  pattern, direction, place, size or order word) was said before it, goes;
* anything else (a bracket with a new place, a new number, an object it does not make plain) stays as it was
  written, for the later stages to read or refuse: "(at the back)", "(30 cm long)", "(any order)" are kept.

Nothing said is dropped unread: an aside only goes when it names no object and says nothing the command did not
already say, or explains itself as an explanation.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from . import lexicon
from .ir import Token
from .vocabulary import tokenize

__all__ = ["bracketed"]

_OPEN = {"(": ")"}  # the tokens keep no square brackets
_PRONOUNS = (("it",), ("them",), ("that", "one"), ("this", "one"), ("the", "other", "one"))
_MEAN = (("i", "mean"), ("that", "is"), ("i", "e"), ("ie",), ("meaning",))


def _spans(toks: Sequence[Token]) -> list[tuple[int, int]]:
    """Token indices (open, close) of each span in parentheses, not nested."""
    out: list[tuple[int, int]] = []
    k = 0
    while k < len(toks):
        close = _OPEN.get(toks[k].text)
        if close is None:
            k += 1
            continue
        end = next((j for j in range(k + 1, len(toks)) if toks[j].text == close), None)
        if end is None or any(t.text in _OPEN for t in toks[k + 1 : end]):
            k += 1
            continue
        out.append((k, end))
        k = end + 1
    return out


def _words(toks: Sequence[Token]) -> list[str]:
    return [t.text for t in toks if t.text[:1].isalnum()]


def _without_mean(words: list[str]) -> list[str]:
    """The words of a clarification without its "I mean" / "that is" / "i.e." at either end."""
    for phrase in _MEAN:
        n = len(phrase)
        if tuple(words[:n]) == phrase:
            words = words[n:]
        if tuple(words[-n:]) == phrase:
            words = words[:-n]
    return words


def _pronoun_before(toks: Sequence[Token], k: int) -> int | None:
    """The index of the first token of the pronoun that ends right before token ``k``, or None."""
    for phrase in _PRONOUNS:
        n = len(phrase)
        if k >= n and tuple(t.text for t in toks[k - n : k]) == phrase:
            return k - n
    return None


def bracketed(text: str, object_word: Callable[[str], bool], request_word: Callable[[str], bool]) -> str:
    """``text`` with its bracketed asides read (see the module): a pronoun made plain by the bracket after it,
    an aside that adds nothing dropped, any other bracket left as written.

    >>> obj = lambda w: w in {"star", "pan", "cans", "red"}
    >>> req = lambda w: w in {"line", "back", "middle", "edge", "long", "order", "any"}
    >>> bracketed("put the pan behind it (the star, I mean).", obj, req)
    'put the pan behind the star.'
    >>> bracketed("the cans in a line, 30 cm long (use your ruler!).", obj, req)
    'the cans in a line, 30 cm long.'
    >>> bracketed("stack the cans (any order)", obj, req), bracketed("the cans in a line (at the back)", obj, req)
    ('stack the cans (any order)', 'the cans in a line (at the back)')
    """
    toks = tokenize(text)
    spans = _spans(toks)
    if not spans:
        return text
    explaining = lexicon.ASIDE_EXPLAINING
    out: list[str] = []
    at = 0
    for k, end in spans:
        inner = _words(toks[k + 1 : end])
        said = set(_words(toks[:k]))
        cut_from = toks[k].start
        plain = _without_mean(inner)
        if any(object_word(w) for w in plain):
            p = _pronoun_before(toks, k)
            if p is None or not plain or plain[0] not in ("the", "that", "this") or len(plain) > 5:
                continue
            out.append(text[at : toks[p].start] + " ".join(plain))
            at = toks[end].end
            continue
        numbers_said = all(w in said for w in inner if w[:1].isdigit())
        explains = any(tuple(inner[: len(ph)]) == ph for ph in explaining)
        nothing_new = all(w in said for w in inner if request_word(w) or w[:1].isdigit())
        if not ((explains and numbers_said) or nothing_new):
            continue
        while cut_from and text[cut_from - 1] == " ":
            cut_from -= 1
        out.append(text[at:cut_from])
        at = toks[end].end
    out.append(text[at:])
    return "".join(out)
