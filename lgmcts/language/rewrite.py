"""One spelling per meaning: phrasings rewritten, before tokenising, into the
forms the grammar of :mod:`.rules` reads.

Directions said with compass points, near and far, "diagonally" or a second
side given by "its"; corrections and repairs ("left of the plate, no wait,
right of the plate"); "the blue bottle's colour"; table places ("table
centre"); the reading orders of a stack ("from the top down"); reasons,
how-to remarks and step numbers that ask for nothing. Also the patterns that
tell a question about the scene from a request, and a clause that only
leaves a stack's order open. Nothing here knows the scene.
"""

from __future__ import annotations

import re

from . import compass, lexicon, said_words  # compass and said_words register replacers of the table
from .lexicon import HUES, MACROS, says
from .measures import find_measures
from .normalise import apply, replacer, step
from .stages import is_mark

__all__ = ["rewrite", "unframe", "plain_words", "QUESTION", "ASKS_TO_ACT", "FREE_ORDER"]

#: A clause that only leaves the order open ("any order is fine"): a stack in any order is a stack.
FREE_ORDER = re.compile(r"however you (like|want|please)|(in )?(any|whatever|random|an arbitrary|no particular|any old) "
                        r"order( you (like|want|choose))?( is (fine|ok|okay|good))?( works)?|"
                        r"(the )?order (of [a-z ]+ )?(does not|do not|doesn't|won't) matter|(the )?order is up to you|(i )?(do not|don't|do n't) (care|mind)( about)?( the| which)?"
                        r"( order)?|whichever( one)?( goes)? on top( is fine)?|(it )?(does not|doesn't) matter which "
                        r"(one )?goes on top|i am not fussy about the order|any old way|(any|either) (one|[a-z]+) "
                        r"(will|would) do|whichever (one )?you (like|want)|whichever order( you (like|want))?")


#: A question about the scene ("is the knife left of the plate?"), not a request.
QUESTION = re.compile(r"(?i)^\s*(is|are|was|were|does|do|did|which|what|what's|where|where's|why|who|whose|"
                      r"how many|how much|how's|how is|how are)\b.*\?\s*$")
#: Questions that ask for an action ("do you mind ...", "is it possible to ...").
ASKS_TO_ACT = re.compile(r"(?i)^\s*(is it possible|is it (ok|okay|alright|all right|fine) (to|for|if)|are you able|"
                         r"do you (mind|think you could)|is there any (chance|way)|what about|how about)\b")

_COMPASS = lexicon.COMPASS
#: A correction: "left of the plate, no wait, right of the plate" keeps the second.
_CORRECTION = re.compile(
    r"(?i)\b(?:(?:to the |on the |in |to its |to their |on its |on their )?(?:left|right|front|behind|back|on top|on|onto|"
    r"under|below|above|beneath)\b[^,;.!?]*?)"
    r"\s*,?\s*\b(?:(?:no,?\s+)?(?:wait|sorry|i mean|actually|make that|or rather|rather)|wait,? no|no(?=\s*,))\b\s*,?\s*")
#: Hesitation and repair words around a correction ("hmm, or no,", "or wait, no,", "? No wait,").
_HEDGE = r"(?:hmm+|hm+|um+|uh+|er|erm|oh|or|well|ah)"
_REPAIR_KEY = r"(?:no|wait|sorry|i mean|i meant|rather|scratch that|make that|hang on|oops)"
_REPAIR_RUN = re.compile(rf"(?i)\s*[,;.?!]\s*((?:(?:{_HEDGE}|{_REPAIR_KEY})\s*[,.!?]?\s*)+?)(?<=[,.!?])\s*(?=[a-z])"
                         r"(?!(?:swap|switch|exchange|reverse|flip|turn|was|is|yes|that)\b)")


def _repairs(text: str) -> str:
    """Every spoken repair marker, with its hesitations, as ", no wait, "."""
    def one(m: re.Match) -> str:
        said = " ".join(lexicon.words(m.group(1)))
        if not re.search(rf"\b{_REPAIR_KEY}\b", said) or not re.fullmatch(
                rf"(?:(?:{_HEDGE}|{_REPAIR_KEY})\s*)+", said) or said in ("no", "well", "oh", "or"):
            return m.group(0)
        return ", no wait, "
    return _REPAIR_RUN.sub(one, text)


_REL_START = re.compile(r"(?i)(?:to the |on the |to its |on its |to their |the )?(?:left|right|front|back|behind|in front)\b")


_REMAKE = re.compile(r"(?i)\s*[,.!?;]\s*(?:(?:hmm+|um+|uh+|oh|no|wait|sorry|actually|or|instead)[,!.]?\s+)*"
                     r"(?:actually|no|wait|sorry|instead)[,!.]?\s+(?:um+,?\s+|uh+,?\s+)*make (?:it|that|them|the (?:stack|tower|"
                     r"order)) (?:into )?(.+?)(?:\s+instead)?\s*(?=[.!?;]|$)")
_SHAPE_PHRASE = re.compile(rf"(?i)\b(?:a|an|one) (?:[a-z]+ )?({MACROS['SHAPE']})\b")
_HUE_LIST = re.compile(rf"(?i)\b{MACROS['HUE']}(?:\s*(?:,|,? and|,? then)\s*{MACROS['HUE']}){{1,7}}\b")


