r"""How sure a verdict of the axis check is: the probability of NOT OK and a guard band.

Every verdict of :func:`ballscrew.axis.run_check` compares a utilisation
:math:`u` (value over limit, above 1 fails) with 1. Its inputs are not exact:

* **the model's error** (:func:`model_error`): the friction torque of a model
  against the scorecard's reference rows, from ``data/model_scatter.csv``
  (written by ``scripts/model_scatter.py``: :math:`\log_{10}` of predicted over
  reference per row, grouped by reference, nut, torque level, and training and
  test rows apart). The check takes the **test** rows' root mean square (bias
  and scatter together: the bias is not corrected) of the case's nut and
  torque level, the measured rows where the scorecard has them; a catalogue
  reference is itself known only to its grade's band, ±30 % read as uniform,
  which adds :math:`0.3/\sqrt 3` in :math:`\ln`. The model's torque is
  multiplied by a log-normal factor of that standard deviation and median 1;
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
    "CATALOGUE_BAND",
    "CONFIDENCE",
    "SAMPLES",
    "SEED",
    "Draws",
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

CATALOGUE_BAND = 0.30
"""Half-width of the makers' drag-torque band at grade C3, 0.6 to 1 N·m [-] (THK A-688
Table 13): how well a catalogue reference torque is itself known, read as uniform."""


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


def draws(
    mass: float, force: float, preload: float, ratings: float, friction_sigma: float,
    samples: int = SAMPLES, seed: int = SEED,
) -> Draws:  # fmt: skip
    """Uniform factors 1 ± each tolerance and a log-normal friction factor of ``friction_sigma``.

    ``friction_sigma`` is the standard deviation of the logarithm of the model's
    error. The streams are drawn in a fixed order from one seeded generator.
    """
    rng = np.random.default_rng(seed)

    def uniform(t: float) -> FloatArray:
        return np.asarray(1.0 + t * rng.uniform(-1.0, 1.0, samples), dtype=float)

    return Draws(
        mass=uniform(mass),
        force=uniform(force),
        preload=uniform(preload),
        ratings=uniform(ratings),
        friction=np.asarray(np.exp(friction_sigma * rng.standard_normal(samples)), dtype=float),
    )


@lru_cache(maxsize=1)
def _scatter_rows() -> tuple[dict[str, str], ...]:
    text = resources.files("ballscrew").joinpath("data/model_scatter.csv").read_text("utf-8")
    lines = [line for line in text.splitlines() if not line.startswith("#")]
    return tuple(csv.DictReader(lines))


def model_error(model: str, nut: str, torque: float) -> tuple[float, str]:
    r"""The model's standard uncertainty in :math:`\ln` of its torque, and where it comes from.

    The test rows of ``data/model_scatter.csv`` for ``model``, the nut
    arrangement (a single nut without preload takes the double nuts' rows) and
    the torque level of ``torque`` [N·m]: the measured group where there is one,
    else the catalogue group with the catalogue's own band added (module
    docstring). A model the scorecard does not hold gets NaN and says so.
    """
    level = "below 1 N*m" if torque < 1.0 else "1 N*m and above"
    kind = "single-4point" if nut == "single-4point" else "double"
    rows = [r for r in _scatter_rows()
            if r["model"] == model and r["nut"] == kind and r["role"] == "test"]  # fmt: skip
    for reference in ("measured", "catalogue"):
        for r in rows:
            if r["reference"] == reference and r["level"] == level:
                rms = float(r["rms_log10"]) * math.log(10.0)
                text = (f"model error of {model}: {r['rows']} {reference} test rows of the "
                        f"scorecard ({kind} nuts, {level}), rms log10 ratio {r['rms_log10']} "
                        f"(bias {r['mean_log10']})")  # fmt: skip
                if reference == "catalogue":
                    band = CATALOGUE_BAND / math.sqrt(3.0)
                    rms = math.hypot(rms, band)
                    text += f", with the catalogue's own +-{CATALOGUE_BAND:.0%} band"
                return rms, text + f": sigma(ln T) = {rms:.3g}"
    return math.nan, f"model error of {model}: not in the scorecard's data (not counted)"
