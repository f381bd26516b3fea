"""Memory and time of the viewer data (/view, ``viz --html``) and the validator (/check) near the format's bounds.

    python benchmarks/view_budget.py

Each case: peak traced memory (tracemalloc) and wall time of
``lgmcts.validate.check`` and ``lgmcts.viz.viewer_data``, and the size of the
/view answer; a case past a cap reports its one-line refusal.
"""

from __future__ import annotations

import json
import time
import tracemalloc

from lgmcts import limits
from lgmcts.errors import InputError
from lgmcts.validate import check
from lgmcts.viz.html import viewer_data


def boxes_and_moves(n: int, m: int, half: float = 10.0) -> tuple[dict, dict, dict]:
    side = int((2 * n) ** 0.5) + 2
    pitch = 2 * half / (side + 1)
    spots = [(-half + pitch * (1 + i), -half + pitch * (1 + j)) for i in range(side) for j in range(side)]
    objects = [{"id": k + 1, "name": "box", "shape": {"type": "box", "size": [pitch / 3] * 3}, "pose": [*spots[k], 0.0]}
               for k in range(n)]
    free, where, actions = list(range(n, len(spots))), list(range(n)), []
    for k in range(m):
        o = (k * 7919) % n
        s = free.pop(0)
        free.append(where[o])
        where[o] = s
        actions.append({"object": o + 1, "to": [*spots[s], 0.0], "purpose": "relocate"})
    goals = {"goals": [{"pattern": "line", "objects": [1, 2, 3]}]}
    return ({"workspace": {"x": [-half, half], "y": [-half, half]}, "objects": objects}, goals,
            {"solved": False, "actions": actions})


def measure(fn, *args, **kwargs) -> tuple[object, float, float]:
    tracemalloc.start()
    t0 = time.perf_counter()
    try:
        out = fn(*args, **kwargs)
    except InputError as exc:
        out = exc
    dt = time.perf_counter() - t0
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return out, dt, peak / 2**20


def main() -> None:
    cases = [(1000, 1000), (2000, 2000), (5000, 1990), (100, 99_000), (5000, 100_000)]
    print("| objects | actions | /check peak MiB | /check s | /view peak MiB | /view s | /view answer |")
    print("|---:|---:|---:|---:|---:|---:|---|")
    for n, m in cases:
        scene, goals, plan = boxes_and_moves(n, m, half=limits.MAX_COORD if n == 5000 else 10.0)
        if n * (m + 1) > 4 * limits.MAX_VIEW_CELLS:
            chk = "not run | not run"  # minutes of replay; the service's timeout ends it
        else:
            _, c_dt, c_peak = measure(check, scene, goals, plan)
            chk = f"{c_peak:.0f} | {c_dt:.1f}"
        data, v_dt, v_peak = measure(viewer_data, scene, plan, goals=goals)
        answer = f"refused: {data}" if isinstance(data, InputError) else f"{len(json.dumps(data)) / 2**20:.1f} MiB"
        print(f"| {n} | {m} | {chk} | {v_peak:.0f} | {v_dt:.1f} | {answer} |")


if __name__ == "__main__":
    main()
