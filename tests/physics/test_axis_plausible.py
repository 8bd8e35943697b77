"""The plausibility bounds of the axis a screw drives, against numbers computed another way.

The bounds of :mod:`ballscrew.plausible` for ``[axis]``: the moving mass and the
acceleration against the static rating C_0a, the span against the shaft's first bending
frequency (the sag it means under its own weight), the feed against the d·n limit, the
inertias and the gear ratio against fixed ranges.
"""

from __future__ import annotations

import math
import warnings

import pytest

from ballscrew.design.limits import MAX_SPEED, critical_speed
from ballscrew.errors import BallScrewInputError, BallScrewPlausibilityWarning
from ballscrew.plausible import (
    check_acceleration,
    check_axis_property,
    check_feed,
    check_moving_mass,
    check_span,
)

C0A = 144.8e3  # HIWIN R32-10K5-FDC's static rating [N] (the bundled catalogue row)
G = 9.80665  # standard gravity [m/s²] (CGPM 1901)
E, RHO = 206e9, 7850.0  # steel as the catalogues take it for the critical speed


def _warned(call: object, *args: object) -> list[str]:
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        call(*args)  # type: ignore[operator]
    return [str(w.message) for w in caught if issubclass(w.category, BallScrewPlausibilityWarning)]


def test_a_mass_whose_weight_exceeds_c0a_is_refused_naming_the_largest_mass() -> None:
    # 144.8 kN / 9.80665 m/s² = 14 765.5 kg, by hand: 14.7 t passes (warned), 14.8 t not.
    assert _warned(check_moving_mass, "axis.moving_mass", "14.7 t", 14_700.0, C0A)
    with pytest.raises(BallScrewInputError, match=r"at most 14770 kg") as info:
        check_moving_mass("axis.moving_mass", "14.8 t", 14_800.0, C0A)
    assert info.value.field == "axis.moving_mass" and info.value.value == "14.8 t"
    with pytest.raises(BallScrewInputError, match=r"static rating C_0a = 144\.8 kN"):
        check_moving_mass("axis.moving_mass", "2500 t", 2.5e6, C0A)


def test_a_mass_is_warned_of_above_half_the_static_rating() -> None:
    # half of C_0a: 7382.7 kg, a static safety of 2 (catalogues: 1 to 3)
    assert not _warned(check_moving_mass, "axis.moving_mass", "7.38 t", 7_380.0, C0A)
    (message,) = _warned(check_moving_mass, "axis.moving_mass", "7.39 t", 7_390.0, C0A)
    assert "axis.moving_mass = 7.39 t" in message and "is above 7383 kg" in message


def test_an_acceleration_whose_force_exceeds_c0a_is_refused() -> None:
    # 250 kg at 579.2 m/s² is 144.8 kN: just below passes (warned), just above not
    assert _warned(check_acceleration, "axis.max_acceleration", "579 m/s**2", 579.0, 250.0, C0A)
    with pytest.raises(BallScrewInputError, match=r"at most 579\.2 m/s²") as info:
        check_acceleration("axis.max_acceleration", "580 m/s**2", 580.0, 250.0, C0A)
    assert info.value.field == "axis.max_acceleration"
    assert not _warned(check_acceleration, "axis.max_acceleration", "5 m/s**2", 5.0, 250.0, C0A)
    assert not _warned(check_acceleration, "axis.max_acceleration", "1e6 m/s**2", 1e6, 0.0, C0A)
    with pytest.raises(BallScrewInputError):  # half a kilogram at 1e6 m/s² is 500 kN
        check_acceleration("axis.max_acceleration", "1e6 m/s**2", 1e6, 0.5, C0A)


def _frequency(root: float, span: float, support: str) -> float:
    return float(critical_speed(root, span, support)) / (2.0 * math.pi)


def test_the_span_refused_is_where_the_shaft_sags_a_third_of_a_metre_under_its_weight() -> None:
    # Computed another way: the sag of a simply supported steel shaft under its own weight,
    # 5 w L^4 / (384 E I) (Timoshenko & Gere), with w = rho g pi d^2/4, I = pi d^4/64. The
    # span at which it sags 1.268 g / (2 pi)^2 = 0.315 m is the one of a 1 Hz first
    # bending frequency; 1 % either side of it passes and is refused (the relation is
    # exact for the uniform beam, so 1 % is only the margin of the test's own rounding).
    d = 0.0264
    sag_1hz = 5.0 * math.pi**4 / 384.0 * G / (2.0 * math.pi) ** 2
    w, inertia = RHO * G * math.pi * d**2 / 4.0, math.pi * d**4 / 64.0
    span = (sag_1hz * 384.0 * E * inertia / (5.0 * w)) ** 0.25
    mount = "supported-supported"
    check_span("axis.bearing_span", "x", 0.99 * span, _frequency(d, 0.99 * span, mount), mount)
    with pytest.raises(BallScrewInputError, match=r"sag over 0\.3 m") as info:
        check_span("axis.bearing_span", "x", 1.01 * span, _frequency(d, 1.01 * span, mount),
                   mount)  # fmt: skip
    assert info.value.field == "axis.bearing_span"
    # the longest span the message names is that span (to the 4 digits shown)
    assert f"at most {span * 1e3:.4g} mm" in info.value.allowed


