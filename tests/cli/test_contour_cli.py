"""``ballscrew contour``: the tables, the JSON, the report, and the errors that name the field."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from cli_runner import run
from shared import ROOT

EXAMPLE = ROOT / "examples" / "xy_table_32x10.toml"
VERTICAL = ROOT / "examples" / "vertical_32x5.toml"
SHORT = ["--radius", "10 mm", "--feed", "1 m/min", "--direction", "CCW"]


def test_contour_prints_json_and_writes_the_report(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    code, out, err = run(["contour", "--case", str(EXAMPLE), "--case", str(VERTICAL), *SHORT,
                          "--json", "-", "--out", str(tmp_path / "r")], capsys)  # fmt: skip
    assert code == 0, err
    doc = json.loads(out)
    assert doc["radius_mm"] == pytest.approx(10.0)
    assert doc["feed_m_per_min"] == pytest.approx(1.0)
    assert [c["compensated"] for c in doc["circles"]] == [False, True]
    assert {g["quadrant_deg"] for g in doc["circles"][0]["glitches"]} == {0, 90, 180, 270}
    assert doc["axes"]["y"]["dynamics"]["external_force_N"] < 0  # the vertical axis' weight
    for name in ("x", "y"):
        loops = doc["axes"][name]["loops"]
        assert loops["velocity_phase_margin_deg"] > 0
    assert "Circular test" in err and "glitch reduction" in err
    for name in ("report.md", "report.html", "contour.json", "figures/polar.png",
                 "data/polar.csv", "data/reversal.csv"):  # fmt: skip
        assert (tmp_path / "r" / name).is_file(), name


def test_contour_refuses_a_case_without_moving_mass(capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run(["contour", *SHORT], capsys)
    assert code == 2
    assert "axis.moving_mass" in err


def test_contour_refuses_three_cases_and_a_bad_radius(capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run(["contour", "--case", str(EXAMPLE), "--case", str(EXAMPLE),
                        "--case", str(EXAMPLE), *SHORT], capsys)  # fmt: skip
    assert code == 2 and "--case" in err
    code, _, err = run(["contour", "--case", str(EXAMPLE), "--radius", "-5 mm"], capsys)
    assert code == 2 and "--radius" in err


def test_export_friction_writes_the_controller_tables(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    hal = tmp_path / "friction.hal"
    args = ["--form", "lincurve", "--speed", "5 m/min", "--out", str(hal), "--json", "-"]
    code, out, err = run(["export-friction", "--case", str(EXAMPLE), *args], capsys)
    assert code == 0, err
    assert "setp friction.x-val-15" in hal.read_text("utf-8")
    doc = json.loads(out)
    assert len(doc["speed_m_s"]) == 16 and doc["rms_error_N"] > 0
    assert "interpolation error" in err
    code, _, err = run(["export-friction", "--case", str(EXAMPLE), "--form", "frict-comp",
                        "--speed", "5 m/min"], capsys)  # fmt: skip
    assert code == 2 and "--axis-number" in err
    fmu = tmp_path / "friction.fmu"
    code, _, err = run(["export-friction", "--case", str(EXAMPLE), "--form", "load-map",
                        "--speed", "1..3000:6 rpm", "--out", str(fmu)], capsys)  # fmt: skip
    assert code == 0, err
    import zipfile

    with zipfile.ZipFile(fmu) as z:
        assert {"modelDescription.xml", "sources/ballscrew_friction_map.h",
                "sources/ballscrew_friction_fmu.c"} <= set(z.namelist())  # fmt: skip


def test_an_axis_note_both_axes_share_is_said_once(capsys: pytest.CaptureFixture[str]) -> None:
    # Two like axes printed 22 note lines, each twice with its axis (a newcomer's trial).
    code, _, err = run(["contour", "--case", str(EXAMPLE), "--case", str(EXAMPLE), *SHORT],
                       capsys)  # fmt: skip
    assert code == 0, err
    notes = [line for line in err.splitlines() if line.startswith("note: ")]
    assert len(notes) == len(set(notes)) and notes
    assert any(line.startswith("note: x, y: ") for line in notes)
    assert not any(line.startswith(("note: x: ", "note: y: ")) for line in notes)
