"""The three public JSON formats (scene, goals, plan) as validated models.

These models are the public contract documented in ``docs/formats.md``.
Lengths are metres, angles radians, in the table frame (+x right, +y away
from the viewer, +z up, yaw counter-clockwise about +z).

Every loader raises :class:`lgmcts.errors.InputError` with a one-line message
on bad input; nothing else escapes.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Annotated, Any, Literal

from pydantic import BaseModel, BeforeValidator, ConfigDict, Field, ValidationError, field_validator, model_validator

from . import limits
from .errors import InputError

if TYPE_CHECKING:  # at run time RELATIONS comes from __getattr__ below
    from .patterns.spatial import RELATIONS

__all__ = [
    "RELATIONS",
    "Action",
    "BoxShape",
    "CylinderShape",
    "Goal",
    "GoalSpec",
    "ObjectSpec",
    "PatternFormat",
    "PlanSpec",
    "PointsShape",
    "PolygonShape",
    "SceneSpec",
    "Workspace",
    "declare_pattern",
    "load_goals",
    "load_plan",
    "load_scene",
    "parse_goals",
    "parse_plan",
    "parse_scene",
    "pattern_format",
    "pattern_names",
    "save_json",
    "to_dict",
]

@dataclass(frozen=True)
class PatternFormat:
    """What the goal format asks of one pattern's goals.

    Attributes
    ----------
    name : the ``pattern`` value.
    min_objects : fewest objects a goal may list.
    anchor : the goal needs an ``anchor`` (and must not list it as an object).
    pose : the goal needs a ``pose`` and exactly one object.
    on_table : the goal's objects must end on the table (not stacked).
    size : the goal may carry a ``size`` (the pattern measures it, or, for a
        tower, accepts and ignores it).
    """

    name: str
    min_objects: int = 1
    anchor: bool = False
    pose: bool = False
    on_table: bool = True
    size: bool = False


_FORMATS: dict[str, PatternFormat] = {}


def declare_pattern(fmt: PatternFormat) -> PatternFormat:
    """Make ``fmt.name`` a pattern the goal format accepts.

    A module adding a pattern calls this once, with
    :func:`lgmcts.validate.register_rule` for its acceptance rule and
    :func:`lgmcts.patterns.register` for its prior. Declaring a name again
    with the same format is a no-op; with another format it is an error.
    """
    old = _FORMATS.get(fmt.name)
    if old is not None and old != fmt:
        raise ValueError(f"pattern '{fmt.name}' is already declared differently")
    _FORMATS[fmt.name] = fmt
    return fmt


def _builtins() -> dict[str, PatternFormat]:
    """The declared formats, the built-in patterns' among them: each built-in
    pattern module declares its own (through :func:`lgmcts.patterns.register`)
    when it is imported, which the first look-up here makes happen."""
    if not _BUILTINS_LOADED:
        _BUILTINS_LOADED.append(True)
        from .patterns.base import registry

        registry()
    return _FORMATS


_BUILTINS_LOADED: list[bool] = []


def pattern_format(name: str) -> PatternFormat | None:
    """The declared format of pattern ``name``, or ``None`` when unknown."""
    return _builtins().get(name)


def pattern_names() -> tuple[str, ...]:
    """Every pattern name the goal format accepts now, built-ins first."""
    return tuple(_builtins())


def __getattr__(name: str) -> Any:
    # RELATIONS (each spatial relation's unit direction in the table frame)
    # belongs to the relation patterns' module; it is read here for the
    # modules that have always imported it from the formats.
    if name == "RELATIONS":
        _builtins()  # every built-in module, in the registry's order
        from .patterns.spatial import RELATIONS

        return RELATIONS
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")


class _Model(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True)


def _finite(values: Any, what: str) -> None:
    for v in values:
        if not math.isfinite(float(v)):
            raise ValueError(f"{what} must be finite numbers")


def _bounded(values: Any, what: str, bound: float) -> None:
    """Finite and at most ``bound`` in absolute value (see :mod:`lgmcts.limits`)."""
    for v in values:
        f = float(v)
        if not math.isfinite(f):
            raise ValueError(f"{what} must be finite numbers")
        if abs(f) > bound:
            raise ValueError(f"{what} must lie within +-{bound:g}, got {f:g}")


def _lengths(values: Any, what: str) -> None:
    """Object lengths between :data:`~lgmcts.limits.MIN_LENGTH` and :data:`~lgmcts.limits.MAX_LENGTH` m."""
    for v in values:
        f = float(v)
        if not limits.MIN_LENGTH <= f <= limits.MAX_LENGTH:
            raise ValueError(f"{what} must lie between {limits.MIN_LENGTH:g} and {limits.MAX_LENGTH:g} m, got {f:g}")


def _pose_bounds(v: Any, what: str) -> None:
    """``[x, y, theta]``: x and y within MAX_COORD, theta within MAX_ANGLE."""
    _bounded(v[:2], what, limits.MAX_COORD)
    _bounded(v[2:], f"{what} yaw", limits.MAX_ANGLE)


def _json_int(v: Any) -> Any:
    # Ids are JSON integers: true, "1" and 1.0 are not ids.
    if isinstance(v, (bool, str, bytes, float)):
        raise ValueError(f"object ids must be JSON integers, got {limits.truncate(repr(v), 40)}")
    if isinstance(v, int) and abs(v) > limits.MAX_ID:
        raise ValueError(f"object ids must lie within +-{limits.MAX_ID}")
    return v


#: An object id: a JSON integer (``true``, ``"1"`` and ``1.0`` are refused).
ObjectId = Annotated[int, BeforeValidator(_json_int)]


def _json_number(v: Any) -> Any:
    # Lengths, coordinates and angles are JSON numbers: "0.25" and true are not.
    if isinstance(v, (bool, str, bytes)) or type(v).__name__ == "bool_":
        raise ValueError(f"expected a number, got {limits.truncate(repr(v), 40)}")
    return v


#: A JSON number (an integer or a float; ``"0.25"`` and ``true`` are refused).
Number = Annotated[float, BeforeValidator(_json_number)]


def _json_bool(v: Any) -> Any:
    if not isinstance(v, bool) and type(v).__name__ != "bool_":
        raise ValueError(f"expected true or false, got {limits.truncate(repr(v), 40)}")
    return v


#: A JSON boolean (``"yes"``, ``1`` and ``"true"`` are refused).
Flag = Annotated[bool, BeforeValidator(_json_bool)]


class BoxShape(_Model):
    """A box; ``size`` is its full extent along the object's x, y, z axes (m)."""

    type: Literal["box"]
    size: tuple[Number, Number, Number]

    @field_validator("size")
    @classmethod
    def _positive(cls, v: tuple[float, float, float]) -> tuple[float, float, float]:
        _finite(v, "box size")
        if min(v) <= 0:
            raise ValueError("box size must be positive")
        _lengths(v, "box size")
        return v


