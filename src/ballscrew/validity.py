"""Validity ranges of the models and correlations, and the warnings for leaving them.

One table (:data:`RANGES`) holds the ranges of the shared layers (film
formulas, Hertz fits, viscosity fit, the nut) with their sources, as fluids
keeps its correlations' ranges; a friction model declares the checks that
apply to it, and its own ranges, in its module (``checks=`` of
:func:`ballscrew.friction.register`). :func:`check` runs the checks common
to every model and the model's own; :func:`ballscrew.friction_torque` warns
once per quantity per call with a :class:`BallScrewValidityWarning` that
carries a :class:`ValidityIssue` (quantity, extreme value, range, source,
model), and records the issues in its result.

The checks cost O(n) for the operating points (minimum and maximum) plus a
handful of scalar evaluations: the dimensionless speed is largest at the
highest speed and lowest temperature, the load at the largest axial load, and
so on, so the extremes are evaluated at those corners only.
"""

from __future__ import annotations

import functools
import math
from collections.abc import Callable, Iterable
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from .contact import ellipticity_exact
from .ehl import dimensionless_load, dimensionless_speed
from .errors import BallScrewValidityWarning, FloatArray
from .geometry import BallScrew
from .kinematics import kinematics, rad_s_to_rpm
from .loads import LIFT_OFF_RATIO, ball_loads
from .lubricant import Lubricant

__all__ = [
    "RANGES",
    "BallScrewValidityWarning",
    "Check",
    "ValidityIssue",
    "ValidityRange",
    "check",
    "film_checks",
    "outside",
]


@dataclass(frozen=True)
class ValidityRange:
    """A published (or stated) range of one quantity for one model or correlation."""

    quantity: str
    low: float
    high: float
    applies_to: str
    source: str
    routine: str = ""
    """Why ordinary ball screws leave this range, if they do: such issues are
    told once, as a note, rather than warned about on every call."""

    def message(self, value: float) -> str:
        """Warning text for ``value`` outside the range."""
        return (
            f"{self.quantity} = {value:.4g} is outside {self.low:.4g} to {self.high:.4g}, the "
            f"range of {self.applies_to} ({self.source}); results there are extrapolated"
        )


@dataclass(frozen=True)
class ValidityIssue:
    """One quantity of a call outside its validity range (``str()`` is the warning text)."""

    quantity: str
    value: float
    low: float
    high: float
    applies_to: str
    source: str
    model: str = ""
    routine: str = ""

    @property
    def excess(self) -> float:
        """How far the value lies outside the range, relative to the range's upper end."""
        if not math.isfinite(self.value):
            return math.inf
        return max(self.low - self.value, self.value - self.high) / max(abs(self.high), 1e-300)

    def __str__(self) -> str:
        rng = ValidityRange(self.quantity, self.low, self.high, self.applies_to, self.source)
        text = rng.message(self.value)
        return f"{self.model}: {text}" if self.model else text

    def note(self) -> str:
        """The issue told as a note: the message and why ordinary screws get it."""
        return f"{self} (usual for ball screws: {self.routine})" if self.routine else str(self)


Check = Callable[
    [BallScrew, Lubricant, FloatArray, FloatArray, FloatArray, dict[str, Any]], list[ValidityIssue]
]
"""A model's validity check: ``f(screw, lubricant, speed, temperature, axial_load, params)``."""


_ROUTINE_FILM = (
    "ball screw contacts run faster and more heavily loaded, for their size, than the "
    "contacts the fits were made from, so every model extrapolates the film here"
)

RANGES: dict[str, ValidityRange] = {
    r.quantity: r
    for r in (
        ValidityRange(
            "ellipticity k (Hamrock-Dowson)",
            1.0,
            8.0,
            "the Hamrock-Dowson film formulas",
            "Hamrock & Dowson 1976-77: k from 1 to 8",
        ),
        ValidityRange(
            "dimensionless speed U",
            1.7e-12,
            1.7e-11,
            "the Hamrock-Dowson film formulas",
            "about the span of their numerical solutions",
            _ROUTINE_FILM,
        ),
        ValidityRange(
            "dimensionless load W",
            3.7e-7,
            1.1e-5,
            "the Hamrock-Dowson film formulas",
            "about the span of their numerical solutions",
            _ROUTINE_FILM,
        ),
        ValidityRange(
            "radius ratio Ry/Rx (Houpert fits)",
            1.0,
            10.0,
            "Houpert's Hertz fits",
            "error under 2 % there, 13 % at a ratio of 72; see ballscrew.contact",
        ),
        ValidityRange(
            "speed factor d_m*n [mm*rpm]",
            0.0,
            160_000.0,
            "ball screws in general",
            "catalogue limit of high-speed ball screws (standard ones: 70 000 to 100 000)",
        ),
        ValidityRange(
            "temperature [degC]",
            0.0,
            150.0,
            "the viscosity-temperature fit",
            "ASTM D341 fit through 40 and 100 °C; below 0 °C waxing and pour points intervene",
        ),
        ValidityRange(
            "axial load / preload",
            0.0,
            LIFT_OFF_RATIO,
            "a preloaded nut",
            "above 2^1.5 the relieved half-nut lifts off and the nut has backlash",
        ),
    )
}
"""All validity ranges, by quantity."""


