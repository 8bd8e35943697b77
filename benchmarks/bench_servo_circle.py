"""Samples per CPU-second of ``simulate_axis``: the 1 kHz circle.

    .venv/bin/python benchmarks/bench_servo_circle.py             # 7 repeats
    .venv/bin/python benchmarks/bench_servo_circle.py --repeat 15

Both axes of examples/xy_table_32x10.toml (two masses, the complete model, 20 N of
guideway friction) follow a 50 mm circle at 2 m/min, sampled at 1 ms with the
lead-in arc ``circle_reference`` adds (9 625 samples per axis), without and with the
16-point friction compensation: the sample loop of ``ballscrew contour``. The CPU
time is the process's (time.process_time), the least of the repeats after one warm-up,
so that other jobs on the machine inflate it as little as possible. The last values of
the traces are printed so that two versions can be checked to compute the same.
"""

from __future__ import annotations

import argparse
import time
import warnings
from pathlib import Path

from ballscrew.io.case import load_case
from ballscrew.servo.cascade import tune
from ballscrew.servo.contour import TABLE_POINTS, circle_reference, controller_compensation
from ballscrew.servo.plant import axis_dynamics
from ballscrew.servo.simulate import simulate_axis
from ballscrew.servo.tables import fit_table

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--repeat", type=int, default=7, help="timed runs (the least counts)")
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    feed = 2.0 / 60.0
    axis = axis_dynamics(load_case(ROOT / "examples/xy_table_32x10.toml"), guide_coulomb=20.0)
    gains = tune(axis, sampling_time=1e-3)
    x, y, vx, vy, ax, ay, _ = circle_reference(0.05, feed, gains.sampling_time)
    table = fit_table(axis.speeds, axis.friction, TABLE_POINTS, max(1.25 * feed, 0.01))
    fx = controller_compensation(table, x, gains.sampling_time)
    fy = controller_compensation(table, y, gains.sampling_time)

    def run() -> tuple[float, ...]:
        tx = simulate_axis(axis, gains, x, vx, ax)
        ty = simulate_axis(axis, gains, y, vy, ay, fy)
        cx = simulate_axis(axis, gains, x, vx, ax, fx)
        return float(tx.table[-1]), float(ty.force[-1]), float(cx.friction[-1])

    last = run()  # warm-up
    best = float("inf")
    for _ in range(args.repeat):
        start = time.process_time()
        run()
        best = min(best, time.process_time() - start)
    samples = 3 * x.size
    print(f"{samples} samples in {best:.3f} s of CPU: {samples / best:,.0f} samples/CPU-s")
    print("last values:", ", ".join(f"{v:.12g}" for v in last))


if __name__ == "__main__":
    main()
