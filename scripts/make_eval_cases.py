"""Write ``data/peer_cases.jsonl``: commands in the peers' own instruction language.

Run ``/path/to/python scripts/make_eval_cases.py`` from the repository root
(deterministic: the same file every time). ``--splits-only FILE`` instead
(re)assigns the ``split`` field of a hand-written case file such as
``data/paraphrase_cases.jsonl`` with the same seeded rule, leaving every
other field as written.

The commands are instantiated, in fresh random scenes, from the template
families of two public code bases, re-implemented here from their published
wording and semantics (not from this project's parser):

* LGMCTS-D (``lgmcts/components/prompt.py``, ``obj_selector.py``,
  ``attribute.py`` and earlier revisions of them; ``lgmcts/utils/spatial_utils.py``
  for the pair relations): VIMA-like objects with textures, two colours per
  scene as in its generator, object sets "objects whose color is equal to
  X" (the reference X itself is in the set), the negated comparisons (every
  object of another colour), the older "Objects with/of/has the
  same/similar/different color/shape as X" and "Objects same as color X",
  the older size comparisons "objects whose size is smaller than / is
  bigger than / is taller than ... X" (bounding-box volume, in scenes where
  height and width order the objects the same way),
  the pattern sentences "{verb} {objects} {prep} a {pattern} pattern",
  "{verb} a {pattern} pattern using {objects}", "Select {objects}, and
  {verb} them {prep} a {pattern} pattern", pair sentences "{verb} {texture}
  {name} {relation} {texture} {name}" with the relation words of its
  nine-point spatial vocabulary (incl. on/above/under/below: a two-object
  stack), joined by "; then ", "; and ", "; while ", "; so " or "; ".
* StructFormer / StructDiffusion (``data/tokenizer.py``): household
  objects, "select objects that are {colour|class}.", "select objects that
  have {greater|less|equal} {height|volume} {than|as} the {anchor}." (the
  peers' vocabulary spells it "volumn"; a third of the cases keep that
  spelling), "select objects that have the same color as the {anchor}."
  (the anchor is not selected: it is a separate role in the peers' goal
  specification), and the structure sentence "{small|medium|large}
  {circle|line|tower|dinner} in the {bottom|middle|top}
  {left|center|right} of the table facing {north|east|south|west}", each
  part present or not as in the peers' sentence builder (size only for
  circles and lines).

Labels are computed here from the scene with the peers' semantics (colour
and name equality, heights and volumes from the object shapes). A stack
whose order the sentence leaves open is ``"unordered": true``; a place
setting is either side of the plate (``any_of``); sizes, regions and facing
are the optional goal fields ``size``, ``region`` ("<row> <col>") and
``facing``, and such cases carry ``"needs": ["params"]``. A command that
cannot be carried out as said (a reference to an absent or ambiguous object,
an empty selection, too few objects for the pattern) must be refused:
``"refuse": true``. Every case has ``family`` and ``split`` (about 35 % "dev",
65 % "test", drawn per family with a fixed seed).
"""

from __future__ import annotations

import argparse
import json
import math
import random
from pathlib import Path

# The peers' template vocabulary; PAIR_WORDS gives "A is ... B" without "A is" and "B".
from lgmcts.bench.peer_language import CONNECTIVES as CORRELATIVES
from lgmcts.bench.peer_language import DIFF_WORDS, EQUAL_WORDS, PAIR_WORDS, PREP, PUT

ROOT = Path(__file__).resolve().parents[1]
OUT = ROOT / "data" / "peer_cases.jsonl"
WS = {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}
SEED = 20261123
DEV_SHARE = 0.35

# ---------------------------------------------------------------- vocabularies
VIMA_NAMES = ("block", "bowl", "pan", "ring", "heart", "flower", "star", "triangle", "hexagon", "pentagon", "cross",
              "diamond", "letter A", "letter E", "letter G", "letter M", "letter R", "letter T", "letter V",
              "L-shaped block", "square")
VIMA_TEXTURES = ("red", "green", "blue", "yellow", "purple", "pink", "cyan", "orange", "white", "red swirl",
                 "yellow paisley", "red and green polka dot", "yellow and blue polka dot", "green and blue stripe",
                 "yellow and green stripe", "granite", "tiger", "rainbow", "wooden", "magenta")
HOUSE_NAMES = ("mug", "cup", "can", "bowl", "box", "bottle", "plate", "jar", "glass")
HOUSE_COLORS = ("red", "green", "blue", "yellow", "white", "black", "orange", "purple", "gray")
CUTLERY = ("fork", "knife", "spoon")

