"""
Oil and temperature
===================

The complete model's friction torque of the reference screw (40 x 10 mm double nut,
2 kN preload) at 1000 rpm as the oil warms, for four oils of the bundled library: on
this screw a thinner or a warmer mineral oil gives a lower torque, and the curves close
in as the oil's viscosity falls.
"""

import matplotlib.pyplot as plt
import numpy as np

from ballscrew import friction_torque, reference_screw

temperature = np.linspace(20.0, 80.0, 31)  # degC
speed = 1000.0 * 2.0 * np.pi / 60.0  # rad/s
oils = ["mineral ISO VG 32", "mineral ISO VG 68", "PAO ISO VG 68", "mineral ISO VG 100"]

fig, ax = plt.subplots(figsize=(6.4, 4.0), layout="constrained")
for oil, style, marker in zip(oils, ["-", "--", "-.", ":"], "osD^", strict=True):
    result = friction_torque(
        reference_screw(), oil, speed=speed, temperature=temperature, warn=False
    )
    ax.plot(temperature, result.total, linestyle=style, marker=marker, markevery=5, label=oil)
ax.set_xlabel("oil temperature [°C]")
ax.set_ylabel("friction torque at 1000 rpm [N·m]")
ax.legend(fontsize="small")
plt.show()
