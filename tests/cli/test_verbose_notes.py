"""The validity notes every ordinary screw gets are short unless asked for (issue 40).

0.2.0 printed two 300-character notes on the Hamrock-Dowson film formulas for the
bundled case, at every run. Now the formulas a model extrapolates are said once, with
the values, in one line; ``ballscrew --verbose`` gives each range and why.
"""

from __future__ import annotations

import pytest

from cli_runner import run


def test_the_bundled_case_gets_one_short_note_and_the_long_form_on_request(
    capsys: pytest.CaptureFixture[str],
) -> None:
    code, _, err = run(["torque", "--speed", "100, 1000 rpm"], capsys)
    notes = [line for line in err.splitlines() if line.startswith("note:")]
    assert code == 0 and len(notes) == 1
    assert "Hamrock-Dowson" in notes[0] and "U " in notes[0] and "W " in notes[0]
    assert len(notes[0]) <= 140
    code, _, err = run(["--verbose", "torque", "--speed", "100, 1000 rpm"], capsys)
    long = [line for line in err.splitlines() if line.startswith("note:")]
    assert code == 0 and len(long) == 2
    assert all("outside" in line and "usual for ball screws" in line for line in long)
