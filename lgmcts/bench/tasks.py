"""Benchmark tasks as data: the task record, seeds and the JSONL suite files.

A suite file holds one task per line::

    {"id": "elgr-00042", "seed": 42, "suite": "elgr", "category": "line+circle",
     "scene": {...scene JSON...}, "instruction": "Put all blocks in a line; and ...",
     "goals": {"goals": [...]},            # ground truth
     "final": {"3": [x, y, theta], ...},   # the arrangement the task was built from
     "final_on": {"5": 4, ...},            # supports in that arrangement (towers)
     "start": {"blockers": [[top, base]], "clutter": [[object, target]]},
     "instructions": "peer"}                # only when phrased in the peers' templates

Seeds: task ``k`` of a suite generated with seed ``S`` is built from the
integer ``S * 1_000_000 + k`` alone, so any task can be rebuilt from its
record, and suites with different ``S`` never share a task. Seed 0 is the
reported test suite; use seeds >= 1 to tune a method ("train").
"""

from __future__ import annotations

import json
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from ..errors import InputError
from ..formats import GoalSpec, SceneSpec, parse_goals, parse_scene
from ..limits import truncate

__all__ = ["SEED_STRIDE", "Task", "read_suite", "task_seed", "write_suite"]

#: Task seeds of suite seed S are ``S * SEED_STRIDE + k``.
SEED_STRIDE = 1_000_000


def _number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def task_seed(suite_seed: int, index: int) -> int:
    """Seed of task ``index`` of a suite generated with ``suite_seed``."""
    if suite_seed < 0 or not 0 <= index < SEED_STRIDE:
        raise InputError(f"seed must be >= 0 and a suite may hold at most {SEED_STRIDE} tasks")
    return suite_seed * SEED_STRIDE + index


@dataclass(frozen=True)
class Task:
    """One benchmark task: a start scene, an instruction and its ground-truth goals.

    ``final``/``final_on`` hold the arrangement the generator built first (it
    meets every goal); ``start`` says how the start state was made hard.
    """

    id: str
    seed: int
    suite: str
    category: str
    scene: dict
    instruction: str
    goals: dict
    final: dict = field(default_factory=dict)
    final_on: dict = field(default_factory=dict)
    start: dict = field(default_factory=dict)
    #: Who wrote the instruction's template: "ours" or "peer" (``lgmcts.bench.peer_language``).
    instructions: str = "ours"

    def scene_spec(self) -> SceneSpec:
        """The start scene as a validated model."""
        return parse_scene(self.scene)

    def goal_spec(self) -> GoalSpec:
        """The ground-truth goals as a validated model."""
        return parse_goals(self.goals)

    def to_dict(self) -> dict[str, Any]:
        extra = {} if self.instructions == "ours" else {"instructions": self.instructions}
        return {
            "id": self.id,
            "seed": self.seed,
            "suite": self.suite,
            "category": self.category,
            "scene": self.scene,
            "instruction": self.instruction,
            "goals": self.goals,
            "final": self.final,
            "final_on": self.final_on,
            "start": self.start,
            **extra,
        }

    @classmethod
    def from_dict(cls, data: dict[str, Any], *, where: str = "task") -> Task:
        """Build a task from a JSON record; :class:`InputError` names what is missing."""
        if not isinstance(data, dict):
            raise InputError(f"{where}: a task must be a JSON object")
        need = ("id", "scene", "instruction", "goals")
        missing = [k for k in need if k not in data]
        if missing:
            raise InputError(f"{where}: missing field(s) {', '.join(missing)}")

        def typed(key: str, kinds: tuple[type, ...], noun: str, default: Any = None) -> Any:
            value = data.get(key, default)
            if (isinstance(value, bool) and bool not in kinds) or not isinstance(value, kinds):
                raise InputError(f"{where}: '{key}' must be {noun}, got {truncate(json.dumps(value), 40)}")
            return value

        ident = typed("id", (str, int), "a string")
        seed = typed("seed", (int,), "a non-negative integer", 0)
        if seed < 0:
            raise InputError(f"{where}: 'seed' must be a non-negative integer, got {seed}")
        goals = typed("goals", (dict, list), "a goal object or list")
        final = typed("final", (dict,), "an object of poses", {}) or {}
        for k, pose in final.items():
            if not (isinstance(pose, list) and len(pose) == 3 and all(_number(v) for v in pose)):
                raise InputError(f"{where}: 'final.{truncate(k, 20)}' must be a pose [x, y, theta]")
        final_on = typed("final_on", (dict,), "an object of supports", {}) or {}
        for k, support in final_on.items():
            if support is not None and (isinstance(support, bool) or not isinstance(support, int)):
                raise InputError(f"{where}: 'final_on.{truncate(k, 20)}' must be an object id or null")
        task = cls(
            id=str(ident),
            seed=seed,
            suite=typed("suite", (str,), "a string", ""),
            category=typed("category", (str,), "a string", ""),
            scene=typed("scene", (dict,), "a scene object"),
            instruction=typed("instruction", (str,), "a string"),
            goals=goals if isinstance(goals, dict) else {"goals": goals},
            final=dict(final),
            final_on=dict(final_on),
            start=dict(typed("start", (dict,), "an object", {}) or {}),
            instructions=typed("instructions", (str,), "a string", "ours"),
        )
        try:
            scene = task.scene_spec()
            task.goal_spec().check_against(scene)
        except InputError as exc:
            raise InputError(f"{where} ({task.id}): {exc}") from None
        return task


def write_suite(tasks: Iterable[Task], path: str | Path) -> int:
    """Write ``tasks`` to a JSONL file atomically; returns how many were written."""
    from ..outputs import atomic_write

    n = 0

    def write(fh: Any) -> None:
        nonlocal n
        for t in tasks:
            fh.write(json.dumps(t.to_dict(), separators=(",", ":")) + "\n")
            n += 1

    # Written beside and renamed over: a failure (a bad task, a full disk)
    # leaves an existing file as it was.
    atomic_write(path, write)
    return n


def read_suite(path: str | Path, *, limit: int | None = None) -> list[Task]:
    """Read a JSONL suite file (the first ``limit`` tasks when given)."""
    return list(_iter_suite(Path(path), limit))


def _iter_suite(path: Path, limit: int | None) -> Iterator[Task]:
    from ..inputs import loads, read_lines

    seen: set[str] = set()
    n = 0
    for lineno, line in read_lines(path, "suite"):
        if limit is not None and n >= limit:
            return
        if not line.strip():
            continue
        try:
            data = loads(line, f"{path} line {lineno}")
        except json.JSONDecodeError as exc:
            raise InputError(f"{path} line {lineno} is not valid JSON: {exc.msg}") from None
        task = Task.from_dict(data, where=f"{path} line {lineno}")
        if task.id in seen:
            raise InputError(f"{path} line {lineno}: duplicate task id {task.id}")
        seen.add(task.id)
        n += 1
        yield task
    if n == 0:
        raise InputError(f"suite file {path} holds no tasks")
