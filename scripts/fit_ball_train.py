"""Fit the complete model's ball-train parameter once, for either ball-train model.

    .venv/bin/python scripts/fit_ball_train.py               # ratio: c_B
    .venv/bin/python scripts/fit_ball_train.py tolerance     # tolerance: sigma_alpha

Training set: the rows of data/validation_cases.csv marked ``training`` (double nuts at 5 % of
the dynamic load rating, every other screw of the catalogue table, 100 rpm). The torque grows
with the parameter (``ratio``: the ball-ball term is c_B times the ball load; ``tolerance``: the
ball train's compressions are proportional to the contact-angle scatter sigma_alpha; in both, times
a ball-ball friction coefficient that itself depends a little on the force through the ball-ball
contact's film), so the least-squares fit of log(T) to log(reference) is a 1-D bounded
minimisation with the model evaluated directly. Prints the fitted value, the scatter of the
per-case values that match each training case exactly, the share of the reference screw's drag
torque that the ball-ball term carries at 100 and 1000 rpm, and the share of training and test
cases inside the makers' band.
"""

from __future__ import annotations

import math
import sys
import warnings

import numpy as np
from scipy.optimize import brentq, minimize_scalar

from ballscrew import friction_torque, reference_screw
from ballscrew.errors import BallScrewValidityWarning
from ballscrew.lubricants import get
from ballscrew.study.validation import ReferenceCase, load_cases

RAD_PER_S_PER_RPM = 2 * math.pi / 60

# model -> (parameter, bounds of the fit, upper end of the per-case root search, label)
TRAINS = {
    "ratio": ("ball_train_constant", 0.5, 1.0, "ball-train constant c_B"),
    "tolerance": ("contact_angle_scatter", 0.05, 0.2, "contact-angle scatter sigma_alpha [rad]"),
}


def parameters(train: str, value: float) -> dict[str, object]:
    """The complete model's parameters for ball-train model ``train`` at ``value``."""
    return {"ball_train": train, TRAINS[train][0]: value}


def torque(case: ReferenceCase, train: str, value: float) -> float:
    """The complete model's torque of a case at the ball-train parameter ``value`` [N*m]."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        r = friction_torque(
            case.screw, get(case.lubricant), speed=case.speed_rpm * RAD_PER_S_PER_RPM,
            temperature=case.temperature, axial_load=case.axial_load,
            model="complete", **parameters(train, value),
        )  # fmt: skip
    return float(r.total)


def exact(case: ReferenceCase, train: str) -> float:
    """The value at which the model meets the case's reference exactly (nan if none)."""
    top = TRAINS[train][2]
    f = lambda c: torque(case, train, c) - case.reference  # noqa: E731
    return brentq(f, 0.0, top, xtol=1e-7 * top) if f(0.0) < 0.0 < f(top) else math.nan


def main() -> None:
    """Run the script."""
    train_model = sys.argv[1] if len(sys.argv) > 1 else "ratio"
    _, bound, _, label = TRAINS[train_model]
    cases = [c for c in load_cases() if c.kind == "catalog"]
    train = [c for c in cases if c.training]
    ref = np.array([c.reference for c in train])

    def loss(value: float) -> float:
        t = [torque(c, train_model, value) for c in train]
        return float(np.sum((np.log(t) - np.log(ref)) ** 2))

    fit = minimize_scalar(loss, bounds=(0.0, bound), method="bounded",
                          options={"xatol": 2e-6 * bound})  # fmt: skip
    value = float(fit.x)
    per_case = np.array([exact(c, train_model) for c in train])
    lo, med, hi = np.nanpercentile(per_case, [16, 50, 84])
    print(f"training cases: {len(train)} (of {len(cases)} catalogue cases)")
    print(f"fitted {label} = {value:.4g}")
    print(f"per-case values matching each training case: median {med:.4g}, "
          f"16-84 % {lo:.4g}-{hi:.4g}")  # fmt: skip
    ratio = np.array([torque(c, train_model, value) for c in train]) / ref
    print(
        f"training ratio predicted/catalogue: median {np.median(ratio):.3f}, "
        f"range {ratio.min():.3f}-{ratio.max():.3f}, std of log10 {np.std(np.log10(ratio)):.3f}"
    )
    oil = get("mineral ISO VG 68")
    speeds = np.array([100.0, 1000.0]) * RAD_PER_S_PER_RPM
    r = friction_torque(reference_screw(), oil, speed=speeds, temperature=40.0,
                        model="complete", **parameters(train_model, value))  # fmt: skip
    share = r.components["ball_ball"] / r.total
    print(f"ball-ball share of the reference screw's torque (40 C): {share[0]:.0%} at 100 rpm, "
          f"{share[1]:.0%} at 1000 rpm")  # fmt: skip
    for name, subset in (("training", train), ("test", [c for c in cases if not c.training])):
        t = [torque(c, train_model, value) for c in subset]
        for nut in ("double", "single-4point"):
            chosen = [(c, v) for c, v in zip(subset, t, strict=True) if c.screw.nut == nut]
            if chosen:
                inside = np.mean([c.low <= v <= c.high for c, v in chosen])
                print(f"{name} {nut}: {inside:.0%} of {len(chosen)} cases inside the makers' band")


if __name__ == "__main__":
    main()
