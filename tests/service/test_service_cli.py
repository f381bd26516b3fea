"""``lgmcts serve`` on the command line: its options and its one-line failures."""

from __future__ import annotations

import socket

import pytest
import typer
from typer.testing import CliRunner

from lgmcts.service.cli import register

pytestmark = pytest.mark.slow


@pytest.fixture(scope="module")
def serve_app() -> typer.Typer:
    app = typer.Typer(add_completion=False, pretty_exceptions_enable=False)
    register(app)
    return app


def test_serve_is_a_command_of_lgmcts():
    from lgmcts.cli import app

    r = CliRunner().invoke(app, ["serve", "--help"])
    assert r.exit_code == 0, r.output
    for option in ("--host", "--port", "--workers", "--max-body", "--timeout"):
        assert option in r.output


@pytest.mark.parametrize(
    "args, message",
    [
        (("--workers", "0"), "workers must be at least 1"),
        (("--timeout", "0"), "timeout must be positive"),
        (("--max-body", "0"), "max_body must be at least 1 byte"),
        (("--max-iter", "0"), "max_iter must be at least 1"),
        (("--port", "70000"), "port must be between 0 and 65535"),
        (("--log-level", "loud"), "unknown log level 'loud' (known: critical, error, warning, info, debug)"),
        (("--host", "no.such.host.invalid"), None),
    ],
)
def test_bad_option_is_one_line_and_exit_2(serve_app, args, message):
    r = CliRunner().invoke(serve_app, list(args))
    assert r.exit_code == 2, r.output
    lines = r.output.strip().splitlines()
    assert len(lines) == 1
    if message is not None:
        assert lines[0] == message
    else:
        assert lines[0].startswith("cannot resolve host 'no.such.host.invalid'")


def test_port_in_use_is_one_line_and_exit_2(serve_app):
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        s.listen()
        port = s.getsockname()[1]
        r = CliRunner().invoke(serve_app, ["--port", str(port)])
    assert r.exit_code == 2
    assert r.output.strip() == f"port {port} on 127.0.0.1 is already in use"