# Older example files also wrote "back right of" / "behind right of".
PAIR_WORDS_OLD = {"left_behind": ("back left of",), "right_behind": ("back right of",)}
VERTICAL = {"on": "top", "above": "top", "under": "bottom", "below": "bottom"}
MIN_OBJECTS = {"line": 2, "circle": 3, "rectangle": 4, "tower": 2}


# ---------------------------------------------------------------- shapes and scenes
def _regular(r: float, m: int, phase: float = 0.0) -> list[list[float]]:
    return [[round(r * math.cos(phase + 2 * math.pi * k / m), 4), round(r * math.sin(phase + 2 * math.pi * k / m), 4)]
            for k in range(m)]


def shape_of(name: str, s: float) -> dict:
    """A footprint shape for ``name`` scaled by ``s`` (metres)."""
    def box(x, y, z):
        return {"type": "box", "size": [round(x * s, 4), round(y * s, 4), round(z * s, 4)]}

    def cyl(r, h):
        return {"type": "cylinder", "radius": round(r * s, 4), "height": round(h * s, 4)}

    def poly(pts, h):
        return {"type": "polygon", "points": [[round(x * s, 4), round(y * s, 4)] for x, y in pts], "height": round(h * s, 4)}

    table = {
        "block": lambda: box(0.04, 0.04, 0.035), "L-shaped block": lambda: box(0.05, 0.03, 0.03),
        "square": lambda: box(0.05, 0.05, 0.012), "bowl": lambda: cyl(0.035, 0.03), "pan": lambda: cyl(0.042, 0.02),
        "ring": lambda: cyl(0.035, 0.01), "heart": lambda: poly([[0, -0.032], [0.03, 0], [0.028, 0.02], [0.015, 0.03],
                                                                   [-0.015, 0.03], [-0.028, 0.02], [-0.03, 0]], 0.015),
        "flower": lambda: poly(_regular(0.032, 8), 0.015), "star": lambda: poly(_regular(0.035, 5, math.pi / 2), 0.015),
        "triangle": lambda: poly(_regular(0.036, 3, math.pi / 2), 0.015),
        "hexagon": lambda: poly(_regular(0.032, 6), 0.015), "pentagon": lambda: poly(_regular(0.032, 5, -math.pi / 2), 0.015),
        "cross": lambda: poly([[0.01, 0.03], [-0.01, 0.03], [-0.03, 0.01], [-0.03, -0.01], [-0.01, -0.03], [0.01, -0.03],
                               [0.03, -0.01], [0.03, 0.01]], 0.015),
        "diamond": lambda: poly([[0, 0.036], [-0.025, 0], [0, -0.036], [0.025, 0]], 0.015),
        "mug": lambda: cyl(0.04, 0.09), "cup": lambda: cyl(0.033, 0.07), "can": lambda: cyl(0.03, 0.11),
        "jar": lambda: cyl(0.035, 0.1), "glass": lambda: cyl(0.03, 0.09), "bottle": lambda: cyl(0.032, 0.2),
        "box": lambda: box(0.08, 0.06, 0.06), "plate": lambda: cyl(0.08, 0.015),
        "fork": lambda: box(0.17, 0.022, 0.01), "knife": lambda: box(0.19, 0.02, 0.01), "spoon": lambda: box(0.16, 0.03, 0.01),
    }
    if name in table:
        return table[name]()
    return poly([[-0.03, -0.03], [0.03, -0.03], [0.01, 0.03], [-0.01, 0.03]], 0.015)  # letters


def height(shape: dict) -> float:
    return shape["size"][2] if shape["type"] == "box" else shape["height"]


def volume(shape: dict) -> float:
    if shape["type"] == "box":
        x, y, z = shape["size"]
        return x * y * z
    if shape["type"] == "cylinder":
        return math.pi * shape["radius"] ** 2 * shape["height"]
    pts = shape["points"]
    area = 0.5 * abs(sum(pts[i][0] * pts[i - 1][1] - pts[i - 1][0] * pts[i][1] for i in range(len(pts))))
    return area * shape["height"]


def _radius(shape: dict) -> float:
    if shape["type"] == "box":
        return 0.5 * math.hypot(shape["size"][0], shape["size"][1])
    if shape["type"] == "cylinder":
        return shape["radius"]
    return max(math.hypot(x, y) for x, y in shape["points"])


