"""A fast first attempt for pose goals on discs: order the moves by what blocks what.

When every goal is a ``pose`` goal of one cylinder, every object is a
cylinder standing on the table, the plan is a matter of order and of
parking places (the setting of dense disc rearrangement benchmarks such as
TRLB's). :func:`sequence_plan` builds such a plan directly, without search:

1. every object whose goal disc is free of the other discs where they stand
   now goes there (an object on its goal never blocks another goal, as goal
   discs do not overlap, so each such move is final);
2. when none can go, the goals left form cycles of "my goal is covered by
   you": the object that alone covers the most of the remaining goals (its
   move frees them), then the one that covers the most (ties: the lower
   index), is parked in a *buffer*, a free spot of the table chosen on
   a grid near its own goal, away from every goal still to be reached when
   there is such a spot (then it blocks nothing later); where the grid has
   none, a disc is *nudged*: slid to a nearby corner of its free space (or
   the nearest place off a goal it alone covers) that uncovers the most
   goals, so that on a packed table a goal comes free without a distant
   buffer; repeat from 1.

Discs are tested as circles, vectorised over all objects (the
polygons stand for the circles; two discs that touch may overlap as polygons
but not as circles, which is how the validator judges cylinders). Parking
spots keep the planner's clearance from every other disc and from the
workspace edge; goal placements need only not overlap (the goal gives no
choice). The plan is then validated like any found plan (and polished); the
caller falls back to the tree search when this returns ``None`` or the
validator refuses the plan. Nothing here draws random numbers: the same
problem gives the same plan.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from ..formats import Action
from ..geometry import circle_crossings, wrap_angle
from ..patterns import CLEARANCE
from ..patterns.pose import XY_TOL, YAW_TOL
from ..scene import TABLE
from ..tolerances import TOL
from .problem import Problem

__all__ = ["eligible", "polish_may_help", "sequence_plan"]

#: Two discs closer than the sum of their radii by at most this much (m)
#: touch rather than overlap (their lens is far below the validator's
#: allowance of 1e-6 m^2).
TOUCH = 1e-7


def eligible(problem: Problem) -> bool:
    """Whether :func:`sequence_plan` applies: every object a cylinder on the
    table, every goal a ``pose`` goal of one object, no object in two goals."""
    sc = problem.scene
    if sc.n == 0 or not problem.goals:
        return False
    if not bool(np.all(sc.discs > 0)) or any(s != TABLE for s in sc.initial.on):
        return False
    if any(g.pattern != "pose" or len(g.objects) != 1 or g.anchor is not None for g in problem.goals):
        return False
    return all(len(ks) == 1 for ks in problem.member.values()) and len(problem.fixed) == len(problem.member)


class _Table:
    """Disc centres and radii as they stand, with each goal's blockers as a boolean matrix."""

    def __init__(self, problem: Problem) -> None:
        sc = problem.scene
        self.r = np.asarray(sc.discs, dtype=float)
        self.pos = np.array(sc.initial.poses[:, :2], dtype=float)
        self.movers = np.array(sorted(problem.fixed), dtype=int)
        self.goal = np.array([problem.fixed[o][:2] for o in self.movers], dtype=float)
        self.yaw = np.array([float(problem.fixed[o][2]) for o in self.movers])
        self.row = {int(o): k for k, o in enumerate(self.movers)}
        self.is_mover = np.zeros(len(self.r), dtype=bool)
        self.is_mover[self.movers] = True
        # blocked[k, j]: disc j, where it stands, overlaps the goal disc of mover k.
        d = np.hypot(*(self.goal[:, None, :] - self.pos[None, :, :]).transpose(2, 0, 1))
        self.blocked = d < self.r[self.movers][:, None] + self.r[None, :] - TOUCH
        self.blocked[np.arange(len(self.movers)), self.movers] = False
        #: Per goal (row), how many discs cover it (the row sums of ``blocked``, kept as discs move).
        self.blockers = self.blocked.sum(axis=1)
        self.done = np.zeros(len(self.movers), dtype=bool)
        self._open_rows: np.ndarray | None = None
        self.scene = sc
        #: Where discs left and arrived, in order, the first ``nchanges`` rows (a cached nudge stays valid while none
        #: of these is near).
        self.changes = np.zeros((16, 2))
        self.nchanges = 0
        self.rmax = float(np.max(self.r))
        #: Per disc, its last nudge: (changes seen, centre, freed goals, cover, the answer).
        self.nudges: dict[int, tuple[int, tuple[float, float], tuple[int, ...], int,
                                     tuple[np.ndarray, int, int] | None]] = {}
        #: Per disc, its last bound of :class:`_Cells` (changes seen, centre, freed goals, cover, the bound).
        self.bounds: dict[int, tuple[int, tuple[float, float], tuple[int, ...], int, tuple[int, int] | None]] = {}
        self._boxes: dict[int, tuple[np.ndarray, np.ndarray]] = {}
        #: The discs moved and the goals (rows) reached, in order, for :class:`_Crossings` to catch up on.
        self.moved: list[int] = []
        self.closed: list[int] = []
        #: Per radius of a disc to nudge, the crossings of the circles it may touch (built once the plan has made
        #: :data:`TABLE_AFTER` nudges), and the nudges made.
        self.crossings: dict[float, _Crossings] = {}
        self.nudged = 0
        #: The cells that bound a nudge before it is computed (built the first time one is to be bounded).
        self.cells: _Cells | None = None

    def box(self, j: int) -> tuple[np.ndarray, np.ndarray]:
        """Lower and upper corners of the box disc ``j``'s centre stays in at its start yaw (its footprint polygon
        inside the workspace)."""
        if j not in self._boxes:
            sc = self.scene
            c, s = math.cos(float(sc.initial.poses[j, 2])), math.sin(float(sc.initial.poses[j, 2]))
            v = np.asarray(sc.local[j], dtype=float) @ np.array([[c, s], [-s, c]])
            xmin, xmax, ymin, ymax = sc.bounds
            self._boxes[j] = (np.array([xmin - v[:, 0].min(), ymin - v[:, 1].min()]),
                              np.array([xmax - v[:, 0].max(), ymax - v[:, 1].max()]))
        return self._boxes[j]

    def move(self, j: int, xy: np.ndarray) -> None:
        if self.nchanges + 2 > len(self.changes):
            self.changes = np.concatenate([self.changes, np.zeros_like(self.changes)])
        self.changes[self.nchanges] = self.pos[j]
        self.changes[self.nchanges + 1] = xy
        self.nchanges += 2
        self.moved.append(j)
        self.pos[j] = xy
        if self.cells is not None:
            self.cells.moved(j)
        d = np.hypot(*(self.goal - xy).T)
        col = d < self.r[self.movers] + self.r[j] - TOUCH
        k = self.row.get(j)
        if k is not None:
            col[k] = False
        self.blockers += col
        self.blockers -= self.blocked[:, j]
        self.blocked[:, j] = col

    def open_rows(self) -> np.ndarray:
        """The goals (rows) not yet reached, in order (not to be changed by the caller)."""
        if self._open_rows is None:
            self._open_rows = np.flatnonzero(~self.done)
        return self._open_rows

    def close(self, k: int) -> None:
        """The goal of mover ``k`` (a row) is reached."""
        self._open_rows = None
        self.done[k] = True
        self.closed.append(k)
        if self.cells is not None:
            self.cells.closed(k)


