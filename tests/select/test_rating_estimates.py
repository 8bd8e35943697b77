"""The estimated load ratings against the makers' printed ones and the bearing standards' tables.

Every bundled catalogue row that prints its ball diameter, circuits and loaded
turns and both ratings is rebuilt here from the CSV's own columns (45 deg and
the makers' groove, ``RATING_CONFORMITY``) and its estimated C_a and C_0a set
against the printed values: their median ratio, and the slope of
ln(estimated/printed) against ln(number of loaded turns), which a wrong turn
exponent shows as a trend (the rows hold 2 to 5 loaded turns). The printed
ratings are the independent reference; no number here comes from the code's
own summary (``rating_scatter``). The groove was fitted once on ten of the rows;
the fit is redone here and checked on the rows it did not see. The two pieces
of the bearing standards the estimates rest on are checked against the
standards' printed tables: ISO 281's f_c of a thrust ball bearing row and
ISO 76's f_0 (4200 MPa).
"""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest

from ballscrew.design.ratings import (
    RATING_CONFORMITY,
    dynamic_rating_estimate,
    static_rating_estimate,
)
from ballscrew.geometry import BallScrew
from shared import ROOT

CSV = ROOT / "src" / "ballscrew" / "data" / "catalog_screws.csv"


def _rows() -> list[dict[str, str]]:
    """The catalogue rows that print the ball, circuits, turns and both ratings."""
    lines = [ln for ln in CSV.read_text(encoding="utf-8").splitlines() if not ln.startswith("#")]
    fields = ("ball_diameter_mm", "circuits", "turns_per_circuit", "dynamic_load_rating_N",
              "static_load_rating_N")  # fmt: skip
    return [row for row in csv.DictReader(lines) if all(row[f].strip() for f in fields)]


def _screw(row: dict[str, str], conformity: float = RATING_CONFORMITY) -> BallScrew:
    d = float(row["pitch_diameter_mm"] or row["nominal_diameter_mm"]) * 1e-3
    return BallScrew(d, float(row["lead_mm"]) * 1e-3, float(row["ball_diameter_mm"]) * 1e-3,
                     math.radians(45.0), conformity, conformity, float(row["turns_per_circuit"]),
                     int(row["circuits"]), "single")  # fmt: skip


