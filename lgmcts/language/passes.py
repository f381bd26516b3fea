"""The passes over a command's text and tokens before its clauses are read: spelled names, ids after their
category, spoken lists, parentheses, context and remark sentences, asides, "the former/latter", parts that
only leave an order open or leave objects alone, and "the same for ..." (:class:`_TokenPasses`, mixed into
:class:`.rules._Parser`).
"""

from __future__ import annotations

from dataclasses import replace
from functools import lru_cache
import re

from . import formal, repairs, stages
from ..errors import InputError
from .assembly import _CUES, _add_params
from .clauses import (
    _COMMAND_VERBS,
    _DIR_WORDS,
    _GOAL_WORDS,
    _LEADING,
    _VERT_WORDS,
    _command_verb,
    _is_number,
    _sentences,
)
from .grounding import COLOUR_WORDS, GROUPS, NUMBERS, Mention, candidates, find_mentions
from .qualifiers import _ATTRS
from .lexicon import HUES as _HUES, TABLE_WORDS, VIEWER_WORDS, context_words
from .matcher import FILLERS, STOPWORDS, _forms, _stem
from .measures import UNITS
from .context import moves_unknown, person_remark
from .same_change import other_side
from .places import POINTING_PARTS
from .normalise import pattern_words
from .rewrite import FREE_ORDER
from .said_words import TRADE_WORDS
from .spelling import english_rank
from .selection import _ASIDE_KEEP, _COMPASS_LEFT, _FACING_CUES, _ROLE_WORDS
from .shapes import COLS, FACINGS, REGION_NOUNS, ROWS, SIZES, take_params
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from .host import ParserHost
else:
    ParserHost = object


#: Where an object said without its article may start: a sentence's start or a command verb.
_ARTICLE_AT = re.compile(rf"(?i)((?:^|[.;!?:]|\b(?:{'|'.join(sorted(_COMMAND_VERBS))}))\s+|^)((?:[a-z]+ ){{0,2}}[a-z]+)\b"
                         rf"(?=(?:\s+[a-z]+)?)")


#: The word lists of a remark and an aside (``[context]`` of the lexicon).
_CTX = context_words()
#: Containers an object can be put in, read as a stack on them ("drop the block in the bowl").
_CONTAINERS = frozenset({"bowl", "mug", "cup", "pan", "pot", "box", "basket", "tray", "dish", "jar", "bin", "crate",
                         "container", "glass"})
_PUT_IN_VERBS = frozenset({"put", "drop", "place", "pop", "set", "stick", "toss", "tuck", "nest", "stash", "move",
                           "goes", "go", "should", "sit", "sits", "land", "lands"})
_PART_ENDS = frozenset({",", ".", ";", "!", "?", ":", "and", "then"})
#: Determiners and possessives before the noun of an aside ("by the window", "in my kitchen").
_ASIDE_DETS = frozenset({"the", "a", "an", "my", "your", "our", "his", "her", "their", "that", "this", "these", "those",
                         "some", "any", "one"})
#: Verbs of a selection clause: it names objects for the next clause ("select
#: objects that are red. circle"; "take the red mug and put it ...").
_SELECT_VERBS = frozenset({"select", "pick", "choose", "take", "grab", "get", "find", "use", "consider", "fetch",
                           "see", "spot", "notice", "locate", "look"})


_NOT_JOIN = frozenset({"around", "next", "near", "beside", "behind", "between", "under", "above", "beneath", "below",
                       "alongside", "inside", "outside", "across", "against", "toward", "towards", "past", "except",
                       "excluding", "minus", "which", "that", "where", "while", "but"})


_MEASURE_WORDS = frozenset({"cm", "mm", "centimeters", "centimetres", "meters", "metres", "inches", "inch", "radius",
                            "diameter", "spacing", "apart", "degrees"})


#: Words of pattern keys too general to name one arrangement by themselves.
_GENERIC_KEY_WORDS = frozenset({"arrange", "form", "formation", "shape", "put", "build", "another", "other", "top",
                                "around", "single", "border", "file", "round", "straight", "vertical", "box"})


#: "(then) do the same with X", "same for X", "the same goes for X", "repeat that for X".
_SAME = re.compile(r"^(?:then |now |and |also )*(?:(?:please |you )?(?:do|repeat|apply) (?:the same|that|this)(?: thing)?"
                   r"(?: again)?|(?:and )?(?:the )?same(?: thing)?(?: goes)?) (?:for|with|to) (.+?)(?: too| as well)?$")


#: Words said with "the same for X" that ask for nothing more ("same for the cups too, please").
_SAME_JOINS = frozenset({",", "and", "too", "also", "please", "but", "as", "well", "though", "only", "this", "time",
                         "again", "then"})

#: Words by which a sentence asks for something, so it does not only describe.
_DESCRIBES_NOT = re.compile(r"\b(should|must|need|needs|has to|have to|is to|are to|want|wants|would|'d|like|to be|"
                            r"end up|ends up|goes|go|belong|belongs|please|can you|could you|let)\b")


#: Verbs of a sentence that says how things are.
_STATE_VERB = re.compile(r"\b(is|are|am|'m|was|were|keep|keeps|'s|seem|seems|look|looks|has|have|got|getting|"
                         r"been)\b")


