"""The estimated load ratings against the makers' printed ones and the bearing standards' tables.

Every bundled catalogue row that prints its ball diameter, circuits and loaded
turns and both ratings is rebuilt here from the CSV's own columns (45 deg and
the makers' groove, ``RATING_CONFORMITY``) and its estimated C_a and C_0a set
against the printed values: their median ratio, and the slope of
ln(estimated/printed) against ln(number of loaded turns), which a wrong turn
exponent, or a wrong fall with the lead angle (the rows of two turns are the
steep ones), shows as a trend (the rows hold 2 to 5 loaded turns). The printed
ratings are the independent reference; no number here comes from the code's
own summary (``rating_scatter``). The groove was fitted once on ten of the rows;
the fit is redone here and checked on the rows it did not see. The two pieces
of the bearing standards the estimates rest on are checked against the
standards' printed tables: ISO 281's f_c of a thrust ball bearing row and
ISO 76's f_0 (4200 MPa), each with a row's balls counted on its pitch circle,
as the estimates count a turn's (``rating_balls_per_circuit``).
"""

from __future__ import annotations

import csv
import math

import numpy as np
import pytest

from ballscrew.design.ratings import (
    RATING_CONFORMITY,
    dynamic_rating_estimate,
    rating_balls_per_circuit,
    static_rating_estimate,
)
from ballscrew.errors import BallScrewInputError
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
    # Issue 48's bound, 0.95 to 1.05. Measured 0.962 (16 to 84 %: 0.95 to 0.99); 0.956 with
    # a turn's balls counted along the helix at its groove then, 0.526.
    _, dynamic, _ = _ratios()
    assert 0.95 <= float(np.median(dynamic)) <= 1.05


def test_the_estimated_static_rating_has_the_printed_median() -> None:
    # Issue 48's bound, 0.9 to 1.1. Measured 1.015 (16 to 84 %: 1.00 to 1.09); 0.66 at the
    # package's friction default 0.55, whose looser grooves the 4200 MPa limit lets carry less.
    _, _, static = _ratios()
    assert 0.9 <= float(np.median(static)) <= 1.1


def test_the_dynamic_rating_has_no_trend_with_the_turns() -> None:
    # Issue 48's bound, |slope| < 0.05 in ln(turns). Measured -0.016. With a turn's balls
    # counted along the helix it was -0.052 (the rows of two turns, all of long leads, sat
    # 5 to 8 % above those of four and five), with ISO 281's turn exponent 0.7 -0.18 (-0.23
    # with the helix's count). The rows cannot tell the turns from the lead angle (over the
    # 18 single nuts ln k and ln cos(phi) correlate at 0.96); the two tests below separate
    # them at one geometry.
    k, dynamic, _ = _ratios()
    assert abs(_slope(k, dynamic)) < 0.05


def test_the_static_rating_has_no_trend_with_the_turns() -> None:
    # C_0a grows as the balls, z sin(alpha) cos(phi): no exponent on the turns to get wrong.
    # Measured +0.014 (-0.041 with the helix's count, the lead angles' correlation with the
    # turns).
    k, _, static = _ratios()
    assert abs(_slope(k, static)) < 0.05


def test_the_groove_refits_from_its_training_rows_and_holds_on_the_others() -> None:
    # RATING_CONFORMITY's fit redone: the conformity minimising the squared ln ratios of
    # both ratings over HIWIN's ten FSC nuts of 14 to 32 mm is 0.5251 (to the 1e-4 grid
    # here), kept as 0.525 (0.5263 with the helix's count of a turn's balls). On the eight
    # FSC nuts of 40 to 63 mm, which it did not see, both medians stay within issue 48's
    # bounds: C_a 0.960 and C_0a 1.013 (with the helix's count C_a was 0.9503, at the
    # bound's edge), with a standard deviation of ln below 0.05 for each (measured 0.012
    # and 0.040; 0.021 and 0.041 with the helix's count).
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
    # One groove explains both ratings: fitted to C_a alone the training rows ask 0.5234,
    # to C_0a alone 0.5259. Were the thrust-row reduction missing from C_a (it is 0.724), the
    # C_a fit would ask a groove looser than 0.54 while C_0a kept asking 0.526.
    train = _cassette_single_nuts(small=True)
    grid = np.arange(0.5150, 0.5450, 0.0001)
    ratios = [_ratios(train, f) for f in grid]
    best = [grid[int(np.argmin([np.sum(np.log(r[j]) ** 2) for r in ratios]))] for j in (1, 2)]
    assert abs(best[0] - best[1]) < 0.005


