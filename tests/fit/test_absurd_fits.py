"""Fits that know when they are absurd (issue 27, item 3).

The issue: "torques in N·mm under an N·m header gave a preload of 847 kN on a
nut rated 56 kN; data with a low-speed friction drop gave a ball-train
constant 4 x its trained value and a clearly systematic residual, with no
warning".
"""

from __future__ import annotations

import json
import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from ballscrew import friction_torque, reference_screw
from ballscrew.cli import main
from ballscrew.fit.calibration import (
    fit_parameters,
    lag1_autocorrelation,
    runs_test,
)
from ballscrew.io.measured import MeasuredCurve
from shared import synthetic_drag_curve

OIL = "PAO ISO VG 68"


def _truth() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    return synthetic_drag_curve()


def _fit(torque: np.ndarray) -> object:
    w, t, _ = _truth()
    curve = MeasuredCurve(w, torque, "synthetic", temperature=t)
    return fit_parameters(reference_screw(), OIL, curve, ["preload", "ball_train_constant"])


def test_runs_test_against_the_textbook_formulas_by_hand() -> None:
    # n1 = n2 = 8 in four blocks: R = 4, mean 2*8*8/16 + 1 = 9,
    # variance 2*64*(128 - 16)/(256*15) = 3.7333, z = -5/1.93218 = -2.5877,
    # one-sided p = Phi(-2.5877) = 0.00483.
    r = runs_test([1, 1, 1, 1, -1, -1, -1, -1] * 2)
    assert (r.runs, r.expected) == (4, 9.0)
    assert r.z == pytest.approx(-5.0 / math.sqrt(2 * 64 * 112 / (256 * 15)), rel=1e-12)
    assert r.p_fewer == pytest.approx(0.004831, abs=2e-6)
    # Alternating signs: as many runs as values, p near 1; one sign only: no test.
    assert runs_test([1, -1] * 8).p_fewer > 0.99
    assert runs_test([1.0] * 10).p_fewer == 1.0


def test_lag1_autocorrelation_by_hand() -> None:
    # x = 1..4, mean 2.5: deviations -1.5 -0.5 0.5 1.5, sum of squares 5,
    # lagged products 0.75 - 0.25 + 0.75 = 1.25: r1 = 0.25.
    assert lag1_autocorrelation([1.0, 2.0, 3.0, 4.0]) == pytest.approx(0.25)
    assert lag1_autocorrelation([1.0, -1.0] * 5) == pytest.approx(-0.9)


def test_noisy_data_of_the_model_itself_are_not_called_absurd() -> None:
    _, _, torque = _truth()
    for seed in range(10):
        rng = np.random.default_rng(seed)
        r = _fit(torque * (1.0 + 0.05 * rng.standard_normal(torque.size)))
        assert r.reliable, (seed, r.warnings)
        assert set(r.structure) >= {"runs", "p_fewer_runs", "lag1_autocorrelation"}


def test_torques_in_n_mm_under_an_n_m_header_are_named_as_a_unit_slip() -> None:
    _, _, torque = _truth()
    r = _fit(torque * 1000.0)
    assert not r.reliable
    text = " | ".join(r.warnings)
    assert "N*mm under an N*m header" in text and "about 10^3" in text
    assert "screw.preload" in text and "static rating C_0a" in text
    assert r.as_dict()["intervals_reliable"] is False


def test_a_low_speed_friction_drop_gives_a_warned_constant_and_structured_residuals() -> None:
    w, _, torque = _truth()
    r = _fit(torque * (1.0 + 0.8 * np.exp(-w / (30 * np.pi / 30))))
    assert not r.reliable
    text = " | ".join(r.warnings)
    assert "ball_train_constant" in text and "training cases" in text
    assert "the residuals have structure" in text and "runs test" in text
    assert r.structure["p_fewer_runs"] < 0.01


def test_the_fit_command_marks_the_intervals_unreliable(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    w, t, torque = _truth()
    csv = tmp_path / "run.csv"
    body = "".join(
        f"{a:.17g},{b:.17g},{c:.17g}\n" for a, b, c in zip(w, t, torque * 1000, strict=True)
    )
    csv.write_text("speed [rad/s],temperature [degC],torque [N*m]\n" + body)
    case = tmp_path / "s.toml"
    case.write_text('[screw]\ndesignation = "HIWIN R40-10K5-FDC"\npreload = "2 kN"\n'
                    '[lubricant]\nname = "PAO ISO VG 68"\n')  # fmt: skip
    with pytest.raises(SystemExit) as info:
        main(["fit", "--case", str(case), "--measured", str(csv), "--free", "preload",
              "--out", str(tmp_path / "fit"), "--json", str(tmp_path / "f.json")])  # fmt: skip
    assert info.value.code == 0
    captured = capsys.readouterr()
    assert "(unreliable)" in captured.out
    assert "N*mm under an N*m header" in captured.err
    assert "C_0a = 184 kN (the HIWIN R40-10K5-FDC catalogue row)" in captured.err
    assert "intervals are unreliable" in captured.err
    assert json.loads((tmp_path / "f.json").read_text())["intervals_reliable"] is False
    assert "intervals are unreliable" in (tmp_path / "fit" / "report.md").read_text()


def test_a_model_validity_issue_at_the_fitted_values_is_told() -> None:
    # Item 5 for fit: 10 kN on a 1.5 kN preload lifts the relieved half-nut off; the
    # fit says so, as ballscrew torque does (routine film notes are left out).
    w, t, _ = _truth()
    loads = np.full(w.size, 10e3)
    screw = reference_screw().replace(preload=1500.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        torque = friction_torque(screw, OIL, speed=w, temperature=t, axial_load=loads,
                                 ball_train_constant=0.03).total  # fmt: skip
    curve = MeasuredCurve(w, np.asarray(torque), "loaded", temperature=t, axial_load=loads)
    r = fit_parameters(screw, OIL, curve, ["ball_train_constant"])
    told = [x for x in r.warnings if x.startswith("model validity")]
    assert len(told) == 1 and "axial load / preload = 6.667" in told[0]
    assert "lifts off" in told[0]
    assert not any("dimensionless" in x for x in r.warnings)
    assert r.reliable
