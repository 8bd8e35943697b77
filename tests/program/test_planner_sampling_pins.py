"""The planner's samples, its arcs' axes, its bound before planning and its retries, by hand.

Each pin checks the motion against a closed form written out here: the jerk-limited S-curve
from rest to rest (module docstring of the planner) reaching its top speed :math:`v` and
acceleration :math:`a` has two jerk phases of :math:`a/j`, a phase of constant acceleration
of :math:`v/a - a/j` and, over :math:`L`, a cruise of :math:`L/v - v/a - a/j`; a move too short
for the acceleration is four jerk phases of :math:`T = (L/2j)^{1/3}`. Ruckig plans those
phases to about 1e-12 s, so sample counts are pinned exactly where no phase's duration is
within 1e-9 of a multiple of the sample time (each ratio is written out).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.program.gcode import read_program
from ballscrew.program.planner import Limits, at_rest, least_samples, plan

LIMITS = Limits(
    feed=np.array([0.5, 0.5, 0.25]),
    acceleration=np.array([2.0, 3.0, 2.0]),
    jerk=np.array([50.0, 60.0, 40.0]),
    rapid_feed=0.5,
    path_tolerance=2e-5,
    sample_time=4.5e-3,
)


def with_sample_time(dt: float) -> Limits:
    return Limits(feed=LIMITS.feed, acceleration=LIMITS.acceleration, jerk=LIMITS.jerk,
                  rapid_feed=0.5, path_tolerance=2e-5, sample_time=dt)  # fmt: skip


# --- samples of lines -------------------------------------------------------------------


def test_a_line_is_sampled_every_sample_time_in_its_speed_changes_and_not_in_its_cruise() -> None:
    # 300 mm on X at 0.5 m/s, 2 m/s^2, 50 m/s^3: jerk phases of a/j = 0.04 s (8.9 samples
    # of 4.5 ms: 9), the constant acceleration v/a - a/j = 0.21 s (46.7: 47), the cruise
    # L/v - v/a - a/j = 0.31 s one sample; twice the speed change, and the block's end.
    m = plan(read_program("G1 X300 F30000\n"), LIMITS)
    assert m.time.size == 2 * (9 + 47 + 9) + 1 + 1
    assert m.time[0] == 0.0 and m.duration == pytest.approx(0.6 + 0.25 + 0.04, rel=1e-9)
    gaps = np.diff(m.time)
    # The cruise is one gap of 0.31 s, from its start to the first sample of the braking.
    assert np.max(gaps) == pytest.approx(0.31, rel=1e-9)
    assert np.sort(gaps)[-2] <= 4.5e-3 * (1 + 1e-9)
    # The first sample starts the jerk phase at X's 50 m/s^3; the last is at rest at the end.
    np.testing.assert_allclose(m.jerk[0], [50.0, 0.0, 0.0], rtol=1e-12)
    assert np.all(m.jerk[-1] == 0.0) and np.all(m.acceleration[-1] == 0.0)
    assert np.all(m.velocity[-1] == 0.0) and np.all(m.position[-1] == [0.3, 0.0, 0.0])


def test_a_lines_axes_follow_the_s_curve_from_the_lines_start() -> None:
    # 300 mm along X from (100, 50, 0) mm: X = 0.1 + s(t), its speed, acceleration and jerk
    # those of the S-curve's closed form (below), Y and Z standing. Ruckig's phases are exact
    # to about 1e-12 s: 1e-9 of each quantity's scale.
    m = plan(read_program("G1 X400 Y50 F30000\n", start=(0.1, 0.05, 0.0)), LIMITS)
    s, sd, sdd, sddd = s_curve(m.time, 0.3, 0.5, 2.0, 50.0)
    ends = np.cumsum([0, 0.04, 0.21, 0.04, 0.31, 0.04, 0.21, 0.04])
    inside = np.min(np.abs(m.time[:, None] - ends[None, :]), axis=1) > 1e-6
    np.testing.assert_allclose(m.position[:, 0], 0.1 + s, rtol=0, atol=1e-12)
    np.testing.assert_allclose(m.velocity[:, 0], sd, rtol=0, atol=1e-9 * 0.5)
    np.testing.assert_allclose(m.acceleration[inside, 0], sdd[inside], rtol=0, atol=1e-9 * 2)
    np.testing.assert_allclose(m.jerk[inside, 0], sddd[inside], rtol=0, atol=1e-9 * 50)
    assert np.all(m.position[:, 1] == 0.05) and np.all(m.position[:, 2] == 0.0)


def test_a_short_line_has_four_jerk_phases_and_no_sample_in_its_empty_phases() -> None:
    # 1 mm on X: no acceleration nor cruise phase, four jerk phases of T = (L/2j)^(1/3) =
    # 21.5 ms (4.8 samples of 4.5 ms: 5 each) and the end: 21 samples, no two at one time.
    t_j = (1e-3 / (2 * 50.0)) ** (1 / 3)
    m = plan(read_program("G1 X1 F30000\n"), LIMITS)
    assert m.duration == pytest.approx(4 * t_j, rel=1e-9)
    assert m.time.size == 4 * 5 + 1
    assert np.all(np.diff(m.time) > 0.0)
    # The path speed peaks at j T^2 in the middle, which is a sample (a phase's start).
    assert np.max(m.path_speed) == pytest.approx(50.0 * t_j**2, rel=1e-9)


def test_the_default_sample_time_is_five_milliseconds() -> None:
    # X at 2.2 m/s^2: jerk phases of 2.2/50 = 44 ms (8.8 samples of 5 ms: 9), the constant
    # acceleration 0.5/2.2 - 0.044 = 183.3 ms (36.7: 37); at 5.5 ms it would be 8 and 34.
    lim = Limits(feed=np.full(3, 0.5), acceleration=np.full(3, 2.2), jerk=np.full(3, 50.0),
                 rapid_feed=0.5, path_tolerance=2e-5)  # fmt: skip
    m = plan(read_program("G1 X300 F30000\n"), lim)
    assert m.time.size == 2 * (9 + 37 + 9) + 1 + 1


def test_a_junction_is_sampled_twice_and_its_speed_carried_over() -> None:
    # Two collinear halves at the feed: the first block ends at 0.5 m/s, the second starts
    # there; both samples at one time, with the path speed 0.5 and no acceleration at the end.
    m = plan(read_program("G1 X150 F30000\nG1 X300\n"), LIMITS)
    junction = np.flatnonzero(np.diff(m.block) != 0)
    assert junction.size == 1
    k = int(junction[0])
    assert m.time[k] == m.time[k + 1]
    # Each half: the speed change's 9 + 47 + 9 samples (4.5 ms), its cruise's one, its end.
    assert m.time.size == 2 * (9 + 47 + 9 + 1 + 1)
    np.testing.assert_allclose(m.position[k], [0.15, 0.0, 0.0], atol=1e-15)
    assert m.path_speed[k] == pytest.approx(0.5, rel=1e-6)
    assert m.path_speed[k + 1] == pytest.approx(0.5, rel=1e-6)
    assert np.all(m.acceleration[k] == 0.0)


def test_the_nominal_time_and_the_feed_flags() -> None:
    # A rapid of 300 mm at 0.5 m/s (0.6 s), a feed back at 0.5 m/s (0.6 s), a dwell of 0.5 s
    # and a half circle of R 10 mm at 0.5 m/s (pi x 0.01 / 0.5 s); only G1 and G3 feed.
    text = "G0 X300\nG1 X0 F30000\nG4 P0.5\nG3 X-20 I-10 J0\n"
    m = plan(read_program(text), LIMITS)
    assert m.nominal_time == pytest.approx(0.6 + 0.6 + 0.5 + math.pi * 0.01 / 0.5, rel=1e-12)
    for block, feeding in ((0, False), (1, True), (2, False), (3, True)):
        assert np.all(m.feeding[m.block == block] == feeding)
    # The dwell's samples stand at X0 for its 0.5 s.
    dwell = m.block == 2
    assert np.ptp(m.time[dwell]) == pytest.approx(0.5, rel=1e-12)
    assert np.all(m.position[dwell] == 0.0) and np.all(m.velocity[dwell] == 0.0)


def test_a_program_that_starts_with_a_dwell_enters_every_block_at_rest() -> None:
    # A dwell, then a line from rest: every block's entry is 0, and the line takes its
    # rest-to-rest time (10 mm at 0.1 m/s, 2 m/s^2, 50 m/s^3: L/v + v/a + a/j) after 0.5 s.
    m = plan(read_program("G4 P0.5\nG1 X10 F6000\n"), LIMITS)
    np.testing.assert_array_equal(m.entry_speed, [0.0, 0.0])
    np.testing.assert_array_equal(m.exit_speed, [0.0, 0.0])
    assert m.duration == pytest.approx(0.5 + 0.01 / 0.1 + 0.1 / 2.0 + 2.0 / 50.0, rel=1e-9)


def test_a_dwell_of_no_time_between_two_moves_has_no_sample() -> None:
    # Two 10 mm moves at 0.1 m/s, 2 m/s^2, 50 m/s^3 with a dwell of 0 s between: each move
    # from rest to rest, jerk phases of 0.04 s (8.9 samples of 4.5 ms: 9), the constant
    # acceleration 0.01 s (2.2: 3), the cruise one sample, the end; the dwell none.
    m = plan(read_program("G1 X10 F6000\nG4 P0\nG1 X0\n"), LIMITS)
    assert m.time.size == 2 * (2 * (9 + 3 + 9) + 1 + 1)
    assert sorted(set(m.block.tolist())) == [0, 2]
    assert m.duration == pytest.approx(2 * (0.01 / 0.1 + 0.1 / 2.0 + 2.0 / 50.0), rel=1e-9)


def test_a_program_without_time_stands_at_its_start() -> None:
    # No block, or only a dwell of 0 s: one sample at rest, at time 0, at the start given.
    for text, blocks in (("M30\n", 0), ("G4 P0\nG4 P0\n", 2)):
        program = read_program(text, start=(0.1, 0.2, 0.3))
        for m in (plan(program, LIMITS), at_rest(program)):
            assert m.time.tolist() == [0.0] and m.path_speed.tolist() == [0.0]
            expected = [[0.1, 0.2, 0.3]] if blocks else [[0.0, 0.0, 0.0]]
            np.testing.assert_array_equal(m.position, expected)
            for rows in (m.velocity, m.acceleration, m.jerk):
                np.testing.assert_array_equal(rows, np.zeros((1, 3)))
            assert m.block.tolist() == [0] and m.feeding.tolist() == [False]
            for per_block in (m.entry_speed, m.exit_speed, m.block_limit, m.block_time):
                np.testing.assert_array_equal(per_block, np.zeros(blocks))
            assert m.nominal_time == 0.0 and m.duration == 0.0
        # The bound before planning: no time; the program without blocks has its one sample
        # (two dwells of 0 s end nowhere: a bound of 0 samples, below the plan's 1).
        assert least_samples(program, LIMITS) == (0.0, 0 if blocks else 1)


# --- arcs: samples every 5 degrees, the axes' turns, the axes' derivatives --------------

SLOW = Limits(feed=np.ones(3), acceleration=np.full(3, 0.02), jerk=np.full(3, 0.1),
              rapid_feed=1.0, path_tolerance=2e-5, sample_time=10.0)  # fmt: skip
"""Slow axes for arcs of R 10 mm at F600 (0.01 m/s): the centripetal bound sqrt(0.5 a R) =
0.01 m/s, the tangential half 0.01 m/s^2 and 0.05 m/s^3 (a/j = 0.2 s, v/a = 1 s), so every
phase sweeps degrees; a sample time of 10 s leaves the angle to set the samples."""


def s_curve(t: np.ndarray, length: float, v: float, a: float, j: float) -> tuple[np.ndarray, ...]:
    """Path position, speed, acceleration and jerk at ``t`` of the rest-to-rest S-curve
    reaching ``v`` and ``a`` over ``length`` (module docstring), phase by phase."""
    t1, t2 = a / j, v / a - a / j
    total = length / v + v / a + a / j
    assert t2 >= 0.0 and total >= 2 * (2 * t1 + t2)

    def rise(t: np.ndarray) -> tuple[np.ndarray, ...]:
        v1, s1 = j * t1**2 / 2, j * t1**3 / 6
        v2, s2 = v1 + a * t2, s1 + v1 * t2 + a * t2**2 / 2
        u, w = t - t1, t - t1 - t2
        phase = np.where(t < t1, 0, np.where(t < t1 + t2, 1, np.where(t < 2 * t1 + t2, 2, 3)))
        s = np.choose(
            phase,
            [
                j * t**3 / 6,
                s1 + v1 * u + a * u**2 / 2,
                s2 + v2 * w + a * w**2 / 2 - j * w**3 / 6,
                s2 + v2 * t1 + a * t1**2 / 2 - j * t1**3 / 6 + v * (w - t1),
            ],
        )
        sd = np.choose(phase, [j * t**2 / 2, v1 + a * u, v2 + a * w - j * w**2 / 2,
                               np.full_like(t, v)])  # fmt: skip
        sdd = np.choose(phase, [j * t, np.full_like(t, a), a - j * w, np.zeros_like(t)])
        sddd = np.choose(phase, [np.full_like(t, j), np.zeros_like(t), np.full_like(t, -j),
                                 np.zeros_like(t)])  # fmt: skip
        return s, sd, sdd, sddd

    up = t <= total / 2
    s_u, sd_u, sdd_u, sddd_u = rise(np.where(up, t, total - t))
    return (np.where(up, s_u, length - s_u), sd_u, np.where(up, sdd_u, -sdd_u),
            sddd_u)  # fmt: skip


def test_an_arc_is_sampled_every_five_degrees_of_each_phase() -> None:
    # A half circle of R 10 mm from 180 deg, counter-clockwise, at 0.01 m/s: the speed
    # change's phases sweep s1 = j t1^3/6 (0.38 deg: 1 sample), the constant acceleration
    # v1 t2 + a t2^2/2 (22.9 deg: 5), the last jerk phase v2 t1 + a t1^2/2 - j t1^3/6
    # (11.1 deg: 3), and the cruise 180 deg less twice 34.4 deg (111.2 deg: 23); at least one
    # sample every 5 deg of each phase, the turn of Y at 270 deg and the end.
    r, v, a, j = 0.01, 0.01, 0.01, 0.05
    t1, t2 = a / j, v / a - a / j
    v1, v2 = j * t1**2 / 2, j * t1**2 / 2 + a * t2
    rise = [j * t1**3 / 6, v1 * t2 + a * t2**2 / 2, v2 * t1 + a * t1**2 / 2 - j * t1**3 / 6]
    cruise = math.pi * r - 2 * sum(rise)
    degrees = [math.degrees(s / r) for s in [*rise, cruise, *rise[::-1]]]
    expected = sum(math.ceil(d / 5.0) for d in degrees) + 1 + 1
    assert expected == 2 * (1 + 5 + 3) + 23 + 2
    m = plan(read_program("G3 X20 Y0 I10 J0 F600\n"), SLOW)
    assert m.duration == pytest.approx(math.pi * r / v + v / a + a / j, rel=1e-9)
    assert m.time.size == expected
    # The bound before planning: the arc's length at its speed, sampled throughout (10 s).
    seconds, samples = least_samples(read_program("G3 X20 Y0 I10 J0 F600\n"), SLOW)
    assert seconds == pytest.approx(math.pi * r / v, rel=1e-12) and samples == 0 + 1
    # The samples of a phase are evenly spaced in time: in the cruise, 111.2/23 = 4.83 deg
    # (the turn's sample left out).
    angle = np.unwrap(np.arctan2(m.position[:, 1], m.position[:, 0] - r))
    angle = angle[np.abs(angle - 1.5 * math.pi) > 1e-9]
    cruise_gaps = np.diff(angle)[9 : 9 + 23]
    np.testing.assert_allclose(cruise_gaps, math.radians(degrees[3] / 23), rtol=1e-9)


@pytest.mark.parametrize("r_mm", [0.7, 3.0])
def test_a_small_arcs_samples_follow_each_phases_angle(r_mm: float) -> None:
    # A half circle of R 0.7 or 3 mm at its centripetal bound sqrt(0.5 x 0.02 R) (2.6 and
    # 5.5 mm/s, the jerk's bound (0.5 x 0.1 R^2)^(1/3) is higher): the phases' angles
    # (R 0.7 mm: 5.5, 7.0, 37.9 deg up, 79.4 cruising, the same down) set the samples.
    r = r_mm * 1e-3
    v, a, j = math.sqrt(0.5 * 0.02 * r), 0.01, 0.05
    assert v < (0.5 * 0.1 * r * r) ** (1 / 3) and v > a * a / j
    t1, t2 = a / j, v / a - a / j
    v1, v2 = j * t1**2 / 2, j * t1**2 / 2 + a * t2
    rise = [j * t1**3 / 6, v1 * t2 + a * t2**2 / 2, v2 * t1 + a * t1**2 / 2 - j * t1**3 / 6]
    cruise = math.pi * r - 2 * sum(rise)
    degrees = [math.degrees(s / r) for s in [*rise, cruise, *rise[::-1]]]
    assert min(abs(d / 5.0 - round(d / 5.0)) for d in degrees) > 0.05  # no ceil on an edge
    text = f"G3 X{2 * r_mm:g} Y0 I{r_mm:g} J0 F600\n"
    m = plan(read_program(text), SLOW)
    assert m.duration == pytest.approx(math.pi * r / v + v / a + a / j, rel=1e-9)
    # One sample every 5 deg of each phase, the turn at 270 deg, the end.
    assert m.time.size == sum(math.ceil(d / 5.0) for d in degrees) + 1 + 1


def test_an_arc_is_sampled_where_an_axis_turns() -> None:
    # A full circle of R 10 mm from 30 deg: X turns at 180 and 360 deg, Y at 90 and 270 deg;
    # each is a sample, on the circle's extreme point (to rounding: 1e-12 m), with that
    # axis at rest. Its start and end (30 deg) are no turn.
    r = 0.01
    c = np.array([-r * math.cos(math.radians(30)), -r * math.sin(math.radians(30))])
    text = f"G3 X0 Y0 I{c[0] * 1e3:.12f} J{c[1] * 1e3:.12f} F600\n"
    m = plan(read_program(text), SLOW)
    for deg, axis in ((90, 1), (180, 0), (270, 1), (360, 0)):
        point = c + r * np.array([math.cos(math.radians(deg)), math.sin(math.radians(deg))])
        hit = np.flatnonzero(np.all(np.abs(m.position[:, :2] - point) < 1e-12, axis=1))
        assert hit.size == 1, deg
        assert abs(m.velocity[hit[0], axis]) < 1e-15
    # Every sample is one of the angle's (5 deg within each phase), those four, or the end.
    r_, v, a, j = r, 0.01, 0.01, 0.05
    t1, t2 = a / j, v / a - a / j
    v1, v2 = j * t1**2 / 2, j * t1**2 / 2 + a * t2
    rise = [j * t1**3 / 6, v1 * t2 + a * t2**2 / 2, v2 * t1 + a * t1**2 / 2 - j * t1**3 / 6]
    cruise = 2 * math.pi * r_ - 2 * sum(rise)
    degrees = [math.degrees(s / r_) for s in [*rise, cruise, *rise[::-1]]]
    assert m.time.size == sum(math.ceil(d / 5.0) for d in degrees) + 4 + 1


PLANES = {
    17: ("X", "Y", "I", "J", 0, 1),
    18: ("Z", "X", "K", "I", 2, 0),
    19: ("Y", "Z", "J", "K", 1, 2),
}
"""Each plane's in-plane axes, their centre words and their indices (the angle from the first)."""


