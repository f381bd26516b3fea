"""Command line and import hygiene, run as a user would (subprocesses)."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest
from typer.testing import CliRunner

from .conftest import ROOT

pytestmark = pytest.mark.slow

PY = sys.executable
TABLETOP = str(ROOT / "examples" / "tabletop.json")


def _run(*args: str, env: dict | None = None, timeout: float = 120) -> subprocess.CompletedProcess:
    return subprocess.run([PY, "-m", "lgmcts", *args], capture_output=True, text=True, cwd=ROOT, env=env, timeout=timeout)


def test_parse_prints_goal_json_offline(tmp_path):
    # No network and an empty Hugging Face cache: the model comes from the installed package.
    env = dict(os.environ, HF_HUB_OFFLINE="1", TRANSFORMERS_OFFLINE="1", HF_HOME=str(tmp_path / "hf"))
    r = _run("parse", TABLETOP, "Move all blocks into a circle; while put the white bottle behind one block", env=env)
    assert r.returncode == 0, r.stderr
    goals = json.loads(r.stdout)["goals"]
    assert goals[0] == {"pattern": "circle", "objects": [1, 2, 3, 4]}
    assert goals[1]["pattern"] == "behind" and goals[1]["objects"] == [5]
    assert r.stderr.strip() == ""
    assert not (tmp_path / "hf" / "hub").exists() or not any((tmp_path / "hf" / "hub").iterdir())


def test_refusal_exits_2_with_one_line():
    r = _run("parse", TABLETOP, "put the purple giraffe in a line")
    assert r.returncode == 2
    assert r.stdout == ""
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and "purple giraffe" in lines[0] and "Traceback" not in r.stderr
    r = _run("parse", "no/such/scene.json", "line up the blocks")
    assert r.returncode == 2 and "not found" in r.stderr and len(r.stderr.strip().splitlines()) == 1


def test_importing_lgmcts_and_planning_from_a_goal_file_do_not_import_torch():
    code = (
        "import sys, lgmcts, lgmcts.language, lgmcts.language.cli, lgmcts.cli\n"
        "s = lgmcts.load_scene(sys.argv[1]); g = lgmcts.load_goals(sys.argv[2])\n"
        "p = lgmcts.plan(s, g, seed=0, max_iter=200)\n"
        "bad = [m for m in ('torch', 'sentence_transformers', 'transformers') if m in sys.modules]\n"
        "print(','.join(bad) or 'clean')\n"
    )
    r = subprocess.run([PY, "-c", code, TABLETOP, str(ROOT / "examples" / "goals.json")], capture_output=True, text=True, cwd=ROOT, timeout=120)
    assert r.returncode == 0, r.stderr
    assert r.stdout.strip() == "clean"


def test_cli_refusals_in_process(matcher):
    from lgmcts.cli import app

    runner = CliRunner()
    for text, needle in [
        ("arrange the blocks in a Fibonacci spiral", "no pattern"),
        ("put the block in a line", "ambiguous"),
        ("put the mug left of the bowl and the mug right of the bowl", "contradiction"),
    ]:
        res = runner.invoke(app, ["parse", TABLETOP, text])
        assert res.exit_code == 2, text
        err = res.stderr if hasattr(res, "stderr") else res.output
        assert needle in err and len(err.strip().splitlines()) == 1


def test_eval_parse_reports_accuracy_categories_failures_and_speed(matcher, tmp_path):
    from lgmcts.cli import app

    cases = tmp_path / "cases.jsonl"
    rows = [
        {"id": "a", "category": "shape", "scene": TABLETOP, "instruction": "line up the blocks",
         "expect": {"goals": [{"pattern": "line", "objects": [1, 2, 3, 4]}]}},
        {"id": "b", "category": "shape", "scene": TABLETOP, "instruction": "line up the blocks",
         "expect": {"goals": [{"pattern": "circle", "objects": [1, 2, 3, 4]}]}},
        {"id": "c", "category": "refusal", "scene": TABLETOP, "instruction": "put the giraffe in a line", "refuse": "giraffe"},
    ]
    cases.write_text("".join(json.dumps(r) + "\n" for r in rows))
    res = CliRunner().invoke(app, ["eval-parse", str(cases), "--json"])
    assert res.exit_code == 0, res.output
    data = json.loads(res.stdout)
    assert data["cases"] == 3 and data["correct"] == 2
    assert data["per_category"]["shape"] == {"correct": 1, "total": 2, "accuracy": 0.5}
    assert [f["id"] for f in data["failures"]] == ["b"]
    assert data["parse_time"]["median_ms"] > 0
    res = CliRunner().invoke(app, ["eval-parse", str(cases), "--min-accuracy", "0.9"])
    assert res.exit_code == 1 and "2/3 correct" in res.stdout
    bad = tmp_path / "bad.jsonl"
    bad.write_text("{not json\n")
    res = CliRunner().invoke(app, ["eval-parse", str(bad)])
    assert res.exit_code == 2
