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

The bounds, quantity by quantity (warned outside / refused outside / source):

* ``nu40``: 1.98 to 3520 mm²/s / above 20 000 mm²/s / ISO 3448 [1]_ (VG 2 to VG 3200);
* ``density15``: 750 to 1100 kg/m³ / 300 to 2500 kg/m³ / base oils [2]_ (not checked);
* ``pressure_viscosity``: 5 to 45 /GPa / 1 to 100 /GPa / [3]_, Table 2.3;
* ``ball_diameter``: the ball series (:data:`ballscrew.geometry.PLAUSIBLE_SIZES`) /
  as ``BallScrew`` refuses / ISO 3290 sizes [4]_ and the bundled catalogue;
* ``loaded_turns``: 1 to 5 per circuit / 0 to 10 (``BallScrew``) / the makers' nuts;
* wiper drag: :func:`wiper_drag_bound` / 10 times that / an estimate (below);
* ``axis.moving_mass``: a weight of half the static rating :math:`C_{0a}` / a weight above
  it / ISO 3408-5 and the catalogues' static safety (:func:`check_moving_mass`);
* ``axis.moving_mass`` above 0 but below the least a nut of the screw weighs (a steel
  sleeve, :func:`least_nut_mass`): warned (the mass includes the nut);
* ``axis.max_acceleration``: the same force, mass times acceleration;
* ``axis.bearing_span``, ``axis.screw_length``: a first bending frequency of the shaft
  below 5 Hz / below 1 Hz / beam theory (:func:`check_span`);
* ``axis.max_feed``: the feed at the nut's d·n limit / the feed at the models' largest
  speed (:func:`check_feed`);
* ``axis.motor_inertia``, ``coupling_inertia``, ``screw_inertia``, ``gear_ratio``:
  :data:`AXIS_RANGES`, the makers' parts (as recalled, not checked) / 10 kg·m², ratios
  outside 1/1000 to 1000.

Which of these sources were read, and what each gives (issue 35, item 4):

* ``nu40``: ISO 3448:1992 clause 3.2 (read in its British reprint, BS 4231:1992) sets 20
  grades, each named after its mid-point viscosity at 40 °C and spanning ±10 % of it; its
  Table 1 (read in a reproduction listing VG 2 to VG 1500) gives VG 2 as 1.98 to 2.42 mm²/s
  (mid-point 2.2). VG 3200's 2880 to 3520 mm²/s follows from the ±10 % rule; ASTM D2422's
  same twenty grades end there too.
* ``density15``: the figures of [2]_ were written from memory and could not be checked
  against the book; the mineral-oil end agrees with the bundled data-sheet oil (Mobil
  Delvac 1320, 887 kg/m³). A perfluoropolyether (about 1900 kg/m³) is warned, not refused.
* ``pressure_viscosity``: [3]_ Table 2.3 lists mineral oils (spindle to cylinder oils) at
  13 to 42 /GPa between 30 and 100 °C, an ethylene-oxide/propylene-oxide copolymer (a
  polyglycol) at about 18 /GPa at 30 °C, and water at 0. The typical range is widened to 5
  and 45 /GPa for synthetics not in the table and for cold oils; the possible range (1 to
  100 /GPa) is a judgement: below it no elastohydrodynamic film forms (water), above it
  lies no tabulated lubricant.
* ``ball_diameter``: ISO 3290-1's own table of nominal diameters could not be read; the
  series is checked against a ball maker's list of ISO 3290 sizes [4]_ (1.5 to 25.4 mm:
  metric sizes and 1/64- and 1/32-inch fractions), holds all of them and every ball of the
  bundled catalogue (3.175, 3.969, 6.35, 9.525 mm). The miniature sizes 0.8 to 1.2 mm are
  from memory of miniature ball screws, not checked.
* wiper drag: no maker's seal torque table could be read. Bosch Rexroth's catalogue
  RE 83 301 (2002-09) has a section "Friction Torques of Seals" (p. 106) whose figures
  were not reachable here, so the bound stays an estimate (:data:`WIPER_SOURCE`).
* the viscosity index is not checked: :class:`ballscrew.lubricant.Lubricant` takes no
  index but ``nu40`` and ``nu100`` (``nu100 < nu40`` is refused), and an index computed
  from them needs ASTM D2270's table, which no installed library provides.

References
----------
.. [1] ISO 3448:1992, *Industrial liquid lubricants - ISO viscosity classification*,
   clause 3.2 and Table 1 (identical: BS 4231:1992); ASTM D2422 (the same 20 grades).
