"""How the calculator is served: uvicorn's HTTP protocol with a deadline for a request's head.

uvicorn closes a connection that stays idle after a response
(``timeout_keep_alive``), but a connection that never sends a whole request
head stays open for ever: enough of them, idle or sending a byte now and then,
would hold the server. :class:`HeadDeadline` closes such a connection
:data:`HEAD_SECONDS` after it opened, or after its last response. The number of
connections is not capped (a cap made idle connections turn every other
request into a 503); the work is bounded by the worker pool instead
(:mod:`.worker`).
"""

from __future__ import annotations

import asyncio
import logging
import time
from typing import Any

import h11
from uvicorn.config import Config
from uvicorn.protocols.http.h11_impl import H11Protocol

__all__ = ["HEAD_SECONDS", "HeadDeadline", "LogRate", "raise_file_limit", "server_config"]

HEAD_SECONDS = 10.0
"""Time a connection has to send a whole request head [s]."""

_HEAD_RECEIVED = (h11.SEND_BODY, h11.DONE, h11.MUST_CLOSE, h11.CLOSED, h11.ERROR)


class HeadDeadline(H11Protocol):
    """uvicorn's HTTP/1.1 protocol, closing a connection that is too slow with its head."""

    _deadline: asyncio.TimerHandle | None = None

    def _arm(self) -> None:
        self._disarm()
        self._deadline = self.loop.call_later(HEAD_SECONDS, self._too_slow)

    def _disarm(self) -> None:
        if self._deadline is not None:
            self._deadline.cancel()
            self._deadline = None

    def _too_slow(self) -> None:
        self._deadline = None
        if not self.transport.is_closing():
            self.transport.close()

    def connection_made(self, transport: asyncio.Transport) -> None:  # type: ignore[override]
        """Open: the head is due within :data:`HEAD_SECONDS`."""
        super().connection_made(transport)
        self._arm()

    def handle_events(self) -> None:
        """Parse what came; once a whole head is in, the deadline is off."""
        super().handle_events()
        if self.conn.their_state in _HEAD_RECEIVED:
            self._disarm()

    def on_response_complete(self) -> None:
        """Answered: the next head (on a kept-alive connection) is due in time too."""
        super().on_response_complete()
        if not self.transport.is_closing() and self.conn.their_state not in _HEAD_RECEIVED:
            self._arm()

    def connection_lost(self, exc: Exception | None) -> None:
        """Closed: nothing is due."""
        self._disarm()
        super().connection_lost(exc)


class LogRate(logging.Filter):
    """Lets through at most ``burst`` records of one message template per ``seconds``.

    With its file descriptors used up, a server fails every accept and logs each
    failure: 166 MB of the same line in 40 s (issue 35). The first records of a kind
    pass, the rest of the window is counted and said once when the next window opens.
    """

    def __init__(self, burst: int = 10, seconds: float = 10.0) -> None:
        super().__init__()
        self.burst, self.seconds = burst, seconds
        self._windows: dict[str, tuple[float, int]] = {}

    def filter(self, record: logging.LogRecord) -> bool:
        """Whether ``record`` is logged (the count of those held back joins the next)."""
        now = time.monotonic()
        key = f"{record.name}:{record.msg}"
        start, count = self._windows.get(key, (now, 0))
        if now - start > self.seconds:
            if count > self.burst:
                record.msg = f"{record.msg} (and {count - self.burst} more like it held back)"
            start, count = now, 0
        self._windows[key] = (start, count + 1)
        if len(self._windows) > 1000:  # a flood of distinct messages: start afresh
            self._windows.clear()
        return count < self.burst


def raise_file_limit() -> int:
    """Raise the process's soft limit of open files to its hard limit; return the limit.

    Each connection holds a file descriptor: with the common soft limit of 256 or
    1024, a few hundred idle connections leave none for the next visitor.
    """
    import resource

    soft, hard = resource.getrlimit(resource.RLIMIT_NOFILE)
    if hard == resource.RLIM_INFINITY or soft < hard:
        try:
            resource.setrlimit(resource.RLIMIT_NOFILE, (hard, hard))
            soft = hard
        except (ValueError, OSError):
            pass
    return int(soft)


def server_config(app: Any, **kwargs: Any) -> Config:
    """Uvicorn's configuration for the calculator (keyword arguments pass through).

    Idle kept-alive connections close after 5 s, a request's head must come
    within :data:`HEAD_SECONDS`, a head is at most 16 kB, and no server header
    is sent. The process may open as many files as its hard limit allows
    (:func:`raise_file_limit`), and the server's own log is rate-limited
    (:class:`LogRate`).
    """
    raise_file_limit()
    for name in ("uvicorn.error", "asyncio"):
        logger = logging.getLogger(name)
        if not any(isinstance(f, LogRate) for f in logger.filters):
            logger.addFilter(LogRate())
    settings: dict[str, Any] = {
        "http": HeadDeadline,
        "timeout_keep_alive": 5,
        "h11_max_incomplete_event_size": 16 * 1024,
        "server_header": False,
        "access_log": False,
        **kwargs,
    }
    return Config(app, **settings)
