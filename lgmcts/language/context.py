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
* **chatter said in the same breath** as the request, without a full stop:
  what comes before a request opener ("my sister's coming over at like
  seven and she's super picky so um could you put ...", the lexicon's
  ``request_openers``), a cut word ("..., whatever, um the letters should
  ...", ``chatter_cuts``) or a colon ("before the inspector comes
  tomorrow: ..."); a time clause said without a comma before the first
  object ("by the time she's here the four letters should ..."); and talk
  of the time or the people of the house before the first object ("it's
  almost noon and lunch is at one the cans ..."), each only where it names
  no object and asks for nothing (a direction only counts in a place, and
  "coming over", "at seven", "7 o'clock" are chatter);
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

__all__ = ["TIME_OPENERS", "drop_context", "meal_visited", "moves_unknown", "person_remark", "wishes"]

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
                         "while", "wake", "wakes", "start", "starts", "begin", "begins", "over", "ready", "time",
                         "round", "rounds", "handover", "break", "nap", "shower", "call", "meds", "visit", "visitors"})
_SOLO_TIME = frozenset({"tonight", "tomorrow", "later", "today", "afterwards", "soon", "sometime", "eventually"})
_KEEP_AFTER = frozenset({"that", "this", "it", "them", "which", "those", "these", "all", "the"})
_ENDS = (".", "!", "?", ";")
_CTX = lexicon.context_words()


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
_CLOCK = frozenset({"min", "mins", "minute", "minutes", "hour", "hours", "hr", "hrs", "o'clock", "clock", "soon", "tonight",
                    "tomorrow", "later", "noon", "pm", "am"})


def _idle(part: tuple[str, ...], object_word: Callable[[str], bool], request_word: Callable[[str], bool],
          timed: bool = False) -> bool:
    """Whether ``part`` names no object and no word of a request; a meal said with a time ("dinner's
    in 20 minutes") or after a time clause's opener (``timed``: "before lunch") is no request for a place
    setting."""
    timed = timed or any(w in _CLOCK for w in part)
    clock = _clock_words(part)
    owned = _owned(part)
    return not any(((object_word(w) and not _article(part, j))
                    or (request_word(w) and not (timed and w in _MEALS) and j not in owned))
                   and j not in clock for j, w in enumerate(part))


def _article(part: Sequence[str], j: int) -> bool:
    """Whether the word at ``j`` is the article "a" or the pronoun "i" rather than a letter of the scene ("a long
    day" where the scene has a letter A; "the A", "letter A" stay the letter)."""
    return part[j] in ("a", "an", "i") and not (j and part[j - 1] in ("the", "letter", "letters"))


def _owned(part: Sequence[str]) -> set[int]:
    """The places of the nouns said after a person's possessive or a length of time ("my shift", "her nap",
    "12hr shift", "night shift"): nouns, never the verbs of a request the same words can be ("shift", "set")."""
    return {j for j in range(1, len(part)) if not part[j].isdigit() and (
        part[j - 1] in _POSSESSIVES or part[j - 1] in _SHIFT_KINDS
        or (part[j] in _TIME_WORDS and (part[j - 1] in _CLOCK or any(c.isdigit() for c in part[j - 1]))))}


_SHIFT_KINDS = frozenset({"night", "day", "late", "early", "double", "long", "morning", "evening", "graveyard"})
_KEEP = frozenset({"keep", "keeps", "kept", "keeping"})
#: Lengths of time a size word may qualify ("a long day", "a short week").
_SPANS = frozenset({"day", "days", "week", "weeks", "night", "nights", "shift", "shifts", "morning", "evening",
                    "afternoon", "year", "month", "while", "time", "one"})


_POSSESSIVES = frozenset({"my", "our", "his", "her", "their", "your"})
#: Words before the noun of a time ("before the meeting", "after my shift").
_OWNERS = _POSSESSIVES | {"the"}


