"""A program's work is bounded before it is done (issue 52).

``sample_time = "1 ns"`` asked for 60 GiB of samples and ``G4 P100000000000`` (3000 years of
dwell) for a 5.3 GiB heat-balance grid; both ended in MemoryError. The samples are now
estimated before any is made and refused past a limit, and the heat balance's steps are
bounded while staying exact for a constant power.
"""

from __future__ import annotations

import dataclasses
import math

import numpy as np
import pytest

from ballscrew.axis.thermal import MAX_STEPS, heat_balance
from ballscrew.errors import BallScrewInputError
from ballscrew.io.machine import load_machine
from ballscrew.program import run_program
from ballscrew.program.planner import MAX_SAMPLES
from shared import ROOT

MACHINE = load_machine(ROOT / "examples" / "machine_vmc.toml")


def test_a_sample_time_that_would_take_billions_of_samples_is_refused_with_its_estimate() -> None:
    machine = dataclasses.replace(MACHINE, sample_time=1e-9)
    # 100 mm at 3 m/min: the cruise is one polynomial (one sample), the speed changes are
    # sampled; they take over 0.1 s, so over 1e8 samples at 1 ns.
    with pytest.raises(BallScrewInputError) as info:
        run_program(machine, "G21 G90\nG1 X100 F3000\nM30\n")
    said = str(info.value)
    assert info.value.field == "program" and "samples" in said and "machine.sample_time" in said
    estimate = float(said.split("about ")[1].split(" samples")[0])
    assert estimate >= 1e8 > MAX_SAMPLES


def test_a_dwell_of_millennia_is_bounded_and_exact() -> None:
    # Constant 10 W into 1000 J/K through 1 W/K over 1e11 s: the steady state T_a + P/G.
    t = np.array([0.0, 1e11])
    temp = heat_balance(t, np.array([10.0, 10.0]), 1000.0, 1.0, 20.0, 20.0)
    assert temp[-1] == pytest.approx(30.0, rel=1e-12)
    # One time constant exactly, however long the grid's steps: 20 + 10 (1 - 1/e).
    t = np.linspace(0.0, 1000.0, 3)
    temp = heat_balance(t, np.full(3, 10.0), 1000.0, 1.0, 20.0, 20.0)
    assert temp[-1] == pytest.approx(20.0 + 10.0 * (1.0 - math.exp(-1.0)), rel=1e-12)
    assert MAX_STEPS <= 1_000_000  # 8 MB an array of the grid


def test_the_millennium_dwell_program_runs() -> None:
    result = run_program(MACHINE, "G21 G90\nG1 X100 F3000\nG4 P100000000000\nG1 X0\nM30\n")
    assert result.motion.duration > 1e11
    assert any("dwell" in n for n in result.notes)  # a dwell over 60 s is told with its reading
