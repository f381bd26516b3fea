"""lgmcts: language-guided Monte-Carlo tree search for tabletop rearrangement.

Quick use::

    import lgmcts
    scene = lgmcts.load_scene("examples/tabletop.json")
    goals = lgmcts.parse(scene, "put all blocks in a circle and the white bottle behind one block")
    plan = lgmcts.plan(scene, goals, seed=0)
    assert lgmcts.check(scene, goals, plan).valid
"""

from __future__ import annotations

from typing import Any

from .errors import InputError
from .formats import (
    Action,
    Goal,
    GoalSpec,
    PlanSpec,
    SceneSpec,
    load_goals,
    load_plan,
    load_scene,
    save_json,
)
from .planner import SearchOptions, StepOptions, plan
from .validate import Verdict, check

#: A plan is the plan JSON model.
Plan = PlanSpec
#: A goal specification is the goal JSON model.
Goals = GoalSpec

__all__ = [
    "Action",
    "Goal",
    "GoalSpec",
    "Goals",
    "InputError",
    "Plan",
    "PlanSpec",
    "SceneSpec",
    "SearchOptions",
    "StepOptions",
    "Verdict",
    "check",
    "load_goals",
    "load_plan",
    "load_scene",
    "parse",
    "plan",
    "save_json",
]

__version__ = "0.1.0"


def parse(scene: Any, text: str, **kwargs: Any) -> GoalSpec:
    """Turn a plain-language command into goals (see :mod:`lgmcts.language`)."""
    from .language import parse as _parse

    return _parse(scene, text, **kwargs)
