"""The HTML page as text: self-contained, with the data the viewer needs."""

from __future__ import annotations

import json
import re
from pathlib import Path

import numpy as np

from lgmcts.formats import load_plan, load_scene
from lgmcts.scene import Scene, replay
from lgmcts.viz import render_html, viewer_data, viewer_js

DATA = Path(__file__).parent / "data"
SCENE = DATA / "cluttered_scene.json"
PLAN = DATA / "cluttered_plan.json"


def expand(frames: list[dict]) -> list[dict]:
    """Full states from the viewer's delta frames, as viewer.js builds them."""
    out: list[dict] = []
    poses: dict = {}
    on: dict = {}
    goals: dict = {}
    for f in frames:
        poses.update(f["poses"])
        on.update(f["on"])
        goals.update({g["index"]: g for g in f["goals"]})
        out.append({"poses": dict(poses), "on": dict(on), "goals": [goals[k] for k in sorted(goals)]})
    return out


def test_page_is_self_contained():
    page = render_html(SCENE, PLAN)
    assert page.startswith("<!DOCTYPE html>")
    assert viewer_js().strip()[:40] in page
    assert not re.search(r"<(link|img|iframe)\b", page, re.I)
    assert not re.search(r"<script[^>]+src=", page, re.I)
    # The only URL is the SVG namespace, which is a name and never fetched.
    urls = set(re.findall(r"https?://[^\s\"')]+", page))
    assert urls <= {"http://www.w3.org/2000/svg"}


def test_viewer_data_contract():
    data = viewer_data(SCENE, PLAN, instruction="hi")
    plan = json.loads(PLAN.read_text())
    sc = Scene.from_spec(load_scene(SCENE))
    assert set(data) == {"scene", "plan", "instruction", "footprints", "paints", "frames", "goal_text"}
    assert data["instruction"] == "hi"
    assert len(data["frames"]) == len(plan["actions"]) + 1
    assert [g["met"] for g in data["frames"][-1]["goals"]] == [True, True]
    assert data["frames"][0]["goals"][1]["met"] is False
    for k, i in enumerate(sc.ids):
        assert np.allclose(data["footprints"][str(i)], sc.local[k], atol=1e-6)
    assert data["paints"]["7"]["texture"] == "dots"
    # The frames, applied in turn, give each replayed state, so the script replays nothing.
    states = replay(sc, load_plan(PLAN).actions)
    for f, st in zip(expand(data["frames"]), states):
        for k, i in enumerate(sc.ids):
            assert np.allclose(f["poses"][str(i)], st.poses[k], atol=1e-6)
            assert f["on"][str(i)] == (None if st.on[k] < 0 else sc.ids[st.on[k]])
    assert len(data["goal_text"]) == len(load_plan(PLAN).goals.goals)
    json.dumps(data, allow_nan=False)


def test_instruction_defaults_to_the_plans_own():
    plan = json.loads(PLAN.read_text())
    plan["instruction"] = "stored command"
    assert viewer_data(SCENE, plan)["instruction"] == "stored command"
    assert "stored command" in render_html(SCENE, plan)


def test_viz_imports_no_plotting_library_until_drawing():
    import subprocess
    import sys

    code = (
        "import sys, lgmcts, lgmcts.viz, lgmcts.cli_util\n"
        "from lgmcts.viz import render_html\n"
        f"render_html({str(SCENE)!r}, {str(PLAN)!r})\n"
        "assert 'matplotlib' not in sys.modules, 'matplotlib imported eagerly'\n"
        "import lgmcts.planner, lgmcts.validate\n"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr


def test_core_does_not_import_viz():
    import subprocess
    import sys

    code = (
        "import sys, lgmcts\n"
        f"s = lgmcts.load_scene({str(SCENE)!r})\n"
        "lgmcts.plan(s, lgmcts.load_plan(" + repr(str(PLAN)) + ").goals, seed=0)\n"
        "bad = [m for m in sys.modules if m.startswith('lgmcts.viz') or m == 'matplotlib']\n"
        "assert not bad, bad\n"
    )
    r = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=120)
    assert r.returncode == 0, r.stderr


