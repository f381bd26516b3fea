"""How fast the offline parser answers: a cold command and a loaded parser.

Run with the project's interpreter::

    .venv/bin/python benchmarks/language_runtime.py [--runs 5] [--cases data/parse_cases.jsonl]

Figures (wall-clock):

* ``import_lgmcts_s`` -- ``python -c "import lgmcts"`` in a fresh process;
* ``cold_parse_s`` -- ``python -m lgmcts parse examples/tabletop.json "..."``
  in a fresh process (interpreter start, CLI, ONNX session, parse, JSON out);
  the two are run alternately, ``--runs`` times each, and their medians,
  minima and maxima are printed side by side so that machine load shows in both;
* ``plan_from_goals_s`` -- ``python -m lgmcts plan SCENE --goal GOALS`` in a
  fresh process (no language model involved), for reference;
* in this process, after the model is loaded (``load_s``: session and key
  embeddings): the time of one parse of every instruction of ``--cases``,
  once with the phrase cache cleared before each instruction (``cold_cache``:
  every phrase runs through the model) and once more with it warm;
* whether a parse process imported torch, transformers or sentence-transformers.
"""

from __future__ import annotations

import argparse
import json
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "examples" / "tabletop.json"
GOALS = ROOT / "examples" / "goals.json"
COMMAND = "Move all blocks into a circle; while put the white bottle behind one block"
HEAVY = ("torch", "transformers", "sentence_transformers")


def _wall(args: list[str]) -> float:
    t0 = time.perf_counter()
    r = subprocess.run(args, cwd=ROOT, capture_output=True, text=True)
    dt = time.perf_counter() - t0
    if r.returncode not in (0, 1):
        raise SystemExit(f"{' '.join(args)} failed: {r.stderr.strip().splitlines()[-1:]}")
    return dt


def _summary(xs: list[float], scale: float = 1.0, nd: int = 3) -> dict:
    xs = sorted(x * scale for x in xs)
    return {
        "median": round(statistics.median(xs), nd),
        "min": round(xs[0], nd),
        "max": round(xs[-1], nd),
        "p95": round(xs[min(len(xs) - 1, int(0.95 * len(xs)))], nd),
        "n": len(xs),
    }


def cold(runs: int) -> dict:
    py = sys.executable
    imp, parse, plan = [], [], []
    _wall([py, "-m", "lgmcts", "parse", str(SCENE), COMMAND])  # page cache: the first run of all reads the disk
    for _ in range(runs):
        imp.append(_wall([py, "-c", "import lgmcts"]))
        parse.append(_wall([py, "-m", "lgmcts", "parse", str(SCENE), COMMAND]))
        plan.append(_wall([py, "-m", "lgmcts", "plan", str(SCENE), "--goal", str(GOALS), "--max-iter", "2000"]))
    probe = (
        "import runpy, sys\n"
        f"sys.argv = ['lgmcts', 'parse', {str(SCENE)!r}, {COMMAND!r}]\n"
        "try:\n    runpy.run_module('lgmcts', run_name='__main__')\nexcept SystemExit:\n    pass\n"
        f"print([m for m in {HEAVY!r} if m in sys.modules], file=sys.stderr)\n"
    )
    r = subprocess.run([py, "-c", probe], cwd=ROOT, capture_output=True, text=True)
    return {
        "import_lgmcts_s": _summary(imp),
        "cold_parse_s": _summary(parse),
        "plan_from_goals_s": _summary(plan),
        "heavy_modules_in_parse": r.stderr.strip().splitlines()[-1] if r.stderr.strip() else "?",
    }


def loaded(cases_path: Path) -> dict:
    from lgmcts.errors import InputError
    from lgmcts.language import parse
    from lgmcts.language.evaluate import load_cases
    from lgmcts.language.matcher import default_matcher

    cases = load_cases(cases_path)
    t0 = time.perf_counter()
    m = default_matcher()
    m.encoder.load()
    m.key_embeddings()
    load_s = time.perf_counter() - t0
    out = {"load_s": round(load_s, 3), "cases": len(cases)}
    for label, clear in (("cold_cache", True), ("warm_cache", False)):
        times = []
        for c in cases:
            if clear:
                m.encoder.clear_cache()
            t = time.perf_counter()
            try:
                parse(c.scene, c.instruction)
            except InputError:
                pass
            times.append(time.perf_counter() - t)
        out[f"parse_ms_{label}"] = _summary(times, 1000.0, 2)
        out[f"parse_ms_{label}"]["mean"] = round(1000 * statistics.fmean(times), 2)
    return out


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=5)
    ap.add_argument("--cases", type=Path, default=ROOT / "data" / "parse_cases.jsonl")
    a = ap.parse_args()
    before = os.getloadavg()[0]
    res = {"cold": cold(a.runs), "loaded": loaded(a.cases)}
    res["load_average_1min"] = {"before": round(before, 2), "after": round(os.getloadavg()[0], 2)}
    res["python"] = sys.version.split()[0]
    print(json.dumps(res, indent=2))


if __name__ == "__main__":
    main()
