"""Execute a plan in MuJoCo with a suction gripper and judge the outcome.

The gripper is a mocap body; picking an object switches on the weld
constraint between the gripper and that object, so the object follows the
gripper through the constraint solver while still colliding with the rest of
the scene. Each action runs the same primitive:

1. check in physics that nothing rests on the object (else the step fails);
2. attach at the object's current pose;
3. lift straight up until its bottom clears the highest object by
   ``clearance``;
4. carry horizontally to above the target while turning to the target yaw;
5. lower, fast to ``approach_height`` above the planned height, then slowly
   until the object's bottom touches something (or ``overshoot`` below the
   planned height: then the object is dropped where it is); when what it
   touches is an object other than the planned support (the rim of a
   neighbour it touches), lift a little, step ``nudge_step`` away from that
   contact and lower again, up to ``nudge_tries`` times;
6. release and let the scene settle until every object is still.

The final state is judged by :func:`lgmcts.validate.goal_satisfied` for every
goal, plus the executor's own rules: no object tilted more than
``max_tilt_deg``, no object off the table or outside the workspace, every
placed object within ``place_tol`` of where the plan put it and on the
support the plan named, and every pick of a clear object.
"""

from __future__ import annotations

import copy
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from ..errors import InputError
from ..formats import GoalSpec, PlanSpec, SceneSpec, load_goals, load_plan, load_scene
from ..scene import TABLE, Scene, State
from ..validate import goal_satisfied
from . import physics
from .model import ModelOptions, SimModel, build_model, yaw_quat

__all__ = ["ExecOptions", "Execution", "Executor", "StepOutcome", "execute_plan"]

FrameHook = Callable[[mujoco.MjData], None]

#: Step failures that only the arm causes; each fails an execution with the arm.
ARM_FAILURES = ("out of reach", "joint limit", "arm collision", "dropped in transfer")


@dataclass(frozen=True)
class ExecOptions:
    """Options of the pick-and-place primitive and of the verdict.

    Attributes
    ----------
    model : physical parameters of the simulated scene.
    speed : cruise speed of the gripper (m/s).
    yaw_rate : turning rate of the gripper while carrying (rad/s).
    clearance : gap kept between the carried object's bottom and the highest
        other object while carrying (m).
    approach_height : height above the planned placement where the slow final
        descent starts (m).
    approach_speed : speed of the final descent (m/s).
    overshoot : how far below the planned height the descent may go without a
        contact before the object is released anyway (m).
    nudge_step : when the lowered object lands on an object other than its
        planned support (the rim of a neighbour it touches or overlaps by a
        sliver the acceptance rules tolerate), it is lifted by
        ``nudge_lift``, moved this far away from that contact and lowered
        again (m).
    nudge_lift : lift before a nudge (m).
    nudge_tries : most nudges per placement; after the last the object is
        released where it is.
    settle_min : time always simulated after a release (s).
    settle_max : longest settling time after a release (s).
    settle_speed : the scene counts as still once every object moves slower
        than this (m/s).
    max_tilt_deg : an object tilted more than this counts as toppled (deg).
    place_tol : largest distance between where the plan put an object and
        where it came to rest (m).
    workspace_tol : how far an object's centre may lie outside the workspace
        before it counts as off the table (m).
    stop_on_failure : stop executing at the first failed pick.
    """

    model: ModelOptions = field(default_factory=ModelOptions)
    speed: float = 0.6
    yaw_rate: float = 4.0
    clearance: float = 0.03
    approach_height: float = 0.015
    approach_speed: float = 0.08
    overshoot: float = 0.02
    nudge_step: float = 0.001
    nudge_lift: float = 0.003
    nudge_tries: int = 4
    settle_min: float = 0.06
    settle_max: float = 2.0
    settle_speed: float = 0.003
    max_tilt_deg: float = 15.0
    place_tol: float = 0.01
    workspace_tol: float = 0.01
    stop_on_failure: bool = True


@dataclass(frozen=True)
class StepOutcome:
    """The outcome of one pick-and-place action.

    Attributes
    ----------
    index : 1-based position of the action in the plan.
    object : id of the object picked.
    ok : the pick succeeded and the object came to rest upright, on the
        planned support, within ``place_tol`` of the planned pose.
    reached : ``[x, y, theta]`` where the object came to rest (m, rad), or
        ``None`` when it was never picked.
    error : distance between ``reached`` and the planned ``to`` (m); ``nan``
        when never picked.
    message : what happened, in words.
    """

    index: int
    object: int
    ok: bool
    reached: tuple[float, float, float] | None
    error: float
    message: str

    def to_dict(self) -> dict[str, Any]:
        return {
            "index": self.index,
            "object": self.object,
            "ok": self.ok,
            "reached": None if self.reached is None else list(self.reached),
            "error": None if math.isnan(self.error) else self.error,
            "message": self.message,
        }


