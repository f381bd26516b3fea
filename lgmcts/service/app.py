"""The HTTP application: routes, limits and the mapping of failures to status codes.

=========  ==============================================================
status     meaning
=========  ==============================================================
200        the result (a plan that is not solved is still 200, ``solved: false``)
413        the request body is larger than ``max_body`` bytes
422        bad input; ``detail`` is the one-line message the CLI prints
500        the planner crashed (its worker died); the service goes on
501        an extra the request needs is not installed
504        the request ran past its wall-clock timeout
=========  ==============================================================

Every error body is ``{"detail": "<one line>"}``.
"""

from __future__ import annotations

import logging
import math
import os
import time
from contextlib import asynccontextmanager
from dataclasses import dataclass
from typing import Annotated, Any, Awaitable, Callable

from fastapi import Body, FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.responses import HTMLResponse, JSONResponse, Response

from .. import __version__
from ..errors import InputError
from ..formats import GoalSpec
from . import jobs
from .models import CheckRequest, ErrorOut, HealthOut, ParseRequest, PlanRequest, VerdictOut, ViewRequest
from .pool import JobTimeout, WorkerCrashed, WorkerPool
from .viewer import EXAMPLE_GOALS, EXAMPLE_INSTRUCTION, EXAMPLE_SCENE, page

__all__ = ["ServiceOptions", "create_app", "options_from_env", "validation_message", "BodyLimit", "TEST_HOOKS_ENV"]

log = logging.getLogger("lgmcts.service")

#: Environment variable that enables the test-only planner methods
#: (:data:`lgmcts.service.jobs.HOOK_METHODS`). Never set it in production.
TEST_HOOKS_ENV = "LGMCTS_SERVICE_TEST_HOOKS"


@dataclass(frozen=True)
class ServiceOptions:
    """Limits of one service instance.

    Parameters
    ----------
    workers : planning processes; requests beyond this many wait in a queue.
    language_workers : processes that parse instructions; each holds its own
        copy of the sentence model (torch), loaded on its first instruction.
    preload_language : load the sentence model in the language workers at
        start-up (in the background) instead of on the first instruction.
    max_body : largest accepted request body (bytes).
    timeout : wall-clock limit of a request (s), queueing included; a request
        may ask for less with its ``timeout`` field, never for more.
    max_iter : cap on the planner's iteration budget; larger requests are cut
        to it (the plan's ``stats.max_iter`` shows the budget used).
    grace : seconds a job may run past its deadline before its worker pool is
        taken as hung and replaced.
    test_hooks : accept the test-only methods ``_crash`` and ``_sleep``.
    warm : start every worker before serving the first request.
    """

    workers: int = 2
    language_workers: int = 1
    preload_language: bool = False
    max_body: int = 4 * 1024 * 1024
    timeout: float = 30.0
    max_iter: int = 10_000
    grace: float = 5.0
    test_hooks: bool = False
    warm: bool = True

    def __post_init__(self) -> None:
        if self.workers < 1:
            raise InputError("workers must be at least 1")
        if self.language_workers < 1:
            raise InputError("language_workers must be at least 1")
        if self.max_body < 1:
            raise InputError("max_body must be at least 1 byte")
        if not self.timeout > 0:
            raise InputError("timeout must be positive")
        if self.max_iter < 1:
            raise InputError("max_iter must be at least 1")
        if not self.grace > 0:
            raise InputError("grace must be positive")


# ---------------------------------------------------------------- errors


def _error(status: int, message: str, **headers: str) -> JSONResponse:
    return JSONResponse({"detail": " ".join(str(message).split())}, status_code=status, headers=headers or None)


def _skip_loc(part: Any) -> bool:
    # pydantic inserts validator names ("function-after[...]") into locations.
    return isinstance(part, str) and part.startswith("function-")


