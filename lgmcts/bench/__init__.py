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

from ..lazy import lazy_names

__all__ = [
    "CAUSES",
    "SUITES",
    "Row",
    "RunOptions",
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

# Loaded on first use, so that other ``lgmcts`` commands import none of it.
_WHERE = {
    **dict.fromkeys(["Row", "summarise", "to_csv", "to_markdown"], ".report"),
    **dict.fromkeys(["CAUSES", "RunOptions", "canonical_goals", "load_results", "run_suite", "run_task"], ".runner"),
    **dict.fromkeys(["SUITES", "Suite", "generate", "iter_generate", "suite"], ".suites"),
    **dict.fromkeys(["Task", "read_suite", "task_seed", "write_suite"], ".tasks"),
}


__getattr__, __dir__ = lazy_names(__name__, _WHERE)