def test_plans_carry_fits_and_viewers_draw_from_them():
    """A plan carries each goal's fitted parameters for its final state; the
    viewer draws the final state from them instead of fitting again, and a
    plan without them (older files) is drawn by fitting."""
    import lgmcts

    root = Path(__file__).resolve().parents[2]
    scene, goals = root / "examples" / "tabletop.json", root / "examples" / "goals.json"
    p = lgmcts.plan(scene, goals, seed=0)
    circle = p.fits[[g.pattern for g in p.goals.goals].index("circle")]
    assert set(circle) == {"centre", "radius", "start_angle", "count"} and circle["count"] == 4
    assert all(f is None for f, g in zip(p.fits, p.goals.goals) if g.pattern in ("behind", "tower", "pose"))
    plan = json.loads(lgmcts.save_json(p))
    k = [g["pattern"] for g in plan["goals"]["goals"]].index("circle")
    drawn = viewer_data(scene, plan)["frames"][-1]["goals"][k]
    assert np.allclose(drawn["centre"], circle["centre"]) and np.isclose(drawn["radius"], circle["radius"])
    plan["fits"][k] = {**circle, "radius": 0.5}  # the viewer believes the plan
    assert viewer_data(scene, plan)["frames"][-1]["goals"][k]["radius"] == 0.5
    del plan["fits"]
    refit = viewer_data(scene, plan)["frames"][-1]["goals"][k]
    assert np.isclose(refit["radius"], circle["radius"])


# ---------------------------------------------------------------- delta frames

from hypothesis import given, settings  # noqa: E402
from hypothesis import strategies as hst  # noqa: E402

from lgmcts.errors import InputError  # noqa: E402
from lgmcts.formats import parse_goals, parse_plan, parse_scene  # noqa: E402
from lgmcts.limits import MAX_VIEW_CELLS  # noqa: E402
from lgmcts.viz.model import goal_shapes  # noqa: E402


def _grid_scene(n: int) -> dict:
    objs = [{"id": k + 1, "name": "block", "shape": {"type": "box", "size": [0.04, 0.04, 0.04]},
             "pose": [-0.4 + 0.1 * (k % 8), -0.3 + 0.1 * (k // 8), 0.0]} for k in range(n)]
    return {"workspace": {"x": [-0.5, 0.5], "y": [-0.4, 0.4]}, "objects": objs}


@settings(max_examples=25, deadline=None)
@given(hst.data())
def test_delta_frames_replay_to_every_state_and_goal(data):
    n = data.draw(hst.integers(5, 8), label="objects")
    ids = list(range(1, n + 1))
    scene = parse_scene(_grid_scene(n))
    goals = parse_goals({"goals": [
        {"pattern": "line", "objects": ids[:3]},
        {"pattern": "tower", "objects": [ids[3], ids[4]]},
        {"pattern": "left", "objects": [ids[1]], "anchor": ids[2]},
    ]})
    acts = []
    for _ in range(data.draw(hst.integers(0, 8), label="actions")):
        o = data.draw(hst.sampled_from(ids))
        on = data.draw(hst.one_of(hst.none(), hst.sampled_from([i for i in ids if i != o])))
        x = data.draw(hst.floats(-0.45, 0.45))
        y = data.draw(hst.floats(-0.35, 0.35))
        acts.append({"object": o, "to": [x, y, 0.0], "on": on})
    plan = parse_plan({"solved": False, "actions": acts})
    out = viewer_data(scene, plan, goals=goals)
    sc = Scene.from_spec(scene)
    states = replay(sc, plan.actions)
    full = expand(out["frames"])
    assert len(full) == len(states)
    for f, state in zip(full, states):
        assert f["poses"] == {str(i): [float(v) for v in state.poses[k]] for k, i in enumerate(sc.ids)}
        want = [s.to_json() for s in goal_shapes(sc, goals, state)]
        assert f["goals"] == json.loads(json.dumps(want))
    # A delta lists only what moved: one object per action here, at mohst.
    assert all(len(f["poses"]) <= 1 for f in out["frames"][1:])


def test_viewer_data_of_a_huge_plan_is_one_line_not_gigabytes():
    n = MAX_VIEW_CELLS // 100_000 + 1
    scene = {"workspace": {"x": [-10, 10], "y": [-10, 10]}, "objects": [
        {"id": k + 1, "name": "b", "shape": {"type": "box", "size": [0.04, 0.04, 0.04]},
         "pose": [-9 + 0.1 * (k % 100), -9 + 0.1 * (k // 100), 0.0]} for k in range(n)]}
    acts = [{"object": 1, "to": [5.0, 5.0 + 0.1 * (k % 2), 0.0]} for k in range(100_000)]
    try:
        viewer_data(scene, {"solved": False, "actions": acts})
    except InputError as exc:
        assert "too large to draw" in str(exc) and "\n" not in str(exc)
    else:  # pragma: no cover - the cap must refuse it
        raise AssertionError("a plan over the cap was drawn")