def make_scene(rng: random.Random, items: list[tuple[str, str, float]]) -> tuple[dict, list[int]] | None:
    """Place ``items`` (name, colour, scale) at random without overlap; ids shuffled.

    Returns the scene and the id of each item (in the order given)."""
    shapes = [shape_of(n, s) for n, _, s in items]
    order = list(range(len(items)))
    rng.shuffle(order)
    ids = [0] * len(items)
    for new_id, k in enumerate(order, 1):
        ids[k] = new_id
    placed: list[tuple[float, float, float]] = []
    poses = []
    for sh in shapes:
        r = _radius(sh)
        for _ in range(400):
            x = rng.uniform(WS["x"][0] + r + 0.01, WS["x"][1] - r - 0.01)
            y = rng.uniform(WS["y"][0] + r + 0.01, WS["y"][1] - r - 0.01)
            if all(math.hypot(x - a, y - b) > r + rb + 0.012 for a, b, rb in placed):
                break
        else:
            return None
        placed.append((x, y, r))
        poses.append([round(x, 3), round(y, 3), round(rng.uniform(-math.pi, math.pi), 3)])
    objs = [None] * len(items)
    for k, (name, color, _) in enumerate(items):
        objs[ids[k] - 1] = {"id": ids[k], "name": name, "color": color, "shape": shapes[k], "pose": poses[k], "on": None}
    return {"workspace": WS, "objects": objs}, ids


# ---------------------------------------------------------------- helpers
def pick(rng: random.Random, seq):
    return seq[rng.randrange(len(seq))]


def goal(pattern: str, objects, **extra) -> dict:
    g = {"pattern": pattern, "objects": sorted(objects) if pattern != "tower" else list(objects)}
    if pattern == "tower" and extra.pop("unordered", False):
        g["objects"] = sorted(objects)
        g["unordered"] = True
    g.update({k: v for k, v in extra.items() if v is not None})
    return g


def pattern_sentence(rng: random.Random, objs: str, pattern: str, *, older: bool = False) -> str:
    """One of the LGMCTS-D pattern sentences (the second older form has a stray preposition)."""
    verb, prep = pick(rng, PUT), pick(rng, PREP)
    forms = [f"{verb} {objs} {prep} a {pattern} pattern", f"{verb} a {pattern} pattern using {objs}",
             f"Select {objs}, and {pick(rng, PUT)} them {pick(rng, PREP)} a {pattern} pattern"]
    if older and rng.random() < 0.12:
        return f"{verb} a {pattern} pattern {prep} using {objs}"
    return pick(rng, forms)


def vima_items(rng: random.Random, names: list[str], colors: list[str]) -> list[tuple[str, str, float]]:
    return [(n, c, round(rng.uniform(0.9, 1.1), 3)) for n, c in zip(names, colors)]


class Builder:
    def __init__(self) -> None:
        self.lines: list[dict] = []
        self.cases: list[dict] = []
        self.n_scene = 0

    def add(self, rng: random.Random, family: str, items, make) -> bool:
        """Place ``items``; ``make(ids, scene)`` returns (instruction, expect or None for refusal, needs) or None."""
        made = make_scene(rng, items)
        if made is None:
            return False
        scene, ids = made
        out = make(ids, scene)
        if out is None:
            return False
        text, expect, needs = out
        self.n_scene += 1
        sid = f"peer-s{self.n_scene:03d}"
        self.lines.append({"scene_id": sid, "scene": scene})
        case = {"id": f"{family}-{sum(c['family'] == family for c in self.cases) + 1:03d}", "family": family,
                "scene": sid, "instruction": text}
        if expect is None:
            case["refuse"] = True
        else:
            case["expect"] = expect
        if needs:
            case["needs"] = list(needs)
        self.cases.append(case)
        self.lines.append(case)
        return True


SMALLER_WORDS = ("is smaller than", "is less than", "is shorter than", "is narrower than", "is smaller in size than")
BIGGER_WORDS = ("is bigger than", "is larger than", "is greater than", "is taller than", "is wider than",
                "is bigger in size than")


def bbox(shape: dict) -> tuple[float, float, float]:
    """Extents (x, y, z) of a shape's bounding box."""
    if shape["type"] == "box":
        return tuple(shape["size"])
    if shape["type"] == "cylinder":
        return (2 * shape["radius"], 2 * shape["radius"], shape["height"])
    xs, ys = [p[0] for p in shape["points"]], [p[1] for p in shape["points"]]
    return (max(xs) - min(xs), max(ys) - min(ys), shape["height"])


# ---------------------------------------------------------------- LGMCTS-D families
def _two_colour_scene(rng: random.Random, n_a: int, n_b: int, *, unique_anchor: bool = True, extra: int = 0):
    """Group A (n_a objects of colour ca, the first one the anchor with a unique name), group B (colour cb)."""
    ca, cb = rng.sample(VIMA_TEXTURES, 2)
    names = rng.sample(VIMA_NAMES, min(len(VIMA_NAMES), n_a + n_b))
    while len(names) < n_a + n_b:
        names.append(pick(rng, VIMA_NAMES[1:]))
    if not unique_anchor:
        names[1] = names[0]
    items = vima_items(rng, names, [ca] * n_a + [cb] * n_b)
    for _ in range(extra):
        items.append((pick(rng, VIMA_NAMES), pick(rng, [c for c in VIMA_TEXTURES if c not in (ca, cb)]), 1.0))
    return items, ca, cb


