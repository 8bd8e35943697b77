"""The web calculator: one page and a JSON API over the library (``ballscrew serve``).

:mod:`ballscrew.web.service` computes (request data in, plain data out) by
the same functions as the command line; :mod:`ballscrew.web.app` is the
Starlette application around it. The layers below never import this package.

It needs the ``web`` extra (``pip install 'ballscrew[web]'``); without it, importing
this package raises :class:`ballscrew.extras.MissingExtraError` naming the extra.
"""

from __future__ import annotations

from ..io.extras import require

require("web", "ballscrew.web")

from .app import create_app  # noqa: E402 - after the check, for its message

__all__ = ["create_app"]
