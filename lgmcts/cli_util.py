"""Small helpers shared by the command-line modules."""

from __future__ import annotations

import sys
from pathlib import Path
from typing import NoReturn

import typer


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
