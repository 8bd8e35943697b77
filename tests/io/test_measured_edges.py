"""Measured files with a cell no ball screw can show, or a cell the CSV module cannot read.

Issue 52's reproducers: a torque cell of 1e308 and one of 10 MB were internal errors of
``fit`` (an overflow in the solver; the CSV module's field limit).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from ballscrew import reference_screw
from ballscrew.errors import BallScrewInputError
from ballscrew.io.measured import parse_measured
from ballscrew.io.motors import parse_motors
from cli_runner import run

HEAD = "speed [rpm],torque [N*m]\n100,0.3\n"


@pytest.mark.parametrize(
    ("row", "said"),
    [
        ("200,1e308\n", "line 3, column 'torque [N*m]' = '1e+308 N*m'"),
        ("200," + "1" * 200_000 + "\n", "line 3 = '(field larger than field limit"),
        # A speed past 1e5 rad/s is named as typed, in the column's unit (it was named in
        # rad/s: 1.047e+307 for a cell of 1e308 rpm).
        ("1e308,0.3\n", "column 'speed [rpm]' = '1e+308 rpm (data row 2)'"),
    ],
)
def test_a_cell_no_screw_can_show_is_refused_naming_its_line(row: str, said: str) -> None:
    with pytest.raises(BallScrewInputError) as info:
        parse_measured(HEAD + row + "300,0.31\n", reference_screw(), "run.csv")
    assert str(info.value).startswith("run.csv: " + said), str(info.value)


def test_the_largest_plausible_values_still_read() -> None:
    # 1e5 N*m is the bound itself; 100 N*mm is a unit, read as 0.1 N*m.
    curve = parse_measured("speed [rad/s],torque [N*mm]\n1e4,1e8\n1,100\n", reference_screw())
    assert curve.torque.tolist() == pytest.approx([1e5, 0.1])


def test_a_motor_table_with_a_huge_cell_is_an_input_error() -> None:
    text = "name, rated_torque [N*m]\n" + "M" * 200_000 + ", 2\n"
    with pytest.raises(BallScrewInputError, match="motor table: line 2"):
        parse_motors(text)


def test_fit_refuses_the_cell_with_exit_2(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    case = tmp_path / "s.toml"
    case.write_text('[screw]\npitch_diameter = "40 mm"\nlead = "10 mm"\n'
                    'ball_diameter = "6.35 mm"\npreload = "2 kN"\n'
                    '[lubricant]\nname = "PAO ISO VG 68"\n')  # fmt: skip
    data = tmp_path / "run.csv"
    data.write_text(HEAD + "200,1e308\n300,0.31\n")
    code, _, err = run(["fit", "--case", str(case), "--measured", str(data), "--free",
                        "preload"], capsys)  # fmt: skip
    assert code == 2 and "1e+308 N*m" in err and "internal error" not in err
