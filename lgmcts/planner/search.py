"""Search loops: Monte-Carlo tree search (paper, "MCTS for TAMP") and the
greedy sequential sampler, both over the same simulation step
(:mod:`.step`) and default rollout policy (:mod:`.rollout`)."""

from __future__ import annotations

import logging
import math
import time
from dataclasses import dataclass, field
from typing import Callable

import numpy as np

from ..formats import Action, PlanSpec
from ..validate import check
from .selection import select_child
from .rollout import default_step, rollout
from .step import Problem, SearchState, StepOptions, attempt, stay
from .tree import Node

__all__ = ["SearchOptions", "SearchResult", "mcts", "greedy", "valid_plan", "validated"]

log = logging.getLogger("lgmcts.planner")


@dataclass(frozen=True)
class SearchOptions:
    """Options of the search loops.

    Attributes
    ----------
    max_iter : expansion budget (each expansion simulates one step).
    time_limit : wall-clock budget in seconds, or ``None``. With a time
        limit the result may depend on machine speed; ``max_iter`` alone is
        deterministic for a seed.
    branching : K, the expansion attempts per object at each node.
    c_ucb : exploration constant of the UCB rule (rewards lie in [0, 1]).
    widening : progressive widening exponent alpha: a node visited n times
        may have tried ``ceil((n + 1) ** alpha)`` expansions before the
        search descends into its children; 1.0 gives the plain "expand every
        action first" rule.
    max_depth : deepest node expanded; ``None`` for ``3 n + 8`` with n the
        number of objects.
    rollout : after each expansion, run a random rollout with the same step
        (as greedy does) and back up its reward; a rollout that reaches every
        goal ends the search. ``False`` gives the paper's one-step simulation.
    anytime : keep searching after the first solution, within the budget,
        for one with fewer actions.
    polish : drop the moves a found plan does not need (see
        :mod:`lgmcts.planner.polish`); applied by every method.
    direct_tries : in rollouts, how many random ready objects are tried for a
        placement that needs no obstacle moved before one clears its way.
    step : options of the simulation step.
    """

    max_iter: int = 10_000
    time_limit: float | None = None
    branching: int = 4
    c_ucb: float = 0.5
    widening: float = 0.5
    rollout: bool = True
    max_depth: int | None = None
    anytime: bool = False
    polish: bool = True
    direct_tries: int = 64
    step: StepOptions = field(default_factory=StepOptions)


@dataclass(frozen=True)
class SearchResult:
    """What a search returns: the plan's actions and statistics."""

    solved: bool
    actions: tuple[Action, ...]
    iterations: int
    nodes: int
    time_s: float
    reason: str = ""
    rejected: int = 0
    solutions: int = 0
    #: Actions of the found plan before ``accept`` rewrote it (0 when unsolved).
    found: int = 0


def valid_plan(problem: Problem, actions: list[Action]) -> bool:
    """Whether ``actions`` meet the acceptance rules for ``problem`` (a replay by the validator)."""
    plan = PlanSpec(solved=True, actions=actions, goals=problem.spec)
    return check(problem.scene, problem.spec, plan).valid


#: What a search does with a plan that reaches every goal in its own model:
#: returns the plan to keep (the same, or a rewrite of it) once the validator
#: accepts it, or ``None`` to reject it and search on. The third argument
#: holds the search's world states along the plan (the initial one, then the
#: one after each action), or ``None``.
Accept = Callable[[Problem, list[Action], "list | None"], "list[Action] | None"]


def validated(problem: Problem, actions: list[Action], worlds: list | None = None) -> list[Action] | None:
    """The default :data:`Accept`: ``actions`` themselves when the validator accepts them."""
    return list(actions) if valid_plan(problem, actions) else None


def _expand(problem: Problem, node: Node, rng: np.random.Generator, opts: SearchOptions) -> Node | None:
    """Try one untried (object, sample) pair at ``node``; return the new child or ``None``."""
    ready = node.state.ready(problem)
    open_ = [o for o in ready if node.attempts.get(o, 0) < opts.branching]
    if not open_:
        return None
    if not node.attempts:
        # The first child follows the default policy (a free or direct move when
        # there is one), so the tree's first path is as good as a rollout's.
        o, tr = default_step(problem, node.state, open_, rng, opts)
        node.attempts[o] = 1
    else:
        fewest = min(node.attempts.get(o, 0) for o in open_)
        pool = [o for o in open_ if node.attempts.get(o, 0) == fewest]
        o = pool[int(rng.integers(len(pool)))]
        first = node.attempts.get(o, 0) == 0
        node.attempts[o] = node.attempts.get(o, 0) + 1
        tr = stay(problem, node.state, o, rng) if first else None
        if tr is None:
            tr = attempt(problem, node.state, o, rng, opts.step)
    if tr is None:
        return None
    child = Node(
        state=tr.state,
        parent=node,
        action=tr.action,
        depth=node.depth + 1,
        n_actions=node.n_actions + (tr.action is not None),
        reward=tr.state.reward(problem),
    )
    node.children.append(child)
    return child


