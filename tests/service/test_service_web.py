"""What a web page, an abandoning client or a huge drawing can make the service do (issue 23)."""

from __future__ import annotations

import json
import os
import socket
import subprocess
import sys
import threading
import time

import httpx
import pytest

from lgmcts import limits

from .conftest import ROOT, start_server, stop_server
from .test_service_hardening import Sink

pytestmark = pytest.mark.slow

SCENE = json.loads((ROOT / "examples" / "tabletop.json").read_text())
GOALS = json.loads((ROOT / "examples" / "goals.json").read_text())
CHECK = {"scene": SCENE, "goals": GOALS, "plan": {"solved": True, "actions": []}}


# ---------------------------------------------------------------- browsers


def test_post_bodies_must_be_sent_as_json(client):
    body = json.dumps(CHECK)
    for kind in ("text/plain", "application/x-www-form-urlencoded", "multipart/form-data; boundary=x", None):
        headers = {} if kind is None else {"content-type": kind}
        r = client.post("/check", content=body, headers=headers)
        assert r.status_code == 415, (kind, r.text)
        assert r.json() == {"detail": "the body must be sent as Content-Type: application/json"}
    r = client.post("/check", content=body, headers={"content-type": "application/json; charset=utf-8"})
    assert r.status_code == 200 and r.json()["valid"] is False


def test_a_foreign_origin_is_refused(client, server):
    for origin in ("http://evil.example", "null", "http://127.0.0.1:1", "http://localhost" + server.url[16:], "x"):
        r = client.post("/check", json=CHECK, headers={"origin": origin})
        assert r.status_code == 403, origin
        assert "another origin" in r.json()["detail"] and "\n" not in r.json()["detail"]
    same = client.post("/check", json=CHECK, headers={"origin": server.url})
    assert same.status_code == 200


def test_a_rebound_host_name_is_refused_on_loopback(client, server):
    port = server.url.rsplit(":", 1)[1]
    for host in (f"evil.example:{port}", "evil.example", f"10.0.0.1:{port}", f"localhost.evil.example:{port}"):
        for method, path in (("GET", "/healthz"), ("POST", "/check")):
            r = client.request(method, path, json=CHECK if method == "POST" else None, headers={"host": host})
            assert r.status_code == 421, (host, path)
            assert "does not serve host" in r.json()["detail"]
    for host in (f"127.0.0.1:{port}", f"localhost:{port}", f"[::1]:{port}", "127.0.0.2"):
        assert client.get("/healthz", headers={"host": host}).status_code == 200, host


def test_allowed_host_and_origin_behind_a_proxy(tmp_path):
    proc, url = start_server("--workers", "1", "--allow-host", "plan.example.org",
                             "--allow-origin", "https://tools.example.org", log=tmp_path / "s.log", hooks=False)
    try:
        with httpx.Client(base_url=url, timeout=60) as c:
            assert c.get("/healthz", headers={"host": "plan.example.org"}).status_code == 200
            assert c.get("/healthz", headers={"host": "other.example.org"}).status_code == 421
            # A page served by the proxy under the public name is same-origin there.
            r = c.post("/check", json=CHECK, headers={"host": "plan.example.org", "origin": "https://plan.example.org"})
            assert r.status_code == 200
            r = c.post("/check", json=CHECK, headers={"origin": "https://tools.example.org"})
            assert r.status_code == 200
            r = c.post("/check", json=CHECK, headers={"origin": "https://evil.example.org"})
            assert r.status_code == 403
    finally:
        stop_server(proc)


def test_api_docs_page_is_off_and_loads_nothing_from_a_cdn(client):
    assert client.get("/docs").status_code == 404 and client.get("/redoc").status_code == 404
    assert "cdn" not in client.get("/").text.lower()
    assert client.get("/openapi.json").status_code == 200


