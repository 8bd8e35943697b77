r"""Shear rheology of a lubricant film: shear stress against shear rate.

All laws are odd in the shear rate (the stress takes the sign of the shear
rate), finite at zero shear rate, and take the local viscosity, so that the
pressure dependence stays in :mod:`ballscrew.lubricant`. The Newtonian stress
is :math:`\tau_N = \eta\dot\gamma`; the limiting shear stress grows with
pressure as :math:`\tau_{lim} = \tau_0 + \gamma_L p` (Bair & Winer [1]_).

References
----------
.. [1] S. Bair, W. O. Winer, "A rheological model for elastohydrodynamic
   contacts based on primary laboratory data", J. Lubr. Technol. 101 (1979)
   258-264.
.. [2] A. A. Elsharkawy, B. J. Hamrock, "Subsurface stresses in micro-EHL
   line contacts", J. Tribol. 113 (1991) 645-655, doi:10.1115/1.2920673.
.. [3] H. Eyring, "Viscosity, plasticity, and diffusion as examples of
   absolute reaction rates", J. Chem. Phys. 4 (1936) 283-291,
   doi:10.1063/1.1749836.
.. [4] T. A. Harris, M. N. Kotzalas, *Advanced Concepts of Bearing
   Technology*, 5th ed., CRC Press, 2007, ch. 4.
"""

from __future__ import annotations

import numpy as np
import numpy.typing as npt

from .errors import FloatArray, check_finite, check_nonnegative, check_positive

__all__ = [
    "bair_winer_1979",
    "eyring_1936",
    "general_non_newtonian",
    "harmonic_combination",
    "limiting_shear_stress",
    "newtonian",
]

ArrayLike = npt.ArrayLike


def newtonian(viscosity: ArrayLike, shear_rate: ArrayLike) -> FloatArray:
    r"""Newtonian shear stress :math:`\tau_N = \eta\dot\gamma`.

    Parameters
    ----------
    viscosity : array_like
        Dynamic viscosity :math:`\eta` [Pa·s], >= 0.
    shear_rate : array_like
        :math:`\dot\gamma` [1/s].

    Returns
    -------
    numpy.ndarray
        Shear stress [Pa].

    Examples
    --------
    >>> float(newtonian(0.1, 1e5))
    10000.0
    """
    eta = check_nonnegative("viscosity", viscosity, "Pa·s")
    rate = check_finite("shear_rate", shear_rate)
    result: FloatArray = eta * rate
    return result


def limiting_shear_stress(
    pressure: ArrayLike, tau0: ArrayLike, coefficient: ArrayLike
) -> FloatArray:
    r"""Limiting shear stress :math:`\tau_{lim} = \tau_0 + \gamma_L p`.

    Parameters
    ----------
    pressure : array_like
        Local contact pressure :math:`p` [Pa], >= 0.
    tau0 : array_like
        Limiting shear stress at ambient pressure :math:`\tau_0` [Pa], >= 0.
    coefficient : array_like
        Pressure coefficient :math:`\gamma_L` [-], >= 0; Bair and Winer [1]
        measured 0.07 to 0.09 for mineral oils at high pressure.

    Returns
    -------
    numpy.ndarray
        [Pa].

    Examples
    --------
    >>> float(limiting_shear_stress(1e9, 2e6, 0.07)) / 1e6
    72.0
    """
    p = check_nonnegative("pressure", pressure, "Pa")
    t0 = check_nonnegative("tau0", tau0, "Pa")
    g = check_nonnegative("coefficient", coefficient)
    result: FloatArray = t0 + g * p
    return result


