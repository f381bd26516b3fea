"""Physics on touching objects: plans executed in MuJoCo on scenes where
footprints touch, with the executor's verdict (SR_ep) and what the verdict
alone does not show (how far neighbours were pushed, how deep objects
interpenetrate).

Examples (the figures in docs/benchmarks.md come from these)::

    python benchmarks/touching_physics.py labbe --ns 5,10,15 --per-n 10
    python benchmarks/touching_physics.py labbe --ns 25 --per-n 5
    python benchmarks/touching_physics.py elgr-dense --n 40
    python benchmarks/touching_physics.py elgr-dense --n 20 --observe

``labbe`` uses :func:`lgmcts.casegen.labbe_protocol_case` (discs that may
touch, seed ``1000 * N + k``); ``elgr-dense`` the dense ELGR-style suite
(seed 0, ground-truth goals). Per case it plans with lgmcts, replays the
plan in MuJoCo one action at a time and records, besides the verdict of
:func:`lgmcts.sim.execute_plan`:

* ``contacts``: the placements the plan makes within 1 mm of another
  table-level footprint (so the figures are about touching placements);
* ``push``: the largest displacement, while the start scene settles or
  during one action, of an object the action did not pick (objects resting
  on the picked one excluded);
* ``penetration``: the deepest object-object contact (MuJoCo's negative
  contact distance) after any action has settled.

With ``--observe`` the plan is made on the scene rebuilt from depth images
(:func:`lgmcts.sim.observe`) and executed on the true scene.
"""

from __future__ import annotations

import argparse
import json
import math
import platform
import statistics
import sys
import time
from datetime import UTC, datetime

import numpy as np
import shapely

from lgmcts import check, plan
from lgmcts.errors import InputError
from lgmcts.scene import TABLE, Scene


def _ns(text: str) -> list[int]:
    out: list[int] = []
    for part in text.split(","):
        a, _, b = part.partition("-")
        out.extend(range(int(a), int(b or a) + 1))
    return out


def contact_placements(scene, p, gap: float = 0.001) -> int:
    """Placements of plan ``p`` that end within ``gap`` of another table-level footprint."""
    sc = Scene.from_spec(scene)
    polys = list(sc.initial.polys)
    on = list(sc.initial.on)
    count = 0
    for a in p.actions:
        i = sc.index[a.object]
        poly = shapely.polygons(sc.footprint(i, np.asarray(a.to, dtype=float)))
        if a.on is None:
            others = [polys[k] for k in range(sc.n) if k != i and on[k] == TABLE]
            if others and min(poly.distance(q) for q in others) <= gap:
                count += 1
        polys[i] = poly
        on[i] = TABLE if a.on is None else sc.index[a.on]
    return count


def outline_density(scene, gap: float = 0.001) -> tuple[float, float]:
    """Fraction of table-level footprints within ``gap`` of another, and the
    largest overlap between two of them (mm^2)."""
    sc = Scene.from_spec(scene)
    table = [k for k in range(sc.n) if sc.initial.on[k] == TABLE]
    polys = sc.initial.polys
    if len(table) < 2:
        return 0.0, 0.0
    near = [min(polys[k].distance(polys[j]) for j in table if j != k) <= gap for k in table]
    worst = max(float(polys[a].intersection(polys[b]).area) for a in table for b in table if a < b)
    return float(np.mean(near)), 1e6 * worst


def physics_probe(scene, p) -> tuple[float, float]:
    """``(push, penetration)`` of plan ``p`` replayed in MuJoCo (m)."""
    from lgmcts.sim import Executor, build_model, physics

    sc = Scene.from_spec(scene)
    sim = build_model(sc)
    ex = Executor(sim)
    before = physics.poses(sim, ex.data)
    ex.settle()
    # Settling the start scene counts too: a start whose objects move by themselves is not at rest.
    push = float(np.hypot(*(physics.poses(sim, ex.data)[:, :2] - before[:, :2]).T).max())
    pen = 0.0
    who = sim.geom_who
    for a in p.actions:
        k = sc.index[a.object]
        before, sup = physics.poses(sim, ex.data), physics.supports(sim, ex.data)
        riding = {j for j in range(sc.n) if sup[j] == k}
        out = ex.pick_and_place(k, np.asarray(a.to, dtype=float), None if a.on is None else sc.index[a.on])
        after = physics.poses(sim, ex.data)
        moved = np.hypot(*(after[:, :2] - before[:, :2]).T)
        rest = [j for j in range(sc.n) if j != k and j not in riding]
        if rest:
            push = max(push, float(moved[rest].max()))
        d = ex.data
        for c in range(d.ncon):
            g1, g2 = d.contact.geom1[c], d.contact.geom2[c]
            if who[g1] >= 0 and who[g2] >= 0:
                pen = max(pen, -float(d.contact.dist[c]))
        if not out.ok:
            break
    return push, pen


