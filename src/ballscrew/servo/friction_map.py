r"""Friction over speed, axial load and temperature: the map a drive or a simulator takes.

What ``ballscrew export-friction --form load-map`` computes.

:func:`friction_map` evaluates a model on a grid of signed screw speeds, signed
axial loads and temperatures, and fits one compact form to the whole grid
(:func:`fit_load_form`). The sign conventions:

* the screw speed :math:`\omega > 0` moves the nut (and the table) towards
  :math:`+x`, at the table speed :math:`v = \omega l/2\pi`;
* the axial load :math:`F` is the force the load exerts on the nut along
  :math:`x`. With :math:`F\omega < 0` it resists the motion and the motor
  drives it (forward driving); with :math:`F\omega > 0` the load pushes the
  way the nut moves and drives the screw (back-driving);
* the friction torque :math:`T_f` and the friction force at the table
  :math:`F_f = 2\pi T_f/l` are signed like the speed: they are what the motor
  must add to move the screw against friction. The motor side divides the
  torque by the gear ratio :math:`i` (motor turns per screw turn) and
  multiplies the speed by it; the gear's own losses are left out.

The compact form:

.. math::

    T_f = \operatorname{sgn}(\omega)\,\big(c_0(T) + c_1|F| + c_2\,d\,|F|\big)
          + b(T)\,\omega,\qquad c_0(T) = c_{0,r}e^{-k_c(T - T_r)},\quad
          b(T) = b_re^{-k_b(T - T_r)},

with :math:`d = +1` when back-driving, :math:`-1` when driving and 0 without
load. At each temperature the four coefficients are a linear least-squares
fit to the grid; across temperatures :math:`k_c` and :math:`k_b` are the
slopes of :math:`\ln c_0` and :math:`\ln b` against :math:`T` (both 0 with one
temperature), and :math:`c_1`, :math:`c_2` their means. The models of this
package dissipate the same power whichever way the power flows, so their
:math:`c_2` comes out near 0: driving and back-driving differ in the motor
torque (:math:`Fl/2\pi \pm T_f`), which is the difference between the forward
efficiency :math:`\eta = 1/(1 + 2\pi T_f/(|F|l))` and the reverse efficiency
:math:`\eta' = 1 - 2\pi T_f/(|F|l)`; the catalogue model, whose efficiencies
are :math:`\tan\beta/\tan(\beta+\rho)` and :math:`\tan(\beta-\rho)/\tan\beta`,
differs to second order in :math:`\rho`.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt
from scipy.optimize import lsq_linear

from ..chain import friction_torque
from ..errors import BallScrewInputError, FloatArray
from ..friction import get_model
from ..io.case import Case
from ..kinematics import rad_s_to_rpm
from ..materials import STANDARD_GRAVITY

_LOWER = np.array([0.0, 0.0, -np.inf, 0.0])
"""Bounds of (c0, c1, c2, b): a friction that never drives the motion."""

__all__ = [
    "MAX_MAP_POINTS",
    "FrictionMap",
    "LoadForm",
    "direction",
    "fit_load_form",
    "friction_map",
    "load_form",
]

MAX_MAP_POINTS = 1_000_000
"""The most grid points of a map (speeds both ways x loads x temperatures): about 1.6 GB
and 15 s of the complete model; a drive's map needs thousands."""

_BYTES, _SECONDS = 1.6e3, 15e-6
"""Peak memory [bytes] and time [s] per map point, measured on 2e5 points of the complete
model (320 MB, 5.6 s with the start-up)."""


def direction(speed: npt.ArrayLike, load: npt.ArrayLike) -> FloatArray:
    r"""The direction of the power flow at each point [-].

    +1 where the load back-drives the screw (:math:`F\omega > 0`), -1 where the
    motor drives the load (:math:`F\omega < 0`), 0 without load or speed.
    """
    result: FloatArray = np.sign(np.asarray(speed, dtype=float) * np.asarray(load, dtype=float))
    return result


