"""The circular test's references, its sample count, the loops' checks and the cascade by hand.

Written from the mutation of ``servo/contour.py`` (outside the evaluation pinned in
``test_contour_pins.py``), ``servo/verdict.py`` and ``servo/cascade.py`` (issue 49). Every
expected number is a hand count, a closed form or a computation of another kind:

- the circle's parts counted in samples (settling, ramp, lead-in, revolution) and its
  kinematics checked against its own positions by central differences;
- the reversal's speeds on a binary sampling time (2^-10 s), where the sums are exact;
- the P position loop's steady lag on a circle, R w / sqrt(w^2 + k_v^2), per axis;
- the symmetric optimum's gains written out, and the loops' frequency responses evaluated
  with numpy from the transfer functions written here (not with ``control``);
- the verdict's limits (30 deg, 6 dB, 10 and 2 times the bandwidth) at and past their ends.
"""

from __future__ import annotations

import math
import time
from dataclasses import replace
from types import SimpleNamespace

import numpy as np
import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import load_case
from ballscrew.servo import axis_dynamics, frictionless, run_contour, tune
from ballscrew.servo.cascade import Gains, loop_figures, loop_systems
from ballscrew.servo.contour import (
    CircleRun,
    ContourResult,
    Glitch,
    ReversalRun,
    circle_reference,
    circular_test,
    contour_samples,
    controller_compensation,
    reversal_reference,
)
from ballscrew.servo.plant import AxisDynamics
from ballscrew.servo.simulate import Trace
from ballscrew.servo.tables import CompensationTable
from ballscrew.servo.verdict import MAX_SAMPLES, Check, check_size, drive_checks, loop_checks
from shared import ROOT

EXAMPLE = ROOT / "examples" / "xy_table_32x10.toml"
VERTICAL = ROOT / "examples" / "vertical_32x5.toml"


# --- the circle's reference -------------------------------------------------------------


def test_the_circles_parts_are_counted_by_hand() -> None:
    # R 10 mm at 0.1 m/s, T_s 1 ms, the default 1 m/s^2 ramp and 50 ms settling:
    # t_r = max(1.5 v/a, 20 T_s) = 0.15 s (150 samples), the revolution 2 pi R/v = 0.6283 s
    # (628 samples). With a 0.2 s lead-in: 50 + 150 + 200 + 628 + 150 + 50 = 1228 samples,
    # the evaluated revolution from 50 + 150 + 200 = 400 to 1028.
    x, *_, window = circle_reference(0.01, 0.1, 1e-3, lead_in=0.2)
    assert x.size == 1228 and window == slice(400, 1028)
    x, *_, window = circle_reference(0.01, 0.1, 1e-3)  # no lead-in by default
    assert x.size == 1028 and window == slice(200, 828)
    # A 100 m/s^2 ramp would take 1.5 ms: the floor of 20 samples (20 ms) holds.
    x, *_, window = circle_reference(0.01, 0.1, 1e-3, acceleration=100.0)
    assert x.size == 50 + 20 + 628 + 20 + 50 and window == slice(70, 698)
    # The settling is its own argument: 10 ms is 10 samples at each end.
    x, *_, window = circle_reference(0.01, 0.1, 1e-3, settle=0.01)
    assert x.size == 10 + 150 + 628 + 150 + 10 and window == slice(160, 788)


@pytest.mark.parametrize("clockwise", [False, True])
def test_the_circles_kinematics_by_hand(clockwise: bool) -> None:
    r, v, ts, lead = 0.01, 0.1, 1e-4, 0.05
    x, y, vx, vy, ax, ay, window = circle_reference(r, v, ts, clockwise=clockwise, lead_in=lead)
    sign = -1.0 if clockwise else 1.0
    # On the circle throughout (1e-15 m: rounding of cos, sin on 1e-2 m).
    np.testing.assert_allclose(np.hypot(x, y), r, rtol=0, atol=1e-15)
    # Starts at rest at 45 deg; the evaluated revolution starts after the ramp's path
    # v t_r/2 (the integral of v (1 - cos(pi t/t_r))/2) and the lead-in's v * lead, t_r 0.15 s.
    assert (x[0], y[0]) == pytest.approx((r / math.sqrt(2), r / math.sqrt(2)), abs=1e-15)
    phi0 = math.pi / 4 + sign * (v * 0.15 / 2 + v * lead) / r
    i = window.start
    assert (x[i], y[i]) == pytest.approx((r * math.cos(phi0), r * math.sin(phi0)), abs=1e-12)
    # The whole path: twice the ramp's v t_r/2 and the feed's n_c samples; at rest at the end.
    n_c = round(lead / ts) + round(2 * math.pi * r / v / ts)
    phi1 = math.pi / 4 + sign * (v * 0.15 + v * n_c * ts) / r
    assert (x[-1], y[-1]) == pytest.approx((r * math.cos(phi1), r * math.sin(phi1)), abs=1e-12)
    assert (vx[-1], vy[-1], ax[-1], ay[-1]) == pytest.approx((0, 0, 0, 0), abs=1e-12)
    assert (vx[0], vy[0], ax[0], ay[0]) == (0.0, 0.0, 0.0, 0.0)
    # At the feed: speed v, centripetal acceleration v^2/R = 1 m/s^2, turning the right way.
    w = window
    np.testing.assert_allclose(np.hypot(vx[w], vy[w]), v, rtol=1e-12)
    np.testing.assert_allclose(np.hypot(ax[w], ay[w]), v * v / r, rtol=1e-9)
    np.testing.assert_allclose(x[w] * vy[w] - y[w] * vx[w], sign * r * v, rtol=1e-12)
    # Mid-ramp: half the feed, the ramp's peak tangential acceleration v pi/(2 t_r).
    mid = 500 + 750
    assert math.hypot(vx[mid], vy[mid]) == pytest.approx(v / 2, rel=1e-12)
    tangential = (vx[mid] * ax[mid] + vy[mid] * ay[mid]) / math.hypot(vx[mid], vy[mid])
    assert tangential == pytest.approx(v * math.pi / (2 * 0.15), rel=1e-9)
    # The speeds and accelerations are the positions' derivatives: central differences
    # (error T_s^2/6 times the third derivative, about 1e-8 of v and 1e-5 of v^2/R here).
    np.testing.assert_allclose((x[2:] - x[:-2]) / (2 * ts), vx[1:-1], rtol=0, atol=1e-6)
    np.testing.assert_allclose((y[2:] - y[:-2]) / (2 * ts), vy[1:-1], rtol=0, atol=1e-6)
    np.testing.assert_allclose((vx[2:] - vx[:-2]) / (2 * ts), ax[1:-1], rtol=0, atol=1e-3)
    np.testing.assert_allclose((vy[2:] - vy[:-2]) / (2 * ts), ay[1:-1], rtol=0, atol=1e-3)