#: "(which one is immaterial)", "(any of them)": a choice left open.
_ANY_ONE = re.compile(r"^(?:which|whichever|any|either)(?: one| of them| of the \w+)?(?: is| will| would)?(?: \w+)?"
                      r"(?: immaterial| irrelevant| fine| do| ok| okay| matter| matters)?$")


#: "leave X where it is", "don't move X": X stays where it is.
_LEAVE = re.compile(r"^(?:so |and |but |just |please )*(?:leave|don't move|do not move|don't touch|do not touch|"
                    r"never mind|ignore) (.+?)(?: (?:exactly |just )?where (?:it is|they are|it's|they're)| alone| in place| be| as (?:it is|"
                    r"they are)| untouched| as is)?(?: please)?$")


#: Words of the free place and position readings (.places, .positions), known to the spelling corrector.
_PLACE_WORDS = frozenset({"strip", "band", "partway", "halfway", "midway", "dead", "centred", "centered", "corner",
                          "edge", "wall", "viewer", "nearest", "closest", "furthest", "farthest", "leftmost",
                          "rightmost", "frontmost", "backmost", "rearmost", "middle", "column", "across", "apart",
                          "wide", "long", "side", "each", "toward", "towards", "facing", "pointing", "turned"})


_SHAPES_PROTECT = frozenset({"lol", "haha", "ok", "okay", "thanks", "thank", "hey", "hi", "hello", "yeah", "yes", "no",
                             "nope", "sure", "cheers", "please", "pls", "plz", "thx", "wanna", "gonna", "gimme",
                             "lemme", "btw", "asap", "thru", "obj", "objs"})


@lru_cache(maxsize=1)
def _table_words() -> frozenset[str]:
    """The English words the rewrite tables read ("required", "aforementioned") and a trade's words, which a
    slip may stand for; not the stems a pattern spells its endings after ("arrang(?:e|ed)")."""
    return frozenset(w for w in pattern_words() if english_rank(w) is not None) | TRADE_WORDS


#: Superlatives of a side, words the spelling corrector knows (read by :mod:`.positions`).
_SUPERLATIVE = frozenset({"leftmost", "rightmost", "frontmost", "nearest", "closest", "backmost", "rearmost", "farthest",
                          "furthest"})



