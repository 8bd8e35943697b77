"""A machine and its part program: each feed axis's energy, torques, heat and reversals.

:func:`run_program` reads a G-code program (:mod:`.gcode`), plans its
jerk-limited motion with look-ahead (:mod:`.planner`), and runs every linear
axis of a machine file (:mod:`ballscrew.io.machine`) through it with the axis
wing (:mod:`.axes`). A program the built-in reader refuses can be read by
LinuxCNC's interpreter where it is installed (:mod:`.rs274`). Needs the
``program`` extra (ruckig, xarray).
"""

from .axes import AxisResult, ProgramResult, Reversal, run_program
from .gcode import Program, read_program
from .rs274 import ReadProgram, read_part_program, read_program_rs274

__all__ = [
    "AxisResult", "Program", "ProgramResult", "ReadProgram", "Reversal", "read_part_program",
    "read_program", "read_program_rs274", "run_program",
]  # fmt: skip
