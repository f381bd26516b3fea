"""The fast first attempt for pose goals on discs (lgmcts.planner.sequence)."""

from __future__ import annotations

import math
from contextlib import contextmanager

import numpy as np
from disc_cases import disc_case, disc_problem
from hypothesis import given, settings
from hypothesis import strategies as st

import lgmcts.planner.sequence as seq
from lgmcts import PlanSpec, check, plan
from lgmcts.errors import InputError
from lgmcts.patterns import CLEARANCE
from lgmcts.planner.problem import Problem
from lgmcts.planner.search import SearchOptions
from lgmcts.planner.sequence import eligible, sequence_plan
from lgmcts.scene import Scene


def _scatter(rng: np.random.Generator, n: int, radius: float) -> list[tuple[float, float]] | None:
    """``n`` non-overlapping disc centres in TRLB's square, by rejection; ``None`` when they do not fit."""
    pts: list[tuple[float, float]] = []
    for _ in range(200 * n):
        p = rng.uniform(radius, 1000 - radius, 2)
        if all(math.hypot(p[0] - q[0], p[1] - q[1]) >= 2 * radius for q in pts):
            pts.append((float(p[0]), float(p[1])))
            if len(pts) == n:
                return pts
    return None


def test_swap_in_a_row_parks_one_disc_off_every_goal():
    # Three discs in a row, touching; the goal rotates them: a cycle, broken by one parked disc.
    r = 100.0
    row = [(300.0, 500.0), (500.0, 500.0), (700.0, 500.0)]
    c = disc_case(row, row[1:] + row[:1], r)
    pr = disc_problem(c)
    assert eligible(pr)
    actions = sequence_plan(pr)
    assert actions is not None and len(actions) == 4
    parked = [a for a in actions if a.purpose == "relocate"]
    assert len(parked) == 1
    spot = np.array(parked[0].to[:2])
    for g in c.goals.goals:
        assert np.hypot(*(spot - np.array(g.pose[:2]))) >= 2 * r / 1000 - 1e-9  # it covers no goal
    p = plan(c.scene, c.goals, seed=0)
    assert p.solved and p.stats.get("sequenced") and len(p.actions) == 4
    assert check(c.scene, c.goals, p).valid


def test_no_room_to_park_falls_back_to_the_search():
    # Two discs swap in a box that holds just the two: no spot to park, so no plan here, and the
    # planner's answer is the tree search's (here: no plan either, with its reason).
    r = 100.0
    c = disc_case([(100.0, 100.0), (300.0, 100.0)], [(300.0, 100.0), (100.0, 100.0)], r, width=400.0, height=200.0)
    pr = disc_problem(c)
    assert eligible(pr) and sequence_plan(pr) is None
    p = plan(c.scene, c.goals, seed=0, max_iter=200)
    q = plan(c.scene, c.goals, seed=0, max_iter=200, options=SearchOptions(sequence=False))
    assert not p.solved and "sequenced" not in p.stats
    assert p.model_dump(exclude={"stats"}) == q.model_dump(exclude={"stats"})
    assert p.stats["reason"] == q.stats["reason"]


def test_not_eligible_leaves_the_search_alone():
    from lgmcts.casegen import random_case

    c = random_case(3)  # pattern goals and boxes: not this path's setting
    assert not eligible(Problem.build(Scene.from_spec(c.scene), c.goals))
    p = plan(c.scene, c.goals, seed=0, max_iter=500)
    q = plan(c.scene, c.goals, seed=0, max_iter=500, options=SearchOptions(sequence=False))
    assert "sequenced" not in p.stats
    assert p.actions == q.actions


