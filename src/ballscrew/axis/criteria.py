r"""The axis check's criteria as a table: a stable key each, and one function per drawn one.

Every row of ``ballscrew check`` (:mod:`ballscrew.axis.check`) carries a key of :data:`KEYS`
(``life``, ``peak_torque``, ...): ``select``, ``program``'s verdict lines, the
reports and the web page find a row by it, never by its label, which carries
the nut's state and the accuracy grade.

The criteria with an uncertain input (:data:`CRITERIA`) are each one record,
:class:`Rule`: key, label, unit, the side of the limit that passes, where the
limit comes from, the formula's source, and **one vectorised function** of the
cycle's inputs (:class:`Inputs`) and the factors on them, one row per draw
(:class:`~.uncertainty.Draws`). The nominal row calls it with a draw of ones
(:func:`nominal`); the Monte Carlo calls the same function with the draws
(:func:`drawn`), so the two cannot drift apart:

* ``life``: L10 hours of the nut's halves in series (ISO 3408-5 cl. 7), the
  force's mass and process parts, the preload and :math:`C_a` scaled;
* ``static_safety``: :math:`C_{0a}/F_{max}` on the most loaded half;
* ``lift_off``: the peak force against :math:`2^{1.5}F_{pr}`, the limit
  scaled with the preload;
* ``buckling`` and ``root_section``: the peak force [kN];
* ``thermal_error``: :math:`\alpha\,\Delta T\cdot 300` mm with the rise scaled
  by the friction factor (the heat is the friction's);
* ``inertia_ratio``: the load inertia with the moving mass scaled;
* ``peak_torque`` and ``rms_torque``: the motor torque with its mass, process
  and friction parts scaled.
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from ..design.sizing import (
    combined_life,
    cubic_mean_load,
    nominal_life,
    preloaded_loads,
    reflected_inertia,
    static_safety,
    thermal_elongation,
)
from ..errors import FloatArray
from .uncertainty import Draws

__all__ = [
    "CRITERIA",
    "KEYS",
    "Inputs",
    "Rule",
    "Sample",
    "drawn",
    "life_hours",
    "life_utilisation",
    "nominal",
    "nut_halves",
    "ones",
]

KEYS: dict[str, str] = {
    "life": "fatigue life L10",
    "static_safety": "static safety C0a/F_max",
    "buckling": "buckling load",
    "root_section": "axial load, root section",
    "critical_speed": "speed / critical speed",
    "dn": "d*n",
    "lift_off": "lift-off F_max / (2^1.5 F_pr)",
    "stiffness": "axis stiffness",
    "lost_motion": "lost motion at reversal",
    "eigenfrequency": "axial eigenfrequency",
    "thermal_error": "thermal lead error per 300 mm",
    "thermal_growth": "thermal growth over the stroke",
    "motor": "motor",
    "inertia_ratio": "inertia ratio J_load/J_motor",
    "peak_torque": "peak torque",
    "rms_torque": "RMS torque / rated torque",
    "motor_speed": "motor speed",
    "acceleration": "acceleration the peak torque allows",
    "travel": "travel used",
}
"""Every row's stable key and the start of its label (``program`` adds ``travel``)."""


