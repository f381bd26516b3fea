"""Physics execution and perception in MuJoCo.

* :func:`execute_plan` runs a plan with a suction gripper in MuJoCo (a
  floating cup, or with ``robot="ur5e"`` a UR5e arm) and judges the final
  state (:class:`Execution`).
* :func:`observe` renders the scene from a camera above the table and turns
  each object's pixels into a point cloud (a scene of ``points`` objects);
  :func:`footprint_iou` scores the result against the true footprints.

The design and its numbers are described in ``docs/sim.md``.

The names below load on first use, so that ``lgmcts`` commands that do not
simulate (``parse``, ``plan``) never import MuJoCo.
"""

from __future__ import annotations

import os

from ..lazy import lazy_names

# MuJoCo reads the OpenGL backend when it is first imported, so it is chosen
# here, before any module of this package imports mujoco. The names below load
# on first use: importing ``lgmcts.sim`` (the command line does) needs no
# mujoco, which comes with the 'sim' extra.
os.environ.setdefault("MUJOCO_GL", "osmesa")
os.environ.setdefault("PYOPENGL_PLATFORM", os.environ["MUJOCO_GL"])

_WHERE = {
    "CameraOptions": ".render",
    "VideoRecorder": ".render",
    "footprint_iou": ".render",
    "observe": ".render",
    "ExecOptions": ".executor",
    "Execution": ".executor",
    "Executor": ".executor",
    "StepOutcome": ".executor",
    "execute_plan": ".executor",
    "ArmExecutor": ".arm_exec",
    "ArmOptions": ".arm_exec",
    "ModelOptions": ".model",
    "SimModel": ".model",
    "build_model": ".model",
}

__all__ = [
    "ArmExecutor",
    "ArmOptions",
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


__getattr__, __dir__ = lazy_names(__name__, _WHERE)
