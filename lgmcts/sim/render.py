"""Cameras: perception from depth and segmentation, and execution videos.

:func:`observe` renders an RGB image, a depth image and a segmentation image
of the scene from a camera straight above the table (``mujoco.Renderer``),
back-projects each object's pixels into a point cloud in the table frame and
returns a scene whose objects are ``points`` shapes: the loop from camera to
footprints of the paper's system.

A camera above the table sees the top faces (and, off-centre, a sliver of the
sides) of the objects, not their bottoms. Each cloud is therefore completed
under the usual tabletop assumption that an object is an upright extrusion:
the outline of its visible points is repeated at the height of what it stands
on (the table, or the top of its support's cloud), so the cloud's z extent is
the object's height and its xy hull is its footprint.

Rendering needs an OpenGL context without a display; ``MUJOCO_GL`` defaults
to ``osmesa`` here (Debian's ``libosmesa6``) and may be set to ``egl`` where
a GPU is available. The variable is read when ``mujoco`` is first imported,
so this module sets it before importing ``mujoco``.
"""

from __future__ import annotations

import os

os.environ.setdefault("MUJOCO_GL", "osmesa")
os.environ.setdefault("PYOPENGL_PLATFORM", os.environ["MUJOCO_GL"])

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import shapely

from ..errors import InputError
from ..formats import SceneSpec, load_scene, parse_scene
from ..scene import TABLE, Scene
from .model import OVERHEAD_CAMERA, SIDE_CAMERA, VIEW_CAMERA, SimModel, build_model

__all__ = [
    "CameraOptions",
    "Frames",
    "VideoRecorder",
    "backproject",
    "drop_strays",
    "footprint_iou",
    "observe",
    "render_frames",
]


@dataclass(frozen=True)
class CameraOptions:
    """Options of the perception cameras.

    Attributes
    ----------
    width, height : image size (pixels); about 1.5 mm per pixel on the
        example table at 640 x 480 from overhead.
    cameras : names of the model cameras whose clouds are fused; the overhead
        camera alone cannot see an object hidden under a larger one, the four
        angled ``side`` cameras see their sides.
    max_points : most points kept per object in the observed scene.
    min_pixels : objects seen in fewer pixels (over all cameras) are left out
        of the observed scene.
    stray_dist : a point of an object's fused cloud with no other point of
        that cloud within this distance is dropped (m). A pixel whose depth
        and label disagree (seen at the rim of an object from a low angle)
        back-projects to a lone point far from the object; kept, it would
        stretch the object's outline by up to tens of centimetres.
    seed : seed of the point subsampling.
    """

    width: int = 640
    height: int = 480
    cameras: tuple[str, ...] = (OVERHEAD_CAMERA, *(f"{SIDE_CAMERA}{j}" for j in range(4)))
    max_points: int = 400
    min_pixels: int = 12
    stray_dist: float = 0.01
    seed: int = 0


@dataclass(frozen=True)
class Frames:
    """Images from one camera.

    Attributes
    ----------
    rgb : ``(h, w, 3)`` uint8 colour image.
    depth : ``(h, w)`` distance along the optical axis (m).
    segmentation : ``(h, w)`` geom id seen at each pixel, -1 for none.
    points : ``(h, w, 3)`` table-frame point seen at each pixel (m).
    """

    rgb: np.ndarray
    depth: np.ndarray
    segmentation: np.ndarray
    points: np.ndarray


def _open_renderer(model: mujoco.MjModel, height: int, width: int) -> mujoco.Renderer:
    try:
        return mujoco.Renderer(model, height=height, width=width)
    except Exception as exc:  # the GL backend could not start: say so in one line
        backend = os.environ.get("MUJOCO_GL", "")
        raise RuntimeError(f"cannot start offscreen rendering with MUJOCO_GL={backend}: {exc}") from None