@dataclass(frozen=True)
class LoadForm:
    """The compact friction form of the module docstring, fitted to a map.

    Attributes are in screw-side SI units: ``c0`` [N·m] at ``reference_temperature``
    [°C], ``c1`` and ``c2`` [N·m/N = m], ``b`` [N·m·s/rad] at the reference
    temperature, ``k_c`` and ``k_b`` [1/K]. ``rms_error`` and ``max_error``
    [N·m] are over the whole grid it was fitted to; ``per_temperature`` holds the
    coefficients fitted at each temperature alone.
    """

    c0: float
    c1: float
    c2: float
    b: float
    k_c: float
    k_b: float
    reference_temperature: float
    rms_error: float
    max_error: float
    per_temperature: tuple[dict[str, float], ...] = ()

    def torque(
        self, speed: npt.ArrayLike, load: npt.ArrayLike, temperature: npt.ArrayLike
    ) -> FloatArray:
        """The form's friction torque [N·m] at screw speed [rad/s], load [N], temperature [°C]."""
        return load_form(speed, load, temperature, self)

    def as_drive_dict(self, lead: float, gear_ratio: float = 1.0) -> dict[str, Any]:
        """Parameters with units on the screw side, the table side and the motor side."""
        to_force = 2.0 * math.pi / lead  # N per N·m
        to_table_speed = lead / (2.0 * math.pi)  # m per rad
        return {
            "formula": "T_f = sgn(w) (c0 exp(-k_c (T - T_r)) + c1 |F| + c2 d |F|) "
            "+ b exp(-k_b (T - T_r)) w;  d = +1 back-driving (F w > 0), -1 driving",
            "screw_side": {
                "c0": {"value": self.c0, "unit": "N*m"},
                "c1": {"value": self.c1, "unit": "N*m/N"},
                "c2": {"value": self.c2, "unit": "N*m/N"},
                "b": {"value": self.b, "unit": "N*m*s/rad"},
            },
            "table_side": {
                "c0": {"value": self.c0 * to_force, "unit": "N"},
                "c1": {"value": self.c1 * to_force, "unit": "N/N"},
                "c2": {"value": self.c2 * to_force, "unit": "N/N"},
                "b": {"value": self.b * to_force / to_table_speed, "unit": "N*s/m"},
            },
            "motor_side": {
                "c0": {"value": self.c0 / gear_ratio, "unit": "N*m"},
                "c1": {"value": self.c1 / gear_ratio, "unit": "N*m/N"},
                "c2": {"value": self.c2 / gear_ratio, "unit": "N*m/N"},
                "b": {"value": self.b / gear_ratio**2, "unit": "N*m*s/rad"},
            },
            "k_c": {"value": self.k_c, "unit": "1/K"},
            "k_b": {"value": self.k_b, "unit": "1/K"},
            "reference_temperature": {"value": self.reference_temperature, "unit": "degC"},
            "rms_error_Nm": self.rms_error,
            "max_error_Nm": self.max_error,
            "per_temperature": list(self.per_temperature),
        }


def load_form(
    speed: npt.ArrayLike, load: npt.ArrayLike, temperature: npt.ArrayLike, form: LoadForm
) -> FloatArray:
    r"""The compact form's friction torque [N·m] (module docstring), broadcast over its inputs.

    Parameters
    ----------
    speed : array_like
        Screw speed :math:`\omega` [rad/s], signed.
    load : array_like
        Axial load :math:`F` on the nut [N], signed (module docstring).
    temperature : array_like
        [°C].
    form : LoadForm
        The coefficients.
    """
    w = np.asarray(speed, dtype=float)
    f = np.asarray(load, dtype=float)
    dt = np.asarray(temperature, dtype=float) - form.reference_temperature
    coulomb = (
        form.c0 * np.exp(-form.k_c * dt)
        + form.c1 * np.abs(f)
        + form.c2 * direction(w, f) * np.abs(f)
    )
    result: FloatArray = np.sign(w) * coulomb + form.b * np.exp(-form.k_b * dt) * w
    return result


def _slope(temperatures: FloatArray, values: FloatArray) -> tuple[float, float]:
    """(value at the first temperature, -d ln(value)/dT) of a log-linear fit.

    The slope is 0 with one temperature or where a value sits at its bound 0
    (below 1e-9 of the largest).
    """
    if temperatures.size < 2 or np.any(values <= 1e-9 * np.max(np.abs(values))):
        return float(values[0]), 0.0
    slope, intercept = np.polyfit(temperatures - temperatures[0], np.log(values), 1)
    return float(math.exp(intercept)), float(-slope)


