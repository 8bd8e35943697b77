r"""Olaru et al.'s (2005) ball screw friction model.

Each ball is in equilibrium under the forces and moments at its screw (s)
and nut (n) contacts; without integrating the shear stress over the contact
ellipses, the model gives the tangential (sliding) force at each contact,
and the torque follows from the forces at the screw contacts. Per contact
:math:`j`, with :math:`U_j, W_j, G` the Hamrock-Dowson groups and
:math:`k_j = R_{y}/R_{x,j}`:

.. math::
    F_{R,j} &= 2.86\,E'R_{x,j}^2\,k_j^{0.348}G^{0.022}U_j^{0.66}W_j^{0.47}
        &&\text{EHL rolling force (Houpert)}\\
    M_{C,j} &= 0.0806\,\mu Q\,\frac{a_j^2}{R_a}\,f_c(E_j)
        &&\text{curvature (differential sliding) moment}\\
    M_{P,j} &= \tfrac38\,\mu Q\,a_j\,f_p(E_j)
        &&\text{pivoting (spin) moment}\\
    M_{ER,j} &= 7.48\cdot10^{-7}(D_w/2)^{0.33}Q^{1.33}
        [1 - 3.519\cdot10^{-3}(k_j - 1)^{0.806}]
        &&\text{elastic hysteresis}\\
    M_B &= \mu_b\,(D_w/2)\,F_B &&\text{ball-ball friction}

with :math:`R_a = (D_w/2)(1+\kappa)/(1+\kappa/2)`, :math:`E_j =
(2R_a/a_j)(D_w\sin\alpha/d_m)` and Houpert's fits
:math:`f_c = 1.0026 - 0.1653E - 0.2638E^2 - 2.5521E^3 + 1.9749E^4`,
:math:`f_p = 0.0042 + 1.1045E + 0.4625E^2 - 0.5648E^3`. Ball equilibrium
gives the tangential force at the screw contact

.. math::
    F_S = \frac{M_{C,n} + M_{C,s} + M_{ER,n} + M_{ER,s} + M_B}{D_w}
          + (F_{R,n} + F_{R,s})(1 + \gamma) + \frac{F_B}{2}

and the torque :math:`T = \sum F_S R_s\cos\lambda` over the loaded balls of
each (half-)nut (the forces act along the helix; :math:`\cos\lambda`
projects them on the circumference).

Decisions on the doubts of the public copies of the model (the study's
description and a public implementation; Olaru's paper was not available):

* **Typo.** The hysteresis bracket is read :math:`3.519\cdot10^{-3}`, not the
  ``3.519e-36`` of the public code (which would make the bracket exactly 1).
* **Units of** :math:`M_{ER}`. Read in SI (:math:`D_w` in m, :math:`Q` in N,
  moment in N·m), the coefficient implies a hysteresis loss factor of about
  0.02 to 0.04; read in mm and N·mm, about :math:`3\cdot10^{-4}`. Steel's
  loss factor is of order 0.005 to 0.01, between the two; the public code
  feeds SI values, so SI is the default and ``hysteresis_units="N·mm"`` the
  alternative. Either way the term is small beside the rolling forces.
* :math:`k` **in** :math:`F_R` is the radius ratio :math:`R_y/R_x` (the
  public code's ``K``; Houpert's contact fits use the same ratio), not the
  ellipticity.
* **The fits** :math:`f_c, f_p` are Houpert's over :math:`0 \le E \le 1`
  (:math:`f_c` falls from 1 to 0, :math:`f_p` rises from 0 to 1). Ball
  screws have :math:`E \approx 2` to 3 (spin-dominated contacts), where the
  polynomials diverge; :math:`E` is therefore clipped to [0, 1], i.e. the
  fits' end values :math:`f_c = 0`, :math:`f_p = 1` are used beyond.
* **The pivoting moment.** The public code leaves :math:`M_P` out of
  :math:`F_S`; since :math:`f_c \to 0` for spin-dominated contacts, doing so
  would leave the model no sliding loss where sliding loss is largest. Here
  it enters by its dissipated power, :math:`\Delta T = \sum M_{P,j}
  |\omega_{s,j}|/|\omega|` (``include_pivoting=True``, default); set it to
  False to follow the public code.
* **The ball-ball force** :math:`F_B` is not defined in any available copy
  (the public code puts :math:`1/Z` N as a placeholder); it is an input,
  default 0 N (balls that do not push each other).
* **The sliding friction coefficient** follows the study's reading of Olaru:
  :math:`\mu = \mu_0 A_c/A_0` with :math:`A_c/A_0 = \exp(-B\Lambda^C)`
  (``sliding_friction="asperity"``); the public code's empirical fit
  :math:`\mu = \exp(-2.643 - 0.002n - 4.983\cdot10^{-7}n^2)` (:math:`n` in
  rpm, attributed there to Hoeprich) is ``sliding_friction="speed-fit"``.

References
----------
.. [1] D. Olaru, G. C. Puiu, L. C. Balan, V. Puiu, "A new model to estimate
   friction torque in a ball screw system", in *Product Engineering*,
   Springer, 2005, pp. 333-346, doi:10.1007/1-4020-2933-0_20.
.. [2] L. Houpert, "Ball bearing and tapered roller bearing torque:
   analytical, numerical and experimental results", Tribol. Trans. 45 (2002)
   345-353, doi:10.1080/10402000208982559.
.. [3] L. Houpert, "Numerical and analytical calculations in ball bearings",
   Proc. Congrès Roulements, Toulouse, 1999.
"""