def test_thomsons_long_screw_passes_and_twice_as_long_is_warned_of() -> None:
    # Thomson's white paper: a 100 in screw of 1 in root has about 18 Hz fixed at both ends
    # and about 8 Hz simply supported: both above the 5 Hz warning, and they are close to the
    # code's frequencies (5 %: "about"); at 200 in, simply supported (a quarter: 2 Hz), warned.
    d, span = 0.0254, 2.54
    assert _frequency(d, span, "fixed-fixed") == pytest.approx(18.0, rel=0.05)
    assert _frequency(d, span, "supported-supported") == pytest.approx(8.0, rel=0.05)
    for support in ("fixed-fixed", "supported-supported"):
        assert not _warned(check_span, "axis.bearing_span", "100 in", span,
                           _frequency(d, span, support), support)  # fmt: skip
    f = _frequency(d, 2 * span, "supported-supported")
    (message,) = _warned(check_span, "axis.bearing_span", "200 in", 2 * span, f, "ss")
    assert "axis.bearing_span = 200 in" in message
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_span("axis.screw_length", "200 in", 2 * span, f, "ss", warn_below=False)


def test_a_feed_limit_past_the_nuts_dn_limit_is_warned_and_past_every_screw_refused() -> None:
    # 32 mm at d·n 70 000: 2187.5 rpm, at lead 10 mm 21.875 m/min (by hand)
    args = (0.010, 0.032, 70_000.0, MAX_SPEED)
    assert not _warned(check_feed, "axis.max_feed", "21.8 m/min", 21.8 / 60, *args)
    (message,) = _warned(check_feed, "axis.max_feed", "22 m/min", 22.0 / 60, *args)
    assert "is above 21.88 m/min" in message
    # MAX_SPEED 1e5 rad/s is 15 915 rev/s: at lead 10 mm, 159.2 m/s
    assert _warned(check_feed, "axis.max_feed", "150 m/s", 150.0, *args)  # warned, not refused
    with pytest.raises(BallScrewInputError, match=r"at most 159\.2 m/s") as info:
        check_feed("axis.max_feed", "200 m/s", 200.0, *args)
    assert info.value.field == "axis.max_feed"


@pytest.mark.parametrize(
    ("name", "value", "outcome"),
    [
        ("motor_inertia", 1.2e-3, "ok"),
        ("motor_inertia", 0.5, "warned"),
        ("motor_inertia", 12.0, "refused"),  # 12 kg*cm² typed as kg*m²
        ("coupling_inertia", 2e-4, "ok"),
        ("coupling_inertia", 0.05, "warned"),
        ("screw_inertia", 1.2, "ok"),  # 100 mm over 15 m: pi rho L d^4/32 = 1.156 kg*m²
        ("screw_inertia", 11.0, "refused"),
        ("gear_ratio", 1.0, "ok"),
        ("gear_ratio", 0.1, "warned"),
        ("gear_ratio", 5000.0, "refused"),
    ],
)
def test_inertias_and_the_gear_ratio_are_held_to_their_ranges(
    name: str, value: float, outcome: str
) -> None:
    field = f"axis.{name}"
    if outcome == "refused":
        with pytest.raises(BallScrewInputError) as info:
            check_axis_property(field, value, name)
        assert info.value.field == field
        return
    assert bool(_warned(check_axis_property, field, value, name)) == (outcome == "warned")


def test_the_ends_are_allowed_as_the_messages_say_at_most() -> None:
    # "at most": a weight equal to C_0a is allowed, equal to half of it not warned; a first
    # bending frequency of exactly 1 Hz is not refused, of exactly 5 Hz not warned
    check_moving_mass("axis.moving_mass", "1 t", 1000.0, 1000.0 * G)
    assert not _warned(check_moving_mass, "axis.moving_mass", "1 t", 1000.0, 2000.0 * G)
    check_span("axis.bearing_span", "x", 1.0, 1.0, "ss")
    assert not _warned(check_span, "axis.bearing_span", "x", 1.0, 5.0, "ss")
    assert not _warned(check_span, "axis.bearing_span", "x", 1.0, 5.2, "ss")
    with pytest.raises(BallScrewInputError, match="at most 0 mm"):
        check_span("axis.bearing_span", "x", 1.0, math.nan, "ss")


