r"""Friction compensation tables with few points: the breakpoints that interpolate best.

A controller's friction table is piecewise linear in the speed with a fixed
number of points (LinuxCNC's ``lincurve`` 16, TwinCAT CNC's ``frict_comp`` 20,
CODESYS' ``CHARCURVE`` 11). The friction curve jumps at zero speed and bends
most at low speed, so equal spacing wastes points. :func:`fit_table` chooses
them:

* for given breakpoints, the values are the linear least-squares fit of the
  piecewise-linear interpolant (hat functions) to the curve on a fine grid;
* the breakpoints minimise that fit's RMS error over the speed range (a
  grid uniform in speed, both directions), by Nelder–Mead over the
  logarithms of their spacings (the last one is the range's end);
* the speeds are mirrored (the same breakpoints both ways), the values are
  fitted for each direction; a table of one side (``one_sided``, TwinCAT)
  fits the mean of both directions' magnitudes, with a first point at speed
  0 carrying the slowest speed's friction.

The error is the table against the model's curve, RMS and largest, over the
range; the controller clamps beyond the last point.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from ..errors import BallScrewInputError, FloatArray

__all__ = ["CompensationTable", "fit_table", "relative_error", "target_curve"]

GRID = 801
"""Points per direction of the grid the error is measured on."""


@dataclass(frozen=True)
class CompensationTable:
    """A piecewise-linear friction table: ``speed`` [m/s] ascending, ``force`` [N] table side."""

    speed: FloatArray
    force: FloatArray
    rms_error: float
    max_error: float
    speed_range: float
    one_sided: bool = False

    def __call__(self, v: npt.ArrayLike) -> FloatArray:
        """The table's force [N] at table speeds ``v`` [m/s], clamped at the ends.

        A one-sided table gives the magnitude at :math:`|v|`, signed like v.
        """
        w = np.asarray(v, dtype=float)
        if self.one_sided:
            out: FloatArray = np.sign(w) * np.interp(np.abs(w), self.speed, self.force)
            return out
        return np.asarray(np.interp(w, self.speed, self.force), dtype=float)

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready table."""
        return {"speed_m_s": self.speed.tolist(), "force_N": self.force.tolist(),
                "rms_error_N": self.rms_error, "max_error_N": self.max_error,
                "speed_range_m_s": self.speed_range, "one_sided": self.one_sided}  # fmt: skip


def target_curve(speeds: FloatArray, friction: FloatArray, v: FloatArray) -> FloatArray:
    """The map's friction [N] at signed speeds ``v``.

    Each direction is interpolated on its own and held at its slowest value towards zero.
    """
    pos, neg = speeds > 0.0, speeds < 0.0
    up = np.interp(np.abs(v), speeds[pos], np.abs(friction[pos]))
    down = np.interp(np.abs(v), -speeds[neg][::-1], np.abs(friction[neg][::-1]))
    out: FloatArray = np.where(v > 0.0, up, np.where(v < 0.0, -down, 0.0))
    return out


def _hat(knots: FloatArray, v: FloatArray) -> FloatArray:
    """Hat-function basis of the interpolant on ``knots`` at ``v`` (clamped ends)."""
    basis = np.zeros((v.size, knots.size))
    vv = np.clip(v, knots[0], knots[-1])
    j = np.clip(np.searchsorted(knots, vv, side="right") - 1, 0, knots.size - 2)
    s = (vv - knots[j]) / (knots[j + 1] - knots[j])
    rows = np.arange(v.size)
    basis[rows, j] = 1.0 - s
    basis[rows, j + 1] = s
    return basis


def fit_table(
    speeds: npt.ArrayLike,
    friction: npt.ArrayLike,
    points: int,
    speed_range: float,
    *,
    one_sided: bool = False,
    zero_point: bool = False,
) -> CompensationTable:
    """The ``points``-point table that fits the friction map best over ``speed_range`` [m/s].

    Parameters
    ----------
    speeds, friction : array_like
        The map: signed table speeds [m/s] ascending, friction [N] signed like them.
    points : int
        Points of the table (both directions together, or one side's with ``one_sided``).
    speed_range : float
        Fastest speed of the table [m/s].
    one_sided : bool
        Speeds >= 0 only (the controller applies the sign).
    zero_point : bool
        Put a point at speed 0 with force 0 (an odd count of mirrored points).
    """
    w = np.asarray(speeds, dtype=float)
    f = np.asarray(friction, dtype=float)
    vmax = float(speed_range)
    if not vmax > 0.0:
        raise BallScrewInputError("speed range", vmax, "a positive speed [m/s]")
    side = points - 1 if one_sided else (points - 1 if zero_point else points) // 2
    if side < 2 or (not one_sided and not zero_point and points % 2):
        raise BallScrewInputError("points", points, "at least 4 (an even count without a "
                                  "zero point, an odd count with one)")  # fmt: skip
    grid = np.linspace(vmax / GRID, vmax, GRID)
    if one_sided:
        target = 0.5 * (target_curve(w, f, grid) - target_curve(w, f, -grid))
        v = grid
    else:
        v = np.concatenate([-grid[::-1], grid])
        target = target_curve(w, f, v)

    def knots(q: FloatArray) -> FloatArray:
        d = np.exp(np.concatenate([q, [0.0]]))
        p = vmax * np.cumsum(d) / np.sum(d)
        if one_sided:
            return np.concatenate([[0.0], p])
        middle = [0.0] if zero_point else []
        return np.concatenate([-p[::-1], middle, p])

    def solve(q: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
        k = knots(q)
        basis = _hat(k, v)
        if zero_point and not one_sided:
            mid = side
            free = np.delete(np.arange(k.size), mid)
            y = np.zeros(k.size)
            y[free] = np.linalg.lstsq(basis[:, free], target, rcond=None)[0]
        else:
            y = np.asarray(np.linalg.lstsq(basis, target, rcond=None)[0], dtype=float)
        return k, y, basis @ y - target

    def cost(q: FloatArray) -> float:
        return float(np.sqrt(np.mean(solve(q)[2] ** 2)))

    from scipy.optimize import minimize

    # Start: geometric spacing from 1e-3 of the range (the steep part near zero).
    start = np.log(np.diff(np.concatenate([[0.0], np.geomspace(1e-3, 1.0, side)])))
    start = start[:-1] - start[-1]
    best = minimize(cost, start, method="Nelder-Mead",
                    options={"maxiter": 150 * side, "xatol": 1e-4, "fatol": 1e-9})  # fmt: skip
    k, y, resid = solve(best.x)
    if one_sided:
        y[0] = float(target[0])  # breakaway: the slowest speed's friction at rest
        resid = np.asarray(_hat(k, v) @ y - target, dtype=float)
    return CompensationTable(k, y, float(np.sqrt(np.mean(resid**2))),
                             float(np.max(np.abs(resid))), vmax, one_sided)  # fmt: skip


def relative_error(table: CompensationTable) -> float:
    """RMS error over the table's largest force [-]."""
    return table.rms_error / max(float(np.max(np.abs(table.force))), 1e-300)