from __future__ import annotations

import math
from typing import Any, Literal

import numpy as np
import numpy.typing as npt

from ..contact import hertz
from ..errors import BallScrewInputError, FloatArray, check_choice, check_nonnegative
from ..geometry import BallScrew
from ..kinematics import rad_s_to_rpm
from ..loads import ball_loads
from ..lubricant import Lubricant
from ..rolling_losses import rolling_force_houpert
from ..state import ContactState, OperatingState
from ..validity import ValidityIssue, ValidityRange, film_checks, outside
from ._common import model_state
from ._registry import register

__all__ = [
    "SPIN_PARAMETER_RANGE",
    "curvature_fit",
    "elastic_hysteresis_moment",
    "olaru",
    "pivoting_fit",
]


def curvature_fit(e: npt.ArrayLike) -> FloatArray:
    r"""Houpert's curvature-moment factor :math:`f_c(E)`, with :math:`E` clipped to [0, 1].

    >>> [round(float(curvature_fit(x)), 4) for x in (0.0, 0.5, 3.0)]
    [1.0026, 0.6584, 0.0]
    """
    x = np.clip(np.asarray(e, dtype=float), 0.0, 1.0)
    result: FloatArray = np.maximum(
        1.0026 - 0.1653 * x - 0.2638 * x**2 - 2.5521 * x**3 + 1.9749 * x**4, 0.0
    )
    return result


def pivoting_fit(e: npt.ArrayLike) -> FloatArray:
    r"""Houpert's pivoting-moment factor :math:`f_p(E)`, with :math:`E` clipped to [0, 1].

    >>> [round(float(pivoting_fit(x)), 4) for x in (0.0, 0.5, 3.0)]
    [0.0042, 0.6015, 1.0064]
    """
    x = np.clip(np.asarray(e, dtype=float), 0.0, 1.0)
    result: FloatArray = 0.0042 + 1.1045 * x + 0.4625 * x**2 - 0.5648 * x**3
    return result


def elastic_hysteresis_moment(
    ball_diameter: float, load: npt.ArrayLike, radius_ratio: float, units: str = "SI"
) -> FloatArray:
    r"""Elastic hysteresis rolling moment of a ball contact [N·m].

    .. math:: M_{ER} = 7.48\cdot10^{-7}(D_w/2)^{0.33}Q^{1.33}[1 - 3.519\cdot10^{-3}(k-1)^{0.806}]

    ``units="SI"`` evaluates it with :math:`D_w` in m and returns N·m;
    ``units="N·mm"`` with :math:`D_w` in mm, reading the result as N·mm
    (converted to N·m). See the module docstring for the choice.

    Examples
    --------
    >>> round(float(elastic_hysteresis_moment(6.35e-3, 29.0, 12.0)) * 1e6, 3)  # µN·m
    9.633
    """
    q = np.asarray(load, dtype=float)
    bracket = 1.0 - 3.519e-3 * max(radius_ratio - 1.0, 0.0) ** 0.806
    if bracket < 0.0:
        # Past a radius ratio of about 1109 (a conformity within about 1e-4 of 0.5) the
        # fit gives a negative hysteresis: outside what it was fitted to.
        raise BallScrewInputError(
            "radius_ratio",
            radius_ratio,
            "at most about 1109 for the hysteresis fit (its bracket turns negative beyond): "
            "a groove conformity this close to 0.5 is outside Olaru's model",
        )
    if units == "SI":
        result: FloatArray = 7.48e-7 * (ball_diameter / 2.0) ** 0.33 * q**1.33 * bracket
        return result
    if units == "N·mm":
        result = 7.48e-7 * (ball_diameter * 1e3 / 2.0) ** 0.33 * q**1.33 * bracket * 1e-3
        return result
    raise BallScrewInputError("hysteresis_units", units, "'SI' or 'N·mm'")


