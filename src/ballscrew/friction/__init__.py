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

Every module of this package whose name does not start with an underscore is
imported here, and registers its model with :func:`register` as it loads: a new
model is a new module, nothing else. Modules starting with an underscore hold
what the models share (the registry, the shear laws).
"""

from __future__ import annotations

import importlib
import pkgutil

from ._registry import MODELS, ModelSpec, get_model, register

__all__ = ["MODELS", "ModelSpec", "get_model", "register"]

for _module in sorted(pkgutil.iter_modules(__path__), key=lambda m: m.name):
    if not _module.name.startswith("_"):
        importlib.import_module(f"{__name__}.{_module.name}")
