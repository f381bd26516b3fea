"""Exact-goal accuracy of a parser on a labelled set of commands.

Case file (JSON Lines). A line with ``"scene_id"`` and ``"scene"`` defines a
named scene; every other line is a case::

    {"id": "rel-003", "category": "relation", "scene": "vima_a",
     "instruction": "Put the red swirl flower left and behind of ...",
     "expect": {"goals": [{"pattern": "left_behind", "objects": [4], "anchor": 5}]}}
    {"id": "ref-001", "category": "refusal", "scene": "vima_a",
     "instruction": "put the purple giraffe in a line", "refuse": "giraffe"}

``scene`` is a name defined earlier in the file, a path (relative to the
case file) or an inline scene. Benchmark task files (``lgmcts
bench-generate``) are read too: their ``goals`` are the expected goals.

Comparison (:func:`goals_match`): goals as sets (one-to-one, order free);
object lists as sets except for ordered patterns without anchor (towers);
an expected goal may say ``"objects_from": [ids], "count": k`` (any k of
those: "three blocks") and ``"anchor_any": [ids]`` (any one: "behind one
block"); ``"disjoint": [[i, j]]`` at the top requires goals i and j to share
no object ("another line"). A tower goal with ``"unordered": true`` matches
its objects in any order (a stack whose order the command leaves open). A
relation of one object to one anchor also matches its inverse ("the cup
right of the mug" and "the mug left of the cup"): the acceptance rule holds
of both in the same states. For the same reason, relation goals of one
direction, one anchor and the same parameters are compared joined into one
("the cup behind the bowl" and "the mug behind the bowl" match "the cup and
the mug behind the bowl"; not where ``disjoint`` is given).
``{"any_of": [expect, expect, ...]}`` passes when any alternative matches
(a place setting with the cutlery on either side). The optional pattern
parameters ``region`` ("top left", "middle center": ``<row> <col>`` with
row bottom|middle|top and col left|center|right), ``size``
(small|medium|large) and ``facing`` (north|east|south|west) must be equal
when either side names them (a size in metres to within half a millimetre: the parser keeps sizes to a tenth
of a millimetre, labels write them to the millimetre or finer, "12 inches" as 0.305 or 0.3048; a pose's x and y likewise and its yaw to a thousandth of a radian, as labels write "1.5708"). A refusal case passes when the parser raises
:class:`~lgmcts.errors.InputError` (and its message contains ``refuse``
when that is a non-empty string).

A case may also carry ``family`` (its template family; used as the
category when ``category`` is absent), ``split`` ("dev" or "test"; see
``--split``) and ``needs`` (e.g. ``["params"]`` for cases whose goals use
the optional parameters).

A **wrong goal** is an answer (goals, not a refusal) that does not match:
goals that differ from the label, or any goals for a command that must be
refused. The wrong-goal rate is taken over the answered commands.
"""

from __future__ import annotations

import itertools
import json
import statistics
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Callable

from ..errors import InputError
from ..formats import GoalSpec, SceneSpec, parse_scene, to_dict

__all__ = ["Case", "CaseResult", "EvalReport", "load_cases", "goals_match", "evaluate"]


@dataclass(frozen=True)
class Case:
    """One labelled command."""

    id: str
    category: str
    scene: SceneSpec
    instruction: str
    expect: dict | None = None
    refuse: str | bool | None = None
    family: str | None = None
    split: str | None = None
    needs: tuple[str, ...] = ()


@dataclass(frozen=True)
class CaseResult:
    case: Case
    ok: bool
    got: dict | None
    error: str | None
    time_s: float


