r"""A machine's feed axes fitted to a measured drive trace: what ``ballscrew identify`` computes.

This module is long on purpose: its method is stated here once in full, and the
regressors, the fit with its bootstrap and the synthetic trace that tests it share
the same model terms and filter.

A drive trace gives, per axis, the measured position and the drive's
current (or torque, or power). The axis model runs on the measured
trajectory, and a few parameters a catalogue does not give are fitted.

**Kinematics, and one filter on both sides.** Speed and acceleration are the
central differences of the measured positions,
:math:`\hat v_k = (x_{k+1} - x_{k-1})/2\Delta t` and :math:`\hat a_k = (x_{k+1} -
2x_k + x_{k-1})/\Delta t^2`. The second is exactly the acceleration averaged
over :math:`\pm\Delta t` with a triangular weight, whatever the motion between
the samples; the measured signal is averaged with the same weight
(:func:`hat`). The model's terms are computed sample by sample, and then the
signal and every term go through the same Gaussian filter (:func:`smooth`,
standard deviation :data:`SMOOTHING` = 10 ms, at least 1.5 samples): the model
is linear in its parameters, so filtering both sides keeps it exact while the
noise of the differences and the sampling error where the acceleration
changes its slope (a jerk phase's ends) average out. The sampling must be
uniform (a drive's trace is), and a trace must resolve the motion: the fit
recovers its parameters within their intervals when each jerk phase spans
ten samples or more (250 Hz for the 50 ms phases of 40 m/s³ and 2 m/s²); a
50 Hz trace of such moves explains the current as well (:math:`R^2`) but
biases the friction parameters, which the trace can then hardly tell apart
(their correlations say so). Where a move starts or stops, the friction steps
between two samples that neither the differences nor the filter can place:
the samples within :math:`2\sigma + 1` of a start or stop are left out of the
fit (not of its scores).

**The model, at the motor shaft** (gear ratio :math:`i`, lead :math:`l`,
:math:`r = l/2\pi i` the table's travel per motor radian):

.. math::

    T = T_J + r\,m\,(a + g\sin\theta) + r F_p + s\,\sigma(v)\,\frac{T_s(\omega, F)}{i}
        + \sigma(v)\frac{T_b}{i} + r F_c\,\sigma(v) + r\,b\,v

- :math:`T_J`: the rotating inertias of the case (motor, coupling, screw);
- :math:`m`: the moving mass, :math:`\theta` the incline, :math:`F_p` a process
  force (none in a trace of an air cut);
- :math:`T_s`: the screw's friction torque from the package's model (the
  machine file's, the complete model by default) at each sample's speed and
  axial load, through :func:`ballscrew.axis.energy.axis_cycle`, times one
  **scale** :math:`s`; :math:`T_b` the support bearings';
- :math:`F_c`, :math:`b`: the guideways' **Coulomb** force and **viscous**
  coefficient;
- :math:`\sigma(v)`: the sign of the speed, zero below :math:`v_s/2` and full
  from the standstill width :math:`v_s = 8\sigma_v` of the trace's speed noise
  (:mod:`ballscrew.axis.standstill`), so that an axis at rest holds.

The drive's signal is :math:`y = y_0 + T/K_t` for a current (:math:`K_t` the
torque constant, :math:`y_0` the current's offset), :math:`y = y_0 + T` for a
torque and :math:`y = y_0 + T\omega_m` for a power (the shaft's; the drive's and
motor's losses are not modelled here).

**What is free, and what is held.** Every term of :math:`T` is linear in
what multiplies it, so a current alone fixes no overall scale: multiplying
:math:`K_t`, :math:`m`, :math:`s`, :math:`F_c`, :math:`b` and the rotating
inertias together leaves it unchanged. A known torque fixes it only if its
shape is none of the free terms': the rotor's inertia multiplies the
acceleration as the mass does, the bearings' drag follows the sign as the
Coulomb force does, and the weight on an inclined axis is a constant as the
offset is. One of :math:`K_t` and :math:`m` is therefore held, and by
default (:func:`free_parameters`) the fit has no more free parameters than
the Coulomb + viscous + inertia regression (:data:`BASELINE_PARAMETERS`, 4):
the offset :math:`y_0`, :math:`F_c`, :math:`b`, and :math:`m` when :math:`K_t`
is known (``--torque-constant``, or the case's ``motor.torque_constant``), else
:math:`K_t` with the case's ``moving_mass`` held; a torque or power trace has
its scale and fits :math:`m`. The screw-friction scale :math:`s` is held at 1:
the screw model's friction hardly changes over an air cut's speeds and loads,
so :math:`s` and :math:`F_c` are one term there (their estimates correlate at
-1), and the model of the screw is what the package brings, the guideway's
Coulomb force what the trace adds. ``free`` and ``hold`` change the set
(``--free kt`` fits :math:`K_t` and holds the mass; ``--free s --hold fc``
scales the screw instead). The model is linear in what is free (in
:math:`1/K_t`, :math:`F_c/K_t`, ... when :math:`K_t` is): one least-squares
solve.

**Identifiability from the data.** Whatever the set, the trace decides what
it tells apart: :func:`identifiability` gives the correlation of the estimates
from the Fisher information :math:`X^TX` of the filtered design, and a pair
beyond :data:`CONFOUNDED` (0.98) is reported as not identifiable, naming both,
with no interval for either (a combination of the two is what the trace
gives). A default viscous term the trace cannot tell from another (one feed)
is held at 0 and the notes say so.

**Intervals.** Residuals of a trace are correlated over several samples
(the filter, the drive's own filters), so the ordinary least-squares
intervals are too narrow. The intervals are a **moving-block residual
bootstrap** of the filtered fit (Künsch, Ann. Stat. 17, 1989, 1217; Lahiri,
Resampling Methods for Dependent Data, 2003, ch. 2): :data:`REPLICATES`
resamples of the residuals in blocks of :math:`L` consecutive samples,
:math:`L` being :data:`BLOCK_LAGS` = 10 times the lag at which the residuals'
autocorrelation falls below 0.1 (at least :math:`n^{1/3}`, at most
:math:`n/4`); each resample is refitted (the same linear solve, all at once)
and the physical parameters (:math:`K_t = 1/c`, ...) are taken from each. The
95 % interval is the 2.5 and 97.5 % percentiles of the replicates, and their
correlation matrix says which parameters the trace cannot tell apart (the
screw scale and the Coulomb force when the screw's friction hardly varies with
speed).

**Scores** (:class:`Score`): :math:`R^2 = 1 - \sum(y - \hat y)^2/\sum(y -
\bar y)^2`, the NRMSE (RMS error over the range of :math:`y`) and the energy the
motor delivers, :math:`E = \int\max(T\omega_m, 0)\,dt`, with the measured
torque :math:`(y - y_0)K_t` and the predicted one taken through the same
fitted :math:`y_0`, :math:`K_t`, the prediction being the filtered model against the
signal as sampled; beside the two baselines a control engineer would fit to the
same (filtered) signal: :math:`y = a_0 + a_1\,\mathrm{sgn}(v)` and the
Coulomb + viscous + inertia regression :math:`y = a_0 + a_1\,\mathrm{sgn}(v) +
a_2 v + a_3\dot v` (times :math:`\omega_m` for a power).

**Synthetic traces** (:func:`synthetic_trace`): the same model with known
parameters on a planned motion, sampled like a drive, with position noise and
autocorrelated signal noise, so that the fit can be checked against the truth.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from ..axis.energy import Axis, axis_cycle, friction_sign
from ..axis.motion import Profile
from ..axis.setup import axis_setup
from ..axis.standstill import standstill_speed
from ..errors import BallScrewInputError, FloatArray
from ..io.case import Case
from ..io.machine import Machine
from ..io.trace import AxisTrace, Trace
from ..materials import STANDARD_GRAVITY

__all__ = [
    "BASELINE_PARAMETERS",
    "CONFOUNDED",
    "PARAMETERS",
    "REPLICATES",
    "SMOOTHING",
    "AxisFit",
    "AxisInputs",
    "IdentifyResult",
    "Parameter",
    "Regressors",
    "Score",
    "TrueAxis",
    "axis_inputs",
    "calibrated_machine_text",
    "fit_axis",
    "free_parameters",
    "identifiability",
    "identify",
    "parameter_names",
    "regressors",
    "score_axis",
    "shaft_energy",
    "synthetic_trace",
]

SMOOTHING = 0.01
"""Standard deviation of the Gaussian filter [s] (at least :data:`MIN_SMOOTHING` samples)."""
MIN_SMOOTHING = 1.5
"""The filter's least standard deviation [samples]."""
REPLICATES = 1000
"""Bootstrap resamples of the residuals."""
BLOCK_LAGS = 10
"""The bootstrap's block over the lag at which the residuals' autocorrelation falls below 0.1."""
UNIFORM = 0.01
"""Largest deviation of a sample spacing from the median spacing, as a share."""