def test_a_disc_already_on_its_goal_stays():
    r = 60.0
    start = [(200.0, 200.0), (500.0, 500.0), (800.0, 800.0)]
    goal = [(200.0, 200.0), (800.0, 200.0), (500.0, 800.0)]
    c = disc_case(start, goal, r)
    actions = sequence_plan(disc_problem(c))
    assert actions is not None and [a.object for a in actions] == [2, 3]
    assert all(a.purpose == "goal" for a in actions)


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 10_000), n=st.integers(2, 14), density=st.sampled_from([0.2, 0.3, 0.4]))
def test_plans_pass_the_validator_and_do_not_depend_on_the_seed(seed, n, density):
    rng = np.random.default_rng(seed)
    radius = math.sqrt(density * 1e6 / (math.pi * n))
    start, goal = _scatter(rng, n, radius), _scatter(rng, n, radius)
    if start is None or goal is None:
        return
    c = disc_case(start, goal, radius)
    pr = disc_problem(c)
    actions = sequence_plan(pr)
    if actions is not None:
        assert sequence_plan(pr) == actions
        assert sum(a.purpose == "goal" for a in actions) <= n
        # Every disc that moves ends on its goal; only parked discs move twice.
        assert len(actions) <= n + sum(a.purpose == "relocate" for a in actions)
    p = plan(c.scene, c.goals, seed=0, max_iter=300)
    q = plan(c.scene, c.goals, seed=seed + 1, max_iter=300)
    if p.stats.get("sequenced"):
        assert p.solved and check(c.scene, c.goals, p).valid
        assert q.actions == p.actions


def test_only_a_disc_on_a_cycle_is_parked():
    # A and B each cover the other's goal (a cycle). C's goal is under A, and C covers the goals of D, E and F:
    # C frees the most goals, but it is on no cycle, so it waits for A to leave; one disc is parked, not two.
    r = 50.0
    start = [(200.0, 500.0), (301.0, 500.0), (600.0, 500.0), (150.0, 150.0), (300.0, 150.0), (450.0, 150.0)]
    goal = [(330.0, 560.0), (170.0, 440.0), (200.0, 590.0), (600.0, 580.0), (530.0, 450.0), (670.0, 450.0)]
    c = disc_case(start, goal, r)
    actions = sequence_plan(disc_problem(c))
    assert actions is not None
    parked = [a.object for a in actions if a.purpose == "relocate"]
    assert len(actions) == 7 and len(parked) == 1 and parked[0] in (1, 2)
    p = plan(c.scene, c.goals, seed=0)
    assert p.solved and p.stats.get("sequenced") and check(c.scene, c.goals, p).valid


def test_a_robot_leaves_the_plan_to_the_search():
    # The fast attempt knows nothing of an arm's reach: with a robot the tree search plans, within reach.
    r = 30.0
    row = [(400.0, 500.0), (460.0, 500.0), (520.0, 500.0)]
    c = disc_case(row, row[1:] + row[:1], r)
    p = plan(c.scene, c.goals, seed=0, max_iter=500, robot="ur5e")
    assert "sequenced" not in p.stats and p.stats["robot"] == "ur5e"
    assert plan(c.scene, c.goals, seed=0, max_iter=500).stats.get("sequenced")


def _dense_case(seed: int, n: int, density: float):
    rng = np.random.default_rng(seed)
    radius = math.sqrt(density * 1e6 / (math.pi * n))
    start, goal = _scatter(rng, n, radius), _scatter(rng, n, radius)
    return None if start is None or goal is None else disc_case(start, goal, radius)


def _parked_clear_of_the_others(c, actions) -> bool:
    """Whether every parked disc stands, where it is parked, at least the clearance away from every other disc."""
    sc = Scene.from_spec(c.scene)
    pos = np.array(sc.initial.poses[:, :2])
    for a in actions:
        i = sc.index[a.object]
        pos[i] = a.to[:2]
        if a.purpose == "relocate":
            gap = np.hypot(*(pos - pos[i]).T) - sc.discs - sc.discs[i]
            gap[i] = np.inf
            if gap.min() < CLEARANCE - 1e-9:
                return False
    return True


def test_a_nudge_plans_where_no_grid_spot_uncovers_a_goal(monkeypatch):
    # Six discs at 40 % density: once the goals that are free are reached, every grid spot for the blocking discs
    # covers as many goals as they do; a short slide of one disc frees a goal, and the rest follows.
    c = _dense_case(11, 6, 0.4)
    assert c is not None
    pr = disc_problem(c)
    actions = sequence_plan(pr)
    assert actions is not None and sequence_plan(pr) == actions
    assert check(c.scene, c.goals, PlanSpec(solved=True, actions=actions, goals=c.goals)).valid
    assert _parked_clear_of_the_others(c, actions)
    # Without the nudge (no reach), the attempt is stuck on the same table.
    monkeypatch.setattr(seq, "NUDGE_REACH", 0.0)
    assert sequence_plan(pr) is None


