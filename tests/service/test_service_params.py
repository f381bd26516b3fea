"""The service plans and checks goals with a region, size and facing."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import lgmcts

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
SCENE = json.loads((ROOT / "examples" / "tabletop.json").read_text())
GOALS = {"goals": [
    {"pattern": "circle", "objects": [1, 2, 3, 4], "region": "top right", "size": "small", "facing": "south"},
    {"pattern": "line", "objects": [5, 6, 7], "region": "bottom", "facing": "north"},
]}


def test_plan_with_params(client):
    r = client.post("/plan", json={"scene": SCENE, "goals": GOALS, "options": {"seed": 1}})
    assert r.status_code == 200, r.text
    plan = r.json()
    assert plan["solved"] and plan["goals"] == GOALS
    assert lgmcts.check(SCENE, GOALS, plan).valid
    ok = client.post("/check", json={"scene": SCENE, "goals": GOALS, "plan": plan})
    assert ok.status_code == 200 and ok.json()["valid"] is True
    moved = {**GOALS, "goals": [{**GOALS["goals"][0], "region": "bottom left"}, GOALS["goals"][1]]}
    bad = client.post("/check", json={"scene": SCENE, "goals": moved, "plan": plan})
    assert bad.status_code == 200 and bad.json()["valid"] is False
    assert any("outside region 'bottom left'" in x for x in bad.json()["reasons"])


def test_bad_param_is_one_line_422(client):
    goals = {"goals": [{"pattern": "line", "objects": [1, 2], "facing": "upwards"}]}
    r = client.post("/plan", json={"scene": SCENE, "goals": goals})
    assert r.status_code == 422
    assert r.json() == {
        "detail": "invalid goals at goals.0: unknown facing 'upwards' (north|east|south|west or an angle in radians)"
    }
