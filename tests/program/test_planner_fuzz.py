"""The planner under random programs: every one is planned, or refused naming its line.

Issue 52's reproducer, a valid 7-line program whose last junction is at the feed cap to the
last digit, made ruckig raise (an internal error of ``ballscrew program``, an HTTP 500 on the
web page). Seeded random programs of lines, arcs, rapids and dwells, with feeds at the axes'
caps, short blocks and near-reversals, now all plan.
"""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.io.machine import load_machine
from ballscrew.program.axes import _limits
from ballscrew.program.gcode import read_program
from ballscrew.program.planner import plan
from shared import ROOT

MACHINE = load_machine(ROOT / "examples" / "machine_vmc.toml")

REPRODUCER = """G21 G90 G17
G0 X112.426 Y146.618 Z-50
G1 F2400
G1 X114.336 Y146.072
G1 X115.314 Y146.317
G1 X116.741 Y146.725
M30
"""


def _program(rng: np.random.Generator) -> str:
    x, y = round(float(rng.uniform(100, 700)), 3), round(float(rng.uniform(100, 400)), 3)
    lines = ["G21 G90 G17", f"G0 X{x:.3f} Y{y:.3f} Z-50"]
    for _ in range(int(rng.integers(2, 12))):
        kind = rng.choice(["G1", "G1", "G0", "G2", "G3", "G4"])
        # Feeds from slow to past every axis's cap (the planner caps them), often round.
        feed = float(rng.choice([2400, 6000, 30000, 60000, rng.uniform(10, 40000)]))
        step = float(rng.choice([0.01, 0.5, 2.0, 50.0])) * rng.uniform(0.2, 1.0)
        angle = rng.uniform(0, 2 * np.pi)
        nx = round(float(np.clip(x + step * np.cos(angle), 10, 790)), 4)
        ny = round(float(np.clip(y + step * np.sin(angle), 10, 490)), 4)
        if kind == "G4":
            lines.append(f"G4 P{rng.uniform(0, 0.2):.3f}")
            continue
        if kind in ("G2", "G3"):
            chord = np.hypot(nx - x, ny - y)
            if chord < 1e-3:
                continue
            radius = chord / 2 * rng.uniform(1.0001, 3.0)
            lines.append(f"{kind} X{nx:.4f} Y{ny:.4f} R{radius:.4f} F{feed:.1f}")
        else:
            lines.append(f"{kind} X{nx:.4f} Y{ny:.4f} F{feed:.1f}")
        x, y = nx, ny
    return "\n".join([*lines, "M30", ""])


def _plan(text: str) -> float:
    program = read_program(text, arc_tolerance=MACHINE.arc_tolerance, machine=MACHINE)
    return plan(program, _limits(MACHINE, program)).duration


def test_the_reproducer_plans() -> None:
    # The last junction at the 2400 mm/min cap: ruckig raised on it; now the block's exit is
    # lowered by 1e-7 of itself and the program takes its time (0.4 s at least: 146 mm of
    # rapid at 30 m/min and 5 mm at 40 mm/s).
    assert _plan(REPRODUCER) > 146.6e-3 / 0.5 + 5.0e-3 / 0.04 * 0.9


@pytest.mark.slow
def test_a_thousand_random_programs_plan_or_are_refused_by_line() -> None:
    rng = np.random.default_rng(20261205)
    refused = 0
    for _ in range(1000):
        text = _program(rng)
        try:
            assert _plan(text) > 0.0
        except BallScrewInputError as exc:  # a refusal names the program line
            assert exc.field.startswith("program line"), (exc, text)
            refused += 1
    assert refused < 50  # nearly every random program is a valid one
