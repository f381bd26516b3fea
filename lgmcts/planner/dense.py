"""A best-first search for tightly packed discs with pose goals.

Where :mod:`.sequence` gets stuck (no parking spot uncovers a goal) and the
table holds at most :data:`MAX_DISCS` discs, the discs often leave no room
anywhere but a few pockets between one another and the edges, as in
TRLB's densest instances (five to ten discs of 14-20 cm radius in a 1 m
square, or tens of smaller ones at D = 0.6). Random samples rarely land in such a pocket; the
points that matter are its corners. :func:`dense_plan` therefore searches
over whole table states, best first, with two kinds of moves per disc:

* straight to its goal, when no other disc covers the goal disc;
* to a *corner of its free space*: the centres where the disc, kept
  :data:`~lgmcts.patterns.CLEARANCE` from every other disc and inside the
  workspace, touches two of them, or one and an edge, or two edges (the
  intersections of the circles of radius ``r_i + r_j + CLEARANCE`` about
  the other centres with each other and with the edges of the box the
  centre must stay in), where these are free.

States are ranked by ``moves + W * (open goals + 1/2 * covered open
goals + E * depth)`` with ``W =`` :data:`WEIGHT` and ``E =`` :data:`DEPTH`,
where ``depth`` sums, over the open goals, how far the other discs reach
into the goal disc (past contact), in mean diameters: among the many moves
that uncover no goal, it ranks first those that push discs out of the
goals they block, the progress the goal count alone does not see (ties:
the shallowest, then the first generated). States are merged when every
centre agrees to :data:`GRID` m. A search stops at the first state where
every disc meets its goal, after ``max_expansions`` states
(:func:`budget`), or at ``deadline``. It runs forwards and, taking turns
with it, backwards, from the goals to the start; when both find nothing
the searches of :data:`MORE`, with other weights and depth terms, and
one with a distance term (how far the discs stand from their open goals,
summed, in mean diameters, :data:`DIST`), take turns (:func:`search`); and
restarts from tables shaken by a random walk of the start (:class:`_Shaken`),
before those searches on a few discs, after them on more. The walks draw from
generators of fixed seeds, so the same problem gives the same plan. Free-space corners are where a disc packs tightest
against its neighbours, so pockets too small to notice on a grid are
found, and a disc slid into a corner leaves the most room elsewhere. The
plan is validated like any found plan by the caller.
"""

from __future__ import annotations

import copy
import heapq
import math
import time
from collections.abc import Sequence
from typing import cast

import numpy as np

from ..formats import Action
from ..geometry import wrap_angle
from ..patterns import CLEARANCE
from ..patterns.pose import XY_TOL, YAW_TOL
from .problem import Problem
from .sequence import TOUCH, eligible

__all__ = ["MAX_DISCS", "budget", "dense_plan"]

_SIDE_AXIS = np.array([0, 0, 1, 1])
#: A vector (u, v) times this, read backwards, is (-v, u): turned a quarter counter-clockwise.
_TURN = np.array([-1.0, 1.0])

#: Most discs on the table for which :func:`dense_plan` is tried.
MAX_DISCS = 40
#: Weight of the goal count against the moves made (greedier above 1).
WEIGHT = 2.0
#: Weight, in the goal count, of how deep other discs stand in the open goal discs (summed, in diameters).
DEPTH = 1.0
#: States whose centres agree to this many metres are one state.
GRID = 5e-4
#: Gap (m) kept between a parked disc and the others.
GAP = CLEARANCE
#: States expanded before giving up, on ten discs or fewer (see :func:`budget`).
EXPANSIONS = 1500
#: Weight, in the goal count of the last search of :data:`MORE`, of how far the discs stand from their open goals
#: (summed, in mean diameters).
DIST = 1.0
#: Budget of a search of :data:`MORE`, in multiples of the first ones', unless it says otherwise.
MORE_FACTOR = 5
#: Further searches, taking turns when the first two find nothing: (weight, backwards, depth weight, distance weight,
#: budget in multiples of the first searches') each. The backward one, where it is the first to plan (TRLB's D = 0.6,
#: n = 10 files 6/7 and 8/9), plans early (after 294 and 740 states alone), so it stops at the first searches' budget
#: and leaves the rest of the turns to the other two.
MORE: tuple[tuple[float, bool, float, float, int], ...] = (
    (3.0, False, DEPTH, 0.0, MORE_FACTOR), (3.0, True, 2 * DEPTH, 0.0, 1), (WEIGHT, False, DEPTH, DIST, MORE_FACTOR))
