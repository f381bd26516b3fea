"""A UR5e arm with a suction cup: its MuJoCo model and its inverse kinematics.

The arm is built in code with :class:`mujoco.MjSpec` from the UR5e's
published kinematics (link offsets, joint axes, masses and inertias as in
robosuite 1.5.2's model) and robosuite's collision meshes, shipped under
``assets/ur5e/`` with their MIT licence. A suction cup (a short cylinder, its
face a site) sits at the tool flange. Every joint is driven by a position
actuator; the links are gravity-compensated, as a UR controller does.

Inverse kinematics is damped least squares on MuJoCo's Jacobians, on an
arm-only model (no table, no objects): :class:`ArmIK`. A top-down pose is the
cup face's position and the yaw of the tool about the vertical; with
``yaw=None`` the yaw is free (the cup is symmetric) and the solution nearest
the seed is returned.

Run ``python -m lgmcts.sim.arm --write-reach`` to recompute the reachability
map that the planner reads (``lgmcts/robot_ur5e.json``).
"""

from __future__ import annotations

import argparse
import json
import math
import time
from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np

__all__ = [
    "UR5E",
    "ArmIK",
    "ArmParts",
    "ArmSpec",
    "IKResult",
    "add_arm",
    "add_cup_welds",
    "arm_only_model",
    "arm_parts",
    "base_pose",
    "robot_spec",
]

ASSETS = Path(__file__).parent / "assets" / "ur5e"


@dataclass(frozen=True)
class ArmSpec:
    """Limits and servo gains of the arm.

    Attributes
    ----------
    name : the robot's name (``"ur5e"``).
    joints : joint names, base to wrist.
    lower, upper : joint position limits (rad). The UR5e's elbow turns
        +-180 deg, but beyond about +-160 deg the forearm folds onto the upper
        arm; the limit here is that.
    vmax : joint speed limits used for trajectories (rad/s).
    amax : joint acceleration limits used for trajectories (rad/s^2).
    kp : position gain of each joint's actuator (N m / rad).
    kv : velocity damping of each actuator (N m s / rad).
    armature : reflected rotor inertia of each joint (kg m^2).
    force : torque limit of each actuator (N m).
    cup_radius : radius of the suction cup (m).
    cup_length : distance from the tool flange to the cup face (m): a long
        tool keeps the wrist above taller neighbours of a picked object.
    base_clear : how far in front of the table's front edge the base centre
        stands (m); the base (7.5 cm in radius) then touches the edge.
    """

    name: str = "ur5e"
    joints: tuple[str, ...] = ("shoulder_pan", "shoulder_lift", "elbow", "wrist_1", "wrist_2", "wrist_3")
    lower: tuple[float, ...] = (-2 * math.pi, -2 * math.pi, -2.8, -2 * math.pi, -2 * math.pi, -2 * math.pi)
    upper: tuple[float, ...] = (2 * math.pi, 2 * math.pi, 2.8, 2 * math.pi, 2 * math.pi, 2 * math.pi)
    vmax: tuple[float, ...] = (2.0, 2.0, 2.5, 3.0, 3.0, 3.0)
    amax: tuple[float, ...] = (8.0, 8.0, 10.0, 12.0, 12.0, 12.0)
    kp: tuple[float, ...] = (4000.0, 4000.0, 3000.0, 800.0, 800.0, 500.0)
    kv: tuple[float, ...] = (200.0, 200.0, 150.0, 30.0, 30.0, 15.0)
    armature: tuple[float, ...] = (0.5, 0.5, 0.3, 0.05, 0.05, 0.05)
    force: tuple[float, ...] = (150.0, 150.0, 150.0, 28.0, 28.0, 28.0)
    cup_radius: float = 0.015
    cup_length: float = 0.12
    base_clear: float = 0.08


UR5E = ArmSpec()

#: Name prefix of every body, geom, joint and actuator of the arm.
PREFIX = "ur5e/"
#: Name of the site at the suction cup's face (the tool point).
CUP_SITE = PREFIX + "cup_face"
#: Name of the cup body (what the suction welds objects to).
CUP_BODY = PREFIX + "cup"
#: Name of the cup's contact geom.
CUP_GEOM = PREFIX + "cup_geom"

