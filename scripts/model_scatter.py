"""Derive each model's error from the scorecard, once, as data the axis check reads.

Run with ``.venv/bin/python scripts/model_scatter.py`` (it rewrites
``src/ballscrew/data/model_scatter.csv``). Every model is run on every reference
case of ``src/ballscrew/data/validation_cases.csv`` (as ``ballscrew validate``
does, :func:`ballscrew.study.validation.score`), and the log ratio
``log10(predicted / reference)`` of each row is grouped by:

* the reference: ``catalogue`` (the makers' drag torque at a preload, itself
  within its grade's band of ±25 to 45 %) or ``measured`` (Jungnickel's
  measured no-load torques at 1000 and 3000 rpm);
* the nut: ``double`` or ``single-4point``;
* the torque level of the reference: below 1 N·m, or 1 N·m and above;
* the role: ``training`` rows (used to set a constant of a model) and ``test``
  rows (not), kept apart.

Each group gets its number of rows, the mean (the bias), the sample standard
deviation and the root mean square of the log ratios (bias and scatter
together). The axis check takes the test rows' root mean square as the model's
standard uncertainty in ``ln`` (times ln 10), the measured group where there is
one (:mod:`ballscrew.axis.uncertainty`).
"""

from __future__ import annotations

import collections
import math
import warnings
from pathlib import Path

import numpy as np

from ballscrew._version import __version__
from ballscrew.study.validation import score

OUT = Path(__file__).resolve().parents[1] / "src" / "ballscrew" / "data" / "model_scatter.csv"
MODELS = ("catalog", "complete")


def _fixed(value: float) -> str:
    """Four decimals, without a negative zero."""
    return f"{round(float(value), 4) + 0.0:.4f}"


def main() -> None:
    """Score the models and write the grouped log ratios."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rows = score(list(MODELS), trends=False)
    groups: dict[tuple[str, str, str, str, str], list[float]] = collections.defaultdict(list)
    for r in rows:
        if not (r.predicted > 0 and r.reference > 0):
            continue
        reference = "measured" if r.kind == "jungnickel" else "catalogue"
        level = "below 1 N*m" if r.reference < 1.0 else "1 N*m and above"
        role = "training" if r.training else "test"
        groups[(r.model, reference, r.nut, level, role)].append(math.log10(r.ratio))
    lines = [
        f"# Model error against the scorecard's reference rows; written by "
        f"scripts/model_scatter.py (ballscrew {__version__}).",
        "# log10(predicted / reference) per group: rows, mean (bias), sample standard "
        "deviation, root mean square.",
        "model,reference,nut,level,role,rows,mean_log10,sd_log10,rms_log10",
    ]
    for key in sorted(groups):
        v = np.asarray(groups[key])
        sd = float(np.std(v, ddof=1)) if v.size > 1 else math.nan
        rms = float(np.sqrt(np.mean(v**2)))
        lines.append(",".join(key) + f",{v.size},{_fixed(np.mean(v))},{_fixed(sd)},{_fixed(rms)}")
    OUT.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    main()
