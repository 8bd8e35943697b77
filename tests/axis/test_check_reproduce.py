"""A check's JSON carries its inputs: the verdict table is rebuilt from the JSON alone."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import pytest

from ballscrew.axis.check import run_check
from ballscrew.axis.duty import profile_from_move, run_energy
from ballscrew.io.case import parse_case
from cli_runner import run

Z_AXIS = Path(__file__).resolve().parents[1] / "data" / "z_axis_bnfn2505_5.toml"
MOVE = "stroke=300 mm, feed=5 m/min, acceleration=2.5 m/s^2, force=1 kN"


def test_the_verdict_table_is_rebuilt_from_the_json_alone(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    out = tmp_path / "check.json"
    report = tmp_path / "report"
    code, _, err = run(["check", "--case", str(Z_AXIS), "--move", MOVE, "--model", "catalog",
                        "--run-time", "10 min", "--json", str(out), "--out", str(report)],
                       capsys)  # fmt: skip
    assert code == 0, err
    doc = json.loads(out.read_text(encoding="utf-8"))
    inputs = doc["inputs"]
    # The file as read, with its hash; the command that made it.
    text = inputs["case"]["text"]
    assert inputs["case"]["sha256"] == hashlib.sha256(Z_AXIS.read_bytes()).hexdigest()
    assert inputs["command"][:4] == ["ballscrew", "check", "--case", str(Z_AXIS)]
    assert doc["ballscrew"]  # the version, written first
    sources = {v["key"]: v["source"] for v in inputs["case"]["values"]}
    assert sources["screw.static_load_rating"] != "given"  # assumed in the file
    assert sources["check.load_factor"] == "given" and sources["screw.conformity_nut"] == "default"
    # Nothing but the JSON from here on.
    case = parse_case(text)
    move = inputs["move"]
    again = run_energy(case, profile_from_move(move, inputs["cycles"]), [inputs["model"]],
                       cycles=inputs["cycles"], temperature=inputs["temperature_C"],
                       run_time=inputs["run_time_s"], move=move)  # fmt: skip
    rebuilt = run_check(again, inputs["model"]).as_dict()
    keys = ("name", "value", "limit", "unit", "utilisation", "verdict", "p_not_ok",
            "utilisation_95", "guarded_verdict")  # fmt: skip
    table = [[c[k] for k in keys] for c in doc["criteria"]]
    assert table == [[c[k] for k in keys] for c in json.loads(json.dumps(rebuilt["criteria"]))]
    assert doc["verdict"] == rebuilt["verdict"] == "NOT OK"
    # The report carries the same inputs.
    md = (report / "report.md").read_text(encoding="utf-8")
    assert "## Inputs" in md and inputs["case"]["sha256"] in md and "check.load_factor" in md
    assert json.loads((report / "data" / "check.json").read_text("utf-8"))["inputs"]["move"] == move


def test_the_energy_report_carries_its_move(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # Issue 34: the energy report had no move.
    report = tmp_path / "energy"
    code, _, err = run(["energy", "--case", str(Z_AXIS), "--move", MOVE, "--model", "catalog",
                        "--run-time", "10 min", "--out", str(report)], capsys)  # fmt: skip
    assert code == 0, err
    md = (report / "report.md").read_text(encoding="utf-8")
    assert "## Inputs" in md and "stroke=0.3" in md and "force=1000" in md
    assert hashlib.sha256(Z_AXIS.read_bytes()).hexdigest() in md
