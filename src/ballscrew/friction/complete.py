r"""The complete loss budget of a lubricated ball screw: the predictive model.

This module is long on purpose: it is one model, the sum of every loss mechanism of the
nut, and each mechanism's share of the loaded balls is assembled here from the laws of
:mod:`ballscrew.rolling_losses` and the state the contacts share.

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
``"helix_slip"``
    The slip the helix forces across the groove (:mod:`ballscrew.helix`):
    the screw's surface sweeps past the nut's at :math:`\omega R\sin\lambda`,
    no rolling of the ball can follow both, and each ball shares the slip
    between its screw and nut contacts so that their transverse friction
    forces balance its moment about the rolling direction. Each contact slips
    under its own mixed-film coefficient together with its spin; the
    component is what the slip adds to the spin's dissipation. It grows with
    the lead angle (as :math:`\mu Q D_w\tan\lambda` at large slip), the trend of
    catalogue drag torques that no other mechanism of the model has.
``"ball_ball"``
    Sliding between neighbouring balls. A ball screw has no cage: adjacent
    balls turn the same way, so their surfaces meet at opposite velocities and
    slide at :math:`\omega_bD_w` (4-point balls: :math:`/\cos\alpha`). The force
    between them, the ball-train force,
    arises because the balls do not all want the same orbital speed (their
    loads, contact angles and diameters differ) and push each other; it is
    taken proportional to the ball load, :math:`F_B = c_B Q`, with one global
    constant :math:`c_B` (:data:`BALL_TRAIN_CONSTANT`), the only constant of
    the model that physics does not give. Its friction coefficient follows the
    lubrication of the ball-ball contact (:func:`ball_ball_friction`): the
    mixed-film coefficient of a circular Hertz contact of two balls under
    :math:`F_B`, with its film parameter from the oil and the sliding speed.
    Then :math:`P = \mu_{BB}c_B\sum_j Z_jQ_j\,v_{BB}`, the sum over the trains :math:`j`,
    with :math:`v_{BB}` the
    neighbours' sliding speed (:func:`ballscrew.kinematics.neighbour_sliding`:
    :math:`\omega_bD_w`, and :math:`\omega_bD_w/\cos\alpha` for 4-point balls,
    which turn about the screw's axis). A double nut's two halves each push their own
    train with their own ball load. A 4-point ball belongs to both families
    but is one ball of one train and pushes its neighbour once, with
    :math:`c_B\max(Q_1, Q_2)`: :math:`c_B` is a force per ball over its
    load, fitted on 2-point balls, and the convention is continuous where one
    pair lifts off (the ball then pushes as a 2-point ball). The alternative,
    :math:`c_B(Q_1 + Q_2)` (a push per loaded pair, the convention until
    0.3.0), gives the 4-point/double ratio 1.25 to 2.14 over the catalogue
    sizes (median 1.59) once the faster sliding of 4-point neighbours is in;
    this one gives 0.98 to 1.62 (median 1.18), against the 1.2 to 1.32
    published. Both are conventions, not fits; this one was chosen with that
    check in view, and the scorecard's 4-point rows stay its test. Nuts whose balls are
    kept apart (:attr:`ballscrew.BallScrew.ball_separation`: spacer balls,
    which turn the other way and roll on their neighbours, or a cage, whose
    conformal oil-filled pockets carry the train's force in a thick film) do
    not have it, nor the recirculation term's ball-ball part.

    With ``ball_train="tolerance"`` the force is not a ratio but follows from
    a product tolerance (:mod:`ballscrew.ball_train`): balls whose contact
    angles scatter by :math:`\sigma_\alpha` (:data:`CONTACT_ANGLE_SCATTER`)
    want different orbital speeds, the train moves at one, and each ball's
    groove traction, from the creep of its spinning contacts at their own
    mixed-film coefficients, adds up along the train into the compressions
    between neighbours (their expected values in closed form). The term is
    then :math:`\mu_{BB}\sum\bar P\,\omega_bD_w` over the contacts of
    each circuit's loaded train, plus the balls' creep. Spacer balls keep the
    push but roll on their neighbours (only the creep is left); a cage takes
    each ball's own traction in its pocket, slid at :math:`\omega_bD_w/2`
    under the ball-ball contact's coefficient (an upper bound: the pocket's
    conformal oil film is thicker). A 4-point ball is one ball of one train
    whose stiffness to creep is that of both its contact pairs.
``"recirculation"``
    The push that carries the ball train round its return path. In the bends
    of the return (total turning angle :math:`\Theta`) each ball presses
    outward with :math:`mv_c^2/\rho`; the balls of a bend, one per ball
    diameter, press with :math:`mv_c^2\Theta/D_w` in all, whatever the bend's
    radius. Sliding at the boundary coefficient, they need the push
    :math:`F_r = \mu_{bl}mv_c^2\Theta/D_w` per circuit, which the loaded balls
    supply through the train, compressed from 0 at the entry of the loaded
    zone to :math:`F_r` at its exit. Per circuit :math:`P = F_rv_c +
    \mu_{BB}\tfrac12F_rZ_c\,\omega_bD_w`: it grows as :math:`\omega^3`, so the
    torque as :math:`\omega^2`, and matters only at high speed.
``"four_point"``
    Only for ``nut="single-4point"``: the extra spin sliding that the
    kinematic conflict of a 4-point contact forces
    (:func:`ballscrew.kinematics.four_point_spin`): the ball must turn about
    an axis parallel to the screw axis.
``"meniscus"``
    Only in a nut full of oil (``lubrication="flooded"`` or ``"circulating"``,
    :data:`ballscrew.lubricant.LUBRICATIONS`): the Newtonian shear of the oil in the gap between
    neighbouring balls outside their Hertz contact
    (:func:`ballscrew.rolling_losses.meniscus_shear_power`). Their surfaces
    slide past each other at :math:`v_{BB}` with no entraining motion, so
    the gap builds no pressure and does not cavitate: a Couette film from the
    Hertz circle of the ball-ball contact (radius :math:`a_{BB}` under
    :math:`F_B`, its own film counted in ``"ball_ball"``) out to the ball's
    equator, its gap on the line of centres the ball-ball contact's film
    thickness (at least the balls' composite roughness). Per circuit of
    :math:`n` loaded balls there are :math:`n - 1` such gaps. Proportional to
    the oil's viscosity at ambient pressure and to :math:`\omega^2`: the
    torque grows linearly with the speed and falls with the temperature as
    the viscosity does (the logarithm of the gap hardly moves). Nuts with
    spacer balls or a cage have no sliding neighbours and no such term.
``"churning"``
    Only in a nut full of oil: the drag of the loaded balls moving through the
    oil at their orbital speed relative to the nut, with the drag curve of a
    sphere at the ball's Reynolds number
    (:func:`ballscrew.rolling_losses.ball_churning_power`); an upper bound (the
    screw drags the oil along, and neighbours shield each other).
``"seals"``
    A wiper or seal drag torque given by the user (``seal_torque``), 0 by
    default: catalogue drag torques are measured without wipers.

The lubrication method (``lubrication``, :data:`ballscrew.lubricant.LUBRICATIONS`) decides which
terms run. In a flooded nut (an oil bath, or circulating oil that keeps the nut
full) the balls run immersed: the meniscus and churning terms run, and the
rolling term has no starvation factor (SKF's kinematic replenishment factor
describes a track whose oil must flow back between balls; an immersed track
has it at hand). With oil dripped or metered in (``"drip"``), oil-air or
grease there is no bulk oil in the nut: no meniscus or churning term, and the
rolling term keeps SKF's replenishment factor with its constant for oil
(``"drip"``, the constant of low-level oil lubrication) or for grease and
oil-air. The balls of the return path, which also move through the oil of a
flooded nut, are left out of both terms (a share of the balls of the order of
10 to 30 %), as is the drag torque of the ball's own spin in the oil beyond the
gaps to its neighbours.

The torque on the screw is the dissipated power over the screw speed,
:math:`T = P/|\omega|`; every power above is proportional to the speed at
fixed contact state, so the ratio is evaluated directly and stays finite at
zero speed.

The ball-train constant was fitted once on the training set of
:mod:`ballscrew.study.validation` (see :data:`BALL_TRAIN_CONSTANT`) and is never
changed per case.

Kinematics with the helix (:mod:`ballscrew.kinematics`): rolling, spin and
sliding speeds keep the lead angle.
"""

