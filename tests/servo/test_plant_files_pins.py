"""Pins of the controller files, the plant and its simulation from their mutation runs (issue 49).

``servo.tables``: tables fitted to friction maps written by hand. A friction that is
linear in the speed on each side is a piecewise-linear curve, so every table fits it
exactly whatever its breakpoints; a curved friction is checked against a least-squares
fit computed here with hat functions of its own (``numpy.interp`` of unit vectors), and
with one free breakpoint against a scan of that breakpoint. The grid the error is measured
on is the one the module's docstring states: 801 speeds each way, from 1/801 of the range.
"""

from __future__ import annotations

import dataclasses
import math
import warnings
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest

from ballscrew.axis.setup import axis_setup
from ballscrew.chain import friction_torque
from ballscrew.design.limits import root_diameter
from ballscrew.design.stiffness import (
    design_nut_stiffness,
    shaft_axial_stiffness,
    torsional_axial_stiffness,
)
from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import Case, load_case, parse_case
from ballscrew.io.measured import MeasuredCurve
from ballscrew.servo.cascade import Gains
from ballscrew.servo.export import axis_inertia, export_friction, log_speeds, run_export_friction
from ballscrew.servo.plant import PRE_ROLLING_RANGE, AxisDynamics, axis_dynamics, frictionless
from ballscrew.servo.simulate import _interp, simulate_axis, substeps
from ballscrew.servo.tables import (
    CompensationTable,
    ControllerTable,
    DriveUnit,
    controller_table,
    fit_table,
    relative_error,
    target_curve,
)
from shared import ROOT

# --------------------------------------------------------------------------- servo.tables

VMAX = 0.1  # m/s, the tables' range
GRID = np.linspace(VMAX / 801, VMAX, 801)  # the docstring's grid, one direction
STEP = GRID[1] - GRID[0]
S = np.geomspace(1e-4, 0.2, 30)  # the map's positive speeds [m/s], beyond the range
MAP_V = np.concatenate([-S[::-1], S])


def _linear(v: np.ndarray) -> np.ndarray:
    """Coulomb plus viscous, not the same both ways: 50 N + 400 N*s/m up, 60 N + 300 down."""
    return np.where(v > 0, 50.0 + 400.0 * v, -(60.0 + 300.0 * np.abs(v)))


def _curved(v: np.ndarray) -> np.ndarray:
    """A Stribeck curve, the same both ways: 30 N + 20 N e^(-|v|/5 mm/s) + 300 N*s/m |v|."""
    return np.sign(v) * (30.0 + 20.0 * np.exp(-np.abs(v) / 0.005) + 300.0 * np.abs(v))


def _map_target(f, v: np.ndarray) -> np.ndarray:  # type: ignore[no-untyped-def]
    """The map of ``f`` at S interpolated linearly, each direction on its own."""
    up = np.interp(np.abs(v), S, np.abs(f(S)))
    down = np.interp(np.abs(v), S, np.abs(f(-S)))
    return np.where(v > 0, up, -down)


def _hats(knots: np.ndarray, v: np.ndarray) -> np.ndarray:
    """Hat functions on ``knots`` at ``v``: column j interpolates the j-th unit vector."""
    return np.stack([np.interp(v, knots, e) for e in np.eye(knots.size)], axis=1)


def test_target_curve_by_hand() -> None:
    # Up: 1 N at 1 m/s, 2 N at 2 m/s; down: 3 N at -1 m/s, 4 N at -2 m/s. Each side is held
    # at its slowest value towards 0 and at its fastest beyond; 0 at rest.
    got = target_curve(np.array([-2.0, -1.0, 1.0, 2.0]), np.array([-4.0, -3.0, 1.0, 2.0]),
                       np.array([-3.0, -1.5, -0.5, 0.0, 0.5, 1.5, 3.0]))  # fmt: skip
    assert got.tolist() == [-4.0, -3.5, -3.0, 0.0, 1.0, 1.5, 2.0]
    # A point at rest belongs to neither direction: each is still held at its slowest speed.
    got = target_curve(np.array([-2.0, -1.0, 0.0, 1.0, 2.0]),
                       np.array([-4.0, -3.0, 0.0, 1.0, 2.0]), np.array([-0.5, 0.5]))  # fmt: skip
    assert got.tolist() == [-3.0, 1.0]


@pytest.mark.parametrize(("points", "kind"), [(16, "two-sided"), (20, "one-sided"),
                                              (11, "zero point")])  # fmt: skip
