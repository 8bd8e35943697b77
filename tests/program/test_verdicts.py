"""`ballscrew program` names what fails on the terminal: verdict lines, warnings, exit status."""

from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

from ballscrew.cli.program import NOT_OK_STATUS
from cli_runner import run

DATA = Path(__file__).resolve().parents[1] / "data"
GENTLE = "G1 X300 F6000\nG1 X0\nM30\n"  # 600 rpm on the 10 mm lead, 300 mm out and back


def _program(tmp_path: Path, text: str, machine: Path, capsys: pytest.CaptureFixture[str],
             *extra: str) -> tuple[int, str, str]:  # fmt: skip
    nc = tmp_path / "part.nc"
    nc.write_text(text, encoding="utf-8")
    return run(["program", str(nc), "--machine", str(machine), *extra], capsys)


def _x_machine(tmp_path: Path, **ratings: str) -> Path:
    """tests/data/machine_x_limits.toml with the marked ratings replaced."""
    text = (DATA / "machine_x_limits.toml").read_text("utf-8")
    for mark, value in ratings.items():
        text, n = re.subn(rf'"[^"]*"(\s*# {mark})', rf'"{value}"\1', text)
        assert n == 1, mark
    path = tmp_path / "machine.toml"
    path.write_text(text, encoding="utf-8")
    return path


def _line(out: str, letter: str) -> str:
    return next(line for line in out.splitlines() if line.startswith(f"{letter}: "))


def test_an_axis_within_its_ratings_is_ok_and_exits_0(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, err = _program(tmp_path, GENTLE, _x_machine(tmp_path), capsys)
    assert code == 0, err
    line = _line(out, "X")
    assert line.startswith("X: OK: lift-off ")
    # 300 mm out and back at 6 m/min: the screw turns at 6 / 0.01 = 600 rpm, d*n = 40 x 600.
    assert "d*n 24000 of 130000 mm*rpm (18%)" in line
    assert "travel 300 of 800 mm (38%)" in line or "travel 300 of 800 mm (37%)" in line
    assert "warning:" not in err


def test_a_vertical_axis_lifting_its_nut_off_is_named_and_exits_not_ok(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # Z of examples/vertical_32x5.toml: 120 kg and a 900 N thrust against its motion, up at
    # 3 m/min: 1177 N + 900 N and the acceleration's share against lift-off at
    # 2^1.5 x 552 N = 1561 N.
    machine = DATA / "machine_vertical_lift_off.toml"
    code, out, err = _program(tmp_path, "G0 Z-300\nG1 Z-10 F3000\nG0 Z0\nM30\n", machine,
                              capsys, "--json", str(tmp_path / "r.json"))  # fmt: skip
    assert code == NOT_OK_STATUS == 3
    line = _line(out, "Z")
    assert line.startswith("Z: NOT OK: ")
    peak = float(re.search(r"lift-off (\d+) of 1561 N \(\d+% NOT OK\)", line)[1])  # type: ignore[index]
    assert 1177.0 + 900.0 < peak < 1177.0 + 900.0 + 120.0 * 2.0  # weight, thrust, <= 2 m/s^2
    assert re.search(r"^warning: Z: lift-off F_max / \(2\^1\.5 F_pr\) \d+ N, limit 1561 N: "
                     r"1\d\d% NOT OK; to change: a preload of at least", err, re.M)  # fmt: skip
    doc = json.loads((tmp_path / "r.json").read_text("utf-8"))
    assert doc["axes"]["Z"]["verdict"] == "NOT OK"
    rows = {c["name"]: c for c in doc["axes"]["Z"]["criteria"]}
    assert rows["lift-off F_max / (2^1.5 F_pr)"]["value"] == pytest.approx(peak, abs=0.5)
    # The verdicts of the nominal values: the check's draws are left out on a program.
    assert all(c["p_not_ok"] is None for c in rows.values())


def test_a_screw_past_its_dn_limit_is_named(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, err = _program(tmp_path, GENTLE, _x_machine(tmp_path, DN_LIMIT="20000 mm*rpm"),
                              capsys)  # fmt: skip
    assert code == 3
    assert "d*n 24000 of 20000 mm*rpm (120% NOT OK)" in _line(out, "X")
    warned = [line for line in err.splitlines() if line.startswith("warning:")]
    assert warned == [
        "warning: X: d*n 24000 mm*rpm, limit 20000 mm*rpm: 120% NOT OK; to change: a longer "
        "lead, or a nut with a higher d*n rating"
    ]


def test_a_motor_at_145_percent_rms_and_130_percent_peak_is_named(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, _, err = _program(tmp_path, GENTLE, _x_machine(tmp_path), capsys,
                            "--json", str(tmp_path / "ok.json"))  # fmt: skip
    assert code == 0, err
    x = json.loads((tmp_path / "ok.json").read_text("utf-8"))["axes"]["X"]
    rms, peak = x["rms_motor_torque_Nm"], x["peak_motor_torque_Nm"]
    weak = _x_machine(tmp_path, RATED_TORQUE=f"{rms / 1.45:.6g} N*m",
                      PEAK_TORQUE=f"{peak / 1.30:.6g} N*m")  # fmt: skip
    code, out, err = _program(tmp_path, GENTLE, weak, capsys)
    assert code == 3
    line = _line(out, "X")
    assert re.search(r"RMS torque [\d.]+ of [\d.]+ N\*m \(145% NOT OK\)", line)
    assert re.search(r"peak torque [\d.]+ of [\d.]+ N\*m \(130% NOT OK\)", line)
    warned = [w for w in err.splitlines() if w.startswith("warning: X: ")]
    assert len(warned) == 2 and "RMS torque / rated torque" in warned[1]


def test_an_axis_the_check_refuses_is_not_checked_and_says_why(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    text = (DATA / "machine_x_limits.toml").read_text("utf-8")
    machine = tmp_path / "machine.toml"
    machine.write_text(re.sub(r"(?m)^motor_inertia = .*\n", "", text), encoding="utf-8")
    code, out, err = _program(tmp_path, GENTLE, machine, capsys)
    assert code == 0, err  # nothing found NOT OK; the line and a note say what is missing
    assert _line(out, "X").startswith("X: NOT CHECKED: (axis.motor_inertia")
    assert "note: X: not checked (axis.motor_inertia" in err


def test_skipped_words_are_one_line_and_axis_notes_name_their_axis(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    text = ("%\nO1000\nT1\nS8000 M3\nG1 X100 F3000 M8 (M3 in a comment)\nS9000\nT2\n"
            "S7000 M3 ; M3 again\nG1 X0\nM5\nM30\n%\n")  # fmt: skip
    code, _, err = _program(tmp_path, text, _x_machine(tmp_path), capsys,
                            "--out", str(tmp_path / "rep"))  # fmt: skip
    assert code == 0, err
    notes = [line for line in err.splitlines() if line.startswith("note: ")]
    assert (
        "note: skipped, no motion of the feed axes: % x2 (first line 1), O (line 2), "
        "T x2 (first line 3), S x3 (first line 4), M3 x2 (first line 4), M8 (line 5), "
        "M5 (line 10)"
    ) in notes  # M3 in the comments not counted
    assert len([n for n in notes if "line 4" in n]) == 1  # no note per skipped word any more
    axis = [n for n in notes if "screw_inertia" in n]
    assert axis and all(n.startswith("note: X: ") for n in axis)
    report = (tmp_path / "rep" / "report.md").read_text("utf-8")
    assert "- X: axis.screw_inertia" in report and "- X: OK: lift-off" in report
