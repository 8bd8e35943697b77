r"""Axial stiffness of a ball screw axis and what it does to positioning (ISO 3408-4).

The nut moves against three springs in series: the screw shaft between the
nut and the bearing that takes the thrust, the ball contacts of the nut, and
the support bearings,

.. math:: \frac{1}{k} = \frac{1}{k_s} + \frac{1}{k_n} + \frac{1}{k_b}.

**Shaft** (THK General Catalog A15, "Axial rigidity of the screw shaft"; ISO
3408-4 clause 5): with :math:`A = \pi d_r^2/4` on the root diameter and the nut
at :math:`a` from the thrust bearing, :math:`k_s = EA/a` when one end takes the
thrust (fixed-free, fixed-supported, supported-supported), and

.. math:: k_s = \frac{E A L}{a\,(L - a)}

when both ends do (fixed-fixed), lowest at mid-span, :math:`4EA/L`.

**Nut**: the Hertz contacts' approach under the ball loads
(:mod:`ballscrew.loads`, :mod:`ballscrew.contact`), :func:`nut_axial_stiffness`:
the stiffness of ideal contacts, every ball carrying its share. The makers
print a lower rigidity for the same nuts (:data:`CATALOGUE_RIGIDITY_RATIO`), and
THK tells designers to take 80 % of that; :func:`design_nut_stiffness` gives
the value a designer would take from the catalogue.

**Axis**: the axial eigenfrequency of the moving mass on that spring,
:math:`f = \sqrt{k/m}/2\pi`, and the lost motion at a reversal: the friction
force :math:`F_f` springs the axis by :math:`F_f/k` one way, then the other,
:math:`\Delta x = 2F_f/k` (the quadrant glitch of a circular test).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
import numpy.typing as npt

from ..contact import hertz
from ..errors import BallScrewInputError, FloatArray, check_positive
from ..geometry import BallScrew
from ..loads import ball_loads

__all__ = [
    "CATALOGUE_RIGIDITY_RATIO",
    "CATALOGUE_RIGIDITY_SCATTER",
    "DESIGN_ALLOWANCE",
    "SHAFT_MODULUS",
    "ReversalPlay",
    "axial_eigenfrequency",
    "design_nut_stiffness",
    "lost_motion",
    "nut_axial_stiffness",
    "reversal_lost_motion",
    "series_stiffness",
    "shaft_axial_stiffness",
    "torsional_axial_stiffness",
]

SHAFT_MODULUS = 206e9
"""Young's modulus of the screw shaft [Pa], as the catalogues take it."""

SHAFT_SHEAR_MODULUS = 79.3e9
r"""Shear modulus of the screw shaft [Pa]: :math:`E/2(1+\nu)` with :math:`\nu` = 0.3."""

CATALOGUE_RIGIDITY_RATIO: float = 1.48
r"""Ideal contact stiffness of a preloaded nut over the rigidity its maker prints [-].

:func:`nut_axial_stiffness` (conformity 0.55, contact angle 45°, the
package's defaults) at a preload of 10 % of the dynamic load rating, the
condition of the printed value, over that value: the median over 10 THK
double and offset-preload nuts (BNFN, BIF; 25 x 5 to 50 x 10 mm; General
Catalog pp. B-658 to B-676), which spread over 1.45 to 1.49 only, so the
model follows the makers' calculation across sizes, leads and circuits and
differs from it by a level. Fitted once (``scripts/fit_nut_rigidity.py``,
``data/catalog_rigidity.csv``). On 10 HIWIN double nuts (FDC, FDI; not used
in the fit) the ratio spans 1.40 to 1.80, median 1.57: the makers' own
calculations differ by that much. What the makers' calculation adds to the
ideal contacts is not printed; uneven load sharing among the balls (pitch
errors, the nut's and shaft's own strain along the nut) is the usual reason
real nuts are softer than their contacts.
"""

CATALOGUE_RIGIDITY_SCATTER: tuple[float, float] = (1.40, 1.80)
"""Range of the ratio over the THK training and HIWIN test nuts [-]."""

DESIGN_ALLOWANCE: float = 0.8
"""Share of the printed nut rigidity THK advises designers to use [-]
(General Catalog, "Axial rigidity of the nut", p. A-709: "roughly 80 %")."""

ONE_END_THRUST = ("fixed-free", "fixed-supported", "supported-supported")