def test_the_messages_give_the_forces_and_spans_computed_by_hand() -> None:
    # 2500 t weighs 2.5e6 kg * 9.80665 m/s² = 24 517 kN; 7.39 t 72.47 kN
    with pytest.raises(BallScrewInputError, match=r"its weight, 2\.452e\+04 kN"):
        check_moving_mass("axis.moving_mass", "2500 t", 2.5e6, C0A)
    (message,) = _warned(check_moving_mass, "axis.moving_mass", "7.39 t", 7_390.0, C0A)
    assert "(its weight 72.47 kN)" in message
    # the span warned of names the longest span of a 5 Hz shaft: by the sag of a simply
    # supported 1 in shaft, 5 w L^4/(384 E I) = 1.268 g/(2 pi 5)^2 (see above; 4 digits shown)
    d = 0.0254
    sag = 5.0 * math.pi**4 / 384.0 * G / (2.0 * math.pi * 5.0) ** 2
    w, inertia = RHO * G * math.pi * d**2 / 4.0, math.pi * d**4 / 64.0
    longest = (sag * 384.0 * E * inertia / (5.0 * w)) ** 0.25
    f = _frequency(d, 5.08, "supported-supported")
    (message,) = _warned(check_span, "axis.bearing_span", "200 in", 5.08, f, "ss")
    assert f"is above {longest * 1e3:.4g} mm" in message
    with pytest.raises(BallScrewInputError, match="at lead 10 mm"):
        check_feed("axis.max_feed", "200 m/s", 200.0, 0.010, 0.032, 70_000.0, MAX_SPEED)
    (message,) = _warned(check_feed, "axis.max_feed", "1 m/s", 1.0, 0.010, 0.032, 70_000.0,
                         MAX_SPEED)  # fmt: skip
    assert "with lead 10 mm" in message and "(6000 rpm, d·n 192,000 mm·rpm)" in message


@pytest.mark.parametrize(
    ("name", "low", "high", "least", "most"),
    [
        # typical range (warned outside) and possible one (refused outside), as sourced
        ("motor_inertia", 0.0, 0.1, 0.0, 10.0),
        ("coupling_inertia", 0.0, 0.01, 0.0, 10.0),
        ("screw_inertia", 0.0, 2.0, 0.0, 10.0),
        ("gear_ratio", 0.2, 100.0, 1e-3, 1e3),
    ],
)
def test_each_range_holds_at_its_ends(
    name: str, low: float, high: float, least: float, most: float
) -> None:
    # 5 % inside and outside each end: a bound moved by 10 % is seen
    field = f"axis.{name}"
    inside = [high * 0.95, low * 1.05 if low else high * 0.3]
    for value in inside:
        assert not _warned(check_axis_property, field, value, name), value
    assert _warned(check_axis_property, field, high * 1.05, name)
    assert _warned(check_axis_property, field, most * 0.95, name)
    if low:
        assert _warned(check_axis_property, field, low * 0.95, name)
        assert _warned(check_axis_property, field, least * 1.05, name)
        with pytest.raises(BallScrewInputError):
            check_axis_property(field, least * 0.95, name)
    with pytest.raises(BallScrewInputError) as info:
        check_axis_property(field, most * 1.05, name)
    assert info.value.value.startswith(f"{most * 1.05:.4g}")


def test_a_process_force_is_held_to_c0a_in_either_direction() -> None:
    from ballscrew.plausible import check_axial_force

    check_axial_force("axes.X.process_force", "144.8 kN", 144.8e3, C0A)  # "at most": the end
    for force in (145e3, -145e3):  # a pull dents the raceways as a push does
        with pytest.raises(BallScrewInputError, match=r"at most 144800 N"):
            check_axial_force("axes.X.process_force", "145 kN", force, C0A)
    assert not _warned(check_axial_force, "axes.X.process_force", "72 kN", 72.4e3, C0A)
    assert _warned(check_axial_force, "axes.X.process_force", "73 kN", -73e3, C0A)


def test_a_machine_axis_feed_limit_is_only_refused() -> None:
    args = (0.010, 0.032, 70_000.0, MAX_SPEED)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        check_feed("axes.Z.max_feed", "1 m/s", 1.0, *args, warn_above=False)
    with pytest.raises(BallScrewInputError):
        check_feed("axes.Z.max_feed", "200 m/s", 200.0, *args, warn_above=False)