def _time_spans(part: Sequence[str]) -> set[int]:
    """The places of the words of a time said inside ``part`` by an opener and a word of time ("quick one
    before lunch", "right after my shift"): a time, not a request ("before" is also "in front of")."""
    out: set[int] = set()
    for j, w in enumerate(part):
        if w not in _EVENT_OPENERS and w != "by":
            continue
        k = j + 1
        while k < len(part) and part[k] in _OWNERS:
            k += 1
        if k < len(part) and (part[k] in _TIME_WORDS or part[k] in _MEALS or part[k] in _DAY_WORDS):
            out.update(range(j, k + 1))
            while k + 1 < len(part) and part[k + 1] in _TIME_WORDS:
                k += 1
                out.add(k)  # "before meds round"
    return out


def _clock_words(part: Sequence[str]) -> set[int]:
    """The places of the words of each time of day in ``part`` ("7 o clock": all three)."""
    out: set[int] = set()
    for j in range(len(part)):
        if _clock_time(part, j):
            out.update((j, j + 1) if part[j + 1] != "o" else (j, j + 1, j + 2))
        elif part[j].isdigit() and j and part[j - 1] in ("at", "by", "till", "until") and (
                j + 1 == len(part) or part[j + 1] in (",", "and", "so", "tonight", "today", "tomorrow", ".")):
            out.add(j)  # "my mom gets home at 6 and ...": a time
    return out


def _clock_time(part: Sequence[str], j: int) -> bool:
    """Whether the number at ``j`` is a time of day ("7 o'clock", "7 o clock", "7 pm"), not an object's id."""
    return part[j].isdigit() and j + 1 < len(part) and part[j + 1] in _CLOCK | {"o"}


def _time_clause(part: tuple[str, ...]) -> bool:
    """Whether ``part`` (without its comma) says when: "after lunch", "once the kids are asleep"."""
    if not part or part[0] not in TIME_OPENERS:
        return False
    if part[0] in _SOLO_TIME and len(part) <= 3:
        return True
    if part[0] in ("after", "before") and len(part) > 1 and part[1] in _KEEP_AFTER - {"the"}:
        return part[1] in ("then", "that") and len(part) == 2 if part[0] == "before" else False
    return any(w in _TIME_WORDS or w.isdigit() for w in part[1:])


#: Openers of a clause that says when by an event ("once the rice is on", "until the guests have gone"), and
#: the words a subject of such an event starts with.
_EVENT_OPENERS = frozenset({"once", "after", "before", "until", "till", "while", "when", "whenever"})
#: Subjects of an event that the speaker does ("while I put the kettle on"): its verb is theirs, no request.
_SPEAKER = frozenset({"i", "we", "i'm", "we're", "i've", "we've"})
_SUBJECT_START = frozenset({"the", "my", "our", "his", "her", "your", "their", "we", "i", "you", "he", "she", "they",
                            "we've", "i've", "everyone", "everybody"})


def _event_clause(part: tuple[str, ...], object_word: Callable[[str], bool],
                  request_word: Callable[[str], bool]) -> bool:
    """Whether ``part`` (without its comma) says when by an event of the house that names no object of the
    scene and asks nothing ("once the rice is on", "before my sister gets here"): a particle of chatter
    ("on", "over") is no request there (:func:`_asks_nothing`)."""
    if not (len(part) > 2 and part[0] in _EVENT_OPENERS and part[1] in _SUBJECT_START):
        return False
    verb = 3 if part[1] in _OWNERS else 2  # "before the glue sets", "until it dries": the event's own verb
    said = part[1:]
    if verb < len(part) and (part[verb].endswith("s") or part[1] in _SPEAKER) and not object_word(
            part[verb - 1]) and not object_word(part[verb]):
        said = part[1:verb] + part[verb + 1 :]  # a verb of the event ("sets"), not a request to set something
    return _asks_nothing(said, object_word, request_word)


