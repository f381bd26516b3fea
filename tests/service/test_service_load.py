"""A bounded load test: 200 /plan requests, 8 in flight, none may fail."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

import lgmcts
from lgmcts.service.load import fire

pytestmark = pytest.mark.slow

ROOT = Path(__file__).resolve().parents[2]
SCENE = json.loads((ROOT / "examples" / "tabletop.json").read_text())
GOALS = json.loads((ROOT / "examples" / "goals.json").read_text())


def test_200_plans_8_in_flight_none_fails(server):
    plans: dict[int, dict] = {}

    def body(i: int) -> dict:
        return {"scene": SCENE, "goals": GOALS, "options": {"seed": i % 10, "max_iter": 2000}}

    report = fire(server.url, body, n=200, concurrency=8)
    assert report.failures == 0, report.errors[:3]
    assert report.unsolved == 0
    assert report.statuses == {"200": 200}
    assert len(report.latencies_s) == 200
    assert 0 < report.median_s <= report.p95_s <= report.max_s
    # After the load, the service still answers the library's plan for a seed.
    import httpx

    with httpx.Client(base_url=server.url, timeout=30) as c:
        for seed in (0, 7):
            plans[seed] = c.post("/plan", json=body(seed)).json()
    for seed, plan in plans.items():
        ref = lgmcts.plan(SCENE, GOALS, seed=seed, max_iter=2000)
        assert [a.model_dump(mode="json") for a in ref.actions] == plan["actions"]


def test_report_counts_errors_as_failures(server):
    report = fire(server.url, lambda i: {"scene": SCENE, "goals": {"goals": []}} if i % 2 else {}, n=6, concurrency=3)
    assert report.failures == 6 and report.statuses == {"422": 6}
    assert len(report.errors) == 6
