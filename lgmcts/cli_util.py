"""Small helpers shared by the command-line modules."""

from __future__ import annotations

import os
import sys
import tempfile
from pathlib import Path
from typing import NoReturn

import typer


def fail(message: str, code: int = 2) -> NoReturn:
    """Print ``message`` as one line on stderr and exit with ``code`` (2: bad input)."""
    typer.echo(" ".join(str(message).split()), err=True)
    raise typer.Exit(code)


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