PARAMETERS: dict[str, tuple[str, str]] = {
    "torque_constant": ("N*m/A", "current-to-torque scale K_t"),
    "offset": ("", "offset of the signal y_0"),
    "moving_mass": ("kg", "moving mass m"),
    "screw_scale": ("", "scale on the screw model's friction s"),
    "guide_coulomb": ("N", "guideway Coulomb force F_c"),
    "guide_viscous": ("N*s/m", "guideway viscous coefficient b"),
}
"""The parameters of an axis: unit and meaning (the offset in the signal's unit)."""


@dataclass(frozen=True)
class AxisInputs:
    """What the fit takes of one axis of the machine (SI).

    ``torque_constant`` [N·m/A]: the motor's :math:`K_t` a current trace's
    torque scale is held by (None: none known, the case's moving mass holds
    it); ``torque_constant_source`` says where it came from.
    """

    letter: str
    case: Case
    axis: Axis
    model: str
    temperature: float
    parameters: dict[str, Any] = field(default_factory=dict)
    torque_constant: float | None = None
    process_force: float = 0.0
    torque_constant_source: str = ""


def axis_inputs(
    machine: Machine, letter: str, torque_constant: float | None = None,
    travel: float | None = None,
) -> AxisInputs:  # fmt: skip
    """The inputs of axis ``letter`` of ``machine`` (its case, set up as ``program`` does).

    ``torque_constant`` [N·m/A] (``--torque-constant``) overrides the case's
    ``motor.torque_constant``; with neither, none is known.
    """
    if letter not in machine.axes:
        raise BallScrewInputError(
            f"trace axis {letter}", letter,
            f"an axis of the machine file ({', '.join(machine.axes)})",
        )  # fmt: skip
    ax = machine.axes[letter]
    case = ax.case
    span = ax.travel[1] - ax.travel[0] if travel is None else travel
    thermal = dict(case.thermal)
    thermal["ambient"] = machine.ambient
    setup = axis_setup(case.screw, case.axis, thermal, span)
    if torque_constant is not None and not (
        math.isfinite(torque_constant) and torque_constant > 0.0
    ):
        raise BallScrewInputError(f"--torque-constant {letter}", torque_constant, "a value > 0")
    source = "--torque-constant" if torque_constant is not None else ""
    if torque_constant is None and case.motor.get("torque_constant") is not None:
        torque_constant = float(case.motor["torque_constant"])
        source = f"axes.{letter}.case.motor.torque_constant"
    return AxisInputs(letter, case, setup.axis, machine.model, ax.start_temperature,
                      case.parameters_for(machine.model), torque_constant,
                      torque_constant_source=source)  # fmt: skip


@dataclass(frozen=True)
class Regressors:
    """The model's terms on a trajectory, as torques at the motor [N·m] per unit parameter.

    ``known``: the rotating inertias, the bearings and the process force (no
    free parameter); ``mass``: per kg of moving mass (inertia and weight);
    ``screw``: the screw model's friction (scale 1); ``coulomb``: per N of
    guideway Coulomb force; ``viscous``: per N·s/m. ``speed`` and
    ``acceleration`` are the table's [m/s, m/s²], ``motor_speed`` [rad/s];
    ``standstill_speed`` [m/s] the ramp's width.
    """

    time: FloatArray
    speed: FloatArray
    acceleration: FloatArray
    motor_speed: FloatArray
    known: FloatArray
    mass: FloatArray
    screw: FloatArray
    coulomb: FloatArray
    viscous: FloatArray
    standstill_speed: float
    sign: FloatArray


def _uniform_step(time: FloatArray, source: str) -> float:
    """The sample spacing [s], refused unless uniform to :data:`UNIFORM`."""
    steps = np.diff(time)
    dt = float(np.median(steps))
    off = np.abs(steps - dt) > UNIFORM * dt
    if np.any(off):
        k = int(np.argmax(off))
        raise BallScrewInputError(
            f"{source}: sample {k + 2}", f"a step of {steps[k] * 1e3:.4g} ms",
            f"uniform sampling ({dt * 1e3:.4g} ms, within {UNIFORM:.0%}): the speed is a "
            "difference of neighbouring samples; cut the trace at the gap or resample it",
        )  # fmt: skip
    return dt


def kinematics(
    time: FloatArray, position: FloatArray, smoothing: float = SMOOTHING, source: str = "trace"
) -> tuple[FloatArray, FloatArray, float, float]:
    r"""Speed [m/s], acceleration [m/s²], standstill width [m/s], filter's width [samples].

    Central differences of the samples (module docstring): the speed
    :math:`(x_{k+1} - x_{k-1})/2\Delta t` and the acceleration :math:`(x_{k+1} - 2x_k +
    x_{k-1})/\Delta t^2`; the width is the speed noise's
    (:func:`~ballscrew.axis.standstill.standstill_speed`).
    """
    dt = _uniform_step(time, source)
    sigma = max(MIN_SMOOTHING, smoothing / dt)
    if time.size < 8 * sigma:
        raise BallScrewInputError(source, f"{time.size} samples",
                                  f"at least {math.ceil(8 * sigma)} (8 times the filter's "
                                  "width)")  # fmt: skip
    v = np.gradient(position, dt)
    a = np.empty_like(position)
    a[1:-1] = (position[2:] - 2.0 * position[1:-1] + position[:-2]) / dt**2
    a[0], a[-1] = a[1], a[-2]
    return v, a, standstill_speed(position, time), sigma


