"""Many screws' heat balances solved together equal each screw's own (steady_temperatures)."""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew import reference_screw
from ballscrew.axis.energy import Axis
from ballscrew.axis.motion import back_and_forth
from ballscrew.axis.thermal import (
    ThermalNode,
    history_grid,
    mean_powers,
    steady_temperature,
    steady_temperatures,
    temperature_histories,
    temperature_history,
)

CYCLE = back_and_forth(0.3, 0.5, 2.0, cycles=1, process_force=2000.0, force_window=(0.05, 0.25))
OIL = "mineral ISO VG 68"


def _screws() -> list:  # type: ignore[type-arg]
    base = reference_screw()
    return [
        base,
        base.replace(lead=0.02),
        base.replace(preload=2.0 * base.preload),
        base.replace(nut="single", preload=0.0),
    ]


def test_the_balances_solved_together_are_each_screws_own() -> None:
    screws = _screws()
    axes = [Axis(moving_mass=200.0), Axis(moving_mass=120.0), Axis(moving_mass=200.0),
            Axis(moving_mass=80.0)]  # fmt: skip
    # Each screw its own node: rises of 23, 13, 64 and 7 K, brackets in every stage of
    # the table (TABLE_STAGES: nodes 5 K apart up to the 5th, the 13th, the last).
    nodes = [ThermalNode(screw_length=0.9), ThermalNode(1.2, machine_resistance=2.0),
             ThermalNode(0.5, ambient=25.0), ThermalNode(screw_length=0.7)]  # fmt: skip
    together = steady_temperatures(CYCLE, screws, OIL, axes, nodes)
    for screw, axis, node, both in zip(screws, axes, nodes, together, strict=True):
        alone = steady_temperature(CYCLE, screw, OIL, axis, node)
        assert both is not None
        # Same balance, same bracket, same Illinois tolerance (1e-11 K): the friction of a
        # batch differs from one screw's by rounding (1e-15), so the roots agree within
        # the iteration's tolerance; the rise is at least a kelvin here.
        assert both.temperature - node.ambient > 1.0
        assert both.temperature == pytest.approx(alone.temperature, rel=0.0, abs=1e-10)
        assert both.friction_power == pytest.approx(alone.friction_power, rel=1e-12)
        # and the root is the balance's: the heat leaves as fast as the friction makes it
        assert both.heat_out == pytest.approx(both.friction_power, rel=1e-9)
        # the history's table, from the same call: the cycle's mean power at each
        grid, powers = both.history_powers  # type: ignore[misc]
        assert np.array_equal(grid, history_grid(node, both.temperature))
        np.testing.assert_allclose(powers, mean_powers(CYCLE, screw, OIL, axis, grid),
                                   rtol=1e-12)  # fmt: skip


def test_the_history_from_a_batch_balance_is_the_screws_own() -> None:
    screw, axis, node = reference_screw(), Axis(moving_mass=200.0), ThermalNode(screw_length=0.9)
    (both,) = steady_temperatures(CYCLE, [screw], OIL, [axis], [node])
    assert both is not None
    _, own = temperature_history(CYCLE, screw, OIL, axis, node, 3600.0, points=20)
    _, batch = temperature_history(CYCLE, screw, OIL, axis, node, 3600.0, points=20, steady=both)
    # The integrator (rtol 1e-8) is started from tables equal to rounding: its steps may
    # differ, within its tolerance on the temperature.
    np.testing.assert_allclose(batch, own, rtol=1e-7)


def test_a_screw_that_cannot_shed_its_heat_gets_none_and_the_others_their_balance() -> None:
    screws = _screws()[:2]
    hot = ThermalNode(screw_length=1e-4)  # a stub of screw: no surface to lose the heat
    nodes = [hot, ThermalNode(screw_length=0.9)]
    axes = [Axis(moving_mass=200.0)] * 2
    with pytest.raises(Exception, match="shed"):
        steady_temperature(CYCLE, screws[0], OIL, axes[0], hot)
    first, second = steady_temperatures(CYCLE, screws, OIL, axes, nodes)
    assert first is None
    assert second is not None and second.temperature == pytest.approx(
        steady_temperature(CYCLE, screws[1], OIL, axes[1], nodes[1]).temperature, abs=1e-10
    )


def test_nodes_integrated_together_follow_each_ones_own_history() -> None:
    screws = _screws()[:3]
    axes = [Axis(moving_mass=200.0)] * 3
    # a long run (the short node settles: held at its steady temperature) and three rises
    nodes = [ThermalNode(screw_length=0.9), ThermalNode(0.3, machine_resistance=0.5),
             ThermalNode(0.5, ambient=25.0)]  # fmt: skip
    steadies = steady_temperatures(CYCLE, screws, OIL, axes, nodes)
    assert all(s is not None for s in steadies)
    together = temperature_histories(CYCLE, screws, nodes, 20_000.0,
                                     [s for s in steadies if s is not None], points=30)  # fmt: skip
    for screw, axis, node, steady, (times, temps) in zip(
        screws, axes, nodes, steadies, together, strict=True
    ):
        own_times, own = temperature_history(CYCLE, screw, OIL, axis, node, 20_000.0,
                                             points=30, steady=steady)  # fmt: skip
        assert np.array_equal(times, own_times)
        assert temps[0] == node.ambient
        # One integration of independent equations, the steps shared: each node within
        # the integrator's tolerance (rtol 1e-8 on the temperature) of its own run.
        np.testing.assert_allclose(temps - node.ambient, own - node.ambient, rtol=1e-5,
                                   atol=1e-6)  # fmt: skip
    # the settled node holds its steady temperature, as alone
    assert together[1][1][-1] == steadies[1].temperature  # type: ignore[union-attr]
