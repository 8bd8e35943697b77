"""
Friction torque against speed
=============================

The reference screw (40 x 10 mm double nut, 2 kN preload) with a PAO ISO VG 68 oil at
40 °C: the complete model's friction torque over the speed range at three preloads,
beside the makers' catalogue rule, which has no speed term.
"""

import matplotlib.pyplot as plt
import numpy as np

from ballscrew import friction_torque, reference_screw

rpm = np.linspace(10.0, 3000.0, 60)
speed = rpm * 2.0 * np.pi / 60.0  # rad/s

fig, ax = plt.subplots(figsize=(6.4, 4.0), layout="constrained")
for preload, style in ((1000.0, ":"), (2000.0, "-"), (3000.0, "--")):
    screw = reference_screw().replace(preload=preload)
    complete = friction_torque(screw, "PAO ISO VG 68", speed=speed, temperature=40.0, warn=False)
    catalog = friction_torque(
        screw, "PAO ISO VG 68", speed=speed, temperature=40.0, model="catalog", warn=False
    )
    ax.plot(rpm, complete.total, "C0" + style, label=f"complete, {preload / 1e3:g} kN")
    ax.plot(rpm, catalog.total, "C1" + style, label=f"catalogue rule, {preload / 1e3:g} kN")
ax.set_xlabel("screw speed [rpm]")
ax.set_ylabel("friction torque [N·m]")
top = max(line.get_ydata().max() for line in ax.get_lines())
ax.set_ylim(0.0, 1.35 * top)  # room above the curves for the legend
ax.legend(ncols=2, fontsize="small", loc="upper left")
plt.show()
