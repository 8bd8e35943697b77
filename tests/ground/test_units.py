"""Quantities as engineers type them: each read as meant or refused, never silently changed.

SLIPS is the list of plausible inputs of issue 27 (number formats, speeds in the
notation of catalogues, leads per revolution, unit spellings, expression bombs).
Each expected value is worked out by hand here, not by the code under test: a
revolution is 2 pi rad, a minute 60 s, 1 kN 1000 N, 1 cSt 1e-6 m^2/s.
"""

from __future__ import annotations

import math
import time
import warnings

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ballscrew.errors import BallScrewInputError, BallScrewReadingWarning
from ballscrew.io.units import parse_range, to_si

RPM = 2.0 * math.pi / 60.0  # rad/s per rev/min
RPS = 2.0 * math.pi  # rad/s per rev/s
REFUSED = None

# (target SI unit, text, the value meant in SI, or REFUSED)
SLIPS: list[tuple[str, str, float | None]] = [
    # speeds as European catalogues and drives write them: revolutions
    ("rad/s", "3000 rpm", 3000 * RPM),
    ("rad/s", "3000 RPM", 3000 * RPM),
    ("rad/s", "3000 1/min", 3000 * RPM),
    ("rad/s", "3000 min^-1", 3000 * RPM),
    ("rad/s", "3000 min**-1", 3000 * RPM),
    ("rad/s", "3000 min⁻¹", 3000 * RPM),
    ("rad/s", "3000 min-1", 3000 * RPM),
    ("rad/s", "3000 rev/min", 3000 * RPM),
    ("rad/s", "3000 r/min", 3000 * RPM),
    ("rad/s", "3000 U/min", 3000 * RPM),
    ("rad/s", "50 rps", 50 * RPS),
    ("rad/s", "50 rev/s", 50 * RPS),
    ("rad/s", "50 Hz", 50 * RPS),  # with a note: Hz read as revolutions per second
    ("rad/s", "314.16 rad/s", 314.16),
    ("rad/s", "314.159 rad/s", REFUSED),  # a point before 3 digits: 314159 or 314.159?
    ("rad/s", "3.000 rpm", REFUSED),  # 0.2.0: 3 rpm (3000 in German notation)
    ("rad/s", "1.500 U/min", REFUSED),  # 0.2.0: 1.5 rpm
    ("rad/s", "18000 deg/s", 18000 * math.pi / 180.0),
    ("rad/s", "3 000 rpm", 3000 * RPM),
    ("rad/s", "1,5 rps", 1.5 * RPS),
    ("rad/s", "3000", REFUSED),  # no unit
    ("rad/s", "10 m/min", REFUSED),  # a table speed is not a screw speed
    ("rad/s", "10**10**8 rpm", REFUSED),  # an expression, not a number
    ("rad/s", "1e400 rpm", REFUSED),  # not finite
    ("rad/s", "3000 rpm" + " " * 5 + "x" * 200, REFUSED),  # too long
    ("rad/s", "3000 " + "a" * 30, REFUSED),  # a unit name no unit has
    # leads: per revolution
    ("m/turn", "10 mm", 0.010),
    ("m/turn", "10 mm/rev", 0.010),
    ("m/turn", "10 mm/revolution", 0.010),
    ("m/turn", "10 mm/turn", 0.010),
    ("m/turn", "1 cm/rev", 0.010),
    ("m/turn", "10 mm/s", REFUSED),
    ("m", "6.35 mm/rev", REFUSED),  # a ball diameter is not per revolution
    # forces: spaces and commas
    ("N", "1 200 N", 1200.0),
    ("N", "1\u00a0200 N", 1200.0),  # no-break space
    ("N", "1\u202f200 N", 1200.0),  # narrow no-break space
    ("N", "1'200 N", 1200.0),
    ("N", "1 000 N", 1000.0),
    ("N", "1 200 000 N", 1.2e6),
    ("N", "1,2 kN", 1200.0),
    ("N", "2,5 kN", 2500.0),
    ("N", "0,5 kN", 500.0),
    ("N", "1.200,5 N", 1200.5),
    ("N", "1,200.5 N", 1200.5),
    ("N", "1.2 kN", 1200.0),
    ("N", "1,200 N", REFUSED),  # 1200 or 1.2? both are shown
    ("N", "1 20 N", REFUSED),  # not groups of three
    ("N", "12 00 N", REFUSED),
    ("N", "1,2,3 N", REFUSED),
    ("N", "−2 kN", -2000.0),  # unicode minus
    ("N", "-2 kN", -2000.0),
    ("N", "2e3 N", 2000.0),
    ("N", "2,5e3 N", 2500.0),
    ("N", "2 kN*m", REFUSED),  # a torque for a force
    ("N", "2 kgf", 2 * 9.80665),
    ("N", "1/2 kN", 500.0),  # a fraction is one number (issue 40)
    ("N", "½ kN", 500.0),
    ("N", "2 k N", REFUSED),  # k alone is no unit... of force
    # torques
    ("N*m", "0,5 Nm", 0.5),
    ("N*m", "0.5 N*m", 0.5),
    ("N*m", "0.5 N·m", 0.5),
    ("N*m", "0.5 N m", 0.5),
    ("N*m", "500 Nmm", 0.5),
    ("N*m", "50 Ncm", 0.5),
    ("N*m", "0.5 kNm", 500.0),
    ("N*m", "500 N*mm", 0.5),
    # temperatures, viscosities, angles, lengths, inertia
    ("degC", "40 °C", 40.0),
    ("degC", "40 degC", 40.0),
    ("degC", "313,15 K", 40.0),
    ("degC", "104 degF", 40.0),
    ("degC", "40 C", 40.0),  # coulomb to pint: read as degC on a temperature, with a note
    ("m**2/s", "68 cSt", 68e-6),
    ("m**2/s", "68 mm²/s", 68e-6),
    ("m**2/s", "68 mm2/s", 68e-6),
    ("m**2/s", "68 mm^2/s", 68e-6),
    ("rad", "45 deg", math.pi / 4),
    ("rad", "45°", math.pi / 4),
    ("rad", "45 %", REFUSED),
    ("rad", "45", REFUSED),
    ("m", "32 mm", 0.032),
    ("m", "3,2 cm", 0.032),
    ("m", ".5 mm", 0.0005),
    ("m", "1.26 in", 1.26 * 0.0254),
    ("m", "5. mm", REFUSED),
    ("m", "mm", REFUSED),
    ("kg*m**2", "1.9e-3 kg·m²", 1.9e-3),
    ("kg*m**2", "1,9 kg*cm^2", 1.9e-4),
    # shop-floor notation (issue 40): an inch is 25.4 mm exactly, g_n 9.80665 m/s^2 exactly
    ("m", "1/4 in", 0.25 * 0.0254),
    ("m", '1.329"', 1.329 * 0.0254),  # a point before three digits: decimal with inches
    ("m", "1.329''", 1.329 * 0.0254),
    ("m", "1.329\u2033", 1.329 * 0.0254),  # double prime
    ("m", "0.25 inch", 0.25 * 0.0254),
    ("m", "1 1/4 in", 1.25 * 0.0254),
    ("m", '3/8"', 0.375 * 0.0254),
    ("m", "5/32 in", 5 / 32 * 0.0254),  # the bundled case's ball
    ("m", "1½ in", 1.5 * 0.0254),
    ("m", "⅜ in", 0.375 * 0.0254),
    ("m", "1/4in", 0.25 * 0.0254),
    ("m", "2 ft", 2 * 12 * 0.0254),
    ("m", "1-1/4 in", REFUSED),  # 1.25 to a machinist, 0.75 to arithmetic
    ("m", "1 5/4 in", REFUSED),  # a whole number and an improper fraction
    ("m", "1/0 in", REFUSED),
    ("m", "1.5/2 in", REFUSED),
    ("m", "1/2/3 in", REFUSED),
    ("m", "2'", REFUSED),  # a foot, an arcminute or a thousands mark
    ("m", "2\u2032", REFUSED),
    ("m", '1,329"', REFUSED),  # a comma before three digits stays ambiguous
    ("m", "1.329 mm", REFUSED),  # ... and a point, in millimetres
    ("m/s", "39.370 in/min", 39.37 * 0.0254 / 60),
    ("m/s", "40 in/min", 40 * 0.0254 / 60),
    ("m/s**2", "0.3 g", 0.3 * 9.80665),  # standard gravity on an acceleration
    ("m/s**2", "0.3 G", 0.3 * 9.80665),  # (pint: gauss)
    ("m/s**2", "2 m/s^2", 2.0),
    ("kg", "300 g", 0.3),  # a mass keeps its grams
    ("m", "5 g", REFUSED),  # a gram is no length
    ("N", "5 lbf", 5 * 0.45359237 * 9.80665),
    ("N", "5 lb", REFUSED),  # a mass: 'lbf' is the force
    ("N*m", "10 lbf*in", 10 * 0.45359237 * 9.80665 * 0.0254),
    ("degC", "104 F", 40.0),  # farad to pint: read as degF on a temperature, with a note
    ("degC", "40 ° C", 40.0),  # a degree sign, a space, C: on a temperature only degC
    ("degC", "40 deg C", 40.0),
    ("degC", "104 deg F", 40.0),
    ("degC", "40 c", REFUSED),  # the speed of light
    ("degC", "40 °", REFUSED),  # an angle
    ("delta_degC", "5 C", 5.0),  # a difference of 5 K (issue 35)
    ("delta_degC", "9 F", 5.0),
    ("m", "32 C", REFUSED),  # a coulomb is no length
]


