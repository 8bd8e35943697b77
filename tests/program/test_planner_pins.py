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
from ballscrew.program.planner import MARGIN, Limits, plan, speed_change_distance

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


ARCS = {
    # plane: (the arc from a start off the origin, its in-plane axes, its normal axis)
    17: ("G0 X10 Y5\nG4 P0.1\nG17 G3 X50 Y5 I20 J0 F30000\n", (0, 1), 2),
    18: ("G0 X10 Z5\nG4 P0.1\nG18 G3 X50 Z5 I20 K0 F30000\n", (2, 0), 1),
    19: ("G0 Y10 Z5\nG4 P0.1\nG19 G3 Y50 Z5 J20 K0 F30000\n", (1, 2), 0),
}


def arc_limits(slow: int) -> Limits:
    """Every axis at 1 m/s, 4 m/s^2, 100 m/s^3 but ``slow`` at 1 m/s^2."""
    acc = np.full(3, 4.0)
    acc[slow] = 1.0
    return Limits(feed=np.ones(3), acceleration=acc, jerk=np.full(3, 100.0), rapid_feed=1.0,
                  path_tolerance=2e-5, sample_time=1e-3)  # fmt: skip


@pytest.mark.parametrize(("plane", "which"), [(p, w) for p in ARCS for w in (0, 1)])
def test_an_arc_takes_the_slower_in_plane_axis(plane: int, which: int) -> None:
    # A half circle of R = 20 mm from rest (a dwell before it), either in-plane axis slow.
    # Half of the slow axis's 1 m/s^2 for the centripetal acceleration, v = sqrt(0.5 x 1 x R)
    # = 0.1 m/s (the jerk's bound (0.5 x 100 x R^2)^(1/3) = 0.27 m/s does not bind), the
    # other half along the path, 0.5 m/s^2, and half the jerk, 50 m/s^3.
    text, in_plane, normal = ARCS[plane]
    m = plan(read_program(text), arc_limits(in_plane[which]))
    r = 0.02
    v = math.sqrt(0.5 * 1.0 * r)
    assert m.block_limit[2] == pytest.approx(v, rel=1e-12)
    assert m.block_time[2] == pytest.approx(s_curve_time(math.pi * r, v, 0.5, 50.0), rel=1e-9)
    # In the cruise the centripetal acceleration is v^2/R = 0.5 m/s^2 on the circle.
    cruise = (m.block == 2) & np.isclose(m.path_speed, v, rtol=1e-12)
    assert cruise.sum() > 10
    centripetal = np.linalg.norm(np.delete(m.acceleration[cruise], normal, axis=1), axis=1)
    np.testing.assert_allclose(centripetal, v * v / r, rtol=1e-9)


def test_a_helix_divides_the_in_plane_bounds_by_its_in_plane_share() -> None:
    # The G17 half circle rising 10 mm in Z: length L = hypot(pi R, h), in-plane share
    # k = pi R / L. The centripetal bound is on the in-plane speed, v k <= sqrt(0.5 a R);
    # the in-plane axes carry k of the path's acceleration and jerk, halved.
    r, h = 0.02, 0.01
    length = math.hypot(math.pi * r, h)
    k = math.pi * r / length
    m = plan(read_program("G0 X10 Y5\nG4 P0.1\nG17 G3 X50 Y5 Z10 I20 J0 F30000\n"),
             arc_limits(1))  # fmt: skip
    v = math.sqrt(0.5 * r) / k
    assert m.block_limit[2] == pytest.approx(v, rel=1e-12)
    assert m.block_time[2] == pytest.approx(s_curve_time(length, v, 0.5 / k, 50.0 / k),
                                            rel=1e-9)  # fmt: skip
    np.testing.assert_allclose(m.position[-1], [0.05, 0.005, 0.01], atol=1e-12)


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


