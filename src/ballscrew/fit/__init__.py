"""Fitting a model to a measurement, and reading a screw's preload over life from one.

Model parameters fitted to a measured curve with intervals (:mod:`.calibration`);
the preload read from drag-torque measurements (:mod:`.monitor`); a drag torque
against the makers' band (:mod:`.acceptance`). Friction for controllers (its forms,
the load map, the export) is the servo wing's (:mod:`ballscrew.servo`).

The commands' entry points: :func:`run_fit` (``ballscrew fit``), :func:`run_monitor`
(``ballscrew monitor``) and :func:`run_acceptance` (``ballscrew acceptance``).
"""

from typing import Any

from .acceptance import Acceptance, run_acceptance
from .calibration import FitResult, run_fit
from .monitor import MonitorResult, run_monitor

__all__ = [
    "Acceptance",
    "FitResult",
    "MonitorResult",
    "run_acceptance",
    "run_fit",
    "run_monitor",
]

_MOVED_NAMES = ("FrictionExport", "FrictionMap", "run_export_friction")
"""Names this wing exported until 0.3.0, now :mod:`ballscrew.servo`'s."""


def __getattr__(name: str) -> Any:
    """The friction export's names, from their new home, with a DeprecationWarning (0.4.0).

    Imported by name at the first use (:mod:`importlib`): the servo wing sits above
    this one, and only this shim for old code reaches up to it.
    """
    import importlib
    import warnings

    if name not in _MOVED_NAMES:
        raise AttributeError(f"module 'ballscrew.fit' has no attribute {name!r}")
    warnings.warn(
        f"ballscrew.fit.{name} moved to ballscrew.servo.{name}; the old name goes in the "
        "next release",
        DeprecationWarning,
        stacklevel=2,
    )
    return getattr(importlib.import_module("ballscrew.servo"), name)
