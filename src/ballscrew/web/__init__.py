"""The web calculator: one page and a JSON API over the library (``ballscrew serve``).

:mod:`ballscrew.web.service` computes (request data in, plain data out) by
the same functions as the command line; :mod:`ballscrew.web.app` is the
Starlette application around it. The layers below never import this package.
"""

from __future__ import annotations

from .app import create_app

__all__ = ["create_app"]
