"""Top-down pictures of a plan with matplotlib.

Every picture uses the table frame seen from above: +x to the right, +y away
from the viewer, so the viewer stands at the bottom edge (marked "viewer").
Objects are drawn as their exact footprints (:mod:`lgmcts.scene`), filled with
the colour their description names (:mod:`lgmcts.viz.paint`), labelled with
id and name. A side panel lists the goals (with whether each holds), the
actions (the current one highlighted) and a legend.

matplotlib is imported lazily, through its object-oriented API and the Agg
canvas only: no pyplot, no global backend switch, safe in a server process.
"""

from __future__ import annotations

import math
import os
import sys
import textwrap
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from tqdm import tqdm

from ..errors import InputError
from ..formats import GoalSpec, PlanSpec, SceneSpec, load_plan, load_scene, parse_goals
from ..scene import TABLE, Scene, State
from .model import GOAL_COLORS, PURPOSE_COLORS, GoalShape, describe_goal, goal_shapes, replay
from .paint import Paint, paint

__all__ = ["FigureOptions", "heatmap_fields", "step_name", "write_plan_figures"]

_HATCH = {"dots": "o", "stripes": "////", "checks": "++", "speckles": "..", "grain": "---", "waves": "\\\\"}
_TABLE_FILL = "#f4efe6"
_TABLE_EDGE = "#8a7f6d"
_PURPOSE_WORD = {"goal": "goal placement", "relocate": "relocation", "unstack": "unstack"}


@dataclass(frozen=True)
class FigureOptions:
    """How the pictures are drawn.

    Attributes
    ----------
    dpi : resolution of the PNG files (dots per inch).
    table_height_in : height of the table drawing (inches); its width follows
        the workspace's aspect ratio.
    panel_width_in : width of the side panel with goals, actions and legend (inches).
    gif_width_px : width of the animation frames (pixels).
    frame_s : how long each animation frame shows (seconds).
    last_frame_s : how long the last frame shows (seconds).
    heatmap_resolution : grid cell of the pose fields (metres).
    max_step_pictures : most ``step_XX.png`` pictures (and animation frames
        after the first); a longer plan gets this many, evenly spaced, the
        last action always among them.
    """

    dpi: int = 110
    table_height_in: float = 5.6
    panel_width_in: float = 3.5
    gif_width_px: int = 860
    frame_s: float = 1.2
    last_frame_s: float = 3.0
    heatmap_resolution: float = 0.005
    max_step_pictures: int = 12


#: Scenes with more objects than this draw no name labels beside objects.
MAX_NAME_LABELS = 60
#: Scenes with more objects than this draw no ids inside objects either.
MAX_ID_LABELS = 150
#: Earlier moves drawn as curved arrows; more are drawn as plain lines.
MAX_ARROWS = 60

# ----------------------------------------------------------------- helpers


