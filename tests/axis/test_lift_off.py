"""Lift-off as a verdict of the check, the lifted-off nut's stiffness, a nut's axial play."""

from __future__ import annotations

import tomllib
from pathlib import Path

import pytest

from ballscrew.axis.check import DEFAULT_AXIAL_PLAY, run_check
from ballscrew.axis.duty import profile_from_move, run_energy
from ballscrew.design.stiffness import design_nut_stiffness
from ballscrew.errors import BallScrewInputError
from ballscrew.io.case import load_case, parse_case
from ballscrew.loads import LIFT_OFF_RATIO
from shared import AXIS_CASE

Z_AXIS = Path(__file__).resolve().parents[1] / "data" / "z_axis_bnfn2505_5.toml"
Z_MOVE = {"stroke": 0.3, "feed": 5.0 / 60.0, "acceleration": 2.5, "force": 1000.0}


def _check(case, move=Z_MOVE):  # type: ignore[no-untyped-def]
    m = dict(move)
    run = run_energy(case, profile_from_move(m, 1), ["catalog"], run_time=600.0, move=m)
    return run_check(run, "catalog")


def _row(result, name: str):  # type: ignore[no-untyped-def]
    return next(c for c in result.criteria if c.name.startswith(name))


def test_z_axis_drilling_upward_lifts_a_half_off() -> None:
    # Issue 34: vertical Z axis, 1 kN drilling upward. Peak axial force m (g + a) + 1 kN
    # (weight, acceleration upward and the drill's reaction on the way up).
    result = _check(load_case(Z_AXIS))
    peak = 120.0 * (9.80665 + 2.5) + 1000.0
    row = _row(result, "lift-off")
    assert row.value == pytest.approx(peak, rel=2e-3)  # g as the package takes it
    assert row.limit == pytest.approx(2**1.5 * 835.0)
    assert row.value / 835.0 == pytest.approx(2.96, abs=0.02)  # the F/F_pr
    assert row.verdict == "NOT OK" and f"{peak / 2**1.5:.4g} N" in row.advice
    assert result.verdict == "NOT OK"
    # The stiffness rows are the lifted-off state's: one half at the peak load. Hertz's
    # contact stiffness grows as Q^(1/3); two halves at F_pr against one at the peak:
    # k_lifted / k_preloaded = (F_peak / F_pr)^(1/3) / 2 (closed form, no difference quotient).
    fig = result.stiffness
    assert fig["lifted_off"] is True
    ratio = fig["nut_N_per_um"] / fig["nut_preloaded_N_per_um"]
    assert ratio == pytest.approx((row.value / 835.0) ** (1 / 3) / 2, rel=2e-2)
    stiff = _row(result, "axis stiffness")
    assert "lifted off" in stiff.name and "lifted off" in _row(result, "lost motion").name
    assert "lifted off" in _row(result, "axial eigenfrequency").name
    k_axis = min(fig["axis_N_per_um"])
    assert stiff.value == pytest.approx(k_axis)
    # The lost motion 2 F_f / k in that state: the softer nut gives the larger one.
    assert _row(result, "lost motion").value == pytest.approx(
        2 * fig["friction_force_N"] / (k_axis * 1e6) * 1e6, rel=1e-9)  # fmt: skip


def test_below_lift_off_the_row_is_ok_and_the_nut_preloaded() -> None:
    result = _check(load_case(Z_AXIS), {**Z_MOVE, "force": 0.0})
    row = _row(result, "lift-off")
    assert row.verdict == "OK" and row.value < LIFT_OFF_RATIO * 835.0
    assert result.stiffness["lifted_off"] is False
    case = load_case(Z_AXIS)
    assert result.stiffness["nut_N_per_um"] == pytest.approx(
        design_nut_stiffness(case.screw) / 1e6)  # fmt: skip


SINGLE = AXIS_CASE.format(
    nut="single", preload="0 N", support="fixed-supported", axis_extra="", sections="{check}"
)


def test_a_nut_without_preload_counts_its_axial_play() -> None:
    move = {"stroke": 0.4, "feed": 0.5, "acceleration": 2.0}
    given = _check(parse_case(SINGLE.format(check='[check]\naxial_play = "10 um"')), move)
    default = _check(parse_case(SINGLE.format(check="")), move)
    assert not any(c.name.startswith("lift-off") for c in given.criteria)  # nothing to lift
    for result, play in ((given, 10e-6), (default, DEFAULT_AXIAL_PLAY)):
        fig = result.stiffness
        elastic = 2 * fig["friction_force_N"] / (min(fig["axis_N_per_um"]) * 1e6)
        assert _row(result, "lost motion").value == pytest.approx((elastic + play) * 1e6)
        assert fig["axial_play_um"] == pytest.approx(play * 1e6)
    assert DEFAULT_AXIAL_PLAY == 20e-6  # THK A15-19: clearance G2, 0.02 mm or less
    assert any("axial play 20 um (default" in a and "check.axial_play" in a
               for a in default.assumptions)  # fmt: skip
    assert not any("(default" in a and "axial play" in a for a in given.assumptions)


def test_axial_play_out_of_range_is_refused() -> None:
    with pytest.raises(BallScrewInputError, match=r"check\.axial_play"):
        parse_case(SINGLE.format(check='[check]\naxial_play = "2 mm"'))


def test_the_web_page_shows_the_lift_off_row() -> None:
    from ballscrew.web import service

    fields = tomllib.loads(Z_AXIS.read_text(encoding="utf-8"))
    fields["screw"]["preload"] = "300 N"  # the page's move has no force: lift off by weight
    move = {"stroke": "300 mm", "feed": "5 m/min", "acceleration": "2.5 m/s**2"}
    page = service.evaluate({"case": fields, "models": [], "move": move})
    rows = {r["name"]: r for r in page["energy"]["check"]["criteria"]}
    row = rows["lift-off F_max / (2^1.5 F_pr)"]
    assert row["verdict"] == "NOT OK"
    assert row["value"] == pytest.approx(120.0 * (9.80665 + 2.5), rel=2e-3)
    assert any("lifted off" in name for name in rows)