def _remade(text: str) -> str:
    """"... in a line. Actually, make it a circle": the circle replaces the line;
    "bottom to top: red, blue, green? Hmm, actually make it green, blue, red": the
    second order replaces the first."""
    m = _REMAKE.search(text)
    if m is None:
        return text
    new, before, after = m.group(1), text[: m.start()], text[m.end():]
    shape = _SHAPE_PHRASE.fullmatch(new)
    olds = list(_SHAPE_PHRASE.finditer(before))
    if shape is not None and olds:
        o = olds[-1]
        return before[: o.start()] + new + before[o.end():] + after
    hues = list(_HUE_LIST.finditer(before))
    if _HUE_LIST.fullmatch(new) and hues:
        o = hues[-1]
        return before[: o.start()] + new + before[o.end():] + after
    return text


_ACT = (r"(?:please |just |now |then |for now |first |kindly )*(?:put|place|move|stack|set|make|arrange|line|build|pile|lay|"
        r"could|can|would|will|get|grab|stick|pop|slide|shift|form|gather|group|bring|leave|keep|have|let|i'd|i want|i need)\b")
_CONTEXT = lexicon.context_words()
#: People a purpose may be about ("so the players can grab them").
_PEOPLE = tuple(_CONTEXT["people"])
_PURPOSE_AFTER = re.compile(r"(?i)\s*,?\s*\b(?:so that|so|in order that|because|since) "
                            r"(?P<c>(?:i|we|you|my|our|he|she|the kids|the children|the " + lexicon.alternation(_PEOPLE) + r"|people|everyone|nobody|no one|"
                            r"it's|it is|it'll|it doesn't|it does not|it won't|it will|it can|they're|they are|they'll|"
                            r"they don't|they do not|they can|they could|they won't|they take|it takes|there's|there is|everything's|"
                            r"everything is|everything will|nothing|the (?:[a-z]+ ){1,2}?(?:is|are|isn't|aren't|won't|doesn't|"
                            r"don't|will|stays|stay|gets|get))\b[^.;!?,]*"
                            # up to a comma before a part that says where, which way or how big
                            r"(?:,(?!\s*(?:in|at|on|along|near|toward|towards|facing|pointing|turned|oriented|"
                            r"over on|up at|halfway|dead|by|next|beside|around|inside|under|about|spanning|\d)\b)"
                            r"[^.;!?,]*)*)")
_PURPOSE_BEFORE = re.compile(rf"(?i)(^|[.;!?:]\s+)(?P<c>(?:(?:and\s+)?(?:so that|so|in order to|to|in order that|because|"
                             rf"since|given that|in preparation for|prior to|subsequent to|following|in view of|owing to|"
                             rf"due to|as part of|pending)\s+[^,;.!?]+,\s*)+)(?={_ACT})")
_REASON_BEFORE = re.compile(rf"(?i)(^|[.;!?]\s+)(?P<c>(?:i need|we need|i want|i have to|i must|i'd like|i'm|i am|i'll|i will|we're|we are|i've|we've|i have|we have|"
                            rf"it's|there's|the [a-z]+ (?:is|are)) [^,;.!?]+),\s*so\s+(?={_ACT})")


#: A heading before the request: "Round two!", "Step one:", "Your double mission:", "Heads up:".
_HEADING = re.compile(
    r"(?i)(^|[.;!?]\s+)(?:(?:alright|okay|ok|right|psst|now),?\s+(?:[a-z]+,\s+)?)?(?:(?:round|level|stage|step|part|phase) "
    r"(?:[a-z]+|\d+)|(?:final|bonus|secret|last|next|lightning|speed|warm[- ]up|first|second|third|practice|double|"
    r"triple|big) (?:round|challenge|mission|task|level|step|stage)|grand finale|finale|next up|"
    r"(?:your|the|today's|this|a|our) (?:[a-z]+ )?(?:mission|task|challenge|riddle|puzzle|quest)|here's a riddle|"
    r"riddle me this|heads up|come on(?:,? come on)?|no pressure|ready|attention|listen up)\s*[!:]+\s*")


#: Words of a sentence that only confirms or hedges ("I think behind, yeah", "Both of them, I think").
_HEDGES = frozenset("""i think guess suppose yeah yes yep yup like mean sort kind of maybe perhaps that that's is it please ok
okay so just um uh hmm oh well sure correct exactly both them all those these ones the a an in on at to would be there
probably i'm pretty really""".split())
#: Words that mean the same arrangement as another ("row" restates "line").
_SAME_WORD = {"row": "line", "lined": "line", "file": "line", "ring": "circle", "loop": "circle", "square": "rectangle",
              "stack": "tower", "pile": "tower", "stacked": "tower", "piled": "tower", "big": "large", "huge": "large",
              "little": "small", "tiny": "small"}


