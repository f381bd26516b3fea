"""Spatial relations: each object in one direction from an anchor object.

Ordered: the objects are placed after their anchor has settled. The prior is
a sector around the relation's direction (narrower than the 45 degree
acceptance half-angle) between touching distance and 0.29 m, cut to the
goal's region when it has one; a facing sets the objects' yaw.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import shapely

from ..geometry import wrap_angle
from ..tolerances import MAX_RELATION_DIST, RELATION_HALF_ANGLE
from .base import CLEARANCE, BasePattern, Context, GoalProgress, goal_xy, params_mask, register, with_heading

#: Unit direction of each spatial relation in the table frame; each is a
#: pattern of its own (also readable as ``lgmcts.formats.RELATIONS``).
RELATIONS: dict[str, tuple[float, float]] = {
    "left": (-1.0, 0.0),
    "right": (1.0, 0.0),
    "front": (0.0, -1.0),
    "behind": (0.0, 1.0),
    "left_front": (-math.sqrt(0.5), -math.sqrt(0.5)),
    "left_behind": (-math.sqrt(0.5), math.sqrt(0.5)),
    "right_front": (math.sqrt(0.5), -math.sqrt(0.5)),
    "right_behind": (math.sqrt(0.5), math.sqrt(0.5)),
}

#: Half-angle of the sampled sector (rad), inside the 45 degree rule.
HALF_ANGLE = math.pi / 4 - 0.06
#: Farthest sampled distance from the anchor (m), inside the 0.30 m rule.
MAX_DIST = 0.29

_PHRASES = {
    "left": ("to the left of", "on the left side of", "left of", "at the left of"),
    "right": ("to the right of", "on the right side of", "right of", "at the right of"),
    "front": ("in front of", "before", "at the front of", "closer to me than"),
    "behind": ("behind", "at the back of", "in back of", "farther from me than", "back of"),
    "left_front": ("to the left and in front of", "in front left of", "front left of", "left front of"),
    "left_behind": ("to the left and behind", "behind and to the left of", "left behind of", "back left of"),
    "right_front": ("to the right and in front of", "in front right of", "front right of", "right front of"),
    "right_behind": ("to the right and behind", "behind and to the right of", "right behind of", "back right of"),
}


@dataclass(frozen=True)
class Relation(BasePattern):
    """One of the eight directional relations; ``relation`` names it."""

    relation: str = "left"
    ordered = True
    min_objects = 1
    anchored = True

    @property
    def name(self) -> str:  # type: ignore[override]
        return self.relation

    @property
    def keys(self) -> tuple[str, ...]:  # type: ignore[override]
        return _PHRASES[self.relation]

    @property
    def description(self) -> str:  # type: ignore[override]
        words = self.relation.replace("_", " and ")
        return f"each object ends {words} of the anchor object, within 0.30 m"

    @property
    def direction(self) -> float:
        dx, dy = RELATIONS[self.relation]
        return math.atan2(dy, dx)

    def ready(self, ctx: Context, obj: int, settled: frozenset[int]) -> bool:
        return ctx.goal.anchor in settled

    def sample(self, ctx: Context, obj: int, rng: np.random.Generator, n: int) -> np.ndarray:
        a = ctx.goal.anchor
        assert a is not None, "a relation goal has an anchor (formats.Goal checks it)"
        base = ctx.state.poses[a, :2]
        lo = min(ctx.radius(a) + ctx.radius(obj) + CLEARANCE, MAX_DIST - 0.01)
        rho = lo + (MAX_DIST - lo) * rng.random(n) ** 2
        ang = self.direction + rng.uniform(-HALF_ANGLE, HALF_ANGLE, n)
        xy = base + rho[:, None] * np.stack([np.cos(ang), np.sin(ang)], axis=1)
        theta = np.full(n, ctx.state.poses[obj, 2])
        out = with_heading(ctx, np.column_stack([xy, theta]))
        if ctx.goal.params.box is not None:
            out = out[params_mask(ctx, obj, out)]
        return out

    def density(self, ctx: Context, obj: int, poses: np.ndarray) -> np.ndarray:
        poses = np.asarray(poses, dtype=float).reshape(-1, 3)
        v = poses[:, :2] - ctx.state.poses[ctx.goal.anchor, :2]
        rho = np.hypot(v[:, 0], v[:, 1])
        ang = np.abs(wrap_angle(np.arctan2(v[:, 1], v[:, 0]) - self.direction))
        ok = (rho > 1e-6) & (rho <= MAX_DIST) & (ang <= HALF_ANGLE)
        if not ctx.goal.params.empty:
            ok &= params_mask(ctx, obj, poses)
        return ok.astype(float)

    def commit(self, ctx: Context, obj: int, pose: np.ndarray, rng: np.random.Generator) -> GoalProgress:
        return ctx.progress.add(obj)

    def region(self, ctx: Context):
        x, y = ctx.state.poses[ctx.goal.anchor, :2]
        arc = self.direction + np.linspace(-math.pi / 4, math.pi / 4, 9)
        pts = [(x, y)] + [(x + 0.30 * math.cos(t), y + 0.30 * math.sin(t)) for t in arc]
        return shapely.Polygon(pts).buffer(ctx.max_radius)

    def describe(self, goal) -> str:
        word = "behind" if self.relation == "behind" else f"{self.relation.replace('_', '-')} of"
        return ", ".join(str(i) for i in goal.objects) + f" {word} {goal.anchor}"

    # The finished arrangement (the acceptance rule and what to draw).
    def accept(self, goal, scene, poses, on) -> str | None:
        d = np.asarray(RELATIONS[self.relation])
        a = poses[scene.index[goal.anchor], :2]
        for i in (scene.index[o] for o in goal.objects):
            v = poses[i, :2] - a
            n = float(np.hypot(*v))
            if n <= 0 or n > MAX_RELATION_DIST:
                return (
                    f"object {scene.ids[i]} is {n:.3f} m from anchor {goal.anchor} (needs 0 < d <= {MAX_RELATION_DIST})"
                )
            ang = math.acos(max(-1.0, min(1.0, float(v @ d) / n)))
            if ang > RELATION_HALF_ANGLE + 1e-9:
                off = math.degrees(ang)
                return f"object {scene.ids[i]} is {off:.0f} deg off '{self.relation}' of anchor {goal.anchor}"
        return None

    def shape(self, goal, scene, poses) -> tuple[str, dict]:
        a = np.asarray(poses[scene.index[goal.anchor], :2], dtype=float)
        xy = goal_xy(goal, scene, poses)
        return "relation", {
            "anchor": a,
            "arrows": [(a, xy[j]) for j in range(len(xy))],
            "direction": np.asarray(RELATIONS[self.relation]),
        }


for _rel in RELATIONS:
    register(Relation(relation=_rel))
