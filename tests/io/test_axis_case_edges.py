"""A newcomer's rough edges of release 0.3.0, as a case file and the command line meet them.

1. absurd ``[axis]`` values passed ``case --check`` (a 2500 t table on a 32 mm screw);
2. a mistyped bearing span was blamed on the screw length;
3. ``--speed "15 m/min"`` was refused though the lead is known;
4. ``select --out`` wrote no report when no candidate passed.
"""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import pytest

from ballscrew.errors import BallScrewInputError, BallScrewPlausibilityWarning
from ballscrew.io.case import parse_case
from ballscrew.io.units import parse_speed_range
from cli_runner import run
from shared import ROOT

XY = (ROOT / "examples" / "xy_table_32x10.toml").read_text(encoding="utf-8")


def _case(old: str, new: str) -> str:
    assert old in XY, old
    return XY.replace(old, new)


def test_a_2500_tonne_table_on_a_32_mm_screw_is_refused_naming_the_mass(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    path = tmp_path / "heavy.toml"
    path.write_text(_case('moving_mass = "250 kg"', 'moving_mass = "2500 t"'), encoding="utf-8")
    code, out, err = run(["case", "--check", str(path)], capsys)
    assert code == 2 and "case file OK" not in out
    assert "axis.moving_mass = '2500 t' is not allowed: at most 1.477e+04 kg" in err


def test_the_example_passes_without_a_plausibility_warning() -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", BallScrewPlausibilityWarning)
        case = parse_case(XY)
    assert case.warned == ()


def test_a_heavy_table_is_warned_of_and_kept_in_the_case() -> None:
    with pytest.warns(BallScrewPlausibilityWarning, match="axis.moving_mass = 8 t"):
        case = parse_case(_case('moving_mass = "250 kg"', 'moving_mass = "8 t"'))
    assert case.axis["moving_mass"] == 8000.0 and len(case.warned) == 1


def test_a_span_in_metres_is_blamed_on_the_span_not_the_screw_length() -> None:
    with pytest.raises(BallScrewInputError) as info:
        parse_case(_case('bearing_span = "1000 mm"', 'bearing_span = "900 m"'))
    assert info.value.field == "axis.bearing_span" and info.value.value == "900 m"
    assert "screw_length" not in str(info.value)


def test_a_long_span_beyond_the_screw_is_blamed_on_the_span_naming_both() -> None:
    # 6 m fixed-supported on a 25.5 mm root: a first bending frequency of 2.2 Hz (warned
    # alone), longer than the 1100 mm screw: the span is the implausible one of the two
    with pytest.raises(BallScrewInputError) as info:
        parse_case(_case('bearing_span = "1000 mm"', 'bearing_span = "6 m"'))
    assert info.value.field == "axis.bearing_span"
    assert "axis.screw_length = '1100 mm'" in str(info.value)
    assert "the span is the implausible one" in str(info.value)


def test_a_span_a_little_longer_than_the_screw_names_both() -> None:
    with pytest.raises(BallScrewInputError) as info:
        parse_case(_case('bearing_span = "1000 mm"', 'bearing_span = "1200 mm"'))
    assert info.value.field == "axis.screw_length"
    assert "axis.bearing_span = '1200 mm'" in str(info.value) and "mistyped" in str(info.value)


def test_a_screw_length_in_metres_is_refused_naming_it() -> None:
    with pytest.raises(BallScrewInputError) as info:
        parse_case(_case('screw_length = "1100 mm"', 'screw_length = "1100 m"'))
    assert info.value.field == "axis.screw_length" and "below 1 Hz" in info.value.allowed


@pytest.mark.parametrize(
    ("old", "new", "field"),
    [
        ('"1.2e-3 kg*m**2"', '"12 kg*m**2"', "axis.motor_inertia"),
        ('support = "fixed-supported"', 'support = "fixed-supported"\nmax_acceleration = '
         '"600 m/s**2"', "axis.max_acceleration"),
        ('support = "fixed-supported"', 'support = "fixed-supported"\nmax_feed = "200 m/s"',
         "axis.max_feed"),
        ('support = "fixed-supported"', 'support = "fixed-supported"\ngear_ratio = 5000',
         "axis.gear_ratio"),
        ('support = "fixed-supported"', 'support = "fixed-sported"', "axis.support"),
    ],
)  # fmt: skip
def test_other_absurd_axis_values_are_refused_naming_their_field(
    old: str, new: str, field: str
) -> None:
    with pytest.raises(BallScrewInputError) as info:
        parse_case(_case(old, new))
    assert info.value.field == field


def test_a_feed_limit_past_the_dn_limit_is_warned() -> None:
    text = _case('support = "fixed-supported"', 'support = "fixed-supported"\nmax_feed = "30 m/s"')
    with pytest.warns(BallScrewPlausibilityWarning, match=r"axis.max_feed = 30 m/s"):
        parse_case(text)


# --- 3. a feed on --speed ------------------------------------------------------------------


def test_15_m_per_min_at_lead_10_mm_is_1500_rpm() -> None:
    # 15 m/min / 10 mm = 1500 turns a minute, by hand; 1e-12: the float rounding of v/l
    read: list = []
    (w,) = parse_speed_range("--speed", "15 m/min", 0.010, notes=read)
    assert w * 60.0 / (2.0 * math.pi) == pytest.approx(1500.0, rel=1e-12)
    assert [str(r) for r in read] == [
        "--speed = '15 m/min' is read as 1500 rpm at lead 10 mm (a feed v turns the screw at "
        "n = v / lead)"
    ]


def test_a_feed_in_inches_at_a_quarter_inch_lead() -> None:
    # 100 in/min on a 1/4 in lead: 400 turns a minute, by hand
    (w,) = parse_speed_range("--speed", "100 in/min", 0.25 * 0.0254, notes=[])
    assert w * 60.0 / (2.0 * math.pi) == pytest.approx(400.0, rel=1e-12)


def test_a_range_of_feeds_gives_evenly_spaced_speeds() -> None:
    read: list = []
    w = parse_speed_range("--speed", "0..30 m/min:7", 0.010, notes=read)
    assert [round(v * 30.0 / math.pi, 9) for v in w] == [0, 500, 1000, 1500, 2000, 2500, 3000]
    assert "0 to 3000 rpm at lead 10 mm" in str(read[0])


def test_a_speed_of_rotation_is_read_as_before_without_a_note() -> None:
    read: list = []
    (w,) = parse_speed_range("--speed", "1500 rpm", 0.010, notes=read)
    assert w == pytest.approx(1500 * math.pi / 30.0, rel=1e-15) and read == []


@pytest.mark.parametrize("text", ["15 kg", "15 m", "15 m/s**2"])
def test_a_quantity_neither_speed_is_still_refused_naming_the_field(text: str) -> None:
    with pytest.raises(BallScrewInputError) as info:
        parse_speed_range("--speed", text, 0.010)
    assert info.value.field == "--speed" and "or a feed" in info.value.allowed


def test_without_a_lead_a_feed_is_refused() -> None:
    with pytest.raises(BallScrewInputError, match="is a linear speed"):
        parse_speed_range("--speed", "15 m/min", None)


def test_a_case_speed_given_as_a_feed_is_read_at_its_lead() -> None:
    case = parse_case(_case('temperature = "25 degC"',
                            'temperature = "25 degC"\nspeed = "15 m/min"'))  # fmt: skip
    assert float(case.speed[0]) * 30.0 / math.pi == pytest.approx(1500.0, rel=1e-12)
    assert any(a.field == "operation.speed" and "1500 rpm at lead 10 mm" in a.reason
               for a in case.assumptions)  # fmt: skip


def test_torque_says_how_it_read_a_feed_and_keeps_it_in_the_provenance(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    case = str(ROOT / "examples" / "xy_table_32x10.toml")
    out_json, out_csv = tmp_path / "t.json", tmp_path / "t.csv"
    code, _, err = run(["torque", "--case", case, "--speed", "15 m/min", "--json", str(out_json),
                        "--csv", str(out_csv)], capsys)  # fmt: skip
    assert code == 0, err
    said = "--speed = '15 m/min' is read as 1500 rpm at lead 10 mm"
    assert f"note: {said}" in err
    doc = json.loads(out_json.read_text(encoding="utf-8"))
    assert doc["rows"][0]["speed [rpm]"] == pytest.approx(1500.0, rel=1e-12)
    meta = json.loads(Path(str(out_csv) + ".meta.json").read_text(encoding="utf-8"))
    for provenance in (doc["provenance"], meta["provenance"]):
        assert [r.startswith(said) for r in provenance["readings"]] == [True]
    code, _, err = run(["torque", "--case", case, "--speed", "15 kg"], capsys)
    assert code == 2 and "error: --speed = '15 kg' is not allowed" in err