def _restatements(text: str) -> str:
    """A sentence after the request that only confirms or restates it ("I think
    behind, yeah.", "Like in a row, I mean.", "Both of them, I think.") asks
    for nothing new: every word it has besides hedges was said before."""
    parts = re.split(r"(?<=[.!?])\s+", text.strip())
    if len(parts) < 2:
        return text
    kept = [parts[0]]
    for p in parts[1:]:
        said = {_SAME_WORD.get(w, w) for w in re.findall(r"[a-z]+", " ".join(kept).lower())}
        words = re.findall(r"[a-z']+", p.lower())
        rest = [w for w in words if w not in _HEDGES]
        if words and len(words) <= 8 and says(p, "hedge") \
                and all(_SAME_WORD.get(w, w) in said for w in rest):
            continue
        kept.append(p)
    return " ".join(kept)


def _asks(clause: str) -> bool:
    """Whether a clause said as a reason has a word by which it would ask for a goal, "left" after a verb of
    having or a subject not counted ("the cleaning staff have left the items scattered")."""
    ws = lexicon.words(clause)
    kept = [w for k, w in enumerate(ws) if not (w == "left" and k and ws[k - 1] in _LEFT_AS_VERB)]
    return says(" ".join(kept), "goal")


#: Words after which "left" is a verb ("have left", "she left", "staff left").
_LEFT_AS_VERB = frozenset({"have", "has", "had", "having", "was", "were", "been", "just", "they", "we", "i", "he",
                           "she", "you", "staff", "someone", "somebody", "everyone", "kids", "operator", "cleaner"})


def _perceived(clause: str) -> bool:
    """Whether a purpose clause is what someone will see or learn ("they can see that they match", "the kids can
    tell which one is bigger"): a perception with its own clause, which asks for nothing whatever words it has."""
    ws = lexicon.words(clause)
    k = next((j for j, w in enumerate(ws) if w in ("can", "could", "will", "may", "might")), None)
    return k is not None and ws[k + 1 : k + 2] in (["see"], ["tell"], ["notice"], ["learn"], ["check"], ["spot"]) \
        and ws[k + 2 : k + 3] in (["that"], ["how"], ["which"], ["what"], ["whether"], ["if"])


#: Verbs by which a purpose would still place something ("so the kids can put the cups behind it" is no reason).
_PLACING = frozenset({"put", "place", "move", "stack", "set", "make", "arrange", "line", "build", "pile", "lay", "stand",
                      "go", "sit", "face", "point", "end", "form", "be", "fit", "stay", "turn", "rotate"})
#: Speakers and people a purpose may name by a pronoun ("so she can find them in the morning").
_PERSONS = frozenset(_CONTEXT["person_pronouns"]) | {"you", "they"}


def _people_can(clause: str) -> bool:
    """Whether a purpose clause says what people will be able to do ("the players can grab them on the way
    past", "the kids could reach them"): its subject is people and its verb places nothing."""
    ws = lexicon.words(clause)
    k = 1 if ws[:1] == ["the"] else 0
    if len(ws) < k + 3:
        return False
    subject, modal, verb = ws[k : k + 3]
    people = subject in _PEOPLE or (k == 0 and subject in _PERSONS)
    return people and modal in ("can", "could", "will", "may", "might") and verb not in _PLACING


def _purposes(text: str) -> str:
    """The reasons people give with a request, which ask for nothing: "... so I
    can read the labels", "so the T is hidden from the camera", "to get the
    drinks ready, put ...", "I'm going to sort the shopping later, so ...".
    Only a clause with no word that could ask for a goal is dropped ("so that
    the blue mug ends up on its left" is a goal)."""
    text = _PURPOSE_AFTER.sub(lambda m: m.group(0) if says(m.group("c"), "goal") and not _perceived(m.group("c"))
                              and not _people_can(m.group("c")) else "", text)
    text = _PURPOSE_BEFORE.sub(lambda m: m.group(0) if _asks(m.group("c")) else m.group(1), text)
    # Kept where the request after it says "them" / "it": its subject may be what they mean ("the cans are
    # everywhere, so put them in a row").
    return _REASON_BEFORE.sub(
        lambda m: m.group(0) if says(m.group("c"), "goal") or says(
            re.split(r"[.;!?]", m.string[m.end():])[0], "pronoun") else m.group(1),
        text)


def _corrected(text: str, relations_only: bool = False) -> str:
    """A corrected relation: "left of the plate, no wait, right of the plate"
    keeps the second; "right of the cup, no wait, left of it": "it" is the cup.
    ``relations_only``: only where the correction is itself a relation."""
    pos = 0
    while True:
        m = _CORRECTION.search(text, pos)
        if m is None:
            return text
        dropped, rest = m.group(0), text[m.end():]
        if not rest.strip(" ,.;!?"):
            # "..., back right actually" at the end: the place said is the correction, nothing follows it
            pos = m.end()
            continue
        if relations_only and not _REL_START.match(rest):
            pos = m.end()
            continue
        np = re.search(r"(?i)\b(?:of|behind|on|onto|under|below|above|beneath) ((?:the|a) [a-z ]+?)\s*(?:,|$)", dropped)
        if np is not None:
            rest = re.sub(r"(?i)^((?:to the |on the |to its |on its )?(?:left|right|front|back)(?: side)? of|behind|"
                          r"in front of|on top of|on|onto|under|below|above|beneath) (?:it|them)\b",
                          lambda k: f"{k.group(1)} {np.group(1)}", rest)
        if dropped[:7].lower() in ("to the ", "on the ") and re.match(r"(?i)the (?:left|right|front|back)\b", rest):
            rest = dropped.split()[0] + " " + rest
        text = text[: m.start()] + rest