def test_a_linear_friction_is_fitted_exactly(points: int, kind: str) -> None:
    # Linear on each side: any table with breakpoints at the grid's ends reproduces it, so
    # the values are the formula at the breakpoints and the error is rounding (1e-9 N of
    # 50 N; the residuals are 1e-13 N).
    t = fit_table(MAP_V, _linear(MAP_V), points, VMAX, one_sided=kind == "one-sided",
                  zero_point=kind == "zero point")  # fmt: skip
    assert t.speed.size == points and t.speed_range == VMAX
    assert t.one_sided is (kind == "one-sided")
    positive = t.speed[t.speed > 0]
    assert positive[0] == pytest.approx(VMAX / 801, rel=1e-12)
    assert positive[-1] == pytest.approx(VMAX, rel=1e-12)
    # Breakpoints at least one grid step apart (every value is seen by the grid).
    assert np.all(np.diff(positive) >= STEP * (1 - 1e-9))
    assert t.rms_error < 1e-9 and t.max_error < 1e-9
    if kind == "one-sided":
        # The mean of both magnitudes, 55 N + 350 N*s/m v; at speed 0 the slowest speed's.
        assert t.speed[0] == 0.0 and positive.size == points - 1
        assert t.force[1:] == pytest.approx(55.0 + 350.0 * positive, rel=1e-9)
        assert t.force[0] == pytest.approx(55.0 + 350.0 * VMAX / 801, rel=1e-9)
        assert t(np.array([-0.05, 0.05])) == pytest.approx([-72.5, 72.5], rel=1e-9)
        return
    assert t.speed[t.speed < 0] == pytest.approx(-positive[::-1], rel=1e-12)
    moving = t.speed != 0.0
    assert t.force[moving] == pytest.approx(_linear(t.speed[moving]), rel=1e-9)
    assert t(np.array([-0.05, 0.05])) == pytest.approx([-75.0, 70.0], rel=1e-9)
    if kind == "zero point":
        assert positive.size == (points - 1) // 2 and t.speed[points // 2] == 0.0
        assert t.force[points // 2] == 0.0
    else:
        assert positive.size == points // 2 and 0.0 not in t.speed


@pytest.mark.parametrize(("points", "kind"), [(8, "two-sided"), (6, "one-sided"),
                                              (9, "zero point")])  # fmt: skip
def test_a_curved_friction_gets_the_least_squares_values_at_its_breakpoints(
    points: int, kind: str
) -> None:
    # At the table's own breakpoints, the values are the least-squares fit of the hat
    # functions to the map on the grid (solved here), and the errors that fit's residual.
    # 1e-9 N: two solutions of the same well-conditioned least-squares problem.
    one = kind == "one-sided"
    t = fit_table(MAP_V, _curved(MAP_V), points, VMAX, one_sided=one,
                  zero_point=kind == "zero point")  # fmt: skip
    v = GRID if one else np.concatenate([-GRID[::-1], GRID])
    target = _map_target(_curved, v)
    if one:
        target = 0.5 * (_map_target(_curved, GRID) - _map_target(_curved, -GRID))
    basis = _hats(t.speed, v)
    free = np.ones(t.speed.size, dtype=bool)
    if kind == "zero point":
        free[points // 2] = False
    y = np.zeros(t.speed.size)
    y[free] = np.linalg.lstsq(basis[:, free], target, rcond=None)[0]
    if one:
        # The point at rest carries the slowest speed's friction (breakaway), not its fit.
        y[0] = target[0]
        assert y[0] == pytest.approx(30.0 + 20.0 * math.exp(-VMAX / 801 / 0.005)
                                     + 300.0 * VMAX / 801, rel=1e-3)  # fmt: skip
    assert t.force == pytest.approx(y, abs=1e-9)
    resid = basis @ y - target
    assert t.rms_error == pytest.approx(float(np.sqrt(np.mean(resid**2))), rel=1e-9)
    assert t.max_error == pytest.approx(float(np.max(np.abs(resid))), rel=1e-9)
    assert relative_error(t) == pytest.approx(t.rms_error / np.max(np.abs(y)), rel=1e-9)


@pytest.mark.parametrize(("points", "kind"), [(6, "two-sided"), (4, "one-sided"),
                                              (7, "zero point")])  # fmt: skip
def test_one_free_breakpoint_is_placed_where_a_scan_finds_the_least_error(
    points: int, kind: str
) -> None:
    # Three breakpoints a side: the slowest grid speed, the range's end and one free one.
    # Scanning the free one over 400 places (own least squares at each) bounds the least
    # RMS error from above; the optimiser's table must reach that bound (1e-9 relative).
    one = kind == "one-sided"
    zero = kind == "zero point"
    t = fit_table(MAP_V, _curved(MAP_V), points, VMAX, one_sided=one, zero_point=zero)
    v = GRID if one else np.concatenate([-GRID[::-1], GRID])
    target = _map_target(_curved, v)

    def rms(p1: float) -> float:
        p = np.array([GRID[0], p1, VMAX])
        knots = (np.concatenate([[0.0], p]) if one else
                 np.concatenate([-p[::-1], [0.0] if zero else [], p]))  # fmt: skip
        basis = _hats(knots, v)
        if zero:
            basis = np.delete(basis, 3, axis=1)
        y = np.linalg.lstsq(basis, target, rcond=None)[0]
        return float(np.sqrt(np.mean((basis @ y - target) ** 2)))

    best = min(rms(p1) for p1 in np.linspace(GRID[0] + STEP, VMAX - STEP, 400))
    positive = t.speed[t.speed > 0]
    assert positive.size == 3
    assert rms(float(positive[1])) <= best * (1 + 1e-9)


def _kinked(kinks: list[float], slopes: list[float]):  # type: ignore[no-untyped-def]
    """A friction of 50 N at the grid's slowest speed, linear between ``kinks`` [m/s]."""

    def magnitude(v: np.ndarray) -> np.ndarray:
        out = 50.0 + slopes[0] * (v - GRID[0])
        for k, a, b in zip(kinks, slopes[:-1], slopes[1:], strict=True):
            out = out + (b - a) * np.clip(v - k, 0.0, None)
        return out

    return lambda v: np.sign(v) * magnitude(np.abs(v))


@pytest.mark.parametrize(
    ("kinks", "slopes", "points", "one"),
    [
        ([GRID[0] + 2 * STEP], [-1e4, 300.0], 4, True),
        ([GRID[0] + 2 * STEP], [-1e4, 300.0], 6, False),
        ([0.003, 0.01, 0.04], [-2000.0, -500.0, 300.0, 100.0], 10, False),
    ],
)
def test_a_friction_with_as_many_kinks_as_free_breakpoints_is_fitted_exactly(
    kinks: list[float], slopes: list[float], points: int, one: bool
) -> None:
    # A piecewise-linear friction whose kinks can all be breakpoints is fitted with no
    # error there, and only there: the optimiser must find them. The first kink lies two
    # grid steps from the slowest speed (breakpoints may be one step apart); the others
    # need three breakpoints placed together. 1e-6 N of kinks worth tens of N (the
    # optimiser stops within 1e-4 of each spacing's logarithm: 1e-9 N is reached).
    f = _kinked(kinks, slopes)
    speeds = np.unique(np.concatenate([S, kinks]))
    speeds = np.concatenate([-speeds[::-1], speeds])
    t = fit_table(speeds, f(speeds), points, VMAX, one_sided=one)
    assert t.rms_error < 1e-6
    positive = t.speed[t.speed > 0]
    assert positive[1 : 1 + len(kinks)] == pytest.approx(kinks, rel=1e-5)


def test_table_sizes_and_range_are_checked() -> None:
    f = _linear(MAP_V)
    for bad in (0.0, -0.1, math.nan):
        with pytest.raises(BallScrewInputError, match="speed range"):
            fit_table(MAP_V, f, 16, bad)
    # Two points a side at least: 4 (even) two-sided, 5 (odd) with a zero point, 3 one-sided.
    for points, kw in ((3, {}), (5, {}), (4, {"zero_point": True}),
                       (2, {"one_sided": True})):  # fmt: skip
        with pytest.raises(BallScrewInputError, match="points"):
            fit_table(MAP_V, f, points, VMAX, **kw)  # type: ignore[arg-type]
    # An even count with a zero point was fitted with one point fewer than asked.
    with pytest.raises(BallScrewInputError, match="an odd count with one"):
        fit_table(MAP_V, f, 10, VMAX, zero_point=True)
    assert fit_table(MAP_V, f, 4, VMAX).speed.size == 4
    assert fit_table(MAP_V, f, 5, VMAX, zero_point=True).speed.size == 5
    assert fit_table(MAP_V, f, 3, VMAX, one_sided=True).speed.size == 3


def test_a_hand_table_interpolates_and_clamps() -> None:
    table = CompensationTable(np.array([-1.0, 1.0, 3.0]), np.array([-8.0, 2.0, 4.0]), 2.0, 3.0,
                              3.0)  # fmt: skip
    assert table(np.array([-2.0, 0.0, 2.0, 5.0])).tolist() == [-8.0, -3.0, 3.0, 4.0]
    assert relative_error(table) == 0.25  # 2 N over the largest |force|, 8 N
    one = CompensationTable(np.array([0.0, 1.0, 3.0]), np.array([5.0, 6.0, 8.0]), 0.0, 0.0,
                            3.0, one_sided=True)  # fmt: skip
    assert one(np.array([-2.0, 0.5, 4.0])).tolist() == [-7.0, 5.5, 8.0]
    d = table.as_dict()
    assert d["speed_m_s"] == [-1.0, 1.0, 3.0] and d["rms_error_N"] == 2.0
    assert d["max_error_N"] == 3.0 and d["speed_range_m_s"] == 3.0 and d["one_sided"] is False


def test_drive_units_as_people_write_them() -> None:
    assert DriveUnit.parse("0.1 % of 3.2 N*m").value == pytest.approx(0.0032, rel=1e-12)
    unit = DriveUnit.parse("1 mA")
    assert (unit.value, unit.kind) == (0.001, "current")
    assert DriveUnit.parse("0.5 % of 4 A").value == pytest.approx(0.02, rel=1e-12)
    for bad in ("0 N*m", "-1 mA"):
        with pytest.raises(BallScrewInputError, match="--drive-unit"):
            DriveUnit.parse(bad)
    with pytest.raises(BallScrewInputError, match="a torque or a current"):
        DriveUnit.parse("3 m/s")
    with pytest.raises(BallScrewInputError, match="kind"):
        DriveUnit(1.0, "speed", "1")


def test_the_motor_side_by_hand() -> None:
    # 100 N through a 10 mm lead and a gear of 2: T = 100 * 0.01 / (2 pi * 2) = 0.0795775 N*m;
    # over K_t = 1.6 N*m/A 0.0497359 A; in units of 1 mA 49.7359, of 3.2 mN*m 24.8680.
    table = CompensationTable(np.array([-0.1, 0.1]), np.array([-100.0, 100.0]), 0.0, 0.0, 0.1)
    torque = 100.0 * 0.01 / (4.0 * math.pi)
    current = ControllerTable("frict-comp", table, "complete", "t", 0.01, 2.0, 20.0, 0.0, 1.6,
                              DriveUnit.parse("1 mA"))  # fmt: skip
    assert current.motor_torque() == pytest.approx([-torque, torque], rel=1e-12)
    assert current.motor_current([100.0]) == pytest.approx([torque / 1.6], rel=1e-12)
    assert current.drive_values([100.0]) == pytest.approx([torque / 1.6 / 1e-3], rel=1e-12)
    d = current.as_dict()
    assert d["motor_current_A"] == pytest.approx([-torque / 1.6, torque / 1.6], rel=1e-12)
    assert d["drive_values"] == pytest.approx([-torque / 1.6e-3, torque / 1.6e-3], rel=1e-12)
    assert d["drive_unit"]["value_SI"] == 0.001 and d["torque_constant_Nm_per_A"] == 1.6
    shares = ControllerTable("frict-comp", table, "complete", "t", 0.01, 2.0, 20.0, 0.0, None,
                             DriveUnit.parse("0.1 % of 3.2 N*m"))  # fmt: skip
    assert shares.drive_values([100.0]) == pytest.approx([torque / 0.0032], rel=1e-12)
    assert "motor_current_A" not in shares.as_dict()
    with pytest.raises(BallScrewInputError, match="--torque-constant"):
        shares.motor_current()
    bare = ControllerTable("lincurve", table, "complete", "t", 0.01, 2.0, 20.0, 0.0)
    with pytest.raises(BallScrewInputError, match="--drive-unit"):
        bare.drive_values()
    assert "drive_values" not in bare.as_dict()


def test_a_vertical_axis_table_against_the_model_at_its_weight() -> None:
    # The vertical example: 120 kg on a vertical axis, no process load: the nut carries
    # -120 kg * g. The table at the range's end equals the model's friction there (the
    # screw's torque at that speed and load, 2 pi / lead per N*m), within the table's own
    # largest error (the model is evaluated here directly, not through the map).
    case = load_case(ROOT / "examples" / "vertical_32x5.toml")
    vmax = 3 / 60
    t = controller_table(case, "complete", "lincurve", speed_range=vmax)
    load = -120.0 * 9.80665
    assert t.axial_load == pytest.approx(load, rel=1e-12)
    assert (t.lead, t.gear_ratio, t.temperature) == (0.005, 1.0, 20.0)
    assert t.table.speed.size == 16 and t.table.speed[-1] == pytest.approx(vmax, rel=1e-12)
    for v in (vmax, -vmax):
        w = np.array([v * 2 * math.pi / 0.005])
        model = float(friction_torque(case.screw, case.lubricant, speed=w, temperature=20.0,
                                      axial_load=load, model="complete",
                                      **case.parameters_for("complete")).total[0])  # fmt: skip
        force = math.copysign(model * 2 * math.pi / 0.005, v)
        assert float(t.table(v)) == pytest.approx(force, abs=t.table.max_error * 1.001)
    with pytest.raises(BallScrewInputError, match="--form"):
        controller_table(case, "complete", "lincurves", speed_range=vmax)
    with pytest.raises(BallScrewInputError, match="--torque-constant"):
        controller_table(case, "complete", "frict-comp", speed_range=vmax,
                         drive_unit=DriveUnit.parse("1 mA"), torque_constant=-1.0)  # fmt: skip


def test_an_inclined_axis_without_a_moving_mass_adds_no_weight() -> None:
    # The load given is the nut's: no mass, no weight along the screw.
    case = _axis_case('incline = "90 deg"')
    t = controller_table(case, "complete", "charcurve", speed_range=0.05, axial_load=300.0)
    assert t.axial_load == 300.0 and t.table.speed.size == 11


# --------------------------------------------------------------------------- servo.export


def _axis_case(axis: str) -> Case:
    """The reference double nut (lead 10 mm) in mineral VG 68 with the given ``[axis]``."""
    return parse_case('title = "axis"\n[screw]\ndesignation = "40x10 double 2.5x2 6.35"\n'
                      'preload = "2 kN"\n[lubricant]\nname = "mineral ISO VG 68"\n'
                      f"[axis]\n{axis}\n")  # fmt: skip


CASE_BUNDLED = load_case(None)
SPEEDS8 = np.geomspace(1.0, 300.0, 8)  # rad/s
GEARED = 'moving_mass = "100 kg"\nmotor_inertia = "1e-3 kg*m**2"\n' \
         'coupling_inertia = "2e-4 kg*m**2"\ngear_ratio = 3'  # fmt: skip


def test_log_speeds_as_typed() -> None:
    rpm = 2 * math.pi / 60
    # A range of 3 is spaced logarithmically: 1, 10, 100 rpm (not 1, 50.5, 100).
    assert log_speeds("1..100:3 rpm") == pytest.approx(np.array([1.0, 10.0, 100.0]) * rpm,
                                                       rel=1e-12)  # fmt: skip
    # A list is sorted; feeds with a lead: 0.6 m/min at 10 mm is 60 rpm.
    assert log_speeds("3, 1, 2 rpm") == pytest.approx(np.array([1.0, 2.0, 3.0]) * rpm)
    with pytest.warns(Warning, match="lead 10 mm"):
        got = log_speeds("0.6..60 m/min:3", 0.01)
    assert got == pytest.approx(np.array([60.0, 600.0, 6000.0]) * rpm, rel=1e-12)
    with pytest.raises(BallScrewInputError, match=r"\(1 of the 3 given is 0 or below\)"):
        log_speeds("0..10:3 rpm")
    with pytest.raises(BallScrewInputError, match=r"\(2 of the 3 given are 0 or below\)"):
        log_speeds("-1, 0, 1 rpm")
    with pytest.raises(BallScrewInputError, match=r"3 or more speeds .*\(2 given\)"):
        log_speeds("1..10:2 rpm")


def test_axis_inertia_by_hand() -> None:
    # J_s + J_c + J_m i^2 + m (l / 2 pi)^2 = 5e-4 + 2e-4 + 1e-3 * 9 + 100 (0.01 / 2 pi)^2.
    axis = SimpleNamespace(screw_inertia=5e-4, coupling_inertia=2e-4, motor_inertia=1e-3,
                           gear_ratio=3.0, moving_mass=100.0)  # fmt: skip
    expected = 5e-4 + 2e-4 + 9e-3 + 100.0 * (0.01 / (2 * math.pi)) ** 2
    assert axis_inertia(axis, 0.01) == pytest.approx(expected, rel=1e-12)  # type: ignore[arg-type]


def _model(case: Case, w: np.ndarray, temperature: float, load: float) -> np.ndarray:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return np.asarray(friction_torque(case.screw, case.lubricant, speed=w,
                                          temperature=temperature, axial_load=load,
                                          model="complete").total)  # fmt: skip


def test_the_lookup_table_rows_by_hand() -> None:
    # Three speeds mirrored, at 40 degC and 500 N: each row's torque is the model's, signed
    # like the speed; table side through the 10 mm lead (v = w l / 2 pi, F = 2 pi T / l).
    case = _axis_case('moving_mass = "100 kg"')
    speeds = np.array([1.0, 10.0, 100.0])
    out = export_friction(case, "complete", "table", speeds=speeds, temperatures=[40.0],
                          axial_load=500.0)  # fmt: skip
    w = np.array([-100.0, -10.0, -1.0, 1.0, 10.0, 100.0])
    torque = np.sign(w) * _model(case, np.abs(w), 40.0, 500.0)
    assert [r["speed [rad/s]"] for r in out.rows] == w.tolist()
    assert [r["torque [N*m]"] for r in out.rows] == pytest.approx(torque, rel=1e-12)
    assert [r["speed [rpm]"] for r in out.rows] == pytest.approx(w * 60 / (2 * math.pi))
    assert [r["table speed [m/s]"] for r in out.rows] == pytest.approx(w * 0.01 / (2 * math.pi))
    assert [r["force [N]"] for r in out.rows] == pytest.approx(torque * 2 * math.pi / 0.01)
    assert out.axial_load == 500.0 and not out.notes
    doc = out.as_dict()
    assert doc["table"] == out.rows and "fits" not in doc and doc["lead_m"] == 0.01


def test_fitted_rows_at_two_temperatures_and_the_document() -> None:
    # The case's load (0 N) by default; at each temperature the fitted line's rows are
    # T_c sgn w + b w with the fitted T_c and b, and the model's torque beside them.
    case = _axis_case('moving_mass = "100 kg"')
    speeds = np.geomspace(1.0, 300.0, 8)
    out = export_friction(case, "complete", "coulomb-viscous", speeds=speeds,
                          temperatures=[20.0, 40.0])  # fmt: skip
    w = np.concatenate([-speeds[::-1], speeds])
    assert [t for t, _ in out.fitted] == [20.0, 40.0] and len(out.rows) == 2 * w.size
    for k, (temp, fit) in enumerate(out.fitted):
        rows = out.rows[k * w.size : (k + 1) * w.size]
        p = fit.parameters
        line = p["coulomb_torque"] * np.sign(w) + p["viscous_coefficient"] * w
        assert [r["torque coulomb-viscous [N*m]"] for r in rows] == pytest.approx(line)
        model = np.sign(w) * _model(case, np.abs(w), temp, 0.0)
        assert [r["torque complete [N*m]"] for r in rows] == pytest.approx(model, rel=1e-12)
        assert [r["temperature [degC]"] for r in rows] == [temp] * w.size
    doc = out.as_dict()
    assert [f["temperature_C"] for f in doc["fits"]] == [20.0, 40.0]
    assert doc["fits"][1]["axial_load_N"] == 0.0
    assert doc["parameters"] == doc["fits"][0]["parameters"]
    assert doc["rms_error_Nm"] == doc["fits"][0]["rms_error_Nm"]


def test_lugre_takes_the_axis_inertia_by_hand() -> None:
    # Critically damped bristle: sigma_1 = 2 sqrt(sigma_0 J), J = J_s + J_c + J_m i^2 +
    # m (l / 2 pi)^2 (J_s as the axis set-up reads it from the screw); a given inertia
    # replaces J.
    case = _axis_case(GEARED)
    axis = axis_setup(case.screw, case.axis, case.thermal, 0.0).axis
    j = axis.screw_inertia + 2e-4 + 1e-3 * 9.0 + 100.0 * (0.01 / (2 * math.pi)) ** 2
    speeds = np.geomspace(1.0, 300.0, 8)
    out = export_friction(case, "complete", "lugre", speeds=speeds, bristle_stiffness=50.0)
    p = out.fitted[0][1].parameters
    assert p["bristle_damping"] == pytest.approx(2 * math.sqrt(50.0 * j), rel=1e-12)
    # The curve beside the model's is the steady state, the Stribeck form of its parameters.
    row = out.rows[-1]
    w = 300.0
    stribeck = (p["coulomb_torque"] + (p["static_torque"] - p["coulomb_torque"])
                * math.exp(-((w / p["stribeck_speed"]) ** p["stribeck_exponent"]))
                + p["viscous_coefficient"] * w)  # fmt: skip
    assert row["torque lugre [N*m]"] == pytest.approx(stribeck, rel=1e-9)
    given = export_friction(case, "complete", "lugre", speeds=speeds, bristle_stiffness=50.0,
                            inertia=2e-3)  # fmt: skip
    assert given.fitted[0][1].parameters["bristle_damping"] == pytest.approx(
        2 * math.sqrt(50.0 * 2e-3), rel=1e-12
    )


def test_a_measured_curve_of_an_inclined_axis_keeps_its_load() -> None:
    # The weight joins the model's load only: a measured curve already carries it.
    case = _axis_case('moving_mass = "120 kg"\nincline = "90 deg"')
    w = np.array([1.0, 3.0, 10.0, 30.0])
    out = export_friction(case, "complete", "coulomb-viscous", speeds=w, axial_load=100.0,
                          measured=MeasuredCurve(w, 0.3 + 2e-4 * w, "m"))  # fmt: skip
    assert out.axial_load == 100.0 and not any("inclined" in n for n in out.notes)


def _line_with(outliers: dict[int, float], n: int) -> MeasuredCurve:
    """``n`` readings of 0.3 N*m + 2e-4 N*m*s/rad w, the given ones off by the given N*m."""
    w = np.geomspace(1.0, 300.0, n)
    t = 0.3 + 2e-4 * w
    for i, off in outliers.items():
        t[i] += off
    return MeasuredCurve(w, t, "m", temperature=np.full(n, 25.0))


def test_doubtful_readings_at_most_a_fifth_and_down_to_six_readings() -> None:
    # The other readings lie exactly on a line, so their robust scale is the floor (1e-9 of
    # the largest torque) and every reading 0.1 N*m off is far past 4 of it. 15 readings:
    # at most 15 // 5 = 3 named, the most doubtful first; 6 readings for 2 parameters: the
    # least that is judged (5 left, 2 + 3), and its one bad reading is named.
    out = export_friction(CASE_BUNDLED, "complete", "coulomb-viscous", speeds=SPEEDS8,
                          measured=_line_with({2: 0.4, 7: 0.3, 11: -0.2, 13: 0.1}, 15))  # fmt: skip
    (named,) = [n for n in out.notes if "data row(s)" in n]
    assert "data row(s) 3, 8, 12 lie" in named
    out = export_friction(CASE_BUNDLED, "complete", "coulomb-viscous", speeds=SPEEDS8,
                          measured=_line_with({4: 0.1}, 6))  # fmt: skip
    (named,) = [n for n in out.notes if "data row(s)" in n]
    assert "data row(s) 5 lie" in named
    assert not any("too few" in n for n in out.notes)
    out = export_friction(CASE_BUNDLED, "complete", "coulomb-viscous", speeds=SPEEDS8,
                          measured=_line_with({4: 0.1}, 5))  # fmt: skip
    assert any("5 readings for 2 parameters" in n for n in out.notes)
    # Exact readings: none is named (each off by rounding only, below 4 floors).
    out = export_friction(CASE_BUNDLED, "complete", "coulomb-viscous", speeds=SPEEDS8,
                          measured=_line_with({}, 15))  # fmt: skip
    assert not any("data row(s)" in n for n in out.notes)


def test_the_load_map_defaults_to_the_cases_loads_mirrored() -> None:
    # The XY example carries no process load: the map's loads are 0 N only; given loads are
    # taken as they are; the temperature is the case's first (25 degC).
    case = load_case(ROOT / "examples" / "xy_table_32x10.toml")
    speeds = np.array([1.0, 10.0, 100.0])
    m = run_export_friction(case, "complete", "load-map", speeds=speeds)
    assert m.loads.tolist() == [0.0] and m.temperatures.tolist() == [25.0]  # type: ignore[union-attr]
    loaded = _axis_case('moving_mass = "100 kg"\n[operation]\naxial_load = "1.5 kN"')
    m = run_export_friction(loaded, "complete", "load-map", speeds=speeds)
    assert m.loads.tolist() == [-1500.0, 0.0, 1500.0]  # type: ignore[union-attr]
    m = run_export_friction(loaded, "complete", "load-map", speeds=speeds, loads=[-200.0, 300.0],
                            temperatures=[30.0, 50.0])  # fmt: skip
    assert m.loads.tolist() == [-200.0, 300.0]  # type: ignore[union-attr]
    assert m.temperatures.tolist() == [30.0, 50.0]  # type: ignore[union-attr]
    form = run_export_friction(loaded, "complete", "table", speeds=speeds, temperatures=[30.0])
    assert form.temperatures == [30.0]  # type: ignore[union-attr]


def _named(out: Any) -> list[str]:
    return [n for n in out.notes if "data row(s)" in n]


@pytest.mark.parametrize(("share", "named"), [(4.2, True), (3.8, False)])
def test_exact_readings_name_one_past_four_floors(share: float, named: bool) -> None:
    # 15 readings exactly on a line but one, off by share x 1e-9 of the largest torque: the
    # others' residuals are rounding, so the robust scale is its floor, 1e-9 of the largest
    # torque, and the reading is named past 4 floors (rounding is 1e-16 N*m here).
    w = np.geomspace(1.0, 300.0, 15)
    t = 0.3 + 2e-4 * w
    t[6] += share * 1e-9 * float(np.max(t))
    out = export_friction(CASE_BUNDLED, "complete", "coulomb-viscous", speeds=SPEEDS8,
                          measured=MeasuredCurve(w, t, "m"))  # fmt: skip
    assert _named(out) == (["at 20 degC, data row(s) 7 lie more than 4 robust standard "
                            "deviations off the fitted curve: check them (they are kept in "
                            "the fit)"] if named else [])  # fmt: skip


@pytest.mark.parametrize(("times", "named"), [(1.1, True), (0.9, False)])
def test_the_robust_scale_is_taken_about_the_median(times: float, named: bool) -> None:
    # Twelve readings scattered unevenly about a line (seven above by 0.5 to 1.5 e, five
    # below by 1.4 e), so that their residuals' median is not 0; one more reading at 10
    # rad/s. The rule, computed here with numpy's own line fit: the others' residuals r,
    # scale 1.4826 median|r - median r|, threshold 4 scales from the others' line.
    e = 0.002
    offsets = np.array([0.5, 1.5, -1.4, 0.67, 1.33, -1.4, 0.83, 1.17, -1.4, 1.0, -1.4, -1.4])
    w = np.geomspace(1.0, 300.0, 12)
    t = 0.3 + 2e-4 * w + offsets * e
    slope, intercept = np.polyfit(w, t, 1)
    r = t - (intercept + slope * w)
    scale = 1.4826 * float(np.median(np.abs(r - np.median(r))))
    # The median matters: 0.17 scales here (about -median the scale would be 1.42 times).
    assert abs(float(np.median(r))) > 0.1 * scale
    extra = intercept + slope * 10.0 + times * 4.0 * scale
    out = export_friction(CASE_BUNDLED, "complete", "coulomb-viscous", speeds=SPEEDS8,
                          measured=MeasuredCurve(np.append(w, 10.0), np.append(t, extra),
                                                 "m"))  # fmt: skip
    assert [n.split(" lie")[0] for n in _named(out)] == (
        ["at 20 degC, data row(s) 13"] if named else []
    )


def test_lugre_is_judged_while_its_parameters_and_three_readings_remain() -> None:
    # LuGre has 7 parameters: 11 readings are the least that are judged (11 >= 7 + 4). Two
    # readings far off: the first is named (10 remain, 7 + 3); judging the second would
    # leave 9, fewer than 7 + 3, so it is not, though a fifth of 11 would allow 2.
    w = np.geomspace(0.3, 300.0, 11)
    t = 0.29 + 0.16 * np.exp(-((w / 0.6) ** 0.8)) + 3e-4 * w
    t[3] += 0.2
    t[8] += 0.1
    out = export_friction(CASE_BUNDLED, "complete", "lugre", speeds=SPEEDS8,
                          bristle_stiffness=50.0,
                          measured=MeasuredCurve(w, t, "m"))  # fmt: skip
    assert [n.split(" lie")[0] for n in _named(out)] == ["at 20 degC, data row(s) 4"]


def test_a_reading_at_rest_does_not_make_a_curve_two_way() -> None:
    # Readings at 0 and forward only: the curve still turns one way, and is said so.
    w = np.array([0.0, 1.0, 3.0, 10.0, 30.0])
    out = export_friction(CASE_BUNDLED, "complete", "coulomb-viscous", speeds=SPEEDS8,
                          measured=MeasuredCurve(w, 0.3 + 2e-4 * w, "m"))  # fmt: skip
    assert any("turns one way" in n for n in out.notes)
    out = export_friction(CASE_BUNDLED, "complete", "coulomb-viscous", speeds=SPEEDS8,
                          measured=MeasuredCurve(-w, 0.3 + 2e-4 * w, "m"))  # fmt: skip
    assert any("turns one way" in n for n in out.notes)
    w = np.array([-0.5, -0.2, 0.2, 0.5, 0.8, 0.9])
    out = export_friction(CASE_BUNDLED, "complete", "coulomb-viscous", speeds=SPEEDS8,
                          measured=MeasuredCurve(w, 0.3 + 2e-4 * np.abs(w), "m"))  # fmt: skip
    assert not any("turns one way" in n for n in out.notes)


# --------------------------------------------------------------------------- servo.plant

SPRUNG = GEARED + '\nbearing_span = "800 mm"\n[check]\nsupport_stiffness = "500 N/um"'


def test_the_two_mass_plant_of_a_geared_axis_by_hand() -> None:
    # m1 = (J_m i^2 + J_c + J_s)(2 pi / l)^2, m2 the moving mass; the spring is the shaft in
    # tension and in torsion at mid-span, the nut and the bearings in series (each from
    # its own function, summed here as compliances); damping 2 * 0.02 sqrt(k m1 m2 / M).
    case = _axis_case(SPRUNG)
    a = axis_dynamics(case, max_speed=0.2)
    js = axis_setup(case.screw, case.axis, case.thermal, 0.0).axis.screw_inertia
    m1 = (1e-3 * 9.0 + 2e-4 + js) * (2 * math.pi / 0.01) ** 2
    assert a.motor_mass == pytest.approx(m1, rel=1e-12) and a.table_mass == 100.0
    d_r = root_diameter(case.screw)
    springs = [shaft_axial_stiffness(d_r, 0.8, 0.4, "fixed-supported"),
               torsional_axial_stiffness(d_r, 0.4, 0.01), design_nut_stiffness(case.screw),
               500e6]  # fmt: skip
    k = 1.0 / sum(1.0 / float(s) for s in springs)
    assert a.stiffness == pytest.approx(k, rel=1e-12)
    assert a.damping == pytest.approx(0.04 * math.sqrt(k * m1 * 100.0 / (m1 + 100.0)), rel=1e-12)
    assert (a.lead, a.gear_ratio, a.external_force) == (0.01, 3.0, 0.0)
    assert any("nut at mid-span (400 mm" in n for n in a.notes)
    assert not any("rigid" in n for n in a.notes)
    # The modes: the eigenvalues of M^-1 K are 0 and w^2; the table on the spring with
    # the motor held rings at sqrt(k / m2).
    stiff = np.array([[k, -k], [-k, k]])
    w2 = np.linalg.eigvals(np.diag([1 / m1, 1 / 100.0]) @ stiff).real.max()
    assert a.eigenfrequency == pytest.approx(math.sqrt(w2) / (2 * math.pi), rel=1e-9)
    assert a.antiresonance == pytest.approx(math.sqrt(k / 100.0) / (2 * math.pi), rel=1e-12)
    # The friction map: 48 table speeds each way up to max_speed, the model's force at the
    # nut's load (0 N) through the lead.
    assert a.speeds.size == 96 and a.speeds[-1] == pytest.approx(0.2, rel=1e-12)
    assert a.speeds[48] == pytest.approx(1e-5, rel=1e-12)
    assert a.speeds[:48] == pytest.approx(-a.speeds[48:][::-1], rel=1e-12)
    for v in (0.2, -0.2, 1e-5):
        w = np.array([abs(v) * 2 * math.pi / 0.01])
        force = float(_model(case, w, 20.0, 0.0)[0]) * 2 * math.pi / 0.01
        assert float(np.interp(v, a.speeds, a.friction)) == pytest.approx(
            math.copysign(force, v), rel=1e-9
        )
    # The bristle: creep friction (the mean of both slowest speeds') over 5 um, critically
    # damped on the motor side; a length given replaces it.
    creep = 0.5 * (abs(a.friction[47]) + abs(a.friction[48]))
    assert a.coulomb_force() == pytest.approx(creep, rel=1e-12)
    assert a.bristle_stiffness == pytest.approx(creep / 5e-6, rel=1e-12)
    assert a.bristle_damping == pytest.approx(2 * math.sqrt(creep / 5e-6 * m1), rel=1e-12)
    assert a.pre_rolling_length == pytest.approx(5e-6, rel=1e-12)
    t = axis_dynamics(case, max_speed=0.2, drag_side="table", pre_rolling_length=2e-6)
    assert t.bristle_stiffness == pytest.approx(creep / 2e-6, rel=1e-12)
    assert t.bristle_damping == pytest.approx(2 * math.sqrt(creep / 2e-6 * 100.0), rel=1e-12)
    assert t.drag_mass == 100.0 and a.drag_mass == pytest.approx(m1, rel=1e-12)
    assert any("(given;" in n for n in t.notes) and any("(the default" in n for n in a.notes)
    # Guides not given: none (and said); the note gives the bristle in um and N/um.
    assert (a.guide_coulomb, a.guide_viscous) == (0.0, 0.0)
    assert any("guideway friction left out" in n for n in a.notes)
    (note,) = [n for n in a.notes if "pre-rolling length" in n]
    assert "pre-rolling length 5 um" in note and f"{creep / 5e-6 / 1e6:.4g} N/um" in note
    assert f"critically damped on {m1:.4g} kg" in note
    # Without a span the screw's length (and inertia) is the set-up's for no travel.
    bare_case = _axis_case(GEARED)
    js0 = axis_setup(bare_case.screw, bare_case.axis, bare_case.thermal, 0.0).axis.screw_inertia
    bare = axis_dynamics(bare_case)
    m1_bare = (9e-3 + 2e-4 + js0) * (2 * math.pi / 0.01) ** 2
    assert bare.motor_mass == pytest.approx(m1_bare, rel=1e-12)
    assert axis_dynamics(case).speeds[-1] == pytest.approx(0.5, rel=1e-12)  # the default


def test_a_vertical_axis_carries_its_weight_on_the_table() -> None:
    # 120 kg vertical: -120 g on the table, and the nut's friction at that load.
    case = load_case(ROOT / "examples" / "vertical_32x5.toml")
    a = axis_dynamics(case, max_speed=0.05, guide_coulomb=40.0, guide_viscous=3.0)
    weight = -120.0 * 9.80665
    assert a.external_force == pytest.approx(weight, rel=1e-12)
    force = float(_model(case, np.array([0.05 * 2 * math.pi / 0.005]), 20.0, weight)[0])
    assert a.friction[-1] == pytest.approx(force * 2 * math.pi / 0.005, rel=1e-9)
    assert (a.guide_coulomb, a.guide_viscous) == (40.0, 3.0)
    assert any("the weight along the axis" in n for n in a.notes)
    assert not any("guideway friction left out" in n for n in a.notes)


def _hand_axis(**changes: object) -> AxisDynamics:
    """A two-mass axis by hand: 40 kg motor side, 60 kg table, 2e8 N/m, drag 50 N / 30 N."""
    base = AxisDynamics("hand", 40.0, 60.0, 2e8, 1000.0, np.array([-1.0, -1e-3, 1e-3, 1.0]),
                        np.array([-80.0, -30.0, 50.0, 90.0]), 8e6, 2e4, lead=0.01,
                        gear_ratio=2.0)  # fmt: skip
    return dataclasses.replace(base, **changes)  # type: ignore[arg-type]


def test_the_plant_figures_by_hand() -> None:
    a = _hand_axis()
    assert a.mass == 100.0 and not a.rigid and a.drag_mass == 40.0
    assert a.coulomb_force() == 40.0  # (30 + 50) / 2
    assert a.pre_rolling_length == pytest.approx(40.0 / 8e6, rel=1e-12)
    # sqrt(2e8 (1/40 + 1/60)) / 2 pi = 457.7 / 2 pi Hz; sqrt(2e8 / 60) / 2 pi.
    assert a.eigenfrequency == pytest.approx(math.sqrt(2e8 / 24.0) / (2 * math.pi), rel=1e-12)
    assert a.antiresonance == pytest.approx(math.sqrt(2e8 / 60.0) / (2 * math.pi), rel=1e-12)
    # 100 N through 10 mm and a gear of 2: 100 * 0.01 / (2 pi 2) N*m.
    assert float(a.motor_torque(100.0)) == pytest.approx(1.0 / (4 * math.pi), rel=1e-12)
    d = a.as_dict()
    assert d["stiffness_N_per_um"] == 200.0 and d["bristle_stiffness_N_per_um"] == 8.0
    assert d["pre_rolling_length_um"] == pytest.approx(5.0, rel=1e-12)
    assert d["eigenfrequency_Hz"] == a.eigenfrequency and d["friction_at_creep_N"] == 40.0
    r = a.as_rigid()
    assert r.rigid and r.damping == 0.0 and r.drag_mass == 100.0
    assert r.bristle_damping == pytest.approx(2 * math.sqrt(8e6 * 100.0), rel=1e-12)
    assert r.eigenfrequency == math.inf and r.antiresonance == math.inf
    assert r.as_dict()["stiffness_N_per_um"] is None and r.as_dict()["antiresonance_Hz"] is None
    table = _hand_axis(drag_side="table")
    assert table.drag_mass == 60.0
    bare = frictionless(_hand_axis(guide_coulomb=20.0, guide_viscous=5.0))
    assert not np.any(bare.friction) and (bare.guide_coulomb, bare.guide_viscous) == (0.0, 0.0)
    with pytest.raises(BallScrewInputError, match="drag_side"):
        _hand_axis(drag_side="nut")


def test_the_plants_inputs_are_checked() -> None:
    with pytest.raises(BallScrewInputError, match=r"moving_mass = 0\.0 is not allowed"):
        axis_dynamics(_axis_case("gear_ratio = 2"))
    case = _axis_case(SPRUNG)
    for bad in (0.0, -0.1):
        with pytest.raises(BallScrewInputError, match="max_speed"):
            axis_dynamics(case, max_speed=bad)
    for bad in (0.0, -1e-6, math.inf):
        with pytest.raises(BallScrewInputError, match="pre_rolling_length"):
            axis_dynamics(case, pre_rolling_length=bad)
    with pytest.raises(BallScrewInputError, match="drag_side"):
        axis_dynamics(case, drag_side="nut")
    # A single nut has a stiffness only under load; no span: a rigid shaft, said.
    single = parse_case('title = "s"\n[screw]\ndesignation = "32x10 single 3x1 6.35"\n'
                        '[lubricant]\nname = "mineral ISO VG 68"\n[axis]\n'
                        'moving_mass = "50 kg"\n')  # fmt: skip
    with pytest.raises(BallScrewInputError, match="single"):
        axis_dynamics(single)
    a = axis_dynamics(single, axial_load=1000.0)
    k_nut = design_nut_stiffness(single.screw, 1000.0)
    assert a.stiffness == pytest.approx(k_nut, rel=1e-12)
    assert any("no span" in n for n in a.notes) and any("bearings rigid" in n for n in a.notes)
    assert axis_dynamics(single, axial_load=1.0).stiffness == pytest.approx(
        design_nut_stiffness(single.screw, 1.0), rel=1e-12
    )
    # Inclined, the weight joins the process load on the nut: 1000 N - 50 kg g.
    tilted = parse_case('title = "s"\n[screw]\ndesignation = "32x10 single 3x1 6.35"\n'
                        '[lubricant]\nname = "mineral ISO VG 68"\n[axis]\n'
                        'moving_mass = "50 kg"\nincline = "90 deg"\n')  # fmt: skip
    a = axis_dynamics(tilted, axial_load=1000.0, max_speed=0.1)
    nut = 1000.0 - 50.0 * 9.80665
    assert a.stiffness == pytest.approx(design_nut_stiffness(tilted.screw, nut), rel=1e-12)
    force = float(_model(tilted, np.array([0.1 * 2 * math.pi / 0.01]), 20.0, nut)[0])
    assert a.friction[-1] == pytest.approx(force * 2 * math.pi / 0.01, rel=1e-9)
    assert any(f"complete at {nut:.4g} N" in n for n in a.notes)


def test_a_creep_friction_below_one_newton_sets_the_bristle_too() -> None:
    # A 12 x 4 single nut under 5 N: 0.39 N of creep friction, over the default 5 um.
    case = parse_case('title = "s"\n[screw]\ndesignation = "12x4 single 3x1 2.5"\n'
                      '[lubricant]\nname = "mineral ISO VG 68"\n[axis]\n'
                      'moving_mass = "5 kg"\n')  # fmt: skip
    a = axis_dynamics(case, axial_load=5.0)
    assert 0.0 < a.coulomb_force() < 1.0
    assert a.bristle_stiffness == pytest.approx(a.coulomb_force() / 5e-6, rel=1e-12)


def test_the_pre_rolling_ranges_lower_end_is_the_linear_limit() -> None:
    # The lower end is where the build-up F = g (1 - e^(-x / delta)) stays linear within
    # 5 % at 0.1 um of travel, rounded: (1 - e^(-0.1)) / 0.1 = 0.952 at 1 um, 0.949 at
    # 0.95 um (the limit is 0.967 um).
    low = PRE_ROLLING_RANGE[0]

    def linear(delta: float) -> float:
        return -math.expm1(-0.1e-6 / delta) / (0.1e-6 / delta)

    assert linear(low) > 0.95 > linear(0.95 * low)


def test_a_map_with_a_point_at_rest_creeps_at_its_slowest_moving_speeds() -> None:
    a = _hand_axis(speeds=np.array([-1.0, -1e-3, 0.0, 1e-3, 1.0]),
                   friction=np.array([-80.0, -30.0, 0.0, 50.0, 90.0]))  # fmt: skip
    assert a.coulomb_force() == 40.0
    # A hand-built axis without guides, weight or gear has none of them and is direct.
    d = _rigid().as_dict()
    assert (d["guide_coulomb_N"], d["guide_viscous_N_s_per_m"]) == (0.0, 0.0)
    assert d["external_force_N"] == 0.0 and d["gear_ratio"] == 1.0


# --------------------------------------------------------------------------- servo.simulate

FLAT = np.array([-1.0, -1e-3, 1e-3, 1.0])  # m/s: a map whose friction is 50 N at every speed


def _rigid(**changes: object) -> AxisDynamics:
    """A rigid 100 kg axis (40 + 60 kg), 50 N of screw drag, a 1 um bristle (stiff)."""
    s0 = 50.0 / 1e-6
    base = AxisDynamics("rigid", 40.0, 60.0, math.inf, 0.0, FLAT, 50.0 * np.sign(FLAT), s0,
                        2.0 * math.sqrt(s0 * 100.0))  # fmt: skip
    return dataclasses.replace(base, **changes)  # type: ignore[arg-type]


def _open_loop(ts: float, tau: float = 1e-12, **changes: float) -> Gains:
    """No feedback (gains of 1e-300): the force is the feed-forward and the compensation."""
    return dataclasses.replace(Gains(ts, 1e-300, 0.0, 0.0, 1e-300, 0.0, tau), **changes)  # type: ignore[arg-type]


def _second_difference(x: np.ndarray, i: int, di: int, ts: float) -> float:
    """The acceleration of a parabola through x[i - di], x[i], x[i + di] [m/s^2]."""
    return float(x[i + di] - 2 * x[i] + x[i - di]) / (di * ts) ** 2


def test_substeps_by_hand() -> None:
    # The fastest of sqrt(s0 / m_drag) = 447 1/s, s1 / m_drag = 500 1/s, the mode
    # sqrt(2e8 / 24 kg) = 2887 1/s and the guide's 2 sqrt(20 N / 1 um / 60 kg) = 1155 1/s,
    # with w h <= 0.1: ceil(1e-3 * 2887 / 0.1) = 29 per millisecond.
    a = _hand_axis(guide_coulomb=20.0)
    assert substeps(a, 1e-3) == 29
    assert substeps(_hand_axis(), 1e-3) == 29
    assert substeps(a, 1e-6) == 1
    # Rigid: sqrt(8e6 / 100) = 283, 2 sqrt(8e6 100) / 100 = 566, guide 2 sqrt(2e7 / 100) = 894.
    assert substeps(a.as_rigid(), 1e-3) == 9
    # The table's bristle drag alone: 2e4 / 60 kg = 333 1/s and sqrt(8e6 / 60) = 365 1/s,
    # below the mode: 29 still; with a soft spring (2e5 N/m: 91 1/s) the bristle sets it.
    soft = _hand_axis(stiffness=2e5, drag_side="table")
    assert substeps(soft, 1e-3) == math.ceil(1e-3 * math.sqrt(8e6 / 60.0) / 0.1)


def test_interpolation_by_hand() -> None:
    xs, ys = [0.0, 1.0, 3.0], [0.0, 2.0, 6.0]
    got = [_interp(xs, ys, x) for x in (-1.0, 0.0, 0.5, 1.0, 2.0, 3.0, 4.0)]
    assert got == [0.0, 0.0, 1.0, 2.0, 4.0, 6.0, 6.0]


def test_a_force_step_on_two_masses_against_the_closed_form() -> None:
    # No friction, no damping, no feedback: F = 300 N on the motor side from t = 0, a
    # constant -500 N on the table that the spring carries from the start. The centre of
    # mass accelerates at F / M; the spring's stretch u = x1 - x2 - ext / k rings at
    # w = sqrt(k (1/m1 + 1/m2)) around F / (m1 w^2):
    # x1 = F t^2 / 2M + (m2 / M) u, x2 - ext / k = F t^2 / 2M - (m1 / M) u,
    # u = F / (m1 w^2) (1 - cos w t). Semi-implicit Euler with w h <= 0.1 over 4 periods
    # keeps the phase within (w h)^2 / 24 per radian: 2 % of u's swing, 1e-3 of x.
    a = frictionless(_hand_axis(damping=0.0, external_force=-500.0))
    ts, n = 1e-4, 400
    t = np.arange(n) * ts
    force = np.full(n, 300.0)
    trace = simulate_axis(a, _open_loop(ts), np.zeros(n), np.zeros(n), np.zeros(n),
                          compensation=force)  # fmt: skip
    w = math.sqrt(2e8 * (1 / 40.0 + 1 / 60.0))
    assert w * t[-1] > 2 * math.pi * 4
    u = 300.0 / (40.0 * w * w) * (1 - np.cos(w * t))
    centre = 300.0 * t**2 / 200.0
    swing = 2 * 300.0 / (40.0 * w * w)
    assert trace.motor == pytest.approx(centre + 0.6 * u, abs=0.02 * swing + 1e-3 * centre[-1])
    tolerance = 0.02 * swing + 1e-3 * centre[-1]
    assert trace.table + 500.0 / 2e8 == pytest.approx(centre - 0.4 * u, abs=tolerance)
    assert (
        trace.time == pytest.approx(t, rel=1e-12) and trace.force[-1] == 800.0
    )  # 300 N + the 500 N held
    assert trace.error == pytest.approx(-trace.table, rel=1e-12)


def test_the_current_lag_and_the_acceleration_feed_forward_against_the_closed_form() -> None:
    # A rigid frictionless 100 kg: F = 0.5 * 100 kg * 2 m/s^2 + 50 N through a lag of 5 ms,
    # F(t) = 150 N (1 - e^(-t/tau)); x = (F / M)(t^2 / 2 - tau t + tau^2 (1 - e^(-t/tau))).
    # A stiff bristle (5e11 N/m) makes the step h 1.4 us: first order, h / t = 1e-3 of x
    # from 5 ms on.
    a = frictionless(_rigid(bristle_stiffness=5e11))
    ts, n, tau = 1e-3, 51, 5e-3
    trace = simulate_axis(a, _open_loop(ts, tau, acceleration_ff=0.5), np.zeros(n),
                          np.zeros(n), np.full(n, 2.0), compensation=np.full(n, 50.0))  # fmt: skip
    t = trace.time
    x = 1.5 * (t**2 / 2 - tau * t + tau**2 * (1 - np.exp(-t / tau)))
    assert trace.table[5:] == pytest.approx(x[5:], rel=1e-3)
    assert trace.motor == pytest.approx(trace.table, rel=1e-12)
    # The force is recorded at the end of its sample.
    assert trace.force[-1] == pytest.approx(150.0 * (1 - math.exp(-(t[-1] + ts) / tau)), rel=1e-6)


@pytest.mark.parametrize("sign", [1.0, -1.0])
def test_screw_and_guide_friction_take_their_share_of_a_constant_force(sign: float) -> None:
    # 300 N on the rigid 100 kg against the screw's 50 N and the guide's 30 N: once the
    # bristles have built up (micrometres of travel), a = 220 / 100 = 2.2 m/s^2 and the
    # friction reported is the map's 50 N (the bristle at its steady deflection g / s0).
    # The acceleration from a second difference of positions 20 ms apart: the bristles'
    # start-up only shifts the parabola. 1e-3: the integration's first-order error.
    a = _rigid(guide_coulomb=30.0)
    ts, n = 1e-3, 101
    trace = simulate_axis(a, _open_loop(ts), np.zeros(n), np.zeros(n), np.zeros(n),
                          compensation=np.full(n, 300.0 * sign))  # fmt: skip
    assert _second_difference(trace.table, 70, 20, ts) == pytest.approx(2.2 * sign, rel=1e-3)
    assert trace.friction[-1] == pytest.approx(50.0 * sign, rel=1e-6)
    # The same on two masses, the drag on either side.
    for side in ("motor", "table"):
        b = _hand_axis(guide_coulomb=30.0, drag_side=side, friction=50.0 * np.sign(FLAT),
                       speeds=FLAT)  # fmt: skip
        trace = simulate_axis(b, _open_loop(ts), np.zeros(n), np.zeros(n), np.zeros(n),
                              compensation=np.full(n, 300.0 * sign))  # fmt: skip
        for x in (trace.motor, trace.table):
            assert _second_difference(x, 70, 20, ts) == pytest.approx(2.2 * sign, rel=2e-3)
        assert trace.friction[-1] == pytest.approx(50.0 * sign, rel=1e-3)


def test_viscous_guide_friction_against_the_closed_form() -> None:
    # 100 N on a rigid frictionless 100 kg with 100 N*s/m on its guides: v = 1 - e^(-t),
    # x = t - (1 - e^(-t)) [m, s]; on two masses the same (the spring is stiff), the
    # table's viscous drag on the table.
    ts, n = 1e-3, 501
    t = np.arange(n) * ts
    x = t - (1 - np.exp(-t))
    for a in (frictionless(_rigid()), frictionless(_hand_axis())):
        a = dataclasses.replace(a, guide_viscous=100.0)
        trace = simulate_axis(a, _open_loop(ts), np.zeros(n), np.zeros(n), np.zeros(n),
                              compensation=np.full(n, 100.0))  # fmt: skip
        assert trace.table[100:] == pytest.approx(x[100:], rel=2e-3)


def _loop(ts: float, mass: float, **changes: float) -> Gains:
    """A P position loop (k_v 50 1/s) over a PI velocity loop crossing at 300 Hz."""
    wc = 2 * math.pi * 300.0
    base = Gains(ts, 50.0, 0.0, 0.0, mass * wc, mass * wc * wc / 10.0, 5e-5)
    return dataclasses.replace(base, **changes)  # type: ignore[arg-type]


def test_the_loop_holds_the_encoders_position_and_the_offset() -> None:
    # A vertical-like load of -1000 N through a 2e8 N/m spring: at rest the table sits
    # 5 um below the motor. With the motor's encoder the motor stays at 0; with a linear
    # scale the integrator moves the motor until the table is at 0 (motor at +5 um); an
    # offset of 20 um is followed as a reference of 20 um, the trace keeping x_ref = 0.
    # After 0.4 s (20 time constants of k_v) the error left is below 1e-9 m.
    a = frictionless(_hand_axis(external_force=-1000.0))
    ts, n = 1e-4, 4001
    zero = np.zeros(n)
    motor = simulate_axis(a, _loop(ts, a.mass), zero, zero, zero)
    assert motor.motor[-1] == pytest.approx(0.0, abs=1e-9)
    assert motor.table[-1] == pytest.approx(-5e-6, abs=1e-9)
    scale = simulate_axis(a, _loop(ts, a.mass, feedback="table"), zero, zero, zero)  # type: ignore[arg-type]
    assert scale.table[-1] == pytest.approx(0.0, abs=1e-9)
    assert scale.motor[-1] == pytest.approx(5e-6, abs=1e-9)
    offset = simulate_axis(a, _loop(ts, a.mass), zero, zero, zero,
                           position_offset=np.full(n, 2e-5))  # fmt: skip
    assert offset.motor[-1] == pytest.approx(2e-5, abs=1e-9)
    assert offset.x_ref.tolist() == zero.tolist()
    assert offset.error[-1] == pytest.approx(-(2e-5 - 5e-6), abs=1e-9)


def test_the_speed_feed_forward_alone_sets_the_speed() -> None:
    # Without the position loop (k_v = 0) and the integrator, the velocity loop drives
    # the speed from the encoder to 0.5 v_ref: 0.1 m/s for v_ref = 0.2, with the time
    # constant M / k_p = 10 ms; after 0.3 s it is there to e^-30.
    a = frictionless(_rigid())
    ts, n = 1e-4, 3001
    gains = Gains(ts, 1e-300, 0.5, 0.0, 1e4, 0.0, 5e-5)
    trace = simulate_axis(a, gains, np.zeros(n), np.full(n, 0.2), np.zeros(n))
    assert (trace.motor[-1] - trace.motor[-2]) / ts == pytest.approx(0.1, rel=1e-6)


def test_a_diverging_loop_and_bad_references_are_refused() -> None:
    a = frictionless(_rigid())
    n = 200
    zero = np.zeros(n)
    with pytest.raises(BallScrewInputError, match="gains"):
        # k_p T_s / M = 1e4: each sample multiplies the speed's error by about 1e4.
        simulate_axis(a, _loop(1e-3, a.mass, kp=1e9), np.r_[0.0, zero[1:] + 1e-3], zero, zero)
    with pytest.raises(BallScrewInputError, match="reference"):
        simulate_axis(a, _loop(1e-3, a.mass), zero, zero[:-1], zero)
    with pytest.raises(BallScrewInputError, match="reference"):
        simulate_axis(a, _loop(1e-3, a.mass), [0.0], [0.0], [0.0])
    two = simulate_axis(a, _loop(1e-3, a.mass), [0.0, 0.0], [0.0, 0.0], [0.0, 0.0])
    assert two.time.tolist() == [0.0, 1e-3]


def test_the_guides_yield_their_pre_sliding_length_under_half_their_friction() -> None:
    # Half the guides' Coulomb force held on the table: the bristle stops at z = F / g0,
    # half of GUIDE_PRESLIDING (1 um), after x = -1 um ln(1 - 1/2) = 0.693 um of travel
    # (LuGre forwards, dz = dx (1 - z / delta)). 3 %: the critically damped bristle's
    # overshoot while it settles (1.3 %).
    a = dataclasses.replace(frictionless(_rigid()), guide_coulomb=30.0)
    n, ts = 400, 1e-4
    trace = simulate_axis(a, _open_loop(ts), np.zeros(n), np.zeros(n), np.zeros(n),
                          compensation=np.full(n, 15.0))  # fmt: skip
    assert trace.table[-1] == pytest.approx(1e-6 * math.log(2.0), rel=0.03)
    assert trace.table[-1] == pytest.approx(trace.table[-50], rel=1e-4)  # at rest


def test_substeps_of_a_light_guide_and_of_no_bristle() -> None:
    # A soft screw bristle (sqrt(1e3 / 100) = 3.2 1/s) and 0.5 N on the guides:
    # 2 sqrt(0.5 N / 1 um / 100 kg) = 141 1/s sets ceil(1e-2 * 141 / 0.1) = 15 sub-steps.
    a = _rigid(bristle_stiffness=1e3, bristle_damping=10.0, guide_coulomb=0.5)
    assert substeps(a, 1e-2) == math.ceil(1e-2 * 2 * math.sqrt(0.5e6 / 100.0) / 0.1)
    # No bristle and no guide: nothing to resolve, one step a sample.
    assert substeps(frictionless(_rigid(bristle_stiffness=0.0, bristle_damping=0.0)), 1e-3) == 1


@pytest.mark.parametrize("scale", [1.0, 0.01])
def test_small_frictions_act_too(scale: float) -> None:
    # 50 N and 30 N, or 0.5 N and 0.3 N (below 1 N, still friction), against 300 N or 3 N
    # on 100 kg: a = (300 - 50 - 30) N x scale / 100 kg = 2.2 m/s^2 x scale.
    s0 = 50.0 * scale / 1e-6
    a = _rigid(friction=50.0 * scale * np.sign(FLAT), bristle_stiffness=s0,
               bristle_damping=2 * math.sqrt(s0 * 100.0), guide_coulomb=30.0 * scale)  # fmt: skip
    ts, n = 1e-3, 101
    trace = simulate_axis(a, _open_loop(ts), np.zeros(n), np.zeros(n), np.zeros(n),
                          compensation=np.full(n, 300.0 * scale))  # fmt: skip
    assert _second_difference(trace.table, 70, 20, ts) == pytest.approx(2.2 * scale, rel=2e-3)
    assert trace.friction[-1] == pytest.approx(50.0 * scale, rel=1e-6)


def test_the_start_is_at_the_first_reference_and_a_held_weight_stays() -> None:
    # Open loop, the integrator holding the weight (-500 N) from the start: the axis stays
    # where the reference starts (1 mm), rigid or sprung, drag on either side.
    n, ts = 100, 1e-3
    x = np.linspace(1e-3, 2e-3, n)
    for a in (frictionless(_rigid(external_force=-500.0)),
              frictionless(_hand_axis(external_force=-500.0, drag_side="table"))):  # fmt: skip
        trace = simulate_axis(a, _open_loop(ts), x, np.zeros(n), np.zeros(n))
        assert trace.motor[0] == 1e-3
        assert trace.motor[-1] == pytest.approx(1e-3, abs=1e-12)


@pytest.mark.parametrize("side", ["motor", "table"])
def test_the_spring_carries_the_tables_inertia_and_its_friction(side: str) -> None:
    # At a steady 2.2 m/s^2 the spring's stretch x1 - x2 is what it pushes the table with:
    # m2 a + the guide's 30 N (+ the screw's 50 N when the drag is on the table), over k;
    # averaged over 30 ms (the mode rings at 2.2 ms, damped by 0.7 %). 3 %: the ringing left.
    a = _hand_axis(guide_coulomb=30.0, drag_side=side, friction=50.0 * np.sign(FLAT),
                   speeds=FLAT)  # fmt: skip
    ts, n = 1e-3, 101
    trace = simulate_axis(a, _open_loop(ts), np.zeros(n), np.zeros(n), np.zeros(n),
                          compensation=np.full(n, 300.0))  # fmt: skip
    stretch = float(np.mean((trace.motor - trace.table)[-30:]))
    carried = 60.0 * 2.2 + 30.0 + (50.0 if side == "table" else 0.0)
    assert stretch == pytest.approx(carried / 2e8, rel=0.03)


def test_viscous_guides_with_the_drag_on_the_table() -> None:
    ts, n = 1e-3, 501
    t = np.arange(n) * ts
    a = dataclasses.replace(frictionless(_hand_axis(drag_side="table")), guide_viscous=100.0)
    trace = simulate_axis(a, _open_loop(ts), np.zeros(n), np.zeros(n), np.zeros(n),
                          compensation=np.full(n, 100.0))  # fmt: skip
    assert trace.table[100:] == pytest.approx((t - (1 - np.exp(-t)))[100:], rel=2e-3)


def test_the_guides_bristle_is_critically_damped() -> None:
    # The same half-Coulomb hold against the continuous LuGre guide, critically damped
    # (sigma_1 = 2 sqrt(sigma_0 M)), solved by scipy: where the table stops depends on the
    # bristle's damping (0.9 % less travel at a damping ratio of 1.1). 0.3 %: the sampled
    # integration's own error (0.1 %).
    from scipy.integrate import solve_ivp

    mass, gc, force = 100.0, 30.0, 15.0
    g0 = gc / 1e-6
    g1 = 2.0 * math.sqrt(g0 * mass)

    def rhs(_t: float, s: np.ndarray) -> list[float]:
        _x, v, z = s
        dz = v - g0 * abs(v) * z / gc
        return [v, (force - g0 * z - g1 * dz) / mass, dz]

    sol = solve_ivp(rhs, (0.0, 0.04), [0.0, 0.0, 0.0], method="LSODA", rtol=1e-10,
                    atol=[1e-15, 1e-12, 1e-15])  # fmt: skip
    a = dataclasses.replace(frictionless(_rigid()), guide_coulomb=gc)
    n, ts = 400, 1e-4
    trace = simulate_axis(a, _open_loop(ts), np.zeros(n), np.zeros(n), np.zeros(n),
                          compensation=np.full(n, force))  # fmt: skip
    assert trace.table[-1] == pytest.approx(sol.y[0, -1], rel=3e-3)
