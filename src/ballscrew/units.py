"""Units at the boundary: quantities typed by people ("25 mm", "2 kN") to SI floats.

All conversions of the configuration files and the command line go through
:func:`to_si`, which uses pint. Inside the package everything is SI
(m, N, Pa, Pa·s, m²/s, rad/s, N·m) and temperatures are in °C.
"""

from __future__ import annotations

import functools
import math
import re
import tokenize
from typing import Any

import pint

from .errors import BallScrewInputError

__all__ = ["parse_range", "range_size", "registry", "to_si"]


@functools.cache
def registry() -> pint.UnitRegistry:  # type: ignore[type-arg]
    """The package's pint unit registry.

    Pint's parsed unit definitions are cached on disk (its ``:auto:`` user
    cache folder), which cuts building the registry from about 0.5 s to
    0.04 s; where no cache folder can be written, the registry is built
    without one.
    """
    try:
        return pint.UnitRegistry(autoconvert_offset_to_baseunit=True, cache_folder=":auto:")
    except OSError:  # read-only home, no cache directory: parse the definitions
        return pint.UnitRegistry(autoconvert_offset_to_baseunit=True)


def to_si(field: str, value: Any, unit: str | None) -> float:
    """Convert ``value`` to the SI unit ``unit`` and return the magnitude.

    Parameters
    ----------
    field : str
        Name of the input, for error messages.
    value : str or number
        A quantity with its unit ("32 mm", "1.5 kN", "45 deg", "3000 rpm",
        "40 degC"). A bare number is accepted only for a dimensionless
        quantity (``unit=""``): anywhere else it is an error that shows how
        to write it, since a number without a unit ("100" for a speed) is
        the commonest silent slip (rad/s or rpm? m or mm?).
    unit : str or None
        Target unit, in pint's notation ("m", "N", "rad", "rad/s", "degC"),
        or "" for a dimensionless number. None: whatever the value's unit is,
        converted to SI base units, and a bare number taken as SI (the
        convention of model parameters, whose units the models document).

    Examples
    --------
    >>> to_si("pitch_diameter", "32 mm", "m")
    0.032
    >>> round(to_si("speed", "3000 rpm", "rad/s"), 4)
    314.1593
    >>> to_si("temperature", "313.15 K", "degC")
    40.0
    >>> to_si("speed", "100", "rad/s")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ballscrew.errors.BallScrewInputError: speed = '100' is not allowed: ...e.g. '100 rpm'...
    """
    ureg = registry()
    if isinstance(value, bool):
        wanted = "a number" if unit is None else f"a quantity in units of {unit}, e.g. '1 {unit}'"
        raise BallScrewInputError(field, value, wanted)
    try:
        if isinstance(value, int | float):
            if unit:
                raise _bare(field, value, unit)
            magnitude = float(value)
        else:
            quantity: Any = ureg.Quantity(str(value).strip())
            if quantity.units == ureg.dimensionless:  # a bare number written as text
                if unit:
                    raise _bare(field, value, unit)
                magnitude = float(quantity.magnitude)
            elif unit is None:
                magnitude = float(quantity.to_base_units().magnitude)
            else:
                magnitude = float(quantity.to(unit).magnitude)
    except BallScrewInputError:
        raise
    except (
        pint.errors.PintError,
        ValueError,
        TypeError,
        AttributeError,
        AssertionError,
        ArithmeticError,
        RecursionError,
        LookupError,
        SyntaxError,
        tokenize.TokenError,  # the unit library's tokenizer on unbalanced brackets
    ) as exc:
        reason = (
            "incompatible unit"
            if isinstance(exc, pint.errors.DimensionalityError)
            else ("not a quantity")
        )
        wanted = (
            "a number or a quantity with its unit"
            if unit is None
            else f"a quantity convertible to {unit} ({reason}), e.g. '1 {unit}'"
        )
        raise BallScrewInputError(field, value, wanted) from None
    if not math.isfinite(magnitude):
        raise BallScrewInputError(field, value, "a finite quantity")
    return magnitude


