"""Pick and place with the UR5e arm: motion, suction and the failures it names.

:class:`ArmExecutor` runs the same plan steps as the floating-cup
:class:`~lgmcts.sim.executor.Executor`, but every motion is the arm's: joint
targets are streamed to the position actuators, one per physics step, and
physics moves the links. For each action:

1. **Reach** (before any motion): inverse kinematics for the cup face on the
   object's top, on the placed object's top at the target, and above both at
   the transfer height. A pose that has no solution fails the step as
   ``out of reach`` (or ``joint limit`` when only the limits stand in the way).
2. **Approach**: a joint-space move to above the object, then straight down
   along the tool axis until the cup's face touches the object's top.
3. **Suction**: the cup's weld to that object is switched on at the relative
   pose it has when the face touches (nothing is held before the contact).
   The weld carries at most ``hold_force``; when a collision pulls harder the
   hold breaks and the object drops.
4. **Retreat** straight up to the transfer height (the carried object's
   bottom ``clearance`` above the highest other object, or lower where the
   arm does not reach that high), a joint-space move to above the target with
   the wrist turned by the object's yaw change (the cup is symmetric, so the
   smallest turn is used), and down along the tool axis until the object
   lands.
5. **Release** and retreat along the tool axis until the cup clears every
   object; the scene settles.

Every physics step is watched: a link of the arm (the cup included) touching
an object other than the one carried, or the table, is recorded with whether
the object moved; a joint at its limit; the carried object dropped.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass

import mujoco
import numpy as np

from ..scene import TABLE
from . import physics
from .arm import ArmIK, ArmParts, IKResult, branch_of, tool_yaw
from .executor import ExecOptions, Executor, StepOutcome
from .model import SimModel

__all__ = ["ArmExecutor", "ArmOptions"]

_IK: dict[str, ArmIK] = {}


def _ik(parts: ArmParts) -> ArmIK:
    if parts.spec.name not in _IK:
        _IK[parts.spec.name] = ArmIK(parts.spec)
    return _IK[parts.spec.name]


@dataclass(frozen=True)
class ArmOptions:
    """Options of the arm's motion and suction.

    Attributes
    ----------
    cart_speed : largest speed of the cup along straight moves (m/s).
    touch_speed : speed of the last centimetres before a touch (m/s).
    touch_band : length of the slow part before a touch (m).
    approach : height above an object's top where the straight approach
        starts and the retreat ends (m).
    clearance : gap between the carried object's bottom and the highest
        other object during the transfer (m).
    hold_force : largest force the suction cup holds (N): about a 30 mm cup
        at 70 kPa of vacuum.
    settle_tol : a move ends when every joint is this close to its target
        (rad), or after ``settle_time``.
    settle_time : longest wait for the joints after a move (s).
    waypoint : spacing of inverse-kinematics waypoints along straight moves (m).
    home : ``(r, z)`` of the cup face at the start: distance from the base
        axis and height (m), straight ahead.
    moved_tol : an object touched by the arm counts as moved when it ends
        this far from where it was (m).
    """

    cart_speed: float = 0.4
    touch_speed: float = 0.06
    touch_band: float = 0.015
    approach: float = 0.05
    clearance: float = 0.03
    hold_force: float = 50.0
    settle_tol: float = 2e-3
    settle_time: float = 0.4
    waypoint: float = 0.02
    home: tuple[float, float] = (0.35, 0.35)
    moved_tol: float = 0.002


@dataclass(frozen=True)
class _Motion:
    """The solved configurations of one pick and place."""

    down_pick: list[np.ndarray]
    down_place: list[np.ndarray]
    z_tr: float
    yaw_pick: float
    yaw_place: float


class _Events:
    """What the watch saw during one action."""

    def __init__(self) -> None:
        self.touched: dict[int, str] = {}
        self.table: str = ""
        self.limit: str = ""
        self.dropped: str = ""


class ArmExecutor(Executor):
    """A live simulation of a scene with the arm (:func:`build_model` with
    ``robot``) that executes actions one at a time.

    Parameters
    ----------
    sim : the compiled scene model; it must hold an arm.
    options : primitive and verdict options (the verdict's rules are the
        floating cup's).
    arm : motion and suction options.
    on_step : called with ``data`` after every physics step (video capture).
    """

    def __init__(
        self,
        sim: SimModel,
        *,
        options: ExecOptions | None = None,
        arm: ArmOptions | None = None,
        on_step: Callable[[mujoco.MjData], None] | None = None,
    ):
        if sim.arm is None:
            raise ValueError("the model holds no arm: build it with robot='ur5e'")
        super().__init__(sim, options=options, on_step=on_step)
        self.parts: ArmParts = sim.arm
        self.aopts = arm or ArmOptions()
        self.ik = _ik(self.parts)
        p = self.parts
        self._lower = np.array(p.spec.lower)
        self._upper = np.array(p.spec.upper)
        self._vmax = np.array(p.spec.vmax)
        self._amax = np.array(p.spec.amax)
        self._kv_kp = np.array(p.spec.kv) / np.array(p.spec.kp)
        r, z = self.aopts.home
        home = self.ik.solve(np.array([0.0, r, z]), 0.0)
        self.data.qpos[p.qpos_adr] = home.q
        self.data.ctrl[p.actuators] = home.q
        mujoco.mj_forward(self.model, self.data)
        self._carried = -1
        self._target = -1
        self._events = _Events()
        arm_geom = np.array([bool(n) for n in p.geoms])
        self._arm_geom = arm_geom
        self._link = p.geoms

    # ------------------------------------------------------------ helpers

    @property
    def q(self) -> np.ndarray:
        """Current joint angles (rad)."""
        return self.data.qpos[self.parts.qpos_adr].copy()

    def _to_base(self, p: np.ndarray) -> np.ndarray:
        return np.asarray(p, dtype=float) - self.parts.base

    def _solve(self, p_world: np.ndarray, yaw: float | None, seed: np.ndarray, branch: int | None = None) -> IKResult:
        if branch is not None and branch_of(seed) != branch:
            seed = None  # type: ignore[assignment]
        return self.ik.solve(self._to_base(p_world), yaw, seed, branch=branch)

    def _watch(self) -> bool:
        """Record arm contacts, joint limits and a broken hold after a physics
        step; return whether the carried object was just dropped."""
        d, sim, ev = self.data, self.sim, self._events
        dropped = False
        if d.ncon:
            g1 = d.contact.geom1
            g2 = d.contact.geom2
            a1 = self._arm_geom[g1]
            a2 = self._arm_geom[g2]
            sel = np.flatnonzero((a1 ^ a2) & (d.contact.dist <= 1e-3))
            for i in sel.tolist():
                arm_g, other = (int(g1[i]), int(g2[i])) if a1[i] else (int(g2[i]), int(g1[i]))
                who = int(sim.geom_who[other])
                if who >= 0:
                    if who == self._carried or (who == self._target and arm_g == self.parts.cup_geom):
                        continue
                    ev.touched.setdefault(who, self._link[arm_g])
                elif who == TABLE and not ev.table:
                    ev.table = self._link[arm_g]
        q = d.qpos[self.parts.qpos_adr]
        at = (q <= self._lower + 1e-3) | (q >= self._upper - 1e-3)
        if at.any() and not ev.limit:
            j = int(np.flatnonzero(at)[0])
            ev.limit = f"{self.parts.spec.joints[j]} at {q[j]:.2f} rad"
        if self._carried >= 0:
            w = int(self.parts.welds[self._carried])
            rows = np.flatnonzero(
                (d.efc_type[: d.nefc] == mujoco.mjtConstraint.mjCNSTR_EQUALITY) & (d.efc_id[: d.nefc] == w)
            )
            if len(rows) >= 3:
                f = float(np.linalg.norm(d.efc_force[rows[:3]]))
                if f > self.aopts.hold_force:
                    d.eq_active[w] = 0
                    ev.dropped = f"the suction cup let go of object {sim.scene.ids[self._carried]} ({f:.0f} N pulled)"
                    self._carried = -1
                    dropped = True
        return dropped

    def _drive(self, path: np.ndarray, vel: np.ndarray, stop: Callable[[], bool] | None = None) -> bool:
        """Stream joint targets (with velocity feed-forward through the
        actuators' damping) one per step; return ``True`` if ``stop`` fired."""
        d, acts = self.data, self.parts.actuators
        for q, v in zip(path, vel):
            d.ctrl[acts] = np.clip(q + self._kv_kp * v, self._lower, self._upper)
            self.step()
            self._watch()
            if stop is not None and stop():
                d.ctrl[acts] = d.qpos[self.parts.qpos_adr]
                return True
        if len(path):
            return self._hold(path[-1], stop)
        return False

    def _hold(self, q: np.ndarray, stop: Callable[[], bool] | None = None) -> bool:
        """Keep ``q`` as the target until the joints reach it (or
        ``settle_time``); return ``True`` if ``stop`` fired on the way."""
        d, acts = self.data, self.parts.actuators
        d.ctrl[acts] = q
        for _ in range(max(1, round(self.aopts.settle_time / self._dt))):
            if float(np.abs(d.qpos[self.parts.qpos_adr] - q).max()) < self.aopts.settle_tol:
                break
            self.step()
            self._watch()
            if stop is not None and stop():
                d.ctrl[acts] = d.qpos[self.parts.qpos_adr]
                return True
        return stop is not None and stop()

    def _profile(
        self, qs: list[np.ndarray], cart_len: float = 0.0, speed: float | None = None
    ) -> tuple[np.ndarray, np.ndarray]:
        """Positions and velocities, one per step, along the joint-space
        polyline ``qs`` under the joints' speed and acceleration limits (a
        trapezoidal profile of the path parameter); ``cart_len``/``speed`` also
        cap the cup's speed on a straight move."""
        qs_a = np.array(qs, dtype=float)
        seg = np.diff(qs_a, axis=0)
        # Path parameter: time at full speed of the slowest joint per segment.
        seg_t = (np.abs(seg) / self._vmax).max(axis=1) if len(seg) else np.zeros(0)
        total = float(seg_t.sum())
        if total < 1e-9:
            return np.zeros((0, 6)), np.zeros((0, 6))
        vs = 1.0
        if speed is not None and cart_len > 0:
            vs = min(1.0, speed * total / cart_len)
        a_s = float((self._amax / self._vmax).min())
        t_acc = vs / a_s
        if vs * t_acc >= total:  # triangle
            t_acc = math.sqrt(total / a_s)
            vs = a_s * t_acc
        t_cruise = (total - vs * t_acc) / vs
        t_end = 2 * t_acc + t_cruise
        n = max(2, math.ceil(t_end / self._dt))
        t = np.linspace(self._dt, t_end, n)
        s = np.where(
            t < t_acc,
            0.5 * a_s * t**2,
            np.where(
                t < t_acc + t_cruise,
                0.5 * a_s * t_acc**2 + vs * (t - t_acc),
                total - 0.5 * a_s * np.maximum(t_end - t, 0.0) ** 2,
            ),
        )
        sdot = np.where(t < t_acc, a_s * t, np.where(t < t_acc + t_cruise, vs, a_s * np.maximum(t_end - t, 0.0)))
        knots = np.concatenate([[0.0], np.cumsum(seg_t)])
        idx = np.clip(np.searchsorted(knots, s, side="right") - 1, 0, len(seg) - 1)
        frac = np.where(seg_t[idx] > 0, (s - knots[idx]) / np.maximum(seg_t[idx], 1e-12), 0.0)
        pos = qs_a[idx] + frac[:, None] * seg[idx]
        dqds = seg[idx] / np.maximum(seg_t[idx], 1e-12)[:, None]
        return pos, dqds * sdot[:, None]

    def _line(
        self, p0: np.ndarray, p1: np.ndarray, yaw: float, seed: np.ndarray, branch: int | None = None
    ) -> list[np.ndarray] | None:
        """Joint waypoints along the straight segment ``p0``-``p1`` of the cup
        face (world, m) at tool yaw ``yaw``, or ``None`` if one is unreachable."""
        n = max(1, math.ceil(float(np.linalg.norm(p1 - p0)) / self.aopts.waypoint))
        out = []
        q = seed
        for i in range(n + 1):
            res = self._solve(p0 + (p1 - p0) * i / n, yaw, q, branch)
            if not res.ok:
                return None
            q = res.q
            out.append(q)
        return out

    def _straight(
        self, qs: list[np.ndarray], length: float, speed: float, stop: Callable[[], bool] | None = None
    ) -> bool:
        pos, vel = self._profile([self.q, *qs], length, speed)
        return self._drive(pos, vel, stop)

    def _joint_move(self, q1: np.ndarray) -> None:
        pos, vel = self._profile([self.q, q1])
        self._drive(pos, vel)

    def _cup_touch(self, k: int) -> bool:
        d = self.data
        if not d.ncon:
            return False
        g1, g2 = d.contact.geom1, d.contact.geom2
        cup, g = self.parts.cup_geom, self.sim.geom[k]
        return bool((((g1 == cup) & (g2 == g)) | ((g2 == cup) & (g1 == g))).any())

    def _wrist_turn(self, q_ref: np.ndarray, q_place: np.ndarray) -> np.ndarray:
        """``q_place`` with wrist 3 at the angle, among those a full turn
        apart and within its limits, nearest to its angle in ``q_ref``."""
        q = q_place.copy()
        best = q[5]
        for k in (-2, -1, 0, 1, 2):
            c = q_place[5] + 2 * math.pi * k
            if self._lower[5] <= c <= self._upper[5] and abs(c - q_ref[5]) < abs(best - q_ref[5]):
                best = c
        q[5] = best
        return q

    # ------------------------------------------------------------ primitive

    def pick_and_place(self, k: int, to: np.ndarray, on: int | None, *, index: int = 0) -> StepOutcome:
        sim, d, o, a = self.sim, self.data, self.opts, self.aopts
        oid = sim.scene.ids[k]
        sup = physics.supports(sim, d)
        blockers = [sim.scene.ids[j] for j, s in enumerate(sup) if s == k]
        if blockers:
            return StepOutcome(
                index, oid, False, None, math.nan, f"pick failed: object {oid} is covered by object {blockers[0]}"
            )
        self._events = _Events()
        self._target = k
        start_poses = physics.poses(sim, d)
        body = sim.body[k]
        h = float(sim.heights[k])
        here = d.xpos[body].copy()
        # The top of the object as it stands (a slight tilt raises one edge).
        tilt = float(physics.tilts(sim, d)[k])
        top_c = float(here[2]) + h / 2 * math.cos(tilt)
        top = top_c + float(sim.scene.radii[k]) * math.sin(tilt)
        z_place = h if on is None else float(d.xpos[sim.body[on], 2]) + float(sim.heights[on]) / 2 + h
        others = np.delete(physics.tops(sim, d), k)
        z_tr_want = max(float(others.max(initial=0.0)) + a.clearance + h, top + a.approach, z_place + a.approach)
        # 1. Reach, before any motion: the wrist branch of the current
        # configuration first, then the other, then one branch for the pick and
        # the other for the place (the wrist flips at the transfer height).
        obj_yaw = float(physics.poses(sim, d)[k, 2])
        turn = math.remainder(float(to[2]) - obj_yaw, 2 * math.pi)
        cur = branch_of(self.q)
        fail: tuple[IKResult, str] | None = None
        mo: _Motion | None = None
        for bp, bl in ((cur, cur), (1 - cur, 1 - cur), (cur, 1 - cur), (1 - cur, cur)):
            got = self._motion(oid, here, top, top_c, to, z_place, z_tr_want, turn, bp, bl)
            if isinstance(got, _Motion):
                mo = got
                break
            if fail is None or (fail[0].reason != "joint limit" and got[0].reason == "joint limit"):
                fail = got
        if mo is None:
            assert fail is not None
            return self._refuse(index, oid, fail[0], fail[1])
        down_pick, down_place, z_tr, yaw_pick, yaw_place = (
            mo.down_pick,
            mo.down_place,
            mo.z_tr,
            mo.yaw_pick,
            mo.yaw_place,
        )
        # 2. Approach and touch.
        self._joint_move(down_pick[0])
        fast = max(0, len(down_pick) - 1 - math.ceil((a.touch_band + 0.01 + top - top_c) / a.waypoint))
        self._straight(down_pick[1 : fast + 1], z_tr - top, a.cart_speed, stop=lambda: self._cup_touch(k))
        touched = self._cup_touch(k) or self._straight(
            down_pick[fast + 1 :], a.touch_band + 0.01, a.touch_speed, stop=lambda: self._cup_touch(k)
        )
        if not touched:
            self._retreat(here[0], here[1], z_tr, yaw_pick)
            return self._outcome(index, oid, k, to, on, start_poses, None, "the cup never touched the object's top")
        # 3. Suction on, at the pose it touched in.
        self._attach(k)
        # 4. Up, across, down.
        up = self._line(self._cup_pos(), np.array([here[0], here[1], z_tr]), yaw_pick, self.q)
        if up is not None:
            self._straight(up[1:], z_tr - top, a.cart_speed)
        self._joint_move(down_place[0])
        fast = max(0, len(down_place) - 1 - math.ceil((a.touch_band + o.approach_height + o.overshoot) / a.waypoint))
        self._straight(down_place[1 : fast + 1], z_tr - z_place, a.cart_speed)
        landed = False
        if self._carried == k:
            landed = self._straight(
                down_place[fast + 1 :],
                o.approach_height + o.overshoot,
                a.touch_speed,
                stop=lambda: physics.bottom_contact(sim, d, k) or self._carried != k,
            )
            landed = landed and self._carried == k
        # 5. Release and retreat.
        dropped = self._carried != k
        self._release()
        # Up along the tool axis until the cup clears every object, so that the
        # next joint-space move starts above the scene.
        clear = float(physics.tops(sim, d).max(initial=0.0)) + a.clearance
        self._retreat(float(to[0]), float(to[1]), max(z_place + a.approach, clear), yaw_place, low=z_place + a.approach)
        self.settle()
        return self._outcome(index, oid, k, to, on, start_poses, landed, "dropped" if dropped else "")

    def _motion(
        self,
        oid: int,
        here: np.ndarray,
        top: float,
        top_c: float,
        to: np.ndarray,
        z_place: float,
        z_tr_want: float,
        turn: float,
        bp: int,
        bl: int,
    ) -> _Motion | tuple[IKResult, str]:
        """Every configuration of one pick and place with the pick in wrist
        branch ``bp`` and the place in ``bl``, or the first pose that has
        none and what it is."""
        a, o = self.aopts, self.opts
        pick = self._solve(np.array([here[0], here[1], top]), None, self.q, bp)
        if not pick.ok:
            return pick, f"object {oid} at ({here[0]:.3f}, {here[1]:.3f})"
        _, rot = self.ik.fk(pick.q)
        yaw_pick = tool_yaw(rot)
        place = self._solve(np.array([to[0], to[1], z_place]), yaw_pick + turn, pick.q, bl)
        if not place.ok:
            return place, f"the place ({to[0]:.3f}, {to[1]:.3f}) of object {oid}"
        place_q = self._wrist_turn(pick.q, place.q)
        # The cup is symmetric: any wrist-3 angle grasps. Centre the pick's and
        # the place's angles on zero, so the wrist never drifts to its limit
        # over many actions; the turn between them stays the smallest one.
        mid = (float(pick.q[5]) + float(place_q[5])) / 2
        pick_q = pick.q.copy()
        pick_q[5] -= mid
        place_q[5] -= mid
        yaw_pick = tool_yaw(self.ik.fk(pick_q)[1])
        yaw_place = tool_yaw(self.ik.fk(place_q)[1])
        z_tr = z_tr_want
        above_pick = above_place = None
        while z_tr >= max(top, z_place) + a.approach - 1e-9:
            above_pick = self._solve(np.array([here[0], here[1], z_tr]), yaw_pick, pick_q, bp)
            above_place = self._solve(np.array([to[0], to[1], z_tr]), yaw_place, place_q, bl)
            if above_pick.ok and above_place.ok:
                break
            z_tr -= 0.02
        if above_pick is None or above_place is None or not (above_pick.ok and above_place.ok):
            res = above_pick if above_pick is not None and not above_pick.ok else above_place
            return (res or pick), f"the way above object {oid}"
        down_pick = self._line(
            np.array([here[0], here[1], z_tr]),
            np.array([here[0], here[1], top_c - 0.01]),
            yaw_pick,
            self._wrist_turn(pick_q, above_pick.q),
            bp,
        )
        down_place = self._line(
            np.array([to[0], to[1], z_tr]),
            np.array([to[0], to[1], z_place - o.overshoot]),
            yaw_place,
            self._wrist_turn(place_q, above_place.q),
            bl,
        )
        if down_pick is None or down_place is None:
            return IKResult(False, pick.q, math.inf, math.inf, "out of reach"), f"the approach to object {oid}"
        down_pick = [self._wrist_turn(pick_q, q) for q in down_pick]
        down_place = [self._wrist_turn(place_q, q) for q in down_place]
        return _Motion(down_pick, down_place, z_tr, yaw_pick, yaw_place)

    def _cup_pos(self) -> np.ndarray:
        return self.data.site_xpos[self.parts.cup_site].copy()

    def _attach(self, k: int) -> None:
        d, m = self.data, self.model
        w = int(self.parts.welds[k])
        b1, b2 = self.parts.cup_body, int(self.sim.body[k])
        r1 = d.xmat[b1].reshape(3, 3)
        relpos = r1.T @ (d.xpos[b2] - d.xpos[b1])
        q1 = d.xquat[b1].copy()
        q1inv = np.array([q1[0], -q1[1], -q1[2], -q1[3]])
        relq = np.zeros(4)
        mujoco.mju_mulQuat(relq, q1inv, d.xquat[b2])
        m.eq_data[w, 0:3] = 0.0
        m.eq_data[w, 3:6] = relpos
        m.eq_data[w, 6:10] = relq
        d.eq_active[w] = 1
        self._carried = k

    def _release(self) -> None:
        if self._carried >= 0:
            self.data.eq_active[int(self.parts.welds[self._carried])] = 0
        self._carried = -1

    def _retreat(self, x: float, y: float, z: float, yaw: float, low: float | None = None) -> None:
        """Straight up to height ``z`` (m) above ``x, y``, or as high as the arm
        reaches down to ``low``."""
        p0 = self._cup_pos()
        z = max(z, float(p0[2]) + 0.02)
        floor = z if low is None else max(low, float(p0[2]) + 0.02)
        while z >= floor - 1e-9:
            up = self._line(p0, np.array([x, y, z]), yaw, self.q)
            if up is not None:
                self._straight(up[1:], z - float(p0[2]), self.aopts.cart_speed)
                return
            z -= 0.02

    def _refuse(self, index: int, oid: int, res: IKResult, what: str) -> StepOutcome:
        if res.reason == "joint limit":
            msg = f"joint limit: reaching {what} needs a joint beyond its limit (nothing moved)"
        else:
            msg = f"out of reach: {what} is beyond the arm's reach (nothing moved)"
        return StepOutcome(index, oid, False, None, math.nan, msg)

    def _outcome(
        self,
        index: int,
        oid: int,
        k: int,
        to: np.ndarray,
        on: int | None,
        start: np.ndarray,
        landed: bool | None,
        note: str,
    ) -> StepOutcome:
        sim, d, o, ev = self.sim, self.data, self.opts, self._events
        pose = physics.poses(sim, d)[k]
        tilt = math.degrees(float(physics.tilts(sim, d)[k]))
        sup = physics.supports(sim, d)[k]
        want = TABLE if on is None else on
        err = float(math.hypot(pose[0] - to[0], pose[1] - to[1]))
        problems = []
        if ev.dropped:
            problems.append(f"dropped in transfer: {ev.dropped}")
        if landed is None:
            problems.append(f"pick failed: {note}")
        elif not landed and not ev.dropped:
            problems.append("released without touching a support")
        now = physics.poses(sim, d)
        for j, link in sorted(ev.touched.items()):
            moved = float(math.hypot(*(now[j, :2] - start[j, :2])))
            what = f"moved it {moved * 1000:.0f} mm" if moved > self.aopts.moved_tol else "did not move it"
            problems.append(f"arm collision: the {link} touched object {sim.scene.ids[j]} ({what})")
        if ev.table:
            problems.append(f"arm collision: the {ev.table} touched the table")
        if ev.limit:
            problems.append(f"joint limit: {ev.limit}")
        if landed is not None:
            if tilt > o.max_tilt_deg:
                problems.append(f"toppled ({tilt:.0f} deg)")
            if sup != want:
                problems.append(f"ended on {self._name(sup)}, planned on {self._name(want)}")
            if err > o.place_tol:
                problems.append(f"{err * 1000:.1f} mm from the planned pose")
        msg = "placed" if not problems else "; ".join(problems)
        reached = (float(pose[0]), float(pose[1]), float(pose[2]))
        return StepOutcome(
            index,
            oid,
            not problems,
            reached if landed is not None else None,
            err if landed is not None else math.nan,
            f"{msg} ({err * 1000:.1f} mm off)" if landed is not None else msg,
        )
