"""Computations of the web calculator in worker processes, each within a hard time budget.

The server's event loop only reads requests and writes answers; every
computation runs in one of a few worker processes (:class:`WorkerPool`). A
computation that passes its time budget cannot be stopped inside a thread, so
its process is killed and a fresh one started: the budget is enforced, and
nothing a request sends can hold the server (a unit-library bomb, a runaway
solver). Requests wait at most half the budget for a free worker, then get
503 "busy".

The functions a worker runs are named, not sent (:data:`FUNCTIONS`); requests
and results cross the process boundary as plain data, and errors as
(kind, status, message, field), since the package's exceptions carry more
than their message.
"""

from __future__ import annotations

import contextlib
import logging
import multiprocessing
import threading
import time
import warnings
from collections.abc import Callable
from multiprocessing.connection import Connection
from typing import Any

import anyio

from ..errors import BallScrewInputError, BallScrewSpeedWarning, BallScrewValidityWarning
from ..helix import load_kernel
from ..io.units import registry
from . import contour, program, select, service
from .inputs import ApiError, Limits

__all__ = ["FUNCTIONS", "WorkerPool"]

LOG = logging.getLogger("ballscrew.web")

Function = Callable[[dict[str, Any], Limits], dict[str, Any]]


def _from_json(function: Function) -> Callable[[bytes, Limits], dict[str, Any]]:
    """``function`` on a request body read as a JSON object, the reading in the worker too."""

    def run(body: bytes, limits: Limits) -> dict[str, Any]:
        return function(service.read_json(body), limits)

    return run


def _case_file(body: bytes, limits: Limits) -> dict[str, Any]:
    return service.read_case_file(body)


FUNCTIONS: dict[str, Callable[[bytes, Limits], dict[str, Any]]] = {
    "torque": _from_json(service.torque),
    "evaluate": _from_json(service.evaluate),
    "program": _from_json(program.run),
    "contour": _from_json(contour.contour),
    "select": _from_json(select.choose),
    "case": _case_file,
}
"""What a worker may be asked to run, by name: each takes the request's body (bytes) and
reads it there, so that reading, like computing, runs within the time budget and off the
server's event loop (a body of the worst shape cannot hold the server)."""


def _cap_memory(memory_bytes: int) -> None:
    """Limit this process's address space to ``memory_bytes`` (where the system allows it).

    An allocation past it raises :class:`MemoryError` in the computation, which is
    answered as a refusal: a request cannot grow a worker until the machine swaps.
    """
    try:
        import resource

        _, hard = resource.getrlimit(resource.RLIMIT_AS)
        cap = memory_bytes if hard == resource.RLIM_INFINITY else min(memory_bytes, hard)
        resource.setrlimit(resource.RLIMIT_AS, (cap, hard))
    except (ImportError, ValueError, OSError):  # no such limit here: the time budget remains
        LOG.warning("the worker's memory could not be capped")


def _serve(conn: Connection, memory_bytes: int | None = None) -> None:
    """A worker's loop: warm up, say so, then run each named function on its request."""
    # The results keep every validity issue, returned as text; no warning is printed.
    warnings.simplefilter("ignore", BallScrewValidityWarning)
    warnings.simplefilter("ignore", BallScrewSpeedWarning)
    # The first computation loads and compiles what the models need (about 0.7 s): done
    # before the worker says it is ready, so that no request pays for it.
    with contextlib.suppress(Exception):
        service.evaluate(service.WARM_UP, service.LIMITS)
        load_kernel()  # the helix's compiled loop, for requests of many points
        registry()  # pint, for a unit the common ones' table does not hold (0.1 s)
    if memory_bytes:
        _cap_memory(memory_bytes)
    conn.send(("ready",))
    while True:
        try:
            name, payload, limits = conn.recv()
        except (EOFError, OSError):
            return
        try:
            answer: tuple[Any, ...] = ("ok", FUNCTIONS[name](payload, limits))
        except ApiError as exc:
            answer = ("error", exc.status, exc.message, exc.field)
        except BallScrewInputError as exc:
            answer = ("error", 422, str(exc), exc.field)
        except MemoryError:
            gib = (memory_bytes or 0) / 1024**3
            answer = ("error", 422, f"the request needs more memory than a computation of the "
                      f"calculator may use ({gib:.3g} GiB): ask for fewer samples, points or "
                      "candidates, or run it with the command line", "")  # fmt: skip
        except Exception:
            LOG.exception("internal error in %s", name)
            answer = ("internal",)
        conn.send(answer)


