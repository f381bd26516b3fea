"""Build a MuJoCo model of a tabletop scene with :class:`mujoco.MjSpec`.

The model holds a static table whose top face is the plane ``z = 0``, one
free body per scene object, a floor far below the table (so a dropped object
comes to rest somewhere), a mocap body that plays the suction gripper and one
inactive weld constraint per object that ties the object to the gripper when
switched on. Two fixed cameras look at the table: ``overhead`` straight down
and ``view`` at an angle from the front (for videos).

Object frames follow the scene format: the body origin sits at the footprint
centre ``(x, y)`` of the pose, at half the object's height, with yaw
``theta`` about +z. Boxes and cylinders use MuJoCo's primitives; polygons and
point clouds become the convex hull of their footprint extruded to their
height (a mesh geom).
"""

from __future__ import annotations

import math
import zlib
from dataclasses import dataclass
from typing import Any

import mujoco
import numpy as np

from ..errors import InputError
from ..formats import SceneSpec
from ..scene import TABLE, Scene

__all__ = [
    "ARM_VIEW_CAMERA",
    "GRIPPER",
    "OVERHEAD_CAMERA",
    "SIDE_CAMERA",
    "VIEW_CAMERA",
    "ModelOptions",
    "SimModel",
    "add_welds",
    "build_model",
    "look_at",
    "yaw_quat",
]

#: Name of the mocap body that plays the suction gripper.
GRIPPER = "gripper"
#: Name of the camera that looks straight down at the table.
OVERHEAD_CAMERA = "overhead"
#: Name of the angled camera used for videos.
VIEW_CAMERA = "view"
#: Name of the camera that films a scene with the arm (from the front right,
#: so the arm does not hide the table).
ARM_VIEW_CAMERA = "arm_view"
#: Prefix of the four angled perception cameras (``side0`` ... ``side3``).
SIDE_CAMERA = "side"

_COLOR_RGBA = {
    "red": (0.85, 0.15, 0.15),
    "green": (0.2, 0.7, 0.25),
    "blue": (0.2, 0.35, 0.85),
    "yellow": (0.95, 0.85, 0.15),
    "purple": (0.55, 0.25, 0.7),
    "white": (0.95, 0.95, 0.95),
    "black": (0.1, 0.1, 0.1),
    "orange": (0.95, 0.55, 0.1),
    "pink": (0.95, 0.55, 0.7),
    "brown": (0.55, 0.35, 0.2),
    "gray": (0.5, 0.5, 0.5),
    "grey": (0.5, 0.5, 0.5),
    "cyan": (0.2, 0.8, 0.85),
}


@dataclass(frozen=True)
class ModelOptions:
    """Physical and numerical parameters of the simulated scene.

    Attributes
    ----------
    timestep : integration step (s).
    density : density of every object (kg/m^3); 500 is light wood or plastic.
    friction : sliding friction coefficient of every contact.
    table_margin : how far the table top extends beyond the workspace (m).
    table_thickness : thickness of the table top (m).
    floor_z : height of the floor below the table top (m, negative).
    weld_timeconst : time constant of the gripper weld (s); stiffer holds
        the carried object closer to the gripper pose.
    cone : friction cone, ``"pyramidal"`` (faster) or ``"elliptic"``.
    sleep : let objects at rest sleep (MuJoCo's island sleeping): they cost
        nothing until something touches them, which makes an action several
        times faster in a cluttered scene.
    """

    timestep: float = 0.004
    density: float = 500.0
    friction: float = 0.8
    table_margin: float = 0.05
    table_thickness: float = 0.04
    floor_z: float = -0.75
    weld_timeconst: float = 0.01
    cone: str = "pyramidal"
    sleep: bool = True


def yaw_quat(theta: float) -> np.ndarray:
    """Unit quaternion ``(w, x, y, z)`` of a rotation by ``theta`` (rad) about +z."""
    return np.array([math.cos(theta / 2), 0.0, 0.0, math.sin(theta / 2)])


