"""The web calculator's application: one page, its script and style, and a JSON API.

Built on Starlette (an ASGI toolkit) and served by uvicorn
(:mod:`ballscrew.cli.serve`). Routes:

``GET /``
    The page (server-rendered HTML; a small script calls the API as inputs change).
``GET /static/{name}``
    The page's script and style, held in memory: no path from a request
    reaches the file system.
``POST /api/torque``
    One model over a case's operating points (:func:`service.torque`).
``POST /api/evaluate``
    Everything the page shows and the files it offers (:func:`service.evaluate`).
``POST /api/case``
    An uploaded case file read as TOML data (:func:`service.read_case_file`).

Safe to leave running: request bodies are capped (413 before the body is
read when ``Content-Length`` says so, and while it streams otherwise), the
work of a request is bounded (:class:`service.Limits`) and runs one request
at a time in a worker thread within a time budget (503 past it), the Host
header must name this server (no DNS rebinding from a web page), and an
internal error answers a generic message while the traceback goes to the
server's log only.
"""

from __future__ import annotations

import contextlib
import json
import logging
import threading
import warnings
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
from ..errors import BallScrewSpeedWarning, BallScrewValidityWarning
from ..io.designation import catalog_screws
from . import service
from .service import LIMITS, ApiError, Limits

__all__ = ["LOOPBACK_HOSTS", "create_app"]

LOG = logging.getLogger("ballscrew.web")

LOOPBACK_HOSTS = ("127.0.0.1", "localhost", "::1", "[::1]")
"""Host names the server answers to when it listens on the loopback interface."""

