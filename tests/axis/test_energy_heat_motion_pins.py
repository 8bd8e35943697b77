"""Pins from the mutation of ``axis/energy.py``, ``axis/motion.py`` and ``axis/thermal.py``.

Each test checks a number against a value worked out by hand here (a closed form of
the catalogue rule, a motion's polynomial, the heat balance's exponential), not
against the code's own output (issue 49).
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew import friction_torque, reference_screw
from ballscrew.axis.energy import (
    Axis,
    axis_cycle,
    friction_energy,
    self_locking,
    weight_back_driving,
)
from ballscrew.axis.motion import Profile
from ballscrew.axis.thermal import ThermalNode
from ballscrew.geometry import BallScrew
from ballscrew.materials import STANDARD_GRAVITY
from shared import PAO

OIL = PAO


def _catalog_terms(mu: float) -> tuple[float, float]:
    """The reference screw's catalogue K = 0.05/sqrt(tan beta) and eta = tan b/tan(b + atan mu)."""
    beta = math.atan(0.01 / (math.pi * 0.04))  # lead 10 mm on a 40 mm pitch diameter
    return 0.05 / math.sqrt(math.tan(beta)), math.tan(beta) / math.tan(beta + math.atan(mu))


# --- axis/energy.py -------------------------------------------------------------------------


def test_a_weight_on_an_inclined_axis_is_its_component_along_the_axis() -> None:
    # 100 kg on an axis inclined by 30 degrees, the catalogue rule (mu = 0.01) on the 2 kN
    # preloaded reference screw: F = m g sin 30 = m g / 2, T = K F_pr l/2pi + F l/2pi
    # (1/eta - 1), so eta' = 1 - 2 pi T/(F l) = 2 - 1/eta - K F_pr/F. Closed form, rounding.
    k, eta = _catalog_terms(0.01)
    force = 100.0 * STANDARD_GRAVITY / 2.0
    expected = 2.0 - 1.0 / eta - k * 2000.0 / force
    axis = Axis(moving_mass=100.0, incline=math.pi / 6)
    got = weight_back_driving(reference_screw(), OIL, axis, model="catalog",
                              friction_coefficient=0.01)  # fmt: skip
    assert got == pytest.approx(expected, rel=1e-12)
    # At 0 kg there is nothing to back-drive: NaN, not a number of a load of 0.
    assert math.isnan(weight_back_driving(reference_screw(), OIL, Axis(moving_mass=0.0,
                                          incline=math.pi / 6), model="catalog"))  # fmt: skip


def test_weight_back_driving_creeps_at_0_1_rad_s_in_oil_at_40_degc_unless_told() -> None:
    # The documented defaults (0.1 rad/s, 40 degC): the complete model's friction depends on
    # both (the film), so another default would change the figure far beyond 1e-9.
    s = reference_screw()
    axis = Axis(moving_mass=300.0, incline=math.pi / 2)
    weight = 300.0 * STANDARD_GRAVITY
    torque = float(friction_torque(s, OIL, speed=0.1, temperature=40.0, axial_load=weight).total)
    expected = 1.0 - 2.0 * math.pi * torque / (weight * s.lead)
    assert weight_back_driving(s, OIL, axis) == pytest.approx(expected, rel=1e-9)


@pytest.mark.parametrize(
    ("ratio", "locked"), [(0.04, False), (0.95, False), (1.05, True), (3.0, True)]
)
def test_a_screw_without_preload_is_self_locking_by_its_friction_angle(
    ratio: float, locked: bool
) -> None:
    # A single nut without preload, the catalogue rule with a friction angle rho = ratio x
    # the lead angle beta (4.55 deg): self-locking when rho reaches beta, at loads from 1 kN
    # up. Close to it (0.95 beta) the reverse efficiency of the load's friction,
    # 2 - 1/eta = 2 - tan(beta + rho)/tan(beta), is only about 0.04 and the verdict still
    # "not locked"; at 1.05 beta it is about -0.06.
    s = reference_screw().replace(nut="single", preload=0.0)
    beta = s.lead_angle
    mu = math.tan(ratio * beta)
    margin = 2.0 - math.tan(beta + ratio * beta) / math.tan(beta)
    assert (margin <= 0.0) == locked  # the verdict worked out first
    assert self_locking(s, OIL, model="catalog", friction_coefficient=mu) is locked


def _creep(speed: float, width: float) -> Profile:
    """1 s at a constant table speed [m/s] on a trajectory whose standstill ramp is ``width``."""
    t = np.linspace(0.0, 1.0, 11)
    v = np.full_like(t, speed)
    zero = np.zeros_like(t)
    return Profile(t, v * t, v, zero, zero, standstill_speed=width)


