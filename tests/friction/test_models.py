"""Model-specific tests: closed-form limits, exact integrals and published values."""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np
import pytest
from scipy import integrate

from ballscrew import friction_torque, lubricants, reference_screw
from ballscrew import rolling_losses as rl
from ballscrew.errors import BallScrewInputError
from ballscrew.friction.catalog import (
    catalog_efficiency,
    preload_from_drag_torque,
    preload_torque,
)
from ballscrew.friction.harris_full import full_contact_power
from ballscrew.friction.harris_simplified import mean_sliding_factor, simplified_contact_force
from ballscrew.friction.olaru import curvature_fit, pivoting_fit
from ballscrew.friction.viscoelastic import lens_moments, viscoelastic_contact
from ballscrew.kinematics import kinematics
from shared import PAO

OIL = PAO


# --- catalog -------------------------------------------------------------------------------
def test_catalog_preload_torque_by_hand() -> None:
    # T_p = 0.05 / sqrt(tan b) * F l / 2 pi; tan b = 10 / (40 pi) = 0.0795775,
    # K = 0.05 / 0.2820948 = 0.1772454, T = 0.1772454 * 2000 * 0.01 / 2 pi = 0.564190 N·m.
    s = reference_screw()
    assert float(preload_torque(2000.0, 0.01, s.lead_angle)) == pytest.approx(0.564190, rel=1e-6)
    r = friction_torque(s, OIL, speed=10.0, temperature=40.0, model="catalog")
    assert float(r.components["preload"]) == pytest.approx(0.564190, rel=1e-6)


def test_catalog_preload_torque_matches_thk_worked_example() -> None:
    # THK General Catalog, "Preload torque" worked example (p. A-689): BNFN4010-5,
    # ball centre diameter 41.75 mm, lead 10 mm, preload 3000 N -> tan(beta)
    # = 0.0762 and a reference torque of 865 N·mm (printed to 3 digits, so
    # the tolerance is half a unit in the last: 0.5/865).
    # The lead angle is the package's (BallScrew.lead_angle), its tangent the printed 0.0762
    # (half a unit in the last digit).
    s = reference_screw().replace(pitch_diameter=0.04175, preload=3000.0)
    beta = s.lead_angle
    assert math.tan(beta) == pytest.approx(0.0762, abs=5e-5)
    assert float(preload_torque(3000.0, 0.010, beta)) * 1e3 == pytest.approx(865.0, abs=0.5)
    r = friction_torque(s, OIL, speed=10.0, temperature=40.0, model="catalog")
    assert float(r.components["preload"]) * 1e3 == pytest.approx(865.0, abs=0.5)


def test_catalog_inverse_round_trip_and_the_study_preloads() -> None:
    s = reference_screw()
    fpr = preload_from_drag_torque([0.2, 0.4, 0.6], s)
    np.testing.assert_allclose(
        preload_torque(fpr, s.lead, s.lead_angle), [0.2, 0.4, 0.6], rtol=1e-14
    )
    assert np.all(np.diff(fpr) > 0)


def test_catalog_efficiency_equals_the_thk_form() -> None:
    # THK writes eta = (1 - mu tan b) / (1 + mu / tan b); identical to tan b / tan(b + rho).
    beta = np.radians(np.linspace(1.0, 30.0, 30))
    mu = 0.003
    thk = (1 - mu * np.tan(beta)) / (1 + mu / np.tan(beta))
    np.testing.assert_allclose(catalog_efficiency(beta, mu), thk, rtol=1e-13)
    assert float(catalog_efficiency(0.1, 0.0)) == pytest.approx(1.0)


def test_catalog_load_term() -> None:
    s = reference_screw()
    r = friction_torque(
        s, OIL, speed=10.0, temperature=40.0, axial_load=[-3000.0, 3000.0], model="catalog"
    )
    eta = float(catalog_efficiency(s.lead_angle, 0.003))
    expected = 3000 * s.lead / (2 * math.pi) * (1 / eta - 1)
    np.testing.assert_allclose(r.components["load"], expected, rtol=1e-14)


# --- viscoelastic ---------------------------------------------------------------------------
def _brute_lens(rp: float, xc: float, rm2: float, n: int = 1500) -> np.ndarray:
    """Moments of the lens on a fine midpoint grid (independent of the closed form)."""
    ext = max(rp, xc + math.sqrt(rm2))
    xs = np.linspace(-ext, ext, n + 1)
    xs = 0.5 * (xs[1:] + xs[:-1])
    x, y = np.meshgrid(xs, xs, indexing="ij")
    inside = (x**2 + y**2 <= rp**2) & ((x - xc) ** 2 + y**2 <= rm2)
    da = (xs[1] - xs[0]) ** 2
    return np.array([np.sum(g[inside]) * da for g in (x**0, x, x**2, x**3, y**2, x * y**2)])


@pytest.mark.parametrize(("xc", "rm2"), [(0.3, 1.0 + 0.09 - 0.2), (0.8, 0.5), (0.1, 0.2)])
def test_lens_moments_against_a_fine_grid(xc: float, rm2: float) -> None:
    rp = 1.0
    chord = (rp**2 - rm2 + xc**2) / (2 * xc)
    closed = np.array(lens_moments(rp, xc, rm2, chord)[:6], dtype=float)
    grid = _brute_lens(rp, xc, rm2)
    # Midpoint grid of 1500^2 cells: boundary error ~ h = 1.3e-3 of the area.
    np.testing.assert_allclose(closed, grid, rtol=0, atol=4e-3)


def _moment_kernels(half: Callable[[float], float]) -> list[Callable[[float], float]]:
    """x-integrands of the moments 1, x, x^2, x^3, y^2, x y^2 of a region |y| <= half(x).

    The y-integrals are exact: 2 Y for the first four, 2 Y^3 / 3 for the last two.
    """
    return [
        lambda x: 2 * half(x),
        lambda x: 2 * x * half(x),
        lambda x: 2 * x**2 * half(x),
        lambda x: 2 * x**3 * half(x),
        lambda x: 2 * half(x) ** 3 / 3,
        lambda x: 2 * x * half(x) ** 3 / 3,
    ]


