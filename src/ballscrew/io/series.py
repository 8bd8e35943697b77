"""Series of drag-torque measurements over a screw's life (units in the header).

A series is a CSV file like a measured curve (:mod:`ballscrew.io.measured`),
one row per measurement, with a time column (any time unit: ``time [h]``,
``operating hours [h]``, ``days [d]``) and a torque column; speed,
temperature and axial load columns are optional::

    time [h],torque [N*m],speed [rpm],temperature [degC]
    0,0.55,100,24
    500,0.53,100,25

Times must increase from row to row. Without a speed column every
measurement is taken at 100 rpm (the speed makers measure the preload drag
torque at); without a temperature column at the case's first temperature.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import BallScrewInputError, FloatArray
from ..geometry import BallScrew
from .files import read_input_text
from .measured import _HEADER, _csv_rows, _dimension, _numbers, _screw_speed
from .units import parse_unit, to_si_array

__all__ = ["TorqueSeries", "parse_series", "read_series"]

CATALOGUE_SPEED = 100.0 * 2.0 * math.pi / 60.0
"""The speed at which makers measure the preload drag torque, 100 rpm [rad/s]."""


@dataclass(frozen=True)
class TorqueSeries:
    """Drag torques over time.

    ``time`` [h], ``torque`` [N·m] (magnitudes), ``speed`` [rad/s],
    ``temperature`` [°C] (None: the case's), ``axial_load`` [N] (None: 0).
    """

    time: FloatArray
    torque: FloatArray
    speed: FloatArray
    source: str
    temperature: FloatArray | None = None
    axial_load: FloatArray | None = None


def _columns(header: list[str], source: str) -> dict[str, tuple[int, str]]:
    columns: dict[str, tuple[int, str]] = {}
    for i, cell in enumerate(header):
        match = _HEADER.match(cell)
        if not match:
            continue
        unit = match.group("unit").strip()
        kind = _dimension(unit)
        if kind == "other" and "time" not in columns:
            try:
                if parse_unit("unit", unit).is_compatible_with("s"):
                    columns["time"] = (i, unit)
                    continue
            except BallScrewInputError:
                pass
        if kind in ("angular", "linear") and "speed" not in columns:
            columns["speed"] = (i, unit)
            columns["speed_kind"] = (i, kind)
        elif kind in ("torque", "temperature", "force") and kind not in columns:
            columns[kind] = (i, unit)
    for key, example in (("time", "'time [h]'"), ("torque", "'torque [N*m]'")):
        if key not in columns:
            raise BallScrewInputError(f"{source}: header", ",".join(header),
                                      f"a {key} column with its unit, e.g. {example}")  # fmt: skip
    return columns


def parse_series(text: str, screw: BallScrew, source: str = "series") -> TorqueSeries:
    """Parse a torque series from CSV text (module docstring)."""
    rows, delimiter = _csv_rows(text, source)
    header = rows[0]
    columns = _columns(header, source)
    values = _numbers(rows, columns, delimiter, source)

    def si(key: str, unit: str) -> FloatArray:
        i, given = columns[key]
        field = f"{source}: column '{header[i].strip()}'"
        return np.asarray(to_si_array(field, values[key], given, unit), dtype=float)

    time = si("time", "hour")
    back = np.flatnonzero(np.diff(time) <= 0.0)
    if back.size:
        line = int(back[0]) + 3  # the header is line 1, the first row line 2
        raise BallScrewInputError(f"{source}: line {line}, column "
                                  f"'{header[columns['time'][0]].strip()}'",
                                  float(values["time"][line - 2]),
                                  "times that increase from row to row")  # fmt: skip
    if "speed" in columns:
        speed = np.abs(_screw_speed(values["speed"], columns, header, screw, source))
    else:
        speed = np.full(time.shape, CATALOGUE_SPEED)
    return TorqueSeries(
        time=time, torque=np.abs(si("torque", "N*m")), speed=np.asarray(speed, dtype=float),
        source=source, temperature=si("temperature", "degC") if "temperature" in columns else None,
        axial_load=si("force", "N") if "force" in columns else None,
    )  # fmt: skip


def read_series(path: str | Path, screw: BallScrew) -> TorqueSeries:
    """Read a torque series from a CSV file (module docstring)."""
    file = Path(path)
    text = read_input_text("--measured", file)
    return parse_series(text, screw, source=str(file))
