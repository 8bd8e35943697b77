"""Print the ball train's targets (issue 38) for each ball-train model of the complete model.

Run with ``.venv/bin/python scripts/ball_train_targets.py``. On the reference screw
(40 x 10 mm, 6.35 mm balls, double nut, 2 kN, mineral ISO VG 68) it prints, for
``ball_train="ratio"`` (the default, F_B = c_B Q) and ``"tolerance"`` (the train from a
contact-angle scatter), each drip-fed (the default for an oil), flooded and with oil-air
(the lubrication method, issue 50):

- T(20 C)/T(40 C) at 100 and 1000 rpm (targets 0.8-1.3 and, for a flooded nut, 1.3-2.2;
  oil-air and drip nuts are reported, not held to the second);
- the speed exponent from 1000 to 3000 rpm (0.1-0.7);
- the preload exponent from 1 to 4 kN at 10, 100 and 3000 rpm (0.9-1.1, 0.9-1.1, 0.45-0.8);
- the forward efficiency under 4 and 8 kN at 1000 rpm (0.88-0.96, rising with load);
- the 4-point/double ratio at equal preload at 1000 rpm (1.15-1.40);
- the loss budget of the double nut and of its 4-point version at 100 and 1000 rpm,
  40 C, by component;
- for the tolerance train, how far its balls are from saturated creep: the creep ratio
  sigma = v_c k sigma_alpha / (|omega_s| a) of each contact, the force G_x it gives
  (saturated: 1), and the contact-angle scatter at which G_x would reach 0.5. A train
  force proportional to the ball load (the makers' linear preload rule) needs saturated
  creep; in the linear range the force grows as mu Q / a, i.e. as Q^(2/3).
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from ballscrew import friction_torque, lubricants, reference_screw
from ballscrew.ball_train import orbital_sensitivity, rolling_creep_integrals
from ballscrew.friction._common import model_state
from ballscrew.friction.complete import CONTACT_ANGLE_SCATTER
from ballscrew.kinematics import kinematics, rpm_to_rad_s

TARGETS = (
    ("T20/T40 at 100 rpm", 0.8, 1.3),
    ("T20/T40 at 1000 rpm", 1.3, 2.2),
    ("speed exponent 1000-3000 rpm", 0.1, 0.7),
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
    runs = [(train, lub) for train in ("ratio", "tolerance") for lub in ("drip", "flooded")]
    for train, lubrication in [*runs, ("ratio", "oil-air")]:

        def run(s, rpm, temp=40.0, load=0.0, train=train, lub=lubrication):  # type: ignore[no-untyped-def]
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                return friction_torque(s, oil, speed=rpm_to_rad_s(rpm), temperature=temp,
                                       axial_load=load, ball_train=train,
                                       lubrication=lub)  # fmt: skip

        def t(s, rpm, temp=40.0):  # type: ignore[no-untyped-def]
            return float(run(s, rpm, temp).total)

        def exponent(rpm: float) -> float:
            lo, hi = (t(screw.replace(preload=f), rpm) for f in (1000.0, 4000.0))
            return math.log(hi / lo) / math.log(4.0)

        values = [
            t(screw, 100.0, 20.0) / t(screw, 100.0),
            t(screw, 1000.0, 20.0) / t(screw, 1000.0),
            math.log(t(screw, 3000.0) / t(screw, 1000.0)) / math.log(3.0),
            exponent(10.0),
            exponent(100.0),
            exponent(3000.0),
            float(run(screw, 1000.0, load=4000.0).efficiency),
            float(run(screw, 1000.0, load=8000.0).efficiency),
            t(screw.replace(nut="single-4point"), 1000.0) / t(screw, 1000.0),
        ]
        print(f"ball_train={train!r}, lubrication={lubrication!r}")
        for (name, low, high), value in zip(TARGETS, values, strict=True):
            verdict = "met" if low <= value <= high else "MISSED"
            print(f"  {name:30s} {value:6.3f}  target {low}-{high}: {verdict}")
        for nut in ("double", "single-4point"):
            for rpm in (100.0, 1000.0):
                r = run(screw.replace(nut=nut), rpm)
                parts = ", ".join(
                    f"{k} {float(v):.3f}" for k, v in r.components.items() if abs(float(v)) > 5e-4
                )
                print(f"  {nut} budget at {rpm:.0f} rpm: {float(r.total):.3f} N*m = {parts}")
    saturation(screw, oil)


def saturation(screw, oil) -> None:  # type: ignore[no-untyped-def]
    """Print how far the tolerance train's creep is from saturation, per contact."""
    state = model_state(screw, oil, rpm_to_rad_s(100.0), 40.0, 0.0, hertz_method="exact",
                        asperity_b=1.42, asperity_c=0.8, state=None)  # fmt: skip
    unit = kinematics(screw, 1.0)
    k = orbital_sensitivity(screw.ball_diameter, screw.pitch_diameter, screw.contact_angle)
    centre = float(unit.orbital_speed) * 0.5 * screw.pitch_diameter / math.cos(screw.lead_angle)
    spread = centre * k * CONTACT_ANGLE_SCATTER  # per unit screw speed [m]
    grid = np.geomspace(1e-3, 10.0, 400)
    print(f"tolerance train creep at sigma_alpha = {math.degrees(CONTACT_ANGLE_SCATTER):.3f} deg")
    for c in state.contacts[:2]:
        a = float(np.ravel(c.hertz.a)[0])
        spin = abs(float(unit.spin_screw if c.side == "screw" else unit.spin_nut))
        aspect = 1.0 / float(np.max(c.hertz.ellipticity))
        _, g = rolling_creep_integrals(aspect, grid)
        ratio = spread / (spin * a)
        half = float(np.interp(0.5, g, grid))
        print(f"  {c.name}: Q {float(np.ravel(c.load)[0]):.1f} N, a {a * 1e3:.3f} mm, "
              f"creep ratio {ratio:.3f}, G_x {float(np.interp(ratio, grid, g)):.3f}; "
              f"G_x = 0.5 needs sigma_alpha = "
              f"{math.degrees(CONTACT_ANGLE_SCATTER * half / ratio):.2f} deg")  # fmt: skip


if __name__ == "__main__":
    main()
