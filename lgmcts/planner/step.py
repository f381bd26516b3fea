"""The simulation step (paper, Algorithm 1, "Simulation").

:func:`attempt`, given a search state and an object to place, returns one
rearrangement action — the object to its sampled pose from
f = f_prior x f_free, or, when the object is covered or its pose is blocked,
a relocation of one blocker to a free pose outside every remaining goal
region — together with the successor state. :func:`stay` commits an object
where it already stands; :func:`probe` and :func:`clear_way` are the parts
the default rollout policy (:mod:`.rollout`) combines.

The problem and its states live in :mod:`.problem`, candidate poses and
collision tests in :mod:`.placement`, the relocation move in
:mod:`.relocate`; their public names are importable from here too.
"""

from __future__ import annotations

import numpy as np
import shapely

from ..scene import TABLE, State
from .base import Transition
from .placement import (
    CONTACT_AREA,
    StepOptions,
    pickable,
    place,
    reachable,
    required_support,
    sample_poses,
    to_table,
    touching_only,
    wrapped,
)
from .problem import Problem, SearchState, commit
from .relocate import relocate

__all__ = [
    "CONTACT_AREA",
    "Problem",
    "SearchState",
    "StepOptions",
    "Transition",
    "attempt",
    "clear_way",
    "probe",
    "relocate",
    "stay",
    "touching_only",
]


def stay(problem: Problem, ss: SearchState, o: int, rng: np.random.Generator) -> Transition | None:
    """Commit ``o`` where it already is, when that satisfies every prior it is in."""
    world = ss.world
    if required_support(problem, ss, o) != world.on[o]:
        return None
    pose = np.asarray(world.poses[o])
    for k in problem.member[o]:
        if problem.patterns[k].density(ss.ctx(problem, k), o, pose[None])[0] <= 0:
            return None
    return Transition(None, commit(problem, ss, world, o, pose, rng))


def _clear_top(world: State, i: int, rng: np.random.Generator, exclude: int = -2) -> int:
    tops = [k for k in world.above(i) if world.clear(k) and k != exclude]
    return int(tops[int(rng.integers(len(tops)))])


def _move_blocker(problem: Problem, ss: SearchState, b: int, rng: np.random.Generator, opts: StepOptions, purpose: str,
                  avoid: int = -1) -> Transition | None:
    """Clear blocker ``b``: straight to its own goal when it is a goal object
    that may be placed now (saving the second move), else to a free pose."""
    if b in problem.member and not ss.committed(problem, b) and b in ss.ready(problem):
        tr = attempt(problem, ss, b, rng, opts, direct=True)
        if tr is not None:
            return tr
    return relocate(problem, ss, b, rng, opts, purpose, avoid)


def _move_anchor(problem: Problem, ss: SearchState, o: int, rng: np.random.Generator, opts: StepOptions,
                 placed: bool = True) -> Transition | None:
    """When no pose of ``o``'s prior lies in the workspace, move one of its
    anchors (it stands near an edge, say): preferably one that no goal
    places, to a free pose; else, with ``placed``, one a goal places, which
    sends that goal back to the remaining ones (a plate that is a tower's
    base, say)."""
    if opts.obstacles != "all":
        return None
    anchors = [g.anchor for k in problem.member[o] if (g := problem.goals[k]).anchor is not None and g.anchor != o]
    free = [a for a in anchors if a not in problem.member]
    if not free and placed:
        # An anchor that a goal places moves this way once at most (while it
        # still stands where it started), so a branch cannot keep carrying it.
        start = problem.scene.initial
        free = [a for a in anchors
                if ss.world.on[a] == start.on[a] and np.array_equal(ss.world.poses[a], start.poses[a])]
    if not free:
        return None
    a = free[int(rng.integers(len(free)))]
    return clear_way(problem, ss, a, rng, opts)


def probe(problem: Problem, ss: SearchState, o: int, rng: np.random.Generator,
          opts: StepOptions) -> tuple[Transition | None, tuple[int, ...]]:
    """A direct placement of ``o`` (as ``attempt(direct=True)``) or, when every
    table candidate collides, the obstacles of its least obstructed one."""
    if not ss.world.clear(o) or required_support(problem, ss, o) != TABLE:
        return attempt(problem, ss, o, rng, opts, direct=True), ()
    if not pickable(problem, ss.world, o, opts):
        return None, ()
    cand = sample_poses(problem, ss, o, rng, opts.samples)
    if len(cand) == 0:
        return None, ()
    tr, inside, hits = to_table(problem, ss, o, cand, rng, opts)
    if tr is not None:
        return tr, ()
    blocked: list[list[int]] = [hits[k] for k in np.flatnonzero(inside) if hits[k]]
    if not blocked:
        return None, ()
    fewest = min(blocked, key=len)
    return None, tuple(fewest)


def clear_way(problem: Problem, ss: SearchState, b: int, rng: np.random.Generator, opts: StepOptions,
              avoid: int = -1) -> Transition | None:
    """Move obstacle ``b`` out of the way of object ``avoid`` (the top of its stack first)."""
    if not ss.world.clear(b):
        return _move_blocker(problem, ss, _clear_top(ss.world, b, rng), rng, opts, "unstack", avoid)
    return _move_blocker(problem, ss, b, rng, opts, "relocate", avoid)


def attempt(problem: Problem, ss: SearchState, o: int, rng: np.random.Generator, opts: StepOptions,
            *, direct: bool = False, placed_anchors: bool = True) -> Transition | None:
    """One simulation step for goal object ``o`` (paper, Algorithm 1).

    Returns ``None`` when no action could be found (no pose in the prior, no
    free pose for a blocker). With ``direct`` only a placement of ``o``
    itself is tried: no unstacking and no relocation. ``placed_anchors``
    lets it move an anchor that a goal places when ``o``'s relation has no
    room at all (rollouts leave that to the tree: such a move is a gamble).
    """
    world = ss.world
    if not world.clear(o):
        if direct:
            return None
        return _move_blocker(problem, ss, _clear_top(world, o, rng), rng, opts, "unstack", o)
    support = required_support(problem, ss, o)
    if support is None or not pickable(problem, world, o, opts):
        return None
    cand = sample_poses(problem, ss, o, rng, opts.samples)
    if len(cand) == 0:
        return None  # the priors exclude each other here: moving an anchor would not help
    if support != TABLE:
        if any(k != o for k in world.holding[support]):
            if direct:
                return None
            return _move_blocker(problem, ss, _clear_top(world, support, rng, exclude=o), rng, opts, "unstack", o)
        pose = wrapped(cand[0])
        if not shapely.contains_xy(world.polys[support], pose[0], pose[1]):
            return None
        if not reachable(problem, world, o, pose[None], opts, support)[0]:
            return None
        return place(problem, ss, o, pose, support, rng)
    tr, inside, hits = to_table(problem, ss, o, cand, rng, opts)
    if tr is not None:
        return tr
    if opts.obstacles != "all" or direct:
        return None
    # Every candidate collides: clear the way for one of them (fewest blockers first).
    blocked = [k for k in np.flatnonzero(inside) if hits[k]]
    if not blocked:
        return _move_anchor(problem, ss, o, rng, opts, placed_anchors)
    fewest = min(len(hits[k]) for k in blocked)
    pick = [k for k in blocked if len(hits[k]) == fewest]
    chosen = hits[int(pick[int(rng.integers(len(pick)))])]
    b = int(chosen[int(rng.integers(len(chosen)))])
    if b == o:
        return None
    return clear_way(problem, ss, b, rng, opts, o)

