"""Single values at the cost of numbers: numpy's elementwise helpers without their dispatch.

The one-point path of the models does hundreds of elementwise operations on what the layers
pass each other; numpy's ufuncs, ``where`` and broadcasting cost microseconds a call on a
single double, where the same comparison on numbers costs a tenth of that. Each helper here
gives numpy's answer (its rule for NaN and signed zeros included; ``tests/friction/
test_one_point_helpers.py`` compares them) and hands anything but single values to numpy.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..errors import FloatArray

__all__ = ["as_float", "broadcast_shape", "broadcast_to", "every", "maximum", "minimum", "where"]

_FLOAT64 = np.dtype(np.float64)


def as_float(x: Any) -> FloatArray:
    """``numpy.asarray(x, dtype=float)``, but a single double (a float, a numpy float) as it is.

    Arithmetic on a numpy float costs a tenth of that on a 0-d array; the one-point path
    does hundreds of operations on what the layers pass each other.
    """
    if type(x) is float or type(x) is np.float64:
        return x  # type: ignore[return-value]
    return np.asarray(x, dtype=float)


def _one_float(x: Any) -> bool:
    """Whether ``x`` is a single double: a float, a numpy float64 or a 0-d float64 array."""
    kind = type(x)
    return (
        kind is float
        or kind is np.float64
        or (kind is np.ndarray and x.dtype is _FLOAT64 and x.ndim == 0)
    )


def where(condition: Any, x: Any, y: Any) -> FloatArray:
    """``numpy.where(condition, x, y)`` of float values, without its cost at a single point.

    One truth value and two single doubles: the chosen one as a numpy float (numpy gives a
    0-d array of it; the value is the same, and arithmetic on a numpy float costs a tenth
    of that on a 0-d array, which the one-point path does hundreds of times). Anything
    else goes to numpy.
    """
    kind = type(condition)
    if (
        (kind is np.bool_ or kind is bool or (kind is np.ndarray and condition.ndim == 0))
        and _one_float(x)
        and _one_float(y)
    ):
        return np.float64(x if condition else y)  # type: ignore[return-value]
    result: FloatArray = np.where(condition, x, y)
    return result


def maximum(x: Any, y: Any) -> FloatArray:
    """``numpy.maximum(x, y)`` of float values; two single doubles compared as such.

    The larger of the two as a numpy float, by numpy's rule (NaN if either is NaN; of two
    equal values, such as 0.0 and -0.0, the second), without a ufunc's dispatch (a
    microsecond a call on the one-point path).
    """
    if _one_float(x) and _one_float(y):
        a, b = float(x), float(y)
        return np.float64(a if a > b or a != a else b)  # type: ignore[return-value]
    result: FloatArray = np.maximum(x, y)
    return result


def minimum(x: Any, y: Any) -> FloatArray:
    """``numpy.minimum(x, y)`` of float values; two single doubles compared as such."""
    if _one_float(x) and _one_float(y):
        a, b = float(x), float(y)
        return np.float64(a if a < b or a != a else b)  # type: ignore[return-value]
    result: FloatArray = np.minimum(x, y)
    return result


def every(condition: Any) -> bool:
    """``bool(numpy.all(condition))``; a single truth value read as such."""
    if type(condition) is np.bool_ or type(condition) is bool:
        return bool(condition)
    return bool(np.all(condition))


def broadcast_shape(*shapes: tuple[int, ...]) -> tuple[int, ...]:
    """``numpy.broadcast_shapes(*shapes)``, at once where every shape is the same one."""
    first = shapes[0]
    for shape in shapes[1:]:
        if shape != first:
            return np.broadcast_shapes(*shapes)
    return first


def broadcast_to(value: Any, shape: tuple[int, ...]) -> FloatArray:
    """``numpy.broadcast_to(value, shape)``, or ``value`` itself where it has that shape.

    The same values without numpy's view machinery (some microseconds a call, which the
    single-point path pays dozens of times): an array of the shape comes back as it is
    (writable, not a read-only view: the layers never write into what they broadcast).
    """
    if type(value) is np.ndarray and value.shape == shape:
        return value
    if not shape and (type(value) is float or type(value) is np.float64):
        return np.asarray(value)
    result: FloatArray = np.broadcast_to(value, shape)
    return result
