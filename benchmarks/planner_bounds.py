"""Costs of small requests that used to cost gigabytes or minutes in the planner.

    PYTHONPATH=$PWD .venv/bin/python benchmarks/planner_bounds.py [--only memory|probes] [--stop-after S]

Prints one line per measurement, each request in a fresh process (so peaks
do not mix): the traced peak (tracemalloc) and the process's maximum RSS.

* memory: two 5 cm blocks and a pose goal on the second one's spot (so it
  must be parked somewhere) on workspaces of +-1 m to +-1,000 m;
* probes: goals the pre-check refuses (or should), with their time to an
  answer and the answer.
"""

from __future__ import annotations

import argparse
import json
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

_RUN = r"""
import json, resource, sys, time, tracemalloc
import lgmcts
from lgmcts.errors import InputError
req = json.loads(sys.stdin.read())
tracemalloc.start()
t0 = time.perf_counter()
try:
    p = lgmcts.plan(req["scene"], req["goals"], method=req.get("method", "lgmcts"), max_iter=req.get("max_iter", 10000),
                    time_limit=req.get("time_limit"))
    answer = f"solved={p.solved} actions={len(p.actions)} iterations={p.stats['iterations']}"
except InputError as exc:
    answer = f"refused: {exc}"
dt = time.perf_counter() - t0
_, peak = tracemalloc.get_traced_memory()
rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
print(json.dumps({"time_s": dt, "peak_mib": peak / 2**20, "rss_mib": rss, "answer": answer}))
"""


def box(i: int, x: float, y: float, size: float = 0.05, on: int | None = None) -> dict:
    return {"id": i, "name": "block", "color": "red", "shape": {"type": "box", "size": [size, size, size]},
            "pose": [x, y, 0.0], "on": on}


def measure(req: dict, timeout: float = 600) -> dict:
    try:
        r = subprocess.run([sys.executable, "-c", _RUN], input=json.dumps(req), capture_output=True, text=True,
                           timeout=timeout, cwd=ROOT)
    except subprocess.TimeoutExpired:
        return {"time_s": float("nan"), "peak_mib": float("nan"), "rss_mib": float("nan"),
                "answer": f"no answer within {timeout:.0f} s (stopped)"}
    if r.returncode != 0:
        return {"time_s": float("nan"), "peak_mib": float("nan"), "rss_mib": float("nan"),
                "answer": "failed: " + (r.stderr.strip().splitlines() or ["?"])[-1]}
    return json.loads(r.stdout)


def memory() -> None:
    for half in (1, 10, 100, 1000):
        objs = [box(1, -0.1, 0.0), box(2, 0.1, 0.0)]
        scene = {"workspace": {"x": [-half, half], "y": [-half, half]}, "objects": objs}
        goals = {"goals": [{"pattern": "pose", "objects": [1], "pose": [0.1, 0.0, 0.0]}]}
        for method in ("lgmcts", "greedy", "pmcts"):
            m = measure({"scene": scene, "goals": goals, "method": method, "max_iter": 1000})
            print(f"+-{half} m workspace, {method}: {m['time_s']:.2f} s, traced peak {m['peak_mib']:.1f} MiB, "
                  f"max RSS {m['rss_mib']:.0f} MiB ({m['answer']})")


def probes() -> dict[str, dict]:
    """The requests of the item-7 probes, by name."""
    ws = {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}
    six = [box(i + 1, -0.3 + 0.12 * i, 0.0, size=0.04) for i in range(6)]
    out: dict[str, dict] = {
        "circle radius below L_min": {
            "scene": {"workspace": ws, "objects": six},
            "goals": {"goals": [{"pattern": "circle", "objects": [1, 2, 3, 4, 5, 6], "size": 0.02}]}},
        "line below L_min": {
            "scene": {"workspace": ws, "objects": six},
            "goals": {"goals": [{"pattern": "line", "objects": [1, 2, 3, 4], "size": 0.05}]}},
        "same 4 objects in a line and a circle": {
            "scene": {"workspace": ws, "objects": six},
            "goals": {"goals": [{"pattern": "line", "objects": [1, 2, 3, 4]},
                                {"pattern": "circle", "objects": [1, 2, 3, 4]}]}},
        "same 6 objects in a line and a circle": {
            "scene": {"workspace": ws, "objects": six},
            "goals": {"goals": [{"pattern": "line", "objects": [1, 2, 3, 4, 5, 6]},
                                {"pattern": "circle", "objects": [1, 2, 3, 4, 5, 6]}]}},
        "line through three non-collinear pose targets": {
            "scene": {"workspace": ws, "objects": six},
            "goals": {"goals": [{"pattern": "line", "objects": [1, 2, 3]},
                                {"pattern": "pose", "objects": [1], "pose": [-0.2, -0.2, 0.0]},
                                {"pattern": "pose", "objects": [2], "pose": [0.0, 0.2, 0.0]},
                                {"pattern": "pose", "objects": [3], "pose": [0.2, -0.2, 0.0]}]}},
        "left and right of one anchor": {
            "scene": {"workspace": ws, "objects": six},
            "goals": {"goals": [{"pattern": "left", "objects": [1], "anchor": 2},
                                {"pattern": "right", "objects": [1], "anchor": 2}]}},
    }
    n = 500
    tall = [box(1, 0.0, 0.0, size=0.04)] + [box(i, 0.0, 0.0, size=0.04, on=i - 1) for i in range(2, n + 1)]
    out[f"unstack a {n}-high tower on a small table"] = {
        "scene": {"workspace": {"x": [-0.3, 0.3], "y": [-0.3, 0.3]}, "objects": tall},
        "goals": {"goals": [{"pattern": "pose", "objects": [1], "pose": [0.2, 0.2, 0.0]}]}}
    out[f"unstack a {n}-high tower on a 2 m x 2 m table"] = {
        "scene": {"workspace": {"x": [-1.0, 1.0], "y": [-1.0, 1.0]}, "objects": tall},
        "goals": {"goals": [{"pattern": "pose", "objects": [1], "pose": [0.2, 0.2, 0.0]}]}}
    return out


def run_probes(max_iter: int, time_limit: float | None, timeout: float) -> None:
    for name, req in probes().items():
        m = measure({**req, "max_iter": max_iter, "time_limit": time_limit}, timeout)
        print(f"{name}: {m['time_s']:.2f} s, traced peak {m['peak_mib']:.1f} MiB: {m['answer'][:200]}")


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--only", choices=["memory", "probes"])
    ap.add_argument("--max-iter", type=int, default=10_000, help="iteration budget of the probes")
    ap.add_argument("--time-limit", type=float, default=None, help="time limit of the probes (s)")
    ap.add_argument("--stop-after", type=float, default=600, help="stop a probe's process after this many seconds")
    args = ap.parse_args()
    if args.only in (None, "memory"):
        memory()
    if args.only in (None, "probes"):
        run_probes(args.max_iter, args.time_limit, args.stop_after)


if __name__ == "__main__":
    main()
