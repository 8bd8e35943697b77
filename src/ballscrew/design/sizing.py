r"""Sizing a ball screw: fatigue life, static safety, buckling, thermal lead error, the motor.

The formulas of ISO 3408-5 and of the makers' selection flows (THK, NSK, HIWIN)
that a feed-drive designer checks beside the friction. Each function is pure
and broadcasts over numpy arrays; SI units throughout.

**Life (ISO 3408-5:2006, clause 7).** A load spectrum of axial loads
:math:`F_i` over :math:`n_i` revolutions has the cubic mean load

.. math:: F_m = \Bigl(\frac{\sum_i |F_i|^3 n_i}{\sum_i n_i}\Bigr)^{1/3},

and the nominal life in revolutions is

.. math:: L_{10} = a_1 \Bigl(\frac{C_a}{F_m}\Bigr)^3 \cdot 10^6,

with :math:`a_1` the reliability factor (:data:`RELIABILITY_FACTORS`). The
makers' selection flows size with the mean load times a **load factor**
:math:`f_w \ge 1` for the running conditions,
:math:`L_{10} = a_1 (C_a/(f_w F_m))^3\cdot 10^6` (:data:`LOAD_FACTORS`): ISO
3408-5's life is :math:`f_w = 1`. In a
preloaded nut (double nut, or a 4-point nut) each half carries the preload
changed by the external load; ISO 3408-5 and the catalogues take

.. math:: F_1 = F_{pr}\Bigl(1 + \frac{|F_a|}{2^{3/2}F_{pr}}\Bigr)^{3/2},
          \quad F_2 = F_1 - |F_a|,

up to the lift-off of the relieved half at :math:`|F_a| = 2^{3/2}F_{pr}`
(:func:`preloaded_loads`), each half's life from its own cubic mean load, and
the nut's life as the two in series:
:math:`L = (L_1^{-10/9} + L_2^{-10/9})^{-9/10}` (:func:`combined_life`).

**Static safety.** :math:`f_s = C_{0a}/F_{max}` (ISO 3408-5, clause 6). THK's guideline
for machine tools is 1 to 1.5 without vibration or impact and 2.5 to 7 with
them (2 to 3 with them for general machinery; General Catalog, "Static Safety
Factor", Table 18, p. A-703); the check's default least value, 2, sits
between.

**Buckling.** Euler's load of the root-diameter section with the mounting's
end-condition factor, times the catalogue's safety factor 0.5 (THK General
Catalog, "Permissible Axial Load", A15-30, equation 5; HSK prints the same):

.. math:: P = s\,\eta\,\frac{\pi^2 E I}{L^2}, \qquad I = \frac{\pi d_r^4}{64},

:math:`\eta` = 0.25 (fixed-free), 1 (supported-supported), 2
(fixed-supported), 4 (fixed-fixed) (:data:`BUCKLING_FACTORS`). With
:math:`E` = 206 GPa and :math:`s` = 0.5 this is the catalogues' rule
:math:`P = m\,d_r^4/L^2\cdot 10^4` N (mm) with :math:`m` = 1.25, 4.99, 9.98,
19.96; THK's English General Catalog rounds these to 1.3, 10 and 20 (p. A-694,
no supported-supported entry), other prints give 5.1, 10.2 and 20.3.

**Thermal lead error.** A screw warmer than its mounting by :math:`\Delta T`
lengthens by :math:`\Delta L = \alpha\,\Delta T\,L` (:math:`\alpha` =
11.5e-6 1/K for bearing steel); over 300 mm of travel this is a lead error to
set against the accuracy grade's travel variation :math:`v_{300p}`
(:data:`TRAVEL_VARIATION_300`).

**Motor.** The load's inertia seen by the motor,
:math:`J_L = [J_s + J_c + m(l/2\pi)^2]/i^2`, against the rotor's
(:func:`reflected_inertia`).
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from ..errors import BallScrewInputError, FloatArray, check_nonnegative, check_positive
from ..materials import STEEL_EXPANSION  # re-exported: the check and its tests read it here
from .stiffness import SHAFT_MODULUS

__all__ = [
    "BUCKLING_FACTORS",
    "BUCKLING_SAFETY",
    "LOAD_FACTORS",
    "RELIABILITY_FACTORS",
    "RELIABILITY_FACTORS_ISO_281",
    "STEEL_EXPANSION",
    "TRAVEL_VARIATION_300",
    "buckling_load",
    "combined_life",
    "cubic_mean_load",
    "life_distance",
    "life_hours",
    "nominal_life",
    "preloaded_loads",
    "reflected_inertia",
    "reliability_factor",
    "static_safety",
    "thermal_elongation",
]

RELIABILITY_FACTORS: dict[float, float] = {
    0.90: 1.0,
    0.95: 0.62,
    0.96: 0.53,
    0.97: 0.44,
    0.98: 0.33,
    0.99: 0.21,
}
"""Life factor :math:`a_1` by reliability, ISO 3408-5:2006 (Table of :math:`a_1`) [-]."""

RELIABILITY_FACTORS_ISO_281: dict[float, float] = {
    0.90: 1.0,
    0.95: 0.64,
    0.96: 0.55,
    0.97: 0.47,
    0.98: 0.37,
    0.99: 0.25,
}
"""The rolling bearings' :math:`a_1` (ISO 281:2007, Table 12), for comparison [-]."""