#: States a search expands in one turn (:func:`search`).
SLICE = 250
#: Shaken restarts (:class:`_Shaken`), when the first two searches find nothing: how many (each expands up to the
#: first searches' budget), and the moves of each walk from the start.
SHAKES = 8
WALK = 400
#: On at most this many discs the shaken restarts come before the searches of :data:`MORE`, else after them. On
#: TRLB's D = 0.6 tables of seven discs, random walks rearrange the discs freely (37-64 arrangements, by the ring
#: label of ``benchmarks/dense_classes.py``, in one walk of 200 000 moves); on those of nine they keep one, also
#: where a plan exists, and there the plans of the further searches (n = 9 and 10) would only come later.
SHAKE_FIRST = 8


def budget(n: int) -> int:
    """States expanded before giving up on ``n`` discs: :data:`EXPANSIONS` up to ten, then fewer in proportion (a
    state costs about ``n`` times as much), about a second of CPU time for each direction of :func:`search`."""
    return EXPANSIONS * 10 // max(n, 10)


class _Discs:
    """The fixed data of one problem: radii, goals, the boxes the centres stay in."""

    def __init__(self, problem: Problem, reverse: bool = False) -> None:
        sc = problem.scene
        self.n = sc.n
        self.ids = sc.ids
        self.r = np.asarray(sc.discs, dtype=float)
        self.start = np.array(sc.initial.poses[:, :2], dtype=float)
        self.yaw0 = np.array(sc.initial.poses[:, 2], dtype=float)
        self.has_goal = np.zeros(self.n, dtype=bool)
        self.goal = self.start.copy()
        self.goal_yaw = self.yaw0.copy()
        for o, pose in problem.fixed.items():
            self.has_goal[o] = True
            self.goal[o] = pose[:2]
            self.goal_yaw[o] = float(pose[2])
        #: How near its goal a disc counts as there: the pose rule's tolerance, or exactly when searching backwards
        #: (the states found become the plan's, so the last must be the start itself).
        self.tol = XY_TOL
        self.all_goals = bool(self.has_goal.all())
        self.diag = (np.arange(self.n), np.arange(self.n))
        self.reverse = reverse
        if reverse:
            self.start, self.goal = self.goal, self.start
            self.tol = 1e-9
        # Each centre's box at its start yaw (buffers keep it): the footprint polygon stays inside the workspace.
        xmin, xmax, ymin, ymax = sc.bounds
        self.lo = np.empty((self.n, 2))
        self.hi = np.empty((self.n, 2))
        for i in range(self.n):
            c, s = math.cos(self.yaw0[i]), math.sin(self.yaw0[i])
            v = np.asarray(sc.local[i], dtype=float) @ np.array([[c, s], [-s, c]])
            self.lo[i] = (xmin - v[:, 0].min(), ymin - v[:, 1].min())
            self.hi[i] = (xmax - v[:, 0].max(), ymax - v[:, 1].max())
        # Least centre distances: with clearance for a buffer, contact allowed at a goal.
        rr = self.r[:, None] + self.r[None, :]
        self.far = rr + GAP
        self.touch = rr - TOUCH
        #: The length that counts as one in the depth term: the mean diameter.
        self.unit = 2.0 * float(self.r.mean()) if self.n else 1.0
        self.yaw_ok = np.abs(wrap_angle(self.yaw0 - self.goal_yaw)) <= YAW_TOL

        self.pairs = np.triu_indices(self.n, 1)
        # Discs alike in radius and box share their candidate corners.
        self.groups: dict[tuple[float, ...], list[int]] = {}
        for i in range(self.n):
            self.groups.setdefault((float(self.r[i]), *self.lo[i].tolist(), *self.hi[i].tolist()), []).append(i)
        # Per group, what its corners need: members, the least centre distances to every disc (and a hair less, for
        # the test of a point being too near), the box, its corners and sides, the radii of each pair's circles.
        self._group_data = []
        for members in self.groups.values():
            i0 = members[0]
            rad = self.far[i0]
            lo, hi = self.lo[i0], self.hi[i0]
            box = np.array([[lo[0], lo[1]], [lo[0], hi[1]], [hi[0], lo[1]], [hi[0], hi[1]]])
            side = np.array([lo[0], hi[0], lo[1], hi[1]])
            every = len(members) == self.n  # then the members are all discs, in order: no gather needed
            self._group_data.append((np.asarray(members), None if every else np.asarray(members), rad,
                                     rad * (1 - 1e-12), lo, hi, box, side, rad[self.pairs[0]], rad[self.pairs[1]]))

    def corners(self, pos: np.ndarray) -> list[np.ndarray]:
        """Per disc, the corners of its free space among the others at ``pos``: an ``(m, 2)`` array each."""
        mi, mp = self.corner_moves(pos)
        bounds = np.searchsorted(mi, np.arange(self.n + 1))
        return [mp[bounds[i]:bounds[i + 1]] for i in range(self.n)]

    def corner_moves(self, pos: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Every move to a corner at ``pos``: the discs (in order) and their new centres (each disc's corners in the
        order found), as :meth:`corners` lists them."""
        discs: list[np.ndarray] = []
        places: list[np.ndarray] = []
        a, b = self.pairs
        pos_t = pos.T
        for members, mem, rad, inner, lo, hi, box, side, ra, rb in self._group_data:
            # Circles with the box's sides (x = lo, x = hi, y = lo, y = hi): the side's coordinate on the side's axis,
            # the centre's other coordinate plus and minus the half chord.
            off = side[:, None] - pos_t[_SIDE_AXIS]  # (side, disc)
            e, j = np.nonzero(np.abs(off) <= rad)
            h = np.sqrt(np.maximum(rad[j] ** 2 - off[e, j] ** 2, 0.0))
            ax = _SIDE_AXIS[e]
            along = pos[j, 1 - ax]
            k = len(e)
            # Circles with each other (as geometry.circle_crossings, inlined: the radii are the group's).
            v = pos[b] - pos[a]
            dd = np.hypot(v[:, 0], v[:, 1])
            ok = (dd > 1e-12) & (dd < ra + rb) & (dd > np.abs(ra - rb))
            ca, cb, v, dd, rao, rbo = a[ok], b[ok], v[ok], dd[ok], ra[ok], rb[ok]
            x = (dd * dd + rao * rao - rbo * rbo) / (2 * dd)
            hc = np.sqrt(np.maximum(rao * rao - x * x, 0.0))
            u = v / dd[:, None]
            nrm = u[:, ::-1] * _TURN * hc[:, None]
            base = pos[ca] + u * x[:, None]
            c = len(ca)
            # The points in the order: box corners, sides (+, then -), crossings (+, then -); tags: the discs whose
            # circles make the point (-1: a side).
            p = np.empty((4 + 2 * k + 2 * c, 2))
            tag = np.full((len(p), 2), -1)
            p[:4] = box
            rows = np.arange(4, 4 + k)
            at = side[e]
            p[rows, ax] = at
            p[rows, 1 - ax] = along + h
            p[rows + k, ax] = at
            p[rows + k, 1 - ax] = along + (-1.0 * h)
            tag[4:4 + 2 * k, 0] = np.concatenate([j, j])
            p[4 + 2 * k:4 + 2 * k + c] = base + nrm
            p[4 + 2 * k + c:] = base - nrm
            tag[4 + 2 * k:, 0] = np.concatenate([ca, ca])
            tag[4 + 2 * k:, 1] = np.concatenate([cb, cb])
            x, y = p[:, 0], p[:, 1]
            inside = (x >= lo[0] - 1e-12) & (y >= lo[1] - 1e-12) & (x <= hi[0] + 1e-12) & (y <= hi[1] + 1e-12)
            p, tag = np.minimum(np.maximum(p[inside], lo), hi), tag[inside]
            # bad[m, j]: point m is too close to disc j (rounding lets a point on j's circle count as on it).
            bad = np.hypot(p[:, None, 0] - pos[None, :, 0], p[:, None, 1] - pos[None, :, 1]) < inner
            nbad = bad.sum(axis=1)
            # A point too close to two discs or more is no member's corner.
            few = nbad <= 1
            p, tag, bad, nbad = p[few], tag[few], bad[few], nbad[few]
            # keep[m, k]: point m is a corner of member k (no other disc too close, not on its own circle).
            keep = (nbad[:, None] - (bad if mem is None else bad[:, mem]) == 0) \
                & (tag[:, :1] != members[None, :]) & (tag[:, 1:] != members[None, :])
            kk, m = np.nonzero(keep.T)
            discs.append(members[kk])
            places.append(p[m])
        if len(discs) == 1:
            return discs[0], places[0]
        mi = np.concatenate(discs)
        order = np.argsort(mi, kind="stable")
        return mi[order], np.concatenate(places)[order]


def dense_plan(problem: Problem, *, max_expansions: int | None = None, deadline: float | None = None,
               max_discs: int = MAX_DISCS) -> list[Action] | None:
    """A plan for an :func:`~lgmcts.planner.sequence.eligible` problem of at most ``max_discs`` discs, by best-first
    search over table states (see the module's notes); ``None`` when none is found within ``max_expansions``
    expanded states (:func:`budget` by default) or by ``deadline`` (a :func:`time.perf_counter` time)."""
    if not eligible(problem) or problem.scene.n > max_discs:
        return None
    n = problem.scene.n
    return search(problem, budget(n) if max_expansions is None else max_expansions, deadline)[0]


def search(problem: Problem, max_expansions: int, deadline: float | None) -> tuple[list[Action] | None, int]:
    """:func:`dense_plan`'s search on an eligible problem: the plan or ``None``, and the states expanded.

    Forwards from the start and, when the problem can be run backwards (every disc has a goal, at its start yaw),
    backwards from the goals, the two taking turns of :data:`SLICE` states, each up to ``max_expansions``: a
    move's inverse is a move (the disc goes back where it stood, which was free of the same others), so the
    states found from the goals to the start, read in reverse, are a plan. Some tables are much easier to unpack
    from one end than the other, and taking turns finds the plan of the easier end at most twice later than
    that search alone, instead of after the whole budget of the other. When both find nothing, the searches of
    :data:`MORE` (other weights and depth terms, a distance term) take turns the same way, each up to its
    multiple of ``max_expansions`` states, or until ``deadline``: which of them finds a plan, and after how many
    states, varies from table to table, and taking turns finds the first plan at most ``len(MORE)`` times later
    than the luckiest search alone would. The shaken restarts (:class:`_Shaken`, :data:`SHAKES` of them, each up
    to ``max_expansions`` states) come before the searches of :data:`MORE` on at most :data:`SHAKE_FIRST` discs,
    after them on more."""
    t = _Discs(problem)
    back = _Discs(problem, reverse=True) if _reversible(t) else None
    first = [_Search(t)] + ([] if back is None else [_Search(back)])
    plan, expanded = _take_turns(first, [max_expansions] * len(first), deadline)
    if plan is not None:
        return plan, expanded
    # Searches done with are let go at once: freeing tens of thousands of states takes a tenth of a second or more,
    # which at the end would run past the deadline.
    first.clear()
    shaken = [_Shaken(t, max_expansions)]
    if t.n <= SHAKE_FIRST:
        plan, more_states = _take_turns(shaken, [SHAKES * max_expansions], deadline)
        expanded += more_states
        if plan is not None:
            return plan, expanded
        shaken = []
    chosen = [m for m in MORE if back is not None or not m[1]]
    more = [_Search(back if reverse and back is not None else t, weight, depth=depth, dist=dist)
            for weight, reverse, depth, dist, _ in chosen]
    plan, further = _take_turns(more, [factor * max_expansions for *_, factor in chosen], deadline)
    expanded += further
    if plan is not None or not shaken:
        return plan, expanded
    more.clear()
    plan, more_states = _take_turns(shaken, [SHAKES * max_expansions], deadline)
    return plan, expanded + more_states


def _take_turns(runs: Sequence[_Search | _Shaken], caps: list[int], deadline: float | None
                ) -> tuple[list[Action] | None, int]:
    """Run the searches ``runs`` in turns of :data:`SLICE` states, each up to its number of ``caps`` states, until
    one finds a plan, all are spent or ``deadline`` passes; the plan or ``None``, and the states they expanded."""
    expanded = 0
    left = list(zip(runs, caps))
    while left and (deadline is None or time.perf_counter() <= deadline):
        for run, most in list(left):
            before = run.expanded
            plan, _ = run.run(min(before + SLICE, most), deadline)
            expanded += run.expanded - before
            if plan is not None:
                return plan, expanded
            if run.expanded >= most or not run.heap:
                left.remove((run, most))
    return None, expanded


def _reversible(t: _Discs) -> bool:
    return bool(t.has_goal.all() and t.yaw_ok.all() and np.all(t.yaw0 == t.goal_yaw))


#: One search state: disc centres, whether each disc's yaw is its goal's, the parent state's index, and the move
#: that led here (the disc, and whether it went to its goal).
_State = tuple[np.ndarray, np.ndarray, int, int, bool]


class _Search:
    """Best-first search state: the states generated, the open list, the merged keys."""

    def __init__(self, t: _Discs, weight: float = WEIGHT, deep: bool = False, depth: float = DEPTH,
                 dist: float = 0.0) -> None:
        self.t = t
        #: The weight of the goals in a state's rank; among states of equal rank, the deepest first when ``deep``
        #: (else the shallowest), then the first generated.
        self.weight = weight
        self.deep = deep
        #: The weight of the depth term in the goal count (:data:`DEPTH`).
        self.depth = depth
        #: The weight of the distance term in the goal count: how far the discs stand from their open goals, summed,
        #: in mean diameters (0 in the first two searches, :data:`DIST` in the last of :data:`MORE`).
        self.dist = dist
        self.states: list[_State] = [(t.start.copy(), t.yaw_ok.copy(), -1, -1, False)]
        #: Open states: (rank, depth or minus depth when ``deep``, index).
        self.heap: list[tuple[float, int, int]] = []
        self.seen = {np.round(t.start / GRID).astype(np.int64).tobytes()}
        #: States expanded so far; whether the goals hold at the start.
        self.expanded = 0
        done0 = self.at_goal(t.start, t.yaw_ok)
        self.solved_at_start = bool(done0.all())
        if not self.solved_at_start:
            pen0 = self.depths(t.start)
            blocked0 = (pen0 > 0).any(axis=1)
            h0 = (~done0).sum() + 0.5 * (blocked0 & ~done0).sum() + depth * (pen0.sum(axis=1) * ~done0).sum() / t.unit
            h0 += dist * float((np.hypot(*(t.start - t.goal).T) * (t.has_goal & ~done0)).sum()) / t.unit
            self.heap.append((weight * float(h0), 0, 0))

    def at_goal(self, pos: np.ndarray, yaw_ok: np.ndarray) -> np.ndarray:
        t = self.t
        return np.asarray(~t.has_goal | ((np.hypot(*(pos - t.goal).T) <= t.tol) & yaw_ok))

    def depths(self, pos: np.ndarray) -> np.ndarray:
        """``pen[k, j]``: how deep disc j, where it stands, reaches into the goal disc of k (0 where it does not
        cover it; past contact, the least centre distance at a goal, less their distance)."""
        t = self.t
        dist = np.hypot(t.goal[:, None, 0] - pos[None, :, 0], t.goal[:, None, 1] - pos[None, :, 1])
        pen = np.maximum(t.touch - dist, 0.0)
        pen[t.diag] = 0.0
        if not t.all_goals:
            pen[~t.has_goal] = 0.0
        return pen

    def run(self, max_expansions: int, deadline: float | None) -> tuple[list[Action] | None, int]:
        """Expand states until a plan is found, ``max_expansions`` states in all have been expanded, the open list
        is empty or ``deadline`` passes; the plan or ``None``, and the states expanded in all. A search that found
        nothing can be run on with a larger ``max_expansions``."""
        if self.solved_at_start:
            return [], 0
        while self.heap:
            if self.expanded >= max_expansions or (deadline is not None and time.perf_counter() > deadline):
                break
            _, depth, s = heapq.heappop(self.heap)
            g = abs(depth)  # stored negated when deepest first
            self.expanded += 1
            last = self.expand(s, g)
            if last is not None:
                return _actions(self.t, self.states, last), self.expanded
        return None, self.expanded

    def expand(self, s: int, g: int) -> int | None:
        """Push every new state one move from state ``s`` (``g`` moves deep); the index of one that meets every
        goal, if any.

        The moves, in order: for each disc, straight to its goal when no other disc covers the goal disc, then to
        each corner of its free space. Each new state is ranked by moves plus the search's weight times (open
        goals + half the open goals covered + the depth term: the search's ``depth`` times how deep, in mean
        diameters, the discs reach into open goal discs, summed + the distance term: the search's ``dist`` times
        how far, in mean diameters, the discs of open goals stand from them, summed); all moves of the state are
        judged at once."""
        t = self.t
        pos, yok = self.states[s][0], self.states[s][1]
        done = self.at_goal(pos, yok)
        pen = self.depths(pos)
        cov = pen > 0
        # Goal moves: disc i's goal disc clear of every other disc; each before the disc's corner moves.
        gi = np.flatnonzero(t.has_goal & ~done & ~cov.any(axis=1))
        ci, cp = t.corner_moves(pos)
        mi = np.concatenate([gi, ci])
        if not len(mi):
            return None
        by_disc = np.argsort(mi, kind="stable")
        mi = mi[by_disc]
        mp = np.concatenate([t.goal[gi], cp])[by_disc]
        mg = by_disc < len(gi)
        # Only moves to states not seen before (to GRID), in the order above.
        key = np.round(pos / GRID).astype(np.int64)
        keys = np.repeat(key[None], len(mi), axis=0)
        keys[np.arange(len(mi)), mi] = np.round(mp / GRID).astype(np.int64)
        # Each state's key as one bytes object (a row read as a single opaque item).
        rows_b = cast(list[bytes], keys.reshape(len(mi), -1).view(np.dtype((np.void, key.nbytes))).ravel().tolist())
        seen = self.seen
        add = seen.add
        fresh = [m for m, b in enumerate(rows_b) if not (b in seen or add(b))]
        if not fresh:
            return None
        f = np.asarray(fresh)
        mi, mp, mg = mi[f], mp[f], mg[f]
        # Open goals covered by the others than the moved disc, and by the moved disc from its new place.
        count = cov.sum(axis=1)
        blocked_rest = (count[None, :] - cov.T[mi]) > 0
        rows = np.arange(len(mi))
        # newcol[m, k]: how deep the moved disc reaches into goal disc k from its new place (touch is symmetric).
        gap = np.hypot(t.goal[None, :, 0] - mp[:, None, 0], t.goal[None, :, 1] - mp[:, None, 1])
        home_gap = gap[rows, mi]  # the moved disc's distance to its own goal
        newcol = np.maximum(t.touch[mi] - gap, 0.0)
        newcol[rows, mi] = 0.0
        if not t.all_goals:
            newcol[:, ~t.has_goal] = 0.0
        col = newcol > 0
        open_ = np.repeat((~done)[None], len(mi), axis=0)
        open_[rows, mi] = True
        blocked = (blocked_rest | col) & open_
        ok_yaw = mg | t.yaw_ok[mi]
        meets = ~t.has_goal[mi] | ((home_gap <= t.tol) & ok_yaw)
        others_open = float((~done).sum()) - ~done[mi]
        h = others_open + ~meets + 0.5 * (blocked.sum(axis=1) - (meets & blocked[rows, mi]))
        if self.depth:
            # Each goal's depth summed over the discs: the parent's, less the moved disc's old, plus its new.
            reach = pen.sum(axis=1)[None, :] - pen.T[mi] + newcol
            open_[rows, mi] = ~meets
            h = h + self.depth * (reach * open_).sum(axis=1) / t.unit
        if self.dist:
            # Each open goal's distance to its disc: the parent's, less the moved disc's old, plus its new.
            d0 = np.hypot(*(pos - t.goal).T) * (t.has_goal & ~done)
            dn = home_gap * (t.has_goal[mi] & ~meets)
            h = h + self.dist * (d0.sum() - d0[mi] + dn) / t.unit
        rank = (g + 1) + self.weight * h
        # The new states, in one block each for the centres and the yaw flags.
        npos = np.repeat(pos[None], len(mi), axis=0)
        npos[rows, mi] = mp
        nyok = np.repeat(yok[None], len(mi), axis=0)
        nyok[rows, mi] = ok_yaw
        last = (meets & (others_open == 0)).tolist()
        order = -(g + 1) if self.deep else g + 1
        for m, (i, home, r, end) in enumerate(zip(mi.tolist(), mg.tolist(), rank.tolist(), last)):
            self.states.append((npos[m], nyok[m], s, i, home))
            if end:
                return len(self.states) - 1
            heapq.heappush(self.heap, (r, order, len(self.states) - 1))
        return None


class _Shaken:
    """Restarts from shaken tables: each walks :data:`WALK` moves from the start, a disc chosen at random put at
    a random free place of its box (the corner search's gap to every other disc), then runs the forward search
    from there for ``each`` states; a plan is the walk's moves followed by the search's. A walk that moves no disc
    (none has a free place) is skipped: its search would be the first one again. Some tables
    the corner search cannot unpack from their start (TRLB's D = 0.6, n = 7, files 2/3), where the best-ranked
    states all keep one arrangement of the discs about one another, a random walk leaves: the discs there change
    places freely under random moves. The walks draw from a generator seeded by the restart's number, so a
    problem gets the same plan each time. Runs like a :class:`_Search` in :func:`_take_turns`."""

    def __init__(self, t: _Discs, each: int) -> None:
        self.t = t
        self.each = each
        #: States expanded by the restarts' searches so far.
        self.expanded = 0
        #: The restarts still to come (empty when all are spent): ``_take_turns`` reads it as a search's open list.
        self.heap = list(range(SHAKES))[::-1]
        self._run: _Search | None = None
        self._walk: list[Action] = []
        self._base = 0

    def run(self, max_expansions: int, deadline: float | None) -> tuple[list[Action] | None, int]:
        """Go on with the restarts until a plan is found, ``max_expansions`` states in all have been expanded,
        every restart is spent or ``deadline`` passes; the plan or ``None``, and the states expanded in all."""
        while self.expanded < max_expansions and (deadline is None or time.perf_counter() <= deadline):
            if self._run is None:
                if not self.heap:
                    break
                self._start(self.heap.pop(), deadline)
                if not self._walk:
                    self._run = None
                    continue
            run = cast(_Search, self._run)
            plan, done = run.run(min(self.each, max_expansions - self._base), deadline)
            self.expanded = self._base + done
            if plan is not None:
                return self._walk + plan, self.expanded
            if done >= self.each or not run.heap:
                self._base, self._run = self.expanded, None
        return None, self.expanded

    def _start(self, seed: int, deadline: float | None) -> None:
        """The walk of restart ``seed`` and a search from where it ends; the walk stops short at ``deadline``."""
        t = self.t
        rng = np.random.default_rng(seed)
        pos = t.start.copy()
        walk: list[Action] = []
        for k in range(4 * WALK):
            if len(walk) >= WALK or (k % 64 == 0 and deadline is not None and time.perf_counter() > deadline):
                break
            i = int(rng.integers(t.n))
            c = t.lo[i] + rng.random((64, 2)) * np.maximum(t.hi[i] - t.lo[i], 0.0)
            near = np.hypot(c[:, None, 0] - pos[None, :, 0], c[:, None, 1] - pos[None, :, 1]) < t.far[i][None, :]
            near[:, i] = False
            free = np.flatnonzero(~near.any(axis=1))
            if len(free):
                pos[i] = c[free[0]]
                walk.append(Action.model_construct(object=t.ids[i], to=(float(pos[i, 0]), float(pos[i, 1]),
                                                                        float(t.yaw0[i])), on=None, purpose="relocate"))
        shaken = copy.copy(t)
        shaken.start = pos
        self._walk = walk
        self._run = _Search(shaken)


def _actions(t: _Discs, states: list[_State], s: int) -> list[Action]:
    """The moves from the first state to state ``s``; searching backwards, from state ``s`` to the first (then each
    move takes its disc to where it stood in the state before, the goal where that was the first state's place)."""
    out: list[Action] = []
    if t.reverse:
        while states[s][2] >= 0:
            _, _, parent, i, _ = states[s]
            xy = states[parent][0][i]
            home = bool(np.all(xy == t.start[i]))
            out.append(Action.model_construct(object=t.ids[i], to=(float(xy[0]), float(xy[1]), float(t.yaw0[i])),
                                              on=None, purpose="goal" if home else "relocate"))
            s = parent
        return out
    while states[s][2] >= 0:
        pos, _, parent, i, to_goal = states[s]
        yaw = t.goal_yaw[i] if to_goal else t.yaw0[i]
        out.append(Action.model_construct(object=t.ids[i], to=(float(pos[i, 0]), float(pos[i, 1]), float(yaw)),
                                          on=None, purpose="goal" if to_goal else "relocate"))
        s = parent
    return out[::-1]
