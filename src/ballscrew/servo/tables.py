r"""Friction compensation tables with few points: the breakpoints that interpolate best.

A controller's friction table is piecewise linear in the speed with a fixed
number of points (LinuxCNC's ``lincurve`` 16, TwinCAT CNC's ``frict_comp`` 20,
CODESYS' ``CHARCURVE`` 11). The friction curve jumps at zero speed and bends
most at low speed, so equal spacing wastes points. :func:`fit_table` chooses
them:

* for given breakpoints, the values are the linear least-squares fit of the
  piecewise-linear interpolant (hat functions) to the curve on a fine grid;
* the breakpoints minimise that fit's RMS error over the speed range (a
  grid uniform in speed, both directions, from 1/:data:`GRID` of the range),
  by Nelder–Mead over the logarithms of their spacings; the first breakpoint
  is the grid's slowest speed (the table changes sign between it and its
  mirror) and the last the range's end;
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
from ..io.case import Case

__all__ = [
    "CONTROLLERS",
    "CompensationTable",
    "ControllerTable",
    "DriveUnit",
    "controller_table",
    "fit_table",
    "relative_error",
    "target_curve",
]

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
    if side < 2 or (not one_sided and (points % 2 == 1) != zero_point):
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
        # The first positive knot is the grid's slowest speed (the table changes sign, or
        # starts, there); the others split the rest of the range by the spacings exp(q).
        # Spacings of at least one grid step, so that every value is seen by the grid.
        d = np.exp(np.concatenate([q, [0.0]]))
        step = grid[1] - grid[0]
        free = vmax - grid[0] - d.size * step
        p = np.concatenate([[grid[0]], grid[0] + step * np.arange(1, d.size + 1)
                            + free * np.cumsum(d) / np.sum(d)])  # fmt: skip
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

    # Start: geometric spacing (the curve bends most near zero speed).
    start = np.log(np.diff(np.geomspace(grid[0], vmax, side)))
    start = start[:-1] - start[-1]
    if start.size:
        options = {"maxiter": 150 * side, "xatol": 1e-4, "fatol": 1e-9}
        start = minimize(cost, start, method="Nelder-Mead", options=options).x
    k, y, resid = solve(start)
    if one_sided:
        y[0] = float(target[0])  # breakaway: the slowest speed's friction at rest
        resid = np.asarray(_hat(k, v) @ y - target, dtype=float)
    return CompensationTable(k, y, float(np.sqrt(np.mean(resid**2))),
                             float(np.max(np.abs(resid))), vmax, one_sided)  # fmt: skip


def relative_error(table: CompensationTable) -> float:
    """RMS error over the table's largest force [-]."""
    return table.rms_error / max(float(np.max(np.abs(table.force))), 1e-300)


CONTROLLERS: dict[str, tuple[int, bool, bool, str]] = {
    "lincurve": (16, False, False, "LinuxCNC HAL component lincurve (at most 16 points)"),
    "frict-comp": (20, True, False, "TwinCAT CNC friction compensation frict_comp (at most 20)"),
    "charcurve": (11, False, True, "CODESYS Util CHARCURVE (2 to 11 points)"),
}
"""Controller -> (points, one-sided, zero point, what it is)."""


@dataclass(frozen=True)
class DriveUnit:
    """One unit of the number a drive reports its torque in (TwinCAT's ``frict_comp`` output).

    ``value`` is one unit in N·m (``kind`` "torque") or in A (``kind`` "current");
    ``text`` is how the user gave it (e.g. "0.1 % of 3.2 N*m", "1 mA").
    """

    value: float
    kind: str
    text: str

    def __post_init__(self) -> None:
        if self.kind not in ("torque", "current"):
            raise BallScrewInputError("drive unit kind", self.kind, "'torque' or 'current'")
        if not (np.isfinite(self.value) and self.value > 0.0):
            raise BallScrewInputError("--drive-unit", self.text, "a positive torque or current")

    @classmethod
    def parse(cls, text: str, field: str = "--drive-unit") -> DriveUnit:
        """A unit as people write it: "1 mA", "0.001 N*m", or a share "0.1 % of 3.2 N*m".

        Examples
        --------
        >>> DriveUnit.parse("0.1 % of 3.2 N*m")
        DriveUnit(value=0.0032, kind='torque', text='0.1 % of 3.2 N*m')
        >>> DriveUnit.parse("1 mA").value
        0.001
        """
        from ..io.units import to_si

        share, _, base = str(text).rpartition(" of ")
        factor = to_si(field, share.strip(), "") if share else 1.0
        base = base.strip()
        try:
            value, kind = to_si(field, base, "N*m"), "torque"
        except BallScrewInputError:
            try:
                value, kind = to_si(field, base, "A"), "current"
            except BallScrewInputError:
                raise BallScrewInputError(
                    field, text, "a torque or a current, or a share of one, e.g. '0.1 % of "
                    "3.2 N*m', '1 mA' or '0.001 N*m'",
                ) from None  # fmt: skip
        return cls(round(factor * value, 15), kind, str(text))


