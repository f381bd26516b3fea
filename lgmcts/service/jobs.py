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

import json
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
    "Abandoned",
    "run_check",
    "run_parse",
    "run_plan",
    "warm_language",
    "warm_up",
    "tracked",
    "worker_init",
    "HOOK_METHODS",
    "inspect",
    "BodyJob",
    "run_body",
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


class Abandoned(BaseException):
    """The client of the job went away; the job was stopped (or never started).

    A ``BaseException``, like ``KeyboardInterrupt``, so that no ``except
    Exception`` inside the planner swallows it.
    """


#: Signal the server sends a worker to stop the job it runs when that job's
#: client went away (see :func:`tracked`).
ABANDON_SIGNAL = getattr(signal, "SIGUSR1", None)


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
_withdrawn: Any = None
_running = 0


def _on_abandon(signum: int, frame: Any) -> None:
    # The server asks this worker to drop its job: only when the job running
    # now is one whose client went away (the signal may arrive late).
    if _running and _withdrawn is not None and _running in list(_withdrawn):
        raise Abandoned("the client went away")


def worker_init(slots: Any = None, counter: Any = None, pids: Any = None, withdrawn: Any = None) -> None:
    """Initialise a worker: leave Ctrl-C to the server, which shuts workers down.

    ``slots`` (a shared integer array, one entry per worker) and ``counter``
    (a shared integer) let :func:`tracked` publish which job each worker runs;
    ``pids`` (one entry per worker) publishes this process's id and
    ``withdrawn`` (a shared ring of job ids) lists the jobs whose clients went
    away: such a job is not started, and :data:`ABANDON_SIGNAL` stops it
    while it runs.
    """
    global _slot, _withdrawn
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    from ..patterns import load_pattern_modules

    load_pattern_modules(None)  # the patterns the server process loaded (LGMCTS_PATTERN_MODULES)
    _withdrawn = withdrawn
    if ABANDON_SIGNAL is not None and withdrawn is not None:
        signal.signal(ABANDON_SIGNAL, _on_abandon)
    if slots is not None and counter is not None:
        with counter.get_lock():
            index = counter.value
            counter.value += 1
        if index < len(slots):
            _slot = (slots, index)
            if pids is not None:
                pids[index] = os.getpid()


def tracked(fn: Callable[[Any], Any], job_id: int, job: Any) -> Any:
    """Run ``fn(job)`` with ``job_id`` published in this worker's slot meanwhile.

    The server reads the slots to tell a job that is really running (and may
    hang) from one that only waits in the executor's queue.
    """
    global _running
    if _withdrawn is not None and job_id in list(_withdrawn):
        raise Abandoned("the client went away before the job started")
    if _slot is None:
        return fn(job)
    slots, index = _slot
    slots[index] = job_id
    _running = job_id
    try:
        return fn(job)
    finally:
        _running = 0
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
    from ..viz.html import viewer_data

    data = viewer_data(job.scene, job.plan, goals=job.goals, instruction=job.instruction)
    return json.dumps(data, separators=(",", ":"), allow_nan=False).encode()


def warm_up(pause: float) -> int:
    """Import the planner and pause briefly, so warm-up jobs land on distinct workers."""
    from .. import planner, validate  # noqa: F401

    time.sleep(pause)
    return os.getpid()



# ---------------------------------------------------------------- raw bodies
#
# The server hands each request's raw body to the workers: reading and
# validating it (JSON parsing holds the interpreter) and serialising the
# answer happen here, never on the server's event loop.


def inspect(body: Any) -> dict:
    """Validate ``body`` (a :class:`lgmcts.service.bodies.Body`) and return what the server needs to go on.

    ``timeout``: the request's own wall-clock limit (s) or ``None``;
    ``instruction``: whether goals must first be parsed from an instruction.
    """
    from .bodies import read_body
    from .models import PlanRequest

    req = read_body(body)
    timeout = req.options.timeout if isinstance(req, PlanRequest) else req.timeout
    return {"timeout": timeout, "instruction": isinstance(req, PlanRequest) and req.instruction is not None}


@dataclass(frozen=True)
class BodyJob:
    """Do the work of ``body`` (validated before by :func:`inspect`) before ``deadline``.

    ``parse_only``: for a plan request with an instruction, parse the
    instruction into goal JSON (in a language worker); ``goals``: then the
    goal JSON so parsed, for the planning worker.
    """

    body: Any
    deadline: float
    goals: bytes | None = None
    parse_only: bool = False


def _json(data: Any) -> bytes:
    return json.dumps(data, separators=(",", ":"), allow_nan=False).encode()


def run_body(job: BodyJob) -> bytes:
    """The JSON answer (bytes) of a request to ``/plan``, ``/parse``, ``/check`` or ``/view``."""
    from .bodies import llm_endpoint, read_body

    body = job.body
    req = read_body(body)
    if body.kind == "check":
        return _json(run_check(CheckJob(req.scene, req.goals, req.plan)))
    if body.kind == "view":
        return run_view(ViewJob(req.scene, req.plan, req.goals, req.instruction))
    if body.kind == "parse" or job.parse_only:
        url, key = llm_endpoint(body.policy, req.llm_base_url, req.parser, req.llm_model)
        return _json(run_parse(ParseJob(req.scene, req.instruction, req.parser, req.llm_model, url, job.deadline, key)))
    from ..formats import parse_goals

    goals = req.goals if job.goals is None else parse_goals(json.loads(job.goals))
    o = req.options
    plan_job = PlanJob(
        scene=req.scene,
        goals=goals,
        instruction=req.instruction,
        method=o.method,
        seed=o.seed,
        max_iter=min(o.max_iter, body.policy.max_iter),
        time_limit=o.time_limit,
        anytime=o.anytime,
        deadline=job.deadline,
        hooks=body.policy.test_hooks,
    )
    return _json(run_plan(plan_job))
