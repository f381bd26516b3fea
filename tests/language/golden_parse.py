"""Golden parses: a digest of the offline parser's output per labelled command, kept in ``tests/data/golden_parses.json``.

Every labelled command the project has (``data/*_cases.jsonl`` and
``tests/language/*.jsonl``) is parsed by the rules parser (the default) with
the shared sentence model, and its output is reduced to a 12-hex-digit digest:

* an answer: SHA-256 of the canonical JSON (sorted keys, no spaces) of its goal
  dicts, in the order the parser gives them;
* a refusal: SHA-256 of ``refuse:`` plus the *reason* of the message, i.e. the
  message with every quoted span (``'...'``, the words of the command it
  echoes) and every number taken out. Which words a refusal quotes is not
  recorded (a change in how a clause is rewritten internally, visible only
  in the echoed words, is not a change of behaviour); a different reason
  ("names no object" instead of "is unclear") is.

A refactor that is meant to leave the parser alone must leave every digest
unchanged; ``tests/language/test_golden_parses.py`` checks that. A change meant
to alter readings (or to reword a refusal reason) rewrites the file on purpose::

    make golden-parse          # = python tests/language/golden_parse.py --write

and says why in its commit; the check mode (no argument) prints the ids whose
digest changed with what the parser gives now.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import re
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[2]
GOLDEN = ROOT / "tests" / "data" / "golden_parses.json"
DIGITS = 12


def case_files() -> list[Path]:
    """Every labelled case file, in a fixed order (paths relative to the repository root are the keys)."""
    files = sorted((ROOT / "data").glob("*_cases.jsonl")) + sorted((ROOT / "tests" / "language").glob("*.jsonl"))
    return files


#: Held-out halves not measured yet: left out of the golden, so that neither a check nor a rewrite of the
#: file shows what the parser gives on them before their one measurement (then the entry is removed).
UNSEEN: dict[str, str] = {}


_QUOTED = re.compile(r"'[^']*'|\"[^\"]*\"")
_NUMBER = re.compile(r"\d+(?:\.\d+)?")


def reason(message: str) -> str:
    """The reason of a refusal message: the message without the command's words it quotes and without numbers."""
    return " ".join(_NUMBER.sub("#", _QUOTED.sub("'…'", message)).split())


def digest_of(goals: dict[str, Any] | None, error: str | None) -> str:
    """The digest of one output: goal dicts (a ``to_dict`` of a GoalSpec) or a refusal message."""
    if goals is not None:
        blob = json.dumps(goals, sort_keys=True, separators=(",", ":"), ensure_ascii=False)
    else:
        blob = "refuse:" + reason(error or "")
    return hashlib.sha256(blob.encode()).hexdigest()[:DIGITS]


def run_parser(parse: Callable[[Any, str], Any], scene: Any, text: str) -> tuple[dict[str, Any] | None, str | None]:
    from lgmcts.errors import InputError
    from lgmcts.formats import to_dict

    try:
        return to_dict(parse(scene, text)), None
    except InputError as exc:
        return None, str(exc)


def compute(progress: bool = False) -> dict[str, dict[str, tuple[str, dict[str, Any] | None, str | None]]]:
    """Per case file (relative path), per case id: (digest, goals or None, refusal message or None)."""
    from lgmcts.language.evaluate import load_cases
    from lgmcts.language.matcher import default_matcher
    from lgmcts.language.rules import parse_rules

    matcher = default_matcher()

    def parse(scene: Any, text: str) -> Any:
        return parse_rules(scene, text, matcher=matcher)

    out: dict[str, dict[str, tuple[str, dict[str, Any] | None, str | None]]] = {}
    for path in case_files():
        rel = path.relative_to(ROOT).as_posix()
        rows: dict[str, tuple[str, dict[str, Any] | None, str | None]] = {}
        for case in load_cases(path):
            if UNSEEN.get(rel) is not None and case.split == UNSEEN[rel]:
                continue
            if case.id in rows:
                raise SystemExit(f"{rel}: case id {case.id!r} appears twice")
            goals, err = run_parser(parse, case.scene, case.instruction)
            rows[case.id] = (digest_of(goals, err), goals, err)
        out[rel] = rows
        if progress:
            print(f"{rel}: {len(rows)} commands", file=sys.stderr)
    return out


def load() -> dict[str, dict[str, str]]:
    data = json.loads(GOLDEN.read_text())
    return {k: dict(v) for k, v in data["files"].items()}


def changes(now: dict[str, dict[str, tuple[str, dict[str, Any] | None, str | None]]],
            old: dict[str, dict[str, str]]) -> list[str]:
    """Lines ``file:id`` for every command whose digest differs, is new or is gone."""
    out: list[str] = []
    for rel in sorted(set(now) | set(old)):
        a, b = old.get(rel, {}), now.get(rel, {})
        for cid in sorted(set(a) | set(b)):
            if cid not in b:
                out.append(f"{rel}:{cid} gone")
            elif cid not in a:
                out.append(f"{rel}:{cid} new")
            elif a[cid] != b[cid][0]:
                out.append(f"{rel}:{cid} changed")
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=(__doc__ or "").splitlines()[0])
    ap.add_argument("--write", action="store_true", help="parse every labelled command and rewrite the file")
    ap.add_argument("--quiet", action="store_true", help="no progress lines")
    args = ap.parse_args(argv)
    now = compute(progress=not args.quiet)
    total = sum(len(v) for v in now.values())
    if args.write:
        GOLDEN.parent.mkdir(parents=True, exist_ok=True)
        files = {rel: {cid: d for cid, (d, _, _) in rows.items()} for rel, rows in now.items()}
        body = {"digits": DIGITS, "files": files}
        # One line per case file keeps the file small; a diff still names the files that moved.
        lines = ",\n".join(f"  {json.dumps(rel)}: {json.dumps(rows, separators=(',', ':'))}"
                           for rel, rows in body["files"].items())
        GOLDEN.write_text(f'{{"digits": {DIGITS}, "files": {{\n{lines}\n}}}}\n')
        print(f"wrote {total} golden parses to {GOLDEN.relative_to(ROOT)}")
        return 0
    diff = changes(now, load())
    for line in diff:
        rel, rest = line.split(":", 1)
        cid = rest.split()[0]
        got = now.get(rel, {}).get(cid)
        shown = "" if got is None else (f" -> refuse: {got[2]}" if got[1] is None else f" -> {json.dumps(got[1]['goals'])}")
        print(line + shown)
    print(f"{total - sum(1 for d in diff if not d.endswith(' gone'))}/{total} golden parses unchanged")
    return 1 if diff else 0


if __name__ == "__main__":
    sys.exit(main())
