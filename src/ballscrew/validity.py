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

A range may be one-sided (an infinite bound: a lubricant's pour point and
flash point, :func:`lubricant_limits`, checked for every model) or a
*statement*, a range with no bounds (NaN): a limitation the results carry
whatever the inputs, told as a note, such as what the models leave out of a
grease (:func:`grease_note`).
"""

from __future__ import annotations

import functools
import math
from collections.abc import Iterable
from dataclasses import dataclass, replace
from typing import Any, Protocol

import numpy as np

from .contact import ellipticity_exact
from .ehl import dimensionless_load, dimensionless_speed
from .errors import BallScrewValidityWarning, FloatArray
from .geometry import BallScrew, ScrewArray, ScrewGeometry
from .kinematics import kinematics, rad_s_to_rpm
from .loads import LIFT_OFF_RATIO, ball_loads
from .lubricant import Lubricant

__all__ = [
    "GREASE_SOURCE",
    "RANGES",
    "BallScrewValidityWarning",
    "Check",
    "ValidityCheck",
    "ValidityIssue",
    "ValidityRange",
    "check",
    "film_checks",
    "grease_note",
    "lubricant_checks",
    "lubricant_limits",
    "outside",
    "statement",
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

    @property
    def is_statement(self) -> bool:
        """A range with no bounds (both NaN): a limitation stated whatever the inputs."""
        return math.isnan(self.low) and math.isnan(self.high)

    def message(self, value: float) -> str:
        """Warning text for ``value`` outside the range (a statement: the statement)."""
        if self.is_statement:
            told = f"{self.quantity} = {value:.4g}" if math.isfinite(value) else self.quantity
            return f"{told}: {self.applies_to} ({self.source})"
        # A one-sided range is a physical limit: beyond it the results do not hold at all.
        ending = "results there do not hold"
        if math.isinf(self.high) and not math.isinf(self.low):
            where = f"below {self.low:.4g}, the lower limit of"
        elif math.isinf(self.low) and not math.isinf(self.high):
            where = f"above {self.high:.4g}, the upper limit of"
        else:
            where = f"outside {self.low:.4g} to {self.high:.4g}, the range of"
            ending = "results there are extrapolated"
        return (
            f"{self.quantity} = {value:.4g} is {where} {self.applies_to} ({self.source}); {ending}"
        )


def _scale(low: float, high: float) -> float:
    """The size a distance outside ``[low, high]`` is measured against (the finite bound)."""
    bound = high if math.isfinite(high) else low if math.isfinite(low) else 1.0
    return max(abs(bound), 1e-300)


@dataclass(frozen=True)
class ValidityIssue:
    """One quantity of a call outside its validity range, or a statement (``str()``: the text)."""

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
        """How far the value lies outside the range, relative to its upper end (else its lower).

        Infinite for a statement (no range) and for a non-finite value.
        """
        if not math.isfinite(self.value) or math.isnan(self.low) or math.isnan(self.high):
            return math.inf
        return max(self.low - self.value, self.value - self.high) / _scale(self.low, self.high)

    def __str__(self) -> str:
        rng = ValidityRange(self.quantity, self.low, self.high, self.applies_to, self.source)
        text = rng.message(self.value)
        return f"{self.model}: {text}" if self.model else text

    def note(self) -> str:
        """The issue told as a note: the message and why ordinary screws get it."""
        return f"{self} (usual for ball screws: {self.routine})" if self.routine else str(self)

    def short(self) -> str:
        """One line for a routine range: the model, the quantity, its value and the range.

        The source of the range and why ordinary screws leave it are in :meth:`note`,
        which the line points to (a :class:`~ballscrew.errors.BallScrewValidityWarning`
        holds the issue as ``issue``). A statement, or an issue that is not
        routine, is told in full (:meth:`note`): it is rare and its source matters.

        >>> issue = ValidityIssue("dimensionless load W", 2e-5, 3.7e-7, 1.1e-5,
        ...                       "the film formulas", "their fits", "complete", "why")
        >>> issue.short()
        'complete: dimensionless load W = 2e-05 is outside 3.7e-07 to 1.1e-05 (the film formulas): extrapolated, usual for ball screws (.issue.note() says why)'
        """  # noqa: E501 - the doctest's one line is the point
        if not self.routine or math.isnan(self.low) or math.isnan(self.high):
            return self.note()
        head = f"{self.model}: " if self.model else ""
        return (
            f"{head}{self.quantity} = {self.value:.4g} is outside {self.low:.4g} to "
            f"{self.high:.4g} ({self.applies_to}): extrapolated, usual for ball screws "
            "(.issue.note() says why)"
        )


class ValidityCheck(Protocol):
    """A model's validity check, the one signature every check has.

    Called as ``check(screw, lubricant, speed, temperature, axial_load, parameters)``
    with the call's inputs (speed [rad/s], temperature [°C], axial load [N], broadcast
    float arrays) and the model's parameters as used; returns the issues it finds,
    worst value each (:func:`outside`). A model names its checks in ``checks=`` of
    :func:`ballscrew.friction.register`; :func:`check` runs them.
    """

    def __call__(
        self, screw: BallScrew, lubricant: Lubricant, speed: FloatArray, temperature: FloatArray,
        axial_load: FloatArray, parameters: dict[str, Any], /,
    ) -> list[ValidityIssue]:  # fmt: skip
        """The issues of one call: those its inputs and state leave a range."""


Check = ValidityCheck
"""The former name of :class:`ValidityCheck`."""


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
            "above 2^1.5 the relieved half-nut (a 4-point nut's relieved contacts) lifts off "
            "and the nut has backlash",
        ),
    )
}
"""All validity ranges, by quantity."""


def outside(r: ValidityRange | str, values: Iterable[float] | FloatArray) -> list[ValidityIssue]:
    """The worst of ``values`` outside range ``r`` (a range or a quantity of RANGES), if any.

    ``values`` may be an array (many screws' corners at once, worked out by numpy) or
    any iterable of numbers; the worst is the first of the largest relative excess.
    """
    if isinstance(r, str):
        r = RANGES[r]
    # A relative tolerance on each bound (of either sign; an infinite bound stays infinite).
    low, high = r.low - 1e-12 * abs(r.low), r.high + 1e-12 * abs(r.high)
    if not isinstance(values, np.ndarray):
        values = [float(v) for v in values]
        if all(low <= v <= high or not math.isfinite(v) for v in values):
            return []  # a few numbers inside (the usual case): no arrays
    vals = np.asarray(values, dtype=float)
    vals = vals.reshape(-1)
    vals = vals[np.isfinite(vals)]
    worst = vals[(vals < low) | (vals > high)]
    if not worst.size:
        return []
    excess = np.maximum(r.low - worst, worst - r.high) / _scale(r.low, r.high)
    value = float(worst[int(np.argmax(excess))])
    return [ValidityIssue(r.quantity, value, r.low, r.high, r.applies_to, r.source, "", r.routine)]


def statement(
    quantity: str, text: str, source: str, *, value: float = math.nan, routine: str = ""
) -> ValidityIssue:
    """A limitation of the results told as an issue with no range (see the module docstring).

    ``str()`` of the issue is ``"quantity[ = value]: text (source)"``; with
    ``routine`` it is told once per session as a note, like the routine ranges.
    """
    return ValidityIssue(quantity, value, math.nan, math.nan, text, source, "", routine)


def lubricant_limits(lubricant: Lubricant) -> list[ValidityRange]:
    """The temperatures the lubricant stays a lubricant in, from its pour and flash points.

    Below the (base) oil's pour point the oil no longer flows to the contacts;
    above its flash point it gives off flammable vapour and is no lubricant
    at all. Each given point is a one-sided range naming the lubricant's
    field, its value and where the lubricant's data come from; none when the
    data sheet gives neither.
    """
    source = lubricant.source or "source not given"
    limits: list[ValidityRange] = []
    if lubricant.pour_point is not None:
        limits.append(
            ValidityRange(
                "temperature [degC] (pour point)",
                lubricant.pour_point,
                math.inf,
                f"{lubricant.name}: pour_point = {lubricant.pour_point:g} degC, below which the "
                "oil does not flow to the contacts",
                source,
            )
        )
    if lubricant.flash_point is not None:
        limits.append(
            ValidityRange(
                "temperature [degC] (flash point)",
                -math.inf,
                lubricant.flash_point,
                f"{lubricant.name}: flash_point = {lubricant.flash_point:g} degC, above which the "
                "oil gives off flammable vapour and is no longer a lubricant",
                source,
            )
        )
    return limits


GREASE_SOURCE = (
    "Lugt, Tribol. Trans. 52 (2009) 470, doi:10.1080/10402000802687940; fully flooded, a grease "
    "and its bled oil form similar films at moderate to high speed: Lubricants 3 (2015) 197, "
    "doi:10.3390/lubricants3020197"
)
"""Where the base-oil description of a grease comes from (the grease note's source)."""


def grease_note(lubricant: Lubricant) -> list[ValidityIssue]:
    """The note of a grease: the models use its base oil, its thickener is left out.

    Elastohydrodynamic film theory describes a grease-lubricated rolling
    contact that is fully flooded and at steady state by the base (bled) oil's
    film (Lugt's review, :data:`GREASE_SOURCE`), which is what the models
    compute from the lubricant's data. What the thickener adds is not modelled:
    thicker films at low speed, the drag of churning grease, and starvation
    (thinner films) at high speed once the grease has been pushed aside. Empty
    for an oil.
    """
    if lubricant.kind != "grease":
        return []
    made = [lubricant.thickener] if lubricant.thickener else []
    made += [f"NLGI {lubricant.nlgi_grade}"] if lubricant.nlgi_grade else []
    what = f" ({', '.join(made)})" if made else ""
    text = (
        f"{lubricant.name} is a grease{what}: the models take its base "
        "oil's viscosity, as elastohydrodynamic film theory does for a fully flooded grease "
        "contact at steady state; the thickener's share of the film and of the drag (grease "
        "churning, starvation at high speed) is not modelled"
    )
    return [
        statement(
            "grease (base oil only)", text, GREASE_SOURCE, routine="many ball screws run on grease"
        )
    ]


def check(
    screw: ScrewGeometry, lubricant: Lubricant, speed: FloatArray, temperature: FloatArray,
    axial_load: FloatArray,
    model: str,
    parameters: dict[str, Any],
    checks: Iterable[ValidityCheck] = (),
) -> list[ValidityIssue]:  # fmt: skip
    """Every quantity of a call that leaves its validity range, worst value each.

    Parameters
    ----------
    screw, lubricant, speed, temperature, axial_load
        The call's inputs (speed [rad/s], temperature [°C], axial load [N]). Many
        screws as a :class:`~ballscrew.geometry.ScrewArray`: the points' first axis is
        the screws' (or 1, shared by all), and each quantity's worst value over all
        screws is reported.
    model : str
        The friction model's name (recorded in each issue).
    parameters : dict
        The model's parameters as used.
    checks : iterable of callables
        The model's own checks (its ``ModelSpec.checks``), run after the
        common ones (speed factor, preload lift-off, and the lubricant's pour
        and flash points, :func:`lubricant_limits`, which bound every model:
        beyond them there is no lubricant, whatever the model makes of it).
    """
    issues: list[ValidityIssue] = []
    if speed.size == 0:
        return issues
    if isinstance(screw, ScrewArray):
        issues += _common_many(screw, speed, axial_load)
    else:
        n_max = float(rad_s_to_rpm(_span(np.abs(speed))[1]))
        issues += outside("speed factor d_m*n [mm*rpm]", [screw.pitch_diameter * 1e3 * n_max])
        if screw.nut != "single" and screw.preload > 0.0:
            load_max = _span(np.abs(axial_load))[1]
            issues += outside("axial load / preload", [load_max / screw.preload])
    t_extremes = list(_span(temperature))
    for limit in lubricant_limits(lubricant):
        issues += outside(limit, t_extremes)
    for model_check in checks:
        # Many screws (a ScrewArray) reach only the models that take them, whose checks
        # take them too (film_checks).
        run: Any = model_check
        issues += run(screw, lubricant, speed, temperature, axial_load, parameters)
    return [_with_model(issue, model) for issue in issues]


@functools.lru_cache(maxsize=1024)
def _with_model(issue: ValidityIssue, model: str) -> ValidityIssue:
    """``issue`` naming ``model`` (kept: a loop over single points meets the same ones)."""
    return replace(issue, model=model)


def _span(x: FloatArray) -> tuple[float, float]:
    """The smallest and largest value of the float array ``x`` (one value: read at once)."""
    if x.size == 1:
        value = float(x.reshape(-1)[0])
        return value, value
    return float(np.min(x)), float(np.max(x))


def _per_screw(x: FloatArray, count: int, reduce: Any) -> FloatArray:
    """``reduce`` of ``x`` over each screw's points (first axis the screws', or 1: shared)."""
    x = np.asarray(x, dtype=float)
    rows = x.reshape(1, -1) if x.ndim == 0 or x.shape[0] == 1 else x.reshape(x.shape[0], -1)
    result: FloatArray = np.broadcast_to(reduce(rows, axis=1), (count,))
    return result


def _common_many(
    screws: ScrewArray, speed: FloatArray, axial_load: FloatArray
) -> list[ValidityIssue]:
    """The speed factor and load-over-preload issues of many screws: the worst of all."""
    count = len(screws)
    n_max = rad_s_to_rpm(_per_screw(np.abs(speed), count, np.max))
    issues = outside(
        "speed factor d_m*n [mm*rpm]", (screws.pitch_diameter.reshape(-1) * 1e3 * n_max).tolist()
    )
    preload = screws.preload.reshape(-1)
    held = preload > 0.0
    if screws.nut != "single" and held.any():
        fa_max = _per_screw(np.abs(axial_load), count, np.max)
        issues += outside("axial load / preload", (fa_max[held] / preload[held]).tolist())
    return issues


def lubricant_checks(
    screw: BallScrew, lubricant: Lubricant, speed: FloatArray, temperature: FloatArray,
    axial_load: FloatArray, parameters: dict[str, Any],
) -> list[ValidityIssue]:  # fmt: skip
    """The viscosity-temperature fit's range and a grease's note (models that use the oil)."""
    t_range = [float(np.min(temperature)), float(np.max(temperature))]
    return outside("temperature [degC]", t_range) + grease_note(lubricant)


def film_checks(
    screw: ScrewGeometry, lubricant: Lubricant, speed: FloatArray, temperature: FloatArray,
    axial_load: FloatArray, parameters: dict[str, Any],
) -> list[ValidityIssue]:  # fmt: skip
    """Ranges of the EHL film formulas and of the Hertz fits, for models built on them.

    Includes :func:`lubricant_checks` (the viscosity fit's range, a grease's
    note). The checks depend on the operating range only through its extremes,
    so their result is cached on those (a loop over single points repeats the
    same extremes).
    """
    if isinstance(screw, ScrewArray):
        return _film_issues_many(
            screw, lubricant, parameters.get("hertz_method") == "houpert", speed, temperature,
            axial_load,
        )  # fmt: skip
    w_abs = np.abs(speed)
    moving = w_abs[w_abs > 0.0]
    slowest, fastest = _span(moving) if moving.size else (0.0, 0.0)
    t_low, t_high = _span(temperature)
    return list(
        _film_issues(
            screw,
            lubricant,
            parameters.get("hertz_method") == "houpert",
            t_low,
            t_high,
            slowest,
            fastest,
            _span(np.abs(axial_load))[1],
        )
    )


def _film_issues_many(
    screws: ScrewArray, lubricant: Lubricant, houpert: bool, speed: FloatArray,
    temperature: FloatArray, axial_load: FloatArray,
) -> list[ValidityIssue]:  # fmt: skip
    """:func:`_film_issues` of many screws at once, each at its own points: the worst of all.

    The same corners of each screw's operating range, evaluated on the screws' arrays.
    """
    count = len(screws)
    t_lo = _per_screw(temperature, count, np.min)
    t_hi = _per_screw(temperature, count, np.max)
    w_abs = np.abs(speed)
    w_max = _per_screw(w_abs, count, np.max)
    w_min = _per_screw(np.where(w_abs > 0.0, w_abs, np.inf), count, np.min)
    w_min = np.where(np.isfinite(w_min), w_min, 0.0)
    fa_max = _per_screw(np.abs(axial_load), count, np.max)
    issues = outside("temperature [degC]", [float(t_lo.min()), float(t_hi.max())])
    issues += grease_note(lubricant)
    ratios = [screws.ry_screw / screws.rx_screw, screws.ry_nut / screws.rx_nut]
    ratios = [np.maximum(r, 1.0 / r).reshape(-1) for r in ratios]
    issues += outside(
        "ellipticity k (Hamrock-Dowson)", np.concatenate([ellipticity_exact(r) for r in ratios])
    )
    if houpert:
        issues += outside("radius ratio Ry/Rx (Houpert fits)", np.concatenate(ratios))
    column = (count, 1)
    eta = np.stack([lubricant.dynamic_viscosity(t_lo), lubricant.dynamic_viscosity(t_hi)], axis=1)
    ep = screws.reduced_modulus.reshape(column)
    radii = (screws.rx_screw.reshape(column), screws.rx_nut.reshape(column))
    u_values = np.empty(0)
    moving = w_max > 0.0
    if moving.any():
        flat = screws.with_ndim(2)
        u = kinematics(flat, np.stack([w_max, w_min], axis=1)).entrainment_speed
        u_values = np.concatenate(
            [dimensionless_speed(eta, u, ep, rx)[moving].ravel() for rx in radii]
        )
    loads = ball_loads(screws.with_ndim(2), np.stack([0.0 * fa_max, fa_max], 1))
    q = np.concatenate([loads.normal_load_1, loads.normal_load_2], axis=1)
    loaded = q > 0.0
    some = loaded.any(axis=1)
    extremes = np.stack(
        [np.where(loaded, q, np.inf).min(axis=1), np.where(loaded, q, 0.0).max(axis=1)], axis=1
    )[some]
    w_values = np.concatenate(
        [dimensionless_load(extremes, ep[some], rx[some]).ravel() for rx in radii]
    )
    issues += outside("dimensionless speed U", u_values)
    issues += outside("dimensionless load W", w_values)
    return issues


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
    issues = outside("temperature [degC]", [t_lo, t_hi]) + grease_note(lubricant)
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