def hat(values: FloatArray) -> FloatArray:
    r"""The samples averaged as ``[1, 2, 1]/4`` (the ends kept) [unit of ``values``].

    The second difference of the positions is the acceleration averaged over
    :math:`\pm\Delta t` with a triangular weight (exactly, whatever the motion
    between the samples); the measured signal, averaged with the same weight
    (by the trapezoidal rule), is the one the model's inertia meets.
    """
    y = np.asarray(values, dtype=float)
    out = y.copy()
    out[1:-1] = 0.25 * y[:-2] + 0.5 * y[1:-1] + 0.25 * y[2:]
    return out


def smooth(values: FloatArray, sigma: float) -> FloatArray:
    """The Gaussian filter of standard deviation ``sigma`` [samples] (the ends held)."""
    from scipy.ndimage import gaussian_filter1d

    out: FloatArray = gaussian_filter1d(np.asarray(values, dtype=float), sigma, mode="nearest")
    return out


def regressors(profile: Profile, inputs: AxisInputs, mass: float | None = None) -> Regressors:
    """The model's terms (:class:`Regressors`) over ``profile``.

    The screw's friction is the model's at each sample's axial load with the
    moving mass ``mass`` (default: the case's), through
    :func:`~ballscrew.axis.energy.axis_cycle` (its sign ramped over the
    profile's ``standstill_speed``).
    """
    screw = inputs.case.screw
    axis = inputs.axis if mass is None else replace(inputs.axis, moving_mass=float(mass))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # speed limits and validity: the fit's notes
        cycle = axis_cycle(profile, screw, inputs.case.lubricant, axis,
                           temperature=inputs.temperature, model=inputs.model,
                           **inputs.parameters)  # fmt: skip
    i = axis.gear_ratio
    lead = screw.lead
    r = lead / (2.0 * math.pi * i)
    omega = cycle.screw_speed
    sign = friction_sign(profile, omega, lead)
    alpha = 2.0 * math.pi * profile.acceleration / lead
    rotating = cycle.inertia_torque / i + axis.motor_inertia * i * alpha
    known = rotating + r * profile.process_force + sign * cycle.bearing_torque / i
    g_axial = STANDARD_GRAVITY * math.sin(axis.incline)
    return Regressors(
        time=profile.time, speed=profile.speed, acceleration=profile.acceleration,
        motor_speed=omega * i, known=known, mass=r * (profile.acceleration + g_axial),
        screw=sign * cycle.friction_torque / i, coulomb=r * sign, viscous=r * profile.speed,
        standstill_speed=profile.standstill_speed, sign=sign,
    )  # fmt: skip


def measured_profile(
    time: FloatArray, position: FloatArray, smoothing: float = SMOOTHING,
    standstill_speed: float | None = None, source: str = "trace", process_force: float = 0.0,
) -> tuple[Profile, float]:  # fmt: skip
    """The trajectory of a measured axis as a :class:`~ballscrew.axis.motion.Profile`.

    Filtered kinematics (:func:`kinematics`); the standstill width from the
    noise unless given. Returns the profile and the filter's width [samples].
    """
    v, a, width, sigma = kinematics(time, position, smoothing, source)
    force = np.full_like(time, float(process_force))
    width = width if standstill_speed is None else standstill_speed
    return Profile(time, position, v, a, force, standstill_speed=width), sigma


@dataclass(frozen=True)
class Parameter:
    """A parameter of an axis: value, 95 % interval, unit; ``fitted`` False when held.

    ``confounded_with``: the fitted parameters this trace cannot tell it from
    (:func:`identifiability`); its interval is then not given (NaN).
    """

    name: str
    value: float
    low: float
    high: float
    unit: str
    fitted: bool = True
    confounded_with: tuple[str, ...] = ()

    @property
    def identifiable(self) -> bool:
        """Whether the trace tells this parameter from every other fitted one."""
        return not self.confounded_with

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready."""
        return {"value": self.value, "low_95": self.low, "high_95": self.high,
                "unit": self.unit, "fitted": self.fitted, "identifiable": self.identifiable,
                "confounded_with": list(self.confounded_with)}  # fmt: skip


@dataclass(frozen=True)
class Score:
    """How well a prediction explains a signal.

    ``r2`` and ``nrmse`` [-]; ``energy_measured`` and ``energy_predicted`` [J]:
    the energy the motor delivers (module docstring).
    """

    r2: float
    nrmse: float
    energy_measured: float
    energy_predicted: float

    @property
    def energy_error(self) -> float:
        """(predicted - measured) / measured energy [-]."""
        if self.energy_measured == 0.0:
            return math.nan
        return (self.energy_predicted - self.energy_measured) / self.energy_measured

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready."""
        return {"r2": self.r2, "nrmse": self.nrmse, "energy_measured_J": self.energy_measured,
                "energy_predicted_J": self.energy_predicted,
                "energy_error": self.energy_error}  # fmt: skip


def shaft_energy(torque: FloatArray, motor_speed: FloatArray, time: FloatArray) -> float:
    r"""Energy the motor delivers, :math:`\int\max(T\omega_m, 0)\,dt` [J] (trapezoidal rule)."""
    p = np.maximum(torque * motor_speed, 0.0)
    return float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(time)))


def _scores(y: FloatArray, predicted: FloatArray, to_power: Any, time: FloatArray) -> Score:
    """R², NRMSE and the energies of measured ``y`` and a prediction of it."""
    residual = y - predicted
    spread = float(np.sum((y - np.mean(y)) ** 2))
    r2 = 1.0 - float(np.sum(residual**2)) / spread if spread > 0.0 else math.nan
    span = float(np.ptp(y))
    nrmse = float(np.sqrt(np.mean(residual**2))) / span if span > 0.0 else math.nan
    return Score(r2, nrmse, _integral_positive(to_power(y), time),
                 _integral_positive(to_power(predicted), time))  # fmt: skip


def _integral_positive(power: FloatArray, time: FloatArray) -> float:
    p = np.maximum(power, 0.0)
    return float(np.sum(0.5 * (p[1:] + p[:-1]) * np.diff(time)))


@dataclass(frozen=True)
class _Design:
    """The linear problem y ≈ X θ + base, its columns named by the parameters they give."""

    matrix: FloatArray  # n x p
    base: FloatArray  # the part of y with no free parameter
    columns: tuple[str, ...]  # the parameter each column gives (its coefficient's meaning)


HELD_AT = {"offset": 0.0, "screw_scale": 1.0, "guide_coulomb": 0.0, "guide_viscous": 0.0}
"""The value a parameter is held at when not fitted (the moving mass: the case's; K_t: known)."""
TERMS = ("moving_mass", "screw_scale", "guide_coulomb", "guide_viscous")
"""The parameters that multiply a term of the torque (:class:`Regressors`)."""
BASELINE_PARAMETERS = 4
"""The Coulomb + viscous + inertia regression's number of parameters."""
CONFOUNDED = 0.98
"""Largest absolute correlation of two estimates still told apart (:func:`identifiability`)."""
ALIASES = {"kt": "torque_constant", "k_t": "torque_constant", "mass": "moving_mass",
           "m": "moving_mass", "s": "screw_scale", "screw": "screw_scale",
           "fc": "guide_coulomb", "f_c": "guide_coulomb", "coulomb": "guide_coulomb",
           "b": "guide_viscous", "viscous": "guide_viscous", "y0": "offset"}  # fmt: skip