class _Process:
    """One worker process and the parent's end of its pipe."""

    def __init__(self, memory_bytes: int | None = None) -> None:
        context = multiprocessing.get_context("spawn")  # no fork of a threaded server
        self.conn, child = context.Pipe()
        self.process = context.Process(target=_serve, args=(child, memory_bytes), daemon=True)
        self.process.start()
        child.close()
        self.ready = False

    def wait_ready(self, seconds: float) -> bool:
        """Whether the process has imported the package and warmed up (waiting ``seconds``)."""
        if not self.ready and self.conn.poll(seconds):
            self.ready = self.conn.recv() == ("ready",)
        return self.ready

    def ask(self, name: str, payload: bytes, limits: Limits, seconds: float) -> Any:
        """The answer; None when the budget ran out (the caller then kills the process)."""
        self.conn.send((name, payload, limits))
        if not self.conn.poll(seconds):
            return None
        return self.conn.recv()

    def stop(self) -> None:
        """End the process now (a computation past its budget is not waited for)."""
        with contextlib.suppress(OSError):
            self.conn.close()
        self.process.kill()
        self.process.join(timeout=5)


class WorkerPool:
    """Worker processes that run :data:`FUNCTIONS`, each request within ``limits.seconds``.

    Parameters
    ----------
    limits : Limits
        The time budget per request (waiting included) and the other request limits.
    processes : int
        Worker processes; requests beyond them wait (at most half the budget).
        0: run in a thread of this process, one request at a time (a budget
        that is answered on time but cannot stop the computation; for tests
        that replace a function of the service in this process).
    """

    def __init__(self, limits: Limits, processes: int = 2) -> None:
        self.limits = limits
        self.size = processes
        self._idle: list[_Process] = []
        self._free = threading.Semaphore(max(processes, 1))
        self._lock = threading.Lock()
        self._started = False

    def start(self, wait: float = 0.0) -> None:
        """Start the processes; wait up to ``wait`` seconds for them to be ready.

        Each imports the package and warms up: a few seconds, in parallel.
        """
        with self._lock:
            if not self._started:
                self._idle = [_Process(self.limits.memory_bytes) for _ in range(self.size)]
                self._started = True
            workers = list(self._idle)
        deadline = time.monotonic() + wait
        for worker in workers:
            worker.wait_ready(max(deadline - time.monotonic(), 0.0))

    def close(self) -> None:
        """Stop every idle process (busy ones end with their request)."""
        with self._lock:
            for worker in self._idle:
                worker.stop()
            self._idle = []
            self._started = False

    def _run(self, name: str, payload: bytes) -> dict[str, Any]:
        begin = time.monotonic()
        if not self._free.acquire(timeout=self.limits.seconds / 2):
            raise ApiError(503, "the calculator is busy; try again in a moment")
        if self.size == 0:
            try:
                with warnings.catch_warnings():  # one at a time: the filters are ours alone
                    warnings.simplefilter("ignore", BallScrewValidityWarning)
                    warnings.simplefilter("ignore", BallScrewSpeedWarning)
                    try:
                        return FUNCTIONS[name](payload, self.limits)
                    except BallScrewInputError as exc:
                        raise ApiError.from_input(exc) from None
            finally:
                self._free.release()
        try:
            self.start()
            with self._lock:
                worker = self._idle.pop()
            left = max(self.limits.seconds - (time.monotonic() - begin), 0.01)
            starting = not worker.wait_ready(left)
            answer = None
            if not starting:
                left = max(self.limits.seconds - (time.monotonic() - begin), 0.01)
                try:
                    answer = worker.ask(name, payload, self.limits, left)
                except (OSError, EOFError):  # the process died (out of memory, killed)
                    answer = ("internal",)
                if answer is None or (answer[0] == "internal" and not worker.process.is_alive()):
                    worker.stop()
                    # A fresh one warms up while the next request waits for it.
                    worker = _Process(self.limits.memory_bytes)
            with self._lock:
                self._idle.append(worker)
        finally:
            self._free.release()
        if starting:
            raise ApiError(503, "the calculator is starting; try again in a moment")
        if answer is None:
            raise ApiError(503, f"the request took over {self.limits.seconds:g} s")
        if answer[0] == "ok":
            result: dict[str, Any] = answer[1]
            return result
        if answer[0] == "error":
            raise ApiError(answer[1], answer[2], answer[3])
        raise RuntimeError(f"the worker failed on {name} (see the server's log)")

    async def __call__(self, name: str, payload: bytes) -> dict[str, Any]:
        """Run ``FUNCTIONS[name]`` on the request body ``payload`` in a worker, off the loop."""
        if self.size:
            return await anyio.to_thread.run_sync(self._run, name, payload)
        try:
            with anyio.fail_after(self.limits.seconds):
                return await anyio.to_thread.run_sync(
                    self._run, name, payload, abandon_on_cancel=True
                )
        except TimeoutError:
            raise ApiError(503, f"the request took over {self.limits.seconds:g} s") from None