def _obj_word(rng: random.Random, word: str) -> str:
    return word if rng.random() < 0.7 else word[0].upper() + word[1:]


def fam_whose(b: Builder, rng: random.Random, family: str, words: tuple[str, ...], same: bool, n: int) -> None:
    made = 0
    while made < n:
        refuse_kind = None
        r = rng.random()
        if r < 0.1:
            refuse_kind = "absent"
        elif r < 0.18 and same:
            refuse_kind = "ambiguous"
        pattern = pick(rng, ("line", "circle", "circle", "line", "rectangle"))
        n_a, n_b = rng.randint(3, 5), rng.randint(3, 5)
        if pattern == "rectangle":
            n_a, n_b = max(n_a, 4), max(n_b, 4)
        items, _ca, cb = _two_colour_scene(rng, n_a, n_b)
        anchor_name = items[0][0]
        if refuse_kind == "ambiguous":  # a second object of that name, in the other colour
            items.append((anchor_name, cb, 1.0))
        if refuse_kind == "absent":
            anchor_name = pick(rng, [x for x in VIMA_NAMES if x not in {it[0] for it in items}])
        word = pick(rng, words)

        def make(ids, scene, items=items, word=word, pattern=pattern, anchor_name=anchor_name, refuse_kind=refuse_kind):
            objs = f"{_obj_word(rng, 'objects')} whose color {word} {anchor_name}"
            text = pattern_sentence(rng, objs, pattern, older=True)
            if refuse_kind:
                return text, None, ()
            sel = [ids[k] for k, it in enumerate(items) if (it[1] == items[0][1]) == same]
            return text, {"goals": [goal(pattern, sel)]}, ()

        made += b.add(rng, family, items, make)


def fam_with_attr(b: Builder, rng: random.Random, n: int) -> None:
    """Older LGMCTS-D: "Objects {with|of|has} {the same|similar|different} {color|shape} as {X}"."""
    made = 0
    while made < n:
        attr = pick(rng, ("color", "shape"))
        describe = pick(rng, ("the same", "similar", "different"))
        pattern = pick(rng, ("line", "circle"))
        if attr == "color":
            items, _ca, _cb = _two_colour_scene(rng, rng.randint(3, 5), rng.randint(3, 5))
            anchor = items[0][0]
        else:
            # a few objects of the anchor's shape, the rest of other shapes, two colours
            shape_name = pick(rng, ("block", "heart", "star", "letter A", "triangle", "bowl", "cross", "flower"))
            k_same = rng.randint(3, 4)
            others = rng.sample([x for x in VIMA_NAMES if x != shape_name], rng.randint(3, 4))
            cols = rng.sample(VIMA_TEXTURES, 2)
            items = [(shape_name, pick(rng, cols), 1.0) for _ in range(k_same)] + [(o, pick(rng, cols), 1.0) for o in others]
            items = vima_items(rng, [i[0] for i in items], [i[1] for i in items])
            same_col = [it for it in items if it[0] == shape_name and it[1] == items[0][1]]
            anchor = f"{items[0][1]} {shape_name}" if (len(same_col) == 1 and rng.random() < 0.5) else shape_name

        def make(ids, scene, items=items, attr=attr, describe=describe, pattern=pattern, anchor=anchor):
            prep = pick(rng, ("with", "of", "has"))
            objs = f"{_obj_word(rng, 'Objects')} {prep} {describe} {attr} as {anchor}"
            text = pattern_sentence(rng, objs, pattern)
            key = 1 if attr == "color" else 0
            equal = describe != "different"
            sel = [ids[k] for k, it in enumerate(items) if (it[key] == items[0][key]) == equal]
            if len(sel) < MIN_OBJECTS[pattern]:
                return None
            return text, {"goals": [goal(pattern, sel)]}, ()

        made += b.add(rng, "lgmcts-with-same-different", items, make)