def _fully_expanded(problem: Problem, node: Node, opts: SearchOptions) -> bool:
    return all(node.attempts.get(o, 0) >= opts.branching for o in node.state.ready(problem))


def _descend(problem: Problem, node: Node, opts: SearchOptions) -> bool:
    """Whether selection should go below ``node`` rather than expand it now."""
    if not any(not c.dead for c in node.children):
        return False
    if _fully_expanded(problem, node, opts):
        return True
    tried = sum(node.attempts.values())
    return tried >= math.ceil((node.visits + 1) ** opts.widening)


def _select(problem: Problem, root: Node, rng: np.random.Generator, opts: SearchOptions) -> Node:
    """Selection: descend from ``root`` by UCB through nodes that should not be expanded now."""
    node = root
    while not node.dead and _descend(problem, node, opts):
        live = [c for c in node.children if not c.dead]
        if not live:
            break
        k = select_child(
            np.array([c.value for c in live]), np.array([c.visits for c in live]), node.visits, opts.c_ucb, rng
        )
        node = live[k]
    return node


def _simulate(problem: Problem, child: Node, rng: np.random.Generator, opts: SearchOptions,
              max_depth: int) -> tuple[float, list[Action] | None, list, int]:
    """Simulation: the value of a new child (its reward, or a default-policy
    rollout's), the rollout's actions when it reached every goal, the world
    after each of them, and the rollout's length."""
    if not opts.rollout:
        return child.reward, None, [], 0
    value, tail, steps, tail_worlds = rollout(problem, child.state, rng, opts, max_depth - child.depth)
    return value, tail, tail_worlds, steps


def _backup(node: Node | None, reward: float) -> None:
    """Back-up: add ``reward`` to the statistics of ``node`` and its ancestors."""
    while node is not None:
        node.visits += 1
        node.value += reward
        node = node.parent


def _mark_dead(node: Node | None) -> None:
    while node is not None and not node.dead:
        if node.children and not all(c.dead for c in node.children):
            return
        node.dead = True
        node = node.parent


@dataclass
class Incumbent:
    """The best the search has found so far.

    ``plan`` is the shortest accepted plan (``None`` until one is found) and
    ``found`` its length before ``accept`` rewrote it; ``partial`` ranks the
    best node by (reward, fewer actions) for an unsolved search's answer.
    """

    partial: tuple[float, int, Node]
    plan: list[Action] | None = None
    found: int = 0
    solutions: int = 0
    rejected: int = 0

    def offer_node(self, node: Node) -> None:
        if (node.reward, -node.n_actions) > self.partial[:2]:
            self.partial = (node.reward, -node.n_actions, node)

    def improves(self, kept: list[Action]) -> bool:
        return self.plan is None or len(kept) < len(self.plan)

    def record(self, kept: list[Action], found: int) -> None:
        self.plan, self.found = kept, found


