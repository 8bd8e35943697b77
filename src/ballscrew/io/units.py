r"""Units at the boundary: quantities typed by people ("25 mm", "2 kN") to SI floats.

This module is long on purpose: it is the one home of every conversion at the
boundary, so its strict grammar, unit names, ranges and messages agree, and the
forms it accepts are stated here in full.

All conversions of the case files, the command line, the web page and the
headers of measured curves go through this module. Inside the package
everything is SI (m, N, Pa, Pa·s, m²/s, rad/s, N·m) and temperatures are in °C.

Reading a quantity takes two steps. The text is first held against a strict
grammar (:func:`split_quantity`): a number, written the way engineers write
numbers, then a unit made of unit names joined by ``*``, ``/``, ``·`` or a
space, each with an optional small integer power. Nothing else reaches the unit
library (pint), so an expression such as ``10**10**8`` or a 20 kB unit name is
refused at once. Pint then converts the unit.

**Numbers.**

* The point is always a decimal point: ``1.5``, ``0.125``.
* In a single value a comma is a decimal comma: ``1,2 kN`` is 1.2 kN. After one
  to three digits, a comma followed by exactly three digits (``1,200``) may be a
  thousands separator or a decimal comma; it is refused, with both readings.
  In a list (``"10, 100, 1000 rpm"``) commas separate the values, so a comma
  between two digits is refused there, with both readings.
* Digits may be grouped by threes with a space (a no-break or thin space too)
  or an apostrophe: ``1 200 N``, ``1'200 N``. Any other grouping is refused: a
  space is never read as a multiplication. After three digits a space followed by
  a group that does not start with 0 (``100 200 N``) may also be two values whose
  comma was forgotten: it is refused, with both ways to write it (``100 000 N``
  and ``100'200 N`` are read as one number).
* With both a point and a comma, the last one is the decimal separator and the
  other groups thousands: ``1.200,5`` and ``1,200.5`` are both 1200.5.
* An exponent follows the digits: ``2.5e3``. The minus sign may be typed as ``−``.

**Speeds.** Catalogues write the speed of a screw as a frequency: ``n = 3000
1/min``. A speed given as a frequency without an angle (``1/min``, ``min^-1``,
``min⁻¹``, ``Hz``, ``1/s``) is therefore read as revolutions per unit time:
``3000 1/min`` is 3000 rpm, and ``50 Hz`` is 50 revolutions per second, 3000
rpm. Per second, some people mean radians (``ω = 100 1/s``): a speed in ``Hz``
or ``1/s`` is read as revolutions and the reading is noted, with the other one
and how to write it. ``rpm``, ``rev/min``, ``r/min``, ``U/min``, ``rps``,
``rad/s`` and ``deg/s`` say what they mean and are read without a note.

**Leads.** A lead is the advance per revolution: ``10 mm/rev`` and ``10 mm``
are the same lead.

**Other spellings.** ``Nm``, ``Ncm``, ``Nmm``, ``kNm`` are newton metres,
centimetres and millimetres (not pint's reading of ``Nm``); ``U`` is a
revolution (``U/min``), not an enzyme unit; ``RPM`` is ``rpm``.

**Shop-floor notation.** A fraction of whole numbers is one number, alone or
after a whole number and a space: ``1/4 in``, ``1 1/4 in``, ``5/32 in``, ``½ kN``,
``1½ in``. ``1-1/4`` is refused (one and a quarter to a machinist, three quarters
to arithmetic). A double quote, a double prime or two apostrophes after a number
is the inch (``1.329"``, ``3/8"``); with the inch a point before three digits is
a decimal point (inch sizes are written to thousandths and no one groups them),
a comma there stays ambiguous. A single apostrophe or prime is refused: a foot
to some, an arcminute to others, and a thousands mark in ``1'200``; write
``ft``. On an acceleration ``g`` and ``G`` are the standard gravity (``0.3 g`` is
2.942 m/s², not 0.3 gram); a mass keeps its grams. On a temperature ``C`` and
``F`` alone are °C and °F (pint's coulomb and farad), read with a note naming
the field; on a temperature difference they are a difference (``5 C`` is 5 K).

**Refusals** name the field and the text, say why (``'g' (gram) is a mass;
this field is a length``, ``'KN' is not a known unit; did you mean 'kN'?``) and
show a form that works (``write e.g. '5 mm'``).
"""

from __future__ import annotations

import functools
import importlib
import math
import re
import sys
import unicodedata
import warnings
from dataclasses import dataclass
from fractions import Fraction
from types import ModuleType
from typing import TYPE_CHECKING, Any

from ..errors import BallScrewInputError, BallScrewReadingWarning


def _import_pint_without_dask() -> ModuleType:
    """Pint, imported without its support for dask arrays.

    Pint looks for dask when it is imported (``importlib.util.find_spec``) and,
    finding it, imports ``dask.base`` to let quantities wrap dask arrays: about
    0.2 s of CPU in every command, though this package hands pint only strings
    and floats (units are converted to SI at the boundary). While pint is
    imported, a ``None`` entry for dask in ``sys.modules`` makes ``find_spec``
    answer that dask is absent; the entry is removed at once, so dask imports
    as usual afterwards (sweeps). Nothing changes if either is already imported.
    """
    if "pint" in sys.modules or "dask" in sys.modules:
        return importlib.import_module("pint")
    sys.modules["dask"] = None  # type: ignore[assignment]
    try:
        return importlib.import_module("pint")
    finally:
        real = sys.modules.pop("dask", None)
        if real is not None:  # a real dask module, not the entry set above: keep it
            sys.modules["dask"] = real


if TYPE_CHECKING:
    import pint


@functools.cache
def _pint() -> ModuleType:
    """Pint, imported on first use (0.1 s of CPU); :data:`PLAIN_FACTORS` are read without it."""
    return _import_pint_without_dask()


__all__ = [
    "MAX_TEXT",
    "Reading",
    "kind_of",
    "parse_range",
    "parse_speed_range",
    "parse_unit",
    "range_size",
    "registry",
    "split_quantity",
    "to_si",
    "to_si_array",
]

MAX_TEXT = 100
"""Characters a quantity, a list or a range may have (a unit name far fewer)."""

_MAX_WORD = 24  # characters of one unit name (pint's longest common ones: ~20)
_MAX_POWER = 4  # |power| of one unit name (m**3, s**-2; nothing needs more)


