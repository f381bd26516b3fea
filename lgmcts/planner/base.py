"""What the search loops search: a :class:`Domain`, and the values it hands back.

The loops in :mod:`.search` know nothing of scenes or patterns; as mctx's
``search`` takes its ``recurrent_fn``, they take a domain and ask it for the
root state, the choices open at a state, one step for a choice, a rollout,
rewards and whether a found plan is accepted. :class:`lgmcts.planner.domain.Rearrangement`
is the tabletop domain; the tests search a toy one with the same loops.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Generic, Protocol, TypeVar

import numpy as np

__all__ = ["Domain", "Rollout", "Transition"]

S = TypeVar("S")
A = TypeVar("A")


@dataclass(frozen=True)
class Transition(Generic[S, A]):
    """Result of one step: the action taken (``None`` when the step commits
    a choice without acting, an object left where it stands) and the new state."""

    action: A | None
    state: S


@dataclass(frozen=True)
class Rollout(Generic[S, A]):
    """Result of a default-policy rollout from a state.

    ``value`` lies in [0, 1] (1 when every goal is reached); ``actions`` are
    the rollout's actions when it reached every goal, else ``None``;
    ``steps`` counts the steps it took (actions and commits alike) and
    ``trace`` holds the state after each of its actions.
    """

    value: float
    actions: list[A] | None
    steps: int
    trace: list[S]


class Domain(Protocol[S, A]):
    """A search problem as the loops in :mod:`.search` see it.

    States are immutable: a step returns a new one. Randomness comes only
    from the ``rng`` passed in, so a seed fixes the search.
    """

    @property
    def depth_limit(self) -> int:
        """Deepest node the tree expands when the options give no depth."""
        ...

    def root(self) -> S:
        """The state the search starts from."""
        ...

    def choices(self, state: S) -> Sequence[int]:
        """The choices (objects) that a step may take at ``state``, in a fixed order."""
        ...

    def reward(self, state: S) -> float:
        """Progress of ``state`` towards the goals, in [0, 1]."""
        ...

    def terminal(self, state: S) -> bool:
        """Whether ``state`` reaches every goal."""
        ...

    def stay(self, state: S, choice: int, rng: np.random.Generator) -> Transition[S, A] | None:
        """Commit ``choice`` without an action, when that already meets its goals; else ``None``."""
        ...

    def step(self, state: S, choice: int, rng: np.random.Generator) -> Transition[S, A] | None:
        """One sampled step for ``choice`` (an expansion of the tree), or ``None`` when none was found."""
        ...

    def default_step(self, state: S, choices: Sequence[int],
                     rng: np.random.Generator) -> tuple[int, Transition[S, A] | None]:
        """The default policy's step among ``choices``: the choice it took and its transition."""
        ...

    def rollout(self, state: S, rng: np.random.Generator, depth: int) -> Rollout[S, A]:
        """Default-policy steps chained from ``state``, at most ``depth`` of them."""
        ...

    def accept(self, actions: list[A], trace: list[S] | None) -> list[A] | None:
        """The plan to keep for ``actions``, which reach every goal in the
        domain's model (themselves, or a rewrite), or ``None`` to reject them.
        ``trace`` holds the states along them (the root's, then the one after
        each action), or ``None``."""
        ...

    def describe(self, actions: Sequence[A]) -> str:
        """A few words on a plan, for the search log."""
        ...