_WISH = re.compile(r"(?i)\bit(?:'d| would) be (?:really |so |very |just )?(?:great|nice|lovely|good|helpful|awesome|ideal|"
                   r"perfect|wonderful|brilliant|cool|fantastic|super)(?: (if|to have|to see|to get))?\s+")
_WISHED_VERB = re.compile(r"(?i)\s+\b(?:were|was|stood|sat|could be|would be|could go|went)\b")


@step("wish")
def _wish(text: str) -> str:
    """"It would be great if the cans were in a row": the state wished for, "the cans in a row"."""
    m = _WISH.search(text)
    if m is None:
        return text
    rest = text[m.end():]
    if m.group(1) == "if":
        rest = _WISHED_VERB.sub("", rest, count=1)
    return text[: m.start()] + rest


def unframe(text: str) -> str:
    """The request without the words that frame it as an end state or open it in speech: the rows of the
    ``[[frame]]`` table of ``data/rewrites.toml``, in order."""
    return apply(text, "frame")


def plain_words(text: str) -> str:
    """A trade's own words for the table's sides and parts said plainly ("frame left" is left, "the
    foreground" the front): the rows of the ``[[plain]]`` table of ``data/rewrites.toml``, in order."""
    return apply(text, "plain")


#: Verb stems of "-ing" forms and their base forms.
_BASE = {"put": "put", "plac": "place", "stack": "stack", "pil": "pile", "arrang": "arrange", "lin": "line",
         "mov": "move", "sett": "set", "lay": "lay", "build": "build", "form": "form", "position": "position",
         "align": "align", "group": "group", "mak": "make", "gett": "get", "bring": "bring", "shift": "shift",
         "slid": "slide", "organis": "organise", "organiz": "organize", "gather": "gather", "sort": "sort"}


#: Words after which "can" is the object ("the white can go ...", "one can goes ...").
_NOUN_BEFORE = frozenset("the a an this that each every one any silver golden other".split()) | HUES

#: Words that speak of heights, which make a "column" a stack.
_HEIGHTS = re.compile(r"(?i)\b(?:tall|taller|topmost|bottommost|stack(?:ed|ing)?|pil(?:e|ed|ing)|on top|"
                      r"at the (?:top|bottom|base)(?! left| right| cent| middle| of the table| edge| side| corner| end| half)|"
                      r"on the bottom|as the base|(?:bottom|top) to (?:top|bottom)|under(?:neath)?|beneath|above|below|"
                      r"highest|lowest|high|vertical)\b")

#: Words by which a part after "yeah" / "like" says where, which way or how big ("..., yeah at the front").
_PLACE_SAID = frozenset({"front", "back", "rear", "corner", "edge", "middle", "centre", "center", "facing", "pointing",
                         "near", "far", "small", "large", "big", "little", "tiny", "cm", "mm", "north", "south",
                         "east", "west"})


def _like_restated(m: re.Match) -> str:
    """Drop ", like ..." where the words before it already ask for an arrangement;
    else keep what it says ("the cups, like round in a circle")."""
    before = set(lexicon.words(m.group(1)))
    said = lexicon.words(m.group(2))
    # ", yeah at the front of the table": a "yeah" that goes on to add a place (a "like ..." restates)
    # ", like a strip along the front": a "like ..." that adds a place (or a "yeah" that goes on to add one)
    new = [w for w in said if w in _PLACE_SAID and w not in before] if said[:1] in (
        ["yeah"], ["yes"], ["yep"]) or "strip" in said or "band" in said else []
    # ", like half a metre long": a measure said loosely is kept (a marked measure never disappears)
    new += [w for w in said if is_mark(w)]
    if says(m.group(1), "asks") and not new:
        return m.group(1)
    return m.group(1) + re.sub(r"(?i),\s*(?:so |and )?(?:like|yeah|you know|i mean|basically)\b", ",", m.group(2))


_SHAPE_NOUN = re.compile(rf"(?i)\b(a|an|one|the) ({MACROS['SHAPE']})\b")
_SIZE_SAID = ((re.compile(r"(?i),?\s*\b(?:nice and|good and|really|nice|small and|tight and)? ?(?:wide|spread out|roomy|"
                          r"spacious)\b(?! of)"), "large"),
              (re.compile(r"(?i),?\s*\b(?:nice and|small and|good and|really) (?:tight|compact|close together|snug)\b"),
               "small"))


#: A size said on its own after the arrangement: ", a big one", ", medium size", a bare ", small" that ends the
#: clause, "(a rectangle) of medium size".
_SIZE_AFTER = re.compile(r"(?i)(?:,\s*(?:(?:a|an) (small|little|tiny|medium|medium-sized|mid-sized|large|big|huge) one|"
                         r"(small|medium|large|big)[- ]?(?:size|sized)|(small|medium|large|big))|"
                         r"\s+of (?:a )?(small|medium|large|big) size)\b(?=\s*(?:[,;.!?]|$))")
