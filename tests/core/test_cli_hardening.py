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


# ---------------------------------------------------------------- issue 23, second round

import resource  # noqa: E402
import signal  # noqa: E402
import stat  # noqa: E402
from pathlib import Path  # noqa: E402

from lgmcts.errors import InputError  # noqa: E402
from lgmcts.formats import parse_goals, parse_plan, parse_scene  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]
BIG_INT = "1" + "0" * 5000


def _file_size_limit(nbytes: int):
    """A child whose files cannot grow past ``nbytes`` (writes fail as on a full disk)."""
    def pre() -> None:
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
        resource.setrlimit(resource.RLIMIT_FSIZE, (nbytes, nbytes))
    return pre


def run_limited(*args: str, nbytes: int, timeout: float = 300, env: dict | None = None) -> subprocess.CompletedProcess:
    return subprocess.run([sys.executable, "-m", "lgmcts", *args], capture_output=True, text=True, timeout=timeout,
                          env={**os.environ, **(env or {})}, preexec_fn=_file_size_limit(nbytes), cwd=ROOT)


def _scene() -> dict:
    return json.loads((ROOT / SCENE).read_text())


def _suite_line(**change) -> str:
    scene = _scene()
    task = {"id": "t-1", "seed": 1, "suite": "elgr", "category": "line", "scene": scene,
            "instruction": "put the blocks in a line", "goals": json.loads((ROOT / GOALS).read_text())}
    task.update(change)
    return json.dumps(task)


@pytest.mark.slow
@pytest.mark.parametrize("where", ["scene", "goals", "plan", "suite", "cases"])
def test_a_5000_digit_integer_is_one_line_exit_2(where, tmp_path):
    scene_text = (ROOT / SCENE).read_text()
    f = tmp_path / "in.json"
    if where == "scene":
        f.write_text(scene_text.replace('"id": 1,', f'"id": {BIG_INT},', 1))
        out = run("check", str(f), GOALS, GOALS)
    elif where == "goals":
        f.write_text(f'{{"goals": [{{"pattern": "line", "objects": [1, {BIG_INT}]}}]}}')
        out = run("check", SCENE, str(f), GOALS)
    elif where == "plan":
        f.write_text(f'{{"solved": true, "actions": [{{"object": {BIG_INT}, "to": [0, 0, 0]}}]}}')
        out = run("check", SCENE, GOALS, str(f))
    elif where == "suite":
        f = tmp_path / "suite.jsonl"
        f.write_text(_suite_line().replace('"seed": 1', f'"seed": {BIG_INT}') + "\n")
        out = run("bench", "--suite", str(f), "--no-exec", "-o", str(tmp_path / "out"))
    else:
        f = tmp_path / "cases.jsonl"
        f.write_text(json.dumps({"scene": _scene(), "instruction": "put the blocks in a line",
                                 "expect": {"goals": []}}).replace('"goals": []', f'"goals": [{BIG_INT}]') + "\n")
        out = run("eval-parse", str(f))
    assert out.returncode == 2, out.stderr[-500:]
    assert one_line(out.stderr) and "digits" in out.stderr, out.stderr[-500:]


@pytest.mark.slow
def test_duplicate_keys_are_refused(tmp_path):
    f = tmp_path / "plan.json"
    f.write_text('{"solved": false, "solved": true, "actions": []}')
    out = run("check", SCENE, GOALS, str(f))
    assert out.returncode == 2 and one_line(out.stderr) and "'solved' twice" in out.stderr


@pytest.mark.slow
@pytest.mark.parametrize("change, words", [
    ({"seed": "abc"}, "'seed'"), ({"final": [1, 2, 3]}, "'final'"), ({"final": {"1": "x"}}, "final.1"),
    ({"final_on": {"1": "2"}}, "final_on.1"), ({"instruction": 5}, "'instruction'"), ({"seed": True}, "'seed'"),
])
def test_suite_files_with_wrong_field_types_are_one_line(change, words, tmp_path):
    f = tmp_path / "suite.jsonl"
    f.write_text(_suite_line(**change) + "\n")
    out = run("bench", "--suite", str(f), "--no-exec", "-o", str(tmp_path / "out"))
    assert out.returncode == 2 and one_line(out.stderr) and words in out.stderr, out.stderr[-500:]


