"""Printed results in the unit system the reader works in: SI as computed, or imperial.

Only what is printed changes: JSON, CSV and ``.mat`` files stay SI (their
headers carry the units), so that files from any run compare with each other.
Every conversion is pint's, through the package's registry
(:func:`ballscrew.io.units.registry`), not a hand-written factor.

**Imperial** prints lengths in inches (``in``), forces in pound-force
(``lbf``), torques in pound-force inches (``lbf*in``), linear speeds (feeds) in
``in/min``, accelerations in ``in/s**2``, stiffnesses in ``lbf/in``, masses in
``lb``, pressures in ``psi``, moments of inertia in ``lb*in**2``, temperatures in
``degF`` and temperature differences in ``delta_degF``. Kept as they are: speeds
of rotation (``rpm``) and anything else with an angle in it (``mm*rpm``),
frequencies, times, plain numbers, powers (``W``: ball screw losses are watts,
and servo data sheets give watts in imperial countries too) and energies
(``J``). A unit this module does not know is printed as it came.
"""

from __future__ import annotations

import functools
import re
from typing import Any

from ..errors import BallScrewInputError
from .numbers import text
from .units import registry

__all__ = [
    "SYSTEMS",
    "column_label",
    "display_row",
    "label_text",
    "shown",
    "system_note",
    "to_display",
    "unit_system",
    "unit_text",
]

SYSTEMS = ("si", "imperial")
"""The unit systems results can be printed in."""

_IMPERIAL = ("in", "lbf", "lbf*in", "in/min", "in/s**2", "lbf/in", "lb", "psi", "lb*in**2")
"""Imperial display units, each taken for the SI unit of its dimension."""

_KEPT_WORDS = frozenset({"J", "kJ", "MJ", "Wh", "kWh", "W", "kW", "mW"})
"""Units printed as computed in every system: energies and powers (see the module)."""

_TEMPERATURES = {"degC": "degF", "°C": "degF", "K": "delta_degF", "delta_degC": "delta_degF"}
"""Temperatures (°C) and their differences (K) to Fahrenheit."""


def unit_system(field: str, value: str | None, default: str = "si") -> str:
    """The unit system asked for (``--units``), checked; ``default`` when not given.

    Examples
    --------
    >>> unit_system("--units", "Imperial"), unit_system("--units", None, "imperial")
    ('imperial', 'imperial')
    """
    if value is None:
        return default
    system = str(value).strip().lower()
    if system not in SYSTEMS:
        raise BallScrewInputError(field, value, "one of " + ", ".join(SYSTEMS))
    return system


@functools.cache
def _display_unit(unit: str) -> str | None:
    """The imperial unit a printed SI unit is shown in, or None to keep it."""
    if unit in _TEMPERATURES:
        return _TEMPERATURES[unit]
    words = set(re.findall(r"[^\W\d_][^\W\d]*", unit))
    if not words or words & _KEPT_WORDS:
        return None
    ureg = registry()
    try:
        parsed = ureg.parse_units(unit.replace("^", "**"))
    except Exception:  # a label such as '-' or 'mm*rpm/x': printed as it came
        return None
    _, root = ureg.get_root_units(parsed)
    if root._units.get("radian", 0) or parsed.dimensionless:
        return None
    for imperial in _IMPERIAL:
        if ureg.parse_units(imperial).dimensionality == parsed.dimensionality:
            return imperial
    return None


def to_display(value: Any, unit: str, system: str) -> tuple[Any, str]:
    """``value`` in ``unit`` as printed in ``system``: the number (or array) and its unit.

    Parameters
    ----------
    value : float or array_like
        A result in the unit it was computed in.
    unit : str
        That unit, as the package prints it (``"N*m"``, ``"kN"``, ``"um"``,
        ``"m/s^2"``, ``"degC"``; ``"K"`` is a temperature difference).
    system : str
        ``"si"`` (unchanged) or ``"imperial"`` (see the module docstring).

    Returns
    -------
    tuple
        The converted value and the unit it is now in.

    Examples
    --------
    >>> value, unit = to_display(1.0, "N*m", "imperial")
    >>> round(value, 6), unit
    (8.850746, 'lbf*in')
    >>> value, unit = to_display(20.0, "degC", "imperial")
    >>> round(value, 9), unit
    (68.0, 'degF')
    >>> to_display(3000.0, "rpm", "imperial"), to_display(5.0, "W", "imperial")
    ((3000.0, 'rpm'), (5.0, 'W'))
    """
    if system == "si" or value is None:
        return value, unit
    target = _display_unit(unit)
    if target is None:
        return value, unit
    ureg = registry()
    source = {"°C": "degC", "K": "delta_degC"}.get(unit, unit).replace("^", "**")
    # shown as the package writes powers elsewhere ('m/s^2'), converted with pint's '**'
    return ureg.Quantity(value, source).to(target).magnitude, target.replace("**", "^")


