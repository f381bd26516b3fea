"""The suites' peer-template instruction mode: deterministic, same tasks, the peers'
sentence families, and sentences that mean exactly the ground-truth goals under the
peers' semantics (read back here by an interpreter written from the peers' templates)."""

from __future__ import annotations

import json
import re

import pytest
from typer.testing import CliRunner

from lgmcts.bench import generate, read_suite
from lgmcts.bench.runner import canonical_goals
from lgmcts.cli import app
from lgmcts.errors import InputError
from lgmcts.formats import parse_goals

VERB = r"(?:Put|Place|Leave)"
PREP = r"(?:at|in|on)"
EQUAL = ("is equal to", "is same as", "is identical to", "is alike", "is equivalent to")
DIFFERENT = ("is different with", "is not the same as", "is not equal to", "is not identical to", "is not alike",
             "is not equivalent to", "is different from")
PAIR = {
    "left to": "left", "right to": "right", "in front of": "front", "behind": "behind", "in back of": "behind",
    "in front left of": "left_front", "in left front of": "left_front", "left and front of": "left_front",
    "in front right of": "right_front", "in right front of": "right_front", "right and front of": "right_front",
    "behind left of": "left_behind", "left behind of": "left_behind", "left and behind of": "left_behind",
    "behind right of": "right_behind", "right behind of": "right_behind", "right and behind of": "right_behind",
    "on": "on", "under": "under", "below": "under",
}
PATTERN_FORMS = (
    re.compile(rf"^{VERB} (?P<objs>.+) {PREP} a (?P<p>\w+) pattern$"),
    re.compile(rf"^{VERB} a (?P<p>\w+) pattern using (?P<objs>.+)$"),
    re.compile(rf"^Select (?P<objs>.+), and {VERB} them {PREP} a (?P<p>\w+) pattern$"),
)
SF_SELECT = re.compile(r"^select objects that are (?P<name>[\w ]+)\. (?P<p>line|circle)$")


def _objects(scene: dict) -> dict[int, tuple[str, str]]:
    return {o["id"]: (o["name"], o["color"]) for o in scene["objects"]}


def _by_desc(objs, desc: str) -> set[int]:
    return {i for i, (n, c) in objs.items() if f"{c} {n}" == desc}


def _one_by_name(objs, name: str) -> int:
    (i,) = [i for i, (n, _) in objs.items() if n == name]
    return i


def _select(objs, words: str) -> set[int]:
    """LGMCTS-D's object sets, with its semantics."""
    for rel in EQUAL + DIFFERENT:
        head = f"objects whose color {rel} "
        if words.startswith(head) and not words.startswith(head + "the "):
            c = objs[_one_by_name(objs, words[len(head):])][1]
            same = rel in EQUAL
            return {i for i, (_, cc) in objs.items() if (cc == c) == same}
    m = re.match(r"^Objects (?:with|of|has) (?:the same|similar) shape as (?P<x>.+)$", words)
    if m:
        return {i for i, (n, _) in objs.items() if n == m["x"]}
    out: set[int] = set()
    for d in words.split(", "):
        found = _by_desc(objs, d)
        assert found, d
        out |= found
    return out


def _read(task) -> frozenset:
    objs = _objects(task.scene)
    sentences = re.split(r"; (?:then |and |while |so )?", task.instruction)
    goals, stack = [], []
    for s in sentences:
        m = SF_SELECT.match(s)
        if m:
            goals.append({"pattern": m["p"], "objects": sorted(i for i, (n, _) in objs.items() if n == m["name"])})
            continue
        for form in PATTERN_FORMS:
            m = form.match(s)
            if m:
                goals.append({"pattern": m["p"], "objects": sorted(_select(objs, m["objs"]))})
                break
        else:
            m = re.match(rf"^{VERB} (?P<rest>.+)$", s)
            assert m, s
            rest = m["rest"]
            word = max((w for w in PAIR if f" {w} " in rest), key=len)
            a, b = rest.split(f" {word} ", 1)
            (ia,) = _by_desc(objs, a)
            (ib,) = _by_desc(objs, b)
            rel = PAIR[word]
            if rel == "on":
                stack.append((ib, ia))
            elif rel == "under":
                stack.append((ia, ib))
            else:
                goals.append({"pattern": rel, "objects": [ia], "anchor": ib})
    if stack:  # chain the (below, above) pairs into one tower
        above = dict(stack)
        (base,) = set(above) - set(above.values())
        tower = [base]
        while tower[-1] in above:
            tower.append(above[tower[-1]])
        assert len(tower) == len(stack) + 1
        goals.append({"pattern": "tower", "objects": tower})
    return canonical_goals(parse_goals({"goals": goals}))


@pytest.mark.parametrize("suite,n", [("elgr", 60), ("structformer", 40)])
def test_peer_instructions_mean_exactly_the_ground_truth(suite, n):
    ours = generate(suite, n=n, seed=3)
    peer = generate(suite, n=n, seed=3, instructions="peer")
    assert sum(t.instructions == "peer" for t in peer) >= 0.95 * n
    for a, b in zip(ours, peer):
        assert b.id == a.id.replace(f"{suite}-", f"{suite}-peer-", 1)
        assert (a.scene, a.goals, a.final, a.start) == (b.scene, b.goals, b.final, b.start)
        if b.instructions == "peer":
            assert b.instruction != a.instruction
            assert _read(b) == canonical_goals(b.goal_spec()), (b.id, b.instruction)


def test_peer_instructions_use_every_peer_family():
    text = " | ".join(
        t.instruction for s in ("elgr", "structformer") for t in generate(s, n=80, seed=5, instructions="peer")
    )
    for needle in (
        "objects whose color is",
        "Objects with",
        "pattern using",
        "Select ",
        ", and ",
        "select objects that are",
        " left to ",
        " on ",
        "; ",
    ):
        assert needle in text, needle
    assert any(
        f" {w} " in text for w in ("in front left of", "left and front of", "behind right of", "right behind of")
    )
    assert not re.search(r"\b(the|all)\b", text.replace("the same", "")), "our own phrasing leaked into peer mode"


def test_peer_mode_is_deterministic_by_seed_and_round_trips(tmp_path):
    a = [t.to_dict() for t in generate("elgr", n=12, seed=2, instructions="peer")]
    b = [t.to_dict() for t in generate("elgr", n=12, seed=2, instructions="peer")]
    c = [t.to_dict() for t in generate("elgr", n=12, seed=4, instructions="peer")]
    assert a == b and a != c
    out = tmp_path / "peer.jsonl"
    res = CliRunner().invoke(
        app,
        [
            "bench-generate",
            "--suite",
            "structformer",
            "--n",
            "8",
            "--seed",
            "2",
            "--instructions",
            "peer",
            "-o",
            str(out),
        ],
    )
    assert res.exit_code == 0, res.output
    tasks = read_suite(out)
    assert [t.to_dict() for t in tasks] == [
        t.to_dict() for t in generate("structformer", n=8, seed=2, instructions="peer")
    ]
    assert all(json.loads(line)["instructions"] == "peer" for line in out.read_text().splitlines())


def test_unknown_instruction_mode_is_refused(tmp_path):
    with pytest.raises(InputError):
        generate("elgr", n=1, instructions="martian")
    res = CliRunner().invoke(
        app,
        ["bench-generate", "--suite", "elgr", "--n", "1", "--instructions", "martian", "-o", str(tmp_path / "x.jsonl")],
    )
    assert res.exit_code == 2
