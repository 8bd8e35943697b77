r"""Full Harris-type friction: local sliding, local viscosity, 2-D integration.

The physics of the study's simplified model (:mod:`.harris_simplified`),
asperity friction :math:`\mu_0 p` on the asperity share :math:`A_c/A_0` and
non-Newtonian lubricant shear on the rest, integrated over each ellipse
without that model's simplifications. It is a research tool, not a
prediction: it has no EHL rolling resistance and its sliding friction
vanishes as the film grows (the full film carries almost no traction at the
low pressures where spin is fastest), so it lies one to two orders of
magnitude below measured drag torques and its torque falls with speed and
rises with temperature, the reverse of measurements. To predict, use
``"complete"`` (:mod:`.complete`), whose sliding term is this quadrature's
centre-pivot form with a full-film traction.

At a point :math:`(x, y)` of a contact ellipse (:math:`x`
rolling, :math:`y` across the groove) the ball slides over the groove at

.. math::
    v_x = s - C y^2 - \omega_s y,\qquad v_y = \omega_s x

with :math:`C` the differential (Heathcote) sliding coefficient and
:math:`\omega_s` the spin (:func:`ballscrew.kinematics.differential_sliding`,
:class:`ballscrew.kinematics.Kinematics`) and :math:`s` a uniform slip. The
local shear stress acts along the sliding direction with magnitude

.. math::
    \tau = \frac{A_c}{A_0}\mu_0 p + \left(1 - \frac{A_c}{A_0}\right)
           \tau_f\!\left(\eta(p), \frac{|v|}{h}, \tau_{lim}(p)\right)

with :math:`\eta(p)` by Roelands (his index :math:`Z` constant across
temperature, :func:`ballscrew.lubricant.roelands_alpha`), :math:`\tau_{lim} = \tau_0 + \gamma_L p`,
the film :math:`h` (central by default) and the rheology of
:func:`~.harris_simplified.shear_stress`.

A ball free to turn and to orbit carries no net rolling-direction force at
either contact (its force and moment balance, with inertia, ball-ball
forces and rolling resistance left out); this fixes the slip :math:`s` of
each contact, found by the Illinois method on all operating points at once,
and with it the two pure-rolling lines. The power dissipated is
:math:`P = \iint \tau |v|\,dA` per contact; the screw supplies it, so the
torque is :math:`T = \sum Z P/|\omega|`. Sliding speeds scale with
:math:`\omega`, so the ratio is evaluated directly and stays finite at zero
speed (where only the asperity friction remains).

The ellipse is integrated in polar coordinates with :math:`r =
\sqrt{1 - \sigma^2}` (so that :math:`p = p_0\sigma` and :math:`dA = ab\,
\sigma\,d\sigma\,d\phi`), Gauss-Legendre in :math:`\sigma` and the
midpoint rule in :math:`\phi` (the integrand has kinks along the
pure-rolling lines); the default ``nodes=(8, 8)`` is within 0.25 % of a
(32, 256) grid for PAO ISO VG 68 and SAE 20 at 20-45 °C, 0.1-320 rad/s,
0 and 3 kN axial load.

References
----------
.. [1] T. A. Harris, M. N. Kotzalas, *Advanced Concepts of Bearing
   Technology*, 5th ed., CRC Press, 2007, ch. 4-5 (friction in ball-raceway
   contacts).
.. [2] J. Sušeň, "A Study on the Ball Screw Friction Torque", CTU Prague,
   eq. (5).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from ..errors import BallScrewInputError, FloatArray, check_choice, check_nonnegative
from ..geometry import BallScrew
from ..kinematics import differential_sliding, kinematics
from ..lubricant import Lubricant
from ..numerics import illinois
from ..state import ContactState, OperatingState
from ..validity import film_checks
from ._common import (
    RHEOLOGY_MODELS,
    contact_pressure_viscosity,
    limiting_shear,
    local_viscosity,
    model_state,
    shear_stress,
)
from ._registry import register

__all__ = ["full_contact_power", "harris_full"]


def full_contact_power(
    *,
    a: FloatArray,
    b: FloatArray,
    p_max: FloatArray,
    asperity_share: FloatArray,
    viscosity: FloatArray,
    pressure_viscosity: float | FloatArray,
    film: FloatArray,
    curvature: float,
    spin: float,
    screw_speed: FloatArray,
    tau0: float,
    gamma_l: float,
    mu0: float,
    rheology_model: str = "harmonic",
    rheology_exponent: float = 1.0,
    eyring_stress: float | None = None,
    nodes: tuple[int, int] = (8, 8),
    tolerance: float = 1e-6,
) -> tuple[FloatArray, FloatArray, FloatArray]:
    r"""Power per unit screw speed dissipated in one contact ellipse [W·s/rad = N·m].

    Parameters
    ----------
    a, b, p_max, asperity_share : numpy.ndarray
        Semi-axes [m] (``a`` across the groove), maximum pressure [Pa],
        :math:`A_c/A_0` [-].
    viscosity : numpy.ndarray
        Ambient-pressure viscosity [Pa·s].
    pressure_viscosity : float or numpy.ndarray
        :math:`\alpha` [1/Pa] (Roelands) at the oil's temperature, one value
        or one per ``viscosity`` (:func:`~._common.contact_pressure_viscosity`).
    film : numpy.ndarray
        Film thickness [m].
    curvature, spin : float
        :math:`C/\omega` [1/(m·rad)] and :math:`\omega_s/\omega` [-]: the
        differential sliding coefficient and the spin per unit screw speed
        (properties of the geometry).
    screw_speed : numpy.ndarray
        :math:`\omega` [rad/s].
    tau0, gamma_l, mu0 : float
        Limiting shear :math:`\tau_0` [Pa], :math:`\gamma_L`, :math:`\mu_0`.
    rheology_model, rheology_exponent, eyring_stress
        See :func:`~.harris_simplified.shear_stress`.
    nodes : (int, int)
        Nodes in :math:`\sigma` (pressure) and :math:`\phi`.
    tolerance : float
        Relative tolerance of the zero-traction slip.

    Returns
    -------
    asperity, lubricant : numpy.ndarray
        :math:`P/|\omega|` of the two terms [N·m].
    slip : numpy.ndarray
        The uniform slip per unit screw speed :math:`s/|\omega|` [m/rad].
    """
    omega = np.abs(screw_speed)
    c_hat = abs(curvature)  # sliding speeds per unit |omega|
    w_hat = abs(spin)
    sig, weight, base_x, vy2 = _ellipse_nodes(a, b, c_hat, w_hat, nodes)
    # Unloaded contacts: dummy pressure (their area a*b is zero, so is their power).
    p = np.where(p_max > 0.0, p_max, 1.0)[:, None] * sig[None, :]
    eta = local_viscosity(viscosity, pressure_viscosity, p, "roelands")
    rate_scale = np.where(film > 0.0, omega / np.where(film > 0, film, 1.0), 0.0)
    eta_rate = np.minimum(eta * rate_scale[:, None], 1e300)[:, :, None]  # tau_N per unit |v|
    tau_lim = (tau0 + gamma_l * p)[:, :, None]
    asp_stress = ((asperity_share * mu0)[:, None] * p)[:, :, None]
    fluid_share = (1.0 - asperity_share)[:, None, None]
    # Harmonic law: fluid stress / |v| = eta_rate * tau_lim / (eta_rate |v| + tau_lim).
    fluid_numerator = fluid_share * eta_rate * tau_lim
    f = _Integrand(
        base_x, vy2, eta_rate, tau_lim, asp_stress, fluid_share, fluid_numerator, weight,
        rheology_model, rheology_exponent, eyring_stress,
    )  # fmt: skip

    # Zero net traction fixes the slip: bracket it between all-backward and
    # all-forward sliding, then Illinois regula falsi on the points not yet
    # converged. The dissipated power is stationary in the slip at the
    # solution (its derivative is the net traction), so a slip good to 1e-6
    # of the bracket gives the power to about 1e-12.
    span = c_hat * a**2 + w_hat * a + 1e-300
    lo, hi = -span.copy(), span.copy()
    everything = slice(None)
    s_hat = illinois(
        f.traction, lo, hi, f.traction(lo, everything), f.traction(hi, everything),
        xtol=tolerance * span,
    )  # fmt: skip
    _, speed, lub = f.stresses(s_hat, everything)
    area = a * b
    asperity = np.einsum("ijk,jk->i", asp_stress * speed, weight) * area
    lubricant = np.einsum("ijk,jk->i", fluid_share * lub * speed, weight) * area
    return asperity, lubricant, s_hat


def _ellipse_nodes(
    a: FloatArray, b: FloatArray, c_hat: float, w_hat: float, nodes: tuple[int, int]
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    r"""The quadrature over the ellipses and the sliding at its nodes.

    Returns :math:`\sigma` (the pressure fraction of each radial node), the
    weights (n_s, n_phi), and :math:`v_x` without slip and :math:`v_y^2`,
    both per unit :math:`|\omega|`, at every point and node.
    """
    n_s, n_phi = nodes
    sig, w_sig = np.polynomial.legendre.leggauss(n_s)
    sig = 0.5 * (sig + 1.0)
    w_sig = 0.5 * w_sig
    phi = (np.arange(n_phi) + 0.5) * (np.pi / n_phi) - np.pi / 2  # x >= 0 half; x -> -x symmetric
    w_phi = 2.0 * np.pi / n_phi  # doubled for the mirrored half
    r = np.sqrt(1.0 - sig**2)
    y = a[:, None, None] * (r[:, None] * np.sin(phi)[None, :])
    base_x = -c_hat * y**2 - w_hat * y  # v_x / |omega| without slip
    # v_y^2 > 0 at every node (r > 0, |phi| < pi/2, spin > 0); the floor keeps
    # unloaded contacts (b = 0, no area) away from 0/0.
    vy2 = (w_hat * b[:, None, None] * (r[:, None] * np.cos(phi)[None, :])) ** 2 + 1e-300
    weight = (w_sig * sig)[:, None] * w_phi  # (n_s, n_phi)
    return sig, weight, base_x, vy2


_Rows = slice | npt.NDArray[np.intp]


@dataclass(frozen=True)
class _Integrand:
    r"""The shear stresses over the ellipses' nodes, as functions of the slip.

    Arrays are (points, n_s, n_phi) or broadcast to it; speeds and stresses
    per unit :math:`|\omega|` where they scale with it.
    """

    base_x: FloatArray
    vy2: FloatArray
    eta_rate: FloatArray
    tau_lim: FloatArray
    asp_stress: FloatArray
    fluid_share: FloatArray
    fluid_numerator: FloatArray
    weight: FloatArray
    rheology_model: str
    rheology_exponent: float
    eyring_stress: float | None

    def stresses(self, s_hat: FloatArray, idx: _Rows) -> tuple[FloatArray, ...]:
        """Sliding :math:`v_x`, :math:`|v|` and the lubricant's stress at slip ``s_hat``."""
        vx = self.base_x[idx] + s_hat[:, None, None]
        speed = np.sqrt(vx * vx + self.vy2[idx])
        tau_n = self.eta_rate[idx] * speed
        lim = self.tau_lim[idx]
        if self.rheology_model == "harmonic":
            lub = tau_n * lim / (tau_n + lim)
        else:
            lub = np.abs(
                shear_stress(
                    self.rheology_model, tau_n, 1.0, lim, self.rheology_exponent,
                    self.eyring_stress,
                )
            )  # fmt: skip
        return vx, speed, lub

    def traction(self, s_hat: FloatArray, idx: _Rows) -> FloatArray:
        """Net rolling-direction traction of the points ``idx`` at slip ``s_hat``."""
        if self.rheology_model == "harmonic":
            vx = self.base_x[idx] + s_hat[:, None, None]
            speed = vx * vx
            speed += self.vy2[idx]
            np.sqrt(speed, out=speed)
            vx /= speed  # direction cosine
            den = self.eta_rate[idx] * speed
            den += self.tau_lim[idx]
            integrand = self.fluid_numerator[idx] / den
            integrand *= speed
            integrand += self.asp_stress[idx]
            integrand *= vx
            out: FloatArray = np.einsum("ijk,jk->i", integrand, self.weight)
            return out
        vx, speed, lub = self.stresses(s_hat, idx)
        total = self.asp_stress[idx] + self.fluid_share[idx] * lub
        result: FloatArray = np.einsum("ijk,jk->i", total * (vx / speed), self.weight)
        return result


