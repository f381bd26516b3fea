"""Small tables for end-to-end parser tests: cylinders named and coloured as said, and the goals a command
gives on one (imported by the test modules of this folder; ``conftest.py`` puts the folder on the path)."""

from __future__ import annotations


def scenes_of(case_file: str) -> dict:
    """The scenes of a case file of this folder by id (its rows with a ``scene_id``: "home", "toys" ...)."""
    import json
    from pathlib import Path

    from lgmcts.formats import parse_scene

    rows = map(json.loads, (Path(__file__).parent / case_file).read_text().splitlines())
    return {r["scene_id"]: parse_scene(r["scene"]) for r in rows if "scene_id" in r}


def cylinders(objects: list[tuple[str, str, float, float]]):
    """A scene of small cylinders (name, colour, x, y), ids from 1 in order."""
    from lgmcts.formats import parse_scene

    return parse_scene({"workspace": {"x": [-0.4, 0.4], "y": [-0.3, 0.3]}, "objects": [
        {"id": k + 1, "name": n, "color": c, "shape": {"type": "cylinder", "radius": 0.03, "height": 0.05},
         "pose": [x, y, 0.0]} for k, (n, c, x, y) in enumerate(objects)]})


def goals_of(scene, said: str) -> list[dict]:
    """The goals the default parser reads from ``said`` on ``scene``, as dicts without empty fields."""
    from lgmcts.language import parse

    return [g.model_dump(exclude_none=True) for g in parse(scene, said).goals]


def assert_reads(scene, said: str, goals: list[dict] | None) -> None:
    """``said`` on ``scene`` gives ``goals`` (in any order) with the rules parser, or is refused where ``goals`` is
    None."""
    import pytest

    from lgmcts.errors import InputError
    from lgmcts.formats import to_dict
    from lgmcts.language.matcher import default_matcher
    from lgmcts.language.rules import parse_rules

    if goals is None:
        with pytest.raises(InputError):
            parse_rules(scene, said, matcher=default_matcher())
        return
    got = to_dict(parse_rules(scene, said, matcher=default_matcher()))["goals"]
    assert sorted(got, key=str) == sorted(goals, key=str)
