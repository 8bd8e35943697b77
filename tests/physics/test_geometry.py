"""Tests of ballscrew.geometry: the BallScrew description and its derived geometry."""

from __future__ import annotations

import dataclasses
import math

import pytest

from ballscrew import BallScrew, BallScrewInputError, reference_screw

BASE = {
    "pitch_diameter": 0.040,
    "lead": 0.010,
    "ball_diameter": 6.35e-3,
    "contact_angle": math.radians(45.0),
    "conformity_screw": 0.55,
    "conformity_nut": 0.55,
    "loaded_turns": 2.5,
    "circuits": 2,
    "nut": "double",
    "preload": 2000.0,
}


def make(**changes: object) -> BallScrew:
    kwargs = dict(BASE)
    kwargs.update(changes)
    return BallScrew(**kwargs)  # type: ignore[arg-type]


def test_derived_geometry_by_hand() -> None:
    s = make()
    # lead angle: atan(10 / (pi 40)) = atan(0.0795775) = 4.5499°
    assert math.degrees(s.lead_angle) == pytest.approx(4.5499, abs=1e-4)
    gamma = 6.35 * math.cos(math.radians(45)) / 40  # 0.112253
    assert s.gamma == pytest.approx(gamma, rel=1e-12)
    # contact radii (d_m -/+ D_w cos a) / 2
    assert s.contact_radius_screw == pytest.approx((0.040 - 6.35e-3 * math.cos(math.pi / 4)) / 2)
    assert s.contact_radius_nut == pytest.approx((0.040 + 6.35e-3 * math.cos(math.pi / 4)) / 2)
    # radii of curvature: (D_w/2)(1 -/+ gamma), f D_w / (2 f - 1) = 5.5 D_w
    assert s.rx_screw == pytest.approx(3.175e-3 * (1 - gamma), rel=1e-12)
    assert s.rx_nut == pytest.approx(3.175e-3 * (1 + gamma), rel=1e-12)
    assert s.ry_screw == pytest.approx(5.5 * 6.35e-3, rel=1e-12)
    assert s.ry_nut == pytest.approx(5.5 * 6.35e-3, rel=1e-12)
    # balls: 2.5 turns x pi 40 mm / cos(lambda) / 6.35 mm = 49.6 -> 49 per circuit
    assert s.balls_per_circuit == 49
    assert s.balls_per_nut == 98


def test_rolling_radii_match_the_bearing_ring_curvature() -> None:
    # Independent derivation: at the screw contact the groove's surface
    # radius in the rolling plane is r_s / cos(alpha) (the ring-curvature of a
    # bearing inner race), convex; the nut's is r_n / cos(alpha), concave.
    s = make()
    ca = math.cos(s.contact_angle)
    r_ball = s.ball_diameter / 2
    inv_screw = 1 / r_ball + ca / s.contact_radius_screw
    inv_nut = 1 / r_ball - ca / s.contact_radius_nut
    assert s.rx_screw == pytest.approx(1 / inv_screw, rel=1e-12)
    assert s.rx_nut == pytest.approx(1 / inv_nut, rel=1e-12)


def test_reference_screw_is_the_documented_case() -> None:
    assert reference_screw() == make()


def test_conformity_and_ball_size_trends() -> None:
    # Tighter conformity -> larger transverse radius; larger ball -> more gamma.
    assert make(conformity_screw=0.52).ry_screw > make(conformity_screw=0.56).ry_screw
    assert make(ball_diameter=8e-3).gamma > make().gamma
    # Steeper contact angle -> smaller gamma -> rx_screw grows towards D_w/2.
    assert make(contact_angle=math.radians(60)).rx_screw > make().rx_screw


def test_immutable_and_replace_revalidates() -> None:
    s = make()
    with pytest.raises(dataclasses.FrozenInstanceError):
        s.lead = 0.02  # type: ignore[misc]
    assert s.replace(preload=100.0).preload == 100.0
    with pytest.raises(BallScrewInputError, match="preload"):
        s.replace(preload=-1.0)
    with pytest.raises(BallScrewInputError, match="colour"):
        s.replace(colour="red")


def test_reduced_modulus_and_roughness() -> None:
    s = make()
    assert s.reduced_modulus == pytest.approx(2.1e11 / 0.91, rel=1e-12)
    assert s.composite_roughness_screw == pytest.approx(math.hypot(0.08e-6, 0.3e-6), rel=1e-12)


@pytest.mark.parametrize(
    ("field", "value", "fragment"),
    [
        ("pitch_diameter", 0.0, "> 0"),
        ("lead", -0.01, "> 0"),
        ("ball_diameter", float("nan"), "finite"),
        ("contact_angle", 0.0, "0° to 90°"),
        ("contact_angle", math.pi / 2, "0° to 90°"),
        ("conformity_screw", 0.5, "exceed 0.5"),
        ("conformity_nut", 0.49, "exceed 0.5"),
        ("preload", -10.0, ">= 0"),
        ("loaded_turns", float("inf"), "finite"),
        ("circuits", 0, "whole number"),
        ("circuits", 1.5, "whole number"),
        ("nut", "triple", "one of"),
        ("ball_diameter", 0.04, "does not fit"),
        ("lead", 0.2, "lead angle below 45"),
        ("roughness_ball", 0.0, "> 0"),
        ("pitch_diameter", "40 mm", "real number"),
        ("pitch_diameter", [0.04, 0.05], "single real number"),
        ("youngs_modulus_ball", -2e11, "> 0"),
        ("poisson_ratio_races", 0.5, "0, 0.5"),
    ],
)
def test_bad_input_raises_one_error_naming_field_value_and_rule(
    field: str, value: object, fragment: str
) -> None:
    with pytest.raises(BallScrewInputError) as info:
        make(**{field: value})
    err = info.value
    assert isinstance(err, ValueError)
    assert err.field == field
    assert fragment in str(err)
    assert field in str(err)


def test_single_nut_refuses_preload() -> None:
    with pytest.raises(BallScrewInputError, match="single-4point"):
        make(nut="single", preload=100.0)
    assert make(nut="single", preload=0.0).preload == 0.0


@pytest.mark.parametrize(
    "field, value, hint",
    [
        ("pitch_diameter", 40.0, "40 mm = 0.04 m"),
        ("lead", 10.0, "10 mm = 0.01 m"),
        ("ball_diameter", 6.35, "6.35 mm = 0.00635 m"),
        ("roughness_screw", 0.3, "0.3 µm = 3e-07 m"),
    ],
)
def test_unit_slips_are_caught_with_a_hint(field: str, value: float, hint: str) -> None:
    # A size typed in mm (or µm) through the API used to pass as metres.
    with pytest.raises(BallScrewInputError, match=field) as info:
        reference_screw().replace(**{field: value})
    assert hint in str(info.value)