def _lens_by_quadrature(rp: float, xc: float, rm2: float) -> np.ndarray:
    """Moments of the lens by adaptive quadrature in x of the exact integrals in y.

    At each x the lens spans |y| <= Y(x) = min of the two circles' half-widths,
    so the y-integrals are 2Y (for 1, x, x^2, x^3) and 2Y^3/3 (for y^2, xy^2).
    """
    from scipy import integrate

    rm = math.sqrt(rm2)
    lo, hi = max(-rp, xc - rm), min(rp, xc + rm)
    chord = (rp**2 - rm2 + xc**2) / (2 * xc)

    def half(x: float) -> float:
        return math.sqrt(max(0.0, min(rp**2 - x**2, rm2 - (x - xc) ** 2)))

    kernels = _moment_kernels(half)
    points = [chord] if lo < chord < hi else None
    return np.array(
        [integrate.quad(f, lo, hi, points=points, epsabs=1e-14, epsrel=1e-12)[0] for f in kernels]
    )


@pytest.mark.parametrize(
    ("rp", "xc", "rm2"), [(1.0, 0.3, 0.89), (1.0, 0.8, 0.5), (1.0, 0.1, 0.2), (2e-5, 3e-7, 3.9e-10)]
)
def test_lens_moments_against_quadrature(rp: float, xc: float, rm2: float) -> None:
    # All six moments to 1e-8 relative (quadrature tolerance 1e-12), including
    # the odd ones, which the grid test above checks only to its 4e-3; the
    # last case has the scales of a ball screw contact (m).
    chord = (rp**2 - rm2 + xc**2) / (2 * xc)
    closed = np.array(lens_moments(rp, xc, rm2, chord)[:6], dtype=float)
    # Quadrature in units of rp (its tolerances are absolute), scaled back.
    scale = np.array([rp**2, rp**3, rp**4, rp**5, rp**4, rp**5])
    exact = _lens_by_quadrature(1.0, xc / rp, rm2 / rp**2)
    np.testing.assert_allclose(closed / scale, exact, rtol=1e-8, atol=1e-12)


def test_viscoelastic_static_and_slow_rolling_limits() -> None:
    # Static: N = pi k R tau^2. Slow rolling: F -> pi gamma v tau^2 (linear viscous).
    k, gamma, radius, q = 2.1e18, 3.5e13, 3.175e-3, 29.0
    tau_s = math.sqrt(q / (math.pi * k * radius))
    c0 = viscoelastic_contact(q, 0.0, radius, stiffness=k, damping=gamma)
    assert float(c0.penetration) == pytest.approx(tau_s, rel=1e-12)
    assert float(c0.friction) == 0.0
    v = 1e-5
    c = viscoelastic_contact(q, v, radius, stiffness=k, damping=gamma)
    # Relative correction is O(gamma v / (k r+)) = 1e-5 here.
    assert float(c.friction) == pytest.approx(math.pi * gamma * v * tau_s**2, rel=1e-4)


def test_viscoelastic_friction_rises_then_falls() -> None:
    # Pöschel et al. (1999): the rolling friction first grows with speed, then falls.
    v = np.geomspace(1e-3, 30.0, 60)
    f = viscoelastic_contact(29.0, v, 3.175e-3).friction
    peak = int(np.argmax(f))
    assert 0 < peak < len(v) - 1
    assert np.all(np.diff(f[: peak + 1]) > 0) and np.all(np.diff(f[peak:]) < 0)


def test_viscoelastic_load_balance_holds() -> None:
    # Re-evaluate the support force at the returned penetration by the grid.
    q, v, radius, k, m, g = 29.0, 1.0, 3.175e-3, 2.1e18, 7.8e-4, 3.5e13
    c = viscoelastic_contact(q, v, radius)
    tau = float(c.penetration)
    rp2 = 2 * radius * tau
    xc = g * v / k
    rm2 = rp2 - 2 * m * v**2 / k + xc**2
    mom = _brute_lens(math.sqrt(rp2), xc, rm2, n=2000)
    support = (
        (k * tau - m * v**2 / radius) * mom[0]
        + g * v / radius * mom[1]
        - k / (2 * radius) * (mom[2] + mom[4])
    )
    assert support + float(c.edge_force) == pytest.approx(q, rel=5e-3)


def test_viscoelastic_torque_arms() -> None:
    s = reference_screw()
    e = friction_torque(s, OIL, speed=100.0, temperature=40.0, model="viscoelastic")
    b = friction_torque(
        s, OIL, speed=100.0, temperature=40.0, model="viscoelastic", torque_arm="ball-radius"
    )
    lever = float(kinematics(s, 1.0).entrainment_speed)  # u / omega, the energy arm
    assert float(b.total / e.total) == pytest.approx(s.ball_diameter / 2 / lever, rel=1e-12)


# --- harris-simplified ----------------------------------------------------------------------
def test_simplified_asperity_term_is_the_exact_integral() -> None:
    # ab ∫∫ c_v (Ac/A0) mu0 p0 sqrt(1 - t² - q²) dt dq = c_v (Ac/A0) mu0 (2/3) pi a b p0
    # = c_v (Ac/A0) mu0 Q exactly.
    a, b, p0 = np.array(2e-4), np.array(5e-5), np.array(1.2e9)
    q = 2 / 3 * math.pi * a * b * p0
    asp, _ = simplified_contact_force(
        a=a,
        b=b,
        p_max=p0,
        asperity_share=np.array(0.4),
        viscosity=0.05,
        pressure_viscosity=1.5e-8,
        shear_rate=np.array(1e5),
        tau0=0.0,
        gamma_l=0.07,
    )
    assert float(asp) == pytest.approx(float(0.3 * 0.4 * 0.1 * q), rel=1e-14)


