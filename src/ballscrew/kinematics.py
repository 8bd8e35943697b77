r"""Rolling kinematics of a ball screw with the helix kept: rotating screw, translating nut.

The screw turns at :math:`\omega` and the nut translates without turning. In
the frame of the nut the screw performs a screw motion of lead :math:`l`
(every point of it moves along its own helix), and the centre of each loaded
ball moves along the helix of the pitch circle, radius :math:`d_m/2`, lead
angle :math:`\lambda` (:math:`\tan\lambda = l/\pi d_m`). The contact normals
lie in the normal plane of that helix (the groove is the envelope of the
ball swept along it), inclined at the contact angle :math:`\alpha`. With
:math:`\gamma = D_w\cos\alpha/d_m`, rolling without slip *along* the groove
at both contacts gives, exactly (Lin, Ravani & Velinsky [1]_; Wei & Lin
[2]_; derived again for this package and checked against a numerical
rigid-body evaluation of the surface velocities, ``tests/physics/test_kinematics.py``):

.. math::
    \omega_m = \tfrac{\omega}{2}(1-\gamma\cos^2\lambda),\qquad
    \omega_b = \frac{\omega d_m}{2D_w\cos\lambda}(1-\gamma^2\cos^4\lambda),\qquad
    u = \frac{\omega d_m}{4\cos\lambda}(1-\gamma^2\cos^4\lambda),\qquad
    v_t = \frac{\omega l}{2\pi}

the orbital speed of the ball centres about the screw axis (relative to the
nut), the ball's rolling speed about its own axis (relative to the frame
that follows its centre), the entrainment (rolling) speed of both contacts,
and the table (nut) speed. With the ball's axis perpendicular to the contact
line (relative to that frame), the spins, the angular speeds about the
contact normal, are

.. math::
    \omega_{s,s} = (\omega-\omega_m)\sin\alpha\cos\lambda,\qquad
    \omega_{s,n} = \omega_m\sin\alpha\cos\lambda .

**The helix forbids pure rolling.** Across the groove (along
:math:`\mathbf m = \mathbf n\times\mathbf t`, in the contact plane,
perpendicular to the rolling direction :math:`\mathbf t`) the screw's surface
at its contact moves at :math:`\omega R\sin\lambda` relative to the ball
centre (:math:`R = D_w/2`): the part :math:`\omega\sin\lambda` of the screw's
angular velocity that lies along :math:`\mathbf t` sweeps it sideways. The
nut's surface does not move across the groove, and any rotation of a rigid
ball moves its two contact points across the groove at equal and opposite
speeds. So the transverse slips at the two contacts always add up to

.. math:: s_\perp = \omega R\sin\lambda

whatever the ball does: "there is always slip" [1]_. How it is shared
between the screw and the nut contact is not a matter of kinematics (the
ball's rotation about :math:`\mathbf t` is free); it follows from the ball's
moment balance (:mod:`ballscrew.helix`). Its ratio to the rolling speed is
:math:`D_w\sin 2\lambda/(d_m(1-\gamma^2\cos^4\lambda))`: 0.6 % for a
40 x 5 mm screw with 3.175 mm balls, 2.5 % for 40 x 10 mm with 6.35 mm
balls, 9 % for 40 x 40 mm.

As :math:`\lambda\to0` every value above becomes that of an angular-contact
bearing with the screw as inner ring and the nut as fixed outer ring
(Harris & Kotzalas [3]_ ch. 8, used by Olaru et al. [4]_), and the
transverse slip vanishes.

All functions accept arrays and broadcast; speeds may be negative (reverse
rotation); magnitudes follow :math:`|\omega|`, signs follow :math:`\omega`.

References
----------
.. [1] W. T. Lin, B. Ravani, S. A. Velinsky, "Kinematics of the ball screw
   mechanism", J. Mech. Des. 116 (1994) 849-855.
.. [2] C. C. Wei, J. F. Lin, "Kinematic analysis of the ball screw mechanism
   considering variable contact angles and elastic deformations", J. Mech.
   Des. 125 (2003) 717-733, doi:10.1115/1.1623761.
.. [3] T. A. Harris, M. N. Kotzalas, *Advanced Concepts of Bearing
   Technology*, 5th ed., CRC Press, 2007, ch. 8.
.. [4] D. Olaru, G. C. Puiu, L. C. Balan, V. Puiu, "A new model to estimate
   friction torque in a ball screw system", *Product Engineering*, Springer,
   2005, doi:10.1007/1-4020-2933-0_20.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from .errors import FloatArray, check_finite
from .geometry import ScrewGeometry, cos, sin, tan

__all__ = [
    "Kinematics",
    "differential_sliding",
    "four_point_spin",
    "kinematics",
    "neighbour_sliding",
    "neighbour_sliding_of",
    "rad_s_to_rpm",
    "rpm_to_rad_s",
]


_RAD_S_PER_RPM = 2.0 * math.pi / 60.0


def rpm_to_rad_s(speed_rpm: npt.ArrayLike) -> FloatArray:
    """Convert revolutions per minute to radians per second.

    >>> round(float(rpm_to_rad_s(60.0)), 6)
    6.283185
    """
    result: FloatArray = check_finite("speed_rpm", speed_rpm) * _RAD_S_PER_RPM
    return result


def rad_s_to_rpm(speed: npt.ArrayLike) -> FloatArray:
    """Convert radians per second to revolutions per minute.

    The inverse of :func:`rpm_to_rad_s`: it divides by the factor that one
    multiplies by, so a speed typed in rpm comes back as typed to rounding.

    >>> round(float(rad_s_to_rpm(2 * math.pi)), 9)
    60.0
    """
    result: FloatArray = np.asarray(speed, dtype=float) / _RAD_S_PER_RPM
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
        Rolling speed of a ball about its own axis, relative to the frame that
        follows its centre, :math:`\omega_b` [rad/s].
    entrainment_speed : numpy.ndarray
        Mean rolling speed of the surfaces at either contact :math:`u` [m/s].
    spin_screw, spin_nut : numpy.ndarray
        Spin (angular speed about the contact normal) at the ball-screw and
        ball-nut contacts [rad/s].
    transverse_slip : numpy.ndarray
        Sum of the across-groove slips at the screw and nut contacts of a
        ball, :math:`s_\perp = \omega R\sin\lambda` [m/s] (module docstring).
    spin_to_roll_screw, spin_to_roll_nut : float
        Spin over ball speed at each contact [-], a property of the geometry:
        :math:`D_w\sin\alpha\cos^2\lambda(1\pm\gamma\cos^2\lambda)/
        (d_m(1-\gamma^2\cos^4\lambda))`.
    """

    screw_speed: FloatArray
    table_speed: FloatArray
    orbital_speed: FloatArray
    ball_speed: FloatArray
    entrainment_speed: FloatArray
    spin_screw: FloatArray
    spin_nut: FloatArray
    transverse_slip: FloatArray

    spin_to_roll_screw: float
    spin_to_roll_nut: float


