"""The LLM parser against a real Chat Completions server on loopback."""

from __future__ import annotations

import json
import socket
import threading
import time
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import pytest

from lgmcts.errors import InputError
from lgmcts.formats import to_dict
from lgmcts.language import parse
from lgmcts.language.matcher import pattern_infos

CIRCLE = json.dumps({"goals": [{"pattern": "circle", "objects": [1, 2, 3, 4]}, {"pattern": "behind", "objects": [5], "anchor": 1}]})


class _Server:
    """Answers ``POST /v1/chat/completions`` from a script; records the requests."""

    def __init__(self, answers: list) -> None:
        self.answers = list(answers)
        self.requests: list[dict] = []
        outer = self

        class Handler(BaseHTTPRequestHandler):
            def log_message(self, *args):  # keep test output clean
                pass

            def do_POST(self):
                body = json.loads(self.rfile.read(int(self.headers["Content-Length"])))
                outer.requests.append({"path": self.path, "body": body, "auth": self.headers.get("Authorization")})
                ans = outer.answers.pop(0)
                if isinstance(ans, int):  # an HTTP error status
                    payload, status = {"error": {"message": "unsupported", "type": "invalid_request_error"}}, ans
                else:
                    status = 200
                    payload = {
                        "id": "cmpl-1", "object": "chat.completion", "created": 0, "model": body["model"],
                        "choices": [{"index": 0, "message": {"role": "assistant", "content": ans}, "finish_reason": "stop"}],
                        "usage": {"prompt_tokens": 1, "completion_tokens": 1, "total_tokens": 2},
                    }
                data = json.dumps(payload).encode()
                self.send_response(status)
                self.send_header("Content-Type", "application/json")
                self.send_header("Content-Length", str(len(data)))
                self.end_headers()
                self.wfile.write(data)

        self.httpd = ThreadingHTTPServer(("127.0.0.1", 0), Handler)
        self.thread = threading.Thread(target=self.httpd.serve_forever, daemon=True)

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.httpd.server_address[1]}/v1"

    def __enter__(self):
        self.thread.start()
        return self

    def __exit__(self, *exc):
        self.httpd.shutdown()
        self.httpd.server_close()


def _llm(scene, url, text="put all blocks in a circle and the bottle behind one block", **kw):
    return parse(scene, text, parser="llm", llm_model="test-model", llm_base_url=url, api_key="k", timeout=10, **kw)


def test_valid_answer_and_the_prompt(tabletop):
    with _Server([CIRCLE]) as srv:
        goals = _llm(tabletop, srv.url)
    assert to_dict(goals) == json.loads(CIRCLE)
    (req,) = srv.requests
    assert req["path"] == "/v1/chat/completions" and req["auth"] == "Bearer k"
    body = req["body"]
    assert body["model"] == "test-model" and body["response_format"]["type"] == "json_schema"
    system, user = body["messages"][0]["content"], body["messages"][-1]["content"]
    for name, info in pattern_infos().items():  # the same database as the offline parser
        assert f"- {name}: {info.description}" in system
    assert "- id 8: red and green polka dot letter A" in user and user.endswith("behind one block")
    # Constrained to the scene's ids and the database's patterns; worked examples first.
    schema = body["response_format"]["json_schema"]["schema"]
    item = schema["properties"]["goals"]["items"]["properties"]
    assert item["objects"]["items"]["enum"] == list(range(1, 10))
    assert item["pattern"]["enum"] == sorted(pattern_infos())
    assert body["max_tokens"] > 0 and [m["role"] for m in body["messages"][1:3]] == ["user", "assistant"]


def test_malformed_json_is_retried_once(tabletop):
    with _Server(["Sure! here it is: {goals: [", "```json\n" + CIRCLE + "\n```"]) as srv:
        goals = _llm(tabletop, srv.url)
    assert to_dict(goals)["goals"][0]["pattern"] == "circle"
    retry = srv.requests[1]["body"]["messages"]
    assert retry[-1]["role"] == "user" and "not valid JSON" in retry[-1]["content"]


def test_unknown_ids_then_valid(tabletop):
    bad = json.dumps({"goals": [{"pattern": "line", "objects": [1, 42]}]})
    with _Server([bad, CIRCLE]) as srv:
        _llm(tabletop, srv.url)
    assert "unknown object id 42" in srv.requests[1]["body"]["messages"][-1]["content"]


