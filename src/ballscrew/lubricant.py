r"""Lubricant properties: viscosity against temperature and pressure, density.

This module is long on purpose: each published correlation (ASTM D341, Vogel,
Barus, Roelands, Jungnickel, the linear density) is one pure function with its
equation, units and reference written out, and :class:`Lubricant`, which applies
them to one oil, stays beside them.

Pure functions for each published correlation, and the :class:`Lubricant`
object that holds one oil's data and applies them. Temperatures are in °C,
everything else in SI units (kinematic viscosity in m²/s, dynamic viscosity
in Pa·s, density in kg/m³, pressure in Pa).

References
----------
.. [1] ASTM D341-20, "Standard practice for viscosity-temperature equations
   and charts for liquid petroleum or hydrocarbon products", ASTM
   International, doi:10.1520/D0341-20.
.. [2] C. Walther, "Über die Auswertung von Viskositätsangaben", Erdöl und
   Teer 7 (1931) 382-384.
.. [3] H. Vogel, "Das Temperaturabhängigkeitsgesetz der Viskosität von
   Flüssigkeiten", Phys. Z. 22 (1921) 645-646.
.. [4] C. Barus, "Isothermals, isopiestics and isometrics relative to
   viscosity", Am. J. Sci. 45 (1893) 87-96.
.. [5] C. J. A. Roelands, *Correlational aspects of the viscosity-
   temperature-pressure relationship of lubricating oils*, PhD thesis, TU
   Delft, 1966.
.. [6] B. J. Hamrock, S. R. Schmid, B. O. Jacobson, *Fundamentals of Fluid
   Film Lubrication*, 2nd ed., Marcel Dekker, 2004, ch. 4.
"""

from __future__ import annotations

import functools
import re
import warnings
from dataclasses import dataclass, fields, replace
from typing import Any, Literal, get_args

import numpy as np
import numpy.typing as npt

from .errors import (
    BallScrewInputError,
    BallScrewPlausibilityWarning,
    FloatArray,
    check_choice,
    check_finite,
    check_in_range,
    check_nonnegative,
    check_positive,
)
from .numerics.single import every, minimum
from .plausible import LUBRICANT_RANGES, check_lubricant_property

__all__ = [
    "FLOODED",
    "LUBRICANT_KINDS",
    "LUBRICATIONS",
    "NLGI_GRADES",
    "PRESSURE_VISCOSITY_MODELS",
    "VISCOSITY_MODELS",
    "Lubricant",
    "astm_d341_constants",
    "astm_d341_viscosity",
    "barus_1893",
    "density_linear",
    "lubrication_method",
    "pressure_viscosity_jungnickel",
    "pressure_viscosity_unchecked",
    "roelands_1966",
    "roelands_alpha",
    "roelands_z",
    "vogel_constants",
    "vogel_viscosity",
]

ArrayLike = npt.ArrayLike
KELVIN = 273.15
"""Offset from °C to K."""

LubricantKind = Literal["oil", "grease"]
LUBRICANT_KINDS: tuple[str, ...] = get_args(LubricantKind)
NLGI_GRADES: tuple[str, ...] = ("000", "00", "0", "1", "2", "3", "4", "5", "6")
"""The NLGI consistency grades (NLGI, ASTM D217 worked penetration classes), softest first."""
_NLGI = r"(?:000|00|[0-6](?:\.5)?)"
_NLGI_GRADE = re.compile(rf"{_NLGI}(?:-{_NLGI})?")

ViscosityModel = Literal["astm_d341", "vogel"]
VISCOSITY_MODELS: tuple[str, ...] = get_args(ViscosityModel)
PressureViscosityModel = Literal["roelands", "barus"]
PRESSURE_VISCOSITY_MODELS: tuple[str, ...] = get_args(PressureViscosityModel)

LUBRICATIONS = ("flooded", "circulating", "oil-air", "drip", "grease")
"""How the oil reaches the balls: the lubrication methods of the complete model
(:func:`ballscrew.friction.complete.complete`, its ``lubrication``).

``"flooded"``
    An oil bath or any arrangement that keeps the nut full of oil: the balls
    run immersed.
``"circulating"``
    Oil pumped through the nut, which it keeps full: the same terms as
    ``"flooded"``.
``"oil-air"``
    Oil-air (or oil mist): oil carried in by air in small amounts.
``"drip"``
    Oil dripped or metered onto the track at intervals, the nut not full: the
    default (``"auto"``) for an oil. The makers' drag torques
    (:mod:`ballscrew.study.validation`, on which the complete model's ball-train
    constant was fitted) state the oil (ISO VG 68) and the speed but not a bath; a nut
    turned on a test bench has its oil applied, not immersed, so the default
    keeps what they measure. ``"oil"``, its name before the other methods
    were modelled, is read as ``"drip"``.
``"grease"``
    A grease-packed nut; the default for a grease
    (:attr:`ballscrew.lubricant.Lubricant.kind`).
"""

FLOODED = ("flooded", "circulating")
"""The methods of :data:`LUBRICATIONS` that keep the nut full of oil."""


