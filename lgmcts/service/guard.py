"""A header timeout for uvicorn's HTTP/1.1 protocol.

uvicorn closes idle keep-alive connections, but a client that opens a
connection and then sends its request headers a byte at a time is never
disconnected. :func:`protocol_with_header_timeout` gives the h11 protocol a
timer: a connection that has not delivered a complete request head within
``header_timeout`` seconds of its first byte (or of opening) is closed. The
request body's pace is the application's business
(:class:`lgmcts.service.app.BodyLimit`, 408).
"""

from __future__ import annotations

import asyncio
from typing import Any

from uvicorn.protocols.http.h11_impl import H11Protocol

__all__ = ["protocol_with_header_timeout"]


class _HeaderTimeoutH11(H11Protocol):
    header_timeout: float = 10.0

    def connection_made(self, transport: asyncio.Transport) -> None:  # type: ignore[override]
        self._head_timer: asyncio.TimerHandle | None = None
        super().connection_made(transport)
        self._arm()

    def _waiting_for_head(self) -> bool:
        return self.cycle is None or self.cycle.response_complete

    def _arm(self) -> None:
        if self._head_timer is None:
            self._head_timer = self.loop.call_later(self.header_timeout, self._head_expired)

    def _disarm(self) -> None:
        if self._head_timer is not None:
            self._head_timer.cancel()
            self._head_timer = None

    def _head_expired(self) -> None:
        self._head_timer = None
        if self._waiting_for_head() and not self.transport.is_closing():
            self.logger.info("closing a connection whose request headers did not arrive within %g s", self.header_timeout)
            self.transport.close()

    def data_received(self, data: bytes) -> None:
        before = self.cycle
        if self._waiting_for_head():
            self._arm()
        super().data_received(data)
        if self.cycle is not before:
            self._disarm()  # a complete request head arrived

    def connection_lost(self, exc: Exception | None) -> None:
        self._disarm()
        super().connection_lost(exc)


def protocol_with_header_timeout(header_timeout: float) -> Any:
    """An h11 protocol class for ``uvicorn.run(http=...)`` closing slow-header connections."""
    return type("HeaderTimeoutH11", (_HeaderTimeoutH11,), {"header_timeout": float(header_timeout)})