def outside(r: ValidityRange | str, values: Iterable[float]) -> list[ValidityIssue]:
    """The worst of ``values`` outside range ``r`` (a range or a quantity of RANGES), if any."""
    if isinstance(r, str):
        r = RANGES[r]
    vals = [v for v in values if math.isfinite(v)]
    worst = [v for v in vals if v < r.low * (1 - 1e-12) or v > r.high * (1 + 1e-12)]
    if not worst:
        return []
    value = max(worst, key=lambda v: max(r.low - v, v - r.high) / max(abs(r.high), 1e-300))
    return [ValidityIssue(r.quantity, value, r.low, r.high, r.applies_to, r.source, "", r.routine)]


def check(
    screw: BallScrew,
    lubricant: Lubricant,
    speed: FloatArray,
    temperature: FloatArray,
    axial_load: FloatArray,
    model: str,
    parameters: dict[str, Any],
    checks: Iterable[Check] = (),
) -> list[ValidityIssue]:
    """Every quantity of a call that leaves its validity range, worst value each.

    Parameters
    ----------
    screw, lubricant, speed, temperature, axial_load
        The call's inputs (speed [rad/s], temperature [°C], axial load [N]).
    model : str
        The friction model's name (recorded in each issue).
    parameters : dict
        The model's parameters as used.
    checks : iterable of callables
        The model's own checks (its ``ModelSpec.checks``), run after the
        common ones (speed factor, preload lift-off).
    """
    issues: list[ValidityIssue] = []
    if speed.size == 0:
        return issues
    n_max = float(rad_s_to_rpm(np.max(np.abs(speed))))
    issues += outside("speed factor d_m*n [mm*rpm]", [screw.pitch_diameter * 1e3 * n_max])
    if screw.nut != "single" and screw.preload > 0.0:
        issues += outside(
            "axial load / preload", [float(np.max(np.abs(axial_load))) / screw.preload]
        )
    for model_check in checks:
        issues += model_check(screw, lubricant, speed, temperature, axial_load, parameters)
    return [replace(issue, model=model) for issue in issues]


def lubricant_checks(
    screw: BallScrew,
    lubricant: Lubricant,
    speed: FloatArray,
    temperature: FloatArray,
    axial_load: FloatArray,
    parameters: dict[str, Any],
) -> list[ValidityIssue]:
    """The viscosity-temperature fit's range, for models that use the lubricant."""
    return outside("temperature [degC]", [float(np.min(temperature)), float(np.max(temperature))])


def film_checks(
    screw: BallScrew,
    lubricant: Lubricant,
    speed: FloatArray,
    temperature: FloatArray,
    axial_load: FloatArray,
    parameters: dict[str, Any],
) -> list[ValidityIssue]:
    """Ranges of the EHL film formulas and of the Hertz fits, for models built on them.

    Includes :func:`lubricant_checks`. The checks depend on the operating
    range only through its extremes, so their result is cached on those
    (a loop over single points repeats the same extremes).
    """
    w_abs = np.abs(speed)
    moving = w_abs[w_abs > 0.0]
    return list(
        _film_issues(
            screw,
            lubricant,
            parameters.get("hertz_method") == "houpert",
            float(np.min(temperature)),
            float(np.max(temperature)),
            float(np.min(moving)) if moving.size else 0.0,
            float(np.max(moving)) if moving.size else 0.0,
            float(np.max(np.abs(axial_load))),
        )
    )


@functools.lru_cache(maxsize=256)
def _film_issues(
    screw: BallScrew,
    lubricant: Lubricant,
    houpert: bool,
    t_lo: float,
    t_hi: float,
    w_min: float,
    w_max: float,
    fa_max: float,
) -> tuple[ValidityIssue, ...]:
    """Film and Hertz-fit issues at the corners of the operating range.

    ``w_min``, ``w_max``: smallest and largest non-zero speed magnitude
    [rad/s] (0 when nothing moves); ``fa_max``: largest |axial load| [N].
    """
    issues = outside("temperature [degC]", [t_lo, t_hi])
    ratios = [screw.ry_screw / screw.rx_screw, screw.ry_nut / screw.rx_nut]
    ratios = [max(r, 1.0 / r) for r in ratios]
    issues += outside(
        "ellipticity k (Hamrock-Dowson)", [float(ellipticity_exact(r)) for r in ratios]
    )
    if houpert:
        issues += outside("radius ratio Ry/Rx (Houpert fits)", ratios)
    eta_hi = float(lubricant.dynamic_viscosity(t_lo))
    eta_lo = float(lubricant.dynamic_viscosity(t_hi))
    ep = screw.reduced_modulus
    radii = (screw.rx_screw, screw.rx_nut)
    u_values: list[float] = []
    if w_max > 0.0:
        # The extreme U: the thickest oil at the fastest speed, the thinnest at the slowest.
        u = kinematics(screw, np.array([w_max, w_min])).entrainment_speed
        u_values = [
            float(v)
            for rx in radii
            for v in dimensionless_speed(np.array([eta_hi, eta_lo]), u, ep, rx)
        ]
    loads = ball_loads(screw, np.array([0.0, fa_max]))
    q = np.concatenate([loads.normal_load_1, loads.normal_load_2])
    q = q[q > 0.0]
    extremes = (q.min(), q.max()) if q.size else ()
    w_values = [float(dimensionless_load(v, ep, rx)) for v in extremes for rx in radii]
    issues += outside("dimensionless speed U", u_values)
    issues += outside("dimensionless load W", w_values)
    return tuple(issues)
