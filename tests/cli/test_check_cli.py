"""``ballscrew check``: the verdict table, the JSON and the errors that name the field."""

from __future__ import annotations

import csv
import io
import json
import re
from pathlib import Path

import pytest

from cli_runner import run
from shared import ROOT

VERTICAL = ROOT / "examples" / "vertical_32x5.toml"
MOVE = ("stroke=500 mm, feed=12 m/min, acceleration=3 m/s^2, force=1.5 kN, force_from=100 mm, "
        "force_to=400 mm, dwell=0.5 s")  # fmt: skip
FAST = ["--model", "catalog", "--run-time", "10 min"]


def test_check_prints_the_table_and_the_json(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(["check", "--case", str(VERTICAL), "--move", MOVE, *FAST, "--json", "-"],
                         capsys)  # fmt: skip
    assert code == 0, err
    doc = json.loads(out)
    names = [c["name"] for c in doc["criteria"]]
    for wanted in ("fatigue life L10", "static safety C0a/F_max", "buckling load",
                   "speed / critical speed", "d*n", "inertia ratio J_load/J_motor",
                   "peak torque", "RMS torque / rated torque", "motor speed"):  # fmt: skip
        assert wanted in names
    assert doc["not_checked"] == []
    assert doc["verdict"] in ("OK", "CHECK", "NOT OK")
    for c in doc["criteria"]:
        assert c["source"], c["name"]
        if c["verdict"] in ("CHECK", "NOT OK"):
            assert c["advice"], c["name"]  # what to change
    assert "the stroke lies in the middle of the span" in doc["assumptions"]
    assert "axis check" in err and "fatigue life" in err  # the table on stderr with --json -


def test_check_of_the_bundled_case_names_what_is_missing(
    capsys: pytest.CaptureFixture[str],
) -> None:
    move = "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2"
    # Without --case the user's axis is missing: a usage error (exit 2) naming the option, not
    # a check of the bundled air-bearing stage that has no moving mass and passes.
    code, out, err = run(["check", "--move", move, *FAST], capsys)
    assert code == 2 and "check needs --case FILE" in err and "--case study" in err
    assert "axis check" not in out
    # Named, the bundled stage is checked, and the title says whose axis it is.
    code, out, err = run(["check", "--case", "study", "--move", move, *FAST], capsys)
    assert code == 0, err
    assert "the bundled study stage, not your axis" in out
    assert "NOT CHECKED" in out and "screw.dynamic_load_rating" in out
    assert "assumed: span between the supports taken as the screw length" in out
    # The stage has no moving mass: the 0 kg is said with the rows it changes.
    assert "assumed: axis.moving_mass = 0 kg (not given)" in out


def test_a_case_without_moving_mass_says_what_it_leaves_out(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    move = "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2"
    text = VERTICAL.read_text(encoding="utf-8")
    without = "\n".join(line for line in text.splitlines() if not line.startswith("moving_mass"))
    assert without != text  # the example has the key: the test removes it
    case = tmp_path / "no_mass.toml"
    case.write_text(without, encoding="utf-8")
    doc = tmp_path / "c.json"
    code, out, err = run(["check", "--case", str(case), "--move", move, "--json", str(doc),
                          *FAST], capsys)  # fmt: skip
    assert code == 0, err
    assert "assumed: axis.moving_mass = 0 kg (not given)" in out
    rows = {c["name"]: c for c in json.loads(doc.read_text())["criteria"]}
    assert rows["axial eigenfrequency"]["verdict"] == "NOT CHECKED"
    # With the example's own mass the note is gone.
    code, out, err = run(["check", "--case", str(VERTICAL), "--move", move, *FAST], capsys)
    assert code == 0, err
    assert "axis.moving_mass = 0 kg" not in out


def test_check_errors_name_the_field(capsys: pytest.CaptureFixture[str]) -> None:
    long_move = "stroke=1 m, feed=12 m/min, acceleration=3 m/s^2"
    code, _, err = run(["check", "--case", str(VERTICAL), "--move", long_move, *FAST], capsys)
    assert code == 2 and "axis.bearing_span" in err
    code, _, err = run(["check", "--case", str(VERTICAL), *FAST], capsys)
    assert code == 2 and "--move" in err


def test_case_check_shows_what_the_axis_check_will_use(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code, out, err = run(["case", "--check", str(VERTICAL)], capsys)
    assert code == 0, err
    assert "18.4 kN" in out and "59.6 kN" in out  # HIWIN R32-05K4-FSC, from the designation
    assert "3000 rpm" in out and "650 N/um" in out and "P5" in out


def test_check_takes_a_trajectory(tmp_path, capsys: pytest.CaptureFixture[str]) -> None:  # type: ignore[no-untyped-def]
    # A smooth out-and-back of 200 mm in 2 s (a cosine), written as a CSV with units.
    import math

    lines = ["time [s],position [mm],force [N]"]
    for i in range(401):
        t = i * 0.005
        lines.append(f"{t:.3f},{100 * (1 - math.cos(math.pi * t)):.6f},500")
    path = tmp_path / "cosine.csv"
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    code, out, err = run(["check", "--case", str(VERTICAL), "--profile", str(path), *FAST,
                          "--json", "-"], capsys)  # fmt: skip
    assert code == 0, err
    doc = json.loads(out)
    positions = doc["stiffness"]["position_mm"]
    assert positions[-1] - positions[0] == pytest.approx(200.0, rel=1e-3)  # the stroke
    speed = next(c for c in doc["criteria"] if c["name"] == "speed / critical speed")
    # Top speed 100 pi mm/s = 18.85 m/min on a 5 mm lead: 3770 rpm.
    assert speed["value"] == pytest.approx(100 * math.pi / 5 * 60, rel=1e-3)


def test_check_out_writes_a_report_whose_files_match_the_json(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "report"
    code, text, err = run(["check", "--case", str(VERTICAL), "--move", MOVE, *FAST,
                           "--json", "-", "--out", str(out)], capsys)  # fmt: skip
    assert code == 0, err
    doc = json.loads(text)
    md = (out / "report.md").read_text(encoding="utf-8")
    # Every figure and file the report links exists.
    for link in re.findall(r"\]\(([^)]+)\)", md):
        assert (out / link).is_file(), link
    for key in ("utilisation", "stiffness", "thermal"):
        assert (out / "figures" / f"{key}.png").read_bytes()[:4] == b"\x89PNG"
    text_of = lambda name: (out / "data" / name).read_text(encoding="utf-8")  # noqa: E731
    rows = list(csv.DictReader(io.StringIO(text_of("utilisation.csv"))))
    assert [r["verdict"] for r in rows] == [c["verdict"] for c in doc["criteria"]]
    stiffness = list(csv.DictReader(io.StringIO(text_of("stiffness.csv"))))
    assert [float(r["lost motion [um]"]) for r in stiffness] == pytest.approx(
        doc["stiffness"]["lost_motion_um"], rel=5e-4
    )  # the CSV's 4 significant digits: within half a unit of the 4th, 5e-4 of the value
    assert f"Verdict: {doc['verdict']}" in md and "report.html" in err
    code, _, err = run(["check", "--case", str(VERTICAL), "--move", MOVE, *FAST,
                        "--out", str(out / "report.md")], capsys)  # fmt: skip
    assert code == 2 and "--out" in err


@pytest.mark.parametrize("columns", [100, 240])
def test_a_narrow_terminal_gets_the_sources_below_the_table(
    columns: int, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    # Below 200 columns the source and advice columns wrapped every row into 20-30 lines
    # ('fatig...', '1.469...'): there they go below the table, one numbered line per row.
    monkeypatch.setenv("COLUMNS", str(columns))
    code, out, err = run(["check", "--case", str(VERTICAL), "--move", MOVE, *FAST], capsys)
    assert code == 0, err
    table = out.split("\n[1] ")[0]
    if columns < 200:
        assert "[1] fatigue life L10: ISO 3408-5" in out and "what to change" not in table
        assert max(len(line) for line in table.splitlines()) <= columns
        assert len(table.splitlines()) < 70  # was about 300 lines at 100 columns
    else:
        assert "what to change" in out and "\n[1] " not in out
