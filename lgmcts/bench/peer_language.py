"""Instructions in the peers' own sentence templates (``--instructions peer``).

The suites' default instructions are written by this project. With
``instructions="peer"`` every task keeps its scene, goals and start state and
gets a new instruction, phrased from its ground-truth goals with the template
families of the peers' public code (re-implemented here, same wording and
semantics):

* LGMCTS-D's pattern sentences "{Put|Place|Leave} {objects} {at|in|on} a
  {pattern} pattern", "{verb} a {pattern} pattern using {objects}" and
  "Select {objects}, and {verb} them {prep} a {pattern} pattern"; its object
  sets "objects whose color is equal to / is same as / is identical to / is
  alike / is equivalent to X" (X, named by its category, is in the set),
  "objects whose color is different from ... X" (every object of another
  colour), the older "Objects with/of/has the same/similar shape as X" (every
  object of X's category), and plain lists "red block, blue star" (a
  description shared by two objects said twice: both are meant); its pair
  sentences "{verb} {colour} {name} {relation} {colour} {name}" with the
  relation words of its nine-point spatial vocabulary ("left to", "in front
  left of", "right behind of", "on", "under"...); its connectives "; then ",
  "; and ", "; while ", "; so ", "; ", the sentences in random order;
* StructFormer's "select objects that are {class}." followed by its
  structure sentence (here only the shape word: the suites' goals carry no
  size, region or facing).

Every phrase is checked against the scene with the peers' semantics: it is
used only when it means exactly the goal's objects. The phrasing is drawn
from its own random stream (from the task seed), so a task's scene and goals
are the same in both modes.
"""

from __future__ import annotations

import dataclasses
import itertools
from collections.abc import Callable

import numpy as np

from .tasks import Task

__all__ = ["MODES", "peer_instruction", "rephrase"]

#: Instruction modes of the suite generators.
MODES = ("ours", "peer")

# The peers' template vocabulary (LGMCTS-D), shared with scripts/make_eval_cases.py.
PUT = ("Put", "Place", "Leave")
PREP = ("at", "in", "on")
CONNECTIVES = ("; then ", "; and ", "; while ", "; so ", "; ")
EQUAL_WORDS = ("is equal to", "is same as", "is identical to", "is alike", "is equivalent to")
DIFF_WORDS = ("is different with", "is not the same as", "is not equal to", "is not identical to", "is not alike",
              "is not equivalent to", "is different from")
PAIR_WORDS = {
    "left": ("left to",),
    "right": ("right to",),
    "front": ("in front of",),
    "behind": ("behind", "in back of"),
    "left_front": ("in front left of", "in left front of", "left and front of"),
    "right_front": ("in front right of", "in right front of", "right and front of"),
    "left_behind": ("behind left of", "left behind of", "left and behind of"),
    "right_behind": ("behind right of", "right behind of", "right and behind of"),
}


def _pick(rng: np.random.Generator, seq):
    return seq[int(rng.integers(len(seq)))]


class _Scene:
    def __init__(self, scene: dict) -> None:
        self.objs = {int(o["id"]): (str(o["name"]), str(o.get("color", ""))) for o in scene["objects"]}

    def name_unique(self, i: int) -> bool:
        return sum(n == self.objs[i][0] for n, _ in self.objs.values()) == 1

    def desc(self, i: int, allowed: set[int] | None = None) -> str | None:
        """ "colour name", when no other object has both (or, with ``allowed``, all that have both are allowed)."""
        n, c = self.objs[i]
        same = {j for j, v in self.objs.items() if v == (n, c)}
        if same != {i} and (allowed is None or not same <= allowed):
            return None
        return f"{c} {n}".strip()

    def with_color(self, c: str) -> set[int]:
        return {i for i, (_, cc) in self.objs.items() if cc == c}

    def with_name(self, n: str) -> set[int]:
        return {i for i, (nn, _) in self.objs.items() if nn == n}


