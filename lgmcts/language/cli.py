"""Command-line plug-in: ``lgmcts parse`` and ``lgmcts eval-parse``."""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path
from typing import Optional

import typer

from ..cli_util import check_output_file, fail, write_text
from ..errors import InputError

__all__ = ["register"]


def parse_cmd(
    scene: Path = typer.Argument(..., help="Scene JSON file."),
    instruction: str = typer.Argument(..., help="Plain-language command, e.g. \"put all blocks in a circle\"."),
    parser: str = typer.Option("rules", help="rules (offline, default) or llm (OpenAI-compatible endpoint)."),
    llm_model: Optional[str] = typer.Option(None, "--llm-model", help="Model name for --parser llm."),
    llm_base_url: Optional[str] = typer.Option(None, "--llm-base-url", help="OpenAI-compatible base URL."),
    output: Optional[str] = typer.Option(None, "-o", "--output", help="Write the goal JSON here (default stdout)."),
) -> None:
    """Turn INSTRUCTION into the goal JSON for SCENE (exit 0; 2 when not understood)."""
    from .. import formats
    from . import parse

    check_output_file(output)
    try:
        spec = formats.load_scene(scene)
        goals = parse(spec, instruction, parser=parser, llm_model=llm_model, llm_base_url=llm_base_url)
    except InputError as exc:
        fail(str(exc))
    write_text(formats.save_json(goals), output)


def eval_parse_cmd(
    cases: Path = typer.Argument(..., help="Case file (JSON Lines), e.g. data/parse_cases.jsonl."),
    parser: str = typer.Option("rules", help="rules or llm."),
    llm_model: Optional[str] = typer.Option(None, "--llm-model"),
    llm_base_url: Optional[str] = typer.Option(None, "--llm-base-url"),
    as_json: bool = typer.Option(False, "--json", help="Print the report as JSON."),
    min_accuracy: Optional[float] = typer.Option(None, "--min-accuracy", help="Exit 1 when accuracy is below this."),
    show: int = typer.Option(50, "--show", help="How many failures to list."),
    cold: bool = typer.Option(False, "--cold", help="Forget cached phrase embeddings before each case (timing)."),
    split: Optional[str] = typer.Option(None, "--split", help="Only the cases of this split: dev or test."),
) -> None:
    """Exact-goal accuracy of a parser on CASES, per category, with failures and parse speed."""
    from . import parse
    from .evaluate import evaluate, load_cases

    try:
        if split is not None and split not in ("dev", "test"):
            raise InputError(f"--split must be dev or test, not '{split}'")
        loaded = load_cases(cases, split=split)
        load_s = None
        if parser == "rules":
            from .matcher import default_matcher

            t0 = time.perf_counter()
            m = default_matcher()
            m.encoder.load()
            m.key_embeddings()
            load_s = time.perf_counter() - t0
        def run(s, t):
            if cold and parser == "rules":
                from .matcher import default_matcher

                default_matcher().encoder.clear_cache()
            return parse(s, t, parser=parser, llm_model=llm_model, llm_base_url=llm_base_url)

        report = evaluate(loaded, run)
        report.load_time_s = load_s
    except InputError as exc:
        fail(str(exc))
    data = report.to_dict()
    if as_json:
        typer.echo(json.dumps(data, indent=2))
    else:
        lines = [f"{data['correct']}/{data['cases']} correct: accuracy {100 * data['accuracy']:.1f}% ({parser} parser)"]
        lines.append(
            f"answered {data['answered']}, wrong goals {data['wrong_goals']} "
            f"({100 * data['wrong_goal_rate']:.1f}% of answered); refused {data['refused']}, "
            f"of which {data['wrongly_refused']} should have been answered"
        )
        if len(data["per_split"]) > 1 or "-" not in data["per_split"]:
            for sp, v in data["per_split"].items():
                lines.append(f"  split {sp:<16} {v['correct']:>4}/{v['total']:<4} {100 * v['accuracy']:6.1f}%")
        for cat, v in data["per_category"].items():
            lines.append(f"  {cat:<22} {v['correct']:>4}/{v['total']:<4} {100 * v['accuracy']:6.1f}%")
        t = data["parse_time"]
        if load_s is not None:
            lines.append(f"model load (incl. key embeddings): {load_s:.2f} s")
        if t:
            lines.append(
                f"parse time per instruction: mean {t['mean_ms']:.1f} ms, median {t['median_ms']:.1f} ms, "
                f"p95 {t['p95_ms']:.1f} ms, max {t['max_ms']:.1f} ms"
            )
        fails = data["failures"]
        if fails:
            lines.append(f"failures ({len(fails)}):")
            for f in fails[:show]:
                got = f["error"] if f["got"] is None else json.dumps(f["got"])
                lines.append(f"  [{f['id']}] {f['instruction']}")
                lines.append(f"      expected {json.dumps(f['expected'])}")
                lines.append(f"      got      {got}")
        typer.echo("\n".join(lines))
    sys.stdout.flush()
    if min_accuracy is not None and report.accuracy < min_accuracy:
        raise typer.Exit(1)


def register(app: typer.Typer) -> None:
    """Add ``parse`` and ``eval-parse`` to the ``lgmcts`` command line."""
    app.command("parse")(parse_cmd)
    app.command("eval-parse")(eval_parse_cmd)
