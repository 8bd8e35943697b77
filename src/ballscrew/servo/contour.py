r"""The circular test (after ISO 230-4) and the reversal test of simulated axes.

What ``ballscrew contour`` computes.

**Circular test.** Two axes follow a circle of radius :math:`R` at the feed
:math:`v` (angular speed :math:`\omega = v/R`), clockwise and
counter-clockwise. The path starts at rest at 45° (between two quadrants),
speeds up smoothly along the arc, runs a **lead-in arc** at the feed, then
one full revolution at the feed (the evaluated part), and stops. ISO 230-4
evaluates the contour the machine runs at its feed, not the start-up: the
lead-in lasts :data:`LEAD_IN_TIME_CONSTANTS` time constants :math:`1/k_v` of
the slower position loop, over which its transient (a tracking lag of up to
:math:`v/k_v`) decays by :math:`e^{-15} \approx 3\cdot10^{-7}`, so that a
lag of 5 mm leaves less than 2 nm; at R 10 mm, 6 m/min and
:math:`k_v` = 20 1/s that is 0.75 s, 1.2 revolutions. Whether the
revolution is settled is also measured (:attr:`CircleRun.residual`: the
change of the following error over one revolution), and a note says when it
is not. From the table positions of the evaluated revolution (what a ballbar
reads):

* the **radial deviation** :math:`\Delta r(\theta) = r(\theta) - R` about the
  circle's centre;
* the **circular deviation** :math:`G`: the radial width of the band between
  two circles about the least-squares centre that holds the evaluated
  revolution (ISO 230-4 evaluates it about such a centre);
* the **circular hysteresis** :math:`H`: the largest radial difference between
  the clockwise and the counter-clockwise path at one angle;
* each **quadrant glitch** (at 0°, 90°, 180°, 270°, where one axis reverses):
  its height, the largest excursion of :math:`\Delta r` within ±30° of the
  quadrant above the revolution's median :math:`\Delta r` (positive outwards),
  and its width, the angle over which it exceeds half its height.

**Reversal test.** One axis runs at :math:`-v`, reverses at constant
acceleration (that of the circle at the quadrant, :math:`v^2/R`) and runs on
at :math:`+v`: the commissioning engineer's first measurement. Its glitch is
the following error's largest departure, after the reversal, from that of the
same run without friction.

**Compensation as a controller applies it.** The same tests with the
friction feed-forward of a controller's table (LinuxCNC's 16 points,
:func:`ballscrew.servo.tables.fit_table`) looked up at the **commanded
velocity**, the change of the position command over the last sample (what
LinuxCNC's ``joint.N.vel-cmd`` and TwinCAT's friction compensation read), and
applied one sample later (:data:`COMPENSATION_DELAY`: the controller sends
the next cycle what it computed this one), so that the table's steep middle
switches the feed-forward with the command's sign, as on the machine
(:func:`controller_compensation`). Nothing is added to the position
reference: the screw's drag does not strain the axial spring (it acts on the
motor side, :mod:`ballscrew.servo.plant`). The glitch's reduction is the
ratio of heights.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import BallScrewInputError, FloatArray
from ..io.case import Case
from .cascade import Gains, LoopFigures, loop_figures, tune
from .plant import AxisDynamics, axis_dynamics, frictionless
from .simulate import Trace, simulate_axis
from .tables import CompensationTable, fit_table
from .verdict import MAX_SAMPLES, Check, check_size, drive_checks, loop_checks, verdict

__all__ = [
    "CircleRun",
    "ContourResult",
    "Glitch",
    "ReversalRun",
    "circle_reference",
    "circular_test",
    "contour_samples",
    "controller_compensation",
    "reversal_test",
    "run_contour",
]

START_ANGLE = math.pi / 4
"""Where the circle starts and ends [rad], between two quadrants."""

QUADRANTS = (0.0, 90.0, 180.0, 270.0)
GLITCH_WINDOW = 30.0
"""Half-width of the window around a quadrant in which its glitch is sought [deg]."""

LEAD_IN_TIME_CONSTANTS = 15.0
"""Length of the lead-in arc before the evaluated revolution, in time constants
:math:`1/k_v` of the slower axis' position loop (module docstring)."""

COMPENSATION_DELAY = 1
"""Samples between the commanded velocity a controller reads and the drive's use of the
friction feed-forward it computes from it (module docstring)."""

