"""Misspellings and informal spellings, corrected before the command is read.

A pure stage on the command's text: :func:`correct_text` returns the text
with each misspelt word replaced, and nothing else touched. Conservative on
purpose, since a wrong correction is a wrong goal:

* a word the parser knows (the scene's names and colours, the pattern
  database's words, the parser's own closed-class words) is never changed,
  so "bowl" never becomes "box" even in a scene with a box and no bowl;
* informal spellings come from a short table (:data:`INFORMAL`: "teh",
  "infront", "cn", "b4" ...);
* a word that is no English word (not a whole word of the sentence model's
  vocabulary) is corrected when exactly one known word lies one edit away
  (an insertion, a deletion, a substitution or two neighbouring letters
  swapped: "recangle", "behnd", "circel", "purpel"), two edits for words of
  eight letters or more; of two known words at the same distance, the one
  the word is with a letter left out wins ("stak": stack, not star), and
  then the one the word is with a letter typed twice ("bowll": bowl, not
  bowls), then the one of the scene's own words ("forc": fork where the
  scene has a fork); any other tie leaves the word as it is;
* a rare English word (:data:`RARE_RANK`) one dropped letter away from
  exactly one of the scene's names or colours or a pattern noun is that word
  ("blu" blue, "hart" heart when the scene has a heart, "lin" line);
  a common word is never corrected; a three-letter word only ever becomes a
  colour or a pattern noun;
* a word that is no English word and is exactly one of the scene's words, colours or
  pattern nouns with some of its vowels left out is that word ("orng" orange, "prpl"
  purple, "bwl" bowl); a plural said with a final z is the plural ("bowlz").

Words of one or two letters and numbers are left alone.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Collection
from functools import lru_cache

__all__ = ["INFORMAL", "RARE_RANK", "SOUNDS_LIKE", "Corrector", "correct_text", "edit_distance", "english_rank"]

#: Informal spellings with one reading, whole words only.
INFORMAL: dict[str, str] = {
    "teh": "the", "hte": "the", "infront": "in front", "cn": "can", "b4": "before", "bc": "because",
    "cuz": "because", "coz": "because", "nxt": "next", "abt": "about", "tmrw": "tomorrow", "ppl": "people",
    "pl0x": "please", "plss": "please", "pleasee": "please", "ontop": "on top", "frm": "from", "wth": "with",
    "betwen": "between", "behing": "behind", "alot": "a lot", "bttm": "bottom", "btm": "bottom",
    "lft": "left", "rght": "right", "cntr": "centre", "ctr": "centre", "rite": "right", "cud": "could",
    "wud": "would", "shud": "should", "thx": "thanks", "thnx": "thanks", "bhind": "behind", "frnt": "front",
    # contractions typed (or transcribed) without their apostrophe, and "em" for "them"
    "doesnt": "doesn't", "dont": "don't", "thats": "that's", "itd": "it'd", "itll": "it'll", "shes": "she's",
    "im": "i'm", "ive": "i've", "youre": "you're", "theyre": "they're", "isnt": "isn't", "wont": "won't",
    "whats": "what's", "theres": "there's", "wouldnt": "wouldn't", "couldnt": "couldn't", "shouldnt": "shouldn't",
    "didnt": "didn't", "arent": "aren't", "hasnt": "hasn't", "havent": "haven't", "em": "them", "ya": "you",
    # texting: "fork knife n spoon", "ur", "plz"
    "n": "and", "ur": "your", "plz": "please", "rn": "now", "tho": "though", "thre": "three",
    # ordinals in figures: "the 2nd can from the left"
    # shorthand for "except": "all the letters exc the T"
    "exc": "except", "excl": "except", "xcept": "except", "exept": "except", "excpet": "except", "excpt": "except",
    "exsept": "except", "eksept": "except", "smal": "small", "smol": "small", "smll": "small", "larg": "large",
    "lrg": "large", "medum": "medium", "meduim": "medium", "mediun": "medium", "frunt": "front", "lain": "line",
    "bowlz": "bowls",
    "2gether": "together", "u": "you", "k": "okay", "kk": "okay", "ty": "thanks", "tysm": "thanks",
    "1st": "first", "2nd": "second", "3rd": "third", "4th": "fourth", "5th": "fifth", "6th": "sixth",
}
#: Words that sound like one of the scene's names: the name, but only where the scene has it ("plait" is
#: "plate" on a table with a plate).
SOUNDS_LIKE: dict[str, str] = {
    "plait": "plate", "plaits": "plates", "bowel": "bowl", "bowels": "bowls", "nife": "knife", "nives": "knives",
    "mugg": "mug", "kup": "cup", "cerial": "cereal", "bottel": "bottle", "phon": "phone", "telephone": "phone",
    "cellphone": "phone", "smartphone": "phone", "boles": "bowls", "bole": "bowl", "lyne": "line", "spun": "spoon",
    "bol": "bowl", "bols": "bowls",
}
#: Homophones read by the next word: "read" is "red", "blew" "blue" and "too"/"for" are "two"/"four" before a
#: thing of the scene ("the read bowl", "the blew can", "too cans", "for blocks"); "write" is "right" before "of" or after "the"/"to".
_BEFORE_A_THING = {"read": "red", "blew": "blue", "too": "two", "for": "four", "won": "one"}
#: Those of :data:`_BEFORE_A_THING` that sound like a colour ("the read bowl", "the blew can").
_COLOUR_SOUNDS = frozenset({"red", "blue"})
_SIDE_SOUNDS = {"write": "right", "rite": "right", "wright": "right"}
#: Words after which a "2" said between words is "to" ("closest 2 me", "2 the right", "needs 2 be").
_AFTER_TO = frozenset({"the", "me", "us", "be", "look", "you", "u", "my", "them", "its", "their", "face", "point",
                       "his", "her", "left", "right"})
#: English words with a vocabulary rank above this are rare enough to be a dropped-letter slip.
RARE_RANK = 7000

_WORD = re.compile(r"[A-Za-z]*\d[A-Za-z\d]*|[A-Za-z]+(?:'[A-Za-z]+)?")


def edit_distance(a: str, b: str, cap: int = 3) -> int:
    """Damerau-Levenshtein distance (adjacent swaps count one), stopped at ``cap``."""
    if abs(len(a) - len(b)) >= cap:
        return cap
    prev2: list[int] = []
    prev = list(range(len(b) + 1))
    for i in range(1, len(a) + 1):
        cur = [i] + [0] * len(b)
        for j in range(1, len(b) + 1):
            cost = a[i - 1] != b[j - 1]
            cur[j] = min(prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost)
            if i > 1 and j > 1 and a[i - 1] == b[j - 2] and a[i - 2] == b[j - 1]:
                cur[j] = min(cur[j], prev2[j - 2] + 1)
        if min(cur) >= cap:
            return cap
        prev2, prev = prev, cur
    return min(prev[-1], cap)


@lru_cache(maxsize=1)
def _english() -> dict[str, int]:
    """Whole words of the sentence model's WordPiece vocabulary with their rank (about by frequency)."""
    try:
        from .embed import weights_path

        lines = (weights_path() / "vocab.txt").read_text(encoding="utf-8").splitlines()
    except Exception:
        return {}
    return {w: k for k, w in enumerate(lines) if w.isalpha() and w.islower()}


