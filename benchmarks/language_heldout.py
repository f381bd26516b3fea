"""Accuracy of the offline parser on the labelled language sets, per file and split.

    python benchmarks/language_heldout.py                 # the default sets
    python benchmarks/language_heldout.py FILE[:SPLIT[:PREFIX,...]] ...

Prints, per set, the commands parsed as labelled, the answered commands and
the wrong goals among them, and the correct commands refused (the figures of
``lgmcts eval-parse FILE --split SPLIT``, without the failure list, so that a
test split can be reported without being read). ``PREFIX,...`` keeps the
cases whose id starts with one of them (one writer's batch: ``freshX``). Run it from another checkout
with ``PYTHONPATH`` set to that checkout to compare two versions of the
parser on the same files.
"""

from __future__ import annotations

import argparse
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DEFAULT = [
    "tests/language/fresh_cases.jsonl:dev", "tests/language/fresh_cases.jsonl:test",
    "data/paraphrase_cases.jsonl:dev", "data/peer_cases.jsonl:dev", "data/peer_cases.jsonl:test",
    "data/parse_cases.jsonl", "tests/language/probe_cases.jsonl",
]


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("sets", nargs="*", default=DEFAULT,
                    help="FILE, FILE:SPLIT (dev or test) or FILE:SPLIT:PREFIX,... (ids starting so)")
    args = ap.parse_args()
    from lgmcts.language.evaluate import evaluate, load_cases
    from lgmcts.language.matcher import default_matcher
    from lgmcts.language.rules import parse_rules

    matcher = default_matcher()
    for item in args.sets:
        path, _, rest = item.partition(":")
        split, _, prefixes = rest.partition(":")
        p = Path(path) if Path(path).is_absolute() else ROOT / path
        cases = [c for c in load_cases(p) if (not split or c.split == split)
                 and (not prefixes or c.id.startswith(tuple(prefixes.split(","))))]
        report = evaluate(cases, lambda s, t: parse_rules(s, t, matcher=matcher))
        n = len(cases)
        ok = sum(r.ok for r in report.results)
        answered = sum(r.got is not None for r in report.results)
        wrong = sum(1 for r in report.results if not r.ok and r.got is not None)
        refused = sum(1 for r in report.results if r.got is None and r.case.refuse is None)
        print(f"{item:42s} {ok}/{n} = {100 * ok / max(n, 1):.1f} %; answered {answered}, wrong goals {wrong} "
              f"({100 * wrong / max(answered, 1):.1f} %), correct commands refused {refused}")


if __name__ == "__main__":
    main()
