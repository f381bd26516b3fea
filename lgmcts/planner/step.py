"""The search problem, its immutable search state and the simulation step.

:func:`attempt` is the paper's Algorithm 1 ("Simulation"): given a search
state and an object to place, it returns one rearrangement action — the
object to its sampled pose from f = f_prior x f_free, or, when the object is
covered or its pose is blocked, a relocation of one blocker to a free pose
outside every remaining goal region — together with the successor state.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from functools import cached_property
from typing import Any

import numpy as np
import shapely

from .. import geometry as geo
from ..errors import InputError
from ..formats import Action, GoalSpec
from ..patterns import CLEARANCE, CompiledGoal, Context, GoalProgress, Pattern, registry
from ..patterns.base import BasePattern, compile_params
from ..scene import TABLE, Scene, State
from .relocate import clear_centres, region_scores, snuggest

__all__ = ["Problem", "SearchState", "Transition", "attempt", "stay", "StepOptions", "CONTACT_AREA", "touching_only"]

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
    return opts.reach.reachable(sc.bounds, np.asarray(poses)[:, :2], top)


def _pickable(problem: Problem, world: State, o: int, opts: StepOptions) -> bool:
    """Whether ``o`` can be picked where it is in ``world``."""
    return bool(reachable(problem, world, o, world.poses[o][None], opts, world.on[o])[0])


@dataclass(frozen=True)
class Problem:
    """A scene and goals compiled to indices, shared by every search node."""

    scene: Scene
    spec: GoalSpec
    goals: tuple[CompiledGoal, ...]
    patterns: tuple[Pattern, ...]

    @classmethod
    def build(cls, scene: Scene, spec: GoalSpec) -> "Problem":
        spec.check_against(scene.spec)
        reg = registry()
        goals, patterns = [], []
        for k, g in enumerate(spec.goals):
            idx = tuple(scene.index[i] for i in g.objects)
            anchor = None if g.anchor is None else scene.index[g.anchor]
            goals.append(CompiledGoal(k, g.pattern, idx, anchor, None if g.pose is None else tuple(g.pose),
                                      compile_params(g, scene)))
            if g.pattern not in reg:
                raise InputError(f"pattern '{g.pattern}' has no prior (lgmcts.patterns.register)")
            patterns.append(reg[g.pattern])
        return cls(scene, spec, tuple(goals), tuple(patterns))

    @cached_property
    def member(self) -> dict[int, tuple[int, ...]]:
        """Goal indices in which each object is a target."""
        out: dict[int, list[int]] = {}
        for g in self.goals:
            for o in g.objects:
                out.setdefault(o, []).append(g.k)
        return {o: tuple(v) for o, v in out.items()}

    @cached_property
    def anchored(self) -> dict[int, tuple[int, ...]]:
        """Goal indices that use each object as their anchor."""
        out: dict[int, list[int]] = {}
        for g in self.goals:
            if g.anchor is not None:
                out.setdefault(g.anchor, []).append(g.k)
        return {o: tuple(v) for o, v in out.items()}

    @cached_property
    def fixed(self) -> dict[int, np.ndarray]:
        """Objects whose one goal has a deterministic prior, with their target pose.

        Such an object's candidates never change, so what blocks it changes
        only when something moves near its target.
        """
        out = {}
        rng = np.random.default_rng(0)  # unused by a deterministic prior
        for o, ks in self.member.items():
            if len(ks) == 1 and getattr(self.patterns[ks[0]], "deterministic", False):
                g = self.goals[ks[0]]
                ctx = Context(self.scene, self.scene.initial, g, GoalProgress())
                out[o] = np.asarray(self.patterns[ks[0]].sample(ctx, o, rng, 1)[0], dtype=float)
        return out

    @cached_property
    def fixed_footprints(self) -> dict[int, Any]:
        """Footprint polygon of each :attr:`fixed` object at its target, for
        those whose target lies inside the workspace (a fixed target may touch
        the edge: the goal leaves no other choice)."""
        objs = list(self.fixed)
        if not objs:
            return {}
        verts, polys = geo.place_each([self.scene.local[o] for o in objs], np.array([self.fixed[o] for o in objs]))
        return {o: polys[j] for j, o in enumerate(objs)
                if geo.inside_workspace(verts[j][None], self.scene.bounds)[0]}

    @cached_property
    def gates(self) -> dict[int, tuple[int, ...]]:
        """Per goal object, its goals whose pattern may hold it back
        (``ready``) or put it on another object (``support``); the others
        (a :class:`BasePattern` that keeps the defaults) need not be asked."""
        def plain(p: Pattern) -> bool:
            t = type(p)
            return getattr(t, "ready", None) is BasePattern.ready and getattr(t, "support", None) is BasePattern.support
        return {o: tuple(k for k in ks if not plain(self.patterns[k])) for o, ks in self.member.items()}

    @cached_property
    def standing_anchors(self) -> frozenset[int]:
        """Anchors that no goal moves: they stay where they stand."""
        return frozenset(self.anchored) - frozenset(self.member)

    @cached_property
    def static_regions(self) -> dict[int, Any]:
        """Region of each unfinished goal whose pattern is deterministic (the
        same in every branch), by goal index; ``None`` for no region."""
        root = self.root()
        return {k: self.patterns[k].region(root.ctx(self, k)) for k in range(len(self.goals))
                if getattr(self.patterns[k], "deterministic", False)}

    @cached_property
    def all_discs(self) -> bool:
        """Whether every object is a cylinder (collisions are then circle tests)."""
        return bool((self.scene.discs > 0).all())

    @cached_property
    def targets(self) -> tuple[int, ...]:
        return tuple(sorted(self.member))

    def root(self) -> "SearchState":
        return SearchState(self.scene.initial, tuple(GoalProgress() for _ in self.goals))


@dataclass(frozen=True, eq=False)
class SearchState:
    """World state plus, per goal, what this branch has fixed."""

    world: State
    progress: tuple[GoalProgress, ...]

    def ctx(self, problem: Problem, k: int) -> Context:
        return Context(problem.scene, self.world, problem.goals[k], self.progress[k])

    def _committed(self, problem: Problem) -> frozenset[int]:
        # Computed once per state (a state only ever serves one problem).
        c = self.__dict__.get("_committed_set")
        if c is None:
            c = frozenset(o for o, ks in problem.member.items() if o in self.progress[ks[0]].placed)
            self.__dict__["_committed_set"] = c
        return c

    def committed(self, problem: Problem, o: int) -> bool:
        """Whether goal object ``o`` has been placed for its goals in this branch."""
        return o in self._committed(problem)

    def settled(self, problem: Problem) -> frozenset[int]:
        """Objects that will not move for a goal any more in this branch."""
        s = self.__dict__.get("_settled_set")
        if s is None:
            free = frozenset(o for o in range(problem.scene.n) if o not in problem.member)
            s = self.__dict__["_settled_set"] = free | self._committed(problem)
        return s

    def goal_done(self, problem: Problem, k: int, settled: frozenset[int] | None = None) -> bool:
        g = problem.goals[k]
        if len(self.progress[k].placed) != len(g.objects):
            return False
        if g.anchor is not None:
            settled = self.settled(problem) if settled is None else settled
            return g.anchor in settled
        return True

    def solved_goals(self, problem: Problem) -> int:
        n = self.__dict__.get("_solved")
        if n is None:
            s = self.settled(problem)
            n = self.__dict__["_solved"] = sum(self.goal_done(problem, k, s) for k in range(len(problem.goals)))
        return n

    def done(self, problem: Problem) -> bool:
        return self.solved_goals(problem) == len(problem.goals)

    def reward(self, problem: Problem) -> float:
        """Share of goals solved, blended with the share of goal objects placed (in [0, 1])."""
        nt = len(problem.targets)
        placed = sum(self.committed(problem, o) for o in problem.targets)
        return 0.5 * self.solved_goals(problem) / len(problem.goals) + 0.5 * placed / nt

    def ready(self, problem: Problem) -> list[int]:
        """Goal objects that may be placed now, in index order."""
        settled = self.settled(problem)
        out = []
        for o in problem.targets:
            if self.committed(problem, o):
                continue
            if all(problem.patterns[k].ready(self.ctx(problem, k), o, settled) for k in problem.gates[o]):
                out.append(o)
        return out


@dataclass(frozen=True)
class Transition:
    """Result of one step: the action taken (``None`` when the object stays) and the new state."""

    action: Action | None
    state: SearchState


def _wrapped(pose: np.ndarray) -> np.ndarray:
    """The pose with its yaw in [-pi, pi)."""
    return np.array([pose[0], pose[1], geo.wrap_angle(float(pose[2]))])


def _action(scene: Scene, i: int, pose: np.ndarray, on: int | None, purpose: str) -> Action:
    return Action(object=scene.ids[i], to=(float(pose[0]), float(pose[1]), float(pose[2])),
                  on=None if on is None else scene.ids[on], purpose=purpose)  # type: ignore[arg-type]


def _required_support(problem: Problem, ss: SearchState, o: int) -> int | None:
    gates = problem.gates[o]
    sup = {problem.patterns[k].support(ss.ctx(problem, k), o) for k in gates}
    if len(gates) < len(problem.member[o]):
        sup.add(TABLE)  # a pattern with the default support is in
    return sup.pop() if len(sup) == 1 else None


def _place(problem: Problem, ss: SearchState, o: int, pose: np.ndarray, support: int, rng: np.random.Generator) -> Transition:
    """Goal object ``o`` put at ``pose`` (wrapped) on ``support``, and committed to its goals."""
    world = ss.world.moved(o, pose, support)
    act = _action(problem.scene, o, pose, None if support == TABLE else support, "goal")
    return Transition(act, _commit(problem, ss, world, o, pose, rng))


def _commit(problem: Problem, ss: SearchState, world: State, o: int, pose: np.ndarray, rng: np.random.Generator) -> SearchState:
    prog = list(ss.progress)
    for k in problem.member[o]:
        ctx = Context(problem.scene, world, problem.goals[k], ss.progress[k])
        prog[k] = problem.patterns[k].commit(ctx, o, pose, rng)
    return SearchState(world, tuple(prog))


def _uncommit(problem: Problem, progress: tuple[GoalProgress, ...], o: int) -> tuple[GoalProgress, ...]:
    """Progress after object ``o`` moved away from where the branch had put it."""
    prog = list(progress)
    for k in problem.member.get(o, ()):
        prog[k] = prog[k].without(o)
    for k in problem.anchored.get(o, ()):
        # The anchor moved: every object placed relative to it must be
        # re-placed, so it leaves its other goals too (an object must not
        # stay committed to a line while its relation waits for it).
        for p in prog[k].placed:
            for k2 in problem.member.get(p, ()):
                if k2 != k:
                    prog[k2] = prog[k2].without(p)
        prog[k] = GoalProgress()
    return tuple(prog)


def stay(problem: Problem, ss: SearchState, o: int, rng: np.random.Generator) -> Transition | None:
    """Commit ``o`` where it already is, when that satisfies every prior it is in."""
    world = ss.world
    if _required_support(problem, ss, o) != world.on[o]:
        return None
    pose = np.asarray(world.poses[o])
    for k in problem.member[o]:
        if problem.patterns[k].density(ss.ctx(problem, k), o, pose[None])[0] <= 0:
            return None
    return Transition(None, _commit(problem, ss, world, o, pose, rng))


def _sample(problem: Problem, ss: SearchState, o: int, rng: np.random.Generator, n: int) -> np.ndarray:
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


def _pairs(problem: Problem, ss: SearchState, o: int, poses: np.ndarray,
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


def _collisions_full(problem: Problem, ss: SearchState, o: int, poses: np.ndarray,
                     opts: StepOptions) -> tuple[np.ndarray, list[list[int]], np.ndarray | None, np.ndarray]:
    """Inside-workspace mask and, per candidate, the objects its footprint
    comes too close to (see :func:`_pairs`); also the candidates' footprint
    polygons (``None`` when only discs are involved) and vertices."""
    inside, ci, oi, polys, verts = _pairs(problem, ss, o, poses, opts)
    hits: list[list[int]] = [[] for _ in range(len(poses))]
    for a, b in zip(ci.tolist(), oi.tolist()):
        hits[a].append(b)
    return inside, hits, polys, verts


def _free(problem: Problem, ss: SearchState, o: int, poses: np.ndarray, opts: StepOptions,
          contact: bool = False) -> np.ndarray:
    """Mask of the candidate poses of ``o`` that are free: inside the
    workspace and clear of every obstacle by the clearance or, with
    ``contact``, inside and at most touching (see :func:`touching_only`)."""
    inside, ci, oi, polys, verts = _pairs(problem, ss, o, poses, opts)
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
    over = geo.overlapping(np.full(len(near), a_poly, dtype=object), np.repeat(np.asarray(a_xy, dtype=float)[None], len(near), 0),
                           np.full(len(near), scene.discs[i]), world.poly_array[near], world.poses[near, :2],
                           scene.discs[near], CONTACT_AREA)
    return not bool(over.any())


def _hard(problem: Problem, ss: SearchState, o: int, poses: np.ndarray, polys: np.ndarray, hits: list[list[int]],
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


def _goal_regions(problem: Problem, ss: SearchState, mover: int = -1, avoid: int = -1) -> tuple[np.ndarray, np.ndarray]:
    """Regions where the remaining goal objects will go, as a shapely array
    (may be empty), and which of them belong to a goal of ``avoid``.

    A goal of ``mover`` alone is left out: parked over its own target, an
    object is in nobody's way but its own, and it is the next to move there.
    """
    parts, theirs = [], []
    static = problem.static_regions
    for k, g in enumerate(problem.goals):
        if len(ss.progress[k].placed) == len(g.objects) or g.objects == (mover,):
            continue
        reg = static[k] if k in static else problem.patterns[k].region(ss.ctx(problem, k))
        if reg is not None:
            parts.append(reg)
            theirs.append(avoid in g.objects)
    out = np.empty(len(parts), dtype=object)
    out[:] = parts
    return out, np.asarray(theirs, dtype=bool)


def relocate(problem: Problem, ss: SearchState, b: int, rng: np.random.Generator, opts: StepOptions, purpose: str,
             avoid: int = -1) -> Transition | None:
    """Move obstacle ``b`` to a free table pose, outside remaining goal regions when possible.

    ``avoid`` is the object ``b`` is moved for: a pose in the way of its
    goals is taken only when there is no other.
    """
    scene, world = problem.scene, ss.world
    if not _pickable(problem, world, b, opts):
        return None
    xmin, xmax, ymin, ymax = scene.bounds
    r = float(scene.radii[b])
    check = replace(opts, obstacles="all")
    target = _off_target(problem, b, avoid)

    def off(poses: np.ndarray) -> np.ndarray:
        return target(poses) & reachable(problem, world, b, poses, opts)

    # Candidates from the grid of clear centres first, then, if it has none
    # (elongated neighbours make it pessimistic), larger uniform batches.
    room = clear_centres(scene, world, b, opts.clearance)
    batches = [2 * opts.samples, 16 * opts.samples]
    if len(room):
        batches.insert(0, -1)
    for n in batches:
        grid = n < 0
        if grid:
            k = 4 * opts.samples
            pick = room[rng.choice(len(room), size=min(len(room), k), replace=False)]
            poses = np.empty((len(pick), 3))
            poses[:, :2] = pick
            n = len(pick)
        else:
            poses = np.empty((n, 3))
            poses[:, 0] = rng.uniform(xmin + r, max(xmin + r, xmax - r), n)
            poses[:, 1] = rng.uniform(ymin + r, max(ymin + r, ymax - r), n)
        poses[:, 2] = np.where(rng.random(n) < 0.5, world.poses[b, 2], rng.uniform(-math.pi, math.pi, n))
        if grid:
            # Circumscribed circles apart by the clearance: free at any yaw.
            free = off(poses)
            if free.any():
                break
            continue
        free = _free(problem, ss, b, poses, check) & off(poses)
        if free.any():
            break
    else:
        # No room with the clearance anywhere: park touching neighbours.
        poses = _contact_spots(problem, ss, b, rng, check, off)
        if not len(poses):
            return None
        free = np.ones(len(poses), dtype=bool)
    idx = np.flatnonzero(free)
    regions, theirs = _goal_regions(problem, ss, b, avoid)
    if len(regions):
        # The free pose that overlaps the fewest regions still to be filled
        # (none, when there is one), so the obstacle is not in the way again;
        # above all not in the way of the object it makes room for.
        score = region_scores(regions, theirs, poses[idx, :2], r)
        idx = idx[score == score.min()]
    if len(idx) > 1:
        # Of the best, the snuggest (see :func:`.relocate.snuggest`).
        idx = idx[[snuggest(scene, world, b, poses[idx, :2])]]
    pose = _wrapped(poses[idx[0]])
    new_world = world.moved(b, pose, TABLE)
    act = _action(scene, b, pose, None, purpose)
    return Transition(act, SearchState(new_world, _uncommit(problem, ss.progress, b)))


def _off_target(problem: Problem, b: int, avoid: int):
    """A mask function over poses ``(k, 3)`` of ``b``: whether ``b`` there
    leaves ``avoid``'s fixed target free (its circle, or its circumscribed
    circle for other shapes, at most touching the target's). All true when
    ``avoid`` has no fixed target: parking on a fixed target would not make
    the room the move is for, so such a spot is never taken."""
    if avoid not in problem.fixed:
        return lambda poses: np.ones(len(poses), dtype=bool)
    sc = problem.scene
    t = problem.fixed[avoid][:2]
    both = sc.discs[b] > 0 and sc.discs[avoid] > 0
    reach = float(sc.discs[b] + sc.discs[avoid]) if both else float(sc.radii[b] + sc.radii[avoid])
    return lambda poses: np.hypot(poses[:, 0] - t[0], poses[:, 1] - t[1]) >= reach - 1e-9


def _contact_spots(problem: Problem, ss: SearchState, b: int, rng: np.random.Generator, opts: StepOptions,
                   keep) -> np.ndarray:
    """Poses ``(k, 3)`` where ``b`` fits at most touching other objects and
    the workspace edge, and that pass the mask function ``keep``: grid
    centres whose circumscribed circles do not overlap, else uniform draws
    that pass the contact test."""
    scene, world = problem.scene, ss.world
    xmin, xmax, ymin, ymax = scene.bounds
    r = float(scene.radii[b])
    room = clear_centres(scene, world, b, 0.0)
    if len(room):
        poses = np.empty((len(room), 3))
        poses[:, :2] = room
        poses[:, 2] = world.poses[b, 2]
        poses = poses[keep(poses)]
        if len(poses):
            return poses[rng.choice(len(poses), size=min(len(poses), 4 * opts.samples), replace=False)]
    n = 16 * opts.samples
    poses = np.empty((n, 3))
    poses[:, 0] = rng.uniform(xmin + r, max(xmin + r, xmax - r), n)
    poses[:, 1] = rng.uniform(ymin + r, max(ymin + r, ymax - r), n)
    poses[:, 2] = world.poses[b, 2]
    keep_mask = keep(poses)
    poses = poses[keep_mask]
    return poses[_free(problem, ss, b, poses, opts, contact=True)] if len(poses) else poses


def _clear_top(world: State, i: int, rng: np.random.Generator, exclude: int = -2) -> int:
    tops = [k for k in world.above(i) if world.clear(k) and k != exclude]
    return int(tops[int(rng.integers(len(tops)))])


def _move_blocker(problem: Problem, ss: SearchState, b: int, rng: np.random.Generator, opts: StepOptions, purpose: str,
                  avoid: int = -1) -> Transition | None:
    """Clear blocker ``b``: straight to its own goal when it is a goal object
    that may be placed now (saving the second move), else to a free pose."""
    if b in problem.member and not ss.committed(problem, b) and b in ss.ready(problem):
        tr = attempt(problem, ss, b, rng, opts, direct=True)
        if tr is not None:
            return tr
    return relocate(problem, ss, b, rng, opts, purpose, avoid)


def _move_anchor(problem: Problem, ss: SearchState, o: int, rng: np.random.Generator, opts: StepOptions,
                 placed: bool = True) -> Transition | None:
    """When no pose of ``o``'s prior lies in the workspace, move one of its
    anchors (it stands near an edge, say): preferably one that no goal
    places, to a free pose; else, with ``placed``, one a goal places, which
    sends that goal back to the remaining ones (a plate that is a tower's
    base, say)."""
    if opts.obstacles != "all":
        return None
    anchors = [g.anchor for k in problem.member[o] if (g := problem.goals[k]).anchor is not None and g.anchor != o]
    free = [a for a in anchors if a not in problem.member]
    if not free and placed:
        # An anchor that a goal places moves this way once at most (while it
        # still stands where it started), so a branch cannot keep carrying it.
        start = problem.scene.initial
        free = [a for a in anchors if ss.world.on[a] == start.on[a] and np.array_equal(ss.world.poses[a], start.poses[a])]
    if not free:
        return None
    a = free[int(rng.integers(len(free)))]
    return clear_way(problem, ss, a, rng, opts)


def _to_table(problem: Problem, ss: SearchState, o: int, cand: np.ndarray, rng: np.random.Generator,
              opts: StepOptions) -> tuple[Transition | None, np.ndarray, list[list[int]]]:
    """Place ``o`` at the first free candidate; also the inside mask and each candidate's obstacles."""
    inside, hits, polys, verts = _collisions_full(problem, ss, o, cand, opts)
    ok = inside & np.array([not h for h in hits])
    if ok.any():
        return _place(problem, ss, o, _wrapped(cand[int(np.flatnonzero(ok)[0])]), TABLE, rng), inside, hits
    if o not in problem.fixed:
        return None, inside, hits
    # A fixed target (a pose goal) has no other pose: where it lies closer
    # than the clearance to a neighbour or the edge, contact is allowed.
    # Obstacles are then only what it would overlap.
    edge = geo.inside_workspace(verts, problem.scene.bounds) & reachable(problem, ss.world, o, cand, opts)
    hard = _hard(problem, ss, o, cand, polys, hits, np.flatnonzero(edge))
    touch = edge & np.array([not h for h in hard])
    if touch.any():
        return _place(problem, ss, o, _wrapped(cand[int(np.flatnonzero(touch)[0])]), TABLE, rng), edge, hard
    return None, edge, hard


