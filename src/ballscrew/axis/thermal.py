r"""The temperature a ball screw reaches: a lumped heat balance solved with the friction.

One thermal node holds the screw and the nut at the lubricant temperature
:math:`T`. The friction of a repeated cycle heats it with the mean power
:math:`\bar P(T)` (from :func:`ballscrew.axis.energy.axis_cycle` at that
temperature: a warmer, thinner oil changes the friction); it loses heat by
convection from the screw's surface and, optionally, by conduction into the
machine through a thermal resistance :math:`R_m`:

.. math::
    C\,\frac{dT}{dt} = \bar P(T) - G(T)\,(T - T_a), \qquad
    G = h\,\pi d L + 1/R_m .

The convection coefficient is the larger of forced convection from a
cylinder rotating in still air, :math:`Nu = 0.133\,Re^{2/3}Pr^{1/3}` with
:math:`Re = \omega d^2/\nu` (Kreith, *Principles of Heat Transfer*; valid for
:math:`Re < 4.3\cdot10^5`), at the cycle's RMS screw speed, and natural
convection from a horizontal cylinder (Churchill and Chu 1975,
:math:`Nu = \{0.60 + 0.387\,Ra^{1/6}/[1 + (0.559/Pr)^{9/16}]^{8/27}\}^2`).
Air properties are taken at 300 K. :func:`steady_temperature` solves the
balance for :math:`dT/dt = 0`; :func:`temperature_history` integrates it over
time (the cycle is short against the thermal time constant, so the mean power
per cycle drives the node).
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from ..chain import friction_torque, friction_torques
from ..errors import (
    BallScrewInputError,
    BallScrewValidityWarning,
    FloatArray,
    check_in_range,
    check_nonnegative,
    check_positive,
)
from ..geometry import BallScrew, nut_length
from ..helix import kernel_scope
from ..lubricant import Lubricant
from ..materials import STANDARD_GRAVITY, STEEL_DENSITY, STEEL_SPECIFIC_HEAT
from ..numerics import illinois
from .energy import Axis, screw_motion
from .motion import Profile

__all__ = [
    "AIR",
    "ThermalNode",
    "convection_coefficient",
    "estimated_screw_length",
    "heat_balance",
    "mean_powers",
    "series_temperature",
    "steady_at_speeds",
    "steady_temperature",
    "steady_temperatures",
    "temperature_histories",
    "temperature_history",
]

AIR = {"conductivity": 0.0263, "kinematic_viscosity": 1.589e-5, "prandtl": 0.707}
"""Air at 300 K and 1 bar: k [W/(m·K)], nu [m²/s], Pr [-] (Incropera, Table A.4)."""


STEEL_HEAT_CAPACITY = STEEL_SPECIFIC_HEAT
"""Specific heat of the screw and nut steel [J/(kg·K)] (:mod:`ballscrew.materials`)."""

KREITH_REYNOLDS_LIMIT = 4.3e5
"""Largest rotational Reynolds number of Kreith's rotating-cylinder correlation [-]."""


@dataclass(frozen=True)
class ThermalNode:
    """The screw and nut as one thermal mass (SI; temperatures in °C).

    Attributes
    ----------
    screw_length : float
        Length of screw exposed to the air [m].
    ambient : float
        Air and machine temperature [°C].
    machine_resistance : float or None
        Thermal resistance from the nut into the machine [K/W]; None for no
        conduction path (convection only, the conservative case).
    nut_mass : float
        Mass of the nut [kg], added to the screw's for the heat capacity.
    """

    screw_length: float
    ambient: float = 20.0
    machine_resistance: float | None = None
    nut_mass: float = 0.0

    def __post_init__(self) -> None:
        check_positive("screw_length", self.screw_length, "m")
        check_in_range("ambient", self.ambient, -273.15, 500.0, unit="°C")
        if self.machine_resistance is not None:
            check_positive("machine_resistance", self.machine_resistance, "K/W")
        check_nonnegative("nut_mass", self.nut_mass, "kg")

    def heat_capacity(self, screw: BallScrew) -> float:
        """Heat capacity of screw and nut [J/K] (steel)."""
        screw_mass = STEEL_DENSITY * math.pi * screw.pitch_diameter**2 / 4 * self.screw_length
        return (screw_mass + self.nut_mass) * STEEL_HEAT_CAPACITY


