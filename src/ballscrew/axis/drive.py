r"""From the motor shaft to the grid: a feed axis's motor, inverter and DC link losses.

ISO 14955-1 assesses a machine tool's energy by its components; for a feed axis
those are, from the load back to the supply, the mechanics (screw, bearings:
:mod:`ballscrew.axis.energy`), the servo motor, the inverter (the drive's motor
module) and the DC link with its supply. This module takes the motor's torque
:math:`T` [N·m] and speed :math:`\omega` [rad/s] at each sample (what
:func:`~ballscrew.axis.energy.axis_cycle` returns) and follows the power back:

1. **Current.** A permanent-magnet synchronous servo motor's torque is its
   torque constant times its phase current,
   :math:`I = |T_{em}|/K_t(\omega)`, with :math:`T_{em} = T + T_{fe}\,
   \mathrm{sign}(\omega)` the electromagnetic torque (the shaft torque and the
   motor's own drag). :math:`K_t` is per ampere **rms** of the phase current
   [N·m/A], as servo data sheets print it (``k_T``, ``K_T``); a constant given
   per ampere of the sine's peak is :math:`K_t/\sqrt 2` and is multiplied by
   :math:`\sqrt 2` before it is given here. It may fall with speed
   (:func:`torque_constant_at`).
2. **Copper loss.** :math:`P_{cu} = 3R_{ph}I^2` for three phases carrying the
   rms current :math:`I` each (:func:`copper_loss`). :math:`R_{ph}` is one
   phase of a star winding. A data sheet's terminal (line-to-line) resistance
   is :math:`R_{tt} = 2R_{ph}` for a star; for a delta winding the same
   :math:`R_{tt}/2` is its star equivalent, so :func:`phase_resistance` halves a
   terminal value in either case.
3. **Iron and friction loss of the motor.** A drag torque :math:`T_{fe}`
   [N·m] (hysteresis and bearings: a power :math:`T_{fe}|\omega|`); a power
   given at the rated speed is read as the drag torque
   :math:`P/\omega_{rated}` (:func:`iron_loss_power`).
4. **Inverter.** The electrical power at the motor's terminals is
   :math:`P_{el} = T\omega + T_{fe}|\omega| + P_{cu}`. The inverter loses
   either a share of it, by an efficiency :math:`\eta`
   (:func:`inverter_loss_efficiency`), or
   :math:`P_{inv} = P_0 + k|I| + rI^2` (:func:`inverter_loss`): its standby
   (control electronics, fans), its switches' voltage drop and switching per
   ampere, and its conduction resistance.
5. **DC link.** :math:`P_{dc} = P_{el} + P_{inv}`. Where it is negative the
   axis regenerates into the DC link, and the link either returns it to the
   grid (``"regenerative"``: an active infeed), stores it in a capacitor up
   to the storage's usable energy and gives it back to the next motoring
   (``"storage"``; beyond the limit it is burnt), or burns it in a braking
   resistor (``"resistor"``) (:func:`dc_link_flows`).

Energies are the trapezoidal integrals of the samples' powers (the DC link's
drawn and regenerated parts from the samples' positive and negative parts, so
that drawn − regenerated = :math:`\int P_{dc}\,dt` exactly). An axis at rest that
holds a load (a vertical axis's weight, a process force) has :math:`T \ne 0` at
:math:`\omega = 0`: it draws current and its copper loss counts over every
dwell and standstill.

Each axis is taken with its own DC link: the energy one axis regenerates while
another motors on a shared link is not netted (the grid energy of a machine
with one supply module can be lower by that).

References
----------
.. [1] ISO 14955-1:2017, Machine tools -- Environmental evaluation of machine
   tools -- Part 1: Design methodology for energy-efficient machine tools.
.. [2] IEC 60034-2-3:2024, Rotating electrical machines -- Part 2-3: Specific
   test methods for determining losses and efficiency of converter-fed AC motors.
.. [3] J. R. Hendershot, T. J. E. Miller, *Design of Brushless Permanent-Magnet
   Machines*, Motor Design Books, 2010 (torque constant, phase and
   line-to-line resistance, copper loss).
.. [4] D. Graovac, M. Pürschel, "IGBT power losses calculation using the
   data-sheet parameters", Infineon application note, 2009 (conduction loss
   of a forward voltage and a resistance, switching loss per ampere).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..errors import BallScrewInputError, FloatArray, check_choice

__all__ = [
    "DC_LINKS",
    "DcLinkFlows",
    "DriveEnergy",
    "DriveSpec",
    "MotorConstants",
    "copper_loss",
    "dc_link_flows",
    "drive_energy",
    "drive_totals",
    "inverter_loss",
    "inverter_loss_efficiency",
    "iron_loss_power",
    "motor_current",
    "phase_resistance",
    "torque_constant_at",
]

DC_LINKS = ("regenerative", "resistor", "storage")
"""What the DC link does with the energy the axes regenerate: return it to the grid,
burn it in a braking resistor, or store it (a capacitor) for the next motoring."""

AT_REST = 1e-6
"""Motor speed [rad/s] below which the motor stands: its iron and friction drag adds no
torque there (a planner's rounding, 1e-15 rad/s, is no direction of motion)."""

RESISTANCE_KINDS = ("phase", "terminal")
"""How a winding resistance is given: one phase of the star, or between two terminals."""


def phase_resistance(resistance: Any, kind: str) -> FloatArray:
    r"""The phase resistance :math:`R_{ph}` [Ω] of a winding resistance given as ``kind``.

    .. math:: R_{ph} = R \;(\text{phase}), \qquad R_{ph} = R_{tt}/2 \;(\text{terminal})

    A star winding measured between two terminals has two phases in series,
    :math:`R_{tt} = 2R_{ph}`; a delta winding's terminal resistance
    :math:`2R_\Delta/3` gives the star equivalent :math:`R_\Delta/3 = R_{tt}/2`
    as well, so the copper loss :math:`3R_{ph}I^2` of the line current
    :math:`I` is :math:`1.5R_{tt}I^2` for either connection (Hendershot and
    Miller, module references).

    Parameters
    ----------
    resistance : float or array_like
        The winding resistance [Ω].
    kind : str
        ``"phase"`` or ``"terminal"`` (line-to-line).

    Returns
    -------
    ndarray
        [Ω].

    Examples
    --------
    >>> float(phase_resistance(2.4, "terminal"))
    1.2
    """
    kind = check_choice("resistance_kind", kind, RESISTANCE_KINDS)
    r = np.asarray(resistance, dtype=float)
    out: FloatArray = r / 2.0 if kind == "terminal" else r * 1.0
    return out


def torque_constant_at(
    speed: Any, torque_constant: float, at_rated_speed: float | None = None,
    rated_speed: float | None = None,
) -> FloatArray:  # fmt: skip
    r"""The torque constant [N·m/A rms] at the motor speed ``speed`` [rad/s].

    .. math:: K_t(\omega) = K_{t0} + (K_{t,r} - K_{t0})\,\min(|\omega|/\omega_r,\,1)

    :math:`K_{t0}` at standstill, :math:`K_{t,r}` at the rated speed
    :math:`\omega_r`, linear between and held beyond (a warm magnet and the
    current's phase lag lower the constant with speed; a data sheet gives the
    two ends). Without ``at_rated_speed`` the constant is :math:`K_{t0}` at all
    speeds.

    Examples
    --------
    >>> torque_constant_at([0.0, 157.0, 314.0, 400.0], 2.0, 1.8, 314.0).round(3).tolist()
    [2.0, 1.9, 1.8, 1.8]
    """
    w = np.abs(np.asarray(speed, dtype=float))
    if at_rated_speed is None:
        return np.full_like(w, torque_constant)
    if rated_speed is None or not rated_speed > 0.0:
        raise BallScrewInputError(
            "motor.rated_speed", rated_speed,
            "the rated speed (> 0) where motor.torque_constant_at_rated_speed applies",
        )  # fmt: skip
    share = np.minimum(w / rated_speed, 1.0)
    out: FloatArray = torque_constant + (at_rated_speed - torque_constant) * share
    return out


def motor_current(torque: Any, torque_constant: Any) -> FloatArray:
    r"""Phase current [A rms] of a servo motor delivering ``torque`` [N·m].

    .. math:: I = |T|/K_t

    with :math:`K_t` [N·m/A] per ampere rms (module docstring); a holding
    torque at standstill draws its current like any other.

    Examples
    --------
    >>> motor_current([-3.6, 0.0, 1.8], 1.8).tolist()
    [2.0, 0.0, 1.0]
    """
    out: FloatArray = np.abs(np.asarray(torque, dtype=float)) / np.asarray(torque_constant)
    return out


def copper_loss(current: Any, resistance: Any) -> FloatArray:
    r"""Copper loss [W] of a three-phase winding: :math:`P_{cu} = 3R_{ph}I^2`.

    ``current`` is the phase current [A rms], ``resistance`` the phase
    resistance :math:`R_{ph}` [Ω] (:func:`phase_resistance` converts a terminal
    value); the stator winding loss of IEC 60034-2-3's loss separation. The
    resistance is the one given (data sheets: at 20 °C); a warm winding's is
    higher by 0.39 %/K (copper), which is not added.

    Examples
    --------
    2 A rms through 1.5 Ω a phase: 3 · 1.5 · 4 = 18 W.

    >>> float(copper_loss(2.0, 1.5))
    18.0
    """
    i = np.asarray(current, dtype=float)
    out: FloatArray = 3.0 * np.asarray(resistance, dtype=float) * i * i
    return out


def iron_loss_power(drag_torque: Any, speed: Any) -> FloatArray:
    r"""The motor's iron and friction loss [W]: :math:`P_{fe} = T_{fe}|\omega|`.

    ``drag_torque`` [N·m], ``speed`` [rad/s]. Hysteresis and bearing friction
    grow with the speed; eddy currents (:math:`\propto\omega^2`) are lumped in.

    Examples
    --------
    >>> float(iron_loss_power(0.1, -314.0))
    31.400000000000002
    """
    out: FloatArray = np.asarray(drag_torque, dtype=float) * np.abs(np.asarray(speed, dtype=float))
    return out


def inverter_loss_efficiency(power: Any, efficiency: float) -> FloatArray:
    r"""Inverter loss [W] at the motor's electrical power ``power`` [W] by an efficiency.

    .. math::

        P_{inv} = P_{el}\,(1/\eta - 1) \quad (P_{el} \ge 0), \qquad
        P_{inv} = |P_{el}|\,(1 - \eta) \quad (P_{el} < 0)

    Motoring, the DC link gives :math:`P_{el}/\eta`; regenerating, it receives
    :math:`\eta|P_{el}|`.

    Examples
    --------
    >>> inverter_loss_efficiency([950.0, -1000.0], 0.95).round(6).tolist()
    [50.0, 50.0]
    """
    if not 0.0 < efficiency <= 1.0:
        raise BallScrewInputError("machine.drive_efficiency", efficiency, "a share in (0, 100 %]")
    p = np.asarray(power, dtype=float)
    out: FloatArray = np.where(p >= 0.0, p * (1.0 / efficiency - 1.0), -p * (1.0 - efficiency))
    return out


def inverter_loss(
    current: Any, standby: float = 0.0, per_ampere: float = 0.0, resistance: float = 0.0
) -> FloatArray:
    r"""Inverter loss [W] by its loss model: :math:`P_{inv} = P_0 + k|I| + rI^2`.

    ``current`` is the motor's phase current [A rms]; :math:`P_0` [W] the
    standby loss (control electronics, fans: drawn at rest too), :math:`k`
    [W/A = V] the switches' forward voltage and switching loss per ampere,
    :math:`r` [Ω] their conduction resistance (all phases together): the
    data-sheet loss model of Graovac and Pürschel (module references), its
    constants lumped over the phases and a sine period.

    Examples
    --------
    >>> inverter_loss([0.0, 4.0], 10.0, 2.0, 0.5).tolist()
    [10.0, 26.0]
    """
    i = np.abs(np.asarray(current, dtype=float))
    out: FloatArray = standby + per_ampere * i + resistance * i * i
    return out


@dataclass(frozen=True)
class DcLinkFlows:
    """Where the DC link's energy goes over a series (J, each >= 0).

    ``drawn - returned = shaft + losses + burnt + stored`` closes the balance
    (:func:`drive_energy`).
    """

    drawn: float
    """From the grid."""
    regenerated: float
    """Into the DC link from the axis (its negative DC power)."""
    returned: float
    """Back to the grid (``"regenerative"``)."""
    burnt: float
    """In the braking resistor (``"resistor"``, and a full storage)."""
    stored: float
    """Left in the storage at the end (``"storage"``)."""
    mode: str = ""
    """The DC link's choice, one of :data:`DC_LINKS`."""

    @property
    def grid(self) -> float:
        """Net energy from the grid: drawn - returned [J]."""
        return self.drawn - self.returned


def _steps(time: FloatArray, power: FloatArray) -> tuple[FloatArray, FloatArray]:
    """The positive and negative parts' trapezoidal energy of each step [J], both >= 0."""
    dt = np.diff(time)
    pos = np.maximum(power, 0.0)
    neg = np.maximum(-power, 0.0)
    out_pos: FloatArray = 0.5 * (pos[1:] + pos[:-1]) * dt
    out_neg: FloatArray = 0.5 * (neg[1:] + neg[:-1]) * dt
    return out_pos, out_neg


def dc_link_flows(time: Any, power: Any, dc_link: str, storage: float | None = None) -> DcLinkFlows:
    r"""The DC link's energies over a series of its power ``power`` [W] at ``time`` [s].

    Per step :math:`k`, the energies drawn :math:`e^+_k` and regenerated
    :math:`e^-_k` are the trapezoids of the samples' positive and negative
    parts. Then, by ``dc_link``:

    - ``"regenerative"``: drawn :math:`\sum e^+`, returned :math:`\sum e^-`;
    - ``"resistor"``: drawn :math:`\sum e^+`, burnt :math:`\sum e^-`;
    - ``"storage"``: the storage's energy :math:`S`, empty at the start (the
      link at its nominal voltage), takes each step's net
      :math:`c_k = e^-_k - e^+_k`, :math:`S_{k+1} = \min(\max(S_k + c_k, 0),
      S_{max})`; what it cannot give is drawn, what it cannot take is burnt.
      The clamped sum runs over the runs of charge and discharge (a loop over
      those, each run vectorised). ``storage`` [J] is :math:`S_{max}`.

    Examples
    --------
    1 kW for 1 s, then -600 W for 1 s, into a 400 J storage: 200 J burnt, and
    nothing left to draw.

    >>> f = dc_link_flows([0, 1, 1, 2], [1000, 1000, -600, -600], "storage", 400.0)
    >>> f.drawn, f.burnt, f.stored
    (1000.0, 200.0, 400.0)
    """
    dc_link = check_choice("machine.dc_link", dc_link, DC_LINKS)
    t = np.asarray(time, dtype=float)
    p = np.asarray(power, dtype=float)
    pos, neg = _steps(t, p)
    drawn, regenerated = float(np.sum(pos)), float(np.sum(neg))
    if dc_link == "regenerative":
        return DcLinkFlows(drawn, regenerated, regenerated, 0.0, 0.0, dc_link)
    if dc_link == "resistor":
        return DcLinkFlows(drawn, regenerated, 0.0, regenerated, 0.0, dc_link)
    if storage is None or not (math.isfinite(storage) and storage >= 0.0):
        raise BallScrewInputError("machine.dc_link_storage", storage,
                                  "the storage's usable energy (>= 0 J)")  # fmt: skip
    charge = neg - pos
    level, short, over = 0.0, 0.0, 0.0
    moves = charge[charge != 0.0]
    edges = np.flatnonzero(np.diff(np.sign(moves)) != 0) + 1
    for run in np.split(moves, edges) if moves.size else []:
        total = float(np.sum(run))
        if total > 0.0:  # charging: the level rises monotonically to the top
            over += max(level + total - storage, 0.0)
            level = min(level + total, storage)
        else:  # discharging: it falls to empty, the rest is drawn
            short += max(-(level + total), 0.0)
            level = max(level + total, 0.0)
    return DcLinkFlows(short, regenerated, 0.0, over, level, dc_link)


@dataclass(frozen=True)
class MotorConstants:
    """A servo motor's electrical constants (SI); None where the case gives none.

    Attributes
    ----------
    torque_constant : float or None
        :math:`K_t` at standstill [N·m/A rms].
    torque_constant_at_rated_speed : float or None
        :math:`K_t` at the rated speed [N·m/A rms] (:func:`torque_constant_at`).
    rated_speed : float or None
        [rad/s].
    phase_resistance : float or None
        :math:`R_{ph}` [Ω] (a terminal value halved: :func:`phase_resistance`).
    iron_loss_torque : float or None
        The motor's iron and friction drag :math:`T_{fe}` [N·m].
    """

    torque_constant: float | None = None
    torque_constant_at_rated_speed: float | None = None
    rated_speed: float | None = None
    phase_resistance: float | None = None
    iron_loss_torque: float | None = None

    @classmethod
    def from_case(cls, motor: Mapping[str, Any]) -> MotorConstants:
        """From a case's ``[motor]`` (:attr:`ballscrew.io.case.Case.motor`, SI).

        ``winding_resistance`` with its ``resistance_kind``; ``iron_loss`` with
        ``iron_loss_kind`` (``"torque"``, or ``"power"`` at the rated speed).
        """
        r = motor.get("winding_resistance")
        r_ph = None if r is None else float(phase_resistance(r, motor["resistance_kind"]))
        iron = motor.get("iron_loss")
        if iron is not None and motor.get("iron_loss_kind") == "power":
            iron = iron / motor["rated_speed"]
        return cls(motor.get("torque_constant"), motor.get("torque_constant_at_rated_speed"),
                   motor.get("rated_speed"), r_ph, iron)  # fmt: skip


@dataclass(frozen=True)
class DriveSpec:
    """The drive of every axis of a machine (SI); None where the machine file gives none.

    Attributes
    ----------
    efficiency : float or None
        The inverter's efficiency [-] (:func:`inverter_loss_efficiency`).
    standby, per_ampere, resistance : float or None
        Its loss model's :math:`P_0` [W], :math:`k` [V], :math:`r` [Ω]
        (:func:`inverter_loss`); those not given are 0 when one is.
    dc_link : str or None
        One of :data:`DC_LINKS`.
    storage : float or None
        The storage's usable energy [J] (``dc_link = "storage"``).
    shared : bool
        Whether the axes share one DC link (one supply module): the machine's
        totals then net the axes' DC powers at each instant before the link's
        choice (:func:`drive_totals`); each axis's own figures stay those of
        the axis alone.
    """

    efficiency: float | None = None
    standby: float | None = None
    per_ampere: float | None = None
    resistance: float | None = None
    dc_link: str | None = None
    storage: float | None = None
    shared: bool = False

    @property
    def loss_model(self) -> bool:
        """Whether the drive's loss is the model :math:`P_0 + k|I| + rI^2`."""
        return any(v is not None for v in (self.standby, self.per_ampere, self.resistance))

    def as_dict(self) -> dict[str, Any]:
        """The settings given, in the JSON document's units (None: not given)."""
        return {"efficiency": self.efficiency, "standby_loss_W": self.standby,
                "loss_per_ampere_V": self.per_ampere, "loss_resistance_ohm": self.resistance,
                "dc_link": self.dc_link, "dc_link_storage_J": self.storage,
                "dc_link_shared": self.shared}  # fmt: skip

    @classmethod
    def from_mapping(cls, drive: Mapping[str, Any]) -> DriveSpec:
        """From :attr:`ballscrew.io.machine.Machine.drive` (keys as the attributes)."""
        fields = {k: drive[k] for k in cls.__dataclass_fields__ if k in drive}
        return cls(**fields)


@dataclass(frozen=True)
class DriveEnergy:
    """One axis's energy from the shaft to the grid over a series (J; None: not computed).

    ``left_out`` says, for each figure not computed or each part missing from
    one, which input was not given.
    """

    shaft_supplied: float
    """Positive shaft power's energy."""
    shaft_returned: float
    """Negative shaft power's energy (the load driving the motor), >= 0."""
    copper_loss: float | None
    iron_loss: float | None
    drive_loss: float | None
    dc_link: DcLinkFlows | None
    left_out: tuple[str, ...] = ()
    current: FloatArray | None = field(default=None, repr=False)
    """The phase current at each sample [A rms] (None without K_t)."""
    dc_power: FloatArray | None = field(default=None, repr=False)
    """The DC link power at each sample [W] (None where a loss is not computed)."""
    time: FloatArray | None = field(default=None, repr=False)
    """The sample times [s]."""
    spec: DriveSpec | None = field(default=None, repr=False)
    """The drive it was computed with."""

    @property
    def grid(self) -> float | None:
        """Net energy from the grid [J] (drawn - returned)."""
        return None if self.dc_link is None else self.dc_link.grid

    def as_dict(self) -> dict[str, Any]:
        """The figures in the JSON document's units (J)."""
        link = self.dc_link
        return {
            "copper_loss_J": self.copper_loss,
            "motor_iron_loss_J": self.iron_loss,
            "drive_loss_J": self.drive_loss,
            "grid_energy_J": self.grid,
            "dc_link_regenerated_J": None if link is None else link.regenerated,
            "returned_to_grid_J": None if link is None else link.returned,
            "burnt_J": None if link is None else link.burnt,
            "stored_J": None if link is None else link.stored,
            "left_out": list(self.left_out),
        }


def _trapezoid(y: FloatArray, t: FloatArray) -> float:
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(t)))


