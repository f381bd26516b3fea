"""StructFormer-style suite: one pattern per task over household objects.

Task
    ``line`` / ``circle``: put every object of one category (or a listed
    few) in a line / circle. ``tower``: stack three or four objects, the
    first named at the bottom. ``dinner``: stack a bowl (or two) on a plate
    and line the cutlery up beside the plate; its goals are a tower, a line
    and a spatial relation (every utensil to the left or right of the plate).
Randomisations
    Categories, colours, sizes, number of objects, distractors, layout and
    the phrasing of the instruction.
Start state
    Objects scattered on the table without overlap; the goal objects are
    rebuilt from a final arrangement that meets the goals (checked with
    :func:`lgmcts.validate.goal_satisfied`), so every task is solvable.
Success
    As in the paper's Table 1: the goal arrangement is collision-free and
    meets the pattern (validator), and here also after execution in physics.
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from ..formats import parse_goals, parse_scene
from ..scene import TABLE, Scene
from ..validate import goal_satisfied
from .catalog import PLAIN_COLORS, kind, scale
from .layout import Layout, pattern_poses, scene_of
from .tasks import Task

__all__ = ["CATEGORIES", "WORKSPACE", "generate_task"]

WORKSPACE = {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}
CATEGORIES: tuple[str, ...] = ("line", "circle", "tower", "dinner")
_GROUP = ("mug", "cup", "can", "bowl", "box", "block", "bottle")
_DISTRACT = ("mug", "cup", "can", "bowl", "box", "block", "bottle", "plate")
_CUTLERY = ("fork", "knife", "spoon")

_TEMPLATES = {
    "line": ("Put {x} in a line", "Arrange {x} in a straight line", "Line up {x}", "Place {x} in a row"),
    "circle": ("Put {x} in a circle", "Arrange {x} in a circle", "Place {x} in a ring", "Form a circle with {x}"),
}


def generate_task(category: str, seed: int, *, task_id: str | None = None) -> Task:
    """Build the StructFormer-style task of ``category`` from ``seed`` (deterministic)."""
    if category not in CATEGORIES:
        raise ValueError(f"unknown StructFormer category {category}")
    rng = np.random.default_rng(seed)
    for _ in range(300):
        t = _attempt(category, rng)
        if t is not None:
            scene, instruction, goals, final, final_on = t
            return Task(
                id=task_id or f"structformer-{seed}",
                seed=seed,
                suite="structformer",
                category=category,
                scene=scene,
                instruction=instruction,
                goals=goals,
                final=final,
                final_on=final_on,
                start={},
            )
    raise RuntimeError(f"could not build a StructFormer task for seed {seed}")  # pragma: no cover


def _obj(name: str, color: str, rng: np.random.Generator, s: float | None = None) -> dict:
    return {"name": name, "color": color, "shape": kind(name).make(scale(rng) if s is None else s)}


def _pick(rng: np.random.Generator, pool) -> str:
    return str(pool[int(rng.integers(len(pool)))])


def _the(o: dict) -> str:
    return f"the {o['color']} {o['name']}"


def _attempt(category: str, rng: np.random.Generator):  # noqa: C901 - one recipe per category
    objs: list[dict] = []
    goal_idx: list[list[int]] = []
    if category in ("line", "circle"):
        name = _pick(rng, _GROUP)
        n = int(rng.integers(3, 7)) if category == "line" else int(rng.integers(4, 7))
        for _ in range(n):
            objs.append(_obj(name, _pick(rng, PLAIN_COLORS), rng))
        goal_idx.append(list(range(n)))
        others = [c for c in _DISTRACT if c != name]
        for _ in range(int(rng.integers(2, 6))):
            objs.append(_obj(_pick(rng, others), _pick(rng, PLAIN_COLORS), rng))
        x = f"all {kind(name).plural}" if rng.random() < 0.5 else f"all the {kind(name).plural}"
        instruction = _pick(rng, _TEMPLATES[category]).format(x=x)
    elif category == "tower":
        n = int(rng.integers(3, 5))
        name = _pick(rng, ("block", "box", "bowl"))
        sizes = sorted(rng.uniform(0.8, 1.15, n), reverse=True)
        colors = list(rng.permutation(PLAIN_COLORS)[:n])
        for k in range(n):
            objs.append(_obj(name, str(colors[k]), rng, float(sizes[k])))
        goal_idx.append(list(range(n)))
        for _ in range(int(rng.integers(2, 6))):
            other = _pick(rng, [c for c in _DISTRACT if c != name])
            objs.append(_obj(other, _pick(rng, PLAIN_COLORS), rng))
        names = [_the(objs[k]) for k in range(n)]
        lst = ", ".join(names[:-1]) + " and " + names[-1]
        instruction = str(rng.choice([
            f"Build a tower of {lst}, from the bottom up",
            f"Put {lst} in a tower, the first one at the bottom",
            f"Pile up {lst}, from the bottom up",
        ]))
    else:  # dinner
        plate_color, bowl_color = _pick(rng, PLAIN_COLORS), _pick(rng, PLAIN_COLORS)
        objs.append(_obj("plate", plate_color, rng, float(rng.uniform(0.95, 1.1))))
        objs.append(_obj("bowl", bowl_color, rng, float(rng.uniform(0.85, 0.95))))
        tower = [0, 1]
        if rng.random() < 0.4:
            objs.append(
                {
                    "name": "bowl",
                    "color": _pick(rng, [c for c in PLAIN_COLORS if c != bowl_color]),
                    "shape": kind("bowl").make(0.68),
                }
            )
            tower.append(2)
        cut = list(rng.permutation(_CUTLERY)[: int(rng.integers(2, 4))])
        cut_idx = []
        for c in cut:
            objs.append(_obj(str(c), "silver", rng, float(rng.uniform(0.9, 1.05))))
            cut_idx.append(len(objs) - 1)
        goal_idx += [tower, cut_idx]
        for _ in range(int(rng.integers(1, 4))):
            objs.append(_obj(_pick(rng, ("mug", "cup", "can", "box", "bottle")), _pick(rng, PLAIN_COLORS), rng))
        side = _pick(rng, ("left", "right"))
        cut_words = ", ".join(f"the {c}" for c in cut[:-1]) + f" and the {cut[-1]}"
        bowls = " and ".join(_the(objs[k]) for k in tower[1:])
        plate = _the(objs[0])
        tower_words = ", ".join(_the(objs[k]) for k in tower[:-1]) + " and " + _the(objs[tower[-1]])
        instruction = str(
            rng.choice(
                [
                    f"Stack {bowls} on {plate}; and put {cut_words} in a line; and put {cut_words} to the "
                    f"{side} of the plate",
                    f"Put {tower_words} in a tower; then put {cut_words} in a line to the {side} of {plate}",
                    f"Build a tower of {tower_words}, from the bottom up; and arrange {cut_words} in a row on "
                    f"the {side} side of the plate",
                ]
            )
        )
    n = len(objs)
    perm = rng.permutation(n)
    for k, o in enumerate(objs):
        o["id"] = int(perm[k]) + 1
    ids = [o["id"] for o in objs]
    scene = scene_of(WORKSPACE, [{k: o[k] for k in ("id", "name", "color", "shape")} for o in objs])

    # Final arrangement.
    layout = Layout(scene, gap=0.01)
    final_on = dict.fromkeys(range(n), TABLE)
    if category in ("line", "circle"):
        for _ in range(40):
            poses = pattern_poses(category, goal_idx[0], scene, rng)
            trial = Layout(scene, gap=0.01)
            if all(trial.try_put(i, p) for i, p in zip(goal_idx[0], poses)):
                for i, p in zip(goal_idx[0], poses):
                    layout.put(i, p)
                break
        else:
            return None
        goals = [{"pattern": category, "objects": [ids[i] for i in goal_idx[0]]}]
    elif category == "tower":
        t = goal_idx[0]
        if layout.random(t[0], rng) is None:
            return None
        for a, b in itertools.pairwise(t):
            layout.poses[b] = np.array([*layout.poses[t[0]][:2], rng.uniform(-math.pi, math.pi)])
            final_on[b] = a
        goals = [{"pattern": "tower", "objects": [ids[i] for i in t]}]
    else:
        tower, cut_idx = goal_idx
        base = tower[0]
        rp = float(scene.radii[base])
        for _ in range(60):
            c = np.array([rng.uniform(-0.22, 0.22), rng.uniform(-0.15, 0.15)])
            sgn = 1.0 if side == "right" else -1.0
            step = 0.045
            x0 = c[0] + sgn * (rp + 0.04)
            cposes = [
                np.array([x0 + sgn * k * step, c[1] + rng.uniform(-0.003, 0.003), math.pi / 2])
                for k in range(len(cut_idx))
            ]
            trial = Layout(scene, gap=0.01)
            if trial.try_put(base, np.array([c[0], c[1], 0.0])) and all(
                trial.try_put(i, p) for i, p in zip(cut_idx, cposes)
            ):
                for i in trial.poses:
                    layout.put(i, trial.poses[i])
                break
        else:
            return None
        for a, b in itertools.pairwise(tower):
            layout.poses[b] = np.array([*layout.poses[base][:2], rng.uniform(-math.pi, math.pi)])
            final_on[b] = a
        goals = [
            {"pattern": "tower", "objects": [ids[i] for i in tower]},
            {"pattern": "line", "objects": [ids[i] for i in cut_idx]},
            {"pattern": side, "objects": [ids[i] for i in cut_idx], "anchor": ids[base]},
        ]
    for i in range(n):
        if i not in layout.poses and layout.random(i, rng) is None:
            return None
    final = np.array([layout.poses[i] for i in range(n)])
    on_t = tuple(final_on[i] for i in range(n))
    gspec = parse_goals({"goals": goals})
    if any(goal_satisfied(g, scene, final, on_t) is not None for g in gspec.goals):
        return None

    # Start: every goal object scattered, distractors where they end.
    movers = {i for m in goal_idx for i in m}
    start = Layout(scene, gap=0.01)
    for i in range(n):
        if i not in movers:
            start.put(i, final[i])
    for i in sorted(movers):
        if start.random(i, rng) is None:
            return None
    objs_out = []
    for i in sorted(range(n), key=lambda i: ids[i]):
        o = objs[i]
        objs_out.append(
            {
                "id": ids[i],
                "name": o["name"],
                "color": o["color"],
                "shape": o["shape"],
                "pose": [round(float(v), 5) for v in start.poses[i]],
                "on": None,
            }
        )
    scene_dict = {"workspace": WORKSPACE, "objects": objs_out}
    st = Scene.from_spec(parse_scene(scene_dict))
    if all(goal_satisfied(g, st, st.initial.poses, st.initial.on) is None for g in gspec.goals):
        return None
    final_d = {str(ids[i]): [float(v) for v in final[i]] for i in range(n)}
    final_on_d = {str(ids[i]): ids[final_on[i]] for i in range(n) if final_on[i] != TABLE}
    return scene_dict, instruction, {"goals": goals}, final_d, final_on_d