def fixed_obstacles(problem: Problem, ss: SearchState, objs: list[int], opts: StepOptions) -> dict[int, tuple[int, ...]]:
    """For the clear, table-bound :attr:`Problem.fixed` objects among ``objs``,
    the obstacles at their target (empty when it is free), in one query.

    Objects whose target lies outside the workspace are left out, as are
    the others; :func:`probe` answers for them.
    """
    world = ss.world
    feet = problem.fixed_footprints
    objs = [o for o in objs if o in feet and world.clear(o) and _required_support(problem, ss, o) == TABLE
            and _pickable(problem, world, o, opts) and reachable(problem, world, o, problem.fixed[o][None], opts)[0]]
    out: dict[int, list[int]] = {o: [] for o in objs}
    if objs and problem.scene.n > 1:
        polys = np.empty(len(objs), dtype=object)
        polys[:] = [feet[o] for o in objs]
        xy = np.array([problem.fixed[o][:2] for o in objs])
        sc = problem.scene
        # Only overlaps block a fixed target (it may touch, see _to_table):
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
    return _place(problem, ss, o, _wrapped(problem.fixed[o]), TABLE, rng)


def probe(problem: Problem, ss: SearchState, o: int, rng: np.random.Generator,
          opts: StepOptions) -> tuple[Transition | None, tuple[int, ...]]:
    """A direct placement of ``o`` (as ``attempt(direct=True)``) or, when every
    table candidate collides, the obstacles of its least obstructed one."""
    if not ss.world.clear(o) or _required_support(problem, ss, o) != TABLE:
        return attempt(problem, ss, o, rng, opts, direct=True), ()
    if not _pickable(problem, ss.world, o, opts):
        return None, ()
    cand = _sample(problem, ss, o, rng, opts.samples)
    if len(cand) == 0:
        return None, ()
    tr, inside, hits = _to_table(problem, ss, o, cand, rng, opts)
    if tr is not None:
        return tr, ()
    blocked = [hits[k] for k in np.flatnonzero(inside) if hits[k]]
    if not blocked:
        return None, ()
    return None, tuple(min(blocked, key=len))