def test_simplified_lubricant_newtonian_and_saturated_limits() -> None:
    a, b, p0 = np.array(2e-4), np.array(5e-5), np.array(1.2e9)
    q = float(2 / 3 * math.pi * a * b * p0)
    kw = {
        "a": a,
        "b": b,
        "p_max": p0,
        "asperity_share": np.array(0.0),
        "tau0": 1e6,
        "gamma_l": 0.07,
    }
    # Newtonian (tiny shear rate, constant viscosity): tau = eta * rate over pi a b.
    _, lub = simplified_contact_force(
        viscosity=0.1,
        pressure_viscosity=1e-30,
        pressure_viscosity_model="barus",
        shear_rate=np.array(1.0),
        **kw,
    )  # type: ignore[arg-type]
    assert float(lub) == pytest.approx(0.1 * 1.0 * math.pi * 2e-4 * 5e-5, rel=1e-6)
    # Saturated: tau -> tau0 + gamma_L p, integral tau0 pi a b + gamma_L Q.
    _, lub = simplified_contact_force(
        viscosity=1e12, pressure_viscosity=1.5e-8, shear_rate=np.array(1e12), **kw
    )  # type: ignore[arg-type]
    assert float(lub) == pytest.approx(1e6 * math.pi * 2e-4 * 5e-5 + 0.07 * q, rel=1e-6)


def test_simplified_options_change_the_result_as_documented() -> None:
    s = reference_screw()
    kw = {"speed": 100.0, "temperature": 40.0, "model": "harris-simplified"}
    base = friction_torque(s, OIL, **kw)  # type: ignore[arg-type]
    both = friction_torque(s, OIL, sliding_sign_on_lubricant=True, **kw)  # type: ignore[arg-type]
    slide = friction_torque(s, OIL, shear_velocity="sliding", **kw)  # type: ignore[arg-type]
    assert float(both.components["lubricant"]) == pytest.approx(
        0.3 * float(base.components["lubricant"]), rel=1e-14
    )
    assert float(slide.components["lubricant"]) < 0.05 * float(base.components["lubricant"])
    np.testing.assert_allclose(slide.components["asperity"], base.components["asperity"])


def test_mean_sliding_factor_by_quadrature() -> None:
    value, _ = integrate.quad(
        lambda q: abs(q * q - 0.347**2) * math.sqrt(1 - q * q), -1, 1, points=[-0.347, 0.347]
    )
    assert mean_sliding_factor() == pytest.approx(value * 2 / math.pi, rel=1e-12)


# --- harris-full ---------------------------------------------------------------------------
def _spin_contact(**overrides: object) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """full_contact_power of one contact under pure spin (omega_s / omega = 0.4)."""
    kw: dict[str, object] = {
        "a": np.array([2.5e-4]),
        "b": np.array([6e-5]),
        "p_max": np.array([1.2e9]),
        "asperity_share": np.array([0.0]),
        "viscosity": np.array([0.05]),
        "pressure_viscosity": 1e-30,
        "film": np.array([2e-7]),
        "curvature": 0.0,
        "spin": 0.4,
        "screw_speed": np.array([3.0]),
        "tau0": 1e30,
        "gamma_l": 0.0,
        "mu0": 0.1,
        "nodes": (24, 64),
    }
    kw.update(overrides)
    return full_contact_power(**kw)  # type: ignore[arg-type]


def test_full_model_newtonian_spin_power_is_exact() -> None:
    # Pure spin, no slip by symmetry, Newtonian film of constant viscosity:
    # |v| = w r with r the distance from the centre, so
    # P = (eta w^2 omega^2 / h) * integral of (x^2 + y^2) dA
    #   = (eta w^2 omega^2 / h) pi a b (a^2 + b^2) / 4,
    # and P/|omega| divides one omega out. The Gauss rule in the pressure
    # coordinate integrates the polynomial exactly; the angular rule too.
    a, b, eta, h, w, omega = 2.5e-4, 6e-5, 0.05, 2e-7, 0.4, 3.0
    asperity, lubricant, slip = _spin_contact()
    expected = eta * (w * omega) ** 2 / h * math.pi * a * b * (a**2 + b**2) / 4 / omega
    assert float(lubricant[0]) == pytest.approx(expected, rel=1e-9)
    assert float(asperity[0]) == 0.0 and abs(float(slip[0])) < 1e-12 * a


def test_full_model_dry_spin_power_is_the_spin_moment() -> None:
    # Coulomb friction only, pure spin: P = mu0 (3Q / 2 pi) w omega a I(0, b/a)
    # (the pressure-weighted mean distance; rolling_losses' independent 12 x 48
    # polar rule, itself checked against pi^2/8 and Harris's elliptic-integral
    # form). Q = (2/3) pi a b p_max. Tolerance: the two quadratures, 1e-4.
    a, b, p0, w = 2.5e-4, 6e-5, 1.2e9, 0.4
    asperity, lubricant, _ = _spin_contact(asperity_share=np.array([1.0]))
    q = 2.0 / 3.0 * math.pi * a * b * p0
    expected = 0.1 * 1.5 / math.pi * q * w * a * float(rl.spin_sliding_integral(0.0, b / a))
    assert float(asperity[0]) == pytest.approx(expected, rel=1e-4)
    assert float(lubricant[0]) == 0.0


def test_full_model_reproduces_heathcote_rolling_lines() -> None:
    # Coulomb friction only (asperity share 1), no spin: the zero-traction slip
    # puts the pure-rolling lines at y0 = ±0.347 a (Heathcote 1921; Johnson,
    # Contact Mechanics, 1985, §8.8). With v_x = s - C y², y0 = sqrt(s / C).
    a = np.array([2.5e-4])
    c = 500.0
    _, _, slip = full_contact_power(
        a=a,
        b=np.array([5e-5]),
        p_max=np.array([1e9]),
        asperity_share=np.array([1.0]),
        viscosity=np.array([0.05]),
        pressure_viscosity=1.5e-8,
        film=np.array([1e-7]),
        curvature=c,
        spin=0.0,
        screw_speed=np.array([100.0]),
        tau0=0.0,
        gamma_l=0.07,
        mu0=0.1,
        nodes=(32, 256),
    )
    # Heathcote's 0.347 is quoted to 3 figures; the quadrature (kinks at y0)
    # is good to about 1e-3 with these nodes.
    assert math.sqrt(float(slip[0]) / c) / float(a[0]) == pytest.approx(0.347, abs=2e-3)


def test_full_model_quadrature_converges() -> None:
    s = reference_screw()
    coarse = friction_torque(s, OIL, speed=[30.0, 300.0], temperature=40.0, model="harris-full")
    fine = friction_torque(
        s, OIL, speed=[30.0, 300.0], temperature=40.0, model="harris-full", nodes=(32, 256)
    )
    # Documented: within 0.25 % of a (32, 256) grid.
    np.testing.assert_allclose(coarse.total, fine.total, rtol=0.0025)


