"""Optional extras: a missing one is named in one line (exit 2 at the CLI),
and a base install (no extras) plans, validates and draws the HTML viewer."""

from __future__ import annotations

import hashlib
import os
import subprocess
import sys
from pathlib import Path

import pytest

from lgmcts.extras import EXTRAS, missing_extra

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "examples" / "tabletop.json"
GOALS = ROOT / "examples" / "goals.json"


def test_every_optional_module_names_its_extra():
    for module, extra in EXTRAS.items():
        msg = missing_extra(ModuleNotFoundError(f"No module named '{module}'", name=module))
        assert msg is not None and f"pip install 'lgmcts[{extra}]'" in msg and "\n" not in msg
    assert missing_extra(ModuleNotFoundError("x", name="numpy")) is None
    assert missing_extra(ValueError("mujoco")) is None


def test_extras_in_pyproject_cover_the_map():
    import tomllib

    meta = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]
    extras = meta["optional-dependencies"]
    assert set(EXTRAS.values()) <= set(extras)
    base = " ".join(meta["dependencies"])
    for heavy in ("torch", "mujoco", "matplotlib", "fastapi", "openai", "sentence-transformers", "rich"):
        assert heavy not in base


def _base_venv() -> Path:
    """A virtual environment with only the base install of this checkout, cached by pyproject.toml."""
    key = hashlib.sha1((ROOT / "pyproject.toml").read_bytes() + str(ROOT).encode()).hexdigest()[:12]
    venv = Path(os.environ.get("LGMCTS_BASE_VENV", f"/tmp/lgmcts-base-venv-{key}"))
    py = venv / "bin" / "python"
    if not (venv / ".ready").exists():
        subprocess.run([sys.executable, "-m", "venv", "--clear", str(venv)], check=True, timeout=120)
        r = subprocess.run(
            [str(py), "-m", "pip", "install", "-q", "-e", str(ROOT)], capture_output=True, text=True, timeout=600
        )
        if r.returncode != 0:
            pytest.skip(f"pip could not install the base package (no package index?): {r.stderr.strip()[-300:]}")
        (venv / ".ready").touch()
    return venv


@pytest.mark.slow
def test_base_install_plans_validates_and_names_missing_extras(tmp_path):
    venv = _base_venv()
    lg = str(venv / "bin" / "lgmcts")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}

    def run(*args: str) -> subprocess.CompletedProcess:
        return subprocess.run([lg, *args], capture_output=True, text=True, timeout=120, env=env, cwd=tmp_path)

    out = venv / "bin" / "python"
    r = subprocess.run([str(out), "-c", "import torch"], capture_output=True, env=env)
    assert r.returncode != 0, "the base venv must not have torch"

    plan = tmp_path / "plan.json"
    r = run("plan", str(SCENE), "--goal", str(GOALS), "-o", str(plan))
    assert r.returncode == 0, r.stderr
    r = run("check", str(SCENE), str(GOALS), str(plan))
    assert r.returncode == 0 and r.stdout.strip() == "valid", r.stdout + r.stderr
    r = run("viz", str(plan), "--scene", str(SCENE), "--html", str(tmp_path / "v.html"))
    assert r.returncode == 0 and (tmp_path / "v.html").stat().st_size > 1000, r.stderr

    for args, extra in [
        (("plan", str(SCENE), "put all blocks in a circle"), "language"),
        (("parse", str(SCENE), "put all blocks in a circle", "--parser", "llm", "--llm-model", "m"), "llm"),
        (("execute", str(SCENE), str(plan)), "sim"),
        (("viz", str(plan), "--scene", str(SCENE), "-o", str(tmp_path / "pics")), "viz"),
        (("serve", "--port", "0"), "service"),
    ]:
        r = run(*args)
        lines = r.stderr.strip().splitlines()
        assert r.returncode == 2 and len(lines) == 1, (args, r.stderr)
        assert f"lgmcts[{extra}]" in lines[0], (args, lines)
