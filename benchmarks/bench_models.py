"""Throughput of every friction model on grids, scattered points and single points, one core.

Run with ``.venv/bin/python benchmarks/bench_models.py``. For each registered
model it evaluates ``friction_torque`` on a grid of speed x temperature x
axial load (default 100 x 10 x 100 = 1e5 points), on as many scattered points
(random speed, temperature and load as three flat arrays, so no layer can work
on fewer values than there are points), and point by point in a Python loop
(one call per point, on a sample of the scattered points). Every rate is given
per CPU-second of this process (``time.process_time``: what the work costs,
whatever else the machine runs) and per wall-clock second; the one-point
column is the CPU cost of one call. The last lines time, in fresh processes,
a one-point ``ballscrew torque`` (whole process: start-up, case, computation)
and the energy of a move with its temperature (``energy_run``, in process
after a warm-up), for 1 and 10 cycles, and measure the peak memory (maximum
resident set) of one 1e7-point call of the complete model on a grid, with and
without its components (about 45 s CPU; ``--no-memory`` skips it).

Targets: on the grid (issues 3 and 8) catalog >= 1e7 pt/s, harris-simplified
and olaru >= 1e6, viscoelastic >= 1e5, harris-full >= 1e4, complete >= 1e5;
scattered (issue 25) complete, olaru and harris-simplified >= 1e6; one point
(issue 25) complete < 0.5 ms, catalog < 0.2 ms; the one-point command < 0.5 s
CPU; a move's energy with its temperature < 0.2 s per cycle; a 1e7-point call
(total only) < 400 MB.
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
from collections.abc import Callable  # noqa: E402

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
SCATTERED_TARGETS = {"complete": 1e6, "olaru": 1e6, "harris-simplified": 1e6}
ONE_POINT_TARGETS_MS = {"complete": 0.5, "catalog": 0.2}
MOVE = (
    "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2, force=2 kN, "
    "force_from=50 mm, force_to=250 mm"
)

_ENERGY = f"""
import time, warnings
warnings.simplefilter("ignore")
from ballscrew.io.case import load_case
from ballscrew.axis.motion import parse_move
from ballscrew.axis.run import energy_run, profile_from_move
case, m = load_case(None), parse_move({MOVE!r})
energy_run(case, profile_from_move(m, 1), ["complete"], cycles=1, run_time=3600.0, move=m)
for cycles in (1, 10):
    profile = profile_from_move(m, cycles)
    cpu = time.process_time()
    energy_run(case, profile, ["complete"], cycles=cycles, run_time=3600.0, move=m)
    print(cycles, time.process_time() - cpu)
"""


_MEMORY = """
import resource, sys, time, warnings
import numpy as np
warnings.simplefilter("ignore")
from ballscrew import friction_torque, lubricants, reference_screw
screw, oil = reference_screw(), lubricants.get("PAO ISO VG 68")
w = np.linspace(1.0, 314.0, 1000)[:, None, None]
t = np.linspace(20.0, 45.0, 100)[None, :, None]
fa = np.linspace(-4000.0, 4000.0, 100)[None, None, :]
components = sys.argv[1] == "1"
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
cpu = time.process_time()
friction_torque(screw, oil, speed=w, temperature=t, axial_load=fa, components=components)
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
print(before / 1024, peak / 1024, time.process_time() - cpu)
"""


def _memory() -> None:
    """Peak memory of one 1e7-point call (complete, a 1000 x 100 x 100 grid), fresh processes."""
    for components in (False, True):
        run = [sys.executable, "-c", _MEMORY, "1" if components else "0"]
        out = subprocess.run(run, check=True, capture_output=True, text=True).stdout.split()
        before, peak, cpu = (float(x) for x in out)
        flag = "" if peak < 400.0 or components else "  above target 400 MB"
        print(
            f"1e7-point grid, complete, components={components}: peak {peak:.0f} MB "
            f"({before:.0f} MB before the call; {peak * 2**20 / 1e7:.0f} bytes a point), "
            f"{cpu:.1f} s CPU{flag}"
        )


def _timed(func: Callable[[], object]) -> tuple[float, float]:
    """CPU and wall seconds of one call."""
    cpu, wall = time.process_time(), time.perf_counter()
    func()
    return time.process_time() - cpu, time.perf_counter() - wall


def _child_cpu(command: list[str]) -> float:
    """User + system CPU seconds of one child process run to its end."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(command, check=True, capture_output=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)


