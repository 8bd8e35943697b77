r"""The makers' catalogue formulas: preload drag torque and efficiency of a ball screw.

Ball screw catalogues (THK, NSK, Hiwin and others) estimate the torque that
a preloaded nut adds, the "dynamic preload torque", from

.. math:: T_p = K\,\frac{F_{pr}\,l}{2\pi},\qquad K = \frac{0.05}{\sqrt{\tan\beta}}

with :math:`F_{pr}` the preload [N], :math:`l` the lead [m] and
:math:`\beta` the lead angle, and the efficiency of a screw from its lead
angle and a friction coefficient. These are empirical rules, not a loss
model: the catalogue friction model (:mod:`ballscrew.friction.catalog`) is
built on them, and case files use their inverse to turn a catalogue drag
torque into a preload.

References
----------
.. [1] THK Co., Ltd., *Ball Screw General Catalog*, section "Preload torque"
   and "Driving torque" (formula and K coefficient).
.. [2] NSK Ltd., *Precision Machine Components* catalogue, "Ball screw
   technical description: preload torque".
"""

from __future__ import annotations

import math

import numpy as np
import numpy.typing as npt

from ..errors import (
    BallScrewInputError,
    FloatArray,
    check_in_range,
    check_nonnegative,
    check_positive,
)
from ..geometry import BallScrew

__all__ = [
    "DRAG_TORQUE_TOLERANCE",
    "catalog_efficiency",
    "drag_torque_tolerance",
    "preload_from_drag_torque",
    "preload_torque",
    "preload_torque_coefficient",
]


def preload_torque_coefficient(lead_angle: npt.ArrayLike, coefficient: float = 0.05) -> FloatArray:
    r"""Catalogue preload torque coefficient :math:`K = c/\sqrt{\tan\beta}` [-].

    Parameters
    ----------
    lead_angle : array_like
        :math:`\beta` [rad], in (0, π/2).
    coefficient : float
        :math:`c`; 0.05 in the catalogues.

    Examples
    --------
    >>> round(float(preload_torque_coefficient(math.atan(0.01 / (math.pi * 0.04)))), 4)
    0.1772
    """
    beta = check_in_range("lead_angle", lead_angle, 0.0, math.pi / 2, unit="rad")
    c = check_positive("coefficient", coefficient)
    result: FloatArray = c / np.sqrt(np.tan(beta))
    return result


def preload_torque(
    preload: npt.ArrayLike, lead: float, lead_angle: float, coefficient: float = 0.05
) -> FloatArray:
    r"""Catalogue dynamic preload (drag) torque :math:`T_p = K F_{pr} l/2\pi` [N·m].

    Parameters
    ----------
    preload : array_like
        :math:`F_{pr}` [N].
    lead : float
        :math:`l` [m].
    lead_angle : float
        :math:`\beta` [rad].
    coefficient : float
        :math:`c` of :func:`preload_torque_coefficient`.

    Examples
    --------
    40 mm x 10 mm screw with 2 kN preload:

    >>> round(float(preload_torque(2000.0, 0.01, math.atan(0.01 / (math.pi * 0.04)))), 4)
    0.5642
    """
    fpr = check_nonnegative("preload", preload, "N")
    lead_m = check_positive("lead", lead, "m")
    k = preload_torque_coefficient(lead_angle, coefficient)
    result: FloatArray = k * fpr * lead_m / (2.0 * math.pi)
    return result


