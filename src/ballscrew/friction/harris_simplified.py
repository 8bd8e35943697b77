r"""The study's simplified friction model after Harris (its eqs. 5 to 8).

At each Hertz contact the friction force is the asperity friction plus the
lubricant shear, integrated over the contact ellipse:

.. math::
    F = ab\iint_{t^2+q^2\le1}\left[c_v\frac{A_c}{A_0}\mu_0 p
        + \left(1 - \frac{A_c}{A_0}\right)\left(\tau_N^{-1} +
        \tau_{lim}^{-1}\right)^{-1}\right]dt\,dq

with :math:`p = p_0\sqrt{1 - t^2 - q^2}`, :math:`A_c/A_0 =
\exp(-B\Lambda^C)`, :math:`\tau_N = \eta(p)\dot\gamma`, :math:`\tau_{lim} =
\tau_0 + \gamma_L p` and the shear rate :math:`\dot\gamma = v_c/h_{min}`
(eq. 8). The study's assumptions are the defaults: :math:`c_v = 0.3`,
:math:`B = 1.42`, :math:`\mu_0 = 0.1`, Houpert's Hertz fits, and the same
shear rate over the whole ellipse. Since nothing but the pressure varies over
the ellipse, the double integral reduces exactly to one over the pressure,
:math:`F = 2\pi ab\int_0^1 g(p_0 s)\,s\,ds`, evaluated by Gauss-Legendre
quadrature; the asperity term integrates in closed form to
:math:`c_v (A_c/A_0)\mu_0 Q`.

Two readings of the study decide the result's magnitude and are options:

``sliding_sign_on_lubricant``
    Eq. (5) as printed applies :math:`c_v` to the asperity term only
    (``False``, default); the text calls :math:`c_v` the sign of the local
    sliding, which would apply to the lubricant shear too (``True``).
``shear_velocity``
    The "surface speed" :math:`v_c` of eq. (8) read as the rolling speed
    :math:`u` (``"rolling"``, default) or as the mean differential
    (Heathcote) sliding speed over the ellipse (``"sliding"``,
    :math:`\bar v_s = \overline{|q^2 - q_0^2|}\,C a^2` with the pure-rolling
    lines at :math:`q_0 = 0.347`, see
    :func:`ballscrew.kinematics.differential_sliding`).

With the rolling speed the shear rate :math:`u/h_{min}` is of order
:math:`10^6`-:math:`10^7` 1/s and the pressure-thickened oil saturates at
:math:`\tau_{lim}` over almost the whole ellipse, so the lubricant force
tends to :math:`(1 - A_c/A_0)(\tau_0\pi ab + \gamma_L Q)`: an equivalent
friction coefficient of :math:`\gamma_L` (0.07), an order of magnitude above
the 0.003 to 0.005 of a rolling ball screw (catalogue drag torques). It is
the traction of a contact in gross sliding at speed :math:`u`, not of a
rolling one; ``shear_velocity="sliding"`` gives rolling-contact magnitudes
for the lubricant term.

**What the simplifications cost.** Against the full integral with the local
sliding of each point (:mod:`.harris_full`: same asperity and shear laws,
differential sliding and spin, zero net traction on each ball), the
simplified model gives 66 to 3800 times the torque for the reference screw
(40 mm x 10 mm, 6.35 mm balls, PAO ISO VG 68) over 10 to 3000 rpm, 500 N to
5 kN preload and 20 to 45 °C (``examples/compare_simplified_full.py``); with
``shear_velocity="sliding"``, 61 to 131 times. Most of the gap is the
asperity term: :math:`c_v(A_c/A_0)\mu_0 Q` is a traction, and charging the
screw with it at the rolling speed treats the contact as sliding, while the
real sliding speeds (differential sliding and spin) are about 1 % of the
rolling speed. At 100 rpm and 2 kN the models give 3.6 and 0.031 N·m,
against 0.56 N·m from the catalogue formula.

References
----------
.. [1] J. Sušeň, "A Study on the Ball Screw Friction Torque", CTU Prague,
   eqs. (5)-(8).
.. [2] T. A. Harris, M. N. Kotzalas, *Advanced Concepts of Bearing
   Technology*, 5th ed., CRC Press, 2007, ch. 4-5.
.. [3] H. L. Heathcote, "The ball bearing: in the making, under test and on
   service", Proc. Inst. Automob. Eng. 15 (1921) 569-702.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from ..errors import (
    BallScrewInputError,
    FloatArray,
    check_choice,
    check_in_range,
    check_nonnegative,
)
from ..geometry import BallScrew
from ..kinematics import differential_sliding
from ..lubricant import Lubricant
from ..state import OperatingState
from ..validity import film_checks
from ._common import (
    RHEOLOGY_MODELS,
    contact_pressure_viscosity,
    limiting_shear,
    local_viscosity,
    model_state,
    shear_stress,
    torque_from_contact_forces,
)
from ._registry import register

__all__ = [
    "HEATHCOTE_ROLLING_LINE",
    "RHEOLOGY_MODELS",
    "harris_simplified",
    "local_viscosity",
    "mean_sliding_factor",
    "mean_sliding_speed",
    "shear_stress",
    "simplified_contact_force",
]

HEATHCOTE_ROLLING_LINE = 0.347
"""Position of the two pure-rolling lines, as a fraction of the semi-major axis (Heathcote)."""


BLOCK_POINTS = 4096
"""Points whose (points x nodes) shear stresses are worked out at once on scattered points.

