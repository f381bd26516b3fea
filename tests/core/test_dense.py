"""The best-first search over free-space corners for a few tightly packed discs (lgmcts.planner.dense)."""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest
from disc_cases import disc_case, disc_problem
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from lgmcts import check, plan
from lgmcts.confinement import confined
from lgmcts.formats import PlanSpec
from lgmcts.planner import dense
from lgmcts.planner.search import SearchOptions
from lgmcts.planner.sequence import sequence_plan
from lgmcts.scene import Scene


def _scatter(rng: np.random.Generator, n: int, radius: float, width: float, height: float):
    pts: list[np.ndarray] = []
    for _ in range(3000):
        p = rng.uniform([radius, radius], [width - radius, height - radius])
        if all(math.hypot(*(p - q)) >= 2 * radius for q in pts):
            pts.append(p)
            if len(pts) == n:
                return np.array(pts)
    return None


# Three discs of 8 cm in a 60 x 30 cm box: the sequence finds no grid spot that uncovers a goal.
NARROW = (600.0, 300.0, 80.0, [(368, 161), (166, 158), (519, 82)], [(207, 181), (373, 169), (519, 104)])


def test_narrow_box_stuck_sequence_is_planned_by_the_corner_search():
    w, h, r, a, b = NARROW
    c = disc_case(a, b, r, w, h)
    pr = disc_problem(c)
    assert sequence_plan(pr) is None
    actions = dense.dense_plan(pr)
    assert actions is not None
    assert check(c.scene, c.goals, PlanSpec(solved=True, actions=actions, goals=c.goals)).valid
    p = plan(c.scene, c.goals, seed=0)
    assert p.solved and p.stats.get("dense") and p.stats["corner_states"] >= 1 and check(c.scene, c.goals, p).valid
    # The same plan again for the same seed (no time limit: nothing depends on the clock).
    again = plan(c.scene, c.goals, seed=0)
    assert [a.model_dump() for a in again.actions] == [a.model_dump() for a in p.actions]
    # Off, the tree search plans it as before, without the flag.
    q = plan(c.scene, c.goals, seed=0, max_iter=20, options=SearchOptions(dense=False))
    assert "dense" not in q.stats


def test_corners_are_free_inside_and_touch_two_constraints():
    rng = np.random.default_rng(3)
    c = disc_case(_scatter(rng, 6, 120.0, 1000.0, 1000.0), _scatter(rng, 6, 120.0, 1000.0, 1000.0), 120.0)
    t = dense._Discs(disc_problem(c))
    pos = t.start
    for i, pts in enumerate(t.corners(pos)):
        assert len(pts)
        others = np.delete(np.arange(t.n), i)
        dist = np.hypot(pts[:, None, 0] - pos[None, others, 0], pts[:, None, 1] - pos[None, others, 1])
        slack = dist - t.far[i, others][None, :]
        assert (slack >= -1e-9).all()
        assert ((pts >= t.lo[i] - 1e-12) & (pts <= t.hi[i] + 1e-12)).all()
        # A corner of the free space: two of its constraints (discs or box sides) are tight.
        edges = np.concatenate([np.abs(pts - t.lo[i]), np.abs(pts - t.hi[i])], axis=1)
        tight = (np.abs(slack) < 1e-9).sum(axis=1) + (edges < 1e-12).sum(axis=1)
        assert (tight >= 2).all()


def test_goals_already_met_give_the_empty_plan_and_large_tables_are_left_alone():
    pts = [(200.0, 200.0), (600.0, 600.0)]
    assert dense.dense_plan(disc_problem(disc_case(pts, pts, 100.0))) == []
    rng = np.random.default_rng(0)
    many = _scatter(rng, dense.MAX_DISCS + 1, 40.0, 1000.0, 1000.0)
    assert dense.dense_plan(disc_problem(disc_case(many, many[::-1], 40.0))) is None


