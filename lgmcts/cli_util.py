"""Small helpers shared by the command-line modules: one-line failures,
output files and the log level chosen by ``-v``."""

from __future__ import annotations

import logging
import sys
from pathlib import Path
from typing import NoReturn

import typer
from tqdm import tqdm


def fail(message: str, code: int = 2) -> NoReturn:
    """Print ``message`` as one line on stderr and exit with ``code`` (2: bad input)."""
    typer.echo(" ".join(str(message).split()), err=True)
    raise typer.Exit(code)


def write_text(text: str, path: str | None) -> None:
    """Write ``text`` to ``path``, or to stdout when ``path`` is ``None`` or ``-``."""
    if path in (None, "-"):
        sys.stdout.write(text + "\n")
        sys.stdout.flush()
        return
    try:
        Path(path).parent.mkdir(parents=True, exist_ok=True)  # type: ignore[arg-type]
        with open(path, "w") as fh:  # type: ignore[arg-type]
            fh.write(text + "\n")
    except OSError as exc:
        fail(f"cannot write {path}: {exc.strerror}")


#: Name of the package's root logger; the planner logs to ``"lgmcts.planner"``.
LOGGER_NAME = "lgmcts"

_LEVELS = (logging.WARNING, logging.INFO, logging.DEBUG)


class _StderrHandler(logging.Handler):
    """Write records to the current ``sys.stderr`` (looked up when a record is
    written, so test capture and redirection work) through ``tqdm.write``, so
    that a line printed under a progress bar does not tear the bar."""

    def emit(self, record: logging.LogRecord) -> None:
        try:
            tqdm.write(self.format(record), file=sys.stderr)
            sys.stderr.flush()
        except Exception:  # pragma: no cover - logging must never raise
            self.handleError(record)


def configure_logging(verbose: int = 0) -> logging.Logger:
    """Send the ``"lgmcts"`` log to stderr: 0 warnings, 1 ``INFO`` (the planner's
    search log), 2 or more ``DEBUG``. Only that logger is touched (other
    libraries keep their levels) and it does not propagate to the root logger;
    calling again changes the level without adding a second handler."""
    level = _LEVELS[max(0, min(int(verbose), len(_LEVELS) - 1))]
    logger = logging.getLogger(LOGGER_NAME)
    handler = next((h for h in logger.handlers if isinstance(h, _StderrHandler)), None)
    if handler is None:
        handler = _StderrHandler()
        logger.addHandler(handler)
    fmt = "%(levelname)s %(name)s: %(message)s" if level <= logging.DEBUG else "%(name)s: %(message)s"
    handler.setFormatter(logging.Formatter(fmt))
    handler.setLevel(level)
    logger.setLevel(level)
    logger.propagate = False
    return logger