def test_the_ramp_follows_the_acceleration_asked_and_its_floor() -> None:
    # 2 m/s^2: t_r = 1.5 v/a = 75 ms, so the ramp is half way (v/2) 37.5 ms in and at the
    # feed from 75 ms; 100 m/s^2 would take 1.5 ms: the floor of 20 samples (10 ms) holds,
    # half way at 5 ms. The path at the feed is at the feed's speed throughout.
    for acceleration, t_r in ((2.0, 0.075), (100.0, 0.01)):
        *_, vx, vy, ax, ay, window = circle_reference(0.01, 0.1, 5e-4, acceleration=acceleration)
        speed = np.hypot(vx, vy)
        assert speed[100 + round(t_r / 2 / 5e-4)] == pytest.approx(0.05, rel=1e-9)
        np.testing.assert_allclose(speed[100 + round(t_r / 5e-4) : window.stop], 0.1, rtol=1e-12)
        peak = float(np.max(np.abs(vx * ax + vy * ay) / np.maximum(speed, 1e-30)))
        assert peak == pytest.approx(0.1 * math.pi / (2 * t_r), rel=1e-3)


@pytest.mark.parametrize(
    ("radius", "feed", "lead_in", "flag"),
    [(0.0, 0.1, 0.0, "--radius"), (0.01, 0.0, 0.0, "--feed"), (0.01, 0.1, -0.1, "lead_in")],
)
def test_a_circle_of_no_radius_or_feed_is_refused(
    radius: float, feed: float, lead_in: float, flag: str
) -> None:
    with pytest.raises(BallScrewInputError, match=flag):
        circle_reference(radius, feed, 1e-3, lead_in=lead_in)


def test_the_samples_estimate_by_hand() -> None:
    # R 10 mm, 0.1 m/s, T_s 1 ms, k_v 40: settling 50 and a ramp of 150 at each end, a
    # lead-in of 15/40 s (375), the revolution 628: 1403 per axis, 2806 per circle. A
    # reversal at v^2/R = 1 m/s^2 takes t_a = 0.1 s to stop: 0.05 + 3 t_a + 2 * 0.3 s of
    # holding = 0.95 s, 950 samples, run twice (with and without friction).
    assert contour_samples(0.01, 0.1, 1e-3, 40.0, circles=1, reversals=0) == 2806
    assert 2 * circle_reference(0.01, 0.1, 1e-3, lead_in=15.0 / 40.0)[0].size == 2806
    assert contour_samples(0.01, 0.1, 1e-3, 40.0, circles=0, reversals=1) == 1900
    assert reversal_reference(0.1, 1.0, 1e-3)[0].size == 950
    # At 4 m/s^2, t_a = 25 ms: 0.725 s; a step (infinite acceleration), none: 0.65 s.
    assert contour_samples(0.01, 0.1, 1e-3, 40.0, circles=0, reversals=1,
                           reversal_acceleration=4.0) == 1450  # fmt: skip
    assert contour_samples(0.01, 0.1, 1e-3, 40.0, circles=0, reversals=1,
                           reversal_acceleration=math.inf) == 1300  # fmt: skip
    # The defaults: four circles and two reversals, 4 * 2806 + 2 * 1900.
    assert contour_samples(0.01, 0.1, 1e-3, 40.0) == 15024
    # A k_v of 20 1/s doubles the lead-in: 375 more samples per axis.
    assert contour_samples(0.01, 0.1, 1e-3, 20.0, circles=1, reversals=0) == 2806 + 750
    with pytest.raises(BallScrewInputError, match="--sampling-time"):
        contour_samples(0.01, 0.1, 0.0, 40.0)


# --- the controller's feed-forward ------------------------------------------------------


def _linear_table() -> CompensationTable:
    """1000 N per m/s from -1 to 1 m/s: the force read back is 1000 v exactly."""
    speed = np.array([-1.0, 1.0])
    return CompensationTable(speed, 1000.0 * speed, 0.0, 0.0, 1.0)


def test_the_feed_forward_reads_the_commanded_velocity_a_sample_late() -> None:
    # Commanded velocities (x[i] - x[i-1])/T_s: 0 (nothing before the first), 0.1, 0.2, 0.3,
    # 0 m/s, starting away from 0 (at 0.5 m); 1000 N per m/s. 1e-9 N: the rounding of
    # differences of 1e-4 m on 0.5 m (1e-16/1e-4 relative) times 300 N.
    ts = 1e-3
    xr = 0.5 + np.array([0.0, 1e-4, 3e-4, 6e-4, 6e-4])
    table = _linear_table()
    at_once = [0.0, 100.0, 200.0, 300.0, 0.0]
    assert controller_compensation(table, xr, ts, 0) == pytest.approx(at_once, abs=1e-9)
    late = [0.0, 0.0, 100.0, 200.0, 300.0]
    assert controller_compensation(table, xr, ts, 1) == pytest.approx(late, abs=1e-9)
    assert controller_compensation(table, xr, ts) == pytest.approx(late, abs=1e-9)
    assert controller_compensation(table, xr, ts, 3) == pytest.approx([0, 0, 0, 0, 100], abs=1e-9)
    assert list(controller_compensation(table, xr, ts, 7)) == [0.0] * 5
    with pytest.raises(BallScrewInputError, match="delay"):
        controller_compensation(table, xr, ts, -1)


# --- one direction's figures ------------------------------------------------------------


def _trace(n: int = 3) -> Trace:
    zero = np.zeros(n)
    return Trace(zero, zero, zero, zero, zero, zero, zero)


def _run(angle: list[float], dev: list[float], g: float = 0.0, glitch: float = 1e-6,
         compensated: bool = False, **kw: float) -> CircleRun:  # fmt: skip
    glitches = (Glitch("x", 0.0, glitch, 5.0, 2.0), Glitch("y", 90.0, -glitch / 2, 4.0, 91.0))
    return CircleRun(False, compensated, np.array(angle), np.array(dev), g, 0.0, glitches,
                     _trace(), _trace(), **kw)  # fmt: skip


def test_a_circle_is_settled_up_to_one_percent_of_g_or_ten_nanometres() -> None:
    g = 1e-5
    assert _run([0.0], [0.0], g, residual=0.01 * g).settled
    assert not _run([0.0], [0.0], g, residual=1.05e-7).settled
    assert _run([0.0], [0.0], 0.0, residual=1e-8).settled
    assert not _run([0.0], [0.0], 0.0, residual=1.05e-8).settled
    assert _run([0.0], [0.0], 0.0).settled  # no residual given: 0