def _cases(args):
    if args.what == "labbe":
        from lgmcts.casegen import labbe_protocol_case

        for n in _ns(args.ns):
            for k in range(args.per_n):
                c = labbe_protocol_case(n, 1000 * n + k)
                yield f"labbe N={n} #{k}", n, c.scene, c.goals
    else:
        from lgmcts.bench.suites import generate

        for t in generate("elgr-dense", n=args.n, seed=0):
            yield t.id, t.category, t.scene_spec(), t.goal_spec()


def main(argv: list[str] | None = None) -> int:
    from lgmcts.sim import execute_plan, observe

    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("what", choices=["labbe", "elgr-dense"])
    ap.add_argument("--ns", default="5,10,15", help="disc counts for labbe, e.g. 5,10,15 or 5-15")
    ap.add_argument("--per-n", type=int, default=10, help="configurations per N (labbe)")
    ap.add_argument("--n", type=int, default=20, help="tasks (elgr-dense)")
    ap.add_argument("--max-iter", type=int, default=10_000)
    ap.add_argument("--observe", action="store_true", help="plan on the observed scene, execute on the true one")
    ap.add_argument("--json", default=None, help="also write per-case rows here")
    args = ap.parse_args(argv)

    rows = []
    for name, group, scene, goals in _cases(args):
        t0 = time.perf_counter()
        plan_scene = observe(scene) if args.observe else scene
        try:
            p = plan(plan_scene, goals, seed=0, max_iter=args.max_iter)
        except InputError as exc:  # e.g. a goal names an object the camera did not see
            row = {"case": name, "group": group, "objects": len(scene.objects), "solved": False, "valid": False,
                   "actions": 0, "refused": str(exc), "wall_s": time.perf_counter() - t0}
            rows.append(row)
            print(json.dumps(row), file=sys.stderr, flush=True)
            continue
        valid = bool(p.solved and check(scene if not args.observe else plan_scene, goals, p).valid)
        row = {"case": name, "group": group, "objects": len(scene.objects), "solved": bool(p.solved), "valid": valid,
               "actions": len(p.actions)}
        if args.observe:
            row["outline_near"], row["outline_overlap_mm2"] = outline_density(plan_scene)
        if p.solved:
            row["contacts"] = contact_placements(plan_scene, p)
            res = execute_plan(scene, p, goals, plan_scene=plan_scene if args.observe else None)
            row["sr_ep"] = bool(res.success)
            row["reasons"] = list(res.reasons[:3])
            row["max_error_mm"] = 1000 * max((s.error for s in res.steps if not math.isnan(s.error)), default=0.0)
            if not args.observe:
                push, pen = physics_probe(scene, p)
                row["push_mm"], row["penetration_mm"] = 1000 * push, 1000 * pen
        row["wall_s"] = time.perf_counter() - t0
        rows.append(row)
        print(json.dumps(row), file=sys.stderr, flush=True)

    now = datetime.now(UTC)
    print(f"date: {now:%Y-%m-%d %H:%M} UTC; machine: {platform.node()}, Python {platform.python_version()}")
    print(f"command: python benchmarks/touching_physics.py {' '.join(argv if argv is not None else sys.argv[1:])}")
    groups = sorted({r["group"] for r in rows}, key=lambda g: (isinstance(g, str), g))
    if args.what != "labbe":
        groups = ["all"]
    print(
        "| group | cases | planned and valid | SR_ep | placements within 1 mm | max push (mm) | max "
        "penetration (mm) | max placement error (mm) |"
    )
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for g in groups:
        rs = [r for r in rows if g == "all" or r["group"] == g]
        ex = [r for r in rs if r["solved"]]
        fmt = lambda key, ex=ex: f"{max((r[key] for r in ex if key in r), default=float('nan')):.2f}"  # noqa: E731
        n_ep = sum(r.get("sr_ep", False) for r in ex)
        print(
            f"| {'N = ' + str(g) if args.what == 'labbe' else g} | {len(rs)} | "
            f"{sum(r['valid'] for r in rs)}/{len(rs)} | "
            f"{n_ep}/{len(ex)} | {sum(r.get('contacts', 0) for r in ex)} of {sum(r['actions'] for r in ex)} | "
            f"{fmt('push_mm')} | {fmt('penetration_mm')} | {fmt('max_error_mm')} |"
        )
    if args.observe:
        obs = [r for r in rows if "outline_near" in r]
        if obs:
            print(
                f"observed outlines: {np.mean([r['outline_near'] for r in obs]):.2f} of the table-level objects "
                "within 1 mm "
                f"of another (mean over {len(obs)} scenes); largest overlap "
                f"{max(r['outline_overlap_mm2'] for r in obs):.3f} mm^2"
            )
    for r in rows:
        if r.get("solved") and not r.get("sr_ep"):
            print(f"  failed in physics {r['case']}: {r['reasons']}")
        if not r["valid"]:
            print(f"  not planned/valid {r['case']}" + (f": refused ({r['refused']})" if "refused" in r else ""))
    if rows:
        print(f"wall time per case: median {statistics.median(r['wall_s'] for r in rows):.2f} s")
    if args.json:
        with open(args.json, "w") as f:
            json.dump(rows, f, indent=1)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
