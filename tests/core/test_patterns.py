"""Every registered pattern prior: poses drawn from it satisfy its acceptance rule."""

from __future__ import annotations

import numpy as np
import pytest
from core_helpers import can, goals, scene

from lgmcts.formats import RELATIONS, parse_goals, parse_scene
from lgmcts.patterns import Context, GoalProgress, registry
from lgmcts.patterns.line import LineParams
from lgmcts.planner.step import Problem
from lgmcts.scene import TABLE, Scene
from lgmcts.validate import goal_satisfied

SIZES = {"line": 5, "circle": 6, "rectangle": 6, "tower": 3, "pose": 1}


def _goal(name: str, n: int) -> dict:
    if name in RELATIONS:
        return {"pattern": name, "objects": list(range(2, n + 2)), "anchor": 1}
    if name == "pose":
        return {"pattern": "pose", "objects": [2], "pose": [0.1, -0.05, 0.4]}
    return {"pattern": name, "objects": list(range(2, n + 2))}


def _sample_goal(name: str, seed: int, radius: float):
    n = SIZES.get(name, 2)
    objs = [can(i + 1, -0.5 + 0.06 * i, -0.45, r=radius) for i in range(n + 1)]
    objs[0]["pose"] = [0.0, 0.0, 0.0]  # the anchor of relations sits mid-table
    sc = Scene.from_spec(parse_scene(scene(*objs, x=(-0.6, 0.6), y=(-0.5, 0.5))))
    gs = parse_goals(goals(_goal(name, n)))
    problem = Problem.build(sc, gs)
    pat, cg = problem.patterns[0], problem.goals[0]
    rng = np.random.default_rng(seed)
    world, prog = sc.initial, GoalProgress()
    settled = frozenset({0})
    for o in cg.objects:
        ctx = Context(sc, world, cg, prog)
        assert pat.ready(ctx, o, settled | frozenset(prog.placed))
        cand = pat.sample(ctx, o, rng, 16)
        assert len(cand) > 0
        dens = pat.density(ctx, o, cand)
        assert (dens > 0).all(), "a sample lies outside its own prior's support"
        pose = cand[0]
        sup = pat.support(ctx, o)
        world = world.moved(o, pose, sup)
        prog = pat.commit(Context(sc, world, cg, prog), o, pose, rng)
    return goal_satisfied(gs.goals[0], sc, world.poses, world.on)


@pytest.mark.parametrize("name", sorted(registry()))
@pytest.mark.parametrize("seed", range(8))
def test_samples_satisfy_pattern(name, seed):
    why = _sample_goal(name, seed, radius=0.012 + 0.004 * (seed % 4))
    assert why is None, why


def test_registry_covers_every_goal_pattern():
    from lgmcts.formats import RELATIONS, pattern_names

    reg = registry()
    # The built-ins, each declared by its own module (formats names none of them).
    assert set(reg) == {"line", "circle", "rectangle", "tower", "pose", *RELATIONS}
    assert set(pattern_names()) >= set(reg)
    for name, p in reg.items():
        assert p.name == name
        assert p.keys and p.description
        assert p.min_objects >= 1


def test_circle_radius_adapts_to_object_size():
    from lgmcts.patterns.circle import radius_range

    def lo(r):
        sc = Scene.from_spec(parse_scene(scene(*[can(i + 1, -0.3 + 0.1 * i, 0.0, r=r) for i in range(6)])))
        g = Problem.build(sc, parse_goals(goals({"pattern": "circle", "objects": [1, 2, 3, 4, 5, 6]})))
        return radius_range(Context(sc, sc.initial, g.goals[0], GoalProgress()))[0]

    assert lo(0.04) > lo(0.015) >= 0.05


def test_tower_prior_is_centred_on_support():
    sc = Scene.from_spec(parse_scene(scene(can(1, 0.1, 0.1), can(2, -0.1, 0.0))))
    problem = Problem.build(sc, parse_goals(goals({"pattern": "tower", "objects": [1, 2]})))
    pat, cg = problem.patterns[0], problem.goals[0]
    ctx = Context(sc, sc.initial, cg, GoalProgress((0,), (-1,)))
    assert pat.support(ctx, 1) == 0
    cand = pat.sample(ctx, 1, np.random.default_rng(0), 4)
    assert np.allclose(cand[:, :2], [0.1, 0.1])
    assert pat.support(ctx, 0) == TABLE


def test_line_takes_a_new_direction_when_its_second_object_is_replaced():
    # A line whose kappa came from objects that have since moved off it, with
    # one object left: the next object placed fixes kappa afresh, so the
    # objects placed after it line up with both (a stale kappa put them on
    # another line and the plan failed validation).
    objs = [can(i + 1, -0.5 + 0.1 * i, -0.4) for i in range(4)]
    sc = Scene.from_spec(parse_scene(scene(*objs, x=(-0.6, 0.6), y=(-0.5, 0.5))))
    gs = parse_goals(goals({"pattern": "line", "objects": [1, 2, 3, 4]}))
    problem = Problem.build(sc, gs)
    pat, cg = problem.patterns[0], problem.goals[0]
    rng = np.random.default_rng(0)
    world = sc.initial.moved(0, np.array([0.0, 0.0, 0.0])).moved(1, np.array([0.2, 0.0, 0.0]))
    prog = GoalProgress().add(0).add(1, params=LineParams((0.0, 0.0), (1.0, 0.0)))  # a line along +x
    prog = prog.without(1)  # object 1 moved away; object 0 still on the line
    world = world.moved(2, np.array([0.0, 0.2, 0.0]))  # object 2 goes straight behind object 0
    prog = pat.commit(Context(sc, world, cg, prog), 2, world.poses[2], rng)
    cand = pat.sample(Context(sc, world, cg, prog), 3, rng, 32)
    assert len(cand) and np.allclose(cand[:, 0], 0.0, atol=0.03)  # on the line x = 0, not y = 0
