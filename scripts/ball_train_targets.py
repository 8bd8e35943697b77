"""Print the ball train's targets (issue 38) for each ball-train model of the complete model.

Run with ``.venv/bin/python scripts/ball_train_targets.py``. On the reference screw
(40 x 10 mm, 6.35 mm balls, double nut, 2 kN, mineral ISO VG 68) it prints, for
``ball_train="ratio"`` (the default, F_B = c_B Q) and ``"tolerance"`` (the train from a
contact-angle scatter):

- T(20 C)/T(40 C) at 100 and 1000 rpm (targets 0.8-1.3 and 1.3-2.2);
- the preload exponent from 1 to 4 kN at 10, 100 and 3000 rpm (0.9-1.1, 0.9-1.1, 0.45-0.8);
- the forward efficiency under 4 and 8 kN at 1000 rpm (0.88-0.96, rising with load);
- the 4-point/double ratio at equal preload at 1000 rpm (1.15-1.40);
- the loss budget at 100 and 1000 rpm, 40 C, by component.
"""

from __future__ import annotations

import math
import warnings

from ballscrew import friction_torque, lubricants, reference_screw
from ballscrew.kinematics import rpm_to_rad_s

TARGETS = (
    ("T20/T40 at 100 rpm", 0.8, 1.3),
    ("T20/T40 at 1000 rpm", 1.3, 2.2),
    ("preload exponent at 10 rpm", 0.9, 1.1),
    ("preload exponent at 100 rpm", 0.9, 1.1),
    ("preload exponent at 3000 rpm", 0.45, 0.8),
    ("efficiency, 4 kN, 1000 rpm", 0.88, 0.96),
    ("efficiency, 8 kN, 1000 rpm", 0.88, 0.96),
    ("4-point/double, 1000 rpm", 1.15, 1.40),
)


def main() -> None:
    """Run the script."""
    screw = reference_screw()
    oil = lubricants.get("mineral ISO VG 68")
    for train in ("ratio", "tolerance"):

        def run(s, rpm, temp=40.0, load=0.0, train=train):  # type: ignore[no-untyped-def]
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                return friction_torque(s, oil, speed=rpm_to_rad_s(rpm), temperature=temp,
                                       axial_load=load, ball_train=train)  # fmt: skip

        def t(s, rpm, temp=40.0):  # type: ignore[no-untyped-def]
            return float(run(s, rpm, temp).total)

        def exponent(rpm: float) -> float:
            lo, hi = (t(screw.replace(preload=f), rpm) for f in (1000.0, 4000.0))
            return math.log(hi / lo) / math.log(4.0)

        values = [
            t(screw, 100.0, 20.0) / t(screw, 100.0),
            t(screw, 1000.0, 20.0) / t(screw, 1000.0),
            exponent(10.0),
            exponent(100.0),
            exponent(3000.0),
            float(run(screw, 1000.0, load=4000.0).efficiency),
            float(run(screw, 1000.0, load=8000.0).efficiency),
            t(screw.replace(nut="single-4point"), 1000.0) / t(screw, 1000.0),
        ]
        print(f"ball_train={train!r}")
        for (name, low, high), value in zip(TARGETS, values, strict=True):
            verdict = "met" if low <= value <= high else "MISSED"
            print(f"  {name:30s} {value:6.3f}  target {low}-{high}: {verdict}")
        for rpm in (100.0, 1000.0):
            r = run(screw, rpm)
            parts = ", ".join(
                f"{k} {float(v):.3f}" for k, v in r.components.items() if abs(float(v)) > 5e-4
            )
            print(f"  budget at {rpm:.0f} rpm: {float(r.total):.3f} N*m = {parts}")


if __name__ == "__main__":
    main()