def test_budget_ends_a_search_with_no_plan():
    # Two discs that fill a box trade places: no plan exists, and the search gives up at its budget.
    c = disc_case([(100.0, 100.0), (300.0, 100.0)], [(300.0, 100.0), (100.0, 100.0)], 100.0, width=400.0, height=200.0)
    actions, expanded = dense.search(disc_problem(c), 50, None)
    assert actions is None and expanded <= 50
    # The planner proves it at once (lgmcts.confinement, asked before the corner search) ...
    p = plan(c.scene, c.goals, seed=0, max_iter=40)
    assert not p.solved and p.stats.get("infeasible") and "corner_states" not in p.stats
    # ... and without the proof says what it tried: the corner search's states and the tree search's budget.
    q = plan(c.scene, c.goals, seed=0, max_iter=40, options=SearchOptions(proof_after=0))
    assert not q.solved and not q.stats.get("infeasible")
    assert 1 <= q.stats["corner_states"] <= dense.budget(2) and q.stats["iterations"] == 40
    # The one-line reason says so too.
    assert f"and {q.stats['corner_states']} table states of the corner search;" in q.stats["reason"]


def _corners_one_by_one(t, pos: np.ndarray, i: int) -> np.ndarray:
    """Disc ``i``'s free-space corners the plain way: every crossing of two other discs' circles, of one with a side
    of ``i``'s box, and the box's own corners, kept where inside the box and no other circle holds them."""
    lo, hi = t.lo[i], t.hi[i]
    others = [k for k in range(t.n) if k != i]
    pts = [(lo[0], lo[1]), (lo[0], hi[1]), (hi[0], lo[1]), (hi[0], hi[1])]
    for k in others:
        rk = t.far[i, k]
        for axis, value in ((0, lo[0]), (0, hi[0]), (1, lo[1]), (1, hi[1])):
            off = value - pos[k, axis]
            if abs(off) <= rk:
                h = math.sqrt(max(rk * rk - off * off, 0.0))
                for sgn in (1.0, -1.0):
                    q = [0.0, 0.0]
                    q[axis], q[1 - axis] = value, pos[k, 1 - axis] + sgn * h
                    pts.append((q[0], q[1]))
    for x, k in enumerate(others):
        for m in others[x + 1:]:
            d = math.hypot(*(pos[m] - pos[k]))
            ra, rb = t.far[i, k], t.far[i, m]
            if 1e-12 < d < ra + rb and d > abs(ra - rb):
                u = (pos[m] - pos[k]) / d
                a = (d * d + ra * ra - rb * rb) / (2 * d)
                h = math.sqrt(max(ra * ra - a * a, 0.0))
                base = pos[k] + u * a
                for sgn in (1.0, -1.0):
                    pts.append(tuple(base + sgn * h * np.array([-u[1], u[0]])))
    p = np.array(pts, dtype=float)
    p = np.clip(p[((p >= lo - 1e-12) & (p <= hi + 1e-12)).all(axis=1)], lo, hi)
    held = np.hypot(p[:, None, 0] - pos[None, others, 0], p[:, None, 1] - pos[None, others, 1]) \
        < t.far[i, others][None, :] * (1 - 1e-12)
    return p[~held.any(axis=1)]


@settings(max_examples=25, deadline=None)
@given(st.integers(2, 9), st.floats(60.0, 140.0), st.integers(0, 10_000))
def test_corners_are_those_found_one_disc_and_one_pair_at_a_time(n, r, seed):
    # The corners judged for all discs of a group at once are, disc by disc, the corners found the plain way.
    rng = np.random.default_rng(seed)
    a = _scatter(rng, n, r, 1000.0, 800.0)
    if a is None:
        return
    t = dense._Discs(disc_problem(disc_case(a, a[::-1], r, 1000.0, 800.0)))
    for i, got in enumerate(t.corners(t.start)):
        want = _corners_one_by_one(t, t.start, i)
        assert len(got) == len(want)
        got, want = got[np.lexsort(got.T)], want[np.lexsort(want.T)]
        assert np.allclose(got, want, atol=1e-9)


def _random_case(n: int, r: float, box: tuple[float, float], seed: int):
    """Two random packings of ``n`` discs in ``box`` as start and goal, or None where one does not fit."""
    w, h = box
    rng = np.random.default_rng(seed)
    a, b = _scatter(rng, n, r, w, h), _scatter(rng, n, r, w, h)
    return None if a is None or b is None else disc_case(a, b, r, w, h)


@settings(max_examples=10, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(3, 5), st.floats(60.0, 85.0), st.sampled_from([(500.0, 400.0), (600.0, 300.0), (500.0, 500.0)]),
       st.integers(0, 10_000))
