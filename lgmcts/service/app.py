"""The HTTP application: routes, limits and the mapping of failures to status codes.

=========  ==============================================================
status     meaning
=========  ==============================================================
200        the result (a plan that is not solved is still 200, ``solved: false``)
401        the server has a token and the request does not carry it (exactly once)
403        the request comes from a web page of another origin (``Origin``)
408        the request body did not arrive within ``read_timeout`` / ``timeout``
413        the request body is larger than ``max_body`` bytes
415        a POST body not sent as ``Content-Type: application/json``
421        the ``Host`` header names a host this server does not serve
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

A request whose client disconnects is dropped: its job is withdrawn from
the queue, or stopped in its worker (:meth:`WorkerPool.run`).

Every error body is ``{"detail": "<one line>"}``.
"""

from __future__ import annotations

import asyncio
import hmac
import ipaddress
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
from pydantic import BaseModel
from pydantic.json_schema import models_json_schema

from .. import __version__
from ..errors import InputError
from ..limits import printable, truncate
from . import jobs
from .bodies import Body, Policy, parse_body, validation_message
from .models import CheckRequest, ErrorOut, HealthOut, ParseRequest, PlanRequest, VerdictOut, ViewRequest
from .pool import JobTimeout, WorkerCrashed, WorkerPool
from .viewer import EXAMPLE_GOALS, EXAMPLE_INSTRUCTION, EXAMPLE_SCENE, page

__all__ = [
    "ServiceOptions",
    "create_app",
    "options_from_env",
    "validation_message",
    "parse_body",
    "BodyLimit",
    "TEST_HOOKS_ENV",
    "TOKEN_ENV",
    "HOSTS_ENV",
    "ORIGINS_ENV",
    "LLM_MODELS_ENV",
    "ARRIVED",
]

log = logging.getLogger("lgmcts.service")

#: Environment variable that enables the test-only planner methods
#: (:data:`lgmcts.service.jobs.HOOK_METHODS`). Never set it in production.
TEST_HOOKS_ENV = "LGMCTS_SERVICE_TEST_HOOKS"

#: Environment variable holding the bearer token (``lgmcts serve --token``).
TOKEN_ENV = "LGMCTS_SERVICE_TOKEN"

#: Environment variables listing (comma-separated) more ``Host`` names, page
#: origins and client-chosen LLM models the server accepts
#: (``lgmcts serve --allow-host/--allow-origin/--allow-llm-model`` add to them).
HOSTS_ENV = "LGMCTS_SERVICE_HOSTS"
ORIGINS_ENV = "LGMCTS_SERVICE_ORIGINS"
LLM_MODELS_ENV = "LGMCTS_SERVICE_LLM_MODELS"

