"""How sure a verdict is: P(NOT OK), the utilisation's interval, the guarded verdict."""

from __future__ import annotations

import csv
import itertools
import math
import re
from importlib import resources
from pathlib import Path

import numpy as np
import pytest
from scipy.stats import norm

from ballscrew.axis.check import run_check
from ballscrew.axis.duty import profile_from_move, run_energy
from ballscrew.axis.uncertainty import SAMPLES, judge, model_error
from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import parse_case

X_AXIS = Path(__file__).resolve().parents[1] / "data" / "x_axis_bnfn3210a5.toml"
X_MOVE = {"stroke": 0.8, "feed": 20.0 / 60.0, "acceleration": 2.0, "force": 3000.0,
          "dwell": 0.85}  # fmt: skip
# The standard error of a probability from SAMPLES draws is at most sqrt(0.25 / 4000) = 0.008;
# three of them: 0.024.
MC = 3.0 * math.sqrt(0.25 / SAMPLES)


def _x(check_lines: str = "", model: str = "catalog"):  # type: ignore[no-untyped-def]
    text = X_AXIS.read_text(encoding="utf-8").replace('required_life = "20000 h"\n', check_lines)
    run = run_energy(parse_case(text), profile_from_move(X_MOVE, 1), [model], run_time=600.0,
                     move=X_MOVE)  # fmt: skip
    return run_check(run, model)


def _row(result, name: str):  # type: ignore[no-untyped-def]
    return next(c for c in result.criteria if c.name.startswith(name))


NOMINAL_HOURS = _row(_x(), "fatigue life").value


def test_decision_rule() -> None:
    assert judge(np.full(100, 0.5)).guarded == "OK (95 %)"
    assert judge(np.full(100, 1.5)).guarded == "NOT OK (95 %)"
    u = np.r_[np.full(94, 0.5), np.full(6, 2.0)]
    r = judge(u)
    assert r.p_not_ok == pytest.approx(0.06) and r.guarded == "undecided"
    assert judge(np.r_[np.full(95, 0.5), np.full(5, 2.0)]).guarded == "OK (95 %)"
    assert judge(np.array([math.nan, 0.5])).p_not_ok == 0.5  # NaN fails, never a silent pass


def test_half_at_a_nominal_utilisation_of_one_and_monotonic() -> None:
    # The life is monotonic in the preload and the rating; with a required life equal to the
    # nominal life the median draw sits at the limit: P(NOT OK) = 0.5 up to the Monte Carlo.
    probs = []
    for factor in (0.3, 0.6, 0.95, 1.0, 1.05, 1.6, 3.0):
        lines = (f'required_life = "{NOMINAL_HOURS * factor:.6f} h"\n'
                 'rating_tolerance = "10 %"\n')  # fmt: skip
        row = _row(_x(lines), "fatigue life")
        assert row.utilisation == pytest.approx(factor, rel=1e-6)
        probs.append(row.uncertainty.p_not_ok)
    assert probs[3] == pytest.approx(0.5, abs=MC)
    assert all(a < b for a, b in itertools.pairwise(probs))  # strictly growing
    assert probs[0] < 0.05 and probs[-1] > 0.95


def test_monte_carlo_against_the_closed_form_of_a_uniform_rating() -> None:
    # Only the rating uncertain, k uniform on [0.9, 1.1]: u = u0 / k^3, so
    # P(u > 1) = P(k < u0^(1/3)) = (u0^(1/3) - 0.9) / 0.2, and the utilisation's 2.5 % and
    # 97.5 % quantiles are u0 / k(97.5 %)^3 and u0 / k(2.5 %)^3.
    u0 = 1.1
    lines = (f'required_life = "{NOMINAL_HOURS * u0:.6f} h"\nrating_tolerance = "10 %"\n'
             'preload_tolerance = "0 %"\n')  # fmt: skip
    row = _row(_x(lines), "fatigue life")
    exact = (u0 ** (1 / 3) - 0.9) / 0.2
    assert row.uncertainty.p_not_ok == pytest.approx(exact, abs=MC)
    k = 0.9 + 0.2 * np.array([0.975, 0.025])
    low, high = u0 / k**3
    # 1 %: the quantiles of 4000 draws of a smooth distribution.
    assert row.uncertainty.low == pytest.approx(low, rel=1e-2)
    assert row.uncertainty.high == pytest.approx(high, rel=1e-2)