_LABEL = re.compile(r"^(?P<name>.*?)\s*\[(?P<unit>[^\[\]]+)\]\s*$")


def column_label(label: str, system: str) -> str:
    """A column's label ``'name [unit]'`` with the unit ``system`` prints.

    Examples
    --------
    >>> column_label("axial load [N]", "imperial"), column_label("speed [rpm]", "imperial")
    ('axial load [lbf]', 'speed [rpm]')
    """
    match = _LABEL.match(label)
    if not match:
        return label
    _, unit = to_display(1.0, match.group("unit"), system)
    return f"{match.group('name')} [{unit}]"


def display_row(row: dict[str, Any], system: str) -> dict[str, Any]:
    """A row of results keyed ``'name [unit]'``, every number in ``system``'s units."""
    out: dict[str, Any] = {}
    for key, value in row.items():
        match = _LABEL.match(key)
        if not match or isinstance(value, str):
            out[key] = value
            continue
        converted, unit = to_display(value, match.group("unit"), system)
        out[f"{match.group('name')} [{unit}]"] = converted
    return out


_BAKED_LENGTH = re.compile(
    r"(?<![\w.*/^])(?P<number>\d+(?:\.\d+)?) ?(?P<unit>mm|um|µm|m)(?![\w*/^])"
    r"(?: \((?P<aside>[^()]*)\))?"
)
"""A length written into a label's words ('per 300 mm', '(P3)' after it), not a unit
of its own ('mm*rpm' is a unit and stays)."""


def label_text(label: str, system: str) -> str:
    """A label with the lengths written into its words in ``system``'s length unit.

    A criterion can carry a length in its name, the length a standard fixes:
    ISO 3408-3's lead accuracy is per 300 mm of travel. In imperial the inch
    figure is shown first, the standard's length beside it, so that the name is
    still found in the standard; a unit of its own (``mm*rpm``) is left as it is.

    Examples
    --------
    >>> label_text("thermal lead error per 300 mm (P3)", "imperial")
    'thermal lead error per 11.81 in (300 mm, P3)'
    >>> label_text("thermal lead error per 300 mm", "imperial")
    'thermal lead error per 11.81 in (300 mm)'
    >>> label_text("thermal lead error per 300 mm (P3)", "si"), label_text("d*n [mm*rpm]", "imperial")
    ('thermal lead error per 300 mm (P3)', 'd*n [mm*rpm]')
    """  # noqa: E501 - a doctest line
    if system == "si":
        return label

    def shown(match: re.Match[str]) -> str:
        number, unit = match.group("number"), match.group("unit")
        value, target = to_display(float(number), unit.replace("µm", "um"), system)
        if target == unit:
            return match.group()
        aside = match.group("aside")
        written = f"{number} {unit}" + (f", {aside}" if aside else "")
        return f"{text(value)} {target} ({written})"

    return _BAKED_LENGTH.sub(shown, label)


_UNIT_TEXT = (
    ("delta_degF", "°F"),
    ("delta_degC", "K"),
    ("degF", "°F"),
    ("degC", "°C"),
    ("**", "^"),
    ("^2", "²"),
    ("^3", "³"),
    ("*", "·"),
    ("um", "µm"),
)
"""How a unit the package writes ('lbf*in', 'degF') reads on a page ('lbf·in', '°F')."""


def unit_text(unit: str) -> str:
    """``unit`` as a page prints it: a middle dot for a product, degree signs, superscripts.

    Typography only: the unit is the same one (no number changes).

    Examples
    --------
    >>> unit_text("lbf*in"), unit_text("degF"), unit_text("m/s**2"), unit_text("um")
    ('lbf·in', '°F', 'm/s²', 'µm')
    """
    for written, printed in _UNIT_TEXT:
        unit = unit.replace(written, printed)
    return unit


def shown(value: Any, unit: str, system: str) -> tuple[Any, str]:
    """:func:`to_display` with the unit as a page prints it (:func:`unit_text`).

    Examples
    --------
    >>> value, unit = shown(1.0, "N*m", "imperial")
    >>> round(value, 4), unit
    (8.8507, 'lbf·in')
    >>> shown(2.5, "N*m", "si")
    (2.5, 'N·m')
    """
    value, target = to_display(value, unit, system)
    return value, unit_text(target)


def system_note(system: str) -> str:
    """The line that states the unit system of a printed result (and that files stay SI)."""
    if system == "si":
        return "units: SI (JSON and CSV files too)"
    return (
        "units: imperial (lbf, in, lbf*in, in/min, degF; speeds in rpm, powers in W, energies "
        "in J); JSON and CSV files stay SI"
    )
