"""Rotary axes listed with their limits: their moves are timed, the ball screws' energy not."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.io.machine import Machine, parse_machine
from ballscrew.program.gcode import FEED, RAPID, read_program
from ballscrew.program.planner import Limits, plan

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"
TABLE = (
    '\n[axes.A]\nmax_feed = "90 deg/s"\nmax_acceleration = "360 deg/s^2"\n'
    'max_jerk = "3600 deg/s^3"\nnote = "a tilting table"\n'
)


@pytest.fixture(scope="module")
def machine() -> Machine:
    text = (EXAMPLES / "machine_vmc.toml").read_text("utf-8")
    return parse_machine(text + TABLE, folder=EXAMPLES)


def limits(omega: float = math.pi / 2) -> Limits:
    """X, Y, Z at 0.5 m/s, 2 m/s^2, 50 m/s^3; A at ``omega``, 360 deg/s^2, 3600 deg/s^3."""
    return Limits(
        np.full(3, 0.5), np.full(3, 2.0), np.full(3, 50.0), 0.5, 1e-5,
        rotary_feed=np.array([omega, math.nan, math.nan]),
        rotary_acceleration=np.array([2 * math.pi, math.nan, math.nan]),
        rotary_jerk=np.array([20 * math.pi, math.nan, math.nan]),
    )  # fmt: skip


def test_the_machine_file_gives_the_limits_in_si(machine: Machine) -> None:
    a = machine.rotary["A"]
    assert (a.max_feed, a.max_acceleration, a.max_jerk) == pytest.approx(
        (math.pi / 2, 2 * math.pi, 20 * math.pi), rel=1e-12
    )
    assert any("axes.A" in n and "timed" in n for n in machine.notes)
    text = (EXAMPLES / "machine_vmc.toml").read_text("utf-8")
    with pytest.raises(BallScrewInputError) as info:
        parse_machine(text + TABLE.replace('max_jerk = "3600 deg/s^3"\n', ""), folder=EXAMPLES)
    assert info.value.field == "axes.A.max_jerk"


def test_a_rotary_move_alone_takes_its_jerk_limited_time() -> None:
    # 90 degrees at 90 deg/s, 360 deg/s^2, 3600 deg/s^3: the speed and the acceleration
    # are reached (v >= a^2/j, pi/2 >= pi/5), so T = theta/v + v/a + a/j = 1 + 0.25 + 0.1.
    p = read_program("G0 A90\nM30\n", machine=_with_a())
    m = plan(p, limits())
    assert m.duration == pytest.approx(1.35, rel=1e-6)
    assert np.all(m.position == 0.0) and np.all(m.velocity == 0.0)  # X, Y, Z stay
    # G1 alone on A: F in degrees per minute, 3600 deg/min = 60 deg/s (>= pi/5 rad/s):
    # 1.5 + (pi/3)/(2 pi) + 0.1 s.
    q = read_program("G1 A90 F3600\nM30\n", machine=_with_a())
    assert q.kind[0] == FEED and q.feed[0] == pytest.approx(math.pi / 3)
    assert plan(q, limits()).duration == pytest.approx(1.5 + 1 / 6 + 0.1, rel=1e-6)


def test_a_rotary_axis_caps_the_linear_feed_and_stops_at_its_corners() -> None:
    # X 100 mm while A turns 90 deg at 45 deg/s at most: 2 s at least, so X runs at
    # 50 mm/s instead of the programmed 100.
    p = read_program("G1 X100 A90 F6000\nG1 X200 A180\nM30\n", machine=_with_a())
    m = plan(p, limits(math.pi / 4))
    assert m.block_limit[0] == pytest.approx(0.05, rel=1e-12)
    assert m.entry_speed[1] == 0.0  # a junction with a rotary axis is a stop
    assert p.rotary_end[1, 0] == pytest.approx(math.pi)  # type: ignore[index]


def test_rotary_words_are_refused_without_limits(machine: Machine) -> None:
    for text, word in (("G1 B30 F100\n", "B30"), ("G2 X1 A5 I1 F100\n", "A5"),
                       ("G28 A0\n", "A0")):  # fmt: skip
        with pytest.raises(BallScrewInputError) as info:
            read_program(text, machine=machine)
        assert info.value.value == word
    with pytest.raises(BallScrewInputError):
        read_program("G0 A30\n")  # no machine file, no rotary axis


def test_the_ball_screws_run_and_the_rotary_axis_is_noted(machine: Machine) -> None:
    from ballscrew.program import run_program

    r = run_program(machine, "G0 A90\nG1 X100 F3000\nM30\n")
    assert list(r.axes) == ["X", "Y", "Z"]
    assert r.program.kind.tolist() == [RAPID, FEED] and "A" in r.program.axes
    assert any("rotary" in n and "left out" in n for n in r.notes)
    # The A move (1.35 s) passes with X at rest: X moves only in the second block.
    moving = np.abs(r.motion.velocity[:, 0]) > 0
    assert r.motion.time[moving].min() >= 1.35 - 1e-9


def _with_a() -> object:
    """A reader's view of a machine with A (read_program takes any object with the keys)."""
    from types import SimpleNamespace

    return SimpleNamespace(dialect="rs274", tool_change_time=None, tools={}, offsets={},
                           reference={}, rotary={"A": None})  # fmt: skip


