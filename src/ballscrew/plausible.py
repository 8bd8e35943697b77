r"""What the makers build and what lubricants are: the typical ranges of the inputs, with sources.

One table for the library, the case files and the web: :class:`ballscrew.BallScrew`
and :class:`ballscrew.lubricant.Lubricant` check their fields against it when they
are built, the case reader checks the wiper drag against the screw, so a value is
held to the same range whichever face it came through.

Two kinds of bound:

* **refused** beyond what the quantity can physically be for a ball screw or a
  lubricant (:class:`~ballscrew.errors.BallScrewInputError`, naming the field, the
  value, the range and its source): most often a unit slip, '68 St' for 68 cSt;
* **warned** outside what makers build or sell
  (:class:`~ballscrew.errors.BallScrewPlausibilityWarning`, naming the field, the
  value, the range and its source): the value is used as given, since a special
  part may be meant.

=====================  ======================  ==========================  ==================
quantity               warned outside          refused outside             source
=====================  ======================  ==========================  ==================
``nu40``               1.98 to 3520 mm²/s      up to 20 000 mm²/s          ISO 3448 (VG 2 to
                                                                           VG 3200)
``density15``          750 to 1100 kg/m³       300 to 2500 kg/m³           base oils [1]_
``pressure_viscosity`` 5 to 45 /GPa            1 to 100 /GPa               [2]_
``ball_diameter``      the ball series         (:data:`ballscrew.geometry  ISO 3290-1, the
                                               .PLAUSIBLE_SIZES`)           bundled catalogue
``loaded_turns``       1 to 5 per circuit      0 to 10 (``BallScrew``)     the makers' nuts
wiper drag             :func:`wiper_drag_      10 x that                   an estimate (below)
                       bound`
=====================  ======================  ==========================  ==================

References
----------
.. [1] T. Mang, W. Dresel (eds.), *Lubricants and Lubrication*, 2nd ed.,
   Wiley-VCH, 2007, ch. 4 (base oils): mineral oils 0.82 to 0.92 g/cm³, PAO
   about 0.83, esters 0.90 to 1.0, polyglycols up to about 1.1, perfluoropolyethers
   about 1.9.
.. [2] B. J. Hamrock, S. R. Schmid, B. O. Jacobson, *Fundamentals of Fluid Film
   Lubrication*, 2nd ed., Marcel Dekker, 2004, ch. 4: pressure-viscosity
   coefficients of lubricating oils of about 10 to 35 /GPa at ordinary temperatures.
"""

from __future__ import annotations

import math
import warnings
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from .errors import BallScrewInputError, BallScrewPlausibilityWarning

__all__ = [
    "BALL_SERIES_MM",
    "LUBRICANT_RANGES",
    "TYPICAL_TURNS",
    "TypicalRange",
    "check_ball_diameter",
    "check_loaded_turns",
    "check_lubricant_property",
    "check_wiper_drag",
    "warn",
    "wiper_drag_bound",
]


class TypicalRange(NamedTuple):
    """A quantity's typical range (warned outside) and possible range (refused outside), in SI.

    ``scale`` and ``unit`` show the values as a user types them (``1e6`` and
    ``"mm²/s"`` for a viscosity in m²/s).
    """

    typical: tuple[float, float]
    possible: tuple[float, float]
    scale: float
    unit: str
    source: str


LUBRICANT_RANGES: dict[str, TypicalRange] = {
    "nu40": TypicalRange(
        (1.98e-6, 3520e-6),
        (0.0, 20000e-6),
        1e6,
        "mm²/s",
        "ISO 3448's viscosity grades run from VG 2 (1.98 to 2.42 mm²/s at 40 °C) to VG 3200 "
        "(2880 to 3520 mm²/s); beyond 20000 mm²/s no lubricating oil flows into a ball "
        "screw's nut ('68 St' is 6800 mm²/s: 68 cSt was likely meant)",
    ),
    "density15": TypicalRange(
        (750.0, 1100.0),
        (300.0, 2500.0),
        1.0,
        "kg/m³",
        "base oils: mineral 820 to 920, PAO about 830, esters 900 to 1000, polyglycols up to "
        "about 1100, perfluoropolyethers about 1900 kg/m³ (Mang & Dresel, Lubricants and "
        "Lubrication, 2007, ch. 4); no oil lies outside 300 to 2500 kg/m³",
    ),
    "pressure_viscosity": TypicalRange(
        (5e-9, 45e-9),
        (1e-9, 100e-9),
        1e9,
        "/GPa",
        "lubricating oils have 10 to 35 /GPa (Hamrock, Schmid & Jacobson, Fundamentals of "
        "Fluid Film Lubrication, 2004, ch. 4); water-based fluids about 5, traction fluids "
        "up to about 40; outside 1 to 100 /GPa no liquid lubricant lies",
    ),
}
"""The lubricant properties held to a range: field -> :class:`TypicalRange` (SI)."""


