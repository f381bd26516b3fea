"""What the pictures show, computed without any plotting library.

:func:`replay` turns a plan into the sequence of scene states it passes
through; :func:`goal_shapes` describes each goal's geometry in a state (the
fitted line, circle or rectangle, relation arrows, tower and pose marks) and
whether the acceptance rules hold. Both the matplotlib figures and the HTML
viewer draw from these descriptions.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass, field

import numpy as np

from ..errors import InputError
from ..formats import Action, Goal, GoalSpec, PlanSpec
from ..params import resolve as resolve_params
from ..patterns import registry
from ..scene import Scene, State, replay
from ..validate import goal_satisfied

__all__ = [
    "GOAL_COLORS",
    "PURPOSE_COLORS",
    "GoalShape",
    "describe_action",
    "describe_goal",
    "goal_shapes",
    "plan_goals",
    "replay",
]

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
        ``"tower"``, ``"pose"`` or ``"points"``, as the goal's pattern draws
        itself (its ``shape``; a pattern module may reuse any kind).
    geometry : by kind —
        line: ``points`` (2, 2) segment end points;
        circle: ``centre`` (2,), ``radius``;
        rectangle: ``corners`` (4, 2);
        relation: ``arrows`` list of ((2,), (2,)) anchor-to-object segments,
        ``direction`` (2,) the relation's unit direction;
        tower: ``centre`` (2,) of the base, ``levels`` object ids bottom-up;
        pose: ``target`` (3,) the goal pose;
        points: ``points`` (n, 2) the centres (a pattern without a shape of its own);
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

        return {
            "index": self.index,
            "met": self.met,
            "problem": self.problem,
            "kind": self.kind,
            **{k: conv(v) for k, v in self.geometry.items()},
        }


def goal_shapes(
    scene: Scene, goals: GoalSpec | None, state: State, fits: list | None = None, only: Iterable[int] | None = None
) -> list[GoalShape]:
    """Describe every goal's geometry in ``state`` and whether it holds.

    ``fits`` are the goals' fitted parameters a plan carries for its final
    state (``PlanSpec.fits``): given for that state, a goal is drawn from
    them instead of being fitted again. ``only``: the indices of the goals
    to describe (in increasing order; default all)."""
    if goals is None:
        return []
    out = []
    chosen = range(len(goals.goals)) if only is None else only
    for k in chosen:
        g = goals.goals[k]
        if any(i not in scene.index for i in [*g.objects, *([g.anchor] if g.anchor is not None else [])]):
            raise InputError(f"goal {k} ({g.pattern}) names an object the scene does not have")
        idx = [scene.index[i] for i in g.objects]
        xy = np.asarray(state.poses[idx, :2], dtype=float)
        problem = goal_satisfied(g, scene, state.poses, state.on)
        pattern = registry().get(g.pattern)
        if pattern is None:
            raise InputError(f"goal {k}: pattern '{g.pattern}' is not registered (load its module)")
        drawn = pattern.draw(fits[k]) if fits is not None and k < len(fits) and fits[k] is not None else None
        kind, geom = drawn if drawn is not None else pattern.shape(g, scene, state.poses)
        geom = dict(geom)
        if g.region is not None or g.facing is not None:
            gp = resolve_params(g, scene.bounds, scene.radii[idx].tolist())
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
    pattern = registry().get(goal.pattern)
    if pattern is None:
        return f"{goal.pattern} of " + ", ".join(str(i) for i in goal.objects)
    return pattern.describe(goal)


def describe_action(scene: Scene, action: Action, number: int, total: int) -> str:
    """One line about an action: ``"3/7  relocate 9 black phone -> (0.12, -0.20)"``."""
    k = scene.index[action.object]
    where = f"on {action.on}" if action.on is not None else f"to ({action.to[0]:.2f}, {action.to[1]:.2f})"
    verb = {"goal": "place", "relocate": "relocate", "unstack": "unstack"}[action.purpose]
    return f"{number}/{total}  {verb} {scene.label(k)} {where}"


def plan_goals(plan: PlanSpec, goals: GoalSpec | None) -> GoalSpec | None:
    """The goals to draw: those given, else the ones the plan carries."""
    return goals if goals is not None else plan.goals
