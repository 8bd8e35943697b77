"""The typical ranges of the inputs (ballscrew.plausible): refused beyond what can be, warned
outside what makers build or sell, through the library classes every face builds (issue 35, 4).

The bounds are outside numbers: ISO 3448's viscosity grades (VG 3200 ends at 3520 mm²/s), the
ball sizes of ISO 3290 as a ball maker lists them, the pressure-viscosity coefficients of
Stachowiak & Batchelor's Table 2.3, and the bundled catalogue rows and oils, which are real
parts and must pass without a word.
"""

from __future__ import annotations

import warnings

import pytest

from ballscrew import BallScrew, BallScrewInputError, reference_screw
from ballscrew import lubricants as bundled
from ballscrew.errors import BallScrewPlausibilityWarning
from ballscrew.friction import get_model
from ballscrew.io.case import parse_case
from ballscrew.io.designation import catalog_screws
from ballscrew.lubricant import Lubricant
from ballscrew.plausible import BALL_SERIES_MM, LUBRICANT_RANGES, wiper_drag_bound


def _screw(**changes: object) -> BallScrew:
    """The reference screw (40 x 10, 6.35 mm balls, 2 kN double nut), changed."""
    return reference_screw().replace(**changes)  # type: ignore[arg-type]


def _quiet(build: object) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error", BallScrewPlausibilityWarning)
        build()  # type: ignore[operator]


@pytest.mark.parametrize(("ball", "lead"), [(12e-3, 10e-3), (10e-3, 10e-3), (6.35e-3, 5e-3)])
def test_a_ball_as_large_as_the_lead_is_refused_by_the_class(ball: float, lead: float) -> None:
    # A ball of a single-start thread sits between neighbouring turns of the groove: it must
    # be smaller than the lead (0.2.0 accepted a 12 mm ball on a 10 mm lead in the library).
    with pytest.raises(BallScrewInputError, match="lead") as info:
        _screw(ball_diameter=ball, lead=lead, pitch_diameter=0.063)
    assert info.value.field == "ball_diameter"


def test_a_case_file_names_the_screw_field_for_it() -> None:
    text = CASE.format(
        screw='pitch_diameter = "40 mm"\nlead = "10 mm"\nball_diameter = "12 mm"', lub=""
    )
    with pytest.raises(BallScrewInputError, match="smaller than the lead") as info:
        parse_case(text)
    assert info.value.field == "screw.ball_diameter"


@pytest.mark.parametrize("mm", [1.5875, 2.381, 3.175, 3.969, 4.762, 6.35, 7.144, 9.525, 12.7, 5.0])
def test_balls_of_the_series_pass_quietly(mm: float) -> None:
    _quiet(lambda: _screw(ball_diameter=mm * 1e-3, lead=0.016))


@pytest.mark.parametrize("mm", [0.25, 0.5, 6.2, 30.0])
def test_a_ball_off_the_series_is_warned_naming_the_field(mm: float) -> None:
    with pytest.warns(BallScrewPlausibilityWarning, match="ball_diameter") as record:
        _screw(ball_diameter=mm * 1e-3, lead=0.032, pitch_diameter=0.080)
    warning = record[0].message
    assert isinstance(warning, BallScrewPlausibilityWarning)
    assert warning.field == "ball_diameter" and "ISO 3290-1" in warning.source


def test_the_series_holds_the_inch_fractions() -> None:
    # 1/32 in steps from 1/16 to 1/2 in that ball screws use (25.4 mm per inch).
    for n in (2, 3, 4, 5, 6, 7, 8, 9, 10, 12, 16):
        assert any(abs(s - n * 25.4 / 32) < 1e-3 for s in BALL_SERIES_MM), n


# Technoball's list of ISO 3290 precision ball sizes [mm] (plausible.py, reference [4]): the
# metric sizes, then 1/16, 3/32, 7/64 in and the 1/32-inch steps to 1 in that it prints.
MAKERS_BALLS_MM = (
    1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 4.5, 5.0, 6.0, 10.0, 12.0, 15.0, 16.0, 20.0, 25.0,
    *(25.4 * n / 64 for n in (4, 6, 7)),
    *(25.4 * n / 32 for n in (4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20,
                               21, 22, 24, 25, 26, 30, 32)),
)  # fmt: skip


@pytest.mark.parametrize("mm", MAKERS_BALLS_MM)
def test_every_size_of_a_ball_makers_iso_3290_list_passes_quietly(mm: float) -> None:
    _quiet(lambda: _screw(ball_diameter=mm * 1e-3, lead=0.032, pitch_diameter=0.100))


def test_every_ball_of_the_bundled_catalogue_is_a_series_size() -> None:
    # The rows print 3.175, 3.969, 6.35 and 9.525 mm (1/8, 5/32, 1/4 and 3/8 in).
    printed = {row.ball_diameter for row in catalog_screws() if row.ball_diameter is not None}
    assert printed
    for d in printed:
        assert min(abs(s * 1e-3 - d) for s in BALL_SERIES_MM) < 1e-3 * d, d


