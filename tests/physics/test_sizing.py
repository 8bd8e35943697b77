"""Sizing formulas (life, static safety, buckling, thermal error, motor) against hand numbers."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.design.sizing import (
    BUCKLING_FACTORS,
    RELIABILITY_FACTORS,
    RELIABILITY_FACTORS_ISO_281,
    TRAVEL_VARIATION_300,
    buckling_load,
    combined_life,
    cubic_mean_load,
    nominal_life,
    preloaded_loads,
    reflected_inertia,
    static_safety,
    thermal_elongation,
)
from ballscrew.errors import BallScrewInputError
from ballscrew.loads import preload_split

# The catalogues' buckling rule P = m d_r^4 / L^2 * 1e4 N (mm), safety 0.5 included:
# HSK (b2b-linearbearing.com, "Screw Shaft Design") and THK (A15-30, eq. 5) print
# m = 1.3, 5.1, 10.2, 20.3 for N (our eta) = 1/4, 1, 2, 4.
CATALOGUE_BUCKLING = {
    "fixed-free": 1.3,
    "supported-supported": 5.1,
    "fixed-supported": 10.2,
    "fixed-fixed": 20.3,
}


@pytest.mark.parametrize(("support", "m"), list(CATALOGUE_BUCKLING.items()))
def test_buckling_load_is_the_catalogue_rule(support: str, m: float) -> None:
    d_mm, length_mm = 33.5, 1200.0
    catalogue = m * d_mm**4 / length_mm**2 * 1e4
    ours = float(buckling_load(d_mm / 1e3, length_mm / 1e3, support))
    # Euler with E = 206 GPa and s = 0.5 gives m = 1.2475 * eta * 4 ... i.e. 1.25, 4.99,
    # 9.98, 19.96: the printed factors are 2.2 % higher (1.275 per unit of eta, E read as
    # 2.1e4 kgf/mm^2 ~ 206 GPa and rounded up); fixed-free 1.25 is printed 1.3 (4 %).
    assert ours == pytest.approx(catalogue, rel=0.045)
    assert ours < catalogue  # the package is on the safe side of the printed rule


def test_buckling_hand_value() -> None:
    # d_r = 20 mm, L = 0.8 m, fixed-supported: I = pi 0.02^4/64 = 7.854e-9 m^4,
    # P = 0.5 * 2 * pi^2 * 206e9 * 7.854e-9 / 0.64 = 24.95 kN.
    assert float(buckling_load(0.02, 0.8)) == pytest.approx(24_951, rel=1e-3)
    assert BUCKLING_FACTORS["fixed-fixed"] == 4 * BUCKLING_FACTORS["supported-supported"]
    with pytest.raises(BallScrewInputError, match="support"):
        buckling_load(0.02, 0.8, "glued")


def test_cubic_mean_load_and_life_by_hand() -> None:
    # A three-phase spectrum (acceleration, feed, deceleration) as the catalogues set it:
    # 1.2 kN over 20 turns, 0.2 kN over 160, 0.8 kN over 20 (hand value below).
    # By hand: 1200^3 20 + 200^3 160 + 800^3 20 = 3.456e10 + 1.28e9 + 1.024e10 = 4.608e10;
    # over 200 turns 2.304e8 N^3, whose cube root is 613.048 N (the load's sign does not count).
    fm = float(cubic_mean_load([1200.0, -200.0, 800.0], [20.0, 160.0, 20.0]))
    assert fm == pytest.approx(613.048, abs=5e-4)
    # L10 = (Ca / Fm)^3 1e6: Ca = 18.4 kN (HIWIN R32-05K4): 30.014^3 1e6 = 2.7038e10 turns.
    life = float(nominal_life(18_400.0, fm))
    assert life == pytest.approx(2.7038e10, rel=1e-4)


def test_cubic_mean_load_broadcasts_over_its_last_axis() -> None:
    # Two spectra in one call, one per row, the turns shared: the catalogues' three phases
    # (2000 N over 100 turns, 1000 N over 800, 3000 N over 100: ((8 + 8 + 27) 1e11 / 1000)
    # ^(1/3) = 1626.13 N) and a constant 500 N, whose cubic mean is 500 N itself.
    loads = np.array([[2000.0, 1000.0, 3000.0], [500.0, 500.0, 500.0]])
    fm = cubic_mean_load(loads, [100.0, 800.0, 100.0])
    assert fm.shape == (2,)
    np.testing.assert_allclose(fm, [1626.13, 500.0], atol=5e-3)
    # One load spectrum over two duty patterns: all turns at 2000 N, then all at 3000 N.
    fm = cubic_mean_load([2000.0, 1000.0, 3000.0], [[1.0, 0.0, 0.0], [0.0, 0.0, 7.0]])
    np.testing.assert_allclose(fm, [2000.0, 3000.0], rtol=1e-12)
    # Only shares of turns count, also below one turn: 100 N and 200 N over a quarter turn
    # each, ((1e6 + 8e6) / 2)^(1/3) = 165.096 N.
    assert float(cubic_mean_load([100.0, 200.0], [0.25, 0.25])) == pytest.approx(165.096, abs=1e-3)


def test_cubic_mean_load_without_turns_is_refused() -> None:
    with pytest.raises(BallScrewInputError, match="revolutions"):
        cubic_mean_load([1000.0, 2000.0], [0.0, 0.0])
    # One spectrum of two without turns is refused too, not returned as NaN.
    with pytest.raises(BallScrewInputError, match="revolutions"):
        cubic_mean_load([1000.0, 2000.0], [[1.0, 1.0], [0.0, 0.0]])


# The reliability factor a1 as printed, by reliability: ISO 3408-5:2006, 7.2.4 (f_ar), the
# values of ISO 281:1990; and ISO 281:2007, Table 12, for the rolling bearings. Both are
# closed forms rounded to two digits: the Weibull law a1 = (ln R / ln 0.9)^(2/3) (slope 3/2)
# and ISO 281:2007's 0.95 (ln R / ln 0.9)^(2/3) + 0.05 (e.g. R = 0.97: 0.4372 -> 0.44 and
# 0.4654 -> 0.47).
PRINTED_A1 = [
    (0.90, 1.0, 1.0),
    (0.95, 0.62, 0.64),
    (0.96, 0.53, 0.55),
    (0.97, 0.44, 0.47),
    (0.98, 0.33, 0.37),
    (0.99, 0.21, 0.25),
]


@pytest.mark.parametrize(("reliability", "a1", "a1_bearings"), PRINTED_A1)
def test_reliability_factors_are_the_printed_ones(
    reliability: float, a1: float, a1_bearings: float
) -> None:
    assert RELIABILITY_FACTORS[reliability] == a1
    assert RELIABILITY_FACTORS_ISO_281[reliability] == a1_bearings
    # The life applies it: Ca / Fm = 10, 1e9 revolutions at 90 %.
    assert float(nominal_life(1e4, 1e3, reliability)) == pytest.approx(a1 * 1e9, rel=1e-12)
    # Each printed value is its closed form rounded (half a unit of the second decimal).
    weibull = (math.log(reliability) / math.log(0.9)) ** (2 / 3)
    assert RELIABILITY_FACTORS[reliability] == pytest.approx(weibull, abs=0.005)
    assert RELIABILITY_FACTORS_ISO_281[reliability] == pytest.approx(
        0.95 * weibull + 0.05, abs=0.005
    )


def test_reliability_factors_are_iso_3408_5() -> None:
    assert sorted(RELIABILITY_FACTORS) == [r for r, _, _ in PRINTED_A1]
    assert sorted(RELIABILITY_FACTORS_ISO_281) == [r for r, _, _ in PRINTED_A1]
    with pytest.raises(BallScrewInputError, match="reliability"):
        nominal_life(1e4, 1e3, 0.93)
    # A reliability between two rows is not rounded onto one of them.
    with pytest.raises(BallScrewInputError, match="reliability"):
        nominal_life(1e4, 1e3, 0.951)
    assert float(nominal_life(1e4, 1e3, 0.95 + 1e-12)) == pytest.approx(0.62e9, rel=1e-12)
    assert math.isinf(float(nominal_life(1e4, 0.0)))
    # A light mean load is a long life, not an infinite one: (1e4 / 0.5)^3 1e6 = 8e18.
    assert float(nominal_life(1e4, 0.5)) == pytest.approx(8e18, rel=1e-12)


def test_preloaded_loads_follow_the_exact_hertz_split() -> None:
    fpr = 1000.0
    fa = np.linspace(0.0, 2.0**1.5 * fpr, 41)
    f1, f2 = preloaded_loads(fa, fpr)
    e1, _ = preload_split(fa, fpr)
    np.testing.assert_allclose(f1 - f2, fa, rtol=1e-12, atol=1e-9)
    # ISO's closed form against the exact Hertz split: within 2.5 % of the loaded half
    # (2.48 % at worst).
    np.testing.assert_allclose(f1, e1, rtol=0.025)
    assert f1[0] == pytest.approx(fpr) and f2[-1] == pytest.approx(0.0, abs=1e-9)
    big1, big2 = preloaded_loads(5000.0, fpr)
    assert (float(big1), float(big2)) == (5000.0, 0.0)
    single1, single2 = preloaded_loads(-700.0, 0.0)
    assert (float(single1), float(single2)) == (700.0, 0.0)


def test_preloaded_loads_depend_only_on_the_ratio() -> None:
    # The split has no scale of its own: F1 / F_pr is a function of |F_a| / F_pr. At a ratio
    # of 1, 1 + 1 / 2^1.5 = 1.353553 and 1.353553^1.5 = 1.574755, at any size of preload,
    # also a fraction of a newton (ISO 3408-5's form; 1575 N at 1 kN in the docstring).
    for preload in (0.1, 1000.0, 1e5):
        f1, f2 = preloaded_loads(preload, preload)
        assert float(f1) == pytest.approx(1.574755 * preload, rel=1e-6)
        assert float(f2) == pytest.approx(0.574755 * preload, rel=2e-6)


def test_combined_life_of_two_halves() -> None:
    assert float(combined_life(1e9, 1e9)) == pytest.approx(2 ** (-0.9) * 1e9)
    assert float(combined_life(1e9, math.inf)) == pytest.approx(1e9)


def test_static_safety() -> None:
    assert float(static_safety(59_600.0, 2_980.0)) == pytest.approx(20.0)
    assert math.isinf(float(static_safety(59_600.0, 0.0)))
    # Below one newton the factor is still the ratio: 59.6 kN / 0.5 N = 119 200.
    assert float(static_safety(59_600.0, -0.5)) == pytest.approx(119_200.0, rel=1e-12)


def test_thermal_elongation_and_grades() -> None:
    # 11.5e-6 / K * 2 K * 300 mm = 6.9 um, above grade P1's 6 um, below P3's 12 um.
    d = float(thermal_elongation(2.0, 0.3))
    assert d == pytest.approx(6.9e-6)
    assert TRAVEL_VARIATION_300["P1"] < d < TRAVEL_VARIATION_300["P3"]
    assert TRAVEL_VARIATION_300["P3"] == 12e-6  # Steinmeyer, lead error over 300 mm


def test_reflected_inertia_is_the_kinetic_energy() -> None:
    # The inertia the motor sees stores the axis's kinetic energy: 150 kg at 0.5 m/s on a
    # 5 mm lead turn the screw (J_s + J_c = 2.1e-4 kg m^2) at 2 pi 0.5 / 0.005 = 628.32 rad/s;
    # E = 150 * 0.25 / 2 + 2.1e-4 * 628.32^2 / 2 = 18.75 + 41.4523 = 60.2023 J, so
    # J = 2 E / omega^2 = 3.04989e-4 kg m^2.
    j = reflected_inertia(150.0, 0.005, 2e-4, 1e-5)
    assert j == pytest.approx(3.04989e-4, rel=2e-6)
    # A 1:2 belt (i = 2) turns the motor at 1256.6 rad/s for the same 60.2023 J:
    # 2 * 60.2023 / 1256.64^2 = 7.6247e-5 kg m^2, a quarter.
    assert reflected_inertia(150.0, 0.005, 2e-4, 1e-5, 2.0) == pytest.approx(7.6247e-5, rel=2e-5)


def test_misumi_worked_examples() -> None:
    # MISUMI, Economy Series e-catalog 2025, "Selection of Ball Screws", technical data
    # (th.c.misumi-ec.com/book/THA_EconomySeries_e-catalog2025, pages 1676 and 1678).
    # Life: BSS1520 (C = 4400 N), mean axial load 250 N, work factor fw = 1.2, mean speed
    # 2118 rpm: Lh = 1e6 / (60 * 2118) * (4400 / (250 * 1.2))^3 = 24824 h as printed.
    from ballscrew.design.sizing import life_hours

    hours = float(life_hours(nominal_life(4400.0, 250.0 * 1.2), 2118.0))
    assert hours == pytest.approx(24_824, rel=2e-4)  # 24 826.6: the print rounds (4400/300)^3
    # Allowable axial load: root 12.5 mm, fixed-support, 820 mm between the points of
    # buckling: P = m d^4 / l^2 1e4 with m = 10, 3630 N as printed. Euler with E = 206 GPa
    # and the safety 0.5 gives m = 9.98: 3623 N, 0.2 % below.
    p = float(buckling_load(12.5e-3, 0.820, "fixed-supported"))
    assert p == pytest.approx(3630.0, rel=3e-3)
    assert p < 3630.0


# Travel variation over 300 mm as printed, in um. THK General Catalog (English), "Accuracy
# of the Ball Screw", p. A-678: Table 2 (fluctuation/300 of C0 to C5) and Table 1 (travel
# distance error per 300 mm of the rolled grades C7, C8, C10). HIWIN, "Ballscrews &
# Accessories" BS-08-2-EN-1704-K, Table 3.3, p. 15 (v300p of the DIN ISO 3408 classes
# 0, 1, 3, 5, 7, 10). Printed integers or halves: exact.
PRINTED_V300_UM = {
    "C0": 3.5, "C1": 5, "C2": 7, "C3": 8, "C5": 18, "C7": 50, "C8": 100, "C10": 210,
    "P0": 3.5, "P1": 6, "P3": 12, "P5": 23, "T5": 23, "T7": 52, "T10": 210,
}  # fmt: skip


@pytest.mark.parametrize(("grade", "microns"), list(PRINTED_V300_UM.items()))
def test_grade_table_is_the_printed_one(grade: str, microns: float) -> None:
    assert TRAVEL_VARIATION_300[grade] == pytest.approx(microns * 1e-6, rel=1e-12)


def test_grade_table_has_no_unprinted_entry() -> None:
    assert set(TRAVEL_VARIATION_300) == set(PRINTED_V300_UM)
