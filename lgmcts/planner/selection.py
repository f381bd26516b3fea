"""Selection rules as pure functions over child statistics."""

from __future__ import annotations

import numpy as np

__all__ = ["select_child", "ucb_scores"]


def ucb_scores(value: np.ndarray, visits: np.ndarray, parent_visits: int, c: float) -> np.ndarray:
    """Upper confidence bounds ``w/n + c sqrt(log N / n)`` (paper, Eq. 1).

    Unvisited children score ``+inf`` so they are tried first.
    """
    value = np.asarray(value, dtype=float)
    visits = np.asarray(visits, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        mean = np.where(visits > 0, value / np.maximum(visits, 1), 0.0)
        bonus = c * np.sqrt(np.log(max(parent_visits, 1)) / np.maximum(visits, 1e-12))
    return np.where(visits > 0, mean + bonus, np.inf)


def select_child(value: np.ndarray, visits: np.ndarray, parent_visits: int, c: float, rng: np.random.Generator) -> int:
    """Index of the child with the highest UCB score, ties broken by ``rng``."""
    s = ucb_scores(value, visits, parent_visits, c)
    best = np.flatnonzero(s == s.max())
    return int(best[0] if len(best) == 1 else best[int(rng.integers(len(best)))])
