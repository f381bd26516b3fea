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


#: What `pytest -m "not slow"` leaves out (`make test` runs everything):
#: physics, the service (a server in a subprocess), headless browsers, Ray, a
#: fresh install, and tests that pay a start-up cost of seconds each: running
#: the `lgmcts` command in a subprocess, loading the sentence model (the
#: `matcher` fixture), drawing pictures with matplotlib, generating suites of
#: packed scenes.
SLOW_PARTS = (
    "sim",
    "service",
    "test_viz_html_browser.py",
    "test_language_cli.py",
    "test_viz_cli.py",
    "test_viz_figures.py",
    "test_cli.py",
    "test_cli_hardening.py",
    "test_viz_limits.py",
    "test_bench_dense.py",
)
SLOW_TESTS = {
    "test_cli_plans_and_checks_goals_with_params",
    "test_cli_bad_param_exits_2",
    "test_cli_loads_pattern_modules",
    "test_generate_cli_writes_the_same_file_for_the_same_seed",
    "test_bench_cli_writes_results_and_summaries",
    "test_pictures_of_a_plan_with_params",
    "test_bar_on_a_terminal_unless_switched_off",
    "test_no_bar_when_piped",
    "test_cli_verbose_shows_the_search_log",
    "test_bundled_and_generated_scenes_pass_the_start_rules_and_precheck",
    "test_cli_parse_runs_without_torch_or_transformers",
}
SLOW_FIXTURES = {"matcher"}


def pytest_collection_modifyitems(config, items):
    for item in items:
        parts = Path(str(item.fspath)).relative_to(ROOT / "tests").parts
        name = getattr(item, "originalname", None) or item.name
        if (any(p in SLOW_PARTS for p in parts) or name in SLOW_TESTS
                or SLOW_FIXTURES & set(getattr(item, "fixturenames", ()))):
            item.add_marker(pytest.mark.slow)