from __future__ import annotations

import functools
import math
from typing import Any, NamedTuple

import numpy as np
import numpy.typing as npt

from .. import ehl
from .. import rolling_losses as rl
from ..ball_train import creep_slope, expected_train, orbital_sensitivity
from ..contact import hertz
from ..errors import FloatArray, check_choice, check_nonnegative
from ..geometry import ScrewArray, ScrewGeometry, cos, screw_derived
from ..helix import SlipContact, transverse_slip_loss
from ..kinematics import (
    differential_sliding,
    four_point_spin,
    kinematics,
    neighbour_sliding,
    neighbour_sliding_of,
    rad_s_to_rpm,
)
from ..lubricant import FLOODED, Lubricant, lubrication_method
from ..materials import STEEL_DENSITY
from ..numerics.single import broadcast_shape, maximum, where
from ..plausible import check_wiper_drag
from ..state import ContactState, OperatingState
from ..validity import film_checks
from ._common import limiting_shear, model_state
from ._registry import register

__all__ = [
    "BALL_TRAINS",
    "BALL_TRAIN_CONSTANT",
    "BALL_TRAIN_SCATTER",
    "CONTACT_ANGLE_SCATTER",
    "CONTACT_ANGLE_SCATTER_RANGE",
    "HYSTERESIS_LOSS_FACTOR",
    "RETURN_TURNING_ANGLE",
    "ball_ball_friction",
    "complete",
]

BALL_TRAIN_CONSTANT: float = 0.0358
r"""Ball-train force over the ball load, :math:`c_B = F_B/Q` [-].

Fitted once (``scripts/fit_ball_train.py``) on the training cases of
:mod:`ballscrew.study.validation` (10 double nuts at 5 % of their load rating), with
every other mechanism in place, the helix's transverse slip included. The
value matching each training case alone spreads over 0.031 to 0.047 (16 to
84 %, median 0.037). On the reference screw (40 x 10 mm, 2 kN, mineral ISO VG
68 at 40 °C) the ball-ball term it sets carries 68 % of the drag torque at
100 rpm and 52 % at 1000 rpm (before the helix slip was modelled: 0.0474, and
88 % at 100 rpm).
"""

BALL_TRAIN_SCATTER: tuple[float, float] = (0.0312, 0.0465)
"""16th and 84th percentiles of the per-case values of :data:`BALL_TRAIN_CONSTANT` [-]:
the constant that would match each training case alone (``scripts/fit_ball_train.py``)."""

CONTACT_ANGLE_SCATTER: float = 0.004997
r"""Standard deviation of the balls' effective contact angles, :math:`\sigma_\alpha` [rad].

The product tolerance behind the ``ball_train="tolerance"`` model
(:mod:`ballscrew.ball_train`): 0.286°. Fitted once (``scripts/fit_ball_train.py``)
on the same training cases as :data:`BALL_TRAIN_CONSTANT`, with every other
mechanism in place; no published tolerance gives it directly. The value matching
each training case alone spreads over 0.22° to 0.47° (16 to 84 %, median 0.40°).
On the reference screw (6.35 mm balls, conformity 0.55) it is the angle a
scatter of 4.5 µm in the grooves' axial positions gives
(:func:`ballscrew.ball_train.angle_scatter`), of the order of the lead variation
within one revolution that the precision grades of ISO 3408-3 allow.
"""

CONTACT_ANGLE_SCATTER_RANGE: tuple[float, float] = (0.003882, 0.008238)
"""16th and 84th percentiles of the per-case values of :data:`CONTACT_ANGLE_SCATTER` [rad]."""

BALL_TRAINS = ("ratio", "tolerance")
"""The ball-train models of :func:`complete`: the fitted ratio :math:`F_B = c_BQ`
(default) or the train's compatibility from a contact-angle tolerance."""

HYSTERESIS_LOSS_FACTOR: float = 0.007
r"""Hysteresis loss factor :math:`\alpha_h` of hardened bearing steel [-].

Johnson (Contact Mechanics, 1985, §9.2) puts the loss factor of hard metals at
1 % or less; 0.7 % is the value commonly quoted for 52100 steel after
Drutowski's rolling-ball measurements (J. Basic Eng. 81 (1959) 233), which
could not be checked in the original. The term is 0.4 % of the reference
screw's torque, so the choice hardly matters.
"""

RETURN_TURNING_ANGLE: float = 2.0 * math.pi
r"""Total angle :math:`\Theta` through which the return path turns the balls [rad].

A tube return lifts the balls out of the groove, bends twice and sets them
back: four bends of about a right angle each; a deflector's crossover turns
them about as much. An assumption, stated with the result.
"""

# SKF's replenishment constant K_rs (catalogue 10000 EN, 2012): 3e-8 for oil bath (low level)
# and oil jet, 6e-8 for grease and oil-air; None: no starvation factor (the balls immersed).
_K_RS: dict[str, float | None] = {
    "flooded": None, "circulating": None, "drip": 3e-8, "oil-air": 6e-8, "grease": 6e-8,
}  # fmt: skip


DIRECT_INTEGRALS: int = 11
"""Up to this many distinct (kappa, aspect) pairs the sliding integral is
evaluated directly; above, it is interpolated (:func:`_interpolated_integral`),
which evaluates it at 11 nodes on the contacts of ball screws: more pairs than
that cost more directly than through the interpolation."""

CHEBYSHEV_DEGREE: int = 10
"""Degree of the Chebyshev interpolation of the sliding integral along kappa (11 nodes)."""

SMOOTH_KAPPA: float = 0.5
r"""Up to this Heathcote-to-spin ratio :math:`\kappa` the sliding integral is so smooth in
:math:`\kappa` that a Chebyshev interpolation of degree 10 over the points' span
reproduces it to 2e-13 (measured for :math:`\beta` from 0.05 to 1 against the rule at
2000 points; ``tests/friction/test_sliding_integral_dedup.py``); ball screw contacts
have :math:`\kappa` of a few thousandths. Past it (near :math:`\kappa = 1` the line of
no Heathcote sliding crosses the ellipse) the cubic splines are taken."""


