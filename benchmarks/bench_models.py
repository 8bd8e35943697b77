"""Throughput of every friction model on grids, scattered points, many screws and single points.

Run with ``.venv/bin/python benchmarks/bench_models.py``. For each registered
model it evaluates ``friction_torque`` on a grid of speed x temperature x
axial load (default 100 x 10 x 100 = 1e5 points), on as many scattered points
(random speed, temperature and load as three flat arrays, so no layer can work
on fewer values than there are points), and point by point in a Python loop
(one call per point, on a sample of the scattered points). Every rate is given
per CPU-second of this process (``time.process_time``: what the work costs,
whatever else the machine runs) and per wall-clock second; the one-point
column is the CPU cost of one call. Then ``friction_torques`` evaluates 1000
random screws (pitch diameter, lead, conformities, contact angle and preload
drawn around the reference screw; ``--screws``) on a 10 x 10 x 10 grid each.
The last lines time, in fresh processes, a one-point ``ballscrew torque``
(whole process: start-up, case, computation) and the energy of a move with
its temperature (``run_energy``, in process after a warm-up), for 1 and 10
cycles, and measure the peak memory (maximum resident set) of one 1e7-point
call of the complete model on a grid, with and without its components (about
45 s CPU; ``--no-memory`` skips it).

Every figure is printed with its target and its ratio to the figures of
release 0.1.0 (``benchmarks/baseline-0.1.0.json``: this script run on that
release's sources, where a call it lacks is replaced by what it had: a loop of
``friction_torque`` for many screws, all components for the memory). ``--json
FILE`` writes this run's figures; ``--readme`` writes the performance table of
``README.md`` and ``docs/guide.md`` (between their ``perf-table`` markers)
from this run, ``--table-from FILE`` from a recorded run.

``benchmarks/bench_many_screws.py`` then times 1000 new screws of every size
(diameters, leads, balls, preloads, a third of them 4-point nuts) x 1000 speeds,
per CPU-second and per wall-second (issue 39).

Targets: on the grid (issues 3 and 8) catalog >= 1e7 pt/s, harris-simplified
and olaru >= 1e6, viscoelastic >= 1e5, harris-full >= 1e4, complete >= 1e5,
and (issue 25) complete >= 3e6; scattered (issue 25) complete, olaru and
harris-simplified >= 1e6; many screws (issue 25) >= 5e5 pt/s, new screws of every
size x 1000 speeds (issue 39) >= 1e6 pt per CPU-second; one point
(issue 25) complete < 0.5 ms, catalog < 0.2 ms; the one-point command < 0.5 s
CPU; a move's energy with its temperature < 0.2 s per cycle; a 1e7-point call
(total only) < 400 MB.
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import argparse  # noqa: E402
import datetime  # noqa: E402
import json  # noqa: E402
import platform  # noqa: E402
import resource  # noqa: E402
import statistics  # noqa: E402
import subprocess  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
import warnings  # noqa: E402
from collections.abc import Callable  # noqa: E402
from pathlib import Path  # noqa: E402
from typing import Any  # noqa: E402

import numpy as np  # noqa: E402

import ballscrew  # noqa: E402
from ballscrew import friction_torque, lubricants, models, reference_screw  # noqa: E402
from ballscrew.errors import BallScrewPlausibilityWarning, BallScrewValidityWarning  # noqa: E402

HERE = Path(__file__).resolve().parent
BASELINE = HERE / "baseline-0.1.0.json"
TARGETS = {
    "catalog": 1e7,
    "harris-simplified": 1e6,
    "olaru": 1e6,
    "viscoelastic": 1e5,
    "harris-full": 1e4,
    "complete": 3e6,
}
SCATTERED_TARGETS = {"complete": 1e6, "olaru": 1e6, "harris-simplified": 1e6}
ONE_POINT_TARGETS_MS = {"complete": 0.5, "catalog": 0.2}
MANY_SCREWS_TARGET = 5e5
MOVE = (
    "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2, force=2 kN, "
    "force_from=50 mm, force_to=250 mm"
)

_ENERGY = f"""
import time, warnings
warnings.simplefilter("ignore")
from ballscrew.io.case import load_case
from ballscrew.axis.motion import parse_move
from ballscrew.axis.duty import profile_from_move, run_energy
case, m = load_case(None), parse_move({MOVE!r})
run_energy(case, profile_from_move(m, 1), ["complete"], cycles=1, run_time=3600.0, move=m)
for cycles in (1, 10):
    profile = profile_from_move(m, cycles)
    cpu = time.process_time()
    run_energy(case, profile, ["complete"], cycles=cycles, run_time=3600.0, move=m)
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
import inspect
kw = {"components": sys.argv[1] == "1"}
if "components" not in inspect.signature(friction_torque).parameters:
    kw = {}  # a release without the option keeps every component
before = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
cpu = time.process_time()
friction_torque(screw, oil, speed=w, temperature=t, axial_load=fa, **kw)
peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
print(before / 1024, peak / 1024, time.process_time() - cpu)
"""

Figures = dict[str, Any]


def _memory(figures: Figures) -> None:
    """Peak memory of one 1e7-point call (complete, a 1000 x 100 x 100 grid), fresh processes."""
    for components in (False, True):
        run = [sys.executable, "-c", _MEMORY, "1" if components else "0"]
        out = subprocess.run(run, check=True, capture_output=True, text=True).stdout.split()
        before, peak, cpu = (float(x) for x in out)
        key = "memory_components_mb" if components else "memory_total_mb"
        figures[key] = peak
        print(
            f"1e7-point grid, complete, components={components}: peak {peak:.0f} MB "
            f"({before:.0f} MB before the call; {peak * 2**20 / 1e7:.0f} bytes a point), "
            f"{cpu:.1f} s CPU" + _against(figures, key, None if components else 400.0)
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


_BASE: Figures = {}
"""The figures of release 0.1.0, when the baseline file is there."""

LOWER_IS_BETTER = ("_ms", "_s", "_mb")


def _against(figures: Figures, key: str, target: float | None) -> str:
    """``  x N.NN vs 0.1.0`` and a miss of the target, for a figure just measured."""
    value, text = figures[key], ""
    base = _BASE.get(key)
    if base:
        text += f"  x{value / base:.2f} vs 0.1.0"
    if target is not None:
        lower = key.endswith(LOWER_IS_BETTER)
        if (value > target) if lower else (value < target):
            text += f"  misses target {target:g} by x{max(value / target, target / value):.2f}"
    return text


def _commands(figures: Figures, runs: int) -> None:
    """The one-point command (whole process) and the energy of a move (in process)."""
    torque = [sys.executable, "-m", "ballscrew", "torque", "--speed", "100 rpm"]
    cpu = [_child_cpu(torque) for _ in range(runs + 1)][1:]  # the first warms the caches
    figures["command_s"] = statistics.median(cpu)
    print(
        f"one-point 'ballscrew torque --speed \"100 rpm\"': {figures['command_s']:.3f} s CPU "
        f"(median of {runs}; {min(cpu):.3f} to {max(cpu):.3f}), whole process"
        + _against(figures, "command_s", 0.5)
    )
    run = [sys.executable, "-c", _ENERGY]
    done = subprocess.run(run, capture_output=True, text=True)
    if done.returncode != 0:
        print("energy of a move: not measured (this version's run_energy differs)")
        return
    for line in done.stdout.split("\n"):
        if line.strip():
            cycles, seconds = int(line.split()[0]), float(line.split()[1])
            key = f"energy_{cycles}_cycles_per_cycle_s"
            figures[key] = seconds / cycles
            print(
                f"energy of {cycles:>2} cycle(s) with its temperature (run_energy, complete): "
                f"{seconds:.3f} s CPU, {seconds / cycles:.3f} s per cycle"
                + _against(figures, key, 0.2)
            )


def _model(figures: Figures, name: str, points: dict[str, np.ndarray], sample: np.ndarray) -> str:
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

    scatter(scattered[:1000])  # warm-up: first-use imports, tables and compiled kernels
    runs = [_timed(grid) for _ in range(2)]
    grid_cpu, grid_wall = min(c for c, _ in runs), min(w for _, w in runs)
    scat_cpu, scat_wall = _timed(lambda: scatter(scattered))
    loop_cpu, loop_wall = _timed(loop)
    one_ms, one_wall = (x / len(sample) * 1e3 for x in (loop_cpu, loop_wall))
    figures[f"{name}_grid"] = n / grid_cpu
    figures[f"{name}_scattered"] = n / scat_cpu
    figures[f"{name}_one_point_ms"] = one_ms
    scat_target, one_target = SCATTERED_TARGETS.get(name), ONE_POINT_TARGETS_MS.get(name)
    notes = [
        f"{what}{_against(figures, f'{name}_{key}', target)}"
        for what, key, target in (
            ("grid", "grid", TARGETS.get(name)),
            ("scattered", "scattered", scat_target),
            ("one point", "one_point_ms", one_target),
        )
    ]
    return (
        f"{name:<18}{n / grid_cpu:>11.3e} ({n / grid_wall:.2e}){TARGETS.get(name, 0.0):>8.0e}"
        f"{n / scat_cpu:>11.3e} ({n / scat_wall:.2e})"
        f"{'' if scat_target is None else f'{scat_target:.0e}':>8}"
        f"{one_ms:>9.3f} ({one_wall:>6.3f}){'' if one_target is None else f'{one_target:g}':>8}"
        + "\n    "
        + "; ".join(notes)
    )


def random_screws(n: int, seed: int = 2) -> list[Any]:
    """``n`` buildable screws around the reference screw (a design space or a sample)."""
    rng = np.random.default_rng(seed)
    base = reference_screw()
    draws = zip(
        rng.uniform(0.032, 0.050, n), rng.uniform(0.008, 0.020, n), rng.uniform(1e3, 3e3, n),
        rng.uniform(0.52, 0.56, n), rng.uniform(0.52, 0.56, n), rng.uniform(40.0, 50.0, n),
        strict=True,
    )  # fmt: skip
    fields = ("pitch_diameter", "lead", "preload", "conformity_screw", "conformity_nut")
    return [
        base.replace(**dict(zip(fields, values[:5], strict=True)), contact_angle=np.radians(a))
        for *values, a in draws
    ]


def _many_screws(figures: Figures, count: int) -> None:
    """``count`` random screws x 1000 points (a 10 x 10 x 10 grid each), complete model."""
    oil = lubricants.get("PAO ISO VG 68")
    screws = random_screws(count)
    w = np.linspace(1.0, 314.0, 10)[:, None, None]
    t = np.linspace(20.0, 45.0, 10)[None, :, None]
    fa = np.linspace(-4000.0, 4000.0, 10)[None, None, :]
    batch = getattr(ballscrew, "friction_torques", None)

    def run(group: list[Any]) -> None:
        if batch is not None:
            batch(group, oil, speed=w, temperature=t, axial_load=fa, components=False)
        else:  # release 0.1.0: one call per screw
            for screw in group:
                friction_torque(screw, oil, speed=w, temperature=t, axial_load=fa)

    run(random_screws(3, seed=99))  # warm-up, other screws
    cpu, wall = _timed(lambda: run(screws))
    figures["many_screws"] = count * 1000 / cpu
    print(
        f"{count} screws x 1000 points (friction_torques, complete, new screws): "
        f"{count * 1000 / cpu:.3e} pt/s ({count * 1000 / wall:.2e} wall)"
        + _against(figures, "many_screws", MANY_SCREWS_TARGET)
    )
    if batch is None:
        return
    # Issue 39: new screws of every size (diameters, leads, balls, preloads, 4-point nuts
    # among them) x 1000 speeds, benchmarks/bench_many_screws.py.
    from bench_many_screws import TARGET, measure

    m = measure(count, 1000)
    figures["many_new_screws"] = m["per_cpu_s"]
    figures["many_new_screws_wall"] = m["per_wall_s"]
    print(
        f"{count} new screws of every size x 1000 speeds (bench_many_screws.py): "
        f"{m['per_cpu_s']:.3e} pt per CPU-s ({m['cpu_s']:.2f} s CPU), {m['per_wall_s']:.2e} "
        f"per wall-s ({m['wall_s']:.2f} s)" + _against(figures, "many_new_screws", TARGET)
    )


TABLE_ROWS: tuple[tuple[str, str, str, str], ...] = (
    ("complete, grid [points/s]", "complete_grid", "3e6", "{:.3g}"),
    ("complete, scattered [points/s]", "complete_scattered", "1e6", "{:.3g}"),
    ("complete, one point [ms]", "complete_one_point_ms", "0.5", "{:.2f}"),
    ("complete, 1000 screws × 1000 points [points/s]", "many_screws", "5e5", "{:.3g}"),
    ("complete, 1000 new screws of every size × 1000 speeds [points/CPU-s]",
     "many_new_screws", "1e6", "{:.3g}"),
    ("olaru, scattered [points/s]", "olaru_scattered", "1e6", "{:.3g}"),
    ("harris-simplified, scattered [points/s]", "harris-simplified_scattered", "1e6", "{:.3g}"),
    ("catalog, one point [ms]", "catalog_one_point_ms", "0.2", "{:.3f}"),
    ("one-point `ballscrew torque`, whole process [s CPU]", "command_s", "0.5", "{:.2f}"),
    ("energy of a move with its temperature [s CPU per cycle]",
     "energy_10_cycles_per_cycle_s", "0.2", "{:.3f}"),
    ("1e7-point call, total only [MB peak]", "memory_total_mb", "400", "{:.0f}"),
)  # fmt: skip


def table(figures: Figures) -> str:
    """The performance table (Markdown) of ``figures`` against the targets and release 0.1.0."""
    lines = [
        f"Measured {figures['date']} on {figures['machine']} by "
        "`benchmarks/bench_models.py --readme` (one core, per CPU-second; "
        f"grid = {figures['grid']} points as an outer product, scattered = "
        f"{figures['points']:.0e} unrelated points; the helix's compiled loop loaded: "
        f"{figures['compiled_helix']}):",
        "",
        "Ratio: this version over 0.1.0 (above 1 is faster for a rate; below 1 is faster, or "
        "smaller, for a time or a memory).",
        "",
        "| figure | target | this version | 0.1.0 | ratio |",
        "|---|---|---|---|---|",
    ]
    for label, key, target, fmt in TABLE_ROWS:
        if key not in figures:
            continue
        value, base = figures[key], _BASE.get(key)
        ratio = f"×{value / base:.2f}" if base else ""
        old = fmt.format(base) if base else "–"
        lines.append(f"| {label} | {target} | {fmt.format(value)} | {old} | {ratio} |")
    lines += [
        "",
        "Every model (this version; in brackets the ratio to 0.1.0):",
        "",
        "| model | grid [points/s] | scattered [points/s] | one point [ms] |",
        "|---|---|---|---|",
    ]
    for name in sorted({k.rsplit("_grid", 1)[0] for k in figures if k.endswith("_grid")}):
        cells = []
        for key, fmt in (("grid", "{:.3g}"), ("scattered", "{:.3g}"), ("one_point_ms", "{:.2f}")):
            value, base = figures[f"{name}_{key}"], _BASE.get(f"{name}_{key}")
            cells.append(fmt.format(value) + (f" (×{value / base:.2f})" if base else ""))
        lines.append(f"| {name} | " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def write_table(path: Path, text: str) -> None:
    """Replace the block between ``<!-- perf-table:start -->`` and ``:end -->`` in ``path``."""
    start, end = "<!-- perf-table:start -->\n", "<!-- perf-table:end -->"
    content = path.read_text(encoding="utf-8")
    head, found, rest = content.partition(start)
    if not found or end not in rest:
        raise SystemExit(f"{path}: no perf-table markers")
    new = head + start + text + end + rest.split(end, 1)[1]
    tmp = path.with_suffix(path.suffix + ".tmp")
    tmp.write_text(new, encoding="utf-8")
    tmp.replace(path)  # atomic: a reader sees the old file or the new one


def main() -> None:
    # The grids leave some published ranges on purpose; time the models, not the warnings.
    warnings.simplefilter("ignore", BallScrewValidityWarning)
    warnings.simplefilter("ignore", BallScrewPlausibilityWarning)  # drawn screws, odd balls
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--speeds", type=int, default=100)
    parser.add_argument("--temperatures", type=int, default=10)
    parser.add_argument("--loads", type=int, default=100)
    parser.add_argument("--loop-points", type=int, default=200)
    parser.add_argument("--screws", type=int, default=1000, help="many-screw row (0: none)")
    parser.add_argument("--model", action="append", help="only these models")
    parser.add_argument(
        "--command-runs", type=int, default=3, help="runs of the one-point command (0: none)"
    )
    parser.add_argument(
        "--no-memory", action="store_true", help="skip the 1e7-point memory measurement"
    )
    parser.add_argument("--json", type=Path, help="write this run's figures to this file")
    parser.add_argument(
        "--baseline",
        type=Path,
        default=BASELINE,
        help="the figures to give ratios against ('none': no ratios)",
    )
    parser.add_argument(
        "--table-from", type=Path,
        help="write the README's and the guide's tables from a --json record, measure nothing",
    )  # fmt: skip
    parser.add_argument(
        "--readme", action="store_true",
        help="write the performance table of README.md and docs/guide.md from this run",
    )  # fmt: skip
    args = parser.parse_args()
    if str(args.baseline) not in ("", "none") and args.baseline.is_file():
        _BASE.update(json.loads(args.baseline.read_text(encoding="utf-8")))
    if args.table_from:
        _write_tables(json.loads(args.table_from.read_text(encoding="utf-8")))
        return

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
    # A long run: the helix's compiled loop loaded once, as a server or a sweep does (a
    # one-off call on fewer than JIT_LOAD_POINTS points would take numpy's path).
    load = getattr(getattr(ballscrew, "helix", None), "load_kernel", None)
    loaded = bool(load()) if load is not None else False
    figures: Figures = {
        "version": ballscrew.__version__,
        "date": datetime.date.today().isoformat(),
        "machine": f"{os.cpu_count()} cores, {platform.machine()}, Python "
        f"{platform.python_version()}",
        "numba": _has("numba"),
        "compiled_helix": loaded,
        "grid": f"{args.speeds} × {args.temperatures} × {args.loads}",
        "points": n,
    }
    print(
        f"ballscrew {figures['version']}; grid and scattered: {n} operating points each; one "
        f"point: mean of {args.loop_points} calls; one core; per CPU-second (per wall-second)"
    )
    header = (
        f"{'model':<18}{'grid [pt/s]':>22}{'target':>8}{'scattered [pt/s]':>22}{'target':>8}"
        f"{'one point [ms]':>18}{'target':>8}"
    )
    print(header)
    print("-" * len(header))
    for spec in models():
        if not args.model or spec.name in args.model:
            print(_model(figures, spec.name, points, sample))
    if args.screws > 0:
        _many_screws(figures, args.screws)
    if args.command_runs > 0:
        _commands(figures, args.command_runs)
    if not args.no_memory:
        _memory(figures)
    if args.json:
        args.json.write_text(json.dumps(figures, indent=1) + "\n", encoding="utf-8")
    if args.readme:
        _write_tables(figures)


def _write_tables(figures: Figures) -> None:
    """The performance tables of README.md and docs/guide.md, from ``figures``."""
    text = table(figures)
    for path in (HERE.parent / "README.md", HERE.parent / "docs" / "guide.md"):
        write_table(path, text)
    print(text)


def _has(module: str) -> bool:
    import importlib.util

    return importlib.util.find_spec(module) is not None


if __name__ == "__main__":
    main()
