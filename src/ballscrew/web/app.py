"""The web calculator's application: one page, its script and style, and a JSON API.

Built on Starlette (an ASGI toolkit) and served by uvicorn
(:mod:`ballscrew.cli.serve`). Routes:

``GET /``
    The page (server-rendered HTML; a small script calls the API as inputs change).
    ``?units=imperial`` (or ``si``) opens it showing results in that unit system
    (:mod:`ballscrew.io.display`); the page keeps its choice in its address.
``GET /static/{name}``
    The page's script and style, held in memory: no path from a request
    reaches the file system.
``POST /api/torque``
    One model over a case's operating points (:func:`service.torque`).
``POST /api/evaluate``
    Everything the page shows and the files it offers (:func:`service.evaluate`).
``POST /api/case``
    An uploaded case file read as TOML data (:func:`service.read_case_file`, in a worker).
``POST /api/program``
    A short part program on the example machine (:func:`program.run`).
``POST /api/select``
    The screws the page's filters leave, checked on the page's move, their
    front and one recommended (:func:`select.choose`).

Safe to leave running: request bodies are capped (413 before the body is
read when ``Content-Length`` says so, and while it streams otherwise), the
work of a request is bounded (:class:`service.Limits`) and runs in a worker
process within a time budget that is enforced (:mod:`.worker`: 503 past it,
the process killed and replaced), the API takes only its own media type
(JSON; TOML for an uploaded case) and refuses requests a page of another
origin sends, the Host header must name this server (no DNS rebinding from a
web page), every answer carries the page's security headers, and an internal
error answers a generic message while the traceback goes to the server's log
only.
"""

from __future__ import annotations

import contextlib
import json
import logging
from collections.abc import AsyncIterator, Awaitable, Callable
from importlib import resources
from typing import Any

import anyio
import jinja2
from starlette.applications import Starlette
from starlette.exceptions import HTTPException
from starlette.middleware import Middleware
from starlette.middleware.trustedhost import TrustedHostMiddleware
from starlette.requests import Request
from starlette.responses import HTMLResponse, JSONResponse, Response
from starlette.routing import Route
from starlette.types import ASGIApp, Message, Receive, Scope, Send

from .. import lubricants
from .._version import __version__
from ..errors import BallScrewInputError
from ..io.designation import catalog_screws
from ..io.display import SYSTEMS, unit_system
from . import program, select, service
from .service import LIMITS, ApiError, Limits
from .worker import WorkerPool

__all__ = ["LOOPBACK_HOSTS", "create_app"]

LOG = logging.getLogger("ballscrew.web")

LOOPBACK_HOSTS = ("127.0.0.1", "localhost", "::1", "[::1]")
"""Host names the server answers to when it listens on the loopback interface."""

_STATIC_TYPES = {
    "app.js": "text/javascript; charset=utf-8",
    "program.js": "text/javascript; charset=utf-8",
    "style.css": "text/css; charset=utf-8",
}

_SECURITY_HEADERS = [
    (
        b"content-security-policy",
        b"default-src 'self'; script-src 'self'; style-src 'self'; img-src 'self' data:; "
        b"connect-src 'self'; frame-ancestors 'none'; base-uri 'none'; form-action 'none'",
    ),
    (b"x-content-type-options", b"nosniff"),
    (b"referrer-policy", b"no-referrer"),
]


class _Guard:
    """Refuse a declared body over the limit before reading it (413); add the security headers."""

    def __init__(self, app: ASGIApp, limit: int) -> None:
        self.app = app
        self.limit = limit

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http":
            await self.app(scope, receive, send)
            return
        length = dict(scope["headers"]).get(b"content-length")
        too_big = False
        if length is not None:
            try:
                too_big = int(length) > self.limit
            except ValueError:
                too_big = True

        async def send_with_headers(message: Message) -> None:
            if message["type"] == "http.response.start":
                message["headers"] = [*message.get("headers", []), *_SECURITY_HEADERS]
            await send(message)

        if length is not None and too_big:
            response = JSONResponse(
                {"error": f"the request body is over {self.limit} bytes"},
                status_code=413,
                headers=_CLOSE,
            )
            await response(scope, receive, send_with_headers)
            return

        await self.app(scope, receive, send_with_headers)


