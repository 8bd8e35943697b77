"""A motor table: the servo motors a selection may pair with each screw (CSV, units in the header).

One motor a row; the header names each column with its unit in brackets::

    name, rated_torque [N*m], peak_torque [N*m], max_speed [1/min],
    rotor_inertia [kg*cm^2], price [EUR]

(one line in the file).

``name``, ``rated_torque``, ``peak_torque``, ``max_speed`` and
``rotor_inertia`` are required; ``price`` is optional, its bracket holding the
currency (any word; not converted). The electrical constants are optional, as
in a case file's ``[motor]`` (:mod:`ballscrew.axis.drive`):
``torque_constant [N*m/A]`` (per ampere rms), ``winding_resistance [ohm]``
with a ``resistance_kind`` column (``phase`` or ``terminal``, no unit), and
``iron_loss`` in a torque unit (a drag) or a power unit (at ``max_speed``); a
selected motor carries them into the candidate's case. The units are converted to SI here, at the
boundary (torques N*m, speed rad/s, inertia kg*m^2); a cell that is not a
number, a value not above zero, a peak torque below the rated one or a column
without its unit is refused naming the line and the column.

A screw price table (:func:`parse_prices`) is two columns, ``designation,
price [EUR]``: a selection adds a screw's price to its motor's.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

from ..errors import BallScrewInputError
from .files import csv_rows, read_input_text
from .units import to_si

__all__ = [
    "ELECTRICAL_COLUMNS",
    "MOTOR_COLUMNS",
    "MotorRow",
    "parse_motors",
    "parse_prices",
    "read_motors",
    "read_prices",
]

MOTOR_COLUMNS: dict[str, str] = {
    "rated_torque": "N*m",
    "peak_torque": "N*m",
    "max_speed": "rad/s",
    "rotor_inertia": "kg*m^2",
}
"""The required numeric columns and the SI unit each is converted to."""

ELECTRICAL_COLUMNS: dict[str, str] = {
    "torque_constant": "N*m/A",
    "winding_resistance": "ohm",
}
"""The optional numeric columns of the motor's electrical constants and their SI units."""

MAX_MOTORS = 1000
"""The most rows a motor table may hold (a maker's whole range is about 100)."""

_HEADER = re.compile(r"^\s*(?P<name>[A-Za-z_][A-Za-z0-9_ ]*?)\s*(?:\[(?P<unit>[^\]]*)\])?\s*$")


@dataclass(frozen=True)
class MotorRow:
    """One motor of the table, in SI: torques [N*m], speed [rad/s], inertia [kg*m^2].

    ``price`` is None without a price column; ``currency`` is its bracket's word.
    """

    name: str
    rated_torque: float
    peak_torque: float
    max_speed: float
    rotor_inertia: float
    price: float | None = None
    currency: str = ""
    line: int = 0
    torque_constant: float | None = None
    """[N·m/A rms]; None without the column."""
    winding_resistance: float | None = None
    """[Ω], of one phase or between two terminals as :attr:`resistance_kind` says."""
    resistance_kind: str | None = None
    iron_loss: str | None = None
    """As written with its column's unit (``"45 W"``, ``"0.1 N*m"``): the case reads it."""


def _positive_number(where: str, cell: str) -> float:
    """The table cell ``cell`` as a finite number above 0, else an error naming ``where``."""
    try:
        number = float(cell)
    except ValueError:
        raise BallScrewInputError(where, cell or "(empty)", "a number") from None
    if not math.isfinite(number) or number <= 0.0:
        raise BallScrewInputError(where, cell, "a finite number > 0")
    return number


