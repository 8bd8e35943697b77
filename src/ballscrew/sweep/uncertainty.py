"""The uncertain inputs of a sweep file: their distributions and how they are sampled.

``[uncertainty]`` names case fields or model parameters with a normal,
uniform or lognormal distribution (units as in case files) and the sampling:
the number of samples, the seed, Sobol indices or plain Monte Carlo, and the
percentiles reported. :func:`parse_uncertainty` checks it into an
:class:`Uncertainty` in SI units.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from ..errors import BallScrewInputError
from ..io.case import Case
from ..io.units import to_si
from .fields import OPERATING, check_value, field_unit, unknown_keys

__all__ = ["DISTRIBUTIONS", "Distribution", "Uncertainty", "parse_uncertainty"]

UNCERTAINTY_KEYS = ("samples", "seed", "sensitivity", "percentiles", "inputs")
DISTRIBUTIONS: dict[str, tuple[str, str]] = {
    "normal": ("mean", "std"),
    "uniform": ("low", "high"),
    "lognormal": ("median", "sigma"),
}
"""Distribution name -> its two parameters (lognormal: median and the std of ln)."""


@dataclass(frozen=True)
class Distribution:
    """An uncertain input: field name, distribution and its two parameters in SI."""

    name: str
    kind: str
    first: float
    second: float
    unit: str

    def salib(self) -> tuple[str, list[float]]:
        """SALib's name and bounds of this distribution."""
        if self.kind == "normal":
            return "norm", [self.first, self.second]
        if self.kind == "uniform":
            return "unif", [self.first, self.second]
        return "lognorm", [math.log(self.first), self.second]

    def describe(self) -> str:
        """The distribution in words, in SI units."""
        a, b = DISTRIBUTIONS[self.kind]
        unit = f" {self.unit}" if self.unit not in ("", "1") else ""
        second = f"{self.second:g}" if self.kind == "lognormal" else f"{self.second:g}{unit}"
        return f"{self.kind}({a} {self.first:g}{unit}, {b} {second})"


@dataclass(frozen=True)
class Uncertainty:
    """``[uncertainty]``: the uncertain inputs and how they are sampled."""

    inputs: tuple[Distribution, ...]
    samples: int
    seed: int
    sensitivity: str
    percentiles: tuple[float, ...]


def _distribution(where: str, name: str, raw: Any, unit: str | None) -> Distribution:
    if not isinstance(raw, dict) or "distribution" not in raw:
        raise BallScrewInputError(
            where, raw, "a table { distribution = 'normal', mean = ..., std = ... }"
        )
    kind = raw["distribution"]
    if kind not in DISTRIBUTIONS:
        raise BallScrewInputError(f"{where}.distribution", kind, f"one of {list(DISTRIBUTIONS)}")
    a, b = DISTRIBUTIONS[kind]
    unknown_keys(f"{where}.", raw, ["distribution", a, b])
    for key in (a, b):
        if key not in raw:
            raise BallScrewInputError(f"{where}.{key}", "(missing)", f"a value ({kind}: {a}, {b})")
    first = to_si(f"{where}.{a}", raw[a], unit)
    second = to_si(f"{where}.{b}", raw[b], "" if kind == "lognormal" else unit)
    if kind == "uniform" and not second > first:
        raise BallScrewInputError(f"{where}.high", raw[b], f"a value above low ({raw[a]})")
    if kind != "uniform" and not second > 0.0:
        raise BallScrewInputError(f"{where}.{b}", raw[b], "a value > 0")
    if kind == "lognormal" and not first > 0.0:
        raise BallScrewInputError(f"{where}.median", raw[a], "a value > 0")
    return Distribution(name, kind, first, second, unit or "")


def parse_uncertainty(raw: Any, case: Case, models: Sequence[str], taken: set[str]) -> Uncertainty:
    """Check ``[uncertainty]``; ``taken`` holds the fields already varied as axes."""
    if not isinstance(raw, dict):
        raise BallScrewInputError("uncertainty", raw, "a table")
    unknown_keys("uncertainty.", raw, UNCERTAINTY_KEYS)
    sensitivity = raw.get("sensitivity", "none")
    if sensitivity not in ("none", "sobol"):
        raise BallScrewInputError("uncertainty.sensitivity", sensitivity, "'sobol' or 'none'")
    samples = raw.get("samples", 256)
    if isinstance(samples, bool) or not isinstance(samples, int) or not 2 <= samples <= 1 << 24:
        raise BallScrewInputError("uncertainty.samples", samples, "a whole number from 2 to 2^24")
    if sensitivity == "sobol" and samples & (samples - 1):
        raise BallScrewInputError(
            "uncertainty.samples",
            samples,
            "a power of 2 for Sobol indices (the balance of Sobol' points needs it)",
        )
    seed = raw.get("seed", 0)
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise BallScrewInputError("uncertainty.seed", seed, "a whole number >= 0")
    percentiles = raw.get("percentiles", [5, 50, 95])
    if (
        not isinstance(percentiles, list)
        or not percentiles
        or not all(isinstance(p, int | float) and not isinstance(p, bool) for p in percentiles)
        or not all(0 <= p <= 100 for p in percentiles)
    ):
        raise BallScrewInputError(
            "uncertainty.percentiles", percentiles, "a list of numbers from 0 to 100"
        )
    inputs = raw.get("inputs")
    if not isinstance(inputs, dict) or not inputs:
        raise BallScrewInputError(
            "uncertainty.inputs", inputs, "a table of uncertain fields and their distributions"
        )
    found = []
    for name, entry in inputs.items():
        where = f"uncertainty.inputs.{name}"
        if name in OPERATING:
            raise BallScrewInputError(
                where, name, "a case field or model parameter (vary speed etc. under [axes])"
            )
        if name in taken:
            raise BallScrewInputError(where, name, "a field that is not also an axis")
        _, unit = field_unit(name, models, where)
        if unit == "-":
            raise BallScrewInputError(where, name, "a numeric field (text fields have no spread)")
        dist = _distribution(where, name, entry, unit)
        for value in (dist.first, dist.first + dist.second) if dist.kind != "uniform" else ():
            check_value(case, models, where, name, value)
        if dist.kind == "uniform":
            check_value(case, models, f"{where}.low", name, dist.first)
            check_value(case, models, f"{where}.high", name, dist.second)
        found.append(dist)
    if sensitivity == "sobol" and len(found) < 2:
        raise BallScrewInputError(
            "uncertainty.inputs", list(inputs), "at least two inputs for Sobol indices"
        )
    return Uncertainty(
        tuple(found), samples, seed, sensitivity, tuple(float(p) for p in percentiles)
    )
