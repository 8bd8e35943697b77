"""Pins of the axis check from its mutation run (issue 49): each against a hand value.

The check's notes, the default preload band, the model error's torque level and speed,
the draws' blocks and the probability that any row fails, each set against a number
worked out here (THK's drag-torque rule, the band's table, a ramp's mean speed, ...).
"""

from __future__ import annotations

import csv
import math
import re
from dataclasses import replace
from importlib import resources
from types import SimpleNamespace
from typing import Any

import numpy as np
import pytest
from scipy.stats import norm

from ballscrew import reference_screw
from ballscrew.axis import check as check_module
from ballscrew.axis import duty, standstill
from ballscrew.axis.check import Criterion, run_check
from ballscrew.axis.criteria import Inputs, Sample, life_hours, nut_halves, ones
from ballscrew.axis.duty import EnergyRun, profile_from_move, run_energy
from ballscrew.axis.motion import Profile
from ballscrew.axis.setup import axis_setup
from ballscrew.axis.standstill import noise_scatter, standstill_speed
from ballscrew.axis.uncertainty import FOUR_POINT_RANGE, SAMPLES, draws, judge, model_error
from ballscrew.design.stiffness import design_nut_stiffness
from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import parse_case
from ballscrew.io.units import to_si
from shared import AXIS_CASE

MOVE = {"stroke": 0.4, "feed": 0.5, "acceleration": 2.0}

# THK's preload drag on the 32 x 10 mm screw of AXIS_CASE: K = 0.05 / sqrt(tan beta),
# tan beta = 10 / (32 pi) = 0.0994718, K = 0.158533; T_p = K F_pr l / 2 pi.
TAN_BETA = 0.01 / (math.pi * 0.032)
K_DRAG = 0.05 / math.sqrt(TAN_BETA)


def _text(nut: str = "single", preload: str = "0 N", support: str = "fixed-supported",
          axis_extra: str = "", sections: str = "", mass: str = "200 kg",
          rating: str = "20 kN") -> str:  # fmt: skip
    text = AXIS_CASE.format(nut=nut, preload=preload, support=support, axis_extra=axis_extra,
                            sections=sections)  # fmt: skip
    text = text.replace('moving_mass = "200 kg"', f'moving_mass = "{mass}"')
    return text.replace('dynamic_load_rating = "20 kN"', f'dynamic_load_rating = "{rating}"')


def _check(text: str, move: dict[str, float] | None = None, model: str = "catalog",
           profile: Profile | None = None) -> Any:  # fmt: skip
    m = dict(MOVE if move is None else move)
    prof = profile_from_move(m, 1) if profile is None else profile
    run = run_energy(parse_case(text), prof, [model], run_time=60.0,
                     move=m if profile is None else None)  # fmt: skip
    return run_check(run, model)


def _note(result: Any, start: str) -> str:
    return next(a for a in result.assumptions if a.startswith(start))


def test_a_single_nut_without_tolerances_draws_nothing_but_the_friction() -> None:
    # No [check] tolerance and no preload: every factor but the friction's is exactly 1,
    # so the life and the static safety (forces, preload, ratings) have no spread, and no
    # preload band is taken (there is no preload to set by its drag torque).
    result = _check(_text(), {**MOVE, "force": 1000.0})
    note = _note(result, "uncertainty: Monte Carlo")
    assert "mass +-0%, process force +-0%, preload +-0%, load ratings +-0%" in note
    assert not any("preload tolerance" in a for a in result.assumptions)
    for key in ("life", "static_safety", "buckling"):
        row = result.row(key)
        assert row.uncertainty.low == row.uncertainty.high == row.utilisation, key


def test_a_model_the_scorecard_lacks_draws_no_friction_factor() -> None:
    # Olaru's model has no printed rows: its error is unknown (NaN), the draws take the
    # friction as exact (sigma 0, no bias), and with no tolerance either every row's
    # interval is its nominal utilisation, the thermal lead error's included.
    result = _check(_text(sections='[check]\naccuracy_grade = "C5"'), model="olaru")
    assert "x exp(-0 + N(0, 0))" in _note(result, "uncertainty: Monte Carlo")
    thermal = result.row("thermal_error")
    assert thermal.utilisation > 0.0
    for row in result.criteria:
        if row.utilisation is not None:
            assert (row.uncertainty.low, row.uncertainty.high) == (row.utilisation,) * 2


