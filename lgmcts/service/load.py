"""A small load generator for the service (used by ``benchmarks/service_load.py`` and the tests).

:func:`fire` sends ``n`` POST requests with at most ``concurrency`` in flight
and reports the failures and the latency distribution. Latency is measured
per request on the client, from sending to the whole answer read (s).
"""

from __future__ import annotations

import asyncio
import time
from collections import Counter
from dataclasses import dataclass, field
from typing import Callable

import httpx
import numpy as np

__all__ = ["LoadReport", "fire", "fire_async"]


@dataclass(frozen=True)
class LoadReport:
    """Outcome of a load run.

    ``failures`` counts answers other than 200 and requests that got no
    answer; ``unsolved`` counts 200 answers whose plan has ``solved: false``.
    Latencies are in seconds; ``throughput`` in requests per second.
    """

    count: int
    failures: int
    unsolved: int
    statuses: dict[str, int]
    median_s: float
    p95_s: float
    max_s: float
    wall_s: float
    latencies_s: tuple[float, ...] = field(repr=False, default=())
    errors: tuple[str, ...] = field(repr=False, default=())

    @property
    def throughput(self) -> float:
        return self.count / self.wall_s if self.wall_s > 0 else float("nan")

    def summary(self) -> str:
        """One line: count, failures, median and p95 latency (ms), throughput."""
        return (
            f"count={self.count} failures={self.failures} unsolved={self.unsolved} "
            f"median_ms={self.median_s * 1e3:.1f} p95_ms={self.p95_s * 1e3:.1f} max_ms={self.max_s * 1e3:.1f} "
            f"throughput_rps={self.throughput:.1f} statuses={dict(sorted(self.statuses.items()))}"
        )


async def fire_async(
    url: str,
    body_for: Callable[[int], dict],
    *,
    n: int,
    concurrency: int,
    path: str = "/plan",
    timeout: float = 120.0,
) -> LoadReport:
    """Send ``n`` requests, ``body_for(i)`` the JSON body of request ``i``; see :func:`fire`."""
    if n < 1 or concurrency < 1:
        raise ValueError("n and concurrency must be at least 1")
    latencies: list[float] = []
    statuses: Counter[str] = Counter()
    errors: list[str] = []
    unsolved = 0
    next_index = 0

    async def worker(client: httpx.AsyncClient) -> None:
        nonlocal next_index, unsolved
        while next_index < n:
            i = next_index
            next_index += 1
            body = body_for(i)
            t0 = time.perf_counter()
            try:
                r = await client.post(path, json=body)
                data = r.json() if r.status_code == 200 else None
            except (httpx.HTTPError, ValueError) as exc:
                statuses[type(exc).__name__] += 1
                errors.append(f"request {i}: {type(exc).__name__}: {exc}")
                continue
            latencies.append(time.perf_counter() - t0)
            statuses[str(r.status_code)] += 1
            if r.status_code != 200:
                errors.append(f"request {i}: {r.status_code} {r.text[:200]}")
            elif isinstance(data, dict) and data.get("solved") is False:
                unsolved += 1

    limits = httpx.Limits(max_connections=concurrency, max_keepalive_connections=concurrency)
    t_start = time.perf_counter()
    async with httpx.AsyncClient(base_url=url, timeout=timeout, limits=limits) as client:
        await asyncio.gather(*(worker(client) for _ in range(min(concurrency, n))))
    wall = time.perf_counter() - t_start
    lat = np.asarray(latencies) if latencies else np.asarray([float("nan")])
    return LoadReport(
        count=n,
        failures=n - statuses.get("200", 0),
        unsolved=unsolved,
        statuses=dict(statuses),
        median_s=float(np.median(lat)),
        p95_s=float(np.percentile(lat, 95)),
        max_s=float(np.max(lat)),
        wall_s=wall,
        latencies_s=tuple(latencies),
        errors=tuple(errors),
    )


def fire(
    url: str,
    body_for: Callable[[int], dict],
    *,
    n: int,
    concurrency: int,
    path: str = "/plan",
    timeout: float = 120.0,
) -> LoadReport:
    """Send ``n`` POST requests to ``url + path`` with at most ``concurrency`` in flight.

    Parameters
    ----------
    url : base URL of the service, e.g. ``http://127.0.0.1:8000``.
    body_for : the JSON body of request ``i`` (``0 <= i < n``).
    n : number of requests.
    concurrency : requests in flight at once (one connection each).
    path : endpoint.
    timeout : client-side limit per request (s).
    """
    return asyncio.run(fire_async(url, body_for, n=n, concurrency=concurrency, path=path, timeout=timeout))
