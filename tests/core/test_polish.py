"""Polishing as the search's accept step."""

from __future__ import annotations

import numpy as np
import pytest

from lgmcts import check, plan
from lgmcts.casegen import labbe_case, random_case
from lgmcts.planner import SearchOptions
from lgmcts.planner import polish as pol
from lgmcts.planner.search import mcts
from lgmcts.planner.step import Problem
from lgmcts.scene import Scene


def _raw(case, seed):
    """A problem and the plan the search finds for it, unpolished."""
    problem = Problem.build(Scene.from_spec(case.scene), case.goals)
    res = mcts(problem, np.random.default_rng(seed), SearchOptions(polish=False))
    assert res.solved
    return problem, list(res.actions)


@pytest.mark.parametrize("case,seed", [(labbe_case(25, 25017), 17), (labbe_case(25, 25002), 2), (labbe_case(20, 5), 0),
                                       (random_case(11), 0), (random_case(40), 0)],
                         ids=["labbe25a", "labbe25b", "labbe20", "random11", "random40"])
def test_polish_stops_early_without_changing_the_result(case, seed, monkeypatch):
    problem, actions = _raw(case, seed)
    fast = pol.polished(problem, actions)
    # Never rejoining the original plan means replaying every rewrite to the end.
    monkeypatch.setattr(pol, "_same", lambda a, b: False)
    slow = pol.polished(problem, actions)
    assert fast == slow
    assert len(fast) <= len(actions)
    if case.kind == "labbe" and seed:
        assert len(fast) < len(actions)  # rewrites were found, so the early stop was exercised
    assert check(case.scene, case.goals, {"solved": True, "actions": [a.model_dump() for a in fast]}).valid


def test_polished_plans_are_shorter_and_reported():
    c = labbe_case(25, 25017)
    p = plan(c.scene, c.goals, seed=17)
    raw = plan(c.scene, c.goals, seed=17, options=SearchOptions(polish=False))
    assert p.solved and raw.solved and check(c.scene, c.goals, p).valid
    assert len(p.actions) < len(raw.actions)
    assert p.stats["actions_before_polish"] == len(raw.actions)


def test_accept_rejects_a_plan_that_misses_a_goal():
    c = labbe_case(6, 1)
    problem, actions = _raw(c, 0)
    assert pol.polished(problem, actions) is not None
    assert pol.polished(problem, actions[:-1]) is None
