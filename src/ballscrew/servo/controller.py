r"""Friction for servo controllers: the forms drives and CNC controls take, fitted to a model.

A controller's friction feed-forward takes a few parameters of a standard
form, fitted here by least squares to a friction model's torque–speed curve
over both directions (:math:`T(-\omega) = -T(\omega)`), with the signs that make
them physical by construction:

* **Coulomb + viscous**: :math:`T = T_c\,\mathrm{sgn}\,\omega + b\,\omega`,
  :math:`T_c, b \ge 0` (bounded linear least squares).
* **Stribeck** (Tustin's exponential form as generalised by Armstrong-Hélouvry,
  1991): :math:`T = \mathrm{sgn}\,\omega\,[T_c + (T_s - T_c)
  e^{-|\omega/\omega_s|^\delta}] + b\,\omega`, with :math:`T_s \ge T_c \ge 0`,
  :math:`b \ge 0`, :math:`0.5 \le \delta \le 2` and :math:`\omega_s` between
  the curve's slowest speed and :data:`STRIBECK_SPAN` of its fastest (a drop
  narrower than the data cannot be resolved).
* **LuGre** (Canudas de Wit, Olsson, Åström and Lischinsky, IEEE TAC 40, 1995):
  a bristle state :math:`z`, :math:`\dot z = \omega - \sigma_0|\omega|z/g(\omega)`,
  :math:`T = \sigma_0 z + \sigma_1\dot z + \sigma_2\omega`, whose steady state
  is the Stribeck curve with :math:`g = T_c + (T_s-T_c)e^{-|\omega/\omega_s|^\delta}`
  and :math:`\sigma_2 = b`. The dynamic parameters cannot come from a
  steady curve. The rules used unless you give them:
  :math:`\sigma_0 = K_a (l/2\pi)^2`, the nut's axial stiffness at its preload
  seen from the screw (pre-sliding in a rolling contact is the elastic contact
  yielding before the balls roll), with :math:`K_a` the design value
  :func:`ballscrew.design.stiffness.design_nut_stiffness` that ``ballscrew
  check`` and the servo model (:mod:`ballscrew.servo`) also take (the ideal
  contacts' stiffness, :func:`nut_axial_stiffness`, is 1.85 times stiffer),
  and :math:`\sigma_1 = 2\zeta\sqrt{\sigma_0 J}` with :math:`\zeta = 1`, a
  critically damped bristle on the axis inertia :math:`J`.
* **table**: the torque itself over speed (and temperature), which a
  controller interpolates.

Table side: with lead :math:`l`, force :math:`F = 2\pi T/l`, speed
:math:`v = l\omega/2\pi`, so :math:`F_c = 2\pi T_c/l` and the viscous
coefficient :math:`c = b(2\pi/l)^2` [N·s/m].
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np
import numpy.typing as npt

from ..design.stiffness import design_nut_stiffness, nut_axial_stiffness
from ..errors import BallScrewInputError, FloatArray, check_nonnegative, check_positive
from ..geometry import BallScrew

__all__ = [
    "FORMS",
    "MOTOR_SIDE",
    "FrictionForm",
    "coulomb_viscous",
    "fit_form",
    "form_curve",
    "lugre_rate",
    "nut_axial_stiffness",
    "stribeck",
    "stribeck_torque",
    "with_intervals",
]

FORMS = ("coulomb-viscous", "stribeck", "lugre", "table")
"""Forms :func:`fit_form` fits (``table`` is written by the CLI)."""

STRIBECK_SPAN = 0.05
"""Upper bound of the Stribeck speed as a share of the curve's fastest speed.

