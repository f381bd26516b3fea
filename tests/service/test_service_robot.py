"""The service plans and checks for a robot arm (``robot``), as ``lgmcts plan/check --robot`` do."""

from __future__ import annotations

import json
import shutil
from collections.abc import Iterator

import httpx
import pytest

import lgmcts

from .conftest import ROOT, start_server, stop_server

pytestmark = pytest.mark.slow

SCENE = json.loads((ROOT / "examples" / "tabletop.json").read_text())
GOALS = json.loads((ROOT / "examples" / "goals.json").read_text())

#: A wide table: its far corner lies beyond the UR5e's reach, not beyond the floating cup's.
WIDE = {
    "workspace": {"x": [-0.7, 0.7], "y": [-0.3, 0.6]},
    "objects": [
        {"id": 1, "name": "block", "color": "red", "shape": {"type": "box", "size": [0.05, 0.05, 0.05]},
         "pose": [0.1, 0.1, 0.0]},
    ],
}
FAR = [0.62, 0.52, 0.0]
FAR_GOALS = {"goals": [{"pattern": "pose", "objects": [1], "pose": FAR}]}
FAR_PLAN = {"solved": True, "actions": [{"object": 1, "to": FAR, "on": None}], "goals": FAR_GOALS}


@pytest.fixture(scope="module")
def arm_client(tmp_path_factory: pytest.TempPathFactory) -> Iterator[httpx.Client]:
    """One planning worker, no language model: these requests give goals."""
    proc, url = start_server(
        "--workers", "1", "--timeout", "60", log=tmp_path_factory.mktemp("robot") / "s.log", hooks=False
    )
    try:
        with httpx.Client(base_url=url, timeout=60.0) as c:
            yield c
    finally:
        stop_server(proc)


@pytest.mark.parametrize(
    ("route", "body"),
    [
        ("/plan", {"scene": SCENE, "goals": GOALS, "options": {"robot": "ur9"}}),
        ("/check", {"scene": SCENE, "goals": GOALS, "plan": {"solved": True, "actions": []}, "robot": "ur9"}),
    ],
)
def test_unknown_robot_is_one_line_422(arm_client, route, body):
    r = arm_client.post(route, json=body)
    assert r.status_code == 422
    assert r.json() == {"detail": "unknown robot 'ur9' (known: ur5e)"}


def test_robot_of_the_wrong_type_is_422(arm_client):
    r = arm_client.post("/plan", json={"scene": SCENE, "goals": GOALS, "options": {"robot": 5}})
    assert r.status_code == 422
    assert r.json()["detail"].startswith("invalid request at options.robot: ")
    # An overlong name is cut in the message, never echoed in full.
    r = arm_client.post("/plan", json={"scene": SCENE, "goals": GOALS, "options": {"robot": "u" * 200}})
    assert r.status_code == 422 and len(r.json()["detail"]) < 120 and "\n" not in r.json()["detail"]


def test_plan_for_the_arm_names_it_and_stays_in_reach(arm_client):
    r = arm_client.post("/plan", json={"scene": SCENE, "goals": GOALS, "options": {"seed": 0, "robot": "ur5e"}})
    assert r.status_code == 200, r.text
    plan = r.json()
    assert plan["solved"] and plan["stats"]["robot"] == "ur5e"
    # The same plan as the library's for the same robot and seed.
    lib = lgmcts.plan(SCENE, GOALS, seed=0, robot="ur5e")
    assert plan["actions"] == [a.model_dump(mode="json") for a in lib.actions]
    assert lgmcts.check(SCENE, GOALS, plan, robot="ur5e").valid
    ok = arm_client.post("/check", json={"scene": SCENE, "goals": GOALS, "plan": plan, "robot": "ur5e"})
    assert ok.status_code == 200 and ok.json()["valid"] is True, ok.text


def test_no_robot_is_the_plain_plan(arm_client):
    plain = arm_client.post("/plan", json={"scene": SCENE, "goals": GOALS})
    null = arm_client.post("/plan", json={"scene": SCENE, "goals": GOALS, "options": {"robot": None}})
    assert plain.status_code == null.status_code == 200
    assert "robot" not in plain.json()["stats"] and "robot" not in null.json()["stats"]
    assert plain.json()["actions"] == null.json()["actions"]


def test_check_rejects_a_place_out_of_reach(arm_client):
    floating = arm_client.post("/check", json={"scene": WIDE, "goals": FAR_GOALS, "plan": FAR_PLAN})
    assert floating.status_code == 200 and floating.json()["valid"] is True
    arm = arm_client.post("/check", json={"scene": WIDE, "goals": FAR_GOALS, "plan": FAR_PLAN, "robot": "ur5e"})
    assert arm.status_code == 200
    verdict = arm.json()
    assert verdict["valid"] is False and verdict["goals"] == [True]
    assert verdict["reasons"] == ["action 1: the place (0.620, 0.520) of object 1 is out of the ur5e's reach"]


def test_planner_keeps_out_of_the_unreachable_corner(arm_client):
    body = {"scene": WIDE, "goals": FAR_GOALS, "options": {"max_iter": 50}}
    plain = arm_client.post("/plan", json=body)
    assert plain.status_code == 200 and plain.json()["solved"] is True
    arm = arm_client.post("/plan", json={**body, "options": {"max_iter": 50, "robot": "ur5e"}})
    assert arm.status_code == 200
    assert arm.json()["solved"] is False and arm.json()["stats"]["robot"] == "ur5e"
    assert arm.json()["actions"] == []


@pytest.mark.skipif(
    shutil.which("chromium") is None, reason="Debian's chromium is not installed (scripts/system-deps.sh)"
)
def test_page_plans_for_the_arm(arm_client):
    sync_api = pytest.importorskip("playwright.sync_api")
    errors: list[str] = []
    with sync_api.sync_playwright() as pw:
        browser = pw.chromium.launch(executable_path=shutil.which("chromium"), args=["--no-sandbox", "--disable-gpu"])
        try:
            page = browser.new_page()
            page.on("pageerror", lambda e: errors.append(str(e)))
            page.goto(str(arm_client.base_url) + "/")
            page.fill("#instruction", "")  # the example's goals: no language model needed
            page.select_option("#robot", "ur5e")
            page.click("#plan")
            page.wait_for_function("document.getElementById('status').textContent.startsWith('solved')", timeout=30_000)
            plan = json.loads(page.inner_text("#json"))
            page.click("#check")
            page.wait_for_function(
                "document.getElementById('status').textContent === 'the plan is valid'", timeout=30_000
            )
        finally:
            browser.close()
    assert errors == []
    assert plan["stats"]["robot"] == "ur5e"
    assert lgmcts.check(SCENE, plan["goals"], plan, robot="ur5e").valid