def _reach(v0: float, length: float, a: float = 2.0, j: float = 50.0) -> float:
    """The speed reached from ``v0`` over ``length``: the root of the speed change's distance
    (module docstring of the planner) found by bisection, independent of its closed form."""

    def distance(v1: float) -> float:
        dv = v1 - v0
        if dv >= a * a / j:
            return 0.5 * (v0 + v1) * (dv / a + a / j)
        return (v0 + v1) * math.sqrt(dv / j)

    low, high = v0, v0 + 10.0
    for _ in range(200):
        mid = 0.5 * (low + high)
        low, high = (mid, high) if distance(mid) < length else (low, mid)
    return 0.5 * (low + high)


@pytest.mark.parametrize("length_mm", [5.0, 1.0])
def test_the_look_ahead_carries_a_speed_through_two_short_blocks(length_mm: float) -> None:
    # Two short blocks before a reversal: the second is entered at the speed that stops
    # within it, the first at the speed that brakes to that one within it (each the
    # MARGIN below); forward, the same from rest. The speed change starts at a speed: 5 mm
    # reaches the acceleration, 1 mm does not. Bisection to 1e-15: 1e-12.
    length = length_mm * 1e-3
    second = _reach(0.0, length) * MARGIN
    first = _reach(second, length) * MARGIN
    text = f"G1 X300 F30000\nG1 X{300 + length_mm:g}\nG1 X{300 + 2 * length_mm:g}\nG1 X0\n"
    back = plan(read_program(text), LIMITS)
    assert back.entry_speed[2] == pytest.approx(second, rel=1e-12)
    assert back.entry_speed[1] == pytest.approx(first, rel=1e-12)
    forward = plan(read_program(f"G1 X{length_mm:g} F30000\nG1 X{2 * length_mm:g}\nG1 X300\n"),
                   LIMITS)  # fmt: skip
    assert forward.exit_speed[0] == pytest.approx(second, rel=1e-12)
    assert forward.exit_speed[1] == pytest.approx(first, rel=1e-12)


def test_a_dwell_is_entered_and_left_at_rest_and_a_program_without_time_stands() -> None:
    m = plan(read_program("G1 X10 F6000\nG4 P0.1\nG1 X0\n"), LIMITS)
    assert m.entry_speed[1] == 0.0 and m.exit_speed[0] == 0.0 and m.exit_speed[1] == 0.0
    # A program that takes no time stands at its start (as LinuxCNC runs it), one sample.
    still = plan(read_program("G4 P0\n"), LIMITS)
    assert still.duration == 0.0 and still.time.size == 1


def test_an_exact_stop_corner_is_a_stop() -> None:
    # G61: no tolerance to blend in, the corner is taken at rest.
    m = plan(read_program("G61 G1 X100 F30000\nG1 Y100\n"), LIMITS)
    assert m.entry_speed[1] == 0.0


def test_a_wide_corner_is_taken_at_the_blends_acceleration_bound() -> None:
    # With a 5 mm tolerance the blend's radius is 12.07 mm, and the acceleration's bound
    # sqrt(a r) = 0.185 m/s lies below the jerk's (j r^2)^(1/3) = 0.218 m/s (a = 2 sqrt2,
    # j = 50 sqrt2 along the blend's direction, as below); the feed and the blocks' reach
    # are higher. Exact but for rounding: 1e-12.
    lim = Limits(feed=LIMITS.feed, acceleration=LIMITS.acceleration, jerk=LIMITS.jerk,
                 rapid_feed=0.5, path_tolerance=5e-3, sample_time=2e-3)  # fmt: skip
    m = plan(read_program("G1 X100 F30000\nG1 Y100\n"), lim)
    s = math.sin(math.pi / 4)
    r = 5e-3 * s / (1 - s)
    assert m.entry_speed[1] == pytest.approx(math.sqrt(2.0 * math.sqrt(2) * r), rel=1e-12)


