"""Misspellings and informal spellings, corrected before the command is read.

A pure stage on the command's text: :func:`correct_text` returns the text
with each misspelt word replaced, and nothing else touched. Conservative on
purpose, since a wrong correction is a wrong goal:

* a word the parser knows (the scene's names and colours, the pattern
  database's words, the parser's own closed-class words) is never changed,
  so "bowl" never becomes "box" even in a scene with a box and no bowl;
* informal spellings come from a short table (:data:`INFORMAL`: "teh",
  "infront", "cn", "b4" ...), and a dialect's words from the lexicon's
  ``[dialect]`` table ("pit": put, "tae": to, "aw": all);
* a word that is no English word (not a whole word of the sentence model's
  vocabulary) is corrected when exactly one known word lies one edit away
  (an insertion, a deletion, a substitution or two neighbouring letters
  swapped: "recangle", "behnd", "circel", "purpel"), two edits for words of
  eight letters or more; of two known words at the same distance, the one
  the word is with a letter left out wins ("stak": stack, not star), and
  then the one the word is with a letter typed twice ("bowll": bowl, not
  bowls), then the one with two neighbouring letters swapped ("tabel": table,
  not label), then the one of the scene's own words ("forc": fork where the
  scene has a fork); any other tie leaves the word as it is;
* a rare English word (:data:`RARE_RANK`) one dropped letter away from
  exactly one of the scene's names or colours or a pattern noun is that word
  ("blu" blue, "hart" heart when the scene has a heart, "lin" line), or else
  two neighbouring letters swapped from exactly one known word ("handels");
  a common word is never corrected; a three-letter word only ever becomes a
  colour or a pattern noun;
* a word that is no English word and is exactly one of the scene's words with two neighbouring
  letters swapped is that word ("blcok": block, though "black" has the same consonants); else one
  that is exactly one of the scene's words, colours or pattern nouns with some of its vowels left
  out is that word ("orng" orange, "prpl"
  purple, "bwl" bowl); a plural said with a final z is the plural ("bowlz");
* a correction by a letter struck for another or one letter too many, into no word of the
  scene and no pattern noun, is not made where a common English word the parser does not know
  is one slip away too ("leter" is no "meter": it may be "later"; on a table with letters it is
  "letter", a letter left out);
* a three-letter word is a word of the parser with a letter left out ("sde": side) where no
  commoner English word is, or a three-letter name of the scene with two letters swapped ("mgu": mug);
* a word no nearer to any of those is one of the words the parser reads in its tables, or a
  protected word of four letters or more, by the commonest slips only: a letter left out, a
  letter typed twice or two neighbouring letters swapped ("requred", "respectivly", "shal",
  "positoned"), and not where a commoner English word is the same kind of slip away; or else an informal
  spelling of six letters or more by the same slips ("infornt": in front);
* else two words typed without the space, where exactly one cut gives two words the parser knows
  of three letters or more, one of them the scene's or the parser's own ("redcan", "frontedge",
  "putthe"), or a side and "of"/"to" ("frontof", "nextto"), or else a colour of the scene and one of its
  names with a letter left out ("bluebock").

An inflection read by :func:`english_rank` doubles the last consonant of a base of one syllable
("letter", never "leter"), and a word with "re" or "un" before an English word is English
("repositioned"). Words of one or two letters and numbers are left alone.
"""

from __future__ import annotations

import re
from collections.abc import Callable, Collection
from functools import lru_cache

from .lexicon import DIALECT

__all__ = ["INFORMAL", "RARE_RANK", "SOUNDS_LIKE", "Corrector", "correct_text", "edit_distance", "english_rank", "starred"]