def _arc_text(plane: int, start: float, sweep: float, turns: int = 1) -> tuple[str, list[float]]:
    """``turns`` arcs of R 10 mm about the origin from ``start`` over ``sweep`` degrees at F600,
    one after the other (each from where the last ended), and the program's start."""
    a, b, ca, cb, ia, ib = PLANES[plane]
    r = 10.0
    lines = [f"G{plane}"]
    for k in range(turns):
        th0, th1 = math.radians(start + k * sweep), math.radians(start + (k + 1) * sweep)
        lines.append(f"{'G3' if sweep > 0 else 'G2'} {a}{r * math.cos(th1):.12f} "
                     f"{b}{r * math.sin(th1):.12f} {ca}{-r * math.cos(th0):.12f} "
                     f"{cb}{-r * math.sin(th0):.12f} F600")  # fmt: skip
    origin = [0.0, 0.0, 0.0]
    origin[ia] = 0.01 * math.cos(math.radians(start))
    origin[ib] = 0.01 * math.sin(math.radians(start))
    return "\n".join([*lines, ""]), origin


@pytest.mark.parametrize(
    ("plane", "start", "sweep", "turns"),
    [
        # From 62 deg over 300 deg: 90 deg in the last jerk phase of the speed change up
        # (28 deg in), 180 and 270 in the cruise, 360 in the constant braking (32.4 deg
        # before the end). In each plane.
        (17, 62.0, 300.0, (90, 180, 270, 360)),
        (18, 62.0, 300.0, (90, 180, 270, 360)),
        (19, 62.0, 300.0, (90, 180, 270, 360)),
        # Clockwise from 200 deg over 150: 180 and 90 deg.
        (18, 200.0, -150.0, (180, 90)),
        # From 75 to 100 deg: 0.44 rad, no cruise; the turn at 90 deg.
        (17, 75.0, 25.0, (90,)),
        # Clockwise from 100 to 75 deg.
        (17, 100.0, -25.0, (90,)),
        # From 89.8 deg: the turn in the first jerk phase (0.38 deg long).
        (17, 89.8, 30.0, (90,)),
    ],
)
def test_every_turn_is_sampled_on_the_circle(plane: int, start: float, sweep: float,
                                             turns: tuple[int, ...]) -> None:  # fmt: skip
    # R 10 mm about the origin; each turn a sample on the circle's extreme point, to
    # rounding (1e-12 m), where that axis is at rest; no two samples at one time.
    _, _, _, _, ia, ib = PLANES[plane]
    text, origin = _arc_text(plane, start, sweep)
    m = plan(read_program(text, start=origin), SLOW)
    for deg in turns:
        point = 0.01 * np.array([math.cos(math.radians(deg)), math.sin(math.radians(deg))])
        near = np.abs(m.position[:, [ia, ib]] - point) < 1e-12
        hit = np.flatnonzero(np.all(near, axis=1))
        assert hit.size == 1, deg
        assert abs(m.velocity[hit[0], ia if deg % 180 == 0 else ib]) < 1e-15
    assert np.all(np.diff(m.time) > 0.0)


