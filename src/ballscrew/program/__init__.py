"""A machine and its part program: each feed axis's energy, torques, heat and reversals.

:func:`run_program` reads a G-code program (:mod:`.gcode`), plans its
jerk-limited motion with look-ahead (:mod:`.planner`), and runs every linear
axis of a machine file (:mod:`ballscrew.io.machine`) through it with the axis
wing (:mod:`.axes`). Needs the ``program`` extra (ruckig, xarray).
"""

from .axes import AxisResult, ProgramResult, Reversal, run_program
from .gcode import Program, read_program

__all__ = ["AxisResult", "Program", "ProgramResult", "Reversal", "read_program", "run_program"]
