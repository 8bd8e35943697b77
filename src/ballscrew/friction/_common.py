"""Helpers shared by the friction models: from contact forces to torque on the screw."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Literal, get_args

import numpy as np
import numpy.typing as npt

from .. import rheology
from ..errors import BallScrewInputError, FloatArray, check_choice, check_nonnegative
from ..geometry import BallScrew, ScrewGeometry
from ..kinematics import kinematics
from ..lubricant import Lubricant, pressure_viscosity_unchecked, roelands_alpha
from ..state import OperatingState, operating_state

__all__ = [
    "RHEOLOGY_MODELS",
    "TORQUE_ARMS",
    "TorqueArm",
    "contact_pressure_viscosity",
    "lever_arms",
    "limiting_shear",
    "local_viscosity",
    "model_state",
    "shear_stress",
    "torque_from_contact_forces",
]

TorqueArm = Literal["energy", "contact-radius", "ball-radius"]
TORQUE_ARMS: tuple[str, ...] = get_args(TorqueArm)


def torque_from_contact_forces(
    state: OperatingState, forces: Sequence[FloatArray], arm: str = "energy"
) -> FloatArray:
    r"""Friction torque on the screw from a resisting force at each contact [N·m].

    ``forces[i]`` is the force per ball at ``state.contacts[i]`` [N], resisting
    the rolling motion. Three conversions:

    ``"energy"`` (default)
        The force dissipates power at the rolling speed of its contact,
        :math:`P = \sum_j Z_j F_j u`, and the screw supplies it:
        :math:`T = P/\omega = \sum_j Z_j F_j\,u/\omega` with
        :math:`u/\omega = d_m(1-\gamma^2\cos^4\lambda)/(4\cos\lambda)`
        (:mod:`ballscrew.kinematics`; a property of the geometry, so the torque
        is defined at zero speed too).
    ``"contact-radius"``
        Each force acts at its contact's distance from the axis, projected on
        the circumference, averaged over screw and nut:
        :math:`T = \tfrac12\sum_j Z_j F_j R_j\cos\lambda`. Within
        :math:`\gamma^2` (about 1 %) of ``"energy"``.
    ``"ball-radius"``
        :math:`T = \sum_j Z_j F_j D_w/2`: the study's statement for the
        viscoelastic model ("total friction force multiplied by the ball
        radius"), kept to reproduce it.
    """
    screw = state.screw
    assert isinstance(screw, BallScrew)  # the models that take many screws do not come here
    levers = lever_arms(screw, arm)
    lever = [levers[c.side] for c in state.contacts]
    total: FloatArray = np.zeros(np.shape(forces[0]))
    for contact, force, r in zip(state.contacts, forces, lever, strict=True):
        total = total + contact.balls * force * r
    return total


def lever_arms(screw: BallScrew, arm: str) -> dict[str, float]:
    """Lever [m] that turns a force per ball at the screw and nut contacts into torque.

    See :func:`torque_from_contact_forces` for the three choices of ``arm``.
    """
    check_choice("torque_arm", arm, TORQUE_ARMS)
    if arm == "energy":
        rolling = float(kinematics(screw, 1.0).entrainment_speed)
        return {"screw": rolling, "nut": rolling}
    if arm == "contact-radius":
        cos_l = math.cos(screw.lead_angle)
        return {
            "screw": 0.5 * screw.contact_radius_screw * cos_l,
            "nut": 0.5 * screw.contact_radius_nut * cos_l,
        }
    return {"screw": 0.5 * screw.ball_diameter, "nut": 0.5 * screw.ball_diameter}


def limiting_shear(
    lubricant: Lubricant, tau0: float | None, coefficient: float | None
) -> tuple[float, float]:
    r"""Limiting-shear parameters :math:`\tau_0` [Pa] and :math:`\gamma_L` [-].

    A model parameter given as ``None`` takes the lubricant's own value.
    """
    t0 = lubricant.limiting_shear_stress if tau0 is None else tau0
    gl = lubricant.limiting_shear_coefficient if coefficient is None else coefficient
    return (
        float(check_nonnegative("limiting_shear_stress", t0, "Pa")),
        float(check_nonnegative("limiting_shear_coefficient", gl)),
    )


RHEOLOGY_MODELS = ("harmonic", "general", "eyring", "bair-winer")
"""The lubricant shear laws the Harris models take by name (:func:`shear_stress`)."""


def shear_stress(
    model: str,
    viscosity: npt.ArrayLike,
    shear_rate: npt.ArrayLike,
    limiting_stress: npt.ArrayLike,
    exponent: float = 1.0,
    eyring_stress: float | None = None,
) -> FloatArray:
    """Lubricant shear stress [Pa] by a named law of :mod:`ballscrew.rheology`.

    ``model`` is one of ``"harmonic"`` (the study's eq. 5), ``"general"``
    (eq. 7 with ``exponent``), ``"eyring"`` (needs ``eyring_stress`` [Pa]; no
    default, since no published value fits every oil) or ``"bair-winer"``.
    """
    if model == "harmonic":
        return rheology.harmonic_combination(viscosity, shear_rate, limiting_stress)
    if model == "general":
        return rheology.general_non_newtonian(viscosity, shear_rate, limiting_stress, exponent)
    if model == "eyring":
        if eyring_stress is None:
            raise BallScrewInputError(
                "eyring_stress",
                None,
                "a stress [Pa] for the Eyring law; it has no default (its value depends on "
                "the oil and pressure: a few MPa is usual)",
            )
        return rheology.eyring_1936(viscosity, shear_rate, eyring_stress)
    if model == "bair-winer":
        return rheology.bair_winer_1979(viscosity, shear_rate, limiting_stress)
    raise BallScrewInputError("rheology", model, f"one of {list(RHEOLOGY_MODELS)}")


def local_viscosity(
    viscosity: FloatArray,
    pressure_viscosity: float | FloatArray,
    pressure: FloatArray,
    model: str,
) -> FloatArray:
    """Viscosity at the local pressure [Pa·s], rows of ``pressure`` against ``viscosity``.

    :func:`ballscrew.lubricant.pressure_viscosity_unchecked` (the one
    implementation of Roelands' and Barus's equations) on rows of pressures;
    ``pressure_viscosity`` is one coefficient, or one per ``viscosity`` (the
    coefficient at each point's temperature, :func:`contact_pressure_viscosity`).
    """
    alpha = np.asarray(pressure_viscosity, dtype=float)[..., None]
    return pressure_viscosity_unchecked(model, viscosity[..., None], alpha, pressure)


def contact_pressure_viscosity(
    lubricant: Lubricant, viscosity: npt.ArrayLike, model: str = "roelands"
) -> FloatArray:
    r"""The pressure-viscosity coefficient [1/Pa] at a contact whose oil has ``viscosity`` [Pa·s].

    Roelands (``model="roelands"``): :math:`\alpha^*` of
    :func:`ballscrew.lubricant.roelands_alpha` with the oil's constant index
    :attr:`~ballscrew.lubricant.Lubricant.roelands_index`, so that the local
    viscosity follows Roelands' formula at the contact's temperature (the
    ambient viscosity carries the temperature). Barus: the oil's
    ``pressure_viscosity`` as given, one value for every point.
    """
    eta0 = np.asarray(viscosity, dtype=float)
    if model == "roelands":
        return roelands_alpha(eta0, lubricant.roelands_index)
    return np.full(eta0.shape, lubricant.pressure_viscosity)


def model_state(
    screw: ScrewGeometry, lubricant: Lubricant, speed: FloatArray, temperature: FloatArray,
    axial_load: FloatArray, *,
    hertz_method: str,
    asperity_b: float,
    asperity_c: float,
    state: OperatingState | None = None,
) -> OperatingState:  # fmt: skip
    """The contact state a model works on: the chain's, or built here when called directly.

    Built unbroadcast (:func:`ballscrew.state.operating_points`), so that each
    layer works on the values it depends on.
    """
    if state is not None:
        return state
    return operating_state(
        screw, lubricant, speed=speed, temperature=temperature, axial_load=axial_load,
        hertz_method=hertz_method, asperity_b=asperity_b, asperity_c=asperity_c,
        broadcast=False,
    )  # fmt: skip