def fam_objects_compare_attr(b: Builder, rng: random.Random, n: int) -> None:
    """Earliest LGMCTS-D selector: "Objects {same as|equal to|...} color {X}" (X by name)."""
    made = 0
    while made < n:
        same = rng.random() < 0.6
        items, _ca, _cb = _two_colour_scene(rng, rng.randint(3, 5), rng.randint(3, 5))
        word = pick(rng, ("equal to", "same as", "identical to", "alike", "equivalent to") if same else
                    ("different with", "not the same as", "not equal to", "not identical to", "different from"))
        pattern = pick(rng, ("line", "circle"))

        def make(ids, scene, items=items, word=word, same=same, pattern=pattern):
            text = f"{pick(rng, PUT)} Objects {word} color {items[0][0]} {pick(rng, PREP)} a {pattern} pattern"
            sel = [ids[k] for k, it in enumerate(items) if (it[1] == items[0][1]) == same]
            return text, {"goals": [goal(pattern, sel)]}, ()

        made += b.add(rng, "lgmcts-objects-compare-color", items, make)


def fam_whose_size(b: Builder, rng: random.Random, n: int) -> None:
    """Older LGMCTS-D size selector: "objects whose size is smaller than / is bigger than ... X".

    The peers compare the volume of the objects' bounding boxes; the scenes here are drawn so that
    height, width and volume all order every object the same way against X (no reading of "taller" or
    "narrower" gives another set), with at least 15 % between any object and X."""
    made = 0
    while made < n:
        bigger = rng.random() < 0.5
        pattern = pick(rng, ("line", "circle"))
        names = rng.sample(VIMA_NAMES, rng.randint(6, 8))
        items = [(nm, pick(rng, VIMA_TEXTURES), round(rng.uniform(0.7, 1.4), 3)) for nm in names]
        boxes = [bbox(shape_of(nm, sc)) for nm, _, sc in items]
        ax, ay, az = boxes[0]
        ok, sel_k = True, []
        for k, (x, y, z) in enumerate(boxes[1:], 1):
            w, aw = max(x, y), max(ax, ay)
            signs = {(z > az * 1.15) - (z < az / 1.15), (w > aw * 1.15) - (w < aw / 1.15),
                     (x * y * z > ax * ay * az * 1.15) - (x * y * z < ax * ay * az / 1.15)}
            if len(signs) != 1 or 0 in signs:
                ok = False
                break
            if signs == {1 if bigger else -1}:
                sel_k.append(k)
        if not ok or len(sel_k) < MIN_OBJECTS[pattern] or len(sel_k) == len(items) - 1:
            continue  # X at neither end: the set is not simply "everything else"

        def make(ids, scene, items=items, bigger=bigger, pattern=pattern, sel_k=sel_k):
            word = pick(rng, BIGGER_WORDS if bigger else SMALLER_WORDS)
            text = pattern_sentence(rng, f"{_obj_word(rng, 'objects')} whose size {word} {items[0][0]}", pattern)
            return text, {"goals": [goal(pattern, [ids[k] for k in sel_k])]}, ()

        made += b.add(rng, "lgmcts-whose-size", items, make)


def _pair_items(rng: random.Random, k: int) -> list[tuple[str, str, float]]:
    """``k`` VIMA objects whose "texture name" descriptions are all different."""
    seen, items = set(), []
    while len(items) < k:
        n, c = pick(rng, VIMA_NAMES), pick(rng, VIMA_TEXTURES)
        if (n, c) not in seen:
            seen.add((n, c))
            items.append((n, c, round(rng.uniform(0.9, 1.1), 3)))
    return items


def fam_pair(b: Builder, rng: random.Random, n: int) -> None:
    made = 0
    rels = list(PAIR_WORDS)
    while made < n:
        rel = rels[made % len(rels)]
        words = PAIR_WORDS[rel] + PAIR_WORDS_OLD.get(rel, ())
        items = _pair_items(rng, rng.randint(5, 9))
        refuse = rng.random() < 0.08

        def make(ids, scene, items=items, rel=rel, words=words, refuse=refuse):
            a, c = items[0], items[1]
            if refuse:  # the anchor is not in the scene
                absent = pick(rng, [x for x in VIMA_NAMES if x not in {it[0] for it in items}])
                text = f"{pick(rng, PUT)} {a[1]} {a[0]} {pick(rng, words)} {c[1]} {absent}"
                return text, None, ()
            text = f"{pick(rng, PUT)} {a[1]} {a[0]} {pick(rng, words)} {c[1]} {c[0]}"
            return text, {"goals": [{"pattern": rel, "objects": [ids[0]], "anchor": ids[1]}]}, ()

        made += b.add(rng, "lgmcts-pair", items, make)


def fam_vertical(b: Builder, rng: random.Random, n: int) -> None:
    made = 0
    words = list(VERTICAL)
    while made < n:
        w = words[made % len(words)]
        items = _pair_items(rng, rng.randint(5, 8))

        def make(ids, scene, items=items, w=w):
            a, c = items[0], items[1]
            text = f"{pick(rng, PUT)} {a[1]} {a[0]} {w} {c[1]} {c[0]}"
            order = [ids[1], ids[0]] if VERTICAL[w] == "top" else [ids[0], ids[1]]
            return text, {"goals": [goal("tower", order)]}, ()

        made += b.add(rng, "lgmcts-pair-vertical", items, make)


