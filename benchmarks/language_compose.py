"""Do the parser's readings compose? Modifiers said after commands it already reads.

    python benchmarks/language_compose.py                    # dev and test phrasings, summary
    python benchmarks/language_compose.py --split dev --show 20

Each labelled command whose goal is one line, circle or rectangle without a
place, size or facing, and which the parser reads as labelled, is said again
with each phrasing of ``tests/language/compose_probes.toml`` appended (a place,
a facing, a measure, something absent from the scene, or a remark that asks
nothing). The answer is scored against the labelled goal with the phrasing's
parameter added:

* ``read``: the goal with the parameter (for ``absent``: a refusal; for
  ``neutral``: the goal unchanged);
* ``refused``: a one-line refusal where a goal was expected (not silent, but
  not read);
* ``dropped``: the labelled goal without the parameter, i.e. the words said
  were silently left out of the goal (a wrong goal);
* ``wrong``: any other answer.

The base commands come from the project's labelled sets (their dev halves
only); they are taken as written, with a final full stop, question or
exclamation mark moved after the phrasing.
"""

from __future__ import annotations

import argparse
import hashlib
import re
import tomllib
from collections import Counter, defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PROBES = ROOT / "tests/language/compose_probes.toml"
BASES = [
    ("data/parse_cases.jsonl", None), ("data/paraphrase_cases.jsonl", "dev"),
    ("tests/language/fresh_cases.jsonl", "dev"), ("tests/language/fresh7_cases.jsonl", "dev"),
]
SHAPES = ("line", "circle", "rectangle")
PARAMS = ("region", "size", "facing")


def load_probes(split: str | None) -> list[dict]:
    rows = tomllib.loads(PROBES.read_text())["probe"]
    return [r for r in rows if split is None or r["split"] == split]


def base_cases(per_pattern: int) -> list:
    """The labelled one-shape commands, ``per_pattern`` of each shape (a fixed choice by id)."""
    from lgmcts.language.evaluate import load_cases

    picked: dict[str, list] = defaultdict(list)
    for path, split in BASES:
        for c in load_cases(ROOT / path):
            if (split and c.split != split) or c.refuse is not None or not c.expect or "goals" not in c.expect:
                continue
            goals = c.expect["goals"]
            if len(goals) != 1 or goals[0].get("pattern") not in SHAPES or any(k in goals[0] for k in PARAMS):
                continue
            if re.search(r"[.!?;]\s+\S", c.instruction.strip()):
                continue  # one sentence only: a phrasing after a remark would belong to it
            picked[goals[0]["pattern"]].append(c)
    out = []
    for pattern in SHAPES:
        cases = sorted(picked[pattern], key=lambda c: hashlib.sha256(c.id.encode()).hexdigest())
        out += cases[:per_pattern]
    return out


def said_with(instruction: str, text: str) -> str:
    s = instruction.rstrip()
    m = re.search(r"[.!?]+$", s)
    end = m.group(0) if m else ""
    return s[: len(s) - len(end)] + text + end


def expected(case, probe: dict) -> dict | None:
    """The labelled goal with the probe's parameter; None where the probe does not apply to its pattern."""
    goal = dict(case.expect["goals"][0])
    if probe["class"] == "place":
        goal["region"] = probe["region"]
    elif probe["class"] == "facing":
        goal["facing"] = probe["facing"]
    elif probe["class"] == "measure":
        size = probe.get(f"size_{goal['pattern']}")
        if size is None:
            return None
        goal["size"] = size
    return {"goals": [goal]}


def score(case, probe: dict, got: dict | None) -> str:
    from lgmcts.language.evaluate import goals_match

    if got is None:
        return "read" if probe.get("refuse") else "refused"
    if goals_match(case.expect, got):
        return "read" if probe.get("same") else "dropped"
    if probe.get("refuse") or probe.get("same"):
        return "wrong"
    want = expected(case, probe)
    assert want is not None
    goals = got.get("goals", [])
    if len(goals) == 1 and isinstance(goals[0].get("size"), (int, float)) and "size" in want["goals"][0]:
        if abs(goals[0]["size"] - want["goals"][0]["size"]) <= 0.002:
            got = {"goals": [{**goals[0], "size": want["goals"][0]["size"]}]}
    return "read" if goals_match(want, got) else "wrong"


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--split", choices=["dev", "test"], default=None, help="only the phrasings of this split")
    ap.add_argument("--per-pattern", type=int, default=30, help="base commands per shape (default 30)")
    ap.add_argument("--show", type=int, default=0, help="list this many dropped or wrong answers (dev only)")
    args = ap.parse_args()
    from lgmcts.errors import InputError
    from lgmcts.language.evaluate import goals_match, to_dict
    from lgmcts.language.matcher import default_matcher
    from lgmcts.language.rules import parse_rules

    matcher = default_matcher()

    def parse(case, text: str) -> dict | None:
        try:
            return to_dict(parse_rules(case.scene, text, matcher=matcher))
        except InputError:
            return None

    bases = [c for c in base_cases(args.per_pattern) if (g := parse(c, c.instruction)) and goals_match(c.expect, g)]
    tally: dict[tuple[str, str], Counter] = defaultdict(Counter)
    shown: list[str] = []
    for probe in load_probes(args.split):
        for case in bases:
            if expected(case, probe) is None:
                continue
            text = said_with(case.instruction, probe["text"])
            result = score(case, probe, parse(case, text))
            tally[(probe["class"], probe["split"])][result] += 1
            if result in ("dropped", "wrong") and probe["split"] == "dev" and len(shown) < args.show:
                shown.append(f"{result:8s} {text}")
    print(f"{len(bases)} base commands read as labelled ({args.per_pattern} per shape at most)")
    print(f"{'class':9s} {'split':5s} {'probes':>6s} {'read':>6s} {'refused':>8s} {'dropped':>8s} {'wrong':>6s}")
    for (cls, split), c in sorted(tally.items()):
        n = sum(c.values())
        print(f"{cls:9s} {split:5s} {n:6d} {c['read']:6d} {c['refused']:8d} {c['dropped']:8d} {c['wrong']:6d}")
    total = Counter()
    for c in tally.values():
        total += c
    n = sum(total.values())
    t = total
    print(f"{'all':9s} {'':5s} {n:6d} {t['read']:6d} {t['refused']:8d} {t['dropped']:8d} {t['wrong']:6d}")
    for line in shown:
        print(line)


if __name__ == "__main__":
    main()