@functools.cache
def registry() -> pint.UnitRegistry:  # type: ignore[type-arg]
    """The package's pint unit registry.

    ``rev`` and ``r`` are added as names of the revolution (``rev/min``,
    ``r/min``). Pint's parsed unit definitions are cached on disk (its
    ``:auto:`` user cache folder), which cuts building the registry from about
    0.5 s to 0.04 s; where no cache folder can be written, the registry is
    built without one.
    """
    unit_registry = _pint().UnitRegistry
    ureg: pint.UnitRegistry  # type: ignore[type-arg]
    try:
        ureg = unit_registry(autoconvert_offset_to_baseunit=True, cache_folder=":auto:")
    except OSError:  # read-only home, no cache directory: parse the definitions
        ureg = unit_registry(autoconvert_offset_to_baseunit=True)
    ureg.define("@alias turn = rev = r")
    return ureg


# --- numbers ---------------------------------------------------------------------------------
_GROUPING = " \u00a0\u2009\u202f'\u2019"  # space, no-break, thin, narrow no-break; apostrophes
_DASHES = str.maketrans({"\u2212": "-", "\u2012": "-", "\u2013": "-", "\ufe63": "-"})
_NUMBER = re.compile(
    r"(?P<sign>[-+]?)\s*"
    r"(?P<digits>\d(?:[\d.," + _GROUPING + r"]*\d)?|[.,]\d+)"
    r"(?P<exponent>[eE][-+]?\d{1,3})?"
)


class AmbiguousNumberError(BallScrewInputError):
    """A number that reads two ways ('1,200', '3.000'); ``numbers`` holds both readings."""

    def __init__(
        self, field: str, value: Any, allowed: str, numbers: tuple[float, ...], unit_text: str
    ) -> None:
        super().__init__(field, value, allowed)
        self.numbers, self.unit_text = numbers, unit_text


class _NotOneNumberError(Exception):
    """The digits cannot be read as one number, or could be read two ways."""

    def __init__(self, why: str, readings: tuple[str, ...] = ()) -> None:
        super().__init__(why)
        self.why = why
        self.readings = readings


def _grouped(parts: list[str]) -> bool:
    """Digits grouped by threes: 1 to 3 digits, then groups of exactly 3."""
    return (
        all(p.isdigit() for p in parts)
        and 1 <= len(parts[0]) <= 3
        and (len(parts) == 1 or parts[0][0] != "0")  # '0 500' is two values, not 500
        and all(len(p) == 3 for p in parts[1:])
    )


def _digits_value(digits: str) -> str:
    """Plain decimal text of the digits as written (grouping and decimal comma resolved)."""
    parts = re.split("[" + _GROUPING + "]", digits)
    if len(parts) > 1:
        *head, last = parts
        tail = re.fullmatch(r"(\d+)(?:([.,])(\d+))?", last)
        if not tail or not _grouped([*head, tail.group(1)]):
            raise _NotOneNumberError(
                "a space inside a number is read only as a thousands separator, between "
                "groups of three digits (e.g. '1 200'); write the number without spaces, "
                "or separate several values with commas ('0, 500')"
            )
        later = [*head[1:], tail.group(1)]
        if len(head[0]) == 3 and re.search(r"\d\s\d", digits) and all(g[0] != "0" for g in later):
            # '1 200' and '12 500' group thousands, but '100 200' reads as well as two values
            # whose comma was forgotten ('100, 200'): neither reading is taken. A group that
            # starts with 0 is no value of its own ('100 000', '250 050': thousands).
            raise _NotOneNumberError(
                "a space after three digits may group thousands or separate two values: "
                f"write '{''.join(head) + tail.group(1)}' for one number, or "
                f"'{head[0]}, {', '.join(later)}' for several"
            )
        fraction = "." + tail.group(3) if tail.group(2) else ""
        return "".join(head) + tail.group(1) + fraction
    points, commas = digits.count("."), digits.count(",")
    if points + commas == 0:
        return digits
    if points and commas:
        decimal = "." if digits.rfind(".") > digits.rfind(",") else ","
        thousands = "," if decimal == "." else "."
        whole, fraction = digits.rsplit(decimal, 1)
        if decimal in whole or not _grouped(whole.split(thousands)):
            raise _NotOneNumberError("a point and a comma that do not make one number")
        return whole.replace(thousands, "") + "." + fraction
    mark = "." if points else ","
    groups = digits.split(mark)
    if len(groups) > 2:  # several marks: only thousands separators can repeat
        if not _grouped(groups):
            raise _NotOneNumberError(f"several '{mark}' that do not group the digits by threes")
        return "".join(groups)
    whole, fraction = groups
    if len(fraction) == 3 and 1 <= len(whole) <= 3 and whole[0] != "0":
        # '1,200' and '3.000' are each read one way in English and the other in German or
        # French: unless the field's range settles it (to_si's plausible), neither reading
        # is taken, and both are shown.
        name = "comma" if mark == "," else "point"
        raise _NotOneNumberError(
            f"a {name} before three digits may group thousands or be a decimal {name}",
            (whole + fraction, whole + "." + fraction),
        )
    return (whole or "0") + "." + fraction


def split_quantity(field: str, text: str) -> tuple[float, str]:
    """The number and the unit text of one quantity, after the grammar's checks.

    Parameters
    ----------
    field : str
        Name of the input, for error messages.
    text : str
        One quantity: ``"1 200 N"``, ``"1,2 kN"``, ``"3000 1/min"``, ``"-5e3 N*m"``.

    Returns
    -------
    tuple of (float, str)
        The number and the unit text, canonical for pint ("" for none).

    Raises
    ------
    BallScrewInputError
        Text that is not a number followed by a unit of the grammar (module
        docstring), or a number that could be read two ways (both are shown).

    Examples
    --------
    >>> split_quantity("preload", "1 200 N")
    (1200.0, 'N')
    >>> split_quantity("preload", "1,2 kN")
    (1.2, 'kN')
    >>> split_quantity("speed", "3000 min⁻¹")
    (3000.0, 'min**-1')
    >>> split_quantity("torque", "0,25 Nm")
    (0.25, '(N*m)')
    """
    raw = _clean(field, text).translate(_VULGAR)
    fraction = _fraction(field, text, raw)
    if fraction is not None:
        return fraction
    match = _NUMBER.match(raw)
    if not match:
        if re.match(r"[-+]?(nan|inf)", raw, re.IGNORECASE):
            raise BallScrewInputError(field, text, "a finite number with its unit, e.g. '1.5 kN'")
        raise BallScrewInputError(field, text, "a number followed by its unit, e.g. '1.5 kN'")
    digits, rest = match.group("digits"), raw[match.end() :]
    one = re.match(r"^(.*\d)\s+1$", digits)  # "3000 1/min": the 1 belongs to the unit
    if one and re.match(r"\s*/", rest) and not match.group("exponent"):
        digits, rest = one.group(1), "1" + rest
    try:
        plain = _digits_value(digits)
    except _NotOneNumberError as exc:
        if len(exc.readings) == 2 and "." in digits and _in_inches(field, text, rest):
            # Inches are written with a decimal point and to thousandths ('1.329"'); no one
            # groups the thousands of an inch size with a point.
            sign, exponent = match.group("sign"), match.group("exponent") or ""
            return float(sign + exc.readings[1] + exponent), _unit_text(field, text, rest)
        if not exc.readings:
            raise BallScrewInputError(field, text, f"one number: {exc.why}") from None
        shown = " or ".join(f"'{float(r):g}{(' ' + rest.strip()) if rest.strip() else ''}'"
                            for r in exc.readings)  # fmt: skip
        sign, exponent = match.group("sign"), match.group("exponent") or ""
        raise AmbiguousNumberError(
            field, text, f"one number: {exc.why} ({shown}?)",
            tuple(float(sign + r + exponent) for r in exc.readings), _unit_text(field, text, rest),
        ) from None  # fmt: skip
    number = float(match.group("sign") + plain + (match.group("exponent") or ""))
    return number, _unit_text(field, text, rest)


