"""``lgmcts execute`` and ``lgmcts observe``: output and exit codes."""

from __future__ import annotations

import json

import pytest
from typer.testing import CliRunner

import lgmcts
from lgmcts.cli import app
from lgmcts.formats import load_goals, load_scene, save_json

pytestmark = pytest.mark.slow

runner = CliRunner()


@pytest.fixture(scope="module")
def files(tmp_path_factory, example_scene, example_goals):
    d = tmp_path_factory.mktemp("exec")
    plan = lgmcts.plan(load_scene(example_scene), load_goals(example_goals), seed=0)
    save_json(plan, d / "plan.json")
    # Picking block 2 while block 3 rests on it.
    bad = {"solved": True, "actions": [{"object": 2, "to": [0.2, -0.2, 0.0], "on": None}]}
    (d / "covered.json").write_text(json.dumps(bad))
    (d / "unknown.json").write_text(json.dumps({"solved": True, "actions": [{"object": 99, "to": [0, 0, 0]}]}))
    (d / "broken.json").write_text("{not json")
    return d


def test_execute_success_exits_0(files, example_scene):
    res = runner.invoke(app, ["execute", str(example_scene), str(files / "plan.json")])
    assert res.exit_code == 0, res.output
    assert "success" in res.stdout
    n_actions = len(json.loads((files / "plan.json").read_text())["actions"])
    assert res.stdout.count("ok   action") == n_actions


def test_execute_failure_exits_1(files, example_scene, example_goals):
    res = runner.invoke(app, ["execute", str(example_scene), str(files / "covered.json"), "--goal", str(example_goals)])
    assert res.exit_code == 1, res.output
    assert "FAIL action 1: object 2: pick failed: object 2 is covered by object 3" in res.stdout
    assert "failure" in res.stdout


def test_execute_json(files, example_scene):
    res = runner.invoke(app, ["execute", str(example_scene), str(files / "plan.json"), "--json"])
    assert res.exit_code == 0
    data = json.loads(res.stdout)
    n_actions = len(json.loads((files / "plan.json").read_text())["actions"])
    assert data["success"] is True and len(data["steps"]) == n_actions
    assert {o["id"] for o in data["final"]["objects"]} == set(range(1, 10))


@pytest.mark.parametrize(
    "plan, goal, message",
    [
        ("unknown.json", True, "action 1 picks unknown object id 99"),
        ("broken.json", True, "is not valid JSON"),
        ("missing.json", True, "plan file not found"),
        ("covered.json", False, "no goals given and the plan carries none"),
    ],
)
def test_execute_bad_input_exits_2_with_one_line(files, example_scene, example_goals, plan, goal, message):
    args = ["execute", str(example_scene), str(files / plan)] + (["--goal", str(example_goals)] if goal else [])
    res = runner.invoke(app, args)
    assert res.exit_code == 2
    assert message in res.stderr
    assert len(res.stderr.strip().splitlines()) == 1
    assert "Traceback" not in res.output


def test_observe_writes_points_scene(render_ok, example_scene, tmp_path):
    out = tmp_path / "observed.json"
    res = runner.invoke(app, ["observe", str(example_scene), "-o", str(out), "--width", "320", "--height", "240"])
    assert res.exit_code == 0, res.output
    seen = load_scene(out)
    assert all(o.shape.type == "points" for o in seen.objects)
    assert "footprint IoU mean" in res.stderr


def test_observe_bad_input_exits_2(tmp_path):
    res = runner.invoke(app, ["observe", str(tmp_path / "nope.json")])
    assert res.exit_code == 2
    assert "scene file not found" in res.stderr