class _Crossings:
    """Where the circles a disc of radius ``rj`` may touch cross one another, for :func:`_nudge`, kept up to date.

    The circles: about each disc ``i``, radius ``r_i + rj +`` the clearance (the nearest a parked disc may come),
    and about each open goal, radius ``r_goal + rj`` and a nanometre (just off the goal disc). Kept: the
    crossings of two disc circles, and of a disc circle and a goal circle (as :func:`_nudge` takes them), each
    with the circles it came from. A disc that moves drops the crossings of its circle and gains its new ones,
    a goal that is reached drops its own; every other crossing is unchanged, so a nudge picks the ones within its
    reach instead of crossing every pair of circles near it again. Each crossing is computed from the same
    numbers in the same order as a nudge would (``a`` the disc of lower index, a disc before a goal), so it is
    the same point to the last bit.

    Kept too: where each of those circles crosses a side of the box ``lo``-``hi`` (that of the disc the table was
    built for; a nudge of a disc with another box crosses the sides itself), as a nudge would cross them; such an
    entry has its circle as both ``a`` and ``b``, and a key below every pair's, in the nudge's order (side by
    side, the ``+`` ones, then the ``-`` ones, by circle)."""

    def __init__(self, t: _Table, rj: float, lo: np.ndarray, hi: np.ndarray) -> None:
        self.n = n = len(t.r)
        #: Circle ``i < n`` is disc ``i``'s; circle ``n + k`` goal row ``k``'s.
        self.span = n + len(t.movers)
        self.rad = np.concatenate([t.r + rj + CLEARANCE, t.r[t.movers] + rj + 1e-9])
        self.p = np.zeros((0, 2))
        self.a = np.zeros(0, dtype=np.intp)
        self.b = np.zeros(0, dtype=np.intp)
        #: The order a nudge generates the crossings in: all the ``+`` ones, then the ``-`` ones, each by (a, b).
        self.key = np.zeros(0, dtype=np.intp)
        self.lo, self.hi = lo.copy(), hi.copy()
        self.sides = np.array([lo[0], hi[0], lo[1], hi[1]])
        self._same: dict[int, bool] = {}
        self.seen = (len(t.moved), len(t.closed))
        a, b = np.triu_indices(n, 1)
        rows = np.flatnonzero(~t.done)
        self._add(t, a, b, rows, np.arange(n))
        self._add_sides(t, np.concatenate([np.arange(n), n + rows]))

    def same_box(self, j: int, lo: np.ndarray, hi: np.ndarray) -> bool:
        """Whether disc ``j``'s box ``lo``-``hi`` is the one whose sides are kept (remembered per disc)."""
        got = self._same.get(j)
        if got is None:
            got = self._same[j] = bool(np.array_equal(self.lo, lo) and np.array_equal(self.hi, hi))
        return got

    def _add_sides(self, t: _Table, circles: np.ndarray) -> None:
        """Add the crossings of each of ``circles`` with the box's sides."""
        cen = np.concatenate([t.pos, t.goal])[circles]
        rad = self.rad[circles]
        off = self.sides[:, None] - cen[:, _AXIS].T  # (side, circle)
        e, k = np.nonzero(np.abs(off) <= rad)
        if not len(e):
            return
        h = np.sqrt(np.maximum(rad[k] ** 2 - off[e, k] ** 2, 0.0))
        ax = _AXIS[e]
        side = self.sides[e]
        q = np.empty((2, len(e), 2))
        for sg, sgn in enumerate((1.0, -1.0)):
            along = cen[k, 1 - ax] + sgn * h
            q[sg, :, 0] = np.where(ax == 0, side, along)
            q[sg, :, 1] = np.where(ax == 1, side, along)
        ck = circles[k]
        self.p = np.concatenate([self.p, q.reshape(-1, 2)])
        self.a = np.concatenate([self.a, ck, ck])
        self.b = np.concatenate([self.b, ck, ck])
        self.key = np.concatenate([self.key, (2 * e - 8) * self.span + ck, (2 * e - 7) * self.span + ck])

    def _add(self, t: _Table, a: np.ndarray, b: np.ndarray, rows: np.ndarray, discs: np.ndarray) -> None:
        """Add the crossings of the disc pairs ``(a, b)`` and of each of ``discs`` with each goal of ``rows``."""
        n = self.n
        cen = np.concatenate([t.pos, t.goal])
        a = np.concatenate([a, np.repeat(discs, len(rows))])
        b = np.concatenate([b, n + np.tile(rows, len(discs))])
        # Circles too far apart to cross are left out here already (as circle_crossings would).
        ok = ((cen[b] - cen[a]) ** 2).sum(axis=1) < (self.rad[a] + self.rad[b]) ** 2 * 1.01 + 1e-12
        plus, minus, a, b = circle_crossings(cen, self.rad, a[ok], b[ok])
        key = a * self.span + b
        self.p = np.concatenate([self.p, plus, minus])
        self.a = np.concatenate([self.a, a, a])
        self.b = np.concatenate([self.b, b, b])
        self.key = np.concatenate([self.key, key, key + self.span * self.span])

    def update(self, t: _Table) -> None:
        """Catch up on the discs moved and the goals reached since the last call."""
        moved, closed = t.moved[self.seen[0]:], t.closed[self.seen[1]:]
        if not moved and not closed:
            return
        self.seen = (len(t.moved), len(t.closed))
        n = self.n
        gone = np.zeros(self.span, dtype=bool)
        gone[moved] = True
        gone[n + np.asarray(closed, dtype=np.intp)] = True
        keep = ~(gone[self.a] | gone[self.b])
        self.p, self.a, self.b, self.key = self.p[keep], self.a[keep], self.b[keep], self.key[keep]
        if moved:
            m = np.array(sorted(set(moved)), dtype=np.intp)
            i = np.repeat(m, n)
            k = np.tile(np.arange(n), len(m))
            # Each pair once: with a disc that did not move, or with a moved one of higher index.
            ok = (i != k) & (~gone[k] | (k > i))
            i, k = i[ok], k[ok]
            self._add(t, np.minimum(i, k), np.maximum(i, k), np.flatnonzero(~t.done), m)
            self._add_sides(t, m)

    def near(self, t: _Table, c: np.ndarray, reach: float, near: np.ndarray, rows: np.ndarray, sides: bool
             ) -> np.ndarray:
        """The crossings of pairs of the circles of discs ``near`` and goals ``rows`` that may lie within ``reach``
        of ``c`` (a little more: the caller tests the reach itself), in a nudge's order; first those of the circles
        with the box's sides when ``sides``."""
        self.update(t)
        p = self.p
        close = (p[:, 0] - c[0]) ** 2 + (p[:, 1] - c[1]) ** 2 <= (reach + 1e-6) ** 2
        sel = np.flatnonzero(close if sides else close & (self.key >= 0))
        inn = np.zeros(self.span, dtype=bool)
        inn[near] = True
        inn[self.n + rows] = True
        sel = sel[inn[self.a[sel]] & inn[self.b[sel]]]
        return p[sel[np.argsort(self.key[sel])]]