def _ratios(
    rows: list[dict[str, str]] | None = None, conformity: float = RATING_CONFORMITY
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """ln(loaded turns), C_a and C_0a estimated/printed over ``rows`` (all with geometry)."""
    turns, dynamic, static = [], [], []
    for row in _rows() if rows is None else rows:
        screw = _screw(row, conformity)
        turns.append(math.log(screw.loaded_turns * screw.circuits))
        dynamic.append(dynamic_rating_estimate(screw) / float(row["dynamic_load_rating_N"]))
        static.append(static_rating_estimate(screw) / float(row["static_load_rating_N"]))
    return np.array(turns), np.array(dynamic), np.array(static)


def _slope(ln_turns: np.ndarray, ratio: np.ndarray) -> float:
    """Least-squares slope of ln(ratio) against ln(turns)."""
    return float(np.polyfit(ln_turns, np.log(ratio), 1)[0])


def _cassette_single_nuts(small: bool) -> list[dict[str, str]]:
    """HIWIN's cassette single nuts (FSC), of 14 to 32 mm (``small``) or of 40 to 63 mm."""
    return [
        r for r in _rows()
        if r["designation"].endswith("-FSC") and (float(r["nominal_diameter_mm"]) <= 32) == small
    ]  # fmt: skip


def test_the_rows_with_geometry_span_two_to_five_loaded_turns() -> None:
    k, dynamic, _ = _ratios()
    assert len(dynamic) == 25
    assert np.exp(k).min() == pytest.approx(2.0) and np.exp(k).max() == pytest.approx(5.0)


def test_the_estimated_dynamic_rating_has_the_printed_median() -> None:
    # Issue 48's bound, 0.95 to 1.05. Measured 0.956 (16 to 84 %: 0.94 to 1.00).
    _, dynamic, _ = _ratios()
    assert 0.95 <= float(np.median(dynamic)) <= 1.05


def test_the_estimated_static_rating_has_the_printed_median() -> None:
    # Issue 48's bound, 0.9 to 1.1. Measured 1.02 (16 to 84 %: 0.98 to 1.08); 0.68 at the
    # package's friction default 0.55, whose looser grooves the 4200 MPa limit lets carry less.
    _, _, static = _ratios()
    assert 0.9 <= float(np.median(static)) <= 1.1


def test_the_dynamic_rating_s_trend_with_the_turns_is_small() -> None:
    # With ISO 281's 0.7 the ratio fell by -0.23 per unit of ln(turns); with 0.86 the slope
    # is -0.052 (the rows of two turns, long leads, sit 5 to 8 % above those of four and
    # five). Four times smaller; the bound is 0.05, below.
    k, dynamic, _ = _ratios()
    assert abs(_slope(k, dynamic)) < 0.06


@pytest.mark.xfail(
    strict=True,
    reason="issue 48 target |slope| < 0.05 not reached: -0.052. The rows of two turns all "
    "have 16 to 40 mm leads; over the 18 single nuts ln(turns) and ln(cos lead angle) "
    "correlate at 0.96, so the rows cannot tell a turn exponent from a lead-angle term "
    "(both in one regression: turns +0.04). Needs rows of two turns at short leads, or the "
    "standard's count of a turn's balls: counted on the ball circle (pi d_m / D_w, as a "
    "bearing row's; the helix holds 1/cos(lead angle) more) both slopes fall under 0.05 "
    "(C_a -0.016, C_0a +0.014), not adopted without the standard's text.",
)
def test_the_dynamic_rating_has_no_trend_with_the_turns() -> None:
    k, dynamic, _ = _ratios()
    assert abs(_slope(k, dynamic)) < 0.05


def test_the_static_rating_has_no_trend_with_the_turns() -> None:
    # C_0a grows as the balls, z sin(alpha) cos(phi): no exponent on the turns to get wrong
    # (measured -0.041, the lead angles' correlation with the turns).
    k, _, static = _ratios()
    assert abs(_slope(k, static)) < 0.05


def test_the_groove_refits_from_its_training_rows_and_holds_on_the_others() -> None:
    # RATING_CONFORMITY's fit redone: the conformity minimising the squared ln ratios of
    # both ratings over HIWIN's ten FSC nuts of 14 to 32 mm is 0.5263 (to the 1e-4 grid
    # here), kept as 0.526. On the eight FSC nuts of 40 to 63 mm, which it did not see,
    # both medians stay within issue 48's bounds: C_a 0.9503 (at the bound's edge) and C_0a
    # 1.02, with a scatter of ln below 0.05 for each (0.021, 0.041).
    train = _cassette_single_nuts(small=True)
    held = _cassette_single_nuts(small=False)
    assert (len(train), len(held)) == (10, 8)
    grid = np.arange(0.5200, 0.5320, 0.0001)
    cost = [float(np.sum(np.log(np.concatenate(_ratios(train, f)[1:])) ** 2)) for f in grid]
    assert grid[int(np.argmin(cost))] == pytest.approx(RATING_CONFORMITY, abs=5e-4)
    _, dynamic, static = _ratios(held)
    assert 0.95 <= float(np.median(dynamic)) <= 1.05
    assert 0.9 <= float(np.median(static)) <= 1.1
    assert np.std(np.log(dynamic), ddof=1) < 0.05 and np.std(np.log(static), ddof=1) < 0.05


def test_each_rating_alone_asks_nearly_the_same_groove() -> None:
    # One groove explains both ratings: fitted to C_a alone the training rows ask 0.5245,
    # to C_0a alone 0.527. Were the thrust-row reduction missing from C_a (it is 0.724), the
    # C_a fit would ask a groove looser than 0.54 while C_0a kept asking 0.527.
    train = _cassette_single_nuts(small=True)
    grid = np.arange(0.5150, 0.5450, 0.0001)
    ratios = [_ratios(train, f) for f in grid]
    best = [grid[int(np.argmin([np.sum(np.log(r[j]) ** 2) for r in ratios]))] for j in (1, 2)]
    assert abs(best[0] - best[1]) < 0.005


@pytest.mark.parametrize(
    ("alpha", "gamma", "printed"),
    [(45, 0.02, 51.7), (45, 0.05, 67.3), (45, 0.10, 79.7), (60, 0.02, 48.1),
     (60, 0.05, 62.6), (60, 0.10, 74.2), (75, 0.05, 59.7), (75, 0.10, 70.7)],
)  # fmt: skip
def test_a_loaded_turn_is_rated_as_iso_281_rates_a_thrust_ball_bearing_row(
    alpha: float, gamma: float, printed: float
) -> None:
    # ISO 281's f_c for thrust ball bearings (ANSI/ABMA 9 the same; Machinery's Handbook,
    # 31st ed., "Values of f_c for Thrust Ball Bearings"): C_a = f_c (cos a)^0.7 tan a
    # Z^(2/3) D_w^1.8 for one row, grooves of 0.54 D_w. One turn of one circuit is one row;
    # the lead angle's (cos phi)^1.3 is divided out. Within 0.2 %: the table's three figures
    # (0.1 % at 50) and THRUST_ROW_FACTOR's three (0.05 %); measured 0.1 % at most.
    d_w = 3.175e-3
    a = math.radians(alpha)
    screw = BallScrew(d_w * math.cos(a) / gamma, 4e-3, d_w, a, 0.54, 0.54, 1.0, 1, "single")
    z = screw.balls_per_circuit
    c_row = dynamic_rating_estimate(screw) / math.cos(screw.lead_angle) ** 1.3
    f_c = c_row / (math.cos(a) ** 0.7 * math.tan(a) * z ** (2 / 3) * (d_w * 1e3) ** 1.8)
    assert f_c == pytest.approx(printed, rel=0.002)


def test_the_4200_mpa_limit_gives_iso_76_s_thrust_bearing_f0() -> None:
    # ISO 76's f_0 of thrust ball bearings (4200 MPa, grooves of 0.54 D_w; C_0a = f_0 Z D_w^2
    # sin a, so f_0 = Q_0 / D_w^2 in N/mm^2): 57.5, 53.5, 49.6 and 45.7 at ball-position
    # ratios 0.05, 0.10, 0.15 and 0.20. The estimate is 0.972 of each: a level 3 % below
    # (the table's elastic constants are not at hand) and the table's fall with the ratio
    # to 0.2 %.
    d_w = 3.175e-3
    share = []
    for gamma, f_0 in ((0.05, 57.5), (0.10, 53.5), (0.15, 49.6), (0.20, 45.7)):
        screw = BallScrew(d_w * math.cos(math.pi / 4) / gamma, 4e-3, d_w, math.pi / 4, 0.54,
                          0.54, 1.0, 1, "single")  # fmt: skip
        per_ball = static_rating_estimate(screw) / (
            screw.balls_per_nut * math.sin(screw.contact_angle) * math.cos(screw.lead_angle)
        )
        share.append(per_ball / (d_w * 1e3) ** 2 / f_0)
    assert 0.96 <= min(share) and max(share) <= 0.99
    assert max(share) - min(share) < 0.002