SETTLED_SHARE = 0.01
"""A revolution whose start-up residual exceeds this share of its G is said unsettled."""

TABLE_POINTS = 16
"""Points of the compensation table fed back into the simulation (LinuxCNC's ``lincurve``)."""


def _circle_counts(
    radius: float, feed: float, ts: float, acceleration: float, settle: float, lead_in: float
) -> tuple[int, int, int, int]:
    """Samples of :func:`circle_reference`'s parts: settle, ramp, lead-in, the revolution."""
    if not (radius > 0.0 and math.isfinite(radius)):
        raise BallScrewInputError("--radius", radius, "a positive radius [m]")
    if not (feed > 0.0 and math.isfinite(feed)):
        raise BallScrewInputError("--feed", feed, "a positive feed [m/s]")
    if not (lead_in >= 0.0 and math.isfinite(lead_in)):
        raise BallScrewInputError("lead_in", lead_in, "a time of 0 s or more")
    t_r = max(1.5 * feed / acceleration, 20 * ts)
    t_c = 2.0 * math.pi * radius / feed
    return round(settle / ts), round(t_r / ts), round(lead_in / ts), round(t_c / ts)


def contour_samples(
    radius: float, feed: float, sampling_time: float, kv: float, *, circles: int = 4,
    reversals: int = 2, reversal_acceleration: float | None = None,
) -> int:  # fmt: skip
    """Samples ``run_contour`` simulates: ``circles`` circles and ``reversals`` reversals.

    Each circle runs both axes over its settling, ramps, lead-in of
    :data:`LEAD_IN_TIME_CONSTANTS`/``kv`` and revolution (:func:`circle_reference`); each
    reversal one axis twice (with and without friction, :func:`reversal_test`). Counted
    before any array is made, so that a radius of a kilometre is refused, not run out of
    memory.
    """
    ts = sampling_time
    if not (ts > 0.0 and math.isfinite(ts)):
        raise BallScrewInputError("--sampling-time", ts, "a positive time [s]")
    n_s, n_r, n_l, n_e = _circle_counts(radius, feed, ts, 1.0, 0.05,
                                        LEAD_IN_TIME_CONSTANTS / kv)  # fmt: skip
    per_circle = 2 * (2 * n_s + 2 * n_r + n_l + n_e)
    acc = feed**2 / radius if reversal_acceleration is None else reversal_acceleration
    t_a = 0.0 if math.isinf(acc) else feed / acc
    per_reversal = 2 * round((0.05 + 3 * t_a + 0.6) / ts)
    return circles * per_circle + reversals * per_reversal


def circle_reference(
    radius: float, feed: float, sampling_time: float, *, clockwise: bool = False,
    acceleration: float = 1.0, settle: float = 0.05, lead_in: float = 0.0,
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray, FloatArray, FloatArray,
           slice]:  # fmt: skip
    r"""The circle's references per sample, and the evaluated samples.

    x, y [m], their speeds [m/s] and accelerations [m/s²], and the slice of
    samples of the evaluated revolution at the feed.

    The path speed rises as :math:`v(1 - \cos(\pi t/t_r))/2` over :math:`t_r =
    \max(1.5\,v/a, 20\,T_s)` (peak tangential acceleration about ``acceleration``
    [m/s²]), holds for ``lead_in`` [s] and then one revolution (the evaluated
    one), and falls the same way.
    """
    ts = sampling_time
    n_s, n_r, n_l, n_e = _circle_counts(radius, feed, ts, acceleration, settle, lead_in)
    t_r = max(1.5 * feed / acceleration, 20 * ts)
    n_c = n_l + n_e  # at the feed
    t = np.arange(n_s + 2 * n_r + n_c + n_s) * ts
    ramp = np.clip((t - n_s * ts) / t_r, 0.0, 1.0)
    down = np.clip((t - (n_s + n_r + n_c) * ts) / t_r, 0.0, 1.0)
    speed = feed * 0.5 * ((1.0 - np.cos(math.pi * ramp)) - (1.0 - np.cos(math.pi * down)))
    rising = np.sin(math.pi * ramp) * ((ramp > 0) & (ramp < 1))
    falling = np.sin(math.pi * down) * ((down > 0) & (down < 1))
    accel = feed * 0.5 * math.pi * (rising - falling) / t_r

    # Path length by the exact integral of the ramp: t/2 - t_r sin(pi t/t_r)/(2 pi).
    def covered(u: FloatArray) -> FloatArray:
        out: FloatArray = feed * t_r * (0.5 * u - np.sin(math.pi * u) / (2.0 * math.pi))
        return out

    in_const = np.clip(t - (n_s + n_r) * ts, 0.0, n_c * ts)
    s = covered(ramp) + feed * in_const + np.where(down > 0, feed * t_r * down - covered(down),
                                                   0.0)  # fmt: skip
    sign = -1.0 if clockwise else 1.0
    phi = START_ANGLE + sign * s / radius
    w = sign * speed / radius
    dw = sign * accel / radius
    x, y = radius * np.cos(phi), radius * np.sin(phi)
    vx, vy = -y * w, x * w
    ax = -x * w * w - y * dw
    ay = -y * w * w + x * dw
    return x, y, vx, vy, ax, ay, slice(n_s + n_r + n_l, n_s + n_r + n_c)