def _unique_integral(kappa: FloatArray, aspect: FloatArray) -> FloatArray:
    """:func:`spin_sliding_integral` evaluated once per distinct (kappa, aspect) pair.

    Up to :data:`DIRECT_INTEGRALS` distinct pairs it is evaluated directly,
    above through :func:`_interpolated_integral` over the points' range. The
    distinct pairs are counted on 1-D keys (a row-wise ``np.unique`` costs
    about 1 µs a row): more distinct values of either coordinate than the
    threshold mean more distinct pairs, so scattered points go straight to
    the interpolation (pointwise, as if it had been evaluated on the distinct
    pairs); otherwise each pair gets the integer key of its two ranks.
    """
    if np.size(kappa) == 1 and np.size(aspect) == 1:  # one point: the rule broadcasts
        one: FloatArray = rl.spin_sliding_integral(kappa, aspect)
        return one
    kappa, aspect = np.broadcast_arrays(kappa, aspect)
    if kappa.size <= DIRECT_INTEGRALS:  # a few points: at each, no counting needed
        few: FloatArray = rl.spin_sliding_integral(kappa, aspect)
        return few
    k, b = kappa.reshape(-1), aspect.reshape(-1)
    k_unique = _distinct_or_none(k)
    b_unique = None if k_unique is None else _distinct_or_none(b)
    if k_unique is None or b_unique is None:
        spline: FloatArray = _interpolated_integral(k, b).reshape(kappa.shape)
        return spline
    k_rank = np.searchsorted(k_unique, k)
    b_rank = np.searchsorted(b_unique, b)
    keys, inverse = np.unique(k_rank * len(b_unique) + b_rank, return_inverse=True)
    k_pair, b_pair = k_unique[keys // len(b_unique)], b_unique[keys % len(b_unique)]
    if len(keys) <= DIRECT_INTEGRALS:
        values = rl.spin_sliding_integral(k_pair, b_pair)
    else:
        values = _interpolated_integral(k_pair, b_pair)
    result: FloatArray = values[inverse.reshape(-1)].reshape(kappa.shape)
    return result


def _rows_integral(kappa: FloatArray, aspect: FloatArray) -> FloatArray:
    """:func:`_unique_integral` of many screws at once, each row (first axis) its own.

    A screw's contacts have one aspect and few distinct kappa (kappa follows the load
    alone). Rows of up to :data:`DIRECT_INTEGRALS` values are evaluated directly;
    longer rows within :data:`SMOOTH_KAPPA` by each row's own Chebyshev interpolation
    over its own span, computed for all rows together (the interpolation of
    :func:`_interpolated_integral`, to a relative 2e-13 of the rule); any other row
    by :func:`_unique_integral` on its own.
    """
    kappa, aspect = np.broadcast_arrays(kappa, aspect)
    count = kappa.shape[0] if kappa.ndim else 1
    k = kappa.reshape(count, -1)
    b = aspect.reshape(count, -1)
    if k.shape[1] <= DIRECT_INTEGRALS:
        direct: FloatArray = rl.spin_sliding_integral(kappa, aspect)
        return direct
    result = np.empty(k.shape)
    k_lo, k_hi = k.min(axis=1), k.max(axis=1)
    b_lo, b_hi = b.min(axis=1), b.max(axis=1)
    smooth = (k_hi <= SMOOTH_KAPPA) & (k_hi > k_lo) & (b_hi - b_lo <= 1e-12 * b_hi)
    if smooth.any():
        from numpy.polynomial import chebyshev

        lo, span = k_lo[smooth, None], (k_hi - k_lo)[smooth, None]
        aspect_0 = 0.5 * (b_lo + b_hi)[smooth, None]
        order = CHEBYSHEV_DEGREE + 1
        x_nodes = chebyshev.chebpts1(order)
        values = rl.spin_sliding_integral(lo + 0.5 * (x_nodes + 1.0) * span, aspect_0)
        coefficients = values @ chebyshev.chebvander(x_nodes, CHEBYSHEV_DEGREE)
        coefficients[:, 0] /= order
        coefficients[:, 1:] /= 0.5 * order
        x = (k[smooth] - lo) * (2.0 / span) - 1.0
        # Clenshaw's recurrence, as numpy's chebval, one series per row.
        c0, c1 = coefficients[:, -2, None], coefficients[:, -1, None]
        x2 = 2.0 * x
        for i in range(3, order + 1):
            c0, c1 = coefficients[:, -i, None] - c1, c0 + c1 * x2
        result[smooth] = c0 + c1 * x
    for row in np.flatnonzero(~smooth):
        result[row] = _unique_integral(k[row], b[row])
    rows: FloatArray = result.reshape(kappa.shape)
    return rows


def _distinct_or_none(x: FloatArray) -> FloatArray | None:
    """The sorted distinct values of ``x``, or None if there are more than :data:`DIRECT_INTEGRALS`.

    A prefix of the values is looked at first, so that scattered points are
    told apart without sorting them all.
    """
    if (
        x.size > 4 * DIRECT_INTEGRALS
        and len(_sorted_distinct(x[: 4 * DIRECT_INTEGRALS])) > DIRECT_INTEGRALS
    ):
        return None
    distinct = _sorted_distinct(x)
    return None if len(distinct) > DIRECT_INTEGRALS else distinct


def _sorted_distinct(x: FloatArray) -> FloatArray:
    """``np.unique(x)`` of a 1-D float array, without its import of ``numpy.ma`` (20 ms)."""
    ordered = np.sort(x)
    keep = np.empty(ordered.shape, dtype=bool)
    keep[:1] = True
    np.not_equal(ordered[1:], ordered[:-1], out=keep[1:])
    result: FloatArray = ordered[keep]
    return result


def _interpolated_integral(kappa: FloatArray, aspect: FloatArray) -> FloatArray:
    r""":func:`spin_sliding_integral` interpolated over the points' range (Chebyshev or splines).

    Many distinct loads (a motion cycle, scattered points) give many
    distinct :math:`\kappa` (it grows as :math:`Q^{1/3}`), while
    :math:`\beta = b/a` hardly varies (Hertz's ellipticity does not depend
    on the load). With one :math:`\beta` and :math:`\kappa \le`
    :data:`SMOOTH_KAPPA` (every ball screw contact), the integral is
    interpolated along :math:`\kappa` by a Chebyshev polynomial of degree
    :data:`CHEBYSHEV_DEGREE` over the points' span, to a relative 2e-13.
    Otherwise it is evaluated on a 65 x 17 grid spanning the points (65
    nodes when :math:`\beta` is constant) and interpolated with cubic
    splines: to a relative 1e-8 over one contact's range, 1e-4 over
    :math:`\kappa` from 0 to 2 and :math:`\beta` from 0.05 to 1
    (``tests/friction/test_complete.py``), below the 12 x 48-point rule's own
    error.
    """
    from scipy.interpolate import RectBivariateSpline, make_interp_spline

    k_lo, k_hi = float(kappa.min()), float(kappa.max())
    b_lo, b_hi = float(aspect.min()), float(aspect.max())
    if k_hi == k_lo:  # one kappa: no span to interpolate over; the rule at every point
        direct: FloatArray = rl.spin_sliding_integral(kappa, aspect)
        return direct
    one_aspect = b_hi - b_lo <= 1e-12 * b_hi
    if one_aspect and k_hi <= SMOOTH_KAPPA:
        # Chebyshev interpolation over the points' span (numpy's chebinterpolate).
        from numpy.polynomial import chebyshev

        aspect_0, span = 0.5 * (b_lo + b_hi), k_hi - k_lo
        coefficients: Any = chebyshev.chebinterpolate(
            lambda x: rl.spin_sliding_integral(k_lo + 0.5 * (x + 1.0) * span, aspect_0),
            CHEBYSHEV_DEGREE,
        )
        smooth = chebyshev.chebval((kappa - k_lo) * (2.0 / span) - 1.0, coefficients)
        return np.asarray(smooth, dtype=float)
    k_nodes = np.linspace(k_lo, k_hi, 65)
    if one_aspect:
        line = rl.spin_sliding_integral(k_nodes, 0.5 * (b_lo + b_hi))
        result: FloatArray = make_interp_spline(k_nodes, line, k=3)(kappa)
        return result
    b_nodes = np.linspace(b_lo, b_hi, 17)
    table = rl.spin_sliding_integral(k_nodes[:, None], b_nodes[None, :])
    spline = RectBivariateSpline(k_nodes, b_nodes, table, kx=3, ky=3)
    result = np.asarray(spline.ev(kappa, aspect), dtype=float)
    return result


def _sliding_per_speed(
    contact: ContactState,
    mu: FloatArray,
    spin: Number,
    curvature: Number,
    rows: bool = False,
    integral: FloatArray | None = None,
) -> FloatArray:
    """Spin + differential sliding power of one contact per unit screw speed [N·m].

    ``rows``: the contact's arrays hold many screws along their first axis
    (:func:`_rows_integral`). ``integral``: the sliding integral at the contact's
    :func:`_sliding_arguments`, if the caller has it (:func:`_one_point_integrals`).
    """
    a = contact.hertz.a
    if integral is None:
        kappa, aspect = _sliding_arguments(contact, spin, curvature)
        integral = _rows_integral(kappa, aspect) if rows else _unique_integral(kappa, aspect)
    result: FloatArray = where(
        a > 0.0, mu * 1.5 / math.pi * contact.load * np.abs(spin) * a * integral, 0.0
    )
    return result


def _sliding_arguments(
    contact: ContactState, spin: Number, curvature: Number
) -> tuple[FloatArray, FloatArray]:
    r"""The sliding integral's :math:`\kappa` and aspect :math:`b/a` at a contact."""
    a = contact.hertz.a
    safe_a = where(a > 0.0, a, 1.0)
    kappa = np.abs(curvature) * safe_a / maximum(np.abs(spin), 1e-300)
    return kappa, contact.hertz.b / safe_a


def _one_point_integrals(
    wanted: list[tuple[ContactState, Number, Number]],
) -> list[FloatArray] | None:
    """The sliding integrals of the (contact, spin, curvature) ``wanted`` at one point, or None.

    At a single operating point the contacts' integrals are taken in one evaluation of
    the rule (:func:`ballscrew.rolling_losses.spin_sliding_integral`, row by row the
    same sums); with more points (or many screws) None: each contact takes its own.
    """
    arguments = [_sliding_arguments(c, spin, curvature) for c, spin, curvature in wanted]
    if not all(np.size(k) == 1 and np.size(b) == 1 for k, b in arguments):
        return None
    values = rl.spin_sliding_integral(
        np.array([_first(k) for k, _ in arguments]),
        np.array([_first(b) for _, b in arguments]),
    )
    return [
        values[i].reshape(broadcast_shape(np.shape(k), np.shape(b)))
        for i, (k, b) in enumerate(arguments)
    ]


def ball_ball_friction(
    state: OperatingState,
    contact: ContactState,
    force: FloatArray,
    boundary: float,
    tau0: float,
    gamma_l: float,
    *,
    asperity_b: float,
    asperity_c: float,
) -> FloatArray:
    r"""Friction coefficient between two neighbouring balls of a cage-less train [-].

    The two balls press on each other with the ball-train force ``force``
    (:math:`F_B`) in a circular Hertz contact, :math:`R_x = R_y = D_w/4`, and
    their surfaces pass each other in opposite directions at
    :math:`\omega_bD_w/2` each. The coefficient is the mixed-film one
    (:func:`ballscrew.rolling_losses.mixed_friction_coefficient`) with the
    asperity share of the film parameter :math:`\Lambda = h_{min}/\sigma`,
    :math:`\sigma = \sqrt2\sigma_{ball}`, and the oil's limiting traction at the
    contact's mean pressure in the film. A contact whose surfaces move in
    opposite directions has no entraining motion: isothermal EHL theory gives
    it no film, and what film it has comes from the thermal viscosity wedge
    (films of such zero-entrainment contacts are measured, thinner than in
    rolling at the same surface speed). The film here is Hamrock and Dowson's
    at the entrainment speed of one surface, :math:`\omega_bD_w/2`: an upper
    bound, so that the coefficient falls from :math:`\mu_{bl}` towards the
    full-film traction as speed and viscosity grow (a Stribeck dependence)
    rather than staying at the boundary value.

    Parameters
    ----------
    state : OperatingState
        The operating points (speed, temperature).
    contact : ContactState
        A contact of the ball family (its viscosity and materials parameter).
    force : numpy.ndarray
        Ball-train force :math:`F_B` [N].
    boundary, tau0, gamma_l : float
        :math:`\mu_{bl}`, :math:`\tau_0` [Pa], :math:`\gamma_L`.
    asperity_b, asperity_c : float
        Constants of :func:`ballscrew.ehl.asperity_share`.

    Returns
    -------
    numpy.ndarray
        :math:`\mu_{BB}`; the boundary coefficient where the force is 0.
    """
    screw = state.screw
    loaded = force > 0.0
    f_safe = where(loaded, force, 1.0)
    h_min = _ball_ball_film(state, contact, f_safe)
    sigma = math.sqrt(2.0) * screw.roughness_ball
    share = ehl.asperity_share(ehl.lambda_ratio_unchecked(h_min, sigma), asperity_b, asperity_c)
    radius = 0.25 * screw.ball_diameter
    mean_pressure = 2.0 / 3.0 * hertz(f_safe, radius, radius, screw.reduced_modulus).p_max
    mu = rl.mixed_friction_coefficient(
        share, boundary, rl.limiting_traction_coefficient(tau0, gamma_l, mean_pressure)
    )
    result: FloatArray = where(loaded, mu, boundary)
    return result


def _ball_ball_film(state: OperatingState, contact: ContactState, force: FloatArray) -> FloatArray:
    r"""Hamrock and Dowson's minimum film of the ball-ball contact under ``force`` (> 0) [m].

    At the entrainment speed of one surface, :math:`\omega_bD_w/2` (an upper bound:
    :func:`ball_ball_friction`).
    """
    screw = state.screw
    radius = 0.25 * screw.ball_diameter
    ep = screw.reduced_modulus
    surface = 0.5 * np.abs(neighbour_sliding_of(screw, state.kinematics))
    # From checked inputs (the state's viscosity, the screw, a force > 0): without checks.
    u_par = ehl.dimensionless_speed_unchecked(contact.viscosity, surface, ep, radius)
    w_par = ehl.dimensionless_load_unchecked(force, ep, radius)
    h_min: FloatArray = ehl.hamrock_dowson_1977_minimum_unchecked(
        radius, u_par, contact.materials_parameter, w_par, 1.0
    )
    return h_min


def _flooded(
    state: OperatingState, lubricant: Lubricant, c_b: float
) -> tuple[FloatArray, FloatArray]:
    """Meniscus and churning torques of a nut full of oil [N·m] (module docstring).

    Per loaded train (each family of a double nut; one for a 4-point nut), the ``n - 1``
    gaps of each circuit's ``n`` loaded balls shear their oil
    (:func:`ballscrew.rolling_losses.meniscus_shear_power`) from the Hertz circle of
    the ball-ball contact under :math:`F_B = c_BQ` outward, the gap on the line of
    centres the larger of that contact's film and the balls' composite roughness;
    every loaded ball churns (:func:`ballscrew.rolling_losses.ball_churning_power`) at
    its orbital speed relative to the nut.
    """
    screw = state.screw
    shape = state.shape
    omega = np.abs(state.kinematics.screw_speed)
    moving = omega > 0.0
    per_omega = np.where(moving, 1.0 / np.where(moving, omega, 1.0), 0.0)
    eta = lubricant.dynamic_viscosity(state.temperature)
    rho = lubricant.density(state.temperature)
    unit = kinematics(screw, 1.0)
    sliding = np.abs(_number(neighbour_sliding(screw, 1.0))) * omega
    centre = np.abs(_number(unit.orbital_speed)) * 0.5 * screw.pitch_diameter
    centre = centre / cos(screw.lead_angle) * omega
    radius = 0.5 * screw.ball_diameter
    sigma = math.sqrt(2.0) * screw.roughness_ball
    n = screw.balls_per_circuit
    gaps_per_ball = (n - 1.0) / n  # n >= 1 (BallScrew refuses an empty circuit)
    screw_side = [c for c in state.contacts if c.side == "screw"]
    trains = screw_side[:1] if screw.nut == "single-4point" else screw_side
    meniscus: FloatArray = np.zeros(shape)
    churning: FloatArray = np.zeros(shape)
    per_ball_churn = rl.ball_churning_power(eta, rho, centre, screw.ball_diameter)
    for c in trains:
        if not _any(c.balls):
            continue
        churning = churning + c.balls * per_ball_churn
        if screw.ball_separation != "none":  # spacer balls or a cage: no sliding neighbours
            continue
        force = c_b * np.abs(c.load)
        pressed = force > 0.0
        f_safe = np.where(pressed, force, 1.0)
        film = np.where(pressed, _ball_ball_film(state, c, f_safe), 0.0)
        ball_radius = 0.25 * screw.ball_diameter  # R_x = R_y of the ball-ball contact
        circle = np.where(
            pressed, hertz(f_safe, ball_radius, ball_radius, screw.reduced_modulus).a, 0.0
        )
        gap = np.maximum(film, sigma)
        power = rl.meniscus_shear_power(eta, sliding, radius, gap, inner_radius=circle)
        meniscus = meniscus + c.balls * gaps_per_ball * power
    return meniscus * per_omega, churning * per_omega


def _helix_slip(
    state: OperatingState, mu: dict[str, FloatArray], spin: dict[str, Number]
) -> FloatArray:
    """Torque of the transverse slip, summed over the balls of every family [N·m]."""
    screw = state.screw
    slip = _per_speed(screw).slip
    by_name = {c.name: c for c in state.contacts}
    rows = isinstance(screw, ScrewArray)

    def slip_contact(c: ContactState) -> SlipContact:
        # b/a = 1/k: Hertz's ellipticity depends on the curvatures alone, not on the load.
        if rows:  # one aspect per screw
            k = np.asarray(c.hertz.ellipticity)
            aspect: Number = 1.0 / np.max(k.reshape(k.shape[0], -1), axis=1)
        else:
            aspect = 1.0 / _largest(c.hertz.ellipticity)
        return SlipContact(c.side, mu[c.name], c.load, c.hertz.a, aspect, spin[c.side])

    groups: list[tuple[tuple[str, ...], int | npt.NDArray[np.intp]]]
    if screw.nut == "single-4point":  # each ball touches both families' contacts
        groups = [(("screw-1", "screw-2", "nut-1", "nut-2"), by_name["screw-1"].balls)]
    else:
        groups = [((f"screw-{f}", f"nut-{f}"), by_name[f"screw-{f}"].balls) for f in (1, 2)]
    total: FloatArray = np.zeros(state.shape)
    groups = [(names, balls) for names, balls in groups if _any(balls)]
    powers = None if rows or state.shape else _families_at_one_point(
        [[slip_contact(by_name[n]) for n in names] for names, _ in groups], slip
    )  # fmt: skip
    for i, (names, balls) in enumerate(groups):
        if powers is None:
            power = transverse_slip_loss([slip_contact(by_name[n]) for n in names], slip).power
        else:
            power = powers[i]
        total = total + balls * power
    return total


def _families_at_one_point(
    families: list[list[SlipContact]], slip: Number
) -> list[FloatArray] | None:
    """The slip powers of a double nut's two families at one point, in one solve, or None.

    Both families' balls touch the same sides with the same aspects and spins (their loads
    differ): their balances are solved as two points of one call of
    :func:`~ballscrew.helix.transverse_slip_loss`, each point's steps its own (the same
    numbers as one call a family). None where that does not hold (one family loaded, a
    4-point nut, contacts that differ): each family is then solved alone.
    """
    if len(families) != 2 or len(families[0]) != len(families[1]):
        return None
    merged = []
    for one, two in zip(families[0], families[1], strict=True):
        if (one.side, one.aspect, one.spin) != (two.side, two.aspect, two.spin):
            return None
        merged.append(
            SlipContact(
                one.side,
                np.array([_first(one.friction), _first(two.friction)]),
                np.array([_first(one.load), _first(two.load)]),
                np.array([_first(one.semi_axis), _first(two.semi_axis)]),
                one.aspect,
                one.spin,
            )
        )
    power = transverse_slip_loss(merged, slip).power
    return [power[0].reshape(()), power[1].reshape(())]


@register(
    "complete",
    title="Complete loss budget: EHL rolling, mixed-film spin and Heathcote sliding, "
    "the helix's transverse slip, hysteresis, ball-ball sliding, recirculation "
    "(the predictive model)",
    reference="Houpert, Tribol. Trans. 45 (2002) 345; SKF Rolling bearings 10000 EN (2012) "
    "friction model; Johnson, Contact Mechanics (1985) ch. 8-9; Lin, Ravani & Velinsky, "
    "J. Mech. Des. 116 (1994) 849 (the helix's slip); ball-train constant fitted once "
    "(ballscrew.study.validation)",
    validity="lubricated steel ball screws with oil or grease, 2-point or 4-point contact, "
    "Hamrock-Dowson film (ellipticity 1-8); ball-train constant trained on catalogue drag "
    "torques of 14-63 mm catalogue screws (HIWIN)",
    purpose="to predict (the default): every loss mechanism, scored against public numbers "
    "(ballscrew validate)",
    checks=(film_checks,),
    batches=lambda parameters: parameters.get("ball_train", "ratio") == "ratio",
)
def complete(
    screw: ScrewGeometry, lubricant: Lubricant, speed: FloatArray, temperature: FloatArray,
    axial_load: FloatArray, *, state: OperatingState | None = None,
    boundary_friction: float = 0.1,
    limiting_shear_stress: float | None = None,
    limiting_shear_coefficient: float | None = None,
    ball_train: str = "ratio",
    ball_train_constant: float = BALL_TRAIN_CONSTANT,
    contact_angle_scatter: float = CONTACT_ANGLE_SCATTER,
    return_turning_angle: float = RETURN_TURNING_ANGLE,
    hysteresis_loss_factor: float = HYSTERESIS_LOSS_FACTOR,
    lubrication: str = "auto",
    thermal_correction: bool = True,
    seal_torque: float = 0.0,
    asperity_b: float = 1.42,
    asperity_c: float = 0.8,
    hertz_method: str = "exact",
) -> dict[str, FloatArray]:  # fmt: skip
    r"""Friction torque as the sum of every loss mechanism (module docstring).

    Parameters
    ----------
    screw, lubricant, speed, temperature, axial_load
        The operating points (see :func:`ballscrew.friction_torque`).
    boundary_friction : float
        :math:`\mu_{bl}` of asperity contact (ball-groove and ball-ball) and
        of the balls in the return path; 0.1 (lubricated steel in boundary
        lubrication; the study's :math:`\mu_0`; SKF's bearing model uses about
        0.15).
    limiting_shear_stress, limiting_shear_coefficient : float, optional
        :math:`\tau_0` [Pa] and :math:`\gamma_L` of the full-film traction;
        default: the lubricant's.
    ball_train : {"ratio", "tolerance"}
        How the ball-train force is found: ``"ratio"`` (default) :math:`F_B = c_BQ`;
        ``"tolerance"`` from the train's compatibility with scattered contact
        angles (:mod:`ballscrew.ball_train`).
    ball_train_constant : float
        :math:`c_B = F_B/Q` [-] of ``"ratio"``; default :data:`BALL_TRAIN_CONSTANT`.
    contact_angle_scatter : float
        :math:`\sigma_\alpha` [rad] of ``"tolerance"``: the standard deviation of the
        balls' effective contact angles; default :data:`CONTACT_ANGLE_SCATTER`.
    return_turning_angle : float
        :math:`\Theta` [rad]; default :data:`RETURN_TURNING_ANGLE`.
    hysteresis_loss_factor : float
        :math:`\alpha_h` [-]; default :data:`HYSTERESIS_LOSS_FACTOR`.
    lubrication : {"auto", "flooded", "circulating", "oil-air", "drip", "grease"}
        The lubrication method (:data:`ballscrew.lubricant.LUBRICATIONS`): in a flooded nut
        (``"flooded"``, ``"circulating"``) the meniscus and churning terms
        run and the rolling term has no starvation factor; otherwise SKF's
        replenishment constant :math:`K_{rs}` is 3e-8 (``"drip"``) or 6e-8
        (``"oil-air"``, ``"grease"``). ``"auto"`` (default): ``"grease"`` for a
        grease, else ``"drip"`` (:func:`ballscrew.lubricant.lubrication_method`).
    thermal_correction : bool
        Apply the inlet shear heating and replenishment factors (default True).
    seal_torque : float
        Drag torque of wipers or seals [N·m], 0 by default; ten times the
        typical drag of the screw's size is refused
        (:func:`ballscrew.plausible.check_wiper_drag`).
    asperity_b, asperity_c : float
        :math:`B`, :math:`C` of :func:`ballscrew.ehl.asperity_share`.
    hertz_method : str
        Hertz solution, default ``"exact"``.

    Returns
    -------
    dict
        ``"rolling"``, ``"sliding"``, ``"helix_slip"``, ``"hysteresis"``,
        ``"ball_ball"``, ``"recirculation"``, ``"meniscus"``, ``"churning"``,
        ``"four_point"``, ``"seals"`` torques [N·m].
    """
    method = lubrication_method(lubrication, lubricant)
    given = (boundary_friction, ball_train, ball_train_constant, contact_angle_scatter,
             return_turning_angle, hysteresis_loss_factor, seal_torque)  # fmt: skip
    try:  # the same values at every call of a loop: checked once (a bad one raises each time)
        mu_bl, c_b, scatter, theta, alpha_h, seal = _numbers_kept(*given)
    except TypeError:  # a value that cannot be a key (an array): checked afresh
        mu_bl, c_b, scatter, theta, alpha_h, seal = _numbers(*given)
    if seal > 0.0:  # no drag cannot be too much
        check_wiper_drag("seal_torque", seal, screw.pitch_diameter, warn_above=False)
    tau0, gamma_l = limiting_shear(lubricant, limiting_shear_stress, limiting_shear_coefficient)
    state = model_state(
        screw, lubricant, speed, temperature, axial_load, hertz_method=hertz_method,
        asperity_b=asperity_b, asperity_c=asperity_c, state=state,
    )  # fmt: skip
    reduction = _thermal_reduction(screw, lubricant, state, method, thermal_correction)
    per_speed = _per_speed(screw)
    four = screw.nut == "single-4point"
    parts, mu = _groove_losses(
        screw, state, per_speed, four, reduction, mu_bl, tau0, gamma_l, alpha_h
    )
    spin = per_speed.spin4 if four else per_speed.spin
    parts["helix_slip"] = _helix_slip(state, mu, spin)
    if ball_train == "ratio":
        parts["ball_ball"], parts["recirculation"] = _ratio_train(
            state, c_b, mu_bl, tau0, gamma_l, theta, asperity_b, asperity_c
        )
    else:
        # One screw at a time (the chain batches only the ratio train): numbers, not arrays.
        one_spin = {side: float(value) for side, value in spin.items()}
        parts["ball_ball"], parts["recirculation"] = _ball_train(
            state, mu, one_spin, scatter, mu_bl, tau0, gamma_l, theta, asperity_b, asperity_c
        )
    if method in FLOODED:
        parts["meniscus"], parts["churning"] = _flooded(state, lubricant, c_b)
    else:  # no bulk oil in the nut
        parts["meniscus"] = parts["churning"] = np.zeros(state.shape)
    parts["seals"] = np.full(state.shape, seal)
    order = ("rolling", "sliding", "helix_slip", "hysteresis", "ball_ball", "recirculation",
             "meniscus", "churning", "four_point", "seals")  # fmt: skip
    return {name: parts[name] for name in order}


def _numbers(
    boundary_friction: Any, ball_train: Any, ball_train_constant: Any, contact_angle_scatter: Any,
    return_turning_angle: Any, hysteresis_loss_factor: Any, seal_torque: Any,
) -> tuple[float, float, float, float, float, float]:  # fmt: skip
    """:func:`complete`'s numeric parameters checked, as floats (and its ball-train rule)."""
    mu_bl = float(check_nonnegative("boundary_friction", boundary_friction))
    check_choice("ball_train", ball_train, BALL_TRAINS)
    c_b = float(check_nonnegative("ball_train_constant", ball_train_constant))
    scatter = float(check_nonnegative("contact_angle_scatter", contact_angle_scatter, "rad"))
    theta = float(check_nonnegative("return_turning_angle", return_turning_angle, "rad"))
    alpha_h = float(check_nonnegative("hysteresis_loss_factor", hysteresis_loss_factor))
    seal = float(check_nonnegative("seal_torque", seal_torque, "N·m"))
    return mu_bl, c_b, scatter, theta, alpha_h, seal


_numbers_kept = functools.lru_cache(maxsize=64, typed=True)(_numbers)
""":func:`_numbers` kept by the values' types and values (True is not taken for 1.0)."""


def _thermal_reduction(
    screw: ScrewGeometry, lubricant: Lubricant, state: OperatingState, lubrication: str,
    thermal_correction: bool,
) -> FloatArray:  # fmt: skip
    """SKF's inlet shear heating times replenishment factor (ones without the correction).

    A flooded nut (``_K_RS`` None) has no replenishment factor: its balls run immersed.
    """
    if not thermal_correction:
        return np.ones(state.shape)
    rpm = rad_s_to_rpm(np.abs(state.kinematics.screw_speed))
    kept = state.kinematic_viscosity if state.lubricant is lubricant else None
    nu = (lubricant.kinematic_viscosity(state.temperature) if kept is None else kept) * 1e6  # mm²/s
    dm_mm = screw.pitch_diameter * 1e3
    section = 3.4 * screw.ball_diameter * 1e3  # D - d of a 72-series bearing, ~3.4 D_w
    reduction: FloatArray = rl.inlet_shear_heating_factor(rpm, dm_mm, nu)
    k_rs = _K_RS[lubrication]
    if k_rs is not None:
        reduction = reduction * rl.replenishment_factor(
            rpm, nu, dm_mm - 0.5 * section, dm_mm + 0.5 * section, k_rs=k_rs
        )
    return reduction


Number = float | FloatArray
"""A geometric quantity: a number for one screw, an array for a :class:`ScrewArray`."""


class _PerSpeed(NamedTuple):
    """Kinematics per unit screw speed, by side where it differs (arrays: one per screw)."""

    rolling_lever: Number  # u / |omega| [m]
    curvature: dict[str, Number]  # Heathcote's C / omega
    spin: dict[str, Number]  # omega_s / omega, 2-point contact
    spin4: dict[str, Number]  # |omega_s| / |omega|, 4-point contact
    slip: Number  # the helix's transverse slip / omega [m]
    sliding: Number  # neighbouring balls' sliding / omega [m]
    orbital: Number  # the balls' orbital speed / omega [-]


def _any(balls: int | npt.NDArray[np.intp]) -> bool:
    """Whether any screw has loaded balls here (a count, or one per screw of a ScrewArray)."""
    return balls != 0 if type(balls) is int else bool(np.any(balls))


def _largest(x: FloatArray) -> float:
    """The largest value of ``x`` (a single value as it is) as a float."""
    return float(x) if np.ndim(x) == 0 else float(np.max(x))


def _first(x: Any) -> float:
    """The first (at one point: the only) value of ``x`` as a float."""
    return x if type(x) is float else float(np.asarray(x).reshape(-1)[0])


def _number(x: Any) -> Number:
    """``x`` as a float (one screw) or an array (one value per screw of a ScrewArray)."""
    return float(x) if np.ndim(x) == 0 else np.asarray(x, dtype=float)


def _per_speed(screw: ScrewGeometry) -> _PerSpeed:
    """The screw's rolling lever, sliding curvature, spins and slips per unit screw speed.

    The geometry's alone: computed once per screw object (:func:`screw_derived`).
    """
    return screw_derived(screw, "complete.per_speed", lambda: _unit_speed(screw))


def _unit_speed(screw: ScrewGeometry) -> _PerSpeed:
    """What :func:`_per_speed` keeps, computed."""
    unit = kinematics(screw, 1.0)
    c_s, c_n = differential_sliding(screw, 1.0)
    s4, n4 = four_point_spin(screw, 1.0)
    return _PerSpeed(
        rolling_lever=_number(unit.entrainment_speed),
        curvature={"screw": _number(c_s), "nut": _number(c_n)},
        spin={"screw": _number(unit.spin_screw), "nut": _number(unit.spin_nut)},
        spin4={"screw": _number(np.abs(s4)), "nut": _number(np.abs(n4))},
        slip=_number(unit.transverse_slip),
        sliding=_number(neighbour_sliding(screw, 1.0)),
        orbital=_number(unit.orbital_speed),
    )


def _groove_losses(
    screw: ScrewGeometry,
    state: OperatingState,
    per_speed: _PerSpeed,
    four: bool,
    reduction: FloatArray,
    mu_bl: float,
    tau0: float,
    gamma_l: float,
    alpha_h: float,
) -> tuple[dict[str, FloatArray], dict[str, FloatArray]]:
    """Rolling, sliding, hysteresis and 4-point torques of the ball-groove contacts.

    Also returns each contact's mixed friction coefficient, by contact name.
    """
    rolling_lever = per_speed.rolling_lever
    curvature, spin, spin4 = per_speed.curvature, per_speed.spin, per_speed.spin4
    # One point: the sums as numbers (the same additions), else arrays added in place.
    one = not state.shape
    parts: dict[str, Any] = {
        k: 0.0 if one else np.zeros(state.shape)
        for k in ("rolling", "sliding", "hysteresis", "four_point")
    }
    mu: dict[str, FloatArray] = {}
    rows = isinstance(screw, ScrewArray)
    loaded = [c for c in state.contacts if _any(c.balls)]
    # Each loaded contact's 2-point integral (and its 4-point one), taken together at one point.
    spins = (spin, spin4) if four else (spin,)
    together = None if rows else _one_point_integrals(
        [(c, s[c.side], curvature[c.side]) for c in loaded for s in spins]
    )  # fmt: skip
    for i, c in enumerate(loaded):
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
        mu[c.name] = rl.mixed_friction_coefficient(
            c.asperity_share, mu_bl, rl.limiting_traction_coefficient(tau0, gamma_l, mean_pressure)
        )
        own = (None, None) if together is None else together[len(spins) * i :][: len(spins)]
        two_point = _sliding_per_speed(c, mu[c.name], spin[c.side], curvature[c.side], rows, own[0])
        parts["sliding"] += z * two_point
        if four:
            parts["four_point"] += z * (
                _sliding_per_speed(c, mu[c.name], spin4[c.side], curvature[c.side], rows, own[1])
                - two_point
            )
        parts["hysteresis"] += (
            z * rl.hysteresis_rolling_force(c.load, c.hertz.b, c.rx, alpha_h) * rolling_lever
        )
    if one:  # arrays, as at many points
        parts = {k: np.array(v, dtype=float) for k, v in parts.items()}
    return parts, mu


def _ball_train(
    state: OperatingState,
    mu: dict[str, FloatArray],
    spin: dict[str, float],
    scatter: float,
    mu_bl: float, tau0: float, gamma_l: float, theta: float, asperity_b: float,
    asperity_c: float,
) -> tuple[FloatArray, FloatArray]:  # fmt: skip
    """Ball-ball (or spacer, or cage pocket) and recirculation torques of the ball train [N·m].

    Per circuit, the expected forces of :func:`ballscrew.ball_train.expected_train`: each
    ball's stiffness to creep from its contacts' mixed-film coefficients, the spread of
    the natural speeds from the contact-angle scatter ``scatter`` [rad].
    """
    screw = state.screw
    shape = state.shape
    unit = kinematics(screw, 1.0)
    # Neighbouring balls slide at omega_b * D_w (4-point: / cos alpha); per unit screw speed:
    sliding = float(neighbour_sliding(screw, 1.0))
    centre = float(unit.orbital_speed) * 0.5 * screw.pitch_diameter / math.cos(screw.lead_angle)
    spread = (
        centre
        * scatter
        * orbital_sensitivity(screw.ball_diameter, screw.pitch_diameter, screw.contact_angle)
    )
    mass = STEEL_DENSITY * math.pi * screw.ball_diameter**3 / 6.0
    omega2 = state.kinematics.screw_speed**2
    # Push per circuit over omega^2 [N s^2]: mu_bl m v_c^2 Theta / D_w.
    push = mu_bl * mass * centre**2 * theta / screw.ball_diameter
    n = screw.balls_per_circuit
    by_name = {c.name: c for c in state.contacts}
    # A 4-point ball is one ball of one train with both contact pairs: its stiffness is
    # the two pairs' together. A double nut has a train per circuit of each half-nut.
    # A single 2-point nut has balls in one family only.
    pairs = [[1, 2]] if screw.nut == "single-4point" else [[1], [2]]
    pairs = [p for p in pairs if by_name[f"screw-{p[0]}"].balls]
    ball_ball: FloatArray = np.zeros(shape)
    recirculation: FloatArray = np.zeros(shape)
    for families in pairs:
        stiffness: FloatArray = np.zeros(shape)
        for f in families:
            c_s = _creep_coefficient(by_name[f"screw-{f}"], mu[f"screw-{f}"], spin["screw"])
            c_n = _creep_coefficient(by_name[f"nut-{f}"], mu[f"nut-{f}"], spin["nut"])
            total = c_s + c_n  # 0 only on a lifted-off half-nut
            series = np.divide(4.0 * c_s * c_n, total, out=np.zeros(shape), where=total > 0.0)
            stiffness = stiffness + series
        means = expected_train(stiffness, spread, n)
        contact = by_name[f"screw-{families[0]}"]
        if screw.ball_separation == "cage":  # each ball's own traction, in its pocket
            pocket = ball_ball_friction(
                state, contact, means.traction, mu_bl, tau0, gamma_l,
                asperity_b=asperity_b, asperity_c=asperity_c,
            )  # fmt: skip
            per_circuit = n * pocket * means.traction * 0.5 * sliding
            mu_bb: FloatArray = np.zeros(shape)
        elif screw.ball_separation == "spacer-balls":  # the push stays, the balls roll
            per_circuit = np.zeros(shape)
            mu_bb = np.zeros(shape)
        else:
            mu_bb = ball_ball_friction(
                state, contact, means.compression, mu_bl, tau0, gamma_l,
                asperity_b=asperity_b, asperity_c=asperity_c,
            )  # fmt: skip
            per_circuit = (n - 1) * mu_bb * means.compression * sliding
        ball_ball = ball_ball + screw.circuits * (per_circuit + n * means.creep_power)
        # The grooves drive the train only where its balls carry load (sign 0: a lifted-off
        # half-nut's balls are not pushed round).
        recirc = push * (centre + 0.5 * n * mu_bb * sliding)
        recirculation = recirculation + screw.circuits * recirc * omega2 * np.sign(contact.load)
    return ball_ball, recirculation


def _creep_coefficient(contact: ContactState, mu: FloatArray, spin: float) -> FloatArray:
    r"""A contact's rolling-direction creep coefficient times the screw speed [N].

    :math:`c\omega = \mu QG_x'(\beta)/(|\omega_s/\omega|a)`
    (:func:`ballscrew.ball_train.creep_slope`); 0 where the contact carries no load.
    """
    a = np.broadcast_to(contact.hertz.a, np.shape(contact.load))
    aspect = 1.0 / _largest(contact.hertz.ellipticity)
    capacity = mu * contact.load * float(creep_slope(aspect))
    result: FloatArray = np.divide(
        capacity, abs(spin) * a, out=np.zeros(np.broadcast(capacity, a).shape), where=a > 0.0
    )
    return result


def _ratio_train(
    state: OperatingState,
    c_b: float,
    mu_bl: float, tau0: float, gamma_l: float, theta: float, asperity_b: float,
    asperity_c: float,
) -> tuple[FloatArray, FloatArray]:  # fmt: skip
    """Ball-ball sliding and recirculation torques of the ball train, :math:`F_B = c_BQ` [N·m]."""
    screw = state.screw
    shape = state.shape
    touching = screw.ball_separation == "none"  # else no surfaces of the train slide
    per_speed = _per_speed(screw)
    # Neighbouring balls slide at omega_b * D_w (4-point: / cos alpha); per unit screw speed:
    sliding = per_speed.sliding
    centre = per_speed.orbital * 0.5 * screw.pitch_diameter / cos(screw.lead_angle)
    mass = STEEL_DENSITY * math.pi * screw.ball_diameter**3 / 6.0
    omega2 = state.kinematics.screw_speed**2
    # Push per circuit over omega^2 [N s^2]: mu_bl m v_c^2 Theta / D_w.
    push = mu_bl * mass * centre**2 * theta / screw.ball_diameter
    ball_ball: FloatArray = np.zeros(shape)
    recirculation: FloatArray = np.zeros(shape)
    screw_side = [c for c in state.contacts if c.side == "screw"]
    if screw.nut == "single-4point":
        # One ball, one push, at the larger pair's load: family 1's, the loaded one
        # (ballscrew.loads puts |F_a| on it).
        trains = [(screw_side[0], screw_side[0].load)]
    else:  # a double nut's halves push their own trains
        trains = [(c, c.load) for c in screw_side]
    for c, load in trains:
        mu_bb = ball_ball_friction(
            state, c, c_b * load, mu_bl, tau0, gamma_l,
            asperity_b=asperity_b, asperity_c=asperity_c,
        ) if touching else np.zeros(shape)  # fmt: skip
        ball_ball = ball_ball + c.balls * mu_bb * c_b * load * sliding
        # The grooves drive the train only where its balls carry load (sign 0: a
        # lifted-off half-nut's balls are not pushed round).
        per_circuit = push * (centre + 0.5 * screw.balls_per_circuit * mu_bb * sliding)
        recirculation = recirculation + screw.circuits * per_circuit * omega2 * np.sign(load)
    return ball_ball, recirculation
