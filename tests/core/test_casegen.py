"""Case generators: the Labbé protocol as its authors sample it, and the dense random cases."""

from __future__ import annotations

import math

import numpy as np
import pytest

from lgmcts import check, plan
from lgmcts.casegen import LABBE_RADIUS, LABBE_SQUARE, labbe_case, labbe_protocol_case
from lgmcts.formats import parse_scene
from lgmcts.scene import Scene


def _centres(case):
    start = np.array([o.pose[:2] for o in case.scene.objects])
    goal = np.array([g.pose[:2] for g in case.goals.goals])
    return start, goal


@pytest.mark.parametrize("n", [1, 2, 12, 25, 37])
def test_protocol_sampling_rules(n):
    c = labbe_protocol_case(n, 7 * n)
    (x0, y0), (x1, y1) = LABBE_SQUARE
    for pts in _centres(c):
        assert pts.shape == (n, 2)
        assert ((pts[:, 0] >= x0) & (pts[:, 0] <= x1) & (pts[:, 1] >= y0) & (pts[:, 1] <= y1)).all()
        if n > 1:
            d = np.hypot(*(pts[:, None] - pts[None]).transpose(2, 0, 1))
            d[np.diag_indices(n)] = np.inf
            assert d.min() >= 2 * LABBE_RADIUS  # touching allowed, no margin required
    # Every footprint lies in the workspace (Scene.from_spec would refuse it otherwise),
    # and the goal configuration is itself legal for the validator.
    sc = Scene.from_spec(c.scene)
    assert sc.n == n
    _, goal = _centres(c)
    actions = [{"object": i + 1, "to": [float(goal[i, 0]), float(goal[i, 1]), 0.0]} for i in range(n)]
    far = c.scene.model_copy(
        update={
            "objects": [o.model_copy(update={"pose": (10.0 + i, 0.0, 0.0)}) for i, o in enumerate(c.scene.objects)],
            "workspace": c.scene.workspace.model_copy(update={"x": (c.scene.workspace.x[0], 100.0)}),
        }
    )
    assert check(far, c.goals, {"solved": True, "actions": actions}).valid


def test_protocol_is_denser_than_the_spaced_variant():
    # The protocol lets discs touch: over a few cases some pair is closer than
    # the spaced variant's 2R x 1.0087 + 4 mm.
    close = min(_min_gap(labbe_protocol_case(20, s)) for s in range(5))
    assert close < 2 * LABBE_RADIUS * 1.0087 + 0.004
    assert min(_min_gap(labbe_case(20, s)) for s in range(3)) >= 2 * LABBE_RADIUS * 1.0087 + 0.004 - 1e-9


def _min_gap(case):
    out = math.inf
    for pts in _centres(case):
        d = np.hypot(*(pts[:, None] - pts[None]).transpose(2, 0, 1))
        d[np.diag_indices(len(pts))] = np.inf
        out = min(out, float(d.min()))
    return out


def test_protocol_is_deterministic_by_seed_and_variant_names():
    assert labbe_protocol_case(20, 3) == labbe_protocol_case(20, 3)
    assert labbe_case(20, 3, variant="protocol") == labbe_protocol_case(20, 3)
    assert labbe_case(20, 3) == labbe_case(20, 3, variant="spaced")
    with pytest.raises(ValueError):
        labbe_case(5, 0, variant="nope")


@pytest.mark.parametrize("n,seed", [(10, 0), (25, 1), (33, 2)])
def test_planner_solves_protocol_cases(n, seed):
    c = labbe_protocol_case(n, 1000 * n + seed)
    p = plan(c.scene, c.goals, seed=seed, max_iter=2000)
    assert p.solved and check(c.scene, c.goals, p).valid


def test_protocol_workspace_admits_centres_on_the_square_edge():
    from lgmcts.casegen import _disc_case, labbe_protocol_case

    ws = labbe_protocol_case(1, 0).scene.workspace
    (x0, y0), (x1, y1) = LABBE_SQUARE
    corners = np.array([[x0, y0], [x1, y1], [x0, y1], [x1, y0]])
    c = _disc_case(corners, corners[::-1], LABBE_RADIUS, {"x": list(ws.x), "y": list(ws.y)}, "labbe")
    assert Scene.from_spec(c.scene).n == 4


@pytest.mark.parametrize("seed", [0, 3, 7])
def test_dense_random_case_adds_packed_clutter_to_the_same_case(seed):
    from lgmcts.casegen import random_case

    base, dense = random_case(seed), random_case(seed, dense=True)
    assert dense == random_case(seed, dense=True)
    assert dense.goals == base.goals and dense.kind == f"dense-{base.kind}"
    nb = len(base.scene.objects)
    assert dense.scene.objects[:nb] == base.scene.objects
    assert 4 <= len(dense.scene.objects) - nb <= 10
    sc = Scene.from_spec(dense.scene)
    polys = sc.initial.polys
    table = [k for k in range(sc.n) if sc.initial.on[k] == -1]
    for e in range(nb, sc.n):
        others = [polys[k] for k in table if k != e]
        assert max(float((polys[e].intersection(q)).area) for q in others) <= 1e-9  # no overlap


def test_pack_clutter_packs_in_contact_without_overlap():
    import shapely

    from lgmcts.casegen import pack_clutter

    rng = np.random.default_rng(0)
    goal = [shapely.box(-0.05, -0.05, 0.05, 0.05)]
    other = [shapely.Point(0.2, 0.1).buffer(0.03)]
    specs = [
        {"id": 10 + k, "name": "block", "color": "red", "shape": {"type": "box", "size": [0.04, 0.03, 0.03]}}
        for k in range(8)
    ]
    out = pack_clutter((-0.4, 0.4, -0.3, 0.3), specs, goal, other, rng)
    assert len(out) == 8 and [o["id"] for o in out] == [s["id"] for s in specs]
    sc = Scene.from_spec(parse_scene({"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}, "objects": out}))
    seen = list(goal) + list(other)
    for p in sc.initial.polys:
        assert max(p.intersection(q).area for q in seen) <= 1e-12  # no overlap
        assert min(p.distance(q) for q in seen) <= 1e-4  # edge to edge with the goal region or a neighbour
        seen.append(p)


@pytest.mark.parametrize("method", ["lgmcts", "greedy", "pmcts"])
def test_dense_random_cases_are_solved(method):
    from lgmcts.casegen import random_case

    for seed in range(3):
        c = random_case(seed, dense=True)
        p = plan(c.scene, c.goals, method=method, seed=seed)
        assert p.solved and check(c.scene, c.goals, p).valid


def test_touching_cylinders_load_as_a_start_scene():
    """Two cylinders in contact are legal at the start, as in a plan (their 32-gons overlap by a sliver)."""
    from lgmcts.formats import parse_scene
    from lgmcts.scene import Scene

    r = 0.0375
    objs = [
        {
            "id": i + 1,
            "name": "disc",
            "color": "red",
            "shape": {"type": "cylinder", "radius": r, "height": 0.02},
            "pose": [0.1 + 2 * r * i, 0.25, 0.3 * i],
            "on": None,
        }
        for i in range(2)
    ]
    Scene.from_spec(parse_scene({"workspace": {"x": [0, 0.5], "y": [0, 0.5]}, "objects": objs}))