def lubrication_method(lubrication: str, lubricant: Lubricant) -> str:
    """The method of :data:`LUBRICATIONS` that ``lubrication`` names for ``lubricant``.

    ``"auto"``: ``"grease"`` for a grease, ``"drip"`` for an oil; ``"oil"`` is read as
    ``"drip"``. A grease cannot flood a nut (its base oil stays in the thickener):
    ``"flooded"``, ``"circulating"``, ``"drip"`` and ``"oil-air"`` with a grease are refused.
    """
    method = check_choice("lubrication", lubrication, ("auto", "oil", *LUBRICATIONS))
    grease = lubricant.kind == "grease"
    if method == "auto":
        return "grease" if grease else "drip"
    if method == "oil":
        method = "drip"
    if grease and method != "grease":
        raise BallScrewInputError(
            "lubrication", lubrication,
            f"'grease' or 'auto' for the grease {lubricant.name!r} (a grease does not "
            "fill the nut with oil)",
        )  # fmt: skip
    return method


_CST = 1e-6  # m²/s per mm²/s (cSt)
ROELANDS_PRESSURE = 1.96e8
"""Roelands' reference pressure :math:`p_r` = 0.196 GPa [Pa] ([6] eq. 4.10)."""
ROELANDS_LN_ETA_INF = -9.67
r""":math:`\ln\eta_\infty` with :math:`\eta_\infty = 6.31\cdot10^{-5}` Pa·s ([6] eq. 4.10)."""
PRESSURE_VISCOSITY_TEMPERATURE = 40.0
"""Temperature [°C] at which a :class:`Lubricant`'s ``pressure_viscosity`` is given.

The bundled oils' coefficients are quoted at 40 °C (``data/lubricants.csv``),
the temperature of the ISO 3448 viscosity grade.
"""


def _temperature(value: ArrayLike) -> FloatArray:
    return check_in_range("temperature", value, -KELVIN, np.inf, unit="°C (above absolute zero)")


def astm_d341_constants(
    nu1: ArrayLike, t1: ArrayLike, nu2: ArrayLike, t2: ArrayLike
) -> tuple[FloatArray, FloatArray]:
    r"""Constants A and B of the ASTM D341 (Walther) equation through two points.

    .. math:: \log_{10}\log_{10}(\nu + 0.7) = A - B\log_{10}T

    with :math:`\nu` in mm²/s and :math:`T` in kelvin.

    Parameters
    ----------
    nu1, nu2 : array_like
        Kinematic viscosities at the two temperatures [m²/s], each > 0.3 mm²/s.
    t1, t2 : array_like
        The two temperatures [°C], ``t1 != t2``.

    Returns
    -------
    A, B : numpy.ndarray
        Constants of the equation [-] (for ν in mm²/s and T in K).

    Examples
    --------
    PAO ISO VG 68 with 68 mm²/s at 40 °C and 10.3 mm²/s at 100 °C:

    >>> a, b = astm_d341_constants(68e-6, 40.0, 10.3e-6, 100.0)
    >>> round(float(a), 4), round(float(b), 4)
    (8.3444, 3.2376)
    """
    z1 = _walther_z(check_positive("nu1", nu1, "m²/s"), "nu1")
    z2 = _walther_z(check_positive("nu2", nu2, "m²/s"), "nu2")
    k1 = np.log10(_temperature(t1) + KELVIN)
    k2 = np.log10(_temperature(t2) + KELVIN)
    if np.any(k1 == k2):
        raise BallScrewInputError("t2", t2, "a temperature different from t1")
    b: FloatArray = (z1 - z2) / (k2 - k1)
    a: FloatArray = z1 + b * k1
    return a, b


def _walther_z(nu: FloatArray, field: str) -> FloatArray:
    r"""Walther's double logarithm of ASTM D341's Z, for a viscosity in m²/s.

    :math:`Z = \nu + 0.7 + \exp(-1.47 - 1.84\nu - 0.51\nu^2)` (ν in mm²/s),
    the D341-09 form valid down to about 0.3 mm²/s; the exponential is below
    1e-10 above 4 mm²/s.
    """
    cst = nu / _CST
    if np.any(cst < 0.3):
        raise BallScrewInputError(field, float(np.min(nu)), "a viscosity of at least 0.3 mm²/s")
    z = cst + 0.7 + np.exp(-1.47 - 1.84 * cst - 0.51 * cst**2)
    result: FloatArray = np.log10(np.log10(z))
    return result


def astm_d341_viscosity(temperature: ArrayLike, a: ArrayLike, b: ArrayLike) -> FloatArray:
    r"""Kinematic viscosity from the ASTM D341 (Walther) equation.

    .. math::
        Z = 10^{10^{A - B\log_{10}T}},\qquad
        \nu = (Z - 0.7) - \exp[-0.7487 - 3.295(Z-0.7) + 0.6119(Z-0.7)^2
               - 0.3193(Z-0.7)^3]

    with :math:`\nu` in mm²/s and :math:`T` in kelvin (ASTM D341-09 and
    later). The exponential corrects viscosities below about 2 mm²/s and is
    negligible above 4 mm²/s.

    Parameters
    ----------
    temperature : array_like
        Temperature [°C].
    a, b : array_like
        Constants from :func:`astm_d341_constants` [-].

    Returns
    -------
    numpy.ndarray
        Kinematic viscosity [m²/s].

    Examples
    --------
    >>> a, b = astm_d341_constants(68e-6, 40.0, 10.3e-6, 100.0)
    >>> round(float(astm_d341_viscosity(20.0, a, b)) * 1e6, 1)  # mm²/s
    187.5
    """
    t = _temperature(temperature) + KELVIN
    with np.errstate(over="ignore"):
        z = 10.0 ** (10.0 ** (np.asarray(a) - np.asarray(b) * np.log10(t)))
    zm = z - 0.7
    # The correction vanishes above a few mm²/s (exp(-292) at 10): capping its
    # argument keeps an overflowed Z an infinite viscosity instead of inf - inf.
    zc = minimum(zm, 10.0)
    correction = np.exp(-0.7487 - 3.295 * zc + 0.6119 * zc**2 - 0.3193 * zc**3)
    result: FloatArray = (zm - correction) * _CST
    return result