#: The operator's LLM model (the llm parser's default; always allowed).
LLM_MODEL_ENV = "LGMCTS_LLM_MODEL"

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
    llm_models : the model names a request may ask for with ``llm_model``
        (the operator's own model and those listed in ``LGMCTS_SERVICE_LLM_MODELS``);
        any other is refused (422) unless the request also brings its own endpoint.
    loopback : the server listens on loopback only; then a ``Host`` header
        naming anything but this machine (or ``allowed_hosts``) is refused (421).
    allowed_hosts : more ``Host`` names to serve (a reverse proxy's public
        name); when not on loopback and given, the only ones served.
    allowed_origins : page origins (``https://example.org``) besides the
        service's own whose requests are accepted; any other ``Origin`` is 403.
    docs : serve the interactive API page at ``/docs`` (it loads Swagger UI
        from a public CDN); off by default, ``/openapi.json`` is always served.
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
    llm_models: tuple[str, ...] = ()
    loopback: bool = False
    allowed_hosts: tuple[str, ...] = ()
    allowed_origins: tuple[str, ...] = ()
    docs: bool = False

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
        if self.token is not None:
            if not self.token.strip():
                raise InputError("the token is blank; give at least 16 characters that are not spaces")
            if self.token != self.token.strip() or any(ord(c) < 32 or ord(c) == 127 for c in self.token):
                raise InputError("the token must not start or end with spaces nor hold control characters")
            if len(self.token) < 16:
                raise InputError("the token must be at least 16 characters long")
            try:
                self.token.encode("utf-8")
            except UnicodeEncodeError:
                raise InputError("the token is not valid UTF-8 text") from None


# ---------------------------------------------------------------- errors


def _error(status: int, message: str, **headers: str) -> JSONResponse:
    line = truncate(" ".join(str(message).split()), MAX_DETAIL)
    return JSONResponse({"detail": line}, status_code=status, headers={k.replace("_", "-"): v for k, v in headers.items()} or None)


def _drop(task: asyncio.Future) -> None:
    """Cancel ``task`` without waiting for it; whatever it ends with is collected, not logged."""
    task.cancel()
    task.add_done_callback(lambda t: t.cancelled() or t.exception())


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
        loopback: bool = False,
        allowed_hosts: tuple[str, ...] = (),
        allowed_origins: tuple[str, ...] = (),
    ) -> None:
        self.app = app
        self.max_body = max_body
        self.token = None if token is None else token.encode("utf-8")
        self.read_timeout = read_timeout
        self.timeout = timeout
        self.loopback = loopback
        self.allowed_hosts = frozenset(h.lower().rstrip(".") for h in allowed_hosts)
        self.allowed_origins = frozenset(o.lower().rstrip("/") for o in allowed_origins)

    def _authorised(self, scope: dict) -> bool:
        """Exactly one ``Authorization: Bearer <token>`` header, compared as bytes in constant time."""
        if self.token is None or scope.get("method") in ("GET", "HEAD", "OPTIONS"):
            return True
        given = [value for name, value in scope.get("headers", ()) if name == b"authorization"]
        if len(given) != 1:
            return False  # none, or several (one guess per request)
        scheme, _, token = given[0].strip().partition(b" ")
        return scheme.lower() == b"bearer" and hmac.compare_digest(token.strip(), self.token)

    def _host_refused(self, host: str | None) -> bool:
        """Whether the ``Host`` header names a host this server does not serve (DNS rebinding)."""
        if host is None or not (self.loopback or self.allowed_hosts):
            return False
        name = _host_name(host)
        if name in self.allowed_hosts:
            return False
        return not (self.loopback and _loopback_name(name))

    def _origin_refused(self, origin: str | None, host: str | None) -> bool:
        """Whether ``Origin`` names a web page of another origin than the service's own."""
        if origin is None:
            return False
        o = origin.strip().lower().rstrip("/")
        if o in self.allowed_origins:
            return False
        scheme, sep, netloc = o.partition("://")
        if not sep or scheme not in ("http", "https") or host is None:
            return True  # "null" (a sandboxed or file page) or garbage
        return netloc != host.strip().lower()

    async def __call__(self, scope: dict, receive: Callable[[], Awaitable[dict]], send: Callable) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        arrived = time.time()
        scope.setdefault("state", {})[ARRIVED] = arrived
        headers: dict[bytes, list[bytes]] = {}
        for name, value in scope.get("headers", ()):
            headers.setdefault(name, []).append(value)
        host = headers.get(b"host", [None])[0]
        host_text = None if host is None else host.decode("latin-1")
        if len(headers.get(b"host", ())) > 1 or self._host_refused(host_text):
            shown = truncate(printable(host_text or ""), 60)
            await _error(421, f"this server does not serve host '{shown}' (see --allow-host)", connection="close")(
                scope, receive, send
            )
            return
        origins = headers.get(b"origin", [])
        if len(origins) > 1 or (origins and self._origin_refused(origins[0].decode("latin-1"), host_text)):
            await _error(
                403, "requests from web pages of another origin are refused (see --allow-origin)", connection="close"
            )(scope, receive, send)
            return
        if not self._authorised(scope):
            await _error(401, "missing or wrong bearer token", www_authenticate="Bearer", connection="close")(
                scope, receive, send
            )
            return
        if scope.get("method") == "POST" and not _json_type(headers.get(b"content-type", [])):
            await _error(415, "the body must be sent as Content-Type: application/json", connection="close")(
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


def _host_name(host: str) -> str:
    """The name in a ``Host`` header without its port, lower case, no trailing dot."""
    h = host.strip().lower()
    if h.startswith("["):
        return h[1 : h.find("]")] if "]" in h else h
    if h.count(":") == 1:
        h = h.split(":", 1)[0]
    return h.rstrip(".")


def _loopback_name(name: str) -> bool:
    """Whether ``name`` (a host name or address) can only mean this machine."""
    if name == "localhost" or name.endswith(".localhost"):
        return True
    try:
        return ipaddress.ip_address(name).is_loopback
    except ValueError:
        return False


def _json_type(values: list[bytes]) -> bool:
    """Whether exactly one ``Content-Type`` was sent and it is ``application/json`` (parameters allowed)."""
    if len(values) != 1:
        return False
    kind = values[0].split(b";", 1)[0].strip().lower()
    return kind == b"application/json"


# ---------------------------------------------------------------- bodies


def _body_doc(model: type[BaseModel], examples: dict | None = None) -> dict:
    """OpenAPI ``requestBody`` of a route that reads its body itself."""
    content: dict[str, Any] = {"schema": {"$ref": f"#/components/schemas/{model.__name__}"}}
    if examples:
        content["examples"] = examples
    return {"requestBody": {"required": True, "content": {"application/json": content}}}


# ---------------------------------------------------------------- app


_ERRORS: dict[int | str, dict[str, Any]] = {
    401: {"model": ErrorOut, "description": "The server has a token and the request lacks it."},
    403: {"model": ErrorOut, "description": "The request comes from a web page of another origin."},
    408: {"model": ErrorOut, "description": "The request body arrived too slowly."},
    413: {"model": ErrorOut, "description": "Request body too large."},
    415: {"model": ErrorOut, "description": "The body was not sent as Content-Type: application/json."},
    421: {"model": ErrorOut, "description": "The Host header names a host this server does not serve."},
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
    # Request bodies are read and validated in a process of their own, so that
    # a bad body is answered at once even while every planning worker is busy.
    intake = WorkerPool(workers=1, grace=opts.grace, name="intake")

    @asynccontextmanager
    async def lifespan(_: FastAPI):
        pool.start(warm=opts.warm)
        language.start(warm=False)
        intake.start(warm=opts.warm)
        if opts.preload_language:
            from .viewer import EXAMPLE_INSTRUCTION, EXAMPLE_SCENE

            for _k in range(opts.language_workers):
                language.submit_background(jobs.warm_language, EXAMPLE_INSTRUCTION, EXAMPLE_SCENE)
        try:
            yield
        finally:
            pool.close()
            language.close()
            intake.close()

    app = FastAPI(
        title="lgmcts planning service",
        version=__version__,
        description=(
            "Plan tabletop rearrangements from goals or plain-language commands. "
            "Lengths in metres, angles in radians, table frame +x right, +y away from the viewer. "
            "Every error answers {\"detail\": \"<one line>\"}."
        ),
        lifespan=lifespan,
        # FastAPI's /docs and /redoc pages load their scripts from a public CDN.
        docs_url="/docs" if opts.docs else None,
        redoc_url=None,
    )
    app.state.pool = pool
    app.state.language = language
    app.state.options = opts
    app.add_middleware(
        BodyLimit,
        max_body=opts.max_body,
        token=opts.token,
        read_timeout=opts.read_timeout,
        timeout=opts.timeout,
        loopback=opts.loopback,
        allowed_hosts=opts.allowed_hosts,
        allowed_origins=opts.allowed_origins,
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

    async def until_disconnect(request: Request) -> None:
        """Return when the client of ``request`` (whose body was read) disconnects."""
        while True:
            message = await request.receive()
            if message.get("type") == "http.disconnect":
                return

    async def guarded(request: Request, work: Callable[[bytes], Awaitable[Any]], what: str) -> Any:
        """Run one request's work on its body; map its failures to one-line JSON errors.

        When the client disconnects first, the work is cancelled (its job
        withdrawn from the queue or stopped in its worker).
        """
        raw = await request.body()
        task = asyncio.ensure_future(work(raw))
        gone = asyncio.ensure_future(until_disconnect(request))
        try:
            await asyncio.wait({task, gone}, return_when=asyncio.FIRST_COMPLETED)
        except asyncio.CancelledError:
            # The server is stopping and its grace period ran out: answer, do not crash.
            _drop(task)
            _drop(gone)
            current = asyncio.current_task()
            if current is not None:
                current.uncancel()
            return _error(503, "the service is shutting down; retry the request", retry_after="1")
        if not task.done():
            _drop(task)
            log.info("%s abandoned: the client went away", what)
            return _error(499, "the client closed the connection")
        gone.cancel()
        try:
            return task.result()
        except InputError as exc:
            return _error(422, str(exc))
        except (JobTimeout, jobs.DeadlinePassed, asyncio.TimeoutError):
            return _error(504, f"{what} did not finish within its wall-clock timeout")
        except WorkerCrashed:
            return _error(500, f"the {what} process crashed on this request; the service has replaced it")
        except jobs.Unavailable as exc:
            return _error(501, str(exc))
        except asyncio.CancelledError:
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
            "restarts": pool.restarts + language.restarts + intake.restarts,
            "timeout_s": opts.timeout,
            "max_iter": opts.max_iter,
            "max_body_bytes": opts.max_body,
        }

    policy = Policy(
        test_hooks=opts.test_hooks,
        max_iter=opts.max_iter,
        llm_base_url=opts.llm_base_url,
        allow_client_llm_url=opts.allow_client_llm_url,
        llm_models=opts.llm_models,
    )

    async def answer(kind: str, raw: bytes, arrived: float) -> Response:
        """Validate ``raw`` in the intake worker, then do its work in the pool that does it.

        The body is parsed in worker processes only, so no request holds
        this process's interpreter; the answer comes back as JSON bytes.
        """
        body = Body(kind, raw, policy)
        meta = await intake.run(jobs.inspect, body, deadline=arrived + opts.timeout)
        deadline = deadline_of(meta["timeout"], arrived)
        if kind == "parse":
            out = await language.run(jobs.run_body, jobs.BodyJob(body, deadline), deadline=deadline)
        elif kind == "plan" and meta["instruction"]:
            try:
                goals = await language.run(
                    jobs.run_body, jobs.BodyJob(body, deadline, parse_only=True), deadline=deadline
                )
            except (JobTimeout, jobs.DeadlinePassed):
                return _error(504, "parsing did not finish within its wall-clock timeout")
            except WorkerCrashed:
                return _error(500, "the parsing process crashed on this request; the service has replaced it")
            out = await pool.run(jobs.run_body, jobs.BodyJob(body, deadline, goals), deadline=deadline)
        else:
            out = await pool.run(jobs.run_body, jobs.BodyJob(body, deadline), deadline=deadline)
        return Response(content=out, media_type="application/json")

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
        return await guarded(request, lambda raw: answer("parse", raw, arrived), "parsing")

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
        return await guarded(request, lambda raw: answer("plan", raw, arrived), "planning")

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
        return await guarded(request, lambda raw: answer("check", raw, arrived), "checking")

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
        return await guarded(request, lambda raw: answer("view", raw, arrived), "drawing")

    @app.get("/", response_class=HTMLResponse, tags=["viewer"])
    async def viewer() -> HTMLResponse:
        """A page to paste or upload a scene, give an instruction or goals, plan and see the plan drawn."""
        return HTMLResponse(page())

    @app.get("/favicon.ico", include_in_schema=False)
    async def favicon() -> Response:
        return Response(status_code=204)

    return app


def _env_list(name: str) -> tuple[str, ...]:
    return tuple(v.strip() for v in os.environ.get(name, "").split(",") if v.strip())


def options_from_env(**kwargs: Any) -> ServiceOptions:
    """:class:`ServiceOptions` from keyword arguments and the environment.

    The environment gives the test hooks (:data:`TEST_HOOKS_ENV`) and adds to
    the allowed hosts, origins and LLM models (:data:`HOSTS_ENV`,
    :data:`ORIGINS_ENV`, :data:`LLM_MODELS_ENV`; the operator's own model,
    :data:`LLM_MODEL_ENV`, is always allowed).
    """
    hooks = os.environ.get(TEST_HOOKS_ENV, "").strip().lower() in ("1", "true", "yes")
    own = _env_list(LLM_MODEL_ENV)[:1]
    kwargs["allowed_hosts"] = tuple(kwargs.get("allowed_hosts", ())) + _env_list(HOSTS_ENV)
    kwargs["allowed_origins"] = tuple(kwargs.get("allowed_origins", ())) + _env_list(ORIGINS_ENV)
    kwargs["llm_models"] = tuple(kwargs.get("llm_models", ())) + own + _env_list(LLM_MODELS_ENV)
    return ServiceOptions(test_hooks=hooks, **kwargs)