def look_at(eye: np.ndarray, target: np.ndarray) -> np.ndarray:
    """Quaternion ``(w, x, y, z)`` of a MuJoCo camera at ``eye`` looking at
    ``target`` with the image's up direction towards +z (m)."""
    back = np.asarray(eye, dtype=float) - np.asarray(target, dtype=float)
    back /= np.linalg.norm(back)
    right = np.cross([0.0, 0.0, 1.0], back)
    if np.linalg.norm(right) < 1e-9:  # looking straight down: image up is +y
        right = np.array([1.0, 0.0, 0.0])
    right /= np.linalg.norm(right)
    up = np.cross(back, right)
    quat = np.zeros(4)
    mujoco.mju_mat2Quat(quat, np.column_stack([right, up, back]).ravel())
    return quat


def _rgba(color: str, k: int) -> list[float]:
    words = color.lower().replace("-", " ").split()
    for w in words:
        if w in _COLOR_RGBA:
            return [*_COLOR_RGBA[w], 1.0]
    # Unknown colour names still get a stable, distinct shade.
    rng = np.random.default_rng(zlib.crc32(color.encode()) if color else k)
    return [*map(float, rng.uniform(0.2, 0.9, 3)), 1.0]


@dataclass(frozen=True, eq=False)
class SimModel:
    """A compiled model and the maps from scene objects to its parts.

    Attributes
    ----------
    scene : the planning view of the scene (footprints, heights, ids).
    model : the compiled, read-only :class:`mujoco.MjModel`.
    body : per object index, its body id.
    geom : per object index, its geom id.
    weld : per object index, the id of its gripper weld constraint.
    qpos_adr : per object index, the address of its free joint in ``qpos``.
    qvel_adr : per object index, the address of its free joint in ``qvel``.
    table_geom : geom id of the table top.
    floor_geom : geom id of the floor.
    mocap : mocap index of the gripper body.
    geom_object : ``(ngeom,)`` object index of each geom, -1 for the rest.
    geom_who : ``(ngeom,)`` object index of each geom, ``-1`` for the table,
        ``-2`` for the floor, ``-3`` for the rest (contact bookkeeping).
    arm : the robot arm's parts (:class:`lgmcts.sim.arm.ArmParts`), or
        ``None`` for a scene with the floating gripper only.
    """

    scene: Scene
    model: mujoco.MjModel
    body: np.ndarray
    geom: np.ndarray
    weld: np.ndarray
    qpos_adr: np.ndarray
    qvel_adr: np.ndarray
    table_geom: int
    floor_geom: int
    mocap: int
    geom_object: np.ndarray
    geom_who: np.ndarray
    arm: Any = None

    @property
    def heights(self) -> np.ndarray:
        """``(n,)`` object heights (m)."""
        return self.scene.heights


def _add_object(spec: mujoco.MjSpec, scene: Scene, k: int, base_z: float, opts: ModelOptions) -> None:
    o = scene.spec.objects[k]
    x, y, th = (float(v) for v in scene.initial.poses[k])
    h = float(scene.heights[k])
    body = spec.worldbody.add_body(name=f"obj{o.id}", pos=[x, y, base_z + h / 2], quat=yaw_quat(th).tolist())
    body.add_freejoint(name=f"obj{o.id}_joint")
    rgba = _rgba(o.color, k)
    friction = [opts.friction, 0.005, 0.0001]
    common = {"name": f"obj{o.id}_geom", "density": opts.density, "friction": friction, "rgba": rgba}
    s = o.shape
    if s.type == "box":
        body.add_geom(type=mujoco.mjtGeom.mjGEOM_BOX, size=[s.size[0] / 2, s.size[1] / 2, s.size[2] / 2], **common)
    elif s.type == "cylinder":
        body.add_geom(type=mujoco.mjtGeom.mjGEOM_CYLINDER, size=[s.radius, s.height / 2, 0.0], **common)
    else:
        # Polygons and point clouds: the convex footprint extruded to the height.
        local = np.asarray(scene.local[k], dtype=float)
        verts = np.concatenate(
            [
                np.column_stack([local, np.full(len(local), -h / 2)]),
                np.column_stack([local, np.full(len(local), h / 2)]),
            ]
        )
        spec.add_mesh(name=f"obj{o.id}_mesh", uservert=verts.ravel().tolist())
        body.add_geom(type=mujoco.mjtGeom.mjGEOM_MESH, meshname=f"obj{o.id}_mesh", **common)


