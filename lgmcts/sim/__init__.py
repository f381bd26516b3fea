"""Physics execution and perception in MuJoCo.

* :func:`execute_plan` runs a plan with a suction gripper in MuJoCo and
  judges the final state (:class:`Execution`).
* :func:`observe` renders the scene from a camera above the table and turns
  each object's pixels into a point cloud (a scene of ``points`` objects);
  :func:`footprint_iou` scores the result against the true footprints.

The design and its numbers are described in ``docs/sim.md``.

The names below load on first use, so that ``lgmcts`` commands that do not
simulate (``parse``, ``plan``) never import MuJoCo.
"""

from __future__ import annotations

import os
from importlib import import_module
from typing import Any

# MUJOCO_GL is read when mujoco is first imported: choose the OpenGL backend
# here, before any module of this package can import it.
os.environ.setdefault("MUJOCO_GL", "osmesa")
os.environ.setdefault("PYOPENGL_PLATFORM", os.environ["MUJOCO_GL"])

__all__ = [
    "CameraOptions",
    "ExecOptions",
    "Execution",
    "Executor",
    "ModelOptions",
    "SimModel",
    "StepOutcome",
    "VideoRecorder",
    "build_model",
    "execute_plan",
    "footprint_iou",
    "observe",
]

_WHERE = {
    **dict.fromkeys(["CameraOptions", "VideoRecorder", "footprint_iou", "observe"], ".render"),
    **dict.fromkeys(["ExecOptions", "Execution", "Executor", "StepOutcome", "execute_plan"], ".executor"),
    **dict.fromkeys(["ModelOptions", "SimModel", "build_model"], ".model"),
}


def __getattr__(name: str) -> Any:
    if name in _WHERE:
        return getattr(import_module(_WHERE[name], __name__), name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


def __dir__() -> list[str]:
    return sorted(__all__)