def test_a_double_nut_without_preload_has_no_lift_off_and_no_preload_band() -> None:
    # Nothing to lift off and no preload to set by its drag torque: no row, no note.
    result = _check(_text(nut="double", preload="0 N"))
    assert result.row("lift_off") is None and result.stiffness["lifted_off"] is False
    assert not any("preload" in a and "band" in a for a in result.assumptions)
    assert "preload +-0%" in _note(result, "uncertainty: Monte Carlo")
    # With no preload one half carries the load: the nut is as stiff as a single nut of the
    # same geometry at the cycle's peak load (400 N, m a), not the near-zero tangent of an
    # unloaded contact (0.86 N/um, as it was), and it has a single nut's axial play.
    single = _check(_text())
    assert result.stiffness["nut_N_per_um"] == pytest.approx(
        single.stiffness["nut_N_per_um"], rel=1e-9
    )
    assert result.stiffness["nut_N_per_um"] > 100.0
    assert _note(result, "double nut without preload: stiffness at the cycle's peak load 400 N")
    assert "Hertz at the cycle's peak load (no preload)" in result.row("stiffness").source
    assert "+ the axial play 20 um" in result.row("lost_motion").source
    # A preloaded double nut has no play, and its Hertz stiffness is the preload's.
    preloaded = _check(_text(nut="double", preload="2 kN"))
    assert "axial play" not in preloaded.row("lost_motion").source
    assert "Hertz at the preload," in preloaded.row("stiffness").source


def test_half_a_newton_of_preload_lifts_off_and_takes_the_lowest_band() -> None:
    # 0.5 N of preload under the table's 400 N (m a): 800 times the preload, far past
    # 2^1.5; the nut is one half at 400 N. Its drag torque K F_pr l / 2 pi = 1.26e-4 N*m
    # lies below THK's table (0.2 N*m and up): the lowest row's +-45 % is taken.
    text = _text(nut="double", preload="0.5 N")
    result = _check(text)
    row = result.row("lift_off")
    assert row is not None and row.value == pytest.approx(400.0, rel=1e-9)
    assert row.limit == pytest.approx(2**1.5 * 0.5, rel=1e-12) and row.verdict == "NOT OK"
    assert result.stiffness["lifted_off"] is True
    screw = parse_case(text).screw
    lifted, preloaded = design_nut_stiffness(screw, 400.0), design_nut_stiffness(screw)
    note = _note(result, "lift-off: ")
    assert "the peak load 400 N is 800 times the preload" in note
    assert f"{lifted / 1e6:.4g} N/um against {preloaded / 1e6:.4g} N/um preloaded" in note
    torque = K_DRAG * 0.5 * 0.01 / (2.0 * math.pi)
    band = _note(result, "preload tolerance")
    assert band.startswith("preload tolerance +-45% (default") and f"{torque:.3g} N*m" in band


@pytest.mark.parametrize(
    ("preload", "band"),
    [(500.0, 0.45), (3000.0, 0.30), (5000.0, 0.25), (12_000.0, 0.20), (30_000.0, 0.20)],
)
def test_the_default_preload_band_is_thks_row_at_the_drag_torque(preload: float,
                                                                  band: float) -> None:  # fmt: skip
    # T_p = K F_pr l / 2 pi = 2.5231e-4 N*m per N: 0.126, 0.757, 1.26, 3.03 and 7.57 N*m,
    # in THK A-688 Table 13's (C3) rows below 0.4 (45 %, the lowest row also below its
    # 0.2), 0.6-1.0 (30 %), 1.0-2.5 (25 %), 2.5-6.3 (20 %), and past the table's 6.3 N*m
    # the last row's 20 %.
    screw = SimpleNamespace(preload=preload, lead=0.01, lead_angle=math.atan(TAN_BETA))
    run = SimpleNamespace(case=SimpleNamespace(screw=screw, check={}, assumptions=[]))
    notes: list[str] = []
    tolerances = check_module._tolerances(run, notes)  # type: ignore[arg-type]
    assert tolerances == (0.0, 0.0, band, 0.0, True)
    torque = K_DRAG * preload * 0.01 / (2.0 * math.pi)
    assert f"at the catalogue drag torque {torque:.3g} N*m" in notes[0]


MOTOR = '[motor]\nrated_torque = "2 N*m"\npeak_torque = "6 N*m"\nrated_speed = "3000 rpm"'
INERTIA = (
    'motor_inertia = "2e-4 kg*m**2"\nscrew_inertia = "8e-4 kg*m**2"\ndn_limit = "150000 mm*rpm"'
)