SPIN_PARAMETER_RANGE = ValidityRange(
    "spin parameter E (Olaru)",
    0.0,
    1.0,
    "Houpert's f_c, f_p fits in Olaru's model",
    "the fits' interval; beyond it their end values are used",
)
"""Where Houpert's curvature and pivoting fits hold."""


def spin_parameter_check(
    screw: BallScrew, lubricant: Lubricant, speed: FloatArray, temperature: FloatArray,
    axial_load: FloatArray, parameters: dict[str, Any],
) -> list[ValidityIssue]:  # fmt: skip
    """Houpert's spin parameter :math:`E` of the model at the extreme ball loads."""
    kappa = float(parameters.get("kappa", 0.05))
    ra = 0.5 * screw.ball_diameter * (1.0 + kappa) / (1.0 + 0.5 * kappa)
    spin = screw.ball_diameter * math.sin(screw.contact_angle) / screw.pitch_diameter
    loads = ball_loads(screw, np.array([0.0, float(np.max(np.abs(axial_load)))]))
    q = np.concatenate([loads.normal_load_1, loads.normal_load_2])
    q = q[q > 0.0]
    if not q.size:
        return []
    method = str(parameters.get("hertz_method", "houpert"))
    values: list[float] = []
    for rx, ry in ((screw.rx_screw, screw.ry_screw), (screw.rx_nut, screw.ry_nut)):
        a = hertz(q, rx, ry, screw.reduced_modulus, method=method).a
        values += [float(v) for v in 2.0 * ra / a * spin]
    return outside(SPIN_PARAMETER_RANGE, values)


@register(
    "olaru",
    title="Olaru et al. (2005): per-ball equilibrium of EHL rolling forces and friction moments",
    reference="D. Olaru et al., A new model to estimate friction torque in a ball screw system, "
    "Product Engineering, Springer 2005, doi:10.1007/1-4020-2933-0_20",
    validity="2-point contact; Houpert (2002) EHL rolling force fit; f_c, f_p fits for E in [0, 1]",
    purpose="to reproduce the study (Sušeň's Fig. 3); not for prediction",
    checks=(film_checks, spin_parameter_check),
)
def olaru(
    screw: BallScrew, lubricant: Lubricant, speed: FloatArray, temperature: FloatArray,
    axial_load: FloatArray, *, state: OperatingState | None = None,
    mu0: float = 0.1,
    sliding_friction: str = "asperity",
    asperity_b: float = 1.42,
    asperity_c: float = 0.8,
    kappa: float = 0.05,
    ball_ball_force: float = 0.0,
    ball_ball_friction: float = 0.1,
    include_pivoting: bool = True,
    hysteresis_units: str = "SI",
    hertz_method: str = "houpert",
) -> dict[str, FloatArray]:  # fmt: skip
    r"""Friction torque by Olaru et al.'s model (decisions: module docstring).

    Parameters
    ----------
    screw, lubricant, speed, temperature, axial_load
        The operating points (see :func:`ballscrew.friction_torque`).
    mu0 : float
        :math:`\mu_0` of :math:`\mu = \mu_0 A_c/A_0`; 0.1 (the study's value).
    sliding_friction : {"asperity", "speed-fit"}
        How :math:`\mu` is found.
    asperity_b, asperity_c : float
        :math:`B`, :math:`C` of :math:`A_c/A_0`.
    kappa : float
        :math:`\kappa` of :math:`R_a`; 0.05 (typical, 0.02 to 0.1).
    ball_ball_force : float
        :math:`F_B` [N]; 0 by default.
    ball_ball_friction : float
        :math:`\mu_b`; 0.1 (public code).
    include_pivoting : bool
        Add the spin power of :math:`M_P` (default True).
    hysteresis_units : {"SI", "N·mm"}
        Reading of the :math:`M_{ER}` coefficient.
    hertz_method : str
        Default ``"houpert"`` (as Olaru).

    Returns
    -------
    dict
        ``"rolling"``, ``"curvature"``, ``"hysteresis"``, ``"pivoting"``,
        ``"ball_ball"`` torques [N·m].
    """
    check_choice("sliding_friction", sliding_friction, ("asperity", "speed-fit"))
    check_nonnegative("mu0", mu0)
    check_nonnegative("ball_ball_force", ball_ball_force, "N")
    check_nonnegative("ball_ball_friction", ball_ball_friction)
    check_nonnegative("kappa", kappa)
    state = model_state(
        screw, lubricant, speed, temperature, axial_load, hertz_method=hertz_method,
        asperity_b=asperity_b, asperity_c=asperity_c, state=state,
    )  # fmt: skip
    dw = screw.ball_diameter
    gamma = screw.gamma
    ra = 0.5 * dw * (1.0 + kappa) / (1.0 + 0.5 * kappa)
    spin_ratio = dw * math.sin(screw.contact_angle) / screw.pitch_diameter
    lever = screw.contact_radius_screw * math.cos(screw.lead_angle)
    omega = np.abs(state.kinematics.screw_speed)
    rpm = rad_s_to_rpm(omega)
    spin_per_speed = _spin_per_speed(screw)

    zeros = np.zeros(state.shape)
    parts = {
        k: zeros.copy() for k in ("rolling", "curvature", "hysteresis", "pivoting", "ball_ball")
    }
    for family in (1, 2):
        pair = {c.side: c for c in state.contacts if c.family == family}
        screw_c = pair["screw"]
        balls = screw_c.balls  # a 4-point ball is listed in both families already
        if balls == 0:
            continue
        q = screw_c.load
        mus = _friction_coefficients(pair, sliding_friction, mu0, rpm)
        f_r, m_c, m_er, pivot_power_per_speed = _ball_forces(
            screw, pair, mus, ra, spin_ratio, spin_per_speed, hysteresis_units, state.shape
        )
        loaded = q > 0.0
        m_b = ball_ball_friction * 0.5 * dw * ball_ball_force
        parts["rolling"] += balls * lever * f_r * (1.0 + gamma)
        parts["curvature"] += balls * lever * m_c / dw
        parts["hysteresis"] += balls * lever * m_er / dw
        parts["ball_ball"] += np.where(
            loaded, balls * lever * (m_b / dw + 0.5 * ball_ball_force), 0.0
        )
        if include_pivoting:
            parts["pivoting"] += balls * pivot_power_per_speed
    return parts


