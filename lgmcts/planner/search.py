"""Search loops: Monte-Carlo tree search (paper, "MCTS for TAMP") and the
greedy sequential sampler.

Both take the problem they search as a :class:`~lgmcts.planner.base.Domain`
(its steps, default policy, rewards and acceptance rule), so they know
nothing of scenes or patterns; :class:`lgmcts.planner.domain.Rearrangement`
is the tabletop domain.
"""

from __future__ import annotations

import logging
import math
import time
from dataclasses import dataclass, field
from typing import Generic, TypeVar

import numpy as np

from .base import Domain
from .placement import StepOptions
from .selection import select_child
from .tree import Node

__all__ = ["SearchOptions", "SearchResult", "greedy", "mcts"]

S = TypeVar("S")
A = TypeVar("A")

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
    max_depth : deepest node expanded; ``None`` for the domain's
        ``depth_limit`` (``3 n + 8`` with n the number of objects).
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
    proof_after : after this many iterations, or ``proof_after_s`` seconds,
        without a plan (whichever comes first), ask the domain once (its
        optional ``impossible()``) whether the goals are provably out of
        reach; a reason it gives ends the search unsolved with that reason.
        ``0`` never asks. The question uses no random numbers, and a proof
        means the search could not have succeeded, so solved plans are the
        same with or without it.
    proof_after_s : see ``proof_after``.
    sequence : for ``lgmcts``, where every goal is a ``pose`` goal of one
        cylinder and all stand on the table, first try the plan of
        :mod:`lgmcts.planner.sequence` (goal order by what blocks what,
        parking spots where blocked in a cycle); the tree search runs only
        when that plan gets stuck or is refused by the validator, and always
        with a robot (``step.reach``).
    dense : for ``lgmcts``, where that plan gets stuck on at most
        :data:`lgmcts.planner.dense.MAX_DISCS` discs, next ask
        :mod:`lgmcts.confinement` for a proof that no plan exists and then
        try the best-first search of :mod:`lgmcts.planner.dense` (free-space
        corners as parking spots) before the tree search; neither draws
        random numbers.
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
    proof_after: int = 20
    proof_after_s: float = 0.25
    sequence: bool = True
    dense: bool = True


@dataclass(frozen=True)
class SearchResult(Generic[A]):
    """What a search returns: the plan's actions and statistics."""

    solved: bool
    actions: tuple[A, ...]
    iterations: int
    nodes: int
    time_s: float
    reason: str = ""
    rejected: int = 0
    solutions: int = 0
    #: Actions of the found plan before ``accept`` rewrote it (0 when unsolved).
    found: int = 0
    #: Whether ``reason`` is the domain's proof that no plan exists.
    proved: bool = False


class _Prover:
    """Asks the domain once, when the iteration or time threshold of the options is passed, why no plan exists."""

    def __init__(self, domain: object, opts: SearchOptions, t0: float) -> None:
        self.ask = getattr(domain, "impossible", None) if opts.proof_after > 0 else None
        self.after, self.at = opts.proof_after, t0 + opts.proof_after_s

    def __call__(self, it: int) -> str | None:
        if self.ask is None or (it < self.after and time.perf_counter() < self.at):
            return None
        ask, self.ask = self.ask, None
        return ask()


def _expand(domain: Domain[S, A], node: Node[S, A], rng: np.random.Generator, opts: SearchOptions) -> Node[S, A] | None:
    """Try one untried (choice, sample) pair at ``node``; return the new child or ``None``."""
    ready = domain.choices(node.state)
    open_ = [o for o in ready if node.attempts.get(o, 0) < opts.branching]
    if not open_:
        return None
    if not node.attempts:
        # The first child follows the default policy (a free or direct move when
        # there is one), so the tree's first path is as good as a rollout's.
        o, tr = domain.default_step(node.state, open_, rng)
        node.attempts[o] = 1
    else:
        fewest = min(node.attempts.get(o, 0) for o in open_)
        pool = [o for o in open_ if node.attempts.get(o, 0) == fewest]
        o = pool[int(rng.integers(len(pool)))]
        first = node.attempts.get(o, 0) == 0
        node.attempts[o] = node.attempts.get(o, 0) + 1
        tr = domain.stay(node.state, o, rng) if first else None
        if tr is None:
            tr = domain.step(node.state, o, rng)
    if tr is None:
        return None
    child = Node(
        state=tr.state,
        parent=node,
        action=tr.action,
        depth=node.depth + 1,
        n_actions=node.n_actions + (tr.action is not None),
        reward=domain.reward(tr.state),
    )
    node.children.append(child)
    return child


