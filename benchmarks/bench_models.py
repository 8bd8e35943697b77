"""Throughput of every friction model on a grid of operating points, one core.

Run with ``.venv/bin/python benchmarks/bench_models.py``. For each registered
model it evaluates ``friction_torque`` on a grid of speed x temperature x
axial load (default 100 x 10 x 100 = 1e5 points), prints operating points per
second, the rate on as many scattered points (random speed, temperature and
load as three flat arrays, so no layer can work on fewer values than there
are points), and the speed-up of the grid over calling the same model point
by point in a Python loop in the same process (the loop runs on a sample of
the scattered points and its rate is per point). The targets apply to the
grid; the scattered rate is what a list of unrelated points costs.
Targets (issue 3): catalog >= 1e7 pt/s,
harris-simplified and olaru >= 1e6, viscoelastic >= 1e5, harris-full >= 1e4,
complete >= 1e5 (issue 8), and every model >= 50x faster than the loop.
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import argparse  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402

import numpy as np  # noqa: E402

from ballscrew import friction_torque, lubricants, models, reference_screw  # noqa: E402
from ballscrew.errors import BallScrewValidityWarning  # noqa: E402

TARGETS = {
    "catalog": 1e7,
    "harris-simplified": 1e6,
    "olaru": 1e6,
    "viscoelastic": 1e5,
    "harris-full": 1e4,
    "complete": 1e5,
}


def main() -> None:
    # The grids leave some published ranges on purpose; time the models, not the warnings.
    warnings.simplefilter("ignore", BallScrewValidityWarning)
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--speeds", type=int, default=100)
    parser.add_argument("--temperatures", type=int, default=10)
    parser.add_argument("--loads", type=int, default=100)
    parser.add_argument("--loop-points", type=int, default=200)
    parser.add_argument("--model", action="append", help="only these models")
    args = parser.parse_args()

    screw = reference_screw()
    oil = lubricants.get("PAO ISO VG 68")
    speed = np.linspace(1.0, 314.0, args.speeds)[:, None, None]
    temperature = np.linspace(20.0, 45.0, args.temperatures)[None, :, None]
    axial = np.linspace(-4000.0, 4000.0, args.loads)[None, None, :]
    n = speed.size * temperature.size * axial.size
    rng = np.random.default_rng(1)
    scattered = np.stack(
        [rng.uniform(1.0, 314.0, n), rng.uniform(20.0, 45.0, n), rng.uniform(-4000.0, 4000.0, n)],
        axis=1,
    )
    sample = scattered[: args.loop_points]

    print(f"grid: {n} operating points; loop sample: {args.loop_points} points; one core")
    header = (
        f"{'model':<19}{'grid [pt/s]':>13}{'target':>10}{'scattered':>13}"
        f"{'loop [pt/s]':>13}{'speed-up':>10}"
    )
    print(header)
    print("-" * len(header))
    for spec in models():
        if args.model and spec.name not in args.model:
            continue
        best = np.inf
        for _ in range(2):
            start = time.perf_counter()
            friction_torque(
                screw,
                oil,
                speed=speed,
                temperature=temperature,
                axial_load=axial,
                model=spec.name,
            )
            best = min(best, time.perf_counter() - start)
        grid_rate = n / best
        start = time.perf_counter()
        friction_torque(
            screw,
            oil,
            speed=scattered[:, 0],
            temperature=scattered[:, 1],
            axial_load=scattered[:, 2],
            model=spec.name,
        )
        scattered_rate = n / (time.perf_counter() - start)
        start = time.perf_counter()
        for w, t, f in sample:
            friction_torque(screw, oil, speed=w, temperature=t, axial_load=f, model=spec.name)
        loop_rate = args.loop_points / (time.perf_counter() - start)
        target = TARGETS.get(spec.name, 0.0)
        flag = "" if grid_rate >= target else "  below target"
        print(
            f"{spec.name:<19}{grid_rate:>13.3e}{target:>10.0e}{scattered_rate:>13.3e}{loop_rate:>13.3e}"
            f"{grid_rate / loop_rate:>9.0f}x{flag}"
        )


if __name__ == "__main__":
    main()