def validation_message(errors: list[dict]) -> str:
    """One line for the first of FastAPI's body validation errors.

    Errors inside the ``scene``, ``goals`` and ``plan`` parts read exactly as
    the CLI's messages for the same file (``invalid scene at objects.0.pose:
    ...``); other fields read ``invalid request at options.seed: ...``.
    """
    if not errors:
        return "invalid request"
    first = errors[0]
    kind = first.get("type", "")
    loc = [p for p in first.get("loc", ()) if not _skip_loc(p)]
    if loc and loc[0] == "body":
        loc = loc[1:]
    if kind == "json_invalid":
        reason = (first.get("ctx") or {}).get("error", "")
        return f"invalid request: the body is not valid JSON{f' ({reason})' if reason else ''}"
    if kind == "missing" and not loc:
        return "invalid request: a JSON body is required"
    if kind in ("model_attributes_type", "dict_type", "model_type") and not loc:
        return "invalid request: the body must be a JSON object sent as Content-Type: application/json"
    if kind == "missing" and len(loc) == 1:
        return f"invalid request: '{loc[0]}' is required"
    what = "request"
    if loc and loc[0] in ("scene", "goals", "plan"):
        what, loc = str(loc[0]), loc[1:]
    msg = str(first.get("msg", "invalid value")).removeprefix("Value error, ")
    where = f" at {'.'.join(str(p) for p in loc)}" if loc else ""
    return f"invalid {what}{where}: {msg}"


# ---------------------------------------------------------------- body limit


class BodyLimit:
    """ASGI middleware: answer 413 to bodies over ``max_body`` bytes.

    A declared ``Content-Length`` over the limit is refused before reading;
    a streamed (chunked) body is read up to the limit and refused when it
    grows past it. Accepted bodies are handed on unchanged.
    """

    def __init__(self, app: Any, *, max_body: int) -> None:
        self.app = app
        self.max_body = max_body

    async def __call__(self, scope: dict, receive: Callable[[], Awaitable[dict]], send: Callable) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        too_big = f"request body larger than {self.max_body} bytes"
        for name, value in scope.get("headers", ()):
            if name == b"content-length":
                try:
                    declared = int(value)
                except ValueError:
                    declared = -1
                if declared > self.max_body:
                    await _error(413, too_big, connection="close")(scope, receive, send)
                    return
        body = bytearray()
        more = True
        while more:
            message = await receive()
            if message["type"] == "http.disconnect":
                return
            body += message.get("body", b"")
            more = message.get("more_body", False)
            if len(body) > self.max_body:
                await _error(413, too_big, connection="close")(scope, receive, send)
                return
        replayed = False

        async def replay() -> dict:
            nonlocal replayed
            if not replayed:
                replayed = True
                return {"type": "http.request", "body": bytes(body), "more_body": False}
            return await receive()

        await self.app(scope, replay, send)


# ---------------------------------------------------------------- app


_ERRORS = {
    413: {"model": ErrorOut, "description": "Request body too large."},
    422: {"model": ErrorOut, "description": "Bad input; the same one-line message as the CLI."},
    500: {"model": ErrorOut, "description": "The planner crashed; the service goes on."},
    504: {"model": ErrorOut, "description": "The request ran past its wall-clock timeout."},
}


_PLAN_EXAMPLES = {
    "goals": {
        "summary": "Goals given as JSON",
        "value": {"scene": EXAMPLE_SCENE, "goals": EXAMPLE_GOALS, "options": {"method": "lgmcts", "seed": 0}},
    },
    "instruction": {
        "summary": "A plain-language instruction",
        "value": {"scene": EXAMPLE_SCENE, "instruction": EXAMPLE_INSTRUCTION},
    },
}
_PARSE_EXAMPLES = {
    "rules": {
        "summary": "The offline parser",
        "value": {"scene": EXAMPLE_SCENE, "instruction": EXAMPLE_INSTRUCTION, "parser": "rules"},
    },
}


