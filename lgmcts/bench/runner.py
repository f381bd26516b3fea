"""The benchmark runner: one function per task, run serially, on local cores
or as Ray tasks, with results appended to a JSONL file that a later run resumes.

Per task (:func:`run_task`): parse the instruction (or take the ground-truth
goals with ``parser="gt"``), plan, judge the plan with
:func:`lgmcts.validate.check` against the *ground-truth* goals, execute it in
MuJoCo (:func:`lgmcts.sim.execute_plan`) and judge the final state against the
ground-truth goals again. The record says where a failed task failed first.

Plug-in planners: ``method="package.module:function"`` calls
``function(scene, goals, seed, max_iter)`` with a
:class:`~lgmcts.formats.SceneSpec`, a :class:`~lgmcts.formats.GoalSpec` and
two ints; it returns a :class:`~lgmcts.formats.PlanSpec` or a dict in the
plan format (``{"solved": ..., "actions": [...]}``).
"""

from __future__ import annotations

import importlib
import json
import math
import os
import signal
import sys
import time
from collections.abc import Callable, Iterable, Iterator
from dataclasses import asdict, dataclass
from multiprocessing import get_context
from pathlib import Path
from typing import Any, cast

from ..errors import InputError
from ..formats import RELATIONS, GoalSpec, PlanSpec, parse_goals, parse_plan, parse_scene, to_dict
from .tasks import Task

__all__ = [
    "CAUSES",
    "RESULTS_FILE",
    "RunOptions",
    "canonical_goals",
    "load_results",
    "resolve_method",
    "run_suite",
    "run_task",
]

RESULTS_FILE = "results.jsonl"
CONFIG_FILE = "run.json"
BUILTIN_METHODS = ("lgmcts", "greedy", "pmcts")
#: Methods that plan from the instruction itself with a language model (no goals parsed).
LLM_METHODS = ("lfsp",)
PARSERS = ("rules", "llm", "gt")

#: Failure causes, in the order a task meets them.
CAUSES: tuple[str, ...] = (
    "parse refused",
    "parser error",
    "parse wrong",
    "planner error",
    "plan not found",
    "plan invalid",
    "executor error",
    "execution failed",
)


@dataclass(frozen=True)
class RunOptions:
    """How each task is run.

    Attributes
    ----------
    method : ``lgmcts``, ``greedy``, ``pmcts``, ``lfsp`` (the language model proposes the
        poses itself from the instruction; ``parser`` is not used) or ``module:function``
        (a plug-in planner).
    parser : ``rules`` (offline parser), ``llm`` or ``gt`` (the ground-truth goals).
    max_iter : planner iteration budget per task.
    time_limit : optional planner wall-clock budget per task (s).
    execute : run solved plans in physics (SR_ep); off gives SR_p only.
    llm_model, llm_base_url : passed to the LLM parser and to ``lfsp``.
    """

    method: str = "lgmcts"
    parser: str = "rules"
    max_iter: int = 10_000
    time_limit: float | None = None
    execute: bool = True
    llm_model: str | None = None
    llm_base_url: str | None = None

    def check(self) -> None:
        """Raise :class:`InputError` for options no task could run with."""
        if self.parser not in PARSERS:
            raise InputError(f"unknown parser '{self.parser}' (known: {', '.join(PARSERS)})")
        if self.max_iter < 1:
            raise InputError("--max-iter must be at least 1")
        if self.time_limit is not None and not (math.isfinite(self.time_limit) and self.time_limit > 0):
            raise InputError("--time-limit must be a positive finite number of seconds")
        resolve_method(self.method)
        if self.method in LLM_METHODS and not (self.llm_model or os.environ.get("LGMCTS_LLM_MODEL")):
            raise InputError(f"--method {self.method} needs --llm-model NAME (or LGMCTS_LLM_MODEL)")


