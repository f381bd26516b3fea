"""Time the validator on a long plan over a large scene.

    python benchmarks/validate_speed.py [--objects 400] [--actions 20000] [--runs 3]

A grid of boxes on a 4 m x 4 m workspace and a plan of random table
placements (many of them illegal: the validator must judge every one);
prints the wall and CPU time of ``lgmcts.check`` per run and the number of
reasons it gives.
"""

from __future__ import annotations

import argparse
import time

import numpy as np


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--objects", type=int, default=400)
    ap.add_argument("--actions", type=int, default=20000)
    ap.add_argument("--runs", type=int, default=3)
    args = ap.parse_args()
    from lgmcts import check

    n = args.objects
    objs = [{"id": k + 1, "name": "block", "color": "red", "shape": {"type": "box", "size": [0.04, 0.04, 0.04]},
             "pose": [-1.9 + 0.09 * (k % 40), -1.9 + 0.09 * (k // 40), 0.0], "on": None} for k in range(n)]
    scene = {"workspace": {"x": [-2, 2], "y": [-2, 2]}, "objects": objs}
    rng = np.random.default_rng(0)
    acts = [
        {
            "object": int(rng.integers(n)) + 1,
            "to": [float(rng.uniform(-1.9, 1.9)), float(rng.uniform(0.5, 1.9)), 0.0],
            "on": None,
        }
        for _ in range(args.actions)
    ]
    plan = {"solved": True, "actions": acts}
    goals = {"goals": [{"pattern": "line", "objects": [1, 2, 3]}]}
    for _ in range(args.runs):
        w, c = time.perf_counter(), time.process_time()
        verdict = check(scene, goals, plan)
        print(
            f"{args.actions} actions over {n} objects: wall {time.perf_counter() - w:.2f} s, "
            f"CPU {time.process_time() - c:.2f} s, {len(verdict.reasons)} reasons"
        )


if __name__ == "__main__":
    main()
