"""End to end on small suites: generator -> parser -> planner -> MuJoCo executor -> verdict."""

from __future__ import annotations

import pytest

from lgmcts.bench import RunOptions, generate, run_suite, summarise

pytest.importorskip("mujoco", reason="the 'sim' extra is not installed")
pytestmark = pytest.mark.slow


@pytest.mark.parametrize("suite,parser", [("elgr", "rules"), ("structformer", "gt")])
def test_small_suite_end_to_end(tmp_path, suite, parser):
    tasks = generate(suite, n=3, seed=21)
    recs = run_suite(
        tasks, tmp_path / suite, options=RunOptions(method="lgmcts", parser=parser, max_iter=3000), workers=1
    )
    assert [r["id"] for r in recs] == [t.id for t in tasks]
    for r in recs:
        # Every stage ran and left its verdict in the record.
        assert r["planning"]["solved"] is not None and r["sr_ep"] is not None
        if parser == "rules":
            assert r["parse"]["correct"] is True, r
        assert r["sr_p"], r
        assert r["execution"] is not None and 0 < r["execution"]["steps"] <= r["planning"]["actions"]
        assert r["sr_ep"] == r["execution"]["success"]
        assert r["sr_ep"] or r["cause"] == "execution failed"
    row = summarise(recs)[-1]
    assert row.tasks == 3 and row.sr_p == 1.0
    assert row.sr_ep >= 2 / 3  # physics may fail a task; it must not fail them all