class CylinderShape(_Model):
    """An upright cylinder of ``radius`` and ``height`` (m)."""

    type: Literal["cylinder"]
    radius: Number
    height: Number

    @model_validator(mode="after")
    def _positive(self) -> CylinderShape:
        _finite((self.radius, self.height), "cylinder radius and height")
        if self.radius <= 0 or self.height <= 0:
            raise ValueError("cylinder radius and height must be positive")
        _lengths((self.radius, self.height), "cylinder radius and height")
        return self


class PolygonShape(_Model):
    """A convex footprint in the object frame, extruded to ``height`` (m)."""

    type: Literal["polygon"]
    points: list[tuple[Number, Number]] = Field(max_length=limits.MAX_POLYGON_POINTS)
    height: Number

    @model_validator(mode="after")
    def _convex(self) -> PolygonShape:
        _finite((c for p in self.points for c in p), "polygon points")
        _finite((self.height,), "polygon height")
        if self.height <= 0:
            raise ValueError("polygon height must be positive")
        _lengths((self.height,), "polygon height")
        _bounded((c for p in self.points for c in p), "polygon points", limits.MAX_LENGTH)
        if len(self.points) < 3:
            raise ValueError("a polygon needs at least 3 points")
        from shapely import MultiPoint

        hull = MultiPoint(self.points).convex_hull
        if hull.geom_type != "Polygon" or hull.area < 1e-8:
            raise ValueError("polygon points must enclose a positive area")
        return self


