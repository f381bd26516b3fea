"""The two held-out evaluation sets are well formed, and the evaluator's label conventions."""

from __future__ import annotations

import copy
import importlib.util
import json
from collections import Counter

import pytest

from lgmcts.errors import InputError
from lgmcts.formats import parse_goals
from lgmcts.language.evaluate import Case, CaseResult, EvalReport, goals_match, load_cases

from .conftest import ROOT

PEER = ROOT / "data" / "peer_cases.jsonl"
PARA = ROOT / "data" / "paraphrase_cases.jsonl"
LABEL_KEYS = ("unordered", "region", "size", "facing")


def _plain_goals(expect: dict) -> list[dict]:
    """Every goal list an expectation allows, with the label-only keys removed and choices made."""
    alts = expect["any_of"] if "any_of" in expect else [expect]
    out = []
    for alt in alts:
        goals = []
        for g in copy.deepcopy(alt["goals"]):
            for k in LABEL_KEYS:
                g.pop(k, None)
            if "objects_from" in g:
                g["objects"] = g.pop("objects_from")[: g.pop("count")]
            if "anchor_any" in g:
                g["anchor"] = g.pop("anchor_any")[0]
            goals.append(g)
        out.append({"goals": goals})
    return out


@pytest.mark.parametrize("path,n_min,refuse_min", [(PEER, 300, 10), (PARA, 200, 30)])
def test_sets_are_large_split_per_family_and_load(path, n_min, refuse_min):
    cases = load_cases(path)
    assert len(cases) >= n_min
    assert sum(c.refuse is not None for c in cases) >= refuse_min
    assert len({c.id for c in cases}) == len(cases)
    by_family: dict[str, Counter] = {}
    for c in cases:
        assert c.family and c.split in ("dev", "test"), c.id
        by_family.setdefault(c.family, Counter())[c.split] += 1
    for fam, cnt in by_family.items():
        assert cnt["dev"] >= 1 and cnt["test"] >= 1, fam
    dev = sum(c.split == "dev" for c in cases) / len(cases)
    assert 0.28 <= dev <= 0.42
    assert len(load_cases(path, split="dev")) + len(load_cases(path, split="test")) == len(cases)


@pytest.mark.parametrize("path", [PEER, PARA])
def test_every_label_is_a_valid_goal_file_for_its_scene(path):
    for c in load_cases(path):
        if c.refuse is not None:
            assert c.refuse is True and c.expect is None, c.id
            continue
        has_params = any(k in json.dumps(c.expect) for k in ('"region"', '"size"', '"facing"'))
        assert has_params == ("params" in c.needs), c.id
        for goals in _plain_goals(c.expect):
            parse_goals(goals).check_against(c.scene)


def test_peer_set_covers_every_template_family():
    fams = {c.family for c in load_cases(PEER)}
    assert {
        "lgmcts-whose-equal", "lgmcts-whose-different", "lgmcts-with-same-different", "lgmcts-objects-compare-color",
        "lgmcts-pair", "lgmcts-pair-vertical", "lgmcts-composite", "lgmcts-two-patterns",
        "structformer-select-color", "structformer-select-class", "structformer-compare", "structformer-same-color",
        "structformer-dinner", "lgmcts-whose-size",
    } <= fams


def test_peer_set_is_regenerated_byte_for_byte():
    spec = importlib.util.spec_from_file_location("make_eval_cases", ROOT / "scripts" / "make_eval_cases.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    lines = mod.build()
    text = "".join(json.dumps(x, separators=(", ", ": ")) + "\n" for x in lines)
    assert text == PEER.read_text()


def test_peer_semantics_reference_in_its_own_colour_set():
    """LGMCTS-D: "objects whose color is equal to X" includes X; StructFormer's "same color as the X" does not."""
    for c in load_cases(PEER):
        if c.refuse is not None:
            continue
        objs = {o.id: o for o in c.scene.objects}
        if c.family == "lgmcts-whose-equal":
            tail = c.instruction.split(" whose color ")[1]
            word = next(w for w in ("is equal to", "is same as", "is identical to", "is alike", "is equivalent to")
                        if tail.startswith(w))
            rest = tail[len(word) + 1:]
            anchor = max((o.name for o in objs.values() if rest.startswith(o.name)), key=len)
            sel = c.expect["goals"][0]["objects"]
            assert any(objs[i].name == anchor for i in sel), c.id
            assert len({objs[i].color for i in sel}) == 1
        if c.family == "structformer-same-color":
            ref = c.instruction.split("same color as the ")[1].split(".")[0]
            sel = c.expect["goals"][0]["objects"]
            assert all(f"{objs[i].color} {objs[i].name}" != ref for i in sel), c.id


def test_label_conventions_unordered_any_of_and_params():
    tower = {"goals": [{"pattern": "tower", "objects": [1, 2, 3], "unordered": True}]}
    assert goals_match(tower, {"goals": [{"pattern": "tower", "objects": [3, 1, 2]}]})
    assert not goals_match(tower, {"goals": [{"pattern": "tower", "objects": [3, 1]}]})
    either = {"any_of": [{"goals": [{"pattern": "left", "objects": [2], "anchor": 1}]},
                         {"goals": [{"pattern": "right", "objects": [1], "anchor": 2}]}]}
    assert goals_match(either, {"goals": [{"pattern": "right", "objects": [1], "anchor": 2}]})
    assert not goals_match(either, {"goals": [{"pattern": "right", "objects": [2], "anchor": 1}]})
    big = {"goals": [{"pattern": "circle", "objects": [1, 2, 3], "size": "large", "region": "top left"}]}
    assert goals_match(big, {"goals": [{"pattern": "circle", "objects": [1, 2, 3], "size": "large", "region": "Top-Left"}]})
    assert not goals_match(big, {"goals": [{"pattern": "circle", "objects": [1, 2, 3]}]})
    assert not goals_match(big, {"goals": [{"pattern": "circle", "objects": [1, 2, 3], "size": "small", "region": "top left"}]})
    centre = {"goals": [{"pattern": "line", "objects": [1, 2], "region": "middle center"}]}
    assert goals_match(centre, {"goals": [{"pattern": "line", "objects": [1, 2], "region": "centre"}]})
    plain = {"goals": [{"pattern": "line", "objects": [1, 2]}]}
    assert not goals_match(plain, {"goals": [{"pattern": "line", "objects": [1, 2], "facing": "north"}]})


def test_wrong_goal_rate_counts_answers_only(tabletop):
    def res(ok, got, refuse=None):
        case = Case("x", "c", tabletop, "t", None if refuse else {"goals": []}, refuse, split="dev")
        return CaseResult(case, ok, got, None if got is not None else "refused", 0.001)

    rep = EvalReport([res(True, {"goals": []}), res(False, {"goals": []}), res(False, None),
                      res(True, None, refuse=True), res(False, {"goals": []}, refuse=True)])
    o = rep.outcomes()
    assert o == {"answered": 3, "wrong_goals": 2, "refused": 2, "wrongly_refused": 1}
    assert rep.wrong_goal_rate == pytest.approx(2 / 3)
    assert rep.per_split() == {"dev": (2, 5)}


def test_split_filter_and_bad_split(tmp_path):
    with pytest.raises(InputError):
        load_cases(PARA, split="nope")
    from typer.testing import CliRunner

    from lgmcts.cli import app

    res = CliRunner().invoke(app, ["eval-parse", str(PARA), "--split", "train"])
    assert res.exit_code == 2
