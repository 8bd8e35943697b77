r"""The viscoelastic rolling-friction model (Pöschel et al. 1999; Tan et al. 2006).

A rigid ball of radius :math:`R` rolls at speed :math:`v` over a bed of
independent vertical mass-spring-damper elements with, per unit area, mass
:math:`m` [kg/m²], damping :math:`\gamma` [N·s/m³] and stiffness :math:`k`
[N/m³] (the study's eq. 1). In the ball's frame an element at
:math:`(x, y)` (:math:`x` forward) is pressed to the paraboloid
:math:`z = \tau - (x^2+y^2)/2R`, so :math:`\dot z = vx/R`, :math:`\ddot z =
-v^2/R` and the pressure it exerts is

.. math:: f = k\left(\tau - \frac{x^2+y^2}{2R}\right) + \gamma\frac{vx}{R} - m\frac{v^2}{R}.

Elements touch the ball inside the circle :math:`r_+^2 = 2R\tau` (below the
undisturbed surface) and while they push (:math:`f \ge 0`): inside the
circle of centre :math:`x_c = \gamma v/k` and radius :math:`r_-^2 = 2R\tau -
2mv^2/k + x_c^2`. The contact area is the lens common to both circles; its
chord lies at :math:`x = mv/\gamma`, and the front arc of the first circle,
the leading edge, spans :math:`\pm\theta_0` with :math:`\cos\theta_0 =
mv/(\gamma r_+)`.

Resting elements reach the leading edge and are set moving at
:math:`\dot z` at once; the momentum they take gives the edge force (the
study's eq. 2)

.. math:: F_B = m\tau v^2\,[2\theta_0 + \sin 2\theta_0]

and the kinetic energy they take, per unit time,

.. math:: P_B = m v^3\frac{r_+^3}{R^2}\left(\sin\theta_0 - \tfrac13\sin^3\theta_0\right).

The penetration :math:`\tau` follows from the load (eq. 3), :math:`Q =
\iint f\,dA + F_B`, and the friction force from the energy balance (eq. 4),
:math:`Fv = \iint f\dot z\,dA + P_B`. The integrals of the quadratic and
cubic polynomials over the lens are evaluated in closed form (moments of
circular segments), and :math:`\tau` is solved on all operating points at
once by bracketing and the Illinois variant of regula falsi.

Limits (exact, tested): static, :math:`\tau = \sqrt{Q/\pi kR}`; slow
rolling, :math:`F \to \pi\gamma v\tau^2`.

Readings of the study:

* The study prints :math:`F_B` with a minus sign in a balance
  :math:`\iint f + F_B + F_N = 0`. With :math:`f` counted positive into the
  bed, the impulse that brings the resting elements to speed pushes the ball
  up and helps carry the load, so it is added to the support (derived
  above; the magnitude agrees with the study's eq. 2).
* The study names :math:`P_B` the kinetic energy per time given to the
  leading edge (``edge_power="kinetic"``, default). In an inelastic capture
  as much energy again is dissipated in the impact; ``edge_power="work"``
  counts both (the value a moment balance on the ball gives).
* The study turns the summed friction force into a torque "multiplied by
  the ball radius" (``torque_arm="ball-radius"``). The default
  ``"energy"`` charges the screw with the power :math:`F u` dissipated at
  each contact, consistent with the other models.
* Each ball-groove contact is treated as the ball on a flat bed (as Tan
  did for micro-ball bearings), so the screw and nut contacts of a ball are
  equal.

Defaults are the study's Fig. 4 values: :math:`k = 2.1\cdot10^{18}` N/m³,
:math:`m = 7.8\cdot10^{-4}` kg/m², :math:`\gamma = 3.5\cdot10^{13}`
N·s/m³ (a 100 nm elastic layer of steel, as the study derives them).

References
----------
.. [1] T. Pöschel, T. Schwager, N. V. Brilliantov, "Rolling friction of a
   hard cylinder on a viscous plane", Eur. Phys. J. B 10 (1999) 169-174,
   doi:10.1007/s100510050841.
.. [2] X. Tan, A. Modafe, R. Ghodssi, "Measurement and modeling of dynamic
   rolling friction in linear microball bearings", J. Dyn. Syst. Meas.
   Control 128 (2006) 891-898, doi:10.1115/1.2362786.
.. [3] J. Sušeň, "A Study on the Ball Screw Friction Torque", CTU Prague,
   section 2.2 and Fig. 4.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from ..errors import (
    FloatArray,
    check_choice,
    check_nonnegative,
    check_positive,
)
from ..geometry import BallScrew
from ..kinematics import kinematics
from ..loads import ball_loads
from ..lubricant import Lubricant
from ..numerics import Index, illinois
from ._common import lever_arms
from ._registry import register

__all__ = ["ViscoelasticContact", "lens_moments", "viscoelastic", "viscoelastic_contact"]


def _segment(
    c: FloatArray, rho: FloatArray, t1: FloatArray, t2: FloatArray
) -> tuple[FloatArray, ...]:
    r"""Moments of the part of a disk between two chords.

    The disk has centre :math:`(c, 0)` and radius :math:`\rho`; with
    :math:`x = c + \rho\cos t`, the part is :math:`t_1 \le t \le t_2`
    (:math:`0 \le t_1 \le t_2 \le \pi`; :math:`t = 0` is the front point).
    Returns :math:`\iint 1, x, x^2, x^3, y^2, xy^2\,dA`.
    """

    def prims(t: FloatArray) -> tuple[FloatArray, ...]:
        s = np.sin(t)
        s2, s4 = np.sin(2 * t), np.sin(4 * t)
        return (
            t / 2 - s2 / 4,  # ∫ sin² t           (n=0, m=2)
            s**3 / 3,  # ∫ cos t sin² t           (n=1, m=2)
            t / 8 - s4 / 32,  # ∫ cos² t sin² t   (n=2, m=2)
            s**3 / 3 - s**5 / 5,  # ∫ cos³ t sin² t (n=3, m=2)
            3 * t / 8 - s2 / 4 + s4 / 32,  # ∫ sin⁴ t (n=0, m=4)
            s**5 / 5,  # ∫ cos t sin⁴ t           (n=1, m=4)
        )

    i02, i12, i22, i32, i04, i14 = (hi - lo for hi, lo in zip(prims(t2), prims(t1), strict=True))
    m0 = 2 * rho**2 * i02
    m1 = 2 * rho**3 * i12
    m2 = 2 * rho**4 * i22
    m3 = 2 * rho**5 * i32
    s0 = 2.0 / 3.0 * rho**4 * i04
    s1 = 2.0 / 3.0 * rho**5 * i14
    return (
        m0,
        c * m0 + m1,
        c**2 * m0 + 2 * c * m1 + m2,
        c**3 * m0 + 3 * c**2 * m1 + 3 * c * m2 + m3,
        s0,
        c * s0 + s1,
    )


def lens_moments(
    r_plus: npt.ArrayLike, centre: npt.ArrayLike, r_minus_sq: npt.ArrayLike, chord: npt.ArrayLike
) -> tuple[FloatArray, ...]:
    r"""Moments of the lens common to two disks on the x axis.

    Disk A has centre 0 and radius ``r_plus``; disk B centre ``centre`` and
    squared radius ``r_minus_sq`` (empty where <= 0); ``chord`` is the
    position of their radical line. The lens is A beyond the chord plus B
    behind it (the power of a point with respect to the two circles decides
    on which side each circle bounds the lens).

    Returns
    -------
    tuple of numpy.ndarray
        :math:`\iint 1, x, x^2, x^3, y^2, xy^2\,dA` [m², m³, m⁴, m⁵, m⁴, m⁵]
        and the half-angle :math:`\theta_0` of A's arc on the boundary [rad].
    """
    rp = np.asarray(r_plus, dtype=float)
    xc = np.asarray(centre, dtype=float)
    rm2 = np.asarray(r_minus_sq, dtype=float)
    ch = np.asarray(chord, dtype=float)
    exists = (rm2 > 0.0) & (rp > 0.0)
    rm = np.sqrt(np.where(exists, rm2, 1.0))
    safe_rp = np.where(exists, rp, 1.0)
    theta0 = np.where(exists, np.arccos(np.clip(ch / safe_rp, -1.0, 1.0)), 0.0)
    t_b = np.where(exists, np.arccos(np.clip((ch - xc) / rm, -1.0, 1.0)), np.pi)
    zero = np.zeros_like(theta0)
    front = _segment(zero, np.where(exists, rp, 0.0), zero, theta0)
    rear = _segment(xc, np.where(exists, rm, 0.0), t_b, np.full_like(t_b, np.pi))
    return (*(f + r for f, r in zip(front, rear, strict=True)), theta0)


@dataclass(frozen=True)
class ViscoelasticContact:
    r"""Solution of one ball on the viscoelastic bed (arrays broadcast over the inputs).

    Attributes
    ----------
    penetration : numpy.ndarray
        :math:`\tau` [m].
    friction : numpy.ndarray
        Rolling friction force :math:`F` [N].
    edge_force : numpy.ndarray
        :math:`F_B` [N].
    leading_edge_angle : numpy.ndarray
        :math:`\theta_0` [rad].
    """

    penetration: FloatArray
    friction: FloatArray
    edge_force: FloatArray
    leading_edge_angle: FloatArray


def _balance(
    tau: FloatArray,
    v: FloatArray,
    radius: float,
    k: float,
    m: float,
    gamma: float,
    leading_edge: bool,
) -> tuple[FloatArray, FloatArray, FloatArray, tuple[FloatArray, ...]]:
    """Support force, edge force, theta0 and lens moments at penetration ``tau``."""
    r_plus = np.sqrt(2.0 * radius * tau)
    xc = gamma * v / k
    rm2 = 2.0 * radius * tau - 2.0 * m * v**2 / k + xc**2
    chord = m * v / gamma
    *mom, theta0 = lens_moments(r_plus, xc, rm2, chord)
    i0, i1, i2, _, iy2, _ = mom
    a0 = k * tau - m * v**2 / radius
    a1 = gamma * v / radius
    a2 = -k / (2.0 * radius)
    support = a0 * i0 + a1 * i1 + a2 * (i2 + iy2)
    edge = m * tau * v**2 * (2.0 * theta0 + np.sin(2.0 * theta0)) if leading_edge else 0.0 * tau
    return support + edge, edge, theta0, tuple(mom)


def viscoelastic_contact(
    load: npt.ArrayLike,
    speed: npt.ArrayLike,
    radius: float,
    *,
    stiffness: float = 2.1e18,
    mass: float = 7.8e-4,
    damping: float = 3.5e13,
    leading_edge: bool = True,
    edge_power: str = "kinetic",
) -> ViscoelasticContact:
    r"""Penetration and rolling friction of a rigid ball on the viscoelastic bed.

    Parameters
    ----------
    load : array_like
        Normal load :math:`Q` [N], >= 0.
    speed : array_like
        Rolling speed :math:`v` [m/s] (sign ignored).
    radius : float
        Ball radius :math:`R` [m].
    stiffness, mass, damping : float
        :math:`k` [N/m³], :math:`m` [kg/m²], :math:`\gamma` [N·s/m³] per unit area.
    leading_edge : bool
        Include the leading-edge force and power.
    edge_power : {"kinetic", "work"}
        See the module docstring.

    Returns
    -------
    ViscoelasticContact

    Examples
    --------
    Static limit :math:`\tau = \sqrt{Q/\pi kR}`:

    >>> c = viscoelastic_contact(30.0, 0.0, 3e-3)
    >>> round(float(c.penetration / np.sqrt(30.0 / (np.pi * 2.1e18 * 3e-3))), 12)
    1.0
    """
    q = check_nonnegative("load", load, "N")
    v = np.abs(np.asarray(speed, dtype=float))
    check_positive("radius", radius, "m")
    k = float(check_positive("stiffness", stiffness, "N/m³"))
    m = float(check_nonnegative("mass", mass, "kg/m²"))
    gamma = float(check_positive("damping", damping, "N·s/m³"))
    check_choice("edge_power", edge_power, ("kinetic", "work"))
    q, v = np.broadcast_arrays(q, v)
    q = q.astype(float)
    v = v.astype(float)
    # An unloaded ball (a lifted-off half-nut) has no contact: solve those points for a
    # stand-in load of 1 N and report no penetration and no friction there (below).
    # Solving for Q = 0 itself fails: the bed's inertia makes the support negative at
    # small penetrations, so the root would sit at an unphysical positive penetration.
    q_solve = np.where(q > 0.0, q, 1.0)
    lo, hi, f_lo, f_hi = _bracket(q_solve, v, radius, k, m, gamma, leading_edge)
    # Illinois regula falsi on all points at once.
    flat_v = v.reshape(-1)
    flat_q = q_solve.reshape(-1)

    def residual_at(tau: FloatArray, index: Index) -> FloatArray:
        total: FloatArray = (
            _balance(tau, flat_v[index], radius, k, m, gamma, leading_edge)[0] - flat_q[index]
        )
        return total

    tau = illinois(residual_at, lo, hi, f_lo, f_hi, xtol=1e-300, rtol=1e-13, ftol=1e-12 * q_solve)
    tau = np.where(q > 0.0, tau, 0.0)
    _, edge, theta0, mom = _balance(tau, v, radius, k, m, gamma, leading_edge)
    friction = _rolling_friction(tau, v, radius, k, m, gamma, theta0, mom, leading_edge, edge_power)
    return ViscoelasticContact(
        penetration=tau,
        friction=np.where(q > 0.0, friction, 0.0),
        edge_force=np.where(q > 0.0, edge, 0.0),
        leading_edge_angle=theta0,
    )


def _bracket(
    q_solve: FloatArray,
    v: FloatArray,
    radius: float,
    k: float,
    m: float,
    gamma: float,
    leading_edge: bool,
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """A bracket of the penetration at every point and the residuals at its ends.

    ``N(0) - Q = -Q <= 0``; the upper end grows from the static solution.
    """

    def residual(tau: FloatArray) -> FloatArray:
        total: FloatArray = _balance(tau, v, radius, k, m, gamma, leading_edge)[0] - q_solve
        return total

    lo = np.zeros_like(q_solve)
    hi = np.sqrt(q_solve / (np.pi * k * radius)) * 1.5
    f_lo = -q_solve
    f_hi = residual(hi)
    for _ in range(200):
        low = f_hi < 0.0
        if not low.any():
            break
        lo = np.where(low, hi, lo)
        f_lo = np.where(low, f_hi, f_lo)
        hi = np.where(low, hi * 2.0, hi)
        f_hi = residual(hi)
    else:  # pragma: no cover - the support grows at least like tau**2
        raise RuntimeError("viscoelastic_contact: could not bracket the penetration")
    return lo, hi, f_lo, f_hi


def _rolling_friction(
    tau: FloatArray,
    v: FloatArray,
    radius: float,
    k: float,
    m: float,
    gamma: float,
    theta0: FloatArray,
    mom: tuple[FloatArray, ...],
    leading_edge: bool,
    edge_power: str,
) -> FloatArray:
    """The bed's rolling friction force at the penetration ``tau``: bulk plus leading edge."""
    _, i1, i2, i3, _, ixy2 = mom
    a0 = k * tau - m * v**2 / radius
    a1 = gamma * v / radius
    a2 = -k / (2.0 * radius)
    bulk = (a0 * i1 + a1 * i2 + a2 * (i3 + ixy2)) / radius
    r_plus = np.sqrt(2.0 * radius * tau)
    edge_friction = m * v**2 * r_plus**3 / radius**2 * (np.sin(theta0) - np.sin(theta0) ** 3 / 3)
    if not leading_edge:
        edge_friction = 0.0 * edge_friction
    elif edge_power == "work":
        edge_friction = 2.0 * edge_friction
    total: FloatArray = bulk + edge_friction
    return total


