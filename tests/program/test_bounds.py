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
    # Refused by the bound before planning ("at least") or by the plan's count ("about").
    estimate = float(said.split("at least " if "at least" in said else "about ")[1]
                     .split(" samples")[0])  # fmt: skip
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


def test_the_bound_before_planning_is_the_closed_form_of_a_move_from_rest() -> None:
    # 700 mm from rest to rest on X at a jerk of 1e-9 m/s^3 (acceleration and feed never
    # reached): the bound takes the peak speed over the whole length, j s^2 with
    # s = (L/j)^(1/3), so L over it is (L/j)^(1/3) = 887.9 s; the planned move, a pure-jerk
    # profile, takes (32 L/j)^(1/3) = 2819 s, 32^(1/3) times the bound.
    from ballscrew.program.axes import _limits
    from ballscrew.program.gcode import read_program
    from ballscrew.program.planner import least_samples, plan

    machine = dataclasses.replace(
        MACHINE, axes={**MACHINE.axes, "X": dataclasses.replace(MACHINE.axes["X"], max_jerk=1e-9)}
    )
    program = read_program("G21 G90\nG1 X700 F3000\nM30\n", machine=machine)
    limits = _limits(machine, program)
    seconds, samples = least_samples(program, limits)
    assert seconds == pytest.approx((0.7 / 1e-9) ** (1 / 3), rel=1e-9)
    assert samples == int(seconds / 5e-3) + 1  # every 5 ms, and the block's end
    motion = plan(program, limits)
    assert motion.duration == pytest.approx((32 * 0.7 / 1e-9) ** (1 / 3), rel=1e-6)
    assert motion.time.size >= samples


def test_the_bound_before_planning_never_exceeds_the_plan() -> None:
    # Seeded random programs (lines, arcs, rapids, dwells, feeds past the caps): the bound
    # of time and of samples is at most what the plan gives, so a refusal by the bound is
    # never one the plan would not make.
    from test_planner_fuzz import _program

    from ballscrew.program.axes import _limits
    from ballscrew.program.gcode import read_program
    from ballscrew.program.planner import least_samples, plan

    rng = np.random.default_rng(52)
    for _ in range(60):
        text = _program(rng)
        try:
            program = read_program(text, arc_tolerance=MACHINE.arc_tolerance, machine=MACHINE)
        except BallScrewInputError:
            continue
        limits = _limits(MACHINE, program)
        seconds, samples = least_samples(program, limits)
        motion = plan(program, limits)
        assert seconds <= motion.duration * (1 + 1e-9) + 1e-12, text
        assert samples <= motion.time.size, text


def test_a_program_far_past_the_bound_is_refused_before_ruckig_runs(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # A jerk of 1e-14 m/s^3 on X: at least (L/j)^(1/3) = 41 212 s of 5 ms samples, 8.24
    # million, past the command line's 3 million; refused before a block is planned.
    import ruckig

    machine = dataclasses.replace(
        MACHINE, axes={**MACHINE.axes, "X": dataclasses.replace(MACHINE.axes["X"], max_jerk=1e-14)}
    )
    monkeypatch.setattr(ruckig, "Ruckig", None)  # planning a block would fail
    from ballscrew.program.axes import _limits
    from ballscrew.program.gcode import read_program
    from ballscrew.program.planner import plan

    program = read_program("G21 G90\nG1 X700 F3000\nM30\n", machine=machine)
    with pytest.raises(BallScrewInputError) as info:
        plan(program, _limits(machine, program))
    said = str(info.value)
    assert "at least 8.24e+06 samples" in said and f"at most {MAX_SAMPLES:.3g} samples" in said
    assert "estimated before planning" in said
