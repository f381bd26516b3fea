"""Context that asks nothing: background sentences, time clauses, remarks.

A pure stage over lower-cased tokens (after the casual register is
normalised), before the command is cut into clauses. What it drops is what
asks for no goal and names nothing a goal could use:

* a **background sentence** with no object word and no word of a request
  (no pattern, direction, place or command verb): "the dog knocked things
  over.", "we have guests coming at seven.", "dinner's in 20 minutes!!" (a
  meal said with a time asks for no place setting);
* a **time clause** at the start or the end of a sentence ("after lunch,",
  "once the kids are asleep,", "before then,", "whenever you get a chance,",
  "..., before the guests arrive"), under the same condition after its
  opening word, so that "after the bowl is on the plate, ..." (it names an
  object) is kept and read;
* nothing of a sentence that names an object: what a remark names may be
  what a later "it" means, and such sentences are left to the parser.

A command is never emptied: when every sentence would go, it is returned as
it came (and refused downstream as asking for nothing).
Which words count is the caller's: ``object_word(w)`` (the scene's names,
colours, ids) and ``request_word(w)`` (pattern words, directions, places,
command verbs).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from . import lexicon

__all__ = ["TIME_OPENERS", "drop_context", "person_remark"]

#: Words that open a time clause.
TIME_OPENERS = frozenset({"after", "before", "once", "when", "whenever", "while", "until", "till", "by", "tonight",
                          "tomorrow", "later", "today", "afterwards", "soon", "sometime", "eventually", "first",
                          "as", "this", "in", "at"})
#: A time clause must say when: a word of time after its opener (or the opener is one itself).
_TIME_WORDS = frozenset({"lunch", "dinner", "breakfast", "tea", "supper", "brunch", "then", "now", "tonight",
                         "tomorrow", "today", "later", "morning", "evening", "afternoon", "night", "weekend",
                         "asleep", "awake", "back", "home", "here", "arrive", "arrives", "come", "comes", "gets",
                         "get", "chance", "minute", "minutes", "hour", "hours", "min", "mins", "trial", "run",
                         "meeting", "class", "guests", "kids", "done", "finished", "leave", "leaves", "o'clock",
                         "noon", "midnight", "soon", "sometime", "eventually", "afterwards", "bed", "school", "work",
                         "shift", "demo", "test", "experiment", "session", "party", "meal", "moment", "second",
                         "while", "wake", "wakes", "start", "starts", "begin", "begins", "over", "ready", "time"})
_SOLO_TIME = frozenset({"tonight", "tomorrow", "later", "today", "afterwards", "soon", "sometime", "eventually"})
_KEEP_AFTER = frozenset({"that", "this", "it", "them", "which", "those", "these", "all", "the"})
_ENDS = (".", "!", "?", ";")


def _sentences(words: tuple[str, ...]) -> list[tuple[str, ...]]:
    out: list[tuple[str, ...]] = []
    start = 0
    for k, w in enumerate(words):
        if w in _ENDS and (k + 1 == len(words) or words[k + 1] not in _ENDS):
            out.append(words[start : k + 1])
            start = k + 1
    if start < len(words):
        out.append(words[start:])
    return out


_MEALS = frozenset({"dinner", "lunch", "breakfast", "tea", "supper", "brunch", "meal", "dinnertime", "lunchtime"})
_CLOCK = frozenset({"min", "mins", "minute", "minutes", "hour", "hours", "hr", "hrs", "o'clock", "soon", "tonight",
                    "tomorrow", "later", "noon", "pm", "am"})


def _idle(part: tuple[str, ...], object_word: Callable[[str], bool], request_word: Callable[[str], bool]) -> bool:
    """Whether ``part`` names no object and no word of a request; a meal said with a time ("dinner's
    in 20 minutes") is no request for a place setting."""
    timed = any(w in _CLOCK for w in part)
    return not any(object_word(w) or (request_word(w) and not (timed and w in _MEALS)) for w in part)


def _time_clause(part: tuple[str, ...]) -> bool:
    """Whether ``part`` (without its comma) says when: "after lunch", "once the kids are asleep"."""
    if not part or part[0] not in TIME_OPENERS:
        return False
    if part[0] in _SOLO_TIME and len(part) <= 3:
        return True
    if part[0] in ("after", "before") and len(part) > 1 and part[1] in _KEEP_AFTER - {"the"}:
        return part[1] == "then" if part[0] == "before" else False
    return any(w in _TIME_WORDS or w.isdigit() for w in part[1:])


def drop_context(words: tuple[str, ...], object_word: Callable[[str], bool],
                 request_word: Callable[[str], bool]) -> tuple[str, ...]:
    """``words`` without the background sentences and time clauses that ask for nothing."""
    sentences = _sentences(words)
    kept: list[tuple[str, ...]] = []
    for sent in sentences:
        body = tuple(w for w in sent if w not in _ENDS)
        if body and _idle(body, object_word, request_word):
            continue  # a background sentence
        kept.append(_without_time(sent, object_word, request_word))
    if not kept or not any(w not in _ENDS and w != "," for s in kept for w in s):
        return words
    return tuple(w for s in kept for w in s)


def _without_time(sent: tuple[str, ...], object_word: Callable[[str], bool],
                  request_word: Callable[[str], bool]) -> tuple[str, ...]:
    """A sentence without its leading and trailing time clauses that ask for nothing."""
    while True:
        cut = next((k for k, w in enumerate(sent) if w == ","), None)
        if cut is None or cut == 0:
            break
        head = sent[:cut]
        if not (_time_clause(head) and _idle(head[1:], object_word, request_word)):
            break
        sent = sent[cut + 1 :]
    end = len(sent)
    while end and sent[end - 1] in _ENDS:
        end -= 1
    for k in range(end - 1, 0, -1):
        if sent[k] in TIME_OPENERS and sent[k] not in ("in", "at", "as", "this", "first", "while"):
            tail = sent[k:end]
            before = sent[:k]
            if _time_clause(tail) and _idle(tail[1:], object_word, request_word) and any(
                    request_word(w) for w in before):
                while before and before[-1] == ",":
                    before = before[:-1]
                return before + sent[end:]
            break
    return sent


_CTX = lexicon.context_words()


def _subject_end(body: Sequence[str]) -> int:
    """How many words of ``body`` make a subject that is a person or a pet ("i'm", "the kids", "my
    nephew's"), 0 for none."""
    if body and body[0] in _CTX["person_pronouns"]:
        return 1
    if len(body) > 1 and body[0] in _CTX["person_possessives"]:
        noun = body[1][:-2] if body[1].endswith("'s") else body[1]
        if noun in _CTX["people"]:
            return 2
    return 0


def person_remark(body: Sequence[str], object_word: Callable[[str], bool],
                  request_word: Callable[[str], bool], command_verb: Callable[[str], bool]) -> bool:
    """Whether ``body`` (the words of a sentence or clause, no punctuation) is a remark about the people or
    pets of the house that asks for nothing: its subject is one of them ("the kids left them all over the
    place", "i'm trying to teach the little one colours lol"), and after it there is no word of the scene's
    objects (``object_word``), no word by which it would ask ("we need", "i'd like", :data:`_CTX` ``asking``)
    and no word of a goal (``request_word``), where a command verb after such a subject is told, not asked
    ("trying to get the little one to learn") and a direction word counts only in a place ("to the left",
    "left of"; "the kids left them" is a verb).

    >>> remark = lambda s: person_remark(s.split(), lambda w: w in {"cans", "red"},
    ...                                  lambda w: w in {"left", "line", "get", "on"}, lambda w: w == "get")
    >>> remark("the kids left them all over the place"), remark("i'm trying to get the little one to learn")
    (True, True)
    >>> remark("we need them in a line"), remark("the kids left the red cans"), remark("the kids are on the left")
    (False, False, False)
    """
    k = _subject_end(body)
    if not k:
        return False
    rest = list(body[k:])
    for j, w in enumerate(rest):
        if w in _CTX["asking"] or object_word(w):
            return False
        if w in lexicon.DIRECTIONS:
            before = rest[j - 1] if j else ""
            after = rest[j + 1] if j + 1 < len(rest) else ""
            if before in _CTX["place_before"] or after in _CTX["place_after"]:
                return False
            continue
        if request_word(w) and not command_verb(w):
            return False
    return bool(rest)
