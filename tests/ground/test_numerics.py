"""Tests of the array root finders in ballscrew.numerics against exact roots."""

from __future__ import annotations

import numpy as np

from ballscrew.numerics import illinois, newton_bracketed


def test_newton_finds_square_roots_to_rounding() -> None:
    # x^2 - c has the root sqrt(c) exactly; quadratic convergence reaches it to a few ulps.
    c = np.array([1e-6, 0.5, 2.0, 3.0, 15.9])
    x = newton_bracketed(
        lambda x, i: (x * x - c[i], 2.0 * x), np.zeros(5), np.full(5, 4.0), np.full(5, 4.0),
        xtol=1e-15,
    )  # fmt: skip
    np.testing.assert_allclose(x, np.sqrt(c), rtol=1e-12)


def test_newton_kept_in_its_bracket_on_a_kinked_residual() -> None:
    # A residual whose Newton steps diverge without a bracket, atan(8(x - r)) (Newton
    # from 8|x - r| > 1.39 overshoots further each step). The bracket
    # must hold it: the root r exactly, to the tolerance asked.
    r = np.array([-0.7, 0.0, 0.3, 0.95])
    x = newton_bracketed(
        lambda x, i: (np.arctan(8.0 * (x - r[i])), 8.0 / (1.0 + (8.0 * (x - r[i])) ** 2)),
        np.full(4, -1.0), np.full(4, 1.0), np.full(4, -1.0), xtol=1e-13,
    )  # fmt: skip
    np.testing.assert_allclose(x, r, atol=1e-12)


def test_newton_bisects_where_the_slope_is_zero() -> None:
    # A residual flat at -1 left of 0.5 (slope 0 there: no Newton step), then linear with
    # its root at 0.8: the bracket's midpoints must carry the iteration to the root.
    def residual(x: np.ndarray, i: object) -> tuple[np.ndarray, np.ndarray]:
        flat = x < 0.5
        return np.where(flat, -1.0, (x - 0.8) / 0.3), np.where(flat, 0.0, 1.0 / 0.3)

    x = newton_bracketed(residual, np.zeros(1), np.ones(1), np.zeros(1), xtol=1e-14)
    np.testing.assert_allclose(x, [0.8], atol=1e-13)


def test_newton_and_illinois_agree_on_a_piecewise_linear_table() -> None:
    # The helix's residuals are tables read linearly: a root inside an interval is exact
    # for both methods (a straight line), so they agree to their tolerances.
    nodes = np.linspace(0.0, 1.0, 9)
    values = np.cumsum(np.r_[0.0, np.linspace(0.05, 0.4, 8)]) - 0.6
    slopes = np.diff(values) / np.diff(nodes)

    def with_slope(x: np.ndarray, i: object) -> tuple[np.ndarray, np.ndarray]:
        k = np.clip(np.searchsorted(nodes, x, side="right") - 1, 0, 7)
        return np.interp(x, nodes, values), slopes[k]

    lo, hi = np.zeros(1), np.ones(1)
    x_newton = newton_bracketed(with_slope, lo, hi, np.full(1, 0.1), xtol=1e-14)
    x_illinois = illinois(
        lambda x, i: with_slope(x, i)[0], lo, hi, values[:1], values[-1:], xtol=1e-14
    )
    np.testing.assert_allclose(x_newton, x_illinois, atol=1e-12)
    assert abs(float(np.interp(x_newton[0], nodes, values))) < 1e-12


def _counted(residual):  # type: ignore[no-untyped-def]
    """The residual, and a list that records how many elements each call evaluated."""
    calls: list[int] = []

    def wrapped(x, i):  # type: ignore[no-untyped-def]
        calls.append(np.size(x))
        return residual(x, i)

    return wrapped, calls


