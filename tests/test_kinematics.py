"""Tests of ballscrew.kinematics: ideal rolling speeds."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew import BallScrewInputError, reference_screw
from ballscrew.kinematics import kinematics, rpm_to_rad_s


def test_no_slip_at_either_contact() -> None:
    # In the frame of the ball set, the screw surface moves at
    # (omega - omega_m) r_s, the nut surface at omega_m r_n, the ball surface
    # at omega_b D_w / 2; pure rolling needs all three equal (and equal to u).
    s = reference_screw()
    k = kinematics(s, np.array([-50.0, 1.0, 300.0]))
    screw_surface = (k.screw_speed - k.orbital_speed) * s.contact_radius_screw
    nut_surface = k.orbital_speed * s.contact_radius_nut
    ball_surface = k.ball_speed * s.ball_diameter / 2
    np.testing.assert_allclose(screw_surface, nut_surface, rtol=1e-14)
    np.testing.assert_allclose(ball_surface, nut_surface, rtol=1e-14)
    np.testing.assert_allclose(k.entrainment_speed, nut_surface, rtol=1e-14)


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
    ):
        assert float(getattr(k3, name)) == pytest.approx(-3 * float(getattr(k1, name)), rel=1e-14)
    zero = kinematics(s, 0.0)
    assert float(zero.entrainment_speed) == 0.0


def test_spin_shares_the_screw_speed_component_along_the_normal() -> None:
    # The grooves' relative angular velocity along the contact normal is
    # omega sin(alpha); with the ball axis normal to the contact line it
    # splits into the two contacts' spins.
    s = reference_screw()
    k = kinematics(s, 100.0)
    assert float(k.spin_screw + k.spin_nut) == pytest.approx(100 * math.sin(s.contact_angle))
    assert float(k.spin_screw / k.ball_speed) == pytest.approx(k.spin_to_roll_screw, rel=1e-14)
    assert float(k.spin_nut / k.ball_speed) == pytest.approx(k.spin_to_roll_nut, rel=1e-14)


def test_small_ball_limit() -> None:
    # gamma -> 0: balls orbit at half the screw speed, u -> omega d_m / 4. The
    # smallest plausible ball on the largest plausible screw gives gamma =
    # 2.8e-4, so the limit holds to O(gamma): tolerance 1e-3.
    s = reference_screw().replace(pitch_diameter=0.5, ball_diameter=2e-4, lead=0.01)
    assert s.gamma < 3e-4
    k = kinematics(s, 2.0)
    assert float(k.orbital_speed) == pytest.approx(1.0, rel=1e-3)
    assert float(k.entrainment_speed) == pytest.approx(2.0 * s.pitch_diameter / 4, rel=1e-3)


def test_rpm_conversion_and_errors() -> None:
    assert float(rpm_to_rad_s(3000.0)) == pytest.approx(100 * math.pi)
    with pytest.raises(BallScrewInputError, match="speed"):
        kinematics(reference_screw(), float("nan"))