@dataclass(frozen=True)
class ControllerTable:
    """A controller's friction table from a model at the axis load and temperature.

    ``table`` is table side (m/s, N); :meth:`motor_torque` and
    :meth:`motor_current` take it to the motor through the lead, the gear ratio
    and the torque constant.
    """

    target: str
    table: CompensationTable
    model: str
    case_title: str
    lead: float
    gear_ratio: float
    temperature: float
    axial_load: float
    torque_constant: float | None = None
    drive_unit: DriveUnit | None = None

    def motor_torque(self, force: npt.ArrayLike | None = None) -> FloatArray:
        """Motor torque [N·m] of table-side forces [N] (the table's by default)."""
        f = self.table.force if force is None else np.asarray(force, dtype=float)
        out: FloatArray = f * self.lead / (2.0 * np.pi * self.gear_ratio)
        return out

    def motor_current(self, force: npt.ArrayLike | None = None) -> FloatArray:
        """Motor current [A]: the motor torque over :math:`K_t`."""
        if self.torque_constant is None:
            raise BallScrewInputError("--torque-constant", None, "the motor's torque constant")
        out: FloatArray = self.motor_torque(force) / self.torque_constant
        return out

    def drive_values(self, force: npt.ArrayLike | None = None) -> FloatArray:
        """Table-side forces [N] (the table's by default) in the drive's units (:class:`DriveUnit`).

        A torque unit divides the motor torque; a current unit the motor current
        :math:`T/K_t`.
        """
        unit = self.drive_unit
        if unit is None:
            raise BallScrewInputError("--drive-unit", None, "the unit of the drive's torque")
        if unit.kind == "current":
            out: FloatArray = self.motor_current(force) / unit.value
            return out
        out = self.motor_torque(force) / unit.value
        return out

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready table, table side and motor side."""
        out = {"target": self.target, "model": self.model, "case": self.case_title,
               "temperature_C": self.temperature, "axial_load_N": self.axial_load,
               "lead_m": self.lead, "gear_ratio": self.gear_ratio,
               **self.table.as_dict(),
               "motor_torque_Nm": self.motor_torque().tolist()}  # fmt: skip
        if self.torque_constant is not None:
            out["torque_constant_Nm_per_A"] = self.torque_constant
            out["motor_current_A"] = self.motor_current().tolist()
        if self.drive_unit is not None:
            out["drive_unit"] = {"text": self.drive_unit.text, "kind": self.drive_unit.kind,
                                 "value_SI": self.drive_unit.value}  # fmt: skip
            out["drive_values"] = self.drive_values().tolist()
        return out


def controller_table(
    case: Case,
    model: str,
    target: str,
    *,
    speed_range: float,
    temperature: float | None = None,
    axial_load: float | None = None,
    torque_constant: float | None = None,
    drive_unit: DriveUnit | None = None,
) -> ControllerTable:
    """The friction table for ``target`` (a key of :data:`CONTROLLERS`) over ``speed_range`` [m/s].

    The model's friction at the axis load (the case's first, plus an inclined
    axis' weight) and temperature (the case's first), over table speeds from
    1e-5 m/s to ``speed_range`` both ways, reduced to the controller's points
    by :func:`fit_table`. ``frict-comp`` needs ``drive_unit`` (its output is
    in the unit the drive reports its torque in), and ``torque_constant`` [N·m/A]
    when that unit is a current.
    """
    import math
    import warnings

    from ..materials import STANDARD_GRAVITY
    from .friction_map import friction_map

    if target not in CONTROLLERS:
        raise BallScrewInputError("--form", target, f"one of {list(CONTROLLERS)}")
    points, one_sided, zero, _ = CONTROLLERS[target]
    if target == "frict-comp" and drive_unit is None:
        raise BallScrewInputError(
            "--drive-unit", None, "the unit the drive reports its torque in (TwinCAT "
            "P-COMP-00047: frict_comp.table[i].out is in the unit of dig_drv.act_torque), "
            "e.g. '0.1 % of 3.2 N*m' (CiA 402: per thousand of the rated torque), "
            "'0.1 % of 4.5 A' or '1 mA' with --torque-constant, or '0.001 N*m'",
        )  # fmt: skip
    needs_kt = target == "frict-comp" and drive_unit is not None and drive_unit.kind == "current"
    if needs_kt and not (torque_constant and torque_constant > 0.0):
        raise BallScrewInputError(
            "--torque-constant", torque_constant, "the motor's torque constant K_t, e.g. "
            f"'1.2 N*m/A' (the drive's unit {drive_unit.text!r} is a current)",  # type: ignore[union-attr]
        )  # fmt: skip
    lead = case.screw.lead
    ratio = float(case.axis.get("gear_ratio", 1.0))
    mass, incline = case.axis.get("moving_mass") or 0.0, case.axis.get("incline", 0.0)
    load = float(case.axial_load.flat[0]) if axial_load is None else float(axial_load)
    load -= mass * STANDARD_GRAVITY * math.sin(incline)
    temp = float(case.temperature.flat[0]) if temperature is None else float(temperature)
    speeds = np.geomspace(1e-5, max(speed_range, 2e-5), 48) * 2.0 * math.pi / lead
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fmap = friction_map(case, model, speeds=speeds, loads=[load], temperatures=[temp])
    table = fit_table(fmap.table_speeds, fmap.force[0, 0, :], points, speed_range,
                      one_sided=one_sided, zero_point=zero)  # fmt: skip
    return ControllerTable(target, table, fmap.model, case.title, lead, ratio, temp, load,
                           torque_constant, drive_unit)  # fmt: skip