def test_the_speed_change_distance_from_a_speed_either_way() -> None:
    # From 0.1 to 0.5 m/s (or back) at 2 m/s^2, 50 m/s^3: 0.5 x 0.6 x (0.2 + 0.04) = 0.072 m;
    # from 0.1 to 0.15 m/s, below a^2/j = 0.08: 0.25 sqrt(0.05/50) = 7.906 mm.
    got = speed_change_distance(np.array([0.1, 0.5, 0.1]), np.array([0.5, 0.1, 0.15]), 2.0, 50.0)
    np.testing.assert_allclose(got, [0.072, 0.072, 0.25 * math.sqrt(0.001)], rtol=1e-12)


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


def test_an_arc_between_two_quadrants_still_gives_the_whole_share_to_both_axes() -> None:
    # From 45 to 135 deg the ends' tangents are (-1, +-1)/sqrt2, yet an in-plane axis is
    # charged the whole in-plane share (module docstring: a long arc reaches it somewhere),
    # so Y (slow, 2 m/s^2) sets the tangential 0.5 x 2 and the centripetal sqrt(0.5 x 2 R).
    r = 0.02
    d = 1e3 * r / math.sqrt(2)
    text = (f"G0 X{30 + d:.10f} Y{5 + d:.10f}\nG4 P0.1\n"
            f"G17 G3 X{30 - d:.10f} Y{5 + d:.10f} I{-d:.10f} J{-d:.10f} F30000\n")  # fmt: skip
    lim = Limits(feed=np.ones(3), acceleration=np.array([4.0, 2.0, 4.0]),
                 jerk=np.full(3, 100.0), rapid_feed=1.0, path_tolerance=2e-5,
                 sample_time=1e-3)  # fmt: skip
    m = plan(read_program(text), lim)
    v = math.sqrt(0.5 * 2.0 * r)
    assert m.block_limit[2] == pytest.approx(v, rel=1e-9)
    assert m.block_time[2] == pytest.approx(s_curve_time(0.5 * math.pi * r, v, 1.0, 50.0),
                                            rel=1e-9)  # fmt: skip


def test_a_helix_whose_jerk_or_normal_feed_binds() -> None:
    # The G17 half circle of R 20 mm rising 10 mm (in-plane share k, normal share n).
    r, h = 0.02, 0.01
    length = math.hypot(math.pi * r, h)
    k, n = math.pi * r / length, h / length
    text = "G0 X10 Y5\nG4 P0.1\nG17 G3 X50 Y5 Z10 I20 J0 F30000\n"
    # Y's jerk 10 m/s^3: the centripetal jerk's bound (0.5 j R^2)^(1/3) / k = 0.126/k m/s
    # lies below the acceleration's sqrt(0.5 x 4 R)/k = 0.2/k. Along the path j = 0.5 x 10/k
    # and a = 0.5 x 4/k, which it does not reach (v < a^2/j): L/v + 2 sqrt(v/j).
    lim = Limits(feed=np.ones(3), acceleration=np.full(3, 4.0),
                 jerk=np.array([100.0, 10.0, 100.0]), rapid_feed=1.0, path_tolerance=2e-5,
                 sample_time=1e-3)  # fmt: skip
    m = plan(read_program(text), lim)
    v, j = (0.5 * 10.0 * r * r) ** (1 / 3) / k, 5.0 / k
    assert v < (2.0 / k) ** 2 / j
    assert m.block_limit[2] == pytest.approx(v, rel=1e-12)
    assert m.block_time[2] == pytest.approx(length / v + 2.0 * math.sqrt(v / j), rel=1e-9)
    # Z at 10 mm/s: the path's speed is Z's over its share n, 0.01/n = 0.064 m/s.
    lim = Limits(feed=np.array([1.0, 1.0, 0.01]), acceleration=np.full(3, 4.0),
                 jerk=np.full(3, 100.0), rapid_feed=1.0, path_tolerance=2e-5,
                 sample_time=1e-3)  # fmt: skip
    m = plan(read_program(text), lim)
    assert m.block_limit[2] == pytest.approx(0.01 / n, rel=1e-12)


