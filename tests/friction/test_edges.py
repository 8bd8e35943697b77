"""Numerical edges: zero and tiny speeds, extreme viscosities, lift-off, limit angles and shapes.

Warnings are errors in the suite (validity warnings aside), so any numpy
overflow or invalid-value warning that leaked would fail these tests.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

import ballscrew
from ballscrew import BallScrewInputError, Lubricant, friction_torque, lubricants, reference_screw
from ballscrew.contact import ellipticity_exact
from shared import ALL_MODELS, PAO

MODELS = ALL_MODELS
OIL = PAO


def _ok(r: object) -> None:
    total = r.total  # type: ignore[attr-defined]
    assert np.all(np.isfinite(total)) and np.all(total >= 0)
    for value in r.components.values():  # type: ignore[attr-defined]
        assert np.all(np.isfinite(value))


@pytest.mark.parametrize("model", MODELS)
def test_zero_tiny_and_reverse_speeds(model: str) -> None:
    speeds = np.array([0.0, 1e-12, 1e-6, -1e-6, -100.0, 100.0])
    r = friction_torque(reference_screw(), OIL, speed=speeds, temperature=40.0, model=model)
    _ok(r)
    # Friction opposes motion in either direction: same magnitude at +/- speed.
    assert r.total[4] == pytest.approx(r.total[5], rel=1e-12)
    # Continuous at standstill: 1e-12 rad/s is within 1e-3 of the zero-speed value
    # (the Coulomb-like parts remain, the viscous parts vanish).
    assert r.total[1] == pytest.approx(r.total[0], rel=1e-3, abs=1e-9)


@pytest.mark.parametrize("model", MODELS)
@pytest.mark.parametrize(("nu40", "nu100"), [(2e-6, 1e-6), (1e-2, 2e-4)])
def test_extreme_viscosities(model: str, nu40: float, nu100: float) -> None:
    oil = Lubricant.from_viscosities("edge", nu40, nu100, 870.0, 2e-8)
    _ok(
        friction_torque(
            reference_screw(),
            oil,
            speed=np.array([0.0, 1.0, 300.0])[:, None],
            temperature=[0.0, 150.0],
            model=model,
        )
    )


@pytest.mark.parametrize("model", MODELS)
def test_lift_off_and_single_nut(model: str) -> None:
    r = friction_torque(
        reference_screw(),
        OIL,
        speed=50.0,
        temperature=40.0,
        axial_load=[0.0, 2.0**1.5 * 2000.0, 1e5],
        model=model,
    )
    _ok(r)
    single = reference_screw().replace(nut="single", preload=0.0)
    _ok(
        friction_torque(
            single, OIL, speed=50.0, temperature=40.0, axial_load=[0.0, 1e3], model=model
        )
    )


@pytest.mark.parametrize("model", MODELS)
@pytest.mark.parametrize("angle_deg", [0.5, 89.5])
def test_contact_angle_near_its_limits(model: str, angle_deg: float) -> None:
    screw = reference_screw().replace(contact_angle=math.radians(angle_deg))
    _ok(friction_torque(screw, OIL, speed=[0.0, 100.0], temperature=40.0, model=model))


@pytest.mark.parametrize("model", MODELS)
@pytest.mark.parametrize("conformity", [0.5001, 0.52, 5.0, 1e3])
def test_ellipticity_near_one_and_above_fifteen(model: str, conformity: float) -> None:
    screw = reference_screw().replace(conformity_screw=conformity, conformity_nut=conformity)
    ratio = screw.ry_screw / screw.rx_screw
    k = float(ellipticity_exact(max(ratio, 1.0 / ratio)))
    # The solver inverts Hertz's relation; evaluate it forwards with scipy's
    # complete elliptic integrals (m = 1 - 1/k^2): it must give back the
    # radius ratio, here from 1.13 up to 5.6e3, to the solver's tolerance.
    from scipy.special import ellipe, ellipk

    m = 1.0 - 1.0 / k**2
    back = (k**2 * ellipe(m) - ellipk(m)) / (ellipk(m) - ellipe(m)) if k > 1.0 else 1.0
    assert back == pytest.approx(max(ratio, 1.0 / ratio), rel=1e-8)
    if model == "olaru" and conformity == 0.5001:
        # Olaru's hysteresis fit turns negative past a radius ratio of about 1109 (issue 28).
        with pytest.raises(BallScrewInputError, match="radius_ratio"):
            friction_torque(screw, OIL, speed=[0.0, 100.0], temperature=40.0, model=model)
        return
    _ok(friction_torque(screw, OIL, speed=[0.0, 100.0], temperature=40.0, model=model))


def test_ellipticity_near_one_exactly() -> None:
    assert float(ellipticity_exact(1.0 + 1e-15)) == pytest.approx(1.0, abs=1e-14)


@pytest.mark.parametrize(
    "bad", [{"speed": np.inf}, {"temperature": np.nan}, {"temperature": -274.0}]
)
def test_refused_clearly(bad: dict[str, float]) -> None:
    args = {"speed": 1.0, "temperature": 40.0}
    args.update(bad)
    with pytest.raises(BallScrewInputError):
        friction_torque(reference_screw(), OIL, **args)  # type: ignore[arg-type]


def test_clashing_shapes_are_an_input_error() -> None:
    with pytest.raises(BallScrewInputError, match="broadcast"):
        friction_torque(reference_screw(), OIL, speed=[1.0, 2.0, 3.0], temperature=[20.0, 30.0])


def test_viscoelastic_lifted_off_half_nut_at_speed_has_no_friction() -> None:
    # Found by Hypothesis: at lift-off (F_a = 2**1.5 F_pr) the relieved half-nut's balls carry
    # Q = 0; the bracket of the penetration used to fail there at speed. The relieved family
    # must add nothing, so a little more preload (still lifted off) gives the same torque.
    screw = ballscrew.BallScrew(
        pitch_diameter=0.039, lead=0.039, ball_diameter=0.08 * 0.039,
        contact_angle=math.radians(45), conformity_screw=0.5625, conformity_nut=0.5625,
        loaded_turns=2.5, circuits=2, preload=100.0,
    )  # fmt: skip
    oil = lubricants.get("mineral ISO VG 68")
    kw = {"speed": 201.4, "temperature": 10.0, "axial_load": 300.0, "model": "viscoelastic"}
    r = ballscrew.friction_torque(screw, oil, **kw)  # type: ignore[arg-type]
    r2 = ballscrew.friction_torque(screw.replace(preload=105.0), oil, **kw)  # type: ignore[arg-type]
    assert float(r.total) > 0.0
    assert float(r2.total) == pytest.approx(float(r.total), rel=1e-9)