def test_the_model_error_reaches_the_thermal_verdict_as_a_log_normal() -> None:
    # The lead error is alpha dT 300 mm with dT scaled by the friction factor
    # exp(-b + N(0, s)): P(u > 1) = Phi((ln u0 - b) / s) exactly (no pre-tension); the bias
    # moves the median to u0 exp(-b), the scatter widens it.
    result = _x('required_life = "20000 h"\naccuracy_grade = "C5"\n', model="complete")
    row = _row(result, "thermal lead error")
    error = model_error("complete", "double", 0.3)
    sigma, bias = error.sigma, error.bias
    assert any("sigma(ln T) = " + f"{sigma:.3g}" in a for a in result.assumptions)
    exact = norm.cdf((math.log(row.utilisation) - bias) / sigma)
    assert row.uncertainty.p_not_ok == pytest.approx(exact, abs=MC)
    lo, hi = row.utilisation * np.exp(norm.ppf([0.025, 0.975]) * sigma - bias)
    assert row.uncertainty.low == pytest.approx(lo, rel=3e-2)  # tails of 4000 draws
    assert row.uncertainty.high == pytest.approx(hi, rel=3e-2)


def test_every_row_with_a_limit_carries_its_probability_in_json() -> None:
    doc = _x().as_dict()
    for c in doc["criteria"]:
        if c["utilisation"] is None:
            assert c["p_not_ok"] is None and c["guarded_verdict"] is None
        else:
            assert 0.0 <= c["p_not_ok"] <= 1.0
            low, high = c["utilisation_95"]
            assert low <= high
            assert c["guarded_verdict"] in ("OK (95 %)", "NOT OK (95 %)", "undecided")
    speed = next(c for c in doc["criteria"] if c["name"].startswith("speed"))
    assert speed["utilisation_95"] == [speed["utilisation"]] * 2  # no uncertain input


def test_the_shipped_model_error_is_the_scorecards_printed_rows() -> None:
    # Provenance: the data file's row is the scorecard's own test rows against the makers'
    # printed rule, recomputed here; the bias (mean) and the scatter (sd) are kept apart.
    from ballscrew.study.validation import score

    rows = [r for r in score(["complete"], trends=False)
            if r.kind == "catalog" and r.nut == "double" and r.reference < 1.0
            and not r.training]  # fmt: skip
    logs = np.log10([r.predicted / r.reference for r in rows])
    bands = np.array([(r.high - r.low) / (2.0 * r.reference) for r in rows])
    text = resources.files("ballscrew").joinpath("data/model_scatter.csv").read_text("utf-8")
    data = list(csv.DictReader(line for line in text.splitlines() if not line.startswith("#")))
    shipped = next(d for d in data if d["model"] == "complete" and d["reference"] == "printed"
                   and d["nut"] == "double" and d["level"] == "below 1 N*m"
                   and d["role"] == "test")  # fmt: skip
    n = logs.size
    assert int(shipped["rows"]) == n == 37
    assert float(shipped["mean_log10"]) == pytest.approx(np.mean(logs), abs=1e-4)
    assert float(shipped["sd_log10"]) == pytest.approx(np.std(logs, ddof=1), abs=1e-4)
    ref = np.sqrt(np.mean((bands / math.sqrt(3.0)) ** 2)) / math.log(10.0)
    assert float(shipped["reference_sd_log10"]) == pytest.approx(ref, abs=1e-4)
    error = model_error("complete", "double", 0.3)
    assert error.bias == pytest.approx(np.mean(logs) * math.log(10.0), abs=3e-4)
    expected = math.sqrt(np.var(logs, ddof=1) * (1 + 1 / n) + ref**2) * math.log(10.0)
    assert error.sigma == pytest.approx(expected, abs=1e-3)
    assert "printed" in error.text and "no measured rows" in error.text
    # Jungnickel's rows are a law: labelled so, never the check's error, shown only from
    # 1000 rpm on (where the law holds).
    assert not any(d["reference"] == "measured" for d in data)
    assert all(d["speed"] == "1000-3000 rpm" for d in data if d["reference"] == "law")
    assert "Jungnickel" not in error.text
    fast = model_error("complete", "double", 0.3, speed=2000.0)
    assert (fast.sigma, fast.bias) == (error.sigma, error.bias)
    assert "a law, not a measurement" in fast.text and "not counted" in fast.text
    # The nut the model fits better gets the narrower interval: the double nut's scatter
    # about its bias is below the 4-point nut's.
    four = model_error("complete", "single-4point", 0.3)
    assert error.sigma < four.sigma
    assert math.isnan(model_error("olaru", "double", 0.3).sigma)


@pytest.mark.parametrize("key", ["preload_tolerance", "rating_tolerance", "mass_tolerance",
                                 "force_tolerance"])  # fmt: skip
def test_a_tolerance_of_100_percent_or_more_is_refused(key: str) -> None:
    text = X_AXIS.read_text(encoding="utf-8").replace("[check]\n", f'[check]\n{key} = "100 %"\n')
    with pytest.raises(BallScrewInputError, match=rf"check\.{key}"):
        parse_case(text)


