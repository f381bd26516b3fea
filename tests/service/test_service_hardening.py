"""The service under hostile clients: tokens, slow clients, deep bodies, borrowed credentials, shutdown."""

from __future__ import annotations

import json
import os
import signal
import socket
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from urllib.parse import urlparse

import httpx
import pytest

from lgmcts import limits

from .conftest import start_server, stop_server

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
SCENE = json.loads((ROOT / "examples" / "tabletop.json").read_text())
GOALS = json.loads((ROOT / "examples" / "goals.json").read_text())
TOKEN = "test-token-0123456789abcdef"
SECRET = "sk-server-secret-must-not-leave"


class Sink:
    """A loopback HTTP server that records every request it gets (and answers 500)."""

    def __init__(self) -> None:
        self.requests: list[dict] = []
        sink = self

        class Handler(BaseHTTPRequestHandler):
            def do_POST(self) -> None:
                n = int(self.headers.get("content-length") or 0)
                sink.requests.append({"path": self.path, "headers": dict(self.headers), "body": self.rfile.read(n)})
                self.send_response(500)
                self.end_headers()

            def log_message(self, *args) -> None:
                pass

        self.server = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self.url = f"http://127.0.0.1:{self.server.server_address[1]}/v1"
        threading.Thread(target=self.server.serve_forever, daemon=True).start()

    def close(self) -> None:
        self.server.shutdown()


@pytest.fixture(scope="module")
def sink():
    s = Sink()
    yield s
    s.close()


@pytest.fixture(scope="module")
def secure(tmp_path_factory):
    """A server with a token, 1 s header and body-read timeouts, and an API key in its environment."""
    log = tmp_path_factory.mktemp("secure") / "server.log"
    old = os.environ.get("OPENAI_API_KEY")
    os.environ["OPENAI_API_KEY"] = SECRET
    os.environ["LGMCTS_SERVICE_TOKEN"] = TOKEN
    try:
        proc, url = start_server("--workers", "1", "--header-timeout", "1", "--read-timeout", "1", "--timeout", "20",
                                 log=log, hooks=False)
    finally:
        os.environ.pop("LGMCTS_SERVICE_TOKEN")
        if old is None:
            os.environ.pop("OPENAI_API_KEY")
        else:
            os.environ["OPENAI_API_KEY"] = old
    yield url, log
    stop_server(proc)


def _auth() -> dict:
    return {"authorization": f"Bearer {TOKEN}"}


def test_token_is_required_on_posts(secure):
    url, _ = secure
    with httpx.Client(base_url=url, timeout=60) as c:
        assert c.get("/healthz").status_code == 200
        r = c.post("/check", json={"scene": SCENE, "goals": GOALS, "plan": {"solved": True, "actions": []}})
        assert r.status_code == 401 and r.json()["detail"] == "missing or wrong bearer token"
        r = c.post("/check", json={"scene": SCENE, "goals": GOALS, "plan": {"solved": True, "actions": []}},
                   headers={"authorization": "Bearer wrong-token-0123456789"})
        assert r.status_code == 401
        r = c.post("/check", json={"scene": SCENE, "goals": GOALS, "plan": {"solved": True, "actions": []}},
                   headers=_auth())
        assert r.status_code == 200 and r.json()["valid"] is False


def test_slow_headers_are_disconnected(secure):
    url, _ = secure
    u = urlparse(url)
    with socket.create_connection((u.hostname, u.port), timeout=10) as s:
        s.sendall(b"GET /healthz HTTP/1.1\r\n")
        t0 = time.monotonic()
        closed = False
        while time.monotonic() - t0 < 30:
            try:
                s.sendall(b"X-Slow: 1\r\n")
            except OSError:
                closed = True
                break
            s.settimeout(0.3)
            try:
                if s.recv(1024) == b"":
                    closed = True
                    break
            except TimeoutError:
                pass
        assert closed, "a client trickling its headers was never disconnected"
        # 1 s allowed; the headers would trickle for 30 s. 15 s is wide enough
        # for a loaded machine.
        assert time.monotonic() - t0 < 15


def test_slow_body_gets_408(secure):
    url, _ = secure
    u = urlparse(url)
    body = json.dumps({"scene": SCENE, "goals": GOALS, "plan": {"solved": True, "actions": []}}).encode()
    head = (
        "POST /check HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
        f"Authorization: Bearer {TOKEN}\r\n"
        f"Content-Length: {len(body)}\r\n\r\n"
    ).encode()
    with socket.create_connection((u.hostname, u.port), timeout=10) as s:
        s.sendall(head + body[:10])
        time.sleep(2.5)  # past the 1 s read timeout
        data = b""
        s.settimeout(30)
        try:
            while b"\r\n\r\n" not in data:
                chunk = s.recv(4096)
                if not chunk:
                    break
                data += chunk
        except TimeoutError:
            pass
    assert data.startswith(b"HTTP/1.1 408"), data[:200]


def test_client_chosen_llm_url_is_refused_and_gets_nothing(secure, sink):
    url, _ = secure
    with httpx.Client(base_url=url, timeout=60, headers=_auth()) as c:
        for path, body in (
            (
                "/parse",
                {"scene": SCENE, "instruction": "put the blocks in a line", "parser": "llm", "llm_base_url": sink.url},
            ),
            (
                "/plan",
                {"scene": SCENE, "instruction": "put the blocks in a line", "parser": "llm", "llm_base_url": sink.url},
            ),
        ):
            r = c.post(path, json=body)
            assert r.status_code == 422 and "operator" in r.json()["detail"]
    assert sink.requests == []


