"""Fitting a model to a measurement, friction for a controller, a screw's preload over life.

Model parameters fitted to a measured curve with intervals (:mod:`.calibration`);
friction forms for servo controllers (:mod:`.controller`, :mod:`.export`) and the
load map (:mod:`.friction_map`); the preload read from drag-torque measurements
(:mod:`.monitor`); a drag torque against the makers' band (:mod:`.acceptance`).

The commands' entry points: :func:`run_fit` (``ballscrew fit``),
:func:`run_export_friction` (``ballscrew export-friction``), :func:`run_monitor`
(``ballscrew monitor``) and :func:`run_acceptance` (``ballscrew acceptance``).
"""

from .acceptance import Acceptance, run_acceptance
from .calibration import FitResult, run_fit
from .export import FrictionExport, run_export_friction
from .friction_map import FrictionMap
from .monitor import MonitorResult, run_monitor

__all__ = [
    "Acceptance",
    "FitResult",
    "FrictionExport",
    "FrictionMap",
    "MonitorResult",
    "run_acceptance",
    "run_export_friction",
    "run_fit",
    "run_monitor",
]