def test_a_row_at_its_limit_exactly_does_not_count_as_failing() -> None:
    # The motor turns at its rated 3000 rpm (0.5 m/s on a 10 mm lead): utilisation 1,
    # CHECK, with no uncertain input. Fixed at both ends (critical speed 0.76), d*n under
    # a limit of 150 000, 5000 h asked of a life of about 17 000 h: no other row comes near
    # its limit in any draw, so the probability that one row or more fails is 0.
    result = _check(_text(nut="double", preload="1 kN", support="fixed-fixed",
                          axis_extra=INERTIA,
                          sections=MOTOR + '\n[check]\nrequired_life = "5000 h"'))  # fmt: skip
    row = result.row("motor_speed")
    assert row.utilisation == 1.0 and row.verdict == "CHECK"
    assert row.uncertainty.p_not_ok == 0.0
    assert all(r.verdict in ("OK", "CHECK", "INFO") for r in result.criteria)
    assert result.p_not_ok == 0.0


@pytest.mark.parametrize(("preload", "level"), [("3800 N", "below 1 N*m"),
                                                ("4200 N", "1 N*m and above")])  # fmt: skip
def test_the_model_error_is_taken_at_the_creep_drag_torque(preload: str, level: str) -> None:
    # THK's rule on this screw: 2.5231e-4 N*m per newton of preload, 0.959 N*m at 3.8 kN
    # and 1.060 N*m at 4.2 kN (C_a 40 kN keeps that preload within the makers' 20 %): the
    # scorecard's rows of the two torque levels either side of 1 N*m.
    result = _check(_text(nut="double", preload=preload, rating="40 kN"))
    f_pr = float(preload.split()[0])
    torque = K_DRAG * f_pr * 0.01 / (2.0 * math.pi)
    assert result.stiffness["friction_force_N"] * 0.01 / (2 * math.pi) == pytest.approx(
        torque, rel=1e-6)  # fmt: skip
    assert f"double nuts, {level};" in _note(result, "model error of catalog")


def _heat_speed(result: Any) -> float:
    note = _note(result, "model error of catalog")
    return float(re.findall(r"friction heat is made at about (\d+) rpm", note)[0])


def test_the_heat_of_a_light_table_is_made_at_two_thirds_of_the_feed() -> None:
    # A single nut has no drag without load: a 1 kg table loads it only on the ramps
    # (m a = 2 N), where the speed rises linearly from 0 to 3000 rpm under a constant
    # friction torque. The heat-weighted mean speed of a ramp, int w^2 dt / int w dt, is
    # 2/3 of its top: 2000 rpm (the heat, about 0.015 J, is far below a joule).
    result = _check(_text(mass="1 kg"))
    assert _heat_speed(result) == pytest.approx(2000.0, abs=1.0)  # printed to the rpm


def test_the_heat_speed_is_a_time_integral_whatever_the_sampling() -> None:
    # A preloaded nut drags with the same torque at every speed (THK's rule): the heat-
    # weighted speed is int w^2 dt / int w dt over the move. 0.4 m at 0.5 m/s with 2.5 m/s^2
    # ramps: 0.2 s each way (0.05 m), 0.6 s at 0.5 m/s. int v^2 dt = 2 a^2 t^3 / 3 + v^2 t
    # = 0.033333 + 0.15 = 0.183333 m^2/s over int v dt = 0.4 m: 0.458333 m/s, 2750 rpm.
    # The cruise is kept at every 10th sample only: the trapezoid's weights differ.
    move = {"stroke": 0.4, "feed": 0.5, "acceleration": 2.5}
    p = profile_from_move(move, 1)
    ramps = np.flatnonzero(p.acceleration != 0.0)
    keep = np.union1d(np.union1d(ramps, np.clip(ramps + 1, 0, p.time.size - 1)),
                      np.arange(0, p.time.size, 10))  # fmt: skip
    keep = np.union1d(keep, [p.time.size - 1])
    thinned = Profile(p.time[keep], p.position[keep], p.speed[keep], p.acceleration[keep],
                      p.process_force[keep])  # fmt: skip
    assert np.ptp(np.diff(thinned.time)) > 5e-3  # not uniform: 1 ms and 10 ms steps
    result = _check(_text(nut="double", preload="1 kN", mass="1 kg"), profile=thinned)
    # 1e-3: the 1 kg table's load friction (2.5 N x 3 % of its torque) on the ramps.
    assert _heat_speed(result) == pytest.approx(2750.0, rel=1e-3)