class PointsShape(_Model):
    """A point cloud in the table frame; footprint = convex hull of its xy."""

    type: Literal["points"]
    points: list[tuple[Number, Number, Number]] = Field(max_length=limits.MAX_CLOUD_POINTS)

    @model_validator(mode="after")
    def _enough(self) -> PointsShape:
        _finite((c for p in self.points for c in p), "cloud points")
        _bounded((c for p in self.points for c in p), "cloud points", limits.MAX_COORD)
        if len(self.points) < 3:
            raise ValueError("a point cloud needs at least 3 points")
        from shapely import MultiPoint

        hull = MultiPoint([(p[0], p[1]) for p in self.points]).convex_hull
        if hull.geom_type != "Polygon" or hull.area < 1e-8:
            raise ValueError("point cloud footprint must have a positive area")
        return self


Shape = Annotated[BoxShape | CylinderShape | PolygonShape | PointsShape, Field(discriminator="type")]


class ObjectSpec(_Model):
    """One object of a scene. ``pose`` is the footprint centre ``[x, y, theta]``."""

    id: ObjectId
    name: str = Field(max_length=limits.MAX_TEXT)
    color: str = Field("", max_length=limits.MAX_TEXT)
    shape: Shape
    pose: tuple[Number, Number, Number] | None = None
    on: ObjectId | None = None

    @field_validator("pose")
    @classmethod
    def _finite_pose(cls, v: tuple[float, float, float] | None) -> tuple[float, float, float] | None:
        if v is not None:
            _finite(v, "pose")
            _pose_bounds(v, "pose")
        return v

    @model_validator(mode="after")
    def _pose_needed(self) -> ObjectSpec:
        if self.pose is None and self.shape.type != "points":
            raise ValueError("pose is required unless the shape is a point cloud")
        return self


class Workspace(_Model):
    """The rectangle of the table the robot may place objects in (m)."""

    x: tuple[Number, Number]
    y: tuple[Number, Number]

    @model_validator(mode="after")
    def _ordered(self) -> Workspace:
        _finite((*self.x, *self.y), "workspace bounds")
        _bounded((*self.x, *self.y), "workspace bounds", limits.MAX_COORD)
        if not (self.x[0] < self.x[1] and self.y[0] < self.y[1]):
            raise ValueError("workspace bounds must be [min, max] with min < max")
        return self


def _acyclic(support: dict[int, int | None]) -> None:
    """Raise when the ``on`` relations form a cycle; linear in the number of objects.

    Each object is walked at most once: a walk stops at an object already
    known to rest (through its chain) on the table.
    """
    grounded: set[int] = set()
    for start in support:
        path: list[int] = []
        on_path: set[int] = set()
        cur: int | None = start
        while cur is not None and cur not in grounded:
            if cur in on_path:
                raise ValueError(f"cycle in 'on' relations through object {cur}")
            path.append(cur)
            on_path.add(cur)
            cur = support[cur]
        grounded.update(path)


def _on_cycle(edges: dict[int, Any]) -> int | None:
    """An object on a cycle of the directed graph ``edges`` (``node -> successors``), or ``None``.

    One iterative depth-first search over all nodes: linear in nodes plus edges.
    """
    state: dict[int, int] = {}  # 1: on the current path, 2: done
    for root in sorted(edges):
        if root in state:
            continue
        state[root] = 1
        stack = [(root, iter(sorted(edges.get(root, ()))))]
        while stack:
            node, it = stack[-1]
            nxt = next(it, None)
            if nxt is None:
                state[node] = 2
                stack.pop()
            elif state.get(nxt) == 1:
                return nxt
            elif nxt not in state:
                state[nxt] = 1
                stack.append((nxt, iter(sorted(edges.get(nxt, ())))))
    return None