def controller_compensation(
    table: CompensationTable, x_ref: FloatArray, sampling_time: float,
    delay: int = COMPENSATION_DELAY,
) -> FloatArray:  # fmt: skip
    """The friction feed-forward [N] per sample as a controller applies ``table``.

    Looked up at the commanded velocity, the position command's change over the
    last sample, :math:`(x_r[i] - x_r[i-1])/T_s`, and applied ``delay`` samples
    later (module docstring); zero before the first command.
    """
    if delay < 0:
        raise BallScrewInputError("delay", delay, "0 or more samples")
    xr = np.asarray(x_ref, dtype=float)
    v_cmd = np.diff(xr, prepend=xr[0]) / sampling_time
    force = table(v_cmd)
    if delay == 0:
        return force
    out: FloatArray = np.concatenate([np.zeros(min(delay, xr.size)), force[:-delay]])
    return out[: xr.size]


@dataclass(frozen=True)
class Glitch:
    """A quadrant glitch: the axis that reverses, the quadrant [deg], height [m], width [deg]."""

    axis: str
    quadrant: float
    height: float
    width: float
    angle: float

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready glitch (µm and degrees)."""
        return {"axis": self.axis, "quadrant_deg": self.quadrant, "height_um": self.height * 1e6,
                "width_deg": self.width, "peak_angle_deg": self.angle}  # fmt: skip


@dataclass(frozen=True)
class CircleRun:
    """One direction of the circular test: deviations, G, glitches, and the traces."""

    clockwise: bool
    compensated: bool
    angle: FloatArray
    deviation: FloatArray
    circular_deviation: float
    mean_radius_error: float
    glitches: tuple[Glitch, ...]
    x: Trace
    y: Trace
    residual: float = 0.0
    """How far the evaluated revolution is from settled [m]: the change of the table's
    following error (x and y together) between its first sample and the same point of the
    path one revolution later. A settled, periodic circle repeats it."""

    @property
    def settled(self) -> bool:
        """True when the revolution repeats within :data:`SETTLED_SHARE` of G (or 10 nm)."""
        return self.residual <= max(SETTLED_SHARE * self.circular_deviation, 1e-8)

    @property
    def largest_glitch(self) -> float:
        """The largest glitch height [m]."""
        return max(abs(g.height) for g in self.glitches)

    def binned(self, width: float = 1.0) -> tuple[FloatArray, FloatArray]:
        """Radial deviation [m] in bins of ``width`` degrees (centres [deg]; no empty bins)."""
        edges = np.arange(0.0, 360.0 + width, width)
        idx = np.clip(np.digitize(self.angle, edges) - 1, 0, edges.size - 2)
        sums = np.bincount(idx, self.deviation, edges.size - 1)
        counts = np.bincount(idx, None, edges.size - 1)
        keep = counts > 0
        return (0.5 * (edges[:-1] + edges[1:]))[keep], sums[keep] / counts[keep]

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready run (µm, degrees; the deviation in 1° bins)."""
        centres, dev = self.binned()
        return {"direction": "CW" if self.clockwise else "CCW",
                "compensated": self.compensated,
                "circular_deviation_G_um": self.circular_deviation * 1e6,
                "mean_radius_error_um": self.mean_radius_error * 1e6,
                "glitches": [g.as_dict() for g in self.glitches],
                "largest_glitch_um": self.largest_glitch * 1e6,
                "start_up_residual_um": self.residual * 1e6, "settled": self.settled,
                "radial_deviation": {"angle_deg": centres.round(3).tolist(),
                                     "deviation_um": (dev * 1e6).tolist()}}  # fmt: skip


