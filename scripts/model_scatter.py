"""Derive each model's error from the scorecard, once, as data the axis check reads.

Run with ``.venv/bin/python scripts/model_scatter.py`` (it rewrites
``src/ballscrew/data/model_scatter.csv``). Every model is run on every reference
case of ``src/ballscrew/data/validation_cases.csv`` (as ``ballscrew validate``
does, :func:`ballscrew.study.validation.score`), and the log ratio
``log10(predicted / reference)`` of each row is grouped by:

* the reference, named for what it is:

  - ``printed``: the makers' printed preload drag-torque rule (THK A-688) at
    their test conditions, 100 rpm, with their printed acceptance band of
    grade C3 (±20 to 45 % by torque level). For a 4-point nut the rule is
    taken 1.25 times (:data:`ballscrew.study.validation.FOUR_POINT_RATIO`,
    a ratio of 1.2 to 1.32 from published figures, not printed by a maker:
    its range is added to the reference's own uncertainty);
  - ``law``: Jungnickel's empirical loss law at 1000 and 3000 rpm (40 °C),
    a law fitted to measured losses, **not** measurements. It holds in its
    own range (1000 to 3000 rpm, viscous regime) and is written here for
    comparison; the axis check never counts it in a model's error.

  The scorecard holds no measured torque: no group is called ``measured``;
* the nut (``double`` or ``single-4point``) and the speed range of the rows;
* the torque level of the reference: below 1 N·m, or 1 N·m and above;
* the role: ``training`` rows (used to set a constant of a model) and ``test``
  rows (not), kept apart.

Each group gets its number of rows, the mean of the log ratios (the
**bias**), their sample standard deviation (the **scatter**, about that
mean), their root mean square (bias and scatter together, for comparison
with earlier versions) and the reference's own standard uncertainty in log10
(``reference_sd_log10``: the root mean square over the rows of the band
read as uniform, ``band / sqrt(3)`` in ln, and for a 4-point nut the ratio's
range). :func:`ballscrew.axis.uncertainty.model_error` turns a ``printed``
test group into the median and the spread of the check's friction factor.
"""

from __future__ import annotations

import collections
import math
import warnings
from pathlib import Path

import numpy as np

from ballscrew._version import __version__
from ballscrew.axis.uncertainty import FOUR_POINT_RANGE
from ballscrew.study.validation import score

OUT = Path(__file__).resolve().parents[1] / "src" / "ballscrew" / "data" / "model_scatter.csv"
MODELS = ("catalog", "complete")


def _fixed(value: float) -> str:
    """Four decimals, without a negative zero."""
    return f"{round(float(value), 4) + 0.0:.4f}"


def _reference_sd(kind: str, nut: str, reference: float, low: float, high: float) -> float:
    """The reference's own standard uncertainty in ln (module docstring)."""
    if kind == "jungnickel":  # a factor band either way, uniform in ln
        return math.log(high / reference) / math.sqrt(3.0)
    sd = (high - low) / (2.0 * reference) / math.sqrt(3.0)  # the makers' +- share, uniform
    if nut == "single-4point":
        lo, hi = FOUR_POINT_RANGE
        sd = math.hypot(sd, math.log(hi / lo) / 2.0 / math.sqrt(3.0))
    return sd


def main() -> None:
    """Score the models and write the grouped log ratios."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rows = score(list(MODELS), trends=False)
    groups: dict[tuple[str, ...], list[tuple[float, float]]] = collections.defaultdict(list)
    for r in rows:
        if not (r.predicted > 0 and r.reference > 0):
            continue
        law = r.kind == "jungnickel"
        reference = "law" if law else "printed"
        speed = "1000-3000 rpm" if law else "100 rpm"
        level = "below 1 N*m" if r.reference < 1.0 else "1 N*m and above"
        role = "training" if r.training else "test"
        ref_sd = _reference_sd(r.kind, r.nut, r.reference, r.low, r.high) / math.log(10.0)
        key = (r.model, reference, r.nut, speed, level, role)
        groups[key].append((math.log10(r.ratio), ref_sd))
    lines = [
        f"# Model error against the scorecard's reference rows; written by "
        f"scripts/model_scatter.py (ballscrew {__version__}).",
        "# reference: printed = the makers' printed drag-torque rule (THK A-688) and C3 band at "
        "100 rpm (4-point nuts x 1.25, a ratio not printed);",
        "# law = Jungnickel's empirical loss law at 1000-3000 rpm, a law and not a measurement: "
        "for comparison, never counted by the check. No measured rows.",
        "# log10(predicted / reference) per group: rows, mean (bias), sample standard "
        "deviation (scatter), root mean square, the reference's own sd.",
        "model,reference,nut,speed,level,role,rows,mean_log10,sd_log10,rms_log10,"
        "reference_sd_log10",
    ]
    for key in sorted(groups):
        v = np.asarray([g[0] for g in groups[key]])
        ref = float(np.sqrt(np.mean(np.asarray([g[1] for g in groups[key]]) ** 2)))
        sd = float(np.std(v, ddof=1)) if v.size > 1 else math.nan
        rms = float(np.sqrt(np.mean(v**2)))
        lines.append(",".join(key) + f",{v.size},{_fixed(np.mean(v))},{_fixed(sd)},"
                     f"{_fixed(rms)},{_fixed(ref)}")  # fmt: skip
    OUT.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