def estimated_screw_length(screw: BallScrew, travel: float) -> float:
    """Screw length in the air when none is given [m]: travel, nut and ends.

    The nut's travel [m], the nut itself (its loaded turns plus one turn for
    the return per circuit, twice for a double nut) and four pitch diameters
    for the bearing seats and the free ends. An assumption for the heat
    balance; give the real length where you know it.

    Examples
    --------
    >>> from ballscrew import reference_screw
    >>> round(estimated_screw_length(reference_screw(), 0.3), 3)
    0.6
    """
    return abs(travel) + nut_length(screw) + 4.0 * screw.pitch_diameter


def convection_coefficient(
    diameter: float, speed: npt.ArrayLike, surface: npt.ArrayLike, ambient: float
) -> FloatArray:
    """Convection coefficient of a horizontal cylinder [W/(m²·K)]: rotating or still.

    The larger of Kreith's rotating-cylinder correlation at ``speed`` [rad/s]
    and Churchill and Chu's natural convection at the surface-to-air
    temperature difference (``surface``, ``ambient`` in °C). Broadcasts over
    ``speed`` and ``surface``.

    Examples
    --------
    A 40 mm screw at 1500 rpm: Re = 1.6e4, Nu = 0.133 Re^(2/3) Pr^(1/3):

    >>> round(float(convection_coefficient(0.04, 157.08, 30.0, 20.0)), 1)
    49.1
    """
    d = float(check_positive("diameter", diameter, "m"))
    nu = AIR["kinematic_viscosity"]
    re = np.abs(np.asarray(speed, dtype=float)) * d**2 / nu
    if re.size and float(np.max(re)) > KREITH_REYNOLDS_LIMIT:
        warnings.warn(
            f"rotational Reynolds number {float(np.max(re)):.3g} of the screw is above "
            f"{KREITH_REYNOLDS_LIMIT:g}, the range of Kreith's rotating-cylinder correlation: "
            "the convection coefficient is extrapolated",
            BallScrewValidityWarning,
            stacklevel=2,
        )
    result: FloatArray = np.maximum(_forced(d, re), _natural(d, surface, ambient))
    return result


def _forced(d: float | FloatArray, re: FloatArray) -> FloatArray:
    """Kreith's rotating cylinder, h [W/(m²·K)] at the rotational Reynolds number ``re``."""
    k, pr = AIR["conductivity"], AIR["prandtl"]
    forced: FloatArray = 0.133 * re ** (2 / 3) * pr ** (1 / 3) * k / d
    return forced


def _natural(
    d: float | FloatArray, surface: npt.ArrayLike, ambient: float | FloatArray
) -> FloatArray:
    """Churchill and Chu's horizontal cylinder, h [W/(m²·K)] at the surface temperature."""
    k, nu, pr = AIR["conductivity"], AIR["kinematic_viscosity"], AIR["prandtl"]
    surf = np.asarray(surface, dtype=float)
    dt = np.maximum(np.abs(surf - ambient), 1e-9)
    film = 0.5 * (surf + ambient) + 273.15
    ra = STANDARD_GRAVITY * (1 / film) * dt * d**3 / (nu * nu / pr)
    natural = (0.60 + 0.387 * ra ** (1 / 6) / (1 + (0.559 / pr) ** (9 / 16)) ** (8 / 27)) ** 2
    h: FloatArray = natural * k / d
    return h


def mean_powers(
    profile: Profile,
    screw: BallScrew,
    lubricant: Lubricant | str,
    axis: Axis,
    temperatures: npt.ArrayLike,
    model: str = "complete",
    **parameters: Any,
) -> FloatArray:
    """Mean friction power of the screw over the cycle at each lubricant temperature [W].

    One friction call: the temperatures against the cycle's distinct samples
    (:class:`_CyclePowers`).
    """
    return _CyclePowers(profile, screw, lubricant, axis, model, parameters)(temperatures)


