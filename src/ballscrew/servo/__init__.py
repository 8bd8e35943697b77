"""The axis under control: its dynamics, a CNC's servo cascade, circular and reversal tests.

What ``ballscrew contour`` computes (:func:`run_contour`); the loops' figures
need the ``servo`` extra (the Python Control Systems Library).
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
from .plant import AxisDynamics, axis_dynamics, frictionless
from .simulate import Trace, simulate_axis
from .tables import CompensationTable, fit_table

__all__ = [
    "AxisDynamics",
    "CircleRun",
    "CompensationTable",
    "ContourResult",
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
    "simulate_axis",
    "tune",
]