.. [2] T. Mang, W. Dresel (eds.), *Lubricants and Lubrication*, 2nd ed.,
   Wiley-VCH, 2007, ch. 4 (base oils): mineral oils 0.82 to 0.92 g/cm³, PAO
   about 0.83, esters 0.90 to 1.0, polyglycols up to about 1.1, perfluoropolyethers
   about 1.9 (not checked against the book).
.. [3] G. W. Stachowiak, A. W. Batchelor, *Engineering Tribology*, 2nd ed.,
   Butterworth-Heinemann, 2001, ch. 2, p. 21, Table 2.3 (pressure-viscosity coefficients of
   commonly used lubricants at 30, 60 and 100 °C).
.. [4] Technoball (Italy), precision steel balls to ISO 3290: nominal diameters 1.5 to
   25.4 mm (www.technoball.it, "sfere di precisione").
"""

from __future__ import annotations

import math
import warnings
from typing import Any, NamedTuple

import numpy as np
import numpy.typing as npt

from .errors import BallScrewInputError, BallScrewPlausibilityWarning
from .materials import STANDARD_GRAVITY, STEEL_DENSITY

__all__ = [
    "AXIS_RANGES",
    "BALL_SERIES_MM",
    "LOWEST_FREQUENCY",
    "LUBRICANT_RANGES",
    "TYPICAL_TURNS",
    "TypicalRange",
    "check_acceleration",
    "check_axial_force",
    "check_axis_property",
    "check_ball_diameter",
    "check_feed",
    "check_loaded_turns",
    "check_lubricant_property",
    "check_moving_mass",
    "check_span",
    "check_wiper_drag",
    "least_nut_mass",
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
        "ISO 3448:1992 (clause 3.2, Table 1): 20 viscosity grades, each ±10 % of its mid-point "
        "at 40 °C, from VG 2 (1.98 to 2.42 mm²/s) to VG 3200 (2880 to 3520 mm²/s); beyond "
        "20000 mm²/s no lubricating oil flows into a ball screw's nut ('68 St' is 6800 mm²/s: "
        "68 cSt was likely meant)",
    ),
    "density15": TypicalRange(
        (750.0, 1100.0),
        (300.0, 2500.0),
        1.0,
        "kg/m³",
        "base oils: mineral 820 to 920, PAO about 830, esters 900 to 1000, polyglycols up to "
        "about 1100 kg/m³ (Mang & Dresel, Lubricants and Lubrication, 2007, ch. 4, as "
        "recalled, not checked); a perfluoropolyether (about 1900) lies above and is used as "
        "given; no oil lies outside 300 to 2500 kg/m³ ('0.88' is g/cm³)",
    ),
    "pressure_viscosity": TypicalRange(
        (5e-9, 45e-9),
        (1e-9, 100e-9),
        1e9,
        "/GPa",
        "mineral oils have 13 to 42 /GPa between 30 and 100 °C, a polyglycol about 18 "
        "(Stachowiak & Batchelor, Engineering Tribology, 2001, Table 2.3); widened to 5 to 45 "
        "for synthetics and cold oils; below 1 /GPa (water: 0) no elastohydrodynamic film "
        "forms, above 100 lies no tabulated lubricant",
    ),
}
"""The lubricant properties held to a range: field -> :class:`TypicalRange` (SI)."""


BALL_SERIES_MM: tuple[float, ...] = (
    0.8, 1.0, 1.2, 1.5, 1.5875, 2.0, 2.381, 2.5, 2.778, 3.0, 3.175, 3.5, 3.969, 4.0, 4.5,
    4.762, 5.0, 5.556, 6.0, 6.35, 7.0, 7.144, 7.5, 7.938, 8.0, 8.731, 9.0, 9.525, 10.0,
    10.319, 11.112, 11.906, 12.0, 12.7, 13.494, 14.0, 14.288, 15.0, 15.081, 15.875, 16.0,
    16.669, 17.462, 19.05, 19.844, 20.0, 20.638, 22.225, 23.812, 25.0, 25.4,
)  # fmt: skip
"""Ball diameters [mm] makers put in ball screws.

