"""The axis check's table of criteria: one function per drawn row, every reader by key."""

from __future__ import annotations

import math
from dataclasses import replace
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest

from ballscrew.axis import check as check_module
from ballscrew.axis.check import AxisCheck, criterion_inputs, run_check
from ballscrew.axis.criteria import CRITERIA, KEYS, Inputs, Sample, life_utilisation, ones
from ballscrew.axis.duty import EnergyRun, profile_from_move, run_energy
from ballscrew.design.sizing import STEEL_EXPANSION
from ballscrew.io.case import parse_case
from ballscrew.loads import LIFT_OFF_RATIO
from ballscrew.report.program import verdict_lines
from ballscrew.select.choose import _figures
from ballscrew.web.service import _criterion
from shared import AXIS_CASE

MOVE = {"stroke": 0.4, "feed": 0.5, "acceleration": 2.0, "force": 2000.0}
MOTOR = ('[motor]\nrated_torque = "4 N*m"\npeak_torque = "12 N*m"\nrated_speed = "3000 rpm"\n'
         '[check]\naccuracy_grade = "p3"\npretension_temperature = "1 K"\n'
         'mass_tolerance = "10 %"\nforce_tolerance = "10 %"\n'
         'rating_tolerance = "10 %"\n')  # fmt: skip
AXIS = ('motor_inertia = "2e-4 kg*m**2"\nscrew_inertia = "8e-4 kg*m**2"\n'
        'coupling_inertia = "1e-4 kg*m**2"\ngear_ratio = 2')  # fmt: skip


def _run(nut: str = "double", preload: str = "1 kN", motor: bool = True) -> EnergyRun:
    text = AXIS_CASE.format(nut=nut, preload=preload, support="fixed-fixed",
                            axis_extra=AXIS if motor else "",
                            sections=MOTOR if motor else "")  # fmt: skip
    return run_energy(parse_case(text), profile_from_move(MOVE, 1), ["catalog"],
                      run_time=600.0, move=MOVE)  # fmt: skip


@pytest.fixture(scope="module")
def full() -> tuple[EnergyRun, AxisCheck]:
    """A preloaded nut behind a gear, with a motor, a grade and tolerances: every drawn row."""
    run = _run()
    return run, run_check(run, "catalog")


def _factors(**given: float) -> Any:
    """One draw: the factors named, the others 1."""
    return replace(ones(), **{k: np.array([v]) for k, v in given.items()})


def _value(inputs: Any, key: str, **given: float) -> float:
    return float(CRITERIA[key].value(Sample(inputs, _factors(**given)))[0])


@pytest.mark.parametrize("case", ["full", "single nut, no motor"])
def test_a_draw_of_ones_reproduces_every_row(case: str, full: tuple[EnergyRun, AxisCheck]) -> None:
    # The Monte Carlo's path (blocks of draws, the utilisation from the rule's side of the
    # limit) at draws of ones against the rows run_check printed: 1e-12, the rounding of a
    # ratio taken once as floats and once as arrays.
    run, result = full if case == "full" else (lambda r: (r, run_check(r)))(
        _run(nut="single", preload="0 N", motor=False))  # fmt: skip
    inputs = criterion_inputs(run)
    samples = check_module._row_samples(inputs, result.criteria, ones(5))
    drawn = {c.key for c in result.criteria if c.utilisation is not None and c.key in CRITERIA}
    assert set(samples) == drawn
    if case == "full":
        assert drawn == set(CRITERIA)  # every drawn criterion is in this case
    for c in result.criteria:
        if c.key in samples:
            np.testing.assert_allclose(samples[c.key], c.utilisation, rtol=1e-12, err_msg=c.key)
            np.testing.assert_allclose(_value(inputs, c.key), c.value, rtol=1e-12)


