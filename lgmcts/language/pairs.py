"""Objects named by their place in a pair said first, and a stack ordered by pairs of colours.

Two text stages of the parser (run by :meth:`.rules._Parser._rewritten`, after the references by position and
colour are named by id), each a pure function of the text and the parser's mention finder:
:func:`pair_named` ("Grab the knife and the fork. First one goes left of the plate, the other one right of it")
and :func:`stack_by_colours` ("stack the bowls with blue under red and red under white"). Each leaves the text as
said where its reading is not clear, for the parser to read or refuse.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ..errors import InputError
from . import lexicon
from .grounding import tokenize
from .stages import _end, _ids

__all__ = ["pair_named", "stack_by_colours"]


#: Words before a pair said on its own ("Grab the knife and the fork.", "See the red bowl and the cup?").
_PAIR_LEAD = frozenset({"grab", "take", "get", "see", "pick", "up", "use", "okay", "ok", "so", "now", "right", "um",
                        "uh", "here's", "there's", "you've", "got"})
_STOPS = frozenset({".", "!", "?", ";"})


def pair_named(text: str, find: Callable[[tuple[str, ...]], list], ids_of: Callable[[Any], list[int]]) -> str:
    """``text`` with the two objects of a pair said on its own first ("Grab the knife and the fork.", "Blue mug and
    red mug.") named by id in the sentence right after it where it says them by their place in the pair: "first
    one" is the first, "second one" the second and "the other one" the one of the two that sentence has not named
    before it ("Blue one in front of the white bottle, the other one behind it": the red mug). Left as said where
    the first sentence is not two references joined by "and" that name one object each, or where "the other one"
    follows no object of the pair."""
    toks = tokenize(text)
    words = tuple(t.text for t in toks)
    stop = next((k for k, w in enumerate(words) if w in _STOPS), None)
    if stop is None:
        return text
    i = 0
    while i < stop and words[i] in _PAIR_LEAD:
        i += 1
    head = words[i:stop]
    try:
        ms = [m for m in find(head) if getattr(m, "det", None) != "pronoun"]
    except InputError:
        return text
    if len(ms) != 2 or ms[0].start != 0 or ms[1].end != len(head) or head[ms[0].end : ms[1].start] != ("and",):
        return text
    pair = [list(ids_of(m)) for m in ms]
    if any(len(p) != 1 for p in pair) or pair[0] == pair[1]:
        return text
    ids = [pair[0][0], pair[1][0]]
    end = next((k for k in range(stop + 1, len(words)) if words[k] in _STOPS), len(words))
    out: list[str] = []
    at = 0
    named: set[int] = set()
    k = stop + 1
    while k < end:
        lo = k - (words[k - 1] == "the")
        if words[k] in ("first", "second") and words[k + 1 : k + 2] == ("one",):
            said, hi = ids[words[k] == "second"], k + 2
        elif words[k : k + 3] == ("the", "other", "one") or (words[k : k + 2] == ("the", "other") and (
                k + 2 >= end or not words[k + 2].isalpha() or words[k + 2] in ("goes", "go", "on", "in", "to", "at"))):
            lo, hi = k, k + 2 + (words[k + 2 : k + 3] == ("one",))
            try:
                named |= {x for m in find(words[stop + 1 : k]) for x in ids_of(m) if x in ids}
            except InputError:
                return text
            if len(named) != 1:
                return text  # none of the pair named before it, or both: which is "the other" is not guessed
            said = next(x for x in ids if x not in named)
        else:
            k += 1
            continue
        named.add(said)
        out.append(text[at : toks[lo].pos] + f"object {said}")
        at = _end(text, toks[hi - 1])
        k = hi
    out.append(text[at:])
    return "".join(out)


#: Words that put one object on or under another in a stack, said between two colours ("blue under red").
_STACKED_ON = {("on",): "on", ("onto",): "on", ("over",): "on", ("above",): "on", ("on", "top", "of"): "on",
               ("under",): "under", ("beneath",): "under", ("below",): "under", ("underneath",): "under"}


def _colour_pairs(words: tuple[str, ...], k: int) -> tuple[list[tuple[str, str, str]], int]:
    """The pairs "HUE on/under HUE" joined by ",", "and", "then" from ``k``, and the end of the last."""
    pairs: list[tuple[str, str, str]] = []
    while k < len(words) and words[k] in lexicon.HUES:
        rel = next(((seq, r) for seq, r in _STACKED_ON.items() if words[k + 1 : k + 1 + len(seq)] == seq), None)
        if rel is None:
            break
        j = k + 1 + len(rel[0])
        if j >= len(words) or words[j] not in lexicon.HUES:
            break
        pairs.append((words[k], rel[1], words[j]))
        k = j + 1
        nxt = k
        while nxt < len(words) and words[nxt] in (",", "and", "then"):
            nxt += 1
        if nxt == k or nxt >= len(words) or words[nxt] not in lexicon.HUES:
            break
        k = nxt
    return pairs, k


def stack_by_colours(text: str, find: Callable[[tuple[str, ...]], list], ids_of: Callable[[Any], list[int]]) -> str:
    """``text`` with a stack of a group ordered by its colours in pairs ("stack the bowls with blue under red and
    red under white", "stack the cans: white on green, red on white") said with each object named ("put the blue
    bowl under the red bowl and the red bowl under the white bowl"), where the pairs name every object of the group
    once, one object each, and chain into one stack; left as said otherwise."""
    toks = tokenize(text)
    words = tuple(t.text for t in toks)
    for k, w in enumerate(words):
        if w != "stack":
            continue
        j = k + 1
        while j < len(words) and words[j] in ("up", "all", "the"):
            j += 1
        if j + 2 >= len(words) or not words[j].endswith("s") or words[j + 1] not in ("with", ":", ","):
            continue
        noun = words[j][:-1]
        pairs, end = _colour_pairs(words, j + 2)
        if len(pairs) < 2 or any(a[2] != b[0] and a[0] != b[2] for a, b in zip(pairs, pairs[1:])):
            continue  # one pair, or pairs that do not chain into one stack: left to be read or refused as said
        group = _ids(("the", words[j]), find, ids_of)
        each = [_ids(("the", c, noun), find, ids_of) for c in dict.fromkeys(c for a, _, b in pairs for c in (a, b))]
        if group is None or any(e is None or len(e) != 1 for e in each) or sorted(
                e[0] for e in each if e is not None) != sorted(group):
            continue
        said = " and ".join(f"the {a} {noun} {rel} the {b} {noun}" for a, rel, b in pairs)
        return text[: toks[k].pos] + "put " + said + text[_end(text, toks[end - 1]) :]
    return text