"""Short names of the parameters for ``--free`` and ``--hold``."""


def parameter_names(text: str | Sequence[str], option: str) -> tuple[str, ...]:
    """``"kt, s"`` (or a list) as names of :data:`PARAMETERS`, each known, or an error."""
    parts = text.replace(";", ",").split(",") if isinstance(text, str) else list(text)
    out: list[str] = []
    for part in parts:
        key = part.strip().lower()
        if not key:
            continue
        name = ALIASES.get(key, key)
        if name not in PARAMETERS:
            raise BallScrewInputError(option, part.strip(),
                                      f"names of parameters: {', '.join(PARAMETERS)} (or "
                                      f"{', '.join(ALIASES)})")  # fmt: skip
        if name not in out:
            out.append(name)
    return tuple(out)


def free_parameters(
    kind: str, inputs: AxisInputs, free: Sequence[str] = (), hold: Sequence[str] = ()
) -> tuple[str, ...]:
    r"""The parameters fitted by default, with ``free`` added and ``hold`` held (module docstring).

    By default, at most :data:`BASELINE_PARAMETERS`: the offset, the guideway's
    Coulomb force and viscous coefficient, and the one of :math:`K_t` and the
    moving mass that is not known: a current trace with a known :math:`K_t`
    (``--torque-constant`` or the case's ``motor.torque_constant``) fits the
    mass; without, :math:`K_t` is fitted and the case's mass holds the scale; a
    torque or power trace fits the mass. The screw-friction scale is held at 1.
    ``free`` = ``torque_constant`` fits :math:`K_t` and holds the mass instead
    (unless ``moving_mass`` is freed too). Refused: a current trace with neither
    :math:`K_t` nor the mass held or known, :math:`K_t` freed on a torque or
    power trace, a name both freed and held.
    """
    both = set(free) & set(hold)
    if both:
        raise BallScrewInputError("--free and --hold", ", ".join(sorted(both)),
                                  "a parameter either freed or held, not both")  # fmt: skip
    names = {"offset", "guide_coulomb", "guide_viscous"}
    if kind == "current" and (inputs.torque_constant is None or "torque_constant" in free):
        names.add("torque_constant")
    else:
        names.add("moving_mass")
    if kind != "current" and "torque_constant" in free:
        raise BallScrewInputError(f"--free (axis {inputs.letter})", "torque_constant",
                                  f"parameters of a {kind} trace: it has its torque scale, "
                                  "no K_t to fit")  # fmt: skip
    names = (names | set(free)) - set(hold)
    if kind == "current" and "torque_constant" not in names and inputs.torque_constant is None:
        raise BallScrewInputError(
            f"--hold (axis {inputs.letter})", "torque_constant",
            "a held K_t known: --torque-constant or the case's motor.torque_constant",
        )  # fmt: skip
    if "moving_mass" not in names and not float(inputs.axis.moving_mass) > 0.0:
        raise BallScrewInputError(
            f"axes.{inputs.letter}.case.axis.moving_mass", float(inputs.axis.moving_mass),
            "a moving mass > 0, or --torque-constant: a current trace gives the torque scale "
            "only with one of them known (the other is fitted)",
        )  # fmt: skip
    return tuple(k for k in PARAMETERS if k in names and not (
        k == "torque_constant" and kind != "current"))  # fmt: skip


def _held_values(kind: str, inputs: AxisInputs, mass: float) -> dict[str, float]:
    """Every parameter's value when held (K_t NaN for a torque or power trace)."""
    kt = inputs.torque_constant if kind == "current" else None
    return {"torque_constant": math.nan if kt is None else kt, "moving_mass": mass, **HELD_AT}


def _design(
    reg: Regressors, kind: str, free: Sequence[str], values: Mapping[str, float]
) -> _Design:
    """X and the fixed part for the signal ``kind`` (module docstring), the rest at ``values``."""
    ones = np.ones_like(reg.time)
    w = reg.motor_speed if kind == "power" else ones
    terms = {"moving_mass": reg.mass, "screw_scale": reg.screw, "guide_coulomb": reg.coulomb,
             "guide_viscous": reg.viscous}  # fmt: skip
    fitted = tuple(n for n in TERMS if n in free)
    held_torque = reg.known + sum((values[n] * terms[n] for n in TERMS if n not in free),
                                  np.zeros_like(ones))  # fmt: skip
    lead = ("offset",) if "offset" in free else ()
    offset = np.zeros_like(ones) if lead else np.full_like(ones, values["offset"])
    if "torque_constant" in free:
        # y = y0 + c (T_known + held terms) + sum (c p) phi_p, c = 1/K_t
        x = np.column_stack([ones, held_torque, *(terms[n] for n in fitted)][1 - len(lead) :])
        return _Design(x, offset, (*lead, "torque_constant", *fitted))
    k = 1.0 / values["torque_constant"] if kind == "current" else 1.0
    # y = y0 + k w (T_known + held terms) + sum p (k w phi_p), k known
    x = np.column_stack([ones, *(k * w * terms[n] for n in fitted)][1 - len(lead) :])
    return _Design(x, offset + k * w * held_torque, (*lead, *fitted))


def _filtered(design: _Design, sigma: float, keep: FloatArray) -> tuple[FloatArray, FloatArray]:
    """The design's columns and fixed part through the same filter as the signal, rows kept."""
    x = np.column_stack([smooth(c, sigma)[keep] for c in design.matrix.T])
    return x, smooth(design.base, sigma)[keep]


def _away_from_starts(profile: Profile, sigma: float) -> FloatArray:
    """The samples whose filter window holds no start or stop of a motion (a bool array).

    Where a move starts or stops, the friction steps between two samples, and
    neither the central difference nor the filter can tell between which:
    those samples are left out of the fit (not of its scores).
    """
    moving = np.abs(profile.speed) > 0.5 * profile.standstill_speed
    change = np.flatnonzero(np.diff(moving.astype(np.int8)) != 0)
    reach = math.ceil(2.0 * sigma) + 1
    near = np.zeros(profile.speed.size + 1, dtype=np.int64)
    np.add.at(near, np.clip(change - reach + 1, 0, near.size - 1), 1)
    np.add.at(near, np.clip(change + reach + 2, 0, near.size - 1), -1)
    keep: FloatArray = np.cumsum(near)[:-1] == 0
    return keep


def _physical(
    theta: FloatArray, design: _Design, values: Mapping[str, float]
) -> dict[str, FloatArray]:
    """Every parameter from the linear coefficients (rows: replicates), the held at ``values``."""
    t = np.atleast_2d(theta)
    n = t.shape[0]
    out = {name: np.full(n, float(values[name])) for name in PARAMETERS}
    column = {name: t[:, k] for k, name in enumerate(design.columns)}
    if "offset" in column:
        out["offset"] = column["offset"]
    c = column.get("torque_constant")
    with np.errstate(divide="ignore", invalid="ignore"):
        if c is not None:
            out["torque_constant"] = 1.0 / c
        for name in TERMS:
            if name in column:
                out[name] = column[name] if c is None else column[name] / c
    return out


