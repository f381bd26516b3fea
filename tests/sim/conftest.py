"""Fixtures of the simulator tests: small scenes and a rendering check."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from lgmcts.formats import parse_scene

sys.path.insert(0, str(Path(__file__).parent))

from sim_scenes import ALL_SHAPES, POLE


@pytest.fixture(scope="session")
def render_ok() -> None:
    """Skip a test when no offscreen OpenGL context can be made (no OSMesa/EGL)."""
    from lgmcts.sim import build_model
    from lgmcts.sim.render import _open_renderer

    sim = build_model(parse_scene(ALL_SHAPES))
    try:
        with _open_renderer(sim.model, 32, 32):
            pass
    except RuntimeError as exc:
        pytest.skip(f"offscreen rendering unavailable: {exc}")


@pytest.fixture()
def all_shapes():
    return parse_scene(ALL_SHAPES)


@pytest.fixture()
def pole_scene():
    return parse_scene(POLE)