@settings(max_examples=25, deadline=None)
@given(seed=st.integers(0, 10_000), n=st.integers(4, 12), density=st.sampled_from([0.35, 0.4, 0.45]))
def test_nudged_plans_are_valid_and_keep_the_clearance(seed, n, density):
    c = _dense_case(seed, n, density)
    if c is None:
        return
    actions = sequence_plan(disc_problem(c))
    if actions is None:
        return
    assert check(c.scene, c.goals, PlanSpec(solved=True, actions=actions, goals=c.goals)).valid
    assert _parked_clear_of_the_others(c, actions)
    # Every disc ends on its goal; a parked disc moves again, so the plan has n + (parked) actions at most.
    assert len(actions) <= n + sum(a.purpose == "relocate" for a in actions)


@settings(max_examples=60, deadline=None)
@given(st.integers(1, 12).flatmap(lambda m: st.lists(st.lists(st.booleans(), min_size=m, max_size=m),
                                                       min_size=m, max_size=m)))
def test_on_cycles_finds_the_nodes_that_reach_themselves(rows):
    adj = np.array(rows, dtype=bool)
    np.fill_diagonal(adj, False)
    # Reference: the transitive closure by repeated relaxation; a node is on a cycle when it reaches itself.
    reach = adj.copy()
    for k in range(len(adj)):
        reach |= reach[:, k:k + 1] & reach[k:k + 1, :]
    assert np.array_equal(seq.on_cycles(adj), np.diag(reach))


@settings(max_examples=40, deadline=None)
@given(seed=st.integers(0, 10_000), n=st.integers(4, 14), density=st.sampled_from([0.3, 0.4, 0.45]))
def test_a_plan_polishing_cannot_shorten_is_left_as_it_is(seed, n, density):
    # polish_may_help says False only where polishing would return the plan unchanged (then it is not run).
    from lgmcts.planner.polish import polished

    c = _dense_case(seed, n, density)
    if c is None:
        return
    pr = disc_problem(c)
    actions = sequence_plan(pr)
    if actions is None or seq.polish_may_help(pr, actions):
        return
    assert polished(pr, actions) == actions


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 10_000), n=st.integers(6, 16), density=st.sampled_from([0.4, 0.45]))
def test_a_remembered_nudge_gives_the_same_plan_as_a_fresh_one(seed, n, density):
    c = _dense_case(seed, n, density)
    if c is None:
        return
    pr = disc_problem(c)
    cached = sequence_plan(pr)
    fresh = seq._cached_nudge
    try:
        seq._cached_nudge = lambda t, j, freed, cover, *bound: seq._nudge(t, j, freed, cover)
        assert sequence_plan(pr) == cached
    finally:
        seq._cached_nudge = fresh


def _mixed(c, seed: int):
    """The case with some discs shrunk (still apart where they stand and at their goals): radii of two or three
    sizes, so that the crossings kept per radius are several."""
    rng = np.random.default_rng(seed)
    objects = []
    for o in c.scene.objects:
        f = float(rng.choice([1.0, 0.9, 0.8]))
        objects.append(o.model_copy(update={"shape": o.shape.model_copy(update={"radius": o.shape.radius * f})}))
    return c.scene.model_copy(update={"objects": objects})


def _turned(scene, seed: int):
    """The scene with some discs standing at another yaw: their footprint polygons turn, so their boxes (where
    the centre may go) differ a little from the others' of the same radius."""
    rng = np.random.default_rng(seed + 1)
    objects = []
    for o in scene.objects:
        if rng.random() < 0.5:
            o = o.model_copy(update={"pose": (o.pose[0], o.pose[1], float(rng.uniform(-math.pi, math.pi)))})
        objects.append(o)
    return scene.model_copy(update={"objects": objects})


def _varied_problem(seed: int, n: int, density: float, mixed: bool, turned: bool = False) -> Problem | None:
    """A dense disc case as a problem, its radii mixed and its discs turned where asked (None: no case, or a turned
    disc whose footprint polygon reaches past the workspace, which the scene refuses)."""
    c = _dense_case(seed, n, density)
    if c is None:
        return None
    scene = _mixed(c, seed) if mixed else c.scene
    if turned:
        scene = _turned(scene, seed)
        try:
            Scene.from_spec(scene)
        except InputError:
            return None
    return Problem.build(Scene.from_spec(scene), c.goals)