def kinematics(screw: ScrewGeometry, speed: npt.ArrayLike) -> Kinematics:
    r"""Rolling speeds and the transverse slip for a screw turning at ``speed``.

    Parameters
    ----------
    screw : BallScrew or ScrewArray
        Geometry (many screws as broadcast arrays: :class:`ballscrew.geometry.ScrewArray`).
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
    (0.1667, 1.0374)
    >>> round(float(k.transverse_slip / k.entrainment_speed), 4)  # slip-to-roll ratio
    0.0254
    """
    w = check_finite("speed", speed)
    g = screw.gamma
    lam = screw.lead_angle
    cos_l, sin_l = cos(lam), sin(lam)
    g_l = g * cos_l**2  # gamma cos^2(lambda)
    sin_a = sin(screw.contact_angle)
    roll = 1.0 - g_l * g_l  # 1 - gamma^2 cos^4(lambda)
    orbital = 0.5 * w * (1.0 - g_l)
    to_roll = screw.ball_diameter * sin_a * cos_l**2 / (screw.pitch_diameter * roll)
    return Kinematics(
        screw_speed=w,
        table_speed=w * screw.lead / (2.0 * math.pi),
        orbital_speed=orbital,
        ball_speed=w * screw.pitch_diameter / (2.0 * screw.ball_diameter * cos_l) * roll,
        entrainment_speed=0.25 * w * screw.pitch_diameter / cos_l * roll,
        spin_screw=(w - orbital) * sin_a * cos_l,
        spin_nut=orbital * sin_a * cos_l,
        transverse_slip=0.5 * w * screw.ball_diameter * sin_l,
        spin_to_roll_screw=to_roll * (1.0 + g_l),
        spin_to_roll_nut=to_roll * (1.0 - g_l),
    )


