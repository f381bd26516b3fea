"""Language: a plain-language command to a goal specification.

Two parsers share one pattern database (:func:`lgmcts.patterns.registry`):

* ``"rules"`` (default, offline, no key): clause splitting, object grounding
  against the scene's names and colours, and pattern choice by Sentence-BERT
  similarity with the database's keys (:mod:`.rules`, :mod:`.matcher`);
* ``"llm"``: any OpenAI-compatible Chat Completions endpoint, prompted with
  the pattern names and meanings from the same database, its answer
  validated against the scene and retried once (:mod:`.llm`).

Both return a :class:`lgmcts.formats.GoalSpec` or raise
:class:`lgmcts.errors.InputError` with one line saying what was not
understood. Nothing here imports torch: the sentence model runs in
onnxruntime (:mod:`.embed`) and is loaded on the first parse that needs it.
The LFSP baseline (:mod:`.lfsp`), in which the language model proposes the
poses itself, uses the same client as the LLM parser.
"""

from __future__ import annotations

import math
import os
from pathlib import Path
from typing import Any

from ..errors import InputError
from ..limits import MAX_INSTRUCTION, truncate
from ..formats import GoalSpec, SceneSpec, load_scene

__all__ = ["parse", "PARSERS"]

#: Names accepted by ``parse(..., parser=...)``.
PARSERS = ("rules", "llm")


def _scene(scene: Any) -> SceneSpec:
    if isinstance(scene, SceneSpec):
        return scene
    if isinstance(scene, (str, Path, dict)):
        return load_scene(scene)
    raise InputError(f"scene must be a SceneSpec, a dict or a path, not {type(scene).__name__}")


#: Environment variable: seconds to wait for one LLM answer (default 30).
LLM_TIMEOUT_ENV = "LGMCTS_LLM_TIMEOUT"


def llm_timeout(default: float = 30.0) -> float:
    """``$LGMCTS_LLM_TIMEOUT`` in seconds (else ``default``); anything but a positive finite number is one line."""
    raw = os.environ.get(LLM_TIMEOUT_ENV, "").strip()
    if not raw:
        return default
    try:
        value = float(raw)
    except ValueError:
        value = float("nan")
    if not (math.isfinite(value) and value > 0):
        raise InputError(f"{LLM_TIMEOUT_ENV} must be a positive number of seconds, got '{truncate(raw, 40)}'")
    return value


def parse(
    scene: Any,
    text: str,
    *,
    parser: str = "rules",
    llm_model: str | None = None,
    llm_base_url: str | None = None,
    api_key: str | None = None,
    timeout: float | None = None,
) -> GoalSpec:
    """Turn a command into goals over the objects of ``scene``.

    Parameters
    ----------
    scene : SceneSpec, dict or path
        The scene the command refers to.
    text : str
        The command, e.g. "Move all blocks into a circle; while put the white
        bottle behind one block".
    parser : {"rules", "llm"}
        Offline rule-based parser (default) or an LLM endpoint.
    llm_model, llm_base_url, api_key : str, optional
        Model name, OpenAI-compatible base URL and key for ``parser="llm"``
        (key default: the ``OPENAI_API_KEY`` environment variable).
    timeout : float, optional
        Seconds to wait for one LLM answer (default: ``LGMCTS_LLM_TIMEOUT``, else 30).

    Returns
    -------
    GoalSpec
        Goals that refer only to objects of ``scene``.

    Raises
    ------
    InputError
        The command names nothing in the scene, an unknown pattern, an empty
        or ambiguous selection, too few objects for a pattern, or a
        contradiction; the message is one line.
    """
    spec = _scene(scene)
    if not isinstance(text, str) or not text.strip():
        raise InputError("the instruction is empty")
    if len(text) > MAX_INSTRUCTION:
        raise InputError(f"the instruction is {len(text)} characters long; the limit is {MAX_INSTRUCTION}")
    if parser == "rules":
        from .matcher import default_matcher
        from .rules import parse_rules

        return parse_rules(spec, text, matcher=default_matcher())
    if parser == "llm":
        from .llm import LLMOptions, parse_llm

        if timeout is None:
            timeout = llm_timeout()
        opts = LLMOptions(model=llm_model, base_url=llm_base_url, api_key=api_key, timeout=timeout)
        return parse_llm(spec, text, options=opts)
    raise InputError(f"unknown parser '{truncate(str(parser), 40)}' (use: {', '.join(PARSERS)})")
