r"""Speed limits of a ball screw: the shaft's critical speed and the nut's d·n value.

**Bounds of any operating point.** Far past any ball screw, so that nothing
absurd reaches the models (:func:`check_operating_bounds`): a speed below
:data:`MAX_SPEED` (about a million rpm), a temperature from absolute zero to
:data:`MAX_TEMPERATURE` (no lubricant survives more) and an axial load below
:data:`MAX_FORCE` (100 MN) in either direction.

**Critical speed.** A rotating shaft whips when its speed reaches the first
bending natural frequency. For a uniform Euler-Bernoulli beam of span
:math:`L` with the section of the thread's root, :math:`d_r`:

.. math::
    \omega_c = \frac{\lambda^2}{L^2}\sqrt{\frac{E I}{\rho A}}
             = \frac{\lambda^2 d_r}{4 L^2}\sqrt{\frac{E}{\rho}},

with :math:`\lambda` the first eigenvalue of the end conditions: 1.8751
(fixed-free), :math:`\pi` (supported-supported), 3.9266 (fixed-supported),
4.7300 (fixed-fixed) (e.g. Blevins, *Formulas for Natural Frequency and Mode
Shape*, Table 8-1). Ball screw makers allow 80 % of it; with steel
(:math:`E` = 206 GPa, :math:`\rho` = 7850 kg/m³) this is their rule
:math:`n = f\,d_r/L^2\cdot 10^7` rpm (mm) with :math:`f` = 3.4, 9.7, 15.1,
21.9 for the four mountings.

**Root diameter.** A gothic-arch groove of radius :math:`r = f d_b` whose
arcs touch the ball at the contact angle :math:`\alpha` has its centres
:math:`e = r - d_b/2` from the ball's centre along the contact lines; its
bottom lies :math:`\sqrt{r^2 - e^2\sin^2\alpha} - e\cos\alpha` inside the
ball's centre, so :math:`d_r = d_m - 2(\sqrt{r^2 - e^2\sin^2\alpha} -
e\cos\alpha)` (:math:`d_m - d_b` for a groove that fits the ball). Give the
catalogue's root diameter where you have it.

**d·n.** The ball return limits the ball speed; catalogues state it as the
product of the nominal diameter [mm] and the speed [rpm]; here the ball
centre (pitch) diameter stands for it, the nearest the geometry holds. Typical limits:
about 70 000–76 000 for standard external returns and 130 000–160 000 for
internal deflectors and high-speed nuts (the screw's catalogue has its own).
"""

from __future__ import annotations

import math
from typing import Literal

import numpy.typing as npt

from ..errors import BallScrewInputError, FloatArray, check_in_range, check_positive
from ..geometry import BallScrew
from ..kinematics import rad_s_to_rpm

__all__ = [
    "DEFAULT_DN_LIMIT",
    "MAX_FORCE",
    "MAX_SPEED",
    "MAX_TEMPERATURE",
    "SUPPORT_EIGENVALUES",
    "Support",
    "check_operating_bounds",
    "critical_speed",
    "root_diameter",
    "speed_limit_issues",
]

MAX_SPEED = 1e5
"""The largest screw speed any model is asked for [rad/s] (about 955 000 rpm)."""
MAX_TEMPERATURE = 500.0
"""The highest lubricant temperature [°C]."""
MAX_FORCE = 1e8
"""The largest axial load [N] (the preload's bound is :data:`ballscrew.geometry.MAX_PRELOAD`)."""


