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
goals)`` with ``W =`` :data:`WEIGHT` (ties: first generated first) and
merged when every centre agrees to :data:`GRID` m. The search stops at the
first state where every disc meets its goal, after ``max_expansions``
states (:func:`budget`), or at ``deadline``. When it finds nothing it runs
again backwards, from the goals to the start (:func:`search`). It uses no
random numbers, so the same problem gives the same plan. Free-space corners are where a disc packs tightest
against its neighbours, so pockets too small to notice on a grid are
found, and a disc slid into a corner leaves the most room elsewhere. The
plan is validated like any found plan by the caller.
"""

from __future__ import annotations

import heapq
import math
import time

import numpy as np

from ..formats import Action
from ..geometry import wrap_angle
from ..patterns import CLEARANCE
from ..patterns.pose import XY_TOL, YAW_TOL
from .problem import Problem
from .sequence import TOUCH, eligible

__all__ = ["MAX_DISCS", "budget", "dense_plan"]

#: Most discs on the table for which :func:`dense_plan` is tried.
MAX_DISCS = 40
#: Weight of the goal count against the moves made (greedier above 1).
WEIGHT = 2.0
#: States whose centres agree to this many metres are one state.
GRID = 5e-4
#: Gap (m) kept between a parked disc and the others.
GAP = CLEARANCE
#: States expanded before giving up, on ten discs or fewer (see :func:`budget`).
EXPANSIONS = 1500


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
        self.yaw_ok = np.abs(wrap_angle(self.yaw0 - self.goal_yaw)) <= YAW_TOL

        # Discs alike in radius and box share their candidate corners.
        self.groups: dict[tuple[float, ...], list[int]] = {}
        for i in range(self.n):
            self.groups.setdefault((float(self.r[i]), *self.lo[i].tolist(), *self.hi[i].tolist()), []).append(i)

    def corners(self, pos: np.ndarray) -> list[np.ndarray]:
        """Per disc, the corners of its free space among the others at ``pos``: an ``(m, 2)`` array each."""
        out: list[np.ndarray] = [np.zeros((0, 2))] * self.n
        for members in self.groups.values():
            i0 = members[0]
            rad = self.far[i0]
            lo, hi = self.lo[i0], self.hi[i0]
            pts = [np.array([[lo[0], lo[1]], [lo[0], hi[1]], [hi[0], lo[1]], [hi[0], hi[1]]])]
            tags = [np.full((4, 2), -1)]
            # Circles with the box's sides: x = lo, x = hi, y = lo, y = hi.
            axis = np.array([0, 0, 1, 1])
            side = np.array([lo[0], hi[0], lo[1], hi[1]])
            off = side[:, None] - pos[:, axis].T  # (side, disc)
            e, j = np.nonzero(np.abs(off) <= rad[None, :])
            h = np.sqrt(np.maximum(rad[j] ** 2 - off[e, j] ** 2, 0.0))
            for sgn in (1.0, -1.0):
                p = np.empty((len(e), 2))
                p[np.arange(len(e)), axis[e]] = side[e]
                p[np.arange(len(e)), 1 - axis[e]] = pos[j, 1 - axis[e]] + sgn * h
                pts.append(p)
                tags.append(np.stack([j, np.full(len(j), -1)], axis=1))
            # Circles with each other.
            a, b = np.triu_indices(self.n, 1)
            v = pos[b] - pos[a]
            dd = np.hypot(v[:, 0], v[:, 1])
            ra, rb = rad[a], rad[b]
            ok = (dd > 1e-12) & (dd < ra + rb) & (dd > np.abs(ra - rb))
            if ok.any():
                a, b, v, dd, ra, rb = a[ok], b[ok], v[ok], dd[ok], ra[ok], rb[ok]
                x = (dd * dd + ra * ra - rb * rb) / (2 * dd)
                h = np.sqrt(np.maximum(ra * ra - x * x, 0.0))
                u = v / dd[:, None]
                nrm = np.stack([-u[:, 1], u[:, 0]], axis=1) * h[:, None]
                base = pos[a] + u * x[:, None]
                pts += [base + nrm, base - nrm]
                tags += [np.stack([a, b], axis=1)] * 2
            p = np.concatenate(pts)
            tag = np.concatenate(tags)
            inside = (p >= lo - 1e-12).all(axis=1) & (p <= hi + 1e-12).all(axis=1)
            p, tag = np.clip(p[inside], lo, hi), tag[inside]
            # bad[m, j]: point m is too close to disc j (rounding lets a point on j's circle count as on it).
            bad = np.hypot(p[:, None, 0] - pos[None, :, 0], p[:, None, 1] - pos[None, :, 1]) \
                < rad[None, :] * (1 - 1e-12)
            nbad = bad.sum(axis=1)
            for i in members:
                keep = (nbad - bad[:, i] == 0) & (tag[:, 0] != i) & (tag[:, 1] != i)
                out[i] = p[keep]
        return out


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

    Forwards from the start first; when that finds nothing and the problem can be run backwards (every disc has
    a goal, at its start yaw), backwards from the goals with the same budget: a move's inverse is a move (the
    disc goes back where it stood, which was free of the same others), so the states found from the goals to the
    start, read in reverse, are a plan. Some tables are easier to unpack from one end than the other."""
    t = _Discs(problem)
    plan, expanded = _Search(t).run(max_expansions, deadline)
    if plan is not None or not _reversible(t):
        return plan, expanded
    back, more = _Search(_Discs(problem, reverse=True)).run(max_expansions, deadline)
    return back, expanded + more


