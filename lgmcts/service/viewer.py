"""The page served at ``/``: paste or upload a scene, plan, and see the plan.

The page is one self-contained HTML document (no network access besides the
calls to this service). When the package ships the plan viewer script
``lgmcts/viz/assets/viewer.js`` (which defines
``LGMCTSViewer.render(container, {scene, plan, instruction})``) it is inlined
and draws the plan; otherwise a small built-in drawing of the start and final
footprints and the plan JSON are shown.
"""

from __future__ import annotations

import json
import re
from pathlib import Path

__all__ = ["page", "viewer_script", "EXAMPLE_SCENE", "EXAMPLE_GOALS", "EXAMPLE_INSTRUCTION"]

VIEWER_JS = Path(__file__).resolve().parent.parent / "viz" / "assets" / "viewer.js"

#: The scene loaded by the page's "example" button (metres, radians).
EXAMPLE_SCENE = {
    "workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]},
    "objects": [
        {"id": 1, "name": "block", "color": "red", "shape": {"type": "box", "size": [0.05, 0.05, 0.05]}, "pose": [-0.25, -0.15, 0.3]},
        {"id": 2, "name": "block", "color": "blue", "shape": {"type": "box", "size": [0.05, 0.05, 0.05]}, "pose": [0.05, 0.02, 0.0]},
        {"id": 3, "name": "block", "color": "green", "shape": {"type": "box", "size": [0.05, 0.05, 0.05]}, "pose": [0.05, 0.02, 0.2], "on": 2},
        {"id": 4, "name": "block", "color": "yellow", "shape": {"type": "box", "size": [0.05, 0.05, 0.05]}, "pose": [0.28, 0.18, -0.4]},
        {"id": 5, "name": "bottle", "color": "white", "shape": {"type": "cylinder", "radius": 0.035, "height": 0.2}, "pose": [-0.3, 0.2, 0.0]},
        {"id": 6, "name": "bowl", "color": "green", "shape": {"type": "cylinder", "radius": 0.07, "height": 0.05}, "pose": [0.15, -0.15, 0.0]},
    ],
}
EXAMPLE_GOALS = {"goals": [{"pattern": "line", "objects": [1, 2, 3, 4]}, {"pattern": "behind", "objects": [5], "anchor": 1}]}
EXAMPLE_INSTRUCTION = "put all blocks in a line and the white bottle behind the red block"

_cache: dict[str, tuple[float, str]] = {}


def viewer_script(path: Path | None = None) -> str | None:
    """The viewer script's text, safe to inline in a ``<script>`` element, or ``None`` if absent.

    Read when its modification time changes, so a viewer installed after the
    server started is picked up on the next page load. ``path`` defaults to
    :data:`VIEWER_JS`.
    """
    path = VIEWER_JS if path is None else path
    try:
        mtime = path.stat().st_mtime
    except OSError:
        return None
    hit = _cache.get(str(path))
    if hit is not None and hit[0] == mtime:
        return hit[1]
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return None
    text = _inline_safe(text)
    _cache[str(path)] = (mtime, text)
    return text


def _inline_safe(js: str) -> str:
    # Inside <script>, the HTML parser ends the element at "</script" whatever
    # the JavaScript context; "<\/" means the same in every JS string or regex.
    return re.sub(r"</(script)", r"<\\/\1", js, flags=re.IGNORECASE).replace("<!--", "<\\!--")


def _json_for_script(data: object) -> str:
    return json.dumps(data).replace("<", "\\u003c").replace(">", "\\u003e").replace("&", "\\u0026")


def page() -> str:
    """The HTML of the viewer page."""
    script = viewer_script()
    viewer = f"<script>{script}</script>" if script is not None else ""
    return (
        _PAGE.replace("/*VIEWER*/", viewer)
        .replace("/*EXAMPLE_SCENE*/null", _json_for_script(EXAMPLE_SCENE))
        .replace("/*EXAMPLE_GOALS*/null", _json_for_script(EXAMPLE_GOALS))
        .replace("/*EXAMPLE_INSTRUCTION*/null", _json_for_script(EXAMPLE_INSTRUCTION))
    )