def _columns(header: list[str], source: str) -> tuple[dict[str, tuple[int, str]], int]:
    """Index and unit of each known column, and the name column's index."""
    found: dict[str, tuple[int, str]] = {}
    name_col = -1
    for i, cell in enumerate(header):
        match = _HEADER.match(cell)
        key = match.group("name").strip().lower().replace(" ", "_") if match else cell.strip()
        unit = (match.group("unit") or "").strip() if match else ""
        if key == "name":
            name_col = i
        elif key == "resistance_kind":
            found[key] = (i, "")
        elif key in MOTOR_COLUMNS or key in ELECTRICAL_COLUMNS or key in ("price", "iron_loss"):
            if not unit:
                example = {"rated_torque": "N*m", "peak_torque": "N*m", "max_speed": "1/min",
                           "rotor_inertia": "kg*cm^2", "price": "EUR",
                           "torque_constant": "N*m/A", "winding_resistance": "ohm",
                           "iron_loss": "W"}[key]  # fmt: skip
                raise BallScrewInputError(
                    f"{source}: line 1, column '{cell.strip()}'", cell.strip(),
                    f"the column's unit in brackets, e.g. '{key} [{example}]'",
                )  # fmt: skip
            found[key] = (i, unit)
    missing = [k for k in ("name", *MOTOR_COLUMNS) if k != "name" and k not in found]
    if ("winding_resistance" in found) != ("resistance_kind" in found):
        missing.append("winding_resistance [ohm] and resistance_kind (phase or terminal) "
                       "together")  # fmt: skip
    if name_col < 0:
        missing.insert(0, "name")
    if missing:
        raise BallScrewInputError(
            f"{source}: line 1 (header)", ",".join(c.strip() for c in header),
            "the columns name, rated_torque [N*m], peak_torque [N*m], max_speed [1/min], "
            f"rotor_inertia [kg*cm^2] (optional price [EUR]); missing: {', '.join(missing)}",
        )  # fmt: skip
    return found, name_col


def parse_motors(text: str, source: str = "motor table") -> tuple[MotorRow, ...]:
    r"""The motors of a CSV table's text (module docstring), in SI.

    Examples
    --------
    >>> text = "name, rated_torque [N*m], peak_torque [N*m], max_speed [1/min], " \
    ...        "rotor_inertia [kg*cm^2]\nM1, 2.4, 7.2, 3000, 3.1\n"
    >>> m = parse_motors(text)[0]
    >>> m.name, round(m.max_speed, 2), m.rotor_inertia
    ('M1', 314.16, 0.00031)
    """
    rows = [r for r in csv_rows(text, source, ",")[0] if any(c.strip() for c in r)]
    rows = [r for r in rows if not r[0].lstrip().startswith("#")]
    if len(rows) < 2:
        raise BallScrewInputError(source, "(no motors)", "a header line and one motor a line")
    if len(rows) - 1 > MAX_MOTORS:
        raise BallScrewInputError(source, f"{len(rows) - 1} motors", f"at most {MAX_MOTORS}")
    header = rows[0]
    columns, name_col = _columns(header, source)
    currency = columns["price"][1] if "price" in columns else ""
    out: list[MotorRow] = []
    seen: set[str] = set()
    for line, row in enumerate(rows[1:], start=2):
        name = row[name_col].strip() if name_col < len(row) else ""
        if not name:
            raise BallScrewInputError(f"{source}: line {line}, column 'name'", "(empty)", "a name")
        if name in seen:
            raise BallScrewInputError(f"{source}: line {line}, column 'name'", name,
                                      "a name no other row has")  # fmt: skip
        seen.add(name)
        values: dict[str, float] = {}
        texts: dict[str, str] = {}
        for key, (col, unit) in columns.items():
            cell = row[col].strip() if col < len(row) else ""
            where = f"{source}: line {line}, column '{header[col].strip()}'"
            if key == "resistance_kind":
                if cell not in ("phase", "terminal"):
                    raise BallScrewInputError(where, cell or "(empty)", "phase or terminal")
                texts[key] = cell
                continue
            number = _positive_number(where, cell)
            if key in ("price", "iron_loss"):
                values[key] = number
                texts[key] = f"{cell} {unit}"
                continue
            try:
                values[key] = to_si(where, f"{cell} {unit}",
                                    {**MOTOR_COLUMNS, **ELECTRICAL_COLUMNS}[key])  # fmt: skip
            except BallScrewInputError as exc:
                raise BallScrewInputError(where, f"{cell} [{unit}]", exc.allowed) from None
        if values["peak_torque"] < values["rated_torque"]:
            raise BallScrewInputError(
                f"{source}: line {line}, column '{header[columns['peak_torque'][0]].strip()}'",
                row[columns["peak_torque"][0]].strip(),
                "a peak torque at least the rated torque",
            )
        out.append(MotorRow(name, values["rated_torque"], values["peak_torque"],
                            values["max_speed"], values["rotor_inertia"], values.get("price"),
                            currency, line, values.get("torque_constant"),
                            values.get("winding_resistance"), texts.get("resistance_kind"),
                            texts.get("iron_loss")))  # fmt: skip
    return tuple(out)