def fam_composite(b: Builder, rng: random.Random, n: int) -> None:
    """A pattern over "objects whose color ... X" and a pair whose anchor is one of the pattern's objects."""
    made = 0
    while made < n:
        pattern = pick(rng, ("line", "circle"))
        items, ca, cb = _two_colour_scene(rng, rng.randint(3, 5), rng.randint(2, 4))
        word = pick(rng, EQUAL_WORDS)
        rel = pick(rng, list(PAIR_WORDS))
        anchor_k = rng.randrange(0, sum(it[1] == ca for it in items))
        mover_k = len(items) - 1 - rng.randrange(sum(it[1] == cb for it in items))

        def make(ids, scene, items=items, word=word, rel=rel, pattern=pattern, anchor_k=anchor_k, mover_k=mover_k):
            descr = [f"{it[1]} {it[0]}" for it in items]
            if descr.count(descr[anchor_k]) > 1 or descr.count(descr[mover_k]) > 1:
                return None
            objs = f"{_obj_word(rng, 'objects')} whose color {word} {items[0][0]}"
            p1 = pattern_sentence(rng, objs, pattern)
            p2 = f"{pick(rng, PUT)} {descr[mover_k]} {pick(rng, PAIR_WORDS[rel])} {descr[anchor_k]}"
            parts = [p1, p2]
            rng.shuffle(parts)
            text = parts[0] + pick(rng, CORRELATIVES) + parts[1]
            sel = [ids[k] for k, it in enumerate(items) if it[1] == items[0][1]]
            g = [goal(pattern, sel), {"pattern": rel, "objects": [ids[mover_k]], "anchor": ids[anchor_k]}]
            return text, {"goals": g}, ()

        made += b.add(rng, "lgmcts-composite", items, make)


def fam_two_patterns(b: Builder, rng: random.Random, n: int) -> None:
    made = 0
    while made < n:
        p1, p2 = pick(rng, ("line", "circle")), pick(rng, ("line", "circle"))
        items, _ca, cb = _two_colour_scene(rng, rng.randint(3, 4), rng.randint(3, 4))
        k2 = next(k for k, it in enumerate(items) if it[1] == cb)
        if sum(it[0] == items[k2][0] for it in items) > 1:
            continue

        def make(ids, scene, items=items, p1=p1, p2=p2, k2=k2):
            s1 = pattern_sentence(rng, f"objects whose color {pick(rng, EQUAL_WORDS)} {items[0][0]}", p1)
            s2 = pattern_sentence(rng, f"objects whose color {pick(rng, EQUAL_WORDS)} {items[k2][0]}", p2)
            text = s1 + pick(rng, CORRELATIVES) + s2
            g1 = [ids[k] for k, it in enumerate(items) if it[1] == items[0][1]]
            g2 = [ids[k] for k, it in enumerate(items) if it[1] == items[k2][1]]
            return text, {"goals": [goal(p1, g1), goal(p2, g2)]}, ()

        made += b.add(rng, "lgmcts-two-patterns", items, make)


# ---------------------------------------------------------------- StructFormer families
ROWS, COLS = ("bottom", "middle", "top"), ("right", "center", "left")
FACING = ("north", "east", "south", "west")


def structure_sentence(rng: random.Random, shape: str) -> tuple[str, dict]:
    """StructFormer's structure sentence with each part present or not; returns it and the goal params."""
    params: dict = {}
    size = pick(rng, ("small", "medium", "large")) if shape in ("circle", "line") and rng.random() < 0.6 else None
    region = (pick(rng, ROWS), pick(rng, COLS)) if rng.random() < 0.6 else None
    facing = pick(rng, FACING) if rng.random() < 0.5 else None
    s = ""
    if size:
        s += size
        params["size"] = size
    s += f" {shape}"
    if region:
        s += f" in the {region[0]} {region[1]} of the table"
        params["region"] = f"{region[0]} {region[1]}"
    if facing:
        s += f" facing {facing}"
        params["facing"] = facing
    return s.strip(), params


def _join(rng: random.Random, selection: str, structure: str) -> str:
    return f"{selection} {structure}" if rng.random() < 0.7 else f"{structure}. {selection}"


