"""Token passes over a group said by its size: "all but two of the blocks" (how many of it are taken) and a
sentence that only narrows the group of the sentence before ("line up the blocks. oh, only the blue and the
green ones"). Run by :meth:`.rules._Parser._command_words` with the other token passes (:mod:`.passes`)."""

from __future__ import annotations

from ..errors import InputError
from .clauses import _sentences
from .grounding import NUMBERS
from .host import ParserHost


def _count(word: str) -> int | None:
    """A small number said as a word or in figures ("two", "3"), or None."""
    n = 1 if word == "one" else NUMBERS.get(word) if not word.isdigit() else int(word)
    return n if n is not None and 0 < n < 20 else None


class _GroupPasses(ParserHost):
    """The passes of this module, a mixin of :class:`.rules._Parser`."""

    def _all_but(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """"all but two of the blocks", "all the blocks but two", "every can except one": a number of the
        group left out, said as how many of it are taken ("any 4 of the blocks": a free choice of that many).
        Refused where none would be left."""
        out = list(words)
        k = 0
        while k < len(out):
            n = None
            if out[k] == "all" and k + 3 < len(out) and out[k + 1] in ("but", "except") \
                    and out[k + 3] == "of" and _count(out[k + 2]) is not None:
                n, np_start, cut = _count(out[k + 2]), k + 4, (k, k + 4)  # "all but two of the blocks"
                np_end = np_start
                try:
                    ms = self._find(tuple(out[np_start:]))
                except InputError:
                    ms = []
                if ms and ms[0].start == 0 and ms[0].plural:
                    np_end = np_start + ms[0].end
            elif out[k] in ("all", "every", "each"):
                j = next((x for x in range(k + 2, min(k + 7, len(out) - 1)) if out[x] in ("but", "except")), None)
                try:
                    ms = self._find(tuple(out[k:j])) if j is not None else []
                except InputError:
                    ms = []
                if j is not None and len(ms) == 1 and ms[0].start == 0 and ms[0].end == j - k \
                        and _count(out[j + 1]) is not None and not (
                            j + 2 < len(out) and (self._object_word(out[j + 2]) or out[j + 2] == "of")):
                    n, np_start, np_end, cut = _count(out[j + 1]), k, j, (j, j + 2)  # "all the blocks but two"
            if n is None:
                k += 1
                continue
            try:
                group = self._find(tuple(out[np_start:np_end]))
            except InputError:
                group = []
            if len(group) != 1:
                k += 1
                continue
            left = len(self._every_match(group[0])) - n
            said = " ".join(out[min(cut[0], np_start) : max(cut[1], np_end)])
            if left < 1:
                raise InputError(f"'{said}' leaves no object to arrange")
            noun = tuple(w for w in out[np_start:np_end] if w not in ("all", "every", "each", "the"))
            new = ["any", str(left), "of", "the", *noun]
            lo, hi = min(cut[0], np_start), max(cut[1], np_end)
            out[lo:hi] = new
            k = lo + len(new)
        return tuple(out)

    def _only_these(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """A sentence that only narrows the group of the sentence before ("line up the blocks. oh, only the
        blue and the green ones"): the group said as the narrower one ("line up the blue and the green
        blocks"), where every object it names is one of the group's and the group is the sentence's only
        plural reference. Left as it is otherwise (and then refused, never dropped)."""
        sentences = _sentences(words, (".", "!", ";"))
        for k in range(1, len(sentences)):
            sent = [w for w in sentences[k] if w not in (".", "!", ";")]
            j = 0
            while j < len(sent) and sent[j] in ("oh", "ah", "um", "uh", "wait", "actually", ",", "but", "no", "sorry"):
                j += 1
            if j >= len(sent) or sent[j] not in ("only", "just"):
                continue
            narrow = tuple(sent[j + 1 :])
            rest: tuple[str, ...] = ()
            if "," in narrow[1:]:
                # "only the blue and the green ones, the rest can stay where they are": the rest is its own sentence
                cut = narrow.index(",", 1)
                narrow, rest = narrow[:cut], narrow[cut + 1 :] + tuple(w for w in sentences[k][-1:] if w in ".!;")
            try:
                before = [m for m in self._find(sentences[k - 1]) if m.plural and m.det != "pronoun"]
                if len(before) != 1:
                    continue
                noun = sentences[k - 1][before[0].end - 1]
                new = tuple(noun if w in ("ones", "one") else w for w in narrow)
                new = new if new[-1:] == (noun,) else new + (noun,)  # "the blue and the green (ones)": blocks
                said = self._find(new)
            except InputError:
                continue
            if not said or said[0].start != 0 or said[-1].end != len(new):
                continue
            group = set(self._every_match(before[0]))
            picked = {i for m in said for i in self._every_match(m)}
            if not picked or not picked <= group or picked == group:
                continue
            prev = sentences[k - 1]
            sentences[k - 1] = prev[: before[0].start] + new + prev[before[0].end :]
            sentences[k] = rest
        return tuple(w for s in sentences for w in s)
