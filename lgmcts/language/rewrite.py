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

__all__ = ["rewrite", "unframe", "QUESTION", "ASKS_TO_ACT", "FREE_ORDER"]

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
ASKS_TO_ACT = re.compile(r"(?i)^\s*(is it possible|are you able|do you (mind|think you could)|what about|how about)\b")

_COMPASS = {"north": "back", "south": "front", "east": "right", "west": "left",
            "northern": "back", "southern": "front", "eastern": "right", "western": "left"}
_COMPASS_REL = re.compile(
    r"(?i)\b(?:to the |on the |at the )?(north|south|east|west)(?:ern)?(?:[- ]?(east|west)(?:ern)?)?"
    r"(?: side| end)? of\b")
_NEAR_FAR = (
    (re.compile(r"(?i)\b(?:on |to )?the far side of\b"), "behind"),
    (re.compile(r"(?i)\b(?:on |to )?the near side of\b"), "in front of"),
    (re.compile(r"(?i)\b(?:further|farther) (?:back|away(?: from (?:me|us|you|the viewer|the camera))?) than\b"),
     "behind"),
    (re.compile(r"(?i)\b(?:nearer|closer)(?: (?:to )?(?:me|us|you|the viewer|the camera|the front))? than\b"),
     "in front of"),
    (re.compile(r"(?i)\b(?:further|farther) (?:forward|to the front) than\b"), "in front of"),
    (re.compile(r"(?i)\bdiagonally (?=(?:behind|in front|forward|back|ahead|to the|left|right|up|down))"), ""),
)
#: "any of the blocks", "either of the mugs": one of them, whichever.
_ANY_OF = re.compile(r"(?i)\b(?:any|either|any one|whichever) of (?:the|those|these)\b")
#: "behind the cup and to its right", "... and to the left of it", "... and off to
#: the right": one diagonal relation to one anchor.
_AND_ITS_SIDE = re.compile(
    r"(?i)\b(in front of|behind|to the left of|to the right of|left of|right of) ((?:the |a |one of the )?[^,;.!?]+?)"
    r"(?: and|,(?= (?:on |to )?(?:its|their) )) "
    r"(?:off |also |just |slightly |a bit )?(?:to |on )?(?:(?:its|their) (left|right|front|back)(?:[- ]hand)?(?: side)?"
    r"|the (left|right|front|back)(?: side)? of (?:it|them)\b|the (left|right)\b(?! of)|(behind|in front of) (?:it|them)\b)")
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
        words = re.findall(r"[a-z]+", m.group(1).lower())
        said = " ".join(words)
        if not re.search(rf"\b{_REPAIR_KEY}\b", said) or not re.fullmatch(
                rf"(?:(?:{_HEDGE}|{_REPAIR_KEY})\s*)+", said) or said in ("no", "well", "oh", "or"):
            return m.group(0)
        return ", no wait, "
    return _REPAIR_RUN.sub(one, text)


_REL_START = re.compile(r"(?i)(?:to the |on the |to its |on its |to their |the )?(?:left|right|front|back|behind|in front)\b")


_REMAKE = re.compile(r"(?i)\s*[,.!?;]\s*(?:(?:hmm+|um+|uh+|oh|no|wait|sorry|actually|or|instead)[,!.]?\s+)*"
                     r"(?:actually|no|wait|sorry|instead)[,!.]?\s+(?:um+,?\s+|uh+,?\s+)*make (?:it|that|them|the (?:stack|tower|"
                     r"order)) (?:into )?(.+?)(?:\s+instead)?\s*(?=[.!?;]|$)")
_SHAPE_PHRASE = re.compile(r"(?i)\b(?:a|an|one) (?:[a-z]+ )?(circle|ring|loop|rectangle|square|line|row|tower|stack|pile)\b")
_HUE_LIST = re.compile(r"(?i)\b(?:red|green|blue|yellow|purple|white|black|orange|pink|brown|grey|gray)"
                       r"(?:\s*(?:,|,? and|,? then)\s*(?:red|green|blue|yellow|purple|white|black|orange|pink|brown|grey|gray)){1,7}\b")


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


#: Words by which a clause can ask for a goal; a purpose clause has none of them.
_GOAL_CUE = re.compile(r"(?i)\b(?:left|right|front|behind|back|on|onto|under|underneath|below|above|beneath|over|top|bottom|"
                       r"base|line|lined|row|circle|ring|loop|tower|stack|stacked|pile|piled|rectangle|square|next|beside|"
                       r"between|facing|face|ends? up|north|south|east|west|diagonal|diagonally|corner|centre|center|middle|"
                       r"edge|side|order|first|last)\b")
_ACT = (r"(?:please |just |now |then |for now |first |kindly )*(?:put|place|move|stack|set|make|arrange|line|build|pile|lay|"
        r"could|can|would|will|get|grab|stick|pop|slide|shift|form|gather|group|bring|leave|keep|have|let|i'd|i want|i need)\b")
_PURPOSE_AFTER = re.compile(r"(?i)\s*,?\s*\b(?:so that|so|in order that|because|since) "
                            r"(?P<c>(?:i|we|you|my|our|he|she|the kids|the children|people|everyone|nobody|no one|"
                            r"it's|it is|it'll|it doesn't|it does not|it won't|it will|it can|they're|they are|they'll|"
                            r"they don't|they do not|they can|they won't|they take|it takes|there's|there is|everything's|"
                            r"everything is|everything will|nothing|the (?:[a-z]+ ){1,2}?(?:is|are|isn't|aren't|won't|doesn't|"
                            r"don't|will|stays|stay|gets|get))\b[^.;!?]*)")
_PURPOSE_BEFORE = re.compile(rf"(?i)(^|[.;!?]\s+)(?:so that|so|in order to|to|in order that|because|since)\s+"
                             rf"(?P<c>[^,;.!?]+),\s*(?={_ACT})")
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
        if words and len(words) <= 8 and re.search(r"(?i)\b(?:i think|yeah|yes|i mean|like|i guess|i suppose|probably|"
                                                    r"that's right|right, yes)\b", p) \
                and all(_SAME_WORD.get(w, w) in said for w in rest):
            continue
        kept.append(p)
    return " ".join(kept)


