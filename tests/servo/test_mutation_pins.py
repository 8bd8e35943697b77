"""Pins of servo/'s fits from their mutation runs (issue 49), each against a number by hand.

``servo.friction_map``: the load map's fit is run on exact data of the compact form (a
linear least-squares fit of exact data returns its coefficients to rounding), and the
map's guards on grids whose point counts are multiplied out by hand. Where the map's
model would be slow or its output unknown, the model is replaced by the compact form
itself, so every coefficient of the map is known.

``servo.controller``: the intervals of a fit against the textbook formulas of a straight line,
and the Stribeck fit's guards on curves written by hand.
"""

from __future__ import annotations

import dataclasses
import math
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import load_case
from ballscrew.servo import friction_map as fm
from ballscrew.servo.friction_map import LoadForm, fit_load_form, friction_map, load_form

CASE = load_case(None)  # the bundled study case
SPEEDS = np.geomspace(1.0, 300.0, 12)  # rad/s
W = np.concatenate([-SPEEDS[::-1], SPEEDS])
LOADS = np.array([-3000.0, -1500.0, 0.0, 1500.0, 3000.0])  # N


def _form(**kw: float) -> LoadForm:
    base = {"c0": 0.3, "c1": 4e-5, "c2": 0.0, "b": 2e-4, "k_c": 0.0, "k_b": 0.0,
            "reference_temperature": 20.0, "rms_error": 0.0, "max_error": 0.0}  # fmt: skip
    return LoadForm(**(base | kw))  # type: ignore[arg-type]


def _exact(truth: LoadForm, temps: np.ndarray) -> LoadForm:
    torque = load_form(W[None, None, :], LOADS[None, :, None], temps[:, None, None], truth)
    return fit_load_form(W, LOADS, temps, torque)


def test_two_temperatures_give_the_slopes_one_gives_none() -> None:
    # Two temperatures are enough for a line through ln c0 and ln b: the exact k's back
    # (rounding only, 1e-8). One temperature: no slope, k = 0, not a placeholder.
    truth = _form(k_c=0.004, k_b=0.025)
    two = _exact(truth, np.array([20.0, 40.0]))
    assert two.k_c == pytest.approx(0.004, rel=1e-8) and two.k_b == pytest.approx(0.025, rel=1e-8)
    one = _exact(truth, np.array([30.0]))
    assert one.k_c == 0.0 and one.k_b == 0.0
    # At 30 degC alone the fit is the form there: c0 e^(-0.004*10), b e^(-0.025*10).
    assert one.c0 == pytest.approx(0.3 * math.exp(-0.04), rel=1e-9)
    assert one.b == pytest.approx(2e-4 * math.exp(-0.25), rel=1e-9, abs=0.0)


def test_a_coefficient_of_zero_has_no_slope() -> None:
    # No viscous term at either temperature: b = 0 exactly and k_b = 0 (ln 0 is not taken).
    fit = _exact(_form(b=0.0, k_c=0.01), np.array([20.0, 40.0]))
    assert fit.b == 0.0 and fit.k_b == 0.0
    assert fit.k_c == pytest.approx(0.01, rel=1e-8)


def test_a_value_just_above_1e_9_of_the_largest_keeps_its_slope() -> None:
    # c0 falls to 1.05e-9 of its value over 20 K: k_c = -ln(1.05e-9)/20 = 1.0337 1/K. The
    # rule zeroes the slope only at or below 1e-9 of the largest c0, so this one is kept.
    # c0 at 40 degC is 3.2e-10 N*m, 1e3 times the map's rounding there (1e-12 of ~0.2 N*m).
    k = -math.log(1.05e-9) / 20.0
    fit = _exact(_form(k_c=k), np.array([20.0, 40.0]))
    assert fit.k_c == pytest.approx(k, rel=1e-6)
    # 0.95e-9 of it: the slope is not trusted, k_c = 0 and c0 is the first temperature's.
    low = _exact(_form(k_c=-math.log(0.95e-9) / 20.0), np.array([20.0, 40.0]))
    assert low.k_c == 0.0 and low.c0 == pytest.approx(0.3, rel=1e-9)