class _TokenPasses(ParserHost):
    """Text and token passes run by :meth:`.rules._Parser.command` before and around clause splitting."""

    def _category_ids(self, text: str) -> str:
        """"blocks 4, 5 and 6", "the bowl 7": ids given after their category, read as
        "objects 4, 5 and 6" when every number is the id of an object of that category."""
        def ids(m: re.Match) -> str:
            noun, nums = m.group(1).lower(), [int(x) for x in re.findall(r"\d+", m.group(2))]
            kinds = {i: n for i, n, _ in self.vocab.objects}
            if all(i in kinds and kinds[i] in (noun, _stem(noun)) for i in nums):
                return ("objects " if len(nums) > 1 else "object ") + m.group(2)
            return m.group(0)

        return re.sub(r"(?i)\b([a-z]+) (\d+(?:\s*,\s*\d+)*(?:,?\s+and\s+\d+)?)\b(?!\s*(?:cm|mm|m|centimet|metre|meter|inch|%))",
                      ids, text)

    def _spoken_lists(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """Lists said without commas ("the red the blue and the orange blocks") get
        them; "toy" before a category ("the toy blocks") is dropped."""
        colour = lambda w: w in self.vocab.color_words or w in COLOUR_WORDS  # noqa: E731
        out: list[str] = []
        for k, w in enumerate(words):
            if w == "the" and out and colour(out[-1]):
                out.append(",")
            if (w in _HUES and out and out[-1] in _HUES
                    and not any(f"{out[-1]} {w}" in c for c in self.vocab.colors.values())):
                out.append(",")  # "bottom to top red orange yellow": one object per colour
            if (w == "and" and k >= 2 and words[k - 2] in ("every", "each", "all") and k + 1 < len(words)
                    and words[k - 1] in self._cat_words and words[k + 1] in self._cat_words):
                out.extend(["and", words[k - 2]])  # "every cup and bowl": every cup and every bowl
                continue
            if w == "toy" and k + 1 < len(words) and (words[k + 1] in self._cat_words
                                                     or _stem(words[k + 1]) in self._cat_words):
                continue
            out.append(w)
        return tuple(out)

    def _noun_first_lists(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """A plural noun said before its colours ("blocks red blue green yellow -> line": the red, blue, green and
        yellow blocks) or before its count ("bowls 3, line": three bowls, where 3 is no id of that kind)."""
        colour = lambda w: w in self.vocab.color_words or w in COLOUR_WORDS  # noqa: E731
        out = list(words)
        k = 0
        while k < len(out):
            # "blocks red blue green yellow -> line": a plural noun, then its colours (two or more)
            j = k + 1
            while j < len(out) and (colour(out[j]) or (out[j] in (",", "and") and j + 1 < len(out)
                                                         and colour(out[j + 1]))):
                j += 1
            if (out[k].endswith("s") and _stem(out[k]) in self._cat_words and k + 2 < len(out) and _is_number(out[k + 1])
                    and out[k + 2] == "," and not (k and (_is_number(out[k - 1]) or out[k - 1] == "object"))):
                out[k], out[k + 1] = out[k + 1], out[k]  # "bowls 3, line": three bowls, said noun first
                k += 2
                continue
            hues = [w for w in out[k + 1 : j] if colour(w)]
            if (len(hues) >= 2 and out[k].endswith("s") and _stem(out[k]) in self._cat_words
                    and not (k and colour(out[k - 1])) and (j == len(out) or not self._object_word(out[j]))):
                listed = [x for h in hues[:-1] for x in (h, ",")][:-1] + ["and", hues[-1]]
                out[k:j] = [*listed, out[k]]
                k += len(listed) + 1
                continue
            k += 1
        return tuple(out)

    def _bare_colour_sets(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """Colours standing for objects after a negation: "neither purple nor orange"
        -> "not purple or orange"; "not red and not blue" -> "not red or blue";
        "except yellow and orange" -> "except the yellow and orange ones"."""
        colour = lambda w: w in self.vocab.color_words or w in COLOUR_WORDS  # noqa: E731
        out = list(words)
        k = 0
        while k < len(out):
            if out[k] == "neither" and k + 1 < len(out) and colour(out[k + 1]):
                out[k] = "not"
            if out[k] == "nor" and k > 0 and colour(out[k - 1]):
                out[k] = "or"
            if out[k : k + 2] == ["and", "not"] and k > 0 and colour(out[k - 1]) and k + 2 < len(out) \
                    and colour(out[k + 2]) and any(out[j] == "not" for j in range(max(0, k - 4), k)):
                out[k : k + 2] = ["or"]
            k += 1
        res: list[str] = []
        k = 0
        while k < len(out):
            res.append(out[k])
            lead = out[k] in ("except", "excluding", "minus") or tuple(out[max(0, k - 1) : k + 1]) in (
                ("apart", "from"), ("other", "than"), ("except", "for"), ("but", "not"))
            if lead and k + 1 < len(out) and colour(out[k + 1]):
                j = k + 1
                while j < len(out) and (colour(out[j]) or out[j] in (",", "and", "or")):
                    j += 1
                while out[j - 1] in (",", "and", "or"):
                    j -= 1
                nxt = out[j] if j < len(out) else ""
                if nxt in ("one", "ones"):
                    res.extend(["the", *out[k + 1 : j]])  # "but not white one": the article only
                    k = j
                    continue
                if not self._content_word(nxt) or nxt in _ASIDE_KEEP or nxt in _DIR_WORDS or nxt in self.key_vocab:
                    res.extend(["the", *out[k + 1 : j], "ones"])
                    k = j
                    continue
            k += 1
        return tuple(res)

    def _arrangement_refs(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """"put that row to the left of the plate", "do it at the front, keep it
        small": an arrangement read before, named by its pattern word or "it"."""
        shape = self.state.last_shape
        if shape is None or not all(isinstance(x, int) for x in shape.objects):
            return words
        nouns = {"line": ("line", "row", "file", "queue"), "circle": ("circle", "ring", "loop"),
                 "rectangle": ("rectangle", "square", "box"), "tower": ("tower", "stack", "pile")}.get(shape.pattern, ())
        out = list(words)
        for k in range(len(out) - 1):
            if out[k] in ("that", "this", "the") and out[k + 1] in nouns and not (
                    k > 0 and out[k - 1] in ("in", "into", "as", "form", "make", "a", "behind", "of", "beside", "to",
                                             "near", "on", "onto", "above", "under", "below", "around", "with")):
                out[k : k + 2] = ["them", ""]
        out = [w for w in out if w]
        if tuple(out) != words:
            self.state.last, self.state.last_tower = list(shape.objects), False
            self.state.it_pair = None
        # "do it at the front of the table", "keep it small": its place or size.
        rest = [w for w in out if w not in ("do", "keep", "make", "it", "them", "please", "put", "place", "have", "move",
                                            "set", "all")]
        if rest and out[0] in ("do", "keep", "make", "put", "place", "move", "set", "have") and any(
                w in ("it", "them") for w in out[:3]) and list(self.state.last) == list(shape.objects):
            size = next((SIZES[w] for w in rest if w in SIZES), None)
            params, left = take_params(tuple(rest), lambda w: False)
            if size is not None:
                params["size"] = size
                left = tuple(w for w in left if w not in SIZES)
            if params and not [w for w in left if w not in STOPWORDS and w != ","]:
                _add_params(shape, params, " ".join(words))
                return ()
        return tuple(out)

    def _articles(self, text: str) -> str:
        """"red can should have the blue bowl behind it", "move blue mug so red mug sits
        on its left": a singular object named without its article, at the start of a
        sentence or right after a command verb, is read as if "the" were said ("can"
        and "a" only after a colour)."""
        colours = _HUES | set(self.vocab.color_words)

        def one(m: re.Match) -> str:
            ws = m.group(2).split()
            k = 0
            while k < len(ws) and ws[k].lower() in colours:
                k += 1
            noun = ws[k].lower() if k < len(ws) else ""
            if noun in self._cat_words and not noun.endswith("s") and len(noun) > 1 and (
                    k > 0 or (noun not in STOPWORDS and noun not in ("can", "a", "i"))) and (
                    k + 1 == len(ws) or ws[k + 1].lower() not in self._cat_words):
                return f"{m.group(1)}the {m.group(2)}"
            return m.group(0)
        return _ARTICLE_AT.sub(one, text)

    def _former_latter(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """"take the spoon and the fork; put the former in front of the latter":
        "the former" / "the latter" replaced by the two references named before."""
        # "the first one" / "the second one" after two references mean the same ("put the first one on
        # top of the second one"), where they are not stack roles ("the first one goes at the bottom").
        ordinal = {"first": "former", "second": "latter"}
        words = tuple(w for k, w in enumerate(words) if not (w == "one" and k >= 2 and words[k - 1] in ordinal
                                                             and words[k - 2] == "the"))
        words = tuple(ordinal.get(w, w) if k and words[k - 1] == "the" and (
            k + 1 >= len(words) or words[k + 1] in ("on", "onto", "under", "in", "behind", "to", "next", "left",
                                                   "right", "beside", "below", "above", "of", "and", ",", ".")) else w
            for k, w in enumerate(words))
        at = [k for k in range(len(words) - 1) if words[k] == "the" and words[k + 1] in ("former", "latter")]
        if not at:
            return words
        try:
            named = [m for m in self._find(words[: at[0]]) if m.det not in ("pronoun",)]
        except InputError:
            return words
        if len(named) == 1:
            named = self._excepted(words, named[0]) or named
        if len(named) < 2:
            return words
        # "..., and then the purple block on the right of the latter": the two named before the part that
        # says it, where there are two (what that part names first is what moves, never its own reference)
        cut = max((k for k in range(at[0]) if words[k] in (",", ";", ".", ":", "and", "then")), default=0)
        before = [m for m in named if m.end <= cut]
        if len(before) >= 2:
            named = before
        pair = {"former": words[named[-2].start : named[-2].end], "latter": words[named[-1].start : named[-1].end]}
        out: list[str] = []
        k = 0
        while k < len(words):
            if k in at:
                ref = pair[words[k + 1]]
                out.extend(ref if ref[0] in ("the", "a", "an") else ("the",) + ref)
                k += 2
                continue
            out.append(words[k])
            k += 1
        return tuple(out)

    def _excepted(self, words: tuple[str, ...], m: Mention) -> list[Mention]:
        """The references of the exception inside ``m`` ("all items other than the plate and the knife": the plate,
        the knife), at their places in ``words``; none where ``m`` says no exception."""
        at = next((k + 1 for k in range(m.start, m.end) if words[k] in ("than", "except", "excluding", "but")), None)
        if at is None:
            return []
        try:
            found = self._find(words[at : m.end])
        except InputError:
            return []
        return [replace(x, start=x.start + at, end=x.end + at) for x in found]

    def _put_in(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """"drop the red block in the white bowl", "red block in the white bowl, blue one in the black bowl":
        one object said to go in a container (a bowl, mug, cup, pan, box ...) at the end of its part goes on
        it, a stack, as "into" does; said after a verb that puts it there or as the whole part. "The can in
        the bowl" inside a longer part stays a reference."""
        if "in" not in words and "inside" not in words:
            return words
        try:
            found = self._find(words)
        except InputError:
            return words
        out = list(words)
        by_start = {m.start: m for m in found}
        for k, w in enumerate(words):
            m = by_start.get(k + 1)
            if w not in ("in", "inside") or m is None or m.plural or not self._container(m):
                continue
            if m.end < len(words) and words[m.end] not in _PART_ENDS:
                continue
            start = max((j + 1 for j in range(k) if words[j] in _PART_ENDS), default=0)
            left = [x for x in found if start <= x.start and x.end <= k]
            if not left or left[-1].end != k:
                continue
            said = words[start : left[-1].start]
            if all(x in _PUT_IN_VERBS or x in ("please", "just", "now", "then", "and", "also") for x in said) and (
                    not said or any(x in _PUT_IN_VERBS for x in said)):
                out[k] = "on"
        return tuple(out)

    def _container(self, m: Mention) -> bool:
        """Whether the one object ``m`` names is a container ("the white bowl", "object 7" a bowl)."""
        names = {o.name for o in self.spec.objects if o.id in m.ids} if m.ids else set(m.names or ())
        return bool(names) and all(n.split()[-1] in _CONTAINERS for n in names)

    def _spelled_right(self, text: str) -> str:
        """The text with misspellings corrected against the scene and the parser's words (.spelling)."""
        lexicon = (set(self.key_vocab) | _COMMAND_VERBS | set(_DIR_WORDS) | set(ROWS) | set(COLS) | set(FACINGS)
                   | REGION_NOUNS | set(SIZES) | COLOUR_WORDS | set(GROUPS) | _ROLE_WORDS | _SUPERLATIVE
                   | _MEASURE_WORDS | _FACING_CUES | POINTING_PARTS | frozenset(UNITS) | _PLACE_WORDS | TABLE_WORDS
                   | VIEWER_WORDS | formal.SPELLED | {"behind", "between", "beside", "next", "above", "below", "under", "onto",
                                       "everything", "object", "objects", "please", "square", "center", "centre"})
        nouns = {w for w in self.key_vocab if w.isalpha() and len(w) > 2} - STOPWORDS - FILLERS
        protect = STOPWORDS | FILLERS | NUMBERS.keys() | _SHAPES_PROTECT | _ATTRS.keys()
        return stages.spell(text, self.vocab, lexicon, nouns, protect, _table_words() | {"respectively"}, self._slips)

    def _remember(self, clause: tuple[str, ...]) -> None:
        """Let later pronouns and bare colours refer to what a dropped remark names."""
        try:
            got = self._select_noting(self._find(clause))
        except InputError:
            return
        if got:
            self.state.last, self.state.last_tower = got, False
            self.state.it_pair = None

    def _remark(self, clause: tuple[str, ...]) -> bool:
        """A sentence that asks for nothing: no pattern, direction, stacking, place,
        size or order word and no command verb, but words besides its object
        references ("the bottles are a mess", "I find it easier to reach")."""
        lead = next((w for w in clause if w not in _LEADING and w not in STOPWORDS), "")
        try:
            named: list[Mention | None] = [m for m in self._find(clause) if m.det != "pronoun"]
        except InputError:
            named = [None]
        counted = {k for m in named if m is not None for k in range(m.start, m.end)}  # "the three cans"
        goal = ((lead in _COMMAND_VERBS or lead in _SELECT_VERBS) and bool(named)) or any(
            (any(f in self.key_vocab and f not in FILLERS for f in _forms(w)) and w not in STOPWORDS)
            or w in _DIR_WORDS or w in _COMPASS_LEFT or w in _VERT_WORDS - {"to", "of"} or w in SIZES or w in ROWS
            or w in COLS or w in FACINGS or w in ("order", "first", "last", "then", "facing")
            or (_is_number(w) and k not in counted)
            for k, w in enumerate(clause))
        if goal or (lead in ("only", "just") and any(m is not None for m in named)):
            return False  # "oh, only the blue and the green ones": which objects, never a remark
        if moves_unknown(clause, frozenset(self._unknown_nouns(clause, []))):
            return False  # "put the teapot by the window", "the teapot should go ...": a request the scene cannot meet
        try:
            ms = self._find(clause)
        except InputError:
            ms = []
        inside = {k for m in ms for k in range(m.start, m.end)}
        return any(w.isalpha() and k not in inside and w not in STOPWORDS and _stem(w) not in FILLERS
                   and not self._content_word(w) and w not in _ROLE_WORDS for k, w in enumerate(clause))

    def _without_asides(self, clause: tuple[str, ...]) -> tuple[str, ...]:
        if clause[:2] in (("there", "are"), ("there", "is"), ("we", "have"), ("you", "have"), ("i", "have")) and not any(
                (_stem(w) in self.key_vocab and _stem(w) not in FILLERS) or w in _DIR_WORDS for w in clause):
            self._remember(clause)  # "there are two bottles": a remark whose noun "the white one" may take
            return ()
        """``clause`` without its comma-separated asides: a part that names no
        object, pattern, direction, place, size or order ("ok robot", "here is
        the plan", "if it is not too much trouble", "could you do that")."""
        if self._remark(clause):
            if clause[-1:] == ("too",) or clause[-2:] == ("as", "well"):
                # "hmm, and the green can as well": objects added to what was asked; where no goal then uses
                # them (no "them" later takes them), the command is refused, never answered without them
                try:
                    self._named_in.append((clause, self._find(clause)))
                except InputError:
                    pass
            if "," in clause and self._names_objects(list(clause)):
                # "A, R, T, E, by the window": a list of objects with an aside that says where is no remark
                for k, w in enumerate(clause):
                    if w == "," and k + 1 < len(clause):
                        tail = list(clause[k + 1 :])
                        if "," not in tail and not any(self._content_word(x) for x in tail):
                            self._unread_aside(tail)
            self._remember(clause)  # "the bottles are a mess. could you stick them ...": them
            return ()
        parts: list[list[str]] = [[]]
        for w in clause:
            if w == ",":
                parts.append([])
            else:
                parts[-1].append(w)
        if len(parts) == 1 and not any(self._content_word(w) for w in parts[0]):
            self._unread_aside(parts[0])
            return ()
        for k in range(len(parts) - 1):
            later = [w for q in parts[k + 1 :] for w in q]
            if (parts[k] and any(w in ("them", "they", "it", "those") for w in later)
                    and self._remark(tuple(parts[k]))):
                # "ok so the letters are a mess, throw them in a circle": a remark, then the request by a pronoun
                self._remember(tuple(parts[k]))
                parts[k] = []
        kept = [p for p in parts if any(self._content_word(w) for w in p) and not (len(parts) > 1 and self._free_order(tuple(p)))]
        for p in parts:
            if not any(self._content_word(w) for w in p):
                self._unread_aside(p)
        if len(kept) > 1:
            # ", just a straight row is fine", ", single file": a part naming again, with no object,
            # the arrangement another part already names.
            said = [self._part_patterns(p) for p in kept]
            kept = [p for k, p in enumerate(kept) if not (
                said[k] and not self._names_objects(p)
                and not any(w in SIZES or w in ROWS or w in COLS or w in FACINGS or w in REGION_NOUNS
                            or w in _COMPASS_LEFT or w in ("facing", "pointing", "little", "tiny", "big") for w in p)
                and said[k] <= set().union(*(said[j] for j in range(len(kept)) if j != k)))]
        if len(kept) == len(parts):
            return clause
        out: list[str] = []
        for p in kept:
            out.extend(([","] if out else []) + p)
        return tuple(out)

    def _unread_aside(self, part: list[str]) -> None:
        """Refuse an aside that says where or how with a noun the parser cannot read ("by the window", "in a
        zigzag", "next to the fridge"): dropping it would leave out what was said. A preposition of
        ``[context] place_prepositions`` followed by a noun phrase whose noun is neither a word the parser reads
        nor one of ``aside_nouns`` ("by the way", "in a minute"); and an arrangement the database lacks said
        alone (", zigzag")."""
        shape = next((w for w in part if self.matcher.names_unsupported(w)), None)
        if shape is not None:
            raise InputError(f"'{' '.join(part)}': '{shape}' names an arrangement the database does not have")
        for k, w in enumerate(part):
            if w not in _CTX["place_prepositions"]:
                continue
            j = k + 1
            if j < len(part) and part[j] in ("to", "of") and w in ("next", "near", "inside", "opposite"):
                j += 1  # "next to the fridge", "inside of the drawer"
            while j < len(part) and part[j] in _ASIDE_DETS:
                j += 1
            if j == k + 1 or j >= len(part) or part[j - 1] in ("to", "of"):
                continue  # a determiner must follow: "by hand", "in time" are idioms
            end = j
            while end < len(part) and part[end].isalpha() and part[end] not in STOPWORDS and end - j < 3:
                end += 1
            noun = part[end - 1] if end > j else ""
            if not noun or noun in _CTX["aside_nouns"] or _stem(noun) in _CTX["aside_nouns"]:
                continue
            raise InputError(f"'{' '.join(part[k:end])}' is not read: it names nothing in the scene and no place or "
                             f"arrangement the parser knows; say it with the table's sides and corners or an object "
                             f"on it, or leave it out")

    def _same_said_after(self, clause: tuple[str, ...]) -> tuple[str, ...]:
        """"the cups, same thing (but front left)": "same for the cups (but front left)"."""
        k = next((k for k in range(2, len(clause)) if clause[k] == "same" and clause[k - 1] in (",", "the")), 0)
        head = tuple(w for w in clause[: k - 1] if w != ",")
        if not k or clause[k + 1 : k + 2] not in ((), ("thing",), ("but",), (",",), ("again",), ("too",)):
            return clause
        refs = self._find(head)
        # only where the words before it are references and nothing else ("the cups, same thing")
        if not refs or {i for m in refs for i in range(m.start, m.end)} != set(range(len(head))):
            return clause
        return ("same", "for", *head, *clause[k + 1 + (clause[k + 1 : k + 2] == ("thing",)) :])

    def _same_as_before(self, clause: tuple[str, ...], last: tuple[str, ...]) -> tuple[str, ...]:
        """"do the same with the yellow letter and the yellow block", "same for the
        mugs": the clause before, its first references replaced by the new ones
        (all of them where as many are named; else the objects placed, so the
        reference object stays). "the cups, same thing" is said as "same for the cups" before
        (:meth:`_same_said_after`, in :meth:`.rules._Parser._read_clauses`)."""
        m = _SAME.match(" ".join(clause))
        if m is None:
            return clause
        if not last:
            raise InputError(f"'{' '.join(clause)}': the same as what? nothing was asked before it")
        rest = tuple(m.group(1).split())
        new = self._find(rest)
        old = self._find(last)
        if not new or len(new) > len(old):
            raise InputError(f"'{' '.join(clause)}': cannot tell which objects take the places of which")
        out = list(last)
        for a, b in reversed(list(zip(old, new))):
            out[a.start : a.end] = rest[b.start : b.end]
        inside = {i for b in new for i in range(b.start, b.end)}
        more = [w for i, w in enumerate(rest) if i not in inside]
        while more and more[0] in _SAME_JOINS:
            more.pop(0)
        if not more or all(w in _SAME_JOINS for w in more):
            return tuple(out)
        sided = other_side(out, more, _SAME_JOINS)
        if sided is not None:
            return sided
        # "same for the cups but front left": a place, a facing or a measure said with it replaces the clause's
        # own (or joins it); anything else is refused, never dropped
        joined = f"{' '.join(out)} , no wait , {' '.join(more)}"
        changed = repairs.typed_repairs(joined)
        if changed != joined:
            return tuple(changed.split())
        kind = repairs.fragment_kind(more)
        if kind in ("place", "facing"):
            return (*out, *(("in", "the") if kind == "place" and more[0] not in ("in", "at", "on") else ()), *more)
        raise InputError(f"'{' '.join(clause)}': '{' '.join(more)}' is not read with 'the same'; say the request in full")

    def _parentheses(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """Parentheses that add nothing are dropped ("(which one is immaterial)",
        "(order immaterial)"); parentheses that list the objects of the phrase
        before them ("the dishes (the plate and the three bowls)", "cans (red,
        white, green)") are dropped where they name the same objects and replace
        the phrase where they name some of them. Others stay, and are refused."""
        out = list(words)
        while "(" in out and ")" in out[out.index("(") :]:
            a = out.index("(")
            b = out.index(")", a)
            inner = tuple(out[a + 1 : b])
            if (not inner or self._free_order(inner) or _ANY_ONE.match(" ".join(inner))
                    or not any(self._content_word(w) for w in inner)
                    or (self._dinner_at(inner) is not None and self._dinner_at(tuple(out[:a])) is not None
                        and not self._find(inner))):
                out[a : b + 1] = []
                continue
            before = tuple(out[:a])
            try:
                outer = next((m for m in self._find(before) if m.end == a and m.det != "pronoun"), None)
                if outer is None:
                    break
                own = find_mentions(self.vocab, inner, self.key_vocab,
                                    (outer.names,) if outer.names is not None else ())
                inside = {k for m in own for k in range(m.start, m.end)}
                if not own or any(k not in inside and w not in (",", "and", "all", "both") and not _is_number(w)
                                  for k, w in enumerate(inner)):
                    break
                whole = set(candidates(self.vocab, replace(outer, det="all", plural=True)))
                named = {o for m in own for o in candidates(self.vocab, replace(m, det="all", plural=True))}
            except InputError:
                break
            if named == whole or (outer.det == "all" and named == set(candidates(self.vocab, outer))):
                out[a : b + 1] = []
            elif named < whole:
                self._note_nouns([outer])
                out[outer.start : b + 1] = list(inner)
            else:
                break
        return tuple(out)

    def _context_sentences(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """Sentences before the request that only describe how things are ("the
        white bowl is in my way.", "i keep knocking the blue mug over.", "the mug,
        the cup and the bottle are crowding the plate.") ask for nothing: they are
        dropped, and what their subject names is what a later "it"/"them" means."""
        sentences = _sentences(words, (".", "!", "?", ";"))
        dropped = 0
        for sent in sentences[:-1]:
            if self._people_remark(sent[:-1]):
                self._remember_subject(sent[:-1])  # "my son loves the red block. put it ...": the block
                dropped += len(sent)  # "i'm trying to teach the little one colours.": about the people
                continue
            if not self._describes(sent[:-1]):
                break
            self._remember_subject(sent[:-1])
            dropped += len(sent)
        return words[dropped:]

    def _people_remark(self, words: tuple[str, ...] | list[str]) -> bool:
        """Whether ``words`` only remark on the people or pets of the house (:func:`.context.person_remark`)."""
        body = [w for w in words if w not in (",", "'", ".", "!", "?", ";")]
        while body and body[0] in _LEADING:
            body = body[1:]
        return person_remark(body, self._object_word, self._request_word, _command_verb)

    def _without_remark_tail(self, sent: tuple[str, ...]) -> tuple[str, ...]:
        """``sent`` without a last clause after a comma that only remarks on the people of the house
        ("put the cans in a line, the kids left them all over the place"), where the words before it ask."""
        end = len(sent)
        while end and sent[end - 1] in (".", "!", "?"):
            end -= 1
        cut = max((k for k in range(end) if sent[k] == ","), default=-1)
        if cut <= 0 or not self._people_remark(sent[cut + 1 : end]) or not any(
                self._request_word(w) for w in sent[:cut]):
            return sent
        return sent[:cut] + sent[end:]

    def _trailing_remarks(self, words: tuple[str, ...]) -> tuple[str, ...]:
        """Sentences after the request that name no object and only remark on it
        ("I'm clearing up, you see.", "Which goes where is totally up to you!",
        "Remember, a square is just a rectangle with equal sides.", "Go!") ask for
        nothing: they are dropped. A sentence with a place, size, facing or order
        word ("At the front.", "Any order.") is kept."""
        sentences = _sentences(words, (".", "!", "?"))
        if len(sentences) < 2:
            return self._without_remark_tail(words)
        out: list[str] = []
        asked = False
        for sent in sentences:
            body = [w for w in sent if w not in (",", ".", "!", "?", "'")]
            while body and body[0] in _LEADING:
                body = body[1:]
            named: list[Mention | None]
            try:
                named = list(self._find(tuple(body))) if body else []
            except InputError:
                named = [None]
            if asked and body and not named and not _command_verb(body[0]) and not any(
                    w in SIZES or w in ROWS or w in COLS or w in _ROLE_WORDS or w in _DIR_WORDS
                    or w in ("order", "first", "last", "then", "facing", "instead", "too", "also") for w in body) and (
                    _STATE_VERB.search(" ".join(body)) or re.search(
                        r"\b(?:go|see|mean|mind|care|know|think|remember|wins?|done|cheers|thanks|thank|please)\b",
                        " ".join(body))):
                continue
            if asked and self._people_remark(body):
                continue  # "The kids made a mess earlier."
            asked = asked or bool(named)
            out.extend(self._without_remark_tail(sent) if named else sent)
        return tuple(out)

    def _describes(self, sent: tuple[str, ...]) -> bool:
        """Whether ``sent`` states how things are rather than asking for anything."""
        body = [w for w in sent if w not in (",", "'")]
        while body and body[0] in _LEADING:
            body = body[1:]
        if len(body) < 2 or _command_verb(body[0]) or body[0] in ("let", "lets", "let's", "go", "i'd", "we'd"):
            return False
        text = " ".join(body)
        if _DESCRIBES_NOT.search(text) or any(cue.search(text) for cue, _ in _CUES):
            return False
        if not (_STATE_VERB.search(text) or body[0] in ("i", "i'm", "we", "time", "there", "it's", "this", "that")):
            return False
        try:
            inside = {k for m in self._find(tuple(body)) for k in range(m.start, m.end)}
        except InputError:
            inside = set()
        for k, w in enumerate(body):
            if k in inside or w in STOPWORDS or w in ("before", "after", "until", "while", "when"):
                continue  # "before guests come over": a time, not a place
            nxt = body[k + 1] if k + 1 < len(body) else ""
            if w == "over" and nxt not in ("the", "a", "an", "it", "them") and k + 1 not in inside:
                continue  # "knocking the mug over", "all over the place" is below
            if w in ROWS or w in COLS:
                # "in the middle", "at the back" say where; "cluttering the middle" only describes.
                if k and (body[k - 1] in ("in", "at", "on", "to", "into") or (
                        body[k - 1] == "the" and k > 1 and body[k - 2] in ("in", "at", "on", "to", "into"))):
                    return False
                continue
            if (w in _VERT_WORDS - {"to", "of", "over"} or w in _DIR_WORDS or w in SIZES or _is_number(w)
                    or w in _ROLE_WORDS or w in ("order", "first", "last", "then", "facing")):
                return False
            st = _stem(w)
            if st in self.key_vocab and st not in FILLERS and st not in _GENERIC_KEY_WORDS:
                return False
        return True

    def _remember_subject(self, sent: tuple[str, ...]) -> None:
        """Remember what the subject of a describing sentence names (all its
        references where it starts with none: "there are two bottles")."""
        try:
            ms = [m for m in self._find(sent) if m.det != "pronoun"]
        except InputError:
            return
        lead: list = []
        for m in ms:
            gap = sent[lead[-1].end : m.start] if lead else sent[:m.start]
            if all(w in ("the", ",", "and", "both", "all") for w in gap) and (lead or all(w in _LEADING or w == "the"
                                                                                       for w in gap)):
                lead.append(m)
            else:
                break
        chosen = lead or ms
        if chosen:
            self._remember(sent[chosen[0].start : chosen[-1].end])

    def _left_alone(self, clause: tuple[str, ...]) -> bool:
        """"leave the plate and the bowl where they are", "so leave it", "don't touch
        the phone": objects that stay put. Nothing to arrange; later pronouns may
        refer to them, and "everything else" leaves them out."""
        m = _LEAVE.match(" ".join(clause))
        if m is None:
            return False
        rest = tuple(m.group(1).split())
        try:
            ms = self._find(rest)
        except InputError:
            return False
        inside = {k for x in ms for k in range(x.start, x.end)}
        if not ms or any(k not in inside and w not in (",", "and", "both") for k, w in enumerate(rest)):
            return False
        # Unlike a remark's, these references must resolve: "leave the bowl" with three bowls is refused.
        got = [o for o in self._select_noting(ms) if isinstance(o, int)]
        self.state.last, self.state.last_tower, self.state.it_pair = list(got), False, None
        self.state.named.update(got)
        return True

    def _part_patterns(self, part: list[str]) -> set[str]:
        """The arrangements (not relations) the words of ``part`` name by themselves."""
        out = set()
        for k, w in enumerate(part):
            if not w.isalpha() or len(w) < 3 or w in STOPWORDS or _stem(w) in FILLERS or w in _DIR_WORDS:
                continue
            if w in ("row", "column") and k and (part[k - 1] in ROWS or part[k - 1] in COLS):
                continue  # "top row", "left column": a place, not a line
            p, _, _ = self.matcher.word_pattern(w)
            if p is not None and not self.infos[p].anchored:
                out.add(p)
        return out

    def _free_order(self, clause: tuple[str, ...]) -> bool:
        """A clause that only leaves a stack's order open: "any order is fine",
        "the order is not important", "which one is under which does not matter"."""
        text = " ".join(clause)
        if FREE_ORDER.fullmatch(text):
            return True
        if re.fullmatch(r"(the )?(order|sequence) of .+ (is|is entirely|is totally) (your call|up to you|your choice|"
                        r"free|open|not important|unimportant|yours to pick|yours)", text):
            return True  # "the order of the other two is your call"
        if not re.search(r"\b(order|sequence|which way (round|up|around)|which (one |of them |of the two )?(is|goes|sits|ends up|comes|lands|sits) "
                         r"(under|on top|on|above|below|over|at the bottom|at the top|first|last|lowest|highest))\b",
                         text):
            return False
        if not re.search(r"\b(not|n't|no|any|whatever|fine|matters?|up to you|care|free|important|irrelevant|"
                         r"unimportant|open|ok|okay|decide|choose|immaterial|arbitrary|unspecified|yours)\b", text):
            return False
        try:
            return not self._find(clause)
        except InputError:
            return False
