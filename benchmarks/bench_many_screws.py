"""Many new screws in one call: points per CPU-second of ``friction_torques`` (issue 39).

Run with ``.venv/bin/python benchmarks/bench_many_screws.py [--screws 1000] [--speeds
1000] [--grid]``. Draws ``--screws`` screws none of which the process has seen
(pitch diameter 16-63 mm, ball 9-16 % of it, lead from just above the ball to 40 mm,
preload 200-5000 N, conformities and contact angle drawn too; two in three double
nuts, one in three 4-point nuts), warms up on three other screws, then times one
``friction_torques`` call of the complete model (the default) on ``--speeds`` speeds
at 40 °C and 1.5 kN (``--grid``: a 10 x 10 x 10 grid of speed, temperature and load
instead). It prints the points per CPU-second (``time.process_time``: one core, what
the work costs whatever else the machine runs) and per wall-second, against the
target of issue 39: 1e6 points per CPU-second for 1000 new screws x 1000 speeds.

The helix's compiled loop is loaded first, as a long run loads it (``load_kernel``).
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import argparse  # noqa: E402
import math  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402
from typing import Any  # noqa: E402

import numpy as np  # noqa: E402

from ballscrew import BallScrew, friction_torques, lubricants, reference_screw  # noqa: E402
from ballscrew.errors import BallScrewPlausibilityWarning, BallScrewValidityWarning  # noqa: E402

TARGET = 1e6
"""Points per CPU-second for 1000 new screws x 1000 speeds (issue 39, item 4)."""


def new_screws(count: int, seed: int = 39) -> list[BallScrew]:
    """``count`` buildable screws of different diameters, leads, balls and preloads."""
    rng = np.random.default_rng(seed)
    base = reference_screw()
    screws = []
    for i in range(count):
        d = rng.uniform(0.016, 0.063)
        ball = rng.uniform(0.09, 0.16) * d
        screws.append(
            base.replace(
                pitch_diameter=d, ball_diameter=ball, lead=rng.uniform(1.1 * ball, 0.04),
                preload=rng.uniform(200.0, 5000.0),
                nut="single-4point" if i % 3 == 2 else "double",
                conformity_screw=rng.uniform(0.52, 0.57), conformity_nut=rng.uniform(0.52, 0.57),
                contact_angle=math.radians(rng.uniform(40.0, 50.0)),
            )
        )  # fmt: skip
    return screws


def measure(count: int, speeds: int, grid: bool = False) -> dict[str, Any]:
    """CPU and wall seconds of one call on ``count`` new screws, and the rates."""
    from ballscrew.helix import load_kernel

    load_kernel()
    oil = lubricants.get("PAO ISO VG 68")
    if grid:
        points: dict[str, Any] = {
            "speed": np.linspace(1.0, 314.0, 10)[:, None, None],
            "temperature": np.linspace(20.0, 45.0, 10)[None, :, None],
            "axial_load": np.linspace(-4000.0, 4000.0, 10)[None, None, :],
        }
        per_screw = 1000
    else:
        points = {"speed": np.linspace(1.0, 314.0, speeds), "temperature": 40.0,
                  "axial_load": 1500.0}  # fmt: skip
        per_screw = speeds
    warm = new_screws(3, seed=99)
    friction_torques(warm, oil, components=False, warn=False, **points)  # first-use costs
    screws = new_screws(count)
    cpu, wall = time.process_time(), time.perf_counter()
    friction_torques(screws, oil, components=False, warn=False, **points)
    cpu, wall = time.process_time() - cpu, time.perf_counter() - wall
    n = count * per_screw
    return {"points": n, "cpu_s": cpu, "wall_s": wall, "per_cpu_s": n / cpu, "per_wall_s": n / wall}


def main() -> None:
    warnings.simplefilter("ignore", BallScrewValidityWarning)
    warnings.simplefilter("ignore", BallScrewPlausibilityWarning)  # drawn screws, odd balls
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--screws", type=int, default=1000)
    parser.add_argument("--speeds", type=int, default=1000)
    parser.add_argument("--grid", action="store_true", help="a 10 x 10 x 10 grid a screw")
    args = parser.parse_args()
    m = measure(args.screws, args.speeds, args.grid)
    what = "10 x 10 x 10 grid" if args.grid else f"{args.speeds} speeds"
    verdict = "meets" if m["per_cpu_s"] >= TARGET else "misses"
    print(
        f"{args.screws} new screws x {what} (friction_torques, complete): "
        f"{m['per_cpu_s']:.3e} points per CPU-second ({m['cpu_s']:.2f} s CPU), "
        f"{m['per_wall_s']:.3e} per wall-second ({m['wall_s']:.2f} s); "
        f"{verdict} the target {TARGET:.0e} (x{m['per_cpu_s'] / TARGET:.2f})"
    )


if __name__ == "__main__":
    main()
