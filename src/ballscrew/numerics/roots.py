"""Numerical helpers shared by the models: bracketing root finders for whole arrays."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import numpy.typing as npt

from ..errors import FloatArray

__all__ = ["Index", "illinois", "newton_bracketed"]

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


def newton_bracketed(
    residual: Callable[[FloatArray, Index], tuple[FloatArray, FloatArray]],
    lo: FloatArray,
    hi: FloatArray,
    guess: FloatArray,
    *,
    xtol: float = 0.0,
    ftol: npt.ArrayLike = 0.0,
    max_iter: int = 100,
) -> FloatArray:
    r"""Roots of an increasing residual, element by element, by Newton's method kept in a bracket.

    Each element starts from ``guess`` inside :math:`[lo, hi]`, where
    :math:`f(lo) \le 0 \le f(hi)`. Every residual evaluation moves one end of
    the bracket to the trial point (by the sign of :math:`f`); the next trial
    is the Newton step :math:`x - f/f'` when it falls strictly inside the
    bracket, the bracket's midpoint otherwise (a flat or kinked residual, a
    step that overshoots). So it converges quadratically near a smooth root
    and never worse than bisection. An element stops once :math:`f = 0`,
    :math:`|f| \le f_{tol}`, the Newton step is below :math:`x_{tol}`, or
    the bracket is narrower than :math:`x_{tol}`.

    Parameters
    ----------
    residual : callable
        ``residual(x, index)`` returns :math:`f` and :math:`df/dx` at the trial
        values ``x`` of the flattened elements ``index``.
    lo, hi, guess : numpy.ndarray
        Brackets and starting points, of one shape.
    xtol : float
        Stopping tolerance on the step and the bracket width.
    ftol : float or array_like
        Stopping tolerance on :math:`|f|` (arrays broadcast to the shape of ``lo``).
    max_iter : int
        Residual evaluations at most.

    Returns
    -------
    numpy.ndarray
        The last trial value of every element.

    Examples
    --------
    >>> c = np.array([2.0, 3.0, 10.0])
    >>> x = newton_bracketed(lambda x, i: (x * x - c[i], 2.0 * x), np.zeros(3),
    ...                      np.full(3, 4.0), np.full(3, 4.0), xtol=1e-14)
    >>> np.allclose(x, np.sqrt(c), rtol=1e-14)
    True
    """
    shape = np.shape(lo)
    lo = np.array(lo, dtype=float).reshape(-1)
    hi = np.array(hi, dtype=float).reshape(-1)
    x = np.array(np.broadcast_to(guess, shape), dtype=float).reshape(-1)
    f_tol = np.broadcast_to(np.asarray(ftol, dtype=float), shape).reshape(-1)
    active: npt.NDArray[np.intp] = np.arange(lo.size)
    for _ in range(max_iter):
        if active.size == 0:
            break
        xa = x[active]
        f, slope = residual(xa, active)
        right = f > 0.0
        a_lo = np.where(right, lo[active], xa)
        a_hi = np.where(right, xa, hi[active])
        lo[active], hi[active] = a_lo, a_hi
        step = f / np.where(slope > 0.0, slope, np.inf)
        trial = xa - step
        inside = (slope > 0.0) & (trial > a_lo) & (trial < a_hi)
        x[active] = np.where(inside, trial, 0.5 * (a_lo + a_hi))
        done = (
            (f == 0.0)
            | (np.abs(f) <= f_tol[active])
            | (inside & (np.abs(step) <= xtol))
            | (a_hi - a_lo <= xtol)
        )
        x[active] = np.where(done & ~inside, xa, x[active])
        active = active[~done]
    result: FloatArray = x.reshape(shape)
    return result
