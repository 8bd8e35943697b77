r"""Friction of the screw's support bearings: SKF's simplified estimate.

.. math:: M = \tfrac12\,\mu\,P\,d

with :math:`P` the equivalent dynamic load [N], :math:`d` the bore [m] and
:math:`\mu` a constant friction coefficient per bearing type (SKF, *Rolling
bearings* catalogue, section "Friction: estimating the frictional moment").
The estimate holds for loads around :math:`P \approx 0.1\,C`, good
lubrication and normal operating conditions; it has no speed or viscosity
term (no drag losses), so at light load and high speed it underestimates.
The axial force of a ball screw goes through the fixed-end bearings; here
:math:`P` is taken as that axial force.
"""

from __future__ import annotations

import numpy.typing as npt

from .errors import BallScrewInputError, FloatArray, check_finite, check_positive

__all__ = ["SKF_FRICTION_COEFFICIENTS", "simplified_bearing_torque"]

SKF_FRICTION_COEFFICIENTS: dict[str, float] = {
    "deep-groove ball": 0.0015,
    "angular-contact ball, single row": 0.0020,
    "angular-contact ball, double row": 0.0024,
    "four-point contact ball": 0.0024,
    "thrust ball": 0.0013,
}
"""SKF's constant friction coefficients of open bearings, by type [-]."""


def simplified_bearing_torque(
    load: npt.ArrayLike, bore: float, bearing_type: str = "angular-contact ball, single row"
) -> FloatArray:
    r"""Frictional moment of a support bearing, :math:`M = \mu P d / 2` [N·m].

    Parameters
    ----------
    load : array_like
        Equivalent load :math:`P` [N] (its magnitude is used).
    bore : float
        Bore diameter :math:`d` [m].
    bearing_type : str
        A key of :data:`SKF_FRICTION_COEFFICIENTS`.

    Examples
    --------
    A 30 mm angular-contact bearing under 2 kN: 0.5 * 0.002 * 2000 * 0.03 = 0.06 N·m.

    >>> round(float(simplified_bearing_torque(2000.0, 0.03)), 6)
    0.06
    """
    if bearing_type not in SKF_FRICTION_COEFFICIENTS:
        raise BallScrewInputError(
            "bearing_type", bearing_type, f"one of {list(SKF_FRICTION_COEFFICIENTS)}"
        )
    d = float(check_positive("bore", bore, "m"))
    p = abs(check_finite("load", load))
    result: FloatArray = 0.5 * SKF_FRICTION_COEFFICIENTS[bearing_type] * p * d
    return result
