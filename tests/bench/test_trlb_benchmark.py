"""benchmarks/planner.py trlb end to end, on TRLB-format files written here (the real ones are not in the repo)."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from pathlib import Path

import pytest

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
JAMMED = [(798, 798), (501, 482), (798, 204), (204, 204), (241, 798)]


def _write(folder: Path, k: int, n: int, d: float, pts, radius: float) -> None:
    cell = folder / f"D={d}" / f"n={n}"
    cell.mkdir(parents=True, exist_ok=True)
    (cell / f"{k}_{n}_{d}.json").write_text(json.dumps({
        "Object_Radius": radius, "Object_Shape": "disc", "Workspace_Density": d, "Workspace_Height": 1000,
        "Workspace_Width": 1000, "number_of_objects": n, "point_list": [list(map(float, p)) for p in pts]}))


def test_trlb_benchmark_plans_validates_and_judges_peer_plans(tmp_path):
    arr = tmp_path / "arrangements"
    r = math.sqrt(0.2 * 1e6 / math.pi / 4)
    grid = [(250, 250), (750, 250), (250, 750), (750, 750)]
    _write(arr, 0, 4, 0.2, grid, r)
    _write(arr, 1, 4, 0.2, grid[1:] + grid[:1], r)
    jammed_goal = list(JAMMED)
    jammed_goal[3], jammed_goal[4] = jammed_goal[4], jammed_goal[3]
    _write(arr, 0, 5, 0.6, JAMMED, 195.441)
    _write(arr, 1, 5, 0.6, jammed_goal, 195.441)
    # TRLB-style runs: a plan through a buffer (valid) and one that drops disc 0 onto disc 1 (invalid).
    g = grid[1:] + grid[:1]
    good = [[0, list(grid[0]), [500, 500]], [3, list(grid[3]), list(g[3])], [2, list(grid[2]), list(g[2])],
            [1, list(grid[1]), list(g[1])], [0, [500, 500], list(g[0])]]
    bad = [[0, list(grid[0]), list(g[0])]]
    peer = {"rows": [
        {"setting": "preprocessing", "density": 0.2, "n": 4, "pair": ["0_4_0.2.json", "1_4_0.2.json"], "solved": True,
         "time_s": 0.01, "cpu_s": 0.01, "actions": len(good), "plan": good},
        {"setting": "demo", "density": 0.2, "n": 4, "pair": ["0_4_0.2.json", "1_4_0.2.json"], "solved": True,
         "time_s": 0.01, "actions": 1, "plan": bad}]}
    (tmp_path / "peer.json").write_text(json.dumps(peer))
    out = tmp_path / "out.json"
    res = subprocess.run([sys.executable, str(ROOT / "benchmarks" / "planner.py"), "trlb", "--instances", str(arr),
                          "--time-limit", "5", "--process-sample", "0", "--peer", str(tmp_path / "peer.json"),
                          "--json", str(out), "--markdown", str(tmp_path / "cells.md")],
                         capture_output=True, text=True, check=False, cwd=ROOT,
                         env={"PYTHONPATH": str(ROOT), "PATH": "/usr/bin:/bin"})
    assert res.returncode == 0, res.stderr
    data = json.loads(out.read_text())["results"]
    rows = {(r["density"], r["n"]): r for r in data["rows"]}
    assert rows[(0.2, 4)]["solved"] and rows[(0.2, 4)]["actions"] >= 4
    jam = rows[(0.6, 5)]
    assert not jam["solved"] and jam["refused"].startswith("no plan keeping the objects on the table exists")
    peers = {r["setting"]: r for r in data["peer_rows"]}
    assert peers["preprocessing"]["valid"] is True and peers["preprocessing"]["solved"] is True
    assert peers["demo"]["valid"] is False and peers["demo"]["solved"] is False
    md = (tmp_path / "cells.md").read_text()
    assert "| 0.6 | 5 | 0/1 (1 proved impossible) |" in md
    assert "TRLB demo: 0 of 1 plans accepted by the validator" in md