def _row_screw(alpha: float, gamma: float, steep: bool) -> BallScrew:
    """One circuit of one turn at ISO's grooves (0.54 D_w) and ball-position ratio ``gamma``.

    Of 4 mm lead, or ``steep``: a lead of half the pitch circle (lead angle 26.6 deg, whose
    helix holds 1/cos = 1.118 times the balls of the ball circle, 1 to 13 more here).
    """
    d_w = 3.175e-3
    d_m = d_w * math.cos(alpha) / gamma
    return BallScrew(d_m, math.pi * d_m / 2 if steep else 4e-3, d_w, alpha, 0.54, 0.54, 1.0, 1,
                     "single")  # fmt: skip


def _balls_of_a_row(screw: BallScrew) -> int:
    """The balls of a full bearing row of the screw's pitch circle: ISO 281's and ISO 76's Z."""
    return math.floor(math.pi * screw.pitch_diameter / screw.ball_diameter)


@pytest.mark.parametrize("steep", [False, True])
@pytest.mark.parametrize(
    ("alpha", "gamma", "printed"),
    [(45, 0.02, 51.7), (45, 0.05, 67.3), (45, 0.10, 79.7), (60, 0.02, 48.1),
     (60, 0.05, 62.6), (60, 0.10, 74.2), (75, 0.05, 59.7), (75, 0.10, 70.7)],
)  # fmt: skip
def test_a_loaded_turn_is_rated_as_iso_281_rates_a_thrust_ball_bearing_row(
    alpha: float, gamma: float, printed: float, steep: bool
) -> None:
    # ISO 281's f_c for thrust ball bearings (ANSI/ABMA 9 the same; Machinery's Handbook,
    # 31st ed., "Values of f_c for Thrust Ball Bearings"): C_a = f_c (cos a)^0.7 tan a
    # Z^(2/3) D_w^1.8 for one row of Z balls on its pitch circle, grooves of 0.54 D_w. One
    # turn of one circuit is one row of the balls its pitch circle holds; the lead angle's
    # (cos phi)^1.3 is divided out. At 4 mm lead the helix holds the same whole number of
    # balls; at the steep lead it holds 1.118 times as many, which, counted, would put f_c
    # 6 to 9 % high (the whole numbers' ratio to the 2/3): the count of a turn's balls is
    # the row's. Within 0.2 %: the
    # table's three figures (0.1 % at 50) and THRUST_ROW_FACTOR's three (0.05 %); measured
    # 0.1 % at most.
    screw = _row_screw(math.radians(alpha), gamma, steep)
    a, d_w = screw.contact_angle, screw.ball_diameter
    z = _balls_of_a_row(screw)
    assert (z < screw.balls_per_circuit) == steep
    c_row = dynamic_rating_estimate(screw) / math.cos(screw.lead_angle) ** 1.3
    f_c = c_row / (math.cos(a) ** 0.7 * math.tan(a) * z ** (2 / 3) * (d_w * 1e3) ** 1.8)
    assert f_c == pytest.approx(printed, rel=0.002)


@pytest.mark.parametrize("steep", [False, True])
def test_the_4200_mpa_limit_gives_iso_76_s_thrust_bearing_f0(steep: bool) -> None:
    # ISO 76's f_0 of thrust ball bearings (4200 MPa, grooves of 0.54 D_w; C_0a = f_0 Z D_w^2
    # sin a for a row of Z balls on its pitch circle, so f_0 = Q_0 / D_w^2 in N/mm^2): 57.5,
    # 53.5, 49.6 and 45.7 at ball-position ratios 0.05, 0.10, 0.15 and 0.20. The estimate is
    # 0.972 of each: a level 3 % below (the table's elastic constants are not at hand) and
    # the table's fall with the ratio to 0.2 %. At the steep lead (the f_c test's) the
    # helix holds 1.118 times the row's balls; counted, the share would be 1.06 to 1.11.
    d_w = 3.175e-3
    share = []
    for gamma, f_0 in ((0.05, 57.5), (0.10, 53.5), (0.15, 49.6), (0.20, 45.7)):
        screw = _row_screw(math.pi / 4, gamma, steep)
        per_ball = static_rating_estimate(screw) / (
            _balls_of_a_row(screw) * math.sin(screw.contact_angle) * math.cos(screw.lead_angle)
        )
        share.append(per_ball / (d_w * 1e3) ** 2 / f_0)
    assert 0.96 <= min(share) and max(share) <= 0.99
    assert max(share) - min(share) < 0.002


