"""Small helpers shared by the command-line modules."""

from __future__ import annotations

import errno
import io
import logging
import os
import sys
from pathlib import Path
from typing import NoReturn

import typer


def fail(message: str, code: int = 2) -> NoReturn:
    """Print ``message`` as one line on stderr and exit with ``code`` (2: bad input).

    Control characters (from names in the input) are escaped, never sent raw.
    """
    typer.echo(one_line(message), err=True)
    raise typer.Exit(code)


def one_line(message: object) -> str:
    """``message`` on one line, runs of white space made single spaces, control characters escaped."""
    from .limits import printable

    return printable(" ".join(str(message).split()))


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
    if sys.stdout is None:  # started with stdout closed: writing must fail, not vanish
        sys.stdout = _ClosedStdout()
    try:
        code = command.main(prog_name=prog_name, standalone_mode=False)
        sys.stdout.flush()
    except cx.NoArgsIsHelpError as exc:
        typer.echo(exc.ctx.get_help() if exc.ctx is not None else str(exc), err=True)
        sys.exit(2)
    except cx.UsageError as exc:
        where = f"{exc.ctx.command_path}: " if exc.ctx is not None else ""
        typer.echo(one_line(f"{where}{exc.format_message()}") + " (see --help)", err=True)
        sys.exit(2)
    except cx.ClickException as exc:
        typer.echo(one_line(exc.format_message()), err=True)
        sys.exit(exc.exit_code)
    except typer.Exit as exc:
        sys.exit(exc.exit_code)
    except SystemExit as exc:
        # Loaded code (a pattern module, a plug-in planner) called sys.exit: a
        # success status would read as "solved" or "valid", so it is an error.
        if exc.code in (0, None):
            _stderr_line("the program was ended by sys.exit(0) in loaded code (a pattern module or plug-in)")
            sys.exit(2)
        raise
    except InputError as exc:  # pragma: no cover - commands catch their own
        typer.echo(one_line(exc), err=True)
        sys.exit(2)
    except ModuleNotFoundError as exc:  # an optional extra that is not installed
        message = missing_extra(exc)
        if message is None:
            raise
        typer.echo(message, err=True)
        sys.exit(2)
    except OSError as exc:
        # Writing the answer failed (stdout closed, on a full device, a broken pipe):
        # every file output has its own message; what is left is stdout.
        _silence_stdout()
        typer.echo(f"cannot write output: {exc.strerror or exc}", err=True)
        sys.exit(2)
    except MemoryError:
        # A last resort: every input has bounds (docs/limits.md) that keep far below this.
        typer.echo("out of memory: the input is too large for this machine (see docs/limits.md)", err=True)
        sys.exit(2)
    except (typer.Abort, KeyboardInterrupt):
        typer.echo("interrupted", err=True)
        sys.exit(130)
    sys.exit(code if isinstance(code, int) else 0)


class _ClosedStdout(io.TextIOBase):
    """Stands for a stdout that was closed before the program started: writing to it fails."""

    def writable(self) -> bool:
        return True

    def write(self, text: str) -> int:
        raise OSError(errno.EBADF, "standard output is closed")


def _stderr_line(text: str) -> None:
    try:
        typer.echo(text, err=True)
    except OSError:  # pragma: no cover - stderr gone too
        pass


def _silence_stdout() -> None:
    """Point file descriptor 1 at the null device so nothing more fails on it, not even at exit."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, 1)
        os.close(devnull)
    except OSError:
        pass


def check_output_file(path: str | Path | None, *, make_parents: bool = True) -> None:
    """Fail (exit 2) unless ``path`` can be written as a file; ``None`` and ``-`` mean stdout.

    With ``make_parents`` false, its folder must already exist.

    Checked before any work so that a bad output location costs nothing and
    overwrites nothing.
    """
    if path in (None, "-"):
        return
    p = Path(path)
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

    The text goes to a temporary file beside ``path`` that then replaces it
    (:func:`lgmcts.outputs.atomic_write`), so a reader never sees half a file,
    a failure leaves the old one, and the file's permissions follow the umask
    (or the file it replaces). A failure is one line and exit status 2.
    """
    from .errors import InputError
    from .outputs import atomic_write

    if path in (None, "-"):
        write_stdout(text + "\n")
        return
    try:
        atomic_write(path, text + "\n")
    except InputError as exc:
        fail(str(exc))


def write_stdout(text: str) -> None:
    """Print ``text`` on stdout; a closed, full or broken stdout is one line on stderr and exit status 2."""
    out = sys.stdout
    try:
        if out is None:
            raise OSError(errno.EBADF, "it is closed")
        out.write(text)
        out.flush()
    except (OSError, ValueError) as exc:
        _silence_stdout()  # nothing more may reach the broken stream, not even at exit
        reason = exc.strerror if isinstance(exc, OSError) and exc.strerror else "it is closed"
        fail(f"cannot write to standard output: {reason}")


#: Name of the package's root logger; the planner logs to ``"lgmcts.planner"``.
LOGGER_NAME = "lgmcts"

_LEVELS = (logging.WARNING, logging.INFO, logging.DEBUG)


class _StderrHandler(logging.Handler):
    """Write records to the current ``sys.stderr`` (looked up when a record is
    written, so test capture and redirection work) through ``tqdm.write``, so
    that a line printed under a progress bar does not tear the bar."""

    def emit(self, record: logging.LogRecord) -> None:
        try:
            # Imported on first use: at module level it costs every command's start-up.
            from tqdm import tqdm

            from .limits import printable

            tqdm.write(printable(self.format(record)), file=sys.stderr)
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
