"""A stack's order said as a list of roles by colour, solved as constraints.

"Stack all four blocks with yellow on top, green under it, red under green,
blue at the bottom" says no order in one phrase: each item places one colour
at the bottom, at the top, in the middle, or right on or right under another
colour ("it" and "that one" are the colour of the item before). This stage
reads such a list after a stack word (``stack``, ``stacked``, ``tower``,
``pile``, ``piled``), or as a sentence of its own where the command has no
stack word, finds every order of the colours it names that keeps every item,
and:

* where exactly one order does, says it plainly ("from the bottom up: blue,
  red, green, yellow"), which the later stages read;
* where none does, refuses, quoting the list (the roles contradict each
  other);
* where several do, or the list is not wholly such items, leaves the text
  to the later stages.

Only lists with at least one item relative to another colour, or said down
from the top with "then" ("green on top, then yellow, then blue, and red at
the base"), are taken: a list of places alone (bottom, top) is read by the later stages as
before.
"""

from __future__ import annotations

from itertools import permutations

from ..errors import InputError
from . import lexicon
from .ir import Token
from .vocabulary import tokenize

__all__ = ["stack_orders"]

_HEADS = frozenset({"stack", "stacked", "tower", "pile", "piled"})
_OPENERS = frozenset({",", ":", "with", "w", "-", ";", "that"})
_SEPARATORS = frozenset({",", "and", "then", ";", "so", "with"})
#: Words between an item's object and its place ("the green one's in the middle", "red goes on blue").
_LINKS = frozenset({"is", "goes", "go", "sits", "sit", "should", "be", "ends", "up", "stays", "must", "will"})
#: Words that may open a sentence that is only a list of roles.
_OPENING = frozenset({"um", "uh", "so", "okay", "ok", "now", "right", "well", "and", "then", "oh", ","})
#: Absolute places in a stack: words -> "bottom" / "top" / "middle".
_PLACES: tuple[tuple[tuple[str, ...], str], ...] = (
    (("at", "the", "bottom"), "bottom"), (("on", "the", "bottom"), "bottom"), (("at", "bottom"), "bottom"),
    (("on", "bottom"), "bottom"), (("as", "the", "base"), "bottom"), (("at", "the", "base"), "bottom"),
    (("as", "base"), "bottom"), (("on", "the", "table"), "bottom"),
    (("on", "the", "top"), "top"), (("on", "top"), "top"), (("at", "the", "top"), "top"), (("at", "top"), "top"),
    (("up", "top"), "top"), (("at", "the", "very", "top"), "top"), (("at", "the", "very", "bottom"), "bottom"),
    (("on", "the", "very", "top"), "top"), (("on", "the", "very", "bottom"), "bottom"), (("to", "top", "it", "off"), "top"),
    (("tops", "it", "off"), "top"), (("caps", "it", "off"), "top"), (("to", "cap", "it", "off"), "top"),
    (("in", "the", "middle"), "middle"), (("base",), "bottom"), (("as", "the", "bottom"), "bottom"),
)
#: Relations to another colour: words -> +1 (right on it) / -1 (right under it).
_RELATIONS: tuple[tuple[tuple[str, ...], int], ...] = (
    (("on", "top", "of"), 1), (("on",), 1), (("onto",), 1), (("above",), 1), (("over",), 1), (("atop",), 1),
    (("underneath",), -1), (("under",), -1), (("below",), -1), (("beneath",), -1),
)
_BACK = (("that", "one"), ("it",), ("that",), ("this",))
#: The places of a stack of three, from the bottom up.
_PLACE_SAID = ("at the bottom", "in the middle", "on top")
#: Words said before a place that add nothing to it ("right at the top", "all the way at the bottom").
_INTENSIFIERS = frozenset({"right", "directly", "just", "very", "way", "all", "the", "up"})
#: Words after a colour that are not its noun.
_NOT_NOUNS = (frozenset(lexicon.ROWS) | frozenset(lexicon.COLS) | _INTENSIFIERS
              | frozenset({",", "and", "then", ";", "so", "goes", "go", "is", "sits", "should", "first", "last"}))


def _colour_at(words: list[str], i: int) -> tuple[str, int] | None:
    """A colour said as an item's object at ``i`` ("the red one", "red", "the red block"): (colour, end)."""
    j = i + (i < len(words) and words[i] == "the")
    if j >= len(words) or words[j] not in lexicon.HUES:
        return None
    k = j + 1
    if k < len(words) and words[k].replace("'", "").isalpha() and words[k] not in _NOT_NOUNS and not any(
            tuple(words[k : k + len(p)]) == p for p, _ in (*_PLACES, *_RELATIONS)):
        k += 1  # "red block", "red one"
    return words[j], k


