"""Units as shop floors type them (issue 40, item 5): read as meant, or refused saying why.

The values meant are worked out here from the definitions, not by the code under test:
an inch is 25.4 mm exactly, the standard gravity 9.80665 m/s^2 exactly (CGPM 1901), a
pound 0.45359237 kg exactly, so a pound-force is 4.4482216152605 N.
"""

from __future__ import annotations

import warnings

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ballscrew.errors import BallScrewInputError, BallScrewReadingWarning
from ballscrew.io.units import parse_range, to_si

INCH = 0.0254
G_N = 9.80665


@pytest.mark.parametrize(
    ("field", "text", "unit", "why", "works"),
    [
        # wrong dimension: what the unit is, what the field is, a form that works
        ("screw.ball_diameter", "5 g", "m", "'g' (gram) is a mass; this field is a length",
         "give a length in e.g. 'mm'"),
        ("axis.moving_mass", "0.3 m/s^2", "kg", "is an acceleration; this field is a mass",
         "give a mass in e.g. 'kg'"),
        ("screw.pitch_diameter", "32 C", "m", "'C' (coulomb) is an electric charge",
         "give a length in e.g. 'mm'"),  # a number shown on another scale could mislead
        ("operation.temperature", "40 c", "degC", "'c' (speed of light) is a linear speed; this "
         "field is a temperature", "'40 degC'"),
        ("operation.temperature", "40 °", "degC", "(degree) is a plain number (an angle or a "
         "ratio); this field is a temperature", "'40 degC'"),
        ("screw.preload", "5 lb", "N", "'lb' (pound) is a mass; this field is a force (a force in "
         "pounds is 'lbf'", "give a force in e.g. 'kN'"),  # not '5 kN': 5 lb is 22 N
        ("screw.ball_diameter", "6.35 mm/rev", "m", "is per revolution, which this field is not",
         "'6.35 mm'"),
        ("screw.pitch_diameter", "5 MM", "m", "(megamolar)", "did you mean 'mm'?"),
        # unknown units: the name, a close one of the field's kind
        ("screw.preload", "5 KN", "N", "'KN' is not a known unit; did you mean 'kN'?", "'5 kN'"),
        ("speed", "3000 rmp", "rad/s", "'rmp' is not a known unit; did you mean 'rpm'?",
         "'3000 rpm'"),
        ("screw.lead", "20 mn", "m", "'mn' is not a known unit; did you mean 'm'", "'20 mm'"),
        ("screw.preload", "5 Newton", "N", "did you mean 'newton'?", "'5 newton'"),  # not 5 kN
        # a bare number where a unit is required
        ("screw.pitch_diameter", "32", "m", "a bare number has no unit", "'32 mm'"),
        # notations refused because they read two ways
        ("screw.pitch_diameter", "2'", "m", "a foot to some and an arcminute to others",
         "'2 ft'"),
        ("screw.pitch_diameter", "1-1/4 in", "m", "1 1/4 (1.25) in shop notation but 1 minus 1/4 "
         "(0.75) in arithmetic", "'1 1/4' or '1.25'"),
        ("screw.pitch_diameter", "1 5/4 in", "m", "a whole number and a proper fraction",
         "'1 1/4 in'"),
        ("screw.pitch_diameter", "1.5/2 in", "m", "a fraction of whole numbers", "'0.25 in'"),
        ("screw.pitch_diameter", "1/0 in", "m", "denominator is not 0", ""),
        ("screw.pitch_diameter", '1,329"', "m", "a comma before three digits",
         """'1329 "' or '1.329 "'"""),
    ],
)  # fmt: skip
def test_each_refusal_names_the_field_the_value_why_and_the_working_form(
    field: str, text: str, unit: str, why: str, works: str
) -> None:
    with pytest.raises(BallScrewInputError) as err:
        to_si(field, text, unit)
    message = str(err.value)
    assert message.startswith(f"{field} = {text!r} is not allowed: "), message
    assert why in message and works in message, message


@pytest.mark.parametrize(
    ("text", "unit", "meant", "note"),
    [
        ("40 C", "degC", 40.0, "'C' alone is the coulomb, a unit of charge; write '40 degC'"),
        ("104 F", "degC", 40.0, "'F' alone is the farad, a unit of capacitance; write '104 degF'"),
        # on a temperature difference, C and F are differences (issue 35): 9 degF is 5 K
        ("5 C", "delta_degC", 5.0, "a difference in °C"),
        ("9 F", "delta_degC", 5.0, "a difference in °F"),
    ],
)
def test_a_temperature_in_c_or_f_is_read_with_a_note_naming_the_field(
    text: str, unit: str, meant: float, note: str
) -> None:
    with pytest.warns(BallScrewReadingWarning) as caught:
        got = to_si("check.pretension_temperature", text, unit)
    # degF to degC: (104 - 32) * 5/9; pint's offset arithmetic rounds in the last bits.
    assert got == pytest.approx(meant, rel=1e-12)
    assert len(caught) == 1
    message = str(caught[0].message)
    assert message.startswith(f"check.pretension_temperature = {text!r} is read as"), message
    assert note in message


