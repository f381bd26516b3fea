"""How many table states each corner search needs on TRLB's dense pairs, alone and taking turns.

Example (the figures of docs/benchmarks.md, "The corner search: a depth term, turns from the start")::

    python benchmarks/dense_searches.py --instances PATH/TRLB/disk_experiments/arrangements --ns 7,8,10 \\
        --searches 2F0,2B0,3F0,3B0,4B0,2F1,2B1,3F1,3B2 --states 7500

For each start/goal pair (files ``2k`` and ``2k+1`` of a cell, as ``planner.py trlb`` pairs them) where the fast
attempt of :mod:`lgmcts.planner.sequence` gets stuck, it runs each search of ``--searches`` alone, with no time
limit, up to ``--states`` expanded states, and prints the states it expanded before its plan (or ``-``) and the
plan's moves; then :func:`lgmcts.planner.dense.search` itself, the searches taking turns as the planner runs them,
with the planner's budget. A search is named by its weight, its direction (``F`` forwards from the start, ``B``
backwards from the goals) and the weight of its depth term (``0``: the goal count alone, as before the term),
then optionally ``d`` and the weight of its distance term (``2F1d1``: weight 2 forwards, depth and distance
weights 1, the last search of :data:`lgmcts.planner.dense.MORE`).
"""

from __future__ import annotations

import argparse
import re
import sys
import time

from dense_classes import pair_arguments, pairs_said  # this folder: run as python benchmarks/dense_searches.py

from lgmcts.planner import dense
from lgmcts.planner.sequence import sequence_plan

_NAME = re.compile(r"^(\d+(?:\.\d+)?)([FB])(\d+(?:\.\d+)?)(?:d(\d+(?:\.\d+)?))?$")


def parse_searches(spec: str) -> list[tuple[str, float, bool, float, float]]:
    """``"2F1,3B2d1"`` -> ``[("2F1", 2.0, False, 1.0, 0.0), ("3B2d1", 3.0, True, 2.0, 1.0)]``; a bad name raises
    ValueError."""
    out = []
    for name in (x.strip() for x in spec.split(",") if x.strip()):
        m = _NAME.match(name)
        if m is None:
            raise ValueError(f"bad search name {name!r} (weight, F or B, depth weight, optionally d and a distance "
                             "weight: e.g. 2F1 or 2F1d1)")
        out.append((name, float(m.group(1)), m.group(2) == "B", float(m.group(3)), float(m.group(4) or 0.0)))
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    pair_arguments(ap, "10")
    ap.add_argument("--searches", default="2F1,2B1,3F1,3B2", help="searches to run alone, e.g. 2F0,3B2")
    ap.add_argument("--states", type=int, default=7500, help="states each search alone expands at most")
    a = ap.parse_args(argv)
    try:
        searches = parse_searches(a.searches)
    except ValueError as e:
        print(f"error: {e}", file=sys.stderr)
        return 2
    todo = pairs_said(a)
    if todo is None:
        return 2
    for d, n, pair, problem in todo:
        if sequence_plan(problem) is not None:
            print(f"D={d} n={n} files {pair}: planned by the fast attempt")
            continue
        cells = []
        for name, weight, backwards, depth, dist in searches:
            run = dense._Search(dense._Discs(problem, reverse=backwards), weight, depth=depth, dist=dist)
            t0 = time.process_time()
            plan, expanded = run.run(a.states, None)
            cpu = time.process_time() - t0
            cells.append(f"{name} {expanded if plan is not None else '-'}"
                         + (f" ({len(plan)} moves, {cpu:.2f} s)" if plan is not None else f" ({cpu:.2f} s)"))
        t0 = time.process_time()
        plan, expanded = dense.search(problem, dense.budget(n), None)
        cpu = time.process_time() - t0
        turns = f"{expanded} ({len(plan)} moves, {cpu:.2f} s)" if plan is not None else f"- after {expanded}"
        print(f"D={d} n={n} files {pair}: " + "; ".join(cells) + f"; in turns: {turns}", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