def _assert_same_answers(pairs) -> None:
    """Each pair of answers (a point or nudge first, then what goes with it) is the same: both none, or the same
    point to the last bit and the same rest."""
    for got, ref in pairs:
        assert (got is None) == (ref is None)
        if got is not None and ref is not None:
            assert np.array_equal(got[0], ref[0]) and got[1:] == ref[1:]


@contextmanager
def _replaced(owner, name: str, fn):
    """``owner.name`` replaced by ``fn`` while the block runs."""
    kept = getattr(owner, name)
    setattr(owner, name, fn)
    try:
        yield kept
    finally:
        setattr(owner, name, kept)


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 10_000), n=st.integers(6, 30), density=st.sampled_from([0.4, 0.45, 0.5]),
       mixed=st.booleans(), turned=st.booleans())
def test_kept_crossings_give_the_nudges_of_crossing_afresh(seed, n, density, mixed, turned):
    # Each nudge of a plan, with the circle crossings (of circle pairs, and of circles with the box's sides where
    # the disc's box is the table's) kept up to date as discs move (_Crossings), is the nudge of crossing the
    # circles near the disc afresh, to the last bit; so is the plan.
    pr = _varied_problem(seed, n, density, mixed, turned)
    if pr is None:
        return
    kept = seq._nudge
    calls = []

    def both(t, j, freed, cover):
        got = kept(t, j, freed, cover)
        seq.DIRECT = True
        try:
            fresh = kept(t, j, freed, cover)
        finally:
            seq.DIRECT = False
        calls.append((got, fresh))
        return got

    table_after = seq.TABLE_AFTER
    try:
        seq._nudge = both
        seq.TABLE_AFTER = 0  # the table from the first nudge on
        plan_kept = sequence_plan(pr)
    finally:
        seq._nudge = kept
        seq.TABLE_AFTER = table_after
    _assert_same_answers(calls)
    seq.DIRECT = True
    try:
        assert sequence_plan(pr) == plan_kept
    finally:
        seq.DIRECT = False


def _spot_by_stamps(spots, t, j):
    """A grid spot for disc ``j`` found as the query did before it kept the points of count 0 and 1: every point
    of count 0, and those of count 1 within j's own stamp (its whole window stamped afresh)."""
    if spots.todo or spots.todo_goals:
        spots._flush(t)
    k = t.row[j]
    mask = spots.count == 0
    own = spots._stamp(t.pos[j], t.r[j] + spots.reach)
    mask[own] = spots.count[own] == 1
    free = np.flatnonzero(mask)
    if not len(free):
        return None
    hits = spots.hits[free]
    if not t.done[k]:
        mine = np.zeros(len(spots.count), dtype=bool)
        mine[spots._stamp(t.goal[k], t.r[j] + spots.rmax - seq.TOUCH)] = True
        hits = hits - mine[free]
    w = len(spots.gx)
    xy = np.stack([spots.gx[free % w], spots.gy[free // w]], axis=1)
    m = int(np.lexsort((np.hypot(*(xy - t.goal[k]).T), hits))[0])
    return xy[m], int(hits[m])


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 10_000), n=st.integers(6, 40), density=st.sampled_from([0.3, 0.4, 0.5]),
       mixed=st.booleans())
def test_a_grid_spot_is_the_one_found_by_stamping_the_disc_afresh(seed, n, density, mixed):
    # The grid query tests only the points of count 1 against the disc's own stamp; each answer of a plan is the
    # one of stamping the disc's whole window (the same point to the last bit, the same count).
    pr = _varied_problem(seed, n, density, mixed)
    if pr is None:
        return
    kept = seq._Spots.spot
    calls = []

    def both(self, t, j):
        got = kept(self, t, j)
        calls.append((got, _spot_by_stamps(self, t, j)))
        return got

    with _replaced(seq._Spots, "spot", both):
        sequence_plan(pr)
    _assert_same_answers(calls)


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 10_000), n=st.integers(6, 40), density=st.sampled_from([0.4, 0.45, 0.5, 0.55]),
       mixed=st.booleans(), turned=st.booleans())
