"""The UR5e arm on the ELGR-style suite (or the StructFormer-style one), beside the floating suction cup.

Usage::

    python benchmarks/arm.py run --n 400 [--start 0] [--out out/arm.jsonl] [--suite elgr] [--plain-arm] [--budget S]
    python benchmarks/arm.py summary [--out out/arm.jsonl] [--ik 1000]

``run`` generates the ELGR-style suite (``lgmcts bench-generate --suite elgr``,
seed 0; ``--suite structformer`` for the other) and, for tasks ``start`` .. ``start + n - 1`` not already in the
results file (so a run can be split into short pieces and resumed), plans
with the ground-truth goals twice (``lgmcts.plan`` without a robot and with
``robot="ur5e"``), judges each plan with the validator (with ``robot`` for the
arm's plan: every pick and place within reach), executes the plain plan with
the floating cup and the arm's plan with the arm, and appends one JSON line
per task. ``--plain-arm`` also executes the plain plan with the arm;
``--budget`` stops starting tasks after that many seconds (short runs on a
shared machine; rerun to go on).

``summary`` prints SR_p, SR_ep, simulated seconds per action, wall time per
pick-and-place and the failure classes, and with ``--ik N`` the inverse
kinematics accuracy and time on N random reachable top-down poses.
"""

from __future__ import annotations

import argparse
import json
import platform
import statistics
import sys
import time
from collections import Counter
from datetime import UTC, datetime
from pathlib import Path

CLASSES = ("out of reach", "joint limit", "arm collision", "dropped in transfer")


def _classes(ex: dict) -> list[str]:
    """The failure classes named in an execution's steps and reasons."""
    text = " | ".join([s["message"] for s in ex["steps"] if not s["ok"]] + list(ex["reasons"]))
    out = [c for c in CLASSES if c in text]
    if not out and not ex["success"]:
        out.append("placement or goal (no arm failure)")
    return out


def _execute(scene, plan, goals, robot: str | None) -> dict:
    from lgmcts.sim import execute_plan

    t0 = time.perf_counter()
    ex = execute_plan(scene, plan, goals, robot=robot)
    wall = time.perf_counter() - t0
    n = max(1, len(plan.actions))
    rec = {
        "success": bool(ex.success),
        "reasons": list(ex.reasons)[:6],
        "steps": [s.to_dict() for s in ex.steps],
        "actions": len(plan.actions),
        "wall_s": round(wall, 4),
        "wall_per_action_s": round(wall / n, 4),
        "sim_s": round(ex.sim_time, 4),
        "sim_per_action_s": round(ex.sim_time / n, 4),
    }
    rec["classes"] = _classes(rec)
    return rec


def run(args: argparse.Namespace) -> None:
    import lgmcts
    from lgmcts.bench.suites import iter_generate
    from lgmcts.formats import parse_goals, parse_scene

    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    done = set()
    if out.exists():
        done = {json.loads(line)["id"] for line in out.read_text().splitlines() if line.strip()}
    tasks = list(iter_generate(args.suite, n=args.start + args.n, seed=0))[args.start :]
    t_run = time.perf_counter()
    for t in tasks:
        if t.id in done:
            continue
        if args.budget and time.perf_counter() - t_run > args.budget:
            print(f"stopping: the {args.budget:.0f} s budget is spent", file=sys.stderr)
            break
        scene, gt = parse_scene(t.scene), parse_goals(t.goals)
        rec: dict = {"id": t.id, "category": t.category, "objects": len(scene.objects)}
        for key, robot in (("cup", None), ("arm", "ur5e")):
            t0 = time.perf_counter()
            plan = lgmcts.plan(scene, gt, seed=t.seed, robot=robot)
            p_wall = time.perf_counter() - t0
            verdict = lgmcts.check(scene, gt, plan, robot=robot)
            valid = bool(plan.solved and verdict.valid)
            r = {
                "solved": bool(plan.solved),
                "valid": valid,
                "plan_s": round(p_wall, 3),
                "actions": len(plan.actions),
                "reasons": list(verdict.reasons)[:3],
            }
            if valid:
                r["exec"] = _execute(scene, plan, gt, robot)
                if key == "cup" and args.plain_arm:
                    r["exec_arm"] = _execute(scene, plan, gt, "ur5e")
            rec[key] = r
        with out.open("a") as fh:
            fh.write(json.dumps(rec) + "\n")
        arm = rec["arm"].get("exec", {})
        print(
            f"{t.id}: cup {rec['cup']['valid']}/{rec['cup'].get('exec', {}).get('success')}, "
            f"arm {rec['arm']['valid']}/{arm.get('success')} {arm.get('classes', '')}",
            file=sys.stderr,
            flush=True,
        )


