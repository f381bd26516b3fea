"""Costs of hostile inputs: a deep `on` stack, a large /plan body next to /healthz, a long plan drawn.

    .venv/bin/python benchmarks/hardening.py [--skip-service] [--skip-viz]

Prints one line per measurement. The inputs are built here, by rule, not
taken from any test: a single stack of N boxes (each on the previous one); a
/plan body holding such a stack of 2,000 boxes with an impossible goal;
a 500-object scene with a 2,000-action plan of random relocations.
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT))


def stack_scene(n: int) -> dict:
    objs = [{"id": i, "name": "block", "shape": {"type": "box", "size": [0.04, 0.04, 0.01]},
             "pose": [0.0, 0.0, 0.0], "on": i - 1 if i else None} for i in range(n)]
    return {"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}, "objects": objs}


def bench_stack() -> None:
    from lgmcts.formats import parse_scene

    for n in (1000, 2000, 3000, 5000):
        data = stack_scene(n)
        t0 = time.perf_counter()
        parse_scene(data)
        print(f"load a stack of {n} objects: {time.perf_counter() - t0:.3f} s")


def bench_service() -> None:
    import httpx

    sys.path.insert(0, str(ROOT / "tests" / "service"))
    from conftest import start_server, stop_server  # the tests' own launcher

    with tempfile.TemporaryDirectory() as tmp:
        proc, url = start_server("--workers", "1", "--timeout", "30", log=Path(tmp) / "log", hooks=False)
        try:
            body = json.dumps({"scene": stack_scene(2000), "goals": {"goals": [
                {"pattern": "line", "objects": list(range(2000))}]}}).encode()
            latencies: list[float] = []
            stop = threading.Event()

            def poll() -> None:
                while not stop.is_set():
                    t = time.perf_counter()
                    httpx.get(url + "/healthz", timeout=60)
                    latencies.append(time.perf_counter() - t)
                    time.sleep(0.05)

            th = threading.Thread(target=poll)
            th.start()
            t0 = time.perf_counter()
            r = httpx.post(url + "/plan", content=body, headers={"content-type": "application/json"}, timeout=120)
            took = time.perf_counter() - t0
            stop.set()
            th.join()
            print(f"/plan with a {len(body) / 1024:.0f} KB body: status {r.status_code} in {took:.2f} s "
                  f"({r.json().get('detail', '')[:60]}); /healthz meanwhile: {len(latencies)} calls, "
                  f"max {max(latencies) * 1000:.0f} ms")
        finally:
            stop_server(proc)


def bench_viz() -> None:
    import random

    rng = random.Random(0)
    spots = [(-0.95 + 0.08 * i, -0.95 + 0.08 * j) for i in range(25) for j in range(24)]
    objs = [{"id": k + 1, "name": "block", "color": "red", "shape": {"type": "box", "size": [0.03, 0.03, 0.03]},
             "pose": [*spots[k], 0.0]} for k in range(500)]
    free, where, acts = list(range(500, 600)), {k: k for k in range(500)}, []
    for _ in range(2000):
        o = rng.randrange(500)
        s = free.pop(rng.randrange(len(free)))
        free.append(where[o])
        where[o] = s
        acts.append({"object": o + 1, "to": [*spots[s], 0.0], "on": None, "purpose": "relocate"})
    with tempfile.TemporaryDirectory() as tmp:
        scene, plan = Path(tmp) / "scene.json", Path(tmp) / "plan.json"
        scene.write_text(json.dumps({"workspace": {"x": [-1, 1], "y": [-1, 1]}, "objects": objs}))
        plan.write_text(json.dumps({"solved": False, "actions": acts}))
        for what, extra in (
            ("pictures", ["-o", str(Path(tmp) / "figs")]),
            ("HTML", ["--html", str(Path(tmp) / "v.html")]),
        ):
            t0 = time.perf_counter()
            out = subprocess.run(
                [sys.executable, "-m", "lgmcts", "viz", str(plan), "--scene", str(scene), *extra],
                capture_output=True,
                text=True,
                cwd=ROOT,
                env={**os.environ, "PYTHONPATH": str(ROOT)},
            )
            print(
                f"viz {what} of 2,000 actions on 500 objects: exit {out.returncode}, {time.perf_counter() - t0:.1f} s"
            )


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--skip-service", action="store_true")
    ap.add_argument("--skip-viz", action="store_true")
    args = ap.parse_args()
    bench_stack()
    if not args.skip_service:
        bench_service()
    if not args.skip_viz:
        bench_viz()


if __name__ == "__main__":
    main()