_SIZE_NAMES = {"little": "small", "tiny": "small", "medium-sized": "medium", "mid-sized": "medium", "big": "large",
               "huge": "large"}
_BARE_SHAPE = re.compile(rf"(?i)\b()({MACROS['SHAPE']})\b")


def _size_words(text: str) -> str:
    """"a rectangle ..., nice and wide": "a large rectangle ..."; "cutlery row ..., medium size":
    "cutlery medium row ..." (only where one arrangement is named by its noun for the size to go with)."""
    shapes = list(_SHAPE_NOUN.finditer(text))
    after = _SIZE_AFTER.search(text)
    if after is not None and not shapes:
        shapes = list(_BARE_SHAPE.finditer(text))
    if len(shapes) != 1:
        return text
    a = shapes[0]
    if after is not None and after.start() >= a.end() and not says(
            text[a.end() : after.end()], "repair"):
        size = next(g for g in after.groups() if g).lower()
        text = text[: after.start()] + text[after.end():]
        return text[: a.start()] + (f"{a.group(1)} " if a.group(1) else "") + \
            f"{_SIZE_NAMES.get(size, size)} {a.group(2)}" + text[a.end():]
    for said, size in _SIZE_SAID:
        m = said.search(text)
        if m is not None and m.start() >= a.end():
            text = text[: m.start()] + text[m.end():]
            art = "a" if a.group(1).lower() in ("an", "one") else a.group(1)
            return text[: a.start()] + f"{art} {size} {a.group(2)}" + text[a.end():]
    return text


def rewrite(text: str) -> str:
    """Phrasings with one reading written the way the grammar reads them: every row of
    ``data/rewrites.toml`` in order (:mod:`.normalise`). Directions
    (:func:`_relation_words`), "the blue bottle's colour" -> "the same colour as
    the blue bottle", "table centre" -> "the centre of the table", the reading
    orders of a stack ("from the top down") and many more; each row says why."""
    return apply(text)


@replacer("compass-relation")
def _compass_relation(m: re.Match[str]) -> str:
    """"west of" -> "to the left of", "south-east of" -> "front right of"."""
    a, b = _COMPASS[m.group(1).lower()], m.group(2)
    if b is None:
        return {"back": "behind", "front": "in front of", "right": "to the right of", "left": "to the left of"}[a]
    return f"{a} {_COMPASS[b.lower()]} of"


@replacer("more-far-most-near")
def _more_far_most_near(m: re.Match[str]) -> str:
    """"more far" -> "farther", "most near" -> "nearest", "more close" -> "closer"."""
    more, word = m.group(1).lower(), m.group(2).lower()
    stem = {"far": "farth", "near": "near", "close": "clos"}[word]
    return stem + ("er" if more == "more" else "est")


@replacer("measure-in-width")
def _measure_in_width(m: re.Match[str]) -> str:
    """"40 cm in width" -> "40 cm wide", "in length" -> "long", "in diameter" -> "across", "in radius" -> "radius"."""
    word = {"width": "wide", "length": "long", "diameter": "across", "radius": "radius"}[m.group(2).lower()]
    return f"{m.group(1)} {word}"


@replacer("and-its-side")
def _and_its_side(m: re.Match[str]) -> str:
    """"behind the cup and to its right" -> "back right of the cup"; a contradiction is kept as said."""
    rel, anchor = m.group(1).lower(), m.group(2)
    s2 = next(g for g in m.groups()[2:] if g).lower()
    s2 = {"behind": "back", "in front of": "front"}.get(s2, s2)
    first = {"in front of": "front", "behind": "back"}.get(rel, rel.replace("to the ", "").replace(" of", ""))
    if {first, s2} in ({"left", "right"}, {"front", "back"}) or first == s2 or (
            first in ("front", "back") and s2 in ("front", "back")):
        return m.group(0)  # "left of it and also right of it": a contradiction, read (and refused) as said
    return f"{first} {s2} of {anchor}"


def _noun_after(m: re.Match) -> str:
    noun = m.group(2)[:-1] if m.group(2).lower().endswith("s") else m.group(2)
    return re.sub(r"(?i)\bone\b", noun, m.group(1)) + ","


def _has_rel(m: re.Match) -> str:
    rel = m.group(3).lower()
    rel = {"on its left": "to the left of", "on its right": "to the right of", "to its left": "to the left of",
           "to its right": "to the right of", "behind it": "behind", "in front of it": "in front of",
           "on top of it": "on top of", "on it": "on", "under it": "under", "below it": "below"}[rel]
    return f"{m.group(2)} {rel} {m.group(1)}"


# ------------------------------------------------------------------ named steps and replacers of the table
# Each is used by one row of data/rewrites.toml (``step = "..."`` or ``fn = "..."``), whose id it carries.

step("restatements")(_restatements)
step("purposes")(_purposes)
step("remade")(_remade)
step("repairs")(_repairs)
step("corrected")(_corrected)
step("size-words")(_size_words)