def _pct(a: int, b: int) -> str:
    return f"{100 * a / b:.1f} % ({a}/{b})" if b else "-"


def summary(args: argparse.Namespace) -> None:
    by_id = {}
    for line in Path(args.out).read_text().splitlines():
        if line.strip():
            rec = json.loads(line)
            by_id[rec["id"]] = rec  # a task run twice counts once (the last run)
    recs = list(by_id.values())
    n = len(recs)
    suite = recs[0]["id"].split("-")[0] if recs else "?"
    print(
        f"date: {datetime.now(UTC):%Y-%m-%d %H:%M} UTC; machine: {platform.node()}, Python {platform.python_version()}"
    )
    print(f"tasks: {n} ({suite} suite, seed 0, ground-truth goals, lgmcts, seed = task seed)\n")
    print(
        "| executor | plans | SR_p | SR_ep | SR_ep / SR_p | sim s / action (median) "
        "| wall s / pick-and-place (median, p95) |"
    )
    print("|---|---|---|---|---|---|---|")
    rows = [("floating cup", "cup", "exec"), ("UR5e arm (plans with --robot ur5e)", "arm", "exec")]
    if any("exec_arm" in r["cup"] for r in recs):
        rows.append(("UR5e arm (plans without --robot)", "cup", "exec_arm"))
    classes: dict[str, Counter] = {}
    for label, key, ex_key in rows:
        valid = sum(r[key]["valid"] for r in recs)
        exs = [r[key][ex_key] for r in recs if ex_key in r[key]]
        ok = sum(e["success"] for e in exs)
        sim = [e["sim_per_action_s"] for e in exs if e["actions"]]
        wall = sorted(e["wall_per_action_s"] for e in exs if e["actions"])
        p95 = wall[min(len(wall) - 1, int(0.95 * len(wall)))] if wall else float("nan")
        ratio = f"{100 * ok / valid:.1f} %" if valid else "-"
        print(
            f"| {label} | {len(exs)} | {_pct(valid, n)} | {_pct(ok, n)} | {ratio} | "
            f"{statistics.median(sim) if sim else float('nan'):.2f} | "
            f"{statistics.median(wall) if wall else float('nan'):.3f}, {p95:.3f} |"
        )
        c: Counter = Counter()
        for e in exs:
            c.update(e["classes"])
        classes[label] = c
    print("\nFailure classes (executions whose steps or verdict name each; one execution may name several):\n")
    for label, c in classes.items():
        print(f"* {label}: " + (", ".join(f"{k} {v}" for k, v in c.most_common()) or "none"))
    unsolved = [r["id"] for r in recs if r["cup"]["valid"] and not r["arm"]["valid"]]
    print(f"\nTasks the floating cup's planner solves but not with --robot ur5e: {len(unsolved)} {unsolved[:10]}")
    for r in recs:
        e = r["arm"].get("exec")
        if e and not e["success"]:
            print(f"  arm failed {r['id']}: {e['reasons'][:2]}")
    if args.ik:
        from lgmcts.sim.arm import _benchmark_ik

        print("\nInverse kinematics:", json.dumps(_benchmark_ik(args.ik, 0)))


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    r = sub.add_parser("run")
    r.add_argument("--n", type=int, default=400)
    r.add_argument("--start", type=int, default=0)
    r.add_argument("--out", default="out/arm.jsonl")
    r.add_argument("--suite", default="elgr", help="elgr (default) or structformer")
    r.add_argument("--plain-arm", action="store_true", help="also execute the plain plans with the arm")
    r.add_argument(
        "--budget", type=float, default=0.0, help="stop starting tasks after this many seconds (0: no limit)"
    )
    s = sub.add_parser("summary")
    s.add_argument("--out", default="out/arm.jsonl")
    s.add_argument("--ik", type=int, default=0)
    a = ap.parse_args()
    run(a) if a.cmd == "run" else summary(a)


if __name__ == "__main__":
    main()
