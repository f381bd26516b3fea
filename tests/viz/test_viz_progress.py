"""Log levels (lgmcts.cli_util.configure_logging) and the drawing progress bar."""

from __future__ import annotations

import io
import logging
from pathlib import Path

import pytest
from typer.testing import CliRunner

from lgmcts.cli import app
from lgmcts.cli_util import LOGGER_NAME, configure_logging

DATA = Path(__file__).parent / "data"


@pytest.fixture(autouse=True)
def _restore_logger():
    logger = logging.getLogger(LOGGER_NAME)
    saved = (logger.level, list(logger.handlers), logger.propagate)
    yield
    logger.setLevel(saved[0])
    logger.handlers[:] = saved[1]
    logger.propagate = saved[2]


class _Tty(io.StringIO):
    def isatty(self) -> bool:
        return True


@pytest.mark.parametrize(
    "verbose, info, debug", [(0, False, False), (1, True, False), (2, True, True), (5, True, True), (-1, False, False)]
)
def test_levels(capsys, verbose, info, debug):
    configure_logging(verbose)
    log = logging.getLogger("lgmcts.planner")
    log.debug("debug line")
    log.info("info line")
    log.warning("warning line")
    err = capsys.readouterr().err
    assert ("info line" in err) is info
    assert ("debug line" in err) is debug
    assert "warning line" in err
    assert "lgmcts.planner" in err


def test_configuring_twice_adds_no_second_handler(capsys):
    configure_logging(1)
    configure_logging(1)
    logging.getLogger("lgmcts.x").info("once")
    assert capsys.readouterr().err.count("once") == 1


def test_other_libraries_stay_quiet(capsys):
    configure_logging(2)
    logging.getLogger("some.library").debug("noise")
    assert "noise" not in capsys.readouterr().err


def _draw(tmp_path, stderr, monkeypatch):
    import json

    from lgmcts.viz import write_plan_figures

    plan = json.loads((DATA / "cluttered_plan.json").read_text())
    plan["actions"] = plan["actions"][:1]  # one step is enough for a bar, and quick to draw
    monkeypatch.setattr("sys.stderr", stderr)
    monkeypatch.setattr("lgmcts.viz.figures.heatmap_fields", lambda *a, **k: [])
    write_plan_figures(DATA / "cluttered_scene.json", plan, tmp_path)
    return stderr.getvalue()


@pytest.mark.slow
def test_no_bar_when_piped(tmp_path, monkeypatch):
    monkeypatch.delenv("LGMCTS_NO_PROGRESS", raising=False)
    assert "drawing steps" not in _draw(tmp_path, io.StringIO(), monkeypatch)


@pytest.mark.slow
def test_bar_on_a_terminal_unless_switched_off(tmp_path, monkeypatch):
    monkeypatch.delenv("LGMCTS_NO_PROGRESS", raising=False)
    assert "drawing steps" in _draw(tmp_path / "a", _Tty(), monkeypatch)
    monkeypatch.setenv("LGMCTS_NO_PROGRESS", "1")
    assert "drawing steps" not in _draw(tmp_path / "b", _Tty(), monkeypatch)


@pytest.mark.slow
def test_cli_verbose_shows_the_search_log():
    runner = CliRunner()
    base = ["plan", str(DATA / "cluttered_scene.json"), "--goal", str(DATA / "cluttered_goals.json"), "--seed", "2"]
    quiet = runner.invoke(app, base)
    loud = runner.invoke(app, [*base, "-v"])
    assert quiet.exit_code == loud.exit_code == 0
    assert "lgmcts.planner" not in quiet.stderr
    assert "lgmcts.planner" in loud.stderr