def test_every_plan_found_is_valid_and_the_same_each_time(n, r, box, seed):
    c = _random_case(n, r, box, seed)
    if c is None:
        return
    actions, _ = dense.search(disc_problem(c), 300, None)
    if actions is None:
        return
    assert check(c.scene, c.goals, PlanSpec(solved=True, actions=actions, goals=c.goals)).valid
    # A plan exists, so the confinement proof must not claim otherwise.
    assert confined(Scene.from_spec(c.scene), c.goals) is None
    again, _ = dense.search(disc_problem(c), 300, None)
    assert again is not None and [x.model_dump() for x in again] == [x.model_dump() for x in actions]


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(3, 5), st.floats(60.0, 85.0), st.sampled_from([(500.0, 400.0), (600.0, 300.0)]),
       st.integers(0, 10_000))
def test_a_backward_search_read_in_reverse_is_a_valid_plan(n, r, box, seed):
    c = _random_case(n, r, box, seed)
    if c is None:
        return
    t = dense._Discs(disc_problem(c), reverse=True)
    assert dense._reversible(t)
    actions, _ = dense._Search(t).run(300, None)
    if actions is None:
        return
    assert check(c.scene, c.goals, PlanSpec(solved=True, actions=actions, goals=c.goals)).valid
    # Every goal move of the plan puts its disc exactly on its goal.
    goal = {g.objects[0]: g.pose[:2] for g in c.goals.goals}
    assert all(x.to[:2] == pytest.approx(goal[x.object], abs=1e-12) for x in actions if x.purpose == "goal")


def test_further_searches_take_turns_where_the_first_two_find_nothing():
    # Seven discs at 58 % of a 1 m square: neither the first search nor the backward one finds a plan in 20 states.
    c = _packed(22, 7, 0.58)
    pr = disc_problem(c)
    assert dense._Search(dense._Discs(pr)).run(20, None)[0] is None
    assert dense._Search(dense._Discs(pr, reverse=True)).run(20, None)[0] is None
    # One of the further searches does, within their budget; the plan is valid and the same each time.
    actions, expanded = dense.search(pr, 20, None)
    assert actions is not None and 2 * 20 < expanded <= (2 + sum(m[-1] for m in dense.MORE)) * 20
    assert check(c.scene, c.goals, PlanSpec(solved=True, actions=actions, goals=c.goals)).valid
    assert confined(Scene.from_spec(c.scene), c.goals) is None
    again, _ = dense.search(pr, 20, None)
    assert again is not None and [x.model_dump() for x in again] == [x.model_dump() for x in actions]