def test_two_full_circles_each_turn_four_times() -> None:
    # Two full circles from 30 deg, one after the other: each has its four turns.
    text, origin = _arc_text(17, 30.0, 360.0, turns=2)
    m = plan(read_program(text, start=origin), SLOW)
    for block in (0, 1):
        for deg in (90, 180, 270, 360):
            point = 0.01 * np.array([math.cos(math.radians(deg)), math.sin(math.radians(deg))])
            near = np.all(np.abs(m.position[:, :2] - point) < 1e-12, axis=1)
            assert np.sum(near & (m.block == block)) == 1, (block, deg)


def test_a_quarter_circle_from_an_axis_to_an_axis_has_no_turn_inside() -> None:
    # From 0 to 90 deg: X turns at 90 deg, the arc's end, which is its own sample; no sample
    # is added at either end, so no two samples share a time.
    m = plan(read_program("G3 X-10 Y10 I-10 J0 F600\n"), SLOW)
    assert np.all(np.diff(m.time) > 0.0)
    # Its samples: 5 deg of each phase (0.38, 22.9, 11.1 deg up, 21.2 cruising, the same
    # down: 1, 5, 3, 5, 3, 5, 1) and the end, nothing more.
    assert m.time.size == 2 * (1 + 5 + 3) + 5 + 1
    np.testing.assert_allclose(m.position[-1], [-0.01, 0.01, 0.0], atol=1e-15)
    assert m.velocity[-1, 0] == 0.0