def backproject(depth: np.ndarray, cam_pos: np.ndarray, cam_mat: np.ndarray, fovy_deg: float) -> np.ndarray:
    """World point of every pixel of a perspective depth image.

    Parameters
    ----------
    depth : ``(h, w)`` distance along the optical axis (m), row 0 at the top.
    cam_pos : ``(3,)`` camera position (m).
    cam_mat : ``(3, 3)`` camera orientation; its columns are the camera's x
        (right), y (up) and z (backwards) axes in the world frame.
    fovy_deg : vertical field of view (degrees).

    Returns
    -------
    ``(h, w, 3)`` points in the world (table) frame (m).
    """
    h, w = depth.shape
    f = 0.5 * h / math.tan(math.radians(fovy_deg) / 2)
    u = (np.arange(w) + 0.5 - w / 2) / f
    v = (h / 2 - (np.arange(h) + 0.5)) / f
    uu, vv = np.meshgrid(u, v)
    cam = np.stack([uu * depth, vv * depth, -depth], axis=-1)
    return cam @ np.asarray(cam_mat).reshape(3, 3).T + np.asarray(cam_pos)


def render_frames(
    sim: SimModel,
    data: mujoco.MjData,
    *,
    camera: str = OVERHEAD_CAMERA,
    width: int = 640,
    height: int = 480,
    renderer: mujoco.Renderer | None = None,
) -> Frames:
    """Render RGB, depth and segmentation of ``data`` from ``camera`` and
    back-project the depth into table-frame points.

    ``renderer`` may be an open renderer of ``sim.model`` of the same size
    (reused across cameras); otherwise one is opened and closed here.
    """
    model = sim.model
    cam = model.camera(camera).id
    mujoco.mj_forward(model, data)
    if renderer is None:
        with _open_renderer(model, height, width) as r:
            return render_frames(sim, data, camera=camera, width=width, height=height, renderer=r)
    r = renderer
    r.update_scene(data, camera=cam)
    rgb = r.render().copy()
    r.enable_depth_rendering()
    r.update_scene(data, camera=cam)
    depth = r.render().astype(float)
    r.enable_segmentation_rendering()
    r.update_scene(data, camera=cam)
    seg = r.render().copy()
    r.disable_segmentation_rendering()
    geom = np.where(seg[..., 1] == int(mujoco.mjtObj.mjOBJ_GEOM), seg[..., 0], -1)
    pts = backproject(depth, data.cam_xpos[cam], data.cam_xmat[cam], float(model.cam_fovy[cam]))
    return Frames(rgb=rgb, depth=depth, segmentation=geom, points=pts)


def _cloud(pts: np.ndarray, bottom: float, max_points: int, rng: np.random.Generator) -> np.ndarray:
    """Subsample a visible cloud and close it down to ``bottom`` (m).

    The outline (convex hull of the xy, simplified to at most a quarter of
    ``max_points`` vertices, each an actual cloud point) is kept at its own
    height and repeated at ``bottom``; the rest of the budget goes to a random
    sample of the other points.
    """
    xy = pts[:, :2]
    hull = shapely.MultiPoint(xy).convex_hull
    ring = np.asarray(hull.exterior.coords)[:-1] if hull.geom_type == "Polygon" else xy
    tol = 2e-4
    while len(ring) > max_points // 4:
        ring = np.asarray(shapely.Polygon(ring).simplify(tol).exterior.coords)[:-1]
        tol *= 2
    # Douglas-Peucker keeps original vertices, so each is a cloud point.
    d = np.linalg.norm(xy[None, :, :] - ring[:, None, :], axis=2)
    outline = np.unique(d.argmin(axis=1))
    budget = max(max_points - 2 * len(outline), 0)
    rest = np.setdiff1d(np.arange(len(pts)), outline)
    extra = rng.choice(rest, size=min(budget, len(rest)), replace=False) if len(rest) else rest
    top = pts[np.concatenate([outline, np.sort(extra)])]
    base = pts[outline].copy()
    base[:, 2] = bottom
    return np.concatenate([top, base])


def drop_strays(points: np.ndarray, dist: float) -> np.ndarray:
    """``points`` without those that have no other point within ``dist`` (m)."""
    if len(points) < 2:
        return points
    from scipy.spatial import cKDTree

    d, _ = cKDTree(points).query(points, k=2)
    return points[d[:, 1] <= dist]