@pytest.fixture()
def operator_llm(tmp_path):
    """A server whose llm parser calls a recording sink with the operator's key and model."""
    sink = Sink()
    env = {"OPENAI_API_KEY": "sk-operator-key", "LGMCTS_LLM_MODEL": "operator-model",
           "LGMCTS_SERVICE_LLM_MODELS": "second-model"}
    old = {k: os.environ.get(k) for k in env}
    os.environ.update(env)
    try:
        proc, url = start_server("--workers", "1", "--llm-base-url", sink.url, log=tmp_path / "s.log", hooks=False)
    finally:
        for k, v in old.items():
            if v is None:
                os.environ.pop(k)
            else:
                os.environ[k] = v
    yield url, sink
    stop_server(proc)
    sink.close()


def test_clients_choose_only_allowed_llm_models(operator_llm):
    url, sink = operator_llm
    ask = {"scene": SCENE, "instruction": "put the blocks in a line", "parser": "llm"}
    with httpx.Client(base_url=url, timeout=120) as c:
        for path in ("/parse", "/plan"):
            r = c.post(path, json={**ask, "llm_model": "page-chosen-model"})
            assert r.status_code == 422 and "not allowed" in r.json()["detail"], r.text
        assert sink.requests == []
        for model in (None, "operator-model", "second-model"):
            before = len(sink.requests)
            r = c.post("/parse", json={**ask, **({"llm_model": model} if model else {})})
            assert r.status_code >= 400 and "\n" not in r.json()["detail"]  # the sink answers 500
            sent = [json.loads(q["body"]).get("model") for q in sink.requests[before:]]
            assert sent and set(sent) == {model or "operator-model"}


def test_long_integers_and_repeated_keys_are_one_line_422(client):
    body = json.dumps(CHECK)
    for raw, words in ((body.replace('"solved": true', '"solved": true, "solved": false'), "'solved' twice"),
                       (body.replace('"actions": []', '"actions": [%s]' % ("1" + "0" * 5000)), "too many digits"),
                       ('{"scene": {}, "scene": {}}', "'scene' twice")):
        r = client.post("/check", content=raw, headers={"content-type": "application/json"})
        assert r.status_code == 422 and words in r.json()["detail"], r.text[:300]
        assert "\n" not in r.json()["detail"]


# ---------------------------------------------------------------- tokens


TOKEN = "t\u00f6k\u00e9n-0123456789-abcdef"


def test_token_compared_as_bytes_and_only_once(tmp_path):
    os.environ["LGMCTS_SERVICE_TOKEN"] = TOKEN
    try:
        proc, url = start_server("--workers", "1", log=tmp_path / "s.log", hooks=False)
    finally:
        os.environ.pop("LGMCTS_SERVICE_TOKEN")
    try:
        good = b"Bearer " + TOKEN.encode()
        with httpx.Client(base_url=url, timeout=60) as c:
            assert c.post("/check", json=CHECK, headers={"authorization": good}).status_code == 200
            assert c.post("/check", json=CHECK).status_code == 401
            # Several Authorization headers are refused, the right one among them included.
            many = [("authorization", f"Bearer guess-{k:04d}-0123456789".encode()) for k in range(50)]
            r = c.post("/check", json=CHECK, headers=httpx.Headers([*many, ("authorization", good)]))
            assert r.status_code == 401
            r = c.post("/check", json=CHECK, headers=httpx.Headers([("authorization", good), ("authorization", good)]))
            assert r.status_code == 401
    finally:
        stop_server(proc)


@pytest.mark.parametrize("token", [" " * 20, "\t" * 16 + "  ", " padded-token-0123456789 ", "tok\x1ben-0123456789abc"])
def test_blank_or_padded_tokens_are_refused_at_start_up(token):
    env = {**os.environ, "LGMCTS_SERVICE_TOKEN": token}
    r = subprocess.run([sys.executable, "-m", "lgmcts.service", "--port", "0"], cwd=ROOT, env=env,
                       capture_output=True, text=True, timeout=60)
    assert r.returncode == 2 and len(r.stderr.strip().splitlines()) == 1 and "token" in r.stderr


# ---------------------------------------------------------------- abandoned requests


def _hang_up(url: str, body: bytes, after: float) -> None:
    host, port = url.removeprefix("http://").split(":")
    head = (f"POST /plan HTTP/1.1\r\nHost: {host}\r\nContent-Type: application/json\r\n"
            f"Content-Length: {len(body)}\r\n\r\n").encode()
    with socket.create_connection((host, int(port))) as s:
        s.sendall(head + body)
        time.sleep(after)


