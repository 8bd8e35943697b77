"""
The six models on one screw
===========================

Every registered model on the reference screw (40 x 10 mm double nut, 2 kN preload,
PAO ISO VG 68 at 40 °C): the complete model predicts, the catalogue rule is the makers'
number, and the study's models (simplified and full Harris, Olaru, viscoelastic) differ
by orders of magnitude, hence the logarithmic axis. ``ballscrew validate`` scores them
against public numbers.
"""

import matplotlib.pyplot as plt
import numpy as np

from ballscrew import friction_torque, models, reference_screw

rpm = np.geomspace(10.0, 3000.0, 40)
speed = rpm * 2.0 * np.pi / 60.0
styles = ["-", "--", "-.", ":", (0, (5, 1)), (0, (3, 1, 1, 1, 1, 1))]
markers = ["o", "s", "^", "v", "D", "x"]

fig, ax = plt.subplots(figsize=(6.4, 4.2), layout="constrained")
for k, spec in enumerate(models()):
    result = friction_torque(
        reference_screw(), "PAO ISO VG 68", speed=speed, temperature=40.0, model=spec.name,
        warn=False,
    )  # fmt: skip
    ax.plot(rpm, result.total, linestyle=styles[k], marker=markers[k], markevery=6,
            label=spec.name)  # fmt: skip
ax.set_xscale("log")
ax.set_yscale("log")
ax.set_xlabel("screw speed [rpm]")
ax.set_ylabel("friction torque [N·m]")
ax.legend(ncols=3, fontsize="small", loc="lower center", bbox_to_anchor=(0.5, 1.0))
plt.show()