# (body, parent offset, parent-frame quaternion, joint axis, mass, inertia
# centre, diagonal inertia, mesh): the UR5e chain as robosuite models it.
_SQ = math.sqrt(0.5)
_LINKS = (
    (
        "shoulder_link",
        (0.0, 0.0, 0.163),
        (1.0, 0.0, 0.0, 0.0),
        (0, 0, 1),
        3.7,
        (0, 0, 0),
        (0.0102675, 0.0102675, 0.00666),
        "shoulder",
    ),
    (
        "upper_arm_link",
        (0.0, 0.138, 0.0),
        (_SQ, 0.0, _SQ, 0.0),
        (0, 1, 0),
        8.393,
        (0, 0, 0.2125),
        (0.133886, 0.133886, 0.0151074),
        "upperarm",
    ),
    (
        "forearm_link",
        (0.0, -0.131, 0.425),
        (1.0, 0.0, 0.0, 0.0),
        (0, 1, 0),
        2.275,
        (0, 0, 0.196),
        (0.0311796, 0.0311796, 0.004095),
        "forearm",
    ),
    (
        "wrist_1_link",
        (0.0, 0.0, 0.392),
        (_SQ, 0.0, _SQ, 0.0),
        (0, 1, 0),
        1.219,
        (0, 0.127, 0),
        (0.0025599, 0.0025599, 0.0021942),
        "wrist1",
    ),
    (
        "wrist_2_link",
        (0.0, 0.127, 0.0),
        (1.0, 0.0, 0.0, 0.0),
        (0, 0, 1),
        1.219,
        (0, 0, 0.1),
        (0.0025599, 0.0025599, 0.0021942),
        "wrist2",
    ),
    (
        "wrist_3_link",
        (0.0, 0.0, 0.1),
        (1.0, 0.0, 0.0, 0.0),
        (0, 1, 0),
        0.1889,
        (0, 0.0771683, 0),
        (0.000132134, 9.90863e-05, 9.90863e-05),
        "wrist3",
    ),
)
#: Arm geoms collide with objects and the table (contype 2 meets their
#: conaffinity 1 only one way) but not with each other.
_ARM_CONTYPE = 2
_ARM_CONAFFINITY = 1


def base_pose(bounds: tuple[float, float, float, float], table_margin: float, arm: ArmSpec = UR5E) -> np.ndarray:
    """World position of the arm's base for a workspace ``(xmin, xmax, ymin,
    ymax)``: the centre of the table's front edge (the viewer's side, -y), on
    the table's top plane (m)."""
    xmin, xmax, ymin, _ = bounds
    return np.array([(xmin + xmax) / 2, ymin - table_margin - arm.base_clear, 0.0])


