"""Random walks over every table the validator accepts, on TRLB's dense pairs: do the ring labels ever change?

Example (the figures in docs/benchmarks.md, "TRLB's instances", the first paragraph)::

    python benchmarks/dense_walks.py --instances PATH/TRLB/disk_experiments/arrangements --ns 6 --moves 600000

For each start/goal pair (files ``2k`` and ``2k+1`` of the cell, as ``planner.py trlb`` pairs them) it walks from
the start, and again from the goals, moving one disc at a time, the disc chosen at random, to the first free place
among ``--tries`` random ones (half anywhere in the box its centre may take, half within one contact distance of
where it stands). Free is what the validator allows, the widest model of actions the planner's proofs use
(:mod:`lgmcts.confinement`): the disc inside the workspace to ``EDGE_TOL``, and no closer to another disc than the
contact distance, the centre distance below which two discs overlap by more than ``OVERLAP_AREA``. Every free
place of the moved disc can be drawn, so a walk is not limited to the corners the corner search
(:mod:`lgmcts.planner.dense`) tries; it is still a sample, not a proof.

Every ``--every`` moves it labels the table as ``dense_classes.py`` does (``ring``: the disc nearest the middle,
if nearer than ``--inner`` m, and the cyclic order of the others about it), and prints, per pair and walk: the
moves made, the labels seen (the most common three), whether the other end's label was seen, how far each disc
went from where the walk began (mm), and how many moves took a disc one contact distance or more from where it
stood (at n = 6 none can: seven discs do not fit, so such a move would leave room for a seventh); then how many
labels the walks from both ends saw.
"""

from __future__ import annotations

import argparse
import time
from collections import Counter

import numpy as np
from dense_classes import pair_arguments, pairs_said, ring_label  # this folder: run as python benchmarks/...

from lgmcts.confinement import contact_distance
from lgmcts.planner.problem import Problem

#: The validator's allowance (m) of a footprint beyond the workspace edge (as :mod:`lgmcts.confinement`).
EDGE_TOL = 1e-3


def walk(problem: Problem, reverse: bool, moves: int, tries: int, every: int, inner: float, seed: int
         ) -> tuple[Counter[str], np.ndarray, int, int, str, str]:
    """One walk: the labels seen, each disc's farthest distance (m) from where it began, the moves made, the long
    moves among them, and the labels of the start and the goals."""
    sc = problem.scene
    n = sc.n
    r = np.asarray(sc.discs, dtype=float)
    start = np.array(sc.initial.poses[:, :2], dtype=float)
    goal = start.copy()
    for o, pose in problem.fixed.items():
        goal[o] = pose[:2]
    xmin, xmax, ymin, ymax = sc.bounds
    lo = np.stack([xmin + r - EDGE_TOL, ymin + r - EDGE_TOL], axis=1)
    hi = np.stack([xmax - r + EDGE_TOL, ymax - r + EDGE_TOL], axis=1)
    d = np.array([[contact_distance(float(a), float(b)) for b in r] for a in r])
    middle = np.array([(xmin + xmax) / 2, (ymin + ymax) / 2])
    ends = ring_label(start, middle, inner), ring_label(goal, middle, inner)
    pos = (goal if reverse else start).copy()
    begin = pos.copy()
    rng = np.random.default_rng(seed)
    labels: Counter[str] = Counter()
    far = np.zeros(n)
    made = long = 0
    half = tries // 2
    for t in range(moves):
        i = int(rng.integers(n))
        c = np.empty((tries, 2))
        c[:half] = rng.uniform(lo[i], hi[i], (half, 2))
        ang = rng.uniform(0, 2 * np.pi, tries - half)
        rad = d[i].max() * np.sqrt(rng.uniform(0, 1, tries - half))
        c[half:] = pos[i] + np.stack([rad * np.cos(ang), rad * np.sin(ang)], axis=1)
        ok = (c >= lo[i]).all(1) & (c <= hi[i]).all(1)
        others = np.arange(n) != i
        gap = np.hypot(c[:, None, 0] - pos[None, others, 0], c[:, None, 1] - pos[None, others, 1])
        ok &= (gap >= d[i, others]).all(1)
        free = np.flatnonzero(ok)
        if len(free):
            p = c[free[0]]
            long += bool(np.hypot(*(p - pos[i])) >= d[i].max())
            pos[i] = p
            made += 1
        if t % every == 0:
            labels[ring_label(pos, middle, inner)] += 1
            far = np.maximum(far, np.hypot(*(pos - begin).T))
    return labels, far, made, long, ends[0], ends[1]


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    pair_arguments(ap, "6")
    ap.add_argument("--moves", type=int, default=200_000, help="moves tried in each walk")
    ap.add_argument("--tries", type=int, default=64, help="random places drawn for each move")
    ap.add_argument("--every", type=int, default=50, help="label the table every so many moves")
    ap.add_argument("--inner", type=float, default=0.2, help="how near the middle a disc counts as inside (m)")
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args(argv)
    todo = pairs_said(a)
    if todo is None:
        return 2
    for d, n, pair, problem in todo:
        seen: list[set[str]] = []
        for reverse in (False, True):
            t0 = time.process_time()
            labels, far, made, long, at_start, at_goal = walk(problem, reverse, a.moves, a.tries, a.every, a.inner,
                                                              a.seed)
            other = at_start if reverse else at_goal
            top = ", ".join(f"{label} x {count}" for label, count in labels.most_common(3))
            more = f" (+{len(labels) - 3} more)" if len(labels) > 3 else ""
            print(f"D={d} n={n} files {pair} from the {'goals' if reverse else 'start'}: {made}/{a.moves} moves "
                  f"made, {long} of them a contact distance or longer, {time.process_time() - t0:.1f} s CPU; "
                  f"{len(labels)} labels: {top}{more}; the other end's label {other} "
                  f"{'seen' if other in labels else 'never seen'}; farthest from the walk's start (mm): "
                  + " ".join(f"{x * 1000:.0f}" for x in far), flush=True)
            seen.append(set(labels))
        print(f"    labels both walks see: {len(seen[0] & seen[1])}", flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
