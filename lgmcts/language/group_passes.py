"""Token passes over a group said by its size: "all but two of the blocks" (how many of it are taken), a
sentence that only narrows the group of the sentence before ("line up the blocks. oh, only the blue and the
green ones"), "the one ..." said again after one object ("the farther bottle, the one at the back, ...") and sides
given to a list "respectively", and a reference put first with a command about it by a pronoun after it ("all the
bowls except the white one put those in a line"). Run by :meth:`.rules._Parser._command_words` with the other token passes (:mod:`.passes`)."""

from __future__ import annotations

from ..errors import InputError
from .clauses import _COMMAND_VERBS, _GOAL_WORDS, _sentences
from .grounding import NUMBERS
from .host import ParserHost
from .matcher import FILLERS, STOPWORDS, _stem
from .passes import _NOT_JOIN
from .positions import _SIDES


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

    def _restated_one(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """"the farther bottle, the one at the back, right of the knife": "the one" said between commas after a
        reference to one object, with only words of where it stands, says the same object again and is left
        out (read as a place it would be a second, wrong goal)."""
        if not any(words[k : k + 3] == (",", "the", "one") for k in range(len(words))):
            return words
        try:
            found = self._find(words)
        except InputError:
            return words
        ends = {m.end: m for m in found}
        k = 0
        out = list(words)
        while k < len(out):
            before = ends.get(k)
            if out[k] == "," and out[k + 1 : k + 3] == ["the", "one"] and before is not None \
                    and before.det == "ids" and len(before.ids) == 1:
                j = next((e for e in range(k + 3, min(len(out), k + 12)) if out[e] == ","), None)
                if j is not None and j > k + 3 and j + 1 < len(out) and all(
                        w in _WHERE_WORDS for w in out[k + 3 : j]) and self._stands_so(before.ids[0], out[k + 3 : j]):
                    del out[k:j]
                    break
            k += 1
        return tuple(out)

    def _stands_so(self, oid: int, said: list[str]) -> bool:
        """Whether object ``oid`` is the one of its kind furthest toward the one side ``said`` names ("at the
        back", "on the left", "closest to me"); refused where it is another, False where no one side is said."""
        sides = {_SIDES[w] for w in said if w in _SIDES and _SIDES[w].kind in ("x", "y")}
        if len(sides) != 1:
            return False
        key = sides.pop()  # which way along x or y is first (references by position read the same keys)
        axis = 0 if key.kind == "x" else 1
        obj = next(o for o in self.spec.objects if o.id == oid)
        kind = [o for o in self.spec.objects if o.name == obj.name and o.pose is not None and o.on is None]
        if obj.pose is None or obj not in kind:
            return False
        best = min(kind, key=lambda o: key.sign * float(o.pose[axis]))  # type: ignore[index]
        if best.id != oid:
            raise InputError(f"'the one {' '.join(said)}' is not the {obj.name} named before it; say which one")
        return True

    def _respectively(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """"place the red and blue blocks to the left and right of the white bowl, respectively": each object
        of the list to its side, in the order said (one relation each; "the letters A and T shall be positioned
        to the left and to the right of the bowl" too, a verb said of the list being only stopwords and
        fillers). Refused where the list and the sides are not as many."""
        if "respectively" not in words:
            return words
        k = words.index("respectively")
        s = max((j + 1 for j in range(k) if words[j] in (".", ";", "!", "?")), default=0)
        try:
            found = list(self._find(words[s:k]))
        except InputError:
            return words
        if len(found) < 2 or found[-1].start == 0 or words[s + found[-1].start - 1] not in ("of", "behind"):
            return words
        anchor, subjects = found[-1], found[:-1]
        said = words[s + subjects[-1].end : s + anchor.start - (words[s + anchor.start - 1] == "of")]
        # "... shall be positioned to the left and to the right of ...": the verb before the sides goes
        lead = next((n for n, w in enumerate(said) if w in _SIDE_OF or w not in STOPWORDS | FILLERS), len(said))
        said = said[lead:]
        sides = [_SIDE_OF[w] for w in said if w in _SIDE_OF]
        if not sides or any(w not in _SIDE_OF and w not in ("to", "the", "and", ",", "in", "on", "its") for w in said):
            return words
        ids: list[int] = []
        for m in subjects:
            got = self._select(m)
            if not isinstance(got, list):
                return words
            if m.color_order and len(m.color_order) == len(got):
                colour = {o.id: o.color for o in self.spec.objects}
                got = sorted(got, key=lambda i: next((n for n, c in enumerate(m.color_order) if colour[i] == c), 0))
            ids.extend(got)
        if len(ids) != len(sides):
            raise InputError(f"'{' '.join(words[s:k + 1])}': {len(ids)} objects and {len(sides)} sides said "
                             f"respectively; give each object one side")
        of = words[s + anchor.start : s + anchor.end]
        out: list[str] = list(words[:s + subjects[0].start])
        for n, (i, side) in enumerate(zip(ids, sides)):
            out += (["and"] if n else []) + ["object", str(i), *side, *(() if side == ("behind",) else ("of",)), *of]
        rest = list(words[s + anchor.end : k]) + list(words[k + 1 :])
        while rest[:1] == [","]:
            rest = rest[1:]
        return tuple(out + rest)

    def _topic_split(self, clause: tuple[str, ...]) -> list[tuple[str, ...]]:
        """"the bowls, stack them with the white one at the bottom", "the green can
        move it so ...": a reference put first, then a command about it by a pronoun."""
        start = 2 if clause[:2] == ("you", "know") else 0
        try:
            ms = self._find(clause[start:])
        except InputError:
            return [clause]
        if not ms or ms[0].start != 0 or ms[0].det == "pronoun":
            return [clause]
        end = ms[0].end
        for m in ms[1:]:
            # "the purple block and the green one stack them ...": a topic of several references
            if m.start == end + 1 and clause[start + end] == "and" and m.det != "pronoun":
                end = m.end
            else:
                break
        j = start + end
        while j < len(clause) and clause[j] in (",", "and", "so", "then"):
            j += 1
        while j < len(clause) and clause[j] in ("just", "please", "now", "then", "can", "could", "you"):
            j += 1
        rest = clause[j:]
        # "those"/"these" standing alone are pronouns too ("... put those in a line"), not before a noun
        said = tuple("them" if w in ("those", "these") and not (rest[k + 1 : k + 2] and (
            rest[k + 1] in self._cat_words or _stem(rest[k + 1]) in self._cat_words)) else w
            for k, w in enumerate(rest))
        if (rest and (rest[0] in _COMMAND_VERBS or rest[0] in ("it", "they", "them") or (
                rest[0].isalpha() and rest[0] not in STOPWORDS and rest[0] not in _GOAL_WORDS
                and rest[0] not in _NOT_JOIN and said[1:2] in (("it",), ("them",))))
                and any(w in ("it", "them", "they") for w in said[:6])):
            return [clause[start : start + end], rest]
        if (end == ms[0].end and clause[start + end : start + end + 1] == (",",) and rest
                and any(w in ("it", "them", "they", "those", "these") for w in rest)):
            # "the tiger pan, the star must be sitting on top of it", "the plate, you
            # are putting the spoon next to it": a topic, then a sentence about it.
            return [clause[start : start + end], rest]
        return [clause]


#: Words that say where an object stands ("the one at the back", "the one closest to me").
_WHERE_WORDS = frozenset({"at", "on", "in", "to", "by", "the", "back", "front", "left", "right", "far", "near", "rear",
                          "end", "side", "corner", "middle", "centre", "center", "top", "bottom", "closest", "nearest",
                          "furthest", "farthest", "me", "us", "you", "over", "there", "that's", "which", "is",
                          "sitting", "standing", "further", "farther", "closer", "nearer", "edge", "hand", "more"})

#: A side said in a list given "respectively", as the words of a relation.
_SIDE_OF = {"left": ("to", "the", "left"), "right": ("to", "the", "right"), "front": ("in", "front"),
            "behind": ("behind",), "back": ("behind",)}
