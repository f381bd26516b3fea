"""The ONNX sentence model: same vectors as sentence-transformers, no torch
on the run-time path, nothing of the language stack when planning from goals."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import numpy as np
import pytest

from lgmcts.language.embed import (
    DIM,
    META_FILE,
    MIN_COSINE,
    ONNX_FILE,
    OnnxEncoder,
    find_artefact,
    mean_pool,
    source_info,
)

from .conftest import CASES, ROOT

PY = sys.executable
TABLETOP = str(ROOT / "examples" / "tabletop.json")
HEAVY = ("torch", "transformers", "sentence_transformers", "sklearn")
LANGUAGE = ("onnxruntime", "tokenizers", "lgmcts.language.embed", "lgmcts.language.matcher", "lgmcts.language.rules")


def _evaluation_sentences() -> list[str]:
    """Every instruction of the labelled set, every pattern key, and a few odd strings."""
    from lgmcts.language.matcher import pattern_infos

    out = [json.loads(line).get("instruction") for line in CASES.read_text().splitlines()]
    out = [t for t in out if t]
    out += [k for info in pattern_infos().values() for k in info.keys]
    out += ["", "a", "!!!", "the " * 300, "Ünïcödé blöck — ½ turn"]
    return list(dict.fromkeys(out))


@pytest.fixture(scope="module")
def onnx_raw():
    """The exported model itself (the stored key table switched off)."""
    return OnnxEncoder(precomputed=False)


@pytest.mark.slow
def test_onnx_embeddings_agree_with_sentence_transformers(onnx_raw):
    import torch
    from sentence_transformers import SentenceTransformer

    from lgmcts.language.embed import weights_path

    texts = sorted(_evaluation_sentences(), key=len)  # batches of similar lengths pad little
    assert len(texts) > 300
    torch.set_num_threads(1)
    ref_model = SentenceTransformer(str(weights_path()), device="cpu", local_files_only=True)
    ref = ref_model.encode(texts, normalize_embeddings=True, convert_to_numpy=True, batch_size=32, show_progress_bar=False)
    got = np.concatenate([onnx_raw.encode(texts[i : i + 32]) for i in range(0, len(texts), 32)])
    cos = np.sum(ref * got, axis=1)
    worst = int(np.argmin(cos))
    assert cos[worst] >= MIN_COSINE, (texts[worst], float(cos[worst]))
    # The stored key table (used for the pattern keys) agrees as well.
    from lgmcts.language.matcher import pattern_infos

    keys = list(dict.fromkeys(k for info in pattern_infos().values() for k in info.keys))
    table = OnnxEncoder().encode(keys)
    expect = got[[texts.index(k) for k in keys]]
    assert np.min(np.sum(table * expect, axis=1)) >= MIN_COSINE


def test_vectors_are_unit_and_independent_of_batch_padding(onnx_raw):
    short, long_ = "a red block", "put every block in a long straight line to the left of the big white bowl"
    alone = onnx_raw.encode([short])
    batch = onnx_raw.encode([long_, short, ""])
    assert batch.shape == (3, DIM) and batch.dtype == np.float32
    assert np.allclose(np.linalg.norm(batch, axis=1), 1.0, atol=1e-5)
    assert float(alone[0] @ batch[1]) > 0.99999
    assert onnx_raw.encode([]).shape == (0, DIM)
    # Same text, same vector, run after run (no sampling, no state).
    assert np.array_equal(onnx_raw.encode([long_]), onnx_raw.encode([long_]))


def test_mean_pool_ignores_padding_and_normalises():
    hidden = np.zeros((2, 3, 2), np.float32)
    hidden[0] = [[1, 0], [3, 0], [100, 100]]  # last token is padding
    hidden[1] = [[0, 2], [0, 2], [0, 2]]
    mask = np.array([[1, 1, 0], [1, 1, 1]])
    out = mean_pool(hidden, mask)
    assert np.allclose(out, [[1, 0], [0, 1]])
    # An all-padding row is zero, not NaN.
    assert np.all(np.isfinite(mean_pool(hidden[:1], np.zeros((1, 3), int))))


def test_a_stale_or_partial_export_is_not_used(tmp_path, monkeypatch):
    monkeypatch.setenv("LGMCTS_EMBED_DIR", str(tmp_path))
    assert find_artefact() is None  # empty folder
    (tmp_path / ONNX_FILE).write_bytes(b"x")
    assert find_artefact() is None  # no metadata
    (tmp_path / META_FILE).write_text(json.dumps({"source": {**source_info(), "weights_bytes": 1}}))
    assert find_artefact() is None  # made from other weights
    (tmp_path / META_FILE).write_text(json.dumps({"source": source_info()}))
    assert find_artefact() == tmp_path


def test_installed_export_records_its_check():
    folder = find_artefact()
    assert folder is not None, "run `python -m lgmcts.language.export` (make install does)"
    meta = json.loads((folder / META_FILE).read_text())
    assert meta["check_min_cosine"] >= MIN_COSINE
    assert len(meta["onnx_sha256"]) == 64 and len(meta["weights_sha256"]) == 64


@pytest.mark.slow
def test_export_is_deterministic(tmp_path):
    """A fresh export gives the same bytes as the installed one."""
    installed = find_artefact()
    assert installed is not None
    r = subprocess.run(
        [PY, "-m", "lgmcts.language.export", "--out", str(tmp_path / "x"), "--quiet"],
        capture_output=True, text=True, cwd=ROOT, timeout=600,
    )
    assert r.returncode == 0, r.stderr
    a = json.loads((installed / META_FILE).read_text())
    b = json.loads((tmp_path / "x" / META_FILE).read_text())
    assert a["onnx_sha256"] == b["onnx_sha256"] and a["optimised_sha256"] == b["optimised_sha256"]
    assert (installed / "known.npz").read_bytes() == (tmp_path / "x" / "known.npz").read_bytes()


_PROBE = (
    "import atexit, json, os, runpy, sys\n"
    "atexit.register(lambda: open(os.environ['PROBE_OUT'], 'w').write(json.dumps(sorted(sys.modules))))\n"
    "sys.argv = ['lgmcts'] + sys.argv[1:]\n"
    "runpy.run_module('lgmcts', run_name='__main__')\n"
)


def _modules_after(tmp_path, *args: str) -> tuple[subprocess.CompletedProcess, set[str]]:
    out = tmp_path / "modules.json"
    env = dict(os.environ, PROBE_OUT=str(out))
    r = subprocess.run([PY, "-c", _PROBE, *args], capture_output=True, text=True, cwd=ROOT, env=env, timeout=300)
    return r, set(json.loads(out.read_text()))


def _loaded(mods: set[str], roots: tuple[str, ...]) -> list[str]:
    return sorted(m for m in mods if any(m == r or m.startswith(r + ".") for r in roots))


@pytest.mark.slow
def test_cli_parse_runs_without_torch_or_transformers(tmp_path):
    r, mods = _modules_after(tmp_path, "parse", TABLETOP, "put all blocks in a circle and the white bottle behind one block")
    assert r.returncode == 0, r.stderr
    assert json.loads(r.stdout)["goals"][0]["pattern"] == "circle"
    assert "onnxruntime" in mods  # the probe sees what was loaded
    assert _loaded(mods, HEAVY) == []


def test_cli_plan_from_a_goal_file_loads_no_language_stack(tmp_path):
    r, mods = _modules_after(tmp_path, "plan", TABLETOP, "--goal", str(ROOT / "examples" / "goals.json"), "--max-iter", "300")
    assert r.returncode in (0, 1), r.stderr
    assert json.loads(r.stdout)["actions"] is not None
    assert _loaded(mods, HEAVY + LANGUAGE) == []


def test_a_full_phrase_cache_is_emptied_without_losing_the_phrases_asked_for():
    """Some phrases found in the cache and some new ones that fill it: the cache is emptied before the new ones
    are stored, and the answer still holds every phrase asked for (it raised KeyError)."""
    from lgmcts.language.matcher import Encoder

    calls: list[list[str]] = []

    class Model:
        def encode(self, texts):
            calls.append(list(texts))
            return [np.full(384, len(t), np.float32) for t in texts]

    enc = Encoder(cache_size=3)
    enc._model = Model()
    first = enc.encode(["a", "bb"])
    got = enc.encode(["a", "ccc", "dddd", "a"])
    assert got.shape == (4, 384)
    assert [float(v[0]) for v in got] == [1.0, 3.0, 4.0, 1.0]
    assert float(first[1][0]) == 2.0
    assert calls == [["a", "bb"], ["ccc", "dddd"]]
