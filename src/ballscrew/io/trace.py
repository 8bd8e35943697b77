r"""Drive traces: time, and per axis the position and the current, torque or power, as measured.

A trace is a table of samples with one column per signal, each column named
with its axis letter, its quantity and its unit in brackets::

    time [s],X position [mm],X current [A],Z position [mm],Z torque [N*m]
    0.00,0.000,0.12,0.000,3.10
    0.02,0.001,0.15,0.000,3.12

- ``time`` once, in a unit of time (s, ms, ...), strictly increasing;
- per linear axis (X, Y, Z): ``position`` (a length) and exactly one of
  ``current`` (A), ``torque`` (N·m, at the motor) or ``power`` (W, electrical
  or at the shaft, as the drive reports it);
- commas, or semicolons or tabs with decimal commas; lines above the header
  (a scope's metadata) are skipped, a last line ``EOF`` is the end; columns
  not named so are left out (and said).

**Scope exports, read as written**, with ``--map`` naming their columns
(``--map "joint.0.motor-pos-fb=X position [mm]"``, one per column, or
:func:`parse_mapping`'s ``;``-separated list):

*LinuxCNC halscope* ("Save log" of the scope's capture; the format written by
``write_log_file`` in LinuxCNC's ``src/hal/utils/scope_files.c``): a first line
``Sampling period is N ns``, then one line per sample, each channel as its
name followed by its value, ``joint.0.motor-pos-fb +1.23400000000000
hm2_7i76e.0.pwmgen.00.value -0.05000000000000 ...``. There is no time column
(the time is the sample's index times the period) and no unit: map each
channel name to the column it is, with its unit (the position in the
machine's units of the INI file, e.g. mm; a PWM or velocity command is not a
current: log the drive's current feedback pin where the amplifier has one).

*TwinCAT Scope* (Beckhoff TE13xx, "Export to csv", Beckhoff Infosys
"Export in csv"): the export writes metadata lines above the channel table
and, per its settings, one time column per channel, one per sample time or
none; the times are milliseconds from the first sample unless "Full
Timestamp" is set (then Windows file times: export without it); the separator
is chosen in the dialog; "Scale values before export" applies the channel's
scaling. Export with one time column shared by the channels ("For each
sampletime", one sample time for all), scaled values, and map the time column
and each channel by their names in the header row (``--map "Time=time [ms]"``,
``--map "X_ActPos=X position [mm]"``, ...). The lines above the header row
are skipped.

*SINUMERIK Trace* (SINUMERIK Operate, "Trace" in the commissioning/diagnosis
area; servo trace of the axes' actual position and current or torque): the
trace is stored as the HMI's own trace file; save or export its samples as
text/CSV where the HMI version offers it (or convert them so), one column
per signal with the time column, and map the columns by the names they carry
(``--map "Time=time [ms]"``, ``--map "X1 Actual position=X position [mm]"``,
``--map "X1 Current actual value=X current [A]"``). Its signals are per
machine axis (X1, Y1, Z1): map each to its program letter.

Every problem is a :class:`~ballscrew.errors.BallScrewInputError` naming the
file, the line and the column.
"""

from __future__ import annotations

import csv
import io
import math
import re
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from ..errors import BallScrewInputError, FloatArray
from .files import read_input_text

__all__ = [
    "KINDS",
    "AxisTrace",
    "Trace",
    "parse_mapping",
    "parse_trace",
    "read_trace",
]

KINDS: dict[str, str] = {"current": "A", "torque": "N*m", "power": "W"}
"""The drive signals a trace may give per axis, and their SI units."""

_QUANTITIES = {"time": "s", "position": "m", **KINDS}
_HEADER = re.compile(
    r"^\s*(?:(?P<axis>[A-Za-z])\s+)?(?P<what>[A-Za-z]+)\s*\[(?P<unit>[^\]]+)\]\s*$"
)
_HALSCOPE = re.compile(r"^\s*Sampling period is\s+(?P<ns>[0-9.eE+-]+)\s*ns", re.IGNORECASE)
MIN_SAMPLES = 20
"""The fewest samples a trace may have (a fit of five parameters needs many more)."""


