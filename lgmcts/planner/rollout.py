"""The default rollout policy: random sequential placements that clear
the way when they must.

:func:`default_step` picks one action (commit an object where it stands,
place one directly, or move the obstacle that blocks the most placements);
:func:`rollout` chains such steps from a search state. Both the tree search
(its first expansion at a node, and its simulations) and the greedy sampler
use them.
"""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import numpy as np

from ..formats import Action
from .base import Rollout, Transition
from .placement import fixed_obstacles, place_fixed
from .problem import Problem, SearchState
from .step import attempt, clear_way, probe, stay

if TYPE_CHECKING:
    from .search import SearchOptions

__all__ = ["BlockMemo", "default_step", "rollout"]


class BlockMemo:
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


def default_step(problem: Problem, ss: SearchState, ready: list[int], rng: np.random.Generator, opts: SearchOptions,
                 memo: BlockMemo | None = None) -> tuple[int, Transition[SearchState, Action] | None]:
    """One default-policy step: commit an object where it stands if one can
    (a free step); else place one of the ready objects (in random order)
    whose prior has a free pose; else move the obstacle that blocks the most
    of their placements (:func:`_blocking_order`, up to :data:`CLEAR_TRIES` of them
    while none can move); else clear the way for a
    random ready object as the simulation step does. ``memo`` carries what
    earlier steps of the same rollout learnt (:class:`BlockMemo`)."""
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
    ranked = _blocking_order(problem, ss, blocks, rng, memo.last if memo is not None else -1)
    for o, b in ranked[:CLEAR_TRIES]:
        tr = clear_way(problem, ss, b, rng, opts.step, o)
        if tr is not None:
            return o, tr
    return order[0], attempt(problem, ss, order[0], rng, opts.step, placed_anchors=False)


#: How many obstacles, best first, a step tries to move before it falls back
#: to the simulation step for a random object.
CLEAR_TRIES = 64


def _blocking_order(problem: Problem, ss: SearchState, blocks: dict[int, tuple[int, ...]],
                    rng: np.random.Generator, last: int = -1) -> list[tuple[int, int]]:
    """Obstacles whose move frees the most goal placements, best first, each
    as (an object it blocks, the obstacle).

    Scored by the objects it alone blocks, then by all it blocks; objects a
    goal has already placed are left alone, and ties are broken at random.
    The object given is one that the obstacle alone blocks when there is one
    (its placement is freed by the move).
    """
    sole: dict[int, int] = {}
    total: dict[int, int] = {}
    first: dict[int, int] = {}
    only: dict[int, int] = {}
    for o, bs in blocks.items():
        for b in bs:
            if b == o or ss.committed(problem, b):
                continue
            total[b] = total.get(b, 0) + 1
            sole[b] = sole.get(b, 0) + (len(bs) == 1)
            first.setdefault(b, o)
            if len(bs) == 1:
                only.setdefault(b, o)
    if not total:
        return []
    if len(total) > 1:
        # The object just moved is not moved straight back out of the way.
        total.pop(last, None)
    cands = sorted(total)
    tie = rng.permutation(len(cands))
    ranked = sorted(range(len(cands)), key=lambda j: (-sole[cands[j]], -total[cands[j]], tie[j]))
    return [(only.get(cands[j], first[cands[j]]), cands[j]) for j in ranked]


def rollout(problem: Problem, ss: SearchState, rng: np.random.Generator, opts: SearchOptions,
            depth: int) -> Rollout[SearchState, Action]:
    """Random sequential placements from ``ss``, at most ``depth`` steps
    (see :class:`~lgmcts.planner.base.Rollout` for what it returns)."""
    actions: list[Action] = []
    trace: list[SearchState] = []
    steps = 0
    memo = BlockMemo(problem, opts.step.clearance) if opts.step.obstacles == "all" else None
    for _ in range(depth):
        if ss.done(problem):
            return Rollout(1.0, actions, steps, trace)
        ready = ss.ready(problem)
        if not ready:
            break
        steps += 1
        _, tr = default_step(problem, ss, ready, rng, opts, memo)
        if tr is None:
            break
        if memo is not None:
            memo.moved(tr.action)
        ss = tr.state
        if tr.action is not None:
            actions.append(tr.action)
            trace.append(ss)
    if ss.done(problem):
        return Rollout(1.0, actions, steps, trace)
    return Rollout(ss.reward(problem), None, steps, trace)