def mcts(problem: Problem, rng: np.random.Generator, opts: SearchOptions = SearchOptions(),
         accept: Accept = validated) -> SearchResult:
    """Monte-Carlo tree search for a plan reaching every goal (as ``accept`` returns it).

    Each iteration runs four phases: select a node (:func:`_select`),
    expand one child there (:func:`_expand`), simulate from it
    (:func:`_simulate`, a default-policy rollout) and back up the value
    (:func:`_backup`). Accepted plans go to the :class:`Incumbent`.
    """
    t0 = time.perf_counter()
    deadline = None if opts.time_limit is None else t0 + opts.time_limit
    max_depth = opts.max_depth if opts.max_depth is not None else 3 * problem.scene.n + 8
    root = Node(problem.root())
    root.reward = root.state.reward(problem)
    inc = Incumbent(partial=(root.reward, 0, root))
    nodes, it, rollout_steps, restarts = 1, 0, 0, 0
    if root.state.done(problem) and accept(problem, [], None) is not None:
        return SearchResult(True, (), 0, 1, time.perf_counter() - t0, solutions=1)
    while it < opts.max_iter:
        if deadline is not None and time.perf_counter() > deadline:
            break
        if root.dead:
            # Every branch tried so far is a dead end, but poses are sampled:
            # open the root again for fresh samples while budget remains.
            root.dead = False
            root.attempts.clear()
            restarts += 1
        node = _select(problem, root, rng, opts)
        if node.dead:
            _mark_dead(node)
            continue
        if node.depth >= max_depth or (inc.plan is not None and node.n_actions >= len(inc.plan)):
            node.dead = True
            _mark_dead(node.parent)
            continue
        it += 1
        child = _expand(problem, node, rng, opts)
        if child is None:
            if _fully_expanded(problem, node, opts) and all(c.dead for c in node.children):
                node.dead = True
                _mark_dead(node.parent)
            _backup(node, node.reward)
            continue
        nodes += 1
        inc.offer_node(child)
        if child.state.done(problem):
            actions = child.path()
            child.dead = True
            kept = accept(problem, actions, child.worlds())
            if kept is not None:
                inc.solutions += 1
                if inc.improves(kept):
                    inc.record(kept, len(actions))
                    log.info("solution with %d actions after %d iterations", len(kept), it)
                _backup(child, 1.0)
                if not opts.anytime:
                    break
                continue
            inc.rejected += 1
            _mark_dead(child.parent)
            continue
        if log.isEnabledFor(logging.DEBUG) and it % 500 == 0:
            log.debug("iteration %d: %d nodes, best reward %.2f at depth %d", it, nodes, inc.partial[0], inc.partial[2].depth)
        value, tail, tail_worlds, steps = _simulate(problem, child, rng, opts, max_depth)
        rollout_steps += steps
        if tail is not None:
            actions = child.path() + tail
            kept = accept(problem, actions, child.worlds() + tail_worlds)
            if kept is not None and inc.improves(kept):
                inc.solutions += 1
                inc.record(kept, len(actions))
                log.info("rollout solution with %d actions after %d iterations", len(kept), it)
                if not opts.anytime:
                    break
        _backup(child, value)
    elapsed = time.perf_counter() - t0
    best = inc.plan
    if log.isEnabledFor(logging.INFO):
        shown = best if best is not None else inc.partial[2].path()
        log.info(
            "mcts: %d iterations, %d nodes, %d rollout steps, %d root restarts, best partial depth %d (reward %.2f), "
            "%s with %d actions (%d relocations, %d unstacks), %.3f s",
            it, nodes, rollout_steps, restarts, inc.partial[2].depth, inc.partial[0], "solved" if best is not None else "unsolved",
            len(shown), sum(a.purpose == "relocate" for a in shown), sum(a.purpose == "unstack" for a in shown), elapsed,
        )
    if best is not None:
        return SearchResult(True, tuple(best), it, nodes, elapsed, rejected=inc.rejected, solutions=inc.solutions,
                            found=inc.found)
    reason = "time limit reached" if deadline is not None and time.perf_counter() > deadline else "iteration budget exhausted"
    return SearchResult(False, tuple(inc.partial[2].path()), it, nodes, elapsed, reason=reason, rejected=inc.rejected)


def greedy(problem: Problem, rng: np.random.Generator, opts: SearchOptions = SearchOptions(),
           accept: Accept = validated) -> SearchResult:
    """Sequential sampling with the same step and relocation rules, no tree.

    Each rollout places random ready objects one after another; a dead end
    restarts from the initial scene. Every step counts as one iteration.
    """
    t0 = time.perf_counter()
    deadline = None if opts.time_limit is None else t0 + opts.time_limit
    max_depth = opts.max_depth if opts.max_depth is not None else 3 * problem.scene.n + 8
    it, rollouts = 0, 0
    best_partial: tuple[float, list[Action]] = (-1.0, [])
    while it < opts.max_iter:
        if deadline is not None and time.perf_counter() > deadline:
            break
        rollouts += 1
        ss: SearchState = problem.root()
        actions: list[Action] = []
        worlds = [ss.world]
        for _ in range(max_depth):
            if ss.done(problem):
                break
            ready = ss.ready(problem)
            if not ready or it >= opts.max_iter:
                break
            it += 1
            _, tr = default_step(problem, ss, ready, rng, opts)
            if tr is None:
                break
            ss = tr.state
            if tr.action is not None:
                actions.append(tr.action)
                worlds.append(ss.world)
        r = ss.reward(problem)
        if r > best_partial[0]:
            best_partial = (r, actions)
        kept = accept(problem, actions, worlds) if ss.done(problem) else None
        if kept is not None:
            return SearchResult(True, tuple(kept), it, rollouts, time.perf_counter() - t0, solutions=1, found=len(actions))
    return SearchResult(False, tuple(best_partial[1]), it, rollouts, time.perf_counter() - t0, reason="iteration budget exhausted")