def observe(scene: SceneSpec | dict | str | Path, *, options: CameraOptions | None = None) -> SceneSpec:
    """Perceive ``scene`` with a simulated depth camera; objects become point clouds.

    Each object's id, name, colour and support (``on``) are the simulator's
    labels; its shape is the point cloud the camera saw (table frame, m),
    closed down to its support as described in the module docstring, with at
    most ``options.max_points`` points. Objects the camera sees in fewer than
    ``options.min_pixels`` pixels are left out (an object resting on one that
    is left out is then said to rest on that object's support).

    Raises
    ------
    InputError
        When the scene is malformed or no object at all can be seen.
    RuntimeError
        When offscreen rendering cannot start (no OpenGL backend).
    """
    opts = options or CameraOptions()
    spec = load_scene(scene) if not isinstance(scene, SceneSpec) else scene
    sc = Scene.from_spec(spec)
    sim = build_model(sc)
    data = mujoco.MjData(sim.model)
    clouds: dict[int, list[np.ndarray]] = {}
    with _open_renderer(sim.model, opts.height, opts.width) as r:
        for name in opts.cameras:
            try:
                sim.model.camera(name)
            except KeyError:
                raise InputError(f"unknown camera '{name}'") from None
            frames = render_frames(sim, data, camera=name, width=opts.width, height=opts.height, renderer=r)
            for k in range(sc.n):
                mask = frames.segmentation == sim.geom[k]
                if mask.any():
                    clouds.setdefault(k, []).append(frames.points[mask])
    rng = np.random.default_rng(opts.seed)
    fused = {k: drop_strays(np.concatenate(c), opts.stray_dist) for k, c in clouds.items()}
    seen = {k: p for k, p in fused.items() if len(p) >= opts.min_pixels}
    if not seen:
        raise InputError("the camera sees no object")
    state = sc.initial

    def support(k: int) -> int:
        s = state.on[k]
        while s != TABLE and s not in seen:
            s = state.on[s]
        return s

    top = {k: float(np.percentile(p[:, 2], 99)) for k, p in seen.items()}
    objects: list[dict[str, Any]] = []
    for k, o in enumerate(spec.objects):
        if k not in seen:
            continue
        s = support(k)
        bottom = 0.0 if s == TABLE else top[s]
        pts = seen[k]
        pts = pts[pts[:, 2] > bottom + 1e-4]
        if len(pts) < 3:
            continue
        cloud = _cloud(pts, bottom, opts.max_points, rng)
        objects.append(
            {
                "id": o.id,
                "name": o.name,
                "color": o.color,
                "shape": {"type": "points", "points": np.round(cloud, 5).tolist()},
                "on": None if s == TABLE else sc.ids[s],
            }
        )
    return parse_scene({"workspace": spec.workspace.model_dump(), "objects": objects})


def footprint_iou(
    true_scene: SceneSpec | dict | str | Path, observed_scene: SceneSpec | dict | str | Path
) -> dict[int, float]:
    """Intersection over union of each object's footprint in two scenes.

    Returns
    -------
    dict
        Object id to IoU in [0, 1], for every object of ``true_scene``; an
        object missing from ``observed_scene`` scores 0.
    """
    a = Scene.from_spec(load_scene(true_scene) if not isinstance(true_scene, SceneSpec) else true_scene)
    b = Scene.from_spec(load_scene(observed_scene) if not isinstance(observed_scene, SceneSpec) else observed_scene)
    out: dict[int, float] = {}
    for k, i in enumerate(a.ids):
        if i not in b.index:
            out[i] = 0.0
            continue
        p, q = a.initial.polys[k], b.initial.polys[b.index[i]]
        union = shapely.area(shapely.union(p, q))
        out[i] = float(shapely.area(shapely.intersection(p, q)) / union) if union > 0 else 0.0
    return out