def _object_set(sc: _Scene, ids: list[int], rng: np.random.Generator) -> str | None:
    """Words for exactly the objects ``ids`` in one of LGMCTS-D's forms, or None."""
    want = set(ids)
    forms: list[Callable[[], str | None]] = []
    colors = {sc.objs[i][1] for i in want}
    names = {sc.objs[i][0] for i in want}
    if len(colors) == 1:
        (c,) = colors
        refs = [i for i in sorted(want) if sc.name_unique(i)]
        if sc.with_color(c) == want and refs:
            forms.append(lambda: f"objects whose color {_pick(rng, EQUAL_WORDS)} {sc.objs[_pick(rng, refs)][0]}")
        others = [i for i in sorted(sc.objs) if i not in want and sc.name_unique(i)]
        diff_refs = [i for i in others if {j for j in sc.objs if sc.objs[j][1] != sc.objs[i][1]} == want]
        if diff_refs:
            forms.append(lambda: f"objects whose color {_pick(rng, DIFF_WORDS)} {sc.objs[_pick(rng, diff_refs)][0]}")
    if len(names) == 1:
        (n,) = names
        if sc.with_name(n) == want:
            forms.append(
                lambda: (
                    f"Objects {_pick(rng, ('with', 'of', 'has'))} {_pick(rng, ('the same', 'similar'))} shape as {n}"
                )
            )
    # A plain list; a description shared by several objects is said once for each (all of them are meant).
    descs = [sc.desc(i, want) for i in ids]
    if all(descs):

        def plain() -> str:
            order = [descs[k] for k in rng.permutation(len(descs))]
            return ", ".join(order)

        forms.append(plain)
    if not forms:
        return None
    return _pick(rng, forms)()


def _pattern_sentence(objs: str, pattern: str, rng: np.random.Generator) -> str:
    verb, prep = _pick(rng, PUT), _pick(rng, PREP)
    return _pick(
        rng,
        (
            f"{verb} {objs} {prep} a {pattern} pattern",
            f"{verb} a {pattern} pattern using {objs}",
            f"Select {objs}, and {_pick(rng, PUT)} them {_pick(rng, PREP)} a {pattern} pattern",
        ),
    )


def _pair(sc: _Scene, a: int, b: int, words: tuple[str, ...], rng: np.random.Generator) -> str | None:
    da, db = sc.desc(a), sc.desc(b)
    if da is None or db is None:
        return None
    return f"{_pick(rng, PUT)} {da} {_pick(rng, words)} {db}"


def _goal_sentences(sc: _Scene, g: dict, rng: np.random.Generator) -> list[str] | None:
    p, ids = g["pattern"], [int(i) for i in g["objects"]]
    if p in PAIR_WORDS:
        pairs = [_pair(sc, i, int(g["anchor"]), PAIR_WORDS[p], rng) for i in ids]
        return None if None in pairs else [s for s in pairs if s is not None]
    if p == "tower":
        levels: list[str | None] = []
        for lo, hi in itertools.pairwise(ids):
            s = _pair(sc, hi, lo, ("on",), rng) if rng.random() < 0.7 else _pair(sc, lo, hi, ("under", "below"), rng)
            levels.append(s)
        return None if None in levels else [s for s in levels if s is not None]
    objs = _object_set(sc, ids, rng)
    if objs is None:
        return None
    return [_pattern_sentence(objs, p, rng)]


def _structformer_selection(sc: _Scene, g: dict, rng: np.random.Generator) -> str | None:
    ids = {int(i) for i in g["objects"]}
    names = {sc.objs[i][0] for i in ids}
    if g["pattern"] in ("line", "circle") and len(names) == 1:
        (n,) = names
        if sc.with_name(n) == ids:
            return f"select objects that are {n}. {g['pattern']}"
    return None


def peer_instruction(task: Task, rng: np.random.Generator) -> str | None:
    """The task's goals in the peers' templates, or None when a goal has no exact peer phrasing."""
    sc = _Scene(task.scene)
    goals = task.goals["goals"]
    if task.suite == "structformer" and len(goals) == 1 and rng.random() < 0.5:
        s = _structformer_selection(sc, goals[0], rng)
        if s is not None:
            return s
    # A line and a relation over the same objects (place settings) say the line once.
    sentences: list[str] = []
    for g in goals:
        out = _goal_sentences(sc, g, rng)
        if out is None:
            return None
        sentences += out
    order = rng.permutation(len(sentences))
    text = sentences[order[0]]
    for k in order[1:]:
        text += _pick(rng, CONNECTIVES) + sentences[k]
    return text


def rephrase(task: Task, mode: str) -> Task:
    """``task`` with its instruction in ``mode`` ("ours": unchanged; "peer": the peers' templates).

    A task whose goals no peer phrasing names exactly keeps its own
    instruction; its ``instructions`` field then stays "ours".
    """
    if mode == "ours":
        return task
    if mode != "peer":
        raise ValueError(f"unknown instruction mode {mode}")
    rng = np.random.default_rng([task.seed, 0x9EE8])
    text = peer_instruction(task, rng)
    new_id = task.id.replace(f"{task.suite}-", f"{task.suite}-peer-", 1)
    if text is None:
        return dataclasses.replace(task, id=new_id)
    return dataclasses.replace(task, instruction=text, instructions="peer", id=new_id)
