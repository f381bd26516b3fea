"""Command-line plug-in: ``lgmcts bench-generate`` and ``lgmcts bench``."""

from __future__ import annotations

from pathlib import Path

import typer

from ..cli_util import fail
from ..errors import InputError

__all__ = ["register"]


_INSTRUCTIONS_HELP = "Instruction templates: ours (written for this parser) or peer (the peers' own templates)."


def _tasks(suite_arg: str, n: int | None, seed: int, instructions: str = "ours"):
    """Tasks and a source label from a suite name or a JSONL file."""
    from .suites import SUITES, generate
    from .tasks import read_suite

    if suite_arg in SUITES:
        label = f"{suite_arg}:seed={seed}" + ("" if instructions == "ours" else f":instructions={instructions}")
        return generate(suite_arg, n=n, seed=seed, instructions=instructions), label, suite_arg
    path = Path(suite_arg)
    if not path.suffix and not path.exists():
        raise InputError(f"unknown suite '{suite_arg}' (known: {', '.join(SUITES)}, or a .jsonl file)")
    if n is not None and n < 1:
        raise InputError("--n must be at least 1")
    tasks = read_suite(path, limit=n)
    return tasks, str(path.resolve()), tasks[0].suite


def bench_generate(
    suite: str = typer.Option(..., "--suite", help="elgr, elgr-dense or structformer."),
    n: int | None = typer.Option(None, "--n", help="Number of tasks (default: the full suite)."),
    seed: int = typer.Option(0, "--seed", help="Suite seed: 0 is the reported test suite, >= 1 for tuning."),
    category: str | None = typer.Option(None, "--category", help="Only tasks of this category."),
    output: Path = typer.Option(..., "-o", "--output", help="JSONL file to write."),
    instructions: str = typer.Option("ours", "--instructions", help=_INSTRUCTIONS_HELP),
) -> None:
    """Generate a benchmark suite as a JSONL file, one task per line."""
    from .suites import iter_generate
    from .tasks import write_suite

    try:
        count = write_suite(iter_generate(suite, n=n, seed=seed, category=category, instructions=instructions), output)
    except InputError as exc:
        fail(str(exc))
    typer.echo(f"wrote {count} {suite} tasks to {output}", err=True)


def bench(
    suite: str = typer.Option(..., "--suite", help="elgr, elgr-dense, structformer, or a suite JSONL file."),
    method: str = typer.Option(
        "lgmcts",
        help="lgmcts, greedy, pmcts, lfsp (the LLM proposes the poses; needs --llm-model), "
        "or module:function (your planner).",
    ),
    parser: str | None = typer.Option(None, help="rules, llm or gt (default: rules; gt for structformer)."),
    n: int | None = typer.Option(None, "--n", help="Run the first N tasks."),
    seed: int = typer.Option(0, "--seed", help="Suite seed when --suite names a suite."),
    workers: int | None = typer.Option(
        None, "--workers", help="Local processes (default and most: the CPUs this run may use)."
    ),
    ray: str | None = typer.Option(None, "--ray", help="Run as Ray tasks: 'local' or a cluster address."),
    max_iter: int = typer.Option(10_000, "--max-iter", help="Planner iteration budget per task."),
    time_limit: float | None = typer.Option(None, "--time-limit", help="Planner wall-clock budget per task (s)."),
    no_exec: bool = typer.Option(False, "--no-exec", help="Skip physics: report SR_p only."),
    llm_model: str | None = typer.Option(None, "--llm-model"),
    llm_base_url: str | None = typer.Option(None, "--llm-base-url"),
    output: Path = typer.Option(..., "-o", "--output", help="Output folder (an interrupted run there resumes)."),
    instructions: str = typer.Option("ours", "--instructions", help=_INSTRUCTIONS_HELP + " Only with a suite name."),
) -> None:
    """Run a planning method on a suite; write results.jsonl, summary.md and summary.csv to OUTPUT.

    SR_p: a plan was found within the budget and is valid against the
    ground-truth goals. SR_ep: that plan, executed in MuJoCo, ends in a state
    meeting them.
    """
    from .report import summarise, to_csv, to_markdown
    from .runner import RunOptions, check_workers, run_suite
    from .tasks import write_suite

    try:
        from .suites import SUITES

        if instructions != "ours" and suite not in SUITES:
            raise InputError("--instructions applies to a suite name; a suite file carries its own instructions")
        tasks, source, suite_name = _tasks(suite, n, seed, instructions)
        chosen = parser or ("gt" if suite_name == "structformer" else "rules")
        opts = RunOptions(
            method=method,
            parser=chosen,
            max_iter=max_iter,
            time_limit=time_limit,
            execute=not no_exec,
            llm_model=llm_model,
            llm_base_url=llm_base_url,
        )
        opts.check()
        check_workers(workers, ray)
        output.mkdir(parents=True, exist_ok=True)
        if suite in SUITES and not (output / "suite.jsonl").exists():
            write_suite(tasks, output / "suite.jsonl")
        records = run_suite(tasks, output, options=opts, workers=workers, ray_address=ray, source=source)
    except InputError as exc:
        fail(str(exc))
    except OSError as exc:
        fail(f"cannot write to {output}: {exc.strerror}")
    rows = summarise(records)
    if opts.method == "lfsp":
        title = f"{suite_name}: lfsp (the language model places the objects), model {opts.llm_model}"
    else:
        title = f"{suite_name}: {opts.method}, parser {opts.parser}, max_iter {opts.max_iter}"
    md = to_markdown(rows, title=title)
    (output / "summary.md").write_text(md + "\n" + _provenance() + "\n")
    (output / "summary.csv").write_text(to_csv(rows))
    typer.echo(md)


def _provenance() -> str:
    """The command line, date and machine, for the summary file."""
    import os
    import platform
    import shlex
    import sys
    import time

    cmd = shlex.join(["lgmcts", *sys.argv[1:]])
    return (
        f"Command: `{cmd}`; {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; "
        f"{platform.node()}, {os.cpu_count()} cores, Python {platform.python_version()}."
    )


def register(app: typer.Typer) -> None:
    """Add the benchmark commands to the ``lgmcts`` app."""
    app.command("bench-generate")(bench_generate)
    app.command("bench")(bench)