def test_inside_the_standstill_ramp_the_friction_works_by_its_ramped_sign() -> None:
    # A measured trajectory's ramp of 10 mm/s; at 7.5 mm/s the sign is 2 |v|/v_s - 1 = 0.5,
    # so the drag (the catalogue's preload torque T_p = K F_pr l/2pi, no axial load) works
    # 0.5 T_p omega t; at 20 mm/s (past the ramp) the whole T_p omega t.
    s = reference_screw()
    k, _ = _catalog_terms(0.003)
    t_p = k * 2000.0 * 0.01 / (2.0 * math.pi)
    axis = Axis(moving_mass=0.0)
    for speed, share in ((0.0075, 0.5), (0.02, 1.0)):
        omega = 2.0 * math.pi * speed / 0.01
        r = axis_cycle(_creep(speed, 0.01), s, OIL, axis, model="catalog")
        assert r.friction_energy == pytest.approx(share * t_p * omega * 1.0, rel=1e-12)
        assert r.constant_efficiency_energy == pytest.approx(share * t_p * omega, rel=1e-12)
        energy = friction_energy(_creep(speed, 0.01), s, OIL, axis, model="catalog")
        assert energy == pytest.approx(share * t_p * omega, rel=1e-12)


def test_friction_energy_alone_is_the_cycles_at_the_same_default_temperature() -> None:
    # friction_energy is axis_cycle's figure without the rest; both default to 40 degC. The
    # complete model's friction changes with the oil's temperature (by percent over 4 K).
    from ballscrew.axis.motion import move

    s, axis = reference_screw(), Axis(moving_mass=100.0)
    p = move(0.1, 0.2, 2.0, sample_time=5e-3)
    cycle = axis_cycle(p, s, OIL, axis)
    assert friction_energy(p, s, OIL, axis) == pytest.approx(cycle.friction_energy, rel=1e-12)
    warmer = friction_energy(p, s, OIL, axis, temperature=44.0)
    assert abs(warmer / cycle.friction_energy - 1.0) > 1e-6  # the pin above can see 4 K


def test_the_working_point_back_drives_when_its_reverse_efficiency_is_positive() -> None:
    # 0.2 m/s against 2 kN (the working point): the catalogue rule (mu = 0.01) on a nut
    # without preload has eta' = 2 - 1/eta, about 0.87 > 0: the load back-drives the screw.
    # With the 2 kN preload's drag at 20 N, eta' = 2 - 1/eta - K F_pr/F is far below 0.
    _, eta = _catalog_terms(0.01)
    t = np.linspace(0.0, 1.0, 11)
    v = np.full_like(t, 0.2)
    zero = np.zeros_like(t)
    free = reference_screw().replace(nut="single", preload=0.0)
    r = axis_cycle(Profile(t, v * t, v, zero, zero + 2000.0), free, OIL, Axis(moving_mass=0.0),
                   model="catalog", friction_coefficient=0.01)  # fmt: skip
    assert r.reverse_efficiency == pytest.approx(2.0 - 1.0 / eta, rel=1e-12)
    assert 0.0 < r.reverse_efficiency < 1.0
    assert r.as_dict()["back_drives_at_working_point"] is True
    light = Profile(t, v * t, v, zero, zero + 20.0)
    held = axis_cycle(light, reference_screw(), OIL, Axis(moving_mass=0.0), model="catalog",
                      friction_coefficient=0.01)  # fmt: skip
    k, _ = _catalog_terms(0.01)
    assert held.reverse_efficiency == pytest.approx(2.0 - 1.0 / eta - k * 2000.0 / 20.0,
                                                    rel=1e-12)  # fmt: skip
    assert held.as_dict()["back_drives_at_working_point"] is False


# --- axis/thermal.py: the heat balance of a time series -----------------------------------


def _step(theta: float, power: float, conductance: float, dt: float, tau: float) -> float:
    """Temperature rise after ``dt`` of constant ``power``: the exponential towards P/G."""
    return power / conductance + (theta - power / conductance) * math.exp(-dt / tau)


def test_heat_balance_of_a_constant_power_from_a_warm_start_is_the_exponential() -> None:
    # C dT/dt = P - G (T - T_a) from T(t0) = 35 degC with T_a = 20 degC, P = 12 W, G = 4 W/K,
    # C = 2000 J/K (tau = 500 s): T = T_a + P/G + (T0 - T_a - P/G) e^-(t - t0)/tau, on times
    # that start at 100 s and are unevenly spaced. The steps of tau/100 = 5 s are exact for
    # a constant power, so the grid's points agree to rounding (1e-12 K); between them
    # (401 s) the linear interpolation errs by at most h^2/8 |T''| = 25/8 * 12/500^2 K.
    from ballscrew.axis.thermal import heat_balance

    t = np.array([100.0, 130.0, 400.0, 401.0, 900.0, 2600.0])
    temp = heat_balance(t, np.full(t.size, 12.0), 2000.0, 4.0, 20.0, 35.0)
    exact = 20.0 + 3.0 + (35.0 - 20.0 - 3.0) * np.exp(-(t - 100.0) / 500.0)
    on_grid = np.array([True, True, True, False, True, True])
    np.testing.assert_allclose(temp[on_grid], exact[on_grid], rtol=0.0, atol=1e-12)
    assert abs(temp[3] - exact[3]) < 25.0 / 8.0 * 12.0 / 500.0**2
    # The same through 2 J/K (tau = 0.5 s) over 10 s sampled at 0, 0.3 and 10 s: steps of
    # 5 ms (a hundredth of tau), so 0.3 s is a point of the grid, exact to rounding.
    t = np.array([0.0, 0.3, 10.0])
    temp = heat_balance(t, np.full(3, 12.0), 2.0, 4.0, 20.0, 35.0)
    np.testing.assert_allclose(temp, 23.0 + 12.0 * np.exp(-t / 0.5), rtol=0.0, atol=1e-12)


