"""Replacement functions of the rows of ``data/rewrites.toml`` for the words of a trade or of a speaker's own
English, which say a place, a side or a reference in other words than the viewer's.

* a stage's directions (the viewer is the audience: "stage left" is the viewer's right, "upstage" the back);
* a programmer's axes, counts and filters ("facing +y", "w/ 4in spacing", "blocks where color != red");
* a Spanish speaker's comparisons, corners and levels ("from up to down", "the corner of behind at the left",
  "below of all", "of 40 cm of diameter", "at the side of");
* a child's colour names said by things everybody knows ("the sky block");
* names a mathematician gives first ("Call the red block A ...", "Let S be ...");
* a sailor's sides, the viewer at the helm (port the left, for'ard the back: one table, ``_NAUTICAL``), and the
  words of other speakers of this and the later rounds ("the most right block", digits read one by one).

Each function is registered with :func:`.normalise.replacer` under the name its row gives in ``fn``; the rows,
with their examples, say what each reads. Importing :mod:`.rewrite` imports this module.
"""

from __future__ import annotations

import re

from . import lexicon
from .compass import _DIGITS, _hour, heading_facing
from .normalise import replacer
from .places import _EDGES
from .vocabulary import _plural

#: A trade's words the rows read that are no words of the English vocabulary, so that the spelling stage
#: knows them ("upstgae", "dwnstage", "abaem").
TRADE_WORDS = frozenset({"upstage", "downstage", "midstage", "centerstage", "centrestage", "offstage", "abeam",
                         "astern", "starboard", "amidships", "aftmost", "masthead"})

#: Verbs after which a side or a stage direction is a facing ("facing stage left", "pointed house left").
_FACING_VERBS = ("facing", "pointing", "pointed", "points", "turned", "face", "faces", "aimed")


def _after_facing(m: re.Match[str]) -> bool:
    """Whether the words just before ``m`` are a verb of facing."""
    return m.string[: m.start()].rstrip().lower().endswith(_FACING_VERBS)


#: Things of the world that, said before an object's noun, say what it holds or is for, not its colour ("the coffee
#: mug", "the milk bottle").
_CONTENTS = frozenset({"coffee", "milk", "chocolate", "soil", "egg", "tea"})


@replacer("world-colour-said-before")
def _world_colour_before(m: re.Match[str]) -> str:
    """"the sky block", "the froggy bowl", "the strawberry one": a thing of the world said before an object's
    noun is its colour (lexicon ``[world_colours]``); any other word, and a content ("the coffee mug"), is left as
    it is."""
    thing = m.group(2).lower()
    colour = None if thing in _CONTENTS else lexicon.WORLD_COLOURS.get(thing)
    return m.group(0) if colour is None else f"{m.group(1)} {colour} "


@replacer("names-given")
def _names_given(m: re.Match[str]) -> str:
    """"Call the red block A and the blue block B. Place A to the left of B.", "Let S be the set of all blocks.
    Make S collinear.": the sentence that gives the names goes, and each name said after it is what it names."""
    names: dict[str, str] = {}
    if m.group("let") is not None:
        said = m.group("what").strip()
        for lead in ("the set of ", "the collection of ", "the group of "):
            if said.lower().startswith(lead):
                said = said[len(lead):]
        names[m.group("let")] = said.split(", the ")[0] if said.endswith(" itself included") else said
    else:
        for part in (m.group("first") + m.group("more")).replace(", and ", " and ").split(" and "):
            part = part.strip(" ,")
            part = part[5:] if part.lower().startswith("call ") else part
            np, _, name = part.rpartition(" ")
            if np and name:
                names[name] = np
    out = []
    for tok in m.group("rest").split(" "):
        core = tok.strip(".,;:!?()")
        out.append(tok.replace(core, names[core], 1) if core in names else tok)
    return " ".join(out)


#: The viewer's side for a stage side: the audience (the viewer) faces the actors, so stage left is the viewer's
#: right; house left is the audience's own left.
_STAGE_SIDE = {("stage", "left"): "right", ("stage", "right"): "left", ("house", "left"): "left",
               ("house", "right"): "right"}


def _up(m: re.Match[str], group: int = 1) -> bool:
    """Whether the "up" / "down" captured in ``group`` is "up" ("upstage": the back; "from up to down")."""
    return (m.group(group) or "").lower() == "up"


