"""The planning service: an HTTP API over the planner (``lgmcts serve``).

``create_app(ServiceOptions(...))`` builds the FastAPI application; run it
with uvicorn. Planning, parsing and checking run in a process pool
(:class:`WorkerPool`), so the event loop never plans and a crashing planner
costs one request, not the service. See ``docs/service.md``.
"""

from .app import ServiceOptions, create_app
from .pool import JobTimeout, WorkerCrashed, WorkerPool

__all__ = ["ServiceOptions", "create_app", "WorkerPool", "JobTimeout", "WorkerCrashed"]