@pytest.mark.parametrize(
    ("text", "plane", "centre", "rise", "sign"),
    [
        ("G17 G3 X20 Y0 I10 J0 F600\n", (0, 1, 2), (0.01, 0.0), 0.0, 1.0),
        ("G18 G2 X0 Z20 K10 I0 F600\n", (2, 0, 1), (0.01, 0.0), 0.0, -1.0),
        ("G19 G3 Y20 Z0 J10 K0 F600\n", (1, 2, 0), (0.01, 0.0), 0.0, 1.0),
        ("G18 G3 X0 Z20 Y7 K10 I0 F600\n", (2, 0, 1), (0.01, 0.0), 0.005, 1.0),
    ],
    ids=["G17", "G18-clockwise", "G19", "G18-helix"],
)
def test_an_arcs_axes_follow_the_circle_and_its_derivatives(
    text: str, plane: tuple[int, int, int], centre: tuple[float, float], rise: float,
    sign: float,
) -> None:  # fmt: skip
    # On the circle p = c + R e^(i theta), theta = theta0 + sign k s/R (k: the in-plane share
    # of a helix), p' = i R theta' e^(i theta), p'' = R (i theta'' - theta'^2) e^(i theta),
    # p''' = R (i theta''' - 3 theta' theta'' - i theta'^3) e^(i theta); the normal axis
    # moves n s. The path's s(t) is the S-curve's closed form at 0.01 m/s, and a = 0.01/k,
    # j = 0.05/k along the path (the in-plane halves over the share). Ruckig's phases are
    # exact to about 1e-12 s; 1e-8 of each quantity's scale.
    r = 0.01
    ia, ib, inn = plane
    length = math.hypot(math.pi * r, rise)
    k, n = math.pi * r / length, rise / length
    v, a, j = 0.01, 0.01 / k, 0.05 / k
    lim = Limits(feed=SLOW.feed, acceleration=SLOW.acceleration, jerk=SLOW.jerk, rapid_feed=1.0,
                 path_tolerance=2e-5, sample_time=0.05)  # fmt: skip
    # The normal axis starts 2 mm off zero (a helix rises from there).
    start = [0.0, 0.0, 0.0]
    start[inn] = 0.002
    m = plan(read_program(text, start=start), lim)
    assert m.duration == pytest.approx(length / v + v / a + a / j, rel=1e-9)
    s, sd, sdd, sddd = s_curve(m.time, length, v, a, j)
    # The phases' ends are samples where the jerk steps: compare inside the phases.
    ends = np.cumsum([0, a / j, v / a - a / j, a / j, length / v - v / a - a / j, a / j,
                      v / a - a / j, a / j])  # fmt: skip
    inside = np.min(np.abs(m.time[:, None] - ends[None, :]), axis=1) > 1e-6
    assert inside.sum() > 40
    np.testing.assert_allclose(m.path_speed, sd, rtol=0, atol=1e-10)
    # The second in-plane axis turns half-way (270 deg, or 90 deg clockwise): a sample (the
    # helix's cruise has one of its own there too).
    assert np.sum(np.abs(np.abs(m.position[:, ib] - centre[1]) - r) < 1e-12) >= 1
    w = sign * k / r
    theta = math.pi + w * s
    d1, d2, d3 = w * sd, w * sdd, w * sddd
    e = np.exp(1j * theta)
    expected = [
        centre[0] + centre[1] * 1j + r * e,
        1j * r * d1 * e,
        r * (1j * d2 - d1**2) * e,
        r * (1j * d3 - 3 * d1 * d2 - 1j * d1**3) * e,
    ]
    normal = [0.002 + n * s, n * sd, n * sdd, n * sddd]
    for got, want, lin, scale in zip((m.position, m.velocity, m.acceleration, m.jerk),
                                     expected, normal, (r, v, a, j), strict=True):  # fmt: skip
        sel = inside if scale in (a, j) else np.ones(m.time.size, bool)
        np.testing.assert_allclose(got[sel, ia], want.real[sel], rtol=0, atol=1e-8 * scale)
        np.testing.assert_allclose(got[sel, ib], want.imag[sel], rtol=0, atol=1e-8 * scale)
        np.testing.assert_allclose(got[sel, inn], lin[sel], rtol=0, atol=1e-8 * scale)


