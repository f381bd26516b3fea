"""Spoken repairs, restarts and echoes, read by what the repaired words are.

A person who speaks a command corrects it as they go and says parts of it
again: "a circle in the near right corner. No, the far right corner. The
far one."; "about 30 centimetres across? Actually no, make it 40 across.
Yeah. Forty."; "put the mug left of the bowl, no, right. Right of the bowl".
This stage reads such text before any other reading (after spelling) and
works by the kind of the words, not by listed sentences:

* **typed repairs** (:func:`typed_repairs`): after a repair marker (the
  lexicon's ``[repairs] markers``: "no", "no wait", "actually", "I mean",
  "make it" ..., said at the start of a sentence or after a comma or a
  dash), a fragment that is wholly one kind of thing replaces the last thing
  of the same kind said before the marker, and the marker and the fragment
  go. The kinds: a *facing* ("facing me", "facing the back wall"), a *place*
  ("the far right corner", "back left"), a *measure* ("40 cm across") and a
  measure's *number* said alone ("40 across": the unit of the measure it
  corrects stays). A fragment of no kind, or with nothing of its kind before
  it, is left to the later stages, which read or refuse it;
* **restarts** (:func:`restarts`): a sentence that ends on a relation word
  which the next sentence starts with and goes on from ("... right. Right of
  the bowl") is one sentence;
* **echoes** (:func:`echoes`): a sentence after the first whose every word
  (besides the lexicon's ``echo_neutral`` words, a question tag and a purpose
  clause that asks for no goal) was said in one sentence before it, with its
  colours and relation words in the same order, asks for nothing new and
  goes ("On the green block." after "... on the green block.", "The far
  one.", "West, the left." after "facing west", "Forty." after "40 across").
  A sentence with a verb of its own, or with one new word, is kept.

Nothing said is dropped unread: a repair replaces a thing of its own kind,
and an echo only goes when every word of it is already in the text.
"""

from __future__ import annotations

from collections.abc import Sequence

from . import lexicon
from .ir import Token
from .measures import _number, find_measures
from .vocabulary import tokenize

__all__ = ["echoes", "fragment_kind", "repaired", "restarts", "typed_repairs"]

_STOPS = frozenset({".", "!", "?", ";"})
#: Tokens after which a repair marker may start.
_BREAKS = _STOPS | frozenset({",", "-", ":", "\u2026", "\u2014", "\u2013"})
#: Fillers said inside a fragment ("the, um, far right corner").
_FILLERS = frozenset({"um", "umm", "uh", "uhh", "er", "erm", "hmm", "hm", "oh", "ah"})
#: Words after a facing verb that say the facing.
_FACING_REST = (frozenset({"away", "from", "toward", "towards", "to", "at", "the", "edge", "wall", "side", "straight",
                           "north", "south", "east", "west", "left", "right", "front", "back", "near", "far", "rear"})
                | lexicon.VIEWER_WORDS)
_FACE_VERBS = lexicon.FACE_VERBS | {"point", "points", "aim"}
#: Words of a place said by the table's rows, columns and parts.
_PLACE_WORDS = (frozenset(lexicon.ROWS) | frozenset(lexicon.COLS) | lexicon.REGION_NOUNS
                | frozenset({"hand", "dead", "smack"}))
_PLACE_LEAD = frozenset({"in", "at", "on", "into", "to", "toward", "towards", "over", "along", "across", "the"})
#: Words a measure's number may have after it when said alone ("40 across", "forty wide").
_NUMBER_ROLE = frozenset({"across", "wide", "long", "radius", "diameter", "big", "each", "side", "apart", "in",
                          "length", "width"})
#: Words of a relation ("put the mug right. Right of the bowl").
_RELATION = frozenset({"on", "onto", "under", "underneath", "below", "beneath", "above", "over", "left", "right",
                       "front", "behind", "back", "top", "bottom"})