def test_a_nudge_never_beats_its_cell_bound(seed, n, density, mixed, turned):
    # Wherever the plan looks for a nudge, the bound of the cells is at least what the nudge finds: (gain,
    # cover - hits) no larger, and no nudge where the bound says none; radii of several sizes and boxes that
    # differ (turned discs) included.
    pr = _varied_problem(seed, n, density, mixed, turned)
    if pr is None:
        return
    kept = seq._cached_nudge
    pairs = []

    def both(t, j, freed, cover, floor=None):
        got = kept(t, j, freed, cover, floor)
        if t.cells is not None:
            nudged = t.nudged
            fresh = seq._nudge(t, j, freed, cover)
            t.nudged = nudged
            pairs.append((t.cells.bound(t, j, freed, cover), fresh, cover))
        return got

    with _replaced(seq, "_cached_nudge", both):
        sequence_plan(pr)
    for most, fresh, cover in pairs:
        if fresh is not None:
            assert most is not None and (fresh[2], cover - fresh[1]) <= most


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 10_000), n=st.integers(6, 40), density=st.sampled_from([0.4, 0.45, 0.5, 0.55]),
       mixed=st.booleans(), turned=st.booleans())
def test_candidates_dropped_in_crowded_cells_are_never_free(seed, n, density, mixed, turned):
    # A nudge drops the candidates in cells that another disc's circle covers whole (_Cells.crowded) before the
    # clearance test: each nudge is the one of testing every candidate, to the last bit, and every point of the
    # table such a cell holds lies inside the circle of a disc other than the nudged one (radius r_i + r_j + the
    # clearance), so it is never free; radii of several sizes and turned discs included.
    pr = _varied_problem(seed, n, density, mixed, turned)
    if pr is None:
        return
    kept = seq._nudge
    rng = np.random.default_rng(seed)
    calls = []
    inside = []

    def both(t, j, freed, cover):
        got = kept(t, j, freed, cover)
        if t.cells is not None:
            nudged = t.nudged
            seq.CROWDED = False
            try:
                full = kept(t, j, freed, cover)
            finally:
                seq.CROWDED = True
            t.nudged = nudged
            calls.append((got, full))
            xmin, xmax, ymin, ymax = t.scene.bounds
            p = rng.uniform([xmin, ymin], [xmax, ymax], size=(300, 2))
            p = p[t.cells.crowded(t, j, p)]
            others = np.arange(len(t.r)) != j
            d = np.hypot(p[:, None, 0] - t.pos[None, others, 0], p[:, None, 1] - t.pos[None, others, 1])
            inside.append(bool((d < t.r[others] + t.r[j] + CLEARANCE).any(axis=1).all()))
        return got

    with _replaced(seq, "_nudge", both):
        sequence_plan(pr)
    assert all(inside)
    _assert_same_answers(calls)


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 10_000), n=st.integers(6, 40), density=st.sampled_from([0.4, 0.45, 0.5, 0.55]),
       mixed=st.booleans())
def test_nudges_skipped_by_their_bound_leave_the_plan_as_it_was(seed, n, density, mixed):
    pr = _varied_problem(seed, n, density, mixed)
    if pr is None:
        return
    bounded = sequence_plan(pr)
    try:
        seq.BOUND = False
        assert sequence_plan(pr) == bounded
    finally:
        seq.BOUND = True


@settings(max_examples=20, deadline=None)
@given(seed=st.integers(0, 10_000), n=st.integers(6, 40), density=st.sampled_from([0.3, 0.4, 0.5]),
       mixed=st.booleans())
def test_open_spot_says_whether_the_grid_spot_covers_no_goal(seed, n, density, mixed):
    # The cheap test before a grid query answers as the query would: a spot of no open goal (but the disc's own).
    pr = _varied_problem(seed, n, density, mixed)
    if pr is None:
        return
    kept = seq._Spots.open_spot
    calls = []

    def both(self, t, j):
        got = kept(self, t, j)
        found = self.spot(t, j)
        calls.append((got, found is not None and found[1] == 0))
        return got

    with _replaced(seq._Spots, "open_spot", both):
        sequence_plan(pr)
    assert all(got == ref for got, ref in calls)
