"""Tabletop rearrangement as a search :class:`~lgmcts.planner.base.Domain`.

:class:`Rearrangement` binds a :class:`~lgmcts.planner.problem.Problem`, the
search options its steps use and an acceptance rule, and answers the search
loops' questions with the simulation step (:mod:`.step`) and the default
rollout policy (:mod:`.rollout`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np

from ..confinement import confined
from ..formats import Action, PlanSpec
from ..scene import State
from ..validate import check
from .base import Rollout, Transition
from .problem import Problem, SearchState
from .rollout import default_step, rollout
from .search import SearchOptions
from .step import attempt, stay

__all__ = ["Accept", "Rearrangement", "valid_plan", "validated"]


def valid_plan(problem: Problem, actions: list[Action]) -> bool:
    """Whether ``actions`` meet the acceptance rules for ``problem`` (a replay by the validator)."""
    plan = PlanSpec(solved=True, actions=actions, goals=problem.spec)
    return check(problem.scene, problem.spec, plan).valid


#: What a search does with a plan that reaches every goal in its own model:
#: returns the plan to keep (the same, or a rewrite of it) once the validator
#: accepts it, or ``None`` to reject it and search on. The third argument
#: holds the world states along the plan (the initial one, then the one after
#: each action), or ``None``.
Accept = Callable[[Problem, list[Action], "list[State] | None"], "list[Action] | None"]


def validated(problem: Problem, actions: list[Action], worlds: list[State] | None = None) -> list[Action] | None:
    """The default :data:`Accept`: ``actions`` themselves when the validator accepts them."""
    return list(actions) if valid_plan(problem, actions) else None


class Rearrangement:
    """The tabletop domain: place every goal object, moving what is in the way.

    Parameters
    ----------
    problem : the problem searched (its goals drive the steps and rewards).
    opts : search options; the steps use ``opts.step`` and ``opts.direct_tries``.
    accept : the acceptance rule applied to plans that reach every goal.
    judge : the problem whose goals ``accept`` checks plans against; the
        searched one when ``None``. The Pose+MCTS baseline searches for
        fixed poses and judges by the original goals.
    """

    def __init__(self, problem: Problem, opts: SearchOptions, *, accept: Accept = validated,
                 judge: Problem | None = None) -> None:
        self.problem = problem
        self.opts = opts
        self._accept = accept
        self.judge = problem if judge is None else judge

    @property
    def depth_limit(self) -> int:
        return 3 * self.problem.scene.n + 8

    def impossible(self) -> str | None:
        """Why no plan can meet the judged goals (see :mod:`lgmcts.confinement`), or ``None`` when not proved.

        Asked by the search loops once (``SearchOptions.proof_after``). The
        proof covers plans that keep the objects on the table, the only
        plans this domain makes for pose goals.
        """
        return confined(self.judge.scene, self.judge.spec)

    def root(self) -> SearchState:
        return self.problem.root()

    def choices(self, state: SearchState) -> list[int]:
        return state.ready(self.problem)

    def reward(self, state: SearchState) -> float:
        return state.reward(self.problem)

    def terminal(self, state: SearchState) -> bool:
        return state.done(self.problem)

    def stay(self, state: SearchState, choice: int,
             rng: np.random.Generator) -> Transition[SearchState, Action] | None:
        return stay(self.problem, state, choice, rng)

    def step(self, state: SearchState, choice: int,
             rng: np.random.Generator) -> Transition[SearchState, Action] | None:
        return attempt(self.problem, state, choice, rng, self.opts.step)

    def default_step(self, state: SearchState, choices: Sequence[int],
                     rng: np.random.Generator) -> tuple[int, Transition[SearchState, Action] | None]:
        return default_step(self.problem, state, list(choices), rng, self.opts)

    def rollout(self, state: SearchState, rng: np.random.Generator, depth: int) -> Rollout[SearchState, Action]:
        return rollout(self.problem, state, rng, self.opts, depth)

    def accept(self, actions: list[Action], trace: list[SearchState] | None) -> list[Action] | None:
        worlds = None if trace is None else [s.world for s in trace]
        return self._accept(self.judge, actions, worlds)

    def describe(self, actions: Sequence[Action]) -> str:
        moved = sum(a.purpose == "relocate" for a in actions)
        unstacked = sum(a.purpose == "unstack" for a in actions)
        return f"{len(actions)} actions ({moved} relocations, {unstacked} unstacks)"
