"""The planner against closed forms, ruckig, and the axes' limits on random programs."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ballscrew.program.gcode import read_program
from ballscrew.program.planner import Limits, plan, speed_change_distance

LIMITS = Limits(
    feed=np.array([0.5, 0.5, 0.25]),
    acceleration=np.array([2.0, 3.0, 2.0]),
    jerk=np.array([50.0, 60.0, 40.0]),
    rapid_feed=0.5,
    path_tolerance=2e-5,
    sample_time=2e-3,
)


def test_one_line_takes_the_jerk_limited_time() -> None:
    # 300 mm at 30 m/min, 2 m/s^2, 50 m/s^3 on X: the rest-to-rest S-curve reaches the feed and
    # the acceleration, so t = L/v + v/a + a/j = 0.6 + 0.25 + 0.04 s.
    m = plan(read_program("G1 X300 F30000\n"), LIMITS)
    assert m.duration == pytest.approx(0.3 / 0.5 + 0.5 / 2.0 + 2.0 / 50.0, rel=1e-9)
    assert m.nominal_time == pytest.approx(0.6)
    np.testing.assert_allclose(m.position[-1], [0.3, 0.0, 0.0], atol=1e-12)


def test_a_short_line_takes_ruckigs_time() -> None:
    from ruckig import InputParameter, Ruckig, Trajectory

    # 5 mm along Y at 0.5 m/s: the feed is not reached. Ruckig alone, with Y's limits.
    inp, traj = InputParameter(1), Trajectory(1)
    inp.current_position, inp.target_position = [0.0], [0.005]
    inp.max_velocity, inp.max_acceleration, inp.max_jerk = [0.5], [3.0], [60.0]
    Ruckig(1).calculate(inp, traj)
    m = plan(read_program("G1 Y5 F30000\n"), LIMITS)
    assert m.duration == pytest.approx(traj.duration, rel=1e-9)


def test_an_arc_has_its_length_and_velocities_f_times_minus_sin_cos() -> None:
    # A counter-clockwise half circle of R 50 mm at 1 m/min about (50, 0).
    feed = 1.0 / 60.0
    m = plan(read_program("G1 X100 Y0 F1000\nG3 X0 Y0 I-50 J0\n"), LIMITS)
    arc = m.block == 1
    xy = m.position[arc, :2]
    length = np.sum(np.linalg.norm(np.diff(xy, axis=0), axis=1))
    # The chords of samples at most 5 degrees apart: shorter than the arc by < 0.04 %.
    assert length == pytest.approx(math.pi * 0.05, rel=4e-4)
    cruise = arc & np.isclose(m.path_speed, feed, rtol=1e-9)
    assert cruise.sum() > 10
    theta = np.arctan2(m.position[cruise, 1], m.position[cruise, 0] - 0.05)
    np.testing.assert_allclose(m.velocity[cruise, 0], -feed * np.sin(theta), atol=1e-12)
    np.testing.assert_allclose(m.velocity[cruise, 1], feed * np.cos(theta), atol=1e-12)
    # The centripetal acceleration v^2/R points at the centre.
    radial = np.stack([np.cos(theta), np.sin(theta)], axis=1)
    a_r = np.sum(m.acceleration[cruise, :2] * radial, axis=1)
    np.testing.assert_allclose(a_r, -(feed**2) / 0.05, rtol=1e-9)


@pytest.mark.parametrize(
    ("first", "twin"),
    [
        ("G90 G1 X10 Y5 F600\nG1 X30 Y5\nG2 X40 Y15 I0 J10\nG0 Z3\nG1 X10 Y20 Z0\n",
         "G91 G1 X10 Y5 F600\nG1 X20 Y0\nG2 X10 Y10 I0 J10\nG0 Z3\nG1 X-30 Y5 Z-3\n"),
        ("G21 G1 X25.4 Y12.7 F508\nG3 X50.8 Y12.7 R12.7\n",
         "G20 G1 X1 Y0.5 F20\nG3 X2 Y0.5 R0.5\n"),
    ],
    ids=["incremental-is-its-absolute-twin", "inch-is-its-millimetre-twin"],
)  # fmt: skip
def test_a_program_and_its_twin_plan_the_same_motion(first: str, twin: str) -> None:
    a, b = plan(read_program(first), LIMITS), plan(read_program(twin), LIMITS)
    # Inches are exact in millimetres (25.4); the times agree to the planner's rounding.
    np.testing.assert_allclose(b.time, a.time, rtol=1e-9, atol=1e-12)
    np.testing.assert_allclose(b.position, a.position, atol=1e-12)


def test_speed_change_distance_against_the_integrated_profile() -> None:
    # Integrate jerk +j, 0, -j numerically: the distance from 0.1 to 0.4 m/s at 2 m/s^2, 50 m/s^3.
    v0, v1, a, j = 0.1, 0.4, 2.0, 50.0
    tj = a / j
    ta = (v1 - v0) / a - tj
    t = np.linspace(0.0, 2 * tj + ta, 200_001)
    acc = np.clip(np.minimum(j * t, j * (2 * tj + ta - t)), 0.0, a)
    v = v0 + np.concatenate([[0.0], np.cumsum(0.5 * (acc[1:] + acc[:-1]) * np.diff(t))])
    s = float(np.sum(0.5 * (v[1:] + v[:-1]) * np.diff(t)))
    assert float(speed_change_distance(v0, v1, a, j)) == pytest.approx(s, rel=1e-6)


points = st.tuples(*(st.integers(0, 40) for _ in range(3)))


@settings(max_examples=40, deadline=None)
@given(
    st.lists(points, min_size=2, max_size=12),
    st.integers(300, 20_000),
    st.floats(0.5, 5.0),
    st.floats(10.0, 200.0),
)
def test_junctions_and_blocks_stay_within_every_axis_limit(
    pts: list[tuple[int, int, int]], feed: int, acc: float, jerk: float
) -> None:
    lim = Limits(
        feed=np.array([0.5, 0.4, 0.2]),
        acceleration=np.array([acc, 0.7 * acc, 1.3 * acc]),
        jerk=np.array([jerk, 0.5 * jerk, 2.0 * jerk]),
        rapid_feed=0.5,
        path_tolerance=1e-5,
        sample_time=2e-3,
    )
    text = f"G1 F{feed}\n" + "".join(f"G1 X{x} Y{y} Z{z}\n" for x, y, z in pts)
    program = read_program(text)
    if program.size == 0:
        return
    m = plan(program, lim)
    tol = 1 + 1e-6
    # Within each block (lines), no axis passes its acceleration, jerk or speed limit.
    assert np.all(np.abs(m.acceleration) <= lim.acceleration * tol + 1e-9)
    assert np.all(np.abs(m.jerk) <= lim.jerk * tol + 1e-9)
    assert np.all(np.abs(m.velocity) <= lim.feed * tol + 1e-12)
    # At each junction the blend within the tolerance asks no axis for more than its limits.
    d = program.end - program.start
    u = d / np.linalg.norm(d, axis=1)[:, None]
    for k in range(1, program.size):
        v = m.entry_speed[k]
        assert v == pytest.approx(m.exit_speed[k - 1])
        cos = -float(u[k - 1] @ u[k])
        if cos < -1 + 1e-12 or v == 0.0:
            continue
        sin_half = math.sqrt(0.5 * (1 - cos))
        r = lim.path_tolerance * sin_half / (1 - sin_half)
        dv = u[k] - u[k - 1]
        dv /= np.linalg.norm(dv)
        centripetal = v * v / r * np.abs(dv)
        rate = v**3 / r**2 * np.abs(dv)
        assert np.all(centripetal <= lim.acceleration * tol)
        assert np.all(rate <= lim.jerk * tol)


def test_collinear_blocks_run_through_at_the_feed() -> None:
    # Two 150 mm halves of the 300 mm line: the look-ahead lets the first end at the feed
    # (each half is long enough to reach it), so the program takes the single line's time.
    one = plan(read_program("G1 X300 F30000\n"), LIMITS)
    two = plan(read_program("G1 X150 F30000\nG1 X300\n"), LIMITS)
    assert two.entry_speed[1] == pytest.approx(0.5, rel=1e-6)
    assert two.duration == pytest.approx(one.duration, rel=1e-6)


def test_a_slower_block_is_entered_at_its_own_feed_and_a_dwell_adds_its_time() -> None:
    fast_slow = plan(read_program("G1 X150 F30000\nG1 X300 F6000\n"), LIMITS)
    assert fast_slow.entry_speed[1] == pytest.approx(0.1, rel=1e-6)
    # The second block cruises at 0.1 m/s from its start: its samples never exceed it.
    second = fast_slow.block == 1
    assert np.max(fast_slow.path_speed[second]) <= 0.1 * (1 + 1e-9)
    # A reversal of the path stops anyway: a dwell there adds exactly its 0.5 s.
    plain = plan(read_program("G1 X100 F6000\nG1 X0\n"), LIMITS)
    dwelt = plan(read_program("G1 X100 F6000\nG4 P0.5\nG1 X0\n"), LIMITS)
    assert dwelt.duration - plain.duration == pytest.approx(0.5, rel=1e-9)
