"""Small scenes shared by the simulator tests."""

from __future__ import annotations

#: One object of every shape type, and a stack.
ALL_SHAPES = {
    "workspace": {"x": [-0.3, 0.3], "y": [-0.25, 0.25]},
    "objects": [
        {"id": 1, "name": "block", "color": "red", "shape": {"type": "box", "size": [0.06, 0.04, 0.05]}, "pose": [-0.15, -0.1, 0.4]},
        {"id": 2, "name": "can", "color": "blue", "shape": {"type": "cylinder", "radius": 0.03, "height": 0.08}, "pose": [0.0, -0.1, 0.0]},
        {
            "id": 3,
            "name": "letter A",
            "color": "green",
            "shape": {"type": "polygon", "points": [[-0.04, -0.03], [0.04, -0.03], [0.0, 0.05]], "height": 0.02},
            "pose": [0.15, -0.1, 0.7],
        },
        {
            "id": 4,
            "name": "scan",
            "color": "yellow",
            "shape": {
                "type": "points",
                "points": [
                    [0.10, 0.10, 0.0], [0.16, 0.10, 0.0], [0.16, 0.15, 0.0], [0.10, 0.15, 0.0],
                    [0.10, 0.10, 0.03], [0.16, 0.10, 0.03], [0.16, 0.15, 0.03], [0.12, 0.16, 0.03],
                ],
            },
        },
        {"id": 5, "name": "block", "color": "purple", "shape": {"type": "box", "size": [0.05, 0.05, 0.04]}, "pose": [-0.15, 0.1, 0.0]},
        {"id": 6, "name": "block", "color": "orange", "shape": {"type": "box", "size": [0.04, 0.04, 0.04]}, "pose": [-0.15, 0.1, 0.3], "on": 5},
    ],
}

#: A narrow pole, a long plank and a block, for the failure modes.
POLE = {
    "workspace": {"x": [-0.3, 0.3], "y": [-0.3, 0.3]},
    "objects": [
        {"id": 1, "name": "pole", "color": "gray", "shape": {"type": "cylinder", "radius": 0.012, "height": 0.15}, "pose": [0.0, 0.0, 0.0]},
        {"id": 2, "name": "plank", "color": "brown", "shape": {"type": "box", "size": [0.2, 0.04, 0.02]}, "pose": [0.15, 0.15, 0.0]},
        {"id": 3, "name": "block", "color": "red", "shape": {"type": "box", "size": [0.04, 0.04, 0.04]}, "pose": [-0.15, -0.15, 0.0]},
    ],
}
