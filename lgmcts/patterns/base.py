"""The pattern protocol, the per-goal search progress and the registry.

A pattern is a parametric geometric prior (paper, "Parametric Geometric
Prior"): given the objects of its goal already placed in the current search
branch, it proposes poses for the next object (``sample``), tells where that
next object may go (``density``, the support of f_prior used for products of
priors and for pictures) and records what a placement fixes (``commit``: the
curve parameters kappa). Each pattern lives in its own module and registers
itself here; adding a pattern means adding a module.
"""

from __future__ import annotations

import importlib
import pkgutil
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, ClassVar, Protocol

import numpy as np
import shapely

from ..geometry import wrap_angle
from ..params import GoalParams
from ..params import resolve as resolve_params
from ..scene import TABLE, Scene, State

__all__ = [
    "BAND",
    "CLEARANCE",
    "EDGE_EPS",
    "MODULES_ENV",
    "CompiledGoal",
    "Context",
    "GoalProgress",
    "Pattern",
    "compile_params",
    "load_pattern_modules",
    "register",
    "registry",
]

#: Gap kept between footprints by the planner (m); the validator only
#: requires no overlap, so this margin absorbs rounding.
CLEARANCE = 0.002
#: Half-width of the band around a fitted curve that the planner samples in
#: (m); well inside the validator's 0.015 m tolerance.
BAND = 0.004
#: Slack on the edges of a prior's support (m or rad), so that a sample
#: clipped exactly to an edge is not lost to floating-point rounding.
EDGE_EPS = 1e-9


@dataclass(frozen=True)
class CompiledGoal:
    """A goal with object ids replaced by scene indices; ``params`` are its
    region, size and facing in numbers (:func:`compile_params`)."""

    k: int
    pattern: str
    objects: tuple[int, ...]
    anchor: int | None = None
    pose: tuple[float, float, float] | None = None
    params: GoalParams = field(default_factory=GoalParams)


#: How far the priors let centres go outside a goal's region box (m), a
#: third of the validator's 0.015 m tolerance: small regions hold more.
REGION_SLACK = 0.005


def compile_params(goal: Any, scene: Scene) -> GoalParams:
    """A format goal's region, size and facing resolved for ``scene``, as the
    priors use them (the region box grown by :data:`REGION_SLACK`)."""
    gp = resolve_params(goal, scene.bounds, scene.radii[[scene.index[i] for i in goal.objects]].tolist())
    if gp.box is not None:
        x0, x1, y0, y1 = gp.box
        e = REGION_SLACK
        gp = replace(gp, box=(x0 - e, x1 + e, y0 - e, y1 + e))
    return gp


@dataclass(frozen=True)
class GoalProgress:
    """What one search branch has fixed for one goal.

    ``placed`` are the object indices committed so far in commit order,
    ``slots`` their slot numbers (pattern-specific, -1 when unused), and
    ``params`` the curve parameters kappa once they are known: the pattern
    module's frozen record (``LineParams``, ``CircleParams``,
    ``RectangleParams``), the same type its ``fit`` returns.
    """

    placed: tuple[int, ...] = ()
    slots: tuple[int, ...] = ()
    params: Any = None

    def add(self, obj: int, slot: int = -1, params: Any = None) -> GoalProgress:
        return GoalProgress((*self.placed, obj), (*self.slots, slot), self.params if params is None else params)

    def without(self, obj: int) -> GoalProgress:
        if obj not in self.placed:
            return self
        keep = [(o, s) for o, s in zip(self.placed, self.slots) if o != obj]
        if not keep:
            return GoalProgress()
        placed, slots = zip(*keep)
        return replace(self, placed=tuple(placed), slots=tuple(slots))


@dataclass(frozen=True)
class Context:
    """Everything a pattern may look at when proposing a pose."""

    scene: Scene
    state: State
    goal: CompiledGoal
    progress: GoalProgress

    @property
    def n(self) -> int:
        return len(self.goal.objects)

    def radius(self, i: int) -> float:
        return float(self.scene.radii[i])

    @property
    def max_radius(self) -> float:
        return float(max(self.scene.radii[list(self.goal.objects)]))


