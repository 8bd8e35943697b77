"""The typical ranges (ballscrew.plausible) at their edges, against the module's own table.

The bounds are the documented ones (the module docstring's table: ISO 3448's VG 2 to VG 3200
for nu40, the base oils' densities, the pressure-viscosity coefficients of oils; the ball
series of ISO 3290-1 within 0.5 %; 1 to 5 turns per circuit; the wipers' estimate). Each
bound is tried just inside and just outside, and the text of a warning or a refusal is held
to the range the table states, in the units a user types.
"""

from __future__ import annotations

import math
import warnings

import numpy as np
import pytest

from ballscrew import BallScrew, BallScrewInputError, reference_screw
from ballscrew.errors import BallScrewPlausibilityWarning
from ballscrew.lubricant import Lubricant
from ballscrew.plausible import BALL_SERIES_MM, check_wiper_drag, wiper_drag_bound

BASE = {"nu40": 68e-6, "nu100": 8.6e-6, "density15": 880.0, "pressure_viscosity": 2.2e-8}


def _screw(**changes: object) -> BallScrew:
    """The reference screw (40 x 10, 6.35 mm balls, 2 kN double nut) on a 16 mm lead, changed."""
    return reference_screw().replace(**{"lead": 0.016, **changes})  # type: ignore[arg-type]


def _warned(build: object, field: str) -> list[BallScrewPlausibilityWarning]:
    """The plausibility warnings about ``field`` that ``build()`` gives."""
    with warnings.catch_warnings(record=True) as record:
        warnings.simplefilter("always")
        build()  # type: ignore[operator]
    return [
        w.message
        for w in record
        if isinstance(w.message, BallScrewPlausibilityWarning) and w.message.field == field
    ]


# field, value [SI], what happens, the value as shown, the range as stated
LUBRICANT_EDGES = [
    # nu40: warned outside 1.98 to 3520 mm²/s (VG 2 to VG 3200), refused above 20000
    ("nu40", 3500e-6, "quiet", "", ""),
    ("nu40", 3600e-6, "warned", "3600 mm²/s", "1.98 to 3520 mm²/s"),
    ("nu40", 20000e-6, "warned", "2e+04 mm²/s", "1.98 to 3520 mm²/s"),
    ("nu40", 21000e-6, "refused", "2.1e+04 mm²/s", "0 to 20000 mm²/s ("),
    # density15: warned outside 750 to 1100 kg/m³, refused outside 300 to 2500 kg/m³
    ("density15", 1090.0, "quiet", "", ""),
    ("density15", 1110.0, "warned", "1110 kg/m³", "750 to 1100 kg/m³"),
    ("density15", 300.0, "warned", "300 kg/m³", "750 to 1100 kg/m³"),
    ("density15", 297.0, "refused", "297 kg/m³", "300 to 2500 kg/m³ ("),
    ("density15", 2500.0, "warned", "2500 kg/m³", "750 to 1100 kg/m³"),
    ("density15", 2525.0, "refused", "2525 kg/m³", "300 to 2500 kg/m³ ("),
    # pressure_viscosity: warned outside 5 to 45 /GPa, refused outside 1 to 100 /GPa
    ("pressure_viscosity", 5.2e-9, "quiet", "", ""),
    ("pressure_viscosity", 4.9e-9, "warned", "4.9 /GPa", "5 to 45 /GPa"),
    ("pressure_viscosity", 44e-9, "quiet", "", ""),
    ("pressure_viscosity", 47e-9, "warned", "47 /GPa", "5 to 45 /GPa"),
    ("pressure_viscosity", 1.05e-9, "warned", "1.05 /GPa", "5 to 45 /GPa"),
    ("pressure_viscosity", 0.95e-9, "refused", "0.95 /GPa", "1 to 100 /GPa ("),
    ("pressure_viscosity", 99e-9, "warned", "99 /GPa", "5 to 45 /GPa"),
    ("pressure_viscosity", 105e-9, "refused", "105 /GPa", "1 to 100 /GPa ("),
]


@pytest.mark.parametrize(("field", "value", "outcome", "shown", "stated"), LUBRICANT_EDGES)
def test_a_lubricant_property_at_the_edges_of_its_ranges(
    field: str, value: float, outcome: str, shown: str, stated: str
) -> None:
    def build() -> Lubricant:
        return Lubricant(name="oil", **{**BASE, field: value})

    if outcome == "refused":
        with pytest.raises(BallScrewInputError) as refused:
            build()
        assert (refused.value.field, refused.value.value) == (field, shown)
        assert refused.value.allowed.startswith(stated)
        return
    told = _warned(build, field)
    if outcome == "quiet":
        assert told == []
    else:
        assert [(w.value, w.allowed) for w in told] == [(shown, stated)]


