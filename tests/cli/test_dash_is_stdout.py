"""'-' is standard output for every single-file option; a report folder option refuses it."""

from __future__ import annotations

import csv
import io
import json
import os
from pathlib import Path

import pytest

from cli_runner import run

DATA = Path(__file__).resolve().parents[1] / "data"
X_AXIS = DATA / "x_axis_bnfn3210a5.toml"
MOVE = "stroke=300 mm, feed=5 m/min, acceleration=1 m/s^2"


@pytest.fixture(autouse=True)
def _in_tmp(tmp_path: Path) -> object:
    old = Path.cwd()
    os.chdir(tmp_path)
    yield
    os.chdir(old)


def test_case_template_out_dash(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    # Issue 34: `case --template --out -` wrote a file named '-'.
    code, out, _ = run(["case", "--template", "--out", "-"], capsys)
    assert code == 0 and out.startswith("# ballscrew case file")
    assert list(tmp_path.iterdir()) == []


def test_torque_csv_dash(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(["torque", "--speed", "100 rpm", "--model", "catalog", "--csv", "-"],
                         capsys)  # fmt: skip
    assert code == 0, err
    rows = list(csv.reader(io.StringIO(out)))
    assert rows[0][:2] == ["model", "speed [rpm]"] and len(rows) == 2  # the CSV alone
    assert "provenance nowhere" in err
    assert list(tmp_path.iterdir()) == []


def test_export_friction_out_dash(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(["export-friction", "--form", "table", "--out", "-"], capsys)
    assert code == 0, err
    assert out.splitlines()[0].startswith("speed [rad/s]")  # the table went to stderr
    assert list(tmp_path.iterdir()) == []


def test_check_json_dash(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(["check", "--case", str(X_AXIS), "--move", MOVE, "--model", "catalog",
                          "--run-time", "10 min", "--json", "-"], capsys)  # fmt: skip
    assert code == 0, err
    assert json.loads(out)["inputs"]["model"] == "catalog"


@pytest.mark.parametrize(
    "args",
    [
        ["check", "--case", str(X_AXIS), "--move", MOVE, "--out", "-"],
        ["energy", "--case", str(X_AXIS), "--move", MOVE, "--out", "-"],
        ["study", "--out", "-"],
        ["validate", "--out", "-"],
    ],
)
def test_a_report_folder_refuses_dash(
    args: list[str], tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, _, err = run(args, capsys)
    assert code == 2
    assert "'--out'" in err and "give a folder name" in err
    assert list(tmp_path.iterdir()) == []
