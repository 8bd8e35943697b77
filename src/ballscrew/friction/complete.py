r"""The complete loss budget of a lubricated ball screw: the predictive model.

Every mechanism that dissipates power in the ball contacts of a ball screw,
each a named component of the result, each from a published law
(:mod:`ballscrew.rolling_losses`), added up over the loaded balls:

``"rolling"``
    EHL rolling resistance: Houpert's hydrodynamic rolling force
    :math:`F_R` on both surfaces of every contact, :math:`P = 2F_Ru`,
    reduced at high speed by SKF's inlet shear heating and kinematic
    replenishment factors. It carries the speed and viscosity dependence,
    :math:`\propto (\eta u)^{0.66}Q^{0.47}`.
``"sliding"``
    Spin and differential (Heathcote) sliding over each Hertz ellipse,
    :math:`P = \mu\iint p|v|\,dA`, with the mixed-film coefficient
    :math:`\mu = (A_c/A_0)\mu_{bl} + (1 - A_c/A_0)\mu_{EHL}`, where
    :math:`\mu_{EHL} = \gamma_L + \tau_0/\bar p` is the lubricant's limiting
    shear (the oil in these contacts is sheared far past its Newtonian range).
``"hysteresis"``
    Elastic hysteresis of the steel, Johnson's :math:`F_h = \tfrac{3}{16}
    \alpha_h Qb/R_x`, :math:`P = F_hu`.
``"ball_ball"``
    Sliding between neighbouring balls. A ball screw has no cage: adjacent
    balls turn the same way, so their surfaces meet at opposite velocities and
    slide at :math:`\omega_bD_w`, with no entraining motion to build a film
    (boundary friction :math:`\mu_{bl}`). The force between them, the
    ball-train force, arises because the balls do not all want the same
    orbital speed (their loads, contact angles and diameters differ) and push
    each other up to a share of the traction their grooves can give; it is
    taken proportional to the ball load, :math:`F_B = c_B\sum Q`, with one
    global constant :math:`c_B` (:data:`BALL_TRAIN_CONSTANT`), the only
    constant of the model that physics does not give. Then :math:`P =
    \mu_{bl}c_B\sum_j Z_jQ_j\,\omega_bD_w`.
``"four_point"``
    Only for ``nut="single-4point"``: the extra spin sliding that the
    kinematic conflict of a 4-point contact forces
    (:func:`ballscrew.kinematics.four_point_spin`): the ball must turn about
    an axis parallel to the screw axis.
``"seals"``
    A wiper or seal drag torque given by the user (``seal_torque``), 0 by
    default: catalogue drag torques are measured without wipers.

The torque on the screw is the dissipated power over the screw speed,
:math:`T = P/|\omega|`; every power above is proportional to the speed at
fixed contact state, so the ratio is evaluated directly and stays finite at
zero speed. Oil churning in a bath is not modelled (ball screws run on
circulating oil, oil-air or grease).

The ball-train constant was fitted once on the training set of
:mod:`ballscrew.validation` (see :data:`BALL_TRAIN_CONSTANT`) and is never
changed per case.
"""

from __future__ import annotations

import math

import numpy as np

from .. import rolling_losses as rl
from ..errors import FloatArray, check_choice, check_nonnegative
from ..geometry import BallScrew
from ..kinematics import differential_sliding, four_point_spin, kinematics
from ..lubricant import Lubricant
from ..state import ContactState, operating_state
from ..validity import film_checks
from ._common import limiting_shear
from ._registry import register

__all__ = ["BALL_TRAIN_CONSTANT", "HYSTERESIS_LOSS_FACTOR", "complete"]

BALL_TRAIN_CONSTANT: float = 0.0474
r"""Ball-train force over the ball load, :math:`c_B = F_B/Q` [-].

Fitted once (``scripts/fit_ball_train.py``) on the training cases of
:mod:`ballscrew.validation`; its training set (10 double nuts at 5 % of their load
rating) and scatter (the value matching each training case alone spreads over
0.030 to 0.072, 16 to 84 %) are in the README and ``docs/models.md``.
"""

HYSTERESIS_LOSS_FACTOR: float = 0.007
r"""Hysteresis loss factor :math:`\alpha_h` of hardened bearing steel [-].

Johnson (Contact Mechanics, 1985, §9.2) puts the loss factor of hard metals at
1 % or less; 0.7 % is the value commonly quoted for 52100 steel after
Drutowski's rolling-ball measurements (J. Basic Eng. 81 (1959) 233), which
could not be checked in the original. The term is 0.4 % of the reference
screw's torque, so the choice hardly matters.
"""

_K_RS = {"oil": 3e-8, "grease": 6e-8}


DIRECT_INTEGRALS: int = 256
"""Up to this many distinct (kappa, aspect) pairs the sliding integral is
evaluated directly; above, it is interpolated (:func:`_interpolated_integral`)."""


