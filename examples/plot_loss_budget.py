"""
The loss budget against speed
=============================

Where the complete model's friction torque goes: each loss mechanism of the reference
screw (40 x 10 mm double nut, 2 kN preload, PAO ISO VG 68 at 40 °C) over the speed
range, stacked. Components that stay zero on this screw (seals, 4-point spin) are left
out.
"""

import matplotlib.pyplot as plt
import numpy as np

from ballscrew import friction_torque, reference_screw

rpm = np.linspace(10.0, 3000.0, 60)
result = friction_torque(
    reference_screw(), "PAO ISO VG 68", speed=rpm * 2.0 * np.pi / 60.0, temperature=40.0,
    warn=False,
)  # fmt: skip
parts = {name: np.broadcast_to(value, rpm.shape) for name, value in result.components.items()}
parts = {name: value for name, value in parts.items() if np.any(value > 0.0)}

fig, ax = plt.subplots(figsize=(6.4, 4.0), layout="constrained")
ax.stackplot(rpm, *parts.values(), labels=[n.replace("_", " ") for n in parts],
             hatch=["", "//", "..", "xx", "\\\\", "--"][: len(parts)], alpha=0.85)  # fmt: skip
ax.plot(rpm, result.total, "k-", lw=1.2, label="total")
ax.set_xlabel("screw speed [rpm]")
ax.set_ylabel("friction torque [N·m]")
ax.set_xlim(rpm[0], rpm[-1])
ax.set_ylim(0.0, 1.45 * float(result.total.max()))  # room above for the legend
ax.legend(ncols=3, fontsize="small", loc="upper left")
plt.show()
