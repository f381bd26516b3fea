"""Placing one object: candidate poses from its priors, collision and
containment tests, and the transition that puts it on its goal.

Candidates are drawn from the product of the priors an object is in
(:func:`sample_poses`); :func:`collisions` tells which obstacles each one
comes too close to, :func:`free_mask` which are free; :func:`to_table`
places the object at the first free one. Obstacles are judged on exact
footprints (circles for two cylinders) with the step's clearance; contact
(:data:`CONTACT_AREA`) is allowed only where a fixed target leaves no choice.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import shapely

from .. import geometry as geo
from ..formats import Action
from ..patterns import CLEARANCE
from ..scene import TABLE, Scene, State
from .base import Transition
from .problem import Problem, SearchState, commit

__all__ = [
    "CONTACT_AREA",
    "StepOptions",
    "collisions",
    "fixed_obstacles",
    "free_mask",
    "make_action",
    "pickable",
    "place",
    "place_fixed",
    "reachable",
    "required_support",
    "sample_poses",
    "to_table",
    "touching_only",
    "wrapped",
]

#: Largest footprint intersection (m²) the planner counts as contact rather
#: than overlap where a goal leaves no room for its clearance: half the
#: validator's tolerance (:data:`lgmcts.validate.OVERLAP_AREA`). Two
#: cylinders are judged on their true circles (they may touch, not overlap).
CONTACT_AREA = 0.5e-6


@dataclass(frozen=True)
class StepOptions:
    """Options of the simulation step.

    Attributes
    ----------
    samples : candidate poses drawn from a prior per attempt.
    clearance : gap kept between footprints and to the workspace edge (m).
    obstacles : ``"all"`` (every table-level object is an obstacle) or
        ``"placed"`` (only objects committed to goals, and anchors that no
        goal moves; used to sample goal arrangements for the PMCTS baseline).
    reach : a robot (:class:`lgmcts.robot.Robot`) or ``None``: with one, an
        object is picked and placed only where the robot reaches a top-down
        grasp of it (:func:`reachable`).
    """

    samples: int = 24
    clearance: float = CLEARANCE
    obstacles: str = "all"
    reach: Any = None


def reachable(problem: Problem, world: State, o: int, poses: np.ndarray, opts: StepOptions,
              support: int = TABLE) -> np.ndarray:
    """Mask over poses ``(k, >=2)`` of ``o`` on ``support`` in ``world``:
    whether ``opts.reach`` grasps ``o`` there from above (all true without a
    robot)."""
    if opts.reach is None:
        return np.ones(len(poses), dtype=bool)
    sc = problem.scene
    base = 0.0 if support == TABLE else world.base_z(support) + float(sc.heights[support])
    top = np.full(len(poses), base + float(sc.heights[o]))
    return np.asarray(opts.reach.reachable(sc.bounds, np.asarray(poses)[:, :2], top), dtype=bool)


def pickable(problem: Problem, world: State, o: int, opts: StepOptions) -> bool:
    """Whether ``o`` can be picked where it is in ``world``."""
    return bool(reachable(problem, world, o, world.poses[o][None], opts, world.on[o])[0])


def wrapped(pose: np.ndarray) -> np.ndarray:
    """The pose with its yaw in [-pi, pi)."""
    return np.array([pose[0], pose[1], geo.wrap_angle(float(pose[2]))])


def make_action(scene: Scene, i: int, pose: np.ndarray, on: int | None, purpose: str) -> Action:
    return Action(object=scene.ids[i], to=(float(pose[0]), float(pose[1]), float(pose[2])),
                  on=None if on is None else scene.ids[on], purpose=purpose)  # type: ignore[arg-type]


def required_support(problem: Problem, ss: SearchState, o: int) -> int | None:
    gates = problem.gates[o]
    sup = {problem.patterns[k].support(ss.ctx(problem, k), o) for k in gates}
    if len(gates) < len(problem.member[o]):
        sup.add(TABLE)  # a pattern with the default support is in
    return sup.pop() if len(sup) == 1 else None


def place(problem: Problem, ss: SearchState, o: int, pose: np.ndarray, support: int,
          rng: np.random.Generator) -> Transition:
    """Goal object ``o`` put at ``pose`` (wrapped) on ``support``, and committed to its goals."""
    world = ss.world.moved(o, pose, support)
    act = make_action(problem.scene, o, pose, None if support == TABLE else support, "goal")
    return Transition(act, commit(problem, ss, world, o, pose, rng))


def sample_poses(problem: Problem, ss: SearchState, o: int, rng: np.random.Generator, n: int) -> np.ndarray:
    """Candidate poses for ``o`` from the product of the priors it is in."""
    goals = list(problem.member[o])

    goals.sort(key=lambda k: problem.patterns[k].rank(problem.goals[k], ss.progress[k], o))
    for driver in goals:
        cand = problem.patterns[driver].sample(ss.ctx(problem, driver), o, rng, n)
        if len(cand) == 0:
            continue
        keep = np.ones(len(cand), dtype=bool)
        for k in goals:
            if k != driver:
                keep &= problem.patterns[k].density(ss.ctx(problem, k), o, cand) > 0
        if keep.any():
            return cand[keep]
    return np.empty((0, 3))


def collision_pairs(problem: Problem, ss: SearchState, o: int, poses: np.ndarray,
           opts: StepOptions) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray | None, np.ndarray]:
    """Inside-workspace mask, the colliding pairs (candidate indices,
    obstacle indices) that count, the candidates' footprint polygons
    (``None`` when only discs are involved) and vertices.

    Tests every footprint (bounding circles first, then exactly: circles for
    two cylinders, polygons otherwise) against the clearance and drops the
    hits that do not count (the moving object itself; with
    ``obstacles="placed"``, objects not yet committed to a goal). Stacked
    objects count too, although the acceptance rules only compare
    table-level footprints: an object put under the overhang of a wide
    object resting on a narrow one would strike it when lowered.
    """
    scene, world = problem.scene, ss.world
    verts = scene.footprint(o, poses).reshape(len(poses), -1, 2)
    inside = geo.inside_workspace(verts, scene.bounds, margin=opts.clearance / 2)
    inside &= reachable(problem, world, o, poses, opts)
    # Disc against discs is decided on circles: no polygons needed then.
    polys = None if scene.discs[o] > 0 and problem.all_discs else shapely.polygons(verts)
    if scene.n <= 1:
        return inside, np.empty(0, dtype=int), np.empty(0, dtype=int), polys, verts
    ci, oi = geo.colliding_near(polys, poses[:, :2], scene.radii[o], world.poly_array,
                                world.poses[:, :2], scene.radii, opts.clearance,
                                cand_disc=scene.discs[o], obs_disc=scene.discs)
    keep = oi != o
    if opts.obstacles == "placed":
        counts = np.array([ss.committed(problem, int(b)) or int(b) in problem.standing_anchors for b in oi], dtype=bool)
        keep &= counts if len(oi) else keep
    return inside, ci[keep], oi[keep], polys, verts


def collisions(problem: Problem, ss: SearchState, o: int, poses: np.ndarray,
                     opts: StepOptions) -> tuple[np.ndarray, list[list[int]], np.ndarray | None, np.ndarray]:
    """Inside-workspace mask and, per candidate, the objects its footprint
    comes too close to (see :func:`collision_pairs`); also the candidates' footprint
    polygons (``None`` when only discs are involved) and vertices."""
    inside, ci, oi, polys, verts = collision_pairs(problem, ss, o, poses, opts)
    hits: list[list[int]] = [[] for _ in range(len(poses))]
    for a, b in zip(ci.tolist(), oi.tolist()):
        hits[a].append(b)
    return inside, hits, polys, verts


def free_mask(problem: Problem, ss: SearchState, o: int, poses: np.ndarray, opts: StepOptions,
          contact: bool = False) -> np.ndarray:
    """Mask of the candidate poses of ``o`` that are free: inside the
    workspace and clear of every obstacle by the clearance or, with
    ``contact``, inside and at most touching (see :func:`touching_only`)."""
    inside, ci, oi, polys, verts = collision_pairs(problem, ss, o, poses, opts)
    if contact:
        inside = geo.inside_workspace(verts, problem.scene.bounds) & reachable(problem, ss.world, o, poses, opts)
        if len(ci):
            world, scene = ss.world, problem.scene
            mine = polys[ci] if polys is not None else np.full(len(ci), None, dtype=object)
            over = geo.overlapping(mine, poses[ci, :2], np.full(len(ci), scene.discs[o]), world.poly_array[oi],
                                   world.poses[oi, :2], scene.discs[oi], CONTACT_AREA)
            ci = ci[over]
    return inside & (np.bincount(ci, minlength=len(poses)) == 0)


def touching_only(scene: Scene, world: State, i: int, near: np.ndarray, polys: np.ndarray | None = None,
                  xy: np.ndarray | None = None) -> bool:
    """Whether object ``i`` (at its pose in ``world``, or at footprint
    ``polys``/centre ``xy``) at most touches the objects ``near``: no
    polygon intersection above :data:`CONTACT_AREA`, no overlap of two
    cylinders' circles."""
    near = np.asarray(near, dtype=int)
    if not len(near):
        return True
    a_poly = world.poly_array[i] if polys is None else polys
    a_xy = world.poses[i, :2] if xy is None else xy
    over = geo.overlapping(np.full(len(near), a_poly, dtype=object),
                           np.repeat(np.asarray(a_xy, dtype=float)[None], len(near), 0),
                           np.full(len(near), scene.discs[i]), world.poly_array[near], world.poses[near, :2],
                           scene.discs[near], CONTACT_AREA)
    return not bool(over.any())


