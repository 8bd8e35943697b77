"""Pins of servo/'s fits from their mutation runs (issue 49), each against a number by hand.

``servo.friction_map``: the load map's fit is run on exact data of the compact form (a
linear least-squares fit of exact data returns its coefficients to rounding), and the
map's guards on grids whose point counts are multiplied out by hand. Where the map's
model would be slow or its output unknown, the model is replaced by the compact form
itself, so every coefficient of the map is known.
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