@dataclass(frozen=True)
class Inputs:
    """What the drawn criteria are computed from: the cycle's samples and the axis's figures.

    The force samples that share their mass and process parts (a cruise, a dwell,
    a constant acceleration) are taken once with their turns added, the torque
    samples likewise with their time weights (:func:`.check._distinct_samples`).
    """

    mass_force: FloatArray
    """The axial force's part from the moving mass (inertia, weight) at each force sample [N]."""
    process_force: FloatArray
    """The process force at each force sample [N]."""
    turns: FloatArray
    """The screw turns made under each force sample [-]."""
    motor_torque: FloatArray
    """The motor torque at each torque sample [N·m]."""
    torque_mass_force: FloatArray
    """The mass part of the axial force at each torque sample [N]."""
    torque_process_force: FloatArray
    """The process force at each torque sample [N]."""
    motor_friction: FloatArray
    """The screw's friction torque at the motor, signed with the speed [N·m]."""
    weights: FloatArray
    """The time weights of the torque samples [s] (their sum is the run's duration)."""
    duration: float
    """The run's duration [s]."""
    rms_torque: float
    """The cycle's RMS motor torque [N·m] (:mod:`ballscrew.axis.energy`'s, over every sample)."""
    lead: float
    """The screw's lead [m]."""
    gear_ratio: float
    """Motor turns per screw turn [-]."""
    preload: float
    """The nut's preload [N] (0 for a single nut)."""
    preloaded: bool
    """Two halves against each other (a double nut, offset or oversized balls)."""
    dynamic_rating: float | None
    """C_a [N], None when unknown."""
    static_rating: float | None
    """C_0a [N], None when unknown."""
    load_factor: float
    """The life's load factor f_w [-]."""
    reliability: float
    """The life's reliability [-] (0.9: L10)."""
    temperature_rise: float
    """The rise the heat balance reaches over the run time [K]."""
    pretension: float
    """The rise a pre-tension absorbs [K]."""
    moving_mass: float
    """[kg]."""
    screw_inertia: float
    """The screw's and the coupling's inertia [kg·m²]."""
    coupling_inertia: float
    """[kg·m²]."""
    motor_inertia: float
    """The rotor's inertia [kg·m²] (0 without a motor)."""


class Sample:
    """The inputs under one block of draws, with what several criteria share computed once."""

    def __init__(self, inputs: Inputs, factors: Draws) -> None:
        self.inputs, self.factors = inputs, factors

    @cached_property
    def force(self) -> FloatArray:
        """The nut's axial force of each draw at each force sample [N], (draws, samples)."""
        f, x = self.factors, self.inputs
        return np.asarray(
            f.mass[:, None] * x.mass_force + f.force[:, None] * x.process_force, dtype=float
        )

    @cached_property
    def peak(self) -> FloatArray:
        """The largest absolute axial force of each draw [N]."""
        return np.asarray(np.max(np.abs(self.force), axis=1), dtype=float)

    @cached_property
    def preload(self) -> FloatArray:
        """The preload of each draw [N]."""
        return np.asarray(self.inputs.preload * self.factors.preload, dtype=float)

    @cached_property
    def torque(self) -> FloatArray:
        r"""The motor torque of each draw at each torque sample [N·m], (draws, samples).

        :math:`T + ((k_m-1) F_m + (k_f-1) F_p)\,l/(2\pi i) + (k_\mu - 1) T_\mu`: the
        mass's and the process force's parts through the screw, the friction's at the
        motor (the friction factor scales the heat and the friction torque, not the
        preload's share of the friction: it is taken as a whole here).
        """
        f, x = self.factors, self.inputs
        km, kf, kfr = f.mass[:, None], f.force[:, None], f.friction[:, None]
        return np.asarray(
            x.motor_torque
            + ((km - 1.0) * x.torque_mass_force + (kf - 1.0) * x.torque_process_force)
            * x.lead / (2.0 * math.pi * x.gear_ratio)
            + (kfr - 1.0) * x.motor_friction,
            dtype=float,
        )  # fmt: skip


def nut_halves(
    force: FloatArray, preload: FloatArray | float, *, preloaded: bool
) -> tuple[FloatArray, FloatArray]:
    """The loads of the nut's two halves (a single nut's two flanks) under ``force`` [N].

    A preloaded nut's halves carry :func:`~ballscrew.design.sizing.preloaded_loads`,
    the first the more loaded one for a positive force; a single nut's flanks each
    carry one sign of the force.
    """
    f = np.asarray(force, dtype=float)
    if not preloaded:
        return np.maximum(f, 0.0), np.maximum(-f, 0.0)
    loaded, relieved = preloaded_loads(f, preload)
    return np.where(f >= 0.0, loaded, relieved), np.where(f >= 0.0, relieved, loaded)


