"""The circular test's evaluation on synthetic paths whose G, glitches and residual are known.

``servo.contour._analyse`` reads a ballbar's table positions; here they are written
directly (no simulation), so every expected number is a closed form of the path:

- a perfect circle about an offset centre: G = 0 about the least-squares centre, and the
  radius about the nominal centre swings by the offset e either way (e at 0°, -e at 180°);
- an ellipse of semi-axes R + d and R - d about the centre: G = 2d (the samples include
  0° and 90°, where the radius is R + d and R - d);
- a tent of height h over [90°, 100°] on a perfect circle: the 90° glitch is h high,
  5° wide (above h/2), peaking at 95°, on the y axis; a bigger tent at 123° to 127° lies outside
  every quadrant's ±30° window and is seen by none;
- a following error that drifts at a known rate: the start-up residual is the drift over
  one revolution, a non-integer number of samples (interpolated).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.servo.contour import QUADRANTS, ContourResult, _analyse, _fit_centre
from ballscrew.servo.simulate import Trace

R = 0.01  # m
N = 1440  # samples per revolution: every 0.25°, so 0°, 90°, 180°, 270° are samples
TS = 1e-3  # s


def trace(table: np.ndarray, error: np.ndarray | None = None) -> Trace:
    """An axis's trace whose table positions are ``table`` and following error ``error``."""
    t = np.arange(table.size) * TS
    err = np.zeros(table.size) if error is None else error
    zero = np.zeros(table.size)
    return Trace(t, table + err, zero, table, table, zero, zero)


def revolution(radius: np.ndarray | float, cx: float = 0.0, cy: float = 0.0,
               clockwise: bool = False) -> tuple[np.ndarray, np.ndarray]:  # fmt: skip
    theta = 2.0 * math.pi * np.arange(N) / N
    if clockwise:
        theta = -theta
    return cx + radius * np.cos(theta), cy + radius * np.sin(theta)


def analyse(x: np.ndarray, y: np.ndarray, clockwise: bool = False, period: float = N,
            ex: np.ndarray | None = None, ey: np.ndarray | None = None):  # type: ignore[no-untyped-def]  # fmt: skip
    # The whole trace is the window, with one more revolution after it for the residual.
    xs, ys = np.concatenate([x, x, x[:2]]), np.concatenate([y, y, y[:2]])
    return _analyse(trace(xs, ex), trace(ys, ey), R, slice(0, N), clockwise, False, period)


def test_a_circle_about_an_offset_centre_has_no_circular_deviation() -> None:
    e = 5e-6
    x, y = revolution(R, cx=e, cy=-2e-6)
    # Kasa's fit is exact on an exact circle: the centre to rounding (1e-15 m of 1e-2 m
    # coordinates; 1e-13 m allowed), G to 1e-13 m; a wrong fit leaves micrometres.
    cx, cy = _fit_centre(x, y)
    assert (cx, cy) == pytest.approx((e, -2e-6), abs=1e-13)
    run = analyse(x, y)
    assert run.circular_deviation == pytest.approx(0.0, abs=1e-13)
    # About the nominal centre the radius swings by the offset: |c + R u| - R.
    np.testing.assert_allclose(run.deviation, np.hypot(x, y) - R, rtol=0, atol=1e-18)
    assert np.max(run.deviation) == pytest.approx(math.hypot(e, 2e-6), rel=1e-6)
    assert np.min(run.deviation) == pytest.approx(-math.hypot(e, 2e-6), rel=1e-6)


def test_an_ellipse_has_g_twice_its_half_axes_difference() -> None:
    d = 3e-6
    theta = 2.0 * math.pi * np.arange(N) / N
    x, y = (R + d) * np.cos(theta), (R - d) * np.sin(theta)
    run = analyse(x, y)
    # Symmetric about both axes: the fitted centre is the origin and the band is
    # R + d - (R - d) = 2d; 1e-12 m is the rounding of the fit on 1e-2 m coordinates.
    assert run.circular_deviation == pytest.approx(2.0 * d, abs=1e-12)
    # The mean radius error: r = sqrt(R^2 + 2Rd cos2t + d^2) - R = d cos2t + d^2/(2R)
    # - d^2 cos^2(2t)/(2R) + O(d^3/R^2) averages to d^2/(4R); the next order is d/R = 3e-4
    # of it: 1e-3.
    assert run.mean_radius_error == pytest.approx(d**2 / (4.0 * R), rel=1e-3)
    # At 0 and 180 deg the glitch is +d (x reverses), at 90 and 270 deg -d (y reverses),
    # each about the median radius error (0 up to d^2/R).
    heights = {g.quadrant: g.height for g in run.glitches}
    axes = {g.quadrant: g.axis for g in run.glitches}
    assert [heights[q] for q in QUADRANTS] == pytest.approx([d, -d, d, -d], rel=1e-3)
    assert axes == {0.0: "x", 90.0: "y", 180.0: "x", 270.0: "y"}
    # Above half the height nearly over the whole window (not past it).
    assert all(59.0 < g.width <= 60.0 for g in run.glitches)
    # Each peaks on its quadrant's own sample, where |d cos 2t| is largest.
    assert [g.angle % 360.0 for g in run.glitches] == pytest.approx(list(QUADRANTS), abs=1e-9)