def test_abandoned_requests_are_cancelled(tmp_path):
    proc, url = start_server("--workers", "1", "--timeout", "120", log=tmp_path / "s.log", hooks=True)
    try:
        # Each would hold the only worker for 20 s.
        options = {"method": "_sleep", "time_limit": 20}
        sleeper = json.dumps({"scene": SCENE, "goals": GOALS, "options": options}).encode()
        for _ in range(4):
            _hang_up(url, sleeper, 0.3)
        t0 = time.monotonic()
        r = httpx.post(
            url + "/plan", json={"scene": SCENE, "goals": GOALS, "options": {"method": "greedy"}}, timeout=120
        )
        took = time.monotonic() - t0
        assert r.status_code == 200 and r.json()["solved"]
        assert took < 10, f"a real request waited {took:.1f} s behind abandoned ones"
        # The worker was not replaced: the jobs were stopped in it.
        assert httpx.get(url + "/healthz").json()["restarts"] == 0
    finally:
        stop_server(proc)


# ---------------------------------------------------------------- big drawings


def _boxes_and_moves(n: int, m: int) -> tuple[dict, dict]:
    side = int((2 * n) ** 0.5) + 2
    spots = [(-4.5 + 0.1 * i, -4.5 + 0.1 * j) for i in range(side) for j in range(side)]
    objects = [
        {"id": k + 1, "name": "box", "shape": {"type": "box", "size": [0.05, 0.05, 0.05]}, "pose": [*spots[k], 0.0]}
        for k in range(n)
    ]
    free, where, actions = list(range(n, len(spots))), list(range(n)), []
    for k in range(m):
        o = (k * 7919) % n
        s = free.pop(0)
        free.append(where[o])
        where[o] = s
        actions.append({"object": o + 1, "to": [*spots[s], 0.0], "purpose": "relocate"})
    return ({"workspace": {"x": [-5, 5], "y": [-5, 5]}, "objects": objects}, {"solved": False, "actions": actions})


def test_healthz_stays_fast_while_a_large_view_is_drawn(tmp_path):
    proc, url = start_server("--workers", "1", log=tmp_path / "s.log", hooks=False)
    try:
        scene, plan = _boxes_and_moves(1500, 1500)
        body = json.dumps({"scene": scene, "plan": plan}).encode()
        out: dict = {}

        def view() -> None:
            r = httpx.post(url + "/view", content=body, headers={"content-type": "application/json"}, timeout=120)
            out["status"], out["size"] = r.status_code, len(r.content)

        t = threading.Thread(target=view)
        t.start()
        waits: list[float] = []
        with httpx.Client(base_url=url, timeout=10) as c:
            c.get("/healthz")
            while t.is_alive() and len(waits) < 300:
                t0 = time.perf_counter()
                assert c.get("/healthz").status_code == 200
                waits.append(time.perf_counter() - t0)
                time.sleep(0.02)
        t.join()
        assert out["status"] == 200
        # Frames are deltas: the answer grows with objects + actions, not their product.
        assert out["size"] < 200 * (1500 + 1500) + len(body)
        assert len(waits) >= 5
        slow = [w for w in waits if w > 0.1]
        assert len(slow) <= max(1, len(waits) // 50), f"/healthz took over 100 ms {len(slow)} of {len(waits)} times"
    finally:
        stop_server(proc)


def test_a_view_beyond_the_drawing_budget_is_one_line():
    """The worker's answer to a /view body past MAX_VIEW_CELLS: one line (422), computed from nothing big."""
    from lgmcts.errors import InputError
    from lgmcts.service import jobs
    from lgmcts.service.bodies import Body, Policy

    n = 2000
    scene, plan = _boxes_and_moves(n, limits.MAX_VIEW_CELLS // n + 1)
    body = Body("view", json.dumps({"scene": scene, "plan": plan}).encode(), Policy())
    with pytest.raises(InputError) as exc:
        jobs.run_body(jobs.BodyJob(body, time.time() + 60))
    assert "too large to draw" in str(exc.value) and "\n" not in str(exc.value)
