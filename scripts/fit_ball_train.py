"""Fit the complete model's one global constant, the ball-train constant c_B, once.

    .venv/bin/python scripts/fit_ball_train.py

Training set: the rows of data/validation_cases.csv marked ``training`` (double nuts at 5 % of
the dynamic load rating, every other screw of the catalogue table, 100 rpm). The torque grows
with c_B (the ball-ball term is c_B times the ball load times a friction coefficient that itself
depends a little on c_B through the ball-ball contact's film), so the least-squares fit of
log(T) to log(reference) is a 1-D bounded minimisation over c_B with the model evaluated
directly. Prints the fitted value, the scatter of the per-case values of c_B that match each
training case exactly, the share of the reference screw's drag torque that the ball-ball term
carries at 100 and 1000 rpm, and the share of training and test cases inside the makers' band.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from ballscrew import friction_torque, reference_screw
from ballscrew.errors import BallScrewValidityWarning
from ballscrew.lubricants import get
from ballscrew.study.validation import ReferenceCase, load_cases

RAD_PER_S_PER_RPM = 2 * math.pi / 60


def torque(case: ReferenceCase, c_b: float) -> float:
    """The complete model's torque of a case at ball-train constant ``c_b`` [N*m]."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        r = friction_torque(
            case.screw, get(case.lubricant), speed=case.speed_rpm * RAD_PER_S_PER_RPM,
            temperature=case.temperature, axial_load=case.axial_load,
            model="complete", ball_train_constant=c_b,
        )  # fmt: skip
    return float(r.total)


def exact(case: ReferenceCase) -> float:
    """The c_B at which the model meets the case's reference exactly (nan if none <= 1)."""
    f = lambda c: torque(case, c) - case.reference  # noqa: E731
    return brentq(f, 0.0, 1.0, xtol=1e-7) if f(0.0) < 0.0 < f(1.0) else math.nan


def main() -> None:
    """Run the script."""
    cases = [c for c in load_cases() if c.kind == "catalog"]
    train = [c for c in cases if c.training]
    ref = np.array([c.reference for c in train])

    def loss(c_b: float) -> float:
        return float(np.sum((np.log([torque(c, c_b) for c in train]) - np.log(ref)) ** 2))

    fit = minimize_scalar(loss, bounds=(0.0, 0.5), method="bounded", options={"xatol": 1e-6})
    c_b = float(fit.x)
    per_case = np.array([exact(c) for c in train])
    lo, med, hi = np.nanpercentile(per_case, [16, 50, 84])
    print(f"training cases: {len(train)} (of {len(cases)} catalogue cases)")
    print(f"fitted ball-train constant c_B = {c_b:.4f}")
    print(f"per-case c_B matching each training case: median {med:.4f}, 16-84 % {lo:.4f}-{hi:.4f}")
    ratio = np.array([torque(c, c_b) for c in train]) / ref
    print(
        f"training ratio predicted/catalogue: median {np.median(ratio):.3f}, "
        f"range {ratio.min():.3f}-{ratio.max():.3f}, std of log10 {np.std(np.log10(ratio)):.3f}"
    )
    oil = get("mineral ISO VG 68")
    r = friction_torque(reference_screw(), oil, speed=np.array([100.0, 1000.0]) * RAD_PER_S_PER_RPM,
                        temperature=40.0, model="complete", ball_train_constant=c_b)  # fmt: skip
    share = r.components["ball_ball"] / r.total
    print(f"ball-ball share of the reference screw's torque (40 C): {share[0]:.0%} at 100 rpm, "
          f"{share[1]:.0%} at 1000 rpm")  # fmt: skip
    for label, subset in (("training", train), ("test", [c for c in cases if not c.training])):
        t = [torque(c, c_b) for c in subset]
        for nut in ("double", "single-4point"):
            chosen = [(c, v) for c, v in zip(subset, t, strict=True) if c.screw.nut == nut]
            if chosen:
                inside = np.mean([c.low <= v <= c.high for c, v in chosen])
                print(f"{label} {nut}: {inside:.0%} of {len(chosen)} cases inside the makers' band")


if __name__ == "__main__":
    main()