def test_heat_balance_keeps_the_trapezoidal_energy_of_each_interval() -> None:
    # Power samples 10, 10, 30, 30 W at 0, 1000, 2000, 2500 s: the intervals' trapezoidal
    # means are 10, 20 and 30 W, each held over its interval (the energy of the samples kept).
    # From 20 degC at T_a = 15 degC, G = 2 W/K, C = 1000 J/K (tau = 500 s), the rise is
    # the exponential towards P/G over each interval in turn: exact at the samples, which
    # lie on the 5 s grid (to rounding, 1e-11 K).
    from ballscrew.axis.thermal import heat_balance

    t = np.array([0.0, 1000.0, 2000.0, 2500.0])
    temp = heat_balance(t, np.array([10.0, 10.0, 30.0, 30.0]), 1000.0, 2.0, 15.0, 20.0)
    rise = [5.0]
    for dt, mean in ((1000.0, 10.0), (1000.0, 20.0), (500.0, 30.0)):
        rise.append(_step(rise[-1], mean, 2.0, dt, 500.0))
    np.testing.assert_allclose(temp, 15.0 + np.array(rise), rtol=0.0, atol=1e-11)


def test_heat_balance_of_a_short_series_steps_by_a_hundredth_of_tau() -> None:
    # A power that is 0 W and rises linearly to 40 W over 100 s, on 2 samples only, into
    # C = 400 J/K through G = 1 W/K (tau = 400 s): the step's mean, 20 W, drives the node.
    # One step of 100 s is exact for the constant mean power; steps of 4 s as well (the mean
    # is the same on all of them): T = 20 + 20 (1 - e^-1/4) degC either way, to rounding.
    from ballscrew.axis.thermal import heat_balance

    temp = heat_balance(np.array([0.0, 100.0]), np.array([0.0, 40.0]), 400.0, 1.0, 20.0, 20.0)
    assert temp[0] == 20.0
    assert temp[1] == pytest.approx(20.0 + 20.0 * (1.0 - math.exp(-0.25)), rel=1e-13)


def _air_h(diameter: float, omega: float, rise: float, ambient: float) -> float:
    """h [W/(m^2 K)]: the larger of Kreith's rotating cylinder and Churchill-Chu's still one.

    Air at 300 K: k = 0.0263 W/(m K), nu = 1.589e-5 m^2/s, Pr = 0.707 (Incropera A.4).
    """
    k, nu, pr = 0.0263, 1.589e-5, 0.707
    forced = 0.133 * (omega * diameter**2 / nu) ** (2 / 3) * pr ** (1 / 3) * k / diameter
    film = ambient + rise / 2 + 273.15
    ra = 9.80665 / film * rise * diameter**3 / (nu * nu / pr)
    nu_d = (0.60 + 0.387 * ra ** (1 / 6) / (1 + (0.559 / pr) ** (9 / 16)) ** (8 / 27)) ** 2
    return float(max(forced, nu_d * k / diameter))


@pytest.mark.parametrize("omega", [0.0, 200.0])
def test_series_temperature_of_a_steady_power_is_the_node_balance_by_hand(omega: float) -> None:
    # The 40 mm reference screw, 0.8 m in the air at 22 degC, 2 K/W into the machine, from
    # 30 degC under 6 W. C = rho c pi d^2/4 L (steel: 7850 kg/m^3, 460 J/(kg K)) and
    # G = h pi d L + 1/R_m, with h at the series' RMS speed (the trapezoidal mean of the
    # squares of 0 and omega over its one interval: omega/sqrt 2) and a surface 1 K above
    # the air. Constant power over one time constant: T_a + P/G + (T0 - T_a - P/G)/e,
    # exact at the series' end (a point of the grid), to rounding.
    from ballscrew.axis.thermal import ThermalNode, series_temperature

    node = ThermalNode(screw_length=0.8, ambient=22.0, machine_resistance=2.0)
    d, length = 0.04, 0.8
    capacity = 7850.0 * math.pi * d**2 / 4.0 * length * 460.0
    g = _air_h(d, omega / math.sqrt(2.0), 1.0, 22.0) * math.pi * d * length + 0.5
    t = np.array([0.0, capacity / g])
    temp = series_temperature(t, np.full(2, 6.0), node, reference_screw(),
                              np.array([0.0, omega]), 30.0)  # fmt: skip
    assert temp[0] == 30.0
    assert temp[1] == pytest.approx(22.0 + 6.0 / g + (8.0 - 6.0 / g) / math.e, rel=1e-12)


# --- axis/motion.py --------------------------------------------------------------------------


def test_moves_and_dwells_are_sampled_every_millisecond_unless_told() -> None:
    # 300 mm at 0.5 m/s and 2 m/s^2: phases of 0.25, 0.35 and 0.25 s, whole milliseconds,
    # so 850 steps of exactly 1 ms (to rounding); a dwell of 1 s, 1000; a planned move has
    # the exact sign of its speed (no standstill ramp).
    from ballscrew.axis.motion import back_and_forth, dwell, move

    p = move(0.3, 0.5, 2.0)
    assert p.time.size == 851 and p.standstill_speed == 0.0
    np.testing.assert_allclose(np.diff(p.time), 1e-3, rtol=1e-9)
    assert dwell(1.0).time.size == 1001
    c = back_and_forth(0.3, 0.5, 2.0, dwell_time=0.1)
    np.testing.assert_allclose(np.diff(c.time), 1e-3, rtol=1e-9)
    assert c.time.size == 2 * 850 + 2 * 100 + 1