_PAGE = """<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>lgmcts planner</title>
<style>
  body { font: 14px/1.4 system-ui, sans-serif; margin: 0; color: #222; }
  header { background: #263238; color: #fff; padding: 8px 16px; }
  header a { color: #b3e5fc; margin-left: 12px; }
  main { display: flex; gap: 16px; padding: 12px 16px; flex-wrap: wrap; }
  #inputs { flex: 0 0 380px; display: flex; flex-direction: column; gap: 6px; }
  #inputs textarea { width: 100%; box-sizing: border-box; font: 12px monospace; }
  #output { flex: 1 1 520px; min-width: 320px; }
  .row { display: flex; gap: 8px; align-items: center; flex-wrap: wrap; }
  #status { min-height: 1.4em; font-weight: 600; }
  #status.error { color: #b71c1c; }
  #status.ok { color: #1b5e20; }
  #json { background: #f5f5f5; padding: 8px; max-height: 320px; overflow: auto; font: 12px monospace; }
  .legend span { margin-right: 12px; }
</style>
</head>
<body>
<header><strong>lgmcts</strong> language-guided tabletop rearrangement planner
  <a href="/openapi.json">OpenAPI</a><a href="/healthz">health</a></header>
<main>
<section id="inputs">
  <label for="scene">Scene JSON</label>
  <textarea id="scene" rows="12" spellcheck="false"></textarea>
  <div class="row"><input type="file" id="scene-file" accept=".json,application/json">
    <button type="button" id="example">Load example</button></div>
  <label for="instruction">Instruction</label>
  <input id="instruction" type="text">
  <label for="goals">or goals JSON (used when the instruction is empty)</label>
  <textarea id="goals" rows="4" spellcheck="false"></textarea>
  <div class="row">
    <label>method <select id="method"><option>lgmcts</option><option>greedy</option><option>pmcts</option></select></label>
    <label>seed <input id="seed" type="number" value="0" style="width:5em"></label>
    <label>max iter <input id="max-iter" type="number" value="10000" style="width:6em"></label>
  </div>
  <div class="row"><button type="button" id="plan">Plan</button><button type="button" id="check">Check plan</button></div>
  <div id="status" role="status"></div>
</section>
<section id="output">
  <div id="view"></div>
  <details open><summary>Plan JSON</summary><pre id="json"></pre></details>
</section>
</main>
/*VIEWER*/
<script>
(function () {
  "use strict";
  var EXAMPLE = { scene: /*EXAMPLE_SCENE*/null, goals: /*EXAMPLE_GOALS*/null, instruction: /*EXAMPLE_INSTRUCTION*/null };
  var $ = function (id) { return document.getElementById(id); };
  var last = null;

  function status(text, cls) { var s = $("status"); s.textContent = text; s.className = cls || ""; }

  function loadExample() {
    $("scene").value = JSON.stringify(EXAMPLE.scene, null, 1);
    $("instruction").value = EXAMPLE.instruction;
    $("goals").value = JSON.stringify(EXAMPLE.goals);
  }

  function readJSON(id, what) {
    var text = $(id).value.trim();
    if (!text) return null;
    try { return JSON.parse(text); } catch (e) { throw new Error(what + " is not valid JSON: " + e.message); }
  }

  async function post(path, body) {
    // A server started with --token: open the page as /#token=<token>.
    var m = location.hash.match(/token=([^&]+)/), headers = { "Content-Type": "application/json" };
    if (m) headers["Authorization"] = "Bearer " + decodeURIComponent(m[1]);
    var r = await fetch(path, { method: "POST", headers: headers, body: JSON.stringify(body) });
    var data = null;
    try { data = await r.json(); } catch (e) { data = { detail: r.statusText }; }
    if (!r.ok) throw new Error(r.status + ": " + (data && data.detail ? data.detail : r.statusText));
    return data;
  }

  async function show(scene, plan, instruction) {
    $("json").textContent = JSON.stringify(plan, null, 2);
    // The server computes what to draw (states, footprints, goal shapes); the script only draws it.
    var data = await post("/view", { scene: scene, plan: plan, instruction: instruction });
    window.LGMCTSViewer.render($("view"), data);
  }

  async function doPlan() {
    try {
      var scene = readJSON("scene", "the scene");
      if (!scene) throw new Error("paste, upload or load a scene first");
      var instruction = $("instruction").value.trim();
      var body = { scene: scene, options: { method: $("method").value, seed: parseInt($("seed").value || "0", 10),
                                             max_iter: parseInt($("max-iter").value || "10000", 10) } };
      if (instruction) body.instruction = instruction; else body.goals = readJSON("goals", "the goals");
      status("planning...");
      var t0 = performance.now();
      var plan = await post("/plan", body);
      last = { scene: scene, plan: plan };
      await show(scene, plan, instruction || null);
      status((plan.solved ? "solved: " : "not solved: ") + plan.actions.length + " actions in " +
             Math.round(performance.now() - t0) + " ms", plan.solved ? "ok" : "error");
    } catch (e) { status(e.message, "error"); }
  }

  async function doCheck() {
    try {
      if (!last) throw new Error("plan first");
      var v = await post("/check", { scene: last.scene, goals: last.plan.goals, plan: last.plan });
      status(v.valid ? "the plan is valid" : "invalid: " + v.reasons.join("; "), v.valid ? "ok" : "error");
    } catch (e) { status(e.message, "error"); }
  }

  $("scene-file").addEventListener("change", function (ev) {
    var f = ev.target.files[0]; if (!f) return;
    f.text().then(function (t) { $("scene").value = t; status("loaded " + f.name); });
  });
  $("example").addEventListener("click", loadExample);
  $("plan").addEventListener("click", doPlan);
  $("check").addEventListener("click", doCheck);
  loadExample();
  window.LGMCTSPage = { plan: doPlan, check: doCheck };
})();
</script>
</body>
</html>
"""
