"""The command line under hostile input: one line on stderr, exit 2, nothing overwritten."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

pytestmark = pytest.mark.slow

SCENE = "examples/tabletop.json"
GOALS = "examples/goals.json"


def run(*args: str, env: dict | None = None, timeout: float = 120) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "lgmcts", *args], capture_output=True, text=True, timeout=timeout,
                          env={**os.environ, **(env or {})})


def one_line(err: str) -> bool:
    return len(err.strip().splitlines()) == 1 and "Traceback" not in err


@pytest.mark.parametrize("args", [
    ("plan", SCENE, "--seed", "abc"),
    ("frobnicate",),
    ("plan",),
    ("check", SCENE, GOALS),
    ("plan", SCENE, "-g", GOALS, "--no-such-option"),
])
def test_usage_errors_are_one_line_exit_2(args):
    out = run(*args)
    assert out.returncode == 2, out.stderr
    assert one_line(out.stderr), out.stderr


@pytest.mark.parametrize("value", ["nan", "inf", "-1"])
def test_time_limit_must_be_finite_and_positive(value):
    out = run("plan", SCENE, "-g", GOALS, "--time-limit", value)
    assert out.returncode == 2 and one_line(out.stderr) and "time_limit" in out.stderr


def test_bad_viz_location_is_found_before_writing(tmp_path):
    f = tmp_path / "f.json"
    f.write_text('{"old": 1}\n')
    not_a_dir = tmp_path / "pictures"
    not_a_dir.write_text("")
    out = run("plan", SCENE, "-g", GOALS, "-o", str(f), "--viz", str(not_a_dir))
    assert out.returncode == 2 and one_line(out.stderr)
    assert f.read_text() == '{"old": 1}\n'
    out = run("plan", SCENE, "-g", GOALS, "-o", str(tmp_path))
    assert out.returncode == 2 and "folder" in out.stderr


def test_output_is_written_atomically(tmp_path):
    f = tmp_path / "plan.json"
    out = run("plan", SCENE, "-g", GOALS, "-o", str(f))
    assert out.returncode == 0, out.stderr
    assert json.loads(f.read_text())["solved"] is True
    assert [p.name for p in tmp_path.iterdir()] == ["plan.json"]  # no temporary left behind


@pytest.mark.parametrize("which", ["scene", "goals", "plan"])
def test_deep_json_is_one_line_exit_2(which, tmp_path):
    deep = tmp_path / "deep.json"
    deep.write_text("[" * 100_000)
    files = {"scene": SCENE, "goals": GOALS, "plan": SCENE}
    files[which] = str(deep)
    out = run("check", files["scene"], files["goals"], files["plan"])
    assert out.returncode == 2 and one_line(out.stderr) and "nested too deeply" in out.stderr


def test_special_files_are_refused(tmp_path):
    out = run("plan", "/dev/zero", "-g", GOALS, timeout=60)
    assert out.returncode == 2 and one_line(out.stderr) and "not a regular file" in out.stderr
    fifo = tmp_path / "fifo.json"
    os.mkfifo(fifo)
    out = run("plan", str(fifo), "-g", GOALS, timeout=60)
    assert out.returncode == 2 and one_line(out.stderr)


def test_byte_cap_env(tmp_path):
    out = run("plan", SCENE, "-g", GOALS, env={"LGMCTS_MAX_INPUT_BYTES": "100"})
    assert out.returncode == 2 and "larger than 100 bytes" in out.stderr


def test_far_target_is_never_valid(tmp_path):
    plan = tmp_path / "plan.json"
    assert run("plan", SCENE, "-g", GOALS, "-o", str(plan)).returncode == 0
    data = json.loads(plan.read_text())
    for x in (1e20, 1e300, 100.0):
        data2 = {
            **data,
            "actions": [*data["actions"], {"object": 9, "to": [x, x, 0], "on": None, "purpose": "relocate"}],
        }
        bad = tmp_path / "bad.json"
        bad.write_text(json.dumps(data2))
        out = run("check", SCENE, GOALS, str(bad))
        assert out.returncode in (1, 2), (x, out.stdout)
        assert "Traceback" not in out.stderr


def test_ids_must_be_integers(tmp_path):
    sc = json.loads(open(SCENE).read())
    sc["objects"][0]["id"] = True
    f = tmp_path / "s.json"
    f.write_text(json.dumps(sc))
    out = run("plan", str(f), "-g", GOALS)
    assert out.returncode == 2 and "JSON integers" in out.stderr


@pytest.mark.parametrize("cmd", [("eval-parse",), ("bench", "--no-exec", "--suite")])
def test_deep_jsonl_lines_are_one_line_exit_2(cmd, tmp_path):
    f = tmp_path / "deep.jsonl"
    f.write_text("[" * 100_000 + "\n")
    args = [*cmd, str(f)]
    if cmd[0] == "bench":
        args += ["-o", str(tmp_path / "out")]
    out = run(*args)
    assert out.returncode == 2 and one_line(out.stderr) and "nested too deeply" in out.stderr, out.stderr


def test_execute_refuses_huge_targets(tmp_path):
    plan = {"solved": True, "actions": [{"object": 9, "to": [1e300, 0, 0], "on": None, "purpose": "relocate"}]}
    f = tmp_path / "plan.json"
    f.write_text(json.dumps(plan))
    out = run("execute", SCENE, str(f))
    assert out.returncode == 2 and one_line(out.stderr), out.stderr


def test_serve_warns_on_a_public_bind_without_token():
    import socket

    from lgmcts.service.cli import _loopback

    assert _loopback("127.0.0.1") and _loopback("::1") and _loopback("localhost")
    assert not _loopback("0.0.0.0") and not _loopback("192.168.1.2")
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        port = s.getsockname()[1]
    env = {k: v for k, v in os.environ.items() if k != "LGMCTS_SERVICE_TOKEN"}
    proc = subprocess.Popen(
        [
            sys.executable,
            "-m",
            "lgmcts.service",
            "--host",
            "0.0.0.0",
            "--port",
            str(port),
            "--workers",
            "1",
            "--log-level",
            "warning",
        ],
        stderr=subprocess.PIPE,
        stdout=subprocess.DEVNULL,
        text=True,
        env=env,
    )
    try:
        first = proc.stderr.readline()
    finally:
        proc.terminate()
        try:
            proc.wait(timeout=20)
        except subprocess.TimeoutExpired:
            proc.kill()
    assert first.startswith("WARNING") and "--token" in first


@pytest.mark.parametrize("value", ["nan", "inf"])
def test_bench_time_limit_must_be_finite(value, tmp_path):
    out = run("bench", "--suite", "elgr", "--n", "1", "--no-exec", "--time-limit", value, "-o", str(tmp_path / "o"))
    assert out.returncode == 2 and one_line(out.stderr) and "time-limit" in out.stderr