def _stage_side(m: re.Match[str]) -> str:
    """The viewer's side said by a stage side in ``m`` ("stage left": right)."""
    said = m.group(0).lower().replace("-", " ").split()
    kind = "house" if "house" in said else "stage"
    return _STAGE_SIDE[kind, "left" if "left" in said else "right"]


@replacer("stage-corner")
def _stage_corner(m: re.Match[str]) -> str:
    """"upstage right": in the back left corner."""
    return f"in the {'back' if _up(m) else 'front'} {_stage_side(m)} corner"


@replacer("stage-diagonal-of")
def _stage_diagonal_of(m: re.Match[str]) -> str:
    """"upstage left of": behind and to the right of."""
    return f"{'behind' if _up(m) else 'in front of'} and to the {_stage_side(m)} of"


@replacer("stage-side-of")
def _stage_side_of(m: re.Match[str]) -> str:
    """"stage left of": to the right of."""
    return f"to the {_stage_side(m)} of"


@replacer("stage-side")
def _stage_side_bare(m: re.Match[str]) -> str:
    """"stage left": on the right ("facing stage left": facing right)."""
    return _stage_side(m) if _after_facing(m) else f"on the {_stage_side(m)}"


@replacer("up-down-stage-of")
def _up_down_stage_of(m: re.Match[str]) -> str:
    """"upstage of": behind; "downstage of": in front of."""
    return "behind" if _up(m) else "in front of"


@replacer("centre-stage")
def _centre_stage(m: re.Match[str]) -> str:
    """"centre stage": in the middle of the table; "down centre": at the front centre; "midstage": in the middle
    row."""
    if m.group(1):
        return "in the middle of the table"
    if m.group(2):
        return f"at the {'back' if _up(m, 2) else 'front'} centre"
    return "in the middle row"


@replacer("stage-furthest")
def _stage_furthest(m: re.Match[str]) -> str:
    """"furthest downstage": nearest the front; "furthest upstage": furthest back; "furthest stage left": furthest
    to the right."""
    if m.group(1):
        return "furthest back" if _up(m) else "nearest the front"
    return f"furthest to the {_stage_side(m)}"


@replacer("in-from-stage-side")
def _in_from_stage_side(m: re.Match[str]) -> str:
    """"second can in from house left": second can from the left."""
    return f"{m.group(1)} {m.group(2)}from the {_stage_side(m)}"


@replacer("against-the-wall")
def _against_the_wall(m: re.Match[str]) -> str:
    """"against the back wall": at the back, or nothing after a place said already ("along the back edge")."""
    back = m.group(1).lower() in ("back", "far")
    before = m.string[: m.start()].lower()
    said = ("the back" in before or "the far" in before) if back else ("the front" in before or "the near" in before)
    return "" if said else f" at the {'back' if back else 'front'}"


#: Headings of the table's axes: +y is away from the viewer.
_AXIS_HEADING = {("+", "y"): "north", ("-", "y"): "south", ("+", "x"): "east", ("-", "x"): "west"}


@replacer("axis-heading")
def _axis_heading(m: re.Match[str]) -> str:
    """"facing +y": facing north."""
    return f"{m.group(1)} {_AXIS_HEADING[m.group(2), m.group(3).lower()]}"


@replacer("the-corner-of-behind")
def _the_corner_of_behind(m: re.Match[str]) -> str:
    """"the corner of behind at the left": the back left corner; "of the right, the one in front": the front right;
    "more near to me, the right one": the near right."""
    if m.group(1):
        return f"the back {m.group(1)} corner"
    if m.group(2):
        return f"the front {m.group(2)} corner"
    return f"the near {m.group(3)} corner"


@replacer("below-of-all")
def _below_of_all(m: re.Match[str]) -> str:
    """"below of all": at the bottom; "above of all", "in the top": on top; "in the bottom": at the bottom."""
    low = m.group(1) is not None or (m.group(2) or "").lower() == "bottom"
    return "at the bottom" if low else "on top"


@replacer("from-up-to-down")
def _from_up_to_down(m: re.Match[str]) -> str:
    """"from up to down": from top to bottom."""
    return "from top to bottom" if _up(m) else "from bottom to top"


@replacer("n-in-spacing")
def _n_in_spacing(m: re.Match[str]) -> str:
    """"w/ 4in spacing": 4 inches apart."""
    unit = m.group(2).lower()
    return f"{m.group(1)} {'inches' if unit.startswith('in') else unit} apart"