@pytest.mark.parametrize(
    "answers, needle",
    [
        ([json.dumps({"goals": [{"pattern": "spiral", "objects": [1, 2, 3]}]})] * 2, "unknown pattern"),
        ([json.dumps({"goals": [{"pattern": "left", "objects": [1]}]})] * 2, "anchor"),
        ([json.dumps({"goals": [{"pattern": "circle", "objects": [1, 2]}]})] * 2, "at least 3"),
        ([json.dumps({"goals": [], "error": "there is no giraffe"})], "no giraffe"),
    ],
)
def test_invalid_twice_or_reported_failure_is_one_clear_error(tabletop, answers, needle):
    with _Server(answers) as srv:
        with pytest.raises(InputError) as err:
            _llm(tabletop, srv.url)
    assert needle in str(err.value) and "\n" not in str(err.value)
    assert len(srv.requests) == len(answers)


def test_server_without_structured_output_is_asked_plainly(tabletop):
    with _Server([400, 422, CIRCLE, CIRCLE]) as srv:
        _llm(tabletop, srv.url)
        _llm(tabletop, srv.url)  # the endpoint's answer is remembered
    kinds = [(r["body"].get("response_format") or {}).get("type") for r in srv.requests]
    assert kinds == ["json_schema", "json_object", None, None]
    # The llama-cpp-python form carries the same schema.
    assert srv.requests[1]["body"]["response_format"]["schema"]["required"] == ["goals", "error"]


def test_server_with_the_json_object_form_keeps_it(tabletop):
    with _Server([422, CIRCLE, CIRCLE]) as srv:
        _llm(tabletop, srv.url)
        _llm(tabletop, srv.url)
    kinds = [(r["body"].get("response_format") or {}).get("type") for r in srv.requests]
    assert kinds == ["json_schema", "json_object", "json_object"]


def test_unreachable_endpoint_and_missing_model(tabletop, monkeypatch):
    with _Server([]) as srv:
        url = srv.url
    with pytest.raises(InputError, match="cannot reach"):
        _llm(tabletop, url)
    monkeypatch.delenv("LGMCTS_LLM_MODEL", raising=False)
    with pytest.raises(InputError, match="--llm-model"):
        parse(tabletop, "line up the blocks", parser="llm", llm_base_url=url)


class _SilentServer:
    """Accepts connections and reads requests but never answers: a server slower
    than any timeout, whatever the load of the machine. It listens before the
    test starts (the kernel completes connections to a listening socket), so a
    client can always reach it and can only time out."""

    def __init__(self) -> None:
        self.sock = socket.create_server(("127.0.0.1", 0))
        self.held: list[socket.socket] = []
        self.thread = threading.Thread(target=self._accept, daemon=True)

    def _accept(self) -> None:
        while True:
            try:
                conn, _ = self.sock.accept()
            except OSError:  # closed by __exit__
                return
            self.held.append(conn)

    @property
    def url(self) -> str:
        return f"http://127.0.0.1:{self.sock.getsockname()[1]}/v1"

    def __enter__(self):
        self.thread.start()
        return self

    def __exit__(self, *exc):
        self.sock.close()
        for conn in self.held:
            conn.close()


def test_a_server_slower_than_the_timeout_is_one_clear_error(tabletop):
    from lgmcts.language.llm import LLMOptions, parse_llm

    with _SilentServer() as srv:
        with pytest.raises(InputError) as err:
            parse_llm(tabletop, "line up the blocks",
                      options=LLMOptions(model="m", base_url=srv.url, api_key="k", timeout=0.2, transport_retries=0))
    assert str(err.value) == "the language model did not answer within 0.2 s"


def test_a_timed_out_request_is_sent_again_when_retries_allow(tabletop):
    from lgmcts.language.llm import LLMOptions, parse_llm

    with _SilentServer() as srv:
        with pytest.raises(InputError, match="did not answer within 0.2 s"):
            parse_llm(tabletop, "line up the blocks",
                      options=LLMOptions(model="m", base_url=srv.url, api_key="k", timeout=0.2, transport_retries=1))
        # One try and one retry, each on a connection of its own. The accepting
        # thread may lag behind the kernel on a busy machine: wait for it.
        give_up = time.monotonic() + 30
        while len(srv.held) < 2 and time.monotonic() < give_up:
            time.sleep(0.05)
        assert len(srv.held) == 2


def test_transient_server_errors_are_retried(tabletop):
    with _Server([503, 500, CIRCLE]) as srv:
        goals = _llm(tabletop, srv.url)
    assert to_dict(goals) == json.loads(CIRCLE) and len(srv.requests) == 3


def test_json_inside_prose_is_read(tabletop):
    with _Server(["Here are the goals: " + CIRCLE + " Hope this helps."]) as srv:
        goals = _llm(tabletop, srv.url)
    assert to_dict(goals) == json.loads(CIRCLE)


