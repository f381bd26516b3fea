"""A specification's register, said as the commands the parser reads.

A person writing a specification says each step in the passive, with a modal:
"The two mugs shall be placed in a line", "The phone shall be picked up. It is
then to be placed to the right of the blue bowl.", "It is required that the
four cans be arranged on a ring", "The cup is to be stacked on top of the mug,
which is itself to be placed on the plate". This stage reads such a step by the
kind of its words (every list is the lexicon's ``[formal]`` table) and says it
as the active command the parser reads, keeping every word that asks for
something:

* **a modal step**: a subject, a modal phrase (``modals``: "shall", "must",
  "is to", "are to" ...), "be" and a participle of ``verbs`` are the verb and
  its object: "the two mugs shall be placed in a line" is "place the two mugs
  in a line". Words that order the step (``kept``: "then") stay, before the
  verb; words that ask nothing (``fillers``: "in turn", "itself", "however")
  go; any other word between the modal and the participle leaves the step as
  said (so "the length is to be 10 in" and "is to be removed and disposed of"
  stay for the stages after);
* **a required step**: after a lead (``leads``: "it is required that"),
  "NP be VERBed" is the same step;
* **a relative step**: ", which is itself to be placed on the plate" after a
  reference is ", and place <that reference> on the plate";
* **a second participle**: "... shall be taken from its present position and
  placed behind the bowl" places the same object ("and place it behind ...");
* **a pick-up**: a step that only picks up ("shall be picked up", "taken from
  its present position") is "pick up NP", which the parser reads as naming the
  object for the pronoun after it ("It is then to be placed ...");
* **"the aforementioned N"** (``anaphors``) is "the N", and "the aforementioned two" said without a noun is
  "them"; "is located" (``states``: a participle that says only where a thing is) is "is";
* **a role said of "the former" or "the latter"** after a comma (``roles``, before a word of
  ``role_relations``) is given with "with": "X and Y shall be stacked, the former on top of the latter" is
  "..., with the former on top of the latter", as a role said after a stack's list is read.

A step's subject starts at its sentence, after any opener ("Accordingly, the
star shall be ...", "(a) The red block shall be ..."), or, after a step said
before it in the same sentence, after a joiner (", and the red block shall in
turn be placed on top of it"). A subject with a speaker's own words ("I think
the mug must be placed ...", ``not_subject``) is left as said.
"""

from __future__ import annotations

from collections.abc import Sequence

from . import lexicon
from .ir import Token
from .vocabulary import tokenize

__all__ = ["SPELLED", "active", "roles_with", "said_actively", "without_anaphors"]

_F = lexicon.FORMAL
_STOPS = frozenset({".", "!", "?", ";", ":"})
#: Participle phrases, longest first, and the verb each is said by.
_VERBS: dict[tuple[str, ...], str] = _F["verbs"]
_PARTICIPLES: tuple[tuple[str, ...], ...] = tuple(sorted(_VERBS, key=len, reverse=True))
_NOT_SUBJECT = frozenset(w for p in _F["not_subject"] for w in p)
_DETERMINERS = frozenset({"the", "a", "an", "this", "that", "these", "those", "its", "their"})
#: First words of a subject said in lower case after the verb ("The two mugs": place the two mugs).
_LOWER_FIRST = frozenset({"the", "a", "an", "all", "every", "each", "both", "those", "these", "it", "they", "any",
                          "one", "its", "their", "some"})
_PLURAL = frozenset({"and", "all", "both", "these", "those", "they", "them", "every"})
#: The words of a step the spelling stage corrects to ("shal be positoned": shall be positioned), and the word
#: that gives a list its sides in order ("respectivly").
SPELLED = frozenset(w for name in ("modals", "leads") for p in _F[name] for w in p if len(w) > 3) | frozenset(
    w for p in _VERBS for w in p if len(w) > 3) | {"respectively"}
#: The longest subject read (a longer run before a modal is not one reference).
_LONGEST = 40


def said_actively(text: str) -> str:
    """``text`` with "the aforementioned N" said as "the N", roles of "the former" given with "with" and each
    formal step said actively."""
    return active(roles_with(without_anaphors(text)))


def roles_with(text: str) -> str:
    """", the former on top of the latter" is ", with the former on top of the latter"."""
    toks = tokenize(text)
    words = [t.text for t in toks]
    edits = [(toks[i].start, toks[i].start, "with ") for i in range(1, len(words)) if words[i - 1] == ","
             and (end := _at(words, i, _F["roles"])) is not None and end < len(words)
             and (words[end],) in _F["role_relations"]]
    return _edited(text, edits)


