"""Fuzzing the loaders and the service's request models.

Whatever the input: a valid result, or one line of bad input (``InputError``,
exit 2 on the command line, 422 in the service); never any other exception.
Inputs are valid documents with one part replaced by arbitrary JSON, and
arbitrary JSON documents.
"""

from __future__ import annotations

import copy
import json
from typing import Any

from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from lgmcts.errors import InputError
from lgmcts.formats import load_goals, load_plan, load_scene, parse_goals, parse_plan, parse_scene
from lgmcts.scene import Scene
from lgmcts.validate import check

SCENE = json.loads(open("examples/tabletop.json").read())
GOALS = json.loads(open("examples/goals.json").read())
PLAN = {"solved": True, "actions": [
    {"object": 3, "to": [-0.3, -0.05, 0.0], "on": None, "purpose": "unstack"},
    {"object": 2, "to": [-0.25, -0.05, 0.0], "on": None, "purpose": "goal"},
    {"object": 3, "to": [-0.25, -0.05, 0.0], "on": 2, "purpose": "goal"},
]}

_scalars = (
    st.none()
    | st.booleans()
    | st.integers(min_value=-(2**70), max_value=2**70)
    | st.floats(allow_nan=True, allow_infinity=True)
    | st.text(max_size=12)
    | st.sampled_from(["box", "cylinder", "polygon", "points", "line", "tower", "pose", "left", "goal", "relocate"])
)
_json = st.recursive(
    _scalars,
    lambda inner: st.lists(inner, max_size=5) | st.dictionaries(st.text(max_size=8), inner, max_size=5),
    max_leaves=20,
)


@st.composite
def _mutated(draw: Any, doc: Any) -> Any:
    """``doc`` with one part (chosen by walking down from the root) replaced by arbitrary JSON."""
    doc = copy.deepcopy(doc)
    parent, key, node = None, None, doc
    while isinstance(node, (dict, list)) and node and draw(st.booleans()):
        keys = list(node) if isinstance(node, dict) else list(range(len(node)))
        k = draw(st.sampled_from(keys))
        parent, key, node = node, k, node[k]
    value = draw(_json)
    if parent is None:
        return value
    if isinstance(parent, dict) and draw(st.integers(0, 5)) == 0:
        del parent[key]
    else:
        parent[key] = value
    return doc


def _one_line(exc: InputError) -> None:
    msg = str(exc)
    assert msg and "\n" not in msg and len(msg) <= InputError.MAX_LENGTH + 40, msg


_settings = settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])


@_settings
@given(scene=_mutated(SCENE), goals=_mutated(GOALS), plan=_mutated(PLAN))
def test_mutated_documents_load_or_fail_in_one_line(scene, goals, plan):
    try:
        sc = Scene.from_spec(parse_scene(scene))
    except InputError as exc:
        _one_line(exc)
        sc = Scene.from_spec(parse_scene(SCENE))
    try:
        gs = parse_goals(goals)
    except InputError as exc:
        _one_line(exc)
        gs = parse_goals(GOALS)
    try:
        pl = parse_plan(plan)
    except InputError as exc:
        _one_line(exc)
        pl = parse_plan(PLAN)
    try:
        verdict = check(sc, gs, pl)
    except InputError as exc:
        _one_line(exc)
        return
    assert isinstance(verdict.valid, bool)
    assert all("\n" not in r for r in verdict.reasons)


@_settings
@given(doc=_json)
def test_arbitrary_json_files(doc, tmp_path_factory):
    f = tmp_path_factory.mktemp("fuzz") / "doc.json"
    f.write_text(json.dumps(doc))
    for loader in (load_scene, load_goals, load_plan):
        try:
            loader(f)
        except InputError as exc:
            _one_line(exc)


@_settings
@given(raw=st.binary(max_size=64) | _json.map(lambda d: json.dumps(d).encode()))
def test_arbitrary_bytes_files(raw, tmp_path_factory):
    f = tmp_path_factory.mktemp("fuzz") / "doc.json"
    f.write_bytes(raw)
    for loader in (load_scene, load_goals, load_plan):
        try:
            loader(f)
        except InputError as exc:
            _one_line(exc)


@_settings
@given(
    body=st.one_of(
        _mutated({"scene": SCENE, "goals": GOALS, "options": {"method": "lgmcts", "seed": 0}}),
        _mutated({"scene": SCENE, "instruction": "put the blocks in a line"}),
        _mutated({"scene": SCENE, "goals": GOALS, "plan": PLAN}),
        _json,
    ),
)
def test_service_request_models(body):
    from lgmcts.service.app import parse_body
    from lgmcts.service.models import CheckRequest, ParseRequest, PlanRequest

    raw = json.dumps(body).encode()
    for model in (PlanRequest, ParseRequest, CheckRequest):
        try:
            req = parse_body(model, raw)
        except InputError as exc:
            _one_line(exc)
            continue
        assert isinstance(req, model)