@dataclass(frozen=True)
class Execution:
    """The result of :func:`execute_plan`.

    Attributes
    ----------
    success : every step succeeded and the final state passes every rule.
    reasons : each rule the final state breaks, in words.
    steps : per executed action, its :class:`StepOutcome`.
    final : the scene as read back from physics (poses and supports).
    goals : per goal, whether it holds in the final state.
    sim_time : simulated time (s).
    """

    success: bool
    reasons: tuple[str, ...]
    steps: tuple[StepOutcome, ...]
    final: SceneSpec
    goals: tuple[bool, ...] = ()
    sim_time: float = 0.0

    def __bool__(self) -> bool:
        return self.success

    def to_dict(self) -> dict[str, Any]:
        from ..formats import to_dict

        return {
            "success": self.success,
            "reasons": list(self.reasons),
            "goals": list(self.goals),
            "steps": [s.to_dict() for s in self.steps],
            "sim_time": self.sim_time,
            "final": to_dict(self.final),
        }


def _smooth(s: float) -> float:
    """Smoothstep on [0, 1]: zero velocity at both ends."""
    return s * s * (3.0 - 2.0 * s)


def _slerp(q0: np.ndarray, q1: np.ndarray, s: float) -> np.ndarray:
    d = float(q0 @ q1)
    if d < 0:
        q1, d = -q1, -d
    if d > 0.9995:
        q = q0 + s * (q1 - q0)
        return q / np.linalg.norm(q)
    a = math.acos(d)
    return (math.sin((1 - s) * a) * q0 + math.sin(s * a) * q1) / math.sin(a)


