"""Where the sentence model's load time goes, in a fresh process.

Run with the project's interpreter (``.venv/bin/python benchmarks/model_load.py``);
each figure is a wall-clock interval in one process, in load order:

* ``import torch``;
* ``import sentence_transformers`` (after torch: transformers, scikit-learn,
  SciPy's statistics and torch's compiler and distributed modules come in here);
* building ``SentenceTransformer`` from the packaged model folder;
* embedding every pattern key once (what :class:`lgmcts.language.matcher.PatternMatcher` caches);
* the total, which is what a first ``lgmcts parse`` waits for.
"""

from __future__ import annotations

import json
import os
import time

os.environ.setdefault("HF_HUB_OFFLINE", "1")
os.environ.setdefault("TRANSFORMERS_OFFLINE", "1")


def main() -> None:
    t0 = time.perf_counter()
    import torch  # noqa: F401

    t1 = time.perf_counter()
    import sentence_transformers  # noqa: F401

    t2 = time.perf_counter()
    from lgmcts.language.matcher import Encoder, PatternMatcher

    enc = Encoder().load()
    t3 = time.perf_counter()
    PatternMatcher(enc).key_embeddings()
    t4 = time.perf_counter()
    print(json.dumps({
        "import_torch_s": round(t1 - t0, 2),
        "import_sentence_transformers_s": round(t2 - t1, 2),
        "build_model_s": round(t3 - t2, 2),
        "key_embeddings_s": round(t4 - t3, 2),
        "total_s": round(t4 - t0, 2),
        "load_average_1min": round(os.getloadavg()[0], 2),
    }))


if __name__ == "__main__":
    main()
