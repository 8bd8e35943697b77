r"""The loaded ball train: why neighbouring balls push each other, and how hard.

A ball screw's balls do not all want the same orbital speed. A ball whose
contact angle is larger by :math:`\Delta\alpha` (a groove-form or pitch
error at its place, a ball a little off size) rolls on radii whose ratio
gives it the natural orbital speed :math:`\omega_m(1 + k\Delta\alpha)`, with
:math:`\omega_m = \tfrac\omega2(1 - \gamma)`, :math:`\gamma = D_w\cos\alpha/d_m`
and

.. math:: k = \frac{\partial\ln\omega_m}{\partial\alpha}
          = \frac{D_w\sin\alpha}{d_m(1-\gamma)}

(:func:`orbital_sensitivity`; 0.12 per radian, 0.2 % per degree, on a
40 x 10 mm screw with 6.35 mm balls). The loaded balls of a circuit form a
contiguous train that closes through the return path, and they can push one
another but never pull. In the steady state the whole train moves at one
common speed :math:`V` (a faster group would catch up round the circuit):
each ball :math:`i` is driven forward by its grooves with

.. math:: T_i = K\,(v_i - V),\qquad v_i = v_c(1 + k\Delta\alpha_i),\qquad
          \sum_i T_i = 0

(:math:`v_c` the centre speed), and the compression between ball :math:`i`
and the ball ahead of it is the cumulative sum of the tractions behind it,
:math:`S_i = \sum_{j\le i}T_j`, raised by the one constant that makes every
compression non-negative (a closed train with some clearance has one gap,
where the sum is lowest): :math:`P_i = S_i - \min_{0\le k\le N}S_k`.

**The traction of a creeping ball.** A ball held off its natural speed by
:math:`\delta = V - v_i` creeps along the rolling direction at both its
contacts; the creeps add up to :math:`2\delta` (a rigid ball's rotation moves
creep from one contact to the other but not their sum) and its moment
balance makes the two rolling-direction forces equal. Each contact spins
(:math:`\omega_s`) as well: the spin already slides every point of the
ellipse, along the rolling direction at speeds up to :math:`\omega_sa` at the
ends of the long axis, so a creep small against :math:`\omega_sa` only tips
the friction at each point and the force grows linearly with it. In full
slip (:math:`\boldsymbol\tau = \mu p\,\mathbf v/|\mathbf v|`, the law of the
spin and of the helix's transverse slip, :mod:`ballscrew.helix`, here with
the uniform slip along the rolling direction instead of across the groove):

.. math:: F_x = \mu Q\,G_x(\beta, \sigma),\qquad \sigma = \frac{\Delta v}{\omega_s a},\qquad
          G_x'(0) = \frac32\,\frac{E(m) - \beta^2K(m)}{1-\beta^2},\ m = 1 - \beta^2

(:func:`creep_slope`; 1.5 for a slender ellipse, :math:`3\pi/8` for a
circle), so each contact has the creep coefficient :math:`c_j = \mu_jQ_jG_x'
(\beta_j)/(|\omega_{s,j}|a_j)` and the ball the stiffness :math:`K =
4c_sc_n/(c_s + c_n)` (its two contacts in series, the force counted on both).
The coefficient :math:`\mu_j` is each contact's mixed-film coefficient, so the
train's forces follow the film parameter: they fall from the boundary value
towards the full-film traction as speed and viscosity grow.

**Expected values over random offsets.** With independent offsets of
standard deviation :math:`\sigma_\alpha` the sums :math:`S_i` are a random-walk
bridge, and the expected compression of every contact is the bridge's expected
maximum (:func:`bridge_maximum`; the bridge form of Spitzer's identity,
:math:`\mathrm E\max_kS_k = \sum_{k=1}^{N-1}\mathrm E[S_k^+]/k`):

.. math:: \bar P = K\,v_c\,k\,\sigma_\alpha\,M_N,\qquad
          M_N = \frac{1}{\sqrt{2\pi}}\sum_{k=1}^{N-1}\sqrt{\frac{N-k}{Nk}}
          \approx\sqrt{\pi N/8}

It grows as :math:`\sqrt N`, has no lead in it, and is proportional to the
spread and to :math:`\mu Q`. :func:`expected_train` gives the means;
:func:`train_by_ball` solves one drawn train ball by ball with the nonlinear
traction law, and the tests hold the two against each other.

**What it dissipates.** Neighbouring balls turn the same way, so where they
touch their surfaces pass each other at :math:`\omega_bD_w`: :math:`P =
\sum_i\mu_{BB}P_i\,\omega_bD_w` over the :math:`N - 1` contacts of the loaded
train; and every ball creeps, :math:`\tfrac12K\delta_i^2` to first order.
Spacer balls (smaller balls between the loaded ones, turning the other way)
roll on their neighbours: the push stays, the sliding goes. A cage takes each
ball's own traction :math:`|T_i|` in an oil-filled pocket whose wall the ball's
surface passes at :math:`\omega_bD_w/2`: the pocket forces are the single
tractions, not their sums.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from . import rolling_losses as rl
from .errors import FloatArray, check_nonnegative, check_positive
from .numerics.elliptic import complete_integrals

__all__ = [
    "TrainMeans",
    "TrainSolution",
    "angle_scatter",
    "bridge_maximum",
    "creep_slope",
    "expected_train",
    "orbital_sensitivity",
    "rolling_creep_integrals",
    "train_by_ball",
]


def orbital_sensitivity(ball_diameter: float, pitch_diameter: float, contact_angle: float) -> float:
    r"""Relative change of a ball's natural orbital speed per radian of contact angle [1/rad].

    .. math:: k = \frac{\partial\ln\omega_m}{\partial\alpha} = \frac{D_w\sin\alpha}{d_m(1-\gamma)},
              \qquad \gamma = \frac{D_w\cos\alpha}{d_m}

    from :math:`\omega_m = \tfrac\omega2(1-\gamma)` (the orbital speed of a ball
    between two races, Harris & Kotzalas, *Rolling Bearing Analysis*, 5th ed.,
    2007, ch. 8; the helix's :math:`\cos^2\lambda` correction, below 1 % on
    catalogue leads, left out of the derivative).

    Examples
    --------
    >>> round(orbital_sensitivity(6.35e-3, 41.4e-3, math.radians(45.0)), 4)
    0.1217
    """
    d = float(check_positive("ball_diameter", ball_diameter, "m"))
    dm = float(check_positive("pitch_diameter", pitch_diameter, "m"))
    gamma = d * math.cos(contact_angle) / dm
    return d * math.sin(contact_angle) / (dm * (1.0 - gamma))


def angle_scatter(
    position_scatter: float,
    ball_diameter: float,
    conformity_screw: float,
    conformity_nut: float,
    contact_angle: float,
) -> float:
    r"""Contact-angle scatter that a scatter of the grooves' axial positions gives [rad].

    A ball touches its two grooves on the line through their centres of
    curvature, :math:`A = (f_s + f_n - 1)D_w` apart (less the elastic
    approach). Moving one groove along the axis by :math:`\Delta z` (a local lead
    deviation of the screw or the nut) turns that line by

    .. math:: \Delta\alpha = \frac{\Delta z\cos\alpha}{(f_s + f_n - 1)D_w}

    to first order (and changes the ball's load by the interference
    :math:`\Delta z\sin\alpha`). A position tolerance in micrometres is thus a
    larger angle scatter for small balls in close-conforming grooves.

    Examples
    --------
    >>> round(math.degrees(angle_scatter(3e-6, 6.35e-3, 0.55, 0.55, math.radians(45.0))), 3)
    0.191
    """
    z = float(check_nonnegative("position_scatter", position_scatter, "m"))
    d = float(check_positive("ball_diameter", ball_diameter, "m"))
    spread = (conformity_screw + conformity_nut - 1.0) * d
    return z * math.cos(contact_angle) / spread


def creep_slope(aspect: npt.ArrayLike) -> FloatArray:
    r"""Slope :math:`G_x'(0)` of the rolling-direction force of a spinning contact [-].

    A contact of semi-axes :math:`a` across and :math:`b = \beta a` along the
    rolling direction, spinning at :math:`\omega_s` and creeping along the
    rolling direction at :math:`\Delta v = \sigma\omega_sa`, in full slip, has
    the normalised sliding velocity :math:`(\sigma - Y, \beta X)` and transmits
    :math:`F_x = \mu QG_x`, :math:`G_x = \frac{3}{2\pi}\iint\sqrt{1-X^2-Y^2}
    (\sigma-Y)/|\hat{\mathbf v}|\,dX\,dY`. Its derivative at :math:`\sigma = 0`
    integrates in closed form (polar coordinates, then :math:`t = \tan\varphi`):

    .. math:: G_x'(0) = \frac32\,\frac{E(m) - \beta^2K(m)}{1 - \beta^2},\qquad m = 1-\beta^2

    with :math:`K, E` the complete elliptic integrals of parameter :math:`m`:
    1.5 as :math:`\beta\to0` (the friction tips sign across the line
    :math:`Y = \sigma`, the pressure's weight there is :math:`\tfrac34`),
    :math:`3\pi/8` for a circle.

    Examples
    --------
    >>> [round(float(v), 4) for v in creep_slope([1e-9, 0.2, 1.0])]
    [1.5, 1.4529, 1.1781]
    """
    beta = np.asarray(aspect, dtype=float)
    if np.any(beta <= 0.0) or np.any(beta > 1.0):
        raise ValueError("aspect must lie in (0, 1]")
    round_ = beta > 1.0 - 1e-6
    b = np.where(round_, 0.5, beta)
    big_k, big_e = complete_integrals(1.0 / b)
    slope = 1.5 * (big_e - b * b * big_k) / (1.0 - b * b)
    result: FloatArray = np.where(round_, 3.0 * math.pi / 8.0, slope)
    return result


def rolling_creep_integrals(aspect: float, slip: npt.ArrayLike) -> tuple[FloatArray, FloatArray]:
    r"""Power and rolling-direction force integrals of a spinning, creeping contact [-].

    :math:`P = \mu\frac{3Q}{2\pi}|\omega_s|a\,J_x` and :math:`F_x = \mu QG_x`, with
    :math:`J_x = \iint\sqrt{1-X^2-Y^2}\,|\hat{\mathbf v}|`, :math:`\hat{\mathbf v} =
    (\sigma - Y, \beta X)` (:func:`creep_slope`), by direct quadrature on a
    40 x 640-node rule over the whole ellipse: the nonlinear law of the
    ball-by-ball reference (:func:`train_by_ball`). As :math:`\sigma\to\infty`,
    :math:`G_x\to1` and :math:`J_x\to\tfrac{2\pi}{3}\sigma`.

    Examples
    --------
    >>> j, g = rolling_creep_integrals(0.2, [0.01, 100.0])
    >>> [round(float(v), 3) for v in g]
    [0.015, 1.0]
    """
    beta = float(check_positive("aspect", aspect))
    sigma = np.asarray(slip, dtype=float)
    x, y, w = _REFERENCE_RULE
    flat = sigma.reshape(-1)
    power = np.empty(flat.shape)
    force = np.empty(flat.shape)
    for start in range(0, flat.size, 256):  # bounded memory, not a loop over points
        s = flat[start : start + 256, None]
        vx = s - y
        vy = beta * x
        speed = np.sqrt(vx * vx + vy * vy)
        power[start : start + 256] = speed @ w
        share = np.divide(vx, speed, out=np.zeros_like(speed), where=speed > 0.0)
        force[start : start + 256] = share @ w
    return power.reshape(sigma.shape), force.reshape(sigma.shape) * (1.5 / math.pi)


_REFERENCE_RULE = rl._disk_rule(40, 640, half=False)


def bridge_maximum(balls: npt.ArrayLike) -> FloatArray:
    r"""Expected maximum of the partial sums of a random-walk bridge [-].

    For :math:`N` independent offsets of unit variance less their mean, the
    partial sums :math:`S_k` (:math:`S_0 = S_N = 0`) have the variance
    :math:`k(N-k)/N`, and for increments that are exchangeable and sum to zero
    the expected maximum is :math:`\sum_{k=1}^{N-1}\mathrm E[S_k^+]/k` (the
    bridge form of Spitzer's identity, F. Spitzer, Trans. Amer. Math. Soc. 82
    (1956) 323-339; checked against simulation in the tests):

    .. math:: M_N = \frac{1}{\sqrt{2\pi}}\sum_{k=1}^{N-1}\sqrt{\frac{N-k}{Nk}}
              \;\to\;\sqrt{\frac{\pi N}{8}}

    (the Brownian bridge's). 0 for one ball.

    Examples
    --------
    >>> [round(float(v), 4) for v in bridge_maximum([1, 2, 10])]
    [0.0, 0.2821, 1.3949]
    """
    n = np.asarray(balls, dtype=float)
    if np.any(n < 1.0):
        raise ValueError("a train has at least one ball")
    top = int(n.max()) if n.size else 1
    k = np.arange(1, max(top, 2), dtype=float)
    # Cumulative sums of sqrt(N-k)/sqrt(k) need N inside: sum over k < N, vectorised.
    terms = np.sqrt(np.maximum(n[..., None] - k, 0.0) / (n[..., None] * k))
    result: FloatArray = terms.sum(axis=-1) / math.sqrt(2.0 * math.pi)
    return result


@dataclass(frozen=True)
class TrainMeans:
    r"""Expected forces and dissipation of one circuit's loaded train (:func:`expected_train`).

    Attributes
    ----------
    compression : numpy.ndarray
        Mean compression of a contact between neighbouring loaded balls, :math:`\bar P` [N].
    traction : numpy.ndarray
        Mean magnitude of one ball's groove traction, :math:`\mathrm E|T_i|` [N].
    creep_power : numpy.ndarray
        Mean creep dissipation of one ball over the screw speed [N·m].
    """

    compression: FloatArray
    traction: FloatArray
    creep_power: FloatArray


def expected_train(stiffness: npt.ArrayLike, speed_spread: npt.ArrayLike, balls: int) -> TrainMeans:
    r"""Expected forces of a train of ``balls`` balls with random natural speeds (closed form).

    Parameters
    ----------
    stiffness : array_like
        Ball stiffness to creep times the screw speed, :math:`K\omega` [N]
        (:math:`K` in N per m/s).
    speed_spread : array_like
        Standard deviation of the balls' natural centre speeds over the screw
        speed, :math:`v_ck\sigma_\alpha/\omega` [m].
    balls : int
        Loaded balls in the train, :math:`N`.

    Returns
    -------
    TrainMeans
        :math:`\bar P = K v_ck\sigma_\alpha M_N`, :math:`\mathrm E|T| = Kv_ck\sigma_\alpha
        \sqrt{2(1-1/N)/\pi}` and :math:`\tfrac12K(v_ck\sigma_\alpha)^2(1-1/N)/\omega`.

    Examples
    --------
    >>> m = expected_train(1000.0, 1e-5, 10)
    >>> round(float(m.compression), 5), round(float(m.traction), 5)
    (0.01395, 0.00757)
    """
    n = int(check_positive("balls", balls))
    k_w = np.asarray(check_nonnegative("stiffness", stiffness, "N"), dtype=float)
    spread = np.asarray(check_nonnegative("speed_spread", speed_spread, "m"), dtype=float)
    force = k_w * spread
    keep = 1.0 - 1.0 / n
    return TrainMeans(
        compression=force * float(bridge_maximum(n)),
        traction=force * math.sqrt(2.0 * keep / math.pi),
        creep_power=0.5 * force * spread * keep,
    )


@dataclass(frozen=True)
class TrainSolution:
    r"""One drawn train solved ball by ball (:func:`train_by_ball`).

    Attributes
    ----------
    speed : float
        Common speed of the train less the mean natural speed, over the screw speed [m].
    traction : numpy.ndarray
        Each ball's groove traction, forward positive [N].
    compression : numpy.ndarray
        Compression of each of the :math:`N - 1` contacts between neighbours, rear to front [N].
    creep_power : float
        Creep dissipation of the train's balls over the screw speed [N·m].
    """

    speed: float
    traction: FloatArray
    compression: FloatArray
    creep_power: float


@dataclass(frozen=True)
class _Contact:
    capacity: float  # mu Q [N]
    scale: float  # |omega_s| a / omega [m]
    aspect: float


def train_by_ball(
    natural: npt.ArrayLike,
    contacts: tuple[tuple[float, float, float], tuple[float, float, float]],
) -> TrainSolution:
    r"""Solve one train ball by ball with the nonlinear creep law (the reference).

    Every ball has the same two contacts (screw, nut), each given as
    (:math:`\mu Q` [N], :math:`|\omega_s|a/\omega` [m], :math:`\beta`); the
    balls differ in their natural centre speeds ``natural`` (over the screw
    speed, rear to front, [m]). For a trial common speed each ball's creep
    :math:`2\delta` is shared between its contacts so that their forces
    :math:`\mu QG_x(\beta, \Delta v/\omega_sa)` are equal (bisection, all balls at
    once); the common speed makes the tractions sum to zero (Brent); the
    compressions are the cumulative sums raised to be non-negative. The
    integrals come from tables of :func:`rolling_creep_integrals` (direct
    quadrature, not the closed-form slope :func:`expected_train` uses).
    """
    from scipy.optimize import brentq

    v = np.asarray(natural, dtype=float)
    pair = [_Contact(*c) for c in contacts]
    tables = [_creep_table(c.aspect) for c in pair]

    def force_of(c: _Contact, table: tuple[FloatArray, ...], creep: FloatArray) -> FloatArray:
        s, _, g = table
        sigma = np.abs(creep) / c.scale
        result: FloatArray = np.sign(creep) * c.capacity * np.interp(sigma, s, g)
        return result

    def split(total: FloatArray) -> FloatArray:
        """The screw contact's creep when the two creeps add up to ``total``."""
        lo = np.minimum(total, 0.0)
        hi = np.maximum(total, 0.0)
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            excess = force_of(pair[0], tables[0], mid) - force_of(pair[1], tables[1], total - mid)
            lo, hi = np.where(excess > 0.0, lo, mid), np.where(excess > 0.0, mid, hi)
        result: FloatArray = 0.5 * (lo + hi)
        return result

    def traction(speed: float) -> tuple[FloatArray, FloatArray]:
        total = 2.0 * (speed - v)
        creep = split(total)
        return -2.0 * force_of(pair[0], tables[0], creep), creep

    span = 2.0 * float(np.ptp(v)) + 1e-30
    mean = float(v.mean())
    speed = brentq(
        lambda u: float(traction(u)[0].sum()), mean - span, mean + span, xtol=1e-16 * span
    )
    t, creep = traction(speed)
    sums = np.concatenate(([0.0], np.cumsum(t)))
    sums[-1] = 0.0
    compression = sums[1:-1] - sums.min()
    power = 0.0
    for c, table, dv in zip(pair, tables, (creep, 2.0 * (speed - v) - creep), strict=True):
        s, j, _ = table
        sigma = np.abs(dv) / c.scale
        power += float(
            np.sum(c.capacity * 1.5 / math.pi * c.scale * (np.interp(sigma, s, j) - j[0]))
        )
    return TrainSolution(speed=speed - mean, traction=t, compression=compression, creep_power=power)


@functools.lru_cache(maxsize=16)
def _creep_table(aspect: float) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Sigma nodes (dense near 0) and J_x, G_x there, by direct quadrature."""
    s = np.concatenate((np.linspace(0.0, 0.2, 801)[:-1], np.geomspace(0.2, 1e3, 400)))
    j, g = rolling_creep_integrals(aspect, s)
    g[0] = 0.0
    return s, j, g
