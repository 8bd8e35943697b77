"""The heat balance on the cycle's distinct samples (issue 25): the former solver's numbers.

``steady_temperature`` used to bisect the balance 60 times, each step running the friction
model over every sample of the profile; it now tabulates the balance once over temperature
on the cycle's distinct (speed, force) samples and polishes the root on the balance itself.
The references here are the former path, written out: the mean power from
``axis_cycle``'s sample-by-sample trapezoidal rule and a 60-step bisection. Tolerances:
mean powers to a relative 1e-12 (the order of a sum changes), steady temperatures to
1e-9 K (the former bisection stops at 200 K / 2^61; the new root at 1e-11 K).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew import reference_screw
from ballscrew.axis.energy import Axis, axis_cycle
from ballscrew.axis.motion import back_and_forth
from ballscrew.axis.thermal import (
    ThermalNode,
    _CyclePowers,
    _rms_speed,
    convection_coefficient,
    mean_powers,
    steady_temperature,
)

OIL = "mineral ISO VG 68"
AXIS = Axis(moving_mass=200.0, dn_limit=1.5e5)  # no speed warning: the test is the heat


def _cycles(n: int):  # type: ignore[no-untyped-def]
    return back_and_forth(0.3, 0.5, 2.0, cycles=n, process_force=2000.0,
                          force_window=(0.05, 0.25))  # fmt: skip


def _former_mean_power(profile, model: str, temperature: float) -> float:  # type: ignore[no-untyped-def]
    r = axis_cycle(profile, reference_screw(), OIL, AXIS, temperature=temperature, model=model)
    return r.friction_energy / profile.duration


def _former_steady(profile, node: ThermalNode, model: str) -> float:  # type: ignore[no-untyped-def]
    screw = reference_screw()
    area = math.pi * screw.pitch_diameter * node.screw_length
    machine = 0.0 if node.machine_resistance is None else 1.0 / node.machine_resistance
    speed = _rms_speed(profile, screw)

    def imbalance(t: float) -> float:
        h = float(convection_coefficient(screw.pitch_diameter, speed, t, node.ambient))
        return _former_mean_power(profile, model, t) - (h * area + machine) * (t - node.ambient)

    lo, hi = node.ambient, node.ambient + 200.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if imbalance(mid) > 0.0 else (lo, mid)
    return 0.5 * (lo + hi)


def test_mean_powers_of_several_cycles_are_the_sample_by_sample_rule() -> None:
    profile = _cycles(3)
    temps = [20.0, 47.5, 90.0]
    got = mean_powers(profile, reference_screw(), OIL, AXIS, temps)
    want = [_former_mean_power(profile, "complete", t) for t in temps]
    np.testing.assert_allclose(got, want, rtol=1e-12)


def test_repeated_cycles_add_no_distinct_samples() -> None:
    one = _CyclePowers(_cycles(1), reference_screw(), OIL, AXIS, "complete", {})
    five = _CyclePowers(_cycles(5), reference_screw(), OIL, AXIS, "complete", {})
    assert five.omega.size == one.omega.size < _cycles(1).time.size
    np.testing.assert_allclose(five(40.0), one(40.0), rtol=1e-12)


@pytest.mark.parametrize(
    "model, resistance", [("harris-simplified", None), ("olaru", 2.0), ("catalog", 0.5)]
)
def test_steady_temperature_is_the_former_bisection(model: str, resistance: float | None) -> None:
    profile = _cycles(1)
    node = ThermalNode(screw_length=1.0, ambient=20.0, machine_resistance=resistance)
    s = steady_temperature(profile, reference_screw(), OIL, AXIS, node, model=model)
    assert s.temperature == pytest.approx(_former_steady(profile, node, model), abs=1e-9)
    assert s.friction_power == pytest.approx(
        _former_mean_power(profile, model, s.temperature), rel=1e-12
    )


@pytest.mark.parametrize("model", ["complete", "harris-full"])
def test_cycle_friction_on_distinct_samples_is_the_sample_by_sample_call(model: str) -> None:
    # axis_cycle runs the model once per distinct (speed, force) and spreads the result back;
    # the reference is friction_torque over every sample (to a relative 1e-12).
    from ballscrew import friction_torque
    from ballscrew.axis.energy import screw_motion

    profile, screw = _cycles(3), reference_screw()
    r = axis_cycle(profile, screw, OIL, AXIS, temperature=35.0, model=model)
    omega, _, force = screw_motion(profile, screw, AXIS)
    direct = friction_torque(screw, OIL, speed=omega, temperature=35.0, axial_load=force,
                             model=model, warn=False)  # fmt: skip
    np.testing.assert_allclose(r.friction_torque, direct.total, rtol=1e-12, atol=0.0)
    np.testing.assert_allclose(r.friction.efficiency, direct.efficiency, rtol=1e-12, atol=1e-15)
    for name, part in direct.components.items():
        np.testing.assert_allclose(r.friction.components[name], part, rtol=1e-12, atol=1e-18)
    assert [str(w) for w in r.friction.warnings] == [str(w) for w in direct.warnings]
    assert r.friction.speed.shape == omega.shape
