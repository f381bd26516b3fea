"""Disc cases in TRLB's units (1 unit = 1 mm), shared by the tests of the fast first attempt and the corner search."""

from __future__ import annotations

import numpy as np

from lgmcts.casegen import TrlbArrangement, trlb_case
from lgmcts.planner.problem import Problem
from lgmcts.scene import Scene


def disc_case(start, goal, radius: float, width: float = 1000.0, height: float = 1000.0):
    """Discs of ``radius`` moved from the points ``start`` to the points ``goal`` in a ``width`` x ``height`` box."""
    def arr(pts):
        return TrlbArrangement("mem", 0.0, radius, width, height, np.asarray(pts, dtype=float))
    return trlb_case(arr(start), arr(goal))


def disc_problem(c) -> Problem:
    """The planner's problem of a case."""
    return Problem.build(Scene.from_spec(c.scene), c.goals)
