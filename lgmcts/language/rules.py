"""The default offline parser: clauses, object grounding, pattern choice.

Pipeline for one command:

1. **Split** into clauses at sentence ends, ";", the connectives
   "then", "while", "also", "after that", "meanwhile", and an "and" or ","
   right before a command verb ("stack the blocks and put the bowls in a
   line"), never inside a list "A, B and C"; split "A on B and C on D"
   into two stacking steps (chained into one tower later); then split a clause
   that names two arrangements at the "and" (or ",") between them
   ("put all blocks in a circle and the white bottle behind one block").
2. **Ground** the object references of each clause (:mod:`.grounding`).
3. **Choose the pattern** of each clause by Sentence-BERT similarity between
   what is left of the clause once its object references are removed
   ("put ... in a line pattern") and the keys of the pattern database
   (:mod:`.matcher`).
4. **Assemble goals**: a pattern with an anchor (the spatial relations) takes
   the objects named before the relation phrase as targets and the object
   named right after it as anchor ("X left of Y"); other patterns take every
   object the clause names. Towers keep the order of naming (first named at
   the bottom) except after "on"/"onto" ("stack A on B": B is below A), and
   "from top to bottom" reverses it; towers where the top of one is the
   bottom of another are joined ("put A on B, then put C on A": [B, A, C]).
5. **Resolve choices**: "one X" as a target prefers objects no other goal
   uses; as an anchor it prefers an object of another goal of the same
   command (the paper's "behind one block" next to "all blocks in a circle").
6. **Check** the result: too few objects for a pattern, contradicting
   relations, cycles and other impossible combinations are refused with one
   line, never turned into a silently wrong goal.

This module holds the options, the state of one command and :class:`_Parser`,
whose :meth:`_Parser.command` runs the steps; the steps live by concern in
:mod:`.clauses` (step 1), :mod:`.passes` (the text and token passes before
it), :mod:`.framing` with :mod:`.readings` (one clause read; step 3 and the
relations of step 4), :mod:`.arrangements` (pattern choice, shape goals, the
place setting), :mod:`.selection` (references resolved against what the
command named before) and :mod:`.assembly` (steps 4 to 6). Grounding (step 2)
is :mod:`.grounding`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
import re

from . import asides, backdrop, formal, lexicon, poses, repairs, spelling, stages, steps
from .positions import TOO_CLOSE
from .stack_order import stack_orders
from ..errors import InputError
from ..formats import GoalSpec, RELATIONS, SceneSpec
from .assembly import _Pending
from .clauses import _bare_letter, _command_verb, _merged_moves, _predicate_split, split_clauses
from .grounding import COLOUR_WORDS, Choice, Mention, Vocabulary, tokenize
from .lexicon import HUES

from .matcher import FILLERS, PatternMatcher, STOPWORDS, _stem
from .passes import _SAME
from .rewrite import ASKS_TO_ACT, QUESTION, plain_words, rewrite, unframe
from .shapes import normalise
from .arrangements import _Arrangements
from .assembly import _Finishing
from .framing import _Framing
from .pairs import pair_named, stack_by_colours
from .passes import _TokenPasses
from .group_passes import _GroupPasses
from .selection import _Selecting

__all__ = ["RulesOptions", "parse_rules", "split_clauses", "goal_dicts"]

#: Words after which a pouring verb asks for the pouring (:meth:`_Parser._tilt`).
_BEFORE_POUR = frozenset({".", ",", ";", "!", "?", "you", "u", "please", "mind", "then", "and", "just", "now"})
#: Words that may follow a way to stand an object ("upside down, then ...", "on its side behind the plate").
_AFTER_TILT = frozenset({"and", "then", "on", "in", "into", "onto", "behind", "next", "beside", "at", "to", "please",
                         "too", "as", "so", "with", "near", "by", "left", "right", "front", "facing", "all", "but",
                         "if", "or", "like", "for", "now", "again", "instead", "under", "over", "above", "below"})
#: Ordinals that say a place in a stack ("fourth from the bottom").
_STACK_ORDINALS = {"second": 2, "third": 3, "fourth": 4, "fifth": 5, "sixth": 6, "seventh": 7, "eighth": 8}
#: Superlatives of size, and the places inside an arrangement they may be given ("tallest in the middle").
_SIZE_SUPERLATIVES = frozenset({"tallest", "shortest", "biggest", "largest", "smallest", "widest", "heaviest",
                                "lightest", "highest", "lowest"})
_INSIDE_PLACES = frozenset({("in", "the", "middle"), ("in", "the", "centre"), ("in", "the", "center"),
                            ("at", "the", "ends"), ("at", "the", "end"), ("on", "the", "ends"), ("on", "the", "outside"),
                            ("on", "the", "outsides"), ("at", "each", "end"), ("in", "middle"), ("on", "ends"),
                            ("on", "the", "bottom"), ("at", "the", "bottom"), ("on", "bottom"), ("at", "bottom"),
                            ("on", "top"), ("at", "the", "top"), ("at", "top"), ("on", "the", "top")})
#: Words after "closer to" that make it a direction, not a nearness to an object ("closer to the front edge").
_EDGE_NOUNS = frozenset({"front", "back", "rear", "edge", "side", "wall", "left", "right", "centre", "center",
                         "middle", "corner", "table"})



def _stack_axis(said: list[str]) -> tuple[int, float] | None:
    """The order of a stack said by places on the table ("ordered front to back", "sorted from left to right"):
    (pose index, sign) with the first place at the bottom, or None."""
    ends = {"front": (1, 1.0), "back": (1, -1.0), "left": (0, 1.0), "right": (0, -1.0)}
    for k, w in enumerate(said):
        if w not in ("ordered", "sorted", "order"):
            continue
        j = k + 1
        while j < len(said) and said[j] in ("from", "the"):
            j += 1
        if said[j : j + 1] and said[j] in ends and said[j + 1 : j + 2] == ["to"]:
            end = said[j + 3] if said[j + 2 : j + 3] == ["the"] else said[j + 2] if j + 2 < len(said) else ""
            if end in ends and ends[end][0] == ends[said[j]][0] and end != said[j]:
                return ends[said[j]]
    return None


@dataclass(frozen=True)
class RulesOptions:
    """Options of the rule-based parser.

    Attributes
    ----------
    prefer_anchor_from_other_goal : bool
        Resolve "one X" as a relation anchor to an object of another goal of
        the same command when there is one (the paper's reading).
    """

    prefer_anchor_from_other_goal: bool = True


#: A stack ordered by where its objects stand now: "from the one closest to me at the bottom to the one
#: furthest away at the top", "the leftmost at the bottom and the rightmost on top".
_STACK_BY_PLACE = re.compile(
    r"(?i),?\s*\b(?:from |with |starting with )?(?:the )?(?:one |block |object |thing )?(?:(closest|nearest|furthest|farthest)"
    r"(?: to| from)? (?:me|you|us|the front|the viewer|the back|away|back)(?: edge)?|(left|right|front|back)most)(?: one)? "
    r"(?:at|on|as) the (bottom|base)(?:,? (?:(?:all the way |right )?(?:up )?to|through to|and) the (?:one |block |object |thing )?"
    r"(?:(?:closest|nearest|furthest|farthest)(?: to| from)? (?:me|you|us|the front|the viewer|the back|away|back)(?: edge)?|"
    r"(?:left|right|front|back)most)(?: one)?(?: (?:at|on) (?:the )?top)?)?")


def _stack_by_place(text: str) -> tuple[str, tuple[int, float] | None]:
    """The text without a stacking order said by where the objects stand now, and that order as
    :func:`_stack_axis` gives it (pose index, sign; the first place at the bottom)."""
    m = _STACK_BY_PLACE.search(text)
    if m is None:
        return text, None
    near, side = (m.group(1) or "").lower(), (m.group(2) or "").lower()
    if near:
        said = m.group(0).lower().split()
        first = said[: min((k for k, w in enumerate(said) if w in ("at", "on", "as")), default=len(said))]
        to_front = any(w in ("me", "you", "us", "front", "viewer") for w in first)
        if near in ("closest", "nearest"):
            bottom_front = to_front
        else:  # "furthest from me" or "furthest away"/"furthest back" at the bottom: the back one
            bottom_front = "from" in first and not to_front
        key = (1, 1.0) if bottom_front else (1, -1.0)
    else:
        key = {"left": (0, 1.0), "right": (0, -1.0), "front": (1, 1.0), "back": (1, -1.0)}[side]
    return text[: m.start()] + text[m.end() :], key


#: A stacking order given by an attribute or a sort, which the parser does not read.
_ORDER_BY = re.compile(
    r"(?i)\b(in (ascending |descending |increasing |decreasing )?order of|ordered by|sorted by|sort(ed)? them|"
    r"in (size|height|colou?r|alphabetical|rainbow|reverse alphabetical|reverse) order|(rainbow|alphabetical) order|(in|by) the order of the (rainbow|alphabet)|by (size|height|colou?r|volume|weight)|"
    r"(from|by) (the )?(shortest|smallest|tallest|largest|biggest|lightest|darkest|heaviest) to (the )?"
    r"(shortest|smallest|tallest|largest|biggest|lightest|darkest|heaviest))\b")


@dataclass
class _State:
    named: set[int] = field(default_factory=set)
    last: list[int | Choice] = field(default_factory=list)
    #: The anchor of the previous clause's relation, if it had one.
    last_anchor: "int | Choice | None" = None
    #: The previous clause built a tower: "it" then means its top object.
    last_tower: bool = False
    #: Objects chosen by a selection clause ("select objects that are red.").
    selection: list[int | Choice] | None = None
    #: A pattern named before its objects ("make a tower: ...").
    header: tuple[str, dict, str] | None = None
    #: "one X" choices made so far ("the other one" takes the one left).
    choices: list = field(default_factory=list)
    #: A group said first and apart ("of the two green things, ..."), which "the other one" chooses from.
    group: list[int] = field(default_factory=list)
    #: The tower of the previous clause, which "then the red block" extends.
    tower: "_Pending | None" = None
    #: The object a stack role just placed in that tower: "then green" goes right above it.
    tower_prev: "int | Choice | None" = None
    #: The object a role just put at the top of that tower: "then yellow" goes right below it.
    tower_down: "int | Choice | None" = None
    #: That tower's order was said by "A on B" / "A under B": a role may not reverse it.
    tower_fixed: bool = False
    #: The last reference selected was a mass ("all the red stuff"): "it" is all of it.
    mass: bool = False
    #: After "put A left of B": (A, B), either of which a following "it" may mean.
    it_pair: "tuple | None" = None
    #: "it" was the reference object of the clause just read: the next clause's "it" is the same.
    it_chain: int | None = None
    #: The last arrangement read (a place said after it is its place).
    last_shape: "_Pending | None" = None
    #: The tower of the previous clause is listed from the top down.
    downward: bool = False
    #: Object nouns named so far, latest first ("stack the cans: green first").
    nouns: list = field(default_factory=list)


#: Plain colour words, said one after another for one object each ("red orange yellow").
_HUES = HUES


class _Parser(_TokenPasses, _GroupPasses, _Selecting, _Arrangements, _Framing, _Finishing):
    """The state of one command being read; its steps are the methods of the mixins it is built from."""

    def __init__(self, spec: SceneSpec, matcher: PatternMatcher, options: RulesOptions) -> None:
        self.spec = spec
        self.vocab = Vocabulary.from_scene(spec)
        self.matcher = matcher
        self.options = options
        self.infos = matcher.infos()
        self.key_vocab = matcher.vocabulary
        self.state = _State()
        #: The readings that answered, one per clause read (:mod:`.readings`).
        self.fired: list[str] = []
        #: Every word of the scene's category names ("letter", "a", "block" ...).
        self._cat_words = frozenset(x for key in self.vocab.categories for x in key)
        #: The clause being read starts "B on it": what the clause before named goes below B.
        self._below_first = False
        #: The object "it" means in the part being read when "it" named a reference object just before.
        self._chain: int | None = None
        #: (subject, reference) of the part before, where the part being read has no object but "it".
        self._implicit: tuple | None = None
        #: The part being read has a side or depth and no support word: its "it" after "A left of B" is B.
        self._it_beside = False
        #: The one object named first in the part being read, where nothing was named before it:
        #: what "it" later in the part means ("the brown box needs to end up with both white
        #: things in front of it").
        self._first: Mention | None = None
        #: The part being read names two objects or more, then "them" (and nothing before the part): "them"
        #: names those objects again, and nothing more.
        self._them_again = False
        #: A second reading: real words one slip from a scene noun read as that noun (.spelling.Corrector).
        self._slips = False
        #: Each part read with its references, for the check that every object named by itself is
        #: used; the rewritten text.
        self._named_in: list[tuple[tuple[str, ...], list[Mention]]] = []
        self._said = ""
        #: The measures said in numbers (.stages.mark_measures) and those a goal took.
        self._measures: list = []
        #: The poses said in numbers (.poses.mark_poses).
        self._poses: list[poses.SaidPose] = []
        self._measured: set[int] = set()
        #: The last goal read from a clause (a later clause with only a facing may be its).
        self._last_read: _Pending | None = None

    def command(self, text: str) -> GoalSpec:
        """Read one command into checked goals: its text said plainly (:meth:`_plain_text`) and rewritten
        (:meth:`_rewritten`), its words (:meth:`_command_words`), a place setting (:meth:`_dinner`,
        :meth:`_setting_clauses`), each clause read (:meth:`_read_clauses`), the checks on the whole
        (:meth:`_whole_command_checks`) and the goals assembled (:meth:`._finish`)."""
        text, order_by = self._plain_text(text)
        words = self._command_words(self._rewritten(text))
        dinner = self._dinner(words)
        if dinner is not None:
            return self._finish(dinner)
        clauses = split_clauses(words, self._cat_words)
        pending: list[_Pending] = []
        setting, clauses = self._setting_clauses(words, clauses, pending)
        self._read_clauses(words, clauses, pending)
        self._whole_command_checks(setting, pending, order_by)
        return self._stack_places_said(self._finish(pending))

    def _plain_text(self, text: str) -> tuple[str, re.Match | None]:
        """The command's text with its spelling corrected, its measures marked, its facings and places said
        plainly, its frame and any order along a line taken out; a command on a condition and a question
        are refused. Also the stacking order by an attribute said, if one is ("in order of size")."""
        # A stack ordered by an attribute ("in order of size"): which object goes
        # lowest is not fixed by the words read here; refused below if a stack results.
        text = formal.said_actively(self._spelled_right(spelling.starred(text)))
        text = steps.finding_steps(asides.bracketed(text, self._object_word, self._request_word), self._object_word)
        text = plain_words(stack_orders(repairs.repaired(text)))
        self._tilt(text)
        _taken_back(text)
        text = _restarted(text)
        self._order_inside(text)
        text, self._poses = poses.mark_poses(text)
        text, self._measures = stages.mark_measures(text)
        text = stages.other_side(stages.said_places(stages.pronoun_facings(stages.said_facings(text))))
        text = unframe(text)
        text, by_place = _stack_by_place(text)
        order_by = _ORDER_BY.search(text)
        self._stack_axis = by_place or _stack_axis(lexicon.words(text))
        # The order along a line ("from left to right") is not part of any goal.
        # "the third block from the left to the right of the bowl" is a reference and a side, no order.
        text = re.sub(r"(?i)\b(from )?(the )?(left to( the)? right|right to( the)? left|front to( the)? back|back to( the)? front)"
                      r"\b(?!(?:\s+hand)?(?:\s+side)?\s+of\b)", " ", text)
        text = re.sub(r"(?i)\b(from|by) (the )?(shortest|smallest|tallest|largest|biggest|lightest|darkest) to (the )?"
                      r"(shortest|smallest|tallest|largest|biggest|lightest|darkest)\b", " ", text)
        bare = re.sub(r"(?i)^\s*(?:(?:hmm+|um+|uh+|so|well|ok(?:ay)?|hey|hi|oh|right|now)\b[,\s]*)+", "", text)
        question = QUESTION.match(bare) or re.search(r"(?i)\b(?:do|don't) you think\s*\?\s*$", bare)
        cond = re.match(r"(?i)^\s*(?:if|unless|in case|when(?:ever)?)\s+(?:the|a|an|any|there|all|both|every|no|it|they)\b"
                        r"(?!\s*(?:is|'s|isn't|is not)?\s*(?:not )?(?:too much|possible|ok|okay|alright|convenient|no)"
                        r"\b)", bare)
        if cond is not None:
            raise InputError(f"'{text.strip()}': a command that depends on a condition is not read; "
                             f"say what to arrange")
        if question is not None and not ASKS_TO_ACT.match(bare):
            raise InputError(f"'{text.strip()}' is a question about the scene, not a command; say what to arrange")
        return text, order_by

    def _rewritten(self, text: str) -> str:
        """The text with objects picked by position or colour named by id, the rewrite table applied, ids said
        after their category and letters said bare read as objects."""
        letters = {n.split()[1].upper() for _, n, _ in self.vocab.objects if n.startswith("letter ") and len(n.split()) == 2}
        if letters:
            # "the T", "the A": a capital letter standing for the letter the scene has (before the references by
            # position and colour read them: "the blocks that match the A and the E").
            text = re.sub(r"\b([Tt]he) ([A-Z])\b(?!')", lambda m: f"{m.group(1)} letter {m.group(2)}"
                          if m.group(2) in letters else m.group(0), text)
        text = stages.named_before(text, self._find, self._every_match)
        text, self.state.group = stages.partitive(text, self._find, self._every_match)
        text = stages.by_position(text, self._find, self._every_match, self._table_xy, self._centre, self._cat_words,
                                  dict(self.vocab.borrowed), group=self.state.group)
        text = stages.by_colour(text, self._find, self._every_match, {o.id: o.color for o in self.spec.objects})
        text = stages.same_again(text, self._find, self._every_match)
        text = pair_named(text, self._find, self._every_match)
        text = stack_by_colours(text, self._find, self._every_match)
        self._nearness(text)
        text = rewrite(self._articles(text))
        self._said = text
        text = self._category_ids(text)
        if letters:
            text = stages.spelled(text, letters)
            text = stages.letters_named(text, letters)
            # "A then R then T then E", "R, T, E": capitals said bare ("A" only where it cannot be
            # the article: after a list word, or before one or the end).
            text = re.sub(r"\b([A-Z])\b(?!')", lambda m: _bare_letter(m, letters), text)
        return text

    @staticmethod
    def _tilt(text: str) -> None:
        """Refuse a way to stand an object that no goal holds ("the cans in a row, upside down"); said before
        a noun it is a name, not a way to stand ("upside-down challenge!"). Refuse a pouring asked for ("Pour
        the bottle into the cup"), not one said as a purpose ("so I can pour the tea")."""
        toks = [t.text for t in tokenize(text) if t.text != "-"]
        for i, end, _ in lexicon.phrase_spans(toks, "tilt"):
            if end == len(toks) or not toks[end][0].isalpha() or toks[end] in _AFTER_TILT:
                raise InputError(f"'{' '.join(toks[i:end])}': a goal keeps every object upright and sets only which "
                                 f"way it faces on the table; say the command without it")
        for i, end, _ in lexicon.phrase_spans([t.lower() for t in toks], "pour"):
            if i == 0 or toks[i - 1] in _BEFORE_POUR or (i >= 2 and toks[i - 2 : i] == ["to", "be"]):
                raise InputError(f"'{' '.join(toks[i:end])}': pouring is not a pick-and-place goal; say where the "
                                 f"objects should stand")

    def _stack_places_said(self, spec: GoalSpec) -> GoalSpec:
        """Refuse a place in a stack said by its number from the bottom or the top ("the green block fourth
        from the bottom") that the stack read does not have: the words would be read past."""
        low = self._said.lower()
        if not any(o in low for o in _STACK_ORDINALS):  # (each word of a token is in the lower-cased text)
            return spec
        toks = [t.text for t in tokenize(self._said)]
        towers = [len(g.objects) for g in spec.goals if g.pattern == "tower"]
        for i, w in enumerate(toks):
            n = _STACK_ORDINALS.get(w)
            if n is not None and tuple(toks[i + 1 : i + 4]) in (("from", "the", "bottom"), ("from", "the", "top")) \
                    and not any(k >= n for k in towers):
                raise InputError(f"'{' '.join(toks[i : i + 4])}': the stack read has "
                                 f"{max(towers, default=0)} objects; list the objects from the bottom up")
        return spec

    @staticmethod
    def _order_inside(text: str) -> None:
        """Refuse an order of the objects inside an arrangement said by a superlative of size ("line up the
        cans, tallest in the middle", "stack the bowls, biggest on the bottom"): no goal holds it (a stack by
        size is refused like "in order of size"), and reading "in the middle" as the table's middle would be a
        wrong goal."""
        low = text.lower()
        if not any(w in low for w in _SIZE_SUPERLATIVES):
            return
        toks = [t.text for t in tokenize(text)]
        for i, w in enumerate(toks):
            if w not in _SIZE_SUPERLATIVES:
                continue
            k = i + 1 + (toks[i + 1 : i + 2] in (["one"], ["ones"]))
            if tuple(toks[k : k + 3]) in _INSIDE_PLACES or tuple(toks[k : k + 2]) in _INSIDE_PLACES:
                raise InputError(f"'{' '.join(toks[i : k + 3])}': an order of the objects inside an arrangement is "
                                 f"not part of any goal; say the command without it")

    def _nearness(self, text: str) -> None:
        """Refuse "closer to the plate" left over once references by position are read: how near one object
        stands to another is part of no goal, and reading it as a side (in front of) would be a wrong goal.
        Closer to the viewer or an edge is a direction and is left to the readers."""
        said = lexicon.words(text)
        for i, w in enumerate(said):
            if w not in ("closer", "nearer") or said[i + 1 : i + 2] != ["to"]:
                continue
            rest = said[i + 2 : i + 6]
            if any(x in lexicon.VIEWER_WORDS or x in _EDGE_NOUNS for x in rest):
                continue
            noun = next((x for x in rest if x in self._cat_words or _stem(x) in self._cat_words), None)
            if noun is not None:
                phrase = " ".join(said[i : i + 2 + rest.index(noun) + 1])
                raise InputError(f"'{phrase}': how near one object stands to another is not part of any goal; "
                                 f"say which side of it (left of, in front of, ...)")

    def _command_words(self, text: str) -> tuple[str, ...]:
        """The words of the text with the token passes applied (spoken lists, parentheses, context and remark
        sentences, "the former/latter", bare colour sets); refuses a reference to no object, and encodes
        in one batch the words that may be read by their own embedding."""
        words = normalise(tuple(t.text for t in tokenize(text)))
        if not any(w.isalnum() for w in words):
            raise InputError("the instruction is empty")
        words = self._spoken_lists(words)
        for k, w in enumerate(words[:-1]):
            nxt = words[k + 1]
            if (w == "no" and (nxt in ("objects", "object", "things", "thing", "items", "item") or (
                    nxt not in ("particular", "order", "matter", "wait") and (
                        nxt in self._cat_words or _stem(nxt) in self._cat_words or nxt in COLOUR_WORDS)))) or (
                    w == "none" and nxt == "of"):
                raise InputError(f"'{w} {nxt}': a reference to no object selects nothing to arrange")
        words = self._all_but(self._parentheses(words))
        words = stages.without_context(words, self._object_word, self._request_word)
        words = self._context_sentences(words)
        words = self._only_these(self._trailing_remarks(words))
        words = self._respectively(self._restated_one(self._put_in(self._former_latter(words))))
        words = self._bare_colour_sets(self._noun_first_lists(words))
        # Words that may be read by their own embedding, encoded in one batch
        # (one forward pass for all of them instead of one per word).
        cand = [w for w in dict.fromkeys(words) if w.isalpha() and len(w) >= 4 and _stem(w) not in self.key_vocab
                and not stages.is_mark(w)
                and _stem(w) not in STOPWORDS and _stem(w) not in FILLERS and w not in STOPWORDS
                and (w,) not in self.vocab.categories and w not in self.vocab.color_words and w not in COLOUR_WORDS]
        if cand:
            self.matcher.prefetch(cand)
        return words

    def _setting_clauses(self, words: tuple[str, ...], clauses: list[tuple[str, ...]],
                         pending: list[_Pending]) -> tuple[list[_Pending], list[tuple[str, ...]]]:
        """Where a place setting is asked for among other clauses, its goals (added to ``pending``) and the
        clauses left to read; no goals and the clauses as they are otherwise."""
        dinner: list[_Pending] | None = None
        if self._dinner_at(words) is not None:
            # "set the table, and put the mug behind the plate as well": the
            # setting from the clauses about it, the other clauses as usual.
            # Where the scene has no setting to lay, "set the table" only
            # introduces what follows ("set the table: stack the bowl on the plate ...").
            own = [c for c in clauses if self._dinner_at(c) is not None or self._setting_only(c)]
            try:
                dinner = self._dinner(tuple(w for c in own for w in c + (",",))[:-1])
            except InputError:
                dinner = []
            if dinner is None:
                # "the table laid for a meal, and the mug should be behind the plate": the
                # setting up to the first break after it, the rest a clause of its own.
                at = next(c for c in clauses if self._dinner_at(c) is not None)
                k = self._dinner_at(at)
                assert k is not None  # the clause was chosen for it
                cut = next((j for j in range(k + 1, len(at)) if at[j] in (",", "and", "plus", "with", "but")), None)
                if cut is not None:
                    head, tail = at[:cut], at[cut:]
                    while tail and tail[0] in (",", "and", "plus", "with", "but", "also"):
                        tail = tail[1:]
                    try:
                        alone = self._dinner(head) if tail and not self._setting_only(tail) else None
                    except InputError:
                        alone = None
                    if alone:
                        dinner, own = alone, [c for c in own if c is not at]
                        clauses = [tail if c is at else c for c in clauses]
            if dinner is None:
                raise InputError(f"'{' '.join(words)}': cannot tell which parts belong to the place setting")
            if dinner:
                pending.extend(dinner)
                clauses = [c for c in clauses if c not in own]
        return (dinner if isinstance(dinner, list) else []), clauses

    def _read_clauses(self, words: tuple[str, ...], clauses: list[tuple[str, ...]], pending: list[_Pending]) -> None:
        """Read the clauses into ``pending``, without their asides and the parts that only leave an order open
        or leave objects alone, a topic said first cut from the command about it, each clause cut where it
        states two goals and "the same for ..." read as the clause before."""
        clauses = [self._same_said_after(c) for c in clauses]
        kept = [c for c in (c if _SAME.match(" ".join(c)) else self._without_asides(c) for c in clauses)
                if c and not self._free_order(c) and not self._left_alone(c)]
        if clauses and not kept:
            raise InputError(f"'{' '.join(words)}' names no object in the scene and no arrangement")
        kept = _merged_moves([c for k in kept for c in self._topic_split(k)])
        last: tuple[str, ...] = ()
        for whole in kept:
            try:
                stated = _predicate_split(whole, self._find(whole), *self._word_kinds())
            except InputError:
                stated = [whole]
            for clause in stated:
                before = len(pending)
                self._read_clause(self._same_as_before(clause, last), pending)
                if len(pending) > before:
                    last = clause

    def _stack_by_axis(self, tower: _Pending) -> None:
        """A stack "ordered front to back" (left to right ...): its objects from the bottom up in that order of
        their places on the table now; a role said that the order breaks is a contradiction."""
        assert self._stack_axis is not None
        axis, sign = self._stack_axis
        ids = [x for x in tower.objects if isinstance(x, int)]
        where = {x: (self.spec.object(x).pose or (0.0, 0.0, 0.0))[axis] * sign for x in ids}
        ranked = sorted(ids, key=lambda x: (where[x], x))
        close = next(((a, b) for a, b in zip(ranked, ranked[1:]) if where[b] - where[a] < TOO_CLOSE), None)
        if close is not None:
            raise InputError(f"the order said is unclear: objects {close[0]} and {close[1]} stand within "
                             f"{TOO_CLOSE * 100:.0f} cm of each other along it; name the objects from the bottom up")
        for x, role in tower.said.items():
            if (role == "bottom" and ranked[0] != x) or (role == "top" and ranked[-1] != x):
                raise InputError(f"contradiction: the order said puts object {x} at the "
                                 f"{'bottom' if ranked.index(x) == 0 else 'top' if ranked[-1] == x else 'middle'}, "
                                 f"not at the {role}")
        tower.objects[:] = ranked

    def _whole_command_checks(self, setting: list[_Pending], pending: list[_Pending], order_by: re.Match | None) -> None:
        """What holds for the command as a whole: the side of a place setting said again is dropped, a tower
        header takes its steps' goals, and a header with no objects, a stacking order by an attribute and
        a command with nothing to arrange are refused."""
        side = next((p for p in setting if p.pattern in ("left", "right")), None)
        stack = set(next((p.objects for p in setting if p.pattern == "tower"), []))
        if side is not None and any(p is not side and p.pattern in RELATIONS and set(p.objects) == set(side.objects)
                                    and p.anchor in stack | {side.anchor} for p in pending):
            # "get dinner ready: the bowl on the plate and the cutlery on the right of it": the side said.
            pending.remove(side)
        if self.state.header is not None and self.state.header[0] == "tower" and any(
                p.pattern == "tower" for p in pending):
            # "build a single tower: A on B, and B on C": the steps built it.
            hparams = self.state.header[1]
            for p in pending:
                if p.pattern == "tower":
                    p.params = {**hparams, **p.params}
            self.state.header = None
        if self.state.header is not None:
            raise InputError(f"'{self.state.header[2]}' names no object in the scene")
        towers = [p for p in pending if p.pattern == "tower"]
        if self._stack_axis is not None and len(towers) == 1 and all(isinstance(x, int) for x in towers[0].objects):
            self._stack_by_axis(towers[0])
        if order_by is not None and any(p.pattern == "tower" for p in pending):
            raise InputError(f"'{order_by.group(0)}': a stacking order by size, colour or sorting is not read; "
                             f"name the objects from the bottom up")
        if not pending:
            if self.state.selection is not None:
                raise InputError("the instruction selects objects but does not say how to arrange them")
            raise InputError("the instruction names nothing to arrange")


#: Words that may follow a request taken back ("..., never mind, thanks").
_AFTER_CANCEL = frozenset({"thanks", "thank", "you", "cheers", "ta", "please", "sorry", "then", "ok", "okay", "after",
                           "all", "actually", "lol", "just", "i", "guess", "robot", "mate"})


def _restarted(text: str) -> str:
    """The request said after one taken back ("the letters in a row facing north... oh no, forget it. Put the
    letters in a circle."): a phrase of the lexicon's ``restart`` list said between stops, with a request after
    it, ends what came before."""
    toks = tokenize(text)
    words = [k for k, t in enumerate(toks) if t.text[:1].isalnum() or t.text[1:2].isalnum()]
    for s, e, _ in sorted(lexicon.phrase_spans([toks[k].text for k in words], "restart"), reverse=True):
        first, last = words[s], words[e - 1]
        if last + 2 < len(toks) and toks[last + 1].text in ".!?;," and (first == 0 or toks[first - 1].text in
                                                                          ".!?;,-\u2026\u2014" or toks[first - 1].text == "no"):
            rest = text[toks[last + 1].end :].lstrip(" .,;!?")
            if not {"it", "them", "they", "those", "these", "em"} & set(lexicon.words(rest)):
                return rest  # what is said after names its own objects
    return text


def _leaves_all(words: list[str]) -> bool:
    """Whether the words after a cancelling phrase ask for nothing: thanks and the like, or a request to leave
    things be ("forget it. leave the letters alone today, please.", "... just leave them where they are")."""
    rest = [w for w in words if w not in _AFTER_CANCEL and w not in ("today", "now", "for", "the", "time", "being")]
    if words[:2] in (["i", "ll"], ["i", "will"]) or words[:1] == ["i'll"]:
        # "..., never mind, I'll sort it meself": the person will do it, nothing is asked
        return len(words) <= 7 and not {"put", "move", "place", "stack", "line", "arrange"} & set(words)
    if rest[:1] != ["leave"] or len(rest) > 8:
        return not rest
    tail = rest[1:]
    return any(tail[k:k + len(p)] == list(p) for p in _LEFT_BE for k in range(len(tail)))


#: How "leave ..." ends when it asks that nothing moves ("leave them alone", "... where they are", "... be").
_LEFT_BE = (("alone",), ("be",), ("where", "they", "are"), ("where", "it", "is"), ("as", "they", "are"),
            ("as", "it", "is"), ("untouched",))


def _taken_back(text: str) -> None:
    """Refuse a command whose end takes the request back ("stack the bottles, wait no, never mind, don't do
    anything, thanks"; the cue list ``cancel`` of the lexicon): the request before it is not asked (before, the
    stack was answered and the words after it dropped)."""
    ws = lexicon.words(text)
    spans = sorted(lexicon.phrase_spans(ws, "cancel"))
    if not spans or not _leaves_all(ws[max(e for _, e, _ in spans):]):
        return
    start = spans[-1][0]
    for s, e, _ in reversed(spans[:-1]):
        if e <= start and all(w in _AFTER_CANCEL or w in ("no", "wait") for w in ws[e:start]):
            start = s  # the run of cancelling words that ends the command
    said = text[text.lower().rfind(ws[start]):].strip(" ,.!")
    raise InputError(f"'{said}': the request is taken back; nothing is asked")


def goal_dicts(spec: SceneSpec, text: str, *, matcher: PatternMatcher, options: RulesOptions | None = None) -> list[dict]:
    """The goals the parser reads, as dicts with their parameters (region, size, facing) even where the
    goal format does not take them yet."""
    return _read_command(spec, text, matcher, options or RulesOptions(), 2)[1].goal_dicts


def parse_rules(
    spec: SceneSpec, text: str, *, matcher: PatternMatcher, options: RulesOptions | None = None
) -> GoalSpec:
    """Parse ``text`` against ``spec`` with the rule-based parser.

    Raises
    ------
    InputError
        With one line saying what was not understood.
    """
    return _read_command(spec, text, matcher, options or RulesOptions(), 2)[0]


def _read_command(spec: SceneSpec, text: str, matcher: PatternMatcher, options: RulesOptions,
                  tries: int) -> tuple[GoalSpec, _Parser]:
    """:meth:`_Parser.command` and the parser that read it, read again without a backdrop sentence its refusal
    blames (:mod:`.backdrop`, at most ``tries`` times) or with real words one slip from a scene noun read as that
    noun; the first refusal stands where the second reading fails too."""
    parser = _Parser(spec, matcher, options)
    try:
        return parser.command(text), parser
    except InputError as err:
        said = stages.unmark(str(err), parser._measures)
        again = backdrop.without_backdrop(text, said, parser._object_word, _command_verb) if tries else None
        if again is not None:
            try:
                return _read_command(spec, again, matcher, options, tries - 1)
            except InputError:
                pass
        slipped = _Parser(spec, matcher, options)
        slipped._slips = True  # "line up the cams pls": a phone's autocorrect, read only where nothing else reads
        if tries and slipped._spelled_right(text) != parser._spelled_right(text):
            try:
                return slipped.command(text), slipped
            except InputError:
                pass
        if said == str(err):
            raise
        raise InputError(said) from None
