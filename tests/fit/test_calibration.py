"""Calibration: parameters recovered from data the model made, with honest intervals."""

from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from ballscrew import friction_torque, reference_screw
from ballscrew.errors import BallScrewInputError
from ballscrew.fit.calibration import fit_parameters, fitted_case_toml
from ballscrew.io.case import parse_case
from ballscrew.io.measured import MeasuredCurve, parse_measured
from shared import synthetic_drag_curve

OIL = "PAO ISO VG 68"
TRUE_PRELOAD, TRUE_CB = 1500.0, 0.03


def _truth() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    return synthetic_drag_curve(TRUE_PRELOAD, TRUE_CB)


def _fit(torque: np.ndarray, free: list[str] | None = None) -> object:
    w, t, _ = _truth()
    curve = MeasuredCurve(w, torque, "synthetic", temperature=t)
    return fit_parameters(reference_screw(), OIL, curve, free or ["preload", "ball_train_constant"])


def test_noise_free_data_give_back_the_true_values() -> None:
    _, _, torque = _truth()
    r = _fit(torque)
    # Starts are 2000 N and 0.0474: the optimum is the truth to the solver's tolerance.
    assert r.estimates["preload"].value == pytest.approx(TRUE_PRELOAD, rel=1e-6)
    assert r.estimates["ball_train_constant"].value == pytest.approx(TRUE_CB, rel=1e-6)
    assert r.rms_residual < 1e-9


def test_true_values_inside_the_intervals_in_most_seeded_trials() -> None:
    # 5 % multiplicative noise, 10 seeds. A nominal 95 % interval covers the
    # truth 9.5 times in 10 on average; P(6 or fewer | 0.95) = 1e-3, so 7 of
    # 10 is a test that a broken interval fails and a sound one passes.
    _, _, torque = _truth()
    hits = {"preload": 0, "ball_train_constant": 0}
    for seed in range(10):
        rng = np.random.default_rng(seed)
        r = _fit(torque * (1.0 + 0.05 * rng.standard_normal(torque.size)))
        for name, true in (("preload", TRUE_PRELOAD), ("ball_train_constant", TRUE_CB)):
            e = r.estimates[name]
            hits[name] += e.low <= true <= e.high
    assert hits["preload"] >= 7 and hits["ball_train_constant"] >= 7, hits


def test_outliers_are_left_out_and_named() -> None:
    _, _, torque = _truth()
    rng = np.random.default_rng(3)
    noisy = torque * (1.0 + 0.02 * rng.standard_normal(torque.size))
    clean = _fit(noisy)
    spoiled = noisy.copy()
    spoiled[[2, 9, 17]] *= 3.0  # three wild readings
    r = _fit(spoiled)
    assert r.outliers == (2, 9, 17)
    assert any("rows 3, 10, 18" in w for w in r.warnings)
    # Without those three points the fit is the clean one to within its own
    # scatter (2 % noise: a few percent on the estimates).
    for name in ("preload", "ball_train_constant"):
        assert r.estimates[name].value == pytest.approx(clean.estimates[name].value, rel=0.05)


def test_a_parameter_the_data_cannot_see_is_held_with_a_warning() -> None:
    # The hysteresis loss is 0.3 % of the torque: 5 % noise hides it.
    _, _, torque = _truth()
    rng = np.random.default_rng(11)
    r = _fit(torque * (1.0 + 0.05 * rng.standard_normal(torque.size)),
             ["preload", "hysteresis_loss_factor"])  # fmt: skip
    e = r.estimates["hysteresis_loss_factor"]
    assert not e.identified and e.low is None and e.value == e.start
    assert any("hysteresis_loss_factor cannot be identified" in w for w in r.warnings)
    assert r.estimates["preload"].identified


