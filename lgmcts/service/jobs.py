"""Work done inside the service's worker processes.

Each function here takes one frozen, picklable job description and returns a
JSON-ready dict. They run in a process of :class:`lgmcts.service.pool.WorkerPool`,
never in the process that serves HTTP, so a slow or crashing planner cannot
stall the event loop. Bad input raises :class:`lgmcts.errors.InputError`
(pickled back to the server, which answers 422); a missing optional part of
the package (an extra that is not installed, see :mod:`lgmcts.extras`)
raises :class:`Unavailable` (answered 501).

The language parser (and with it torch) is imported lazily, only by the jobs
that need it.
"""

from __future__ import annotations

import os
import signal
import time
from dataclasses import dataclass
from typing import Any, Callable

from ..errors import InputError
from ..extras import missing_extra
from ..formats import GoalSpec, PlanSpec, SceneSpec, to_dict

__all__ = [
    "CheckJob",
    "ParseJob",
    "PlanJob",
    "Unavailable",
    "DeadlinePassed",
    "run_check",
    "run_parse",
    "run_plan",
    "warm_language",
    "warm_up",
    "tracked",
    "worker_init",
    "HOOK_METHODS",
]

#: Margin (s) added to the planner's own time limit beyond the request's
#: deadline. The server gives up at the deadline; the margin only ensures the
#: planner is not what decides the race, so an over-long search ends as a 504.
DEADLINE_MARGIN = 0.2

#: Methods that exist only when the server runs with test hooks enabled:
#: ``_crash`` kills the worker process; ``_sleep`` first sleeps for the
#: request's ``time_limit`` seconds, deaf to every deadline (a hung planner),
#: then plans with ``lgmcts`` and no time limit.
HOOK_METHODS = ("_crash", "_sleep")


class Unavailable(RuntimeError):
    """An optional part of the package (the language parser) is missing."""


class DeadlinePassed(RuntimeError):
    """The request's wall-clock deadline passed before the work could start."""


@dataclass(frozen=True)
class ParseJob:
    """Turn ``instruction`` into goals for ``scene`` before ``deadline`` (``time.time()`` s)."""

    scene: SceneSpec
    instruction: str
    parser: str = "rules"
    llm_model: str | None = None
    llm_base_url: str | None = None
    deadline: float = float("inf")
    #: Key for the LLM endpoint; ``None``: the server's own (``OPENAI_API_KEY``).
    api_key: str | None = None


@dataclass(frozen=True)
class PlanJob:
    """Plan for ``scene`` towards ``goals``.

    ``deadline`` is the request's wall-clock deadline (``time.time()`` seconds);
    the planner's time limit never runs past it by more than
    :data:`DEADLINE_MARGIN`. ``time_limit`` is the client's own budget (s) or
    ``None``. ``instruction``, when the goals came from one, is copied into
    the plan.
    """

    scene: SceneSpec
    goals: GoalSpec
    method: str
    seed: int
    max_iter: int
    time_limit: float | None
    anytime: bool
    deadline: float
    instruction: str | None = None
    hooks: bool = False


@dataclass(frozen=True)
class CheckJob:
    """Judge ``plan`` on ``scene`` against ``goals``."""

    scene: SceneSpec
    goals: GoalSpec
    plan: PlanSpec


_slot: tuple[Any, int] | None = None


def worker_init(slots: Any = None, counter: Any = None) -> None:
    """Initialise a worker: leave Ctrl-C to the server, which shuts workers down.

    ``slots`` (a shared integer array, one entry per worker) and ``counter``
    (a shared integer) let :func:`tracked` publish which job each worker runs.
    """
    global _slot
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    from ..patterns import load_pattern_modules

    load_pattern_modules(None)  # the patterns the server process loaded (LGMCTS_PATTERN_MODULES)
    if slots is not None and counter is not None:
        with counter.get_lock():
            index = counter.value
            counter.value += 1
        if index < len(slots):
            _slot = (slots, index)