The product over the Gauss nodes (``tau @ ws``) of more rows wakes OpenBLAS's threads, which
spin and bill their CPU to the process: on 1e5 scattered points a call took 0.20 s of user
CPU with OpenBLAS's default threads and 0.09 s in blocks (or with ``OPENBLAS_NUM_THREADS=1``),
the same numbers to the last bit. The blocks' temporaries (0.25 MB) also stay in the cache,
and the allocator hands the same memory back block after block: with 8192 points a block
(0.5 MB temporaries) each 1e5-point call took 38 000 fresh pages from the system (0.04-0.06
s of system time, a third of the call), with 4096 points 16 000 (0.01-0.02 s)."""


@functools.cache
def mean_sliding_factor(q0: float = HEATHCOTE_ROLLING_LINE) -> float:
    r"""Area mean of :math:`|q^2 - q_0^2|` over the unit disk [-].

    .. math:: \frac{2}{\pi}\int_{-1}^{1}|q^2 - q_0^2|\sqrt{1-q^2}\,dq

    (0.19966 for :math:`q_0 = 0.347`), by adaptive quadrature split at the
    kinks :math:`\pm q_0`.

    >>> round(mean_sliding_factor(), 5)
    0.19966
    """

    def integrand(q: float) -> float:
        return abs(q * q - q0 * q0) * float(np.sqrt(1.0 - q * q)) * 2.0 / np.pi

    from scipy import integrate  # imported on first use: slow to import

    value, _ = integrate.quad(integrand, -1.0, 1.0, points=[-q0, q0])
    return float(value)


def mean_sliding_speed(curvature_coefficient: npt.ArrayLike, a: npt.ArrayLike) -> FloatArray:
    r"""Area-mean differential sliding speed over a contact ellipse [m/s].

    Heathcote slip across the contact, :math:`v(y) = C\,(y^2 - q_0^2a^2)`
    with the rolling lines at :math:`y = \pm q_0 a`, averaged in magnitude
    over the ellipse: :math:`\bar v = |C|\,a^2\,\overline{|q^2 - q_0^2|}`
    (:func:`mean_sliding_factor`).

    Parameters
    ----------
    curvature_coefficient : array_like
        :math:`C` [1/(m·s)] of :func:`ballscrew.kinematics.differential_sliding`.
    a : array_like
        Semi-axis across the groove [m].
    """
    c = np.asarray(curvature_coefficient, dtype=float)
    aa = np.asarray(a, dtype=float)
    result: FloatArray = mean_sliding_factor() * np.abs(c) * aa**2
    return result


@functools.cache
def _pressure_nodes(nodes: int) -> tuple[FloatArray, FloatArray]:
    """Gauss-Legendre nodes and weights on [0, 1], weights multiplied by 2 s (disk mean)."""
    x, w = np.polynomial.legendre.leggauss(nodes)
    s = 0.5 * (x + 1.0)
    return s, w * s  # 2 * (w/2) * s


def simplified_contact_force(
    *,
    a: npt.ArrayLike,
    b: npt.ArrayLike,
    p_max: npt.ArrayLike,
    asperity_share: npt.ArrayLike,
    viscosity: npt.ArrayLike,
    pressure_viscosity: npt.ArrayLike,
    shear_rate: npt.ArrayLike,
    tau0: float,
    gamma_l: float,
    mu0: float = 0.1,
    sliding_coefficient: float = 0.3,
    sliding_sign_on_lubricant: bool = False,
    rheology_model: str = "harmonic",
    rheology_exponent: float = 1.0,
    eyring_stress: float | None = None,
    pressure_viscosity_model: str = "roelands",
    nodes: int = 8,
) -> tuple[FloatArray, FloatArray]:
    r"""Asperity and lubricant friction force of one contact ellipse (study eq. 5) [N].

    Parameters
    ----------
    a, b : array_like
        Semi-axes [m].
    p_max : array_like
        Maximum Hertz pressure [Pa].
    asperity_share : array_like
        :math:`A_c/A_0` [-].
    viscosity : array_like
        Viscosity at ambient pressure :math:`\eta_0` [Pa·s].
    pressure_viscosity : array_like
        :math:`\alpha` [1/Pa] at the oil's temperature, one value or one per
        ``viscosity`` (:func:`~._common.contact_pressure_viscosity`).
    shear_rate : array_like
        :math:`\dot\gamma` [1/s].
    tau0, gamma_l : float
        Limiting shear stress :math:`\tau_0` [Pa] and slope :math:`\gamma_L` [-].
    mu0 : float
        Boundary friction coefficient :math:`\mu_0` [-].
    sliding_coefficient : float
        :math:`c_v` [-].
    sliding_sign_on_lubricant : bool
        Apply :math:`c_v` to the lubricant term too.
    rheology_model, rheology_exponent, eyring_stress
        See :func:`shear_stress`.
    pressure_viscosity_model : {"roelands", "barus"}
        Local viscosity law.
    nodes : int
        Gauss-Legendre nodes in the pressure coordinate; the default 8
        integrate the lubricant term to a relative 7e-4 (12 nodes: 4e-5;
        PAO ISO VG 68 and SAE 20 at 20-45 °C, 0.1-320 rad/s, against 96
        nodes; ``tests/friction/test_models.py``).

    Returns
    -------
    asperity, lubricant : numpy.ndarray
        The two terms of the force [N].
    """
    s, ws = _pressure_nodes(nodes)
    # Not broadcast against each other: the local viscosity (the costly part)
    # depends on the temperature and the load only, not on the speed.
    aa, bb, p0, share, rate, eta0 = (
        np.asarray(x, dtype=float) for x in (a, b, p_max, asperity_share, shear_rate, viscosity)
    )
    area = np.pi * aa * bb
    # Unloaded contacts (p0 = 0) have no area; give them a dummy pressure so
    # that tau_lim > 0 everywhere, their force is zero through the area.
    p0 = np.where(p0 > 0.0, p0, 1.0)
    load = 2.0 / 3.0 * np.where(area > 0.0, p0, 0.0) * area  # Q = (2/3) p0 pi a b
    alpha = np.asarray(pressure_viscosity, dtype=float)
    law = _ShearLaw(
        tau0, gamma_l, rheology_model, rheology_exponent, eyring_stress,
        pressure_viscosity_model, moving=bool(np.all(rate != 0)),
    )  # fmt: skip
    shape = np.broadcast_shapes(p0.shape, eta0.shape, alpha.shape, rate.shape)
    size = math.prod(shape)
    if (
        size <= BLOCK_POINTS
        or math.prod(np.broadcast_shapes(p0.shape, eta0.shape, alpha.shape)) < size
    ):
        # One block, or a grid whose local viscosity is worked out on fewer values than
        # there are points: unexpanded, as given.
        lub_integral = law.disk_mean(p0, eta0, alpha, rate, s, ws)
    else:
        # Every point has a pressure of its own (scattered points): the (points x nodes)
        # temporaries in blocks that stay in the cache, each point's numbers as in one go.
        flat = [np.broadcast_to(x, shape).reshape(-1) for x in (p0, eta0, alpha, rate)]
        lub_integral = np.empty(size)
        for start in range(0, size, BLOCK_POINTS):
            part = slice(start, start + BLOCK_POINTS)
            p0b, eta0b, alphab, rateb = (x[part] for x in flat)
            lub_integral[part] = law.disk_mean(p0b, eta0b, alphab, rateb, s, ws)
        lub_integral = lub_integral.reshape(shape)
    asperity = sliding_coefficient * share * mu0 * load
    lubricant = (1.0 - share) * area * lub_integral
    if sliding_sign_on_lubricant:
        lubricant = sliding_coefficient * lubricant
    return asperity, lubricant


@dataclass(frozen=True)
class _ShearLaw:
    """The lubricant's shear stress over a contact's pressures: the kernel of eq. (5)."""

    tau0: float
    gamma_l: float
    rheology_model: str
    rheology_exponent: float
    eyring_stress: float | None
    pressure_viscosity_model: str
    moving: bool
    """No shear rate is 0 (over all the points, so that every block takes one formula)."""

    def disk_mean(
        self,
        p0: FloatArray,
        eta0: FloatArray,
        alpha: FloatArray,
        rate: FloatArray,
        s: FloatArray,
        ws: FloatArray,
    ) -> FloatArray:
        r"""Mean shear stress over the disk, :math:`2\int_0^1\tau(p_0 s)\,s\,ds` [Pa]."""
        p = p0[..., None] * s
        tau_lim = p * self.gamma_l
        tau_lim += self.tau0
        # A new array of the full shape, so the steps below may work in place.
        visc = local_viscosity(eta0, alpha, p, self.pressure_viscosity_model)
        tau_n = visc * np.abs(rate)[..., None]
        if self.rheology_model == "harmonic":
            # tau_N tau_lim / (tau_N + tau_lim), written to stay finite for tau_N = inf.
            if self.moving:
                tau = np.divide(tau_lim, tau_n, out=tau_n)
                tau += 1.0
                np.divide(tau_lim, tau, out=tau)
            else:
                tau = _harmonic(tau_n, tau_lim)
        else:
            # The laws take eta and the shear rate; pass tau_N as eta x 1/s, capped
            # where the pressure-viscosity law overflowed (the stress is saturated there).
            tau = np.abs(
                shear_stress(
                    self.rheology_model,
                    np.minimum(tau_n, 1e30),
                    1.0,
                    tau_lim,
                    self.rheology_exponent,
                    self.eyring_stress,
                )
            )
        result: FloatArray = tau @ ws  # mean of tau over the disk: 2 ∫ tau(p0 s) s ds
        return result


def _harmonic(tau_n: FloatArray, tau_lim: FloatArray) -> FloatArray:
    """Harmonic combination that is 0 where tau_N is 0."""
    with np.errstate(divide="ignore"):
        result: FloatArray = np.where(tau_n > 0.0, tau_lim / (1.0 + tau_lim / tau_n), 0.0)
    return result


@register(
    "harris-simplified",
    title="Sušeň's simplified model after Harris: asperity friction + non-Newtonian shear",
    reference="J. Sušeň, A Study on the Ball Screw Friction Torque, CTU Prague, eqs. (5)-(8); "
    "T. A. Harris, M. N. Kotzalas, Advanced Concepts of Bearing Technology, CRC, 2007",
    validity="EHL/mixed lubrication, Hamrock-Dowson film (ellipticity 1-8); Roelands viscosity",
    purpose="to reproduce the study (Sušeň's Figs. 6-8); not for prediction",
    checks=(film_checks,),
)
def harris_simplified(
    screw: BallScrew, lubricant: Lubricant, speed: FloatArray, temperature: FloatArray,
    axial_load: FloatArray, *, state: OperatingState | None = None,
    mu0: float = 0.1,
    sliding_coefficient: float = 0.3,
    sliding_sign_on_lubricant: bool = False,
    shear_velocity: str = "rolling",
    rheology_model: str = "harmonic",
    rheology_exponent: float = 1.0,
    eyring_stress: float | None = None,
    pressure_viscosity_model: str = "roelands",
    limiting_shear_stress: float | None = None,
    limiting_shear_coefficient: float | None = None,
    asperity_b: float = 1.42,
    asperity_c: float = 0.8,
    hertz_method: str = "houpert",
    torque_arm: str = "energy",
    nodes: int = 8,
) -> dict[str, FloatArray]:  # fmt: skip
    r"""Friction torque by the study's simplified model (module docstring).

    Parameters
    ----------
    screw, lubricant, speed, temperature, axial_load
        The operating points (see :func:`ballscrew.friction_torque`).
    mu0 : float
        Boundary friction coefficient :math:`\mu_0`; 0.1 (study).
    sliding_coefficient : float
        :math:`c_v`; 0.3 (study: 65 % of the ellipse slips against rolling,
        35 % with it).
    sliding_sign_on_lubricant : bool
        Apply :math:`c_v` to the lubricant shear too; default False (eq. 5 as printed).
    shear_velocity : {"rolling", "sliding"}
        Velocity of eq. (8); default ``"rolling"`` (the study's "surface speed").
    rheology_model : {"harmonic", "general", "eyring", "bair-winer"}
        Shear law; default ``"harmonic"`` (eq. 5).
    rheology_exponent : float
        :math:`n` of the general model (eq. 7).
    eyring_stress : float, optional
        :math:`\tau_E` [Pa] of the Eyring law; required with ``rheology_model="eyring"``.
    pressure_viscosity_model : {"roelands", "barus"}
        Default Roelands (his index :math:`Z` constant across temperature,
        :func:`ballscrew.lubricant.roelands_alpha`): Barus overflows at
        contact pressures. Barus takes the oil's ``pressure_viscosity`` as given.
    limiting_shear_stress, limiting_shear_coefficient : float, optional
        :math:`\tau_0` [Pa] and :math:`\gamma_L` [-]; default: the lubricant's.
    asperity_b, asperity_c : float
        :math:`B`, :math:`C` of :math:`A_c/A_0`; 1.42 (study) and 0.8.
    hertz_method : str
        Default ``"houpert"`` (study).
    torque_arm : {"energy", "contact-radius", "ball-radius"}
        See :func:`ballscrew.friction._common.torque_from_contact_forces`.
    nodes : int
        Gauss-Legendre nodes over the pressure (default 8, see
        :func:`simplified_contact_force`).

    Returns
    -------
    dict
        ``"asperity"`` and ``"lubricant"`` torques [N·m].
    """
    check_choice("shear_velocity", shear_velocity, ("rolling", "sliding"))
    check_choice("rheology_model", rheology_model, RHEOLOGY_MODELS)
    check_choice("pressure_viscosity_model", pressure_viscosity_model, ("roelands", "barus"))
    check_nonnegative("mu0", mu0)
    # c_v < 0 (more of the ellipse slipping with the rolling than against it) would make
    # the sliding friction drive the screw: a negative friction torque.
    check_in_range(
        "sliding_coefficient", sliding_coefficient, 0.0, 1.0, inclusive=(True, True),
        unit="(0 to 1: below 0 the sliding friction would drive the screw)",
    )  # fmt: skip
    tau0, gamma_l = limiting_shear(lubricant, limiting_shear_stress, limiting_shear_coefficient)
    if isinstance(nodes, bool) or not isinstance(nodes, int) or nodes < 2:
        raise BallScrewInputError("nodes", nodes, "a whole number >= 2")

    state = model_state(
        screw, lubricant, speed, temperature, axial_load, hertz_method=hertz_method,
        asperity_b=asperity_b, asperity_c=asperity_c, state=state,
    )  # fmt: skip
    c_screw, c_nut = differential_sliding(screw, state.kinematics.screw_speed)
    asperity_forces, lubricant_forces = [], []
    for contact in state.contacts:
        if shear_velocity == "rolling":
            velocity = np.abs(contact.entrainment_speed)
        else:
            c = c_screw if contact.side == "screw" else c_nut
            velocity = mean_sliding_speed(c, contact.hertz.a)
        loaded = contact.film_minimum > 0.0
        rate = np.where(loaded, velocity / np.where(loaded, contact.film_minimum, 1.0), 0.0)
        asp, lub = simplified_contact_force(
            a=contact.hertz.a,
            b=contact.hertz.b,
            p_max=contact.hertz.p_max,
            asperity_share=contact.asperity_share,
            viscosity=contact.viscosity,
            pressure_viscosity=contact_pressure_viscosity(
                lubricant, contact.viscosity, pressure_viscosity_model
            ),
            shear_rate=rate,
            tau0=tau0,
            gamma_l=gamma_l,
            mu0=mu0,
            sliding_coefficient=sliding_coefficient,
            sliding_sign_on_lubricant=sliding_sign_on_lubricant,
            rheology_model=rheology_model,
            rheology_exponent=rheology_exponent,
            eyring_stress=eyring_stress,
            pressure_viscosity_model=pressure_viscosity_model,
            nodes=nodes,
        )
        asperity_forces.append(asp)
        lubricant_forces.append(lub)
    return {
        "asperity": torque_from_contact_forces(state, asperity_forces, torque_arm),
        "lubricant": torque_from_contact_forces(state, lubricant_forces, torque_arm),
    }