@register(
    "harris-full",
    title="Full Harris-type integral of the study's asperity + shear physics (no rolling "
    "resistance; trends reversed)",
    reference="T. A. Harris, M. N. Kotzalas, Advanced Concepts of Bearing Technology, CRC, 2007, "
    "ch. 4-5",
    validity="EHL/mixed lubrication, Hamrock-Dowson film (ellipticity 1-8); Roelands viscosity; "
    "balls in free rolling (no ball-ball forces)",
    chunk=4096,
    purpose="research: the simplified model's physics without its simplifications; "
    "not for prediction",
    checks=(film_checks,),
)
def harris_full(
    screw: BallScrew, lubricant: Lubricant, speed: FloatArray, temperature: FloatArray,
    axial_load: FloatArray, *, state: OperatingState | None = None,
    mu0: float = 0.1,
    rheology_model: str = "harmonic",
    rheology_exponent: float = 1.0,
    eyring_stress: float | None = None,
    limiting_shear_stress: float | None = None,
    limiting_shear_coefficient: float | None = None,
    asperity_b: float = 1.42,
    asperity_c: float = 0.8,
    film: str = "central",
    hertz_method: str = "exact",
    nodes: tuple[int, int] = (8, 8),
) -> dict[str, FloatArray]:  # fmt: skip
    r"""Friction torque by the full Harris-type integral (module docstring).

    Parameters
    ----------
    screw, lubricant, speed, temperature, axial_load
        The operating points (see :func:`ballscrew.friction_torque`).
    mu0 : float
        Boundary friction coefficient :math:`\mu_0`; 0.1 (as the study).
    rheology_model, rheology_exponent, eyring_stress
        Shear law, see :func:`~.harris_simplified.shear_stress`.
    limiting_shear_stress, limiting_shear_coefficient : float, optional
        :math:`\tau_0` [Pa], :math:`\gamma_L`; default: the lubricant's.
    asperity_b, asperity_c : float
        :math:`B`, :math:`C` of :math:`A_c/A_0`.
    film : {"central", "minimum"}
        Film thickness for the shear rate (default central: the film over
        the Hertz zone).
    hertz_method : str
        Default ``"exact"``.
    nodes : (int, int)
        Quadrature nodes (pressure, angle).

    Returns
    -------
    dict
        ``"asperity"`` and ``"lubricant"`` torques [N·m].
    """
    check_choice("rheology_model", rheology_model, RHEOLOGY_MODELS)
    check_choice("film", film, ("central", "minimum"))
    tau0, gamma_l = limiting_shear(lubricant, limiting_shear_stress, limiting_shear_coefficient)
    mu = float(check_nonnegative("mu0", mu0))
    n_nodes = _node_counts(nodes)
    state = model_state(
        screw, lubricant, speed, temperature, axial_load, hertz_method=hertz_method,
        asperity_b=asperity_b, asperity_c=asperity_c, state=state,
    )  # fmt: skip
    kin = state.kinematics
    c_s, c_n = (float(c) for c in differential_sliding(screw, 1.0))  # per unit screw speed
    unit = kinematics(screw, 1.0)
    shape = state.shape
    out: dict[str, Any] = {"asperity": np.zeros(shape), "lubricant": np.zeros(shape)}
    for contact in state.contacts:
        if contact.balls == 0:
            continue
        curvature = c_s if contact.side == "screw" else c_n
        spin = float(unit.spin_screw if contact.side == "screw" else unit.spin_nut)
        flat = _flat_contact(contact, kin.screw_speed, film, shape)
        asp, lub, _ = full_contact_power(
            a=flat[0],
            b=flat[1],
            p_max=flat[2],
            asperity_share=flat[3],
            viscosity=flat[4],
            pressure_viscosity=contact_pressure_viscosity(lubricant, flat[4]),
            film=flat[5],
            curvature=curvature,
            spin=spin,
            screw_speed=flat[6],
            tau0=tau0,
            gamma_l=gamma_l,
            mu0=mu,
            rheology_model=rheology_model,
            rheology_exponent=rheology_exponent,
            eyring_stress=eyring_stress,
            nodes=n_nodes,
        )
        balls = contact.balls  # a 4-point ball is listed in both families already
        out["asperity"] = out["asperity"] + balls * asp.reshape(shape)
        out["lubricant"] = out["lubricant"] + balls * lub.reshape(shape)
    return out


def _node_counts(nodes: tuple[int, int]) -> tuple[int, int]:
    """The quadrature's node counts, checked: two whole numbers >= 2."""
    try:
        n_nodes = (int(nodes[0]), int(nodes[1]))
    except (TypeError, ValueError, IndexError):
        raise BallScrewInputError("nodes", nodes, "two whole numbers >= 2") from None
    if min(n_nodes) < 2:
        raise BallScrewInputError("nodes", nodes, "two whole numbers >= 2")
    return n_nodes


def _flat_contact(
    contact: ContactState, screw_speed: FloatArray, film: str, shape: tuple[int, ...]
) -> list[FloatArray]:
    """A contact's a, b, p_max, asperity share, viscosity, film and the screw speed, flat."""
    h = contact.film_central if film == "central" else contact.film_minimum
    return [
        np.ravel(np.broadcast_to(v, shape))
        for v in (
            contact.hertz.a,
            contact.hertz.b,
            contact.hertz.p_max,
            contact.asperity_share,
            contact.viscosity,
            h,
            screw_speed,
        )
    ]