@dataclass(frozen=True)
class AxisTrace:
    """One axis of a trace (SI).

    Attributes
    ----------
    letter : str
        The program letter (X, Y or Z).
    position : numpy.ndarray
        Measured position [m].
    signal : numpy.ndarray
        The drive's current [A], torque [N·m] or power [W].
    kind : str
        "current", "torque" or "power".
    columns : tuple of str
        The header cells the position and the signal were read from.
    """

    letter: str
    position: FloatArray
    signal: FloatArray
    kind: str
    columns: tuple[str, str] = ("", "")

    @property
    def unit(self) -> str:
        """The SI unit of :attr:`signal`."""
        return KINDS[self.kind]


@dataclass(frozen=True)
class Trace:
    """A drive trace: times [s] and its axes by letter, in the order X, Y, Z."""

    time: FloatArray
    axes: dict[str, AxisTrace]
    source: str = "trace"
    notes: tuple[str, ...] = field(default=())

    @property
    def sample_time(self) -> float:
        """The median time between two samples [s]."""
        return float(np.median(np.diff(self.time)))


def parse_mapping(text: str | None) -> dict[str, str]:
    """``"name=X position [mm]; other=X current [A]"`` as {name: column}.

    The names are the export's own column (or halscope channel) names; the
    columns are what :mod:`ballscrew.io.trace` reads (``time [unit]``,
    ``LETTER position|current|torque|power [unit]``).
    """
    out: dict[str, str] = {}
    for part in (text or "").split(";"):
        if not part.strip():
            continue
        name, sep, column = part.rpartition("=")
        if not sep or not name.strip() or not _HEADER.match(column):
            raise BallScrewInputError(
                "--map", part.strip(),
                "NAME=COLUMN, the export's column name and what it is, e.g. "
                "'joint.0.motor-pos-fb=X position [mm]'",
            )  # fmt: skip
        out[name.strip()] = column.strip()
    return out


def read_trace(path: str | Path, mapping: Mapping[str, str] | None = None) -> Trace:
    """Read a trace file (module docstring); ``mapping`` renames the export's columns."""
    return parse_trace(read_input_text("trace", path), source=str(path), mapping=mapping)


def parse_trace(
    text: str, *, source: str = "trace", mapping: Mapping[str, str] | None = None
) -> Trace:
    """A :class:`Trace` from the text of a trace file (module docstring)."""
    names = dict(mapping or {})
    text = text.lstrip("\ufeff")
    lines = text.splitlines()
    first = next((k for k, line in enumerate(lines) if line.strip()), None)
    if first is None:
        raise BallScrewInputError(source, "(empty)", "a header and the samples")
    hal = _HALSCOPE.match(lines[first])
    if hal:
        header, rows, start = _halscope(lines, first, hal, source)
    else:
        header, rows, start = _table(lines, names, source)
    return _assemble(header, rows, start, names, source, halscope=bool(hal))


def _halscope(
    lines: list[str], first: int, hal: re.Match[str], source: str
) -> tuple[list[str], list[list[str]], int]:
    """The log of halscope: names and values in pairs on each line; a time column added."""
    try:
        period = float(hal.group("ns")) * 1e-9
    except ValueError:
        period = math.nan
    if not (math.isfinite(period) and period > 0.0):
        raise BallScrewInputError(f"{source}: line {first + 1}", lines[first].strip(),
                                  "'Sampling period is N ns' with N > 0")  # fmt: skip
    header: list[str] = []
    rows: list[list[str]] = []
    start = 0
    for k in range(first + 1, len(lines)):
        cells = lines[k].split()
        if not cells:
            continue
        if len(cells) % 2:
            raise BallScrewInputError(f"{source}: line {k + 1}", lines[k].strip()[:60],
                                      "pairs of a channel name and its value")  # fmt: skip
        channels = cells[0::2]
        if not header:
            header, start = ["time [s]", *channels], k
        elif channels != header[1:]:
            raise BallScrewInputError(f"{source}: line {k + 1}", " ".join(channels),
                                      f"the channels of line {start + 1}: "
                                      f"{' '.join(header[1:])}")  # fmt: skip
        rows.append([repr(len(rows) * period), *cells[1::2]])
    if not header:
        raise BallScrewInputError(source, "(no samples)", "lines of channel names and values")
    return header, rows, start