@dataclass
class EvalReport:
    """Accuracy overall and per category, the failures, and parse speed."""

    results: list[CaseResult] = field(default_factory=list)
    load_time_s: float | None = None

    @property
    def accuracy(self) -> float:
        return sum(r.ok for r in self.results) / len(self.results) if self.results else 0.0

    def per_category(self) -> dict[str, tuple[int, int]]:
        out: dict[str, list[int]] = {}
        for r in self.results:
            c = out.setdefault(r.case.category, [0, 0])
            c[0] += r.ok
            c[1] += 1
        return {k: (v[0], v[1]) for k, v in sorted(out.items())}

    @property
    def failures(self) -> list[CaseResult]:
        return [r for r in self.results if not r.ok]

    def outcomes(self) -> dict[str, int]:
        """Counts: answered, wrong goals among them, refused, refused wrongly (a correct command refused)."""
        answered = [r for r in self.results if r.got is not None]
        refused = [r for r in self.results if r.got is None]
        return {
            "answered": len(answered),
            "wrong_goals": sum(not r.ok for r in answered),
            "refused": len(refused),
            "wrongly_refused": sum(not r.ok for r in refused),
        }

    @property
    def wrong_goal_rate(self) -> float:
        """Wrong goals over answered commands (0 when nothing was answered)."""
        o = self.outcomes()
        return o["wrong_goals"] / o["answered"] if o["answered"] else 0.0

    def per_split(self) -> dict[str, tuple[int, int]]:
        out: dict[str, list[int]] = {}
        for r in self.results:
            c = out.setdefault(r.case.split or "-", [0, 0])
            c[0] += r.ok
            c[1] += 1
        return {k: (v[0], v[1]) for k, v in sorted(out.items())}

    def timing(self) -> dict[str, float]:
        ts = sorted(r.time_s for r in self.results)
        if not ts:
            return {}
        p95 = ts[min(len(ts) - 1, int(round(0.95 * (len(ts) - 1))))]
        return {"mean_ms": 1e3 * statistics.fmean(ts), "median_ms": 1e3 * statistics.median(ts), "p95_ms": 1e3 * p95,
                "max_ms": 1e3 * ts[-1]}

    def to_dict(self) -> dict[str, Any]:
        return {
            "cases": len(self.results),
            "correct": sum(r.ok for r in self.results),
            "accuracy": self.accuracy,
            "per_category": {k: {"correct": a, "total": b, "accuracy": a / b} for k, (a, b) in self.per_category().items()},
            "per_split": {k: {"correct": a, "total": b, "accuracy": a / b} for k, (a, b) in self.per_split().items()},
            **self.outcomes(),
            "wrong_goal_rate": self.wrong_goal_rate,
            "model_load_s": self.load_time_s,
            "parse_time": self.timing(),
            "failures": [
                {"id": r.case.id, "category": r.case.category, "instruction": r.case.instruction,
                 "expected": r.case.expect if r.case.refuse is None else {"refuse": r.case.refuse},
                 "got": r.got, "error": r.error}
                for r in self.failures
            ],
        }


#: Most goals one expectation may list: matching tries every order of the parsed goals.
MAX_EXPECTED_GOALS = 8


def _check_expect(e: Any, depth: int = 0) -> None:
    """Raise :class:`InputError` unless ``e`` is an expectation the matcher can read."""
    if not isinstance(e, dict):
        raise InputError("'expect' must be a goal object {\"goals\": [...]} or {\"any_of\": [...]}")
    if "any_of" in e:
        alts = e["any_of"]
        if depth > 0 or not isinstance(alts, list) or not alts:
            raise InputError("'any_of' must be a non-empty list of goal objects (not nested)")
        for alt in alts:
            _check_expect(alt, depth + 1)
        return
    goals = e.get("goals")
    if not isinstance(goals, list) or not all(isinstance(g, dict) and isinstance(g.get("pattern"), str) for g in goals):
        raise InputError("'expect' must be a goal object {\"goals\": [{\"pattern\": ...}, ...]}")
    if len(goals) > MAX_EXPECTED_GOALS:
        raise InputError(f"'expect' lists {len(goals)} goals; at most {MAX_EXPECTED_GOALS}")
    for g in goals:
        for key in ("objects", "objects_from"):
            if key in g and not (isinstance(g[key], list) and all(_integer(i) for i in g[key])):
                raise InputError(f"'{key}' of an expected goal must be a list of object ids")
    pairs = e.get("disjoint", [])
    if not isinstance(pairs, list) or not all(
        isinstance(p, list) and len(p) == 2 and all(_integer(i) and 0 <= i < len(goals) for i in p) for p in pairs
    ):
        raise InputError("'disjoint' must be a list of pairs of goal positions")


def _integer(v: Any) -> bool:
    return isinstance(v, int) and not isinstance(v, bool)