_VULGAR = {
    ord(c): f" {Fraction(unicodedata.numeric(c)).limit_denominator(10)}" for c in "½⅓⅔¼¾⅕⅖⅗⅘⅙⅚⅛⅜⅝⅞"
}
"""The vulgar-fraction characters as a space and 'n/d': '1½ in' is '1 1/2 in'."""
_FRACTION = re.compile(
    r"(?P<sign>[-+]?)\s*(?:(?P<whole>\d{1,9})(?P<joint>\s+|-))?"
    r"(?P<num>\d{1,9})\s*[/\u2044]\s*(?P<den>\d{1,9})(?![\d.,/\u2044])(?!\s*[eE][-+]?\d)"
)
_SLASHED_DIGITS = re.compile(r"\d\s*[/\u2044]\s*[-+]?\d")
_FRACTION_HELP = (
    "a fraction of whole numbers, alone or after a whole number and a space: "
    "'1/4 in', '3/8\"', '1 1/4 in' (or a decimal: '0.25 in')"
)


def _fraction(field: str, text: str, raw: str) -> tuple[float, str] | None:
    """A number written as a fraction ('1/4 in', '1 1/4 in', '3/8 in'), or None if it is none.

    Fractions are how inch sizes are written (a 5/32 in ball, a 1 1/4 in screw), and a
    fraction is one number in any unit. '1-1/4' is refused: one and a quarter to a
    machinist, three quarters to arithmetic.
    """
    match = _FRACTION.match(raw)
    if not match:
        if _SLASHED_DIGITS.search(raw):
            raise BallScrewInputError(field, text, _FRACTION_HELP)
        return None
    num, den = int(match.group("num")), int(match.group("den"))
    whole = match.group("whole")
    if den == 0:
        raise BallScrewInputError(field, text, "a fraction whose denominator is not 0")
    if whole is not None and match.group("joint") == "-":
        w = int(whole)
        raise BallScrewInputError(
            field, text,
            f"'{w}-{num}/{den}' is {w} {num}/{den} ({w + num / den:g}) in shop notation but "
            f"{w} minus {num}/{den} ({w - num / den:g}) in arithmetic: write "
            f"'{w} {num}/{den}' or '{w + num / den:g}' with the unit",
        )  # fmt: skip
    if whole is not None and num >= den:
        raise BallScrewInputError(
            field, text, f"a whole number and a proper fraction ('{whole} {num}/{den}' is none): "
            + _FRACTION_HELP,
        )  # fmt: skip
    value = Fraction(int(whole or 0)) + Fraction(num, den)
    number = float(-value if match.group("sign") == "-" else value)
    return number, _unit_text(field, text, raw[match.end() :])


def _in_inches(field: str, text: str, rest: str) -> bool:
    """Whether the unit is the inch, or the inch per a time ('1.329"', '39.370 in/min')."""
    words = re.findall(r"[^\W\d_][^\W\d]*", _unit_text(field, text, rest))
    return bool(words) and words[0] in ("inch", "in", "inches")


def _clean(field: str, text: str) -> str:
    raw = str(text).translate(_DASHES).strip()
    if len(raw) > MAX_TEXT:
        raise BallScrewInputError(
            field, f"{raw[:20]}... ({len(raw)} characters)", f"at most {MAX_TEXT} characters"
        )
    return raw


# --- units -----------------------------------------------------------------------------------
_SUPERSCRIPTS = str.maketrans("⁰¹²³⁴⁵⁶⁷⁸⁹⁻⁺", "0123456789-+")
_WORD = r"[^\W\d_](?:[^\W\d]*[^\W\d_])?|°[CF]?|%"
_UNIT_TOKEN = re.compile(
    r"\s*(?:(?P<one>1)(?=\s*/)|(?P<word>" + _WORD + r")"
    r"(?:\s*(?:\*\*|\^)\s*(?P<power>[-+]?\d+)|(?P<attached>[-+]?\d+)(?![\d.]))?"
    r"|(?P<op>[*/·⋅×])|(?P<paren>[()]))"
)
_ALIASES = {
    "U": "turn",  # Umdrehungen: U/min
    "RPM": "rpm",
    "Nm": "(N*m)",
    "Ncm": "(N*cm)",
    "Nmm": "(N*mm)",
    "kNm": "(kN*m)",
    "mNm": "(mN*m)",
}
_UNIT_HELP = (
    "a unit made of unit names joined by '*', '/' or '·' with small integer powers, "
    "e.g. 'mm', 'kN', 'rpm', 'N*m', 'mm**2/s'"
)


_INCH_MARKS = ("''", "\u2032\u2032", "\u2019\u2019", '"', "\u2033", "\u201d")
"""Marks read as the inch: a double quote, a double prime, a closing quote, two primes."""
_FOOT_MARKS = "'\u2032\u2019"
_FOOT_HELP = (
    "a single mark (') after a number is a foot to some and an arcminute to others, and "
    "groups thousands in 1'200: it is no unit here; write 'ft' for feet (e.g. '2 ft' or "
    "'24 in') or 'arcmin'"
)


def _marks(field: str, text: str, rest: str) -> str:
    """The inch marks of ``rest`` written as 'inch'; a foot or minute mark refused."""
    for mark in _INCH_MARKS:
        rest = rest.replace(mark, " inch ")
    if any(mark in rest for mark in _FOOT_MARKS):
        raise BallScrewInputError(field, text, _FOOT_HELP)
    return rest