def clear_way(problem: Problem, ss: SearchState, b: int, rng: np.random.Generator, opts: StepOptions,
              avoid: int = -1) -> Transition | None:
    """Move obstacle ``b`` out of the way of object ``avoid`` (the top of its stack first)."""
    if not ss.world.clear(b):
        return _move_blocker(problem, ss, _clear_top(ss.world, b, rng), rng, opts, "unstack", avoid)
    return _move_blocker(problem, ss, b, rng, opts, "relocate", avoid)


def attempt(problem: Problem, ss: SearchState, o: int, rng: np.random.Generator, opts: StepOptions,
            *, direct: bool = False, placed_anchors: bool = True) -> Transition | None:
    """One simulation step for goal object ``o`` (paper, Algorithm 1).

    Returns ``None`` when no action could be found (no pose in the prior, no
    free pose for a blocker). With ``direct`` only a placement of ``o``
    itself is tried: no unstacking and no relocation. ``placed_anchors``
    lets it move an anchor that a goal places when ``o``'s relation has no
    room at all (rollouts leave that to the tree: such a move is a gamble).
    """
    world = ss.world
    if not world.clear(o):
        if direct:
            return None
        return _move_blocker(problem, ss, _clear_top(world, o, rng), rng, opts, "unstack", o)
    support = _required_support(problem, ss, o)
    if support is None or not _pickable(problem, world, o, opts):
        return None
    cand = _sample(problem, ss, o, rng, opts.samples)
    if len(cand) == 0:
        return None  # the priors exclude each other here: moving an anchor would not help
    if support != TABLE:
        if any(k != o for k in world.holding[support]):
            if direct:
                return None
            return _move_blocker(problem, ss, _clear_top(world, support, rng, exclude=o), rng, opts, "unstack", o)
        pose = _wrapped(cand[0])
        if not shapely.contains_xy(world.polys[support], pose[0], pose[1]):
            return None
        if not reachable(problem, world, o, pose[None], opts, support)[0]:
            return None
        return _place(problem, ss, o, pose, support, rng)
    tr, inside, hits = _to_table(problem, ss, o, cand, rng, opts)
    if tr is not None:
        return tr
    if opts.obstacles != "all" or direct:
        return None
    # Every candidate collides: clear the way for one of them (fewest blockers first).
    blocked = [k for k in np.flatnonzero(inside) if hits[k]]
    if not blocked:
        return _move_anchor(problem, ss, o, rng, opts, placed_anchors)
    fewest = min(len(hits[k]) for k in blocked)
    pick = [k for k in blocked if len(hits[k]) == fewest]
    chosen = hits[int(pick[int(rng.integers(len(pick)))])]
    b = int(chosen[int(rng.integers(len(chosen)))])
    if b == o:
        return None
    return clear_way(problem, ss, b, rng, opts, o)