def drop_context(words: tuple[str, ...], object_word: Callable[[str], bool],
                 request_word: Callable[[str], bool]) -> tuple[str, ...]:
    """``words`` without the background sentences and time clauses that ask for nothing."""
    sentences = _sentences(words)
    kept: list[tuple[str, ...]] = []
    for k, sent in enumerate(sentences):
        sent = _without_chatter(sent, object_word, request_word)
        body = tuple(w for w in sent if w not in _ENDS)
        if body and not wishes(body) and (_idle(body, object_word, request_word) or (
                k < len(sentences) - 1 and _asks_nothing(body, object_word, request_word))):
            continue  # a background sentence ("it's been raining all week and the cat's been under my feet.")
        if k < len(sentences) - 1 and _reported(body):
            continue  # "my mum always said a proper table has the knife on the right." before the request
        if k < len(sentences) - 1 and _story(body, object_word, request_word):
            if not any(w in _PRONOUNS for s in sentences[k + 1 :] for w in s):
                continue  # "i used to play with blocks like these as a little girl." before the request
            named = _story_objects(body, object_word)
            if named:  # "my granddaughter set these letters out last week. ... them in a circle": what "them" means
                kept.append(named + (".",))
                continue
        kept.append(_without_time(sent, object_word, request_word))
    if not kept or not any(w not in _ENDS and w != "," for s in kept for w in s):
        return words
    return tuple(w for s in kept for w in s)


def wishes(body: Sequence[str]) -> bool:
    """Whether ``body`` says where a thing should go ("the teapot should go by the window"; not "which one should
    go first"): a request about an object the scene may lack, for the parser to refuse, never background."""
    return any(w in ("should", "must") and body[j + 1 : j + 2] and body[j + 1] in _GOING and (
        j < 2 or body[j - 2] in ("the", "a", "an", "my", "our", "your", "this", "that")) for j, w in enumerate(body))


_GOING = frozenset({"go", "be", "sit", "stand", "end", "move", "face", "point", "stay"})
#: Verbs that place an object ("put the teapot by the window").
_PLACING = frozenset({"put", "place", "move", "set", "stand", "lay", "bring", "stick", "pop"})


def moves_unknown(clause: Sequence[str], unknown: frozenset[str]) -> bool:
    """Whether ``clause`` asks to move an object the scene lacks (one of ``unknown``) to a place: "put the
    teapot by the window", "the teapot should go on the tray" (a verb of placing or "should go", "the" and the
    noun, then a preposition of place), never a heading ("set the props:") or an idiom ("leave the third where
    it is").

    >>> moves_unknown("put the teapot by the window".split(), frozenset({"teapot", "window"}))
    True
    >>> moves_unknown("set the props".split(), frozenset({"props"}))
    False
    """
    for k in range(1, len(clause) - 1):
        if clause[k - 1] == "the" and clause[k] in unknown and (
                (k >= 2 and clause[k - 2] in _PLACING) or wishes(clause[k + 1 : k + 3])):
            return any(w in _CTX["place_prepositions"] or w in lexicon.DIRECTIONS for w in clause[k + 1 :])
    return False


def _reported(body: Sequence[str]) -> bool:
    """Whether ``body`` reports what a person says or thinks ("my mum always said a proper table has the knife
    on the right", "our jamie reckons you can't do a ring"): a person's subject (or a name after "my" / "our"),
    a verb of the lexicon's ``reporting`` list after it (adverbs between), and no word by which it relays a wish
    ("my wife says the cans should go in a line" is kept).

    >>> _reported("my mum always said a proper table has the knife on the right of the plate".split())
    True
    >>> _reported("our jamie reckons you can't do a ring".split()), _reported("my wife says the cans should go left".split())
    (True, False)
    >>> _reported("the cans said to be red".split())
    False
    """
    words = [w for w in body if w not in _LEAD]
    k = _subject_end(words)
    if not k and len(words) > 3 and words[0] in _CTX["person_possessives"] and words[0] != "the":
        k = 2  # "our jamie reckons": a name after a possessive
    j = k
    while k and j < len(words) and words[j] in _CTX["reporting_adverbs"]:
        j += 1
    if not k or j >= len(words) - 1 or words[j] not in _CTX["reporting"]:
        return False
    return not any(w in _WISHING for w in words[j + 1 :])


def _open_end(lead: Sequence[str]) -> bool:
    """Whether ``lead`` stops where its own clause goes on: after a verb, a preposition or an article ("my
    daughter keeps knocking" goes on with its object), so the words after it are not a request of their own."""
    last = lead[-1]
    return (last in _TELLING or last in _PAST or last.endswith(("ing", "ed")) or last in ("the", "a", "an", "of")
            or last in _CTX["place_prepositions"] or last in _CHATTER_PARTICLES)


