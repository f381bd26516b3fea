"""Plans for goals with a region, size and facing hold in physics."""

from __future__ import annotations

import pytest

import lgmcts
from lgmcts.sim import execute_plan

pytestmark = pytest.mark.slow


@pytest.mark.parametrize("goals", [
    {"goals": [
        {"pattern": "circle", "objects": [1, 2, 3, 4], "region": "top right", "size": "small", "facing": "south"},
        {"pattern": "line", "objects": [5, 6, 7], "region": "bottom", "facing": "north"},
    ]},
    {"goals": [
        {"pattern": "tower", "objects": [2, 3, 4], "region": "bottom right", "facing": "west"},
        {"pattern": "rectangle", "objects": [1, 5, 7, 8], "region": "left", "size": "medium", "facing": "east"},
    ]},
])
def test_plans_with_params_succeed_in_physics(example_scene, goals):
    plan = lgmcts.plan(example_scene, goals, seed=1, max_iter=3000)
    assert plan.solved and lgmcts.check(example_scene, goals, plan).valid
    result = execute_plan(example_scene, plan, goals)
    assert result.success, result.reasons
    assert all(result.goals)
