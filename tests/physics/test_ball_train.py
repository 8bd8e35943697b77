"""The ball train: closed forms against quadrature, simulation and the ball-by-ball solve."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew import lubricants, reference_screw
from ballscrew.ball_train import (
    angle_scatter,
    bridge_maximum,
    creep_slope,
    expected_train,
    orbital_sensitivity,
    rolling_creep_integrals,
    train_by_ball,
)
from ballscrew.kinematics import kinematics
from ballscrew.rolling_losses import limiting_traction_coefficient, mixed_friction_coefficient
from ballscrew.state import operating_state

OIL = lubricants.get("mineral ISO VG 68")


def test_orbital_sensitivity_is_the_derivative_of_the_bearing_orbital_speed() -> None:
    # omega_m / omega = (1 - D cos(alpha) / d_m) / 2, differentiated numerically (central
    # difference, step 1e-6 rad: truncation error ~1e-12 relative).
    d, dm, alpha, h = 6.35e-3, 41.4e-3, math.radians(45.0), 1e-6

    def log_orbit(a: float) -> float:
        return math.log(0.5 * (1.0 - d * math.cos(a) / dm))

    numeric = (log_orbit(alpha + h) - log_orbit(alpha - h)) / (2.0 * h)
    assert orbital_sensitivity(d, dm, alpha) == pytest.approx(numeric, rel=1e-8)


@pytest.mark.parametrize("aspect", [0.03, 0.1, 0.2, 0.5, 0.9, 1.0])
def test_creep_slope_closed_form_matches_the_quadrature(aspect: float) -> None:
    # G_x(sigma)/sigma at sigma = 1e-3 by direct quadrature on the 40 x 640 rule; the
    # curvature of G_x over 1e-3 and the rule's error on the kink line Y = sigma are
    # below 0.2 % (the rule converges as its angular spacing, 1e-2 rad, times the kink's
    # weight).
    _, g = rolling_creep_integrals(aspect, np.array([1e-3]))
    assert float(creep_slope(aspect)) == pytest.approx(float(g[0]) / 1e-3, rel=2e-3)


def test_creep_limits_are_coulombs() -> None:
    # Far past the spin's own sliding speeds the whole contact slides one way: F = mu Q,
    # P = mu Q dv, i.e. G -> 1 and J -> (2 pi / 3) sigma; at sigma = 1e4 within 1e-6.
    j, g = rolling_creep_integrals(0.2, np.array([1e4]))
    assert float(g[0]) == pytest.approx(1.0, abs=1e-6)
    assert float(j[0]) / 1e4 == pytest.approx(2.0 * math.pi / 3.0, rel=1e-6)


def test_creep_force_is_the_slip_derivative_of_the_power() -> None:
    # Full slip: dP/d(dv) = F, i.e. (3/2pi) dJ/dsigma = G; central difference, step 1e-3.
    sigma = np.array([0.05 - 1e-3, 0.05, 0.05 + 1e-3])
    j, g = rolling_creep_integrals(0.3, sigma)
    assert 1.5 / math.pi * (j[2] - j[0]) / 2e-3 == pytest.approx(g[1], rel=1e-3)


def test_bridge_maximum_matches_simulation_and_the_brownian_limit() -> None:
    # 40000 simulated Gaussian bridges per length: standard error of the mean maximum
    # below 0.5 % of it, so 2 % is four standard errors.
    rng = np.random.default_rng(7)
    for n in (2, 7, 30):
        x = rng.standard_normal((40000, n))
        x -= x.mean(axis=1, keepdims=True)
        sums = np.concatenate((np.zeros((40000, 1)), np.cumsum(x, axis=1)), axis=1)
        assert float(bridge_maximum(n)) == pytest.approx(sums.max(axis=1).mean(), rel=0.02)
    # Large N: the Brownian bridge's sqrt(pi N / 8), less the discrete walk's
    # overshoot, which stays bounded (about 0.58 for Gaussian steps).
    big = 10000
    assert math.sqrt(math.pi * big / 8.0) - float(bridge_maximum(big)) == pytest.approx(
        0.58, abs=0.03
    )


def test_angle_scatter_is_the_turn_of_the_line_of_centres() -> None:
    # Exact geometry: the line through the two groove centres, A = (fs + fn - 1) D apart,
    # its axial leg moved by dz; to first order in dz / A (1e-3 here: 0.1 % second order).
    d, fs, fn, alpha, dz = 6.35e-3, 0.55, 0.56, math.radians(40.0), 0.7e-6
    a = (fs + fn - 1.0) * d
    exact = math.atan2(a * math.sin(alpha) + dz, a * math.cos(alpha)) - alpha
    assert angle_scatter(dz, d, fs, fn, alpha) == pytest.approx(exact, rel=2e-3)


def _reference_contacts(rpm: float) -> tuple[tuple[float, float, float], ...]:
    """The reference screw's screw and nut contacts: (mu Q, |omega_s| a / omega, b/a)."""
    screw = reference_screw()
    st = operating_state(screw, OIL, speed=rpm * math.pi / 30.0, temperature=40.0)
    unit = kinematics(screw, 1.0)
    spin = {"screw": abs(float(unit.spin_screw)), "nut": abs(float(unit.spin_nut))}
    out = []
    for c in st.contacts[:2]:
        mean_pressure = 2.0 / 3.0 * float(c.hertz.p_max)
        mu = float(mixed_friction_coefficient(
            c.asperity_share, 0.1,
            limiting_traction_coefficient(OIL.limiting_shear_stress,
                                          OIL.limiting_shear_coefficient, mean_pressure),
        ))  # fmt: skip
        a = float(c.hertz.a)
        out.append((mu * float(c.load), spin[c.side] * a, 1.0 / float(c.hertz.ellipticity)))
    return tuple(out)


