"""The resource budget of docs/limits.md: inputs near the format's bounds stay within it.

Scenes are drawn near the bounds (thousands of objects, polygons and point
clouds of the largest sizes, workspaces up to +-1,000 m, plans as long as
the drawing cap allows, goals over many objects) and given to the library
functions behind the service's ``/check`` and ``/view``. Their peak traced
memory must stay under :data:`BUDGET`, and the answer of ``/view`` must stay
small; anything beyond a cap must be one line of bad input.
"""

from __future__ import annotations

import json
import math
import tracemalloc

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from lgmcts import limits
from lgmcts.errors import InputError
from lgmcts.validate import check
from lgmcts.viz.html import viewer_data

pytestmark = pytest.mark.slow

#: The memory a job may use (docs/limits.md): peak traced allocations.
BUDGET = 1 << 30

#: Largest /view answer (bytes) the caps allow for: MAX_VIEW_DRAWN entries at
#: well under 100 bytes each.
ANSWER = 100 * limits.MAX_VIEW_DRAWN


def _shape(kind: str, k: int, size: float) -> dict:
    if kind == "box":
        return {"type": "box", "size": [size, size * 0.8, size]}
    if kind == "cylinder":
        return {"type": "cylinder", "radius": size / 2, "height": size}
    n = limits.MAX_POLYGON_POINTS
    ring = [[size / 2 * math.cos(2 * math.pi * j / n), size / 2 * math.sin(2 * math.pi * j / n)] for j in range(n)]
    return {"type": "polygon", "points": ring, "height": size}


@st.composite
def near_bounds(draw: st.DrawFn) -> tuple[dict, dict, dict]:
    n = draw(st.sampled_from([1, 2, 50, 1000, limits.MAX_OBJECTS]), label="objects")
    half = draw(st.sampled_from([0.5, 10.0, limits.MAX_COORD]), label="half width")
    kind = draw(st.sampled_from(["box", "cylinder", "polygon"]), label="shape")
    if kind == "polygon":
        n = min(n, 50)  # 1,000 vertices each
    side = math.ceil(math.sqrt(n))
    pitch = 2 * half / (side + 1)
    size = min(limits.MAX_LENGTH, pitch * 0.5)
    objects = []
    for k in range(n):
        x, y = -half + pitch * (1 + k % side), -half + pitch * (1 + k // side)
        objects.append({"id": k + 1, "name": "thing", "shape": _shape(kind, k, size),
                        "pose": [x, y, draw(st.sampled_from([0.0, limits.MAX_ANGLE]))] if k == 0 else [x, y, 0.0]})
    ids = list(range(1, n + 1))
    goals = []
    if n >= 2:
        goals.append({"pattern": "line", "objects": ids})
        goals.append({"pattern": "left", "objects": ids[1:], "anchor": 1})
    goals.append({"pattern": "pose", "objects": [1], "pose": [half * 0.5, -half * 0.5, 0.0]})
    members = sum(len(g["objects"]) + 1 for g in goals)
    longest = min(limits.MAX_ACTIONS, limits.MAX_VIEW_CELLS // (n + members) - 1, 1_500)
    m = draw(st.integers(0, max(0, longest)), label="actions")
    actions = []
    for j in range(m):
        o = draw(st.sampled_from(ids)) if j < 50 else ids[j % n]
        actions.append({"object": o, "to": [draw(st.floats(-half, half)), draw(st.floats(-half, half)), 0.0],
                        "purpose": "relocate"})
    scene = {"workspace": {"x": [-half, half], "y": [-half, half]}, "objects": objects}
    return scene, {"goals": goals}, {"solved": True, "actions": actions}


def _peak(fn, *args, **kwargs):
    tracemalloc.start()
    try:
        try:
            out = fn(*args, **kwargs)
        except InputError as exc:
            out = exc
        return out, tracemalloc.get_traced_memory()[1]
    finally:
        tracemalloc.stop()


@settings(max_examples=5, deadline=None, suppress_health_check=[HealthCheck.too_slow, HealthCheck.data_too_large])
@given(near_bounds())
def test_check_and_view_stay_within_the_memory_budget(case):
    scene, goals, plan = case
    _verdict, peak = _peak(check, scene, goals, plan)
    assert peak < BUDGET, f"/check peaked at {peak / 2**20:.0f} MiB"
    data, peak = _peak(viewer_data, scene, plan, goals=goals)
    assert peak < BUDGET, f"/view peaked at {peak / 2**20:.0f} MiB"
    if isinstance(data, InputError):
        assert "\n" not in str(data) and "too large to draw" in str(data)
    else:
        assert len(json.dumps(data)) < ANSWER
        assert len(data["frames"]) == len(plan["actions"]) + 1


def test_a_drawing_past_the_cap_is_refused_before_it_costs_memory():
    n = 2_000
    objects = [{"id": k + 1, "name": "b", "shape": {"type": "box", "size": [0.01, 0.01, 0.01]},
                "pose": [-900 + 0.1 * (k % 100), -900 + 0.1 * (k // 100), 0.0]} for k in range(n)]
    scene = {"workspace": {"x": [-1000, 1000], "y": [-1000, 1000]}, "objects": objects}
    # One relation goal over every object, redrawn at each move: the cap on what the frames list stops it.
    goals = {"goals": [{"pattern": "left", "objects": list(range(2, n + 1)), "anchor": 1}]}
    plan = {"solved": False, "actions": [{"object": 2 + k % 2, "to": [0.001 * k, 0.0, 0.0]} for k in range(1_000)]}
    out, peak = _peak(viewer_data, scene, plan, goals=goals)
    assert isinstance(out, InputError) and "too large to draw" in str(out)
    assert peak < 100 * 2**20
