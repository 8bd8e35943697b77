"""The lumped heat balance: energy conserved, exact limits, published correlations."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew import reference_screw
from ballscrew.axis.energy import Axis
from ballscrew.axis.motion import back_and_forth
from ballscrew.axis.thermal import (
    AIR,
    ThermalNode,
    convection_coefficient,
    steady_temperature,
    temperature_history,
)

CYCLE = back_and_forth(0.3, 0.5, 2.0, cycles=1, process_force=2000.0, force_window=(0.05, 0.25))


def test_natural_convection_of_a_still_cylinder() -> None:
    # Churchill and Chu at Ra = g beta dT d^3 / (nu alpha), by hand for a 40 mm
    # cylinder 10 K above 20 °C air (beta = 1/298.15 K).
    k, nu, pr = AIR["conductivity"], AIR["kinematic_viscosity"], AIR["prandtl"]
    ra = 9.80665 / 298.15 * 10.0 * 0.04**3 / (nu * nu / pr)
    nu_d = (0.60 + 0.387 * ra ** (1 / 6) / (1 + (0.559 / pr) ** (9 / 16)) ** (8 / 27)) ** 2
    assert 1e4 < ra < 1e6  # laminar, inside the correlation's range
    assert convection_coefficient(0.04, 0.0, 30.0, 20.0) == pytest.approx(nu_d * k / 0.04)


def test_steady_state_heat_in_equals_heat_out() -> None:
    node = ThermalNode(screw_length=1.0, ambient=20.0, machine_resistance=2.0)
    s = steady_temperature(CYCLE, reference_screw(), "mineral ISO VG 68", Axis(moving_mass=200.0),
                           node)  # fmt: skip
    assert s.temperature > 20.0
    # The root is found to 1e-11 K on the balance itself: it holds to rounding.
    assert s.heat_out == pytest.approx(s.friction_power, rel=1e-9)


def test_history_with_constant_power_and_conductance_is_the_exponential() -> None:
    # The catalogue model's friction does not depend on temperature, and forced
    # convection at the cycle's speed does not either (it exceeds natural
    # convection here), so T = Ta + P/G (1 - exp(-G t / C)) exactly.
    screw = reference_screw()
    node = ThermalNode(screw_length=1.0, ambient=20.0, machine_resistance=2.0, nut_mass=3.0)
    axis = Axis(moving_mass=200.0)
    s = steady_temperature(CYCLE, screw, "mineral ISO VG 68", axis, node, model="catalog")
    t, temp = temperature_history(CYCLE, screw, "mineral ISO VG 68", axis, node, 7200.0,
                                  model="catalog")  # fmt: skip
    capacity = node.heat_capacity(screw)
    expected = 20.0 + s.friction_power / s.conductance * (1 - np.exp(-s.conductance * t / capacity))
    np.testing.assert_allclose(temp, expected, rtol=1e-5)
    # Heat capacity of steel: 7850 kg/m^3 * pi/4 * 0.04^2 m^2 * 1 m * 460 J/(kg K) + 3 kg * 460.
    assert capacity == pytest.approx((7850 * math.pi / 4 * 0.04**2 + 3.0) * 460.0, rel=1e-12)


def test_a_run_of_years_settles_on_the_steady_temperature_at_once() -> None:
    # Issue 35: a run time of 1e6 h held the solver for minutes. The exponential of the
    # test above reaches its steady value after a few C/G (here about an hour): a run of
    # 10 years ends at the steady temperature, and its first hours follow the exponential.
    import time

    screw = reference_screw()
    node = ThermalNode(screw_length=1.0, ambient=20.0, machine_resistance=2.0, nut_mass=3.0)
    axis = Axis(moving_mass=200.0)
    s = steady_temperature(CYCLE, screw, "mineral ISO VG 68", axis, node, model="catalog")
    start = time.process_time()
    years = 10 * 8760 * 3600.0
    t, temp = temperature_history(CYCLE, screw, "mineral ISO VG 68", axis, node, years,
                                  model="catalog", points=100_001)  # fmt: skip
    assert time.process_time() - start < 5.0  # CPU seconds; 0.2.0 took minutes
    assert temp[-1] == pytest.approx(s.temperature, abs=1e-6)
    early = t < 4 * 3600.0
    tau = node.heat_capacity(screw) / s.conductance
    expected = 20.0 + s.friction_power / s.conductance * (1 - np.exp(-t[early] / tau))
    np.testing.assert_allclose(temp[early], expected, rtol=1e-5)


def test_run_time_and_steady_speeds_have_limits() -> None:
    from ballscrew.axis.duty import profile_from_move, run_energy
    from ballscrew.errors import BallScrewInputError
    from ballscrew.io.case import load_case

    case = load_case()
    profile = profile_from_move({"stroke": 0.3, "feed": 0.5, "acceleration": 2.0}, 1)
    with pytest.raises(BallScrewInputError, match=r"--run-time.*at most 100 000 h"):
        run_energy(case, profile, ["catalog"], run_time=1e30 * 3600.0)
    with pytest.raises(BallScrewInputError, match=r"--steady-speeds.*at most 1000 speeds"):
        run_energy(case, profile, ["catalog"], steady_speeds=np.linspace(1.0, 300.0, 1001))


def test_mean_powers_over_temperatures_in_one_call_match_each_cycle() -> None:
    from ballscrew.axis.energy import axis_cycle
    from ballscrew.axis.thermal import mean_powers

    screw, axis = reference_screw(), Axis(moving_mass=200.0, dn_limit=1.5e5)
    temps = np.array([20.0, 35.0, 60.0])
    powers = mean_powers(CYCLE, screw, "mineral ISO VG 68", axis, temps)
    each = [axis_cycle(CYCLE, screw, "mineral ISO VG 68", axis, temperature=t).friction_energy
            / CYCLE.duration for t in temps]  # fmt: skip
    np.testing.assert_allclose(powers, each, rtol=1e-12)
    assert powers[0] > powers[-1]  # thinner oil, less friction


def test_steady_at_speeds_balances_each_speed_as_a_separate_calculation_does() -> None:
    from ballscrew import friction_torque
    from ballscrew.axis.thermal import steady_at_speeds

    screw = reference_screw()
    node = ThermalNode(screw_length=0.8, ambient=22.0, machine_resistance=3.0)
    omega = np.array([20.0, 100.0, 250.0])
    s = steady_at_speeds(screw, "mineral ISO VG 68", node, omega, axial_load=1000.0)
    for w, temp in zip(omega, s.temperature, strict=True):
        # Heat in: the model's torque at this speed and temperature, by a
        # separate call. Heat out: convection over the screw plus the path
        # into the machine.
        torque = float(friction_torque(screw, "mineral ISO VG 68", speed=w, temperature=temp,
                                       axial_load=1000.0).total)  # fmt: skip
        h = float(convection_coefficient(screw.pitch_diameter, w, temp, 22.0))
        out = (h * math.pi * screw.pitch_diameter * 0.8 + 1 / 3.0) * (temp - 22.0)
        # Bisection to 200 K / 2^50 = 2e-13 K; heat in and out agree to the
        # torque's rounding.
        assert torque * w == pytest.approx(out, rel=1e-8)
    assert np.all(np.diff(s.temperature) > 0.0)  # faster runs warmer


def test_steady_at_one_speed_is_the_cycle_steady_state_of_constant_running() -> None:
    from ballscrew.axis.motion import Profile
    from ballscrew.axis.thermal import steady_at_speeds

    screw = reference_screw()
    node = ThermalNode(screw_length=1.0, ambient=20.0, machine_resistance=2.0)
    omega = 150.0
    v = omega * screw.lead / (2 * math.pi)
    t = np.linspace(0.0, 10.0, 5)
    steady_run = Profile(t, v * t, np.full(5, v), np.zeros(5), np.zeros(5))
    cyc = steady_temperature(steady_run, screw, "mineral ISO VG 68", Axis(moving_mass=0.0), node)
    at = steady_at_speeds(screw, "mineral ISO VG 68", node, [omega])
    # Two solvers (scalar bisection over the cycle's mean power, vectorised
    # bisection over the torque) of the same balance.
    assert float(at.temperature[0]) == pytest.approx(cyc.temperature, abs=1e-6)


def test_rotating_cylinder_correlation_warns_past_its_reynolds_range() -> None:
    # Re = omega d^2 / nu: a 100 mm screw at 7000 rpm reaches 4.6e5, past Kreith's 4.3e5;
    # a 40 mm screw at 3000 rpm (3.2e4) stays inside.
    import warnings as w

    from ballscrew.axis.thermal import convection_coefficient
    from ballscrew.errors import BallScrewValidityWarning

    with pytest.warns(BallScrewValidityWarning, match="Reynolds number 4.6"):
        convection_coefficient(0.1, 7000 * math.pi / 30, 40.0, 20.0)
    with w.catch_warnings():
        w.simplefilter("error")
        convection_coefficient(0.04, 3000 * math.pi / 30, 40.0, 20.0)


@pytest.mark.parametrize("length, resistance", [(0.7, None), (1.3, 2.5)])
def test_cycle_conductance_is_convection_over_the_screw_plus_the_machine_path(
    length: float, resistance: float | None
) -> None:
    # G = h pi d L + 1/R_m, with h the rotating-cylinder value at the cycle's RMS speed and
    # the steady temperature, recomputed here; no machine path when R_m is None.
    from ballscrew.axis.thermal import _rms_speed

    screw = reference_screw()
    node = ThermalNode(screw_length=length, ambient=20.0, machine_resistance=resistance)
    s = steady_temperature(CYCLE, screw, "mineral ISO VG 68", Axis(moving_mass=200.0), node)
    h = float(convection_coefficient(0.04, _rms_speed(CYCLE, screw), s.temperature, 20.0))
    expected = h * math.pi * 0.04 * length + (0.0 if resistance is None else 1.0 / resistance)
    assert s.conductance == pytest.approx(expected, rel=1e-12)


def test_heat_capacity_of_a_bare_screw_and_the_history_from_ambient() -> None:
    # No nut mass given: the steel cylinder alone, 7850 * pi/4 * d^2 * L * 460 J/K.
    screw = reference_screw()
    node = ThermalNode(screw_length=0.7)
    assert node.heat_capacity(screw) == pytest.approx(7850 * math.pi / 4 * 0.04**2 * 0.7 * 460.0)
    t, temp = temperature_history(CYCLE, screw, "mineral ISO VG 68", Axis(moving_mass=200.0),
                                  node, 600.0, model="catalog", points=11)  # fmt: skip
    assert t[0] == 0.0 and t[-1] == 600.0 and temp[0] == 20.0


def test_a_node_that_cannot_shed_its_heat_names_the_speed_and_the_limit() -> None:
    # 1 mm of screw in still air at 3000 rpm: the friction cannot leave below 200 K above the
    # ambient, and the message says the limit in °C.
    from ballscrew.axis.thermal import steady_at_speeds
    from ballscrew.errors import BallScrewInputError

    node = ThermalNode(screw_length=1e-3, ambient=25.0)
    with pytest.raises(BallScrewInputError, match="shed below 225 °C"):
        steady_at_speeds(reference_screw(), "mineral ISO VG 68", node, [314.0])


def test_estimated_length_of_a_single_nut_counts_its_turns_once() -> None:
    # travel + (turns + 1) * circuits * lead + 4 d, the nut counted once for a single nut.
    from ballscrew.axis.thermal import estimated_screw_length

    s = reference_screw().replace(nut="single", preload=0.0)
    expected = 0.3 + (s.loaded_turns + 1.0) * s.circuits * s.lead + 4 * s.pitch_diameter
    assert estimated_screw_length(s, 0.3) == pytest.approx(expected, rel=1e-12)
