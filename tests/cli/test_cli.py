"""End-to-end tests of the command-line interface."""

from __future__ import annotations

import csv
import json
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from ballscrew import __version__, friction_torque
from ballscrew.errors import BallScrewValidityWarning
from ballscrew.io.case import load_case
from cli_runner import run
from shared import DATA

SMALL = DATA / "small_case.toml"


def test_version_and_help(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(["--version"], capsys)
    assert code == 0 and __version__ in out
    for command in ("study", "torque", "models", "lubricants", "demo", "case", "screws", "energy",
                    "check", "serve"):  # fmt: skip
        code, out, _ = run([command, "--help"], capsys)
        assert code == 0 and "Example" in out, command


def test_models_and_lubricants(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(["models"], capsys)
    assert code == 0
    for name in ("catalog", "olaru", "viscoelastic", "harris-simplified", "harris-full"):
        assert name in out
    code, out, _ = run(["lubricants"], capsys)
    assert code == 0 and "PAO ISO VG 68" in out and "SAE 20" in out


def test_demo(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(["demo"], capsys)
    assert code == 0 and "Hertz contact" in out and "h_min [µm]" in out


def test_torque_outputs_agree_with_the_library(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    csv_file, json_file = tmp_path / "t.csv", tmp_path / "t.json"
    code, out, _ = run(
        [
            "torque",
            "--case",
            str(SMALL),
            "--model",
            "olaru",
            "--model",
            "catalog",
            "--speed",
            "100, 1000 rpm",
            "--temperature",
            "20, 40 degC",
            "--axial-load",
            "0, 1 kN",
            "--csv",
            str(csv_file),
            "--json",
            str(json_file),
        ],
        capsys,
    )
    assert code == 0, out
    rows = list(csv.DictReader(csv_file.read_text().splitlines()))
    assert len(rows) == 2 * 2 * 2 * 2
    assert set(rows[0]) >= {"speed [rpm]", "torque [N*m]", "power loss [W]", "efficiency [-]"}
    payload = json.loads(json_file.read_text())
    meta = payload["provenance"]
    assert meta["ballscrew"] == __version__ and len(payload["rows"]) == 16
    case = load_case(SMALL)
    # The provenance carries the resolved inputs and each model's parameters.
    assert meta["screw"]["pitch_diameter"] == case.screw.pitch_diameter
    assert meta["case"]["text"] == case.text
    assert set(meta["models"]) == {"olaru", "catalog"}
    assert meta["models"]["catalog"]["parameters"]["preload_coefficient"] == 0.05
    assert json.loads((tmp_path / "t.csv.meta.json").read_text())["provenance"] == meta
    for row in rows:
        r = friction_torque(
            case.screw,
            case.lubricant,
            speed=float(row["speed [rpm]"]) * 2 * math.pi / 60,
            temperature=float(row["temperature [degC]"]),
            axial_load=float(row["axial load [N]"]),
            model=row["model"],
        )
        # Results are written to 4 significant digits (docs/guide.md, "Numbers in outputs"):
        # rounding moves a value by at most half a unit of the 4th digit, 5e-4 of it.
        assert float(row["torque [N*m]"]) == pytest.approx(float(r.total), rel=5e-4)


@pytest.mark.slow
def test_study_writes_a_complete_reproducible_report(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out_dir = tmp_path / "report"
    code, out, _ = run(["study", "--case", str(SMALL), "--out", str(out_dir)], capsys)
    assert code == 0
    assert "report.html" in out
    keys = [
        "fig3_olaru",
        "fig4_viscoelastic",
        "fig5_viscoelastic_preload",
        "fig6_simplified",
        "fig7_simplified_preload",
        "fig8_lubricants",
        "fig9_all_models",
        "fig10_simplified_vs_complete",
        "fig11_complete_budget",
        "fig12_controller",
        "fig13_sensitivity",
    ]
    for key in keys:
        for sub, ext in (("figures", "png"), ("figures", "svg"), ("data", "csv")):
            assert (out_dir / sub / f"{key}.{ext}").stat().st_size > 0
    # CSV: units in the header, values equal to the library's.
    rows = list(csv.reader((out_dir / "data" / "fig3_olaru.csv").read_text().splitlines()))
    assert rows[0][0] == "speed [rpm]" and rows[0][2].endswith("torque [N*m]")
    case = load_case(SMALL)
    speeds = np.array([float(r[1]) for r in rows[1:]])
    expected = friction_torque(
        case.screw, case.lubricant, speed=speeds, temperature=case.study_temperature, model="olaru"
    ).total
    # the CSV carries 4 significant digits (io.numbers): within half a unit of the 4th digit
    np.testing.assert_allclose([float(r[2]) for r in rows[1:]], expected, rtol=5e-4)
    assert all(len(r[2].replace(".", "").replace("-", "").lstrip("0")) <= 4 for r in rows[1:])
    md = (out_dir / "report.md").read_text()
    html = (out_dir / "report.html").read_text()
    for text in ("Findings", "Assumptions", "Table 1", "assumed:"):
        assert text in md
    assert html.count("data:image/png;base64,") == len(keys)
    # Regenerated from its run record, the report is byte-identical.
    again = tmp_path / "again"
    code, _, _ = run(["study", "--record", str(out_dir / "run.json"), "--out", str(again)], capsys)
    assert code == 0
    first = sorted(p.relative_to(out_dir) for p in out_dir.rglob("*") if p.is_file())
    second = sorted(p.relative_to(again) for p in again.rglob("*") if p.is_file())
    assert first == second
    for rel in first:
        assert (out_dir / rel).read_bytes() == (again / rel).read_bytes(), rel


@pytest.mark.slow
def test_study_with_a_measured_curve(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # A synthetic curve written for this test only (not a measurement).
    measured = tmp_path / "curve.csv"
    measured.write_text("table speed [mm/s],torque [N*m]\n50,0.3\n200,0.35\n600,0.4\n")
    out_dir = tmp_path / "r"
    code, _, err = run(
        ["study", "--case", str(SMALL), "--measured", str(measured), "--out", str(out_dir)], capsys
    )
    assert code == 0, err
    md = (out_dir / "report.md").read_text()
    assert "Against the measured curve" in md and "RMSE" in md
    record = json.loads((out_dir / "run.json").read_text())
    assert record["measured_csv"].startswith("table speed")


@pytest.mark.parametrize(
    ("args", "fragment"),
    [
        (["torque", "--case", "/no/such/case.toml"], "case"),
        (["torque", "--case", str(SMALL), "--speed", "fast"], "--speed"),
        (["torque", "--case", str(SMALL), "--speed", "10..20 kg"], "--speed"),
        (["torque", "--case", str(SMALL), "--model", "coulomb"], "model"),
        (["torque", "--frobnicate"], "frobnicate"),
        (["study", "--record", "/no/run.json"], "record"),
        (["demo", "--lubricant", "castor oil"], "castor oil"),
    ],
)
def test_bad_input_exits_2_with_one_line(
    args: list[str], fragment: str, capsys: pytest.CaptureFixture[str]
) -> None:
    code, _, err = run(args, capsys)
    assert code == 2
    lines = [line for line in err.splitlines() if line.strip()]
    assert len(lines) == 1, err
    assert fragment in lines[0] and "Traceback" not in err


def test_bad_case_file_names_the_field(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    text = SMALL.read_text().replace('"3.969 mm"', '"3.969 kg"')
    bad = tmp_path / "bad.toml"
    bad.write_text(text)
    code, _, err = run(["torque", "--case", str(bad)], capsys)
    assert code == 2 and "screw.ball_diameter" in err and "kg" in err


def test_torque_rerun_gives_byte_identical_csv_and_json(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    outputs = []
    for run_no in range(2):
        csv_file, json_file = tmp_path / f"t{run_no}.csv", tmp_path / f"t{run_no}.json"
        code, _, _ = run(
            [
                "torque",
                "--case",
                str(SMALL),
                "--model",
                "harris-full",
                "--speed",
                "0..3000:4 rpm",
                "--csv",
                str(csv_file),
                "--json",
                str(json_file),
            ],
            capsys,
        )
        assert code == 0
        outputs.append((csv_file.read_bytes(), json_file.read_bytes()))
    assert outputs[0] == outputs[1]


def test_torque_json_carries_the_library_s_floats_unrounded(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # A newcomer's trial of 0.3.0: the JSON rows were rounded to 7 digits, where the guide
    # ("Numbers in outputs") promises full precision in JSON. The library's own call at the
    # same point is the independent number: the JSON must read back to the very same floats.
    out = tmp_path / "t.json"
    args = ["torque", "--case", str(SMALL), "--model", "complete", "--speed", "100, 1000 rpm",
            "--temperature", "40 degC", "--axial-load", "1 kN", "--json", str(out)]  # fmt: skip
    code, _, err = run(args, capsys)
    assert code == 0, err
    rows = json.loads(out.read_text(encoding="utf-8"))["rows"]
    case = load_case(SMALL)
    with warnings.catch_warnings():  # the film formulas' routine note: not the subject here
        warnings.simplefilter("ignore", BallScrewValidityWarning)
        r = friction_torque(case.screw, case.lubricant, speed=np.array([100.0, 1000.0]) * math.pi
                            / 30, temperature=40.0, axial_load=1000.0, model="complete",
                            **case.parameters_for("complete"))  # fmt: skip
    assert [row["speed [rpm]"] for row in rows] == [100.0, 1000.0]  # the inputs as typed
    assert [row["torque [N*m]"] for row in rows] == r.total.tolist()
    assert [row["efficiency [-]"] for row in rows] == r.efficiency.tolist()
    assert any(len(repr(row["torque [N*m]"])) > 10 for row in rows)  # more than 7 digits kept


def test_torque_csv_for_a_decimal_comma_spreadsheet_and_a_pivot(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    csv_file = tmp_path / "wide.csv"
    args = ["torque", "--case", str(SMALL), "--model", "complete", "--model", "catalog"]
    args += ["--speed", "0..3000:31 rpm", "--axial-load", "0, 2 kN", "--csv", str(csv_file)]
    args += ["--csv-layout", "wide", "--csv-dialect", "semicolon-decimal-comma"]
    code, out, err = run(args, capsys)
    assert code == 0, err
    # 124 rows: the terminal shows torque as speeds x models, and says so.
    assert "--table full" in out and "complete" in out
    lines = csv_file.read_text(encoding="utf-8").splitlines()
    header = lines[0].split(";")
    assert header == ["speed [rpm]", "temperature [degC]", "axial load [N]",
                      "torque complete [N*m]", "torque catalog [N*m]"]  # fmt: skip
    assert len(lines) == 1 + 31 * 2
    first = lines[3].split(";")  # 100 rpm, 20 degC, 0 N: rounded at output, decimal comma
    assert first[:3] == ["100", "20", "0"] and "," in first[3] and "." not in first[3]
    case = load_case(SMALL)
    api = friction_torque(case.screw, case.lubricant, speed=100 * math.pi / 30, temperature=20.0)
    # 4 significant digits: at most half a unit of the 4th digit off, 5e-4 of the value.
    assert float(first[3].replace(",", ".")) == pytest.approx(float(api.total), rel=5e-4)


def test_a_large_torque_grid_prints_a_summary_and_a_huge_one_is_refused(
    capsys: pytest.CaptureFixture[str],
) -> None:
    # Issue 27: 40 000 points spent 95 % of 41 s drawing the terminal table.
    code, out, err = run(["torque", "--model", "catalog", "--speed", "1..3000:2000 rpm",
                          "--temperature", "20, 40 degC"], capsys)  # fmt: skip
    assert code == 0 and "4,000 rows: shown as a summary" in out
    assert out.count("\n") < 12  # one row per model, not 4000
    code, out, _ = run(["torque", "--model", "catalog", "--speed", "1..3000:50 rpm",
                        "--table", "none"], capsys)  # fmt: skip
    assert code == 0 and out == ""
    # 1e6 speeds x 1000 temperatures: refused before anything is computed.
    code, _, err = run(["torque", "--speed", "1..3000:1000000 rpm",
                        "--temperature", "20..40:1000 degC"], capsys)  # fmt: skip
    assert code == 2 and "operating points = '1,000,000,000'" in err and "--max-points" in err


@pytest.mark.parametrize("speed", ["10**10**8 rpm", "100 " + "r" * 20_000])
def test_an_expression_or_a_huge_unit_name_is_refused_at_once(
    speed: str, capsys: pytest.CaptureFixture[str]
) -> None:
    # Issue 28: the unit library evaluated '**' (this text froze the command and the
    # server) and parsed unit names in quadratic time (a 60 kB name: 75 s).
    import time

    start = time.process_time()
    code, _, err = run(["torque", "--model", "catalog", "--speed", speed], capsys)
    assert code == 2 and "--speed = " in err
    assert time.process_time() - start < 1.0  # CPU seconds: the grammar refuses first