def test_the_list_holds_at_least_sixty_slips() -> None:
    assert len(SLIPS) >= 60


@pytest.mark.parametrize(("unit", "text", "meant"), SLIPS)
def test_each_slip_is_read_as_meant_or_refused(unit: str, text: str, meant: float | None) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", BallScrewReadingWarning)
        if meant is None:
            with pytest.raises(BallScrewInputError, match=r"^field = "):
                to_si("field", text, unit)
        else:
            # 1e-12: the conversion factors are exact or pint's defined constants.
            assert to_si("field", text, unit) == pytest.approx(meant, rel=1e-12, abs=1e-15)


@pytest.mark.parametrize(
    ("text", "shown"),
    [("1,200 N", r"'1200 N' or '1\.2 N'"), ("1.200 N", r"'1200 N' or '1\.2 N'"),
     ("3.000 rpm", r"'3000 rpm' or '3 rpm'")],
)  # fmt: skip
def test_a_number_read_two_ways_shows_both_readings(text: str, shown: str) -> None:
    with pytest.raises(BallScrewInputError, match=shown):
        to_si("screw.preload", text, "rad/s" if "rpm" in text else "N")


@pytest.mark.parametrize(
    ("text", "meant"), [("3.969 mm", 3.969e-3), ("6,350 mm", 6.35e-3), ("4.762 mm", 4.762e-3)]
)
def test_the_fields_range_settles_a_number_read_two_ways(text: str, meant: float) -> None:
    # A ball of 3969 mm is none: inside a ball diameter's range only one reading remains.
    assert to_si("screw.ball_diameter", text, "m", plausible=(0.3e-3, 0.1)) == meant