_Side = Literal["screw", "nut"]


def _friction_coefficients(
    pair: dict[_Side, ContactState], sliding_friction: str, mu0: float, rpm: FloatArray
) -> dict[str, FloatArray]:
    r"""The sliding friction coefficient :math:`\mu` of each contact of a ball, by side."""
    if sliding_friction == "asperity":
        return {side: mu0 * c.asperity_share for side, c in pair.items()}
    mu_fit = np.exp(-2.643 - 0.002 * rpm - 4.983e-7 * rpm**2)
    return {"screw": mu_fit, "nut": mu_fit}


def _ball_forces(
    screw: BallScrew,
    pair: dict[_Side, ContactState],
    mus: dict[str, FloatArray],
    ra: float,
    spin_ratio: float,
    spin_per_speed: dict[str, float],
    hysteresis_units: str,
    shape: tuple[int, ...],
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    r"""One ball's rolling force, curvature and hysteresis moments, and pivoting power.

    Sums over the ball's two contacts: :math:`F_R` [N], :math:`M_C` and
    :math:`M_{ER}` [N·m], and the pivoting power per unit screw speed
    :math:`M_P \omega_s/|\omega|` [N·m].
    """
    dw = screw.ball_diameter
    q = pair["screw"].load
    f_r: FloatArray = np.zeros(shape)
    m_c: FloatArray = np.zeros(shape)
    m_er: FloatArray = np.zeros(shape)
    pivot_power_per_speed: FloatArray = np.zeros(shape)
    for side, c in pair.items():
        ratio = float(c.ry) / float(c.rx)  # one screw: this model takes no ScrewArray
        f_r = f_r + rolling_force_houpert(
            screw.reduced_modulus,
            c.rx,
            ratio,
            c.materials_parameter,
            c.speed_parameter,
            c.load_parameter,
        )
        a = c.hertz.a
        with np.errstate(divide="ignore"):
            e = np.where(a > 0.0, 2.0 * ra / np.where(a > 0, a, 1.0) * spin_ratio, 0.0)
        m_c = m_c + 0.0806 * mus[side] * q * a**2 / ra * curvature_fit(e)
        m_er = m_er + elastic_hysteresis_moment(dw, q, ratio, hysteresis_units)
        m_p = 0.375 * mus[side] * q * a * pivoting_fit(e)
        pivot_power_per_speed = pivot_power_per_speed + m_p * spin_per_speed[side]
    return f_r, m_c, m_er, pivot_power_per_speed


def _spin_per_speed(screw: BallScrew) -> dict[str, float]:
    r""":math:`|\omega_s|/|\omega|` at each contact, by side.

    The bearing kinematics of Olaru's paper, which neglects the helix
    (:mod:`ballscrew.kinematics` keeps it; the spin differs by
    :math:`\cos\lambda`).
    """
    gamma = screw.gamma
    return {
        "screw": 0.5 * (1.0 + gamma) * math.sin(screw.contact_angle),
        "nut": 0.5 * (1.0 - gamma) * math.sin(screw.contact_angle),
    }