@pytest.mark.parametrize("rise_mm", [0.0, 5.0])
def test_a_line_tangent_to_an_arcs_end_runs_through(rise_mm: float) -> None:
    # A quarter circle (or helix) from 180 to 270 deg about (30, 5), then a line along its
    # end tangent: no corner, the junction runs at the arc's own limit 0.1/k m/s (Y slow,
    # as above). A corner there would be taken at a few mm/s.
    r = 0.02
    arc = 0.5 * math.pi * r
    total = math.hypot(arc, rise_mm * 1e-3)
    k, n = arc / total, rise_mm * 1e-3 / total
    end = (30.0, -15.0, rise_mm)
    tip = (end[0] + 30.0 * k, end[1], end[2] + 30.0 * n)
    text = (f"G0 X10 Y5\nG4 P0.1\nG17 G3 X30 Y-15 Z{rise_mm:g} I20 J0 F30000\n"
            f"G1 X{tip[0]:.12f} Z{tip[2]:.12f}\n")  # fmt: skip
    m = plan(read_program(text), arc_limits(1))
    assert m.entry_speed[3] == pytest.approx(math.sqrt(0.5 * r) / k, rel=1e-9)


def test_a_sharp_corner_takes_grbls_bound() -> None:
    # X, then back along (-1, 1)/sqrt2: the turn leaves 45 deg between the blocks. Grbl's
    # blend: r = d sin(22.5)/(1 - sin(22.5)); along the blend's direction
    # d = (u2 - u1)/|u2 - u1| the axes allow min_i a_i/|d_i| and min_i j_i/|d_i|.
    m = plan(read_program("G1 X100 F30000\nG1 X0 Y100\n"), LIMITS)
    u1, u2 = np.array([1.0, 0.0]), np.array([-1.0, 1.0]) / math.sqrt(2)
    d = (u2 - u1) / np.linalg.norm(u2 - u1)
    s = math.sin(math.radians(22.5))
    r = 2e-5 * s / (1 - s)
    a = min(2.0 / abs(d[0]), 3.0 / abs(d[1]))
    j = min(50.0 / abs(d[0]), 60.0 / abs(d[1]))
    assert m.entry_speed[1] == pytest.approx(min(math.sqrt(a * r), (j * r * r) ** (1 / 3)),
                                             rel=1e-9)  # fmt: skip


@pytest.mark.parametrize("half", [False, True])
def test_a_corner_after_a_helix_takes_the_helixs_unit_tangent(half: bool) -> None:
    # The quarter helix above ends along u1 = (k, 0, n) (in-plane share k, rise share n),
    # then a line along -Y; the half helix ends along (0, k, n), then a line along -X: a
    # right angle, blended by Grbl's rule along (u2 - u1)/|u2 - u1|.
    r, rise = 0.02, 0.005
    arc = (1.0 if half else 0.5) * math.pi * r
    total = math.hypot(arc, rise)
    k, n = arc / total, rise / total
    u1 = np.array([0.0, k, n] if half else [k, 0.0, n])
    u2 = np.array([-1.0, 0.0, 0.0] if half else [0.0, -1.0, 0.0])
    lim = Limits(feed=np.ones(3), acceleration=np.array([4.0, 1.0, 4.0]),
                 jerk=np.full(3, 100.0), rapid_feed=1.0, path_tolerance=1e-3,
                 sample_time=1e-3)  # fmt: skip
    end = "X50 Y5" if half else "X30 Y-15"
    line = "X0" if half else "Y-50"
    text = f"G0 X10 Y5\nG4 P0.1\nG17 G3 {end} Z5 I20 J0 F30000\nG1 {line}\n"
    m = plan(read_program(text), lim)
    d = (u2 - u1) / np.linalg.norm(u2 - u1)
    s = math.sin(math.pi / 4)
    blend = 1e-3 * s / (1 - s)
    a = min(lim.acceleration[i] / abs(d[i]) for i in range(3))
    j = min(lim.jerk[i] / abs(d[i]) for i in range(3))
    corner = min(math.sqrt(a * blend), (j * blend * blend) ** (1 / 3))
    assert corner < math.sqrt(0.5 * r) / k  # below the helix's own limit
    assert m.entry_speed[3] == pytest.approx(corner, rel=1e-9)