@step("corrected-relations")
def _corrected_relations(text: str) -> str:
    return _corrected(text, relations_only=True)


_NOT_THE = re.compile(r"(?i)(?:not|no) (the [a-z ]+?)(?=,|$)")


@replacer("not-these-just-the-rest")
def _not_these_just_the_rest(m: re.Match[str]) -> str:
    """"not the cans, not the bowls, just the rest": everything but them."""
    more = _NOT_THE.findall(m.group(2) + ",")
    return "everything except " + " and ".join([m.group(1), *more])


@step("strip")
def _strip(text: str) -> str:
    return text.strip()


@replacer("from-base-bottom-top")
def _from_base_bottom_top(m: re.Match[str]) -> str:
    return f"{m.group(2)} {('on top' if m.group(1).lower() == 'top' else 'at the bottom')}"


@replacer("from-red-green-blue")
def _from_red_green_blue(m: re.Match[str]) -> str:
    role = {"bottom": "at the bottom", "middle": "in the middle", "top": "on top"}[m.group(2).lower()]
    return f"{m.group(1)} {role}"


@replacer("middle-centre-center-table")
def _middle_centre_center_table(k: re.Match[str]) -> str:
    return 'at the ' + {'near': 'front', 'far': 'back'}.get(k.group(1).lower(), k.group(1)) + ' of the table'


@replacer("right-purple-block-further")
def _right_purple_block_further(m: re.Match[str]) -> str:
    return m.group(1) + (' and behind it' if m.group(2).lower() in ('back', 'away') else ' and in front of it')


@replacer("linear-formation-circular-arrangement")
def _linear_formation_circular_arrangement(k: re.Match[str]) -> str:
    return {'linear': 'a line', 'circular': 'a circle', 'rectangular': 'a rectangle'}[k.group(1).lower()]


@replacer("bottles-side-by-side")
def _bottles_side_by_side(m: re.Match[str]) -> str:
    return f'{m.group(1)} and {m.group(4)} {m.group(2)}{m.group(3)}'


@replacer("object-taken-back")
def _object_taken_back(m: re.Match[str]) -> str:
    """"the red mug, no wait, the blue one": the object said second, with the noun of the first ("the blue mug")."""
    return f"{m.group('said')} {m.group('head')}" if m.group("said") else ""


@replacer("mean-meaning-namely-red")
def _mean_meaning_namely_red(k: re.Match[str]) -> str:
    return f'the {k.group(2)} {k.group(1)}'


@replacer("any-other-column-line")
def _any_other_column_line(m: re.Match[str]) -> str:
    return 'tower' if _HEIGHTS.search(m.string) else 'line'


@replacer("red-block-above-after")
def _red_block_above_after(m: re.Match[str]) -> str:
    return 'on top of it' if m.group(1).lower() in ('above', 'over') else f'{m.group(1)} it'


@replacer("mug-top-other-two")
def _mug_top_other_two(m: re.Match[str]) -> str:
    return f'the {m.group(1)}s on top of each other'


@replacer("next-box-left-left")
def _next_box_left_left(m: re.Match[str]) -> str:
    side = m.group(2) or m.group(3)  # "on its left", or "left side" said bare
    return {'far': 'behind ', 'near': 'in front of '}.get(side.lower(), f'to the {side} of ') + m.group(1)


_THIRDS = {"top": "at the back", "upper": "at the back", "back": "at the back", "far": "at the back",
           "rear": "at the back", "bottom": "at the front", "lower": "at the front", "front": "at the front",
           "near": "at the front", "left": "on the left", "right": "on the right", "left-hand": "on the left",
           "right-hand": "on the right"}


@replacer("quarter-turn")
def _quarter_turn(m: re.Match[str]) -> str:
    return {"quarter": "90 degrees", "half": "180 degrees"}.get((m.group(1) or "").lower(), "270 degrees")


@replacer("the-far-one")
def _the_far_one(m: re.Match[str]) -> str:
    return f"the {'farther' if m.group(1).lower() == 'far' else 'nearer'} {m.group(2)}"


@replacer("thirds-of-frame")
def _thirds_of_frame(m: re.Match[str]) -> str:
    return _THIRDS[m.group(1).lower()]


@replacer("learners-english-you-putting")
def _learners_english_you_putting(m: re.Match[str]) -> str:
    return _BASE.get(m.group(1).lower(), m.group(1))


@replacer("would-you-mind-laying")
def _would_you_mind_laying(m: re.Match[str]) -> str:
    return f'{m.group(1)} {_BASE.get(m.group(2).lower(), m.group(2))}'


@replacer("order-from-bottom-list")
def _order_from_bottom_list(m: re.Match[str]) -> str:
    return ', from bottom to top' if m.group(1).lower() == 'bottom' else ', from top to bottom'