def test_a_direction_term_just_above_the_maps_rounding_is_kept() -> None:
    # One temperature, no viscous term: the largest torque is c0 + (c1 + |c2|) 3000 N. A c2
    # whose largest torque, |c2| 3000 N, is 1.05e-12 of that stays (recovered to 1e-4 of
    # itself: the fit's rounding is ~1e-16 of the torque); 0.95e-12 of it is printed as 0.
    c0, c1, f = 0.3, 4e-5, 3000.0
    for share, kept in ((1.05e-12, True), (0.95e-12, False)):
        c2 = share * (c0 + c1 * f) / (f * (1.0 - share))  # |c2| f = share * largest torque
        fit = _exact(_form(c2=c2, b=0.0), np.array([20.0]))
        if kept:
            assert fit.c2 == pytest.approx(c2, rel=1e-3, abs=0.0)
        else:
            assert fit.c2 == 0.0


def _no_model(*args: Any, **kwargs: Any) -> Any:
    raise LookupError("the model was reached")


def test_the_map_size_limit_and_its_estimate(monkeypatch: pytest.MonkeyPatch) -> None:
    # 1000 speeds both ways x 520 loads x 1 temperature = 1 040 000 points > 1 000 000:
    # about 1.04e6 * 1.6 kB = 1.66 GB and 1.04e6 * 15 us = 15.6 s = 0.26 min.
    with pytest.raises(BallScrewInputError) as err:
        friction_map(CASE, "catalog", speeds=np.arange(1.0, 1001.0), loads=np.arange(520.0),
                     temperatures=[40.0])  # fmt: skip
    text = str(err.value)
    assert "1,040,000 (1000 speeds both ways x 520 loads x 1 temperatures)" in text
    assert "at most 1,000,000 (about 1.66 GB and 0.26 min" in text
    # Exactly 1 000 000 points is allowed: the map goes on to the model.
    monkeypatch.setattr(fm, "friction_torque", _no_model)
    with pytest.raises(LookupError):
        friction_map(CASE, "catalog", speeds=np.arange(1.0, 1001.0), loads=np.arange(500.0),
                     temperatures=[40.0])  # fmt: skip


def test_two_speeds_are_enough() -> None:
    m = friction_map(CASE, "catalog", speeds=[0.0, 1.0, 2.0], loads=[0.0], temperatures=[40.0])
    np.testing.assert_array_equal(m.speeds, [-2.0, -1.0, 1.0, 2.0])


def _form_as_model(truth: LoadForm) -> Any:
    """A stand-in for the model whose torque is the compact form's (unsigned, as r.total)."""

    def model(*args: Any, speed: Any, temperature: Any, axial_load: Any, **kw: Any) -> Any:
        return SimpleNamespace(total=np.sign(speed) * load_form(speed, axial_load, temperature,
                                                                truth))  # fmt: skip

    return model


def test_a_power_flow_asymmetry_is_told_as_its_share(monkeypatch: pytest.MonkeyPatch) -> None:
    # c2 = 3e-5 N*m/N at |F| = 1 kN: driving and back-driving differ by 2 c2 |F| = 0.06 N*m,
    # out of the largest torque c0 + (c1 + c2) 1 kN = 0.33 N*m: 0.18 of it (no viscous term).
    truth = _form(c0=0.2, c1=1e-4, c2=3e-5, b=0.0)
    monkeypatch.setattr(fm, "friction_torque", _form_as_model(truth))
    m = friction_map(CASE, "catalog", speeds=SPEEDS, loads=[-1000.0, 0.0, 1000.0],
                     temperatures=[40.0])  # fmt: skip
    assert any("agrees to 1.8e-01 of its largest value" in n for n in m.notes), m.notes
    assert m.form.c2 == pytest.approx(3e-5, rel=1e-9)


