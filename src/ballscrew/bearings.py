r"""Friction of the screw's support bearings: SKF's simplified estimate, or Palmgren's model.

SKF's simplified estimate:

.. math:: M = \tfrac12\,\mu\,P\,d

with :math:`P` the equivalent dynamic load [N], :math:`d` the bore [m] and
:math:`\mu` a constant friction coefficient per bearing type (SKF, *Rolling
bearings* catalogue, section "Friction: estimating the frictional moment").
The estimate holds for loads around :math:`P \approx 0.1\,C`, good
lubrication and normal operating conditions; it has no speed or viscosity
term (no drag losses), so at light load and high speed it underestimates.
The axial force of a ball screw goes through the fixed-end bearings; here
:math:`P` is taken as that axial force.

Palmgren's model (:func:`palmgren_bearing_torque`) adds the drag of the
lubricant, :math:`M_0 \propto (\nu n)^{2/3} d_M^3`, to a load term
:math:`M_1 = f_1 P_1 d_M`; it needs the bearing's outside diameter and static
load rating, and its factors are printed per bearing series (Schaeffler,
*Rolling bearings*, catalogue HR 1, 2006, "Friction and increases in
temperature", pp. 55–60). The preload of the support bearings themselves is
not included in either estimate.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import numpy.typing as npt

from .errors import BallScrewInputError, FloatArray, check_finite, check_positive
from .kinematics import rad_s_to_rpm

__all__ = [
    "PALMGREN_BEARINGS",
    "SKF_FRICTION_COEFFICIENTS",
    "PalmgrenBearing",
    "palmgren_bearing_torque",
    "palmgren_drag_torque",
    "palmgren_load_torque",
    "simplified_bearing_torque",
]

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


@dataclass(frozen=True)
class PalmgrenBearing:
    r"""Palmgren's coefficients of one bearing type (Schaeffler HR 1, pp. 57–60).

    Attributes
    ----------
    f0_grease, f0_oil : float
        Lubrication factor :math:`f_0` with grease or oil mist, and with an
        oil bath or recirculating oil [-].
    f1_factor, f1_exponent : float
        :math:`f_1 = z\,(P_0/C_0)^y` [-].
    p1_factor : float
        Load for friction under a purely axial load, :math:`P_1 = c\,F_a` [-].
    series : str
        The bearing series the factors are printed for.
    """

    f0_grease: float
    f0_oil: float
    f1_factor: float
    f1_exponent: float
    p1_factor: float
    series: str


PALMGREN_BEARINGS: dict[str, PalmgrenBearing] = {
    "angular-contact ball, single row": PalmgrenBearing(2.0, 3.0, 0.001, 0.33, 1.0,
                                                        "718..-B, 72..-B, 73..-B"),
    "angular-contact ball, double row": PalmgrenBearing(4.0, 6.0, 0.001, 0.33, 1.4,
                                                        "33, 33..-DA"),
    "four-point contact ball": PalmgrenBearing(2.7, 4.0, 0.001, 0.33, 1.5, "QJ2, QJ3"),
    "thrust ball": PalmgrenBearing(1.0, 1.5, 0.0012, 0.33, 1.0, "511, 512, 513, 514"),
    "screw-support (ZKLN, ZKLF)": PalmgrenBearing(4.0, 6.0, 0.001, 0.33, 1.4,
                                                  "ZKLN, ZKLF"),
}  # fmt: skip
"""Palmgren's factors by bearing type, as printed in Schaeffler's catalogue HR 1
(2006), "Friction and increases in temperature", pp. 57–60: :math:`f_0` for
the two lubrication columns, :math:`f_1` and :math:`P_1`. Readings taken here:
the screw-support units ZKLN/ZKLF are double-direction angular-contact
bearings and take the double-row :math:`P_1 = 1.4F_a` and :math:`f_1`
(their own cell is shared with other series in the copy read); a radial load
on the support (:math:`-0.1F_r` in :math:`P_1`) is neglected."""


def palmgren_drag_torque(
    speed: npt.ArrayLike,
    kinematic_viscosity: npt.ArrayLike,
    mean_diameter: float,
    f0: float,
) -> FloatArray:
    r"""Palmgren's load-independent frictional moment :math:`M_0` [N·m].

    .. math::
        M_0 = f_0\,10^{-7}\,(\nu n)^{2/3}\,d_M^3 \quad (\nu n \ge 2000),\qquad
        M_0 = 160\cdot 10^{-7} f_0\,d_M^3 \quad (\nu n < 2000)

    in the catalogue's units: :math:`M_0` [N·mm], :math:`\nu` [mm²/s],
    :math:`n` [1/min], :math:`d_M = (d + D)/2` [mm] (Schaeffler HR 1, 2006,
    p. 55; Timken Engineering Manual, p. 184). The two branches meet at
    :math:`\nu n = 2000` to 1 % (:math:`2000^{2/3} = 158.7`). It is the drag of
    the lubricant, rising with speed and viscosity.

    Parameters
    ----------
    speed : array_like
        Shaft speed [rad/s] (its magnitude is used).
    kinematic_viscosity : array_like
        Of the lubricant (for grease, its base oil) at the operating
        temperature [m²/s].
    mean_diameter : float
        :math:`d_M` [m].
    f0 : float
        Lubrication factor, see :data:`PALMGREN_BEARINGS` [-].

    Examples
    --------
    A screw-support bearing of 30 mm bore and 62 mm outside diameter, grease
    (f0 = 4), VG 68 at 40 °C, 3000 rpm: 4e-7 * 204000^(2/3) * 46^3 N·mm.

    >>> import math
    >>> round(float(palmgren_drag_torque(100 * math.pi, 68e-6, 0.046, 4.0)), 4)
    0.1349
    """
    w = abs(check_finite("speed", speed))
    nu = check_positive("kinematic_viscosity", kinematic_viscosity, "m^2/s")
    dm = float(check_positive("mean_diameter", mean_diameter, "m"))
    f = float(check_positive("f0", f0))
    nu_n = nu * 1e6 * rad_s_to_rpm(w)  # mm²/s times 1/min
    dm_mm3 = (dm * 1e3) ** 3
    n_mm = np.where(nu_n >= 2000.0, f * 1e-7 * np.cbrt(nu_n) ** 2 * dm_mm3, 160e-7 * f * dm_mm3)
    result: FloatArray = n_mm * 1e-3
    return result


def palmgren_load_torque(
    load: npt.ArrayLike, mean_diameter: float, static_rating: float, bearing_type: str
) -> FloatArray:
    r"""Palmgren's load-dependent frictional moment :math:`M_1 = f_1 P_1 d_M` [N·m].

    :math:`f_1 = z\,(P_0/C_0)^y` and :math:`P_1 = c\,F_a` from
    :data:`PALMGREN_BEARINGS` (Schaeffler HR 1, 2006, pp. 58–60), with the
    static equivalent load :math:`P_0` taken as the axial load :math:`F_a`
    (an approximation: a purely axial load on a support).

    Parameters
    ----------
    load : array_like
        Axial load :math:`F_a` through the bearing [N] (magnitude used).
    mean_diameter : float
        :math:`d_M` [m].
    static_rating : float
        Basic static load rating :math:`C_0` [N], from the bearing's catalogue.
    bearing_type : str
        A key of :data:`PALMGREN_BEARINGS`.

    Examples
    --------
    2 kN through a double-row bearing of C0 = 40 kN and d_M = 46 mm:
    0.001 * 0.05^0.33 * 1.4 * 2000 N * 0.046 m.

    >>> m1 = palmgren_load_torque(2000.0, 0.046, 40e3, "angular-contact ball, double row")
    >>> round(float(m1), 5)
    0.04793
    """
    spec = _palmgren(bearing_type)
    fa = abs(check_finite("load", load))
    dm = float(check_positive("mean_diameter", mean_diameter, "m"))
    c0 = float(check_positive("static_rating", static_rating, "N"))
    f1 = spec.f1_factor * (fa / c0) ** spec.f1_exponent
    result: FloatArray = f1 * spec.p1_factor * fa * dm
    return result


def palmgren_bearing_torque(
    speed: npt.ArrayLike,
    load: npt.ArrayLike,
    kinematic_viscosity: npt.ArrayLike,
    *,
    bore: float,
    outer_diameter: float,
    static_rating: float,
    bearing_type: str = "screw-support (ZKLN, ZKLF)",
    lubrication: str = "grease",
) -> FloatArray:
    r"""Frictional moment of a support bearing by Palmgren, :math:`M_0 + M_1` [N·m].

    :func:`palmgren_drag_torque` with :math:`d_M = (d + D)/2` and the type's
    :math:`f_0` for ``lubrication`` ("grease", which also stands for oil
    mist, or "oil" for an oil bath or recirculating oil), plus
    :func:`palmgren_load_torque`. Unlike :func:`simplified_bearing_torque`,
    it rises with speed and viscosity. The catalogue warns that a freshly
    greased bearing can run at 2–5 times :math:`M_0` until the grease has
    been worked out of the way.

    Parameters
    ----------
    speed : array_like
        Shaft speed [rad/s].
    load : array_like
        Axial load through the bearing [N].
    kinematic_viscosity : array_like
        Lubricant (or grease base oil) viscosity at the operating temperature [m²/s].
    bore, outer_diameter : float
        :math:`d` and :math:`D` [m].
    static_rating : float
        :math:`C_0` [N].
    bearing_type : str
        A key of :data:`PALMGREN_BEARINGS`.
    lubrication : {"grease", "oil"}

    Examples
    --------
    >>> import math
    >>> m = palmgren_bearing_torque([0.0, 100 * math.pi], 2000.0, 68e-6, bore=0.03,
    ...                             outer_diameter=0.062, static_rating=40e3)
    >>> [round(float(x), 3) for x in m]
    [0.054, 0.183]
    """
    spec = _palmgren(bearing_type)
    if lubrication not in ("grease", "oil"):
        raise BallScrewInputError("bearing_lubrication", lubrication, "'grease' or 'oil'")
    d = float(check_positive("bearing_bore", bore, "m"))
    big = float(check_positive("bearing_outer_diameter", outer_diameter, "m"))
    if big <= d:
        raise BallScrewInputError(
            "bearing_outer_diameter", outer_diameter, f"a diameter above the bore {d:g} m"
        )
    dm = 0.5 * (d + big)
    f0 = spec.f0_grease if lubrication == "grease" else spec.f0_oil
    result: FloatArray = palmgren_drag_torque(speed, kinematic_viscosity, dm, f0) + (
        palmgren_load_torque(load, dm, static_rating, bearing_type)
    )
    return result


def _palmgren(bearing_type: str) -> PalmgrenBearing:
    if bearing_type not in PALMGREN_BEARINGS:
        raise BallScrewInputError(
            "bearing_type", bearing_type, f"one of {list(PALMGREN_BEARINGS)} for Palmgren's model"
        )
    return PALMGREN_BEARINGS[bearing_type]
