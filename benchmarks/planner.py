"""Planner benchmark: seeded random cases, the Labbé et al. protocol, peak memory.

Examples (one core; the figures in docs/benchmarks.md come from these)::

    python benchmarks/planner.py random --n 300
    python benchmarks/planner.py random --n 300 --dense
    python benchmarks/planner.py labbe --per-n 100 --ns 1-37
    python benchmarks/planner.py labbe --variant spaced --ns 1,4,8,12,16,20,25,30,37
    python benchmarks/planner.py memory --objects 40

``random`` draws cases from :func:`lgmcts.casegen.random_case` (6-16
objects, 1-2 goals, half with blockers stacked on goal objects, half with
clutter standing where goal objects went in the arrangement the case was
built from; every case is solvable by construction) and plans each with
every method. ``labbe`` follows Labbé et al. (RA-L 2020) as their public
evaluator samples it (:func:`lgmcts.casegen.labbe_protocol_case`): N discs
of radius 3.75 cm, start and goal centres by random sequential addition in a
0.5 m x 0.5 m square with every centre distance at least 2R (discs may
touch), a ``pose`` goal for every disc; ``--variant spaced`` gives the
earlier, more spaced generator (:func:`lgmcts.casegen.labbe_case`). ``memory`` runs one planning
process to the full iteration budget on a 40-object scene whose goals cannot
all be met (a line of 20 objects, and one object both left and right of
another), and reports its peak resident memory and the tree size.
"""

from __future__ import annotations

import argparse
import json
import platform
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from lgmcts import check, plan
from lgmcts.casegen import LABBE_VARIANTS, labbe_case, random_case


def _row(c, method: str, seed: int, max_iter: int, repeat: int = 1) -> dict:
    # With repeat > 1 the same (deterministic) plan is computed again and the
    # fastest run counts: on a shared VM that filters out time stolen by
    # other tenants, not work.
    wall = cpu = float("inf")
    for _ in range(max(1, repeat)):
        t, tc = time.perf_counter(), time.process_time()
        p = plan(c.scene, c.goals, method=method, seed=seed, max_iter=max_iter)
        wall = min(wall, time.perf_counter() - t)
        cpu = min(cpu, time.process_time() - tc)
    ok = bool(p.solved and check(c.scene, c.goals, p).valid)
    return {"solved": ok, "time_s": wall, "cpu_s": cpu, "iterations": p.stats["iterations"], "actions": len(p.actions),
            "lower_bound": c.lower_bound, "reference": c.reference, "objects": len(c.scene.objects), "kind": c.kind}


def _summary(rows: list[dict]) -> dict:
    t = np.array([r["time_s"] for r in rows])
    ok = [r for r in rows if r["solved"]]
    return {
        "cases": len(rows),
        "success": len(ok) / len(rows),
        "time_median_s": float(np.median(t)),
        "time_p95_s": float(np.percentile(t, 95)),
        "time_max_s": float(t.max()),
        # Process CPU time: on a shared machine, less affected by other tenants than wall time.
        "cpu_median_s": float(np.median([r["cpu_s"] for r in rows])),
        "cpu_p95_s": float(np.percentile([r["cpu_s"] for r in rows], 95)),
        "iterations_mean": float(np.mean([r["iterations"] for r in rows])),
        "actions_mean": float(np.mean([r["actions"] for r in ok])) if ok else float("nan"),
        "lower_bound_mean": float(np.mean([r["lower_bound"] for r in ok])) if ok else float("nan"),
        "actions_over_bound": (
            float(np.sum([r["actions"] for r in ok]) / max(1, np.sum([r["lower_bound"] for r in ok])))
            if ok
            else float("nan")
        ),
        "reference_mean": float(np.mean([r["reference"] for r in ok])) if ok else float("nan"),
        "actions_over_reference": (
            float(np.sum([r["actions"] for r in ok]) / max(1, np.sum([r["reference"] for r in ok])))
            if ok
            else float("nan")
        ),
    }


def cmd_random(a: argparse.Namespace) -> dict:
    cases = [random_case(a.first_seed + k, dense=a.dense) for k in range(a.n)]
    out: dict = {}
    for m in a.methods.split(","):
        rows = []
        for k, c in enumerate(cases):
            rows.append(_row(c, m, seed=k, max_iter=a.max_iter))
            if a.progress:
                print(f"\r{m}: {k + 1}/{len(cases)}", end="", file=sys.stderr, flush=True)
        if a.progress:
            print(file=sys.stderr)
        s = _summary(rows)
        by_n: dict[int, list[float]] = {}
        for r in rows:
            by_n.setdefault(r["objects"], []).append(r["time_s"])
        s["time_median_by_objects"] = {n: float(np.median(v)) for n, v in sorted(by_n.items())}
        s["by_kind"] = {k: _summary([r for r in rows if r["kind"] == k]) for k in sorted({r["kind"] for r in rows})}
        out[m] = s
    print(
        "| method | cases | success | median time (s) | p95 time (s) | max time (s) | mean iterations | mean actions "
        "| mean reference | actions / reference | mean lower bound | actions / bound |"
    )
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for m, s in out.items():
        print(
            f"| {m} | {s['cases']} | {100 * s['success']:.1f}% | {s['time_median_s']:.3f} | {s['time_p95_s']:.3f} | "
            f"{s['time_max_s']:.2f} | {s['iterations_mean']:.1f} | {s['actions_mean']:.2f} | "
            f"{s['reference_mean']:.2f} | {s['actions_over_reference']:.3f} | {s['lower_bound_mean']:.2f} | "
            f"{s['actions_over_bound']:.3f} |"
        )
    return out