#: Words an echo may say in another order ("in the middle of it" after "in the back middle").
_UNORDERED = frozenset({"in", "at", "to", "of", "side"})
#: Verbs by which a sentence asks for something of its own.
_VERBS = frozenset({"put", "place", "move", "stack", "make", "set", "arrange", "build", "pile", "stick", "stand", "turn",
                    "rotate", "swap", "switch", "take", "leave", "keep", "get", "bring", "pop", "slide", "shift",
                    "push", "pull", "lay", "line", "form", "group", "gather", "flip", "spin", "face", "point",
                    "don't", "do", "not", "never", "except", "but", "without", "only"})
_PURPOSE_SUBJECTS = frozenset({"i", "we", "you", "they", "it", "that", "everyone", "people", "he", "she"})


def repaired(text: str) -> str:
    """``text`` with its typed repairs made, its restarts joined and its echoes taken out."""
    return echoes(restarts(typed_repairs(text)))


def _marker_at(words: Sequence[str], k: int) -> int:
    """The end of a repair marker starting at ``k`` (with its hesitations and further markers), or ``k``."""
    j = k
    while j < len(words):
        for phrase in lexicon.REPAIR_MARKERS:
            if tuple(words[j : j + len(phrase)]) == phrase:
                j += len(phrase)
                break
        else:
            if j > k and (words[j] in lexicon.HESITATIONS or words[j] in (",", "-", "\u2014")):
                j += 1
                continue
            return j
    return j


def fragment_kind(words: Sequence[str]) -> str | None:
    """The kind of a repair's fragment (its filler words taken out): facing, place, measure, number, or None."""
    if not words or len(words) > 8:
        return None
    if words[0] in _FACE_VERBS and len(words) > 1 and all(w in _FACING_REST for w in words[1:]):
        return "facing"
    rest = _place_words(words)
    if rest and all(w in _PLACE_WORDS for w in rest) and any(w in lexicon.ROWS or w in lexicon.COLS for w in rest):
        return "place"
    num = _number(list(words), 0)
    if num is not None:
        after = words[num[1] :]
        if any(w in lexicon.UNITS for w in after):
            return "measure" if find_measures(" ".join(words)) else None
        if all(w in _NUMBER_ROLE for w in after):
            return "number"
    return None


def _place_words(words: Sequence[str]) -> Sequence[str]:
    """``words`` without the prepositions and the article that lead a place ("in the back left": back left)."""
    i = 0
    while i < len(words) and words[i] in _PLACE_LEAD:
        i += 1
    return words[i:]


def _last_facing(toks: Sequence[Token], end: int) -> tuple[int, int] | None:
    """The character span of the last facing said before token ``end`` ("facing away from me")."""
    for i in range(end - 1, -1, -1):
        if toks[i].text in _FACE_VERBS:
            j = i + 1
            while j < end and toks[j].text in _FACING_REST:
                j += 1
            if j > i + 1:
                return toks[i].start, toks[j - 1].end
    return None


def _last_place(toks: Sequence[Token], end: int) -> tuple[int, int] | None:
    """The character span of the last place said before token ``end`` ("near right corner" of "in the near right
    corner"): a run of place words after a preposition, with a row or column word, not a relation ("left of")."""
    i = end - 1
    while i >= 0:
        if toks[i].text not in _PLACE_WORDS:
            i -= 1
            continue
        s = i
        while s > 0 and toks[s - 1].text in _PLACE_WORDS:
            s -= 1
        run = [t.text for t in toks[s : i + 1]]
        lead = s - 1 - (s > 0 and toks[s - 1].text == "the")
        after = toks[i + 1].text if i + 1 < len(toks) else ""
        if (lead >= 0 and toks[lead].text in _PLACE_LEAD and after != "of"
                and any(w in lexicon.ROWS or w in lexicon.COLS for w in run)):
            return toks[s].start, toks[i].end
        i = s - 1
    return None