def test_the_drawn_functions_scale_as_their_formulas(full: tuple[EnergyRun, AxisCheck]) -> None:
    run, result = full
    x = criterion_inputs(run)
    # The load inertia behind a gear of 2: (J_s + J_c + k m (l/2 pi)^2) / i^2 over the rotor's,
    # 200 kg on a 10 mm lead, the mass 1.5 times.
    j = (8e-4 + 1e-4 + 1.5 * 200.0 * (0.01 / (2.0 * math.pi)) ** 2) / 2.0**2
    assert _value(x, "inertia_ratio", mass=1.5) == pytest.approx(j / 2e-4, rel=1e-12)
    # Without the mass's part the peak axial force is the process force's, twice over.
    assert _value(x, "buckling", mass=0.0, force=2.0) == pytest.approx(4.0, rel=1e-12)
    assert _value(x, "lift_off", mass=0.0) == pytest.approx(2000.0, rel=1e-12)
    # Lift-off's limit scales with the preload: half the preload, twice the utilisation.
    row = result.row("lift_off")
    assert row is not None and row.limit == pytest.approx(LIFT_OFF_RATIO * 1000.0)
    u = check_module.drawn("lift_off", Sample(x, _factors(preload=0.5)), row.limit)
    assert u[0] == pytest.approx(2.0 * float(row.utilisation or 0.0), rel=1e-12)
    # A life goes as the rating cubed; a static safety as the rating.
    assert _value(x, "life", ratings=2.0) == pytest.approx(8.0 * _value(x, "life"), rel=1e-12)
    fs = _value(x, "static_safety")
    assert _value(x, "static_safety", ratings=1.3) == pytest.approx(1.3 * fs, rel=1e-12)
    # The heat is the friction's: twice the friction, twice the rise, less the pre-tension.
    rise = result.thermal["temperature_rise_K"]
    error = STEEL_EXPANSION * (2.0 * rise - 1.0) * 0.3 * 1e6
    assert _value(x, "thermal_error", friction=2.0) == pytest.approx(error, rel=1e-12)
    # Torques: the mass's part of the motor torque is m a l / (2 pi i) (with the screw's
    # and rotor's inertia in the rest); without the process force and the mass, the peak
    # falls by at least the process force's torque, F l / (2 pi i) / efficiency >= F l / 2 pi i.
    # The rows are the cycle's own torques (ballscrew.axis.energy's, every sample).
    cycle = run.results["catalog"].cycle
    assert result.row("peak_torque").value == cycle.peak_motor_torque  # type: ignore[union-attr]
    assert result.row("rms_torque").value == cycle.rms_motor_torque  # type: ignore[union-attr]
    peak = _value(x, "peak_torque")
    bare = _value(x, "peak_torque", force=0.0)
    assert peak - bare >= 2000.0 * 0.01 / (2.0 * math.pi * 2.0) * (1.0 - 1e-9)


def test_every_reader_finds_rows_by_key(full: tuple[EnergyRun, AxisCheck]) -> None:
    run, result = full
    doc = result.as_dict()["criteria"]
    keys = [row["key"] for row in doc]
    assert len(keys) == len(set(keys)) and set(keys) <= set(KEYS)
    for c in result.criteria:
        assert c.name.startswith(KEYS[c.key]), c.key  # the table names each row's label
        assert result.row(c.key) is c
    assert result.row("travel") is None
    # Every label changed: the readers find the same rows.
    renamed = replace(result, criteria=[replace(c, name=f"row {i}")
                                        for i, c in enumerate(result.criteria)])  # fmt: skip
    before, after = _figures(result, run, "catalog", 0.0), _figures(renamed, run, "catalog", 0.0)
    for name in ("motor_margin", "stiffness_N_per_um", "lost_motion_um"):
        assert not math.isnan(before[name]) and after[name] == before[name], name
    axis = SimpleNamespace(check=renamed, verdicts=renamed.criteria, verdict=renamed.verdict,
                           notes=[])  # fmt: skip
    line = verdict_lines(SimpleNamespace(axes={"X": axis}))[0]  # type: ignore[arg-type]
    shown = ["lift-off ", "d*n ", "RMS torque ", "peak torque ", "motor speed ",
             "thermal lead error per 300 mm "]  # fmt: skip
    at = [line.find("; " + label) if i else line.find(": " + label) for i, label in
          enumerate(shown)]  # fmt: skip
    assert all(a >= 0 for a in at) and at == sorted(at), line
    web = [_criterion(row, "si") for row in renamed.as_dict()["criteria"]]
    assert [row["key"] for row in web] == keys


def _inputs(**given: Any) -> Inputs:
    """A two-sample cycle by hand: 1 s at each sample, no load, a 10 mm lead, no gear."""
    zero = np.zeros(2)
    base: dict[str, Any] = dict(
        mass_force=zero, process_force=zero, turns=np.ones(2), motor_torque=zero,
        torque_mass_force=zero, torque_process_force=zero, motor_friction=zero,
        weights=np.ones(2), duration=2.0, rms_torque=0.0, lead=0.01, gear_ratio=1.0,
        preload=0.0, preloaded=False, dynamic_rating=None, static_rating=None,
        load_factor=1.0, reliability=0.9, temperature_rise=0.0, pretension=0.0,
        moving_mass=0.0, screw_inertia=0.0, coupling_inertia=0.0, motor_inertia=1e-4,
    )  # fmt: skip
    return Inputs(**(base | given))