def _unit_text(field: str, text: str, rest: str) -> str:
    """The unit part checked against the grammar and rewritten for pint ("" for none)."""
    rest = _marks(field, text, rest.translate(_SUPERSCRIPTS)).strip()
    out: list[str] = []
    depth, position, expect_unit = 0, 0, True
    while position < len(rest):
        token = _UNIT_TOKEN.match(rest, position)
        if not token or token.end() == position:
            shown = rest[position : position + 12].strip()
            raise BallScrewInputError(field, text, f"'{shown}' is not part of a unit: {_UNIT_HELP}")
        position = token.end()
        if token.group("word") or token.group("one"):
            if not expect_unit:
                out.append("*")  # "N m": a space between two units multiplies them
            word = token.group("word") or "1"
            power = token.group("power") or token.group("attached")
            if len(word) > _MAX_WORD or (power and abs(int(power)) > _MAX_POWER):
                why = (f"no unit has a name of {len(word)} letters" if len(word) > _MAX_WORD
                       else f"a power of at most {_MAX_POWER}")  # fmt: skip
                raise BallScrewInputError(field, text, f"{why}: {_UNIT_HELP}")
            out.append(_ALIASES.get(word, word) + (f"**{int(power)}" if power else ""))
            expect_unit = False
        elif token.group("op"):
            if expect_unit:
                why = f"'{token.group('op')}' needs a unit name on each side"
                raise BallScrewInputError(field, text, f"{why}: {_UNIT_HELP}")
            out.append("/" if token.group("op") == "/" else "*")
            expect_unit = True
        elif token.group("paren") == "(":
            if not expect_unit or depth >= 2:
                why = "brackets two deep at most" if depth >= 2 else "'(' after a unit name"
                raise BallScrewInputError(field, text, f"{why}: {_UNIT_HELP}")
            depth += 1
            out.append("(")
        else:
            if expect_unit or depth == 0:
                why = "')' without its '('" if depth == 0 else "'()' around no unit"
                raise BallScrewInputError(field, text, f"{why}: {_UNIT_HELP}")
            depth -= 1
            out.append(")")
    if depth or (out and expect_unit):
        why = "a bracket left open" if depth else "the unit ends with an operator"
        raise BallScrewInputError(field, text, f"{why}: {_UNIT_HELP}")
    return "".join(out)


def parse_unit(field: str, text: str) -> Any:
    """A pint unit from unit text alone (a column header's ``[unit]``), through the grammar.

    Examples
    --------
    >>> str(parse_unit("speed", "1/min"))
    '1 / minute'
    >>> str(parse_unit("torque", "Nmm"))
    'millimeter * newton'
    """
    raw = _clean(field, text)
    return _pint_unit(field, text, _unit_text(field, text, raw))


_TWO_WAY_UNITS = {
    "grad": "'grad' is a gradian (0.9 deg) to pint but a degree in German (Grad): write "
    "'deg' for degrees or 'gon' for gradians",
}
"""Unit names that are one unit to pint and another to people who type them: refused."""


_COMMON_UNITS = (
    "mm", "cm", "m", "um", "µm", "in", "inch", "ft", "N", "kN", "lbf", "kgf", "N*m", "Nm",
    "Nmm", "lbf*in", "rpm", "rev/min", "rad/s", "deg", "rad", "degC", "degF", "K", "kg", "g",
    "lb", "s", "min", "h", "Pa", "MPa", "GPa", "psi", "cSt", "mm**2/s", "mPa*s", "cP", "W",
    "kW", "hp", "J", "kJ", "Wh", "kWh", "m/s", "m/min", "mm/min", "in/min", "m/s**2", "Hz",
    "kg/m**3", "%",
)  # fmt: skip
"""The units suggested for a unit name that is none (close spellings, any case)."""


def _known(ureg: Any, word: str) -> bool:
    """Whether pint knows ``word`` as a unit ('nan' makes pint's own test raise ValueError)."""
    try:
        return word in ureg
    except (ValueError, TypeError, AttributeError, LookupError, ArithmeticError):
        return False


def _unknown_unit(
    unit: str, example: str, target: str | None = None, number_text: str | None = None
) -> str:
    """Why the unit text is no unit: the first name pint does not know, and a close one."""
    import difflib

    ureg = registry()
    words = re.findall(r"[^\W\d_][^\W\d]*", unit)
    unknown = next((w for w in words if not _known(ureg, w)), None)
    if unknown is None:
        return _UNIT_HELP + " (not a known unit)"
    lower = {u.lower(): u for u in _COMMON_UNITS}
    recased = unknown.lower() in lower or _known(ureg, unknown.lower())
    if unknown.lower() in lower:  # 'KN', 'MPA': the case is wrong
        close = [lower[unknown.lower()]]
    elif _known(ureg, unknown.lower()):  # 'Newton'
        close = [unknown.lower()]
    else:
        close = difflib.get_close_matches(unknown, _COMMON_UNITS, n=5, cutoff=0.6)
        if target:  # the field's own kind first: '20 mn' on a length is 'mm' before 'min'
            wanted = kind_of(target)
            close.sort(key=lambda c: kind_of(_ALIASES.get(c, c)) != wanted)
        close = close[:2]
    guess = f"; did you mean {' or '.join(repr(c) for c in close)}?" if close else ""
    if recased and number_text is not None and unknown == unit.strip():
        example = f"write e.g. '{number_text} {close[0]}'"  # the same unit, not another scale
    return f"'{unknown}' is not a known unit{guess} ({example})"


def _pint_unit(
    field: str, text: str, unit: str, number: Any = None, target: str | None = None
) -> Any:
    if unit.strip() in _TWO_WAY_UNITS:
        raise BallScrewInputError(field, text, _TWO_WAY_UNITS[unit.strip()])
    try:
        return registry().parse_units(unit) if unit else registry().dimensionless
    except (_pint().errors.PintError, ValueError, TypeError, AttributeError, AssertionError,
            ArithmeticError, LookupError, SyntaxError):  # fmt: skip
        example = (f"write e.g. '{_shown(number)} {_example(target)}'" if target
                   else "e.g. 'mm', 'kN', 'rpm', 'N*m', 'degC'")  # fmt: skip
        shown = _shown(number) if target else None
        why = _unknown_unit(unit, example, target, shown)
        raise BallScrewInputError(field, text, why) from None


# --- conversion ------------------------------------------------------------------------------
def _angle_power(unit: Any) -> int:
    """The power of the radian in a unit's root units (pint keeps the radian as a base unit)."""
    _, root = registry().get_root_units(unit)
    power: Any = root._units.get("radian", 0)  # a UnitsContainer: {name: power}
    return int(power)


