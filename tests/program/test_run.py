"""A machine through a program: energies against independent integrals and `ballscrew energy`."""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from ballscrew.chain import friction_torque
from ballscrew.errors import BallScrewInputError
from ballscrew.io.machine import load_machine, parse_machine
from ballscrew.program import run_program
from cli_runner import run

ROOT = Path(__file__).resolve().parents[2]
EXAMPLES = ROOT / "examples"

AXIS_CASE = """
title = "X for the test"
[screw]
designation = "HIWIN R40-10K5-FDC"
preload_share = "6 %"
contact_angle = "45 deg"
[lubricant]
name = "PAO ISO VG 68"
[operation]
temperature = "40 degC"
[axis]
moving_mass = "300 kg"
bearing_span = "1100 mm"
screw_length = "1200 mm"
screw_inertia = "2.4e-3 kg*m**2"
motor_inertia = "1.8e-3 kg*m**2"
bearing_bore = "30 mm"
dn_limit = "130000 mm*rpm"
"""


def _one_axis_machine(tmp_path: Path, force: str = "0 N") -> Path:
    (tmp_path / "x.toml").write_text(AXIS_CASE, encoding="utf-8")
    machine = tmp_path / "m.toml"
    machine.write_text(
        f"""
[machine]
rapid_feed = "30 m/min"
ambient = "40 degC"
start_temperature = "40 degC"
sample_time = "1 ms"
[axes.X]
case = "x.toml"
max_feed = "30 m/min"
max_acceleration = "2 m/s^2"
max_jerk = "50 m/s^3"
travel = ["0 mm", "800 mm"]
process_force = "{force}"
""",
        encoding="utf-8",
    )
    return machine


