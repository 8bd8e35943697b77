"""The study report's findings are computed from its series, never fixed sentences."""

from __future__ import annotations

import dataclasses
import re

import numpy as np
import pytest

from ballscrew.io.case import load_case
from ballscrew.study.reproduce import StudyResult, run_study

pytestmark = pytest.mark.slow  # every test reads one whole study run


@pytest.fixture(scope="module")
def study() -> StudyResult:
    return run_study(load_case(None))


def _finding(result: StudyResult, model: str) -> str:
    (line,) = [f for f in result.findings if f.startswith(f"{model}: ")]
    return line


def _expected_relation(torque: np.ndarray, lo: float, hi: float) -> str:
    if np.all(torque < lo):
        return "below"
    if np.all(torque > hi):
        return "above"
    return "inside"


@pytest.mark.parametrize("band", [None, (0.01, 0.02), (5.0, 9.0)])
def test_each_model_finding_states_its_range_and_side_of_the_band(
    study: StudyResult, band: tuple[float, float] | None
) -> None:
    result = study
    if band is not None:  # the same case with another measured band: the words must follow
        case = dataclasses.replace(study.case, measured_range=band)
        result = run_study(case)
    lo, hi = min(result.case.measured_range), max(result.case.measured_range)
    series = {
        s.model: s for s in next(f for f in result.figures if f.key == "fig9_all_models").series
    }
    for model in ("olaru", "viscoelastic", "harris-simplified", "complete"):
        line = _finding(result, model)
        t = np.asarray(series[model].torque)
        low, high = (float(x) for x in re.findall(r"([0-9.e+-]+) to ([0-9.e+-]+) N·m", line)[0])
        assert low == pytest.approx(float(t.min()), rel=5e-3)
        assert high == pytest.approx(float(t.max()), rel=5e-3)
        assert _expected_relation(t, lo, hi) in line, line


def test_complete_model_is_in_fig9_and_its_budget_adds_up(study: StudyResult) -> None:
    figures = {f.key: f for f in study.figures}
    fig9 = {s.model: s for s in figures["fig9_all_models"].series}
    budget = figures["fig11_complete_budget"]
    assert budget.stacked and {s.label for s in budget.series} >= {"rolling", "ball-ball"}
    np.testing.assert_allclose(sum(s.torque for s in budget.series), fig9["complete"].torque,
                               rtol=1e-12)  # fmt: skip
    compare = figures["fig10_simplified_vs_complete"]
    assert [s.model for s in compare.series][-1] == "complete"
    assert not any("harris-full" == s.model for s in compare.series)


def test_no_fixed_claim_that_the_simplified_model_is_low(study: StudyResult) -> None:
    # The old report printed "closest to the measurement but low" beside a curve 3-10 x above
    # the band; only the study's own words may say so, followed by this run's computed answer.
    for line in study.findings:
        if "but low" in line:
            assert line.startswith("The study found") and "the simplified model is" in line


USER_CASE = """
title = "25 x 5 single nut, oversize balls"
[screw]
pitch_diameter = "25.4 mm"
lead = "5 mm"
ball_diameter = "3.175 mm"
nut = "single-4point"
preload = "400 N"
[lubricant]
name = "mineral ISO VG 68"
[operation]
speed = "50..2000:4 rpm"
temperature = "40 degC"
axial_load = "1.5 kN"
"""


def test_a_study_of_another_case_is_that_case_s_study(study: StudyResult, tmp_path: object) -> None:
    from ballscrew import friction_torque
    from ballscrew.io.case import parse_case
    from ballscrew.report.study import write_report

    case = parse_case(USER_CASE)
    result = run_study(case)
    assert not result.reproduction and study.reproduction
    # No measured band of another machine, no statements about the study's findings.
    assert case.measured_range == ()
    assert not any("The study found" in f or "study's finding" in f for f in result.findings)
    # The case's temperature and load are the figures' (not the study's 20 °C and 0 N).
    fig9 = next(f for f in result.figures if f.key == "fig9_all_models")
    complete = next(s for s in fig9.series if s.model == "complete")
    assert complete.temperature == 40.0
    direct = friction_torque(case.screw, case.lubricant, speed=case.speed, temperature=40.0,
                             axial_load=1500.0)  # fmt: skip
    np.testing.assert_allclose(complete.torque, direct.total, rtol=1e-12)
    assert "axial load 1500 N" in fig9.caption and "40 °C" in fig9.caption
    # The preload sweep is the case's own: 0.5, 1 and 1.5 times its 400 N.
    assert sorted(result.preloads.values()) == pytest.approx([200.0, 400.0, 600.0])
    # The report says what it is and draws no band.
    out = tmp_path / "report"  # type: ignore[operator]
    write_report(result, out)
    text = (out / "report.md").read_text(encoding="utf-8")
    assert "Reproduction of" not in text and "Kamalzadeh" not in text and "nan" not in text
    assert "25 x 5 single nut" in text


