"""Pictures of extreme inputs: huge workspaces, long plans, crowded scenes."""

from __future__ import annotations

import numpy as np
import pytest

from lgmcts.formats import parse_goals, parse_plan, parse_scene
from lgmcts.scene import Scene
from lgmcts.viz.fields import MAX_FIELD_CELLS, pose_fields
from lgmcts.viz.figures import FigureOptions, pictured_steps, write_plan_figures

pytestmark = pytest.mark.slow


def test_pictured_steps():
    assert pictured_steps(5, 12) == [1, 2, 3, 4, 5]
    steps = pictured_steps(2000, 12)
    assert len(steps) == 12 and steps[-1] == 2000 and steps == sorted(set(steps)) and steps[0] >= 1
    assert pictured_steps(3, 0) == []


def _huge():
    scene = parse_scene(
        {
            "workspace": {"x": [-1000, 1000], "y": [-1000, 1000]},
            "objects": [
                {"id": 1, "name": "slab", "shape": {"type": "box", "size": [10, 10, 10]}, "pose": [990, 990, 0]},
                {
                    "id": 2,
                    "name": "speck",
                    "shape": {"type": "box", "size": [0.001, 0.001, 0.001]},
                    "pose": [-999, -999, 9999],
                },
            ],
        }
    )
    goals = parse_goals({"goals": [{"pattern": "pose", "objects": [2], "pose": [999, -999, -9999]}]})
    plan = parse_plan({"solved": True, "actions": [{"object": 2, "to": [999, -999, -9999], "purpose": "goal"}]})
    return scene, goals, plan


def test_heatmap_grid_of_a_huge_workspace_is_bounded():
    scene, goals, plan = _huge()
    f = pose_fields(Scene.from_spec(scene), goals, list(plan.actions), 0)
    assert len(f.xs) <= MAX_FIELD_CELLS + 1 and len(f.ys) <= MAX_FIELD_CELLS + 1


def test_huge_workspace_and_tiny_objects_draw(tmp_path):
    scene, goals, plan = _huge()
    paths = write_plan_figures(scene, plan, tmp_path, goals=goals)
    assert all(p.exists() and p.stat().st_size > 0 for p in paths)


def test_long_plan_gets_a_bounded_number_of_pictures(tmp_path):
    rng = np.random.default_rng(0)
    spots = [(-0.9 + 0.1 * i, -0.9 + 0.1 * j) for i in range(19) for j in range(19)]
    objs = [
        {"id": k + 1, "name": "block", "shape": {"type": "box", "size": [0.03, 0.03, 0.03]}, "pose": [*spots[k], 0.0]}
        for k in range(200)
    ]
    scene = parse_scene({"workspace": {"x": [-1, 1], "y": [-1, 1]}, "objects": objs})
    free, where, acts = list(range(200, len(spots))), {k: k for k in range(200)}, []
    for _ in range(300):
        o = int(rng.integers(200))
        s = free.pop(int(rng.integers(len(free))))
        free.append(where[o])
        where[o] = s
        acts.append({"object": o + 1, "to": [*spots[s], 0.0], "purpose": "relocate"})
    plan = parse_plan({"solved": False, "actions": acts})
    paths = write_plan_figures(scene, plan, tmp_path, options=FigureOptions(dpi=40, max_step_pictures=4))
    names = sorted(p.name for p in paths)
    assert len([n for n in names if n.startswith("step_")]) == 4
    assert "step_300.png" in names
