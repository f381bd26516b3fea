"""The ``lgmcts`` command line. Errors become exit codes here: 2 for bad
input (one line on stderr), 1 for a plan or check that did not succeed."""

from __future__ import annotations

import importlib
import json
import os
from pathlib import Path

import typer

from .cli_util import check_output_dir, check_output_file, configure_logging, fail, one_line, run_app, write_text
from .errors import InputError

app = typer.Typer(
    add_completion=False,
    no_args_is_help=True,
    pretty_exceptions_enable=False,
    help="Plan tabletop rearrangements from goals or plain-language commands.",
)

@app.callback()
def _root(
    pattern_module: list[str] = typer.Option(
        [],
        "--pattern-module",
        metavar="MODULE",
        help="Import a pattern module (a module name or a .py file) before the command; repeatable. "
        "Also read from LGMCTS_PATTERN_MODULES (':'-separated).",
    ),
) -> None:
    from .patterns import MODULES_ENV, load_pattern_modules

    try:
        load_pattern_modules(None)
        load_pattern_modules(pattern_module)
    except InputError as exc:
        fail(str(exc))
    if pattern_module:
        # Worker processes (the service's pools) load them from the environment.
        given = [str(Path(m).resolve()) if m.endswith(".py") else m for m in pattern_module]
        os.environ[MODULES_ENV] = os.pathsep.join([v for v in [os.environ.get(MODULES_ENV, "")] if v] + given)


_PLUGINS = ("lgmcts.language.cli", "lgmcts.sim.cli", "lgmcts.viz.cli", "lgmcts.service.cli", "lgmcts.bench.cli")


#: Default wall-clock budget of ``lgmcts plan`` (s). A plan that the
#: iteration budget would decide takes seconds on a tabletop; the limit only
#: stops searches that no budget ends in reasonable time (goals the planner
#: cannot meet but the pre-check cannot prove impossible). The library's
#: ``plan()`` has no default limit, so its plans depend on the seed alone.
PLAN_TIME_LIMIT = 120.0


@app.command()
def plan(
    scene: Path = typer.Argument(..., help="Scene JSON file."),
    instruction: str | None = typer.Argument(None, help="Plain-language command (instead of --goal)."),
    goal: Path | None = typer.Option(None, "--goal", "-g", help="Goal JSON file."),
    method: str = typer.Option("lgmcts", help="lgmcts, greedy or pmcts."),
    seed: int = typer.Option(0, help="Random seed; the same seed gives the same plan."),
    max_iter: int = typer.Option(10_000, "--max-iter", help="Iteration budget."),
    time_limit: float = typer.Option(
        PLAN_TIME_LIMIT, "--time-limit", help="Wall-clock budget in seconds; 0 for none (only --max-iter then)."
    ),
    anytime: bool = typer.Option(False, help="Keep searching within the budget for a shorter plan."),
    parser: str = typer.Option("rules", help="Instruction parser: rules or llm."),
    llm_model: str | None = typer.Option(None, "--llm-model"),
    llm_base_url: str | None = typer.Option(None, "--llm-base-url"),
    output: str | None = typer.Option(None, "-o", "--output", help="Write the plan JSON here (default stdout)."),
    viz: Path | None = typer.Option(None, "--viz", help="Write pictures of the plan into this folder."),
    robot: str | None = typer.Option(
        None, "--robot", help="Plan for this arm (ur5e): every pick and place within its reach."
    ),
    verbose: int = typer.Option(0, "-v", "--verbose", count=True, help="-v: search log, -vv: debug."),
) -> None:
    """Plan actions for SCENE towards --goal GOALS.json or an INSTRUCTION.

    Exit status: 0 solved, 1 not solved (the partial plan is still written), 2 bad input.
    Pictures that cannot be written (--viz on a full disk) are one line on
    stderr; the status stays the plan's, the plan being written.
    """
    from . import formats
    from .planner import plan as run_plan

    configure_logging(verbose)
    check_output_file(output)
    check_output_dir(viz)
    try:
        spec = formats.load_scene(scene)
        if (goal is None) == (instruction is None):
            fail("give either --goal GOALS.json or an instruction, not both or neither")
        if goal is not None:
            goals = formats.load_goals(goal)
        else:
            from .language import parse

            assert instruction is not None  # one of the two, checked above
            goals = parse(spec, instruction, parser=parser, llm_model=llm_model, llm_base_url=llm_base_url)
        limit = None if time_limit == 0 else time_limit
        result = run_plan(spec, goals, method=method, seed=seed, max_iter=max_iter, time_limit=limit, anytime=anytime,
                          robot=robot)
    except InputError as exc:
        fail(str(exc))
    if instruction is not None:
        result = result.model_copy(update={"instruction": instruction})
    write_text(formats.save_json(result), output)
    if viz is not None:
        from .viz import write_plan_figures

        try:
            paths = write_plan_figures(spec, result, viz, goals=goals, instruction=instruction)
            typer.echo(f"wrote {len(paths)} pictures to {viz}", err=True)
        except InputError as exc:
            # The plan is written; its exit status stays the plan's, the pictures' failure is one line.
            typer.echo(f"the plan was written but not its pictures: {one_line(exc)}", err=True)
    st = result.stats
    status = "solved" if result.solved else f"not solved ({st.get('reason', '')})"
    typer.echo(
        f"{status}: {len(result.actions)} actions, {st['iterations']} iterations, {st['time_s']:.3f} s", err=True
    )
    raise typer.Exit(0 if result.solved else 1)


@app.command()
def check(
    scene: Path = typer.Argument(..., help="Scene JSON file."),
    goals: Path = typer.Argument(..., help="Goal JSON file."),
    plan_file: Path = typer.Argument(..., metavar="PLAN", help="Plan JSON file."),
    as_json: bool = typer.Option(False, "--json", help="Print the verdict as JSON."),
    robot: str | None = typer.Option(
        None, "--robot", help="Also require every pick and place within this arm's reach (ur5e)."
    ),
) -> None:
    """Replay PLAN on SCENE and judge it against GOALS (exit 0 valid, 1 invalid, 2 bad input)."""
    from .validate import check as run_check

    try:
        verdict = run_check(scene, goals, plan_file, robot=robot)
    except InputError as exc:
        fail(str(exc))
    if as_json:
        typer.echo(json.dumps({"valid": verdict.valid, "reasons": list(verdict.reasons), "goals": list(verdict.goals)}))
    else:
        typer.echo("valid" if verdict.valid else "invalid")
        for r in verdict.reasons:
            typer.echo(f"  - {r}")
    raise typer.Exit(0 if verdict.valid else 1)


def _register_plugins() -> None:
    # The plug-in modules import only typer; what a command needs beyond the
    # base install loads when it runs (see main() for a missing extra).
    for name in _PLUGINS:
        importlib.import_module(name).register(app)


_register_plugins()


def main() -> None:
    """Entry point: run the app; usage errors and stray bad input become one line and exit 2."""
    run_app(app)


if __name__ == "__main__":
    main()