@register(
    "viscoelastic",
    title="Viscoelastic bed (Pöschel; Tan): rigid ball rolling on mass-spring-damper elements",
    reference="T. Pöschel et al., Eur. Phys. J. B 10 (1999) 169, doi:10.1007/s100510050841; "
    "X. Tan et al., J. Dyn. Syst. Meas. Control 128 (2006) 891, doi:10.1115/1.2362786",
    validity="parameters per unit area from a thin elastic layer; fitted for micro-ball bearings",
    purpose="to reproduce the study (Sušeň's Figs. 4-5); not for prediction",
)
def viscoelastic(
    screw: BallScrew, lubricant: Lubricant, speed: FloatArray, temperature: FloatArray,
    axial_load: FloatArray, *,
    stiffness: float = 2.1e18,
    mass: float = 7.8e-4,
    damping: float = 3.5e13,
    leading_edge: bool = True,
    edge_power: str = "kinetic",
    torque_arm: str = "energy",
) -> dict[str, FloatArray]:  # fmt: skip
    r"""Friction torque by the viscoelastic model (module docstring).

    Parameters
    ----------
    screw, lubricant, speed, temperature, axial_load
        The operating points; the lubricant and temperature do not enter.
    stiffness, mass, damping : float
        :math:`k` [N/m³], :math:`m` [kg/m²], :math:`\gamma` [N·s/m³]; the
        study's Fig. 4 values by default.
    leading_edge : bool
        Include the leading-edge force and power (default True).
    edge_power : {"kinetic", "work"}
        See the module docstring.
    torque_arm : {"energy", "contact-radius", "ball-radius"}
        ``"energy"`` (default) or the study's ``"ball-radius"``.

    Returns
    -------
    dict
        ``"viscoelastic"`` torque [N·m].
    """
    levers = lever_arms(screw, torque_arm)
    kin = kinematics(screw, speed)
    bl = ball_loads(screw, axial_load)
    radius = 0.5 * screw.ball_diameter
    u = np.abs(kin.entrainment_speed)
    total: FloatArray = np.zeros(np.broadcast_shapes(u.shape, bl.normal_load_1.shape))
    for q, balls in ((bl.normal_load_1, bl.balls_1), (bl.normal_load_2, bl.balls_2)):
        if balls == 0:
            continue
        sol = viscoelastic_contact(
            q,
            u,
            radius,
            stiffness=stiffness,
            mass=mass,
            damping=damping,
            leading_edge=leading_edge,
            edge_power=edge_power,
        )
        lever = levers["screw"] + levers["nut"]  # the two contacts of a ball are equal
        total = total + balls * sol.friction * lever
    return {"viscoelastic": total}
