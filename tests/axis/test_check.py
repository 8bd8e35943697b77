"""The axis check: each criterion against a hand calculation over a simple cycle."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.axis.check import CHECK_FROM, run_check, verdict
from ballscrew.axis.duty import profile_from_move, run_energy
from ballscrew.design.sizing import STEEL_EXPANSION, TRAVEL_VARIATION_300
from ballscrew.design.stiffness import SHAFT_MODULUS, nut_axial_stiffness
from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import Case, parse_case

BASE = """
title = "check test"
[screw]
pitch_diameter = "32 mm"
lead = "10 mm"
ball_diameter = "6.35 mm"
loaded_turns = 2.5
circuits = 2
nut = "{nut}"
preload = "{preload}"
dynamic_load_rating = "20 kN"
static_load_rating = "50 kN"
[lubricant]
name = "PAO ISO VG 68"
[operation]
temperature = "20 degC"
[axis]
moving_mass = "200 kg"
bearing_span = "1200 mm"
root_diameter = "26 mm"
support = "{support}"
{axis_extra}
{sections}
"""

MOVE = {"stroke": 0.4, "feed": 0.5, "acceleration": 2.0}


def _case(
    nut: str = "single", preload: str = "0 N", support: str = "fixed-supported",
    axis_extra: str = "", sections: str = "",
) -> Case:  # fmt: skip
    return parse_case(BASE.format(nut=nut, preload=preload, support=support,
                                  axis_extra=axis_extra, sections=sections))  # fmt: skip


def _check(case: Case, move: dict[str, float] | None = None, run_time: float = 60.0):  # type: ignore[no-untyped-def]
    m = dict(MOVE if move is None else move)
    run = run_energy(case, profile_from_move(m, 1), ["catalog"], run_time=run_time, move=m)
    return run, run_check(run)


def _row(result, name: str):  # type: ignore[no-untyped-def]
    return next(c for c in result.criteria if c.name.startswith(name))


def test_verdict_bands() -> None:
    assert verdict(0.5) == "OK"
    assert verdict(CHECK_FROM) == "CHECK" and verdict(1.0) == "CHECK"
    assert verdict(1.01) == "NOT OK" and verdict(math.inf) == "NOT OK"
    assert verdict(math.nan) == "NOT OK"  # never a silent pass


def test_life_of_a_single_nut_by_hand() -> None:
    # Horizontal, no process force: the nut carries m a = 400 N while it accelerates and
    # brakes, nothing at feed. Out: +400 N over the acceleration (v^2/2a = 62.5 mm), -400 N
    # over the braking; back the same mirrored. Each flank carries 400 N over 2 x 62.5 mm
    # of the 800 mm the nut travels: F_m = 400 (125/800)^(1/3) = 215.4 N on both flanks.
    _, result = _check(_case())
    fm = 400.0 * (0.125 / 0.8) ** (1 / 3)
    assert result.life["mean_load_N"] == pytest.approx([fm, fm], rel=5e-3)
    one = (20_000.0 / fm) ** 3 * 1e6  # ISO 3408-5, a1 = 1
    both = 2.0 ** (-0.9) * one  # two equal flanks in series, (L^-10/9 + L^-10/9)^-9/10
    assert result.life["L10_revolutions"] == pytest.approx(both, rel=1.5e-2)
    # 80 turns per cycle of 2 x (0.4/0.5 + 0.5/2) s = 2.1 s
    turns_per_s = 80.0 / 2.1
    assert result.life["turns_per_cycle"] == pytest.approx(80.0, rel=1e-3)
    row = _row(result, "fatigue life")
    assert row.value == pytest.approx(both / turns_per_s / 3600.0, rel=1.5e-2)
    assert row.limit == 20_000.0 and row.verdict == "OK"
    assert result.life["L10_km"] == pytest.approx(result.life["L10_revolutions"] * 0.01 / 1e3)


def test_static_safety_buckling_and_speed_by_hand() -> None:
    _, result = _check(_case(nut="double", preload="1 kN"))
    # Peak 400 N on a 1 kN preload: the loaded half carries 1000 (1 + 400/2828)^1.5 = 1220 N.
    half = 1000.0 * (1 + 400.0 / 2.0**1.5 / 1000.0) ** 1.5
    assert _row(result, "static safety").value == pytest.approx(50_000.0 / half, rel=1e-3)
    # Euler, fixed-supported (eta = 2), x 0.5: pi^2 E (pi 0.026^4/64) / 1.2^2 = 31.8 kN.
    p = 0.5 * 2 * math.pi**2 * SHAFT_MODULUS * math.pi * 0.026**4 / 64 / 1.2**2
    buckling = _row(result, "buckling")
    assert buckling.limit == pytest.approx(p / 1e3, rel=1e-9)
    assert buckling.value == pytest.approx(0.4, rel=1e-6)
    # 0.5 m/s on a 10 mm lead is 3000 rpm; THK's 15.1 d_r / L^2 1e7 = 2726 rpm allows less.
    speed = _row(result, "speed / critical")
    assert speed.value == pytest.approx(3000.0, rel=1e-9)
    assert speed.limit == pytest.approx(15.1 * 26 / 1200**2 * 1e7, rel=0.01)
    assert speed.verdict == "NOT OK" and "longer lead" in speed.advice
    assert _row(result, "d*n").value == pytest.approx(32 * 3000.0)


def test_stiffness_over_the_stroke_is_the_closed_form() -> None:
    case = _case(nut="double", preload="1 kN", support="fixed-fixed",
                 sections='[check]\nsupport_stiffness = "500 N/um"')  # fmt: skip
    _, result = _check(case)
    s = result.stiffness
    ea = SHAFT_MODULUS * math.pi * 0.026**2 / 4
    a = np.array(s["position_mm"]) / 1e3
    assert a[0] == pytest.approx(0.4) and a[-1] == pytest.approx(0.8)  # stroke centred
    shaft = ea * 1.2 / (a * (1.2 - a))
    np.testing.assert_allclose(s["shaft_N_per_um"], shaft / 1e6, rtol=1e-12)
    # The nut as a designer takes it: the printed level (contacts / 1.48) times 0.8.
    k_nut = 0.8 * nut_axial_stiffness(case.screw) / 1.48
    k = 1 / (1 / shaft + 1 / k_nut + 1 / 500e6)
    np.testing.assert_allclose(s["axis_N_per_um"], k / 1e6, rtol=1e-12)
    # Least at mid-span, 4EA/L in series with the nut and the bearings.
    least = 1 / (1 / (4 * ea / 1.2) + 1 / k_nut + 1 / 500e6)
    assert _row(result, "axis stiffness").value == pytest.approx(least / 1e6, rel=1e-9)
    np.testing.assert_allclose(s["eigenfrequency_Hz"], np.sqrt(k / 200.0) / (2 * math.pi))
    np.testing.assert_allclose(s["lost_motion_um"], 2 * s["friction_force_N"] / k * 1e6)
    # Torsion from the drive end to the nut: 2 T_f a / (G J_p) * l / 2 pi.
    t_f = s["friction_force_N"] * 0.01 / (2 * math.pi)
    gj = 79.3e9 * math.pi * 0.026**4 / 32
    np.testing.assert_allclose(
        s["lost_motion_torsion_um"], 2 * t_f * a / gj * 0.01 / (2 * math.pi) * 1e6
    )


def test_thermal_lead_error_and_pretension() -> None:
    grade = '[check]\naccuracy_grade = "p3"\npretension_temperature = "1 K"'
    case = _case(nut="double", preload="1 kN", support="fixed-fixed", sections=grade)
    run, result = _check(case, run_time=600.0)
    rise = run.results["catalog"].final_temperature - run.node.ambient
    row = _row(result, "thermal lead error")
    assert row.value == pytest.approx(STEEL_EXPANSION * max(rise - 1.0, 0.0) * 0.3 * 1e6)
    assert row.limit == pytest.approx(TRAVEL_VARIATION_300["P3"] * 1e6)
    growth = _row(result, "thermal growth over the stroke")
    assert growth.value == pytest.approx(STEEL_EXPANSION * max(rise - 1.0, 0.0) * 0.4 * 1e6)
    t = result.thermal
    assert t["temperature_C"][-1] == pytest.approx(rise + run.node.ambient)
    assert t["error_per_300mm_over_time_um"][-1] == pytest.approx(row.value)
    assert t["error_per_300mm_over_time_um"][0] == 0.0  # from the ambient
    with pytest.raises(BallScrewInputError, match="pretension_temperature"):
        _check(_case(sections='[check]\npretension_temperature = "2 K"'))


def test_motor_check_by_hand() -> None:
    motor = '[motor]\nrated_torque = "2 N*m"\npeak_torque = "6 N*m"\nrated_speed = "3000 rpm"'
    case = _case(nut="double", preload="1 kN",
                 axis_extra='motor_inertia = "2e-4 kg*m**2"\nscrew_inertia = "8e-4 kg*m**2"',
                 sections=motor)  # fmt: skip
    run, result = _check(case)
    # J_load = 8e-4 + 200 (0.01 / 2 pi)^2 = 8e-4 + 5.066e-4 = 1.3066e-3 kg m^2: 6.53 x rotor.
    j_load = 8e-4 + 200 * (0.01 / (2 * math.pi)) ** 2
    assert _row(result, "inertia ratio").value == pytest.approx(j_load / 2e-4, rel=1e-9)
    assert _row(result, "inertia ratio").verdict == "OK"
    assert _row(result, "motor speed").value == pytest.approx(3000.0)
    assert _row(result, "motor speed").verdict == "CHECK"  # at the rated speed
    cycle = run.cycles_by_model["catalog"]
    assert _row(result, "peak torque").value == cycle.peak_motor_torque
    assert _row(result, "RMS torque").value == cycle.rms_motor_torque
    # Hand value of the peak: the inertia of rotor, screw and table, (J_m + J_load) 2 pi a / l
    # = 1.5066e-3 * 1256.6 = 1.893 N m (the table's m a l / 2 pi = 0.637 N m of it), plus
    # the catalogue drag of a 1 kN preload (0.2 to 0.3 N m).
    inertia = (2e-4 + j_load) * 2 * math.pi * 2.0 / 0.01
    assert inertia == pytest.approx(1.8933, abs=1e-4)
    assert inertia + 0.2 < cycle.peak_motor_torque < inertia + 0.3
    # The acceleration the peak torque allows, run as a move, needs the peak torque.
    allowed = _row(result, "acceleration the peak").value
    run2, _ = _check(case, {**MOVE, "acceleration": allowed})
    assert run2.cycles_by_model["catalog"].peak_motor_torque == pytest.approx(6.0, rel=0.02)


def test_missing_inputs_are_named() -> None:
    case = parse_case(BASE.format(nut="single", preload="0 N", support="fixed-supported",
                                  axis_extra="", sections="")
                      .replace('dynamic_load_rating = "20 kN"\n', "")
                      .replace('static_load_rating = "50 kN"\n', ""))  # fmt: skip
    _, result = _check(case)
    assert "screw.dynamic_load_rating" in _row(result, "fatigue life").advice
    assert "screw.static_load_rating" in _row(result, "static safety").advice
    assert _row(result, "motor").verdict == "NOT CHECKED"
    assert {"fatigue life", "static safety C0a/F_max", "motor"} <= set(result.not_checked)
    with pytest.raises(BallScrewInputError, match=r"axis\.bearing_span"):
        _check(case, {**MOVE, "stroke": 1.15})
    motor = '[motor]\npeak_torque = "6 N*m"'
    with pytest.raises(BallScrewInputError, match=r"axis\.motor_inertia"):
        _check(_case(sections=motor))
    with pytest.raises(BallScrewInputError, match=r"check\.accuracy_grade"):
        _case(sections='[check]\naccuracy_grade = "P9"')
    with pytest.raises(BallScrewInputError, match=r"check\.reliability"):
        _case(sections='[check]\nreliability = "93 %"')
    with pytest.raises(BallScrewInputError, match=r"motor\.rated_torque"):
        _case(sections='[motor]\nrated_torque = "-2 N*m"')
    assert _case(sections='[check]\nreliability = "0.95"').check["reliability"] == 0.95


def test_a_designation_gives_both_ratings() -> None:
    case = parse_case(
        '[screw]\ndesignation = "HIWIN R32-05K4-FSC"\npreload = "0 N"\nball_diameter = "3.175 mm"'
        '\n[lubricant]\nname = "PAO ISO VG 68"'
    )
    assert (case.dynamic_load_rating, case.static_load_rating) == (18_400.0, 59_600.0)


def test_thermal_error_closes_the_heat_balance() -> None:
    # Run long against the node's time constant: the rise is the steady one, where the
    # cycle's mean friction power leaves through the conductance, dT = P / G (the energy
    # balance of ballscrew.axis.thermal), and the error is alpha P / G 300 mm.
    from ballscrew.axis.thermal import steady_temperature

    case = _case(nut="double", preload="2 kN", sections='[check]\naccuracy_grade = "C5"')
    run, result = _check(case, run_time=20 * 3600.0)
    steady = steady_temperature(run.profile, case.screw, case.lubricant, run.axis, run.node,
                                model="catalog")  # fmt: skip
    balance = steady.friction_power / steady.conductance
    assert steady.heat_out == pytest.approx(steady.friction_power, rel=1e-6)
    row = _row(result, "thermal lead error")
    assert row.value == pytest.approx(STEEL_EXPANSION * balance * 0.3 * 1e6, rel=2e-3)
    assert row.limit == pytest.approx(18.0)


def test_the_entry_points_old_names_still_answer_with_a_deprecation_warning() -> None:
    from ballscrew.axis import check, duty

    with pytest.warns(DeprecationWarning, match="run_energy"):
        assert duty.energy_run is duty.run_energy
    with pytest.warns(DeprecationWarning, match="run_check"):
        assert check.axis_check is check.run_check
    with pytest.raises(AttributeError):
        _ = duty.no_such_name