def test_a_range_holding_both_readings_settles_nothing() -> None:
    with pytest.raises(BallScrewInputError, match=r"'1200 kg' or '1\.2 kg'"):
        to_si("axis.moving_mass", "1.200 kg", "kg", plausible=(0.0, 1e5))


@pytest.mark.parametrize("text", ["50 Hz", "100 1/s", "2 kHz"])
def test_a_speed_in_hertz_is_read_as_revolutions_and_says_so(text: str) -> None:
    with pytest.warns(BallScrewReadingWarning, match="rpm; for radians per second") as caught:
        to_si("speed", text, "rad/s")
    assert "revolutions per second" in str(caught[0].message)


@pytest.mark.parametrize("text", ["3000 1/min", "3000 min^-1", "3000 rpm", "300 rad/s"])
def test_speeds_that_say_what_they_mean_need_no_note(text: str) -> None:
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        to_si("speed", text, "rad/s")


@pytest.mark.parametrize(
    ("text", "values"),
    [
        ("10, 100, 1000 rpm", [10 * RPM, 100 * RPM, 1000 * RPM]),
        ("1 000, 2 000 N", [1000.0, 2000.0]),
        ("1,2; 2,5 kN", [1200.0, 2500.0]),  # semicolons: commas are decimal
        ("0,5..2,5:3 kN", [500.0, 1500.0, 2500.0]),
        ("0..3000 1/min:3", [0.0, 1500 * RPM, 3000 * RPM]),
        ("10 rpm..100 rpm:2", [10 * RPM, 100 * RPM]),
    ],
)
def test_lists_and_ranges(text: str, values: list[float]) -> None:
    unit = "N" if text.endswith("N") else "rad/s"
    assert parse_range("x", text, unit) == pytest.approx(values, rel=1e-12)