def add_arm(spec: mujoco.MjSpec, base: np.ndarray, arm: ArmSpec = UR5E, *, actuators: bool = True) -> None:
    """Add the arm with its suction cup to ``spec``, its base at ``base``
    (world, m), the shoulder's zero pointing along +y (into the table)."""
    # Joint ranges below are in radians.
    spec.compiler.degree = False
    for mesh in ("base", *(m for *_, m in _LINKS)):
        spec.add_mesh(name=PREFIX + mesh, file=str(ASSETS / f"{mesh}.stl"))
    grey = [0.75, 0.77, 0.8, 1.0]
    blue = [0.49, 0.68, 0.8, 1.0]
    # Yaw +90 deg: the arm's +x (where the upper arm points at zero) becomes +y.
    body = spec.worldbody.add_body(name=PREFIX + "base", pos=[float(v) for v in base], quat=[_SQ, 0.0, 0.0, _SQ])
    body.add_geom(
        name=PREFIX + "base_geom",
        type=mujoco.mjtGeom.mjGEOM_MESH,
        meshname=PREFIX + "base",
        rgba=[0.2, 0.2, 0.2, 1.0],
        contype=_ARM_CONTYPE,
        conaffinity=_ARM_CONAFFINITY,
    )
    parent = body
    for j, (name, pos, quat, axis, mass, ipos, inertia, mesh) in enumerate(_LINKS):
        link = parent.add_body(name=PREFIX + name, pos=list(pos), quat=list(quat), gravcomp=1.0)
        link.mass = mass
        link.ipos = list(ipos)
        link.inertia = list(inertia)
        link.explicitinertial = True
        link.add_joint(
            name=PREFIX + arm.joints[j],
            axis=list(axis),
            range=[arm.lower[j], arm.upper[j]],
            limited=mujoco.mjtLimited.mjLIMITED_TRUE,
            armature=arm.armature[j],
            damping=0.0,
        )
        link.add_geom(
            name=PREFIX + name + "_geom",
            type=mujoco.mjtGeom.mjGEOM_MESH,
            meshname=PREFIX + mesh,
            rgba=blue if j in (0, 3) else grey,
            contype=_ARM_CONTYPE,
            conaffinity=_ARM_CONAFFINITY,
            density=0.0,
        )
        parent = link
    # The tool flange: 9.8 cm out along wrist 3's +y; the cup's axis is the flange's +z.
    cup = parent.add_body(name=CUP_BODY, pos=[0.0, 0.098, 0.0], quat=[_SQ, -_SQ, 0.0, 0.0], gravcomp=1.0)
    cup.mass = 0.05
    cup.inertia = [1e-5, 1e-5, 1e-5]
    cup.explicitinertial = True
    stem = arm.cup_length - 0.01
    cup.add_geom(
        name=PREFIX + "cup_stem",
        type=mujoco.mjtGeom.mjGEOM_CYLINDER,
        size=[0.012, stem / 2, 0.0],
        pos=[0.0, 0.0, stem / 2],
        rgba=[0.3, 0.3, 0.3, 1.0],
        contype=_ARM_CONTYPE,
        conaffinity=_ARM_CONAFFINITY,
        density=0.0,
    )
    cup.add_geom(
        name=CUP_GEOM,
        type=mujoco.mjtGeom.mjGEOM_CYLINDER,
        size=[arm.cup_radius, 0.005, 0.0],
        pos=[0.0, 0.0, arm.cup_length - 0.005],
        rgba=[0.1, 0.1, 0.1, 1.0],
        contype=_ARM_CONTYPE,
        conaffinity=_ARM_CONAFFINITY,
        density=0.0,
    )
    cup.add_site(name=CUP_SITE, pos=[0.0, 0.0, arm.cup_length], size=[0.004, 0.0, 0.0], rgba=[1.0, 0.2, 0.2, 0.0])
    if actuators:
        for j, jn in enumerate(arm.joints):
            spec.add_actuator(
                name=PREFIX + jn + "_servo",
                target=PREFIX + jn,
                trntype=mujoco.mjtTrn.mjTRN_JOINT,
                gaintype=mujoco.mjtGain.mjGAIN_FIXED,
                biastype=mujoco.mjtBias.mjBIAS_AFFINE,
                gainprm=[arm.kp[j]] + [0.0] * 9,
                biasprm=[0.0, -arm.kp[j], -arm.kv[j]] + [0.0] * 7,
                ctrlrange=[arm.lower[j], arm.upper[j]],
                ctrllimited=mujoco.mjtLimited.mjLIMITED_TRUE,
                forcerange=[-arm.force[j], arm.force[j]],
                forcelimited=mujoco.mjtLimited.mjLIMITED_TRUE,
            )


def robot_spec(name: str) -> ArmSpec:
    """The :class:`ArmSpec` of the robot called ``name``."""
    from ..errors import InputError

    if name != UR5E.name:
        raise InputError(f"unknown robot {name!r} (known: {UR5E.name})")
    return UR5E


def add_cup_welds(spec: mujoco.MjSpec, ids: tuple[int, ...] | list[int], timeconst: float) -> None:
    """One inactive weld per object between the suction cup and the object
    (``cup<id>``); the executor sets its relative pose when it switches it on."""
    from .model import add_welds

    add_welds(spec, CUP_BODY, "cup", ids, timeconst)