def preload_from_drag_torque(
    drag_torque: npt.ArrayLike, screw: BallScrew, coefficient: float = 0.05
) -> FloatArray:
    r"""Preload that the catalogue formula turns into the given drag torque.

    The inverse of :func:`preload_torque`, :math:`F_{pr} = 2\pi T_p/(K l)`,
    which the study uses to turn measured drag torques (0.2 and 0.6 N·m) into
    preloads.

    Parameters
    ----------
    drag_torque : array_like
        :math:`T_p` [N·m], >= 0.
    screw : BallScrew
        Provides the lead and lead angle (its own preload is ignored).
    coefficient : float
        :math:`c` of :func:`preload_torque_coefficient`.

    Returns
    -------
    numpy.ndarray
        :math:`F_{pr}` [N].

    Examples
    --------
    >>> from ballscrew import reference_screw
    >>> round(float(preload_from_drag_torque(0.5642, reference_screw())), 0)
    2000.0
    """
    tp = check_nonnegative("drag_torque", drag_torque, "N·m")
    k = preload_torque_coefficient(screw.lead_angle, coefficient)
    result: FloatArray = 2.0 * math.pi * tp / (k * screw.lead)
    return result


def catalog_efficiency(
    lead_angle: npt.ArrayLike, friction_coefficient: npt.ArrayLike
) -> FloatArray:
    r"""Forward efficiency of a screw, :math:`\eta = \tan\beta/\tan(\beta + \arctan\mu)` [-].

    Parameters
    ----------
    lead_angle : array_like
        :math:`\beta` [rad].
    friction_coefficient : array_like
        :math:`\mu` [-]; catalogues use about 0.003 to 0.01 for ball screws.

    Examples
    --------
    >>> round(float(catalog_efficiency(math.radians(4.55), 0.003)), 4)
    0.9634
    """
    beta = check_in_range("lead_angle", lead_angle, 0.0, math.pi / 2, unit="rad")
    mu = check_nonnegative("friction_coefficient", friction_coefficient)
    rho = np.arctan(mu)
    if np.any(beta + rho >= math.pi / 2):
        raise BallScrewInputError(
            "friction_coefficient", float(np.max(mu)), "a value with lead angle + atan(mu) < 90°"
        )
    result: FloatArray = np.tan(beta) / np.tan(beta + rho)
    return result


DRAG_TORQUE_TOLERANCE: dict[str, tuple[tuple[float, float, float], ...]] = {
    "C3": ((0.2, 0.4, 0.45), (0.4, 0.6, 0.35), (0.6, 1.0, 0.30), (1.0, 2.5, 0.25),
           (2.5, 6.3, 0.20)),
}  # fmt: skip
"""Permitted deviation of a measured dynamic preload drag torque from its reference.

By accuracy grade: rows of (lowest reference torque [N·m], highest [N·m],
tolerance [-]). THK General Catalog, ball screw section, A-688, Table 13
("tolerance on the preload torque"; JIS B 1192 / ISO 3408-3 give the permitted
variation of the dynamic preload torque by grade and torque level), grade C3,
thread length up to 40 times the diameter. Only grade C3's row is held here,
the row that could be checked against the catalogue's worked example
(BNFN4010-5, 3 kN preload, reference 865 N·mm, ±30 %).
"""


def drag_torque_tolerance(reference_torque: float, grade: str = "C3") -> tuple[float, float, float]:
    """The row of :data:`DRAG_TORQUE_TOLERANCE` for a reference torque [N·m].

    Returns (lowest, highest reference torque of the row [N·m], tolerance [-]).
    A row's upper edge belongs to it (0.4 N·m is the 0.2-0.4 row).

    >>> drag_torque_tolerance(0.865)
    (0.6, 1.0, 0.3)
    """
    rows = DRAG_TORQUE_TOLERANCE.get(grade.strip().upper())
    if rows is None:
        raise BallScrewInputError("grade", grade, "one of " + ", ".join(DRAG_TORQUE_TOLERANCE)
                                  + " (the grades whose rows this version holds)")  # fmt: skip
    for row in rows:
        if row[0] <= reference_torque <= row[1]:
            return row
    raise BallScrewInputError(
        "reference torque", f"{reference_torque:.4g} N*m",
        f"{rows[0][0]:g} to {rows[-1][1]:g} N*m (the table's range for grade {grade})")  # fmt: skip
