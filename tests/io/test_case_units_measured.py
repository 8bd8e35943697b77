"""Tests of the boundary: units, case files and measured curves."""

from __future__ import annotations

import math

import numpy as np
import pytest

from ballscrew import BallScrewInputError, reference_screw
from ballscrew.errors import BallScrewReadingWarning
from ballscrew.friction.catalog import preload_from_drag_torque, preload_torque
from ballscrew.io.case import default_case_path, load_case, parse_case
from ballscrew.io.measured import error_metrics, parse_measured
from ballscrew.io.units import parse_range, to_si
from shared import SMALL_CASE

SMALL = SMALL_CASE


@pytest.mark.parametrize(
    ("text", "unit", "expected"),
    [
        ("32 mm", "m", 0.032),
        ("1.5 kN", "N", 1500.0),
        ("45 deg", "rad", math.pi / 4),
        ("3000 rpm", "rad/s", 100 * math.pi),
        ("0.2 N*m", "N*m", 0.2),
        ("68 cSt", "m**2/s", 68e-6),
        ("17 1/GPa", "1/Pa", 17e-9),
        ("313.15 K", "degC", 40.0),
        (0.55, "", 0.55),
        ("0.55", "", 0.55),
    ],
)
def test_to_si(text: object, unit: str, expected: float) -> None:
    assert to_si("x", text, unit) == pytest.approx(expected, rel=1e-12)


@pytest.mark.parametrize(
    "bad", ["32 kg", "fast", "", "nan mm", "inf N", True, "1e999 m", "[", "(2 mm"]
)
def test_to_si_rejects(bad: object) -> None:
    with pytest.raises(BallScrewInputError, match="field"):
        to_si("field", bad, "m")


@pytest.mark.parametrize(
    "bare, unit, example",
    [
        ("100", "rad/s", "100 rpm"),
        (40, "m", "40 mm"),
        ("2", "N", "2 kN"),
        (20.0, "degC", "20.0 degC"),
    ],
)
def test_bare_numbers_with_a_dimension_are_refused_with_an_example(
    bare: object, unit: str, example: str
) -> None:
    # A bare "100" for a speed used to be read as 100 rad/s (955 rpm).
    with pytest.raises(BallScrewInputError, match="bare number") as info:
        to_si("speed", bare, unit)
    assert f"'{example}'" in str(info.value)


def test_bare_numbers_in_ranges_and_on_the_command_line_are_refused() -> None:
    with pytest.raises(BallScrewInputError, match="--speed"):
        parse_range("--speed", "0..3000:7", "rad/s")
    with pytest.raises(BallScrewInputError, match="bare number"):
        parse_range("--speed", "100, 200", "rad/s")
    assert parse_range("--speed", "100, 200 rpm", "rad/s")[1] == pytest.approx(200 * math.pi / 30)


def test_parse_range_forms() -> None:
    assert parse_range("s", "0..3000 rpm", "rad/s")[-1] == pytest.approx(100 * math.pi)
    assert len(parse_range("s", "0..3000 rpm", "rad/s")) == 50
    assert len(parse_range("s", "0..3000:7 rpm", "rad/s")) == 7
    assert parse_range("t", "20, 30, 45 degC", "degC") == [20.0, 30.0, 45.0]
    assert parse_range("f", "-1 kN, 2 kN", "N") == [-1000.0, 2000.0]
    for bad in ("", "1..", "a..b rpm", "1, , 2 rpm", "0..10:0 rpm"):
        with pytest.raises(BallScrewInputError):
            parse_range("s", bad, "rad/s")


def test_bundled_case_derives_the_preload_like_the_study() -> None:
    case = load_case()
    assert default_case_path().exists()
    # The preload turns back into the case's 0.4 N·m drag torque.
    torque = preload_torque(case.screw.preload, case.screw.lead, case.screw.lead_angle)
    assert float(torque) == pytest.approx(0.4, rel=1e-12)
    assumed = {a.field for a in case.assumptions}
    assert {"screw.pitch_diameter", "screw.lead", "screw.ball_diameter", "lubricant.name"} <= (
        assumed
    )
    assert all(a.reason for a in case.assumptions)


def test_case_errors_name_the_field() -> None:
    text = SMALL.read_text()
    cases = [
        (text.replace("lead =", "leed ="), "screw"),
        (text.replace('"3.969 mm"', '"3.969 kg"'), "screw.ball_diameter"),
        (text.replace("preload_drag_torque", "preload"), "screw.preload"),
        (
            text.replace("preload_drag_torque = {", 'preload = "1 kN"\npreload_drag_torque = {'),
            "screw.preload",
        ),
        (text + "\n[extra]\nx = 1\n", "extra"),
        ("title = [", "case"),
        (text.replace('"PAO ISO VG 68" = [', '"castor" = ['), "lubricant"),
        (
            text.replace(
                'value = 0.55, assumed = "middle of the usual 0.52 to 0.56" }',
                'value = 0.45, assumed = "x" }',
                1,
            ),
            "screw.conformity_screw",
        ),
    ]
    for bad, field in cases:
        with pytest.raises(BallScrewInputError) as info:
            parse_case(bad)
        assert field in str(info.value), (field, str(info.value))


