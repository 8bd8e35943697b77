"""What a new user typed, and what the commands must say back (the newcomer's round).

Each test is one input as a machine-tool engineer typed it on first use; the refusal must
name the option or the line, the value as typed and what is allowed, and a value the case
already holds must be taken from it rather than asked for again.
"""

from __future__ import annotations

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