@replacer("of-diameter")
def _of_diameter(m: re.Match[str]) -> str:
    """"of 40 cm of diameter": 40 cm across; "of 15 cm of radius": with a radius of 15 cm."""
    return f"{m.group(1)} across" if m.group(2).lower() == "diameter" else f"with a radius of {m.group(1)}"


@replacer("at-the-side-of")
def _at_the_side_of(m: re.Match[str]) -> str:
    """"at the side of": next to; "at each side of": on each side of."""
    return "next to" if m.group(1).lower() == "the" else f"on {m.group(1)} side of"


@replacer("where-colour-is-not")
def _where_colour_is_not(m: re.Match[str]) -> str:
    """"blocks where color != red": the blocks that are not red."""
    return f"the {m.group(1)} that are {'not ' if m.group(2) == '!=' else ''}{m.group(3)}"


@replacer("nearest-the-house")
def _nearest_the_house(m: re.Match[str]) -> str:
    """"nearest the house": nearest the front; "most upstage": backmost; "most downstage": frontmost."""
    if m.group(1):
        return f"{m.group(1)} the front"
    return "backmost" if _up(m, 2) else "frontmost"


@replacer("upstage-downstage")
def _upstage_downstage(m: re.Match[str]) -> str:
    """"upstage": at the back ("facing upstage": facing away from me); "downstage": at the front (facing me)."""
    up = _up(m)
    if _after_facing(m):
        return "away from me" if up else "me"
    return "at the back" if up else "at the front"


@replacer("most-right-one")
def _most_right_one(m: re.Match[str]) -> str:
    """"the most right block", "the thing at most left side": the rightmost block, the leftmost thing."""
    noun, side = (m.group(1), m.group(2)) if m.group(1) else (m.group(4), m.group(3))
    return f"{m.group(0)[:3]} {side.lower()}most {noun}"  # "the" or "The", as said


@replacer("digits-read-one-by-one")
def _digits_read_one_by_one(m: re.Match[str]) -> str:
    """"one five" before a unit: 15 (a number read digit by digit, as a heading's digits are)."""
    return "".join(str(_DIGITS[w]) for w in m.group(1).lower().replace("-", " ").split())


@replacer("clock-facing")
def _clock_facing(m: re.Match[str]) -> str:
    """"pointing twelve o'clock": facing north, the heading of the hour (twelve is away from the viewer, three to
    the right); the row reads only the four hours that are a facing."""
    hour = _hour(m.group(2))
    facing = heading_facing(30 * hour) if hour else None
    return f"facing {facing}" if facing else m.group(0)


@replacer("number-singular-noun")
def _number_singular_noun(m: re.Match[str]) -> str:
    """"two can", "all block": the plural ("two cans", "all blocks", "two knives")."""
    return f"{m.group(1)} {_plural(m.group(2))}"


@replacer("anchor-at-the-back")
def _anchor_at_the_back(m: re.Match[str]) -> str:
    """"behind the can at the very back": behind the can furthest back ("at the front": nearest the front)."""
    where = "furthest back" if m.group(3).lower() == "back" else "nearest the front"
    return f"{m.group(1)} the {m.group(2)} {where}"


@replacer("o-apostrophe-of")
def _o_apostrophe_of(m: re.Match[str]) -> str:
    """"o'" and "o" before "the": of; "an'": and."""
    return "and" if (m.group(1) or "").lower() == "an" else "of" if m.group(1) else "of "


#: A boat's words for the table's sides, the viewer at the helm looking toward the back: port is the viewer's left,
#: the bow (for'ard) the back of the table, the stern (aft) the front.
_NAUTICAL = {"port": "left", "starboard": "right", "for'ard": "back", "forard": "back", "bow": "back", "fore": "back",
             "aft": "front", "abaft": "front", "stern": "front", "astern": "front"}


def _sea(word: str) -> str:
    """The table's side a boat's word says ("port": left, "for'ard": back)."""
    return _NAUTICAL[word.lower().replace("\u2019", "'")]


@replacer("port-starboard")
def _port_starboard(m: re.Match[str]) -> str:
    """"port" -> "left", "starboard" -> "right" (the word alone, after the rows that read it with its object)."""
    return _sea(m.group(1))


