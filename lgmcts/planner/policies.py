"""Planning methods built from the shared parts: ``lgmcts``, ``greedy`` and ``pmcts``.

* ``lgmcts`` — MCTS over poses sampled from the pattern priors (the paper's
  method).
* ``greedy`` — the same step without a tree: sequential sampling with
  restarts.
* ``pmcts`` — the paper's Pose+MCTS baseline: goal poses are fixed first
  (sampled from the priors among the goal objects alone, blind to the rest of
  the scene), then MCTS only orders the moves to those fixed ``pose`` goals.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import replace
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import InputError
from ..feasibility import precheck
from ..formats import Action, Goal, GoalSpec, PlanSpec, SceneSpec, load_goals, load_scene
from ..patterns import Pattern, registry
from ..patterns.base import BasePattern, fit_json, goal_xy
from ..robot import plan_reach_problems, robot_of
from ..scene import Scene, replay
from ..validate import goal_satisfied
from .dense import MAX_DISCS, budget
from .dense import search as corner_search
from .domain import Accept, Rearrangement, validated
from .polish import polished
from .problem import Problem
from .search import SearchOptions, SearchResult, greedy, mcts
from .sequence import eligible, polish_may_help, sequence_plan

__all__ = ["METHODS", "goal_poses", "plan"]


def goal_poses(problem: Problem, rng: np.random.Generator, opts: SearchOptions) -> GoalSpec | None:
    """Fix a pose for every goal object by sampling the priors among goal objects only.

    Tower goals above their base stay tower goals (their pose follows the
    base). An anchor that no goal moves gets a pose goal too, where the
    arrangement left it, so the move search cannot carry it away as an
    obstacle. Returns ``None`` when no arrangement was found within the budget.
    """
    blind = replace(opts, step=replace(opts.step, obstacles="placed"), max_iter=max(opts.max_iter // 10, 200))
    res = greedy(Rearrangement(problem, blind), rng, blind)
    if not res.solved:
        return None
    final = {a.object: a.to for a in res.actions}
    scene = problem.scene
    goals: list[Goal] = []
    fixed: set[int] = set()
    for g, pattern in zip(problem.spec.goals, problem.patterns):
        if _stacks(pattern):
            goals.append(g)
            fixed.update(g.objects[1:])
    for o in [*problem.targets, *sorted(problem.standing_anchors)]:
        oid = scene.ids[o]
        if oid in fixed:
            continue
        start = scene.initial.poses[o]
        pose = final.get(oid, (float(start[0]), float(start[1]), float(start[2])))
        goals.append(Goal(pattern="pose", objects=[oid], pose=pose))
    return GoalSpec(goals=goals)


def _stacks(pattern: Pattern) -> bool:
    """Whether a pattern stacks its objects (a tower): PMCTS keeps such goals as they are."""
    return not pattern.on_table and not getattr(pattern, "needs_pose", False)


def _accept(opts: SearchOptions) -> Accept:
    """Found plans are polished (:mod:`.polish`) as they are validated, unless ``opts.polish`` is off;
    with a robot (``opts.step.reach``), a plan is accepted only when the robot reaches every pick and place."""
    base = polished if opts.polish else validated
    robot = opts.step.reach
    if robot is None:
        return base

    def within_reach(problem: Problem, actions: list, worlds: list | None) -> list | None:
        out = base(problem, actions, worlds)
        if out is None or plan_reach_problems(problem.scene, out, robot):
            return None
        return out

    return within_reach


#: What a method returns: the search's result and extra statistics for the plan.
Outcome = tuple[SearchResult[Action], dict[str, Any]]


def _sequenced(problem: Problem, opts: SearchOptions) -> Outcome | None:
    """The fast first attempt of :mod:`.sequence` (pose goals on discs), accepted like a found plan; ``None`` when
    it does not apply, gets stuck or is refused."""
    if not opts.sequence or opts.step.reach is not None or not eligible(problem):
        return None  # with a robot, the search's steps keep every pick and place within its reach
    t0 = time.perf_counter()
    actions = sequence_plan(problem)
    if actions is None:
        return None
    # A plan without a parked disc moves each disc once, straight to its goal: polishing has nothing to drop; nor
    # where every parked disc, left in place or sent straight to its goal, would surely overlap another.
    parked = any(a.purpose == "relocate" for a in actions)
    kept = (_accept(opts) if parked and polish_may_help(problem, actions) else validated)(problem, actions, None)
    if kept is None:
        return None
    return SearchResult(True, tuple(kept), 0, 0, time.perf_counter() - t0, solutions=1, found=len(actions)), \
        {"sequenced": True}


def _dense_applies(problem: Problem, opts: SearchOptions) -> bool:
    return opts.sequence and opts.dense and opts.step.reach is None and eligible(problem) \
        and problem.scene.n <= MAX_DISCS


#: Iterations of the tree search before :mod:`.dense` takes over on a few tightly packed discs. Where the tree
#: search plans such a table soon it does so in its first few (TRLB's D = 0.5-0.6 tables it plans: in 1-3
#: iterations, one in 5), and each iteration that finds nothing there costs 10-40 ms (once 10 were run: 0.1-0.4 s
#: before the corner search, which then often plans in less).
DENSE_AFTER = 3


def _left(opts: SearchOptions, t0: float) -> float | None:
    return None if opts.time_limit is None else max(opts.time_limit - (time.perf_counter() - t0), 1e-3)


def _dense_run(problem: Problem, rng: np.random.Generator, opts: SearchOptions) -> Outcome:
    """Where the fast attempt got stuck on a few discs (:func:`_dense_applies`): a proof that no plan exists
    (:mod:`lgmcts.confinement`, unless ``opts.proof_after`` is 0), else :data:`DENSE_AFTER` iterations of the tree
    search, else the best-first search of :mod:`.dense`, else the tree search with the rest of the budget. Nothing
    here but the tree search draws random numbers, so the plan is the same for a seed when no time limit cuts it."""
    t0 = time.perf_counter()
    tree = Rearrangement(problem, opts, accept=_accept(opts))
    why = tree.impossible() if opts.proof_after > 0 else None
    if why is not None:
        return SearchResult(False, (), 0, 0, time.perf_counter() - t0, reason=why, proved=True), {}
    # The proof was asked: the tree search does not ask again.
    opts = replace(opts, proof_after=0)
    quick = min(DENSE_AFTER, opts.max_iter)
    res = mcts(tree, rng, replace(opts, max_iter=quick, time_limit=_left(opts, t0)))
    if res.solved or quick >= opts.max_iter:
        return res, {}
    deadline = None if opts.time_limit is None else t0 + opts.time_limit
    actions, states = corner_search(problem, budget(problem.scene.n), deadline)
    kept = None if actions is None else _accept(opts)(problem, actions, None)
    if kept is not None:
        return SearchResult(True, tuple(kept), res.iterations, res.nodes, time.perf_counter() - t0, solutions=1,
                            found=len(actions or ())), {"dense": True, "corner_states": states}
    rest = replace(opts, max_iter=opts.max_iter - res.iterations, time_limit=_left(opts, t0))
    final = mcts(Rearrangement(problem, rest, accept=_accept(rest)), rng, rest)
    # What was tried: the stats say how many table states the corner search expanded without a plan.
    return replace(final, iterations=final.iterations + res.iterations, time_s=time.perf_counter() - t0), \
        {"corner_states": states}


def _run_lgmcts(problem: Problem, rng: np.random.Generator, opts: SearchOptions) -> Outcome:
    first = _sequenced(problem, opts)
    if first is not None:
        return first
    if _dense_applies(problem, opts):
        return _dense_run(problem, rng, opts)
    return mcts(Rearrangement(problem, opts, accept=_accept(opts)), rng, opts), {}


def _run_greedy(problem: Problem, rng: np.random.Generator, opts: SearchOptions) -> Outcome:
    return greedy(Rearrangement(problem, opts, accept=_accept(opts)), rng, opts), {}


def _run_pmcts(problem: Problem, rng: np.random.Generator, opts: SearchOptions) -> Outcome:
    if all(getattr(p, "needs_pose", False) or _stacks(p) for p in problem.patterns):
        return mcts(Rearrangement(problem, opts, accept=_accept(opts)), rng, opts), {}
    t0 = time.perf_counter()
    poses = goal_poses(problem, rng, opts)
    if poses is None:
        return SearchResult(False, (), 0, 0, time.perf_counter() - t0, reason="no goal arrangement found"), {}
    fixed = Problem.build(problem.scene, poses)
    # Searched for the fixed poses; accepted (and polished) for the goals themselves.
    res = mcts(Rearrangement(fixed, opts, accept=_accept(opts), judge=problem), rng, opts)
    extra = {"pose_goals": poses.model_dump(mode="json", exclude_none=True)}
    return replace(res, time_s=time.perf_counter() - t0), extra


METHODS: dict[str, Callable[[Problem, np.random.Generator, SearchOptions], Outcome]] = {
    "lgmcts": _run_lgmcts,
    "greedy": _run_greedy,
    "pmcts": _run_pmcts,
}


def plan(
    scene: SceneSpec | dict | str | Path,
    goals: GoalSpec | dict | list | str | Path,
    *,
    method: str = "lgmcts",
    seed: int = 0,
    max_iter: int = 10_000,
    time_limit: float | None = None,
    anytime: bool = False,
    options: SearchOptions | None = None,
    robot: str | None = None,
) -> PlanSpec:
    """Plan pick-and-place actions that bring ``scene`` to a state meeting ``goals``.

    Parameters
    ----------
    scene, goals : models, dicts or JSON file paths (see ``docs/formats.md``).
    method : ``"lgmcts"``, ``"greedy"`` or ``"pmcts"``.
    seed : seed of the random generator; the same seed gives the same plan
        when no ``time_limit`` cuts the search.
    max_iter : iteration budget (passes of the tree search, each at most one
        expansion; steps for greedy, a rollout without a step counting one).
    time_limit : optional wall-clock budget (s).
    anytime : keep searching within the budget for a plan with fewer actions.
    options : full :class:`SearchOptions`; ``max_iter``, ``time_limit`` and
        ``anytime`` override its fields.
    robot : a robot's name (``"ur5e"``, see :mod:`lgmcts.robot`): every pick
        and placement of the plan is then one the robot reaches from above.
        ``None`` (default): no robot, the plan is the same as before.

    Returns
    -------
    PlanSpec
        ``solved`` false with the best partial plan when the budget ran out.
        Raises :class:`InputError` only for bad input.
    """
    if method not in METHODS:
        raise InputError(f"unknown method '{method}' (known: {', '.join(METHODS)})")
    if max_iter < 1:
        raise InputError("max_iter must be at least 1")
    if seed < 0:
        raise InputError("seed must be a non-negative integer")
    if time_limit is not None and not (math.isfinite(time_limit) and time_limit > 0):
        raise InputError("time_limit must be a positive finite number of seconds")
    spec = scene if isinstance(scene, SceneSpec) else load_scene(scene if isinstance(scene, dict) else Path(scene))
    gspec = goals if isinstance(goals, GoalSpec) else load_goals(
        {"goals": goals} if isinstance(goals, list) else goals if isinstance(goals, dict) else Path(goals)
    )
    sc = Scene.from_spec(spec)
    gspec.check_against(spec)
    precheck(sc, gspec)
    problem = Problem.build(sc, gspec)
    opts = options or SearchOptions()
    opts = replace(opts, max_iter=max_iter, time_limit=time_limit, anytime=anytime or opts.anytime)
    if robot is not None:
        opts = replace(opts, step=replace(opts.step, reach=robot_of(robot)))
    rng = np.random.default_rng(seed)
    t0 = time.perf_counter()
    res, extra = METHODS[method](problem, rng, opts)
    found = res.found or len(res.actions)
    res = replace(res, time_s=time.perf_counter() - t0)
    stats: dict[str, Any] = {
        "method": method,
        "seed": seed,
        "iterations": res.iterations,
        "nodes": res.nodes,
        "time_s": round(res.time_s, 6),
        "actions": len(res.actions),
        "relocations": sum(a.purpose != "goal" for a in res.actions),
        "max_iter": max_iter,
    }
    if robot is not None:
        stats["robot"] = robot
        rb = opts.step.reach
        w = sc.initial
        tops = np.array([w.base_z(k) + float(sc.heights[k]) for k in range(sc.n)])
        far = ~rb.reachable(sc.bounds, w.poses[:, :2], tops)
        if far.any():
            # Objects the arm cannot pick where they stand: a goal that must move one is not solved.
            stats["out_of_reach"] = [sc.ids[k] for k in np.flatnonzero(far)]
    if res.solved and found != len(res.actions):
        stats["actions_before_polish"] = found
    if time_limit is not None:
        stats["time_limit"] = time_limit
    if res.solutions > 1:
        stats["solutions"] = res.solutions
    if not res.solved:
        stats["reason"] = res.reason
        if res.proved:
            stats["infeasible"] = True
        else:
            # What was tried, in the same line: the budget spent and how far the best partial plan got.
            final = replay(sc, list(res.actions))[-1]
            met = sum(goal_satisfied(g, sc, final.poses, final.on) is None for g in gspec.goals)
            corner = extra.get("corner_states")
            tried = f", and {corner} table states of the corner search" if corner else ""
            stats["reason"] = (f"{res.reason} after {res.iterations} iterations and {res.nodes} search nodes{tried}; "
                               f"the best partial plan ({len(res.actions)} actions) meets {met} of {len(gspec.goals)} "
                               "goals; no proof was found that no plan exists")
    stats.update(extra)
    return PlanSpec(solved=res.solved, actions=list(res.actions), goals=gspec, stats=stats,
                    fits=final_fits(sc, gspec, res.actions))


def final_fits(scene: Scene, goals: GoalSpec, actions: Sequence[Action]) -> list[dict | None]:
    """Each goal's pattern parameters fitted to the state ``actions`` end in
    (JSON-ready; ``None`` for patterns without a fit): what a plan carries so
    that viewers draw the arrangement without fitting it again."""
    reg = registry()
    if all(type(reg[g.pattern]).fit is BasePattern.fit for g in goals.goals):
        return [None] * len(goals.goals)  # patterns without a fit (pose goals): no replay needed
    final = replay(scene, actions)[-1]
    return [fit_json(reg[g.pattern].fit(goal_xy(g, scene, final.poses))) for g in goals.goals]