class _CyclePowers:
    """The cycle's mean friction power as a function of temperature, on its distinct samples.

    The friction of a sample depends on its screw speed and axial force (and
    the temperature); a profile repeats them (constant feed, dwells, and every
    cycle after the first), so the trapezoidal rule's weights are summed over
    the samples of each distinct (speed, force) pair and the friction model
    runs on the distinct pairs only: ``n`` cycles cost what one does. The
    mean power equals the sample-by-sample trapezoidal rule up to the order
    of the summation (a relative 1e-15).
    """

    def __init__(
        self, profile: Profile, screw: BallScrew, lubricant: Lubricant | str, axis: Axis,
        model: str, parameters: dict[str, Any],
    ) -> None:  # fmt: skip
        omega, _, force = screw_motion(profile, screw, axis)
        keys = np.empty(omega.shape, dtype=complex)
        keys.real, keys.imag = omega, force
        pairs, inverse = np.unique(keys, return_inverse=True)
        dt = np.diff(profile.time)
        share = np.zeros(omega.shape)
        share[:-1] += 0.5 * dt
        share[1:] += 0.5 * dt
        summed = np.bincount(inverse.reshape(-1), weights=share, minlength=pairs.size)
        self.weight: FloatArray = summed.astype(float) / profile.duration
        self.omega, self.force = pairs.real.copy(), pairs.imag.copy()
        self.args = (screw, lubricant, model, parameters)

    def __call__(self, temperatures: npt.ArrayLike) -> FloatArray:
        """Mean power [W] at each temperature [°C]: one friction call."""
        temps = np.atleast_1d(np.asarray(temperatures, dtype=float))
        screw, lubricant, model, parameters = self.args
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            torque = friction_torque(
                screw, lubricant, speed=self.omega[None, :], temperature=temps[:, None],
                axial_load=self.force[None, :], model=model, **parameters,
            ).total  # fmt: skip
        power = np.broadcast_to(torque, (temps.size, self.omega.size)) * np.abs(self.omega)
        result: FloatArray = power @ self.weight
        return result


def _conductance(node: ThermalNode, screw: BallScrew, speed: float, temperature: float) -> float:
    return float(_conductances(node, screw, speed, np.array([temperature]))[0])


def _conductances(
    node: ThermalNode, screw: BallScrew, speed: float, temperatures: FloatArray
) -> FloatArray:
    area = math.pi * screw.pitch_diameter * node.screw_length
    h = convection_coefficient(screw.pitch_diameter, speed, temperatures, node.ambient)
    machine = 0.0 if node.machine_resistance is None else 1.0 / node.machine_resistance
    result: FloatArray = h * area + machine
    return result


def _node_conductance(
    node: ThermalNode, screw: BallScrew, speed: float
) -> Callable[[float], float]:
    """:func:`_conductance` at one speed as a function of the temperature alone.

    The same operations (the forced part once, its speed being fixed), without
    the checks of every call: the heat balance's integrator asks for it at
    every step.
    """
    _conductance(node, screw, speed, node.ambient)  # checks the inputs, warns once
    d = screw.pitch_diameter
    area = math.pi * d * node.screw_length
    machine = 0.0 if node.machine_resistance is None else 1.0 / node.machine_resistance
    forced = _forced(d, np.abs(np.asarray(speed, dtype=float)) * d**2 / AIR["kinematic_viscosity"])

    def conductance(temperature: float) -> float:
        h = np.maximum(forced, _natural(d, np.array([temperature]), node.ambient))
        return float((h * area + machine)[0])

    return conductance