@pytest.mark.parametrize("text", ["1,2 kN", "10,100,1000 rpm", "2,5"])
def test_a_comma_between_digits_in_a_list_is_refused_with_both_readings(text: str) -> None:
    with pytest.raises(BallScrewInputError, match=r"ambiguous in a list: two values .* decimal"):
        parse_range("--axial-load", text, "N")


@pytest.mark.parametrize(
    "text", ["10**10**8 rpm", "1 " + "m" * 20_000, "9" * 5000 + " rpm", "(((((rpm)))))"]
)
def test_bombs_are_refused_at_once(text: str) -> None:
    start = time.process_time()
    with pytest.raises(BallScrewInputError):
        to_si("speed", text, "rad/s")
    # The grammar refuses before the unit library parses: far under a second of CPU.
    assert time.process_time() - start < 0.5


# --- the fuzzer: numbers written every way, units with known factors ------------------------
UNITS = {  # unit text: (target, factor to the target's SI unit)
    "N": ("N", 1.0),
    "kN": ("N", 1e3),
    "mm": ("m", 1e-3),
    "µm": ("m", 1e-6),
    "rpm": ("rad/s", RPM),
    "1/min": ("rad/s", RPM),
    "min⁻¹": ("rad/s", RPM),
    "rad/s": ("rad/s", 1.0),
    "N·m": ("N*m", 1.0),
    "Nmm": ("N*m", 1e-3),
    "cSt": ("m**2/s", 1e-6),
}
SPACES = [" ", "\u00a0", "\u2009", "\u202f", "'"]


def _grouped(whole: str, sep: str) -> str:
    head = len(whole) % 3 or 3
    return sep.join([whole[:head]] + [whole[i : i + 3] for i in range(head, len(whole), 3)])


@st.composite
def written(draw: st.DrawFn) -> tuple[str, float, str, float]:
    """A quantity written one of the ways people write it, and the value it means."""
    whole = draw(st.integers(0, 9_999_999))
    fraction = draw(st.text("0123456789", min_size=0, max_size=4))
    unit = draw(st.sampled_from(sorted(UNITS)))
    negative = draw(st.booleans())
    style = draw(st.sampled_from(["plain", "comma", "grouped", "grouped-comma", "exponent"]))
    digits = str(whole)
    if style in ("grouped", "grouped-comma"):
        digits = _grouped(digits, draw(st.sampled_from(SPACES)))
    mark = "," if style in ("comma", "grouped-comma") else "."
    number = digits + (mark + fraction if fraction else "")
    exponent = draw(st.integers(-6, 6)) if style == "exponent" else 0
    text = number + (f"e{exponent}" if style == "exponent" else "")
    sign = draw(st.sampled_from(["-", "\u2212"])) if negative else ""
    value = float(f"{whole}.{fraction or 0}e{exponent}") * (-1 if negative else 1)
    target, factor = UNITS[unit]
    return f"{sign}{text} {unit}", value * factor, target, factor


@settings(max_examples=400, deadline=None)
@given(case=written())
def test_a_number_in_any_format_is_read_right_or_refused(
    case: tuple[str, float, str, float],
) -> None:
    text, meant, target, _ = case
    try:
        got = to_si("x", text, target)
    except BallScrewInputError as exc:
        # Refused only where the text could mean two numbers: a mark then three digits, or
        # three digits, a space and a group that may be a second value.
        said = str(exc)
        assert "thousands or be a decimal" in said or "or separate two values" in said, text
        return
    # Each format is exact decimal text; the conversion adds one rounding: 1e-12.
    assert got == pytest.approx(meant, rel=1e-12, abs=1e-300), text