def test_sparse_data_error_and_few_degrees_of_freedom_warn() -> None:
    w, t, torque = _truth()
    two = MeasuredCurve(w[:2], torque[:2], "two points", temperature=t[:2])
    with pytest.raises(BallScrewInputError, match="more points than free parameters"):
        fit_parameters(reference_screw(), OIL, two, ["preload", "ball_train_constant"])
    four = MeasuredCurve(w[[0, 5, 11, 12]], torque[[0, 5, 11, 12]], "four",
                         temperature=t[[0, 5, 11, 12]])  # fmt: skip
    r = fit_parameters(reference_screw(), OIL, four, ["preload", "ball_train_constant"])
    assert any("degree(s) of freedom" in w for w in r.warnings)
    with pytest.raises(BallScrewInputError, match="--free"):
        fit_parameters(reference_screw(), OIL, four, ["lead"])
    with pytest.raises(BallScrewInputError, match="parameter of model 'catalog'"):
        fit_parameters(reference_screw(), OIL, four, ["ball_train_constant"], model="catalog")


def test_the_fitted_case_file_loads_and_gives_the_fitted_torque() -> None:
    _, _, torque = _truth()
    r = _fit(torque)
    text = (
        'title = "mine"\n[screw]\npitch_diameter = "40 mm"  # as drawn\nlead = "10 mm"\n'
        'ball_diameter = "6.35 mm"\npreload_drag_torque = "0.3 N*m"\n'
        '[lubricant]\nname = "PAO ISO VG 68"\n'
    )
    out = fitted_case_toml(text, r)
    assert "# as drawn" in out  # the user's comments stay
    case = parse_case(out)
    assert case.screw.preload == pytest.approx(TRUE_PRELOAD, rel=1e-5)
    fitted_cb = case.model_parameters["complete"]["ball_train_constant"]
    assert fitted_cb == pytest.approx(TRUE_CB, rel=1e-5)


def test_measured_files_carry_temperature_and_load_columns() -> None:
    m = parse_measured(
        "speed [rpm];temperature [K];axial load [kN];torque [N*mm]\n"
        "100;313,15;1,5;300\n-200;293,15;0;400\n",
        reference_screw(),
    )
    np.testing.assert_allclose(m.temperature, [40.0, 20.0])
    np.testing.assert_allclose(m.axial_load, [1500.0, 0.0])
    np.testing.assert_allclose(m.torque, [0.3, 0.4])
    assert m.speed[1] < 0.0  # the direction is kept


