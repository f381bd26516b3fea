"""Benchmark suites (ELGR-style and StructFormer-style), their generator and
the runner that measures SR_p / SR_ep of a planning method on them.

Quick use::

    from lgmcts.bench import generate, run_suite, RunOptions, summarise, to_markdown
    tasks = generate("elgr", n=20, seed=0)
    records = run_suite(tasks, "out/elgr", options=RunOptions(method="lgmcts"), workers=2)
    print(to_markdown(summarise(records)))

See ``docs/bench.md``.
"""

from __future__ import annotations

from .report import Row, summarise, to_csv, to_markdown
from .runner import CAUSES, RunOptions, canonical_goals, load_results, run_suite, run_task
from .suites import SUITES, Suite, generate, iter_generate, suite
from .tasks import Task, read_suite, task_seed, write_suite

__all__ = [
    "CAUSES",
    "Row",
    "RunOptions",
    "SUITES",
    "Suite",
    "Task",
    "canonical_goals",
    "generate",
    "iter_generate",
    "load_results",
    "read_suite",
    "run_suite",
    "run_task",
    "suite",
    "summarise",
    "task_seed",
    "to_csv",
    "to_markdown",
    "write_suite",
]
