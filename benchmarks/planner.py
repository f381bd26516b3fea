"""Planner benchmark: seeded random cases, the Labbé et al. protocol, peak memory.

Examples (one core; the figures in docs/benchmarks.md come from these)::

    python benchmarks/planner.py random --n 300
    python benchmarks/planner.py random --n 300 --dense
    python benchmarks/planner.py labbe --per-n 100 --ns 1-37
    python benchmarks/planner.py labbe --variant spaced --ns 1,4,8,12,16,20,25,30,37
    python benchmarks/planner.py memory --objects 40
    python benchmarks/planner.py trlb --instances PATH/TRLB/disk_experiments/arrangements --pairs 5

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
``trlb`` plans the instances of TRLB (Gao et al., ICRA 2022; the public
repository ``arc-l/TRLB``, folder ``disk_experiments/arrangements``, which
is read from ``--instances`` and never copied here): files ``2k`` and
``2k+1`` of each (density, count) cell form a start/goal pair
(:func:`lgmcts.casegen.trlb_pairs`, :func:`lgmcts.casegen.trlb_case`), every
plan is judged by the validator, and per cell it reports success, median and
p95 planning time, the whole ``lgmcts plan`` process time for a sample, and
actions per object; ``--peer`` adds the same figures for TRLB's own planner
from a file of its runs (see docs/benchmarks.md for that file's format).
"""

from __future__ import annotations

import argparse
import json
import math
import platform
import resource
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from lgmcts import Action, InputError, PlanSpec, check, plan, save_json
from lgmcts.casegen import (
    LABBE_VARIANTS,
    TRLB_UNIT,
    labbe_case,
    random_case,
    trlb_case,
    trlb_pairs,
)


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


def _trlb_row(d: float, n: int, files: tuple[Path, Path], a: argparse.Namespace, process: bool) -> dict:
    case = trlb_case(*files)
    row: dict = {"density": d, "n": n, "pair": [f.name for f in files], "solved": False, "refused": "", "reason": ""}
    t, tc = time.perf_counter(), time.process_time()
    try:
        p = plan(case.scene, case.goals, seed=a.seed, max_iter=a.max_iter, time_limit=a.time_limit)
    except InputError as e:
        # A refusal is a proof that no plan exists (lgmcts.feasibility), as is
        # an unsolved plan marked infeasible below.
        row.update(time_s=time.perf_counter() - t, cpu_s=time.process_time() - tc, refused=str(e), actions=0)
    else:
        row.update(time_s=time.perf_counter() - t, cpu_s=time.process_time() - tc, actions=len(p.actions),
                   iterations=p.stats["iterations"], reason=p.stats.get("reason", ""),
                   sequenced=bool(p.stats.get("sequenced")), dense=bool(p.stats.get("dense")))
        if p.stats.get("infeasible"):
            # The planner's proof that no table-only plan exists (lgmcts.confinement).
            row["refused"] = row["reason"]
        verdict = check(case.scene, case.goals, p)
        row["solved"] = bool(p.solved and verdict.valid)
        if p.solved and not verdict.valid:
            row["reason"] = "rejected by the validator: " + "; ".join(verdict.reasons[:2])
    if process:
        row["process_s"], row["process_cpu_s"] = _process_time(case, a)
    return row


