"""
A torque map of a catalogue screw
=================================

The complete model's friction torque of a HIWIN R40-10K5-FDC double nut (named by its
catalogue designation, preload 5 % of its dynamic load rating, mineral ISO VG 68 at
40 °C) over screw speed and axial load in one broadcast call: the map a designer
reads the drag of a working point from.
"""

import matplotlib.pyplot as plt
import numpy as np

from ballscrew import friction_torque
from ballscrew.io.case import parse_case

case = parse_case("""
title = "HIWIN R40-10K5-FDC"
[screw]
designation = "HIWIN R40-10K5-FDC"
preload_share = "5 %"
[lubricant]
name = "mineral ISO VG 68"
""")
rpm = np.linspace(10.0, 3000.0, 60)
load = np.linspace(-8000.0, 8000.0, 41)
result = friction_torque(case.screw, case.lubricant, speed=rpm[None, :] * np.pi / 30.0,
                         temperature=40.0, axial_load=load[:, None], warn=False)  # fmt: skip

fig, ax = plt.subplots(figsize=(6.4, 4.2), layout="constrained")
levels = np.linspace(float(result.total.min()), float(result.total.max()), 12)
filled = ax.contourf(rpm, load / 1e3, result.total, levels=levels, cmap="viridis")
lines = ax.contour(rpm, load / 1e3, result.total, levels=levels[::2], colors="k",
                   linewidths=0.6)  # fmt: skip
ax.clabel(lines, fmt="%.2f", fontsize=7)
fig.colorbar(filled, ax=ax, label="friction torque [N·m]", format="%.2f")
ax.set_xlabel("screw speed [rpm]")
ax.set_ylabel("axial load [kN]")
ax.set_title(f"{case.title}, preload {case.screw.preload:.0f} N", fontsize="medium")
plt.show()
