r"""The preload over a screw's life, from a series of drag-torque measurements.

What ``ballscrew monitor`` computes. Wear lowers a ball screw's preload, and
with it the drag torque: the drag torque is how makers set the preload, and a
series of it over operating hours shows the preload going.

1. **Each measurement's preload.** A model's torque rises with the preload at
   every operating point; :func:`preload_curves` evaluates it on a grid of
   preloads at the series' operating points, and :func:`invert` reads each
   measured torque back to the preload that gives it (linear interpolation
   between grid preloads, one vectorised search for all points).
2. **The trend**, monotone by construction: an exponential decay
   :math:`F(t) = F_0e^{bt}` (a straight line in :math:`\ln F`) or a straight
   line :math:`F(t) = F_0 + bt`, fitted by ordinary least squares, with
   Student-t 95 % intervals of the mean trend and, for each point, of one
   measurement (the prediction interval, from the residual scatter).
3. **The threshold crossing**: the time at which the trend reaches a
   preload the user gives (a force, a share of the initial preload, or the
   preload below which a working load lifts a half-nut off,
   :math:`F_a/2^{3/2}`), with the inverse-regression interval: the times at
   which the trend's 95 % band contains the threshold, found on a grid and
   refined by Brent's method (Draper & Smith,
   Applied Regression Analysis, 3rd ed. 1998, §3.2, the "inverse
   prediction" interval). It may be open-ended when the data cannot
   exclude late times.

The model's level carries its own uncertainty: the preloads are those of the
model, and their trend is what a series measures best. A share of the initial
preload does not depend on that level; **an absolute threshold** (a force, a
lift-off) does, so its crossing interval adds the level's uncertainty to the
trend's band (in quadrature, 95 %): the model's error from the scorecard
(:func:`ballscrew.axis.uncertainty.model_error`, a standard uncertainty of
:math:`\ln T`) divided by the torque's elasticity to the preload at the
series' start, :math:`\partial\ln T/\partial\ln F`, read off the model's
curves. **A first reading** outside the case's preload by more than the
makers' drag-torque band of grade C3 at the case's catalogue torque (THK A-688
Table 13; ±25 to 45 %) gets a note: the screw, the case or the model is not
what the other two say.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from scipy.optimize import brentq
from scipy.stats import t as student_t

from ..chain import friction_torque
from ..errors import BallScrewInputError, FloatArray
from ..friction import get_model
from ..io.case import Case
from ..io.series import TorqueSeries
from ..loads import LIFT_OFF_RATIO

__all__ = [
    "MonitorResult",
    "PreloadCurves",
    "Threshold",
    "invert",
    "monitor_preload",
    "preload_curves",
    "run_monitor",
    "threshold",
]

TRENDS = ("exponential", "linear")


@dataclass(frozen=True)
class PreloadCurves:
    """The model's torque ``torque[k, i]`` [N·m] at ``preloads[k]`` [N] and point ``i``."""

    preloads: FloatArray
    torque: FloatArray
    model: str


def preload_curves(
    case: Case,
    model: str,
    series: TorqueSeries,
    *,
    preloads: FloatArray | None = None,
) -> PreloadCurves:
    """Evaluate ``model`` at every point of ``series`` for a grid of preloads.

    The grid defaults to 0 and 48 preloads spaced geometrically from 1 % to 4
    times the case's preload. The torque must rise with the preload at every
    point (else the preload cannot be read from it).
    """
    name = get_model(model).name
    base = case.screw.preload if case.screw.preload > 0.0 else 1000.0
    grid = (np.concatenate([[0.0], np.geomspace(0.01 * base, 4.0 * base, 48)])
            if preloads is None else np.asarray(preloads, dtype=float))  # fmt: skip
    first = float(np.ravel(case.temperature)[0])
    temperature = (series.temperature if series.temperature is not None
                   else np.full(series.time.shape, first))  # fmt: skip
    load = series.axial_load if series.axial_load is not None else 0.0
    rows = []
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        for f in grid:
            rows.append(friction_torque(
                case.screw.replace(preload=float(f)), case.lubricant, speed=series.speed,
                temperature=temperature, axial_load=load, model=name,
                **case.parameters_for(name),
            ).total)  # fmt: skip
    torque = np.asarray(rows, dtype=float).reshape(grid.size, -1)
    if np.any(np.diff(torque, axis=0) <= 0.0):
        raise BallScrewInputError("--model", name, "a model whose torque rises with the "
                                  "preload at the series' points")  # fmt: skip
    return PreloadCurves(grid, torque, name)


