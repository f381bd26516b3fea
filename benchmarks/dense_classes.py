"""Which arrangement classes the corner search reaches on TRLB's undecided dense pairs.

Example (the figures in docs/benchmarks.md, "What the searches show at n = 6 and 9", come from these, the first two
from the search before its depth term, as ``--depth 0`` runs it)::

    python benchmarks/dense_classes.py --instances PATH/TRLB/disk_experiments/arrangements --ns 6 --states 8000
    python benchmarks/dense_classes.py --instances PATH/TRLB/disk_experiments/arrangements --ns 9 --states 3000
    python benchmarks/dense_classes.py --instances PATH/TRLB/disk_experiments/arrangements --ns 6,7,9 --depth 2

For each start/goal pair (files ``2k`` and ``2k+1`` of the cell, as ``planner.py trlb`` pairs them) it runs the
corner search of :mod:`lgmcts.planner.dense` forwards from the start and backwards from the goals, each for
``--states`` expanded states with no time limit, and labels every table state either reached:

* ``ring``: the disc nearest the middle of the square if it is nearer than ``--inner`` m (else ``-``), and the
  cyclic order of the other discs about that disc's centre (about the middle where there is none), read from
  the lowest number;
* ``grid`` (square counts only, k x k discs): the discs of each row of a k x k grid, rows by rank of y and
  discs in a row by rank of x.

Discs are numbered as in TRLB's files, from 0. It prints, per pair and direction, the states reached and how
many carry each label, and the labels the two directions share. A label that never changes along either
search, and differs between the two, is evidence (not a proof) that no plan joins start and goal: the corner
search moves discs only to corners of their free space, and a search is not exhaustive.
"""

from __future__ import annotations

import argparse
import math
import sys
import time
from collections import Counter
from pathlib import Path

import numpy as np

from lgmcts.casegen import trlb_case, trlb_pairs
from lgmcts.errors import InputError
from lgmcts.planner import dense
from lgmcts.planner.problem import Problem
from lgmcts.scene import Scene


def ring_label(pos: np.ndarray, middle: np.ndarray, inner: float) -> str:
    """The disc nearest ``middle`` when nearer than ``inner`` (else ``-``), then the others' cyclic order about it."""
    r = np.hypot(*(pos - middle).T)
    k = int(np.argmin(r))
    centre = pos[k] if r[k] < inner else middle
    rest = [j for j in range(len(pos)) if j != k or r[k] >= inner]
    ang = np.arctan2(pos[rest, 1] - centre[1], pos[rest, 0] - centre[0])
    order = [rest[j] for j in np.argsort(ang)]
    m = order.index(min(order))
    head = str(k) if r[k] < inner else "-"
    return head + "|" + " ".join(map(str, order[m:] + order[:m]))


def grid_label(pos: np.ndarray) -> str | None:
    """The discs of each row of a k x k grid (rows by rank of y, discs by rank of x), or ``None`` if n is not k^2."""
    k = math.isqrt(len(pos))
    if k * k != len(pos):
        return None
    by_y = np.argsort(pos[:, 1], kind="stable")
    rows = [sorted(by_y[k * i:k * i + k].tolist(), key=lambda j: pos[j, 0]) for i in range(k)]
    return "|".join(" ".join(map(str, row)) for row in rows)


def pair_arguments(ap: argparse.ArgumentParser, ns: str) -> None:
    """The arguments that choose TRLB's pairs (read by :func:`dense_pairs`); ``ns``: the default object counts."""
    ap.add_argument("--instances", required=True, help="TRLB's disk_experiments/arrangements folder")
    ap.add_argument("--density", type=float, default=0.6)
    ap.add_argument("--ns", default=ns, help="object counts, e.g. 6,9")
    ap.add_argument("--pairs", type=int, default=5)


def pairs_said(a: argparse.Namespace) -> list[tuple[float, int, str, Problem]] | None:
    """The pairs the arguments of :func:`pair_arguments` choose, or None after a one-line error on stderr."""
    try:
        return dense_pairs(a.instances, a.density, a.ns, a.pairs)
    except (ValueError, InputError) as e:
        print(f"error: {e}", file=sys.stderr)
        return None