def _fit_centre(x: FloatArray, y: FloatArray) -> tuple[float, float]:
    """Least-squares circle centre (Kåsa's linear fit)."""
    a = np.column_stack([2 * x, 2 * y, np.ones_like(x)])
    sol = np.linalg.lstsq(a, x * x + y * y, rcond=None)[0]
    return float(sol[0]), float(sol[1])


def _glitches(angle: FloatArray, dev: FloatArray) -> tuple[Glitch, ...]:
    base = float(np.median(dev))
    out = []
    for q in QUADRANTS:
        diff = (angle - q + 180.0) % 360.0 - 180.0
        inside = np.abs(diff) <= GLITCH_WINDOW
        order = np.argsort(diff[inside])
        d, e = diff[inside][order], dev[inside][order] - base
        j = int(np.argmax(np.abs(e)))
        height = float(e[j])
        above = np.abs(e) >= 0.5 * abs(height)
        lo = j
        while lo > 0 and above[lo - 1]:
            lo -= 1
        hi = j
        while hi < e.size - 1 and above[hi + 1]:
            hi += 1
        axis = "x" if q in (0.0, 180.0) else "y"
        out.append(Glitch(axis, q, height, float(d[hi] - d[lo]), float((q + d[j]) % 360.0)))
    return tuple(out)


def _analyse(x: Trace, y: Trace, radius: float, window: slice, clockwise: bool,
             compensated: bool, period: float) -> CircleRun:  # fmt: skip
    """G, the deviations and the glitches of the evaluated ``window``.

    ``period``: one revolution at the feed, in samples (not rounded).
    """
    px, py = x.table[window], y.table[window]
    cx, cy = _fit_centre(px, py)
    r_fit = np.hypot(px - cx, py - cy)
    dev = np.hypot(px, py) - radius
    angle = np.degrees(np.arctan2(py, px)) % 360.0
    # The same point of the path one revolution apart: the window's first sample and the
    # error interpolated one period later (the feed still holds there: the ramp down starts
    # with no slope), so that the rounding of the period to samples does not count.
    i = window.start
    j = min(i + math.floor(period), x.time.size - 2)
    f = i + period - j

    def later(e: FloatArray) -> float:
        return float(e[j] + (e[j + 1] - e[j]) * f)

    residual = math.hypot(later(x.error) - x.error[i], later(y.error) - y.error[i])
    return CircleRun(clockwise, compensated, angle, dev, float(np.ptp(r_fit)),
                     float(np.mean(dev)), _glitches(angle, dev), x, y, residual)  # fmt: skip


def circular_test(
    axes: tuple[AxisDynamics, AxisDynamics],
    gains: tuple[Gains, Gains],
    radius: float,
    feed: float,
    *,
    clockwise: bool = False,
    tables: tuple[CompensationTable, CompensationTable] | None = None,
) -> CircleRun:
    """One direction of the circular test (module docstring); ``tables`` compensate friction."""
    ts = gains[0].sampling_time
    if gains[1].sampling_time != ts:
        raise BallScrewInputError("sampling_time", gains[1].sampling_time,
                                  f"the same for both axes ({ts:g} s)")  # fmt: skip
    lead_in = LEAD_IN_TIME_CONSTANTS / min(gains[0].kv, gains[1].kv)
    x, y, vx, vy, ax, ay, window = circle_reference(radius, feed, ts, clockwise=clockwise,
                                                    lead_in=lead_in)  # fmt: skip
    if tables is None:
        tx = simulate_axis(axes[0], gains[0], x, vx, ax)
        ty = simulate_axis(axes[1], gains[1], y, vy, ay)
    else:
        fx = controller_compensation(tables[0], x, ts)
        fy = controller_compensation(tables[1], y, ts)
        tx = simulate_axis(axes[0], gains[0], x, vx, ax, fx)
        ty = simulate_axis(axes[1], gains[1], y, vy, ay, fy)
    period = 2.0 * math.pi * radius / feed / ts
    return _analyse(tx, ty, radius, window, clockwise, tables is not None, period)


