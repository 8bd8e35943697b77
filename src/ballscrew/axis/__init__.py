"""The axis around the screw.

Motion profiles (:mod:`.motion`), torques, powers and energies over a cycle
(:mod:`.energy`), the motor's, drive's and DC link's losses from the shaft to the grid
(:mod:`.drive`), the temperature screw and nut reach (:mod:`.thermal`), an axis from
a case file with what it leaves out filled in and stated (:mod:`.setup`), the axis over
its duty for every model at once (:mod:`.duty`) and the whole axis check
(:mod:`.check`), its criteria with an uncertain input one function each
(:mod:`.criteria`) and their Monte Carlo's draws (:mod:`.uncertainty`).

The entry points of the commands: :func:`run_energy` (``ballscrew energy``) and
:func:`run_check` (``ballscrew check``), each returning one typed result.
"""

from .check import AxisCheck, Criterion, run_check
from .duty import EnergyRun, ModelEnergy, run_energy
from .energy import Axis, CycleResult, axis_cycle

__all__ = [
    "Axis",
    "AxisCheck",
    "Criterion",
    "CycleResult",
    "EnergyRun",
    "ModelEnergy",
    "axis_cycle",
    "run_check",
    "run_energy",
]