def life_hours(
    force: FloatArray, preload: FloatArray, rating: FloatArray, turns: FloatArray,
    speed_rpm: float, *, preloaded: bool, load_factor: float, reliability: float,
) -> FloatArray:  # fmt: skip
    r"""L10 life of a cycle repeated, one per draw [h] (ISO 3408-5 cl. 7).

    ``force`` [N] is (draws, samples), the nut's axial force at each sample of
    the cycle, ``turns`` (samples,) the screw turns made under each, ``preload``
    [N] and ``rating`` [N] (draws,) the preload and :math:`C_a` of each draw.
    The halves' loads are :func:`nut_halves`, each half's cubic mean load gives
    :math:`L = a_1 (C_a/(f_w F_m))^3 10^6` revolutions, the halves in series;
    hours at ``speed_rpm``, the cycle's mean speed.
    """
    pre = np.asarray(preload, dtype=float)[:, None]
    h1, h2 = nut_halves(force, pre, preloaded=preloaded)
    revs = combined_life(nominal_life(rating, cubic_mean_load(h1, turns), reliability,
                                      load_factor),
                         nominal_life(rating, cubic_mean_load(h2, turns), reliability,
                                      load_factor))  # fmt: skip
    return np.asarray(np.asarray(revs, dtype=float) / (60.0 * speed_rpm), dtype=float)


def life_utilisation(
    force: FloatArray, preload: FloatArray, rating: FloatArray, turns: FloatArray,
    required_hours: float, speed_rpm: float, *, preloaded: bool, load_factor: float,
    reliability: float = 0.9,
) -> FloatArray:  # fmt: skip
    """Required over computed L10 life of a cycle, one per draw [-] (:func:`life_hours`)."""
    hours = life_hours(force, preload, rating, turns, speed_rpm, preloaded=preloaded,
                       load_factor=load_factor, reliability=reliability)  # fmt: skip
    return np.asarray(required_hours / hours, dtype=float)


def _life(s: Sample) -> FloatArray:
    """L10 hours of each draw: the forces, the preload and C_a scaled."""
    x = s.inputs
    assert x.dynamic_rating is not None  # the row is NOT CHECKED without it
    rpm = float(np.sum(x.turns)) / x.duration * 60.0
    return life_hours(s.force, s.preload, x.dynamic_rating * s.factors.ratings, x.turns, rpm,
                      preloaded=x.preloaded, load_factor=x.load_factor,
                      reliability=x.reliability)  # fmt: skip


def _static_safety(s: Sample) -> FloatArray:
    """C_0a over the most loaded half's peak load, the rating and the forces scaled."""
    x = s.inputs
    assert x.static_rating is not None  # the row is NOT CHECKED without it
    # A single nut has no preload; a preloaded nut of preload 0 draws 0 too.
    half = preloaded_loads(s.peak, s.preload if x.preloaded else 0.0)[0]
    return static_safety(x.static_rating * s.factors.ratings, half)


def _peak(s: Sample) -> FloatArray:
    """The peak axial force [N] (lift-off)."""
    return s.peak


def _peak_kN(s: Sample) -> FloatArray:
    """The peak axial force [kN] (buckling and the root section's yield)."""
    return np.asarray(s.peak / 1e3, dtype=float)


def _thermal_error(s: Sample) -> FloatArray:
    """The lead error per 300 mm [µm], the temperature rise scaled by the friction factor."""
    x = s.inputs
    rise = np.maximum(x.temperature_rise * s.factors.friction - x.pretension, 0.0)
    return np.asarray(thermal_elongation(rise, 0.3) * 1e6, dtype=float)


def _inertia_ratio(s: Sample) -> FloatArray:
    """J_load / J_motor, the moving mass scaled."""
    x = s.inputs
    linear = reflected_inertia(x.moving_mass, x.lead) * s.factors.mass
    j = (x.screw_inertia + x.coupling_inertia + linear) / x.gear_ratio**2
    return np.asarray(j / x.motor_inertia, dtype=float)


def _peak_torque(s: Sample) -> FloatArray:
    """The largest |motor torque| of each draw [N·m]."""
    return np.asarray(np.max(np.abs(s.torque), axis=1), dtype=float)


def _rms_torque(s: Sample) -> FloatArray:
    r"""The RMS motor torque of each draw over the run [N·m].

    The cycle's RMS torque scaled by :math:`\sqrt{\sum w T^2 / \sum w T_0^2}`, the
    draw's mean square over the nominal one on the distinct samples: at a draw of
    ones the ratio is exactly 1 and the row is the cycle's own figure.
    """
    x = s.inputs
    nominal_square = np.sum(x.weights * x.motor_torque**2)
    if nominal_square <= 0.0:  # no torque at all: scaling has nothing to scale
        return np.asarray(np.sqrt(np.sum(x.weights * s.torque**2, axis=1) / x.duration),
                          dtype=float)  # fmt: skip
    ratio = np.sum(x.weights * s.torque**2, axis=1) / nominal_square
    return np.asarray(x.rms_torque * np.sqrt(ratio), dtype=float)


