"""Plan polishing: drop moves a solved plan does not need.

Search returns the first plan that reaches every goal, and its random
relocations are often more than the scene requires: an obstacle moved out of
a region that the pattern ended up not using, or a buried goal object parked
on the table before its final move. Two rewrites fix most of that:

* **merge** — an object moved more than once goes straight to its last pose
  at its first move, and the later move is dropped;
* **drop** — a relocation (or any earlier move of an object that moves
  again) is removed.

Both passes are linear in the number of actions. Each candidate rewrite is
replayed on the planner's own states from the first action it changes,
until it rejoins a state of the plan being rewritten with the same actions
still to come (the rest is unchanged). The replay checks every
pick of a clear object, every table placement inside the workspace and
keeping the search's clearance from every other footprint (or, for a goal
placement on a fixed target, at most touching it: the contact that the
search itself allows, see :func:`lgmcts.planner.placement.touching_only`), every
stacking onto a clear
support over its footprint, and every goal met at the end (firmly, still
met when every centre moves by up to 2 mm, for a goal whose objects no
longer end where the search put them). The polished
plan is then checked by the independent validator
(:func:`lgmcts.validate.check`); should it fail there, the plan as the
search found it is validated and returned instead.
"""

from __future__ import annotations

import numpy as np
import shapely

from .. import geometry as geo
from ..formats import Action
from ..patterns import CLEARANCE
from ..scene import TABLE, replay
from ..validate import goal_satisfied
from .domain import valid_plan
from .placement import CONTACT_AREA, touching_only
from .problem import Problem

__all__ = ["polished"]


def _worlds(problem: Problem, actions: list[Action]) -> list:
    """States of the planner's world before each action and after the last."""
    return replay(problem.scene, actions)


def _same(a, b) -> bool:
    return a is b or (a.on == b.on and np.array_equal(a.poses, b.poses))


def _replay(problem: Problem, actions: list[Action], start: int, world, ref: np.ndarray,
            worlds: list | None = None, sync: int = 0, shift: int = 0) -> list | None:
    """Replay ``actions[start:]`` from ``world``: the states before each of
    them and after the last when every move is legal and every goal ends met
    (firmly where an object ends elsewhere than in ``ref``), else ``None``.

    ``worlds`` are the states of the plan being rewritten, whose action
    ``t + shift`` is ``actions[t]`` for every ``t >= sync``. Once the replay
    reaches one of those states before such an action, the rest would repeat
    a replay already accepted, so its states are taken as they are.
    """
    scene = problem.scene
    states = [world]
    for t in range(start, len(actions)):
        if worlds is not None and t >= sync and t > start and _same(world, worlds[t + shift]):
            return states[:-1] + worlds[t + shift :]
        a = actions[t]
        i = scene.index[a.object]
        if not world.clear(i):
            return None
        pose = np.asarray(a.to, dtype=float)
        if a.on is None:
            if not geo.inside_workspace(scene.footprint(i, pose)[None], scene.bounds)[0]:
                return None
            world = world.moved(i, pose, TABLE)
            _, near = geo.colliding_near(world.poly_array[i : i + 1], pose[:2], scene.radii[i], world.poly_array,
                                         world.poses[:, :2], scene.radii, CLEARANCE * 0.99,
                                         cand_disc=scene.discs[i], obs_disc=scene.discs)
            near = near[near != i]
            # Closer than the clearance only where the search allows it: a
            # fixed target (pose goal) placed in contact.
            if len(near) and not (_contact_ok(problem, a, i) and touching_only(scene, world, i, near)):
                return None
        else:
            j = scene.index[a.on]
            if any(k != i for k in world.holding[j]) or not shapely.contains_xy(world.polys[j], pose[0], pose[1]):
                return None
            world = world.moved(i, pose, j)
        states.append(world)
    return states if _goals_hold_firmly(problem, world, ref) else None


#: Rewritten plans must still meet every goal with each centre moved by up to
#: this much (m), in :data:`FIRM_TRIALS` fixed random ways: a rewrite may leave
#: objects where they happen to stand, and a goal met only by a hair (a centre
#: at the edge of a relation's cone, a minimum-area rectangle that could as
#: well lie another way) would fail under the smallest placement error.
FIRM_JITTER = 0.002
FIRM_TRIALS = 8


def _goals_hold_firmly(problem: Problem, world, ref: np.ndarray) -> bool:
    """Every goal holds, and those with an object (or anchor) ending elsewhere
    than in the final poses ``ref`` of the search's plan hold firmly."""
    scene, goals = problem.scene, problem.spec.goals
    if any(goal_satisfied(g, scene, world.poses, world.on) is not None for g in goals):
        return False
    moved = {scene.ids[i] for i in np.flatnonzero(np.any(world.poses != ref, axis=1))}
    goals = [g for g in goals if moved.intersection(g.objects) or g.anchor in moved]
    if not goals:
        return True
    rng = np.random.default_rng(0)
    for _ in range(FIRM_TRIALS):
        poses = np.array(world.poses, dtype=float)
        poses[:, :2] += rng.uniform(-FIRM_JITTER, FIRM_JITTER, (scene.n, 2))
        if any(goal_satisfied(g, scene, poses, world.on) is not None for g in goals):
            return False
    return True


