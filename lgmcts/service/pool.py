"""A process pool for planning jobs that survives crashed and hung workers.

:class:`WorkerPool` wraps :class:`concurrent.futures.ProcessPoolExecutor` for
use from an asyncio server:

* every job has a wall-clock deadline; past it the awaiting request gets
  :class:`JobTimeout` at once, and a job still queued is withdrawn;
* a worker that dies (segfault, ``os._exit``, the OOM killer) breaks a
  ``ProcessPoolExecutor`` and fails every job it held. The pool is replaced by
  a fresh one, and each failed job is run once more alone in a single-use
  process: a job that crashes again is the culprit and gets
  :class:`WorkerCrashed`; the bystanders get their results;
* a job still running ``grace`` seconds after its deadline is taken as hung:
  the pool is replaced and the old one's processes are killed, which sends its
  other jobs through the same retry.

Processes are started with ``forkserver`` where available (a fork of a server
that has already imported the planner, so a replacement pool is ready in
milliseconds) and ``spawn`` elsewhere; never plain ``fork`` from a process that
runs threads.
"""

from __future__ import annotations

import asyncio
import itertools
import logging
import multiprocessing
import os
import time
from concurrent.futures import Future, ProcessPoolExecutor
from concurrent.futures.process import BrokenProcessPool
from typing import Any, Callable

from . import jobs

__all__ = ["WorkerPool", "JobTimeout", "WorkerCrashed", "PRELOAD"]

log = logging.getLogger("lgmcts.service")

#: Modules the fork server imports once so that every worker starts warm.
#: How many abandoned job ids the workers can see at once (a ring: the oldest
#: falls out; by then its job has long been dropped).
WITHDRAWN_RING = 256

PRELOAD = ("lgmcts.formats", "lgmcts.scene", "lgmcts.validate", "lgmcts.planner", "lgmcts.service.jobs")


class JobTimeout(Exception):
    """The job did not finish before its deadline."""


class WorkerCrashed(Exception):
    """The worker process running the job died, also when the job ran alone."""


def _context(start_method: str | None) -> multiprocessing.context.BaseContext:
    if start_method is None:
        start_method = "forkserver" if "forkserver" in multiprocessing.get_all_start_methods() else "spawn"
    if start_method == "fork":
        raise ValueError("the 'fork' start method is unsafe in a threaded server; use forkserver or spawn")
    ctx = multiprocessing.get_context(start_method)
    if start_method == "forkserver":
        ctx.set_forkserver_preload(list(PRELOAD))
    return ctx


def _kill(executor: ProcessPoolExecutor) -> None:
    """Kill an executor's processes and shut it down without waiting."""
    # ProcessPoolExecutor has no public way to stop a running job before
    # Python 3.14 (terminate_workers); its process table is the only handle.
    procs = list((getattr(executor, "_processes", None) or {}).values())
    for p in procs:
        try:
            p.kill()
        except (OSError, ValueError, AttributeError):  # already gone or closed
            pass
    executor.shutdown(wait=False, cancel_futures=True)


