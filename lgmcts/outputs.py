"""Writing output files so that a failure never leaves a half-written or clobbered file.

:func:`atomic_write` writes to a temporary file beside the target and
renames it over the target only once everything was written and flushed;
a full disk, a read-only folder or an interrupted run leaves the old file as
it was. The new file gets the permissions an ordinary ``open(path, "w")``
would give it: those of the file it replaces, else ``0666`` less the umask
(so a page written for a web server stays readable by it).
"""

from __future__ import annotations

import os
import stat
import tempfile
import threading
from collections.abc import Callable
from pathlib import Path
from typing import IO

from .errors import InputError

__all__ = ["atomic_write", "new_file_mode", "publish", "temporary_beside"]

_umask_lock = threading.Lock()


def _umask() -> int:
    with _umask_lock:  # os.umask can only be read by setting it
        mask = os.umask(0o022)
        os.umask(mask)
    return mask


def new_file_mode(path: str | Path) -> int:
    """The permission bits a file written at ``path`` gets: the existing file's, else ``0666`` less the umask."""
    try:
        st = os.stat(path)
    except OSError:
        return 0o666 & ~_umask()
    return stat.S_IMODE(st.st_mode) if stat.S_ISREG(st.st_mode) else 0o666 & ~_umask()


def temporary_beside(path: str | Path, suffix: str = ".tmp") -> Path:
    """A fresh, empty temporary file in the folder of ``path`` (created, so the name is ours)."""
    target = Path(path)
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=suffix, dir=target.parent)
    os.close(fd)
    return Path(tmp)


def publish(tmp: str | Path, path: str | Path) -> None:
    """Give ``tmp`` the permissions of :func:`new_file_mode` and rename it over ``path``."""
    os.chmod(tmp, new_file_mode(path))
    os.replace(tmp, path)


def atomic_write(path: str | Path, content: str | bytes | Callable[[IO[str]], None], *, what: str = "") -> None:
    """Write ``content`` (text, bytes, or a function writing to a text stream) to ``path`` atomically.

    Raises
    ------
    InputError
        One line (``cannot write PATH: No space left on device``) when the
        file cannot be written; the old file, if any, is untouched and no
        temporary file is left behind.
    """
    target = Path(path)
    tmp: Path | None = None
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        tmp = temporary_beside(target)
        if isinstance(content, bytes):
            with open(tmp, "wb") as fb:
                fb.write(content)
        else:
            with open(tmp, "w", encoding="utf-8") as fh:
                if isinstance(content, str):
                    fh.write(content)
                else:
                    content(fh)
        publish(tmp, target)
        tmp = None
    except OSError as exc:
        label = f"{what} " if what else ""
        raise InputError(f"cannot write {label}{target}: {exc.strerror or exc}") from None
    finally:
        if tmp is not None:
            try:
                os.unlink(tmp)
            except OSError:
                pass