def load_cases(path: str | Path, *, split: str | None = None) -> list[Case]:
    """Read a case file (or a benchmark task file); bad lines raise :class:`InputError`.

    With ``split``, only the cases of that split ("dev" or "test").
    """
    path = Path(path)
    from ..inputs import loads, read_text

    lines = read_text(path, "case").splitlines()
    scenes: dict[str, SceneSpec] = {}
    cases: list[Case] = []
    for n, line in enumerate(lines, 1):
        if not line.strip() or line.lstrip().startswith("//"):
            continue
        try:
            row = loads(line, f"{path}:{n}")
        except json.JSONDecodeError as exc:
            raise InputError(f"{path}:{n}: not valid JSON ({exc.msg})") from None
        if not isinstance(row, dict):
            raise InputError(f"{path}:{n}: each line must be a JSON object")
        try:
            if "scene_id" in row:
                scenes[str(row["scene_id"])] = parse_scene(row["scene"])
                continue
            ref = row["scene"]
            if isinstance(ref, dict):
                scene = parse_scene(ref)
            elif isinstance(ref, str) and ref in scenes:
                scene = scenes[ref]
            elif isinstance(ref, str):
                from ..formats import load_scene

                scene = load_scene(path.parent / ref)
            else:
                raise InputError("'scene' must be a scene name, a path or an inline scene")
            expect = row.get("expect")
            if expect is None and "goals" in row and "refuse" not in row:
                g = row["goals"]
                expect = g if isinstance(g, dict) else {"goals": g}
            if expect is not None:
                _check_expect(expect)
            refuse = row.get("refuse")
            if refuse is not None and not isinstance(refuse, (str, bool)):
                raise InputError("'refuse' must be true or the words the refusal must contain")
            if expect is None and refuse is None:
                raise InputError("a case needs 'expect' (goals) or 'refuse'")
            family = row.get("family")
            category = row.get("category", family if family is not None else "uncategorised")
            for key, value in (("id", row.get("id")), ("instruction", row["instruction"]), ("family", family),
                               ("category", category), ("split", row.get("split"))):
                if value is not None and not isinstance(value, str) and not (key == "id" and _integer(value)):
                    raise InputError(f"'{key}' must be a string")
            needs = row.get("needs") or ()
            if not isinstance(needs, (list, tuple)) or not all(isinstance(x, str) for x in needs):
                raise InputError("'needs' must be a list of strings")
            case = Case(str(row.get("id", f"line-{n}")), str(category), scene, str(row["instruction"]), expect, refuse,
                        None if family is None else str(family), None if row.get("split") is None else str(row["split"]),
                        tuple(needs))
            if split is None or case.split == split:
                cases.append(case)
        except KeyError as exc:
            raise InputError(f"{path}:{n}: missing field {exc.args[0]!r}") from None
        except InputError as exc:
            raise InputError(f"{path}:{n}: {exc}") from None
    if not cases:
        raise InputError(f"{path}: no cases" + (f" in split '{split}'" if split is not None else ""))
    return cases


def _ordered_patterns() -> frozenset[str]:
    from .matcher import pattern_infos

    return frozenset(n for n, i in pattern_infos().items() if i.ordered and not i.anchored)


#: Optional pattern parameters compared when either side names them.
PARAMS = ("region", "size", "facing")
_ROWS, _COLS = ("bottom", "middle", "top"), ("left", "center", "right")


def _norm_param(key: str, value: Any) -> Any:
    if not isinstance(value, str):
        return value
    words = value.lower().replace("centre", "center").replace("-", " ").split()
    if key != "region":
        return " ".join(words)
    row = next((w for w in words if w in _ROWS or w in ("front", "back")), None)
    col = next((w for w in words if w in _COLS), None)
    if row is None and col is None:
        return " ".join(words)
    row = {"front": "bottom", "back": "top"}.get(row, row) if row is not None else "middle"
    if col is None:
        col = "center"
    if row == "center":
        row = "middle"
    return f"{row} {col}"


#: The relation that holds of the anchor when ``pattern`` holds of the object:
#: the acceptance rule (within 45 degrees of the direction, 0 < d <= 0.30 m) is
#: the same either way round, so "A left of B" and "B right of A" are one goal.
_INVERSE = {"left": "right", "right": "left", "front": "behind", "behind": "front", "left_front": "right_behind",
            "right_behind": "left_front", "left_behind": "right_front", "right_front": "left_behind"}