def test_the_deviation_in_one_degree_bins_by_hand() -> None:
    # 0.2 and 0.7 deg share the first bin (mean 2 um), 1.5 deg is alone in the second, 359.5
    # and 360.0 (what -1e-20 mod 360 rounds to) the last (mean 6 um); empty bins are left out.
    run = _run([0.2, 0.7, 1.5, 359.5, 360.0], [1e-6, 3e-6, 5e-6, 7e-6, 5e-6])
    centres, dev = run.binned()
    assert list(centres) == [0.5, 1.5, 359.5]
    assert dev == pytest.approx([2e-6, 5e-6, 6e-6], rel=1e-12)
    centres, dev = run.binned(2.0)
    assert list(centres) == [1.0, 359.0]
    assert dev == pytest.approx([3e-6, 6e-6], rel=1e-12)


def test_the_json_of_a_circle_and_a_reversal_in_micrometres() -> None:
    run = _run([0.2, 1.5], [1e-6, -2e-6], g=4e-6, glitch=3e-6, residual=5e-8)
    doc = run.as_dict()
    assert doc["circular_deviation_G_um"] == pytest.approx(4.0)
    assert doc["largest_glitch_um"] == pytest.approx(3.0)
    assert doc["start_up_residual_um"] == pytest.approx(0.05)
    assert doc["glitches"][0]["height_um"] == pytest.approx(3.0)
    assert doc["radial_deviation"] == {"angle_deg": [0.5, 1.5],
                                       "deviation_um": pytest.approx([1.0, -2.0])}  # fmt: skip
    assert _run([0.0], [0.0]).as_dict()["mean_radius_error_um"] == 0.0
    mean = replace(_run([0.0], [0.0]), mean_radius_error=-2.5e-6)
    assert mean.as_dict()["mean_radius_error_um"] == pytest.approx(-2.5)
    rev = ReversalRun(0.1, 2.0, 7e-6, 0.004, _trace(), _trace(), False).as_dict()
    assert rev["glitch_um"] == pytest.approx(7.0) and rev["time_to_peak_ms"] == pytest.approx(4.0)


def test_the_reduction_is_the_first_directions_glitch_ratio() -> None:
    def result(*runs: CircleRun) -> ContourResult:
        return ContourResult(None, None, None, 0.01, 0.1, runs, (), None, "test", 0.0)  # type: ignore[arg-type]

    plain, comp = _run([0.0], [0.0], glitch=4e-6), _run([0.0], [0.0], glitch=1e-6, compensated=True)
    other = _run([0.0], [0.0], glitch=9e-6)
    other_comp = _run([0.0], [0.0], glitch=3e-6, compensated=True)
    assert result(plain, comp, other, other_comp).reduction == pytest.approx(4.0)
    # A compensated glitch of nothing: divided by a floor of 1e-15 m.
    none = _run([0.0], [0.0], glitch=0.0, compensated=True)
    assert result(plain, none).reduction == pytest.approx(4e-6 / 1e-15)
    assert result(plain).reduction is None


# --- one direction simulated ------------------------------------------------------------


@pytest.fixture(scope="module")
def axis() -> AxisDynamics:
    return axis_dynamics(load_case(EXAMPLE))


def _stiff(mass: float, kv: float, ts: float = 1e-4) -> Gains:
    """A velocity loop of 300 Hz crossover over a P position loop, no feed-forward."""
    wc = 2 * math.pi * 300.0
    return Gains(ts, kv, 0.0, 0.0, mass * wc, mass * wc * wc / 10.0, 5e-5)


def test_each_axis_lags_by_its_own_first_order_loop(axis: AxisDynamics) -> None:
    # x without friction at k_v 20 1/s, y with the screw's friction at 10 1/s, both rigid, no
    # feed-forward: each coordinate follows k_v/(s + k_v), so its error on the settled circle
    # (w = v/R = 10 rad/s) swings with the amplitude R w/sqrt(w^2 + k_v^2): 4.47 mm and
    # 7.07 mm. 1 %: the 300 Hz velocity loop adds a phase of about w/(2 pi 300), and the
    # friction's glitches are micrometres.
    plain = frictionless(axis).as_rigid()
    rough = axis.as_rigid()
    gains = (_stiff(plain.mass, 20.0), _stiff(rough.mass, 10.0))
    r, v = 0.01, 0.1
    run = circular_test((plain, rough), gains, r, v)
    w = v / r
    # The lead-in is 15 time constants of the slower loop, y's (1.5 s): 500 + 1500 + 15000
    # + 6283 + 1500 + 500 samples.
    assert run.x.time.size == 25283 and run.y.time.size == 25283
    window = slice(500 + 1500 + 15000, 500 + 1500 + 15000 + 6283)
    ex, ey = run.x.error[window], run.y.error[window]
    assert float(np.max(np.abs(ex))) == pytest.approx(r * w / math.hypot(w, 20.0), rel=0.01)
    assert float(np.max(np.abs(ey))) == pytest.approx(r * w / math.hypot(w, 10.0), rel=0.01)
    assert not np.any(run.x.friction) and np.any(run.y.friction)
    # Settled: the error repeats one revolution later (to the interpolation's nanometre).
    assert run.settled and run.residual < 1e-8 and not run.compensated


def test_each_axis_gets_its_own_table(axis: AxisDynamics) -> None:
    # A table of zero on x leaves x's run as it was; 1000 N per m/s on y (no friction to
    # cancel: a disturbance of 100 N at the feed, micrometres against the lag) changes y's.
    # Different axes and gains, so that a swap shows; here x is the slower loop (10 1/s):
    # a lead-in of 1.5 s, 250 + 750 + 7500 + 3142 + 750 + 250 samples of 0.2 ms.
    plain = frictionless(axis).as_rigid()
    rough = axis.as_rigid()
    gains = (_stiff(plain.mass, 10.0, 2e-4), _stiff(rough.mass, 20.0, 2e-4))
    zero = CompensationTable(np.array([-1.0, 1.0]), np.zeros(2), 0.0, 0.0, 1.0)
    bare = circular_test((plain, rough), gains, 0.01, 0.1)
    comp = circular_test((plain, rough), gains, 0.01, 0.1, tables=(zero, _linear_table()))
    assert comp.compensated and comp.x.time.size == 12642
    np.testing.assert_array_equal(comp.x.table, bare.x.table)
    assert not np.any(comp.x.friction) and np.any(comp.y.friction)
    assert float(np.max(np.abs(comp.y.table - bare.y.table))) > 1e-7
    window = slice(250 + 750 + 7500, 250 + 750 + 7500 + 3142)
    ey = float(np.max(np.abs(comp.y.error[window])))
    assert ey == pytest.approx(0.01 * 10.0 / math.hypot(10.0, 20.0), rel=0.01)