def test_doubling_the_friction_behind_a_gear_adds_the_drag_at_the_motor() -> None:
    # tests/axis/test_check.py's geared axis: peak 1.459475 N*m while accelerating, of which
    # the screw's drag at the motor (0.252313 + 0.019396) / 2 = 0.135855 N*m. Twice the
    # friction adds that drag once more at the same sample: 1.595330 N*m.
    motor = '[motor]\nrated_torque = "2 N*m"\npeak_torque = "6 N*m"\nrated_speed = "6000 rpm"'
    gear = 'motor_inertia = "2e-4 kg*m**2"\nscrew_inertia = "8e-4 kg*m**2"\ngear_ratio = 2'
    text = _text(nut="double", preload="1 kN", axis_extra=gear, sections=motor)
    run = run_energy(parse_case(text), profile_from_move(MOVE, 1), ["catalog"], run_time=60.0,
                     move=dict(MOVE))  # fmt: skip
    inputs = check_module.criterion_inputs(run)
    doubled = replace(ones(), friction=np.array([2.0]))
    peak = float(check_module.CRITERIA["peak_torque"].value(Sample(inputs, doubled))[0])
    assert peak == pytest.approx(1.459475 + 0.135855, rel=2e-6)


_BARE: dict[str, Any] = dict(
    mass_force=np.zeros(1), process_force=np.zeros(1), turns=np.ones(1),
    motor_torque=np.zeros(1), torque_mass_force=np.zeros(1), torque_process_force=np.zeros(1),
    motor_friction=np.zeros(1), weights=np.ones(1), duration=1.0, rms_torque=0.0, lead=0.01,
    gear_ratio=1.0, preload=0.0, preloaded=False, dynamic_rating=None, static_rating=None,
    load_factor=1.0, reliability=0.9, temperature_rise=0.0, pretension=0.0, moving_mass=0.0,
    screw_inertia=0.0, coupling_inertia=0.0, motor_inertia=1e-4,
)  # fmt: skip
"""One sample at rest, a 10 mm lead, no gear: the drawn criteria's inputs set by hand."""


def test_a_cycle_of_more_samples_than_a_block_is_drawn_one_draw_at_a_time() -> None:
    # 2 000 001 distinct force samples, more than a block of 2 million (draw, sample)
    # pairs holds: one draw per block. The peak force 2000 N is 2 kN against a 4 kN
    # buckling limit, 0.5 in every draw.
    n = 2_000_001
    force = np.linspace(0.0, 2000.0, n)
    inputs = Inputs(**(_BARE | {"mass_force": force, "process_force": np.zeros(n),
                                "turns": np.ones(n)}))  # fmt: skip
    row = Criterion("buckling load", 2.0, 4.0, "kN", 0.5, "OK", "", key="buckling")
    out = check_module._row_samples(inputs, [row], ones(3))
    np.testing.assert_array_equal(out["buckling"], [0.5, 0.5, 0.5])


def test_a_single_nuts_play_is_stated_where_it_is_added() -> None:
    # 10 um given: the note and the lost motion's source say so, in micrometres.
    result = _check(_text(sections='[check]\naxial_play = "10 um"'))
    assert "its axial play 10 um (given) is added to the lost motion" in "\n".join(
        result.assumptions)  # fmt: skip
    assert "+ the axial play 10 um" in result.row("lost_motion").source


# --- axis/criteria.py ----------------------------------------------------------------------


def test_the_halves_of_a_nut_under_half_a_newton() -> None:
    # A preloaded nut of 1 kN under +0.5 N: the first half is the more loaded one,
    # F_pr (1 + F / (2^1.5 F_pr))^1.5 = 1000.26518 N, the second carries that less the
    # force, 999.76518 N (ISO 3408-5's halves: their difference is the force), the other way
    # round at -0.5 N. A single nut's flanks carry one sign of the force each: 0.5 and 0.
    more = 1000.0 * (1.0 + 0.5 / (2.0**1.5 * 1000.0)) ** 1.5
    less = more - 0.5
    h1, h2 = nut_halves(np.array([0.5, -0.5]), 1000.0, preloaded=True)
    np.testing.assert_allclose(h1, [more, less], rtol=1e-14)
    np.testing.assert_allclose(h2, [less, more], rtol=1e-14)
    s1, s2 = nut_halves(np.array([0.5, -0.5]), 0.0, preloaded=False)
    np.testing.assert_array_equal(s1, [0.5, 0.0])
    np.testing.assert_array_equal(s2, [0.0, 0.5])