def test_a_force_window_may_start_at_the_start_and_end_at_the_end_of_the_stroke() -> None:
    # The window [0, s] is the whole move (the default); [0, 100 mm] the first 100 mm.
    from ballscrew.axis.motion import check_force_window, move

    assert check_force_window((0.0, 0.3), 0.3) == (0.0, 0.3)
    p = move(0.3, 0.5, 2.0, process_force=50.0, force_window=(0.0, 0.1))
    np.testing.assert_array_equal(p.process_force > 0.0, np.abs(p.position) <= 0.1)
    # 1e-9 of the stroke past its end is rounding (a unit's conversion), 1e-6 is not.
    assert check_force_window((0.1, 0.3 * (1.0 + 5e-10)), 0.3)[1] > 0.3
    with pytest.raises(Exception, match="inside the stroke, 300 mm"):
        check_force_window((0.1, 0.3 * (1.0 + 1e-6)), 0.3)


def test_a_position_may_step_by_rounding_only_at_a_time_given_twice() -> None:
    # STEP_POSITION = 1e-9 m: a step of 0.9 nm at a repeated time is rounding, 1.05 nm is not.
    from ballscrew.errors import BallScrewInputError

    t = np.array([0.0, 0.5, 0.5, 1.0])
    zero = np.zeros(4)
    for step, ok in ((0.9e-9, True), (1.05e-9, False)):
        x = np.array([0.0, 0.1, 0.1 + step, 0.2])
        if ok:
            assert Profile(t, x, zero, zero, zero).duration == 1.0
        else:
            with pytest.raises(BallScrewInputError, match="position"):
                Profile(t, x, zero, zero, zero)


def test_a_dwell_of_zero_seconds_is_a_move_without_dwell() -> None:
    from ballscrew.axis.motion import parse_move

    m = parse_move("stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2, dwell=0 s")
    assert m == {"stroke": pytest.approx(0.3), "feed": pytest.approx(0.5),
                 "acceleration": pytest.approx(2.0), "dwell": 0.0}  # fmt: skip


def test_back_and_forth_refuses_more_than_five_million_samples_before_making_any() -> None:
    # 3 m at 1.5 m/s and 0.5 m/s^2 (s/v = 2 s, v/a = 3 s) with dwells of 0.25 s: a cycle is
    # at least 2 (2 + 3 + 0.25) = 10.5 s; 300 000 of them at 0.5 s per sample would be
    # 6.3 million samples. The stroke of 1e30 m below shows that the refusal comes before
    # any array is made.
    from ballscrew.axis.motion import back_and_forth
    from ballscrew.errors import BallScrewInputError

    with pytest.raises(BallScrewInputError) as info:
        back_and_forth(-3.0, 1.5, 0.5, dwell_time=0.25, cycles=300_000, sample_time=0.5)
    assert "300000 cycle(s) of 10.5 s" in str(info.value)
    assert "at most 5,000,000 samples of 0.5 s in all (2.5e+06 s of motion)" in str(info.value)
    # A negative dwell is no dwell: 10 s a cycle, 5.2 million samples.
    with pytest.raises(BallScrewInputError, match="260000 cycle\\(s\\) of 10 s"):
        back_and_forth(3.0, 1.5, 0.5, dwell_time=-1.0, cycles=260_000, sample_time=0.5)
    with pytest.raises(BallScrewInputError, match="move"):
        back_and_forth(1e30, 0.5, 0.5)
    # Bad limits are named as the move names them (no division by zero first).
    for kwargs, name in (({"feed": 0.0}, "feed"), ({"acceleration": 0.0}, "acceleration"),
                         ({"sample_time": 0.0}, "sample_time")):  # fmt: skip
        args: dict[str, float] = {"feed": 0.5, "acceleration": 2.0, "sample_time": 1e-3}
        with pytest.raises(BallScrewInputError, match=name):
            back_and_forth(0.3, **(args | kwargs))  # type: ignore[arg-type]


def test_a_stroke_of_0_is_refused_and_one_of_a_metre_is_not() -> None:
    from ballscrew.axis.motion import parse_move
    from ballscrew.errors import BallScrewInputError

    with pytest.raises(BallScrewInputError, match="a stroke, not 0"):
        parse_move("stroke=0 mm, feed=30 m/min, acceleration=2 m/s^2")
    assert parse_move("stroke=1 m, feed=30 m/min, acceleration=2 m/s^2")["stroke"] == 1.0


def test_a_profile_standing_at_one_time_is_refused_as_such() -> None:
    # Two samples at the same time and place: no duration, whatever the position says.
    from ballscrew.errors import BallScrewInputError

    t, zero = np.array([1.0, 1.0]), np.zeros(2)
    with pytest.raises(BallScrewInputError, match="1 s throughout"):
        Profile(t, zero, zero, zero, zero)


# --- axis/thermal.py: the cycle's mean power and its steady state ----------------------------