@dataclass(frozen=True)
class ReversalRun:
    """The reversal test of one axis: its glitch and the traces with and without friction."""

    speed: float
    acceleration: float
    glitch: float
    time_to_peak: float
    trace: Trace
    reference: Trace
    compensated: bool

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready run."""
        return {"speed_m_s": self.speed, "acceleration_m_s2": self.acceleration,
                "compensated": self.compensated, "glitch_um": self.glitch * 1e6,
                "time_to_peak_ms": self.time_to_peak * 1e3}  # fmt: skip


def reversal_reference(
    speed: float, acceleration: float, sampling_time: float, hold: float = 0.3
) -> tuple[FloatArray, FloatArray, FloatArray, int]:
    """From rest to -speed, hold, through zero to +speed at ``acceleration``, hold.

    An infinite ``acceleration`` makes each change of speed a step within one sample
    (a jog reversed at once). Returns x, v, a per sample and the sample of the zero
    crossing.
    """
    ts = sampling_time
    if not acceleration > 0.0:
        raise BallScrewInputError("acceleration", acceleration, "a positive acceleration")
    if math.isinf(acceleration):
        segments = [(0.05, 0.0), (ts, -speed / ts), (hold, 0.0), (ts, 2 * speed / ts),
                    (hold, 0.0)]  # fmt: skip
    else:
        t_a = speed / acceleration
        segments = [(0.05, 0.0), (t_a, -acceleration), (hold, 0.0), (2 * t_a, acceleration),
                    (hold, 0.0)]  # fmt: skip
    acc = np.concatenate([np.full(max(round(d / ts), 1), a) for d, a in segments])
    v = np.concatenate([[0.0], np.cumsum(acc[:-1]) * ts])
    x = np.concatenate([[0.0], np.cumsum(0.5 * (v[1:] + v[:-1])) * ts])
    crossing = int(np.argmax((v[:-1] < 0.0) & (v[1:] >= 0.0))) + 1
    return x, v, acc, crossing


def reversal_test(
    axis: AxisDynamics, gains: Gains, speed: float, acceleration: float,
    table: CompensationTable | None = None,
) -> ReversalRun:  # fmt: skip
    """The reversal test (module docstring)."""
    x, v, a, k = reversal_reference(speed, acceleration, gains.sampling_time)
    comp = None if table is None else controller_compensation(table, x, gains.sampling_time)
    run = simulate_axis(axis, gains, x, v, a, comp)
    clean = simulate_axis(frictionless(axis), gains, x, v, a)
    after = slice(k, None)
    diff = (run.error - clean.error)[after]
    before = float((run.error - clean.error)[k - 1])
    j = int(np.argmax(np.abs(diff - before)))
    return ReversalRun(speed, acceleration, float(diff[j] - before), j * gains.sampling_time,
                       run, clean, table is not None)  # fmt: skip


@dataclass(frozen=True)
class ContourResult:
    """``ballscrew contour``: the axes, loops, circles and reversals, compensated or not."""

    axes: tuple[AxisDynamics, AxisDynamics]
    gains: tuple[Gains, Gains]
    figures: tuple[LoopFigures, LoopFigures]
    radius: float
    feed: float
    circles: tuple[CircleRun, ...]
    reversals: tuple[ReversalRun, ...]
    tables: tuple[CompensationTable, CompensationTable]
    model: str
    cpu_seconds: float
    notes: tuple[str, ...] = field(default_factory=tuple)
    checks: tuple[Check, ...] = ()
    """Whether the loops and the drive can run the circle (:mod:`ballscrew.servo.verdict`);
    when one fails no circle or reversal is simulated."""

    @property
    def verdict(self) -> str:
        """The worst check's: "OK", "CHECK" or "NOT OK" (then no circle was run)."""
        return verdict(self.checks)

    def circle(self, clockwise: bool, compensated: bool) -> CircleRun | None:
        """The run of that direction, with or without compensation."""
        return next((c for c in self.circles if c.clockwise == clockwise
                     and c.compensated == compensated), None)  # fmt: skip

    @property
    def hysteresis(self) -> float | None:
        """Circular hysteresis H [m] without compensation (both directions needed)."""
        cw, ccw = self.circle(True, False), self.circle(False, False)
        if cw is None or ccw is None:
            return None
        a1, d1 = cw.binned()
        a2, d2 = ccw.binned()
        common = np.intersect1d(a1, a2)
        return float(np.max(np.abs(d1[np.isin(a1, common)] - d2[np.isin(a2, common)])))

    @property
    def reduction(self) -> float | None:
        """Largest glitch without compensation over that with it [-] (first direction)."""
        plain = [c for c in self.circles if not c.compensated]
        comp = [c for c in self.circles if c.compensated]
        if not plain or not comp:
            return None
        return plain[0].largest_glitch / max(comp[0].largest_glitch, 1e-15)

    def as_dict(self) -> dict[str, Any]:
        """The JSON document of ``ballscrew contour --json``."""
        h = self.hysteresis
        return {
            "verdict": self.verdict, "checks": [c.as_dict() for c in self.checks],
            "model": self.model, "radius_mm": self.radius * 1e3,
            "feed_m_per_min": self.feed * 60.0,
            "axes": {name: {"dynamics": a.as_dict(), "gains": g.as_dict(a),
                            "loops": f.as_dict(), "compensation_table": t.as_dict()}
                     for name, a, g, f, t in zip("xy", self.axes, self.gains, self.figures,
                                                 self.tables, strict=True)},
            "circles": [c.as_dict() for c in self.circles],
            "circular_hysteresis_H_um": None if h is None else h * 1e6,
            "glitch_reduction": self.reduction,
            "reversals": [r.as_dict() for r in self.reversals],
            "cpu_seconds": self.cpu_seconds,
            "notes": list(self.notes),
        }  # fmt: skip