def without_anaphors(text: str) -> str:
    """"the aforementioned bowl" is "the bowl": a word of ``anaphors`` after a determiner goes; "the aforementioned
    two" said without a noun is "them". "is located" (``states``) is "is"."""
    toks = tokenize(text)
    words = [t.text for t in toks]
    edits: list[tuple[int, int, str]] = []
    for i in range(1, len(words)):
        end = _at(words, i, _F["anaphors"])
        if end is None or words[i - 1] not in _DETERMINERS or end >= len(words) or not words[end].isalpha():
            if words[i - 1] in ("is", "are") and _at(words, i, _F["states"]) is not None:
                edits.append((toks[i - 1].end, toks[i].end, ""))
            continue
        if (words[end] in lexicon.NUMBERS or words[end] == "both") and (
                end + 1 == len(words) or not words[end + 1].isalpha()):
            edits.append((toks[i - 1].start, toks[end].end, "them"))
        else:
            edits.append((toks[i - 1].end, toks[end - 1].end, ""))
    return _edited(text, edits)


def active(text: str) -> str:
    """``text`` with each step said in a specification's passive said as the command it asks for (see the
    module's doc): "the phone shall be picked up" is "pick up the phone"."""
    toks = tokenize(text)
    words = [t.text for t in toks]
    edits: list[tuple[int, int, str]] = []
    start: int | None = 0
    joins: list[tuple[int, bool]] = []
    plural: bool | None = None  # the last step's object in this sentence: plural or not (None: no step yet)
    k = 0
    while k < len(words):
        if words[k] in _STOPS:
            start, joins, plural, k = k + 1, [], None, k + 1
            continue
        step = _lead_step(words, k) or _modal_step(words, k, start, joins)
        if step is not None:
            a, end, said, subject = step
            edits.append((toks[a].start, toks[end - 1].end, _command(text, toks, a, said, subject)))
            plural = _is_plural(words[subject[0] : subject[1]])
            start, joins, k = None, [], end
            continue
        if plural is not None and words[k] == "and":
            kept: list[str] = []
            second = _participle(words, k + 1, kept)
            if second is not None:
                end, said = second
                said = " ".join(["and", *kept, said, "them" if plural else "it"])
                edits.append((toks[k].start, toks[end - 1].end, said))
                k = end
                continue
        joiner = _at(words, k, _F["joiners"])
        if plural is not None and joiner is not None:
            joins.append((joiner, k > 0 and words[k - 1] == ","))
            k = joiner
            continue
        k += 1
    return _edited(text, edits)


#: A step found: the first token it replaces, the token after it, its verb (with any word kept before it) and
#: the token span of its object.
_Step = tuple[int, int, str, tuple[int, int]]


def _lead_step(words: Sequence[str], k: int) -> _Step | None:
    """"it is required that NP be VERBed ..." starting at ``k``."""
    lead = _said(words, k, _F["leads"], [])
    if lead is None:
        return None
    for j in range(lead, len(words)):
        if words[j] in _STOPS:
            return None
        if words[j] == "be":
            kept: list[str] = []
            got = _be_verb(words, j, kept)
            if got is None or not _subject_ok(words[lead:j]):
                return None
            return k, got[0], " ".join([*kept, got[1]]), (lead, j)
    return None


def _modal_step(words: Sequence[str], k: int, start: int | None, joins: Sequence[tuple[int, bool]]) -> _Step | None:
    """"NP shall be VERBed ..." with its modal at ``k``: its subject from ``start`` (or from a joiner after a
    step said before it), or ", which is to be VERBed" after a reference."""
    kept: list[str] = []
    modal = _said(words, k, _F["modals"], kept)
    got = None if modal is None else _be_verb(words, modal, kept)
    if got is None:
        return None
    end, verb = got
    said = " ".join([*kept, verb])
    if k >= 3 and words[k - 1] in ("which", "who") and words[k - 2] == ",":
        d = max((i for i in range(max(0, k - 8), k - 2) if words[i] in _DETERMINERS), default=None)
        if d is None or not all(w.isalpha() or w == "'s" for w in words[d : k - 2]):
            return None
        return k - 2, end, f", and {said}", (d, k - 2)
    if start is None:
        with_comma = [j for j, comma in joins if comma]
        start = with_comma[-1] if with_comma else joins[0][0] if joins else None
    if start is None:
        return None
    s = _subject_start(words, start, k)
    if not _subject_ok(words[s:k]):
        return None
    return s, end, said, (s, k)