def fit_load_form(
    speeds: FloatArray, loads: FloatArray, temperatures: FloatArray, torque: FloatArray
) -> LoadForm:
    r"""Fit :class:`LoadForm` to a map ``torque[temperature, load, speed]`` [N·m].

    The speeds [rad/s] and loads [N] are signed; ``torque`` is signed like the
    speed (module docstring). Linear least squares at each temperature with
    :math:`c_0, c_1, b \ge 0` (:func:`scipy.optimize.lsq_linear`: a fitted
    friction never drives the motion, even where the model's curve is not
    linear in speed), then a log-linear fit of :math:`c_0` and :math:`b` across
    the temperatures.
    """
    w, f = np.meshgrid(speeds, loads)
    columns = np.stack(
        [np.sign(w), np.sign(w) * np.abs(f), np.sign(w) * direction(w, f) * np.abs(f), w], axis=-1
    ).reshape(-1, 4)
    per_t = []
    reach = np.max(np.abs(columns), axis=0)  # each term's largest factor over the grid
    for k, temp in enumerate(temperatures):
        coef = lsq_linear(columns, torque[k].reshape(-1), bounds=(_LOWER, np.inf), method="bvls").x
        # A term that moves no torque of the map by more than its rounding (1e-12 of the
        # largest) is 0: a model with no driving/back-driving difference gives c2 of
        # 1e-21 N*m/N, a different rounding on each path through the model.
        resolution = 1e-12 * float(np.max(np.abs(torque[k])))
        coef = np.where(np.abs(coef) * reach <= resolution, 0.0, coef)
        per_t.append({"temperature_C": float(temp), "c0_Nm": float(coef[0]),
                      "c1_Nm_per_N": float(coef[1]), "c2_Nm_per_N": float(coef[2]),
                      "b_Nms_per_rad": float(coef[3])})  # fmt: skip
    c0s = np.array([p["c0_Nm"] for p in per_t])
    bs = np.array([p["b_Nms_per_rad"] for p in per_t])
    c0, k_c = _slope(temperatures, c0s)
    b, k_b = _slope(temperatures, bs)
    form = LoadForm(
        c0=c0, c1=float(np.mean([p["c1_Nm_per_N"] for p in per_t])),
        c2=float(np.mean([p["c2_Nm_per_N"] for p in per_t])), b=b, k_c=k_c, k_b=k_b,
        reference_temperature=float(temperatures[0]), rms_error=0.0, max_error=0.0,
        per_temperature=tuple(per_t),
    )  # fmt: skip
    err = form.torque(speeds[None, None, :], loads[None, :, None], temperatures[:, None, None])
    err = err - torque
    return LoadForm(**{**form.__dict__, "rms_error": float(np.sqrt(np.mean(err**2))),
                       "max_error": float(np.max(np.abs(err)))})  # fmt: skip


@dataclass
class FrictionMap:
    """A model's friction torque over signed speeds, signed loads and temperatures.

    ``torque[i, j, k]`` [N·m] is at ``temperatures[i]`` [°C], ``loads[j]`` [N]
    and ``speeds[k]`` [rad/s] (screw side, signed like the speed: module
    docstring); ``form`` the compact form fitted to it.
    """

    case_title: str
    model: str
    lead: float
    gear_ratio: float
    speeds: FloatArray
    loads: FloatArray
    temperatures: FloatArray
    torque: FloatArray
    form: LoadForm
    notes: list[str] = field(default_factory=list)

    @property
    def force(self) -> FloatArray:
        """The friction force at the table [N], same axes as :attr:`torque`."""
        result: FloatArray = self.torque * (2.0 * math.pi / self.lead)
        return result

    @property
    def table_speeds(self) -> FloatArray:
        """Table speeds [m/s]."""
        result: FloatArray = self.speeds * (self.lead / (2.0 * math.pi))
        return result

    @property
    def motor_speeds(self) -> FloatArray:
        """Motor speeds [rad/s] (times the gear ratio)."""
        result: FloatArray = self.speeds * self.gear_ratio
        return result

    @property
    def motor_torque(self) -> FloatArray:
        """Friction torque at the motor [N·m] (over the gear ratio; gear losses left out)."""
        result: FloatArray = self.torque / self.gear_ratio
        return result

    def rows(self) -> list[dict[str, float]]:
        """One row per grid point, table side and motor side, units in the column names."""
        t, f, w = np.meshgrid(self.temperatures, self.loads, self.speeds, indexing="ij")
        v = w * self.lead / (2.0 * math.pi)
        return [
            {"temperature [degC]": float(a), "axial load [N]": float(b),
             "table speed [m/s]": float(c), "friction force [N]": float(d),
             "motor speed [rad/s]": float(e), "motor speed [rpm]": float(rad_s_to_rpm(e)),
             "motor friction torque [N*m]": float(g), "back-driving [-]": float(h)}
            for a, b, c, d, e, g, h in zip(
                t.ravel(), f.ravel(), v.ravel(), self.force.ravel(),
                (w * self.gear_ratio).ravel(), self.motor_torque.ravel(),
                direction(w, f).ravel(), strict=True,
            )
        ]  # fmt: skip

    def as_dict(self) -> dict[str, Any]:
        """The JSON document: axes, the compact form and the notes (the writer adds the version)."""
        return {
            "case": self.case_title, "model": self.model,
            "form": "load-map", "lead_m": self.lead, "gear_ratio": self.gear_ratio,
            "axes": {"temperature_C": self.temperatures.tolist(),
                     "axial_load_N": self.loads.tolist(),
                     "screw_speed_rad_s": self.speeds.tolist()},
            "fit": self.form.as_drive_dict(self.lead, self.gear_ratio),
            "notes": list(self.notes),
        }  # fmt: skip