BALL_SERIES_MM: tuple[float, ...] = (
    0.8, 1.0, 1.2, 1.5, 1.5875, 2.0, 2.381, 2.5, 2.778, 3.0, 3.175, 3.5, 3.969, 4.0, 4.5,
    4.762, 5.0, 5.556, 6.0, 6.35, 7.0, 7.144, 7.5, 7.938, 8.0, 8.731, 9.0, 9.525, 10.0,
    11.112, 12.0, 12.7, 14.0, 14.288, 15.0, 15.875, 16.0, 17.462, 19.05, 20.0, 22.225, 25.4,
)  # fmt: skip
"""Ball diameters [mm] makers put in ball screws: the metric sizes and the inch fractions
(1/16 in = 1.5875 mm, 3/32, 7/64, 1/8, 5/32, 3/16, 7/32, 1/4, 9/32, 5/16, 11/32, 3/8,
7/16, 1/2, 9/16, 5/8, 11/16, 3/4, 7/8, 1 in) of the ball grades of ISO 3290-1; the bundled
catalogue rows (``data/catalog_screws.csv``) use 3.175, 3.969, 6.35 and 9.525 mm."""

_BALL_MATCH = 0.005
"""A ball within 0.5 % of a series size is that size (3.97 mm for 5/32 in = 3.969 mm)."""

BALL_SERIES_SOURCE = (
    "the ball sizes of ISO 3290-1 that makers use in ball screws, 0.8 to 25.4 mm "
    "(1/32 in steps and whole millimetres)"
)

TYPICAL_TURNS = (1.0, 5.0)
"""Loaded turns per circuit makers build: one turn for internal recirculation (the
bundled catalogue's deflector and cassette nuts), 1.5 to 3.5 for tubes, up to 5 for end
caps."""

TURNS_SOURCE = (
    "the makers' nuts: 1 turn per circuit with internal deflectors, 1.5 to 3.5 with return "
    "tubes, up to 5 with end caps (a designation's '2.5x2' is 2.5 turns in each of 2 circuits)"
)

WIPER_LIP_TORQUE = 0.5
"""Drag torque [N·m] of a nut's two contact wipers on a 40 mm screw, estimated below."""

WIPER_SOURCE = (
    "an estimate of a nut's two contact wipers: each elastomer lip presses about 0.15 N per "
    "mm along some 1.5 pitch circumferences of the thread profile at a friction coefficient "
    "of about 0.4, about 0.5 N*m on a 40 mm screw, growing with the square of the diameter "
    "(longer lip, larger radius); catalogue drag torques are measured without wipers"
)


def warn(field: str, value: str, allowed: str, source: str) -> None:
    """Warn that ``field = value`` lies outside ``allowed`` (a text), giving the ``source``.

    Python's warning filter shows each text once per place in the code (the
    command line prints each once), so a value read twice is told once.
    """
    warnings.warn(BallScrewPlausibilityWarning(field, value, allowed, source), stacklevel=3)


def _shown(value: float, r: TypicalRange) -> str:
    return f"{value * r.scale:.4g} {r.unit}"


