"""Friction models, one module each, registered by name.

========================= ==============================================
name                      module
========================= ==============================================
``"complete"``            :mod:`ballscrew.friction.complete`
``"catalog"``             :mod:`ballscrew.friction.catalog`
``"harris-simplified"``   :mod:`ballscrew.friction.harris_simplified`
``"olaru"``               :mod:`ballscrew.friction.olaru`
``"viscoelastic"``        :mod:`ballscrew.friction.viscoelastic`
``"harris-full"``         :mod:`ballscrew.friction.harris_full`
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