class Executor:
    """A live simulation of one scene that executes actions one at a time.

    Parameters
    ----------
    sim : the compiled scene model.
    options : primitive and verdict options.
    on_step : called with ``data`` after every physics step (video capture).
    """

    def __init__(self, sim: SimModel, *, options: ExecOptions | None = None, on_step: FrameHook | None = None):
        self.sim = sim
        self.opts = options or ExecOptions()
        self.model = sim.model
        self.data = mujoco.MjData(sim.model)
        self.on_step = on_step
        mujoco.mj_forward(self.model, self.data)
        self._dt = self.model.opt.timestep

    # ------------------------------------------------------------ stepping

    def step(self, n: int = 1) -> None:
        """Advance the physics by ``n`` steps."""
        m, d, hook = self.model, self.data, self.on_step
        for _ in range(n):
            mujoco.mj_step(m, d)
            if hook is not None:
                hook(d)

    def settle(self) -> None:
        """Step until every object is still (or ``settle_max`` has passed)."""
        o = self.opts
        self.step(max(1, round(o.settle_min / self._dt)))
        left = max(0, round((o.settle_max - o.settle_min) / self._dt))
        chunk = 5
        while left > 0:
            if physics.speeds(self.sim, self.data).max() < o.settle_speed:
                return
            self.step(min(chunk, left))
            left -= chunk

    def _move(self, pos: np.ndarray, quat: np.ndarray, speed: float, stop: Callable[[], bool] | None = None) -> bool:
        """Drive the gripper to ``pos``/``quat`` along a straight line; return
        ``True`` if ``stop`` fired on the way."""
        d, mi = self.data, self.sim.mocap
        p0, q0 = d.mocap_pos[mi].copy(), d.mocap_quat[mi].copy()
        dist = float(np.linalg.norm(pos - p0))
        ang = 2 * math.acos(min(1.0, abs(float(q0 @ quat))))
        t = max(dist / speed, ang / self.opts.yaw_rate, 2 * self._dt)
        n = max(1, math.ceil(t / self._dt))
        for i in range(1, n + 1):
            s = _smooth(i / n) if stop is None else i / n
            d.mocap_pos[mi] = p0 + s * (pos - p0)
            d.mocap_quat[mi] = _slerp(q0, quat, s)
            self.step()
            if stop is not None and stop():
                return True
        return False

    def snapshot(self) -> mujoco.MjData:
        """A copy of the whole simulation, to :meth:`restore` later.

        A full ``MjData`` copy rather than ``mj_getState``: the state vector
        does not record which objects sleep, and replays from it differ in the
        last digits when sleeping is on.
        """
        return copy.copy(self.data)

    def restore(self, snapshot: mujoco.MjData) -> None:
        """Return to a state taken by :meth:`snapshot` (the snapshot stays reusable)."""
        self.data = copy.copy(snapshot)

    # ------------------------------------------------------------ read-back

    def state(self) -> tuple[np.ndarray, tuple[int, ...]]:
        """Current ``(n, 3)`` poses and supports (object index, TABLE or FLOOR)."""
        return physics.poses(self.sim, self.data), physics.supports(self.sim, self.data)

    # ------------------------------------------------------------ primitive

    def pick_and_place(self, k: int, to: np.ndarray, on: int | None, *, index: int = 0) -> StepOutcome:
        """Move object index ``k`` to pose ``to`` on the table (``on=None``) or
        on object index ``on``; return what happened."""
        sim, d, o = self.sim, self.data, self.opts
        oid = sim.scene.ids[k]
        sup = physics.supports(sim, d)
        blockers = [sim.scene.ids[j] for j, s in enumerate(sup) if s == k]
        if blockers:
            why = f"pick failed: object {oid} is covered by object {blockers[0]}"
            return StepOutcome(index, oid, False, None, math.nan, why)
        body = sim.body[k]
        mi = sim.mocap
        d.mocap_pos[mi] = d.xpos[body]
        d.mocap_quat[mi] = d.xquat[body]
        d.eq_active[sim.weld[k]] = 1
        half = float(sim.heights[k]) / 2
        others = np.delete(physics.tops(sim, d), k)
        carry_z = max(float(others.max(initial=0.0)), 0.0) + o.clearance + half
        carry_z = max(carry_z, float(d.xpos[body, 2]) + o.clearance)
        here = d.mocap_pos[mi].copy()
        self._move(np.array([here[0], here[1], carry_z]), d.mocap_quat[mi].copy(), o.speed)
        target_q = yaw_quat(float(to[2]))
        self._move(np.array([to[0], to[1], carry_z]), target_q, o.speed)
        if on is None:
            z_place = half
        else:
            z_place = float(d.xpos[sim.body[on], 2]) + float(sim.heights[on]) / 2 + half
        self._move(np.array([to[0], to[1], z_place + o.approach_height]), target_q, o.speed)
        landed = self._move(
            np.array([to[0], to[1], z_place - o.overshoot]),
            target_q,
            o.approach_speed,
            stop=lambda: physics.bottom_contact(sim, d, k),
        )
        want = TABLE if on is None else on
        xy = np.array(to[:2], dtype=float)
        for _ in range(o.nudge_tries if landed else 0):
            # Landed on something other than the planned support: step away from it.
            wrong = [p for j, p in physics.landing(sim, d, k) if j != want and j >= 0]
            if not wrong or any(j == want for j, _ in physics.landing(sim, d, k)):
                break
            away = d.xpos[body, :2] - np.mean(wrong, axis=0)[:2]
            norm = float(np.hypot(*away))
            if norm < 1e-9:
                break
            xy = xy + o.nudge_step * away / norm
            here = d.mocap_pos[mi].copy()
            self._move(here + np.array([0.0, 0.0, o.nudge_lift]), target_q, o.approach_speed)
            self._move(np.array([xy[0], xy[1], here[2] + o.nudge_lift]), target_q, o.approach_speed)
            landed = self._move(
                np.array([xy[0], xy[1], z_place - o.overshoot]),
                target_q,
                o.approach_speed,
                stop=lambda: physics.bottom_contact(sim, d, k),
            )
        d.eq_active[sim.weld[k]] = 0
        d.mocap_pos[mi] = d.mocap_pos[mi] + np.array([0.0, 0.0, 0.05])
        self.settle()
        pose = physics.poses(sim, d)[k]
        tilt = math.degrees(float(physics.tilts(sim, d)[k]))
        rests_on = physics.supports(sim, d)[k]
        err = float(math.hypot(pose[0] - to[0], pose[1] - to[1]))
        problems = []
        if not landed:
            problems.append("released without touching a support")
        if tilt > o.max_tilt_deg:
            problems.append(f"toppled ({tilt:.0f} deg)")
        if rests_on != want:
            problems.append(f"ended on {self._name(rests_on)}, planned on {self._name(want)}")
        if err > o.place_tol:
            problems.append(f"{err * 1000:.1f} mm from the planned pose")
        msg = "placed" if not problems else "; ".join(problems)
        reached = (float(pose[0]), float(pose[1]), float(pose[2]))
        return StepOutcome(index, oid, not problems, reached, err, f"{msg} ({err * 1000:.1f} mm off)")

    def _name(self, s: int) -> str:
        if s == TABLE:
            return "the table"
        if s == physics.FLOOR:
            return "the floor"
        return f"object {self.sim.scene.ids[s]}"


