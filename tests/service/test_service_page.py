"""The viewer page at ``/`` in headless Chromium, planning through the live service."""

from __future__ import annotations

import io
import shutil

import numpy as np
import pytest

pytestmark = pytest.mark.slow

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")


@pytest.mark.skipif(CHROMIUM is None, reason="Debian's chromium is not installed (scripts/system-deps.sh)")
def test_page_plans_and_draws(server, tmp_path):
    sync_api = pytest.importorskip("playwright.sync_api")
    from PIL import Image

    errors: list[str] = []
    with sync_api.sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=CHROMIUM, args=["--no-sandbox", "--disable-gpu"])
        try:
            page = browser.new_page(viewport={"width": 1100, "height": 800})
            page.on("console", lambda m: errors.append(m.text) if m.type == "error" else None)
            page.on("pageerror", lambda e: errors.append(str(e)))
            page.goto(server.url + "/")
            # Plan from the example's goals (the instruction needs the language parser).
            page.fill("#instruction", "")
            page.click("#plan")
            page.wait_for_function(
                "document.getElementById('status').textContent.startsWith('solved')", timeout=30_000
            )
            assert '"solved": true' in page.inner_text("#json")
            page.click("#check")
            page.wait_for_function(
                "document.getElementById('status').textContent === 'the plan is valid'", timeout=30_000
            )
            drawn = page.locator("#view")
            assert drawn.locator("svg, canvas").count() >= 1
            shot = page.screenshot(path=str(tmp_path / "page.png"))
        finally:
            browser.close()
    assert errors == []
    grey = np.asarray(Image.open(io.BytesIO(shot)).convert("L"))
    assert int(grey.max()) - int(grey.min()) > 100 and len(np.unique(grey)) > 20
