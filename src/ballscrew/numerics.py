"""Numerical helpers shared by the models: one bracketing root finder for whole arrays."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import numpy.typing as npt

from .errors import FloatArray

__all__ = ["Index", "illinois"]

Index = slice | npt.NDArray[np.intp]
"""The elements a residual is asked for: all (a slice) or those still iterating."""


def illinois(
    residual: Callable[[FloatArray, Index], FloatArray],
    lo: FloatArray,
    hi: FloatArray,
    f_lo: FloatArray,
    f_hi: FloatArray,
    *,
    xtol: npt.ArrayLike = 0.0,
    rtol: float = 0.0,
    ftol: npt.ArrayLike = 0.0,
    max_iter: int = 200,
) -> FloatArray:
    r"""Roots of an increasing residual, element by element, by the Illinois method.

    Regula falsi on brackets :math:`[lo, hi]` with :math:`f(lo) \le 0 <
    f(hi)`, halving the retained end's value when the same end is kept twice
    (Dowell & Jarratt's Illinois modification, superlinear). All elements
    iterate together; an element stops once :math:`f = 0`, :math:`hi - lo
    \le x_{tol} + r_{tol}|hi|` or :math:`|f| \le f_{tol}`, and the residual
    is then evaluated only on the others (``residual(x, index)`` receives the
    trial values and the indices of the flattened elements they belong to).

    Parameters
    ----------
    residual : callable
        ``residual(x, index)`` for the flattened elements ``index``.
    lo, hi, f_lo, f_hi : numpy.ndarray
        Brackets and the residual there, of one shape.
    xtol, rtol, ftol : float or array_like
        Stopping tolerances (arrays broadcast to the shape of ``lo``).
    max_iter : int
        Iterations at most.

    Returns
    -------
    numpy.ndarray
        The last trial value of every element (the root within the tolerances).

    References
    ----------
    .. [1] M. Dowell, P. Jarratt, "A modified regula falsi method for
       computing the root of an equation", BIT 11 (1971) 168-174,
       doi:10.1007/BF01934364.

    Examples
    --------
    >>> c = np.array([2.0, 3.0, 10.0])
    >>> x = illinois(lambda x, i: x * x - c[i], np.zeros(3), np.full(3, 4.0),
    ...              -c, 16.0 - c, xtol=1e-14)
    >>> np.allclose(x, np.sqrt(c))
    True
    """
    shape = np.shape(lo)
    lo = np.array(lo, dtype=float).reshape(-1)
    hi = np.array(hi, dtype=float).reshape(-1)
    f_lo = np.array(np.broadcast_to(f_lo, shape), dtype=float).reshape(-1)
    f_hi = np.array(np.broadcast_to(f_hi, shape), dtype=float).reshape(-1)
    x_tol = np.broadcast_to(np.asarray(xtol, dtype=float), shape).reshape(-1)
    f_tol = np.broadcast_to(np.asarray(ftol, dtype=float), shape).reshape(-1)
    n = lo.size
    side = np.zeros(n, dtype=int)
    x = hi.copy()
    active: npt.NDArray[np.intp] = np.arange(n)
    for _ in range(max_iter):
        if active.size == 0:
            break
        a_lo, a_hi, a_flo, a_fhi = lo[active], hi[active], f_lo[active], f_hi[active]
        denom = a_fhi - a_flo
        guess = np.where(
            denom > 0.0,
            a_hi - a_fhi * (a_hi - a_lo) / np.where(denom > 0.0, denom, 1.0),
            0.5 * (a_lo + a_hi),
        )
        guess = np.clip(guess, a_lo, a_hi)
        f = residual(guess, active)
        right = f > 0.0
        kept = side[active]
        hi[active] = np.where(right, guess, a_hi)
        f_hi[active] = np.where(right, f, np.where(kept == -1, 0.5 * a_fhi, a_fhi))
        lo[active] = np.where(right, a_lo, guess)
        f_lo[active] = np.where(right, np.where(kept == 1, 0.5 * a_flo, a_flo), f)
        side[active] = np.where(right, 1, -1)
        x[active] = guess
        width = hi[active] - lo[active]
        done = (
            (f == 0.0)
            | (width <= x_tol[active] + rtol * np.abs(hi[active]))
            | (np.abs(f) <= f_tol[active])
        )
        active = active[~done]
    result: FloatArray = x.reshape(shape)
    return result