class SceneSpec(_Model):
    """A tabletop scene: the workspace and its objects."""

    workspace: Workspace
    objects: list[ObjectSpec] = Field(max_length=limits.MAX_OBJECTS)

    @model_validator(mode="after")
    def _consistent(self) -> SceneSpec:
        ids = [o.id for o in self.objects]
        seen: set[int] = set()
        for i in ids:
            if i in seen:
                raise ValueError(f"duplicate object id {i}")
            seen.add(i)
        support = {o.id: o.on for o in self.objects}
        for o in self.objects:
            if o.on is not None and o.on not in seen:
                raise ValueError(f"object {o.id} is on unknown object {o.on}")
            if o.on == o.id:
                raise ValueError(f"object {o.id} is on itself")
        _acyclic(support)
        return self

    def object(self, object_id: int) -> ObjectSpec:
        for o in self.objects:
            if o.id == object_id:
                return o
        raise InputError(f"unknown object id {object_id}")


class Goal(_Model):
    """One pattern goal over a set of objects.

    ``region``, ``size`` and ``facing`` are optional parameters (where the
    objects go, how big the arrangement is, which way it faces); their
    meaning and tolerances are defined in :mod:`lgmcts.params`.
    """

    pattern: str = Field(max_length=limits.MAX_TEXT)
    objects: list[ObjectId] = Field(max_length=limits.MAX_OBJECTS)
    anchor: ObjectId | None = None
    pose: tuple[Number, Number, Number] | None = None
    region: str | tuple[float, float, float, float] | None = None
    size: str | float | None = None
    facing: str | float | None = None

    @field_validator("region", "size", "facing", mode="before")
    @classmethod
    def _param_value(cls, v: Any, info: Any) -> Any:
        if isinstance(v, bool):
            raise ValueError(f"'{info.field_name}' must be a name or a number, not true/false")
        if isinstance(v, str):
            return " ".join(v.lower().split())
        if info.field_name == "region" and v is not None:
            if not isinstance(v, (list, tuple)) or len(v) != 4 or not all(
                    isinstance(c, (int, float)) and not isinstance(c, bool) for c in v):
                raise ValueError("a region is a name such as 'top left' or a box [xmin, xmax, ymin, ymax]")
            _bounded(v, "region box", limits.MAX_COORD)
        elif v is not None and not isinstance(v, (int, float)):
            raise ValueError(f"'{info.field_name}' must be a name or a number")
        elif info.field_name == "facing" and v is not None:
            _bounded((v,), "facing", limits.MAX_ANGLE)
        elif info.field_name == "size" and v is not None:
            _bounded((v,), "size", limits.MAX_COORD)
        return v

    def _check_params(self, fmt: PatternFormat) -> None:
        from . import params as gp

        p = self.pattern
        given = [k for k in ("region", "size", "facing") if getattr(self, k) is not None]
        if given and fmt.pose:
            raise ValueError(f"a {p} goal takes no '{given[0]}' (its pose says where)")
        if self.region is not None:
            gp.region_box(self.region, (0.0, 1.0, 0.0, 1.0))
        if self.size is not None:
            if not fmt.size:
                raise ValueError(f"a {p} goal takes no 'size'")
            if isinstance(self.size, str):
                if self.size not in gp.SIZES:
                    raise ValueError(f"unknown size '{self.size}' (small|medium|large or a length in metres)")
            elif not (math.isfinite(self.size) and self.size > 0):
                raise ValueError("a size in metres must be a positive number")
        if self.facing is not None:
            gp.heading_of(self.facing)

    @model_validator(mode="after")
    def _shape(self) -> Goal:
        p = self.pattern
        fmt = pattern_format(p)
        if fmt is None:
            raise ValueError(f"unknown pattern '{p}' (known: {', '.join(pattern_names())})")
        if len(set(self.objects)) != len(self.objects):
            raise ValueError(f"{p} goal lists an object twice")
        n = len(self.objects)
        if fmt.anchor:
            if self.anchor is None:
                raise ValueError(f"{p} goal needs an 'anchor'")
            if n < 1:
                raise ValueError(f"{p} goal needs at least one object")
            if self.anchor in self.objects:
                raise ValueError(f"{p} goal: anchor {self.anchor} is also one of its objects")
        elif self.anchor is not None:
            raise ValueError(f"{p} goal takes no 'anchor'")
        if fmt.pose:
            if self.pose is None or n != 1:
                raise ValueError(f"{p} goal needs exactly one object and a 'pose'")
            _finite(self.pose, "goal pose")
            _pose_bounds(self.pose, "goal pose")
        elif self.pose is not None:
            raise ValueError(f"{p} goal takes no 'pose'")
        self._check_params(fmt)
        need = fmt.min_objects
        if n < need:
            noun = "object" if n == 1 else "objects"
            raise ValueError(f"a {p} needs at least {need} objects, got {n} {noun}")
        return self