@pytest.mark.parametrize("turns", [0.5, 6.0, 9.5])
def test_loaded_turns_outside_1_to_5_are_warned(turns: float) -> None:
    with pytest.warns(BallScrewPlausibilityWarning, match="loaded_turns"):
        _screw(loaded_turns=turns)


@pytest.mark.parametrize("turns", [1.0, 1.5, 2.5, 3.5, 5.0])
def test_loaded_turns_makers_build_pass_quietly(turns: float) -> None:
    _quiet(lambda: _screw(loaded_turns=turns))


def test_every_bundled_catalogue_nut_passes_quietly() -> None:
    # Real parts: their balls and turns lie in the series (or the catalogue's assumption).
    for row in catalog_screws():
        if row.ball_diameter is None:  # the case would need it given
            continue
        text = CASE.format(screw=f'designation = "{row.designation}"', lub="").replace(
            'preload = "2 kN"', 'preload = "0 N"'
        )
        _quiet(lambda text=text: parse_case(text))


def test_every_bundled_lubricant_passes_quietly() -> None:
    for name in bundled.names():
        oil = bundled.get(name)
        _quiet(lambda oil=oil: oil.replace(source="again"))


@pytest.mark.parametrize(
    ("field", "value"),
    [("nu40", 3520e-6), ("nu40", 2e-6), ("density15", 750.0), ("density15", 1100.0),
     ("pressure_viscosity", 10e-9), ("pressure_viscosity", 35e-9)],
)  # fmt: skip
def test_lubricant_properties_inside_their_typical_range_pass(field: str, value: float) -> None:
    # VG 3200's upper limit (3520 mm²/s) and VG 2's lower one (1.98) are inside.
    base = {"nu40": 68e-6, "nu100": 1e-6 if field == "nu40" else 8.6e-6, "density15": 880.0,
            "pressure_viscosity": 2.2e-8}  # fmt: skip
    _quiet(lambda: Lubricant(name="oil", **{**base, field: value}))


def test_the_nu40_range_is_iso_3448s_rule_applied_to_its_end_grades() -> None:
    # ISO 3448:1992 clause 3.2: each grade spans +-10 % of its mid-point at 40 °C; the first
    # grade, VG 2, has the mid-point 2.2 mm²/s (Table 1: 1.98 to 2.42), the last is VG 3200.
    low, high = LUBRICANT_RANGES["nu40"].typical
    assert low == pytest.approx(0.9 * 2.2e-6, rel=1e-12)
    assert high == pytest.approx(1.1 * 3200e-6, rel=1e-12)


@pytest.mark.parametrize("per_gpa", [13.0, 13.4, 17.6, 25.0, 41.5])
def test_tabulated_pressure_viscosity_coefficients_pass_quietly(per_gpa: float) -> None:
    # Stachowiak & Batchelor, Engineering Tribology, Table 2.3: mineral oils from 13 (a spindle
    # oil at 100 °C) to 41.5 /GPa (a cylinder oil at 30 °C); a polyglycol 17.6 at 30 °C.
    base = {"nu40": 68e-6, "nu100": 8.6e-6, "density15": 880.0}
    _quiet(lambda: Lubricant(name="oil", pressure_viscosity=per_gpa * 1e-9, **base))


def test_a_perfluoropolyether_is_warned_not_refused() -> None:
    # A PFPE oil weighs about 1.9 g/cm³: a real (vacuum, clean-room) lubricant, used as given.
    with pytest.warns(BallScrewPlausibilityWarning, match="density15") as record:
        oil = Lubricant(name="PFPE", nu40=68e-6, nu100=8.6e-6, density15=1900.0,
                        pressure_viscosity=2.5e-8)  # fmt: skip
    assert oil.density15 == 1900.0
    message = record[0].message
    assert isinstance(message, BallScrewPlausibilityWarning)
    assert "perfluoropolyether" in message.source


@pytest.mark.parametrize(
    ("field", "value"),
    [("nu40", 6800e-6), ("nu40", 1e-2), ("density15", 1900.0), ("density15", 700.0),
     ("pressure_viscosity", 50e-9), ("pressure_viscosity", 3e-9)],
)  # fmt: skip
def test_lubricant_properties_outside_their_typical_range_are_warned(
    field: str, value: float
) -> None:
    # '68 St' is 6800 mm²/s, above ISO VG 3200's 3520: warned, used as given (a 10000 mm²/s
    # oil is what tests/friction/test_edges.py takes to the edge on purpose).
    base = {"nu40": 68e-6, "nu100": 8.6e-6, "density15": 880.0, "pressure_viscosity": 2.2e-8}
    with pytest.warns(BallScrewPlausibilityWarning, match=field) as record:
        oil = Lubricant(name="oil", **{**base, field: value})
    assert getattr(oil, field) == value
    message = record[0].message
    assert isinstance(message, BallScrewPlausibilityWarning) and message.source


