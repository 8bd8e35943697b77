"""The axis check: each criterion against a hand calculation over a simple cycle."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew.axis.check import CHECK_FROM, run_check, verdict
from ballscrew.axis.duty import profile_from_move, run_energy
from ballscrew.axis.motion import Profile
from ballscrew.design.sizing import STEEL_EXPANSION, TRAVEL_VARIATION_300
from ballscrew.design.stiffness import SHAFT_MODULUS, nut_axial_stiffness
from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import Case, parse_case
from shared import AXIS_CASE

BASE = AXIS_CASE  # a 32 x 10 mm nut on a 200 kg horizontal axis (tests/shared.py)

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


def _case_with_mass(mass: str, nut: str = "single", preload: str = "0 N") -> Case:
    text = BASE.format(nut=nut, preload=preload, support="fixed-supported", axis_extra="",
                       sections="")  # fmt: skip
    return parse_case(text.replace('moving_mass = "200 kg"', f'moving_mass = "{mass}"'))


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
    one = (20_000.0 / (1.2 * fm)) ** 3 * 1e6  # ISO 3408-5, a1 = 1, the default f_w = 1.2
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
    # Hand value of the peak, while accelerating at 2 m/s^2 (THK's catalogue formulas):
    # - the inertia of rotor, screw and table: J_m + J_load = 2e-4 + 1.30661e-3 = 1.50661e-3
    #   kg m^2, times 2 pi / l = 628.319 1/m: 0.946628 N m per m/s^2, 1.893257 N m at 2 m/s^2;
    # - the preload drag T_p = 0.05 / sqrt(tan beta) F_pr l / 2 pi, tan beta = 10 / (32 pi)
    #   = 0.0994718: K = 0.158533, T_p = 158.533 * 0.01 / 2 pi = 0.252313 N m;
    # - the load's friction F l / 2 pi (1 / eta - 1), eta = (1 - mu tan beta) /
    #   (1 + mu / tan beta) = 0.970434 (mu = 0.003), 400 N: 0.636620 * 0.030467 = 0.019396 N m.
    # Sum 2.164966 N m (6 digits: rel 1e-6).
    assert _row(result, "peak torque").value == pytest.approx(2.164966, rel=1e-6)
    # The acceleration the peak torque allows: (6 - 0.252313 - 0.019396) / 0.946628
    # = 6.05126 m/s^2 (the load's friction taken at the cycle's own 400 N).
    allowed = _row(result, "acceleration the peak")
    assert allowed.value == pytest.approx(6.05126, rel=2e-6)
    assert result.motor["allowed_acceleration_m_s2"] == allowed.value
    # Run as a move, it needs the peak torque, plus the load friction of the heavier
    # inertia force: 200 * 6.05 = 1210 N gives 0.0587 N m instead of 0.0194, +0.039 N m.
    run2, _ = _check(case, {**MOVE, "acceleration": allowed.value})
    assert run2.cycles_by_model["catalog"].peak_motor_torque == pytest.approx(6.039, abs=1e-3)
    # The motor's ratings are the rows' limits, in the units the case gave them.
    assert _row(result, "peak torque").limit == pytest.approx(6.0, rel=1e-12)
    assert _row(result, "RMS torque").limit == pytest.approx(2.0, rel=1e-12)
    assert _row(result, "motor speed").limit == pytest.approx(3000.0, rel=1e-12)
    # The servo makers' rule of thumb: a load inertia at most 10 times the rotor's.
    assert _row(result, "inertia ratio").limit == 10.0


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
    with pytest.raises(BallScrewInputError, match=r"axis\.motor_inertia = '\(missing\)'"):
        _check(_case(sections=motor))
    with pytest.raises(BallScrewInputError, match=r"axis\.motor_inertia = 0 "):
        _check(_case(axis_extra='motor_inertia = "0 kg*m**2"', sections=motor))
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


# --- Each row's value and limit against a number from outside the check -------------------


def test_verdict_turns_to_check_at_the_documented_ninety_percent() -> None:
    # docs/axis-energy.md: "OK below 90 % of the limit, CHECK up to it, NOT OK past it".
    assert verdict(0.8999) == "OK"
    assert verdict(0.9) == "CHECK"
    assert CHECK_FROM == 0.9


def test_axial_load_on_the_root_section_is_thks_rule() -> None:
    # THK, Permissible Axial Load, A15-30, eq. 6: P2 = sigma pi / 4 d_r^2 = 116 d_r^2 N (mm)
    # with sigma = 147 N/mm^2. For the 26 mm root: 147 * pi / 4 * 676 = 78 046.6 N; THK's
    # rounded 116 * 676 = 78 416 N is 0.47 % above.
    _, result = _check(_case())
    row = _row(result, "axial load, root section")
    assert row.limit == pytest.approx(78.0466, rel=1e-6)
    assert row.limit == pytest.approx(116 * 26**2 / 1e3, rel=5e-3) and row.limit < 78.416
    assert row.value == pytest.approx(0.4, rel=1e-6)  # m a = 200 kg * 2 m/s^2
    assert row.utilisation == pytest.approx(0.4 / 78.0466, rel=1e-6) and row.verdict == "OK"


def test_lost_motion_and_eigenfrequency_rows_by_hand() -> None:
    case = _case(nut="double", preload="1 kN", support="fixed-fixed",
                 sections='[check]\nsupport_stiffness = "500 N/um"')  # fmt: skip
    _, result = _check(case)
    # The drag at creep speed as an axial force, 2 pi T_p / l = K F_pr with THK's
    # K = 0.05 / sqrt(tan beta), tan beta = 10 / (32 pi) = 0.0994718: 158.533 N.
    assert result.stiffness["friction_force_N"] == pytest.approx(158.533, rel=3e-6)
    # Least stiffness at mid-span: the shaft fixed-fixed, 4 E A / L = 4 * 206e9 * 5.30929e-4
    # / 1.2 = 3.64571e8 N/m, in series with the nut and the bearings (500 N/um).
    ea = SHAFT_MODULUS * math.pi * 0.026**2 / 4
    k_nut = 0.8 * nut_axial_stiffness(case.screw) / 1.48
    least = 1 / (1 / (4 * ea / 1.2) + 1 / k_nut + 1 / 500e6)
    # The most lost motion, 2 F_f / k at the least stiffness, in um.
    play = _row(result, "lost motion at reversal")
    assert play.value == pytest.approx(2 * 158.533 / least * 1e6, rel=3e-6)
    # The least eigenfrequency, sqrt(k / m) / 2 pi with the 200 kg table.
    freq = _row(result, "axial eigenfrequency")
    assert freq.value == pytest.approx(math.sqrt(least / 200.0) / (2 * math.pi), rel=1e-9)
    assert result.stiffness["nut_N_per_um"] == pytest.approx(k_nut / 1e6, rel=1e-12)
    assert f"nut {k_nut / 1e6:.4g} N/um" in _row(result, "axis stiffness").source
    # The shaft's twist under T_p = 0.252313 N m from the drive to the far end of the
    # stroke, 0.8 m: G J_p = 79.3e9 * pi 0.026^4 / 32 = 3557.6 N m^2, 2 T_p a / G J_p
    # = 1.1348e-4 rad, times l / 2 pi: 0.18 um.
    assert "twists the shaft, up to 0.18 um" in play.source
    # the nut's own share, 2 F_f / k_nut, by hand from the nut stiffness above
    assert f"2 F_f / k_nut = {2 * 158.533 / (k_nut / 1e6):.2g} um" in play.source
    assert "upper bound" in play.source
    # The nut's level as stated: contacts over 1.48, printed nuts 0.56 to 0.71 of theirs
    # (THK's and HIWIN's tables, tests/physics/test_stiffness.py), THK's allowance 0.8.
    notes = "\n".join(result.assumptions)
    assert "over 1.48" in notes and "0.56 to 0.71" in notes and "allowance 0.8" in notes
    assert result.stiffness["bearings_N_per_um"] == pytest.approx(500.0, rel=1e-12)
    # Without a moving mass there is no eigenfrequency to give: the row says so.
    _, still = _check(_case_with_mass("0 kg", nut="double", preload="1 kN"))
    assert _row(still, "axial eigenfrequency").verdict == "NOT CHECKED"


def test_a_single_nut_needs_a_load_for_its_stiffness() -> None:
    with pytest.raises(BallScrewInputError, match=r"screw\.nut"):
        _check(_case_with_mass("0 kg"))
    # A light table (0.2 kg at 2 m/s^2: 0.4 N) still loads the nut and gets its stiffness.
    _, light = _check(_case_with_mass("0.2 kg"))
    assert 0.0 < _row(light, "axis stiffness").value < math.inf
    assert _row(light, "axial eigenfrequency").verdict == "INFO"
    # Its static safety is the rating over that load: 50 kN / 0.4 N = 125 000.
    assert _row(light, "static safety").value == pytest.approx(125_000.0, rel=1e-9)


def test_nut_length_and_the_stroke_that_fits() -> None:
    # The nut: (loaded turns + 1) circuits lead = 3.5 * 2 * 10 mm = 70 mm, twice for a
    # double nut. The stroke fits the 1200 mm span up to 1200 - 70 = 1130 mm.
    _, single = _check(_case())
    assert single.stiffness["nut_length_mm"] == pytest.approx(70.0, rel=1e-12)
    _, double = _check(_case(nut="double", preload="1 kN"))
    assert double.stiffness["nut_length_mm"] == pytest.approx(140.0, rel=1e-12)
    _check(_case(), {**MOVE, "stroke": 1.125})
    with pytest.raises(BallScrewInputError,
                       match=r"'1200 mm'.*stroke 1135 mm plus the nut 70 mm"):  # fmt: skip
        _check(_case(), {**MOVE, "stroke": 1.135})


def test_the_life_row_reports_the_mean_speed_and_the_turns() -> None:
    # 80 turns in the 2.1 s cycle (test_life_of_a_single_nut_by_hand): 80 / 2.1 * 60
    # = 2285.71 rpm.
    _, result = _check(_case(nut="double", preload="1 kN"))
    assert result.life["mean_speed_rpm"] == pytest.approx(2285.714, rel=1e-6)
    # A move shorter than a turn still has a life: 4 mm there and back on a 10 mm lead is
    # 0.8 turn, at 0.05 m/s and 2 m/s^2 in 2 (0.08 + 0.025) = 0.21 s: 228.571 rpm, a tenth.
    # The ramps take 2 * 0.05^2 / 4 = 1.25 mm of the 4 mm, the share of 125 of 400 mm above,
    # under the same 400 N: the same mean loads and revolutions, ten times the hours.
    _, short = _check(_case(nut="double", preload="1 kN"),
                      {"stroke": 0.004, "feed": 0.05, "acceleration": 2.0})  # fmt: skip
    assert short.life["turns_per_cycle"] == pytest.approx(0.8, rel=1e-9)
    assert short.life["mean_speed_rpm"] == pytest.approx(228.5714, rel=1e-6)
    assert short.life["mean_load_N"] == pytest.approx(result.life["mean_load_N"], rel=1e-6)
    hours = _row(result, "fatigue life").value
    assert _row(short, "fatigue life").value == pytest.approx(10 * hours, rel=1e-6)


def test_several_cycles_count_their_turns_per_cycle() -> None:
    # Three cycles of the 80-turn move: 240 turns in 6.3 s, still 80 per cycle and the
    # same life in hours as one cycle.
    case = _case(nut="double", preload="1 kN")
    run = run_energy(case, profile_from_move(MOVE, 3), ["catalog"], cycles=3, run_time=60.0,
                     move=dict(MOVE))  # fmt: skip
    result = run_check(run)
    assert result.life["turns_per_cycle"] == pytest.approx(80.0, rel=1e-3)
    _, one = _check(case)
    assert _row(result, "fatigue life").value == pytest.approx(
        _row(one, "fatigue life").value, rel=1e-9
    )


def test_a_cycle_without_turns_has_no_life_row() -> None:
    case = _case(nut="double", preload="1 kN")
    time, zero = np.linspace(0.0, 2.0, 5), np.zeros(5)
    run = run_energy(case, Profile(time, zero, zero, zero, zero), ["catalog"], run_time=60.0)
    row = _row(run_check(run), "fatigue life")
    assert row.verdict == "NOT CHECKED" and "no turn" in row.advice


def test_pretension_needs_a_fixed_fixed_screw_and_only_absorbs_a_rise() -> None:
    # Any pre-tension, even half a kelvin, on a screw that is not fixed at both ends.
    with pytest.raises(BallScrewInputError, match="pretension_temperature"):
        _check(_case(sections='[check]\npretension_temperature = "0.5 K"'))
    # A pre-tension larger than the rise leaves no lead error and no growth (not a negative
    # one): the catalogue cycle warms the screw by ~1 K in 60 s.
    grade = '[check]\naccuracy_grade = "C5"\npretension_temperature = "5 K"'
    _, result = _check(_case(nut="double", preload="1 kN", support="fixed-fixed",
                             sections=grade))  # fmt: skip
    assert 0.0 < result.thermal["temperature_rise_K"] < 5.0
    assert _row(result, "thermal lead error").value == 0.0
    assert _row(result, "thermal growth over the stroke").value == 0.0
    assert max(result.thermal["error_per_300mm_over_time_um"]) == 0.0


def test_a_life_under_an_hour_is_still_a_ratio() -> None:
    # 49.5 kN of process force on the 20 kN nut: a life below one hour, whose utilisation
    # is the required 20 000 h over it, not an infinite one.
    _, result = _check(_case(), {**MOVE, "force": 49_500.0})
    row = _row(result, "fatigue life")
    assert 0.0 < row.value < 1.0
    assert row.utilisation == pytest.approx(20_000.0 / row.value, rel=1e-12)
    assert row.verdict == "NOT OK"


def test_the_assumptions_state_the_numbers_taken() -> None:
    # Without a bearing span the screw length (1300 mm here) is the span; without a root
    # diameter the groove's: r = 0.55 * 6.35 = 3.4925 mm, e = r - 3.175 = 0.3175 mm, depth
    # sqrt(r^2 - (e sin 45)^2) - e cos 45 = 3.48528 - 0.22451 = 3.26077 mm, d_r = 32 - 2 *
    # 3.26077 = 25.48 mm.
    text = (BASE.format(nut="single", preload="0 N", support="fixed-supported",
                        axis_extra='screw_length = "1300 mm"', sections="")
            .replace('bearing_span = "1200 mm"\n', "")
            .replace('root_diameter = "26 mm"\n', ""))  # fmt: skip
    _, result = _check(parse_case(text))
    notes = "\n".join(result.assumptions)
    assert "span between the supports taken as the screw length 1300 mm" in notes
    assert "root diameter 25.48 mm estimated from the groove" in notes
    # A single nut's stiffness is taken at the cycle's peak load, m a = 400 N.
    assert "stiffness at the cycle's peak load 400 N" in notes


def test_a_gear_divides_the_load_inertia_and_the_drag() -> None:
    # The motor test's axis behind a 1:2 gear (i = 2 motor turns per screw turn), by hand:
    # J_load = (8e-4 + 5.06606e-4) / 4 = 3.26651e-4 kg m^2, 1.63326 x the rotor;
    # per m/s^2 of the table (2e-4 + 3.26651e-4) 2 pi 2 / 0.01 = 0.661810 N m; the drag at
    # the motor (0.252313 + 0.019396) / 2 = 0.135855 N m (test_motor_check_by_hand).
    motor = '[motor]\nrated_torque = "2 N*m"\npeak_torque = "6 N*m"\nrated_speed = "6000 rpm"'
    gear = 'motor_inertia = "2e-4 kg*m**2"\nscrew_inertia = "8e-4 kg*m**2"\ngear_ratio = 2'
    case = _case(nut="double", preload="1 kN", axis_extra=gear, sections=motor)
    _, result = _check(case)
    assert _row(result, "inertia ratio").value == pytest.approx(1.63326, rel=3e-6)
    # The peak, 2 m/s^2: 0.661810 * 2 + 0.135855 = 1.459475 N m.
    assert _row(result, "peak torque").value == pytest.approx(1.459475, rel=2e-6)
    # The acceleration 6 N m allows: (6 - 0.135855) / 0.661810 = 8.86077 m/s^2.
    assert _row(result, "acceleration the peak").value == pytest.approx(8.86077, rel=2e-6)
    # 3000 screw rpm are 6000 motor rpm, the rated speed.
    assert _row(result, "motor speed").value == pytest.approx(6000.0, rel=1e-9)