def _within(gx: np.ndarray, gy: np.ndarray, step: float, xy: np.ndarray, rad: np.ndarray
            ) -> tuple[np.ndarray, np.ndarray]:
    """The points of the grid ``gx`` x ``gy`` (spacing ``step``) closer than ``rad[i]`` to ``xy[i]`` (none where
    ``rad[i] <= 0``), as flat indices, those of ``xy[0]`` first, then ``xy[1]``'s and so on; and how many each."""
    xy = np.atleast_2d(xy)
    rad = np.atleast_1d(rad)
    if not len(gx) or not len(gy) or not len(xy):
        return np.zeros(0, dtype=np.intp), np.zeros(len(xy), dtype=np.intp)
    k = max(1, math.ceil(2 * float(rad.max()) / step) + 2)
    w, h = len(gx), len(gy)
    ix = np.floor((xy[:, 0] - rad - gx[0]) / step).astype(np.intp)[:, None] + np.arange(k)
    iy = np.floor((xy[:, 1] - rad - gy[0]) / step).astype(np.intp)[:, None] + np.arange(k)
    ixc, iyc = np.minimum(np.maximum(ix, 0), w - 1), np.minimum(np.maximum(iy, 0), h - 1)
    dx = np.where(ix == ixc, gx[ixc] - xy[:, :1], np.inf)  # (m, k); off the grid: never inside
    dy = np.where(iy == iyc, gy[iyc] - xy[:, 1:], np.inf)
    ok = (dx[:, None, :] ** 2 + dy[:, :, None] ** 2 < (rad * rad)[:, None, None]) & (rad > 0)[:, None, None]
    return (iyc[:, :, None] * w + ixc[:, None, :])[ok], ok.reshape(len(xy), -1).sum(axis=1)


class _Stamps:
    """Per disc (or goal), the flat indices of the grid points it counts for, where it stands now: those of
    :func:`_within` for all at first, then each one's own after it moves."""

    def __init__(self, flat: np.ndarray, counts: np.ndarray) -> None:
        self.flat = flat
        self.start = np.concatenate([[0], np.cumsum(counts)]).tolist()
        self.new: dict[int, np.ndarray] = {}

    def __getitem__(self, i: int) -> np.ndarray:
        got = self.new.get(i)
        return self.flat[self.start[i]:self.start[i + 1]] if got is None else got

    def __setitem__(self, i: int, cells: np.ndarray) -> None:
        self.new[i] = cells

    def count(self, items: list[int], size: int) -> np.ndarray:
        """How many of ``items`` count for each of the ``size`` points."""
        return np.bincount(np.concatenate([self[i] for i in items] + [_NONE]), minlength=size)

    def restamp(self, items: list[int], flat: np.ndarray, counts: np.ndarray, total: np.ndarray) -> None:
        """Give ``items`` their new stamps (``flat``, ``counts`` as :func:`_within` returns them, in the order of
        ``items``), and bring ``total`` (the count at each point) up to date: one less at each point of an old
        stamp, one more at each point of a new one (a stamp holds a point once)."""
        ends = np.cumsum(counts).tolist()
        for i, a, e in zip(items, [0, *ends], ends):
            total[self[i]] -= 1
            new = flat[a:e]
            total[new] += 1
            self[i] = new

    def unstamp(self, items: list[int], total: np.ndarray) -> None:
        """One less in ``total`` at each point of the stamps of ``items`` (each item once)."""
        for i in items:
            total[self[i]] -= 1


class _Kept:
    """Counts at the points of a grid, one per disc and one per open goal standing near each point, brought up to
    date lazily: :meth:`moved` and :meth:`closed` only note what changed, :meth:`_flush` re-stamps the discs that
    moved and takes out the goals reached before the next query. A subclass keeps ``stamps`` and ``goal_stamps``
    (:class:`_Stamps`), says how a disc is stamped where it stands now (:meth:`_stamped`), which arrays hold the two
    counts (:meth:`_totals`) and what it found from them that the update makes stale (:meth:`_forget`)."""

    stamps: _Stamps
    goal_stamps: _Stamps

    def __init__(self) -> None:
        #: Discs moved and goals reached since the counts were last brought up to date.
        self.todo: list[int] = []
        self.todo_goals: list[int] = []

    def moved(self, j: int) -> None:
        """Disc ``j`` moved (applied at the next query, all moves at once)."""
        self.todo.append(j)

    def closed(self, k: int) -> None:
        """The goal of mover ``k`` is reached: it counts no more."""
        self.todo_goals.append(k)

    def _stamped(self, t: _Table, moved: list[int]) -> tuple[np.ndarray, np.ndarray]:
        raise NotImplementedError

    def _totals(self) -> tuple[np.ndarray, np.ndarray]:
        raise NotImplementedError

    def _forget(self) -> None:
        raise NotImplementedError

    def _flush(self, t: _Table) -> None:
        discs, goals = self._totals()
        if self.todo:
            moved = list(dict.fromkeys(self.todo))
            self.stamps.restamp(moved, *self._stamped(t, moved), discs)
        if self.todo_goals:
            self.goal_stamps.unstamp(self.todo_goals, goals)
        self.todo.clear()
        self.todo_goals.clear()
        self._forget()


