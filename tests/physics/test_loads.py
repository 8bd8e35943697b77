"""Tests of ballscrew.loads: preload split and normal load per ball."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scipy import optimize

from ballscrew import BallScrewInputError, reference_screw
from ballscrew.loads import LIFT_OFF_RATIO, ball_loads, preload_split


def _split_by_brent(fa: float, fpr: float) -> tuple[float, float]:
    """Independent scalar solution of the Hertzian preload split with scipy's brentq."""
    if fa >= LIFT_OFF_RATIO * fpr:
        return fa, 0.0
    s = optimize.brentq(lambda s: (1 + s) ** 1.5 - (1 - s) ** 1.5 - fa / fpr, 0.0, 1.0, xtol=1e-15)
    return fpr * (1 + s) ** 1.5, fpr * (1 - s) ** 1.5


def test_split_matches_independent_scalar_root_finder() -> None:
    ratios = np.array([0.0, 1e-6, 0.01, 0.3, 1.0, 2.0, 2.8, 2.828, 2.9, 10.0])
    fpr = 1500.0
    f1, f2 = preload_split(ratios * fpr, fpr)
    for r, a, b in zip(ratios, f1, f2, strict=True):
        ra, rb = _split_by_brent(r * fpr, fpr)
        # brentq to 1e-15 in s; 1e-9 N absolute covers both solvers' rounding.
        assert a == pytest.approx(ra, abs=1e-9)
        assert b == pytest.approx(rb, abs=1e-9)


def test_split_conserves_force_and_deflection() -> None:
    fa = np.linspace(-4000.0, 4000.0, 801)
    f1, f2 = preload_split(fa, 1000.0)
    # Force balance holds exactly (by construction of the relieved force).
    np.testing.assert_allclose(f1 - f2, np.abs(fa), rtol=0, atol=1e-9)
    # Hertz compatibility while both are loaded: delta_1 + delta_2 = 2 delta_0,
    # i.e. (F1/Fpr)^(2/3) + (F2/Fpr)^(2/3) = 2, independent of the stiffness.
    both = f2 > 0
    np.testing.assert_allclose(
        (f1[both] / 1000) ** (2 / 3) + (f2[both] / 1000) ** (2 / 3), 2.0, rtol=1e-12
    )
    assert np.all(f1 >= 1000.0 - 1e-9) and np.all(f2 >= 0)


def test_small_load_limit_and_lift_off() -> None:
    # Linearised Hertz: F1 ~ Fpr + Fa/2 for Fa << Fpr (error O((Fa/Fpr)^2)).
    f1, f2 = preload_split(10.0, 1000.0)
    assert float(f1) == pytest.approx(1005.0, rel=1e-5)
    assert float(f2) == pytest.approx(995.0, rel=1e-5)
    # Lift-off at 2^(3/2) Fpr: just below, family 2 is still (barely) loaded.
    f1, f2 = preload_split([0.999 * LIFT_OFF_RATIO * 1000, LIFT_OFF_RATIO * 1000], 1000.0)
    assert f2[0] > 0 and f2[1] == 0.0
    assert LIFT_OFF_RATIO == pytest.approx(2.828427, rel=1e-6)


def test_split_is_monotonic_in_load() -> None:
    fa = np.linspace(0.0, 5000.0, 1001)
    f1, f2 = preload_split(fa, 1000.0)
    assert np.all(np.diff(f1) > 0)
    assert np.all(np.diff(f2) <= 0)


def test_ball_loads_double_nut_by_hand() -> None:
    s = reference_screw()
    loads = ball_loads(s)
    q_ref = 2000.0 / (98 * math.sin(math.pi / 4) * math.cos(s.lead_angle))  # 28.953 N
    assert float(loads.normal_load_1) == pytest.approx(q_ref, rel=1e-12)
    assert float(loads.normal_load_2) == pytest.approx(q_ref, rel=1e-12)
    assert loads.balls_1 == loads.balls_2 == 98
    assert not loads.lifted_off


def test_ball_loads_sign_symmetry_and_lift_off_flag() -> None:
    s = reference_screw()
    plus = ball_loads(s, [1000.0, 7000.0])
    minus = ball_loads(s, [-1000.0, -7000.0])
    np.testing.assert_array_equal(plus.normal_load_1, minus.normal_load_1)
    assert list(plus.lifted_off) == [False, True]
    assert plus.normal_load_2[1] == 0.0


def test_single_nut_carries_load_on_one_flank() -> None:
    s = reference_screw().replace(nut="single", preload=0.0)
    loads = ball_loads(s, [0.0, 500.0, -500.0])
    per_ball = 500.0 / (98 * math.sin(math.pi / 4) * math.cos(s.lead_angle))
    np.testing.assert_allclose(loads.normal_load_1, [0.0, per_ball, per_ball], rtol=1e-12)
    np.testing.assert_array_equal(loads.normal_load_2, 0.0)
    assert loads.balls_2 == 0


def test_four_point_nut_splits_like_double_nut_on_the_same_balls() -> None:
    double = ball_loads(reference_screw(), 1500.0)
    four = ball_loads(reference_screw().replace(nut="single-4point"), 1500.0)
    np.testing.assert_allclose(four.normal_load_1, double.normal_load_1, rtol=1e-15)
    np.testing.assert_allclose(four.normal_load_2, double.normal_load_2, rtol=1e-15)


@pytest.mark.parametrize("bad", [float("nan"), float("inf"), "1 kN"])
def test_bad_axial_load(bad: object) -> None:
    with pytest.raises(BallScrewInputError, match="axial_load"):
        ball_loads(reference_screw(), bad)  # type: ignore[arg-type]


def test_negative_preload_in_split() -> None:
    with pytest.raises(BallScrewInputError, match="preload"):
        preload_split(10.0, -1.0)
