"""The labelled set and the comparison rules of the evaluation."""

from __future__ import annotations

import pytest

from lgmcts.language import parse
from lgmcts.language.evaluate import evaluate, goals_match, load_cases

from .conftest import CASES


def test_labelled_set_is_large_and_covers_refusals():
    cases = load_cases(CASES)
    assert len(cases) >= 200
    cats = {c.category for c in cases}
    assert {"relation", "shape", "composite", "grounding", "free", "refusal"} <= cats
    assert sum(c.refuse is not None for c in cases) >= 30


@pytest.mark.slow
def test_accuracy_on_the_labelled_set(matcher):
    report = evaluate(load_cases(CASES), lambda s, t: parse(s, t))
    fails = [(r.case.id, r.error or r.got) for r in report.failures]
    assert report.accuracy >= 0.97, fails


def test_goal_comparison_rules():
    tower = {"goals": [{"pattern": "tower", "objects": [1, 2, 3]}]}
    assert goals_match(tower, {"goals": [{"pattern": "tower", "objects": [1, 2, 3]}]})
    assert not goals_match(tower, {"goals": [{"pattern": "tower", "objects": [3, 2, 1]}]})
    line = {"goals": [{"pattern": "line", "objects": [1, 2, 3]}, {"pattern": "left", "objects": [4], "anchor_any": [1, 2]}]}
    assert goals_match(line, {"goals": [{"pattern": "left", "objects": [4], "anchor": 2}, {"pattern": "line", "objects": [3, 1, 2]}]})
    assert not goals_match(line, {"goals": [{"pattern": "left", "objects": [4], "anchor": 3}, {"pattern": "line", "objects": [3, 1, 2]}]})
    assert not goals_match(line, {"goals": [{"pattern": "line", "objects": [3, 1, 2]}]})
    pick = {"goals": [{"pattern": "line", "objects_from": [1, 2, 3, 4], "count": 2},
                      {"pattern": "line", "objects_from": [1, 2, 3, 4], "count": 2}], "disjoint": [[0, 1]]}
    assert goals_match(pick, {"goals": [{"pattern": "line", "objects": [1, 2]}, {"pattern": "line", "objects": [3, 4]}]})
    assert not goals_match(pick, {"goals": [{"pattern": "line", "objects": [1, 2]}, {"pattern": "line", "objects": [2, 3]}]})
    assert not goals_match(pick, {"goals": [{"pattern": "line", "objects": [1, 5]}, {"pattern": "line", "objects": [3, 4]}]})


def test_a_relation_matches_its_inverse_only():
    # "the cup right of the mug" and "the mug left of the cup" hold in the same states.
    exp = {"goals": [{"pattern": "right", "objects": [7], "anchor": 6}]}
    assert goals_match(exp, {"goals": [{"pattern": "left", "objects": [6], "anchor": 7}]})
    assert goals_match(exp, {"goals": [{"pattern": "right", "objects": [7], "anchor": 6}]})
    assert not goals_match(exp, {"goals": [{"pattern": "left", "objects": [7], "anchor": 6}]})
    assert not goals_match(exp, {"goals": [{"pattern": "right", "objects": [6], "anchor": 7}]})
    diag = {"goals": [{"pattern": "left_front", "objects": [1], "anchor": 2}]}
    assert goals_match(diag, {"goals": [{"pattern": "right_behind", "objects": [2], "anchor": 1}]})
    assert not goals_match(diag, {"goals": [{"pattern": "left_behind", "objects": [2], "anchor": 1}]})
    # Several objects to one anchor are not one relation the other way round.
    many = {"goals": [{"pattern": "behind", "objects": [1, 2], "anchor": 3}]}
    assert not goals_match(many, {"goals": [{"pattern": "front", "objects": [3], "anchor": 1}]})


def test_relations_of_one_direction_and_anchor_compare_joined():
    # "the cup and the mug behind the bowl" asks what "the cup behind the bowl, the mug behind the bowl" asks.
    joined = {"goals": [{"pattern": "behind", "objects": [2, 4], "anchor": 7}]}
    apart = {"goals": [{"pattern": "behind", "objects": [2], "anchor": 7}, {"pattern": "behind", "objects": [4], "anchor": 7}]}
    assert goals_match(joined, apart) and goals_match(apart, joined)
    # another anchor, another direction or another facing stays another goal
    for other in ({"pattern": "behind", "objects": [4], "anchor": 8}, {"pattern": "front", "objects": [4], "anchor": 7},
                  {"pattern": "behind", "objects": [4], "anchor": 7, "facing": "north"}):
        assert not goals_match(joined, {"goals": [{"pattern": "behind", "objects": [2], "anchor": 7}, other]})
    # an object left out is still missing
    assert not goals_match(joined, {"goals": [{"pattern": "behind", "objects": [2], "anchor": 7}]})


def test_a_size_in_metres_matches_to_the_millimetre():
    exp = {"goals": [{"pattern": "line", "objects": [1, 2], "size": 0.3048}]}
    assert goals_match(exp, {"goals": [{"pattern": "line", "objects": [1, 2], "size": 0.305}]})
    assert not goals_match(exp, {"goals": [{"pattern": "line", "objects": [1, 2], "size": 0.31}]})
    assert not goals_match(exp, {"goals": [{"pattern": "line", "objects": [1, 2], "size": "medium"}]})


def test_a_pose_matches_to_half_a_millimetre_and_a_thousandth_of_a_radian():
    exp = {"goals": [{"pattern": "pose", "objects": [15], "pose": [0.1, -0.2, 1.5708]}]}
    assert goals_match(exp, {"goals": [{"pattern": "pose", "objects": [15], "pose": [0.1, -0.2, 1.5707963]}]})
    assert goals_match(exp, {"goals": [{"pattern": "pose", "objects": [15], "pose": [0.1004, -0.2, 1.5708]}]})
    assert not goals_match(exp, {"goals": [{"pattern": "pose", "objects": [15], "pose": [0.101, -0.2, 1.5708]}]})
    assert not goals_match(exp, {"goals": [{"pattern": "pose", "objects": [15], "pose": [0.1, -0.2, 1.58]}]})
