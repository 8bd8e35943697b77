r"""Materials of a ball screw: bearing steel's constants, and two pairings of surfaces.

The ground the geometry and the contact layers stand on: the elastic
constants, density, specific heat and thermal expansion of the steel of balls,
screw and nut, the reduced modulus of two elastic bodies (Hertz and EHL theory) and the
composite roughness of two surfaces (the film parameter). The functions are
also importable from :mod:`ballscrew.contact` and :mod:`ballscrew.ehl`.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .errors import FloatArray, check_in_range, check_nonnegative, check_positive

__all__ = [
    "STANDARD_GRAVITY",
    "STEEL_DENSITY",
    "STEEL_EXPANSION",
    "STEEL_POISSON_RATIO",
    "STEEL_SPECIFIC_HEAT",
    "STEEL_YOUNGS_MODULUS",
    "composite_roughness",
    "reduced_modulus",
]

ArrayLike = npt.ArrayLike

STANDARD_GRAVITY: float = 9.80665
"""Standard acceleration of gravity [m/s²] (CGPM 1901, ISO 80000-3)."""

STEEL_YOUNGS_MODULUS: float = 2.1e11
"""Young's modulus of bearing steel [Pa] (the default of balls, screw and nut)."""

STEEL_POISSON_RATIO: float = 0.3
"""Poisson's ratio of bearing steel [-]."""

STEEL_DENSITY: float = 7850.0
"""Density of the steel of balls, screw and nut [kg/m³] (a typical handbook value for
carbon and low-alloy steels; 52100 bearing steel is 7810 to 7830)."""

STEEL_SPECIFIC_HEAT: float = 460.0
"""Specific heat of steel [J/(kg·K)] (a typical handbook value)."""

STEEL_EXPANSION: float = 11.5e-6
"""Linear thermal expansion of bearing steel [1/K] (THK and NSK take 11.8e-6 and 12e-6)."""


def reduced_modulus(e1: ArrayLike, nu1: ArrayLike, e2: ArrayLike, nu2: ArrayLike) -> FloatArray:
    r"""Reduced (effective) elastic modulus of two bodies in contact, Hamrock's convention.

    .. math:: E' = \frac{2}{(1-\nu_1^2)/E_1 + (1-\nu_2^2)/E_2}

    Parameters
    ----------
    e1, e2 : array_like
        Young's moduli of the two bodies [Pa].
    nu1, nu2 : array_like
        Poisson's ratios of the two bodies [-], in [0, 0.5).

    Returns
    -------
    numpy.ndarray
        Reduced modulus :math:`E'` [Pa]. Note that Johnson's :math:`E^*` is
        :math:`E'/2`.

    Examples
    --------
    Two steel bodies (E = 210 GPa, ν = 0.3):

    >>> round(float(reduced_modulus(210e9, 0.3, 210e9, 0.3)) / 1e9, 2)
    230.77

    References
    ----------
    .. [1] B. J. Hamrock, S. R. Schmid, B. O. Jacobson, *Fundamentals of
       Fluid Film Lubrication*, 2nd ed., Marcel Dekker, 2004, ch. 16.
    """
    e1a = check_positive("e1 (Young's modulus)", e1, "Pa")
    e2a = check_positive("e2 (Young's modulus)", e2, "Pa")
    nu1a = check_in_range("nu1 (Poisson's ratio)", nu1, 0.0, 0.5, inclusive=(True, False))
    nu2a = check_in_range("nu2 (Poisson's ratio)", nu2, 0.0, 0.5, inclusive=(True, False))
    result: FloatArray = 2.0 / ((1.0 - nu1a**2) / e1a + (1.0 - nu2a**2) / e2a)
    return result


def composite_roughness(sigma1: ArrayLike, sigma2: ArrayLike) -> FloatArray:
    r"""Composite RMS roughness of two surfaces, :math:`\sqrt{\sigma_1^2 + \sigma_2^2}` [m].

    Examples
    --------
    >>> round(float(composite_roughness(0.3e-6, 0.4e-6)) * 1e6, 6)
    0.5
    """
    s1 = check_nonnegative("sigma1", sigma1, "m")
    s2 = check_nonnegative("sigma2", sigma2, "m")
    result: FloatArray = np.hypot(s1, s2)
    return result