class GoalSpec(_Model):
    """A list of pattern goals; every one must hold at the end of the plan."""

    goals: list[Goal] = Field(max_length=limits.MAX_GOALS)

    def check_against(self, scene: SceneSpec) -> None:
        """Raise :class:`InputError` when a goal cannot refer to ``scene``."""
        if not self.goals:
            raise InputError("the goal list is empty")
        self._check_references(scene)
        from .params import conflict

        why = conflict(self.goals, (*scene.workspace.x, *scene.workspace.y))
        if why is not None:
            raise InputError(why)
        self._check_fixed_poses()
        below = self._check_towers()
        self._check_relations()
        for g in self.goals:
            if _builtins()[g.pattern].on_table:
                for o in g.objects:
                    if o in below:
                        raise InputError(
                            f"object {o} must be on the table for its {g.pattern} goal but on object {below[o]} "
                            "for a tower"
                        )

    def _check_references(self, scene: SceneSpec) -> None:
        """Every named object is in the scene; every region box meets the workspace."""
        ids = {o.id for o in scene.objects}
        for k, g in enumerate(self.goals):
            for i in [*g.objects, *([g.anchor] if g.anchor is not None else [])]:
                if i not in ids:
                    raise InputError(f"goal {k} ({g.pattern}) names unknown object id {i}")
            if isinstance(g.region, tuple):
                ws = scene.workspace
                x0, x1, y0, y1 = g.region
                if x1 <= ws.x[0] or x0 >= ws.x[1] or y1 <= ws.y[0] or y0 >= ws.y[1]:
                    raise InputError(f"goal {k} ({g.pattern}): region box {list(g.region)} lies outside the workspace")

    def _check_fixed_poses(self) -> None:
        """A pose goal and another fixed pose for the same object contradict."""
        fixed: dict[int, tuple[float, float, float] | None] = {}
        for g in self.goals:
            if g.pattern == "pose":
                o = g.objects[0]
                if o in fixed and fixed[o] != g.pose:
                    raise InputError(f"object {o} has two different pose goals")
                fixed[o] = g.pose

    def _check_towers(self) -> dict[int, int]:
        """Tower order must not contradict itself or put an object on itself;
        returns the object each tower member rests on."""
        below: dict[int, int] = {}
        for g in self.goals:
            if g.pattern == "tower":
                for a, b in zip(g.objects, g.objects[1:]):
                    if b in below and below[b] != a:
                        raise InputError(f"object {b} must rest on both {below[b]} and {a}")
                    below[b] = a
        on_cycle = _on_cycle({b: (a,) for b, a in below.items()})
        if on_cycle is not None:
            raise InputError(f"tower goals form a cycle through object {on_cycle}")
        return below

    def _check_relations(self) -> None:
        """Relations among the same goal objects must not form a cycle of dependencies."""
        dep: dict[int, set[int]] = {}
        for g in self.goals:
            if g.anchor is not None:
                for o in g.objects:
                    dep.setdefault(o, set()).add(g.anchor)
        on_cycle = _on_cycle(dep)
        if on_cycle is not None:
            raise InputError(f"spatial relations form a cycle through object {on_cycle}")


