"""Benchmark: goals with a region, size and facing on seeded random cases.

Each case comes from :func:`lgmcts.casegen.random_case` (its generator knows
nothing of the parameters). Every line, circle, rectangle and tower goal of
the case then gets parameters drawn at random from the whole value space,
seeded by the case: a region (one of the nine cells, a row or a column) with
probability 0.7, a size (small / medium / large) with probability 0.5 (not
for towers), a facing (a compass name or an angle) with probability 0.5, and
at least one of them. The case is planned with and without the parameters
(same seed and budget), every plan reported solved is checked by the
validator, and the rows say whether the parameters fit at all by the format's
own definition (the size bands do not collapse).

Example (the figures in docs/benchmarks.md come from this)::

    python benchmarks/params.py --n 200 --max-iter 3000
"""

from __future__ import annotations

import argparse
import json
import math
import platform
import sys
import time

import numpy as np

from lgmcts import check, plan
from lgmcts.casegen import random_case
from lgmcts.formats import parse_goals, pattern_format, to_dict
from lgmcts.params import COLUMNS, HEADINGS, ROWS, resolve, size_range, sized_pattern
from lgmcts.scene import Scene

REGIONS = [f"{r} {c}" for r in ROWS for c in COLUMNS] + list(ROWS) + ["left", "right"]


def with_params(goals: dict, rng: np.random.Generator) -> dict:
    out = []
    for g in goals["goals"]:
        g = dict(g)
        fmt = pattern_format(g["pattern"])
        if fmt is not None and fmt.size:  # the patterns whose goals take a size
            while True:
                if rng.random() < 0.7:
                    g["region"] = str(rng.choice(REGIONS))
                if g["pattern"] != "tower" and rng.random() < 0.5:
                    g["size"] = str(rng.choice(["small", "medium", "large"]))
                if rng.random() < 0.5:
                    g["facing"] = (
                        str(rng.choice(list(HEADINGS))) if rng.random() < 0.5 else float(rng.uniform(-math.pi, math.pi))
                    )
                if any(k in g for k in ("region", "size", "facing")):
                    break
        out.append(g)
    return {"goals": out}


def fits(scene: Scene, goals: dict) -> bool:
    """Whether no goal's size bands collapse (the room holds the tightest arrangement)."""
    for g in goals["goals"]:
        if sized_pattern(g["pattern"]) is None:
            continue
        idx = [scene.index[i] for i in g["objects"]]
        gp = resolve(g, scene.bounds, scene.radii[idx])
        if gp.room is None:
            continue
        h = gp.heading if g["pattern"] == "line" else None
        lo, hi = size_range(g["pattern"], len(idx), float(scene.radii[idx].max()), gp.room, "medium", h)
        if hi <= lo:
            return False
    return True


def run(n: int, max_iter: int, offset: int) -> list[dict]:
    rows = []
    for seed in range(offset, offset + n):
        c = random_case(seed)
        base = to_dict(c.goals)
        params = with_params(base, np.random.default_rng(10_000 + seed))
        sc = Scene.from_spec(c.scene)
        parse_goals(params).check_against(c.scene)
        row = {"case": seed, "fits": fits(sc, params), "goals": params}
        for tag, gs in (("plain", base), ("params", params)):
            t = time.perf_counter()
            p = plan(c.scene, gs, seed=seed, max_iter=max_iter)
            dt = time.perf_counter() - t
            valid = bool(check(c.scene, gs, p).valid) if p.solved else False
            row[tag] = {"solved": bool(p.solved), "valid": valid, "time_s": round(dt, 4), "actions": len(p.actions)}
        rows.append(row)
        print(json.dumps({k: row[k] for k in ("case", "fits", "plain", "params")}), file=sys.stderr)
    return rows


def summary(rows: list[dict]) -> dict:
    def stats(sel: list[dict], tag: str) -> dict:
        solved = [r[tag] for r in sel if r[tag]["solved"]]
        return {
            "cases": len(sel),
            "solved": len(solved),
            "solved_valid": sum(s["valid"] for s in solved),
            "median_time_s": float(np.median([s["time_s"] for s in solved])) if solved else None,
            "median_actions": float(np.median([s["actions"] for s in solved])) if solved else None,
        }

    fit = [r for r in rows if r["fits"]]
    return {
        "all": {"plain": stats(rows, "plain"), "params": stats(rows, "params")},
        "fitting": {"plain": stats(fit, "plain"), "params": stats(fit, "params")},
        "python": platform.python_version(),
    }


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--n", type=int, default=200)
    ap.add_argument("--max-iter", type=int, default=3000)
    ap.add_argument("--offset", type=int, default=0, help="first case seed")
    ap.add_argument("--rows", help="write every row (JSON lines) here")
    a = ap.parse_args(argv)
    rows = run(a.n, a.max_iter, a.offset)
    if a.rows:
        with open(a.rows, "w") as fh:
            for r in rows:
                fh.write(json.dumps(r) + "\n")
    print(json.dumps(summary(rows), indent=2))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
