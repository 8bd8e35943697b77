r"""Uncertainty propagation and global sensitivity: sampling and Sobol indices (SALib).

The uncertain inputs are :class:`~ballscrew.sweep.uncertainty.Distribution` objects
(normal, uniform, lognormal, in SI). Two designs, both seeded and so
repeatable:

* Monte Carlo (:func:`sample` with ``sobol=False``): a Latin hypercube of
  ``n`` points (McKay, Beckman & Conover 1979), SALib's ``latin.sample``;
  percentiles of the outputs follow from the evaluated points.
* Sobol indices (``sobol=True``): Saltelli's scheme on a scrambled Sobol'
  sequence, SALib's ``sobol.sample`` without second-order terms, giving
  :math:`n(D+2)` points for :math:`D` inputs; :func:`sobol_indices` then
  estimates the first-order indices :math:`S_i = V[E(Y|X_i)]/V(Y)` and the
  total indices :math:`S_{Ti} = E[V(Y|X_{\sim i})]/V(Y)` (Saltelli 2002;
  Saltelli et al. 2010 estimators, as SALib implements them) with bootstrap
  95 % confidence half-widths.

References
----------
.. [1] A. Saltelli, "Making best use of model evaluations to compute
   sensitivity indices", Comput. Phys. Commun. 145 (2002) 280-297,
   doi:10.1016/S0010-4655(02)00280-1.
.. [2] A. Saltelli, P. Annoni, I. Azzini, F. Campolongo, M. Ratto, S.
   Tarantola, "Variance based sensitivity analysis of model output", Comput.
   Phys. Commun. 181 (2010) 259-270, doi:10.1016/j.cpc.2009.09.018.
.. [3] J. Herman, W. Usher, "SALib: an open-source Python library for
   sensitivity analysis", JOSS 2 (2017) 97, doi:10.21105/joss.00097.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from ..errors import BallScrewInputError, FloatArray
from .uncertainty import Distribution

__all__ = ["SobolIndices", "problem", "sample", "sobol_indices"]


@dataclass(frozen=True)
class SobolIndices:
    """First-order and total Sobol indices of one output, with 95 % half-widths."""

    names: tuple[str, ...]
    first: FloatArray
    first_conf: FloatArray
    total: FloatArray
    total_conf: FloatArray

    def as_dict(self) -> dict[str, dict[str, float]]:
        """Input -> its total and first-order index, each with its 95 % half-width."""
        return {
            name: {
                "total": float(self.total[i]), "total_conf": float(self.total_conf[i]),
                "first": float(self.first[i]), "first_conf": float(self.first_conf[i]),
            }
            for i, name in enumerate(self.names)
        }  # fmt: skip

    def ranking(self) -> list[int]:
        """Input positions by decreasing total index."""
        return [int(i) for i in np.argsort(-self.total, kind="stable")]


def problem(inputs: Sequence[Distribution]) -> dict[str, Any]:
    """SALib's problem definition of the inputs."""
    if not inputs:
        raise BallScrewInputError("uncertainty.inputs", [], "at least one uncertain input")
    dists = [d.salib() for d in inputs]
    return {
        "num_vars": len(inputs),
        "names": [d.name for d in inputs],
        "dists": [kind for kind, _ in dists],
        "bounds": [bounds for _, bounds in dists],
    }


def sample(inputs: Sequence[Distribution], n: int, seed: int, *, sobol: bool) -> FloatArray:
    """Input points, one row each, columns in the order of ``inputs`` (SI).

    ``sobol=True``: Saltelli's ``n(D+2)`` rows for :func:`sobol_indices`
    (``n`` a power of 2); otherwise an ``n``-point Latin hypercube.
    """
    from SALib.sample import latin
    from SALib.sample import sobol as sobol_sampler

    spec = problem(inputs)
    if sobol:
        if n < 2 or n & (n - 1):
            raise BallScrewInputError("uncertainty.samples", n, "a power of 2 (at least 2)")
        rows = sobol_sampler.sample(spec, n, calc_second_order=False, seed=seed)
    else:
        rows = latin.sample(spec, n, seed=seed)
    return np.ascontiguousarray(rows, dtype=float)


def sobol_indices(
    inputs: Sequence[Distribution], outputs: npt.ArrayLike, seed: int, resamples: int = 1000
) -> SobolIndices:
    """Sobol indices of a scalar output evaluated at the rows of :func:`sample` (sobol=True)."""
    from SALib.analyze import sobol as sobol_analysis

    y = np.asarray(outputs, dtype=float).reshape(-1)
    d = len(inputs)
    if y.size % (d + 2) or not np.all(np.isfinite(y)):
        raise BallScrewInputError(
            "outputs", f"{y.size} values", f"finite values, a multiple of D + 2 = {d + 2}"
        )
    if float(np.var(y)) == 0.0:  # nothing varies: every index is 0, none is estimable
        zero = np.zeros(d)
        return SobolIndices(tuple(i.name for i in inputs), zero, zero, zero, zero)
    result = sobol_analysis.analyze(
        problem(inputs),
        y,
        calc_second_order=False,
        num_resamples=resamples,
        conf_level=0.95,
        print_to_console=False,
        seed=seed,
    )
    return SobolIndices(
        names=tuple(i.name for i in inputs),
        first=np.asarray(result["S1"], dtype=float),
        first_conf=np.asarray(result["S1_conf"], dtype=float),
        total=np.asarray(result["ST"], dtype=float),
        total_conf=np.asarray(result["ST_conf"], dtype=float),
    )
