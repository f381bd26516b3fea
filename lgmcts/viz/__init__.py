"""Pictures, animations and an HTML viewer of plans (outside the core).

* :func:`write_plan_figures` — top-down PNGs of the initial scene, every
  action and the final scene with each goal's shape, a before/after pair, an
  animated GIF and the pose-field heatmaps of one step (matplotlib).
* :func:`render_html` — one self-contained HTML page that plays the plan.
* :func:`viewer_data` / :func:`viewer_js` — the pieces of that page, for
  embedding the viewer elsewhere (the planning service serves it).

Nothing in the planner imports this package; matplotlib is imported only when
a picture is drawn.
"""

from __future__ import annotations

from ..lazy import lazy_names

__all__ = [
    "FigureOptions",
    "Paint",
    "heatmap_fields",
    "paint",
    "render_html",
    "viewer_data",
    "viewer_js",
    "write_plan_figures",
]

# Loaded on first use, so that commands without pictures import none of it.
_WHERE = {
    **dict.fromkeys(["FigureOptions", "heatmap_fields", "write_plan_figures"], ".figures"),
    **dict.fromkeys(["render_html", "viewer_data", "viewer_js"], ".html"),
    **dict.fromkeys(["Paint", "paint"], ".paint"),
}


__getattr__, __dir__ = lazy_names(__name__, _WHERE)
