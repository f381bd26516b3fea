"""The HTML viewer in headless Chromium (Debian's package, driven by Playwright)."""

from __future__ import annotations

import io
import json
import shutil
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from lgmcts.formats import load_plan, load_scene
from lgmcts.scene import Scene
from lgmcts.viz import render_html, viewer_data, viewer_js
from lgmcts.viz.model import replay

DATA = Path(__file__).parent / "data"
SCENE = DATA / "cluttered_scene.json"
PLAN = DATA / "cluttered_plan.json"
CHROMIUM = shutil.which("chromium") or ("/usr/bin/chromium" if Path("/usr/bin/chromium").exists() else None)
ARGS = [
    "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
    "--disable-background-networking", "--disable-component-update", "--disable-sync",
]

sync_api = pytest.importorskip("playwright.sync_api", reason="the playwright package is not installed")
pytestmark = [
    pytest.mark.slow,
    pytest.mark.skipif(CHROMIUM is None, reason="chromium is not installed (run scripts/system-deps.sh)"),
]


@pytest.fixture(scope="module")
def browser():
    with sync_api.sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=ARGS)
        yield b
        b.close()


class Page:
    """A page that records console errors and uncaught exceptions."""

    def __init__(self, browser):
        self.page = browser.new_page(viewport={"width": 1280, "height": 820})
        self.errors: list[str] = []
        self.page.on("console", lambda m: self.errors.append(m.text) if m.type == "error" else None)
        self.page.on("pageerror", lambda e: self.errors.append(str(e)))
        self.page.on("requestfailed", lambda r: self.errors.append(f"request failed: {r.url}"))
        self.requests: list[str] = []
        self.page.on("request", lambda r: self.requests.append(r.url))

    def poses(self) -> dict[int, tuple[float, float, float]]:
        rows = self.page.eval_on_selector_all(
            ".lgv-obj", "els => els.map(e => [e.dataset.id, e.dataset.x, e.dataset.y, e.dataset.theta])"
        )
        return {int(i): (float(x), float(y), float(t)) for i, x, y, t in rows}


@pytest.fixture()
def page(browser):
    p = Page(browser)
    yield p
    p.page.close()


def _open(page: Page, tmp_path: Path, html: str) -> None:
    f = tmp_path / "plan.html"
    f.write_text(html, encoding="utf-8")
    page.page.goto(f.as_uri())
    page.page.wait_for_selector(".lgv-obj")


def _expected(step: int) -> dict[int, np.ndarray]:
    scene = Scene.from_spec(load_scene(SCENE))
    states = replay(scene, list(load_plan(PLAN).actions))
    return {i: states[step].poses[k] for k, i in enumerate(scene.ids)}


def _distinct_colors(png: bytes) -> int:
    img = np.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=np.uint32)
    return len(np.unique((img[..., 0] << 16) | (img[..., 1] << 8) | img[..., 2]))


def test_page_plays_to_the_final_poses(page, tmp_path):
    html = render_html(SCENE, PLAN, instruction="line up the blocks, bottle right of the blue one")
    _open(page, tmp_path, html)
    n = len(load_plan(PLAN).actions)
    assert page.page.locator(".lgv-obj").count() == len(load_scene(SCENE).objects)
    assert "line up the blocks" in page.page.inner_text(".lgv-instr")
    start = page.poses()
    for i, p in _expected(0).items():
        assert np.allclose(start[i], p, atol=1e-9)
    assert page.page.locator(".lgv-goals li.lgv-unmet").count() >= 1
    shot0 = page.page.screenshot()
    # Step to the last action by clicking it in the action list.
    page.page.click(f".lgv-actions li[data-step='{n}']")
    assert page.page.get_attribute(".lgv", "data-step") == str(n)
    final = page.poses()
    for i, p in _expected(n).items():
        assert np.allclose(final[i], p, atol=1e-9), i
    assert page.page.evaluate("window.lgmctsViewer.step()") == n
    assert page.page.locator(".lgv-goals li.lgv-met").count() == len(load_plan(PLAN).goals.goals)
    assert f"Step {n} of {n}" in page.page.inner_text(".lgv-caption")
    shot = page.page.screenshot()
    assert _distinct_colors(shot) > 200
    a, b = (np.asarray(Image.open(io.BytesIO(s)).convert("L"), dtype=int) for s in (shot0, shot))
    assert np.abs(a - b).mean() > 0.5  # the picture changed
    (tmp_path / "viewer.png").write_bytes(shot)
    assert page.errors == []
    assert all(u.startswith(("file:", "data:")) for u in page.requests)