_SUFFIXES = (("ies", "y"), ("ied", "y"), ("ing", ""), ("ing", "e"), ("ed", ""), ("ed", "e"), ("es", ""), ("s", ""),
             ("er", ""), ("er", "e"), ("est", ""), ("est", "e"), ("ly", ""), ("'s", ""), ("y", ""))


def english_rank(word: str) -> int | None:
    """The word's rank in the English vocabulary (smaller: more common), or None if it is none.

    An inflected form ("crowding", "stacked", "tidier") has the rank of its base word."""
    eng = _english()
    if word in eng:
        return eng[word]
    for suffix, repl in _SUFFIXES:
        if len(word) > len(suffix) + 2 and word.endswith(suffix):
            base = word[: -len(suffix)]
            for b in (base + repl, base[:-1] if len(base) > 3 and base[-1] == base[-2] else None):
                if b and b in eng:
                    return eng[b]
    return None


def _consonants(word: str) -> str:
    """The consonants of ``word`` in order, a doubled one once ("yellow": "ylw"; "bloo": "bl")."""
    out = ""
    for ch in word:
        if ch not in "aeiou" and not out.endswith(ch):
            out += ch
    return out


def _vowels_dropped(short: str, long: str) -> bool:
    """Whether ``short`` is ``long`` with some of its vowels left out, its first letter kept ("orng", "prpl")."""
    if len(short) < 3 or len(short) >= len(long) or short[0] != long[0]:
        return False
    k = 0
    for ch in long:
        if k < len(short) and ch == short[k]:
            k += 1
        elif ch not in "aeiou":
            return False
    return k == len(short)


