"""
The preload over a screw's life
===============================

A series of drag-torque measurements (``examples/drag_torque_series.csv``: 13 readings
over 12 000 operating hours at 100 rpm) read back as preloads through the complete
model, their exponential trend with its 95 % band, and when the preload falls to half
its initial value: what ``ballscrew monitor --threshold "50 %"`` prints and plots.
"""

from pathlib import Path

import matplotlib.pyplot as plt
import numpy as np

from ballscrew.fit.monitor import run_monitor
from ballscrew.io.case import load_case
from ballscrew.io.series import read_series

# The series beside this script (run from its folder, or from the repository's root).
data = next(p for p in (Path("drag_torque_series.csv"), Path("examples/drag_torque_series.csv"))
            if p.exists())  # fmt: skip
case = load_case(None)  # the bundled study case: its screw and oil
series = read_series(data, case.screw)
result = run_monitor(case, series, limit="50 %")
assert result.limit is not None
print(f"50 % of the initial preload at {result.crossing:.0f} h "
      f"(95 %: {result.crossing_low:.0f} to {result.crossing_high:.0f} h)")  # fmt: skip

fig, ax = plt.subplots(figsize=(6.4, 4.0), layout="constrained")
grid = np.linspace(series.time[0], series.time[-1], 200)
mean, low, high = result.band(grid)
ax.fill_between(grid, low, high, color="C0", alpha=0.2, label="trend, 95 % band")
ax.plot(grid, mean, "C0-", label="exponential trend")
ax.errorbar(series.time, result.preload, fmt="o", color="C1", markersize=4, capsize=2,
            yerr=[result.preload - result.preload_low, result.preload_high - result.preload],
            label="preload read from each torque (95 %)")  # fmt: skip
ax.axhline(result.limit.value, color="C3", linestyle="--", label="50 % of the initial preload")
ax.axvspan(result.crossing_low, result.crossing_high, color="C3", alpha=0.1)
ax.set_xlabel("operating hours [h]")
ax.set_ylabel("preload [N]")
ax.set_ylim(bottom=0.0)
ax.legend(fontsize="small", loc="lower left")
plt.show()