def overlaps_beyond_contact(problem: Problem, ss: SearchState, o: int, poses: np.ndarray, polys: np.ndarray | None,
                            hits: list[list[int]],
          cands: np.ndarray) -> list[list[int]]:
    """Per candidate, its obstacles (among ``hits``) that it overlaps beyond
    contact; only the candidates ``cands`` are tested, the others get none."""
    scene, world = problem.scene, ss.world
    ci = [a for a in cands.tolist() for _ in hits[a]]
    oi = [b for a in cands.tolist() for b in hits[a]]
    out: list[list[int]] = [[] for _ in hits]
    if ci:
        mine = polys[ci] if polys is not None else np.full(len(ci), None, dtype=object)
        over = geo.overlapping(mine, poses[ci, :2], np.full(len(ci), scene.discs[o]), world.poly_array[oi],
                               world.poses[oi, :2], scene.discs[oi], CONTACT_AREA)
        for a, b, v in zip(ci, oi, over.tolist()):
            if v:
                out[a].append(b)
    return out


def to_table(problem: Problem, ss: SearchState, o: int, cand: np.ndarray, rng: np.random.Generator,
              opts: StepOptions) -> tuple[Transition | None, np.ndarray, list[list[int]]]:
    """Place ``o`` at the first free candidate; also the inside mask and each candidate's obstacles."""
    inside, hits, polys, verts = collisions(problem, ss, o, cand, opts)
    ok = inside & np.array([not h for h in hits])
    if ok.any():
        return place(problem, ss, o, wrapped(cand[int(np.flatnonzero(ok)[0])]), TABLE, rng), inside, hits
    if o not in problem.fixed:
        return None, inside, hits
    # A fixed target (a pose goal) has no other pose: where it lies closer
    # than the clearance to a neighbour or the edge, contact is allowed.
    # Obstacles are then only what it would overlap.
    edge = geo.inside_workspace(verts, problem.scene.bounds) & reachable(problem, ss.world, o, cand, opts)
    hard = overlaps_beyond_contact(problem, ss, o, cand, polys, hits, np.flatnonzero(edge))
    touch = edge & np.array([not h for h in hard])
    if touch.any():
        return place(problem, ss, o, wrapped(cand[int(np.flatnonzero(touch)[0])]), TABLE, rng), edge, hard
    return None, edge, hard


