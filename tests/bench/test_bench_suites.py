"""Suite generators: determinism, format validity, solvability by construction,
infeasible starts as claimed, and unambiguous references."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import shapely

from lgmcts.bench import SUITES, Task, generate, read_suite, task_seed, write_suite
from lgmcts.bench.catalog import VIMA_COLORS, VIMA_KINDS
from lgmcts.bench.refs import resolve, resolve_loose, unambiguous
from lgmcts.errors import InputError
from lgmcts.formats import parse_goals, parse_scene
from lgmcts.scene import TABLE, Scene
from lgmcts.validate import goal_satisfied

REPO = Path(__file__).resolve().parents[2]
CASES = [(s, c) for s in SUITES for c in SUITES[s].categories]


def _build(suite: str, category: str, k: int) -> Task:
    return SUITES[suite].build(category, task_seed(7, k), task_id=f"t{k}")


def _final_state(task: Task, scene: Scene) -> tuple[np.ndarray, tuple[int, ...]]:
    poses = np.array([task.final[str(i)] for i in scene.ids], dtype=float)
    on = tuple(scene.index[task.final_on[str(i)]] if str(i) in task.final_on else TABLE for i in scene.ids)
    return poses, on


@pytest.mark.parametrize("suite,category", CASES)
def test_same_seed_same_task_other_seed_other_task(suite, category):
    a = _build(suite, category, 3).to_dict()
    b = _build(suite, category, 3).to_dict()
    c = _build(suite, category, 4).to_dict()
    assert json.dumps(a, sort_keys=True) == json.dumps(b, sort_keys=True)
    assert a["scene"] != c["scene"]


@pytest.mark.parametrize("suite,category", CASES)
def test_tasks_are_valid_and_solvable_by_construction(suite, category):
    for k in range(3):
        task = _build(suite, category, k)
        assert task.category == category and task.suite == suite
        spec = parse_scene(task.scene)
        goals = parse_goals(task.goals)
        goals.check_against(spec)  # ids exist, no contradictions
        scene = Scene.from_spec(spec)
        # The arrangement the task was built from meets every goal...
        poses, on = _final_state(task, scene)
        for g in goals.goals:
            assert goal_satisfied(g, scene, poses, on) is None, (task.id, g)
        # ...and its table-level footprints do not overlap.
        polys = [shapely.Polygon(scene.footprint(i, poses[i])) for i in range(scene.n) if on[i] == TABLE]
        for x in range(len(polys)):
            for y in range(x + 1, len(polys)):
                assert polys[x].intersection(polys[y]).area < 1e-6
        # The start does not already solve the task.
        st = scene.initial
        assert any(goal_satisfied(g, scene, st.poses, st.on) is not None for g in goals.goals)


@pytest.mark.parametrize("category", SUITES["elgr"].categories)
def test_elgr_starts_are_infeasible_as_claimed(category):
    for k in range(3):
        task = _build("elgr", category, k)
        scene = Scene.from_spec(parse_scene(task.scene))
        goals = parse_goals(task.goals)
        movers = {o for g in goals.goals for o in g.objects}
        blockers, clutter = task.start["blockers"], task.start["clutter"]
        assert blockers and clutter
        for top, base in blockers:
            # Something rests on an object that must move: it cannot be picked first.
            assert base in movers
            assert scene.initial.on[scene.index[top]] == scene.index[base]
        for obj, target in clutter:
            # Another object lies where a goal object ends in the built arrangement.
            assert obj not in movers and target in movers
            i, t = scene.index[obj], scene.index[target]
            here = shapely.Polygon(scene.footprint(i, scene.initial.poses[i]))
            there = shapely.Polygon(scene.footprint(t, np.asarray(task.final[str(target)])))
            assert here.intersection(there).area > 1e-4
        assert len(goals.goals) == 2


def test_elgr_instructions_name_their_objects_unambiguously():
    # Every "the X" phrase in an instruction must match one object of the scene.
    for k in range(40):
        cat = SUITES["elgr"].categories[k % 10]
        task = _build("elgr", cat, k)
        objs = task.scene["objects"]
        text = task.instruction
        for o in objs:
            phrase = f"the {o['color']} {o['name']}"
            if phrase in text:
                assert len(resolve(("one", o["color"], o["name"]), objs)) == 1
                assert len(resolve_loose(("one", o["color"], o["name"]), objs)) == 1


def test_reference_ambiguity_is_detected():
    objs = [
        {"id": 1, "name": "block", "color": "red"},
        {"id": 2, "name": "block", "color": "red swirl"},
        {"id": 3, "name": "heart", "color": "red"},
        {"id": 4, "name": "heart", "color": "blue"},
    ]
    assert resolve(("all_color", "red"), objs) == {1, 3}
    assert not unambiguous(("all_color", "red"), objs, {1, 3})  # "red" also touches "red swirl"
    assert not unambiguous(("one", "red", "block"), objs, {1})
    assert unambiguous(("one", "blue", "heart"), objs, {4})
    assert unambiguous(("all_name", "heart"), objs, {3, 4})
    # The reference belongs to its "same colour" set (the peers' reading): alone here.
    assert resolve(("same_color", ("one", "blue", "heart")), objs) == {4}
    assert not unambiguous(("one", None, "heart"), objs, {3})


def test_elgr_suite_spans_the_catalogue_and_the_phrasings():
    tasks = generate("elgr", n=120, seed=0)
    assert [t.category for t in tasks[:10]] == list(SUITES["elgr"].categories)
    names = {o["name"] for t in tasks for o in t.scene["objects"]}
    colors = {o["color"] for t in tasks for o in t.scene["objects"]}
    assert len(names) >= 10 and len(colors) >= 8
    assert names <= {k.name for k in VIMA_KINDS} and colors <= set(VIMA_COLORS)
    text = [t.instruction for t in tasks]
    for conn in ("; and ", " while ", "; then "):
        assert any(conn in s for s in text), conn
    patterns = {g["pattern"] for t in tasks for g in t.goals["goals"]}
    assert {"line", "circle", "rectangle"} <= patterns and len(patterns - {"line", "circle", "rectangle"}) >= 6
    assert len({t.id for t in tasks}) == 120


def test_structformer_dinner_is_tower_line_and_relation():
    task = _build("structformer", "dinner", 1)
    pats = [g["pattern"] for g in task.goals["goals"]]
    assert pats[:2] == ["tower", "line"] and pats[2] in ("left", "right")
    names = {o["id"]: o["name"] for o in task.scene["objects"]}
    tower, line, rel = task.goals["goals"]
    assert names[tower["objects"][0]] == "plate" and all(names[i] == "bowl" for i in tower["objects"][1:])
    assert {names[i] for i in line["objects"]} <= {"fork", "knife", "spoon"}
    assert rel["anchor"] == tower["objects"][0] and rel["objects"] == line["objects"]


def test_suite_file_round_trip_and_bad_files(tmp_path):
    tasks = generate("structformer", n=6, seed=2)
    path = tmp_path / "s.jsonl"
    assert write_suite(tasks, path) == 6
    back = read_suite(path)
    assert [t.to_dict() for t in back] == [t.to_dict() for t in tasks]
    assert len(read_suite(path, limit=2)) == 2
    bad = tmp_path / "bad.jsonl"
    bad.write_text('{"id": "x"}\n')
    with pytest.raises(InputError, match="missing field"):
        read_suite(bad)
    bad.write_text("not json\n")
    with pytest.raises(InputError, match="not valid JSON"):
        read_suite(bad)
    dup = tmp_path / "dup.jsonl"
    dup.write_text(path.read_text().splitlines()[0] + "\n" + path.read_text().splitlines()[0] + "\n")
    with pytest.raises(InputError, match="duplicate task id"):
        read_suite(dup)
    with pytest.raises(InputError, match="not found"):
        read_suite(tmp_path / "missing.jsonl")


@pytest.mark.slow
def test_generate_cli_writes_the_same_file_for_the_same_seed(tmp_path):
    outs = []
    for name in ("a.jsonl", "b.jsonl"):
        r = subprocess.run(
            [
                sys.executable,
                "-m",
                "lgmcts",
                "bench-generate",
                "--suite",
                "elgr",
                "--n",
                "4",
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
    assert outs[0] == outs[1] and len(outs[0].splitlines()) == 4
    r = subprocess.run(
        [sys.executable, "-m", "lgmcts", "bench-generate", "--suite", "nope", "-o", str(tmp_path / "c.jsonl")],
        capture_output=True,
        text=True,
        cwd=REPO,
        timeout=120,
    )
    assert r.returncode == 2 and r.stderr.strip().count("\n") == 0 and "unknown suite" in r.stderr
