"""The preload over a screw's life: inversion, trend intervals, threshold crossing, bad series."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from ballscrew import friction_torque
from ballscrew.errors import BallScrewInputError
from ballscrew.fit.monitor import PreloadCurves, invert, preload_curves, run_monitor, threshold
from ballscrew.io.case import default_case_path, load_case
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
        r = run_monitor(CASE, noisy, curves=curves, limit="50 %")
        covered.append((preload >= r.trend_low) & (preload <= r.trend_high))
        share_hits += r.crossing_low <= share_time <= r.crossing_high
        g = run_monitor(CASE, noisy, curves=curves, limit=f"{force} N")
        force_hits += g.crossing_low <= force_time <= g.crossing_high
    # 95 % intervals, a trend of the true form and nearly Gaussian errors in ln F:
    # at least 90 % (the bar; 40 trials leave a few points of sampling spread).
    assert np.mean(covered) >= 0.9
    assert share_hits / trials >= 0.9 and force_hits / trials >= 0.9


def test_an_exact_series_gives_its_decay_rate(truth: tuple[np.ndarray, np.ndarray]) -> None:
    _, torque = truth
    r = run_monitor(CASE, series(torque), limit="50 %")
    assert r.slope == pytest.approx(-1.0 / TAU, rel=1e-2)  # the inversion's 0.5 %, over ln F
    assert r.crossing == pytest.approx(TAU * math.log(2.0), rel=1e-2)


def test_a_threshold_above_the_initial_preload_is_said_to_be_passed_already(
    truth: tuple[np.ndarray, np.ndarray],
) -> None:
    _, torque = truth
    r = run_monitor(CASE, series(torque), limit=f"{1.2 * CASE.screw.preload} N")
    assert r.crossing < 0.0 and any("from the first measurement on" in n for n in r.notes)
    late = run_monitor(CASE, series(torque), limit="10 %")
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
        run_monitor(CASE, parse_series("time [h],torque [N*m]\n0,0.3\n5,0.28\n", screw))
    # N*mm written under an N*m header: far past 4 times the case's preload.
    with pytest.raises(BallScrewInputError, match="check the torque unit"):
        run_monitor(CASE, parse_series("time [h],torque [N*m]\n0,300\n5,290\n9,280\n", screw))
    # Without axial load and preload no ball carries load: the model's torque is 0.
    assert model_torque(0.0, float(np.ravel(CASE.temperature)[0])) == 0.0
    text = "time [d],torque [N*m]\n0,0.3\n5,0.28\n9,0\n"
    with pytest.raises(BallScrewInputError, match="measurement"):
        run_monitor(CASE, parse_series(text, screw))
    r = run_monitor(CASE, parse_series(text, screw), trend="linear")
    assert r.preload[-1] == 0.0 and any("zero preload" in n for n in r.notes)
    np.testing.assert_allclose(r.series.time, [0.0, 120.0, 216.0])  # days in hours


def test_cli_monitor(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    data = Path(__file__).resolve().parents[2] / "examples" / "drag_torque_series.csv"
    plot = tmp_path / "p.png"
    own = ["monitor", "--case", str(default_case_path()), "--measured", str(data)]
    code, out, err = run([*own, "--threshold", "50 %", "--plot", str(plot)], capsys)
    assert code == 0, err
    assert "threshold 50 % of the initial" in out and plot.read_bytes()[:4] == b"\x89PNG"
    code, _, err = run([*own, "--plot", str(tmp_path / "p.gif")], capsys)
    assert code == 2 and "--plot" in err


def test_bands_and_crossings_against_an_independent_regression(
    truth: tuple[np.ndarray, np.ndarray],
) -> None:
    from scipy.optimize import brentq
    from scipy.stats import linregress
    from scipy.stats import t as student_t

    _, torque = truth
    noisy = series(torque * (1.0 + 0.02 * np.random.default_rng(7).standard_normal(TIME.size)))
    force = 0.5 * CASE.screw.preload
    r = run_monitor(CASE, noisy, limit=f"{force} N")
    y = np.log(r.preload)
    fit = linregress(TIME, y)
    n = TIME.size
    s = float(np.sqrt(np.sum((y - fit.intercept - fit.slope * TIME) ** 2) / (n - 2)))
    q = float(student_t.ppf(0.975, n - 2))
    assert r.slope == pytest.approx(fit.slope, rel=1e-10)
    assert r.intercept == pytest.approx(fit.intercept, rel=1e-10)
    assert r.residual_sd == pytest.approx(s, rel=1e-10)
    # The mean's standard error: s^2/n + (t - mean t)^2 se_b^2 (se_b from linregress).
    se = np.sqrt(s**2 / n + (TIME - TIME.mean()) ** 2 * fit.stderr**2)
    centre = fit.intercept + fit.slope * TIME
    np.testing.assert_allclose(r.trend, np.exp(centre), rtol=1e-10)
    np.testing.assert_allclose(r.trend_low, np.exp(centre - q * se), rtol=1e-10)
    np.testing.assert_allclose(r.trend_high, np.exp(centre + q * se), rtol=1e-10)
    # One measurement's interval: its own value +- q s.
    np.testing.assert_allclose(r.preload_low, np.exp(y - q * s), rtol=1e-10)
    np.testing.assert_allclose(r.preload_high, np.exp(y + q * s), rtol=1e-10)
    # The crossing of a force and its inverse-prediction interval, root by root.
    y_th = np.log(force)
    assert r.crossing == pytest.approx((y_th - fit.intercept) / fit.slope, rel=1e-10)

    # An absolute threshold adds the model level's 95 % (1.96 sigma(ln F)) in quadrature.
    level = 1.96 * r.level_sd
    assert r.level_sd > 0.0

    def edge(t: float) -> float:
        mean_se = np.sqrt(s**2 / n + (t - TIME.mean()) ** 2 * fit.stderr**2)
        return abs(fit.intercept + fit.slope * t - y_th) - np.hypot(q * mean_se, level)

    low = brentq(edge, TIME[0] - 1e4, r.crossing)
    high = brentq(edge, r.crossing, TIME[-1] + 1e5)
    # Both refined to Brent's tolerance (1e-9 h) from the same function: far below 1e-6 h.
    assert r.crossing_low == pytest.approx(low, abs=1e-6)
    assert r.crossing_high == pytest.approx(high, abs=1e-6)
    # A share of the initial preload: ln(share) over the slope's 95 % interval.
    g = run_monitor(CASE, noisy, limit="50 %")
    edges = sorted(np.log(0.5) / (fit.slope + np.array([-1.0, 1.0]) * q * fit.stderr))
    assert (g.crossing_low, g.crossing_high) == pytest.approx(tuple(edges), rel=1e-10)
    assert g.crossing == pytest.approx(np.log(0.5) / fit.slope, rel=1e-10)


def test_grid_defaults_exact_nodes_and_notes(truth: tuple[np.ndarray, np.ndarray]) -> None:
    _, torque = truth
    curves = preload_curves(CASE, "complete", series(torque))
    f = CASE.screw.preload
    assert curves.preloads[0] == 0.0 and curves.preloads.size == 49
    assert curves.preloads[1] == pytest.approx(0.01 * f) and curves.preloads[-1] == pytest.approx(
        4 * f
    )
    # A torque on a grid node reads back the node exactly, the top node included.
    nodes = curves.torque[[5, 20, -1], 0]
    back, below = invert(PreloadCurves(curves.preloads, curves.torque[:, :3], "complete"), nodes)
    np.testing.assert_allclose(back, curves.preloads[[5, 20, -1]], rtol=1e-12)
    assert not below.any()
    # A screw without preload: the grid is set from 1 kN.
    bare = load_case(None)
    object.__setattr__(bare, "screw", CASE.screw.replace(preload=0.0))
    assert preload_curves(bare, "catalog", series(torque)).preloads[-1] == pytest.approx(4000.0)
    # Few points, and a preload that does not fall: said.
    few = TorqueSeries(TIME[:5], torque[:5], np.full(5, CATALOGUE_SPEED), "few")
    assert any("5 measurements" in n for n in run_monitor(CASE, few, limit="50 %").notes)
    rising = run_monitor(CASE, series(torque[::-1]), limit="50 %")
    assert rising.slope > 0 and any("does not fall" in n for n in rising.notes)
    for bad in ("0 %", "100 %", "0 kN"):
        with pytest.raises(BallScrewInputError, match="--threshold"):
            threshold(bad, 1800.0)


def test_the_former_name_warns_and_gives_the_same_result(
    truth: tuple[np.ndarray, np.ndarray],
) -> None:
    from ballscrew.fit.monitor import monitor_preload

    _, torque = truth
    with pytest.warns(DeprecationWarning, match="run_monitor"):
        old = monitor_preload(CASE, series(torque), limit="50 %")
    new = run_monitor(CASE, series(torque), limit="50 %")
    np.testing.assert_array_equal(old.preload, new.preload)
