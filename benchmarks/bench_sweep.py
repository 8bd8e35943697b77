"""Sweep throughput in process and on 2 local workers, and the peak memory of a large sweep.

    .venv/bin/python benchmarks/bench_sweep.py                 # all three parts
    .venv/bin/python benchmarks/bench_sweep.py --large 1e9     # a larger memory test

1. Throughput: the complete model on a 40 x 10 mm screw over 2e7 points (20 preloads x
   200 speeds x 50 temperatures x 100 loads), in this process and on a local cluster of
   2 worker processes (cluster start-up excluded); the ratio of the two.
2. Grouping: points per second of a sweep that varies the screw (20 preloads) against
   one of as many points that varies only speed, temperature and load (one screw).
3. Memory: a sweep of ``--large`` points (default 2e8: its three outputs are 4.8 GB as
   float64, more than twice the 2 GB budget) on 2 workers; the peak resident memory of
   this process and of each worker (getrusage), against the size of the result.
"""

from __future__ import annotations

import argparse
import math
import resource
import shutil
import tempfile
import time
from pathlib import Path

from ballscrew.sweep.execute import run_sweep
from ballscrew.sweep.spec import parse_sweep

CASE = """
[case]
title = "40 x 10 mm double nut"
[case.screw]
designation = "40x10 double 2.5x2 6.35"
preload = "2 kN"
[case.lubricant]
name = "PAO ISO VG 68"
"""


def sweep(axes: str, models: str = '["complete"]', outputs: str = "") -> str:
    out = f"outputs = [{outputs}]\n" if outputs else ""
    return f"models = {models}\n{out}{CASE}\n[axes]\n{axes}\n"


def timed(text: str, folder: Path, name: str, **kwargs: object) -> tuple[float, object]:
    out = folder / name
    start = time.perf_counter()
    report = run_sweep(parse_sweep(text), out, **kwargs)  # type: ignore[arg-type]
    wall = time.perf_counter() - start
    shutil.rmtree(out)
    return wall, report


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--large", type=float, default=2e8, help="points of the memory test")
    parser.add_argument("--skip", default="", help="parts to skip, e.g. '1,2'")
    args = parser.parse_args()
    skip = set(args.skip.split(","))
    folder = Path(tempfile.mkdtemp(prefix="bench_sweep_"))
    try:
        if "1" not in skip:
            text = sweep('speed = "10..3000:200 rpm"\ntemperature = "20..60 degC:50"\n'
                         'axial_load = "0..5 kN:100"\n"screw.preload" = "1..3 kN:20"')  # fmt: skip
            points = 20 * 200 * 50 * 100
            print(f"1. throughput: complete model, {points:.0e} points")
            _, local = timed(text, folder, "in_process.zarr")
            rate_1 = local.points_per_second  # type: ignore[attr-defined]
            print(f"   in process:    {rate_1:.3g} points/s")
            wall, dist = timed(text, folder, "workers.zarr", workers=2)
            rate_2 = dist.points_per_second  # type: ignore[attr-defined]
            print(f"   2 workers:     {rate_2:.3g} points/s (wall {wall:.1f} s with start-up)")
            print(f"   ratio:         {rate_2 / rate_1:.2f} x the in-process rate")
        if "2" not in skip:
            print("2. grouping by screw: complete model, 2e6 points each, in process")
            one = sweep('speed = "10..3000:4000 rpm"\ntemperature = "20..60 degC:10"\n'
                        'axial_load = "0..5 kN:50"')  # fmt: skip
            many = sweep('speed = "10..3000:200 rpm"\ntemperature = "20..60 degC:10"\n'
                         'axial_load = "0..5 kN:50"\n"screw.preload" = "1..3 kN:20"')  # fmt: skip
            _, a = timed(one, folder, "one.zarr")
            _, b = timed(many, folder, "many.zarr")
            ra, rb = a.points_per_second, b.points_per_second  # type: ignore[attr-defined]
            print(f"   one screw:     {ra:.3g} points/s")
            print(f"   20 screws:     {rb:.3g} points/s ({rb / ra:.2f} x)")
        if "3" not in skip:
            n = int(args.large)
            speeds = max(1, round(n / (20 * 50 * 100)))
            text = sweep(
                f'speed = "10..3000:{speeds} rpm"\ntemperature = "20..60 degC:20"\n'
                'axial_load = "0..5 kN:50"\n"screw.preload" = "1..3 kN:100"',
                outputs='"torque", "efficiency", "power_loss"',
            )
            points = speeds * 20 * 50 * 100
            raw = points * 3 * 8
            print(f"3. memory: complete model, {points:.2e} points, result {raw / 1e9:.1f} GB "
                  "as float64, on 2 workers")  # fmt: skip
            out = folder / "large.zarr"
            start = time.perf_counter()
            report = run_sweep(parse_sweep(text), out, workers=2)
            wall = time.perf_counter() - start
            stored = sum(p.stat().st_size for p in out.rglob("*") if p.is_file())
            client = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
            print(
                f"   wall {wall:.0f} s, {report.points_per_second:.3g} points/s, "
                f"{report.plan.n_chunks} chunks, store {stored / 1e9:.2f} GB on disk"
            )
            print(
                f"   peak RSS: this process {client / 1e9:.2f} GB; workers "
                + ", ".join(f"{v / 1e9:.2f} GB" for v in report.peak_rss.values())
            )
            worst = max(client, *report.peak_rss.values())
            print(
                f"   largest peak {worst / 1e9:.2f} GB = {raw / worst:.1f} x smaller than the "
                "result; " + ("under" if worst < 2e9 else "OVER") + " the 2 GB budget"
            )
            assert math.isfinite(report.points_per_second)
    finally:
        shutil.rmtree(folder, ignore_errors=True)


if __name__ == "__main__":
    main()