class WorkerPool:
    """A replaceable process pool running :mod:`lgmcts.service.jobs` functions.

    Parameters
    ----------
    workers : number of worker processes (>= 1).
    grace : seconds a job may run past its deadline before its pool is
        declared hung, replaced and its processes killed.
    start_method : ``"forkserver"``, ``"spawn"`` or ``None`` (forkserver
        where the platform has it).
    name : what the pool runs, for log messages.
    """

    def __init__(self, *, workers: int, grace: float = 2.0, start_method: str | None = None, name: str = "worker") -> None:
        if workers < 1:
            raise ValueError("workers must be at least 1")
        self.name = name
        self.workers = workers
        self.grace = grace
        self._ctx = _context(start_method)
        self._executor: ProcessPoolExecutor | None = None
        self._generation = 0
        self.restarts = 0
        self._isolated: asyncio.Semaphore | None = None
        self._slots: Any = None
        self._pids: Any = None
        self._withdrawn: Any = None
        self._withdrawn_next = 0
        self._job_ids = itertools.count(1)
        #: Jobs dropped because their clients went away (running or queued).
        self.abandoned = 0

    # ------------------------------------------------------------ lifecycle

    def _new_executor(self) -> ProcessPoolExecutor:
        # Each worker publishes the id of the job it runs in its slot, so a
        # job past its deadline can be told running (maybe hung) from queued.
        # The pids let the pool stop one worker's job; ``withdrawn`` is a ring
        # of the ids of jobs whose clients went away.
        self._slots = self._ctx.Array("q", self.workers, lock=False)
        self._pids = self._ctx.Array("q", self.workers, lock=False)
        self._withdrawn = self._ctx.Array("q", WITHDRAWN_RING, lock=False)
        self._withdrawn_next = 0
        counter = self._ctx.Value("i", 0)
        return ProcessPoolExecutor(
            max_workers=self.workers,
            mp_context=self._ctx,
            initializer=jobs.worker_init,
            initargs=(self._slots, counter, self._pids, self._withdrawn),
        )

    def start(self, *, warm: bool = True) -> None:
        """Create the executor; with ``warm``, start every worker now (blocks).

        Without ``warm`` no process starts before the first job.
        """
        self._executor = self._new_executor()
        if warm:
            futures = [self._executor.submit(jobs.warm_up, 0.2) for _ in range(self.workers)]
            for f in futures:
                f.result(timeout=120)

    def submit_background(self, fn: Callable[..., Any], *args: Any) -> Future:
        """Submit ``fn(*args)`` without awaiting it (warm-up work); failures are logged."""
        if self._executor is None:
            raise RuntimeError("the worker pool is not started")
        future = self._executor.submit(fn, *args)

        def report(f: Future) -> None:
            if not f.cancelled() and f.exception() is not None:
                log.warning("%s pool: background job failed: %s", self.name, f.exception())

        future.add_done_callback(report)
        return future

    def close(self, *, timeout: float = 3.0) -> None:
        """Stop every worker; jobs still running after ``timeout`` seconds are killed."""
        if self._executor is not None:
            executor, self._executor = self._executor, None
            procs = list((getattr(executor, "_processes", None) or {}).values())
            manager = getattr(executor, "_executor_manager_thread", None)
            executor.shutdown(wait=False, cancel_futures=True)
            # Idle workers exit at once; give running jobs a moment, then kill
            # them. Joining the manager thread lets the executor free its queues.
            t_end = time.monotonic() + timeout
            for p in procs:
                p.join(max(0.0, t_end - time.monotonic()))
                if p.is_alive():
                    p.kill()
            if manager is not None:
                manager.join(timeout)

    def _renew(self, generation: int, why: str) -> None:
        """Replace the executor of ``generation`` (no-op when already replaced)."""
        if generation != self._generation or self._executor is None:
            return
        old = self._executor
        self._executor = self._new_executor()
        self._generation += 1
        self.restarts += 1
        log.warning("%s pool replaced (%s); %d replacement(s) so far", self.name, why, self.restarts)
        _kill(old)

    # ------------------------------------------------------------ running

    async def run(self, fn: Callable[[Any], Any], job: Any, *, deadline: float) -> Any:
        """Run ``fn(job)`` in a worker and return its result.

        Parameters
        ----------
        fn : a module-level function of :mod:`lgmcts.service.jobs`.
        job : its picklable argument.
        deadline : wall-clock deadline, ``time.time()`` seconds.

        Raises
        ------
        JobTimeout : the deadline passed.
        WorkerCrashed : the job killed its worker twice (once in the pool, once alone).
        Exception : whatever ``fn`` raised (``InputError`` for bad input).
        """
        if self._executor is None:
            raise RuntimeError("the worker pool is not started")
        for _ in range(3):
            generation, job_id = self._generation, next(self._job_ids)
            try:
                future = self._executor.submit(jobs.tracked, fn, job_id, job)
            except RuntimeError:  # broken or shut down (BrokenProcessPool is one)
                self._renew(generation, "broken before submission")
                continue
            slots = self._slots
            try:
                return await asyncio.wait_for(asyncio.wrap_future(future), timeout=deadline - time.time())
            except asyncio.TimeoutError:
                self._watch(future, generation, job_id, slots)
                raise JobTimeout() from None
            except BrokenProcessPool:
                # It may have been the culprit or a bystander: run it alone.
                self._renew(generation, "a worker died")
                return await self._run_alone(fn, job, deadline=deadline)
            except asyncio.CancelledError:
                task = asyncio.current_task()
                if task is not None and task.cancelling():
                    # The request was given up (its client went away, or the server stops).
                    self._abandon(future, generation, job_id)
                    raise
                if not future.cancelled():
                    raise
                # Withdrawn, unstarted, from a pool that was replaced: submit again.
                continue
        raise WorkerCrashed()  # the pool broke on every attempt

    def _abandon(self, future: Future, generation: int, job_id: int) -> None:
        """Drop job ``job_id``: withdrawn if still queued, stopped if running.

        A job already handed to the executor's call queue cannot be withdrawn;
        its id goes into the shared ``withdrawn`` ring, so a worker refuses
        to start it, and a worker running it gets :data:`jobs.ABANDON_SIGNAL`,
        which ends the job there (the worker stays). A job deaf to the signal
        (stuck in native code) is left to its deadline and ``grace``.
        """
        if future.done() or generation != self._generation:
            return
        self.abandoned += 1
        if future.cancel():
            return
        ring = self._withdrawn
        ring[self._withdrawn_next % len(ring)] = job_id
        self._withdrawn_next += 1
        if jobs.ABANDON_SIGNAL is None:
            return
        for index, running in enumerate(list(self._slots)):
            if running == job_id and self._pids[index] > 0:
                try:
                    os.kill(int(self._pids[index]), jobs.ABANDON_SIGNAL)
                except OSError:  # the worker is already gone
                    pass

    def _watch(self, future: Future, generation: int, job_id: int, slots: Any) -> None:
        """Every ``grace`` s, replace the pool if job ``job_id`` is still running.

        A job that only waits in the executor's queue is left alone: it ends
        at once when a worker takes it, its deadline being past.
        """
        loop = asyncio.get_running_loop()

        def check() -> None:
            if future.done() or generation != self._generation:
                return
            if job_id in list(slots):
                self._renew(generation, f"a job ran {self.grace:g} s past its deadline")
            else:
                loop.call_later(self.grace, check)

        loop.call_later(self.grace, check)

    async def _run_alone(self, fn: Callable[[Any], Any], job: Any, *, deadline: float) -> Any:
        """Run one job in a single-use process, to tell a culprit from a bystander."""
        if self._isolated is None:
            self._isolated = asyncio.Semaphore(self.workers)
        async with self._isolated:
            executor = ProcessPoolExecutor(max_workers=1, mp_context=self._ctx, initializer=jobs.worker_init)
            try:
                future = executor.submit(fn, job)
                return await asyncio.wait_for(asyncio.wrap_future(future), timeout=deadline - time.time())
            except asyncio.TimeoutError:
                raise JobTimeout() from None
            except BrokenProcessPool:
                raise WorkerCrashed() from None
            finally:
                _kill(executor)