# --- a block ruckig refuses: its exit lowered by 0, 1e-7, 1e-6, 1e-5, 1e-4 in turn --------


def _refusing(monkeypatch: pytest.MonkeyPatch, above: float, how: str) -> list[float]:
    """Ruckig refusing every exit speed above ``above`` (raising, or an error result); the
    exit speeds it was asked for, in order."""
    import ruckig

    real, asked = ruckig.Ruckig, []

    class Refusing:
        def __init__(self, dofs: int) -> None:
            self.otg = real(dofs)

        def calculate(self, inp: object, traj: object) -> object:
            target = float(inp.target_velocity[0])  # type: ignore[attr-defined]
            asked.append(target)
            if target > above:
                if how == "raise":
                    raise ruckig.RuckigError("refused")
                return ruckig.Result.ErrorInvalidInput
            return self.otg.calculate(inp, traj)

    monkeypatch.setattr(ruckig, "Ruckig", Refusing)
    return asked


@pytest.mark.parametrize("how", ["raise", "result"])
def test_a_refused_exit_is_lowered_by_each_share_in_turn(
    monkeypatch: pytest.MonkeyPatch, how: str
) -> None:
    # Three collinear thirds: the first two blocks exit at the feed, 0.5 m/s. Refused above
    # 0.5 (1 - 5e-5), each is asked at 0.5, then lowered by 1e-7, 1e-6, 1e-5 (1.11e-5 in all:
    # still refused) and 1e-4 (1.111e-4: planned); the next block enters at that speed.
    asked = _refusing(monkeypatch, 0.5 * (1 - 5e-5), how)
    m = plan(read_program("G1 X100 F30000\nG1 X200\nG1 X300\n"), LIMITS)
    shares = [0.0, 1e-7, 1e-6, 1e-5, 1e-4]
    tried = [0.5 * math.prod(1 - x for x in shares[: i + 1]) for i in range(5)]
    # The second block enters at the first's lowered exit and is asked for 0.5 again.
    np.testing.assert_allclose(asked, [*tried, *tried, 0.0], rtol=1e-15)
    np.testing.assert_allclose(m.exit_speed, [tried[-1], tried[-1], 0.0], rtol=1e-15)
    np.testing.assert_array_equal(m.entry_speed, [0.0, *m.exit_speed[:2]])
    # The path speed is continuous at the junctions: the next block starts from it.
    for k in np.flatnonzero(np.diff(m.block) != 0):
        assert m.path_speed[k] == m.path_speed[k + 1] == m.exit_speed[m.block[k]]
    # Not far from the plan without refusals: 1.1e-4 of the speed over the junctions.
    assert m.duration == pytest.approx(0.3 / 0.5 + 0.5 / 2.0 + 2.0 / 50.0, rel=1e-5)


