"""Validity ranges of the models and correlations, and the warnings for leaving them.

One table (:data:`RANGES`) holds every range with its source, as fluids keeps
its correlations' ranges; :func:`check` finds the quantities of a call that
leave them and :func:`friction_torque` warns once per quantity per call with
a :class:`BallScrewValidityWarning` naming the quantity, its extreme value and
the range, and records the messages in its result.

The checks cost O(n) for the operating points (minimum and maximum) plus a
handful of scalar evaluations: the dimensionless speed is largest at the
highest speed and lowest temperature, the load at the largest axial load, and
so on, so the extremes are evaluated at those corners only.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass
from typing import Any

import numpy as np

from .contact import ellipticity_exact
from .errors import BallScrewValidityWarning, FloatArray
from .geometry import BallScrew
from .loads import LIFT_OFF_RATIO, ball_loads
from .lubricant import Lubricant

__all__ = ["RANGES", "BallScrewValidityWarning", "ValidityRange", "check"]


@dataclass(frozen=True)
class ValidityRange:
    """A published (or stated) range of one quantity for one model or correlation."""

    quantity: str
    low: float
    high: float
    applies_to: str
    source: str

    def message(self, value: float) -> str:
        """Warning text for ``value`` outside the range."""
        return (
            f"{self.quantity} = {value:.4g} is outside {self.low:.4g} to {self.high:.4g}, the "
            f"range of {self.applies_to} ({self.source}); results there are extrapolated"
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
        ),
        ValidityRange(
            "dimensionless load W",
            3.7e-7,
            1.1e-5,
            "the Hamrock-Dowson film formulas",
            "about the span of their numerical solutions",
        ),
        ValidityRange(
            "radius ratio Ry/Rx (Houpert fits)",
            1.0,
            10.0,
            "Houpert's Hertz fits",
            "error under 2 % there, 13 % at 72 (ballscrew.contact)",
        ),
        ValidityRange(
            "spin parameter E (Olaru)",
            0.0,
            1.0,
            "Houpert's f_c, f_p fits in Olaru's model",
            "the fits' interval; beyond it their end values are used",
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


def _outside(name: str, values: Iterable[float]) -> list[str]:
    r = RANGES[name]
    vals = [v for v in values if math.isfinite(v)]
    worst = [v for v in vals if v < r.low * (1 - 1e-12) or v > r.high * (1 + 1e-12)]
    if not worst:
        return []
    value = max(worst, key=lambda v: max(r.low - v, v - r.high) / max(abs(r.high), 1e-300))
    return [r.message(value)]


def check(
    screw: BallScrew,
    lubricant: Lubricant,
    speed: FloatArray,
    temperature: FloatArray,
    axial_load: FloatArray,
    model: str,
    parameters: dict[str, Any],
) -> list[str]:
    """Messages for every quantity of a call that leaves its validity range.

    Parameters
    ----------
    screw, lubricant, speed, temperature, axial_load
        The call's inputs (speed [rad/s], temperature [°C], axial load [N]).
    model : str
        The friction model (decides which ranges apply).
    parameters : dict
        The model's parameters as used.
    """
    messages: list[str] = []
    if speed.size == 0:
        return messages
    w_abs = np.abs(speed)
    n_max = float(np.max(w_abs)) * 60.0 / (2.0 * math.pi)
    messages += _outside("speed factor d_m*n [mm*rpm]", [screw.pitch_diameter * 1e3 * n_max])
    if model != "catalog":
        messages += _outside(
            "temperature [degC]", [float(np.min(temperature)), float(np.max(temperature))]
        )
    if screw.nut != "single" and screw.preload > 0.0:
        messages += _outside(
            "axial load / preload", [float(np.max(np.abs(axial_load))) / screw.preload]
        )
    if model in ("catalog", "viscoelastic"):
        return messages
    ratios = [screw.ry_screw / screw.rx_screw, screw.ry_nut / screw.rx_nut]
    ratios = [max(r, 1.0 / r) for r in ratios]
    messages += _outside(
        "ellipticity k (Hamrock-Dowson)", [float(ellipticity_exact(r)) for r in ratios]
    )
    if parameters.get("hertz_method") == "houpert":
        messages += _outside("radius ratio Ry/Rx (Houpert fits)", ratios)
    messages += _film_groups(screw, lubricant, speed, temperature, axial_load)
    if model == "olaru":
        messages += _olaru_spin(screw, axial_load, parameters)
    return messages


def _film_groups(
    screw: BallScrew,
    lubricant: Lubricant,
    speed: FloatArray,
    temperature: FloatArray,
    axial_load: FloatArray,
) -> list[str]:
    """Extremes of U and W at the corners of the operating range."""
    w_abs = np.abs(speed)
    t_lo, t_hi = float(np.min(temperature)), float(np.max(temperature))
    eta_hi = float(lubricant.dynamic_viscosity(t_lo))
    eta_lo = float(lubricant.dynamic_viscosity(t_hi))
    u_scale = screw.pitch_diameter * (1.0 - screw.gamma**2) / 4.0
    ep = screw.reduced_modulus
    u_values: list[float] = []
    moving = w_abs[w_abs > 0.0]
    for rx in (screw.rx_screw, screw.rx_nut):
        if moving.size:
            u_values.append(eta_hi * float(np.max(moving)) * u_scale / (ep * rx))
            u_values.append(eta_lo * float(np.min(moving)) * u_scale / (ep * rx))
    loads = ball_loads(screw, np.array([0.0, float(np.max(np.abs(axial_load)))]))
    q = np.concatenate([loads.normal_load_1, loads.normal_load_2])
    q = q[q > 0.0]
    w_values = [
        float(v) / (ep * rx**2)
        for v in (q.min(), q.max())
        if q.size
        for rx in (screw.rx_screw, screw.rx_nut)
    ]
    return _outside("dimensionless speed U", u_values) + _outside("dimensionless load W", w_values)


def _olaru_spin(screw: BallScrew, axial_load: FloatArray, parameters: dict[str, Any]) -> list[str]:
    """Houpert's spin parameter E of Olaru's model at the extreme loads."""
    from .contact import hertz

    kappa = float(parameters.get("kappa", 0.05))
    ra = 0.5 * screw.ball_diameter * (1.0 + kappa) / (1.0 + 0.5 * kappa)
    spin = screw.ball_diameter * math.sin(screw.contact_angle) / screw.pitch_diameter
    loads = ball_loads(screw, np.array([0.0, float(np.max(np.abs(axial_load)))]))
    q = np.concatenate([loads.normal_load_1, loads.normal_load_2])
    q = q[q > 0.0]
    if not q.size:
        return []
    method = str(parameters.get("hertz_method", "houpert"))
    values: list[float] = []
    for rx, ry in ((screw.rx_screw, screw.ry_screw), (screw.rx_nut, screw.ry_nut)):
        a = hertz(q, rx, ry, screw.reduced_modulus, method=method).a
        values += [float(v) for v in 2.0 * ra / a * spin]
    return _outside("spin parameter E (Olaru)", values)