def history_grid(node: ThermalNode, steady: float) -> FloatArray:
    """The temperatures [°C] at which :func:`temperature_history` tabulates the mean power.

    Every 2 K or so from the ambient to 1 K past the steady temperature ``steady``.
    """
    grid: FloatArray = np.linspace(
        node.ambient, steady + 1.0, max(3, int(steady - node.ambient) // 2 + 3)
    )
    return grid


def _rms_speed(profile: Profile, screw: BallScrew) -> float:
    omega = 2 * math.pi * profile.speed / screw.lead
    dt = np.diff(profile.time)
    mean_sq = np.sum(0.5 * (omega[1:] ** 2 + omega[:-1] ** 2) * dt) / profile.duration
    return float(math.sqrt(mean_sq))


@dataclass(frozen=True)
class SteadyState:
    """The steady temperature of a repeated cycle and the heat flows there."""

    temperature: float
    friction_power: float
    heat_out: float
    conductance: float
    history_powers: tuple[FloatArray, FloatArray] | None = field(
        default=None, repr=False, compare=False
    )
    """The mean friction power on :func:`temperature_history`'s grid (temperatures [°C],
    powers [W]), where it was computed with the balance (:func:`steady_temperatures`)."""
    history: tuple[FloatArray, FloatArray] | None = field(default=None, repr=False, compare=False)
    """The temperature history (times [s], temperatures [°C]), where it was integrated with
    other screws' (:func:`temperature_histories`)."""


TABLE_STEP = 5.0
"""Spacing of the temperatures at which :func:`steady_temperature` tabulates the balance [K]."""


def steady_temperature(
    profile: Profile,
    screw: BallScrew,
    lubricant: Lubricant | str,
    axis: Axis,
    node: ThermalNode,
    *,
    model: str = "complete",
    **parameters: Any,
) -> SteadyState:
    r"""Temperature at which the cycle's mean friction power leaves as heat [°C].

    Solves :math:`\bar P(T) = G(T)(T - T_a)` between the ambient temperature
    and 200 °C above it. The balance is first tabulated every
    :data:`TABLE_STEP` kelvin in one friction call over the cycle's distinct
    samples; the first step over which it changes sign brackets the root,
    which is then found on the balance itself by the Illinois method (to
    1e-11 K, a few more evaluations of the cycle), not on the table.
    """
    check_positive("screw_length", node.screw_length, "m")
    speed = _rms_speed(profile, screw)
    mean_power = _CyclePowers(profile, screw, lubricant, axis, model, parameters)

    def imbalance(t: FloatArray) -> FloatArray:
        heat_out = _conductances(node, screw, speed, t) * (t - node.ambient)
        result: FloatArray = mean_power(t) - heat_out
        return result

    lo, hi = node.ambient, node.ambient + 200.0
    nodes = np.linspace(lo, hi, round((hi - lo) / TABLE_STEP) + 1)
    table = imbalance(nodes)
    if table[-1] > 0.0:
        raise BallScrewInputError(
            "thermal", "(steady state)", "a cycle whose friction the node can shed below "
            f"{hi:g} °C (give a machine_resistance or a longer screw_length)",
        )  # fmt: skip
    j = int(np.argmax(table <= 0.0))  # the first node at or past the balance
    if j == 0 or table[j] == 0.0:
        t = float(nodes[j])
    else:  # -imbalance rises through 0 in (nodes[j-1], nodes[j]]
        t = float(
            illinois(
                lambda x, _i: -imbalance(x), nodes[j - 1 : j], nodes[j : j + 1],
                -table[j - 1 : j], -table[j : j + 1], xtol=1e-11,
            )[0]
        )  # fmt: skip
    g = _conductance(node, screw, speed, t)
    power = float(mean_power(t)[0])
    return SteadyState(t, power, g * (t - node.ambient), g)


MAX_POINTS = 2_000_000
"""The most (screw, temperature, sample) points :func:`steady_temperatures` evaluates at once."""

TABLE_STAGES = (5, 13)
"""The table nodes :func:`steady_temperatures` evaluates first (up to the 5th, then the 13th,
with the last), before the rest for the screws not yet balanced."""


def steady_temperatures(
    profile: Profile,
    screws: list[BallScrew],
    lubricant: Lubricant | str,
    axes: list[Axis],
    nodes: list[ThermalNode],
    *,
    model: str = "complete",
    **parameters: Any,
) -> list[SteadyState | None]:
    """:func:`steady_temperature` of many screws on one lubricant and model, together.

    The same balance, table and Illinois iteration, with the friction of every
    screw in one call (:func:`~ballscrew.chain.friction_torques`, each screw at its
    own distinct samples, padded with weightless repeats of its first). The
    table is evaluated in stages (:data:`TABLE_STAGES`, and its last node, whose
    sign decides the error): a screw whose balance changes sign early needs no
    more of it, and the first sign change and the error are those of the whole
    table. The temperatures equal the screw-by-screw ones to the rounding of the
    friction and of the weighted sums (a relative 1e-13; the Illinois tolerance
    is 1e-11 K). Each carries the mean power on :func:`temperature_history`'s grid,
    from the same call as its power at the root. None for a screw whose balance
    does not close below 200 K above the ambient, or for every screw when a point
    cannot be solved: :func:`steady_temperature` then runs alone and raises its error.
    """
    n = len(screws)
    if n == 0:
        return []
    for node in nodes:
        check_positive("screw_length", node.screw_length, "m")
    samples = [_CyclePowers(profile, s, lubricant, a, model, parameters)
               for s, a in zip(screws, axes, strict=True)]  # fmt: skip
    width = max(c.omega.size for c in samples)

    def padded(values: list[FloatArray], fill: list[float]) -> FloatArray:
        out = np.empty((n, width))
        for i, (v, f) in enumerate(zip(values, fill, strict=True)):
            out[i, : v.size], out[i, v.size :] = v, f
        return out

    omega = padded([c.omega for c in samples], [float(c.omega[0]) for c in samples])
    force = padded([c.force for c in samples], [float(c.force[0]) for c in samples])
    weight = padded([c.weight for c in samples], [0.0] * n)
    speeds = [_rms_speed(profile, s) for s in screws]
    ambient = np.array([node.ambient for node in nodes])

    def powers(rows: npt.NDArray[np.intp], temps: FloatArray) -> FloatArray:
        """Mean power of the screws ``rows`` at their temperatures ``temps`` (rows x k)."""
        out: FloatArray = np.empty(temps.shape)
        # The helix's compiled loop for these calls alone (kernel_scope): every screw's
        # rows at once; the process's other calls keep their path and their numbers.
        step = max(1, MAX_POINTS // (temps.shape[1] * width))
        for start in range(0, rows.size, step):
            part = slice(start, start + step)
            r = rows[part]
            with warnings.catch_warnings(), kernel_scope():
                warnings.simplefilter("ignore")
                torque = friction_torques(
                    [screws[i] for i in r], lubricant, speed=omega[r, None, :],
                    temperature=temps[part, :, None], axial_load=force[r, None, :],
                    model=model, paired=True, warn=False, components=False, **parameters,
                ).total  # fmt: skip
            out[part] = np.einsum("rkp,rp->rk", torque * np.abs(omega[r, None, :]), weight[r])
        return out

    def imbalance(rows: npt.NDArray[np.intp], temps: FloatArray) -> FloatArray:
        heat = np.array([_conductances(nodes[i], screws[i], speeds[i], t) * (t - nodes[i].ambient)
                         for i, t in zip(rows, temps, strict=True)])  # fmt: skip
        out: FloatArray = powers(rows, temps) - heat
        return out

    count = round(200.0 / TABLE_STEP) + 1
    grid = ambient[:, None] + np.linspace(0.0, 200.0, count)[None, :]
    table = np.full((n, count), np.nan)
    every = np.arange(n)
    try:
        first = [*range(TABLE_STAGES[0]), count - 1]
        table[:, first] = imbalance(every, grid[:, first])
        for lo, hi in ((TABLE_STAGES[0], TABLE_STAGES[1]), (TABLE_STAGES[1], count - 1)):
            rows = every[~np.any(table[:, :lo] <= 0.0, axis=1) & (table[:, -1] <= 0.0)]
            if rows.size:
                table[np.ix_(rows, np.arange(lo, hi))] = imbalance(rows, grid[rows, lo:hi])
        ok = table[:, -1] <= 0.0
        j = np.where(ok, np.argmax(table <= 0.0, axis=1), 0)
        at_node = ok & ((j == 0) | (table[every, j] == 0.0))
        root = np.where(at_node, grid[every, j], np.nan)
        solve = every[ok & ~at_node]
        if solve.size:
            js = j[solve]
            root[solve] = illinois(
                lambda x, idx: -imbalance(solve[idx], x[:, None])[:, 0],
                grid[solve, js - 1], grid[solve, js], -table[solve, js - 1], -table[solve, js],
                xtol=1e-11,
            )  # fmt: skip
        done = every[ok]
        power = np.full(n, np.nan)
        grids = {int(i): history_grid(nodes[i], float(root[i])) for i in done}
        if done.size:
            # The power at the root, and on the history's grid, in one call.
            size = 1 + max(g.size for g in grids.values())
            temps = np.empty((done.size, size))
            for r, i in enumerate(done):
                tg = grids[int(i)]
                temps[r, 0], temps[r, 1 : tg.size + 1], temps[r, tg.size + 1 :] = (
                    root[i], tg, tg[-1])  # fmt: skip
            table_powers = powers(done, temps)
            power[done] = table_powers[:, 0]
            on_grid = {int(i): table_powers[r, 1 : grids[int(i)].size + 1]
                       for r, i in enumerate(done)}  # fmt: skip
    except BallScrewInputError:
        return [None] * n
    out: list[SteadyState | None] = []
    for i in range(n):
        if not ok[i]:
            out.append(None)
            continue
        t = float(root[i])
        g = _conductance(nodes[i], screws[i], speeds[i], t)
        out.append(SteadyState(t, float(power[i]), g * (t - nodes[i].ambient), g,
                               (grids[i], on_grid[i])))  # fmt: skip
    return out


@dataclass(frozen=True)
class SteadyAtSpeed:
    """Steady temperatures of continuous running, one per speed (arrays, SI, °C)."""

    speed: FloatArray
    temperature: FloatArray
    torque: FloatArray
    power: FloatArray
    conductance: FloatArray


def steady_at_speeds(
    screw: BallScrew,
    lubricant: Lubricant | str,
    node: ThermalNode,
    speeds: npt.ArrayLike,
    *,
    axial_load: float = 0.0,
    model: str = "complete",
    **parameters: Any,
) -> SteadyAtSpeed:
    r"""Steady temperature and friction torque of the screw running at each constant speed.

    Solves :math:`T_f(\omega, T)\,|\omega| = G(\omega, T)(T - T_a)` for every
    speed [rad/s] at once: a vectorised bisection between the ambient and
    200 °C above it, one friction call per step over all the speeds.
    A speed whose friction the node cannot shed below that raises an error.
    """
    check_positive("screw_length", node.screw_length, "m")
    omega = np.atleast_1d(np.asarray(speeds, dtype=float))
    area = math.pi * screw.pitch_diameter * node.screw_length
    machine = 0.0 if node.machine_resistance is None else 1.0 / node.machine_resistance

    def flows(temp: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            torque = friction_torque(
                screw, lubricant, speed=omega, temperature=temp, axial_load=axial_load,
                model=model, **parameters,
            ).total  # fmt: skip
        g = convection_coefficient(screw.pitch_diameter, omega, temp, node.ambient) * area
        return torque, torque * np.abs(omega), g + machine

    lo = np.full_like(omega, node.ambient)
    hi = lo + 200.0
    _, p_hi, g_hi = flows(hi)
    if np.any(too_hot := p_hi > g_hi * (hi - node.ambient)):
        raise BallScrewInputError(
            "speed", float(omega[np.argmax(too_hot)]),
            f"a speed whose friction the node can shed below {node.ambient + 200:g} °C "
            "(give a machine_resistance or a longer screw_length)",
        )  # fmt: skip
    for _ in range(50):
        mid = 0.5 * (lo + hi)
        _, p, g = flows(mid)
        warm = p > g * (mid - node.ambient)
        lo, hi = np.where(warm, mid, lo), np.where(warm, hi, mid)
    temp = 0.5 * (lo + hi)
    torque, power, g = flows(temp)
    return SteadyAtSpeed(omega, temp, torque, power, g)


SETTLED = 30.0
"""Time constants after which a repeated cycle's temperature is taken as its steady one [-]
(:func:`temperature_history`; e^-30 = 1e-13 of the rise is left)."""


def temperature_history(
    profile: Profile,
    screw: BallScrew,
    lubricant: Lubricant | str,
    axis: Axis,
    node: ThermalNode,
    duration: float,
    *,
    model: str = "complete",
    points: int = 200,
    steady: SteadyState | None = None,
    **parameters: Any,
) -> tuple[FloatArray, FloatArray]:
    """Temperature over ``duration`` [s] of repeating the cycle from the ambient: (t, T).

    The mean power per cycle is tabulated over temperature (every 2 K up to
    the steady temperature) and the heat balance integrated with scipy's
    ``solve_ivp``. ``steady`` is the cycle's :func:`steady_temperature`, if
    already solved (with its history, if integrated, :func:`temperature_histories`).
    """
    from scipy.integrate import solve_ivp

    check_positive("duration", duration, "s")
    if steady is None:
        steady = steady_temperature(profile, screw, lubricant, axis, node, model=model,
                                    **parameters)  # fmt: skip
    times = np.linspace(0.0, duration, points)
    if steady.history is not None and np.array_equal(steady.history[0], times):
        return steady.history
    speed = _rms_speed(profile, screw)
    grid = history_grid(node, steady.temperature)
    given = steady.history_powers
    if given is not None and np.array_equal(given[0], grid):
        powers = given[1]
    else:
        powers = mean_powers(profile, screw, lubricant, axis, grid, model, **parameters)
    capacity = node.heat_capacity(screw)
    conductance = _node_conductance(node, screw, speed)

    def rate(_t: float, y: FloatArray) -> FloatArray:
        temp = float(y[0])
        power = float(np.interp(temp, grid, powers))
        loss = conductance(temp) * (temp - node.ambient)
        return np.array([(power - loss) / capacity])

    # Past SETTLED time constants C/G the temperature is within e^-SETTLED of the steady one:
    # the balance is integrated that far at most, and the steady temperature held after
    # (a run time of years otherwise held the solver for minutes).
    settled = SETTLED * capacity / _conductance(node, screw, speed, steady.temperature)
    span = min(duration, settled)
    inside = times[times <= span]
    sol = solve_ivp(rate, (0.0, span), [node.ambient], t_eval=inside, rtol=1e-8, atol=1e-8)
    held = np.full(times.size - inside.size, steady.temperature)
    return times, np.concatenate([np.asarray(sol.y[0]), held])


def temperature_histories(
    profile: Profile,
    screws: list[BallScrew],
    nodes: list[ThermalNode],
    duration: float,
    steadies: list[SteadyState],
    *,
    points: int = 200,
) -> list[tuple[FloatArray, FloatArray]]:
    """:func:`temperature_history` of many screws, their nodes integrated together.

    Each screw's balance solved with its power table (``steadies``, from
    :func:`steady_temperatures`, which carry it), the nodes one system of
    independent equations for ``solve_ivp``: the same equations, tables and
    tolerances (rtol 1e-8), the steps shared. Each temperature equals the
    screw's own integration within that tolerance (not to rounding: the steps
    differ). Past its :data:`SETTLED` time constants a node holds its steady
    temperature, as alone.
    """
    from scipy.integrate import solve_ivp

    check_positive("duration", duration, "s")
    n = len(screws)
    times = np.linspace(0.0, duration, points)
    if n == 0:
        return []
    tables = [st.history_powers for st in steadies]
    if any(t is None for t in tables):
        raise BallScrewInputError("steadies", "(no power table)", "steady_temperatures' states")
    grids = [t[0] for t in tables if t is not None]
    size = max(g.size for g in grids)
    powers = np.empty((n, size))
    for i, t in enumerate(tables):
        assert t is not None
        powers[i, : t[1].size], powers[i, t[1].size :] = t[1], t[1][-1]
    first = np.array([g[0] for g in grids])
    step = np.array([g[1] - g[0] for g in grids])
    last = np.array([g.size - 1 for g in grids])
    d = np.array([s.pitch_diameter for s in screws])
    ambient = np.array([node.ambient for node in nodes])
    area = np.pi * d * np.array([node.screw_length for node in nodes])
    machine = np.array([0.0 if node.machine_resistance is None else 1.0 / node.machine_resistance
                        for node in nodes])  # fmt: skip
    capacity = np.array([node.heat_capacity(s) for node, s in zip(nodes, screws, strict=True)])
    speeds = [_rms_speed(profile, s) for s in screws]
    for node, s, speed in zip(nodes, screws, speeds, strict=True):
        _conductance(node, s, speed, node.ambient)  # checks the inputs, warns once
    forced = _forced(d, np.abs(np.array(speeds)) * d**2 / AIR["kinematic_viscosity"])
    rows = np.arange(n)

    def rate(_t: float, y: FloatArray) -> FloatArray:
        # np.interp on each screw's even grid: clamped at its ends
        pos = np.clip((y - first) / step, 0.0, last)
        j = np.minimum(pos.astype(int), last - 1)
        power = powers[rows, j] + (pos - j) * (powers[rows, j + 1] - powers[rows, j])
        g = np.maximum(forced, _natural(d, y, ambient)) * area + machine
        out: FloatArray = (power - g * (y - ambient)) / capacity
        return out

    steady = np.array([st.temperature for st in steadies])
    g_steady = np.maximum(forced, _natural(d, steady, ambient)) * area + machine
    span = np.minimum(duration, SETTLED * capacity / g_steady)
    inside = times[times <= float(np.max(span))]
    sol = solve_ivp(rate, (0.0, float(np.max(span))), ambient, t_eval=inside, rtol=1e-8,
                    atol=1e-8)  # fmt: skip
    out = []
    for i in range(n):
        own = times <= span[i]
        temps = np.full(times.size, steady[i])
        temps[own] = np.asarray(sol.y[i])[: int(np.sum(own))]
        out.append((times, temps))
    return out


MAX_STEPS = 1_000_000
"""The most steps of :func:`heat_balance` (8 MB an array)."""


def heat_balance(
    time: FloatArray, power: FloatArray, capacity: float, conductance: float,
    ambient: float, start: float,
) -> FloatArray:  # fmt: skip
    r"""Temperature [°C] of a lumped mass heated by ``power`` [W] at each of ``time`` [s].

    :math:`C\dot T = P - G(T - T_a)` from :math:`T(0)` = ``start``; the power is
    averaged over steps of at most a hundredth of :math:`\tau = C/G` (energy
    kept exactly: the steps take the trapezoidal energy of the samples; at most
    :data:`MAX_STEPS` of them, so that a dwell of days stays bounded: each step is
    still exact for a power constant within it), and
    each step is integrated exactly, :math:`T_{k+1} - T_\infty = (T_k -
    T_\infty)e^{-h/\tau}` with :math:`T_\infty = T_a + \bar P/G`, by a linear
    filter (no Python loop over the steps). A series of no duration (one sample,
    or one time throughout) stays at ``start``.

    Examples
    --------
    Constant 10 W into 1000 J/K through 1 W/K for one time constant from 20 °C:
    20 + 10 (1 - 1/e) = 26.32 °C.

    >>> t = np.linspace(0.0, 1000.0, 11)
    >>> round(float(heat_balance(t, np.full(11, 10.0), 1000.0, 1.0, 20.0, 20.0)[-1]), 2)
    26.32
    """
    from scipy.signal import lfilter

    tau = capacity / conductance
    duration = float(time[-1] - time[0])
    if not duration > 0.0:  # no time passes: the start (the steps below would be 0/0)
        return np.full(np.shape(time), float(start))
    steps = min(max(1, math.ceil(duration / (tau / 100.0)), min(time.size, 100_000)), MAX_STEPS)
    grid = np.linspace(time[0], time[-1], steps + 1)
    energy = np.concatenate([[0.0], np.cumsum(0.5 * (power[1:] + power[:-1]) * np.diff(time))])
    mean = np.diff(np.interp(grid, time, energy)) / np.diff(grid)
    h = float(grid[1] - grid[0])
    decay = math.exp(-h / tau)
    # T_{k+1} - T_a = decay (T_k - T_a) + (1 - decay) P_k / G
    drive = (1.0 - decay) * mean / conductance
    rise, _ = lfilter([1.0], [1.0, -decay], drive, zi=[decay * (start - ambient)])
    temp = ambient + np.concatenate([[start - ambient], rise])
    out: FloatArray = np.interp(time, grid, temp)
    return out


def series_temperature(
    time: FloatArray, power: FloatArray, node: ThermalNode, screw: BallScrew,
    speed: FloatArray, start: float,
) -> FloatArray:  # fmt: skip
    r"""Temperature [°C] of screw and nut over a time series of heat ``power`` [W].

    The node's balance :math:`C\dot T = P(t) - G\,(T - T_a)` (:func:`heat_balance`)
    from ``start`` [°C], with the node's heat capacity and one conductance
    :math:`G = h\,\pi d L + 1/R_m` for the whole series: the convection at the
    series' RMS screw speed (``speed`` [rad/s] at each of ``time`` [s], the
    trapezoidal mean of its square) and a surface 1 K above the ambient, as
    :func:`steady_temperature` takes it.

    Examples
    --------
    A still screw with a constant power settles towards :math:`T_a + P/G`:

    >>> from ballscrew import reference_screw
    >>> s, node = reference_screw(), ThermalNode(screw_length=0.6, machine_resistance=0.5)
    >>> t = np.linspace(0.0, 1e6, 101)
    >>> temp = series_temperature(t, np.full(101, 4.0), node, s, np.zeros(101), 20.0)
    >>> g = _conductance(node, s, 0.0, 21.0)
    >>> bool(abs(temp[-1] - (20.0 + 4.0 / g)) < 1e-6)
    True
    """
    capacity = node.heat_capacity(screw)
    duration = float(time[-1] - time[0])
    mean_square = float(np.sum(0.5 * (speed[1:] ** 2 + speed[:-1] ** 2) * np.diff(time)))
    rms = math.sqrt(mean_square / duration) if duration > 0 else 0.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        g = _conductance(node, screw, rms, node.ambient + 1.0)
    return heat_balance(time, power, capacity, g, node.ambient, start)
