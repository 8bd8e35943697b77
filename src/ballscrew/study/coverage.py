r"""Does the check's guard band hold the truth as often as it says? Synthetic cases.

The axis check (:mod:`ballscrew.axis.uncertainty`) draws a row's uncertain
inputs and reports P(NOT OK) and the utilisation's central 95 % interval. This
module tests that machinery on cases whose truth is known: each synthetic case
gets nominal inputs and tolerances from stated distributions, a **true** value
of every uncertain input is drawn from the distribution the check assumes (or,
for the friction, from the scorecard's rows themselves), the true utilisation
is computed with the criterion's formula, and the check's draws
(:func:`~ballscrew.axis.uncertainty.draws`, :func:`~ballscrew.axis.uncertainty.judge`)
are run on the nominal inputs. Two criteria:

``life``
    The fatigue life of a preloaded double nut
    (:func:`ballscrew.axis.criteria.life_utilisation`) over an out-and-back cycle
    (acceleration, a cruise with a process force, deceleration; back without
    the force). Per case: :math:`C_a` log-uniform 10 to 100 kN; preload 2 to
    10 % of :math:`C_a`, uniform; the inertia force log-uniform 2 to 10 % of
    :math:`C_a` and the process force 1 to 10 %; tolerances uniform on
    0 to 20 % (mass), 0 to 30 % (process force), 20 to 45 % (preload, the
    makers' C3 drag-torque bands) and 0 to 15 % (ratings); the required life
    set so that the nominal utilisation is log-uniform on 0.3 to 3.
``thermal``
    The thermal lead error, linear in the friction factor (no pre-tension):
    :math:`u = u_0 k`, :math:`u_0` log-uniform on 0.3 to 3, :math:`k` the
    model's error (:func:`~ballscrew.axis.uncertainty.model_error`). Its truth
    is drawn either from the stated log-normal (``friction="stated"``) or from
    the scorecard (``friction="rows"``): a printed test row of the nut kind and
    level picked at random, :math:`k = (T_{ref}/T_{model})(1 + a\,U)` with
    :math:`a` its band and :math:`U` uniform on -1 to 1, the reference's own
    tolerance. The second is a test of the model error itself: a bias left in,
    or a spread too narrow for the rows, shows as a coverage below 95 %.

:func:`coverage` returns, per case, P(NOT OK), the interval and the truth;
:meth:`Coverage.held` the share of truths inside the interval and
:meth:`Coverage.reliability` the observed share NOT OK per bin of P(NOT OK).
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass
from functools import partial

import numpy as np

from ..axis.criteria import life_utilisation
from ..axis.uncertainty import SAMPLES, draws, judge, model_error
from ..errors import BallScrewInputError, FloatArray

__all__ = ["CRITERIA", "Coverage", "coverage"]

CRITERIA = ("life", "thermal")
"""The criteria the synthetic cases are drawn for."""

_TURNS = np.array([2.0, 2.0, 6.0, 6.0])
"""Turns under each force of the out-and-back cycle: the inertia force forwards
(accelerating out, decelerating back), backwards (decelerating out, accelerating back),
the cruise out with the process force, the cruise back without it."""
_MASS = np.array([1.0, -1.0, 0.0, 0.0])
"""The inertia force's sign under each."""
_PROCESS = np.array([0.0, 0.0, 1.0, 0.0])
"""The process force's share under each: on the outward cruise only."""


@dataclass(frozen=True)
class Coverage:
    """Per synthetic case: the check's P(NOT OK), its 95 % interval, the true utilisation."""

    criterion: str
    p_not_ok: FloatArray
    low: FloatArray
    high: FloatArray
    truth: FloatArray

    def held(self) -> float:
        """The share of cases whose true utilisation lies inside the 95 % interval [-]."""
        return float(np.mean((self.low <= self.truth) & (self.truth <= self.high)))

    def reliability(self, bins: int = 10) -> tuple[FloatArray, FloatArray, FloatArray]:
        """Per bin of P(NOT OK): its mean P, the observed share truly NOT OK, the cases.

        Bins of equal width on 0 to 1; an empty bin gives NaN.
        """
        edges = np.linspace(0.0, 1.0, bins + 1)
        which = np.clip(np.digitize(self.p_not_ok, edges) - 1, 0, bins - 1)
        count = np.bincount(which, minlength=bins).astype(float)
        fails = (self.truth > 1.0).astype(float)
        with np.errstate(invalid="ignore", divide="ignore"):
            mean_p = np.bincount(which, self.p_not_ok, minlength=bins) / count
            observed = np.bincount(which, fails, minlength=bins) / count
        return mean_p, observed, count


def _log_uniform(rng: np.random.Generator, low: float, high: float, n: int) -> FloatArray:
    return np.asarray(np.exp(rng.uniform(math.log(low), math.log(high), n)), dtype=float)