def _noun_at(words: list[str], i: int) -> str | None:
    """The noun of an item's object at ``i`` ("block" of "the red block"; None for "the red one", "red")."""
    got = _colour_at(words, i)
    if got is None:
        return None
    noun = words[got[1] - 1]
    return None if noun in lexicon.HUES or noun in ("one", "ones") or not noun.isalpha() else noun


def _item(words: list[str], i: int, prev: str | None, then: str = ""
          ) -> tuple[tuple[str, str, str | int], int] | None:
    """One item at ``i``: ((colour, "place", place) or (colour, "rel", other colour and step)), end. With
    ``then`` ("+" or "-": the item came after "then", in a list said upward or downward), a colour said alone
    goes right on (under) the item before."""
    got = _colour_at(words, i)
    if got is None:
        return None
    if then and prev is not None and (got[1] == len(words) or words[got[1]] in _SEPARATORS | {".", "!", "?"}):
        return (got[0], "then", f"{prev}{then}"), got[1]
    colour, k = got
    while k < len(words) and words[k] in _LINKS:
        k += 1
    at = k
    while at < len(words) and words[at] in _INTENSIFIERS - {"the"}:
        at += 1  # "red right at the top"
    for seq, place in _PLACES:
        if at > k and tuple(words[at : at + len(seq)]) == seq:
            return (colour, "place", place), at + len(seq)
    for seq, place in _PLACES:
        if tuple(words[k : k + len(seq)]) == seq and words[k + len(seq) : k + len(seq) + 1] != ["of"]:
            return (colour, "place", place), k + len(seq)
    for seq, step in _RELATIONS:
        if tuple(words[k : k + len(seq)]) == seq:
            j = k + len(seq)
            for back in _BACK:
                if tuple(words[j : j + len(back)]) == back and prev is not None:
                    return (colour, "rel", f"{prev}{'+' if step > 0 else '-'}"), j + len(back)
            other = _colour_at(words, j)
            if other is not None:
                return (colour, "rel", f"{other[0]}{'+' if step > 0 else '-'}"), other[1]
            return None
    return None


def _relation_at(words: list[str], k: int) -> bool:
    """Whether a relation to another colour ("on", "on top of", "under") is said at ``k``."""
    return any(tuple(words[k : k + len(seq)]) == seq for seq, _ in _RELATIONS)


def _colours(items: list[tuple[str, str, str | int]]) -> tuple[str, ...]:
    """The colours a list names, in the order said: the items' own and those they are placed on or under."""
    return tuple(dict.fromkeys([c for c, _, _ in items] + [str(w)[:-1] for _, k, w in items if k != "place"]))


def _orders(items: list[tuple[str, str, str | int]], size: int = 0) -> list[tuple[str, ...]]:
    """Every bottom-up order of the items' colours that keeps every item (in a stack of ``size``, the places
    of the objects no item names said "?")."""
    out: list[tuple[str, ...]] = []
    said = list(_colours(items))
    for order in dict.fromkeys(permutations(said + ["?"] * max(0, size - len(said)))):
        pos = {c: n for n, c in enumerate(order)}
        ok = True
        for c, kind, what in items:
            if kind == "place":
                want = {"bottom": 0, "top": len(order) - 1, "middle": (len(order) - 1) / 2}[str(what)]
                ok = pos[c] == want
            else:
                other, sign = str(what)[:-1], str(what)[-1]
                ok = other in pos and pos[c] == pos[other] + (1 if sign == "+" else -1)
            if not ok:
                break
        if ok:
            out.append(order)
    return out


def _list_at(words: list[str], i: int) -> tuple[list[tuple[str, str, str | int]], int]:
    """The items of a role list starting at ``i`` and its end."""
    items: list[tuple[str, str, str | int]] = []
    prev: str | None = None
    k = i
    then = ""
    while k < len(words):
        got = _item(words, k, prev, then)
        if got is None:
            break
        items.append(got[0])
        prev = got[0][0]
        k = got[1]
        if got[0][1] == "rel" and str(got[0][2])[:-1] in lexicon.HUES and _relation_at(words, k):
            # a chain, "red on yellow on blue": the colour just said is the next item's object
            k = max(j for j in range(i, k) if words[j] in lexicon.HUES)
            then = ""
            continue
        j = k
        while j < len(words) and words[j] in _SEPARATORS:
            j += 1
        # "then" goes up the stack, or down it where the list starts at the top
        then = ("-" if items[0][1:] == ("place", "top") else "+") if "then" in words[k:j] else ""
        if j == k and k < len(words) and words[k] not in (".", "!", "?"):
            break
        if _colour_at(words, j) is None:
            break
        k = j
    return items, k


