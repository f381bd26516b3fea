"""Write tests/language/issue9_cases.jsonl: hand-written commands of the eight
kinds of language of issue 9 (pattern words outside the keys, the peers'
selection templates, vertical relations, where/how big, collective and
negated references, pronouns and inverted relations, stack order, casual
register) and refusals. Deterministic; run from the repository root."""

import json
from pathlib import Path


def cyl(r, h):
    return {"type": "cylinder", "radius": r, "height": h}


def box(x, y, z):
    return {"type": "box", "size": [x, y, z]}


def scene(objs):
    out = []
    for k, (name, color, shape) in enumerate(objs):
        x = -0.33 + 0.11 * (k % 7)
        y = -0.22 + 0.11 * (k // 7)
        out.append({"id": k + 1, "name": name, "color": color, "shape": shape, "pose": [round(x, 3), round(y, 3), 0.0], "on": None})
    return {"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}, "objects": out}


KITCHEN = scene([
    ("mug", "red", cyl(0.04, 0.10)),        # 1
    ("mug", "blue", cyl(0.04, 0.09)),       # 2
    ("bowl", "white", cyl(0.07, 0.05)),     # 3
    ("bowl", "green", cyl(0.06, 0.05)),     # 4
    ("plate", "white", cyl(0.11, 0.02)),    # 5
    ("fork", "silver", box(0.02, 0.18, 0.01)),   # 6
    ("knife", "silver", box(0.02, 0.20, 0.01)),  # 7
    ("spoon", "silver", box(0.03, 0.16, 0.01)),  # 8
    ("can", "red", cyl(0.033, 0.12)),       # 9
    ("can", "white", cyl(0.033, 0.12)),     # 10
    ("can", "green", cyl(0.033, 0.12)),     # 11
    ("bottle", "blue", cyl(0.035, 0.22)),   # 12
    ("block", "yellow", box(0.04, 0.04, 0.04)),  # 13
    ("block", "red", box(0.04, 0.04, 0.04)),     # 14
    ("block", "blue", box(0.05, 0.05, 0.05)),    # 15
])

LETTERS = scene([
    ("letter A", "red", box(0.05, 0.05, 0.02)),   # 1
    ("letter B", "blue", box(0.05, 0.05, 0.02)),  # 2
    ("letter E", "red", box(0.05, 0.05, 0.02)),   # 3
    ("letter G", "green", box(0.05, 0.05, 0.02)), # 4
    ("heart", "red", box(0.05, 0.05, 0.02)),      # 5
    ("star", "yellow", box(0.05, 0.05, 0.02)),    # 6
    ("triangle", "blue", box(0.05, 0.05, 0.02)),  # 7
    ("block", "green", box(0.04, 0.04, 0.04)),    # 8
    ("ring", "purple", box(0.05, 0.05, 0.02)),    # 9
    ("flower", "yellow", box(0.05, 0.05, 0.02)),  # 10
])

CASES = []


def case(cat, sc, text, goals=None, refuse=None, disjoint=None):
    c = {"id": f"{cat}-{sum(1 for x in CASES if x['category'] == cat) + 1:03d}", "category": cat, "scene": sc,
         "instruction": text}
    if refuse is not None:
        c["refuse"] = refuse
    else:
        c["expect"] = {"goals": goals}
        if disjoint:
            c["expect"]["disjoint"] = disjoint
    CASES.append(c)


def g(pattern, objects=None, anchor=None, **kw):
    d = {"pattern": pattern}
    if objects is not None:
        d["objects"] = objects
    if anchor is not None:
        d["anchor"] = anchor
    d.update(kw)
    return d


K, L = "kitchen9", "letters9"
CANS, BLOCKS, LET4, CUT = [9, 10, 11], [13, 14, 15], [1, 2, 3, 4], [6, 7, 8]

# 1. pattern words outside the keys
case("pattern_words", K, "Put all the cans in single file", [g("line", CANS)])
case("pattern_words", K, "queue the cans up", [g("line", CANS)])
case("pattern_words", K, "Arrange the blocks in a loop", [g("circle", BLOCKS)])
case("pattern_words", K, "Formulate all cans into a line", [g("line", CANS)])
case("pattern_words", L, "Put the four letters on the perimeter of a square", [g("rectangle", LET4)])
case("pattern_words", L, "Put one letter at each corner of a square", [g("rectangle", LET4)])
case("pattern_words", K, "set the blocks out in a straight row", [g("line", BLOCKS)])
case("pattern_words", K, "arrange the cans in a round formation", [g("circle", CANS)])
case("pattern_words", K, "place the cans one after another in a straight path", [g("line", CANS)])
case("pattern_words", L, "put the letters at the four corners of a rectangle", [g("rectangle", LET4)])

# 2. the peers' selection templates (LGMCTS-D: the reference is in a "same" set)
case("peer_selection", L, "Put objects whose color is equal to letter A in a circle pattern", [g("circle", [1, 3, 5])])
case("peer_selection", L, "Place objects whose color is same as heart at a line pattern", [g("line", [1, 3, 5])])
case("peer_selection", L, "Leave objects whose color is identical to star on a line pattern", [g("line", [6, 10])])
case("peer_selection", L, "Put objects whose color is alike triangle in a line pattern", [g("line", [2, 7])])
case("peer_selection", L, "Put a line pattern using objects whose color is equivalent to letter G", [g("line", [4, 8])])
case("peer_selection", L, "Select objects whose color is different from letter A, and put them in a circle pattern",
     [g("circle", [2, 4, 6, 7, 8, 9, 10])])
case("peer_selection", L, "Place objects whose color is not the same as heart in a line pattern", [g("line", [2, 4, 6, 7, 8, 9, 10])])
case("peer_selection", L, "Select objects with the same color as letter B, and place them on a line pattern", [g("line", [2, 7])])
case("peer_selection", L, "Put objects whose color is not equal to star in a circle pattern", [g("circle", [1, 2, 3, 4, 5, 7, 8, 9])])
case("peer_selection", L, "Leave objects whose color is different with the ring in a circle pattern",
     [g("circle", [1, 2, 3, 4, 5, 6, 7, 8, 10])])
case("peer_selection", K, "select objects that are can. put them in a line.", [g("line", CANS)])
case("peer_selection", K, "select objects that are red. circle", [g("circle", [1, 9, 14])])
case("peer_selection", K, "select objects that have greater height than the white bowl. line",
     [g("line", [1, 2, 9, 10, 11, 12])])
case("peer_selection", K, "select objects that have less height than the red mug. circle",
     [g("circle", [2, 3, 4, 5, 6, 7, 8, 13, 14, 15])])
# StructFormer's "that have the same/equal ... as the X" leaves the X out.
case("peer_selection", K, "select objects that have equal height as the red can. line", [g("line", [10, 11])])
case("peer_selection", K, "select objects that have the same color as the red mug. line", [g("line", [9, 14])])
case("peer_selection", K, "line in the top left of the table. select objects that are can.", [g("line", CANS, region="top left")])
case("peer_selection", K, "Select Objects with the same shape as the red can, and put them in a line pattern", [g("line", CANS)])
case("peer_selection", K, "select objects that have greater volume than the red mug. line", [g("line", [3, 4, 5, 12])])

# 3. vertical relations between two objects: a two-object tower
case("vertical", K, "place the red block above the blue block", [g("tower", [15, 14])])
case("vertical", K, "put the yellow block under the red block", [g("tower", [13, 14])])
case("vertical", K, "put the green bowl below the white bowl", [g("tower", [4, 3])])
case("vertical", K, "put the white bowl on the plate", [g("tower", [5, 3])])
case("vertical", K, "set the red block on top of the yellow block", [g("tower", [13, 14])])
case("vertical", K, "slide the plate underneath the green bowl", [g("tower", [5, 4])])

# 4. where and how big
case("params", K, "Put the cans in a large circle in the top left of the table facing north",
     [g("circle", CANS, size="large", region="top left", facing="north")])
case("params", K, "select objects that are can. small line in the bottom right of the table facing east",
     [g("line", CANS, size="small", region="bottom right", facing="east")])
case("params", K, "a big circle of the blocks in the top-left corner", [g("circle", BLOCKS, size="large", region="top left")])
case("params", K, "put the cans in a short line near the front edge", [g("line", CANS, size="small", region="bottom")])
case("params", K, "line the blocks up in the middle of the table", [g("line", BLOCKS, region="middle center")])
case("params", K, "medium circle of cans in the middle center of the table facing west",
     [g("circle", CANS, size="medium", region="middle center", facing="west")])
case("params", K, "put the blocks in a row along the back of the table on the right", [g("line", BLOCKS, region="top right")])
case("params", K, "Set the table", [g("tower", [5, 3, 4]), g("line", CUT), g("left", CUT, 5)])
case("params", K, "set the table with the knife, fork and spoon to the right of the plate",
     [g("tower", [5, 3, 4]), g("line", CUT), g("right", CUT, 5)])

# 5. collective, negated and counted references
case("collective", K, "put the silverware in a line", [g("line", CUT)])
case("collective", K, "line up the cutlery", [g("line", CUT)])
case("collective", K, "put anything blue in a line", [g("line", [2, 12, 15])])
case("collective", K, "arrange the cans that are not red in a line", [g("line", [10, 11])])
case("collective", K, "put all cans but the white one in a line", [g("line", [9, 11])])
case("collective", K, "put two of the three cans in a line", [g("line", objects_from=CANS, count=2)])
case("collective", K, "put one mug to the left of the plate and the other one to the right of the plate",
     [g("left", objects_from=[1, 2], count=1, anchor=5), g("right", objects_from=[1, 2], count=1, anchor=5)],
     disjoint=[[0, 1]])
case("collective", K, "put the red things in a circle", [g("circle", [1, 9, 14])])
case("collective", L, "put all the letters in a row", [g("line", LET4)])
case("collective", K, "put the blocks that are not yellow in a line", [g("line", [14, 15])])
case("collective", K, "line up everything that is white", [g("line", [3, 5, 10])])

# 6. reference inside and across clauses, inverted relations
case("reference", K, "take the red mug and put it behind the plate", [g("behind", [1], 5)])
case("reference", K, "move the red mug so that the plate ends up on the mug's right", [g("left", [1], 5)])
case("reference", K, "grab the yellow block and put it in front of the blue bottle", [g("front", [13], 12)])
case("reference", K, "put the red can so that it is left of the white can", [g("left", [9], 10)])
# "it" after "A left of B", as the reference object of a side or depth, is B: every free-form
# writer of the fresh sets reads it so (it was read as A, then refused as unclear).
case("reference", K, "put the red mug on the left side of the plate, then put the blue mug behind it",
     [g("left", [1], 5), g("behind", [2], 5)])
case("reference", K, "move the blue mug so that the bottle is on its left", [g("right", [2], 12)])

# 7. stack order in many phrasings
case("stack_order", K, "stack the blocks with the blue block as the base, then the red block, then the yellow block",
     [g("tower", [15, 14, 13])])
case("stack_order", K, "make a tower: the yellow block on top, the red block in the middle, the blue block at the bottom",
     [g("tower", [15, 14, 13])])
case("stack_order", K, "use the blue block as the foundation, the red block goes on it, and the yellow block goes on top",
     [g("tower", [15, 14, 13])])
case("stack_order", K, "stack the yellow block, the red block and the blue block from top to bottom", [g("tower", [15, 14, 13])])
case("stack_order", K, "build a tower of the blue block crowned by the red block", [g("tower", [15, 14])])
case("stack_order", K, "the red block goes on the blue block", [g("tower", [15, 14])])
case("stack_order", K, "stack the blocks, the blue one at the bottom and the yellow one on top", [g("tower", [15, 14, 13])])

# 8. casual register and filler
case("casual", K, "hey robot, could u pls put the cans in a line? thx", [g("line", CANS)])
case("casual", K, "can you line up the cans for me?", [g("line", CANS)])
case("casual", K, "pls stack the red block on the blue one, thanks!", [g("tower", [15, 14])])
case("casual", K, "would you mind arranging the blocks in a circle please", [g("circle", BLOCKS)])
case("casual", K, "yo, cans in a row plz", [g("line", CANS)])
case("casual", K, "Hi! Put all the mugs to the left of the plate, please and thank you.", [g("left", [1, 2], 5)])
case("casual", K, "ok so basically i want the blocks in a circle, cheers", [g("circle", BLOCKS)])

# refusals: ambiguous or impossible commands
case("refusal", K, "put the cans somewhere nice", refuse="")
case("refusal", K, "put the mug behind the plate", refuse="ambiguous")
case("refusal", K, "arrange the blocks in a spiral", refuse="")
case("refusal", K, "put the giraffes in a line", refuse="giraffe")
case("refusal", K, "select objects that are purple. line", refuse="")
case("refusal", K, "stack the red block on the blue block and the blue block on the red block", refuse="contradiction")
case("refusal", K, "put two of the four cans in a line", refuse="")
case("refusal", K, "put the blue mug left of the plate and right of the plate", refuse="")
case("refusal", K, "put the red block in a circle", refuse="at least")
case("refusal", K, "put the cans in a large small circle", refuse="")
case("refusal", K, "put the cans in a circle in the top left and in the bottom right", refuse="")
case("refusal", K, "select objects that have greater height than the bottle. line", refuse="")


def main() -> None:
    path = Path(__file__).with_name("issue9_cases.jsonl")
    lines = [json.dumps({"scene_id": K, "scene": KITCHEN}), json.dumps({"scene_id": L, "scene": LETTERS})]
    lines += [json.dumps(c) for c in CASES]
    path.write_text("\n".join(lines) + "\n")
    print(f"{len(CASES)} cases -> {path}")


if __name__ == "__main__":
    main()