def test_every_ball_of_the_series_is_a_metric_or_an_inch_size_once() -> None:
    # ISO 3290-1's nominal sizes: metric ones in 0.5 mm steps from 1.5 mm (and 0.8, 1 and
    # 1.2 mm below), inch ones in steps of 1/64 in = 0.396875 mm (written to 3 decimals, so
    # within 5e-4 mm); ascending, each once (a ball must be one size of the series).
    inch = 25.4 / 64
    for s in BALL_SERIES_MM:
        metric = s in (0.8, 1.0, 1.2) or (s >= 1.5 and (2 * s).is_integer())
        assert metric or abs(s - round(s / inch) * inch) <= 5e-4 + 1e-12, s
    assert list(BALL_SERIES_MM) == sorted(set(BALL_SERIES_MM))


def test_a_ball_within_half_a_per_cent_of_a_series_size_is_that_size() -> None:
    # 1/4 in = 6.35 mm: 0.4 % off is that ball, 0.52 % off is not (the next sizes, 6 and
    # 7 mm, are 5 and 10 % away).
    assert _warned(lambda: _screw(ball_diameter=6.35e-3 * 0.996), "ball_diameter") == []
    (told,) = _warned(lambda: _screw(ball_diameter=6.35e-3 * 1.0052), "ball_diameter")
    assert told.allowed == "a series size, such as 6.35 or 7 mm"


@pytest.mark.parametrize(
    ("mm", "stated"),
    [(0.9, "a series size, such as 0.8 or 1 mm"), (30.0, "0.8 to 25.4 mm"),
     (0.5, "0.8 to 25.4 mm")],
)  # fmt: skip
def test_a_ball_off_the_series_is_told_the_sizes_near_it_or_the_series_range(
    mm: float, stated: str
) -> None:
    # The series runs from 0.8 mm to 1 in (25.4 mm); 0.9 mm lies between its 0.8 and 1 mm.
    (told,) = _warned(
        lambda: _screw(ball_diameter=mm * 1e-3, lead=0.032, pitch_diameter=0.080),
        "ball_diameter",
    )
    assert told.allowed == stated


def test_five_and_a_quarter_turns_per_circuit_are_warned() -> None:
    # Makers build up to 5 loaded turns per circuit (end caps).
    (told,) = _warned(lambda: _screw(loaded_turns=5.25), "loaded_turns")
    assert told.allowed == "1 to 5 turns per circuit"


def test_the_wipers_bound_on_a_40_mm_screw_follows_from_its_estimate() -> None:
    # WIPER_SOURCE's estimate: two lips, each pressing 0.15 N/mm along 1.5 circumferences of
    # a 40 mm screw, friction coefficient 0.4, at the 20 mm radius: 2 * 0.15 * 1.5 pi 40 *
    # 0.4 * 0.020 = 0.452 N*m, "about 0.5 N*m": the bound is that to one digit.
    estimate = 2 * 0.15 * (1.5 * math.pi * 40.0) * 0.4 * 0.020
    assert wiper_drag_bound(0.040) == float(f"{estimate:.1g}") == 0.5


def test_a_wiper_drag_of_ten_times_the_bound_is_warned_and_above_it_refused() -> None:
    # On a 40 mm screw the bound is 0.5 N*m: up to it quiet, above it warned, above ten times
    # it (5 N*m) refused, the message stating "at most 5 N*m".
    def drag(value: float) -> None:
        check_wiper_drag("screw.wiper_drag", value, 0.040)

    assert _warned(lambda: drag(0.5), "screw.wiper_drag") == []
    assert len(_warned(lambda: drag(0.505), "screw.wiper_drag")) == 1
    assert len(_warned(lambda: drag(5.0), "screw.wiper_drag")) == 1
    with pytest.raises(BallScrewInputError) as refused:
        drag(5.05)
    assert refused.value.allowed.startswith("at most 5 N*m on a 40 mm screw")


def test_many_screws_are_judged_by_the_square_of_their_diameters() -> None:
    # The bound scales as d^2: a 20 mm screw's is a quarter of a 40 mm one's (0.125 N*m).
    # 4 N*m on 40 mm is 8 times its bound; 0.92 N*m on 20 mm 7.36 times (with d^2.2 it
    # would be 8.45): the 40 mm screw is the furthest past, warned, not refused.
    torques, diameters = np.array([4.0, 0.92]), np.array([0.040, 0.020])
    (told,) = _warned(lambda: check_wiper_drag("seal", torques, diameters), "seal")
    assert told.value == "4 N*m" and "on a 40 mm screw" in told.allowed
    # 1.6 N*m on 20 mm is 12.8 times its bound (a bound linear in d would make it 3.2 times
    # and the 40 mm screw's 4 the furthest): refused, naming the 20 mm screw.
    with pytest.raises(BallScrewInputError, match="on a 20 mm screw") as refused:
        check_wiper_drag("seal", np.array([4.0, 1.6]), diameters)
    assert refused.value.value == "1.6 N*m"