def _last_number(text: str, end: int) -> tuple[int, int, int, int] | None:
    """The last measure said before character ``end``: the character span of its number, then of the whole
    measure."""
    found = [m for m in find_measures(text[:end]) if m.end <= end]
    if not found:
        return None
    m = found[-1]
    toks = tokenize(m.text)
    ws = [t.text for t in toks]
    for i in range(len(ws)):
        got = _number(ws, i)
        if got is not None:
            return m.start + toks[i].start, m.start + toks[got[1] - 1].end, m.start, m.end
    return None


def typed_repairs(text: str) -> str:
    """``text`` with each repair whose fragment is a facing, a place, a measure or a measure's number made: the
    fragment replaces the last thing of its kind before the marker; the marker and the fragment go."""
    for _ in range(8):
        toks = tokenize(text)
        words = [t.text for t in toks]
        for k in range(len(words)):
            if k and words[k - 1] not in _BREAKS:
                continue
            j = _marker_at(words, k)
            if j == k:
                continue
            e = j
            while e < len(words) and words[e] not in _STOPS and words[e] != ",":
                e += 1
            frag = [w for w in words[j:e] if w not in _FILLERS]
            kind = fragment_kind(frag)
            if kind is None or e == j:
                continue
            cut = k - 1 if k else k  # the stop or comma before the marker goes with it
            while cut > 0 and words[cut - 1] in _BREAKS:
                cut -= 1
            cut_at = toks[cut].start if k else 0
            new = text[toks[j].start : toks[e - 1].end]
            old: tuple[int, int] | None = None
            if kind == "facing":
                old = _last_facing(toks, cut)
            elif kind == "place":
                old = _last_place(toks, cut)
                lead = len(words[j:e]) - len(_place_words(words[j:e]))
                new = text[toks[j + lead].start : toks[e - 1].end] if lead < e - j else new
            else:
                num = _last_number(text, cut_at)
                if num is not None and kind == "number":
                    got = _number(words, j)
                    old = (num[0], num[1])
                    new = text[toks[j].start : toks[got[1] - 1].end] if got else new
                elif num is not None:
                    old = (num[2], num[3])
            if old is None or old[1] > cut_at:
                continue
            text = text[: old[0]] + new + text[old[1] : cut_at] + text[toks[e - 1].end :]
            break  # one repair made: read the text again
        else:
            break  # no repair left
    return text


def restarts(text: str) -> str:
    """``text`` with a sentence that ends on a relation word which the next one starts with and goes on from
    joined to it ("put the mug right. Right of the bowl": "put the mug right of the bowl")."""
    toks = tokenize(text)
    words = [t.text for t in toks]
    for i in range(len(words) - 3, 0, -1):
        if (words[i] in _RELATION and words[i + 1] in _STOPS and words[i + 2] == words[i]
                and words[i + 3] in ("of", "the", "side")):
            text = text[: toks[i].start] + text[toks[i + 2].start :]
    return text


def _sentences(toks: Sequence[Token]) -> list[tuple[int, int]]:
    """The token ranges of the sentences (each with its stop)."""
    out: list[tuple[int, int]] = []
    s = 0
    for i, t in enumerate(toks):
        if t.text in _STOPS and (i + 1 == len(toks) or toks[i + 1].text not in _STOPS):
            out.append((s, i + 1))
            s = i + 1
    if s < len(toks):
        out.append((s, len(toks)))
    return out


def _canonical(words: Sequence[str]) -> list[str]:
    """The words of a sentence as an echo compares them: numbers by value, words said the same by one word,
    plurals by their singular."""
    out: list[str] = []
    i = 0
    while i < len(words):
        num = None if words[i] in lexicon.ECHO_NEUTRAL else _number(list(words), i)
        if num is not None:
            out.append(f"{num[0]:g}")
            i = num[1]
            continue
        w = lexicon.SAME_WORD.get(words[i], words[i])
        out.append(w[:-1] if len(w) > 3 and w.endswith("s") and not w.endswith("ss") else w)
        i += 1
    return out