def invert(curves: PreloadCurves, torque: FloatArray) -> tuple[FloatArray, FloatArray]:
    """The preload [N] that gives each measured torque.

    Also returns a mask of the torques at or below the model's torque at the
    grid's lowest preload (0 by default): their preload is that lowest one.
    """
    t = np.asarray(torque, dtype=float)
    table = curves.torque
    k = np.clip(np.sum(table < t[None, :], axis=0), 1, table.shape[0] - 1)
    cols = np.arange(t.size)
    t0, t1 = table[k - 1, cols], table[k, cols]
    f0, f1 = curves.preloads[k - 1], curves.preloads[k]
    s = np.clip((t - t0) / (t1 - t0), 0.0, None)
    beyond = t > table[-1]
    if np.any(beyond):
        row = int(np.flatnonzero(beyond)[0])
        raise BallScrewInputError(f"measurement {row + 1}", float(t[row]),
                                  f"a torque below the model's at {curves.preloads[-1]:.4g} N "
                                  f"({float(table[-1, row]):.4g} N*m): 4 times the case's "
                                  "preload (check the torque unit)")  # fmt: skip
    below = t <= table[0]
    result: FloatArray = np.where(below, curves.preloads[0], f0 + s * (f1 - f0))
    return result, below


@dataclass(frozen=True)
class Threshold:
    """A preload threshold [N] and how it was given.

    ``share`` is its share of the initial preload (None for a force given outright).
    """

    value: float
    text: str
    share: float | None = None


def threshold(text: str, initial: float) -> Threshold:
    """Read a threshold: ``"50 %"`` (of ``initial`` [N]), ``"1.2 kN"``, ``"lift-off 3 kN"``."""
    from ..io.units import to_si

    raw = text.strip()
    if raw.endswith("%"):
        try:
            share = float(raw[:-1].strip().replace(",", "."))
        except ValueError:
            raise BallScrewInputError("--threshold", text, "e.g. '50 %', '1.2 kN' or "
                                      "'lift-off 3 kN'") from None  # fmt: skip
        if not 0.0 < share < 100.0:
            raise BallScrewInputError("--threshold", text, "a share between 0 and 100 %")
        return Threshold(share / 100.0 * initial, f"{share:g} % of the initial {initial:.4g} N",
                         share / 100.0)  # fmt: skip
    if raw.lower().startswith("lift-off"):
        load = to_si("--threshold", raw[len("lift-off") :].strip(), "N")
        value = abs(load) / LIFT_OFF_RATIO
        return Threshold(value, f"lift-off under {abs(load):.4g} N (F_a / 2^1.5 = {value:.4g} N)")
    value = to_si("--threshold", raw, "N")
    if not value > 0.0:
        raise BallScrewInputError("--threshold", text, "a positive preload")
    return Threshold(value, f"{value:.4g} N")