def test_client_llm_url_when_allowed_never_gets_the_server_key(tmp_path, sink):
    log = tmp_path / "server.log"
    old = os.environ.get("OPENAI_API_KEY")
    os.environ["OPENAI_API_KEY"] = SECRET
    try:
        proc, url = start_server("--workers", "1", "--allow-client-llm-url", log=log, hooks=False)
    finally:
        if old is None:
            os.environ.pop("OPENAI_API_KEY")
        else:
            os.environ["OPENAI_API_KEY"] = old
    try:
        before = len(sink.requests)
        r = httpx.post(
            url + "/parse",
            json={
                "scene": SCENE,
                "instruction": "put the blocks in a line",
                "parser": "llm",
                "llm_model": "m",
                "llm_base_url": sink.url,
            },
            timeout=120,
        )
        assert r.status_code in (422, 500, 502, 504) and "\n" not in r.json()["detail"]
        got = sink.requests[before:]
        assert got, "the allowed client URL was never called"
        for req in got:
            assert SECRET not in json.dumps(req["headers"]) and SECRET.encode() not in req["body"]
    finally:
        stop_server(proc)


def test_deep_and_big_bodies_are_one_line_422(secure):
    url, _ = secure
    with httpx.Client(base_url=url, timeout=60, headers=_auth()) as c:
        r = c.post("/plan", content=b"[" * 100_000, headers={"content-type": "application/json"})
        assert r.status_code == 422 and r.json()["detail"] == "invalid request: the body is nested too deeply"
        long = "put the blocks in a line " * (limits.MAX_INSTRUCTION // 10)
        r = c.post("/parse", json={"scene": SCENE, "instruction": long})
        assert r.status_code == 422 and len(r.json()["detail"]) < 600
        plan = {"solved": True, "actions": [{"object": 9, "to": [1e20, 1e20, 0], "on": None, "purpose": "relocate"}]}
        r = c.post("/check", json={"scene": SCENE, "goals": GOALS, "plan": plan})
        assert r.status_code == 422 and "action pose" in r.json()["detail"]
        plan["actions"][0]["to"] = [100.0, 100.0, 0.0]
        r = c.post("/check", json={"scene": SCENE, "goals": GOALS, "plan": plan})
        assert r.status_code == 200 and r.json()["valid"] is False
        r = c.post(
            "/plan",
            json={
                "scene": SCENE,
                "goals": {
                    "goals": [
                        {"pattern": "pose", "objects": [1], "pose": [0.1, 0.1, 0]},
                        {"pattern": "pose", "objects": [2], "pose": [0.1, 0.1, 0]},
                    ]
                },
            },
        )
        assert r.status_code == 422 and "pose goals" in r.json()["detail"]


def test_timeout_runs_from_arrival(secure):
    """A body sent slowly (each piece within the read timeout) counts against the request's timeout."""
    url, _ = secure
    u = urlparse(url)
    body = json.dumps({"scene": SCENE, "goals": GOALS, "plan": {"solved": True, "actions": []}, "timeout": 2}).encode()
    head = (
        "POST /check HTTP/1.1\r\nHost: 127.0.0.1\r\nContent-Type: application/json\r\n"
        f"Authorization: Bearer {TOKEN}\r\n"
        f"Content-Length: {len(body)}\r\n\r\n"
    ).encode()
    with socket.create_connection((u.hostname, u.port), timeout=10) as s:
        s.sendall(head)
        t0 = time.monotonic()
        # Pieces 0.2 s apart (the read timeout is 1 s: a wide margin on a busy
        # machine) for 3 s, past the request's own 2 s.
        for k in range(0, len(body), 50):
            s.sendall(body[k : k + 50])
            time.sleep(0.2 if time.monotonic() - t0 < 3 else 0)
        s.settimeout(20)
        data = s.recv(4096)
    # 2 s of the request's own timeout were spent sending: 504, not a verdict.
    assert data.startswith(b"HTTP/1.1 504"), data[:200]


def test_sigint_with_a_request_in_flight_answers_json(tmp_path):
    log = tmp_path / "server.log"
    proc, url = start_server("--workers", "1", "--grace", "1", "--timeout", "60", log=log, hooks=True)
    result: dict = {}

    def call() -> None:
        try:
            result["r"] = httpx.post(
                url + "/plan",
                json={"scene": SCENE, "goals": GOALS, "options": {"method": "_sleep", "time_limit": 20}},
                timeout=60,
            )
        except httpx.HTTPError as exc:  # pragma: no cover - reported below
            result["error"] = exc

    t = threading.Thread(target=call)
    t.start()
    time.sleep(3.0)  # for the request to reach the worker, on a loaded machine too
    proc.send_signal(signal.SIGINT)
    t.join(30)
    try:
        proc.wait(timeout=30)
    finally:
        stop_server(proc)
    assert "r" in result, result
    r = result["r"]
    assert r.status_code in (200, 503) and r.headers["content-type"].startswith("application/json")
    assert "\n" not in r.json()["detail"]
    assert "Traceback" not in log.read_text()
