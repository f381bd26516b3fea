"""Steps that only pick objects out, read as the topic of the steps after them.

Instructions written as steps often give a step that selects before the step that moves: "1. Find the two
mugs. 2. Put the red one behind the plate. 3. Put the other one in front of it."; "Look at the red bowl. Find the
can that is the same colour. Put that can behind the box."; "First, find the middle one of the three silver
things. Next, put it on the right of the mug." A person reads the first step as what the next ones are about.
This stage, on the text after spelling, reads a sentence that is only a verb of finding (the lexicon's ``[steps]
selecting``: "find", "look at", "pick up", "locate" ...) and one reference, followed by a sentence of its own,
in one of two ways:

* a colour comparison left open in a later step ("the can that is the same colour.", "the one that matches.")
  is completed with the reference ("... the same colour as the red bowl"), and the finding step goes, since
  its object was only looked at;
* otherwise the step becomes the topic of what follows, said with a colon ("the two mugs: put the red one
  ..."), which the parser reads as the group that "the red one", "the other one", "it" and "them" pick from.

A step that says anything besides its reference (a pattern, a direction, a place, a number of its own) is not
only a finding step and is left as it is; so is the last sentence of a command.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from . import lexicon
from .ir import Token
from .vocabulary import tokenize

__all__ = ["finding_steps"]

_STOPS = frozenset({".", "!", "?", ";"})
_STARTS = frozenset({"the", "all", "both", "those", "these", "each", "every", "letter"})
_OPENERS = frozenset({"first", "firstly", "next", "then", "now", "step", "and", "so", "ok", "okay", "please", ","})
#: Words by which a step picks from the group found before it ("the red one", "the other one", "the rest").
_PICKS = frozenset({"one", "ones", "other", "others", "former", "latter", "rest", "remaining", "first", "second"})
_OPEN_COMPARISONS = (("same", "colour"), ("same", "color"), ("that", "matches"), ("matching", "one"))


def _sentences(toks: Sequence[Token]) -> list[tuple[int, int]]:
    """(first, end) token indices of each sentence, the stop included; an enumerator ("2.") starts the sentence
    after it."""
    out, first = [], 0
    for k, t in enumerate(toks):
        if t.text not in _STOPS:
            continue
        if k == first + 1 and toks[first].text[:1].isdigit():
            continue  # "2." numbers the step after it
        if t.text == "." and k and toks[k - 1].text[:1].isdigit() and k + 1 < len(toks) and toks[k + 1].text[:1].isdigit():
            continue  # "0.3 m"
        out.append((first, k + 1))
        first = k + 1
    if first < len(toks):
        out.append((first, len(toks)))
    return out


def _enumerator_end(toks: Sequence[Token], first: int, end: int) -> int:
    """The index after the enumerator a sentence opens with ("2.", "3)", "step 4:"), ``first`` where none."""
    k = first
    if k < end and toks[k].text == "step":
        k += 1
    if k < end and toks[k].text[:1].isdigit():
        k += 1
        if k < end and toks[k].text in (".", ")", ":"):
            k += 1
        return k
    return first


def _finding(toks: Sequence[Token], first: int, end: int,
             object_word: Callable[[str], bool]) -> tuple[int, int] | None:
    """(where the verb starts, where the reference starts) of a finding step, or None where the sentence is not
    one."""
    k = _enumerator_end(toks, first, end)  # "1.", "2)", "step 3:"
    while k < end and toks[k].text in _OPENERS:
        k += 1  # "first,", "next,"
    verb_at = k
    for verb in lexicon.FINDING_VERBS:
        if tuple(t.text for t in toks[k : k + len(verb)]) == verb:
            k += len(verb)
            break
    else:
        return None
    stop = end - 1 if toks[end - 1].text in _STOPS else end
    ref = [t.text for t in toks[k:stop]]
    if not ref or (ref[0] not in _STARTS and not ref[0][:1].isdigit()) or not any(object_word(w) for w in ref):
        return None
    if any(w in lexicon.COMMAND_VERBS or w in lexicon.ARRANGEMENT_NOUNS or w == "and" for w in ref):
        return None  # "find the cans and put them in a line": more than a finding step
    return verb_at, k


def finding_steps(text: str, object_word: Callable[[str], bool]) -> str:
    """``text`` with its finding steps read (see the module).

    >>> obj = lambda w: w in {"mugs", "mug", "bowl", "can", "red", "cans"}
    >>> finding_steps("1. Find the two mugs. 2. Put the red one behind the bowl.", obj)
    'the two mugs: Put the red one behind the bowl.'
    >>> finding_steps("Look at the red bowl. Find the can that is the same colour. Put that can behind the bowl.", obj)
    'Find the can that is the same colour as the red bowl. Put that can behind the bowl.'
    >>> finding_steps("Find the cans and put them in a line.", obj)
    'Find the cans and put them in a line.'
    """
    for _ in range(12):  # each round reads one step, which then is one no more
        toks = tokenize(text)
        sents = _sentences(toks)
        for s, (first, end) in enumerate(sents[:-1]):
            got = _finding(toks, first, end, object_word)
            read = text if got is None else _read_step(text, toks, (first, got[1]), end, sents[s + 1])
            if read != text:
                text = read
                break
        else:
            return text
    return text


def _read_step(text: str, toks: Sequence[Token], got: tuple[int, int], end: int, nxt: tuple[int, int]) -> str:
    """``text`` with the finding step whose sentence and reference start at ``got`` (the sentence ending at token
    ``end``) read into the sentence ``nxt`` after it; its enumerator and opening words go with it."""
    verb_at, k = got
    stop = end - 1 if toks[end - 1].text in _STOPS else end
    ref = text[toks[k].start : toks[stop - 1].end]
    nxt_first, nxt_end = nxt
    words = [t.text for t in toks[nxt_first:nxt_end]]
    for j in range(len(words) - 1):
        if tuple(words[j : j + 2]) in _OPEN_COMPARISONS and (j + 2 == len(words) or words[j + 2] in _STOPS
                                                             or words[j + 2] == ","):
            at = toks[nxt_first + j + 1].end
            return text[: toks[verb_at].start] + text[toks[nxt_first].start : at] + f" as {ref}" + text[at:]
    heads = {t.text for t in toks[k + 1 : stop]}
    for j in range(len(words) - 2):
        if words[j : j + 2] == ["same", "colour" if "colour" in words else "color"] and words[j + 2] == "as" and \
                j + 4 < len(words) and words[j + 3] in ("that", "this") and words[j + 4] in heads:
            # "find the bottle furthest back. then find the mug ... the same colour as that bottle": only looked at
            a, b = toks[nxt_first + j + 3].start, toks[nxt_first + j + 4].end
            return text[: toks[verb_at].start] + text[toks[nxt_first].start : a] + ref + text[b:]
    if not _PICKS & set(words):
        return text  # "find every red thing. put them all in a row": "them" reads its antecedent as it is
    after = _enumerator_end(toks, nxt_first, nxt_end)
    rest = text[toks[after].start :] if after < len(toks) else ""
    return text[: toks[verb_at].start] + f"{ref}: " + rest
