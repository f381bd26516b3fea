"""Polishing as the search's accept step."""

from __future__ import annotations

import numpy as np
import pytest

from lgmcts import check, plan
from lgmcts.casegen import labbe_case, random_case
from lgmcts.planner import SearchOptions
from lgmcts.planner import polish as pol
from lgmcts.planner.domain import Rearrangement
from lgmcts.planner.problem import Problem
from lgmcts.planner.search import mcts
from lgmcts.scene import Scene


def _raw(case, seed):
    """A problem and the plan the search finds for it, unpolished."""
    problem = Problem.build(Scene.from_spec(case.scene), case.goals)
    opts = SearchOptions(polish=False)
    res = mcts(Rearrangement(problem, opts), np.random.default_rng(seed), opts)
    assert res.solved
    return problem, list(res.actions)


@pytest.mark.parametrize("case,seed,shortens", [(labbe_case(25, 25014), 14, True), (labbe_case(25, 25002), 2, False),
                                                (labbe_case(20, 5), 0, False), (random_case(11), 0, False),
                                                (random_case(40), 0, False)],
                         ids=["labbe25a", "labbe25b", "labbe20", "random11", "random40"])
def test_polish_stops_early_without_changing_the_result(case, seed, shortens, monkeypatch):
    problem, actions = _raw(case, seed)
    fast = pol.polished(problem, actions)
    # Never rejoining the original plan means replaying every rewrite to the end.
    monkeypatch.setattr(pol, "_same", lambda a, b: False)
    slow = pol.polished(problem, actions)
    assert fast == slow
    assert len(fast) <= len(actions)
    if shortens:
        assert len(fast) < len(actions)  # rewrites were found, so the early stop was exercised
    assert check(case.scene, case.goals, {"solved": True, "actions": [a.model_dump() for a in fast]}).valid


def test_polished_plans_are_shorter_and_reported():
    c = labbe_case(25, 25014)
    p = plan(c.scene, c.goals, seed=14)
    raw = plan(c.scene, c.goals, seed=14, options=SearchOptions(polish=False))
    assert p.solved and raw.solved and check(c.scene, c.goals, p).valid
    assert len(p.actions) < len(raw.actions)
    assert p.stats["actions_before_polish"] == len(raw.actions)


def test_accept_rejects_a_plan_that_misses_a_goal():
    c = labbe_case(6, 1)
    problem, actions = _raw(c, 0)
    assert pol.polished(problem, actions) is not None
    assert pol.polished(problem, actions[:-1]) is None


def test_replay_keeps_the_clearance_except_for_fixed_targets():
    # A pose goal's fixed target 1.1 mm from a box may be reached in contact;
    # a move for a sampled goal (here a relation) may not come that close.
    from lgmcts.formats import Action, parse_goals, parse_scene

    def box(i, x, y):
        return {"id": i, "name": "block", "color": "red", "shape": {"type": "box", "size": [0.04, 0.04, 0.04]},
                "pose": [x, y, 0.0], "on": None}

    sc = Scene.from_spec(parse_scene({"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]},
                                      "objects": [box(1, 0.2, 0.2), box(2, -0.2, 0.0), box(3, 0.0, 0.0)]}))
    gs = parse_goals({"goals": [{"pattern": "pose", "objects": [1], "pose": [0.0411, 0.0, 0.0]},
                                {"pattern": "left", "objects": [2], "anchor": 3}]})
    problem = Problem.build(sc, gs)
    ref = np.array(sc.initial.poses)
    to_target = Action(object=1, to=(0.0411, 0.0, 0.0), purpose="goal")
    too_close = Action(object=2, to=(-0.0411, 0.0, 0.0), purpose="goal")
    assert pol._replay(problem, [to_target], 0, sc.initial, ref) is not None
    assert pol._replay(problem, [to_target, too_close], 0, sc.initial, ref) is None