class _Spots(_Kept):
    """Grid points where a parked disc could stand, kept up to date as discs move.

    Built the first time a disc must be parked. ``count[p]``: how many discs
    stand too close to point ``p`` for a parked disc (within the sum of the
    radii, the largest mover's for the parked one, plus the clearance);
    ``hits[p]``: how many open goals a disc at ``p`` would overlap. Each disc
    and goal touches only the points within its reach, so a move costs a few
    dozen points and a query is linear in the grid.
    """

    def __init__(self, t: _Table, bounds: tuple[float, float, float, float]) -> None:
        rmax = float(np.max(t.r[t.movers]))
        self.reach = rmax + CLEARANCE
        self.rmax = rmax
        edge = rmax / math.cos(math.pi / 24) + CLEARANCE  # the footprint polygon's reach, and the gap to the edge
        self.step = float(np.min(t.r[t.movers])) / 2
        xmin, xmax, ymin, ymax = bounds
        self.gx = np.arange(xmin + edge, xmax - edge + 1e-12, self.step)
        self.gy = np.arange(ymin + edge, ymax - edge + 1e-12, self.step)
        self.size = len(self.gx) * len(self.gy)
        #: Per disc, the points it crowds where it stands; per goal (row), the points it reaches.
        self.stamps = _Stamps(*_within(self.gx, self.gy, self.step, t.pos, t.r + self.reach))
        self.goal_stamps = _Stamps(*_within(self.gx, self.gy, self.step, t.goal, t.r[t.movers] + rmax - TOUCH))
        self.count = self.stamps.count(list(range(len(t.r))), self.size)
        self.hits = self.goal_stamps.count(np.flatnonzero(~t.done).tolist(), self.size)
        super().__init__()
        #: Per disc, the grid points its own goal disc reaches (as in ``hits``), as a mask, kept once made.
        self._goal_stamp: dict[int, np.ndarray] = {}
        #: The points no disc crowds and those one disc crowds, as the counts stand (``None``: not yet found).
        self._free: tuple[np.ndarray, np.ndarray] | None = None
        #: For :meth:`open_spot`, as the counts stand: whether a point has both counts 0, else the points with both
        #: counts at most 1 and which of the two counts is 1 there (``None``: not yet found).
        self._open: tuple[bool, np.ndarray, np.ndarray, np.ndarray] | None = None

    def _stamp(self, xy: np.ndarray, rad: np.ndarray | float) -> np.ndarray:
        """Flat indices of the grid points closer than ``rad[i]`` to centre ``xy[i]``, for every i (repeats kept)."""
        return _within(self.gx, self.gy, self.step, xy, np.atleast_1d(rad))[0]

    def _stamped(self, t: _Table, moved: list[int]) -> tuple[np.ndarray, np.ndarray]:
        return _within(self.gx, self.gy, self.step, t.pos[moved], t.r[moved] + self.reach)

    def _totals(self) -> tuple[np.ndarray, np.ndarray]:
        return self.count, self.hits

    def _forget(self) -> None:
        self._free = None
        self._open = None

    def open_spot(self, t: _Table, j: int) -> bool:
        """Whether :meth:`spot` finds disc ``j`` a point that covers no open goal (its own aside), without the query:
        a point of count 0 or of count 1 in j's own stamp (the disc crowding it is j), with no open goal or only j's
        own (its goal stamp) within reach. Both counts of such a point are at most 1, and such points are few on a
        packed table, so this tests them alone."""
        if self.todo or self.todo_goals:
            self._flush(t)
        if self._open is None:
            low = (self.count <= 1) & (self.hits <= 1)
            both0 = bool((low & (self.count == 0) & (self.hits == 0)).any())
            pts = np.flatnonzero(low)
            self._open = (both0, pts, self.count[pts] == 1, self.hits[pts] == 1)
        both0, pts, crowded, hit = self._open
        if both0:
            return True
        if not len(pts):
            return False
        # The test of spot on j's points of count 1, on these points.
        rad = t.r[j] + self.reach
        dx = self.gx[pts % len(self.gx)] - t.pos[j, 0]
        dy = self.gy[pts // len(self.gx)] - t.pos[j, 1]
        ok = ~crowded | (dx ** 2 + dy ** 2 < rad * rad)
        k = t.row[j]
        if t.done[k]:
            return bool((ok & ~hit).any())
        if j not in self._goal_stamp:
            self._goal_stamp[j] = self._goal_mask(t, j)
        return bool((ok & (~hit | self._goal_stamp[j][pts])).any())

    def _goal_mask(self, t: _Table, j: int) -> np.ndarray:
        """The grid points disc ``j``'s own goal disc reaches (as in ``hits``)."""
        mine = np.zeros(len(self.count), dtype=bool)
        mine[self.goal_stamps[t.row[j]]] = True
        return mine

    def spot(self, t: _Table, j: int) -> tuple[np.ndarray, int] | None:
        """The free point for disc ``j`` that covers the fewest open goals
        (other than its own), nearest its goal among those; with that count."""
        if self.todo or self.todo_goals:
            self._flush(t)
        k = t.row[j]
        # The points no disc crowds, and those only j crowds: a count of 1 at a point of j's own stamp (the test
        # of _stamp, on the few points of count 1 instead of j's whole window).
        if self._free is None:
            self._free = (np.flatnonzero(self.count == 0), np.flatnonzero(self.count == 1))
        free, ones = self._free
        if len(ones):
            rad = t.r[j] + self.reach
            dx = self.gx[ones % len(self.gx)] - t.pos[j, 0]
            dy = self.gy[ones // len(self.gx)] - t.pos[j, 1]
            mine = ones[dx ** 2 + dy ** 2 < rad * rad]
            if len(mine):
                free = np.sort(np.concatenate([free, mine]))
        if not len(free):
            return None
        hits = self.hits[free]
        if not t.done[k]:
            if j not in self._goal_stamp:
                self._goal_stamp[j] = self._goal_mask(t, j)
            hits = hits - self._goal_stamp[j][free]
        xy = np.stack([self.gx[free % len(self.gx)], self.gy[free // len(self.gx)]], axis=1)
        dist = np.hypot(*(xy - t.goal[k]).T)
        m = int(np.lexsort((dist, hits))[0])
        return xy[m], int(hits[m])


class _Cells(_Kept):
    """Square cells over the table, each with how many disc circles and open goal circles cover it *whole*, to
    bound what a nudge can reach before computing it (:meth:`bound`).

    The circles are those of :func:`_nudge` for the smallest disc to nudge (a larger disc's circles are larger, so a
    cell covered whole for the smallest is covered whole for every disc): about each disc ``i`` radius
    ``r_i + rmin +`` the clearance, about each open goal ``r_goal + rmin`` (less :data:`TOUCH`). A cell is counted
    when its centre is nearer than the radius less half the cell's diagonal (and a nanometre), so every point of
    it lies inside. Kept up to date as discs move and goals are reached, as :class:`_Spots` keeps its counts."""

    def __init__(self, t: _Table, bounds: tuple[float, float, float, float]) -> None:
        self.rmin = float(np.min(t.r[t.movers]))
        self.side = CELL * self.rmin
        self.half = self.side * math.sqrt(2.0) / 2
        xmin, xmax, ymin, ymax = bounds
        self.cx = xmin + self.side * (np.arange(max(1, math.ceil((xmax - xmin) / self.side))) + 0.5)
        self.cy = ymin + self.side * (np.arange(max(1, math.ceil((ymax - ymin) / self.side))) + 0.5)
        self.origin = (xmin, ymin)
        self._origin = np.array([xmin, ymin])
        self._last = np.array([len(self.cx) - 1, len(self.cy) - 1])
        self.size = len(self.cx) * len(self.cy)
        self._own = np.zeros(self.size, dtype=np.intp)  # scratch: the disc of a crowded() call marked
        #: Per disc, the cells its circle covers whole where it stands; per goal (row), those its circle covers.
        self.stamps = _Stamps(*_within(self.cx, self.cy, self.side, t.pos, self._disc_rad(t.r)))
        self.goal_stamps = _Stamps(*_within(self.cx, self.cy, self.side, t.goal, self._goal_rad(t.r[t.movers])))
        self.discs = self.stamps.count(list(range(len(t.r))), self.size)
        self.goals = self.goal_stamps.count(np.flatnonzero(~t.done).tolist(), self.size)
        super().__init__()
        #: The cells no disc circle covers whole, as the counts stand: centres and the open goals covering them whole
        #: (``None``: not yet found).
        self._zero: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None

    def _disc_rad(self, r: np.ndarray | float) -> np.ndarray:
        return np.asarray(r + self.rmin + CLEARANCE - self.half - 1e-9, dtype=float)

    def _goal_rad(self, r: np.ndarray | float) -> np.ndarray:
        return np.asarray(r + self.rmin - TOUCH - self.half - 1e-9, dtype=float)

    def _stamped(self, t: _Table, moved: list[int]) -> tuple[np.ndarray, np.ndarray]:
        return _within(self.cx, self.cy, self.side, t.pos[moved], self._disc_rad(t.r[moved]))

    def _totals(self) -> tuple[np.ndarray, np.ndarray]:
        return self.discs, self.goals

    def _forget(self) -> None:
        self._zero = None

    def crowded(self, t: _Table, j: int, p: np.ndarray) -> np.ndarray:
        """Whether each point of ``p`` (on the table) lies in a cell that the circle of a disc other than ``j`` covers
        whole: the point lies inside that disc's circle of a nudge of ``j`` (as large or larger), so no nudge of
        ``j`` stands there."""
        if self.todo or self.todo_goals:
            self._flush(t)
        # Truncation, then at least 0: the floor's cell, as the points lie at or right of and above the origin.
        ij = ((p - self._origin) / self.side).astype(np.intp)
        np.minimum(np.maximum(ij, 0, out=ij), self._last, out=ij)
        cell = ij[:, 1] * len(self.cx) + ij[:, 0]
        mine = self.stamps[j]
        self._own[mine] = 1
        out = self.discs[cell] > self._own[cell]
        self._own[mine] = 0
        return out

    def bound(self, t: _Table, j: int, freed: np.ndarray, cover: int) -> tuple[int, int] | None:
        """An upper bound on the ``(gain, cover - hits)`` of :func:`_nudge` for disc ``j``; ``None`` when the nudge
        surely finds no free place. Every candidate of the nudge lies within its reach of ``j`` and inside j's box,
        free of every other disc's circle: in a cell not covered whole by another disc's circle, and there it lies in
        every goal circle that covers the cell whole; so its gain is at most ``len(freed)`` less the goals of
        ``freed`` covering its cell whole, its hits at least the open goals but ``j``'s own covering it whole."""
        if self.todo or self.todo_goals:
            self._flush(t)
        w = len(self.cx)
        if self._zero is None:
            zero = np.flatnonzero(self.discs == 0)
            self._zero = (self.cx[zero % w], self.cy[zero // w], self.goals[zero])
        # The cells no disc covers whole, and those only j covers whole (of j's own stamp, a count of 1).
        mine = self.stamps[j]
        mine = mine[self.discs[mine] == 1]
        zx, zy, zh = self._zero
        x = np.concatenate([zx, self.cx[mine % w]])
        y = np.concatenate([zy, self.cy[mine // w]])
        c = t.pos[j]
        lo, hi = t.box(j)
        reach = NUDGE_REACH * float(t.r[j]) + self.half + 1e-9
        half = self.side / 2 + 1e-9
        sel = np.flatnonzero(((x - c[0]) ** 2 + (y - c[1]) ** 2 <= reach * reach) & (x >= lo[0] - half)
                             & (x <= hi[0] + half) & (y >= lo[1] - half) & (y <= hi[1] + half))
        if not len(sel):
            return None
        x, y, h = x[sel], y[sel], np.concatenate([zh, self.goals[mine]])[sel]
        k = t.row.get(j)
        if k is not None and not t.done[k]:
            h = h - self._covers(x, y, t.goal[k], float(self._goal_rad(t.r[j])))
        gain = np.full(len(sel), len(freed))
        for g in freed.tolist():
            gain -= self._covers(x, y, t.goal[g], float(self._goal_rad(t.r[t.movers[g]])))
        best = int(gain.max())
        return best, cover - int(h[gain == best].min())

    def _covers(self, x: np.ndarray, y: np.ndarray, xy: np.ndarray, rad: float) -> np.ndarray:
        """Whether the circle about ``xy`` of (shrunk) radius ``rad`` covers each cell of centre ``(x, y)`` whole (the
        test of :func:`_within`)."""
        if rad <= 0:
            return np.zeros(len(x), dtype=np.intp)
        return ((x - xy[0]) ** 2 + (y - xy[1]) ** 2 < rad * rad).astype(np.intp)


#: How many discs, best score first, are offered a parking spot on the grid when the goals left are blocked.
CANDIDATES = 4
#: Park only discs on a cycle when there are such (see :func:`_score`); off gives the plain score, for comparison.
CYCLES = True
#: How far (in its own radii) a nudged disc may go from where it stands (see :func:`_nudge`).
NUDGE_REACH = 6.0
#: The side of a cell of :class:`_Cells`, in radii of the smallest disc.
CELL = 0.25
#: Bound a nudge by :class:`_Cells` before computing it (off: compute every nudge the order asks for; for tests).
BOUND = True
#: Drop a nudge's candidates that lie in a cell another disc's circle covers whole (:meth:`_Cells.crowded`) before
#: the clearance test, once the cells are built (off: test them all; the same nudges; for tests).
CROWDED = True


#: Cross the circles near a nudged disc afresh each time instead of keeping them (:class:`_Crossings`; the same
#: points; for tests).
DIRECT = False
#: Nudges of a plan that cross the circles afresh before :class:`_Crossings` is built (building it crosses every
#: pair on the table once, which only pays off over many nudges; most plans need none or a few).
TABLE_AFTER = 16

_AXIS = np.array([0, 0, 1, 1])
_NONE = np.zeros(0, dtype=np.intp)
_SIGN = np.array([1.0, -1.0])[None, :, None]


@functools.lru_cache(maxsize=4096)
def _pairs(m: int, first: int) -> tuple[np.ndarray, np.ndarray]:
    """Index pairs ``a < b`` of ``m`` circles whose first member is one of the ``first`` first circles."""
    a, b = np.triu_indices(m, 1)
    keep = a < first
    return a[keep], b[keep]


def _nudge(t: _Table, j: int, freed: np.ndarray, cover: int) -> tuple[np.ndarray, int, int] | None:
    """A nearby place for disc ``j`` on a table too packed for the grid: ``(centre, hits, gain)`` or ``None``.

    Candidates lie within :data:`NUDGE_REACH` radii of where ``j`` stands: the corners of its free space (where
    it touches two other discs with the clearance, or one and a side of its box, or two sides; the same corners
    as :mod:`.dense`'s), the points where it touches a disc and just clears an open goal disc, and for each goal
    in ``freed`` (the open goals only ``j`` covers, rows of ``t``) the nearest point that clears it. Of the free
    ones (the clearance from every other disc, inside the box), the one that uncovers the most of ``freed``
    (``gain``), then covers the fewest open goals (``hits``, its own goal aside), then lies nearest its goal; it
    must uncover a goal or cover fewer than the ``cover`` open goals ``j`` covers now, so every nudge makes
    progress (a goal comes free, or fewer (goal, disc) covers remain)."""
    rj = float(t.r[j])
    c = t.pos[j]
    reach = NUDGE_REACH * rj
    lo, hi = t.box(j)
    # Discs whose clearance circle (radius r_i + r_j + clearance about them) meets the reach.
    near = np.flatnonzero(np.hypot(*(t.pos - c).T) < reach + rj + t.r + CLEARANCE)
    near = near[near != j]
    ocen, orad = t.pos[near], t.r[near] + rj + CLEARANCE
    own = t.row.get(j)
    rows = t.open_rows()
    if own is not None:
        rows = rows[rows != own]
    rows = rows[np.hypot(*(t.goal[rows] - c).T) < reach + t.r[t.movers[rows]] + rj]
    gcen, grad = t.goal[rows], t.r[t.movers[rows]] + rj
    cen = np.concatenate([ocen, gcen])
    rad = np.concatenate([orad, grad + 1e-9])  # just off a goal disc: touching, not covering
    pts = [np.array([[lo[0], lo[1]], [lo[0], hi[1]], [hi[0], lo[1]], [hi[0], hi[1]]])]
    for k in freed.tolist():
        v = c - t.goal[k]
        dv = math.hypot(float(v[0]), float(v[1]))
        if dv > 1e-12:
            pts.append((t.goal[k] + v / dv * (t.r[t.movers[k]] + rj + 1e-9))[None])
    cross = None if DIRECT else t.crossings.get(rj)
    if cross is None and not DIRECT and t.nudged >= TABLE_AFTER:
        cross = t.crossings[rj] = _Crossings(t, rj, lo, hi)
    t.nudged += 1
    # Circles with the box's sides x = lo, x = hi, y = lo, y = hi: per side, the + crossings, then the - ones
    # (kept in the table when it was built for this box). Only the sides within reach (the crossings on another
    # lie beyond it).
    kept_sides = cross is not None and cross.same_box(j, lo, hi)
    near_side = [] if kept_sides else \
        [s for s, (v, w) in enumerate(((lo[0], c[0]), (hi[0], c[0]), (lo[1], c[1]), (hi[1], c[1])))
         if abs(float(v) - float(w)) <= reach + 1e-9]
    if near_side:
        sides = np.array([lo[0], hi[0], lo[1], hi[1]])[near_side]
        off = sides[:, None] - cen[:, _AXIS[near_side]].T  # (side, circle)
        e, k = np.nonzero(np.abs(off) <= rad)
    if near_side and len(e):
        h = np.sqrt(np.maximum(rad[k] ** 2 - off[e, k] ** 2, 0.0))
        ax = _AXIS[near_side][e]
        q = np.empty((2 * len(e), 2))
        for sgn, part in ((1.0, slice(0, len(e))), (-1.0, slice(len(e), None))):
            along = cen[k, 1 - ax] + sgn * h
            q[part, 0] = np.where(ax == 0, sides[e], along)
            q[part, 1] = np.where(ax == 1, sides[e], along)
        pts.append(q[np.argsort(np.concatenate([2 * e, 2 * e + 1]), kind="stable")])
    # Circle pairs with at least one disc's circle (two goal circles' crossings lie in some disc's, as a rule).
    if cross is None:
        plus, minus, _, _ = circle_crossings(cen, rad, *_pairs(len(cen), len(ocen)))
        pts += [plus, minus]
    else:
        pts.append(cross.near(t, c, reach, near, rows, kept_sides))
    p = np.concatenate(pts)
    x, y = p[:, 0], p[:, 1]
    p = p[(x >= lo[0] - 1e-12) & (y >= lo[1] - 1e-12) & (x <= hi[0] + 1e-12) & (y <= hi[1] + 1e-12)]
    p = np.minimum(np.maximum(p, lo), hi)
    if t.cells is not None and CROWDED:
        # Not in a cell that another disc's circle covers whole: such a point is not free.
        p = p[~t.cells.crowded(t, j, p)]
    p = p[np.hypot(*(p - c).T) <= reach]
    # Squared distances (the margins below are far above their rounding). Rounding lets a point on a disc's circle
    # count as on it, not inside.
    free = ~((p[:, None, 0] - ocen[None, :, 0]) ** 2 + (p[:, None, 1] - ocen[None, :, 1]) ** 2
             < (orad * (1 - 1e-12)) ** 2).any(axis=1)
    if not free.any():
        return None
    p = p[free]
    cov = (p[:, None, 0] - gcen[None, :, 0]) ** 2 + (p[:, None, 1] - gcen[None, :, 1]) ** 2 < (grad - TOUCH) ** 2
    mark = np.zeros(len(t.movers), dtype=bool)
    mark[freed] = True
    gain = len(freed) - cov[:, mark[rows]].sum(axis=1)
    hits = cov.sum(axis=1)
    good = (gain > 0) | (hits < cover)
    if not good.any():
        return None
    p, gain, hits = p[good], gain[good], hits[good]
    dist = np.hypot(*(p - (t.goal[own] if own is not None else c)).T)
    m = int(np.lexsort((dist, hits, -gain))[0])
    return p[m], int(hits[m]), int(gain[m])


def _unchanged(t: _Table, j: int, seen: tuple, key: tuple[int, ...], cover: int, near: float) -> bool:
    """Whether an answer for disc ``j`` remembered as ``seen`` (changes seen, centre, freed goals, cover, answer) still
    holds: ``j`` stands where it stood, covers the same goals, and no disc left or arrived within ``near`` of it."""
    c = t.pos[j]
    if seen[2] != key or seen[3] != cover or seen[1] != (c[0], c[1]):
        return False
    if seen[0] == t.nchanges:
        return True
    d = t.changes[seen[0]:t.nchanges] - c
    return not bool((np.hypot(d[:, 0], d[:, 1]) < near).any())


def _cached_nudge(t: _Table, j: int, freed: np.ndarray, cover: int, floor: tuple[int, int] | None = None
                  ) -> tuple[np.ndarray, int, int] | None:
    """:func:`_nudge`, answered from the last one for ``j`` when nothing it depends on changed: ``j`` stands where
    it stood, covers the same goals, and no disc left or arrived within the reach of its discs and goals (its
    nudge looks only there; a goal closes only when a disc arrives on it).

    Else, given ``floor`` (the ``(gain, cover - hits)`` of the caller's best nudge so far; it keeps the
    first of equal ones), ``None`` without computing it where :meth:`_Cells.bound` shows that it finds nothing that
    beats ``floor``; such an answer is not remembered (the bound is). Without ``floor`` the bound is not tried: the
    first disc's nudge is nearly always needed."""
    key = tuple(freed.tolist())
    near = NUDGE_REACH * t.r[j] + t.r[j] + t.rmax + CLEARANCE + 1e-6
    seen = t.nudges.get(j)
    if seen is not None and _unchanged(t, j, seen, key, cover, near):
        return seen[4]
    if floor is not None and BOUND:
        if t.cells is None:
            t.cells = _Cells(t, t.scene.bounds)
        # The bound looks at the cells whose centre lies within the reach and half a cell's diagonal of j; a disc
        # counts for a cell within its circle's radius less that half diagonal, a goal likewise: the same ``near``.
        known = t.bounds.get(j)
        if known is not None and _unchanged(t, j, known, key, cover, near):
            most = known[4]
        else:
            most = t.cells.bound(t, j, freed, cover)
            t.bounds[j] = (t.nchanges, (t.pos[j, 0], t.pos[j, 1]), key, cover, most)
        if most is None or most <= floor:
            return None
    found = _nudge(t, j, freed, cover)
    t.nudges[j] = (t.nchanges, (t.pos[j, 0], t.pos[j, 1]), key, cover, found)
    return found


def _choose(t: _Table, spots: _Spots, score: np.ndarray, cover: np.ndarray) -> tuple[int, np.ndarray] | None:
    """The disc to park and its spot; ``None`` when no move makes progress (parking would go round in circles).

    In this order: of the :data:`CANDIDATES` best scored discs (with goals of their own), the first whose grid
    spot covers no open goal; else the best :func:`_nudge` of any candidate (most goals uncovered, then fewest
    covers left; candidates in score order, stopping once none further can do better); else the grid spot whose
    move uncovers the most goals."""
    idx = np.argsort(-score, kind="stable")
    idx = idx[(score[idx] > 0) & t.is_mover[idx]]
    order = idx.tolist()
    for j in order[:CANDIDATES]:
        # The query itself only for a disc it answers with a spot clear of the open goals (on a packed table, none).
        if spots.open_spot(t, j):
            found = spots.spot(t, j)
            assert found is not None and found[1] == 0
            return j, found[0]
    rows = np.flatnonzero(~t.done)
    b = t.blocked[rows]
    sole = t.blockers[rows] == 1
    nudge: tuple[tuple[int, int], int, np.ndarray] | None = None
    for j in order:
        freed = rows[sole & b[:, j]]
        # The best a move of j can do: uncover every goal it alone covers, and cover none.
        if nudge is not None and nudge[0] >= (len(freed), int(cover[j])):
            break
        found_n = _cached_nudge(t, j, freed, int(cover[j]), None if nudge is None else nudge[0])
        if found_n is None:
            continue
        key = (found_n[2], int(cover[j]) - found_n[1])
        if nudge is None or key > nudge[0]:
            nudge = (key, j, found_n[0])
    if nudge is not None:
        return nudge[1], nudge[2]
    best: tuple[int, int, np.ndarray] | None = None
    for j in order[:CANDIDATES]:
        found = spots.spot(t, j)
        if found is not None and int(cover[j]) - found[1] > 0 and (best is None or int(cover[j]) - found[1] > best[0]):
            best = (int(cover[j]) - found[1], j, found[0])
    return None if best is None else (best[1], best[2])


def on_cycles(adj: np.ndarray) -> np.ndarray:
    """Per node of the directed graph ``adj`` (``adj[u, v]``: an edge u -> v; no self-loops), whether it lies on
    a cycle: its strongly connected component has more than one node (Tarjan's algorithm, iterative).

    The graphs here have a few edges per node; a loop over the edges costs less than building a sparse matrix
    for a library call. The successors are read from one list by each node's first edge (the edges come by
    source), and each node on the search path keeps a pointer to its next edge."""
    m = len(adj)
    src, dst = np.nonzero(adj)
    first = np.searchsorted(src, np.arange(m + 1)).tolist()
    succ = dst.tolist()
    nxt = first[:-1]
    index = [-1] * m
    low = [0] * m
    on_stack = [False] * m
    stack: list[int] = []
    out = np.zeros(m, dtype=bool)
    counter = 0
    for root in range(m):
        if index[root] >= 0:
            continue
        index[root] = counter
        counter += 1
        if first[root] == first[root + 1]:
            continue  # no edge out: a component of its own
        low[root] = index[root]
        stack.append(root)
        on_stack[root] = True
        path = [root]
        while path:
            u = path[-1]
            e = nxt[u]
            if e < first[u + 1]:
                nxt[u] = e + 1
                v = succ[e]
                if index[v] < 0:
                    index[v] = low[v] = counter
                    counter += 1
                    stack.append(v)
                    on_stack[v] = True
                    path.append(v)
                elif on_stack[v] and index[v] < low[u]:
                    low[u] = index[v]
                continue
            path.pop()
            if path and low[u] < low[path[-1]]:
                low[path[-1]] = low[u]
            if low[u] == index[u]:
                w = stack.pop()
                on_stack[w] = False
                if w != u:  # more than one node: all on a cycle
                    comp = [w]
                    while w != u:
                        w = stack.pop()
                        on_stack[w] = False
                        comp.append(w)
                    out[comp] = True
    return out


def _score(t: _Table, b: np.ndarray) -> np.ndarray:
    """Per disc, how much parking it helps (0: not a candidate): the disc that alone covers the most goals (its
    move frees them) first, then the one that covers the most. Only discs on a cycle of "my goal is covered by
    you" are candidates when there are such: any other disc reaches its goal once the cycles are broken, so
    parking it would cost a move for nothing. ``b``: the rows of ``t.blocked`` of the open goals, in order."""
    n = len(t.r)
    score = b[t.blockers[t.open_rows()] == 1].sum(axis=0) * (n + 1) + b.sum(axis=0)
    score[t.movers[t.done]] = 0  # a disc on its goal stays
    if CYCLES:
        rows = np.flatnonzero(~t.done)
        movers = t.movers[rows]
        on_cycle = on_cycles(b[:, movers])  # open goal -> the open movers covering it
        if on_cycle.any() and (score[movers[on_cycle]] > 0).any():
            score[movers[~on_cycle]] = 0
    return score


def _action(oid: int, pose: tuple[float, float, float] | np.ndarray, purpose: str) -> Action:
    """A table placement; built without the model's checks (the numbers are finite poses on the table, and the
    validator replays the plan)."""
    return Action.model_construct(object=oid, to=(float(pose[0]), float(pose[1]), float(pose[2])), on=None,
                                  purpose=purpose)


def sequence_plan(problem: Problem, max_actions: int | None = None) -> list[Action] | None:
    """A plan for an :func:`eligible` problem by goal order and parking, or
    ``None`` when it gets stuck (no parking spot, or more than ``max_actions``
    moves, ``3 n`` by default)."""
    if not eligible(problem):
        return None
    sc = problem.scene
    t = _Table(problem)
    limit = 3 * sc.n if max_actions is None else max_actions
    spots: _Spots | None = None
    # An object that already meets its goal stays where it is, unless it covers another goal.
    at = np.hypot(*(t.pos[t.movers] - t.goal).T) <= XY_TOL
    at &= np.abs(wrap_angle(sc.initial.poses[t.movers, 2] - t.yaw)) <= YAW_TOL
    at &= ~t.blocked[:, t.movers].any(axis=0)
    t.done[at] = True
    t._open_rows = None
    actions: list[Action] = []
    while not t.done.all():
        if len(actions) >= limit:
            return None
        ready = np.flatnonzero(~t.done & (t.blockers == 0))
        if len(ready):
            for k in ready.tolist():
                if t.blockers[k]:  # a goal placed just before may cover it (goals that overlap)
                    continue
                o = int(t.movers[k])
                pose = np.array([t.goal[k, 0], t.goal[k, 1], t.yaw[k]])
                actions.append(_action(sc.ids[o], pose, "goal"))
                t.move(o, t.goal[k])
                t.close(k)
                if spots is not None:
                    spots.moved(o)
                    spots.closed(k)
            continue
        b = t.blocked[~t.done]
        score = _score(t, b)
        if spots is None:
            spots = _Spots(t, sc.bounds)
        park = _choose(t, spots, score, b.sum(axis=0))
        if park is None:
            return None
        j, spot = park
        actions.append(_action(sc.ids[j], (spot[0], spot[1], sc.initial.poses[j, 2]), "relocate"))
        t.move(j, spot)
        spots.moved(j)
    return actions


def polish_may_help(problem: Problem, actions: list[Action]) -> bool:
    """Whether polishing (:mod:`.polish`) might shorten a plan of :func:`sequence_plan`; ``False`` only when it
    surely cannot, so the plan is validated without it.

    For a disc that moves more than once (parked, perhaps parked again, then to its goal), polishing tries at
    each of its moves but the last to send it straight to its goal there, dropping its later moves (merge), and
    to leave it where it stood until its next move (drop), and to drop its last move; it replays the plan from
    there with the search's rules: a placement keeps the clearance from every other disc, or for a goal
    placement at most touches it. A merge surely fails when a disc stands on the goal at that move, or a
    placement before the last move overlaps the goal; a drop when a placement before the disc's next move
    overlaps where it stood (as circles, by more than a margin); dropping the last move when the disc's place
    before it is farther from its goal than the pose goals' acceptance tolerance (and a millimetre). Any other
    kind of move (a first move that is not a parking) leaves the answer to polishing."""
    sc = problem.scene
    r = np.asarray(sc.discs, dtype=float)
    obj = [sc.index[a.object] for a in actions]
    moves: dict[int, list[int]] = {}
    for k, o in enumerate(obj):
        moves.setdefault(o, []).append(k)
    again = {o: ks for o, ks in moves.items() if len(ks) > 1}
    if not again:
        return False
    to = np.array([a.to[:2] for a in actions], dtype=float)
    reloc = np.array([a.purpose == "relocate" for a in actions])
    # How close a placed disc may come to another before the replay surely refuses it (a margin below the rule).
    gap = np.where(reloc, 0.98 * CLEARANCE, -1e-6)
    pos = np.array(sc.initial.poses[:, :2], dtype=float)
    before: list[np.ndarray] = []
    for k, o in enumerate(obj):
        before.append(pos.copy())
        pos[o] = to[k]
    idx = np.asarray(obj)

    def overlaps(steps: np.ndarray, o: int, xy: np.ndarray) -> bool:
        """Whether a placement of ``steps`` surely overlaps disc ``o`` standing at ``xy``."""
        lim = r[idx[steps]] + r[o] + gap[steps]
        return bool((np.hypot(*(to[steps] - xy).T) < lim).any())

    for o, ks in again.items():
        last = ks[-1]
        if not reloc[ks[:-1]].all() or actions[last].purpose != "goal" \
                or math.hypot(*(to[ks[-2]] - to[last])) <= TOL + 1e-3:
            return True
        goal = to[last]
        others = np.arange(sc.n) != o
        for m, i in enumerate(ks[:-1]):
            drop_fails = overlaps(np.arange(i + 1, ks[m + 1]), o, before[i][o])
            rest = np.arange(i + 1, last)
            rest = rest[idx[rest] != o]
            merge_fails = bool((np.hypot(*(before[i][others] - goal).T) < r[others] + r[o] - 1e-6).any()) \
                or overlaps(rest, o, goal)
            if not (drop_fails and merge_fails):
                return True
    return False