def _fully_expanded(domain: Domain[S, A], node: Node[S, A], opts: SearchOptions) -> bool:
    return all(node.attempts.get(o, 0) >= opts.branching for o in domain.choices(node.state))


def _descend(domain: Domain[S, A], node: Node[S, A], opts: SearchOptions) -> bool:
    """Whether selection should go below ``node`` rather than expand it now."""
    if not any(not c.dead for c in node.children):
        return False
    if _fully_expanded(domain, node, opts):
        return True
    tried = sum(node.attempts.values())
    return tried >= math.ceil((node.visits + 1) ** opts.widening)


def _select(domain: Domain[S, A], root: Node[S, A], rng: np.random.Generator, opts: SearchOptions) -> Node[S, A]:
    """Selection: descend from ``root`` by UCB through nodes that should not be expanded now."""
    node = root
    while not node.dead and _descend(domain, node, opts):
        live = [c for c in node.children if not c.dead]
        if not live:
            break
        k = select_child(
            np.array([c.value for c in live]), np.array([c.visits for c in live]), node.visits, opts.c_ucb, rng
        )
        node = live[k]
    return node


def _simulate(domain: Domain[S, A], child: Node[S, A], rng: np.random.Generator, opts: SearchOptions,
              max_depth: int) -> tuple[float, list[A] | None, list[S], int]:
    """Simulation: the value of a new child (its reward, or a default-policy
    rollout's), the rollout's actions when it reached every goal, the state
    after each of them, and the rollout's length."""
    if not opts.rollout:
        return child.reward, None, [], 0
    r = domain.rollout(child.state, rng, max_depth - child.depth)
    return r.value, r.actions, r.trace, r.steps


def _backup(node: Node[S, A] | None, reward: float) -> None:
    """Back-up: add ``reward`` to the statistics of ``node`` and its ancestors."""
    while node is not None:
        node.visits += 1
        node.value += reward
        node = node.parent


def _mark_dead(node: Node[S, A] | None) -> None:
    while node is not None and not node.dead:
        if node.children and not all(c.dead for c in node.children):
            return
        node.dead = True
        node = node.parent


@dataclass
class Incumbent(Generic[S, A]):
    """The best the search has found so far.

    ``plan`` is the shortest accepted plan (``None`` until one is found) and
    ``found`` its length before ``accept`` rewrote it; ``partial`` ranks the
    best node by (reward, fewer actions) for an unsolved search's answer.
    """

    partial: tuple[float, int, Node[S, A]]
    plan: list[A] | None = None
    found: int = 0
    solutions: int = 0
    rejected: int = 0

    def offer_node(self, node: Node[S, A]) -> None:
        if (node.reward, -node.n_actions) > self.partial[:2]:
            self.partial = (node.reward, -node.n_actions, node)

    def improves(self, kept: list[A]) -> bool:
        return self.plan is None or len(kept) < len(self.plan)

    def record(self, kept: list[A], found: int) -> None:
        self.plan, self.found = kept, found