def _mpl() -> tuple[Any, Any]:
    """The Figure class and the Agg canvas, imported on first use."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg
    from matplotlib.figure import Figure

    return Figure, FigureCanvasAgg


def _nice_length(span: float) -> float:
    """A round scale-bar length (m) about a fifth of ``span``."""
    target = span / 5.0
    for cm in (1, 2, 5, 10, 20, 25, 50, 100, 200, 500):
        if cm / 100.0 >= target * 0.7:
            return cm / 100.0
    return 10.0


def _rgba(color: Any, alpha: float) -> tuple[float, float, float, float]:
    from matplotlib.colors import to_rgba

    return to_rgba(color, alpha)


@dataclass(frozen=True)
class _Ctx:
    """What every drawing function needs about the plan being drawn."""

    scene: Scene
    goals: GoalSpec | None
    plan: PlanSpec
    states: list[State]
    paints: tuple[Paint, ...]
    instruction: str | None
    options: FigureOptions
    #: The plan's fits of its final state, when drawn against its own goals.
    fits: list | None = None

    def shapes(self, step: int) -> list[GoalShape]:
        """The goals' shapes after ``step`` actions (the last from the plan's fits)."""
        return goal_shapes(
            self.scene, self.goals, self.states[step], fits=self.fits if step == self.n_actions else None
        )

    @property
    def n_actions(self) -> int:
        return len(self.plan.actions)

    def goal_color(self, k: int) -> str:
        return GOAL_COLORS[k % len(GOAL_COLORS)]

    def goal_membership(self) -> dict[int, list[int]]:
        """Object index -> indices of the goals it belongs to (as object or anchor)."""
        out: dict[int, list[int]] = {}
        if self.goals is None:
            return out
        for k, g in enumerate(self.goals.goals):
            for i in g.objects:
                out.setdefault(self.scene.index[i], []).append(k)
        return out


def _footprint(ctx: _Ctx, state: State, k: int, pose: Sequence[float] | None = None) -> np.ndarray:
    p = state.poses[k] if pose is None else np.asarray(pose, dtype=float)
    return ctx.scene.footprint(k, p)


def _level(state: State, k: int) -> int:
    lv, s = 0, state.on[k]
    while s != TABLE:
        lv += 1
        s = state.on[s]
    return lv


def _draw_table(ax: Any, scene: Scene, *, scale_bar: bool = True, viewer: bool = True, fontsize: float = 8) -> None:
    from matplotlib.patches import Rectangle

    xmin, xmax, ymin, ymax = scene.bounds
    w, h = xmax - xmin, ymax - ymin
    m = 0.09 * max(w, h)
    ax.add_patch(Rectangle((xmin, ymin), w, h, facecolor=_TABLE_FILL, edgecolor=_TABLE_EDGE, lw=1.2, zorder=0))
    from matplotlib.collections import LineCollection

    step = 0.1 if max(w, h) <= 2.0 else 0.5 if max(w, h) <= 20.0 else 10.0 ** math.ceil(math.log10(max(w, h) / 40))
    segs = [[(gx, ymin), (gx, ymax)] for gx in np.arange(math.ceil(xmin / step) * step, xmax, step)]
    segs += [[(xmin, gy), (xmax, gy)] for gy in np.arange(math.ceil(ymin / step) * step, ymax, step)]
    ax.add_collection(LineCollection(segs, colors="#e2dacb", linewidths=0.6, zorder=0.5))
    ax.set_xlim(xmin - m * 0.6, xmax + m * 0.6)
    ax.set_ylim(ymin - m, ymax + m * 0.45)
    ax.set_aspect("equal")
    ax.tick_params(labelsize=fontsize - 1.5, length=2, colors="#666666")
    for side in ("top", "right"):
        ax.spines[side].set_visible(False)
    for side in ("left", "bottom"):
        ax.spines[side].set_color("#bbbbbb")
    ax.set_xlabel("x (m)", fontsize=fontsize - 1, color="#666666", labelpad=1)
    ax.set_ylabel("y (m)", fontsize=fontsize - 1, color="#666666", labelpad=1)
    if viewer:
        ax.text(
            (xmin + xmax) / 2,
            ymin - m * 0.5,
            "▼  viewer side (front, −y)  ▼",
            ha="center",
            va="center",
            fontsize=fontsize,
            color="#555555",
            fontweight="bold",
            zorder=5,
        )
        ax.text(
            (xmin + xmax) / 2,
            ymax + m * 0.22,
            "back (+y)",
            ha="center",
            va="center",
            fontsize=fontsize - 1.5,
            color="#999999",
        )
    if scale_bar:
        L = _nice_length(w)
        x0, y0 = xmin, ymin - m * 0.5
        ax.plot([x0, x0 + L], [y0, y0], color="#222222", lw=2.5, solid_capstyle="butt", zorder=5)
        for xx in (x0, x0 + L):
            ax.plot([xx, xx], [y0 - m * 0.08, y0 + m * 0.08], color="#222222", lw=1.2, zorder=5)
        ax.text(x0 + L / 2, y0 + m * 0.12, f"{L * 100:g} cm", ha="center", va="bottom", fontsize=fontsize - 1, zorder=5)
        # Axis arrows: which way +x and +y point.
        ax_x, ax_y = xmax - m * 1.4, ymin - m * 0.55
        a = m * 0.55
        kw: dict[str, Any] = {"arrowstyle": "-|>", "color": "#444444", "lw": 1.0, "mutation_scale": 8}
        from matplotlib.patches import FancyArrowPatch

        ax.add_patch(FancyArrowPatch((ax_x, ax_y), (ax_x + a, ax_y), zorder=5, **kw))
        ax.add_patch(FancyArrowPatch((ax_x, ax_y), (ax_x, ax_y + a), zorder=5, **kw))
        ax.text(ax_x + a * 1.08, ax_y, "x", va="center", fontsize=fontsize - 1.5, color="#444444")
        ax.text(ax_x, ax_y + a * 1.1, "y", ha="center", va="bottom", fontsize=fontsize - 1.5, color="#444444")


def _add(ax: Any, patch: Any) -> None:
    """``ax.add_patch`` without the data-limit update (the limits are set by
    :func:`_draw_table` before objects are drawn); much faster for hundreds of objects."""
    patch.set_transform(ax.transData)
    patch.set_clip_path(ax.patch)
    ax.add_artist(patch)


def _draw_object(
    ax: Any, ctx: _Ctx, state: State, k: int, *, edge: Any = None, lw: float = 1.0, alpha: float = 1.0, z: float = 2.0
) -> None:
    from matplotlib.patches import Polygon

    pt = ctx.paints[k]
    verts = _footprint(ctx, state, k)
    lvl = _level(state, k)
    zz = z + lvl * 0.1
    if lvl:
        # A drop shadow, offset down-right, tells a stacked object from one on the table.
        off = np.array([0.006, -0.006]) * min(lvl, 3)
        _add(
            ax, Polygon(verts + off, closed=True, facecolor=(0, 0, 0, 0.28 * alpha), edgecolor="none", zorder=zz - 0.01)
        )
    _add(ax, Polygon(verts, closed=True, facecolor=_rgba(pt.fill, alpha), edgecolor="none", zorder=zz))
    if pt.texture:
        _add(
            ax,
            Polygon(
                verts,
                closed=True,
                fill=False,
                hatch=_HATCH.get(pt.texture, "//"),
                edgecolor=_rgba(pt.mark, alpha),
                lw=0,
                zorder=zz + 0.01,
            ),
        )
    _add(
        ax,
        Polygon(
            verts,
            closed=True,
            fill=False,
            edgecolor=edge if edge is not None else _rgba(pt.edge, alpha),
            lw=lw,
            zorder=zz + 0.02,
        ),
    )


def _label_positions(
    ctx: _Ctx, ax: Any, state: State, labels: dict[int, str], fontsize: float
) -> dict[int, tuple[float, float, str, str]]:
    """Place each label next to its object, keeping clear of labels and objects.

    Spots around the object's bounding box (below, above, right, left, the four
    diagonals, then the same a little further out) are scored by how much of
    the label would cover labels already placed, other objects, or leave the
    axes; the cheapest wins, earlier spots breaking ties. Text size is
    estimated from the font size, which is close enough for a greedy choice.
    Returns ``index -> (x, y, ha, va)`` in data coordinates (m).
    """
    fig = ax.figure
    bbox = ax.get_position()
    xl, yl = ax.get_xlim(), ax.get_ylim()
    w_in = bbox.width * fig.get_figwidth()
    m_per_pt = (xl[1] - xl[0]) / (w_in * 72.0)
    ch_w, ch_h = 0.56 * fontsize * m_per_pt, 1.3 * fontsize * m_per_pt
    placed = np.zeros((0, 4))
    verts = [_footprint(ctx, state, j) for j in range(ctx.scene.n)]
    feet = np.array([(v[:, 0].min(), v[:, 1].min(), v[:, 0].max(), v[:, 1].max()) for v in verts])
    out = {}

    def overlap(b: np.ndarray, others: np.ndarray) -> float:
        if not len(others):
            return 0.0
        w = np.clip(np.minimum(b[2], others[:, 2]) - np.maximum(b[0], others[:, 0]), 0, None)
        h = np.clip(np.minimum(b[3], others[:, 3]) - np.maximum(b[1], others[:, 1]), 0, None)
        return float((w * h).sum())

    # The stack each object stands in (its base), found once: a label may
    # cover its own stack but not other objects.
    bases = np.array([_base(state, j) for j in range(ctx.scene.n)])

    def cost(b: np.ndarray, k: int) -> float:
        area = (b[2] - b[0]) * (b[3] - b[1])
        mine = bases != bases[k]
        c = 3.0 * overlap(b, placed) / area + 1.5 * overlap(b, feet[mine]) / area
        if b[0] < xl[0] or b[2] > xl[1] or b[1] < yl[0] or b[3] > yl[1]:
            c += 5.0
        return c

    order = sorted(labels, key=lambda k: (-state.poses[k, 1], state.poses[k, 0]))
    for k in order:
        lines = labels[k].split("\n")
        tw = max(len(t) for t in lines) * ch_w
        th = len(lines) * ch_h
        x0, y0, x1, y1 = feet[k]
        cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
        cands = []
        for gap in (0.004, 0.02):
            cands += [
                ((cx - tw / 2, y0 - gap - th, cx + tw / 2, y0 - gap), (cx, y0 - gap, "center", "top")),
                ((cx - tw / 2, y1 + gap, cx + tw / 2, y1 + gap + th), (cx, y1 + gap, "center", "bottom")),
                ((x1 + gap, cy - th / 2, x1 + gap + tw, cy + th / 2), (x1 + gap, cy, "left", "center")),
                ((x0 - gap - tw, cy - th / 2, x0 - gap, cy + th / 2), (x0 - gap, cy, "right", "center")),
                ((x1, y0 - gap - th, x1 + tw, y0 - gap), (x1, y0 - gap, "left", "top")),
                ((x0 - tw, y0 - gap - th, x0, y0 - gap), (x0, y0 - gap, "right", "top")),
                ((x1, y1 + gap, x1 + tw, y1 + gap + th), (x1, y1 + gap, "left", "bottom")),
                ((x0 - tw, y1 + gap, x0, y1 + gap + th), (x0, y1 + gap, "right", "bottom")),
            ]
        scores = [cost(np.asarray(b), k) + 0.002 * j for j, (b, _) in enumerate(cands)]
        best = int(np.argmin(scores))
        placed = np.vstack([placed, np.asarray(cands[best][0])[None]])
        out[k] = cands[best][1]
    return out


def _base(state: State, i: int) -> int:
    """The object at the bottom of the stack that object ``i`` stands in."""
    while state.on[i] != TABLE:
        i = state.on[i]
    return i


def _same_stack(state: State, a: int, b: int) -> bool:
    """Whether objects ``a`` and ``b`` stand in the same stack."""
    return _base(state, a) == _base(state, b)


def _draw_plain(ax: Any, ctx: _Ctx, state: State, ks: list[int], dim: set[int]) -> None:
    """Objects ``ks`` (on the table, untextured) as one filled and edged polygon collection."""
    if not ks:
        return
    from matplotlib.collections import PolyCollection

    verts = [_footprint(ctx, state, k) for k in ks]
    alpha = [0.35 if k in dim else 1.0 for k in ks]
    faces = [_rgba(ctx.paints[k].fill, a) for k, a in zip(ks, alpha)]
    edges = [_rgba(ctx.paints[k].edge, a) for k, a in zip(ks, alpha)]
    ax.add_collection(
        PolyCollection(verts, closed=True, facecolors=faces, edgecolors=edges, linewidths=0.9, zorder=2.0)
    )


def _draw_objects(
    ax: Any,
    ctx: _Ctx,
    state: State,
    *,
    highlight: dict[int, str] | None = None,
    rings: bool = False,
    fontsize: float = 7.0,
    dim: set[int] | None = None,
) -> None:
    """All objects of ``state``, lowest first, with their labels and stack marks."""
    import matplotlib.patheffects as pe
    from matplotlib.patches import Polygon

    highlight = highlight or {}
    dim = dim or set()
    scene = ctx.scene
    order = sorted(range(scene.n), key=lambda k: (_level(state, k), k))
    member = ctx.goal_membership() if rings else {}
    if scene.n > MAX_NAME_LABELS:
        # Crowded: plain objects (on the table, untextured, not highlighted) in
        # one collection, which draws in a fraction of the time of one patch each.
        plain = [k for k in order if _level(state, k) == 0 and k not in highlight and not ctx.paints[k].texture]
        _draw_plain(ax, ctx, state, plain, dim)
        done = set(plain)
        order = [k for k in order if k not in done]
    for k in order:
        if k in member:
            # Goal objects get a ring in the colour of (each of) their goal(s).
            verts = _footprint(ctx, state, k)
            c = verts.mean(axis=0)
            for j, gk in enumerate(member[k][:2]):
                grow = 1.0 + (0.010 + 0.006 * j) / max(float(scene.radii[k]), 1e-3)
                ax.add_patch(
                    Polygon(
                        c + (verts - c) * grow,
                        closed=True,
                        fill=False,
                        edgecolor=ctx.goal_color(gk),
                        lw=1.6,
                        zorder=1.8 + _level(state, k) * 0.1,
                    )
                )
        _draw_object(
            ax, ctx, state, k, edge=highlight.get(k), lw=2.6 if k in highlight else 0.9, alpha=0.35 if k in dim else 1.0
        )
    # Labels: the id inside the object; name (and what it rests on) beside it.
    # Crowded scenes keep fewer words: beyond MAX_NAME_LABELS objects the
    # names go, beyond MAX_ID_LABELS the ids too (text is most of the drawing
    # time, and hundreds of labels are unreadable anyway).
    labels: dict[int, str] = {}
    names = scene.n <= MAX_NAME_LABELS
    ids = scene.n <= MAX_ID_LABELS
    for k in range(scene.n):
        pt = ctx.paints[k]
        x, y, _ = state.poses[k]
        covered = bool(state.holding[k])
        if ids and not covered:
            ax.text(
                x,
                y,
                str(scene.ids[k]),
                ha="center",
                va="center",
                fontsize=fontsize + 0.5,
                fontweight="bold",
                color=pt.ink,
                zorder=4 + _level(state, k) * 0.1,
                path_effects=[pe.withStroke(linewidth=1.6, foreground=pt.fill)],
            )
        if names and state.on[k] == TABLE:
            stack = [k]
            while state.holding[stack[-1]]:
                stack.append(state.holding[stack[-1]][0])
            lines = []
            for depth, j in enumerate(reversed(stack)):
                name = scene.label(j)
                if depth == 0 and len(stack) > 1:
                    name += f"  (stack of {len(stack)})"
                elif depth > 0:
                    name = "  on " + name
                lines.append(name)
            labels[k] = "\n".join(lines)
    pos = _label_positions(ctx, ax, state, labels, fontsize)
    for k, text in labels.items():
        x, y, ha, va = pos[k]
        stacked = "\n" in text
        ax.text(
            x,
            y,
            text,
            ha=ha,
            va=va,
            fontsize=fontsize,
            color="#222222",
            zorder=6,
            linespacing=1.1,
            bbox={
                "boxstyle": "round,pad=0.18",
                "facecolor": "white",
                "edgecolor": "#7048e8" if stacked else "#cccccc",
                "lw": 0.9 if stacked else 0.5,
                "alpha": 0.85,
            },
        )


def _draw_goal_shapes(
    ax: Any, ctx: _Ctx, shapes: list[GoalShape], *, faint: bool = False, only_met: bool = False
) -> None:
    from matplotlib.patches import Circle, FancyArrowPatch, Polygon, Rectangle

    for s in shapes:
        if only_met and not s.met:
            continue
        col = ctx.goal_color(s.index)
        alpha = 0.55 if faint else 0.95
        style = {
            "edgecolor": _rgba(col, alpha),
            "facecolor": "none",
            "lw": 1.6 if faint else 2.2,
            "ls": (0, (5, 3)),
            "zorder": 1.5,
        }
        g = s.geometry
        if "region" in g:
            x0, x1, y0, y1 = g["region"]
            ax.add_patch(
                Rectangle(
                    (x0, y0),
                    x1 - x0,
                    y1 - y0,
                    edgecolor=_rgba(col, 0.5 * alpha),
                    facecolor=_rgba(col, 0.06),
                    lw=1.0,
                    ls=(0, (1, 2)),
                    zorder=0.6,
                )
            )
        if "heading" in g:
            c, h = np.asarray(g["anchor_point"], dtype=float), g["heading"]
            tip = c + 0.06 * np.array([math.cos(h), math.sin(h)])
            ax.add_patch(
                FancyArrowPatch(
                    tuple(c),
                    tuple(tip),
                    arrowstyle="-|>",
                    mutation_scale=12,
                    color=_rgba(col, alpha),
                    lw=1.6,
                    zorder=4.4,
                )
            )
        if s.kind == "line":
            p = g["points"]
            d = p[1] - p[0]
            n = float(np.hypot(*d))
            ext = (d / n) * 0.03 if n > 0 else np.zeros(2)
            ax.plot(
                [p[0][0] - ext[0], p[1][0] + ext[0]],
                [p[0][1] - ext[1], p[1][1] + ext[1]],
                color=style["edgecolor"],
                lw=style["lw"],
                ls=style["ls"],
                zorder=1.5,
            )
        elif s.kind == "circle":
            if g["radius"] > 0:
                ax.add_patch(Circle(g["centre"], g["radius"], **style))
                ax.plot(*g["centre"], marker="+", color=style["edgecolor"], ms=7, mew=1.3, zorder=1.5)
        elif s.kind == "rectangle":
            ax.add_patch(Polygon(g["corners"], closed=True, **style))
        elif s.kind == "relation":
            for a, b in g["arrows"]:
                d = np.asarray(b) - np.asarray(a)
                if float(np.hypot(*d)) < 1e-6:
                    continue
                ax.add_patch(
                    FancyArrowPatch(
                        a,
                        b,
                        arrowstyle="-|>",
                        mutation_scale=14,
                        color=_rgba(col, alpha),
                        lw=2.0 if not faint else 1.4,
                        shrinkA=6,
                        shrinkB=8,
                        zorder=4.5,
                    )
                )
                mid = (np.asarray(a) + np.asarray(b)) / 2
                ax.text(
                    mid[0],
                    mid[1],
                    s.goal.pattern.replace("_", "-"),
                    fontsize=6.5,
                    color=col,
                    ha="center",
                    va="center",
                    zorder=4.6,
                    bbox={
                        "boxstyle": "round,pad=0.12",
                        "facecolor": "white",
                        "edgecolor": col,
                        "lw": 0.6,
                        "alpha": 0.9,
                    },
                )
        elif s.kind == "tower":
            c = g["centre"]
            k0 = ctx.scene.index[s.goal.objects[0]]
            r = float(ctx.scene.radii[k0]) + 0.016
            ax.add_patch(
                Circle(c, r, edgecolor=_rgba(col, alpha), facecolor="none", lw=2.0, ls=(0, (2, 2)), zorder=4.5)
            )
            ax.text(
                c[0] + r * 0.75,
                c[1] + r * 0.75,
                f"tower ×{len(s.goal.objects)}",
                fontsize=6.5,
                color=col,
                zorder=4.6,
                bbox={"boxstyle": "round,pad=0.12", "facecolor": "white", "edgecolor": col, "lw": 0.6, "alpha": 0.9},
            )
        elif s.kind == "points":
            p = np.asarray(g["points"], dtype=float).reshape(-1, 2)
            ax.plot(
                p[:, 0], p[:, 1], ls="none", marker="o", mfc="none", color=style["edgecolor"], ms=9, mew=1.3, zorder=1.5
            )
        elif s.kind == "pose":
            t = g["target"]
            k0 = ctx.scene.index[s.goal.objects[0]]
            verts = ctx.scene.footprint(k0, t)
            ax.add_patch(
                Polygon(verts, closed=True, edgecolor=_rgba(col, alpha), facecolor="none", lw=1.4, ls=":", zorder=4.5)
            )
            ax.plot(t[0], t[1], marker="x", color=col, ms=6, mew=1.4, zorder=1.9)


def _draw_path(
    ax: Any, a: Sequence[float], b: Sequence[float], color: Any, *, lw: float = 2.2, faint: bool = False
) -> None:
    from matplotlib.patches import FancyArrowPatch

    a2, b2 = np.asarray(a[:2], dtype=float), np.asarray(b[:2], dtype=float)
    if float(np.hypot(*(b2 - a2))) < 1e-4:
        ax.plot(*b2, marker="o", color=color, ms=4, zorder=4.8)
        return
    ax.add_patch(
        FancyArrowPatch(
            tuple(a2),
            tuple(b2),
            arrowstyle="-|>" if not faint else "->",
            mutation_scale=16 if not faint else 9,
            connectionstyle="arc3,rad=-0.18",
            color=color,
            lw=lw,
            zorder=4.8 if not faint else 1.6,
            shrinkA=2,
            shrinkB=4,
            alpha=1.0 if not faint else 0.45,
        )
    )


def _draw_faint_paths(ax: Any, moves: list[tuple[Sequence[float], Sequence[float], Any]], *, lw: float) -> None:
    """Faint arrows for earlier moves; beyond MAX_ARROWS moves, straight lines in one collection.

    Curved arrows cost milliseconds each to lay out; a plan of thousands of
    actions would take minutes to draw with them.
    """
    if len(moves) <= MAX_ARROWS:
        for a, b, color in moves:
            _draw_path(ax, a, b, color, lw=lw, faint=True)
        return
    from matplotlib.collections import LineCollection

    segs = [[(float(a[0]), float(a[1])), (float(b[0]), float(b[1]))] for a, b, _ in moves]
    ax.add_collection(LineCollection(segs, colors=[c for _, _, c in moves], linewidths=lw * 0.6, alpha=0.3, zorder=1.6))


def _panel(ax: Any, ctx: _Ctx, shapes: list[GoalShape], step: int | None, *, fontsize: float = 8.0) -> None:
    """Side panel: goals with status, the action list, and the legend."""
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    ax.set_axis_off()
    fig = ax.figure
    h_in = ax.get_position().height * fig.get_figheight()
    lh = fontsize * 1.5 / 72.0 / h_in
    y = 1.0

    def line(
        text: str,
        *,
        color: str = "#222222",
        weight: str = "normal",
        size: float = fontsize,
        x: float = 0.0,
        box: str | None = None,
    ) -> None:
        nonlocal y
        kw = {}
        if box:
            kw["bbox"] = {"boxstyle": "round,pad=0.2", "facecolor": box, "edgecolor": "none", "alpha": 0.18}
        ax.text(
            x, y, text, transform=ax.transAxes, ha="left", va="top", fontsize=size, color=color, fontweight=weight, **kw
        )
        y -= lh * size / fontsize

    if ctx.goals is not None:
        line("Goals", weight="bold", size=fontsize + 1)
        for s in shapes:
            mark = "✓" if s.met else "✗"
            ax.add_patch(_square(ax, y, ctx.goal_color(s.index), lh))
            line(f"{mark} {describe_goal(s.goal)}", x=0.07, color="#222222" if s.met else "#b02a2a")
        y -= lh * 0.4
    n = ctx.n_actions
    line(
        f"Plan: {n} action{'s' if n != 1 else ''}" + ("" if ctx.plan.solved else "  (NOT solved)"),
        weight="bold",
        size=fontsize + 1,
    )
    lo, hi = 0, n
    window = 12
    if n > window:
        cur = step if step is not None else n
        lo = max(0, min(cur - window // 2, n - window))
        hi = lo + window
    if lo > 0:
        line(f"… {lo} earlier", color="#888888")
    for j in range(lo, hi):
        a = ctx.plan.actions[j]
        verb = {"goal": "place", "relocate": "relocate", "unstack": "unstack"}[a.purpose]
        k = ctx.scene.index[a.object]
        where = f"onto {a.on}" if a.on is not None else f"→ ({a.to[0]:+.2f}, {a.to[1]:+.2f})"
        text = (
            textwrap.shorten(f"{j + 1}. {verb} {ctx.scene.ids[k]} {ctx.scene.names[k]}", 30, placeholder="…")
            + f" {where}"
        )
        col = PURPOSE_COLORS[a.purpose]
        if step is None:
            line(text, color=col)
        elif j + 1 == step:
            line("▸ " + text, color=col, weight="bold", box=col)
        elif j + 1 < step:
            line("  " + text, color="#444444")
        else:
            line("  " + text, color="#aaaaaa")
    if hi < n:
        line(f"… {n - hi} more", color="#888888")
    handles = [
        Line2D([], [], color=PURPOSE_COLORS["goal"], lw=2.2, marker=">", ms=5, label="goal placement"),
        Line2D([], [], color=PURPOSE_COLORS["relocate"], lw=2.2, marker=">", ms=5, label="relocation (obstacle)"),
        Line2D([], [], color=PURPOSE_COLORS["unstack"], lw=2.2, marker=">", ms=5, label="unstack (blocker)"),
        Line2D([], [], color="#555555", lw=1.2, ls="--", label="pose before the move"),
        Patch(facecolor="#bbbbbb", edgecolor="#444444", lw=0.8, label="object (id inside)"),
        Patch(facecolor="#777777", edgecolor="#7048e8", lw=0.9, label="stacked: shadow, boxed label"),
        Line2D([], [], color="#1f77b4", lw=1.8, ls=(0, (5, 3)), label="goal shape (fitted)"),
    ]
    ax.legend(
        handles=handles,
        loc="lower left",
        fontsize=fontsize - 1,
        frameon=True,
        framealpha=0.9,
        borderpad=0.5,
        handlelength=2.2,
        title="Legend",
        title_fontsize=fontsize,
    )


def _square(ax: Any, y: float, color: str, lh: float) -> Any:
    from matplotlib.patches import Rectangle

    return Rectangle(
        (0.0, y - lh * 0.8), 0.045, lh * 0.65, transform=ax.transAxes, facecolor=color, edgecolor="none", clip_on=False
    )


def _titles(fig: Any, ctx: _Ctx, title: str, fontsize: float = 11) -> None:
    fig.text(0.012, 0.985, title, ha="left", va="top", fontsize=fontsize, fontweight="bold", color="#111111")
    if ctx.instruction:
        text = textwrap.shorten(ctx.instruction, 150, placeholder="…")
        fig.text(0.012, 0.947, f"“{text}”", ha="left", va="top", fontsize=fontsize - 2, style="italic", color="#444444")


def _new_figure(ctx: _Ctx, *, panels: int = 1, panel: bool = True) -> tuple[Any, list[Any], Any | None]:
    Figure, Canvas = _mpl()
    opts = ctx.options
    xmin, xmax, ymin, ymax = ctx.scene.bounds
    w, h = xmax - xmin, ymax - ymin
    m = 0.09 * max(w, h)
    aspect = (w + 1.2 * m) / (h + 1.45 * m)
    table_w = opts.table_height_in * aspect
    top_in, bottom_in, left_in = 0.75, 0.45, 0.55
    width = left_in + panels * (table_w + 0.35) + (opts.panel_width_in if panel else 0.1)
    height = opts.table_height_in + top_in + bottom_in
    fig = Figure(figsize=(width, height), dpi=opts.dpi, facecolor="white")
    Canvas(fig)
    axes = []
    for p in range(panels):
        x = (left_in + p * (table_w + 0.35)) / width
        axes.append(fig.add_axes((x, bottom_in / height, table_w / width, opts.table_height_in / height)))
    pax = None
    if panel:
        x = (left_in + panels * (table_w + 0.35) + 0.1) / width
        pax = fig.add_axes((x, bottom_in / height, (opts.panel_width_in - 0.2) / width, opts.table_height_in / height))
    return fig, axes, pax


def _to_image(fig: Any) -> np.ndarray:
    fig.canvas.draw()
    return np.asarray(fig.canvas.buffer_rgba())[..., :3].copy()


# ----------------------------------------------------------------- figures


def render_state(ctx: _Ctx, step: int, *, goals_drawn: str = "met") -> np.ndarray:
    """Picture of the scene after ``step`` actions (0: the initial scene) as RGB.

    ``goals_drawn``: ``"met"`` draws the shapes of the goals that hold,
    ``"all"`` every goal's fitted shape, ``"none"`` no shapes.
    """
    state = ctx.states[step]
    shapes = ctx.shapes(step)
    fig, (ax,), pax = _new_figure(ctx)
    _draw_table(ax, ctx.scene)
    n = ctx.n_actions
    highlight: dict[int, str] = {}
    if step == 0:
        title = f"Initial scene · {ctx.scene.n} objects"
    elif step == n and goals_drawn == "all":
        title = "Final scene · " + (
            "all goals met" if all(s.met for s in shapes) else f"{sum(not s.met for s in shapes)} goal(s) not met"
        )
    else:
        a = ctx.plan.actions[step - 1]
        title = f"Step {step} of {n} · {_PURPOSE_WORD[a.purpose]}: {ctx.scene.label(ctx.scene.index[a.object])}"
    # Earlier moves as faint arrows, the current one bold with its old pose dashed.
    if 0 < step and goals_drawn != "all":
        moves: list[tuple[Sequence[float], Sequence[float], Any]] = []
        for j in range(step - 1):
            a = ctx.plan.actions[j]
            moves.append((ctx.states[j].poses[ctx.scene.index[a.object]], a.to, "#8d8d8d"))
        _draw_faint_paths(ax, moves, lw=1.0)
    if goals_drawn != "none":
        _draw_goal_shapes(ax, ctx, shapes, faint=goals_drawn == "met", only_met=goals_drawn == "met")
    if 0 < step and goals_drawn != "all":
        from matplotlib.patches import Polygon

        a = ctx.plan.actions[step - 1]
        k = ctx.scene.index[a.object]
        col = PURPOSE_COLORS[a.purpose]
        before = ctx.states[step - 1]
        old = _footprint(ctx, before, k)
        # Drawn above the objects: the old pose is often under another object (an unstacked blocker).
        ax.add_patch(Polygon(old, closed=True, fill=False, edgecolor=col, lw=1.4, ls="--", zorder=4.7))
        _draw_path(ax, before.poses[k], a.to, col)
        highlight[k] = col
    _draw_objects(ax, ctx, state, highlight=highlight, rings=step == 0 or goals_drawn == "all")
    _titles(fig, ctx, title)
    _panel(pax, ctx, shapes, None if goals_drawn == "all" else step)
    img = _to_image(fig)
    return img


def render_before_after(ctx: _Ctx) -> np.ndarray:
    """The initial and the final scene side by side (final with goal shapes) as RGB."""
    n = ctx.n_actions
    final = ctx.states[n]
    shapes = ctx.shapes(n)
    fig, (a0, a1), pax = _new_figure(ctx, panels=2)
    for ax, _state, name in ((a0, ctx.states[0], "before"), (a1, final, f"after {n} action{'s' if n != 1 else ''}")):
        _draw_table(ax, ctx.scene)
        ax.set_title(name, fontsize=10, fontweight="bold", loc="center", pad=3)
    moves: list[tuple[Sequence[float], Sequence[float], Any]] = [
        (ctx.states[j].poses[ctx.scene.index[a.object]], a.to, PURPOSE_COLORS[a.purpose])
        for j, a in enumerate(ctx.plan.actions)
    ]
    _draw_faint_paths(a1, moves, lw=1.2)
    _draw_objects(a0, ctx, ctx.states[0], rings=True)
    _draw_goal_shapes(a1, ctx, shapes)
    _draw_objects(a1, ctx, final, rings=True)
    met = sum(s.met for s in shapes)
    status = "solved" if ctx.plan.solved else "NOT solved"
    _titles(fig, ctx, f"Before and after · plan {status}, {met}/{len(shapes)} goals met")
    _panel(pax, ctx, shapes, None)
    return _to_image(fig)


def _fields(ctx: _Ctx, step: int) -> Any:
    from .fields import pose_fields

    if ctx.goals is None:
        raise InputError("heatmaps need the goals (the plan carries none; pass them)")
    if not 1 <= step <= ctx.n_actions:
        raise InputError(f"step {step} is outside the plan's {ctx.n_actions} actions (steps count from 1)")
    return pose_fields(
        ctx.scene, ctx.goals, list(ctx.plan.actions), step - 1, resolution=ctx.options.heatmap_resolution
    )


def heatmap_fields(
    scene: SceneSpec | Scene | dict | str | Path,
    plan: PlanSpec | dict | str | Path,
    step: int,
    *,
    goals: GoalSpec | dict | list | None = None,
    resolution: float = 0.005,
) -> Any:
    """The grids drawn in ``heatmaps_step_XX.png`` for action ``step`` (counted from 1).

    Returns
    -------
    lgmcts.viz.fields.Fields
        ``prior`` (H, W) in [0, 1], ``free`` (H, W) bool and ``product``
        ``= prior * free``, on cell centres ``xs`` (W,) and ``ys`` (H,) in metres,
        ``resolution`` metres apart.
    """
    ctx = _context(scene, plan, goals, None, FigureOptions(heatmap_resolution=resolution))
    return _fields(ctx, step)


def render_heatmaps(ctx: _Ctx, step: int) -> np.ndarray:
    """f_prior, f_free and f = f_prior × f_free for action ``step`` (1-based) as RGB.

    Black is 0 and white 1, as in the paper's Fig. 5. The grids are those of
    :func:`lgmcts.viz.fields.pose_fields` in the state before the action;
    the object's pose before the move is a circle, the pose the plan chose a star.
    """
    import matplotlib.patheffects as pe

    fields = _fields(ctx, step)
    a = ctx.plan.actions[step - 1]
    k = ctx.scene.index[a.object]
    before = ctx.states[step - 1]
    Figure, Canvas = _mpl()
    xmin, xmax, ymin, ymax = ctx.scene.bounds
    aspect = (xmax - xmin) / (ymax - ymin)
    ph = 3.3
    pw = ph * aspect
    width = 0.5 + 3 * (pw + 0.5) + 0.9
    height = ph + 1.45
    fig = Figure(figsize=(width, height), dpi=ctx.options.dpi, facecolor="white")
    Canvas(fig)
    data = [fields.prior, fields.free.astype(float), fields.product]
    names = [
        r"$f_{\mathrm{prior}}$  (pattern prior)",
        r"$f_{\mathrm{free}}$  (collision-free, in workspace)",
        r"$f = f_{\mathrm{prior}} \times f_{\mathrm{free}}$",
    ]
    extent = (
        fields.xs[0] - (fields.xs[1] - fields.xs[0]) / 2,
        fields.xs[-1] + (fields.xs[1] - fields.xs[0]) / 2,
        fields.ys[0] - (fields.ys[1] - fields.ys[0]) / 2,
        fields.ys[-1] + (fields.ys[1] - fields.ys[0]) / 2,
    )
    im = None
    for p, (grid, name) in enumerate(zip(data, names)):
        ax = fig.add_axes(((0.5 + p * (pw + 0.5)) / width, 0.55 / height, pw / width, ph / height))
        im = ax.imshow(grid, origin="lower", extent=extent, cmap="gray", vmin=0.0, vmax=1.0, interpolation="nearest")
        for j in range(ctx.scene.n):
            if j == k:
                continue
            v = _footprint(ctx, before, j)
            ax.fill(v[:, 0], v[:, 1], facecolor="none", edgecolor="#f2a541", lw=0.7)
        ax.plot(
            *before.poses[k, :2],
            marker="o",
            ms=7,
            mfc="none",
            mec="#4dabf7",
            mew=1.6,
            ls="none",
            label=f"{ctx.scene.ids[k]} now",
        )
        ax.plot(
            a.to[0], a.to[1], marker="*", ms=13, mfc="white", mec="#e03131", mew=1.2, ls="none", label="chosen pose"
        )
        ax.set_xlim(xmin, xmax)
        ax.set_ylim(ymin, ymax)
        ax.set_aspect("equal")
        ax.set_title(name, fontsize=9)
        ax.tick_params(labelsize=6.5, length=2)
        ax.text(0.5, -0.085, "▼ viewer", transform=ax.transAxes, ha="center", va="top", fontsize=7, color="#555555")
        L = _nice_length(xmax - xmin)
        x0, y0 = xmin + 0.02, ymin + 0.02
        halo = [pe.withStroke(linewidth=3.2, foreground="black")]
        ax.plot([x0, x0 + L], [y0, y0], color="#ffd43b", lw=2.2, solid_capstyle="butt", path_effects=halo)
        ax.text(
            x0 + L / 2,
            y0 + 0.008,
            f"{L * 100:g} cm",
            color="#ffd43b",
            fontsize=7,
            fontweight="bold",
            ha="center",
            va="bottom",
            path_effects=halo,
        )
        if p == 0:
            ax.legend(loc="upper left", fontsize=6.5, framealpha=0.85, handletextpad=0.3, borderpad=0.3)
    cax = fig.add_axes(((0.5 + 3 * (pw + 0.5) - 0.3) / width, 0.55 / height, 0.12 / width, ph / height))
    cb = fig.colorbar(im, cax=cax)
    cb.ax.tick_params(labelsize=7)
    cb.set_label("density (0 black … 1 white)", fontsize=7)
    verb = _PURPOSE_WORD[a.purpose]
    goals = ctx.goals.goals if ctx.goals is not None else []
    member = [describe_goal(g) for g in goals if ctx.scene.ids[k] in g.objects]
    why = ("; goal: " + ", ".join(member)) if member and a.purpose == "goal" else ""
    fig.text(
        0.01,
        0.98,
        f"Pose fields at step {step} of {ctx.n_actions} · {verb} of {ctx.scene.label(k)}{why}",
        ha="left",
        va="top",
        fontsize=10,
        fontweight="bold",
    )
    if a.purpose != "goal":
        fig.text(
            0.01,
            0.925,
            "not a goal placement: the prior is uniform and only free space constrains the pose",
            ha="left",
            va="top",
            fontsize=8,
            color="#555555",
        )
    elif ctx.instruction:
        fig.text(
            0.01,
            0.925,
            f"“{textwrap.shorten(ctx.instruction, 140, placeholder='…')}”",
            ha="left",
            va="top",
            fontsize=8,
            style="italic",
            color="#444444",
        )
    return _to_image(fig)


# ----------------------------------------------------------------- entry point


def _context(scene: Any, plan: Any, goals: Any, instruction: str | None, options: FigureOptions) -> _Ctx:
    spec = scene.spec if isinstance(scene, Scene) else load_scene(scene)
    sc = scene if isinstance(scene, Scene) else Scene.from_spec(spec)
    pl = load_plan(plan)
    gs = parse_goals(goals) if goals is not None else pl.goals
    if gs is not None:
        gs.check_against(sc.spec)
    if instruction is None:
        extra = getattr(pl, "model_extra", None) or {}
        instruction = extra.get("instruction") if isinstance(extra.get("instruction"), str) else None
    states = replay(sc, list(pl.actions))
    paints = tuple(paint(c) for c in sc.colors)
    return _Ctx(sc, gs, pl, states, paints, instruction, options, pl.fits if goals is None else None)


def _save(path: Path, save: Callable[[Path], None]) -> Path:
    """Run ``save(tmp)`` on a temporary file beside ``path``, then rename it over ``path``.

    A full disk or a read-only folder is one line (:class:`InputError`) and
    leaves neither a truncated picture nor a temporary file.
    """
    from ..outputs import publish, temporary_beside

    tmp: Path | None = None
    try:
        tmp = temporary_beside(path, suffix=path.suffix)
        save(tmp)
        publish(tmp, path)
        tmp = None
    except OSError as exc:
        raise InputError(f"cannot write picture {path}: {exc.strerror or exc}") from None
    finally:
        if tmp is not None:
            try:
                tmp.unlink()
            except OSError:
                pass
    return path


def _save_png(img: np.ndarray, path: Path, dpi: int) -> Path:
    from PIL import Image

    return _save(path, lambda tmp: Image.fromarray(img).save(tmp, format="PNG", dpi=(dpi, dpi), compress_level=6))


def _gif(frames: list[np.ndarray], path: Path, opts: FigureOptions) -> Path:
    from PIL import Image

    ims = []
    for f in frames:
        im = Image.fromarray(f)
        scale = opts.gif_width_px / im.width
        if scale < 1:
            im = im.resize((opts.gif_width_px, max(1, round(im.height * scale))), Image.Resampling.LANCZOS)
        ims.append(im.convert("P", palette=Image.Palette.ADAPTIVE, colors=255))
    durations = [int(opts.frame_s * 1000)] * len(ims)
    durations[-1] = int(opts.last_frame_s * 1000)
    # disposal=1 and optimize=False keep one GIF frame per plan state (Pillow
    # would otherwise merge frames it finds identical).
    return _save(path, lambda tmp: ims[0].save(
        tmp, format="GIF", save_all=True, append_images=ims[1:], duration=durations, loop=0, optimize=False, disposal=1
    ))


def step_name(step: int, n_actions: int) -> str:
    """Zero-padded step number used in file names (``"03"``, or ``"003"`` past 99)."""
    return f"{step:0{max(2, len(str(n_actions)))}d}"


def pictured_steps(n: int, most: int) -> list[int]:
    """The actions (counted from 1) of an ``n``-action plan that get a picture: all, or ``most`` evenly spaced."""
    if n <= most:
        return list(range(1, n + 1))
    if most < 1:
        return []
    return sorted({round(v) for v in np.linspace(n / most, n, most)})


def write_plan_figures(
    scene: SceneSpec | Scene | dict | str | Path,
    plan: PlanSpec | dict | str | Path,
    out_dir: str | Path,
    *,
    goals: GoalSpec | dict | list | None = None,
    instruction: str | None = None,
    heatmap_step: int | None = None,
    options: FigureOptions = FigureOptions(),
) -> list[Path]:
    """Write the pictures of a plan into ``out_dir`` (created if needed).

    Parameters
    ----------
    scene : the scene the plan starts from (model, dict or JSON path).
    plan : the plan (model, dict or JSON path).
    out_dir : folder to write into.
    goals : goals to draw; default the goals the plan carries. Without any,
        no goal shapes and no heatmaps are drawn.
    instruction : the plain-language command, shown under each title;
        default the plan's ``instruction`` field when it has one.
    heatmap_step : 1-based number of the action whose pose fields are drawn
        (``heatmaps_step_XX.png``); default the first goal placement.
    options : sizes and timings, see :class:`FigureOptions`.

    Returns
    -------
    list of Path
        In order: ``initial.png``, ``step_01.png`` … one per action (at most
        ``options.max_step_pictures``, evenly spaced),
        ``final.png``, ``before_after.png``, ``plan.gif`` (one frame for the
        initial scene and one per pictured action), and ``heatmaps_step_XX.png`` when
        goals are known and the plan has a goal placement (or ``heatmap_step``).

    Raises
    ------
    InputError
        Bad scene, plan or goals, an action naming an unknown object, or a
        ``heatmap_step`` outside the plan.
    """
    ctx = _context(scene, plan, goals, instruction, options)
    n = ctx.n_actions
    if heatmap_step is not None and not 1 <= heatmap_step <= n:
        raise InputError(f"heatmap step {heatmap_step} is outside the plan's {n} actions (steps count from 1)")
    out = Path(out_dir)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"cannot create folder {out}: {exc.strerror}") from None
    written: list[Path] = []
    frames: list[np.ndarray] = []
    img = render_state(ctx, 0)
    frames.append(img)
    written.append(_save_png(img, out / "initial.png", options.dpi))
    # A bar only on a terminal (tqdm's disable=None); LGMCTS_NO_PROGRESS=1 hides it there too.
    quiet = os.environ.get("LGMCTS_NO_PROGRESS", "") not in ("", "0")
    steps = tqdm(
        pictured_steps(n, options.max_step_pictures),
        desc="drawing steps",
        file=sys.stderr,
        leave=False,
        disable=True if quiet else None,
    )
    for s in steps:
        img = render_state(ctx, s)
        frames.append(img)
        written.append(_save_png(img, out / f"step_{step_name(s, n)}.png", options.dpi))
    written.append(_save_png(render_state(ctx, n, goals_drawn="all"), out / "final.png", options.dpi))
    written.append(_save_png(render_before_after(ctx), out / "before_after.png", options.dpi))
    written.append(_gif(frames, out / "plan.gif", options))
    if heatmap_step is None and ctx.goals is not None:
        heatmap_step = next((j + 1 for j, a in enumerate(ctx.plan.actions) if a.purpose == "goal"), None)
    if heatmap_step is not None and ctx.goals is not None:
        img = render_heatmaps(ctx, heatmap_step)
        written.append(_save_png(img, out / f"heatmaps_step_{step_name(heatmap_step, n)}.png", options.dpi))
    return written
