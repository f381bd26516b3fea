"""Every bound the input formats, the loaders and the service enforce.

``docs/limits.md`` lists each with its reason. The bounds sit far beyond any
real tabletop (a table is about a metre across, an object a few centimetres)
so that no honest input meets them; they exist so that hostile input fails as
one line of bad input instead of exhausting memory or time, or reaching
arithmetic where floating point stops meaning anything.

This module imports nothing from the package; every layer may read it.
"""

from __future__ import annotations

import os

__all__ = [
    "MAX_ACTIONS",
    "MAX_ANGLE",
    "MAX_CLOUD_POINTS",
    "MAX_COORD",
    "MAX_GOALS",
    "MAX_ID",
    "MAX_INPUT_BYTES",
    "MAX_INPUT_BYTES_ENV",
    "MAX_INSTRUCTION",
    "MAX_LENGTH",
    "MAX_OBJECTS",
    "MAX_POLYGON_POINTS",
    "MAX_TEXT",
    "MAX_VIEW_CELLS",
    "MAX_VIEW_DRAWN",
    "MIN_LENGTH",
    "START_OVERLAP_AREA",
    "max_input_bytes",
    "printable",
    "truncate",
]

#: Largest absolute value of a table-frame coordinate (poses, workspace
#: bounds, action targets, point-cloud points), metres. At 1e3 m a double
#: still resolves 1e-13 m, so footprints keep their shape.
MAX_COORD = 1_000.0

#: Largest absolute yaw (rad). Yaws are taken modulo 2*pi; beyond this the
#: sine and cosine of a double lose the precision of the footprint.
MAX_ANGLE = 10_000.0

#: Smallest and largest object length (box sides, radius, height, polygon
#: vertex coordinates in the object frame), metres.
MIN_LENGTH = 1e-3
MAX_LENGTH = 10.0

#: Objects in one scene.
MAX_OBJECTS = 5_000

#: Vertices of one polygon shape, and points of one point cloud.
MAX_POLYGON_POINTS = 1_000
MAX_CLOUD_POINTS = 100_000

#: Goals in one goal specification, actions in one plan.
MAX_GOALS = 10_000
MAX_ACTIONS = 100_000

#: Characters of an object's name or colour.
MAX_TEXT = 200

#: Object ids are JSON integers with ``abs(id) <= MAX_ID``.
MAX_ID = 2**31 - 1

#: Characters of a plain-language instruction.
MAX_INSTRUCTION = 2_000

#: Largest overlap (m^2) two table-level footprints of a start scene may
#: share; the validator's own overlap tolerance. Touching objects (distance
#: 0, no area in common) are legal.
START_OVERLAP_AREA = 1e-6

#: Largest ``(objects + goal members) x (actions + 1)`` the viewer data
#: (``lgmcts viz --html``, the service's ``/view``) is computed for: the
#: replay compares every pose at every step and redraws the goals of each
#: moved object. At the cap it takes about 7 s and 30 MB on a 2-core VM.
MAX_VIEW_CELLS = 10_000_000

#: Most objects and goal members the viewer's frames may list in all (each
#: frame lists the objects that changed and the goals drawn anew, whole):
#: bounds the answer of ``/view`` to tens of megabytes.
MAX_VIEW_DRAWN = 1_000_000

#: Default cap on the bytes of one input file (or one line of a JSONL file).
MAX_INPUT_BYTES = 16 * 1024 * 1024

#: Environment variable overriding :data:`MAX_INPUT_BYTES` (a positive integer).
MAX_INPUT_BYTES_ENV = "LGMCTS_MAX_INPUT_BYTES"


def max_input_bytes() -> int:
    """The byte cap on an input file: ``$LGMCTS_MAX_INPUT_BYTES`` or :data:`MAX_INPUT_BYTES`."""
    raw = os.environ.get(MAX_INPUT_BYTES_ENV, "").strip()
    if not raw:
        return MAX_INPUT_BYTES
    try:
        value = int(raw)
    except ValueError:
        value = 0
    if value < 1:
        from .errors import InputError

        raise InputError(f"{MAX_INPUT_BYTES_ENV} must be a positive integer, got '{truncate(raw, 40)}'")
    return value


def truncate(text: str, limit: int = 80) -> str:
    """``text`` cut to ``limit`` characters (with ``...`` and the full length) for echoing in errors."""
    text = str(text)
    if len(text) <= limit:
        return text
    return f"{text[:limit]}... ({len(text)} characters)"


def printable(text: str) -> str:
    """``text`` with every control character escaped (``\\x1b``, ``\\n``), safe to print on a terminal.

    Names and other text from input files reach error messages; raw escape
    sequences there could retitle or reprogram the reader's terminal.
    """
    text = str(text)
    if text.isprintable():
        return text
    return "".join(c if c.isprintable() or c == " " else repr(c)[1:-1] for c in text)
