"""Tests of ballscrew.lubricant and the bundled library ballscrew.lubricants."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew import BallScrewInputError, Lubricant, lubricants
from ballscrew.lubricant import (
    astm_d341_constants,
    astm_d341_viscosity,
    barus_1893,
    density_linear,
    pressure_viscosity_jungnickel,
    roelands_1966,
    roelands_alpha,
    roelands_z,
    vogel_constants,
    vogel_viscosity,
)

TEMPS = np.array([20.0, 25.0, 30.0, 35.0, 40.0, 45.0])


@pytest.mark.parametrize(
    ("nu40", "nu100", "a_ref", "b_ref", "table"),
    [
        # shared/reference/equations.md §5.1, Walther fits worked independently
        # there (A, B to 4 decimals; viscosities to 0.1 mm²/s).
        (68.0, 10.3, 8.3444, 3.2376, [187.5, 141.7, 109.1, 85.4, 68.0, 54.9]),
        (68.0, 10.0, 8.5096, 3.3038, [191.8, 144.0, 110.2, 85.9, 68.0, 54.7]),
        (68.0, 8.6, 9.3778, 3.6517, [216.9, 156.9, 116.3, 88.0, 68.0, 53.5]),
        (50.0, 7.5, 9.1114, 3.5579, [142.6, 106.5, 81.3, 63.2, 50.0, 40.2]),
        (60.0, 8.5, 9.0112, 3.5099, [176.3, 130.7, 98.9, 76.4, 60.0, 47.9]),
    ],
)
def test_walther_against_reference_table(
    nu40: float, nu100: float, a_ref: float, b_ref: float, table: list[float]
) -> None:
    a, b = astm_d341_constants(nu40 * 1e-6, 40.0, nu100 * 1e-6, 100.0)
    # The table rounds A and B to 4 decimals: half a unit is 5e-5.
    assert float(a) == pytest.approx(a_ref, abs=5e-5)
    assert float(b) == pytest.approx(b_ref, abs=5e-5)
    nu = astm_d341_viscosity(TEMPS, a, b) * 1e6
    # 0.1 mm²/s rounding of the table: 0.05 plus float noise.
    np.testing.assert_allclose(nu, table, atol=0.051)


def test_astm_d341_worked_example() -> None:
    # A viscosity-temperature calculator citing ASTM D341 (research notes):
    # 32 mm²/s at 40 °C and 5.4 mm²/s at 100 °C give 8.5 mm²/s at 80 °C (printed
    # to 2 figures, with T = °C + 273: A = 9.5259, B = 3.7449). With 273.15, an
    # independent implementation (the `tribology` package's walther()) gives
    # 8.533214691536 mm²/s; the kelvin offset moves A and B but the
    # interpolated viscosity only by 1e-5 relative.
    a, b = astm_d341_constants(32e-6, 40.0, 5.4e-6, 100.0)
    nu80 = float(astm_d341_viscosity(80.0, a, b)) * 1e6
    assert nu80 == pytest.approx(8.5, abs=0.05)
    assert nu80 == pytest.approx(8.533214691536, rel=1e-10)
    # The calculator's printed line (T + 273, A = 9.5259, B = 3.7449) at 353 K:
    # log log(nu + 0.7) = 9.5259 - 3.7449 log10(353) = -0.01526, nu = 8.5357 mm²/s. Its A and B
    # rounded to 4 decimals move that by up to 0.0104 mm²/s (A +- 5e-5 and B -+ 5e-5 at
    # 353 K), the kelvin offset by 1e-4: the package's viscosity is within 0.011 of it.
    printed = 10 ** (10 ** (9.5259 - 3.7449 * math.log10(353.0))) - 0.7
    assert nu80 == pytest.approx(printed, abs=0.011)


def test_astm_d341_low_viscosity_form_round_trips() -> None:
    # D341-09 gives Z(nu) and an approximate inverse; their round trip is good
    # to about 2e-4 mm²/s down to 0.3 mm²/s (research notes), exact above 4.
    for nu in (0.3, 0.5, 1.0, 2.0, 5.0, 50.0):
        a, b = astm_d341_constants(nu * 1e-6, 40.0, nu * 0.5e-6 + 0.15e-6, 100.0)
        back = float(astm_d341_viscosity(40.0, a, b)) * 1e6
        assert back == pytest.approx(nu, abs=3e-4)


def test_walther_passes_through_its_points_and_falls_with_temperature() -> None:
    a, b = astm_d341_constants(68e-6, 40.0, 10.3e-6, 100.0)
    np.testing.assert_allclose(
        astm_d341_viscosity([40.0, 100.0], a, b), [68e-6, 10.3e-6], rtol=1e-12
    )
    nu = astm_d341_viscosity(np.linspace(-20, 150, 200), a, b)
    assert np.all(np.diff(nu) < 0)


def test_walther_constants_do_not_depend_on_the_temperature_scale() -> None:
    # ASTM D341 charts use kelvin or rankine; log10 T differs by a constant,
    # which shifts A only. Two points given at other temperatures must give the
    # same line: fit through (20 °C, 60 °C) points of the first line.
    a, b = astm_d341_constants(68e-6, 40.0, 10.3e-6, 100.0)
    n20, n60 = astm_d341_viscosity([20.0, 60.0], a, b)
    a2, b2 = astm_d341_constants(n20, 20.0, n60, 60.0)
    assert float(a2) == pytest.approx(float(a), rel=1e-12)
    assert float(b2) == pytest.approx(float(b), rel=1e-12)


def test_vogel_thermca_vg68_values() -> None:
    # Thermca's fluids library, mineral VG 68 (A = 0.071e-6 m²/s, B = 929 °C,
    # C = 95 °C); values from shared/reference/equations.md §5.1, 0.1 mm²/s.
    nu = vogel_viscosity([20, 25, 30, 35, 40, 45, 100], 0.071e-6, 929.0) * 1e6
    np.testing.assert_allclose(nu, [228.9, 163.5, 119.9, 90.1, 69.2, 54.1, 8.3], atol=0.051)


def test_vogel_fit_passes_through_points() -> None:
    a, b = vogel_constants(68e-6, 40.0, 10.3e-6, 100.0)
    np.testing.assert_allclose(vogel_viscosity([40.0, 100.0], a, b), [68e-6, 10.3e-6], rtol=1e-12)


def test_vogel_and_walther_agree_between_their_points() -> None:
    # Two different laws fitted through the same two points stay within a few
    # per cent between them (measured 2.1 % at 70 °C for a PAO 68).
    oil = lubricants.get("PAO ISO VG 68")
    vogel = oil.replace(viscosity_model="vogel")
    t = np.linspace(40.0, 100.0, 61)
    ratio = vogel.kinematic_viscosity(t) / oil.kinematic_viscosity(t)
    assert np.max(np.abs(ratio - 1)) < 0.03


def test_roelands_initial_slope_is_alpha_and_stays_below_barus() -> None:
    eta0, alpha = 0.05, 2e-8
    dp = 1e3
    slope = (math.log(float(roelands_1966(eta0, alpha, dp))) - math.log(eta0)) / dp
    assert slope == pytest.approx(alpha, rel=1e-4)
    p = np.linspace(1e7, 2e9, 50)
    assert np.all(roelands_1966(eta0, alpha, p) < barus_1893(eta0, alpha, p))
    assert float(roelands_1966(eta0, alpha, 0.0)) == eta0
    assert np.all(np.diff(roelands_1966(eta0, alpha, p)) > 0)


def test_roelands_closed_form_value() -> None:
    # Worked step by step (catches a wrong constant p_r = 1.96e8 Pa or
    # ln(eta_inf) = -9.67): span = ln(0.05) + 9.67 = 6.674268,
    # Z = 1.5e-8 * 1.96e8 / span = 0.440498, (1 + 1e9/1.96e8)^Z - 1 = 1.218197,
    # eta/eta0 = exp(6.674268 * 1.218197) = exp(8.130570) = 3396.7.
    assert float(roelands_1966(0.05, 1.5e-8, 1e9)) / 0.05 == pytest.approx(3396.7, rel=5e-5)


def test_roelands_across_temperature_by_hand() -> None:
    # Roelands' complete formula, ln(eta) + 9.67 = (ln eta0(T) + 9.67)(1 + p/p_r)^Z with Z
    # a constant of the oil, worked by hand for mineral ISO VG 68 (eta0 = 0.0588676 Pa·s and
    # alpha = 25 /GPa at 40 °C; eta0 = 0.190215 Pa·s at 20 °C) at 20 °C and 1 GPa:
    # span(40) = ln 0.0588676 + 9.67 = 6.837536, Z = 25e-9 * 1.96e8 / 6.837536 = 0.716632,
    # span(20) = ln 0.190215 + 9.67 = 8.010400, alpha*(20) = Z * 8.010400 / 1.96e8
    # = 2.92883e-8 /Pa; (1 + 1e9 / 1.96e8)^Z = 6.102041^0.716632 = 3.655081,
    # ln(eta) = 8.010400 * 3.655081 - 9.67 = 19.60866, eta = 3.2804e8 Pa·s.
    # Tolerances: the hand values carry 6-7 figures.
    z = roelands_z(0.0588676, 25e-9)
    assert float(z) == pytest.approx(0.716632, rel=2e-6)
    alpha20 = roelands_alpha(0.190215, z)
    assert float(alpha20) == pytest.approx(2.92883e-8, rel=2e-6)
    assert float(roelands_1966(0.190215, alpha20, 1e9)) == pytest.approx(3.2804e8, rel=5e-5)
    # The bundled oil through its own viscosity fit (0.190215 Pa·s at 20 °C to 6 figures).
    oil = lubricants.get("mineral ISO VG 68")
    assert oil.roelands_index == pytest.approx(0.716632, rel=2e-6)
    assert float(oil.pressure_viscosity_at(20.0)) == pytest.approx(2.92883e-8, rel=5e-6)
    assert float(oil.viscosity_at_pressure(20.0, 1e9)) == pytest.approx(3.2804e8, rel=1e-4)


def test_roelands_across_temperature_limits_and_direction() -> None:
    oil = lubricants.get("mineral ISO VG 68")
    t = np.array([0.0, 20.0, 40.0, 60.0, 100.0])
    # No pressure: the ambient viscosity; at 40 °C (where alpha is given): alpha itself.
    np.testing.assert_allclose(
        oil.viscosity_at_pressure(t, 0.0), oil.dynamic_viscosity(t), rtol=1e-15
    )
    assert float(oil.pressure_viscosity_at(40.0)) == pytest.approx(25e-9, rel=1e-14)
    # The initial slope d ln(eta)/dp at each temperature is alpha*(T) (difference over 1 kPa).
    slope = np.log(oil.viscosity_at_pressure(t, 1e3) / oil.dynamic_viscosity(t)) / 1e3
    np.testing.assert_allclose(slope, oil.pressure_viscosity_at(t), rtol=1e-4)
    # Z is the oil's constant: recovered from alpha*(T) and eta0(T) at every temperature.
    np.testing.assert_allclose(
        roelands_z(oil.dynamic_viscosity(t), oil.pressure_viscosity_at(t)),
        oil.roelands_index,
        rtol=1e-12,
    )
    # Colder oil: larger alpha and thicker under pressure (one alpha at every temperature
    # gave 2.1e6 Pa·s at 20 °C against 4.5e6 Pa·s at 40 °C at 1 GPa).
    assert np.all(np.diff(oil.pressure_viscosity_at(t)) < 0)
    for p in (1e8, 1e9, 2.5e9):
        assert np.all(np.diff(oil.viscosity_at_pressure(t, p)) < 0)
    assert float(oil.viscosity_at_pressure(20.0, 1e9)) > float(oil.viscosity_at_pressure(40.0, 1e9))
    # Barus keeps alpha as given: eta0(T) exp(alpha p).
    np.testing.assert_allclose(
        oil.viscosity_at_pressure(t, 1e8, model="barus"),
        oil.dynamic_viscosity(t) * math.exp(25e-9 * 1e8),
        rtol=1e-13,
    )


def test_roelands_across_temperature_broadcasts() -> None:
    oil = lubricants.get("PAO ISO VG 68")
    t = np.array([20.0, 30.0, 45.0])[:, None]
    p = np.array([0.0, 3e8, 1e9, 2e9])
    eta = oil.viscosity_at_pressure(t, p)
    assert eta.shape == (3, 4)
    for i in range(3):
        for j in range(4):
            one = oil.viscosity_at_pressure(float(t[i, 0]), float(p[j]))
            assert float(eta[i, j]) == pytest.approx(float(one), rel=1e-14)
    assert oil.pressure_viscosity_at(t).shape == (3, 1)
    assert roelands_alpha(np.full((2, 3), 0.05), np.array([0.5, 0.6, 0.7])).shape == (2, 3)


def test_roelands_across_temperature_refuses_bad_input() -> None:
    oil = lubricants.get("mineral ISO VG 68")
    with pytest.raises(BallScrewInputError, match="pressure"):
        oil.viscosity_at_pressure(20.0, -1.0)
    # Far below the pour point the viscosity fit overflows: the error names the temperature.
    with pytest.raises(BallScrewInputError, match="temperature"):
        oil.viscosity_at_pressure(-250.0, 1e9)
    with pytest.raises(BallScrewInputError, match="temperature"):
        oil.pressure_viscosity_at(-300.0)
    with pytest.raises(BallScrewInputError, match="temperature"):
        oil.viscosity_at_pressure(math.nan, 1e9)
    with pytest.raises(BallScrewInputError, match="model"):
        oil.viscosity_at_pressure(20.0, 1e9, model="doolittle")
    # At or below eta_inf = 6.31e-5 Pa·s Roelands' formula has no meaning.
    with pytest.raises(BallScrewInputError, match="viscosity"):
        roelands_z(6.3e-5, 2e-8)
    with pytest.raises(BallScrewInputError, match="viscosity"):
        roelands_alpha(6.31e-5, 0.6)
    # The bound itself: ln(eta) + 9.67 is exactly 0 at eta = exp(-9.67) = 6.315e-5 Pa·s.
    with pytest.raises(BallScrewInputError, match="viscosity"):
        roelands_z(math.exp(-9.67), 2e-8)
    # Just above it the formula holds: ln(1e-4) + 9.67 = 0.459660, Z = 3.92 / 0.459660.
    assert float(roelands_z(1e-4, 2e-8)) == pytest.approx(8.52805, rel=1e-5)
    with pytest.raises(BallScrewInputError, match="alpha"):
        roelands_z(0.05, 0.0)
    with pytest.raises(BallScrewInputError, match="z"):
        roelands_alpha(0.05, -0.5)


def test_barus_overflows_to_inf_without_warning() -> None:
    assert math.isinf(float(barus_1893(0.05, 2e-8, 1e11)))


def test_density_and_dynamic_viscosity() -> None:
    assert float(density_linear(15.0, 850.0)) == 850.0
    assert float(density_linear(115.0, 850.0)) == pytest.approx(850 * (1 - 0.065))
    oil = Lubricant.from_viscosities("test", 68e-6, 10.3e-6, 850.0, 1.5e-8)
    eta = oil.dynamic_viscosity(40.0)
    assert float(eta) == pytest.approx(68e-6 * 850 * (1 - 6.5e-4 * 25), rel=1e-12)


def test_pressure_viscosity_estimate() -> None:
    # Thermca's fit: 1.29e-7 * (68e-6)**0.204 = 1.82e-8 /Pa (equations.md §5.2).
    assert float(pressure_viscosity_jungnickel(68e-6)) == pytest.approx(1.82e-8, rel=3e-3)
    oil = Lubricant.from_viscosities("x", 68e-6, 9e-6, 870.0)
    assert oil.pressure_viscosity == pytest.approx(1.82e-8, rel=3e-3)
    assert "estimated" in oil.source


def test_viscosity_at_pressure_models() -> None:
    oil = lubricants.get("mineral ISO VG 68")
    r = oil.viscosity_at_pressure(40.0, 5e8)
    b = oil.viscosity_at_pressure(40.0, 5e8, model="barus")
    assert float(r) < float(b)
    with pytest.raises(BallScrewInputError, match="model"):
        oil.viscosity_at_pressure(40.0, 5e8, model="doolittle")


@pytest.mark.parametrize(
    ("changes", "field"),
    [
        ({"nu100": 70e-6}, "nu100"),
        ({"nu40": -1.0}, "nu40"),
        ({"density15": float("nan")}, "density15"),
        ({"pressure_viscosity": 0.0}, "pressure_viscosity"),
        ({"limiting_shear_coefficient": -0.1}, "limiting_shear_coefficient"),
        ({"viscosity_model": "andrade"}, "viscosity_model"),
        ({"name": ""}, "name"),
    ],
)
def test_bad_lubricant_input(changes: dict[str, object], field: str) -> None:
    base = lubricants.get("PAO ISO VG 68")
    with pytest.raises(BallScrewInputError) as info:
        base.replace(**changes)
    assert info.value.field == field


def test_bad_temperature() -> None:
    oil = lubricants.get("SAE 20")
    with pytest.raises(BallScrewInputError, match="temperature"):
        oil.kinematic_viscosity(-300.0)
    with pytest.raises(BallScrewInputError, match="temperature"):
        oil.kinematic_viscosity(float("nan"))


def test_library_contents_and_lookup() -> None:
    required = {
        "PAO ISO VG 68",
        "mineral ISO VG 68",
        "SAE 20",
        "mineral ISO VG 32",
        "mineral ISO VG 46",
        "mineral ISO VG 100",
    }
    assert required <= set(lubricants.names())
    for oil in lubricants.all_lubricants():
        assert oil.source, oil.name
        # ISO 3448: the grade number is the mid-point viscosity at 40 °C (±10 %).
        if "ISO VG" in oil.name:
            grade = float(oil.name.rsplit(" ", 1)[1])
            assert 0.9 * grade <= oil.nu40 * 1e6 <= 1.1 * grade
    assert lubricants.get("  pao iso   vg 68 ").name == "PAO ISO VG 68"


def test_sae20_is_inside_sae_j300() -> None:
    # SAE J300 (2009 table): an SAE 20 has 5.6 <= nu100 < 9.3 mm²/s.
    assert 5.6e-6 <= lubricants.get("SAE 20").nu100 < 9.3e-6


def test_unknown_lubricant_lists_the_names() -> None:
    with pytest.raises(BallScrewInputError) as info:
        lubricants.get("castor oil")
    for name in lubricants.names():
        assert name in str(info.value)