def _process_time(case, a: argparse.Namespace) -> tuple[float, float]:
    """Wall and CPU time of one whole ``lgmcts plan`` process (start-up, reading, planning, writing) on ``case``."""
    import tempfile

    with tempfile.TemporaryDirectory() as tmp:
        scene, goals, out = Path(tmp, "scene.json"), Path(tmp, "goals.json"), Path(tmp, "plan.json")
        save_json(case.scene, scene)
        save_json(case.goals, goals)
        cmd = [sys.executable, "-m", "lgmcts", "plan", str(scene), "--goal", str(goals), "-o", str(out),
               "--seed", str(a.seed), "--max-iter", str(a.max_iter)]
        if a.time_limit:
            cmd += ["--time-limit", str(a.time_limit)]
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        t = time.perf_counter()
        subprocess.run(cmd, capture_output=True, text=True, check=False)
        wall = time.perf_counter() - t
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        return wall, (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def _trlb_peer_plan(case, moves: list) -> PlanSpec:
    """A plan of TRLB's ``[object, from, to]`` moves (TRLB units, objects from 0) for ``case``."""
    goal = {g.objects[0]: g.pose for g in case.goals.goals}
    acts = []
    for obj, _, to in moves:
        pose = (to[0] * TRLB_UNIT, to[1] * TRLB_UNIT, 0.0)
        target = goal[obj + 1]
        at_goal = math.hypot(pose[0] - target[0], pose[1] - target[1]) < 1e-6
        acts.append(Action(object=obj + 1, to=pose, purpose="goal" if at_goal else "relocate"))
    return PlanSpec(solved=True, actions=acts, goals=case.goals)


def _trlb_peer_checks(rows: list[dict], a: argparse.Namespace) -> None:
    """Judge TRLB's plans with the validator (a plan it rejects does not count
    as solved); replay a sample in MuJoCo (``physics``): up to
    ``--peer-physics`` plans of the preprocessing setting with at most
    ``--peer-physics-max-n`` discs, the smallest first, taken from each
    density in turn."""
    root = Path(a.instances)
    cases = {}
    for r in rows:
        if not r.get("plan"):
            continue
        tag = f"{r['density']:g}"
        case = cases[id(r)] = trlb_case(*(root / f"D={tag}" / f"n={r['n']}" / name for name in r["pair"]))
        verdict = check(case.scene, case.goals, _trlb_peer_plan(case, r["plan"]))
        r["valid"] = bool(verdict.valid)
        if not verdict.valid:
            r["solved"] = False
            r["invalid_reasons"] = list(verdict.reasons[:3])
    by_density: dict[float, list[dict]] = {}
    for r in sorted(rows, key=lambda r: (r["n"], r["pair"])):
        if r.get("valid") and r["setting"] == "preprocessing" and r["n"] <= a.peer_physics_max_n:
            by_density.setdefault(r["density"], []).append(r)
    queues = [by_density[d] for d in sorted(by_density)]
    picked: list[dict] = []
    while len(picked) < a.peer_physics and any(queues):
        for q in queues:
            if q and len(picked) < a.peer_physics:
                picked.append(q.pop(0))
    if picked:
        from lgmcts.sim import execute_plan

        for r in picked:
            case = cases[id(r)]
            t = time.perf_counter()
            ex = execute_plan(case.scene, _trlb_peer_plan(case, r["plan"]), case.goals)
            r["physics"] = bool(ex.success)
            r["physics_s"] = time.perf_counter() - t
            if not ex.success:
                r["physics_reasons"] = list(ex.reasons[:3])


def _trlb_cell(rows: list[dict]) -> dict:
    ok = [r for r in rows if r["solved"]]
    t = [r["time_s"] for r in ok]
    proc = [r["process_s"] for r in rows if r.get("process_s") is not None]
    proc_cpu = [r["process_cpu_s"] for r in rows if r.get("process_cpu_s") is not None]
    return {
        "pairs": len(rows),
        "solved": len(ok),
        "refused": sum(bool(r.get("refused")) for r in rows),
        "time_median_s": float(np.median(t)) if t else float("nan"),
        "time_p95_s": float(np.percentile(t, 95)) if t else float("nan"),
        "time_median_all_s": float(np.median([r["time_s"] for r in rows])),
        # Process CPU time of the planner alone: on a shared machine, less
        # affected by other tenants than wall time (absent for peers' rows without it).
        "cpu_median_s": (float(np.median([r["cpu_s"] for r in ok])) if ok and all("cpu_s" in r for r in ok)
                         else float("nan")),
        "process_median_s": float(np.median(proc)) if proc else float("nan"),
        "process_cpu_median_s": float(np.median(proc_cpu)) if proc_cpu else float("nan"),
        "actions_per_object": float(np.mean([r["actions"] / r["n"] for r in ok])) if ok else float("nan"),
        "refuse_time_max_s": max([r["time_s"] for r in rows if r.get("refused")], default=float("nan")),
    }


def _trlb_table(groups: dict[str, list[dict]]) -> tuple[dict, list[str]]:
    """Per-cell, per-density and scaling figures of each planner's rows, as JSON and markdown lines."""
    names = list(groups)
    cells = sorted({(r["density"], r["n"]) for rows in groups.values() for r in rows})
    out: dict = {"cells": {}, "densities": {}, "exponent_d04": {}}
    head = " | ".join(f"{m}: solved | {m}: median / p95 plan (s) | {m}: median CPU (s) | {m}: actions/object"
                      for m in names)
    md = ["| D | n | " + head + " | lgmcts: process wall / CPU (s) |",
          "|---|---|" + "---|---|---|---|" * len(names) + "---|"]
    for d, n in cells:
        line = f"| {d:g} | {n} |"
        for m in names:
            s = _trlb_cell([r for r in groups[m] if (r["density"], r["n"]) == (d, n)]) if any(
                (r["density"], r["n"]) == (d, n) for r in groups[m]) else None
            out["cells"].setdefault(f"{d:g}/{n}", {})[m] = s
            if s is None:
                line += " - | - | - | - |"
                continue
            solved = f"{s['solved']}/{s['pairs']}" + (f" ({s['refused']} proved impossible)" if s["refused"] else "")
            line += (f" {solved} | {s['time_median_s']:.3f} / {s['time_p95_s']:.3f} | {s['cpu_median_s']:.3f} |"
                     f" {s['actions_per_object']:.2f} |")
        first = out["cells"][f"{d:g}/{n}"].get(names[0])
        has = first is not None and first["process_median_s"] == first["process_median_s"]
        line += f" {first['process_median_s']:.2f} / {first['process_cpu_median_s']:.2f} |" if has else " - |"
        md.append(line)
    md += ["", "| D | " + " | ".join(f"{m}: solved | {m}: median plan (s) | {m}: median CPU (s) | {m}: actions/object"
                                     for m in names) + " |",
           "|---|" + "---|---|---|---|" * len(names)]
    for d in sorted({c[0] for c in cells}):
        line = f"| {d:g} |"
        for m in names:
            band = [r for r in groups[m] if r["density"] == d]
            s = _trlb_cell(band) if band else None
            out["densities"].setdefault(f"{d:g}", {})[m] = s
            line += " - | - | - | - |" if s is None else (
                f" {s['solved']}/{s['pairs']} | {s['time_median_s']:.3f} | {s['cpu_median_s']:.3f} |"
                f" {s['actions_per_object']:.2f} |")
        md.append(line)
    md.append("")
    for m in names:
        # Median planning time per n at D = 0.4, n = 50-200, fitted as t = c n^k (least squares in log-log).
        for key, what in (("time_s", "wall"), ("cpu_s", "CPU")):
            pts = []
            for n in sorted({r["n"] for r in groups[m] if r["density"] == 0.4 and 50 <= r["n"] <= 200}):
                t = [r[key] for r in groups[m] if r["density"] == 0.4 and r["n"] == n and r["solved"] and key in r]
                if t:
                    pts.append((n, float(np.median(t))))
            if len(pts) >= 2:
                k, _ = np.polyfit(np.log([p[0] for p in pts]), np.log([p[1] for p in pts]), 1)
                out["exponent_d04"][f"{m} ({what})"] = {"exponent": float(k), "points": pts}
                md.append(f"{m}: median planning {what} time at D = 0.4, n = {pts[0][0]}-{pts[-1][0]} grows as "
                          f"n^{k:.2f} ({len(pts)} values of n)")
    return out, md


def _trlb_plan_all(a: argparse.Namespace) -> list[dict]:
    """Plan every selected pair; one row each (partial results saved as they come)."""
    ds = {float(x) for x in a.densities.split(",")} if a.densities else None
    ns = set(_ns(a.ns)) if a.ns else None
    todo = [(d, n, f) for d, n, f in trlb_pairs(a.instances, a.pairs)
            if (ds is None or d in ds) and (ns is None or n in ns)]
    rows: list[dict] = []
    seen: dict[tuple[float, int], int] = {}
    for k, (d, n, files) in enumerate(todo):
        seen[(d, n)] = seen.get((d, n), 0) + 1
        r = _trlb_row(d, n, files, a, process=seen[(d, n)] <= a.process_sample)
        rows.append(r)
        if a.progress:
            verdict = "ok" if r["solved"] else "refused" if r["refused"] else "unsolved"
            print(f"\r{k + 1}/{len(todo)} D={d:g} n={n}: {verdict} {r['time_s']:.2f} s   ",
                  end="", file=sys.stderr, flush=True)
        if a.json:
            a.json.parent.mkdir(parents=True, exist_ok=True)
            a.json.with_suffix(".partial.json").write_text(json.dumps({"rows": rows}))
    if a.progress:
        print(file=sys.stderr)
    return rows


def _trlb_peer_rows(a: argparse.Namespace) -> tuple[list[dict], list]:
    """TRLB's runs from the ``--peer`` files (a later file's row for the same setting and pair wins), judged."""
    keyed: dict[tuple, dict] = {}
    meta = []
    for f in a.peer or []:
        peer = json.loads(f.read_text())
        meta.append(peer.get("meta"))
        for r in peer["rows"]:
            keyed[(r["setting"], r["density"], r["n"], tuple(r["pair"]))] = r
    rows = list(keyed.values())
    if rows and a.instances.is_dir():
        _trlb_peer_checks(rows, a)
    return rows, meta


def _trlb_peer_lines(groups: dict[str, list[dict]], max_n: int) -> list[str]:
    """Lines on the peers' plans: how many the validator accepts, and physics against the validator."""
    lines = []
    for m in [m for m in groups if m != "lgmcts"]:
        mine = [r for r in groups[m] if "valid" in r]
        lines.append(f"{m}: {sum(r['valid'] for r in mine)} of {len(mine)} plans accepted by the validator "
                     "(a rejected plan counts as unsolved)")
    phys = [r for m, g in groups.items() if m != "lgmcts" for r in g if "physics" in r]
    if phys:
        agree = sum(r["physics"] == r["valid"] for r in phys)
        cells = sorted({(r["density"], r["n"]) for r in phys})
        lines.append(f"MuJoCo replay of {len(phys)} TRLB plans (preprocessing setting, n <= {max_n}, "
                     f"cells {', '.join(f'{d:g}/{n}' for d, n in cells)}): "
                     f"{sum(r['physics'] for r in phys)} succeed, {sum(r['valid'] for r in phys)} valid; "
                     f"physics and validator agree on {agree} of {len(phys)}")
    return lines


def cmd_trlb(a: argparse.Namespace) -> dict:
    rows = json.loads(a.results.read_text())["results"]["rows"] if a.results else _trlb_plan_all(a)
    groups = {"lgmcts": rows}
    peer_rows, peer_meta = _trlb_peer_rows(a)
    for r in peer_rows:
        groups.setdefault(f"TRLB {r['setting']}", []).append(r)
    summary, md = _trlb_table(groups)
    print("\n".join(md))
    for r in rows:
        if r.get("refused"):
            print(f"proved impossible D={r['density']:g} n={r['n']} {r['pair']}: {r['refused']} ({r['time_s']:.3f} s)")
    extra = _trlb_peer_lines(groups, a.peer_physics_max_n)
    print("\n".join(extra))
    md += extra
    if a.markdown:
        a.markdown.parent.mkdir(parents=True, exist_ok=True)
        a.markdown.write_text("\n".join(md) + "\n")
    return {"rows": rows, "summary": summary, "peer_meta": peer_meta or None, "peer_rows": peer_rows}


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
    tr = sub.add_parser("trlb")
    tr.add_argument("--instances", type=Path, default=Path("TRLB/disk_experiments/arrangements"),
                    help="TRLB's disk_experiments/arrangements folder (git clone https://github.com/arc-l/TRLB)")
    tr.add_argument("--pairs", type=int, default=5, help="start/goal pairs per cell (files 2k and 2k+1)")
    tr.add_argument("--densities", help="only these densities, e.g. 0.4,0.6")
    tr.add_argument("--ns", help="only these object counts: a list and/or ranges (50-200)")
    tr.add_argument("--time-limit", type=float, default=30.0, help="planning budget per case (s)")
    tr.add_argument("--seed", type=int, default=0)
    tr.add_argument("--process-sample", type=int, default=1,
                    help="per cell, time this many cases also as a whole 'lgmcts plan' process")
    tr.add_argument("--peer", type=Path, action="append",
                    help="TRLB's own runs on the same pairs (JSON with 'rows'); may be repeated")
    tr.add_argument("--peer-physics", type=int, default=0,
                    help="replay this many of TRLB's plans (preprocessing setting) in MuJoCo")
    tr.add_argument("--peer-physics-max-n", type=int, default=20, help="only plans of at most this many discs")
    tr.add_argument("--results", type=Path, help="summarise the rows of an earlier --json instead of planning")
    tr.add_argument("--markdown", type=Path, help="also write the tables here")
    for p in (r, lb, mem, tr):
        p.add_argument("--max-iter", type=int, default=10_000)
        p.add_argument("--json", type=Path, help="also write the results here")
        p.add_argument("--progress", action="store_true")
    a = ap.parse_args()
    t0 = time.perf_counter()
    res = {"random": cmd_random, "labbe": cmd_labbe, "memory": cmd_memory, "trlb": cmd_trlb}[a.cmd](a)
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
