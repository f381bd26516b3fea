"""Search loops: Monte-Carlo tree search (paper, "MCTS for TAMP") and the
greedy sequential sampler, both over the same simulation step."""

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
from .step import (Problem, SearchState, StepOptions, Transition, attempt, clear_way, fixed_obstacles, place_fixed, probe,
                   stay)
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


class _BlockMemo:
    """Within one rollout, what blocks each object with a fixed target, and
    which of them do not stand on their target.

    A blockers entry holds until an object moves into reach of that target
    or away from among its obstacles, so a crowded scene does not test every
    goal pose against every footprint at every step; "not on its target" holds
    until the object itself moves. Skipping a test does not change the
    random stream: fixed targets are drawn without it.
    """

    def __init__(self, problem: Problem, clearance: float) -> None:
        self.problem = problem
        self.clearance = clearance
        self.known: dict[int, tuple[int, ...]] = {}
        #: Objects with a fixed target that do not stand on it (until they move).
        self.unmet: set[int] = set()
        self.last = -1

    def get(self, o: int) -> tuple[int, ...] | None:
        return self.known.get(o)

    def put(self, o: int, blockers: tuple[int, ...]) -> None:
        if o in self.problem.fixed:
            self.known[o] = blockers

    def moved(self, action: Action | None) -> None:
        if action is None:
            return
        sc = self.problem.scene
        m = self.last = sc.index[action.object]
        self.unmet.discard(m)
        if not self.known:
            return
        self.known.pop(m, None)
        if action.on is not None:
            self.known.pop(sc.index[action.on], None)
        x, y = action.to[0], action.to[1]
        for o in list(self.known):
            t = self.problem.fixed[o]
            near = math.hypot(t[0] - x, t[1] - y) <= sc.radii[o] + sc.radii[m] + self.clearance + 1e-9
            if near or m in self.known[o]:
                del self.known[o]


def _step(problem: Problem, ss: SearchState, ready: list[int], rng: np.random.Generator, opts: SearchOptions,
          memo: _BlockMemo | None = None) -> tuple[int, Transition | None]:
    """One default-policy step: commit an object where it stands if one can
    (a free step); else place one of the ready objects (in random order)
    whose prior has a free pose; else move the obstacle that blocks the most
    of their placements (:func:`_most_blocking`); else clear the way for a
    random ready object as the simulation step does. ``memo`` carries what
    earlier steps of the same rollout learnt (:class:`_BlockMemo`)."""
    order = [ready[k] for k in rng.permutation(len(ready))]
    for o in order:
        if memo is not None and o in memo.unmet:
            continue
        tr = stay(problem, ss, o, rng)
        if tr is not None:
            return o, tr
        if memo is not None and o in problem.fixed:
            memo.unmet.add(o)
    blocks: dict[int, tuple[int, ...]] = {}
    tries = order[: opts.direct_tries]
    # Fixed targets not yet known to be blocked: one query for all (with
    # every object an obstacle; "placed" leaves that to the probe).
    fresh = {}
    if opts.step.obstacles == "all":
        fresh = fixed_obstacles(problem, ss, [o for o in tries if memo is None or memo.get(o) is None], opts.step)
    for o in tries:
        known = memo.get(o) if memo is not None else None
        if known is not None:
            blocks[o] = known
            continue
        if o in fresh:
            if not fresh[o]:
                return o, place_fixed(problem, ss, o, rng)
            blocks[o] = fresh[o]
            if memo is not None:
                memo.put(o, fresh[o])
            continue
        tr, blockers = probe(problem, ss, o, rng, opts.step)
        if tr is not None:
            return o, tr
        if blockers:
            blocks[o] = blockers
            if memo is not None:
                memo.put(o, blockers)
    pick = _most_blocking(problem, ss, blocks, rng, memo.last if memo is not None else -1)
    if pick is not None:
        o, b = pick
        tr = clear_way(problem, ss, b, rng, opts.step, o)
        if tr is not None:
            return o, tr
    return order[0], attempt(problem, ss, order[0], rng, opts.step, placed_anchors=False)


def _most_blocking(problem: Problem, ss: SearchState, blocks: dict[int, tuple[int, ...]],
                   rng: np.random.Generator, last: int = -1) -> tuple[int, int] | None:
    """The obstacle whose move frees the most goal placements: (an object it
    blocks, the obstacle), or ``None``.

    Scored by the objects it alone blocks, then by all it blocks; objects a
    goal has already placed are left alone, and ties are broken at random.
    """
    sole: dict[int, int] = {}
    total: dict[int, int] = {}
    first: dict[int, int] = {}
    for o, bs in blocks.items():
        for b in bs:
            if b == o or ss.committed(problem, b):
                continue
            total[b] = total.get(b, 0) + 1
            sole[b] = sole.get(b, 0) + (len(bs) == 1)
            first.setdefault(b, o)
    if not total:
        return None
    if len(total) > 1:
        # The object just moved is not moved straight back out of the way.
        total.pop(last, None)
    best = max((sole[b], total[b]) for b in total)
    ties = sorted(b for b in total if (sole[b], total[b]) == best)
    b = ties[int(rng.integers(len(ties)))]
    return first[b], b