def _house_items(rng: random.Random, groups: list[tuple[str, str | None, int]], n_distract: int,
                 avoid_names=(), avoid_colors=()) -> list[tuple[str, str, float]]:
    items = []
    for name, color, k in groups:
        for _ in range(k):
            items.append((name, color or pick(rng, HOUSE_COLORS), round(rng.uniform(0.85, 1.2), 3)))
    for _ in range(n_distract):
        nm = pick(rng, [x for x in HOUSE_NAMES if x not in avoid_names])
        items.append((nm, pick(rng, [c for c in HOUSE_COLORS if c not in avoid_colors]), round(rng.uniform(0.85, 1.2), 3)))
    return items


def _sf_goal(shape: str, sel: list[int], params: dict) -> dict:
    if shape == "tower":
        return goal("tower", sel, unordered=True, **params)
    return goal(shape, sel, **params)


def fam_sf_select(b: Builder, rng: random.Random, n: int, by: str) -> None:
    made = 0
    family = f"structformer-select-{by}"
    while made < n:
        shape = pick(rng, ("circle", "line", "line", "circle", "tower"))
        k = rng.randint(3, 5) if shape != "tower" else rng.randint(2, 4)
        refuse = rng.random() < 0.08
        if by == "color":
            color = pick(rng, HOUSE_COLORS)
            groups = [(pick(rng, HOUSE_NAMES[:7]), color, 1) for _ in range(k)]
            items = _house_items(rng, groups, rng.randint(2, 5), avoid_colors=(color,))
            word = color if not refuse else pick(rng, [c for c in HOUSE_COLORS if c not in {it[1] for it in items}] or ["violet"])
            key = 1
        else:
            name = pick(rng, ("mug", "cup", "can", "bowl", "box", "bottle", "jar", "glass"))
            items = _house_items(rng, [(name, None, k)], rng.randint(2, 5), avoid_names=(name,))
            word = name if not refuse else pick(rng, [x for x in HOUSE_NAMES if x not in {it[0] for it in items}] or ["teapot"])
            key = 0

        def make(ids, scene, items=items, word=word, key=key, shape=shape, refuse=refuse):
            struct, params = structure_sentence(rng, shape)
            text = _join(rng, f"select objects that are {word}.", struct)
            if refuse:
                return text, None, ()
            sel = [ids[j] for j, it in enumerate(items) if it[key] == word]
            if len(sel) < MIN_OBJECTS[shape]:
                return None
            return text, {"goals": [_sf_goal(shape, sel, params)]}, ("params",) if params else ()

        made += b.add(rng, family, items, make)


def fam_sf_compare(b: Builder, rng: random.Random, n: int) -> None:
    made = 0
    while made < n:
        comp = pick(rng, ("greater", "less", "equal"))
        attr = pick(rng, ("height", "volume", "volumn"))
        shape = pick(rng, ("circle", "line", "line", "tower"))
        anchor_name = pick(rng, HOUSE_NAMES)
        anchor = (anchor_name, pick(rng, HOUSE_COLORS), round(rng.uniform(0.9, 1.1), 3))
        items = [anchor]
        if comp == "equal":  # same category at the same scale, other colours
            for c in rng.sample([c for c in HOUSE_COLORS if c != anchor[1]], rng.randint(3, 4)):
                items.append((anchor_name, c, anchor[2]))
        items += _house_items(rng, [], rng.randint(4, 7), avoid_names=(anchor_name,))
        measure = height if attr == "height" else volume
        vals = [measure(shape_of(nm, s)) for nm, _, s in items]
        a = vals[0]
        if any(v != a and abs(v - a) < 0.1 * a for v in vals[1:]):
            continue  # no near ties: the comparison must be clear to the eye
        des_object = sum(it[1] == anchor[1] for it in items) == 1 and rng.random() < 0.3
        if not des_object and sum(it[:2] == anchor[:2] for it in items) > 1:
            continue

        def make(ids, scene, items=items, comp=comp, attr=attr, shape=shape, vals=vals, des_object=des_object):
            des = f"{items[0][1]} object" if des_object else f"{items[0][1]} {items[0][0]}"
            jun = "as" if comp == "equal" else "than"
            sel_text = f"select objects that have {comp} {attr} {jun} the {des}."
            test = {"greater": lambda v: v > vals[0], "less": lambda v: v < vals[0], "equal": lambda v: v == vals[0]}[comp]  # noqa: B023 (used in this iteration)
            sel = [ids[j] for j in range(1, len(items)) if test(vals[j])]
            if not sel:
                struct, params = structure_sentence(rng, shape)
                return _join(rng, sel_text, struct), None, ()
            if len(sel) < MIN_OBJECTS[shape] or len(sel) > 7:
                return None
            struct, params = structure_sentence(rng, shape)
            return _join(rng, sel_text, struct), {"goals": [_sf_goal(shape, sel, params)]}, ("params",) if params else ()

        made += b.add(rng, "structformer-compare", items, make)