class VideoRecorder:
    """Record an mp4 of a simulation, one frame per ``1/fps`` s of sim time.

    Use as a context manager; pass :meth:`capture` as the executor's
    per-step hook.

    Parameters
    ----------
    sim : the compiled scene model.
    path : the mp4 file to write.
    fps : frames per second of simulated time.
    width, height : frame size (pixels; multiples of 16 encode best).
    camera : name of the model camera to film from.
    """

    def __init__(
        self,
        sim: SimModel,
        path: str | Path,
        *,
        fps: int = 25,
        width: int = 640,
        height: int = 480,
        camera: str = VIEW_CAMERA,
    ):
        self.sim, self.path, self.fps = sim, Path(path), fps
        self.width, self.height = width, height
        self.camera = sim.model.camera(camera).id
        self.every = max(1, round(1.0 / (fps * sim.model.opt.timestep)))
        self._count = 0
        self._renderer: mujoco.Renderer | None = None
        self._writer: Any = None
        self._tmp: Path | None = None
        self.frames = 0

    def __enter__(self) -> VideoRecorder:
        import imageio.v2 as imageio

        from ..outputs import temporary_beside

        # The video is encoded into a temporary file beside the target, which
        # replaces the target only once it is complete (see __exit__).
        try:
            self._tmp = temporary_beside(self.path, suffix=".mp4")
            self._writer = imageio.get_writer(
                self._tmp, fps=self.fps, codec="libx264", macro_block_size=16, ffmpeg_log_level="quiet"
            )
        except Exception as exc:
            self._discard()
            raise InputError(f"cannot write video {self.path}: {_reason(exc)}") from None
        self._renderer = _open_renderer(self.sim.model, self.height, self.width)
        return self

    def capture(self, data: mujoco.MjData) -> None:
        """Per-step hook: render a frame every ``1/fps`` s of simulated time."""
        if self._count % self.every == 0:
            assert self._renderer is not None
            self._renderer.update_scene(data, camera=self.camera)
            try:
                self._writer.append_data(self._renderer.render())
            except Exception as exc:  # the encoder died: a full disk, a read-only folder
                raise InputError(f"cannot write video {self.path}: {_reason(exc)}") from None
            self.frames += 1
        self._count += 1

    def _discard(self) -> None:
        tmp = getattr(self, "_tmp", None)
        if tmp is not None:
            try:
                tmp.unlink()
            except OSError:
                pass
            self._tmp = None

    def __exit__(self, kind: object, *exc: object) -> None:
        """Close the encoder; publish the video only when it is complete.

        An encoder that failed (or a file that reads back with fewer frames
        than were captured) raises :class:`InputError` and leaves no video,
        so nothing reports success over a truncated file.
        """
        if self._renderer is not None:
            self._renderer.close()
        failure: str | None = None
        if self._writer is not None:
            try:
                self._writer.close()
            except Exception as err:
                failure = _reason(err)
        if kind is not None:
            self._discard()
            return
        if failure is None:
            failure = _incomplete(self._tmp, self.frames)
        if failure is None and self._tmp is None:
            failure = "the encoder wrote nothing"
        if failure is None and self._tmp is not None:
            from ..outputs import publish

            try:
                publish(self._tmp, self.path)
                self._tmp = None
            except OSError as err:
                failure = err.strerror or str(err)
        if failure is not None:
            self._discard()
            raise InputError(f"cannot write video {self.path}: {failure}")


def _reason(exc: BaseException) -> str:
    """The first line of an exception's text (the encoder's messages run over many lines)."""
    lines = [ln.strip() for ln in str(exc).splitlines() if ln.strip()]
    for ln in lines:
        if "No space left" in ln or "Permission denied" in ln or "Read-only" in ln or "File too large" in ln:
            return ln
    return lines[0] if lines else type(exc).__name__


def _incomplete(path: Path | None, frames: int) -> str | None:
    """Why the mp4 at ``path`` is not a complete video of ``frames`` frames, or ``None``."""
    import imageio_ffmpeg

    if path is None or frames == 0:
        return None if frames == 0 else "the encoder wrote nothing"
    try:
        counted, _ = imageio_ffmpeg.count_frames_and_secs(str(path))
    except Exception as exc:
        del exc
        return "the encoder left a truncated file (is the disk full?)"
    if counted < frames:
        return f"the video holds {counted} of {frames} frames"
    return None
