"""The ELGR-style and StructFormer-style suites (built from the peers' templates) parse to their own goals,
every task: the suites' 100 % SR_p is a target of the parser, so a change that loses one fails here."""

from __future__ import annotations

import pytest

pytestmark = pytest.mark.slow


@pytest.mark.parametrize("name, n", [("elgr", 400), ("structformer", 200)])
def test_every_suite_task_parses_to_its_goals(name, n):
    from lgmcts.bench.suites import generate
    from lgmcts.errors import InputError
    from lgmcts.language.evaluate import goals_match
    from lgmcts.language.matcher import default_matcher
    from lgmcts.language.rules import parse_rules

    matcher = default_matcher()
    missed = []
    for task in generate(name, n=n, seed=0):
        try:
            goals = parse_rules(task.scene_spec(), task.instruction, matcher=matcher)
        except InputError as exc:
            missed.append(f"{task.instruction!r}: refused ({exc})")
            continue
        if not goals_match(task.goals, goals):
            missed.append(f"{task.instruction!r}: {goals}")
    assert not missed, "\n".join(missed[:5])