def test_a_temperature_in_c_is_noted_once_in_a_list() -> None:
    notes: list[object] = []
    assert parse_range("operation.temperature", "20, 40 C", "degC", notes=notes) == [20.0, 40.0]
    assert len(notes) == 1 and "coulomb" in str(notes[0])


@pytest.mark.parametrize(
    ("text", "meant"),
    [("0.3 g", 0.3 * G_N), ("0.3 G", 0.3 * G_N), ("1/2 g", 0.5 * G_N), ("2.94 m/s^2", 2.94)],
)
def test_g_on_an_acceleration_is_the_standard_gravity(text: str, meant: float) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no note: g on an acceleration means one thing
        assert to_si("--move acceleration", text, "m/s**2") == pytest.approx(meant, rel=1e-12)


def test_a_mass_keeps_its_grams() -> None:
    assert to_si("axis.nut_mass", "300 g", "kg") == pytest.approx(0.3, rel=1e-12)


@pytest.mark.parametrize(
    ("text", "meant"),
    [
        ("1/4 in", 0.25 * INCH),
        ('1.329"', 1.329 * INCH),
        ("0.25 inch", 0.25 * INCH),
        ("1 1/4 in", 1.25 * INCH),
        ('3/8"', 0.375 * INCH),
        ("3/8\u2033", 0.375 * INCH),  # a double prime
        ("3/8\u201d", 0.375 * INCH),  # a closing quote, as word processors type '"'
        ("1¼ in", 1.25 * INCH),
        ("-1/4 in", -0.25 * INCH),
    ],
)
def test_fractions_and_inch_marks(text: str, meant: float) -> None:
    # A fraction of small integers is exact before the one conversion: 1e-12.
    assert to_si("screw.pitch_diameter", text, "m") == pytest.approx(meant, rel=1e-12)


def test_fractions_in_lists_and_ranges() -> None:
    assert parse_range("x", '1/4, 3/8, 1 1/2"', "m") == pytest.approx(
        [0.25 * INCH, 0.375 * INCH, 1.5 * INCH], rel=1e-12
    )
    assert parse_range("x", "1/4..1/2:3 in", "m") == pytest.approx(
        [0.25 * INCH, 0.375 * INCH, 0.5 * INCH], rel=1e-12
    )


def test_a_speed_per_minute_is_no_fraction() -> None:
    # '3000 1/min': the 1 belongs to the unit, as before fractions were read.
    assert to_si("speed", "3000 1/min", "rad/s") == pytest.approx(100.0 * 3.141592653589793)


# --- the fuzzer: inch sizes written every way shop floors write them -------------------------
INCH_MARKS = ['"', " in", " inch", "\u2033", "''", " inches", "in"]


@st.composite
def inch_size(draw: st.DrawFn) -> tuple[str, float]:
    """An inch size as a fraction, a mixed number or a decimal, and the metres it means."""
    whole = draw(st.integers(0, 99))
    style = draw(st.sampled_from(["fraction", "mixed", "decimal", "vulgar"]))
    mark = draw(st.sampled_from(INCH_MARKS))
    if style == "decimal":
        digits = draw(st.text("0123456789", min_size=1, max_size=4))
        return f"{whole}.{digits}{mark}", float(f"{whole}.{digits}") * INCH
    if style == "vulgar":
        char, value = draw(st.sampled_from([("½", 0.5), ("¼", 0.25), ("¾", 0.75), ("⅜", 0.375)]))
        return f"{whole or ''}{char}{mark}", (whole + value) * INCH
    den = draw(st.sampled_from([2, 4, 8, 16, 32, 64]))
    num = draw(st.integers(1, den - 1 if style == "mixed" else 3 * den))
    if style == "mixed" and whole:
        return f"{whole} {num}/{den}{mark}", (whole + num / den) * INCH
    return f"{num}/{den}{mark}", num / den * INCH


@settings(max_examples=300, deadline=None)
@given(case=inch_size())
def test_an_inch_size_in_any_notation_is_read_as_meant(case: tuple[str, float]) -> None:
    text, meant = case
    # Every notation is exact decimal or rational text; one conversion rounds: 1e-12.
    assert to_si("screw.ball_diameter", text, "m") == pytest.approx(meant, rel=1e-12), text


@settings(max_examples=200, deadline=None)
@given(
    number=st.sampled_from(["1", "0.3", "1/4", "1 1/4", "40"]),
    unit=st.sampled_from(["g", "G", "C", "F", "c", "'", "′", "in", '"', "lbf", "lb", "kg", "K"]),
    target=st.sampled_from(["m", "kg", "N", "m/s**2", "degC", "delta_degC"]),
)
def test_a_shop_floor_unit_on_any_field_is_read_or_refused_with_the_reason(
    number: str, unit: str, target: str
) -> None:
    text = f"{number} {unit}"
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", BallScrewReadingWarning)
            to_si("field", text, target)
    except BallScrewInputError as exc:
        message = str(exc)
        # Refused: the message names the field and the text and says why, with a form.
        assert message.startswith(f"field = {text!r} is not allowed: "), message
        assert any(w in message for w in ("this field is", "write", "not a known unit")), message