class Pattern(Protocol):
    """What every pattern module provides.

    Attributes
    ----------
    name : pattern name used in the goal format.
    keys : phrases that name the pattern in language (its Sentence-BERT keys).
    description : one sentence meaning, shown to language models.
    min_objects : fewest objects a goal of this pattern may have.
    ordered : whether objects must be placed in list order (tower) or after
        an anchor (relations).
    on_table : whether the goal's objects must end on the table.
    anchored : whether a goal names an ``anchor`` (relations).
    needs_pose : whether a goal gives a ``pose`` (and one object).
    size_word : what a goal's ``size`` measures ("radius", "length"...), or
        ``None`` when the pattern has no size of its own; a pattern with one
        also defines ``size`` (the measure) and ``size_band`` (the lengths
        small, medium and large divide).
    size_ignored : a goal may carry a ``size`` that the pattern ignores (a
        tower, whose footprint is its base object's).
    deterministic : whether ``sample`` returns the same poses whatever the
        branch and the random generator (a fixed target), and ``region`` the
        same region for as long as the goal is unfinished; the planner may
        then remember what blocks such an object, and the region.
    """

    @property
    def name(self) -> str: ...

    @property
    def keys(self) -> tuple[str, ...]: ...

    @property
    def description(self) -> str: ...

    @property
    def min_objects(self) -> int: ...

    @property
    def ordered(self) -> bool: ...

    @property
    def on_table(self) -> bool: ...

    @property
    def size_word(self) -> str | None: ...

    def ready(self, ctx: Context, obj: int, settled: frozenset[int]) -> bool:
        """Whether ``obj`` may be placed now (order constraints)."""

    def support(self, ctx: Context, obj: int) -> int:
        """Index of the object ``obj`` must rest on, or ``TABLE``."""

    def sample(self, ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
        """``(n, 3)`` candidate poses for ``obj`` from f_prior (may be fewer rows)."""

    def density(self, ctx: Context, obj: int, poses: np.ndarray) -> np.ndarray:
        """f_prior at ``(m, 3)`` poses for ``obj``: ``(m,)`` floats, 0 outside the support."""

    def commit(self, ctx: Context, obj: int, pose: np.ndarray, rng: np.random.Generator) -> GoalProgress:
        """Progress after placing ``obj`` at ``pose``."""

    def region(self, ctx: Context) -> Any:
        """Shapely geometry where the unplaced objects will go, or ``None`` if unknown."""

    def rank(self, goal: CompiledGoal, progress: GoalProgress, obj: int) -> int:
        """Order among the priors ``obj`` is in: the lowest ranked samples, the others filter."""

    def recover(
        self, goal: CompiledGoal, placed: tuple[int, ...], poses: np.ndarray, final: np.ndarray
    ) -> GoalProgress:
        """The search progress of ``goal`` whose ``placed`` objects stand at
        ``poses``, in a plan that ends at ``final`` (plans do not record kappa;
        the pose-field pictures rebuild it from the plan)."""

    def fit(self, xy: np.ndarray) -> Any:
        """The pattern's parameter record fitted to final centres ``(n, 2)``
        (a frozen dataclass of floats, or ``None`` when there is nothing to fit)."""

    def accept(self, goal: Any, scene: Scene, poses: np.ndarray, on: tuple[int, ...]) -> str | None:
        """The acceptance rule: ``None`` when ``goal`` (a format goal) holds for
        ``poses``/``on``, else why not. The on-table requirement is checked before."""

    def shape(self, goal: Any, scene: Scene, poses: np.ndarray) -> tuple[str, dict]:
        """What to draw for ``goal`` at ``poses``: a kind and its geometry (see
        :class:`lgmcts.viz.model.GoalShape`)."""

    def describe(self, goal: Any) -> str:
        """A few words for a format goal, as pictures and the viewer list it."""

    def draw(self, fitted: dict) -> tuple[str, dict] | None:
        """What to draw from a fitted record in its JSON form (as plans carry
        it, :func:`fit_json`), or ``None`` when the record alone does not say."""

    def size(self, fitted: Any) -> float:
        """The characteristic length a goal's ``size`` is compared with (m)."""

    def size_band(
        self, n: int, rmax: float, room: tuple[float, float, float, float], heading: float | None
    ) -> tuple[float, float]:
        """``(L_min, L_max)``: the shortest and longest characteristic length
        (m) of ``n`` objects of largest circumradius ``rmax`` whose centres
        lie in ``room`` (``xmin, xmax, ymin, ymax``), for a facing ``heading``
        (rad) or none; :func:`lgmcts.params.size_range` splits it into the
        named sizes."""

    def facing_axis(self, fitted: Any) -> tuple[float, float, str] | None:
        """The arrangement's own direction for a ``facing``: ``(angle, period,
        what)``, the angle compared with the heading modulo ``period``, or ``None``."""


_REGISTRY: dict[str, Pattern] = {}


def register(pattern: Pattern) -> Pattern:
    """Add a pattern instance to the database (keyed by its name).

    This one call is all a pattern module makes: it declares the pattern in
    the goal format (from ``min_objects``, ``anchored``, ``needs_pose`` and
    ``on_table``), gives the validator its rule (``accept``), the pictures its
    shape and the language parser its keys (read from this registry).
    """
    from ..formats import PatternFormat, declare_pattern

    declare_pattern(
        PatternFormat(
            pattern.name,
            min_objects=pattern.min_objects,
            anchor=bool(getattr(pattern, "anchored", False)),
            pose=bool(getattr(pattern, "needs_pose", False)),
            on_table=pattern.on_table,
            size=getattr(pattern, "size_word", None) is not None or bool(getattr(pattern, "size_ignored", False)),
        )
    )
    _REGISTRY[pattern.name] = pattern
    return pattern


def registry() -> dict[str, Pattern]:
    """All registered patterns by name (importing every built-in module: each
    module of this package but this one registers its patterns on import)."""
    if not _BUILTINS_IMPORTED:
        _BUILTINS_IMPORTED.append(True)
        for m in sorted(pkgutil.iter_modules(_package_path()), key=lambda m: m.name):
            if m.name != "base":
                importlib.import_module(f"{__package__}.{m.name}")
    return dict(_REGISTRY)


_BUILTINS_IMPORTED: list[bool] = []


def _package_path() -> list[str]:
    return [str(Path(__file__).resolve().parent)]


#: Environment variable naming pattern modules to import (separated by the
#: platform's path separator, ``:`` on Linux): module names or ``.py`` files.
MODULES_ENV = "LGMCTS_PATTERN_MODULES"


def load_pattern_modules(specs: str | list[str] | tuple[str, ...] | None = None) -> list[str]:
    """Import pattern modules that live outside the package.

    Each entry is an importable module name (``mylab.patterns.zigzag``) or
    the path of a ``.py`` file; with ``specs=None`` the entries come from
    :data:`MODULES_ENV`. Importing a module is what registers its pattern.
    Returns the module names loaded; a module that cannot be found or fails
    to import is an :class:`~lgmcts.errors.InputError` with one line.
    """
    import importlib
    import importlib.util
    import os
    import sys
    from pathlib import Path

    from ..errors import InputError

    if specs is None:
        specs = os.environ.get(MODULES_ENV, "")
    if isinstance(specs, str):
        specs = [s for s in specs.split(os.pathsep) if s.strip()]
    loaded = []
    for spec in specs:
        spec = spec.strip()
        try:
            if spec.endswith(".py") or os.sep in spec:
                path = Path(spec)
                if not path.is_file():
                    raise InputError(f"pattern module {spec}: no such file")
                name = f"lgmcts_pattern_{path.stem}"
                if name not in sys.modules:
                    mspec = importlib.util.spec_from_file_location(name, path)
                    mod = importlib.util.module_from_spec(mspec)  # type: ignore[arg-type]
                    sys.modules[name] = mod
                    try:
                        mspec.loader.exec_module(mod)  # type: ignore[union-attr]
                    except BaseException:
                        sys.modules.pop(name, None)
                        raise
            else:
                name = spec
                importlib.import_module(spec)
        except InputError:
            raise
        except SystemExit as exc:
            # A module must not end the program (least of all with status 0, "valid").
            raise InputError(f"pattern module {spec} failed to load: it called sys.exit({exc.code!r})") from None
        except Exception as exc:
            raise InputError(f"pattern module {spec} failed to load: {type(exc).__name__}: {exc}") from None
        loaded.append(name)
    return loaded


# ---------------------------------------------------------------- helpers


def uniform_poses(scene: Scene, obj: int, rng: np.random.Generator, n: int, margin: float = 0.0) -> np.ndarray:
    """``(n, 3)`` poses uniform over the workspace shrunk by the object's radius."""
    xmin, xmax, ymin, ymax = scene.bounds
    r = float(scene.radii[obj]) + margin
    lo_x, hi_x = xmin + r, xmax - r
    lo_y, hi_y = ymin + r, ymax - r
    if lo_x > hi_x:
        lo_x = hi_x = (xmin + xmax) / 2
    if lo_y > hi_y:
        lo_y = hi_y = (ymin + ymax) / 2
    out = np.empty((n, 3))
    out[:, 0] = rng.uniform(lo_x, hi_x, n)
    out[:, 1] = rng.uniform(lo_y, hi_y, n)
    out[:, 2] = rng.uniform(-np.pi, np.pi, n)
    return out


#: Share of a facing's tolerance within which the priors let an object that
#: already stands there keep its yaw; new placements take the heading exactly.
YAW_SHARE = 0.5


def room(ctx: Context, obj: int, margin: float = 0.0) -> tuple[float, float, float, float]:
    """Box where ``obj``'s centre may go: the workspace shrunk by its radius
    (plus ``margin``), cut to the goal's region. Empty when min > max."""
    xmin, xmax, ymin, ymax = ctx.scene.bounds
    r = float(ctx.scene.radii[obj]) + margin
    box = (xmin + r, xmax - r, ymin + r, ymax - r)
    reg = ctx.goal.params.box
    if reg is not None:
        box = (max(box[0], reg[0]), min(box[1], reg[1]), max(box[2], reg[2]), min(box[3], reg[3]))
    return box


def start_poses(ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
    """``(n, 3)`` poses for a goal's first object: uniform over the workspace
    (as :func:`uniform_poses`) or, with a region, over the part of it that
    ``obj`` fits in; the yaw is the goal's heading when it has one."""
    gp = ctx.goal.params
    if gp.box is None:
        out = uniform_poses(ctx.scene, obj, rng, n)
    else:
        x0, x1, y0, y1 = room(ctx, obj)
        if x0 > x1 or y0 > y1:
            return np.empty((0, 3))
        out = np.column_stack([rng.uniform(x0, x1, n), rng.uniform(y0, y1, n), rng.uniform(-np.pi, np.pi, n)])
    return with_heading(ctx, out)


def with_heading(ctx: Context, poses: np.ndarray) -> np.ndarray:
    """``poses`` with their yaw set to the goal's heading, when it has one."""
    h = ctx.goal.params.heading
    if h is not None and len(poses):
        poses = np.array(poses, dtype=float)
        poses[:, 2] = h
    return poses


def params_mask(ctx: Context, obj: int, poses: np.ndarray) -> np.ndarray:
    """Whether each of ``(m, 3)`` poses keeps ``obj`` in the goal's region
    (centre in the box) and facing its heading (yaw within :data:`YAW_SHARE`
    of the facing's tolerance: pi/16 for a named facing, 0.05 rad for an angle)."""
    poses = np.asarray(poses, dtype=float).reshape(-1, 3)
    gp = ctx.goal.params
    ok = np.ones(len(poses), dtype=bool)
    if gp.box is not None:
        x0, x1, y0, y1 = gp.box
        e = EDGE_EPS
        ok &= (poses[:, 0] >= x0 - e) & (poses[:, 0] <= x1 + e) & (poses[:, 1] >= y0 - e) & (poses[:, 1] <= y1 + e)
    if gp.heading is not None:
        d = np.abs(wrap_angle(poses[:, 2] - gp.heading))
        ok &= d <= YAW_SHARE * gp.heading_tol
    return ok


def box_region(ctx: Context) -> Any:
    """The goal's region box as a shapely polygon (``None`` without one)."""
    reg = ctx.goal.params.box
    if reg is None:
        return None
    return shapely.box(reg[0], reg[2], reg[1], reg[3])


@dataclass(frozen=True)
class BasePattern:
    """Defaults shared by the pattern classes."""

    name: ClassVar[str] = ""
    keys: ClassVar[tuple[str, ...]] = ()
    description: ClassVar[str] = ""
    min_objects: ClassVar[int] = 1
    ordered: ClassVar[bool] = False
    on_table: ClassVar[bool] = True
    anchored: ClassVar[bool] = False
    needs_pose: ClassVar[bool] = False
    size_word: ClassVar[str | None] = None
    size_ignored: ClassVar[bool] = False
    deterministic: ClassVar[bool] = False

    def ready(self, ctx: Context, obj: int, settled: frozenset[int]) -> bool:
        return True

    def support(self, ctx: Context, obj: int) -> int:
        return TABLE

    def region(self, ctx: Context) -> Any:
        return None

    def _density(self, ctx: Context, obj: int, poses: np.ndarray) -> np.ndarray:
        """f_prior of the pattern alone (before a goal's region and facing narrow it)."""
        raise NotImplementedError(f"pattern '{self.name}' defines neither density nor _density")

    def density(self, ctx: Context, obj: int, poses: np.ndarray) -> np.ndarray:
        # A pattern may define only _density (its own support); a goal's
        # region and facing then narrow it here.
        poses = np.asarray(poses, dtype=float).reshape(-1, 3)
        if ctx.goal.params.empty:
            return self._density(ctx, obj, poses)
        return self._density(ctx, obj, poses) * params_mask(ctx, obj, poses)

    def rank(self, goal: CompiledGoal, progress: GoalProgress, obj: int) -> int:
        # Priors whose kappa is fixed sample best, then relations, then the rest.
        if progress.params is not None:
            return 2
        return 3 if goal.anchor is not None else 4

    def recover(
        self, goal: CompiledGoal, placed: tuple[int, ...], poses: np.ndarray, final: np.ndarray
    ) -> GoalProgress:
        return GoalProgress(tuple(placed), tuple(-1 for _ in placed), None)

    def fit(self, xy: np.ndarray) -> Any:
        return None

    def accept(self, goal: Any, scene: Scene, poses: np.ndarray, on: tuple[int, ...]) -> str | None:
        from ..errors import InputError

        raise InputError(f"pattern '{self.name}' has no acceptance rule (define accept in its module)")

    def shape(self, goal: Any, scene: Scene, poses: np.ndarray) -> tuple[str, dict]:
        return "points", {"points": goal_xy(goal, scene, poses)}

    def draw(self, fitted: dict) -> tuple[str, dict] | None:
        return None

    def describe(self, goal: Any) -> str:
        """A few words for ``goal`` (a format goal): ``"circle of 1, 2, 3"``."""
        return f"{self.name} of " + ", ".join(str(i) for i in goal.objects)

    def size(self, fitted: Any) -> float:
        raise NotImplementedError(f"pattern '{self.name}' has no size")

    def size_band(
        self, n: int, rmax: float, room: tuple[float, float, float, float], heading: float | None
    ) -> tuple[float, float]:
        raise NotImplementedError(f"pattern '{self.name}' has no size")

    def facing_axis(self, fitted: Any) -> tuple[float, float, str] | None:
        return None


def fit_json(fitted: Any) -> dict | None:
    """A fitted record (a frozen dataclass of numbers and tuples) as JSON-ready
    lists and floats, or ``None`` when there is none or it is not finite."""
    import dataclasses

    if fitted is None or not dataclasses.is_dataclass(fitted):
        return None

    def conv(v: Any) -> Any:
        if isinstance(v, (tuple, list, np.ndarray)):
            return [conv(x) for x in v]
        if isinstance(v, (bool, np.bool_)):
            return bool(v)
        if isinstance(v, (int, np.integer)):
            return int(v)
        if isinstance(v, (float, np.floating)):
            if not np.isfinite(v):
                raise ValueError
            return float(v)
        return v

    try:
        return {f.name: conv(getattr(fitted, f.name)) for f in dataclasses.fields(fitted)}
    except ValueError:
        return None


def goal_xy(goal: Any, scene: Scene, poses: np.ndarray) -> np.ndarray:
    """``(n, 2)`` centres of a format goal's objects at ``poses``."""
    return np.asarray(poses[[scene.index[i] for i in goal.objects], :2], dtype=float)


def wrap_off(a: float, b: float, period: float) -> float:
    """Distance between angles ``a`` and ``b`` modulo ``period`` (rad)."""
    d = (a - b) % period
    return min(d, period - d)
