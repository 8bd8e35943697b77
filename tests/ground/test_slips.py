"""Inputs typed loosely are read as meant or refused naming the field (issue 35).

Each slip below was misread silently by release 0.2.0 (the attack's list): a range with
three points, two values typed with a space for one, a key of --move given twice. Each
is now refused, with the form that works in the message.
"""

from __future__ import annotations

import numpy as np
import pytest

from ballscrew import friction_torque, reference_screw
from ballscrew.axis.motion import parse_move
from ballscrew.errors import BallScrewInputError
from ballscrew.io.units import parse_range, to_si


@pytest.mark.parametrize(
    ("text", "hint"),
    [
        ("10...3000:3 rpm", "'a..b unit'"),  # 0.2.0: 10, 5.15 and 0.3 rpm
        ("10\u20263000 rpm", "'a..b unit'"),  # the ellipsis character
    ],
)
def test_a_range_with_three_points_is_refused(text: str, hint: str) -> None:
    with pytest.raises(BallScrewInputError, match="speed") as err:
        parse_range("speed", text, "rad/s")
    assert hint in str(err.value)


@pytest.mark.parametrize("reader", ["one value", "a list"])
def test_two_values_typed_with_a_space_are_refused(reader: str) -> None:
    # 0.2.0 read '0 500 N' as one value of 500 N: a thousands group cannot start with 0.
    with pytest.raises(BallScrewInputError, match=r"axial_load.*'0, 500'"):
        if reader == "one value":
            to_si("axial_load", "0 500 N", "N")
        else:
            parse_range("axial_load", "0 500 N", "N")


@pytest.mark.parametrize(("text", "meant"), [("1 200 N", 1200.0), ("12 500 N", 12500.0)])
def test_thousands_groups_are_still_read(text: str, meant: float) -> None:
    assert to_si("axial_load", text, "N") == meant


def test_a_move_key_given_twice_is_refused() -> None:
    # 0.2.0 kept the last stroke (200 mm) without a word.
    with pytest.raises(BallScrewInputError, match=r"--move stroke.*twice"):
        parse_move("stroke=300 mm, feed=1 m/min, acceleration=1 m/s^2, stroke=200 mm")


@pytest.mark.parametrize(
    ("value", "why"),
    [
        (b"100", "not bytes"),  # 0.2.0: 100 rad/s
        (np.datetime64("2026-11-26"), "not a date"),  # 0.2.0: days since 1970 as rad/s
        (np.timedelta64(3, "s"), "not a time span"),
        (True, "not a truth value"),  # 0.2.0: 1 rad/s
        ([10.0, True], "not a truth value"),
        ("100", "to_si"),  # text goes through the unit reader first
        (10**400, "below 1.8e308"),  # 0.2.0: OverflowError in every model
    ],
)
def test_a_speed_that_is_no_number_is_refused_by_name(value: object, why: str) -> None:
    with pytest.raises(BallScrewInputError, match="speed") as err:
        friction_torque(reference_screw(), "mineral ISO VG 68", speed=value, temperature=40.0)
    assert why in str(err.value)


@pytest.mark.parametrize("value", [100, np.float32(100.0), np.int64(100), [100, 200]])
def test_numbers_of_any_numeric_type_are_read(value: object) -> None:
    r = friction_torque(reference_screw(), "mineral ISO VG 68", speed=value, temperature=40.0,
                        model="catalog")  # fmt: skip
    assert np.all(np.asarray(r.total) > 0.0)


@pytest.mark.parametrize(
    ("parameter", "value", "why"),
    [
        ("boundary_friction", 1e10, "a friction coefficient"),  # 0.2.0: up to 2e301 N*m
        ("boundary_friction", -0.1, "a friction coefficient"),
        ("boundary_friction", [0.1, 0.2], "a real number"),  # 0.2.0: a foreign TypeError
        ("boundary_friction", True, "a real number"),
        ("limiting_shear_stress", 1e300, "a stress of 0 to 10 GPa"),
        ("limiting_shear_stress", float("nan"), "a stress of 0 to 10 GPa"),
        ("thermal_correction", "no", "true or false"),
        ("lubrication", 3, "a name"),
        ("ball_train_constant", 2.0, "a force ratio of 0 to 1"),
    ],
)
def test_a_model_parameter_out_of_its_range_or_kind_is_refused(
    parameter: str, value: object, why: str
) -> None:
    with pytest.raises(BallScrewInputError, match=parameter) as err:
        friction_torque(reference_screw(), "mineral ISO VG 68", speed=100.0, temperature=40.0,
                        model="complete", **{parameter: value})  # fmt: skip
    assert why in str(err.value)


