"""A screw by its catalogue designation or size notation, in the API and in case files."""

from __future__ import annotations

import math

import pytest

from ballscrew import BallScrew
from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import parse_case
from ballscrew.io.designation import catalog_screws, find, parse_size, resolve

CASE = """
[screw]
designation = "{designation}"
{extra}
[lubricant]
name = "mineral ISO VG 68"
"""


def test_lookup_ignores_case_spaces_and_the_maker() -> None:
    a = find("HIWIN R40-10K5-FDC")
    assert find("r40-10k5-fdc") is a and find("  hiwin   R40-10K5-FDC ") is a
    with pytest.raises(BallScrewInputError, match="closest: HIWIN R40-10K5-FDC"):
        find("HIWIN R40-10K5-FDX")


def test_size_notation_in_millimetres() -> None:
    g = parse_size("25x5 single-4point 1x4 3.175")
    assert g == pytest.approx(
        {"pitch_diameter": 0.025, "lead": 0.005, "loaded_turns": 1.0, "ball_diameter": 0.003175}
        | {"circuits": 4, "nut": "single-4point"}  # type: ignore[operator]
    )
    for bad in ("25 by 5", "25x5 triple", "25x5 2.5x2.5 3"):
        with pytest.raises(BallScrewInputError, match="designation"):
            parse_size(bad)


def test_every_catalogue_row_is_a_consistent_screw() -> None:
    # Every row with its ball diameter and turns builds a valid BallScrew, and
    # its printed ratings are those of a real nut: C0a above Ca (static ratings
    # exceed dynamic ones for ball screws), except the one misprint the table
    # flags in its notes.
    assert len(catalog_screws()) >= 30
    for s in catalog_screws():
        assert s.source and s.page, s.name
        if s.dynamic_load_rating and s.static_load_rating and "misprint" not in s.notes:
            assert s.static_load_rating > s.dynamic_load_rating, s.name
        r = resolve(s.name)
        if "ball_diameter" in r.geometry and "loaded_turns" in r.geometry:
            screw = BallScrew(contact_angle=math.radians(45), conformity_screw=0.55,
                              conformity_nut=0.55, **r.geometry)  # fmt: skip
            assert screw.balls_per_circuit >= 5, s.name


def test_case_by_designation_with_a_preload_share() -> None:
    case = parse_case(CASE.format(designation="HIWIN R40-10K5-FDC", extra='preload_share = "5 %"'))
    s = case.screw
    # HIWIN prints Cdyn = 63.4 kN for this nut: 5 % of it.
    assert s.preload == pytest.approx(0.05 * 63400.0, rel=1e-12)
    assert (s.ball_diameter, s.lead, s.circuits, s.nut) == (0.00635, 0.010, 5, "double")
    assumed = {a.field for a in case.assumptions}
    assert {"screw.pitch_diameter", "screw.loaded_turns"} <= assumed
    assert "BS-08-2-EN-1704-K" in case.screw_source


def test_keys_given_override_the_designation_and_gaps_are_named() -> None:
    extra = 'preload = "1 kN"\nball_diameter = "7.144 mm"\nloaded_turns = 2.5'
    case = parse_case(CASE.format(designation="THK BIF4010-5", extra=extra))
    assert case.screw.pitch_diameter == pytest.approx(
        0.04175
    )  # THK prints the ball centre diameter
    assert case.screw.ball_diameter == pytest.approx(0.007144)
    assert "screw.loaded_turns" not in {a.field for a in case.assumptions}
    with pytest.raises(BallScrewInputError, match="does not give it") as info:
        parse_case(CASE.format(designation="THK BIF4010-5", extra='preload = "1 kN"'))
    assert info.value.field == "screw.ball_diameter"
    with pytest.raises(BallScrewInputError, match="dynamic_load_rating"):
        parse_case(
            CASE.format(designation="40x10 double 2.5x2 6.35", extra='preload_share = "5 %"')
        )
    with pytest.raises(BallScrewInputError, match="exactly one"):
        parse_case(CASE.format(designation="40x10 double 2.5x2 6.35",
                               extra='preload = "1 kN"\npreload_share = "5 %"'))  # fmt: skip
