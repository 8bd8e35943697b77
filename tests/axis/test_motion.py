"""Motion profiles against the closed forms of trapezoidal and S-curve moves."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.axis.motion import back_and_forth, chain, dwell, move
from ballscrew.errors import BallScrewInputError


@pytest.mark.parametrize("stroke", [0.3, -0.3])
def test_trapezoidal_move_closed_form(stroke: float) -> None:
    # Reaches the feed v: duration s/v + v/a, distance s; the speed is the
    # derivative of the position (central differences, exact for quadratics).
    s, v, a = abs(stroke), 0.5, 2.0
    p = move(stroke, v, a, sample_time=1e-3)
    assert p.duration == pytest.approx(s / v + v / a, rel=1e-12)
    assert float(p.position[-1]) == pytest.approx(stroke, rel=1e-12)
    assert float(np.max(np.abs(p.speed))) == pytest.approx(v, rel=1e-12)
    assert float(np.max(np.abs(p.acceleration))) == pytest.approx(a, rel=1e-12)
    mid = slice(1, -1)
    numeric = (p.position[2:] - p.position[:-2]) / (p.time[2:] - p.time[:-2])
    smooth = np.abs(np.diff(p.acceleration))[1:] == 0  # away from the steps in a
    np.testing.assert_allclose(numeric[smooth], p.speed[mid][smooth], atol=1e-9)


def test_short_move_is_a_triangle() -> None:
    # v_peak = sqrt(s a), duration 2 sqrt(s / a).
    p = move(0.02, 0.5, 2.0)
    assert float(p.speed.max()) == pytest.approx(math.sqrt(0.02 * 2.0), rel=1e-9)
    assert p.duration == pytest.approx(2 * math.sqrt(0.02 / 2.0), rel=1e-9)


@pytest.mark.parametrize(("s", "j"), [(0.3, 50.0), (0.3, 5.0), (0.01, 50.0), (0.001, 500.0)])
def test_s_curve_respects_its_limits_and_ends_at_rest(s: float, j: float) -> None:
    v, a = 0.5, 2.0
    p = move(s, v, a, jerk=j, sample_time=1e-4)
    assert float(p.position[-1]) == pytest.approx(s, rel=1e-9)
    assert float(p.speed[-1]) == 0.0 and float(p.speed.max()) <= v * (1 + 1e-12)
    assert float(np.abs(p.acceleration).max()) <= a * (1 + 1e-12)
    jerk = np.abs(np.diff(p.acceleration) / np.diff(p.time))
    assert float(jerk.max()) <= j * (1 + 1e-9)
    if s == 0.3 and j == 50.0:
        # Full S-curve: the trapezoid's duration plus a / j.
        assert p.duration == pytest.approx(s / v + v / a + a / j, rel=1e-12)


def test_cycles_and_dwells_chain_in_time_and_place() -> None:
    c = back_and_forth(0.3, 0.5, 2.0, dwell_time=0.5, cycles=3, process_force=2000.0,
                       force_window=(0.05, 0.25))  # fmt: skip
    assert c.duration == pytest.approx(3 * (2 * 0.85 + 2 * 0.5), rel=1e-12)
    assert float(c.position[-1]) == pytest.approx(0.0, abs=1e-12)
    assert np.all(np.diff(c.time) > 0)
    # The force acts on the way out only, inside the window.
    out = (c.speed > 0) & (c.process_force > 0)
    assert out.any() and float(c.position[out].min()) >= 0.05 - 1e-12
    assert not np.any((c.speed < 0) & (c.process_force != 0))
    d = chain(dwell(1.0), move(0.2, 0.5, 2.0))
    assert d.duration == pytest.approx(1.0 + 0.2 / 0.5 + 0.5 / 2.0, rel=1e-12)


@pytest.mark.parametrize(
    "kwargs, field",
    [({"feed": 0.0}, "feed"), ({"acceleration": -1.0}, "acceleration"), ({"jerk": 0.0}, "jerk")],
)
def test_bad_moves_are_refused(kwargs: dict[str, float], field: str) -> None:
    args = {"stroke": 0.3, "feed": 0.5, "acceleration": 2.0} | kwargs
    with pytest.raises(BallScrewInputError, match=field):
        move(**args)  # type: ignore[arg-type]
    with pytest.raises(BallScrewInputError, match="cycles"):
        back_and_forth(0.3, 0.5, 2.0, cycles=0)


def test_trajectory_from_csv_with_units_and_decimal_commas() -> None:
    from ballscrew.axis.motion import read_trajectory

    # x = 0.5 t^2 [m] sampled in mm and ms: v = t, a = 1 (finite differences
    # of second order are exact for a quadratic).
    t = np.linspace(0.0, 1.0, 11)
    text = "time [ms];position [mm];force [kN]\n" + "\n".join(
        f"{ti * 1e3:g};{0.5 * ti**2 * 1e3:.6f};2".replace(".", ",") for ti in t
    )
    p = read_trajectory(text)
    np.testing.assert_allclose(p.speed, t, atol=1e-9)
    np.testing.assert_allclose(p.acceleration, 1.0, atol=1e-6)
    np.testing.assert_allclose(p.process_force, 2000.0)
    speed_csv = "time [s],speed [m/min]\n0,0\n1,60\n2,60\n"
    q = read_trajectory(speed_csv)
    assert float(q.position[-1]) == pytest.approx(0.5 + 1.0)  # trapezoidal integral
    bad_files = {
        "time,position [mm]\n0,0\n1,1\n": "'name [unit]'",
        "time [s],force [N]\n0,0\n1,1\n": "position or speed",
        "time [s],position [mm]\n0,0\n0,1\n1,2\n": "times increasing",
    }
    for bad, words in bad_files.items():
        with pytest.raises(BallScrewInputError) as info:
            read_trajectory(bad)
        assert words in str(info.value)


@pytest.mark.parametrize(("s", "j"), [(0.3, 50.0), (0.01, 50.0)])
def test_s_curve_speed_is_the_derivative_of_its_position(s: float, j: float) -> None:
    # Inside each phase x(t) is a cubic: a centred difference of positions on three samples
    # of one phase gives v to O(dt^2 j) (1e-4 s, 50 m/s^3: 1e-7 m/s). The jerk phases'
    # position errors cancel at the end of a move, so only this check sees them.
    p = move(s, 0.5, 2.0, jerk=j, sample_time=1e-4)
    numeric = (p.position[2:] - p.position[:-2]) / (p.time[2:] - p.time[:-2])
    jerk = np.diff(p.acceleration) / np.diff(p.time)
    same_phase = np.abs(jerk[1:] - jerk[:-1]) < 1e-6 * j  # both intervals in one phase
    np.testing.assert_allclose(numeric[same_phase], p.speed[1:-1][same_phase], atol=1e-6)
    accel = (p.speed[2:] - p.speed[:-2]) / (p.time[2:] - p.time[:-2])
    np.testing.assert_allclose(accel[same_phase], p.acceleration[1:-1][same_phase], atol=1e-6)


def test_a_one_metre_move_the_force_over_the_whole_move_and_rest_at_the_end() -> None:
    # 1 m at 0.5 m/s and 2 m/s²: 1/0.5 + 0.5/2 s. No window: the force on every sample,
    # from x = 0 to x = s included; the move ends with a = v = 0.
    p = move(1.0, 0.5, 2.0, process_force=100.0)
    assert p.duration == pytest.approx(2.25, rel=1e-12)
    assert float(p.position[-1]) == pytest.approx(1.0, rel=1e-12)
    np.testing.assert_array_equal(p.process_force, 100.0)
    assert float(p.acceleration[-1]) == 0.0 and float(p.speed[-1]) == 0.0
    still = move(0.0, 0.5, 2.0)
    assert float(np.abs(still.position).max()) == 0.0


def test_dwell_samples_and_place() -> None:
    d = dwell(1.0, sample_time=0.25)
    np.testing.assert_allclose(d.time, [0.0, 0.25, 0.5, 0.75, 1.0])
    np.testing.assert_array_equal(d.position, 0.0)
    np.testing.assert_array_equal(dwell(0.5, position=0.2).position, 0.2)


def test_chain_moves_each_piece_to_where_the_last_ended() -> None:
    # A trajectory recorded from t = 5 s at x = 0.1 m, twice: the chain starts at 0 s and
    # 0 m, the second copy starts where the first ended, and the duration is the sum.
    from ballscrew.axis.motion import read_trajectory

    rec = read_trajectory("time [s],position [m]\n5,0.1\n5.5,0.15\n6,0.3\n")
    assert rec.duration == pytest.approx(1.0, rel=1e-12)
    c = chain(rec, rec)
    np.testing.assert_allclose(c.time, [0.0, 0.5, 1.0, 1.5, 2.0])
    np.testing.assert_allclose(c.position, [0.0, 0.05, 0.2, 0.25, 0.4], atol=1e-15)


def test_back_and_forth_defaults_one_cycle_no_dwell_no_force() -> None:
    c = back_and_forth(0.3, 0.5, 2.0)
    assert c.duration == pytest.approx(2 * 0.85, rel=1e-12)
    assert not c.process_force.any()
    assert float(c.position[-1]) == pytest.approx(0.0, abs=1e-12)


def test_profiles_need_two_samples_at_increasing_times() -> None:
    from ballscrew.axis.motion import Profile

    two = np.array([0.0, 1.0])
    assert Profile(two, two, two, two, two).duration == 1.0
    back = np.array([0.0, 1.0, 0.5])
    with pytest.raises(BallScrewInputError, match="time"):
        Profile(back, back, back, back, back)
    still = np.array([1.0, 1.0])
    with pytest.raises(BallScrewInputError, match="time"):
        Profile(still, two, two, two, two)
    # A time given twice is a step of the speed (a program's junction), not of the position.
    t, x = np.array([0.0, 0.5, 0.5, 1.0]), np.array([0.0, 0.1, 0.1, 0.3])
    step = Profile(t, x, np.array([0.2, 0.2, 0.4, 0.4]), np.zeros(4), np.zeros(4))
    assert step.duration == 1.0
    with pytest.raises(BallScrewInputError, match="position"):
        Profile(t, np.array([0.0, 0.1, 0.2, 0.3]), x, x, x)


def test_trajectory_errors_name_the_line_and_the_header() -> None:
    from ballscrew.axis.motion import read_trajectory

    # Line 1 is the header: the third line holds the time that does not increase.
    with pytest.raises(BallScrewInputError, match="line 3"):
        read_trajectory("time [s],position [mm]\n0,0\n0,1\n1,2\n")
    with pytest.raises(BallScrewInputError, match=r"time \[s\],force \[N\]"):
        read_trajectory("time [s],force [N]\n0,0\n1,1\n")
    # Speeds integrated by the trapezoidal rule over steps of 2 s: 0 + 2 * (0 + 1)/2 + ...
    q = read_trajectory("time [s],speed [m/s]\n0,0\n2,1\n4,1\n")
    np.testing.assert_allclose(q.position, [0.0, 1.0, 3.0])


def test_a_profile_whose_time_stalls_names_the_sample() -> None:
    # Issue 52: the refusal said "time = '(profile)'"; it names the time and its sample.
    from ballscrew.axis.motion import Profile

    t = np.array([0.0, 0.2, 0.1, 0.3])
    zero = np.zeros(4)
    with pytest.raises(BallScrewInputError) as info:
        Profile(t, zero, zero, zero, zero)
    assert "time = '0.1 s at sample 3, after 0.2 s'" in str(info.value)
    with pytest.raises(BallScrewInputError, match="time = '1 sample"):
        Profile(t[:1], zero[:1], zero[:1], zero[:1], zero[:1])
