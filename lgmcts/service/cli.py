"""``lgmcts serve``: run the planning service (FastAPI on uvicorn)."""

from __future__ import annotations

import errno
import os
import socket

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
    ) -> None:
        """Serve POST /plan, /parse, /check, GET /healthz, the API docs at /docs and a viewer at /.

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
            )
        except InputError as exc:
            fail(str(exc))
        _check_port(host, port)

        import uvicorn

        uvicorn.run(
            create_app(opts),
            host=host,
            port=port,
            log_level=log_level,
            timeout_graceful_shutdown=5,
        )
