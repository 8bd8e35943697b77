"""Olaru's model: each moment and force turned into torque by an energy balance.

The model states its equations (module docstring of ballscrew.friction.olaru, after Olaru et
al. 2005 and Houpert 2002); here each torque component is rebuilt from the contact states and
the kinematics, by the power each term dissipates, not by the model's lever arms. A screw with
a large pitch diameter and small balls keeps Houpert's spin parameter E below 1, so the
curvature (Heathcote) moment is active as well as the pivoting one.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew import BallScrew, friction_torque, reference_screw
from ballscrew import rolling_losses as rl
from ballscrew.loads import ball_loads
from ballscrew.state import operating_state
from shared import MINERAL

OIL = MINERAL


def _houpert_fc(e: float) -> float:  # Houpert's curvature factor, E in [0, 1]
    e = min(max(e, 0.0), 1.0)
    return max(1.0026 - 0.1653 * e - 0.2638 * e**2 - 2.5521 * e**3 + 1.9749 * e**4, 0.0)


def _houpert_fp(e: float) -> float:  # Houpert's pivoting factor, E in [0, 1]
    e = min(max(e, 0.0), 1.0)
    return 0.0042 + 1.1045 * e + 0.4625 * e**2 - 0.5648 * e**3


@pytest.mark.parametrize("axial", [0.0, 3000.0])
def test_olaru_components_by_their_dissipated_power(axial: float) -> None:
    screw = BallScrew(
        pitch_diameter=0.100, lead=0.010, ball_diameter=3.175e-3,
        contact_angle=math.radians(45), conformity_screw=0.54, conformity_nut=0.54,
        loaded_turns=2.5, circuits=2, nut="double", preload=3000.0,
    )  # fmt: skip
    w, temp = 200 * math.pi / 30, 40.0
    r = friction_torque(screw, OIL, speed=w, temperature=temp, axial_load=axial, model="olaru")
    st = operating_state(screw, OIL, speed=w, temperature=temp, axial_load=axial,
                         hertz_method="houpert")  # fmt: skip
    # Olaru's model keeps the bearing kinematics of its paper (helix neglected): rolling
    # speed omega d_m (1 - gamma^2) / 4, spins (1 +- gamma) omega sin(alpha) / 2.
    g, sin_a = screw.gamma, math.sin(screw.contact_angle)
    u = w * screw.pitch_diameter * (1 - g * g) / 4
    cos_l = math.cos(screw.lead_angle)
    dw = screw.ball_diameter
    ra = 0.5 * dw * 1.05 / 1.025  # kappa = 0.05
    spins = {"screw": w * (1 + g) * sin_a / 2, "nut": w * (1 - g) * sin_a / 2}
    rolling = curvature = pivoting = hysteresis = 0.0
    e_values = []
    for c in st.contacts:
        q, a = float(c.load), float(c.hertz.a)
        if q == 0.0:
            continue
        mu = 0.1 * float(c.asperity_share)
        f_r = float(rl.rolling_force_houpert(screw.reduced_modulus, c.rx, c.ry / c.rx,
                    c.materials_parameter, c.speed_parameter, c.load_parameter))  # fmt: skip
        # F_R resists both surfaces (2 F_R u); the model's arm R_s cos(l)(1 + gamma) is the
        # energy arm d_m(1 - gamma^2)/2 per F_R times cos(l): the force acts along the helix.
        rolling += c.balls * 2 * f_r * u / w * cos_l
        e = 2 * ra / a * dw * math.sin(screw.contact_angle) / screw.pitch_diameter
        e_values.append(e)
        m_c = 0.0806 * mu * q * a**2 / ra * _houpert_fc(e)
        m_er = 7.48e-7 * (dw / 2) ** 0.33 * q**1.33 * (1 - 3.519e-3 * (c.ry / c.rx - 1) ** 0.806)
        # Rolling-resistance moments act on the ball, which turns at omega_b; the model puts
        # them on the screw through the tangential force M/D_w at the screw contact.
        lever = screw.contact_radius_screw * cos_l
        curvature += c.balls * lever * m_c / dw
        hysteresis += c.balls * lever * m_er / dw
        pivoting += c.balls * 0.375 * mu * q * a * _houpert_fp(e) * spins[c.side] / w
    assert max(e_values) < 1.0  # the curvature term is exercised
    comp = {k: float(v) for k, v in r.components.items()}
    assert comp["rolling"] == pytest.approx(rolling, rel=1e-9)
    assert comp["curvature"] == pytest.approx(curvature, rel=1e-9) and curvature > 0.0
    assert comp["pivoting"] == pytest.approx(pivoting, rel=1e-9)
    assert comp["hysteresis"] == pytest.approx(hysteresis, rel=1e-9)
    assert np.isclose(comp["ball_ball"], 0.0)


def _reference_parts(**params: object) -> tuple[dict[str, float], object]:
    s = reference_screw()
    r = friction_torque(s, OIL, speed=1500 * math.pi / 30, temperature=40.0, model="olaru",
                        **params)  # type: ignore[arg-type]  # fmt: skip
    return {k: float(v) for k, v in r.components.items()}, s


def test_ball_ball_force_term() -> None:
    # F_B at each ball: a friction moment mu_b (D_w/2) F_B and half the force itself on the
    # screw-side tangential force (Olaru's ball equilibrium), over every loaded ball.
    fb, mu_b = 0.8, 0.12
    parts, s = _reference_parts(ball_ball_force=fb, ball_ball_friction=mu_b)
    lever = s.contact_radius_screw * math.cos(s.lead_angle)  # type: ignore[attr-defined]
    balls = 2 * s.balls_per_nut  # type: ignore[attr-defined]
    expected = balls * lever * (mu_b * 0.5 * fb + 0.5 * fb)
    assert parts["ball_ball"] == pytest.approx(expected, rel=1e-12)


def test_speed_fit_friction_coefficient() -> None:
    # The public code's fit mu = exp(-2.643 - 0.002 n - 4.983e-7 n^2), n in rpm (attributed to
    # Hoeprich), the same at every contact; the pivoting power follows with that mu.
    n = 1500.0
    w = n * math.pi / 30
    mu_fit = math.exp(-2.643 - 0.002 * n - 4.983e-7 * n**2)
    fit, s = _reference_parts(sliding_friction="speed-fit")
    st = operating_state(reference_screw(), OIL, speed=w, temperature=40.0,
                         hertz_method="houpert")  # fmt: skip
    g, sin_a = s.gamma, math.sin(s.contact_angle)  # type: ignore[attr-defined]
    spins = {"screw": w * (1 + g) * sin_a / 2, "nut": w * (1 - g) * sin_a / 2}  # Olaru's
    ra = 0.5 * s.ball_diameter * 1.05 / 1.025  # type: ignore[attr-defined]
    ratio = s.ball_diameter * math.sin(s.contact_angle) / s.pitch_diameter  # type: ignore[attr-defined]
    expected = sum(
        c.balls * 0.375 * mu_fit * float(c.load) * float(c.hertz.a)
        * _houpert_fp(2 * ra / float(c.hertz.a) * ratio) * spins[c.side] / w
        for c in st.contacts
    )  # fmt: skip
    assert fit["pivoting"] == pytest.approx(expected, rel=1e-9)


def test_spin_parameter_warning_names_the_models_value() -> None:
    # E = (2 R_a / a)(D_w sin(alpha) / d_m) at the heaviest ball load, with Houpert's semi-axis.
    import warnings

    from ballscrew import contact
    from ballscrew.errors import BallScrewValidityWarning

    s = reference_screw()
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", BallScrewValidityWarning)
        r = friction_torque(s, OIL, speed=10.0, temperature=40.0, model="olaru")
    (issue,) = [i for i in r.warnings if i.quantity.startswith("spin parameter E")]
    assert caught
    q = float(ball_loads(s, 0.0).normal_load_1)
    ra = 0.5 * s.ball_diameter * 1.05 / 1.025
    values = [
        2 * ra / float(contact.hertz(q, rx, ry, s.reduced_modulus, method="houpert").a)
        * s.ball_diameter * math.sin(s.contact_angle) / s.pitch_diameter
        for rx, ry in ((s.rx_screw, s.ry_screw), (s.rx_nut, s.ry_nut))
    ]  # fmt: skip
    assert issue.value == pytest.approx(max(values), rel=1e-12)
    assert (issue.low, issue.high) == (0.0, 1.0)


@pytest.mark.parametrize("ball_ball_force", [0.0, 0.8])
def test_lifted_off_double_nut_equals_a_single_nut(ball_ball_force: float) -> None:
    # Past lift-off the relieved half-nut's balls carry nothing and add nothing.
    double = reference_screw()
    single = double.replace(nut="single", preload=0.0)
    kw = {"speed": [3.0, 100.0], "temperature": 40.0, "axial_load": 7000.0, "model": "olaru",
          "ball_ball_force": ball_ball_force}  # fmt: skip
    a = friction_torque(double, OIL, **kw)  # type: ignore[arg-type]
    b = friction_torque(single, OIL, **kw)  # type: ignore[arg-type]
    np.testing.assert_allclose(a.total, b.total, rtol=1e-12)