_STATIC_TYPES = {
    "app.js": "text/javascript; charset=utf-8",
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
        if length is not None:
            try:
                too_big = int(length) > self.limit
            except ValueError:
                too_big = True
            if too_big:
                response = JSONResponse(
                    {"error": f"the request body is over {self.limit} bytes"}, status_code=413
                )
                await response(scope, receive, send)
                return

        async def send_with_headers(message: Message) -> None:
            if message["type"] == "http.response.start":
                message["headers"] = [*message.get("headers", []), *_SECURITY_HEADERS]
            await send(message)

        await self.app(scope, receive, send_with_headers)


async def _body(request: Request, limits: Limits) -> bytes:
    """The request body, refused (413) as soon as it passes the limit."""
    chunks: list[bytes] = []
    size = 0
    async for chunk in request.stream():
        size += len(chunk)
        if size > limits.body_bytes:
            raise ApiError(413, f"the request body is over {limits.body_bytes} bytes")
        chunks.append(chunk)
    return b"".join(chunks)


def _static() -> dict[str, bytes]:
    folder = resources.files("ballscrew.web").joinpath("static")
    return {name: folder.joinpath(name).read_bytes() for name in _STATIC_TYPES}


def _page_context() -> dict[str, Any]:
    return {
        "version": __version__,
        "screws": [s.name for s in catalog_screws()],
        "lubricants": lubricants.names(),
        "models": service.model_choices(),
        "limits": LIMITS,
    }


def _page() -> bytes:
    """The page, rendered once from its template."""
    templates = jinja2.Environment(
        loader=jinja2.PackageLoader("ballscrew.web", "templates"),
        autoescape=True,
        undefined=jinja2.StrictUndefined,
    )
    return templates.get_template("index.html").render(**_page_context()).encode("utf-8")


class _Worker:
    """Runs a computation in a worker thread, one request at a time, within the time budget."""

    def __init__(self, limits: Limits) -> None:
        self.limits = limits
        self.lock = threading.Lock()

    def _run(self, function: Callable[..., dict[str, Any]], *args: Any) -> dict[str, Any]:
        # Half the budget to wait for the worker, so that "busy" is told in time.
        if not self.lock.acquire(timeout=self.limits.seconds / 2):
            raise ApiError(503, "the calculator is busy; try again in a moment")
        try:
            # One at a time, so the warning filters (process-wide) are ours alone;
            # the results keep every validity issue, returned as text.
            with warnings.catch_warnings():
                warnings.simplefilter("ignore", BallScrewValidityWarning)
                warnings.simplefilter("ignore", BallScrewSpeedWarning)
                return function(*args)
        finally:
            self.lock.release()

    async def __call__(self, function: Callable[..., dict[str, Any]], *args: Any) -> dict[str, Any]:
        """Run ``function`` in a worker thread, one request at a time, within the budget."""
        try:
            with anyio.fail_after(self.limits.seconds):
                return await anyio.to_thread.run_sync(
                    self._run, function, *args, abandon_on_cancel=True
                )
        except TimeoutError:
            raise ApiError(503, f"the request took over {self.limits.seconds:g} s") from None


_Endpoint = Callable[[Request], Awaitable[Response]]


def _index(page: bytes) -> _Endpoint:
    """``GET /``: the page."""

    async def index(request: Request) -> Response:
        return HTMLResponse(page, headers={"cache-control": "no-cache"})

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


def _json_route(
    function: Callable[[dict[str, Any], Limits], dict[str, Any]], limits: Limits, compute: _Worker
) -> _Endpoint:
    """An API route: the JSON body to ``function`` (in the worker), its result as JSON."""

    async def endpoint(request: Request) -> Response:
        payload = service.read_json(await _body(request, limits))
        return _json(await compute(function, payload, limits))

    return endpoint


def _case_file(limits: Limits) -> _Endpoint:
    """``POST /api/case``: an uploaded case file read as TOML data."""

    async def case_file(request: Request) -> Response:
        return _json(service.read_case_file(await _body(request, limits)))

    return case_file


async def _api_error(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, ApiError)
    return JSONResponse(exc.payload(), status_code=exc.status)


async def _http_error(request: Request, exc: Exception) -> Response:
    assert isinstance(exc, HTTPException)
    text = {404: "not found", 405: "method not allowed"}.get(exc.status_code, "refused")
    if request.url.path.startswith("/api/"):
        return JSONResponse({"error": text}, status_code=exc.status_code)
    return HTMLResponse(_message_page(text), status_code=exc.status_code)


async def _internal_error(request: Request, exc: Exception) -> Response:
    # The traceback goes to the server's log (uvicorn logs the exception too);
    # the browser is told only that something failed on the server.
    LOG.error("internal error on %s %s", request.method, request.url.path, exc_info=exc)
    text = "internal error: the server could not compute this (see the server's log)"
    if request.url.path.startswith("/api/"):
        return JSONResponse({"error": text}, status_code=500)
    return HTMLResponse(_message_page(text), status_code=500)


def _lifespan(
    compute: _Worker, limits: Limits
) -> Callable[[Starlette], contextlib.AbstractAsyncContextManager[None]]:
    """The application's lifespan: a warm-up computation before the first request."""

    @contextlib.asynccontextmanager
    async def lifespan(app: Starlette) -> AsyncIterator[None]:
        # The first computation loads and compiles what the models need (about
        # 0.7 s); done here, before the first visitor, the page opens at full speed.
        try:
            await compute(service.evaluate, service.WARM_UP, limits)
        except Exception:  # the server still starts, and answers what it can
            LOG.exception("warm-up computation failed")
        yield

    return lifespan


def create_app(limits: Limits = LIMITS, allowed_hosts: list[str] | None = None) -> Starlette:
    """The application; ``allowed_hosts``: Host names it answers (default: loopback names)."""
    compute = _Worker(limits)
    hosts = list(allowed_hosts) if allowed_hosts is not None else list(LOOPBACK_HOSTS)
    return Starlette(
        debug=False,
        lifespan=_lifespan(compute, limits),
        routes=[
            Route("/", _index(_page()), methods=["GET"]),
            Route("/static/{name}", _static_file(_static()), methods=["GET"]),
            Route("/api/torque", _json_route(service.torque, limits, compute), methods=["POST"]),
            Route(
                "/api/evaluate", _json_route(service.evaluate, limits, compute), methods=["POST"]
            ),
            Route("/api/case", _case_file(limits), methods=["POST"]),
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