def _ns(spec: str) -> list[int]:
    """``"1-37"`` or ``"1,4,8"`` (or a mix) as a list of N."""
    out: list[int] = []
    for part in spec.split(","):
        lo, _, hi = part.partition("-")
        out.extend(range(int(lo), int(hi) + 1) if hi else [int(lo)])
    return out


def cmd_labbe(a: argparse.Namespace) -> dict:
    out: dict = {}
    print("| N | method | success | actions / object | median time (s) | p95 time (s) | median CPU (s) | p95 CPU (s) |")
    print("|---|---|---|---|---|---|---|---|")
    for n in _ns(a.ns):
        cases = [labbe_case(n, 1000 * n + k, variant=a.variant) for k in range(a.per_n)]
        for m in a.methods.split(","):
            rows = []
            for k, c in enumerate(cases):
                rows.append(_row(c, m, seed=k, max_iter=a.max_iter, repeat=a.repeat))
                if a.progress:
                    print(f"\rN = {n} {m}: {k + 1}/{len(cases)}", end="", file=sys.stderr, flush=True)
            if a.progress:
                print(file=sys.stderr)
            s = _summary(rows)
            ok = [r for r in rows if r["solved"]]
            s["actions_per_object"] = float(np.mean([r["actions"] / n for r in ok])) if ok else float("nan")
            out[f"{n}/{m}"] = s
            print(
                f"| {n} | {m} | {100 * s['success']:.0f}% | {s['actions_per_object']:.3f} | {s['time_median_s']:.4f} | "
                f"{s['time_p95_s']:.4f} | {s['cpu_median_s']:.4f} | {s['cpu_p95_s']:.4f} |",
                flush=True,
            )
            if a.json:
                # Partial results survive a run cut short.
                a.json.parent.mkdir(parents=True, exist_ok=True)
                a.json.with_suffix(".partial.json").write_text(json.dumps(out, indent=1))
    return out


_MEMORY_CHILD = r"""
import json, resource, sys, time
from lgmcts import plan
n = int(sys.argv[1]); max_iter = int(sys.argv[2])
cols = 8
objs = []
for i in range(n):
    x = -0.35 + 0.1 * (i % cols); y = -0.25 + 0.1 * (i // cols)
    objs.append({"id": i + 1, "name": "block", "color": "red", "shape": {"type": "box", "size": [0.04, 0.04, 0.04]},
                 "pose": [x, y, 0.0], "on": None})
scene = {"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}, "objects": objs}
# Object n-1 must end both left and right of object n: impossible, so the search
# runs its whole budget, while a line of the first half of the objects lets it
# grow a deep, wide tree.
goals = {"goals": [{"pattern": "line", "objects": [o["id"] for o in objs[:6]]},
                   {"pattern": "left", "objects": [n - 1], "anchor": n},
                   {"pattern": "right", "objects": [n - 1], "anchor": n}]}
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
t = time.perf_counter()
p = plan(scene, goals, seed=0, max_iter=max_iter)
print(json.dumps({"objects": n, "solved": p.solved, "iterations": p.stats["iterations"], "nodes": p.stats["nodes"],
                  "time_s": time.perf_counter() - t, "rss_before_mb": before / 1024,
                  "peak_rss_mb": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024}))
"""


def cmd_memory(a: argparse.Namespace) -> dict:
    r = subprocess.run(
        [sys.executable, "-c", _MEMORY_CHILD, str(a.objects), str(a.max_iter)], capture_output=True, text=True
    )
    if r.returncode != 0:
        raise SystemExit(r.stderr.strip().splitlines()[-1])
    out = json.loads(r.stdout)
    print(json.dumps(out, indent=1))
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("random")
    r.add_argument("--n", type=int, default=300)
    r.add_argument("--first-seed", type=int, default=0)
    r.add_argument("--methods", default="lgmcts,greedy,pmcts")
    r.add_argument(
        "--dense",
        action="store_true",
        help="the dense variant: 4-10 extra clutter objects packed edge to edge around the goal region",
    )
    lb = sub.add_parser("labbe")
    lb.add_argument("--ns", default="1-37", help="N values: a list (1,4,8) and/or ranges (1-37)")
    lb.add_argument(
        "--variant",
        default="protocol",
        choices=LABBE_VARIANTS,
        help="protocol: as the authors' evaluator samples it; spaced: the earlier, easier generator",
    )
    lb.add_argument("--per-n", type=int, default=100)
    lb.add_argument("--methods", default="lgmcts")
    lb.add_argument("--repeat", type=int, default=1, help="plan each case this many times and keep the fastest time")
    mem = sub.add_parser("memory")
    mem.add_argument("--objects", type=int, default=40)
    for p in (r, lb, mem):
        p.add_argument("--max-iter", type=int, default=10_000)
        p.add_argument("--json", type=Path, help="also write the results here")
        p.add_argument("--progress", action="store_true")
    a = ap.parse_args()
    t0 = time.perf_counter()
    res = {"random": cmd_random, "labbe": cmd_labbe, "memory": cmd_memory}[a.cmd](a)
    meta = {
        "command": " ".join(["python", *sys.argv]),
        "machine": f"{platform.machine()} {platform.processor() or ''}".strip(),
        "python": platform.python_version(),
        "date": time.strftime("%Y-%m-%d"),
        "wall_s": time.perf_counter() - t0,
    }
    print(f"\n{meta['command']}  ({meta['date']}, {meta['wall_s']:.0f} s)")
    if a.json:
        a.json.parent.mkdir(parents=True, exist_ok=True)
        a.json.write_text(json.dumps({"meta": meta, "results": res}, indent=1))


if __name__ == "__main__":
    main()