def read_motors(path: str | Path) -> tuple[MotorRow, ...]:
    """The motors of the CSV file at ``path`` (:func:`parse_motors`)."""
    return parse_motors(read_input_text("--motors", path), source=Path(path).name)


def parse_prices(text: str, source: str = "price table") -> tuple[dict[str, float], str]:
    r"""The screw prices of a CSV table ``designation, price [EUR]``: name -> price, currency.

    ``designation`` is a screw's name as ``ballscrew select`` names it: a
    catalogue nut with its maker (``HIWIN R32-20K4-FSC``) or an ISO size
    (``ISO 25x20-3.969``); case and blanks are ignored. A price that is not a
    positive number, a name given twice or a price column without its currency
    is refused naming the line and the column.

    Examples
    --------
    >>> parse_prices("designation, price [EUR]\nHIWIN R32-20K4-FSC, 310\n")
    ({'HIWIN R32-20K4-FSC': 310.0}, 'EUR')
    """
    rows = [r for r in csv_rows(text, source, ",")[0] if any(c.strip() for c in r)]
    rows = [r for r in rows if not r[0].lstrip().startswith("#")]
    if len(rows) < 2:
        raise BallScrewInputError(source, "(no screws)", "a header line and one screw a line")
    header = rows[0]
    cells = [_HEADER.match(c) for c in header]
    keys = [m.group("name").strip().lower() if m else c.strip() for m, c in zip(cells, header,
            strict=True)]  # fmt: skip
    if "designation" not in keys or "price" not in keys:
        raise BallScrewInputError(f"{source}: line 1 (header)", ",".join(header),
                                  "the columns designation, price [EUR]")  # fmt: skip
    name_col, price_col = keys.index("designation"), keys.index("price")
    match = cells[price_col]
    currency = (match.group("unit") or "").strip() if match else ""
    if not currency:
        raise BallScrewInputError(f"{source}: line 1, column '{header[price_col].strip()}'",
                                  header[price_col].strip(),
                                  "the currency in brackets, e.g. 'price [EUR]'")  # fmt: skip
    out: dict[str, float] = {}
    seen: set[str] = set()
    for line, row in enumerate(rows[1:], start=2):
        name = " ".join(row[name_col].split()) if name_col < len(row) else ""
        if not name or name.upper() in seen:
            raise BallScrewInputError(
                f"{source}: line {line}, column 'designation'", name or "(empty)",
                "a designation no other row has",
            )  # fmt: skip
        seen.add(name.upper())
        cell = row[price_col].strip() if price_col < len(row) else ""
        where = f"{source}: line {line}, column '{header[price_col].strip()}'"
        out[name] = _positive_number(where, cell)
    return out, currency


def read_prices(path: str | Path) -> tuple[dict[str, float], str]:
    """The screw prices of the CSV file at ``path`` (:func:`parse_prices`)."""
    return parse_prices(read_input_text("--screw-prices", path), source=Path(path).name)
