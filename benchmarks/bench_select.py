"""Throughput of ``ballscrew select``: candidates per CPU-second through the whole axis check.

Run with ``.venv/bin/python benchmarks/bench_select.py [--diameter "25..40 mm"]
[--lead "5..20 mm"] [--dwell "3 s"]``. Selects a screw for the example vertical axis
(``examples/vertical_32x5.toml``) over its move, with every catalogue nut of the
ranges at the light, medium and heavy preload, and prints the CPU time (process
time, one core), the candidates per CPU-second, the move's samples and the
largest and median CPU time of one candidate.

Each candidate runs ``run_energy`` and ``run_check`` on its own (about 1 s for
a 6000-sample move, most of it the check's Monte Carlo and the heat balance):
the arrays-in-every-layer rewrite of issue 39 item 4 is what would make many
screws cost what one grid costs.
"""

from __future__ import annotations

import argparse
import statistics
import time
from pathlib import Path

from ballscrew.axis.duty import profile_from_move
from ballscrew.axis.motion import parse_move
from ballscrew.io.case import load_case
from ballscrew.io.units import parse_range
from ballscrew.select import run_select

ROOT = Path(__file__).resolve().parents[1]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--diameter", default="25..40 mm")
    parser.add_argument("--lead", default="5..20 mm")
    parser.add_argument("--dwell", default="3 s")
    args = parser.parse_args()
    d = parse_range("--diameter", args.diameter, "m", default_points=2)
    lead = parse_range("--lead", args.lead, "m", default_points=2)
    m = parse_move("stroke=500 mm, feed=12 m/min, acceleration=3 m/s^2, force=1.5 kN, "
                   f"force_from=100 mm, force_to=400 mm, dwell={args.dwell}")  # fmt: skip
    profile = profile_from_move(m, 1)
    case = load_case(ROOT / "examples" / "vertical_32x5.toml")
    start = time.process_time()
    result = run_select(case, profile, diameter=(min(d), max(d)), lead=(min(lead), max(lead)),
                        objectives=["energy", "life", "stiffness"], move=m)  # fmt: skip
    cpu = time.process_time() - start
    n = len(result.evaluated)
    checked = [
        e.figures["seconds"]
        for e in result.evaluated
        if e.figures["energy_J"] == e.figures["energy_J"]
    ]
    print(f"{n} candidates ({len(checked)} checked, the rest stopped by an input error), "
          f"{len(profile.time)} samples per move")  # fmt: skip
    print(f"CPU time {cpu:.1f} s: {n / cpu:.2f} candidates per CPU-second")
    if checked:
        print(f"one checked candidate: median {statistics.median(checked):.2f} s, "
              f"largest {max(checked):.2f} s of CPU")  # fmt: skip
    print(f"front: {len(result.front)} of {len(result.feasible)} feasible; recommended: "
          f"{result.evaluated[result.recommended].name}")  # fmt: skip


if __name__ == "__main__":
    main()
