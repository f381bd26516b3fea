"""Request and response bodies of the planning service.

The scene, goal and plan parts are the library's own format models
(:mod:`lgmcts.formats`), so the service accepts exactly what the command line
reads from files and its OpenAPI description documents the same formats.
"""

from __future__ import annotations

from pydantic import BaseModel, ConfigDict, Field

from ..formats import GoalSpec, PlanSpec, SceneSpec
from ..limits import MAX_INSTRUCTION, MAX_TEXT

__all__ = ["PlanOptions", "ParseRequest", "PlanRequest", "CheckRequest", "VerdictOut", "ErrorOut", "HealthOut"]


class _Body(BaseModel):
    model_config = ConfigDict(extra="forbid")


class PlanOptions(_Body):
    """Planner settings; the same meaning as the options of ``lgmcts plan``."""

    method: str = Field(default="lgmcts", max_length=MAX_TEXT, description="lgmcts, greedy or pmcts.")
    seed: int = Field(default=0, description="Random seed; the same seed gives the same plan.")
    max_iter: int = Field(default=10_000, description="Iteration budget; the server caps it (see /healthz).")
    time_limit: float | None = Field(default=None, description="Planning budget in seconds (wall clock).")
    anytime: bool = Field(default=False, description="Keep searching within the budget for a shorter plan.")
    robot: str | None = Field(
        default=None,
        max_length=MAX_TEXT,
        description="Plan for this arm (ur5e): every pick and place within its top-down reach; "
        "null: no robot, the plan is the same as without the field.",
    )
    timeout: float | None = Field(
        default=None, description="Wall-clock limit of this request in seconds; at most the server's timeout."
    )


class ParseRequest(_Body):
    """Turn a plain-language instruction into goals for a scene."""

    scene: SceneSpec
    instruction: str = Field(..., max_length=MAX_INSTRUCTION, description="Plain-language command.")
    parser: str = Field("rules", max_length=MAX_TEXT, description="Instruction parser: rules or llm.")
    llm_model: str | None = Field(None, max_length=MAX_TEXT, description="Model name for the llm parser.")
    llm_base_url: str | None = Field(
        None,
        max_length=MAX_TEXT,
        description="OpenAI-compatible endpoint for the llm parser: refused (422) unless the server allows "
        "client-chosen endpoints; such a request never gets the server's API key.",
    )
    timeout: float | None = Field(None, description="Wall-clock limit in seconds; at most the server's timeout.")


class PlanRequest(_Body):
    """Plan for a scene towards ``goals`` or towards the goals of ``instruction`` (exactly one)."""

    scene: SceneSpec
    instruction: str | None = Field(
        None, max_length=MAX_INSTRUCTION, description="Plain-language command (instead of goals)."
    )
    goals: GoalSpec | None = Field(None, description="Goal specification (instead of an instruction).")
    parser: str = Field("rules", max_length=MAX_TEXT, description="Instruction parser: rules or llm.")
    llm_model: str | None = Field(None, max_length=MAX_TEXT)
    llm_base_url: str | None = Field(
        None, max_length=MAX_TEXT, description="As for /parse: refused unless the server allows it."
    )
    options: PlanOptions = Field(default_factory=lambda: PlanOptions())


class CheckRequest(_Body):
    """Replay a plan on a scene and judge it against goals."""

    scene: SceneSpec
    goals: GoalSpec
    plan: PlanSpec
    robot: str | None = Field(
        None,
        max_length=MAX_TEXT,
        description="Also require every pick and place within this arm's top-down reach (ur5e).",
    )
    timeout: float | None = Field(None, description="Wall-clock limit in seconds; at most the server's timeout.")


class ViewRequest(_Body):
    """Compute what the viewer draws for a plan on a scene."""

    scene: SceneSpec
    plan: PlanSpec
    goals: GoalSpec | None = Field(None, description="Goals to draw; default the plan's own.")
    instruction: str | None = None
    timeout: float | None = Field(None, description="Wall-clock limit in seconds; at most the server's timeout.")


class VerdictOut(BaseModel):
    """Outcome of /check: validity, the violations in words, and per-goal success."""

    valid: bool
    reasons: list[str]
    goals: list[bool]


class ErrorOut(BaseModel):
    """Every error: one line for a person."""

    detail: str


class HealthOut(BaseModel):
    """Liveness and the server's limits."""

    status: str
    version: str
    workers: int
    language_workers: int
    restarts: int = Field(..., description="How many times a worker pool was replaced.")
    timeout_s: float
    max_iter: int
    max_body_bytes: int
