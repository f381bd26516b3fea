"""Golden plans: the planner gives the recorded plan for every (case, method, seed).

A failure here means a change altered plans. If that was the intent (a
planner improvement), regenerate with ``make golden`` and review the diff of
``tests/data/golden_plans.json``; if not, the change broke a refactor.
"""

from __future__ import annotations

import golden
import pytest

RECORDED = golden.load()
RUNS = golden.runs()


def test_golden_file_covers_every_run():
    assert sorted(RECORDED) == sorted(golden.key({"case": c, "method": m, "seed": s}) for c, m, s in RUNS)
    assert {m for _, m, _ in RUNS} == {"lgmcts", "greedy", "pmcts"}
    assert len(golden.cases()) >= 30


@pytest.mark.parametrize("case,method,seed", RUNS, ids=[f"{c}/{m}/{s}" for c, m, s in RUNS])
def test_plan_matches_golden(case, method, seed):
    got = golden.compute(case, method, seed)
    want = RECORDED[golden.key(got)]
    assert got == want, f"plan changed for {golden.key(got)}: run `make golden` only if the change is intended"
    # Golden plans are only worth guarding when they are right.
    assert got["solved"] == got["valid"]


def test_digest_sees_every_field():
    import lgmcts

    a = lgmcts.PlanSpec(solved=True, actions=[lgmcts.Action(object=1, to=(0.1, 0.2, 0.0))])
    variants = [
        lgmcts.PlanSpec(solved=False, actions=a.actions),
        lgmcts.PlanSpec(solved=True, actions=[lgmcts.Action(object=2, to=(0.1, 0.2, 0.0))]),
        lgmcts.PlanSpec(solved=True, actions=[lgmcts.Action(object=1, to=(0.1, 0.2001, 0.0))]),
        lgmcts.PlanSpec(solved=True, actions=[lgmcts.Action(object=1, to=(0.1, 0.2, 0.0), on=3)]),
        lgmcts.PlanSpec(solved=True, actions=[lgmcts.Action(object=1, to=(0.1, 0.2, 0.0), purpose="relocate")]),
    ]
    assert len({golden.digest(p) for p in [a, *variants]}) == 1 + len(variants)
