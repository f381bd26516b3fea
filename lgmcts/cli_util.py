"""Small helpers shared by the command-line modules."""

from __future__ import annotations

import logging
import os
import sys
import tempfile
from pathlib import Path
from typing import NoReturn

import typer
from tqdm import tqdm


def fail(message: str, code: int = 2) -> NoReturn:
    """Print ``message`` as one line on stderr and exit with ``code`` (2: bad input)."""
    typer.echo(" ".join(str(message).split()), err=True)
    raise typer.Exit(code)


def _click_exceptions():
    """The exception classes of the click that typer runs on (newer typer vendors its own copy)."""
    try:
        from typer._click import exceptions as cx
    except ImportError:  # pragma: no cover - typer on the public click
        from click import exceptions as cx
    return cx


def run_app(app: typer.Typer, prog_name: str = "lgmcts") -> NoReturn:
    """Run a typer app as a program: usage errors, stray bad input and a missing
    optional extra (:mod:`lgmcts.extras`) are one line and exit 2, never a boxed panel."""
    from .errors import InputError
    from .extras import missing_extra

    cx = _click_exceptions()
    command = typer.main.get_command(app)
    try:
        code = command.main(prog_name=prog_name, standalone_mode=False)
    except cx.NoArgsIsHelpError as exc:
        typer.echo(exc.ctx.get_help() if exc.ctx is not None else str(exc), err=True)
        sys.exit(2)
    except cx.UsageError as exc:
        where = f"{exc.ctx.command_path}: " if exc.ctx is not None else ""
        typer.echo(" ".join(f"{where}{exc.format_message()}".split()) + " (see --help)", err=True)
        sys.exit(2)
    except cx.ClickException as exc:
        typer.echo(" ".join(exc.format_message().split()), err=True)
        sys.exit(exc.exit_code)
    except typer.Exit as exc:
        sys.exit(exc.exit_code)
    except InputError as exc:  # pragma: no cover - commands catch their own
        typer.echo(str(exc), err=True)
        sys.exit(2)
    except ModuleNotFoundError as exc:  # an optional extra that is not installed
        message = missing_extra(exc)
        if message is None:
            raise
        typer.echo(message, err=True)
        sys.exit(2)
    except MemoryError:
        # A last resort: every input has bounds (docs/limits.md) that keep far below this.
        typer.echo("out of memory: the input is too large for this machine (see docs/limits.md)", err=True)
        sys.exit(2)
    except (typer.Abort, KeyboardInterrupt):
        typer.echo("interrupted", err=True)
        sys.exit(130)
    sys.exit(code if isinstance(code, int) else 0)


def check_output_file(path: str | Path | None, *, make_parents: bool = True) -> None:
    """Fail (exit 2) unless ``path`` can be written as a file; ``None`` and ``-`` mean stdout.

    With ``make_parents`` false, its folder must already exist.

    Checked before any work so that a bad output location costs nothing and
    overwrites nothing.
    """
    if path in (None, "-"):
        return
    p = Path(path)  # type: ignore[arg-type]
    if p.is_dir():
        fail(f"cannot write {p}: it is a folder")
    if p.exists() and not p.is_file():
        fail(f"cannot write {p}: it is not a regular file")
    if not make_parents and not p.parent.is_dir():
        fail(f"cannot write {p}: folder {p.parent} does not exist")
    parent = _existing_parent(p.parent)
    if not parent.is_dir():
        fail(f"cannot write {p}: {parent} is not a folder")
    if not os.access(parent, os.W_OK | os.X_OK):
        fail(f"cannot write {p}: {parent} is not writable")


def check_output_dir(path: str | Path | None) -> None:
    """Fail (exit 2) unless ``path`` is, or can be made, a writable folder."""
    if path is None:
        return
    p = Path(path)
    if p.exists() and not p.is_dir():
        fail(f"cannot write pictures into {p}: it exists and is not a folder")
    parent = _existing_parent(p)
    if not parent.is_dir():
        fail(f"cannot write pictures into {p}: {parent} is not a folder")
    if not os.access(parent, os.W_OK | os.X_OK):
        fail(f"cannot write pictures into {p}: {parent} is not writable")


def _existing_parent(p: Path) -> Path:
    """``p`` or its nearest ancestor that exists."""
    p = p if str(p) else Path(".")
    while not p.exists() and p != p.parent:
        p = p.parent
    return p


def write_text(text: str, path: str | None) -> None:
    """Write ``text`` to ``path`` atomically, or to stdout when ``path`` is ``None`` or ``-``.

    The text goes to a temporary file beside ``path`` that then replaces it,
    so a reader never sees half a file and a failure leaves the old one.
    """
    if path in (None, "-"):
        sys.stdout.write(text + "\n")
        sys.stdout.flush()
        return
    target = Path(path)  # type: ignore[arg-type]
    tmp = None
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
        with os.fdopen(fd, "w") as fh:
            fh.write(text + "\n")
        os.replace(tmp, target)
        tmp = None
    except OSError as exc:
        fail(f"cannot write {path}: {exc.strerror}")
    finally:
        if tmp is not None:
            try:
                os.unlink(tmp)
            except OSError:
                pass


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