@dataclass(frozen=True)
class Rule:
    """One drawn criterion: what it is, where its limit comes from, and its one function."""

    key: str
    label: str
    unit: str
    at_least: bool
    """The value passes above the limit (a life, a safety factor); else below it."""
    limit: str
    """Where the limit comes from."""
    source: str
    value: Callable[[Sample], FloatArray]
    """The row's value of each draw, in ``unit``."""
    limit_factor: str | None = None
    """The factor of :class:`~.uncertainty.Draws` that scales the limit too (lift-off's
    preload), None when the limit is fixed."""

    def utilisation(self, value: FloatArray, limit: FloatArray | float) -> FloatArray:
        """Value over limit (limit over value for :attr:`at_least`): above 1 fails."""
        v = np.asarray(value, dtype=float)
        if not self.at_least:
            return np.asarray(v / limit, dtype=float)
        with np.errstate(divide="ignore"):  # a value of 0 (no life, no safety): infinity
            return np.asarray(limit / v, dtype=float)

    def limits(self, limit: float, factors: Draws) -> FloatArray:
        """The limit of each draw: ``limit`` scaled by :attr:`limit_factor`, else ``limit``."""
        if self.limit_factor is None:
            return np.full(np.size(factors.mass), float(limit))
        return np.asarray(limit * getattr(factors, self.limit_factor), dtype=float)


CRITERIA: dict[str, Rule] = {
    r.key: r
    for r in (
        Rule("life", KEYS["life"], "h", True, "check.required_life (20000 h by default)",
             "ISO 3408-5:2006 cl. 7 with the makers' load factor", _life),
        Rule("static_safety", KEYS["static_safety"], "-", True, "check.static_safety",
             "ISO 3408-5:2006 cl. 6; THK A-703 Table 18", _static_safety),
        Rule("lift_off", KEYS["lift_off"], "N", False, "2^1.5 times the preload",
             "ISO 3408-5:2006, the preloaded halves", _peak, "preload"),
        Rule("buckling", KEYS["buckling"], "kN", False, "Euler on the root diameter x 0.5",
             "THK General Catalog A15-30, eq. 5", _peak_kN),
        Rule("root_section", KEYS["root_section"], "kN", False, "147 MPa on the root section",
             "THK General Catalog A15-30, eq. 6", _peak_kN),
        Rule("thermal_error", KEYS["thermal_error"], "um", False,
             "v300p of the accuracy grade (ISO 3408-3)", "alpha dT 300 mm", _thermal_error),
        Rule("inertia_ratio", KEYS["inertia_ratio"], "-", False, "10, a servo sizing rule",
             "J_load = [J_s + J_c + m (l/2 pi)^2] / i^2", _inertia_ratio),
        Rule("peak_torque", KEYS["peak_torque"], "N*m", False, "motor.peak_torque",
             "the cycle's torques against the motor's ratings", _peak_torque),
        Rule("rms_torque", KEYS["rms_torque"], "N*m", False, "motor.rated_torque",
             "the cycle's torques against the motor's ratings", _rms_torque),
    )
}  # fmt: skip
"""The criteria with an uncertain input, by key."""


def ones(n: int = 1) -> Draws:
    """Factors of one on every input: the nominal draw."""
    one = np.ones(n)
    return Draws(mass=one, force=one, preload=one, ratings=one, friction=one)


def nominal(key: str, inputs: Inputs) -> float:
    """The nominal value of criterion ``key``: its function at a draw of ones."""
    return float(CRITERIA[key].value(Sample(inputs, ones()))[0])


def drawn(key: str, sample: Sample, limit: float) -> FloatArray:
    """The utilisation of criterion ``key`` at each draw of ``sample``, its nominal limit given."""
    rule = CRITERIA[key]
    return rule.utilisation(rule.value(sample), rule.limits(limit, sample.factors))