async def _body(request: Request, limits: Limits) -> bytes:
    """The request body: 413 as soon as it passes the limit, 408 if it comes too slowly."""
    chunks: list[bytes] = []
    size = 0
    try:
        with anyio.fail_after(limits.seconds):
            async for chunk in request.stream():
                size += len(chunk)
                if size > limits.body_bytes:
                    raise ApiError(413, f"the request body is over {limits.body_bytes} bytes")
                chunks.append(chunk)
    except TimeoutError:
        raise ApiError(408, f"the request body took over {limits.seconds:g} s") from None
    return b"".join(chunks)


def _static() -> dict[str, bytes]:
    folder = resources.files("ballscrew.web").joinpath("static")
    return {name: folder.joinpath(name).read_bytes() for name in _STATIC_TYPES}


def _page_context(system: str) -> dict[str, Any]:
    return {
        "units": system,
        "version": __version__,
        "screws": [s.name for s in catalog_screws()],
        "lubricants": lubricants.names(),
        "models": service.model_choices(),
        "limits": LIMITS,
        "program_blocks": program.MAX_BLOCKS,
        "select_candidates": select.MAX_CANDIDATES,
        "select_makers": sorted({s.maker for s in catalog_screws()}),
    }


def _pages() -> dict[str, bytes]:
    """The page, rendered once from its template for each unit system it can show."""
    templates = jinja2.Environment(
        loader=jinja2.PackageLoader("ballscrew.web", "templates"),
        autoescape=True,
        undefined=jinja2.StrictUndefined,
    )
    page = templates.get_template("index.html")
    return {system: page.render(**_page_context(system)).encode("utf-8") for system in SYSTEMS}


_Endpoint = Callable[[Request], Awaitable[Response]]


def _index(pages: dict[str, bytes]) -> _Endpoint:
    """``GET /``: the page, in the unit system ``?units=`` names (400 for another)."""

    async def index(request: Request) -> Response:
        try:
            system = unit_system("units", request.query_params.get("units"))
        except BallScrewInputError as exc:
            return HTMLResponse(_message_page(str(exc)), status_code=400)
        return HTMLResponse(pages[system], headers={"cache-control": "no-cache"})

    return index


def _static_file(static: dict[str, bytes]) -> _Endpoint:
    """``GET /static/{name}``: the page's script or style, from memory; 404 for any other name."""

    async def static_file(request: Request) -> Response:
        name = request.path_params["name"]
        if name not in static:
            raise HTTPException(404)
        return Response(
            static[name], media_type=_STATIC_TYPES[name], headers={"cache-control": "no-cache"}
        )

    return static_file


def _same_origin(request: Request, media: str) -> None:
    """Refuse a body of another type, and a request a page of another origin sent.

    A page elsewhere can send a cross-origin "simple" request (text/plain, a
    form) to this server without the browser asking first; requiring the API's
    own media type, and an Origin that names this server when there is one,
    closes that door.
    """
    kind = request.headers.get("content-type", "").split(";")[0].strip().lower()
    if kind != media:
        raise ApiError(415, f"the request body must be sent as {media}")
    origin = request.headers.get("origin")
    if origin is not None:
        host = request.headers.get("host", "")
        if origin.split("://", 1)[-1].rstrip("/") != host:
            raise ApiError(403, "a request from another web page is refused")


def _json_route(name: str, limits: Limits, compute: WorkerPool) -> _Endpoint:
    """An API route: the JSON body to the worker's function ``name``, its result as JSON."""

    async def endpoint(request: Request) -> Response:
        _same_origin(request, "application/json")
        return _json(await compute(name, await _body(request, limits)))

    return endpoint


def _case_file(limits: Limits, compute: WorkerPool) -> _Endpoint:
    """``POST /api/case``: an uploaded case file (sent as application/toml) read as TOML data."""

    async def case_file(request: Request) -> Response:
        _same_origin(request, "application/toml")
        return _json(await compute("case", await _body(request, limits)))

    return case_file


_CLOSE = {"connection": "close"}
"""The header of every refusal: the connection is closed once it is answered, so a client
that goes on sending (a body past the limit, trickled) holds nothing."""


async def _api_error(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, ApiError)
    return JSONResponse(exc.payload(), status_code=exc.status, headers=_CLOSE)


