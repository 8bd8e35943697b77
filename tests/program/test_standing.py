"""A program that moves no feed axis runs, as a controller runs it: the axes stand.

A subroutine file run alone, a program of M, S and T words, or of dwells and tool changes
only: no motion energy, its time standing (a vertical axis holding its weight through its
motor), one note that it moves no axis, and every output (table, CSV, report, JSON, web).
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from ballscrew.io.machine import load_machine
from ballscrew.materials import STANDARD_GRAVITY
from ballscrew.program import run_program
from ballscrew.report.program import time_series_csv, write_program_report
from cli_runner import run

ROOT = Path(__file__).resolve().parents[2]
MACHINE = ROOT / "examples" / "machine_vmc.toml"
# Z of the example machine (examples/vertical_32x5.toml): 120 kg, vertical, lead 5 mm;
# k_T 1.6 N*m/A, 3.6 ohm between terminals (a star winding: 1.8 ohm a phase).
HOLDING = 120.0 * STANDARD_GRAVITY * 0.005 / (2.0 * math.pi)  # the weight on the screw [N*m]
COPPER = 3.0 * 1.8 * (HOLDING / 1.6) ** 2  # 3 R_ph I^2 at the holding current [W]


def test_a_program_without_blocks_takes_no_time_and_no_energy() -> None:
    machine = load_machine(MACHINE)
    r = run_program(machine, "M3 S1000\nM5\nM2\n")
    assert r.program.size == 0 and r.motion.duration == 0.0 and r.motion.time.size == 1
    for a in r.axes.values():
        energies = (a.friction_energy, a.bearing_energy, a.supplied_energy,
                    a.regenerated_energy, a.process_work, a.potential_energy)  # fmt: skip
        assert energies == (0.0,) * 6 and math.isnan(a.friction_share)
        assert a.drive is not None and a.drive.as_dict()["grid_energy_J"] in (0.0, None)
    # The motor holds the vertical axis: its torque is the weight's on the screw (no
    # friction at rest, no gear), X and Y carry nothing.
    assert r.axes["Z"].peak_torque == pytest.approx(HOLDING, rel=1e-12)
    assert r.axes["X"].peak_torque == 0.0
    assert any("moves no feed axis and takes no time" in n for n in r.notes)
    doc = r.as_dict()
    assert doc["blocks"] == 0 and doc["program_time_s"] == 0.0
    json.dumps(doc)  # a valid document (no NaN reaches it unconverted: checked by the CLI)
    rows = time_series_csv(r).decode().splitlines()
    assert len(rows) == 2 and rows[1].split(",")[:3] == ["0", "0", "0"]


def test_dwells_alone_hold_a_vertical_axis_for_their_time(tmp_path: Path) -> None:
    machine = load_machine(MACHINE)
    r = run_program(machine, "G4 P10\nM2\n")
    assert r.motion.duration == 10.0
    assert any("moves no feed axis" in n and "10 s" in n for n in r.notes)
    z = r.axes["Z"]
    assert z.supplied_energy == 0.0 and z.friction_energy == 0.0
    assert z.rms_torque == pytest.approx(HOLDING, rel=1e-9)
    # The copper loss of the holding current over the dwell, 18.5 J.
    assert z.drive is not None and z.drive.copper_loss == pytest.approx(COPPER * 10.0, rel=1e-9)
    # X stands without load: its drive only draws its standby power, 10 W for 10 s.
    x = r.axes["X"]
    assert x.drive is not None and x.drive.copper_loss == 0.0
    assert x.drive.drive_loss == pytest.approx(100.0, rel=1e-12)
    written = write_program_report(tmp_path, r)
    assert {p.name for p in written} >= {"path.png", "time_series.csv", "report.md"}


def test_the_command_runs_it_with_a_note(tmp_path: Path, capsys: pytest.CaptureFixture[str]
                                         ) -> None:  # fmt: skip
    program = tmp_path / "sub.ngc"
    program.write_text("(a file of M words only)\nM3 S2000\nM8\nM9\nM5\nM2\n", encoding="utf-8")
    csv = tmp_path / "series.csv"
    code, out, err = run(["program", str(program), "--machine", str(MACHINE), "--csv",
                          str(csv), "--out", str(tmp_path / "report"), "--json",
                          str(tmp_path / "r.json")], capsys)  # fmt: skip
    assert code == 0, err
    assert "note: the program moves no feed axis" in err
    assert "0 blocks, 0 s" in out and "nan" not in out and " -0 " not in out
    assert len(csv.read_text(encoding="utf-8").splitlines()) == 2
    assert (tmp_path / "report" / "report.html").is_file()
    assert json.loads((tmp_path / "r.json").read_text(encoding="utf-8"))["blocks"] == 0


def test_the_web_page_runs_it() -> None:
    pytest.importorskip("starlette")
    from starlette.testclient import TestClient

    from ballscrew.web import create_app

    with TestClient(create_app(allowed_hosts=["testserver"], processes=0)) as client:
        answer = client.post("/api/program", json={"program": "M3 S1000\nG4 P1\nM2\n"})
    assert answer.status_code == 200, answer.text
    doc = answer.json()
    assert doc["blocks"] == 1 and doc["program_time_s"] == 1.0
    assert any("moves no feed axis" in n for n in doc["notes"])
    assert np.isclose(doc["axes"]["Z"]["rms_motor_torque_Nm"], HOLDING, rtol=1e-9)
