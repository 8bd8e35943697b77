r"""Elastohydrodynamic film thickness, film parameter and asperity contact share.

Hamrock and Dowson's (1977) isothermal, fully flooded film-thickness formulas
for elliptical contacts, in their dimensionless groups

.. math::
    U = \frac{\eta_0 u}{E' R_x},\qquad G = \alpha E',\qquad
    W = \frac{Q}{E' R_x^2},

with :math:`R_x` the effective radius in the entrainment (rolling) direction,
:math:`u` the mean entrainment speed and :math:`k = a/b` the ellipticity, the
major axis lying across the rolling direction (as in a ball screw groove).

The curve fits come from 34 numerical solutions with ellipticity
:math:`1 \le k \le 8`, steel, bronze and silicon nitride solids and mineral
oils ([1]_, and Part II of the series for the range of :math:`k`); the
speed, load and materials parameters of those runs spanned roughly
:math:`U \approx 10^{-12}` to :math:`10^{-11}`, :math:`W \approx 4\cdot10^{-7}`
to :math:`10^{-5}` and :math:`G \approx 2500` to 5000 (approximate spans,
not yet checked against the paper's tables; :mod:`ballscrew.validity` warns
outside :math:`U` 1.7e-12 to 1.7e-11 and :math:`W` 3.7e-7 to 1.1e-5, and does
not check :math:`G`). Ball screws
at high speed reach :math:`U \approx 10^{-10}` and are extrapolated.
Optical measurements on steel against sapphire found films on average 30 %
thicker than the minimum-film formula predicts (Koye & Winer [3]_).

References
----------
.. [1] B. J. Hamrock, D. Dowson, "Isothermal elastohydrodynamic lubrication of
   point contacts, Part III - Fully flooded results", J. Lubr. Technol. 99
   (1977) 264-276, doi:10.1115/1.3453074.
.. [2] R. S. Zhou, M. R. Hoeprich, "Torque of tapered roller bearings", J.
   Tribol. 113 (1991) 590-597, doi:10.1115/1.2920666.
.. [3] K. A. Koye, W. O. Winer, "An experimental evaluation of the Hamrock
   and Dowson minimum film thickness equation for fully flooded EHD point
   contacts", J. Lubr. Technol. 103 (1981) 284-294, doi:10.1115/1.3251646.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import numpy.typing as npt

from .errors import FloatArray, check_finite, check_in_range, check_nonnegative, check_positive
from .materials import composite_roughness

__all__ = [
    "asperity_share",
    "composite_roughness",
    "dimensionless_load",
    "dimensionless_materials",
    "dimensionless_speed",
    "hamrock_dowson_1977_central",
    "hamrock_dowson_1977_minimum",
    "lambda_ratio",
]

ArrayLike = npt.ArrayLike


def dimensionless_speed(
    viscosity: ArrayLike, entrainment_speed: ArrayLike, reduced_modulus: ArrayLike, rx: ArrayLike
) -> FloatArray:
    r"""Hamrock-Dowson speed parameter :math:`U = \eta_0 |u|/(E' R_x)` [-].

    Parameters
    ----------
    viscosity : array_like
        Dynamic viscosity at ambient pressure :math:`\eta_0` [Pa·s].
    entrainment_speed : array_like
        Mean rolling speed :math:`u` [m/s]; its sign is ignored.
    reduced_modulus : array_like
        :math:`E'` [Pa].
    rx : array_like
        Effective radius in the rolling direction [m].

    Examples
    --------
    >>> float(dimensionless_speed(0.05, 1.0, 2.3e11, 0.003)) # doctest: +ELLIPSIS
    7.24...e-11
    """
    eta = check_positive("viscosity", viscosity, "Pa·s")
    u = check_finite("entrainment_speed", entrainment_speed)
    ep = check_positive("reduced_modulus", reduced_modulus, "Pa")
    r = check_positive("rx", rx, "m")
    return dimensionless_speed_unchecked(eta, u, ep, r)


def dimensionless_speed_unchecked(eta: Any, u: Any, ep: Any, r: Any) -> FloatArray:
    """:func:`dimensionless_speed` of inputs the caller has checked (the one formula)."""
    result: FloatArray = eta * np.abs(u) / (ep * r)
    return result


def dimensionless_materials(
    pressure_viscosity: ArrayLike, reduced_modulus: ArrayLike
) -> FloatArray:
    r"""Hamrock-Dowson materials parameter :math:`G = \alpha E'` [-].

    Examples
    --------
    >>> round(float(dimensionless_materials(2e-8, 2.3077e11)))
    4615
    """
    alpha = check_positive("pressure_viscosity", pressure_viscosity, "1/Pa")
    ep = check_positive("reduced_modulus", reduced_modulus, "Pa")
    result: FloatArray = alpha * ep
    return result


def dimensionless_load(load: ArrayLike, reduced_modulus: ArrayLike, rx: ArrayLike) -> FloatArray:
    r"""Hamrock-Dowson load parameter :math:`W = Q/(E' R_x^2)` [-].

    Examples
    --------
    >>> float(dimensionless_load(100.0, 2.3e11, 0.003)) # doctest: +ELLIPSIS
    4.83...e-05
    """
    q = check_nonnegative("load", load, "N")
    ep = check_positive("reduced_modulus", reduced_modulus, "Pa")
    r = check_positive("rx", rx, "m")
    return dimensionless_load_unchecked(q, ep, r)


def dimensionless_load_unchecked(q: Any, ep: Any, r: Any) -> FloatArray:
    """:func:`dimensionless_load` of inputs the caller has checked (the one formula)."""
    result: FloatArray = q / (ep * r**2)
    return result


def _film_inputs(
    rx: ArrayLike, u: ArrayLike, g: ArrayLike, w: ArrayLike, k: ArrayLike
) -> tuple[FloatArray, ...]:
    return (
        check_positive("rx", rx, "m"),
        check_nonnegative("U (dimensionless speed)", u),
        check_positive("G (dimensionless materials parameter)", g),
        check_positive("W (dimensionless load)", w),
        check_in_range("k (ellipticity)", k, 1.0, np.inf, inclusive=(True, False)),
    )


def hamrock_dowson_1977_minimum(
    rx: ArrayLike, u: ArrayLike, g: ArrayLike, w: ArrayLike, k: ArrayLike
) -> FloatArray:
    r"""Minimum EHL film thickness of an elliptical contact (Hamrock & Dowson 1977).

    .. math:: h_{min} = 3.63\,R_x\,U^{0.68}G^{0.49}W^{-0.073}\,(1 - e^{-0.68k})

    Parameters
    ----------
    rx : array_like
        Effective radius in the rolling direction [m].
    u, g, w : array_like
        Dimensionless speed, materials and load parameters [-], see
        :func:`dimensionless_speed`, :func:`dimensionless_materials`,
        :func:`dimensionless_load`.
    k : array_like
        Ellipticity :math:`a/b \ge 1` [-], major axis across the rolling
        direction.

    Returns
    -------
    numpy.ndarray
        :math:`h_{min}` [m]; zero at zero speed.

    Notes
    -----
    Hamrock & Dowson (1977), see the module references. Validity: module docstring.

    Examples
    --------
    >>> h = hamrock_dowson_1977_minimum(0.003, 7e-11, 4600.0, 4.8e-5, 5.0)
    >>> round(float(h) * 1e6, 3)  # µm
    0.169
    """
    return hamrock_dowson_1977_minimum_unchecked(*_film_inputs(rx, u, g, w, k))


def hamrock_dowson_1977_minimum_unchecked(r: Any, uu: Any, gg: Any, ww: Any, kk: Any) -> FloatArray:
    """:func:`hamrock_dowson_1977_minimum` of inputs the caller has checked (the one formula).

    For the contact state, whose inputs follow from checked ones (a loaded contact's
    ``W`` > 0, Hertz's ellipticity >= 1).
    """
    result: FloatArray = 3.63 * r * uu**0.68 * gg**0.49 * ww**-0.073 * (1.0 - np.exp(-0.68 * kk))
    return result


def hamrock_dowson_1977_central(
    rx: ArrayLike, u: ArrayLike, g: ArrayLike, w: ArrayLike, k: ArrayLike
) -> FloatArray:
    r"""Central EHL film thickness of an elliptical contact (Hamrock & Dowson 1977).

    .. math:: h_c = 2.69\,R_x\,U^{0.67}G^{0.53}W^{-0.067}\,(1 - 0.61e^{-0.73k})

    Parameters and return as :func:`hamrock_dowson_1977_minimum` (result
    :math:`h_c` [m]).

    Examples
    --------
    >>> h = hamrock_dowson_1977_central(0.003, 7e-11, 4600.0, 4.8e-5, 5.0)
    >>> round(float(h) * 1e6, 3)  # µm
    0.212
    """
    r, uu, gg, ww, kk = _film_inputs(rx, u, g, w, k)
    result: FloatArray = (
        2.69 * r * uu**0.67 * gg**0.53 * ww**-0.067 * (1.0 - 0.61 * np.exp(-0.73 * kk))
    )
    return result


def lambda_ratio(film_thickness: ArrayLike, roughness: ArrayLike) -> FloatArray:
    r"""Film parameter :math:`\Lambda = h/\sigma` [-].

    Parameters
    ----------
    film_thickness : array_like
        Film thickness, usually :math:`h_{min}` [m].
    roughness : array_like
        Composite RMS roughness [m], > 0 (see :func:`composite_roughness`).

    Examples
    --------
    >>> float(lambda_ratio(0.62e-6, 0.31e-6))
    2.0
    """
    h = check_nonnegative("film_thickness", film_thickness, "m")
    s = check_positive("roughness", roughness, "m")
    return lambda_ratio_unchecked(h, s)


def lambda_ratio_unchecked(h: Any, s: Any) -> FloatArray:
    """:func:`lambda_ratio` of inputs the caller has checked (the one formula)."""
    result: FloatArray = h / s
    return result


def asperity_share(
    film_parameter: ArrayLike, b: ArrayLike = 1.42, c: ArrayLike = 0.8
) -> FloatArray:
    r"""Share of the contact carried by asperities, :math:`A_c/A_0 = \exp(-B\Lambda^C)`.

    The form is Zhou and Hoeprich's (1991) [2]; the study (its eq. 6) takes
    :math:`B = 1.42` from Olaru's model but does not give :math:`C`. The
    default :math:`C = 0.8` is the value of the public code of Olaru's model;
    neither constant was checked
    against Zhou and Hoeprich's paper, so both are parameters.

    Parameters
    ----------
    film_parameter : array_like
        :math:`\Lambda` [-], >= 0.
    b, c : array_like
        Constants [-].

    Returns
    -------
    numpy.ndarray
        :math:`A_c/A_0` [-], 1 at :math:`\Lambda = 0`, falling towards 0.

    Examples
    --------
    >>> round(float(asperity_share(1.0)), 4)
    0.2417
    """
    lam = check_nonnegative("film_parameter", film_parameter)
    bb = check_positive("b", b)
    cc = check_positive("c", c)
    return asperity_share_unchecked(lam, bb, cc)


def asperity_share_unchecked(lam: Any, bb: Any, cc: Any) -> FloatArray:
    """:func:`asperity_share` of inputs the caller has checked (the one formula)."""
    result: FloatArray = np.exp(-bb * lam**cc)
    return result