def test_forwards_and_backwards_take_turns_from_the_start():
    # Seven discs at 60 %: forwards finds nothing in 1000 states, backwards plans in 565. Taking turns of SLICE
    # states, the backward plan comes after three turns each (not after the forward search's whole budget).
    pr = disc_problem(_packed(36, 7, 0.60))
    assert dense._Search(dense._Discs(pr)).run(1000, None)[0] is None
    back, b = dense._Search(dense._Discs(pr, reverse=True)).run(1000, None)
    assert back is not None and dense.SLICE < b <= 1000
    actions, expanded = dense.search(pr, 1000, None)
    turns = -(-b // dense.SLICE)
    assert expanded == turns * dense.SLICE + b < 1000 + b
    assert actions is not None and [x.model_dump() for x in actions] == [x.model_dump() for x in back]


@settings(max_examples=8, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(st.integers(4, 7), st.sampled_from([0.5, 0.55, 0.6]), st.integers(0, 10_000), st.booleans(),
       st.sampled_from([0.0, 1.0, 2.0]), st.sampled_from([0.0, 1.0, 2.5]))
def test_each_rank_is_moves_plus_weight_times_the_goal_count(n, density, seed, reverse, depth, dist):
    # The ranks a search pushes, updated move by move, equal the goal count computed afresh for each state: open
    # goals, half the open goals another disc covers, the depth term (how deep the discs reach into open goal
    # discs, in mean diameters) and the distance term (how far the discs of open goals stand from them).
    try:
        pr = disc_problem(_packed(seed, n, density))
    except AssertionError:
        return
    t = dense._Discs(pr, reverse=reverse)
    run = dense._Search(t, 3.0, False, depth, dist)
    if run.run(15, None)[0] is not None:
        return
    for rank, _, k in run.heap:
        pos, yok = run.states[k][0], run.states[k][1]
        moves, s = 0, k
        while run.states[s][2] >= 0:
            moves, s = moves + 1, run.states[s][2]
        open_ = ~(~t.has_goal | ((np.hypot(*(pos - t.goal).T) <= t.tol) & yok))
        pen = np.zeros((t.n, t.n))
        for g in range(t.n):
            for j in range(t.n):
                if g != j and t.has_goal[g]:
                    pen[g, j] = max(t.r[g] + t.r[j] - dense.TOUCH - math.hypot(*(t.goal[g] - pos[j])), 0.0)
        h = open_.sum() + 0.5 * ((pen > 0).any(axis=1) & open_).sum() \
            + depth * (pen.sum(axis=1) * open_).sum() / (2 * t.r.mean()) \
            + dist * sum(math.hypot(*(pos[g] - t.goal[g])) for g in range(t.n) if open_[g]) / (2 * t.r.mean())
        assert rank == pytest.approx(moves + 3.0 * h, abs=1e-9)


def _one_goal_dropped(seed: int):
    """A seven-disc square at 58 % whose last disc has no goal: it cannot be searched backwards."""
    c = _packed(seed, 7, 0.58)
    return dataclasses.replace(c, goals=c.goals.model_copy(update={"goals": c.goals.goals[:-1]}))


def test_without_a_goal_for_every_disc_only_forward_searches_run():
    forwards = sum(factor for _, backwards, _, _, factor in dense.MORE if not backwards)
    # No plan: the forward search's budget, the shaken restarts' (forwards too), then the forward further searches',
    # and no backward search at all.
    pr = disc_problem(_one_goal_dropped(22))
    assert not dense._reversible(dense._Discs(pr))
    assert dense.search(pr, 40, None) == (None, 40 + dense.SHAKES * 40 + forwards * 40)
    # A plan the forward search misses in 40 states, found by a further forward search; valid.
    c = _one_goal_dropped(5)
    pr = disc_problem(c)
    assert dense._Search(dense._Discs(pr)).run(40, None)[0] is None
    actions, expanded = dense.search(pr, 40, None)
    assert actions is not None and 40 < expanded <= 40 + dense.SHAKES * 40 + forwards * 40
    assert check(c.scene, c.goals, PlanSpec(solved=True, actions=actions, goals=c.goals)).valid


def test_a_search_run_on_in_turns_finds_what_one_run_finds():
    # Expanding in slices (as the further searches take turns) gives the states of one run with the whole budget.
    c = _random_case(4, 80.0, (500.0, 400.0), 10)
    t = dense._Discs(disc_problem(c))
    whole = dense._Search(t, 3.0, True)
    one, n_one = whole.run(400, None)
    sliced = dense._Search(t, 3.0, True)
    res: tuple = (None, 0)
    for cap in range(7, 400 + 7, 7):
        res = sliced.run(min(cap, 400), None)
        if res[0] is not None:
            break
    assert res[1] == n_one and len(sliced.states) == len(whole.states)
    assert (res[0] is None) == (one is None)
    if one is not None:
        assert [x.model_dump() for x in res[0]] == [x.model_dump() for x in one]


def _packed(seed: int, n: int, density: float):
    """Start and goal: two packings of ``n`` discs covering ``density`` of a 1 m square (TRLB's units), each found by
    pushing overlapping discs of random start points apart."""
    r = 1000.0 * math.sqrt(density / (math.pi * n))
    lo, hi = np.array([r, r]), np.array([1000.0 - r, 1000.0 - r])
    rng = np.random.default_rng(seed)
    out: list[np.ndarray] = []
    for _ in range(50):
        if len(out) == 2:
            break
        p = rng.uniform(lo, hi, size=(n, 2))
        for _ in range(1000):
            d = p[:, None, :] - p[None, :, :]
            dist = np.hypot(d[..., 0], d[..., 1]) + np.eye(n) * 1e9
            if (dist >= 2 * r + 1.0).all():
                out.append(p)
                break
            over = np.maximum(2 * r + 2.0 - dist, 0.0)
            p = np.clip(p + 0.3 * (d / dist[..., None] * over[..., None]).sum(axis=1), lo, hi)
    assert len(out) == 2, "no packing found"
    return disc_case(out[0], out[1], r)


@pytest.mark.parametrize("seed,density", [(2, 0.57), (5, 0.60), (8, 0.55), (11, 0.58)])
def test_the_confinement_proof_refuses_no_dense_square_the_corner_search_plans(seed, density):
    # Seven discs at 55-60 % of a 1 m square (TRLB's D = 0.6, n = 7 is 60 %): the corner search plans each (most
    # only with the further searches), the plan is valid, and the proof does not call the case impossible.
    c = _packed(seed, 7, density)
    actions, _ = dense.search(disc_problem(c), 150, None)
    assert actions is not None
    assert check(c.scene, c.goals, PlanSpec(solved=True, actions=actions, goals=c.goals)).valid
    assert confined(Scene.from_spec(c.scene), c.goals) is None


def test_where_the_proof_refuses_the_corner_search_finds_nothing():
    # Five discs at 59 % of the square: proved impossible, and no search finds a plan either.
    c = _packed(12, 5, 0.59)
    assert confined(Scene.from_spec(c.scene), c.goals) is not None
    assert dense.search(disc_problem(c), 30, None)[0] is None


def test_each_further_search_stops_at_its_own_budget():
    # Five discs at 59 %, no plan: the first two searches spend their budget, then each shaken restart the same
    # budget, then each further search its own multiple of it (the backward one of MORE stops at one budget, the
    # others go on), all states counted once.
    c = _packed(12, 5, 0.59)
    pr = disc_problem(c)
    assert dense._reversible(dense._Discs(pr))
    assert [m[-1] for m in dense.MORE] == [dense.MORE_FACTOR, 1, dense.MORE_FACTOR]
    total = 2 * 30 + dense.SHAKES * 30 + sum(m[-1] for m in dense.MORE) * 30
    assert dense.search(pr, 30, None) == (None, total)
    # The turns of one search of several caps: each run ends at its own cap.
    t, back = dense._Discs(pr), dense._Discs(pr, reverse=True)
    runs = [dense._Search(t), dense._Search(back), dense._Search(t, 3.0)]
    assert dense._take_turns(runs, [40, 7, 300], None) == (None, 347)
    assert [r.expanded for r in runs] == [40, 7, 300]


def test_a_shaken_restart_plans_where_every_corner_search_is_stuck():
    # TRLB's D = 0.6, n = 7, files 2/3 (its coordinates in mm): no corner search plans it from the start (the first
    # two spend their budget, the further ones 19 500 states in all), while the discs change places freely under
    # random moves. A restart's walk moves discs to random free places, and the forward search from where it ends
    # plans; the walk followed by that plan is a valid plan, and the same each time.
    start = [(515.4, 486.0), (531.9, 829.2), (172.8, 829.2), (829.2, 644.2), (829.2, 172.8), (374.3, 172.8),
             (172.8, 455.0)]
    goal = [(829.2, 678.9), (516.4, 829.2), (541.5, 475.5), (172.8, 450.7), (775.1, 172.8), (378.9, 172.8),
            (172.8, 829.2)]
    c = disc_case(start, goal, 165.17779672231737)
    pr = disc_problem(c)
    t = dense._Discs(pr)
    assert dense._Search(t).run(dense.budget(7), None)[0] is None
    assert dense._Search(dense._Discs(pr, reverse=True)).run(dense.budget(7), None)[0] is None
    run = dense._Shaken(t, dense.budget(7))
    actions, expanded = run.run(dense.SHAKES * dense.budget(7), None)
    assert actions is not None and expanded <= dense.SHAKES * dense.budget(7)
    assert len(actions) > dense.WALK // 2  # the walk's moves come first
    assert check(c.scene, c.goals, PlanSpec(solved=True, actions=actions, goals=c.goals)).valid
    again, _ = dense._Shaken(t, dense.budget(7)).run(dense.SHAKES * dense.budget(7), None)
    assert again is not None and [x.model_dump() for x in again] == [x.model_dump() for x in actions]
    # A table where no disc has a free place anywhere: every walk is empty, so no restart searches at all.
    tight = disc_problem(disc_case([(100.0, 100.0), (300.0, 100.0)], [(300.0, 100.0), (100.0, 100.0)], 100.0,
                                   width=400.0, height=200.0))
    assert dense._Shaken(dense._Discs(tight), 50).run(400, None) == (None, 0)
