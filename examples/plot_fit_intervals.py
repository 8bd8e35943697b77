"""
A preload fitted to a measured curve, with its interval
=======================================================

A torque-speed curve "measured" on the reference screw (the complete model at a
1.6 kN preload with 4 % noise, so the truth is known) and the preload ``ballscrew fit``
finds from it, with its 95 % interval, starting from the nominal 2 kN. The residuals
show what the fitted model leaves unexplained.
"""

import matplotlib.pyplot as plt
import numpy as np

from ballscrew import friction_torque, reference_screw
from ballscrew.fit.calibration import fit_parameters
from ballscrew.io.measured import MeasuredCurve

screw = reference_screw()  # 2 kN nominal preload
rpm = np.geomspace(10.0, 3000.0, 25)
speed = rpm * np.pi / 30.0
truth = friction_torque(screw.replace(preload=1600.0), "mineral ISO VG 68", speed=speed,
                        temperature=40.0, warn=False).total  # fmt: skip
rng = np.random.default_rng(1)
measured = MeasuredCurve(speed, truth * (1.0 + 0.04 * rng.standard_normal(rpm.size)), "synthetic")
fit = fit_parameters(screw, "mineral ISO VG 68", measured, ["preload"], temperature=40.0)
p = fit.estimates["preload"]
print(f"preload {p.value:.0f} N, 95 % {p.low:.0f} to {p.high:.0f} N (truth 1600 N)")

fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(6.4, 4.8), layout="constrained")
top.plot(rpm, measured.torque, "o", ms=4, label="measured (synthetic)")
top.plot(rpm, fit.fitted, "-", label=f"fitted: preload {p.value:.0f} N [{p.low:.0f}, {p.high:.0f}]")
top.set_ylabel("friction torque [N·m]")
top.legend(fontsize="small")
bottom.axhline(0.0, color="0.5", lw=0.8)
bottom.plot(rpm, measured.torque - fit.fitted, "s", ms=3, color="C3")
bottom.set_xscale("log")
bottom.set_xlabel("screw speed [rpm]")
bottom.set_ylabel("residual [N·m]")
plt.show()
