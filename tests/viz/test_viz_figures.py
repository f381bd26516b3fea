"""Pictures of a plan: which files, how many, and that they show something."""

from __future__ import annotations

import itertools
import json
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from lgmcts.errors import InputError
from lgmcts.formats import load_plan, load_scene
from lgmcts.scene import Scene
from lgmcts.validate import check
from lgmcts.viz import FigureOptions, heatmap_fields, write_plan_figures
from lgmcts.viz.model import goal_shapes, replay

pytestmark = pytest.mark.slow

DATA = Path(__file__).parent / "data"
SCENE = DATA / "cluttered_scene.json"
PLAN = DATA / "cluttered_plan.json"
FAST = FigureOptions(dpi=50, gif_width_px=320)


@pytest.fixture(scope="module")
def figures(tmp_path_factory):
    out = tmp_path_factory.mktemp("figs")
    paths = write_plan_figures(load_scene(SCENE), load_plan(PLAN), out, instruction="line up the blocks", options=FAST)
    return out, paths


def _colors(path: Path) -> int:
    img = np.asarray(Image.open(path).convert("RGB"), dtype=np.uint32)
    return len(np.unique((img[..., 0] << 16) | (img[..., 1] << 8) | img[..., 2]))


def test_the_golden_plan_is_valid_and_mixes_purposes():
    # The fixture plan must stay meaningful: valid, with an unstack and a relocation.
    assert check(SCENE, load_plan(PLAN).goals, PLAN).valid
    purposes = [a["purpose"] for a in json.loads(PLAN.read_text())["actions"]]
    assert {"goal", "unstack", "relocate"} <= set(purposes)


def test_one_picture_per_action_plus_overview(figures):
    out, paths = figures
    n = len(load_plan(PLAN).actions)
    names = [p.name for p in paths]
    assert names[0] == "initial.png"
    assert names[1 : n + 1] == [f"step_{k:02d}.png" for k in range(1, n + 1)]
    assert names[n + 1 :] == ["final.png", "before_after.png", "plan.gif", "heatmaps_step_01.png"]
    assert sorted(p.name for p in out.iterdir()) == sorted(names)
    assert all(p.stat().st_size > 0 for p in paths)


def test_pictures_are_not_blank(figures):
    _, paths = figures
    for p in paths:
        if p.suffix == ".png":
            assert _colors(p) > 40, p.name
            img = np.asarray(Image.open(p).convert("L"), dtype=float)
            assert img.std() > 10, p.name


def test_frames_share_one_size(figures):
    out, _ = figures
    sizes = {Image.open(p).size for p in out.glob("step_*.png")} | {Image.open(out / "initial.png").size}
    assert len(sizes) == 1


def test_consecutive_step_frames_differ(figures):
    out, _ = figures
    frames = [np.asarray(Image.open(p).convert("RGB"), dtype=int) for p in sorted(out.glob("step_*.png"))]
    for a, b in itertools.pairwise(frames):
        assert np.abs(a - b).sum() > 0


def test_gif_has_initial_frame_and_one_per_action(figures):
    out, _ = figures
    gif = Image.open(out / "plan.gif")
    assert gif.n_frames == len(load_plan(PLAN).actions) + 1
    assert gif.info.get("loop") == 0
    assert gif.size[0] == FAST.gif_width_px


def test_empty_plan_draws_initial_and_final_without_heatmaps(tmp_path):
    plan = {"solved": False, "actions": [], "goals": json.loads(PLAN.read_text())["goals"], "stats": {}}
    paths = write_plan_figures(SCENE, plan, tmp_path, options=FAST)
    assert [p.name for p in paths] == ["initial.png", "final.png", "before_after.png", "plan.gif"]
    assert Image.open(tmp_path / "plan.gif").n_frames == 1


def test_heatmap_step_is_chosen_and_checked(tmp_path):
    plan = json.loads(PLAN.read_text())
    plan["actions"] = plan["actions"][:3]  # a partial plan draws too; fewer frames keep this fast
    paths = write_plan_figures(SCENE, plan, tmp_path, heatmap_step=3, options=FAST)
    assert paths[-1].name == "heatmaps_step_03.png"
    assert _colors(paths[-1]) > 40
    with pytest.raises(InputError, match="outside the plan"):
        write_plan_figures(SCENE, PLAN, tmp_path, heatmap_step=0, options=FAST)


def test_unknown_object_in_plan_is_an_input_error(tmp_path):
    plan = json.loads(PLAN.read_text())
    plan["actions"][0]["object"] = 99
    with pytest.raises(InputError, match="unknown object id 99"):
        write_plan_figures(SCENE, plan, tmp_path, options=FAST)


@pytest.mark.parametrize("step", [1, 2, 3, 4, 5])
def test_heatmap_product_vanishes_off_free_space(step):
    f = heatmap_fields(SCENE, PLAN, step, resolution=0.01)
    assert f.prior.shape == f.free.shape == f.product.shape == (len(f.ys), len(f.xs))
    assert np.all(f.product[~f.free] == 0)
    assert np.allclose(f.product[f.free], f.prior[f.free])
    assert f.prior.min() >= 0 and f.prior.max() <= 1


def test_heatmap_is_positive_around_the_chosen_goal_pose():
    plan = load_plan(PLAN)
    for step, a in enumerate(plan.actions, start=1):
        if a.purpose != "goal":
            continue
        f = heatmap_fields(SCENE, PLAN, step, resolution=0.005)
        assert f.product.max() > 0
        i, j = np.argmin(abs(f.xs - a.to[0])), np.argmin(abs(f.ys - a.to[1]))
        assert f.product[max(j - 1, 0) : j + 2, max(i - 1, 0) : i + 2].max() > 0
        # The prior really constrains a goal placement: much of the free table is excluded.
        assert (f.product > 0).sum() < f.free.sum()


def test_replay_and_goal_shapes_follow_the_plan():
    scene = Scene.from_spec(load_scene(SCENE))
    plan = load_plan(PLAN)
    states = replay(scene, list(plan.actions))
    assert len(states) == len(plan.actions) + 1
    for a in plan.actions:
        last = [b for b in plan.actions if b.object == a.object][-1]
        assert np.allclose(states[-1].poses[scene.index[a.object]], last.to)
    final = goal_shapes(scene, plan.goals, states[-1])
    assert [s.kind for s in final] == ["line", "relation"] and all(s.met for s in final)
    first = goal_shapes(scene, plan.goals, states[0])
    assert not first[1].met and first[1].problem
    seg = final[0].geometry["points"]
    xy = states[-1].poses[[scene.index[i] for i in plan.goals.goals[0].objects], :2]
    # Every line member lies on the drawn segment's line, within the acceptance tolerance.
    u = (seg[1] - seg[0]) / np.linalg.norm(seg[1] - seg[0])
    d = np.abs((xy - seg[0]) @ np.array([-u[1], u[0]]))
    assert d.max() <= 0.015