def general_non_newtonian(
    viscosity: ArrayLike, shear_rate: ArrayLike, limiting_stress: ArrayLike, n: ArrayLike = 1.0
) -> FloatArray:
    r"""The "general" non-Newtonian model, the study's eq. (7).

    .. math::
        \tau = \tau_{lim}\left[1 + \left(\frac{\eta\dot\gamma}{\tau_{lim}}
        \right)^{-n}\right]^{-1/n}
        = \frac{\eta\dot\gamma}{\left[1 + (\eta\dot\gamma/\tau_{lim})^n
        \right]^{1/n}}

    Newtonian at low shear rate, tending to :math:`\tau_{lim}` at high
    shear rate; :math:`n = 1` is the harmonic combination of the study's
    eq. (5) (:func:`harmonic_combination`), :math:`n \to \infty` the ideal
    visco-plastic law :math:`\min(\tau_N, \tau_{lim})`.

    Parameters
    ----------
    viscosity : array_like
        Local dynamic viscosity :math:`\eta` [Pa·s].
    shear_rate : array_like
        :math:`\dot\gamma` [1/s] (either sign).
    limiting_stress : array_like
        :math:`\tau_{lim}` [Pa], > 0.
    n : array_like
        Shape exponent [-], > 0; default 1.

    Returns
    -------
    numpy.ndarray
        Shear stress [Pa], with the sign of the shear rate.

    Notes
    -----
    The study prints eq. (7) as :math:`\tau_s = \tau_{lim}[1 - (\dot\gamma
    \eta/\tau_L)^{-n}]^{1/n}`, which is negative under the root for every
    Newtonian (low) shear stress and so cannot be what was computed. The form
    above is Elsharkawy and Hamrock's general model [2]; it has the limits
    the study describes and reduces to the study's own eq. (5) at
    :math:`n = 1`, so it is taken as the intended reading.

    Examples
    --------
    >>> float(general_non_newtonian(1.0, 1.0, 1.0))  # tau_N = tau_lim: half of each
    0.5
    >>> round(float(general_non_newtonian(1.0, 1e9, 50e6, n=2)) / 50e6, 6)
    0.998752
    """
    eta = check_nonnegative("viscosity", viscosity, "Pa·s")
    rate = check_finite("shear_rate", shear_rate)
    tau_lim = check_positive("limiting_stress", limiting_stress, "Pa")
    nn = check_positive("n", n)
    tau_n = eta * np.abs(rate)
    x = tau_n / tau_lim
    with np.errstate(over="ignore"):
        # For x**n overflowing, the stress is tau_lim to machine precision.
        xn = x**nn
        magnitude = np.where(np.isfinite(xn), tau_n / (1.0 + xn) ** (1.0 / nn), tau_lim)
    result: FloatArray = np.sign(rate) * magnitude
    return result


def harmonic_combination(
    viscosity: ArrayLike, shear_rate: ArrayLike, limiting_stress: ArrayLike
) -> FloatArray:
    r"""Harmonic combination of Newtonian and limiting stress, the study's eq. (5).

    .. math:: \tau = \left(\tau_N^{-1} + \tau_{lim}^{-1}\right)^{-1}
              = \frac{\tau_N\,\tau_{lim}}{\tau_N + \tau_{lim}}

    The :math:`n = 1` case of :func:`general_non_newtonian`.

    Examples
    --------
    >>> float(harmonic_combination(0.1, 3e8, 15e6))
    10000000.0
    """
    return general_non_newtonian(viscosity, shear_rate, limiting_stress, n=1.0)


def eyring_1936(
    viscosity: ArrayLike, shear_rate: ArrayLike, eyring_stress: ArrayLike
) -> FloatArray:
    r"""Eyring's shear-thinning law, :math:`\tau = \tau_E\,\mathrm{asinh}(\eta\dot\gamma/\tau_E)`.

    Parameters
    ----------
    viscosity : array_like
        Local dynamic viscosity [Pa·s].
    shear_rate : array_like
        [1/s].
    eyring_stress : array_like
        :math:`\tau_E` [Pa], > 0; 2 to 10 MPa is typical of mineral oils
        (Harris & Kotzalas [4]).

    Returns
    -------
    numpy.ndarray
        Shear stress [Pa]; unbounded (grows logarithmically).

    Examples
    --------
    >>> round(float(eyring_1936(1.0, 5e6, 5e6)) / 5e6, 6)  # asinh(1)
    0.881374
    """
    eta = check_nonnegative("viscosity", viscosity, "Pa·s")
    rate = check_finite("shear_rate", shear_rate)
    tau_e = check_positive("eyring_stress", eyring_stress, "Pa")
    result: FloatArray = tau_e * np.arcsinh(eta * rate / tau_e)
    return result


def bair_winer_1979(
    viscosity: ArrayLike, shear_rate: ArrayLike, limiting_stress: ArrayLike
) -> FloatArray:
    r"""Bair and Winer's limiting-shear law (steady, viscous part).

    .. math:: \tau = \tau_{lim}\left[1 - \exp\left(-\frac{\eta\dot\gamma}{\tau_{lim}}\right)\right]

    Bair and Winer's model [1] adds an elastic term
    :math:`\dot\tau/G_\infty` for transient shear; at the steady shear of a
    friction calculation it vanishes and the law above remains.

    Parameters
    ----------
    viscosity : array_like
        Local dynamic viscosity [Pa·s].
    shear_rate : array_like
        [1/s].
    limiting_stress : array_like
        :math:`\tau_{lim}` [Pa], > 0.

    Returns
    -------
    numpy.ndarray
        Shear stress [Pa].

    Examples
    --------
    >>> round(float(bair_winer_1979(1.0, 1e7, 1e7)) / 1e7, 6)  # 1 - 1/e
    0.632121
    """
    eta = check_nonnegative("viscosity", viscosity, "Pa·s")
    rate = check_finite("shear_rate", shear_rate)
    tau_lim = check_positive("limiting_stress", limiting_stress, "Pa")
    result: FloatArray = -np.sign(rate) * tau_lim * np.expm1(-eta * np.abs(rate) / tau_lim)
    return result
