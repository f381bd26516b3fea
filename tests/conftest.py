"""Shared test set-up: offline model hub, headless rendering, example paths."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

os.environ.setdefault("HF_HUB_OFFLINE", "1")
os.environ.setdefault("TRANSFORMERS_OFFLINE", "1")
os.environ.setdefault("MUJOCO_GL", "osmesa")
os.environ.setdefault("PYOPENGL_PLATFORM", "osmesa")

ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="session")
def root() -> Path:
    return ROOT


@pytest.fixture(scope="session")
def example_scene() -> Path:
    return ROOT / "examples" / "tabletop.json"


@pytest.fixture(scope="session")
def example_goals() -> Path:
    return ROOT / "examples" / "goals.json"