#: Informal spellings with one reading, whole words only.
INFORMAL: dict[str, str] = {
    "teh": "the", "hte": "the", "infront": "in front", "infrontof": "in front of", "bak": "back", "kans": "cans",
    "lang": "long", "cn": "can", "b4": "before", "bc": "because",
    "cuz": "because", "coz": "because", "nxt": "next", "abt": "about", "tmrw": "tomorrow", "ppl": "people",
    "pl0x": "please", "plss": "please", "pleasee": "please", "ontop": "on top", "frm": "from", "wth": "with",
    "betwen": "between", "behing": "behind", "alot": "a lot", "bttm": "bottom", "btm": "bottom",
    "lft": "left", "rght": "right", "cntr": "centre", "ctr": "centre", "rite": "right", "cud": "could",
    "wud": "would", "shud": "should", "thx": "thanks", "thnx": "thanks", "bhind": "behind", "frnt": "front",
    # contractions typed (or transcribed) without their apostrophe, and "em" for "them"
    "doesnt": "doesn't", "dont": "don't", "thats": "that's", "itd": "it'd", "thatd": "that'd", "itll": "it'll", "shes": "she's",
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
    "bowlz": "bowls", "neer": "near",
    "2gether": "together", "u": "you", "k": "okay", "kk": "okay", "ty": "thanks", "tysm": "thanks", "ta": "thanks",
    "lil": "little", "lign": "line", "idc": "i don't care", "idk": "i don't know", "inchs": "inches",
    "lineup": "line up", "oclok": "o'clock", "oclock": "o'clock",
    # a short word run into "the": "behind ofthe plate"
    "ofthe": "of the", "tothe": "to the", "onthe": "on the", "inthe": "in the", "atthe": "at the",
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
#: Real words a phone's autocorrect puts for a word of place, read as that word only beside the words of a place
#: (the word, the words before it, the words after it): "lest of the bowl", "the back tight corner", "behold the plate".
_AUTOCORRECTED: dict[str, tuple[str, frozenset[str], frozenset[str]]] = {
    "lest": ("left", frozenset({"the", "to", "on", "far", "top", "bottom", "back", "front", "face", "facing", "point",
                                "pointing", "turned"}),
             frozenset({"of", "side", "corner", "edge", "hand", "end"})),
    "tight": ("right", frozenset({"to", "far", "top", "bottom", "back", "front"}),
              frozenset({"of", "side", "corner", "edge", "hand", "end"})),
    "behold": ("behind", frozenset(), frozenset({"the", "it", "them", "that", "each", "both", "my", "your"})),
    "font": ("front", frozenset({"in", "the", "to"}), frozenset({"of", "edge", "row", "corner", "left", "right"})),
}
#: Words after which a noun comes, so that a real word one slip from a scene noun there is that noun ("the cams").
_DETERMINERS = frozenset({"the", "both", "two", "three", "four", "all", "these", "those", "each", "every", "my"})
#: Known words that never follow "the" ("the for and knife": the fork).
_NEVER_AFTER_THE = frozenset({"for", "soon", "of", "to", "on"})
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


def _doubles_its_end(base: str) -> bool:
    """Whether ``base`` is one syllable ending in one vowel and one consonant ("let", "stop", "put"), whose last
    letter is doubled before an ending that starts with a vowel ("letter", "stopped"; never "leter")."""
    vowels = [k for k, ch in enumerate(base) if ch in "aeiou"]
    return len(base) >= 3 and len(vowels) == 1 and vowels[0] == len(base) - 2 and base[-1] not in "wxy"


def english_rank(word: str) -> int | None:
    """The word's rank in the English vocabulary (smaller: more common), or None if it is none.

    An inflected form ("crowding", "stacked", "tidier") has the rank of its base word, and so has the word
    said again or undone ("repositioned", "unstacked"); a base of one syllable ending in a vowel and a
    consonant doubles that consonant before an ending with a vowel ("letter", "putting"), so "leter" is no
    form of "let"; a base's silent "e" goes before such an ending ("facing"), so "faceing" is no form of
    "face"; and an adverb of a word in -al ends in -ally ("actually"), so "actualy" is none."""
    eng = _english()
    if word in eng:
        return eng[word]
    again = english_rank(word[2:]) if word[:2] in ("re", "un") and len(word) > 6 else None
    if again is not None:
        return again  # "repositioned", "unstacked": a word said again or undone
    for suffix, repl in _SUFFIXES:
        if len(word) > len(suffix) + 2 and word.endswith(suffix):
            base = word[: -len(suffix)]
            # a doubled last letter only before an ending with a vowel ("stopped", "bigger"; "bowlls" is no "bowls")
            doubled = len(base) > 3 and base[-1] == base[-2] and suffix[0] in "aeiouy"
            for b in (base + repl, base[:-1] if doubled else None):
                if b and b in eng and not (b == base and suffix[0] in "aeiouy" and (
                        _doubles_its_end(base) or (base[-1] == "e" and base[-2:-1] not in ("e", "o", "y"))
                        or (suffix == "y" and base.endswith("al")))):
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


def _swapped(w: str, t: str) -> bool:
    """Whether ``w`` is ``t`` with two neighbouring letters swapped ("mgu": mug)."""
    return len(w) == len(t) and any(w == t[:k] + t[k + 1] + t[k] + t[k + 2 :] for k in range(len(t) - 1)) and w != t


def _slip_of_informal(w: str) -> str | None:
    """The reading of the one informal spelling of six letters or more (:data:`INFORMAL`) that ``w`` is with
    two neighbouring letters swapped, a letter left out or one typed twice ("infornt": in front), or None."""
    hits = {v for k, v in INFORMAL.items() if len(k) >= 6 and abs(len(k) - len(w)) <= 1
            and (_swapped(w, k) or _dropped_letter(w, k) or _doubled(w, k))}
    return hits.pop() if len(hits) == 1 else None


def _one_edit(w: str) -> set[str]:
    """The strings one insertion, deletion, substitution or swap of neighbouring letters from ``w``."""
    letters = "abcdefghijklmnopqrstuvwxyz"
    cuts = [(w[:k], w[k:]) for k in range(len(w) + 1)]
    out = {a + b[1:] for a, b in cuts if b}
    out |= {a + b[1] + b[0] + b[2:] for a, b in cuts if len(b) > 1}
    out |= {a + c + b[1:] for a, b in cuts if b for c in letters}
    out |= {a + c + b for a, b in cuts for c in letters}
    return out - {w}


#: Words of a side that a preposition may be typed onto ("frontof", "nextto").
_SIDE_WORDS = frozenset({"front", "left", "right", "back", "next", "top", "behind", "close", "near", "side"})
#: The words of :attr:`Corrector.read` (and the protected ones) have this many letters or more.
_READ_LETTERS = 4


class Corrector:
    """Corrections against a fixed vocabulary.

    ``scene``: the scene's own words (names with their plurals, colours);
    ``lexicon``: the other words a misspelling may stand for (pattern words, directions,
    command verbs, measure words); ``protect``: words that are never changed (fillers, chatter),
    and a correction only as the words of ``read`` are; ``nouns``: the pattern nouns, which with the
    scene's words are the only targets of a rare real word; ``colours``: colour
    words, which with the pattern nouns are the only targets of a three-letter
    non-word ("blu", "lin"; never an object's name: "ish" is not "dish"); ``rank``: the English
    rank of a word or None (:func:`english_rank` by default); ``read``: more words the parser reads (those
    of its rewrite tables, "required", "respectively"), which with the protected words of four letters or
    more ("shall", "placed") a word is only by the commonest slips (:meth:`_slip_of_read`).
    """

    def __init__(self, scene: Collection[str], lexicon: Collection[str], nouns: Collection[str] = (),
                 rank: Callable[[str], int | None] = english_rank, protect: Collection[str] = (),
                 colours: Collection[str] = (), read: Collection[str] = (), slips: bool = False) -> None:
        self.scene = frozenset(w for w in scene if w.isalpha())
        self.targets = frozenset(w for w in lexicon if w.isalpha()) - self.scene
        self.known = self.scene | self.targets | frozenset(protect)
        # A protected word of four letters or more may be what a slip meant; a shorter one ("the", "its",
        # "lol") is too near too many slips to be one's correction.
        self.read = frozenset(w for w in (*read, *protect) if w.isalpha() and len(w) >= _READ_LETTERS) - self.targets \
            - self.scene
        self.nouns = frozenset(nouns) | self.scene
        self.colours = frozenset(colours)
        self.rank = rank
        #: Whether a real word one slip from a scene noun after "the" is that noun ("line up the cams"): for a
        #: second reading only, as "the cat", "the latter" and "my mum" are words of their own.
        self.slips = slips

    def word(self, w: str) -> str:
        """The correction of one lower-case word (itself where none is sure)."""
        if w in self.known:
            return w
        if w in SOUNDS_LIKE and SOUNDS_LIKE[w] in self.scene:
            return SOUNDS_LIKE[w]
        if w in INFORMAL:
            return INFORMAL[w]
        if w in DIALECT:
            return DIALECT[w]
        if len(w) < 3:
            return w
        r = self.rank(w)
        if r is not None:
            if r < RARE_RANK:
                return w
            hits = [t for t in self.nouns if _dropped_letter(w, t)] or [t for t in self.targets if _swapped(w, t)]
            return hits[0] if len(hits) == 1 else w
        if not w.isalpha():
            return w
        if w.endswith("z") and w[:-1] + "s" in self.scene:
            return w[:-1] + "s"  # "bowlz", "cupz": a plural said with a z
        swaps = [t for t in self.scene if _swapped(w, t)]
        if len(swaps) == 1:
            return swaps[0]  # "blcok": the block, before a colour with the same consonants ("black")
        skeleton = [t for t in self.scene | self.colours | self.nouns if _vowels_dropped(w, t)]
        if len(skeleton) == 1:
            return skeleton[0]  # "orng", "prpl", "grn": a scene word or colour with its vowels left out
        sounds_as = [t for t in self.colours if t[0] == w[0] and abs(len(t) - len(w)) <= 2
                     and len(_consonants(t)) >= 2 and _consonants(t) == _consonants(w)
                     and (len(w) > 3 or sorted(w) == sorted(t))]  # three letters: only two swapped ("rde", not "rad")
        if len(sounds_as) == 1:
            return sounds_as[0]  # "bloo", "yelo", "rde": a colour with its vowels spelt otherwise
        if len(w) == 3:
            return self._three_letters(w)
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
            return self._slip_of_read(w) or _slip_of_informal(w) or self._run_together(w) or w
        fixed = w
        if len(best) > 1:
            # A letter left out is the commonest slip ("stak" is "stack" before "star"), then a letter typed
            # twice ("bowll" is "bowl" before "bowls"), then two neighbouring letters swapped ("tabel" is "table"
            # before "label"), then the scene's own word ("forc" is "fork" on a table with a fork, before "form").
            for prefer in (lambda t: _dropped_letter(w, t), lambda t: _doubled(w, t), lambda t: _swapped(w, t),
                           lambda t: t in self.scene):
                if sum(map(prefer, best)) == 1:
                    fixed = next(t for t in best if prefer(t))
                    break
        else:
            fixed = best[0]
        return fixed if best_d > 1 or self._beats_english(w, fixed) else w

    def _beats_english(self, w: str, fixed: str) -> bool:
        """Whether ``fixed``, one slip from ``w``, stands against the common English words (:data:`RARE_RANK`)
        the parser does not know one slip from ``w`` too: the scene's own word or a pattern noun does ("leter"
        is "letter" on a table with letters, "lyne" a line), and so does a word ``w`` is with a letter left out,
        typed twice or two neighbouring letters swapped, the commonest slips ("stck" is "stack", though "stick"
        is as near; "lien" a line); a letter struck for another or one too many only where no such English
        word is near ("leter" is no "meter" on a table without letters: it may be "later")."""
        if fixed == w or fixed in self.nouns or _dropped_letter(w, fixed) or _doubled(w, fixed) or _swapped(w, fixed):
            return True
        eng = _english()
        return not any(eng.get(c, RARE_RANK) < RARE_RANK and c not in self.known for c in _one_edit(w))

    def _slip_of_read(self, w: str) -> str | None:
        """The one word of :attr:`read` that ``w`` is with a letter left out, a letter typed twice or two
        neighbouring letters swapped ("requred": required, "shal": shall, "plcaed": placed), where no commoner
        English word the parser does not know is so near ("ples" is no "piles": it may be "poles"; "shal" is
        "shall", not the rarer "shale"), or None."""
        def slip(t: str) -> bool:
            return _dropped_letter(w, t) or _doubled(w, t) or _swapped(w, t)

        hits = [t for t in self.read if abs(len(t) - len(w)) <= 1 and slip(t)]
        return hits[0] if len(hits) == 1 and not self._commoner(w, hits[0], slip) else None

    def _commoner(self, w: str, hit: str, slip: Callable[[str], bool]) -> bool:
        """Whether an English word the parser does not know, commoner than ``hit``, is the same kind of
        ``slip`` from ``w``."""
        eng = _english()
        rank = self.rank(hit)
        return any(c in eng and c not in self.known and c != hit and slip(c) and (rank is None or eng[c] < rank)
                   for c in _one_edit(w))

    def _three_letters(self, w: str) -> str:
        """A three-letter word that is no English word: a letter left out of a colour, a pattern noun or a word
        of the parser other than an object's name ("blu", "lin", "sde": side, no commoner English word being
        a letter longer; "ish" never "dish"); else one
        slip in a three-letter name of the scene, a neighbouring key struck ("cip": cup) or two neighbouring
        letters swapped ("mgu": mug). Only where exactly one word is so near."""
        hits = [t for t in (self.nouns | self.targets | self.colours) - self.scene | self.colours
                if _dropped_letter(w, t)]
        if len(hits) == 1 and hits[0] in self.targets - self.nouns - self.colours and self._commoner(
                w, hits[0], lambda t: _dropped_letter(w, t)):
            return w  # a word of the parser's only where no commoner English word is as near
        if not hits:
            hits = [t for t in self.scene if len(t) == 3 and (_key_slip(w, t) or _swapped(w, t))]
        return hits[0] if len(hits) == 1 else w

    def _run_together(self, w: str) -> str | None:
        """Two words typed without the space between them ("redcan", "frontedge", "putthe"), or None: the one way
        to cut ``w`` into two words the parser knows, of three letters or more each, one of them the scene's or
        the parser's own (not only a filler or a stopword); a word of two letters only as "of" or "to" after a
        side ("frontof", "nextto"), since "in", "on", "up" begin and end too many words ("inlay", "headin")."""
        cuts = [(w[:n], w[n:]) for n in range(3, len(w) - 2) if w[:n] in self.known and w[n:] in self.known
                and (w[:n] in self.scene or w[:n] in self.targets or w[n:] in self.scene or w[n:] in self.targets)]
        cuts += [(w[:-2], w[-2:])] if w[:-2] in _SIDE_WORDS and w[-2:] in ("of", "to") else []
        if not cuts:
            # "bluebock": a colour of the scene, then one of its names with a letter left out
            names = [t for t in self.scene - self.colours if len(t) > 3]
            for n in range(3, len(w) - 2):
                if w[:n] in self.colours and w[:n] in self.scene:
                    hits = [t for t in names if _dropped_letter(w[n:], t)]
                    cuts += [(w[:n], hits[0])] if len(hits) == 1 else []
        return " ".join(cuts[0]) if len(cuts) == 1 else None

    def text(self, text: str) -> str:
        """``text`` with each misspelt word replaced (case kept for the first letter), the rest as it was."""

        found = [m for m in _WORD.finditer(text) if not (m.group(0) == "2" and text[m.end() : m.end() + 1] in ")].:")]
        said = [m.group(0).lower() for m in found]
        out: list[str] = []
        at = 0
        for k, m in enumerate(found):
            w = m.group(0)
            if m.start() and text[m.start() - 1] in "'\u2019":
                if "'" + w.lower() in DIALECT:  # "'cept": a dialect's word said with its apostrophe
                    out.append(text[at : m.start() - 1] + DIALECT["'" + w.lower()])
                    at = m.end()
                continue  # "'em", "'round": said with its apostrophe, read as it is
            if text[m.end() : m.end() + 1] == "/":
                continue  # "w/", "b/c": read by the rewrite table
            if w.lower().endswith("in") and text[m.end() : m.end() + 1] in ("'", "\u2019") and len(w) > 3 and (
                    self.rank(w.lower() + "g") is not None):  # "matchin'", "pointin'": a dropped g
                out.append(text[at : m.start()] + w + "g")
                at = m.end() + 1
                continue
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
        prev = said[k - 1] if k else ""
        if w in _AUTOCORRECTED and (prev in _AUTOCORRECTED[w][1] or nxt in _AUTOCORRECTED[w][2]):
            return _AUTOCORRECTED[w][0]  # a phone's autocorrect: "put it lest of the bowl", "behold the plate"
        if self.slips and (prev in _DETERMINERS or prev in self.colours) and w.isalpha() and len(w) >= 3 and (w not in self.known or w in _NEVER_AFTER_THE):
            near = [t for t in self.scene - self.colours if edit_distance(w, t, 2) == 1 and len(t) >= 3]
            near = [t for t in near if t.endswith("s") == w.endswith("s")] if len(near) > 1 else near
            if len(near) == 1 and english_rank(w) is not None:
                return near[0]  # "line up the cams", "the blow", "both cops": a real word one slip from a scene noun
        if w == "w" and nxt in ("the", "a", "an", "one", "my", "its", "their", "his", "her", "them", "it", "any"):
            return "with"  # texting: "share a color w one of the bowls"
        if w == "2" and nxt in _AFTER_TO and k and not said[k - 1].isdigit():
            return "to"  # texting: "closest 2 me", "slide it 2 the right", "needs 2 be"
        return None


def starred(text: str) -> str:
    """``text`` with a texter's correction sent after it ("take the blow and put it on the plate *bowl") put in
    place: the word before it nearest in spelling (two edits at most, or half the word's letters; of those, the
    nearest in length, then the last) becomes the starred word, which goes.

    >>> starred("take the blow and put it on the plate *bowl")
    'take the bowl and put it on the plate'
    >>> starred("line up the clocks, all facing away from me *blocks")
    'line up the blocks, all facing away from me'
    """
    words = text.split()
    fixes = [w[1:].strip(".,!?") for w in words if w.startswith("*") and w[1:].strip(".,!?").isalpha()]
    if not fixes:
        return text
    kept = [w for w in words if not (w.startswith("*") and w[1:].strip(".,!?").isalpha())]
    for fix in fixes:
        scored = [(edit_distance(w.strip(".,!?;:").lower(), fix.lower()), abs(len(w.strip(".,!?;:")) - len(fix)), -k)
                  for k, w in enumerate(kept) if w.strip(".,!?;:").isalpha() and w.strip(".,!?;:").lower() != fix.lower()]
        best = min(scored, default=(3, 0, 0))
        if best[0] <= max(2, len(fix) // 2):
            k = -best[2]
            bare = kept[k].strip(".,!?;:")
            kept[k] = kept[k].replace(bare, fix)
    return " ".join(kept)


def correct_text(text: str, scene: Collection[str], lexicon: Collection[str], nouns: Collection[str] = (),
                 protect: Collection[str] = (), colours: Collection[str] = (), read: Collection[str] = ()) -> str:
    """:meth:`Corrector.text` with a corrector built for this call."""
    return Corrector(scene, lexicon, nouns, protect=protect, colours=colours, read=read).text(text)
