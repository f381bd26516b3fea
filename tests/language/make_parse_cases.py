"""Write ``data/parse_cases.jsonl``: the labelled set for ``lgmcts eval-parse``.

Run ``.venv/bin/python tests/language/make_parse_cases.py`` from the
repository root. Part of the set is templated (relations, shapes, composite
ELGR-style commands), the expected goals computed here from what each
template refers to, never from the parser; the rest is written by hand
(free-form phrasings, grounding rules and refusals). The output is
deterministic.
"""

from __future__ import annotations

import json
import random
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
OUT = ROOT / "data" / "parse_cases.jsonl"

WS = {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}


def _scene(items: list[tuple[str, str]]) -> dict:
    objs = []
    for k, (name, color) in enumerate(items):
        x = -0.33 + 0.11 * (k % 7)
        y = -0.22 + 0.11 * (k // 7)
        objs.append({"id": k + 1, "name": name, "color": color,
                     "shape": {"type": "box", "size": [0.04, 0.04, 0.04]}, "pose": [round(x, 3), round(y, 3), 0.0], "on": None})
    return {"workspace": WS, "objects": objs}


SCENES = {
    "vima_a": _scene([
        ("block", "red"), ("block", "blue"), ("block", "green and blue stripe"), ("flower", "red swirl"),
        ("letter A", "red and green polka dot"), ("letter R", "yellow"), ("heart", "green"), ("triangle", "green"),
        ("bowl", "granite"), ("star", "purple"), ("pan", "tiger"), ("ring", "rainbow"), ("hexagon", "yellow"),
        ("cross", "blue"), ("block", "yellow"),
    ]),
    "vima_b": _scene([
        ("pentagon", "red"), ("square", "purple"), ("triangle", "red"), ("block", "yellow"), ("block", "red swirl"),
        ("bowl", "white"), ("heart", "purple"), ("flower", "green"), ("letter A", "blue"), ("ring", "green"),
        ("hexagon", "red"), ("pan", "granite"), ("star", "tiger"), ("cross", "rainbow"),
    ]),
    "kitchen": _scene([
        ("mug", "red"), ("mug", "blue"), ("bowl", "white"), ("bowl", "green"), ("bottle", "white"), ("bottle", "blue"),
        ("phone", "black"), ("pan", "gray"), ("block", "red"), ("block", "green"), ("block", "blue"), ("block", "yellow"),
        ("plate", "white"),
    ]),
    "blocks8": _scene([
        ("block", "red"), ("block", "red"), ("block", "blue"), ("block", "blue"), ("block", "green"), ("block", "green"),
        ("block", "yellow"), ("block", "white"), ("bowl", "white"), ("mug", "purple"),
    ]),
}
# The bundled example scene, copied so the case file stands alone.
SCENES["tabletop"] = json.loads((ROOT / "examples" / "tabletop.json").read_text())

REL_PHRASES = {
    "left": ["to the left of", "left of", "on the left side of", "on the left of"],
    "right": ["to the right of", "right of", "on the right side of", "on the right of"],
    "front": ["in front of", "at the front of", "in front of"],
    "behind": ["behind", "at the back of", "in back of"],
    "left_front": ["to the left and in front of", "in front left of", "front left of", "left and in front of"],
    "left_behind": ["left and behind of", "to the left and behind", "behind and to the left of", "back left of"],
    "right_front": ["to the right and in front of", "in front right of", "front right of", "right and in front of"],
    "right_behind": ["right and behind of", "to the right and behind", "behind and to the right of", "back right of"],
}
REL_TEMPLATES = ["Put {a} {rel} {b}", "Place {a} {rel} {b}", "Move {a} {rel} {b}", "Set {a} {rel} {b}"]
SHAPE_TEMPLATES = {
    "line": ["Place {x} in a line pattern", "Put {x} in a line", "Line up {x}", "Arrange {x} in a straight line",
             "Move {x} into a row", "Put {x} in a row", "Align {x} in a line"],
    "circle": ["Put {x} in a circle", "Arrange {x} in a circle pattern", "Move {x} into a circle",
               "Place {x} in a ring", "Form a circle with {x}", "Arrange {x} in a ring"],
    "rectangle": ["Place {x} in a rectangle pattern", "Arrange {x} in a rectangle", "Put {x} into a rectangle",
                  "Move {x} to form a rectangular frame", "Put {x} on the border of a square"],
}
CONNECTIVES = ["; and ", " while ", "; then ", ". Also ", ", and then ", ". Then "]


def _label(scene: dict, oid: int, article: bool = True) -> str:
    o = next(o for o in scene["objects"] if o["id"] == oid)
    words = f"{o['color']} {o['name']}"
    return f"the {words}" if article else words


def _unique_ids(scene: dict) -> list[int]:
    seen: dict[tuple[str, str], int] = {}
    for o in scene["objects"]:
        seen[(o["name"], o["color"])] = seen.get((o["name"], o["color"]), 0) + 1
    return [o["id"] for o in scene["objects"] if seen[(o["name"], o["color"])] == 1]


#: Group references per scene: (phrase, ids) usable for shapes (at least 2 objects).
GROUPS = {
    "vima_a": [("all blocks", [1, 2, 3, 15]), ("all the blocks", [1, 2, 3, 15]), ("all yellow objects", [6, 13, 15]),
               ("objects whose color is the same as the letter R", [13, 15]),
               ("the red block, the blue cross and the purple star", [1, 14, 10]),
               ("all blue objects", [2, 14]), ("the blocks", [1, 2, 3, 15]),
               ("all the green objects", [7, 8]), ("the yellow hexagon, the granite bowl, the tiger pan and the rainbow ring", [13, 9, 11, 12])],
    "vima_b": [("objects whose color is the same as the triangle", [1, 11]), ("all red objects", [1, 3, 11]),
               ("all purple items", [2, 7]), ("all the green objects", [8, 10]),
               ("the objects that have the same color as the heart", [2]),
               ("the yellow block, the blue letter A, the white bowl and the granite pan", [4, 9, 6, 12]),
               ("all blocks", [4, 5]), ("the red pentagon, the red triangle and the red hexagon", [1, 3, 11])],
    "kitchen": [("all blocks", [9, 10, 11, 12]), ("the mugs", [1, 2]), ("all the bowls", [3, 4]),
                ("all white objects", [3, 5, 13]), ("the red mug, the blue bottle and the black phone", [1, 6, 7]),
                ("all blue items", [2, 6, 11]), ("the bottles", [5, 6])],
}


def _shape_cases(rng: random.Random) -> list[dict]:
    out = []
    for scene_id, groups in GROUPS.items():
        for phrase, ids in groups:
            for pattern, templates in SHAPE_TEMPLATES.items():
                need = {"line": 2, "circle": 3, "rectangle": 4}[pattern]
                if len(ids) < need:
                    continue
                t = rng.choice(templates)
                text = t.format(x=phrase)
                text = text[0].upper() + text[1:]
                out.append({"category": "shape", "scene": scene_id, "instruction": text,
                            "expect": {"goals": [{"pattern": pattern, "objects": sorted(ids)}]}})
    return out


def _relation_cases(rng: random.Random) -> list[dict]:
    out = []
    for scene_id in ("vima_a", "vima_b", "kitchen"):
        scene = SCENES[scene_id]
        uniq = _unique_ids(scene)
        for rel, phrases in REL_PHRASES.items():
            for phrase in phrases[:3]:
                a, b = rng.sample(uniq, 2)
                bare = scene_id != "kitchen" and rng.random() < 0.4  # ELGR style: "Put red swirl flower left of ..."
                text = rng.choice(REL_TEMPLATES).format(a=_label(scene, a, not bare), rel=phrase, b=_label(scene, b, not bare))
                out.append({"category": "relation", "scene": scene_id, "instruction": text,
                            "expect": {"goals": [{"pattern": rel, "objects": [a], "anchor": b}]}})
    return out


def _composite_cases(rng: random.Random) -> list[dict]:
    out = []
    for scene_id in ("vima_a", "vima_b", "kitchen"):
        scene = SCENES[scene_id]
        uniq = _unique_ids(scene)
        for _ in range(14):
            phrase, ids = rng.choice([g for g in GROUPS[scene_id] if len(g[1]) >= 2])
            pattern = rng.choice([p for p in SHAPE_TEMPLATES if {"line": 2, "circle": 3, "rectangle": 4}[p] <= len(ids)])
            first = rng.choice(SHAPE_TEMPLATES[pattern]).format(x=phrase)
            free = [i for i in uniq if i not in ids]
            a, b = rng.sample(free, 2)
            rel = rng.choice(list(REL_PHRASES))
            second = rng.choice(REL_TEMPLATES).format(a=_label(scene, a), rel=rng.choice(REL_PHRASES[rel]), b=_label(scene, b))
            conn = rng.choice(CONNECTIVES)
            if rng.random() < 0.5:
                first, second = second, first
            if conn.startswith(". "):
                second = second[0].upper() + second[1:]
            else:
                second = second[0].lower() + second[1:]
            text = first[0].upper() + first[1:] + conn + second
            out.append({"category": "composite", "scene": scene_id, "instruction": text,
                        "expect": {"goals": [{"pattern": pattern, "objects": sorted(ids)},
                                             {"pattern": rel, "objects": [a], "anchor": b}]}})
    return out


def _g(pattern: str, objects: list[int], anchor: int | None = None, **extra) -> dict:
    g = {"pattern": pattern, "objects": objects}
    if anchor is not None:
        g["anchor"] = anchor
    g.update(extra)
    return g


#: Hand-written cases: (category, scene, instruction, goals | refusal substring).
HAND: list[tuple[str, str, str, object]] = [
    # The paper's example and other free-form commands.
    ("free", "tabletop", "Move all blocks into a circle; while put the white bottle behind one block",
     [_g("circle", [1, 2, 3, 4]), {"pattern": "behind", "objects": [5], "anchor_any": [1, 2, 3, 4]}]),
    ("free", "tabletop", "put all blocks in a circle and the white bottle behind one block",
     [_g("circle", [1, 2, 3, 4]), {"pattern": "behind", "objects": [5], "anchor_any": [1, 2, 3, 4]}]),
    ("free", "tabletop", "Could you please line up the blocks for me?", [_g("line", [1, 2, 3, 4])]),
    ("free", "tabletop", "I want the mug to the right of the bowl", [_g("right", [7], 6)]),
    ("free", "tabletop", "Arrange the four blocks in a ring, then put the phone in front of the bowl",
     [_g("circle", [1, 2, 3, 4]), _g("front", [9], 6)]),
    ("free", "tabletop", "Make a square border with the blocks", [_g("rectangle", [1, 2, 3, 4])]),
    ("free", "tabletop", "Build a tower with the red block at the bottom and the blue block on top", [_g("tower", [1, 2])]),
    ("free", "tabletop", "Pile up the yellow block, the green block and the red block", [_g("tower", [4, 3, 1])]),
    ("free", "tabletop", "Stack the green block on the yellow block", [_g("tower", [4, 3])]),
    ("free", "tabletop", "Put the red and green polka dot letter A behind the phone", [_g("behind", [8], 9)]),
    ("free", "tabletop", "place the bottle behind and to the left of the purple mug", [_g("left_behind", [5], 7)]),
    ("free", "tabletop", "The mug goes in front of the bottle", [_g("front", [7], 5)]),
    ("free", "tabletop", "Put every block in a straight row. Also put the bowl to the right of the phone.",
     [_g("line", [1, 2, 3, 4]), _g("right", [6], 9)]),
    ("free", "tabletop", "First line up the red block and the blue block, then put the cup left of the bowl",
     [_g("line", [1, 2]), _g("left", [7], 6)]),
    ("free", "kitchen", "Set the table: stack the white bowl on the white plate and line up the red mug and the blue mug to the left of the plate",
     [_g("tower", [13, 3]), _g("line", [1, 2]), _g("left", [1, 2], 13)]),
    ("free", "kitchen", "put the red mug and the blue mug in a row on the right side of the plate",
     [_g("line", [1, 2]), _g("right", [1, 2], 13)]),
    ("free", "kitchen", "Put the blocks in a circle and the bottles in a line", [_g("circle", [9, 10, 11, 12]), _g("line", [5, 6])]),
    ("free", "kitchen", "make a line with the red block and the blue block and a circle with the mugs and the phone",
     [_g("line", [9, 11]), _g("circle", [1, 2, 7])]),
    ("free", "kitchen", "put the red block and the green block to the left of the pan and the mugs in a line",
     [_g("left", [9, 10], 8), _g("line", [1, 2])]),
    ("free", "kitchen", "Place the phone in front right of the white plate", [_g("right_front", [7], 13)]),
    ("free", "kitchen", "Put the pan at the back of the black phone", [_g("behind", [8], 7)]),
    ("free", "kitchen", "Put the phone to the left of the blue bottle and the pan to the right of the blue bottle",
     [_g("left", [7], 6), _g("right", [8], 6)]),
    ("free", "kitchen", "arrange all the blocks in a rectangle while the bottles go behind the plate",
     [_g("rectangle", [9, 10, 11, 12]), _g("behind", [5, 6], 13)]),
    ("free", "vima_a", "Put red swirl flower left and behind of red and green polka dot letter A; then Place objects whose color is same as letter R in a line pattern",
     [_g("left_behind", [4], 5), _g("line", [13, 15])]),
    ("free", "vima_a", "Put the green heart in front of the purple star while the blocks form a circle",
     [_g("front", [7], 10), _g("circle", [1, 2, 3, 15])]),
    ("free", "vima_a", "arrange all blocks except the yellow one in a line", [_g("line", [1, 2, 3])]),
    ("free", "vima_a", "arrange all blocks except the red one and the blue one in a line", [_g("line", [3, 15])]),
    ("free", "vima_a", "put the blocks but not the green and blue stripe block in a ring", [_g("circle", [1, 2, 15])]),
    ("free", "vima_a", "Place the green and blue striped block to the right of the tiger pan", [_g("right", [3], 11)]),
    ("free", "vima_a", "Put the polka dot letter A behind the star", [_g("behind", [5], 10)]),
    ("free", "vima_a", "arrange the blocks in a square", [_g("rectangle", [1, 2, 3, 15])]),
    ("free", "vima_b", "arrange the red objects in a ring and put the square to the left of the ring",
     [_g("circle", [1, 3, 11]), _g("left", [2], 10)]),
    ("free", "vima_b", "Put the square in front of the star", [_g("front", [2], 13)]),
    ("free", "vima_b", "Put the hexagon, the pentagon, the triangle and the cross in a square",
     [_g("rectangle", [11, 1, 3, 14])]),
    # Grounding rules: synonyms and plurals.
    ("grounding", "tabletop", "put the cup behind the phone", [_g("behind", [7], 9)]),
    ("grounding", "tabletop", "line up the cubes", [_g("line", [1, 2, 3, 4])]),
    ("grounding", "tabletop", "put the boxes in a circle", [_g("circle", [1, 2, 3, 4])]),
    ("grounding", "kitchen", "put the cups in a line", [_g("line", [1, 2])]),
    ("grounding", "kitchen", "put the cellphone to the left of the frying pan", [_g("left", [7], 8)]),
    ("grounding", "kitchen", "put the blue bottle behind the dish", "ambiguous"),
    ("grounding", "kitchen", "put the blue bottle behind the white dish", "ambiguous"),
    ("grounding", "kitchen", "put the blue bottle behind the plate", [_g("behind", [6], 13)]),
    ("grounding", "kitchen", "put the red, green and blue blocks in a line", [_g("line", [9, 10, 11])]),
    ("grounding", "kitchen", "Stack the red, green and blue blocks", [_g("tower", [9, 10, 11])]),
    ("grounding", "kitchen", "stack the blue, green and red blocks into a tower", [_g("tower", [11, 10, 9])]),
    ("grounding", "kitchen", "put the red and blue mugs in front of the phone", [_g("front", [1, 2], 7)]),
    ("grounding", "kitchen", "put object 7 behind object 13", [_g("behind", [7], 13)]),
    ("grounding", "kitchen", "put objects 9, 10 and 11 in a circle", [_g("circle", [9, 10, 11])]),
    ("grounding", "kitchen", "put object #5 to the right of the red mug", [_g("right", [5], 1)]),
    ("grounding", "kitchen", "line up objects 1, 2 and 42", "42"),
    ("grounding", "kitchen", "put all white objects in a circle", [_g("circle", [3, 5, 13])]),
    ("grounding", "kitchen", "put the white ones in a circle", [_g("circle", [3, 5, 13])]),
    ("grounding", "kitchen", "arrange everything except the blocks in a line",
     [_g("line", [1, 2, 3, 4, 5, 6, 7, 8, 13])]),
    ("grounding", "kitchen", "put the bottles in a line, then put the phone behind them",
     [_g("line", [5, 6]), _g("behind", [7], 5), _g("behind", [7], 6)]),
    ("grounding", "kitchen", "put the red block left of the pan and the other blocks in a row",
     [_g("left", [9], 8), _g("line", [10, 11, 12])]),
    ("grounding", "kitchen", "put the red mug left of the bowls", [_g("left", [1], 3), _g("left", [1], 4)]),
    ("grounding", "kitchen", "put the red mug in front of the green bowl and the other mug behind it",
     [_g("front", [1], 4), _g("behind", [2], 1)]),
    ("grounding", "kitchen", "put the phone to the left of one block", [{"pattern": "left", "objects": [7], "anchor_any": [9, 10, 11, 12]}]),
    ("grounding", "kitchen", "put one bottle in front of the plate", [{"pattern": "front", "objects_from": [5, 6], "count": 1, "anchor": 13}]),
    ("grounding", "kitchen", "put a mug behind the pan", [{"pattern": "behind", "objects_from": [1, 2], "count": 1, "anchor": 8}]),
    ("grounding", "kitchen", "put three blocks in a circle", [{"pattern": "circle", "objects_from": [9, 10, 11, 12], "count": 3}]),
    ("grounding", "kitchen", "put two blocks in a line and the phone behind one block",
     [{"pattern": "line", "objects_from": [9, 10, 11, 12], "count": 2},
      {"pattern": "behind", "objects": [7], "anchor_any": [9, 10, 11, 12]}]),
    ("grounding", "blocks8", "put three blocks in a line and another three blocks in a line",
     {"goals": [{"pattern": "line", "objects_from": [1, 2, 3, 4, 5, 6, 7, 8], "count": 3},
                {"pattern": "line", "objects_from": [1, 2, 3, 4, 5, 6, 7, 8], "count": 3}], "disjoint": [[0, 1]]}),
    ("grounding", "blocks8", "make a line of four blocks, then make another line with four blocks",
     {"goals": [{"pattern": "line", "objects_from": [1, 2, 3, 4, 5, 6, 7, 8], "count": 4},
                {"pattern": "line", "objects_from": [1, 2, 3, 4, 5, 6, 7, 8], "count": 4}], "disjoint": [[0, 1]]}),
    ("grounding", "blocks8", "put the red blocks in a line and another line of two blocks",
     {"goals": [_g("line", [1, 2]), {"pattern": "line", "objects_from": [3, 4, 5, 6, 7, 8], "count": 2}], "disjoint": [[0, 1]]}),
    ("grounding", "blocks8", "put the red blocks in a line and three other blocks in a circle",
     [_g("line", [1, 2]), {"pattern": "circle", "objects_from": [3, 4, 5, 6, 7, 8], "count": 3}]),
    ("grounding", "blocks8", "put both red blocks behind the bowl", [_g("behind", [1, 2], 9)]),
    ("grounding", "blocks8", "put both blue blocks and the white block in a circle", [_g("circle", [3, 4, 8])]),
    ("grounding", "blocks8", "place all blocks except the green ones and the yellow one in a rectangle", [_g("rectangle", [1, 2, 3, 4, 8])]),
    ("grounding", "blocks8", "put the blocks whose color is the same as the bowl behind the mug", [_g("behind", [8], 10)]),
    ("grounding", "blocks8", "put the objects with the same color as the bowl in a line", "needs at least"),
    ("grounding", "blocks8", "stack the green blocks on the blue blocks", [_g("tower", [3, 4, 5, 6])]),
    ("grounding", "vima_a", "Place objects whose color is same as heart in a line pattern", "needs at least"),
    ("grounding", "vima_a", "Place objects whose colour is the same as the yellow hexagon in a line pattern", [_g("line", [6, 15])]),
    ("grounding", "vima_a", "Place the objects that have the same color as the blue cross and the red block in a line",
     [_g("line", [2, 1])]),
    ("grounding", "vima_a", "put the letters in a line", [_g("line", [5, 6])]),
    ("grounding", "vima_a", "put the letter A left of the letter R", [_g("left", [5], 6)]),
    ("grounding", "vima_a", "put the rainbow ring on the right of the granite bowl", [_g("right", [12], 9)]),
    ("grounding", "vima_a", "put the ring into the bowl", "does not say how"),
    # Second batch of free-form commands, written after the parser's rules were fixed
    # (their first-run score is reported in docs/language.md).
    ("heldout", "tabletop", "Can you put the bottle behind the green bowl, please?", [_g("behind", [5], 6)]),
    ("heldout", "tabletop", "Arrange the red, green and yellow blocks in a straight line", [_g("line", [1, 3, 4])]),
    ("heldout", "tabletop", "Put the phone on the right side of the white bottle", [_g("right", [9], 5)]),
    ("heldout", "tabletop", "Place all of the blocks in a circle", [_g("circle", [1, 2, 3, 4])]),
    ("heldout", "tabletop", "Stack the yellow block onto the red block", [_g("tower", [1, 4])]),
    ("heldout", "tabletop", "Put the mug in front of the phone and the bottle behind the phone",
     [_g("front", [7], 9), _g("behind", [5], 9)]),
    ("heldout", "tabletop", "I'd like the blocks lined up", [_g("line", [1, 2, 3, 4])]),
    ("heldout", "tabletop", "Put the letter A to the right and behind the bowl", [_g("right_behind", [8], 6)]),
    ("heldout", "tabletop", "Form a rectangle using all the blocks", [_g("rectangle", [1, 2, 3, 4])]),
    ("heldout", "tabletop", "Put the purple mug on the left of the phone. Then line up the blocks.",
     [_g("left", [7], 9), _g("line", [1, 2, 3, 4])]),
    ("heldout", "kitchen", "Put the pan behind the white plate and stack the blocks", [_g("behind", [8], 13), _g("tower", [9, 10, 11, 12])]),
    ("heldout", "kitchen", "Make a circle out of the red block, the green block and the blue block", [_g("circle", [9, 10, 11])]),
    ("heldout", "kitchen", "Move the white bottle to the front of the black phone", [_g("front", [5], 7)]),
    ("heldout", "kitchen", "Put both bottles to the left of the pan", [_g("left", [5, 6], 8)]),
    ("heldout", "kitchen", "Put the blue mug behind the plate, then put the red mug in front of the plate",
     [_g("behind", [2], 13), _g("front", [1], 13)]),
    ("heldout", "kitchen", "Line the bowls up", [_g("line", [3, 4])]),
    ("heldout", "kitchen", "arrange the yellow block, the blue bottle, the red mug and the phone in a rectangle",
     [_g("rectangle", [12, 6, 1, 7])]),
    ("heldout", "kitchen", "Place the green bowl in front and to the right of the blue bottle", [_g("right_front", [4], 6)]),
    ("heldout", "kitchen", "put the white bowl on top of the plate", [_g("tower", [13, 3])]),
    ("heldout", "kitchen", "put the blocks in a ring around", [_g("circle", [9, 10, 11, 12])]),
    ("heldout", "vima_a", "Put the tiger pan to the left of the rainbow ring while putting the yellow objects in a line",
     [_g("left", [11], 12), _g("line", [6, 13, 15])]),
    ("heldout", "vima_a", "Place the purple star behind and to the right of the granite bowl", [_g("right_behind", [10], 9)]),
    ("heldout", "vima_a", "Move all the blocks into a row; and put the heart in front of the star",
     [_g("line", [1, 2, 3, 15]), _g("front", [7], 10)]),
    ("heldout", "vima_a", "put the blue cross left of the hexagon", [_g("left", [14], 13)]),
    ("heldout", "vima_a", "put the ring behind the flower", [_g("behind", [12], 4)]),
    ("heldout", "vima_b", "Arrange the red pentagon, the red triangle, the red hexagon and the purple square in a rectangle pattern",
     [_g("rectangle", [1, 3, 11, 2])]),
    ("heldout", "vima_b", "Place the green flower to the right of the green ring", [_g("right", [8], 10)]),
    ("heldout", "vima_b", "Put all purple objects in a line. Also put the star behind the bowl.",
     [_g("line", [2, 7]), _g("behind", [13], 6)]),
    ("heldout", "blocks8", "Put two red blocks in a row and the yellow block behind the mug",
     [_g("line", [1, 2]), _g("behind", [7], 10)]),
    ("heldout", "blocks8", "stack the white block on the yellow block on the green block", "ambiguous"),
    ("heldout", "blocks8", "put the blue blocks to the left of the bowl", [_g("left", [3, 4], 9)]),
    ("heldout", "kitchen", "put the teapot in a line with the mugs", "teapot"),
    ("heldout", "kitchen", "arrange the mugs in a heart shape", "no pattern"),
    ("heldout", "kitchen", "put the bottles in a line and the phone in the middle", "middle"),
    # Refusals: each must be refused with one line that names the problem.
    ("refusal", "tabletop", "put the purple giraffe in a line", "giraffe"),
    ("refusal", "tabletop", "put the spaceship behind the bowl", "spaceship"),
    ("refusal", "tabletop", "arrange the blocks in a Fibonacci spiral", "no pattern"),
    ("refusal", "tabletop", "arrange the blocks in a zigzag", "no pattern"),
    ("refusal", "vima_a", "arrange the blocks in a triangle", "no pattern"),
    ("refusal", "vima_a", "put all blocks in a star shape", "no pattern"),
    ("refusal", "tabletop", "put the mug next to the bowl", "no pattern"),
    ("refusal", "tabletop", "put all green bowls in a line", "needs at least"),
    ("refusal", "kitchen", "put all purple bowls in a line", "nothing in the scene matches"),
    ("refusal", "kitchen", "put the mugs in a circle", "needs at least 3"),
    ("refusal", "kitchen", "put the red block in a line", "needs at least 2"),
    ("refusal", "kitchen", "put the phone in a rectangle with the mugs", "needs at least 4"),
    ("refusal", "kitchen", "put the bottle behind the plate", "ambiguous"),
    ("refusal", "kitchen", "put the block to the left of the phone", "ambiguous"),
    ("refusal", "kitchen", "put the red mug left of the bowl", "ambiguous"),
    ("refusal", "kitchen", "put the mug left of the plate and the mug right of the plate", "ambiguous"),
    ("refusal", "kitchen", "put the red mug left of the plate and the red mug right of the plate", "contradiction"),
    ("refusal", "kitchen", "stack the red block on the blue block and stack the blue block on the red block", "contradiction"),
    ("refusal", "kitchen", "put the phone left of the pan and the pan left of the phone", "contradiction"),
    ("refusal", "kitchen", "put the red block in a line with the green block and stack the red block on the blue block", "contradiction"),
    ("refusal", "kitchen", "move the red mug", "does not say how"),
    ("refusal", "kitchen", "put the red mug to the left", "of what"),
    ("refusal", "kitchen", "asdf qwerty", "names no object"),
    ("refusal", "kitchen", "   ", "empty"),
    ("refusal", "kitchen", "put five blocks in a line", "only 4"),
    ("refusal", "blocks8", "put four blocks in a line and another five blocks in a circle", "needed"),
    ("refusal", "blocks8", "put the red block behind the bowl", "ambiguous"),
    ("refusal", "blocks8", "put the mug behind itself", "itself"),
    ("refusal", "vima_b", "put the square behind the square", "itself"),
    ("refusal", "vima_b", "put the orange block in a line", "nothing"),
    ("refusal", "vima_b", "put the red swirl star left of the bowl", "nothing in the scene matches"),
    ("refusal", "vima_b", "put objects whose color is the same as the unicorn in a line", "unicorn"),
    ("refusal", "vima_b", "Put all blocks in a circle", "needs at least 3"),
    ("refusal", "vima_b", "put the heart on the left of the bowl and on the right of the bowl", "right"),
    # Known gaps closed after the sets above were settled (appended so that the
    # ids of the earlier cases stay the same).
    # Elided heads: the noun is shared with a coordinated neighbour.
    ("grounding", "tabletop", "Put the red and the blue blocks in a line", [_g("line", [1, 2])]),
    ("grounding", "tabletop", "Put the red, the blue and the green blocks in a circle", [_g("circle", [1, 2, 3])]),
    ("grounding", "blocks8", "Put the red and the blue blocks in a rectangle", [_g("rectangle", [1, 2, 3, 4])]),
    ("grounding", "kitchen", "Stack the yellow and the blue blocks", [_g("tower", [12, 11])]),
    ("grounding", "kitchen", "put the red and the blue mugs behind the plate", [_g("behind", [1, 2], 13)]),
    ("grounding", "kitchen", "put the red block and the green one in a line", [_g("line", [9, 10])]),
    ("grounding", "kitchen", "put the red one and the green block in a line", [_g("line", [9, 10])]),
    ("grounding", "kitchen", "line up the red block and the blue", [_g("line", [9, 11])]),
    ("refusal", "kitchen", "put the red in a line", "ambiguous"),
    # A list "A, B, C and D" stays in one command; "and" before a verb starts a new one.
    ("free", "tabletop", "Stack the red block, the blue block, the green block and the yellow block into a tower",
     [_g("tower", [1, 2, 3, 4])]),
    ("free", "vima_b", "Stack the purple square, the red pentagon, the green ring and the yellow block into a tower",
     [_g("tower", [2, 1, 10, 4])]),
    ("free", "kitchen", "put the bowls in a line and stack the blocks", [_g("line", [3, 4]), _g("tower", [9, 10, 11, 12])]),
    ("free", "kitchen", "stack the blocks and put the bowls in a line", [_g("tower", [9, 10, 11, 12]), _g("line", [3, 4])]),
    ("free", "kitchen", "Stack the red block, the blue block and the green block and put the mugs in a line",
     [_g("tower", [9, 11, 10]), _g("line", [1, 2])]),
    ("free", "kitchen", "stack the blocks and get the bowls in a line", [_g("tower", [9, 10, 11, 12]), _g("line", [3, 4])]),
    ("free", "kitchen", "put the mugs in a row, place the phone behind the plate",
     [_g("line", [1, 2]), _g("behind", [7], 13)]),
    # A line and a relation over the same objects in one clause.
    ("free", "tabletop", "Line up the red block and the blue block to the left of the bowl",
     [_g("line", [1, 2]), _g("left", [1, 2], 6)]),
    ("free", "tabletop", "Line up the red and the blue blocks to the left of the bowl",
     [_g("line", [1, 2]), _g("left", [1, 2], 6)]),
    ("free", "kitchen", "Line up the red block and the blue block behind the white plate",
     [_g("line", [9, 11]), _g("behind", [9, 11], 13)]),
    ("free", "tabletop", "To the left of the bowl, line up the red block and the blue block",
     [_g("line", [1, 2]), _g("left", [1, 2], 6)]),
    ("free", "tabletop", "To the left of the bowl, line up the red block and the blue block, and put the mug behind the phone",
     [_g("line", [1, 2]), _g("left", [1, 2], 6), _g("behind", [7], 9)]),
    # Stacking step by step: chained "A on B" commands make one tower, bottom first.
    ("free", "tabletop", "Put the red block on the blue block, then put the green block on the red block",
     [_g("tower", [2, 1, 3])]),
    ("free", "tabletop", "Put the green block on the red block, then put the red block on the blue block",
     [_g("tower", [2, 1, 3])]),
    ("free", "tabletop", "Stack the red block on the blue block and the green block on the red block",
     [_g("tower", [2, 1, 3])]),
    ("free", "tabletop", "Put the red block on the blue block. Put the green block on the red block. Put the yellow block on the green block.",
     [_g("tower", [2, 1, 3, 4])]),
    ("free", "tabletop", "Put the red block on the blue block, then put the green block on top of it", [_g("tower", [2, 1, 3])]),
    ("free", "kitchen", "Stack the white bowl on the white plate, then put the red mug on the white bowl", [_g("tower", [13, 3, 1])]),
    ("refusal", "kitchen", "put the red block on the blue block and the green block on the blue block", "contradiction"),
    # Colours given in part: every word given must be in the object's colour.
    ("grounding", "vima_a", "put the swirl flower behind the star", [_g("behind", [4], 10)]),
    ("grounding", "vima_a", "Put the red flower to the left of the tiger pan", [_g("left", [4], 11)]),
    ("grounding", "vima_a", "put the blue stripe block in front of the heart", [_g("front", [3], 7)]),
    ("grounding", "vima_a", "Put the striped block right of the swirl flower", [_g("right", [3], 4)]),
    ("grounding", "vima_b", "put the swirl block and the yellow block in a line", [_g("line", [5, 4])]),
    ("grounding", "vima_b", "put the red objects in a circle", [_g("circle", [1, 3, 11])]),
    ("refusal", "vima_b", "put the swirl star left of the bowl", "nothing in the scene matches"),
    ("refusal", "vima_a", "put the swirl heart behind the star", "nothing in the scene matches"),
    ("grounding", "tabletop", "put the red one and the blue one and the green bowl in a circle", [_g("circle", [1, 2, 6])]),
    ("grounding", "tabletop", "put the green bowl, the red and the blue blocks in a circle", [_g("circle", [6, 1, 2])]),
]


#: Cases whose label changed when "objects whose color is the same as X" came
#: to include X itself, as in the peers' object selectors (LGMCTS-D's
#: ``select_obj`` puts the reference in its "equal" set). The phrases and the
#: random draws above are kept as they were so that no case id moves; the
#: expected goals of these cases are replaced when the file is written.
RELABELLED: dict[str, dict] = {
    "shape-009": {"goals": [_g("line", [6, 13, 15])]},
    "shape-020": {"goals": [_g("line", [1, 3, 11])]},
    "composite-015": {"goals": [_g("line", [1, 3, 11]), _g("right_behind", [14], 5)]},
    "composite-017": {"goals": [_g("line", [1, 3, 11]), _g("behind", [5], 10)]},
    "composite-018": {"goals": [_g("line", [1, 3, 11]), _g("front", [2], 6)]},
    "composite-022": {"goals": [_g("line", [1, 3, 11]), _g("left", [2], 5)]},
    "composite-028": {"goals": [_g("line", [1, 3, 11]), _g("left_front", [3], 12)]},
    "free-024": {"goals": [_g("left_behind", [4], 5), _g("line", [6, 13, 15])]},
    "grounding-037": {"goals": [_g("line", [8, 9])]},
    "grounding-039": {"goals": [_g("line", [7, 8])]},
    "grounding-040": {"goals": [_g("line", [6, 13, 15])]},
    # "into the bowl": one object inside the other is a stack (as the free-form writers label it).
    "grounding-045": {"goals": [_g("tower", [9, 12])]},
    "grounding-023": {"goals": [_g("front", [1], 4), _g("behind", [2], 4)]},
    # "next to the bowl" with no side: either side of it (as the later free-form writers label it), not a refusal.
    "refusal-007": {"any_of": [{"goals": [_g("left", [7], 6)]}, {"goals": [_g("right", [7], 6)]}]},
}

#: Cases that became refusals (none left). "it" after "A in front of B" was read
#: as A, then refused as unclear; it is now B, the reference object, as every
#: free-form writer of the fresh sets reads it where a side or depth follows
#: ("the phone left of the mug and the knife to its right": eight dev labels say
#: the mug, four accept either, none says the phone or refuses).
REFUSED: dict[str, str] = {}


def main() -> None:
    rng = random.Random(20240501)
    rows: list[dict] = []
    for sid, scene in SCENES.items():
        rows.append({"scene_id": sid, "scene": scene})
    cases = _relation_cases(rng) + _shape_cases(rng) + _composite_cases(rng)
    for cat, sid, text, want in HAND:
        row = {"category": cat, "scene": sid, "instruction": text}
        if isinstance(want, str):
            row["category"] = "refusal" if cat == "refusal" else cat
            row["refuse"] = want
        elif isinstance(want, dict):
            row["expect"] = want
        else:
            row["expect"] = {"goals": want}
        cases.append(row)
    counters: dict[str, int] = {}
    for c in cases:
        counters[c["category"]] = counters.get(c["category"], 0) + 1
        c["id"] = f"{c['category']}-{counters[c['category']]:03d}"
        if c["id"] in RELABELLED:
            c.pop("refuse", None)
            c["expect"] = RELABELLED[c["id"]]
        if c["id"] in REFUSED:
            c.pop("expect", None)
            c["refuse"] = REFUSED[c["id"]]
        rows.append({k: c[k] for k in ("id", "category", "scene", "instruction") if k in c}
                    | {k: c[k] for k in ("expect", "refuse") if k in c})
    OUT.parent.mkdir(parents=True, exist_ok=True)
    OUT.write_text("".join(json.dumps(r) + "\n" for r in rows))
    print(f"wrote {len(cases)} cases and {len(SCENES)} scenes to {OUT.relative_to(ROOT)}")


if __name__ == "__main__":
    main()
