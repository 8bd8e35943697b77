"""The single-value shortcuts of ``ballscrew.errors`` give numpy's values (issue 51).

``where``, ``maximum``, ``minimum``, ``every``, ``as_float``, ``broadcast_shape`` and
``broadcast_to`` take one point's values without numpy's dispatch; numpy's own functions are the
reference, on the awkward values too (NaN, signed zeros, infinities), and arrays must
go to numpy unchanged. Exact comparison: a choice between two values makes no rounding.
"""

from __future__ import annotations

import itertools
import math

import numpy as np
import pytest

from ballscrew.numerics.single import (
    as_float,
    broadcast_shape,
    broadcast_to,
    every,
    maximum,
    minimum,
    where,
)

AWKWARD = [0.0, -0.0, 1.5, -2.25, math.inf, -math.inf, math.nan, 5e-324, 1.7976931348623157e308]
KINDS = [float, np.float64, np.asarray]


def _same(a: object, b: object) -> bool:
    """Equal to the bit (NaN equal to NaN, -0.0 unequal to 0.0)."""
    x, y = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    return x.shape == y.shape and x.tobytes() == y.tobytes()


@pytest.mark.parametrize("kind_x, kind_y", list(itertools.product(KINDS, KINDS)))
def test_maximum_minimum_of_single_values_are_numpys(kind_x: object, kind_y: object) -> None:
    for a, b in itertools.product(AWKWARD, AWKWARD):
        x, y = kind_x(a), kind_y(b)  # type: ignore[operator]
        # Of two equal values (0.0 and -0.0) numpy returns the second; so must these.
        assert _same(maximum(x, y), np.maximum(x, y)), (a, b)
        assert _same(minimum(x, y), np.minimum(x, y)), (a, b)


@pytest.mark.parametrize("condition", [True, False, np.bool_(True), np.bool_(False),
                                       np.asarray(True), np.asarray(False)])  # fmt: skip
def test_where_of_single_values_is_numpys(condition: object) -> None:
    for a, b in itertools.product(AWKWARD, AWKWARD):
        assert _same(where(condition, a, np.float64(b)), np.where(condition, a, b)), (a, b)


def test_arrays_go_to_numpy() -> None:
    x = np.array([1.0, math.nan, -0.0, 3.0])
    y = np.array([2.0, 0.0, 0.0, -math.inf])
    c = x > 1.0
    assert _same(where(c, x, y), np.where(c, x, y))
    assert _same(maximum(x, y), np.maximum(x, y))
    assert _same(minimum(x, 0.5), np.minimum(x, 0.5))
    assert every(np.array([True, True])) and not every(np.array([True, False]))
    assert every(np.bool_(True)) and not every(False)


def test_broadcasts_are_numpys() -> None:
    assert broadcast_shape((3, 1), (3, 1)) == (3, 1)
    assert broadcast_shape((3, 1), (1, 4), ()) == np.broadcast_shapes((3, 1), (1, 4), ())
    with pytest.raises(ValueError):
        broadcast_shape((3,), (4,))
    a = np.arange(6.0).reshape(2, 3)
    assert broadcast_to(a, (2, 3)) is a  # the array itself where the shape fits
    assert _same(broadcast_to(a[0], (2, 3)), np.broadcast_to(a[0], (2, 3)))
    assert _same(broadcast_to(2.5, ()), np.broadcast_to(2.5, ()))
    assert _same(broadcast_to(np.float64(-0.0), (2,)), np.broadcast_to(-0.0, (2,)))


def test_as_float_is_numpys_asarray() -> None:
    for value in (2.5, np.float64(-0.0), np.asarray(3.0), [1.0, 2.0], 4, np.int64(7)):
        assert _same(as_float(value), np.asarray(value, dtype=float)), value
    single = np.float64(1.25)
    assert as_float(single) is single  # a single double comes back as it is