def test_a_bump_just_outside_the_glitch_window_is_no_glitch() -> None:
    # A circle with a 2 um bump on one sample at 119.5 deg (29.5 deg past the 90 deg
    # quadrant: inside its +-30 deg window) or at 121.5 deg (31.5 deg past: outside).
    from ballscrew.servo.contour import _analyse

    n, r = 1440, 0.01
    theta = 2.0 * math.pi * np.arange(n) / n

    def glitch_90(at: float) -> float:
        radius = r + 2e-6 * np.isclose(np.degrees(theta), at)
        x, y = radius * np.cos(theta), radius * np.sin(theta)
        xs, ys = np.concatenate([x, x[:2]]), np.concatenate([y, y[:2]])
        zero = np.zeros(xs.size)
        tx = Trace(zero, xs, zero, xs, xs, zero, zero)
        ty = Trace(zero, ys, zero, ys, ys, zero, zero)
        run = _analyse(tx, ty, r, slice(0, n), False, False, float(n))
        return next(g.height for g in run.glitches if g.quadrant == 90.0)

    assert glitch_90(119.5) == pytest.approx(2e-6, abs=1e-15)
    assert glitch_90(121.5) == pytest.approx(0.0, abs=1e-15)


def test_axes_sampled_at_different_times_are_refused(axis: AxisDynamics) -> None:
    a = axis.as_rigid()
    with pytest.raises(BallScrewInputError, match=r"sampling_time = 0\.0002 .*\(0\.0001 s\)"):
        circular_test((a, a), (_stiff(a.mass, 10.0), _stiff(a.mass, 10.0, 2e-4)), 0.01, 0.1)


# --- the reversal's reference -----------------------------------------------------------


def test_the_reversal_on_a_binary_sampling_time() -> None:
    # T_s = 2^-10 s, 0.125 m/s at 8 m/s^2 (a T_s = 2^-7 m/s a sample): every sum is exact.
    # Rest 0.05 s (51 samples), 16 samples down to -v, 0.3 s at -v (307), 32 samples up to
    # +v, 307 at +v. The speed is 0 again after 51 + 16 + 307 + 16 = 390 samples.
    ts, v = 2.0**-10, 0.125
    x, speed, acc, k = reversal_reference(v, 8.0, ts)
    assert x.size == 51 + 16 + 307 + 32 + 307 and k == 390
    assert speed[k - 1] == -8.0 * ts and speed[k] == 0.0
    assert not np.any(speed[:52]) and not np.any(x[:52]) and not np.any(acc[:51])
    assert speed[51 + 16] == -v and speed[-1] == v
    # Displacement: the stop's -v t_a/2; the ramp through zero and the holds cancel but for
    # the last sample, which the trace ends at the start of: -v T_s.
    assert x[-1] == pytest.approx(-v * (v / 8.0) / 2 - v * ts, rel=1e-12)
    # A longer hold moves the crossing by its samples (0.5 s: 512).
    assert reversal_reference(v, 8.0, ts, hold=0.5)[3] == 51 + 16 + 512 + 16
    # A step: -v within one sample, +v within one sample, zero crossed at 51 + 1 + 307 + 1.
    x, speed, _, k = reversal_reference(v, math.inf, ts)
    assert k == 360 and x.size == 51 + 1 + 307 + 1 + 307
    assert (speed[51], speed[52], speed[k - 1], speed[k]) == (0.0, -v, -v, v)
    assert x[-1] == pytest.approx(-1.5 * v * ts, rel=1e-12)  # -v T_s/2 - 2 v T_s + v T_s
    # A ramp shorter than half a sample still takes one sample each way.
    assert reversal_reference(v, 1e6, ts)[3] == 360
    # Any positive acceleration runs, however gentle.
    assert reversal_reference(v, 0.5, ts)[3] == 51 + 256 + 307 + 256


def test_the_reversal_glitch_is_read_from_the_sample_before_the_crossing(monkeypatch) -> None:  # type: ignore[no-untyped-def]
    # The two runs replaced by traces written here: the clean run lags by 1 mm throughout;
    # the run with friction by 2 um more up to the crossing's sample k - 1, then 2.5 um, 2.2 um
    # on, a peak of 9 um at k + 10 (7 um above the 2 um before) and a trough of -5.5 um at
    # k + 30 (7.5 um below): the glitch is -7.5 um, 30 samples (30 ms) after the crossing.
    import ballscrew.servo.contour as contour
    from ballscrew.servo.contour import reversal_test

    ts = 1e-3
    _, _, _, k = reversal_reference(0.02, 1.0, ts)

    def fake(axis, gains, x, v, a, comp=None):  # type: ignore[no-untyped-def]
        error = np.full(x.size, 1e-3)
        if np.any(axis.friction):
            extra = np.where(np.arange(x.size) < k, 2e-6, 2.2e-6)
            extra[k], extra[k + 10], extra[k + 30] = 2.5e-6, 9e-6, -5.5e-6
            error = error + extra
        zero = np.zeros(x.size)
        return Trace(np.arange(x.size) * ts, x, v, x - error, x - error, zero, zero)

    monkeypatch.setattr(contour, "simulate_axis", fake)
    axis = _axis()
    axis = replace(axis, friction=np.array([-100.0, 100.0]))
    run = reversal_test(axis, Gains(ts, 40.0, 1.0, 1.0, 1e4, 1e5, 1e-4), 0.02, 1.0)
    assert run.glitch == pytest.approx(-7.5e-6, abs=1e-12)
    assert run.time_to_peak == pytest.approx(0.030, abs=1e-12)


def test_the_json_of_a_contour_in_millimetres_and_metres_per_minute(unstable) -> None:  # type: ignore[no-untyped-def]
    # R 4 mm at 20 mm/s (1.2 m/min); H of two 1-degree bins 3 um and 1 um: 2 um.
    _, result = unstable
    cw = replace(_run([10.5], [3e-6]), clockwise=True)
    ccw = _run([10.5], [1e-6])
    doc = replace(result, circles=(cw, ccw)).as_dict()
    assert doc["radius_mm"] == pytest.approx(4.0) and doc["feed_m_per_min"] == pytest.approx(1.2)
    assert doc["circular_hysteresis_H_um"] == pytest.approx(2.0)
    assert result.as_dict()["circular_hysteresis_H_um"] is None


# --- run_contour: the estimate, the notes, the pairing of axes ---------------------------


def _estimate(**kw: object) -> int:
    """The samples ``run_contour`` estimates, read from its refusal at a limit of 1."""
    with pytest.raises(BallScrewInputError, match="simulated samples") as info:
        run_contour([load_case(EXAMPLE)], max_samples=1, **kw)  # type: ignore[arg-type]
    return int(str(info.value.value).split(" ")[0].replace(",", ""))


