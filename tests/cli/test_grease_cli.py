"""Greases and wipers on the command line: the library listing, --wiper-drag, case --check."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from cli_runner import run
from shared import DATA

SMALL = DATA / "small_case.toml"


def test_lubricants_lists_the_greases_with_thickener_and_grade(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("COLUMNS", "400")  # one line per row's first line
    code, out, _ = run(["lubricants"], capsys)
    assert code == 0 and "kind" in out and "pour / flash" in out
    (row,) = [line for line in out.splitlines() if "SKF LGHP 2" in line]
    assert "grease (polyurea, NLGI 2-3, mineral)" in row and "- / 210" in row
    (row,) = [line for line in out.splitlines() if "Mobil Polyrex EM" in line]
    assert "grease (polyurea, NLGI 2)" in row
    (row,) = [line for line in out.splitlines() if "PAO ISO VG 68" in line]
    assert "│ oil " in row


def test_torque_with_a_wiper_drag_adds_it_to_the_complete_model(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    def torques(*extra: str) -> dict[str, list[float]]:
        out = tmp_path / "t.json"
        args = ["torque", "--case", str(SMALL), "--speed", "100, 1000 rpm", "--model",
                "complete", "--model", "catalog", "--json", str(out), *extra]  # fmt: skip
        code, _, err = run(args, capsys)
        assert code == 0, err
        rows = json.loads(out.read_text("utf-8"))["rows"]
        found: dict[str, list[float]] = {}
        for r in rows:
            found.setdefault(r["model"], []).append(r["torque [N*m]"])
        return found

    plain, wiped = torques(), torques("--wiper-drag", "0.05 N*m")
    added = [b - a for a, b in zip(plain["complete"], wiped["complete"], strict=True)]
    assert added == pytest.approx([0.05, 0.05], abs=1e-9)  # the JSON rounds to 12 digits
    assert wiped["catalog"] == plain["catalog"]


def test_torque_notes_the_models_that_leave_the_wiper_out(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code, _, err = run(["torque", "--case", str(SMALL), "--speed", "100 rpm", "--model",
                        "catalog", "--wiper-drag", "0.05 N*m"], capsys)  # fmt: skip
    assert code == 0
    assert "note: wiper drag [N*m] = 0.05: left out" in err


@pytest.mark.parametrize("value", ["-0.05 N*m", "0.05", "0.05 N"])
def test_a_bad_wiper_drag_option_is_refused_naming_it(
    value: str, capsys: pytest.CaptureFixture[str]
) -> None:
    code, _, err = run(["torque", "--case", str(SMALL), "--speed", "100 rpm",
                        "--wiper-drag", value], capsys)  # fmt: skip
    assert code != 0 and "--wiper-drag" in err


def test_case_check_shows_the_wiper_and_the_grease(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("COLUMNS", "300")
    case = tmp_path / "greased.toml"
    case.write_text(
        '[screw]\ndesignation = "HIWIN R40-10K5-FDC"\npreload_share = "5 %"\n'
        'wiper_drag = "0.05 N*m"\n[lubricant]\nname = "SKF LGHP 2"\n',
        "utf-8",
    )
    code, out, _ = run(["case", "--check", str(case)], capsys)
    assert code == 0 and "case file OK" in out
    assert "wiper drag" in out and "0.05 N*m" in out
    assert "polyurea, NLGI 2-3, mineral" in out
