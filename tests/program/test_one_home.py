"""The program takes the creep speed, the steel's expansion, the node's conductance and the
reversal's lost motion from where they are defined (issue 49).

When the copies were removed, the example program's result
(``ballscrew program examples/pocket_contour_drill.nc --machine examples/machine_vmc.toml``)
was bit-identical before and after; the tests below check the recipes against the
published numbers and the defined functions, not against a snapshot.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from ballscrew.axis import thermal
from ballscrew.axis.check import CREEP_SPEED
from ballscrew.axis.thermal import ThermalNode, convection_coefficient, series_temperature
from ballscrew.geometry import reference_screw
from ballscrew.io.machine import load_machine
from ballscrew.program import axes
from ballscrew.program.axes import run_program

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(scope="module")
def example() -> dict[str, dict[str, object]]:
    machine = load_machine(EXAMPLES / "machine_vmc.toml")
    text = (EXAMPLES / "pocket_contour_drill.nc").read_text("utf-8")
    result: dict[str, dict[str, object]] = run_program(machine, text).as_dict()["axes"]
    return result


def test_the_program_uses_the_published_expansion_and_two_f_over_k(
    example: dict[str, dict[str, object]],
) -> None:
    # alpha = 11.5e-6 /K (THK and NSK print 11.8e-6 and 12e-6): the thermal lead error over the
    # travel, alpha dT L; the lost motion 2 F_f / k of every reversal. Both are products of
    # the printed numbers: 1e-12 is rounding (the JSON's um and mm conversions).
    for letter, now in example.items():
        rise = float(now["max_temperature_C"]) - float(now["start_temperature_C"])  # type: ignore[arg-type]
        lead_error = 11.5e-6 * rise * float(now["travel_mm"]) * 1e-3 * 1e6  # type: ignore[arg-type]
        assert now["thermal_lead_error_um"] == pytest.approx(lead_error, rel=1e-12), letter
        for r in now["reversals"]:  # type: ignore[attr-defined]
            two_f_over_k = 2.0 * r["friction_force_N"] / (r["stiffness_N_per_um"] * 1e6) * 1e6
            assert r["lost_motion_um"] == pytest.approx(two_f_over_k, rel=1e-12), letter


def test_one_home_for_each_fact() -> None:
    assert axes.heat_balance is thermal.heat_balance  # the old import path still works
    assert axes.CREEP_SPEED is CREEP_SPEED  # the check's creep speed, not a second 0.1
    assert not hasattr(axes, "THERMAL_EXPANSION")


def test_series_temperature_takes_the_conductance_the_program_took() -> None:
    """The program's former recipe, written out: G = h(RMS speed, 1 K above the air) pi d L
    + 1/R_m, C = the node's, then the exact heat balance. Same operations: 1e-12."""
    screw = reference_screw()
    node = ThermalNode(screw_length=0.8, ambient=21.0, machine_resistance=2.0, nut_mass=3.0)
    t = np.linspace(0.0, 600.0, 601)
    omega = 150.0 * np.sin(t / 7.0)
    power = 20.0 + 15.0 * np.abs(np.sin(t / 7.0))
    rms = math.sqrt(float(np.sum(0.5 * (omega[1:] ** 2 + omega[:-1] ** 2) * np.diff(t))) / 600.0)
    h = float(convection_coefficient(screw.pitch_diameter, rms, 22.0, 21.0))
    g = h * math.pi * screw.pitch_diameter * 0.8 + 1.0 / 2.0
    old = thermal.heat_balance(t, power, node.heat_capacity(screw), g, 21.0, 25.0)
    new = series_temperature(t, power, node, screw, omega, 25.0)
    np.testing.assert_allclose(new, old, rtol=1e-12, atol=0)
