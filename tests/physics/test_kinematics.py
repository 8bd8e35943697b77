"""Tests of ballscrew.kinematics: rolling speeds and the transverse slip of the helix."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew import BallScrewInputError, reference_screw
from ballscrew.geometry import BallScrew
from ballscrew.kinematics import four_point_spin, kinematics, rpm_to_rad_s


def _rotation_z(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def _rigid_body_check(screw: BallScrew, omega: float) -> dict[str, float]:
    """Speeds computed from explicit rigid motions, independently of the closed forms.

    The screw, seen from the nut, is turned by omega*t about z and advanced by its lead: a
    material point's velocity is the central difference of its position over +-dt (exact for
    a rotation to O(dt^2), so dt = 1e-6 s gives 1e-12 relative). The ball centre sits on the
    pitch helix; the contact normals lie in the helix's normal plane. The ball is a rigid body
    with centre speed V along the helix and angular velocity W; the two conditions "no slip
    along the groove" at both contacts, with no rotation about the normal relative to the
    frame that follows the centre, are solved as a linear system, with the rotation about the
    groove direction t left at zero relative to that frame.
    """
    rm, lead, r = screw.pitch_diameter / 2, screw.lead, screw.ball_diameter / 2
    alpha = screw.contact_angle
    lam = math.atan(lead / (2 * math.pi * rm))
    e_r, e_t, e_z = np.eye(3)
    t = math.cos(lam) * e_t + math.sin(lam) * e_z  # rolling direction at the ball centre
    b = -math.sin(lam) * e_t + math.cos(lam) * e_z
    centre = rm * e_r
    n_s = -math.cos(alpha) * e_r - math.sin(alpha) * b
    p_s, p_n = centre + r * n_s, centre - r * n_s
    m_s = np.cross(n_s, t)
    dt = 1e-6

    def screw_point(p: np.ndarray, time: float) -> np.ndarray:
        return _rotation_z(omega * time) @ p + np.array([0, 0, omega * time * lead / (2 * np.pi)])

    def screw_velocity(p: np.ndarray) -> np.ndarray:
        return (screw_point(p, dt) - screw_point(p, -dt)) / (2 * dt)

    v_s = screw_velocity(p_s)

    # Unknowns: V (centre speed along t), W_m, W_n (ball angular velocity along m_s and n_s);
    # W_t fixed by "no rotation about t relative to the orbiting frame". The orbiting frame
    # turns at omega_m = V cos(lam) / rm about z, so its rate along t is omega_m sin(lam).
    def residual(x: np.ndarray) -> np.ndarray:
        v, w_m, w_n = x
        om_m = v * math.cos(lam) / rm
        w = w_m * m_s + w_n * n_s + om_m * math.sin(lam) * t
        ball_s = v * t + np.cross(w, p_s - centre)
        ball_n = v * t + np.cross(w, p_n - centre)
        spin_rel = (w - om_m * e_z) @ n_s  # ball axis normal to the contact line
        return np.array([(ball_s - v_s) @ t, ball_n @ t, spin_rel])

    base = residual(np.zeros(3))
    jac = np.column_stack([residual(np.eye(3)[i]) - base for i in range(3)])
    v, w_m, w_n = np.linalg.solve(jac, -base)
    om_m = v * math.cos(lam) / rm
    w = w_m * m_s + w_n * n_s + om_m * math.sin(lam) * t
    ball_s = v * t + np.cross(w, p_s - centre)
    ball_n = v * t + np.cross(w, p_n - centre)
    # The contact points move with the orbiting frame: rolling speed relative to them.
    frame_s = om_m * np.cross(e_z, p_s) + om_m * lead / (2 * np.pi) * e_z
    return {
        "orbital": om_m,
        "entrainment": (ball_s - frame_s) @ t,
        "spin_screw": (w - omega * e_z) @ n_s,
        "spin_nut": -(w @ -n_s),
        "slip_screw": (ball_s - v_s) @ m_s,
        "slip_nut": ball_n @ m_s,
        "ball_rolling": (w - om_m * e_z) @ m_s,
    }


@pytest.mark.parametrize(
    ("dm", "lead", "dw", "alpha_deg"),
    [(40, 5, 3.175, 45), (40, 10, 6.35, 45), (40, 40, 6.35, 45), (25, 25, 3.969, 30)],
)
def test_closed_forms_against_a_rigid_body_evaluation(
    dm: float, lead: float, dw: float, alpha_deg: float
) -> None:
    s = reference_screw().replace(
        pitch_diameter=dm * 1e-3, lead=lead * 1e-3, ball_diameter=dw * 1e-3,
        contact_angle=math.radians(alpha_deg),
    )  # fmt: skip
    omega = 37.0
    ref = _rigid_body_check(s, omega)
    k = kinematics(s, omega)
    # Central differences over dt = 1e-6 s and a 3 x 3 solve: 1e-8 relative is generous.
    assert float(k.orbital_speed) == pytest.approx(ref["orbital"], rel=1e-8)
    assert float(k.entrainment_speed) == pytest.approx(ref["entrainment"], rel=1e-8)
    assert float(k.ball_speed) == pytest.approx(abs(ref["ball_rolling"]), rel=1e-8)
    assert float(k.spin_screw) == pytest.approx(abs(ref["spin_screw"]), rel=1e-8)
    assert float(k.spin_nut) == pytest.approx(abs(ref["spin_nut"]), rel=1e-8)
    # The transverse slips add up to omega R sin(lambda) (here with the split the
    # orbiting frame gives; any ball rotation about t only moves slip between them).
    total = abs(ref["slip_screw"]) + abs(ref["slip_nut"])
    assert float(k.transverse_slip) == pytest.approx(total, rel=1e-8)
    assert ref["slip_screw"] * ref["slip_nut"] >= 0.0  # same spatial direction


def test_bearing_limit_as_the_lead_angle_vanishes() -> None:
    # lambda -> 0 (a 1 mm lead on a 500 mm screw, with a 0.8 mm ball that fits between its
    # turns: lambda = 6.4e-4 rad): the angular-contact bearing values of Harris & Kotzalas
    # ch. 8 come back to O(lambda^2) ~ 4e-7, hence 1e-6.
    s = reference_screw().replace(pitch_diameter=0.5, ball_diameter=0.8e-3, lead=1e-3)
    g, a, omega = s.gamma, s.contact_angle, 10.0
    k = kinematics(s, omega)
    om_m = omega / 2 * (1 - g)
    assert float(k.orbital_speed) == pytest.approx(om_m, rel=1e-6)
    assert float(k.ball_speed) == pytest.approx(
        omega * s.pitch_diameter / (2 * s.ball_diameter) * (1 - g * g), rel=1e-6
    )
    assert float(k.spin_screw) == pytest.approx((omega - om_m) * math.sin(a), rel=1e-6)
    assert float(k.spin_nut) == pytest.approx(om_m * math.sin(a), rel=1e-6)
    # In the bearing, the surfaces roll on their own contact radii at the rolling speed.
    assert float(k.entrainment_speed) == pytest.approx(om_m * s.contact_radius_nut, rel=1e-6)
    assert float(k.transverse_slip) < 1e-4 * float(k.entrainment_speed)


def test_transverse_slip_grows_with_the_lead_as_published() -> None:
    # Slip-to-roll ratio D_w sin(2 lambda) / (d_m (1 - gamma^2 cos^4 lambda)): 0.6 % for
    # 40 x 5 mm with 3.175 mm balls, 2.5 % for 40 x 10 with 6.35 mm, 9.3 % for 40 x 40.
    ratios = []
    for lead, dw in ((5e-3, 3.175e-3), (10e-3, 6.35e-3), (40e-3, 6.35e-3)):
        s = reference_screw().replace(lead=lead, ball_diameter=dw)
        k = kinematics(s, 1.0)
        ratios.append(float(k.transverse_slip / k.entrainment_speed))
    assert ratios == pytest.approx([0.00633, 0.02542, 0.09273], abs=5e-5)


def test_table_speed_is_lead_per_revolution() -> None:
    s = reference_screw()
    one_rev_per_s = kinematics(s, 2 * math.pi)
    assert float(one_rev_per_s.table_speed) == pytest.approx(s.lead, rel=1e-15)


def test_linear_and_odd_in_speed() -> None:
    s = reference_screw()
    k1 = kinematics(s, 10.0)
    k3 = kinematics(s, -30.0)
    for name in (
        "table_speed",
        "orbital_speed",
        "ball_speed",
        "entrainment_speed",
        "spin_screw",
        "spin_nut",
        "transverse_slip",
    ):
        assert float(getattr(k3, name)) == pytest.approx(-3 * float(getattr(k1, name)), rel=1e-14)
    zero = kinematics(s, 0.0)
    assert float(zero.entrainment_speed) == 0.0


def test_spin_shares_the_screw_speed_component_along_the_normal() -> None:
    # The grooves' relative angular velocity along the contact normal is
    # omega sin(alpha) cos(lambda); with the ball axis normal to the contact line it
    # splits into the two contacts' spins.
    s = reference_screw()
    k = kinematics(s, 100.0)
    assert float(k.spin_screw + k.spin_nut) == pytest.approx(
        100 * math.sin(s.contact_angle) * math.cos(s.lead_angle), rel=1e-14
    )
    assert float(k.spin_screw / k.ball_speed) == pytest.approx(k.spin_to_roll_screw, rel=1e-14)
    assert float(k.spin_nut / k.ball_speed) == pytest.approx(k.spin_to_roll_nut, rel=1e-14)


@pytest.mark.parametrize(("lead", "alpha_deg"), [(5e-3, 45.0), (10e-3, 40.0), (40e-3, 50.0)])
def test_four_point_ball_rolls_about_the_line_through_its_screw_contacts(
    lead: float, alpha_deg: float
) -> None:
    # Rigid-body check with the helix: relative to the frame that follows the ball centre,
    # the ball turns about b (the line through its two screw contacts at +-alpha in the
    # normal plane) at omega_b / cos(alpha). Then nothing slips along the groove at any of
    # the four contact centres, and the spin about each normal is four_point_spin's.
    ball = min(6.35e-3, 0.635 * lead)  # 1/8 in on the 5 mm lead: smaller than the lead
    s = reference_screw().replace(lead=lead, ball_diameter=ball,
                                  contact_angle=math.radians(alpha_deg))  # fmt: skip
    omega = 23.0
    rm, r, alpha = s.pitch_diameter / 2, s.ball_diameter / 2, s.contact_angle
    lam = math.atan(lead / (2 * math.pi * rm))
    k = kinematics(s, omega)
    om_m = float(k.orbital_speed)
    e_r, e_t, e_z = np.eye(3)
    t = math.cos(lam) * e_t + math.sin(lam) * e_z
    b = -math.sin(lam) * e_t + math.cos(lam) * e_z
    centre = rm * e_r
    v_centre = om_m * rm / math.cos(lam) * t
    w_ball = om_m * e_z - float(k.ball_speed) / math.cos(alpha) * b
    spins = {}
    for sign in (1.0, -1.0):
        n_s = -math.cos(alpha) * e_r - sign * math.sin(alpha) * b
        for member, n, rate in (("screw", n_s, omega), ("nut", -n_s, 0.0)):
            point = centre + r * n
            surface = rate * np.cross(e_z, point) + rate * lead / (2 * np.pi) * e_z
            ball = v_centre + np.cross(w_ball, point - centre)
            # Along the groove the surfaces roll together (central differences not needed:
            # both velocities are exact rigid-body expressions): 1e-12 of the rolling speed.
            assert abs((ball - surface) @ t) < 1e-12 * float(k.entrainment_speed), (member, sign)
            spins[member] = abs(float((w_ball - rate * e_z) @ n))
    spin_s, spin_n = four_point_spin(s, omega)
    assert spins["screw"] == pytest.approx(abs(float(spin_s)), rel=1e-12)
    assert spins["nut"] == pytest.approx(abs(float(spin_n)), rel=1e-12)


def test_small_ball_limit() -> None:
    # gamma -> 0: balls orbit at half the screw speed, u -> omega d_m / (4 cos lambda). The
    # smallest plausible ball on the largest plausible screw gives gamma = 2.8e-4, so the
    # limit holds to O(gamma): tolerance 1e-3.
    s = reference_screw().replace(pitch_diameter=0.5, ball_diameter=2e-4, lead=0.01)
    assert s.gamma < 3e-4
    k = kinematics(s, 2.0)
    assert float(k.orbital_speed) == pytest.approx(1.0, rel=1e-3)
    assert float(k.entrainment_speed) == pytest.approx(
        2.0 * s.pitch_diameter / 4 / math.cos(s.lead_angle), rel=1e-3
    )


def test_rpm_conversion_and_errors() -> None:
    assert float(rpm_to_rad_s(3000.0)) == pytest.approx(100 * math.pi)
    with pytest.raises(BallScrewInputError, match="speed"):
        kinematics(reference_screw(), float("nan"))
