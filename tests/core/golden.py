"""Golden plans: an action digest per (case, method, seed), kept in ``tests/data/golden_plans.json``.

A refactor that is meant to leave behaviour alone must leave every digest
unchanged; ``tests/core/test_golden.py`` checks that. A change that is meant
to change plans regenerates the file on purpose, with the explicit command::

    make golden                # = python tests/core/golden.py --write

and the diff of ``tests/data/golden_plans.json`` shows which plans moved.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import lgmcts
from lgmcts.bench import elgr, structformer
from lgmcts.casegen import labbe_case, random_case
from lgmcts.formats import parse_goals, parse_scene

GOLDEN = Path(__file__).resolve().parents[1] / "data" / "golden_plans.json"
MAX_ITER = 3000


def _random(seed: int) -> Callable[[], tuple[Any, Any]]:
    def make():
        c = random_case(seed)
        return c.scene, c.goals

    return make


def _labbe(n: int, seed: int) -> Callable[[], tuple[Any, Any]]:
    def make():
        c = labbe_case(n, seed)
        return c.scene, c.goals

    return make


def _suite(module, category: str, seed: int) -> Callable[[], tuple[Any, Any]]:
    def make():
        t = module.generate_task(category, seed)
        return parse_scene(t.scene), parse_goals(t.goals)

    return make


def cases() -> dict[str, Callable[[], tuple[Any, Any]]]:
    """Every golden case by name: random cases, Labbé discs and suite tasks."""
    out: dict[str, Callable[[], tuple[Any, Any]]] = {}
    for s in range(24):
        out[f"random-{s}"] = _random(s)
    for n, s in [(5, 0), (10, 0), (10, 1), (16, 0), (20, 0), (25, 0), (25, 1), (30, 0)]:
        out[f"labbe-{n}-{s}"] = _labbe(n, s)
    for i, cat in enumerate(elgr.CATEGORIES):
        out[f"elgr-{cat}-{i}"] = _suite(elgr, cat, 1000 + i)
    for i, cat in enumerate(structformer.CATEGORIES * 2):
        out[f"structformer-{cat}-{i}"] = _suite(structformer, cat, 2000 + i)
    return out


#: (case name prefix, methods, seeds): lgmcts everywhere, baselines on a subset.
def runs() -> list[tuple[str, str, int]]:
    names = list(cases())
    out = [(n, "lgmcts", 0) for n in names]
    out += [(n, "lgmcts", 1) for n in names if n.startswith(("random-", "elgr-"))][:8]
    out += [(n, m, 0) for n in names[:6] for m in ("greedy", "pmcts")]
    out += [(n, m, 0) for n in names if n.startswith("labbe-10") for m in ("greedy", "pmcts")]
    return out


def digest(plan: lgmcts.PlanSpec) -> str:
    """SHA-256 of the solved flag and every action, poses rounded to 1e-6 m / rad."""
    acts = [[a.object, [round(float(v), 6) for v in a.to], a.on, a.purpose] for a in plan.actions]
    blob = json.dumps([bool(plan.solved), acts], separators=(",", ":"))
    return hashlib.sha256(blob.encode()).hexdigest()[:16]


def compute(case: str, method: str, seed: int) -> dict[str, Any]:
    scene, goals = cases()[case]()
    p = lgmcts.plan(scene, goals, method=method, seed=seed, max_iter=MAX_ITER)
    valid = lgmcts.check(scene, goals, p).valid if p.solved else False
    return {"case": case, "method": method, "seed": seed, "solved": bool(p.solved), "valid": bool(valid),
            "actions": len(p.actions), "digest": digest(p)}


def key(r: dict[str, Any]) -> str:
    return f"{r['case']}/{r['method']}/{r['seed']}"


def load() -> dict[str, dict[str, Any]]:
    return {key(r): r for r in json.loads(GOLDEN.read_text())["plans"]}


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--write", action="store_true", help="recompute every golden plan and rewrite the file")
    args = ap.parse_args(argv)
    rows = [compute(c, m, s) for c, m, s in runs()]
    if args.write:
        GOLDEN.parent.mkdir(parents=True, exist_ok=True)
        GOLDEN.write_text(json.dumps({"max_iter": MAX_ITER, "plans": rows}, indent=1) + "\n")
        print(f"wrote {len(rows)} golden plans to {GOLDEN}")
        return 0
    old = load()
    changed = [key(r) for r in rows if old.get(key(r)) != r]
    for k in changed:
        print(f"changed: {k}")
    print(f"{len(rows) - len(changed)}/{len(rows)} golden plans unchanged")
    return 1 if changed else 0


if __name__ == "__main__":
    sys.path.insert(0, str(Path(__file__).parent))
    sys.exit(main())
