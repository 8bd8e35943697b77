"""The estimated load ratings against the makers' printed ones, read from the CSV itself.

Every bundled catalogue row that prints its ball diameter, circuits and loaded
turns and both ratings is rebuilt here from the CSV's own columns (45 deg and
conformity 0.55, the estimates' documented geometry) and its estimated C_a and
C_0a set against the printed values: their median ratio, and the slope of
ln(estimated/printed) against ln(number of loaded turns), which a wrong turn
exponent shows as a trend (the rows hold 2 to 5 loaded turns). The printed
ratings are the independent reference; no number here comes from the code's
own summary (``rating_scatter``).
"""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest

from ballscrew.design.ratings import dynamic_rating_estimate, static_rating_estimate
from ballscrew.geometry import BallScrew
from shared import ROOT

CSV = ROOT / "src" / "ballscrew" / "data" / "catalog_screws.csv"


def _ratios() -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """ln(loaded turns), C_a and C_0a estimated/printed over the rows with geometry."""
    lines = [ln for ln in CSV.read_text(encoding="utf-8").splitlines() if not ln.startswith("#")]
    turns, dynamic, static = [], [], []
    for row in csv.DictReader(lines):
        fields = ("ball_diameter_mm", "circuits", "turns_per_circuit", "dynamic_load_rating_N",
                  "static_load_rating_N")  # fmt: skip
        if any(not row[f].strip() for f in fields):
            continue
        d = float(row["pitch_diameter_mm"] or row["nominal_diameter_mm"]) * 1e-3
        screw = BallScrew(d, float(row["lead_mm"]) * 1e-3, float(row["ball_diameter_mm"]) * 1e-3,
                          math.radians(45.0), 0.55, 0.55, float(row["turns_per_circuit"]),
                          int(row["circuits"]), "single")  # fmt: skip
        turns.append(math.log(screw.loaded_turns * screw.circuits))
        dynamic.append(dynamic_rating_estimate(screw) / float(row["dynamic_load_rating_N"]))
        static.append(static_rating_estimate(screw) / float(row["static_load_rating_N"]))
    return np.array(turns), np.array(dynamic), np.array(static)


def _slope(ln_turns: np.ndarray, ratio: np.ndarray) -> float:
    """Least-squares slope of ln(ratio) against ln(turns)."""
    return float(np.polyfit(ln_turns, np.log(ratio), 1)[0])


def test_the_rows_with_geometry_span_two_to_five_loaded_turns() -> None:
    k, dynamic, _ = _ratios()
    assert len(dynamic) == 25
    assert np.exp(k).min() == pytest.approx(2.0) and np.exp(k).max() == pytest.approx(5.0)


def test_the_estimated_dynamic_rating_has_the_printed_median() -> None:
    # ISO 3408-5's turn exponent 0.86: median 1.03 (0.82 with ISO 281's 0.7)
    _, dynamic, _ = _ratios()
    assert 0.95 <= float(np.median(dynamic)) <= 1.05


def test_the_dynamic_rating_s_trend_with_the_turns_is_small() -> None:
    # With ISO 281's 0.7 the ratio fell by -0.23 per unit of ln(turns); with 0.86 the slope
    # is -0.052 (the rows of two turns, long leads, sit 5 to 8 % above those of four and
    # five). Four times smaller; the bound is 0.05, below.
    k, dynamic, _ = _ratios()
    assert abs(_slope(k, dynamic)) < 0.06


@pytest.mark.xfail(strict=True, reason="issue 48 target |slope| < 0.05 not reached: -0.052")
def test_the_dynamic_rating_has_no_trend_with_the_turns() -> None:
    k, dynamic, _ = _ratios()
    assert abs(_slope(k, dynamic)) < 0.05


@pytest.mark.xfail(
    strict=True,
    reason="issue 48 target 0.9-1.1 not reached: C_0a median 0.68 "
    "(the 4200 MPa definition at conformity 0.55; the makers' grooves are closer)",
)
def test_the_estimated_static_rating_has_the_printed_median() -> None:
    _, _, static = _ratios()
    assert 0.9 <= float(np.median(static)) <= 1.1


def test_the_static_rating_has_no_trend_with_the_turns() -> None:
    # C_0a grows as the balls, z sin(alpha) cos(phi): no exponent on the turns to get wrong
    k, _, static = _ratios()
    assert abs(_slope(k, static)) < 0.05