def vogel_constants(
    nu1: ArrayLike, t1: ArrayLike, nu2: ArrayLike, t2: ArrayLike, c: ArrayLike = 95.0
) -> tuple[FloatArray, FloatArray]:
    r"""Constants of Vogel's equation :math:`\nu = A\exp[B/(T + C)]` through two points.

    Parameters
    ----------
    nu1, nu2 : array_like
        Kinematic viscosities [m²/s] at temperatures ``t1``, ``t2`` [°C].
    c : array_like
        Vogel's third constant [°C]; default 95 °C, the value of Cameron's
        fixed-C form used for mineral oils.

    Returns
    -------
    A : numpy.ndarray
        [m²/s].
    B : numpy.ndarray
        [°C].

    Examples
    --------
    >>> a, b = vogel_constants(68e-6, 40.0, 10.3e-6, 100.0)
    >>> round(float(b), 1)
    828.1
    """
    n1 = check_positive("nu1", nu1, "m²/s")
    n2 = check_positive("nu2", nu2, "m²/s")
    ta = _temperature(t1)
    tb = _temperature(t2)
    cc = check_finite("c", c)
    if np.any(ta == tb):
        raise BallScrewInputError("t2", t2, "a temperature different from t1")
    if np.any((ta + cc <= 0.0) | (tb + cc <= 0.0)):
        raise BallScrewInputError("c", c, "a value with temperature + c > 0 at both points")
    b: FloatArray = np.log(n1 / n2) / (1.0 / (ta + cc) - 1.0 / (tb + cc))
    a: FloatArray = n1 * np.exp(-b / (ta + cc))
    return a, b


def vogel_viscosity(
    temperature: ArrayLike, a: ArrayLike, b: ArrayLike, c: ArrayLike = 95.0
) -> FloatArray:
    r"""Kinematic viscosity from Vogel's equation, :math:`\nu = A\exp[B/(T + C)]`.

    Parameters
    ----------
    temperature : array_like
        [°C], above :math:`-C`.
    a : array_like
        [m²/s].
    b, c : array_like
        [°C].

    Returns
    -------
    numpy.ndarray
        Kinematic viscosity [m²/s].

    Examples
    --------
    Thermca's mineral VG 68 constants (A = 0.071e-6 m²/s, B = 929 °C):

    >>> round(float(vogel_viscosity(40.0, 0.071e-6, 929.0)) * 1e6, 1)
    69.2
    """
    t = _temperature(temperature)
    cc = np.asarray(c, dtype=float)
    if np.any(t + cc <= 0.0):
        raise BallScrewInputError("temperature", temperature, "a value above -c (Vogel)")
    result: FloatArray = np.asarray(a) * np.exp(np.asarray(b) / (t + cc))
    return result


def density_linear(
    temperature: ArrayLike, density15: ArrayLike, expansion: ArrayLike = 6.5e-4
) -> FloatArray:
    r"""Density of an oil against temperature, linear in temperature.

    .. math:: \rho(T) = \rho_{15}\,[1 - \beta_\rho (T - 15)]

    Parameters
    ----------
    temperature : array_like
        [°C].
    density15 : array_like
        Density at 15 °C [kg/m³].
    expansion : array_like
        :math:`\beta_\rho` [1/K]; default 6.5e-4 /K, typical of mineral oils
        and PAOs between 0 and 150 °C (Hamrock et al. [6] ch. 4).

    Returns
    -------
    numpy.ndarray
        Density [kg/m³].

    Examples
    --------
    >>> round(float(density_linear(40.0, 850.0)), 2)
    836.19
    """
    t = _temperature(temperature)
    result: FloatArray = np.asarray(density15) * (1.0 - np.asarray(expansion) * (t - 15.0))
    return result


def barus_1893(viscosity: ArrayLike, alpha: ArrayLike, pressure: ArrayLike) -> FloatArray:
    r"""Viscosity at pressure by Barus's exponential law, :math:`\eta = \eta_0 e^{\alpha p}`.

    Parameters
    ----------
    viscosity : array_like
        Dynamic viscosity at ambient pressure :math:`\eta_0` [Pa·s].
    alpha : array_like
        Pressure-viscosity coefficient :math:`\alpha` [1/Pa].
    pressure : array_like
        Gauge pressure :math:`p` [Pa], >= 0.

    Returns
    -------
    numpy.ndarray
        Dynamic viscosity [Pa·s]; ``inf`` where it overflows (:math:`\alpha p
        > 709`), which is why :func:`roelands_1966` is preferred at contact
        pressures.

    Examples
    --------
    >>> round(float(barus_1893(0.05, 2e-8, 1e8)) / 0.05, 4)
    7.3891
    """
    p = check_nonnegative("pressure", pressure, "Pa")
    return pressure_viscosity_unchecked("barus", np.asarray(viscosity, dtype=float), alpha, p)