def test_a_lightly_loaded_flank_alone_sets_a_single_nuts_life() -> None:
    # 10 N on one flank of a single nut of C_a 20 kN, f_w 1, a1 1 (90 %): ISO 3408-5's
    # (20000 / 10)^3 1e6 = 8e15 turns; the other flank carries nothing and lasts for ever,
    # so the pair lasts what the loaded flank does (1e-12: the power's rounding). At 60 rpm:
    # 8e15 / 3600 h.
    force = np.full((1, 3), 10.0)
    hours = life_hours(force, np.zeros(1), np.array([20_000.0]), np.ones(3), 60.0,
                       preloaded=False, load_factor=1.0, reliability=0.9)  # fmt: skip
    assert hours[0] == pytest.approx(8e15 / 3600.0, rel=1e-12)


def test_the_inertia_ratio_behind_a_gear_of_three() -> None:
    # J_load = (J_s + J_c + m (l / 2 pi)^2) / i^2 (THK A15-47's reflected inertia): 8e-4,
    # 1e-4 and 200 kg on a 10 mm lead, 1:3: (9e-4 + 5.066059e-4) / 9 = 1.562895e-4 kg m^2,
    # 0.781448 times a rotor of 2e-4 kg m^2 (a gear of 2 would not tell i^2 from 2 i).
    x = Inputs(**(_BARE | {"gear_ratio": 3.0, "screw_inertia": 8e-4, "coupling_inertia": 1e-4,
                           "moving_mass": 200.0, "motor_inertia": 2e-4}))  # fmt: skip
    j = (9e-4 + 200.0 * (0.01 / (2.0 * math.pi)) ** 2) / 9.0
    value = float(check_module.CRITERIA["inertia_ratio"].value(Sample(x, ones()))[0])
    assert value == pytest.approx(j / 2e-4, rel=1e-12)


# --- axis/uncertainty.py -------------------------------------------------------------------


def test_the_guard_bands_edges() -> None:
    # 95 of 100 draws past the limit: P = 0.95 exactly, NOT OK with 95 % confidence.
    r = judge(np.r_[np.full(5, 0.5), np.full(95, 2.0)])
    assert r.p_not_ok == 0.95 and r.guarded == "NOT OK (95 %)"
    # A utilisation of exactly 1 passes (above 1 fails).
    assert judge(np.ones(10)).p_not_ok == 0.0
    # The central 95 %: the 2.5 % and 97.5 % quantiles of 0, 1/4000, ..., 1 are 0.025 and
    # 0.975 (sample 100 and 3900 of 4000 steps).
    r = judge(np.linspace(0.0, 1.0, 4001))
    assert (r.low, r.high) == pytest.approx((0.025, 0.975), abs=1e-15)


def test_draws_without_a_bias_have_the_median_one() -> None:
    # No tolerance and a friction sigma of 0: every factor is 1 (no bias unless one is
    # given); 10 % on the mass: 1 +- 0.1, uniform.
    d = draws(0.1, 0.0, 0.0, 0.0, 0.0)
    np.testing.assert_array_equal(d.friction, np.ones(SAMPLES))
    np.testing.assert_array_equal(d.force, np.ones(SAMPLES))
    assert 0.9 <= d.mass.min() < 0.901 and 1.099 < d.mass.max() <= 1.1


def test_the_model_errors_torque_level_and_law_speed_edges() -> None:
    # The scorecard's levels: below 1 N*m, and 1 N*m and above (scripts/model_scatter.py
    # puts a reference of exactly 1 N*m in the upper one). Jungnickel's law is shown from
    # 1000 rpm on (its rows: 1000 to 3000 rpm).
    assert "1 N*m and above" in model_error("catalog", "double", 1.0).text
    assert "below 1 N*m" in model_error("catalog", "double", 0.999).text
    assert "Jungnickel" in model_error("catalog", "double", 0.3, speed=1000.0).text
    assert "Jungnickel" not in model_error("catalog", "double", 0.3, speed=999.0).text
    assert model_error("olaru", "double", 0.3).rows == 0  # no rows: none counted


def _printed_row(model: str, nut: str) -> dict[str, str]:
    text = resources.files("ballscrew").joinpath("data/model_scatter.csv").read_text("utf-8")
    data = csv.DictReader(line for line in text.splitlines() if not line.startswith("#"))
    return next(d for d in data if d["model"] == model and d["reference"] == "printed"
                and d["nut"] == nut and d["level"] == "below 1 N*m"
                and d["role"] == "test")  # fmt: skip


