"""The search loops on a toy domain: they take their domain as a parameter.

The toy is a walk on a small directed graph from node 0 to node 4; an
action is the node stepped to. Its shortest plan is known (0 -> 1 -> 4), its
other plans are longer (0 -> 2 -> 3 -> 4, 0 -> 1 -> 3 -> 4) and node 5 is a
dead end, so the tests can tell whether the loops find the optimum, respect
their budget, honour the acceptance rule and repeat themselves for a seed.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field

import numpy as np
import pytest

from lgmcts.planner.base import Domain, Rollout, Transition
from lgmcts.planner.search import SearchOptions, greedy, mcts

EDGES: dict[int, tuple[int, ...]] = {0: (1, 2), 1: (3, 4), 2: (3, 5), 3: (4,), 4: (), 5: ()}
GOAL = 4
SHORTEST = [1, 4]


@dataclass
class Walk:
    """The graph walk as a :class:`~lgmcts.planner.base.Domain`; counts the steps it is asked for."""

    edges: dict[int, tuple[int, ...]] = field(default_factory=lambda: dict(EDGES))
    only: list[int] | None = None  # accept only this plan (``None``: every plan that reaches the goal)
    start: int = 0
    steps: int = 0
    rejected: int = 0

    @property
    def depth_limit(self) -> int:
        return len(self.edges) + 2

    def root(self) -> int:
        return self.start

    def choices(self, state: int) -> Sequence[int]:
        return self.edges[state]

    def reward(self, state: int) -> float:
        return 1.0 if state == GOAL else 0.0

    def terminal(self, state: int) -> bool:
        return state == GOAL

    def stay(self, state: int, choice: int, rng: np.random.Generator) -> Transition[int, int] | None:
        return None

    def step(self, state: int, choice: int, rng: np.random.Generator) -> Transition[int, int] | None:
        self.steps += 1
        return Transition(choice, choice)

    def default_step(self, state: int, choices: Sequence[int],
                     rng: np.random.Generator) -> tuple[int, Transition[int, int] | None]:
        self.steps += 1
        c = int(choices[int(rng.integers(len(choices)))])
        return c, Transition(c, c)

    def rollout(self, state: int, rng: np.random.Generator, depth: int) -> Rollout[int, int]:
        actions: list[int] = []
        trace: list[int] = []
        for _ in range(depth):
            if state == GOAL or not self.edges[state]:
                break
            c = int(self.edges[state][int(rng.integers(len(self.edges[state])))])
            actions.append(c)
            trace.append(c)
            state = c
        done = state == GOAL
        return Rollout(1.0 if done else 0.0, actions if done else None, len(actions), trace)

    def accept(self, actions: list[int], trace: list[int] | None) -> list[int] | None:
        ok = self.only is None or actions == self.only
        if not ok:
            self.rejected += 1
        return list(actions) if ok else None

    def describe(self, actions: Sequence[int]) -> str:
        return f"{len(actions)} moves"


def _is_walk(actions: Sequence[int]) -> bool:
    node = 0
    for a in actions:
        if a not in EDGES[node]:
            return False
        node = a
    return node == GOAL


def test_the_toy_meets_the_protocol():
    d: Domain[int, int] = Walk()  # checked by mypy; at run time the loops only call its methods
    assert d.choices(d.root()) == (1, 2)


@pytest.mark.parametrize("rollout", [True, False])
@pytest.mark.parametrize("seed", range(5))
def test_mcts_finds_a_walk_to_the_goal(seed, rollout):
    res = mcts(Walk(), np.random.default_rng(seed), SearchOptions(max_iter=200, rollout=rollout))
    assert res.solved and _is_walk(res.actions), res


@pytest.mark.parametrize("seed", range(5))
def test_anytime_mcts_finds_the_shortest_walk(seed):
    res = mcts(Walk(), np.random.default_rng(seed), SearchOptions(max_iter=300, anytime=True))
    assert res.solved and list(res.actions) == SHORTEST


@pytest.mark.parametrize("method", [mcts, greedy])
@pytest.mark.parametrize("seed", range(3))
def test_the_acceptance_rule_decides_what_is_kept(method, seed):
    walk = Walk(only=[2, 3, 4])
    res = method(walk, np.random.default_rng(seed), SearchOptions(max_iter=2000))
    assert res.solved and list(res.actions) == [2, 3, 4]


@pytest.mark.parametrize("method", [mcts, greedy])
@pytest.mark.parametrize("budget", [1, 7, 50])
def test_an_unreachable_goal_ends_with_the_budget(method, budget):
    walk = Walk(edges={0: (1, 2), 1: (3,), 2: (3, 5), 3: (5,), 4: (), 5: ()})
    res = method(walk, np.random.default_rng(0), SearchOptions(max_iter=budget))
    assert not res.solved and res.reason == "iteration budget exhausted"
    assert 1 <= res.iterations <= budget
    # Each iteration asks the domain for one step at most (rollouts aside).
    assert walk.steps <= budget


@pytest.mark.parametrize("method", [mcts, greedy])
def test_the_same_seed_gives_the_same_search(method):
    def run(seed: int):
        walk = Walk(only=SHORTEST)
        res = method(walk, np.random.default_rng(seed), SearchOptions(max_iter=500))
        return res.solved, res.actions, res.iterations, res.nodes, walk.steps, walk.rejected

    assert run(3) == run(3)
    assert run(3)[0]


def test_greedy_counts_its_steps_against_the_budget():
    walk = Walk(only=[9])  # no plan is ever accepted
    res = greedy(walk, np.random.default_rng(0), SearchOptions(max_iter=40))
    assert not res.solved and res.iterations == 40 and walk.steps == 40
    assert walk.rejected >= 1


# A domain whose steps add nothing must still end with the budget: the
# loops count every pass (tree search) and every rollout without a step
# (greedy), so these ran for ever before.


@pytest.mark.timeout(60)
@pytest.mark.parametrize("method", [mcts, greedy])
@pytest.mark.parametrize("budget", [1, 5, 300])
def test_a_root_with_no_choice_ends_with_the_budget(method, budget):
    walk = Walk(edges={0: (), 1: (), 2: (), 3: (), 4: (), 5: ()})
    res = method(walk, np.random.default_rng(0), SearchOptions(max_iter=budget))
    assert not res.solved and res.reason == "iteration budget exhausted"
    assert res.iterations == budget and walk.steps == 0


@pytest.mark.timeout(60)
@pytest.mark.parametrize("method", [mcts, greedy])
def test_a_rejected_root_ends_with_the_budget(method):
    walk = Walk(start=GOAL, only=[9])  # the root reaches the goal, but no plan is accepted
    res = method(walk, np.random.default_rng(0), SearchOptions(max_iter=5))
    assert not res.solved and res.iterations == 5 and walk.rejected >= 1


@pytest.mark.timeout(60)
def test_a_tree_pruned_at_the_root_ends_with_the_budget():
    res = mcts(Walk(), np.random.default_rng(0), SearchOptions(max_iter=5, max_depth=0))
    assert not res.solved and res.iterations == 5
