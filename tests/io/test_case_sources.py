"""Each value of a case with where it comes from: given, catalogue, default or assumed."""

from __future__ import annotations

from types import SimpleNamespace

from ballscrew.io.case import parse_case

CASE = """
title = "sources"
[screw]
designation = "HIWIN R32-10K5-FDC"
preload_share = { value = "6 %", assumed = "a medium preload" }
lead = "10 mm"
[lubricant]
name = "PAO ISO VG 68"
[axis]
moving_mass = "250 kg"
[check]
load_factor = 1.2
"""


def test_sources_of_a_designated_case() -> None:
    case = parse_case(CASE)
    src = case.sources
    assert src["screw.lead"] == "given"
    assert src["screw.ball_diameter"] == "catalogue"  # the designation's row
    assert src["screw.pitch_diameter"] == "assumed"  # HIWIN prints none: noted as assumed
    assert src["screw.contact_angle"] == "default"  # neither written nor in the row
    assert src["screw.conformity_screw"] == "default"
    assert src["screw.preload_share"] == "assumed"
    assert src["axis.moving_mass"] == "given" and src["axis.bearing_span"] == "default"
    assert src["check.load_factor"] == "given" and src["check.static_safety"] == "default"


def test_the_study_report_labels_defaults_as_defaults() -> None:
    # Issue 34: the study report's inputs table said "given" for the default contact angle
    # and conformity.
    from ballscrew.report.study import _inputs

    result = SimpleNamespace(case=parse_case(CASE), axial_load=0.0)
    table = _inputs(result)[0].content  # type: ignore[arg-type]
    status = {row[0]: row[2] for row in table[1]}
    assert status["contact angle"] == "default"
    assert status["conformity screw / nut"] == "default"
    assert status["lead"] == "given"
    assert status["pitch diameter"].startswith("assumed: the catalogue prints no")