def roelands_1966(viscosity: ArrayLike, alpha: ArrayLike, pressure: ArrayLike) -> FloatArray:
    r"""Viscosity at pressure by Roelands' equation (isothermal form).

    .. math::
        \eta = \eta_0\exp\left\{(\ln\eta_0 + 9.67)\left[\left(1 +
        \frac{p}{p_r}\right)^{Z} - 1\right]\right\},\qquad
        Z = \frac{\alpha\,p_r}{\ln\eta_0 + 9.67}

    with :math:`p_r = 1.96\cdot10^8` Pa and :math:`\eta` in Pa·s; the
    pressure-viscosity index :math:`Z` is chosen so that the initial slope
    :math:`d\ln\eta/dp` at :math:`p = 0` equals Barus's :math:`\alpha`.
    ``alpha`` must be the coefficient at the temperature of ``viscosity``:
    Roelands' :math:`Z` belongs to the oil, so a coefficient measured
    at another temperature is carried over by :func:`roelands_z` and
    :func:`roelands_alpha` (as :meth:`Lubricant.viscosity_at_pressure` does).

    Parameters
    ----------
    viscosity : array_like
        Dynamic viscosity at ambient pressure :math:`\eta_0` [Pa·s], above
        :math:`\eta_\infty = 6.31\cdot10^{-5}` Pa·s.
    alpha : array_like
        Pressure-viscosity coefficient [1/Pa].
    pressure : array_like
        Gauge pressure [Pa], >= 0.

    Returns
    -------
    numpy.ndarray
        Dynamic viscosity [Pa·s].

    Examples
    --------
    At 1 GPa a PAO of 0.05 Pa·s and 1.5e-8 /Pa thickens far less than by Barus:

    >>> eta = roelands_1966(0.05, 1.5e-8, 1e9)
    >>> round(float(np.log10(eta / 0.05)), 2), round(float(1.5e-8 * 1e9 / np.log(10)), 2)
    (3.53, 6.51)

    References
    ----------
    .. [1] C. J. A. Roelands, PhD thesis, TU Delft, 1966; in the form of
       Hamrock, Schmid and Jacobson, *Fundamentals of Fluid Film
       Lubrication*, 2004, eq. (4.10)-(4.11).
    """
    eta0 = check_positive("viscosity", viscosity, "Pa·s")
    p = check_nonnegative("pressure", pressure, "Pa")
    _roelands_span(eta0)
    return pressure_viscosity_unchecked("roelands", eta0, alpha, p)


def _roelands_span(viscosity: ArrayLike) -> FloatArray:
    r""":math:`\ln\eta_0 + 9.67` of a viscosity [Pa·s], refused (as ``viscosity``) where <= 0."""
    eta0 = check_positive("viscosity", viscosity, "Pa·s")
    span: FloatArray = np.log(eta0) - ROELANDS_LN_ETA_INF
    if np.any(span <= 0.0):
        raise BallScrewInputError(
            "viscosity", float(np.min(eta0)), "a viscosity above 6.31e-5 Pa·s"
        )
    return span


def roelands_z(viscosity: ArrayLike, alpha: ArrayLike) -> FloatArray:
    r"""Roelands' pressure-viscosity index :math:`Z` from a pressure-viscosity coefficient.

    .. math:: Z = \frac{\alpha\,p_r}{\ln\eta_0 + 9.67}

    with :math:`p_r = 1.96\cdot10^8` Pa and :math:`\eta_0` in Pa·s: the index
    whose Roelands curve has the initial slope :math:`d\ln\eta/dp = \alpha`
    at the ambient viscosity :math:`\eta_0` (the derivative at :math:`p = 0`
    of :func:`roelands_1966`'s exponent). In Roelands' correlation ([1]_)
    :math:`Z` belongs to the oil and varies with temperature only through a
    term :math:`C_Z\log_{10}(1 + T/135)` (:math:`T` in °C) that is known for few
    oils ([2]_ tabulates :math:`D_Z` and :math:`C_Z` for some); with no
    :math:`C_Z` given, the package takes :math:`Z` constant (:math:`C_Z = 0`),
    derived once from :math:`\alpha` and :math:`\eta_0` at the temperature
    :math:`\alpha` was measured at.

    Parameters
    ----------
    viscosity : array_like
        Ambient-pressure viscosity :math:`\eta_0` [Pa·s] at the temperature
        of ``alpha``, above :math:`\eta_\infty = 6.31\cdot10^{-5}` Pa·s.
    alpha : array_like
        Pressure-viscosity coefficient at that temperature [1/Pa], > 0.

    Returns
    -------
    numpy.ndarray
        :math:`Z` [-].

    Examples
    --------
    A mineral ISO VG 68 with 0.0589 Pa·s and 25 /GPa at 40 °C:

    >>> round(float(roelands_z(0.0588676, 25e-9)), 4)
    0.7166

    References
    ----------
    .. [1] C. J. A. Roelands, *Correlational aspects of the viscosity-
       temperature-pressure relationship of lubricating oils*, PhD thesis,
       TU Delft, 1966; C. J. A. Roelands, J. C. Vlugter, H. I. Waterman,
       "The viscosity-temperature-pressure relationship of lubricating oils
       and its correlation with chemical constitution", J. Basic Eng. 85
       (1963) 601-610. Constants as in Hamrock, Schmid and Jacobson,
       *Fundamentals of Fluid Film Lubrication*, 2004, eq. (4.10)-(4.11).
    .. [2] R. Larsson, P. O. Larsson, E. Eriksson, M. Sjöberg, E. Höglund,
       "Lubricant properties for input to hydrodynamic and
       elastohydrodynamic lubrication analyses", Proc. IMechE J 214 (2000)
       17-27.
    """
    a = check_positive("alpha", alpha, "1/Pa")
    result: FloatArray = a * ROELANDS_PRESSURE / _roelands_span(viscosity)
    return result


