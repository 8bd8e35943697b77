"""Fitting a model to a measurement, friction for a controller, a screw's preload over life.

Model parameters fitted to a measured curve with intervals (:mod:`.calibration`);
friction forms for servo controllers (:mod:`.controller`, :mod:`.export`) and the
load map (:mod:`.friction_map`); the preload read from drag-torque measurements
(:mod:`.monitor`); a drag torque against the makers' band (:mod:`.acceptance`).

The commands' entry points: :func:`run_fit`, :func:`run_export_friction`,
:func:`run_monitor`, :func:`run_acceptance`.
"""

from .acceptance import run_acceptance
from .calibration import run_fit
from .export import run_export_friction
from .monitor import run_monitor

__all__ = ["run_acceptance", "run_export_friction", "run_fit", "run_monitor"]