def test_the_model_errors_text_gives_the_median_factor() -> None:
    # The true torque's median is the model's times 10^-b, b the rows' mean log10 ratio,
    # read here from the shipped data file: the catalogue rule against a 4-point nut's
    # reference (1.25 times the rule), b = -0.0969, x 1.25.
    row = _printed_row("catalog", "single-4point")
    factor = 10.0 ** -float(row["mean_log10"])
    assert f"{factor:.3g}" == "1.25"
    assert f"the model's x {factor:.3g})" in model_error("catalog", "single-4point", 0.3).text
    # The complete model's sigma(ln T): sqrt(s^2 (1 + 1/n) + u_ref^2) ln 10 of its row.
    row = _printed_row("complete", "double")
    error = model_error("complete", "double", 0.3)
    n, sd, ref = int(row["rows"]), float(row["sd_log10"]), float(row["reference_sd_log10"])
    sigma = math.sqrt(sd * sd * (1.0 + 1.0 / n) + ref * ref) * math.log(10.0)
    assert error.sigma == pytest.approx(sigma, rel=1e-12)
    assert error.bias == pytest.approx(float(row["mean_log10"]) * math.log(10.0), rel=1e-12)


def test_the_four_point_range_is_skfs_and_jungnickels() -> None:
    # SKF's constant friction coefficients, four-point over angular contact bearings,
    # 0.0024 / 0.0020 = 1.2; Jungnickel's law gives up to 1.32 (study.validation).
    assert FOUR_POINT_RANGE == pytest.approx((0.0024 / 0.0020, 1.32), rel=1e-12)


# --- axis/standstill.py --------------------------------------------------------------------


def test_the_mad_to_sigma_factor_is_one_over_the_normal_quartile() -> None:
    assert standstill._MAD_TO_SIGMA == pytest.approx(1.0 / norm.ppf(0.75), rel=1e-15)


def test_the_width_of_a_quantised_trace_by_hand() -> None:
    # At rest on one count of 0.1 um with two flips (tests/axis/test_standstill.py): the
    # noise is the quantisation's, q / sqrt(12); at 50 Hz through the central difference
    # (gain 1/sqrt 2) and k = 8: v_s = 8 q / (sqrt(12) sqrt(2) 0.02 s) = 8.165e-6 m/s.
    x = np.zeros(200)
    x[50] = x[120] = 1e-7
    t = np.arange(200) * 0.02
    width = 8.0 * 1e-7 / math.sqrt(12.0) / math.sqrt(2.0) / 0.02
    assert standstill_speed(x, t) == pytest.approx(width, rel=1e-12)
    # Six samples are enough to tell (five are not); times that do not increase are refused.
    flips = np.array([0.0, 1e-7, 0.0, 0.0, 1e-7, 0.0])
    assert standstill_speed(flips, t[:6]) >= 8.0 * 1e-7 / math.sqrt(24.0) / 0.02
    assert standstill_speed(flips[:5], t[:5]) == 0.0
    with pytest.raises(BallScrewInputError, match="time"):
        standstill_speed(x[:10], np.zeros(10))


def test_the_noise_of_too_few_or_constant_samples() -> None:
    # Third differences need order + 2 = 5 samples at least; first ones 3; a constant trace
    # has no noise and no quantum.
    assert noise_scatter(np.zeros(5)) == 0.0
    with pytest.raises(BallScrewInputError, match=r"'. samples' is not allowed: at least 5$"):
        noise_scatter(np.zeros(4))
    assert noise_scatter(np.zeros(3), order=1) == 0.0
    with pytest.raises(BallScrewInputError, match="order"):
        noise_scatter(np.zeros(10), order=0)


def test_the_noise_on_a_constant_jerk_is_the_noises() -> None:
    # A constant jerk j has the constant third difference j dt^3 (8e-5 m here, 80 times the
    # noise): the median takes it, and the scatter about it is the 1 um noise's. 4000
    # samples: the MAD's sampling error is about 1.65 / sqrt(4000) = 2.6 %; 8 % is three.
    rng = np.random.default_rng(5)
    t = np.arange(4000) * 0.02
    x = 10.0 * t**3 / 6.0 + rng.normal(0.0, 1e-6, t.size)
    assert noise_scatter(x) == pytest.approx(1e-6, rel=0.08)