def _stiffness(contacts: tuple[tuple[float, float, float], ...]) -> float:
    c_s, c_n = (q * float(creep_slope(b)) / s for q, s, b in contacts)
    return 4.0 * c_s * c_n / (c_s + c_n)


@pytest.mark.slow
@pytest.mark.parametrize("scatter_deg", [0.3, 1.0])
def test_closed_form_agrees_with_the_ball_by_ball_train(scatter_deg: float) -> None:
    # 300 drawn trains of the reference screw's 49 balls a circuit, each solved ball by ball
    # with the nonlinear creep law (tables of direct quadrature), against the closed form.
    # The mean compression's standard error over 300 draws is about 3 % (its spread is about
    # half its mean); the linearised law errs by the curvature of G_x over the creeps met
    # (sigma up to ~0.03 at 1 degree: the concave law then gives up to 3 % less than the
    # linear one). Pass: within 4 standard errors plus that 3 %.
    screw = reference_screw()
    contacts = _reference_contacts(100.0)
    unit = kinematics(screw, 1.0)
    centre = float(unit.orbital_speed) * 0.5 * screw.pitch_diameter / math.cos(screw.lead_angle)
    k = orbital_sensitivity(screw.ball_diameter, screw.pitch_diameter, screw.contact_angle)
    spread = centre * k * math.radians(scatter_deg)
    n = screw.balls_per_circuit
    rng = np.random.default_rng(11)
    mean_p, mean_t, creep = [], [], []
    for _ in range(300):
        natural = spread * rng.standard_normal(n)
        sol = train_by_ball(natural, (contacts[0], contacts[1]))
        assert np.all(sol.compression >= 0.0)  # balls push, never pull
        assert abs(sol.traction.sum()) < 1e-9 * np.abs(sol.traction).sum()
        mean_p.append(sol.compression.mean())
        mean_t.append(np.abs(sol.traction).mean())
        creep.append(sol.creep_power / n)
    means = expected_train(_stiffness(contacts), spread, n)
    err = np.std(mean_p) / math.sqrt(len(mean_p))
    curvature = 0.03 * scatter_deg
    assert float(means.compression) == pytest.approx(
        np.mean(mean_p), abs=4.0 * err + curvature * np.mean(mean_p)
    )
    err_t = np.std(mean_t) / math.sqrt(len(mean_t))
    assert float(means.traction) == pytest.approx(
        np.mean(mean_t), abs=4.0 * err_t + curvature * np.mean(mean_t)
    )
    # The creep dissipation is second order (1/2 K delta^2): same draws, 10 % (its spread
    # over draws is about 20 %, over 300 draws about 1.2 %, plus the law's curvature).
    assert float(means.creep_power) == pytest.approx(np.mean(creep), rel=0.1)