@settings(max_examples=200, deadline=None)
@given(
    number=st.floats(0.001, 1e6),
    junk=st.text(st.characters(codec="utf-8", exclude_categories=("Cs",)), min_size=1, max_size=12),
)
def test_a_unit_of_any_text_is_a_known_unit_or_refused(number: float, junk: str) -> None:
    text = f"{number!r} {junk}"
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", BallScrewReadingWarning)
            got = to_si("x", text, "N")
    except BallScrewInputError:
        return
    # Accepted: then it is a force unit pint knows, and the number scaled by its factor.
    from ballscrew.io.units import parse_unit, registry

    factor = registry().Quantity(1.0, parse_unit("x", junk.strip())).to("N").magnitude
    assert got == pytest.approx(number * factor, rel=1e-12), text


def test_a_quantity_read_again_gives_the_same_number_and_a_note_every_time() -> None:
    # to_si keeps what it read (a selection parses one case text per candidate): the
    # number read again is the first reading's, and a reading with a note is not kept,
    # so that each read tells it.
    assert to_si("lead", "10 mm", "m/turn") == to_si("lead", "10 mm", "m/turn") == 0.01
    for _ in range(2):
        notes: list = []  # type: ignore[type-arg]
        assert to_si("speed", "50 Hz", "rad/s", notes) == pytest.approx(2 * math.pi * 50)
        assert len(notes) == 1 and "revolutions per second" in str(notes[0])


def test_a_list_comma_before_three_digits_names_the_thousands_reading_too() -> None:
    # '1,200 N' in a list field reads three ways; the one most users mean (1200 N) was left
    # out of the message (a newcomer's trial). A comma before 1 or 2 digits has no such reading.
    with pytest.raises(BallScrewInputError, match=r"thousands \('1200'\)"):
        parse_range("--axial-load", "1,200 N", "N")
    with pytest.raises(BallScrewInputError) as info:
        parse_range("--axial-load", "1,5 kN", "N")
    assert "thousands" not in info.value.allowed


@pytest.mark.parametrize(
    ("text", "read"),
    [("20 K", -253.15), ("0 K", -273.15), ("1000 degF", 537.778), ("-150 degC", -150.0)],
)
def test_a_temperature_no_machine_can_have_is_refused_as_typed(text: str, read: float) -> None:
    # 20 K is -253.15 degC (pint's absolute kelvin): typed for a machine's ambient it cooled
    # the screws to -150 degC. The message names the text as typed and its reading.
    with pytest.raises(BallScrewInputError) as info:
        to_si("machine.ambient", text, "degC")
    said = str(info.value)
    assert f"machine.ambient = '{text}'" in said and f"read as {read:.6g} degC" in said
    # Kelvin's hint only where kelvin was typed (issue 52: '900 degC' got it too).
    assert ("a temperature in K is absolute" in said) is text.endswith(" K")
    with pytest.raises(BallScrewInputError):  # in a list too, and at either end of a range
        parse_range("--temperature", f"20 degC, {text}", "degC")


def test_temperatures_a_machine_can_have_and_rises_pass() -> None:
    # The range's ends are read (-100 and 400 degC); 313.15 K is 40 degC; a rise of 300 K is a
    # difference, not a temperature.
    assert to_si("t", "-100 degC", "degC") == -100.0
    assert to_si("t", "400 degC", "degC") == 400.0
    assert to_si("t", "313.15 K", "degC") == pytest.approx(40.0, abs=1e-12)
    assert to_si("rise", "300 K", "delta_degC") == 300.0


@pytest.mark.parametrize(
    ("text", "read"),
    [("1 200 N", 1200.0), ("12 500 N", 12500.0), ("100 000 N", 100000.0),
     ("100'200 N", 100200.0), ("250 050 N", 250050.0)],
)  # fmt: skip
def test_space_grouped_thousands_are_read(text: str, read: float) -> None:
    assert to_si("axial_load", text, "N") == read


@pytest.mark.parametrize("text", ["100 200 N", "100 200 300 N", "999 100 N"])
def test_three_digits_then_a_space_that_may_be_a_lost_comma_is_refused(text: str) -> None:
    # Issue 52: '100 200 N' was read as 100 200 N with a warning only; it reads as well as
    # '100, 200 N' with the comma forgotten. Both ways of writing it are shown.
    with pytest.raises(BallScrewInputError) as info:
        to_si("axial_load", text, "N")
    said = str(info.value)
    assert "group thousands or separate two values" in said
    assert f"'{text[:3]}, " in said  # the reading as several values