def _commands(runs: int) -> None:
    """The one-point command (whole process) and the energy of a move (in process)."""
    torque = [sys.executable, "-m", "ballscrew", "torque", "--speed", "100 rpm"]
    cpu = [_child_cpu(torque) for _ in range(runs + 1)][1:]  # the first warms the caches
    median = statistics.median(cpu)
    flag = "" if median < 0.5 else "  above target 0.5 s"
    print(
        f"one-point 'ballscrew torque --speed \"100 rpm\"': {median:.3f} s CPU "
        f"(median of {runs}; {min(cpu):.3f} to {max(cpu):.3f}), whole process{flag}"
    )
    run = [sys.executable, "-c", _ENERGY]
    out = subprocess.run(run, check=True, capture_output=True, text=True).stdout
    for line in out.split("\n"):
        if line.strip():
            cycles, seconds = int(line.split()[0]), float(line.split()[1])
            per = seconds / cycles
            flag = "" if per < 0.2 else "  above target 0.2 s per cycle"
            print(
                f"energy of {cycles:>2} cycle(s) with its temperature (energy_run, complete): "
                f"{seconds:.3f} s CPU, {per:.3f} s per cycle{flag}"
            )


def _model_row(name: str, points: dict[str, np.ndarray], sample: np.ndarray) -> str:
    """One model's grid, scattered and one-point rates, and the targets it misses."""
    screw, oil = reference_screw(), lubricants.get("PAO ISO VG 68")
    speed, temperature, axial, scattered = (
        points[k] for k in ("speed", "temperature", "axial", "scattered")
    )
    n = len(scattered)

    def grid() -> None:
        friction_torque(screw, oil, speed=speed, temperature=temperature, axial_load=axial,
                        model=name)  # fmt: skip

    def scatter(rows: np.ndarray) -> None:
        friction_torque(screw, oil, speed=rows[:, 0], temperature=rows[:, 1],
                        axial_load=rows[:, 2], model=name)  # fmt: skip

    def loop() -> None:
        for w, t, f in sample:
            friction_torque(screw, oil, speed=w, temperature=t, axial_load=f, model=name)

    runs = [_timed(grid) for _ in range(2)]
    grid_cpu, grid_wall = min(c for c, _ in runs), min(w for _, w in runs)
    scatter(scattered[:1000])  # warm-up: first-use imports and tables
    scat_cpu, scat_wall = _timed(lambda: scatter(scattered))
    loop_cpu, loop_wall = _timed(loop)
    one_ms, one_wall = (x / len(sample) * 1e3 for x in (loop_cpu, loop_wall))
    flags = [
        what
        for what, missed in (
            ("grid", n / grid_cpu < TARGETS.get(name, 0.0)),
            ("scattered", n / scat_cpu < SCATTERED_TARGETS.get(name, 0.0)),
            ("one point", one_ms > ONE_POINT_TARGETS_MS.get(name, np.inf)),
        )
        if missed
    ]
    scat_target, one_target = SCATTERED_TARGETS.get(name), ONE_POINT_TARGETS_MS.get(name)
    return (
        f"{name:<18}{n / grid_cpu:>11.3e} ({n / grid_wall:.2e}){TARGETS.get(name, 0.0):>8.0e}"
        f"{n / scat_cpu:>11.3e} ({n / scat_wall:.2e})"
        f"{'' if scat_target is None else f'{scat_target:.0e}':>8}"
        f"{one_ms:>9.3f} ({one_wall:>6.3f}){'' if one_target is None else f'{one_target:g}':>8}"
        + (f"  below target: {', '.join(flags)}" if flags else "")
    )


def main() -> None:
    # The grids leave some published ranges on purpose; time the models, not the warnings.
    warnings.simplefilter("ignore", BallScrewValidityWarning)
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--speeds", type=int, default=100)
    parser.add_argument("--temperatures", type=int, default=10)
    parser.add_argument("--loads", type=int, default=100)
    parser.add_argument("--loop-points", type=int, default=200)
    parser.add_argument("--model", action="append", help="only these models")
    parser.add_argument(
        "--command-runs", type=int, default=3, help="runs of the one-point command (0: none)"
    )
    parser.add_argument(
        "--no-memory", action="store_true", help="skip the 1e7-point memory measurement"
    )
    args = parser.parse_args()

    points = {
        "speed": np.linspace(1.0, 314.0, args.speeds)[:, None, None],
        "temperature": np.linspace(20.0, 45.0, args.temperatures)[None, :, None],
        "axial": np.linspace(-4000.0, 4000.0, args.loads)[None, None, :],
    }
    n = args.speeds * args.temperatures * args.loads
    rng = np.random.default_rng(1)
    points["scattered"] = np.stack(
        [rng.uniform(1.0, 314.0, n), rng.uniform(20.0, 45.0, n), rng.uniform(-4000.0, 4000.0, n)],
        axis=1,
    )
    sample = points["scattered"][: args.loop_points]

    print(
        f"grid and scattered: {n} operating points each; one point: mean of "
        f"{args.loop_points} calls; one core; per CPU-second (per wall-second)"
    )
    header = (
        f"{'model':<18}{'grid [pt/s]':>22}{'target':>8}{'scattered [pt/s]':>22}{'target':>8}"
        f"{'one point [ms]':>18}{'target':>8}"
    )
    print(header)
    print("-" * len(header))
    for spec in models():
        if not args.model or spec.name in args.model:
            print(_model_row(spec.name, points, sample))
    if args.command_runs > 0:
        _commands(args.command_runs)
    if not args.no_memory:
        _memory()


if __name__ == "__main__":
    main()