@replacer("red-bowl-down-white")
def _red_bowl_down_white(m: re.Match[str]) -> str:
    """"red bowl down, white bowl up, blue bowl between": a role said by one word, after an object said by its colour."""
    said = m.group(2)
    ws = lexicon.words(said)
    if ((said[:1].isalpha() and ws[:1] in (["hold"], ["turn"], ["fill"], ["heap"]))
            or any(w.isascii() and w.isalpha() and ((len(w) >= 5 and w.endswith("ed")) or (len(w) >= 6 and w.endswith("ing")))
                   for w in ws)
            or says(said, "request")
            or not any(w in HUES or w in ("silver", "one") for w in ws)):
        return m.group(0)
    return m.group(1) + said + {"down": " at the bottom", "up": " on the top", "between": " in between"}[m.group(3).lower()]


@replacer("can-go-sit-stay")
def _can_go_sit_stay(m: re.Match[str]) -> str:
    return m.group(0) if (m.group(1) or '').strip().lower() in _NOUN_BEFORE else f"{m.group(1) or ''}could {m.group(2)}"


@replacer("drop-cup-into-bowl")
def _drop_cup_into_bowl(m: re.Match[str]) -> str:
    return (m.group(1) + ' ' if m.group(1) else '') + 'on '


@replacer("blocks-too-but-separately")
def _blocks_too_but_separately(m: re.Match[str]) -> str:
    """", and the blocks too": the same again for them; but where "and" ends a list ("line up the mug, the cup
    and the bottle as well") the last item is one of that list (it was split off as a line of its own)."""
    last = lexicon.words(m.group(1).split(",")[-1])
    if "," in m.group(1) and last[:1] == ["the"] and len(last) <= 4 and "separately" not in m.group(0).lower():
        return f"{m.group(1)} and {m.group(2)}"
    return f'{m.group(1)}. the same for {m.group(2)}' if says(m.group(1), "asks") else m.group(0)


replacer("ones-noun-said-after")(_noun_after)


replacer("like-right-top-restatement")(_like_restated)


replacer("has-have-should-directly")(_has_rel)


@replacer("green-bowl-top-blue")
def _green_bowl_top_blue(m: re.Match[str]) -> str:
    """A support relation after ", with" inside a sentence that speaks of a stack stays part of the stack."""
    if m.group(2).lower() in ("on top of", "on", "under", "underneath", "below", "beneath") and says(m.string[: m.start()].split(".")[-1], "stack"):
        return m.group(0)
    return f", and {m.group(1)} {m.group(2)} "


@replacer("highest-topmost-stack-roles")
def _highest_topmost_stack_roles(m: re.Match[str]) -> str:
    return m.group(1).split()[0].replace('top', 'highest').replace('bottom', 'lowest')


#: The compass point each edge word names (the lexicon's compass, turned round; "far" and "near" the back and front).
_EDGE_POINT = {side: point for point, side in _COMPASS.items() if point in ("north", "south", "east", "west")} | {
    "far": "north", "near": "south"}


@replacer("facing-restated-by-edge")
def _facing_restated_by_edge(m: re.Match[str]) -> str:
    """"faces west, toward the left edge": the edge names the same direction, the facing once; else as said."""
    return m.group(1) if _EDGE_POINT[m.group(3).lower()] == m.group(2).lower() else m.group(0)


@replacer("only-spoon-not-fork")
def _only_spoon_not_fork(m: re.Match[str]) -> str:
    """", not the white one," after a plural ("the bowls, but not the white one,"): an exception; else nothing.

    "the cups and the bowls, but not the red bowl (though)," and "all of the bowls and cups, but not the red
    bowl,": a noun said in the plural just before is an exception from that group too (it was dropped, and the
    red bowl kept in the group)."""
    said = lexicon.words(m.group(2))
    if said[-1:] == ["though"]:
        said = said[:-1]
    before = lexicon.words(m.string[: m.start()])[-6:]
    plural = bool(said) and said[-1] not in ("one", "ones") and any(
        w in before for w in (said[-1] + "s", said[-1] + "es", said[-1][:-1] + "ies"))
    if said and (plural or (re.search(r"(?i)\b(?:the|all|all the|every) (?:[a-z]+ )?[a-z]+s\s*$",
                                      m.string[: m.start()]) is not None and said[-1] in ("one", "ones"))):
        return f" except the {' '.join(said)},"
    return ","


@replacer("circle-them-up-ring")
def _circle_them_up_ring(m: re.Match[str]) -> str:
    return f"put {('them' if m.group(2).lower() in ('em', chr(39) + 'em') else m.group(2))} in a circle"


@replacer("after-behind-beside-next")
def _after_behind_beside_next(m: re.Match[str]) -> str:
    return '' if says(m.string, "row") else 'in a line'


@replacer("their-new-spot-place")
def _their_new_spot_place(m: re.Match[str]) -> str:
    return ('it ' if m.group(1).lower() == 'its' else 'they ') + m.group(2)


@replacer("repairs-inside-reference-blue")
def _repairs_inside_reference_blue(m: re.Match[str]) -> str:
    """A request taken back ("..., no wait, ..."): dropped where it asked for an arrangement or a place setting,
    unless what follows only names again the object it ended on ("... in front of the yellow cup, no wait, the
    orange cup": that object is corrected, by the rows after this one)."""
    if _same_head_again(m) or not (says(m.group(2), "asks") or says(m.group(2), "setting")):
        return m.group(0)
    return m.group(1)


