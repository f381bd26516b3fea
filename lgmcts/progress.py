"""Progress bars and log set-up for long-running work.

Two small helpers used at the edges of the library (command line, benchmark
runner, batch scripts); the core never imports this module.

* :func:`configure_logging` routes the ``"lgmcts"`` logger (and with it the
  planner's search log ``"lgmcts.planner"``) to stderr at a level chosen by
  how many ``-v`` flags were given.
* :func:`progress` wraps an iterable in a progress bar when stderr is a
  terminal, and returns the iterable untouched otherwise, so piped or
  redirected runs stay quiet.

Log records are written through ``tqdm.write`` so that a message printed
while a bar is on screen does not tear the bar apart.
"""

from __future__ import annotations

import logging
import os
import sys
from typing import Iterable, TypeVar

__all__ = ["configure_logging", "progress", "progress_enabled", "LOGGER_NAME"]

#: Name of the package's root logger; the planner logs to ``"lgmcts.planner"``.
LOGGER_NAME = "lgmcts"

T = TypeVar("T")

_LEVELS = (logging.WARNING, logging.INFO, logging.DEBUG)


class _StderrHandler(logging.Handler):
    """Write records to the *current* ``sys.stderr`` (looked up at emit time).

    Looking the stream up late keeps the handler correct when stderr is
    replaced after set-up (test capture, ``contextlib.redirect_stderr``).
    """

    def emit(self, record: logging.LogRecord) -> None:
        try:
            msg = self.format(record)
            stream = sys.stderr
            try:
                from tqdm import tqdm

                tqdm.write(msg, file=stream)
            except ImportError:  # pragma: no cover - tqdm is a dependency
                stream.write(msg + "\n")
            stream.flush()
        except Exception:  # pragma: no cover - logging must never raise
            self.handleError(record)


def configure_logging(verbose: int = 0) -> logging.Logger:
    """Send the package's log to stderr at a level chosen by ``verbose``.

    Parameters
    ----------
    verbose : int
        0: warnings and errors only; 1: ``INFO`` (the planner's search log:
        iterations, best depth, solutions found, relocations); 2 or more:
        ``DEBUG`` (per-iteration detail). Negative values count as 0.

    Returns
    -------
    logging.Logger
        The ``"lgmcts"`` logger. Calling this again only changes its level;
        it never adds a second handler.

    Notes
    -----
    Only the ``"lgmcts"`` logger is touched: third-party libraries keep their
    own levels, so ``-vv`` does not flood the terminal with their debug
    output. The logger does not propagate to the root logger, so a root
    handler configured elsewhere does not print every line twice.
    """
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


def progress_enabled(stream: object | None = None) -> bool:
    """Whether a progress bar should be drawn on ``stream`` (default stderr).

    False when the stream is not a terminal, or when the environment sets
    ``LGMCTS_NO_PROGRESS`` to a non-empty value other than ``0``.
    """
    flag = os.environ.get("LGMCTS_NO_PROGRESS", "")
    if flag and flag != "0":
        return False
    stream = sys.stderr if stream is None else stream
    isatty = getattr(stream, "isatty", None)
    try:
        return bool(isatty and isatty())
    except (ValueError, OSError):  # a closed stream
        return False


def progress(iterable: Iterable[T], *, total: int | None = None, desc: str = "", disable: bool | None = None) -> Iterable[T]:
    """Iterate over ``iterable`` with a progress bar on a terminal.

    Parameters
    ----------
    iterable : Iterable
        What to iterate over; consumed lazily, once.
    total : int, optional
        Number of items, when ``len(iterable)`` is not available (generators,
        ``imap`` results). Without it the bar shows a count and a rate only.
    desc : str
        Short label shown before the bar.
    disable : bool, optional
        Force the bar off (True) or decide automatically (None: shown only
        when stderr is a terminal, see :func:`progress_enabled`). ``False``
        forces it on, which is only useful for testing.

    Returns
    -------
    Iterable
        ``iterable`` itself when no bar is shown (so nothing is printed and
        nothing is slowed down), else a ``tqdm`` wrapper writing to stderr.
    """
    show = progress_enabled() if disable is None else not disable
    if not show:
        return iterable
    from tqdm import tqdm

    if total is None:
        try:
            total = len(iterable)  # type: ignore[arg-type]
        except TypeError:
            total = None
    return tqdm(iterable, total=total, desc=desc or None, file=sys.stderr, dynamic_ncols=True, leave=False, unit="it")