def _reversible(t: _Discs) -> bool:
    return bool(t.has_goal.all() and t.yaw_ok.all() and np.all(t.yaw0 == t.goal_yaw))


#: One search state: disc centres, whether each disc's yaw is its goal's, the parent state's index, and the move
#: that led here (the disc, and whether it went to its goal).
_State = tuple[np.ndarray, np.ndarray, int, int, bool]


class _Search:
    """Best-first search state: the states generated, the open list, the merged keys."""

    def __init__(self, t: _Discs) -> None:
        self.t = t
        self.states: list[_State] = [(t.start.copy(), t.yaw_ok.copy(), -1, -1, False)]
        self.heap: list[tuple[float, int, int]] = []
        self.seen = {np.round(t.start / GRID).astype(np.int64).tobytes()}

    def at_goal(self, pos: np.ndarray, yaw_ok: np.ndarray) -> np.ndarray:
        t = self.t
        return np.asarray(~t.has_goal | ((np.hypot(*(pos - t.goal).T) <= t.tol) & yaw_ok))

    def covered(self, pos: np.ndarray) -> np.ndarray:
        """``cov[k, j]``: disc j, where it stands, covers the goal disc of k."""
        t = self.t
        cov = np.hypot(t.goal[:, None, 0] - pos[None, :, 0], t.goal[:, None, 1] - pos[None, :, 1]) < t.touch
        cov[np.arange(t.n), np.arange(t.n)] = False
        cov[~t.has_goal] = False
        return cov

    def run(self, max_expansions: int, deadline: float | None) -> tuple[list[Action] | None, int]:
        pos0, yaw0 = self.states[0][0], self.states[0][1]
        done0 = self.at_goal(pos0, yaw0)
        if done0.all():
            return [], 0
        blocked0 = self.covered(pos0).any(axis=1)
        self.heap.append((WEIGHT * float((~done0).sum() + 0.5 * (blocked0 & ~done0).sum()), 0, 0))
        expanded = 0
        while self.heap:
            if expanded >= max_expansions or (deadline is not None and time.perf_counter() > deadline):
                break
            _, g, s = heapq.heappop(self.heap)
            expanded += 1
            last = self.expand(s, g)
            if last is not None:
                return _actions(self.t, self.states, last), expanded
        return None, expanded

    def expand(self, s: int, g: int) -> int | None:
        """Push every new state one move from state ``s`` (``g`` moves deep); the index of one that meets every
        goal, if any."""
        t = self.t
        pos, yok = self.states[s][0], self.states[s][1]
        done = self.at_goal(pos, yok)
        cov = self.covered(pos)
        key = np.round(pos / GRID).astype(np.int64)
        corners = t.corners(pos)
        for i in range(t.n):
            # Moves of disc i: to its goal when free, and to each corner of its free space.
            rest = cov.copy()
            rest[:, i] = False
            blocked_rest = np.asarray(rest.any(axis=1))
            if t.has_goal[i] and not done[i]:
                free = np.hypot(*(pos - t.goal[i]).T) >= t.touch[i]
                free[i] = True
                if free.all():
                    found = self.push(s, g, i, t.goal[i][None, :], True, done, blocked_rest, key)
                    if found is not None:
                        return found
            found = self.push(s, g, i, corners[i], False, done, blocked_rest, key)
            if found is not None:
                return found
        return None

    def push(self, s: int, g: int, i: int, pts: np.ndarray, to_goal: bool, done: np.ndarray,
             blocked_rest: np.ndarray, key: np.ndarray) -> int | None:
        """Push the states with disc ``i`` of state ``s`` moved to each of ``pts`` (not seen before); the index of
        one that meets every goal, if any. Ranked by moves plus :data:`WEIGHT` times (open goals + half the open
        goals covered)."""
        t = self.t
        if not len(pts):
            return None
        keys = np.repeat(key[None], len(pts), axis=0)
        keys[:, i] = np.round(pts / GRID).astype(np.int64)
        fresh = []
        for m, row in enumerate(keys):
            b = row.tobytes()
            if b not in self.seen:
                self.seen.add(b)
                fresh.append(m)
        if not fresh:
            return None
        # Goals disc i would cover from each point, and whether the point meets its own goal.
        col = np.hypot(t.goal[None, :, 0] - pts[:, None, 0], t.goal[None, :, 1] - pts[:, None, 1]) \
            < t.touch[None, :, i]
        col[:, i] = False
        col[:, ~t.has_goal] = False
        open_ = ~done
        open_[i] = True  # judged per point below
        blocked = (blocked_rest[None, :] | col) & open_[None, :]
        ok_yaw = True if to_goal else bool(t.yaw_ok[i])
        meets = ~t.has_goal[i] | ((np.hypot(*(pts - t.goal[i]).T) <= t.tol) & ok_yaw)
        others_open = float((~done).sum() - (not done[i]))
        yok = self.states[s][1].copy()
        yok[i] = ok_yaw
        pos = self.states[s][0]
        for m in fresh:
            npos = pos.copy()
            npos[i] = pts[m]
            self.states.append((npos, yok, s, i, to_goal))
            now = bool(meets[m])
            if now and others_open == 0:
                return len(self.states) - 1
            h = others_open + (not now) + 0.5 * (float(blocked[m].sum()) - (now and bool(blocked[m, i])))
            heapq.heappush(self.heap, (g + 1 + WEIGHT * h, g + 1, len(self.states) - 1))
        return None


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
