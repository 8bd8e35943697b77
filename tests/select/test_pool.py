"""The candidate pool: ISO 3408-2 sizes with estimated ratings, nut kinds, a motor table.

The rating estimate is judged against the makers' printed ratings (independent
numbers: the bundled catalogue rows), and by a law the Lundberg-Palmgren form
implies (a nut with half the balls per turn carries (1/2)^(2/3) of the load).
The motor table's numbers are checked against the unit conversions done by hand.
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from ballscrew.axis.duty import profile_from_move
from ballscrew.axis.motion import parse_move
from ballscrew.design.ratings import (
    RATING_CONFORMITY,
    dynamic_rating_estimate,
    rating_balls_per_circuit,
)
from ballscrew.errors import BallScrewInputError
from ballscrew.geometry import BallScrew
from ballscrew.io.case import load_case, parse_case
from ballscrew.io.designation import catalog_screws
from ballscrew.io.motors import parse_motors, parse_prices, read_motors
from ballscrew.select import run_select
from ballscrew.select.pool import ISO_SIZES, candidates, iso_rows, rating_scatter
from cli_runner import run
from shared import ROOT, reference_case_toml

CASE = ROOT / "examples" / "vertical_32x5.toml"
MOTORS = ROOT / "examples" / "motors.csv"
MOVE = ("stroke=500 mm, feed=12 m/min, acceleration=3 m/s^2, force=1.5 kN, force_from=100 mm, "
        "force_to=400 mm, dwell=3 s")  # fmt: skip
HEADER = "name, rated_torque [N*m], peak_torque [N*m], max_speed [1/min], rotor_inertia [kg*cm^2]"


def test_the_rating_estimate_lies_near_the_printed_ratings() -> None:
    # The makers' own ratings (25 rows with a printed ball diameter) are the
    # independent reference. ISO 3408-5's scheme at the makers' groove (RATING_CONFORMITY)
    # gives both medians within issue 48's bounds (C_a 0.962, C_0a 1.015); every C_a row
    # within 0.9 to 1.4 bounds the scatter the documentation states (0.94 to 1.35, the two
    # above 1.1 HIWIN's internal-recirculation T4 nuts, whose return takes part of a turn).
    s = rating_scatter()
    assert s["rows"] == 25
    assert 0.95 <= s["dynamic"]["median"] <= 1.05
    assert 0.9 <= s["dynamic"]["min"] and s["dynamic"]["max"] <= 1.4
    assert 0.9 <= s["static"]["median"] <= 1.1


def test_half_the_balls_carry_two_thirds_power_of_the_load() -> None:
    # C ~ Z^(2/3) per turn (Z^(-1/3) in Q_c times Z balls): spacer balls halve the
    # load balls (of an even count: 20 on the ball circle the rating counts, and on the
    # helix), so C falls by (1/2)^(2/3) = 0.630 exactly.
    full = BallScrew(0.041, 0.01, 0.00635, math.radians(45), 0.55, 0.55, 1.0, 4, "single")
    spacer = full.replace(ball_separation="spacer-balls")
    assert full.balls_per_circuit == 2 * spacer.balls_per_circuit
    assert rating_balls_per_circuit(full) == 2 * rating_balls_per_circuit(spacer) == 20
    ratio = dynamic_rating_estimate(spacer) / dynamic_rating_estimate(full)
    assert ratio == pytest.approx(0.5 ** (2 / 3), rel=1e-12)


def test_a_loaded_turn_counts_alike_in_one_circuit_or_in_two() -> None:
    # Every loaded turn counts alike (ISO 3408-5's k^0.86): one circuit of
    # two turns holds twice the balls of one turn (40 = 2 x 20 on this 41 mm screw, on the
    # ball circle the rating counts and on the helix), so it has the balls per turn, and the
    # turns, of two circuits of one turn: the same rating.
    two_turns = BallScrew(0.041, 0.01, 0.00635, math.radians(45), 0.55, 0.55, 2.0, 1, "single")
    two_circuits = two_turns.replace(loaded_turns=1.0, circuits=2)
    assert two_turns.balls_per_circuit == 2 * two_circuits.balls_per_circuit == 40
    assert rating_balls_per_circuit(two_turns) == 2 * rating_balls_per_circuit(two_circuits)
    assert dynamic_rating_estimate(two_turns) == pytest.approx(
        dynamic_rating_estimate(two_circuits), rel=1e-12
    )


def test_iso_sizes_are_candidates_labelled_estimated() -> None:
    text = CASE.read_text(encoding="utf-8")
    found = candidates(text, diameter=(0.025, 0.025), lead=(0.02, 0.02), preloads=["light"],
                       sources=["iso"])  # fmt: skip
    assert {c.nut for c in found} == {"double", "single-4point", "spacer-balls"}
    for c in found:
        assert c.estimated and c.row.maker == "ISO"
        case = parse_case(c.text, source=c.name)
        assert case.screw.lead == pytest.approx(0.02)
        assert case.screw.ball_diameter == pytest.approx(3.969e-3)
        # Estimated at the makers' groove (RATING_CONFORMITY); the case keeps its own
        # conformity for the friction.
        groove = {"conformity_screw": RATING_CONFORMITY, "conformity_nut": RATING_CONFORMITY}
        assert case.ratings.dynamic == pytest.approx(
            dynamic_rating_estimate(case.screw.replace(nut="single", preload=0.0, **groove)),
            rel=1e-6,
        )
        assert case.screw.preload == pytest.approx(0.03 * case.ratings.dynamic, rel=1e-6)
    spacer = next(c for c in found if c.nut == "spacer-balls")
    assert parse_case(spacer.text).screw.ball_separation == "spacer-balls"


def test_an_iso_size_a_catalogue_row_prints_is_left_to_the_catalogue() -> None:
    text = CASE.read_text(encoding="utf-8")
    both = candidates(text, diameter=(0.032, 0.032), lead=(0.01, 0.01), preloads=["light"],
                      sources=["catalogue", "iso"])  # fmt: skip
    assert not any(c.estimated for c in both)
    alone = candidates(text, diameter=(0.032, 0.032), lead=(0.01, 0.01), preloads=["light"],
                       sources=["iso"])  # fmt: skip
    assert alone and all(c.estimated for c in alone)
    assert len(iso_rows()) == len(ISO_SIZES)
    printed = {(r.nominal_diameter, r.lead) for r in catalog_screws()}
    assert any((r.nominal_diameter, r.lead) not in printed for r in iso_rows())


def test_unknown_source_nut_and_an_empty_iso_filter_are_refused() -> None:
    text = CASE.read_text(encoding="utf-8")
    with pytest.raises(BallScrewInputError, match="catalogue, iso") as info:
        candidates(text, sources=["web"])
    assert info.value.field == "--source"
    with pytest.raises(BallScrewInputError, match="spacer-balls") as info:
        candidates(text, nuts=["triple"])
    assert info.value.field == "--nut"
    with pytest.raises(BallScrewInputError, match=r"closest: .*ISO 80x") as info:
        candidates(text, diameter=(0.1, 0.2), sources=["iso"])
    with pytest.raises(BallScrewInputError, match="spacer balls only for ISO") as info:
        candidates(text, diameter=(0.032, 0.032), nuts=["spacer-balls"])


def test_the_motor_table_is_read_in_si() -> None:
    motors = read_motors(MOTORS)
    assert [m.name for m in motors][:2] == ["servo 0.4 kW", "servo 0.75 kW"]
    m = motors[2]
    # 9.0 kg*cm^2 = 9.0e-4 kg*m^2; 3000 1/min = 100 pi rad/s
    assert m.rotor_inertia == pytest.approx(9.0e-4, rel=1e-12)
    assert m.max_speed == pytest.approx(100 * math.pi, rel=1e-12)
    assert (m.rated_torque, m.peak_torque, m.price, m.currency) == (6.0, 18.0, 890.0, "EUR")


@pytest.mark.parametrize(
    ("body", "where", "allowed"),
    [
        ("M1, 2.4, 7.2, fast, 3.1", "line 2, column 'max_speed [1/min]'", "a number"),
        ("M1, 2.4, 7.2, 3000, 3.1\nM2, 2.4, 1.0, 3000, 3.1", "line 3, column 'peak_torque",
         "at least the rated"),
        ("M1, -2.4, 7.2, 3000, 3.1", "line 2, column 'rated_torque", "> 0"),
        ("M1, 2.4, 7.2, 3000, 3.1\nM1, 3, 9, 3000, 4", "line 3, column 'name'", "no other row"),
        ("M1, 2.4, 7.2, 3000", "line 2, column 'rotor_inertia", "a number"),
    ],
)  # fmt: skip
def test_a_bad_motor_row_names_its_line_and_column(body: str, where: str, allowed: str) -> None:
    with pytest.raises(BallScrewInputError, match=allowed) as info:
        parse_motors(f"{HEADER}\n{body}\n", source="m.csv")
    assert where in info.value.field


def test_a_motor_column_without_its_unit_is_refused() -> None:
    with pytest.raises(BallScrewInputError, match=r"rated_torque \[N\*m\]") as info:
        parse_motors("name, rated_torque, peak_torque [N*m], max_speed [rpm], "
                     "rotor_inertia [kg*cm^2]\nM1, 2, 6, 3000, 3\n", source="m.csv")  # fmt: skip
    assert info.value.field == "m.csv: line 1, column 'rated_torque'"
    with pytest.raises(BallScrewInputError, match="missing: rotor_inertia"):
        parse_motors("name, rated_torque [N*m], peak_torque [N*m], max_speed [rpm]\nM, 2, 6, 9\n")


def test_a_motor_replaces_the_cases_motor_and_rotor_inertia() -> None:
    motors = read_motors(MOTORS)
    found = candidates(CASE.read_text(encoding="utf-8"), diameter=(0.032, 0.032),
                       lead=(0.02, 0.02), preloads=["light"], motors=motors[:2])  # fmt: skip
    assert len(found) == 2
    for c, m in zip(found, motors[:2], strict=True):
        case = parse_case(c.text, source=c.name)
        assert case.axis["motor_inertia"] == pytest.approx(m.rotor_inertia, rel=1e-7)
        assert case.motor["rated_torque"] == pytest.approx(m.rated_torque, rel=1e-7)
        assert case.motor["peak_torque"] == pytest.approx(m.peak_torque, rel=1e-7)
        assert case.motor["rated_speed"] == pytest.approx(m.max_speed, rel=1e-7)
        assert c.price == m.price and m.name in c.name
        assert case.axis["moving_mass"] == load_case(CASE).axis["moving_mass"]


def test_price_without_a_price_column_is_refused_before_any_candidate_runs() -> None:
    m = parse_move(MOVE)
    with pytest.raises(BallScrewInputError, match="price column") as info:
        run_select(load_case(CASE), profile_from_move(m, 1), objectives=["energy", "price"],
                   move=m)  # fmt: skip
    assert info.value.field == "--objective"


def test_motors_and_price_give_a_front_over_price(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    pytest.importorskip("pymoo")
    # A 4 s dwell: at 3 s the 4-point nut's heat (its balls turn 1/cos(alpha) faster than a
    # 2-point ball's, kinematics.neighbour_sliding) puts the thermal lead error at 101 % of P5.
    move = MOVE.replace("dwell=3 s", "dwell=4 s")
    code, text, err = run(["select", "--case", str(CASE), "--move", move, "--diameter", "32 mm",
                           "--lead", "20 mm", "--preload", "light", "--motors", str(MOTORS),
                           "--objective", "energy", "--objective", "price"], capsys)  # fmt: skip
    assert code == 0, err
    # the 0.4 and 0.75 kW motors cannot move the 120 kg slide (RMS torque, inertia ratio):
    # the cheapest motor that passes, 1.5 kW (890 EUR), is on the front
    assert "servo 1.5 kW" in text and "recommended:" in text
    bad = tmp_path / "bad.csv"
    bad.write_text(f"{HEADER}\nM1, 2.4, 7.2, 3000, lots\n", encoding="utf-8")
    code, _, err = run(["select", "--case", str(CASE), "--move", MOVE, "--motors", str(bad)],
                       capsys)  # fmt: skip
    assert code == 2 and "line 2" in err and "rotor_inertia" in err


def test_a_screw_price_table_adds_to_the_motor_and_names_what_it_misses() -> None:
    prices, currency = parse_prices(
        "designation, price [EUR]\nHIWIN R32-20K4-FSC, 310\nhiwin  r40-20k4-fsc, 420\n"
    )
    assert currency == "EUR"
    text = CASE.read_text(encoding="utf-8")
    motors = read_motors(MOTORS)
    found = candidates(text, diameter=(0.032, 0.040), lead=(0.02, 0.02), preloads=["light"],
                       makers=["HIWIN"], motors=motors[2:3], screw_prices=prices)  # fmt: skip
    by_screw = {c.row.name: c.price for c in found}
    assert by_screw == {"HIWIN R32-20K4-FSC": 310 + 890, "HIWIN R40-20K4-FSC": 420 + 890}
    with pytest.raises(
        BallScrewInputError, match="missing: HIWIN R32-10K5-FDC, HIWIN R32-10K5-FSC"
    ) as info:
        candidates(text, diameter=(0.032, 0.032), lead=(0.01, 0.02), preloads=["light"],
                   makers=["HIWIN"], screw_prices=prices)  # fmt: skip
    assert info.value.field == "--screw-prices"
    m = parse_move(MOVE)
    with pytest.raises(BallScrewInputError, match="motor table's currency, EUR"):
        run_select(load_case(CASE), profile_from_move(m, 1), objectives=["price"],
                   diameter=(0.032, 0.040), lead=(0.02, 0.02), makers=["HIWIN"], move=m,
                   motors=motors[2:3], screw_prices=prices, currency="USD")  # fmt: skip


@pytest.mark.parametrize(
    ("text", "where", "allowed"),
    [
        ("designation, price\nA, 3\n", "line 1, column 'price'", "currency in brackets"),
        ("designation, price [EUR]\nA, free\n", "line 2, column 'price [EUR]'", "a number"),
        ("designation, price [EUR]\nA, 3\na, 4\n", "line 3, column 'designation'", "no other"),
        ("name, cost [EUR]\nA, 3\n", "line 1 (header)", "designation, price"),
    ],
)  # fmt: skip
def test_a_bad_screw_price_row_names_its_line_and_column(
    text: str, where: str, allowed: str
) -> None:
    with pytest.raises(BallScrewInputError, match=allowed) as info:
        parse_prices(text, source="p.csv")
    assert where in info.value.field


def test_the_command_takes_a_screw_price_table(capsys: pytest.CaptureFixture[str]) -> None:
    pytest.importorskip("pymoo")
    prices = ROOT / "examples" / "screw_prices.csv"
    move = MOVE.replace("dwell=3 s", "dwell=4 s")  # as in the test above: the P5 thermal limit
    code, text, err = run(["select", "--case", str(CASE), "--move", move, "--diameter",
                           "32..40 mm", "--lead", "20 mm", "--maker", "HIWIN", "--preload",
                           "light", "--screw-prices", str(prices), "--objective", "energy",
                           "--objective", "price"], capsys)  # fmt: skip
    assert code == 0, err
    # R32-20K4 (380 EUR) needs less energy than R40-20K4 (460 EUR): it alone is the front
    # (its price printed in the table), so it is recommended, although the R40 has the lower
    # largest utilisation (84 % against 89 %, both above 80 %): a candidate beaten on every
    # objective picked is never the recommendation
    table = text.split("recommended:")[0]
    assert "HIWIN R32-20K4-FSC" in table and "380" in table and "R40-20K4" not in table
    # ... at nominal values. Neither is sure at 95 % (the thermal lead error's P(NOT OK):
    # R32 about 48 %, R40 about 29 %): undecided, and the one less likely to fail is named,
    # off the front as it is
    flat = " ".join(text.split())
    assert (
        "recommended: undecided (none passes with 95% confidence; least likely to fail: "
        "HIWIN R40-20K4-FSC" in flat
    )


def test_the_heavy_class_is_tried_on_double_nuts_only() -> None:
    # HIWIN keeps a single nut's preload within 5 % of C_a, a double nut's within 10 %:
    # heavy (8 %) is a double nut's class only
    text = CASE.read_text(encoding="utf-8")
    iso = candidates(text, diameter=(0.025, 0.025), lead=(0.02, 0.02), preloads=["heavy"],
                     sources=["iso"])  # fmt: skip
    assert [c.nut for c in iso] == ["double"]
    with pytest.raises(BallScrewInputError, match="'heavy' a double nut") as info:
        candidates(text, diameter=(0.032, 0.032), lead=(0.005, 0.005), preloads=["heavy"])
    assert "HIWIN R32-05K4-FSC" in info.value.allowed


def test_the_report_marks_the_iso_sizes_estimated(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    pytest.importorskip("pymoo")
    case = tmp_path / "case.toml"
    case.write_text(reference_case_toml("report", speed="100 rpm", axial_load="0 N",
                                        more='[axis]\nmoving_mass = "200 kg"\n'),
                    encoding="utf-8")  # fmt: skip
    out = tmp_path / "report"
    code, text, err = run(["select", "--case", str(case), "--move", "stroke=300 mm, "
                           "feed=15 m/min, acceleration=2 m/s^2", "--diameter", "25 mm",
                           "--lead", "20 mm", "--source", "iso", "--preload", "light",
                           "--out", str(out)], capsys)  # fmt: skip
    assert code == 0, err
    assert "(estimated)" in text and "estimated/printed over 25 catalogue rows" in text
    rows = (out / "data" / "front.csv").read_text(encoding="utf-8")
    assert rows.count(",estimated,") == 3  # the ISO 25 x 20 size as three nut kinds
    assert (out / "figures" / "front.png").is_file()
    assert "estimated from their geometry" in (out / "report.md").read_text(encoding="utf-8")
