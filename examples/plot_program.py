"""
A machine through a part program
================================

The example machining centre (``examples/machine_vmc.toml``: X and Y on preloaded
40 x 10 mm double nuts carrying 450 and 800 kg, Z vertical with its 120 kg weight) runs
a short program: a rapid over the part, a plunge, a rectangle with rounded corners and
a drilled hole. Each axis's motor torque over time, the path coloured by the screws'
friction power with every reversal marked, and the load direction across each reversal
of Z (its weight keeps the nut on one flank). ``ballscrew program PART.nc --machine
MACHINE.toml --out DIR`` draws the same for any program.
"""

import warnings
from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from ballscrew.io.machine import load_machine
from ballscrew.program import run_program

warnings.simplefilter("ignore")  # the models' validity notes
# The machine file beside this script (the gallery runs it from examples/, a user from the root).
here = Path(".") if Path("machine_vmc.toml").exists() else Path("examples")
machine = load_machine(here / "machine_vmc.toml")
program = """G21 G90 G17
G0 X300 Y200 Z-140
G1 Z-155 F400
G1 X430 F2500
G3 X450 Y220 R20
G1 Y300
G3 X430 Y320 R20
G1 X320
G3 X300 Y300 R20
G1 Y200
G0 Z-140
G0 X380 Y260
G1 Z-175 F250
G4 P0.5
G0 Z-140
M30
"""
r = run_program(machine, program)

fig, (path, torque) = plt.subplots(1, 2, figsize=(10, 4.2), layout="constrained")
xy = r.motion.position[:, :2] * 1e3
power = r.data["friction_power"].sum("axis").values
sc = path.scatter(xy[:, 0], xy[:, 1], c=power, s=4, cmap="viridis")
fig.colorbar(sc, ax=path, label="friction power of the screws [W]")
for letter, marker in (("X", "o"), ("Y", "s"), ("Z", "^")):
    t = np.array([rev.time for rev in r.axes[letter].reversals])
    if t.size:
        path.scatter(
            np.interp(t, r.motion.time, xy[:, 0]),
            np.interp(t, r.motion.time, xy[:, 1]),
            marker=marker,
            facecolors="none",
            edgecolors="red",
            label=f"{letter} reversal",
        )
path.set_aspect("equal")
path.set_xlabel("X [mm]")
path.set_ylabel("Y [mm]")
path.legend(fontsize="small")
for letter in r.axes:
    torque.plot(r.motion.time, r.data["motor_torque"].sel(axis=letter), label=letter)
torque.set_xlabel("time [s]")
torque.set_ylabel("motor torque [N·m]")
torque.legend()
z = r.axes["Z"]
directions = ", ".join(v.load_direction for v in z.reversals)
torque.set_title(f"Z reversals, load before/after: {directions}", fontsize="small")
for letter, a in r.axes.items():
    print(
        f"{letter}: friction {a.friction_energy:.1f} J ({a.friction_share:.0%}), "
        f"peak {a.peak_torque:.2f} N·m, RMS {a.rms_torque:.2f} N·m, {len(a.reversals)} reversals"
    )
plt.show()
