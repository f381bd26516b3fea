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
frames : optional list (one per plan state, ``len(actions) + 1``) of
    ``{"goals": [<goal shape>, ...]}`` with each goal's fitted geometry and
    whether it holds; without it the script fits the shapes itself and shows
    no pass/fail marks.
"""

from __future__ import annotations

import html as _html
import json
import re
from functools import lru_cache
from importlib import resources
from typing import Any

import numpy as np

from ..formats import GoalSpec, PlanSpec, SceneSpec, load_plan, load_scene, parse_goals, to_dict
from ..scene import TABLE, Scene
from .model import describe_goal, goal_shapes, replay
from .paint import paint

__all__ = ["render_html", "script_json", "viewer_data", "viewer_js"]


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
    states = replay(sc, list(pl.actions))
    # The plan's own fits draw its final state when it is drawn against its own goals.
    fits = pl.fits if goals is None else None
    footprints = {str(i): np.round(sc.local[k], 6).tolist() for k, i in enumerate(sc.ids)}
    scene_json = to_dict(sc.to_spec(sc.initial))
    frames = [
        {
            "poses": {str(i): [float(v) for v in st.poses[k]] for k, i in enumerate(sc.ids)},
            "on": {str(i): (None if st.on[k] == TABLE else sc.ids[st.on[k]]) for k, i in enumerate(sc.ids)},
            "goals": [s.to_json() for s in goal_shapes(sc, gs, st, fits=fits if k == len(states) - 1 else None)],
        }
        for k, st in enumerate(states)
    ]
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