@functools.cache
def _target(unit: str) -> tuple[Any, int]:
    parsed = registry().parse_units(unit)
    return parsed, _angle_power(parsed)


def _per_turn(field: str, text: str, unit: Any, target: str, number: Any = None) -> Any:
    """The factor that reads a frequency as revolutions, or a length as one per revolution.

    Pint counts the radian as 1, so without this "10 mm/rev" would become a lead
    of 1.6 mm and "3000 1/min" a speed of 477 rpm. The promotion applies only
    where the target has one power of the angle and a dimension besides it (a
    speed, a lead); a value with another power of the angle is refused.
    """
    ureg = registry()
    wanted, angle = _target(target)
    have = _angle_power(unit)
    if have == angle:
        return ureg.dimensionless
    factor = ureg.turn**angle
    if (
        have != 0
        or abs(angle) != 1
        or wanted.dimensionless
        or not (unit * factor).is_compatible_with(wanted)
    ):
        raise _wrong_dimension(field, text, number, unit, target)
    return factor


_KINDS = (
    ("m", "a length"), ("kg", "a mass"), ("s", "a time"), ("N", "a force"),
    ("N*m", "a torque or an energy"), ("Pa", "a pressure or a stress"),
    ("m/s", "a linear speed"), ("m/s**2", "an acceleration"), ("m/s**3", "a jerk"),
    ("K", "a temperature"), ("K/W", "a thermal resistance"),
    ("C", "an electric charge"), ("F", "a capacitance"), ("A", "an electric current"),
    ("V", "a voltage"), ("gauss", "a magnetic flux density"),
    ("Hz", "a frequency or a speed of rotation"), ("W", "a power"), ("m**2", "an area"),
    ("m**3", "a volume"), ("m**2/s", "a kinematic viscosity"), ("Pa*s", "a dynamic viscosity"),
    ("kg/m**3", "a density"), ("N/m", "a stiffness"), ("kg*m**2", "a moment of inertia"),
    ("1/Pa", "a pressure-viscosity coefficient"), ("", "a plain number (an angle or a ratio)"),
    ("N*m/A", "a torque constant (torque per current)"), ("ohm", "a resistance"),
)  # fmt: skip
"""Names of dimensions, for refusals: '0.3 g' is a mass; this field is an acceleration."""


@functools.cache
def _kind_names() -> dict[Any, str]:
    ureg = registry()
    return {ureg.parse_units(u).dimensionality if u else ureg.dimensionless.dimensionality: k
            for u, k in _KINDS}  # fmt: skip


def kind_of(unit: Any) -> str:
    """What a unit measures, in words: 'a length', 'a force', 'an electric charge'.

    Examples
    --------
    >>> kind_of("C"), kind_of("m/turn"), kind_of("delta_degC")
    ('an electric charge', 'a length', 'a temperature')
    """
    if isinstance(unit, str):
        return _kind_of_text(unit)
    dims = unit.dimensionality
    return _kind_names().get(dims, f"a quantity of dimension {dims}")


@functools.cache
def _kind_of_text(unit: str) -> str:
    return kind_of(registry().parse_units(unit))


def _wrong_dimension(
    field: str, text: str, number: Any, have: Any, target: str
) -> BallScrewInputError:
    """The refusal of a unit of another dimension: what the unit is, what the field is."""
    example = _example(target)
    name = str(have).replace("_", " ")
    symbol = f"{have:~}".replace(" ", "")
    wanted = kind_of(target)
    if kind_of(have) == wanted:  # the same dimension, another power of the angle
        per = "per revolution" if _angle_power(have) else "not per revolution"
        why = f"'{symbol}' ({name}) is {per}, which this field is not"
    else:
        why = f"'{symbol}' ({name}) is {kind_of(have)}; this field is {wanted}"
    close = {u.lower(): u for u in _COMMON_UNITS}.get(symbol.lower())
    if close and close != symbol and kind_of(close) == wanted:  # '5 MM': megamolar, or mm?
        why += f" (did you mean '{close}'?)"
    elif kind_of(have) == "a mass" and wanted == "a force":
        why += " (a force in pounds is 'lbf', in kilograms 'kgf')"
    if wanted == "a temperature":
        example = "degC"
    if kind_of(have) != wanted and wanted != "a temperature":
        # the number belongs to another quantity ('300 kg' is 2.9 kN, '3000 1/min' no feed):
        # show the unit to give it in, not the number on a scale it was not typed for
        return BallScrewInputError(field, text, f"{why}: give {wanted} in e.g. '{example}'")
    return BallScrewInputError(field, text, f"{why}: write e.g. '{_shown(number)} {example}'")


def _shown(number: Any) -> str:
    """A scalar as typed in an example ('40'); for a column of numbers (or none), 1."""
    return f"{float(number):g}" if isinstance(number, int | float) else "1"


_ACCELERATION_G = re.compile(r"(?<!\w)[gG](?!\w)")
_SPACED_DEGREES = re.compile(r"(?:°|deg|degree|degrees)\*([CF])")
_TEMPERATURE_LETTERS = {"C": ("degC", "°C", "the coulomb, a unit of charge"),
                        "F": ("degF", "°F", "the farad, a unit of capacitance")}  # fmt: skip


def _shop_unit(
    field: str, text: str, number: Any, unit_text: str, unit: str, notes: list[Reading] | None
) -> str:
    """Unit text as shop floors mean it where the field's dimension settles it.

    ``g`` (or ``G``) on an acceleration is the standard gravity, 9.80665 m/s² (to
    pint a gram, or a gauss); ``C`` and ``F`` alone on a temperature are degrees
    Celsius and Fahrenheit (to pint a coulomb and a farad), read with a note. Any
    other field keeps pint's reading (a mass in ``g`` stays grams).
    """
    kind = kind_of(unit)
    if kind == "an acceleration" and _ACCELERATION_G.search(unit_text):
        return _ACCELERATION_G.sub("standard_gravity", unit_text)
    if kind == "a temperature" and (spaced := _SPACED_DEGREES.fullmatch(unit_text)):
        return "deg" + spaced.group(1)  # '40 ° C', '40 deg C': degrees Celsius, nothing else
    if kind == "a temperature" and unit_text in _TEMPERATURE_LETTERS:
        written, symbol, pint_name = _TEMPERATURE_LETTERS[unit_text]
        n = _shown(number) + " "
        what = "a difference in " if unit == "delta_degC" else ""
        _tell([Reading(field, text, f"{what}{symbol}: '{unit_text}' alone is {pint_name}; "
                                    f"write '{n}{written}'")], notes)  # fmt: skip
        return written
    return unit_text