def roelands_alpha(viscosity: ArrayLike, z: ArrayLike) -> FloatArray:
    r"""Pressure-viscosity coefficient at a temperature from Roelands' constant index :math:`Z`.

    .. math::
        \alpha^*(T) = \left.\frac{d\ln\eta}{dp}\right|_{p=0}
        = \frac{Z\,[\ln\eta_0(T) + 9.67]}{p_r}

    with :math:`p_r = 1.96\cdot10^8` Pa and :math:`\eta_0(T)` the ambient
    viscosity [Pa·s] at temperature :math:`T`. Roelands' complete
    viscosity-temperature-pressure formula ([1]_) is
    :math:`\ln\eta + 9.67 = [\ln\eta_0(T) + 9.67](1 + p/p_r)^Z` with
    :math:`Z` a property of the oil, here held constant (see
    :func:`roelands_z`; his temperature term, with its index :math:`S_0`,
    only gives :math:`\eta_0(T)`, which the package takes from the oil's
    ASTM D341 or Vogel fit instead). Its initial slope therefore
    falls as the oil warms, in proportion to :math:`\ln\eta_0 + 9.67`: a
    colder oil thickens more under pressure, not less. With ``z`` from
    :func:`roelands_z` at the reference temperature, :func:`roelands_1966`
    evaluated with :math:`\alpha^*(T)` is Roelands' formula at :math:`T`.

    Parameters
    ----------
    viscosity : array_like
        Ambient-pressure viscosity :math:`\eta_0(T)` [Pa·s], above
        :math:`6.31\cdot10^{-5}` Pa·s.
    z : array_like
        Roelands' pressure-viscosity index [-] (:func:`roelands_z`), > 0.

    Returns
    -------
    numpy.ndarray
        :math:`\alpha^*` [1/Pa].

    Examples
    --------
    The mineral VG 68 of :func:`roelands_z` (Z = 0.7166) at 20 °C, where its
    viscosity is 0.190 Pa·s: 17 % above its 25 /GPa at 40 °C.

    >>> z = roelands_z(0.0588676, 25e-9)
    >>> round(float(roelands_alpha(0.190215, z)) * 1e9, 2)
    29.29

    References
    ----------
    .. [1] C. J. A. Roelands, PhD thesis, TU Delft, 1966; Roelands, Vlugter
       and Waterman, J. Basic Eng. 85 (1963) 601-610 (see :func:`roelands_z`).
    """
    zz = check_positive("z", z, "(Roelands' pressure-viscosity index)")
    result: FloatArray = zz * _roelands_span(viscosity) / ROELANDS_PRESSURE
    return result


def pressure_viscosity_unchecked(
    model: str, viscosity: FloatArray, alpha: ArrayLike, pressure: FloatArray
) -> FloatArray:
    r"""Barus's or Roelands' viscosity at pressure, without input checks [Pa·s].

    The one implementation of both equations (:func:`barus_1893`,
    :func:`roelands_1966`, which check their inputs first), for the inner
    loops of the friction models on large arrays. Roelands' form is evaluated
    as :math:`\eta_0\exp\{(\ln\eta_0 + 9.67)\,\mathrm{expm1}[Z\ln(1 +
    p/p_r)]\}`, which keeps its precision at small pressures.
    """
    eta0 = np.asarray(viscosity, dtype=float)
    if model == "barus":
        with np.errstate(over="ignore"):
            result: FloatArray = eta0 * np.exp(np.asarray(alpha) * pressure)
        return result
    span = np.log(eta0) - ROELANDS_LN_ETA_INF
    out: FloatArray = np.asarray(
        np.log1p(pressure / ROELANDS_PRESSURE) * (np.asarray(alpha) * ROELANDS_PRESSURE / span),
        dtype=float,
    )
    np.expm1(out, out=out)
    out *= span
    with np.errstate(over="ignore"):
        np.exp(out, out=out)
    out *= eta0
    return out


