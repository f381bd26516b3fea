"""Physics execution and perception in MuJoCo.

* :func:`execute_plan` runs a plan with a suction gripper in MuJoCo and
  judges the final state (:class:`Execution`).
* :func:`observe` renders the scene from a camera above the table and turns
  each object's pixels into a point cloud (a scene of ``points`` objects);
  :func:`footprint_iou` scores the result against the true footprints.

The design and its numbers are described in ``docs/sim.md``.
"""

# The render module picks the OpenGL backend (MUJOCO_GL) and must run before
# anything imports mujoco, so it is imported first.
from .render import CameraOptions, VideoRecorder, footprint_iou, observe  # isort: skip
from .executor import ExecOptions, Execution, Executor, StepOutcome, execute_plan
from .model import ModelOptions, SimModel, build_model

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
