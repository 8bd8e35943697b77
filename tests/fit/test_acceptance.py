"""Acceptance of a measured drag torque against the makers' band (THK A-688 Table 13)."""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from ballscrew.design.catalog_formulas import drag_torque_tolerance, preload_torque
from ballscrew.errors import BallScrewInputError
from ballscrew.fit.acceptance import accept_drag_torque
from cli_runner import run
from shared import BNFN4010


def test_thk_worked_example() -> None:
    # THK's selection example: BNFN4010-5 (ball centre diameter 41.75 mm, lead 10 mm),
    # preload 3000 N, reference torque 865 N*mm, grade C3 +-30 %.
    reference = float(preload_torque(3000.0, 0.010, math.atan(0.010 / (math.pi * 0.04175))))
    assert reference == pytest.approx(0.865, abs=5e-4)  # the catalogue prints whole N*mm
    a = accept_drag_torque(0.865, 0.865)
    assert a.row == (0.6, 1.0, 0.30)
    assert (a.low, a.high) == pytest.approx((0.6055, 1.1245))
    assert a.accepted and any("fluctuation is unknown" in n for n in a.notes)


@pytest.mark.parametrize(
    ("torque", "tolerance"),
    [(0.2, 0.45), (0.4, 0.45), (0.40001, 0.35), (0.6, 0.35), (0.60001, 0.30), (1.0, 0.30),
     (1.00001, 0.25), (2.5, 0.25), (2.50001, 0.20), (6.3, 0.20)],
)  # fmt: skip
def test_each_row_at_its_edges(torque: float, tolerance: float) -> None:
    assert drag_torque_tolerance(torque)[2] == tolerance


def test_edges_of_the_band_and_the_table() -> None:
    assert accept_drag_torque([0.6056, 0.6056], 0.865).accepted
    assert not accept_drag_torque(0.6050, 0.865).accepted
    assert (
        accept_drag_torque(1.1244, 0.865).accepted and not accept_drag_torque(1.125, 0.865).accepted
    )
    for ref in (0.19, 6.4):
        with pytest.raises(BallScrewInputError, match="reference torque"):
            accept_drag_torque(0.5, ref)
    with pytest.raises(BallScrewInputError, match="grade"):
        accept_drag_torque(0.5, 0.5, grade="C5")
    # A trace: the mean is judged, the fluctuation reported; N*mm read as N*m is named.
    a = accept_drag_torque([0.8, 0.92, 0.86], 0.865)
    assert a.mean == pytest.approx(0.86) and a.fluctuation == pytest.approx(0.12)
    assert any("check the torque unit" in n for n in accept_drag_torque(865.0, 0.865).notes)


def test_cli(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    case = tmp_path / "bnfn.toml"
    case.write_text(BNFN4010, encoding="utf-8")
    code, out, err = run(["acceptance", "--case", str(case), "--torque", "0.80, 0.92, 0.86 N*m"],
                         capsys)  # fmt: skip
    assert code == 0, err
    assert "reference 0.8646 N*m" in out and "verdict: ACCEPTED" in out
    code, out, _ = run(["acceptance", "--case", str(case), "--torque", "1 200 N*mm",
                        "--reference", "865 N*mm"], capsys)  # fmt: skip
    assert code == 0 and "NOT ACCEPTED (+38.7% from the reference)" in out
    code, _, err = run(["acceptance", "--case", str(case)], capsys)
    assert code == 2 and "--torque" in err


def test_unit_slip_note_at_its_edges() -> None:
    # The note fires past a factor of 100 either way (N*mm read as N*m is 1000).
    def slip(mean: float, reference: float) -> bool:
        return any("check the torque unit" in n for n in accept_drag_torque(mean, reference).notes)

    assert slip(60.0, 0.5) and not slip(45.0, 0.5)  # 120 and 90 times
    assert not slip(50.0, 0.5) and slip(52.5, 0.5)  # exactly 100 is not past it; 105 is
    assert not slip(0.005, 0.5) and not slip(0.0105, 1.0)  # exactly 1/100, and just above it
    assert slip(0.004, 0.5)


def test_band_edges_belong_to_the_band_and_the_json() -> None:
    edge = accept_drag_torque(0.7, 1.0)  # row 0.6-1.0: +-30 %, so 0.7 is the lower edge
    assert edge.accepted and accept_drag_torque(1.3, 1.0).accepted
    one = accept_drag_torque(0.9, 1.0)
    assert one.fluctuation == 0.0 and one.points == 1
    doc = accept_drag_torque([0.8, 0.9], 1.0).as_dict()
    assert doc["row"] == {"from_Nm": 0.6, "to_Nm": 1.0, "tolerance": 0.3}
    assert doc["accepted_from_Nm"] == pytest.approx(0.7) and doc["accepted_to_Nm"] == 1.3
    assert doc["mean_torque_Nm"] == pytest.approx(0.85) and doc["fluctuation_Nm"] == pytest.approx(
        0.1
    )
    with pytest.raises(BallScrewInputError, match="a positive reference torque"):
        accept_drag_torque(0.5, 0.0)