def _resolve(scene: Any, plan: Any, goals: Any) -> tuple[SceneSpec, PlanSpec, GoalSpec]:
    spec = load_scene(scene) if not isinstance(scene, SceneSpec) else scene
    pl = load_plan(plan) if not isinstance(plan, PlanSpec) else plan
    if goals is None:
        if pl.goals is None:
            raise InputError("no goals given and the plan carries none")
        gs = pl.goals
    else:
        gs = load_goals(goals) if not isinstance(goals, GoalSpec) else goals
    gs.check_against(spec)
    ids = {o.id for o in spec.objects}
    for n, a in enumerate(pl.actions, start=1):
        if a.object not in ids:
            raise InputError(f"action {n} picks unknown object id {a.object}")
        if a.on is not None and a.on not in ids:
            raise InputError(f"action {n} places on unknown object id {a.on}")
        if a.on == a.object:
            raise InputError(f"action {n} places object {a.object} on itself")
    return spec, pl, gs


def _compose(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Planar pose composition ``a ∘ b`` (``b`` expressed in ``a``'s frame)."""
    c, s = math.cos(a[2]), math.sin(a[2])
    return np.array([a[0] + c * b[0] - s * b[1], a[1] + s * b[0] + c * b[1], a[2] + b[2]])


def _relative(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Planar pose of ``b`` in the frame of ``a`` (``a⁻¹ ∘ b``)."""
    c, s = math.cos(a[2]), math.sin(a[2])
    dx, dy = b[0] - a[0], b[1] - a[1]
    return np.array([c * dx + s * dy, -s * dx + c * dy, b[2] - a[2]])


def execute_plan(
    scene: SceneSpec | dict | str | Path,
    plan: PlanSpec | dict | str | Path,
    goals: GoalSpec | dict | str | Path | None = None,
    *,
    options: ExecOptions | None = None,
    video: str | Path | None = None,
    plan_scene: SceneSpec | dict | str | Path | None = None,
    robot: str | None = None,
) -> Execution:
    """Execute ``plan`` on ``scene`` in MuJoCo and judge the final state.

    Parameters
    ----------
    scene : the true scene that is simulated (spec, dict or JSON path).
    plan : the plan (spec, dict or JSON path).
    goals : the goals to judge against; defaults to the goals the plan
        carries.
    options : primitive and verdict options (:class:`ExecOptions`).
    video : write an mp4 of the execution here (angled camera).
    plan_scene : the scene the plan was made on when it differs from
        ``scene`` (e.g. one built by :func:`lgmcts.sim.observe`). Each
        action's ``to`` then moves the object rigidly by the same motion it
        makes in ``plan_scene``, which keeps the planned footprint where the
        planner put it even when the observed pose frame differs from the
        true one.
    robot : ``"ur5e"``: execute with a UR5e arm and suction cup
        (:mod:`lgmcts.sim.arm_exec`) instead of the floating cup.

    Returns
    -------
    Execution
        Success, reasons, per-step outcomes and the final scene.

    Raises
    ------
    InputError
        For malformed inputs (unknown ids, unreadable files); a plan that
        fails in physics is a value, not an exception.
    """
    opts = options or ExecOptions()
    spec, pl, gs = _resolve(scene, plan, goals)
    sc = Scene.from_spec(spec)
    offsets = None
    if plan_scene is not None:
        ps = Scene.from_spec(load_scene(plan_scene) if not isinstance(plan_scene, SceneSpec) else plan_scene)
        if set(ps.ids) != set(sc.ids):
            raise InputError("plan_scene and scene do not hold the same object ids")
        offsets = {i: _relative(ps.initial.poses[ps.index[i]], sc.initial.poses[sc.index[i]]) for i in sc.ids}
    sim = build_model(sc, options=opts.model, robot=robot)
    if video is not None:
        from .model import ARM_VIEW_CAMERA, VIEW_CAMERA
        from .render import VideoRecorder

        with VideoRecorder(sim, video, camera=ARM_VIEW_CAMERA if sim.arm is not None else VIEW_CAMERA) as rec:
            return _run(sim, sc, pl, gs, opts, offsets, rec.capture)
    return _run(sim, sc, pl, gs, opts, offsets, None)


def _executor(sim: SimModel, opts: ExecOptions, hook: FrameHook | None) -> Executor:
    """The floating cup's executor, or the arm's when the model holds one."""
    if sim.arm is not None:
        from .arm_exec import ArmExecutor

        return ArmExecutor(sim, options=opts, on_step=hook)
    return Executor(sim, options=opts, on_step=hook)


def _arm_failure(sim: SimModel, n: int, out: StepOutcome) -> list[str]:
    """The step as a reason when it names a failure only the arm causes (a
    real arm stops on these: the plan fails even if the scene ends right)."""
    if sim.arm is not None and out.reached is not None and any(c in out.message for c in ARM_FAILURES):
        return [f"action {n}: {out.message}"]
    return []


def _run(
    sim: SimModel,
    sc: Scene,
    pl: PlanSpec,
    gs: GoalSpec,
    opts: ExecOptions,
    offsets: dict[int, np.ndarray] | None,
    hook: FrameHook | None,
) -> Execution:
    ex = _executor(sim, opts, hook)
    ex.settle()
    steps: list[StepOutcome] = []
    targets: dict[int, tuple[np.ndarray, int]] = {}
    reasons: list[str] = []
    for n, a in enumerate(pl.actions, start=1):
        k = sc.index[a.object]
        to = np.asarray(a.to, dtype=float)
        if offsets is not None:
            to = _compose(to, offsets[a.object])
        on = None if a.on is None else sc.index[a.on]
        out = ex.pick_and_place(k, to, on, index=n)
        steps.append(out)
        reasons.extend(_arm_failure(sim, n, out))
        if out.reached is None:
            reasons.append(f"action {n}: {out.message}")
            if opts.stop_on_failure:
                break
            continue
        targets[k] = (to, TABLE if on is None else on)
    poses, sup = ex.state()
    moving = physics.speeds(sim, ex.data)
    if moving.max(initial=0.0) > 10 * opts.settle_speed:
        k = int(moving.argmax())
        reasons.append(f"object {sc.ids[k]} is still moving ({moving[k]:.3f} m/s) after settling")
    tilt = np.degrees(physics.tilts(sim, ex.data))
    bottom = ex.data.xpos[sim.body][:, 2] - sim.heights / 2
    xmin, xmax, ymin, ymax = sc.bounds
    tol = opts.workspace_tol
    for k, i in enumerate(sc.ids):
        x, y = poses[k, :2]
        if sup[k] == physics.FLOOR or bottom[k] < -0.02:
            reasons.append(f"object {i} fell off the table")
        elif not (xmin - tol <= x <= xmax + tol and ymin - tol <= y <= ymax + tol):
            reasons.append(f"object {i} left the workspace (centre at {x:.3f}, {y:.3f})")
        if tilt[k] > opts.max_tilt_deg:
            reasons.append(f"object {i} toppled (tilted {tilt[k]:.0f} deg)")
    for k, (to, want) in targets.items():
        i = sc.ids[k]
        err = math.hypot(poses[k, 0] - to[0], poses[k, 1] - to[1])
        if err > opts.place_tol:
            reasons.append(f"object {i} rests {err * 1000:.1f} mm from where the plan put it")
        if sup[k] != want and sup[k] != physics.FLOOR:
            reasons.append(f"object {i} rests on {ex._name(sup[k])}, the plan put it on {ex._name(want)}")
    # The acceptance rules see the floor as the table: falling off is reported above.
    final_on = _acyclic(tuple(TABLE if s == physics.FLOOR else s for s in sup))
    results = []
    for g_i, g in enumerate(gs.goals):
        why = goal_satisfied(g, sc, poses, final_on)
        results.append(why is None)
        if why is not None:
            reasons.append(f"goal {g_i} ({g.pattern} {g.objects}): {why}")
    final = sc.to_spec(State.make(sc, poses, final_on))
    return Execution(
        success=not reasons,
        reasons=tuple(reasons),
        steps=tuple(steps),
        final=final,
        goals=tuple(results),
        sim_time=float(ex.data.time),
    )


def _acyclic(on: tuple[int, ...]) -> tuple[int, ...]:
    """Break any support cycle (impossible in a settled scene, but the scene
    format forbids it) by putting the object on the table."""
    out = list(on)
    for k in range(len(out)):
        seen, cur = {k}, out[k]
        while cur != TABLE:
            if cur in seen:
                out[k] = TABLE
                break
            seen.add(cur)
            cur = out[cur]
    return tuple(out)
