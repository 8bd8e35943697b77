"""Speed limits: the shaft's critical speed and the nut's d·n, checked on profiles."""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest
from scipy.optimize import brentq

from ballscrew import reference_screw
from ballscrew.axis.energy import Axis, axis_cycle
from ballscrew.axis.motion import move
from ballscrew.design.limits import SAFETY_FACTOR, critical_speed, root_diameter
from ballscrew.errors import BallScrewInputError, BallScrewSpeedWarning

# Catalogue rule n = f d_r / L^2 * 1e7 rpm (d_r, L in mm), f printed to three
# digits (HIWIN, THK, engineering tables): fixed-free 3.4, supported-supported
# 9.7, fixed-supported 15.1, fixed-fixed 21.9.
CATALOGUE_FACTORS = {
    "fixed-free": 3.4,
    "supported-supported": 9.7,
    "fixed-supported": 15.1,
    "fixed-fixed": 21.9,
}


@pytest.mark.parametrize(("support", "factor"), list(CATALOGUE_FACTORS.items()))
def test_critical_speed_is_the_catalogue_rule(support: str, factor: float) -> None:
    d_mm, span_mm = 33.5, 1200.0
    rpm = SAFETY_FACTOR * float(critical_speed(d_mm / 1e3, span_mm / 1e3, support)) * 30 / math.pi
    catalogue = factor * d_mm / span_mm**2 * 1e7
    # The printed factor is rounded to 0.1: it may be off by 0.05.
    assert rpm == pytest.approx(catalogue, rel=0.05 / factor)


def test_critical_speed_scales_as_diameter_over_span_squared() -> None:
    base = float(critical_speed(0.03, 1.0))
    assert float(critical_speed(0.06, 1.0)) == pytest.approx(2 * base, rel=1e-12)
    assert float(critical_speed(0.03, 2.0)) == pytest.approx(base / 4, rel=1e-12)
    with pytest.raises(BallScrewInputError, match="support"):
        critical_speed(0.03, 1.0, "clamped")


@pytest.mark.parametrize("conformity", [0.505, 0.52, 0.55, 0.6])
@pytest.mark.parametrize("angle_deg", [40.0, 45.0, 50.0])
def test_root_is_where_the_two_groove_arcs_meet(conformity: float, angle_deg: float) -> None:
    # Build one arc of the gothic arch from its contact point: the contact is
    # d_b/2 from the ball's centre along the contact line, and the arc's centre
    # r further on, through the ball's centre. The groove's bottom is where
    # this arc crosses the symmetry plane (axial coordinate 0), found by root
    # finding along the arc (coordinates: radial y outward, axial x).
    screw = reference_screw().replace(conformity_screw=conformity,
                                      contact_angle=math.radians(angle_deg))  # fmt: skip
    db, a = screw.ball_diameter, screw.contact_angle
    r = conformity * db
    ball = np.array([0.0, screw.pitch_diameter / 2])
    towards_screw = np.array([math.sin(a), -math.cos(a)])
    contact = ball + 0.5 * db * towards_screw
    centre = contact - r * towards_screw
    # Points of the arc: centre + r (sin t, -cos t); the bottom has x = 0.
    t = brentq(lambda s: centre[0] + r * math.sin(s), -math.pi / 2, math.pi / 2)
    bottom_y = centre[1] - r * math.cos(t)
    assert root_diameter(screw) == pytest.approx(2 * bottom_y, rel=1e-12)
    assert root_diameter(screw) < screw.pitch_diameter - db  # the groove is deeper than the ball


def _over(screw_speed_rpm: float, lead: float) -> float:
    """Table feed [m/s] for a screw speed [rpm]."""
    return screw_speed_rpm / 60.0 * lead


def test_profiles_past_the_limits_warn_and_inside_them_do_not() -> None:
    screw = reference_screw()  # 40 mm: the default d·n limit 70 000 is 1750 rpm
    lead = screw.lead
    inside = move(0.3, _over(1700.0, lead), 2.0)
    outside = move(0.3, _over(1800.0, lead), 2.0)
    axis = Axis(moving_mass=50.0)
    with warnings.catch_warnings():
        warnings.simplefilter("error", BallScrewSpeedWarning)
        r = axis_cycle(inside, screw, "mineral ISO VG 68", axis, model="catalog")
    assert r.speed_warnings == ()
    with pytest.warns(BallScrewSpeedWarning, match=r"d·n = 72,000 mm·rpm"):
        r = axis_cycle(outside, screw, "mineral ISO VG 68", axis, model="catalog")
    assert len(r.speed_warnings) == 1
    # A long, fixed-free screw whips first: 80 % of the critical speed of a
    # 2 m fixed-free span with the estimated root.
    span = 2.0
    allowed = SAFETY_FACTOR * float(critical_speed(root_diameter(screw), span, "fixed-free"))
    allowed_rpm = allowed * 30 / math.pi
    assert allowed_rpm < 1700.0
    long_axis = Axis(moving_mass=50.0, bearing_span=span, support="fixed-free")
    below = move(0.3, _over(0.98 * allowed_rpm, lead), 2.0)
    above = move(0.3, _over(1.02 * allowed_rpm, lead), 2.0)
    assert axis_cycle(below, screw, "mineral ISO VG 68", long_axis,
                      model="catalog").speed_warnings == ()  # fmt: skip
    with pytest.warns(BallScrewSpeedWarning, match="critical speed"):
        axis_cycle(above, screw, "mineral ISO VG 68", long_axis, model="catalog")


def test_axis_refuses_unknown_supports_and_bad_spans() -> None:
    with pytest.raises(BallScrewInputError, match="support"):
        Axis(moving_mass=1.0, support="welded")
    with pytest.raises(BallScrewInputError, match="bearing_span"):
        Axis(moving_mass=1.0, bearing_span=-1.0)
    with pytest.raises(BallScrewInputError, match="dn_limit"):
        Axis(moving_mass=1.0, dn_limit=0.0)


def test_critical_speed_message_gives_the_span_and_root_in_mm() -> None:
    # A designer checks the message against the drawing: 1500 mm span, 33.5 mm root.
    from ballscrew.design.limits import speed_limit_issues

    (message,) = speed_limit_issues(reference_screw(), 3000 * math.pi / 30, span=1.5,
                                    support="fixed-free", root=0.0335,
                                    dn_limit=1e9)  # fmt: skip
    assert "fixed-free span of 1500 mm, root diameter 33.5 mm" in message
