"""Hostile input to the core: the validator's bounds, the loaders' limits, the start-scene rules."""

from __future__ import annotations

import json
import math
import os
import subprocess
import sys

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from lgmcts import limits
from lgmcts.errors import InputError
from lgmcts.formats import load_goals, load_plan, load_scene, parse_goals, parse_plan, parse_scene
from lgmcts.scene import Scene
from lgmcts.validate import check

from .core_helpers import box, can, goals, scene

EXAMPLE = "examples/tabletop.json"


def _example_plan() -> dict:
    """A valid plan of the example scene: object 9 moved to a free spot, object 5 behind 1 already."""
    return {"solved": True, "actions": [{"object": 9, "to": [0.3, 0.05, 0.0], "on": None, "purpose": "relocate"}]}


def _pose_goal_of_9() -> dict:
    return goals({"pattern": "pose", "objects": [9], "pose": [0.3, 0.05, 0.0]})


def test_example_plan_is_valid():
    assert check(EXAMPLE, _pose_goal_of_9(), _example_plan()).valid


@pytest.mark.parametrize("x", [1e20, 1e300, -1e20, 1e10, 100.0, 0.5])
def test_far_away_targets_are_never_valid(x):
    """A footprint at 1e20 collapses to a point: bounds must be checked before geometry."""
    plan = _example_plan()
    plan["actions"].append({"object": 9, "to": [x, x, 0.0], "on": None, "purpose": "relocate"})
    g = goals({"pattern": "behind", "objects": [5], "anchor": 1})
    if abs(x) > limits.MAX_COORD:
        with pytest.raises(InputError, match="action pose"):
            check(EXAMPLE, g, plan)
    else:
        assert not check(EXAMPLE, g, plan).valid
    verdict = check(EXAMPLE, g, _constructed(plan))
    assert not verdict.valid
    assert any("outside the workspace" in r for r in verdict.reasons)


def _constructed(plan: dict):
    """The plan built in code, bypassing the format's bounds (the validator must hold on its own)."""
    from lgmcts.formats import Action, PlanSpec

    acts = [Action.model_construct(object=a["object"], to=tuple(a["to"]), on=a["on"], purpose=a["purpose"])
            for a in plan["actions"]]
    return PlanSpec.model_construct(solved=True, actions=acts, goals=None, stats={})


_floats = st.floats(allow_nan=True, allow_infinity=True, width=64)