def test_slider_buttons_and_keys(page, tmp_path):
    _open(page, tmp_path, render_html(SCENE, PLAN))
    pg = page.page
    pg.eval_on_selector(".lgv-slider", "s => { s.value = 2; s.dispatchEvent(new Event('input', {bubbles: true})); }")
    assert pg.get_attribute(".lgv", "data-step") == "2"
    for i, p in _expected(2).items():
        assert np.allclose(page.poses()[i], p, atol=1e-9)
    pg.click(".lgv-next")
    assert pg.get_attribute(".lgv", "data-step") == "3"
    pg.click(".lgv-prev")
    pg.click(".lgv-prev")
    assert pg.get_attribute(".lgv", "data-step") == "1"
    pg.focus(".lgv")
    pg.keyboard.press("End")
    assert pg.get_attribute(".lgv", "data-step") == str(len(load_plan(PLAN).actions))
    pg.keyboard.press("Home")
    assert pg.get_attribute(".lgv", "data-step") == "0"
    # Play advances on its own; pause stops it.
    pg.click(".lgv-play")
    pg.wait_for_function("window.lgmctsViewer.step() >= 1", timeout=5000)
    pg.click(".lgv-play")
    assert pg.evaluate("window.lgmctsViewer.playing()") is False
    assert page.errors == []


def test_render_draws_the_states_computed_in_python(page):
    """The script draws the states, footprints and shapes of viewer_data; it replays and fits nothing itself."""
    scene = json.loads((DATA / "shapes_scene.json").read_text())
    plan = {
        "solved": True,
        "actions": [
            {"object": 5, "to": [0.2, 0.1, 0.0], "on": None, "purpose": "unstack"},
            {"object": 1, "to": [-0.1, -0.1, 1.0], "on": None, "purpose": "goal"},
            {"object": 5, "to": [-0.1, -0.1, 0.0], "on": 1, "purpose": "goal"},
        ],
        "goals": {"goals": [{"pattern": "tower", "objects": [1, 5]}, {"pattern": "line", "objects": [2, 3, 4]}]},
    }
    data = json.loads(json.dumps(viewer_data(scene, plan)))
    pg = page.page
    pg.set_content(f"<html><body><div id='v'></div><script>{viewer_js()}</script></body></html>")
    pg.evaluate("d => { window.v = LGMCTSViewer.render(document.getElementById('v'), d); }", data)
    assert pg.evaluate("window.v.count()") == 3
    pg.evaluate("window.v.setStep(3)")
    poses = page.poses()
    assert np.allclose(poses[5], [-0.1, -0.1, 0.0]) and np.allclose(poses[1], [-0.1, -0.1, 1.0])
    assert pg.get_attribute(".lgv-obj[data-id='5']", "data-on") == "1"
    assert pg.locator(".lgv-goal").count() == 2
    assert page.errors == []
    # Without the computed parts it says so in one line instead of guessing.
    del data["frames"]
    out = pg.evaluate("d => LGMCTSViewer.render(document.getElementById('v'), d)", data)
    assert out is None and "viewer_data" in pg.inner_text("#v")


def test_bad_data_shows_a_message_not_an_exception(page):
    pg = page.page
    pg.set_content(f"<html><body><div id='v'></div><script>{viewer_js()}</script></body></html>")
    out = pg.evaluate("() => LGMCTSViewer.render(document.getElementById('v'), {scene: {objects: []}})")
    assert out is None
    assert "Cannot show this plan" in pg.inner_text("#v")
    assert page.errors == []


def test_instruction_cannot_break_out_of_the_page(page, tmp_path):
    evil = "</script><script>window.pwned = 1</script> & <b>bold</b>"
    _open(page, tmp_path, render_html(SCENE, PLAN, instruction=evil, title="<i>t</i>"))
    assert page.page.evaluate("window.pwned") is None
    assert evil in page.page.inner_text(".lgv-instr")
    assert page.page.title() == "<i>t</i>"
    assert page.errors == []


def test_empty_plan_shows_the_scene(page, tmp_path):
    plan = {"solved": False, "actions": [], "goals": json.loads(PLAN.read_text())["goals"], "stats": {}}
    _open(page, tmp_path, render_html(SCENE, plan))
    pg = page.page
    assert pg.evaluate("window.lgmctsViewer.count()") == 0
    pg.click(".lgv-play")
    pg.click(".lgv-next")
    assert pg.get_attribute(".lgv", "data-step") == "0"
    for i, p in _expected(0).items():
        assert np.allclose(page.poses()[i], p, atol=1e-9)
    assert "not solved" in pg.inner_text(".lgv-head")
    assert page.errors == []