def _unique_integral(kappa: FloatArray, aspect: FloatArray) -> FloatArray:
    """:func:`spin_sliding_integral` evaluated once per distinct (kappa, aspect) pair."""
    kappa, aspect = np.broadcast_arrays(kappa, aspect)
    pairs = np.stack([kappa, aspect], axis=-1).reshape(-1, 2)
    unique, inverse = np.unique(pairs, axis=0, return_inverse=True)
    if len(unique) <= DIRECT_INTEGRALS:
        values = rl.spin_sliding_integral(unique[:, 0], unique[:, 1])
    else:
        values = _interpolated_integral(unique[:, 0], unique[:, 1])
    result: FloatArray = values[inverse.reshape(-1)].reshape(kappa.shape)
    return result


def _interpolated_integral(kappa: FloatArray, aspect: FloatArray) -> FloatArray:
    r""":func:`spin_sliding_integral` through a cubic spline over the points' range.

    Many distinct loads (a motion cycle, scattered points) give many
    distinct :math:`\kappa` (it grows as :math:`Q^{1/3}`), while
    :math:`\beta = b/a` hardly varies (Hertz's ellipticity does not depend
    on the load). The integral, smooth in both, is evaluated on a 65 x 17
    grid spanning the points (65 nodes when :math:`\beta` is constant) and
    interpolated with cubic splines: to a relative 1e-8 over one contact's
    range, 1e-4 over :math:`\kappa` from 0 to 2 and :math:`\beta` from
    0.05 to 1 (``tests/test_complete.py``), below the 12 x 48-point rule's
    own error.
    """
    from scipy.interpolate import RectBivariateSpline, make_interp_spline

    k_nodes = np.linspace(float(kappa.min()), float(kappa.max()), 65)
    b_lo, b_hi = float(aspect.min()), float(aspect.max())
    if b_hi - b_lo <= 1e-12 * b_hi:
        line = rl.spin_sliding_integral(k_nodes, 0.5 * (b_lo + b_hi))
        result: FloatArray = make_interp_spline(k_nodes, line, k=3)(kappa)
        return result
    b_nodes = np.linspace(b_lo, b_hi, 17)
    table = rl.spin_sliding_integral(k_nodes[:, None], b_nodes[None, :])
    spline = RectBivariateSpline(k_nodes, b_nodes, table, kx=3, ky=3)
    result = np.asarray(spline.ev(kappa, aspect), dtype=float)
    return result


def _sliding_per_speed(
    contact: ContactState, mu: FloatArray, spin: float, curvature: float
) -> FloatArray:
    """Spin + differential sliding power of one contact per unit screw speed [N·m]."""
    a = contact.hertz.a
    b = contact.hertz.b
    safe_a = np.where(a > 0.0, a, 1.0)
    kappa = abs(curvature) * safe_a / max(abs(spin), 1e-300)
    integral = _unique_integral(kappa, b / safe_a)
    result: FloatArray = np.where(
        a > 0.0, mu * 1.5 / math.pi * contact.load * abs(spin) * a * integral, 0.0
    )
    return result


