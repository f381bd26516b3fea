"""What the pictures show, computed without any plotting library.

:func:`replay` turns a plan into the sequence of scene states it passes
through; :func:`goal_shapes` describes each goal's geometry in a state (the
fitted line, circle or rectangle, relation arrows, tower and pose marks) and
whether the acceptance rules hold. Both the matplotlib figures and the HTML
viewer draw from these descriptions.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import shapely

from ..errors import InputError
from ..formats import RELATIONS, Action, Goal, GoalSpec, PlanSpec
from ..params import resolve as resolve_params
from ..scene import TABLE, Scene, State
from ..validate import fit_circle, goal_satisfied

__all__ = ["GoalShape", "replay", "goal_shapes", "describe_action", "describe_goal", "plan_goals", "GOAL_COLORS", "PURPOSE_COLORS"]

#: Colours of goals, in order (a qualitative palette that stays readable in grey).
GOAL_COLORS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2")

#: Colours of the three action purposes.
PURPOSE_COLORS = {"goal": "#1b9e77", "relocate": "#e8590c", "unstack": "#7048e8"}


@dataclass(frozen=True)
class GoalShape:
    """Geometry of one goal in one state (table frame, metres).

    Attributes
    ----------
    index : position of the goal in the goal list.
    goal : the goal itself.
    problem : None when the goal holds, else the reason it does not.
    kind : ``"line"``, ``"circle"``, ``"rectangle"``, ``"relation"``,
        ``"tower"`` or ``"pose"``.
    geometry : by kind —
        line: ``points`` (2, 2) segment end points;
        circle: ``centre`` (2,), ``radius``;
        rectangle: ``corners`` (4, 2);
        relation: ``arrows`` list of ((2,), (2,)) anchor-to-object segments,
        ``direction`` (2,) the relation's unit direction;
        tower: ``centre`` (2,) of the base, ``levels`` object ids bottom-up;
        pose: ``target`` (3,) the goal pose;
        and, for a goal with parameters, ``region`` ``[xmin, xmax, ymin,
        ymax]`` (its box in the scene's workspace) and ``heading`` (rad,
        with ``anchor_point`` (2,) where to draw it: the centres' mean).
    """

    index: int
    goal: Goal
    problem: str | None
    kind: str
    geometry: dict = field(default_factory=dict)

    @property
    def met(self) -> bool:
        return self.problem is None

    def to_json(self) -> dict:
        """JSON-ready form (lists of floats) for the HTML viewer."""

        def conv(v):
            if isinstance(v, np.ndarray):
                return np.round(v, 6).tolist()
            if isinstance(v, (list, tuple)):
                return [conv(x) for x in v]
            if isinstance(v, (np.floating, float)):
                return round(float(v), 6)
            if isinstance(v, np.integer):
                return int(v)
            return v

        return {"index": self.index, "met": self.met, "problem": self.problem, "kind": self.kind, **{k: conv(v) for k, v in self.geometry.items()}}


def replay(scene: Scene, actions: list[Action]) -> list[State]:
    """States before the first action and after each one (``len(actions) + 1``).

    Raises
    ------
    InputError
        When an action names an object the scene does not have. Illegal but
        well-formed actions (picking a covered object) are replayed as given:
        pictures show what the plan says, the validator judges it.
    """
    states = [scene.initial]
    for k, a in enumerate(actions):
        if a.object not in scene.index:
            raise InputError(f"action {k + 1} moves unknown object id {a.object}")
        if a.on is not None and a.on not in scene.index:
            raise InputError(f"action {k + 1} places object {a.object} on unknown object id {a.on}")
        if a.on == a.object:
            raise InputError(f"action {k + 1} places object {a.object} on itself")
        sup = TABLE if a.on is None else scene.index[a.on]
        states.append(states[-1].moved(scene.index[a.object], np.asarray(a.to, dtype=float), sup))
    return states


def _line(xy: np.ndarray) -> np.ndarray:
    c = xy.mean(axis=0)
    if len(xy) < 2 or np.allclose(xy, c):
        return np.stack([c, c])
    _, _, vt = np.linalg.svd(xy - c, full_matrices=False)
    u = vt[0]
    t = (xy - c) @ u
    return np.stack([c + u * t.min(), c + u * t.max()])


def goal_shapes(scene: Scene, goals: GoalSpec | None, state: State) -> list[GoalShape]:
    """Describe every goal's geometry in ``state`` and whether it holds."""
    if goals is None:
        return []
    out = []
    for k, g in enumerate(goals.goals):
        if any(i not in scene.index for i in [*g.objects, *([g.anchor] if g.anchor is not None else [])]):
            raise InputError(f"goal {k} ({g.pattern}) names an object the scene does not have")
        idx = [scene.index[i] for i in g.objects]
        xy = np.asarray(state.poses[idx, :2], dtype=float)
        problem = goal_satisfied(g, scene, state.poses, state.on)
        p = g.pattern
        geom: dict
        if p == "line":
            kind, geom = "line", {"points": _line(xy)}
        elif p == "circle":
            c, r = fit_circle(xy) if len(xy) >= 3 else (xy.mean(axis=0), 0.0)
            kind, geom = "circle", {"centre": np.asarray(c), "radius": float(r) if math.isfinite(r) else 0.0}
        elif p == "rectangle":
            rect = shapely.MultiPoint(xy).minimum_rotated_rectangle
            if rect.geom_type == "Polygon":
                corners = np.asarray(rect.exterior.coords)[:4]
            else:  # collinear centres: draw the degenerate rectangle as its segment
                seg = _line(xy)
                corners = np.stack([seg[0], seg[1], seg[1], seg[0]])
            kind, geom = "rectangle", {"corners": corners}
        elif p in RELATIONS:
            a = np.asarray(state.poses[scene.index[g.anchor], :2], dtype=float)  # type: ignore[index]
            kind = "relation"
            geom = {"anchor": a, "arrows": [(a, xy[j]) for j in range(len(xy))], "direction": np.asarray(RELATIONS[p])}
        elif p == "tower":
            kind, geom = "tower", {"centre": xy[0], "levels": list(g.objects)}
        else:
            kind, geom = "pose", {"target": np.asarray(g.pose, dtype=float)}
        if g.region is not None or g.facing is not None:
            gp = resolve_params(g, scene.bounds, scene.radii[idx])
            if gp.box is not None:
                geom["region"] = np.asarray(gp.box, dtype=float)
            if gp.heading is not None:
                geom["heading"] = float(gp.heading)
                geom["anchor_point"] = xy.mean(axis=0)
        out.append(GoalShape(k, g, problem, kind, geom))
    return out


def describe_goal(goal: Goal) -> str:
    """One short line: ``"circle of 1, 2, 3, 4"``, ``"5 behind 1"``,
    ``"large circle of 1, 2, 3 in top left, facing north"``."""
    text = _describe_shape(goal)
    if isinstance(goal.size, str):
        text = f"{goal.size} {text}"
    elif goal.size is not None:
        text = f"{text}, size {goal.size:.2f} m"
    if isinstance(goal.region, str):
        text += f" in {goal.region}"
    elif goal.region is not None:
        text += " in [" + ", ".join(f"{v:.2f}" for v in goal.region) + "]"
    if isinstance(goal.facing, str):
        text += f", facing {goal.facing}"
    elif goal.facing is not None:
        text += f", facing {goal.facing:.2f} rad"
    return text


def _describe_shape(goal: Goal) -> str:
    objs = ", ".join(str(i) for i in goal.objects)
    p = goal.pattern
    if p in RELATIONS:
        word = "behind" if p == "behind" else f"{p.replace('_', '-')} of"
        return f"{objs} {word} {goal.anchor}"
    if p == "tower":
        return "tower " + " < ".join(str(i) for i in goal.objects)
    if p == "pose":
        x, y, t = goal.pose  # type: ignore[misc]
        return f"{objs} to ({x:.2f}, {y:.2f}, {t:.2f})"
    return f"{p} of {objs}"


def describe_action(scene: Scene, action: Action, number: int, total: int) -> str:
    """One line about an action: ``"3/7  relocate 9 black phone -> (0.12, -0.20)"``."""
    k = scene.index[action.object]
    where = f"on {action.on}" if action.on is not None else f"to ({action.to[0]:.2f}, {action.to[1]:.2f})"
    verb = {"goal": "place", "relocate": "relocate", "unstack": "unstack"}[action.purpose]
    return f"{number}/{total}  {verb} {scene.label(k)} {where}"


def plan_goals(plan: PlanSpec, goals: GoalSpec | None) -> GoalSpec | None:
    """The goals to draw: those given, else the ones the plan carries."""
    return goals if goals is not None else plan.goals