def test_the_estimate_run_contour_refuses_by_hand() -> None:
    # The defaults: R 50 mm, 2 m/min, T_s 250 us, k_v 40 1/s, both directions with and
    # without compensation (4 circles) and 2 reversals. Per axis and circle: settling 200
    # and a ramp of 0.05 s (200) at each end, a lead-in of 0.375 s (1500), a revolution of
    # 2 pi 0.05/(1/30) = 9.4248 s (37699): 39999. A reversal at v^2/R = 1/45 m/s^2 stops in
    # R/v = 1.5 s: 0.05 + 4.5 + 0.6 s = 20600 samples, twice. 4 * 2 * 39999 + 2 * 2 * 20600.
    assert _estimate() == 402392
    assert _estimate(compensate=False) == 2 * 2 * 39999 + 2 * 20600
    assert _estimate(directions=("CW",), compensate=False) == 2 * 39999 + 2 * 20600
    # Given gains: the slower k_v sets the lead-in (15/20 s: 3000 samples).
    case = load_case(EXAMPLE)
    g = tune(axis_dynamics(case))
    both = (replace(g, kv=20.0), g)
    assert _estimate(gains=both, compensate=False) == 2 * 2 * (39999 + 1500) + 2 * 20600
    assert _estimate(gains=both[::-1], compensate=False) == 2 * 2 * (39999 + 1500) + 2 * 20600
    # Gains of two sampling times are refused before anything is estimated or built.
    with pytest.raises(BallScrewInputError, match=r"T_s 0\.0005 s on y.*\(0\.00025 s\)"):
        run_contour([case], gains=(g, replace(g, sampling_time=5e-4)))
    check_size(MAX_SAMPLES)  # the limit itself runs
    with pytest.raises(BallScrewInputError, match="4,000,001"):
        check_size(MAX_SAMPLES + 1)


@pytest.mark.parametrize(
    ("kw", "flag"),
    [({"pre_rolling_length": 0.0}, "--pre-rolling"), ({"kv": 0.0}, "--kv"),
     ({"guide_coulomb": -1.0}, "--guide-friction"), ({"guide_viscous": -1.0}, "guide_viscous")],
)  # fmt: skip
def test_run_contours_refusals_name_the_flag(kw: dict[str, float], flag: str) -> None:
    with pytest.raises(BallScrewInputError, match=flag):
        run_contour([load_case(EXAMPLE)], **kw)  # type: ignore[arg-type]


def test_a_pre_rolling_length_is_named_in_micrometres() -> None:
    with pytest.raises(BallScrewInputError, match="-5 um"):
        run_contour([load_case(EXAMPLE)], pre_rolling_length=-5e-6)


def test_no_guide_friction_is_allowed() -> None:
    # 0 N and 0 N*s/m are magnitudes of no friction, not refused (read from the estimate).
    assert _estimate(guide_coulomb=0.0, guide_viscous=0.0) == 402392
    # Nor are a positive pre-rolling length and a small positive k_v (0.5 1/s: a lead-in of
    # 30 s, 120000 samples more per axis and circle).
    assert _estimate(pre_rolling_length=5e-6) == 402392
    assert _estimate(kv=0.5) == 402392 + 4 * 2 * (120000 - 1500)
    with pytest.raises(BallScrewInputError, match="--case"):
        run_contour([])


def _quick_table(speeds: np.ndarray, friction: np.ndarray, points: int, top: float):  # type: ignore[no-untyped-def]
    """In place of the 16-point fit (seconds of Nelder-Mead): the line through the axis's
    friction at -top and +top, with the points asked for and the top speed kept to check."""
    speed = np.linspace(-top, top, points)
    force = np.interp(speed, speeds, friction)
    return CompensationTable(speed, force, 0.0, 0.0, top)


@pytest.fixture(scope="module")
def unstable():  # type: ignore[no-untyped-def]
    # k_v 2000 1/s: an unstable position loop, NOT OK, so no circle is simulated; the axes,
    # tables, checks and notes are all made. Two cases: x the table, y the vertical axis.
    import ballscrew.servo.contour as contour

    cases = [load_case(EXAMPLE), load_case(VERTICAL)]
    with pytest.MonkeyPatch.context() as mp:
        mp.setattr(contour, "fit_table", _quick_table)
        start = time.process_time()
        result = run_contour(cases, radius=0.004, feed=0.02, kv=2000.0)
        assert 0.0 < result.cpu_seconds <= time.process_time() - start
        return cases, result