@dataclass(frozen=True)
class Reading:
    """How a text that could be meant two ways was read: the field, the text, the reading."""

    field: str
    text: str
    reading: str

    def __str__(self) -> str:
        given = f" = {self.text!r}" if self.text else ""
        return f"{self.field}{given} is read as {self.reading}"


def _frequency_note(field: str, text: str, number: Any, unit: Any) -> Reading | None:
    """How a speed in Hz or 1/s was read (per minute, nobody means radians)."""
    ureg = registry()
    if _angle_power(unit) or not unit.is_compatible_with(ureg.hertz):
        return None
    if "minute" in str(unit):
        return None
    per_second = ureg.Quantity(1.0, unit).to("1/s").magnitude
    if getattr(number, "ndim", 0) == 0:
        rps = float(number) * per_second
        shown = f"{rps:g} revolutions per second, {rps * 60.0:g} rpm"
    else:
        shown = f"revolutions per second (1 {unit:~} = {per_second * 60.0:g} rpm)"
        text = ""  # a column: its unit is in the field's name
    return Reading(field, text, f"{shown}; for radians per second write the unit rad/s")


def to_si(
    field: str,
    value: Any,
    unit: str | None,
    notes: list[Reading] | None = None,
    plausible: tuple[float, float] | None = None,
) -> float:
    """Convert ``value`` to the SI unit ``unit`` and return the magnitude.

    Parameters
    ----------
    field : str
        Name of the input, for error messages.
    value : str or number
        A quantity with its unit ("32 mm", "1,5 kN", "45 deg", "3000 rpm",
        "3000 1/min", "40 degC"), read by the grammar of the module docstring.
        A bare number is accepted only for a dimensionless quantity
        (``unit=""``): anywhere else it is an error that shows how to write it,
        since a number without a unit ("100" for a speed) is the commonest
        silent slip (rad/s or rpm? m or mm?).
    unit : str or None
        Target unit, in pint's notation ("m", "N", "rad", "rad/s", "m/turn",
        "degC"), or "" for a dimensionless number; "delta_degC" for a temperature
        difference, which reads "5 degC" and "5 K" alike as a difference of 5 K.
        None: whatever the value's unit is, converted to SI base units, and a bare
        number taken as SI (the convention of model parameters, whose units the
        models document).
    notes : list of Reading, optional
        Where to add how an ambiguous unit was read (a speed in Hz or 1/s);
        without it, a :class:`~ballscrew.errors.BallScrewReadingWarning`.
    plausible : (float, float), optional
        The field's plausible range in ``unit``: a number that reads two ways
        ("3.969 mm", "1,200 N") is taken in the one reading inside it; without a
        range, or with both readings (or none) inside, it is refused showing both.

    Examples
    --------
    >>> to_si("pitch_diameter", "32 mm", "m")
    0.032
    >>> round(to_si("speed", "3000 rpm", "rad/s"), 4)
    314.1593
    >>> round(to_si("speed", "3000 1/min", "rad/s"), 4)  # revolutions, as catalogues mean
    314.1593
    >>> to_si("preload", "1 200 N", "N"), to_si("preload", "1,2 kN", "N")
    (1200.0, 1200.0)
    >>> round(to_si("lead", "10 mm/rev", "m/turn"), 6), round(to_si("lead", "10 mm", "m/turn"), 6)
    (0.01, 0.01)
    >>> to_si("temperature", "313.15 K", "degC")
    40.0
    >>> to_si("rise", "5 degC", "delta_degC"), to_si("rise", "9 degF", "delta_degC")
    (5.0, 5.0)
    >>> to_si("speed", "100", "rad/s")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ballscrew.errors.BallScrewInputError: speed = '100' is not allowed: ...e.g. '100 rpm'...
    """
    if not isinstance(value, str):
        return _to_si(field, value, unit, notes, plausible)
    # A quantity read once is kept (a selection parses the same case text for thousands of
    # screws): the same text, unit and range give the same number. One read with a note
    # (an ambiguous unit) is not kept, so that its note is told every time.
    key = (field, value, unit, plausible)
    known = _READ.get(key)
    if known is not None:
        return known
    readings: list[Reading] = []
    result = _to_si(field, value, unit, readings, plausible)
    if readings:
        if notes is not None:
            notes.extend(readings)
        else:
            for reading in readings:
                warnings.warn(BallScrewReadingWarning(str(reading)), stacklevel=2)
    elif len(_READ) < _READ_MOST:
        _READ[key] = result
    return result


_READ: dict[tuple[str, str, str | None, tuple[float, float] | None], float] = {}
_READ_MOST = 100_000
"""The most quantities :func:`to_si` keeps."""


def _to_si(
    field: str,
    value: Any,
    unit: str | None,
    notes: list[Reading] | None,
    plausible: tuple[float, float] | None,
) -> float:
    """:func:`to_si` without its memory."""
    if isinstance(value, bool):
        wanted = "a number" if unit is None else f"a quantity in units of {unit}, e.g. '1 {unit}'"
        raise BallScrewInputError(field, value, wanted)
    if isinstance(value, int | float):
        if unit:
            raise _bare(field, value, unit)
        return _finite(field, value, float(value))
    try:
        number, unit_text = split_quantity(field, str(value))
    except AmbiguousNumberError as amb:
        if plausible is None:
            raise
        values = [_value_si(field, str(value).strip(), n, amb.unit_text, unit, notes)
                  for n in amb.numbers]  # fmt: skip
        inside = [v for v in values if plausible[0] <= v <= plausible[1]]
        if len(inside) != 1:
            raise
        # The other reading is outside the field's range (a 3969 mm ball): nothing to tell.
        return inside[0]
    return _value_si(field, str(value).strip(), number, unit_text, unit, notes)


TEMPERATURE_RANGE = (-100.0, 400.0)
"""Temperatures [degC] a quantity read for a temperature (not a difference) may have: from
arctic storage to well past any oil's flash point. Outside it the text cannot be meant (most
often kelvin typed for degrees Celsius)."""


