"""
Friction for a servo controller
===============================

The complete model's torque-speed curve of the study's screw at 20 and 40 °C, both
directions, and the Stribeck form a drive's friction feed-forward takes, fitted to it
(``ballscrew export-friction --form stribeck``): Coulomb and static torque, Stribeck
speed and exponent, viscous coefficient, each with its fit error.
"""

import matplotlib.pyplot as plt
import numpy as np

from ballscrew.io.case import load_case
from ballscrew.servo.controller import stribeck_torque
from ballscrew.servo.export import export_friction

case = load_case(None)  # the bundled study case
speeds = np.geomspace(0.1, 300.0, 40)  # rad/s, mirrored to negative speeds
result = export_friction(case, "complete", "stribeck", temperatures=[20.0, 40.0], speeds=speeds)

fig, ax = plt.subplots(figsize=(6.4, 4.0), layout="constrained")
w = np.concatenate([-speeds[::-1], speeds])
for (temp, form), colour in zip(result.fitted, ("C0", "C3"), strict=True):
    model = [row[f"torque {result.model} [N*m]"] for row in result.rows
             if row["temperature [degC]"] == temp]  # fmt: skip
    ax.plot(w, model, "o", ms=3, color=colour, label=f"complete model, {temp:g} °C")
    ax.plot(w, stribeck_torque(w, **form.parameters), "-", color=colour,
            label=f"Stribeck fit (RMS error {form.rms_error:.3f} N·m)")  # fmt: skip
ax.set_xscale("symlog", linthresh=1.0)
ax.set_xlabel("screw speed [rad/s]")
ax.set_ylabel("friction torque [N·m]")
ax.legend(fontsize="small", loc="upper left")
plt.show()