@settings(max_examples=300, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(x=_floats, y=_floats, t=_floats, size=st.floats(min_value=limits.MIN_LENGTH, max_value=0.3))
def test_validator_accepts_only_footprints_inside_the_workspace(x, y, t, size):
    """Over the whole float range: a table placement judged legal has its footprint inside the workspace.

    The test's own criterion: a square of side ``size`` at any yaw contains the
    disc of radius ``size / 2`` about its centre, so a legal centre lies at
    least ``size / 2`` (less the validator's 1 mm edge tolerance) from every wall.
    """
    sc = scene(box(1, 0.0, 0.0, size=size), x=(-0.4, 0.4), y=(-0.3, 0.3))
    plan = {"solved": True, "actions": [{"object": 1, "to": [x, y, t], "on": None, "purpose": "goal"}]}
    g = goals({"pattern": "pose", "objects": [1], "pose": [0.0, 0.0, 0.0]})
    try:
        verdict = check(sc, g, plan)
    except InputError as exc:
        # Only the format's bounds may refuse the plan as bad input.
        assert not all(math.isfinite(v) for v in (x, y, t)) or max(abs(x), abs(y)) > limits.MAX_COORD \
            or abs(t) > limits.MAX_ANGLE, str(exc)
        assert "\n" not in str(exc)
        return
    # The format let it through: it must be finite and bounded.
    assert math.isfinite(x) and math.isfinite(y) and math.isfinite(t)
    legal = not any(r.startswith("action 1") for r in verdict.reasons)
    if legal:
        margin = size / 2 - 1e-3 - 1e-9
        assert -0.4 + margin <= x <= 0.4 - margin
        assert -0.3 + margin <= y <= 0.3 - margin
    # The same pose built in code (no format bounds) is judged the same way or refused.
    verdict2 = check(sc, g, _constructed(plan))
    assert verdict2.valid == verdict.valid


@settings(max_examples=200, deadline=None)
@given(x=_floats, y=_floats, t=_floats)
def test_validator_refuses_unbounded_poses_built_in_code(x, y, t):
    sc = scene(box(1, 0.0, 0.0))
    plan = _constructed({"actions": [{"object": 1, "to": [x, y, t], "on": None, "purpose": "goal"}]})
    verdict = check(sc, goals({"pattern": "pose", "objects": [1], "pose": [0.0, 0.0, 0.0]}), plan)
    if not (math.isfinite(x) and math.isfinite(y) and math.isfinite(t)) or max(abs(x), abs(y)) > 0.4:
        assert not verdict.valid


# ---------------------------------------------------------------- start scenes


def test_overlapping_start_scene_is_bad_input():
    sc = scene(box(1, 0.0, 0.0), box(2, 0.01, 0.0))
    with pytest.raises(InputError, match="objects 1 and 2 overlap"):
        Scene.from_spec(parse_scene(sc))
    with pytest.raises(InputError, match="overlap"):
        check(sc, goals({"pattern": "pose", "objects": [1], "pose": [0.2, 0.0, 0.0]}), {"solved": True, "actions": []})


def test_touching_start_objects_are_legal():
    # Two 4 cm boxes side by side, sharing an edge exactly; a can touching the second.
    sc = scene(box(1, 0.0, 0.0), box(2, 0.04, 0.0), can(3, 0.08, 0.0, r=0.02))
    Scene.from_spec(parse_scene(sc))


def test_overlap_below_tolerance_is_legal_and_stacks_are_not_overlaps():
    # 1e-5 m of interpenetration along a 4 cm edge: 4e-7 m^2, below 1e-6 m^2.
    Scene.from_spec(parse_scene(scene(box(1, 0.0, 0.0), box(2, 0.04 - 1e-5, 0.0))))
    Scene.from_spec(parse_scene(scene(box(1, 0.0, 0.0), box(2, 0.0, 0.0, on=1))))


@pytest.mark.parametrize("bad", [True, "1", 1.0, 2**40])
@pytest.mark.parametrize("where", ["object", "on", "goal", "anchor", "action"])
def test_ids_are_json_integers(bad, where):
    sc = scene(box(1, 0.0, 0.0), box(2, 0.2, 0.0))
    if where == "object":
        sc["objects"][0]["id"] = bad
        with pytest.raises(InputError, match=r"JSON integers|within"):
            parse_scene(sc)
    elif where == "on":
        sc["objects"][1]["on"] = bad
        with pytest.raises(InputError, match=r"JSON integers|within"):
            parse_scene(sc)
    elif where == "goal":
        with pytest.raises(InputError, match=r"JSON integers|within"):
            parse_goals(goals({"pattern": "line", "objects": [bad, 2]}))
    elif where == "anchor":
        with pytest.raises(InputError, match=r"JSON integers|within"):
            parse_goals(goals({"pattern": "left", "objects": [2], "anchor": bad}))
    else:
        with pytest.raises(InputError, match=r"JSON integers|within"):
            parse_plan({"solved": True, "actions": [{"object": bad, "to": [0, 0, 0]}]})


@pytest.mark.parametrize("shape,needle", [
    ({"type": "box", "size": [1e-300, 0.04, 0.04]}, "box size"),
    ({"type": "box", "size": [1e300, 0.04, 0.04]}, "box size"),
    ({"type": "cylinder", "radius": 1e-9, "height": 0.04}, "cylinder"),
    ({"type": "cylinder", "radius": 0.02, "height": 1e6}, "cylinder"),
    ({"type": "polygon", "points": [[0, 0], [1e9, 0], [0, 1e9]], "height": 0.02}, "polygon points"),
    ({"type": "polygon", "points": [[0, 0], [0.1, 0], [0, 0.1]], "height": 1e-300}, "polygon height"),
    ({"type": "points", "points": [[0, 0, 0], [1e300, 0, 0], [0, 1e300, 0]]}, "cloud points"),
])
def test_sizes_are_bounded(shape, needle):
    obj = {"id": 1, "name": "x", "shape": shape, "pose": [0.0, 0.0, 0.0]}
    with pytest.raises(InputError, match=needle):
        parse_scene(scene(obj))


@pytest.mark.parametrize("pose", [[1e300, 0, 0], [0, -1e4, 0], [0, 0, 1e300]])
def test_poses_are_bounded(pose):
    with pytest.raises(InputError, match="pose"):
        parse_scene(scene(box(1, pose[0], pose[1], theta=pose[2])))
    with pytest.raises(InputError, match="goal pose"):
        parse_goals(goals({"pattern": "pose", "objects": [1], "pose": pose}))


def test_counts_are_bounded():
    with pytest.raises(InputError, match="at most"):
        parse_plan({"solved": True, "actions": [{"object": 1, "to": [0, 0, 0]}] * (limits.MAX_ACTIONS + 1)})
    with pytest.raises(InputError, match="at most"):
        parse_scene(scene(box(1, 0, 0, name="x" * (limits.MAX_TEXT + 1))))


def test_long_on_chain_loads_in_linear_time():
    """A stack of MAX_OBJECTS objects loads (the former cycle check took minutes: cubic)."""
    code = (
        "from lgmcts.formats import parse_scene\n"
        "from lgmcts import limits\n"
        "n = limits.MAX_OBJECTS\n"
        "objs = [{'id': i, 'name': 'b', 'shape': {'type': 'box', 'size': [0.04, 0.04, 0.01]},"
        " 'pose': [0, 0, 0], 'on': i - 1 if i else None} for i in range(n)]\n"
        "parse_scene({'workspace': {'x': [-1, 1], 'y': [-1, 1]}, 'objects': objs})\n"
        "objs[0]['on'] = n - 1\n"
        "try:\n    parse_scene({'workspace': {'x': [-1, 1], 'y': [-1, 1]}, 'objects': objs})\n"
        "except ValueError as e:\n    assert 'cycle' in str(e); print('ok')\n"
    )
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, timeout=60,
                         env={**os.environ, "PYTHONPATH": os.getcwd()})
    assert out.stdout.strip() == "ok", out.stderr