class Action(_Model):
    """Pick ``object`` and place it at ``to`` on the table or on object ``on``."""

    object: ObjectId
    to: tuple[Number, Number, Number]
    on: ObjectId | None = None
    purpose: Literal["goal", "relocate", "unstack"] = "goal"

    @field_validator("to")
    @classmethod
    def _finite_to(cls, v: tuple[float, float, float]) -> tuple[float, float, float]:
        _finite(v, "action pose")
        _pose_bounds(v, "action pose")
        return v


class PlanSpec(_Model):
    """A plan: the actions, whether they solve the goals, and search statistics."""

    model_config = ConfigDict(extra="allow", frozen=True)

    solved: Flag
    actions: list[Action] = Field(max_length=limits.MAX_ACTIONS)
    goals: GoalSpec | None = None
    stats: dict[str, Any] = Field(default_factory=dict)
    #: Per goal, its pattern's parameters fitted to the plan's final state
    #: (docs/formats.md, "Plan"); ``None`` for a goal whose pattern fits none.
    fits: list[dict[str, Any] | None] | None = None


def _one_line(err: ValidationError, what: str) -> str:
    first = err.errors()[0]
    loc = ".".join(str(x) for x in first.get("loc", ()) if not isinstance(x, str) or not x.startswith("function-"))
    msg = first.get("msg", "invalid value")
    msg = limits.truncate(msg.removeprefix("Value error, "), 300)
    where = f" at {limits.truncate(loc, 120)}" if loc else ""
    return f"invalid {what}{where}: {msg}"


def _read(source: Any, what: str) -> Any:
    if isinstance(source, (dict, list, BaseModel)):
        return source
    from . import inputs

    path = Path(source)
    text = inputs.read_text(path, what)
    try:
        return inputs.loads(text, f"{what} file {path}")
    except json.JSONDecodeError as exc:
        raise InputError(f"{what} file {path} is not valid JSON: {exc.msg} (line {exc.lineno})") from None


def parse_scene(data: Any) -> SceneSpec:
    """Validate a scene given as a dict (or a ``SceneSpec``)."""
    if isinstance(data, SceneSpec):
        return data
    try:
        return SceneSpec.model_validate(data)
    except ValidationError as err:
        raise InputError(_one_line(err, "scene")) from None


def parse_goals(data: Any) -> GoalSpec:
    """Validate a goal specification given as a dict or a list of goals."""
    if isinstance(data, GoalSpec):
        return data
    if isinstance(data, list):
        data = {"goals": data}
    try:
        return GoalSpec.model_validate(data)
    except ValidationError as err:
        raise InputError(_one_line(err, "goals")) from None


def parse_plan(data: Any) -> PlanSpec:
    """Validate a plan given as a dict."""
    if isinstance(data, PlanSpec):
        return data
    try:
        return PlanSpec.model_validate(data)
    except ValidationError as err:
        raise InputError(_one_line(err, "plan")) from None


def load_scene(source: str | Path | dict | SceneSpec) -> SceneSpec:
    """Read and validate a scene JSON file (or dict)."""
    return parse_scene(_read(source, "scene"))


def load_goals(source: str | Path | dict | list | GoalSpec) -> GoalSpec:
    """Read and validate a goal JSON file (or dict)."""
    return parse_goals(_read(source, "goals"))


def load_plan(source: str | Path | dict | PlanSpec) -> PlanSpec:
    """Read and validate a plan JSON file (or dict)."""
    return parse_plan(_read(source, "plan"))


def to_dict(model: BaseModel) -> dict:
    """JSON-ready dict of a format model; goals omit their unused keys."""
    data = model.model_dump(mode="json")

    def clean(goals: dict | None) -> None:
        if goals:
            goals["goals"] = [{k: v for k, v in g.items() if v is not None} for g in goals["goals"]]

    if isinstance(model, GoalSpec):
        clean(data)
    elif isinstance(model, PlanSpec):
        clean(data.get("goals"))
    return data


def save_json(model: BaseModel, path: str | Path | None = None, *, indent: int = 2) -> str:
    """Serialise any of the format models; write it to ``path`` when given."""
    text = json.dumps(to_dict(model), indent=indent)
    if path is not None:
        Path(path).write_text(text + "\n")
    return text