def resolve_method(method: str) -> Callable[..., Any] | str:
    """A built-in method name, or the plug-in function ``module:function`` names.

    The current directory is importable, so a planner in ``./my_planner.py``
    is ``my_planner:plan``.
    """
    if method in BUILTIN_METHODS or method in LLM_METHODS:
        return method
    if ":" not in method:
        known = ", ".join(BUILTIN_METHODS + LLM_METHODS)
        raise InputError(f"unknown method '{method}' (use {known} or module:function)")
    mod_name, _, fn_name = method.partition(":")
    if not mod_name or not fn_name:
        raise InputError(f"method '{method}' must be module:function")
    if os.getcwd() not in sys.path:
        sys.path.append(os.getcwd())
    try:
        mod = importlib.import_module(mod_name)
    except ImportError as exc:
        raise InputError(f"cannot import planner module '{mod_name}': {exc}") from None
    fn = getattr(mod, fn_name, None)
    if not callable(fn):
        raise InputError(f"module '{mod_name}' has no function '{fn_name}'")
    return fn


def canonical_goals(spec: GoalSpec) -> frozenset:
    """Goals as a set of atoms, for comparing a parse with the ground truth.

    Shape patterns compare as object sets, towers in order, relations one
    (relation, object, anchor) atom per object, so ``left [3, 4] of 5`` equals
    ``left [3] of 5`` plus ``left [4] of 5``.
    """
    atoms: set = set()
    for g in spec.goals:
        if g.pattern in RELATIONS:
            atoms.update((g.pattern, o, g.anchor) for o in g.objects)
        elif g.pattern == "tower":
            atoms.add(("tower", tuple(g.objects)))
        elif g.pattern == "pose":
            atoms.add(("pose", g.objects[0], tuple(round(v, 4) for v in g.pose or ())))
        else:
            atoms.add((g.pattern, frozenset(g.objects)))
    return frozenset(atoms)


def _first(reasons: Iterable[str]) -> str:
    for r in reasons:
        return str(r)
    return ""


def run_task(task: dict | Task, options: RunOptions) -> dict[str, Any]:
    """Run one task end to end; never raises for a failing task.

    Returns the JSON-ready record written to the results file.
    """
    t_all = time.perf_counter()
    t = task if isinstance(task, Task) else Task.from_dict(task)
    rec: dict[str, Any] = {
        "id": t.id,
        "suite": t.suite,
        "category": t.category,
        "seed": t.seed,
        "instruction": t.instruction,
        "instructions": t.instructions,
        "method": options.method,
        "parser": options.parser,
    }
    scene = parse_scene(t.scene)
    gt = parse_goals(t.goals)
    cause: str | None = None
    detail = ""

    # 1. Language.
    t0 = time.perf_counter()
    goals: GoalSpec | None = None
    parse_correct: bool | None = None
    lfsp = options.method in LLM_METHODS
    if lfsp:
        rec["parser"] = None  # the model reads the instruction itself
    elif options.parser == "gt":
        goals = gt
    else:
        try:
            from ..language import parse

            goals = parse(
                scene,
                t.instruction,
                parser=options.parser,
                llm_model=options.llm_model,
                llm_base_url=options.llm_base_url,
            )
            parse_correct = canonical_goals(goals) == canonical_goals(gt)
        except InputError as exc:
            cause, detail = "parse refused", str(exc)
            parse_correct = False
        except Exception as exc:  # a crash of the parser is a result, not the end of the run
            cause, detail = "parser error", f"{type(exc).__name__}: {exc}"
            parse_correct = False
    rec["parse"] = {
        "correct": parse_correct,
        "goals": to_dict(goals) if goals is not None else None,
        "time_s": round(time.perf_counter() - t0, 6),
    }

    # 2. Planning, judged against the ground truth.
    plan: PlanSpec | None = None
    rec["plan"] = None
    rec["planning"] = {
        "solved": False,
        "valid": False,
        "reasons": [],
        "time_s": None,
        "iterations": None,
        "actions": None,
    }
    if goals is not None or lfsp:
        t0 = time.perf_counter()
        try:
            gs = cast(GoalSpec, goals)  # without lfsp the goals are there (the condition above)
            plan = _lfsp(scene, t.instruction, options) if lfsp else _plan(scene, gs, t.seed, options)
        except Exception as exc:
            cause, detail = "planner error", f"{type(exc).__name__}: {exc}"
        wall = time.perf_counter() - t0
        if plan is not None:
            from ..validate import check

            verdict = check(scene, gt, plan)
            st = plan.stats or {}
            rec["plan"] = to_dict(plan)
            rec["planning"] = {
                "solved": bool(plan.solved),
                "valid": bool(plan.solved and verdict.valid),
                "reasons": list(verdict.reasons)[:5],
                "time_s": round(float(st.get("time_s", wall)), 6),
                "wall_s": round(wall, 6),
                "iterations": st.get("iterations"),
                "actions": len(plan.actions),
            }
            if not plan.solved:
                cause, detail = "plan not found", str(st.get("reason", ""))
            elif not verdict.valid:
                cause, detail = "plan invalid", _first(verdict.reasons)
            if cause is not None and parse_correct is False:
                cause = "parse wrong"
    sr_p = bool(rec["planning"]["valid"])

    # 3. Physics.
    rec["execution"] = None
    sr_ep: bool | None = None
    if options.execute:
        sr_ep = False
        if sr_p and plan is not None:
            t0 = time.perf_counter()
            try:
                from ..sim import execute_plan

                ex = execute_plan(scene, plan, gt)
                rec["execution"] = {
                    "success": bool(ex.success),
                    "reasons": list(ex.reasons)[:5],
                    "steps": len(ex.steps),
                    "time_s": round(time.perf_counter() - t0, 6),
                }
                sr_ep = bool(ex.success)
                if not ex.success:
                    cause, detail = "execution failed", _first(ex.reasons)
            except Exception as exc:
                cause, detail = "executor error", f"{type(exc).__name__}: {exc}"
                rec["execution"] = {
                    "success": False,
                    "reasons": [detail],
                    "steps": 0,
                    "time_s": round(time.perf_counter() - t0, 6),
                }
    rec["sr_p"] = sr_p
    rec["sr_ep"] = sr_ep
    rec["cause"] = cause
    rec["detail"] = " ".join(detail.split())[:300]
    rec["total_s"] = round(time.perf_counter() - t_all, 6)
    return rec