EXAMPLE_UNITS: dict[str, str] = {
    "rad/s": "rpm",
    "m": "mm",
    "N": "kN",
    "degC": "degC",
    "N*m": "N*m",
    "rad": "deg",
    "Pa*s": "mPa*s",
    "m**2/s": "mm**2/s",
    "kg/m**3": "kg/m**3",
    "1/Pa": "1/GPa",
}
"""The unit shown in the example of an error for each target unit."""


def _bare(field: str, value: Any, unit: str) -> BallScrewInputError:
    example = EXAMPLE_UNITS.get(unit, unit)
    return BallScrewInputError(
        field,
        value,
        f"a quantity with its unit, e.g. '{str(value).strip()} {example}' "
        "(a bare number has no unit)",
    )


_RANGE = re.compile(
    r"^\s*(?P<lo>[-+]?[0-9.]+(?:[eE][-+]?\d+)?)\s*\.\.\s*(?P<hi>[-+]?[0-9.]+(?:[eE][-+]?\d+)?)"
    r"\s*(?::\s*(?P<n>\d+))?\s*(?P<unit>[^:]*?)\s*(?::\s*(?P<n2>\d+))?\s*$"
)


def range_size(text: str, default_points: int = 50) -> int:
    """How many values :func:`parse_range` would give for ``text``, without converting any.

    For a caller that must bound the work a text asks for before it is done
    (a range ``a..b:n`` may ask for a million points).

    Examples
    --------
    >>> range_size("0..3000:31 rpm"), range_size("0..3000 rpm"), range_size("20, 40 degC")
    (31, 50, 2)
    """
    raw = str(text).strip()
    match = _RANGE.match(raw)
    if match:
        count = match.group("n") or match.group("n2")
        return int(count) if count else default_points
    return raw.count(",") + 1


def parse_range(field: str, text: str, unit: str | None, default_points: int = 50) -> list[float]:
    """Parse ``"0..3000 rpm"``, ``"10..3000:31 rpm"`` or a list ``"20, 30, 45 degC"`` to SI values.

    ``a..b`` gives ``default_points`` evenly spaced values (``a..b:n`` gives
    ``n``; the count may also follow the unit); a comma-separated list gives
    those values. The unit is written once, at the end. ``unit`` is the SI
    target unit, as for :func:`to_si`.

    Examples
    --------
    >>> [round(v, 3) for v in parse_range("speed", "0..60:3 rpm", "rad/s")]
    [0.0, 3.142, 6.283]
    >>> parse_range("temperature", "20, 30 degC", "degC")
    [20.0, 30.0]
    """
    raw = str(text).strip()
    allowed = "a value, a list 'a, b, c unit' or a range 'a..b unit' (optionally 'a..b:n unit')"
    if not raw:
        raise BallScrewInputError(field, text, allowed)
    match = _RANGE.match(raw)
    if match:
        count = match.group("n") or match.group("n2")
        n = int(count) if count else default_points
        if n < 1 or n > 1_000_000:
            raise BallScrewInputError(field, text, "between 1 and 1e6 points")
        suffix = f" {match.group('unit')}" if match.group("unit") else ""
        lo = to_si(field, match.group("lo") + suffix, unit)
        hi = to_si(field, match.group("hi") + suffix, unit)
        if n == 1:
            return [lo]
        return [lo + (hi - lo) * i / (n - 1) for i in range(n)]
    if ".." in raw:
        raise BallScrewInputError(field, text, allowed)
    parts = [p.strip() for p in raw.split(",")]
    if any(not p for p in parts):
        raise BallScrewInputError(field, text, allowed)
    last = parts[-1].split(None, 1)
    suffix = f" {last[1]}" if len(last) == 2 else ""
    parts[-1] = last[0]
    return [to_si(field, p if " " in p else p + suffix, unit) for p in parts]