@register(
    "complete",
    title="Complete loss budget: EHL rolling, mixed-film spin and Heathcote sliding, "
    "hysteresis, ball-ball sliding (the predictive model)",
    reference="Houpert, Tribol. Trans. 45 (2002) 345; SKF Rolling bearings 10000 EN (2012) "
    "friction model; "
    "Johnson, Contact Mechanics (1985) ch. 8-9; ball-train constant fitted once "
    "(ballscrew.validation)",
    validity="lubricated steel ball screws with oil or grease, 2-point or 4-point contact, "
    "Hamrock-Dowson film (ellipticity 1-8); ball-train constant trained on catalogue drag "
    "torques of 14-63 mm catalogue screws (HIWIN)",
    purpose="to predict (the default): every loss mechanism, scored against public numbers "
    "(ballscrew validate)",
    checks=(film_checks,),
)
def complete(
    screw: BallScrew,
    lubricant: Lubricant,
    speed: FloatArray,
    temperature: FloatArray,
    axial_load: FloatArray,
    *,
    boundary_friction: float = 0.1,
    limiting_shear_stress: float | None = None,
    limiting_shear_coefficient: float | None = None,
    ball_train_constant: float = BALL_TRAIN_CONSTANT,
    hysteresis_loss_factor: float = HYSTERESIS_LOSS_FACTOR,
    lubrication: str = "oil",
    thermal_correction: bool = True,
    seal_torque: float = 0.0,
    asperity_b: float = 1.42,
    asperity_c: float = 0.8,
    hertz_method: str = "exact",
) -> dict[str, FloatArray]:
    r"""Friction torque as the sum of every loss mechanism (module docstring).

    Parameters
    ----------
    screw, lubricant, speed, temperature, axial_load
        The operating points (see :func:`ballscrew.friction_torque`).
    boundary_friction : float
        :math:`\mu_{bl}` of asperity contact and of the ball-ball contacts;
        0.1 (lubricated steel in boundary lubrication; the study's
        :math:`\mu_0`; SKF's bearing model uses about 0.15).
    limiting_shear_stress, limiting_shear_coefficient : float, optional
        :math:`\tau_0` [Pa] and :math:`\gamma_L` of the full-film traction;
        default: the lubricant's.
    ball_train_constant : float
        :math:`c_B = F_B/Q` [-]; default :data:`BALL_TRAIN_CONSTANT`. Set 0
        for a nut with spacer balls or a ball retainer.
    hysteresis_loss_factor : float
        :math:`\alpha_h` [-]; default :data:`HYSTERESIS_LOSS_FACTOR`.
    lubrication : {"oil", "grease"}
        Sets SKF's replenishment constant :math:`K_{rs}` (3e-8 oil, 6e-8
        grease or oil-air).
    thermal_correction : bool
        Apply the inlet shear heating and replenishment factors (default True).
    seal_torque : float
        Drag torque of wipers or seals [N·m], 0 by default.
    asperity_b, asperity_c : float
        :math:`B`, :math:`C` of :func:`ballscrew.ehl.asperity_share`.
    hertz_method : str
        Hertz solution, default ``"exact"``.

    Returns
    -------
    dict
        ``"rolling"``, ``"sliding"``, ``"hysteresis"``, ``"ball_ball"``,
        ``"four_point"``, ``"seals"`` torques [N·m].
    """
    check_choice("lubrication", lubrication, tuple(_K_RS))
    mu_bl = float(check_nonnegative("boundary_friction", boundary_friction))
    c_b = float(check_nonnegative("ball_train_constant", ball_train_constant))
    alpha_h = float(check_nonnegative("hysteresis_loss_factor", hysteresis_loss_factor))
    seal = float(check_nonnegative("seal_torque", seal_torque, "N·m"))
    tau0, gamma_l = limiting_shear(lubricant, limiting_shear_stress, limiting_shear_coefficient)
    state = operating_state(
        screw,
        lubricant,
        speed=speed,
        temperature=temperature,
        axial_load=axial_load,
        hertz_method=hertz_method,
        asperity_b=asperity_b,
        asperity_c=asperity_c,
        broadcast=False,
    )
    kin = state.kinematics
    shape = state.shape
    gamma = screw.gamma
    dm = screw.pitch_diameter
    rolling_lever = dm * (1.0 - gamma**2) / 4.0  # u / |omega| [m]
    if thermal_correction:
        rpm = np.abs(kin.screw_speed) * 60.0 / (2.0 * math.pi)
        nu = lubricant.kinematic_viscosity(state.temperature) * 1e6  # mm²/s
        dm_mm = dm * 1e3
        section = 3.4 * screw.ball_diameter * 1e3  # D - d of a 72-series bearing, ~3.4 D_w
        reduction = rl.inlet_shear_heating_factor(rpm, dm_mm, nu) * rl.replenishment_factor(
            rpm, nu, dm_mm - 0.5 * section, dm_mm + 0.5 * section, k_rs=_K_RS[lubrication]
        )
    else:
        reduction = np.ones(shape)
    unit = kinematics(screw, 1.0)
    c_s, c_n = differential_sliding(screw, 1.0)
    curvature = {"screw": float(c_s), "nut": float(c_n)}
    spin = {"screw": float(unit.spin_screw), "nut": float(unit.spin_nut)}
    s4, n4 = four_point_spin(screw, 1.0)
    spin4 = {"screw": float(abs(s4)), "nut": float(abs(n4))}
    four = screw.nut == "single-4point"

    parts = {k: np.zeros(shape) for k in ("rolling", "sliding", "hysteresis", "four_point")}
    ball_load_sum: FloatArray = np.zeros(shape)
    for c in state.contacts:
        if c.balls == 0:
            continue
        z = c.balls
        f_r = rl.rolling_force_houpert(
            screw.reduced_modulus,
            c.rx,
            c.ry / c.rx,
            c.materials_parameter,
            np.abs(c.speed_parameter),
            c.load_parameter,
        )
        parts["rolling"] += z * 2.0 * f_r * reduction * rolling_lever
        mean_pressure = 2.0 / 3.0 * c.hertz.p_max
        mu = rl.mixed_friction_coefficient(
            c.asperity_share, mu_bl, rl.limiting_traction_coefficient(tau0, gamma_l, mean_pressure)
        )
        two_point = _sliding_per_speed(c, mu, spin[c.side], curvature[c.side])
        parts["sliding"] += z * two_point
        if four:
            parts["four_point"] += z * (
                _sliding_per_speed(c, mu, spin4[c.side], curvature[c.side]) - two_point
            )
        parts["hysteresis"] += (
            z * rl.hysteresis_rolling_force(c.load, c.hertz.b, c.rx, alpha_h) * rolling_lever
        )
        if c.side == "screw":  # one ball-train load per ball and family
            ball_load_sum = ball_load_sum + z * c.load
    # Neighbouring balls slide at omega_b * D_w = |omega| d_m (1 - gamma^2) / 2.
    parts["ball_ball"] = mu_bl * c_b * ball_load_sum * dm * (1.0 - gamma**2) / 2.0
    parts["seals"] = np.full(shape, seal)
    return parts