@pytest.mark.parametrize(
    "answer, needle",
    [
        ({"goals": [{"pattern": "left", "objects": [1, 2], "anchor": 2}]}, "cannot also be"),
        ({"goals": [{"pattern": "line", "objects": [1, 1, 2]}]}, "listed twice"),
        ({"goals": [{"pattern": "pose", "objects": [1], "pose": [0.1, "x", 0]}]}, "three finite numbers"),
        ({"goals": [{"pattern": "left", "objects": [1], "anchor": True}]}, "anchor"),
        ([1, 2], "JSON object"),
        ("", "empty"),
    ],
)
def test_answers_that_break_the_schema_or_the_scene(tabletop, answer, needle):
    text = answer if isinstance(answer, str) else json.dumps(answer)
    with _Server([text, text]) as srv:
        with pytest.raises(InputError) as err:
            _llm(tabletop, srv.url)
    assert needle in str(err.value) and "\n" not in str(err.value)
    assert "no valid goals after 2 tries" in str(err.value)


# ------------------------------------------------------------------ LFSP


def test_lfsp_actions_are_checked_and_sent_back_once(tabletop):
    from lgmcts.language.lfsp import plan_lfsp
    from lgmcts.language.llm import LLMOptions

    outside = json.dumps({"actions": [{"object": 5, "to": [0.9, 0.0, 0.0], "on": None}], "error": None})
    good = json.dumps({"actions": [{"object": 5, "to": [0.12, 0.05, 0.0], "on": None}], "error": None})
    with _Server([outside, good]) as srv:
        plan = plan_lfsp(tabletop, "put the white bottle behind the green bowl",
                         options=LLMOptions(model="m", base_url=srv.url, api_key="k", timeout=10))
    assert plan.solved and [(a.object, a.to, a.on) for a in plan.actions] == [(5, (0.12, 0.05, 0.0), None)]
    first, second = (r["body"] for r in srv.requests)
    assert "outside the workspace" in second["messages"][-1]["content"]
    # The prompt gives poses and sizes; the schema limits ids to the scene's.
    assert "- 5: white bottle, round, radius 0.035 m" in first["messages"][-1]["content"]
    schema = first["response_format"]["json_schema"]["schema"]
    assert schema["properties"]["actions"]["items"]["properties"]["object"]["enum"] == list(range(1, 10))


@pytest.mark.parametrize(
    "answer, needle",
    [
        ({"actions": [{"object": 5, "to": [0.1, 0.1, 0.0], "on": 5}], "error": None}, "'on'"),
        ({"actions": [{"object": 42, "to": [0.1, 0.1, 0.0], "on": None}], "error": None}, "unknown object id 42"),
        ({"actions": [{"object": 5, "to": [0.1, None, 0.0], "on": None}], "error": None}, "three finite numbers"),
        ({"actions": [], "error": "no giraffe here"}, "no giraffe here"),
    ],
)
def test_lfsp_unusable_answers_are_one_line_errors(tabletop, answer, needle):
    from lgmcts.language.lfsp import plan_lfsp
    from lgmcts.language.llm import LLMOptions

    with _Server([json.dumps(answer)] * 2) as srv:
        with pytest.raises(InputError) as err:
            plan_lfsp(tabletop, "put the bottle somewhere", options=LLMOptions(model="m", base_url=srv.url, timeout=10))
    assert needle in str(err.value) and "\n" not in str(err.value)


def test_lfsp_is_a_bench_method_judged_like_the_others(tabletop, monkeypatch):
    from lgmcts.bench import RunOptions, generate, run_task

    task = generate("elgr", n=1, seed=0)[0]
    # Moving nothing useful: a plan the validator must reject.
    answer = json.dumps({"actions": [{"object": task.scene["objects"][0]["id"], "to": [0.0, 0.0, 0.0], "on": None}],
                         "error": None})
    with _Server([answer]) as srv:
        rec = run_task(task, RunOptions(method="lfsp", llm_model="m", llm_base_url=srv.url, execute=False))
    assert rec["parser"] is None and rec["parse"]["goals"] is None
    assert rec["planning"]["solved"] and not rec["sr_p"] and rec["cause"] == "plan invalid"
    assert "Command: " + task.instruction in srv.requests[0]["body"]["messages"][-1]["content"]
    with _Server(["not json", "still not json"]) as srv:
        rec = run_task(task, RunOptions(method="lfsp", llm_model="m", llm_base_url=srv.url, execute=False))
    assert rec["cause"] == "plan not found" and "no valid actions" in rec["detail"]
    monkeypatch.delenv("LGMCTS_LLM_MODEL", raising=False)
    with pytest.raises(InputError, match="--llm-model"):
        RunOptions(method="lfsp").check()