def test_fit_command_writes_case_report_and_json(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    import json

    from ballscrew.cli import main

    w, t, torque = _truth()
    csv = tmp_path / "run.csv"
    body = "".join(f"{float(a)!r},{float(b)!r},{float(c)!r}\n"
                   for a, b, c in zip(w, t, torque, strict=True))  # fmt: skip
    csv.write_text("speed [rad/s],temperature [degC],torque [N*m]\n" + body)
    case = tmp_path / "s.toml"
    case.write_text('[screw]\npitch_diameter = "40 mm"\nlead = "10 mm"\n'
                    'ball_diameter = "6.35 mm"\npreload = "2 kN"\n'
                    '[lubricant]\nname = "PAO ISO VG 68"\n')  # fmt: skip
    with pytest.raises(SystemExit) as info:
        main(["fit", "--case", str(case), "--measured", str(csv), "--free",
              "preload, ball_train_constant", "--out", str(tmp_path / "fit"),
              "--json", "-"])  # fmt: skip
    assert info.value.code == 0
    payload = json.loads(capsys.readouterr().out)
    p = payload["parameters"]["preload"]
    assert p["value"] == pytest.approx(TRUE_PRELOAD, rel=1e-5) and p["low"] <= p["high"]
    assert payload["rms_residual_Nm"] < 1e-8 and isinstance(payload["warnings"], list)
    for name in ("fitted-case.toml", "report.html", "report.md", "fit.json", "data/fit.csv",
                 "figures/fit.png"):  # fmt: skip
        assert (tmp_path / "fit" / name).is_file(), name
    with pytest.raises(SystemExit) as info:
        main(["fit", "--case", str(case), "--measured", str(csv), "--free", "preload",
              "--start", "preload=1500"])  # fmt: skip
    assert info.value.code == 2 and "bare number" in capsys.readouterr().err
    # A start outside the parameter's bounds (a preload of -1 kN, 2 MN) is refused as typed,
    # where it was moved to the bound (1 N) without a word.
    for typed, shown in (("-1 kN", "-1000 N"), ("2 MN", "2e+06 N")):
        with pytest.raises(SystemExit) as info:
            main(["fit", "--case", str(case), "--measured", str(csv), "--free", "preload",
                  "--start", f"preload={typed}"])  # fmt: skip
        err = capsys.readouterr().err
        assert info.value.code == 2 and f"start preload = '{shown}'" in err, err
        assert "from 1 to 1e+06 N" in err


def _catalog_curve(loads: np.ndarray, noise: np.ndarray) -> MeasuredCurve:
    w = np.full(loads.size, 100 * np.pi / 30)
    clean = friction_torque(reference_screw(), OIL, speed=w, temperature=40.0, axial_load=loads,
                            model="catalog").total  # fmt: skip
    return MeasuredCurve(w, np.asarray(clean) * (1.0 + noise), "catalog", axial_load=loads)


def test_interval_of_a_proportional_model_is_the_textbook_one() -> None:
    # At no axial load the catalogue torque is K * A (K the preload coefficient): a
    # one-parameter linear regression through the origin, solved here by hand: K = a.y/a.a,
    # s^2 = sum r^2/(n-1), se = s/|a|, and the log-space interval exp(ln K +- t_{n-1} se/K)
    # (Student's t from scipy). Only the solver's tolerance separates the two (1e-6).
    from scipy.stats import t as student

    rng = np.random.default_rng(5)
    n = 12
    curve = _catalog_curve(np.zeros(n), 0.05 * rng.standard_normal(n))
    r = fit_parameters(reference_screw(), OIL, curve, ["preload_coefficient"], model="catalog")
    a = friction_torque(reference_screw(), OIL, speed=1.0, temperature=40.0, model="catalog",
                        preload_coefficient=1.0).total * np.ones(n)  # fmt: skip
    y = curve.torque
    k = float(a @ y / (a @ a))
    s = math.sqrt(float(np.sum((y - k * a) ** 2)) / (n - 1))
    half = student.ppf(0.975, n - 1) * s / math.sqrt(float(a @ a)) / k
    e = r.estimates["preload_coefficient"]
    assert e.value == pytest.approx(k, rel=1e-6)
    assert e.low == pytest.approx(k * math.exp(-half), rel=1e-6)
    assert e.high == pytest.approx(k * math.exp(half), rel=1e-6)
    assert r.rms_residual == pytest.approx(math.sqrt(np.mean((y - k * a) ** 2)), rel=1e-6)


@pytest.mark.parametrize("low, warned", [(0.0, False), (2500.0, True)])
def test_correlation_of_two_linear_terms_as_regression_predicts(low: float, warned: bool) -> None:
    # Catalogue torque = K * A + F_a * g(mu), nearly linear in mu: the estimates of a
    # constant and a slope in F_a correlate as -mean(F)/rms(F) (regression through two
    # columns, 1 and F). Loads 0..3 kN: -0.87, no warning; 2.5..3 kN: -0.998, a warning.
    loads = np.linspace(low, 3000.0, 16)
    rng = np.random.default_rng(8)
    curve = _catalog_curve(loads, 0.002 * rng.standard_normal(loads.size))
    free = ["preload_coefficient", "friction_coefficient"]
    r = fit_parameters(reference_screw(), OIL, curve, free, model="catalog")
    rho = -float(np.mean(loads) / np.sqrt(np.mean(loads**2)))
    # 2e-2: g(mu) is linear in mu to the first order only (1/eta - 1 with mu ~ 0.003).
    assert r.correlation[0, 1] == pytest.approx(rho, abs=2e-2)
    assert any("are correlated" in w for w in r.warnings) is warned


def test_defaults_temperature_and_load_when_the_file_has_none() -> None:
    # Documented defaults of fit_parameters: 20 °C and no axial load.
    w, t, torque = _truth()
    keep = t == 20.0
    bare = MeasuredCurve(w[keep], torque[keep], "no columns")
    r = fit_parameters(reference_screw(), OIL, bare, ["preload"])
    assert r.temperature.tolist() == [20.0] * int(keep.sum())
    assert r.axial_load.tolist() == [0.0] * int(keep.sum())


def test_every_parameter_unidentified_leaves_the_start_and_its_residual() -> None:
    # Only the hysteresis factor free, under 5 % noise: held at its start, and the
    # residual reported is that of the start values, computed here directly.
    w, t, torque = _truth()
    rng = np.random.default_rng(11)
    noisy = torque * (1.0 + 0.05 * rng.standard_normal(torque.size))
    r = fit_parameters(reference_screw().replace(preload=TRUE_PRELOAD), OIL,
                       MeasuredCurve(w, noisy, "s", temperature=t), ["hysteresis_loss_factor"],
                       parameters={"ball_train_constant": TRUE_CB})  # fmt: skip
    assert not r.estimates["hysteresis_loss_factor"].identified
    assert r.rms_residual == pytest.approx(math.sqrt(np.mean((torque - noisy) ** 2)), rel=1e-9)


def test_identifiability_thresholds() -> None:
    # A log parameter is unidentified when its 95 % interval (+-1.96 sd) spans more than a
    # factor 100 (half-width ln(100)/2 = 2.303); a linear one when it spans its whole range.
    from ballscrew.fit.calibration import FITTABLE, _unidentified

    log_p, lin_p = FITTABLE["preload"], FITTABLE["seal_torque"]
    assert not _unidentified(log_p, 2.30 / 1.96, 10) and _unidentified(log_p, 2.31 / 1.96, 10)
    span = lin_p.high - lin_p.low
    assert not _unidentified(lin_p, 0.99 * span / 3.92, 10)
    assert _unidentified(lin_p, 1.01 * span / 3.92, 10)
    assert _unidentified(lin_p, math.inf, 10)


def test_an_unseen_parameter_does_not_take_a_seen_one_down_with_it() -> None:
    # Hysteresis is invisible under 5 % noise; the ball-train constant is not. Held one at a
    # time, the second is still fitted, with its interval around the truth.
    w, t, torque = _truth()
    rng = np.random.default_rng(11)
    noisy = torque * (1.0 + 0.05 * rng.standard_normal(torque.size))
    r = fit_parameters(reference_screw().replace(preload=TRUE_PRELOAD), OIL,
                       MeasuredCurve(w, noisy, "s", temperature=t),
                       ["hysteresis_loss_factor", "ball_train_constant"])  # fmt: skip
    assert not r.estimates["hysteresis_loss_factor"].identified
    cb = r.estimates["ball_train_constant"]
    assert cb.identified and cb.low is not None and cb.high is not None
    assert cb.low <= TRUE_CB <= cb.high


def test_json_outlier_rows_count_from_one_like_the_warning() -> None:
    _, _, torque = _truth()
    spoiled = torque.copy()
    spoiled[[2, 9]] *= 3.0
    r = _fit(spoiled)
    assert r.as_dict()["outlier_rows"] == [3, 10]
    assert any("rows 3, 10" in w for w in r.warnings)


@pytest.mark.parametrize("k, flagged", [(3.8, False), (4.2, True)])
def test_outlier_threshold_is_four_robust_standard_deviations(k: float, flagged: bool) -> None:
    # Additive readings +-e in turn: the residuals are +-e, so the median absolute deviation
    # is e and the robust standard deviation 1.4826 e (the normal distribution's
    # 1/Phi^-1(3/4)). One reading k robust deviations off is an outlier past k = 4 only;
    # 3.8 and 4.2 stay 5 % clear of the line; the fit moves the residuals by far less.
    _, _, torque = _truth()
    e = 0.01
    signs = np.where(np.arange(torque.size) % 2 == 0, 1.0, -1.0)
    data = torque + e * signs
    data[7] = torque[7] + k * 1.4826 * e * signs[7]
    r = _fit(data)
    assert (r.outliers == (7,)) is flagged, r.outliers


def test_of_two_unseen_directions_the_least_sensitive_parameter_is_held() -> None:
    # One temperature: preload and c_B are nearly collinear and hysteresis is invisible, so
    # the first round sees two unbounded directions. Holding the parameter the torque is
    # least sensitive to (hysteresis) leaves preload and c_B fitted, as without it.
    w, t, torque = _truth()
    keep = t == 20.0
    rng = np.random.default_rng(2)
    data = torque[keep] * (1.0 + 0.03 * rng.standard_normal(int(keep.sum())))
    curve = MeasuredCurve(w[keep], data, "one temperature", temperature=t[keep])
    both = fit_parameters(reference_screw(), OIL, curve, ["preload", "ball_train_constant"])
    free = ["preload", "ball_train_constant", "hysteresis_loss_factor"]
    three = fit_parameters(reference_screw(), OIL, curve, free)
    assert not three.estimates["hysteresis_loss_factor"].identified
    for name in ("preload", "ball_train_constant"):
        assert three.estimates[name].identified
        assert three.estimates[name].value == pytest.approx(both.estimates[name].value, rel=1e-3)


def test_residuals_signs_and_the_correlation_diagonal() -> None:
    # Residuals are model minus measurement: a reading tripled lies far above the fit that
    # leaves it out, so its residual is negative; each parameter correlates with itself by 1.
    _, _, torque = _truth()
    spoiled = torque.copy()
    spoiled[4] *= 3.0
    r = _fit(spoiled)
    assert r.outliers == (4,) and float(r.residuals[4]) < -torque[4]
    np.testing.assert_array_equal(np.diag(r.correlation), 1.0)


@pytest.mark.parametrize("points, warned", [(3, True), (4, True), (5, False)])
def test_few_degrees_of_freedom_warn_below_three(points: int, warned: bool) -> None:
    # Two free parameters: 3 and 4 points leave 1 and 2 degrees of freedom (warned), 5 leave
    # 3 (not).
    w, t, torque = _truth()
    rows = np.linspace(0, torque.size - 1, points).round().astype(int)
    curve = MeasuredCurve(w[rows], torque[rows], "few", temperature=t[rows])
    r = fit_parameters(reference_screw(), OIL, curve, ["preload", "ball_train_constant"])
    assert any("degree(s) of freedom" in x for x in r.warnings) is warned


@pytest.mark.parametrize("spoiled, dropped", [(4, True), (5, False)])
def test_outliers_are_at_most_a_fifth_of_the_points(spoiled: int, dropped: bool) -> None:
    # 24 points: 4 wild readings (17 %) are outliers; 5 (21 %) are more than a fifth, so the
    # model is taken to miss the data's shape and nothing is left out.
    _, _, torque = _truth()
    rng = np.random.default_rng(4)
    data = torque * (1.0 + 0.01 * rng.standard_normal(torque.size))
    data[[1, 6, 11, 16, 21][:spoiled]] *= 3.0
    r = _fit(data)
    assert (len(r.outliers) == spoiled) is dropped
    assert dropped or r.outliers == ()


def test_a_log_parameter_cannot_start_at_zero() -> None:
    w, t, torque = _truth()
    curve = MeasuredCurve(w, torque, "s", temperature=t)
    # A single nut without preload: its preload cannot seed a fit in log space.
    single = reference_screw().replace(nut="single", preload=0.0)
    with pytest.raises(BallScrewInputError, match="positive start value"):
        fit_parameters(single, OIL, curve, ["preload"])


def test_nothing_identifiable_leaves_the_start_and_its_residuals() -> None:
    # The hysteresis factor alone, on data it barely touches: it is held at its start, and
    # the residuals are those of the case as given (model minus measurement, at the case's
    # 2 kN preload and the default ball-train constant) computed here directly.
    w, t, torque = _truth()
    r = _fit(torque, ["hysteresis_loss_factor"])
    assert not r.estimates["hysteresis_loss_factor"].identified
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        start = friction_torque(reference_screw(), OIL, speed=w, temperature=t).total
    np.testing.assert_allclose(r.residuals, start - torque, rtol=1e-9, atol=1e-12)
    assert r.rms_residual == pytest.approx(float(np.sqrt(np.mean((start - torque) ** 2))), 1e-9)