def _plan(scene, goals: GoalSpec, seed: int, options: RunOptions) -> PlanSpec:
    m = resolve_method(options.method)
    if isinstance(m, str):
        from ..planner import plan

        return plan(scene, goals, method=m, seed=seed, max_iter=options.max_iter, time_limit=options.time_limit)
    out = m(scene, goals, seed, options.max_iter)
    if isinstance(out, PlanSpec):
        return out
    if isinstance(out, dict):
        return parse_plan(out)
    raise TypeError(f"plug-in planner returned {type(out).__name__}, not a PlanSpec or dict")


def _lfsp(scene, instruction: str, options: RunOptions) -> PlanSpec:
    """The language model's own plan; a refusal or unusable answer is an unsolved plan."""
    from ..language.lfsp import plan_lfsp
    from ..language.llm import LLMOptions

    t0 = time.perf_counter()
    try:
        from ..language import llm_timeout

        timeout = llm_timeout(120.0)
        opts = LLMOptions(model=options.llm_model, base_url=options.llm_base_url, timeout=timeout)
        return plan_lfsp(scene, instruction, options=opts)
    except InputError as exc:
        dt = round(time.perf_counter() - t0, 6)
        return PlanSpec(
            solved=False, actions=[], stats={"method": "lfsp", "reason": str(exc), "iterations": 0, "time_s": dt}
        )


def _safe(task: dict, options: RunOptions) -> dict[str, Any]:
    # Everything a worker returns is a record; a crash outside the stages above
    # (a task that does not load) still becomes one.
    try:
        return run_task(task, options)
    except Exception as exc:
        return {
            "id": task.get("id"),
            "suite": task.get("suite", ""),
            "category": task.get("category", ""),
            "seed": task.get("seed"),
            "method": options.method,
            "parser": options.parser,
            "sr_p": False,
            "sr_ep": False if options.execute else None,
            "cause": "task error",
            "detail": f"{type(exc).__name__}: {exc}"[:300],
            "planning": {},
            "parse": {},
            "execution": None,
        }


# ---------------------------------------------------------------- results file


def load_results(out_dir: str | Path, *, repair: bool = False) -> list[dict[str, Any]]:
    """Records of ``out_dir/results.jsonl``; a torn last line (an interrupted write) is dropped.

    With ``repair``, the file is rewritten without the torn line so appends
    continue cleanly.
    """
    path = Path(out_dir) / RESULTS_FILE
    if not path.exists():
        return []
    records, good_bytes, torn = [], 0, False
    with open(path, "rb") as fh:
        for raw in fh:
            try:
                rec = json.loads(raw)
                if not isinstance(rec, dict) or "id" not in rec or not raw.endswith(b"\n"):
                    raise ValueError
            except ValueError:
                torn = True
                break
            records.append(rec)
            good_bytes += len(raw)
    if torn and repair:
        with open(path, "r+b") as fh:
            fh.truncate(good_bytes)
    return records