def test_a_quantum_is_whole_multiples_to_one_percent_in_99_steps_of_100() -> None:
    # Steps of 1 and 99 of 2.0095 quanta: every ratio within 1 % of a whole number; 2.0105:
    # not. 99 of 100 steps whole is enough: one step of 1.5 quanta among them still reads.
    q = 1e-7
    assert standstill._quantum(np.cumsum(np.r_[0.0, 1.0, np.full(99, 2.0095)]) * q) == q
    assert standstill._quantum(np.cumsum(np.r_[0.0, 1.0, np.full(99, 2.0105)]) * q) == 0.0
    steps = np.r_[0.0, 1.0, np.full(98, 2.0), 1.5]  # 99 whole of 100
    assert standstill._quantum(np.cumsum(steps) * q) == q
    steps = np.r_[0.0, 1.0, np.full(97, 2.0), 1.5, 1.5]  # 98 of 100
    assert standstill._quantum(np.cumsum(steps) * q) == 0.0


# --- axis/setup.py -------------------------------------------------------------------------


def test_the_estimated_length_names_the_travel() -> None:
    derived = axis_setup(reference_screw(), {"moving_mass": 1.0}, {}, 0.3).derived
    assert derived["axis.screw_length"][1] == (
        "from the travel 300 mm, the nut and 4 pitch diameters"
    )


# --- axis/duty.py --------------------------------------------------------------------------

DUTY = AXIS_CASE.format(nut="double", preload="1 kN", support="fixed-fixed",
                        axis_extra='max_feed = "30 m/min"\ndn_limit = "120000 mm*rpm"',
                        sections="")  # fmt: skip


def test_the_run_times_range_and_default() -> None:
    # More than 0 and at most 100 000 h; the default is the commands' --run-time "1 h".
    case, profile = parse_case(DUTY), profile_from_move(MOVE, 1)
    assert run_energy(case, profile, ["catalog"]).run_time == to_si("--run-time", "1 h", "s")
    assert EnergyRun.__dataclass_fields__["run_time"].default == 3600.0
    for hours in (0.5 / 3600.0, 100_000.0):
        assert run_energy(case, profile, ["catalog"], run_time=hours * 3600.0).run_time > 0.0
    for seconds, shown in ((0.0, "'0 h'"), (100_001 * 3600.0, "'100001 h'")):
        with pytest.raises(BallScrewInputError, match=f"--run-time = {shown}"):
            run_energy(case, profile, ["catalog"], run_time=seconds)


def test_at_most_a_thousand_steady_speeds(monkeypatch: pytest.MonkeyPatch) -> None:
    # 1000 speeds are solved (the solver stubbed here: only the count is checked), 1001 not.
    seen: list[int] = []

    def solver(screw: Any, lubricant: Any, node: Any, speeds: Any, **kw: Any) -> None:
        seen.append(int(np.size(speeds)))

    monkeypatch.setattr(duty, "steady_at_speeds", solver)
    case, profile = parse_case(DUTY), profile_from_move(MOVE, 1)
    run_energy(case, profile, ["catalog"], steady_speeds=np.linspace(1.0, 300.0, 1000))
    assert seen == [1000]
    with pytest.raises(BallScrewInputError, match="at most 1000 speeds"):
        run_energy(case, profile, ["catalog"], steady_speeds=np.linspace(1.0, 300.0, 1001))


def test_a_feed_at_the_axis_limit_passes_and_one_above_is_shown_in_m_per_min() -> None:
    # max_feed 30 m/min = 0.5 m/s exactly: a move at 0.5 m/s passes; at 20 m/min it is
    # refused, both feeds in m/min as machine tools give them.
    run_energy(parse_case(DUTY), profile_from_move(MOVE, 1), ["catalog"])
    slower = parse_case(DUTY.replace('"30 m/min"', '"20 m/min"'))
    with pytest.raises(BallScrewInputError, match=r"0\.5 m/s \(30 m/min\).*\(20 m/min\)"):
        run_energy(slower, profile_from_move(MOVE, 1), ["catalog"])


def test_a_force_window_given_by_its_end_starts_at_the_start() -> None:
    p = profile_from_move({**MOVE, "force": 100.0, "force_to": 0.1}, 1)
    loaded = p.position[p.process_force != 0.0]
    assert loaded.min() == 0.0 and loaded.max() == pytest.approx(0.1, abs=1e-12)


def test_steady_running_without_a_move_force_takes_no_load() -> None:
    # The catalogue model at no load is THK's preload drag: K F_pr l / 2 pi = 0.252313 N*m.
    run = run_energy(parse_case(DUTY), profile_from_move(MOVE, 1), ["catalog"],
                     steady_speeds=[100.0], move=dict(MOVE))  # fmt: skip
    at = run.results["catalog"].steady_at_speed
    expected = K_DRAG * 1000.0 * 0.01 / (2.0 * math.pi)
    np.testing.assert_allclose(at.torque, [expected], rtol=1e-6)


