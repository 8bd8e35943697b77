"""The preload over a screw's life: inversion, trend intervals, threshold crossing, bad series."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from ballscrew import friction_torque
from ballscrew.errors import BallScrewInputError
from ballscrew.fit.monitor import invert, monitor_preload, preload_curves, threshold
from ballscrew.io.case import load_case
from ballscrew.io.series import CATALOGUE_SPEED, TorqueSeries, parse_series
from ballscrew.loads import LIFT_OFF_RATIO
from cli_runner import run

CASE = load_case(None)
TIME = np.linspace(0.0, 10000.0, 15)
TAU = 8000.0  # h: the synthetic preload decays as exp(-t / TAU)


def model_torque(preload: float, temperature: float = 20.0) -> float:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return float(friction_torque(CASE.screw.replace(preload=preload), CASE.lubricant,
                                     speed=CATALOGUE_SPEED, temperature=temperature,
                                     model="complete").total)  # fmt: skip


@pytest.fixture(scope="module")
def truth() -> tuple[np.ndarray, np.ndarray]:
    preload = CASE.screw.preload * np.exp(-TIME / TAU)
    return preload, np.array([model_torque(f) for f in preload])


def series(torque: np.ndarray) -> TorqueSeries:
    return TorqueSeries(TIME, torque, np.full(TIME.shape, CATALOGUE_SPEED), "synthetic")


def test_inversion_reads_back_the_preload(truth: tuple[np.ndarray, np.ndarray]) -> None:
    preload, torque = truth
    curves = preload_curves(CASE, "complete", series(torque))
    back, below = invert(curves, torque)
    assert not below.any()
    # Linear interpolation between 48 geometric grid preloads (13 % apart) of a curve
    # that is nearly linear in the preload: within 0.5 %.
    np.testing.assert_allclose(back, preload, rtol=5e-3)


def test_intervals_cover_the_truth_at_the_stated_rate(truth: tuple[np.ndarray, np.ndarray]) -> None:
    preload, torque = truth
    curves = preload_curves(CASE, "complete", series(torque))
    rng = np.random.default_rng(20261125)
    share_time = TAU * math.log(2.0)  # 50 % of the initial preload
    force = 0.4 * CASE.screw.preload
    force_time = TAU * math.log(CASE.screw.preload / force)
    covered, share_hits, force_hits = [], 0, 0
    trials = 40
    for _ in range(trials):
        noisy = series(torque * (1.0 + 0.03 * rng.standard_normal(TIME.size)))
        r = monitor_preload(CASE, noisy, curves=curves, limit="50 %")
        covered.append((preload >= r.trend_low) & (preload <= r.trend_high))
        share_hits += r.crossing_low <= share_time <= r.crossing_high
        g = monitor_preload(CASE, noisy, curves=curves, limit=f"{force} N")
        force_hits += g.crossing_low <= force_time <= g.crossing_high
    # 95 % intervals, a trend of the true form and nearly Gaussian errors in ln F:
    # at least 90 % (the bar; 40 trials leave a few points of sampling spread).
    assert np.mean(covered) >= 0.9
    assert share_hits / trials >= 0.9 and force_hits / trials >= 0.9


def test_an_exact_series_gives_its_decay_rate(truth: tuple[np.ndarray, np.ndarray]) -> None:
    _, torque = truth
    r = monitor_preload(CASE, series(torque), limit="50 %")
    assert r.slope == pytest.approx(-1.0 / TAU, rel=1e-2)  # the inversion's 0.5 %, over ln F
    assert r.crossing == pytest.approx(TAU * math.log(2.0), rel=1e-2)


def test_a_threshold_above_the_initial_preload_is_said_to_be_passed_already(
    truth: tuple[np.ndarray, np.ndarray],
) -> None:
    _, torque = truth
    r = monitor_preload(CASE, series(torque), limit=f"{1.2 * CASE.screw.preload} N")
    assert r.crossing < 0.0 and any("from the first measurement on" in n for n in r.notes)
    late = monitor_preload(CASE, series(torque), limit="10 %")
    assert late.crossing > TIME[-1] and any("extrapolated beyond" in n for n in late.notes)


def test_thresholds() -> None:
    assert threshold("50 %", 1800.0).value == pytest.approx(900.0)
    assert threshold("1,2 kN", 1800.0).value == pytest.approx(1200.0)
    assert threshold("lift-off 3 kN", 1800.0).value == pytest.approx(3000.0 / LIFT_OFF_RATIO)
    for bad in ("150 %", "abc %", "-2 kN", "2 kg"):
        with pytest.raises(BallScrewInputError, match="--threshold"):
            threshold(bad, 1800.0)


def test_bad_series_name_the_row() -> None:
    screw = CASE.screw
    with pytest.raises(BallScrewInputError, match="line 3"):
        parse_series("time [h],torque [N*m]\n0,0.3\n0,0.29\n5,0.28\n", screw)
    with pytest.raises(BallScrewInputError, match="time column"):
        parse_series("time,torque [N*m]\n0,0.3\n", screw)
    with pytest.raises(BallScrewInputError, match="at least 3"):
        monitor_preload(CASE, parse_series("time [h],torque [N*m]\n0,0.3\n5,0.28\n", screw))
    # N*mm written under an N*m header: far past 4 times the case's preload.
    with pytest.raises(BallScrewInputError, match="check the torque unit"):
        monitor_preload(CASE, parse_series("time [h],torque [N*m]\n0,300\n5,290\n9,280\n", screw))
    # Without axial load and preload no ball carries load: the model's torque is 0.
    assert model_torque(0.0, float(np.ravel(CASE.temperature)[0])) == 0.0
    text = "time [d],torque [N*m]\n0,0.3\n5,0.28\n9,0\n"
    with pytest.raises(BallScrewInputError, match="measurement"):
        monitor_preload(CASE, parse_series(text, screw))
    r = monitor_preload(CASE, parse_series(text, screw), trend="linear")
    assert r.preload[-1] == 0.0 and any("zero preload" in n for n in r.notes)
    np.testing.assert_allclose(r.series.time, [0.0, 120.0, 216.0])  # days in hours


def test_cli_monitor(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    data = Path(__file__).resolve().parents[2] / "examples" / "drag_torque_series.csv"
    plot = tmp_path / "p.png"
    code, out, err = run(["monitor", "--measured", str(data), "--threshold", "50 %",
                          "--plot", str(plot)], capsys)  # fmt: skip
    assert code == 0, err
    assert "threshold 50 % of the initial" in out and plot.read_bytes()[:4] == b"\x89PNG"
    code, _, err = run(["monitor", "--measured", str(data), "--plot", str(tmp_path / "p.gif")],
                       capsys)  # fmt: skip
    assert code == 2 and "--plot" in err
