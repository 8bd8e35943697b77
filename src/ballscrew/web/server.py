"""How the calculator is served: uvicorn's HTTP protocol with a deadline for a request's head.

uvicorn closes a connection that stays idle after a response
(``timeout_keep_alive``), but a connection that never sends a whole request
head stays open for ever: enough of them, idle or sending a byte now and then,
would hold the server. :class:`HeadDeadline` closes such a connection
:data:`HEAD_SECONDS` after it opened, or after its last response.

Each connection holds a file descriptor, and a server whose descriptors are used
up cannot accept the next visitor (with 256 of them, 300 idle connections made
'/' time out, issue 35). The connections are therefore kept to what the
descriptors allow (:func:`connection_budget`): at the budget, a new connection
closes the oldest one that has not yet sent a request head, which costs a visitor
nothing, rather than being refused (a cap that refused made idle connections turn
every other request into a 503). The work is bounded by the worker pool
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

__all__ = [
    "ACCEPT_BURST",
    "HEAD_SECONDS",
    "HeadDeadline",
    "LogRate",
    "connection_budget",
    "raise_file_limit",
    "server_config",
]

HEAD_SECONDS = 10.0
"""Time a connection has to send a whole request head [s]."""

RESERVED_FILES = 64
"""File descriptors kept from connections: the listening socket, the worker pool's pipes,
log files, the modules and data files read while serving."""


ACCEPT_BURST = 32
"""The listening backlog, which is also how many connections asyncio accepts in one go:
half of :data:`RESERVED_FILES`, so a burst of accepts fits in the reserve."""


def connection_budget(file_limit: int) -> int:
    """The most connections a server with ``file_limit`` descriptors holds at once.

    All but :data:`RESERVED_FILES`, and at least 16.

    >>> connection_budget(256), connection_budget(1024)
    (192, 960)
    """
    return max(16, file_limit - RESERVED_FILES)


_HEAD_RECEIVED = (h11.SEND_BODY, h11.DONE, h11.MUST_CLOSE, h11.CLOSED, h11.ERROR)


class HeadDeadline(H11Protocol):
    """uvicorn's HTTP/1.1 protocol, closing a connection that is too slow with its head.

    It also keeps the open connections within :attr:`budget` (set by
    :func:`server_config` from the file limit): a connection opened at the budget
    closes the oldest open one that is waiting for its request head.
    """

    _deadline: asyncio.TimerHandle | None = None
    budget: int = connection_budget(1024)
    """The most connections held at once (:func:`connection_budget`)."""
    _books: dict[int, tuple[dict[HeadDeadline, None], dict[HeadDeadline, None]]] = {}  # noqa: RUF012
    """Per event loop (one per server): its open connections, and those without a whole head,
    oldest first."""

    def _book(self) -> tuple[dict[HeadDeadline, None], dict[HeadDeadline, None]]:
        return HeadDeadline._books.setdefault(id(self.loop), ({}, {}))

    def _make_room(self) -> None:
        """At the budget, close the oldest connections that have not sent a head."""
        opened, waiting = self._book()
        while len(opened) >= HeadDeadline.budget and waiting:
            oldest = next(iter(waiting))
            oldest._forget()
            if not oldest.transport.is_closing():
                oldest.transport.close()

    def _forget(self) -> None:
        opened, waiting = self._book()
        opened.pop(self, None)
        waiting.pop(self, None)

    def _arm(self) -> None:
        self._disarm()
        self._deadline = self.loop.call_later(HEAD_SECONDS, self._too_slow)
        self._book()[1][self] = None

    def _disarm(self) -> None:
        self._book()[1].pop(self, None)
        if self._deadline is not None:
            self._deadline.cancel()
            self._deadline = None

    def _too_slow(self) -> None:
        self._deadline = None
        if not self.transport.is_closing():
            self.transport.close()

    def connection_made(self, transport: asyncio.Transport) -> None:  # type: ignore[override]
        """Open: the head is due within :data:`HEAD_SECONDS`; room made at the budget."""
        super().connection_made(transport)
        self._make_room()
        self._book()[0][self] = None
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
        self._forget()
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
    (:func:`raise_file_limit`), its connections are kept within what that
    leaves (:func:`connection_budget`), and the server's own log is rate-limited
    (:class:`LogRate`).
    """
    HeadDeadline.budget = connection_budget(raise_file_limit())
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
        # asyncio accepts up to `backlog` connections in one burst before the budget's
        # closes run: a burst within the reserve never meets EMFILE (at 2048, 300 idle
        # connections on 256 descriptors did, and each failed accept scheduled a retry
        # that flooded the log when the server stopped)
        "backlog": ACCEPT_BURST,
        **kwargs,
    }
    return Config(app, **settings)