def run_contour(
    cases: Sequence[Case],
    *,
    radius: float = 0.05,
    feed: float = 2.0 / 60.0,
    model: str = "complete",
    directions: Sequence[str] = ("CCW", "CW"),
    sampling_time: float = 250e-6,
    kv: float = 40.0,
    phase_margin: float = math.radians(45.0),
    velocity_ff: float = 1.0,
    acceleration_ff: float = 1.0,
    feedback: str = "motor",
    guide_coulomb: float | None = None,
    guide_viscous: float = 0.0,
    rigid: bool = False,
    compensate: bool = True,
    gains: tuple[Gains, Gains] | None = None,
    reversal_acceleration: float | None = None,
    pre_rolling_length: float | None = None,
    drag_side: str = "motor",
    max_samples: int = MAX_SAMPLES,
    on_step: Callable[[str], None] | None = None,
) -> ContourResult:
    """The circular test of one case (both axes) or two (x, y), with the reversal test.

    Parameters
    ----------
    cases : sequence of Case
        One case for both axes or two (x then y).
    radius, feed : float
        [m], [m/s].
    model : str
        Friction model.
    directions : sequence of {"CCW", "CW"}
        The directions run.
    sampling_time, kv, phase_margin, velocity_ff, acceleration_ff, feedback
        The cascade (:func:`ballscrew.servo.cascade.tune`).
    guide_coulomb, guide_viscous : float, optional
        Guideway friction [N], [N·s/m] of each axis; None leaves it out (noted).
    rigid : bool
        One-mass axes.
    compensate : bool
        Also run with the 16-point friction table fed forward.
    gains : tuple of Gains, optional
        The loops' gains of x and y, instead of the tuning rule (the arguments
        ``sampling_time`` to ``feedback`` are then not used); both of one sampling time.
    reversal_acceleration : float, optional
        [m/s²] of the reversal test; default the circle's at the quadrant,
        :math:`v^2/R`; ``math.inf`` reverses the speed in one sample.
    pre_rolling_length : float, optional
        [m] of the screws' drag, for both axes (default: each case's, else
        :data:`ballscrew.servo.plant.PRE_ROLLING_LENGTH`).
    drag_side : {"motor", "table"}
        Where the screws' drag acts (:func:`ballscrew.servo.plant.axis_dynamics`).
    max_samples : int
        The most samples simulated (:func:`contour_samples`, estimated before any
        is); more is refused with the estimate.
    on_step : callable, optional
        Called with a description after each circle or reversal simulated (a
        progress bar's advance).

    The loops and the drive are checked first (:mod:`ballscrew.servo.verdict`):
    when one is NOT OK the result carries the checks and no circle or reversal (a
    loop that cannot run is not drawn); CHECK runs them, the verdict beside.

    Raises :class:`~ballscrew.io.extras.MissingExtraError` without the ``servo``
    extra (the loops' margins need the Python Control Systems Library).
    """
    from ..io.extras import require

    require("servo", "ballscrew contour")
    _check_contour_inputs(cases, directions, pre_rolling_length, guide_coulomb, guide_viscous,
                          kv if gains is None else None)  # fmt: skip
    if gains is not None and gains[1].sampling_time != gains[0].sampling_time:
        raise BallScrewInputError("gains", f"T_s {gains[1].sampling_time:g} s on y",
                                  "the same sampling time for both axes as x's "
                                  f"({gains[0].sampling_time:g} s)")  # fmt: skip
    runs = len(directions) * (2 if compensate else 1)
    kv_low = min(g.kv for g in gains) if gains is not None else kv
    ts_run = gains[0].sampling_time if gains is not None else sampling_time
    samples = contour_samples(radius, feed, ts_run, kv_low, circles=runs,
                              reversals=2 if compensate else 1,
                              reversal_acceleration=reversal_acceleration)  # fmt: skip
    check_size(samples, max_samples)
    start = time.process_time()
    pair = (cases[0], cases[-1])
    top = max(1.25 * feed, 0.01)
    dyn = tuple(axis_dynamics(c, model, max_speed=max(top, 0.05), guide_coulomb=guide_coulomb,
                              guide_viscous=guide_viscous, pre_rolling_length=pre_rolling_length,
                              drag_side=drag_side) for c in pair)  # fmt: skip
    if rigid:
        dyn = tuple(d.as_rigid() for d in dyn)
    axes = (dyn[0], dyn[1])
    if gains is None:
        tuned = tuple(tune(a, sampling_time=sampling_time, kv=kv, phase_margin=phase_margin,
                           velocity_ff=velocity_ff, acceleration_ff=acceleration_ff,
                           feedback=feedback) for a in axes)  # fmt: skip
        gains = (tuned[0], tuned[1])
    g2 = gains
    figures = (loop_figures(axes[0], g2[0]), loop_figures(axes[1], g2[1]))
    tables = tuple(fit_table(a.speeds, a.friction, TABLE_POINTS, top) for a in axes)
    t2 = (tables[0], tables[1])
    ref = circle_reference(radius, feed, g2[0].sampling_time,
                           lead_in=LEAD_IN_TIME_CONSTANTS / min(g.kv for g in g2))  # fmt: skip
    peaks = (float(np.max(np.abs(ref[4]))), float(np.max(np.abs(ref[5]))))
    del ref
    checks = [c for name, a, g, f in zip("xy", axes, g2, figures, strict=True)
              for c in loop_checks(name, f, g)]  # fmt: skip
    for name, a, case, peak in zip("xy", axes, pair, peaks, strict=True):
        checks += drive_checks(name, a, case.motor, feed, peak)
    circles: list[CircleRun] = []
    reversals: list[ReversalRun] = []
    step = on_step or (lambda _: None)
    if verdict(checks) != "NOT OK":
        circles, reversals = _run_tests(axes, g2, t2, radius, feed, directions, compensate,
                                        reversal_acceleration, step)  # fmt: skip
    notes = _contour_notes(axes, g2, pair, circles, one_case=len(cases) == 1, rigid=rigid,
                           top=top)  # fmt: skip
    return ContourResult(axes, g2, figures, radius, feed, tuple(circles), tuple(reversals), t2,
                         model, time.process_time() - start, tuple(notes),
                         tuple(checks))  # fmt: skip