def mcts(domain: Domain[S, A], rng: np.random.Generator, opts: SearchOptions = SearchOptions()) -> SearchResult[A]:
    """Monte-Carlo tree search for a plan reaching every goal (as the domain's ``accept`` returns it).

    Each iteration runs four phases: select a node (:func:`_select`),
    expand one child there (:func:`_expand`), simulate from it
    (:func:`_simulate`, a default-policy rollout) and back up the value
    (:func:`_backup`). Accepted plans go to the :class:`Incumbent`. A pass
    that only prunes a dead or too deep node counts as an iteration too, so
    ``opts.max_iter`` bounds the loop whatever the domain returns.
    """
    t0 = time.perf_counter()
    deadline = None if opts.time_limit is None else t0 + opts.time_limit
    max_depth = opts.max_depth if opts.max_depth is not None else domain.depth_limit
    root: Node[S, A] = Node(domain.root())
    root.reward = domain.reward(root.state)
    inc: Incumbent[S, A] = Incumbent(partial=(root.reward, 0, root))
    nodes, it, rollout_steps, restarts = 1, 0, 0, 0
    prover = _Prover(domain, opts, t0)
    if domain.terminal(root.state) and domain.accept([], None) is not None:
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
        # Every pass counts, the ones that only prune the tree too, so the
        # budget ends the search whatever the domain's steps return.
        it += 1
        node = _select(domain, root, rng, opts)
        if node.dead:
            _mark_dead(node)
            continue
        if node.depth >= max_depth or (inc.plan is not None and node.n_actions >= len(inc.plan)):
            node.dead = True
            _mark_dead(node.parent)
            continue
        why = prover(it) if inc.plan is None else None
        if why is not None:
            return SearchResult(False, tuple(inc.partial[2].path()), it, nodes, time.perf_counter() - t0, reason=why,
                                rejected=inc.rejected, proved=True)
        child = _expand(domain, node, rng, opts)
        if child is None:
            if _fully_expanded(domain, node, opts) and all(c.dead for c in node.children):
                node.dead = True
                _mark_dead(node.parent)
            _backup(node, node.reward)
            continue
        nodes += 1
        inc.offer_node(child)
        if domain.terminal(child.state):
            actions = child.path()
            child.dead = True
            kept = domain.accept(actions, child.trace())
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
            log.debug("iteration %d: %d nodes, best reward %.2f at depth %d", it, nodes, inc.partial[0],
                      inc.partial[2].depth)
        value, tail, tail_trace, steps = _simulate(domain, child, rng, opts, max_depth)
        rollout_steps += steps
        if tail is not None:
            actions = child.path() + tail
            kept = domain.accept(actions, child.trace() + tail_trace)
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
            "%s with %s, %.3f s",
            it, nodes, rollout_steps, restarts, inc.partial[2].depth, inc.partial[0],
            "solved" if best is not None else "unsolved", domain.describe(shown), elapsed,
        )
    if best is not None:
        return SearchResult(True, tuple(best), it, nodes, elapsed, rejected=inc.rejected, solutions=inc.solutions,
                            found=inc.found)
    timed_out = deadline is not None and time.perf_counter() > deadline
    reason = "time limit reached" if timed_out else "iteration budget exhausted"
    return SearchResult(False, tuple(inc.partial[2].path()), it, nodes, elapsed, reason=reason, rejected=inc.rejected)


def greedy(domain: Domain[S, A], rng: np.random.Generator, opts: SearchOptions = SearchOptions()) -> SearchResult[A]:
    """Sequential sampling with the same step and relocation rules, no tree.

    Each rollout places random ready objects one after another; a dead end
    restarts from the initial scene. Every step counts as one iteration, and
    a rollout that takes no step counts as one.
    """
    t0 = time.perf_counter()
    deadline = None if opts.time_limit is None else t0 + opts.time_limit
    max_depth = opts.max_depth if opts.max_depth is not None else domain.depth_limit
    it, rollouts = 0, 0
    best_partial: tuple[float, list[A]] = (-1.0, [])
    prover = _Prover(domain, opts, t0)
    while it < opts.max_iter:
        if deadline is not None and time.perf_counter() > deadline:
            break
        rollouts += 1
        ss = domain.root()
        actions: list[A] = []
        trace = [ss]
        start = it
        for _ in range(max_depth):
            if domain.terminal(ss):
                break
            ready = domain.choices(ss)
            if not ready or it >= opts.max_iter:
                break
            it += 1
            _, tr = domain.default_step(ss, ready, rng)
            if tr is None:
                break
            ss = tr.state
            if tr.action is not None:
                actions.append(tr.action)
                trace.append(ss)
        if it == start:
            # A rollout that took no step (nothing to choose, or nothing to
            # do) still counts, or such rollouts would repeat for ever.
            it += 1
        r = domain.reward(ss)
        if r > best_partial[0]:
            best_partial = (r, actions)
        kept = domain.accept(actions, trace) if domain.terminal(ss) else None
        if kept is not None:
            return SearchResult(True, tuple(kept), it, rollouts, time.perf_counter() - t0, solutions=1,
                                found=len(actions))
        why = prover(it)
        if why is not None:
            return SearchResult(False, tuple(best_partial[1]), it, rollouts, time.perf_counter() - t0, reason=why,
                                proved=True)
    return SearchResult(False, tuple(best_partial[1]), it, rollouts, time.perf_counter() - t0,
                        reason="iteration budget exhausted")
