"""Each of the planner's limits, by a block where it binds, against its closed form.

The rest-to-rest time of a block whose jerk-limited S-curve reaches both the top speed
:math:`v` and the acceleration :math:`a` (:math:`v \\ge a^2/j`, and the block longer than
twice the speed change's distance) is :math:`L/v + v/a + a/j`: two S-curves of
:math:`v/a + a/j` each, which cover :math:`v(v/a + a/j)` together, and a cruise over the rest.
Ruckig plans those blocks to its own precision (1e-9 relative is two orders above it and
far below any wrong limit, which moves the time by percents).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.program.gcode import read_program
from ballscrew.program.planner import MARGIN, Limits, plan

LIMITS = Limits(
    feed=np.array([0.5, 0.5, 0.25]),
    acceleration=np.array([2.0, 3.0, 2.0]),
    jerk=np.array([50.0, 60.0, 40.0]),
    rapid_feed=0.5,
    path_tolerance=2e-5,
    sample_time=2e-3,
)


def s_curve_time(length: float, v: float, a: float, j: float) -> float:
    """Rest to rest over ``length`` reaching ``v`` and ``a`` (module docstring)."""
    assert v >= a * a / j and length >= v * (v / a + a / j)
    return length / v + v / a + a / j


def test_a_z_feed_is_capped_by_the_slow_z_axis() -> None:
    # F = 0.5 m/s on Z, whose axis runs at 0.25 m/s: the block runs at 0.25 with Z's 2 m/s^2
    # and 40 m/s^3.
    m = plan(read_program("G1 Z-100 F30000\n"), LIMITS)
    assert m.block_limit[0] == pytest.approx(0.25, rel=1e-12)
    assert m.duration == pytest.approx(s_curve_time(0.1, 0.25, 2.0, 40.0), rel=1e-9)
    assert np.max(np.abs(m.velocity[:, 2])) == pytest.approx(0.25, rel=1e-9)
    assert np.max(np.abs(m.acceleration[:, 2])) == pytest.approx(2.0, rel=1e-9)


def test_a_diagonal_projects_each_axis_limit_onto_the_path() -> None:
    # 300 x 400 mm, u = (0.6, 0.8): the feed 0.5/0.8 = 0.625 (Y), the acceleration
    # min(2/0.6, 3/0.8) = 10/3 (X), the jerk min(50/0.6, 60/0.8) = 75 (Y) m/s^3.
    m = plan(read_program("G1 X300 Y400 F60000\n"), LIMITS)
    v, a, j = 0.625, 10.0 / 3.0, 75.0
    assert m.block_limit[0] == pytest.approx(v, rel=1e-12)
    assert m.duration == pytest.approx(s_curve_time(0.5, v, a, j), rel=1e-9)
    # X is the axis whose acceleration binds: it reaches its 2 m/s^2, Y 0.8 x 10/3.
    assert np.max(np.abs(m.acceleration[:, 0])) == pytest.approx(2.0, rel=1e-9)
    assert np.max(np.abs(m.acceleration[:, 1])) == pytest.approx(0.8 * a, rel=1e-9)
    assert np.max(np.abs(m.jerk[:, 1])) == pytest.approx(60.0, rel=1e-9)


@pytest.mark.parametrize(
    ("text", "slow", "normal"),
    [
        ("G17 G3 X40 Y0 I20 J0 F30000\n", 1, 2),  # the XY plane's second axis: Y
        ("G18 G3 X40 Z0 I20 K0 F30000\n", 0, 1),  # ZX: X
        ("G19 G3 Y40 Z0 J20 K0 F30000\n", 2, 0),  # YZ: Z
    ],
)
def test_an_arc_takes_the_slower_in_plane_axis(text: str, slow: int, normal: int) -> None:
    # Every axis at 1 m/s, 4 m/s^2, 100 m/s^3 but the plane's second axis at 1 m/s^2: half
    # of it for the centripetal acceleration, v = sqrt(0.5 x 1 x R) = 0.1 m/s on R = 20 mm
    # (the jerk's bound (0.5 x 100 x R^2)^(1/3) = 0.27 m/s does not bind), the other half
    # along the path, 0.5 m/s^2, and half the jerk, 50 m/s^3.
    acc = np.full(3, 4.0)
    acc[slow] = 1.0
    lim = Limits(feed=np.ones(3), acceleration=acc, jerk=np.full(3, 100.0), rapid_feed=1.0,
                 path_tolerance=2e-5, sample_time=1e-3)  # fmt: skip
    m = plan(read_program(text), lim)
    r = 0.02
    v = math.sqrt(0.5 * 1.0 * r)
    assert m.block_limit[0] == pytest.approx(v, rel=1e-12)
    assert m.duration == pytest.approx(s_curve_time(math.pi * r, v, 0.5, 50.0), rel=1e-9)
    # In the cruise the centripetal acceleration is v^2/R = 0.5 m/s^2 on the circle.
    cruise = np.isclose(m.path_speed, v, rtol=1e-12)
    assert cruise.sum() > 10
    centripetal = np.linalg.norm(np.delete(m.acceleration[cruise], normal, axis=1), axis=1)
    np.testing.assert_allclose(centripetal, v * v / r, rtol=1e-9)


@pytest.mark.parametrize(
    ("length_mm", "v_stop"),
    [
        # a reaches 2 m/s^2 (v >= a^2/j = 0.08): 0.25 v^2 + 0.02 v = 0.005 m
        (5.0, (-0.02 + math.sqrt(0.02**2 + 4 * 0.25 * 0.005)) / (2 * 0.25)),
        # it does not: L = v sqrt(v/j), v = (L^2 j)^(1/3)
        (1.0, (1e-6 * 50.0) ** (1.0 / 3.0)),
    ],
)
def test_the_look_ahead_brakes_and_accelerates_within_a_short_block(
    length_mm: float, v_stop: float
) -> None:
    # A short block before a reversal (a stop): the block before enters it at the highest
    # speed from which X (2 m/s^2, 50 m/s^3) stops within it, the look-ahead's MARGIN
    # (1e-7) below; the same short block from rest leaves at that speed (forward pass).
    # 1e-12 on top of the margin: the quadratic and Cardano's root in floating point.
    back = plan(read_program(f"G1 X300 F30000\nG1 X{300 + length_mm:g}\nG1 X0\n"), LIMITS)
    assert back.entry_speed[1] == pytest.approx(v_stop * MARGIN, rel=1e-12)
    assert back.exit_speed[0] == back.entry_speed[1]
    forward = plan(read_program(f"G1 X{length_mm:g} F30000\nG1 X300\n"), LIMITS)
    assert forward.exit_speed[0] == pytest.approx(v_stop * MARGIN, rel=1e-12)
    assert forward.entry_speed[1] == forward.exit_speed[0]


def test_a_right_angle_corner_is_taken_at_the_blends_jerk_bound() -> None:
    # X then Y at 90 degrees with a 20 um path tolerance: the blend's radius
    # r = d sin45/(1 - sin45) = 48.3 um; along the blend's direction (-1, 1)/sqrt2 the axes
    # allow a = min(2, 3) sqrt2 and j = min(50, 60) sqrt2; the jerk's bound (j r^2)^(1/3) =
    # 5.5 mm/s is below the acceleration's sqrt(a r) = 11.7 mm/s. No look-ahead margin
    # applies to a corner: exact but for rounding (1e-12).
    m = plan(read_program("G1 X100 F30000\nG1 Y100\n"), LIMITS)
    s = math.sin(math.pi / 4)
    r = 2e-5 * s / (1 - s)
    corner = min(math.sqrt(2.0 * math.sqrt(2) * r), (50.0 * math.sqrt(2) * r * r) ** (1 / 3))
    assert corner == pytest.approx((50.0 * math.sqrt(2) * r * r) ** (1 / 3))
    assert m.entry_speed[1] == pytest.approx(corner, rel=1e-12)