def friction_map(
    case: Case,
    model: str,
    *,
    speeds: npt.ArrayLike,
    loads: npt.ArrayLike,
    temperatures: npt.ArrayLike,
    gear_ratio: float | None = None,
) -> FrictionMap:
    """Evaluate ``model`` on the grid and fit the compact form (module docstring).

    Parameters
    ----------
    case : Case
        Screw, lubricant, model parameters; ``[axis]`` gives the gear ratio and
        the weight of an inclined axis (named in the notes).
    model : str
        A registered friction model.
    speeds : array_like
        Screw speeds [rad/s]; positive ones are mirrored to negative ones, and 0
        is left out (the friction at rest is not a single value).
    loads : array_like
        Axial loads on the nut [N], signed; at least one.
    temperatures : array_like
        [°C], at least one.
    gear_ratio : float, optional
        Motor turns per screw turn; default the case's ``[axis] gear_ratio`` or 1.
    """
    name = get_model(model).name
    w = np.unique(np.abs(np.asarray(speeds, dtype=float).ravel()))
    w = w[w > 0.0]
    if w.size < 2:
        raise BallScrewInputError("--speed", np.asarray(speeds).tolist(),
                                  "two or more non-zero speeds")  # fmt: skip
    w = np.concatenate([-w[::-1], w])
    f = np.unique(np.asarray(loads, dtype=float).ravel())
    t = np.unique(np.asarray(temperatures, dtype=float).ravel())
    points = w.size * f.size * t.size
    if points > MAX_MAP_POINTS:
        raise BallScrewInputError(
            "map points", f"{points:,} ({w.size // 2} speeds both ways x {f.size} loads x "
            f"{t.size} temperatures)",
            f"at most {MAX_MAP_POINTS:,} (about {points * _BYTES / 1e9:.3g} GB and "
            f"{points * _SECONDS / 60:.3g} min of the model by estimate): take fewer "
            "speeds, loads or temperatures ('0.1..3000:60 rpm', '-4..4:9 kN')",
        )  # fmt: skip
    ratio = float(case.axis.get("gear_ratio", 1.0) if gear_ratio is None else gear_ratio)
    if not ratio > 0.0 or not math.isfinite(ratio):
        raise BallScrewInputError("gear_ratio", ratio, "a positive number (motor turns per "
                                  "screw turn)")  # fmt: skip
    with warnings.catch_warnings():  # validity warnings are the torque command's business
        warnings.simplefilter("ignore")
        r = friction_torque(
            case.screw, case.lubricant, speed=w[None, None, :], temperature=t[:, None, None],
            axial_load=f[None, :, None], model=name, **case.parameters_for(name),
        )  # fmt: skip
    torque = np.broadcast_to(np.sign(w) * r.total, (t.size, f.size, w.size)).copy()
    notes = []
    mass, incline = case.axis.get("moving_mass"), case.axis.get("incline", 0.0)
    if mass and incline:
        weight = mass * STANDARD_GRAVITY * math.sin(incline)
        notes.append(f"the axis is inclined: its weight adds {weight:.4g} N along x to the "
                     "process force (give the total as the axial load)")  # fmt: skip
    mirrored = torque[:, ::-1, :]  # the same speeds at the opposite loads
    if np.all(f == -f[::-1]):
        scale = max(float(np.max(np.abs(torque))), 1e-300)
        asym = float(np.max(np.abs(torque - mirrored))) / scale
        notes.append(f"driving and back-driving at the same |F|: the friction agrees to "
                     f"{asym:.1e} of its largest value; the motor torque differs by "
                     "F l/2pi +- T_f (the forward and reverse efficiencies)")  # fmt: skip
    form = fit_load_form(w, f, t, torque)
    if t.size > 1 and (form.k_b == 0.0 or form.k_c == 0.0):
        notes.append("a coefficient reached 0 at some temperature: its temperature factor "
                     "is left at 1 (k = 0); see per_temperature in the JSON")  # fmt: skip
    return FrictionMap(case.title, name, case.screw.lead, ratio, w, f, t, torque, form, notes)