def _story_objects(body: Sequence[str], object_word: Callable[[str], bool]) -> tuple[str, ...]:
    """The one noun phrase of the objects a story names ("my granddaughter set these letters out": "these
    letters"), for a pronoun after it; nothing where it names none or more than one phrase."""
    said = [j for j, w in enumerate(body) if object_word(w) and not _article(body, j)]
    if not said:
        return ()
    start = said[0]
    while start and body[start - 1] in ("the", "these", "those", "all", "both", "my", "our"):
        start -= 1
    start = _phrase_start(tuple(body), start, object_word) if body[start] not in ("these", "those") else start
    if any(j != said[0] + n for n, j in enumerate(said)):
        return ()
    return tuple(body[start : said[-1] + 1])


def _in_place(part: Sequence[str], j: int) -> bool:
    """Whether the direction word at ``j`` takes part in a place ("to the left", "left of", "the left side"),
    not a verb ("the kids left them out")."""
    before = part[j - 1] if j else ""
    after = part[j + 1] if j + 1 < len(part) else ""
    return before in _CTX["place_before"] or after in _CTX["place_after"]


def _asks_nothing(part: Sequence[str], object_word: Callable[[str], bool],
                  request_word: Callable[[str], bool]) -> bool:
    """Whether ``part`` names no object and asks for no goal: a direction counts only in a place ("to the
    left", "left of"; "my daughter just left" is a verb), a verb or particle of chatter not at all
    ("coming over", "knocked everything over", "at seven")."""
    clock = _clock_words(part) | _time_spans(part)
    owned = _owned(part)
    timed = any(w in _CLOCK for w in part)  # "lunch is at one, it's almost noon": a meal said with a time
    for j, w in enumerate(part):
        if j in clock or (j in owned and not object_word(w)):
            continue
        if w in _SHIFT_KINDS and part[j + 1 : j + 2] and part[j + 1] in _SPANS:
            continue  # "it's been a long day", "a late night": a length of time, no size
        if w in _KEEP and part[j + 1 : j + 2] and part[j + 1].endswith("ing"):
            continue  # "i keep going back and forth": "keep" says it goes on, it keeps nothing in place
        if object_word(w) and w not in ("everything", "anything") and not _article(part, j):
            return False
        if w in lexicon.DIRECTIONS:
            if _in_place(part, j):
                return False
            continue
        if w in ("round", "around") and j and part[j - 1] in _COMING:
            continue  # "our lass is coming round for her tea": a visit, no circle
        if (w == "table" and not (j and part[j - 1] in ("the", "this"))) or (w in ("top", "tops") and j and (
                part[j - 1].isdigit() or part[j - 1] in _NUMBER_WORDS)):
            continue  # "table six, two-top, mains", "12-top coming in at eight": a party of guests, no place
        if part[j + 1 : j + 2] and part[j + 1] in _POSSESSIVES:
            continue  # "under my feet", "on her way": of a person, not of the table
        if request_word(w) and w not in _CHATTER_PARTICLES and not (w in _MEALS and (timed or meal_visited(part, j))):
            return False
    return True


#: Words of a request that chatter uses too ("coming over", "at like seven", "knocked everything over").
_CHATTER_PARTICLES = frozenset({"over", "on", "at", "in", "up", "off", "out", "down", "back", "get", "gets", "go", "around",
                                "goes", "everything", "anything", "first", "last", "next", "end"})
#: Verbs of a visit, after which "round" is a particle ("coming round", "popped round").
_COMING = frozenset({"come", "comes", "coming", "came", "pop", "pops", "popping", "popped", "drop", "dropping",
                     "dropped", "swing", "swinging", "bring", "bringing", "going", "go", "goes", "went"})
#: Words before "for dinner" that say someone comes to the meal: a verb of a visit or the place it goes to
#: ("guests are coming (over) for dinner", "she's staying for lunch").
_VISITING = _COMING | {"over", "round", "around", "here", "home", "staying", "stay", "stays", "joining", "join",
                       "joins", "out", "in"}


def meal_visited(words: Sequence[str], j: int) -> bool:
    """Whether the meal word at ``j`` is one someone comes to ("guests are coming for dinner"), so that it asks for
    no place setting."""
    return j > 1 and words[j - 1] == "for" and words[j - 2] in _VISITING