def check_lubricant_property(field: str, value: float, name: str | None = None) -> None:
    """Refuse ``value`` [SI] outside the possible range of ``field``; warn outside the typical.

    ``name`` is the field of :data:`LUBRICANT_RANGES` when ``field`` names it
    otherwise (``lubricant.nu40`` for ``nu40``).
    """
    r = LUBRICANT_RANGES[name or field]
    low, high = r.possible
    if not (low <= value <= high):  # the range the message states, ends included
        raise BallScrewInputError(
            field, _shown(value, r),
            f"{low * r.scale:g} to {high * r.scale:g} {r.unit} ({r.source})",
        )  # fmt: skip
    low, high = r.typical
    if not (low <= value <= high):
        warn(field, _shown(value, r), f"{low * r.scale:g} to {high * r.scale:g} {r.unit}",
             r.source)  # fmt: skip


def check_ball_diameter(field: str, diameter: float) -> None:
    """Warn when ``diameter`` [m] is no size of the makers' ball series (:data:`BALL_SERIES_MM`)."""
    mm = diameter * 1e3
    nearest = min(BALL_SERIES_MM, key=lambda s: abs(s - mm))
    if abs(nearest - mm) <= _BALL_MATCH * nearest:
        return
    if mm < BALL_SERIES_MM[0] or mm > BALL_SERIES_MM[-1]:
        allowed = f"{BALL_SERIES_MM[0]:g} to {BALL_SERIES_MM[-1]:g} mm"
    else:
        below = max(s for s in BALL_SERIES_MM if s < mm)
        above = min(s for s in BALL_SERIES_MM if s > mm)
        allowed = f"a series size, such as {below:g} or {above:g} mm"
    warn(field, f"{mm:.4g} mm", allowed, BALL_SERIES_SOURCE)


def check_loaded_turns(field: str, turns: float) -> None:
    """Warn when ``turns`` per circuit lie outside what makers build (:data:`TYPICAL_TURNS`)."""
    low, high = TYPICAL_TURNS
    if not (low <= turns <= high):
        warn(field, f"{turns:g}", f"{low:g} to {high:g} turns per circuit", TURNS_SOURCE)


def wiper_drag_bound(pitch_diameter: float) -> float:
    """The wipers' typical largest drag torque [N·m] on a screw of ``pitch_diameter`` [m].

    :data:`WIPER_LIP_TORQUE` on a 40 mm screw, scaled with the square of the
    diameter (:data:`WIPER_SOURCE`).
    """
    return WIPER_LIP_TORQUE * (pitch_diameter / 0.040) ** 2


def check_wiper_drag(
    field: str, torque: npt.ArrayLike, pitch_diameter: npt.ArrayLike, *, warn_above: bool = True
) -> None:
    """Refuse a wiper drag [N·m] ten times the typical bound of the screw's size; warn above it.

    ``warn_above=False`` only refuses (the complete model's ``seal_torque``, which
    a case's ``wiper_drag`` reaches once the case reader has warned of it).

    >>> check_wiper_drag("screw.wiper_drag", 0.05, 0.040)
    >>> try:
    ...     check_wiper_drag("screw.wiper_drag", 50.0, 0.040)
    ... except BallScrewInputError as exc:
    ...     print(exc.field, exc.value)
    screw.wiper_drag 50 N*m
    """
    # Many screws at once (a ScrewArray's diameters): judged by the one furthest past its bound.
    torques, diameters = np.broadcast_arrays(
        np.ravel(np.asarray(torque, dtype=float)), np.ravel(np.asarray(pitch_diameter, dtype=float))
    )
    worst = int(np.argmax(torques / (WIPER_LIP_TORQUE * (diameters / 0.040) ** 2)))
    value, diameter = float(torques[worst]), float(diameters[worst])
    typical = wiper_drag_bound(diameter)
    size = f"a {diameter * 1e3:.4g} mm screw"
    if not math.isfinite(value) or value > 10.0 * typical:
        raise BallScrewInputError(
            field, f"{value:.4g} N*m",
            f"at most {10.0 * typical:.3g} N*m on {size}, ten times the wipers' typical "
            f"{typical:.2g} N*m ({WIPER_SOURCE}); a wiper drag in N*mm or N*cm given as N*m?",
        )  # fmt: skip
    if warn_above and value > typical:
        warn(field, f"{value:.4g} N*m", f"at most about {typical:.2g} N*m on {size}",
             WIPER_SOURCE)  # fmt: skip