def identifiability(
    x: FloatArray, names: Sequence[str]
) -> tuple[FloatArray, list[tuple[str, str, float]]]:
    r"""The estimates' correlation from the Fisher information, and the pairs not told apart.

    For the linear model :math:`y = X\theta + e` with errors of equal variance,
    the covariance of :math:`\hat\theta` is :math:`\sigma^2 (X^TX)^{-1}`, the
    inverse of the Fisher information; scaling the errors or their correlation
    in time changes its size, hardly its shape. With the columns scaled to unit
    length and :math:`X = U S V^T`, :math:`(X^TX)^{-1} = V S^{-2} V^T` (singular
    values below :math:`10^{-12}` of the largest taken at that floor, so an exactly
    rank-deficient design gives correlations of :math:`\pm 1`). Returns the
    correlation matrix (order of ``names``) and each pair whose correlation
    exceeds :data:`CONFOUNDED` in size: a combination of the two is known, each
    alone is not.
    """
    norms = np.linalg.norm(x, axis=0)
    norms[norms == 0.0] = 1.0
    _, sv, vt = np.linalg.svd(x / norms, full_matrices=False)
    sv = np.maximum(sv, 1e-12 * sv[0]) if sv.size else sv
    cov = (vt.T / sv**2) @ vt
    d = np.sqrt(np.diag(cov))
    corr: FloatArray = cov / np.outer(d, d)
    pairs = [(names[a], names[b], float(corr[a, b])) for a in range(len(names))
             for b in range(a + 1, len(names)) if abs(corr[a, b]) > CONFOUNDED]  # fmt: skip
    return corr, pairs


