"""`lgmcts viz` exit codes and outputs, and `plan --viz`."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from typer.testing import CliRunner

from lgmcts.cli import app

pytestmark = pytest.mark.slow

DATA = Path(__file__).parent / "data"
SCENE = str(DATA / "cluttered_scene.json")
PLAN = str(DATA / "cluttered_plan.json")
runner = CliRunner()


def _one_line(result) -> str:
    err = result.stderr.strip()
    assert err and "\n" not in err and "Traceback" not in err, err
    return err


def test_html_only(tmp_path):
    out = tmp_path / "plan.html"
    r = runner.invoke(app, ["viz", PLAN, "--scene", SCENE, "--html", str(out), "--instruction", "tidy up"])
    assert r.exit_code == 0, r.output
    text = out.read_text()
    assert "LGMCTSViewer.render" in text and "tidy up" in text


def test_pictures_with_step(tmp_path):
    plan = json.loads(Path(PLAN).read_text())
    plan["actions"] = plan["actions"][:2]
    pf = tmp_path / "short.json"
    pf.write_text(json.dumps(plan))
    r = runner.invoke(app, ["viz", str(pf), "--scene", SCENE, "-o", str(tmp_path / "figs"), "--step", "2"])
    assert r.exit_code == 0, r.output
    names = sorted(p.name for p in (tmp_path / "figs").iterdir())
    assert names == sorted(
        [
            "initial.png",
            "step_01.png",
            "step_02.png",
            "final.png",
            "before_after.png",
            "plan.gif",
            "heatmaps_step_02.png",
        ]
    )


@pytest.mark.parametrize(
    "args, message",
    [
        (["viz", PLAN, "--scene", SCENE], "nothing to write"),
        (["viz", PLAN, "--scene", "missing.json", "--html", "x.html"], "scene file not found"),
        (["viz", "missing.json", "--scene", SCENE, "--html", "x.html"], "plan file not found"),
        (["viz", SCENE, "--scene", SCENE, "--html", "x.html"], "invalid plan"),
        (["viz", PLAN, "--scene", SCENE, "-o", "figs", "--step", "9"], "outside the plan"),
        (["viz", PLAN, "--scene", SCENE, "--html", "x.html", "--step", "1"], "give -o DIR"),
        (
            ["viz", PLAN, "--scene", SCENE, "--html", "x.html", "--goal", str(DATA / "bad_goals.json")],
            "unknown object id 42",
        ),
        (["viz", PLAN, "--scene", SCENE, "--html", "no/such/dir/x.html"], "cannot write"),
    ],
)
def test_bad_input_exits_2_with_one_line(tmp_path, monkeypatch, args, message):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "d").mkdir()
    r = runner.invoke(app, args)
    assert r.exit_code == 2, r.output
    assert message in _one_line(r)
    assert not (tmp_path / "figs").exists()


def test_unknown_object_in_plan_exits_2(tmp_path):
    plan = json.loads(Path(PLAN).read_text())
    plan["actions"][1]["object"] = 77
    pf = tmp_path / "p.json"
    pf.write_text(json.dumps(plan))
    r = runner.invoke(app, ["viz", str(pf), "--scene", SCENE, "--html", str(tmp_path / "x.html")])
    assert r.exit_code == 2
    assert "unknown object id 77" in _one_line(r)


def test_plan_command_writes_pictures(tmp_path):
    figs = tmp_path / "figs"
    goals = tmp_path / "g.json"
    goals.write_text(json.dumps({"goals": [{"pattern": "right", "objects": [5], "anchor": 1}]}))
    r = runner.invoke(app, ["plan", SCENE, "--goal", str(goals), "-o", str(tmp_path / "p.json"), "--viz", str(figs)])
    assert r.exit_code == 0, r.output
    n = len(json.loads((tmp_path / "p.json").read_text())["actions"])
    assert len(list(figs.glob("step_*.png"))) == n
    assert (figs / "plan.gif").exists() and (figs / "final.png").exists()
