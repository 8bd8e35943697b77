"""The flooded nut: oil shear between neighbouring balls, ball churning, no starvation.

Each law of :mod:`ballscrew.rolling_losses` that only a nut full of oil has, against a
computation made another way (a numerical integral, a limit, measured drag coefficients),
and the complete model's terms against the lubrication method and the targets of T(20 °C)/
T(40 °C) for a flooded nut.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from scipy.integrate import quad

from ballscrew import friction_torque, lubricants, reference_screw
from ballscrew import rolling_losses as rl
from ballscrew.errors import BallScrewInputError, BallScrewValidityWarning
from ballscrew.kinematics import kinematics, neighbour_sliding, rpm_to_rad_s
from ballscrew.lubricant import lubrication_method

OIL = lubricants.get("mineral ISO VG 68")
R = 3.175e-3  # radius of the reference screw's 6.35 mm balls [m]


def _meniscus_by_quadrature(eta: float, v0: float, h0: float, r_in: float, r_out: float) -> float:
    """The defining integral, eta v(r)^2 / h(r) over the ring, by adaptive quadrature."""

    def integrand(r: float) -> float:
        gap = h0 + 2.0 * (R - math.sqrt(R * R - r * r))
        speed = v0 * math.sqrt(1.0 - (r / R) ** 2)
        return eta * speed**2 / gap * 2.0 * math.pi * r

    # Most of the integral lies within a few sqrt(R h0) of the axis: split there.
    knee = min(r_out, max(r_in, 10.0 * math.sqrt(R * h0)))
    first = quad(integrand, r_in, knee, epsabs=0.0, epsrel=1e-12, limit=200)[0]
    return first + quad(integrand, knee, r_out, epsabs=0.0, epsrel=1e-12, limit=200)[0]


@pytest.mark.parametrize(
    ("h0", "r_in", "r_out"),
    [(0.2e-6, 0.0, R), (0.05e-6, 30e-6, R), (5e-6, 0.0, 1e-3), (0.2e-6, 0.5e-3, 2.9e-3)],
)
def test_meniscus_power_is_its_integral(h0: float, r_in: float, r_out: float) -> None:
    # Closed form against quadrature of eta v^2/h 2 pi r dr with the sphere's exact gap and
    # the local sliding speed; both are exact, so only rounding (1e-9) separates them.
    closed = float(rl.meniscus_shear_power(0.058, 2.2, R, h0, r_in, r_out))
    assert closed == pytest.approx(_meniscus_by_quadrature(0.058, 2.2, h0, r_in, r_out), rel=1e-9)


def test_meniscus_near_the_axis_is_the_parabolic_gap() -> None:
    # Within r_m << R the gap is h0 + r^2/R and the speed v0: P = pi eta v0^2 R ln(1 +
    # r_m^2/(R h0)), a second closed form; they part by O(r_m^2/R^2) = 0.3 % at r_m = R/20.
    r_m = R / 20.0
    parabolic = math.pi * 0.058 * 2.2**2 * R * math.log(1.0 + r_m**2 / (R * 0.2e-6))
    closed = float(rl.meniscus_shear_power(0.058, 2.2, R, 0.2e-6, 0.0, r_m))
    assert closed == pytest.approx(parabolic, rel=5e-3)
    # An empty ring dissipates nothing; a thinner gap more (the logarithm).
    assert float(rl.meniscus_shear_power(0.058, 2.2, R, 0.2e-6, 1e-3, 1e-3)) == 0.0
    thin, thick = (float(rl.meniscus_shear_power(0.058, 2.2, R, h)) for h in (0.1e-6, 1e-6))
    assert thin / thick == pytest.approx(math.log(2 * R / 0.1e-6) / math.log(2 * R / 1e-6), rel=0.1)


# Measured drag coefficients of smooth spheres (Re, C_D), as listed from the standard drag
# curve by the Indiana University of Pennsylvania's calculus project
# (www.ma.iup.edu/projects/CalcDEMma/drag/drag7.html), from Re 3 to 1.7e5; its values below
# Re = 1 lie 15-20 % above Stokes's exact law and are left out (the limit is tested below).
MEASURED = [
    (3.020, 10.86), (7.015, 5.623), (15.49, 3.388), (57.54, 1.479), (144.5, 0.9204),
    (264.9, 0.7194), (512.9, 0.5623), (1000.0, 0.4786), (1862.0, 0.4365), (3162.0, 0.4074),
    (4764.0, 0.3890), (8375.0, 0.3981), (1.556e4, 0.4395), (2.648e4, 0.4571),
    (3.467e4, 0.4775), (5.888e4, 0.4732), (1e5, 0.4624), (1.702e5, 0.4395),
]  # fmt: skip


def test_sphere_drag_follows_the_measured_curve() -> None:
    # Schiller-Naumann is within 10 % of the curve below Re 1000; Newton's constant 0.44
    # stands for a curve that wanders between 0.39 and 0.48 above it: 15 % covers both, and a
    # slip in either constant of the law (0.15, 0.687) moves C_D by 30 % or more at Re 500.
    re, measured = np.array(MEASURED).T
    np.testing.assert_allclose(rl.sphere_drag_coefficient(re), measured, rtol=0.15)
    # From Re 100 to 600, where Schiller and Naumann fitted their law, it meets these data to
    # within 1 %: 3 % there, so that a 10 % slip in its 0.15 (+9 % at Re 265) fails.
    middle = (re > 100.0) & (re < 600.0)
    np.testing.assert_allclose(rl.sphere_drag_coefficient(re[middle]), measured[middle], rtol=0.03)


def test_sphere_drag_has_stokes_limit_and_refuses_no_flow() -> None:
    # Stokes (1851): C_D Re / 24 -> 1; the inertia correction is 0.15 Re^0.687 = 0.6 % at 0.001.
    assert float(rl.sphere_drag_coefficient(1e-3)) * 1e-3 / 24.0 == pytest.approx(1.0, rel=1e-2)
    with pytest.raises(BallScrewInputError, match="reynolds"):
        rl.sphere_drag_coefficient([10.0, 0.0])


def test_churning_is_stokes_drag_when_slow_and_quadratic_when_fast() -> None:
    # Creeping flow: F = 3 pi eta D v (Stokes), P = F v, to the 1 % of the inertia correction.
    eta, rho, d = 0.5, 870.0, 6.35e-3
    v = 1e-4  # Re = 1.1e-3
    stokes = 3.0 * math.pi * eta * d * v * v
    assert float(rl.ball_churning_power(eta, rho, v, d)) == pytest.approx(stokes, rel=1e-2)
    # Newton's regime: P = 0.44/2 rho (pi D^2/4) v^3 exactly; at rest nothing.
    fast = float(rl.ball_churning_power(1e-4, rho, 10.0, d))  # Re = 5.5e5 / 10 = 5.5e4
    assert fast == pytest.approx(0.22 * rho * math.pi * d * d / 4.0 * 1000.0, rel=1e-12)
    assert float(rl.ball_churning_power(eta, rho, 0.0, d)) == 0.0


def _complete(lubrication: str, rpm: float, temperature: float, lubricant=OIL, **kw):  # type: ignore[no-untyped-def]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        return friction_torque(
            reference_screw().replace(**kw), lubricant, speed=rpm_to_rad_s(rpm),
            temperature=temperature, model="complete", lubrication=lubrication,
        )  # fmt: skip


@pytest.mark.parametrize("method", ["drip", "oil-air", "auto", "oil"])
def test_without_bulk_oil_the_flooded_terms_are_absent(method: str) -> None:
    r = _complete(method, 1000.0, 40.0)
    assert float(r.components["meniscus"]) == 0.0
    assert float(r.components["churning"]) == 0.0


def test_grease_has_no_flooded_terms_and_cannot_flood() -> None:
    grease = lubricants.get("SKF LGHP 2")
    r = _complete("grease", 1000.0, 40.0, lubricant=grease)
    assert float(r.components["meniscus"]) == float(r.components["churning"]) == 0.0
    assert lubrication_method("auto", grease) == "grease"
    assert lubrication_method("auto", OIL) == lubrication_method("oil", OIL) == "drip"
    with pytest.raises(BallScrewInputError, match="does not fill the nut"):
        _complete("flooded", 1000.0, 40.0, lubricant=grease)
    with pytest.raises(BallScrewInputError, match="lubrication"):
        _complete("bath", 1000.0, 40.0)


def _film(viscosity: float, speed: float, force: float, g: float, ep: float) -> float:
    """Hamrock and Dowson's (1977) minimum film of a circular contact, R = D_w/4 [m].

    H = 3.63 U^0.68 G^0.49 W^-0.073 (1 - exp(-0.68)), U = eta u/(E'R), W = F/(E'R^2).
    """
    radius = R / 2.0
    u_par = viscosity * speed / (ep * radius)
    w_par = force / (ep * radius**2)
    return 3.63 * radius * u_par**0.68 * g**0.49 * w_par**-0.073 * (1.0 - math.exp(-0.68))


@pytest.mark.parametrize(
    ("nut", "temperature", "c_b"),
    [("double", 40.0, None), ("double", 20.0, None), ("double", 40.0, 0.0),
     ("double", 40.0, 0.02), ("single-4point", 20.0, None)],
)  # fmt: skip
def test_flooded_meniscus_term_is_the_sum_over_the_gaps(
    nut: str, temperature: float, c_b: float | None
) -> None:
    # Rebuilt from the geometry: each train's circuits of n loaded balls have n - 1 gaps
    # (a double nut: a train per half; a 4-point nut: one), each sheared (by quadrature) from
    # the Hertz circle of F_B = c_B Q (Hertz: a = (3 F R_e / 2E')^(1/3), R_e = D_w/4) outward,
    # the gap the larger of the ball-ball film (Hamrock-Dowson at one surface's speed,
    # omega_b D_w / 2) and the composite roughness; no force, no circle and the roughness gap.
    # The default c_B gives F_B = 1.04 N, whose film is 0.12 um at 40 C, 0.26 um at 20 C.
    from ballscrew.friction.complete import BALL_TRAIN_CONSTANT
    from ballscrew.state import operating_state

    s = reference_screw().replace(nut=nut)
    constant = BALL_TRAIN_CONSTANT if c_b is None else c_b
    omega = rpm_to_rad_s(1000.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        r = friction_torque(s, OIL, speed=omega, temperature=temperature, model="complete",
                            lubrication="flooded", ball_train_constant=constant)  # fmt: skip
        state = operating_state(s, OIL, speed=omega, temperature=temperature)
    eta = float(OIL.dynamic_viscosity(temperature))
    v0 = abs(float(neighbour_sliding(s, omega)))
    sigma = math.sqrt(2) * s.roughness_ball
    trains = [c for c in state.contacts if c.side == "screw"][: 1 if nut != "double" else 2]
    total = 0.0
    for c in trains:
        force = constant * float(c.load)
        if force > 0.0:
            a = (3.0 * force * (s.ball_diameter / 4) / (2.0 * s.reduced_modulus)) ** (1 / 3)
            film = _film(eta, v0 / 2, force, float(c.materials_parameter), s.reduced_modulus)
        else:
            a = film = 0.0
        gaps = s.circuits * (s.balls_per_circuit - 1)
        total += gaps * _meniscus_by_quadrature(eta, v0, max(film, sigma), a, R)
    # Quadrature against the closed form (1e-9); Hamrock-Dowson's film here and in the model
    # from the same formula; the Hertz radius from its closed form against the package's
    # exact solution (a circle: 1e-6).
    assert float(r.components["meniscus"]) == pytest.approx(total / omega, rel=1e-6)
    assert float(r.components["meniscus"]) > 0.0


def test_flooded_terms_vanish_at_rest_and_without_a_train() -> None:
    # At zero speed nothing slides or moves through the oil: 0, finite, without a warning.
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        rest = _complete("flooded", 0.0, 40.0)
    assert float(rest.components["meniscus"]) == float(rest.components["churning"]) == 0.0
    # Slow (1 and 2 rpm): the film is below the roughness, the gap stays sigma, so the meniscus
    # power grows as v^2 and its torque as the speed, exactly (Couette shear, no inertia).
    slow = [float(_complete("flooded", n, 40.0).components["meniscus"]) for n in (1.0, 2.0)]
    assert slow[1] / slow[0] == pytest.approx(2.0, rel=1e-9)
    # A 4-point nut: one train, every loaded ball churns once.
    s = reference_screw().replace(nut="single-4point")
    omega = rpm_to_rad_s(1000.0)
    r = _complete("flooded", 1000.0, 40.0, nut="single-4point")
    centre = abs(float(kinematics(s, omega).orbital_speed)) * 0.02 / math.cos(s.lead_angle)
    one = float(
        rl.ball_churning_power(OIL.dynamic_viscosity(40.0), OIL.density(40.0), centre, 6.35e-3)
    )
    assert float(r.components["churning"]) == pytest.approx(
        s.circuits * s.balls_per_circuit * one / omega, rel=1e-12
    )


def test_flooded_rolling_term_has_no_starvation_factor() -> None:
    # Flooded: the inlet shear heating factor alone; drip: times SKF's replenishment factor.
    s = reference_screw()
    nu = float(OIL.kinematic_viscosity(20.0)) * 1e6
    dm, section = 40.0, 3.4 * 6.35
    phi_rs = float(rl.replenishment_factor(1000.0, nu, dm - section / 2, dm + section / 2))
    flooded = float(_complete("flooded", 1000.0, 20.0).components["rolling"])
    drip = float(_complete("drip", 1000.0, 20.0).components["rolling"])
    assert drip / flooded == pytest.approx(phi_rs, rel=1e-12)
    assert phi_rs < 0.9  # a visible difference at 20 °C and 1000 rpm
    del s


def test_flooded_reference_nut_meets_the_temperature_targets() -> None:
    # Issue 50 / the physics map's targets for a flooded nut: T20/T40 0.8-1.3 at 100 rpm,
    # 1.3-2.2 at 1000 rpm; the 100 rpm torque moves under 3 % from the drip-fed nut's.
    def t(method: str, rpm: float, temperature: float) -> float:
        return float(_complete(method, rpm, temperature).total)

    assert 0.8 <= t("flooded", 100.0, 20.0) / t("flooded", 100.0, 40.0) <= 1.3
    assert 1.3 <= t("flooded", 1000.0, 20.0) / t("flooded", 1000.0, 40.0) <= 2.2
    assert t("circulating", 1000.0, 20.0) == t("flooded", 1000.0, 20.0)
    for temperature in (20.0, 40.0):
        moved = t("flooded", 100.0, temperature) / t("drip", 100.0, temperature) - 1.0
        assert 0.0 < moved < 0.03
    # Both flooded terms follow the viscosity: at 1000 rpm they carry more at 20 °C.
    cold, warm = _complete("flooded", 1000.0, 20.0), _complete("flooded", 1000.0, 40.0)
    for name in ("meniscus", "churning"):
        assert float(cold.components[name]) > 1.5 * float(warm.components[name]) > 0.0


def test_spacer_balls_churn_but_do_not_shear_a_meniscus() -> None:
    r = _complete("flooded", 1000.0, 40.0, ball_separation="spacer-balls")
    assert float(r.components["meniscus"]) == 0.0
    assert float(r.components["churning"]) > 0.0
    # Churning: every loaded ball at its orbital speed, as the law gives for one ball.
    s = reference_screw().replace(ball_separation="spacer-balls")
    omega = rpm_to_rad_s(1000.0)
    centre = abs(float(kinematics(s, omega).orbital_speed)) * 0.02 / math.cos(s.lead_angle)
    one = float(
        rl.ball_churning_power(OIL.dynamic_viscosity(40.0), OIL.density(40.0), centre, 6.35e-3)
    )
    balls = 2 * s.circuits * s.balls_per_circuit  # load balls only (spacers left out)
    assert float(r.components["churning"]) == pytest.approx(balls * one / omega, rel=1e-12)