def _nouns(words: list[str], i: int, end: int) -> dict[str, str]:
    """The noun said with each colour of a list ("the red can" -> can); a colour said without one stays bare (the
    readings give it the noun of its neighbours or of the stack's group)."""
    return {words[k]: n for k in range(i, end) if words[k] in lexicon.HUES and (n := _noun_at(words, k))}


def _said_alone(text: str, toks: tuple[Token, ...], words: list[str]) -> str:
    """A sentence that is only a list of roles by colour, with the nouns of its objects ("the green bowl on the
    blue bowl, and the white bowl on top of the green bowl, so the green one's in the middle"): said as a stack of
    those objects from the bottom up."""
    s = 0
    while s < len(words):
        i = s
        while i < len(words) and words[i] in _OPENING:
            i += 1
        items, end = _list_at(words, i)
        stop = next((e for e in range(i, len(words)) if words[e] in (".", "!", "?", ";")), len(words))
        if len(items) >= 2 and len(_colours(items)) >= 2 and end == stop and any(k == "rel" for _, k, _ in items):
            kinds = {n for k in range(i, end) if words[k] in lexicon.HUES and (n := _noun_at(words, k))}
            orders = _orders(items)
            if len(kinds) == 1 and len(orders) == 1:
                (noun,) = kinds
                said = [f"the {c} {noun}" for c in orders[0]]
                return text[: toks[i].start] + "stack " + ", ".join(said[:-1]) + " and " + said[-1] + \
                    " from the bottom up" + text[toks[end - 1].end :]
            if not orders:
                raise InputError(f"'{text[toks[i].start : toks[end - 1].end]}': the places said in the stack "
                                 f"contradict each other")
        s = stop + 1
    return text


def stack_orders(text: str) -> str:
    """``text`` with a stack's list of roles by colour said as its one order from the bottom up."""
    toks: tuple[Token, ...] = tokenize(text)
    words = [t.text for t in toks]
    if not any(w in _HEADS for w in words):
        return _said_alone(text, toks, words)
    for h, w in enumerate(words):
        if w not in _HEADS:
            continue
        for s in range(h + 1, min(len(words), h + 8)):
            if words[s] in (".", "!", "?"):
                break
            if words[s] not in _OPENERS and not (words[s].endswith("s") and words[s + 1 : s + 2] and
                                                 words[s + 1] in lexicon.HUES):
                # "w/" is read as "w" (the tokens keep no slash); a list may follow the group's noun right away
                # ("stack the blocks red on yellow on blue")
                continue
            start = s + 1
            items, end = _list_at(words, start)
            downward = items[:1] and items[0][1:] == ("place", "top") and any(kind == "then" for _, kind, _ in items)
            if len(items) < 2 or len(_colours(items)) < 2 or not (any(kind == "rel" for _, kind, _ in items) or downward):
                continue  # places alone are read by the readings after
            counted = [lexicon.NUMBERS.get(x, int(x) if x.isdigit() else 0) for x in words[h + 1 : start]]
            if max(counted, default=0) > len(_colours(items)):
                # "stack the three bowls, the red one in the middle, the blue one under it": one object unnamed;
                # where three places are fixed all the same, each named one is said by its place
                fixed = _orders(items, 3) if max(counted) == 3 else []
                if len(fixed) != 1:
                    continue
                cut = toks[s].start if words[s] in _OPENERS else toks[s].end
                places = [f"{c} {_PLACE_SAID[n]}" for n, c in enumerate(fixed[0]) if c != "?"]
                return text[:cut].rstrip() + ", " + ", ".join(places) + text[toks[end - 1].end :]
            orders = _orders(items)
            said = text[toks[s].start : toks[end - 1].end]
            if not orders:
                raise InputError(f"'{said.strip(' ,:')}': the places said in the stack contradict each other")
            if len(orders) > 1:
                return text
            nouns = _nouns(words, start, end)
            if (not nouns and w in ("stacked", "piled")) or 0 < len(nouns) < len(orders[0]):
                # "the three bowls stacked with ...", "purple on top, orange below it, and the black bowl at the
                # base": a group said before, or nouns said with some items only, are left to the readings
                return text
            named = [f"the {c} {nouns[c]}" if c in nouns else c for c in orders[0]]
            cut = toks[s].start if words[s] in _OPENERS else toks[s].end
            return text[:cut].rstrip() + ", from the bottom up: " + ", ".join(named) + \
                text[toks[end - 1].end :]
    return text