def test_full_model_asperity_part_at_zero_speed_is_finite() -> None:
    r = friction_torque(
        reference_screw(), OIL, speed=[0.0, 1e-3], temperature=40.0, model="harris-full"
    )
    assert r.total[0] > 0.0
    assert float(r.total[1]) == pytest.approx(float(r.total[0]), rel=1e-2)


# --- olaru -----------------------------------------------------------------------------------
def test_olaru_fits_end_values_and_clipping() -> None:
    # Houpert's fits at E = 1: f_c = -0.0037 -> clipped to 0, f_p = 1.0064.
    assert float(curvature_fit(1.0)) == 0.0
    assert float(pivoting_fit(1.0)) == pytest.approx(1.0064, abs=1e-4)
    assert float(curvature_fit(5.0)) == 0.0 and float(pivoting_fit(5.0)) == float(pivoting_fit(1.0))


def test_olaru_rolling_force_scales_with_speed_to_the_0_66() -> None:
    # F_R ∝ U^0.66 at fixed load and temperature: rolling torque ratio 2^0.66.
    r = friction_torque(
        reference_screw(), OIL, speed=[50.0, 100.0], temperature=40.0, model="olaru"
    )
    ratio = r.components["rolling"][1] / r.components["rolling"][0]
    assert float(ratio) == pytest.approx(2**0.66, rel=1e-12)


def test_olaru_options() -> None:
    s = reference_screw()
    base = friction_torque(s, OIL, speed=100.0, temperature=40.0, model="olaru")
    no_pivot = friction_torque(
        s, OIL, speed=100.0, temperature=40.0, model="olaru", include_pivoting=False
    )
    assert float(no_pivot.components["pivoting"]) == 0.0
    assert float(base.components["pivoting"]) > 0.0
    mm = friction_torque(
        s, OIL, speed=100.0, temperature=40.0, model="olaru", hysteresis_units="N·mm"
    )
    # SI vs mm reading differ by 1000^0.33 / 1000 in the moment.
    assert float(mm.components["hysteresis"] / base.components["hysteresis"]) == pytest.approx(
        1000**0.33 / 1000, rel=1e-12
    )
    # At standstill Lambda = 0, so mu = mu0 * Ac/A0 = 0.1; the speed fit gives
    # exp(-2.643) = 0.07114 at n = 0: the Coulomb moments scale by that ratio.
    fit = friction_torque(
        s, OIL, speed=0.0, temperature=40.0, model="olaru", sliding_friction="speed-fit"
    )
    still = friction_torque(s, OIL, speed=0.0, temperature=40.0, model="olaru")
    assert float(fit.components["pivoting"] / still.components["pivoting"]) == pytest.approx(
        math.exp(-2.643) / 0.1, rel=1e-12
    )


@pytest.mark.parametrize("model", ["harris-simplified", "olaru", "viscoelastic", "harris-full"])
@pytest.mark.parametrize("axial", [0.0, 1500.0])
def test_four_point_nut_counts_each_contact_once(model: str, axial: float) -> None:
    # Regression (issue 8): a 4-point nut of Z balls and a double nut of Z balls per half have
    # the same contacts: two families of Z balls, each ball pressed at Q on screw and nut. The
    # load model lists the 4-point balls in both families already; the models used to multiply
    # by 2 again. Per-contact losses are the same whichever nut lists them, so the torques of
    # models with no ball-level coupling must be equal (they were exactly 2x apart).
    double = reference_screw()
    four = double.replace(nut="single-4point")
    oil = lubricants.get("PAO ISO VG 68")
    kw = {"speed": [10.0, 100.0], "temperature": 40.0, "axial_load": axial, "model": model}
    t4 = friction_torque(four, oil, **kw).total  # type: ignore[arg-type]
    t2 = friction_torque(double, oil, **kw).total  # type: ignore[arg-type]
    np.testing.assert_allclose(t4, t2, rtol=1e-12)


def test_catalog_functions_accept_every_lead_angle_below_90_degrees_only() -> None:
    # The rule is defined for 0 < beta < 90°: 89° is accepted by both
    # functions, 90° refused; the efficiency also needs beta + atan(mu) < 90°.
    from ballscrew.friction.catalog import catalog_efficiency, preload_torque_coefficient

    steep, right = math.radians(89.0), math.pi / 2
    assert float(preload_torque_coefficient(steep)) == pytest.approx(
        0.05 / math.sqrt(math.tan(steep)), rel=1e-12
    )
    assert 0.0 < float(catalog_efficiency(steep, 0.0)) <= 1.0
    for func in (preload_torque_coefficient, lambda b: catalog_efficiency(b, 0.0)):
        with pytest.raises(BallScrewInputError, match="lead_angle"):
            func(right)
    beta = math.radians(80.0)
    ok, too_much = math.tan(math.radians(9.9)), math.tan(math.radians(10.1))
    assert float(catalog_efficiency(beta, ok)) == pytest.approx(
        math.tan(beta) / math.tan(math.radians(89.9)), rel=1e-9
    )
    with pytest.raises(BallScrewInputError, match="friction_coefficient"):
        catalog_efficiency(beta, too_much)


def test_mean_sliding_speed_is_the_area_mean_over_the_ellipse() -> None:
    # Average |C (y^2 - (q0 a)^2)| over a fine grid of the ellipse x^2/b^2 +
    # y^2/a^2 <= 1 (midpoint rule, 2000 x 2000: error well under 1e-3).
    from ballscrew.friction.harris_simplified import HEATHCOTE_ROLLING_LINE, mean_sliding_speed

    a, b, c = 3e-4, 7e-5, 2.5e4
    n = 2000
    y = (np.arange(n) + 0.5) / n * 2 * a - a
    x = (np.arange(n) + 0.5) / n * 2 * b - b
    xx, yy = np.meshgrid(x, y)
    inside = xx**2 / b**2 + yy**2 / a**2 <= 1.0
    slip = np.abs(c * (yy**2 - (HEATHCOTE_ROLLING_LINE * a) ** 2))
    expected = float(slip[inside].mean())
    assert float(mean_sliding_speed(-c, a)) == pytest.approx(expected, rel=1e-3)