LOAD_FACTORS: dict[str, tuple[float, float]] = {
    "smooth": (1.0, 1.2),
    "normal": (1.2, 1.5),
    "impact": (1.5, 3.0),
}
r"""Range of the load factor :math:`f_w` by running condition [-].

The mean load is multiplied by :math:`f_w` before the life is computed:
smooth running without impact 1.0 to 1.2, normal running 1.2 to 1.5, running
with impact or vibration 1.5 to 3.0. THK prints these three ranges (General
Catalog, Ball Screw, "Studying the Service Life", table of the load factor,
A15-40 in catalogue 504E); HIWIN (*Ballscrews & Accessories*, the life
calculation's operating-condition factor :math:`f_w`) and NSK (the load
factor of its life calculation) size the same way; MISUMI's worked example
takes :math:`f_w` = 1.2 (Economy Series e-catalog 2025, "Selection of Ball
Screws", p. 1676).
"""

BUCKLING_FACTORS: dict[str, float] = {
    "fixed-free": 0.25,
    "supported-supported": 1.0,
    "fixed-supported": 2.0,
    "fixed-fixed": 4.0,
}
r"""End-condition factor :math:`\eta` of Euler's buckling load (THK's :math:`\eta_1`) [-]."""

BUCKLING_SAFETY = 0.5
"""Safety factor the catalogues apply to Euler's load (THK A15-30 eq. 5, HSK) [-]."""

TRAVEL_VARIATION_300: dict[str, float] = {
    # ISO 3408-3:2006, positioning (P) and transport (T) grades, v_300p
    "P0": 3.5e-6,
    "P1": 6e-6,
    "P3": 12e-6,
    "P5": 23e-6,
    "T5": 23e-6,
    "T7": 52e-6,
    "T10": 210e-6,
    # JIS B 1192-1997: fluctuation over 300 mm (C0 to C5), travel distance error per 300 mm
    # (C7 to C10)
    "C0": 3.5e-6,
    "C1": 5e-6,
    "C2": 7e-6,
    "C3": 8e-6,
    "C5": 18e-6,
    "C7": 50e-6,
    "C8": 100e-6,
    "C10": 210e-6,
}
r"""Permissible travel variation over 300 mm by accuracy grade [m].

The C grades are JIS B 1192-1997 as THK prints them (General Catalog, English,
"Accuracy of the Ball Screw", p. A-678): for C0, C1, C2, C3 and C5 the
permissible fluctuation over 300 mm of thread (Table 2: 3.5, 5, 7, 8, 18 µm);
for the rolled grades C7, C8 and C10 the permissible travel distance error
over 300 mm (Table 1: ±50, ±100, ±210 µm), which THK's selection examples use
as the grade's figure (pp. A-723 and A-737).

The P and T grades are the :math:`v_{300p}` of ISO 3408-3:2006 as HIWIN
prints them for its tolerance classes 0, 1, 3, 5, 7 and 10 (*Ballscrews &
Accessories*, BS-08-2-EN-1704-K, Table 3.3, p. 15: 3.5, 6, 12, 23, 52,
210 µm); T5 takes grade 5's figure. HIWIN names these classes T0 to T10 in its
own scheme, which is not ISO's transport grade T, so only ISO's names are
keys here. P3 = 12 µm is also Steinmeyer's "lead error over 300 mm". Grades 2
and 4 of ISO 3408-3 are left out (HIWIN prints 8 and 18 µm for them under
"JIS", the figures THK gives for C3 and C5, so the naming is not settled).
"""


def reliability_factor(reliability: float) -> float:
    """The life factor :math:`a_1` of ISO 3408-5 at a reliability of 0.90 to 0.99 [-]."""
    key = round(float(reliability), 2)
    if key not in RELIABILITY_FACTORS or abs(key - float(reliability)) > 1e-9:
        raise BallScrewInputError(
            "reliability", reliability, f"one of {sorted(RELIABILITY_FACTORS)} (ISO 3408-5)"
        )
    return RELIABILITY_FACTORS[key]