def _preload_drag() -> float:
    """The catalogue's drag of the 2 kN reference screw, T_p = K F_pr l/2pi [N m]."""
    k, _ = _catalog_terms(0.003)
    return k * 2000.0 * 0.01 / (2.0 * math.pi)


def test_the_cycles_mean_power_is_the_drag_times_the_trapezoidal_mean_screw_speed() -> None:
    # 1 s at +0.1 m/s, then a step to -0.3 m/s held 2 s (a time given twice): the table
    # travels 0.1 + 0.6 m in 3 s. Under the catalogue's drag alone (no load) the mean power
    # is T_p 2 pi (0.7 m / l) / 3 s at every temperature.
    from ballscrew.axis.thermal import mean_powers

    t = np.array([0.0, 1.0, 1.0, 3.0])
    v = np.array([0.1, 0.1, -0.3, -0.3])
    x = np.array([0.0, 0.1, 0.1, -0.5])
    zero = np.zeros(4)
    p = Profile(t, x, v, zero, zero)
    got = mean_powers(p, reference_screw(), OIL, Axis(moving_mass=0.0), [20.0, 60.0], "catalog")
    expected = _preload_drag() * 2.0 * math.pi * 0.7 / 0.01 / 3.0
    np.testing.assert_allclose(got, expected, rtol=1e-12)


@pytest.mark.parametrize(
    ("length", "resistance", "preload"),
    [(1.0, 1.0, 2000.0), (0.02, 20.0, 200.0), (1.0, None, 2000.0), (1.0, 1.0, 20.0)],
)
def test_the_steady_temperature_and_time_constant_of_a_drag_shed_by_forced_convection(
    length: float, resistance: float | None, preload: float
) -> None:
    # 0.25 m/s held (1500 rpm, omega = 157.08 rad/s) under the catalogue's drag alone:
    # P = T_p omega (88.6 W at 2 kN of preload, 8.86 W at 200 N), whatever the temperature.
    # The rotating screw's forced convection (Kreith) beats natural convection at the rise
    # (12 K, 51 K), so G does not depend on the temperature either: G = h pi d L + 1/R_m,
    # T = T_a + P/G (the Illinois root, to 1e-11 K), and the history is
    # T_a + P/G (1 - e^-t/tau), tau = C/G, C = rho c pi d^2/4 L. The second node conducts
    # less than 1 W/K (0.17 W/K): its time constant is 525 s. The third has no path into
    # the machine (convection alone, 14 K); the fourth warms by 0.12 K only.
    from ballscrew.axis.thermal import steady_temperature, temperature_history

    t = np.linspace(0.0, 2.0, 5)
    v = np.full(5, 0.25)
    zero = np.zeros(5)
    p = Profile(t, v * t, v, zero, zero)
    omega = 2.0 * math.pi * 0.25 / 0.01
    power = _preload_drag() * preload / 2000.0 * omega
    node = ThermalNode(screw_length=length, ambient=18.0, machine_resistance=resistance)
    machine = 0.0 if resistance is None else 1.0 / resistance
    g = _air_h(0.04, omega, 12.0, 18.0) * math.pi * 0.04 * length + machine
    s, axis = reference_screw().replace(preload=preload), Axis(moving_mass=0.0)
    st = steady_temperature(p, s, OIL, axis, node, model="catalog")
    assert st.temperature == pytest.approx(18.0 + power / g, abs=1e-9)
    assert st.friction_power == pytest.approx(power, rel=1e-12)
    assert st.conductance == pytest.approx(g, rel=1e-12)
    assert st.heat_out == pytest.approx(power, rel=1e-9)
    tau = 7850.0 * math.pi * 0.04**2 / 4.0 * length * 460.0 / g
    times, temp = temperature_history(p, s, OIL, axis, node, 3.0 * tau, model="catalog",
                                      points=7)  # fmt: skip
    np.testing.assert_allclose(times, np.linspace(0.0, 3.0 * tau, 7), rtol=1e-12)
    # solve_ivp at rtol = atol = 1e-8: the exponential to 1e-6 K.
    np.testing.assert_allclose(temp, 18.0 + power / g * (1.0 - np.exp(-times / tau)), atol=1e-6)


def test_an_s_curve_keeps_a_constant_acceleration_phase_of_half_a_microsecond() -> None:
    # 0.5 m/s, 2 m/s^2 and a jerk of 8.000016 m/s^3: the jerk phases last a/j = 0.249999 s
    # and the constant acceleration between them v/a - a/j = 0.5 us. Left out, the move
    # would end about a t_a t = 2.5e-7 m short; kept, it is s/v + v/a + a/j long and ends
    # at the stroke (to rounding, 1e-12).
    from ballscrew.axis.motion import move

    j = 8.000016
    p = move(0.3, 0.5, 2.0, jerk=j, sample_time=1e-3)
    assert float(p.position[-1]) == pytest.approx(0.3, rel=1e-12)
    assert p.duration == pytest.approx(0.3 / 0.5 + 0.5 / 2.0 + 2.0 / j, rel=1e-12)


