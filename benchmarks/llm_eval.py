"""The LLM parser and LFSP measured on a local server (``make llm-eval``).

Starts llama-cpp-python's OpenAI-compatible server with Gemma 3 270M on
127.0.0.1 (:class:`lgmcts.language.local_llm.LocalServer`), then

1. runs every language evaluation set that exists (``data/parse_cases.jsonl``,
   ``data/peer_cases.jsonl``, ``data/paraphrase_cases.jsonl``) through
   ``--parser llm``, next to the offline parser on the same cases;
2. runs LFSP (``lgmcts bench --method lfsp``) on the first ``--lfsp-n`` tasks
   of the ``elgr`` and ``structformer`` suites (seed 0), next to ``lgmcts``
   on the same tasks (offline parser for elgr, ground-truth goals for
   structformer, as ``lgmcts bench`` does by default).

``--every K`` keeps every K-th case of each set (deterministic), for a
sample on a slow machine. Any other endpoint: ``--base-url URL --model NAME``
(the local server is then not started). Results go to ``--out`` (JSON,
per-set reports, bench records) and a summary is printed.
"""

from __future__ import annotations

import argparse
import json
import os
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SETS = ("data/parse_cases.jsonl", "data/peer_cases.jsonl", "data/paraphrase_cases.jsonl")


def _eval_set(path: Path, every: int, llm_opts, limit: int | None) -> dict:
    from lgmcts.language import parse
    from lgmcts.language.evaluate import evaluate, load_cases
    from lgmcts.language.llm import parse_llm

    cases = load_cases(path)[::every]
    if limit:
        cases = cases[:limit]
    t0 = time.perf_counter()
    llm = evaluate(cases, lambda s, t: parse_llm(s, t, options=llm_opts))
    llm_s = time.perf_counter() - t0
    rules = evaluate(cases, lambda s, t: parse(s, t))
    d = llm.to_dict()
    return {
        "set": str(path.relative_to(ROOT) if path.is_relative_to(ROOT) else path),
        "cases": len(cases),
        "every": every,
        "llm_correct": d["correct"],
        "llm_accuracy": d["accuracy"],
        "llm_per_category": {k: f"{v['correct']}/{v['total']}" for k, v in d["per_category"].items()},
        "llm_refused": sum(1 for r in llm.results if r.got is None),
        "llm_wall_s": round(llm_s, 1),
        "llm_median_s": round(sorted(r.time_s for r in llm.results)[len(cases) // 2], 2) if cases else None,
        "rules_correct": rules.to_dict()["correct"],
        "rules_accuracy": rules.accuracy,
        "llm_failures_sample": d["failures"][:5],
    }


def _bench(suite: str, n: int, out: Path, base_url: str, model: str) -> dict:
    from lgmcts.bench import RunOptions, generate, run_suite, summarise

    tasks = generate(suite, n=n, seed=0)
    res = {}
    parser = "gt" if suite == "structformer" else "rules"
    for method in ("lfsp", "lgmcts"):
        opts = RunOptions(method=method, parser=parser, llm_model=model, llm_base_url=base_url)
        recs = run_suite(tasks, out / f"{suite}-{method}", options=opts, workers=1, show_progress=False)
        row = summarise(recs)[-1]
        causes = {}
        for r in recs:
            if r.get("cause"):
                causes[r["cause"]] = causes.get(r["cause"], 0) + 1
        res[method] = {"tasks": row.tasks, "sr_p": row.sr_p, "sr_ep": row.sr_ep, "causes": causes}
    return res


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--every", type=int, default=1, help="keep every K-th case of each set")
    ap.add_argument("--limit", type=int, default=None, help="at most this many cases per set (after --every)")
    ap.add_argument("--lfsp-n", type=int, default=20, help="tasks per suite for LFSP (0: skip)")
    ap.add_argument("--sets", nargs="*", default=None, help="case files (default: those of the project that exist)")
    ap.add_argument("--no-sets", action="store_true", help="LFSP only")
    ap.add_argument("--out", type=Path, default=ROOT / "out" / "llm-eval")
    ap.add_argument("--base-url", default=None, help="an endpoint of your own instead of the local server")
    ap.add_argument("--model", default=None)
    a = ap.parse_args()
    import signal

    signal.signal(signal.SIGTERM, lambda *_: sys.exit(143))  # stop the server on kill, too
    from lgmcts.language.llm import LLMOptions
    from lgmcts.language.local_llm import MODEL_ALIAS, LocalServer, available

    a.out.mkdir(parents=True, exist_ok=True)
    sets = [Path(p) for p in (a.sets or [ROOT / s for s in SETS])]
    sets = [p for p in sets if p.is_file() and not a.no_sets]
    server = None
    if a.base_url is None:
        why = available()
        if why:
            print(f"error: {why}", file=sys.stderr)
            return 2
        server = LocalServer(log=a.out / "server.log").start()
        os.environ.update(server.env())
        base_url, model = server.base_url, MODEL_ALIAS
    else:
        base_url, model = a.base_url, a.model or os.environ.get("LGMCTS_LLM_MODEL")
    opts = LLMOptions(model=model, base_url=base_url, timeout=300)
    report: dict = {"endpoint": base_url, "model": model, "sets": [], "lfsp": {}}
    try:
        for p in sets:
            r = _eval_set(p, a.every, opts, a.limit)
            report["sets"].append(r)
            print(json.dumps({k: v for k, v in r.items() if k != "llm_failures_sample"}), flush=True)
        if a.lfsp_n > 0:
            for suite in ("elgr", "structformer"):
                report["lfsp"][suite] = _bench(suite, a.lfsp_n, a.out, base_url, model)
                print(json.dumps({suite: report["lfsp"][suite]}), flush=True)
    finally:
        if server is not None:
            server.stop()
    report["load_average_1min"] = round(os.getloadavg()[0], 2)
    (a.out / "report.json").write_text(json.dumps(report, indent=2) + "\n")
    print(f"report: {a.out / 'report.json'}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