@pytest.mark.parametrize(
    ("field", "value"),
    [("nu40", 0.03), ("density15", 8800.0), ("pressure_viscosity", 2.2e-7),
     ("pressure_viscosity", 2.2e-10)],
)  # fmt: skip
def test_lubricant_properties_beyond_what_can_be_are_refused(field: str, value: float) -> None:
    base = {"nu40": 68e-6, "nu100": 8.6e-6, "density15": 880.0, "pressure_viscosity": 2.2e-8}
    with pytest.raises(BallScrewInputError) as info:
        Lubricant(name="oil", **{**base, field: value})
    assert info.value.field == field
    assert " to " in info.value.allowed and "(" in info.value.allowed  # the range, its source


SIZE = 'pitch_diameter = "40 mm"\nlead = "10 mm"\nball_diameter = "{ball}"'

CASE = """
[screw]
{screw}
preload = "2 kN"

[lubricant]
name = "mineral ISO VG 68"
{lub}

[operation]
speed = "100 rpm"
temperature = "40 degC"
axial_load = "1 kN"
"""


def test_68_st_in_a_case_file_is_warned_and_kept_in_the_case() -> None:
    lub = 'nu40 = "68 St"\nnu100 = "8.6 cSt"\ndensity15 = "880 kg/m**3"'
    text = CASE.format(
        screw='pitch_diameter = "40 mm"\nlead = "10 mm"\nball_diameter = "6.35 mm"', lub=lub
    )
    with pytest.warns(BallScrewPlausibilityWarning, match="lubricant.nu40 = 6800 mm²/s"):
        case = parse_case(text)
    assert case.lubricant.nu40 == pytest.approx(6.8e-3)
    # Only what was typed: the pressure-viscosity coefficient estimated from it is not warned.
    assert len(case.warned) == 1 and "ISO 3448" in case.warned[0]


def test_wiper_drag_bound_grows_with_the_square_of_the_diameter() -> None:
    # Lip length and radius each grow with the diameter.
    assert wiper_drag_bound(0.080) == pytest.approx(4.0 * wiper_drag_bound(0.040))


def test_wiper_drag_bound_is_of_the_order_of_skfs_lip_seal_friction() -> None:
    # SKF's model of a rolling bearing's contact seal, M = KS1 * ds**2.25 (+ KS2 = 0 for large
    # bearings) [N*mm, ds in mm], KS1 = 0.018 (as coded in Thermca's bearing.py): 72 N*mm on a
    # 40 mm counterface. A ball screw's two wipers follow the thread, a longer lip than two
    # bearing seals: more than those, within a factor ten.
    two_lips = 2 * 0.018 * 40.0**2.25 / 1e3
    assert 1.0 < wiper_drag_bound(0.040) / two_lips < 10.0
    # The growth with the diameter, d**2 here against SKF's d**2.25: within 20 % from 40 to 80.
    assert wiper_drag_bound(0.080) / wiper_drag_bound(0.040) == pytest.approx(2**2.25, rel=0.2)


SCREW = 'pitch_diameter = "40 mm"\nlead = "10 mm"\nball_diameter = "6.35 mm"\nwiper_drag = "{drag}"'


def test_a_50_nm_wiper_drag_is_refused_naming_the_field() -> None:
    # 0.2.0 gave a 50.5 N*m drag torque for it; a wiper's lip cannot press that hard.
    with pytest.raises(BallScrewInputError, match="N\\*mm or N\\*cm") as info:
        parse_case(CASE.format(screw=SCREW.format(drag="50 N*m"), lub=""))
    assert info.value.field == "screw.wiper_drag"


def test_a_large_wiper_drag_is_warned_and_a_usual_one_is_not() -> None:
    with pytest.warns(BallScrewPlausibilityWarning, match="screw.wiper_drag"):
        parse_case(CASE.format(screw=SCREW.format(drag="2 N*m"), lub=""))
    _quiet(lambda: parse_case(CASE.format(screw=SCREW.format(drag="0.05 N*m"), lub="")))


def test_the_complete_models_seal_torque_is_refused_in_the_library() -> None:
    screw = _screw()
    oil = bundled.get("mineral ISO VG 68")
    model = get_model("complete")
    import numpy as np

    one = np.asarray(100.0)
    with pytest.raises(BallScrewInputError) as info:
        model(screw, oil, one, np.asarray(40.0), np.asarray(1000.0), seal_torque=50.0)
    assert info.value.field == "seal_torque"


def test_a_wiper_drag_on_many_screws_is_judged_by_the_screw_furthest_past_its_bound() -> None:
    # Many screws at once (friction_torques' ScrewArray): 1 N*m is 2x the typical 0.5 N*m
    # of a 40 mm screw but 50x the 0.0125 N*m of a 6.3 mm one (the bound scales as d^2), so
    # the batch is refused and the message names the small screw.
    import numpy as np

    from ballscrew.plausible import check_wiper_drag

    with pytest.raises(BallScrewInputError, match=r"6\.3 mm screw") as info:
        check_wiper_drag("seal_torque", 1.0, np.array([[0.040], [0.0063]]), warn_above=False)
    assert info.value.value == "1 N*m"
    check_wiper_drag("seal_torque", 1.0, np.array([[0.040], [0.050]]), warn_above=False)