def drive_energy(
    time: Any, torque: Any, speed: Any, motor: MotorConstants, drive: DriveSpec,
    *, name: str = "the axis",
) -> DriveEnergy:  # fmt: skip
    r"""An axis's energies from the motor shaft to the grid (module docstring).

    Parameters
    ----------
    time : array_like
        Sample times [s], increasing.
    torque : array_like
        Motor shaft torque :math:`T` at each sample [N·m] (holding torques at
        rest included).
    speed : array_like
        Motor speed :math:`\omega` [rad/s].
    motor : MotorConstants
    drive : DriveSpec
    name : str
        How ``left_out`` names the axis's case.

    Returns
    -------
    DriveEnergy
        The copper loss needs :math:`K_t` and :math:`R`, the drive loss needs
        :math:`K_t` (the current) and an efficiency or loss model, the grid
        energy all of them and the DC link's choice; the motor's iron loss is
        optional (0 when not given, and said). Each one not computed is None,
        and ``left_out`` says why.

    Examples
    --------
    A constant 4 N·m held for 10 s by a motor of 2 N·m/A and 1 Ω a phase:
    3 · 1 · 2² · 10 = 120 J of copper loss.

    >>> e = drive_energy([0, 10], [4, 4], [0, 0], MotorConstants(2.0, phase_resistance=1.0),
    ...                  DriveSpec(efficiency=1.0, dc_link="resistor"))
    >>> e.copper_loss, e.grid
    (120.0, 120.0)
    """
    t = np.asarray(time, dtype=float)
    torque_ = np.asarray(torque, dtype=float)
    w = np.asarray(speed, dtype=float)
    shaft = torque_ * w
    supplied = _trapezoid(np.maximum(shaft, 0.0), t)
    returned = -_trapezoid(np.minimum(shaft, 0.0), t)
    left: list[str] = []
    k_t = motor.torque_constant
    drag = motor.iron_loss_torque
    p_fe = iron_loss_power(0.0 if drag is None else drag, w)
    iron = None if drag is None else _trapezoid(p_fe, t)
    if drag is None:
        left.append(f"motor iron and friction loss: left out, {name} has no motor.iron_loss")
    current = p_cu = None
    if k_t is None:
        left.append(f"copper loss: not computed, {name} has no motor.torque_constant")
    else:
        moving = np.where(np.abs(w) > AT_REST, np.sign(w), 0.0)
        t_em = torque_ + moving * (0.0 if drag is None else drag)
        k = torque_constant_at(w, k_t, motor.torque_constant_at_rated_speed, motor.rated_speed)
        current = motor_current(t_em, k)
        if motor.phase_resistance is None:
            left.append(f"copper loss: not computed, {name} has no motor.winding_resistance")
        else:
            p_cu = copper_loss(current, motor.phase_resistance)
    copper = None if p_cu is None else _trapezoid(p_cu, t)
    p_inv = None
    if drive.efficiency is None and not drive.loss_model:
        left.append("drive loss: not computed, the machine file gives neither "
                    "machine.drive_efficiency nor the loss model machine.drive_standby_loss, "
                    "drive_loss_per_ampere, drive_loss_resistance")  # fmt: skip
    elif drive.loss_model and current is not None:
        p_inv = inverter_loss(current, drive.standby or 0.0, drive.per_ampere or 0.0,
                              drive.resistance or 0.0)  # fmt: skip
    elif drive.efficiency is not None and p_cu is not None:
        p_inv = inverter_loss_efficiency(shaft + p_fe + p_cu, drive.efficiency)
    else:
        left.append("drive loss: not computed without the motor's current and copper loss")
    loss = None if p_inv is None else _trapezoid(p_inv, t)
    link = p_dc = None
    if drive.dc_link is None:
        left.append("energy from the grid: not computed, the machine file gives no "
                    "machine.dc_link (regenerative, resistor or storage)")  # fmt: skip
    elif p_cu is None or p_inv is None:
        left.append("energy from the grid: not computed without the copper and drive losses")
    else:
        p_dc = shaft + p_fe + p_cu + p_inv
        link = dc_link_flows(t, p_dc, drive.dc_link, drive.storage)
    return DriveEnergy(supplied, returned, copper, iron, loss, link, tuple(left), current, p_dc,
                       t, drive)  # fmt: skip