def test_model_parameters_inside_their_ranges_are_read() -> None:
    r = friction_torque(reference_screw(), "mineral ISO VG 68", speed=100.0, temperature=40.0,
                        model="complete", boundary_friction=0.12, limiting_shear_stress=2e7,
                        thermal_correction=False)  # fmt: skip
    assert float(r.total) > 0.0


@pytest.mark.parametrize("text", ["5 K", "5 degC", "5 °C", "5 delta_degC", "9 degF"])
def test_a_temperature_rise_typed_in_celsius_is_a_rise(text: str) -> None:
    # 0.2.0 read pretension_temperature = "5 degC" as 278.15 K: the thermal error went
    # from 14.75 um NOT OK to 0 um, and the verdict to OK.
    from ballscrew.io.case import parse_case
    from shared import reference_case_toml

    toml = reference_case_toml("rise", speed="100 rpm", axial_load="0 N",
                               more=f'[check]\npretension_temperature = "{text}"\n')  # fmt: skip
    assert parse_case(toml).check["pretension_temperature"] == pytest.approx(5.0)


@pytest.mark.parametrize(("text", "absolute"), [("278.15 K", True), ("40 degC", False)])
def test_a_pretension_rise_past_what_a_shaft_is_set_for_is_refused(
    text: str, absolute: bool
) -> None:
    # Issue 52: "278.15 K" (an absolute temperature typed for a rise) was taken as a rise of
    # 278 K: the thermal error went to 0 and the verdict to OK. A rise of 30 K already
    # stresses a steel shaft by 210 GPa x 11.5e-6/K x 30 K = 72 MPa; catalogues set a few K.
    from ballscrew.io.case import parse_case
    from shared import reference_case_toml

    toml = reference_case_toml("rise", speed="100 rpm", axial_load="0 N",
                               more=f'[check]\npretension_temperature = "{text}"\n')  # fmt: skip
    with pytest.raises(BallScrewInputError) as info:
        parse_case(toml)
    said = str(info.value)
    assert "check.pretension_temperature" in said and f"'{text}'" in said
    assert "a temperature rise from 0 to 30 K" in said
    assert ("a temperature in K is absolute" in said) is absolute


@pytest.mark.parametrize(
    ("key", "text"),
    [("check.required_life", "20.000 h"), ("axis.moving_mass", "1.200 kg")],
)
def test_a_case_value_that_reads_two_ways_is_refused(key: str, text: str) -> None:
    # 0.2.0: a 20 h life limit and a 1.2 kg mass (German readers meant 20 000 h, 1200 kg).
    from ballscrew.io.case import parse_case
    from shared import reference_case_toml

    section, name = key.split(".")
    toml = reference_case_toml("slip", speed="100 rpm", axial_load="0 N",
                               more=f'[{section}]\n{name} = "{text}"\n')  # fmt: skip
    with pytest.raises(BallScrewInputError, match=key):
        parse_case(toml)


def test_a_ball_diameter_in_three_decimals_is_read_as_the_ball_it_is() -> None:
    from ballscrew.io.case import load_case

    assert load_case().screw.ball_diameter == pytest.approx(3.969e-3)  # '3.969 mm'


@pytest.mark.parametrize(
    ("change", "why"),
    [
        ({"youngs_modulus_ball": 210e6}, "GPa given as MPa"),  # 0.2.0: 7.5 x the torque
        ({"youngs_modulus_races": 2.1e15}, "5e+10 to 7e+11 Pa"),
        ({"circuits": 10**18}, "1 to 20"),  # 0.2.0: 3.8e20 N*m
        ({"loaded_turns": 25.0}, "at most 10 per circuit"),  # a designation's '25x2'
    ],
)
def test_a_screw_no_maker_builds_is_refused_by_name(change: dict[str, float], why: str) -> None:
    (name,) = change
    with pytest.raises(BallScrewInputError, match=name) as err:
        reference_screw().replace(**change)
    assert why in str(err.value)


