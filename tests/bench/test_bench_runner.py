"""The runner: records and causes, resume after an interruption, plug-in
planners, summaries, the Ray path and the bench command."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from lgmcts.bench import (
    RunOptions,
    canonical_goals,
    generate,
    load_results,
    run_suite,
    run_task,
    summarise,
    to_csv,
    to_markdown,
)
from lgmcts.bench.runner import RESULTS_FILE
from lgmcts.errors import InputError
from lgmcts.formats import parse_goals

REPO = Path(__file__).resolve().parents[2]
PLAN_ONLY = RunOptions(method="lgmcts", parser="gt", execute=False, max_iter=2000)


@pytest.fixture(scope="module")
def tasks():
    return generate("elgr", n=4, seed=11)


def test_run_task_plans_and_judges_against_ground_truth(tasks):
    rec = run_task(tasks[0], PLAN_ONLY)
    assert rec["id"] == tasks[0].id and rec["sr_p"] is True and rec["cause"] is None
    assert rec["sr_ep"] is None and rec["execution"] is None
    assert rec["planning"]["solved"] and rec["planning"]["actions"] == len(rec["plan"]["actions"]) > 0
    json.dumps(rec)  # JSON-ready


def test_canonical_goals_compare_sets_towers_and_split_relations():
    a = parse_goals(
        {"goals": [{"pattern": "line", "objects": [1, 2, 3]}, {"pattern": "left", "objects": [4, 5], "anchor": 6}]}
    )
    b = parse_goals(
        {
            "goals": [
                {"pattern": "left", "objects": [5], "anchor": 6},
                {"pattern": "line", "objects": [3, 1, 2]},
                {"pattern": "left", "objects": [4], "anchor": 6},
            ]
        }
    )
    c = parse_goals(
        {"goals": [{"pattern": "line", "objects": [1, 2, 3]}, {"pattern": "left", "objects": [4, 5], "anchor": 1}]}
    )
    assert canonical_goals(a) == canonical_goals(b) != canonical_goals(c)
    t1 = parse_goals({"goals": [{"pattern": "tower", "objects": [1, 2]}]})
    t2 = parse_goals({"goals": [{"pattern": "tower", "objects": [2, 1]}]})
    assert canonical_goals(t1) != canonical_goals(t2)


def _write_planner(tmp_path: Path, body: str) -> str:
    name = f"my_planner_{abs(hash(body)) % 10**8}"
    (tmp_path / f"{name}.py").write_text(body)
    sys.path.insert(0, str(tmp_path))
    return name


def test_plugin_planner_is_called_and_judged(tmp_path, tasks):
    mod = _write_planner(
        tmp_path,
        (
            "import lgmcts\n"
            "calls = []\n"
            "def good(scene, goals, seed, max_iter):\n"
            "    calls.append((seed, max_iter))\n"
            "    return lgmcts.formats.to_dict(lgmcts.plan(scene, goals, seed=seed, max_iter=max_iter))\n"
            "def lazy(scene, goals, seed, max_iter):\n"
            "    return {'solved': True, 'actions': []}\n"
            "def broken(scene, goals, seed, max_iter):\n"
            "    raise RuntimeError('boom')\n"
        ),
    )
    try:
        rec = run_task(tasks[1], RunOptions(method=f"{mod}:good", parser="gt", execute=False, max_iter=1500))
        assert rec["sr_p"] is True
        assert sys.modules[mod].calls == [(tasks[1].seed, 1500)]
        # A plan that claims success but does nothing fails the validator.
        rec = run_task(tasks[1], RunOptions(method=f"{mod}:lazy", parser="gt", execute=False))
        assert rec["sr_p"] is False and rec["cause"] == "plan invalid" and "goal" in rec["detail"]
        rec = run_task(tasks[1], RunOptions(method=f"{mod}:broken", parser="gt", execute=False))
        assert rec["cause"] == "planner error" and "boom" in rec["detail"]
        with pytest.raises(InputError, match="no function"):
            RunOptions(method=f"{mod}:missing").check()
        with pytest.raises(InputError, match="cannot import"):
            RunOptions(method="no_such_module_xyz:plan").check()
        with pytest.raises(InputError, match="unknown method"):
            RunOptions(method="dijkstra").check()
        with pytest.raises(InputError, match="unknown parser"):
            RunOptions(parser="magic").check()
        with pytest.raises(InputError, match="workers"):
            run_suite(tasks[:1], tmp_path / "w", options=PLAN_ONLY, workers=0)
    finally:
        sys.path.remove(str(tmp_path))


def test_interrupted_run_resumes_from_its_jsonl(tmp_path, tasks):
    out = tmp_path / "run"
    first = run_suite(tasks[:2], out, options=PLAN_ONLY, workers=1, source="t")
    assert [r["id"] for r in first] == [t.id for t in tasks[:2]]
    path = out / RESULTS_FILE
    lines = path.read_text().splitlines(keepends=True)
    # Interrupted while writing the second record: keep the first and half a line.
    path.write_text(lines[0] + lines[1][: len(lines[1]) // 2])
    assert [r["id"] for r in load_results(out)] == [tasks[0].id]
    again = run_suite(tasks, out, options=PLAN_ONLY, workers=1, source="t")
    assert [r["id"] for r in again] == [t.id for t in tasks]
    ids = [json.loads(x)["id"] for x in path.read_text().splitlines()]
    assert sorted(ids) == sorted(t.id for t in tasks) and len(ids) == len(set(ids))
    assert again[0] == json.loads(lines[0])  # the finished task was not run again
    with pytest.raises(InputError, match="method"):
        run_suite(tasks, out, options=RunOptions(method="greedy", parser="gt", execute=False), workers=1, source="t")


def test_summary_counts_rates_and_causes():
    recs = [
        {
            "id": "a",
            "category": "x",
            "sr_p": True,
            "sr_ep": True,
            "cause": None,
            "parse": {"correct": True},
            "planning": {"actions": 4, "time_s": 0.1},
        },
        {
            "id": "b",
            "category": "x",
            "sr_p": True,
            "sr_ep": False,
            "cause": "execution failed",
            "parse": {"correct": True},
            "planning": {"actions": 6, "time_s": 0.3},
        },
        {
            "id": "c",
            "category": "y",
            "sr_p": False,
            "sr_ep": False,
            "cause": "parse refused",
            "parse": {"correct": False},
            "planning": {},
        },
        {
            "id": "d",
            "category": "y",
            "sr_p": False,
            "sr_ep": False,
            "cause": "plan not found",
            "parse": {"correct": True},
            "planning": {"actions": 9, "time_s": 2.0},
        },
    ]
    rows = summarise(recs)
    assert [r.group for r in rows] == ["x", "y", "all"]
    allr = rows[-1]
    assert allr.tasks == 4 and allr.sr_p == 0.5 and allr.sr_ep == 0.25 and allr.parse_acc == 0.75
    assert allr.mean_actions == 5.0 and allr.plan_median_s == pytest.approx(0.3)
    assert allr.causes == {"parse refused": 1, "plan not found": 1, "execution failed": 1}
    md = to_markdown(rows)
    assert "| all | 4 | 50.0% | 25.0% | 75.0% | 5.00 |" in md
    csv = to_csv(rows).splitlines()
    assert csv[0].startswith("group,tasks,sr_p,sr_ep") and csv[-1].startswith("all,4,0.5000,0.2500,0.7500,5.000")


@pytest.mark.slow
def test_ray_runs_the_same_task_function(tmp_path, tasks):
    ray = pytest.importorskip("ray", reason="ray is an optional extra (pip install 'lgmcts[ray]')")
    ray.init(num_cpus=1, include_dashboard=False, log_to_driver=False)
    try:
        recs = run_suite(tasks[:2], tmp_path / "ray", options=PLAN_ONLY, ray_address="local", source="r")
    finally:
        ray.shutdown()
    local = [run_task(t, PLAN_ONLY) for t in tasks[:2]]
    assert [r["id"] for r in recs] == [t.id for t in tasks[:2]]
    # Same seed, same plan, wherever the task ran.
    assert [r["plan"]["actions"] for r in recs] == [r["plan"]["actions"] for r in local]
    # A cluster address nobody answers on is bad input, reported at once.
    with pytest.raises(InputError, match="cannot reach Ray"):
        run_suite(tasks[:1], tmp_path / "ray2", options=PLAN_ONLY, ray_address="127.0.0.1:1", source="r")


@pytest.mark.slow
def test_bench_cli_writes_results_and_summaries(tmp_path):
    out = tmp_path / "cli"
    cmd = [
        sys.executable,
        "-m",
        "lgmcts",
        "bench",
        "--suite",
        "structformer",
        "--n",
        "4",
        "--no-exec",
        "--workers",
        "2",
        "--max-iter",
        "2000",
        "-o",
        str(out),
    ]
    r = subprocess.run(cmd, capture_output=True, text=True, cwd=REPO, timeout=170)
    assert r.returncode == 0, r.stderr
    assert "| all | 4 |" in r.stdout and r.stderr == ""  # no progress bar when stderr is not a terminal
    assert len((out / RESULTS_FILE).read_text().splitlines()) == 4
    assert (out / "summary.csv").read_text().startswith("group,tasks")
    assert (out / "suite.jsonl").exists() and json.loads((out / "run.json").read_text())["parser"] == "gt"
    for bad, msg in ((["--method", "nope"], "unknown method"), (["--suite", "missing.jsonl"], "not found")):
        args = [*cmd[:4], "--suite", "elgr", "--n", "1", "-o", str(tmp_path / "bad"), *bad]
        r = subprocess.run(args, capture_output=True, text=True, cwd=REPO, timeout=120)
        assert r.returncode == 2 and msg in r.stderr and len(r.stderr.strip().splitlines()) == 1, (bad, r.stderr)


def test_ray_failures_are_one_line_with_an_auth_hint():
    from lgmcts.bench.runner import _ray_failure

    line = _ray_failure("ray://head:10001", RuntimeError("UNAUTHENTICATED: invalid\nauthentication token"))
    assert "\n" not in line and "RAY_AUTH_TOKEN" in line and "UNAUTHENTICATED" in line
    assert "RAY_AUTH_TOKEN" not in _ray_failure("ray://head:10001", ConnectionError("refused"))