def test_refusals_name_the_window_the_line_and_the_sample() -> None:
    from ballscrew.axis.motion import check_force_window, parse_move, read_trajectory
    from ballscrew.errors import BallScrewInputError

    with pytest.raises(BallScrewInputError, match="250 mm to 50 mm"):
        check_force_window((0.25, 0.05), 0.3)
    # Line 1 is the header: the value 'nan' is on line 4; a time repeated on line 4 too.
    with pytest.raises(BallScrewInputError, match="line 4, column position") as info:
        read_trajectory("time [s],position [mm]\n0,0\n1,1\n2,nan\n3,3\n")
    assert "nan" in str(info.value)
    with pytest.raises(BallScrewInputError, match="line 4"):
        read_trajectory("time [s],position [mm]\n0,0\n1,1\n1,2\n2,3\n")
    with pytest.raises(BallScrewInputError, match="--move force") as info:
        parse_move("stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2, force=1,2 kN")
    assert "1,2 kN" in str(info.value)
    with pytest.raises(BallScrewInputError, match="more than 0"):
        parse_move("stroke=300 mm, feed=0 m/min, acceleration=2 m/s^2")
    # The sample whose time goes back, after a time given twice: the 4th (0.4 s after 0.5 s).
    t = np.array([0.0, 0.5, 0.5, 0.4])
    zero = np.zeros(4)
    with pytest.raises(BallScrewInputError, match=r"0\.4 s at sample 4, after 0\.5 s"):
        Profile(t, zero, zero, zero, zero)


def test_a_speed_trace_ramps_its_sign_over_8_times_its_noise_from_6_samples() -> None:
    # Speeds given (not positions): the standstill ramp is 8 times their noise (of second
    # differences); with fewer than 6 samples there is no estimate and the sign is exact.
    from ballscrew.axis.motion import read_trajectory
    from ballscrew.axis.standstill import noise_scatter

    v = [0.0, 0.011, -0.009, 0.012, -0.008, 0.010]
    text = "time [s],speed [m/s]\n" + "\n".join(f"{k},{x}" for k, x in enumerate(v))
    width = 8.0 * noise_scatter(np.array(v), order=2)
    assert width > 0.0
    assert read_trajectory(text).standstill_speed == pytest.approx(width, rel=1e-12)
    short = "time [s],speed [m/s]\n" + "\n".join(f"{k},{x}" for k, x in enumerate(v[:5]))
    assert read_trajectory(short).standstill_speed == 0.0


def test_a_position_jumping_at_a_time_given_twice_is_named_with_both_places() -> None:
    from ballscrew.errors import BallScrewInputError

    t, zero = np.array([0.0, 0.5, 0.5, 1.0]), np.zeros(4)
    x = np.array([0.0, 0.1, 0.2, 0.3])
    with pytest.raises(BallScrewInputError, match=r"0\.1 m then 0\.2 m at 0\.5 s"):
        Profile(t, x, zero, zero, zero)


def test_a_series_of_no_duration_stays_at_its_start() -> None:
    # No time passes: no heat flows (it was 0/0, NaN, before the mutation run found it).
    from ballscrew.axis.thermal import heat_balance, series_temperature

    node = ThermalNode(screw_length=0.8, ambient=22.0, machine_resistance=2.0)
    one = series_temperature(np.array([5.0]), np.array([3.0]), node, reference_screw(),
                             np.array([0.0]), 30.0)  # fmt: skip
    np.testing.assert_array_equal(one, [30.0])
    same = heat_balance(np.array([5.0, 5.0]), np.array([3.0, 3.0]), 100.0, 1.0, 22.0, 30.0)
    np.testing.assert_array_equal(same, [30.0, 30.0])


def test_a_series_starting_later_than_0_s_takes_its_own_duration() -> None:
    # The same one time constant as above from t = 100 s: the RMS speed over the series'
    # own duration (omega/sqrt 2), the result one time constant after its start.
    from ballscrew.axis.thermal import series_temperature

    node = ThermalNode(screw_length=0.8, ambient=22.0, machine_resistance=2.0)
    capacity = 7850.0 * math.pi * 0.04**2 / 4.0 * 0.8 * 460.0
    g = _air_h(0.04, 200.0 / math.sqrt(2.0), 1.0, 22.0) * math.pi * 0.04 * 0.8 + 0.5
    t = np.array([100.0, 100.0 + capacity / g])
    temp = series_temperature(t, np.full(2, 6.0), node, reference_screw(),
                              np.array([0.0, 200.0]), 30.0)  # fmt: skip
    assert temp[1] == pytest.approx(22.0 + 6.0 / g + (8.0 - 6.0 / g) / math.e, rel=1e-12)
    # Speeds of 100 and 200 rad/s: the RMS is sqrt((100^2 + 200^2)/2) = 158.1 rad/s.
    g = _air_h(0.04, math.sqrt(25_000.0), 1.0, 22.0) * math.pi * 0.04 * 0.8 + 0.5
    t = np.array([100.0, 100.0 + capacity / g])
    temp = series_temperature(t, np.full(2, 6.0), node, reference_screw(),
                              np.array([100.0, 200.0]), 30.0)  # fmt: skip
    assert temp[1] == pytest.approx(22.0 + 6.0 / g + (8.0 - 6.0 / g) / math.e, rel=1e-12)
    # A series of 0.8 s at 100 and 200 rad/s is cooled at that RMS speed as well.
    temp = series_temperature(np.array([0.0, 0.8]), np.full(2, 6.0), node, reference_screw(),
                              np.array([100.0, 200.0]), 30.0)  # fmt: skip
    tau = capacity / g
    exact = 22.0 + 6.0 / g + (8.0 - 6.0 / g) * math.exp(-0.8 / tau)
    assert temp[1] == pytest.approx(exact, rel=1e-12)


