"""A self-contained HTML page that plays a plan in the browser.

The page inlines :file:`assets/viewer.js` (which brings its own CSS) and the
plan's data, so it opens from disk with no network access. The same script
is what the planning service serves at ``/``: any page can call
``LGMCTSViewer.render(element, data)`` with the data contract below
(documented in ``docs/viz.md``).

``data`` keys
-------------
scene : the scene JSON (required).
plan : the plan JSON, carrying its goals (required).
instruction : the plain-language command, or null.
footprints : optional ``{id: [[x, y], ...]}``, each object's footprint in its
    own frame (m); without it the script derives footprints from the shapes.
paints : optional ``{id: {fill, second, mark, ink, edge, texture}}`` read from
    the colour text; without it the script knows a few colour words itself.
frames : one entry per plan state (``len(actions) + 1``), each a change
    over the state before: ``{"poses": {id: pose}, "on": {id: id|null},
    "goals": [<goal shape>, ...]}`` listing only the objects whose pose or
    support changed and the goals drawn anew (each shape names its goal by
    ``index``). The first frame lists every object and goal, the last every
    goal. A frame listing everything (the older form) reads the same.
"""

from __future__ import annotations

import html as _html
import json
import re
from collections.abc import Iterator
from functools import lru_cache
from importlib import resources
from typing import Any

import numpy as np

from .. import limits
from ..errors import InputError
from ..formats import GoalSpec, PlanSpec, SceneSpec, load_plan, load_scene, parse_goals, to_dict
from ..scene import TABLE, Scene, State, advance
from .model import describe_goal, goal_shapes
from .paint import paint

__all__ = ["check_view_size", "render_html", "script_json", "viewer_data", "viewer_js"]


@lru_cache(maxsize=1)
def viewer_js() -> str:
    """Source of the browser viewer (defines the global ``LGMCTSViewer``)."""
    return resources.files("lgmcts.viz").joinpath("assets/viewer.js").read_text(encoding="utf-8")


def script_json(value: Any) -> str:
    """JSON safe to put inside a ``<script>`` element (no ``</script>`` break-out)."""
    text = json.dumps(value, separators=(",", ":"), allow_nan=False)
    return (
        text.replace("<", "\\u003c")
        .replace(">", "\\u003e")
        .replace("&", "\\u0026")
        .replace("\u2028", "\\u2028")
        .replace("\u2029", "\\u2029")
    )


def _inline_safe(js: str) -> str:
    """Script text that cannot end its ``<script>`` element early.

    The HTML parser closes a script at ``</script`` in any letter case and treats
    ``<!--`` specially whatever the JavaScript context; ``<\\/`` and ``<\\!``
    mean the same characters inside every JavaScript string or regex.
    """
    return re.sub(r"</(script)", r"<\\/\1", js, flags=re.IGNORECASE).replace("<!--", "<\\!--")


def check_view_size(objects: int, actions: list | int, goals: GoalSpec | None) -> None:
    """Refuse, in one line, a plan whose viewer data would cost more than the caps of docs/limits.md.

    * :data:`~lgmcts.limits.MAX_VIEW_CELLS` bounds the work,
      ``(objects + goal members) x (actions + 1)``: the replay compares every
      pose at every step, and a goal is drawn again whenever one of its
      objects moves;
    * :data:`~lgmcts.limits.MAX_VIEW_DRAWN` bounds the answer: what the
      frames list (every object and goal member once, then at each action
      the moved object and the members of each goal over it or its new
      support) is counted from the actions before any is replayed.
    """
    n = actions if isinstance(actions, int) else len(actions)
    sizes = [len(g.objects) + 1 for g in goals.goals] if goals is not None else []
    members = sum(sizes)
    cells = (objects + members) * (n + 1)
    if cells > limits.MAX_VIEW_CELLS:
        raise InputError(
            f"the plan is too large to draw: ({objects} objects + {members} goal members) x {n + 1} states "
            f"= {cells} exceeds {limits.MAX_VIEW_CELLS} (docs/limits.md)"
        )
    if isinstance(actions, int):
        return
    over: dict[int, int] = {}
    if goals is not None:
        for k, g in enumerate(goals.goals):
            for i in {*g.objects, *([g.anchor] if g.anchor is not None else [])}:
                over[i] = over.get(i, 0) + sizes[k]
    drawn = objects + 2 * members
    for a in actions:
        drawn += 1 + over.get(a.object, 0) + (over.get(a.on, 0) if a.on is not None else 0)
    if drawn > limits.MAX_VIEW_DRAWN:
        raise InputError(
            f"the plan is too large to draw: its frames would list about {drawn} objects and goal members, "
            f"more than {limits.MAX_VIEW_DRAWN} (docs/limits.md)"
        )