def differential_sliding(
    screw: ScrewGeometry, speed: npt.ArrayLike
) -> tuple[FloatArray, FloatArray]:
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
        C_s = \frac{\omega_b + (\omega-\omega_m)\cos\alpha\cos\lambda}{2R_{d,s}},\quad
        C_n = \frac{\omega_b - \omega_m\cos\alpha\cos\lambda}{2R_{d,n}}

    where the linear term is the spin (see :class:`Kinematics`) and a uniform
    slip adds to both when the ball's speed departs from rolling; the
    grooves' angular velocities enter through their components
    :math:`(\omega-\omega_m)\cos\alpha\cos\lambda` and
    :math:`\omega_m\cos\alpha\cos\lambda` along the ball's rolling axis.

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
    (52793, 42197)
    """
    kin = kinematics(screw, speed)
    cos_a = cos(screw.contact_angle) * cos(screw.lead_angle)
    c_s = (kin.ball_speed + (kin.screw_speed - kin.orbital_speed) * cos_a) / (
        2.0 * screw.deformed_radius_screw
    )
    c_n = (kin.ball_speed - kin.orbital_speed * cos_a) / (2.0 * screw.deformed_radius_nut)
    return c_s, c_n


def four_point_spin(screw: ScrewGeometry, speed: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
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
    extra = kin.ball_speed * tan(screw.contact_angle)
    return extra + kin.spin_screw, extra - kin.spin_nut


def neighbour_sliding(screw: ScrewGeometry, speed: npt.ArrayLike) -> FloatArray:
    r"""Sliding speed between two neighbouring balls of a cage-less train [m/s].

    Neighbours turn alike; they touch on their line of centres, along the
    rolling direction :math:`\mathbf t`, where their surfaces move in
    opposite directions at :math:`R|\boldsymbol\Omega\times\mathbf t|` each,
    :math:`\boldsymbol\Omega` being a ball's angular velocity relative to the
    frame that follows its centre. So they slide at
    :math:`D_w|\boldsymbol\Omega\times\mathbf t|`:

    * a 2-point ball turns about an axis perpendicular to its contact line
      (:class:`Kinematics`), which is perpendicular to :math:`\mathbf t`:
      :math:`\omega_bD_w`;
    * a 4-point ball (``nut="single-4point"``) rolls at all four contact
      centres only if it turns about the axial direction of the helix's
      normal plane (:func:`four_point_spin`), tilted by :math:`\alpha` from
      the 2-point axis, at :math:`\omega_b/\cos\alpha`, so that its contact
      points, at :math:`R\cos\alpha` from that axis, keep the rolling speed:
      :math:`\omega_bD_w/\cos\alpha`, 41 % more at 45°.

    Derived for this package and checked against a rigid-body solution of the
    four rolling conditions (``tests/physics/test_four_point_rigid_body.py``).

    Parameters
    ----------
    screw : BallScrew or ScrewArray
        Geometry and nut arrangement.
    speed : array_like
        Screw angular speed :math:`\omega` [rad/s].

    Returns
    -------
    numpy.ndarray
        [m/s], with the sign of the speed.

    Examples
    --------
    >>> import math
    >>> from ballscrew import reference_screw
    >>> s = reference_screw()
    >>> two = neighbour_sliding(s, 100.0)
    >>> four = neighbour_sliding(s.replace(nut="single-4point"), 100.0)
    >>> round(float(four / two), 4) == round(1 / math.cos(s.contact_angle), 4)
    True
    """
    return neighbour_sliding_of(screw, kinematics(screw, speed))


def neighbour_sliding_of(screw: ScrewGeometry, kin: Kinematics) -> FloatArray:
    """:func:`neighbour_sliding` from the screw's kinematics ``kin`` at the speeds wanted [m/s].

    For a caller that holds them already (the contact state's): the same numbers, without
    working out every rolling speed again.
    """
    sliding: FloatArray = kin.ball_speed * screw.ball_diameter
    if screw.nut == "single-4point":
        sliding = sliding / cos(screw.contact_angle)
    return sliding
