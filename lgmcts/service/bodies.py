"""Request bodies: reading them, the operator's rules they must follow, and their one-line errors.

Everything here runs in a worker process (the intake pool, then the pool
that does the work), never in the process that serves HTTP: parsing a large
JSON body holds the interpreter for a tenth of a second or more, which would
stall every other request, ``GET /healthz`` included.
"""

from __future__ import annotations

import json
import math
from dataclasses import dataclass
from typing import Any

from pydantic import BaseModel, ValidationError

from .. import inputs
from ..errors import InputError
from ..limits import printable, truncate
from .models import CheckRequest, ParseRequest, PlanRequest, ViewRequest

__all__ = ["Policy", "Body", "parse_body", "validation_message", "read_body", "llm_endpoint", "MODELS"]

#: The request model of each route.
MODELS: dict[str, type[BaseModel]] = {
    "plan": PlanRequest,
    "parse": ParseRequest,
    "check": CheckRequest,
    "view": ViewRequest,
}


@dataclass(frozen=True)
class Policy:
    """The operator's rules a request body must follow (from :class:`~lgmcts.service.app.ServiceOptions`)."""

    test_hooks: bool = False
    max_iter: int = 10_000
    llm_base_url: str | None = None
    allow_client_llm_url: bool = False
    llm_models: tuple[str, ...] = ()


@dataclass(frozen=True)
class Body:
    """The raw body of a request to route ``kind`` and the rules it must follow."""

    kind: str
    raw: bytes
    policy: Policy


def _skip_loc(part: Any) -> bool:
    # pydantic inserts validator names ("function-after[...]") into locations.
    return isinstance(part, str) and part.startswith("function-")


def validation_message(errors: list[dict]) -> str:
    """One line for the first of FastAPI's body validation errors.

    Errors inside the ``scene``, ``goals`` and ``plan`` parts read exactly as
    the CLI's messages for the same file (``invalid scene at objects.0.pose:
    ...``); other fields read ``invalid request at options.seed: ...``.
    """
    if not errors:
        return "invalid request"
    first = errors[0]
    kind = first.get("type", "")
    loc = [p for p in first.get("loc", ()) if not _skip_loc(p)]
    if loc and loc[0] == "body":
        loc = loc[1:]
    if kind == "json_invalid":
        reason = (first.get("ctx") or {}).get("error", "")
        return f"invalid request: the body is not valid JSON{f' ({reason})' if reason else ''}"
    if kind == "missing" and not loc:
        return "invalid request: a JSON body is required"
    if kind in ("model_attributes_type", "dict_type", "model_type") and not loc:
        return "invalid request: the body must be a JSON object sent as Content-Type: application/json"
    if kind == "missing" and len(loc) == 1:
        return f"invalid request: '{loc[0]}' is required"
    what = "request"
    if loc and loc[0] in ("scene", "goals", "plan"):
        what, loc = str(loc[0]), loc[1:]
    msg = str(first.get("msg", "invalid value")).removeprefix("Value error, ")
    where = f" at {'.'.join(str(p) for p in loc)}" if loc else ""
    return f"invalid {what}{where}: {msg}"


def parse_body(model: type[BaseModel], raw: bytes) -> Any:
    """Validate a request body (bytes) into ``model``; :class:`InputError` with one line otherwise.

    The JSON rules are the file loaders' (:func:`lgmcts.inputs.loads`): an
    object naming a key twice or an integer too long to read is refused.
    """
    if not raw.strip():
        raise InputError("invalid request: a JSON body is required")
    try:
        data = inputs.loads(raw, "the body")
    except UnicodeDecodeError:
        raise InputError("invalid request: the body is not valid JSON (not UTF-8)") from None
    except json.JSONDecodeError as exc:
        raise InputError(f"invalid request: the body is not valid JSON ({exc.msg})") from None
    except InputError as exc:
        raise InputError(f"invalid request: {exc}") from None
    try:
        return model.model_validate(data)
    except ValidationError as err:
        raise InputError(validation_message([dict(e) for e in err.errors()])) from None
    except RecursionError:
        raise InputError("invalid request: the body is nested too deeply") from None


def llm_endpoint(policy: Policy, url: str | None, parser: str, model: str | None) -> tuple[str | None, str | None]:
    """The endpoint and key override of a request's LLM parse.

    The endpoint is server configuration. A client-named URL is refused
    unless the operator allowed it, and then never gets the server's key.
    With the server's endpoint (and key), the model is the operator's or one
    the operator listed (:attr:`Policy.llm_models`).
    """
    if url is None:
        if parser != "rules" and model is not None and model not in policy.llm_models:
            raise InputError(
                f"llm_model '{truncate(printable(model), 60)}' is not allowed: the server uses its operator's "
                "model (leave llm_model out), or those listed in LGMCTS_SERVICE_LLM_MODELS"
            )
        return policy.llm_base_url, None
    if not policy.allow_client_llm_url:
        raise InputError(
            "llm_base_url is chosen by the server's operator (lgmcts serve --llm-base-url), not by requests"
        )
    if not url.startswith(("http://", "https://")):
        raise InputError("llm_base_url must be an http:// or https:// URL")
    return url, "none"  # a placeholder: the server's own key never leaves for a client-chosen host


def _timeout(value: float | None) -> None:
    if value is not None and not (math.isfinite(value) and value > 0):
        raise InputError("timeout must be positive")


def read_body(body: Body) -> Any:
    """The validated request of ``body``, every rule checked; :class:`InputError` (422) otherwise."""
    from ..planner import METHODS
    from .jobs import HOOK_METHODS

    model = MODELS.get(body.kind)
    if model is None:
        raise ValueError(f"unknown route {body.kind!r}")
    req = parse_body(model, body.raw)
    pol = body.policy
    if isinstance(req, ParseRequest):
        _timeout(req.timeout)
        llm_endpoint(pol, req.llm_base_url, req.parser, req.llm_model)
    elif isinstance(req, PlanRequest):
        o = req.options
        if (req.goals is None) == (req.instruction is None):
            raise InputError("give either goals or an instruction, not both or neither")
        if req.goals is not None:
            req.goals.check_against(req.scene)
        if o.seed < 0:
            # numpy's generators take no negative seeds.
            raise InputError("seed must be a non-negative integer")
        if o.time_limit is not None and not (math.isfinite(o.time_limit) and o.time_limit > 0):
            raise InputError("time_limit must be positive")
        if o.method not in METHODS and not (pol.test_hooks and o.method in HOOK_METHODS):
            raise InputError(f"unknown method '{truncate(o.method, 40)}' (known: {', '.join(METHODS)})")
        _timeout(o.timeout)
        if req.instruction is not None:
            llm_endpoint(pol, req.llm_base_url, req.parser, req.llm_model)
    else:
        _timeout(req.timeout)
    return req
