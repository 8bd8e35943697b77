r"""The manufacturers' catalogue formula for ball screw drag torque and efficiency.

Ball screw catalogues (THK, NSK, Hiwin and others) estimate the torque that
a preloaded nut adds, the "dynamic preload torque", from

.. math:: T_p = K\,\frac{F_{pr}\,l}{2\pi},\qquad K = \frac{0.05}{\sqrt{\tan\beta}}

with :math:`F_{pr}` the preload [N], :math:`l` the lead [m] and
:math:`\beta` the lead angle. An external axial load :math:`F_a` adds the
friction part of the driving torque :math:`F_a l/(2\pi\eta)`:

.. math::
    T_a = \frac{|F_a|\,l}{2\pi}\left(\frac{1}{\eta} - 1\right),\qquad
    \eta = \frac{\tan\beta}{\tan(\beta + \rho)},\quad \rho = \arctan\mu

(forward efficiency, rotation to translation). This is the engineers'
reference against which the physical models are held. The formulas themselves,
and the catalogues they come from, are in :mod:`ballscrew.catalog_formulas`
(named here too).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from ..design.catalog_formulas import (
    catalog_efficiency,
    preload_from_drag_torque,
    preload_torque,
    preload_torque_coefficient,
)
from ..errors import FloatArray
from ..geometry import BallScrew
from ..lubricant import Lubricant
from ..validity import ValidityIssue, ValidityRange, outside
from ._registry import register

__all__ = [
    "catalog",
    "catalog_efficiency",
    "preload_from_drag_torque",
    "preload_torque",
    "preload_torque_coefficient",
]


CATALOG_TEMPERATURE_RANGE = ValidityRange(
    "temperature [degC] (catalogue rule)",
    0.0,
    60.0,
    "the catalogue drag-torque rule",
    "makers rate drag torque near room temperature with their own lubricant and the rule has "
    "no temperature term; the bounds are this package's judgement, not a published limit",
)


def catalog_temperature_check(
    screw: BallScrew, lubricant: Lubricant, speed: FloatArray, temperature: FloatArray,
    axial_load: FloatArray, parameters: dict[str, Any],
) -> list[ValidityIssue]:  # fmt: skip
    """The catalogue rule's temperature range (it does not follow temperature)."""
    return outside(
        CATALOG_TEMPERATURE_RANGE, [float(np.min(temperature)), float(np.max(temperature))]
    )


@register(
    "catalog",
    title="Manufacturers' catalogue formula: preload drag torque plus load torque",
    reference="THK Ball Screw General Catalog, 'Preload torque' and 'Driving torque'",
    validity="preloaded precision ball screws; speed, lubricant and temperature do not enter",
    purpose="the manufacturers' rule: the catalogue drag torque and efficiency, a reference "
    "for the others",
    checks=(catalog_temperature_check,),
)
def catalog(
    screw: BallScrew, lubricant: Lubricant, speed: FloatArray, temperature: FloatArray,
    axial_load: FloatArray, *,
    preload_coefficient: float = 0.05,
    friction_coefficient: float = 0.003,
) -> dict[str, FloatArray]:  # fmt: skip
    r"""Catalogue friction torque: preload drag torque plus the external-load term.

    Parameters
    ----------
    screw : BallScrew
        Geometry and preload.
    lubricant : Lubricant
        Not used (the formula has no lubricant).
    speed, temperature : numpy.ndarray
        Not used (the formula has no speed or temperature dependence).
    axial_load : numpy.ndarray
        External axial load [N].
    preload_coefficient : float
        :math:`c` in :math:`K = c/\sqrt{\tan\beta}`; default 0.05 (catalogues).
    friction_coefficient : float
        :math:`\mu` of the efficiency; default 0.003, THK's value for ball screws.

    Returns
    -------
    dict
        ``"preload"`` :math:`T_p` and ``"load"`` :math:`T_a` [N·m].
    """
    beta = screw.lead_angle
    tp = preload_torque(screw.preload, screw.lead, beta, preload_coefficient)
    eta = catalog_efficiency(beta, friction_coefficient)
    ta = np.abs(axial_load) * screw.lead / (2.0 * math.pi) * (1.0 / eta - 1.0)
    return {"preload": np.broadcast_to(tp, ta.shape), "load": ta}
