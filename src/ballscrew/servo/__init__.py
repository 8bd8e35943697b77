"""The axis under control, and the friction a controller is given.

Its dynamics, a CNC's servo cascade, circular and reversal tests:
what ``ballscrew contour`` computes (:func:`run_contour`); the loops' figures
need the ``servo`` extra (the Python Control Systems Library). What
``ballscrew export-friction`` computes (:func:`run_export_friction`): friction
forms for a controller (:mod:`.controller`), the load map (:mod:`.friction_map`)
and the controllers' tables (:mod:`.tables`).
"""

from .cascade import Gains, LoopFigures, loop_figures, tune
from .contour import (
    CircleRun,
    ContourResult,
    ReversalRun,
    circular_test,
    contour_samples,
    controller_compensation,
    reversal_test,
    run_contour,
)
from .export import FrictionExport, run_export_friction
from .friction_map import FrictionMap
from .plant import AxisDynamics, axis_dynamics, frictionless
from .simulate import Trace, simulate_axis
from .tables import CompensationTable, fit_table

__all__ = [
    "AxisDynamics",
    "CircleRun",
    "CompensationTable",
    "ContourResult",
    "FrictionExport",
    "FrictionMap",
    "Gains",
    "LoopFigures",
    "ReversalRun",
    "Trace",
    "axis_dynamics",
    "circular_test",
    "contour_samples",
    "controller_compensation",
    "fit_table",
    "frictionless",
    "loop_figures",
    "reversal_test",
    "run_contour",
    "run_export_friction",
    "simulate_axis",
    "tune",
]