Every ISO 3290 size of a ball maker's list (Technoball: 1.5 to 4.5 mm in half
millimetres, 5, 6, 10, 12, 15, 16, 20 and 25 mm; 1/16, 3/32 and 7/64 in, 1/32-inch steps
from 1/8 to 11/16 in, then 3/4, 25/32, 13/16, 15/16 and 1 in), with 7.0, 7.5, 8.0, 9.0
and 14.0 mm and 7/8 in kept from the first list (not checked), and the miniature 0.8 to
1.2 mm balls (not checked). The bundled catalogue rows (``data/catalog_screws.csv``) use
3.175, 3.969, 6.35 and 9.525 mm."""

_BALL_MATCH = 0.005
"""A ball within 0.5 % of a series size is that size (3.97 mm for 5/32 in = 3.969 mm)."""

BALL_SERIES_SOURCE = (
    "the steel ball sizes of ISO 3290-1 as ball makers list them, 1.5 to 25.4 mm (whole and "
    "half millimetres, 1/32 in steps), and 0.8 to 1.2 mm for miniature screws"
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
"""Drag torque [N·m] of a nut's two contact wipers on a 40 mm screw, estimated below.

No maker's figure backs it: THK, HIWIN and NSK print their drag torques without wipers, and
the one seal torque table found (Bosch Rexroth RE 83 301, 2002-09, "Friction Torques of
Seals", p. 106) could not be read. A cross-check of the order of magnitude and of the
growth with the diameter: SKF's model of the friction of rolling-bearing contact seals,
:math:`M = K_{S1} d_s^{\beta} + K_{S2}` with :math:`\beta` = 2 to 2.25, gives about
0.07 N·m for one lip on a 40 mm counterface (:math:`K_{S1}` = 0.018, :math:`\beta` = 2.25,
as coded in the open-source Thermca library, ``thermca/lib/bearing.py``, after the SKF
General Catalogue 2006; the catalogue itself was not read). A ball screw's wipers follow
the thread profile, a longer lip than a bearing seal's, hence about 3.5 times two such
lips, growing as :math:`d^2` like SKF's."""

WIPER_SOURCE = (
    "an estimate of a nut's two contact wipers: each elastomer lip presses about 0.15 N per "
    "mm along some 1.5 pitch circumferences of the thread profile at a friction coefficient "
    "of about 0.4, about 0.5 N*m on a 40 mm screw, growing with the square of the diameter "
    "(longer lip, larger radius; SKF's lip-seal friction grows as d^2 to d^2.25); "
    "catalogue drag torques are measured without wipers, and no maker's wiper torque "
    "table was found"
)


def warn(field: str, value: str, allowed: str, source: str) -> None:
    """Warn that ``field = value`` lies outside ``allowed`` (a text), giving the ``source``.

    Python's warning filter shows each text once per place in the code (the
    command line prints each once), so a value read twice is told once.
    """
    warnings.warn(BallScrewPlausibilityWarning(field, value, allowed, source), stacklevel=3)


def _plain(value: float) -> str:
    """``value`` to 4 significant digits, without an exponent from 0.001 to 10^7.

    A bound reads "at most 14770 kg" and "13540 mm", not "1.477e+04 kg".

    >>> _plain(14771.3), _plain(0.25), _plain(3.2e9)
    ('14770', '0.25', '3.2e+09')
    """
    rounded = float(f"{value:.4g}")
    return f"{rounded:.10g}" if 1e-3 <= abs(rounded) < 1e7 else f"{value:.4g}"


def _shown(value: float, r: TypicalRange) -> str:
    return f"{value * r.scale:.4g} {r.unit}"


def check_lubricant_property(field: str, value: float, name: str | None = None) -> None:
    """Refuse ``value`` [SI] outside the possible range of ``field``; warn outside the typical.

    ``name`` is the field of :data:`LUBRICANT_RANGES` when ``field`` names it
    otherwise (``lubricant.nu40`` for ``nu40``).
    """
    _check_range(field, value, LUBRICANT_RANGES[name or field])


def _check_range(field: str, value: float, r: TypicalRange) -> None:
    """Refuse ``value`` [SI] outside ``r``'s possible range; warn outside its typical one."""
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


def wiper_drag_bound(pitch_diameter: npt.ArrayLike) -> Any:
    """The wipers' typical largest drag torque [N·m] on a screw of ``pitch_diameter`` [m].

    A float for a float, an array for an array (many screws).

    :data:`WIPER_LIP_TORQUE` on a 40 mm screw, scaled with the square of the
    diameter (:data:`WIPER_SOURCE`).
    """
    return WIPER_LIP_TORQUE * (np.asarray(pitch_diameter, dtype=float) / 0.040) ** 2


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
    worst = int(np.argmax(torques / wiper_drag_bound(diameters)))
    value, diameter = float(torques[worst]), float(diameters[worst])
    typical = float(wiper_drag_bound(diameter))
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


# --- the axis a screw drives ---------------------------------------------------------------

STATIC_SOURCE = (
    "ISO 3408-5:2006 5.1: the static rating C_0a is the axial load that dents the most loaded "
    "ball contact permanently (4200 MPa); catalogues (THK, HIWIN) ask a static safety "
    "C_0a/F of 1 to 3"
)
"""Where the bounds of the moving mass and the acceleration come from."""


def _against_static(
    field: str, text: str, force: float, static_rating: float, what: str, per: float, unit: str
) -> None:
    """Refuse a ``force`` [N] above the static rating [N], warn above half of it.

    ``what`` says what the force is ("its weight"); the field's largest value is the
    allowed force over ``per`` (the force of one ``unit`` of the field).
    """
    c0 = f"C_0a = {static_rating / 1e3:.4g} kN"
    if not math.isfinite(force) or force > static_rating:
        raise BallScrewInputError(
            field, text,
            f"at most {_plain(static_rating / per)} {unit}: {what}, {force / 1e3:.4g} kN, would "
            f"exceed the screw's static rating {c0}, which dents its raceways ({STATIC_SOURCE})",
        )  # fmt: skip
    if force > 0.5 * static_rating:
        warn(field, f"{text} ({what} {force / 1e3:.4g} kN)",
             f"at most {_plain(0.5 * static_rating / per)} {unit}, a static safety of 2 "
             f"against {c0}",
             STATIC_SOURCE)  # fmt: skip


NUT_SOURCE = (
    "a lower bound of the nut the moving mass carries: a steel sleeve from the ball-centre "
    "diameter out by two ball diameters (the groove and the thinnest wall) over the loaded "
    "turns' length, no flange, no ball return, so a real nut weighs more (not checked "
    "against catalogue masses); a unit slip, g for kg? 0 leaves the mass out"
)


def least_nut_mass(
    pitch_diameter: float, ball_diameter: float, lead: float, turns: float, halves: int
) -> float:
    r"""A lower bound of a ball nut's mass [kg] (:data:`NUT_SOURCE`).

    .. math:: m = \rho\,\frac{\pi}{4}\left[(d_m + 2 D_w)^2 - d_m^2\right] n\,l\,h

    a steel sleeve (:math:`\rho` = 7850 kg/m³) from the ball-centre diameter
    :math:`d_m` to :math:`d_m + 2 D_w` (``ball_diameter`` :math:`D_w`) over the
    length of its loaded turns, ``turns`` :math:`n` (turns per circuit times
    circuits) of ``lead`` :math:`l`, in each of ``halves`` :math:`h` (2 for a
    double nut). The balls' own mass lies inside it.

    >>> print(f"{least_nut_mass(0.025, 0.003175, 0.005, 5.0, 1):.3f}")
    0.055
    """
    area = math.pi / 4.0 * ((pitch_diameter + 2.0 * ball_diameter) ** 2 - pitch_diameter**2)
    return STEEL_DENSITY * area * turns * lead * halves


def check_moving_mass(
    field: str, text: str, mass: float, static_rating: float, least: float = 0.0
) -> None:
    r"""Refuse a moving mass [kg] whose weight exceeds the screw's static rating [N]; warn at half.

    A mass :math:`m` whose weight :math:`m g` exceeds :math:`C_{0a}` dents the
    raceways when it hangs on a vertical axis, and on any axis when it is accelerated
    at 1 g; at half of it the static safety is 2, the middle of the catalogues' 1 to 3
    (:data:`STATIC_SOURCE`). ``text`` is the value as typed, for the message. A mass
    above 0 but below ``least`` [kg] (:func:`least_nut_mass`), lighter than the nut it
    includes, is warned of; 0 leaves the mass out.

    >>> check_moving_mass("axis.moving_mass", "250 kg", 250.0, 144.8e3)
    >>> try:
    ...     check_moving_mass("axis.moving_mass", "2500 t", 2.5e6, 144.8e3)
    ... except BallScrewInputError as exc:
    ...     print(exc.allowed[:16])
    at most 14770 kg
    """
    _against_static(field, text, mass * STANDARD_GRAVITY, static_rating, "its weight",
                    STANDARD_GRAVITY, "kg")  # fmt: skip
    if 0.0 < mass < least:
        warn(field, text, f"at least {least:.2g} kg, the least a nut of this screw weighs",
             NUT_SOURCE)  # fmt: skip


def check_axial_force(field: str, text: str, force: float, static_rating: float) -> None:
    """Refuse an axial force [N] above the screw's static rating [N]; warn above half of it.

    A process force the screw carries (a machine axis' feed force): above
    :math:`C_{0a}` it dents the raceways (:data:`STATIC_SOURCE`).
    """
    _against_static(field, text, abs(force), static_rating, "the force", 1.0, "N")


def check_acceleration(
    field: str, text: str, acceleration: float, mass: float, static_rating: float
) -> None:
    r"""Refuse an acceleration [m/s²] whose force on ``mass`` [kg] exceeds the static rating.

    The screw pushes :math:`m a` into the mass; above :math:`C_{0a}` it dents its
    raceways at every start (:data:`STATIC_SOURCE`), above half of it the static
    safety is below 2 (warned). Nothing is checked without a mass.
    """
    if mass > 0.0:
        _against_static(field, text, mass * acceleration, static_rating,
                        f"the force on the moving mass of {mass:.4g} kg", mass, "m/s²")  # fmt: skip


LOWEST_FREQUENCY = (1.0, 5.0)
r"""The first bending frequency [Hz] of a screw shaft below which its span is refused, and
below which it is warned of.

For a uniform shaft between simple supports, the first natural frequency is
:math:`\omega_1 = \pi^2\sqrt{EI/(\rho A)}/L^2` and the sag under its own weight
:math:`\delta = 5\rho g A L^4/(384 E I)`, so :math:`\omega_1^2\delta = (5\pi^4/384)\,g
\approx 1.27\,g` whatever the size (e.g. Blevins, *Formulas for Natural Frequency and
Mode Shape*, Table 8-1; Timoshenko & Gere, the uniformly loaded simple beam): at 1 Hz
the shaft sags about 0.31 m under its own weight, no nut can run on it; at 5 Hz about
13 mm, and it may turn at no more than 240 rpm (80 % of its critical speed)."""

SPAN_SOURCE = (
    "the shaft's first bending frequency, lambda^2 d_r sqrt(E/rho)/(4 L^2) (Blevins, Table "
    "8-1); a simply supported shaft of first frequency f sags 1.27 g/(2 pi f)^2 under its own "
    "weight: 0.31 m at 1 Hz, 13 mm at 5 Hz"
)


def check_span(
    field: str, text: str, span: float, frequency: float, mounting: str, *, warn_below: bool = True
) -> None:
    """Refuse a span [m] whose shaft bends below 1 Hz; warn below 5 Hz (:data:`LOWEST_FREQUENCY`).

    ``frequency`` [Hz] is the shaft's first bending frequency over ``span``
    (:func:`ballscrew.design.limits.critical_speed` over 2π), ``mounting`` says how
    it was computed ("fixed-supported, root diameter 26.4 mm"); the longest span
    allowed follows from the frequency's :math:`1/L^2`. ``warn_below=False`` only
    refuses (a screw's whole length, which is not its span).

    >>> check_span("axis.bearing_span", "1000 mm", 1.0, 36.0, "fixed-supported")
    >>> try:
    ...     check_span("axis.bearing_span", "900 m", 900.0, 0.0001, "fixed-supported")
    ... except BallScrewInputError as exc:
    ...     print(exc.field, exc.allowed[:15])
    axis.bearing_span at most 9000 mm
    """
    refused, warned = LOWEST_FREQUENCY
    if not math.isfinite(frequency) or frequency < refused:
        longest = span * math.sqrt(frequency / refused) if math.isfinite(frequency) else 0.0
        raise BallScrewInputError(
            field, text,
            f"at most {_plain(longest * 1e3)} mm for this screw ({mounting}): over "
            f"{span:.4g} m its shaft's first bending frequency is {frequency:.3g} Hz, "
            f"below {refused:g} Hz, and it would sag over 0.3 m under its own weight "
            f"({SPAN_SOURCE}); a length in m meant mm?",
        )  # fmt: skip
    if warn_below and frequency < warned:
        longest = span * math.sqrt(frequency / warned)
        warn(field, f"{text} (first bending frequency {frequency:.3g} Hz)",
             f"at most {_plain(longest * 1e3)} mm for this screw ({mounting}), a first bending "
             f"frequency of {warned:g} Hz", SPAN_SOURCE)  # fmt: skip


_SLIP = "; a feed in m/s meant m/min?"
_SLIP_FACTOR = 10.0
"""A feed past the d·n limit by this factor is asked whether m/s was typed for m/min (a
factor 60); a feed a few per cent past it is a design choice, and asked nothing."""


def check_feed(
    field: str, text: str, feed: float, lead: float, pitch_diameter: float, dn_limit: float,
    max_speed: float, *, warn_above: bool = True,
) -> None:  # fmt: skip
    """Refuse a feed [m/s] past the models' largest speed; warn past the nut's d·n limit.

    The screw turns at :math:`n = v/l` (``lead`` :math:`l` [m]); above
    ``max_speed`` [rad/s] (:data:`ballscrew.design.limits.MAX_SPEED`) no operating
    point is taken; above the d·n limit ``dn_limit`` [mm·rpm] (the case's, from its
    catalogue) the ball return is damaged, so a feed limit beyond it never binds.
    ``warn_above=False`` only refuses (a machine axis' feed limit, which only caps the
    planner's moves: the moves that reach the d·n limit are told when run).
    """
    rpm = feed / lead * 60.0
    if not math.isfinite(feed) or feed / lead * 2.0 * math.pi > max_speed:
        raise BallScrewInputError(
            field, text,
            f"at most {max_speed / (2.0 * math.pi) * lead:.4g} m/s at lead {lead * 1e3:g} mm: "
            f"{_plain(rpm)} rpm is past every ball screw's speed (a feed in m/s meant m/min?)",
        )  # fmt: skip
    dn = pitch_diameter * 1e3 * rpm
    if warn_above and dn > dn_limit:
        most = dn_limit / (pitch_diameter * 1e3) * lead  # m/min
        warn(field, f"{text} ({_plain(rpm)} rpm, d·n {dn:,.0f} mm·rpm)",
             f"at most {most:.4g} m/min, the feed at the nut's d·n limit {dn_limit:,.0f} mm·rpm "
             f"with lead {lead * 1e3:g} mm", "the axis' d·n limit (axis.dn_limit, the nut's "
             "catalogue: about 70 000 for external returns, up to 160 000 for high-speed "
             f"nuts){_SLIP if dn > _SLIP_FACTOR * dn_limit else ''}")  # fmt: skip


AXIS_RANGES: dict[str, TypicalRange] = {
    "motor_inertia": TypicalRange(
        (0.0, 0.1),
        (0.0, 10.0),
        1.0,
        "kg*m^2",
        "servo motors' rotors run from about 2e-6 kg*m^2 (50 W) to about 0.1 kg*m^2 (the "
        "largest feed-drive servos, some 30 kW), as recalled from Siemens 1FK7/1FT7, Yaskawa "
        "Sigma-7 and Mitsubishi HG ranges, not checked; above 10 kg*m^2, a solid steel "
        "cylinder 400 mm across and 0.5 m long, lies no feed drive's rotor ('kg*cm**2' "
        "typed as 'kg*m**2'?)",
    ),
    "coupling_inertia": TypicalRange(
        (0.0, 0.01),
        (0.0, 10.0),
        1.0,
        "kg*m^2",
        "couplings of feed drives (bellows, disc, elastomer) run from about 1e-6 to 0.01 "
        "kg*m^2, as recalled from R+W and KTR tables, not checked; above 10 kg*m^2 (a solid "
        "steel cylinder 400 mm across and 0.5 m long) lies no coupling",
    ),
    "screw_inertia": TypicalRange(
        (0.0, 2.0),
        (0.0, 10.0),
        1.0,
        "kg*m^2",
        "a solid steel shaft of 100 mm over 15 m, about the largest ball screw made, has "
        "1.2 kg*m^2 (pi rho L d^4/32); above 10 kg*m^2 lies no ball screw",
    ),
    "gear_ratio": TypicalRange(
        (0.2, 100.0),
        (1e-3, 1e3),
        1.0,
        "",
        "belt stages of 1 to 5 and planetary gearboxes of 3 to 10 a stage, up to 100 in two "
        "(as recalled, not checked), in motor turns per screw turn; outside 1/1000 to 1000 no "
        "feed drive's transmission lies (the ratio inverted?)",
    ),
}
"""The ``[axis]`` quantities held to a fixed range: field -> :class:`TypicalRange` (SI)."""


def check_axis_property(field: str, value: float, name: str | None = None) -> None:
    """Refuse ``value`` [SI] outside :data:`AXIS_RANGES`' possible range, warn outside the typical.

    ``name`` is the key of :data:`AXIS_RANGES` when ``field`` names it otherwise
    (``axis.motor_inertia``).
    """
    _check_range(field, value, AXIS_RANGES[name or field])
