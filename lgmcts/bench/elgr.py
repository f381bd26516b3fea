"""ELGR-style suite: two composed patterns, infeasible starts, templated language.

Task
    Bring a scene of VIMA-like objects (blocks, bowls, letters, hearts,
    stars...) to a state meeting two pattern goals named in one instruction,
    e.g. "Put all blocks in a line; and place the red swirl flower to the left
    of the granite letter A". The category is the pair of pattern kinds, one
    of the 10 unordered pairs of ``line``, ``circle``, ``rectangle`` and
    ``spatial`` (one of the 8 relations).
Randomisations
    Object categories, colours/textures and sizes; which objects a goal uses
    and how the instruction names them (a category, a colour, "the same colour
    as" another object, or a list); pattern sizes; the phrasing of each
    sub-instruction and the connective ("; and", " while ", "; then ",
    ". Also"); the layout.
Start state
    Built backwards from a final arrangement that meets every goal
    (checked with :func:`lgmcts.validate.goal_satisfied`): objects that must
    move are scattered, at least one object is stacked on an object that must
    move, and at least one other object lies where a goal object ends in that
    arrangement.
Dense variant (suite ``elgr-dense``)
    The same task (same scene objects, poses, instruction and goals) plus
    6-12 extra objects packed edge to edge around the goal region, touching
    within micrometres and overlapping nothing (:func:`_densify`).
Success
    The ground-truth goals hold after the plan (validator) and after its
    execution in physics (SR_p and SR_ep).
"""

from __future__ import annotations

import math
from itertools import combinations_with_replacement
from typing import Any

import numpy as np
import shapely

from ..formats import RELATIONS, parse_goals, parse_scene
from ..scene import TABLE, Scene
from ..validate import goal_satisfied
from .catalog import PLAIN_COLORS, VIMA_COLORS, VIMA_KINDS, color_words, kind, scale
from .layout import Layout, pattern_poses, relation_pose, scene_of
from .refs import phrase, unambiguous
from .tasks import Task

__all__ = ["CATEGORIES", "WORKSPACE", "generate_task"]

WORKSPACE = {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}
_KINDS = ("line", "circle", "rectangle", "spatial")
#: The 10 unordered pairs of pattern kinds.
CATEGORIES: tuple[str, ...] = tuple(f"{a}+{b}" for a, b in combinations_with_replacement(_KINDS, 2))
_SIZES = {"line": (3, 5), "circle": (3, 5), "rectangle": (4, 5)}

_SHAPE_TEMPLATES = {
    "line": (
        "Place {x} in a line pattern",
        "Put {x} in a line",
        "Arrange {x} in a straight line",
        "Line up {x}",
        "Move {x} into a row",
    ),
    "circle": (
        "Put {x} in a circle",
        "Arrange {x} in a circle pattern",
        "Move {x} into a circle",
        "Place {x} in a ring",
        "Form a circle with {x}",
    ),
    "rectangle": (
        "Place {x} in a rectangle pattern",
        "Arrange {x} in a rectangle",
        "Put {x} into a rectangle",
        "Move {x} to form a rectangular frame",
        "Set {x} on the perimeter of a rectangle",
    ),
}
_SPATIAL_TEMPLATES = ("Put {a} {rel} {b}", "Place {a} {rel} {b}", "Move {a} {rel} {b}", "Set {a} {rel} {b}")
_REL_WORDS = {
    "left": ("to the left of", "on the left side of", "left of"),
    "right": ("to the right of", "on the right side of", "right of"),
    "front": ("in front of", "at the front of"),
    "behind": ("behind", "at the back of"),
    "left_front": ("to the left and in front of", "front left of"),
    "left_behind": ("to the left and behind", "behind and to the left of"),
    "right_front": ("to the right and in front of", "front right of"),
    "right_behind": ("to the right and behind", "behind and to the right of"),
}
_CONNECTIVES = ("; and ", " while ", "; then ", ". Also ")
_PLURAL_KINDS = tuple(k.name for k in VIMA_KINDS if k.plural)
_ALL_NAMES = tuple(k.name for k in VIMA_KINDS)