@dataclass(frozen=True, eq=False)
class ArmParts:
    """Where the arm lives in a compiled scene model.

    Attributes
    ----------
    spec : the arm's limits.
    base : world position of the base (m).
    qpos_adr, dof_adr : ``(6,)`` addresses of the joints in ``qpos``/``qvel``.
    actuators : ``(6,)`` actuator ids, base to wrist.
    cup_body, cup_geom, cup_site : ids of the cup's body, face geom and site.
    welds : per object index, the id of its cup weld.
    geoms : ``(ngeom,)`` for each geom, the name of the arm link it belongs
        to, ``""`` for geoms not of the arm.
    """

    spec: ArmSpec
    base: np.ndarray
    qpos_adr: np.ndarray
    dof_adr: np.ndarray
    actuators: np.ndarray
    cup_body: int
    cup_geom: int
    cup_site: int
    welds: np.ndarray
    geoms: tuple[str, ...]


_LINK_WORDS = {
    "base": "base",
    "shoulder_link": "shoulder",
    "upper_arm_link": "upper arm",
    "forearm_link": "forearm",
    "wrist_1_link": "wrist 1",
    "wrist_2_link": "wrist 2",
    "wrist_3_link": "wrist 3",
    "cup": "suction cup",
}


def arm_parts(model: mujoco.MjModel, ids: tuple[int, ...] | list[int], arm: ArmSpec, base: np.ndarray) -> ArmParts:
    """The :class:`ArmParts` of a compiled model that holds the arm."""
    jnt = [model.joint(PREFIX + j).id for j in arm.joints]
    names = []
    for g in range(model.ngeom):
        body = model.body(int(model.geom_bodyid[g])).name
        names.append(_LINK_WORDS.get(body[len(PREFIX) :], body) if body.startswith(PREFIX) else "")
    return ArmParts(
        spec=arm,
        base=np.asarray(base, dtype=float),
        qpos_adr=np.array([model.jnt_qposadr[j] for j in jnt]),
        dof_adr=np.array([model.jnt_dofadr[j] for j in jnt]),
        actuators=np.array([model.actuator(PREFIX + j + "_servo").id for j in arm.joints]),
        cup_body=model.body(CUP_BODY).id,
        cup_geom=model.geom(CUP_GEOM).id,
        cup_site=model.site(CUP_SITE).id,
        welds=np.array([model.equality(f"cup{i}").id for i in ids]),
        geoms=tuple(names),
    )


def arm_only_model(arm: ArmSpec = UR5E) -> mujoco.MjModel:
    """The arm alone, its base at the origin (kinematics only)."""
    spec = mujoco.MjSpec()
    spec.modelname = "ur5e_kinematics"
    add_arm(spec, np.zeros(3), arm, actuators=False)
    return spec.compile()


@dataclass(frozen=True)
class IKResult:
    """The outcome of one inverse-kinematics query.

    Attributes
    ----------
    ok : a solution within tolerance and within the joint limits was found.
    q : the joint angles (rad), the best found when not ``ok``.
    pos_err : distance of the cup face from the target (m).
    rot_err : angle between the tool's orientation and the target (rad).
    reason : ``""`` when ok, else ``"out of reach"`` or ``"joint limit"``.
    """

    ok: bool
    q: np.ndarray
    pos_err: float
    rot_err: float
    reason: str = ""


_DOWN = np.array([[1.0, 0.0, 0.0], [0.0, -1.0, 0.0], [0.0, 0.0, -1.0]])


def down_rotation(yaw: float) -> np.ndarray:
    """Rotation of a tool pointing straight down, turned by ``yaw`` about +z."""
    c, s = math.cos(yaw), math.sin(yaw)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]) @ _DOWN


def tool_yaw(rot: np.ndarray) -> float:
    """Yaw about +z of a tool frame (its x axis projected on the table)."""
    return math.atan2(float(rot[1, 0]), float(rot[0, 0]))


def _rot_error(r: np.ndarray, rd: np.ndarray) -> np.ndarray:
    """Rotation vector taking ``r`` to ``rd`` (world frame)."""
    q, qd, qe = np.zeros(4), np.zeros(4), np.zeros(4)
    mujoco.mju_mat2Quat(q, r.ravel())
    mujoco.mju_mat2Quat(qd, rd.ravel())
    qi = np.array([q[0], -q[1], -q[2], -q[3]])
    mujoco.mju_mulQuat(qe, qd, qi)
    if qe[0] < 0:
        qe = -qe
    v = qe[1:]
    n = float(np.linalg.norm(v))
    if n < 1e-12:
        return np.zeros(3)
    return v / n * 2.0 * math.atan2(n, float(qe[0]))