def test_a_balance_closing_just_past_a_node_of_the_table_is_found_there() -> None:
    # As above, the drag set so that P/G = 10.05 K: the imbalance at the table's node of
    # +10 K is only G x 0.05 K = 0.36 W, still positive; the root is T_a + 10.05 K.
    from ballscrew.axis.thermal import steady_temperature

    omega = 2.0 * math.pi * 0.25 / 0.01
    g = _air_h(0.04, omega, 10.0, 18.0) * math.pi * 0.04 + 1.0
    preload = 2000.0 * (10.05 * g) / (_preload_drag() * omega)
    t = np.linspace(0.0, 2.0, 5)
    v, zero = np.full(5, 0.25), np.zeros(5)
    node = ThermalNode(screw_length=1.0, ambient=18.0, machine_resistance=1.0)
    st = steady_temperature(Profile(t, v * t, v, zero, zero), reference_screw().replace(
        preload=preload), OIL, Axis(moving_mass=0.0), node, model="catalog")  # fmt: skip
    assert st.temperature == pytest.approx(28.05, abs=1e-9)


def test_a_drag_the_node_sheds_only_above_200_k_is_refused() -> None:
    # The catalogue's drag at 0.25 m/s set so that P = 200 K x G + 0.5 W (G by hand as
    # above, 1 m of screw and 1 K/W): the balance closes 0.07 K beyond the range searched.
    from ballscrew.axis.thermal import steady_temperature
    from ballscrew.errors import BallScrewInputError

    omega = 2.0 * math.pi * 0.25 / 0.01
    g = _air_h(0.04, omega, 200.0, 18.0) * math.pi * 0.04 + 1.0
    preload = 2000.0 * (200.0 * g + 0.5) / (_preload_drag() * omega)
    t = np.linspace(0.0, 2.0, 5)
    v, zero = np.full(5, 0.25), np.zeros(5)
    node = ThermalNode(screw_length=1.0, ambient=18.0, machine_resistance=1.0)
    with pytest.raises(BallScrewInputError, match="below 218 °C"):
        steady_temperature(Profile(t, v * t, v, zero, zero), reference_screw().replace(
            preload=preload), OIL, Axis(moving_mass=0.0), node, model="catalog")  # fmt: skip


def test_an_ambient_of_500_degc_or_more_or_below_absolute_zero_is_refused() -> None:
    from ballscrew.errors import BallScrewInputError

    assert ThermalNode(screw_length=1.0, ambient=499.0).ambient == 499.0
    with pytest.raises(BallScrewInputError, match="ambient"):
        ThermalNode(screw_length=1.0, ambient=520.0)
    with pytest.raises(BallScrewInputError, match="ambient"):  # below absolute zero
        ThermalNode(screw_length=1.0, ambient=-280.0)


def test_the_history_of_a_warming_oil_ends_at_the_steady_temperature() -> None:
    # The complete model: the cycle's power falls as the oil warms. Its table every 2 K or
    # less (h), interpolated linearly, errs by at most h^2/8 |P''|, which shifts the
    # history's end by that over G - P' (both by hand from the cycle's mean power at the
    # steady temperature and 2 K either side). 25 time constants on, the history is there
    # within twice that bound (P'' is not constant over the table).
    from ballscrew.axis.motion import back_and_forth
    from ballscrew.axis.thermal import mean_powers, steady_temperature, temperature_history

    node = ThermalNode(screw_length=0.8, ambient=22.0, machine_resistance=2.0)
    cycle, s, axis = back_and_forth(0.3, 0.5, 2.0), reference_screw(), Axis(moving_mass=200.0)
    st = steady_temperature(cycle, s, OIL, axis, node)
    temp = st.temperature
    p = mean_powers(cycle, s, OIL, axis, [temp - 2.0, temp, temp + 2.0])
    second, first = (p[0] - 2.0 * p[1] + p[2]) / 4.0, (p[2] - p[0]) / 4.0
    bound = 2.0 * (2.0**2 / 8.0 * abs(second)) / (st.conductance - first)
    tau = node.heat_capacity(s) / st.conductance
    _, history = temperature_history(cycle, s, OIL, axis, node, 25.0 * tau, points=6,
                                     steady=st)  # fmt: skip
    assert abs(history[-1] - temp) < bound
    assert bound < 0.01  # a bound that says something


def test_a_half_second_series_warms_by_its_exponential() -> None:
    # 10 W into 1 J/K through 1 W/K (tau = 1 s) for 0.5 s from the ambient: 10 (1 - e^-0.5) K.
    from ballscrew.axis.thermal import heat_balance

    temp = heat_balance(np.array([0.0, 0.5]), np.full(2, 10.0), 1.0, 1.0, 20.0, 20.0)
    assert temp[1] == pytest.approx(20.0 + 10.0 * (1.0 - math.exp(-0.5)), rel=1e-13)


# --- axis/thermal.py: the batch functions ------------------------------------------------------