def _goal_ok(exp: dict, got: dict, ordered: frozenset[str]) -> bool:
    if (exp.get("pattern") != got.get("pattern") and _INVERSE.get(got.get("pattern", "")) == exp.get("pattern")
            and len(got.get("objects", [])) == 1 and len(exp.get("objects", [])) == 1 and "anchor" in exp
            and not any(got.get(k) is not None or exp.get(k) is not None for k in PARAMS)):
        # "the cup right of the mug" labelled, "the mug left of the cup" read: one goal.
        got = {"pattern": exp["pattern"], "objects": [got.get("anchor")], "anchor": got["objects"][0]}
    if exp.get("pattern") != got.get("pattern"):
        return False
    for key in PARAMS:
        a, b = _norm_param(key, exp.get(key)), _norm_param(key, got.get(key))
        if isinstance(a, (int, float)) and isinstance(b, (int, float)) and abs(a - b) < 5e-4:
            continue  # a size in metres, to the millimetre labels write ("12 inches": 0.3048 and 0.305)
        if a != b:
            return False
    objs = list(got.get("objects", []))
    if "objects" in exp:
        if exp["pattern"] in ordered and not exp.get("unordered"):
            if list(exp["objects"]) != objs:
                return False
        elif sorted(exp["objects"]) != sorted(objs):
            return False
    if "objects_from" in exp:
        k = int(exp.get("count", 1))
        if len(objs) != k or len(set(objs)) != k or not set(objs) <= set(exp["objects_from"]):
            return False
    anchor = got.get("anchor")
    if "anchor_any" in exp:
        if anchor not in exp["anchor_any"]:
            return False
    elif exp.get("anchor") != anchor:
        return False
    if exp.get("pose") is not None or got.get("pose") is not None:
        a, b = exp.get("pose"), got.get("pose")
        # to half a millimetre and a thousandth of a radian, as labels write them ("1.5708" for a quarter turn)
        if a is None or b is None or any(abs(x - y) > tol for x, y, tol in zip(a, b, (5e-4, 5e-4, 1e-3))):
            return False
    return True


def _merged_relations(goals: list[dict]) -> list[dict]:
    """``goals`` with the relation goals of one direction, one anchor and the same parameters joined into one
    ("the cup behind the bowl" and "the mug behind the bowl" as "the cup and the mug behind the bowl"): a
    relation holds of each of its objects apart, so the two forms ask for the same thing."""
    out: list[dict] = []
    at: dict[tuple, int] = {}
    for g in goals:
        if g.get("pattern") not in _INVERSE or "anchor" not in g or "objects" not in g:
            out.append(g)
            continue
        key = (g["pattern"], g["anchor"], *(json.dumps(g.get(k)) for k in PARAMS))
        if key in at:
            k = at[key]
            out[k] = {**out[k], "objects": list(dict.fromkeys([*out[k]["objects"], *g["objects"]]))}
        else:
            at[key] = len(out)
            out.append(g)
    return out


def goals_match(expected: dict, got: GoalSpec | dict) -> bool:
    """Whether ``got`` equals the expected goals under the rules above."""
    data = to_dict(got) if isinstance(got, GoalSpec) else got
    if "any_of" in expected:
        return any(goals_match(alt, data) for alt in expected["any_of"])
    exp_goals, got_goals = list(expected.get("goals", [])), list(data.get("goals", []))
    if "disjoint" not in expected:  # (its pairs are positions in the list as written)
        exp_goals, got_goals = _merged_relations(exp_goals), _merged_relations(got_goals)
    if len(exp_goals) != len(got_goals):
        return False
    ordered = _ordered_patterns()
    disjoint = [tuple(p) for p in expected.get("disjoint", [])]
    for perm in itertools.permutations(range(len(got_goals))):
        if all(_goal_ok(e, got_goals[j], ordered) for e, j in zip(exp_goals, perm)):
            if all(not set(got_goals[perm[a]]["objects"]) & set(got_goals[perm[b]]["objects"]) for a, b in disjoint):
                return True
    return False


def evaluate(
    cases: list[Case],
    parse_fn: Callable[[SceneSpec, str], GoalSpec],
    *,
    progress: Callable[[int, int], None] | None = None,
) -> EvalReport:
    """Run ``parse_fn`` on every case and score it (wall time per case in s)."""
    report = EvalReport()
    for k, case in enumerate(cases):
        t0 = time.perf_counter()
        got, err = None, None
        try:
            got = to_dict(parse_fn(case.scene, case.instruction))
        except InputError as exc:
            err = str(exc)
        dt = time.perf_counter() - t0
        if case.refuse is not None:
            want = case.refuse if isinstance(case.refuse, str) else ""
            ok = err is not None and want.lower() in err.lower()
        else:
            ok = got is not None and goals_match(case.expect or {}, got)
        report.results.append(CaseResult(case, ok, got, err, dt))
        if progress is not None:
            progress(k + 1, len(cases))
    return report