def generate_task(category: str, seed: int, *, task_id: str | None = None, dense: bool = False) -> Task:
    """Build the ELGR-style task of ``category`` from ``seed`` (deterministic).

    ``dense=True`` gives the task of the dense variant (suite ``elgr-dense``):
    the same task plus touching clutter packed around the goal region
    (:func:`_densify`).
    """
    if category not in CATEGORIES:
        raise ValueError(f"unknown ELGR category {category}")
    rng = np.random.default_rng(seed)
    kinds = category.split("+")
    for _ in range(400):
        t = _attempt(kinds, rng)
        if t is not None:
            scene, instruction, goals, final, start, meanings = t
            if dense:
                scene, final, start = _densify(scene, goals, final, start, meanings, np.random.default_rng([seed, 1]))
            name = "elgr-dense" if dense else "elgr"
            return Task(
                id=task_id or f"{name}-{seed}",
                seed=seed,
                suite=name,
                category=category,
                scene=scene,
                instruction=instruction,
                goals=goals,
                final=final,
                start=start,
            )
    raise RuntimeError(f"could not build an ELGR task for seed {seed}")  # pragma: no cover


#: Extra objects the dense variant tries to pack (it keeps those that find a
#: spot in contact and leave every reference of the instruction unchanged).
DENSE_EXTRA = (6, 12)
#: Packings drawn per extra object (see :func:`_densify`).
_DENSE_TRIES = 6


def _densify(scene: dict, goals: dict, final: dict, start: dict, meanings: list, rng: np.random.Generator):
    """Add clutter packed edge to edge around the goal region of a task.

    Between 6 and 12 extra VIMA-like objects (their number, kinds, colours,
    sizes and yaws drawn from ``rng``) are slid, each from the final centre
    of a random goal object along a random ray, to the first pose where they
    overlap nothing, then bisected to within micrometres of contact
    (:func:`lgmcts.casegen.pack_clutter`). Of up to six such packings per
    object, the first that touches both a table-level object of the start scene and
    the spot of a goal object is kept, else the best drawn (touching the
    start scene counts more than touching a goal spot). They keep clear of every final
    footprint (so the arrangement the task was built from stays legal with
    the extras where they start, which is also their final pose) and of
    every start footprint, stacked objects' included (no extra stands under
    the overhang of an object resting on another). An extra whose name and colour would
    change what a reference of the instruction means is redrawn. The start
    state lists the extras under ``"packed"``.
    """
    from ..casegen import pack_clutter

    objects = [dict(o) for o in scene["objects"]]
    st = Scene.from_spec(parse_scene(scene))
    goal_ids = {i for g in goals["goals"] for i in g["objects"]}
    goal_feet: list = []
    other_feet: list = []
    start_feet: list = []
    table_feet: list = []
    for k, i in enumerate(st.ids):
        fp = shapely.polygons(st.footprint(k, np.asarray(final[str(i)], dtype=float)))
        (goal_feet if i in goal_ids else other_feet).append(fp)
        # Every start footprint, stacked ones too: an extra taller than a
        # base would otherwise stand under the overhang of the object on it.
        start_feet.append(st.initial.polys[k])
        if st.initial.on[k] == TABLE:
            table_feet.append(st.initial.polys[k])
    other_feet += start_feet

    def st_one(o: dict) -> shapely.Polygon:
        one = Scene.from_spec(parse_scene({"workspace": WORKSPACE, "objects": [o]}))
        return one.initial.polys[0]

    specs: list[dict] = []
    next_id = max(o["id"] for o in objects) + 1
    for _ in range(int(rng.integers(DENSE_EXTRA[0], DENSE_EXTRA[1] + 1))):
        for _try in range(30):
            name, color = _pick(rng, _ALL_NAMES), _pick(rng, VIMA_COLORS)
            cand = {"id": next_id, "name": name, "color": color}
            pool = objects + specs + [cand]
            if all(unambiguous(ref, pool, want) for ref, want in meanings):
                specs.append({**cand, "shape": kind(name).make(scale(rng))})
                next_id += 1
                break
    bounds = (WORKSPACE["x"][0], WORKSPACE["x"][1], WORKSPACE["y"][0], WORKSPACE["y"][1])
    packed: list[dict] = []
    real = list(table_feet)  # table-level footprints of the start scene
    for spec in specs:
        best, best_score = None, -1
        for _ in range(_DENSE_TRIES):
            got = pack_clutter(bounds, [spec], goal_feet, other_feet + real[len(table_feet) :], rng)
            if not got:
                continue
            k = st_one(got[0])
            score = 2 * (min(shapely.distance(k, q) for q in real) <= 1e-4) + (
                min(shapely.distance(k, q) for q in goal_feet) <= 1e-4
            )
            if score > best_score:
                best, best_score = (got[0], k), score
            if score == 3:
                break
        if best is not None:
            packed.append(best[0])
            real.append(best[1])
    out_scene = {**scene, "objects": objects + packed}
    out_final = {**final, **{str(o["id"]): list(o["pose"]) for o in packed}}
    return out_scene, out_final, {**start, "packed": [o["id"] for o in packed]}