#: Words of a time of day or a day, by which chatter before a request is told apart ("it's almost noon and ...").
_DAY_WORDS = frozenset({"morning", "evening", "afternoon", "night", "tonight", "tomorrow", "today", "weekend",
                        "noon", "midnight", "lunchtime", "dinnertime"})
_OPENERS = tuple(sorted((tuple(p.split()) for p in _CTX["request_openers"]), key=len, reverse=True))
_CHATTER_CUTS = frozenset(_CTX["chatter_cuts"])
#: Words that join chatter to the request said after it in the same breath.
_JOINS = frozenset({"and", "so", "um", "uh", "umm", "uhh", "er", "erm"})
_LEAD = frozenset({"okay", "ok", "so", "um", "uh", "umm", "uhh", "er", "erm", "well", "and", "like", "yeah", ",", ":"})


def _without_chatter(sent: tuple[str, ...], object_word: Callable[[str], bool],
                     request_word: Callable[[str], bool]) -> tuple[str, ...]:
    """A sentence without the chatter said before its request in the same breath: what comes before a
    request opener ("... so um could you put"), a cut word ("..., whatever, um the letters should"), a
    colon ("before the inspector comes tomorrow: ...") or, for a time clause said without a comma, the
    first object ("by the time she's here the four letters should ..."), when it names no object and
    asks for nothing (:func:`_asks_nothing`), and what follows names an object or asks."""
    n = len(sent)
    for k in range(1, n):
        opener = next((o for o in _OPENERS if sent[k : k + len(o)] == o), None)
        cut = opener is not None or sent[k] in _CHATTER_CUTS or sent[k] == ":" or (
            sent[k] == "," and k + 1 < n and sent[k + 1] in ("just", "please", "now", "so")) or (
            sent[k] in (",", "and") and _told(sent[:k])) or (sent[k] == "but" and _conceded(sent[:k]))
        if not cut:
            continue
        head = [w for w in sent[:k] if w not in _LEAD]
        tail = sent[k:] if opener is not None else sent[k + 1 :]
        if opener is not None and (opener[-1] == "find" or opener[:3] == ("i", "should", "like")):
            tail = sent[k + len(opener) :]  # "i should like to find the two cups ...": the wish's frame goes too
        if head and (_asks_nothing(head, object_word, request_word) or (
                sent[k] == "," and _story(head, object_word, request_word)
                and not any(w in _PRONOUNS for w in tail))) and any(
                object_word(w) or request_word(w) for w in tail):
            while tail and tail[0] in _LEAD:
                tail = tail[1:]
            return _without_chatter(tuple(tail), object_word, request_word)  # "... and my mom said ... so can you"
        if any(object_word(w) for w in sent[:k]):
            break
    first = next((k for k, w in enumerate(sent) if object_word(w) and not _article(sent, k)), None)
    if first and "," not in sent[:first]:
        # "its almost noon and lunch is at one the cans all stacked up" (the wish's frame read before): chatter
        # about the time or the people of the house, then the request from its first object on; a story of
        # the people of the house runs on into it without a joining word ("my nephew made a mess again uh the
        # letters ...")
        start = _phrase_start(sent, first, object_word)
        lead_cut = [w for w in sent[:start] if w not in _LEAD]
        told = any(w in _DAY_WORDS or w in _CLOCK or w in _MEALS or w in _CTX["people"] for w in lead_cut)
        joined = any(w in _JOINS for w in sent[:start]) or (
            _story(lead_cut, object_word, request_word) and not _open_end(lead_cut)
            and any(request_word(w) for w in sent[start:]))
        if len(lead_cut) >= 3 and told and joined and _asks_nothing(lead_cut, object_word, request_word):
            return sent[start:]
    if sent and sent[0] in TIME_OPENERS:
        first = next((k for k, w in enumerate(sent) if object_word(w)), None)
        if first and "," not in sent[:first]:
            start = _phrase_start(sent, first, object_word)
            when = sent[:start]
            if len(when) > 1 and ((_time_clause(when) and _asks_nothing(when[1:], object_word, request_word))
                                  or _event_clause(when, object_word, request_word)):
                return sent[start:]  # "after my nap the cans lined up"
    return sent


