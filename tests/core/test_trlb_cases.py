"""TRLB's instance files (disc arrangements in a 1000-unit square) as planning cases."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

from lgmcts import InputError, check, plan
from lgmcts.casegen import TRLB_UNIT, read_trlb_arrangement, trlb_case, trlb_pairs
from lgmcts.scene import Scene


def _write(folder, k: int, n: int, d: float, pts, radius: float) -> None:
    cell = folder / f"D={d}" / f"n={n}"
    cell.mkdir(parents=True, exist_ok=True)
    (cell / f"{k}_{n}_{d}.json").write_text(json.dumps({
        "Object_Radius": radius, "Object_Shape": "disc", "Workspace_Density": d, "Workspace_Height": 1000,
        "Workspace_Width": 1000, "number_of_objects": n, "point_list": [list(map(float, p)) for p in pts]}))


def _grid(n: int, radius: float, shift: int) -> list:
    # n discs on a grid with room to spare, the order rotated by ``shift``.
    cols = math.ceil(math.sqrt(n))
    step = 1000 / cols
    pts = [((i % cols + 0.5) * step, (i // cols + 0.5) * step) for i in range(n)]
    return pts[shift:] + pts[:shift]


def test_pairs_follow_file_numbers_and_cells(tmp_path):
    r = math.sqrt(0.2 * 1e6 / math.pi / 4)
    for k in range(5):
        _write(tmp_path, k, 4, 0.2, _grid(4, r, k % 4), r)
    _write(tmp_path, 0, 9, 0.4, _grid(9, 20, 0), 20)  # a lone file: no pair
    pairs = trlb_pairs(tmp_path, pairs=5)
    assert [(d, n, s.name, g.name) for d, n, (s, g) in pairs] == [
        (0.2, 4, "0_4_0.2.json", "1_4_0.2.json"), (0.2, 4, "2_4_0.2.json", "3_4_0.2.json")]
    assert len(trlb_pairs(tmp_path, pairs=1)) == 1


def test_case_scales_units_and_pairs_points_by_index(tmp_path):
    r = 100.0
    _write(tmp_path, 0, 4, 0.2, _grid(4, r, 0), r)
    _write(tmp_path, 1, 4, 0.2, _grid(4, r, 1), r)
    c = trlb_case(*trlb_pairs(tmp_path)[0][2])
    assert tuple(c.scene.workspace.x) == (0.0, 1.0) and tuple(c.scene.workspace.y) == (0.0, 1.0)
    starts = np.array([o.pose[:2] for o in c.scene.objects])
    goals = np.array([g.pose[:2] for g in c.goals.goals])
    np.testing.assert_allclose(starts * 1000, _grid(4, r, 0))
    np.testing.assert_allclose(goals * 1000, _grid(4, r, 1))
    assert all(o.shape.type == "cylinder" and o.shape.radius == pytest.approx(r * TRLB_UNIT) for o in c.scene.objects)
    assert [g.objects for g in c.goals.goals] == [[1], [2], [3], [4]]
    p = plan(c.scene, c.goals, seed=0)
    assert p.solved and check(c.scene, c.goals, p).valid


def test_disc_touching_the_edge_is_inside_the_workspace(tmp_path):
    # TRLB keeps disc footprints inside its square; a disc whose edge touches
    # the border there is inside the workspace here too.
    r = 150.0
    pts = [(r, r), (1000 - r, 1000 - r)]
    _write(tmp_path, 0, 2, 0.2, pts, r)
    _write(tmp_path, 1, 2, 0.2, pts[::-1], r)
    c = trlb_case(*trlb_pairs(tmp_path)[0][2])
    sc = Scene.from_spec(c.scene)
    p = plan(c.scene, c.goals, seed=0)
    assert p.solved and check(sc, c.goals, p).valid


@pytest.mark.parametrize("content, needle", [
    ("not json", "not a TRLB arrangement"),
    (json.dumps({"Object_Radius": 10}), "not a TRLB arrangement"),
    (json.dumps({"Object_Radius": -1, "Object_Shape": "disc", "Workspace_Density": 0.2, "Workspace_Height": 1000,
                 "Workspace_Width": 1000, "number_of_objects": 1, "point_list": [[5, 5]]}), "positive"),
    (json.dumps({"Object_Radius": 1, "Object_Shape": "stick", "Workspace_Density": 0.2, "Workspace_Height": 1000,
                 "Workspace_Width": 1000, "number_of_objects": 1, "point_list": [[5, 5]]}), "only disc"),
    (json.dumps({"Object_Radius": 1, "Object_Shape": "disc", "Workspace_Density": 0.2, "Workspace_Height": 1000,
                 "Workspace_Width": 1000, "number_of_objects": 2, "point_list": [[5, 5]]}), "number_of_objects"),
])
def test_bad_files_are_one_line_errors(tmp_path, content, needle):
    f = tmp_path / "x.json"
    f.write_text(content)
    with pytest.raises(InputError, match=needle) as e:
        read_trlb_arrangement(f)
    assert "\n" not in str(e.value)


def test_mismatched_pair_and_missing_folder_are_refused(tmp_path):
    _write(tmp_path, 0, 2, 0.2, [(100, 100), (500, 500)], 50)
    _write(tmp_path, 1, 3, 0.2, [(100, 100), (500, 500), (800, 800)], 50)
    with pytest.raises(InputError, match="not a start/goal pair"):
        trlb_case(tmp_path / "D=0.2/n=2/0_2_0.2.json", tmp_path / "D=0.2/n=3/1_3_0.2.json")
    with pytest.raises(InputError, match="no such folder"):
        trlb_pairs(tmp_path / "missing")
    with pytest.raises(InputError, match="no TRLB arrangement pairs"):
        trlb_pairs(tmp_path / "D=0.2")