@replacer("nautical-corner")
def _nautical_corner(m: re.Match[str]) -> str:
    """"the for'ard port corner": the back left corner."""
    a, b = _sea(m.group(1)), _sea(m.group(2))
    fore_aft, side = (a, b) if a in ("back", "front") else (b, a)
    return f"the {fore_aft} {side} corner"


@replacer("nautical-off-the-bow")
def _nautical_off_the_bow(m: re.Match[str]) -> str:
    """"off the port bow of": behind and to the left of; "off the starboard quarter of": in front of and to the
    right of."""
    fore = "behind" if m.group(2).lower() == "bow" else "in front of"
    return f"{fore} and to the {_sea(m.group(1))} of"


@replacer("nautical-side-of")
def _nautical_side_of(m: re.Match[str]) -> str:
    """"to port of", "on the starboard side of": to the left (right) of; "for'ard of": behind; "astern of": in front
    of."""
    side = _sea(m.group(1))
    return {"back": "behind", "front": "in front of"}.get(side, f"to the {side} of")


@replacer("nautical-facing")
def _nautical_facing(m: re.Match[str]) -> str:
    """"pointing for'ard": facing north; "to port": west."""
    return f"facing {_EDGES[_sea(m.group(1))]}"


@replacer("nautical-edge-any")
def _nautical_edge_any(m: re.Match[str]) -> str:
    """"the stern edge of the table", "the bow of the table": the front edge, the back edge."""
    return f"the {_sea(m.group(1) or m.group(2))} edge"


@replacer("nautical-abeam-on-its-side")
def _nautical_abeam(m: re.Match[str]) -> str:
    """"abeam of the white one, on its starboard side": to the right of it."""
    return f"to the {_sea(m.group(2))} of {m.group(1)}"


@replacer("nautical-most")
def _nautical_most(m: re.Match[str]) -> str:
    """"aftmost": frontmost; "furthest for'ard": furthest back; "furthest to starboard": furthest to the right
    ("forward" is left out: said ashore, "the block farthest forward" is the one nearest the viewer)."""
    if m.group(1):
        return "frontmost"
    side = _sea(m.group(3))
    nearest = "nearer" if m.group(2).lower() in ("further", "farther") else "nearest"
    return {"back": f"{m.group(2)} back", "front": f"{nearest} the front"}.get(side, f"{m.group(2)} to the {side}")


@replacer("corner-at-the-back-on-the-left")
def _corner_at_the_back(m: re.Match[str]) -> str:
    """"in the corner at the back, on the left": in the back left corner; "in the right corner, the one in front of
    me": in the front right corner."""
    if m.group(1):
        return f"in the {m.group(1).lower()} {m.group(2).lower()} corner"
    return f"in the front {m.group(3).lower()} corner"


@replacer("from-the-top-to-the-bottom-list")
def _from_the_top_list(m: re.Match[str]) -> str:
    """", from the top to the bottom, red, white, blue": ", from the top down: red, white, blue"."""
    return ", from the top down: " if m.group(1).lower() == "top" else ", from the bottom up: "


@replacer("at-the-summit")
def _at_the_summit(m: re.Match[str]) -> str:
    """"at the summit", "up at the masthead": on top; "down at the keel", "the plate under,": at the bottom."""
    said = m.group(0).lower()
    return " at the bottom" if said == " under" else "at the bottom" if "keel" in said else "on top"


@replacer("must-be-the-base")
def _must_be_the_base(m: re.Match[str]) -> str:
    """"must be the base": at the bottom; "and the purple one the top": and the purple one on top."""
    place = (m.group(1) or m.group(3)).lower()
    said = "on top" if place == "top" else "at the bottom"
    return f"{m.group(2)} {said}" if m.group(2) else said


@replacer("not-the-x-itself")
def _not_the_x_itself(m: re.Match[str]) -> str:
    """"no' the": not the; "itsel'": itself."""
    return "not " if m.group(0).lower().startswith("no") else "itself"


@replacer("fore-and-aft")
def _fore_and_aft(m: re.Match[str]) -> str:
    """"running fore and aft": running from front to back; "end to end" (of a measure): long."""
    return "long" if m.group(0).lower() == "end to end" else "running from front to back"


@replacer("beside-it-by-the-right")
def _beside_it_by_the_right(m: re.Match[str]) -> str:
    """"beside the red mug by the right": to the right of the red mug; "by the left of": to the left of."""
    if m.group(1):
        return f"to the {m.group(2).lower()} of {m.group(1)}"
    return f"to the {m.group(3).lower()} of"
