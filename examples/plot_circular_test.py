"""
Circular test with quadrant glitches
====================================

A simulated circular test after ISO 230-4 (``ballscrew contour``): the example
XY table (``examples/xy_table_32x10.toml``, a 32 × 10 mm double nut carrying
250 kg on each axis) follows a circle of 20 mm radius at 2 m/min under a CNC's
servo cascade. The ballbar's polar plot magnifies the radial deviation: the
spikes at 0°, 90°, 180° and 270° are the quadrant glitches, where one axis
reverses and the screw's friction changes sign. The dashed trace is the same
test with the friction compensation of a 16-point LinuxCNC table from the
model, fed forward at the commanded speed.
"""

from pathlib import Path

import matplotlib.pyplot as plt

from ballscrew.io.case import load_case
from ballscrew.report.contour import polar_figure
from ballscrew.servo import run_contour

# The case beside this script (the gallery runs it from examples/, a user from the root).
case = load_case(next(p for p in (Path("xy_table_32x10.toml"), Path("examples/xy_table_32x10.toml"))
                      if p.exists()))  # fmt: skip
result = run_contour([case], radius=0.02, feed=2.0 / 60.0, directions=("CCW",))
for run in result.circles:
    label = "with compensation" if run.compensated else "without compensation"
    print(
        f"{label}: G = {run.circular_deviation * 1e6:.1f} um, "
        f"largest glitch {run.largest_glitch * 1e6:.1f} um"
    )
print(f"glitch reduction: {result.reduction:.2f}; CPU {result.cpu_seconds:.2f} s")

polar_figure(list(result.circles), case.title, figure=plt.figure(figsize=(6.0, 6.0)))
plt.show()