async def _http_error(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, HTTPException)
    text = {404: "not found", 405: "method not allowed"}.get(exc.status_code, "refused")
    if request.url.path.startswith("/api/"):
        return JSONResponse({"error": text}, status_code=exc.status_code, headers=_CLOSE)
    return HTMLResponse(_message_page(text), status_code=exc.status_code, headers=_CLOSE)


async def _internal_error(request: Request, exc: Exception) -> Response:
    # The traceback goes to the server's log (uvicorn logs the exception too);
    # the browser is told only that something failed on the server.
    LOG.error("internal error on %s %s", request.method, request.url.path, exc_info=exc)
    text = "internal error: the server could not compute this (see the server's log)"
    if request.url.path.startswith("/api/"):
        return JSONResponse({"error": text}, status_code=500, headers=_CLOSE)
    return HTMLResponse(_message_page(text), status_code=500, headers=_CLOSE)


def _lifespan(
    compute: WorkerPool, heavy: WorkerPool
) -> Callable[[Starlette], contextlib.AbstractAsyncContextManager[None]]:
    """The application's lifespan: the workers started and warmed up; stopped at the end."""

    @contextlib.asynccontextmanager
    async def lifespan(app: Starlette) -> AsyncIterator[None]:
        # The workers import the package and warm up (the first computation loads and
        # compiles what the models need) before the first visitor: the page opens at
        # full speed. Computing in this process, the warm-up is one request.
        async with anyio.create_task_group() as group:
            for pool in (compute, heavy):
                group.start_soon(anyio.to_thread.run_sync, pool.start, 120.0)
        if not compute.size:
            try:
                await compute("evaluate", json.dumps(service.WARM_UP).encode("utf-8"))
            except Exception:  # the server still starts, and answers what it can
                LOG.exception("warm-up computation failed")
        try:
            yield
        finally:
            compute.close()
            heavy.close()

    return lifespan


def create_app(
    limits: Limits = LIMITS, allowed_hosts: list[str] | None = None, processes: int = 2
) -> Starlette:
    """The application; ``allowed_hosts``: Host names it answers (default: loopback names).

    ``processes``: worker processes that compute (:class:`~.worker.WorkerPool`; 0 runs
    the computations in a thread of this process, as tests that replace a function of
    the service need). The routes whose requests may each take the whole time budget
    (a program, a circular test, a selection) run in a pool of their own, of one
    process: a burst of them waits there, and the page's light requests (torque,
    evaluate, a case file) are still answered by the others.
    """
    compute = WorkerPool(limits, processes)
    heavy = WorkerPool(limits, min(processes, 1))
    hosts = list(allowed_hosts) if allowed_hosts is not None else list(LOOPBACK_HOSTS)
    return Starlette(
        debug=False,
        lifespan=_lifespan(compute, heavy),
        routes=[
            Route("/", _index(_pages()), methods=["GET"]),
            Route("/static/{name}", _static_file(_static()), methods=["GET"]),
            Route("/api/torque", _json_route("torque", limits, compute), methods=["POST"]),
            Route("/api/evaluate", _json_route("evaluate", limits, compute), methods=["POST"]),
            Route("/api/case", _case_file(limits, compute), methods=["POST"]),
            Route("/api/program", _json_route("program", limits, heavy), methods=["POST"]),
            Route("/api/contour", _json_route("contour", limits, heavy), methods=["POST"]),
            Route("/api/select", _json_route("select", limits, heavy), methods=["POST"]),
        ],
        middleware=[
            Middleware(_Guard, limit=limits.body_bytes),
            Middleware(TrustedHostMiddleware, allowed_hosts=hosts),
        ],
        exception_handlers={
            ApiError: _api_error,
            HTTPException: _http_error,
            Exception: _internal_error,
        },
    )


def _json(data: dict[str, Any]) -> Response:
    """Strict JSON (no NaN; the service sends non-finite numbers as null)."""
    body = json.dumps(data, ensure_ascii=False, allow_nan=False, separators=(",", ":"))
    return Response(body.encode("utf-8"), media_type="application/json")


def _message_page(text: str) -> str:
    from html import escape

    return (
        "<!doctype html><html lang='en'><meta charset='utf-8'><title>ballscrew</title>"
        f"<p>{escape(text)}</p><p><a href='/'>back to the calculator</a></p></html>"
    )