def _check_contour_inputs(
    cases: Sequence[Case],
    directions: Sequence[str],
    pre_rolling_length: float | None,
    guide_coulomb: float | None,
    guide_viscous: float,
    kv: float | None,
) -> None:
    """Refuse :func:`run_contour`'s arguments that cannot run, naming the CLI flag.

    ``kv`` None: the gains are given, the position gain is not checked.
    """
    if not 1 <= len(cases) <= 2:
        raise BallScrewInputError("--case", len(cases), "one case (both axes) or two (x, y)")
    bad = [d for d in directions if d not in ("CW", "CCW")]
    if bad or not directions:
        raise BallScrewInputError("--direction", bad or list(directions), "CW and/or CCW")
    if pre_rolling_length is not None and not (
        math.isfinite(pre_rolling_length) and pre_rolling_length > 0.0
    ):
        raise BallScrewInputError("--pre-rolling", f"{pre_rolling_length * 1e6:g} um",
                                  "a positive length, e.g. '5 um'")  # fmt: skip
    for flag, value, unit in (("--guide-friction", guide_coulomb, "N"),
                              ("guide_viscous", guide_viscous, "N*s/m")):  # fmt: skip
        if value is not None and not (math.isfinite(value) and value >= 0.0):
            raise BallScrewInputError(flag, f"{value:g} {unit}", "a magnitude of 0 or more: "
                                      "the friction opposes the motion either way, its sign "
                                      "is the motion's")  # fmt: skip
    if kv is not None and not (math.isfinite(kv) and kv > 0.0):
        raise BallScrewInputError("--kv", f"{kv:g} 1/s", "a positive position gain, e.g. "
                                  "'40 1/s' (machine tools run 15 to 70 1/s)")  # fmt: skip


