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
what the models share (the registry, the shear laws). The shipped models load
first, in the order listings have always shown them; any other module follows,
by name. A model has the signature of :class:`FrictionModel` and its validity checks
that of :class:`ballscrew.validity.ValidityCheck`; :func:`register` holds both to them.
"""

from __future__ import annotations

import importlib
import pkgutil

from ._registry import (
    MODELS,
    NONE_MEANS,
    PARAMETER_UNITS,
    FrictionModel,
    ModelSpec,
    get_model,
    register,
)

__all__ = [
    "MODELS",
    "NONE_MEANS",
    "PARAMETER_UNITS",
    "FrictionModel",
    "ModelSpec",
    "get_model",
    "register",
]

_SHIPPED = ("catalog", "complete", "harris_simplified", "harris_full", "olaru", "viscoelastic")
_OTHERS = sorted(m.name for m in pkgutil.iter_modules(__path__) if m.name not in _SHIPPED)
for _name in (*_SHIPPED, *_OTHERS):
    if not _name.startswith("_"):
        importlib.import_module(f"{__name__}.{_name}")