#: Words by which the part before "but" is about the objects after all ("everything but the red can").
_GROUP_WORDS = frozenset({"everything", "anything", "all", "each", "every", "both", "any", "none", "nothing"})


def _conceded(head: Sequence[str]) -> bool:
    """Whether ``head``, said before "but", is a remark of its own ("honestly it looks fine", "i keep going back and
    forth on this"): a clause of at least three words with no word of a group, so that "everything but the red
    can" stays one reference. Whether it asks nothing is the caller's check."""
    body = [w for w in head if w not in _LEAD]
    return len(body) >= 3 and not any(w in _GROUP_WORDS for w in body)


_NUMBER_WORDS = frozenset({"two", "three", "four", "five", "six", "seven", "eight", "nine", "ten"})
#: Verbs by which a clause tells what happened or happens in the house ("the groceries finally came", "i just got
#: back from the store", "my daughter keeps knocking ..."), besides past forms in -ed.
_TELLING = frozenset({"came", "come", "comes", "got", "get", "gets", "went", "go", "goes", "is", "are", "was", "were",
                      "'s", "has", "have", "had", "keeps", "keep", "kept", "says", "said", "sits", "left", "leaves",
                      "made", "makes", "did", "does", "do", "took", "takes", "brought", "bought", "ate", "fell",
                      "broke", "spilled", "spilt", "knocked", "arrived", "played", "used", "love", "loves", "likes"})


_PRONOUNS = frozenset({"it", "them", "they", "those", "these", "one", "ones", "its", "their"})


def _story(body: Sequence[str], object_word: Callable[[str], bool], request_word: Callable[[str], bool]) -> bool:
    """Whether ``body`` tells what the people of the house do or did, naming objects only as part of the story
    ("my daughter keeps knocking the bottles over", "i used to play with blocks like these"): a person's
    subject, a verb of telling, no word by which it asks, no place, and no word of a goal but the objects'."""
    words = [w for w in body if w not in _LEAD]
    if not _subject_end(words) or not _told(words):
        return False
    past = next((j for j, w in enumerate(words) if w in _PAST or (w.endswith("ed") and len(w) > 4)), len(words))
    subject = _subject_end(words)
    wishing = any(w in _WISHING or w in _CTX["asking"] for w in words)
    for j, w in enumerate(words):
        if j == subject and subject >= 2 and words[subject - 1] in _CTX["people"]:
            past = min(past, j)
            continue  # "my granddaughter set these letters out": the verb of a person named, told, never asked
        if w == "left" and j and words[j - 1] in _LEAVERS:
            continue  # "my nephew left his stuff everywhere"
        if j > past and not wishing:
            continue  # "the previous operator left the star close to the front edge": what was done, told
        if (w in _CTX["asking"] and not object_word(w)) or (w in lexicon.DIRECTIONS and _in_place(words, j)):
            return False
        if j > past and w in _ARRANGEMENT_NOUNS:
            continue  # "my daughter built a tower earlier and knocked it over": what was done, not asked for
        if request_word(w) and not object_word(w) and w not in _CHATTER_PARTICLES:
            return False
    return True


#: Past forms of the verbs a story tells with, besides those in -ed ("my daughter built a tower").
_PAST = frozenset({"built", "made", "came", "went", "got", "took", "brought", "broke", "fell", "did", "had", "left",
                   "knocked", "played"})
#: The nouns of the arrangements (:data:`.lexicon.SHAPE_NOUNS`).
_ARRANGEMENT_NOUNS = lexicon.ARRANGEMENT_NOUNS