def test_custom_lubricant_in_a_case() -> None:
    text = SMALL.read_text().replace(
        '[lubricant]\nname = { value = "PAO ISO VG 68", assumed = "the study chose PAO ISO VG 68 '
        "from the manufacturer's recommended viscosity\" }",
        '[lubricant]\nname = "my oil"\nnu40 = "46 cSt"\nnu100 = "7 cSt"\ndensity15 = "870 kg/m^3"',
    )
    case = parse_case(text)
    assert case.lubricant.name == "my oil" and case.lubricant.nu40 == pytest.approx(46e-6)


@pytest.mark.parametrize(
    ("header", "rows", "speed"),
    [
        ("speed [rpm],torque [N*m]", "60,0.3", 2 * math.pi),
        ("speed [rad/s], torque [N m]", "2,-0.3", 2.0),
        ("table speed [mm/s],torque [mN*m]", "10,300", 0.010 * 2 * math.pi / 0.010),
    ],
)
def test_measured_units(header: str, rows: str, speed: float) -> None:
    curve = parse_measured(f"{header}\n{rows}\n", reference_screw())
    assert float(curve.speed[0]) == pytest.approx(speed)
    assert float(curve.torque[0]) == pytest.approx(0.3)


def test_measured_speeds_as_frequencies_are_revolutions() -> None:
    # 60 1/min and 1 Hz are one revolution per second: 2 pi rad/s (by hand).
    per_minute = parse_measured("speed [1/min],torque [N*m]\n60,0.3\n", reference_screw())
    assert float(per_minute.speed[0]) == pytest.approx(2 * math.pi, rel=1e-12)
    with pytest.warns(BallScrewReadingWarning, match=r"column 'speed \[Hz\]' is read as rev"):
        hertz = parse_measured("speed [Hz],torque [N*m]\n1,0.3\n", reference_screw())
    assert float(hertz.speed[0]) == pytest.approx(2 * math.pi, rel=1e-12)


@pytest.mark.parametrize(
    ("text", "fragment"),
    [
        ("", "empty"),
        ("speed,torque\n1,2\n", "speed column"),
        ("speed [rpm],force [N]\n1,2\n", "torque column"),
        ("speed [rpm],torque [N*m]\n", "data row"),
        ("speed [rpm],torque [N*m]\n1,abc\n", "line 2"),
        ("speed [rpm],torque [N*m]\nnan,1\n", "finite"),
        ("speed [kN],torque [N*m]\n1,2\n", "speed column"),
        ("speed [rpm],torque [N*m]\n1e12,1\n", "below 1e5"),
    ],
)
def test_measured_errors(text: str, fragment: str) -> None:
    with pytest.raises(BallScrewInputError, match=fragment):
        parse_measured(text, reference_screw())


def test_error_metrics_by_hand() -> None:
    m = error_metrics([1.0, 3.0], [2.0, 2.0])
    assert m["rmse"] == pytest.approx(1.0)
    assert m["mean_relative"] == pytest.approx(0.5) and m["max_relative"] == pytest.approx(0.5)


def test_preloads_of_the_study_torques() -> None:
    s = load_case().screw
    f = preload_from_drag_torque(np.array([0.2, 0.6]), s)
    assert float(f[1] / f[0]) == pytest.approx(3.0)


def test_measured_csv_with_decimal_commas_and_semicolons() -> None:
    # A spreadsheet in a decimal-comma locale writes "0,31" with ";" between
    # cells; with "," between cells the decimal comma used to split the
    # number and the torque was read as 0.
    from ballscrew import reference_screw
    from ballscrew.io.measured import parse_measured

    screw = reference_screw()
    semi = parse_measured("speed [rpm];torque [N*m]\n100;0,31\n500;0,36\n", screw)
    tab = parse_measured("speed [rpm]\ttorque [N*m]\n100\t0,31\n500\t0,36\n", screw)
    plain = parse_measured("speed [rpm],torque [N*m]\n100,0.31\n500,0.36\n", screw)
    for curve in (semi, tab):
        np.testing.assert_allclose(curve.torque, plain.torque, rtol=1e-15)
        np.testing.assert_allclose(curve.speed, plain.speed, rtol=1e-15)
    with pytest.raises(BallScrewInputError, match="decimal commas need ';'"):
        parse_measured("speed [rpm],torque [N*m]\n100,0,31\n", screw)