@pytest.mark.slow
@pytest.mark.parametrize("change, words", [
    ({"needs": 5}, "'needs'"), ({"expect": "abc"}, "'expect'"), ({"expect": {"any_of": 3}}, "any_of"),
    ({"refuse": 3}, "'refuse'"), ({"instruction": ["x"]}, "'instruction'"),
    ({"expect": {"goals": [{"pattern": "line", "objects": [1, 2]}] * 12}}, "at most"),
])
def test_case_files_with_wrong_field_types_are_one_line(change, words, tmp_path):
    row = {"id": "c1", "scene": _scene(), "instruction": "put the blocks in a line",
           "expect": {"goals": [{"pattern": "line", "objects": [1, 2, 3, 4]}]}}
    row.update(change)
    f = tmp_path / "cases.jsonl"
    f.write_text(json.dumps(row) + "\n")
    out = run("eval-parse", str(f))
    assert out.returncode == 2 and one_line(out.stderr) and words in out.stderr, out.stderr[-500:]


@pytest.mark.slow
def test_stdout_on_a_full_device_or_closed_is_one_line(tmp_path):
    with open("/dev/full", "w") as full:
        out = subprocess.run([sys.executable, "-m", "lgmcts", "plan", SCENE, "-g", GOALS], stdout=full,
                             stderr=subprocess.PIPE, text=True, timeout=120, cwd=ROOT)
    assert out.returncode == 2 and one_line(out.stderr) and "No space left" in out.stderr, out.stderr
    plan = tmp_path / "plan.json"
    assert run("plan", SCENE, "-g", GOALS, "-o", str(plan)).returncode == 0
    for args in (("check", SCENE, GOALS, str(plan)), ("check", SCENE, GOALS, str(plan), "--json"),
                 ("plan", SCENE, "-g", GOALS)):
        out = subprocess.run([sys.executable, "-m", "lgmcts", *args], stdout=subprocess.DEVNULL, stderr=subprocess.PIPE,
                             text=True, timeout=120, cwd=ROOT, preexec_fn=lambda: os.close(1))
        assert out.returncode == 2 and one_line(out.stderr) and "closed" in out.stderr, (args, out.stderr)


@pytest.mark.slow
def test_pictures_on_a_full_disk_leave_the_written_plan_and_its_status(tmp_path):
    plan, pics = tmp_path / "plan.json", tmp_path / "pics"
    out = run_limited("plan", SCENE, "-g", GOALS, "-o", str(plan), "--viz", str(pics), nbytes=20_000)
    assert out.returncode == 0, out.stderr[-800:]
    assert "Traceback" not in out.stderr and "the plan was written but not its pictures" in out.stderr
    assert json.loads(plan.read_text())["solved"] is True
    assert not [p for p in pics.iterdir() if p.stat().st_size == 0 or p.name.startswith(".")]
    out = run_limited("viz", str(plan), "-s", SCENE, "-o", str(tmp_path / "more"), nbytes=20_000)
    assert out.returncode == 2 and one_line(out.stderr) and "cannot write picture" in out.stderr, out.stderr[-800:]