def _value_si(
    field: str,
    text: str,
    number: float,
    unit_text: str,
    unit: str | None,
    notes: list[Reading] | None,
) -> float:
    """One number in ``unit_text`` to ``unit``: a bare number only where no unit is wanted."""
    if not unit_text and unit:
        raise _bare(field, text, unit)
    result = _finite(field, text, float(_convert(field, text, number, unit_text, unit, notes)))
    if unit == "degC" and not TEMPERATURE_RANGE[0] <= result <= TEMPERATURE_RANGE[1]:
        low, high = TEMPERATURE_RANGE
        kelvin = unit_text.strip().lower() in ("k", "kelvin", "kelvins")
        raise BallScrewInputError(
            field, text,
            f"a temperature from {low:g} to {high:g} degC, where a machine, its screw and its "
            f"oil can be (read as {result:.6g} degC"
            + ("; a temperature in K is absolute: '20 K' is -253 degC, write '20 degC')"
               if kelvin else ")"),
        )  # fmt: skip
    return result


def _finite(field: str, given: object, magnitude: float) -> float:
    """``magnitude`` if it is finite; else the error naming the value as ``given``."""
    if not math.isfinite(magnitude):
        raise BallScrewInputError(field, given, "a finite quantity")
    return magnitude


def _convert(
    field: str,
    text: str,
    number: Any,
    unit_text: str,
    unit: str | None,
    notes: list[Reading] | None,
) -> Any:
    """``number`` in ``unit_text`` converted to ``unit`` (a scalar or an array)."""
    if type(number) is float:  # what pint gives, to the last bit (tests/io/test_units_plain.py)
        plain = PLAIN_FACTORS.get((unit_text, unit))
        if plain is not None:
            return number * plain
        if (unit_text, unit) == ("degC", "degC"):
            return (number + 273.15) - 273.15  # pint's way: to kelvin and back
    ureg = registry()
    if unit:
        unit_text = _shop_unit(field, text, number, unit_text, unit, notes)
    have = _pint_unit(field, text, unit_text, number, unit)
    try:
        if unit is None:
            return ureg.Quantity(number, have).to_base_units().magnitude
        if unit == "":
            return ureg.Quantity(number, have).to("").magnitude
        if unit == "delta_degC":  # a difference: 5 degC (or degF) is 5 K (9 degF 5 K) of it
            have = _as_difference(have)
        factor = _per_turn(field, text, have, unit, number)
        if unit == "rad/s" and (note := _frequency_note(field, text, number, have)):
            _tell([note], notes)
        return (ureg.Quantity(number, have) * factor).to(unit).magnitude
    except BallScrewInputError:
        raise
    except _pint().errors.DimensionalityError:
        raise _wrong_dimension(field, text, number, have, unit or "") from None
    except (_pint().errors.PintError, ValueError, TypeError, ArithmeticError):
        raise BallScrewInputError(field, text, _UNIT_HELP) from None


PLAIN_FACTORS: dict[tuple[str, str | None], float] = {
    # the bundled case's and the commonest typed units, each to its field's SI unit
    ("mm", "m"): 0.001,
    ("um", "m"): 1e-06,
    ("m", "m"): 1.0,
    ("mm", "m/turn"): 0.001,
    ("rpm", "rad/s"): 0.10471975511965977,
    ("rad/s", "rad/s"): 1.0,
    ("N", "N"): 1.0,
    ("kN", "N"): 1000.0,
    ("N*m", "N*m"): 1.0,
    ("deg", "rad"): 0.017453292519943295,
    ("K", "delta_degC"): 1.0,
    ("kg", "kg"): 1.0,
    ("kg*m**2", "kg*m**2"): 1.0,
    ("mm*rpm", "mm*rpm"): 1.0,
    ("%", ""): 0.01,
}
"""Units whose conversion to a field's unit is one product, ``number * factor``: read without
pint (whose import and registry cost 0.1 s of CPU at every start of the command line). Each
factor is the one pint computes, and the result equals pint's to the last bit for any number
(``tests/io/test_units_plain.py`` holds every entry to that); a text that needs a note or a
refusal never reaches this table (none of its units is ambiguous). A temperature in degC for a
field in degC is read without pint too, as pint reads it: to kelvin and back."""


def _as_difference(unit: Any) -> Any:
    """A temperature unit as the unit of a difference: degC -> delta_degC, degF -> delta_degF.

    A field that is a temperature difference (a rise) reads '5 degC' as a rise of
    5 K: pint would read it as the temperature 278.15 K (issue 35: a pre-tension of
    '5 degC' became 278 K and flipped the thermal check's verdict).
    """
    ureg = registry()
    for absolute, delta in (("degree_Celsius", "delta_degree_Celsius"),
                            ("degree_Fahrenheit", "delta_degree_Fahrenheit")):  # fmt: skip
        if unit == ureg.Unit(absolute):
            return ureg.Unit(delta)
    return unit


def to_si_array(
    field: str, values: Any, unit_text: str, unit: str, notes: list[Reading] | None = None
) -> Any:
    """Numbers in ``unit_text`` (a column's unit) converted to ``unit``, by the same rules.

    Examples
    --------
    >>> [round(float(v), 4) for v in to_si_array("speed", [60.0, 3000.0], "1/min", "rad/s")]
    [6.2832, 314.1593]
    """
    import numpy as np

    text = f"[{unit_text}]"
    rewritten = _unit_text(field, text, _clean(field, unit_text))
    return np.asarray(_convert(field, text, np.asarray(values, float), rewritten, unit, notes))


EXAMPLE_UNITS: dict[str, str] = {
    "rad/s": "rpm",
    "m": "mm",
    "m/turn": "mm",
    "N": "kN",
    "degC": "degC",
    "N*m": "N*m",
    "rad": "deg",
    "Pa*s": "mPa*s",
    "m**2/s": "mm**2/s",
    "kg/m**3": "kg/m**3",
    "1/Pa": "1/GPa",
    "delta_degC": "K",
}
"""The unit shown in the example of an error for each target unit."""


def _example(unit: str) -> str:
    return EXAMPLE_UNITS.get(unit, unit)


def _bare(field: str, value: Any, unit: str) -> BallScrewInputError:
    return BallScrewInputError(
        field,
        value,
        f"a quantity with its unit, e.g. '{str(value).strip()} {_example(unit)}' "
        "(a bare number has no unit)",
    )


def _tell(readings: list[Reading], notes: list[Reading] | None) -> None:
    """Add the readings to ``notes``, or warn of each when there is no list to add them to."""
    if notes is not None:
        notes.extend(readings)
        return
    for reading in readings:
        warnings.warn(BallScrewReadingWarning(str(reading)), stacklevel=4)


# --- lists and ranges ------------------------------------------------------------------------
_COUNT = re.compile(r":\s*(\d{1,9})(?!\d)")  # a count of more digits is refused below