def test_the_note_of_a_coefficient_at_zero(monkeypatch: pytest.MonkeyPatch) -> None:
    temps = [20.0, 40.0]
    note = "a coefficient reached 0"
    # No viscous term (k_b = 0), c0 with a slope: the note. No Coulomb term either way round.
    for truth in (_form(b=0.0, k_c=0.01), _form(c0=0.0, k_b=0.02)):
        monkeypatch.setattr(fm, "friction_torque", _form_as_model(truth))
        m = friction_map(CASE, "catalog", speeds=SPEEDS, loads=LOADS, temperatures=temps)
        assert any(note in n for n in m.notes), truth
    # Both with a slope: no note; one temperature, where k = 0 by definition: no note.
    monkeypatch.setattr(fm, "friction_torque", _form_as_model(_form(k_c=0.01, k_b=0.02)))
    m = friction_map(CASE, "catalog", speeds=SPEEDS, loads=LOADS, temperatures=temps)
    assert not any(note in n for n in m.notes)
    m = friction_map(CASE, "catalog", speeds=SPEEDS, loads=LOADS, temperatures=[40.0])
    assert m.form.k_b == 0.0 and not any(note in n for n in m.notes)


def test_a_case_without_gear_or_incline_is_a_direct_level_axis(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # The docstring's defaults: gear ratio 1 and no incline when the case's [axis] has none.
    monkeypatch.setattr(fm, "friction_torque", _form_as_model(_form()))
    case = dataclasses.replace(CASE, axis={"moving_mass": 100.0})
    m = friction_map(case, "catalog", speeds=SPEEDS, loads=[0.0], temperatures=[40.0])
    assert m.gear_ratio == 1.0
    assert not any("inclined" in n for n in m.notes)


# ``servo.controller``: the intervals by the textbook formulas of a straight line, and the
# Stribeck fit's guards on curves written by hand.

T975 = {1: 12.706204736, 2: 4.302652730}  # Student t, 97.5 % quantile (any t table)


@pytest.mark.parametrize(
    ("speed", "torque"),
    [([1.0, 2.0, 3.0], [1.0, 1.2, 1.6]), ([1.0, 2.0, 3.0, 4.0], [1.0, 1.2, 1.6, 1.7])],
)
def test_intervals_of_a_straight_line_by_hand(speed: list[float], torque: list[float]) -> None:
    # At positive speeds T = T_c + b w is a straight line: b = Sxy/Sxx, T_c = mean T - b mean w,
    # s^2 = SSE/(n - 2), se(b) = s/sqrt(Sxx), se(T_c) = s sqrt(1/n + mean(w)^2/Sxx). The form is
    # linear, so the central differences are exact to rounding (1e-9 of the half-widths).
    from ballscrew.servo.controller import coulomb_viscous, with_intervals

    x, y = np.array(speed), np.array(torque)
    n = x.size
    sxx = float(np.sum((x - x.mean()) ** 2))
    b = float(np.sum((x - x.mean()) * (y - y.mean()))) / sxx
    tc = float(y.mean()) - b * float(x.mean())
    s = math.sqrt(float(np.sum((y - tc - b * x) ** 2)) / (n - 2))
    q = T975[n - 2]
    got = with_intervals(coulomb_viscous(x, y), x, y)
    assert got.intervals is not None
    for name, value, se in (("coulomb_torque", tc, s * math.sqrt(1 / n + x.mean() ** 2 / sxx)),
                            ("viscous_coefficient", b, s / math.sqrt(sxx))):  # fmt: skip
        lo, hi = got.intervals[name]
        assert (lo + hi) / 2 == pytest.approx(value, rel=1e-9)
        assert (hi - lo) / 2 == pytest.approx(q * se, rel=1e-6)  # t to 10 digits


def test_two_points_for_two_parameters_give_no_intervals() -> None:
    from ballscrew.servo.controller import coulomb_viscous, with_intervals

    got = with_intervals(coulomb_viscous([1.0, 2.0], [1.0, 1.2]), [1.0, 2.0], [1.0, 1.2])
    assert got.intervals == {} and "2 points for 2 parameters: no intervals" in got.notes


WS = np.concatenate([-np.geomspace(0.01, 300.0, 40)[::-1], np.geomspace(0.01, 300.0, 40)])


def test_a_stribeck_curve_read_through_zero_speed() -> None:
    # A reading at rest (torque 0 by the form's sgn) does not set the slowest speed: the
    # exact curve's parameters come back as without it (rounding of the solver, 1e-6).
    from ballscrew.servo.controller import stribeck, stribeck_torque

    true = {"coulomb_torque": 0.3, "static_torque": 0.5, "stribeck_speed": 2.0,
            "stribeck_exponent": 1.3, "viscous_coefficient": 1e-3}  # fmt: skip
    w = np.concatenate([WS, [0.0]])
    fit = stribeck(w, stribeck_torque(w, **true))
    for key, value in true.items():
        assert fit.parameters[key] == pytest.approx(value, rel=1e-6), key


@pytest.mark.parametrize(("drop", "noted"), [(0.0105, False), (0.0095, True)])
def test_the_no_drop_note_at_one_percent(drop: float, noted: bool) -> None:
    # T_s - T_c of 1.05 % of T_c is a drop; 0.95 % is told as none (the fit returns both to
    # 1e-6 of T_c, far inside the 0.05 % either side of the 1 % rule).
    from ballscrew.servo.controller import stribeck, stribeck_torque

    torque = stribeck_torque(WS, 0.3, 0.3 * (1.0 + drop), 2.0, 1.3, 1e-3)
    fit = stribeck(WS, torque)
    assert fit.parameters["static_torque"] - fit.parameters["coulomb_torque"] == pytest.approx(
        0.3 * drop, rel=1e-3
    )
    assert any("no Stribeck drop" in n for n in fit.notes) is noted


def test_intervals_of_an_exact_line_with_a_reading_at_rest() -> None:
    # T = 1 + 0.5 w read at 1, 2, 3 rad/s and 0 at rest (the form's sgn 0 = 0): the fit is
    # exact, every residual 0, so each interval has zero width and sits on its value.
    from ballscrew.servo.controller import coulomb_viscous, with_intervals

    # At 1, 2, 4 rad/s (1.5, 2, 3 N*m) every number is exact in binary: a covariance of 0,
    # still an interval (of zero width), not a parameter "at its bound".
    for w, t in (([0.0, 1.0, 2.0, 3.0], [0.0, 1.5, 2.0, 2.5]), ([1.0, 2.0, 4.0], [1.5, 2.0, 3.0])):
        got = with_intervals(coulomb_viscous(w, t), w, t)
        assert got.intervals is not None and not got.notes
        for name, value in (("coulomb_torque", 1.0), ("viscous_coefficient", 0.5)):
            lo, hi = got.intervals[name]
            assert lo == pytest.approx(value, rel=1e-12) and hi == pytest.approx(value, rel=1e-12)


def test_a_parameter_at_its_bound_gets_no_interval() -> None:
    # A torque that falls with speed: b stops at its bound 0 (an unbounded fit would give
    # b < 0), so b has no interval and says why; T_c has one.
    from ballscrew.servo.controller import coulomb_viscous, with_intervals

    w = np.array([1.0, 2.0, 3.0, 4.0])
    t = 0.5 - 1e-3 * w
    got = with_intervals(coulomb_viscous(w, t), w, t)
    assert got.parameters["viscous_coefficient"] == 0.0
    assert got.intervals is not None and set(got.intervals) == {"coulomb_torque"}
    assert "viscous_coefficient sits at its bound 0: no interval" in got.notes


def test_every_parameter_through_a_gear_of_2_by_hand() -> None:
    # Motor turns per screw turn i = 2: a torque halves, a speed doubles, an exponent stays,
    # a torque per speed or per angle is divided by i^2 = 4 (the gear's losses left out).
    from ballscrew.servo.controller import FrictionForm

    p = {"coulomb_torque": 0.3, "static_torque": 0.5, "stribeck_speed": 2.0,
         "stribeck_exponent": 1.3, "viscous_coefficient": 1e-3, "bristle_stiffness": 40.0,
         "bristle_damping": 0.8}  # fmt: skip
    motor = FrictionForm("lugre", p, 0.0, 0.0).as_drive_dict(gear_ratio=2.0)["motor_side"]
    expected = {"coulomb_torque": 0.15, "static_torque": 0.25, "stribeck_speed": 4.0,
                "stribeck_exponent": 1.3, "viscous_coefficient": 2.5e-4,
                "bristle_stiffness": 10.0, "bristle_damping": 0.2}  # fmt: skip
    assert {k: v["value"] for k, v in motor.items()} == pytest.approx(expected, rel=1e-15)