def shaft_axial_stiffness(
    root_diameter: npt.ArrayLike,
    span: float,
    position: npt.ArrayLike,
    support: str = "fixed-supported",
    *,
    youngs_modulus: float = SHAFT_MODULUS,
) -> FloatArray:
    r"""Axial stiffness of the screw shaft at the nut [N/m].

    ``position`` :math:`a` [m] is the nut's distance from the bearing that
    takes the thrust (for fixed-fixed, from either end), ``span`` :math:`L` the
    distance between the supports [m]: :math:`EA/a`, or :math:`EAL/(a(L-a))`
    for fixed-fixed (module docstring).

    Examples
    --------
    A 33.5 mm root: :math:`EA/a` at 0.5 m is 363 N/um; fixed-fixed over 1 m at
    mid-span :math:`4EA/L`, twice that (each half of the shaft carries half the load).

    >>> round(float(shaft_axial_stiffness(0.0335, 1.0, 0.5, "fixed-free")) / 1e6)
    363
    >>> round(float(shaft_axial_stiffness(0.0335, 1.0, 0.5, "fixed-fixed")) / 1e6)
    726
    """
    d = check_positive("root_diameter", root_diameter, "m")
    length = float(check_positive("bearing_span", span, "m"))
    a = np.asarray(position, dtype=float)
    if np.any((a <= 0.0) | (a >= length)):
        raise BallScrewInputError(
            "position", float(a.flat[np.argmax((a <= 0.0) | (a >= length))]),
            f"a nut position strictly between the supports (0 to {length:g} m)",
        )  # fmt: skip
    ea = youngs_modulus * math.pi * d**2 / 4.0
    if support == "fixed-fixed":
        return np.asarray(ea * length / (a * (length - a)), dtype=float)
    if support in ONE_END_THRUST:
        return np.asarray(ea / a, dtype=float)
    raise BallScrewInputError("support", support, f"one of {[*ONE_END_THRUST, 'fixed-fixed']}")


def torsional_axial_stiffness(
    root_diameter: npt.ArrayLike,
    length: npt.ArrayLike,
    lead: float,
    *,
    shear_modulus: float = SHAFT_SHEAR_MODULUS,
) -> FloatArray:
    r"""The shaft's torsion between the drive and the nut, as an axial stiffness [N/m].

    A torque :math:`T` twists a length :math:`a` of the root section by
    :math:`T a/(G J_p)`, :math:`J_p = \pi d_r^4/32`; the nut, held by the
    screw's lead :math:`l`, sees :math:`x = (l/2\pi)\,\theta` under the axial
    force :math:`F = 2\pi T/l`, so

    .. math:: k_t = \frac{G J_p}{a}\Bigl(\frac{2\pi}{l}\Bigr)^2 .

    >>> round(float(torsional_axial_stiffness(0.0266, 0.5, 0.01)) / 1e6)  # N/um
    3077
    """
    d = check_positive("root_diameter", root_diameter, "m")
    a = check_positive("length", length, "m")
    polar = math.pi * d**4 / 32.0
    return np.asarray(shear_modulus * polar / a * (2.0 * math.pi / lead) ** 2, dtype=float)


def nut_axial_stiffness(screw: BallScrew, axial_load: float = 0.0) -> float:
    r"""Axial stiffness of the nut's ball contacts [N/m] at ``axial_load`` [N].

    The contact approach :math:`\delta(Q)` of screw and nut contacts (Hertz)
    maps to an axial displacement :math:`\delta/(\sin\alpha\cos\lambda)`; the
    stiffness is the difference quotient of the external load over the nut's
    displacement (both half-nuts of a double nut or both contact-line
    families of a 4-point nut act as springs in parallel while neither lifts
    off). Only the contacts: the screw shaft, nut body and supports add
    compliance.
    """
    sa = math.sin(screw.contact_angle) * math.cos(screw.lead_angle)
    scale = max(abs(axial_load), screw.preload, 1.0)
    step = 1e-4 * scale
    # ball_loads puts |F| on family 1: difference forward from |F|.
    loads = np.array([abs(axial_load), abs(axial_load) + step])
    bl = ball_loads(screw, loads)
    e = screw.reduced_modulus

    def approach(q: FloatArray) -> FloatArray:
        s = hertz(q, screw.rx_screw, screw.ry_screw, e).approach
        n = hertz(q, screw.rx_nut, screw.ry_nut, e).approach
        return np.asarray(s + n, dtype=float)

    # Displacement of the nut along +F: family 1 (loaded by +F) closes.
    x = approach(bl.normal_load_1) / sa
    if (screw.nut == "single" or not screw.preload > 0.0) and axial_load == 0.0:
        raise BallScrewInputError(
            "axial_load",
            axial_load,
            "a load on a single nut, or on any nut without preload (no stiffness at 0)",
        )
    return float((loads[1] - loads[0]) / (x[1] - x[0]))


