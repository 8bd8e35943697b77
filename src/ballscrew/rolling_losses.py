r"""Loss mechanisms of a lubricated ball contact, one published law each.

The friction of a ball screw is the sum of what its ball contacts dissipate.
This module holds the laws of each mechanism as pure, vectorised functions;
:mod:`ballscrew.friction.complete` adds them up over the balls of a screw.

=============================== ===================================================
mechanism                       function
=============================== ===================================================
EHL rolling resistance          :func:`rolling_force_houpert` (Houpert 2002), capped at
                                speed by :func:`inlet_shear_heating_factor` and
                                :func:`replenishment_factor` (SKF 2012)
spin and differential sliding   :func:`spin_sliding_integral` (Hertz pressure times
                                the sliding speed, over the contact ellipse) with the
                                mixed-film coefficient :func:`mixed_friction_coefficient`
spin with a transverse slip     :func:`spin_slip_integrals` (power and transverse force
                                of a spinning contact that also slips across the
                                groove; used by :mod:`ballscrew.helix`)
elastic hysteresis              :func:`hysteresis_rolling_force` (Johnson 1985)
oil shear between neighbours    :func:`meniscus_shear_power` (Couette shear of the
                                gap between two counter-sliding balls; a flooded nut)
ball churning                   :func:`ball_churning_power` with the sphere drag curve
                                :func:`sphere_drag_coefficient` (Schiller & Naumann 1933)
=============================== ===================================================

Units are SI unless a function says otherwise (the SKF factors are empirical
fits in rpm, mm and mm²/s and say so).
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from .errors import FloatArray
from .numerics.single import as_float, where

__all__ = [
    "ball_churning_power",
    "hysteresis_rolling_force",
    "inlet_shear_heating_factor",
    "limiting_traction_coefficient",
    "meniscus_shear_power",
    "mixed_friction_coefficient",
    "replenishment_factor",
    "rolling_force_houpert",
    "sphere_drag_coefficient",
    "spin_sliding_integral",
    "spin_slip_integrals",
]


def rolling_force_houpert(
    reduced_modulus: npt.ArrayLike,
    rx: npt.ArrayLike,
    radius_ratio: npt.ArrayLike,
    g: npt.ArrayLike,
    u: npt.ArrayLike,
    w: npt.ArrayLike,
) -> FloatArray:
    r"""Houpert's EHL rolling (hydrodynamic) force of a point contact [N].

    .. math:: F_R = 2.86\,E'R_x^2\,k^{0.348}G^{0.022}U^{0.66}W^{0.47}

    The force that the pressure flow in the inlet of an isothermal, fully
    flooded EHL contact exerts against the rolling of each of the two
    surfaces (Houpert [1]_, fitted to numerical EHL solutions); with both
    surfaces resisted, a contact rolling at the entrainment speed :math:`u`
    dissipates :math:`2F_Ru`.

    Parameters
    ----------
    reduced_modulus : array_like
        :math:`E'` [Pa].
    rx : array_like
        Effective radius in the rolling direction [m].
    radius_ratio : array_like
        :math:`k = R_y/R_x` [-].
    g, u, w : array_like
        Hamrock-Dowson materials, speed and load parameters [-].

    References
    ----------
    .. [1] L. Houpert, "Ball bearing and tapered roller bearing torque:
       analytical, numerical and experimental results", Tribol. Trans. 45
       (2002) 345-353, doi:10.1080/10402000208982559.

    Examples
    --------
    >>> round(float(rolling_force_houpert(2.3e11, 3e-3, 12.0, 4600.0, 1e-11, 1e-5)), 4)
    0.0042
    """
    result: FloatArray = (
        2.86
        * as_float(reduced_modulus)
        * as_float(rx) ** 2
        * as_float(radius_ratio) ** 0.348
        * as_float(g) ** 0.022
        * as_float(u) ** 0.66
        * as_float(w) ** 0.47
    )
    return result


def inlet_shear_heating_factor(
    speed_rpm: npt.ArrayLike, pitch_diameter_mm: npt.ArrayLike, viscosity_mm2_s: npt.ArrayLike
) -> FloatArray:
    r"""SKF's inlet shear heating reduction factor of the rolling moment [-].

    .. math:: \phi_{ish} = \frac{1}{1 + 1.84\cdot10^{-9}(n\,d_m)^{1.28}\nu^{0.64}}

    with :math:`n` [rpm], :math:`d_m` [mm] and :math:`\nu` [mm²/s] at the
    operating temperature (SKF [1]_). Shear heating in the inlet thins the
    oil that builds the film, so the rolling resistance grows more slowly than
    :math:`(\nu n)^{0.66}` at high speed. For a ball screw :math:`n` is the
    screw speed and :math:`d_m` the pitch diameter: the entrainment speed
    :math:`u = \pi n d_m(1-\gamma^2)/120` is then the same as in a bearing of
    that mean diameter with a rotating inner ring.

    References
    ----------
    .. [1] SKF, *Rolling bearings*, catalogue 10000 EN, 2012, "Friction: the
       SKF model for calculating the frictional moment" (inlet shear heating
       reduction factor).

    Examples
    --------
    >>> round(float(inlet_shear_heating_factor(3000.0, 40.0, 68.0)), 3)
    0.92
    """
    nd = np.abs(as_float(speed_rpm)) * as_float(pitch_diameter_mm)
    result: FloatArray = 1.0 / (1.0 + 1.84e-9 * nd**1.28 * as_float(viscosity_mm2_s) ** 0.64)
    return result


def replenishment_factor(
    speed_rpm: npt.ArrayLike,
    viscosity_mm2_s: npt.ArrayLike,
    bore_mm: float | FloatArray,
    outside_mm: float | FloatArray,
    *,
    k_rs: float = 3e-8,
    k_z: float = 4.4,
) -> FloatArray:
    r"""SKF's kinematic replenishment (starvation) reduction factor [-].

    .. math::
        \phi_{rs} = \exp\!\left[-K_{rs}\,\nu\,n\,(d + D)
                     \sqrt{\frac{K_Z}{2(D - d)}}\right]

    with :math:`n` [rpm], :math:`\nu` [mm²/s], bore :math:`d` and outside
    diameter :math:`D` [mm]; :math:`K_{rs} = 3\cdot10^{-8}` for oil
    lubrication (bath, jet) and :math:`6\cdot10^{-8}` for grease and
    oil-air; :math:`K_Z = 4.4` for angular contact ball bearings (SKF [1]_).
    At high speed the oil pushed aside by one ball has no time to flow back
    before the next, the inlet starves and the rolling resistance drops.

    References
    ----------
    .. [1] SKF, *Rolling bearings*, catalogue 10000 EN, 2012, "Friction"
       (kinematic replenishment/starvation reduction factor).

    Examples
    --------
    >>> round(float(replenishment_factor(3000.0, 68.0, 34.0, 46.0)), 3)
    0.811
    """
    n = np.abs(as_float(speed_rpm))
    nu = as_float(viscosity_mm2_s)
    exponent = (
        k_rs * nu * n * (bore_mm + outside_mm) * np.sqrt(k_z / (2.0 * (outside_mm - bore_mm)))
    )
    result: FloatArray = np.exp(-exponent)
    return result


def hysteresis_rolling_force(
    load: npt.ArrayLike, semi_axis: npt.ArrayLike, rx: float | FloatArray, loss_factor: float
) -> FloatArray:
    r"""Elastic hysteresis rolling resistance of a ball contact [N].

    .. math:: F_h = \frac{3}{16}\,\alpha_h\,\frac{Q\,b}{R_x}

    Johnson's [1]_ result for a sphere rolling on an elastic half-space whose
    material loses the fraction :math:`\alpha_h` of the elastic strain energy
    it stores (the rolling resistance coefficient :math:`3\alpha_h b/16R`,
    after Tabor [2]_): the pressure on the leading half of the contact, whose
    moment about the centre is :math:`3Qb/16` for any Hertz ellipse, does
    work :math:`3Qb/16R_x` per unit distance rolled, with :math:`b` the contact
    semi-axis in the rolling
    direction and :math:`R_x` the effective radius in that direction. The
    power lost is :math:`F_h u`.

    References
    ----------
    .. [1] K. L. Johnson, *Contact Mechanics*, Cambridge University Press,
       1985, §9.2 (rolling resistance from hysteresis).
    .. [2] D. Tabor, "The mechanism of rolling friction. II. The elastic
       range", Proc. R. Soc. A 229 (1955) 198-220, doi:10.1098/rspa.1955.0082.

    Examples
    --------
    A sphere of 3 mm radius at 30 N with a 0.2 mm contact, loss factor 1 %:

    >>> round(float(hysteresis_rolling_force(30.0, 0.2e-3, 3e-3, 0.01)) * 1e3, 4)  # mN
    3.75
    """
    result: FloatArray = (3.0 / 16.0) * loss_factor * as_float(load) * as_float(semi_axis) / rx
    return result


def limiting_traction_coefficient(
    tau0: float, gamma_l: float, mean_pressure: npt.ArrayLike
) -> FloatArray:
    r"""Full-film traction coefficient of a contact sheared at its limiting stress [-].

    .. math:: \mu_{EHL} = \frac{1}{Q}\iint (\tau_0 + \gamma_L p)\,dA
              = \gamma_L + \frac{\tau_0}{\bar p}

    with :math:`\bar p = Q/\pi ab = \tfrac23 p_{max}` the mean Hertz pressure.
    In the spin and differential sliding of a ball screw the lubricant is
    sheared far beyond its Newtonian range (at 10 rpm the spin slides a
    0.8 mm contact at about 0.3 mm/s across a 50 nm film, a shear rate of
    6000/s, while the viscosity at 1 GPa exceeds 10⁵ Pa·s), so it carries its
    limiting shear stress :math:`\tau_0 + \gamma_L p` (Bair & Winer [1]_). For
    mineral oils (:math:`\gamma_L \approx 0.07`) this gives the few
    hundredths that bearing practice uses for full-film sliding (SKF's
    :math:`\mu_{EHL}` = 0.05 for mineral oil, 0.04 for synthetic oils [2]_).

    References
    ----------
    .. [1] S. Bair, W. O. Winer, "A rheological model for elastohydrodynamic
       contacts based on primary laboratory data", J. Lubr. Technol. 101
       (1979) 258-264.
    .. [2] SKF, *Rolling bearings*, catalogue 10000 EN, 2012, p. 105 (sliding
       friction coefficient: :math:`\mu_{EHL}` 0.05 mineral, 0.04 synthetic oil).

    Examples
    --------
    >>> round(float(limiting_traction_coefficient(4e6, 0.04, 1e9)), 4)
    0.044
    """
    p = as_float(mean_pressure)
    safe = where(p > 0.0, p, 1.0)
    result: FloatArray = where(p > 0.0, gamma_l + tau0 / safe, 0.0)
    return result


def mixed_friction_coefficient(
    asperity_share: npt.ArrayLike, boundary: npt.ArrayLike, full_film: npt.ArrayLike
) -> FloatArray:
    r"""Sliding friction coefficient of a mixed-lubricated contact [-].

    .. math:: \mu = \frac{A_c}{A_0}\mu_{bl} + \left(1 - \frac{A_c}{A_0}\right)\mu_{EHL}

    The share :math:`A_c/A_0` of the load carried by asperity contact slides
    at the boundary coefficient, the rest at the full-film traction
    coefficient. The same weighting, with a speed-viscosity weight in place
    of the film-parameter share, is SKF's sliding coefficient [1]_; unlike
    :math:`\mu_0 A_c/A_0` it does not vanish in a thick film.

    References
    ----------
    .. [1] SKF, *Rolling bearings*, catalogue 10000 EN, 2012, p. 105.

    Examples
    --------
    >>> [round(float(mixed_friction_coefficient(s, 0.1, 0.05)), 3) for s in (0.0, 0.5, 1.0)]
    [0.05, 0.075, 0.1]
    """
    s = as_float(asperity_share)
    result: FloatArray = s * as_float(boundary) + (1.0 - s) * as_float(full_film)
    return result


def _disk_rule(
    n_radial: int, n_angle: int, *, half: bool = True
) -> tuple[FloatArray, FloatArray, FloatArray]:
    r"""Nodes X, Y and weights over the unit disk for integrands times sqrt(1-X²-Y²).

    With :math:`\rho = \sin\theta`, :math:`\sqrt{1-\rho^2}\,\rho\,d\rho =
    \cos^2\theta\sin\theta\,d\theta`, smooth on [0, π/2]: Gauss-Legendre in
    :math:`\theta`, midpoint in the angle (the integrand has kinks on the pure-rolling
    lines). With ``half`` the nodes cover X >= 0 only and the weights include the
    factor 2 of the mirrored half (for integrands even in X); otherwise the whole disk.
    """
    t, w_t = np.polynomial.legendre.leggauss(n_radial)
    theta = 0.25 * np.pi * (t + 1.0)
    w_theta = 0.25 * np.pi * w_t * np.cos(theta) ** 2 * np.sin(theta)
    span = np.pi if half else 2.0 * np.pi
    phi = (np.arange(n_angle) + 0.5) * (span / n_angle) - span / 2.0
    rho = np.sin(theta)
    x = (rho[:, None] * np.cos(phi)[None, :]).ravel()
    y = (rho[:, None] * np.sin(phi)[None, :]).ravel()
    w = (w_theta[:, None] * np.full(n_angle, 2.0 * np.pi / n_angle)[None, :]).ravel()
    return x, y, w


_RULE = _disk_rule(12, 48)
_FULL_RULE = _disk_rule(12, 96, half=False)


def spin_sliding_integral(curvature: npt.ArrayLike, aspect: npt.ArrayLike) -> FloatArray:
    r"""Pressure-weighted sliding speed over a Hertz ellipse under spin and Heathcote sliding [-].

    A ball contact with semi-axes :math:`a` (across the groove, :math:`y`)
    and :math:`b` (rolling direction, :math:`x`), pivoting at its centre,
    slides at :math:`v_x = -Cy^2 - \omega_s y`, :math:`v_y = \omega_s x`
    (spin :math:`\omega_s`, differential-sliding coefficient :math:`C`). A
    friction coefficient :math:`\mu` then dissipates

    .. math::
        P = \mu\iint p\,|v|\,dA = \mu\,\frac{3Q}{2\pi}\,|\omega_s|\,a\,I(\kappa, \beta),
        \qquad
        I = \iint_{X^2+Y^2\le1} \sqrt{1-X^2-Y^2}\,
            \sqrt{(\kappa Y^2 + Y)^2 + \beta^2X^2}\,dX\,dY

    with :math:`\kappa = Ca/\omega_s` and :math:`\beta = b/a`. Limits: a
    circle with spin only (:math:`\kappa = 0`, :math:`\beta = 1`) gives
    :math:`I = \pi^2/8` and the spin moment :math:`\tfrac{3\pi}{16}\mu Qa`
    of Lundberg and Johnson [1]_; a long thin ellipse (:math:`\beta \to 0`)
    gives :math:`I = \pi/4` and :math:`\tfrac38\mu Qa`, the end value of
    Houpert's pivoting factor; in between, spin alone gives Harris's
    :math:`\tfrac38\mu QaE(e)` with :math:`E` the complete elliptic integral
    of the second kind of eccentricity :math:`e^2 = 1 - \beta^2`. Spin
    dominates the sliding of ball screw
    contacts, so the contact is taken to pivot about its centre; the uniform
    slip that zero net traction would add changes :math:`P` only to second
    order, since :math:`P` is stationary in the slip there. In ball screw
    contacts (:math:`\kappa \approx 0.35`, :math:`\beta \approx 0.2`) the
    Heathcote term adds only about 0.03 % to the spin's power.

    Parameters
    ----------
    curvature : array_like
        :math:`\kappa` [-], >= 0.
    aspect : array_like
        :math:`\beta = b/a` [-], in (0, 1].

    References
    ----------
    .. [1] K. L. Johnson, *Contact Mechanics*, Cambridge University Press,
       1985, §8.4 (twisting of an elastic sphere: the spin moment of a
       circular contact in full slip).

    Examples
    --------
    >>> round(float(spin_sliding_integral(0.0, 1.0) / (math.pi**2 / 8)), 4)
    1.0
    """
    power, _ = _sliding_quadrature(curvature, aspect, 0.0, force=False)
    return power


def _sliding_quadrature(
    curvature: npt.ArrayLike, aspect: npt.ArrayLike, slip: npt.ArrayLike, *, force: bool
) -> tuple[FloatArray, FloatArray]:
    """Power and (optionally) transverse-force integrals on the disk rule, in bounded chunks."""
    given = (
        np.asarray(curvature, dtype=float),
        np.asarray(aspect, dtype=float),
        np.asarray(slip, dtype=float),
    )
    if given[0].shape == given[1].shape == given[2].shape:
        kappa, beta, sigma = given  # one shape (one point, or a contact each): no broadcast
    else:
        kappa, beta, sigma = np.broadcast_arrays(*given)
    x, y, w = _FULL_RULE if force else _RULE  # with a slip the integrand is not even in X
    flat = [a.reshape(-1) for a in (kappa, beta, sigma)]
    power = np.empty(flat[0].shape)
    side = np.empty(flat[0].shape) if force else power
    step = 4096
    # The sums over the rule's nodes by einsum, not a BLAS product: OpenBLAS's threads
    # would wake for them and spin, costing CPU time (0.13 s of a one-point command).
    for start in range(0, power.size, step):  # bounded memory, not a loop over points
        k, b, sg = (a[start : start + step, None] for a in flat)
        # vx = k y^2 + y, vy = b x + sg, speed = sqrt(vx^2 + vy^2): the same operations in
        # the same order, in place (two temporaries of points x nodes instead of seven).
        vx = k * y
        vx *= y
        vx += y
        vy = b * x
        vy += sg
        speed = np.multiply(vx, vx, out=vx)
        if force:  # vy is wanted below
            speed += vy * vy
        else:
            speed += np.multiply(vy, vy, out=vy)
        np.sqrt(speed, out=speed)
        power[start : start + step] = np.einsum("ij,j->i", speed, w)
        if force:
            share = np.divide(vy, speed, out=np.zeros_like(speed), where=speed > 0.0)
            side[start : start + step] = np.einsum("ij,j->i", share, w)
    result = power.reshape(kappa.shape)
    lateral: FloatArray = (side.reshape(kappa.shape) * (1.5 / math.pi)) if force else result
    return result, lateral


def spin_slip_integrals(
    curvature: npt.ArrayLike, aspect: npt.ArrayLike, slip: npt.ArrayLike
) -> tuple[FloatArray, FloatArray]:
    r"""Power and transverse force of a spinning contact that also slips across the groove [-].

    The contact of :func:`spin_sliding_integral` (spin :math:`\omega_s`,
    Heathcote coefficient :math:`C`, semi-axes :math:`a` across and :math:`b`
    along the rolling direction) slips besides uniformly across the groove at
    :math:`\Delta v`: :math:`v_x = -Cy^2 - \omega_s y`, :math:`v_y = \omega_s x +
    \Delta v`. Sliding everywhere against the local coefficient :math:`\mu`
    (full slip, :math:`\boldsymbol\tau = \mu p\,\mathbf v/|\mathbf v|`), the
    contact dissipates and transmits

    .. math::
        P = \mu\,\frac{3Q}{2\pi}\,|\omega_s|\,a\,J(\kappa,\beta,\sigma),\qquad
        F_y = \mu Q\,G(\kappa,\beta,\sigma)

    .. math::
        J = \iint_{X^2+Y^2\le1}\sqrt{1-X^2-Y^2}\,|\hat{\mathbf v}|\,dX\,dY,\qquad
        G = \frac{3}{2\pi}\iint_{X^2+Y^2\le1}\sqrt{1-X^2-Y^2}\,
            \frac{\beta X + \sigma}{|\hat{\mathbf v}|}\,dX\,dY

    with :math:`\hat{\mathbf v} = (-\kappa Y^2 - Y,\ \beta X + \sigma)`,
    :math:`\kappa = Ca/\omega_s`, :math:`\beta = b/a` and the slip ratio
    :math:`\sigma = \Delta v/(\omega_s a)`. :math:`J(\kappa,\beta,0)` is
    :func:`spin_sliding_integral`; as :math:`\sigma\to\infty`, :math:`G\to1`
    (the whole contact slides one way: :math:`F_y = \mu Q`) and
    :math:`J\to\tfrac{2\pi}{3}\sigma` (:math:`P = \mu Q\Delta v`). In between the
    spin turns part of the friction away from the slip: a spinning contact
    gives less transverse force for a small slip than Coulomb's
    :math:`\mu Q` (the spin-creep coupling of rolling contact mechanics,
    Johnson [1]_ §8.4), and the slip in turn lowers the spin's own
    dissipation. Exact identity, used in the tests: :math:`P = F_y\Delta v +
    M_z\omega_s + (\text{Heathcote})`, with :math:`M_z` the friction moment
    about the normal.

    Parameters
    ----------
    curvature : array_like
        :math:`\kappa` [-], >= 0.
    aspect : array_like
        :math:`\beta = b/a` [-], in (0, 1].
    slip : array_like
        :math:`\sigma` [-], >= 0.

    Returns
    -------
    J, G : numpy.ndarray
        The power and transverse-force integrals [-].

    References
    ----------
    .. [1] K. L. Johnson, *Contact Mechanics*, Cambridge University Press,
       1985, §8.4 (spin and creep in rolling contact; full-slip limits).

    Examples
    --------
    >>> j, g = spin_slip_integrals(0.0, 0.2, [0.0, 1.0, 1e4])
    >>> [round(float(v), 3) for v in g]
    [0.0, 0.921, 1.0]
    >>> round(float(j[2] / 1e4 / (2 * math.pi / 3)), 4)
    1.0
    """
    return _sliding_quadrature(curvature, aspect, slip, force=True)


def meniscus_shear_power(
    viscosity: npt.ArrayLike,
    sliding_speed: npt.ArrayLike,
    radius: npt.ArrayLike,
    gap: npt.ArrayLike,
    inner_radius: npt.ArrayLike = 0.0,
    wetted_radius: npt.ArrayLike | None = None,
) -> FloatArray:
    r"""Power of the Newtonian oil shear between two neighbouring balls that slide [W].

    Two balls of radius :math:`R` face each other across the gap
    :math:`h(r) = h_0 + 2(R - \sqrt{R^2 - r^2})` at the distance :math:`r`
    from their line of centres (:math:`h_0` on that line). Both turn with
    the same angular velocity :math:`\boldsymbol\Omega` perpendicular to the
    line of centres, as the balls of a cage-less train do
    (:func:`ballscrew.kinematics.neighbour_sliding`), so at every point of the
    gap their surfaces move parallel to each other in opposite directions,
    at :math:`\pm\Omega\sqrt{R^2 - r^2}`: their relative speed is
    :math:`v(r) = v_0\sqrt{1 - r^2/R^2}`, :math:`v_0 = 2\Omega R` the
    sliding speed on the line of centres, and their mean (entraining) speed is
    zero everywhere. Reynolds' equation then has no source: the gap builds no
    pressure, so nothing cavitates and the oil is in plain Couette shear at
    ambient pressure, with the shear stress :math:`\tau = \eta v/h` (a
    Newtonian oil: the shear rates, :math:`v/h \approx 10^4` to
    :math:`10^6` /s at 1 to 2 m/s, stay in mineral oils' Newtonian range at
    ambient pressure). The power over the wetted ring
    :math:`r_i \le r \le r_m` is

    .. math::
        P = \eta\int_{r_i}^{r_m}\frac{v(r)^2}{h(r)}\,2\pi r\,dr
          = \frac{2\pi\eta v_0^2}{R^2}\left[G(s)\right]_{s_m}^{s_i},\qquad
        G(s) = -\frac{s^3}{6} - \frac{cs^2}{8} - \frac{c^2s}{8}
               - \frac{c^3}{16}\ln(c - 2s)

    with :math:`s = \sqrt{R^2 - r^2}` and :math:`c = h_0 + 2R` (the integrand
    becomes :math:`s^3/(c - 2s)`, divided out into a polynomial and
    :math:`c^3/8(c - 2s)`). Near the line of centres it is the familiar
    :math:`P \approx \pi\eta v_0^2R\ln(1 + r_m^2/Rh_0)`: logarithmic in the gap,
    so the film thickness :math:`h_0` matters little. The inner radius leaves
    out a disc already counted otherwise (the Hertz contact of balls pressed
    together, whose film is sheared at its limiting stress); outside it the
    gap is taken as that of the undeformed spheres plus :math:`h_0`. The
    Couette profile holds where the gap is thinner than the viscous boundary
    layer of the spinning ball, :math:`\sqrt{\nu/\Omega}` (0.3 to 1 mm for ISO
    VG 68 at 1000 rpm); farther out, where the gap opens past it, the shear is
    that of the ball's boundary layer, of the same order, and the logarithm
    makes that outer ring a small share.

    Derived for this package (the Couette shear of a lubricated gap,
    e.g. Hamrock, Schmid & Jacobson, *Fundamentals of Fluid Film
    Lubrication*, 2nd ed., 2004, ch. 7, applied to two spheres in
    counter-sliding); checked against a numerical integral in
    ``tests/physics/test_flooded_nut.py``.

    Parameters
    ----------
    viscosity : array_like
        Dynamic viscosity of the oil at ambient pressure [Pa·s].
    sliding_speed : array_like
        :math:`v_0`, the balls' relative surface speed on their line of
        centres [m/s] (the sign is ignored).
    radius : array_like
        Ball radius :math:`R` [m].
    gap : array_like
        :math:`h_0`, the gap on the line of centres [m], > 0.
    inner_radius : array_like
        :math:`r_i` [m], 0 by default.
    wetted_radius : array_like, optional
        :math:`r_m` [m], up to :math:`R` (the default: the facing hemispheres
        wetted, as in a nut full of oil).

    Returns
    -------
    numpy.ndarray
        The power dissipated in one gap [W] (0 where :math:`r_m \le r_i`).

    Examples
    --------
    Two 6.35 mm balls of a nut at 1000 rpm (sliding at 2.2 m/s) in mineral ISO VG 68
    at 40 °C (0.058 Pa·s), 0.2 µm apart:

    >>> round(float(meniscus_shear_power(0.058, 2.2, 3.175e-3, 0.2e-6)) * 1e3, 2)  # mW
    23.89
    """
    eta = np.asarray(viscosity, dtype=float)
    v0 = np.abs(np.asarray(sliding_speed, dtype=float))
    r = np.asarray(radius, dtype=float)
    h0 = np.asarray(gap, dtype=float)
    r_in = np.minimum(np.asarray(inner_radius, dtype=float), r)
    r_out = r if wetted_radius is None else np.minimum(np.asarray(wetted_radius, float), r)
    r_out = np.maximum(r_out, r_in)
    c = h0 + 2.0 * r
    s_in = np.sqrt(np.maximum(r * r - r_in * r_in, 0.0))
    s_out = np.sqrt(np.maximum(r * r - r_out * r_out, 0.0))
    # G(s_in) - G(s_out); the logarithms as one log of their ratio (c - 2 s_in >= h0 > 0).
    polynomial = (
        -(s_in**3 - s_out**3) / 6.0 - c * (s_in**2 - s_out**2) / 8.0 - c * c * (s_in - s_out) / 8.0
    )
    logarithm = c**3 / 16.0 * np.log((c - 2.0 * s_out) / (c - 2.0 * s_in))
    result: FloatArray = 2.0 * math.pi * eta * v0**2 / r**2 * (polynomial + logarithm)
    return result


def sphere_drag_coefficient(reynolds: npt.ArrayLike) -> FloatArray:
    r"""Drag coefficient of a smooth sphere in steady flow against its Reynolds number [-].

    .. math::
        C_D = \max\left(\frac{24}{Re}\left(1 + 0.15\,Re^{0.687}\right),\ 0.44\right),
        \qquad Re = \frac{\rho vD}{\eta}

    Schiller and Naumann's [1]_ law, Stokes's :math:`24/Re` corrected for
    inertia, which follows the measured drag curve to :math:`Re \approx 800`,
    joined (where the two meet, :math:`Re \approx 960`) to the constant 0.44 of
    Newton's regime, which the curve keeps within about 10 % up to the drag
    crisis near :math:`Re = 2\cdot10^5` (Clift, Grace & Weber [2]_, who
    tabulate both). The balls of a ball screw in oil have :math:`Re` of 1 to a
    few thousand. Checked against measured values of the standard drag curve in
    ``tests/physics/test_flooded_nut.py``.

    References
    ----------
    .. [1] L. Schiller, A. Naumann, "Über die grundlegenden Berechnungen bei der
       Schwerkraftaufbereitung", Z. Ver. Dtsch. Ing. 77 (1933) 318-320.
    .. [2] R. Clift, J. R. Grace, M. E. Weber, *Bubbles, Drops, and Particles*,
       Academic Press, 1978, ch. 5 (the standard drag curve of rigid spheres).

    Examples
    --------
    >>> [round(float(sphere_drag_coefficient(r)), 3) for r in (1.0, 100.0, 1e4)]
    [27.6, 1.092, 0.44]
    """
    re = np.asarray(reynolds, dtype=float)
    if np.any(~(re > 0.0)):
        from .errors import BallScrewInputError

        raise BallScrewInputError("reynolds", re, "a Reynolds number above 0")
    result: FloatArray = np.maximum(24.0 / re * (1.0 + 0.15 * re**0.687), 0.44)
    return result


def ball_churning_power(
    viscosity: npt.ArrayLike,
    density: npt.ArrayLike,
    speed: npt.ArrayLike,
    diameter: npt.ArrayLike,
) -> FloatArray:
    r"""Power a ball loses to the drag of the oil it moves through [W].

    .. math::
        P = F_Dv = \tfrac12 C_D(Re)\,\rho\,\frac{\pi D_w^2}{4}\,v^3,\qquad
        Re = \frac{\rho vD_w}{\eta}

    The ball moves through the oil at the speed :math:`v` (a ball screw's: the
    orbital speed of the ball centre relative to the nut, the oil taken at rest
    in the nut), against the drag of a sphere in steady flow with
    :func:`sphere_drag_coefficient`. The same form is the ball drag of
    high-speed ball bearings (Harris & Kotzalas [1]_, with the density of the
    oil-air mixture inside the bearing; here the nut is full of oil). The
    neighbours of a ball in a train shield it from part of the flow, and the
    screw drags the oil along with it: both make the free-sphere value an upper
    bound.

    Parameters
    ----------
    viscosity : array_like
        Dynamic viscosity of the oil [Pa·s], > 0.
    density : array_like
        Density of the oil [kg/m³].
    speed : array_like
        Speed of the ball through the oil [m/s] (the sign is ignored).
    diameter : array_like
        Ball diameter :math:`D_w` [m].

    Returns
    -------
    numpy.ndarray
        [W]; 0 at zero speed.

    References
    ----------
    .. [1] T. A. Harris, M. N. Kotzalas, *Rolling Bearing Analysis: Advanced
       Concepts of Bearing Technology*, 5th ed., CRC Press, 2007 (the fluid
       drag on the balls of a high-speed ball bearing).

    Examples
    --------
    A 6.35 mm ball at 1.05 m/s in mineral ISO VG 68 at 40 °C:

    >>> round(float(ball_churning_power(0.058, 858.0, 1.05, 6.35e-3)) * 1e3, 2)  # mW
    17.28
    """
    eta = np.asarray(viscosity, dtype=float)
    rho = np.asarray(density, dtype=float)
    v = np.abs(np.asarray(speed, dtype=float))
    d = np.asarray(diameter, dtype=float)
    moving = v > 0.0
    reynolds = np.where(moving, rho * np.where(moving, v, 1.0) * d / eta, 1.0)
    drag = sphere_drag_coefficient(reynolds)
    result: FloatArray = np.where(moving, 0.5 * drag * rho * 0.25 * math.pi * d * d * v**3, 0.0)
    return result
