"""What a new user typed, and what the commands must say back (the newcomer's round).

Each test is one input as a machine-tool engineer typed it on first use; the refusal must
name the option or the line, the value as typed and what is allowed, and a value the case
already holds must be taken from it rather than asked for again.
"""

from __future__ import annotations

from pathlib import Path

import pytest

from cli_runner import run
from shared import ROOT

XY = str(ROOT / "examples" / "xy_table_32x10.toml")  # no [motor] torque_constant
VERTICAL = str(ROOT / "examples" / "vertical_32x5.toml")  # torque_constant 1.6 N*m/A

FRICT_COMP = ["export-friction", "--form", "frict-comp", "--speed", "5 m/min", "--axis", "X",
              "--axis-number", "1", "--drive-unit", "1 mA", "--out", "-"]  # fmt: skip


def test_a_current_unit_takes_the_cases_torque_constant(
    capsys: pytest.CaptureFixture[str],
) -> None:
    """The case's motor.torque_constant is the K_t of a drive unit in mA; it was refused
    as '--torque-constant = None' though the case gave it."""
    code, out, err = run([*FRICT_COMP, "--case", VERTICAL], capsys)
    assert code == 0, err
    assert "K_t = 1.6 N*m/A" in out  # the file's header says which K_t scales its units
    assert "motor.torque_constant, 1.6 N*m/A" in err
    typed = run([*FRICT_COMP, "--case", VERTICAL, "--torque-constant", "1.6 N*m/A"], capsys)
    assert typed[1] == out  # the same file as when typed


