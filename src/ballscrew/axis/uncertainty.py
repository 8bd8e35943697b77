r"""How sure a verdict of the axis check is: the probability of NOT OK and a guard band.

Every verdict of :func:`ballscrew.axis.run_check` compares a utilisation
:math:`u` (value over limit, above 1 fails) with 1. Its inputs are not exact:

* **the model's error** (:func:`model_error`): the friction torque of a model
  against the makers' printed values, from ``data/model_scatter.csv``
  (written by ``scripts/model_scatter.py``: :math:`\log_{10}` of predicted over
  reference per row of the scorecard, grouped by reference, nut, speed range,
  torque level, and training and test rows apart). Only the **printed** test
  rows count: the makers' drag-torque rule (THK A-688) at their test speed of
  100 rpm, within their printed C3 band. The scorecard holds no measured
  torque; its Jungnickel rows are a *law* (1000 to 3000 rpm, viscous regime),
  shown beside the error when the cycle runs there and never counted. **Bias
  and scatter apart**: the rows' mean log ratio :math:`b` moves the median of
  the true torque to :math:`T_{model}\,e^{-b}`; its spread is
  :math:`\sigma^2 = s^2(1 + 1/n) + u_{ref}^2`, with :math:`s` the rows'
  standard deviation about their mean, :math:`1/n` for the mean estimated from
  :math:`n` rows, and :math:`u_{ref}` the reference's own uncertainty (its band
  read as uniform, :math:`a/\sqrt 3`). The model's torque is multiplied by a
  log-normal factor of median :math:`e^{-b}` and that :math:`\sigma`;
* **the case's tolerances** (``[check]`` ``preload_tolerance``,
  ``rating_tolerance``, ``mass_tolerance``, ``force_tolerance``): each a ±
  share, read as a uniform range (a tolerance without a stated distribution,
  as GUM 4.3.7 takes it). Without a preload tolerance the preload takes the
  makers' drag-torque band of grade C3 at the case's catalogue drag torque
  (the preload is set by that torque; THK A-688 Table 13); the others are 0
  when not given, and the check says so.

**Method: Monte Carlo** over :data:`SAMPLES` draws with a fixed seed (the
same draws for every row and every run, so a result reproduces and the
probability is monotonic in the nominal utilisation). Each row is recomputed
from its formula with the drawn inputs, vectorised: the load rows (life,
static safety, lift-off, buckling, root section) from the cycle's force split
into its mass part and its process part; the thermal lead error with the
temperature rise scaled by the friction factor (the heat balance is linear in
the heat); the motor's torques with the friction, mass and process parts of
the motor torque scaled; the inertia ratio with the mass. The tests compare
it with a closed form where one exists (a log-normal utilisation:
:math:`P = \Phi(\ln u_0/\sigma)`), and at :data:`SAMPLES` the probability's
standard error is at most :math:`\sqrt{0.25/4000}` = 0.008.

**Decision rule** (:func:`judge`), after ISO 14253-1's guard bands read on the
utilisation's distribution: **OK with 95 % confidence** when
:math:`P(u > 1) \le 5\,\%`, **NOT OK with 95 % confidence** when
:math:`P(u > 1) \ge 95\,\%`, otherwise **undecided** (neither proven; a
verdict the inputs' tolerances cannot settle). The interval printed is the
utilisation's central 95 % (2.5 % and 97.5 % quantiles).
"""

from __future__ import annotations

import csv
import math
from dataclasses import dataclass
from functools import lru_cache
from importlib import resources
from typing import Any

import numpy as np

from ..errors import FloatArray

__all__ = [
    "CONFIDENCE",
    "FOUR_POINT_RANGE",
    "LAW_SPEED",
    "SAMPLES",
    "SEED",
    "Draws",
    "ModelError",
    "VerdictUncertainty",
    "draws",
    "judge",
    "model_error",
]

SAMPLES = 4000
"""Monte Carlo draws per check [-]."""

SEED = 34
"""Seed of the draws: the same inputs give the same probabilities."""

CONFIDENCE = 0.95
"""Confidence of the guard-banded verdict [-]."""

FOUR_POINT_RANGE = (1.2, 1.32)
"""Range of a 4-point nut's drag torque over a double nut's at equal preload [-]: SKF's
four-point over angular-contact friction coefficients (1.2) to Jungnickel's law (1.32),
:data:`ballscrew.study.validation.FOUR_POINT_RATIO`. The scorecard's 4-point reference is
the printed rule times 1.25; this range, not printed by a maker, is part of its uncertainty."""

LAW_SPEED = 1000.0
"""Speed from which Jungnickel's law applies [rpm] (its rows: 1000 to 3000 rpm)."""