def test_the_planner_refuses_a_rotary_axis_without_limits() -> None:
    p = read_program("G0 X1\nG0 A90\nM30\n", machine=_with_a())
    with pytest.raises(BallScrewInputError) as info:
        plan(p, Limits(np.full(3, 0.5), np.full(3, 2.0), np.full(3, 50.0), 0.5, 1e-5))
    assert info.value.field == "program line 2" and info.value.value == "A"


def test_a_rotary_move_turns_by_the_difference_of_its_angles() -> None:
    # A90 then A45: 90 deg, a stop (a junction with a rotary axis), then 45 deg back. Both
    # reach 90 deg/s (the ramp up and down takes v (v/a + a/j) = 0.35 v = 31.5 deg), so each
    # takes theta/v + v/a + a/j: 1 + 0.35 and 0.5 + 0.35 s. Ruckig's profile is exact; 1e-6
    # as above.
    p = read_program("G0 A90\nG0 A45\nM30\n", machine=_with_a())
    m = plan(p, limits())
    assert m.block_time == pytest.approx([1.35, 0.85], rel=1e-6)
    assert m.duration == pytest.approx(2.2, rel=1e-6)


def test_a_rotary_move_of_one_radian_is_a_move() -> None:
    # 180/pi deg is 1 rad to the last bit. A, B and C turn 1 rad each, alone, all with A's
    # limits: each axis runs the profile of a 1 rad move at pi/2 rad/s (the ramps take
    # 0.35 pi/2 = 0.55 rad < 1 rad, so the speed is reached): 1/(pi/2) + 0.25 + 0.1 s.
    import dataclasses
    from types import SimpleNamespace

    one = math.degrees(1.0)
    three = SimpleNamespace(**{**vars(_with_a()), "rotary": dict.fromkeys("ABC")})
    p = read_program(f"G0 A{one!r} B{one!r} C{one!r}\nM30\n", machine=three)
    assert p.rotary_end is not None and p.rotary_end.tolist() == [[1.0, 1.0, 1.0]]
    lim = dataclasses.replace(
        limits(), rotary_feed=np.full(3, math.pi / 2), rotary_acceleration=np.full(3, 2 * math.pi),
        rotary_jerk=np.full(3, 20 * math.pi),
    )  # fmt: skip
    assert plan(p, lim).duration == pytest.approx(2 / math.pi + 0.35, rel=1e-6)


def test_a_rapid_of_no_length_is_capped_by_the_rapid_feed() -> None:
    # The readers never write a move of no length, but a Program built by hand may: a rapid
    # that moves no axis, linear or rotary, has only the machine's rapid feed (0.5 m/s) as
    # its top speed, not the unbounded one a rotary move alone starts from.
    import dataclasses

    p = read_program("G0 X1\nG0 X2\nG1 X3 F600\nM30\n")
    end, start = p.end.copy(), p.start.copy()
    end[1] = start[1]
    start[2] = end[1]
    q = dataclasses.replace(p, start=start, end=end)
    m = plan(q, limits())
    assert m.block_limit.tolist() == pytest.approx([0.5, 0.5, 0.01], rel=1e-12)
    assert m.block_time[1] == 0.0