def _rollout(problem: Problem, ss: SearchState, rng: np.random.Generator, opts: SearchOptions,
             depth: int) -> tuple[float, list[Action] | None, int, list]:
    """Random sequential placements from ``ss``: (reward, actions if solved,
    steps, the world after each action)."""
    actions: list[Action] = []
    worlds: list = []
    steps = 0
    memo = _BlockMemo(problem, opts.step.clearance) if opts.step.obstacles == "all" else None
    for _ in range(depth):
        if ss.done(problem):
            return 1.0, actions, steps, worlds
        ready = ss.ready(problem)
        if not ready:
            break
        steps += 1
        _, tr = _step(problem, ss, ready, rng, opts, memo)
        if tr is None:
            break
        if memo is not None:
            memo.moved(tr.action)
        ss = tr.state
        if tr.action is not None:
            actions.append(tr.action)
            worlds.append(ss.world)
    if ss.done(problem):
        return 1.0, actions, steps, worlds
    return ss.reward(problem), None, steps, worlds


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
        o, tr = _step(problem, node.state, open_, rng, opts)
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


def _backprop(node: Node | None, reward: float) -> None:
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


def mcts(problem: Problem, rng: np.random.Generator, opts: SearchOptions = SearchOptions(),
         accept: Accept = validated) -> SearchResult:
    """Monte-Carlo tree search for a plan reaching every goal (as ``accept`` returns it)."""
    t0 = time.perf_counter()
    deadline = None if opts.time_limit is None else t0 + opts.time_limit
    max_depth = opts.max_depth if opts.max_depth is not None else 3 * problem.scene.n + 8
    root = Node(problem.root())
    root.reward = root.state.reward(problem)
    best: list[Action] | None = None
    found = 0
    best_partial: tuple[float, int, Node] = (root.reward, 0, root)
    nodes, rejected, solutions, it, rollout_steps, restarts = 1, 0, 0, 0, 0, 0
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
        node = root
        # Selection: descend through fully expanded nodes by UCB.
        while not node.dead and _descend(problem, node, opts):
            live = [c for c in node.children if not c.dead]
            if not live:
                break
            k = select_child(
                np.array([c.value for c in live]), np.array([c.visits for c in live]), node.visits, opts.c_ucb, rng
            )
            node = live[k]
        if node.dead:
            _mark_dead(node)
            continue
        if node.depth >= max_depth or (best is not None and node.n_actions >= len(best)):
            node.dead = True
            _mark_dead(node.parent)
            continue
        it += 1
        child = _expand(problem, node, rng, opts)
        if child is None:
            if _fully_expanded(problem, node, opts) and all(c.dead for c in node.children):
                node.dead = True
                _mark_dead(node.parent)
            _backprop(node, node.reward)
            continue
        nodes += 1
        if (child.reward, -child.n_actions) > best_partial[:2]:
            best_partial = (child.reward, -child.n_actions, child)
        if child.state.done(problem):
            actions = child.path()
            child.dead = True
            kept = accept(problem, actions, child.worlds())
            if kept is not None:
                solutions += 1
                if best is None or len(kept) < len(best):
                    best, found = kept, len(actions)
                    log.info("solution with %d actions after %d iterations", len(kept), it)
                _backprop(child, 1.0)
                if not opts.anytime:
                    break
                continue
            rejected += 1
            _mark_dead(child.parent)
            continue
        if log.isEnabledFor(logging.DEBUG) and it % 500 == 0:
            log.debug("iteration %d: %d nodes, best reward %.2f at depth %d", it, nodes, best_partial[0], best_partial[2].depth)
        value = child.reward
        if opts.rollout:
            value, tail, steps, tail_worlds = _rollout(problem, child.state, rng, opts, max_depth - child.depth)
            rollout_steps += steps
            if tail is not None:
                actions = child.path() + tail
                kept = accept(problem, actions, child.worlds() + tail_worlds)
                if kept is not None and (best is None or len(kept) < len(best)):
                    solutions += 1
                    best, found = kept, len(actions)
                    log.info("rollout solution with %d actions after %d iterations", len(kept), it)
                    if not opts.anytime:
                        break
        _backprop(child, value)
    elapsed = time.perf_counter() - t0
    if log.isEnabledFor(logging.INFO):
        shown = best if best is not None else best_partial[2].path()
        log.info(
            "mcts: %d iterations, %d nodes, %d rollout steps, %d root restarts, best partial depth %d (reward %.2f), "
            "%s with %d actions (%d relocations, %d unstacks), %.3f s",
            it, nodes, rollout_steps, restarts, best_partial[2].depth, best_partial[0], "solved" if best is not None else "unsolved",
            len(shown), sum(a.purpose == "relocate" for a in shown), sum(a.purpose == "unstack" for a in shown), elapsed,
        )
    if best is not None:
        return SearchResult(True, tuple(best), it, nodes, elapsed, rejected=rejected, solutions=solutions, found=found)
    reason = "time limit reached" if deadline is not None and time.perf_counter() > deadline else "iteration budget exhausted"
    return SearchResult(False, tuple(best_partial[2].path()), it, nodes, elapsed, reason=reason, rejected=rejected)


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
            _, tr = _step(problem, ss, ready, rng, opts)
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