def _told(head: Sequence[str]) -> bool:
    """Whether ``head`` tells something rather than names things: a subject and a verb of telling in at least
    four words ("the groceries finally came"), not a list of objects ("the saucer and the red can")."""
    body = [w for w in head if w not in _LEAD]
    subject = _subject_end(body)
    told = subject and not any(w in _WISHING or w in _CTX["asking"] for w in body)
    past = next((j for j, w in enumerate(body) if told and (w in _PAST or (w.endswith("ed") and len(w) > 4))),
                len(body))  # "the previous operator left the star close to the front edge": where it was
    if told and subject >= 2 and body[subject - 1] in _CTX["people"]:
        past = min(past, subject)  # "my son put the star on the left yesterday"
    if any(w in lexicon.DIRECTIONS and not (w == "back" and j and body[j - 1] in _BACK_FROM)
           and not (w == "left" and j and body[j - 1] in _LEAVERS) and j <= past for j, w in enumerate(body)):
        return False  # "the teapot is to be placed diagonally behind": where, not a story ("i just got back" is)
    if any(w in _WISHING or (w in _CTX["place_prepositions"] and j + 1 < len(body) and body[j + 1] in ("the", "a", "an"))
           for j, w in enumerate(body)):
        return False  # "the teapot should go on the tray": a request about an object the scene lacks
    return len(body) >= 4 and (any(w in _TELLING or (w.endswith("ed") and len(w) > 4) for w in body[1:]) or (
        subject >= 2 and body[subject - 1] in _CTX["people"]))  # "my granddaughter set these letters out"


#: Words after which "left" is the verb ("my nephew left his stuff out", "she just left").
_LEAVERS = frozenset(_CTX["people"]) | frozenset(_CTX["person_pronouns"]) | {"just", "already", "they", "you"}
_WISHING = frozenset({"should", "must", "need", "needs", "want", "wants", "would", "could", "please", "gotta",
                      "gonna", "has to", "have to", "let's"})
_BACK_FROM = frozenset({"got", "get", "gets", "came", "come", "comes", "went", "go", "be", "been", "am", "i'm", "is",
                        "was", "just", "bring", "brought"})


def _phrase_start(sent: tuple[str, ...], first: int, object_word: Callable[[str], bool]) -> int:
    """Where the noun phrase of the object word at ``first`` starts ("the four letters": at "the")."""
    start = first
    while start and (sent[start - 1] in ("the", "a", "an", "all", "both") or sent[start - 1].isdigit()
                     or sent[start - 1] in _NUMBER_WORDS or object_word(sent[start - 1])):
        start -= 1
    return start


def _without_time(sent: tuple[str, ...], object_word: Callable[[str], bool],
                  request_word: Callable[[str], bool]) -> tuple[str, ...]:
    """A sentence without its leading and trailing time clauses that ask for nothing."""
    while True:
        cut = next((k for k, w in enumerate(sent) if w == ","), None)
        if cut is None or cut == 0:
            break
        head = sent[:cut]
        if not ((_time_clause(head) and _idle(head[1:], object_word, request_word, timed=True))
                or _event_clause(head, object_word, request_word)):
            break
        sent = sent[cut + 1 :]
    end = len(sent)
    while end and sent[end - 1] in _ENDS:
        end -= 1
    for k in range(end - 1, 0, -1):
        if sent[k] in TIME_OPENERS and sent[k] not in ("in", "at", "as", "this", "first", "while"):
            tail = sent[k:end]
            before = sent[:k]
            if ((_time_clause(tail) and _idle(tail[1:], object_word, request_word, timed=True))
                    or _event_clause(tail, object_word, request_word)) and any(request_word(w) for w in before):
                while before and before[-1] == ",":
                    before = before[:-1]
                return before + sent[end:]
            break
    return sent




def _subject_end(body: Sequence[str]) -> int:
    """How many words of ``body`` make a subject that is a person or a pet ("i'm", "the kids", "my
    nephew's"), 0 for none."""
    if body and body[0] in _CTX["person_pronouns"]:
        return 1
    if len(body) > 1 and body[0] in _CTX["person_possessives"]:
        noun = body[1][:-2] if body[1].endswith("'s") else body[1]
        if noun in _CTX["people"]:
            return 2
        if len(body) > 2 and body[1] in _PERSON_ADJECTIVES and body[2] in _CTX["people"]:
            return 3  # "the previous operator", "the cleaning staff"
    return 0


#: Words said before a person's noun in a subject ("the previous operator", "the cleaning staff").
_PERSON_ADJECTIVES = frozenset({"previous", "last", "other", "new", "old", "night", "day", "cleaning", "morning",
                                "evening", "late", "early", "visiting", "lab", "test", "little", "eldest", "youngest"})


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
            if _in_place(rest, j):
                return False
            continue
        if request_word(w) and not command_verb(w):
            return False
    return bool(rest)
