"""Helpers shared by the friction models: from contact forces to torque on the screw."""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Literal, get_args

import numpy as np

from ..errors import BallScrewInputError, FloatArray
from ..state import OperatingState

__all__ = ["TORQUE_ARMS", "TorqueArm", "torque_from_contact_forces"]

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
        :math:`T = P/\omega = \sum_j Z_j F_j\,d_m(1-\gamma^2)/4` (the ratio
        :math:`u/\omega` is a property of the geometry, so the torque is
        defined at zero speed too).
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
    if arm == "energy":
        lever = [screw.pitch_diameter * (1.0 - screw.gamma**2) / 4.0] * len(state.contacts)
    elif arm == "contact-radius":
        cos_l = math.cos(screw.lead_angle)
        lever = [0.5 * c.radius * cos_l for c in state.contacts]
    elif arm == "ball-radius":
        lever = [0.5 * screw.ball_diameter] * len(state.contacts)
    else:
        raise BallScrewInputError("torque_arm", arm, f"one of {list(TORQUE_ARMS)}")
    total: FloatArray = np.zeros(np.shape(forces[0]))
    for contact, force, r in zip(state.contacts, forces, lever, strict=True):
        total = total + contact.balls * screw.contacts_per_ball * force * r
    return total
