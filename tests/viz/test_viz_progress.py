"""Progress bars and log levels (lgmcts.progress)."""

from __future__ import annotations

import io
import logging
from pathlib import Path

import pytest
from typer.testing import CliRunner

from lgmcts.cli import app
from lgmcts.progress import LOGGER_NAME, configure_logging, progress, progress_enabled

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


@pytest.mark.parametrize("verbose, info, debug", [(0, False, False), (1, True, False), (2, True, True), (5, True, True), (-1, False, False)])
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


def test_progress_is_transparent_when_piped(monkeypatch, capsys):
    monkeypatch.setattr("sys.stderr", io.StringIO())
    items = [1, 2, 3]
    assert progress(items, desc="x") is items
    assert not progress_enabled()


def test_progress_draws_on_a_terminal(monkeypatch):
    fake = _Tty()
    monkeypatch.setattr("sys.stderr", fake)
    monkeypatch.delenv("LGMCTS_NO_PROGRESS", raising=False)
    assert progress_enabled()
    out = list(progress(iter(range(5)), total=5, desc="cases"))
    assert out == [0, 1, 2, 3, 4]
    text = fake.getvalue()
    assert "cases" in text and "/5" in text and "it/s" in text


def test_environment_switch_turns_bars_off(monkeypatch):
    monkeypatch.setattr("sys.stderr", _Tty())
    monkeypatch.setenv("LGMCTS_NO_PROGRESS", "1")
    items = (i for i in range(3))
    assert progress(items) is items


def test_cli_verbose_shows_the_search_log():
    runner = CliRunner()
    base = ["plan", str(DATA / "cluttered_scene.json"), "--goal", str(DATA / "cluttered_goals.json"), "--seed", "2"]
    quiet = runner.invoke(app, base)
    loud = runner.invoke(app, [*base, "-v"])
    assert quiet.exit_code == loud.exit_code == 0
    assert "lgmcts.planner" not in quiet.stderr
    assert "lgmcts.planner" in loud.stderr
