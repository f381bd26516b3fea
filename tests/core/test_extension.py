"""A pattern added in one module (examples/plugins/column.py) reaches the
goal format, the validator and the planner without touching the package."""

from __future__ import annotations

import importlib.util
import sys

import pytest

from lgmcts import check, plan
from lgmcts.errors import InputError
from lgmcts.formats import PatternFormat, declare_pattern, parse_goals, pattern_names


@pytest.fixture
def column(root):
    from lgmcts import formats, validate
    from lgmcts.patterns import base

    spec = importlib.util.spec_from_file_location("column_plugin", root / "examples" / "plugins" / "column.py")
    mod = importlib.util.module_from_spec(spec)
    sys.modules["column_plugin"] = mod
    spec.loader.exec_module(mod)
    try:
        yield mod
    finally:
        sys.modules.pop("column_plugin", None)
        base._REGISTRY.pop("column", None)
        validate._RULES.pop("column", None)
        formats._FORMATS.pop("column", None)


def _scene(n: int = 4) -> dict:
    objs = [{"id": i + 1, "name": "block", "color": "red", "shape": {"type": "box", "size": [0.04, 0.04, 0.04]},
             "pose": [-0.3 + 0.15 * i, -0.2 + 0.1 * (i % 2), 0.0], "on": None} for i in range(n)]
    return {"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}, "objects": objs}


def test_unknown_until_the_module_is_imported():
    assert "column" not in pattern_names()
    with pytest.raises(InputError, match="unknown pattern 'column'"):
        parse_goals({"goals": [{"pattern": "column", "objects": [1, 2]}]})


def test_a_plugin_pattern_is_planned_and_checked(column):
    assert "column" in pattern_names()
    goals = {"goals": [{"pattern": "column", "objects": [1, 2, 3, 4]}]}
    for seed in range(3):
        p = plan(_scene(), goals, seed=seed)
        assert p.solved
        v = check(_scene(), goals, p)
        assert v.valid, v.reasons
        xs = [a.to[0] for a in p.actions]
        assert max(xs) - min(xs) <= 0.03
    # The plugin's own rule judges: the start state is no column.
    v = check(_scene(), goals, {"solved": True, "actions": [], "goals": goals})
    assert not v.valid and "off the column" in v.reasons[0]
    # Its format is enforced like a built-in one.
    with pytest.raises(InputError, match="at least 2 objects"):
        parse_goals({"goals": [{"pattern": "column", "objects": [1]}]})


@pytest.mark.parametrize("size", ["small", "large", 0.3])
def test_a_plugin_pattern_with_a_size_is_planned_and_checked(column, size):
    """The plugin declares a size (size_word, size, size_band): goals carry it,
    the planner honours it and the validator judges it with the plugin's rule."""
    from lgmcts import load_scene
    from lgmcts.params import SIZE_TOL, size_range, sized_pattern
    from lgmcts.scene import Scene

    assert parse_goals({"goals": [{"pattern": "column", "objects": [1, 2], "size": size}]}).goals[0].size == size
    assert sized_pattern("column") is not None
    goals = {"goals": [{"pattern": "column", "objects": [1, 2, 3, 4], "size": size}]}
    sc = Scene.from_spec(load_scene(_scene()))
    r = float(sc.radii.max())
    xmin, xmax, ymin, ymax = sc.bounds
    lo, hi = size_range("column", 4, r, (xmin + r, xmax - r, ymin + r, ymax - r), size)
    p = plan(_scene(), goals, seed=0)
    assert p.solved
    v = check(_scene(), goals, p)
    assert v.valid, v.reasons
    final = {o["id"]: o["pose"][1] for o in _scene()["objects"]}
    final.update({a.object: a.to[1] for a in p.actions})
    length = max(final.values()) - min(final.values())
    assert lo - SIZE_TOL <= length <= hi + SIZE_TOL
    # The same plan judged against another size fails on the plugin's size rule.
    other = {"goals": [{"pattern": "column", "objects": [1, 2, 3, 4], "size": 0.05 if length > 0.2 else 0.5}]}
    v = check(_scene(), other, p)
    assert not v.valid and "length" in v.reasons[0]


def test_declarations_cannot_clash_or_replace_built_ins():
    from lgmcts.validate import register_rule

    with pytest.raises(ValueError, match="declared differently"):
        declare_pattern(PatternFormat("line", min_objects=5))
    with pytest.raises(ValueError, match="built-in"):
        register_rule("line", lambda *a: None)
    with pytest.raises(ValueError, match="declare pattern"):
        register_rule("never_declared", lambda *a: None)


def test_a_declared_pattern_without_a_prior_is_a_clear_error():
    from lgmcts import formats

    declare_pattern(PatternFormat("prior_less", min_objects=2))
    try:
        with pytest.raises(InputError, match="has no prior"):
            plan(_scene(), {"goals": [{"pattern": "prior_less", "objects": [1, 2]}]})
    finally:
        formats._FORMATS.pop("prior_less", None)


def _cli(*args: str, env: dict | None = None):
    import os
    import subprocess

    e = {k: v for k, v in os.environ.items() if k != "LGMCTS_PATTERN_MODULES"}
    e.update(env or {})
    return subprocess.run([sys.executable, "-m", "lgmcts", *args], capture_output=True, text=True, timeout=300, env=e)


@pytest.mark.slow
def test_cli_loads_pattern_modules(root, tmp_path):
    import json

    plugin = str(root / "examples" / "plugins" / "column.py")
    scene = str(root / "examples" / "tabletop.json")
    goals = tmp_path / "g.json"
    goals.write_text(json.dumps({"goals": [{"pattern": "column", "objects": [1, 2, 3]}]}))
    out = tmp_path / "p.json"
    r = _cli("plan", scene, "--goal", str(goals))
    assert r.returncode == 2 and "unknown pattern 'column'" in r.stderr
    r = _cli("--pattern-module", plugin, "plan", scene, "--goal", str(goals), "-o", str(out))
    assert r.returncode == 0, r.stderr
    r = _cli("check", scene, str(goals), str(out), env={"LGMCTS_PATTERN_MODULES": plugin})
    assert r.returncode == 0 and r.stdout.startswith("valid"), r.stdout + r.stderr
    r = _cli("--pattern-module", "no_such_module_xyz", "check", scene, str(goals), str(out))
    assert r.returncode == 2 and r.stderr.strip().count("\n") == 0 and "no_such_module_xyz" in r.stderr


def test_a_plugin_pattern_is_drawn_and_known_to_language(column):
    """One register() call: goal_shapes draws the column from its own shape,
    the HTML viewer gets it, and the language database lists its keys."""
    import numpy as np

    from lgmcts.language.matcher import pattern_infos
    from lgmcts.scene import Scene
    from lgmcts.viz import viewer_data
    from lgmcts.viz.model import goal_shapes, replay

    goals = {"goals": [{"pattern": "column", "objects": [1, 2, 3, 4]}]}
    p = plan(_scene(), goals, seed=0)
    sc = Scene.from_spec(parse_scene_dict(_scene()))
    final = replay(sc, p.actions)[-1]
    (shape,) = goal_shapes(sc, parse_goals(goals), final)
    assert shape.met and shape.kind == "line"
    (x0, y0), (x1, y1) = shape.geometry["points"]
    xy = final.poses[[sc.index[i] for i in (1, 2, 3, 4)], :2]
    assert x0 == x1 == pytest.approx(xy[:, 0].mean())
    assert (y0, y1) == pytest.approx((xy[:, 1].min(), xy[:, 1].max()))
    assert np.isfinite(np.asarray(shape.geometry["points"])).all()
    start = goal_shapes(sc, parse_goals(goals), sc.initial)[0]
    assert not start.met and "off the column" in start.problem
    data = viewer_data(_scene(), p)
    last = data["frames"][-1]["goals"][0]
    assert last["kind"] == "line" and last["met"] and np.allclose(last["points"], shape.geometry["points"], atol=1e-6)
    info = pattern_infos()["column"]
    assert "in a column" in info.keys and info.min_objects == 2 and not info.anchored


def parse_scene_dict(d):
    from lgmcts.formats import parse_scene

    return parse_scene(d)
