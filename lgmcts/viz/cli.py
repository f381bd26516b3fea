"""The ``lgmcts viz`` command: pictures and an HTML viewer of a saved plan."""

from __future__ import annotations

from pathlib import Path

import typer

from ..cli_util import check_output_dir, check_output_file, fail, write_text
from ..errors import InputError


def viz(
    plan_file: Path = typer.Argument(..., metavar="PLAN", help="Plan JSON file (as written by `lgmcts plan`)."),
    scene: Path = typer.Option(..., "--scene", "-s", help="Scene JSON file the plan starts from."),
    output: Path | None = typer.Option(
        None, "-o", "--output", help="Write the PNG pictures and plan.gif into this folder."
    ),
    html: Path | None = typer.Option(None, "--html", help="Write a self-contained HTML viewer to this file."),
    step: int | None = typer.Option(
        None,
        "--step",
        help="Action (counted from 1) whose pose-field heatmaps to draw; default the first goal placement.",
    ),
    goal: Path | None = typer.Option(
        None, "--goal", "-g", help="Goal JSON file; default the goals stored in the plan."
    ),
    instruction: str | None = typer.Option(None, "--instruction", help="Command text to show; default the plan's own."),
) -> None:
    """Draw PLAN on SCENE: PNGs, a GIF and heatmaps (-o DIR) and/or an HTML viewer (--html FILE).

    Exit status: 0 written, 2 bad input (one line on stderr).
    """
    from .. import formats

    if output is None and html is None:
        fail("nothing to write: give -o DIR for pictures and/or --html FILE for the viewer")
    if step is not None and output is None:
        fail("--step chooses the heatmap step of the pictures; give -o DIR as well")
    check_output_dir(output)
    check_output_file(html, make_parents=False)
    try:
        spec = formats.load_scene(scene)
        pl = formats.load_plan(plan_file)
        goals = formats.load_goals(goal) if goal is not None else None
        if output is not None:
            from .figures import write_plan_figures

            paths = write_plan_figures(spec, pl, output, goals=goals, instruction=instruction, heatmap_step=step)
            typer.echo(f"wrote {len(paths)} files to {output}", err=True)
        if html is not None:
            from .html import render_html

            page = render_html(spec, pl, instruction=instruction, goals=goals)
            write_text(page.removesuffix("\n"), str(html))
            typer.echo(f"wrote {html}", err=True)
    except InputError as exc:
        fail(str(exc))


def register(app: typer.Typer) -> None:
    """Add the ``viz`` command to the ``lgmcts`` command line."""
    app.command("viz")(viz)
