"""
The simplified model against the full Harris-type integral
==========================================================

Run with ``.venv/bin/python examples/compare_simplified_full.py``. Evaluates
both models for the bundled reference screw over a grid of screw speed,
preload and temperature (PAO ISO VG 68) and prints the ratio simplified/full
of the friction torque, for the study's reading (rolling speed in the shear
rate) and for the sliding-speed reading. The numbers back the statement in
the docstring of ``ballscrew.friction.harris_simplified``.
"""

from __future__ import annotations

import numpy as np

from ballscrew import friction_torque, lubricants, reference_screw


def main() -> None:
    oil = lubricants.get("PAO ISO VG 68")
    speeds_rpm = np.array([10.0, 100.0, 1000.0, 3000.0])
    speed = speeds_rpm * 2 * np.pi / 60
    temperatures = np.array([20.0, 30.0, 45.0])
    preloads = [500.0, 2000.0, 5000.0]
    print("ratio of friction torque, simplified / full (reference screw, PAO ISO VG 68)")
    print(f"{'preload [N]':>12}{'T [°C]':>8}" + "".join(f"{n:>10.0f} rpm" for n in speeds_rpm))
    ratios: dict[str, list[float]] = {"rolling": [], "sliding": []}
    for fpr in preloads:
        screw = reference_screw().replace(preload=fpr)
        for t in temperatures:
            full = friction_torque(screw, oil, speed=speed, temperature=t, model="harris-full")
            for reading in ("rolling", "sliding"):
                simple = friction_torque(
                    screw, oil, speed=speed, temperature=t, shear_velocity=reading
                )
                ratio = simple.total / full.total
                ratios[reading].extend(ratio.tolist())
                if reading == "rolling":
                    print(f"{fpr:>12.0f}{t:>8.0f}" + "".join(f"{r:>14.1f}" for r in ratio))
    for reading, values in ratios.items():
        print(
            f"shear_velocity={reading!r}: simplified/full from {min(values):.1f} "
            f"to {max(values):.1f}"
        )


if __name__ == "__main__":
    main()