def build_model(scene: SceneSpec | Scene, *, options: ModelOptions | None = None, robot: str | None = None) -> SimModel:
    """Compile a MuJoCo model of ``scene`` with every object at its pose.

    Stacked objects start resting on their supports: an object's bottom is at
    the summed heights of the objects below it (m).

    Parameters
    ----------
    scene : the scene (a validated spec or a :class:`lgmcts.scene.Scene`).
    options : physical parameters; defaults to :class:`ModelOptions`.
    robot : ``"ur5e"`` adds a UR5e arm with a suction cup, its base at the
        centre of the table's front edge (:mod:`lgmcts.sim.arm`), and one
        inactive weld per object between the cup and the object.
    """
    opts = options or ModelOptions()
    sc = scene if isinstance(scene, Scene) else Scene.from_spec(scene)
    spec = mujoco.MjSpec()
    spec.modelname = "lgmcts_table"
    spec.option.timestep = opts.timestep
    spec.option.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    if opts.cone not in ("pyramidal", "elliptic"):
        raise ValueError(f"unknown friction cone {opts.cone!r}")
    spec.option.cone = mujoco.mjtCone.mjCONE_ELLIPTIC if opts.cone == "elliptic" else mujoco.mjtCone.mjCONE_PYRAMIDAL
    if opts.sleep:
        spec.option.enableflags |= int(mujoco.mjtEnableBit.mjENBL_SLEEP)
    spec.visual.global_.offwidth = 1280
    spec.visual.global_.offheight = 960
    spec.visual.quality.shadowsize = 0
    # No multisampling: depth and segmentation pixels must line up exactly.
    spec.visual.quality.offsamples = 0
    xmin, xmax, ymin, ymax = sc.bounds
    cx, cy = (xmin + xmax) / 2, (ymin + ymax) / 2
    hx = (xmax - xmin) / 2 + opts.table_margin
    hy = (ymax - ymin) / 2 + opts.table_margin
    wb = spec.worldbody
    wb.add_light(name="sun", pos=[cx, cy - 0.5, 2.0], dir=[0.0, 0.25, -1.0], diffuse=[0.8, 0.8, 0.8])
    wb.add_geom(
        name="floor",
        type=mujoco.mjtGeom.mjGEOM_PLANE,
        size=[hx * 4, hy * 4, 0.1],
        pos=[cx, cy, opts.floor_z],
        rgba=[0.3, 0.3, 0.32, 1.0],
        friction=[opts.friction, 0.005, 0.0001],
    )
    wb.add_geom(
        name="table",
        type=mujoco.mjtGeom.mjGEOM_BOX,
        size=[hx, hy, opts.table_thickness / 2],
        pos=[cx, cy, -opts.table_thickness / 2],
        rgba=[0.72, 0.6, 0.45, 1.0],
        friction=[opts.friction, 0.005, 0.0001],
    )
    # Overhead camera: straight down, high enough to see the whole table.
    fovy = 45.0
    aspect = 4.0 / 3.0
    t = math.tan(math.radians(fovy) / 2)
    height = 1.08 * max(hy / t, hx / (t * aspect)) + float(np.max(sc.heights, initial=0.0))
    wb.add_camera(name=OVERHEAD_CAMERA, pos=[cx, cy, height], quat=[1.0, 0.0, 0.0, 0.0], fovy=fovy)
    # Angled camera from the front, looking at the table centre (videos).
    dist = 1.25 * max(hx * 1.6, hy * 2.2)
    elev = math.radians(50.0)
    eye = np.array([cx, cy - dist * math.cos(elev), dist * math.sin(elev)])
    wb.add_camera(name=VIEW_CAMERA, pos=eye.tolist(), quat=look_at(eye, np.array([cx, cy, 0.0])).tolist(), fovy=fovy)
    # Four angled cameras around the table for perception: they see the
    # sides of objects that the overhead camera sees only from the top.
    side = 1.1 * math.hypot(hx, hy) / t
    for j, az in enumerate((-90.0, 0.0, 90.0, 180.0)):
        a = math.radians(az)
        eye = np.array(
            [cx + side * math.cos(elev) * math.cos(a), cy + side * math.cos(elev) * math.sin(a), side * math.sin(elev)]
        )
        wb.add_camera(
            name=f"{SIDE_CAMERA}{j}", pos=eye.tolist(), quat=look_at(eye, np.array([cx, cy, 0.0])).tolist(), fovy=fovy
        )
    grip = wb.add_body(name=GRIPPER, mocap=True, pos=[cx, cy, height * 0.5])
    grip.add_geom(
        name="gripper_cup",
        type=mujoco.mjtGeom.mjGEOM_SPHERE,
        size=[0.008, 0.0, 0.0],
        contype=0,
        conaffinity=0,
        rgba=[0.2, 0.2, 0.2, 0.0],
        density=0.0,
    )
    state = sc.initial
    for k in range(sc.n):
        _add_object(spec, sc, k, state.base_z(k), opts)
    add_welds(spec, GRIPPER, "grip", [o.id for o in sc.spec.objects], opts.weld_timeconst)
    if robot is not None:
        from .arm import add_arm, add_cup_welds, base_pose, robot_spec

        arm_spec = robot_spec(robot)
        add_arm(spec, base_pose(sc.bounds, opts.table_margin, arm_spec), arm_spec)
        add_cup_welds(spec, sc.ids, opts.weld_timeconst)
        reach = max(hx, hy) * 2.2 + 0.6
        eye = np.array([cx + 0.75 * reach, cy - 0.55 * reach, 0.7 * reach])
        look = np.array([cx, cy - 0.2 * hy, 0.1])
        wb.add_camera(name=ARM_VIEW_CAMERA, pos=eye.tolist(), quat=look_at(eye, look).tolist(), fovy=fovy)
    try:
        model = spec.compile()
    except ValueError as exc:
        # MuJoCo refuses bodies whose mass or inertia underflows its minimum
        # (a tiny, thin object): bad input to the simulator, said in one line.
        raise InputError(f"the simulator cannot build this scene: {' '.join(str(exc).split())[:200]}") from None
    bodies = np.array([model.body(f"obj{i}").id for i in sc.ids])
    geoms = np.array([model.geom(f"obj{i}_geom").id for i in sc.ids])
    welds = np.array([model.equality(f"grip{i}").id for i in sc.ids])
    jnt = [model.body_jntadr[b] for b in bodies]
    geom_object = np.full(model.ngeom, -1, dtype=int)
    geom_object[geoms] = np.arange(sc.n)
    geom_who = np.full(model.ngeom, -3, dtype=int)
    geom_who[geoms] = np.arange(sc.n)
    geom_who[model.geom("table").id] = TABLE
    geom_who[model.geom("floor").id] = -2
    arm = None
    if robot is not None:
        from .arm import arm_parts

        arm = arm_parts(model, sc.ids, robot_spec(robot), base_pose(sc.bounds, opts.table_margin, robot_spec(robot)))
    return SimModel(
        scene=sc,
        model=model,
        body=bodies,
        geom=geoms,
        weld=welds,
        qpos_adr=np.array([model.jnt_qposadr[j] for j in jnt]),
        qvel_adr=np.array([model.jnt_dofadr[j] for j in jnt]),
        table_geom=model.geom("table").id,
        floor_geom=model.geom("floor").id,
        mocap=int(model.body_mocapid[model.body(GRIPPER).id]),
        geom_object=geom_object,
        geom_who=geom_who,
        arm=arm,
    )


def add_welds(spec: mujoco.MjSpec, body: str, prefix: str, ids: list[int] | tuple[int, ...], timeconst: float) -> None:
    """One inactive weld per object between ``body`` and the object (``<prefix><id>``).

    The relative pose is the identity (the object frame follows ``body``'s);
    the executor sets the actual one when it switches a weld on.
    """
    for i in ids:
        spec.add_equality(
            name=f"{prefix}{i}",
            type=mujoco.mjtEq.mjEQ_WELD,
            objtype=mujoco.mjtObj.mjOBJ_BODY,
            name1=body,
            name2=f"obj{i}",
            active=False,
            data=[0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 1, 0],
            solref=[timeconst, 1.0],
        )
