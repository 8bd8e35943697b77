"""acceptance: ISO 14253-1's three-way decision, each speed on its own, a stated band, a plot."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest

from ballscrew.errors import BallScrewInputError
from ballscrew.fit.acceptance import DECISIONS, accept_drag_torque, decide
from ballscrew.kinematics import rpm_to_rad_s
from cli_runner import run
from shared import BNFN4010


def test_iso_14253_zones_on_thks_example() -> None:
    # THK's example: reference 0.865 N*m, C3 row 0.6-1.0 N*m, +-30 %: band 0.6055-1.1245.
    # With U = 0.05 N*m: conformance proven inside 0.6555-1.0745, non-conformance proven
    # outside 0.5555-1.1745, undecided between (ISO 14253-1:2017, 5.2 and 5.3).
    for mean, expected in ((0.86, DECISIONS[0]), (1.07, DECISIONS[0]), (1.08, DECISIONS[2]),
                           (1.17, DECISIONS[2]), (1.18, DECISIONS[1]), (0.66, DECISIONS[0]),
                           (0.65, DECISIONS[2]), (0.55, DECISIONS[1])):  # fmt: skip
        a = accept_drag_torque(mean, 0.865, uncertainty=0.05)
        assert a.decision == expected, mean
    # Without U the decision is the band's: inside is proven, outside disproven.
    assert accept_drag_torque(1.1, 0.865).decision == DECISIONS[0]
    assert accept_drag_torque(1.2, 0.865).decision == DECISIONS[1]
    assert any("no measurement uncertainty" in n for n in accept_drag_torque(1.1, 0.865).notes)
    assert decide(1.0, 0.7, 1.3, 0.4) == DECISIONS[2]  # U wider than half the band


def test_each_speed_of_a_trace_is_judged_on_its_own() -> None:
    # Issue 34: a trace at 100 and 1500 rpm was averaged. Readings 0.85 N*m at 100 rpm
    # (inside) and 1.30 N*m at 1500 rpm (outside the 1.1245 edge): averaged (1.075) they
    # would pass; on their own the trace has one speed out.
    w = rpm_to_rad_s(np.array([100.0] * 3 + [1500.0] * 3))
    torque = [0.84, 0.85, 0.86, 1.29, 1.30, 1.31]
    a = accept_drag_torque(torque, 0.865, speed=w, uncertainty=0.02)
    assert [round(v.speed * 30 / math.pi) for v in a.speeds] == [100, 1500]
    assert [v.mean for v in a.speeds] == pytest.approx([0.85, 1.30])
    assert [v.decision for v in a.speeds] == [DECISIONS[0], DECISIONS[1]]
    assert a.decision == DECISIONS[1] and not a.accepted
    assert accept_drag_torque(torque, 0.865).accepted  # averaged, as before, it passed
    doc = a.as_dict()
    assert [s["speed_rpm"] for s in doc["speeds"]] == pytest.approx([100.0, 1500.0])
    assert any("each judged on its own" in n for n in a.notes)


def test_a_stated_band_handles_references_below_the_table_and_other_grades() -> None:
    with pytest.raises(BallScrewInputError, match="--tolerance"):
        accept_drag_torque(0.15, 0.15)  # below 0.2 N*m: the table has no row
    with pytest.raises(BallScrewInputError, match="--tolerance"):
        accept_drag_torque(0.5, 0.5, grade="C5")  # only C3 is held (refused, as before)
    a = accept_drag_torque(0.17, 0.15, tolerance=0.5)
    assert (a.low, a.high) == pytest.approx((0.075, 0.225)) and a.accepted
    assert "given" in a.as_dict()["source"]


def test_cli_trace_uncertainty_and_plot(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    case = tmp_path / "bnfn.toml"
    case.write_text(BNFN4010, encoding="utf-8")
    trace = tmp_path / "trace.csv"
    trace.write_text("speed [rpm],torque [N*m]\n100,0.84\n100,0.86\n1500,1.29\n1500,1.31\n",
                     encoding="utf-8")  # fmt: skip
    plot = tmp_path / "trace.png"
    out_json = tmp_path / "a.json"
    code, out, err = run(["acceptance", "--case", str(case), "--measured", str(trace),
                          "--uncertainty", "2 %", "--plot", str(plot), "--json",
                          str(out_json)], capsys)  # fmt: skip
    assert code == 0, err
    assert "at 100 rpm" in out and "at 1500 rpm" in out
    assert "decision (ISO 14253-1, U = 0.0173 N*m): non-conformance proven" in out
    assert plot.read_bytes()[:4] == b"\x89PNG"
    doc = json.loads(out_json.read_text(encoding="utf-8"))
    assert doc["decision"] == "non-conformance proven" and len(doc["speeds"]) == 2
    code, _, err = run(["acceptance", "--case", str(case), "--torque", "0.15 N*m",
                        "--reference", "0.15 N*m", "--tolerance", "40 %"], capsys)  # fmt: skip
    assert code == 0, err
