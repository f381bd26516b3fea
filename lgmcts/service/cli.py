"""``lgmcts serve``: run the planning service (FastAPI on uvicorn)."""

from __future__ import annotations

import errno
import ipaddress
import math
import os
import socket
from typing import Optional

import typer

from ..cli_util import fail
from ..errors import InputError

__all__ = ["register"]


def _check_port(host: str, port: int) -> None:
    """Fail with one line when ``host:port`` cannot be bound (in use, bad address)."""
    try:
        infos = socket.getaddrinfo(host, port, type=socket.SOCK_STREAM)
    except socket.gaierror as exc:
        fail(f"cannot resolve host '{host}': {exc.strerror}")
    family, kind, proto, _, addr = infos[0]
    with socket.socket(family, kind, proto) as s:
        s.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
        try:
            s.bind(addr)
        except OSError as exc:
            if exc.errno == errno.EADDRINUSE:
                fail(f"port {port} on {host} is already in use")
            fail(f"cannot listen on {host}:{port}: {exc.strerror}")


def _loopback(host: str) -> bool:
    """Whether ``host`` names only this machine (127.0.0.0/8, ::1, localhost)."""
    if host.lower() == "localhost":
        return True
    try:
        return ipaddress.ip_address(host).is_loopback
    except ValueError:
        return False


def default_workers() -> int:
    """One planning worker per CPU this process may use."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # pragma: no cover - not Linux
        return max(1, os.cpu_count() or 1)


def register(app: typer.Typer) -> None:
    """Add the ``serve`` command to the ``lgmcts`` command line.

    Nothing heavy is imported here: FastAPI and uvicorn load when ``serve`` runs.
    """

    @app.command()
    def serve(
        host: str = typer.Option("127.0.0.1", help="Address to listen on."),
        port: int = typer.Option(8000, help="TCP port."),
        workers: int = typer.Option(default_workers(), help="Planning processes (default: one per CPU)."),
        language_workers: int = typer.Option(1, "--language-workers", help="Processes that parse instructions."),
        preload_language: bool = typer.Option(
            False, "--preload-language", help="Load the sentence model at start-up, not on the first instruction."
        ),
        max_body: int = typer.Option(4 * 1024 * 1024, "--max-body", help="Largest request body in bytes (413 above)."),
        timeout: float = typer.Option(30.0, help="Wall-clock limit of a request in seconds (504 past it)."),
        max_iter: int = typer.Option(10_000, "--max-iter", help="Cap on a request's planner iteration budget."),
        grace: float = typer.Option(5.0, help="Seconds a job may overrun its timeout before its worker is replaced."),
        log_level: str = typer.Option("info", "--log-level", help="critical, error, warning, info or debug."),
        token: Optional[str] = typer.Option(
            None,
            "--token",
            envvar="LGMCTS_SERVICE_TOKEN",
            show_envvar=True,
            help="Require 'Authorization: Bearer TOKEN' on every POST (at least 16 characters). "
            "Prefer the environment variable: a command line is visible to other users.",
        ),
        read_timeout: float = typer.Option(
            10.0, "--read-timeout", help="Longest wait in seconds for the next piece of a request body (408 past it)."
        ),
        header_timeout: float = typer.Option(
            10.0, "--header-timeout", help="Seconds a connection may take to send its request headers before it is closed."
        ),
        llm_base_url: Optional[str] = typer.Option(
            None, "--llm-base-url", help="OpenAI-compatible endpoint of the llm parser (the key: OPENAI_API_KEY)."
        ),
        allow_client_llm_url: bool = typer.Option(
            False,
            "--allow-client-llm-url",
            help="Accept llm_base_url in requests; such requests never receive the server's API key.",
        ),
        allow_llm_model: list[str] = typer.Option(
            [],
            "--allow-llm-model",
            help="A model name requests may ask for besides LGMCTS_LLM_MODEL; repeatable "
            "(also LGMCTS_SERVICE_LLM_MODELS, comma-separated).",
        ),
        allow_host: list[str] = typer.Option(
            [],
            "--allow-host",
            help="A Host name to serve besides loopback ones (a reverse proxy's public name); repeatable "
            "(also LGMCTS_SERVICE_HOSTS, comma-separated).",
        ),
        allow_origin: list[str] = typer.Option(
            [],
            "--allow-origin",
            help="A web page origin (https://example.org) whose requests are accepted; repeatable "
            "(also LGMCTS_SERVICE_ORIGINS, comma-separated).",
        ),
        docs: bool = typer.Option(
            False, "--docs", help="Serve the interactive API page at /docs (it loads Swagger UI from a public CDN)."
        ),
    ) -> None:
        """Serve POST /plan, /parse, /check, /view, GET /healthz, /openapi.json and a viewer at /.

        Planning runs in a pool of WORKERS processes; bad input answers 422
        with the same one-line message as the CLI.
        """
        from .app import create_app, options_from_env

        if not 0 <= port <= 65535:
            fail("port must be between 0 and 65535")
        if log_level not in ("critical", "error", "warning", "info", "debug"):
            fail(f"unknown log level '{log_level}' (known: critical, error, warning, info, debug)")
        try:
            opts = options_from_env(
                workers=workers,
                language_workers=language_workers,
                preload_language=preload_language,
                max_body=max_body,
                timeout=timeout,
                max_iter=max_iter,
                grace=grace,
                token=None if token == "" else token,
                read_timeout=read_timeout,
                header_timeout=header_timeout,
                llm_base_url=llm_base_url,
                allow_client_llm_url=allow_client_llm_url,
                llm_models=tuple(allow_llm_model),
                loopback=_loopback(host),
                allowed_hosts=tuple(allow_host),
                allowed_origins=tuple(allow_origin),
                docs=docs,
            )
        except InputError as exc:
            fail(str(exc))
        _check_port(host, port)
        if opts.token is None and not _loopback(host):
            typer.echo(
                f"WARNING: serving on {host}, reachable from other machines, with no authentication: anyone who "
                "can reach this port can make it plan (use --token or LGMCTS_SERVICE_TOKEN, or a proxy with "
                "authentication; see docs/service.md, Security)",
                err=True,
            )

        import uvicorn

        from .guard import protocol_with_header_timeout

        uvicorn.run(
            create_app(opts),
            host=host,
            port=port,
            log_level=log_level,
            http=protocol_with_header_timeout(opts.header_timeout),
            timeout_graceful_shutdown=max(1, math.ceil(opts.grace)),
        )
