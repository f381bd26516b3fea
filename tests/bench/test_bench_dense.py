"""The dense ELGR-style suite: the same tasks plus touching clutter packed
around the goal region; start scenes legal (no overlap beyond the validator's
tolerance) and measurably dense; end to end through parser, planner and MuJoCo."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import shapely

from lgmcts.bench import SUITES, generate, task_seed
from lgmcts.formats import parse_scene
from lgmcts.scene import TABLE, Scene
from lgmcts.validate import OVERLAP_AREA

pytestmark = pytest.mark.slow

REPO = Path(__file__).resolve().parents[2]


def _lens(r1: float, r2: float, d: float) -> float:
    # Area of the intersection of two circles (independent of the validator's own).
    if d >= r1 + r2:
        return 0.0
    if d <= abs(r1 - r2):
        return np.pi * min(r1, r2) ** 2
    a = r1 * r1 * np.arccos((d * d + r1 * r1 - r2 * r2) / (2 * d * r1))
    b = r2 * r2 * np.arccos((d * d + r2 * r2 - r1 * r1) / (2 * d * r2))
    return float(a + b - 0.5 * np.sqrt((-d + r1 + r2) * (d + r1 - r2) * (d - r1 + r2) * (d + r1 + r2)))


def _start_overlaps(task) -> tuple[float, int]:
    """Largest overlap area between table-level start footprints (the
    validator's measure: polygons, the true circles between two cylinders),
    and the number of footprints outside the workspace."""
    spec = parse_scene(task.scene)
    sc = Scene.from_spec(spec)
    shapes = {o.id: o.shape for o in spec.objects}
    table = [k for k in range(sc.n) if sc.initial.on[k] == TABLE]
    polys = sc.initial.polys
    worst = 0.0
    for a in table:
        for b in table:
            if b <= a:
                continue
            sa, sb = shapes[sc.ids[a]], shapes[sc.ids[b]]
            if sa.type == "cylinder" and sb.type == "cylinder":
                d = float(np.hypot(*(sc.initial.poses[a, :2] - sc.initial.poses[b, :2])))
                area = _lens(sa.radius, sb.radius, d)
            else:
                area = float(polys[a].intersection(polys[b]).area)
            worst = max(worst, area)
    xmin, xmax, ymin, ymax = sc.bounds
    ws = shapely.box(xmin, ymin, xmax, ymax)
    outside = sum(float(polys[k].difference(ws).area) > OVERLAP_AREA for k in table)
    return worst, outside


def _near_fraction(task, gap: float = 1e-3) -> float:
    """Fraction of table-level start objects with another within ``gap`` (m)."""
    sc = Scene.from_spec(parse_scene(task.scene))
    table = [k for k in range(sc.n) if sc.initial.on[k] == TABLE]
    polys = sc.initial.polys
    near = [min(polys[k].distance(polys[j]) for j in table if j != k) <= gap for k in table]
    return float(np.mean(near))


def test_dense_task_is_the_elgr_task_plus_packed_clutter():
    for k in range(10):
        cat = SUITES["elgr"].categories[k]
        base = SUITES["elgr"].build(cat, task_seed(4, k))
        dense = SUITES["elgr-dense"].build(cat, task_seed(4, k))
        assert dense.suite == "elgr-dense" and dense.category == cat
        assert dense.instruction == base.instruction and dense.goals == base.goals
        nb = len(base.scene["objects"])
        assert dense.scene["objects"][:nb] == base.scene["objects"]
        extra = [o["id"] for o in dense.scene["objects"][nb:]]
        # 6-12 drawn; one that finds no spot in contact is left out.
        assert extra == dense.start["packed"] and 4 <= len(extra) <= 12
        assert all(str(i) in dense.final for i in extra)


def test_dense_generation_is_deterministic_by_seed(tmp_path):
    a = [t.to_dict() for t in generate("elgr-dense", n=4, seed=9)]
    b = [t.to_dict() for t in generate("elgr-dense", n=4, seed=9)]
    c = [t.to_dict() for t in generate("elgr-dense", n=4, seed=10)]
    assert json.dumps(a, sort_keys=True) == json.dumps(b, sort_keys=True)
    assert all(x["scene"] != y["scene"] for x, y in zip(a, c))
    # The CLI writes byte-identical files for the same seed.
    outs = []
    for name in ("a.jsonl", "b.jsonl"):
        r = subprocess.run(
            [
                sys.executable,
                "-m",
                "lgmcts",
                "bench-generate",
                "--suite",
                "elgr-dense",
                "--n",
                "2",
                "--seed",
                "3",
                "-o",
                str(tmp_path / name),
            ],
            capture_output=True,
            text=True,
            cwd=REPO,
            timeout=120,
        )
        assert r.returncode == 0, r.stderr
        outs.append((tmp_path / name).read_text())
    assert outs[0] == outs[1] and all(json.loads(line)["suite"] == "elgr-dense" for line in outs[0].splitlines())


def test_dense_start_scenes_are_legal_and_dense():
    tasks = generate("elgr-dense", n=20, seed=2)
    fractions = []
    for t in tasks:
        worst, outside = _start_overlaps(t)
        assert worst <= OVERLAP_AREA, (t.id, worst)  # the validator's no-overlap rule with its tolerance
        assert outside == 0, t.id
        fractions.append(_near_fraction(t))
        # Every extra object is packed: within 0.1 mm of a start footprint or of a final spot.
        sc = Scene.from_spec(parse_scene(t.scene))
        finals = {i: shapely.Polygon(sc.footprint(sc.index[i], np.asarray(t.final[str(i)]))) for i in sc.ids}
        [k for k in range(sc.n) if sc.initial.on[k] == TABLE]
        for i in t.start["packed"]:
            k = sc.index[i]
            # Not under the overhang of a stacked object either.
            stacked = [j for j in range(sc.n) if sc.initial.on[j] != TABLE]
            assert all(sc.initial.polys[k].intersection(sc.initial.polys[j]).area <= 1e-12 for j in stacked), (t.id, i)
            d_start = min(sc.initial.polys[k].distance(sc.initial.polys[j]) for j in range(sc.n) if j != k)
            d_goal = min(sc.initial.polys[k].distance(finals[g]) for g in sc.ids if g != i)
            assert min(d_start, d_goal) <= 1e-4, (t.id, i)
    # Measured on this generator: about two thirds of the table-level objects
    # touch a neighbour in the start scene (0.65 over 50 tasks of seed 3); the
    # base suite keeps every pair at least 8 mm apart.
    assert np.mean(fractions) >= 0.5 and min(fractions) >= 0.2
    base = generate("elgr", n=10, seed=2)
    assert max(_near_fraction(t) for t in base) == 0.0


def test_dense_instructions_still_mean_the_ground_truth():
    # The extras never change what a reference means: the offline parser reads
    # every instruction on the dense scene as the ground-truth goals.
    pytest.importorskip("lgmcts.language")
    from lgmcts.bench.runner import canonical_goals
    from lgmcts.formats import parse_goals
    from lgmcts.language import parse

    for t in generate("elgr-dense", n=12, seed=6):
        got = parse(parse_scene(t.scene), t.instruction, parser="rules")
        assert canonical_goals(got) == canonical_goals(parse_goals(t.goals)), (t.id, t.instruction)


def test_small_dense_suite_end_to_end(tmp_path):
    pytest.importorskip("lgmcts.language")
    sim = pytest.importorskip("lgmcts.sim")
    if not hasattr(sim, "execute_plan"):
        pytest.skip("no physics executor")
    from lgmcts.bench import RunOptions, run_suite, summarise

    tasks = generate("elgr-dense", n=3, seed=21)
    recs = run_suite(
        tasks, tmp_path / "d", options=RunOptions(method="lgmcts", parser="rules", max_iter=3000), workers=1
    )
    assert [r["id"] for r in recs] == [t.id for t in tasks] and all(r["suite"] == "elgr-dense" for r in recs)
    for r in recs:
        assert r["parse"]["correct"] is True, r
        assert r["sr_p"], r
        assert r["sr_ep"] == r["execution"]["success"]
    row = summarise(recs)[-1]
    assert row.tasks == 3 and row.sr_p == 1.0


def test_dense_suite_from_the_cli_and_unknown_suites(tmp_path):
    r = subprocess.run(
        [sys.executable, "-m", "lgmcts", "bench-generate", "--suite", "elgr-densest", "-o", str(tmp_path / "x.jsonl")],
        capture_output=True,
        text=True,
        cwd=REPO,
        timeout=120,
    )
    assert r.returncode == 2 and "unknown suite" in r.stderr and "elgr-dense" in r.stderr