The Stribeck drop is a low-speed effect (mixed lubrication giving way to a
full film); without the bound, the exponential term would be bent to mimic
the concave rise of rolling losses at high speed, and its parameters would
lose their meaning.
"""

UNITS = {
    "coulomb_torque": "N*m",
    "static_torque": "N*m",
    "stribeck_speed": "rad/s",
    "stribeck_exponent": "-",
    "viscous_coefficient": "N*m*s/rad",
    "bristle_stiffness": "N*m/rad",
    "bristle_damping": "N*m*s/rad",
}
"""Screw-side units of the parameters."""

TABLE_SIDE = {
    "coulomb_torque": ("coulomb_force", "N", 1),
    "static_torque": ("static_force", "N", 1),
    "stribeck_speed": ("stribeck_table_speed", "m/s", -1),
    "viscous_coefficient": ("viscous_table_coefficient", "N*s/m", 2),
    "bristle_stiffness": ("bristle_table_stiffness", "N/m", 2),
    "bristle_damping": ("bristle_table_damping", "N*s/m", 2),
}
"""Table-side name, unit and power of 2π/l that converts each screw-side parameter."""

MOTOR_SIDE = {
    "coulomb_torque": -1,
    "static_torque": -1,
    "stribeck_speed": 1,
    "stribeck_exponent": 0,
    "viscous_coefficient": -2,
    "bristle_stiffness": -2,
    "bristle_damping": -2,
}
"""Power of the gear ratio :math:`i` (motor turns per screw turn) that takes each
screw-side parameter to the motor: torques over :math:`i`, speeds times :math:`i`,
torque per speed or per angle over :math:`i^2` (gear losses left out)."""


def stribeck_torque(
    speed: npt.ArrayLike,
    coulomb_torque: float,
    static_torque: float,
    stribeck_speed: float,
    stribeck_exponent: float,
    viscous_coefficient: float,
) -> FloatArray:
    r"""The Stribeck curve :math:`T(\omega)` [N·m] at screw speeds [rad/s] (module docstring).

    Examples
    --------
    At the Stribeck speed the excess over Coulomb has fallen to 1/e:

    >>> round(float(stribeck_torque(2.0, 0.3, 0.5, 2.0, 1.0, 0.0)), 6)
    0.373576
    """
    w = np.asarray(speed, dtype=float)
    g = coulomb_torque + (static_torque - coulomb_torque) * np.exp(
        -(np.abs(w / stribeck_speed) ** stribeck_exponent)
    )
    out: FloatArray = np.sign(w) * g + viscous_coefficient * w
    return out


def lugre_rate(
    z: npt.ArrayLike, speed: npt.ArrayLike, params: dict[str, float]
) -> tuple[FloatArray, FloatArray]:
    r"""LuGre bristle rate :math:`\dot z` [rad/s] and torque [N·m] at state ``z`` [rad]."""
    w = np.asarray(speed, dtype=float)
    zz = np.asarray(z, dtype=float)
    g = params["coulomb_torque"] + (params["static_torque"] - params["coulomb_torque"]) * np.exp(
        -(np.abs(w / params["stribeck_speed"]) ** params["stribeck_exponent"])
    )
    s0 = params["bristle_stiffness"]
    dz = w - s0 * np.abs(w) * zz / g
    torque: FloatArray = (
        s0 * zz + params["bristle_damping"] * dz + params["viscous_coefficient"] * w
    )
    return np.asarray(dz, dtype=float), torque


@dataclass(frozen=True)
class FrictionForm:
    """A fitted friction form: screw-side parameters, their units, and the fit error."""

    form: str
    parameters: dict[str, float]
    rms_error: float
    max_error: float
    notes: tuple[str, ...] = ()
    intervals: dict[str, tuple[float, float]] | None = None

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready parameters: screw-side values with their units (and 95 % intervals)."""
        return self.as_drive_dict()

    def as_drive_dict(
        self, lead: float | None = None, gear_ratio: float | None = None
    ) -> dict[str, Any]:
        """:meth:`as_dict` with table-side values for ``lead``, motor-side ones for ``gear_ratio``.

        With 95 % intervals where fitted to a measurement.
        """
        out: dict[str, Any] = {
            "form": self.form,
            "parameters": {k: {"value": v, "unit": UNITS[k]} for k, v in self.parameters.items()},
            "rms_error_Nm": self.rms_error,
            "max_error_Nm": self.max_error,
            "notes": list(self.notes),
        }
        if self.intervals is not None:
            for name, (lo, hi) in self.intervals.items():
                out["parameters"][name]["interval_95"] = [lo, hi]
        if gear_ratio is not None:
            out["motor_side"] = {
                name: {"value": v * gear_ratio ** MOTOR_SIDE[name], "unit": UNITS[name]}
                for name, v in self.parameters.items()
            }
            out["gear_ratio"] = gear_ratio
        if lead is not None:
            k = 2.0 * math.pi / lead
            out["table_side"] = {
                TABLE_SIDE[name][0]: {
                    "value": value * k ** TABLE_SIDE[name][2],
                    "unit": TABLE_SIDE[name][1],
                }
                for name, value in self.parameters.items()
                if name in TABLE_SIDE
            }
            out["lead_m"] = lead
        return out


def _errors(model: FloatArray, target: FloatArray) -> tuple[float, float]:
    d = model - target
    return float(np.sqrt(np.mean(d * d))), float(np.max(np.abs(d)))