def _config(options: RunOptions, source: str) -> dict[str, Any]:
    return {"source": source, **asdict(options)}


def _check_config(out: Path, config: dict[str, Any]) -> None:
    path = out / CONFIG_FILE
    if path.exists():
        try:
            old = json.loads(path.read_text())
        except (OSError, ValueError):
            old = None
        keys = ("source", "method", "parser", "max_iter", "time_limit", "execute")
        if isinstance(old, dict):
            diff = [k for k in keys if old.get(k) != config.get(k)]
            if diff:
                k = diff[0]
                raise InputError(
                    f"{out} holds a run with {k}={old.get(k)!r}, not {config.get(k)!r}; resume with the same "
                    "settings or use another -o"
                )
    path.write_text(json.dumps(config, indent=2) + "\n")


def usable_cpus() -> int:
    """The CPUs this process may run on (its affinity), at least 1: the cap on ``--workers``."""
    try:
        return max(1, len(os.sched_getaffinity(0)))
    except AttributeError:  # pragma: no cover - not Linux
        return max(1, os.cpu_count() or 1)


def check_workers(workers: int | None, ray_address: str | None = None) -> None:
    """Refuse a worker count below 1, or above the usable CPUs for a run on this machine."""
    if workers is not None and workers < 1:
        raise InputError("--workers must be at least 1")
    cpus = usable_cpus()
    if workers is not None and workers > cpus and ray_address in (None, "local"):
        # Each worker is a process with its own planner and simulator: more
        # than the cores only multiplies memory.
        raise InputError(f"--workers {workers} is more than the {cpus} CPUs this machine lets the run use")


def run_suite(
    tasks: list[Task],
    out_dir: str | Path,
    *,
    options: RunOptions,
    workers: int | None = None,
    ray_address: str | None = None,
    source: str = "",
    show_progress: bool | None = None,
) -> list[dict[str, Any]]:
    """Run ``tasks`` into ``out_dir``, skipping tasks whose record is already there.

    Parameters
    ----------
    tasks : the suite.
    out_dir : folder of ``results.jsonl`` and ``run.json`` (created).
    options : how each task runs.
    workers : local processes (default: every core); 1 runs in this process.
    ray_address : run as Ray tasks instead: ``"local"`` starts a local Ray
        instance (or uses the one already initialised), anything else is
        passed to ``ray.init(address=...)``.
    source : a name for the suite (recorded in ``run.json``; a resumed run
        must have the same).
    show_progress : a progress bar on stderr; default when stderr is a terminal.

    Returns
    -------
    Every record of the run in task order (those resumed included).
    """
    options.check()
    check_workers(workers, ray_address)
    cpus = usable_cpus()
    out = Path(out_dir)
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"cannot create {out}: {exc.strerror}") from None
    _check_config(out, _config(options, source))
    done = {r["id"]: r for r in load_results(out, repair=True)}
    todo = [t for t in tasks if t.id not in done]
    n_workers = workers or cpus
    if show_progress is None:
        show_progress = sys.stderr.isatty()
    from tqdm import tqdm

    _interrupt_on_sigterm()
    bar = tqdm(
        total=len(tasks),
        initial=len(tasks) - len(todo),
        desc=f"{options.method}",
        unit="task",
        disable=not show_progress,
        file=sys.stderr,
        dynamic_ncols=True,
    )
    n_ok = sum(bool(r.get("sr_p")) for r in done.values())
    n_run = len(done)
    try:
        with open(out / RESULTS_FILE, "a") as fh:
            if ray_address is not None:
                stream = _ray_map(todo, options, ray_address, workers)
            elif n_workers == 1 or len(todo) <= 1:
                stream = (_safe(t.to_dict(), options) for t in todo)
            else:
                stream = _pool_map(todo, options, n_workers)
            for rec in stream:
                fh.write(json.dumps(rec, separators=(",", ":")) + "\n")
                fh.flush()
                done[rec["id"]] = rec
                n_run += 1
                n_ok += bool(rec.get("sr_p"))
                bar.set_postfix_str(f"SR_p {100 * n_ok / n_run:.1f}%", refresh=False)
                bar.update(1)
    finally:
        bar.close()
    order = {t.id: k for k, t in enumerate(tasks)}
    return sorted((r for r in done.values() if r["id"] in order), key=lambda r: order[r["id"]])