def test_a_block_refused_at_every_share_is_refused_by_its_line(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # Refused above 0.5 (1 - 2e-4): the five tries lower the exit by 1.111e-4 at most.
    asked = _refusing(monkeypatch, 0.5 * (1 - 2e-4), "raise")
    with pytest.raises(BallScrewInputError) as info:
        plan(read_program("G1 X150 F30000\nG1 X300\n"), LIMITS)
    assert info.value.field == "program line 1" and "ruckig" in str(info.value)
    lowest = 0.5 * (1 - 1e-7) * (1 - 1e-6) * (1 - 1e-5) * (1 - 1e-4)
    assert len(asked) == 5 and asked[-1] == pytest.approx(lowest, rel=1e-15)


# --- the bound before planning, and the refusals past it ----------------------------------


@pytest.mark.parametrize(
    ("text", "seconds", "busy", "ends"),
    [
        # At the feed: L/v = 0.6 s; the speed change to 0.5 m/s and back, v/a + a/j each.
        ("G1 X300 F30000\n", 0.6, 2 * (0.5 / 2.0 + 2.0 / 50.0), 1),
        # At 0.01 m/s, below a^2/j = 0.08: 2 sqrt(dv/j) each way.
        ("G1 X300 F600\n", 30.0, 2 * 2 * math.sqrt(0.01 / 50.0), 1),
        # 1 mm from rest to rest reaches j s^2 with j s^3 = L: L over it, (L/j)^(1/3), all busy.
        ("G1 X1 F30000\n", (1e-3 / 50.0) ** (1 / 3), (1e-3 / 50.0) ** (1 / 3), 1),
        # A half circle of R 10 mm at sqrt(0.5 x 2 R) = 0.1 m/s: an arc is sampled throughout.
        ("G3 X20 Y0 I10 J0 F30000\n", math.pi * 0.01 / 0.1, math.pi * 0.01 / 0.1, 1),
        # Two halves at the feed: the speed changes up in the first and down in the second,
        # none at the junction (entered and left at the top).
        ("G1 X150 F30000\nG1 X300\n", 0.6, 2 * (0.5 / 2.0 + 2.0 / 50.0), 2),
        # Dwells: their time, one end each but for a dwell of 0 s.
        ("G4 P0.5\nG4 P0\n", 0.5, 0.0, 1),
    ],
    ids=["cruise", "slow", "short", "arc", "halves", "dwells"],
)
def test_the_bound_before_planning_by_hand(text: str, seconds: float, busy: float, ends: int
                                           ) -> None:  # fmt: skip
    # At least one sample every 4.5 ms of the speed changes, and one at each block's end.
    program = read_program(text)
    got_seconds, got_samples = least_samples(program, LIMITS)
    assert got_seconds == pytest.approx(seconds, rel=1e-12)
    assert got_samples == int(busy / 4.5e-3) + ends
    m = plan(program, LIMITS)
    assert got_seconds <= m.duration and got_samples <= m.time.size


def test_the_bound_before_planning_just_below_the_speed_changes_full_acceleration() -> None:
    # At 4000 mm/min (0.0667 m/s, between a^2/j = 0.08 and half of it) the speed change
    # does not reach a: 2 sqrt(dv/j) = 73.03 ms each way (dv/a + a/j would be 73.33 ms).
    v = 4.0 / 60.0
    busy = 2 * 2 * math.sqrt(v / 50.0)
    seconds, samples = least_samples(read_program("G1 X300 F4000\n"), with_sample_time(1e-5))
    assert seconds == pytest.approx(0.3 / v, rel=1e-12)
    assert busy / 1e-5 % 1 > 0.1  # 14605.9: no rounding at the integer part
    assert samples == int(busy / 1e-5) + 1


def test_a_program_past_the_samples_is_refused_by_the_bound_or_by_the_plans_count() -> None:
    # The 300 mm line at 4.5 ms: the bound is 129 samples (above), the plan makes 132.
    program = read_program("G1 X300 F30000\n")
    assert plan(program, LIMITS, max_samples=132).time.size == 132
    with pytest.raises(BallScrewInputError) as info:
        plan(program, LIMITS, max_samples=131)
    said = str(info.value)
    assert "about 132 samples (0.89 s of motion, a sample at most every 4.5 ms)" in said
    assert "at most 131 samples" in said and "counted from the plan" in said
    # At the bound itself, the plan counts.
    with pytest.raises(BallScrewInputError, match="about 132 samples"):
        plan(program, LIMITS, max_samples=129)
    with pytest.raises(BallScrewInputError) as info:
        plan(program, LIMITS, max_samples=128)
    said = str(info.value)
    assert "at least 129 samples (at least 0.6 s, a sample at most every 4.5 ms)" in said
    assert "a lower bound estimated before planning" in said
    # The count holds an arc's turns: the half circle at 0.01 m/s has 43 samples (above).
    arc = read_program("G3 X20 Y0 I10 J0 F600\n")
    assert plan(arc, SLOW, max_samples=43).time.size == 43
    with pytest.raises(BallScrewInputError, match="about 43 samples"):
        plan(arc, SLOW, max_samples=42)


def test_the_default_bound_is_three_million_samples() -> None:
    # The 300 mm line's 0.58 s of speed change at a sample every 0.187 us: at least 3.1
    # million samples, past the 3 million allowed; refused before a block is planned.
    with pytest.raises(BallScrewInputError) as info:
        plan(read_program("G1 X300 F30000\n"), with_sample_time(0.58 / 3.1e6))
    said = str(info.value)
    assert "at least 3.1e+06 samples" in said and "at most 3e+06 samples" in said


# --- the look-ahead's margin, the progress -------------------------------------------------


def test_the_look_ahead_keeps_one_ten_millionth_below_the_stopping_speed() -> None:
    # 5 mm before a reversal: X (2 m/s^2, 50 m/s^3) stops within it from the root of
    # 0.25 v^2 + 0.02 v = 0.005 m; the block before enters it 1e-7 below that speed.
    v_stop = (-0.02 + math.sqrt(0.02**2 + 4 * 0.25 * 0.005)) / (2 * 0.25)
    m = plan(read_program("G1 X300 F30000\nG1 X305\nG1 X0\n"), LIMITS)
    assert m.entry_speed[1] == pytest.approx(v_stop * (1 - 1e-7), rel=1e-13)


@pytest.mark.parametrize(("blocks", "step"), [(50, 1), (250, 2)])
def test_the_progress_is_told_every_hundredth_of_the_blocks_and_at_the_end(
    blocks: int, step: int
) -> None:
    told: list[tuple[int, int]] = []
    text = "G1 F30000\n" + "".join(f"G1 X{k + 1}\n" for k in range(blocks))
    plan(read_program(text), LIMITS, progress=lambda done, total: told.append((done, total)))
    assert told == [(k, blocks) for k in range(0, blocks, step)] + [(blocks, blocks)]