def tracked(fn: Callable[[Any], Any], job_id: int, job: Any) -> Any:
    """Run ``fn(job)`` with ``job_id`` published in this worker's slot meanwhile.

    The server reads the slots to tell a job that is really running (and may
    hang) from one that only waits in the executor's queue.
    """
    if _slot is None:
        return fn(job)
    slots, index = _slot
    slots[index] = job_id
    try:
        return fn(job)
    finally:
        slots[index] = 0


def run_parse(job: ParseJob) -> dict:
    """Goal JSON (a dict) for ``job.instruction``."""
    from ..language import parse

    remaining = job.deadline - time.time()
    if remaining <= 0:
        raise DeadlinePassed("the request's deadline passed before parsing started")
    try:
        goals = parse(
            job.scene,
            job.instruction,
            parser=job.parser,
            llm_model=job.llm_model,
            llm_base_url=job.llm_base_url,
            api_key=job.api_key,
            timeout=max(1.0, min(remaining, 60.0)),
        )
    except ModuleNotFoundError as exc:  # the 'language' (or 'llm') extra is not installed
        message = missing_extra(exc)
        if message is None:
            raise
        raise Unavailable(message) from None
    return to_dict(goals)


def warm_language(instruction: str, scene: dict) -> float:
    """Parse once so that the sentence model is loaded; returns the time taken (s)."""
    t0 = time.perf_counter()
    try:
        run_parse(ParseJob(SceneSpec.model_validate(scene), instruction))
    except (Unavailable, InputError):
        pass
    return time.perf_counter() - t0


def run_plan(job: PlanJob) -> dict:
    """Plan JSON (a dict) for ``job``."""
    if job.hooks and job.method == "_crash":
        os._exit(70)
    method, time_limit = job.method, job.time_limit
    if job.hooks and method == "_sleep":
        time.sleep(time_limit or 60.0)
        method, time_limit = "lgmcts", None
    from ..planner import plan

    remaining = job.deadline - time.time()
    if remaining <= 0:
        raise DeadlinePassed("the request's deadline passed before planning started")
    backstop = remaining + DEADLINE_MARGIN
    limit = backstop if time_limit is None else min(time_limit, backstop)
    result = plan(
        job.scene,
        job.goals,
        method=method,
        seed=job.seed,
        max_iter=job.max_iter,
        time_limit=limit,
        anytime=job.anytime,
    )
    data = to_dict(result)
    stats = data.get("stats", {})
    if time_limit is None:
        # The backstop is the server's business; the plan should read as if
        # the client had called the library without a time limit.
        stats.pop("time_limit", None)
    else:
        stats["time_limit"] = time_limit
    if job.instruction is not None:
        data["instruction"] = job.instruction
    return data


def run_check(job: CheckJob) -> dict:
    """Verdict JSON (a dict): ``valid``, ``reasons`` and per-goal ``goals``."""
    from ..validate import check

    verdict = check(job.scene, job.goals, job.plan)
    return {"valid": verdict.valid, "reasons": list(verdict.reasons), "goals": list(verdict.goals)}


@dataclass(frozen=True)
class ViewJob:
    """What the viewer draws for ``plan`` on ``scene`` (against ``goals``, default the plan's)."""

    scene: SceneSpec
    plan: PlanSpec
    goals: GoalSpec | None = None
    instruction: str | None = None


def run_view(job: ViewJob) -> bytes:
    """The viewer's data (:func:`lgmcts.viz.viewer_data`) as JSON bytes.

    Serialised here, in the worker, so that the server's event loop only
    passes the bytes on; the size is bounded by
    :data:`lgmcts.limits.MAX_VIEW_CELLS` (frames are deltas).
    """
    import json

    from ..viz.html import viewer_data

    data = viewer_data(job.scene, job.plan, goals=job.goals, instruction=job.instruction)
    return json.dumps(data, separators=(",", ":"), allow_nan=False).encode()


def warm_up(pause: float) -> int:
    """Import the planner and pause briefly, so warm-up jobs land on distinct workers."""
    from .. import planner, validate  # noqa: F401

    time.sleep(pause)
    return os.getpid()

