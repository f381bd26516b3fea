"""Load benchmark of the planning service.

Starts ``python -m lgmcts.service`` on a free loopback port (or uses ``--url``),
sends a few warm-up requests, then N ``POST /plan`` requests with at most C in
flight (request i uses seed i), and prints the count, the failures and the
median and p95 latency.

Example::

    .venv/bin/python benchmarks/service_load.py --n 200 --concurrency 8 --workers 2
"""

from __future__ import annotations

import argparse
import datetime as dt
import json
import os
import platform
import socket
import subprocess
import sys
import time
from pathlib import Path

import httpx

from lgmcts.service.load import fire

ROOT = Path(__file__).resolve().parents[1]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def _start(workers: int, timeout: float) -> tuple[subprocess.Popen, str]:
    port = _free_port()
    cmd = [
        sys.executable, "-m", "lgmcts.service", "--port", str(port), "--workers", str(workers),
        "--timeout", str(timeout), "--log-level", "warning",
    ]
    proc = subprocess.Popen(cmd, cwd=ROOT)
    url = f"http://127.0.0.1:{port}"
    t_end = time.monotonic() + 120
    while time.monotonic() < t_end:
        if proc.poll() is not None:
            sys.exit(f"the service exited with status {proc.returncode}")
        try:
            if httpx.get(url + "/healthz", timeout=1).status_code == 200:
                return proc, url
        except httpx.TransportError:
            pass
        time.sleep(0.1)
    proc.kill()
    sys.exit("the service did not start within 120 s")


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--n", type=int, default=200, help="number of measured requests")
    ap.add_argument("--concurrency", "-c", type=int, default=8, help="requests in flight at once")
    ap.add_argument("--workers", type=int, default=os.cpu_count() or 1, help="service worker processes")
    ap.add_argument("--scene", type=Path, default=ROOT / "examples" / "tabletop.json")
    ap.add_argument("--goals", type=Path, default=ROOT / "examples" / "goals.json")
    ap.add_argument("--method", default="lgmcts")
    ap.add_argument("--max-iter", type=int, default=10_000)
    ap.add_argument("--timeout", type=float, default=30.0, help="the service's request timeout (s)")
    ap.add_argument("--warmup", type=int, default=8, help="unmeasured requests first")
    ap.add_argument("--url", help="use a running service instead of starting one")
    ap.add_argument("--json", action="store_true", help="print the report as JSON")
    args = ap.parse_args(argv)

    scene = json.loads(args.scene.read_text())
    goals = json.loads(args.goals.read_text())

    def body(i: int) -> dict:
        return {
            "scene": scene,
            "goals": goals,
            "options": {"method": args.method, "seed": i, "max_iter": args.max_iter},
        }

    proc = None
    url = args.url
    if url is None:
        proc, url = _start(args.workers, args.timeout)
    try:
        if args.warmup:
            fire(url, body, n=args.warmup, concurrency=min(args.concurrency, args.warmup))
        report = fire(url, body, n=args.n, concurrency=args.concurrency)
    finally:
        if proc is not None:
            proc.terminate()
            proc.wait(timeout=30)
    meta = {
        "date_utc": dt.datetime.now(dt.UTC).strftime("%Y-%m-%d %H:%M"),
        "machine": f"{platform.machine()} {os.cpu_count()} CPUs, {platform.system()} {platform.release()}",
        "python": platform.python_version(),
        "workers": args.workers if args.url is None else "external",
        "scene": str(args.scene),
        "goals": str(args.goals),
        "method": args.method,
        "max_iter": args.max_iter,
        "concurrency": args.concurrency,
    }
    if args.json:
        out = {
            **meta,
            "count": report.count,
            "failures": report.failures,
            "unsolved": report.unsolved,
            "median_ms": round(report.median_s * 1e3, 2),
            "p95_ms": round(report.p95_s * 1e3, 2),
            "max_ms": round(report.max_s * 1e3, 2),
            "throughput_rps": round(report.throughput, 2),
            "statuses": report.statuses,
        }
        print(json.dumps(out, indent=2))
    else:
        print(" ".join(f"{k}={v}" for k, v in meta.items()))
        print(report.summary())
    for e in report.errors[:5]:
        print(e, file=sys.stderr)
    return 0 if report.failures == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