def test_illinois_converges_superlinearly() -> None:
    # The cube root of c from the bracket [0, 4] to 1e-14. Illinois converges with order
    # 1.442 (Dowell & Jarratt): 15 evaluations here; plain regula falsi (no halving)
    # stalls on the convex x^3, and bisection needs 48.
    c = np.array([0.3, 2.0, 27.0, 50.0])
    residual, calls = _counted(lambda x, i: x**3 - c[i])
    x = illinois(residual, np.zeros(4), np.full(4, 4.0), -c, 64.0 - c, xtol=1e-14)
    np.testing.assert_allclose(x, np.cbrt(c), rtol=1e-14)
    assert len(calls) <= 16


def test_newton_converges_quadratically() -> None:
    # sqrt(c) from x0 = 4 to 1e-14. Newton's error
    # squares each step: from 4 to sqrt(2) about 7 evaluations; bisection needs 50.
    c = np.array([0.5, 2.0, 3.0, 15.9])
    residual, calls = _counted(lambda x, i: (x * x - c[i], 2.0 * x))
    x = newton_bracketed(residual, np.zeros(4), np.full(4, 4.0), np.full(4, 4.0), xtol=1e-14)
    np.testing.assert_allclose(x, np.sqrt(c), rtol=1e-14)
    assert len(calls) <= 9


def test_each_element_stops_at_its_own_root() -> None:
    # An element started on its root is done after one evaluation and never evaluated
    # again; the others go on: the calls shrink to the elements still iterating.
    c = np.array([4.0, 2.0])
    for solve in ("newton", "illinois"):
        if solve == "newton":
            residual, calls = _counted(lambda x, i: (x * x - c[i], 2.0 * x))
            x = newton_bracketed(residual, np.zeros(2), np.full(2, 3.0), np.array([2.0, 3.0]),
                                 xtol=1e-15)  # fmt: skip
        else:
            # The first element's residual is a line: the first secant lands on its root.
            residual, calls = _counted(lambda x, i: np.where(i == 0, x - 2.0, x * x - c[i]))
            x = illinois(residual, np.zeros(2), np.full(2, 3.0), np.array([-2.0, -2.0]),
                         np.array([1.0, 7.0]), xtol=1e-15)  # fmt: skip
        np.testing.assert_allclose(x, np.sqrt(c), rtol=1e-15)
        assert calls[0] == 2 and all(n == 1 for n in calls[1:]) and len(calls) > 1


def test_a_force_tolerance_alone_stops_both_at_the_root() -> None:
    # Given only ftol (the step tolerance left at its default, 0), both run until |f| is
    # that small: the root of x^2 - c to ftol / f'(root) = 1e-12 / 2.8, not a looser one.
    c = np.array([2.0, 8.0])
    x_i = illinois(lambda x, i: x * x - c[i], np.zeros(2), np.full(2, 4.0), -c, 16.0 - c,
                   ftol=1e-12)  # fmt: skip
    x_n = newton_bracketed(lambda x, i: (x * x - c[i], 2.0 * x), np.zeros(2), np.full(2, 4.0),
                           np.full(2, 4.0), ftol=1e-12)  # fmt: skip
    np.testing.assert_allclose(x_i, np.sqrt(c), atol=1e-12)
    np.testing.assert_allclose(x_n, np.sqrt(c), atol=1e-12)


def test_newton_keeps_its_order_on_a_shallow_residual() -> None:
    # The same roots with the residual scaled by 1e-3 (slopes well below 1): Newton's
    # steps do not depend on the scale, so the count stays that of the unscaled problem.
    c = np.array([0.5, 2.0, 3.0, 15.9])
    residual, calls = _counted(lambda x, i: (1e-3 * (x * x - c[i]), 2e-3 * x))
    x = newton_bracketed(residual, np.zeros(4), np.full(4, 4.0), np.full(4, 4.0), xtol=1e-14)
    np.testing.assert_allclose(x, np.sqrt(c), rtol=1e-14)
    assert len(calls) <= 9