def _table(
    lines: list[str], names: Mapping[str, str], source: str
) -> tuple[list[str], list[list[str]], int]:
    """A delimited table: the header is the first row naming two known or mapped columns."""
    for k, line in enumerate(lines):
        if not line.strip():
            continue
        delimiter = ";" if ";" in line else ("\t" if "\t" in line else ",")
        cells = next(csv.reader([line], delimiter=delimiter))
        known = [c for c in cells if c.strip() in names or _HEADER.match(c)]
        if len(known) >= 2:
            body = [r for r in csv.reader(io.StringIO("\n".join(lines[k + 1 :])),
                                          delimiter=delimiter)]  # fmt: skip
            rows: list[list[str]] = []
            for r in body:
                if not any(c.strip() for c in r):
                    rows.append([])  # kept for the line numbers, dropped below
                    continue
                if r[0].strip().upper() == "EOF":
                    break
                rows.append([c.replace(",", ".") if delimiter != "," else c for c in r])
            return [c.strip() for c in cells], rows, k
    raise BallScrewInputError(
        f"{source}: header", "(none found)",
        "a row naming the columns with their units, e.g. 'time [s],X position [mm],"
        "X current [A]', or --map to name an export's columns",
    )  # fmt: skip


_Wanted = dict[tuple[str, str], tuple[int, str, str]]
"""The trace's columns by (axis letter or "", quantity): (index, unit, header cell)."""


def _assemble(
    header: list[str], rows: list[list[str]], start: int, names: Mapping[str, str], source: str,
    *, halscope: bool,
) -> Trace:  # fmt: skip
    """The columns parsed, converted to SI and grouped by axis."""
    wanted, left_out = _header_columns(header, names, source, halscope=halscope)
    if ("", "time") not in wanted:
        raise BallScrewInputError(f"{source}: header", ",".join(header),
                                  "a time column, e.g. 'time [s]'")  # fmt: skip
    letters = sorted({a for a, _ in wanted if a}, key="XYZ".index)
    if not letters:
        raise BallScrewInputError(f"{source}: header", ",".join(header),
                                  "an axis: 'X position [mm]' and 'X current [A]' (or torque, "
                                  "power)")  # fmt: skip
    data = [(start + 2 + n, r) for n, r in enumerate(rows) if r]
    if len(data) < MIN_SAMPLES:
        raise BallScrewInputError(source, f"{len(data)} samples", f"at least {MIN_SAMPLES}")

    def column(key: tuple[str, str]) -> FloatArray:
        return _column(wanted[key], _QUANTITIES[key[1]], data, source)

    time = column(("", "time"))
    steps = np.diff(time)
    if not np.all(steps > 0.0):
        n = int(np.argmax(steps <= 0.0)) + 1
        raise BallScrewInputError(f"{source}: line {data[n][0]}, column '{wanted['', 'time'][2]}'",
                                  data[n][1][wanted["", "time"][0]],
                                  "times increasing")  # fmt: skip
    axes: dict[str, AxisTrace] = {}
    for letter in letters:
        kinds = [k for k in KINDS if (letter, k) in wanted]
        if (letter, "position") not in wanted or len(kinds) != 1:
            given = [w for a, w in wanted if a == letter]
            raise BallScrewInputError(
                f"{source}: axis {letter}", ", ".join(given),
                f"'{letter} position [unit]' and exactly one of current, torque or power",
            )  # fmt: skip
        axes[letter] = AxisTrace(
            letter, column((letter, "position")), column((letter, kinds[0])), kinds[0],
            (wanted[letter, "position"][2], wanted[letter, kinds[0]][2]),
        )  # fmt: skip
    notes = (f"columns left out (not named as a trace column): {', '.join(left_out)}",) if (
        left_out) else ()  # fmt: skip
    return Trace(time - time[0], axes, source, notes)


