"""End-to-end runs of the ``lgmcts`` command line: exit codes and one-line errors."""

from __future__ import annotations

import json
import subprocess
import sys

import pytest

pytestmark = pytest.mark.slow


def run(*args: str, cwd=None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "lgmcts", *args], capture_output=True, text=True, cwd=cwd, timeout=300)


def test_plan_then_check(example_scene, example_goals, tmp_path):
    out = tmp_path / "plan.json"
    r = run("plan", str(example_scene), "--goal", str(example_goals), "--seed", "3", "-o", str(out))
    assert r.returncode == 0, r.stderr
    data = json.loads(out.read_text())
    assert data["solved"] is True and data["actions"]
    assert data["goals"] == json.loads(example_goals.read_text())
    assert data["stats"]["iterations"] >= 1
    r = run("check", str(example_scene), str(example_goals), str(out))
    assert r.returncode == 0 and r.stdout.startswith("valid")


def test_plan_to_stdout_is_deterministic(example_scene, example_goals):
    a = run("plan", str(example_scene), "--goal", str(example_goals), "--seed", "4", "--method", "greedy")
    b = run("plan", str(example_scene), "--goal", str(example_goals), "--seed", "4", "--method", "greedy")
    assert a.returncode == b.returncode == 0
    assert json.loads(a.stdout)["actions"] == json.loads(b.stdout)["actions"]


def test_check_rejects_a_bad_plan(example_scene, example_goals, tmp_path):
    bad = tmp_path / "bad.json"
    # Object 2 has object 3 on it: picking it first is illegal, and the goals are not met.
    bad.write_text(json.dumps({"solved": True, "actions": [{"object": 2, "to": [0.3, -0.2, 0.0], "on": None}]}))
    r = run("check", str(example_scene), str(example_goals), str(bad), "--json")
    assert r.returncode == 1
    verdict = json.loads(r.stdout)
    assert not verdict["valid"] and any("not clear" in x for x in verdict["reasons"])


def test_unsolved_plan_exits_1_and_still_writes(tmp_path):
    scene = {
        "workspace": {"x": [-0.1, 0.2], "y": [-0.03, 0.03]},
        "objects": [
            {
                "id": i,
                "name": "block",
                "shape": {"type": "box", "size": [0.03, 0.03, 0.03]},
                "pose": [-0.08 + 0.04 * i, 0.0, 0.0],
            }
            for i in range(5)
        ],
    }
    goals = {"goals": [{"pattern": "circle", "objects": [0, 1, 2, 3, 4]}]}
    (tmp_path / "s.json").write_text(json.dumps(scene))
    (tmp_path / "g.json").write_text(json.dumps(goals))
    r = run(
        "plan",
        str(tmp_path / "s.json"),
        "--goal",
        str(tmp_path / "g.json"),
        "--max-iter",
        "100",
        "-o",
        str(tmp_path / "p.json"),
    )
    assert r.returncode == 1
    assert json.loads((tmp_path / "p.json").read_text())["solved"] is False


BAD = [
    ({"goals": [{"pattern": "line", "objects": [1, 99]}]}, "unknown object id 99"),
    ({"goals": [{"pattern": "line", "objects": [1]}]}, "a line needs at least 2 objects"),
    ({"goals": [{"pattern": "circle", "objects": [1, 2]}]}, "a circle needs at least 3 objects"),
    ({"goals": [{"pattern": "left", "objects": [1], "anchor": 1}]}, "also one of its objects"),
    ({"goals": [{"pattern": "hexagram", "objects": [1, 2]}]}, "unknown pattern"),
    ({"goals": []}, "goal list is empty"),
    ("not json at all", "not valid JSON"),
]


@pytest.mark.parametrize("goals,needle", BAD)
def test_bad_goals_exit_2_with_one_line(goals, needle, example_scene, tmp_path):
    g = tmp_path / "g.json"
    g.write_text(goals if isinstance(goals, str) else json.dumps(goals))
    r = run("plan", str(example_scene), "--goal", str(g))
    assert r.returncode == 2
    err = r.stderr.strip()
    assert needle in err and "\n" not in err and "Traceback" not in err
    r = run("check", str(example_scene), str(g), str(g))
    assert r.returncode == 2 and "Traceback" not in r.stderr


@pytest.mark.parametrize(
    "scene,needle",
    [
        (
            {
                "workspace": {"x": [0, 1], "y": [0, 1]},
                "objects": [
                    {"id": 1, "name": "b", "shape": {"type": "box", "size": [0.1, 0.1, 0.1]}, "pose": [0.5, 0.5, 0]},
                    {"id": 1, "name": "b", "shape": {"type": "box", "size": [0.1, 0.1, 0.1]}, "pose": [0.2, 0.2, 0]},
                ],
            },
            "duplicate object id",
        ),
        (
            {
                "workspace": {"x": [0, 1], "y": [0, 1]},
                "objects": [
                    {"id": 1, "name": "b", "shape": {"type": "box", "size": [0.1, 0.1, 0.1]}, "pose": [5, 0.5, 0]}
                ],
            },
            "outside the workspace",
        ),
        (
            {
                "workspace": {"x": [0, 1], "y": [0, 1]},
                "objects": [{"id": 1, "name": "b", "shape": {"type": "cone"}, "pose": [0.5, 0.5, 0]}],
            },
            "invalid scene",
        ),
    ],
)
def test_bad_scene_exit_2(scene, needle, example_goals, tmp_path):
    s = tmp_path / "s.json"
    s.write_text(json.dumps(scene))
    r = run("plan", str(s), "--goal", str(example_goals))
    assert r.returncode == 2
    assert needle in r.stderr and "Traceback" not in r.stderr


def test_missing_file_and_bad_option(example_scene, example_goals):
    r = run("plan", "/nonexistent/scene.json", "--goal", str(example_goals))
    assert r.returncode == 2 and "not found" in r.stderr
    r = run("plan", str(example_scene), "--goal", str(example_goals), "--method", "dijkstra")
    assert r.returncode == 2 and "unknown method" in r.stderr
    r = run("plan", str(example_scene))
    assert r.returncode == 2 and "--goal" in r.stderr