def _subject_start(words: Sequence[str], s: int, k: int) -> int:
    """The first word of a subject said from ``s`` to ``k``, after the commas, openers, joiners and list marks
    before it ("And the red block shall ...")."""
    while s < k:
        opener = _at(words, s, _F["openers"]) or _at(words, s, _F["joiners"])
        if words[s] == ",":
            s += 1
        elif opener is not None:
            s = opener
        elif words[s] == "(" and s + 2 < k and words[s + 2] == ")":
            s += 3  # "(a) The red block shall be placed ..."
        else:
            break
    if s < k and (words[s],) in _F["intros"]:
        # "Before dinner, the table is to be set": after the phrase's last comma (none: no subject)
        return max((j + 1 for j in range(s, k) if words[j] == ","), default=k)
    return s


def _subject_ok(subject: Sequence[str]) -> bool:
    """Whether ``subject`` may be a step's object: not too long, no stop, no word of ``not_subject`` ("is" and
    "are" only after a relative word)."""
    relative = [k for k, w in enumerate(subject) if (w,) in _F["relatives"]]
    return 0 < len(subject) <= _LONGEST and not any(
        w in _STOPS or (w in _NOT_SUBJECT and not (w in ("is", "are") and relative and relative[0] < k))
        for k, w in enumerate(subject))


def _be_verb(words: Sequence[str], j: int, kept: list[str]) -> tuple[int, str] | None:
    """"be" and a participle at ``j`` (the words between them that ask nothing skipped): the token after the
    participle and its verb."""
    j = _skip(words, j, kept)
    if j >= len(words) or words[j] != "be":
        return None
    return _participle(words, j + 1, kept)


def _participle(words: Sequence[str], j: int, kept: list[str] | None = None) -> tuple[int, str] | None:
    """A participle of ``verbs`` at ``j`` (after words that ask nothing): the token after it and its verb."""
    j = _skip(words, j, kept if kept is not None else [])
    for phrase in _PARTICIPLES:
        if tuple(words[j : j + len(phrase)]) == phrase:
            return j + len(phrase), _VERBS[phrase]
    return None


def _skip(words: Sequence[str], j: int, kept: list[str]) -> int:
    """``j`` moved past commas, fillers and kept words (those collected in ``kept``)."""
    while j < len(words):
        filler = _at(words, j, _F["fillers"])
        order = _at(words, j, _F["kept"])
        if words[j] == ",":
            j += 1
        elif filler is not None:
            j = filler
        elif order is not None:
            kept.append(" ".join(words[j:order]))
            j = order
        else:
            break
    return j


def _said(words: Sequence[str], i: int, phrases: Sequence[tuple[str, ...]], kept: list[str]) -> int | None:
    """The token after the first of ``phrases`` said at ``i``, with commas and fillers allowed between its words
    ("it is, however, required that"), or None."""
    for phrase in phrases:
        j = i
        between: list[str] = []
        for n, w in enumerate(phrase):
            if n:
                j = _skip(words, j, between)
            if j >= len(words) or words[j] != w:
                break
            j += 1
        else:
            kept += between
            return j
    return None


def _at(words: Sequence[str], i: int, phrases: Sequence[tuple[str, ...]]) -> int | None:
    """The token after the first of ``phrases`` said at ``i`` word for word, or None."""
    for phrase in phrases:
        if tuple(words[i : i + len(phrase)]) == phrase:
            return i + len(phrase)
    return None


def _is_plural(subject: Sequence[str]) -> bool:
    if subject == ["it"]:
        return False
    last = [w for w in subject if w.isalpha()][-1:]
    return (any(w in _PLURAL or lexicon.NUMBERS.get(w, 0) > 1 for w in subject)
            or bool(last and last[0].endswith("s") and not last[0].endswith("ss")))


def _command(text: str, toks: Sequence[Token], a: int, said: str, subject: tuple[int, int]) -> str:
    """The active command of a step: its verb (capitalised where the step began a sentence in capitals) and its
    object as said."""
    s, e = subject
    obj = text[toks[s].start : toks[e - 1].end]
    letter = toks[s].text == "a" and (e == s + 1 or toks[s + 1].text in ("and", "or", ",", ")"))  # "A and T"
    if toks[s].text in _LOWER_FIRST and not letter:
        obj = obj[:1].lower() + obj[1:]
    lead = said.lstrip(", ")
    prefix = said[: len(said) - len(lead)]
    if text[toks[a].start : toks[a].start + 1].isupper():
        lead = lead[:1].upper() + lead[1:]
    return f"{prefix}{lead} {obj}"


def _edited(text: str, edits: Sequence[tuple[int, int, str]]) -> str:
    """``text`` with each ``(start, end, new)`` character span replaced (spans in order, none overlapping)."""
    out: list[str] = []
    at = 0
    for a, b, new in sorted(edits):
        out += [text[at:a], new]
        at = b
    return "".join(out + [text[at:]])
