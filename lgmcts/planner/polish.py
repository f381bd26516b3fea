"""Plan polishing: drop moves a solved plan does not need.

Search returns the first plan that reaches every goal, and its random
relocations are often more than the scene requires: an obstacle moved out of
a region that the pattern ended up not using, or a buried goal object parked
on the table before its final move. Two rewrites fix most of that, each kept
only when the acceptance rules (:func:`lgmcts.validate.check`) still hold for
the whole plan:

* **merge** — an object moved more than once goes straight to its last pose
  at its first move, and the later move is dropped;
* **drop** — a relocation (or any earlier move of an object that moves
  again) is removed.

Both passes are linear in the number of actions, each candidate costing one
replay of the plan. A rewrite must also keep the search's clearance around
every table placement (the acceptance rules alone would allow objects to
touch).
"""

from __future__ import annotations

import numpy as np
import shapely

from ..formats import Action
from ..patterns import CLEARANCE
from ..scene import TABLE
from .search import valid_plan
from .step import Problem

__all__ = ["polish"]


def _worlds(problem: Problem, actions: list[Action]) -> list:
    """States of the planner's world before each action and after the last."""
    scene = problem.scene
    world = scene.initial
    out = [world]
    for a in actions:
        on = TABLE if a.on is None else scene.index[a.on]
        world = world.moved(scene.index[a.object], np.asarray(a.to, dtype=float), on)
        out.append(world)
    return out


def _clear_enough(problem: Problem, actions: list[Action], clearance: float, start: int = 0, world=None) -> bool:
    """Whether every table placement from ``actions[start]`` on keeps ``clearance`` from every other footprint.

    ``world`` is the state before ``actions[start]`` (the initial state when
    omitted). The acceptance rules only forbid overlap, but the search keeps
    a gap (and keeps clear of stacked objects' overhangs) so that a real
    gripper's placement error does not land an object on its neighbour; a
    rewrite must not take that margin away.
    """
    scene = problem.scene
    world = scene.initial if world is None else world
    for a in actions[start:]:
        i = scene.index[a.object]
        on = TABLE if a.on is None else scene.index[a.on]
        world = world.moved(i, np.asarray(a.to, dtype=float), on)
        if on != TABLE:
            continue
        others = [k for k in range(scene.n) if k != i]
        arr = np.empty(len(others), dtype=object)
        arr[:] = [world.polys[k] for k in others]
        if shapely.dwithin(world.polys[i], arr, clearance * 0.99).any():
            return False
    return True


def _valid(problem: Problem, actions: list[Action], start: int = 0, world=None) -> bool:
    """Whether a rewrite that leaves ``actions[:start]`` unchanged is still a valid plan.

    The clearance replay runs first, from the unchanged prefix's state and
    stopping at the first conflict, so that most rejected rewrites never
    reach the validator's full replay.
    """
    return _clear_enough(problem, actions, CLEARANCE, start, world) and valid_plan(problem, actions)


def _merge(problem: Problem, actions: list[Action]) -> list[Action]:
    worlds = _worlds(problem, actions)
    i = 0
    while i < len(actions):
        a = actions[i]
        later = [j for j in range(i + 1, len(actions)) if actions[j].object == a.object]
        if later:
            j = later[-1]
            last = actions[j]
            trial = list(actions)
            trial[i] = last
            for k in reversed(later):
                del trial[k]
            if _valid(problem, trial, i, worlds[i]):
                actions = trial
                worlds = _worlds(problem, actions)
                continue
        i += 1
    return actions


def _drop(problem: Problem, actions: list[Action]) -> list[Action]:
    moves: dict[int, int] = {}
    for a in actions:
        moves[a.object] = moves.get(a.object, 0) + 1
    worlds = _worlds(problem, actions)
    i = 0
    while i < len(actions):
        a = actions[i]
        if a.purpose != "goal" or moves[a.object] > 1:
            trial = actions[:i] + actions[i + 1 :]
            if _valid(problem, trial, i, worlds[i]):
                moves[a.object] -= 1
                actions = trial
                worlds = _worlds(problem, actions)
                continue
        i += 1
    return actions


def polish(problem: Problem, actions: list[Action] | tuple[Action, ...]) -> list[Action]:
    """A plan no longer than ``actions`` that still meets every goal.

    ``actions`` must be a valid plan for ``problem``; the result is valid too
    (each rewrite is checked by replaying it).
    """
    out = _merge(problem, list(actions))
    return _drop(problem, out)
