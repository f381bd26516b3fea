"""Instructions over HTTP: /parse, /plan from an instruction, and torch kept
out of the serving process. The language worker loads its sentence model in
the background when the test server starts (``--preload-language``), so these
tests run after the others."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import lgmcts

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
SCENE = json.loads((ROOT / "examples" / "tabletop.json").read_text())


def test_parse_answers_goals(client):
    r = client.post("/parse", json={"scene": SCENE, "instruction": "put all blocks in a circle"})
    assert r.status_code == 200, r.text
    # Objects 1-4 are the scene's blocks.
    assert r.json() == {"goals": [{"pattern": "circle", "objects": [1, 2, 3, 4]}]}


def test_plan_from_an_instruction(client):
    body = {"scene": SCENE, "instruction": "put all blocks in a circle"}
    r = client.post("/plan", json=body)
    assert r.status_code == 200, r.text
    plan = r.json()
    assert plan["instruction"] == body["instruction"]
    assert plan["goals"] == {"goals": [{"pattern": "circle", "objects": [1, 2, 3, 4]}]}
    assert plan["solved"] and lgmcts.check(SCENE, plan["goals"], plan).valid


def test_bad_instruction_is_one_line_422(client):
    r = client.post("/parse", json={"scene": SCENE, "instruction": "   "})
    assert r.status_code == 422
    assert r.json() == {"detail": "the instruction is empty"}
    r = client.post("/plan", json={"scene": SCENE, "instruction": "x", "parser": "oracle"})
    assert r.status_code == 422 and r.json()["detail"].startswith("unknown parser 'oracle'")


@pytest.mark.skipif(not Path("/proc/self/maps").exists(), reason="needs Linux /proc")
def test_main_process_never_loads_torch(client, server):
    client.post("/plan", json={"scene": SCENE, "goals": {"goals": [{"pattern": "line", "objects": [1, 2]}]}})
    client.post("/parse", json={"scene": SCENE, "instruction": "put all blocks in a line"})
    maps = Path(f"/proc/{server.pid}/maps").read_text()
    assert "torch" not in maps




def test_the_pages_example_instruction_means_its_example_goals(client):
    from lgmcts.service.viewer import EXAMPLE_GOALS, EXAMPLE_INSTRUCTION, EXAMPLE_SCENE

    r = client.post("/parse", json={"scene": EXAMPLE_SCENE, "instruction": EXAMPLE_INSTRUCTION})
    assert r.status_code == 200 and r.json() == EXAMPLE_GOALS
