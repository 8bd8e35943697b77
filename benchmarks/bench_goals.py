"""Issue 51's figures in one run, each with its goal and its ratio to the goal, CPU and wall.

Run with ``.venv/bin/python benchmarks/bench_goals.py [--quick]``. Each figure is measured
on one core: CPU seconds are this process's (``time.process_time``) or, for a whole
command, the child process's user + system time; wall seconds beside them. The ratio is
the figure over its goal, written so that above 1 meets it (a rate over its floor, a
ceiling over a time).

- one-point ``ballscrew torque --speed "100 rpm" --model complete``, whole process
  (median of 5, after one run that warms the file cache): goal < 0.5 s CPU;
- harris-simplified on 1e5 scattered points (median of 3 after a warm-up): goal
  >= 8e5 points per CPU-second;
- 1000 new screws x 1000 speeds, complete (``bench_many_screws.py``): goal >= 1e6 points
  per CPU-second;
- one point of the complete model through ``friction_torque`` (mean of 200 calls): goal
  < 0.5 ms CPU;
- ``ballscrew select`` over issue 51's pool (``bench_select.py --motors``: catalogue rows
  and ISO sizes of 20-63 mm x 5-40 mm, 6 oils x the example table's 4 motors, 2352
  candidates): goal >= 67 candidates per CPU-second (2000 in 30 s).

The 10 000-block program ``bench_program.py --max 1e4`` (< 10 s CPU) and the circle at
1 kHz ``ballscrew contour`` (< 2 s CPU) have their own; ``--quick`` takes 300 screws
instead of 1000 and 2 oils (784 candidates) instead of 6.
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import argparse  # noqa: E402
import resource  # noqa: E402
import statistics  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))

from bench_many_screws import measure  # noqa: E402
from bench_select import DEFAULT_MOVE, TARGET_RATE, motor_pool, time_select  # noqa: E402

from ballscrew import friction_torque, lubricants, reference_screw  # noqa: E402

ROWS: list[tuple[str, float, float, float, bool]] = []
"""(figure, value, wall value, goal, higher is better) of this run."""


def _row(name: str, value: float, wall: float, goal: float, higher: bool) -> None:
    ROWS.append((name, value, wall, goal, higher))
    ratio = value / goal if higher else goal / value
    verdict = "meets" if ratio >= 1.0 else "MISSES"
    print(f"{name:<58}{value:>11.3g}{wall:>11.3g}{goal:>9.3g}{ratio:>8.2f}  {verdict}",
          flush=True)  # fmt: skip


def one_point_command() -> None:
    """The whole process of a one-point ``ballscrew torque`` (median of 5)."""
    run = [sys.executable, "-m", "ballscrew", "torque", "--speed", "100 rpm", "--model",
           "complete"]  # fmt: skip
    cpu, wall = [], []
    for i in range(6):
        before, start = resource.getrusage(resource.RUSAGE_CHILDREN), time.perf_counter()
        subprocess.run(run, check=True, capture_output=True)
        after, end = resource.getrusage(resource.RUSAGE_CHILDREN), time.perf_counter()
        if i:  # the first warms the file cache
            cpu.append(after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime)
            wall.append(end - start)
    _row("one-point 'ballscrew torque' [s CPU, whole process]", statistics.median(cpu),
         statistics.median(wall), 0.5, False)  # fmt: skip


def harris_simplified_scattered(n: int = 100_000) -> None:
    """harris-simplified on ``n`` unrelated points (speed, temperature, load drawn)."""
    screw, oil = reference_screw(), lubricants.get("PAO ISO VG 68")
    rng = np.random.default_rng(1)
    w, t, fa = rng.uniform(1.0, 314.0, n), rng.uniform(20.0, 45.0, n), rng.uniform(-4e3, 4e3, n)

    def call(k: int) -> None:
        friction_torque(screw, oil, speed=w[:k], temperature=t[:k], axial_load=fa[:k],
                        model="harris-simplified")  # fmt: skip

    call(1000)
    cpu, wall = [], []
    for _ in range(3):
        c, s = time.process_time(), time.perf_counter()
        call(n)
        cpu.append(time.process_time() - c)
        wall.append(time.perf_counter() - s)
    _row("harris-simplified, 1e5 scattered points [points/CPU-s]", n / statistics.median(cpu),
         n / statistics.median(wall), 8e5, True)  # fmt: skip


def many_screws(count: int) -> None:
    """``count`` new screws x 1000 speeds (``bench_many_screws.measure``)."""
    m = measure(count, 1000)
    _row(f"complete, {count} new screws x 1000 speeds [points/CPU-s]", m["per_cpu_s"],
         m["per_wall_s"], 1e6, True)  # fmt: skip


def complete_one_point(calls: int = 200) -> None:
    """One operating point of the complete model through ``friction_torque``."""
    screw, oil = reference_screw(), lubricants.get("PAO ISO VG 68")
    kw = {"speed": 100.0, "temperature": 40.0, "axial_load": 500.0}
    friction_torque(screw, oil, **kw)  # type: ignore[arg-type]
    c, s = time.process_time(), time.perf_counter()
    for _ in range(calls):
        friction_torque(screw, oil, **kw)  # type: ignore[arg-type]
    cpu, wall = (time.process_time() - c) / calls, (time.perf_counter() - s) / calls
    _row("complete, one point through friction_torque [ms CPU]", cpu * 1e3, wall * 1e3, 0.5,
         False)  # fmt: skip


def selection(oils: int) -> None:
    """``run_select`` over issue 51's pool (``bench_select.motor_pool``) with ``oils`` oils."""
    from ballscrew.io.case import load_case

    case = load_case(Path(__file__).resolve().parents[1] / "examples" / "vertical_32x5.toml")
    pool = motor_pool(case, oils)
    r = time_select(case, pool, DEFAULT_MOVE.format(dwell="3 s"))
    _row(f"select, {len(pool)} candidates [candidates/CPU-s]", r["candidates"] / r["cpu_s"],
         r["candidates"] / r["wall_s"], TARGET_RATE, True)  # fmt: skip


def main() -> None:
    warnings.simplefilter("ignore")
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--quick", action="store_true", help="300 screws instead of 1000")
    args = parser.parse_args()
    print(f"{'figure':<58}{'CPU':>11}{'wall':>11}{'goal':>9}{'ratio':>8}")
    one_point_command()
    harris_simplified_scattered()
    many_screws(300 if args.quick else 1000)
    complete_one_point()
    selection(2 if args.quick else 6)


if __name__ == "__main__":
    main()