def test_an_assumed_value_carries_its_own_range() -> None:
    # The fixture's C_0a is assumed; given a range there, it stands in for rating_tolerance.
    text = X_AXIS.read_text(encoding="utf-8")
    ranged = text.replace('assumed = "twice BIF3210A-5', 'tolerance = "10 %", assumed = "twice '
                          "BIF3210A-5")  # fmt: skip
    ranged = ranged.replace('moving_mass = "500 kg"', 'moving_mass = { value = "500 kg", '
                            'assumed = "slide and vice", tolerance = "20 %" }')  # fmt: skip
    stated = text.replace("[check]\n", '[check]\nrating_tolerance = "10 %"\n'
                          'mass_tolerance = "20 %"\n')  # fmt: skip
    results = []
    for case_text in (ranged, stated):
        run = run_energy(parse_case(case_text), profile_from_move(X_MOVE, 1), ["catalog"],
                         run_time=600.0, move=X_MOVE)  # fmt: skip
        results.append(run_check(run, "catalog"))
    for name in ("fatigue life", "static safety", "lift-off"):
        a, b = (_row(r, name).uncertainty for r in results)
        assert (a.p_not_ok, a.low, a.high) == (b.p_not_ok, b.low, b.high), name
    assert any("rating tolerance +-10% from the range of the assumed screw.static_load_rating"
               in n for n in results[0].assumptions)  # fmt: skip
    wide, narrow = _row(results[0], "static safety").uncertainty, _row(_x(), "static safety")
    assert wide.high - wide.low > narrow.uncertainty.high - narrow.uncertainty.low


def test_an_assumed_range_of_100_percent_is_refused() -> None:
    text = X_AXIS.read_text(encoding="utf-8").replace(
        'assumed = "twice BIF3210A-5', 'tolerance = "100 %", assumed = "twice BIF3210A-5'
    )
    with pytest.raises(BallScrewInputError, match=r"screw\.static_load_rating\.tolerance"):
        parse_case(text)


def test_the_distinct_samples_give_the_sample_by_sample_probabilities(
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    # The Monte Carlo takes the samples that share their forces (or torques) once, with
    # their turns (or weights) added: the cruise, the dwell and each constant
    # acceleration of the move. Against every sample taken on its own (the grouping
    # switched off), with tolerances on every input: the same probabilities, the
    # intervals equal to the rounding of sums taken in another order.
    from ballscrew.axis import check as check_module

    lines = ('required_life = "20000 h"\nrating_tolerance = "10 %"\nmass_tolerance = "20 %"\n'
             'force_tolerance = "15 %"\n')  # fmt: skip
    grouped = _x(lines, model="complete")

    def every_sample(keys, sums):  # type: ignore[no-untyped-def]
        return (*(np.asarray(k, dtype=float).reshape(-1) for k in keys),
                *(np.asarray(w, dtype=float).reshape(-1) for w in sums))  # fmt: skip

    monkeypatch.setattr(check_module, "_distinct_samples", every_sample)
    alone = _x(lines, model="complete")
    compared = 0
    for a, b in zip(grouped.criteria, alone.criteria, strict=True):
        assert a.name == b.name
        if a.uncertainty is None:
            assert b.uncertainty is None
            continue
        assert b.uncertainty is not None
        assert a.uncertainty.p_not_ok == b.uncertainty.p_not_ok, a.name
        assert a.uncertainty.guarded == b.uncertainty.guarded
        np.testing.assert_allclose([a.uncertainty.low, a.uncertainty.high],
                                   [b.uncertainty.low, b.uncertainty.high], rtol=1e-12)  # fmt: skip
        compared += 1
    assert compared >= 5  # life, static safety, torques, inertia, thermal error at least


def test_the_default_preload_band_says_what_it_does_to_the_life_row() -> None:
    # Without check.preload_tolerance the preload takes the makers' C3 band (+-30 % at this
    # nut's 0.61 N*m); the note's two ends are the life row's utilisation at the preload
    # 30 % lower and higher, which a whole check of the case with that preload gives too.
    result = _x('required_life = "20000 h"\n')
    note = next(a for a in result.assumptions if "default preload band alone" in a)
    low, high = (
        float(x) for x in re.findall(r"utilisation from ([\d.]+) .* to ([\d.]+) ", note)[0]
    )
    nominal = _row(result, "fatigue life").utilisation
    base = X_AXIS.read_text(encoding="utf-8")
    for value, preload in ((low, "1652 N"), (high, "3068 N")):  # 2360 N x (1 -+ 0.3)
        text = base.replace('preload = "2360 N"', f'preload = "{preload}"')
        run = run_energy(parse_case(text), profile_from_move(X_MOVE, 1), ["catalog"],
                         run_time=600.0, move=X_MOVE)  # fmt: skip
        # 3 digits: the note prints 3 significant digits.
        assert _row(run_check(run, "catalog"), "fatigue life").utilisation == pytest.approx(
            value, rel=5e-3
        )
    assert low < nominal < high
    given = _x('required_life = "20000 h"\npreload_tolerance = "10 %"\n')
    assert not any("default preload band" in a for a in given.assumptions)
