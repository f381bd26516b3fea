"""A second reading without the backdrop sentence a refusal blames.

Stories told before (or after) a request take endless forms: "My grandson set you up this morning and swore
you could tidy.", "Back when I was breaking colts we'd work 'em in a round pen.", "That tiger pan was my late
wife's, won it at the county fair in '78." The context stage (:mod:`.context`) drops those it can tell from
their words; the rest reach the clause reader, which refuses them by quoting words that name nothing.

This stage reads such a refusal once more: when the words it quotes come from one sentence that tells rather
than asks, and another sentence asks, the command is read again without that sentence. A sentence tells when

* it starts with a person ("I", "we", "my grandson", "her neglect", "back when I was ..."), names one
  ("Mr. Okafor", "Little Bailey's coming over Sunday") or says what was ("was", "were", "used to"), and
* it has no word by which it would ask (:data:`_ASKING`: "please", "should", "could you", "I want" ...) and
  does not start with a command verb.

Where it names objects of the scene and a later sentence speaks of them by a pronoun ("... tiger pan was my
late wife's ... Set the heart behind it"), only those objects are kept, said as a sentence of their own
(the clause reader takes a later "it" or "the other one" from them). The second reading stands only if it
reads; otherwise the first refusal is the answer.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from . import lexicon
from .spelling import INFORMAL

__all__ = ["sentences", "without_backdrop"]

_CTX = lexicon.context_words()
#: Words by which a sentence asks (single words) or pairs of words ("could you").
_ASKING = frozenset({"please", "pls", "plz", "should", "must", "need", "needs", "want", "wants", "let's", "lets",
                     "gotta", "kindly", "shall", "ought", "mind", "like", "prefer"})
_ASKING_PAIRS = frozenset({("could", "you"), ("would", "you"), ("can", "you"), ("will", "you"), ("have", "to"),
                           ("has", "to"), ("reckon", "you"), ("can", "we"), ("could", "we"), ("i", "d")})
#: The words a telling sentence may start with.
_PERSON_START = frozenset(_CTX["person_pronouns"]) | {"you", "they", "back", "years", "ever", "last", "yesterday",
                                                      "when", "i've", "we've", "mama", "papa", "grandma", "grandpa"}
_POSSESSIVES = frozenset({"my", "our", "her", "his", "their", "your"})
_WAS = frozenset({"was", "were", "used", "had", "did"})
_LEAD = frozenset({"so", "well", "ok", "okay", "oh", "and", "now", "anyway", "honestly", "see", "look", "hey"})
_PRONOUNS = frozenset({"it", "them", "they", "its", "their", "other", "both", "em"})
#: Titles before a person's name.
_PEOPLE_TITLES = frozenset({"mr", "mrs", "ms", "dr", "prof", "miss"})
#: Words that open a correction ("No, ugh, the other one."), never a story.
_REPAIRS = frozenset({"no", "nope", "wait", "actually", "sorry", "oops", "scratch", "not", "nah", "hmm"})
#: Abbreviations whose full stop ends no sentence.
_TITLES = frozenset({"mr", "mrs", "ms", "dr", "st", "prof", "no", "approx", "e.g", "i.e", "vs"})


def sentences(text: str) -> list[str]:
    """``text`` cut after each ".", "!" or "?" that ends a sentence (not the stop of "Mrs." or of "3.5").

    >>> sentences("Mrs. Patel is here. Put the cups in a row! Thanks")
    ['Mrs. Patel is here.', ' Put the cups in a row!', ' Thanks']
    """
    out: list[str] = []
    start = 0
    for k, c in enumerate(text):
        if c not in ".!?" or (k + 1 < len(text) and not text[k + 1].isspace()):
            continue
        before = text[start:k].split()
        if c == "." and before and before[-1].lower().strip("'\"(") in _TITLES:
            continue
        out.append(text[start : k + 1])
        start = k + 1
    if text[start:].strip():
        out.append(text[start:])
    return out


def _asks(ws: Sequence[str], command_verb: Callable[[str], bool]) -> bool:
    """Whether the words ``ws`` of one sentence ask for something."""
    body = [w for w in ws if w not in _LEAD]
    if body and command_verb(body[0]):
        return True
    return any(w in _ASKING for w in ws) or any(p in _ASKING_PAIRS for p in zip(ws, ws[1:]))


def _tells(ws: Sequence[str], said: str, object_word: Callable[[str], bool]) -> bool:
    """Whether the words ``ws`` of one sentence (``said`` as written) tell of a person or of what was."""
    body = [w for w in ws if w not in _LEAD]
    if not body or body[0] in _REPAIRS:
        return False
    if body[0] in _PERSON_START or (body[0] in _POSSESSIVES and len(body) > 1 and not object_word(body[1])):
        return True
    return any(w in _WAS for w in body) or _named_person(said, object_word)


def _named_person(said: str, object_word: Callable[[str], bool]) -> bool:
    """Whether ``said`` names a person: a title ("Mr. Okafor") or a capitalised word after the first that is
    neither "I" nor a word of the scene ("Little Bailey's coming over")."""
    words = said.replace("'", " ").split()
    return any(w.strip(".,").lower() in _PEOPLE_TITLES for w in words[:1]) or any(
        w[:1].isupper() and len(w.strip(".,;:!?")) > 1 and not object_word(w.strip(".,;:!?").lower())
        for w in words[1:])


def _overlap(quoted: Sequence[str], ws: Sequence[str]) -> float:
    said = set(ws)
    return sum(w in said for w in quoted) / len(quoted) if quoted else 0.0


def _objects_said(ws: Sequence[str], object_word: Callable[[str], bool]) -> str:
    """The objects a telling sentence names, said as a list ("the tiger pan", "the star and the heart"), or ""."""
    out: list[list[str]] = []
    run: list[str] = []
    for w in ws:
        if object_word(w) and w not in ("a", "an", "i", "everything", "anything"):
            run.append(w)
            continue
        if run:
            out.append(run)
            run = []
    if run:
        out.append(run)
    return " and ".join("the " + " ".join(r) for r in out)


def without_backdrop(text: str, refusal: str, object_word: Callable[[str], bool],
                     command_verb: Callable[[str], bool]) -> str | None:
    """``text`` without the one telling sentence that the first words ``refusal`` quotes come from, or None
    where there is none (or no other sentence asks).

    >>> said = lambda w: w in ("pan", "heart", "tiger")
    >>> verb = lambda w: w in ("set", "put")
    >>> without_backdrop("That tiger pan was my late wife's, won it at the county fair. Set the heart behind it.",
    ...                  "'the county fair' names nothing in the scene", said, verb)
    ' the tiger pan. Set the heart behind it.'
    """
    if refusal.count("'") < 2:
        return None
    quoted = lexicon.words(refusal.split("'")[1])
    parts = sentences(text)
    if len(parts) < 2 or not quoted:
        return None
    said = [[INFORMAL.get(w, lexicon.DIALECT.get(w, w)) for w in lexicon.words(p)] for p in parts]
    best = max(range(len(parts)), key=lambda k: _overlap(quoted, said[k]))
    ws = said[best]
    if _overlap(quoted, ws) < 0.6 or _asks(ws, command_verb) or not _tells(ws, parts[best], object_word):
        return None
    if not any(_asks(said[k], command_verb) for k in range(len(parts)) if k != best):
        return None
    later = [w for k in range(best + 1, len(parts)) for w in said[k]]
    kept = _objects_said(ws, object_word) if any(w in _PRONOUNS for w in later) else ""
    return "".join(p if k != best else (" " + kept + "." if kept else "") for k, p in enumerate(parts))