def preloaded_loads(
    axial_load: npt.ArrayLike, preload: npt.ArrayLike
) -> tuple[FloatArray, FloatArray]:
    r"""Axial loads of the loaded and the relieved half of a preloaded nut [N] (ISO 3408-5).

    :math:`F_1 = F_{pr}(1 + |F_a|/(2^{3/2}F_{pr}))^{3/2}` and
    :math:`F_2 = F_1 - |F_a|` up to lift-off at :math:`|F_a| = 2^{3/2}F_{pr}`;
    past it :math:`F_1 = |F_a|`, :math:`F_2 = 0`. Without preload,
    :math:`F_1 = |F_a|`. (The exact Hertz split is
    :func:`ballscrew.loads.preload_split`; the standard's form is within 2.5 %.)

    Examples
    --------
    >>> f1, f2 = preloaded_loads([0.0, 1000.0, 5000.0], 1000.0)
    >>> [round(float(v)) for v in f1], [round(float(v)) for v in f2]
    ([1000, 1575, 5000], [1000, 575, 0])
    """
    fa = np.abs(np.asarray(axial_load, dtype=float))
    fpr = check_nonnegative("preload", preload, "N")
    lift = 2.0**1.5 * fpr
    with np.errstate(divide="ignore", invalid="ignore"):
        inside = fpr * (1.0 + fa / np.where(lift > 0.0, lift, 1.0)) ** 1.5
    f1 = np.where(fa < lift, inside, fa)
    return np.asarray(f1, dtype=float), np.asarray(f1 - fa, dtype=float)


def cubic_mean_load(loads: npt.ArrayLike, revolutions: npt.ArrayLike) -> FloatArray:
    r"""Cubic mean of axial loads over the revolutions made under each [N] (ISO 3408-5).

    :math:`F_m = (\sum |F_i|^3 n_i / \sum n_i)^{1/3}` over the last axis;
    ``revolutions`` :math:`n_i \ge 0` (any unit: only their shares count).

    Examples
    --------
    The catalogues' three-phase spectrum: 2000 N over 100 turns, 1000 N over 800,
    3000 N over 100: :math:`((0.8 + 0.8 + 2.7)\cdot 10^{12} / 1000)^{1/3}` = 1626 N.

    >>> round(float(cubic_mean_load([2000.0, 1000.0, 3000.0], [100.0, 800.0, 100.0])))
    1626
    """
    f = np.abs(np.asarray(loads, dtype=float))
    n = check_nonnegative("revolutions", revolutions)
    total = np.sum(n, axis=-1)
    if np.any(total <= 0.0):
        raise BallScrewInputError("revolutions", "(all zero)", "some revolutions under load")
    return np.asarray(np.cbrt(np.sum(f**3 * n, axis=-1) / total), dtype=float)


def nominal_life(
    dynamic_rating: npt.ArrayLike,
    mean_load: npt.ArrayLike,
    reliability: float = 0.90,
    load_factor: npt.ArrayLike = 1.0,
) -> FloatArray:
    r"""Nominal life in revolutions [-]: :math:`a_1 (C_a/(f_w F_m))^3\cdot 10^6`.

    ISO 3408-5's life with the makers' load factor :math:`f_w \ge 1`
    (:data:`LOAD_FACTORS`; 1, the default, is the standard's own life).
    ``dynamic_rating`` :math:`C_a` and ``mean_load`` :math:`F_m` in N; a zero
    mean load gives an infinite life.

    Examples
    --------
    :math:`C_a` = 63.4 kN at 3 kN: 9.44e9 revolutions; at 99 % reliability 0.21 of it.

    >>> f"{float(nominal_life(63400.0, 3000.0)):.3e}"
    '9.439e+09'
    >>> f"{float(nominal_life(63400.0, 3000.0, 0.99)):.3e}"
    '1.982e+09'

    With :math:`f_w` = 1.2 the life is :math:`1.2^3` = 1.728 times shorter:

    >>> f"{float(nominal_life(63400.0, 3000.0, load_factor=1.2)):.3e}"
    '5.462e+09'
    """
    c = check_positive("dynamic_load_rating", dynamic_rating, "N")
    fw = check_positive("load_factor", load_factor)
    if np.any(fw < 1.0):
        raise BallScrewInputError(
            "load_factor", load_factor, "a factor >= 1 (1: ISO 3408-5's life; THK: 1.0 to 3.0)"
        )
    f = check_nonnegative("mean_load", mean_load, "N") * fw
    with np.errstate(divide="ignore"):
        ratio = np.where(f > 0.0, c / np.where(f > 0.0, f, 1.0), np.inf)
    return np.asarray(reliability_factor(reliability) * ratio**3 * 1e6, dtype=float)


