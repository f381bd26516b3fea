"""Parse time per instruction once the sentence model is loaded.

Usage: python benchmarks/parse_speed.py CASES.jsonl [CASES.jsonl ...] [--split dev]

Runs every case of the files twice: the first pass ("first") meets each
phrase for the first time in this process (the encoder's phrase cache only
holds what earlier cases put there, as in a session), the second ("warm")
finds every phrase cached. Reports wall time and this process's CPU time
(user + system) per instruction: on a shared machine the CPU time is the
parser's own cost, the wall time adds the waiting for other processes.
"""

from __future__ import annotations

import argparse
import os
import statistics
import time

os.environ.setdefault("HF_HUB_OFFLINE", "1")


def _stats(xs: list[float]) -> str:
    xs = sorted(xs)
    p95 = xs[min(len(xs) - 1, round(0.95 * (len(xs) - 1)))]
    return (
        f"mean {1e3 * statistics.fmean(xs):.1f} ms, median {1e3 * statistics.median(xs):.1f} ms, p95 {1e3 * p95:.1f} ms"
    )


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("files", nargs="+")
    ap.add_argument("--split", default=None)
    args = ap.parse_args()
    from lgmcts.errors import InputError
    from lgmcts.language import parse
    from lgmcts.language.evaluate import load_cases
    from lgmcts.language.matcher import default_matcher

    cases = []
    for f in args.files:
        cases += [c for c in load_cases(f) if args.split is None or getattr(c, "split", None) == args.split]
    m = default_matcher()
    t0 = time.perf_counter()
    m.encoder.load()
    m.key_embeddings()
    print(
        f"{len(cases)} instructions; model load {time.perf_counter() - t0:.2f} s; load average {os.getloadavg()[0]:.1f}"
    )
    for name in ("first", "warm"):
        wall, cpu = [], []
        for c in cases:
            w0, c0 = time.perf_counter(), time.process_time()
            try:
                parse(c.scene, c.instruction)
            except InputError:
                pass
            wall.append(time.perf_counter() - w0)
            cpu.append(time.process_time() - c0)
        print(f"{name}: wall {_stats(wall)}; cpu {_stats(cpu)}")
    print(f"load average after: {os.getloadavg()[0]:.1f}")


if __name__ == "__main__":
    main()
