"""Measure the simulator on seeded random cases: executed-plan success, time
per action, footprint IoU of perception, and plan-on-observed success.

Run ``python -m lgmcts.sim.evaluate --seeds 0-49`` (add ``--observe`` for the
perception loop, ``--tasks suite.jsonl`` for benchmark tasks written by
``lgmcts bench-generate``). The figures in ``docs/sim.md`` come from this script.
"""

from __future__ import annotations

import argparse
import platform
import signal
import statistics
import sys
import time
from datetime import UTC, datetime

import numpy as np


def _seeds(text: str) -> list[int]:
    out: list[int] = []
    for part in text.split(","):
        if "-" in part:
            a, b = part.split("-")
            out.extend(range(int(a), int(b) + 1))
        else:
            out.append(int(part))
    return out


class _Timeout(Exception):
    pass


def _alarm(signum: int, frame: object) -> None:
    raise _Timeout()


def main(argv: list[str] | None = None) -> int:
    """Command-line entry point; prints a summary and returns 0."""
    from .. import plan as run_plan
    from ..casegen import random_case
    from ..formats import load_goals, load_scene
    from . import execute_plan, footprint_iou, observe

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--seeds", default="0-19", help="seeds of lgmcts.casegen.random_case, e.g. 0-49 or 1,2,5")
    ap.add_argument("--method", default="lgmcts")
    ap.add_argument("--observe", action="store_true", help="also observe each scene, plan on it and execute")
    ap.add_argument("--no-example", action="store_true", help="leave out examples/tabletop.json")
    ap.add_argument(
        "--tasks",
        default=None,
        help="a suite file (JSON Lines, from `lgmcts bench-generate`): run its first --n tasks with their "
        "ground-truth goals instead of random cases",
    )
    ap.add_argument(
        "--n",
        type=int,
        default=20,
        help="number of suite tasks (with --tasks), or of configurations per N (with --labbe)",
    )
    ap.add_argument(
        "--labbe",
        default=None,
        help="use --n Labbé protocol configurations (lgmcts.casegen.labbe_protocol_case, discs that may touch) "
        "for each N in this list, e.g. 10,25, instead of random cases",
    )
    ap.add_argument("--dense", action="store_true", help="the dense variant of the random cases (packed clutter)")
    ap.add_argument("--case-timeout", type=float, default=20.0, help="skip a seed whose case takes longer to build (s)")
    args = ap.parse_args(argv)

    cases: list = []
    if args.tasks is not None:
        from ..bench.tasks import read_suite
        from ..errors import InputError

        try:
            tasks = read_suite(args.tasks, limit=args.n)
        except InputError as exc:
            print(exc, file=sys.stderr)
            return 2
        for t in tasks:
            cases.append((f"{t.id} ({t.category})", t.scene_spec(), t.goal_spec()))
        args.no_example, args.seeds = True, ""
    if args.labbe is not None:
        from ..casegen import labbe_protocol_case

        for n_disc in _seeds(args.labbe):
            for k in range(args.n):
                c = labbe_protocol_case(n_disc, 1000 * n_disc + k)
                cases.append((f"labbe N={n_disc} #{k}", c.scene, c.goals))
        args.no_example, args.seeds = True, ""
    if not args.no_example:
        from pathlib import Path

        root = Path(__file__).resolve().parents[2]
        cases.append(("example", load_scene(root / "examples/tabletop.json"), load_goals(root / "examples/goals.json")))
    skipped = []
    signal.signal(signal.SIGALRM, _alarm)
    for s in _seeds(args.seeds) if args.seeds else []:
        signal.setitimer(signal.ITIMER_REAL, args.case_timeout)
        try:
            c = random_case(s, dense=args.dense)
        except _Timeout:
            skipped.append(s)
            continue
        finally:
            signal.setitimer(signal.ITIMER_REAL, 0)
        cases.append((f"seed {s}", c.scene, c.goals))

    planned = executed = 0
    per_action: dict[int, list[float]] = {}
    failures = []
    ious: list[float] = []
    obs_planned = obs_ok = 0
    obs_fail = []
    for name, scene, goals in cases:
        plan = run_plan(scene, goals, method=args.method, seed=0)
        if plan.solved:
            planned += 1
            t0 = time.perf_counter()
            res = execute_plan(scene, plan, goals)
            dt = time.perf_counter() - t0
            if plan.actions:
                per_action.setdefault(len(scene.objects), []).append(dt / len(plan.actions))
            if res.success:
                executed += 1
            else:
                failures.append((name, res.reasons[:3]))
        if args.observe:
            seen = observe(scene)
            ious.extend(footprint_iou(scene, seen).values())
            op = run_plan(seen, goals, method=args.method, seed=0)
            if op.solved:
                obs_planned += 1
                r = execute_plan(scene, op, goals, plan_scene=seen)
                obs_ok += r.success
                if not r.success:
                    obs_fail.append((name, r.reasons[:3]))
        print(
            f"{name}: {len(scene.objects)} objects, planned {plan.solved}, {len(plan.actions)} actions",
            file=sys.stderr,
            flush=True,
        )

    all_t = [x for v in per_action.values() for x in v]
    print(
        f"date: {datetime.now(UTC):%Y-%m-%d %H:%M} UTC; machine: {platform.node()} "
        f"({platform.processor() or platform.machine()})"
    )
    print(f"cases: {len(cases)} (skipped seeds whose case did not build in {args.case_timeout:.0f} s: {skipped})")
    print(f"planned ({args.method}): {planned}; executed successfully: {executed}/{planned}")
    for name, why in failures:
        print(f"  failed {name}: {why}")
    if all_t:
        print(
            f"wall time per action: median {statistics.median(all_t):.3f} s, p95 {np.percentile(all_t, 95):.3f} "
            f"s, max {max(all_t):.3f} s"
        )
        for n in sorted(per_action):
            print(
                f"  {n:2d} objects: median {statistics.median(per_action[n]):.3f} s/action over "
                f"{len(per_action[n])} plans"
            )
    if args.observe:
        print(
            f"footprint IoU over {len(ious)} objects: mean {np.mean(ious):.4f}, min {np.min(ious):.4f}, p5 "
            f"{np.percentile(ious, 5):.4f}"
        )
        print(
            f"plan on observed scene: planned {obs_planned}/{len(cases)}, executed successfully {obs_ok}/{obs_planned}"
        )
        for name, why in obs_fail:
            print(f"  failed {name}: {why}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
