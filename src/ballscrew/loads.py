r"""Normal load on each ball from the preload and an external axial load.

A ball screw has two families of loaded contact lines, inclined at
:math:`+\alpha` and :math:`-\alpha`: the two half-nuts of a double nut, the
two contact pairs of each ball of a 4-point nut, or (single nut) the one flank
that carries the load. Family 1 is the one an external axial load
:math:`F_a > 0` loads further; family 2 is relieved. Per ball of a family the
normal contact load follows from the axial force :math:`F_j` it carries:

.. math:: Q_j = \frac{F_j}{Z\,\sin\alpha\,\cos\lambda}

with :math:`Z` the loaded balls of the family (Harris & Kotzalas [1]_ §1 for
the bearing, Olaru et al. [2]_ for the screw). The load on the screw contact
equals that on the nut contact of the same ball (ball equilibrium, inertia
neglected).

Preloaded families share an external load through the Hertz law
:math:`F_j = K\delta_j^{3/2}` [1]_: with :math:`\delta_{1,2} = \delta_0 \pm
x`, :math:`F_{pr} = K\delta_0^{3/2}` and :math:`F_1 - F_2 = F_a`, the ratio
:math:`s = x/\delta_0` solves

.. math:: (1+s)^{3/2} - (1-s)^{3/2} = F_a/F_{pr},

independently of :math:`K`. Family 2 lifts off (:math:`F_2 = 0`) at
:math:`F_a = 2^{3/2}F_{pr} \approx 2.83\,F_{pr}`; beyond that family 1 carries
:math:`F_a` alone. The contact angle is held at its nominal value (rigid
contact-angle assumption; Harris & Kotzalas [1]_ give the load-dependent
angle of angular-contact bearings, not modelled here).

References
----------
.. [1] T. A. Harris, M. N. Kotzalas, *Advanced Concepts of Bearing
   Technology*, 5th ed., CRC Press, 2007, ch. 1.
.. [2] D. Olaru, G. C. Puiu, L. C. Balan, V. Puiu, "A new model to estimate
   friction torque in a ball screw system", *Product Engineering*, Springer,
   2005, doi:10.1007/1-4020-2933-0_20.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from .errors import FloatArray, check_finite, check_nonnegative
from .geometry import ScrewGeometry, cos, sin
from .numerics.single import every, maximum, minimum, where

__all__ = ["LIFT_OFF_RATIO", "BallLoads", "ball_loads", "preload_split"]

LIFT_OFF_RATIO: float = 2.0**1.5
"""External axial load over preload at which the relieved family lifts off, :math:`2^{3/2}`."""


def preload_split(
    axial_load: npt.ArrayLike, preload: npt.ArrayLike
) -> tuple[FloatArray, FloatArray]:
    r"""Axial forces of two families preloaded against each other under an external load.

    Solves :math:`(1+s)^{3/2} - (1-s)^{3/2} = |F_a|/F_{pr}` for :math:`s` by
    Newton's method on the whole array (monotone convergence from
    :math:`s_0 = |F_a|/3F_{pr}`, since the left side is increasing and
    concave), then :math:`F_1 = F_{pr}(1+s)^{3/2}`, :math:`F_2 =
    F_{pr}(1-s)^{3/2}`; past lift-off :math:`F_1 = |F_a|`, :math:`F_2 = 0`.

    Parameters
    ----------
    axial_load : array_like
        External axial load :math:`F_a` [N]; its sign says which family is
        loaded, the result is given for the loaded one first.
    preload : array_like
        Preload :math:`F_{pr}` [N], >= 0.

    Returns
    -------
    loaded, relieved : numpy.ndarray
        Axial force on the loaded family (1) and the relieved family (2) [N];
        ``loaded - relieved == abs(axial_load)`` always.

    Examples
    --------
    Small loads are shared nearly half and half; at 2^1.5 times the preload the
    relieved family lifts off:

    >>> f1, f2 = preload_split([0.0, 100.0, 2.0**1.5 * 1000.0], 1000.0)
    >>> [round(float(v), 1) for v in f1], [round(float(v), 1) for v in f2]
    ([1000.0, 1050.4, 2828.4], [1000.0, 950.4, 0.0])
    """
    fa = np.abs(check_finite("axial_load", axial_load))
    fpr = check_nonnegative("preload", preload, "N")
    if np.shape(fa) != np.shape(fpr):
        fa, fpr = np.broadcast_arrays(fa, fpr)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        # A subnormal preload overflows to inf: that is lift-off, as it should be.
        ratio = where(fpr > 0.0, fa / where(fpr > 0.0, fpr, 1.0), np.inf)
    lifted = ratio >= LIFT_OFF_RATIO
    r = where(lifted, 0.0, ratio)
    s = r / 3.0
    # The bounds by maximum and minimum, as numpy's clip (whose wrapper costs microseconds a
    # call, which a single point pays at every step; numerics.single.maximum compares one point's
    # values as numbers).
    for _ in range(60):
        sp = np.sqrt(1.0 + s)
        sm = np.sqrt(maximum(1.0 - s, 0.0))
        g = sp**3 - sm**3 - r
        step = g / (1.5 * (sp + sm))
        s = minimum(maximum(s - step, 0.0), 1.0)
        if every(np.abs(step) <= 1e-14):
            break
    loaded = where(lifted, fa, fpr * (1.0 + s) ** 1.5)
    # The relieved force follows from the loaded one so that the balance is exact.
    relieved = where(lifted, 0.0, maximum(loaded - fa, 0.0))
    return loaded, relieved


@dataclass(frozen=True)
class BallLoads:
    """Ball loads of both contact-line families (arrays broadcast over the axial load).

    Attributes
    ----------
    axial_force_1, axial_force_2 : numpy.ndarray
        Axial force carried by the loaded family (1) and the relieved family (2) [N].
    normal_load_1, normal_load_2 : numpy.ndarray
        Normal load on each ball contact of family 1 and 2 [N]; the screw and
        nut contacts of a ball carry the same load.
    balls_1, balls_2 : int
        Loaded balls in each family [-]. For a 4-point nut both families are
        the same balls; for a single nut family 2 is empty.
    contact_angle : float
        Contact angle used [rad] (the nominal one).
    lifted_off : numpy.ndarray
        True where family 2 of a preloaded nut has lost its load.
    """

    axial_force_1: FloatArray
    axial_force_2: FloatArray
    normal_load_1: FloatArray
    normal_load_2: FloatArray
    balls_1: int | npt.NDArray[np.intp]
    balls_2: int | npt.NDArray[np.intp]
    contact_angle: float | FloatArray
    lifted_off: npt.NDArray[np.bool_]


def ball_loads(screw: ScrewGeometry, axial_load: npt.ArrayLike = 0.0) -> BallLoads:
    r"""Normal load per ball contact for the screw's nut arrangement and preload.

    Parameters
    ----------
    screw : BallScrew
        Geometry and preload.
    axial_load : array_like
        External axial load on the nut :math:`F_a` [N] (either sign).

    Returns
    -------
    BallLoads

    Notes
    -----
    ``"double"`` and ``"single-4point"``: the two families share the load by
    :func:`preload_split`; each half-nut of a double nut has
    ``screw.balls_per_nut`` balls, while in a 4-point nut every ball belongs to
    both families. ``"single"``: all balls carry :math:`|F_a|` on one flank.

    Examples
    --------
    >>> from ballscrew.geometry import reference_screw  # 40 x 10 mm, 98 balls a half-nut
    >>> loads = ball_loads(reference_screw())
    >>> round(float(loads.normal_load_1), 2)  # 2000 / (98 sin 45° cos 4.55°)
    28.95
    """
    fa = check_finite("axial_load", axial_load)
    z = screw.balls_per_nut
    per_ball = 1.0 / (z * sin(screw.contact_angle) * cos(screw.lead_angle))
    if screw.nut == "single":
        f1 = np.abs(fa)
        f2 = np.zeros_like(f1)
        lifted = np.zeros(f1.shape, dtype=bool)
        balls_2 = 0 * z
    else:
        f1, f2 = preload_split(fa, screw.preload)
        lifted = (f2 <= 0.0) & (screw.preload > 0.0)
        balls_2 = z
    return BallLoads(
        axial_force_1=f1,
        axial_force_2=f2,
        normal_load_1=f1 * per_ball,
        normal_load_2=f2 * per_ball,
        balls_1=z,
        balls_2=balls_2,
        contact_angle=screw.contact_angle,
        lifted_off=lifted,
    )