def drive_totals(drives: list[DriveEnergy]) -> dict[str, Any]:
    r"""The machine's sums of its axes' :meth:`DriveEnergy.as_dict` figures (J).

    A figure any axis lacks is None for the machine (its ``left_out`` says why);
    ``left_out`` is every axis's, each once. With a shared DC link
    (:attr:`DriveSpec.shared`, the axes on one time base), the DC link's figures
    are those of the summed DC power, :math:`\sum_{axes} P_{dc}(t)`, through the
    link's choice: what one axis regenerates while another motors is used there,
    and only the rest is returned, burnt or stored; ``dc_link_shared`` says so.
    """
    out: dict[str, Any] = {}
    parts = [d.as_dict() for d in drives]
    for key in parts[0] if parts else ():
        if key == "left_out":
            continue
        values = [p[key] for p in parts]
        out[key] = None if any(v is None for v in values) else float(sum(values))
    out["left_out"] = list(dict.fromkeys(n for p in parts for n in p["left_out"]))
    spec = drives[0].spec if drives else None
    shared = spec is not None and spec.shared and spec.dc_link is not None
    powers = [d.dc_power for d in drives]
    out["dc_link_shared"] = shared
    if shared and all(p is not None for p in powers):
        assert spec is not None and spec.dc_link is not None and drives[0].time is not None
        net = np.sum(np.stack([p for p in powers if p is not None]), axis=0)
        f = dc_link_flows(drives[0].time, net, spec.dc_link, spec.storage)
        out |= {
            "grid_energy_J": f.grid,
            "dc_link_regenerated_J": f.regenerated,
            "returned_to_grid_J": f.returned,
            "burnt_J": f.burnt,
            "stored_J": f.stored,
        }
    return out