def _life(n: int, rng: np.random.Generator, truth_rng: np.random.Generator) -> Coverage:
    rating = _log_uniform(rng, 10e3, 100e3, n)
    preload = rating * rng.uniform(0.02, 0.10, n)
    inertia = rating * _log_uniform(rng, 0.02, 0.10, n)
    process = rating * _log_uniform(rng, 0.01, 0.10, n)
    tol = np.column_stack([rng.uniform(0.0, 0.20, n), rng.uniform(0.0, 0.30, n),
                           rng.uniform(0.20, 0.45, n), rng.uniform(0.0, 0.15, n)])  # fmt: skip
    u0 = _log_uniform(rng, 0.3, 3.0, n)
    true_k = 1.0 + tol * truth_rng.uniform(-1.0, 1.0, (n, 4))
    life = partial(life_utilisation, preloaded=True, load_factor=1.0)  # ISO 3408-5's own
    m = inertia[:, None] * _MASS
    f = process[:, None] * _PROCESS
    # Nominal hours at 1 rpm; the required life makes the nominal utilisation u0.
    required = u0 / life(m + f, preload, rating, _TURNS, 1.0, 1.0)
    truth = life(true_k[:, :1] * m + true_k[:, 1:2] * f, preload * true_k[:, 2],
                             rating * true_k[:, 3], _TURNS, 1.0, 1.0) * required  # fmt: skip
    # The check's draws: draws(t, ...) is 1 + t U with the same U for every t (one seeded
    # stream per input), so unit tolerances give U, and each case's factors are 1 + t U.
    unit = draws(1.0, 1.0, 1.0, 1.0, 0.0)
    streams = np.stack([unit.mass, unit.force, unit.preload, unit.ratings]) - 1.0
    p, low, high = (np.empty(n) for _ in range(3))
    chunk = max(1, 2_000_000 // (SAMPLES * _TURNS.size))
    for start in range(0, n, chunk):
        sl = slice(start, min(start + chunk, n))
        k = 1.0 + tol[sl, :, None] * streams[None, :, :]  # (cases, 4, draws)
        force = k[:, 0, :, None] * m[sl, None, :] + k[:, 1, :, None] * f[sl, None, :]
        u = life(
            force.reshape(-1, _TURNS.size),
            (preload[sl, None] * k[:, 2]).reshape(-1),
            (rating[sl, None] * k[:, 3]).reshape(-1),
            _TURNS,
            1.0,
            1.0,
        )
        u = u.reshape(-1, SAMPLES) * required[sl, None]  # fmt: skip
        for j, row in enumerate(u, start):
            r = judge(row)
            p[j], low[j], high[j] = r.p_not_ok, r.low, r.high
    return Coverage("life", p, low, high, truth)


def _printed_rows(model: str, nut: str, torque: float) -> tuple[FloatArray, FloatArray]:
    """The scorecard's printed test rows of the nut and level: reference/model, band."""
    from .validation import score

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rows = score([model], trends=False)
    kind = "single-4point" if nut == "single-4point" else "double"
    high = torque >= 1.0
    chosen = [r for r in rows if r.kind == "catalog" and r.nut == kind and not r.training
              and (r.reference >= 1.0) == high and r.predicted > 0.0]  # fmt: skip
    ratio = np.array([r.reference / r.predicted for r in chosen])
    band = np.array([(r.high - r.low) / (2.0 * r.reference) for r in chosen])
    if kind == "single-4point":
        # The 4-point reference's ratio, 1.2 to 1.32 (FOUR_POINT_RANGE), around its 1.25.
        from ..axis.uncertainty import FOUR_POINT_RANGE

        lo, hi = FOUR_POINT_RANGE
        band = np.hypot(band, (hi - lo) / 2.0 / 1.25)
    return ratio, band


def _thermal(
    n: int, rng: np.random.Generator, truth_rng: np.random.Generator, friction: str,
    model: str, nut: str, torque: float,
) -> Coverage:  # fmt: skip
    error = model_error(model, nut, torque)
    if math.isnan(error.sigma):
        raise BallScrewInputError("model", model, "a model of the scorecard: catalog, complete")
    u0 = _log_uniform(rng, 0.3, 3.0, n)
    if friction == "stated":
        k_true = np.exp(error.sigma * truth_rng.standard_normal(n) - error.bias)
    else:
        ratio, band = _printed_rows(model, nut, torque)
        pick = truth_rng.integers(0, ratio.size, n)
        k_true = ratio[pick] * (1.0 + band[pick] * truth_rng.uniform(-1.0, 1.0, n))
    d = draws(0.0, 0.0, 0.0, 0.0, error.sigma, friction_bias=error.bias)
    u = u0[:, None] * d.friction[None, :]
    # judge() per case, as the check calls it (its quantiles and its NaN rule).
    results = [judge(row) for row in u]
    p = np.array([r.p_not_ok for r in results])
    low = np.array([r.low for r in results])
    high = np.array([r.high for r in results])
    return Coverage("thermal", p, low, high, u0 * k_true)


def coverage(
    criterion: str, cases: int = 2000, seed: int = 2024, friction: str = "stated",
    model: str = "complete", nut: str = "double", torque: float = 0.3,
) -> Coverage:  # fmt: skip
    """The check's uncertainty on ``cases`` synthetic cases of ``criterion`` (module docstring).

    ``friction`` (thermal only): ``"stated"`` draws the true friction factor
    from the check's log-normal, ``"rows"`` from the scorecard's printed rows
    of ``model``, ``nut`` and the level of ``torque`` [N·m]. The cases come from
    a generator seeded with ``seed``, their truths from another, and the
    check's draws use its own fixed seed (:data:`~ballscrew.axis.uncertainty.SAMPLES`
    draws each).
    """
    if criterion not in CRITERIA:
        raise BallScrewInputError("criterion", criterion, "one of " + ", ".join(CRITERIA))
    if friction not in ("stated", "rows"):
        raise BallScrewInputError("friction", friction, "'stated' or 'rows'")
    if cases < 1:
        raise BallScrewInputError("cases", cases, "at least 1")
    rng = np.random.default_rng(seed)
    truth_rng = np.random.default_rng(seed + 1)
    if criterion == "life":
        return _life(cases, rng, truth_rng)
    return _thermal(cases, rng, truth_rng, friction, model, nut, torque)