@pytest.mark.slow
def test_a_video_on_a_full_disk_is_not_reported_written(tmp_path):
    plan, video = tmp_path / "plan.json", tmp_path / "run.mp4"
    assert run("plan", SCENE, "-g", GOALS, "-o", str(plan)).returncode == 0
    env = {
        "MUJOCO_GL": os.environ.get("MUJOCO_GL", "osmesa"),
        "PYOPENGL_PLATFORM": os.environ.get("PYOPENGL_PLATFORM", "osmesa"),
    }
    out = run_limited("execute", SCENE, str(plan), "--video", str(video), nbytes=30_000, env=env)
    if "OpenGL" in out.stderr or "EGL" in out.stderr:
        pytest.skip("no OpenGL for the video")
    assert out.returncode == 2, out.stderr[-800:]
    assert one_line(out.stderr) and "cannot write video" in out.stderr, out.stderr[-800:]
    assert "success" not in out.stdout and "wrote" not in out.stderr
    assert not video.exists() and not list(tmp_path.glob(".run.mp4*"))


@pytest.mark.slow
def test_bench_generate_with_a_bad_option_keeps_the_file(tmp_path):
    f = tmp_path / "suite.jsonl"
    f.write_text("keep me\n")
    for bad in (("--n", "0"), ("--category", "nope"), ("--seed", "-1"), ("--instructions", "nope")):
        out = run("bench-generate", "--suite", "elgr", *bad, "-o", str(f))
        assert out.returncode == 2 and one_line(out.stderr), (bad, out.stderr)
        assert f.read_text() == "keep me\n"
    assert [p.name for p in tmp_path.iterdir()] == ["suite.jsonl"]


@pytest.mark.slow
def test_outputs_follow_the_umask_and_keep_an_existing_mode(tmp_path):
    kept = tmp_path / "kept.json"
    kept.write_text("{}")
    kept.chmod(0o644)
    fresh, private = tmp_path / "fresh.json", tmp_path / "private.json"
    for path, mask in ((kept, 0o077), (fresh, 0o022), (private, 0o077)):
        out = subprocess.run(
            [sys.executable, "-m", "lgmcts", "plan", SCENE, "-g", GOALS, "-o", str(path)],
            capture_output=True,
            text=True,
            timeout=120,
            cwd=ROOT,
            preexec_fn=lambda m=mask: os.umask(m),
        )
        assert out.returncode == 0, out.stderr
    assert stat.S_IMODE(kept.stat().st_mode) == 0o644
    assert stat.S_IMODE(fresh.stat().st_mode) == 0o644
    assert stat.S_IMODE(private.stat().st_mode) == 0o600


@pytest.mark.slow
def test_llm_timeout_variable_is_checked(tmp_path):
    out = run(
        "parse",
        SCENE,
        "put the blocks in a line",
        "--parser",
        "llm",
        "--llm-model",
        "m",
        "--llm-base-url",
        "http://127.0.0.1:9/v1",
        env={"LGMCTS_LLM_TIMEOUT": "abc"},
    )
    assert out.returncode == 2 and one_line(out.stderr) and "LGMCTS_LLM_TIMEOUT" in out.stderr


@pytest.mark.slow
def test_a_pattern_module_calling_sys_exit_cannot_make_a_tampered_plan_pass(tmp_path):
    module = tmp_path / "quits.py"
    module.write_text("import sys\nsys.exit(0)\n")
    plan = tmp_path / "tampered.json"
    plan.write_text('{"solved": true, "actions": [{"object": 1, "to": [5.0, 5.0, 0.0]}]}')
    for out in (
        run("--pattern-module", str(module), "check", SCENE, GOALS, str(plan)),
        run("check", SCENE, GOALS, str(plan), env={"LGMCTS_PATTERN_MODULES": str(module)}),
    ):
        assert out.returncode == 2 and one_line(out.stderr) and "sys.exit(0)" in out.stderr, out.stderr


@pytest.mark.slow
def test_control_characters_in_names_never_reach_stderr_raw(tmp_path):
    scene = _scene()
    scene["objects"][1]["name"] = "\x1b]0;pwned\x07block\x1b[2J\x9b1m"
    scene["objects"][1]["pose"] = [5.0, 5.0, 0.0]
    f = tmp_path / "scene.json"
    f.write_text(json.dumps(scene))
    out = run("plan", str(f), "-g", GOALS)
    assert out.returncode == 2 and one_line(out.stderr)
    assert not any(ord(c) < 32 or 0x7F <= ord(c) < 0xA0 for c in out.stderr.rstrip("\n")), repr(out.stderr)
    assert "\\x1b]0;pwned\\x07block" in out.stderr