def test_the_energy_at_the_final_temperature_is_the_warm_oils() -> None:
    # The complete model's drag is partly viscous: the screw warmed to about 29.6 degC over
    # the hour makes less friction than at the 20 degC the cycle was computed at.
    run = run_energy(parse_case(DUTY), profile_from_move(MOVE, 1), ["complete"])
    r = run.results["complete"]
    assert r.final_temperature > run.temperature + 5.0
    assert r.friction_energy_at_final_temperature < 0.99 * r.cycle.friction_energy


def test_the_energy_per_cycle_is_one_cycles() -> None:
    case = parse_case(DUTY)
    one = run_energy(case, profile_from_move(MOVE, 1), ["catalog"]).as_dict()
    three = run_energy(case, profile_from_move(MOVE, 3), ["catalog"], cycles=3).as_dict()
    assert three["friction_energy_per_cycle_J"] == pytest.approx(
        one["friction_energy_J"], rel=1e-9)  # fmt: skip


def test_a_trajectory_file_repeated(tmp_path: Any) -> None:
    # 1 s of a trajectory, at rest then 10 mm, repeated 3 times: 3 s and 30 mm, each
    # repetition starting where the last ended.
    t = np.linspace(0.0, 1.0, 101)
    x = np.where(t < 0.5, 0.0, 10.0 * (t - 0.5) / 0.5)
    path = tmp_path / "move.csv"
    path.write_text("time [s],position [mm]\n"
                    + "\n".join(f"{a:.2f},{b:.3f}" for a, b in zip(t, x, strict=True)))  # fmt: skip
    one = duty.profile_from_file(str(path), 1, standstill_speed=0.0)
    three = duty.profile_from_file(str(path), 3, standstill_speed=0.0)
    assert three.duration == pytest.approx(3.0 * one.duration, rel=1e-12)
    assert np.ptp(three.position) == pytest.approx(3.0 * np.ptp(one.position), rel=1e-12)


def _with_third_differences(d: list[float]) -> np.ndarray:
    """A trace whose third differences are exactly ``d`` (integers: every sum is exact)."""
    y = np.concatenate([[0.0, 0.0, 0.0], np.asarray(d, dtype=float)])
    return np.cumsum(np.cumsum(np.cumsum(y)))


def test_noise_scatter_cuts_at_four_spreads_about_the_median() -> None:
    # Third differences 100 + k for k = -50..50, and two readings at 100 +/- 160. The median
    # is 100; the deviations are 0, then 1..50 twice, then 160 twice: their median (the 52nd
    # of 103) is 26, a spread of 1.4826 * 26 = 38.55 and a cut at 4 spreads of 154.2, which
    # drops the two at 160 (4.4 spreads, 169.6, would keep them). Without them the median
    # deviation is the 51st of 101, 25: sigma = 1.4826 * 25 / sqrt(20) = 8.288 (the 1.4826
    # to 4 digits: 1e-4 relative). Kept, they would give 26 instead of 25 (+4 %); a cut
    # measured from -100 instead of 100 would keep 6 readings, and a quite other number.
    d = [100.0 + k for k in range(-50, 51)] + [-60.0, 260.0]
    sigma = noise_scatter(_with_third_differences(d))
    assert sigma == pytest.approx(1.4826 * 25 / math.sqrt(20.0), rel=1e-4)


def test_noise_scatter_keeps_a_cut_of_exactly_five_differences() -> None:
    # Nine third differences: -2..2 and +/-100, +/-200. Median 0; deviations 0,1,1,2,2,100,
    # 100,200,200, median 2, a cut at 4 * 1.4826 * 2 = 11.9 that keeps exactly five (the
    # least allowed): the next pass's median deviation is 1, sigma = 1.4826 / sqrt(20) =
    # 0.3315. Stopping at five (a floor of 6) would leave the first pass's 0.663. The trace
    # is read in whole steps, whose quantisation floor 1/sqrt(12) = 0.289 lies below.
    d = [-2.0, -1.0, 0.0, 1.0, 2.0, 100.0, 200.0, -100.0, -200.0]
    sigma = noise_scatter(_with_third_differences(d))
    assert sigma == pytest.approx(1.4826 / math.sqrt(20.0), rel=1e-4)