@pytest.mark.parametrize("law", ["harmonic", "general", "eyring", "bair-winer"])
def test_every_shear_law_is_newtonian_at_a_tiny_shear_rate(law: str) -> None:
    # At a shear stress far below the limiting one, every law gives eta * rate
    # (the Eyring law for tau << tau_E: tau_E asinh(eta rate / tau_E) -> eta rate).
    a, b, p0 = np.array(2e-4), np.array(5e-5), np.array(1.2e9)
    _, lub = simplified_contact_force(
        a=a,
        b=b,
        p_max=p0,
        asperity_share=np.array(0.0),
        viscosity=0.1,
        pressure_viscosity=1e-30,
        pressure_viscosity_model="barus",
        shear_rate=np.array(1.0),
        tau0=1e6,
        gamma_l=0.07,
        rheology_model=law,
        eyring_stress=5e6,
    )  # type: ignore[arg-type]
    assert float(lub) == pytest.approx(0.1 * 1.0 * math.pi * 2e-4 * 5e-5, rel=1e-5)


def test_simplified_model_input_bounds() -> None:
    # c_v is allowed on [0, 1] (both ends; below 0 the torque was negative, issue 28), at
    # least 2 quadrature nodes.
    kw = {"speed": 10.0, "temperature": 40.0, "model": "harris-simplified"}
    for cv in (0.0, 1.0):
        friction_torque(reference_screw(), OIL, sliding_coefficient=cv, **kw)  # type: ignore[arg-type]
    for cv in (-1.0, -0.01, 1.01):
        with pytest.raises(BallScrewInputError, match="sliding_coefficient"):
            friction_torque(reference_screw(), OIL, sliding_coefficient=cv, **kw)  # type: ignore[arg-type]
    two = friction_torque(reference_screw(), OIL, nodes=2, **kw)  # type: ignore[arg-type]
    many = friction_torque(reference_screw(), OIL, nodes=48, **kw)  # type: ignore[arg-type]
    # Two Gauss nodes already integrate the smooth pressure profile to a few per cent.
    assert float(two.total) == pytest.approx(float(many.total), rel=0.05)
    with pytest.raises(BallScrewInputError, match="nodes"):
        friction_torque(reference_screw(), OIL, nodes=1, **kw)  # type: ignore[arg-type]


def test_simplified_defaults_are_the_study_values() -> None:
    # The study states mu0 = 0.1, B = 1.42 (A_c/A0 = exp(-B Lambda^C)) and
    # c_v = 0.3 (65 % of the ellipse slipping against rolling); it gives no C,
    # and C = 0.8 is the value of the public code of Olaru's model.
    from ballscrew.friction import get_model

    p = get_model("harris-simplified").parameters
    assert (p["mu0"], p["sliding_coefficient"]) == (0.1, 0.3)
    assert (p["asperity_b"], p["asperity_c"]) == (1.42, 0.8)


@pytest.mark.parametrize(
    ("v", "m"),
    [
        (0.3, 7.8e-4),
        (3.0, 7.8e-4),
        (12.0, 7.8e-4),
        (3.0, 5e6),
        (1.0, 3e7),
        (2.0, 3e7),
        (3.0, 1e8),
        (5.0, 1e8),
    ],  # the last needs the penetration bracket to grow
)
def test_viscoelastic_friction_is_the_pressure_moment_over_the_lens(v: float, m: float) -> None:
    # Pöschel's bed: p = k z + gamma dz/dt + m d2z/dt2 with z = tau - (x^2 + y^2)/2R
    # under the ball moving at v (dz/dt = v x / R, d2z/dt2 = -v^2 / R). Without
    # the leading-edge term the rolling friction is the moment of p about the
    # ball centre over R, integrated here on a fine grid over the contact lens,
    # independently of the closed-form moments. Grid of 1600^2 cells over the
    # ball's disk: boundary error ~ 1e-3. The study's bed mass hardly acts (its
    # terms are 1e-11 of the spring's); the heavy beds make them count.
    q, radius, k, g = 29.0, 3.175e-3, 2.1e18, 3.5e13
    c = viscoelastic_contact(q, v, radius, mass=m, leading_edge=False)
    tau = float(c.penetration)
    rp = math.sqrt(2 * radius * tau)
    xc = g * v / k
    rm2 = rp**2 - 2 * m * v**2 / k + xc**2
    n = 1600
    xs = np.linspace(-rp, rp, n + 1)  # the lens lies inside the ball's disk
    xs = 0.5 * (xs[1:] + xs[:-1])
    x, y = np.meshgrid(xs, xs, indexing="ij")
    inside = (x**2 + y**2 <= rp**2) & ((x - xc) ** 2 + y**2 <= rm2)
    p = k * (tau - (x**2 + y**2) / (2 * radius)) + g * v * x / radius - m * v**2 / radius
    da = (xs[1] - xs[0]) ** 2
    assert float(np.sum(p[inside]) * da) == pytest.approx(q, rel=3e-3)  # the load it carries
    friction = float(np.sum((p * x)[inside]) * da) / radius
    assert float(c.friction) == pytest.approx(friction, rel=3e-3)