def _run_tests(
    axes: tuple[AxisDynamics, AxisDynamics],
    gains: tuple[Gains, Gains],
    tables: tuple[CompensationTable, CompensationTable],
    radius: float,
    feed: float,
    directions: Sequence[str],
    compensate: bool,
    reversal_acceleration: float | None,
    step: Callable[[str], None],
) -> tuple[list[CircleRun], list[ReversalRun]]:
    """The circles of each direction and the x axis's reversal, each also compensated.

    The reversal runs at ``reversal_acceleration`` [m/s²], default the circle's
    :math:`v^2/R`; ``step`` is called after each run.
    """
    circles: list[CircleRun] = []
    reversals: list[ReversalRun] = []
    for d in directions:
        circles.append(circular_test(axes, gains, radius, feed, clockwise=d == "CW"))
        step(f"{d} circle")
        if compensate:
            circles.append(circular_test(axes, gains, radius, feed, clockwise=d == "CW",
                                         tables=tables))  # fmt: skip
            step(f"{d} circle, compensated")
    acc = feed**2 / radius if reversal_acceleration is None else reversal_acceleration
    reversals.append(reversal_test(axes[0], gains[0], feed, acc))
    step("reversal")
    if compensate:
        reversals.append(reversal_test(axes[0], gains[0], feed, acc, tables[0]))
        step("reversal, compensated")
    return circles, reversals


def _contour_notes(
    axes: tuple[AxisDynamics, AxisDynamics],
    gains: tuple[Gains, Gains],
    pair: tuple[Case, Case],
    circles: Sequence[CircleRun],
    *,
    one_case: bool,
    rigid: bool,
    top: float,
) -> list[str]:
    """The notes of a circular test: the axes', the loops', unsettled circles, the method.

    ``top`` [m/s] is the highest speed of the compensation tables.
    """
    notes = [f"{name}: {n}" for name, a in zip("xy", axes, strict=True) for n in a.notes]
    notes += [f"{name}: {n}" for name, g in zip("xy", gains, strict=True) for n in g.notes]
    for c in circles:
        if not c.settled:
            notes.append(f"the {'CW' if c.clockwise else 'CCW'} circle"
                         f"{' with compensation' if c.compensated else ''} had not settled: "
                         f"its following error changed by {c.residual * 1e6:.3g} um over the "
                         "evaluated revolution (a slow or poorly damped loop); G, H and the "
                         "glitches carry that transient")  # fmt: skip
    for name, case in zip("xy", pair, strict=True):
        missing = [k for k in ("rated_speed", "peak_torque") if k not in case.motor]
        if missing:
            notes.append(f"{name}: no [motor] {' or '.join(missing)} in the case: the feed's "
                         "motor speed, torque and acceleration are not checked against "
                         "it")  # fmt: skip
    if one_case:
        notes.append("one case for both axes")
    if rigid:
        notes.append("rigid axes (one mass each): no lost motion between motor and table")
    notes.append(f"compensation: the {TABLE_POINTS}-point table of each axis' friction up to "
                 f"{top:.4g} m/s, looked up at the commanded velocity and applied "
                 f"{COMPENSATION_DELAY} sample later, as a controller does")  # fmt: skip
    notes.append(f"circle: a lead-in arc of {LEAD_IN_TIME_CONSTANTS:g}/k_v "
                 f"({LEAD_IN_TIME_CONSTANTS / min(g.kv for g in gains):.3g} s) at the feed "
                 "before the evaluated revolution, so that G, H and the glitches are the "
                 "settled circle's")  # fmt: skip
    return notes
