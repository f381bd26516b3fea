"""Shared test set-up: offline model hub, headless rendering, example paths."""

from __future__ import annotations

import os
from pathlib import Path

import pytest
from hypothesis import settings

# The suite is deterministic: property tests draw the same examples on every
# run, so a pass here is a pass on CI. HYPOTHESIS_PROFILE=explore draws fresh
# examples on each run to hunt for new counter-examples. No profile has a
# per-example deadline: on a loaded machine any fixed one can fail a good run.
settings.register_profile("repeatable", derandomize=True, deadline=None)
settings.register_profile("explore", derandomize=False, deadline=None)
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


def pytest_configure(config: pytest.Config) -> None:
    """Slow tests carry ``@pytest.mark.slow`` (or ``pytestmark``) where they are
    defined: physics, the service, headless browsers, Ray, a fresh install,
    and tests that pay seconds of start-up each (the ``lgmcts`` command in a
    subprocess, the sentence model through the ``matcher`` fixture, pictures
    drawn with matplotlib, suites of packed scenes). ``-m "not slow"`` is the
    quick lane; it relies on the marker being declared in pyproject.toml."""
    declared = [line.split(":", 1)[0].strip() for line in config.getini("markers")]
    if "slow" not in declared:
        raise pytest.UsageError("the 'slow' marker is not declared in pyproject.toml [tool.pytest.ini_options]")