def _purposes(text: str) -> str:
    """The reasons people give with a request, which ask for nothing: "... so I
    can read the labels", "so the T is hidden from the camera", "to get the
    drinks ready, put ...", "I'm going to sort the shopping later, so ...".
    Only a clause with no word that could ask for a goal is dropped ("so that
    the blue mug ends up on its left" is a goal)."""
    text = _PURPOSE_AFTER.sub(lambda m: m.group(0) if _GOAL_CUE.search(m.group("c")) else "", text)
    text = _PURPOSE_BEFORE.sub(lambda m: m.group(0) if _GOAL_CUE.search(m.group("c")) else m.group(1), text)
    # Kept where the request after it says "them" / "it": its subject may be what they mean ("the cans are
    # everywhere, so put them in a row").
    return _REASON_BEFORE.sub(
        lambda m: m.group(0) if _GOAL_CUE.search(m.group("c")) or re.search(
            r"(?i)\b(?:it|its|them|they|those|these|'em)\b", re.split(r"[.;!?]", m.string[m.end():])[0]) else m.group(1),
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
        if relations_only and not _REL_START.match(rest):
            pos = m.end()
            continue
        np = re.search(r"(?i)\b(?:of|behind|on|onto|under|below|above|beneath) ((?:the|a) [a-z ]+?)\s*(?:,|$)", dropped)
        if np is not None:
            rest = re.sub(r"(?i)^((?:to the |on the |to its |on its )?(?:left|right|front|back)(?: side)? of|behind|"
                          r"in front of|on top of|on|onto|under|below|above|beneath) (?:it|them)\b",
                          lambda k: f"{k.group(1)} {np.group(1)}", rest)
        if re.match(r"(?i)(?:to|on) the ", dropped) and re.match(r"(?i)the (?:left|right|front|back)\b", rest):
            rest = dropped.split()[0] + " " + rest
        text = text[: m.start()] + rest


#: A contrast that only confirms the choice: "on the red mug, not the blue one".
_NOT_THE_OTHER = re.compile(r"(?i)\s*,?\s*\b(?:and )?not (?:on |onto |to |behind |beside )?(?:the|that) [a-z ]{0,20}?one\b")


#: Words that frame a request as the state wanted at the end ("the goal is ...",
#: "when it's done, ...", "picture this: ..."), and spoken openers ("okay so, um").
_FRAMES = (
    r"\b(?:so |basically |honestly |mm,? )*the (?:end |final )?goal(?: state)?(?: i'm after| i am after| here)?"
    r"(?: is| would be)?(?: (?:to have|to get|to see|that|for))?\s*:?\s*",
    r"\b(?:when|once|after) (?:it's|it is|it has been|everything is|everything's|you're|you are|you've|you have|"
    r"all is|it's all|it is all|we're|we are)(?: all)? (?:done|finished|complete|completed|over|through)\b,?\s*",
    r"\bwhen all's said and done\b,?\s*|\bwhen all is said and done\b,?\s*|\bat the end of the day\b,?\s*",
    r"\bin the end\b,?\s*|\bultimately\b,?\s*|\bthe way i (?:picture|see|imagine) it\b,?\s*",
    r"\bpicture this\s*:?\s*|^\s*(?:picture|imagine)\b\s*|\bfinal (?:layout|state|arrangement|result|setup|picture)\s*:\s*",
    r"\bthe end state(?: i'm after| i am after| i want| wanted)?\s*:\s*",
    r"\bthe (?:end |final |main )?(?:idea|plan|aim|point|target|result)(?: here)? is(?: that| to have| for)?\s+",
    r"\bwhat i'?m after is\s+|\bwhat i am after is\s+|\bwhat i want is\s+",
    r"\bwhen i (?:come back|get back|return)(?:,)?\s*",
    r"^\s*(?:can|could|may|might) (?:we|i) (?:please )?(?:have|get|see)\s+(?=the\b|all\b|every|both\b|any\b)",
    r"^\s*(?:okay |ok |so |right )*(?:two|three|four|a couple of|a few) (?:things|jobs|tasks)\b[^.:;!?]*[.:;!?]\s*",
    r"\b(?:tidy[- ]up|clean[- ]up) time\s*[!.]?\s*",
    r"\b(?:the kids?|my (?:son|daughter|wife|husband|partner|kids?|boss|mum|mom|dad)|grandma|grandpa) "
    r"(?:wants?|would like|needs?|asked for)\s+",
)
_OPENER = re.compile(r"(?i)^\s*(?:(?:so|okay|ok|alright|all right|well|um+|uh+|hmm+|mm+|oh|yeah|yes|hey|real quick|"
                     r"basically|like)\b[,\s]*|right\b\s*(?:,|so\b)[,\s]*)+")


_WISH = re.compile(r"(?i)\bit(?:'d| would) be (?:really |so |very |just )?(?:great|nice|lovely|good|helpful|awesome|ideal|"
                   r"perfect|wonderful|brilliant|cool|fantastic|super)(?: (if|to have|to see|to get))?\s+")


def unframe(text: str) -> str:
    """The request without the words that frame it as an end state or open it in speech."""
    text = _OPENER.sub("", text)
    # "It would be great if the cans were in a row", "it'd be nice to have the bowls stacked": the state wished for.
    m = _WISH.search(text)
    if m is not None:
        rest = text[m.end():]
        if m.group(1) == "if":
            rest = re.sub(r"(?i)\s+\b(?:were|was|stood|sat|could be|would be|could go|went)\b", "", rest, count=1)
        text = text[: m.start()] + rest
    for f in _FRAMES:
        text = re.sub(f"(?i){f}", "", text)
    text = re.sub(r"(?i)\bthe (?:final|finished|end) (stack|tower|pile|line|row|circle|ring|rectangle|square|arrangement)\b",
                  r"the \1", text)
    text = re.sub(r"(?i)\bthe (?:final|finished|end) (?:layout|arrangement|state|result|picture|table) "
                  r"(?:should|will|must) (?:have|show|be)\s*:?\s*", "", text)
    text = re.sub(r"(?i)\bthe goal for (the (?:[a-z]+ ){0,2}?[a-z]+) is(?: that)?\b", r"\1:", text)
    return _OPENER.sub("", text)


#: Verb stems of "-ing" forms and their base forms.
_BASE = {"put": "put", "plac": "place", "stack": "stack", "pil": "pile", "arrang": "arrange", "lin": "line",
         "mov": "move", "sett": "set", "lay": "lay", "build": "build", "form": "form", "position": "position",
         "align": "align", "group": "group", "mak": "make", "gett": "get", "bring": "bring", "shift": "shift",
         "slid": "slide", "organis": "organise", "organiz": "organize", "gather": "gather", "sort": "sort"}


#: Words after which "can" is the object ("the white can go ...", "one can goes ...").
_NOUN_BEFORE = frozenset("""the a an this that each every one any red green blue yellow purple white black orange pink
    brown gray grey silver golden other""".split())

#: Words that speak of heights, which make a "column" a stack.
_HEIGHTS = re.compile(r"(?i)\b(?:tall|taller|topmost|bottommost|stack(?:ed|ing)?|pil(?:e|ed|ing)|on top|"
                      r"at the (?:top|bottom|base)(?! left| right| cent| middle| of the table| edge| side| corner| end| half)|"
                      r"on the bottom|as the base|(?:bottom|top) to (?:top|bottom)|under(?:neath)?|beneath|above|below|"
                      r"highest|lowest|high|vertical)\b")
#: Words that ask for an arrangement or a relation.
_ASKS = re.compile(r"(?i)\b(?:in front|behind|left|right|on top|onto|on|under|underneath|below|beneath|above|circle|"
                   r"ring|loop|row|line|lined|stack|stacked|pile|piled|tower|rectangle|square|facing|pointing)\b")


def _like_restated(m: re.Match) -> str:
    """Drop ", like ..." where the words before it already ask for an arrangement;
    else keep what it says ("the cups, like round in a circle")."""
    if _ASKS.search(m.group(1)):
        return m.group(1)
    return m.group(1) + re.sub(r"(?i),\s*(?:so |and )?(?:like|yeah|you know|i mean|basically)\b", ",", m.group(2))


_SHAPE_NOUN = re.compile(r"(?i)\b(a|an|one|the) (circle|ring|loop|rectangle|square|line|row|tower|stack|pile)\b")
_SIZE_SAID = ((re.compile(r"(?i),?\s*\b(?:nice and|good and|really|nice|small and|tight and)? ?(?:wide|spread out|roomy|"
                          r"spacious)\b(?! of)"), "large"),
              (re.compile(r"(?i),?\s*\b(?:nice and|small and|good and|really) (?:tight|compact|close together|snug)\b"),
               "small"))


#: A size said on its own after the arrangement: ", a big one", ", medium size".
_SIZE_AFTER = re.compile(r"(?i),\s*(?:(?:a|an) (small|little|tiny|medium|medium-sized|mid-sized|large|big|huge) one|"
                         r"(small|medium|large|big)[- ]?(?:size|sized))\b(?=\s*(?:[,;.!?]|$))")
_SIZE_NAMES = {"little": "small", "tiny": "small", "medium-sized": "medium", "mid-sized": "medium", "big": "large",
               "huge": "large"}
_BARE_SHAPE = re.compile(r"(?i)\b()(circle|ring|loop|rectangle|square|line|row|tower|stack|pile)\b")


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
    if after is not None and after.start() >= a.end() and not re.search(
            r"(?i)\b(?:no|wait|sorry|actually|i mean|rather)\b", text[a.end() : after.end()]):
        size = (after.group(1) or after.group(2)).lower()
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
    """Phrasings with one reading written the way the grammar reads them:
    directions (:func:`_relation_words`), "the blue bottle's colour" -> "the
    same colour as the blue bottle", "that matches / shares the same colour
    as" -> "with the same colour as", "table centre" / "the table's left
    edge" -> "the centre / left edge of the table", and the reading orders of
    a stack ("from the top down", "bottom up") -> "from top to bottom" /
    "from bottom to top"."""
    text = re.sub(r"(?i)\b(?:right|just|directly) (next to|beside|alongside)\b", r"\1", text)  # "right next to": next to
    # A trailing-off "..." is a pause inside the sentence before a lowercase word ("in front of... no,
    # behind"), and a sentence end before a capital.
    text = re.sub(r"\s*(?:\.{3,}|\u2026)\s*(?=[a-z])", ", ", text)
    text = re.sub(r"\s*(?:\.{3,}|\u2026)", ". ", text).strip()
    # "Stack them so that the blue block is at the top, ...": at the very start, "them" are the objects named next.
    text = re.sub(r"(?i)^\s*((?:please |now |ok(?:ay)?,? )?(?:stack|pile|tower) )them (up )?(?=(?:so that|so|such that|with|"
                  r"in the order|in this order)\b)", r"\1\2", text)
    # "a big round of the blocks": a circle.
    text = re.sub(r"(?i)\b(a|one) ((?:[a-z]+ )?)round(?= of\b)", r"\1 \2circle", text)
    # A place setting said as an end state: "everything should be laid out for a meal", "dinner should be set".
    modal = r"(?:should|must|needs to|need to|ought to|has to|have to|will|is to)\s+be"
    text = re.sub(rf"(?i)\b(?:everything|things|it all|all of it|the table|the place|the setting)\s+{modal}\s+(?:all )?"
                  r"(?:laid out|set out|set up|set|laid|ready|prepared)\s+for\s+(?:a |the )?(?:meal|dinner|lunch|supper|"
                  r"breakfast|eating)\b", "set the table", text)
    text = re.sub(rf"(?i)\b(?:dinner|lunch|supper|breakfast|the meal)\s+{modal}\s+(?:laid out|set out|set up|set|laid|"
                  r"ready|served)\b", "set the table", text)
    text = re.sub(r"(?i)^\s*by the time (?:i|we|you|they|he|she|the [a-z]+) [a-z]+(?: [a-z]+)?,\s*", "", text)
    text = re.sub(r"(?i)\b(should|must|will) (?:also|too|then) (be|end up)\b", r"\1 \2", text)
    # "the cup should end up on the bowl": the state, as "should be".
    text = re.sub(r"(?i)\b(should|must|will|needs to|need to|has to|have to|ought to) (?:end up|wind up|finish up)\b",
                  r"\1 be", text)
    # "put the bowl on the plate with the cutlery in a line to its left": "with" after a relation starts a
    # second goal (not one line of the bowl and the cutlery).
    text = re.sub(r"(?i)\b((?:on|onto|on top of|behind|in front of|left of|right of|under|underneath|beneath|below|above) "
                  r"the(?: [a-z]+){1,3}?),? with (the(?! latter| former)(?: [a-z]+){1,3}?) (?=(?:in a|in one|lined|to the|to its|"
                  r"on the (?:left|right)|on its|behind|in front|beside|next to|left of|right of)\b)", r"\1, and \2 ", text)
    # "every piece of cutlery", "the three pieces of silverware": the cutlery (a piece is not any object).
    text = re.sub(r"(?i)\b(?:every|each|any) (?:single )?(?:piece|item|bit) of (?:the )?(cutlery|silverware|flatware|crockery|"
                  r"tableware)\b", r"all the \1", text)
    text = re.sub(r"(?i)\b(the|all|all the|all of the|both) ((?:two|three|four|five|six|\d) )?(?:pieces|items|bits) of (?:the )?"
                  r"(cutlery|silverware|flatware|crockery|tableware)\b", r"\1 \2\3", text)
    # "crown the orange block with the purple one", "use the pan to support the bowl": the second on the first.
    text = re.sub(r"(?i)\b(?:crown|cap|top off|top) (the(?: [a-z]+){1,3}?) with (the(?: [a-z]+){1,3}?)(?=\s*(?:[,.;!?]|$|and\b))",
                  r"put \2 on \1", text)
    text = re.sub(r"(?i)\buse (the(?: [a-z]+){1,3}?) to (?:support|hold up|carry|hold) (the(?: [a-z]+){1,3}?)"
                  r"(?=\s*(?:[,.;!?]|$|and\b))", r"put \2 on \1", text)
    # "stand them one on the next", "lay them out one beside the next": a stack, a row.
    text = re.sub(r"(?i)\bone (?:on|atop|upon|on top of) (?:the next|the next one)\b", "on top of each other", text)
    text = re.sub(r"(?i)\bone (?:beside|next to|after|behind) the next(?: one)?\b", "in a row", text)
    # "it doesn't matter which one goes at the bottom", "either one can go on top": the order is open.
    text = re.sub(r"(?i)\b(?:(?:it )?(?:does not|doesn't|does n't) matter which|(?:either|any|whichever))(?: one| of them| "
                  r"of the (?:two|three|four|[a-z]+))? (?:can |may |could |will )?(?:goes|go|sits|sit|is|ends up|end up|"
                  r"comes|come|lands|land|be) (?:on|at) (?:the )?(?:bottom|top|base)\b", "in any order", text)
    text = re.sub(r"(?i)\bwhichever(?: one)?(?: goes)? (?:on top|at the top|at the bottom|on the bottom|underneath)\b",
                  "in any order", text)
    # "arranged around a common centre to form a circle": what a circle is, not a place on the table.
    text = re.sub(r"(?i)\s*\b(?:around|round|about) (?:a|one|the) (?:common|shared|single|central|same) (?:centre|center|point|"
                  r"middle|spot)\b", "", text)
    # Stack roles in other words: floors and layers, "(base)", "base = yellow", "crowning the whole thing",
    # "red bottom, green middle", "red on the table" in a stack, "the white one holds up the black one".
    text = re.sub(r"(?i)\b(?:is|as|on|at|in|for) the (?:ground|bottom|first|lowest) (?:floor|layer|level|storey|story|tier)\b",
                  "at the bottom", text)
    text = re.sub(r"(?i)\b(?:is|as|on|at|in|for) the (?:top|upper|uppermost|highest) (?:floor|layer|level|storey|story|tier)\b",
                  "on top", text)
    text = re.sub(r"(?i)\s*\((?:the )?(?:base|bottom)\)", " at the bottom", text)
    text = re.sub(r"(?i)\s*\((?:the )?top\)", " on top", text)
    text = re.sub(r"(?i)(?<!to )(?<!from )(?<!the )\b(base|bottom|top)\s*(?:=|is)\s*(red|green|blue|yellow|purple|white|black|"
                  r"orange|pink|brown|gr[ae]y)\b",
                  lambda m: f"{m.group(2)} {'on top' if m.group(1).lower() == 'top' else 'at the bottom'}", text)
    text = re.sub(r"(?i)\b(?:crowning|topping|capping) (?:it all|the (?:whole )?(?:thing|stack|tower|pile|lot))\b", "on top", text)
    text = re.sub(r"(?i)(?<!to )(?<!from )\b(red|green|blue|yellow|purple|white|black|orange|pink|brown|gr[ae]y) (bottom|middle|top)"
                  r"\b(?! of)(?=\s*(?:[,;.!?]|$|and\b))",
                  lambda m: f"{m.group(1)} {dict(bottom='at the bottom', middle='in the middle', top='on top')[m.group(2).lower()]}",
                  text)
    if re.search(r"(?i)\b(?:stack|stacked|tower|pile|piled)\b", text):
        text = re.sub(r"(?i)\b(red|green|blue|yellow|purple|white|black|orange|pink|brown|gr[ae]y) (?:goes |sits |stays |rests )?"
                      r"(?:directly )?on the table\b", r"\1 at the bottom", text)
    text = re.sub(r"(?i)\b(the(?: [a-z]+){1,3}?) (?:has to |must |should |will |can |is to |needs to )?(?:hold|holds|support|"
                  r"supports|carry|carries|bear|bears) up (the(?: [a-z]+){1,3}?)(?=\s*(?:[,;.!?]|$|and\b))", r"\2 on \1", text)
    # "take / use the tiger pan as the base and put the star onto it": the star on the tiger pan.
    m = re.search(r"(?i)\b(?:take|use|have|start with|begin with) (the(?: [a-z]+){1,3}?) as the (?:base|bottom|foundation)"
                  r"(?: layer| level)?\s*,?\s*(?:and |then )*", text)
    if m is not None and re.search(r"(?i)\b(?:it)\b", text[m.end():]):
        rest = re.sub(r"(?i)\bit\b", m.group(1), text[m.end():], count=1)
        text = text[: m.start()] + rest
    text = re.sub(r"(?i)\b(the(?: [a-z]+){1,3}?) (?:forms|makes up|serves as|acts as) the (?:base|foundation)\b",
                  r"\1 at the bottom", text)
    # "in the middle of the right-hand side of the table", "at the centre of the table's front edge".
    text = re.sub(r"(?i)\b(?:in|at) the (?:middle|centre|center) of the (left|right)(?:[- ]hand)? (?:side|edge|half)\b",
                  r"on the \1 side", text)
    text = re.sub(r"(?i)\b(?:in|at) the (?:middle|centre|center) of the (?:table's )?(front|back|near|far) (?:edge|side|half)"
                  r"(?: of the table)?\b", lambda k: "at the " + {"near": "front", "far": "back"}.get(k.group(1).lower(),
                                                                                       k.group(1)) + " of the table", text)
    # "oriented so that it faces west": facing west.
    text = re.sub(r"(?i),?\s*\b(?:(?:oriented|orientated|turned|rotated|positioned|arranged|placed|set) )?so (?:that )?"
                  r"(?:it|they|the (?:[a-z]+ ){0,2}[a-z]+) (?:faces|face|is facing|are facing|points|point)(?: towards?)? "
                  r"(?:the )?(north|south|east|west)\b", r" facing \1", text)
    # "farther from the viewer than the blue bowl": behind it.
    viewer = r"(?:the viewer|the camera|the observer|the front|me|us|you|the robot)"
    text = re.sub(rf"(?i)\b(?:farther|further|more distant) (?:away )?from {viewer} than\b", "behind", text)
    text = re.sub(rf"(?i)\b(?:closer|nearer) to {viewer} than\b", "in front of", text)
    # "... nearer to me than it is": the comparison's own verb.
    text = re.sub(r"(?i)\b(in front of|behind) (it|them|the(?: [a-z]+){1,3}?) (?:is|are|does|do)(?=\s*(?:[.,;!?]|$))",
                  r"\1 \2", text)
    # "to the right of the purple block, further back": that side and behind it (a diagonal).
    text = re.sub(r"(?i)\b(to the (?:left|right) of the(?: [a-z]+){1,3}?),? (?:and )?(?:a bit |slightly |a little |just )?"
                  r"(?:further|farther) (back|forward|away|towards me|toward me)\b",
                  lambda m: m.group(1) + (" and behind it" if m.group(2).lower() in ("back", "away") else " and in front of it"),
                  text)
    # "in a linear formation", "a circular arrangement".
    text = re.sub(r"(?i)\b(?:an? )?(linear|circular|rectangular) (?:formation|arrangement|configuration|array|layout)\b",
                  lambda k: {"linear": "a line", "circular": "a circle", "rectangular": "a rectangle"}[k.group(1).lower()],
                  text)
    # "With the exception of the red A, arrange the letters in a row": the exception after the request.
    text = re.sub(r"(?i)^(?:with the exception of|except for|apart from|aside from|other than|excluding) (the [^,;.!?]+?),\s*"
                  r"([^;.!?]+)", r"\2, except \1", text)
    # "bowls, minus the blue one -> stack", "blocks that aren't red - tower": an arrangement after an arrow or a dash.
    text = re.sub(r"(?i)\s*(?:->|=>|→|\s-)\s*(?:a |one )?(stack|tower|pile|line|row|circle|ring|square|rectangle)\b",
                  r" in a \1", text)
    # "if that's all right with you", "if it's no trouble at all": politeness that asks for nothing.
    text = re.sub(r"(?i),?\s*\bif (?:that's|that is|it's|it is|that'd be|it'd be) (?:all right|alright|ok|okay|fine|no trouble|"
                  r"not too much (?:trouble|bother)|no bother)(?: at all)?(?: with you| by you| for you)?\b,?", "", text)
    text = re.sub(r"(?i),?\s*\bif you see what i mean\b", "", text)
    text = re.sub(r"(?i),?\s*\b(?:while|whilst) (?:i|we) (?:[a-z']+ ){0,3}?[a-z']+(?=\s*(?:[.!?;]|$))", "", text)
    # A choice left open, said on its own: "either is fine", "either bowl will do", "either way round".
    text = re.sub(r"(?i)\s*[,.;!?]\s*(?:(?:either|any|whichever)(?: one| of them| of the [a-z]+| [a-z]+)?(?: at all)? "
                  r"(?:is|will|would|'ll|should)? ?(?:be )?(?:fine|do|ok|okay|work|good)|either way(?: round| around)?|"
                  r"whichever (?:ones?|way)(?: you like)?)\s*(?=[.!?;]|$)", "", text)
    # "bottle's in the way", "the star's wandered off": "is" / "has", not a possessive.
    text = re.sub(r"(?i)\b(?!(?:it|that|there|what|here|let|he|she|who|where|everything|nothing|something|one)'s)([a-z]+)'s "
                  r"(in|on|too|so|very|really|still|just|not|been|gone|got|wandered|sitting|standing|lying|blocking|taking|"
                  r"getting|always|already|over|out|under|behind|kind|quite|pretty|way|near|far|close|rolled|fallen|moved)\b",
                  r"\1 is \2", text)
    # A place setting with the cutlery "beside the plate" / "next to it" / "on either side": a side is
    # left open, and the left one is chosen.
    if re.search(r"(?i)\b(?:cutlery|silverware|flatware|utensils|fork,? (?:the )?knife,? and (?:the )?spoon)\b", text) \
            and re.search(r"(?i)\bplate\b", text):
        text = re.sub(r"(?i)\b(?:beside|next to|alongside|by the side of) (the plate|it)\b(?:\s*[,;]?\s*(?:on )?(?:whichever|"
                      r"either|any) side(?: you like| you want| is fine| acceptable| will do)?)?", r"to the left of \1", text)
        text = re.sub(r"(?i)\bon (?:either|whichever|any) side(?: of (?:the plate|it))?\b", "to the left of the plate", text)
        text = re.sub(r"(?i)\s*[,;]\s*(?:on )?(?:whichever|either|any) side(?: you like| you want| is fine| will do)?"
                      r"(?=\s*[.!?)]|\s*$)", "", text)
    # "whatever is black or white", "whatever matches the cup": everything that is.
    text = re.sub(r"(?i)\bwhatever (?:is |'s )?(?=(?:red|green|blue|yellow|purple|white|black|orange|pink|brown|gr[ae]y|silver)\b)",
                  "everything ", text)
    text = re.sub(r"(?i)\b(?:whatever|everything|anything|all the (?:things|objects|items|stuff)) (?:shares?|has) (?:a|the) "
                  r"(colou?r|shape) (?:with|as)\b", r"everything with the same \1 as", text)
    text = re.sub(r"(?i)\bwhatever (?=(?:with the same|is the same|matches|shares|has the same))", "everything ", text)
    # ", like," set off by commas is a filler ("all the blocks that aren't, like, red").
    text = re.sub(r"(?i)\b(aren't|are not|isn't|is not|are|is|that|which|the)\s*,\s*like,\s*", r"\1 ", text)
    # "stack things up from the bottom: first the plate, ...": "things" without a determiner selects nothing.
    text = re.sub(r"(?i)\b(stack|pile)( up)? (?:things|stuff)( up)?(?=\s*(?:from\b|:|,|so\b|like\b|as\b|with\b))",
                  r"\1\2\3", text)
    # "the bottles side by side with the white can", "the bowls in a line with the red block": one line of both.
    text = re.sub(r"(?i)(?:^|(?<=[,;:.!?] )|(?<=\bput )|(?<=\bwant )|(?<=\bplace )|(?<=\bline up )|(?<=\bthe ))"
                  r"((?:the )?(?:[a-z]+ ){0,2}?[a-z]+) (side by side|in a (?:line|row)|lined up)((?: in a (?:line|row))?) with "
                  r"(the(?: [a-z]+){1,3}?)(?=\s*(?:[,;.!?]|$|and\b))",
                  lambda m: f"{m.group(1)} and {m.group(4)} {m.group(2)}{m.group(3)}", text)
    # "the letters, all but the yellow T, in a row"; "the things the same colour as the can, that can included,".
    text = re.sub(r"(?i),\s*all but (the [^,;.!?]+?)\s*,", r" except \1,", text)
    text = re.sub(r"(?i),\s*(?:that|the|this) [a-z]+(?: [a-z]+)? (?:included|too|as well),", ",", text)
    # "take the yellow cup, and could you put it ...": one request.
    text = re.sub(r"(?i),?\s*\band (?:could|can|would|will) you (?:please |maybe |just )?(?=(?:put|place|move|stack|set|"
                  r"line|arrange|make|pop|stick|slide|shift|get|lay|pile)\b)", " and ", text)
    # "tidy up the letters, put 'em in a row": the objects, then the request about them.
    text = re.sub(r"(?i)(^|[.;!?]\s+)(?:please )?(?:tidy|clean|sort|neaten|organi[sz]e)(?: up)? (the [a-z ]+?),\s*"
                  r"(?=(?:and |then )?(?:put|place|line|stack|arrange|make|set|get|pile|lay)\b)", r"\1\2, ", text)
    # "the plate on the bottom, then the bowl, then the mug on top": a stack described without a word for it.
    if not re.search(r"(?i)\b(?:stack|stacks|stacked|stacking|tower|towers|pile|piles|piled)\b|on top of (?:each other|one "
                     r"another|the other)", text) and re.search(
            r"(?i)\b(?:on top|at the top|then|above it|on it|next)\b", text):
        text = re.sub(r"(?i)(^|[.;:!?]\s*|\b(?:so|want|like|need|have)\s+)((?:the )?(?:[a-z]+ ){0,2}?[a-z]+ (?:on|at) the "
                      r"(?:bottom|base)\b)", r"\1build a tower with \2", text, count=1)
    # "to its left and in front of it": the same diagonal as "in front of it and to its left".
    text = re.sub(r"(?i)\b(?:to|on) (its|their) (left|right)(?: side)? and (in front of|behind) (it|them)\b",
                  r"\3 \4 and to \1 \2", text)
    # "behind both of them": behind them.
    text = re.sub(r"(?i)\b(behind|in front of|left of|right of|next to|beside|on|under|below|above|of) (?:both|all) of "
                  r"(them|those)\b", r"\1 \2", text)
    # "the letters side by side": next to each other, in a line.
    text = re.sub(r"(?i)\b(?:next to each other|side by side)(?! with)(?=\s*,\s*(?:all )?in a (?:row|line))", "", text)
    text = re.sub(r"(?i)(?<=, )side by side\b(?! with)", "next to each other", text)
    text = re.sub(r"(?i)\bside by side\b(?! with)", "in a row", text)
    # "at the far right": the right side ("the far right corner" is the back right).
    text = re.sub(r"(?i)\b(?:at|on|to|over at|over on) the far (left|right)\b(?! corner| side| of| edge)", r"on the \1 side of the table", text)
    # "not the cans, not the bowls, just the rest": everything but them.
    m = re.match(r"(?i)^\s*(?:not|no) (the [a-z ]+?)((?:,\s*(?:and )?(?:not|no) the [a-z ]+?)*),\s*(?:just |only )?(?:the rest|"
                 r"everything else|all the rest|the others)\b", text)
    if m is not None:
        more = re.findall(r"(?i)(?:not|no) (the [a-z ]+?)(?=,|$)", m.group(2) + ",")
        text = "everything except " + " and ".join([m.group(1), *more]) + text[m.end():]
    # "the warm coloured blocks, I mean red, orange and yellow": the colours said.
    hue = r"(?:red|green|blue|yellow|purple|white|black|orange|pink|brown|gr[ae]y)"
    text = re.sub(rf"(?i)\bthe (?:[a-z-]+ ){{0,2}}?([a-z]+s),\s*(?:i mean|meaning|that is|namely)\s*,?\s*((?:the )?{hue}"
                  rf"(?:(?:\s*,\s*|\s+and\s+|\s*,\s*and\s+|\s+or\s+)(?:the )?{hue})*)(?: ones)?\b",
                  lambda k: f"the {k.group(2)} {k.group(1)}", text)
    # "the letters, the ones that aren't red": the letters that aren't red.
    text = re.sub(r"(?i)\b(the [a-z]+s),\s*(?:i mean |like )?the ones (that|which|who) ", r"\1 \2 ", text)
    # "facing east, you know, toward the right": the facing said again.
    text = re.sub(r"(?i)\b(facing (?:north|south|east|west))\s*,\s*(?:you know,?\s*|like,?\s*|i mean,?\s*)*(?:toward|towards|to|"
                  r"pointing(?: to| toward| towards)?|so it points) (?:the )?(?:right|left|front|back|me|us|you|the viewer|"
                  r"away from (?:me|us|you))\b", r"\1", text)
    # A tag question at the end: ", right?", ", okay?".
    text = re.sub(r"(?i)\s*,\s*(?:right|okay|ok|yeah|alright)\s*\?\s*$", ".", text)
    # "that same bowl": the bowl named before.
    text = re.sub(r"(?i)\bthat same\b", "the same", text)
    text = re.sub(r"(?i)\bwhichever way (?:up|round|around)\b", "in any order", text)
    # "gather the star, the heart and the pan into a circle": put them there; "gather up X and ...": take them.
    text = re.sub(r"(?i)\bgather(?: up| together)? (?=[^.;!?]*?\b(?:into|in) (?:a|an|one)\b)", "put ", text)
    text = re.sub(r"(?i)\bgather(?: up| together)? ", "take ", text)
    # Fillers between commas after a function word: "the blocks that, uh, aren't red", "as the, uh, the green can".
    text = re.sub(r"(?i)\b(that|which|the|a|an|are|is|to|of|on|in|with|at|as)\s*,\s*(?:(?:uh|um|er|erm|hmm|like)\s*,?\s*)+",
                  r"\1 ", text)
    text = re.sub(r"\b([Tt]he) the\b", r"\1", text)
    # "the things that match the white can, colour-wise": the same colour as it.
    text = re.sub(r"(?i)\b(?:that|which) (?:match|matches) (the(?: [a-z]+){1,3}?),?\s*colou?r[- ]?wise\b",
                  r"with the same colour as \1", text)
    # "diagonally in front of the bowl, on the left", "behind the can, off to the right", "in front of the
    # bowl but a bit to the left, like diagonally": one diagonal.
    text = re.sub(r"(?i),?\s*\b(?:like |sort of |kind of )?diagonally\b(?=\s*[,.;!?]|\s*$)", "", text)
    text = re.sub(r"(?i)\b(in front of|behind) (the(?: [a-z]+){1,3}?),?\s*(?:but\s+)?(?:a bit |slightly |just |a little )?"
                  r"(?:on|off to|to|over to|towards|toward) the (left|right)\b(?! of| side of the table)",
                  r"\1 \2 and to its \3", text)
    # "on the right side of the table, halfway back": the middle row, which a side alone already means.
    text = re.sub(r"(?i),?\s*\bhalfway (?:back|up the table|down the table)\b", "", text)
    # "build a stack where the red block is at the bottom ...": the stack with those roles.
    text = re.sub(r"(?i)\b(stack|tower|pile) (?:where|in which|such that|so that) (?=the\b)", r"\1 with ", text)
    text = re.sub(r"(?i)\bup top\b", "on top", text)
    # "from top to bottom it's purple, orange, yellow": the list itself.
    text = re.sub(r"(?i)\b(from (?:top to bottom|bottom to top)),? (?:it's|it is|they're|they are|they go|it goes|"
                  r"we have|you have) ", r"\1: ", text)
    # "last thing, ...", "one more thing:": a heading.
    text = re.sub(r"(?i)(^|[,.;!?]\s*)(?:and )?(?:one )?(?:last|final|first|one more|another|next) thing\s*[,:]\s*", r"\1",
                  text)
    # "piled into one tall column": a stack.
    text = re.sub(r"(?i)\b(stack|stacked|stacking|pile|piled|piling)( up)? into (?:one |a )?(?:single |tall |neat |straight )*"
                  r"(?:column|pillar)\b", r"\1\2 into a tower", text)
    # Any other "column" is a line ("the letters in a column", "column, front to back"), unless the command
    # speaks of heights ("one column of blocks: purple topmost ... yellow at the base").
    text = re.sub(r"(?i)\bcolumn\b", lambda m: "tower" if _HEIGHTS.search(text) else "line", text)
    # "arrange it so the phone sits on the can's left", "make it so ...": the state asked for.
    text = re.sub(r"(?i)(^|[.;!?]\s+)(?:please |could you |can you )?(?:arrange|make|set|fix|have|get) (?:it|things) so(?: that)?\s+",
                  r"\1", text)
    # "I want two piles. Red on yellow, blue on green.": a count of stacks, then each stack.
    text = re.sub(r"(?i)(^|[.;!?]\s+)(?:i (?:want|need|would like)|i'd like|make|build|we need|there should be|let's have)"
                  r"(?: me)? (?:two|three) (?:separate )?(?:piles|stacks|towers)\s*[.:;]\s*(?=\S)", r"\1", text)
    # "red on yellow in one, blue on green in the other": the two stacks named one by one.
    text = re.sub(r"(?i)\s*\bin (?:one|the first)(?: one| pile| stack| tower)?(?=\s*[,;])", "", text)
    text = re.sub(r"(?i)\s*\bin the (?:other|second)(?: one| pile| stack| tower)?\b", "", text)
    # "the cup on one side of the plate and the bottle on the other": one left, one right.
    text = re.sub(r"(?i)\b(the(?: [a-z]+){1,3}?) on one side of (the(?: [a-z]+){1,3}?),? and (the(?: [a-z]+){1,3}?) on the other"
                  r"(?: side)?(?: of it)?\b", r"\1 to the left of \2 and \3 to the right of \2", text)
    text = re.sub(r"(?i),?\s*\b(?:while|whilst) you(?:'re| are) at it,?", "", text)
    text = re.sub(r"(?i)\b(?:in )?between (?:them|those|the two|these)(?: two)?\b(?! and)", "in the middle", text)
    # "green under blue under yellow": two steps of one stack.
    hue = r"(?:red|green|blue|yellow|purple|white|black|orange|pink|brown|gr[ae]y)"
    text = re.sub(rf"(?i)\b({hue}) (under|below|beneath|on|above|over) ({hue}) \2 ({hue})\b", r"\1 \2 \3 and \3 \2 \4", text)
    # "and the red block above that": "that" after a place word is the object just placed.
    text = re.sub(r"(?i)\b(on top of|on|onto|above|over|atop|upon|under|below|beneath|underneath|behind|in front of|"
                  r"left of|right of) (?:that|this)(?: one)?(?=\s*(?:[,;.!?]|$|and\b|then\b|please\b))",
                  lambda m: "on top of it" if m.group(1).lower() in ("above", "over") else f"{m.group(1)} it", text)
    text = re.sub(r"(?i)\bone (?:on top of|on|onto|above|upon|atop|over) (?:the other|another)\b", "on top of each other",
                  text)
    text = re.sub(r"(?i)\bany ?(?:way|old way|order) (?:you|u) (?:want|like|please)\b", "", text)
    # "one mug on top of the other": the two mugs stacked.
    text = re.sub(r"(?i)\bone ([a-z]+) (?:on top of|on|onto|above|upon|atop|over) the other(?: one)?\b",
                  lambda m: f"the {m.group(1)}s on top of each other", text)
    # Articles and "of" left out: "on top the plate", "red block at bottom", "in front the bowl".
    text = re.sub(r"(?i)\b(on top|in front|in back|on the top|at the top|on the left side|on the right side)"
                  r" (the|a|an|this|that|my|your)\b", r"\1 of \2", text)
    text = re.sub(r"(?i)\b(at|on|in) (bottom|top|base)\b(?! of)", r"\1 the \2", text)
    # "next to the box on its left": left of the box.
    text = re.sub(r"(?i)\b(?:next to|beside|by|alongside) (the (?:[a-z]+ ){0,3}?[a-z]+|it|them),? (?:on|to|at) "
                  r"(?:(?:its|their|the) )?(left|right|far|near)(?: side| hand side)?\b",
                  lambda m: {"far": "behind ", "near": "in front of "}.get(m.group(2).lower(),
                                                                          f"to the {m.group(2)} of ") + m.group(1), text)
    # "centred on the table", "in the dead centre": the middle of the table.
    text = re.sub(r"(?i)\b(?:centred|centered) (?:on|in|at) the (?:table|workspace|tabletop)\b",
                  "in the centre of the table", text)
    # "... and behind of it": "behind it" (not after "left"/"right", where "right behind of" is a diagonal).
    text = re.sub(r"(?i)(?<!left )(?<!right )\bbehind of (it|them)\b", r"behind \1", text)
    # Learners' English: "you are putting them in a circle" (a request), "everything what is blue",
    # "do them in a round shape".
    text = re.sub(r"(?i)\byou(?:'re| are) (put|plac|stack|pil|arrang|lin|mov|sett|lay|build|form|position|align|group)"
                  r"(?:t|e)?ing\b", lambda m: _BASE.get(m.group(1).lower(), m.group(1)), text)
    # "would you mind laying the table?", "how about setting a place ...": the request itself.
    text = re.sub(r"(?i)\b(mind|about|try|consider) (put|plac|stack|pil|arrang|lin|mov|sett|lay|build|form|position|align|"
                  r"group|mak|gett|bring|shift|slid|organis|organiz|gather|sort)(?:t|e)?ing\b",
                  lambda m: f"{m.group(1)} {_BASE.get(m.group(2).lower(), m.group(2))}", text)
    text = re.sub(r"(?i)\b(everything|anything|all|things|objects) what\b", r"\1 that", text)
    text = re.sub(r"(?i)(^|[,.;:!?]\s*)do (them|it|those|these|the [a-z]+)\b(?= (?:in|into|as|like) )", r"\1put \2", text)
    # "in that order from the bottom": the list before it is bottom first.
    text = re.sub(r"(?i),?\s*\bin (?:that|this|the same) order,? (?:starting )?from the (bottom|top)(?: up| down)?\b",
                  lambda m: ", from bottom to top" if m.group(1).lower() == "bottom" else ", from top to bottom", text)
    # "red bowl down, white bowl up, blue bowl between": a stack's roles by one word each.
    text = re.sub(r"(?i)(^|[,:;]\s*|\band )((?:the )?(?:(?!the\b)[a-z]+ ){0,2}(?!the\b)[a-z]+) (down|up|between)(?=\s*(?:[,;.]|and\b|$))",
                  lambda m: m.group(0) if re.match(r"(?i)(?:pile|stack|line|set|put|place|move|make|build|pick|lift|"
                                                   r"hold|turn|fill|heap|them|it)\b", m.group(2))
                  or re.search(r"(?i)\b[a-z]{3,}(?:ed|ing)\b", m.group(2))
                  or re.search(r"(?i)\b(?:pile|stack|line|set|put|place|move|make|build|lift|pick|them|it|those|these|"
                               r"they)\b", m.group(2))
                  or not re.search(r"(?i)\b(?:red|green|blue|yellow|purple|white|black|orange|pink|brown|gray|grey|"
                                   r"silver|one)\b", m.group(2)) else
                  m.group(1) + m.group(2) + {"down": " at the bottom", "up": " on the top",
                                              "between": " in between"}[m.group(3).lower()], text)
    # "can" as a verb ("where I can see them", "the other two can go in between"): not the object.
    text = re.sub(r"(?i)\b(i|you|we|they|he|she) can\b", r"\1 could", text)
    text = re.sub(r"(?i)\b([a-z]+ )?can (go|be|sit|stay|see|find|reach|get|have|do|come|end|stand|rest|lie)\b",
                  lambda m: m.group(0) if (m.group(1) or "").strip().lower() in _NOUN_BEFORE
                  else f"{m.group(1) or ''}could {m.group(2)}", text)
    # "where I can see them", "so I can count them": a reason, asking for nothing.
    text = re.sub(r"(?i),?\s*\b(?:where|so that|so) (?:i|you|we|they|he|she) (?:can|could) (?:easily )?"
                  r"(?:see|reach|find|get to|grab|count|use|spot|read) (?:it|them|those|these)\b", "", text)
    # "all six of them", "both of them" after the objects: a restatement.
    text = re.sub(r"(?i),\s*(?:(?:uh|um|like),?\s*)*(?:all|both)(?: [a-z0-9]+)? of (?:them|it)\b(?=\s*(?:[,.;!?]|$))", "",
                  text)
    text = re.sub(r"(?i)\bevery single\b", "every", text)
    text = re.sub(r"(?i)\b([a-z]+)'s (sitting|standing|resting|lying|placed|going|ending|ended|sat|stood)\b", r"\1 is \2",
                  text)
    # "drop the cup into the bowl", "the white bowl sitting in the black bowl": one inside the other, a stack.
    text = re.sub(r"(?i)\b(?:(sitting|nested|nesting|resting|tucked|placed|set) )?(?:into|inside(?: of)?|(?<=sitting )in|"
                  r"(?<=nested )in|(?<=resting )in|(?<=tucked )in)\s+(?=(?:the|it)\b(?! (?:middle|centre|center|corner|front|"
                  r"back|left|right|top|bottom|row|line|circle|ring|stack|pile|rectangle|square)\b))",
                  lambda m: (m.group(1) + " " if m.group(1) else "") + "on ", text)
    # Spoken fillers between commas; "would ya" at the end.
    text = re.sub(r"(?i),\s*(?:like|you know|i guess|basically|yeah)\s*,", ",", text)
    text = re.sub(r"(?i),?\s*\b(?:would|will|could) (?:ya|you)\b(?=\s*(?:[,.;!?]|$))", "", text)
    # "..., and the blocks too(, but separately)": the same again for other objects.
    text = re.sub(r"(?i)([^.;!?]*?),?\s*\band (the (?:[a-z]+ ){0,3}?[a-z]+) (?:too|as well)(?:,? but (?:separately|on their own|"
                  r"apart))?\b", lambda m: f"{m.group(1)}. the same for {m.group(2)}" if _ASKS.search(m.group(1))
                  else m.group(0), text)
    # "the orange one and the yellow one, blocks I mean": the noun of the "one"s said after them.
    def _noun_after(m: re.Match) -> str:
        noun = m.group(2)[:-1] if m.group(2).lower().endswith("s") else m.group(2)
        return re.sub(r"(?i)\bone\b", noun, m.group(1)) + ","
    text = re.sub(r"(?i)((?:\bthe [a-z]+ one(?:,? and |, )?){2,}),\s*([a-z]+) i mean\s*,", _noun_after, text)
    # "a rectangle, a big one": the size of that arrangement.
    text = re.sub(r"(?i)\b(a|an) (rectangle|circle|line|row|ring|loop|square|tower|stack|pile),?\s*(?:uh,?\s*|um,?\s*)?"
                  r"(?:a|an) (big|large|small|little|medium|medium-sized|short|long|wide|tall|huge|tiny) one\b",
                  r"a \3 \2", text)
    # "the blocks that are, like, red or orange": the filler gone, the comma too.
    text = re.sub(r"(?i)\b(that|which|who) (are|is)\s*,\s*", r"\1 \2 ", text)
    text = re.sub(r"(?i)\b(make|put|do|stack|arrange|set|get) like\b", r"\1", text)
    # "as for the red mug: ...", "regarding the knife, ...": the topic of what follows.
    text = re.sub(r"(?i)\b(?:as for|regarding|about|concerning|with regard to|as to) (the (?:[a-z]+ ){0,3}?[a-z]+)\s*[:,]",
                  r"\1,", text)
    # "..., like right on top of it": a restatement of what the sentence already asks.
    text = re.sub(r"(?i)([^.;!?]*?)(,\s*(?:so |and )?(?:like|yeah|you know|i mean|basically)\b[^,.;!?]*)",
                  _like_restated, text)
    # "the plate with the bowl on it": the bowl on the plate; ", with the cup sitting on the plate": and the
    # cup on the plate.
    text = re.sub(r"(?i)\b(the (?:[a-z]+ ){0,2}?[a-z]+) with (the (?:[a-z]+ ){0,2}?[a-z]+) (?:sitting |resting |standing )?"
                  r"(?:on top of it|on it|on top)\b", r"\2 on \1", text)
    text = re.sub(r"(?i),\s*with (the (?:[a-z]+ ){0,2}?[a-z]+) (?:sitting|standing|resting|placed|lying|set|perched|nested) "
                  r"(on|under|underneath|below|beneath|above|behind|in front of|to the)\b", r", and \1 \2", text)
    # "the blue bowl's the base", "the white one's on top": "is", not a possessive.
    text = re.sub(r"(?i)\b([a-z]+)'s (?:the )?(base|bottom|foundation)\b", r"\1 at the bottom", text)
    text = re.sub(r"(?i)\b([a-z]+)'s (?:the top|on top|at the top|the cap)\b", r"\1 on top", text)
    # Sizes said in everyday words: "nice and wide", "small and tight", "spread out".
    text = _size_words(text)
    # "over on the left": on the left side of the table.
    text = re.sub(r"(?i)\bover (?:on|to) the (left|right)\b(?! of)", r"on the \1 side of the table", text)
    # "the orange cup with the red can to its left", "the letter E has the blue block behind it": the
    # second object placed relative to the first.
    def _has_rel(m: re.Match) -> str:
        rel = m.group(3).lower()
        rel = {"on its left": "to the left of", "on its right": "to the right of", "to its left": "to the left of",
               "to its right": "to the right of", "behind it": "behind", "in front of it": "in front of",
               "on top of it": "on top of", "on it": "on", "under it": "under", "below it": "below"}[rel]
        return f"{m.group(2)} {rel} {m.group(1)}"
    text = re.sub(r"(?i)\b(the (?:[a-z]+ ){0,2}?[a-z]+) (?:has|have|with|should have) (the (?:[a-z]+ ){0,2}?[a-z]+) "
                  r"(?:directly |sitting |standing |just |right |placed |resting )?(on its left|on its right|to its left|"
                  r"to its right|behind it|in front of it|on top of it|on it|under it|below it)\b", _has_rel, text)
    # ", with the green bowl on top of the blue bowl": and the green bowl on top of it.
    text = re.sub(r"(?i),\s*with (the (?:[a-z]+ ){0,2}?[a-z]+) (on top of|on|under|underneath|below|beneath|behind|"
                  r"in front of|to the left of|to the right of)\s+(?=the\b)",
                  lambda m: m.group(0) if m.group(2).lower() in ("on top of", "on", "under", "underneath", "below", "beneath")
                  and re.search(r"(?i)\b(?:stack|pile|tower)\b", m.string[: m.start()].split(".")[-1])
                  else f", and {m.group(1)} {m.group(2)} ", text)
    # "put the tiger pan down as the base", "where the green can is the base": the bottom of the stack.
    text = re.sub(r"(?i)\bdown (as (?:the|a) (?:base|bottom layer|bottom|foundation))\b", r"\1", text)
    text = re.sub(r"(?i)\bis the (base|foundation|bottom layer)\b", r"as the \1", text)
    # "the highest", "topmost": stack roles.
    text = re.sub(r"(?i)\b(?:is|are) the (highest|lowest|top one|bottom one)\b", lambda m: m.group(1).split()[0]
                  .replace("top", "highest").replace("bottom", "lowest"), text)
    text = re.sub(r"(?i)\b(topmost|uppermost)\b", "highest", text)
    text = re.sub(r"(?i)\b(bottommost|undermost|lowermost)\b", "lowest", text)
    # "the mug is to be supported by the plate": on it; "whatever's blue": everything that is.
    text = re.sub(r"(?i)\b(?:supported|held up|carried|borne) by\b", "on", text)
    text = re.sub(r"(?i)\bwhatever(?:'s| is)\b", "everything that is", text)
    # "only the spoon, not the fork, goes behind": the fork is named only to be left out.
    # "the bowls, but not the white one, ...": an exception from the group before.
    text = re.sub(r"(?i),\s*(?:but |and )?not (the|a|an) ((?:[a-z]+ ){0,2}?[a-z]+)\s*,",
                  lambda m: f" except the {m.group(2)}," if re.search(r"(?i)\b(?:the|all|all the|every) (?:[a-z]+ )?[a-z]+s\s*$",
                                                                     m.string[: m.start()])
                  and re.search(r"(?i)\bones?$", m.group(2)) else ",", text)
    # "circle them up", "ring those": the shape's name as the verb.
    text = re.sub(r"(?i)\b(circle|ring|loop)\s+(them|those|these|it|'em|em)(?:\s+up)?\b",
                  lambda m: f"put {'them' if m.group(2).lower() in ('em', chr(39) + 'em') else m.group(2)} in a circle",
                  text)
    # "the mug's gotta go left of the bottle": goes.
    text = re.sub(r"(?i)\b([a-z]+)(?:'s| has| is) (?:gotta|got to|going to|gonna) (go|sit|end up)\b", r"\1 \2", text)
    # "anything red or blue, cans and bowls alike,": says which kinds the selection spans, adds none.
    text = re.sub(r"(?i),\s*(?:both )?(?:the )?[a-z]+ and (?:the )?[a-z]+ alike\b", "", text)
    # "get the cup onto the bowl": put it there ("get" alone selects).
    text = re.sub(r"(?i)\bget (the (?:[a-z]+ ){0,2}?[a-z]+) (onto|on top of|on|into|in front of|behind|to the left of|"
                  r"to the right of|under|underneath|below|beneath)\b", r"put \1 \2", text)
    # "underneath the green cup I want the blue bowl": the relation put first.
    text = re.sub(r"(?i)^\s*(underneath|under|beneath|below|on top of|behind|in front of|to the left of|to the right of)"
                  r" (the (?:[a-z]+ ){0,2}?[a-z]+),? (?:i want|i'd like|i would like|we need|there should be|put|place|"
                  r"goes|should go) (the (?:[a-z]+ ){0,2}?[a-z]+)\s*([.!]?)\s*$", r"put \3 \1 \2\4", text)
    # "near the front": a place on the table (not "near the bowl").
    text = re.sub(r"(?i)\bnear the (front|back|left|right)(?!(?: edge| side)? of)(?! (?:left|right|center|centre|middle|"
                  r"corner|front|back)\b)(?: edge| side)?\b", r"at the \1 of the table", text)
    # "the very center": the center.
    text = re.sub(r"(?i)\bthe very (centre|center|middle|front|back|edge|end|corner|left|right)\b", r"the \1", text)
    # "..., the mugs stacked, ...": a stack said without a verb.
    text = re.sub(r"(?i)(^|[,;:]\s*|\band )(the (?:[a-z]+ ){0,2}?[a-z]+) (stacked|piled)(?: up)?(?=\s*(?:[,;.]|and\b|$))",
                  r"\1stack \2", text)
    # A spaced dash between two statements: "the box is in the way - move it ...".
    text = re.sub(r"\s+[-\u2013\u2014]+\s+", ". ", text)
    # "everything on the table apart from the plate": "on the table" only says where they are now.
    text = re.sub(r"(?i)\b(everything|all the objects|all objects|all the items|all the things|all items) (?:on|from) "
                  r"the (?:table|tabletop|workspace)\b", r"\1", text)
    # Stack roles said with a verb: "white is lowest", "highest is blue", "after it green".
    text = re.sub(r"(?i)\b(?:is|are|goes|go|sits|sit|comes|come|should be|must be|will be) (lowest|highest|"
                  r"undermost|uppermost|topmost|bottommost)\b", r"\1", text)
    text = re.sub(r"(?i)\b(lowest|highest|uppermost|topmost|bottommost|undermost) (?:is|should be|must be|will be|goes) "
                  r"((?:the )?[a-z]+(?: (?:one|can|block|bowl|cup|mug|letter|plate|bottle))?)(?=\s*(?:[,.;!?]|and\b|$))",
                  r"\2 \1", text)
    text = re.sub(r"(?i)(,\s*|\band )after (?:it|that|this|them)\b,?", r"\1then", text)
    text = re.sub(r"(?i),\s*(?:" + FREE_ORDER.pattern + r"|i(?:'m| am) not fussy about the order)\s*(?=[,.;!?]|$)",
                  "", text)
    # "stacked in an arbitrary order", "(order immaterial)": the order is left open.
    text = re.sub(r"(?i)\s*\b(?:in|with|using) (?:any|whatever|random|an arbitrary|arbitrary|no particular|any old|"
                  r"no specific|no set|no fixed|an unspecified|unspecified) (?:order|sequence)\b", "", text)
    text = re.sub(r"(?i)\s*\((?:the )?(?:order|sequence) (?:is )?(?:immaterial|irrelevant|arbitrary|unimportant|free|"
                  r"open|not important|does not matter|doesn't matter|up to you)\)", "", text)
    after = r"(?i)\bone (?:after|behind|beside|next to) (?:the other|another)\b"
    text = re.sub(after, "" if re.search(r"(?i)\b(row|line|file|queue)\b", text) else "in a line", text)
    # "right in front of", "right behind the box": "right" says "directly" ("right behind of" stays a diagonal).
    text = re.sub(r"(?i)\b(?:right|directly|just|immediately|straight) (in front of|behind(?! of)|above|below|under|"
                  r"underneath|beneath|on top of|next to|beside)\b", r"\1", text)
    # ", not in front of it" after a relation: a contrast that adds nothing.
    text = re.sub(r"(?i),\s*(?:but |and )?not (?:in front of|behind|to the left of|to the right of|left of|right of|"
                  r"on top of|on|under|below|above)\b[^,;.!?]*", "", text)
    # Reasons and how-to remarks ask for nothing: "..., because the bowl keeps dripping", "make it so".
    text = re.sub(r"(?i)^\s*(?:because|since|as) [^.;:!?,]*[:,]\s*", "", text)  # "Since I'm about to eat: ..."
    text = re.sub(r"(?i),?\s*\b(?:because|since|'cause|cause|as i|so i can|so that i can)\b[^.;:!?]*", "", text)
    text = re.sub(r"(?i)\b(?:make it so|get there by [^.;!?]*|(?:,\s*)?so move it there|move it there|"
                  r"(?:to )?make that happen)\b", "", text)
    text = re.sub(r"(?i)\b(its|their) (?:new )?(?:spot|place|position|location|home) (should be|is|will be|must be)\b",
                  lambda m: ("it " if m.group(1).lower() == "its" else "they ") + m.group(2), text)
    # "starting with the green block, ..., finishing with the blue one": the bottom and the top.
    text = re.sub(r"(?i)\b(?:starting|beginning) with (the (?:[a-z]+ ){0,3}?[a-z]+)(?= *(?:,|;|then\b|and\b|$))",
                  r"\1 at the bottom", text)
    # "pile up the blocks starting with yellow, then green": a bare colour the same way.
    text = re.sub(r"(?i),?\s*\b(?:starting|beginning) with (red|green|blue|yellow|purple|white|black|orange|pink|brown|"
                  r"gr[ae]y|silver)(?= *(?:,|;|then\b|and\b))", r", \1 at the bottom", text)
    text = re.sub(r"(?i)\b(?:finishing|ending|topping it off|finishing off) with (the (?:[a-z]+ ){0,3}?[a-z]+?)"
                  r"(?: at the top| on top| on the top)?(?= *(?:[,.;!?]|$))", r"\1 on top", text)
    # "A on B, which itself sits on C" -> "A on B, and B on C".
    text = re.sub(r"(?i)\b(the (?:[a-z]+ ){0,3}?[a-z]+),? (?:which|that) (?:itself |in turn )?(?:sits|is|rests|stands|goes|"
                  r"should sit|should be) (on top of|on|above|under|below|beneath)\b", r"\1, and \1 \2", text)
    text = re.sub(r"(?i)\ba pair of\b", "two of", text)
    text = re.sub(r"(?i)[,;]?\s*\bi (?:don't|do not|won't) (?:mind|care) which(?: one| ones| two| three| four)?\b", "", text)
    text = re.sub(r"(?i),\s*(?:both|all|each) of them\b", "", text)
    # Numbered steps: "1. put ...", "2) line up ..." (a step number is no size).
    text = re.sub(r"(?i)(?:^|(?<=[\s:;,.]))(?:step )?\d{1,2}\s*[.)]\s+(?=[a-z])", "; ", text)
    text = re.sub(r"(?i)\b(?:two|three|four|five|\d) steps\s*:", "", text)
    text = re.sub(r"(?i)\bdo (?=(?:put|place|move|set|stack|line|arrange|make|build|pile)\b)", "", text)
    text = re.sub(r"(?i)\bthat (?:match|matches) the colou?r of\b", "with the same colour as", text)
    text = re.sub(r"(?i)\beither (?!of\b)(?=[a-z]+\b)", "one ", text)
    text = re.sub(r"(?i)\b(?:turned|rotated|oriented|orientated) to face\b", "facing", text)
    text = re.sub(r"(?i)\bspread[- ]out\b", "wide", text)
    text = re.sub(r"(?i)\bover (on|in|at|by|to|towards)\b", r"\1", text)
    text = re.sub(r"(?i)\b(left|right)[- ]hand(?: side)?\b", r"\1 side", text)
    text = re.sub(r"(?i),\s*(?:resting|sitting|standing|lying) (?:on|upon|on top of) (?:it|them)\b", "", text)
    text = _corrected(_repairs(_remade(_purposes(_restatements(_HEADING.sub(r"\1", text))))), relations_only=True)
    # "in a small circle, no wait, a medium one": the corrected size.
    text = re.sub(r"(?i)\b(a|an) (?:small|medium|large|big|little|tiny|huge|wide|tight|short|long)(?:[- ]sized)? ([a-z]+)"
                  r"\s*,\s*no wait,\s*(?:a|an) (small|medium|large|big|little|tiny|huge|wide|tight|short|long)"
                  r"(?:[- ]sized)? (?:one|\2)\b", r"a \3 \2", text)
    # "out of the bowls, no wait, out of the mugs": the second object for the same role.
    text = re.sub(r"(?i)\b(out of|on top of|on|onto|in|into|to|at|behind|under|underneath|with|from|of|beside|next to) "
                  r"the [a-z ]+?\s*,\s*no wait,\s*(?=\1 the\b)", "", text)
    # Repairs inside a reference: "on the blue no wait the red bowl" -> "on the red bowl".
    # A whole request taken back: "set the table, actually no, just put the bowl on the plate", "put the
    # white things in a circle, no wait, the blue things in a circle".
    text = re.sub(r"(?i)(^|[.;!?]\s*|,\s*(?:and |then )?)([^,.;!?]*?)\s*,\s*(?:no wait|wait no|no sorry|sorry no|"
                  r"actually no|no actually|no no|scratch that|forget that|never mind that|no)[,!.]?\s*"
                  r"(?:(?:um|uh|actually|wait|sorry)[,\s]*)*(?=(?:the|put|place|move|stack|set|make|arrange|line|build|"
                  r"just|instead)\b)",
                  lambda m: m.group(1) if _ASKS.search(m.group(2)) or re.search(
                      r"(?i)\b(?:table|dinner|setting|place)\b", m.group(2)) else m.group(0), text)
    text = re.sub(r"(?i)^\s*(?:just|instead)\s+", "", text)
    # A correction in a sentence of its own ("... under the red one. Wait, sorry, the blue one."): the
    # same as one after a comma.
    text = re.sub(r"(?i)[.!?]\s+(?:(?:no|wait|sorry|actually|oops|i mean|i meant)\b[,!.]?\s*)+"
                  r"(?!(?:put|place|move|stack|set|make|arrange|line|build|and|then|also|plus|swap|switch|exchange|"
                  r"reverse|flip|turn)\b)", ", no wait, ", text)
    repair = r"(?:no wait|wait no|no|sorry|i mean|i meant)"
    text = re.sub(rf"(?i)\bthe(?:\s+[a-z]+){{1,3}}?\s+{repair}\s+(?=the\b)", "", text)
    # The same with commas: "the red bowl, no sorry, the blue bowl", "the cups, no wait, um, the bowls".
    said = r"(?:(?:no|oh|wait|sorry|actually|i mean|i meant|or rather|scratch that|make that|rather)[,.!]?\s*){1,3}"
    text = re.sub(rf"(?i)\bthe(?:\s+[a-z]+){{1,3}}?\s*,\s*{said},?\s*(?:(?:um|uh|er|erm)\s*,?\s*)*(?=the\b)", "",
                  text)
    text = re.sub(rf"(?i)\b(?:on|onto|in|to|at|behind|under|underneath)(?:\s+the)?\s+{repair}\s+"
                  rf"(?=(?:on|onto|in|to|at|behind|under|underneath)\b)", "", text)
    text = re.sub(r"(?i)\b(?:it )?(?:does not|doesn't|does n't) matter which(?: one| way(?: round| around| up)?| [a-z]+)?(?: goes where| goes on top)?\b|"
                  r"\bwhichever(?: one)?(?:\s*[.!?]*\s*$)", "", text)
    text = re.sub(r"(?i)\b(?:out|up) front\b", "at the front of the table", text)
    text = re.sub(r"(?i)\balong the (back|front|left|right)\b(?! of| left| right| center| centre| middle| back| front| side|"
                  r" edge| corner| half)", r"along the \1 of the table", text)
    text = re.sub(r"(?i)\b(?:before|after|when|once|until) (?:the kids|you|we|i|they|he|she|my [a-z]+|our [a-z]+) "
                  r"(?:get|gets|come|comes|arrive|arrives|leave|leaves|are|is|go|goes|wake|wakes)\b[^,;.!?]*", "", text)
    text = re.sub(r"(?i),\s*on the (?:side|end) (?:closest|nearest|nearer|closer) to (?:me|us|you|the viewer)\b", "", text)
    # A corrected list item: ", orange on the bottom, no actually yellow on the bottom".
    text = re.sub(r"(?i),\s*+(?!no\b|wait\b|sorry\b)[^,;.!?]+?,\s*(?:no,?\s*)?(?:wait|sorry|actually|i mean|make that)\b,?\s*",
                  ", ", text)
    # "the white can should end up with the yellow cup sitting on it" -> "the yellow cup on the white can"
    text = re.sub(r"(?i)\b(the (?:[a-z]+ ){0,3}?[a-z]+) (?:should |must |will )?(?:end up|be left|be) with "
                  r"(the (?:[a-z]+ ){0,3}?[a-z]+) (?:sitting|resting|standing|placed|stacked|lying) (on top of|on|upon) "
                  r"(?:it|them)\b", r"\2 \3 \1", text)
    text = re.sub(r"(?i),?\s*(?:and |but )?leave (?:the [a-z ,]+?|them|it) alone\b", "", text)
    text = _corrected(text)
    text = _NOT_THE_OTHER.sub(lambda m: m.group(0) if re.search(r"(?i)\bbut\s*,?\s*$", text[: m.start()])
                              else "", text)
    text = re.sub(r"(?i)\bright (in|at|on) the (centre|center|middle|front|back|edge)\b", r"\1 the \2", text)
    text = _relation_words(text)
    text = re.sub(r"(?i)\b(the|a) ((?:[a-z]+ ){0,3}?[a-z]+)'s (colou?r|shape)\b", r"the same \3 as \1 \2", text)
    text = re.sub(r"(?i)\b(?:(?:that|which) (?:match|matches|share|shares)|matching|sharing) (?:the )?same (colou?r|shape) as\b",
                  r"with the same \1 as", text)
    text = re.sub(r"(?i)\b(?:(?:that|which) (?:shares?|has|have)|sharing|having) (?:a|the|its|their) (colou?r|shape) with\b",
                  r"with the same \1 as", text)
    text = re.sub(r"(?i)\b(?:the )?table(?:'s)? (centre|center|middle|left|right|front|back)( side| edge| half| corner)?\b",
                  r"the \1\2 of the table", text)
    text = re.sub(r"(?i)\b(?:reading |going |listed |counting )?(?:from )?(?:the )?top (?:down|downwards)\b",
                  "from top to bottom", text)
    return re.sub(r"(?i)\b(?:reading |going |listed |counting )?(?:from )?(?:the )?bottom (?:up|upwards)\b",
                  "from bottom to top", text)


def _relation_words(text: str) -> str:
    """Directions said with compass points, near and far, "diagonally" or a
    second side given by "its" rewritten as the relation phrases of the
    pattern keys ("west of" -> "left of", "south-east of" -> "front right
    of", "further back than" -> "behind", "behind the cup and to its right"
    -> "behind and to the right of the cup")."""

    def compass(m: re.Match) -> str:
        a, b = _COMPASS[m.group(1).lower()], m.group(2)
        if b is None:
            return {"back": "behind", "front": "in front of", "right": "to the right of", "left": "to the left of"}[a]
        return f"{a} {_COMPASS[b.lower()]} of"

    text = _ANY_OF.sub("one of the", text)
    text = _COMPASS_REL.sub(compass, text)
    for pat, rep in _NEAR_FAR:
        text = pat.sub(rep, text)

    def side(m: re.Match) -> str:
        rel, anchor = m.group(1).lower(), m.group(2)
        s2 = next(g for g in m.groups()[2:] if g).lower()
        s2 = {"behind": "back", "in front of": "front"}.get(s2, s2)
        first = {"in front of": "front", "behind": "back"}.get(rel, rel.replace("to the ", "").replace(" of", ""))
        if {first, s2} in ({"left", "right"}, {"front", "back"}) or first == s2 or (
                first in ("front", "back") and s2 in ("front", "back")):
            return m.group(0)  # "left of it and also right of it": a contradiction, read (and refused) as said
        return f"{first} {s2} of {anchor}"

    return _AND_ITS_SIDE.sub(side, text)