@pytest.mark.parametrize(("v", "m"), [(8.0, 7.8e-4), (3.0, 5e6)])
def test_viscoelastic_leading_edge_terms(v: float, m: float) -> None:
    # Bed elements struck by the leading arc of the contact (|phi| <= theta0 on
    # the circle of radius r+) jump to the ball's vertical speed v r+ cos(phi) / R;
    # the arc sweeps area at v cos(phi) r+ dphi. By quadrature over the arc:
    # impulse rate (edge force) = integral of m (v r+ cos / R)(v r+ cos) dphi, and
    # kinetic-energy rate / v (edge friction) = integral of (m/2)(v r+ cos / R)^2
    # r+ cos dphi; the "work" reading doubles the friction (module docstring).
    from scipy import integrate

    q, radius = 29.0, 3.175e-3
    kinetic = viscoelastic_contact(q, v, radius, mass=m, edge_power="kinetic")
    work = viscoelastic_contact(q, v, radius, mass=m, edge_power="work")
    none = viscoelastic_contact(q, v, radius, mass=m, leading_edge=False)
    tau, t0 = float(kinetic.penetration), float(kinetic.leading_edge_angle)
    rp = math.sqrt(2 * radius * tau)
    assert 0.0 < t0 < math.pi / 2
    force = integrate.quad(lambda f: m * (v * rp * math.cos(f) / radius) * v * rp * math.cos(f),
                           -t0, t0, epsrel=1e-13)[0]  # fmt: skip
    assert float(kinetic.edge_force) == pytest.approx(force, rel=1e-9)
    edge = integrate.quad(lambda f: 0.5 * m * (v * rp * math.cos(f) / radius) ** 2 * rp
                          * math.cos(f), -t0, t0, epsrel=1e-13)[0]  # fmt: skip
    # Same penetration in both readings: they differ by the edge friction only.
    assert float(work.penetration) == tau
    assert float(work.friction - kinetic.friction) == pytest.approx(edge, rel=1e-6)
    if m > 1.0:  # heavy bed: the edge terms are a visible share of the totals
        assert edge > 1e-3 * float(kinetic.friction)
        # And the load balance includes the edge force: springs, dampers and
        # bed mass over the lens (grid, as in the pressure-moment test) plus it.
        k, g = 2.1e18, 3.5e13
        xc = g * v / k
        rm2 = rp**2 - 2 * m * v**2 / k + xc**2
        xs = np.linspace(-rp, rp, 1601)
        xs = 0.5 * (xs[1:] + xs[:-1])
        x, y = np.meshgrid(xs, xs, indexing="ij")
        inside = (x**2 + y**2 <= rp**2) & ((x - xc) ** 2 + y**2 <= rm2)
        p = k * (tau - (x**2 + y**2) / (2 * radius)) + g * v * x / radius - m * v**2 / radius
        support = float(np.sum(p[inside])) * (xs[1] - xs[0]) ** 2
        assert support + float(kinetic.edge_force) == pytest.approx(q, rel=3e-3)
        assert float(kinetic.edge_force) > 0.01 * q
    assert float(none.edge_force) == 0.0


def test_viscoelastic_torque_is_the_power_of_the_contacts() -> None:
    # Energy balance: T |omega| = sum over balls of F u at the screw and at the
    # nut contact, u = omega d_m (1 - gamma^2 cos^4 lambda) / (4 cos lambda) the rolling
    # speed of the ball (computed here from the closed form, not the kinematics module).
    s = reference_screw().replace(nut="single", preload=0.0)
    w, fa = 150.0, 2500.0
    r = friction_torque(s, OIL, speed=w, temperature=40.0, axial_load=fa, model="viscoelastic")
    cos_l = math.cos(s.lead_angle)
    u = w * s.pitch_diameter * (1 - s.gamma**2 * cos_l**4) / (4 * cos_l)
    q = fa / (s.balls_per_nut * math.sin(s.contact_angle) * math.cos(s.lead_angle))
    f = float(viscoelastic_contact(q, u, s.ball_diameter / 2).friction)
    assert float(r.total) * w == pytest.approx(s.balls_per_nut * 2 * f * u, rel=1e-9)


def test_viscoelastic_defaults_are_the_study_values() -> None:
    # The study's Fig. 4: k = 2.1e18 N/m^3, m = 7.8e-4 kg/m^2, gamma = 3.5e13 N s/m^3.
    from ballscrew.friction import get_model

    p = get_model("viscoelastic").parameters
    assert (p["stiffness"], p["mass"], p["damping"]) == (2.1e18, 7.8e-4, 3.5e13)
    # The contact solver's own defaults are the same values.
    import inspect

    own = inspect.signature(viscoelastic_contact).parameters
    assert (own["stiffness"].default, own["mass"].default, own["damping"].default) == (
        2.1e18, 7.8e-4, 3.5e13,
    )  # fmt: skip


@pytest.mark.parametrize("temperature", [40.0, 20.0])
def test_simplified_lubricant_torque_from_the_contact_states(temperature: float) -> None:
    # The study's eqs. (5) and (8) assembled by hand from the contact states:
    # per contact, F = (1 - A_c/A0) * integral over the ellipse of the harmonic
    # mean of tau_N = eta(p) u / h_min (Roelands at the oil's temperature, its index Z
    # constant: Lubricant.viscosity_at_pressure) and tau_lim = tau0 + gamma_L p,
    # on a 400 x 400 polar grid; torque = sum of balls * F * u / omega.
    # The model's 8-node Gauss rule is good to 7e-4 (its docstring): tolerance 2e-3.
    from ballscrew.friction._common import limiting_shear
    from ballscrew.state import operating_state

    s, w = reference_screw(), 120.0
    r = friction_torque(s, OIL, speed=w, temperature=temperature, model="harris-simplified")
    st = operating_state(s, OIL, speed=w, temperature=temperature, hertz_method="houpert")
    tau0, gl = limiting_shear(OIL, None, None)
    rho = (np.arange(400) + 0.5) / 400
    phi = (np.arange(400) + 0.5) / 400 * 2 * np.pi
    rr, _ = np.meshgrid(rho, phi, indexing="ij")
    torque = 0.0
    for c in st.contacts:
        if c.balls == 0:
            continue
        a, b, p0 = float(c.hertz.a), float(c.hertz.b), float(c.hertz.p_max)
        p = p0 * np.sqrt(1 - rr**2)
        eta = OIL.viscosity_at_pressure(temperature, p)
        tau_n = eta * abs(float(c.entrainment_speed)) / float(c.film_minimum)
        tau_lim = tau0 + gl * p
        tau = tau_n * tau_lim / (tau_n + tau_lim)
        area_weight = a * b * rr * (1 / 400) * (2 * np.pi / 400)  # dA = a b r dr dphi
        force = (1 - float(c.asperity_share)) * float(np.sum(tau * area_weight))
        torque += c.balls * force * float(kinematics(s, 1.0).entrainment_speed)
    assert float(r.components["lubricant"]) == pytest.approx(torque, rel=2e-3)


