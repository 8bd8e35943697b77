"""Error types of the package and the input checks shared by every layer.

Every check raises :class:`BallScrewInputError` (a :class:`ValueError`) whose
message names the field, the value received and what is allowed, so that a
user never sees a traceback from deep inside numpy or a silent NaN.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np
import numpy.typing as npt

__all__ = [
    "BallScrewInputError",
    "BallScrewPlausibilityWarning",
    "BallScrewReadingWarning",
    "BallScrewValidityWarning",
    "broadcast_inputs",
    "check_choice",
    "check_finite",
    "check_in_range",
    "check_nonnegative",
    "check_positive",
]

FloatArray = npt.NDArray[np.float64]


class BallScrewInputError(ValueError):
    """An input is outside what a function or object accepts.

    Attributes
    ----------
    field : str
        Name of the offending input.
    value : object
        The value received.
    allowed : str
        Plain-language description of what is allowed.
    """

    def __init__(self, field: str, value: Any, allowed: str) -> None:
        self.field = field
        self.value = value
        self.allowed = allowed
        super().__init__(f"{field} = {_show(value)} is not allowed: {allowed}")

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickled with its three parts (to a worker process and back), not its message."""
        return (type(self), (self.field, self.value, self.allowed))


class BallScrewValidityWarning(UserWarning):
    """An input lies outside the published validity range of a model or correlation.

    The result is still computed (extrapolated); the message names the
    quantity, its value and the range, and ``issue`` holds them as a
    :class:`ballscrew.validity.ValidityIssue`. A range every ordinary ball screw
    leaves (the film formulas' speed and load) is told in one line
    (:meth:`~ballscrew.validity.ValidityIssue.short`), once per session; its
    source and reason are ``issue.note()``. See :mod:`ballscrew.validity`.
    """

    def __init__(self, issue: Any) -> None:
        super().__init__(issue.short() if hasattr(issue, "short") else str(issue))
        self.issue = issue


class BallScrewSpeedWarning(UserWarning):
    """A motion drives the screw above its critical speed or its nut's d·n limit.

    See :mod:`ballscrew.limits`.
    """


def _beyond(allowed: str) -> str:
    """How a value stands to ``allowed``: "is above 14 m/min" for "at most 14 m/min"."""
    for bound, verb in (("at most ", "is above "), ("at least ", "is below ")):
        if allowed.startswith(bound):
            return verb + allowed[len(bound) :]
    return f"lies outside {allowed}"


class BallScrewPlausibilityWarning(UserWarning):
    """An input lies outside what makers build or sell, and is used as given.

    A ball off the makers' series, loaded turns outside 1 to 5, an oil thicker
    than ISO VG 3200 (see :mod:`ballscrew.plausible`). The message names the
    field, the value, the typical range and its source; the four are kept as
    attributes.
    """

    def __init__(self, field: str, value: str, allowed: str, source: str) -> None:
        super().__init__(f"{field} = {value} {_beyond(allowed)} ({source}); it is used as given")
        self.field = field
        self.value = value
        self.allowed = allowed
        self.source = source

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickled with its four parts, not its message."""
        return (type(self), (self.field, self.value, self.allowed, self.source))


class BallScrewReadingWarning(UserWarning):
    """A quantity's text could be meant two ways; the message says which reading was taken.

    A speed in ``Hz`` or ``1/s`` is read as revolutions per second (see
    :mod:`ballscrew.units`); the message gives the other reading and how to
    write it.
    """


def _show(value: Any) -> str:
    """Short printable form of a scalar or the first offending array element."""
    try:
        arr = np.asarray(value)
    except Exception:  # any odd object: fall back to its repr
        arr = np.asarray(None)
    if arr.ndim == 0:
        text = repr(arr.item()) if arr.dtype.kind in "biufc" else repr(value)
        return text if len(text) <= 80 else text[:77] + "..."
    return f"array of shape {arr.shape}"


_NUMBER_KINDS = frozenset("iuf")  # signed and unsigned integers, floats: what a quantity is


_FLOAT64 = np.dtype(np.float64)


def _as_float_array(field: str, value: Any) -> FloatArray:
    if type(value) is float or type(value) is np.float64:  # one number, cheapest first
        return np.asarray(value)
    if type(value) is np.ndarray and value.dtype is _FLOAT64:
        # What the layers pass each other: already a float array (the same object back).
        return value
    kind = _kind(value)
    if kind == "U":
        raise BallScrewInputError(
            field,
            value,
            "a real number or an array of real numbers in SI units (a text with its unit, "
            "such as '3000 1/min', is read by ballscrew.io.units.to_si(field, text, unit) "
            "first)",
        )
    if kind not in _NUMBER_KINDS and kind != "O":
        what = {"b": "a truth value", "S": "bytes", "M": "a date", "m": "a time span"}
        raise BallScrewInputError(
            field, value, f"a real number or an array of real numbers, not {what.get(kind, kind)}"
        )
    try:
        arr = np.asarray(value, dtype=np.float64)
    except OverflowError:
        raise BallScrewInputError(
            field, value, "a number a double-precision float can hold (below 1.8e308)"
        ) from None
    except (TypeError, ValueError):
        raise BallScrewInputError(
            field, value, "a real number or an array of real numbers"
        ) from None
    return arr


def _kind(value: Any) -> str:
    """The kind letter numpy gives ``value``'s elements ('O' for mixed Python objects)."""
    if isinstance(value, bool | np.bool_):
        return "b"
    if isinstance(value, int):  # a Python int of any length: 'i' (too long: overflow below)
        return "i"
    if isinstance(value, list | tuple):
        for odd, letter in ((str, "U"), (bytes, "S"), (bool | np.bool_, "b")):
            if any(isinstance(v, odd) for v in value):
                return letter
        return "O"
    try:
        return str(np.asarray(value).dtype.kind)
    except Exception:  # an object numpy cannot hold: let the conversion say why
        return "O"


