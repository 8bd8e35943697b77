"""``export-friction --form frict-comp|charcurve|lincurve`` run on their own default ``--speed``.

The default, '0.1..3000:60 rpm', is a screw speed: the table spans the table speeds
it gives at the case's lead, 3000 rpm x 10 mm = 0.5 m/s (issue 52: both forms refused
their own default as "not a linear speed").
"""

from __future__ import annotations

import json

import pytest

from cli_runner import run
from shared import ROOT

EXAMPLE = str(ROOT / "examples" / "xy_table_32x10.toml")


@pytest.mark.parametrize("form", ["frict-comp", "charcurve", "lincurve"])
def test_the_default_speed_is_read_at_the_lead(
    form: str, capsys: pytest.CaptureFixture[str]
) -> None:
    extra = ["--axis-number", "1", "--drive-unit", "0.001 N*m"] if form == "frict-comp" else []
    code, out, err = run(["export-friction", "--case", EXAMPLE, "--form", form, *extra,
                          "--json", "-"], capsys)  # fmt: skip
    assert code == 0, err
    doc = json.loads(out)
    assert doc["speed_range_m_s"] == pytest.approx(3000 / 60 * 0.010, rel=1e-12)


def test_a_feed_still_gives_the_table_speed(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(["export-friction", "--case", EXAMPLE, "--form", "charcurve",
                          "--speed", "6 m/min", "--json", "-"], capsys)  # fmt: skip
    assert code == 0, err
    assert json.loads(out)["speed_range_m_s"] == pytest.approx(0.1, rel=1e-12)