def coulomb_viscous(speed: npt.ArrayLike, torque: npt.ArrayLike) -> FrictionForm:
    r"""Fit :math:`T = T_c\,\mathrm{sgn}\,\omega + b\,\omega` with :math:`T_c, b \ge 0`.

    ``speed`` [rad/s] signed, ``torque`` [N·m] signed (friction's sign: that of
    the speed).

    Examples
    --------
    >>> f = coulomb_viscous([-2.0, -1.0, 1.0, 2.0], [-0.5, -0.4, 0.4, 0.5])
    >>> round(f.parameters["coulomb_torque"], 6), round(f.parameters["viscous_coefficient"], 6)
    (0.3, 0.1)
    """
    from scipy.optimize import lsq_linear

    w = np.asarray(speed, dtype=float)
    t = np.asarray(torque, dtype=float)
    a = np.column_stack([np.sign(w), w])
    sol = lsq_linear(a, t, bounds=(0.0, np.inf), method="bvls")
    tc, b = (float(v) for v in sol.x)
    rms, mx = _errors(a @ sol.x, t)
    return FrictionForm("coulomb-viscous", {"coulomb_torque": tc, "viscous_coefficient": b},
                        rms, mx)  # fmt: skip


def stribeck(speed: npt.ArrayLike, torque: npt.ArrayLike) -> FrictionForm:
    """Fit the Stribeck form (module docstring) with its bounds; the result has ``T_s >= T_c``."""
    from scipy.optimize import least_squares

    w = np.asarray(speed, dtype=float)
    t = np.asarray(torque, dtype=float)
    cv = coulomb_viscous(w, t)
    tc0, b0 = cv.parameters["coulomb_torque"], cv.parameters["viscous_coefficient"]
    slowest = float(np.min(np.abs(w[w != 0.0])))
    fastest = float(np.max(np.abs(w)))
    # Parameters: T_c, T_s - T_c, log omega_s, delta, b (all bounded).
    scale = max(float(np.max(np.abs(t))), 1e-12)

    def resid(p: FloatArray) -> FloatArray:
        model = stribeck_torque(w, p[0], p[0] + p[1], math.exp(p[2]), p[3], p[4])
        out: FloatArray = (model - t) / scale
        return out

    best = None
    for ws0 in np.geomspace(slowest, fastest * STRIBECK_SPAN, 5):
        start = np.array([tc0 * 0.9, tc0 * 0.2 + 1e-9 * scale, math.log(ws0), 1.0, b0])
        sol = least_squares(
            resid, start,
            bounds=([0.0, 0.0, math.log(slowest), 0.5, 0.0],
                    [np.inf, np.inf, math.log(fastest * STRIBECK_SPAN), 2.0, np.inf]),
            x_scale=[scale, scale, 1.0, 1.0, scale / fastest],
        )  # fmt: skip
        if best is None or sol.cost < best.cost:
            best = sol
    assert best is not None
    p = best.x
    params = {
        "coulomb_torque": float(p[0]),
        "static_torque": float(p[0] + p[1]),
        "stribeck_speed": float(math.exp(p[2])),
        "stribeck_exponent": float(p[3]),
        "viscous_coefficient": float(p[4]),
    }
    rms, mx = _errors(stribeck_torque(w, **params), t)
    notes: list[str] = []
    if params["static_torque"] - params["coulomb_torque"] < 0.01 * params["coulomb_torque"]:
        notes.append(
            "the curve has no Stribeck drop (static = Coulomb torque): the Stribeck speed "
            "and exponent are then arbitrary"
        )
    return FrictionForm("stribeck", params, rms, mx, tuple(notes))


def form_curve(form: str, w: FloatArray, p: dict[str, float]) -> FloatArray:
    """The torque [N·m] of a fitted coulomb-viscous or Stribeck form at signed speeds [rad/s]."""
    if form == "coulomb-viscous":
        result: FloatArray = p["coulomb_torque"] * np.sign(w) + p["viscous_coefficient"] * w
        return result
    keys = ("coulomb_torque", "static_torque", "stribeck_speed", "stribeck_exponent",
            "viscous_coefficient")  # fmt: skip
    return stribeck_torque(w, *(p[k] for k in keys))