def test_a_designation_with_25_turns_is_refused() -> None:
    from ballscrew.io.case import parse_case

    toml = '[screw]\ndesignation = "40x10 double 25x2 6.35"\npreload = "2 kN"\n'
    toml += '[lubricant]\nname = "mineral ISO VG 68"\n[operation]\nspeed = "100 rpm"\n'
    with pytest.raises(BallScrewInputError, match="loaded_turns"):
        parse_case(toml)


@pytest.mark.parametrize("workers", [0, 100_000, True])
def test_a_sweep_asking_for_absurd_workers_is_refused(workers: int) -> None:
    # 0.2.0 tried to start 100 000 local processes.
    from ballscrew.sweep.execute import run_sweep
    from shared import ROOT

    with pytest.raises(BallScrewInputError, match="--workers"):
        run_sweep(ROOT / "examples" / "sweep_preload.toml", "unused.zarr", workers=workers)


def _case_with(section: str, lines: str) -> str:
    from shared import AXIS_CASE

    text = AXIS_CASE.format(nut="double", preload="1 kN", support="fixed-supported",
                            axis_extra="", sections="")  # fmt: skip
    return text.replace(f"[{section}]\n", f"[{section}]\n{lines}\n") if f"[{section}]" in text \
        else text + f"\n[{section}]\n{lines}\n"  # fmt: skip


@pytest.mark.parametrize(
    ("section", "lines", "field", "why"),
    [
        ("screw", 'static_load_rating = "10 kN"', "screw.static_load_rating", "swapped"),
        ("motor", 'rated_torque = "6 N*m"\npeak_torque = "2 N*m"', "motor.peak_torque",
         "swapped"),
        ("axis", 'screw_length = "1000 mm"', "axis.screw_length", "bearing span 1200 mm"),
    ],
)  # fmt: skip
def test_inputs_that_contradict_each_other_are_refused(
    section: str, lines: str, field: str, why: str
) -> None:
    # 0.2.0 used each as given: C_0a below C_a (the case's C_a is 20 kN), a peak torque
    # below the rated one, a screw shorter than the span between its supports.
    from ballscrew.io.case import parse_case

    text = _case_with(section, lines)
    if section == "screw":  # the base case states C_0a; this one replaces it
        text = text.replace('static_load_rating = "50 kN"\n', "")
    with pytest.raises(BallScrewInputError, match=field) as err:
        parse_case(text)
    assert why in str(err.value)


def test_grad_is_refused_for_it_is_two_units() -> None:
    # 0.2.0: contact_angle = "45 grad" gave 40.5 deg (pint's gradian; 'Grad' is a degree).
    with pytest.raises(BallScrewInputError, match="gon"):
        to_si("screw.contact_angle", "45 grad", "rad")
    assert to_si("screw.contact_angle", "50 gon", "rad") == pytest.approx(np.pi / 4)


def test_a_negative_drag_torque_is_refused(capsys: pytest.CaptureFixture[str]) -> None:
    # 0.2.0 took 'acceptance --torque "-1 N*m"' as +1 N*m.
    from cli_runner import run
    from shared import ROOT

    case = ROOT / "src" / "ballscrew" / "data" / "kamalzadeh_stage.toml"
    code, _, err = run(["acceptance", "--case", str(case), "--torque", "-1 N*m"], capsys)
    assert code == 2 and "--torque" in err and "0 N*m or more" in err


def test_a_move_without_commas_between_its_keys_says_so() -> None:
    # 'stroke=400 mm feed=6 m/min ...' read 'mm feed' as a unit before: the message now
    # names the missing comma.
    with pytest.raises(BallScrewInputError) as info:
        parse_move("stroke=400 mm feed=6 m/min acceleration=2 m/s^2")
    assert "without a comma between them" in str(info.value)