def create_app(options: ServiceOptions | None = None) -> FastAPI:
    """Build the ASGI application (start it with uvicorn; see :mod:`lgmcts.service.cli`).

    The worker pool is started when the application starts (ASGI lifespan)
    and stopped when it stops.
    """
    opts = options or ServiceOptions()
    pool = WorkerPool(workers=opts.workers, grace=opts.grace, name="planning")
    # Parsing has its own processes: the sentence model (torch, a few hundred
    # MB) is loaded once per language worker, never in the planning workers
    # nor in this process.
    language = WorkerPool(workers=opts.language_workers, grace=opts.grace, name="language")

    @asynccontextmanager
    async def lifespan(_: FastAPI):
        pool.start(warm=opts.warm)
        language.start(warm=False)
        if opts.preload_language:
            from .viewer import EXAMPLE_INSTRUCTION, EXAMPLE_SCENE

            for _ in range(opts.language_workers):
                language.submit_background(jobs.warm_language, EXAMPLE_INSTRUCTION, EXAMPLE_SCENE)
        try:
            yield
        finally:
            pool.close()
            language.close()

    app = FastAPI(
        title="lgmcts planning service",
        version=__version__,
        description=(
            "Plan tabletop rearrangements from goals or plain-language commands. "
            "Lengths in metres, angles in radians, table frame +x right, +y away from the viewer. "
            "Every error answers {\"detail\": \"<one line>\"}."
        ),
        lifespan=lifespan,
    )
    app.state.pool = pool
    app.state.language = language
    app.state.options = opts
    app.add_middleware(BodyLimit, max_body=opts.max_body)

    @app.exception_handler(Exception)
    async def _unexpected(_: Request, exc: Exception) -> JSONResponse:
        # Last resort (the server logs the traceback): still one line of JSON.
        return _error(500, f"internal error: {type(exc).__name__}")

    @app.exception_handler(RequestValidationError)
    async def _invalid(_: Request, exc: RequestValidationError) -> JSONResponse:
        return _error(422, validation_message(list(exc.errors())))

    def deadline_of(requested: float | None) -> float:
        if requested is not None and not (math.isfinite(requested) and requested > 0):
            raise InputError("timeout must be positive")
        limit = opts.timeout if requested is None else min(requested, opts.timeout)
        return time.time() + limit

    async def run(
        fn: Callable[[Any], Any], job: Any, deadline: float, what: str, on: WorkerPool = pool
    ) -> JSONResponse | dict:
        try:
            return await on.run(fn, job, deadline=deadline)
        except InputError as exc:
            return _error(422, str(exc))
        except (JobTimeout, jobs.DeadlinePassed):
            return _error(504, f"{what} did not finish within its wall-clock timeout")
        except WorkerCrashed:
            return _error(500, f"the {what} process crashed on this request; the service has replaced it")
        except jobs.Unavailable as exc:
            return _error(501, str(exc))
        except Exception as exc:  # a planner bug: log it whole, answer one line
            log.error("%s failed", what, exc_info=exc)
            return _error(500, f"{what} failed: {type(exc).__name__}: {exc}")

    @app.get("/healthz", response_model=HealthOut, tags=["service"])
    async def healthz() -> dict:
        """Liveness, the number of workers and pool replacements, and the limits."""
        return {
            "status": "ok",
            "version": __version__,
            "workers": opts.workers,
            "language_workers": opts.language_workers,
            "restarts": pool.restarts + language.restarts,
            "timeout_s": opts.timeout,
            "max_iter": opts.max_iter,
            "max_body_bytes": opts.max_body,
        }

    @app.post("/parse", response_model=None, responses={200: {"description": "Goal JSON."}, **_ERRORS}, tags=["planning"])
    async def parse(req: Annotated[ParseRequest, Body(openapi_examples=_PARSE_EXAMPLES)]) -> Any:
        """Turn an instruction into goal JSON (``{"goals": [...]}``) for the scene."""
        try:
            deadline = deadline_of(req.timeout)
        except InputError as exc:
            return _error(422, str(exc))
        job = jobs.ParseJob(req.scene, req.instruction, req.parser, req.llm_model, req.llm_base_url, deadline)
        return await run(jobs.run_parse, job, deadline, "parsing", on=language)

    @app.post("/plan", response_model=None, responses={200: {"description": "Plan JSON."}, **_ERRORS}, tags=["planning"])
    async def plan(req: Annotated[PlanRequest, Body(openapi_examples=_PLAN_EXAMPLES)]) -> Any:
        """Plan actions for the scene towards ``goals`` or an ``instruction``.

        The answer is the plan JSON of ``lgmcts plan``: ``solved``, ``actions``,
        ``goals``, ``stats`` (and ``instruction`` when one was given).
        """
        o = req.options
        try:
            deadline = deadline_of(o.timeout)
            if (req.goals is None) == (req.instruction is None):
                raise InputError("give either goals or an instruction, not both or neither")
            if req.goals is not None:
                req.goals.check_against(req.scene)
            from ..planner import METHODS

            if o.seed < 0:
                # numpy's generators take no negative seeds.
                raise InputError("seed must be a non-negative integer")
            if o.time_limit is not None and not (math.isfinite(o.time_limit) and o.time_limit > 0):
                raise InputError("time_limit must be positive")
            if o.method not in METHODS and not (opts.test_hooks and o.method in jobs.HOOK_METHODS):
                raise InputError(f"unknown method '{o.method}' (known: {', '.join(METHODS)})")
        except InputError as exc:
            return _error(422, str(exc))
        goals = req.goals
        if req.instruction is not None:
            parse_job = jobs.ParseJob(req.scene, req.instruction, req.parser, req.llm_model, req.llm_base_url, deadline)
            parsed = await run(jobs.run_parse, parse_job, deadline, "parsing", on=language)
            if isinstance(parsed, JSONResponse):
                return parsed
            goals = GoalSpec.model_validate(parsed)
        job = jobs.PlanJob(
            scene=req.scene,
            goals=goals,
            instruction=req.instruction,
            method=o.method,
            seed=o.seed,
            max_iter=min(o.max_iter, opts.max_iter),
            time_limit=o.time_limit,
            anytime=o.anytime,
            deadline=deadline,
            hooks=opts.test_hooks,
        )
        return await run(jobs.run_plan, job, deadline, "planning")

    @app.post("/check", response_model=VerdictOut, responses=_ERRORS, tags=["planning"])
    async def check(req: CheckRequest) -> Any:
        """Replay the plan on the scene and judge it against the goals (``lgmcts check --json``)."""
        try:
            deadline = deadline_of(req.timeout)
        except InputError as exc:
            return _error(422, str(exc))
        return await run(jobs.run_check, jobs.CheckJob(req.scene, req.goals, req.plan), deadline, "checking")

    @app.post("/view", response_model=None, responses={200: {"description": "Viewer data."}, **_ERRORS}, tags=["viewer"])
    async def view(req: ViewRequest) -> Any:
        """What the viewer draws for the plan: each state's poses, footprints, paints and goal shapes
        (``lgmcts.viz.viewer_data``); the page's script draws only this."""
        try:
            deadline = deadline_of(req.timeout)
        except InputError as exc:
            return _error(422, str(exc))
        job = jobs.ViewJob(req.scene, req.plan, req.goals, req.instruction)
        return await run(jobs.run_view, job, deadline, "drawing")

    @app.get("/", response_class=HTMLResponse, tags=["viewer"])
    async def viewer() -> HTMLResponse:
        """A page to paste or upload a scene, give an instruction or goals, plan and see the plan drawn."""
        return HTMLResponse(page())

    @app.get("/favicon.ico", include_in_schema=False)
    async def favicon() -> Response:
        return Response(status_code=204)

    return app


def options_from_env(**kwargs: Any) -> ServiceOptions:
    """:class:`ServiceOptions` from keyword arguments, with test hooks read from the environment."""
    hooks = os.environ.get(TEST_HOOKS_ENV, "").strip().lower() in ("1", "true", "yes")
    return ServiceOptions(test_hooks=hooks, **kwargs)