def _range_parts(field: str, raw: str) -> tuple[str, str, int | None]:
    """``a..b:n unit`` split into the text of a, of 'b unit' and the count (None: default)."""
    if "..." in raw or "\u2026" in raw:
        raise BallScrewInputError(
            field, raw, "a range with two points, 'a..b unit' ('...' is no range)"
        )
    low, high = raw.split("..", 1)
    counts = _COUNT.findall(high)
    if ".." in high or len(counts) > 1 or high.count(":") != len(counts):
        raise BallScrewInputError(field, raw, _LIST_HELP)
    high = _COUNT.sub(" ", high, count=1)
    return low.strip(), " ".join(high.split()), int(counts[0]) if counts else None


_LIST_HELP = "a value, a list 'a, b, c unit' or a range 'a..b unit' (optionally 'a..b:n unit')"


def range_size(text: str, default_points: int = 50) -> int:
    """How many values :func:`parse_range` would give for ``text``, without converting any.

    For a caller that must bound the work a text asks for before it is done
    (a range ``a..b:n`` may ask for a million points).

    Examples
    --------
    >>> range_size("0..3000:31 rpm"), range_size("0..3000 rpm"), range_size("20, 40 degC")
    (31, 50, 2)
    """
    raw = str(text).strip()
    if ".." in raw:
        counts = _COUNT.findall(raw)
        return int(counts[0]) if counts else default_points
    return len(re.split("[,;]", raw))


def parse_range(
    field: str,
    text: str,
    unit: str | None,
    default_points: int = 50,
    notes: list[Reading] | None = None,
) -> list[float]:
    """Parse ``"0..3000 rpm"``, ``"10..3000:31 rpm"`` or a list ``"20, 30, 45 degC"`` to SI values.

    ``a..b`` gives ``default_points`` evenly spaced values (``a..b:n`` gives
    ``n``; the count may also follow the unit); a list separated by commas (or
    semicolons) gives those values. The unit is written once, at the end, or
    with each value. ``unit`` is the SI target unit, as for :func:`to_si`.
    In a list a comma between two digits (``1,2 kN``) is refused: a list of
    two values or a decimal comma?

    Examples
    --------
    >>> [round(v, 3) for v in parse_range("speed", "0..60:3 rpm", "rad/s")]
    [0.0, 3.142, 6.283]
    >>> parse_range("temperature", "20, 30 degC", "degC")
    [20.0, 30.0]
    >>> parse_range("axial_load", "1 000; 2 500 N", "N")
    [1000.0, 2500.0]
    """
    read: list[Reading] = []  # one reading of the unit is enough: the last value's
    values = _range_values(field, text, unit, default_points, read)
    _tell(read[-1:], notes)
    return values


def parse_speed_range(
    field: str,
    text: str,
    lead: float | None,
    default_points: int = 50,
    notes: list[Reading] | None = None,
) -> list[float]:
    r"""Screw speeds [rad/s] from speeds of rotation, or from feeds at the screw's ``lead`` [m].

    As :func:`parse_range` with the unit ``rad/s``; where the text is a linear speed
    (``15 m/min``, ``0..30 m/min:7``, ``100 in/min``) and the lead is known, each feed
    :math:`v` turns the screw at :math:`n = v/l`, :math:`\omega = 2\pi v/l`, and the
    reading is told (``notes``, else a
    :class:`~ballscrew.errors.BallScrewReadingWarning`): "1500 rpm at lead 10 mm".
    Without a lead, or for a quantity that is neither, the refusal is
    :func:`parse_range`'s, naming ``field``.

    Examples
    --------
    >>> [round(v * 30 / 3.141592653589793, 6) for v in parse_speed_range(
    ...     "--speed", "15 m/min", 0.010, notes=[])]
    [1500.0]
    """
    try:
        return parse_range(field, text, "rad/s", default_points, notes)
    except BallScrewInputError as refused:
        if lead is None or not (math.isfinite(lead) and lead > 0.0):
            raise
        try:
            feeds = parse_range(field, text, "m/s", default_points)
        except BallScrewInputError as again:
            if again.allowed == refused.allowed:  # not the unit: the number, as typed
                raise refused from None
            raise BallScrewInputError(
                refused.field, refused.value,
                f"{refused.allowed} (or a feed, e.g. '15 m/min', read as the screw speed at "
                f"the lead {lead * 1e3:.6g} mm)",
            ) from None  # fmt: skip
    speeds = [2.0 * math.pi * v / lead for v in feeds]
    rpm = [v / lead * 60.0 for v in feeds]
    if len(rpm) > 1 and (".." in str(text) or "\u2026" in str(text)):  # a range
        shown = f"{rpm[0]:.6g} to {rpm[-1]:.6g}"
    else:  # one value, or a list as typed
        shown = ", ".join(f"{n:.6g}" for n in rpm)
    _tell([Reading(field, str(text).strip(), f"{shown} rpm at lead {lead * 1e3:.6g} mm (a feed "
                   "v turns the screw at n = v / lead)")], notes)  # fmt: skip
    return speeds


def _range_values(
    field: str, text: str, unit: str | None, default_points: int, notes: list[Reading]
) -> list[float]:
    raw = _clean(field, text)
    if not raw:
        raise BallScrewInputError(field, text, _LIST_HELP)
    if ".." in raw or "\u2026" in raw:
        low, high, count = _range_parts(field, raw)
        n = default_points if count is None else count
        if n < 1 or n > 1_000_000:
            raise BallScrewInputError(field, text, "between 1 and 1e6 points")
        hi_number, hi_unit = split_quantity(field, high)
        lo_number, lo_unit = split_quantity(field, low)
        lo = _value_si(field, text, lo_number, lo_unit or hi_unit, unit, notes)
        hi = _value_si(field, text, hi_number, hi_unit, unit, notes)
        if n == 1:
            return [lo]
        return [lo + (hi - lo) * i / (n - 1) for i in range(n)]
    if ";" in raw:  # semicolons separate the values: a comma is a decimal comma
        items = raw.split(";")
    else:
        mixed = re.search(r"(\d+),(\d+)", raw)
        if mixed:
            a, b = mixed.groups()
            grouped = f", thousands ('{a}{b}')" if len(b) == 3 and a[0] != "0" else ""
            raise BallScrewInputError(
                field, text,
                f"'{a},{b}' is ambiguous in a list: two values ('{a}, {b}'){grouped} or a "
                f"decimal comma ('{a}.{b}')? Write one of them (or separate the values "
                "with ';')",
            )  # fmt: skip
        items = raw.split(",")
    items = [p.strip() for p in items]
    if any(not p for p in items):
        raise BallScrewInputError(field, text, _LIST_HELP)
    split = [split_quantity(field, p) for p in items]
    suffix = split[-1][1]
    return [_value_si(field, text, number, own or suffix, unit, notes) for number, own in split]