def design_nut_stiffness(screw: BallScrew, axial_load: float = 0.0) -> float:
    r"""Axial stiffness of the nut as a designer takes it from a catalogue [N/m].

    .. math:: k_{n,design} = 0.8\,\frac{k_{n,Hertz}}{1.48}

    :func:`nut_axial_stiffness` brought to the makers' printed level
    (:data:`CATALOGUE_RIGIDITY_RATIO`), times THK's design allowance
    (:data:`DESIGN_ALLOWANCE`): 0.54 times the ideal contacts' stiffness.

    Examples
    --------
    >>> from ballscrew import reference_screw
    >>> s = reference_screw()
    >>> round(design_nut_stiffness(s) / nut_axial_stiffness(s), 3)
    0.541
    """
    return DESIGN_ALLOWANCE * nut_axial_stiffness(screw, axial_load) / CATALOGUE_RIGIDITY_RATIO


def series_stiffness(*stiffnesses: npt.ArrayLike | None) -> FloatArray:
    r"""Springs in series: :math:`1/\sum(1/k_j)` [N/m]; None or infinite ones are rigid.

    >>> float(series_stiffness(2e8, 2e8, None))
    100000000.0
    """
    compliance: FloatArray = np.asarray(0.0)
    for k in stiffnesses:
        if k is None:
            continue
        compliance = compliance + 1.0 / check_positive("stiffness", k, "N/m")
    with np.errstate(divide="ignore"):
        return np.asarray(1.0 / compliance, dtype=float)


def axial_eigenfrequency(stiffness: npt.ArrayLike, mass: npt.ArrayLike) -> FloatArray:
    r"""Axial natural frequency of a mass on a spring, :math:`\sqrt{k/m}/2\pi` [Hz].

    >>> round(float(axial_eigenfrequency(1e8, 100.0)), 1)
    159.2
    """
    k = check_positive("stiffness", stiffness, "N/m")
    m = check_positive("moving_mass", mass, "kg")
    return np.asarray(np.sqrt(k / m) / (2.0 * math.pi), dtype=float)


def lost_motion(friction_force: npt.ArrayLike, stiffness: npt.ArrayLike) -> FloatArray:
    r"""Lost motion at a reversal, :math:`2F_f/k` [m].

    >>> round(float(lost_motion(50.0, 1e8)) * 1e6, 2)  # 50 N on 100 N/um, in um
    1.0
    """
    k = check_positive("stiffness", stiffness, "N/m")
    return np.asarray(2.0 * np.abs(np.asarray(friction_force, dtype=float)) / k, dtype=float)


class ReversalPlay(NamedTuple):
    """What a reversal does to the axis (SI), each over the nut positions asked."""

    friction_force: FloatArray
    """The screw's drag as an axial force, :math:`2\\pi T_f/l` [N]."""
    stiffness: FloatArray
    """The axis's stiffness at the nut: shaft, nut and bearings in series [N/m]."""
    lost_motion: FloatArray
    """:math:`2F_f/k` [m]."""


def reversal_lost_motion(
    friction_torque: npt.ArrayLike, lead: float, root_diameter: float, span: float,
    position: npt.ArrayLike, support: str, nut_stiffness: float,
    bearing_stiffness: float | None = None,
) -> ReversalPlay:  # fmt: skip
    r"""The lost motion of a reversal with the nut at ``position`` [m] from the thrust end.

    The screw's drag torque ``friction_torque`` :math:`T_f` [N·m] as an axial
    force :math:`F_f = 2\pi T_f/l` on the lead :math:`l` [m]; the axis's
    stiffness :math:`k` at the nut, the shaft (:func:`shaft_axial_stiffness`
    over ``span`` with ``support``), the nut (``nut_stiffness``, e.g.
    :func:`design_nut_stiffness`) and the bearings (None: rigid) in series
    (:func:`series_stiffness`); the lost motion :math:`2F_f/k`
    (:func:`lost_motion`). Broadcasts the torque against the positions.

    Examples
    --------
    0.1 N·m on a 10 mm lead is 62.8 N; a 26.6 mm root 0.5 m from the thrust end
    (EA/a = 229 N/um) in series with a 500 N/um nut gives 157.0 N/um, 0.80 um:

    >>> play = reversal_lost_motion(0.1, 0.01, 0.0266, 1.0, 0.5, "fixed-supported", 5e8)
    >>> [round(float(x), 2) for x in (play.friction_force, play.stiffness / 1e6,
    ...                               play.lost_motion * 1e6)]
    [62.83, 157.04, 0.8]
    """
    pos = np.asarray(position, dtype=float)
    torque = np.asarray(friction_torque, dtype=float)
    shape = np.broadcast_shapes(torque.shape, pos.shape)
    force = 2.0 * math.pi * np.broadcast_to(torque, shape) / lead
    k_shaft = shaft_axial_stiffness(root_diameter, span, pos, support)
    k = np.broadcast_to(series_stiffness(k_shaft, nut_stiffness, bearing_stiffness), shape)
    play = np.broadcast_to(lost_motion(force, k), shape)
    return ReversalPlay(force, k, play)
