"""Shared fixtures: scenes and one sentence model for the whole session."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

from lgmcts.formats import load_scene, parse_scene

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(Path(__file__).parent))  # tables.py, the small tables of the end-to-end tests
CASES = ROOT / "data" / "parse_cases.jsonl"


@pytest.fixture(scope="session")
def tabletop():
    return load_scene(ROOT / "examples" / "tabletop.json")


@pytest.fixture(scope="session")
def scenes():
    """The named scenes of the labelled set, by name."""
    import json

    out = {}
    for line in CASES.read_text().splitlines():
        row = json.loads(line)
        if "scene_id" in row:
            out[row["scene_id"]] = parse_scene(row["scene"])
    return out


@pytest.fixture(scope="session")
def matcher():
    """The process-wide matcher with its model loaded once per session."""
    from lgmcts.language.matcher import default_matcher

    m = default_matcher()
    m.encoder.load()
    m.key_embeddings()
    return m
