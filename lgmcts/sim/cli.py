"""``lgmcts execute`` and ``lgmcts observe``: the physics executor and the
camera at the command line."""

from __future__ import annotations

import json
from pathlib import Path

import typer

from ..cli_util import check_output_file, fail, write_text
from ..errors import InputError


def execute(
    scene: Path = typer.Argument(..., help="Scene JSON file."),
    plan: Path = typer.Argument(..., help="Plan JSON file."),
    goal: Path | None = typer.Option(None, "--goal", "-g", help="Goal JSON file (default: the plan's goals)."),
    video: Path | None = typer.Option(None, "--video", help="Write an mp4 of the execution here."),
    plan_scene: Path | None = typer.Option(
        None, "--plan-scene", help="The scene the plan was made on, when it differs from SCENE (e.g. an observed one)."
    ),
    as_json: bool = typer.Option(False, "--json", help="Print the outcome as JSON."),
    robot: str | None = typer.Option(
        None, "--robot", help="Execute with this arm (ur5e) instead of the floating suction cup."
    ),
) -> None:
    """Execute PLAN on SCENE in MuJoCo and judge the final state.

    Exit status: 0 success, 1 failure (a step failed or a rule is broken), 2 bad input.
    """
    from .executor import execute_plan

    check_output_file(video, make_parents=False)
    try:
        result = execute_plan(scene, plan, goal, video=video, plan_scene=plan_scene, robot=robot)
    except InputError as exc:
        fail(str(exc))
    except RuntimeError as exc:  # no OpenGL for the video
        fail(str(exc))
    if as_json:
        write_text(json.dumps(result.to_dict(), indent=2), None)
    else:
        for s in result.steps:
            mark = "ok  " if s.ok else "FAIL"
            typer.echo(f"{mark} action {s.index}: object {s.object}: {s.message}")
        typer.echo("success" if result.success else "failure")
        for r in result.reasons:
            typer.echo(f"  - {r}")
    if video is not None:
        typer.echo(f"wrote {video}", err=True)
    raise typer.Exit(0 if result.success else 1)


def observe(
    scene: Path = typer.Argument(..., help="Scene JSON file (the simulator's ground truth)."),
    output: str | None = typer.Option(None, "-o", "--output", help="Write the observed scene here (default stdout)."),
    width: int = typer.Option(640, help="Image width (pixels)."),
    height: int = typer.Option(480, help="Image height (pixels)."),
) -> None:
    """Render SCENE from a camera above the table and write the observed scene
    (objects as point clouds). The footprint IoU against SCENE goes to stderr."""
    from ..formats import save_json
    from .render import CameraOptions, footprint_iou
    from .render import observe as run_observe

    if width < 16 or height < 16:
        fail("image width and height must be at least 16 pixels")
    check_output_file(output)
    try:
        seen = run_observe(scene, options=CameraOptions(width=width, height=height))
        iou = footprint_iou(scene, seen)
    except InputError as exc:
        fail(str(exc))
    except RuntimeError as exc:
        fail(str(exc))
    write_text(save_json(seen), output)
    vals = list(iou.values())
    typer.echo(
        f"observed {len(seen.objects)} of {len(vals)} objects; footprint IoU mean {sum(vals) / len(vals):.3f}, "
        f"min {min(vals):.3f}",
        err=True,
    )


def register(app: typer.Typer) -> None:
    """Add the ``execute`` and ``observe`` commands to ``app``."""
    app.command()(execute)
    app.command()(observe)