def test_one_axis_program_equals_ballscrew_energy(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    machine = _one_axis_machine(tmp_path)
    result = run_program(load_machine(machine), "G1 X300 F30000\nG1 X0\nM30\n")
    code, _, err = run(
        ["energy", "--case", str(tmp_path / "x.toml"), "--json", str(tmp_path / "e.json"),
         "--move", "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2, jerk=50 m/s^3"],
        capsys,
    )  # fmt: skip
    assert code == 0, err
    energy = json.loads((tmp_path / "e.json").read_text("utf-8"))
    x = result.axes["X"]
    # The same S-curve out and back at 40 degC (the program warms the screw by < 0.05 K);
    # 1 % covers the sampling (1 ms there, phase ends and 1 ms here).
    assert x.friction_energy == pytest.approx(energy["friction_energy_J"], rel=0.01)
    assert x.bearing_energy == pytest.approx(energy["bearing_energy_J"], rel=0.01)
    assert x.peak_torque == pytest.approx(energy["peak_motor_torque_Nm"], rel=0.01)
    assert x.rms_torque == pytest.approx(energy["rms_motor_torque_Nm"], rel=0.01)
    assert result.motion.duration == pytest.approx(energy["duration_s"], rel=1e-6)
    # One reversal, at 300 mm, with the deceleration's load on the nut before and after it.
    assert len(x.reversals) == 1
    assert x.reversals[0].position == pytest.approx(0.3, abs=1e-9)


def test_friction_energy_is_the_integral_of_the_models_torque_times_speed(tmp_path: Path) -> None:
    machine = load_machine(EXAMPLES / "machine_vmc.toml")
    text = (
        "G0 X100 Y100 Z-10\nG1 Z-60 F600\nG1 X300 F3000\nG2 X350 Y150 R50\nG1 Y300\n"
        "G3 X300 Y350 I-50 J0\nG1 X100 Y100\nG0 Z-10\nM30\n"
    )
    r = run_program(machine, text)
    ds = r.data
    for letter, ax in machine.axes.items():
        case = ax.case
        v = ds["velocity"].sel(axis=letter).values
        omega = 2 * math.pi * v / case.screw.lead
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            t_f = friction_torque(
                case.screw, case.lubricant, speed=omega,
                temperature=ds["temperature"].sel(axis=letter).values,
                axial_load=ds["axial_force"].sel(axis=letter).values, model=machine.model,
            ).total  # fmt: skip
        t = ds["time"].values
        power = t_f * np.abs(omega)
        integral = float(np.sum(0.5 * (power[1:] + power[:-1]) * np.diff(t)))
        # The model at each sample's own temperature against the program's two runs
        # interpolated in temperature: within 1 %.
        assert r.axes[letter].friction_energy == pytest.approx(integral, rel=0.01)
        assert float(np.sum(r.axes[letter].energy_per_block)) == pytest.approx(
            r.axes[letter].friction_energy, rel=1e-9
        )
        assert float(np.sum(r.axes[letter].supplied_per_block)) == pytest.approx(
            r.axes[letter].supplied_energy, rel=1e-9
        )
    # The vertical axis carries its weight: the nut's load never changes sign at a reversal.
    z = r.axes["Z"]
    assert z.reversals and all(rev.load_direction == "+/+" for rev in z.reversals)


def test_the_energy_balance_closes(tmp_path: Path) -> None:
    # Motor work = friction + bearings + process work + potential energy (at rest at both ends).
    machine = load_machine(_one_axis_machine(tmp_path, force="1 kN"))
    r = run_program(machine, "G1 X200 F6000\nG1 X50 F3000\nG0 X400\nM30\n")
    x = r.axes["X"]
    net = x.supplied_energy - x.regenerated_energy
    balance = x.friction_energy + x.bearing_energy + x.process_work + x.potential_energy
    assert net == pytest.approx(balance, rel=2e-3)
    assert x.process_work == pytest.approx(1000.0 * 0.35, rel=2e-3)  # 200 + 150 mm fed


@pytest.mark.parametrize(
    ("text", "field"),
    [
        ("G1 X900 F1000\n", "program line 1"),  # past X's travel (0 to 800 mm)
        ("G1 X100 F1000\nG1 Y10\n", "program line 2"),  # no Y in the machine file
        ("G1 X10 F1000\nG2 X10 Y0 I-20 J0\n", "program line 2"),  # an arc in X and Y
    ],
)
def test_program_errors_name_the_line(tmp_path: Path, text: str, field: str) -> None:
    machine = load_machine(_one_axis_machine(tmp_path))
    with pytest.raises(BallScrewInputError) as info:
        run_program(machine, text)
    assert info.value.field == field


def test_an_arc_bulging_past_the_travel_is_refused() -> None:
    machine = load_machine(EXAMPLES / "machine_vmc.toml")
    # End points inside X's 0 to 800 mm; the circle about (-10, 100) reaches X = -30 mm.
    with pytest.raises(BallScrewInputError) as info:
        run_program(machine, "G1 X10 Y100 F1000\nG2 X10 Y100 I-20 J0\n")
    assert info.value.field == "program line 2" and "X" in str(info.value.value)


def test_machine_file_errors_name_the_key(tmp_path: Path) -> None:
    good = (EXAMPLES / "machine_vmc.toml").read_text("utf-8")
    with pytest.raises(BallScrewInputError) as info:
        parse_machine(good.replace('max_jerk = "60', 'max_jerks = "60'), folder=EXAMPLES)
    assert info.value.field == "axes.X.max_jerks"
    with pytest.raises(BallScrewInputError) as info:
        parse_machine(good.replace('"60 m/s^3"', '"60 m/s^2"'), folder=EXAMPLES)
    assert info.value.field == "axes.X.max_jerk"
    with pytest.raises(BallScrewInputError) as info:
        parse_machine(good.replace('["0 mm", "800 mm"]', '["10 mm", "800 mm"]'), folder=EXAMPLES)
    assert info.value.field == "axes.X.travel"  # the program starts at 0
    rotary = parse_machine(good + '\n[axes.C]\nnote = "a rotary table"\n', folder=EXAMPLES)
    assert any("axes.C" in n for n in rotary.notes)


def test_the_command_writes_json_and_csv(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    nc = tmp_path / "part.nc"
    nc.write_text("G0 X100 Y100 Z-10\nG1 X200 F2000 M8\nG1 Y200\nM30\n", encoding="utf-8")
    code, out, err = run(
        ["program", str(nc), "--machine", str(EXAMPLES / "machine_vmc.toml"),
         "--json", str(tmp_path / "r.json"), "--csv", str(tmp_path / "t.csv")],
        capsys,
    )  # fmt: skip
    assert code == 0, err
    assert "friction share" in out
    assert "note: skipped, no motion of the feed axes: M8 (line 2)" in err
    doc = json.loads((tmp_path / "r.json").read_text("utf-8"))
    assert set(doc["axes"]) == {"X", "Y", "Z"} and doc["blocks"] == 3
    header = (tmp_path / "t.csv").read_text("utf-8").splitlines()[0]
    assert "X motor torque [N*m]" in header


def test_the_command_without_the_extra_says_so(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    import sys

    monkeypatch.setitem(sys.modules, "ruckig", None)
    code, _, err = run(["program", "x.nc", "--machine", "m.toml"], capsys)
    assert code == 2
    assert err.strip().count("\n") == 0 and "ballscrew[program]" in err


@pytest.mark.slow
def test_the_example_program_and_its_report(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, _, err = run(
        ["program", str(EXAMPLES / "pocket_contour_drill.nc"), "--machine",
         str(EXAMPLES / "machine_vmc.toml"), "--out", str(tmp_path / "report")],
        capsys,
    )  # fmt: skip
    assert code == 0, err
    for name in ("report.html", "figures/path.png", "figures/energy.png", "data/reversals.csv"):
        assert (tmp_path / "report" / name).is_file()


@pytest.mark.parametrize(
    ("old", "new", "field"),
    [
        # X: 450 kg on a HIWIN R40-10K5-FDC; a process force, or 450 kg at 3000 m/s² (1350 kN),
        # past its static rating is refused; 300 m/s at lead 10 mm is 1.8 million rpm
        ('process_force = { value = "600 N"', 'process_force = { value = "600 kN"',
         "axes.X.process_force"),
        ('max_acceleration = "3 m/s^2"', 'max_acceleration = "3000 m/s^2"',
         "axes.X.max_acceleration"),
        ('max_feed = "30 m/min"', 'max_feed = "300 m/s"', "axes.X.max_feed"),
    ],
)  # fmt: skip
def test_a_machine_axis_past_its_screw_is_refused_naming_the_key(
    old: str, new: str, field: str
) -> None:
    good = (EXAMPLES / "machine_vmc.toml").read_text("utf-8")
    assert old in good
    with pytest.raises(BallScrewInputError) as info:
        parse_machine(good.replace(old, new, 1), folder=EXAMPLES)
    assert info.value.field == field
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # the example itself passes without a warning
        parse_machine(good, folder=EXAMPLES)
