"""Tests of ballscrew.ehl: Hamrock-Dowson film thickness, film parameter, asperity share."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew import BallScrewInputError
from ballscrew.ehl import (
    asperity_share,
    composite_roughness,
    dimensionless_load,
    dimensionless_materials,
    dimensionless_speed,
    hamrock_dowson_1977_central,
    hamrock_dowson_1977_minimum,
    lambda_ratio,
)

BASE = {"rx": 3e-3, "u": 5e-11, "g": 4600.0, "w": 5e-5, "k": 5.0}


def _ratio(func: object, name: str, factor: float) -> float:
    lo = dict(BASE)
    hi = dict(BASE)
    hi[name] = BASE[name] * factor
    return float(func(**hi) / func(**lo))  # type: ignore[operator]


@pytest.mark.parametrize(
    ("func", "exponents"),
    [
        (hamrock_dowson_1977_minimum, {"u": 0.68, "g": 0.49, "w": -0.073, "rx": 1.0}),
        (hamrock_dowson_1977_central, {"u": 0.67, "g": 0.53, "w": -0.067, "rx": 1.0}),
    ],
)
def test_film_thickness_exponents(func: object, exponents: dict[str, float]) -> None:
    # Hamrock & Dowson (1977) eqs. (33), (34): power laws in U, G, W, linear in Rx.
    for name, exponent in exponents.items():
        assert math.log(_ratio(func, name, 10.0)) / math.log(10.0) == pytest.approx(
            exponent, rel=1e-12
        )


def test_ellipticity_factor_limits() -> None:
    # (1 - exp(-0.68 k)) and (1 - 0.61 exp(-0.73 k)): values at k = 1 by hand,
    # tending to 1 for a line contact (k -> infinity).
    args = dict(BASE)
    args["k"] = 1.0
    h1 = hamrock_dowson_1977_minimum(**args)
    args["k"] = 1e6
    hinf = hamrock_dowson_1977_minimum(**args)
    assert float(h1 / hinf) == pytest.approx(1 - math.exp(-0.68), rel=1e-12)
    args["k"] = 1.0
    c1 = hamrock_dowson_1977_central(**args)
    args["k"] = 1e6
    cinf = hamrock_dowson_1977_central(**args)
    assert float(c1 / cinf) == pytest.approx(1 - 0.61 * math.exp(-0.73), rel=1e-12)


def test_minimum_below_central_over_the_fitted_range() -> None:
    u = np.geomspace(1.7e-12, 1.7e-10, 20)[:, None, None]
    w = np.geomspace(3.7e-7, 3.7e-5, 20)[None, :, None]
    k = np.linspace(1.0, 8.0, 15)[None, None, :]
    hmin = hamrock_dowson_1977_minimum(3e-3, u, 4600.0, w, k)
    hc = hamrock_dowson_1977_central(3e-3, u, 4600.0, w, k)
    assert hmin.shape == (20, 20, 15)
    assert np.all(hmin < hc)


def test_dimensionless_groups_by_hand() -> None:
    assert float(dimensionless_speed(0.05, -2.0, 2.3e11, 3e-3)) == pytest.approx(
        0.05 * 2.0 / (2.3e11 * 3e-3)
    )
    assert float(dimensionless_materials(2e-8, 2.3e11)) == pytest.approx(4600.0)
    assert float(dimensionless_load(30.0, 2.3e11, 3e-3)) == pytest.approx(30 / (2.3e11 * 9e-6))


def test_zero_speed_gives_zero_film() -> None:
    assert float(hamrock_dowson_1977_minimum(3e-3, 0.0, 4600.0, 5e-5, 5.0)) == 0.0


def test_lambda_and_asperity_share() -> None:
    sigma = float(composite_roughness(0.08e-6, 0.3e-6))
    assert sigma == pytest.approx(math.sqrt(0.08**2 + 0.3**2) * 1e-6)
    assert float(lambda_ratio(0.62e-6, sigma)) == pytest.approx(0.62 / math.sqrt(0.0964))
    lam = np.linspace(0.0, 5.0, 101)
    share = asperity_share(lam)
    assert share[0] == 1.0
    assert np.all(np.diff(share) < 0)
    # exp(-1.42 * 3^0.8) by hand: 3^0.8 = 2.40822, exp(-3.41967) = 0.032723
    assert float(asperity_share(3.0)) == pytest.approx(math.exp(-1.42 * 3**0.8), rel=1e-14)
    assert float(asperity_share(3.0)) == pytest.approx(0.032723, abs=1e-6)


@pytest.mark.parametrize(
    ("kwargs", "field"),
    [
        ({"k": 0.5}, "ellipticity"),
        ({"u": -1e-11}, "dimensionless speed"),
        ({"w": 0.0}, "dimensionless load"),
        ({"rx": float("nan")}, "rx"),
    ],
)
def test_bad_input(kwargs: dict[str, float], field: str) -> None:
    args = dict(BASE)
    args.update(kwargs)
    with pytest.raises(BallScrewInputError, match=field):
        hamrock_dowson_1977_minimum(**args)
    with pytest.raises(BallScrewInputError, match="roughness"):
        lambda_ratio(1e-6, 0.0)


def test_hamrock_209_bearing_film_against_a_second_implementation() -> None:
    # Inner-race contact of Hamrock's 209 ball bearing example (geometry in
    # test_contact.py): Rx = 5.1093 mm, E' = 219.78 GPa, exact k = 9.2850,
    # w = 4545.5 N, mean rolling speed 6.2517 m/s, eta0 = 0.01 Pa·s,
    # alpha = 2.2e-8 /Pa. The expected values are NOT the book's printed
    # results (not available here): they come from a second implementation of
    # Hamrock and Dowson's formulas written separately from this package, so
    # the test guards against slips in the package's transcription (a wrong
    # exponent or constant changes h_min by far more than the 1e-4 µm
    # tolerance, which is the rounding of the second implementation's output).
    rx, ep = 5.1093e-3, 219.78e9
    u = dimensionless_speed(0.01, 6.2517, ep, rx)
    w = dimensionless_load(4545.5, ep, rx)
    g = dimensionless_materials(2.2e-8, ep)
    assert float(u) == pytest.approx(5.5674e-11, rel=2e-5)
    assert float(w) == pytest.approx(7.9226e-4, rel=2e-5)
    assert float(hamrock_dowson_1977_minimum(rx, u, g, w, 9.2850)) * 1e6 == pytest.approx(
        0.2120, abs=1e-4
    )
    assert float(hamrock_dowson_1977_central(rx, u, g, w, 9.2850)) * 1e6 == pytest.approx(
        0.2679, abs=1e-4
    )
