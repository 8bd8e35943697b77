"""Throughput of the physical layers: vectorised calls against a point-by-point loop.

Run with ``.venv/bin/python benchmarks/bench_layers.py [--points N]``. Prints
operating points per second for each layer on one core, and the speed-up of
the vectorised call over calling the same function once per point in a
Python loop in the same process (the loop runs on a subset and is scaled).
"""

from __future__ import annotations

import argparse
import time
from collections.abc import Callable

import numpy as np

from ballscrew import lubricants, reference_screw
from ballscrew.contact import hertz
from ballscrew.state import operating_state


def _rate(func: Callable[[], object], points: int, repeat: int = 3) -> float:
    best = np.inf
    for _ in range(repeat):
        start = time.perf_counter()
        func()
        best = min(best, time.perf_counter() - start)
    return points / best


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--points", type=int, default=100_000, help="grid size (default 1e5)")
    parser.add_argument("--loop-points", type=int, default=500, help="points for the loop")
    args = parser.parse_args()
    n, n_loop = args.points, args.loop_points

    rng = np.random.default_rng(0)
    screw = reference_screw()
    oil = lubricants.get("PAO ISO VG 68")
    loads = rng.uniform(1.0, 200.0, n)
    speed = rng.uniform(1.0, 300.0, n)
    temperature = rng.uniform(20.0, 45.0, n)
    axial = rng.uniform(-3000.0, 3000.0, n)
    ep = screw.reduced_modulus

    cases: dict[str, tuple[Callable[[], object], Callable[[], object]]] = {}
    for method in ("exact", "houpert", "hamrock_brewe"):
        cases[f"hertz[{method}]"] = (
            lambda m=method: hertz(loads, screw.rx_screw, screw.ry_screw, ep, method=m),
            lambda m=method: [
                hertz(q, screw.rx_screw, screw.ry_screw, ep, method=m) for q in loads[:n_loop]
            ],
        )
    cases["operating_state"] = (
        lambda: operating_state(screw, oil, speed=speed, temperature=temperature, axial_load=axial),
        lambda: [
            operating_state(screw, oil, speed=w, temperature=t, axial_load=f)
            for w, t, f in zip(speed[:n_loop], temperature[:n_loop], axial[:n_loop], strict=True)
        ],
    )

    print(f"{'layer':<22}{'vectorised [pt/s]':>20}{'loop [pt/s]':>16}{'speed-up':>12}")
    for name, (vectorised, loop) in cases.items():
        fast = _rate(vectorised, n)
        slow = _rate(loop, n_loop, repeat=1)
        print(f"{name:<22}{fast:>20.3e}{slow:>16.3e}{fast / slow:>11.0f}x")


if __name__ == "__main__":
    main()