@dataclass(frozen=True)
class VerdictUncertainty:
    """The probability that a row is NOT OK, its utilisation's interval, the guarded verdict."""

    p_not_ok: float
    low: float
    high: float
    guarded: str

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready values."""
        return {
            "p_not_ok": self.p_not_ok,
            "utilisation_95": [self.low, self.high],
            "guarded_verdict": self.guarded,
        }


def judge(samples: FloatArray) -> VerdictUncertainty:
    """P(NOT OK), the central 95 % interval and the guarded verdict of utilisation samples.

    A NaN sample counts as NOT OK (never a silent pass), as in
    :func:`ballscrew.axis.check.verdict`.

    >>> r = judge(np.array([0.5, 0.8, 1.2, 0.9]))
    >>> r.p_not_ok, r.guarded
    (0.25, 'undecided')
    """
    u = np.asarray(samples, dtype=float)
    fails = np.isnan(u) | (u > 1.0)
    p = float(np.mean(fails))
    finite = u[~np.isnan(u)]
    if finite.size:
        low, high = (float(q) for q in np.quantile(finite, [0.025, 0.975]))
    else:
        low = high = math.nan
    if p <= 1.0 - CONFIDENCE:
        guarded = "OK (95 %)"
    elif p >= CONFIDENCE:
        guarded = "NOT OK (95 %)"
    else:
        guarded = "undecided"
    return VerdictUncertainty(p, low, high, guarded)


@dataclass(frozen=True)
class Draws:
    """Factors on the nominal inputs, one per draw (median 1)."""

    mass: FloatArray
    force: FloatArray
    preload: FloatArray
    ratings: FloatArray
    friction: FloatArray

    def __getitem__(self, index: slice) -> Draws:
        """The draws ``index`` (a block of them) of every factor."""
        return Draws(self.mass[index], self.force[index], self.preload[index],
                     self.ratings[index], self.friction[index])  # fmt: skip


def draws(
    mass: float, force: float, preload: float, ratings: float, friction_sigma: float,
    samples: int = SAMPLES, seed: int = SEED, friction_bias: float = 0.0,
) -> Draws:  # fmt: skip
    r"""Uniform factors 1 ± each tolerance and a log-normal friction factor.

    The friction factor is :math:`\exp(-b + \sigma z)`, :math:`z` standard
    normal, with ``friction_sigma`` :math:`\sigma` and ``friction_bias``
    :math:`b` the standard deviation and the mean of :math:`\ln(T_{model}/T)`
    (:class:`ModelError`). The streams are drawn in a fixed order from one
    seeded generator.
    """
    rng = np.random.default_rng(seed)

    def uniform(t: float) -> FloatArray:
        return np.asarray(1.0 + t * rng.uniform(-1.0, 1.0, samples), dtype=float)

    return Draws(
        mass=uniform(mass),
        force=uniform(force),
        preload=uniform(preload),
        ratings=uniform(ratings),
        friction=np.asarray(
            np.exp(friction_sigma * rng.standard_normal(samples) - friction_bias), dtype=float
        ),
    )


@lru_cache(maxsize=1)
def _scatter_rows() -> tuple[dict[str, str], ...]:
    text = resources.files("ballscrew").joinpath("data/model_scatter.csv").read_text("utf-8")
    lines = [line for line in text.splitlines() if not line.startswith("#")]
    return tuple(csv.DictReader(lines))


@dataclass(frozen=True)
class ModelError:
    r"""A model's error in :math:`\ln T` against the makers' printed values.

    ``bias`` is the mean of :math:`\ln(T_{model}/T_{reference})` (the true
    torque's median is the model's times :math:`e^{-b}`), ``sigma`` the
    standard deviation of :math:`\ln T` about that median, ``rows`` the number
    of rows they come from, ``text`` where they come from. NaN when the model
    has no rows.
    """

    bias: float
    sigma: float
    rows: int
    text: str


def model_error(model: str, nut: str, torque: float, speed: float | None = None) -> ModelError:
    r"""The model's bias and standard uncertainty in :math:`\ln` of its torque, and their source.

    The ``printed`` test rows of ``data/model_scatter.csv`` for ``model``, the
    nut arrangement (a single nut without preload takes the double nuts' rows)
    and the torque level of ``torque`` [N·m], combined as the module docstring
    says. ``speed`` [rpm], where the cycle's friction heat is made: from
    :data:`LAW_SPEED` on, the text adds the model against Jungnickel's law (a
    law, not a measurement) in its range, not counted. A model the scorecard
    does not hold gets NaN and says so.
    """
    level = "below 1 N*m" if torque < 1.0 else "1 N*m and above"
    kind = "single-4point" if nut == "single-4point" else "double"
    rows = [r for r in _scatter_rows()
            if r["model"] == model and r["nut"] == kind and r["role"] == "test"
            and r["level"] == level]  # fmt: skip
    printed = next((r for r in rows if r["reference"] == "printed"), None)
    if printed is None:
        return ModelError(
            math.nan,
            math.nan,
            0,
            f"model error of {model}: not in the scorecard's data (not counted)",
        )
    ln10 = math.log(10.0)
    n = int(printed["rows"])
    mean, sd = float(printed["mean_log10"]), float(printed["sd_log10"])
    ref = float(printed["reference_sd_log10"])
    sigma = math.sqrt(sd**2 * (1.0 + 1.0 / n) + ref**2) * ln10
    text = (f"model error of {model}: {n} test rows against the makers' printed drag torque "
            f"(THK A-688 rule at 100 rpm, {kind} nuts, {level}; no measured rows): bias "
            f"{mean:+.3f} in log10 (the true torque's median is the model's x "
            f"{10.0 ** -mean:.3g}), scatter sd {sd:.3f} (x sqrt(1 + 1/{n})), the printed "
            f"band's own {ref:.3f}: sigma(ln T) = {sigma:.3g}")  # fmt: skip
    if speed is not None and speed >= LAW_SPEED:
        law = next((r for r in rows if r["reference"] == "law"), None)
        text += (f"; the cycle's friction heat is made at about {speed:.0f} rpm, where no "
                 "measured or printed torque exists (the 100 rpm error is used)")  # fmt: skip
        if law is not None:
            text += (f"; against Jungnickel's law there (a law, not a measurement, "
                     f"{law['speed']}, {law['rows']} rows) the model's bias is "
                     f"{float(law['mean_log10']):+.3f} and its scatter "
                     f"{float(law['sd_log10']):.3f} in log10, not counted")  # fmt: skip
    return ModelError(mean * ln10, sigma, n, text)
