"""Goals refused by the planner's pre-check are one-line 422 answers, at once."""

from __future__ import annotations

import pytest

pytestmark = pytest.mark.slow


def _box(i: int, x: float, y: float) -> dict:
    return {"id": i, "name": "block", "color": "red", "shape": {"type": "box", "size": [0.05, 0.05, 0.04]},
            "pose": [x, y, 0.0], "on": None}


@pytest.mark.parametrize("method", ["lgmcts", "greedy", "pmcts"])
def test_a_tower_that_contradicts_a_relation_is_422(client, method):
    scene = {"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}, "objects": [_box(1, -0.1, 0.0), _box(2, 0.1, 0.0)]}
    goals = {"goals": [{"pattern": "tower", "objects": [1, 2]}, {"pattern": "right", "objects": [1], "anchor": 2}]}
    r = client.post("/plan", json={"scene": scene, "goals": goals, "options": {"method": method, "max_iter": 5}},
                    timeout=20)
    assert r.status_code == 422, r.text
    detail = r.json()["detail"]
    assert "order objects in a cycle" in detail and "\n" not in detail
