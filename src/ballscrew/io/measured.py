"""Measured torque-speed curves: reading them (units in the header) and error metrics.

A measured curve is a CSV file with a header naming each column and its unit
in brackets; the separator may be a comma, or a semicolon or tab with decimal
commas (as spreadsheets write them in decimal-comma locales), for example::

    speed [rpm],torque [N*m]
    100,0.31
    500,0.36

The speed column may be the screw's angular speed (any unit pint converts to
rad/s: ``rpm``, ``rad/s``) or the table's linear speed (``m/s``, ``mm/s``),
which is turned into screw speed with the screw's lead; its sign is the
direction of rotation. The torque column needs a unit convertible to N·m.
Torques are taken as magnitudes (friction opposes the motion in either
direction). Optional columns hold each point's lubricant temperature (a
temperature unit: ``temperature [degC]``) and axial load (a force unit:
``axial load [N]``), for curves measured at several temperatures or loads.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import numpy.typing as npt

from ..errors import BallScrewInputError, FloatArray
from ..geometry import BallScrew
from .files import csv_rows, read_input_text
from .units import parse_unit, to_si_array

__all__ = ["MeasuredCurve", "error_metrics", "parse_measured", "read_measured"]

_DECIMAL_COMMA = re.compile(r"^[-+]?\d*,\d+(?:[eE][-+]?\d+)?$|^[-+]?\d+,$")
_HEADER = re.compile(r"^\s*(?P<name>[^\[\]]+?)\s*\[(?P<unit>[^\[\]]+)\]\s*$")


@dataclass(frozen=True)
class MeasuredCurve:
    """A measured friction characteristic.

    Attributes
    ----------
    speed : numpy.ndarray
        Screw speed [rad/s].
    torque : numpy.ndarray
        Friction torque magnitude [N·m].
    source : str
        Where it was read from.
    temperature : numpy.ndarray or None
        Lubricant temperature of each point [°C], if the file gives it.
    axial_load : numpy.ndarray or None
        Axial load of each point [N], if the file gives it.
    """

    speed: FloatArray
    torque: FloatArray
    source: str
    temperature: FloatArray | None = None
    axial_load: FloatArray | None = None


def _dimension(unit: str) -> str:
    """What a column's unit measures; a frequency (1/min, Hz) is a screw speed in revolutions."""
    try:
        parsed = parse_unit("unit", unit)
    except BallScrewInputError:
        return "unknown"
    if parsed.is_compatible_with("K"):
        return "temperature"
    for kind, ref in (("angular", "rad/s"), ("linear", "m/s"), ("torque", "N*m"), ("force", "N")):
        if parsed.is_compatible_with(ref):
            return kind
    return "other"


def parse_measured(text: str, screw: BallScrew, source: str = "measured data") -> MeasuredCurve:
    """Parse a measured curve from CSV text (see the module docstring)."""
    rows, delimiter = _csv_rows(text, source)
    header = rows[0]
    columns = _header_columns(header, source)
    if len(rows) < 2:
        raise BallScrewInputError(source, "(no data rows)", "at least one data row")
    values = _numbers(rows, columns, delimiter, source)

    def si(key: str, unit: str) -> FloatArray:
        i, given = columns[key]
        field = f"{source}: column '{header[i].strip()}'"
        return np.asarray(to_si_array(field, values[key], given, unit), dtype=float)

    speed = _screw_speed(values["speed"], columns, header, screw, source)
    torque = np.abs(si("torque", "N*m"))
    _within(torque, MOST_TORQUE, "N*m", header[columns["torque"][0]], source)
    temperature = None
    if "temperature" in columns:
        temperature = si("temperature", "degC")
        if np.any(temperature <= -273.15):
            raise BallScrewInputError(
                f"{source}: column '{header[columns['temperature'][0]].strip()}'",
                float(np.min(temperature)),
                "temperatures above absolute zero (check the unit)",
            )
    load = si("force", "N") if "force" in columns else None
    return MeasuredCurve(
        speed=np.asarray(speed, dtype=float),
        torque=np.asarray(torque, dtype=float),
        source=source,
        temperature=temperature,
        axial_load=load,
    )


MOST_TORQUE = 1e5
"""The largest drag torque a measured file may hold [N·m]: a hundred times the largest
ball screw's; past it the column's unit is wrong (or the cell is a slip such as 1e308)."""


def _within(values: FloatArray, most: float, unit: str, column: str, source: str) -> None:
    """Refuse the first value of a column past ``most`` (in SI), naming its line as read."""
    over = np.flatnonzero(~(np.abs(values) <= most))
    if over.size:
        raise BallScrewInputError(
            f"{source}: line {int(over[0]) + 2}, column '{column.strip()}'",
            f"{float(values[over[0]]):.6g} {unit}",
            f"at most {most:g} {unit} in magnitude for a ball screw (check the column's unit)",
        )