def fam_sf_same_color(b: Builder, rng: random.Random, n: int) -> None:
    made = 0
    while made < n:
        shape = pick(rng, ("circle", "line", "line", "tower"))
        color = pick(rng, HOUSE_COLORS)
        k = rng.randint(3, 5)
        anchor_name = pick(rng, HOUSE_NAMES)
        groups = [(anchor_name, color, 1)] + [(pick(rng, [x for x in HOUSE_NAMES if x != anchor_name]), color, 1) for _ in range(k)]
        items = _house_items(rng, groups, rng.randint(2, 4), avoid_colors=(color,))

        def make(ids, scene, items=items, shape=shape):
            struct, params = structure_sentence(rng, shape)
            text = _join(rng, f"select objects that have the same color as the {items[0][1]} {items[0][0]}.", struct)
            sel = [ids[j] for j in range(1, len(items)) if items[j][1] == items[0][1]]
            return text, {"goals": [_sf_goal(shape, sel, params)]}, ("params",) if params else ()

        made += b.add(rng, "structformer-same-color", items, make)


def fam_sf_dinner(b: Builder, rng: random.Random, n: int) -> None:
    made = 0
    while made < n:
        cut = rng.sample(CUTLERY, rng.randint(2, 3))
        items = [("plate", pick(rng, HOUSE_COLORS), 1.0), ("bowl", pick(rng, HOUSE_COLORS), 0.9)]
        items += [(c, "silver", round(rng.uniform(0.95, 1.05), 3)) for c in cut]
        items += _house_items(rng, [], rng.randint(1, 3), avoid_names=("plate", "bowl"))

        def make(ids, scene, items=items, cut=cut):
            struct, params = structure_sentence(rng, "dinner")
            utensils = [ids[2 + j] for j in range(len(cut))]
            alts = []
            for side in ("left", "right"):
                alts.append({"goals": [goal("tower", [ids[0], ids[1]], **params), goal("line", utensils),
                                       {"pattern": side, "objects": sorted(utensils), "anchor": ids[0]}]})
            return struct, {"any_of": alts}, ("params",) if params else ()

        made += b.add(rng, "structformer-dinner", items, make)


# ---------------------------------------------------------------- splits and output
def assign_splits(cases: list[dict], seed: int = SEED) -> None:
    """About 35 % of each family "dev", the rest "test", drawn with ``seed``; every family gets both."""
    fams: dict[str, list[dict]] = {}
    for c in cases:
        fams.setdefault(c["family"], []).append(c)
    for fam in sorted(fams):
        group = fams[fam]
        rng = random.Random(f"{seed}:{fam}")
        k = min(len(group) - 1, max(1, round(DEV_SHARE * len(group))))
        dev = set(rng.sample(range(len(group)), k))
        for i, c in enumerate(group):
            c["split"] = "dev" if i in dev else "test"


def build() -> list[dict]:
    b = Builder()
    rng = random.Random(SEED)
    fam_whose(b, rng, "lgmcts-whose-equal", EQUAL_WORDS, True, 45)
    fam_whose(b, rng, "lgmcts-whose-different", DIFF_WORDS, False, 35)
    fam_with_attr(b, rng, 36)
    fam_objects_compare_attr(b, rng, 10)
    fam_pair(b, rng, 40)
    fam_vertical(b, rng, 16)
    fam_composite(b, rng, 36)
    fam_two_patterns(b, rng, 14)
    fam_sf_select(b, rng, 28, "color")
    fam_sf_select(b, rng, 28, "class")
    fam_sf_compare(b, rng, 34)
    fam_sf_same_color(b, rng, 18)
    fam_sf_dinner(b, rng, 12)
    fam_whose_size(b, rng, 14)
    assign_splits(b.cases)
    return b.lines


def _write(lines: list[dict], path: Path) -> None:
    path.write_text("".join(json.dumps(x, separators=(", ", ": ")) + "\n" for x in lines))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--splits-only", type=Path, help="assign splits of this hand-written case file in place")
    ap.add_argument("-o", "--output", type=Path, default=OUT)
    args = ap.parse_args()
    if args.splits_only:
        rows = [json.loads(x) for x in args.splits_only.read_text().splitlines() if x.strip()]
        assign_splits([r for r in rows if "scene_id" not in r])
        _write(rows, args.splits_only)
        return
    lines = build()
    _write(lines, args.output)
    cases = [x for x in lines if "scene_id" not in x]
    print(f"wrote {len(cases)} cases over {len(lines) - len(cases)} scenes to {args.output}")


if __name__ == "__main__":
    main()