# HIWIN's ground flange single nuts with internal single recirculation (FSI): families of one
# size and lead that differ only in their circuits, {circuits: (C_a, C_0a) [N]} as printed in
# HIWIN GmbH, Ballscrews & Accessories, BS-08-2-EN-1704-K, pp. 52-53, Table 6.6. Keys: nominal
# diameter and lead [mm]. None: a C_0a printed with its digits out of place (10,117 and
# 21,118 N, where the same nuts in the double-nut Table 6.7 print 101,170 and 211,180).
FSI_FAMILIES = {
    (16, 5): {3: (7310, 13310), 4: (9360, 17750)},
    (20, 2): {4: (3990, 11120), 6: (5180, 15510)},
    (20, 5): {3: (8520, 17670), 4: (10910, 23560)},
    (25, 2): {3: (3090, 9800), 4: (3950, 13070), 6: (5600, 19600)},
    (25, 5): {3: (9770, 23140), 4: (12520, 30850), 5: (15160, 38560), 6: (17730, 46270)},
    (25, 10): {3: (15910, 32360), 4: (20380, 43150)},
    (32, 5): {3: (11170, 30810), 4: (14310, 41080), 6: (20270, 61620)},
    (32, 10): {3: (25390, 53270), 4: (32520, 71020)},
    (40, 5): {4: (15990, 52800), 6: (22650, 79190)},
    (40, 10): {3: (29590, 70690), 4: (37890, 94260)},
    (50, 5): {4: (17570, 67450), 6: (24900, None)},
    (50, 10): {3: (33970, 92560), 4: (43500, 123410), 6: (61650, 185110)},
    (63, 10): {4: (48600, 158580), 6: (68870, 237860)},
    (80, 10): {4: (55590, None), 6: (78790, 316770)},
    (80, 20): {3: (96630, 316220), 4: (123750, 421620)},
}


def test_the_turn_exponent_is_the_makers_own_scaling_at_one_geometry() -> None:
    # Two nuts of one size, lead and ball that differ only in their circuits have the same
    # per-turn rating, so the estimate's ratio is (k / k0)^0.86 whatever the geometry (the
    # ball here is any the size admits: the ratio does not depend on it). The makers' printed
    # ratios are the independent reference, free of the lead angle that confounds the
    # catalogue's spread of turns (module docstring of ballscrew.design.ratings). A pair is
    # compared where its printed C_0a grows as the circuits (within 1 %), which says the
    # circuits hold the same balls (C_0a counts them: 4200 MPa on equally loaded balls):
    # 17 HIWIN pairs; R20-2T4/T6 fails it (C_0a as circuits^0.82, so more than the circuits
    # differ) and two have no C_0a. Each HIWIN pair's C_a ratio is (k / k0)^0.86 within
    # 0.2 % (the printed four or five figures; measured 0.17 % at most), and so is THK's
    # (BIF4010-5, one circuit of 2.5 turns, against BNFN4010-5, two: 0.12 %). With ISO 281's
    # 0.7 every pair would miss by 4.7 to 11.7 %.
    checked = 0
    for (d, lead), family in FSI_FAMILIES.items():
        k0 = min(family)
        ball = 1.5 if lead == 2 else 3.175
        for k, (c_a, c_0a) in family.items():
            base_static = family[k0][1]
            if k == k0 or c_0a is None or base_static is None:
                continue
            if abs(c_0a / base_static / (k / k0) - 1) > 0.01:
                continue
            estimated = [
                dynamic_rating_estimate(BallScrew(d * 1e-3, lead * 1e-3, ball * 1e-3,
                                                  math.radians(45.0), RATING_CONFORMITY,
                                                  RATING_CONFORMITY, 1.0, n, "single"))
                for n in (k0, k)
            ]  # fmt: skip
            assert estimated[1] / estimated[0] == pytest.approx(c_a / family[k0][0], rel=0.002)
            checked += 1
    assert checked == 17
    lines = [ln for ln in CSV.read_text(encoding="utf-8").splitlines() if not ln.startswith("#")]
    thk = {r["designation"]: r for r in csv.DictReader(lines)}
    one, two = thk["BIF4010-5"], thk["BNFN4010-5"]
    assert float(two["static_load_rating_N"]) / float(one["static_load_rating_N"]) == (
        pytest.approx(2.0, rel=0.01)
    )
    printed = float(two["dynamic_load_rating_N"]) / float(one["dynamic_load_rating_N"])
    screws = [BallScrew(41.75e-3, 10e-3, 6.35e-3, math.radians(45.0), RATING_CONFORMITY,
                        RATING_CONFORMITY, 2.5, n, "single") for n in (1, 2)]  # fmt: skip
    estimated = dynamic_rating_estimate(screws[1]) / dynamic_rating_estimate(screws[0])
    assert estimated == pytest.approx(printed, rel=0.002)