def test_long_tower_and_relation_chains_are_checked_quickly():
    n = 3000
    objs = [box(i, 0, 0, on=i - 1 if i else None) for i in range(n)]
    sc = parse_scene(scene(*objs))
    gs = parse_goals(goals({"pattern": "tower", "objects": list(range(n))}))
    gs.check_against(sc)
    chain = [{"pattern": "left", "objects": [i + 1], "anchor": i} for i in range(n - 1)]
    parse_goals(goals(*chain)).check_against(sc)
    with pytest.raises(InputError, match="cycle"):
        parse_goals(goals(*chain, {"pattern": "left", "objects": [0], "anchor": n - 1})).check_against(sc)


# ---------------------------------------------------------------- files


@pytest.mark.parametrize("loader", [load_scene, load_goals, load_plan])
def test_deeply_nested_json_is_one_line(loader, tmp_path):
    f = tmp_path / "deep.json"
    f.write_text("[" * 100_000)
    with pytest.raises(InputError, match="nested too deeply"):
        loader(f)


def test_byte_cap_is_enforced_and_overridable(tmp_path, monkeypatch):
    f = tmp_path / "scene.json"
    f.write_text(json.dumps(scene(box(1, 0, 0))))
    monkeypatch.setenv(limits.MAX_INPUT_BYTES_ENV, "50")
    with pytest.raises(InputError, match="larger than 50 bytes"):
        load_scene(f)
    monkeypatch.setenv(limits.MAX_INPUT_BYTES_ENV, "nonsense")
    with pytest.raises(InputError, match=limits.MAX_INPUT_BYTES_ENV):
        load_scene(f)
    monkeypatch.setenv(limits.MAX_INPUT_BYTES_ENV, "100000")
    load_scene(f)


@pytest.mark.skipif(not hasattr(os, "mkfifo"), reason="needs FIFOs")
def test_fifo_is_refused_without_blocking(tmp_path):
    fifo = tmp_path / "pipe.json"
    os.mkfifo(fifo)
    with pytest.raises(InputError, match="not a regular file"):
        load_scene(fifo)


@pytest.mark.skipif(not os.path.exists("/dev/zero"), reason="needs /dev/zero")
def test_devices_and_folders_are_refused(tmp_path):
    with pytest.raises(InputError, match="not a regular file"):
        load_plan("/dev/zero")
    with pytest.raises(InputError, match="folder"):
        load_goals(tmp_path)
