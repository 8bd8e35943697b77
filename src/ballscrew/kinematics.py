r"""Ideal rolling kinematics of a ball screw: rotating screw, translating nut.

The screw turns at :math:`\omega` and the nut translates without turning. In
the frame that follows the ball set (the "cage" frame of a bearing) the balls
roll without sliding on both grooves; this is the bearing analogy with the
screw as the rotating inner ring and the nut as the fixed outer ring (Harris
& Kotzalas [1]_ ch. 8, used by Olaru et al. [2]_). With :math:`\gamma =
D_w\cos\alpha/d_m`:

.. math::
    \omega_m = \tfrac{\omega}{2}(1-\gamma),\qquad
    \omega_b = \frac{d_m}{2D_w}(1-\gamma^2)\,\omega,\qquad
    u = \frac{\omega d_m}{4}(1-\gamma^2),\qquad
    v_t = \frac{\omega l}{2\pi}

are the orbital speed of the ball centres about the screw axis (relative to
the nut), the ball's rotational speed about its own axis, the entrainment
(rolling) speed of both contacts, and the table (nut) speed. The ball's axis
is taken perpendicular to the contact line; the grooves' angular velocities
then have components :math:`(\omega-\omega_m)\sin\alpha` (screw) and
:math:`\omega_m\sin\alpha` (nut) along the contact normal, the spin speeds of
the two contacts. The axial advance of the balls along the helix adds terms
of order :math:`\tan\lambda`, neglected here (exact treatment: Wei & Lin
[3]_).

All functions accept arrays and broadcast; speeds may be negative (reverse
rotation); magnitudes follow :math:`|\omega|`, signs follow :math:`\omega`.

References
----------
.. [1] T. A. Harris, M. N. Kotzalas, *Advanced Concepts of Bearing
   Technology*, 5th ed., CRC Press, 2007, ch. 8.
.. [2] D. Olaru, G. C. Puiu, L. C. Balan, V. Puiu, "A new model to estimate
   friction torque in a ball screw system", *Product Engineering*, Springer,
   2005, doi:10.1007/1-4020-2933-0_20.
.. [3] C. C. Wei, J. F. Lin, J. Mech. Des. 125 (2003) 717-733,
   doi:10.1115/1.1623762.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy.typing as npt

from .errors import FloatArray, check_finite
from .geometry import BallScrew

__all__ = [
    "Kinematics",
    "differential_sliding",
    "four_point_spin",
    "kinematics",
    "rpm_to_rad_s",
]


def rpm_to_rad_s(speed_rpm: npt.ArrayLike) -> FloatArray:
    """Convert revolutions per minute to radians per second.

    >>> round(float(rpm_to_rad_s(60.0)), 6)
    6.283185
    """
    result: FloatArray = check_finite("speed_rpm", speed_rpm) * (2.0 * math.pi / 60.0)
    return result


@dataclass(frozen=True)
class Kinematics:
    r"""Speeds of a ball screw under ideal rolling (arrays broadcast over the screw speed).

    Attributes
    ----------
    screw_speed : numpy.ndarray
        Angular speed of the screw :math:`\omega` [rad/s].
    table_speed : numpy.ndarray
        Axial speed of the nut :math:`v_t = \omega l/2\pi` [m/s].
    orbital_speed : numpy.ndarray
        Angular speed of the ball centres about the screw axis, relative to
        the nut :math:`\omega_m` [rad/s].
    ball_speed : numpy.ndarray
        Angular speed of a ball about its own axis :math:`\omega_b` [rad/s].
    entrainment_speed : numpy.ndarray
        Mean rolling speed of the surfaces at either contact :math:`u` [m/s].
    spin_screw, spin_nut : numpy.ndarray
        Spin (angular speed about the contact normal) at the ball-screw and
        ball-nut contacts [rad/s].
    spin_to_roll_screw, spin_to_roll_nut : float
        Spin over ball speed at each contact [-], a property of the geometry:
        :math:`D_w\sin\alpha/(d_m(1\mp\gamma))`.
    """

    screw_speed: FloatArray
    table_speed: FloatArray
    orbital_speed: FloatArray
    ball_speed: FloatArray
    entrainment_speed: FloatArray
    spin_screw: FloatArray
    spin_nut: FloatArray

    spin_to_roll_screw: float
    spin_to_roll_nut: float


def kinematics(screw: BallScrew, speed: npt.ArrayLike) -> Kinematics:
    r"""Ideal rolling speeds for a screw turning at ``speed``.

    Parameters
    ----------
    screw : BallScrew
        Geometry.
    speed : array_like
        Angular speed of the screw :math:`\omega` [rad/s].

    Returns
    -------
    Kinematics

    Examples
    --------
    A 40 mm x 10 mm screw with 6.35 mm balls at 1000 rpm:

    >>> import math
    >>> from ballscrew import BallScrew
    >>> s = BallScrew(pitch_diameter=0.040, lead=0.010, ball_diameter=6.35e-3,
    ...               contact_angle=math.radians(45), conformity_screw=0.55,
    ...               conformity_nut=0.55, loaded_turns=2.5, circuits=2)
    >>> k = kinematics(s, rpm_to_rad_s(1000.0))
    >>> round(float(k.table_speed), 4), round(float(k.entrainment_speed), 4)
    (0.1667, 1.034)
    """
    w = check_finite("speed", speed)
    g = screw.gamma
    sin_a = math.sin(screw.contact_angle)
    orbital = 0.5 * w * (1.0 - g)
    return Kinematics(
        screw_speed=w,
        table_speed=w * screw.lead / (2.0 * math.pi),
        orbital_speed=orbital,
        ball_speed=w * screw.pitch_diameter / (2.0 * screw.ball_diameter) * (1.0 - g * g),
        entrainment_speed=0.25 * w * screw.pitch_diameter * (1.0 - g * g),
        spin_screw=(w - orbital) * sin_a,
        spin_nut=orbital * sin_a,
        spin_to_roll_screw=screw.ball_diameter * sin_a / (screw.pitch_diameter * (1.0 - g)),
        spin_to_roll_nut=screw.ball_diameter * sin_a / (screw.pitch_diameter * (1.0 + g)),
    )


def differential_sliding(screw: BallScrew, speed: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
    r"""Curvature coefficients of the differential (Heathcote) sliding at both contacts.

    Across the groove the pressed contact surface is curved with the deformed
    radius :math:`R_d = 2fD_w/(2f+1)`; a point at transverse distance
    :math:`y` from the contact centre lies nearer the ball's axis and, at the
    screw, farther from the screw axis (at the nut: nearer). With the ball
    and groove surfaces moving together at :math:`y = 0`, the sliding speed
    of the ball over the groove in the rolling direction is, to second order
    in :math:`y/R_d`,

    .. math::
        \Delta v(y) = -C\,y^2 \mp \omega_s y,\qquad
        C_s = \frac{\omega_b + (\omega-\omega_m)\cos\alpha}{2R_{d,s}},\quad
        C_n = \frac{\omega_b - \omega_m\cos\alpha}{2R_{d,n}}

    where the linear term is the spin (see :class:`Kinematics`) and a uniform
    slip adds to both when the ball's speed departs from ideal rolling.

    Parameters
    ----------
    screw : BallScrew
        Geometry.
    speed : array_like
        Screw angular speed :math:`\omega` [rad/s].

    Returns
    -------
    C_s, C_n : numpy.ndarray
        [1/(m·s)], with the sign of the speed.

    Examples
    --------
    >>> import math
    >>> from ballscrew import reference_screw
    >>> cs, cn = differential_sliding(reference_screw(), 100.0)
    >>> round(float(cs)), round(float(cn))
    (52660, 42031)
    """
    kin = kinematics(screw, speed)
    cos_a = math.cos(screw.contact_angle)
    c_s = (kin.ball_speed + (kin.screw_speed - kin.orbital_speed) * cos_a) / (
        2.0 * screw.deformed_radius_screw
    )
    c_n = (kin.ball_speed - kin.orbital_speed * cos_a) / (2.0 * screw.deformed_radius_nut)
    return c_s, c_n


def four_point_spin(screw: BallScrew, speed: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
    r"""Spin at the screw and nut contacts of a ball with four-point contact [rad/s].

    A ball of a 2-point nut rolls about an axis perpendicular to its contact
    line (the assumption of :class:`Kinematics`), so its own rotation has no
    component along the contact normal. A ball pressed against both flanks
    of gothic-arch grooves rolls without sliding at the centres of all four
    contacts only if its axis is parallel to the screw axis: pure rolling at
    two contacts of one member (at :math:`+\alpha` and :math:`-\alpha`, at
    the same distance from the screw axis) makes the ball turn about the line
    through them. Its rotation then has the component
    :math:`\omega_b\tan\alpha` along every contact normal, which adds to the
    groove's spin at the screw and subtracts from it at the nut:

    .. math::
        \omega_{s,s}^{4} = \omega_b\tan\alpha + (\omega - \omega_m)\sin\alpha,\qquad
        \omega_{s,n}^{4} = \omega_b\tan\alpha - \omega_m\sin\alpha

    (magnitudes, signs as the screw speed). This extra spin is the sliding
    that the kinematic conflict of a 4-point contact costs (the same balls
    on 2-point contacts spin at :math:`(\omega - \omega_m)\sin\alpha` and
    :math:`\omega_m\sin\alpha`).

    Examples
    --------
    >>> import math
    >>> from ballscrew import reference_screw
    >>> s, n = four_point_spin(reference_screw(), 1.0)
    >>> k = kinematics(reference_screw(), 1.0)
    >>> round(float(s - k.spin_screw), 4) == round(float(n + k.spin_nut), 4)  # both ω_b tan α
    True
    """
    kin = kinematics(screw, speed)
    extra = kin.ball_speed * math.tan(screw.contact_angle)
    return extra + kin.spin_screw, extra - kin.spin_nut