def _doubled(long: str, short: str) -> bool:
    """Whether ``long`` is ``short`` with one of its letters typed twice ("bowll", "cupp")."""
    return len(long) == len(short) + 1 and any(
        long[k] == long[k - 1] and long[:k] + long[k + 1 :] == short for k in range(1, len(long)))


def _dropped_letter(short: str, long: str) -> bool:
    return len(long) == len(short) + 1 and any(long[:k] + long[k + 1 :] == short for k in range(len(long)))


_KEY_ROWS = ("qwertyuiop", "asdfghjkl", "zxcvbnm")
#: Letters beside each other on a keyboard row.
_NEIGHBOURS = {a: {row[k - 1] if k else "", row[k + 1] if k + 1 < len(row) else ""} - {""}
               for row in _KEY_ROWS for k, a in enumerate(row)}


def _key_slip(w: str, t: str) -> bool:
    """Whether ``w`` is ``t`` with one letter struck as its neighbour on the keyboard ("cip": cup)."""
    diff = [(a, b) for a, b in zip(w, t) if a != b]
    return len(w) == len(t) and len(diff) == 1 and diff[0][0] in _NEIGHBOURS.get(diff[0][1], set())


def _sound(w: str) -> str:
    """A rough key of how a word sounds: c and k alike, s before e/i/y as c, ph as f, a final -el as -le
    ("sirkle", "cirkel" and "circle" share one)."""
    w = w.replace("ph", "f").replace("ck", "c").replace("k", "c")
    if w[:1] == "s" and w[1:2] in ("e", "i", "y"):
        w = "c" + w[1:]
    return w[:-2] + "le" if w.endswith("el") else w


#: Words of a side that a preposition may be typed onto ("frontof", "nextto").
_SIDE_WORDS = frozenset({"front", "left", "right", "back", "next", "top", "behind", "close", "near"})