def _crowds(problem: Problem, actions: list[Action], worlds: list, poly, i: int, j: int) -> bool:
    """Whether a table placement of another object among ``actions[i + 1 : j]``
    comes within the clearance of ``poly``: with ``actions[i]``'s object
    standing there meanwhile that placement would fail, so a rewrite that
    leaves it there need not be replayed."""
    sc = problem.scene
    obj = actions[i].object
    ks = [k for k in range(i + 1, min(j, len(actions))) if actions[k].on is None and actions[k].object != obj]
    if not ks:
        return False
    placed = np.empty(len(ks), dtype=object)
    placed[:] = [worlds[k + 1].polys[sc.index[actions[k].object]] for k in ks]
    near = np.flatnonzero(shapely.dwithin(poly, placed, CLEARANCE * 0.99))
    if not len(near):
        return False
    # A fixed target placed in contact is no conflict (the search allows that, see placement.touching_only).
    a = sc.index[obj]
    b = np.array([sc.index[actions[ks[t]].object] for t in near])
    xy_a = np.array(shapely.get_coordinates(shapely.centroid(poly)))[0] if sc.discs[a] > 0 else np.zeros(2)
    xy_b = np.array([worlds[ks[t] + 1].poses[sc.index[actions[ks[t]].object], :2] for t in near])
    over = geo.overlapping(np.full(len(near), poly, dtype=object), np.repeat(xy_a[None], len(near), axis=0),
                           np.full(len(near), sc.discs[a]), placed[near], xy_b, sc.discs[b], CONTACT_AREA)
    forgiven = np.array([_contact_ok(problem, actions[ks[t]], int(bb)) for t, bb in zip(near, b)]) & ~over
    return not bool(forgiven.all())


def _contact_ok(problem: Problem, action: Action, i: int) -> bool:
    """Whether the search may place ``action``'s object ``i`` closer than the
    clearance: a goal placement on a fixed target (see placement.to_table)."""
    return action.purpose == "goal" and i in problem.fixed


def _merge(problem: Problem, actions: list[Action], worlds: list, ref: np.ndarray) -> tuple[list[Action], list]:
    i = 0
    while i < len(actions):
        a = actions[i]
        later = [j for j in range(i + 1, len(actions)) if actions[j].object == a.object]
        if later:
            j = later[-1]
            last = actions[j]
            trial = list(actions)
            trial[i] = last
            for k in reversed(later):
                del trial[k]
            final = worlds[j + 1].polys[problem.scene.index[a.object]]
            after = (None if _crowds(problem, actions, worlds, final, i, j)
                     else _replay(problem, trial, i, worlds[i], ref, worlds, j + 1 - len(later), len(later)))
            if after is not None:
                actions = trial
                worlds = worlds[:i] + after
                continue
        i += 1
    return actions, worlds


def _drop(problem: Problem, actions: list[Action], worlds: list, ref: np.ndarray) -> list[Action]:
    moves: dict[int, int] = {}
    for a in actions:
        moves[a.object] = moves.get(a.object, 0) + 1
    i = 0
    while i < len(actions):
        a = actions[i]
        if a.purpose != "goal" or moves[a.object] > 1:
            trial = actions[:i] + actions[i + 1 :]
            nxt = next((j for j in range(i + 1, len(actions)) if actions[j].object == a.object), len(actions))
            o = problem.scene.index[a.object]
            stays = worlds[i].polys[o]
            skip = _crowds(problem, actions, worlds, stays, i, nxt) or _last_move_needed(
                problem, worlds, i, o, nxt, ref
            )
            after = None if skip else _replay(problem, trial, i, worlds[i], ref, worlds, i, 1)
            if after is not None:
                moves[a.object] -= 1
                actions = trial
                worlds = worlds[:i] + after
                continue
        i += 1
    return actions


def _last_move_needed(problem: Problem, worlds: list, i: int, o: int, nxt: int, ref: np.ndarray) -> bool:
    """Whether dropping action ``i``, the last move of object ``o`` (``nxt``
    past the end), surely leaves a goal unmet.

    A replay of the plan without that move can never rejoin the plan's
    states (``o`` stands elsewhere in all of them), so if it succeeds it
    ends in the final state with ``o`` left where it stood before ``i``; the
    goals are judged on that state now, as the replay would judge them at
    its end, without the replay's steps. Same answer, without replaying to
    the end of a long plan.
    """
    if nxt < len(worlds) - 1:
        return False
    before, last = worlds[i], worlds[-1]
    if before.on[o] == last.on[o] and np.array_equal(before.poses[o], last.poses[o]):
        return False
    return not _goals_hold_firmly(problem, last.moved(o, before.poses[o], before.on[o]), ref)


def _rewrite(problem: Problem, actions: list[Action], worlds: list | None = None) -> list[Action]:
    if worlds is None or len(worlds) != len(actions) + 1:
        worlds = _worlds(problem, actions)
    ref = np.array(worlds[-1].poses)
    merged, worlds = _merge(problem, actions, worlds, ref)
    return _drop(problem, merged, worlds, ref)


def polished(problem: Problem, actions: list[Action], worlds: list | None = None) -> list[Action] | None:
    """The search's acceptance step with polishing (a :data:`~lgmcts.planner.domain.Accept`).

    ``actions`` reach every goal in the planner's model but have not been
    validated. The polished plan is returned when the validator accepts it,
    else ``actions`` when it accepts those, else ``None``. Usually one
    validator run, where polishing a validated plan would take two.
    ``worlds``, the search's states along the plan, saves replaying it.
    """
    out = _rewrite(problem, list(actions), worlds)
    if len(out) < len(actions) and valid_plan(problem, out):
        return out
    return list(actions) if valid_plan(problem, actions) else None