def check_operating_bounds(
    speed: npt.ArrayLike, temperature: npt.ArrayLike, axial_load: npt.ArrayLike, prefix: str = ""
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Speed [rad/s], temperature [°C] and axial load [N] as float arrays, each within its bound.

    ``prefix`` goes before the field named in an error (``"operation."`` for a
    case file's keys).

    Examples
    --------
    >>> check_operating_bounds(2e5, 20.0, 0.0)
    Traceback (most recent call last):
    ...
    ballscrew.errors.BallScrewInputError: speed = 200000.0 is not allowed: a value in (-100000, 100000) rad/s (about a million rpm at most)
    """  # noqa: E501
    w = check_in_range(
        f"{prefix}speed", speed, -MAX_SPEED, MAX_SPEED, unit="rad/s (about a million rpm at most)"
    )
    t = check_in_range(
        f"{prefix}temperature", temperature, -273.15, MAX_TEMPERATURE,
        unit="°C (above absolute zero, at most 500 °C: no lubricant survives more)",
    )  # fmt: skip
    fa = check_in_range(
        f"{prefix}axial_load", axial_load, -MAX_FORCE, MAX_FORCE, unit="N (at most 100 MN)"
    )
    return w, t, fa


Support = Literal["fixed-free", "supported-supported", "fixed-supported", "fixed-fixed"]

SUPPORT_EIGENVALUES: dict[str, float] = {
    "fixed-free": 1.87510,
    "supported-supported": math.pi,
    "fixed-supported": 3.92660,
    "fixed-fixed": 4.73004,
}
r"""First bending eigenvalue :math:`\lambda` of a uniform beam by end conditions [-]."""

SAFETY_FACTOR = 0.8
"""Share of the critical speed ball screw makers allow [-]."""

DEFAULT_DN_LIMIT = 70_000.0
"""d·n limit [mm·rpm] assumed when none is given: a standard nut with external return."""

STEEL = {"youngs_modulus": 206e9, "density": 7850.0}
"""Steel as ball screw catalogues take it for the critical speed: E [Pa], rho [kg/m³]."""


def root_diameter(screw: BallScrew) -> float:
    """Root diameter of the screw's thread [m] from the gothic-arch groove.

    Examples
    --------
    The reference screw (40 mm, 6.35 mm balls, conformity 0.55, 45°): a
    root of 33.48 mm, a little below ``d_m - d_b`` = 33.65 mm, the limit of a
    groove that fits the ball:

    >>> from ballscrew import reference_screw
    >>> round(root_diameter(reference_screw()) * 1e3, 2)
    33.48
    """
    r = screw.conformity_screw * screw.ball_diameter
    e = r - 0.5 * screw.ball_diameter
    a = screw.contact_angle
    depth = math.sqrt(r * r - (e * math.sin(a)) ** 2) - e * math.cos(a)
    return screw.pitch_diameter - 2.0 * depth


def critical_speed(
    diameter: npt.ArrayLike,
    span: npt.ArrayLike,
    support: str = "fixed-supported",
    *,
    youngs_modulus: float = STEEL["youngs_modulus"],
    density: float = STEEL["density"],
) -> FloatArray:
    r"""First bending critical speed of the screw shaft [rad/s] (no safety factor).

    :math:`\omega_c = \lambda^2 d_r \sqrt{E/\rho} / (4 L^2)`.

    Parameters
    ----------
    diameter : array_like
        Root diameter :math:`d_r` [m].
    span : array_like
        Distance between the supports :math:`L` [m].
    support : str
        A key of :data:`SUPPORT_EIGENVALUES`.

    Examples
    --------
    A 33.5 mm root over 1 m, fixed-supported: 80 % of it is close to the
    catalogue rule's 15.1 * 33.5 / 1000**2 * 1e7 = 5059 rpm (its factor is
    rounded to three digits).

    >>> round(0.8 * float(rad_s_to_rpm(critical_speed(0.0335, 1.0))))
    5053
    """
    if support not in SUPPORT_EIGENVALUES:
        raise BallScrewInputError("support", support, f"one of {list(SUPPORT_EIGENVALUES)}")
    d = check_positive("root_diameter", diameter, "m")
    span_m = check_positive("bearing_span", span, "m")
    lam = SUPPORT_EIGENVALUES[support]
    e = float(check_positive("youngs_modulus", youngs_modulus, "Pa"))
    rho = float(check_positive("density", density, "kg/m^3"))
    result: FloatArray = lam**2 * d * math.sqrt(e / rho) / (4.0 * span_m**2)
    return result


def speed_limit_issues(
    screw: BallScrew,
    max_speed: float,
    *,
    span: float | None = None,
    support: str = "fixed-supported",
    dn_limit: float = DEFAULT_DN_LIMIT,
    root: float | None = None,
) -> list[str]:
    """Messages for a screw speed [rad/s] above 80 % of the critical speed or the d·n limit.

    ``span`` [m] is the distance between the supports (None: critical speed
    not checked), ``root`` [m] the root diameter (None: :func:`root_diameter`),
    ``dn_limit`` in mm·rpm.
    """
    rpm = float(rad_s_to_rpm(abs(max_speed)))
    out: list[str] = []
    dn = screw.pitch_diameter * 1e3 * rpm
    if dn > dn_limit:
        out.append(
            f"d·n = {dn:,.0f} mm·rpm at {rpm:,.0f} rpm exceeds the limit {dn_limit:,.0f}: "
            "the ball return may be damaged; lower the feed, take a longer lead, or give "
            "axis.dn_limit from your screw's catalogue"
        )
    if span is not None:
        d_r = root_diameter(screw) if root is None else root
        allowed = SAFETY_FACTOR * float(rad_s_to_rpm(critical_speed(d_r, span, support)))
        if rpm > allowed:
            out.append(
                f"{rpm:,.0f} rpm exceeds 80 % of the shaft's critical speed ({allowed:,.0f} rpm "
                f"for a {support} span of {span * 1e3:g} mm, root diameter {d_r * 1e3:.3g} mm): "
                "the screw will whip; shorten the span, stiffen the mounting or lower the feed"
            )
    return out