@dataclass
class MonitorResult:
    """Preloads, trend and threshold crossing of a series (module docstring).

    ``preload`` [N] per measurement with ``preload_low``/``preload_high`` (95 %
    prediction interval); ``trend``, ``trend_low``, ``trend_high`` [N] the mean
    trend and its 95 % band at ``time`` [h]; ``intercept`` and ``slope`` in the
    trend's space (ln N and 1/h, or N and N/h); ``crossing`` [h] with
    ``crossing_low``/``crossing_high`` (inf: not excluded).
    """

    series: TorqueSeries
    model: str
    trend_kind: str
    preload: FloatArray
    preload_low: FloatArray
    preload_high: FloatArray
    trend: FloatArray
    trend_low: FloatArray
    trend_high: FloatArray
    intercept: float
    slope: float
    residual_sd: float
    limit: Threshold | None
    crossing: float
    crossing_low: float
    crossing_high: float
    notes: list[str] = field(default_factory=list)
    level_sd: float = 0.0
    """Standard uncertainty of the model's preload level, in ln N (absolute thresholds)."""

    def band(self, time: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
        """The trend and its 95 % band [N] at ``time`` [h]."""
        return _band(self, np.asarray(time, dtype=float))

    def as_dict(self) -> dict[str, Any]:
        """The JSON document of ``ballscrew monitor`` (the writer adds the version)."""
        rows = [{"time_h": float(a), "torque_Nm": float(b), "preload_N": float(c),
                 "preload_low_N": float(d), "preload_high_N": float(e),
                 "trend_N": float(f), "trend_low_N": float(g), "trend_high_N": float(h)}
                for a, b, c, d, e, f, g, h in zip(
                    self.series.time, self.series.torque, self.preload, self.preload_low,
                    self.preload_high, self.trend, self.trend_low, self.trend_high,
                    strict=True)]  # fmt: skip
        unit = "1/h" if self.trend_kind == "exponential" else "N/h"
        return {
            "source": self.series.source, "model": self.model,
            "trend": {"kind": self.trend_kind,
                      "initial_preload_N": _value(self.trend_kind, self.intercept),
                      "slope": {"value": self.slope, "unit": unit},
                      "residual_sd": self.residual_sd},
            "threshold": None if self.limit is None else {
                "preload_N": self.limit.value, "given": self.limit.text,
                "crossing_h": self.crossing, "crossing_low_h": self.crossing_low,
                "crossing_high_h": self.crossing_high, "level_sd_ln": self.level_sd},
            "points": rows, "notes": list(self.notes),
        }  # fmt: skip


def _value(kind: str, y: FloatArray | float) -> Any:
    return np.exp(y) if kind == "exponential" else y


def _band(r: MonitorResult, time: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
    y, half = _mean_band(r.series.time, r.intercept, r.slope, r.residual_sd, time)
    return (_value(r.trend_kind, y), _value(r.trend_kind, y - half),
            _value(r.trend_kind, y + half))  # fmt: skip


def _mean_band(
    t_data: FloatArray, a: float, b: float, sd: float, time: FloatArray
) -> tuple[FloatArray, FloatArray]:
    """OLS mean line a + b t and its 95 % half-width at ``time``."""
    n = t_data.size
    q = float(student_t.ppf(0.975, n - 2))
    centre = float(np.mean(t_data))
    sxx = float(np.sum((t_data - centre) ** 2))
    half = q * sd * np.sqrt(1.0 / n + (time - centre) ** 2 / sxx)
    return a + b * time, half


def run_monitor(
    case: Case,
    series: TorqueSeries,
    *,
    model: str = "complete",
    trend: str = "exponential",
    limit: str | None = None,
    curves: PreloadCurves | None = None,
) -> MonitorResult:
    """Preload per measurement, its trend and the threshold crossing (module docstring).

    Parameters
    ----------
    case : Case
        The screw (its preload sets the grid), lubricant and model parameters.
    series : TorqueSeries
        The measurements.
    model : str
        The friction model that reads torque as preload.
    trend : {"exponential", "linear"}
        The trend's form.
    limit : str, optional
        Threshold text (:func:`threshold`); its share refers to the trend's
        initial preload.
    curves : PreloadCurves, optional
        Precomputed :func:`preload_curves` for this series (else computed).
    """
    if trend not in TRENDS:
        raise BallScrewInputError("--trend", trend, " or ".join(TRENDS))
    n = series.time.size
    if n < 3:
        raise BallScrewInputError(
            series.source, f"{n} measurement(s)",
            "at least 3 measurements for a trend with an interval")  # fmt: skip
    curves = curves or preload_curves(case, model, series)
    preload, below = invert(curves, series.torque)
    notes = []
    if np.any(below):
        rows = ", ".join(str(i + 1) for i in np.flatnonzero(below))
        if trend == "exponential":
            raise BallScrewInputError(
                f"{series.source}: measurement(s) {rows}", series.torque[below].tolist(),
                "torques above the model's torque without preload: the preload is gone "
                "there (use --trend linear to keep these points at zero preload)")  # fmt: skip
        notes.append(f"measurement(s) {rows}: torque at or below the model's without preload; "
                     "read as zero preload")  # fmt: skip
    y = np.log(preload) if trend == "exponential" else preload
    b, a = np.polyfit(series.time, y, 1)
    resid = y - (a + b * series.time)
    sd = float(math.sqrt(np.sum(resid**2) / (n - 2)))
    q = float(student_t.ppf(0.975, n - 2))
    result = MonitorResult(
        series, curves.model, trend, preload, _value(trend, y - q * sd), _value(trend, y + q * sd),
        np.zeros(n), np.zeros(n), np.zeros(n), float(a), float(b), sd, None,
        math.nan, math.nan, math.nan, notes,
    )  # fmt: skip
    result.trend, result.trend_low, result.trend_high = result.band(series.time)
    if b >= 0.0:
        notes.append("the preload does not fall over the series: no crossing time")
    _first_reading(case, result)
    if limit is not None:
        result.limit = threshold(limit, float(_value(trend, a)))
        if result.limit.share is None:
            result.level_sd = _level_sd(case, curves, series, preload, notes)
        _crossing(result)
    if n < 6:
        notes.append(f"{n} measurements: the intervals are wide (t quantile {q:.3g})")
    return result


def monitor_preload(*args: Any, **kwargs: Any) -> MonitorResult:
    """The former name of :func:`run_monitor` (for one release; it warns)."""
    warnings.warn(
        "ballscrew.fit.monitor.monitor_preload is now run_monitor (also ballscrew.fit."
        "run_monitor); the old name goes in the next release",
        DeprecationWarning,
        stacklevel=2,
    )
    return run_monitor(*args, **kwargs)


def _with_level(r: MonitorResult, y: FloatArray, half: FloatArray) -> tuple[FloatArray, FloatArray]:
    """The trend's 95 % half-width with the model level's 95 % added in quadrature."""
    if r.level_sd <= 0.0:
        return y, half
    # ln F for the exponential trend; F itself for the linear one (first order: F sigma).
    level = 1.96 * r.level_sd * (1.0 if r.trend_kind == "exponential" else np.abs(y))
    return y, np.sqrt(half**2 + level**2)


def _first_reading(case: Case, r: MonitorResult) -> None:
    """A note when the first preload lies outside the case's by more than the makers' band."""
    from ..design.catalog_formulas import (
        DRAG_TORQUE_TOLERANCE,
        drag_torque_tolerance,
        preload_torque,
    )

    screw = case.screw
    if screw.preload <= 0.0:
        return
    rows = DRAG_TORQUE_TOLERANCE["C3"]
    torque = float(preload_torque(screw.preload, screw.lead, screw.lead_angle))
    band = drag_torque_tolerance(min(max(torque, rows[0][0]), rows[-1][1]))[2]
    first = float(r.preload[0])
    if abs(first / screw.preload - 1.0) > band:
        r.notes.append(
            f"the first reading gives {first:.4g} N, {first / screw.preload - 1.0:+.0%} from the "
            f"case's preload {screw.preload:.4g} N, outside the makers' band of +-{band:.0%} "
            f"(C3 at {torque:.3g} N*m, THK A-688 Table 13): check the case's preload, the "
            "screw, or the model's level"
        )


def _level_sd(
    case: Case, curves: PreloadCurves, series: TorqueSeries, preload: FloatArray,
    notes: list[str],
) -> float:  # fmt: skip
    """The model level's standard uncertainty in ln of the preload read (module docstring)."""
    from ..axis.uncertainty import model_error

    error = model_error(curves.model, case.screw.nut, float(series.torque[0]))
    # The preloads read here are the model's own, not corrected for its bias: the bias
    # counts as error, in quadrature with the spread.
    sigma, origin = math.hypot(error.sigma, error.bias), error.text
    if math.isnan(sigma):
        notes.append(origin + ": the crossing's interval leaves the level out")
        return 0.0
    # Elasticity d ln T / d ln F at the first reading, from the model's curves.
    f0 = float(preload[0])
    k = int(np.clip(np.searchsorted(curves.preloads, f0), 2, curves.preloads.size - 1))
    lo, hi = curves.preloads[k - 1], curves.preloads[k]
    t_lo, t_hi = curves.torque[k - 1, 0], curves.torque[k, 0]
    slope = math.log(t_hi / t_lo) / math.log(hi / lo)
    level = sigma / slope
    notes.append(f"an absolute threshold depends on the model's level: {origin}; over the "
                 f"torque's elasticity to the preload {slope:.3g}, sigma(ln F) = {level:.3g}, "
                 "added to the crossing's interval")  # fmt: skip
    return float(level)


def _crossing(r: MonitorResult) -> None:
    """The threshold crossing time and its inverse-regression interval, in place."""
    assert r.limit is not None
    y_th = math.log(r.limit.value) if r.trend_kind == "exponential" else r.limit.value
    if r.slope < 0.0:
        r.crossing = (y_th - r.intercept) / r.slope
        if r.crossing < r.series.time[0]:
            r.notes.append(f"the trend is below the threshold from the first measurement on "
                           f"(extrapolated back, it crossed at {r.crossing:.0f} h)")  # fmt: skip
        elif r.crossing > r.series.time[-1]:
            r.notes.append(f"the crossing at {r.crossing:.0f} h is extrapolated beyond the series")
    if r.limit.share is not None and r.trend_kind == "exponential":
        # A share of the initial preload is reached at ln(share)/b whatever F_0 is: the
        # interval is the slope's (its 95 % t interval), not the band's.
        t = r.series.time
        se = r.residual_sd / math.sqrt(float(np.sum((t - np.mean(t)) ** 2)))
        q = float(student_t.ppf(0.975, t.size - 2))
        lo, hi = r.slope - q * se, r.slope + q * se
        share = math.log(r.limit.share)
        r.crossing_low = share / lo if lo < 0.0 else math.inf
        r.crossing_high = share / hi if hi < 0.0 else math.inf
        r.crossing_low, r.crossing_high = sorted((r.crossing_low, r.crossing_high))
        return
    span = float(r.series.time[-1] - r.series.time[0])
    grid = np.linspace(r.series.time[0] - span, r.series.time[-1] + 20.0 * span, 40001)
    y, half = _with_level(r, *_mean_band(r.series.time, r.intercept, r.slope, r.residual_sd,
                                         grid))  # fmt: skip
    inside = np.abs(y - y_th) <= half
    if not np.any(inside):
        r.crossing_low = r.crossing_high = math.nan
        return
    idx = np.flatnonzero(inside)

    def edge(t: float) -> float:  # the band's edge crosses the threshold where this is 0
        mean, half_width = _with_level(r, *_mean_band(
            r.series.time, r.intercept, r.slope, r.residual_sd, np.array([t])))  # fmt: skip
        return float(abs(mean[0] - y_th) - half_width[0])

    # Each edge found on the grid is refined to the root between its two nodes.
    r.crossing_low = (brentq(edge, grid[idx[0] - 1], grid[idx[0]], xtol=1e-9)
                      if idx[0] > 0 else -math.inf)  # fmt: skip
    r.crossing_high = (brentq(edge, grid[idx[-1]], grid[idx[-1] + 1], xtol=1e-9)
                       if idx[-1] < grid.size - 1 else math.inf)  # fmt: skip
