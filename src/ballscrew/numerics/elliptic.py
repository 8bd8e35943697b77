r"""Carlson's symmetric elliptic integrals and the complete integrals K and E.

Hertz's contact ellipse needs the complete elliptic integrals of the first and
second kind at the ellipse's axis ratio. They are computed here in Carlson's
symmetric form, :math:`R_F` and :math:`R_D`, by duplication and a fifth-order
series (B. C. Carlson, "Numerical computation of real or complex elliptic
integrals", Numer. Algorithms 10 (1995) 13-26, algorithms 1 and 4; DLMF 19.36),
on whole arrays, each element stopping at its own step. ``scipy.special`` has
the same integrals, but importing it costs about 0.15 s of CPU in every command;
the two agree to a few units of the last place (``tests/ground/test_startup.py``).
One point takes the same steps on Python floats (the same bits, 50 times faster).
"""

from __future__ import annotations

import functools
import math
from typing import Any

import numpy as np
import numpy.typing as npt

from ..errors import FloatArray

__all__ = ["carlson_rd", "carlson_rf", "complete_integrals"]


def complete_integrals(k: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
    r"""Complete elliptic integrals K and E [-] for an ellipse of axis ratio ``k = a/b >= 1``.

    The parameter is :math:`m = 1 - 1/k^2`. In Carlson's symmetric form, with
    :math:`p = 1 - m = 1/k^2` (DLMF 19.25.1), :math:`\mathcal{F} = R_F(0, p, 1)`
    and :math:`\mathcal{E} = \tfrac13p\,[R_D(0, p, 1) + R_D(0, 1, p)]`, a sum of
    positive terms, so both keep full precision for slender ellipses. Evaluated
    here (:func:`carlson_rf`, :func:`carlson_rd`) rather than with
    ``scipy.special``, whose import costs about 0.15 s of CPU in every command:
    the two agree to a few units of the last place.
    """
    k = np.asarray(k, dtype=float)
    if k.size == 1:  # one geometry: once per process (a ball screw has two)
        one_k, one_e = _complete_integrals_one(float(k.flat[0]))
        return np.full(k.shape, one_k), np.full(k.shape, one_e)
    p = 1.0 / k**2
    big_k: FloatArray = carlson_rf(0.0, p, 1.0)
    big_e: FloatArray = p / 3.0 * (carlson_rd(0.0, p, 1.0) + carlson_rd(0.0, 1.0, p))
    return big_k, big_e


@functools.lru_cache(maxsize=1024)
def _complete_integrals_one(k: float) -> tuple[float, float]:
    """:func:`complete_integrals` at one axis ratio, operation for operation (the same bits)."""
    p = 1.0 / (k * k)
    big_e = p / 3.0 * (_carlson_rd_one(0.0, p, 1.0) + _carlson_rd_one(0.0, 1.0, p))
    return _carlson_rf_one(0.0, p, 1.0), big_e


_EPS = float(np.finfo(float).eps)


def _rf_series(big_x: Any, big_y: Any) -> Any:
    """Carlson's fifth-order series of :math:`R_F` after the duplications (floats or arrays)."""
    big_z = -(big_x + big_y)
    e2 = big_x * big_y - big_z * big_z
    e3 = big_x * big_y * big_z
    return 1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0


def _rd_series(big_x: Any, big_y: Any) -> Any:
    """Carlson's fifth-order series of :math:`R_D` after the duplications (floats or arrays)."""
    big_z = -(big_x + big_y) / 3.0
    xy, zz = big_x * big_y, big_z * big_z
    e2 = xy - 6.0 * zz
    e3 = (3.0 * xy - 8.0 * zz) * big_z
    e4 = 3.0 * (xy - zz) * zz
    e5 = xy * zz * big_z
    return (
        1.0
        - 3.0 * e2 / 14.0
        + e3 / 6.0
        + 9.0 * e2 * e2 / 88.0
        - 3.0 * e4 / 22.0
        - 9.0 * e2 * e3 / 52.0
        + 3.0 * e5 / 26.0
    )


def _duplication(
    x: FloatArray, y: FloatArray, z: FloatArray, a0: FloatArray, q: FloatArray, name: str
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Carlson's duplication of (x, y, z) until each element's spread is below ``q``.

    Returns the mean ``a``, the scale 4**-n and, for R_D (``name == "R_D"``), the
    sum of its terms scale / (sqrt(z) (z + lambda)) (0 for R_F, whose z may be 0);
    each element stops at its own step.
    """
    a, scale, total = a0.copy(), np.ones_like(a0), np.zeros_like(a0)
    for _ in range(100):
        active = q * scale >= np.abs(a)
        if not active.any():
            return a, scale, total
        sx, sy, sz = np.sqrt(x), np.sqrt(y), np.sqrt(z)
        lam = sx * (sy + sz) + sy * sz
        if name == "R_D":
            total = np.where(active, total + scale / (sz * (z + lam)), total)
        x = np.where(active, 0.25 * (x + lam), x)
        y = np.where(active, 0.25 * (y + lam), y)
        z = np.where(active, 0.25 * (z + lam), z)
        a = np.where(active, 0.25 * (a + lam), a)
        scale = np.where(active, 0.25 * scale, scale)
    raise RuntimeError(f"{name} did not converge")  # pragma: no cover - 4-fold per step


def _duplication_one(
    x: float, y: float, z: float, a: float, q: float, name: str
) -> tuple[float, float, float]:
    """:func:`_duplication` at one point, operation for operation (the same bits)."""
    scale, total = 1.0, 0.0
    for _ in range(100):
        if not q * scale >= abs(a):
            return a, scale, total
        sx, sy, sz = math.sqrt(x), math.sqrt(y), math.sqrt(z)
        lam = sx * (sy + sz) + sy * sz
        if name == "R_D":
            total = total + scale / (sz * (z + lam))
        x, y, z, a = 0.25 * (x + lam), 0.25 * (y + lam), 0.25 * (z + lam), 0.25 * (a + lam)
        scale = 0.25 * scale
    raise RuntimeError(f"{name} did not converge")  # pragma: no cover


def carlson_rf(x: npt.ArrayLike, y: npt.ArrayLike, z: npt.ArrayLike) -> FloatArray:
    r"""Carlson's symmetric elliptic integral of the first kind :math:`R_F(x, y, z)`, x, y, z >= 0.

    Duplication to the relative precision of a double, then the fifth-order
    series (Carlson, Numer. Algorithms 10 (1995) 13-26, algorithm 1), on the
    whole array; each element stops at its own step, so an element's value
    does not depend on the others.
    """
    x, y, z = (np.array(v, dtype=float) for v in np.broadcast_arrays(x, y, z))
    if x.size == 1:  # one geometry: the same steps on Python floats, 50 times faster
        one: FloatArray = np.full(x.shape, _carlson_rf_one(float(x.flat[0]), float(y.flat[0]),
                                                          float(z.flat[0])))  # fmt: skip
        return one
    a0 = (x + y + z) / 3.0
    dx, dy = a0 - x, a0 - y
    q = (3.0 * _EPS) ** (-1.0 / 6.0) * np.maximum(
        np.maximum(np.abs(dx), np.abs(dy)), np.abs(a0 - z)
    )
    a, scale, _ = _duplication(x, y, z, a0, q, "R_F")
    series = _rf_series(dx * scale / a, dy * scale / a)
    result: FloatArray = series / np.sqrt(a)
    return result


def _carlson_rf_one(x: float, y: float, z: float) -> float:
    """:func:`carlson_rf` at one point, operation for operation (the same bits)."""
    a0 = (x + y + z) / 3.0
    dx, dy = a0 - x, a0 - y
    q = (3.0 * _EPS) ** (-1.0 / 6.0) * max(max(abs(dx), abs(dy)), abs(a0 - z))
    a, scale, _ = _duplication_one(x, y, z, a0, q, "R_F")
    series: float = _rf_series(dx * scale / a, dy * scale / a)
    return series / math.sqrt(a)


def _carlson_rd_one(x: float, y: float, z: float) -> float:
    """:func:`carlson_rd` at one point, operation for operation (the same bits)."""
    a0 = (x + y + 3.0 * z) / 5.0
    dx, dy = a0 - x, a0 - y
    q = (0.25 * _EPS) ** (-1.0 / 6.0) * max(max(abs(dx), abs(dy)), abs(a0 - z))
    a, scale, total = _duplication_one(x, y, z, a0, q, "R_D")
    series: float = _rd_series(dx * scale / a, dy * scale / a)
    return scale * series / (a * math.sqrt(a)) + 3.0 * total


def carlson_rd(x: npt.ArrayLike, y: npt.ArrayLike, z: npt.ArrayLike) -> FloatArray:
    r"""Carlson's symmetric elliptic integral of the second kind :math:`R_D(x, y, z)`, z > 0.

    Duplication and the fifth-order series (Carlson 1995, algorithm 4), each
    element stopping at its own step, as :func:`carlson_rf`.
    """
    x, y, z = (np.array(v, dtype=float) for v in np.broadcast_arrays(x, y, z))
    if x.size == 1:  # one geometry: the same steps on Python floats
        one: FloatArray = np.full(x.shape, _carlson_rd_one(float(x.flat[0]), float(y.flat[0]),
                                                          float(z.flat[0])))  # fmt: skip
        return one
    a0 = (x + y + 3.0 * z) / 5.0
    dx, dy = a0 - x, a0 - y
    q = (0.25 * _EPS) ** (-1.0 / 6.0) * np.maximum(
        np.maximum(np.abs(dx), np.abs(dy)), np.abs(a0 - z)
    )
    a, scale, total = _duplication(x, y, z, a0, q, "R_D")
    series = _rd_series(dx * scale / a, dy * scale / a)
    result: FloatArray = scale * series / (a * np.sqrt(a)) + 3.0 * total
    return result