def _frames(sc: Scene, actions: list, gs: GoalSpec | None, fits: list | None) -> Iterator[dict]:
    """The viewer's frames as deltas: frame 0 holds every pose, support and goal
    shape; each later frame only what changed since the one before (the objects
    whose pose or support changed, the goals over them); the last frame holds
    every goal again (drawn from ``fits`` when given).

    Only two states are alive at a time, so memory grows with the changes,
    not with objects x actions.
    """
    ids = sc.ids
    by_object: dict[int, list[int]] = {}
    sizes = [len(g.objects) + 1 for g in gs.goals] if gs is not None else []
    drawn = 0
    if gs is not None:
        for k, g in enumerate(gs.goals):
            for i in {*g.objects, *([g.anchor] if g.anchor is not None else [])}:
                by_object.setdefault(sc.index[i], []).append(k)
    n = len(actions)

    def entry(st: State, which: list[int], only: list[int] | None, last: bool) -> dict:
        # What the answer holds grows with the objects listed and the members
        # of the goals drawn: bounded, so the answer stays tens of megabytes.
        nonlocal drawn
        drawn += len(which) + sum(sizes[k] for k in (range(len(sizes)) if only is None else only))
        if drawn > limits.MAX_VIEW_DRAWN:
            raise InputError(
                f"the plan is too large to draw: its frames would list more than {limits.MAX_VIEW_DRAWN} "
                "objects and goal members (docs/limits.md)"
            )
        return {
            "poses": {str(ids[k]): [float(v) for v in st.poses[k]] for k in which},
            "on": {str(ids[k]): (None if st.on[k] == TABLE else ids[st.on[k]]) for k in which},
            "goals": [s.to_json() for s in goal_shapes(sc, gs, st, fits=fits if last else None, only=only)],
        }

    st = sc.initial
    yield entry(st, list(range(len(ids))), None, n == 0)
    for number, a in enumerate(actions, start=1):
        nxt = advance(st, number, a)
        changed = np.flatnonzero(
            np.any(nxt.poses != st.poses, axis=1) | (np.asarray(nxt.on) != np.asarray(st.on))
        ).tolist()
        last = number == n
        # A goal is drawn anew when one of its objects moved or changed what it
        # rests on or carries (the old and new support of a moved object).
        near = set(changed)
        for k in changed:
            near.update(s for s in (st.on[k], nxt.on[k]) if s != TABLE)
        touched = None if last else sorted({g for k in near for g in by_object.get(k, ())})
        yield entry(nxt, changed, touched, last)
        st = nxt


def viewer_data(
    scene: SceneSpec | Scene | dict | str,
    plan: PlanSpec | dict | str,
    *,
    goals: GoalSpec | dict | list | None = None,
    instruction: str | None = None,
) -> dict:
    """The ``data`` object for ``LGMCTSViewer.render``, with every optional part filled.

    Parameters
    ----------
    scene, plan : models, dicts or JSON paths.
    goals : goals to show; default the plan's own.
    instruction : the command to show; default the plan's ``instruction`` field.

    Returns
    -------
    dict
        JSON-ready: ``scene``, ``plan``, ``instruction``, ``footprints``,
        ``paints`` and ``frames`` (see the module docstring).
    """
    sc = scene if isinstance(scene, Scene) else Scene.from_spec(load_scene(scene))
    pl = load_plan(plan)
    gs = parse_goals(goals) if goals is not None else pl.goals
    if gs is not None:
        gs.check_against(sc.spec)
        pl = pl.model_copy(update={"goals": gs})
    if instruction is None:
        extra = pl.model_extra or {}
        instruction = extra.get("instruction") if isinstance(extra.get("instruction"), str) else None
    actions = list(pl.actions)
    check_view_size(len(sc.ids), actions, gs)
    # The plan's own fits draw its final state when it is drawn against its own goals.
    fits = pl.fits if goals is None else None
    footprints = {str(i): np.round(sc.local[k], 6).tolist() for k, i in enumerate(sc.ids)}
    scene_json = to_dict(sc.to_spec(sc.initial))
    frames = list(_frames(sc, actions, gs, fits))
    return {
        "scene": scene_json,
        "plan": to_dict(pl),
        "instruction": instruction,
        "footprints": footprints,
        "paints": {str(i): paint(c).to_json() for i, c in zip(sc.ids, sc.colors)},
        "frames": frames,
        "goal_text": [describe_goal(g) for g in (gs.goals if gs is not None else [])],
    }


def render_html(
    scene: SceneSpec | Scene | dict | str,
    plan: PlanSpec | dict | str,
    *,
    instruction: str | None = None,
    title: str | None = None,
    goals: GoalSpec | dict | list | None = None,
) -> str:
    """One self-contained HTML page that plays ``plan`` on ``scene``.

    Parameters
    ----------
    scene, plan : models, dicts or JSON paths.
    instruction : the plain-language command shown above the drawing;
        default the plan's ``instruction`` field.
    title : page title; default a summary of the plan.
    goals : goals to highlight; default the plan's own.

    Returns
    -------
    str
        The page: scene to scale (SVG), play/pause, a step slider, the
        clickable action list, goals with pass/fail marks, the instruction.
        No external resource is referenced.
    """
    data = viewer_data(scene, plan, goals=goals, instruction=instruction)
    n = len(data["plan"]["actions"])
    if title is None:
        title = (
            f"lgmcts plan: {n} action{'s' if n != 1 else ''}, {'solved' if data['plan']['solved'] else 'not solved'}"
        )
    return _PAGE.format(
        title=_html.escape(title),
        script=_inline_safe(viewer_js()),
        data=script_json(data),
    )


_PAGE = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{title}</title>
<style>html,body{{margin:0;padding:0;background:#fafaf7;}}</style>
</head>
<body>
<div id="lgmcts-viewer"></div>
<script>
{script}
</script>
<script>
window.lgmctsData = {data};
window.lgmctsViewer = LGMCTSViewer.render(document.getElementById("lgmcts-viewer"), window.lgmctsData);
</script>
</body>
</html>
"""
