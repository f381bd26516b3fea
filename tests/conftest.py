"""Shared test set-up: offline model hub, headless rendering, example paths."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from hypothesis import settings

# The suite is deterministic: property tests draw the same examples on every
# run, so a pass here is a pass on CI. HYPOTHESIS_PROFILE=explore draws fresh
# examples on each run to hunt for new counter-examples.
settings.register_profile("repeatable", derandomize=True)
settings.register_profile("explore", derandomize=False)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "repeatable"))

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


#: Test folders and files whose tests are all slow: physics, the service (a
#: server in a subprocess), headless browsers. `pytest -m "not slow"` is the
#: quick loop; `make test` runs everything.
SLOW_PARTS = ("sim", "service", "test_viz_html_browser.py")


def pytest_collection_modifyitems(config, items):
    for item in items:
        parts = Path(str(item.fspath)).relative_to(ROOT / "tests").parts
        if any(p in SLOW_PARTS for p in parts):
            item.add_marker(pytest.mark.slow)
