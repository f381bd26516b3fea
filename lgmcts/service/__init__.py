"""The planning service: an HTTP API over the planner (``lgmcts serve``).

``create_app(ServiceOptions(...))`` builds the FastAPI application; run it
with uvicorn. Planning, parsing and checking run in process pools
(:class:`WorkerPool`), so the event loop never plans and a crashing planner
costs one request, not the service. See ``docs/service.md``.

The names below load on first use, so that ``lgmcts`` commands other than
``serve`` never import FastAPI.
"""

from __future__ import annotations

from ..lazy import lazy_names

__all__ = ["ServiceOptions", "create_app", "WorkerPool", "JobTimeout", "WorkerCrashed", "LoadReport", "fire"]

_WHERE = {
    "ServiceOptions": ".app",
    "create_app": ".app",
    "WorkerPool": ".pool",
    "JobTimeout": ".pool",
    "WorkerCrashed": ".pool",
    "LoadReport": ".load",
    "fire": ".load",
}


__getattr__, __dir__ = lazy_names(__name__, _WHERE)
