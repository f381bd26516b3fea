"""The HTTP application: routes, limits and the mapping of failures to status codes.

=========  ==============================================================
status     meaning
=========  ==============================================================
200        the result (a plan that is not solved is still 200, ``solved: false``)
401        the server has a token and the request does not carry it
408        the request body did not arrive within ``read_timeout`` / ``timeout``
413        the request body is larger than ``max_body`` bytes
422        bad input; ``detail`` is the one-line message the CLI prints
500        the planner crashed (its worker died); the service goes on
501        an extra the request needs is not installed
503        the service is shutting down (retry on another instance)
504        the request ran past its wall-clock timeout
=========  ==============================================================

The request body is read, parsed and validated off the event loop (a
thread), and every CPU-bound step after it runs in a worker process, so
``GET /healthz`` answers while large requests are being handled. A request's
wall-clock timeout runs from the moment its headers arrived.

Every error body is ``{"detail": "<one line>"}``.
"""

from __future__ import annotations

import asyncio
import hmac
import json
import logging
import math
import os
import time
from contextlib import asynccontextmanager
from dataclasses import dataclass
from typing import Any, Awaitable, Callable

from fastapi import FastAPI, Request
from fastapi.exceptions import RequestValidationError
from fastapi.openapi.utils import get_openapi
from fastapi.responses import HTMLResponse, JSONResponse, Response
from pydantic import BaseModel, ValidationError
from pydantic.json_schema import models_json_schema

from .. import __version__
from ..errors import InputError
from ..formats import GoalSpec
from ..limits import truncate
from . import jobs
from .models import CheckRequest, ErrorOut, HealthOut, ParseRequest, PlanRequest, VerdictOut, ViewRequest
from .pool import JobTimeout, WorkerCrashed, WorkerPool
from .viewer import EXAMPLE_GOALS, EXAMPLE_INSTRUCTION, EXAMPLE_SCENE, page

__all__ = [
    "ServiceOptions",
    "create_app",
    "options_from_env",
    "validation_message",
    "BodyLimit",
    "TEST_HOOKS_ENV",
    "TOKEN_ENV",
    "ARRIVED",
]

log = logging.getLogger("lgmcts.service")

#: Environment variable that enables the test-only planner methods
#: (:data:`lgmcts.service.jobs.HOOK_METHODS`). Never set it in production.
TEST_HOOKS_ENV = "LGMCTS_SERVICE_TEST_HOOKS"

#: Environment variable holding the bearer token (``lgmcts serve --token``).
TOKEN_ENV = "LGMCTS_SERVICE_TOKEN"

#: Key of ``scope["state"]`` holding the ``time.time()`` at which a request's headers arrived.
ARRIVED = "lgmcts_arrived"

#: Longest ``detail`` line (characters); longer messages are cut.
MAX_DETAIL = 500


