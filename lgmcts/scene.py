"""Immutable scene model: what never changes (:class:`Scene`) and what an
action changes (:class:`State`).

A :class:`State` holds the poses and supports of every object. States are
never mutated: :meth:`State.moved` returns a new one that shares every
footprint polygon but the moved object's, so search-tree nodes stay small.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np
import shapely

from . import geometry as geo
from . import limits
from .errors import InputError
from .formats import ObjectSpec, SceneSpec, Workspace

__all__ = ["TABLE", "Scene", "State", "advance", "replay"]

#: Support index meaning "on the table".
TABLE = -1


def _pose3(p: Any) -> tuple[float, float, float]:
    x, y, t = (float(v) for v in p)
    return x, y, t


def _local_footprint(obj: ObjectSpec) -> tuple[np.ndarray, float, tuple[float, float, float]]:
    """Object-frame footprint, height and pose of one object spec."""
    s = obj.shape
    if s.type == "box":
        return geo.box_footprint(s.size[0], s.size[1]), float(s.size[2]), _pose3(obj.pose)
    if s.type == "cylinder":
        return geo.circle_footprint(s.radius), float(s.height), _pose3(obj.pose)
    if s.type == "polygon":
        pts = geo.convex_footprint(np.asarray(s.points, dtype=float))
        return pts, float(s.height), _pose3(obj.pose)
    # A point cloud lives in the table frame; its footprint centre is the
    # centroid of the convex hull of its xy, unless the pose says otherwise.
    cloud = np.asarray(s.points, dtype=float)
    hull = geo.convex_footprint(cloud[:, :2])
    height = float(cloud[:, 2].max() - cloud[:, 2].min())
    if obj.pose is None:
        c = shapely.Polygon(hull).centroid
        pose = (float(c.x), float(c.y), 0.0)
    else:
        pose = _pose3(obj.pose)
    x, y, t = pose
    ct, st = math.cos(-t), math.sin(-t)
    d = hull - np.array([x, y])
    local = np.stack([ct * d[:, 0] - st * d[:, 1], st * d[:, 0] + ct * d[:, 1]], axis=1)
    return local, max(height, 1e-3), pose


def _outside(verts: list[np.ndarray], on: tuple[int, ...], bounds: tuple[float, float, float, float]) -> list[int]:
    """Indices of the table-level footprints (vertices ``verts``) not inside the workspace, in order; one test per
    vertex count."""
    groups: dict[int, list[int]] = {}
    for k, v in enumerate(verts):
        if on[k] == TABLE:
            groups.setdefault(len(v), []).append(k)
    out: list[int] = []
    for ks in groups.values():
        ok = geo.inside_workspace(np.stack([verts[k] for k in ks]), bounds, margin=-1e-6)
        out += [k for k, good in zip(ks, ok.tolist()) if not good]
    return sorted(out)


def _refuse_start_overlaps(spec: SceneSpec, on: tuple[int, ...], polys: np.ndarray) -> None:
    """Raise :class:`InputError` when two table-level footprints share more than
    :data:`lgmcts.limits.START_OVERLAP_AREA` m^2 (:func:`geometry.overlap_pairs`).
    Touching is legal.
    """
    table = np.flatnonzero(np.asarray(on) == TABLE)
    if len(table) < 2:
        return
    objs = [spec.objects[k] for k in table]
    disc = np.array([o.shape.radius if o.shape.type == "cylinder" else 0.0 for o in objs], dtype=float)
    xy = np.array([o.pose[:2] if o.pose is not None else (0.0, 0.0) for o in objs], dtype=float)
    a, b, areas = geo.overlap_pairs(np.asarray(polys, dtype=object)[table], disc, xy)
    bad = np.flatnonzero(areas > limits.START_OVERLAP_AREA)
    if len(bad):
        k = bad[0]
        i, j = spec.objects[table[a[k]]], spec.objects[table[b[k]]]
        raise InputError(
            f"objects {i.id} and {j.id} overlap by {areas[k] * 1e4:.2f} cm^2 in the start scene "
            f"(footprints on the table may touch, not overlap)"
        )


@dataclass(frozen=True, eq=False)
class Scene:
    """The static part of a scene: workspace and object descriptions.

    Attributes
    ----------
    ids : object ids in file order; an object's *index* is its position here.
    local : per object, its ``(k, 2)`` footprint in the object frame (m).
    heights : ``(n,)`` object heights (m).
    radii : ``(n,)`` circumradius of each footprint about its centre (m).
    bounds : ``(xmin, xmax, ymin, ymax)`` of the workspace (m).
    """

    spec: SceneSpec
    ids: tuple[int, ...]
    names: tuple[str, ...]
    colors: tuple[str, ...]
    local: tuple[np.ndarray, ...]
    heights: np.ndarray
    radii: np.ndarray
    bounds: tuple[float, float, float, float]
    initial: State

    @classmethod
    def from_spec(cls, spec: SceneSpec, *, overlap_ok: bool = False) -> Scene:
        """Build the scene; raise :class:`InputError` for objects off the workspace.

        Table-level footprints that overlap by more than
        :data:`lgmcts.limits.START_OVERLAP_AREA` m^2 are bad input too, unless
        ``overlap_ok`` (for scenes built only for their footprints, with every
        object at one place).
        """
        ids = tuple(o.id for o in spec.objects)
        if not ids:
            raise InputError("the scene has no objects")
        index = {i: k for k, i in enumerate(ids)}
        local, heights, poses = [], [], []
        for o in spec.objects:
            lf, h, p = _local_footprint(o)
            lf.setflags(write=False)
            local.append(lf)
            heights.append(h)
            poses.append(p)
        ws = spec.workspace
        bounds = (ws.x[0], ws.x[1], ws.y[0], ws.y[1])
        pose_arr = np.asarray(poses, dtype=float)
        on = tuple(TABLE if o.on is None else index[o.on] for o in spec.objects)
        verts, polys = geo.place_each(local, pose_arr)
        outside = _outside(verts, on, bounds)
        if outside:
            o = spec.objects[outside[0]]
            raise InputError(f"object {o.id} ({o.name}) lies outside the workspace")
        if not overlap_ok:
            _refuse_start_overlaps(spec, on, polys)
        scene = cls(
            spec=spec,
            ids=ids,
            names=tuple(o.name for o in spec.objects),
            colors=tuple(o.color for o in spec.objects),
            local=tuple(local),
            heights=np.asarray(heights, dtype=float),
            radii=np.asarray([geo.radius_of(lf) for lf in local], dtype=float),
            bounds=bounds,
            initial=None,  # type: ignore[arg-type]
        )
        object.__setattr__(scene, "initial", State.make(scene, pose_arr, on, polys))
        return scene

    @cached_property
    def index(self) -> dict[int, int]:
        """Map from object id to index."""
        return {i: k for k, i in enumerate(self.ids)}

    @property
    def n(self) -> int:
        return len(self.ids)

    @cached_property
    def discs(self) -> np.ndarray:
        """``(n,)`` radius of each cylinder's true circle (m), 0 for other shapes.

        Footprints are polygons circumscribing the circle; two cylinders that
        touch overlap as polygons by a sliver, so contact between cylinders is
        judged on the circles.
        """
        return np.array([o.shape.radius if o.shape.type == "cylinder" else 0.0 for o in self.spec.objects], dtype=float)

    def footprint(self, i: int, pose: np.ndarray) -> np.ndarray:
        """Table-frame vertices of object index ``i`` at ``pose`` (``(3,)`` or ``(m, 3)``)."""
        return geo.transform(self.local[i], pose)

    def label(self, i: int) -> str:
        """Short human label of object index ``i``: ``"3 red block"``."""
        color = f"{self.colors[i]} " if self.colors[i] else ""
        return f"{self.ids[i]} {color}{self.names[i]}"

    def to_spec(self, state: State) -> SceneSpec:
        """The scene JSON model for ``state`` (point clouds moved rigidly)."""
        objs = []
        for k, o in enumerate(self.spec.objects):
            pose = tuple(float(v) for v in state.poses[k])
            shape = o.shape
            if shape.type == "points":
                x0, y0, t0 = self.initial.poses[k]
                x1, y1, t1 = pose
                dz = state.base_z(k) - self.initial.base_z(k)
                pts = np.asarray(shape.points, dtype=float)
                c, s = math.cos(t1 - t0), math.sin(t1 - t0)
                dx, dy = pts[:, 0] - x0, pts[:, 1] - y0
                moved = np.stack([x1 + c * dx - s * dy, y1 + s * dx + c * dy, pts[:, 2] + dz], axis=1)
                shape = shape.model_copy(update={"points": [tuple(map(float, p)) for p in moved]})
            sup = state.on[k]
            on = None if sup == TABLE else self.ids[sup]
            objs.append(o.model_copy(update={"pose": pose, "shape": shape, "on": on}))
        return SceneSpec(workspace=Workspace(x=self.spec.workspace.x, y=self.spec.workspace.y), objects=objs)


@dataclass(frozen=True, eq=False)
class State:
    """Poses and supports of every object; immutable and cheap to derive.

    ``poses`` is a read-only ``(n, 3)`` array; ``on[i]`` is the index of the
    object that ``i`` rests on, or :data:`TABLE`.
    """

    scene: Scene = field(repr=False)
    poses: np.ndarray
    on: tuple[int, ...]
    _polys: tuple = field(repr=False, default=())

    @classmethod
    def make(cls, scene: Scene, poses: np.ndarray, on: tuple[int, ...], polys: np.ndarray | None = None) -> State:
        """The state with ``poses`` and supports ``on`` (``polys``: the
        footprint polygons at those poses, when already built)."""
        poses = np.array(poses, dtype=float)
        poses.setflags(write=False)
        if polys is None:
            polys = geo.place_each(scene.local, poses)[1]
        return cls(scene, poses, tuple(on), tuple(polys))

    def moved(self, i: int, pose: np.ndarray | tuple[float, float, float], on: int = TABLE, *,
              footprint: bool = True) -> State:
        """A new state with object ``i`` at ``pose`` resting on ``on``; without ``footprint`` its entry of
        :attr:`polys` is ``None`` (for a replay that judges cylinders on their circles and builds no polygon)."""
        poses = self.poses.copy()
        poses[i] = pose
        poses.setflags(write=False)
        if on == self.on[i]:
            sup = self.on
        else:
            changed = list(self.on)
            changed[i] = on
            sup = tuple(changed)
        polys = list(self._polys)
        polys[i] = shapely.polygons(geo.transform(self.scene.local[i], poses[i])) if footprint else None
        out = State(self.scene, poses, sup, tuple(polys))
        if on == self.on[i]:
            # Same supports: what depends on them alone carries over.
            for key in ("holding", "table_level"):
                if key in self.__dict__:
                    out.__dict__[key] = self.__dict__[key]
        return out

    @property
    def polys(self) -> tuple:
        """Shapely footprint polygon of every object at its pose."""
        return self._polys

    @cached_property
    def holding(self) -> tuple[tuple[int, ...], ...]:
        """``holding[i]``: indices of the objects resting directly on ``i``."""
        out: list[list[int]] = [[] for _ in self.on]
        for k, s in enumerate(self.on):
            if s != TABLE:
                out[s].append(k)
        return tuple(tuple(x) for x in out)

    def clear(self, i: int) -> bool:
        """Whether nothing rests on object ``i`` (so it can be picked or stacked on)."""
        return not self.holding[i]

    def above(self, i: int) -> list[int]:
        """All objects resting on ``i``, directly or through others."""
        out, todo = [], list(self.holding[i])
        while todo:
            k = todo.pop()
            out.append(k)
            todo.extend(self.holding[k])
        return out

    def base_z(self, i: int) -> float:
        """Height of the bottom of object ``i`` above the table (m)."""
        z, s = 0.0, self.on[i]
        while s != TABLE:
            z += float(self.scene.heights[s])
            s = self.on[s]
        return z

    @cached_property
    def table_level(self) -> np.ndarray:
        """Indices of the objects standing on the table."""
        return np.asarray([k for k, s in enumerate(self.on) if s == TABLE], dtype=int)

    @cached_property
    def poly_array(self) -> np.ndarray:
        """:attr:`polys` as a numpy object array (for vectorised predicates)."""
        out = np.empty(len(self._polys), dtype=object)
        out[:] = self._polys
        return out


def _pose_out_of_bounds(pose: np.ndarray) -> str | None:
    """Why a target pose is unusable before any geometry, or ``None``.

    Non-finite values, coordinates beyond :data:`lgmcts.limits.MAX_COORD` and
    yaws beyond :data:`lgmcts.limits.MAX_ANGLE` are refused (the plan format
    refuses them too; this holds for plans built in code), so that footprints
    are only ever built at magnitudes where they keep their shape.
    """
    if pose.shape != (3,) or not np.isfinite(pose).all():
        return "has a non-finite target pose"
    if abs(pose[0]) > limits.MAX_COORD or abs(pose[1]) > limits.MAX_COORD or abs(pose[2]) > limits.MAX_ANGLE:
        return "placed outside the workspace (target beyond the coordinate bounds)"
    return None


def advance(state: State, number: int, action: Any, *, footprint: bool = True) -> State:
    """The state after ``action`` (the plan's action ``number``, from 1).

    The one step of every replay: :func:`replay`, the validator, polishing,
    the pose fields, the pictures and the service's viewer all go through it.
    Only what makes the action meaningless is refused here; an illegal but
    well-formed action (picking a covered object, an overlap) is taken as
    given, for the validator to judge. Without ``footprint`` the moved
    object's polygon is not built (see :meth:`State.moved`).

    Raises
    ------
    InputError
        When the action names an object or support the scene does not have,
        places an object on itself, or has a non-finite or out-of-bounds
        target pose; the message starts with ``"action <number>: "``.
    """
    scene = state.scene
    if action.object not in scene.index:
        raise InputError(f"action {number}: unknown object id {action.object}")
    if action.on is not None and action.on not in scene.index:
        raise InputError(f"action {number}: object {action.object} placed on unknown object id {action.on}")
    if action.on == action.object:
        raise InputError(f"action {number}: object {action.object} placed on itself")
    pose = np.asarray(action.to, dtype=float)
    bad = _pose_out_of_bounds(pose)
    if bad is not None:
        raise InputError(f"action {number}: object {action.object} {bad}")
    sup = TABLE if action.on is None else scene.index[action.on]
    return state.moved(scene.index[action.object], pose, sup, footprint=footprint)


def replay(scene: Scene, actions: Sequence[Any]) -> list[State]:
    """The states a plan passes through: before the first action and after
    each one (``len(actions) + 1``), each from :func:`advance`.

    Raises
    ------
    InputError
        At the first action :func:`advance` refuses.
    """
    states = [scene.initial]
    for k, a in enumerate(actions, start=1):
        states.append(advance(states[-1], k, a))
    return states