def life_hours(revolutions: npt.ArrayLike, mean_speed: npt.ArrayLike) -> FloatArray:
    r"""A life in revolutions as hours at a mean speed [h]: :math:`L_h = L/(60\,n_m)`.

    ``mean_speed`` :math:`n_m` in rpm: the revolutions of a duty cycle over its
    duration, dwells included (ISO 3408-5's mean speed).

    >>> round(float(life_hours(9.439e9, 1500.0)))
    104878
    """
    n = check_positive("mean_speed", mean_speed, "rpm")
    return np.asarray(np.asarray(revolutions, dtype=float) / (60.0 * n), dtype=float)


def life_distance(revolutions: npt.ArrayLike, lead: float) -> FloatArray:
    r"""A life in revolutions as travel [m]: :math:`L_s = L\,l`.

    >>> float(life_distance(1e9, 0.01)) / 1e3  # km
    10000.0
    """
    return np.asarray(
        np.asarray(revolutions, dtype=float) * float(check_positive("lead", lead, "m")),
        dtype=float,
    )


def combined_life(*lives: npt.ArrayLike) -> FloatArray:
    r"""Life of parts that fail in series: :math:`(\sum L_j^{-10/9})^{-9/10}` (ISO 3408-5).

    The two halves of a preloaded nut, or the two flanks of a single nut
    loaded both ways. Infinite lives drop out.

    >>> round(float(combined_life(1e9, 1e9)) / 1e9, 3)
    0.536
    """
    total = sum(np.asarray(v, dtype=float) ** (-10.0 / 9.0) for v in lives)
    with np.errstate(divide="ignore"):
        return np.asarray(np.asarray(total, dtype=float) ** (-0.9), dtype=float)


def static_safety(static_rating: npt.ArrayLike, max_load: npt.ArrayLike) -> FloatArray:
    r"""Static safety factor :math:`f_s = C_{0a}/F_{max}` [-] (infinite without load)."""
    c0 = check_positive("static_load_rating", static_rating, "N")
    f = np.abs(np.asarray(max_load, dtype=float))
    with np.errstate(divide="ignore"):
        return np.asarray(np.where(f > 0.0, c0 / np.where(f > 0.0, f, 1.0), np.inf), dtype=float)


def buckling_load(
    root_diameter: npt.ArrayLike,
    length: npt.ArrayLike,
    support: str = "fixed-supported",
    *,
    safety: float = BUCKLING_SAFETY,
    youngs_modulus: float = SHAFT_MODULUS,
) -> FloatArray:
    r"""Permissible compressive load of the screw shaft against buckling [N].

    :math:`P = s\,\eta\,\pi^2 E I/L^2` with :math:`I = \pi d_r^4/64`
    (module docstring); ``length`` is the unsupported length between the
    bearing that takes the thrust and the nut (the catalogues' :math:`l_a`).

    Examples
    --------
    THK's rule for a 33.5 mm root over 1 m, fixed-supported:
    :math:`10.2 \cdot 33.5^4/1000^2 \cdot 10^4` = 128.4 kN (its factor rounded
    from 9.98).

    >>> round(float(buckling_load(0.0335, 1.0)) / 1e3, 1)
    125.7
    """
    if support not in BUCKLING_FACTORS:
        raise BallScrewInputError("support", support, f"one of {list(BUCKLING_FACTORS)}")
    d = check_positive("root_diameter", root_diameter, "m")
    span = check_positive("length", length, "m")
    inertia = math.pi * d**4 / 64.0
    return np.asarray(
        safety * BUCKLING_FACTORS[support] * math.pi**2 * youngs_modulus * inertia / span**2,
        dtype=float,
    )


def thermal_elongation(
    temperature_rise: npt.ArrayLike, length: npt.ArrayLike, expansion: float = STEEL_EXPANSION
) -> FloatArray:
    r"""Thermal elongation :math:`\Delta L = \alpha\,\Delta T\,L` [m].

    >>> round(float(thermal_elongation(3.0, 0.3)) * 1e6, 2)  # 3 K over 300 mm, in um
    10.35
    """
    return np.asarray(
        expansion * np.asarray(temperature_rise, dtype=float) * np.asarray(length, dtype=float),
        dtype=float,
    )


def reflected_inertia(
    moving_mass: float,
    lead: float,
    screw_inertia: float = 0.0,
    coupling_inertia: float = 0.0,
    gear_ratio: float = 1.0,
) -> float:
    r"""Inertia of the load seen at the motor [kg·m²]: :math:`[J_s + J_c + m(l/2\pi)^2]/i^2`.

    ``gear_ratio`` :math:`i` is motor turns per screw turn.

    >>> f"{reflected_inertia(100.0, 0.01, 1e-4):.4e}"
    '3.5330e-04'
    """
    check_nonnegative("moving_mass", moving_mass, "kg")
    check_positive("lead", lead, "m")
    check_positive("gear_ratio", gear_ratio)
    linear = moving_mass * (lead / (2.0 * math.pi)) ** 2
    return float((screw_inertia + coupling_inertia + linear) / gear_ratio**2)