def _header_columns(
    header: list[str], names: Mapping[str, str], source: str, *, halscope: bool
) -> tuple[_Wanted, list[str]]:
    """The header's trace columns by (axis, quantity), and the cells left out.

    ``names`` maps a header cell to its trace name (``--map``); a halscope file's
    cells other than the first (its time) are read only through it. A named cell
    must give an axis X, Y or Z (none for the time), a known quantity and a unit
    of it, each (axis, quantity) once.
    """
    from .units import parse_unit

    unknown = sorted(set(names) - set(header))
    if unknown:
        raise BallScrewInputError(f"--map {unknown[0]}", unknown[0],
                                  f"a column of {source}: {', '.join(header)}")  # fmt: skip
    wanted: _Wanted = {}
    left_out: list[str] = []
    for i, cell in enumerate(header):
        named = names.get(cell, "" if halscope and i > 0 else cell)
        m = _HEADER.match(named)
        what = m.group("what").lower() if m else ""
        if not m or what not in _QUANTITIES:
            left_out.append(cell)
            continue
        axis = (m.group("axis") or "").upper()
        if (what == "time") != (axis == ""):
            raise BallScrewInputError(
                f"{source}: header '{cell}'", named,
                "'time [unit]' (no axis), or an axis letter and its quantity, e.g. "
                "'X position [mm]'",
            )  # fmt: skip
        if axis and axis not in "XYZ":
            raise BallScrewInputError(f"{source}: header '{cell}'", axis,
                                      "a linear axis X, Y or Z")  # fmt: skip
        unit = m.group("unit").strip()
        parsed = parse_unit(f"{source}: header '{cell}'", unit)
        if not parsed.is_compatible_with(_QUANTITIES[what]):
            raise BallScrewInputError(f"{source}: header '{cell}'", unit,
                                      f"a unit of {what}, e.g. {_QUANTITIES[what]}")  # fmt: skip
        key = (axis, what)
        if key in wanted:
            raise BallScrewInputError(f"{source}: header '{cell}'", named,
                                      f"one {what} column{' for ' + axis if axis else ''} "
                                      f"(also '{wanted[key][2]}')")  # fmt: skip
        wanted[key] = (i, unit, cell)
    return wanted, left_out


def _column(
    where: tuple[int, str, str], quantity: str, data: list[tuple[int, list[str]]], source: str
) -> FloatArray:
    """One column of the data rows as numbers in SI.

    ``where`` is its (index, unit, header cell), ``quantity`` a unit of its
    quantity and ``data`` the (file line, cells) of each row; a cell that is not
    a finite number is refused with its line.
    """
    from .units import to_si_array

    i, unit, cell = where
    values = np.empty(len(data))
    for n, (line, r) in enumerate(data):
        try:
            values[n] = float(r[i])
        except (ValueError, IndexError):
            shown = r[i] if i < len(r) else "(missing)"
            raise BallScrewInputError(f"{source}: line {line}, column '{cell}'", shown,
                                      "a number") from None  # fmt: skip
        if not math.isfinite(values[n]):
            raise BallScrewInputError(f"{source}: line {line}, column '{cell}'", r[i],
                                      "a finite number")  # fmt: skip
    return np.asarray(to_si_array(f"{source}: column '{cell}'", values, unit, quantity),
                      dtype=float)  # fmt: skip