def test_train_force_grows_as_the_square_root_of_the_train_and_with_the_scatter() -> None:
    # Closed form: M_N tends to sqrt(pi N / 8) less a bounded overshoot (about 0.58), so
    # quadrupling the train doubles the force but for that offset; linear in the scatter.
    ratio = float(bridge_maximum(400) / bridge_maximum(100))
    root = math.sqrt(math.pi / 8.0)
    assert ratio == pytest.approx((root * 20.0 - 0.58) / (root * 10.0 - 0.58), rel=0.005)
    one = expected_train(1.0, 1e-5, 50)
    two = expected_train(1.0, 2e-5, 50)
    assert float(two.compression) == pytest.approx(2.0 * float(one.compression), rel=1e-12)


def test_one_ball_train_has_no_push() -> None:
    m = expected_train(1000.0, 1e-5, 1)
    assert float(m.compression) == 0.0
    assert float(m.traction) == 0.0


def test_ball_by_ball_train_pushes_only_and_balances() -> None:
    # Three balls: the rear one naturally fastest. The rear ball drives, the two ahead are
    # held back; the compressions are the running sums of the tractions, never negative.
    contacts = ((5.0, 1e-3, 0.2), (5.0, 1e-3, 0.2))
    sol = train_by_ball(np.array([2e-6, -1e-6, -1e-6]), contacts)
    assert sol.traction[0] > 0.0 > sol.traction[1]
    assert sol.compression[0] == pytest.approx(sol.traction[0], rel=1e-9)
    assert sol.compression[1] == pytest.approx(sol.traction[0] + sol.traction[1], abs=1e-12)
    assert np.all(sol.compression >= 0.0)


def test_input_checks() -> None:
    with pytest.raises(ValueError):
        creep_slope(0.0)
    with pytest.raises(ValueError):
        bridge_maximum(0)


def test_bridge_maximum_is_elementwise() -> None:
    many = bridge_maximum([2, 7, 30])
    assert [float(v) for v in many] == [float(bridge_maximum(n)) for n in (2, 7, 30)]


@pytest.mark.parametrize("creep", [2e-3, 1e-4])
def test_two_ball_train_in_the_linear_regime(creep: float) -> None:
    # Two balls whose natural speeds are m + d and m - d, with unlike contacts (a slender
    # and a round ellipse, different capacities and spin scales): the train runs at m,
    # each ball is held off by d, its contacts share the creep 2d so that their forces
    # mu Q G_x'(beta) dv / (omega_s a) are equal (springs in series), the traction is
    # K d, K = 4 c_s c_n / (c_s + c_n), the compression between them K d, and the creep
    # dissipates 1/2 K d^2 per ball. ``creep`` sets the screw contact's creep ratio: the
    # quadrature's G_x/sigma there matches the closed-form slope within 5e-4 (the rule's
    # kink line), so the forces within 1e-3; the tables' linear interpolation of J
    # (node spacing 2.5e-4, J quadratic) errs by h^2/(4 sigma^2), 0.4 % at 2e-3, so the
    # dissipation within 0.8 % (at 1e-4, below one node, only the forces are checked).
    screw_contact, nut_contact = (3.0, 2e-4, 0.05), (2.0, 1e-4, 1.0)
    c_s, c_n = (q * float(creep_slope(b)) / s for q, s, b in (screw_contact, nut_contact))
    stiffness = 4.0 * c_s * c_n / (c_s + c_n)
    shift = 2.0 * stiffness / c_s  # the screw contact's creep per unit d (its share of 2d)
    d = creep * screw_contact[1] / shift
    m = 3.0 * d
    sol = train_by_ball(np.array([m + d, m - d]), (screw_contact, nut_contact))
    assert sol.speed == pytest.approx(0.0, abs=1e-9 * d)
    assert sol.traction[0] == pytest.approx(stiffness * d, rel=1e-3)
    assert sol.traction[1] == pytest.approx(-stiffness * d, rel=1e-3)
    assert sol.compression[0] == pytest.approx(stiffness * d, rel=1e-3)
    if creep > 1e-3:
        assert sol.creep_power == pytest.approx(stiffness * d * d, rel=8e-3)
