"""The registry of benchmark suites and the suite generator.

Each suite is a module with ``CATEGORIES`` and ``generate_task(category,
seed, task_id=...)``. Task ``k`` of a suite has category ``CATEGORIES[k %
len(CATEGORIES)]`` (so any prefix of a suite is balanced) and seed
:func:`lgmcts.bench.tasks.task_seed` ``(seed, k)``.
"""

from __future__ import annotations

from collections.abc import Callable, Iterator
from dataclasses import dataclass
from functools import partial
from types import ModuleType

from ..errors import InputError
from . import elgr, structformer
from .tasks import Task, task_seed

__all__ = ["SUITES", "Suite", "generate", "iter_generate", "suite"]


@dataclass(frozen=True)
class Suite:
    """A registered suite: its name, categories, default size and task builder."""

    name: str
    categories: tuple[str, ...]
    default_n: int
    build: Callable[..., Task]
    description: str


def _suite(name: str, mod: ModuleType, default_n: int, description: str, **options) -> Suite:
    build = partial(mod.generate_task, **options) if options else mod.generate_task
    return Suite(name, tuple(mod.CATEGORIES), default_n, build, description)


#: Registered suites by name.
SUITES: dict[str, Suite] = {
    "elgr": _suite("elgr", elgr, 1600, "two composed patterns, infeasible starts, templated language"),
    "elgr-dense": _suite("elgr-dense", elgr, 1600, "the elgr tasks plus touching clutter packed around the goal region",
                         dense=True),
    "structformer": _suite("structformer", structformer, 2000, "one pattern per task: line, circle, tower, dinner"),
}


def suite(name: str) -> Suite:
    """The suite called ``name``; :class:`InputError` for an unknown one."""
    try:
        return SUITES[name]
    except KeyError:
        raise InputError(f"unknown suite '{name}' (known: {', '.join(SUITES)})") from None


def iter_generate(name: str, *, n: int | None = None, seed: int = 0, category: str | None = None,
                  instructions: str = "ours") -> Iterator[Task]:
    """The first ``n`` tasks of suite ``name`` generated with ``seed``, one at a time.

    Every option is checked when this is called (:class:`InputError`), before
    the first task is made: a caller may open its output file after the call.

    With ``category``, only that category's tasks (their indices and seeds
    are those they have in the full suite). ``instructions="peer"`` phrases
    each task with the peers' sentence templates
    (:mod:`lgmcts.bench.peer_language`); scenes and goals are unchanged.
    """
    from .peer_language import MODES, rephrase

    if instructions not in MODES:
        raise InputError(f"unknown instruction mode '{instructions}' (known: {', '.join(MODES)})")
    s = suite(name)
    if n is not None and n < 1:
        raise InputError("--n must be at least 1")
    if seed < 0:
        raise InputError("--seed must be >= 0")
    if category is not None and category not in s.categories:
        raise InputError(f"unknown category '{category}' of suite {name} (known: {', '.join(s.categories)})")
    total = s.default_n if n is None else n
    return _generated(s, name, total, seed, category, instructions, rephrase)


def _generated(s: Suite, name: str, total: int, seed: int, category: str | None, instructions: str,
               rephrase: Callable[[Task, str], Task]) -> Iterator[Task]:
    made, k = 0, 0
    while made < total:
        cat = s.categories[k % len(s.categories)]
        if category is None or cat == category:
            yield rephrase(s.build(cat, task_seed(seed, k), task_id=f"{name}-{seed}-{k:05d}"), instructions)
            made += 1
        k += 1


def generate(name: str, *, n: int | None = None, seed: int = 0, category: str | None = None,
             instructions: str = "ours") -> list[Task]:
    """The first ``n`` tasks of suite ``name`` (its default size when ``n`` is None)."""
    return list(iter_generate(name, n=n, seed=seed, category=category, instructions=instructions))
