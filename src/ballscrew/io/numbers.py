"""How many significant digits each printed or CSV number carries: one rule, one place.

A friction model is good to some per cent, so a torque printed with 17 digits
(``0.30259790342381945``) or a speed written ``-3000.0000000000005`` says more than
anyone knows. Every number a command prints to the terminal, or writes into a CSV
file, goes through this module; JSON and ``.mat`` files keep full precision.

The rule (docs/guide.md, "Numbers in outputs"):

* on the terminal, every number has at most :data:`TERMINAL_DIGITS` (4)
  significant digits;
* in CSV files, the coordinates a result is given at keep enough digits that a
  time series keeps its sample spacing and a speed grid its steps: times,
  positions (m, mm, in) and angles 7, speeds 6; everything else (torques, forces,
  powers, energies, efficiencies, temperatures, errors in um, ...) 4. The column's
  unit, in square brackets in its header (``speed [rpm]``), says which
  (:func:`column_digits`); a file with its own rule (the friction map's lookup
  table) says so;
* the Markdown and HTML reports give results to 4 and echo the case's inputs (in SI)
  to :data:`INPUT_DIGITS` (6).

Trailing zeros are not written (``3000``, not ``3000.0``), so a number never shows
more digits than it has. The functions are for imperial output too: convert, then
:func:`text`.
"""

from __future__ import annotations

import math
import re
from typing import Any

__all__ = [
    "CSV_DIGITS",
    "INPUT_DIGITS",
    "TERMINAL_DIGITS",
    "UNIT_QUANTITY",
    "column_digits",
    "sig",
    "significant_digits",
    "text",
]

TERMINAL_DIGITS = 4
"""Significant digits of every number printed on the terminal."""

INPUT_DIGITS = 6
"""Significant digits of an input a report echoes (its case's values in SI)."""

CSV_DIGITS: dict[str, int] = {
    "time": 7,
    "position": 7,
    "angle": 7,
    "speed": 6,
    "result": 4,
}
"""Significant digits in CSV files, by quantity (``result``: everything else)."""

UNIT_QUANTITY: dict[str, str] = {
    **dict.fromkeys(("s", "ms", "min", "h"), "time"),
    **dict.fromkeys(("m", "mm", "in"), "position"),
    **dict.fromkeys(("rad", "deg", "°"), "angle"),
    **dict.fromkeys(("rpm", "rad/s", "m/s", "mm/s", "m/min", "mm/min", "in/min", "1/min"), "speed"),
}
"""A column's unit (as written in its header's brackets) -> its quantity in :data:`CSV_DIGITS`."""

_UNIT = re.compile(r"\[([^\]]*)\]\s*$")


def sig(x: float, digits: int) -> float:
    """``x`` rounded to ``digits`` significant digits; zero, NaN and infinities unchanged.

    >>> sig(-3000.0000000000005, 6), sig(0.30259790342381945, 4), sig(12345.6, 4)
    (-3000.0, 0.3026, 12350.0)
    """
    x = float(x)
    if not math.isfinite(x) or x == 0.0:
        return x
    return float(f"{x:.{digits}g}")


def text(x: Any, digits: int = TERMINAL_DIGITS) -> str:
    """``x`` as text with at most ``digits`` significant digits and no trailing zeros.

    Plain notation from 1e-4 to 1e16, scientific beyond; integers and non-numbers
    (strings, None) as they are.

    >>> text(-3000.0000000000005), text(0.30259790342381945), text(12345.6), text(5.5565e-7)
    ('-3000', '0.3026', '12350', '5.557e-07')
    >>> text(float("nan")), text(7), text("complete")
    ('nan', '7', 'complete')
    """
    if isinstance(x, bool) or (not isinstance(x, float) and not _is_real_float(x)):
        return str(x)
    value = sig(float(x), digits)
    if value == 0.0:
        return "0"
    shown = repr(value)
    return shown[:-2] if shown.endswith(".0") else shown


def _is_real_float(x: object) -> bool:
    """Whether ``x`` is a floating-point scalar of another kind (numpy's)."""
    return hasattr(x, "dtype") and getattr(x.dtype, "kind", "") == "f"


def column_digits(header: str) -> int:
    """The significant digits of a CSV column, from the unit in its header's brackets.

    >>> column_digits("t [s]"), column_digits("speed [rpm]"), column_digits("torque [N*m]")
    (7, 6, 4)
    """
    found = _UNIT.search(header)
    unit = found.group(1).strip() if found else ""
    return CSV_DIGITS[UNIT_QUANTITY.get(unit, "result")]


def significant_digits(shown: str) -> int:
    """How many significant digits a number as written shows (0 for zero).

    Leading zeros never count; trailing zeros of an integer do not either (``3000``
    is one digit), those after a decimal point do (``3000.0`` is five).

    >>> significant_digits("-3000.0000000000005"), significant_digits("0.0300"), significant_digits("1.5e+06")
    (17, 3, 2)
    """  # noqa: E501 - a doctest line
    mantissa = re.split(r"[eE]", shown.strip().lstrip("+-"), maxsplit=1)[0]
    if "." in mantissa:
        return len(mantissa.replace(".", "").lstrip("0"))
    return len(mantissa.lstrip("0").rstrip("0"))