def _same_head_again(m: re.Match[str]) -> bool:
    """Whether the words after the repair ``m`` up to the next stop are one reference ("the orange cup", at most
    four words) with the head noun that the words before the repair end on."""
    tail = m.string[m.end() :]
    stop = min((k for k in (tail.find(c) for c in ",.;!?") if k >= 0), default=len(tail))
    said, before = lexicon.words(tail[:stop]), lexicon.words(m.group(2))
    return 2 <= len(said) <= 4 and said[0] == "the" and bool(before) and said[-1] == before[-1]


@replacer("not-the-other-one")
def _not_the_other_one(m: re.Match[str]) -> str:
    """"on the red mug, not the blue one": a contrast with the object named right before, dropped; after an
    exception, a plural or "but" ("the blocks in a circle, not the purple one") the words are kept for the parser, which
    reads them as an exception or refuses them (:meth:`.rules._Parser._trailing_not`)."""
    before = m.string[: m.start()]
    single = re.search(r"(?i)\bthe(?: [a-z]+){0,2} ([a-z]+)\s*,?\s*$", before)
    # after an exception in the same sentence ("all the bowls except the white one and not the green one"):
    # one more exception, kept for the parser
    if re.search(r"(?i)\bbut\s*,?\s*$|\b(?:except|excluding|other than|apart from|aside from|besides)\b[^.;!?]*$",
                 before) or single is None or (len(single.group(1)) >= 2 and single.group(1)[-1] == "s"
                                                                     and single.group(1)[-2] != "s"):
        return m.group(0)  # after "but", or a plural ("the blocks, not the purple one"): an exception
    return ""


#: The word said after a measure for the length each noun names ("a quarter of a metre across").
_MEASURED_AS = {"diameter": "in diameter", "width": "wide", "radius": "radius", "length": "long", "side": "each side",
                "spacing": "apart", "gap": "apart"}


@replacer("measure-said-as-noun")
def _measure_said_as_noun(m: re.Match[str]) -> str:
    """"; the diameter should come to a quarter of a metre" -> ", a quarter of a metre in diameter" (the
    measure said after its noun); left as said where the words after the verb are not one measure."""
    said = m.group(2).strip()
    found = find_measures(said)
    if len(found) != 1 or found[0].start != 0 or found[0].end != len(said):
        return m.group(0)
    return f", {said} {_MEASURED_AS[m.group(1).lower()]}"


@replacer("either-side")
def _either_side(m: re.Match[str]) -> str:
    """"the fork and the knife on either side of the plate" (both sides, one on each side): one object left of
    the reference and the other right of it (which goes where is left open by the command; left to right as
    named)."""
    first, second, anchor = m.group("a"), m.group("b"), m.group("z")
    return f"{first} to the left of {anchor} and {second} to the right of {anchor}"


@replacer("next-to-one-side")
def _next_to_one_side(m: re.Match[str]) -> str:
    """"put the star next to the pan" (no side said): to the left of it, as "either side" is read; left as said
    after a shape or an arrangement in the same sentence ("the blocks in a heart shape next to the heart", "the
    cans in a line next to the plate"), which the parser refuses."""
    before = m.string[: m.start()]
    sentence = before[max(before.rfind(c) for c in ".;!?") + 1 :]
    after = lexicon.words(m.string[m.end() :])[:6]
    if {"shape", *lexicon.ARRANGEMENT_NOUNS} & set(lexicon.words(sentence)) or m.group(1).lower() in ("the other", "the next", "the last") or (
            {"left", "right", "side", "either"} & set(after)) or before.rstrip().endswith(","):
        # a shape, "one beside the other", a side said after ("left side or right side"), or an aside between
        # commas ("line up the cans, beside the window, thanks": refused quoting it, never read as a side)
        return m.group(0)
    return f"to the left of {m.group(1)}"


@replacer("round-the-back")
def _round_the_back(m: re.Match[str]) -> str:
    """"round the back of the bowl": behind it; "round the front of": in front of it."""
    return "behind" if m.group(1).lower() == "back" else "in front of"


#: Things of the world said with "the" because there is one of them ("coloured like the sky").
_ONLY_ONE = frozenset({"sky", "sea", "sun", "ocean", "night", "snow", "grass"})


@replacer("world-colour")
def _world_colour(m: re.Match[str]) -> str:
    """"the same colour as a banana": yellow (lexicon ``[world_colours]``); "coloured like the sky": that are blue
    (said after a plural noun) or that is blue."""
    thing = m.group(2).lower()
    colour = lexicon.WORLD_COLOURS.get(thing)
    if colour is None or (m.group(1).lower() == "the" and thing not in _ONLY_ONE):
        return m.group(0)
    if m.group(0).lower().startswith("colo"):
        noun = lexicon.words(m.string[: m.start()])[-1:]
        plural = bool(noun) and noun[0].endswith("s") and not noun[0].endswith("ss")
        return f"that {'are' if plural else 'is'} {colour}"
    return colour


@replacer("whose-colour")
def _whose_colour(m: re.Match[str]) -> str:
    """"whose colour matches that of": that is the same colour as ("whose colours ...": that are)."""
    return f"that {'are' if m.group(1) else 'is'} the same colour as"