def _interrupt_on_sigterm() -> None:
    """Turn SIGTERM into KeyboardInterrupt so a killed run still stops its workers."""
    import threading

    if threading.current_thread() is not threading.main_thread():
        return
    if signal.getsignal(signal.SIGTERM) in (signal.SIG_DFL, None):

        def _raise(signum: int, frame: Any) -> None:
            raise KeyboardInterrupt

        signal.signal(signal.SIGTERM, _raise)


def _worker_init() -> None:
    # One math thread per worker: the workers already use every core, and
    # oversubscribed BLAS/torch threads make each parse many times slower.
    for var in ("OMP_NUM_THREADS", "MKL_NUM_THREADS", "OPENBLAS_NUM_THREADS"):
        os.environ.setdefault(var, "1")


def _pool_map(tasks: list[Task], options: RunOptions, workers: int) -> Iterator[dict[str, Any]]:
    # Spawned workers: no torch or MuJoCo state is inherited through fork.
    # Tasks go out one at a time, so an interrupted run loses at most the
    # tasks in flight; on any exit the workers are terminated, not awaited.
    ctx = get_context("spawn")
    pool = ctx.Pool(workers, initializer=_worker_init)
    try:
        yield from pool.imap_unordered(_safe_star, [(t.to_dict(), options) for t in tasks], chunksize=1)
        pool.close()
    finally:
        pool.terminate()
        pool.join()


def _safe_star(args: tuple[dict, RunOptions]) -> dict[str, Any]:
    return _safe(*args)


def _reachable(address: str, timeout: float = 5.0) -> None:
    """Fail fast with one line when a ``host:port`` Ray address does not answer.

    Ray itself retries an unreachable cluster for minutes before giving up.
    """
    import socket

    if address in ("local", "auto"):
        return
    hostport = address.split("://", 1)[-1]
    host, _, port = hostport.rpartition(":")
    if not host or not port.isdigit():
        return
    try:
        socket.create_connection((host, int(port)), timeout=timeout).close()
    except OSError as exc:
        raise InputError(f"cannot reach Ray at {address}: {exc.strerror or exc}") from None


def _ray_failure(address: str, exc: BaseException) -> str:
    """One line saying why Ray would not start or connect, with a hint for token authentication."""
    text = " ".join(str(exc).split())
    kind = type(exc).__name__
    line = f"cannot connect to Ray at {address}: {kind}: {text[:300]}"
    if any(w in text.lower() for w in ("auth", "token", "unauthenticated", "permission denied")):
        line += (
            " (the cluster uses token authentication: set RAY_AUTH_TOKEN, or RAY_AUTH_TOKEN_PATH, to its token, "
            "which `ray get-auth-token` prints on the head node; see docs/bench.md)"
        )
    return line


def _ray_map(tasks: list[Task], options: RunOptions, address: str, workers: int | None) -> Iterator[dict[str, Any]]:
    try:
        import ray
    except ImportError:
        raise InputError("--ray needs Ray: pip install 'lgmcts[ray]'") from None
    started = False
    if not ray.is_initialized():
        if address.startswith("ray://"):
            import importlib.util

            if importlib.util.find_spec("grpc") is None:
                raise InputError("--ray ray://... needs Ray's client: pip install 'lgmcts[ray]' (ray[client])")
        _reachable(address)
        try:
            if address == "local":
                ray.init(num_cpus=workers, include_dashboard=False, log_to_driver=False)
            else:
                ray.init(address=address, log_to_driver=False)
        except Exception as exc:  # an unreachable cluster is bad input to the runner
            raise InputError(_ray_failure(address, exc)) from None
        started = True
    try:
        remote = ray.remote(_safe)
        pending = [remote.remote(t.to_dict(), options) for t in tasks]
        while pending:
            finished, pending = ray.wait(pending, num_returns=1)
            for ref in finished:
                yield ray.get(ref)
    finally:
        if started:
            ray.shutdown()
