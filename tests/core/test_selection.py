"""UCB selection (paper, Eq. 1) as pure functions."""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from lgmcts.planner.selection import select_child, ucb_scores


def test_unvisited_children_score_infinity():
    s = ucb_scores(np.array([1.0, 0.0, 2.0]), np.array([2, 0, 4]), 6, 1.0)
    assert math.isinf(s[1]) and np.isfinite(s[[0, 2]]).all()


def test_scores_are_mean_plus_bonus():
    value, visits, parent, c = np.array([3.0, 1.0]), np.array([4, 1]), 5, 0.7
    want = value / visits + c * np.sqrt(math.log(parent) / visits)
    assert np.allclose(ucb_scores(value, visits, parent, c), want)


def test_no_exploration_picks_the_best_mean():
    rng = np.random.default_rng(0)
    assert select_child(np.array([1.0, 3.0, 2.0]), np.array([2, 2, 2]), 6, 0.0, rng) == 1
    # A less visited child wins once exploration counts enough.
    assert select_child(np.array([9.0, 1.0]), np.array([10, 1]), 11, 5.0, rng) == 1


def test_unvisited_child_is_taken_before_any_visited_one():
    rng = np.random.default_rng(1)
    assert select_child(np.array([100.0, 0.0]), np.array([1, 0]), 1, 1.0, rng) == 1


def test_ties_are_broken_by_the_generator_and_reproducibly():
    value, visits = np.zeros(4), np.zeros(4, dtype=int)
    picks = [select_child(value, visits, 0, 1.0, np.random.default_rng(s)) for s in range(40)]
    assert set(picks) == {0, 1, 2, 3}
    again = [select_child(value, visits, 0, 1.0, np.random.default_rng(s)) for s in range(40)]
    assert picks == again


@settings(max_examples=50, deadline=None)
@given(st.lists(st.tuples(st.floats(0, 50), st.integers(1, 30)), min_size=1, max_size=8), st.floats(0, 3))
def test_selected_child_has_the_highest_score(rows, c):
    value = np.array([r[0] for r in rows])
    visits = np.array([r[1] for r in rows])
    parent = int(visits.sum())
    k = select_child(value, visits, parent, c, np.random.default_rng(0))
    s = ucb_scores(value, visits, parent, c)
    assert s[k] == s.max()