def _held(preload: float) -> tuple[Profile, BallScrew, Axis, ThermalNode, float, float]:
    """0.25 m/s held under the catalogue's drag at ``preload``; its power [W] and G [W/K]."""
    t = np.linspace(0.0, 2.0, 5)
    v, zero = np.full(5, 0.25), np.zeros(5)
    omega = 2.0 * math.pi * 0.25 / 0.01
    g = _air_h(0.04, omega, 12.0, 18.0) * math.pi * 0.04 + 1.0
    power = _preload_drag() * preload / 2000.0 * omega
    node = ThermalNode(screw_length=1.0, ambient=18.0, machine_resistance=1.0)
    s = reference_screw().replace(preload=preload)
    return Profile(t, v * t, v, zero, zero), s, Axis(moving_mass=0.0), node, power, g


def test_one_screw_balanced_and_integrated_in_a_batch_is_the_closed_form() -> None:
    # As test_the_steady_temperature_and_time_constant_...: T_a + P/G and the exponential
    # with tau = C/G, through the batch functions with one screw; 200 points by default.
    from ballscrew.axis.thermal import steady_temperatures, temperature_histories

    p, s, axis, node, power, g = _held(2000.0)
    (st,) = steady_temperatures(p, [s], OIL, [axis], [node], model="catalog")
    assert st is not None and st.temperature == pytest.approx(18.0 + power / g, abs=1e-9)
    tau = 7850.0 * math.pi * 0.04**2 / 4.0 * 460.0 / g
    ((times, temp),) = temperature_histories(p, [s], [node], 3.0 * tau, [st])
    assert times.size == 200
    np.testing.assert_allclose(temp, 18.0 + power / g * (1.0 - np.exp(-times / tau)), atol=1e-6)


def test_a_batch_gives_none_where_the_node_sheds_the_drag_only_above_200_k() -> None:
    # P = 200 K x G + 0.5 W: 0.07 K beyond the range (as alone, where it is refused).
    from ballscrew.axis.thermal import steady_temperatures

    p, s, axis, node, _, g = _held(2000.0)
    omega = 2.0 * math.pi * 0.25 / 0.01
    g = _air_h(0.04, omega, 200.0, 18.0) * math.pi * 0.04 + 1.0
    hot = s.replace(preload=2000.0 * (200.0 * g + 0.5) / (_preload_drag() * omega))
    first, second = steady_temperatures(p, [hot, s], OIL, [axis, axis], [node, node],
                                        model="catalog")  # fmt: skip
    assert first is None and second is not None


def test_a_batch_whose_friction_cannot_be_computed_gives_none_for_every_screw() -> None:
    # A friction angle beyond 90 degrees less the lead angle: the catalogue rule refuses it,
    # and the batch answers None for each screw (steady_temperature alone raises the error).
    from ballscrew.axis.thermal import steady_temperatures

    p, s, axis, node, _, _ = _held(2000.0)
    got = steady_temperatures(p, [s, s], OIL, [axis, axis], [node, node], model="catalog",
                              friction_coefficient=20.0)  # fmt: skip
    assert got == [None, None]


def test_batch_roots_next_to_the_table_nodes_are_the_closed_form() -> None:
    # Drags set for rises of 0.12 K (before the first node past the ambient), 10.05 K and
    # 20.05 K (0.05 K past the nodes of +10 and +20 K, the latter the first stage's last,
    # where the imbalance is only G x 0.05 K = 0.36 W): T_a + P/G each, to 1e-9 K.
    from ballscrew.axis.thermal import steady_temperatures

    p, s, axis, node, _, _ = _held(2000.0)
    omega = 2.0 * math.pi * 0.25 / 0.01
    rises = (0.12, 10.05, 20.05)
    screws = []
    for rise in rises:
        g = _air_h(0.04, omega, rise, 18.0) * math.pi * 0.04 + 1.0
        screws.append(s.replace(preload=2000.0 * rise * g / (_preload_drag() * omega)))
    got = steady_temperatures(p, screws, OIL, [axis] * 3, [node] * 3, model="catalog")
    for st, rise in zip(got, rises, strict=True):
        assert st is not None and st.temperature == pytest.approx(18.0 + rise, abs=1e-9)


def test_a_batch_of_axes_with_unlike_samples_is_each_axis_balance_alone() -> None:
    # A moving mass adds forces to the samples (more distinct samples than without): the
    # batch pads the shorter list with weightless samples, and each temperature is the one
    # steady_temperature finds for that axis alone (to 1e-9 K: both solve to 1e-11 K).
    from ballscrew.axis.motion import back_and_forth
    from ballscrew.axis.thermal import steady_temperature, steady_temperatures

    cycle, s = back_and_forth(0.3, 0.5, 2.0), reference_screw()
    axes = [Axis(moving_mass=0.0), Axis(moving_mass=400.0)]
    node = ThermalNode(screw_length=0.8, ambient=22.0, machine_resistance=2.0)
    got = steady_temperatures(cycle, [s, s], OIL, axes, [node, node], model="catalog")
    for st, axis in zip(got, axes, strict=True):
        alone = steady_temperature(cycle, s, OIL, axis, node, model="catalog")
        assert st is not None and st.temperature == pytest.approx(alone.temperature, abs=1e-9)
    assert got[0] is not None and got[1] is not None
    assert got[1].temperature > got[0].temperature + 0.1  # the masses' forces add friction