def test_no_torque_constant_anywhere_is_refused_by_name(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code, _, err = run([*FRICT_COMP, "--case", XY], capsys)
    assert code == 2
    assert "--torque-constant = '(not given)'" in err
    assert "None" not in err
    assert "[motor] torque_constant" in err


@pytest.mark.parametrize(
    ("flag", "value"),
    [("--bristle-stiffness", "-5 N*m/rad"), ("--bristle-damping", "0 N*m*s/rad"),
     ("--inertia", "-1e-3 kg*m**2")],
)  # fmt: skip
def test_lugre_options_name_the_flag_and_the_value_as_typed(
    flag: str, value: str, capsys: pytest.CaptureFixture[str]
) -> None:
    """They were refused as 'bristle_stiffness = -5.0 ... > 0 N*m/rad' (no flag, SI)."""
    code, _, err = run(["export-friction", "--case", XY, "--form", "lugre", flag, value],
                       capsys)  # fmt: skip
    assert code == 2
    assert f"{flag} = '{value}' is not allowed: more than 0" in err


def test_torque_constant_outside_the_controller_tables_is_refused(
    capsys: pytest.CaptureFixture[str],
) -> None:
    """A K_t given with --form stribeck was ignored without a word."""
    code, _, err = run(["export-friction", "--case", XY, "--form", "stribeck",
                        "--torque-constant", "1.2 N*m/A"], capsys)  # fmt: skip
    assert code == 2
    assert "--torque-constant is an option of the controller tables" in err


MACHINE = str(ROOT / "examples" / "machine_vmc.toml")


@pytest.mark.parametrize("content", ["", "\n\n", "  \r\n"])
def test_an_empty_program_is_refused(
    content: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """An empty file ran as a program of no block: a table of zeros and exit status 0."""
    pytest.importorskip("ruckig")
    empty = tmp_path / "part.nc"
    empty.write_bytes(content.encode())
    code, out, err = run(["program", str(empty), "--machine", MACHINE], capsys)
    assert code == 2 and not out
    assert f"PROGRAM = '{empty}' is not allowed" in err and "this file is empty" in err


@pytest.mark.parametrize(
    ("args", "says"),
    [(["torque", "--case"], "case = "), (["program", MACHINE, "--machine"], "--machine = ")],
)  # fmt: skip
def test_an_empty_case_or_machine_file_says_it_is_empty(
    args: list[str], says: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Both were refused as 'screw = (missing)' / 'machine = (missing)'."""
    if args[0] == "program":
        pytest.importorskip("ruckig")
    empty = tmp_path / "empty.toml"
    empty.write_text("\n", encoding="utf-8")
    code, _, err = run([*args, str(empty)], capsys)
    assert code == 2
    assert f"{says}'{empty}' is not allowed" in err and "this file is empty" in err
    assert "(missing)" not in err


def test_a_toml_list_where_one_text_goes_is_explained(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """A list of loads as a TOML array was refused as 'array of shape (2,) ... Input should
    be a valid string' (pydantic's words)."""
    case = tmp_path / "list.toml"
    text = (ROOT / "examples" / "xy_table_32x10.toml").read_text(encoding="utf-8")
    case.write_text(text.replace("[operation]", '[operation]\naxial_load = ["1 kN", "2 kN"]', 1),
                    encoding="utf-8")  # fmt: skip
    code, _, err = run(["torque", "--case", str(case)], capsys)
    assert code == 2
    assert """operation.axial_load = '["1 kN", "2 kN"]' is not allowed""" in err
    assert "not a TOML list" in err and '"0, 2 kN"' in err
    assert "array of shape" not in err and "valid string" not in err


@pytest.mark.parametrize(
    ("args", "flag"),
    [(["torque", "--speed", "1e9 rpm"], "--speed"),
     (["torque", "--speed", "0..2e6 rpm"], "--speed"),
     (["energy", "--move", "stroke=100 mm, feed=6 m/min, acceleration=1 m/s^2",
       "--steady-speeds", "1e9 rpm"], "--steady-speeds")],
)  # fmt: skip
def test_a_speed_past_any_screw_is_refused_as_typed(
    args: list[str], flag: str, capsys: pytest.CaptureFixture[str]
) -> None:
    """Refused as 'speed = 104719755.12 is not allowed: ... rad/s': not the flag, not the
    value typed. The bound is 1e5 rad/s = 954 930 rpm (30/pi x 1e5)."""
    code, _, err = run([*args, "--case", XY], capsys)
    assert code == 2
    assert f"{flag} = '{args[args.index(flag) + 1]}' is not allowed" in err
    assert "954,930 rpm" in err


def test_a_case_speed_past_any_screw_shows_the_text_of_the_file(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    case = tmp_path / "fast.toml"
    text = (ROOT / "examples" / "xy_table_32x10.toml").read_text(encoding="utf-8")
    case.write_text(text.replace("[operation]", '[operation]\nspeed = "1e9 rpm"', 1),
                    encoding="utf-8")  # fmt: skip
    code, _, err = run(["torque", "--case", str(case)], capsys)
    assert code == 2
    assert "operation.speed = '1e9 rpm' is not allowed" in err


def _hand_trace(path: Path) -> Path:
    """Twenty samples typed by hand (Windows line ends): 0.1 s at 1 m/s^2, then 0.1 m/s;
    the current steps with the acceleration. Too little motion to fix a mass."""
    rows = ["time [s],X position [mm],X current [A]"]
    for k in range(20):
        t = k * 0.01
        p = 0.5 * t * t if t <= 0.1 else 0.005 + 0.1 * (t - 0.1)
        i = 0.3 if k == 0 else (1.3 if t <= 0.1 else 0.55)
        rows.append(f"{t:.2f},{p * 1e3:.4f},{i:.3f}")
    path.write_bytes(("\r\n".join(rows) + "\r\n").encode())
    return path


def test_identify_writes_no_machine_file_with_a_negative_mass(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The fitted mass, negative, was written as 'moving_mass = "-806 kg"' to a calibrated
    file that 'ballscrew program --machine' then refused ('0 or more')."""
    trace = _hand_trace(tmp_path / "hand.csv")
    out = tmp_path / "calibrated.toml"
    code, printed, err = run(["identify", str(trace), "--machine", MACHINE,
                              "--calibrated", str(out)], capsys)  # fmt: skip
    assert code == 2 and not out.exists()
    assert "moving mass m" in printed  # the fit itself is still shown
    assert "--calibrated (axes.X moving mass fitted) = '-" in err
    assert "a mass above 0" in err and "--free kt" in err


@pytest.mark.parametrize("flag", ["--speed", "--temperature", "--axial-load"])
def test_an_empty_operating_point_option_is_refused(
    flag: str, capsys: pytest.CaptureFixture[str]
) -> None:
    """'--speed ""' (a shell variable left empty) ran the case's own speeds without a word."""
    code, out, err = run(["torque", "--case", XY, flag, ""], capsys)
    assert code == 2 and not out
    assert f"{flag} = '' is not allowed" in err


def test_program_summary_prints_large_values_plainly() -> None:
    """An hour's program supplies more than 10 kJ: '{:.4g}' printed it '1.235e+04' beside
    the grid rows' plain '12760'; a thermal error above 100 um printed '1.2e+02'."""
    pytest.importorskip("ruckig")
    import dataclasses

    from ballscrew.io.machine import load_machine
    from ballscrew.program import run_program
    from ballscrew.report.program import summary_rows

    r = run_program(load_machine(MACHINE), "G21 G90\nG1 X10 F3000\nM30\n")
    r.axes["X"] = dataclasses.replace(r.axes["X"], supplied_energy=12345.6,
                                      thermal_lead_error=123.4e-6)  # fmt: skip
    rows = {row[0]: row[1:] for row in summary_rows(r)}
    assert rows["energy supplied [J]"][0] == "12350"  # 4 significant digits, no exponent
    assert rows["thermal lead error over the travel [um]"][0] == "120"
    assert "reversals (load +/+, +/-, -/+, -/-)" in rows


@pytest.mark.parametrize("command", ["energy", "check"])
@pytest.mark.parametrize("typed", ["0 s", "-2 min"])
def test_a_run_time_is_refused_as_typed(
    command: str, typed: str, capsys: pytest.CaptureFixture[str]
) -> None:
    """'--run-time "0 s"' was refused as '--run-time = '0 h'': not what was typed."""
    code, _, err = run([command, "--case", XY, "--move",
                        "stroke=100 mm, feed=6 m/min, acceleration=1 m/s^2",
                        "--run-time", typed], capsys)  # fmt: skip
    assert code == 2
    assert f"--run-time = '{typed}' is not allowed: more than 0 and at most 100,000 h" in err


def _machine_with(tmp_path: Path, old: str, new: str) -> Path:
    text = (ROOT / "examples" / "machine_vmc.toml").read_text(encoding="utf-8")
    assert old in text
    path = tmp_path / "machine.toml"
    path.write_text(text.replace(old, new, 1), encoding="utf-8")
    (tmp_path / "vertical_32x5.toml").write_text(
        (ROOT / "examples" / "vertical_32x5.toml").read_text(encoding="utf-8"), encoding="utf-8"
    )
    return path


def test_a_reversed_travel_is_shown_as_written(tmp_path: Path) -> None:
    """Refused as 'axes.X.travel = array of shape (2,)'."""
    from ballscrew.errors import BallScrewInputError
    from ballscrew.io.machine import load_machine

    path = _machine_with(tmp_path, 'travel = ["0 mm", "800 mm"]', 'travel = ["800 mm", "0 mm"]')
    with pytest.raises(BallScrewInputError) as info:
        load_machine(path)
    assert str(info.value).startswith("""axes.X.travel = '["800 mm", "0 mm"]' is not allowed""")


def test_a_negative_tool_length_is_refused(tmp_path: Path) -> None:
    """T1 = "-95 mm" (a Fanuc H register's sign) was taken, moving Z 190 mm off."""
    from ballscrew.errors import BallScrewInputError
    from ballscrew.io.machine import load_machine

    path = _machine_with(tmp_path, 'T1 = { value = "95 mm"', 'T1 = { value = "-95 mm"')
    with pytest.raises(BallScrewInputError, match=r"tools\.T1 = '-95 mm' is not allowed: a "
                       "tool length of 0 or more"):  # fmt: skip
        load_machine(path)


@pytest.mark.parametrize(
    ("flag", "typed", "allowed"),
    [("--radius", "0 mm", "more than 0"), ("--radius", "-50 mm", "more than 0"),
     ("--feed", "0 m/min", "more than 0"), ("--sampling-time", "0 ms", "more than 0"),
     ("--phase-margin", "0 deg", "between 0 and 90 deg"),
     ("--phase-margin", "120 deg", "between 0 and 90 deg")],
)  # fmt: skip
def test_contour_options_refused_as_typed(
    flag: str, typed: str, allowed: str, capsys: pytest.CaptureFixture[str]
) -> None:
    """Refused as '--radius = -0.05 ... a positive radius [m]', 'phase_margin =
    119.99999999999999': SI numbers the user never typed."""
    pytest.importorskip("control")
    code, _, err = run(["contour", "--case", XY, "--case", XY, flag, typed], capsys)
    assert code == 2
    assert f"{flag} = '{typed}' is not allowed: {allowed}" in err


def test_a_case_file_saved_with_a_byte_order_mark_is_read(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Notepad's 'UTF-8 with BOM' and CR LF line ends: refused as 'valid TOML (Invalid
    statement (at line 1, column 1))'. It must give the same torque as the plain file."""
    plain = ROOT / "examples" / "xy_table_32x10.toml"
    saved = tmp_path / "notepad.toml"
    saved.write_bytes(b"\xef\xbb\xbf" + plain.read_bytes().replace(b"\n", b"\r\n"))
    args = ["torque", "--speed", "1000 rpm", "--json", "-", "--table", "none"]
    code, windows, err = run([*args, "--case", str(saved)], capsys)
    assert code == 0, err
    code, unix, err = run([*args, "--case", str(plain)], capsys)
    assert code == 0, err
    import json

    assert json.loads(windows)["rows"] == json.loads(unix)["rows"]


def test_identify_calibrates_a_machine_saved_with_a_byte_order_mark(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """The machine read, its text re-read by tomlkit for the calibrated file failed with
    'internal error: EmptyKeyError: Empty key at line 1 col 0'."""
    machine = tmp_path / "machine.toml"
    machine.write_bytes(b"\xef\xbb\xbf" + (ROOT / "examples" / "machine_vmc.toml").read_bytes())
    (tmp_path / "vertical_32x5.toml").write_bytes(
        b"\xef\xbb\xbf" + (ROOT / "examples" / "vertical_32x5.toml").read_bytes()
    )
    trace = tmp_path / "trace.csv"
    rows = ["time [s],X position [mm],X current [A],Z position [mm],Z current [A]"]
    for k in range(400):  # X and Z out and back at 0.1 m/s: enough to fit, quickly
        t = k * 0.004
        x = 50.0 * (1.0 - abs(1.0 - t / 0.8)) if t < 1.6 else 0.0
        rows.append(f"{t:.3f},{x:.4f},{0.4 if k % 200 < 100 else -0.4:.3f},{-x:.4f},0.6")
    trace.write_text("\n".join(rows) + "\n", encoding="utf-8")
    out = tmp_path / "calibrated.toml"
    code, _, err = run(["identify", str(trace), "--machine", str(machine), "--calibrated",
                        str(out), "--free", "kt"], capsys)  # fmt: skip
    assert "internal error" not in err
    assert code == 0, err
    from ballscrew.io.machine import load_machine

    assert load_machine(out).axes["X"].case.screw.lead == pytest.approx(0.010)


@pytest.mark.parametrize(
    "args",
    [["torque", "--case", XY, "--json", ""],
     ["energy", "--case", XY, "--move", "stroke=100 mm, feed=6 m/min, acceleration=1 m/s^2",
      "--temperature", " "],
     ["export-friction", "--case", XY, "--temperature", ""],
     ["check", "--case", "", "--move", "stroke=100 mm, feed=6 m/min, acceleration=1 m/s^2"],
     ["torque", "--case", XY, "--model", "complete", "--model", ""]],
)  # fmt: skip
def test_any_option_typed_empty_is_refused(
    args: list[str], capsys: pytest.CaptureFixture[str]
) -> None:
    """'--json ""' wrote nothing, '--temperature ""' took the case's: both without a word
    (a shell variable left empty)."""
    code, out, err = run(args, capsys)
    empty = next(i for i, a in enumerate(args) if not a.strip())
    assert code == 2 and not out
    assert f"{args[empty - 1]} = '{args[empty]}' is not allowed: a value" in err


def test_identify_says_a_negative_mass_is_not_a_mass(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    """Without --calibrated the table showed the fitted mass, negative, with no word."""
    trace = _hand_trace(tmp_path / "hand.csv")
    code, printed, err = run(["identify", str(trace), "--machine", MACHINE], capsys)
    assert code == 0, err
    assert "is not a mass: the trace does not show enough acceleration" in printed + err