def _block_length(residual: FloatArray) -> int:
    """Twice the lag at which the residuals' autocorrelation falls below 0.1; >= n^(1/3)."""
    n = residual.size
    e = residual - residual.mean()
    spectrum = np.fft.rfft(e, 2 * n)
    acf = np.fft.irfft(spectrum * np.conj(spectrum))[:n]
    acf = acf / acf[0] if acf[0] > 0 else acf
    below = np.nonzero(acf < 0.1)[0]
    lag = int(below[0]) if below.size else n
    return int(min(n // 4, max(math.ceil(n ** (1.0 / 3.0)), BLOCK_LAGS * lag)))


def _bootstrap(
    x: FloatArray, residual: FloatArray, block: int, replicates: int, seed: int
) -> FloatArray:
    """Coefficient replicates of a moving-block residual bootstrap (replicates x p)."""
    n = residual.size
    rng = np.random.default_rng(seed)
    blocks = math.ceil(n / block)
    starts = rng.integers(0, n - block + 1, size=(replicates, blocks))
    index = (starts[:, :, None] + np.arange(block)).reshape(replicates, -1)[:, :n]
    e = residual - residual.mean()
    pinv = np.linalg.pinv(x)
    out: FloatArray = e[index] @ pinv.T
    return out


@dataclass(frozen=True)
class AxisFit:
    """One axis fitted to its trace.

    Attributes
    ----------
    letter, kind : str
        The axis and its signal ("current", "torque" or "power").
    held : str
        What holds the torque scale: "torque_constant" (K_t known and held),
        "moving_mass" (K_t fitted, the case's mass held), "signal" (a torque or
        power trace), "offset" (both fitted, the offset held) or "nothing" (both
        fitted: not identifiable).
    parameters : dict
        :class:`Parameter` by name (:data:`PARAMETERS`).
    correlation : numpy.ndarray
        The fitted parameters' correlation over the bootstrap (order of ``free``).
    free : tuple of str
        The fitted parameters' names.
    score : Score
        The fit on its own trace.
    baselines : dict
        The baselines' :class:`Score` by name.
    baseline_coefficients : dict
        The baselines' fitted coefficients by name.
    measured, predicted : numpy.ndarray
        The signal and the model's prediction of it.
    time : numpy.ndarray
        [s].
    block_length : int
        The bootstrap's block length [samples].
    standstill_speed : float
        The ramp's width [m/s].
    notes : tuple of str
        What the fit assumed or could not tell apart.
    confounded : tuple
        The pairs of fitted parameters the trace cannot tell apart, with the
        correlation of their estimates (:func:`identifiability`).
    """

    letter: str
    kind: str
    held: str
    parameters: dict[str, Parameter]
    correlation: FloatArray
    free: tuple[str, ...]
    score: Score
    baselines: dict[str, Score]
    baseline_coefficients: dict[str, FloatArray]
    measured: FloatArray = field(repr=False)
    predicted: FloatArray = field(repr=False)
    baseline_predictions: dict[str, FloatArray] = field(repr=False)
    time: FloatArray = field(repr=False)
    block_length: int
    standstill_speed: float
    notes: tuple[str, ...] = ()
    confounded: tuple[tuple[str, str, float], ...] = ()

    def value(self, name: str) -> float:
        """A parameter's value."""
        return self.parameters[name].value

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready (the time series left out)."""
        return {
            "signal": self.kind, "torque_scale_held_by": self.held,
            "free_parameters": len(self.free), "baseline_parameters": BASELINE_PARAMETERS,
            "not_identifiable": [{"parameters": [a, b], "correlation": r}
                                 for a, b, r in self.confounded],
            "parameters": {k: p.as_dict() for k, p in self.parameters.items()},
            "correlation": {"parameters": list(self.free),
                            "matrix": self.correlation.tolist()},
            "fit": self.score.as_dict(),
            "baselines": {k: s.as_dict() for k, s in self.baselines.items()},
            "bootstrap_block_samples": self.block_length,
            "standstill_speed_m_per_s": self.standstill_speed,
            "notes": list(self.notes),
        }  # fmt: skip


BASELINES = ("sign(v) alone", "Coulomb + viscous + inertia")
"""The baselines a control engineer fits to the same signal (module docstring)."""


def _baseline_matrix(reg: Regressors, kind: str, name: str) -> FloatArray:
    ones = np.ones_like(reg.time)
    w = reg.motor_speed if kind == "power" else ones
    sgn = np.sign(reg.speed)
    if name == BASELINES[0]:
        return np.column_stack([ones, w * sgn])
    return np.column_stack([ones, w * sgn, w * reg.speed, w * reg.acceleration])


def _signal_unit(kind: str) -> str:
    return {"current": "A", "torque": "N*m", "power": "W"}[kind]


def _to_power(kind: str, offset: float, torque_constant: float, motor_speed: FloatArray) -> Any:
    """A function from the signal to the shaft power (module docstring)."""
    if kind == "power":
        return lambda y: y - offset
    k = torque_constant if kind == "current" else 1.0
    return lambda y: (y - offset) * k * motor_speed


def fit_axis(
    trace: AxisTrace, time: FloatArray, inputs: AxisInputs, *, smoothing: float = SMOOTHING,
    standstill_speed: float | None = None, replicates: int = REPLICATES, seed: int = 0,
    source: str = "trace", free: Sequence[str] = (), hold: Sequence[str] = (),
) -> AxisFit:  # fmt: skip
    """Fit one axis of a trace (module docstring).

    ``standstill_speed`` [m/s]: the ramp's width (None: 8 times the speed
    noise); ``replicates``: bootstrap resamples; ``seed`` makes them
    reproducible; ``free`` and ``hold``: parameters fitted beyond the default
    set, or held (:func:`free_parameters`).
    """
    if isinstance(replicates, bool) or not isinstance(replicates, int) or replicates < 100:
        raise BallScrewInputError("replicates", replicates, "a whole number >= 100")
    kind = trace.kind
    chosen = free_parameters(kind, inputs, free, hold)
    profile, sigma = measured_profile(time, trace.position, smoothing, standstill_speed,
                                      f"{source}: axis {trace.letter}",
                                      inputs.process_force)  # fmt: skip
    case_mass = float(inputs.axis.moving_mass)
    y = trace.signal
    keep = _away_from_starts(profile, sigma)
    y_f = smooth(hat(y), sigma)[keep]
    values = _held_values(kind, inputs, case_mass)
    reg = regressors(profile, inputs, case_mass)
    auto_held: list[tuple[str, str, float]] = []
    while True:
        design = _design(reg, kind, chosen, values)
        x_f, base_f = _filtered(design, sigma, keep)
        _, pairs = identifiability(x_f, design.columns)
        # A trace that cannot tell the viscous term from another (one feed) holds it at 0
        # when it was free by default, and says so; a pair the user freed is reported.
        viscous = [pair for pair in pairs if "guide_viscous" in pair[:2]]
        if not viscous or "guide_viscous" in free:
            break
        chosen = tuple(k for k in chosen if k != "guide_viscous")
        auto_held.append(viscous[0])
    theta, *_ = np.linalg.lstsq(x_f, y_f - base_f, rcond=None)
    point = {k: float(v[0]) for k, v in _physical(theta, design, values).items()}
    mass = point["moving_mass"]
    if "moving_mass" in chosen and abs(mass - case_mass) > 0.02 * max(case_mass, 1.0):
        # The screw's friction was taken at the case's mass: once again at the fitted one.
        reg = regressors(profile, inputs, max(mass, 0.0))
        design = _design(reg, kind, chosen, values)
        x_f, base_f = _filtered(design, sigma, keep)
        _, pairs = identifiability(x_f, design.columns)
        theta, *_ = np.linalg.lstsq(x_f, y_f - base_f, rcond=None)
        point = {k: float(v[0]) for k, v in _physical(theta, design, values).items()}
    fitted = smooth(design.matrix @ theta + design.base, sigma)
    residual = y_f - x_f @ theta - base_f
    block = _block_length(residual)
    draws = theta + _bootstrap(x_f, residual, block, replicates, seed)
    reps = _physical(draws, design, values)
    held = ("signal" if kind != "current" else "torque_constant"
            if "torque_constant" not in chosen else "moving_mass"
            if "moving_mass" not in chosen else "nothing"
            if "offset" in chosen else "offset")  # fmt: skip
    parameters = _parameters(kind, chosen, pairs, point, reps)
    with np.errstate(invalid="ignore", divide="ignore"):
        correlation = np.atleast_2d(
            np.corrcoef(np.column_stack([reps[k] for k in chosen]), rowvar=False)
        ).astype(float)
    kt = point["torque_constant"]
    to_power = _to_power(kind, point["offset"], kt, reg.motor_speed)
    score = _scores(y, fitted, to_power, time)
    baselines, coefficients, predictions = _baselines(reg, kind, y, y_f, sigma, keep, to_power,
                                                      time)  # fmt: skip
    notes = _notes(chosen, pairs, parameters, profile.standstill_speed, inputs, held)
    for one, other, r in auto_held:
        partner = other if one == "guide_viscous" else one
        notes.append(f"guide_viscous held at 0: this trace cannot tell it from {partner} "
                     f"(correlation {r:+.3f}): one speed, or speeds too alike; a trace with "
                     "more feeds frees it")  # fmt: skip
    return AxisFit(trace.letter, kind, held, parameters, correlation, chosen, score, baselines,
                   coefficients, y, fitted, predictions, time, block, profile.standstill_speed,
                   tuple(notes), tuple(pairs))  # fmt: skip


def _parameters(
    kind: str, chosen: Sequence[str], pairs: Sequence[tuple[str, str, float]],
    point: Mapping[str, float], reps: Mapping[str, FloatArray],
) -> dict[str, Parameter]:  # fmt: skip
    """Each parameter with its 95 % interval (none when confounded; its value when held)."""
    confounded: dict[str, list[str]] = {}
    for one, other, _ in pairs:
        confounded.setdefault(one, []).append(other)
        confounded.setdefault(other, []).append(one)
    parameters: dict[str, Parameter] = {}
    for name, (unit, _) in PARAMETERS.items():
        is_free = name in chosen
        with_ = tuple(confounded.get(name, ()))
        lo, hi = ((float(np.nanpercentile(reps[name], 2.5)), float(np.nanpercentile(reps[name],
                  97.5))) if is_free and not with_ else
                  (math.nan, math.nan) if is_free else (point[name], point[name]))  # fmt: skip
        parameters[name] = Parameter(name, point[name], lo, hi,
                                     _signal_unit(kind) if name == "offset" else unit,
                                     is_free, with_)  # fmt: skip
    return parameters


def _baselines(
    reg: Regressors, kind: str, y: FloatArray, y_f: FloatArray, sigma: float, keep: FloatArray,
    to_power: Any, time: FloatArray,
) -> tuple[dict[str, Score], dict[str, FloatArray], dict[str, FloatArray]]:  # fmt: skip
    """The baselines fitted to the filtered signal: scores, coefficients, predictions."""
    baselines, coefficients, predictions = {}, {}, {}
    for name in BASELINES:
        xb = _baseline_matrix(reg, kind, name)
        cb, *_ = np.linalg.lstsq(np.column_stack([smooth(c, sigma)[keep] for c in xb.T]), y_f,
                                 rcond=None)  # fmt: skip
        coefficients[name] = cb
        predictions[name] = smooth(xb @ cb, sigma)
        baselines[name] = _scores(y, predictions[name], to_power, time)
    return baselines, coefficients, predictions


ADVICE = {
    frozenset(("screw_scale", "guide_coulomb")): "the screw model's friction hardly changes "
    "with this trace's speeds and loads, so its scale and a guideway Coulomb force are one "
    "term; a trace with other loads (a process force, another moving mass, up and down a "
    "vertical axis) can separate them; by default the screw's scale is held at 1",
    frozenset(("torque_constant", "moving_mass")): "every torque of the model scales with "
    "both; a known torque of another shape separates them (the gravity of a vertical axis "
    "with the offset held: --hold offset; a known process force); by default one is held, "
    "K_t from the motor's data or else the case's moving mass",
}
"""Why a pair is not identifiable, and what would separate it."""


def _notes(
    free: Sequence[str], pairs: Sequence[tuple[str, str, float]],
    parameters: Mapping[str, Parameter], width: float, inputs: AxisInputs, held: str,
) -> list[str]:  # fmt: skip
    """What the fit assumed, and the parameters the trace could not tell apart."""
    notes = [
        f"standstill: no friction below +-{width * 5e2:.3g} mm/s, the full friction from "
        f"+-{width * 1e3:.3g} mm/s (8 x the speed noise)"
    ]
    if inputs.process_force == 0.0:
        notes.append("no process force (an air cut)")
    if held == "torque_constant":
        notes.append(f"K_t held at {inputs.torque_constant:.4g} N*m/A "
                     f"({inputs.torque_constant_source}); --free kt fits it and holds the "
                     "case's moving mass instead")  # fmt: skip
        mass, case_mass = parameters["moving_mass"], float(inputs.axis.moving_mass)
        if mass.fitted and mass.value <= 0.0:
            notes.append(f"the fitted moving mass, {mass.value:.4g} kg, is not a mass: the "
                         "trace does not show enough acceleration for it (too short, too "
                         "slow or too coarse); take a trace with several accelerations, or "
                         "--free kt to hold the case's mass")  # fmt: skip
        elif case_mass > 0.0 and mass.identifiable and abs(mass.value / case_mass - 1.0) > 0.25:
            notes.append(f"the fitted moving mass is {mass.value / case_mass:.2f} times the "
                         f"case's {case_mass:.4g} kg: the case's mass or K_t is off (a drive "
                         "that logs the peak or q-axis current against a K_t per A rms is "
                         "off by sqrt(2) = 1.41); the trace alone cannot tell which")  # fmt: skip
    if len(free) > BASELINE_PARAMETERS:
        notes.append(f"{len(free)} parameters are free, more than the Coulomb + viscous + "
                     f"inertia regression's {BASELINE_PARAMETERS}")  # fmt: skip
    for a, b, r in pairs:
        why = ADVICE.get(frozenset((a, b)), "their terms have nearly the same shape in this "
                         "trace")  # fmt: skip
        notes.append(f"{a} and {b} are not identifiable from this trace (correlation {r:+.3f} "
                     "of their estimates, from the Fisher information): their intervals are "
                     f"not given, only a combination of the two is known; {why}")  # fmt: skip
    for name, p in parameters.items():
        if p.fitted and p.identifiable and name in TERMS and p.high < 0.0:
            notes.append(f"{name} is negative beyond its interval ({p.value:.3g}): the model "
                         "misses something this trace holds")  # fmt: skip
    return notes


def score_axis(
    fit: AxisFit, trace: AxisTrace, time: FloatArray, inputs: AxisInputs, *,
    smoothing: float = SMOOTHING, source: str = "trace",
) -> tuple[Score, dict[str, Score], FloatArray]:  # fmt: skip
    """A fitted axis's prediction of another trace, scored; the baselines' too.

    The parameters of ``fit`` on the trajectory of ``trace`` (its own
    standstill width); the baselines with the coefficients fitted on the first
    trace. Returns the model's :class:`Score`, the baselines' and the prediction.
    """
    if trace.kind != fit.kind:
        raise BallScrewInputError(f"{source}: axis {trace.letter}", trace.kind,
                                  f"the signal the fit was made on, {fit.kind}")  # fmt: skip
    profile, sigma = measured_profile(time, trace.position, smoothing, None,
                                      f"{source}: axis {trace.letter}",
                                      inputs.process_force)  # fmt: skip
    predicted, reg = predict_signal(fit, profile, inputs)
    predicted = smooth(predicted, sigma)
    p = fit.parameters
    to_power = _to_power(fit.kind, p["offset"].value, p["torque_constant"].value,
                         reg.motor_speed)  # fmt: skip
    y = trace.signal
    baselines = {name: _scores(y, smooth(_baseline_matrix(reg, fit.kind, name)
                                         @ fit.baseline_coefficients[name], sigma),
                               to_power, time)
                 for name in BASELINES}  # fmt: skip
    return _scores(y, predicted, to_power, time), baselines, predicted


def predict_signal(
    fit: AxisFit, profile: Profile, inputs: AxisInputs
) -> tuple[FloatArray, Regressors]:
    """The signal a fitted axis gives over ``profile``, and the model's terms there."""
    p = {k: v.value for k, v in fit.parameters.items()}
    reg = regressors(profile, inputs, max(p["moving_mass"], 0.0))
    torque = axis_torque(reg, p)
    if fit.kind == "power":
        return p["offset"] + torque * reg.motor_speed, reg
    k = p["torque_constant"] if fit.kind == "current" else 1.0
    return p["offset"] + torque / k, reg


def axis_torque(reg: Regressors, p: Mapping[str, float]) -> FloatArray:
    """The motor torque of the model [N·m] with the parameters ``p`` (module docstring)."""
    out: FloatArray = (
        reg.known
        + p["moving_mass"] * reg.mass
        + p["screw_scale"] * reg.screw
        + p["guide_coulomb"] * reg.coulomb
        + p["guide_viscous"] * reg.viscous
    )
    return out  # fmt: skip


@dataclass(frozen=True)
class IdentifyResult:
    """Every axis of a trace fitted (:func:`identify`), and the validation, when asked."""

    source: str
    fits: dict[str, AxisFit]
    validation: dict[str, tuple[Score, dict[str, Score], FloatArray]] = field(
        default_factory=dict, repr=False
    )
    validation_source: str = ""
    validation_time: FloatArray | None = field(default=None, repr=False)
    validation_measured: dict[str, FloatArray] = field(default_factory=dict, repr=False)
    notes: tuple[str, ...] = ()

    def as_dict(self) -> dict[str, Any]:
        """The JSON document of ``ballscrew identify --json``."""
        from .._version import __version__

        out: dict[str, Any] = {
            "ballscrew": __version__, "trace": self.source,
            "axes": {k: f.as_dict() for k, f in self.fits.items()},
            "notes": list(self.notes),
        }  # fmt: skip
        if self.validation:
            out["validation"] = {
                "trace": self.validation_source,
                "axes": {k: {"model": s.as_dict(),
                             "baselines": {n: b.as_dict() for n, b in base.items()}}
                         for k, (s, base, _) in self.validation.items()},
            }  # fmt: skip
        return out


def identify(
    trace: Trace, machine: Machine, *, torque_constants: Mapping[str, float] | None = None,
    validate: Trace | None = None, smoothing: float = SMOOTHING,
    standstill_speed: float | None = None, replicates: int = REPLICATES, seed: int = 0,
    free: Sequence[str] = (), hold: Sequence[str] = (),
) -> IdentifyResult:  # fmt: skip
    """Fit every axis of ``trace`` (module docstring); score ``validate`` with the fit.

    ``torque_constants`` [N·m/A] by axis override the cases' ``motor.torque_constant``;
    ``free`` and ``hold`` (names of :data:`PARAMETERS`) apply to every axis
    (:func:`free_parameters`).
    """
    constants = dict(torque_constants or {})
    for letter in constants:
        if letter not in trace.axes:
            raise BallScrewInputError(
                f"--torque-constant {letter}", letter,
                f"an axis of the trace ({', '.join(trace.axes)})",
            )  # fmt: skip
    fits: dict[str, AxisFit] = {}
    inputs: dict[str, AxisInputs] = {}
    for letter, ax in trace.axes.items():
        travel = float(np.ptp(ax.position))
        inputs[letter] = axis_inputs(machine, letter, constants.get(letter), travel)
        fits[letter] = fit_axis(ax, trace.time, inputs[letter], smoothing=smoothing,
                                standstill_speed=standstill_speed, replicates=replicates,
                                seed=seed, source=trace.source, free=free,
                                hold=hold)  # fmt: skip
    result = IdentifyResult(trace.source, fits, notes=trace.notes)
    if validate is None:
        return result
    scored = {}
    for letter, fit in fits.items():
        if letter not in validate.axes:
            raise BallScrewInputError(
                f"{validate.source}: axis {letter}", "(missing)",
                f"the axes of the fitted trace, {', '.join(fits)}",
            )  # fmt: skip
        scored[letter] = score_axis(fit, validate.axes[letter], validate.time, inputs[letter],
                                    smoothing=smoothing, source=validate.source)  # fmt: skip
    return replace(result, validation=scored, validation_source=validate.source,
                   validation_time=validate.time,
                   validation_measured={k: validate.axes[k].signal for k in fits})  # fmt: skip


def _resampled(time: FloatArray, at: FloatArray, values: FloatArray, step: float) -> FloatArray:
    """``values`` sampled at ``at`` read at ``time``: linear, held across wider gaps.

    A planner samples a dwell by its two ends only; the signal at its start holds
    until its end (a step where the next move starts), not a ramp across the dwell.
    """
    k = np.clip(np.searchsorted(at, time, side="right") - 1, 0, at.size - 2)
    gap = at[k + 1] - at[k]
    linear = np.interp(time, at, values)
    held: FloatArray = np.where(gap > 2.0 * step, values[k], linear)
    return held


@dataclass(frozen=True)
class TrueAxis:
    """The truth of a synthetic axis: its parameters (SI) and its signal."""

    torque_constant: float = 1.2
    offset: float = 0.05
    moving_mass: float = 300.0
    screw_scale: float = 1.0
    guide_coulomb: float = 60.0
    guide_viscous: float = 200.0
    kind: str = "current"

    def as_parameters(self) -> dict[str, float]:
        """By the names of :data:`PARAMETERS`."""
        return {k: float(getattr(self, k)) for k in PARAMETERS}


def synthetic_trace(
    profiles: Mapping[str, Profile], inputs: Mapping[str, AxisInputs],
    truth: Mapping[str, TrueAxis], *, sample_time: float = 0.02,
    position_noise: float = 1e-6, signal_noise: float = 0.03, correlation: float = 0.5,
    seed: int = 0, source: str = "synthetic",
) -> Trace:  # fmt: skip
    r"""A drive trace the model makes of planned motions, sampled like a drive, with noise.

    Each axis's exact motion (``profiles``, finely sampled, all of equal
    duration) gives its signal through the model with the parameters of
    ``truth`` (exact sign of the speed: no friction at rest); both are sampled
    every ``sample_time`` [s]. The positions get white noise of
    ``position_noise`` [m]; the signal autocorrelated noise, an AR(1) process
    :math:`e_k = \rho e_{k-1} + \sqrt{1-\rho^2}\,\sigma\,\epsilon_k` of standard
    deviation ``signal_noise`` :math:`\sigma` (in the signal's unit) and
    lag-one correlation ``correlation`` :math:`\rho`. Reproducible by ``seed``.
    """
    from scipy.signal import lfilter

    from ..io.trace import AxisTrace as _AxisTrace

    if not 0.0 <= correlation < 1.0:
        raise BallScrewInputError("correlation", correlation, "in [0, 1)")
    rng = np.random.default_rng(seed)
    end = min(float(p.time[-1]) for p in profiles.values())
    time = np.arange(0.0, end + 0.5 * sample_time, sample_time)
    time = time[time <= end]
    axes: dict[str, AxisTrace] = {}
    for letter, profile in profiles.items():
        ax, true = inputs[letter], truth[letter]
        exact = replace(profile, standstill_speed=0.0)
        p = true.as_parameters()
        reg = regressors(exact, ax, p["moving_mass"])
        torque = axis_torque(reg, p)
        if true.kind == "power":
            signal = p["offset"] + torque * reg.motor_speed
        elif true.kind == "torque":
            signal = p["offset"] + torque
        else:
            signal = p["offset"] + torque / p["torque_constant"]
        y = _resampled(time, profile.time, signal, sample_time)
        x = np.interp(time, profile.time, profile.position)
        white = rng.normal(0.0, 1.0, time.size)
        scale = math.sqrt(1.0 - correlation**2)  # a stationary start: e_0 = white_0
        rest = lfilter([scale], [1.0, -correlation], white[1:], zi=[correlation * white[0]])[0]
        e = np.concatenate([white[:1], rest])
        axes[letter] = _AxisTrace(
            letter, x + rng.normal(0.0, position_noise, time.size), y + signal_noise * e,
            true.kind,
            (f"{letter} position [m]", f"{letter} {true.kind} [{_signal_unit(true.kind)}]"),
        )  # fmt: skip
    return Trace(time, axes, source)


NO_KEY = {
    "torque_constant": "motor.torque_constant",
    "screw_scale": "study.model_parameters.<model>.friction_scale",
    "guide_coulomb": "axis.guide_coulomb",
    "guide_viscous": "axis.guide_viscous",
}
"""The fitted values a machine file has no key for yet, and the key each would take."""


def calibrated_machine_text(machine: Machine, result: IdentifyResult) -> str:
    """The machine file with each fitted axis's case inline and its fitted moving mass in it.

    What a machine file can hold is written as its keys (``axes.L.case.axis.moving_mass``,
    with its 95 % interval as a comment); the parameters it has no key for
    (:data:`NO_KEY`) are written as comments at the top, with the intervals, so
    that ``ballscrew program --machine`` reads the file and a reader sees all
    that was fitted.
    """
    import tomlkit

    doc = tomlkit.parse(machine.text)
    header = [f"Calibrated by ballscrew identify on {result.source}."]
    axes = doc["axes"]
    assert isinstance(axes, dict)
    for letter, fit in result.fits.items():
        entry = axes[letter]
        assert isinstance(entry, dict)
        case = tomlkit.parse(machine.axes[letter].case.text)
        entry["case"] = case
        mass = fit.parameters["moving_mass"]
        if mass.fitted and mass.identifiable:
            section = case.setdefault("axis", tomlkit.table())
            item = tomlkit.item(f"{mass.value:.5g} kg")
            item.comment(f"fitted by ballscrew identify: 95 % interval {mass.low:.4g} to "
                         f"{mass.high:.4g} kg")  # fmt: skip
            section["moving_mass"] = item
        for name, key in NO_KEY.items():
            p = fit.parameters[name]
            if p.fitted:
                unit = f" {p.unit}" if p.unit else ""
                spread = (f"95 %: {p.low:.4g} to {p.high:.4g}" if p.identifiable else
                          f"not identifiable with {', '.join(p.confounded_with)}")  # fmt: skip
                header.append(f"{letter}: {PARAMETERS[name][1]} = {p.value:.4g}{unit} "
                              f"({spread}); no key holds it yet ({key}): program leaves it "
                              "out")  # fmt: skip
    return "".join(f"# {line}\n" for line in header) + tomlkit.dumps(doc)