def pressure_viscosity_jungnickel(kinematic_viscosity: ArrayLike) -> FloatArray:
    r"""Rough estimate of the pressure-viscosity coefficient from the viscosity.

    .. math:: \alpha = 1.29\cdot10^{-7}\,\nu^{0.204}\quad(\nu\ \text{in m²/s})

    An empirical fit for mineral oils after Jungnickel (2010), as coded in the
    open-source Thermca library (``thermca/lib/ball_screw.py``; the primary
    source was not read). Use a measured value where one exists.

    Parameters
    ----------
    kinematic_viscosity : array_like
        [m²/s].

    Returns
    -------
    numpy.ndarray
        :math:`\alpha` [1/Pa].

    Examples
    --------
    >>> round(float(pressure_viscosity_jungnickel(68e-6)) * 1e8, 2)
    1.82
    """
    nu = check_positive("kinematic_viscosity", kinematic_viscosity, "m²/s")
    result: FloatArray = 1.29e-7 * nu**0.204
    return result


@dataclass(frozen=True)
class Lubricant:
    r"""A lubricating oil, or a grease's base oil, and the correlations that give its properties.

    Build one with :meth:`from_viscosities` or take a bundled one from
    :func:`ballscrew.lubricants.get`. A grease (``kind="grease"``) is
    described by its base oil: the viscosities, density and pressure-viscosity
    coefficient are the base oil's, which is what elastohydrodynamic film
    theory uses for a fully flooded grease-lubricated contact at steady state
    (see :mod:`ballscrew.validity`, which states what that leaves out); its
    thickener and consistency are recorded, not modelled.

    Parameters
    ----------
    name : str
        Label.
    nu40, nu100 : float
        Kinematic viscosity at 40 °C and 100 °C [m²/s]; ``nu100 < nu40``.
    density15 : float
        Density at 15 °C [kg/m³].
    pressure_viscosity : float
        Pressure-viscosity coefficient :math:`\alpha` [1/Pa] at 40 °C
        (:data:`PRESSURE_VISCOSITY_TEMPERATURE`). Roelands' law keeps its
        index :math:`Z` (:attr:`roelands_index`, derived from :math:`\alpha`
        at 40 °C) constant, so its coefficient at another temperature
        (:meth:`pressure_viscosity_at`) falls as the oil warms; Barus's law
        and the EHL film's materials parameter use :math:`\alpha` as given.

        ``nu40``, ``density15`` and ``pressure_viscosity`` are refused beyond
        what a lubricant can be and warned of outside the typical range
        (:data:`ballscrew.plausible.LUBRICANT_RANGES`, with their sources):
        ``nu40`` of ISO VG 2 to VG 3200 (1.98 to 3520 mm²/s) is typical, above
        20000 mm²/s refused.
    limiting_shear_stress : float
        :math:`\tau_0` of the limiting shear stress :math:`\tau_{lim} = \tau_0
        + \gamma_L p` [Pa].
    limiting_shear_coefficient : float
        :math:`\gamma_L` [-].
    thermal_expansion : float
        :math:`\beta_\rho` of :func:`density_linear` [1/K].
    viscosity_model : {"astm_d341", "vogel"}
        Viscosity-temperature law fitted through ``nu40`` and ``nu100``.
    source : str
        Where the numbers come from.
    kind : {"oil", "grease"}
        An oil, or a grease described by its base oil (default ``"oil"``).
    thickener : str
        A grease's thickener ("lithium", "lithium complex", "calcium
        sulfonate", "polyurea", ...); empty for an oil or when unknown.
    nlgi_grade : str
        A grease's NLGI consistency grade as its data sheet writes it: one of
        :data:`NLGI_GRADES`, a half grade ("1.5") or a span ("2-3"); empty
        for an oil or when unknown.
    base_oil : str
        The (base) oil's type ("mineral", "PAO", "ester", ...); empty when
        unknown.
    pour_point, flash_point : float or None
        Pour point and flash point of the (base) oil [°C], where its data
        sheet gives them; None otherwise. The friction chain warns when a
        temperature lies below the pour point or above the flash point
        (:func:`ballscrew.validity.lubricant_limits`).

    Examples
    --------
    >>> oil = Lubricant.from_viscosities("PAO ISO VG 68", 68e-6, 10.3e-6, 845.0, 1.5e-8)
    >>> round(float(oil.kinematic_viscosity(20.0)) * 1e6, 1)
    187.5
    >>> round(float(oil.dynamic_viscosity(40.0)), 4)
    0.0565
    """

    name: str
    nu40: float
    nu100: float
    density15: float
    pressure_viscosity: float
    limiting_shear_stress: float = 0.0
    limiting_shear_coefficient: float = 0.07
    thermal_expansion: float = 6.5e-4
    viscosity_model: ViscosityModel = "astm_d341"
    source: str = ""
    kind: LubricantKind = "oil"
    thickener: str = ""
    nlgi_grade: str = ""
    base_oil: str = ""
    pour_point: float | None = None
    flash_point: float | None = None

    def __post_init__(self) -> None:
        if not isinstance(self.name, str) or not self.name.strip():
            raise BallScrewInputError("name", self.name, "a non-empty text")
        for field in ("nu40", "nu100", "density15", "pressure_viscosity"):
            self._scalar(field, check_positive)
        for field in ("limiting_shear_stress", "limiting_shear_coefficient"):
            self._scalar(field, check_nonnegative)
        self._scalar(
            "thermal_expansion",
            lambda f, v: check_in_range(f, v, 0.0, 0.01, inclusive=(True, False), unit="1/K"),
        )
        for field in LUBRICANT_RANGES:  # refused beyond what lubricants are, warned outside
            check_lubricant_property(field, getattr(self, field))
        if self.nu100 >= self.nu40:
            raise BallScrewInputError(
                "nu100", self.nu100, f"a value below nu40 ({self.nu40!r} m²/s)"
            )
        if self.nu100 < 0.3e-6:
            raise BallScrewInputError("nu100", self.nu100, "a viscosity of at least 0.3 mm²/s")
        if self.viscosity_model not in VISCOSITY_MODELS:
            raise BallScrewInputError(
                "viscosity_model", self.viscosity_model, f"one of {list(VISCOSITY_MODELS)}"
            )
        if self.density(100.0) <= 0.0:
            raise BallScrewInputError(
                "thermal_expansion", self.thermal_expansion, "a value giving a positive density"
            )
        self._grease_fields()
        self._limits()

    def _grease_fields(self) -> None:
        """Check kind, thickener, NLGI grade and base oil (the grease-only ones need a grease)."""
        if self.kind not in LUBRICANT_KINDS:
            raise BallScrewInputError("kind", self.kind, f"one of {list(LUBRICANT_KINDS)}")
        for name in ("thickener", "nlgi_grade", "base_oil"):
            value = getattr(self, name)
            if not isinstance(value, str):
                raise BallScrewInputError(name, value, "a text (empty when unknown)")
            object.__setattr__(self, name, " ".join(value.split()))
        for name in ("thickener", "nlgi_grade"):
            if getattr(self, name) and self.kind != "grease":
                raise BallScrewInputError(
                    name, getattr(self, name), 'empty for an oil (give kind="grease")'
                )
        if self.nlgi_grade and not _NLGI_GRADE.fullmatch(self.nlgi_grade):
            raise BallScrewInputError(
                "nlgi_grade",
                self.nlgi_grade,
                f"an NLGI grade {list(NLGI_GRADES)}, a half grade ('1.5') or a span ('2-3')",
            )

    def _limits(self) -> None:
        """Check the pour point and flash point [°C]: None, or finite with pour < flash."""
        for name in ("pour_point", "flash_point"):
            if getattr(self, name) is not None:
                self._scalar(
                    name,
                    lambda f, v: check_in_range(f, v, -KELVIN, np.inf, unit="°C"),
                )
        if (
            self.pour_point is not None
            and self.flash_point is not None
            and self.pour_point >= self.flash_point
        ):
            raise BallScrewInputError(
                "flash_point",
                self.flash_point,
                f"a value above pour_point ({self.pour_point!r} °C)",
            )

    def _scalar(self, name: str, check: Any) -> None:
        value = getattr(self, name)
        if np.ndim(value) != 0 or isinstance(value, bool):
            raise BallScrewInputError(name, value, "a single real number")
        object.__setattr__(self, name, float(check(name, value)))

    @classmethod
    def from_viscosities(
        cls,
        name: str,
        nu40: float,
        nu100: float,
        density15: float,
        pressure_viscosity: float | None = None,
        **kwargs: Any,
    ) -> Lubricant:
        r"""Lubricant from its data-sheet viscosities.

        Parameters
        ----------
        name : str
            Label.
        nu40, nu100 : float
            Kinematic viscosities at 40 and 100 °C [m²/s].
        density15 : float
            Density at 15 °C [kg/m³].
        pressure_viscosity : float, optional
            :math:`\alpha` [1/Pa]; when omitted, estimated from ``nu40`` by
            :func:`pressure_viscosity_jungnickel` (a rough fit for mineral oils).
        **kwargs
            Other fields of :class:`Lubricant`.
        """
        if pressure_viscosity is None:
            # nu40 checked here, by its own name: the estimate would refuse it as its input.
            check_positive("nu40", nu40, "m²/s")
            pressure_viscosity = float(pressure_viscosity_jungnickel(nu40))
            kwargs.setdefault("source", "pressure-viscosity estimated (Jungnickel)")
            with warnings.catch_warnings():  # an estimate is not warned of: nu40 is, if at all
                warnings.filterwarnings(
                    "ignore", "pressure_viscosity", BallScrewPlausibilityWarning
                )
                return cls(
                    name=name, nu40=nu40, nu100=nu100, density15=density15,
                    pressure_viscosity=pressure_viscosity, **kwargs,
                )  # fmt: skip
        return cls(
            name=name,
            nu40=nu40,
            nu100=nu100,
            density15=density15,
            pressure_viscosity=pressure_viscosity,
            **kwargs,
        )

    def replace(self, **changes: Any) -> Lubricant:
        """Return a copy with some fields changed (validated again)."""
        known = {f.name for f in fields(self)}
        for key in changes:
            if key not in known:
                raise BallScrewInputError(
                    key, changes[key], f"a field of Lubricant: {sorted(known)}"
                )
        return replace(self, **changes)

    @functools.cached_property
    def _fit(self) -> tuple[FloatArray, FloatArray]:
        """The viscosity-temperature fit's two constants, computed once (the oil is immutable)."""
        if self.viscosity_model == "vogel":
            return vogel_constants(self.nu40, 40.0, self.nu100, 100.0)
        return astm_d341_constants(self.nu40, 40.0, self.nu100, 100.0)

    def kinematic_viscosity(self, temperature: ArrayLike) -> FloatArray:
        """Kinematic viscosity at ambient pressure [m²/s] at ``temperature`` [°C]."""
        a, b = self._fit
        if self.viscosity_model == "vogel":
            return vogel_viscosity(temperature, a, b)
        return astm_d341_viscosity(temperature, a, b)

    def check_temperature(self, field: str, temperature: ArrayLike) -> FloatArray:
        """Return ``temperature`` [°C], refused (as ``field``) where this oil has no viscosity.

        Far below its pour point the viscosity-temperature fit of an oil
        overflows (the ASTM D341 fit of a VG 68 oil near -230 °C) or passes the
        pole of Vogel's equation: no friction can be computed there, and the
        error names the temperature the user gave, not a viscosity.
        """
        t = check_in_range(field, temperature, -KELVIN, np.inf, unit="°C (above absolute zero)")
        with np.errstate(over="ignore", invalid="ignore"):
            if self.viscosity_model == "vogel":
                ok = t + 95.0 > 0.0
            else:
                ok = np.isfinite(self.kinematic_viscosity(t))
        if not every(ok):
            cold = float(np.min(np.asarray(t)[~np.asarray(ok)]))
            raise BallScrewInputError(
                field,
                cold,
                f"a temperature at which {self.name}'s viscosity-temperature fit gives a "
                f"viscosity ({self.viscosity_model} fit through 40 and 100 °C; it has none "
                "this far below the pour point, where the oil is a solid)",
            )
        return t

    def density(self, temperature: ArrayLike) -> FloatArray:
        """Density [kg/m³] at ``temperature`` [°C], see :func:`density_linear`."""
        return density_linear(temperature, self.density15, self.thermal_expansion)

    def dynamic_viscosity(self, temperature: ArrayLike) -> FloatArray:
        """Dynamic viscosity at ambient pressure [Pa·s] at ``temperature`` [°C]."""
        return self.viscosities(temperature)[1]

    def viscosities(self, temperature: ArrayLike) -> tuple[FloatArray, FloatArray]:
        """Kinematic [m²/s] and dynamic [Pa·s] viscosity at ``temperature`` [°C], one fit."""
        nu = self.kinematic_viscosity(temperature)
        eta: FloatArray = nu * self.density(temperature)
        return nu, eta

    @functools.cached_property
    def roelands_index(self) -> float:
        """Roelands' pressure-viscosity index :math:`Z` [-] of this oil (:func:`roelands_z`).

        Derived once from ``pressure_viscosity`` and the viscosity at
        :data:`PRESSURE_VISCOSITY_TEMPERATURE` (40 °C), and constant across
        temperature as in Roelands' correlation.
        """
        eta_ref = self.dynamic_viscosity(PRESSURE_VISCOSITY_TEMPERATURE)
        return float(roelands_z(eta_ref, self.pressure_viscosity))

    def pressure_viscosity_at(self, temperature: ArrayLike) -> FloatArray:
        r"""Roelands' pressure-viscosity coefficient :math:`\alpha^*` [1/Pa] at a temperature [°C].

        :func:`roelands_alpha` with this oil's constant :attr:`roelands_index`:
        ``pressure_viscosity`` at 40 °C, more below, less above (for the
        bundled mineral ISO VG 68, 29.3 /GPa at 20 °C against 25 /GPa at 40 °C).
        """
        t = self.check_temperature("temperature", temperature)
        return roelands_alpha(self.dynamic_viscosity(t), self.roelands_index)

    def viscosity_at_pressure(
        self, temperature: ArrayLike, pressure: ArrayLike, model: str = "roelands"
    ) -> FloatArray:
        """Dynamic viscosity [Pa·s] at ``temperature`` [°C] and gauge ``pressure`` [Pa].

        ``model`` is ``"roelands"`` (default: :func:`roelands_1966` with the
        coefficient :meth:`pressure_viscosity_at` the temperature, that is
        Roelands' formula with his index :math:`Z` constant across
        temperature) or ``"barus"`` (:func:`barus_1893` with
        ``pressure_viscosity`` as given). ``temperature`` and ``pressure``
        broadcast against each other.

        Examples
        --------
        Colder oil is thicker under pressure too (mineral ISO VG 68, 1 GPa):

        >>> from ballscrew import lubricants
        >>> oil = lubricants.get("mineral ISO VG 68")
        >>> eta = oil.viscosity_at_pressure([20.0, 40.0], 1e9)
        >>> bool(eta[0] > eta[1])
        True
        """
        check_choice("model", model, PRESSURE_VISCOSITY_MODELS)
        t = self.check_temperature("temperature", temperature)
        eta0 = self.dynamic_viscosity(t)
        if model == "roelands":
            alpha = roelands_alpha(eta0, self.roelands_index)
            return roelands_1966(eta0, alpha, pressure)
        return barus_1893(eta0, self.pressure_viscosity, pressure)