def fixed_obstacles(problem: Problem, ss: SearchState, objs: list[int],
                    opts: StepOptions) -> dict[int, tuple[int, ...]]:
    """For the clear, table-bound :attr:`Problem.fixed` objects among ``objs``,
    the obstacles at their target (empty when it is free), in one query.

    Objects whose target lies outside the workspace are left out, as are
    the others; :func:`probe` answers for them.
    """
    world = ss.world
    feet = problem.fixed_footprints
    objs = [o for o in objs if o in feet and world.clear(o) and required_support(problem, ss, o) == TABLE
            and pickable(problem, world, o, opts) and reachable(problem, world, o, problem.fixed[o][None], opts)[0]]
    out: dict[int, list[int]] = {o: [] for o in objs}
    if objs and problem.scene.n > 1:
        polys = np.empty(len(objs), dtype=object)
        polys[:] = [feet[o] for o in objs]
        xy = np.array([problem.fixed[o][:2] for o in objs])
        sc = problem.scene
        # Only overlaps block a fixed target (it may touch, see to_table):
        # pairs that meet at all, then those that overlap beyond contact.
        ci, oi = geo.colliding_near(polys, xy, sc.radii[objs], world.poly_array, world.poses[:, :2],
                                    sc.radii, 0.0, cand_disc=sc.discs[objs], obs_disc=sc.discs)
        keep = oi != np.asarray(objs)[ci]
        ci, oi = ci[keep], oi[keep]
        if len(ci):
            mover = np.asarray(objs)[ci]
            over = geo.overlapping(polys[ci], xy[ci], sc.discs[mover], world.poly_array[oi], world.poses[oi, :2],
                                   sc.discs[oi], CONTACT_AREA)
            for a, b in zip(ci[over].tolist(), oi[over].tolist()):
                out[objs[a]].append(int(b))
    return {o: tuple(v) for o, v in out.items()}


def place_fixed(problem: Problem, ss: SearchState, o: int, rng: np.random.Generator) -> Transition:
    """Put a :attr:`Problem.fixed` object on its target, which
    :func:`fixed_obstacles` found free."""
    return place(problem, ss, o, wrapped(problem.fixed[o]), TABLE, rng)