@pytest.mark.slow
def test_bench_workers_are_capped(tmp_path):
    f = tmp_path / "suite.jsonl"
    f.write_text(_suite_line() + "\n")
    out = run("bench", "--suite", str(f), "--no-exec", "--workers", "100000", "-o", str(tmp_path / "out"))
    assert out.returncode == 2 and one_line(out.stderr) and "CPUs" in out.stderr
    assert not (tmp_path / "out").exists()


@pytest.mark.slow
def test_embed_dir_pointing_nowhere_is_one_line_and_creates_nothing(tmp_path):
    where = tmp_path / "nowhere" / "deep"
    out = run("parse", SCENE, "put the blocks in a line", env={"LGMCTS_EMBED_DIR": str(where)})
    assert out.returncode == 2 and one_line(out.stderr) and "LGMCTS_EMBED_DIR" in out.stderr
    assert not (tmp_path / "nowhere").exists()


def _obj(**change) -> dict:
    o = {"id": 1, "name": "block", "shape": {"type": "box", "size": [0.05, 0.05, 0.05]}, "pose": [0.0, 0.0, 0.0]}
    o.update(change)
    return o


@pytest.mark.parametrize(
    "scene",
    [
        {"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}, "objects": [_obj(pose=["-0.25", 0.0, 0.0])]},
        {
            "workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]},
            "objects": [_obj(shape={"type": "box", "size": [True, 0.05, 0.05]})],
        },
        {
            "workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]},
            "objects": [_obj(shape={"type": "box", "size": ["0.05", 0.05, 0.05]})],
        },
        {
            "workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]},
            "objects": [_obj(shape={"type": "cylinder", "radius": "0.1", "height": 0.1})],
        },
        {"workspace": {"x": ["-0.4", 0.4], "y": [-0.3, 0.3]}, "objects": [_obj()]},
        {"workspace": {"x": [-0.4, 0.4], "y": [-0.3, True]}, "objects": [_obj()]},
    ],
)
def test_numbers_given_as_strings_or_booleans_are_refused_in_scenes(scene):
    with pytest.raises(InputError, match="expected a number"):
        parse_scene(scene)


@pytest.mark.parametrize(
    "plan",
    [
        {"solved": "yes", "actions": []},
        {"solved": 1, "actions": []},
        {"solved": True, "actions": [{"object": 1, "to": ["0.1", 0.0, 0.0]}]},
        {"solved": True, "actions": [{"object": 1, "to": [0.1, False, 0.0]}]},
    ],
)
def test_plans_take_json_booleans_and_numbers_only(plan):
    with pytest.raises(InputError, match="expected"):
        parse_plan(plan)


@pytest.mark.parametrize(
    "goal, words",
    [
        ({"pattern": "pose", "objects": [1], "pose": ["0.1", 0, 0]}, "expected a number"),
        ({"pattern": "line", "objects": [1, 2], "facing": 1e300}, "facing"),
        ({"pattern": "line", "objects": [1, 2], "region": [-1e300, 1e300, -1, 1]}, "region box"),
        ({"pattern": "line", "objects": [1, 2], "size": True}, "not true/false"),
        ({"pattern": "line", "objects": [1, 2], "size": 1e300}, "size"),
    ],
)
def test_goal_numbers_are_json_numbers_within_bounds(goal, words):
    with pytest.raises(InputError, match=words):
        parse_goals({"goals": [goal]})


def test_in_bounds_goal_parameters_still_load():
    parse_goals(
        {
            "goals": [
                {"pattern": "line", "objects": [1, 2], "facing": 1.5, "region": [-0.2, 0.2, -0.1, 0.1], "size": 0.3}
            ]
        }
    )