def with_intervals(
    fitted: FrictionForm, speed: npt.ArrayLike, torque: npt.ArrayLike
) -> FrictionForm:
    r"""The fit with Student-t 95 % intervals of its curve parameters, from the data.

    The covariance is :math:`s^2(J^TJ)^{-1}` with :math:`J` the Jacobian of the
    form's torque over its curve parameters (central differences) and
    :math:`s^2` the residual variance over :math:`n - p` degrees of freedom,
    as :func:`ballscrew.fit.calibration.fit_parameters` gives them. A
    parameter at its bound (a viscous term of 0) or one the data do not
    determine (a singular :math:`J^TJ`) gets no interval, with a note.
    LuGre's bristle parameters are not fitted to the curve: no interval.
    """
    from scipy.stats import t as student_t

    w = np.asarray(speed, dtype=float)
    t = np.asarray(torque, dtype=float)
    p = dict(fitted.parameters)
    names = [k for k in p if k in ("coulomb_torque", "static_torque", "stribeck_speed",
                                   "stribeck_exponent", "viscous_coefficient")]  # fmt: skip
    form = "coulomb-viscous" if fitted.form == "coulomb-viscous" else "stribeck"
    dof = w.size - len(names)
    notes = list(fitted.notes)
    if dof < 1:
        notes.append(f"{w.size} points for {len(names)} parameters: no intervals")
        return FrictionForm(fitted.form, p, fitted.rms_error, fitted.max_error, tuple(notes), {})
    jac = np.empty((w.size, len(names)))
    for j, name in enumerate(names):
        h = 1e-6 * max(abs(p[name]), 1e-9)
        up, down = dict(p), dict(p)
        up[name] += h
        down[name] -= h
        jac[:, j] = (form_curve(form, w, up) - form_curve(form, w, down)) / (2.0 * h)
    resid = form_curve(form, w, p) - t
    s2 = float(resid @ resid) / dof
    q = float(student_t.ppf(0.975, dof))
    intervals: dict[str, tuple[float, float]] = {}
    try:
        cov = s2 * np.linalg.inv(jac.T @ jac)
    except np.linalg.LinAlgError:
        notes.append("the data do not determine every parameter: no intervals")
        return FrictionForm(fitted.form, p, fitted.rms_error, fitted.max_error, tuple(notes), {})
    for j, name in enumerate(names):
        if p[name] == 0.0 or not cov[j, j] >= 0.0:
            notes.append(f"{name} sits at its bound 0: no interval")
            continue
        half = q * math.sqrt(float(cov[j, j]))
        intervals[name] = (p[name] - half, p[name] + half)
    return FrictionForm(fitted.form, p, fitted.rms_error, fitted.max_error, tuple(notes),
                        intervals)  # fmt: skip


def fit_form(
    form: str,
    speed: npt.ArrayLike,
    torque: npt.ArrayLike,
    *,
    screw: BallScrew | None = None,
    inertia: float | None = None,
    bristle_stiffness: float | None = None,
    bristle_damping: float | None = None,
    damping_ratio: float = 1.0,
) -> FrictionForm:
    """Fit ``form`` ("coulomb-viscous", "stribeck" or "lugre") to a signed torque curve.

    For LuGre, ``bristle_stiffness`` [N·m/rad] defaults to the rule of the
    module docstring (needs ``screw``), ``bristle_damping`` [N·m·s/rad] to a
    critically damped bristle on ``inertia`` [kg·m²] (the axis inertia at the
    screw).
    """
    if form == "coulomb-viscous":
        return coulomb_viscous(speed, torque)
    if form == "stribeck":
        return stribeck(speed, torque)
    if form != "lugre":
        raise BallScrewInputError("form", form, f"one of {list(FORMS[:3])}")
    base = stribeck(speed, torque)
    notes = list(base.notes)
    if bristle_stiffness is None:
        if screw is None:
            raise BallScrewInputError(
                "bristle_stiffness", None, "a value, or the screw for the stiffness rule"
            )
        k = design_nut_stiffness(screw)
        bristle_stiffness = k * (screw.lead / (2.0 * math.pi)) ** 2
        notes.append(
            f"bristle stiffness from the nut's design stiffness {k / 1e6:.4g} N/um (the value "
            "ballscrew check takes): a rule, not a measurement; identify it from a torque "
            "reversal if the controller needs it"
        )
    s0 = float(check_positive("bristle_stiffness", bristle_stiffness, "N*m/rad"))
    if bristle_damping is None:
        if inertia is None or inertia <= 0.0:
            raise BallScrewInputError(
                "inertia", inertia, "the axis inertia at the screw [kg*m**2] for the damping rule, "
                "or give bristle_damping",
            )  # fmt: skip
        bristle_damping = 2.0 * damping_ratio * math.sqrt(s0 * inertia)
        notes.append(f"bristle damping: damping ratio {damping_ratio:g} on {inertia:.4g} kg*m**2")
    s1 = float(check_nonnegative("bristle_damping", bristle_damping, "N*m*s/rad"))
    params = dict(base.parameters) | {"bristle_stiffness": s0, "bristle_damping": s1}
    return FrictionForm("lugre", params, base.rms_error, base.max_error, tuple(notes))
