"""Reading input files safely: regular files only, a byte cap, bounded JSON nesting.

Every loader of the package reads through these helpers, so a FIFO, a device
(``/dev/zero``), an over-long file or JSON nested a hundred thousand levels
deep is one line of bad input (:class:`~lgmcts.errors.InputError`), never a
hang, an exhausted memory or a traceback. The byte cap is
:func:`lgmcts.limits.max_input_bytes` (``$LGMCTS_MAX_INPUT_BYTES``).
"""

from __future__ import annotations

import json
import os
import stat
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from . import limits
from .errors import InputError

__all__ = ["loads", "read_lines", "read_text"]


def _open(path: Path, what: str) -> int:
    """A descriptor of ``path``, refused unless it is a regular file.

    Opened non-blocking so that a FIFO without a writer cannot hang the open;
    the type is then checked on the open descriptor, not on the name.
    """
    try:
        fd = os.open(path, os.O_RDONLY | getattr(os, "O_NONBLOCK", 0))
    except FileNotFoundError:
        raise InputError(f"{what} file not found: {path}") from None
    except OSError as exc:
        raise InputError(f"cannot read {what} file {path}: {exc.strerror}") from None
    try:
        mode = os.fstat(fd).st_mode
    except OSError as exc:  # pragma: no cover - fstat of an open descriptor
        os.close(fd)
        raise InputError(f"cannot read {what} file {path}: {exc.strerror}") from None
    if not stat.S_ISREG(mode):
        os.close(fd)
        kind = "a folder" if stat.S_ISDIR(mode) else "not a regular file"
        raise InputError(f"{what} file {path} is {kind}")
    return fd


def read_text(path: str | Path, what: str) -> str:
    """The UTF-8 text of the regular file ``path``, at most the byte cap long."""
    path = Path(path)
    cap = limits.max_input_bytes()
    fd = _open(path, what)
    try:
        with os.fdopen(fd, "rb") as fh:
            data = fh.read(cap + 1)
    except OSError as exc:
        raise InputError(f"cannot read {what} file {path}: {exc.strerror}") from None
    if len(data) > cap:
        raise InputError(
            f"{what} file {path} is larger than {cap} bytes (raise the cap with {limits.MAX_INPUT_BYTES_ENV})"
        )
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError:
        raise InputError(f"cannot read {what} file {path}: it is not UTF-8 text") from None


def read_lines(path: str | Path, what: str) -> Iterator[tuple[int, str]]:
    """``(line number, line)`` of a JSONL file; each line at most the byte cap long."""
    path = Path(path)
    cap = limits.max_input_bytes()
    fd = _open(path, what)
    with os.fdopen(fd, "rb") as fh:
        n = 0
        while True:
            try:
                raw = fh.readline(cap + 1)
            except OSError as exc:
                raise InputError(f"cannot read {what} file {path}: {exc.strerror}") from None
            if not raw:
                return
            n += 1
            if len(raw) > cap:
                raise InputError(
                    f"{path} line {n} is longer than {cap} bytes (raise the cap with {limits.MAX_INPUT_BYTES_ENV})"
                )
            try:
                yield n, raw.decode("utf-8")
            except UnicodeDecodeError:
                raise InputError(f"{path} line {n} is not UTF-8 text") from None


class _DuplicateKey(Exception):
    def __init__(self, key: str) -> None:
        super().__init__(key)
        self.key = key


def _unique_keys(pairs: list[tuple[str, Any]]) -> dict[str, Any]:
    """``object_pairs_hook`` refusing an object that names a key twice (JSON lets the last win silently)."""
    out: dict[str, Any] = {}
    for key, value in pairs:
        if key in out:
            raise _DuplicateKey(key)
        out[key] = value
    return out


def loads(text: str | bytes, where: str) -> Any:
    """``json.loads`` whose failures are one line naming ``where``.

    Malformed JSON raises ``json.JSONDecodeError`` as before (callers word
    it); everything else that makes the text unusable raises
    :class:`InputError`: JSON nested deeper than the interpreter can parse,
    an object naming the same key twice, an integer longer than Python reads
    (``sys.get_int_max_str_digits``), bytes that are not UTF-8.
    """
    try:
        return json.loads(text, object_pairs_hook=_unique_keys)
    except RecursionError:
        raise InputError(f"{where} is nested too deeply") from None
    except _DuplicateKey as exc:
        key = limits.truncate(limits.printable(exc.key), 40)
        raise InputError(f"{where} names the key '{key}' twice in one object") from None
    except json.JSONDecodeError:
        raise
    except UnicodeDecodeError:
        raise InputError(f"{where} is not UTF-8 text") from None
    except ValueError:
        # json raises a bare ValueError for an integer with too many digits.
        raise InputError(f"{where} holds a number with too many digits") from None