def _per_turn_lead_exponents(
    group: list[str], ln_cos: list[float], turns: list[float], ratings: list[tuple[float, float]]
) -> tuple[float, float]:
    """Exponents of cos(lead angle) of C_a / k^0.86 and C_0a / k, one intercept per group."""
    names = sorted(set(group))
    x = np.array([[float(g == n) for n in names] + [c] for g, c in zip(group, ln_cos, strict=True)])
    k = np.array(turns)
    dynamic = np.log(np.array([r[0] for r in ratings]) / k**0.86)
    static = np.log(np.array([r[1] for r in ratings]) / k)
    return (float(np.linalg.lstsq(x, dynamic, rcond=None)[0][-1]),
            float(np.linalg.lstsq(x, static, rcond=None)[0][-1]))  # fmt: skip


def test_at_one_size_and_ball_the_printed_ratings_fall_faster_with_the_lead() -> None:
    # What the catalogue can say of the lead angle with the turns divided out as the makers
    # divide them (k^0.86 for C_a, k for C_0a: the test above): HIWIN's FSC single nuts that
    # share a size and a ball and differ in lead (20 and 25 mm with 3.175 mm balls, 5 mm
    # against 20 and 25 mm leads; 32 and 40 mm with 6.35 mm balls, 10 to 40 mm; 9 rows in
    # 4 groups), per-turn ratings regressed on ln cos(lead angle), one intercept a group.
    # Estimated, with a turn's balls counted on the ball circle (rating_balls_per_circuit),
    # as cos^1.3 for C_a (z^(2/3) cos^1.3, z the same at one size and ball) and cos^1 for
    # C_0a (z cos(phi)); measured 1.30 and 1.00. Counted along the helix, whose turn holds
    # 1/cos(phi) more balls (BallScrew.balls_per_circuit: the same estimates times the
    # counts' ratio to the 2/3 and to the 1), they would fall as cos^(1.3 - 2/3) and cos^0;
    # measured 0.60 and -0.05, the balls rounded down. Printed: cos^1.88 and cos^1.33. So
    # the circle's count is the nearer for both ratings, the reason it was taken, and the
    # estimates still fall slower than the makers' ratings, by cos^0.58 and cos^0.33
    # (asserted: more than 0.3 and 0.2). Issue 48's trend with the turns was this fall: the
    # rows of two turns are the steep ones.
    rows = _cassette_single_nuts(small=True) + _cassette_single_nuts(small=False)
    leads: dict[str, set[str]] = {}
    for r in rows:
        leads.setdefault(f"{r['nominal_diameter_mm']}/{r['ball_diameter_mm']}", set()).add(
            r["lead_mm"]
        )
    group, ln_cos, turns = [], [], []
    printed, estimated, helix = [], [], []
    for r in rows:
        key = f"{r['nominal_diameter_mm']}/{r['ball_diameter_mm']}"
        if len(leads[key]) < 2:
            continue
        screw = _screw(r)
        group.append(key)
        ln_cos.append(math.log(math.cos(screw.lead_angle)))
        turns.append(screw.loaded_turns * screw.circuits)
        printed.append((float(r["dynamic_load_rating_N"]), float(r["static_load_rating_N"])))
        estimated.append((dynamic_rating_estimate(screw), static_rating_estimate(screw)))
        more = screw.balls_per_circuit / rating_balls_per_circuit(screw)
        helix.append((estimated[-1][0] * more ** (2 / 3), estimated[-1][1] * more))
    assert len(turns) == 9 and len(set(group)) == 4
    printed_dynamic, printed_static = _per_turn_lead_exponents(group, ln_cos, turns, printed)
    estimated_dynamic, estimated_static = _per_turn_lead_exponents(group, ln_cos, turns, estimated)
    assert estimated_dynamic == pytest.approx(1.3, abs=0.05)
    assert estimated_static == pytest.approx(1.0, abs=0.05)
    assert printed_dynamic > estimated_dynamic + 0.3 and printed_static > estimated_static + 0.2
    helix_dynamic, helix_static = _per_turn_lead_exponents(group, ln_cos, turns, helix)
    assert helix_dynamic == pytest.approx(1.3 - 2 / 3, abs=0.1)
    assert helix_static == pytest.approx(0.0, abs=0.1)


def test_a_turn_too_short_for_one_ball_on_its_circle_is_refused_with_its_field() -> None:
    # An eighth of a turn of an 8 mm screw of 5 mm lead: the helix's length holds one
    # 3.175 mm ball (1.009 places, so the geometry takes it), the ball circle's 0.99. No
    # rating of no balls: the estimates refuse the turns by name rather than divide by zero.
    screw = BallScrew(8e-3, 5e-3, 3.175e-3, math.pi / 4, 0.525, 0.525, 0.125, 1, "single")
    assert screw.balls_per_circuit == 1
    for estimate in (dynamic_rating_estimate, static_rating_estimate):
        with pytest.raises(BallScrewInputError) as refused:
            estimate(screw)
        assert refused.value.field == "loaded_turns" and "ball circle" in refused.value.allowed