def _said_again(content: Sequence[str], before: Sequence[str]) -> bool:
    """Whether every word of ``content`` is in the sentence ``before``, in the same order but for place words
    ("cup: left of bottle. Bottle: left of cup." says something else)."""
    if not set(content) <= set(before):
        return False
    ordered = [w for w in content if w not in _PLACE_WORDS and w not in _UNORDERED]
    ordered = [w for n, w in enumerate(ordered) if not n or ordered[n - 1] != w]
    pos = 0
    for w in ordered:
        try:
            pos = before.index(w, pos) + 1
        except ValueError:
            return False
    return True


def _dash_runs(text: str) -> list[tuple[int, int]]:
    """The character spans of the dashes of ``text`` that set off an aside ("--", an em or en dash, a lone "-"
    with spaces)."""
    runs: list[tuple[int, int]] = []
    i = 0
    while i < len(text):
        if text[i] in "-\u2014\u2013":
            j = i
            while j < len(text) and text[j] in "-\u2014\u2013":
                j += 1
            if j - i > 1 or text[i] != "-" or (text[i - 1 : i] in (" ", "") and text[j : j + 1] in (" ", "")):
                runs.append((i, j))
            i = j
        else:
            i += 1
    return runs


def _dash_echoes(text: str) -> str:
    """``text`` without an aside set off by dashes that only says again what its sentence said before it ("the
    third can from the left -- hmm, from the left, yeah -- put it ...")."""
    runs = _dash_runs(text)
    for (a0, a1), (b0, b1) in zip(runs, runs[1:]):
        inner = tokenize(text[a1:b0])
        head = text[:a0]
        cut = max(head.rfind(c) for c in ".!?;")
        before = [t.text for t in tokenize(head[cut + 1 :]) if t.kind != "punct"]
        if not before or any(t.text in _STOPS for t in inner):
            continue
        words = [t.text for t in inner if t.kind != "punct"]
        if words and _echo(words, False, [_canonical(before)]):
            return _dash_echoes(head.rstrip() + ", " + text[b1:].lstrip())
    return text


def echoes(text: str) -> str:
    """``text`` without the sentences after the first that only say again what one sentence before said, and
    without asides between dashes that only say again what their sentence said."""
    text = _dash_echoes(text)
    toks = tokenize(text)
    sents = _sentences(toks)
    drop: list[tuple[int, int]] = []
    seen: list[list[str]] = []
    for n, (a, b) in enumerate(sents):
        words = [t.text for t in toks[a:b] if t.kind != "punct"]
        if n and _echo(words, toks[b - 1].text == "?", seen):
            drop.append((toks[a].start, toks[b - 1].end))
            continue
        seen.append(_canonical(words))
    for lo, hi in reversed(drop):
        text = text[:lo].rstrip() + (" " if text[hi:].strip() else "") + text[hi:].lstrip()
    return text


def _echo(words: list[str], question: bool, seen: Sequence[Sequence[str]]) -> bool:
    """Whether a sentence of ``words`` only says again what one of the sentences ``seen`` said."""
    if question:
        for tag in lexicon.QUESTION_TAGS:
            if tuple(words[-len(tag) :]) == tag:
                words = words[: -len(tag)]
                break
    for i, w in enumerate(words):
        if w == "so" and i + 1 < len(words) and words[i + 1] in _PURPOSE_SUBJECTS | {"that"} and i:
            if not lexicon.says(" ".join(words[i + 1 :]), "goal"):
                words = words[:i]
            break
    if any(w in _VERBS for w in words) or len(words) > 12:
        return False
    canon = _canonical(words)
    # a preposition that leads a place says nothing of its own ("anywhere on the left side is fine")
    lead = {n for n, w in enumerate(canon) if w in _PLACE_LEAD and any(
        x in _PLACE_WORDS for x in canon[n + 1 : n + 3])}
    content = [w for n, w in enumerate(canon) if n not in lead and w not in lexicon.ECHO_NEUTRAL
               and w not in lexicon.TABLE_WORDS]
    if not content:
        return bool(words) and all(w in lexicon.ECHO_NEUTRAL for w in words)
    return any(_said_again(content, before) for before in seen)
