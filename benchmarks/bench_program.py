"""Blocks per CPU-second of ``run_program`` on the example machine, at 1e3, 1e4 and 1e5 blocks.

    .venv/bin/python benchmarks/bench_program.py            # 1e3, 1e4, 1e5 blocks
    .venv/bin/python benchmarks/bench_program.py --max 1e4  # skip the largest

The program is scripts/make_example_program.py's pocket, contour and drilled holes
(655 blocks) repeated until it holds at least the number of blocks asked for (each
repetition at feeds 0.3 % apart, so that no sample repeats an earlier one's speed and load
and the friction model runs on every sample), run on
examples/machine_vmc.toml (3 axes, the complete model). The CPU time is the process's
(time.process_time) over reading, planning and the three axes, after one warm-up run;
the target is 10 000 blocks in under 10 s with the cost linear in the length.
"""

from __future__ import annotations

import argparse
import importlib.util
import math
import sys
import time
import warnings
from pathlib import Path

from ballscrew.io.machine import load_machine
from ballscrew.program import read_program, run_program

ROOT = Path(__file__).resolve().parents[1]


def _generator() -> object:
    spec = importlib.util.spec_from_file_location("gen", ROOT / "scripts/make_example_program.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--max", type=float, default=1e5, help="the largest program [blocks]")
    args = parser.parse_args()
    warnings.simplefilter("ignore")
    machine = load_machine(ROOT / "examples/machine_vmc.toml")
    gen = _generator()
    one = read_program(gen.program(1)).size  # type: ignore[attr-defined]
    run_program(machine, gen.program(1))  # type: ignore[attr-defined]  # warm-up
    print(f"{'blocks':>8} {'samples':>9} {'CPU [s]':>8} {'blocks/CPU-s':>13} {'program [s]':>12}")
    for target in (1e3, 1e4, 1e5):
        if target > args.max:
            break
        text = gen.program(math.ceil(target / one), vary=True)  # type: ignore[attr-defined]
        start = time.process_time()
        r = run_program(machine, text)
        cpu = time.process_time() - start
        n = r.program.size
        print(f"{n:>8} {r.motion.time.size:>9} {cpu:>8.2f} {n / cpu:>13.0f} "
              f"{r.motion.duration:>12.0f}")  # fmt: skip
        sys.stdout.flush()


if __name__ == "__main__":
    main()