class Corrector:
    """Corrections against a fixed vocabulary.

    ``scene``: the scene's own words (names with their plurals, colours);
    ``lexicon``: the other words a misspelling may stand for (pattern words, directions,
    command verbs, measure words); ``protect``: words that are never changed and never
    a correction (fillers, chatter); ``nouns``: the pattern nouns, which with the
    scene's words are the only targets of a rare real word; ``colours``: colour
    words, which with the pattern nouns are the only targets of a three-letter
    non-word ("blu", "lin"; never an object's name: "ish" is not "dish"); ``rank``: the English
    rank of a word or None (:func:`english_rank` by default).
    """

    def __init__(self, scene: Collection[str], lexicon: Collection[str], nouns: Collection[str] = (),
                 rank: Callable[[str], int | None] = english_rank, protect: Collection[str] = (),
                 colours: Collection[str] = ()) -> None:
        self.scene = frozenset(w for w in scene if w.isalpha())
        self.targets = frozenset(w for w in lexicon if w.isalpha()) - self.scene
        self.known = self.scene | self.targets | frozenset(protect)
        self.nouns = frozenset(nouns) | self.scene
        self.colours = frozenset(colours)
        self.rank = rank

    def word(self, w: str) -> str:
        """The correction of one lower-case word (itself where none is sure)."""
        if w in self.known:
            return w
        if w in SOUNDS_LIKE and SOUNDS_LIKE[w] in self.scene:
            return SOUNDS_LIKE[w]
        if w in INFORMAL:
            return INFORMAL[w]
        if len(w) < 3:
            return w
        r = self.rank(w)
        if r is not None:
            if r < RARE_RANK:
                return w
            hits = [t for t in self.nouns if _dropped_letter(w, t)]
            return hits[0] if len(hits) == 1 else w
        if not w.isalpha():
            return w
        if w.endswith("z") and w[:-1] + "s" in self.scene:
            return w[:-1] + "s"  # "bowlz", "cupz": a plural said with a z
        skeleton = [t for t in self.scene | self.colours | self.nouns if _vowels_dropped(w, t)]
        if len(skeleton) == 1:
            return skeleton[0]  # "orng", "prpl", "grn": a scene word or colour with its vowels left out
        sounds_as = [t for t in self.colours if t[0] == w[0] and abs(len(t) - len(w)) <= 2
                     and len(_consonants(t)) >= 2 and _consonants(t) == _consonants(w)
                     and (len(w) > 3 or sorted(w) == sorted(t))]  # three letters: only two swapped ("rde", not "rad")
        if len(sounds_as) == 1:
            return sounds_as[0]  # "bloo", "yelo", "rde": a colour with its vowels spelt otherwise
        if len(w) == 3:
            hits = [t for t in self.nouns - self.scene | self.colours if _dropped_letter(w, t)]
            if not hits:  # "cip": a neighbouring key struck for one letter of a three-letter name ("cup")
                hits = [t for t in self.scene if len(t) == 3 and _key_slip(w, t)]
            return hits[0] if len(hits) == 1 else w
        sounds = {t for t in self.nouns | self.colours if len(t) > 3 and _sound(t) == _sound(w)}
        if len(sounds) == 1:
            return sounds.pop()  # "sirkle", "cirkel": spelt as it sounds
        cap = 2 if len(w) >= 8 else 1
        best: list[str] = []
        best_d = cap + 1
        for t in self.scene | self.targets:
            if len(t) < 3 or abs(len(t) - len(w)) > cap:
                continue
            d = edit_distance(w, t, cap + 1)
            if d < best_d:
                best, best_d = [t], d
            elif d == best_d:
                best.append(t)
        if best_d > cap:
            # "frontof", "leftof", "nextto": a side and its preposition typed without the space
            cut = next((n for n in range(2, len(w) - 1) if w[:n] in _SIDE_WORDS and w[n:] in ("of", "to")), 0)
            return f"{w[:cut]} {w[cut:]}" if cut else w
        if len(best) > 1:
            # A letter left out is the commonest slip ("stak" is "stack" before "star"), then a letter typed
            # twice ("bowll" is "bowl" before "bowls"), then the scene's own word ("forc" is "fork" on a table
            # with a fork, before "form").
            for prefer in (lambda t: _dropped_letter(w, t), lambda t: _doubled(w, t), lambda t: t in self.scene):
                if sum(map(prefer, best)) == 1:
                    return next(t for t in best if prefer(t))
            return w
        return best[0]

    def text(self, text: str) -> str:
        """``text`` with each misspelt word replaced (case kept for the first letter), the rest as it was."""

        found = [m for m in _WORD.finditer(text) if not (m.group(0) == "2" and text[m.end() : m.end() + 1] in ")].:")]
        said = [m.group(0).lower() for m in found]
        out: list[str] = []
        at = 0
        for k, m in enumerate(found):
            w = m.group(0)
            if m.start() and text[m.start() - 1] in "'\u2019":
                continue  # "'em", "'round": said with its apostrophe, read as it is
            if text[m.end() : m.end() + 1] == "/":
                continue  # "w/", "b/c": read by the rewrite table
            fixed = self._in_context(said, k) or self.word(w.lower())
            if fixed != w.lower():
                out.append(text[at : m.start()] + (fixed[0].upper() + fixed[1:] if w[0].isupper() else fixed))
                at = m.end()
        out.append(text[at:])
        return "".join(out)

    def _in_context(self, said: list[str], k: int) -> str | None:
        """A homophone read by its neighbours (:data:`_BEFORE_A_THING`, :data:`_SIDE_SOUNDS`), or None."""
        w = said[k]
        nxt = said[k + 1] if k + 1 < len(said) else ""
        nxt = self.word(nxt) if nxt and nxt not in self.known else nxt
        if w in _BEFORE_A_THING:
            want = _BEFORE_A_THING[w]
            if want in _COLOUR_SOUNDS and want in self.scene and (nxt in self.scene - self.colours
                                                                  or nxt in ("one", "ones")):
                return want
            if want in ("two", "four") and nxt.endswith("s") and nxt in self.scene - self.colours:
                return want
            if want == "one" and nxt in ("of", "more"):
                return want
        if w in _SIDE_SOUNDS and (nxt == "of" or (k and said[k - 1] in ("the", "to"))):
            return _SIDE_SOUNDS[w]
        if w == "w" and nxt in ("the", "a", "an", "one", "my", "its", "their", "his", "her", "them", "it", "any"):
            return "with"  # texting: "share a color w one of the bowls"
        if w == "2" and nxt in _AFTER_TO and k and not said[k - 1].isdigit():
            return "to"  # texting: "closest 2 me", "slide it 2 the right", "needs 2 be"
        return None


def correct_text(text: str, scene: Collection[str], lexicon: Collection[str], nouns: Collection[str] = (),
                 protect: Collection[str] = (), colours: Collection[str] = ()) -> str:
    """:meth:`Corrector.text` with a corrector built for this call."""
    return Corrector(scene, lexicon, nouns, protect=protect, colours=colours).text(text)