def test_the_motor_torques_of_a_cycle_by_hand() -> None:
    # Motor torques 3 and 1 N*m for 1 s each: RMS sqrt((9 + 1) / 2) = sqrt(5), peak 3.
    x = _inputs(motor_torque=np.array([3.0, 1.0]), rms_torque=math.sqrt(5.0),
                torque_mass_force=np.array([100.0, 0.0]),
                motor_friction=np.array([0.5, 0.5]), gear_ratio=2.0)  # fmt: skip
    assert _value(x, "rms_torque") == math.sqrt(5.0)
    assert _value(x, "peak_torque") == 3.0
    # Twice the mass: its 100 N more at the nut is 100 * 0.01 / (2 pi * 2) N*m more at
    # the motor; twice the friction, 0.5 N*m more at both samples.
    more = 100.0 * 0.01 / (4.0 * math.pi)
    assert _value(x, "peak_torque", mass=2.0) == pytest.approx(3.0 + more, rel=1e-12)
    rms = math.sqrt(((3.5 + more) ** 2 + 1.5**2) / 2.0)
    assert _value(x, "rms_torque", mass=2.0, friction=2.0) == pytest.approx(rms, rel=1e-12)
    # A cycle without motor torque: the draw's torque alone, 100 N of process force.
    y = _inputs(torque_process_force=np.array([0.0, 100.0]))
    half = 0.5 * 100.0 * 0.01 / (2.0 * math.pi)  # kf - 1 = 0.5 on one sample of two
    assert _value(y, "rms_torque", force=1.5) == pytest.approx(half / math.sqrt(2.0), rel=1e-12)


def test_the_load_rows_of_a_cycle_by_hand() -> None:
    # 1 kN and -3 kN on a single nut of C_0a 12 kN: static safety 12 / 3 = 4; a preloaded
    # nut of 1 kN: the loaded half at 3 kN (past lift-off at 2.83 kN) carries the 3 kN.
    x = _inputs(mass_force=np.array([1000.0, -3000.0]), static_rating=12_000.0)
    assert _value(x, "static_safety") == pytest.approx(4.0, rel=1e-12)
    assert _value(x, "buckling") == pytest.approx(3.0, rel=1e-12)
    pre = replace(x, preload=1000.0, preloaded=True)
    assert _value(pre, "static_safety") == pytest.approx(4.0, rel=1e-12)
    below = replace(pre, mass_force=np.array([1000.0, -2000.0]))
    loaded = 1000.0 * (1.0 + 2000.0 / (LIFT_OFF_RATIO * 1000.0)) ** 1.5
    assert _value(below, "static_safety") == pytest.approx(12_000.0 / loaded, rel=1e-12)
    # Utilisation: at most, value over limit; at least, limit over value, a zero value fails.
    safety, buckling = CRITERIA["static_safety"], CRITERIA["buckling"]
    np.testing.assert_allclose(safety.utilisation(np.array([0.5, 4.0]), 2.0), [4.0, 0.5])
    assert safety.utilisation(np.array([0.0]), 2.0)[0] == math.inf
    np.testing.assert_allclose(buckling.utilisation(np.array([0.5, 4.0]), 2.0), [0.25, 2.0])


def test_the_life_of_a_constant_load_by_hand() -> None:
    # A single nut under 2 kN on one flank, C_a 20 kN, f_w 1: (20/2)^3 1e6 = 1e9 turns
    # (ISO 3408-5 with a1 = 1 at the default 90 %; the other flank unloaded lasts for
    # ever), at 600 rpm 1e9 / 36000 h; 20 000 h asked is 0.72 of it.
    force = np.full((1, 2), 2000.0)
    hours = 1e9 / (60.0 * 600.0)
    u = life_utilisation(force, np.zeros(1), np.array([20_000.0]), np.ones(2), 20_000.0,
                         600.0, preloaded=False, load_factor=1.0)  # fmt: skip
    assert u[0] == pytest.approx(20_000.0 / hours, rel=1e-12)