def _csv_rows(text: str, source: str) -> tuple[list[list[str]], str]:
    """The non-blank rows of the CSV text (at least the header), and its separator."""
    # The separator is the header's: a semicolon or a tab (spreadsheets in
    # decimal-comma locales), else a comma.
    rows, delimiter = csv_rows(text, source)
    rows = [r for r in rows if any(cell.strip() for cell in r)]
    if delimiter == "," and rows:
        wide = next((i for i, r in enumerate(rows[1:], start=2) if len(r) > len(rows[0])), None)
        if wide is not None:
            raise BallScrewInputError(
                f"{source}: line {wide}",
                ",".join(rows[wide - 1]),
                f"{len(rows[0])} comma-separated cells like the header; decimal commas need "
                "';' (or tab) as the separator",
            )
    if not rows:
        raise BallScrewInputError(source, "(empty)", "a CSV file with a header and data rows")
    return rows, delimiter


def _header_columns(header: list[str], source: str) -> dict[str, tuple[int, str]]:
    """Index and unit of each known column; ``speed_kind`` holds angular or linear."""
    columns: dict[str, tuple[int, str]] = {}
    for i, cell in enumerate(header):
        match = _HEADER.match(cell)
        if not match:
            continue
        kind = _dimension(match.group("unit").strip())
        if kind in ("angular", "linear") and "speed" not in columns:
            columns["speed"] = (i, match.group("unit").strip())
            columns["speed_kind"] = (i, kind)
        elif kind in ("torque", "temperature", "force") and kind not in columns:
            columns[kind] = (i, match.group("unit").strip())
    if "speed" not in columns:
        raise BallScrewInputError(
            f"{source}: header",
            ",".join(header),
            "a speed column with its unit, e.g. 'speed [rpm]', 'speed [rad/s]' or "
            "'table speed [mm/s]'",
        )
    if "torque" not in columns:
        raise BallScrewInputError(
            f"{source}: header",
            ",".join(header),
            "a torque column with its unit, e.g. 'torque [N*m]'",
        )
    return columns


def _numbers(
    rows: list[list[str]], columns: dict[str, tuple[int, str]], delimiter: str, source: str
) -> dict[str, list[float]]:
    """The data rows' numbers, by column key, in the file's units."""
    header = rows[0]
    keys = [k for k in ("time", "speed", "torque", "temperature", "force") if k in columns]
    values: dict[str, list[float]] = {k: [] for k in keys}
    for line, row in enumerate(rows[1:], start=2):
        for key in keys:
            col = columns[key][0]
            cell = row[col].strip() if col < len(row) else ""
            if delimiter != "," and _DECIMAL_COMMA.match(cell):
                cell = cell.replace(",", ".")
            try:
                number = float(cell)
            except ValueError:
                raise BallScrewInputError(
                    f"{source}: line {line}, column '{header[col].strip()}'", cell, "a number"
                ) from None
            if not math.isfinite(number):
                raise BallScrewInputError(
                    f"{source}: line {line}, column '{header[col].strip()}'",
                    cell,
                    "a finite number",
                )
            values[key].append(number)
    return values


def _screw_speed(
    numbers: list[float], columns: dict[str, tuple[int, str]], header: list[str],
    screw: BallScrew, source: str,
) -> FloatArray:  # fmt: skip
    """The speed column as screw speed [rad/s] (a table speed through the lead)."""
    i, speed_unit = columns["speed"]
    field = f"{source}: column '{header[i].strip()}'"
    if columns["speed_kind"][1] == "linear":
        table = to_si_array(field, numbers, speed_unit, "m/s")
        speed = np.asarray(table) * (2.0 * math.pi / screw.lead)
    else:
        speed = np.asarray(to_si_array(field, numbers, speed_unit, "rad/s"))
    if np.any(np.abs(speed) > 1e5):
        k = int(np.argmax(np.abs(speed)))  # named as typed, in the column's unit
        raise BallScrewInputError(
            f"{source}: column '{header[columns['speed'][0]].strip()}'",
            f"{numbers[k]:g} {speed_unit} (data row {k + 1})",
            "speeds below 1e5 rad/s (about 1e6 rpm)",
        )
    return speed


def read_measured(path: str | Path, screw: BallScrew) -> MeasuredCurve:
    """Read a measured curve from a CSV file (see the module docstring)."""
    file = Path(path)
    text = read_input_text("measured", file)
    return parse_measured(text, screw, source=str(file))


def error_metrics(model: npt.ArrayLike, measured: npt.ArrayLike) -> dict[str, float]:
    """RMSE [N·m], mean and maximum relative error [-] of a model against measurements.

    Relative errors are :math:`(T_{model} - T_{meas})/T_{meas}`; the mean is of
    their magnitudes. Points with zero measured torque are left out of the
    relative errors.

    Examples
    --------
    >>> m = error_metrics([1.0, 2.2], [1.0, 2.0])
    >>> round(m["rmse"], 4), round(m["mean_relative"], 3), round(m["max_relative"], 3)
    (0.1414, 0.05, 0.1)
    """
    mod = np.asarray(model, dtype=float)
    meas = np.asarray(measured, dtype=float)
    rmse = float(np.sqrt(np.mean((mod - meas) ** 2)))
    nonzero = meas != 0.0
    rel = np.abs(mod[nonzero] - meas[nonzero]) / np.abs(meas[nonzero])
    return {
        "rmse": rmse,
        "mean_relative": float(np.mean(rel)) if rel.size else math.nan,
        "max_relative": float(np.max(rel)) if rel.size else math.nan,
    }
