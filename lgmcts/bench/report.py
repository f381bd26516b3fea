"""Summaries of benchmark records: SR_p, SR_ep, parse accuracy, actions,
planning time and failures by cause, per category and overall, as Markdown
and CSV."""

from __future__ import annotations

import csv
import io
from collections import Counter
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .runner import CAUSES

__all__ = ["Row", "summarise", "to_csv", "to_markdown"]


@dataclass(frozen=True)
class Row:
    """Figures of one group of tasks (a category, or ``all``).

    Rates are fractions in [0, 1]; ``None`` where they do not apply (SR_ep
    of a run without execution, parse accuracy with ground-truth goals).
    Times are planning times in seconds.
    """

    group: str
    tasks: int
    sr_p: float
    sr_ep: float | None
    parse_acc: float | None
    mean_actions: float | None
    plan_median_s: float | None
    plan_p95_s: float | None
    causes: dict[str, int] = field(default_factory=dict)


def _row(group: str, recs: list[dict[str, Any]]) -> Row:
    n = len(recs)
    sr_p = sum(bool(r.get("sr_p")) for r in recs) / n
    ep = [r.get("sr_ep") for r in recs]
    sr_ep = None if all(v is None for v in ep) else sum(bool(v) for v in ep) / n
    pc = [(r.get("parse") or {}).get("correct") for r in recs]
    parse_acc = None if all(v is None for v in pc) else sum(bool(v) for v in pc) / n
    acts_or_none = [(r.get("planning") or {}).get("actions") for r in recs if r.get("sr_p")]
    acts = [a for a in acts_or_none if a is not None]
    times_or_none = [(r.get("planning") or {}).get("time_s") for r in recs]
    times = np.array([t for t in times_or_none if t is not None], dtype=float)
    causes = Counter(r["cause"] for r in recs if r.get("cause"))
    return Row(
        group=group,
        tasks=n,
        sr_p=sr_p,
        sr_ep=sr_ep,
        parse_acc=parse_acc,
        mean_actions=float(np.mean(acts)) if acts else None,
        plan_median_s=float(np.median(times)) if len(times) else None,
        plan_p95_s=float(np.percentile(times, 95)) if len(times) else None,
        causes=dict(sorted(causes.items(), key=lambda kv: (CAUSES.index(kv[0]) if kv[0] in CAUSES else 99, kv[0]))),
    )


def summarise(records: Iterable[dict[str, Any]]) -> list[Row]:
    """One row per category (sorted) and a last row ``all``; empty input gives no rows."""
    recs = list(records)
    if not recs:
        return []
    cats = sorted({r.get("category", "") for r in recs})
    rows = [_row(c or "-", [r for r in recs if r.get("category", "") == c]) for c in cats] if len(cats) > 1 else []
    rows.append(_row("all", recs))
    return rows


def _pct(v: float | None) -> str:
    return "n/a" if v is None else f"{100 * v:.1f}%"


def _num(v: float | None, fmt: str) -> str:
    return "n/a" if v is None else format(v, fmt)


def _causes(c: dict[str, int]) -> str:
    return ", ".join(f"{k}: {v}" for k, v in c.items()) or "none"


def to_markdown(rows: list[Row], *, title: str = "") -> str:
    """A Markdown table of ``rows``."""
    head = (
        "| group | tasks | SR_p | SR_ep | parse acc. | mean actions | plan time median (s) | plan time p95 (s) "
        "| failures by cause |"
    )
    sep = "|---|---:|---:|---:|---:|---:|---:|---:|---|"
    lines = [f"### {title}", ""] if title else []
    lines += [head, sep]
    for r in rows:
        lines.append(
            f"| {r.group} | {r.tasks} | {_pct(r.sr_p)} | {_pct(r.sr_ep)} | {_pct(r.parse_acc)} | "
            f"{_num(r.mean_actions, '.2f')} | {_num(r.plan_median_s, '.3f')} | {_num(r.plan_p95_s, '.3f')} | "
            f"{_causes(r.causes)} |"
        )
    return "\n".join(lines) + "\n"


def to_csv(rows: list[Row]) -> str:
    """The same figures as CSV, one column per failure cause."""
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(
        [
            "group",
            "tasks",
            "sr_p",
            "sr_ep",
            "parse_acc",
            "mean_actions",
            "plan_median_s",
            "plan_p95_s",
            *CAUSES,
            "other_failures",
        ]
    )
    for r in rows:
        other = sum(v for k, v in r.causes.items() if k not in CAUSES)
        w.writerow(
            [
                r.group,
                r.tasks,
                f"{r.sr_p:.4f}",
                "" if r.sr_ep is None else f"{r.sr_ep:.4f}",
                "" if r.parse_acc is None else f"{r.parse_acc:.4f}",
                "" if r.mean_actions is None else f"{r.mean_actions:.3f}",
                "" if r.plan_median_s is None else f"{r.plan_median_s:.4f}",
                "" if r.plan_p95_s is None else f"{r.plan_p95_s:.4f}",
                *[r.causes.get(c, 0) for c in CAUSES],
                other,
            ]
        )
    return buf.getvalue()