def test_controller_figure_is_the_stribeck_form_fitted_to_the_complete_curve(
    study: StudyResult,
) -> None:
    # Fig. 12 must show, beside the complete model's curve, Tustin's form evaluated with the
    # parameters printed in its caption; the curve must follow the model within the fit's own
    # stated maximum error (the caption's number, not a tolerance chosen here).
    fig = next(f for f in study.figures if f.key == "fig12_controller")
    model, fitted = fig.series
    assert model.model == "complete" and fitted.model == "stribeck"
    p = fitted.parameters
    w = np.asarray(model.speed_rpm) * np.pi / 30.0
    tc, ts, ws, d, b = (p[k] for k in ("coulomb_torque", "static_torque", "stribeck_speed",
                                       "stribeck_exponent", "viscous_coefficient"))  # fmt: skip
    by_hand = tc + (ts - tc) * np.exp(-(np.abs(w / ws) ** d)) + b * w  # Tustin, written out
    np.testing.assert_allclose(fitted.torque, by_hand, rtol=1e-12)
    assert ts >= tc >= 0.0 and b >= 0.0
    max_error = float(re.search(r"max ([0-9.e+-]+) N·m", fig.caption).group(1))  # type: ignore[union-attr]
    keep = w > 0
    assert np.max(np.abs(fitted.torque[keep] - model.torque[keep])) <= max_error * 1.01


def test_sensitivity_finding_follows_the_indices(study: StudyResult) -> None:
    from ballscrew.study.sensitivity import sensitivity_finding as _sensitivity_finding

    s = study.sensitivity
    assert s is not None and s.evaluations == s.base_samples * (len(s.inputs) + 2)
    (line,) = [f for f in study.findings if f.startswith("Uncertainty of the complete model")]
    top = s.indices.ranking()[0]
    assert f"{s.inputs[top].label} (S_T = {s.indices.total[top]:.2f}" in line
    pre = [u.distribution.name for u in s.inputs].index("screw.preload")
    # The same words must turn when the numbers do: make the preload clearly first ...
    total = np.full(len(s.inputs), 0.05)
    total[pre] = 0.9
    conf = np.full(len(s.inputs), 0.01)
    first = replace_indices(s, total, conf)
    assert "The preload is the leading uncertainty, as the study found" in _sensitivity_finding(
        first, True
    )
    # ... or first but within the interval of the runner-up ...
    total[(pre + 1) % len(total)] = 0.88
    assert "not clearly ahead" in _sensitivity_finding(replace_indices(s, total, conf), True)
    # ... or last.
    total[pre] = 0.0
    text = _sensitivity_finding(replace_indices(s, total, conf), False)
    assert f"rank {len(total)} of {len(total)}" in text and "study" not in text


def replace_indices(s: object, total: np.ndarray, conf: np.ndarray) -> object:
    indices = dataclasses.replace(s.indices, total=total.copy(), total_conf=conf)  # type: ignore[attr-defined]
    return dataclasses.replace(s, indices=indices)  # type: ignore[type-var]


def test_model_parameters_carry_the_units_of_their_docstrings() -> None:
    from ballscrew.report.study import _shown, parameter_units

    # The viscoelastic model documents k [N/m³], m [kg/m²], gamma [N·s/m³].
    units = parameter_units("viscoelastic")
    assert units == {"stiffness": "N/m³", "mass": "kg/m²", "damping": "N·s/m³"}
    assert _shown(3.5e13, units["damping"]) == "3.5e+13 N·s/m³"
    assert _shown("ball-radius", None) == "ball-radius" and _shown(0.0358, "-") == "0.0358"
    assert parameter_units("complete")["return_turning_angle"] == "rad"


def test_the_study_result_is_json_with_every_figure_and_finding(study: StudyResult) -> None:
    import json

    doc = json.loads(json.dumps(study.as_dict()))
    assert [f["key"] for f in doc["figures"]] == [f.key for f in study.figures]
    first = study.figures[0].series[0]
    assert doc["figures"][0]["series"][0]["torque_Nm"] == pytest.approx(first.torque.tolist())
    assert doc["findings"] == list(study.findings)
    if study.sensitivity is not None:
        assert set(doc["sensitivity"]["indices"]) == set(study.sensitivity.indices.names)