def _pick(rng: np.random.Generator, pool: list[str] | tuple[str, ...]) -> str:
    return str(pool[int(rng.integers(len(pool)))])


def _attempt(kinds: list[str], rng: np.random.Generator):  # noqa: C901 - one linear recipe
    # 1. Roles and the attributes each goal reserves.
    goals: list[dict[str, Any]] = []  # {"kind", "mode", "n", "name"/"color", members (role keys)}
    reserved_names: dict[str, int] = {}  # name -> goal index that owns it
    reserved_colors: dict[str, int] = {}  # colour -> goal index that owns it
    for g, k in enumerate(kinds):
        if k == "spatial":
            goals.append({"kind": "spatial", "relation": _pick(rng, tuple(RELATIONS))})
            continue
        lo, hi = _SIZES[k]
        n = int(rng.integers(lo, hi + 1))
        mode = _pick(
            rng, ("all_name", "all_color", "same_color", "list") if n <= 4 else ("all_name", "all_color", "same_color")
        )
        spec: dict[str, Any] = {"kind": k, "mode": mode, "n": n}
        if mode == "all_name":
            free = [c for c in _PLURAL_KINDS if c not in reserved_names]
            spec["name"] = _pick(rng, free)
            reserved_names[spec["name"]] = g
        elif mode in ("all_color", "same_color"):
            taken = set().union(*(color_words(c) for c in reserved_colors)) if reserved_colors else set()
            pool = PLAIN_COLORS if rng.random() < 0.6 else VIMA_COLORS
            free = [c for c in pool if not (color_words(c) & taken)]
            spec["color"] = _pick(rng, free)
            reserved_colors[spec["color"]] = g
            if mode == "same_color":
                free_names = [c for c in _ALL_NAMES if c not in reserved_names]
                spec["ref_name"] = _pick(rng, free_names)
                reserved_names[spec["ref_name"]] = g
        goals.append(spec)

    taken_words = {c: color_words(c) for c in reserved_colors}

    def make(owner: int | None, *, name: str | None = None, color: str | None = None) -> dict:
        if name is None:
            names = [c for c in _ALL_NAMES if c not in reserved_names or reserved_names[c] == owner]
            name = _pick(rng, names)
        if color is None:
            colors = [
                c
                for c in VIMA_COLORS
                if all(not (color_words(c) & w) or reserved_colors[rc] == owner for rc, w in taken_words.items())
            ]
            color = _pick(rng, colors)
        return {"name": name, "color": color, "shape": kind(name).make(scale(rng))}

    objs: list[dict] = []
    members: list[list[int]] = []
    extra: dict[int, int] = {}  # goal -> index of its "same colour" referent
    for g, spec in enumerate(goals):
        if spec["kind"] == "spatial":
            members.append([])
            continue
        idx = []
        for _ in range(spec["n"]):
            if spec["mode"] == "all_name":
                o = make(g, name=spec["name"])
            elif spec["mode"] in ("all_color", "same_color"):
                o = make(g, color=spec["color"])
                while o["name"] == spec.get("ref_name"):
                    o = make(g, color=spec["color"])
            else:
                o = make(None)
            objs.append(o)
            idx.append(len(objs) - 1)
        members.append(idx)
        if spec["mode"] == "same_color":
            objs.append(make(g, name=spec["ref_name"], color=spec["color"]))
            extra[g] = len(objs) - 1
            idx.append(extra[g])  # the referent belongs to its "same colour" set
    # Spatial goals: a new target; the anchor new or taken from another goal.
    placed_before = [i for m in members for i in m]
    for spec in goals:
        if spec["kind"] != "spatial":
            continue
        objs.append(make(None))
        target = len(objs) - 1
        anchor_pool = placed_before + [
            i for s in goals if s["kind"] == "spatial" and "target" in s for i in (s["target"], s["anchor"])
        ]
        if anchor_pool and rng.random() < 0.6:
            anchor = int(anchor_pool[int(rng.integers(len(anchor_pool)))])
        else:
            objs.append(make(None))
            anchor = len(objs) - 1
        spec["target"], spec["anchor"] = target, anchor
    for _ in range(int(rng.integers(2, 5))):
        objs.append(make(None))
    n = len(objs)
    if n > 16:
        return None

    # 2. Ids in random order, then the references.
    perm = rng.permutation(n)
    for j, o in enumerate(objs):
        o["id"] = int(perm[j]) + 1
    ids = [o["id"] for o in objs]
    specs_by_id = sorted(objs, key=lambda o: o["id"])

    def one_ref(i: int) -> tuple | None:
        o = objs[i]
        forms = [("one", None, o["name"]), ("one", o["color"], o["name"])]
        if rng.random() < 0.6:
            forms.reverse()
        for f in forms:
            if unambiguous(f, specs_by_id, {o["id"]}):
                return f
        return None

    refs: list[tuple] = []
    sets: list[frozenset[int]] = []
    for g, spec in enumerate(goals):
        if spec["kind"] == "spatial":
            ra, rb = one_ref(spec["target"]), one_ref(spec["anchor"])
            if ra is None or rb is None:
                return None
            refs.append((ra, rb))
            sets.append(frozenset({ids[spec["target"]]}))
            continue
        want = frozenset(ids[i] for i in members[g])
        mode = spec["mode"]
        if mode == "all_name":
            ref = ("all_name", spec["name"])
        elif mode == "all_color":
            ref = ("all_color", spec["color"])
        elif mode == "same_color":
            rr = one_ref(extra[g])
            if rr is None:
                return None
            ref = ("same_color", rr)
        else:
            parts = []
            for i in sorted(members[g], key=lambda i: ids[i]):
                o = objs[i]
                parts.append(("one", o["color"], o["name"]))
            ref = ("list", tuple(parts))
        if not unambiguous(ref, specs_by_id, want):
            return None
        refs.append(ref)
        sets.append(want)
    if len(sets) == 2 and sets[0] & sets[1]:
        return None

    # 3. Final arrangement meeting every goal.
    scene = scene_of(WORKSPACE, [{k: o[k] for k in ("id", "name", "color", "shape")} for o in objs])
    layout = Layout(scene)
    for g, spec in enumerate(goals):
        if spec["kind"] == "spatial":
            continue
        for _ in range(40):
            poses = pattern_poses(spec["kind"], members[g], scene, rng)
            if all(layout.fits(i, p) for i, p in zip(members[g], poses)):
                trial = Layout(scene)
                if all(trial.try_put(i, p) for i, p in zip(members[g], poses)):
                    for i, p in zip(members[g], poses):
                        layout.put(i, p)
                    break
        else:
            return None
    for spec in goals:
        if spec["kind"] != "spatial":
            continue
        a, t = spec["anchor"], spec["target"]
        if a not in layout.poses and layout.random(a, rng) is None:
            return None
        for _ in range(80):
            p = relation_pose(spec["relation"], layout.poses[a], scene.radii[a], scene.radii[t], rng)
            if layout.try_put(t, p):
                break
        else:
            return None
    for i in range(n):
        if i not in layout.poses and layout.random(i, rng) is None:
            return None
    final = np.array([layout.poses[i] for i in range(n)])
    goal_list = []
    for g, spec in enumerate(goals):
        if spec["kind"] == "spatial":
            goal_list.append(
                {"pattern": spec["relation"], "objects": [ids[spec["target"]]], "anchor": ids[spec["anchor"]]}
            )
        else:
            goal_list.append({"pattern": spec["kind"], "objects": sorted(sets[g])})
    gspec = parse_goals({"goals": goal_list})
    on_table = tuple(TABLE for _ in range(n))
    if any(goal_satisfied(g, scene, final, on_table) is not None for g in gspec.goals):
        return None

    # 4. Start state: movers scattered, clutter on their final spots, blockers on movers.
    movers = sorted({i for m in members for i in m} | {s["target"] for s in goals if s["kind"] == "spatial"})
    anchors = {s["anchor"] for s in goals if s["kind"] == "spatial"}
    statics = [i for i in range(n) if i not in movers]
    free_statics = [i for i in statics if i not in anchors]
    rng.shuffle(free_statics)
    n_clutter = min(len(free_statics) - 1, int(rng.integers(1, 3)))
    if n_clutter < 1:
        return None
    clutter = free_statics[:n_clutter]
    top_pool = free_statics[n_clutter:] + list(movers)
    start = Layout(scene)
    for i in statics:
        if i not in clutter and i not in top_pool:
            start.put(i, final[i])
    clutter_pairs = []
    for c in clutter:
        t = int(movers[int(rng.integers(len(movers)))])
        p = np.array([final[t, 0], final[t, 1], rng.uniform(-math.pi, math.pi)])
        if not start.try_put(c, p):
            return None
        clutter_pairs.append((c, t))
    # Blockers: 1-2 tops, each on a distinct mover of similar or larger size.
    n_tops = int(rng.integers(1, 3))
    rng.shuffle(top_pool)
    tops: list[tuple[int, int]] = []
    bases_used: set[int] = set()
    for top in top_pool:
        if len(tops) == n_tops:
            break
        cands = [
            b
            for b in movers
            if b != top
            and b not in bases_used
            and b not in {t for t, _ in tops}
            and scene.radii[top] <= 1.2 * scene.radii[b]
            and scene.heights[b] <= 0.04
        ]
        if top in bases_used or not cands:
            continue
        b = int(cands[int(rng.integers(len(cands)))])
        tops.append((top, b))
        bases_used.add(b)
    if not tops:
        return None
    top_ids = {t for t, _ in tops}
    for i in range(n):
        if i in start.poses or i in top_ids:
            continue
        if i in statics and i not in top_pool:
            continue
        if start.random(i, rng) is None:
            return None
    start_poses = dict(start.poses)
    on = dict.fromkeys(range(n), TABLE)
    for t, b in tops:
        start_poses[t] = np.array([start_poses[b][0], start_poses[b][1], rng.uniform(-math.pi, math.pi)])
        on[t] = b
    start_objs = []
    for i in sorted(range(n), key=lambda i: ids[i]):
        o = objs[i]
        start_objs.append(
            {
                "id": ids[i],
                "name": o["name"],
                "color": o["color"],
                "shape": o["shape"],
                "pose": [round(float(v), 5) for v in start_poses[i]],
                "on": None if on[i] == TABLE else ids[on[i]],
            }
        )
    scene_dict = {"workspace": WORKSPACE, "objects": start_objs}
    sspec = parse_scene(scene_dict)
    st = Scene.from_spec(sspec)
    if all(goal_satisfied(g, st, st.initial.poses, st.initial.on) is None for g in gspec.goals):
        return None
    # Rounding of start poses must not break the clutter/blocker claims; final poses are kept exact.
    final_d = {str(ids[i]): [float(v) for v in final[i]] for i in range(n)}

    # 5. The instruction.
    clauses = []
    for g, spec in enumerate(goals):
        if spec["kind"] == "spatial":
            ra, rb = refs[g]
            tpl = _pick(rng, _SPATIAL_TEMPLATES)
            clauses.append(
                tpl.format(a=phrase(ra, rng), rel=_pick(rng, _REL_WORDS[spec["relation"]]), b=phrase(rb, rng))
            )
        else:
            tpl = _pick(rng, _SHAPE_TEMPLATES[spec["kind"]])
            clauses.append(tpl.format(x=phrase(refs[g], rng)))
    conn = _pick(rng, _CONNECTIVES)
    second = clauses[1]
    instruction = clauses[0] + conn + (second[0].lower() + second[1:])
    start_d = {
        "blockers": [[ids[t], ids[b]] for t, b in tops],
        "clutter": [[ids[c], ids[t]] for c, t in clutter_pairs],
    }
    # What each reference must keep meaning when objects are added (dense variant).
    meanings: list[tuple[tuple, frozenset[int]]] = []
    for g, spec in enumerate(goals):
        if spec["kind"] == "spatial":
            ra, rb = refs[g]
            meanings += [(ra, frozenset({ids[spec["target"]]})), (rb, frozenset({ids[spec["anchor"]]}))]
        else:
            meanings.append((refs[g], sets[g]))
            if spec["mode"] == "same_color":
                meanings.append((refs[g][1], frozenset({ids[extra[g]]})))
    return scene_dict, instruction, {"goals": goal_list}, final_d, start_d, meanings
