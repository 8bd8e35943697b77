"""Friction models, one module each, registered by name.

========================= ==============================================
name                      module
========================= ==============================================
``"catalog"``             :mod:`ballscrew.friction.catalog`
========================= ==============================================
"""

from __future__ import annotations

from . import catalog, complete, harris_full, harris_simplified, olaru, viscoelastic
from ._registry import MODELS, ModelSpec, get_model, register

__all__ = [
    "MODELS",
    "ModelSpec",
    "catalog",
    "complete",
    "get_model",
    "harris_full",
    "harris_simplified",
    "olaru",
    "register",
    "viscoelastic",
]