@dataclass(frozen=True)
class ServiceOptions:
    """Limits of one service instance.

    Parameters
    ----------
    workers : planning processes; requests beyond this many wait in a queue.
    language_workers : processes that parse instructions; each holds its own
        copy of the sentence model (onnxruntime), loaded on its first instruction.
    preload_language : load the sentence model in the language workers at
        start-up (in the background) instead of on the first instruction
        (the load takes about half a second; rarely worth it).
    max_body : largest accepted request body (bytes).
    timeout : wall-clock limit of a request (s), queueing included; a request
        may ask for less with its ``timeout`` field, never for more.
    max_iter : cap on the planner's iteration budget; larger requests are cut
        to it (the plan's ``stats.max_iter`` shows the budget used).
    grace : seconds a job may run past its deadline before its worker pool is
        taken as hung and replaced.
    test_hooks : accept the test-only methods ``_crash`` and ``_sleep``.
    warm : start every worker before serving the first request.
    token : when set, POST requests need ``Authorization: Bearer <token>`` (401 otherwise).
    read_timeout : longest wait (s) for the next piece of a request body (408 past it).
    header_timeout : longest time (s) a connection may take to send a request's headers
        (enforced by the server, :mod:`lgmcts.service.cli`).
    llm_base_url : the OpenAI-compatible endpoint of ``parser: "llm"`` (server
        configuration; ``None``: ``OPENAI_BASE_URL`` or OpenAI itself).
    allow_client_llm_url : accept ``llm_base_url`` from requests. Such requests
        never receive the server's API key.
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
    token: str | None = None
    read_timeout: float = 10.0
    header_timeout: float = 10.0
    llm_base_url: str | None = None
    allow_client_llm_url: bool = False

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
        for name in ("timeout", "grace", "read_timeout", "header_timeout"):
            value = getattr(self, name)
            if not (math.isfinite(value) and value > 0):
                raise InputError(f"{name} must be a positive finite number of seconds")
        if self.token is not None and len(self.token) < 16:
            raise InputError("the token must be at least 16 characters long")


# ---------------------------------------------------------------- errors


def _error(status: int, message: str, **headers: str) -> JSONResponse:
    line = truncate(" ".join(str(message).split()), MAX_DETAIL)
    return JSONResponse({"detail": line}, status_code=status, headers={k.replace("_", "-"): v for k, v in headers.items()} or None)


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
    """ASGI middleware at the door: arrival time, the token, the body's size and pace.

    * stamps ``scope["state"][ARRIVED]`` with the time the headers arrived
      (every timeout of the request runs from it);
    * with a ``token``, answers 401 to a POST without ``Authorization: Bearer
      <token>`` before reading its body (GET pages stay open: the viewer,
      the API description and ``/healthz`` hold nothing secret);
    * answers 413 to bodies over ``max_body`` bytes: a declared
      ``Content-Length`` over the limit is refused before reading; a streamed
      (chunked) body is refused when it grows past it;
    * answers 408 when the next piece of the body takes longer than
      ``read_timeout`` s, or the whole body longer than ``timeout`` s, so a
      client trickling its body is disconnected.

    Accepted bodies are handed on unchanged.
    """

    def __init__(
        self,
        app: Any,
        *,
        max_body: int,
        token: str | None = None,
        read_timeout: float = 10.0,
        timeout: float = 30.0,
    ) -> None:
        self.app = app
        self.max_body = max_body
        self.token = token
        self.read_timeout = read_timeout
        self.timeout = timeout

    def _authorised(self, scope: dict) -> bool:
        if self.token is None or scope.get("method") in ("GET", "HEAD", "OPTIONS"):
            return True
        for name, value in scope.get("headers", ()):
            if name == b"authorization":
                scheme, _, given = value.decode("latin-1").partition(" ")
                if scheme.lower() == "bearer" and hmac.compare_digest(given.strip().encode(), self.token.encode()):
                    return True
        return False

    async def __call__(self, scope: dict, receive: Callable[[], Awaitable[dict]], send: Callable) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        arrived = time.time()
        scope.setdefault("state", {})[ARRIVED] = arrived
        if not self._authorised(scope):
            await _error(401, "missing or wrong bearer token", www_authenticate="Bearer", connection="close")(
                scope, receive, send
            )
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
        body_deadline = arrived + self.timeout
        while more:
            wait = min(self.read_timeout, body_deadline - time.time())
            try:
                if wait <= 0:
                    raise asyncio.TimeoutError
                message = await asyncio.wait_for(receive(), timeout=wait)
            except asyncio.TimeoutError:
                slow = f"the request body did not arrive in time (read timeout {self.read_timeout:g} s, request timeout {self.timeout:g} s)"
                await _error(408, slow, connection="close")(scope, receive, send)
                return
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


# ---------------------------------------------------------------- bodies


def parse_body(model: type[BaseModel], raw: bytes) -> Any:
    """Validate a request body (bytes) into ``model``; :class:`InputError` with one line otherwise.

    Runs in a thread, never on the event loop: JSON parsing and the format
    validators are CPU-bound.
    """
    if not raw.strip():
        raise InputError("invalid request: a JSON body is required")
    try:
        data = json.loads(raw)
    except RecursionError:
        raise InputError("invalid request: the body is nested too deeply") from None
    except UnicodeDecodeError:
        raise InputError("invalid request: the body is not valid JSON (not UTF-8)") from None
    except json.JSONDecodeError as exc:
        raise InputError(f"invalid request: the body is not valid JSON ({exc.msg})") from None
    try:
        return model.model_validate(data)
    except ValidationError as err:
        raise InputError(validation_message(list(err.errors()))) from None
    except RecursionError:
        raise InputError("invalid request: the body is nested too deeply") from None


def _body_doc(model: type[BaseModel], examples: dict | None = None) -> dict:
    """OpenAPI ``requestBody`` of a route that reads its body itself."""
    content: dict[str, Any] = {"schema": {"$ref": f"#/components/schemas/{model.__name__}"}}
    if examples:
        content["examples"] = examples
    return {"requestBody": {"required": True, "content": {"application/json": content}}}


# ---------------------------------------------------------------- app


_ERRORS = {
    401: {"model": ErrorOut, "description": "The server has a token and the request lacks it."},
    408: {"model": ErrorOut, "description": "The request body arrived too slowly."},
    413: {"model": ErrorOut, "description": "Request body too large."},
    422: {"model": ErrorOut, "description": "Bad input; the same one-line message as the CLI."},
    500: {"model": ErrorOut, "description": "The planner crashed; the service goes on."},
    503: {"model": ErrorOut, "description": "The service is shutting down."},
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
    # Parsing has its own processes: the sentence model (onnxruntime; a
    # process that has parsed peaks at about 230 MB) is loaded once per language worker, never in the planning
    # workers nor in this process.
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
    app.add_middleware(
        BodyLimit, max_body=opts.max_body, token=opts.token, read_timeout=opts.read_timeout, timeout=opts.timeout
    )

    @app.exception_handler(Exception)
    async def _unexpected(_: Request, exc: Exception) -> JSONResponse:
        # Last resort (the server logs the traceback): still one line of JSON.
        return _error(500, f"internal error: {type(exc).__name__}")

    @app.exception_handler(RequestValidationError)
    async def _invalid(_: Request, exc: RequestValidationError) -> JSONResponse:
        return _error(422, validation_message(list(exc.errors())))

    def arrival(request: Request) -> float:
        return float(request.scope.get("state", {}).get(ARRIVED, time.time()))

    def deadline_of(requested: float | None, arrived: float) -> float:
        if requested is not None and not (math.isfinite(requested) and requested > 0):
            raise InputError("timeout must be positive")
        limit = opts.timeout if requested is None else min(requested, opts.timeout)
        return arrived + limit

    async def off_loop(fn: Callable[..., Any], *args: Any, deadline: float) -> Any:
        """``fn(*args)`` in a thread, given up (504) at ``deadline``."""
        remaining = deadline - time.time()
        if remaining <= 0:
            raise jobs.DeadlinePassed("the request's deadline passed")
        return await asyncio.wait_for(asyncio.to_thread(fn, *args), timeout=remaining)

    def llm_endpoint(url: str | None) -> tuple[str | None, str | None]:
        """The endpoint and key override of a request's LLM parse.

        The endpoint is server configuration. A client-named URL is refused
        unless the operator allowed it, and then never gets the server's key.
        """
        if url is None:
            return opts.llm_base_url, None
        if not opts.allow_client_llm_url:
            raise InputError(
                "llm_base_url is chosen by the server's operator (lgmcts serve --llm-base-url), not by requests"
            )
        if not url.startswith(("http://", "https://")):
            raise InputError("llm_base_url must be an http:// or https:// URL")
        return url, "none"  # a placeholder: the server's own key never leaves for a client-chosen host

    async def guarded(work: Callable[[], Awaitable[Any]], what: str) -> Any:
        """Run one request's work; map its failures to one-line JSON errors."""
        try:
            return await work()
        except InputError as exc:
            return _error(422, str(exc))
        except (JobTimeout, jobs.DeadlinePassed, asyncio.TimeoutError):
            return _error(504, f"{what} did not finish within its wall-clock timeout")
        except WorkerCrashed:
            return _error(500, f"the {what} process crashed on this request; the service has replaced it")
        except jobs.Unavailable as exc:
            return _error(501, str(exc))
        except asyncio.CancelledError:
            # The server is stopping and its grace period ran out: answer, do not crash.
            task = asyncio.current_task()
            if task is not None:
                task.uncancel()
            return _error(503, "the service is shutting down; retry the request", retry_after="1")
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

    def prepare_parse(raw: bytes) -> tuple[ParseRequest, str | None, str | None]:
        req = parse_body(ParseRequest, raw)
        url, key = llm_endpoint(req.llm_base_url)
        return req, url, key

    @app.post(
        "/parse",
        response_model=None,
        responses={200: {"description": "Goal JSON."}, **_ERRORS},
        tags=["planning"],
        openapi_extra=_body_doc(ParseRequest, _PARSE_EXAMPLES),
    )
    async def parse(request: Request) -> Any:
        """Turn an instruction into goal JSON (``{"goals": [...]}``) for the scene."""
        arrived = arrival(request)

        async def work() -> Any:
            raw = await request.body()
            req, url, key = await off_loop(prepare_parse, raw, deadline=arrived + opts.timeout)
            deadline = deadline_of(req.timeout, arrived)
            job = jobs.ParseJob(req.scene, req.instruction, req.parser, req.llm_model, url, deadline, key)
            return await language.run(jobs.run_parse, job, deadline=deadline)

        return await guarded(work, "parsing")

    def prepare_plan(raw: bytes) -> tuple[PlanRequest, str | None, str | None]:
        from ..planner import METHODS

        req = parse_body(PlanRequest, raw)
        o = req.options
        if (req.goals is None) == (req.instruction is None):
            raise InputError("give either goals or an instruction, not both or neither")
        if req.goals is not None:
            req.goals.check_against(req.scene)
        if o.seed < 0:
            # numpy's generators take no negative seeds.
            raise InputError("seed must be a non-negative integer")
        if o.time_limit is not None and not (math.isfinite(o.time_limit) and o.time_limit > 0):
            raise InputError("time_limit must be positive")
        if o.method not in METHODS and not (opts.test_hooks and o.method in jobs.HOOK_METHODS):
            raise InputError(f"unknown method '{truncate(o.method, 40)}' (known: {', '.join(METHODS)})")
        url, key = llm_endpoint(req.llm_base_url) if req.instruction is not None else (None, None)
        return req, url, key

    @app.post(
        "/plan",
        response_model=None,
        responses={200: {"description": "Plan JSON."}, **_ERRORS},
        tags=["planning"],
        openapi_extra=_body_doc(PlanRequest, _PLAN_EXAMPLES),
    )
    async def plan(request: Request) -> Any:
        """Plan actions for the scene towards ``goals`` or an ``instruction``.

        The answer is the plan JSON of ``lgmcts plan``: ``solved``, ``actions``,
        ``goals``, ``stats`` (and ``instruction`` when one was given).
        """
        arrived = arrival(request)

        async def work() -> Any:
            raw = await request.body()
            req, url, key = await off_loop(prepare_plan, raw, deadline=arrived + opts.timeout)
            o = req.options
            deadline = deadline_of(o.timeout, arrived)
            goals = req.goals
            if req.instruction is not None:
                parse_job = jobs.ParseJob(req.scene, req.instruction, req.parser, req.llm_model, url, deadline, key)
                try:
                    parsed = await language.run(jobs.run_parse, parse_job, deadline=deadline)
                except (JobTimeout, jobs.DeadlinePassed):
                    return _error(504, "parsing did not finish within its wall-clock timeout")
                except WorkerCrashed:
                    return _error(500, "the parsing process crashed on this request; the service has replaced it")
                goals = await off_loop(GoalSpec.model_validate, parsed, deadline=deadline)
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
            return await pool.run(jobs.run_plan, job, deadline=deadline)

        return await guarded(work, "planning")

    @app.post(
        "/check",
        response_model=VerdictOut,
        responses=_ERRORS,
        tags=["planning"],
        openapi_extra=_body_doc(CheckRequest),
    )
    async def check(request: Request) -> Any:
        """Replay the plan on the scene and judge it against the goals (``lgmcts check --json``)."""
        arrived = arrival(request)

        async def work() -> Any:
            raw = await request.body()
            req = await off_loop(parse_body, CheckRequest, raw, deadline=arrived + opts.timeout)
            deadline = deadline_of(req.timeout, arrived)
            return await pool.run(jobs.run_check, jobs.CheckJob(req.scene, req.goals, req.plan), deadline=deadline)

        return await guarded(work, "checking")

    def openapi() -> dict:
        # The POST routes read their bodies themselves (off the event loop);
        # their documented bodies are the request models, added here.
        if app.openapi_schema:
            return app.openapi_schema
        schema = get_openapi(title=app.title, version=app.version, description=app.description, routes=app.routes)
        _, defs = models_json_schema(
            [(m, "validation") for m in (ParseRequest, PlanRequest, CheckRequest, ViewRequest)],
            ref_template="#/components/schemas/{model}",
        )
        schema.setdefault("components", {}).setdefault("schemas", {}).update(defs.get("$defs", {}))
        app.openapi_schema = schema
        return schema

    app.openapi = openapi  # type: ignore[method-assign]

    @app.post(
        "/view",
        response_model=None,
        responses={200: {"description": "Viewer data."}, **_ERRORS},
        tags=["viewer"],
        openapi_extra=_body_doc(ViewRequest),
    )
    async def view(request: Request) -> Any:
        """What the viewer draws for the plan: each state's poses, footprints, paints and goal shapes
        (``lgmcts.viz.viewer_data``); the page's script draws only this."""
        arrived = arrival(request)

        async def work() -> Any:
            raw = await request.body()
            req = await off_loop(parse_body, ViewRequest, raw, deadline=arrived + opts.timeout)
            deadline = deadline_of(req.timeout, arrived)
            job = jobs.ViewJob(req.scene, req.plan, req.goals, req.instruction)
            body = await pool.run(jobs.run_view, job, deadline=deadline)
            return Response(content=body, media_type="application/json")

        return await guarded(work, "drawing")

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

