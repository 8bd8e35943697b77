"""Tests of ballscrew.rheology: shear stress laws."""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew import BallScrewInputError
from ballscrew.rheology import (
    bair_winer_1979,
    eyring_1936,
    general_non_newtonian,
    harmonic_combination,
    limiting_shear_stress,
    newtonian,
)

RATES = np.concatenate([-np.geomspace(1e9, 1e-3, 60), [0.0], np.geomspace(1e-3, 1e9, 60)])
ETA, TAU_LIM = 0.5, 40e6


def test_harmonic_is_general_with_n_1_and_matches_closed_form() -> None:
    tn = ETA * RATES
    closed = tn * TAU_LIM / (np.abs(tn) + TAU_LIM)
    np.testing.assert_allclose(harmonic_combination(ETA, RATES, TAU_LIM), closed, rtol=1e-14)
    np.testing.assert_array_equal(
        general_non_newtonian(ETA, RATES, TAU_LIM, 1.0), harmonic_combination(ETA, RATES, TAU_LIM)
    )


@pytest.mark.parametrize("law", ["general1", "general3", "eyring", "bair_winer"])
def test_laws_are_odd_newtonian_at_low_shear_and_monotonic(law: str) -> None:
    def tau(rate: np.ndarray) -> np.ndarray:
        if law == "general1":
            return general_non_newtonian(ETA, rate, TAU_LIM, 1.0)
        if law == "general3":
            return general_non_newtonian(ETA, rate, TAU_LIM, 3.0)
        if law == "eyring":
            return eyring_1936(ETA, rate, 5e6)
        return bair_winer_1979(ETA, rate, TAU_LIM)

    t = tau(RATES)
    np.testing.assert_allclose(t, -t[::-1], rtol=1e-14)
    assert np.all(np.diff(t) > 0)
    low = 1e-3  # tau_N / tau_lim = 1.25e-11: Newtonian to 1e-10
    assert float(tau(np.array(low))) == pytest.approx(ETA * low, rel=1e-10)
    assert float(tau(np.array(0.0))) == 0.0


def test_limiting_laws_saturate_and_stay_below_both_limits() -> None:
    for t in (
        general_non_newtonian(ETA, RATES, TAU_LIM, 1.0),
        general_non_newtonian(ETA, RATES, TAU_LIM, 2.5),
        bair_winer_1979(ETA, RATES, TAU_LIM),
    ):
        assert np.all(np.abs(t) <= np.minimum(np.abs(ETA * RATES), TAU_LIM) * (1 + 1e-15))
    # Far above the transition (tau_N / tau_lim = 1.25e7) all reach tau_lim.
    huge = np.array(1e15)
    for law in (harmonic_combination, bair_winer_1979):
        assert float(law(ETA, huge, TAU_LIM)) == pytest.approx(TAU_LIM, rel=1e-6)


def test_general_model_tends_to_visco_plastic_for_large_n() -> None:
    t = general_non_newtonian(ETA, RATES, TAU_LIM, 200.0)
    ideal = np.sign(RATES) * np.minimum(np.abs(ETA * RATES), TAU_LIM)
    # Largest gap at tau_N = tau_lim: factor 2^(-1/200) = 0.99654.
    np.testing.assert_allclose(t, ideal, rtol=3.5e-3)


def test_general_model_no_overflow_warning_at_huge_shear() -> None:
    assert float(general_non_newtonian(1e6, 1e12, 1e6, 50.0)) == pytest.approx(1e6)


def test_eyring_grows_without_bound() -> None:
    assert float(eyring_1936(ETA, 1e12, 5e6)) > 5 * 5e6


def test_newtonian_and_limiting_stress() -> None:
    assert float(newtonian(0.1, -2e5)) == pytest.approx(-2e4)
    np.testing.assert_allclose(limiting_shear_stress([0.0, 1e9], 2e6, 0.07), [2e6, 72e6])


@pytest.mark.parametrize(
    "bad",
    [{"limiting_stress": 0.0}, {"n": -1.0}, {"viscosity": -1.0}, {"shear_rate": float("nan")}],
)
def test_bad_input(bad: dict[str, float]) -> None:
    args = {"viscosity": 1.0, "shear_rate": 1.0, "limiting_stress": 1.0, "n": 1.0}
    args.update(bad)
    with pytest.raises(BallScrewInputError, match=next(iter(bad))):
        general_non_newtonian(**args)
