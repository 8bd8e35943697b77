"""Fit the complete model's one global constant, the ball-train constant c_B, once.

    .venv/bin/python scripts/fit_ball_train.py

Training set: the rows of data/validation_cases.csv marked ``training`` (double nuts at 5 % of
the dynamic load rating, every other screw of the catalogue table, 100 rpm). The torque is
linear in c_B, T = T0 + c_B * B, so the least-squares fit of log(T) to log(reference) is a 1-D
minimisation. Prints the fitted value, the scatter of the per-case values of c_B that would
match each training case exactly, and the share of training and test cases inside their band.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
from scipy.optimize import minimize_scalar

from ballscrew import friction_torque
from ballscrew.errors import BallScrewValidityWarning
from ballscrew.lubricants import get
from ballscrew.validation import load_cases

RPM = 2 * math.pi / 60


def parts(case: object) -> tuple[float, float]:
    """(torque without ball-ball sliding, ball-ball torque per unit c_B) [N·m]."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        r = friction_torque(
            case.screw, get(case.lubricant), speed=case.speed_rpm * RPM,  # type: ignore[attr-defined]
            temperature=case.temperature, axial_load=case.axial_load,  # type: ignore[attr-defined]
            model="complete", ball_train_constant=1.0,
        )  # fmt: skip
    b = float(r.components["ball_ball"])
    return float(r.total) - b, b


def main() -> None:
    """Run the script."""
    cases = [c for c in load_cases() if c.kind == "catalog"]
    train = [c for c in cases if c.training]
    t0, b = (np.array(v) for v in zip(*(parts(c) for c in train), strict=True))
    ref = np.array([c.reference for c in train])

    def loss(c_b: float) -> float:
        return float(np.sum((np.log(t0 + c_b * b) - np.log(ref)) ** 2))

    fit = minimize_scalar(loss, bounds=(0.0, 1.0), method="bounded", options={"xatol": 1e-6})
    c_b = float(fit.x)
    exact = (ref - t0) / b
    lo, med, hi = np.percentile(exact, [16, 50, 84])
    print(f"training cases: {len(train)} (of {len(cases)} catalogue cases)")
    print(f"fitted ball-train constant c_B = {c_b:.4f}")
    print(f"per-case c_B matching each training case: median {med:.4f}, 16-84 % {lo:.4f}-{hi:.4f}")
    ratio = (t0 + c_b * b) / ref
    print(
        f"training ratio predicted/catalogue: median {np.median(ratio):.3f}, "
        f"range {ratio.min():.3f}-{ratio.max():.3f}, std of log10 {np.std(np.log10(ratio)):.3f}"
    )
    for label, subset in (("training", train), ("test", [c for c in cases if not c.training])):
        t = np.array([sum(parts(c) * np.array([1.0, c_b])) for c in subset])
        inside = np.mean([(c.low <= v <= c.high) for c, v in zip(subset, t, strict=True)])
        print(f"{label}: {inside:.0%} of {len(subset)} cases within +-30 %")


if __name__ == "__main__":
    main()