def _first_bad(arr: FloatArray, bad: npt.NDArray[np.bool_]) -> float:
    return float(arr[bad].flat[0])


def check_finite(field: str, value: Any) -> FloatArray:
    """Return ``value`` as a float array, raising if any element is NaN or infinite."""
    arr = _as_float_array(field, value)
    if arr.ndim == 0:
        # One value: plain float comparisons, about ten times cheaper than
        # numpy's reductions on a 0-d array (this is the single-point path).
        if not math.isfinite(float(arr)):
            raise BallScrewInputError(field, float(arr), "finite real numbers")
        return arr
    bad = ~np.isfinite(arr)
    if bad.any():
        raise BallScrewInputError(field, _first_bad(arr, bad), "finite real numbers")
    return arr


def check_positive(field: str, value: Any, unit: str = "") -> FloatArray:
    """Return ``value`` as a float array, raising unless every element is finite and > 0."""
    arr = check_finite(field, value)
    if arr.ndim == 0:
        if not float(arr) > 0.0:
            raise BallScrewInputError(field, float(arr), f"a value > 0 {unit}".rstrip())
        return arr
    bad = arr <= 0.0
    if bad.any():
        raise BallScrewInputError(field, _first_bad(arr, bad), f"a value > 0 {unit}".rstrip())
    return arr


def check_nonnegative(field: str, value: Any, unit: str = "") -> FloatArray:
    """Return ``value`` as a float array, raising unless every element is finite and >= 0."""
    arr = check_finite(field, value)
    if arr.ndim == 0:
        if float(arr) < 0.0:
            raise BallScrewInputError(field, float(arr), f"a value >= 0 {unit}".rstrip())
        return arr
    bad = arr < 0.0
    if bad.any():
        raise BallScrewInputError(field, _first_bad(arr, bad), f"a value >= 0 {unit}".rstrip())
    return arr


def check_in_range(
    field: str,
    value: Any,
    low: float,
    high: float,
    *,
    inclusive: tuple[bool, bool] = (False, False),
    unit: str = "",
) -> FloatArray:
    """Return ``value`` as a float array, raising unless every element lies in the interval.

    ``inclusive`` says whether the lower and upper bounds themselves are allowed.
    """
    arr = check_finite(field, value)

    def error(bad_value: float) -> BallScrewInputError:
        left = "[" if inclusive[0] else "("
        right = "]" if inclusive[1] else ")"
        text = f"a value in {left}{low:g}, {high:g}{right} {unit}".rstrip()
        # to 12 significant digits: a converted input shows as typed (1000, not 1000.0000000000001)
        return BallScrewInputError(field, float(f"{bad_value:.12g}"), text)

    if arr.ndim == 0:
        v = float(arr)
        ok = (v >= low if inclusive[0] else v > low) and (v <= high if inclusive[1] else v < high)
        if not ok:
            raise error(v)
        return arr
    below = arr < low if inclusive[0] else arr <= low
    above = arr > high if inclusive[1] else arr >= high
    bad = below | above
    if bad.any():
        raise error(_first_bad(arr, bad))
    return arr


def check_choice(field: str, value: Any, options: tuple[str, ...] | list[str]) -> str:
    """Return ``value`` if it is one of ``options``, else raise naming them."""
    if not isinstance(value, str) or value not in options:
        raise BallScrewInputError(field, value, f"one of {list(options)}")
    return value


def broadcast_inputs(**arrays: Any) -> list[FloatArray]:
    """Broadcast named arrays against each other; raise naming them if their shapes clash."""
    try:
        return list(np.broadcast_arrays(*arrays.values()))
    except ValueError:
        shapes = ", ".join(f"{k} {np.shape(v)}" for k, v in arrays.items())
        raise BallScrewInputError(
            ", ".join(arrays),
            shapes,
            "array shapes that broadcast against each other (numpy rules)",
        ) from None
