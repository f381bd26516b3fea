"""Pieces of the service that need no server: error lines, the viewer page, options."""

from __future__ import annotations

import pytest

from lgmcts.errors import InputError
from lgmcts.formats import parse_scene
from lgmcts.service import ServiceOptions, viewer
from lgmcts.service.app import validation_message

pytestmark = pytest.mark.slow


@pytest.mark.parametrize(
    "errors, line",
    [
        ([], "invalid request"),
        (
            [
                {
                    "type": "json_invalid",
                    "loc": ("body", 3),
                    "msg": "JSON decode error",
                    "ctx": {"error": "Expecting value"},
                }
            ],
            "invalid request: the body is not valid JSON (Expecting value)",
        ),
        ([{"type": "missing", "loc": ("body",), "msg": "Field required"}], "invalid request: a JSON body is required"),
        (
            [{"type": "missing", "loc": ("body", "goals"), "msg": "Field required"}],
            "invalid request: 'goals' is required",
        ),
        (
            [
                {
                    "type": "value_error",
                    "loc": ("body", "scene", "function-after[_consistent()]"),
                    "msg": "Value error, duplicate object id 1",
                }
            ],
            "invalid scene: duplicate object id 1",
        ),
        (
            [{"type": "int_parsing", "loc": ("body", "options", "seed"), "msg": "bad int"}],
            "invalid request at options.seed: bad int",
        ),
    ],
)
def test_validation_message(errors, line):
    assert validation_message(errors) == line


def test_validation_message_matches_the_format_loader():
    bad = {
        "workspace": {"x": [0, 1], "y": [0, 1]},
        "objects": [{"id": 1, "name": "a", "shape": {"type": "box", "size": [1, 1]}, "pose": [0, 0, 0]}],
    }
    from pydantic import ValidationError

    from lgmcts.formats import SceneSpec

    try:
        SceneSpec.model_validate(bad)
    except ValidationError as err:
        errors = [{**e, "loc": ("body", "scene", *e["loc"])} for e in err.errors()]
    with pytest.raises(InputError) as exc:
        parse_scene(bad)
    assert validation_message(errors) == str(exc.value)


def test_viewer_script_is_inlined_safely(tmp_path, monkeypatch):
    js = tmp_path / "viewer.js"
    js.write_text('window.LGMCTSViewer = {render: function (c, d) { c.innerHTML = "</script><b>" + "<!--"; }};')
    monkeypatch.setattr(viewer, "VIEWER_JS", js)
    html = viewer.page()
    assert "window.LGMCTSViewer = {render" in html
    body = html.split("<script>", 1)[1].split("</script>", 1)[0]
    assert "</script" not in body.lower() and "<!--" not in body
    assert "<\\/script>" in body


def test_example_scene_is_valid():
    parse_scene(viewer.EXAMPLE_SCENE)


@pytest.mark.parametrize(
    "kwargs, message",
    [
        ({"workers": 0}, "workers must be at least 1"),
        ({"timeout": -1.0}, "timeout must be positive"),
        ({"max_iter": 0}, "max_iter must be at least 1"),
        ({"grace": 0.0}, "grace must be positive"),
    ],
)
def test_service_options_reject_bad_limits(kwargs, message):
    with pytest.raises(InputError, match=message):
        ServiceOptions(**kwargs)


def test_test_hooks_are_off_unless_the_environment_says_so(monkeypatch):
    import json
    from pathlib import Path

    from lgmcts.service.app import TEST_HOOKS_ENV, options_from_env

    monkeypatch.delenv(TEST_HOOKS_ENV, raising=False)
    assert options_from_env().test_hooks is False
    monkeypatch.setenv(TEST_HOOKS_ENV, "1")
    assert options_from_env().test_hooks is True
    root = Path(__file__).resolve().parents[2]
    body = {
        "scene": json.loads((root / "examples" / "tabletop.json").read_text()),
        "goals": json.loads((root / "examples" / "goals.json").read_text()),
        "options": {"method": "_crash"},
    }
    # The intake worker refuses the method before any planning worker would be needed.
    from lgmcts.service import jobs
    from lgmcts.service.bodies import Body, Policy

    with pytest.raises(InputError) as exc:
        jobs.inspect(Body("plan", json.dumps(body).encode(), Policy(test_hooks=False)))
    assert str(exc.value) == "unknown method '_crash' (known: lgmcts, greedy, pmcts)"
    assert jobs.inspect(Body("plan", json.dumps(body).encode(), Policy(test_hooks=True)))["instruction"] is False


def test_a_missing_extra_is_a_501_naming_it(monkeypatch):
    """The parse job turns a missing optional module into Unavailable (501) with the extra to install."""
    import lgmcts.language
    from lgmcts.service import jobs

    def parse(*args, **kwargs):
        raise ModuleNotFoundError("No module named 'onnxruntime'", name="onnxruntime")

    monkeypatch.setattr(lgmcts.language, "parse", parse)
    scene = parse_scene(viewer.EXAMPLE_SCENE)
    with pytest.raises(jobs.Unavailable, match=r"pip install 'lgmcts\[language\]'"):
        jobs.run_parse(jobs.ParseJob(scene, "put the blocks in a line"))

    def broken(*args, **kwargs):
        raise ModuleNotFoundError("No module named 'lgmcts_internal_typo'", name="lgmcts_internal_typo")

    monkeypatch.setattr(lgmcts.language, "parse", broken)
    with pytest.raises(ModuleNotFoundError):  # a real bug is not dressed up as a missing extra
        jobs.run_parse(jobs.ParseJob(scene, "put the blocks in a line"))