def test_general_shear_law_at_its_default_exponent_is_the_harmonic_one() -> None:
    # The study's general law (eq. 7), (tau_N^-n + tau_lim^-n)^(-1/n), is eq. 5's
    # harmonic mean at n = 1, its default.
    from ballscrew.friction.harris_simplified import _harmonic, shear_stress

    tau_n = np.array([0.5, 3e5, 2e7, 4e9])
    tau_lim = np.full(4, 1e7)
    general = shear_stress("general", tau_n, 1.0, tau_lim)
    np.testing.assert_allclose(general, tau_n * tau_lim / (tau_n + tau_lim), rtol=1e-12)
    # The harmonic helper keeps tiny stresses (0.5 Pa here) and gives 0 at 0.
    np.testing.assert_allclose(_harmonic(tau_n, tau_lim), general, rtol=1e-12)
    assert float(_harmonic(np.array([0.0]), np.array([1e7]))[0]) == 0.0


@pytest.mark.parametrize(("c", "rho", "t1", "t2"), [(0.0, 1.0, 0.0, 1.1), (0.4, 0.7, 0.5, 2.9)])
def test_disk_segment_moments_against_quadrature(
    c: float, rho: float, t1: float, t2: float
) -> None:
    # One segment of a disk (centre (c, 0), radius rho) between the chords at
    # x = c + rho cos t2 and c + rho cos t1, by quadrature in x of the exact
    # y-integrals. In a lens the terms that depend on the chord's half-height
    # alone cancel between its two segments, so the lens test cannot see them.
    from scipy import integrate

    from ballscrew.friction.viscoelastic import _segment

    def half(x: float) -> float:
        return math.sqrt(max(0.0, rho**2 - (x - c) ** 2))

    kernels = _moment_kernels(half)
    lo, hi = c + rho * math.cos(t2), c + rho * math.cos(t1)
    exact = [integrate.quad(f, lo, hi, epsabs=1e-14, epsrel=1e-12)[0] for f in kernels]
    arr = [np.array(v) for v in (c, rho, t1, t2)]
    closed = [float(m) for m in _segment(*arr)]
    np.testing.assert_allclose(closed, exact, rtol=1e-9, atol=1e-13)


@pytest.mark.parametrize("q", [0.5, 29.0, 400.0])
def test_viscoelastic_static_penetration_at_any_load(q: float) -> None:
    # At rest the springs alone carry the load: N = pi k R tau^2 (a light ball
    # load such as 0.5 N as well as a heavy one).
    k, radius = 2.1e18, 3.175e-3
    c = viscoelastic_contact(q, 0.0, radius, stiffness=k)
    assert float(c.penetration) == pytest.approx(math.sqrt(q / (math.pi * k * radius)), rel=1e-12)


def test_full_model_slip_zeroes_the_net_traction_of_a_fluid_film() -> None:
    # Fluid film only (asperity share 0), spin and Heathcote sliding together,
    # harmonic law with a finite limiting stress: the slip the model returns
    # must make the net rolling-direction traction vanish, and the power must
    # be the integral of tau |v| - both computed here on an independent polar
    # grid of the ellipse (500 x 720 midpoints, constant viscosity).
    a, b, p0, eta, h, omega = 2.5e-4, 6e-5, 1.2e9, 0.05, 2e-7, 30.0
    # tau_N reaches ~1e3 Pa at the contact's edge: a limiting stress of that order
    # puts the film well into the nonlinear part of the harmonic law.
    c_hat, w_hat, tau0, gl = 400.0, 0.3, 300.0, 1e-7
    asperity, lubricant, slip = _spin_contact(
        a=np.array([a]), b=np.array([b]), p_max=np.array([p0]), viscosity=np.array([eta]),
        film=np.array([h]), curvature=c_hat, spin=w_hat, screw_speed=np.array([omega]),
        tau0=tau0, gamma_l=gl, nodes=(32, 128),
    )  # fmt: skip
    s = float(slip[0])
    rho = (np.arange(500) + 0.5) / 500
    phi = (np.arange(720) + 0.5) / 720 * 2 * np.pi
    r, f = np.meshgrid(rho, phi, indexing="ij")
    x, y = b * r * np.cos(f), a * r * np.sin(f)
    vx = -c_hat * y**2 - w_hat * y + s  # per unit |omega|
    vy = w_hat * x
    speed = np.hypot(vx, vy)
    p = p0 * np.sqrt(1 - r**2)
    tau_n = eta * omega / h * speed
    tau_lim = tau0 + gl * p
    tau = tau_n * tau_lim / (tau_n + tau_lim)
    da = a * b * r * (1 / 500) * (2 * np.pi / 720)
    net = float(np.sum(tau * vx / speed * da))
    scale = float(np.sum(tau * da))
    assert abs(net) < 2e-4 * scale
    assert float(lubricant[0]) == pytest.approx(float(np.sum(tau * speed * da)), rel=2e-4)
    assert float(asperity[0]) == 0.0


@pytest.mark.parametrize("law", ["general", "eyring", "bair-winer"])
def test_full_model_every_shear_law_is_newtonian_far_below_its_limits(law: str) -> None:
    # With limiting and Eyring stresses far above the film's stresses, every
    # law gives eta * rate, so the pure-spin power is the Newtonian closed form.
    a, b, eta, h, w, omega = 2.5e-4, 6e-5, 0.05, 2e-7, 0.4, 3.0
    _, lubricant, _ = _spin_contact(rheology_model=law, eyring_stress=1e30)
    expected = eta * (w * omega) ** 2 / h * math.pi * a * b * (a**2 + b**2) / 4 / omega
    assert float(lubricant[0]) == pytest.approx(expected, rel=1e-6)


def test_contact_pressure_viscosity_follows_the_law_named() -> None:
    # Roelands: the coefficient at the contact's temperature, found from the viscosity alone
    # (Z constant); Barus: the oil's alpha as given, one per point.
    from ballscrew.friction._common import contact_pressure_viscosity

    t = np.array([[20.0], [40.0], [60.0]])
    eta = OIL.dynamic_viscosity(t)
    np.testing.assert_allclose(
        contact_pressure_viscosity(OIL, eta), OIL.pressure_viscosity_at(t), rtol=1e-13
    )
    barus = contact_pressure_viscosity(OIL, eta, "barus")
    assert barus.shape == (3, 1)
    assert np.all(barus == OIL.pressure_viscosity)