def dense_pairs(instances: str, density: float, ns_said: str, pairs: int
                ) -> list[tuple[float, int, str, Problem]]:
    """TRLB's start/goal pairs at ``density`` for the object counts of ``ns_said`` ("6,9"): density, count, the
    pair's file numbers ("2/3") and its planning problem. Raises ValueError (InputError) on what it cannot read,
    or where no pair fits."""
    ns = {int(x) for x in ns_said.split(",") if x.strip()}
    todo = [(d, n, f) for d, n, f in trlb_pairs(instances, pairs) if d == density and n in ns]
    if not todo:
        raise ValueError(f"no pairs at D={density} for n in {sorted(ns)} under {instances}")
    out = []
    for d, n, files in todo:
        case = trlb_case(*files)
        pair = "/".join(Path(f).name.split("_")[0] for f in files)
        out.append((d, n, pair, Problem.build(Scene.from_spec(case.scene), case.goals)))
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    pair_arguments(ap, "6")
    ap.add_argument("--states", type=int, default=3000, help="states each search expands")
    ap.add_argument("--weight", type=float, default=dense.WEIGHT)
    ap.add_argument("--depth", type=float, default=dense.DEPTH,
                    help="weight of the depth term in the goal count (0: the search before it had one)")
    ap.add_argument("--inner", type=float, default=0.2, help="how near the middle a disc counts as inside (m)")
    ap.add_argument("--plan", action="store_true",
                    help="also run the planner's corner search (its budget, no time limit) and label its plan's states")
    a = ap.parse_args(argv)
    todo = pairs_said(a)
    if todo is None:
        return 2
    for d, n, pair, problem in todo:
        seen: dict[str, list[Counter[str]]] = {"ring": [], "grid": []}
        for reverse in (False, True):
            t = dense._Discs(problem, reverse=reverse)
            middle = (t.lo[0] + t.hi[0]) / 2
            search = dense._Search(t, a.weight, depth=a.depth)
            t0 = time.process_time()
            plan, expanded = search.run(a.states, None)
            ring: Counter[str] = Counter()
            grid: Counter[str] = Counter()
            for pos, *_ in search.states:
                ring[ring_label(pos, middle, a.inner)] += 1
                g = grid_label(pos)
                if g is not None:
                    grid[g] += 1
            seen["ring"].append(ring)
            seen["grid"].append(grid)
            where = "backwards" if reverse else "forwards"
            print(f"D={d} n={n} files {pair} {where}: {expanded} expanded, {len(search.states)} states, "
                  f"plan {'found' if plan is not None else 'none'}, {time.process_time() - t0:.1f} s CPU")
            for kind, labels in (("ring", ring), ("grid", grid)):
                if labels:
                    top = ", ".join(f"{label} x {count}" for label, count in labels.most_common(3))
                    more = f" (+{len(labels) - 3} more)" if len(labels) > 3 else ""
                    print(f"    {kind}: {len(labels)} labels: {top}{more}")
        shared = {kind: len(set(v[0]) & set(v[1])) for kind, v in seen.items() if v[0]}
        print("    labels both directions reach: " + ", ".join(f"{k} {v}" for k, v in shared.items()))
        if a.plan:
            print("    " + plan_labels(problem, a.inner))
    return 0


def plan_labels(problem: Problem, inner: float) -> str:
    """The labels the states of the corner search's plan pass through (each label once, in order), or why none."""
    t = dense._Discs(problem)
    middle = (t.lo[0] + t.hi[0]) / 2
    actions, expanded = dense.search(problem, dense.budget(t.n), None)
    if actions is None:
        return f"corner search: no plan in {expanded} states"
    pos = t.start.copy()
    states = [pos.copy()]
    index = {o: i for i, o in enumerate(t.ids)}
    for x in actions:
        pos[index[x.object]] = x.to[:2]
        states.append(pos.copy())
    out = [f"corner search: plan of {len(actions)} moves after {expanded} states"]
    for kind, label in (("ring", lambda q: ring_label(q, middle, inner)), ("grid", grid_label)):
        path: list[str] = []
        for q in states:
            lab = label(q)
            if lab is not None and (not path or path[-1] != lab):
                path.append(lab)
        if path:
            out.append(f"{kind}: {len(set(path))} labels along it: " + ", ".join(path))
        else:
            out.append(f"{kind}: none")
    return "; ".join(out)


if __name__ == "__main__":
    raise SystemExit(main())
