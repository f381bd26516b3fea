"""A real service on loopback for the service tests, started once per session."""

from __future__ import annotations

import os
import socket
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path

import httpx
import pytest

ROOT = Path(__file__).resolve().parents[2]

#: The test server's body limit (bytes), small so a 413 needs little traffic.
MAX_BODY = 256 * 1024


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@dataclass(frozen=True)
class Server:
    url: str
    pid: int
    log: Path


def start_server(*args: str, log: Path, hooks: bool = True, startup: float = 90.0) -> tuple[subprocess.Popen, str]:
    """Start ``python -m lgmcts.service`` on a free port; return the process and its URL once healthy."""
    port = free_port()
    env = dict(os.environ)
    if hooks:
        env["LGMCTS_SERVICE_TEST_HOOKS"] = "1"
    cmd = [sys.executable, "-m", "lgmcts.service", "--port", str(port), "--log-level", "warning", *args]
    proc = subprocess.Popen(cmd, cwd=ROOT, env=env, stdout=log.open("w"), stderr=subprocess.STDOUT)
    url = f"http://127.0.0.1:{port}"
    t_end = time.monotonic() + startup
    while time.monotonic() < t_end:
        if proc.poll() is not None:
            raise RuntimeError(f"service exited with {proc.returncode}: {log.read_text()[-2000:]}")
        try:
            if httpx.get(url + "/healthz", timeout=1.0).status_code == 200:
                return proc, url
        except httpx.TransportError:
            pass
        time.sleep(0.1)
    proc.kill()
    raise RuntimeError(f"service did not start within {startup} s: {log.read_text()[-2000:]}")


def stop_server(proc: subprocess.Popen) -> None:
    proc.terminate()
    try:
        proc.wait(timeout=15)
    except subprocess.TimeoutExpired:
        proc.kill()
        proc.wait()


@pytest.fixture(scope="session")
def server(tmp_path_factory: pytest.TempPathFactory) -> Server:
    """Two planning workers, one language worker loading its model at once, test
    hooks on, a 60 s timeout (tests ask for less per request), 1 s grace and a
    256 KiB body limit."""
    log = tmp_path_factory.mktemp("service") / "server.log"
    proc, url = start_server(
        "--workers",
        "2",
        "--preload-language",
        "--timeout",
        "60",
        "--grace",
        "1",
        "--max-body",
        str(MAX_BODY),
        "--max-iter",
        "5000",
        log=log,
    )
    try:
        yield Server(url=url, pid=proc.pid, log=log)
    finally:
        stop_server(proc)


@pytest.fixture()
def client(server: Server) -> httpx.Client:
    with httpx.Client(base_url=server.url, timeout=30.0) as c:
        yield c
