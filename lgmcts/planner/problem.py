"""The search problem and its immutable search state.

:class:`Problem` holds a scene and its goals compiled to indices, shared by
every search node; :class:`SearchState` is a world state plus, per goal,
what a branch has fixed. :func:`commit` and :func:`uncommit` update that
progress when an object is put on its goal or moved away from it.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import Any

import numpy as np

from .. import geometry as geo
from ..errors import InputError
from ..formats import GoalSpec
from ..patterns import CompiledGoal, Context, GoalProgress, Pattern, registry
from ..patterns.base import BasePattern, compile_params
from ..scene import Scene, State

__all__ = ["Problem", "SearchState", "commit", "uncommit"]


@dataclass(frozen=True)
class Problem:
    """A scene and goals compiled to indices, shared by every search node."""

    scene: Scene
    spec: GoalSpec
    goals: tuple[CompiledGoal, ...]
    patterns: tuple[Pattern, ...]

    @classmethod
    def build(cls, scene: Scene, spec: GoalSpec) -> Problem:
        spec.check_against(scene.spec)
        reg = registry()
        goals, patterns = [], []
        for k, g in enumerate(spec.goals):
            idx = tuple(scene.index[i] for i in g.objects)
            anchor = None if g.anchor is None else scene.index[g.anchor]
            pose = None if g.pose is None else (g.pose[0], g.pose[1], g.pose[2])
            goals.append(CompiledGoal(k, g.pattern, idx, anchor, pose, compile_params(g, scene)))
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
    def free_objects(self) -> frozenset[int]:
        """Objects that no goal moves."""
        return frozenset(range(self.scene.n)) - frozenset(self.member)

    @cached_property
    def targets(self) -> tuple[int, ...]:
        return tuple(sorted(self.member))

    def root(self) -> SearchState:
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
            s = self.__dict__["_settled_set"] = problem.free_objects | self._committed(problem)
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
        placed = len(self._committed(problem))  # committed objects are targets
        return 0.5 * self.solved_goals(problem) / len(problem.goals) + 0.5 * placed / nt

    def ready(self, problem: Problem) -> list[int]:
        """Goal objects that may be placed now, in index order."""
        settled = self.settled(problem)
        done = self._committed(problem)
        gates = problem.gates
        out = []
        for o in problem.targets:
            if o in done:
                continue
            if not gates[o] or all(problem.patterns[k].ready(self.ctx(problem, k), o, settled) for k in gates[o]):
                out.append(o)
        return out


def commit(problem: Problem, ss: SearchState, world: State, o: int, pose: np.ndarray,
           rng: np.random.Generator) -> SearchState:
    """The state with ``world`` and goal object ``o`` committed at ``pose`` to each of its goals."""
    prog = list(ss.progress)
    for k in problem.member[o]:
        ctx = Context(problem.scene, world, problem.goals[k], ss.progress[k])
        prog[k] = problem.patterns[k].commit(ctx, o, pose, rng)
    out = SearchState(world, tuple(prog))
    _carry_counts(problem, ss, out, problem.member[o])
    return out


def _carry_counts(problem: Problem, parent: SearchState, child: SearchState, changed: tuple[int, ...]) -> None:
    """Derive ``child``'s committed set and solved-goal count from ``parent``'s
    when only the goals ``changed`` differ between them: the work of one step
    grows with the goals it touches, not with the scene.

    The result is what the child would compute from scratch: an object's
    commitment depends only on its first goal's progress, and a goal's
    completion only on its own progress and on whether its anchor is settled.
    """
    before = parent.__dict__.get("_committed_set")
    if before is None:
        return
    member = problem.member
    flips = []
    for k in changed:
        for p in problem.goals[k].objects:
            ks = member.get(p)
            if ks and ks[0] == k and (p in before) != (p in child.progress[k].placed):
                flips.append(p)
    after = before.symmetric_difference(flips) if flips else before
    child.__dict__["_committed_set"] = after
    solved = parent.__dict__.get("_solved")
    if solved is None:
        return
    touched = set(changed)
    for p in flips:
        touched.update(problem.anchored.get(p, ()))
    s_parent, s_child = parent.settled(problem), child.settled(problem)
    for k in touched:
        solved += int(child.goal_done(problem, k, s_child)) - int(parent.goal_done(problem, k, s_parent))
    child.__dict__["_solved"] = solved


def uncommit(problem: Problem, progress: tuple[GoalProgress, ...], o: int) -> tuple[GoalProgress, ...]:
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