def test_the_notes_of_a_run_say_its_table_and_lead_in(unstable, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    _, result = unstable
    assert result.verdict == "NOT OK" and result.circles == () and result.reversals == ()
    notes = " | ".join(result.notes)
    # The table up to 1.25 times the feed (0.025 m/s); the friction map up to 0.05 m/s at
    # least; the lead-in 15/2000 s.
    assert "friction up to 0.025 m/s" in notes and "applied 1 sample later" in notes
    assert "16-point table" in notes and "up to 0.05 m/s" in notes
    assert "(0.0075 s)" in notes
    assert "one case for both axes" not in notes
    assert all(t.speed.size == 16 for t in result.tables)
    assert all(t.speed[-1] == pytest.approx(0.025) for t in result.tables)
    import ballscrew.servo.contour as contour

    monkeypatch.setattr(contour, "fit_table", _quick_table)
    slow = run_contour([load_case(EXAMPLE)], radius=0.004, feed=0.004, kv=2000.0,
                       directions=("CW",))  # fmt: skip
    assert "friction up to 0.01 m/s" in " ".join(slow.notes)  # the table's floor, 10 mm/s
    assert slow.tables[0].speed[-1] == 0.01
    assert "one case for both axes" in slow.notes
    # A feed above 40 mm/s: the friction map runs to 1.25 times it (0.0625 m/s), not 0.05.
    fast = run_contour([load_case(EXAMPLE)], radius=0.004, feed=0.05, kv=2000.0)
    assert "96 speeds up to 0.0625 m/s" in " ".join(fast.notes)


def test_each_axis_is_its_own_case(unstable) -> None:  # type: ignore[no-untyped-def]
    cases, result = unstable
    ax, ay = (axis_dynamics(c, max_speed=0.05) for c in cases)
    assert result.axes[0].mass == pytest.approx(ax.mass) and result.axes[1].mass == ay.mass
    assert result.axes[1].external_force == pytest.approx(ay.external_force)
    assert ax.mass != ay.mass
    assert [a.guide_viscous for a in result.axes] == [0.0, 0.0]  # none unless given
    for a, g, f, t in zip(result.axes, result.gains, result.figures, result.tables, strict=True):
        assert g == tune(a, kv=2000.0)
        assert f == loop_figures(a, g)
        # The table is made from its own axis's friction (the stand-in's line through it).
        assert float(t(0.025)) == pytest.approx(float(np.interp(0.025, a.speeds, a.friction)))
    # The drive's checks of each axis: v/(l/2 pi) in rpm, with each case's lead (10, 5 mm).
    speeds = [c for c in result.checks if c.name == "motor speed at the feed"]
    assert [c.axis for c in speeds] == ["x", "y"]
    assert [c.value for c in speeds] == pytest.approx([0.02 / 0.01 * 60, 0.02 / 0.005 * 60])
    # The path's peak acceleration of each axis is its own coordinate's: x's and y's of
    # the circle's reference (they differ: the ramp starts at 45 deg and turns), at most the
    # ramp's tangential pi/3 m/s^2 (t_r = 1.5 v/(1 m/s^2)) and v^2/R = 0.1 m/s^2 together.
    ref = circle_reference(0.004, 0.02, 250e-6, lead_in=15.0 / 2000.0)
    acc = [c.value for c in result.checks if c.name.startswith("peak acceleration")]
    assert acc == [float(np.max(np.abs(ref[4]))), float(np.max(np.abs(ref[5])))]
    assert acc[0] != acc[1] and max(acc) <= math.hypot(math.pi / 3, 0.1)


def test_the_runs_of_a_contour_and_their_reversal(axis: AxisDynamics) -> None:
    # Each direction plain and compensated, then x's reversal at v^2/R (0.2 m/s^2 for
    # 20 mm/s on 2 mm) plain and with x's table. x has no friction and a table of zero: its
    # compensated reversal is the plain one; y's table (1000 N per m/s) would change it.
    from ballscrew.servo.contour import _run_tests, reversal_test

    plain = frictionless(axis).as_rigid()
    rough = axis.as_rigid()
    gains = (_stiff(plain.mass, 40.0, 2e-4), _stiff(rough.mass, 20.0, 2e-4))
    zero = CompensationTable(np.array([-1.0, 1.0]), np.zeros(2), 0.0, 0.0, 1.0)
    steps: list[str] = []
    circles, reversals = _run_tests((plain, rough), gains, (zero, _linear_table()), 0.002,
                                    0.02, ("CW",), True, None, steps.append)  # fmt: skip
    assert steps == ["CW circle", "CW circle, compensated", "reversal", "reversal, compensated"]
    assert [(c.clockwise, c.compensated) for c in circles] == [(True, False), (True, True)]
    assert [r.acceleration for r in reversals] == pytest.approx([0.2, 0.2], rel=1e-12)
    assert [r.compensated for r in reversals] == [False, True]
    assert not np.any(reversals[0].trace.friction)  # x's axis
    np.testing.assert_array_equal(reversals[1].trace.table, reversals[0].trace.table)
    own = reversal_test(plain, gains[0], 0.02, 0.2)
    np.testing.assert_array_equal(reversals[0].trace.table, own.trace.table)
    # A given acceleration is used; without compensation, one circle and one reversal.
    circles, reversals = _run_tests((plain, rough), gains, (zero, zero), 0.002, 0.02, ("CCW",),
                                    False, 0.5, steps.append)  # fmt: skip
    assert len(circles) == 1 and [r.acceleration for r in reversals] == [0.5]


def test_the_notes_of_unsettled_circles_and_missing_motors() -> None:
    from ballscrew.servo.contour import _contour_notes

    a = replace(_axis(), notes=("an axis note",))
    g = Gains(1e-4, 40.0, 1.0, 1.0, 1e4, 1e5, 1e-4, notes=("a gains note",))
    g20 = replace(g, kv=20.0)
    motor = SimpleNamespace(motor={"rated_speed": 300.0, "peak_torque": 10.0})
    bare = SimpleNamespace(motor={"peak_torque": 10.0})
    settled = _run([0.0], [0.0], 1e-5, residual=1e-7)
    moving = _run([0.0], [0.0], 1e-5, residual=2e-6)
    moving_comp = _run([0.0], [0.0], 1e-5, compensated=True, residual=3e-6)
    notes = _contour_notes((a, a), (g, g20), (motor, bare), [settled, moving, moving_comp],  # type: ignore[arg-type]
                           one_case=False, rigid=True, top=0.05)  # fmt: skip
    text = " | ".join(notes)
    assert notes[:4] == ["x: an axis note", "y: an axis note", "x: a gains note",
                         "y: a gains note"]  # fmt: skip
    assert text.count("had not settled") == 2
    assert "the CCW circle had not settled: its following error changed by 2 um" in text
    assert "the CCW circle with compensation had not settled" in text
    assert "changed by 3 um" in text
    assert "y: no [motor] rated_speed in the case" in text and "x: no [motor]" not in text
    assert "rigid axes (one mass each)" in text and "one case for both axes" not in text
    # The lead-in of the slower loop: 15/20 s.
    assert "a lead-in arc of 15/k_v (0.75 s)" in text


# --- the verdict's checks ----------------------------------------------------------------


def _figures(pm: float, gm: float, bw: float):  # type: ignore[no-untyped-def]
    from ballscrew.servo.cascade import LoopFigures

    return LoopFigures(100.0, pm, gm, bw, 10.0, 60.0, 20.0, 20.0)


def test_the_loop_checks_limits_written_out() -> None:
    g = Gains(1e-3, 40.0, 1.0, 1.0, 1e4, 1e5, 1e-4)  # 1000 Hz of sampling
    # Phase 30 deg and gain 6 dB are the least allowed; a velocity loop of 100 Hz is sampled
    # 10 times: all at their limit, OK.
    at = {c.name: c for c in loop_checks("x", _figures(30.0, 6.0, 100.0), g)}
    assert [c.status for c in at.values()] == ["OK"] * 6
    ratio = at["sampling frequency over the velocity-loop bandwidth"]
    assert ratio.value == pytest.approx(10.0) and ratio.limit == 10.0 and ratio.hard == 2.0
    # Just past: 29.9 deg and 5.9 dB are CHECK (above 0), -0.1 deg NOT OK.
    past = {c.name: c for c in loop_checks("x", _figures(29.9, 5.9, 101.0), g)}
    assert past["velocity-loop phase margin"].status == "CHECK"
    assert past["velocity-loop gain margin"].status == "CHECK"
    assert past["sampling frequency over the velocity-loop bandwidth"].status == "CHECK"
    assert "below 0.0009901 s" in past["sampling frequency over the velocity-loop bandwidth"].advice
    gone = {c.name: c for c in loop_checks("x", _figures(-0.1, -0.1, 501.0), g)}
    assert gone["velocity-loop phase margin"].status == "NOT OK"
    assert gone["velocity-loop gain margin"].status == "NOT OK"
    # 1000 Hz over 501 Hz is 1.996: below Nyquist's 2, NOT OK; over 500 Hz, exactly 2: CHECK.
    assert gone["sampling frequency over the velocity-loop bandwidth"].status == "NOT OK"
    nyq = {c.name: c for c in loop_checks("x", _figures(45.0, 10.0, 500.0), g)}
    assert nyq["sampling frequency over the velocity-loop bandwidth"].status == "CHECK"
    # A margin of exactly 0 is a loop at the edge of stability (it rings for ever): NOT OK,
    # as the module's docstring says; the sampling ratio's hard limit (Nyquist, 2) is not
    # strict (exactly 2 is CHECK, above).
    edge = {c.name: c for c in loop_checks("x", _figures(0.0, 0.0, 100.0), g)}
    assert edge["velocity-loop phase margin"].status == "NOT OK"
    assert edge["velocity-loop gain margin"].status == "NOT OK"
    # A margin just above 0 is stable, if barely: CHECK.
    low = {c.name: c for c in loop_checks("x", _figures(0.1, 0.1, 100.0), g)}
    assert low["velocity-loop phase margin"].status == "CHECK"
    assert low["velocity-loop gain margin"].status == "CHECK"
    # No bandwidth (0 or infinite): no ratio, NOT OK, and says so.
    for bw in (0.0, math.inf):
        none = {c.name: c for c in loop_checks("x", _figures(45.0, 10.0, bw), g)}
        c = none["sampling frequency over the velocity-loop bandwidth"]
        assert math.isnan(c.value) and c.status == "NOT OK" and "no bandwidth" in c.advice
    # A tiny but positive bandwidth is a bandwidth: 1e-3 Hz is sampled 1e6 times.
    tiny = {c.name: c for c in loop_checks("x", _figures(45.0, 10.0, 1e-3), g)}
    assert tiny["sampling frequency over the velocity-loop bandwidth"].value == pytest.approx(1e6)


def test_a_checks_margin_and_its_text() -> None:
    floor = Check("x", "phase", 35.0, 30.0, "deg", True, "raise it")
    ceiling = Check("x", "speed", 2500.0, 3000.0, "rpm", False, "lower it")
    assert floor.margin == 5.0 and ceiling.margin == 500.0
    assert floor.text() == "x: phase 35 deg >= 30 deg"
    at_ceiling = Check("x", "speed", 3000.0, 3000.0, "rpm", False, "lower it")
    assert at_ceiling.ok and at_ceiling.margin == 0.0
    over = Check("x", "speed", 3000.5, 3000.0, "rpm", False, "lower it")
    assert not over.ok and over.text().endswith("> 3000 rpm (lower it)")


def test_the_drive_checks_by_hand() -> None:
    # A two-mass axis of 200 kg, lead 10 mm through a 2:1 gear: 0.01/(4 pi) m per motor
    # radian. At 0.05 m/s: 0.05/(0.01/(4 pi)) = 62.83 rad/s = 600 rpm. Screw friction 300 N
    # either way, guideways 50 N + 100 N*s/m * 0.05 m/s, a weight of -80 N: a drag of 435 N.
    # At 2 m/s^2: 200 * 2 + 435 = 835 N, times 0.01/(4 pi): 0.66446 N*m. A peak torque of
    # 1 N*m gives (1/(0.01/(4 pi)) - 435)/200 = 4.108 m/s^2.
    axis = AxisDynamics("x", 20.0, 180.0, 2e8, 100.0, np.array([-0.2, 0.2]),
                        np.array([-300.0, 300.0]), 1e8, 1e4, guide_coulomb=50.0,
                        guide_viscous=100.0, external_force=-80.0, lead=0.01,
                        gear_ratio=2.0)  # fmt: skip
    motor = {"rated_speed": 100.0, "peak_torque": 1.0}  # rad/s, N*m
    checks = {c.name: c for c in drive_checks("x", axis, motor, 0.05, 2.0)}
    speed = checks["motor speed at the feed"]
    assert speed.value == pytest.approx(600.0, rel=1e-12)
    assert speed.limit == pytest.approx(100.0 * 30.0 / math.pi, rel=1e-12) and not speed.floor
    torque = checks["peak motor torque"]
    per_rad = 0.01 / (4 * math.pi)
    assert torque.value == pytest.approx(835.0 * per_rad, rel=1e-12) and torque.limit == 1.0
    acc = checks["peak acceleration of the path (start-up ramp, v^2/R)"]
    assert acc.value == 2.0 and acc.limit == pytest.approx((1.0 / per_rad - 435.0) / 200.0)
    assert drive_checks("x", axis, {}, 0.05, 2.0) == []


# --- the cascade ------------------------------------------------------------------------


def _axis(rigid: bool = True) -> AxisDynamics:
    """200 kg (20 on the motor side), 2e8 N/m, 100 N*s/m; no friction; lead 10 mm, gear 1."""
    k = math.inf if rigid else 2e8
    return AxisDynamics("x", 20.0, 180.0, k, 0.0 if rigid else 100.0, np.array([-1.0, 1.0]),
                        np.zeros(2), 1e8, 1e4)  # fmt: skip


def test_the_symmetric_optimum_by_hand() -> None:
    # 45 deg: a = (1 + sin 45)/cos 45 = 1 + sqrt 2; the small lag tau_c + T_s; the crossover
    # 1/(a lag); K_p = m w_c; T_i = a/w_c, K_i = K_p/T_i = m w_c^2/a.
    a = 1.0 + math.sqrt(2.0)
    lag = 1e-4 + 2e-4
    wc = 1.0 / (a * lag)
    g = tune(_axis(), sampling_time=2e-4, current_lag=1e-4, kv=30.0)
    assert (g.kp, g.ki) == pytest.approx((200.0 * wc, 200.0 * wc * wc / a), rel=1e-12)
    assert (g.sampling_time, g.kv, g.current_lag) == (2e-4, 30.0, 1e-4)
    assert "a = 2.41 for 45 deg, small lag 0.3 ms" in g.notes[0]
    # 60 deg: a = (1 + sin 60)/cos 60 = 2 + sqrt 3.
    a60 = 2.0 + math.sqrt(3.0)
    g60 = tune(_axis(), sampling_time=2e-4, current_lag=1e-4, phase_margin=math.radians(60.0))
    assert g60.kp == pytest.approx(200.0 / (a60 * lag), rel=1e-12)
    # The documented defaults: 250 us, tau_c of a 1 kHz current loop, 45 deg, k_v 40 1/s,
    # full feed-forward.
    d = tune(_axis())
    assert (d.sampling_time, d.kv, d.velocity_ff, d.acceleration_ff) == (250e-6, 40.0, 1.0, 1.0)
    assert d.current_lag == pytest.approx(1.0 / (2.0 * math.pi * 1000.0), rel=1e-12)
    lag_d = 250e-6 + 1.0 / (2.0 * math.pi * 1000.0)
    assert d.kp == pytest.approx(200.0 / (a * lag_d), rel=1e-12)


def test_the_crossover_is_held_below_half_the_antiresonance() -> None:
    # sqrt(2e8/180)/(2 pi) = 167.8 Hz: half is 83.9 Hz, below the 1/(a 0.3 ms) = 1381 rad/s
    # = 219.8 Hz the rule asks. K_p = m 2 pi 83.9 Hz, the PI's corner a below it.
    axis = _axis(rigid=False)
    half = 0.5 * math.sqrt(2e8 / 180.0)
    g = tune(axis, sampling_time=2e-4, current_lag=1e-4)
    a = 1.0 + math.sqrt(2.0)
    assert g.kp == pytest.approx(200.0 * half, rel=1e-12)
    assert g.ki == pytest.approx(200.0 * half * half / a, rel=1e-12)
    assert "crossover lowered from 220 Hz to half the axis' antiresonance, 84 Hz" in g.notes[1]
    # A slower loop (1 ms of lag: 1/(a 1.1 ms) = 60 Hz) is left where it is.
    slow = tune(axis, sampling_time=1e-3, current_lag=1e-4)
    assert len(slow.notes) == 1 and slow.kp == pytest.approx(200.0 / (a * 1.1e-3), rel=1e-12)


@pytest.mark.parametrize("degrees", [0.0, 90.0, -10.0])
def test_a_phase_margin_outside_0_to_90_degrees_is_refused(degrees: float) -> None:
    with pytest.raises(BallScrewInputError, match="phase_margin"):
        tune(_axis(), phase_margin=math.radians(degrees))


def test_the_tuning_takes_phase_margins_near_either_end() -> None:
    for degrees in (0.5, 85.0):
        tune(_axis(), phase_margin=math.radians(degrees))
    with pytest.raises(BallScrewInputError, match="a positive time"):
        tune(_axis(), sampling_time=0.0)


def test_the_gains_refuse_what_cannot_run() -> None:
    base = Gains(1e-4, 30.0, 1.0, 1.0, 1e4, 1e5, 1e-4)
    for name in ("sampling_time", "kv", "kp", "current_lag"):
        with pytest.raises(BallScrewInputError, match=name):
            replace(base, **{name: 0.0})
    with pytest.raises(BallScrewInputError, match="ki"):
        replace(base, ki=-1.0)
    assert replace(base, ki=0.0).ki == 0.0  # a P velocity loop
    assert replace(base, kp=0.5).kp == 0.5  # small positive gains run
    # Motor side: K (l/(2 pi i))^2, lead 10 mm, gear 2: (0.01/(4 pi))^2 = 6.333e-7 m^2/rad^2.
    r = (0.01 / (4 * math.pi)) ** 2
    axis = replace(_axis(), gear_ratio=2.0)
    motor = base.as_dict(axis)["motor_side"]
    assert motor == pytest.approx({"kp_N_m_s_per_rad": 1e4 * r, "ki_N_m_per_rad": 1e5 * r})


def _open_loops(axis: AxisDynamics, g: Gains, w: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The velocity and the position open loop at s = j w, written out with numpy."""
    s = 1j * w
    t = g.sampling_time
    pade = (1 - s * t / 2 + (s * t) ** 2 / 12) / (1 + s * t / 2 + (s * t) ** 2 / 12)
    m1, m2, k, c = axis.motor_mass, axis.table_mass, axis.stiffness, axis.damping
    if axis.rigid:
        plant = 1 / (axis.mass * s)
        scale = 1.0
    else:
        spring = m2 * s**2 + c * s + k
        plant = s * spring / (s**2 * (m1 * spring + m2 * (c * s + k)))
        scale = 1.0 if g.feedback == "motor" else (c * s + k) / spring
    vel = (g.kp + g.ki / s) / (g.current_lag * s + 1) * pade * plant
    pos = g.kv * vel / (1 + vel) * scale / s
    return vel, pos


@pytest.mark.parametrize(("rigid", "feedback"), [(True, "motor"), (False, "motor"),
                                                 (False, "table")])  # fmt: skip
def test_the_loops_transfer_functions_against_numpy(rigid: bool, feedback: str) -> None:
    axis = _axis(rigid)
    g = replace(tune(axis, sampling_time=2e-4, current_lag=1e-4, kv=30.0), feedback=feedback)
    loops = loop_systems(axis, g)
    w = np.array([3.0, 30.0, 300.0, 1000.0, 3000.0])
    vel, pos = _open_loops(axis, g, w)
    # 1e-6: minreal's cancellation of near-equal poles and zeros, far below a change of form.
    np.testing.assert_allclose(loops["velocity_open"](1j * w), vel, rtol=1e-6)
    np.testing.assert_allclose(loops["velocity_closed"](1j * w), vel / (1 + vel), rtol=1e-6)
    np.testing.assert_allclose(loops["position_open"](1j * w), pos, rtol=1e-6)
    np.testing.assert_allclose(loops["position_closed"](1j * w), pos / (1 + pos), rtol=1e-6)
    if rigid:
        np.testing.assert_allclose(loops["plant"](1j * w), 1 / (200.0 * 1j * w), rtol=1e-12)


def test_the_loops_figures_against_numpy() -> None:
    # Crossover |L| = 1, phase margin 180 + arg L there, gain margin -20 log10 |L| where the
    # phase is -180, the bandwidth of L/(1 + L) (3 dB down: 10^(-3/20), not 1/sqrt 2):
    # found by root-finding on the numpy loops above. 1e-3: the root finder's tolerance and
    # control's own frequency grid.
    from scipy.optimize import brentq

    axis = _axis()
    g = tune(axis, sampling_time=2e-4, current_lag=1e-4, kv=30.0)
    f = loop_figures(axis, g)

    def vel(w: float) -> complex:
        return complex(_open_loops(axis, g, np.array([w]))[0][0])

    def pos(w: float) -> complex:
        return complex(_open_loops(axis, g, np.array([w]))[1][0])

    for k, loop, crossover, pm, gm, bw, lo, hi in (
        (0, vel, f.velocity_crossover_hz, f.velocity_phase_margin_deg,
         f.velocity_gain_margin_db, f.velocity_bandwidth_hz, 50.0, 5e3),
        (1, pos, f.position_crossover_hz, f.position_phase_margin_deg,
         f.position_gain_margin_db, f.position_bandwidth_hz, 1.0, 300.0),
    ):  # fmt: skip
        wc = brentq(lambda w, L=loop: abs(L(w)) - 1.0, lo, hi, xtol=1e-10)  # type: ignore[misc]
        assert crossover == pytest.approx(wc / (2 * math.pi), rel=1e-3)
        phase = math.degrees(np.angle(loop(wc)))
        assert pm == pytest.approx(180.0 + phase, abs=0.05)
        # The first -180 deg crossing above the crossover (the phase falls with the delay).
        grid = np.geomspace(wc, 1e6, 20000)
        ph = np.unwrap(np.angle(_open_loops(axis, g, grid)[k]))
        i = int(np.argmax(ph <= -math.pi))
        w180 = brentq(lambda w, L=loop: np.angle(L(w) / -1.0), grid[i - 1], grid[i])  # type: ignore[misc]
        assert gm == pytest.approx(-20.0 * math.log10(abs(loop(w180))), abs=0.01)
        drop = abs(loop(1e-3) / (1 + loop(1e-3))) * 10 ** (-3 / 20)
        wb = brentq(lambda w, L=loop, d=drop: abs(L(w) / (1 + L(w))) - d, 1e-2,
                    1e5)  # type: ignore[misc]  # fmt: skip
        assert bw == pytest.approx(wb / (2 * math.pi), rel=1e-3)