class ArmIK:
    """Damped-least-squares inverse kinematics of the cup face, in the base
    frame (the base at the origin, the shoulder's zero along +y).

    Parameters
    ----------
    arm : the arm's limits.
    pos_tol, rot_tol : a solution is accepted within these (m, rad).
    """

    def __init__(self, arm: ArmSpec = UR5E, *, pos_tol: float = 1e-4, rot_tol: float = 1e-3):
        self.arm = arm
        self.model = arm_only_model(arm)
        self.data = mujoco.MjData(self.model)
        self.site = self.model.site(CUP_SITE).id
        self._elbow = self.model.body(PREFIX + "forearm_link").id
        self._links = np.array(
            [self.model.body(PREFIX + b).id for b in ("wrist_1_link", "wrist_2_link", "wrist_3_link")]
        )
        self.lower = np.array(arm.lower)
        self.upper = np.array(arm.upper)
        self.pos_tol = pos_tol
        self.rot_tol = rot_tol
        self._jp = np.zeros((3, self.model.nv))
        self._jr = np.zeros((3, self.model.nv))
        # Canonical top-down configurations straight ahead, elbow up, in two
        # branches: wrist 2 at -90 deg (BRANCHES[0], the wrist outward: reaches
        # from about 0.3 to 0.9 m) and at +90 deg (BRANCHES[1], the wrist
        # folded back towards the base: about 0.15 to 0.7 m). Every other seed
        # is turned from these.
        self._canon: dict[int, list[tuple[float, np.ndarray]]] = {}
        for b, q0, radii in (
            (0, np.array([0.0, -1.9, 1.9, -1.57, -1.57, 0.0]), (0.3, 0.5, 0.7, 0.85)),
            (1, np.array([-0.5, -1.09, 2.27, 0.39, 1.57, 0.0]), (0.3, 0.2, 0.45, 0.6)),
        ):
            self._canon[b] = []
            for r in radii:
                res = self._solve(np.array([0.0, r, 0.1]), 0.0, q0, limits=True)
                if res.ok and branch_of(res.q) == b:
                    q0 = res.q
                    self._canon[b].append((r, res.q.copy()))

    def fk(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Cup-face position and rotation matrix at joint angles ``q``."""
        d = self.data
        d.qpos[:] = q
        mujoco.mj_kinematics(self.model, d)
        return d.site_xpos[self.site].copy(), d.site_xmat[self.site].reshape(3, 3).copy()

    def _solve(
        self, pos: np.ndarray, yaw: float | None, seed: np.ndarray, *, limits: bool, iters: int = 100
    ) -> IKResult:
        m, d, s = self.model, self.data, self.site
        q = np.array(seed, dtype=float)
        lam = 1e-2
        ep = np.zeros(3)
        er = np.zeros(3)
        for _ in range(iters):
            d.qpos[:] = q
            mujoco.mj_kinematics(m, d)
            mujoco.mj_comPos(m, d)
            r = d.site_xmat[s].reshape(3, 3)
            ep = pos - d.site_xpos[s]
            rd = down_rotation(tool_yaw(r) if yaw is None else yaw)
            er = _rot_error(r, rd)
            if float(np.linalg.norm(ep)) < self.pos_tol * 0.1 and float(np.linalg.norm(er)) < self.rot_tol * 0.1:
                break
            mujoco.mj_jacSite(m, d, self._jp, self._jr, s)
            jac = np.vstack([self._jp, self._jr])
            e = np.concatenate([ep, er])
            dq = jac.T @ np.linalg.solve(jac @ jac.T + lam * lam * np.eye(6), e)
            step = float(np.abs(dq).max())
            if step > 0.4:
                dq *= 0.4 / step
            q = q + dq
            if limits:
                q = np.clip(q, self.lower, self.upper)
        d.qpos[:] = q
        mujoco.mj_kinematics(m, d)
        r = d.site_xmat[s].reshape(3, 3)
        pe = float(np.linalg.norm(pos - d.site_xpos[s]))
        re = float(np.linalg.norm(_rot_error(r, down_rotation(tool_yaw(r) if yaw is None else yaw))))
        # The elbow stays above the table top (the base plane) by 5 cm, the wrist by 3 cm.
        ok = (
            pe <= self.pos_tol
            and re <= self.rot_tol
            and _elbow_up(q)
            and float(d.xpos[self._elbow, 2]) > 0.05
            and float(d.xpos[self._links, 2].min()) > 0.03
        )
        return IKResult(ok, q, pe, re, "" if ok else "out of reach")

    def seeds(self, pos: np.ndarray, branch: int | None = None) -> list[np.ndarray]:
        """Seeds for a target: the canonical configurations of ``branch``
        (both when ``None``, the outward branch first except near the base)
        turned to face it, nearest in reach first."""
        bearing = math.atan2(-float(pos[0]), float(pos[1]))
        r = math.hypot(float(pos[0]), float(pos[1]))
        out = []
        # Near the base only the folded branch reaches: try it first there.
        order = BRANCHES if r >= 0.3 else BRANCHES[::-1]
        for b in order if branch is None else (branch,):
            for _, q in sorted(self._canon[b], key=lambda c: abs(c[0] - r)):
                qs = q.copy()
                qs[0] = _wrap(qs[0] + bearing)
                out.append(qs)
        return out

    def solve(
        self,
        pos: np.ndarray,
        yaw: float | None = None,
        seed: np.ndarray | None = None,
        *,
        why: bool = True,
        branch: int | None = None,
    ) -> IKResult:
        """A configuration putting the cup face at ``pos`` (base frame, m)
        pointing straight down, turned to ``yaw`` (rad; ``None``: any yaw,
        the one nearest the seed).

        Tries ``seed`` first, then the canonical seeds; with ``branch`` only a
        solution in that branch (:func:`branch_of`) counts. When none converges
        within the joint limits but one does without them, the reason is
        ``"joint limit"``, else ``"out of reach"`` (``why=False`` skips that
        test and says ``"out of reach"``).
        """
        pos = np.asarray(pos, dtype=float)
        tries = ([np.asarray(seed, dtype=float)] if seed is not None else []) + self.seeds(pos, branch)
        best: IKResult | None = None
        for q0 in tries:
            res = self._solve(pos, yaw, q0, limits=True)
            if res.ok and (branch is None or branch_of(res.q) == branch):
                return res
            if best is None or res.pos_err < best.pos_err:
                best = res
        assert best is not None
        if not why:
            return best
        free = self._solve(pos, yaw, tries[0], limits=False)
        if free.ok and (np.any(free.q < self.lower - 1e-9) or np.any(free.q > self.upper + 1e-9)):
            return IKResult(False, best.q, best.pos_err, best.rot_err, "joint limit")
        return best


def _wrap(a: float) -> float:
    return (a + math.pi) % (2 * math.pi) - math.pi


#: The two wrist branches the arm works in (see :class:`ArmIK`).
BRANCHES = (0, 1)


def branch_of(q: np.ndarray) -> int:
    """The wrist branch of a configuration: 0 with wrist 2 at -90 deg (modulo a
    full turn), 1 at +90 deg."""
    return 0 if math.sin(float(q[4])) < 0 else 1


def _elbow_up(q: np.ndarray) -> bool:
    """The elbow bends the usual way (the forearm above the wrist line): the
    elbow angle's sign as in the canonical configuration."""
    return bool(q[2] > 0.05)


# --------------------------------------------------------------- reachability


def reach_map(
    ik: ArmIK,
    *,
    table_margin: float = 0.05,
    r_step: float = 0.01,
    z_step: float = 0.02,
    r_max: float = 1.0,
    z_max: float = 0.6,
) -> dict:
    """Over a grid of horizontal distance ``r`` from the base axis and height
    ``z`` of the cup face above the base, whether a top-down pose is reachable
    (checked at two bearings; the shoulder turns fully, so the others are the
    same). Returns the map as a JSON-ready dict of per-height ``[r_min, r_max]``
    intervals."""
    rs = np.arange(0.0, r_max + 1e-9, r_step)
    zs = np.arange(0.0, z_max + 1e-9, z_step)
    rows: list[list[float] | None] = []
    for z in zs:
        ok_r = []
        prev: np.ndarray | None = None
        for r in rs:
            good = True
            for b in (0.0, 2.0):
                p = np.array([-r * math.sin(b), r * math.cos(b), z])
                res = ik.solve(p, None, prev if b == 0.0 else None, why=False)
                if not res.ok:
                    good = False
                    break
                if b == 0.0:
                    prev = res.q
            ok_r.append(good)
        arr = np.array(ok_r)
        if not arr.any():
            rows.append(None)
            continue
        idx = np.nonzero(arr)[0]
        # The reachable set at one height is one interval; keep its largest run.
        runs = np.split(idx, np.nonzero(np.diff(idx) > 1)[0] + 1)
        run = max(runs, key=len)
        rows.append([round(float(rs[run[0]]), 4), round(float(rs[run[-1]]), 4)])
    return {
        "robot": ik.arm.name,
        "what": "top-down reach of the cup face: per height z above the base plane, "
        "the interval of horizontal distance r from the base axis",
        "z": [round(float(z), 4) for z in zs],
        "r": rows,
        "r_step": r_step,
        "cup_length": ik.arm.cup_length,
        "base_gap": round(table_margin + ik.arm.base_clear, 4),
    }


def _benchmark_ik(n: int, seed: int) -> dict:
    """Solve ``n`` random top-down poses drawn inside the reachability map and
    report accuracy and time."""
    from ..robot import load_robot

    robot = load_robot("ur5e")
    ik = ArmIK()
    rng = np.random.default_rng(seed)
    pe, re, times = [], [], []
    fails = 0
    drawn = 0
    while drawn < n:
        r = rng.uniform(0.0, 1.0)
        z = rng.uniform(0.0, 0.4)
        b = rng.uniform(-math.pi, math.pi)
        if not robot.reach_rz(np.array([r]), np.array([z]))[0]:
            continue
        drawn += 1
        p = np.array([-r * math.sin(b), r * math.cos(b), z])
        yaw = float(rng.uniform(-math.pi, math.pi))
        t0 = time.perf_counter()
        res = ik.solve(p, yaw)
        times.append(time.perf_counter() - t0)
        pos, rot = ik.fk(res.q)
        pe.append(float(np.linalg.norm(pos - p)))
        re.append(float(np.linalg.norm(_rot_error(rot, down_rotation(yaw)))))
        fails += not res.ok
    # Unreachable poses: beyond the arm's length, and inside its base.
    wrong = 0
    far = [np.array([0.0, 1.2, 0.1]), np.array([0.9, 0.6, 0.0]), np.array([0.0, 0.02, 0.05])]
    for p in far:
        res = ik.solve(p, 0.0)
        wrong += res.ok
    return {
        "poses": n,
        "solved": n - fails,
        "pos_err_max_mm": 1000 * max(pe),
        "rot_err_max_rad": max(re),
        "time_median_ms": 1000 * float(np.median(times)),
        "time_p95_ms": 1000 * float(np.percentile(times, 95)),
        "unreachable_reported_as_solved": wrong,
    }


def main(argv: list[str] | None = None) -> None:
    ap = argparse.ArgumentParser(description="UR5e reachability map and IK figures.")
    ap.add_argument("--write-reach", action="store_true", help="recompute lgmcts/robot_ur5e.json")
    ap.add_argument("--ik", type=int, default=0, help="solve this many random reachable top-down poses and report")
    ap.add_argument("--seed", type=int, default=0)
    a = ap.parse_args(argv)
    if a.write_reach:
        t0 = time.perf_counter()
        data = reach_map(ArmIK())
        path = Path(__file__).resolve().parent.parent / "robot_ur5e.json"
        path.write_text(json.dumps(data, indent=1) + "\n")
        print(f"wrote {path} in {time.perf_counter() - t0:.1f} s")
    if a.ik:
        print(json.dumps(_benchmark_ik(a.ik, a.seed), indent=2))


if __name__ == "__main__":
    main()
