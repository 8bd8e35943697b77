"""
The energy of an axis over one move
===================================

A 200 kg table on the reference screw (40 x 10 mm double nut, 2 kN preload, PAO ISO VG
68 at 40 °C) moved 300 mm out and back at 15 m/min with 2 m/s² ramps. The complete
model's friction torque over the cycle, the motor torque it takes with the inertia,
and the friction energy beside the catalogue's constant-efficiency rule:
``ballscrew energy`` computes the same from a case file.
"""

import matplotlib.pyplot as plt

from ballscrew import reference_screw
from ballscrew.axis.energy import Axis, axis_cycle
from ballscrew.axis.motion import back_and_forth

profile = back_and_forth(0.3, 0.25, 2.0, dwell_time=0.2)
axis = Axis(moving_mass=200.0, screw_inertia=1.9e-3, motor_inertia=1.2e-3)
r = axis_cycle(profile, reference_screw(), "PAO ISO VG 68", axis, temperature=40.0)

fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(6.4, 4.8), layout="constrained")
top.plot(r.time, profile.speed * 60.0, "k-")
top.set_ylabel("table speed [m/min]")
bottom.plot(r.time, r.motor_torque, "C0-", label="motor torque")
bottom.plot(r.time, r.friction_torque, "C3--", label="screw friction torque (magnitude)")
bottom.set_xlabel("time [s]")
bottom.set_ylabel("torque [N·m]")
bottom.legend(fontsize="small", loc="lower left")
top.set_title(
    f"friction energy {r.friction_energy:.0f} J per cycle "
    f"(constant-efficiency rule {r.constant_efficiency_energy:.0f} J)",
    fontsize="medium",
)
plt.show()