@pytest.mark.parametrize("temperature", [40.0, 20.0])
def test_full_model_assembles_its_contacts(temperature: float) -> None:
    # The model's torque is the sum over the contacts of balls * P/|omega| from
    # the contact power, with the sliding and spin per unit screw speed taken
    # here from the kinematics at the operating speed (linear in it), and
    # Roelands' coefficient at the oil's temperature (Lubricant.pressure_viscosity_at).
    from ballscrew.friction._common import limiting_shear
    from ballscrew.kinematics import differential_sliding, kinematics
    from ballscrew.state import operating_state

    s, w, t = reference_screw(), 80.0, temperature
    r = friction_torque(s, OIL, speed=w, temperature=t, axial_load=700.0, model="harris-full")
    st = operating_state(s, OIL, speed=w, temperature=t, axial_load=700.0,
                         hertz_method="exact")  # fmt: skip
    alpha = float(OIL.pressure_viscosity_at(t))
    tau0, gl = limiting_shear(OIL, None, None)
    c_s, c_n = (float(c) / w for c in differential_sliding(s, w))
    kin = kinematics(s, w)
    spins = {"screw": float(kin.spin_screw) / w, "nut": float(kin.spin_nut) / w}
    asperity = lubricant = 0.0
    for c in st.contacts:
        if c.balls == 0:
            continue
        asp, lub, _ = full_contact_power(
            a=np.atleast_1d(c.hertz.a), b=np.atleast_1d(c.hertz.b),
            p_max=np.atleast_1d(c.hertz.p_max), asperity_share=np.atleast_1d(c.asperity_share),
            viscosity=np.atleast_1d(c.viscosity), pressure_viscosity=alpha,
            film=np.atleast_1d(c.film_central), curvature=c_s if c.side == "screw" else c_n,
            spin=spins[c.side], screw_speed=np.atleast_1d(w), tau0=tau0, gamma_l=gl, mu0=0.1,
        )  # fmt: skip
        asperity += c.balls * float(asp[0])
        lubricant += c.balls * float(lub[0])
    assert float(r.components["asperity"]) == pytest.approx(asperity, rel=1e-9)
    assert float(r.components["lubricant"]) == pytest.approx(lubricant, rel=1e-9)


def test_full_model_inputs_and_the_study_constants() -> None:
    from ballscrew.friction import get_model

    p = get_model("harris-full").parameters
    assert (p["mu0"], p["asperity_b"], p["asperity_c"]) == (0.1, 1.42, 0.8)  # the study's
    kw = {"speed": 10.0, "temperature": 40.0, "model": "harris-full"}
    friction_torque(reference_screw(), OIL, nodes=(2, 2), **kw)  # type: ignore[arg-type]
    with pytest.raises(BallScrewInputError, match="nodes"):
        friction_torque(reference_screw(), OIL, nodes=(1, 8), **kw)  # type: ignore[arg-type]


@pytest.mark.parametrize(("model", "rel"), [("harris-simplified", 1e-12), ("harris-full", 1e-9)])
def test_harris_models_general_law_at_its_default_exponent_is_eq5(model: str, rel: float) -> None:
    kw = {"speed": 150.0, "temperature": 40.0, "model": model}
    harmonic = friction_torque(reference_screw(), OIL, **kw)  # type: ignore[arg-type]
    general = friction_torque(reference_screw(), OIL, rheology_model="general", **kw)  # type: ignore[arg-type]
    assert float(general.total) == pytest.approx(float(harmonic.total), rel=rel)


def test_eyring_law_needs_its_stress() -> None:
    # No default: no published Eyring stress fits every oil.
    kw = {"speed": 10.0, "temperature": 40.0, "rheology_model": "eyring"}
    for model in ("harris-simplified", "harris-full"):
        with pytest.raises(BallScrewInputError, match="eyring_stress"):
            friction_torque(reference_screw(), OIL, model=model, **kw)  # type: ignore[arg-type]
        r = friction_torque(reference_screw(), OIL, model=model, eyring_stress=5e6, **kw)  # type: ignore[arg-type]
        assert float(r.total) > 0.0


def test_viscoelastic_edge_cases_one_ball_and_no_speed() -> None:
    # A nut with a single loaded ball still has friction; with the leading
    # edge switched off, a ball at rest has exactly none (not NaN).
    s = reference_screw().replace(nut="single", preload=0.0, circuits=1, loaded_turns=0.08)
    assert s.balls_per_nut == 1
    r = friction_torque(s, OIL, speed=50.0, temperature=40.0, axial_load=500.0,
                        model="viscoelastic")  # fmt: skip
    assert float(r.total) > 0.0
    c = viscoelastic_contact(29.0, 0.0, 3.175e-3, leading_edge=False)
    assert float(c.friction) == 0.0


def test_full_model_slip_is_the_same_for_every_law_in_the_newtonian_limit() -> None:
    # With spin and Heathcote sliding the slip is not zero; far below every
    # law's limits all laws are Newtonian, so they must find the same slip.
    kw = {"curvature": 400.0, "spin": 0.3, "tau0": 1e30, "eyring_stress": 1e30}
    slips = [float(_spin_contact(rheology_model=law, **kw)[2][0])
             for law in ("harmonic", "general", "eyring", "bair-winer")]  # fmt: skip
    assert abs(slips[0]) > 0.0
    np.testing.assert_allclose(slips, slips[0], rtol=1e-6)


def test_full_model_node_counts_and_a_single_ball() -> None:
    kw = {"speed": 60.0, "temperature": 40.0, "model": "harris-full"}
    coarse = friction_torque(reference_screw(), OIL, nodes=(6, 6), **kw)  # type: ignore[arg-type]
    fine = friction_torque(reference_screw(), OIL, nodes=(6, 48), **kw)  # type: ignore[arg-type]
    assert float(coarse.total) != float(fine.total)  # the angular count is used
    one = reference_screw().replace(nut="single", preload=0.0, circuits=1, loaded_turns=0.08)
    assert float(friction_torque(one, OIL, axial_load=500.0, **kw).total) > 0.0  # type: ignore[arg-type]
