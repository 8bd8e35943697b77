"""The complete model and its loss laws, against independent numbers and limits."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from scipy import integrate, special
from scipy.optimize import brentq

from ballscrew import BallScrew, friction_torque, reference_screw
from ballscrew import rolling_losses as rl
from ballscrew.errors import BallScrewValidityWarning
from ballscrew.friction.complete import BALL_TRAIN_CONSTANT, BALL_TRAIN_SCATTER
from ballscrew.friction.harris_full import full_contact_power
from ballscrew.kinematics import differential_sliding, four_point_spin, kinematics
from ballscrew.lubricants import get as get_lubricant
from ballscrew.state import operating_state
from ballscrew.study.validation import ReferenceCase, load_cases
from shared import MINERAL

OIL = MINERAL
RPM = 2.0 * math.pi / 60.0


# --- spin and differential sliding -------------------------------------------------------
def test_spin_integral_reaches_johnsons_circle_and_the_thin_ellipse() -> None:
    # Circle in full-slip spin: M = 3*pi/16 mu Q a (Johnson 1985, §8.4), i.e. I = pi^2/8.
    # A long thin ellipse: M = 3/8 mu Q a (the end value of Houpert's pivoting factor), I = pi/4.
    # Tolerances: the 12 x 48 rule is exact to 1e-12 for the circle (smooth in polar
    # coordinates); the thin limit is taken at b/a = 1e-6, which itself moves I by < 1e-5.
    assert float(rl.spin_sliding_integral(0.0, 1.0)) == pytest.approx(math.pi**2 / 8, rel=1e-10)
    assert float(rl.spin_sliding_integral(0.0, 1e-6)) == pytest.approx(math.pi / 4, rel=5e-4)


@pytest.mark.parametrize("beta", [0.05, 0.2, 0.5, 0.9])
def test_spin_integral_matches_harris_elliptic_form(beta: float) -> None:
    # Spin alone over an ellipse: M = 3/8 mu Q a E(e), e^2 = 1 - (b/a)^2 (Harris, Rolling
    # Bearing Analysis, friction chapter), i.e. I = pi/4 E(e). Rule error < 2e-4 (kink of |Y|).
    assert float(rl.spin_sliding_integral(0.0, beta)) == pytest.approx(
        math.pi / 4 * special.ellipe(1 - beta**2), rel=3e-4
    )


@pytest.mark.parametrize(("kappa", "beta"), [(0.5, 0.15), (2.0, 0.12), (5.0, 0.3)])
def test_spin_integral_against_adaptive_quadrature(kappa: float, beta: float) -> None:
    # The same integral by scipy's adaptive dblquad over the disk (Cartesian, independent of
    # the polar rule); kinks of |v| make the fixed rule good to about 2e-4 (measured on a
    # 40 x 400 rule), so 1e-3 is the tolerance.
    def f(y: float, x: float) -> float:
        return math.sqrt(max(1 - x * x - y * y, 0.0)) * math.hypot(kappa * y * y + y, beta * x)

    with warnings.catch_warnings():  # quadpack may flag round-off at the disk's rim
        warnings.simplefilter("ignore", integrate.IntegrationWarning)
        ref, _ = integrate.dblquad(
            f, -1, 1, lambda x: -math.sqrt(1 - x * x), lambda x: math.sqrt(1 - x * x), epsabs=1e-9
        )
    assert float(rl.spin_sliding_integral(kappa, beta)) == pytest.approx(ref, rel=1e-3)


@pytest.mark.parametrize("rpm", [100.0, 1000.0])
def test_centre_pivot_sliding_matches_the_zero_traction_solution(rpm: float) -> None:
    # Independent check of the pivot-at-the-centre simplification: harris-full's solver finds
    # the slip that zero net traction requires, for Coulomb friction mu*p (asperity share 1,
    # no fluid). The sliding power is minimal at that slip (its slope is the net traction),
    # so the centre pivot can only be above it, and spin dominates ball screw contacts, so by
    # little. Measured: 1.4e-4 below on the reference screw, i.e. the slip's effect is below
    # the two quadratures' own errors (~1e-4): 0.2 % either way.
    screw = reference_screw()
    st = operating_state(screw, OIL, speed=rpm * RPM, temperature=40.0, hertz_method="exact")
    c_s, c_n = differential_sliding(screw, 1.0)
    unit = kinematics(screw, 1.0)
    mu = 0.07
    for c, curv, spin in (
        (st.contacts[0], c_s, unit.spin_screw),
        (st.contacts[1], c_n, unit.spin_nut),
    ):
        solved, _, _ = full_contact_power(
            a=np.atleast_1d(c.hertz.a), b=np.atleast_1d(c.hertz.b),
            p_max=np.atleast_1d(c.hertz.p_max), asperity_share=np.ones(1),
            viscosity=np.full(1, 1e-3), pressure_viscosity=0.0, film=np.ones(1),
            curvature=float(curv), spin=float(spin), screw_speed=np.atleast_1d(rpm * RPM),
            tau0=0.0, gamma_l=0.0, mu0=mu, nodes=(16, 64),
        )  # fmt: skip
        kappa = abs(float(curv)) * float(c.hertz.a) / abs(float(spin))
        ours = (
            mu * 1.5 / math.pi * float(c.load) * abs(float(spin)) * float(c.hertz.a)
            * float(rl.spin_sliding_integral(kappa, float(c.hertz.b / c.hertz.a)))
        )  # fmt: skip
        assert ours / float(solved[0]) == pytest.approx(1.0, abs=2e-3)


def test_limiting_traction_coefficient_is_the_mean_of_the_limiting_stress() -> None:
    # (1/Q) * integral of (tau0 + gamma_L p) over a Hertz ellipse, by quadrature of the
    # pressure (p = p0 sqrt(1 - r^2), Q = 2/3 pi a b p0); a = 1 mm, b = 0.1 mm, p0 = 1.5 GPa.
    a, b, p0, tau0, gl = 1e-3, 1e-4, 1.5e9, 4e6, 0.05
    q = 2.0 / 3.0 * math.pi * a * b * p0
    integral, _ = integrate.quad(
        lambda r: (tau0 + gl * p0 * math.sqrt(1 - r * r)) * 2 * math.pi * r * a * b, 0, 1
    )
    mean = q / (math.pi * a * b)
    assert float(rl.limiting_traction_coefficient(tau0, gl, mean)) == pytest.approx(
        integral / q, rel=1e-9
    )


def test_unloaded_contact_has_no_traction_coefficient() -> None:
    # p = 0 (an unloaded contact): no area, no traction; not tau0/0.
    assert float(rl.limiting_traction_coefficient(4e6, 0.04, 0.0)) == 0.0


def test_mixed_coefficient_limits_keep_a_full_film_traction() -> None:
    assert float(rl.mixed_friction_coefficient(1.0, 0.1, 0.04)) == 0.1  # boundary only
    assert float(rl.mixed_friction_coefficient(0.0, 0.1, 0.04)) == 0.04  # thick film: not 0


# --- hysteresis ------------------------------------------------------------------------
def test_hysteresis_force_from_the_work_of_the_leading_half() -> None:
    # Tabor's argument (Johnson 1985, §9.2): per unit distance rolled, the pressure does work
    # (1/R_x) * integral over the leading half (x > 0) of p * x dA on the surface it presses
    # down; the fraction alpha is lost. Integrate that over an elliptical Hertz contact.
    b, a, rx, q, alpha = 0.15e-3, 1.2e-3, 2.8e-3, 30.0, 0.01
    p0 = 1.5 * q / (math.pi * a * b)
    work, _ = integrate.dblquad(
        lambda y, x: p0 * math.sqrt(max(1 - (x / b) ** 2 - (y / a) ** 2, 0.0)) * x,
        0, b, lambda x: -a * math.sqrt(1 - (x / b) ** 2), lambda x: a * math.sqrt(1 - (x / b) ** 2),
    )  # fmt: skip
    assert float(rl.hysteresis_rolling_force(q, b, rx, alpha)) == pytest.approx(
        alpha * work / rx, rel=1e-6
    )


# --- rolling resistance -------------------------------------------------------------------
def test_houpert_force_in_dimensional_form() -> None:
    # With U = eta u/(E' Rx), G = alpha E', W = Q/(E' Rx^2) substituted, F_R scales as
    # Rx^0.40, E'^-0.108 and alpha^0.022 (2 - 0.66 - 2*0.47; 1 + 0.022 - 0.66 - 0.47):
    # exponents worked out by hand from the formula's dimensionless form.
    def force(rx: float, e: float, alpha: float) -> float:
        eta, u, q, k = 0.05, 0.5, 200.0, 10.0
        return float(rl.rolling_force_houpert(e, rx, k, alpha * e, eta * u / (e * rx),
                                              q / (e * rx**2)))  # fmt: skip

    base = force(2.5e-3, 2.3e11, 2e-8)
    assert force(5e-3, 2.3e11, 2e-8) / base == pytest.approx(2.0**0.40, rel=1e-12)
    assert force(2.5e-3, 4.6e11, 2e-8) / base == pytest.approx(2.0**-0.108, rel=1e-12)
    assert force(2.5e-3, 2.3e11, 4e-8) / base == pytest.approx(2.0**0.022, rel=1e-12)


def test_rolling_term_follows_houperts_exponents_without_thermal_correction() -> None:
    # F_R ~ U^0.66: speed x 10 and viscosity (temperature) change scale the isothermal rolling
    # term by exactly those powers (the contact geometry does not change with speed).
    s = reference_screw()
    r = friction_torque(
        s, OIL, speed=[100 * RPM, 1000 * RPM], temperature=40.0, thermal_correction=False
    )
    roll = r.components["rolling"]
    assert roll[1] / roll[0] == pytest.approx(10.0**0.66, rel=1e-10)
    r20 = friction_torque(s, OIL, speed=100 * RPM, temperature=20.0, thermal_correction=False)
    eta = OIL.dynamic_viscosity(np.array([20.0, 40.0]))
    assert float(r20.components["rolling"]) / roll[0] == pytest.approx(
        float(eta[0] / eta[1]) ** 0.66, rel=1e-10
    )


def test_thermal_factors_vanish_at_low_speed_and_cap_at_high_speed() -> None:
    assert float(rl.inlet_shear_heating_factor(1e-6, 40.0, 68.0)) == pytest.approx(1.0, abs=1e-12)
    assert float(rl.replenishment_factor(1e-6, 68.0, 30.0, 50.0)) == pytest.approx(1.0, abs=1e-9)
    fast = rl.inlet_shear_heating_factor(np.array([1e3, 1e4, 1e5]), 40.0, 68.0)
    assert np.all(np.diff(fast) < 0.0) and fast[-1] < 0.5


# --- ball-ball sliding ----------------------------------------------------------------------
def _ball_ball_coefficient(
    screw: BallScrew,
    rpm: float,
    temp: float,
    force: float,
    mu_bl: float = 0.1,
    tau0: float | None = None,
    turn: float = 1.0,
) -> float:
    """Mixed-film coefficient of two balls under the ball-train force, from the published
    formulas written out here: Johnson's circle a = (3FR/4E*)^(1/3), R = D_w/4, E* = E'/2;
    Hamrock-Dowson's h_min at k = 1 with one surface's speed omega_b D_w / 2 (omega_b from
    the closed form of the helix kinematics, times ``turn``: 1/cos(alpha) for a 4-point
    ball); Zhou-Hoeprich's exp(-1.42 Lambda^0.8) with the composite roughness of two balls;
    the limiting traction gamma_L + tau0 / p_mean."""
    w = rpm * RPM
    cos_l = math.cos(screw.lead_angle)
    g = screw.gamma
    omega_b = turn * w * screw.pitch_diameter / (2 * screw.ball_diameter * cos_l)
    omega_b *= 1 - g**2 * cos_l**4
    r, ep = screw.ball_diameter / 4, screw.reduced_modulus
    a = (3 * force * r / (4 * ep / 2)) ** (1 / 3)
    p_mean = force / (math.pi * a * a)
    eta = float(OIL.dynamic_viscosity(temp))
    u_par = eta * omega_b * screw.ball_diameter / 2 / (ep * r)
    h = (3.63 * r * u_par**0.68 * (OIL.pressure_viscosity * ep) ** 0.49
         * (force / (ep * r * r)) ** -0.073 * (1 - math.exp(-0.68)))  # fmt: skip
    share = math.exp(-1.42 * (h / (math.sqrt(2) * screw.roughness_ball)) ** 0.8)
    t0 = OIL.limiting_shear_stress if tau0 is None else tau0
    return share * mu_bl + (1 - share) * (OIL.limiting_shear_coefficient + t0 / p_mean)


@pytest.mark.parametrize(("rpm", "temp"), [(100.0, 40.0), (1000.0, 40.0), (1000.0, 20.0)])
def test_ball_ball_power_from_the_ball_spin(rpm: float, temp: float) -> None:
    # Energy balance computed another way: neighbouring balls turn the same way, so their
    # surfaces slide at omega_b * D_w; with the ball-train force c_B * Q and the ball-ball
    # contact's own mixed-film coefficient, the power over all balls divided by the screw
    # speed must equal the torque component.
    s = reference_screw()
    w = rpm * RPM
    r = friction_torque(s, OIL, speed=w, temperature=temp, ball_train_constant=0.05)
    st = operating_state(s, OIL, speed=w, temperature=temp)
    slide = float(kinematics(s, w).ball_speed) * s.ball_diameter
    power = 0.0
    for c in st.contacts:
        if c.side == "screw":
            force = 0.05 * float(c.load)
            power += _ball_ball_coefficient(s, rpm, temp, force) * force * c.balls * slide
    assert float(r.components["ball_ball"]) == pytest.approx(power / w, rel=1e-9)


def test_ball_ball_coefficient_follows_the_film() -> None:
    # Stribeck: boundary at creep speed, falling towards the full-film traction as the speed
    # and the viscosity (a colder oil) build the film.
    s = reference_screw()
    mus = [_ball_ball_coefficient(s, n, 40.0, 1.0) for n in (0.01, 100.0, 3000.0)]
    assert mus[0] == pytest.approx(0.1, abs=1e-3)
    assert mus[0] > mus[1] > mus[2] > OIL.limiting_shear_coefficient
    assert _ball_ball_coefficient(s, 100.0, 20.0, 1.0) < mus[1]


def test_kept_apart_balls_do_not_slide_on_each_other() -> None:
    # Spacer balls or a cage: no ball-ball sliding, and the recirculation push costs only its
    # own friction in the return, F_r v_c per circuit (no compressed train sliding).
    s = reference_screw()
    kw = {"speed": [100 * RPM, 3000 * RPM], "temperature": 40.0}
    full = friction_torque(s, OIL, **kw)  # type: ignore[arg-type]
    assert np.all(full.components["ball_ball"] > 0.0)
    for kind in ("spacer-balls", "cage"):
        kept_screw = s.replace(ball_separation=kind)
        kept = friction_torque(kept_screw, OIL, **kw)  # type: ignore[arg-type]
        assert np.all(kept.components["ball_ball"] == 0.0)
        w = 3000 * RPM
        cos_l, g = math.cos(s.lead_angle), s.gamma
        v_c = w / 2 * (1 - g * cos_l**2) * s.pitch_diameter / 2 / cos_l
        mass = 7850 * math.pi * s.ball_diameter**3 / 6
        push = 0.1 * mass * v_c**2 * 2 * math.pi / s.ball_diameter
        assert float(kept.components["recirculation"][1]) == pytest.approx(
            2 * s.circuits * push * v_c / w, rel=1e-9
        )
    # Spacers take every other place: half the load balls (rounded up), each loaded more.
    spaced = s.replace(ball_separation="spacer-balls")
    assert spaced.balls_per_circuit == (s.balls_per_circuit + 1) // 2


def test_recirculation_by_hand() -> None:
    # Per circuit the bends press the balls outward with m v_c^2 Theta / D_w in all; sliding
    # at mu_bl they need the push F_r, which costs F_r v_c in the return and, as the loaded
    # train's mean compression F_r / 2, mu_BB F_r / 2 * omega_b D_w per loaded ball.
    s = reference_screw()
    rpm, temp = 3000.0, 40.0
    w = rpm * RPM
    r = friction_torque(s, OIL, speed=w, temperature=temp)
    cos_l, g = math.cos(s.lead_angle), s.gamma
    v_c = w / 2 * (1 - g * cos_l**2) * s.pitch_diameter / 2 / cos_l
    omega_b = w * s.pitch_diameter / (2 * s.ball_diameter * cos_l) * (1 - g**2 * cos_l**4)
    mass = 7850 * math.pi * s.ball_diameter**3 / 6
    push = 0.1 * mass * v_c**2 * 2 * math.pi / s.ball_diameter
    q = float(operating_state(s, OIL, speed=w, temperature=temp).contacts[0].load)
    mu_bb = _ball_ball_coefficient(s, rpm, temp, BALL_TRAIN_CONSTANT * q)
    per_circuit = push * v_c + 0.5 * push * s.balls_per_circuit * mu_bb * omega_b * s.ball_diameter
    circuits = 2 * s.circuits  # both halves of the double nut
    assert float(r.components["recirculation"]) == pytest.approx(
        circuits * per_circuit / w, rel=1e-9
    )
    slow = friction_torque(s, OIL, speed=w / 10, temperature=temp)
    # omega^2 apart from the ball-ball coefficient's own speed dependence
    ratio = float(r.components["recirculation"] / slow.components["recirculation"])
    assert 80 < ratio < 110


# --- four-point contact ------------------------------------------------------------------
def test_four_point_nut_differs_from_the_double_nut_by_its_extra_spin_slip_and_circuits() -> None:
    # Same balls, loads and contacts (see test_models): rolling, sliding and hysteresis are
    # equal; a 4-point ball shares its transverse slip over four contacts (and spins more);
    # the double nut has twice the circuits to recirculate.
    double = reference_screw()
    four = double.replace(nut="single-4point")
    kw = {"speed": [10 * RPM, 1000 * RPM], "temperature": 40.0, "axial_load": 1000.0}
    r4 = friction_torque(four, OIL, **kw)  # type: ignore[arg-type]
    r2 = friction_torque(double, OIL, **kw)  # type: ignore[arg-type]
    for key in ("rolling", "sliding", "hysteresis", "seals"):
        np.testing.assert_allclose(r4.components[key], r2.components[key], rtol=1e-12)
    # Ball-ball sliding: a 4-point ball is one ball of one train and pushes its neighbour
    # once, with c_B times the larger of its two pairs' loads, where each half of the double
    # nut pushes its own train with its own load; and a 4-point ball turns 1/cos(alpha)
    # faster (kinematics.neighbour_sliding), so neighbours slide faster, on a thicker film.
    turn = 1.0 / math.cos(double.contact_angle)
    loads = [float(c.load) for c in operating_state(double, OIL, speed=1.0, temperature=40.0,
                                                    axial_load=1000.0).contacts[::2]]  # fmt: skip
    assert loads[0] != pytest.approx(loads[1], rel=0.05)  # the axial load splits the pairs
    for i, rpm in enumerate((10.0, 1000.0)):
        forces = [BALL_TRAIN_CONSTANT * q for q in loads]
        mu2 = sum(f * _ball_ball_coefficient(double, rpm, 40.0, f) for f in forces)
        push = max(forces)
        mu4 = push * _ball_ball_coefficient(double, rpm, 40.0, push, turn=turn)
        expected = turn * mu4 / mu2
        # The hand formulas reproduce the model's coefficient to ~1e-9 (test above).
        ratio = float(r4.components["ball_ball"][i] / r2.components["ball_ball"][i])
        assert ratio == pytest.approx(expected, rel=1e-6)
    assert np.all(r4.components["four_point"] > 0.0)
    assert np.all(r2.components["four_point"] == 0.0)
    assert np.all(r4.components["helix_slip"] != r2.components["helix_slip"])
    # Each double-nut family recirculates its circuits; the 4-point nut's balls once.
    assert float(r2.components["recirculation"][1]) > 1.5 * float(r4.components["recirculation"][1])


# --- the reference screw's trends (issue 8 targets) ----------------------------------------
def test_reference_screw_trends() -> None:
    s = reference_screw()
    rpm = np.array([100.0, 300.0, 1000.0, 3000.0])
    t40 = friction_torque(s, OIL, speed=rpm * RPM, temperature=40.0).total
    t20 = friction_torque(s, OIL, speed=rpm * RPM, temperature=20.0).total
    assert np.all(np.diff(t40) > 0.0)  # rising with speed above 100 rpm
    ratio = float(t20[2] / t40[2])  # at 1000 rpm
    assert 1.1 <= ratio <= 2.5
    lo = friction_torque(s.replace(preload=1000.0), OIL, speed=1000 * RPM, temperature=40.0)
    hi = friction_torque(s.replace(preload=4000.0), OIL, speed=1000 * RPM, temperature=40.0)
    exponent = math.log(float(hi.total) / float(lo.total)) / math.log(4.0)
    assert 0.5 <= exponent <= 1.1


# --- the complete model's assembly, by energy balances computed another way -------------------
@pytest.mark.parametrize("rpm", [3.0, 150.0])  # asperity share ~0.93 and ~0.57
@pytest.mark.parametrize("nut", ["double", "single-4point"])
def test_complete_components_from_contact_powers(nut: str, rpm: float) -> None:
    # Each component recomputed from the contact states: power of every contact at the
    # entrainment speed of the kinematics (not the lever formula), sliding by harris-full's
    # zero-traction solver with the mixed coefficient, divided by the screw speed. The solver
    # and the centre-pivot integral agree to ~2e-4 (test above): 0.3 % tolerance there.
    screw = reference_screw().replace(nut=nut)
    w, temp, axial = rpm * RPM, 30.0, 800.0
    # A large tau0 (20 MPa) makes tau0 / mean pressure a tenth of the full-film coefficient,
    # so the mean pressure (2/3 p_max) is pinned too.
    tau0 = 2e7
    # A boundary coefficient far from the full-film one makes the asperity share count.
    mu_bl = 0.3
    r = friction_torque(screw, OIL, speed=w, temperature=temp, axial_load=axial,
                        thermal_correction=False, limiting_shear_stress=tau0,
                        boundary_friction=mu_bl)  # fmt: skip
    st = operating_state(screw, OIL, speed=w, temperature=temp, axial_load=axial,
                         hertz_method="exact")  # fmt: skip
    u = float(kinematics(screw, w).entrainment_speed)
    c_s, c_n = differential_sliding(screw, 1.0)
    unit = kinematics(screw, 1.0)
    s4, n4 = four_point_spin(screw, 1.0)
    rolling = hysteresis = sliding = extra = ball_ball = 0.0
    trains: list[tuple[int, float]] = []  # (balls, load) of each train's balls
    for c in st.contacts:
        q, a, b = float(c.load), float(c.hertz.a), float(c.hertz.b)
        f_r = float(rl.rolling_force_houpert(screw.reduced_modulus, c.rx, c.ry / c.rx,
                    c.materials_parameter, c.speed_parameter, c.load_parameter))  # fmt: skip
        rolling += c.balls * 2 * f_r * u / w
        hysteresis += c.balls * 3 / 16 * 0.007 * q * b / c.rx * u / w
        p_mean = q / (math.pi * a * b)
        share = float(c.asperity_share)
        mu = share * mu_bl + (1 - share) * (OIL.limiting_shear_coefficient + tau0 / p_mean)
        screw_side = c.side == "screw"
        curv = float(c_s if screw_side else c_n)
        spins = [float(unit.spin_screw if screw_side else unit.spin_nut)]
        spins.append(abs(float(s4 if screw_side else n4)))
        powers = []
        for spin in spins:
            solved, _, _ = full_contact_power(
                a=np.atleast_1d(a), b=np.atleast_1d(b), p_max=np.atleast_1d(c.hertz.p_max),
                asperity_share=np.ones(1), viscosity=np.full(1, 1e-3), pressure_viscosity=0.0,
                film=np.ones(1), curvature=curv, spin=spin, screw_speed=np.atleast_1d(w),
                tau0=0.0, gamma_l=0.0, mu0=mu, nodes=(16, 64),
            )  # fmt: skip
            powers.append(float(solved[0]))
        sliding += c.balls * powers[0]
        extra += c.balls * (powers[1] - powers[0])
        if screw_side:
            trains.append((c.balls, q))
    # A 4-point ball is one ball of one train: one push, at its larger pair's load; and it
    # turns 1/cos(alpha) faster than a 2-point one (its axis is the screw's;
    # tests/physics/test_four_point_rigid_body.py).
    turn = 1.0
    if nut == "single-4point":
        trains = [(trains[0][0], max(q for _, q in trains))]
        turn = 1 / math.cos(screw.contact_angle)
    for balls, q in trains:
        force = BALL_TRAIN_CONSTANT * q
        mu_bb = _ball_ball_coefficient(screw, rpm, temp, force, mu_bl=mu_bl, tau0=tau0, turn=turn)
        ball_ball += (
            balls * mu_bb * force * turn * float(kinematics(screw, w).ball_speed)
            * (screw.ball_diameter / w)
        )  # fmt: skip
    comp = {k: float(v) for k, v in r.components.items()}
    assert comp["rolling"] == pytest.approx(rolling, rel=1e-12)
    assert comp["hysteresis"] == pytest.approx(hysteresis, rel=1e-12)
    assert comp["ball_ball"] == pytest.approx(ball_ball, rel=1e-9)
    assert comp["sliding"] == pytest.approx(sliding, rel=3e-3)
    if nut == "single-4point":
        assert comp["four_point"] == pytest.approx(extra, rel=3e-3)
    else:
        assert comp["four_point"] == 0.0


def test_thermal_and_replenishment_factors_as_mapped_for_a_screw() -> None:
    # The rolling term with the corrections over the isothermal one equals SKF's factors at
    # n in rpm, d_m in mm, nu in mm^2/s, with the screw mapped to an angular contact bearing
    # of bore d_m - 1.7 D_w and outside diameter d_m + 1.7 D_w (K_rs = 3e-8 oil, 6e-8 grease).
    s = reference_screw()
    n, temp = 2000.0, 40.0
    nu = float(OIL.kinematic_viscosity(temp)) * 1e6
    dm, dw = 40.0, 6.35
    ish = 1 / (1 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)
    for lubrication, k_rs in (("oil", 3e-8), ("grease", 6e-8)):
        rs = math.exp(-k_rs * nu * n * (2 * dm) * math.sqrt(4.4 / (2 * 3.4 * dw)))
        hot = friction_torque(s, OIL, speed=n * RPM, temperature=temp, lubrication=lubrication)
        cold = friction_torque(s, OIL, speed=n * RPM, temperature=temp, thermal_correction=False)
        ratio = float(hot.components["rolling"]) / float(cold.components["rolling"])
        assert ratio == pytest.approx(ish * rs, rel=1e-12)


def test_seal_torque_adds_a_constant() -> None:
    s = reference_screw()
    a = friction_torque(s, OIL, speed=[0.0, 100 * RPM], temperature=40.0)
    b = friction_torque(s, OIL, speed=[0.0, 100 * RPM], temperature=40.0, seal_torque=0.25)
    np.testing.assert_allclose(b.total - a.total, 0.25, rtol=1e-12)


def test_grid_of_loads_equals_point_by_point_and_lift_off_is_finite() -> None:
    # Distinct loads in one call (the spin integral is evaluated once per distinct contact)
    # must give what each load gives alone; past lift-off (F_a > 2.83 F_pr) the relieved
    # half-nut carries nothing and adds nothing.
    s = reference_screw()
    loads = np.array([0.0, 700.0, 2500.0, 6000.0, 9000.0])
    grid = friction_torque(s, OIL, speed=300 * RPM, temperature=40.0, axial_load=loads)
    for load, total in zip(loads, grid.total, strict=True):
        alone = friction_torque(s, OIL, speed=300 * RPM, temperature=40.0, axial_load=load)
        assert float(total) == pytest.approx(float(alone.total), rel=1e-12)
    assert np.all(np.isfinite(grid.total))
    more = friction_torque(s.replace(preload=2100.0), OIL, speed=300 * RPM, temperature=40.0,
                           axial_load=9000.0)  # fmt: skip
    assert float(more.total) == pytest.approx(float(grid.total[-1]), rel=1e-12)


def test_lifted_off_double_nut_equals_a_single_nut_under_the_same_load() -> None:
    # Past lift-off the relieved half-nut carries nothing: the loaded half's balls carry F_a
    # alone, exactly as the balls of a 2-point single nut of the same size do.
    double = reference_screw()
    single = double.replace(nut="single", preload=0.0)
    kw = {"speed": [3 * RPM, 1000 * RPM], "temperature": 40.0, "axial_load": 7000.0}
    a = friction_torque(double, OIL, **kw)  # type: ignore[arg-type]
    b = friction_torque(single, OIL, **kw)  # type: ignore[arg-type]
    np.testing.assert_allclose(a.total, b.total, rtol=1e-12)


def test_interpolated_sliding_integral_matches_the_direct_rule() -> None:
    # Above DIRECT_INTEGRALS distinct pairs the integral is splined; the
    # spline must reproduce the quadrature rule it interpolates (a relative
    # 2e-4 over a range far wider than a ball screw's, where the aspect ratio
    # varies 20-fold; one contact's range is far tighter, see below).
    from ballscrew.friction.complete import _interpolated_integral

    rng = np.random.default_rng(7)
    kappa, beta = rng.uniform(0.0, 2.0, 3000), rng.uniform(0.05, 1.0, 3000)
    np.testing.assert_allclose(
        _interpolated_integral(kappa, beta), rl.spin_sliding_integral(kappa, beta), rtol=2e-4
    )


def test_many_distinct_loads_give_the_directly_integrated_torque(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # 2000 scattered loads (2000 distinct contact sizes) take the spline path;
    # the torque must equal the direct evaluation to a relative 1e-7
    # (interpolation error 1e-8 on one contact's range, plus rounding).
    import ballscrew.friction.complete as module

    rng = np.random.default_rng(3)
    kwargs = dict(
        speed=rng.uniform(1.0, 300.0, 2000),
        temperature=rng.uniform(20.0, 45.0, 2000),
        axial_load=rng.uniform(-4000.0, 4000.0, 2000),
    )
    splined = friction_torque(reference_screw(), OIL, **kwargs).components["sliding"]
    monkeypatch.setattr(module, "DIRECT_INTEGRALS", 10**9)
    direct = friction_torque(reference_screw(), OIL, **kwargs).components["sliding"]
    np.testing.assert_allclose(splined, direct, rtol=1e-7)


def test_sliding_component_carries_the_heathcote_term() -> None:
    # The sliding torque by hand: spin and Heathcote coefficient from the closed forms of the
    # helix kinematics (not the kinematics module), the mixed coefficient from the contact
    # state, the integral on the direct rule. Heathcote adds about 3e-4 to the spin's power,
    # so the 1e-9 tolerance tells its presence.
    s = reference_screw()
    w, temp = 500 * RPM, 40.0
    r = friction_torque(s, OIL, speed=w, temperature=temp)
    st = operating_state(s, OIL, speed=w, temperature=temp, hertz_method="exact")
    cos_l, sin_a, cos_a = (
        math.cos(s.lead_angle),
        math.sin(s.contact_angle),
        math.cos(s.contact_angle),
    )
    g = s.gamma * cos_l**2
    om_m = w / 2 * (1 - g)
    omega_b = w * s.pitch_diameter / (2 * s.ball_diameter * cos_l) * (1 - g * g)
    spin = {"screw": (w - om_m) * sin_a * cos_l, "nut": om_m * sin_a * cos_l}
    heathcote = {
        "screw": (omega_b + (w - om_m) * cos_a * cos_l) / (2 * s.deformed_radius_screw),
        "nut": (omega_b - om_m * cos_a * cos_l) / (2 * s.deformed_radius_nut),
    }
    expected = 0.0
    for c in st.contacts:
        a, b, q = float(c.hertz.a), float(c.hertz.b), float(c.load)
        share = float(c.asperity_share)
        mu = share * 0.1 + (1 - share) * (
            OIL.limiting_shear_coefficient + OIL.limiting_shear_stress / (q / (math.pi * a * b))
        )
        kappa = heathcote[c.side] * a / spin[c.side]
        integral = float(rl.spin_sliding_integral(kappa, b / a))
        expected += c.balls * mu * 1.5 / math.pi * q * spin[c.side] * a * integral / w
    assert float(r.components["sliding"]) == pytest.approx(expected, rel=1e-9)


# --- the fitted ball-train constant ------------------------------------------------------
def _training_cases() -> list[ReferenceCase]:
    return [c for c in load_cases() if c.kind == "catalog" and c.training]


def _case_torque(case: ReferenceCase, c_b: float) -> float:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        r = friction_torque(
            case.screw, get_lubricant(case.lubricant), speed=case.speed_rpm * RPM,
            temperature=case.temperature, axial_load=case.axial_load, model="complete",
            ball_train_constant=c_b,
        )  # fmt: skip
    return float(r.total)


def test_ball_train_constant_is_the_least_squares_fit_of_the_training_cases() -> None:
    # The constant is the minimiser of sum (log T - log T_ref)^2 over the training cases
    # (the makers' drag torques), given to 3 figures: the minimum lies within 0.0358 +- 5e-5,
    # 0.14 %. The loss, quadratic about its minimum, is then lower at the constant than 1 %
    # to either side.
    train = _training_cases()
    assert len(train) >= 5
    ref = np.log([c.reference for c in train])

    def loss(c_b: float) -> float:
        return float(np.sum((np.log([_case_torque(c, c_b) for c in train]) - ref) ** 2))

    at = loss(BALL_TRAIN_CONSTANT)
    assert at < loss(0.99 * BALL_TRAIN_CONSTANT)
    assert at < loss(1.01 * BALL_TRAIN_CONSTANT)


def test_ball_train_scatter_is_the_spread_of_the_per_case_constants() -> None:
    # Per training case, the c_B at which the model meets the makers' torque exactly (the
    # torque grows with c_B); their 16th and 84th percentiles are the stated scatter, given to
    # 4 decimals: within 5e-5, plus 1e-7 for the root finder's tolerance.
    train = _training_cases()

    def exact(case: ReferenceCase) -> float:
        return float(brentq(lambda c: _case_torque(case, c) - case.reference, 1e-4, 0.5,
                            xtol=1e-8))  # fmt: skip

    lo, hi = np.percentile([exact(c) for c in train], [16, 84])
    assert lo == pytest.approx(BALL_TRAIN_SCATTER[0], abs=5e-5 + 1e-7)
    assert hi == pytest.approx(BALL_TRAIN_SCATTER[1], abs=5e-5 + 1e-7)
    assert lo < BALL_TRAIN_CONSTANT < hi


def test_four_point_ball_train_is_the_same_for_either_direction_of_the_load() -> None:
    # A 4-point nut is mirror-symmetric: reversing the axial load swaps its two contact
    # pairs' loads, so every component, the ball train's included (one push per ball at
    # the larger pair's load), is unchanged, to rounding; and the push is the loaded
    # pair's, c_B Q_1 with Q_1 > Q_2 (not the relieved pair's, nor their sum).
    four = reference_screw().replace(nut="single-4point")
    kw = {"speed": [10 * RPM, 1000 * RPM], "temperature": 40.0}
    push = friction_torque(four, OIL, axial_load=1500.0, **kw)  # type: ignore[arg-type]
    pull = friction_torque(four, OIL, axial_load=-1500.0, **kw)  # type: ignore[arg-type]
    for key in ("ball_ball", "recirculation", "sliding", "four_point"):
        np.testing.assert_allclose(push.components[key], pull.components[key], rtol=1e-9)
    loads = [float(c.load) for c in operating_state(four, OIL, speed=1.0, temperature=40.0,
                                                    axial_load=-1500.0).contacts[::2]]  # fmt: skip
    assert loads[0] > 1.5 * loads[1]
    force = BALL_TRAIN_CONSTANT * loads[0]
    turn = 1.0 / math.cos(four.contact_angle)
    for i, rpm in enumerate((10.0, 1000.0)):
        mu_bb = _ball_ball_coefficient(four, rpm, 40.0, force, turn=turn)
        w = rpm * RPM
        ball_speed = float(kinematics(four, w).ball_speed)
        expected = four.balls_per_nut * mu_bb * force * turn * ball_speed * four.ball_diameter / w
        assert float(pull.components["ball_ball"][i]) == pytest.approx(expected, rel=1e-9)