def tent_circle(
    clockwise: bool, offset: float = 0.0, size: float = 0.0, last: float = 0.0
) -> tuple[np.ndarray, np.ndarray]:
    """A circle of radius R + ``size`` with a tent h = 2 um high on 89.9 to 100.1 deg, one
    4 um high on 123 to 127 deg and one ``last`` high on 328.95 to 333.05 deg; the same points run
    either way (samples at 0.25 (k + offset) deg)."""
    h = 2e-6
    angle = np.degrees(2.0 * math.pi * (np.arange(N) + offset) / N)
    if clockwise:
        angle = (-angle) % 360.0
    # Above h/2 within 2.55 deg of 95: the samples 92.5 to 97.5 deg.
    bump = np.maximum(h * (1.0 - np.abs(angle - 95.0) / 5.1), 0.0)
    # Twice as high at 123 to 127 deg: outside 90 +- 30 and 180 +- 30.
    bump += np.maximum(2.0 * h * (1.0 - np.abs(angle - 125.0) / 2.0), 0.0)
    bump += last * np.maximum(1.0 - np.abs(angle - 331.0) / 2.05, 0.0)
    theta = np.radians(angle)
    return (R + size + bump) * np.cos(theta), (R + size + bump) * np.sin(theta)


@pytest.mark.parametrize("clockwise", [False, True])
def test_a_bump_at_ninety_degrees_is_that_quadrants_glitch(clockwise: bool) -> None:
    h = 2e-6
    # The circle 1 um too large: each glitch is measured from the median radius error.
    run = analyse(*tent_circle(clockwise, size=1e-6, last=-h), clockwise=clockwise)
    assert run.clockwise is clockwise
    by_quadrant = {g.quadrant: g for g in run.glitches}
    g90 = by_quadrant[90.0]
    # The heights are the tent's to the rounding of hypot on 1e-2 m (1e-17 m): 1e-15 m.
    assert g90.axis == "y"
    assert g90.height == pytest.approx(h, abs=1e-15)
    # Above half its height on the samples from 92.5 to 97.5 deg.
    assert g90.width == pytest.approx(5.0, abs=1e-9)
    assert g90.angle == pytest.approx(95.0, abs=1e-9)
    for q in (180.0, 270.0):
        assert by_quadrant[q].height == pytest.approx(0.0, abs=1e-15)
    # A dent h deep at 331 deg is the 0 deg glitch, peaking 29 deg before the quadrant;
    # above half its depth from 330 deg, the window's first sample, to 332 deg.
    assert by_quadrant[0.0].height == pytest.approx(-h, abs=1e-15)
    assert by_quadrant[0.0].angle == pytest.approx(331.0, abs=1e-9)
    assert by_quadrant[0.0].width == pytest.approx(2.0, abs=1e-9)
    assert by_quadrant[0.0].axis == "x"
    assert run.largest_glitch == pytest.approx(h, abs=1e-15)


def test_the_hysteresis_pairs_the_two_directions_by_angle() -> None:
    # CW and CCW over the same points (in opposite order; none on a bin's edge): no
    # hysteresis. The tents on one direction only: H is their highest 1-degree bin, the
    # 4 um tent's samples at 124.125 to 124.875 or 125.125 to 125.875 deg, 0.5 deg from its
    # top on average: 4 um (1 - 0.5/2) = 3 um; 1e-15 m: rounding.
    def contour(cw: object, ccw: object) -> ContourResult:
        return ContourResult(None, None, None, R, 0.01, (cw, ccw), (), None, "test", 0.0)  # type: ignore[arg-type]

    tent_cw = analyse(*tent_circle(True, 0.5), clockwise=True)
    tent_ccw = analyse(*tent_circle(False, 0.5), clockwise=False)
    assert contour(tent_cw, tent_ccw).hysteresis == pytest.approx(0.0, abs=1e-15)
    plain_ccw = analyse(*revolution(R), clockwise=False)
    h = contour(tent_cw, plain_ccw).hysteresis
    assert h == pytest.approx(4e-6 * (1.0 - 0.5 / 2.0), abs=1e-15)


def test_the_residual_is_the_drift_over_one_revolution() -> None:
    # Following errors drifting at 1 and -2 um/s, and a revolution of 1000.4 samples
    # (period not a whole number of samples): the error one period later differs by the
    # drift times 1.0004 s, linear and so exact under the interpolation (1e-18 m: rounding).
    # The evaluated revolution starts at sample 7, not the trace's first.
    x, y = revolution(R)
    xs, ys = np.concatenate([x[-7:], x, x, x[:2]]), np.concatenate([y[-7:], y, y, y[:2]])
    t = np.arange(xs.size) * TS
    period = 1000.4
    window = slice(7, 7 + N)
    run = _analyse(trace(xs, 1e-6 * t), trace(ys, -2e-6 * t), R, window, False, False, period)
    assert run.residual == pytest.approx(math.hypot(1e-6, 2e-6) * period * TS, rel=1e-9)
    # A quadratic drift, e = c t^2: the error one period P later, interpolated linearly
    # between the samples around it, exceeds c (t + P)^2 by c f (1 - f) TS^2, f = 0.4.
    c = 1e-3
    quad = _analyse(trace(xs, c * t**2), trace(ys), R, window, False, False, period)
    t0, t1 = 7 * TS, (7 + period) * TS
    assert quad.residual == pytest.approx(c * (t1**2 - t0**2) + c * 0.4 * 0.6 * TS**2,
                                          rel=1e-9)  # fmt: skip
    steady = _analyse(trace(xs), trace(ys), R, window, False, False, period)
    assert steady.residual == 0.0
