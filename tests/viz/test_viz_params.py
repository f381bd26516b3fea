"""Pictures and viewer data of goals with a region, size and facing."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from lgmcts import plan
from lgmcts.formats import load_scene, parse_goals
from lgmcts.params import region_box
from lgmcts.scene import Scene
from lgmcts.viz import FigureOptions, render_html, viewer_data, write_plan_figures
from lgmcts.viz.model import describe_goal, goal_shapes, replay

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "tabletop.json"
GOALS = {"goals": [
    {"pattern": "circle", "objects": [1, 2, 3, 4], "region": "top right", "size": "small", "facing": "south"},
    {"pattern": "line", "objects": [5, 6, 7], "region": "bottom", "facing": "north"},
]}


@pytest.fixture(scope="module")
def solved():
    p = plan(EXAMPLE, GOALS, seed=1, max_iter=3000)
    assert p.solved
    return p


def test_goal_shapes_carry_region_and_heading(solved):
    sc = Scene.from_spec(load_scene(EXAMPLE))
    final = replay(sc, list(solved.actions))[-1]
    shapes = goal_shapes(sc, parse_goals(GOALS), final)
    assert all(s.met for s in shapes)
    assert np.allclose(shapes[0].geometry["region"], region_box("top right", sc.bounds))
    assert shapes[0].geometry["heading"] == pytest.approx(-math.pi / 2)
    assert np.allclose(shapes[1].geometry["region"], region_box("bottom", sc.bounds))
    data = viewer_data(EXAMPLE, solved)
    last = data["frames"][-1]["goals"]
    assert last[0]["region"] == pytest.approx(list(region_box("top right", sc.bounds)), abs=1e-6)
    assert last[1]["heading"] == pytest.approx(math.pi / 2)
    json.dumps(data, allow_nan=False)
    assert "lgv-region" in render_html(EXAMPLE, solved)


def test_describe_goal_names_the_params():
    g = parse_goals(GOALS).goals
    assert describe_goal(g[0]) == "small circle of 1, 2, 3, 4 in top right, facing south"
    assert describe_goal(g[1]) == "line of 5, 6, 7 in bottom, facing north"
    plain = parse_goals([{"pattern": "line", "objects": [1, 2]}]).goals[0]
    assert describe_goal(plain) == "line of 1, 2"


@pytest.mark.slow
def test_pictures_of_a_plan_with_params(solved, tmp_path):
    paths = write_plan_figures(EXAMPLE, solved, tmp_path, options=FigureOptions(dpi=50, gif_width_px=320))
    assert (tmp_path / "final.png").exists() and all(p.exists() for p in paths)


@pytest.mark.slow
def test_viewer_draws_regions_and_headings(solved, tmp_path):
    import shutil

    sync_api = pytest.importorskip("playwright.sync_api", reason="the playwright package is not installed")
    chromium = shutil.which("chromium") or ("/usr/bin/chromium" if Path("/usr/bin/chromium").exists() else None)
    if chromium is None:
        pytest.skip("chromium is not installed (run scripts/system-deps.sh)")
    f = tmp_path / "plan.html"
    f.write_text(render_html(EXAMPLE, solved), encoding="utf-8")
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=chromium, args=["--headless", "--no-sandbox", "--disable-gpu"])
        page = b.new_page()
        errors: list[str] = []
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.goto(f.as_uri())
        page.wait_for_selector(".lgv-obj")
        assert page.locator(".lgv-region").count() == 2
        assert page.locator(".lgv-heading").count() == 2
        b.close()
    assert not errors


@pytest.mark.slow
def test_viewer_draws_the_regions_computed_in_python(solved):
    """The page the service serves draws the regions of viewer_data (its /view):
    the same boxes as lgmcts.params."""
    import shutil

    from lgmcts.viz import viewer_js

    sync_api = pytest.importorskip("playwright.sync_api", reason="the playwright package is not installed")
    chromium = shutil.which("chromium") or ("/usr/bin/chromium" if Path("/usr/bin/chromium").exists() else None)
    if chromium is None:
        pytest.skip("chromium is not installed (run scripts/system-deps.sh)")
    scene = json.loads(EXAMPLE.read_text())
    plan = json.loads(solved.model_dump_json())
    plan["goals"]["goals"][1]["region"] = "middle row"
    sc = Scene.from_spec(load_scene(EXAMPLE))
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=chromium, args=["--headless", "--no-sandbox", "--disable-gpu"])
        page = b.new_page()
        errors: list[str] = []
        page.on("pageerror", lambda e: errors.append(str(e)))
        page.set_content(f"<html><body><div id='v'></div><script>{viewer_js()}</script></body></html>")
        page.evaluate("d => { window.v = LGMCTSViewer.render(document.getElementById('v'), d); }",
                      json.loads(json.dumps(viewer_data(scene, plan))))
        rects = page.eval_on_selector_all(
            ".lgv-region", "els => els.map(e => [+e.getAttribute('width'), +e.getAttribute('height')])"
        )
        assert page.locator(".lgv-heading").count() == 2
        b.close()
    assert not errors
    boxes = [region_box("top right", sc.bounds), region_box("middle row", sc.bounds)]
    assert len(rects) == 2
    for (w, h), bx in zip(rects, boxes):
        assert w / h == pytest.approx((bx[1] - bx[0]) / (bx[3] - bx[2]), rel=1e-3)
