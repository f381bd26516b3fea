"""Small scene builders for the core tests."""

from __future__ import annotations

from typing import Any


def box(i: int, x: float, y: float, *, theta: float = 0.0, size: float = 0.04, on: int | None = None,
        name: str = "block", color: str = "red", height: float = 0.04) -> dict[str, Any]:
    return {"id": i, "name": name, "color": color, "shape": {"type": "box", "size": [size, size, height]},
            "pose": [x, y, theta], "on": on}


def can(i: int, x: float, y: float, *, r: float = 0.02, on: int | None = None, name: str = "can",
        color: str = "blue") -> dict[str, Any]:
    return {"id": i, "name": name, "color": color, "shape": {"type": "cylinder", "radius": r, "height": 0.08},
            "pose": [x, y, 0.0], "on": on}


def scene(*objects: dict[str, Any], x=(-0.4, 0.4), y=(-0.3, 0.3)) -> dict[str, Any]:
    return {"workspace": {"x": list(x), "y": list(y)}, "objects": list(objects)}


def goals(*gs: dict[str, Any]) -> dict[str, Any]:
    return {"goals": list(gs)}
