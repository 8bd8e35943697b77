"""The significant digits of printed and CSV numbers (ballscrew.io.numbers, issue 40).

The checks are against the definition of rounding to d significant digits, worked out
independently of the code: |x - shown| is at most half a unit of the d-th digit,
0.5 * 10**(floor(log10|x|) - d + 1), and the text shows no more than d digits.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from ballscrew.io.numbers import column_digits, sig, significant_digits, text
from cli_runner import run


@pytest.mark.parametrize(
    ("value", "digits", "shown"),
    [
        (-3000.0000000000005, 4, "-3000"),  # the speed issue 40 quotes
        (0.30259790342381945, 4, "0.3026"),  # a 17-digit torque
        (99.99999999999999, 6, "100"),
        (12345.6, 4, "12350"),
        (5.556476e-07, 4, "5.556e-07"),  # below 1e-4: scientific
        (-0.0, 4, "0"),
        (float("nan"), 4, "nan"),
        (float("-inf"), 4, "-inf"),
    ],
)
def test_known_values(value: float, digits: int, shown: str) -> None:
    assert text(value, digits) == shown


def test_integers_and_words_are_shown_as_they_are() -> None:
    assert (text(7), text("complete"), text(None), text(True)) == ("7", "complete", "None", "True")
    assert text(np.float32(0.123456)) == "0.1235" and text(np.int64(12)) == "12"


@pytest.mark.parametrize("digits", [1, 4, 6, 7])
def test_rounding_keeps_within_half_a_unit_of_the_last_digit(digits: int) -> None:
    rng = np.random.default_rng(40)
    values = rng.uniform(-1, 1, 2000) * 10.0 ** rng.integers(-9, 12, 2000)
    for x in values:
        shown = text(float(x), digits)
        half_unit = 0.5 * 10.0 ** (math.floor(math.log10(abs(x))) - digits + 1)
        # A relative 1e-15 for the binary representation of the decimal text.
        assert abs(float(shown) - x) <= half_unit * (1 + 1e-12) + abs(x) * 1e-15, (x, shown)
        assert significant_digits(shown) <= digits, (x, shown)
        assert sig(float(x), digits) == float(shown)


@pytest.mark.parametrize(
    ("shown", "count"),
    [("3000", 1), ("3000.0", 5), ("0.0300", 3), ("-1.5e+06", 2), ("0", 0), ("101", 3)],
)
def test_significant_digits_as_written(shown: str, count: int) -> None:
    # Leading zeros never count; an integer's trailing zeros do not either.
    assert significant_digits(shown) == count


@pytest.mark.parametrize(
    ("header", "digits"),
    [("time [s]", 7), ("position [mm]", 7), ("speed [rpm]", 6), ("table speed [m/s]", 6),
     ("angle [deg]", 7), ("shaft angle [rad]", 7),
     ("torque [N*m]", 4), ("temperature [degC]", 4), ("efficiency [-]", 4), ("model", 4),
     ("error from friction with compensation [um]", 4)],
)  # fmt: skip
def test_a_column_s_digits_come_from_its_unit(header: str, digits: int) -> None:
    assert column_digits(header) == digits


def test_a_report_echoes_its_inputs_to_six_digits(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    # docs/guide.md, "Numbers in outputs": a report gives the case's inputs it echoes (in
    # SI) to 6 significant digits. The vertical example's incline of 90 deg is pi/2 rad =
    # 1.5707963...: to 6 digits 1.57080, written without its trailing zero "1.5708" (to 4
    # digits it would be "1.571", to 7 "1.570796").
    case = Path(__file__).resolve().parents[2] / "examples" / "vertical_32x5.toml"
    move = "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2, force=2 kN"
    code, _, err = run(["check", "--case", str(case), "--move", move, "--out",
                        str(tmp_path / "report")], capsys)  # fmt: skip
    assert code == 0, err
    report = (tmp_path / "report" / "report.md").read_text("utf-8")
    assert "| axis.incline | 1.5708 | rad | given |" in report
