"""Run the benchmark figures of docs/bench.md and print their tables.

Usage::

    python benchmarks/suite_figures.py [--out out/bench] [--workers N] [--quick]

Runs, one after the other (each resumable: rerun the script after an
interruption), the full ELGR-style suite (1,600 tasks) and StructFormer-style
suite (2,000 tasks) with lgmcts, greedy and pmcts, all with execution in
MuJoCo and the 10,000-iteration budget. ``--quick`` runs 5 tasks of each to
check the set-up. Prints every summary table with the command that made it.
"""

from __future__ import annotations

import argparse
import platform
import shlex
import subprocess
import sys
import time
from pathlib import Path

#: (suite, method, wall-clock cap per task in s or None), as reported in docs/bench.md.
RUNS = (
    ("elgr", "lgmcts", None),
    ("elgr", "greedy", None),
    ("elgr", "pmcts", 30),
    ("structformer", "lgmcts", None),
    ("structformer", "greedy", 30),
    ("structformer", "pmcts", 30),
)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default="out/bench", help="folder of the run folders")
    ap.add_argument("--workers", type=int, default=None, help="local processes per run (default: every core)")
    ap.add_argument("--quick", action="store_true", help="20 tasks per run")
    args = ap.parse_args()
    out = Path(args.out)
    print(
        f"machine: {platform.node()} ({platform.processor() or platform.machine()}), date "
        f"{time.strftime('%Y-%m-%d', time.gmtime())}\n"
    )
    for suite, method, cap in RUNS:
        n = 5 if args.quick else None
        folder = out / f"{suite}-{method}" if not args.quick else out / f"quick-{suite}-{method}"
        cmd = ["lgmcts", "bench", "--suite", suite, "--method", method, "-o", str(folder)]
        if n is not None:
            cmd[4:4] = ["--n", str(n)]
        if cap is not None:
            cmd += ["--time-limit", str(cap)]
        if args.workers is not None:
            cmd += ["--workers", str(args.workers)]
        t0 = time.time()
        res = subprocess.run([sys.executable, "-m", "lgmcts", *cmd[1:]], capture_output=True, text=True)
        if res.returncode != 0:
            print(f"`{shlex.join(cmd)}` failed: {res.stderr.strip()}")
            continue
        print(f"`{shlex.join(cmd)}` ({time.time() - t0:.0f} s wall)\n")
        print(res.stdout)


if __name__ == "__main__":
    main()
