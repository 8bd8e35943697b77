r"""A machine through its part program: each feed axis's torques, energies, heat and reversals.

This module is long on purpose: it is the one place where the planned motion meets each
axis (its cycle, its exact distances, its heat, its reversals, its drive losses and its
verdicts), and those steps share one time series and one set of notes per axis.

:func:`run_program` reads the program (:mod:`.gcode`), plans its jerk-limited
motion (:mod:`.planner`) and runs every linear axis of the machine through it
with the axis wing (:mod:`ballscrew.axis`):

- the axis and its heat balance from its case (:func:`ballscrew.axis.setup.axis_setup`);
- a :class:`~ballscrew.axis.motion.Profile` of the axis's samples, with the
  process force against the motion in feed blocks;
- :func:`ballscrew.axis.energy.axis_cycle` at the starting temperature: the
  friction model over all samples at once (inertia, gravity and process force
  in the axial load), the support bearings, the motor torque;
- the temperature of screw and nut from the lumped heat balance
  :math:`C\,\dot T = P_f(t) - G\,(T - T_a)`
  (:func:`ballscrew.axis.thermal.series_temperature`: the node's conductance at
  the program's RMS screw speed), integrated exactly for a power held constant
  over steps of at most a hundredth of the time constant;
- the friction at each instant's temperature: the cycle run again at the
  program's warmest temperature, and each sample's friction torque
  interpolated linearly in temperature between the two runs (the model is
  smooth in temperature over a few kelvin; both runs are the model's own);
- every reversal of each axis: its time, position, the axial load on either
  side (its mean over :data:`LOAD_WINDOW` of motion; the sign a controller's
  friction compensation needs), the friction
  force :math:`F_f = 2\pi T_f/l` of the model at the check's creep speed
  (:data:`ballscrew.axis.check.CREEP_SPEED`) under that load, and the lost
  motion :math:`2F_f/k` with the axis stiffness :math:`k` at that nut position
  (shaft, nut at the makers' printed level, thrust bearings;
  :func:`ballscrew.design.stiffness.reversal_lost_motion`);
- the thermal lead error over the travel, :math:`\alpha\,\Delta T\,L`
  (:func:`ballscrew.design.sizing.thermal_elongation`, the steel's
  :data:`ballscrew.materials.STEEL_EXPANSION`).

:func:`heat_balance` is :func:`ballscrew.axis.thermal.heat_balance`, importable
here as before.

Energies follow the component view of ISO 14955-1 and -2 for the feed axes:
the mechanical energy the motor delivers to the axis (positive shaft power),
the energy it takes back (negative shaft power, which a regenerative drive
returns), the useful work on the process, and the losses by component
(screw friction, support bearings); from the motor shaft to the grid, the
motor's copper and iron loss, the drive's loss and the DC link's regeneration
(:mod:`ballscrew.axis.drive`, from each axis's motor torque and speed), each
left out and said where its case or the machine file gives no constant.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..axis.check import CREEP_SPEED, AxisCheck, Criterion, run_check
from ..axis.drive import DriveEnergy, DriveSpec, MotorConstants, drive_energy, drive_totals
from ..axis.duty import EnergyRun, ModelEnergy
from ..axis.energy import CycleResult, axis_cycle
from ..axis.motion import Profile
from ..axis.setup import AxisSetup, axis_setup
from ..axis.thermal import heat_balance, series_temperature
from ..chain import friction_torque
from ..design.limits import root_diameter
from ..design.sizing import thermal_elongation
from ..design.stiffness import design_nut_stiffness, reversal_lost_motion
from ..errors import BallScrewInputError, FloatArray
from ..io.machine import LINEAR_AXES, Machine
from ..materials import STANDARD_GRAVITY
from .gcode import ARC, DWELL, Program, read_program
from .planner import Limits, Motion, plan

__all__ = ["AxisResult", "ProgramResult", "Reversal", "heat_balance", "run_program"]

ARC_PLANES = {17: (0, 1), 18: (2, 0), 19: (1, 2)}
"""The in-plane axes (indices of X, Y, Z) of each arc plane."""

MOVING = 1e-9
"""Axis speed below which an axis stands [m/s]."""
LOAD_WINDOW = 0.02
"""Time over which the load on either side of a reversal is averaged [s]."""


@dataclass(frozen=True)
class Reversal:
    """One reversal of an axis (SI)."""

    time: float
    position: float
    load_before: float
    load_after: float
    friction_force: float
    stiffness: float
    lost_motion: float
    line: int

    @property
    def load_direction(self) -> str:
        """The sign of the nut's axial load before and after: '+/+', '+/-', ..."""

        def sign(f: float) -> str:
            return "+" if f > 0 else "-" if f < 0 else "0"

        return f"{sign(self.load_before)}/{sign(self.load_after)}"

    def as_dict(self) -> dict[str, Any]:
        """In the units of the JSON document."""
        return {
            "line": self.line, "time_s": self.time, "position_mm": self.position * 1e3,
            "load_before_N": self.load_before, "load_after_N": self.load_after,
            "load_direction": self.load_direction, "friction_force_N": self.friction_force,
            "stiffness_N_per_um": self.stiffness / 1e6, "lost_motion_um": self.lost_motion * 1e6,
        }  # fmt: skip


@dataclass(frozen=True)
class AxisResult:
    """One axis over the program (SI; energies in J, torques in N·m, temperatures in °C)."""

    letter: str
    title: str
    friction_energy: float
    bearing_energy: float
    supplied_energy: float
    regenerated_energy: float
    process_work: float
    potential_energy: float
    peak_torque: float
    rms_torque: float
    peak_speed: float
    rated_torque: float | None
    peak_rating: float | None
    rated_speed: float | None
    start_temperature: float
    final_temperature: float
    max_temperature: float
    thermal_lead_error: float
    travel: float
    reversals: tuple[Reversal, ...]
    energy_per_block: FloatArray = field(repr=False)
    """Screw friction energy of each block [J]."""
    supplied_per_block: FloatArray = field(repr=False, default_factory=lambda: np.zeros(0))
    """Energy the motor supplies in each block (positive shaft power) [J]."""
    notes: tuple[str, ...] = ()
    drive: DriveEnergy | None = field(default=None, repr=False)
    """Motor, drive and DC link losses and the energy from the grid."""
    distance: float = 0.0
    """Distance the axis moves over the program, both ways counted [m]."""
    feed_distance: float = 0.0
    """Of which in feed blocks (G1, G2, G3), where the process force acts [m]."""
    check: AxisCheck | None = field(default=None, repr=False)
    """``ballscrew check``'s criteria over the program (None: the check refused the axis,
    the reason in ``notes``)."""
    verdicts: tuple[Criterion, ...] = ()
    """The check's rows, and the travel used against the axis's travel."""

    @property
    def verdict(self) -> str:
        """The worst verdict of the rows with a limit; NOT CHECKED without a check."""
        if self.check is None:
            return "NOT CHECKED"
        found = {c.verdict for c in self.verdicts}
        return next((v for v in ("NOT OK", "CHECK") if v in found), "OK")

    @property
    def friction_share(self) -> float:
        """Screw and bearing friction over all the energy the axis turns over [-].

        The energy turned over is where the energy goes: the friction, the
        process work, what the motor takes back, and the potential energy
        stored (a weight lifted). For a horizontal axis that is the energy the
        motor supplies; for a descending vertical axis the weight supplies
        part of it. NaN when nothing moved.
        """
        losses = self.friction_energy + self.bearing_energy
        total = (losses + max(self.process_work, 0.0) + self.regenerated_energy
                 + max(self.potential_energy, 0.0))  # fmt: skip
        return losses / total if total > 0 else math.nan

    def as_dict(self) -> dict[str, Any]:
        """The axis's numbers in the JSON document's units."""
        return {
            "case": self.title,
            "supplied_energy_J": self.supplied_energy,
            "regenerated_energy_J": self.regenerated_energy,
            "process_work_J": self.process_work,
            "potential_energy_J": self.potential_energy,
            "friction_energy_J": self.friction_energy,
            "bearing_energy_J": self.bearing_energy,
            "friction_share": self.friction_share,
            "peak_motor_torque_Nm": self.peak_torque,
            "rms_motor_torque_Nm": self.rms_torque,
            "peak_motor_speed_rpm": self.peak_speed * 30.0 / math.pi,
            "motor_rated_torque_Nm": self.rated_torque,
            "motor_peak_torque_Nm": self.peak_rating,
            "motor_rated_speed_rpm": None
            if self.rated_speed is None
            else self.rated_speed * 30.0 / math.pi,
            "start_temperature_C": self.start_temperature,
            "final_temperature_C": self.final_temperature,
            "max_temperature_C": self.max_temperature,
            "thermal_lead_error_um": self.thermal_lead_error * 1e6,
            "travel_mm": self.travel * 1e3,
            "distance_mm": self.distance * 1e3,
            "feed_distance_mm": self.feed_distance * 1e3,
            "reversals": [r.as_dict() for r in self.reversals],
            "verdict": self.verdict,
            "criteria": [c.as_dict() for c in self.verdicts],
            "notes": list(self.notes),
            **({} if self.drive is None else self.drive.as_dict()),
        }


@dataclass(frozen=True)
class ProgramResult:
    """What ``ballscrew program`` reports.

    Attributes
    ----------
    machine : str
        The machine's title.
    program : Program
        The blocks read.
    motion : Motion
        The planned motion.
    axes : dict
        Letter -> :class:`AxisResult`.
    data : xarray.Dataset
        The time series (dimensions ``time`` and ``axis``), units in each
        variable's ``attrs``.
    notes : tuple of str
        What was skipped or assumed.
    """

    machine: str
    program: Program = field(repr=False)
    motion: Motion = field(repr=False)
    axes: dict[str, AxisResult]
    data: Any = field(repr=False)
    notes: tuple[str, ...] = ()
    inputs: dict[str, Any] = field(default_factory=dict, repr=False)
    """The machine's settings (SI) and the program's SHA-256, carried into the JSON."""

    @property
    def friction_energy(self) -> float:
        """Screw friction of all axes [J]."""
        return sum(a.friction_energy for a in self.axes.values())

    @property
    def supplied_energy(self) -> float:
        """Energy the motors deliver to all axes [J]."""
        return sum(a.supplied_energy for a in self.axes.values())

    def as_dict(self) -> dict[str, Any]:
        """The JSON document of ``ballscrew program --json``."""
        from .._version import __version__

        supplied = self.supplied_energy
        losses = sum(a.friction_energy + a.bearing_energy for a in self.axes.values())
        turned = sum(
            a.friction_energy + a.bearing_energy + max(a.process_work, 0.0)
            + a.regenerated_energy + max(a.potential_energy, 0.0)
            for a in self.axes.values()
        )  # fmt: skip
        return {
            "ballscrew": __version__,
            "machine": self.machine,
            "blocks": self.program.size,
            "program_time_s": self.motion.duration,
            "nominal_time_s": self.motion.nominal_time,
            "samples": int(self.motion.time.size),
            "machine_totals": {
                "supplied_energy_J": supplied,
                "regenerated_energy_J": sum(a.regenerated_energy for a in self.axes.values()),
                "process_work_J": sum(a.process_work for a in self.axes.values()),
                "friction_energy_J": self.friction_energy,
                "bearing_energy_J": sum(a.bearing_energy for a in self.axes.values()),
                "friction_share": losses / turned if turned > 0 else None,
                **drive_totals([a.drive for a in self.axes.values() if a.drive is not None]),
            },
            "axes": {k: a.as_dict() for k, a in self.axes.items()},
            "energy_per_block_J": {
                "line": self.program.line.tolist(),
                "friction": {k: a.energy_per_block.tolist() for k, a in self.axes.items()},
                "supplied": {k: a.supplied_per_block.tolist() for k, a in self.axes.items()},
            },
            "notes": list(self.notes),
            "inputs": self.inputs,
        }


def _inputs(machine: Machine, program: Program) -> dict[str, Any]:
    """What the result was computed from: the machine's settings (SI) and the program's hash."""
    import hashlib

    return {
        "program_sha256": hashlib.sha256(program.text.encode("utf-8")).hexdigest(),
        "model": machine.model,
        "rapid_feed_m_per_s": machine.rapid_feed,
        "path_tolerance_m": machine.path_tolerance,
        "arc_tolerance_m": machine.arc_tolerance,
        "sample_time_s": machine.sample_time,
        "ambient_C": machine.ambient,
        "drive": DriveSpec.from_mapping(machine.drive).as_dict(),
        "axes": {
            k: {"case": a.case.title, "max_feed_m_per_s": a.max_feed,
                "max_acceleration_m_per_s2": a.max_acceleration, "max_jerk_m_per_s3": a.max_jerk,
                "travel_m": list(a.travel), "process_force_N": a.process_force,
                "start_temperature_C": a.start_temperature}
            for k, a in machine.axes.items()
        },
    }  # fmt: skip


def _limits(machine: Machine, program: Program) -> Limits:
    nan = math.nan
    axes = machine.axes
    return Limits(
        feed=np.array([axes[k].max_feed if k in axes else nan for k in LINEAR_AXES]),
        acceleration=np.array(
            [axes[k].max_acceleration if k in axes else nan for k in LINEAR_AXES]
        ),
        jerk=np.array([axes[k].max_jerk if k in axes else nan for k in LINEAR_AXES]),
        rapid_feed=machine.rapid_feed,
        path_tolerance=machine.path_tolerance,
        sample_time=machine.sample_time,
        rotary_feed=_rotary_limit(machine, "max_feed"),
        rotary_acceleration=_rotary_limit(machine, "max_acceleration"),
        rotary_jerk=_rotary_limit(machine, "max_jerk"),
    )


def _rotary_limit(machine: Machine, name: str) -> FloatArray:
    """One limit of A, B, C as :class:`Limits` takes it (NaN: the file gives none)."""
    rotary = machine.rotary
    return np.array([getattr(rotary[k], name) if k in rotary else math.nan for k in "ABC"])


def _check_travel(machine: Machine, program: Program) -> None:
    """Refuse a block past an axis's travel, naming its line; an axis the machine lacks."""
    for i, letter in enumerate(LINEAR_AXES):
        moved = program.kind != 3
        if letter in program.axes and letter not in machine.axes:
            in_plane = np.isin(program.plane, [p for p, axes in ARC_PLANES.items() if i in axes])
            uses = (program.end[:, i] != program.start[:, i]) | ((program.kind == ARC) & in_plane)
            k = int(np.argmax(uses))
            raise BallScrewInputError(
                f"program line {int(program.line[k])}", letter,
                f"an axis of the machine file ({', '.join(machine.axes)})",
            )  # fmt: skip
        if letter not in machine.axes:
            continue
        low, high = machine.axes[letter].travel
        ends = np.concatenate([program.start[moved, i], program.end[moved, i]])
        lines = np.concatenate([program.line[moved], program.line[moved]])
        bad = (ends < low - 1e-12) | (ends > high + 1e-12)
        if np.any(bad):
            k = int(np.argmax(bad))
            raise BallScrewInputError(
                f"program line {int(lines[k])}", f"{letter}{ends[k] * 1e3:g} mm",
                f"within axes.{letter}.travel, {low * 1e3:g} to {high * 1e3:g} mm (machine "
                "coordinates: the program's plus the work offset and, on Z, the tool length)",
            )  # fmt: skip


def _arc_travel(machine: Machine, program: Program, motion: Motion) -> None:
    """Refuse an arc that bulges past an axis's travel (its end points inside)."""
    for i, letter in enumerate(LINEAR_AXES):
        if letter not in machine.axes:
            continue
        low, high = machine.axes[letter].travel
        x = motion.position[:, i]
        bad = (x < low - 1e-9) | (x > high + 1e-9)
        if np.any(bad):
            k = int(np.argmax(bad))
            raise BallScrewInputError(
                f"program line {int(program.line[motion.block[k]])}",
                f"{letter}{x[k] * 1e3:.4g} mm",
                f"within axes.{letter}.travel, {low * 1e3:g} to {high * 1e3:g} mm",
            )  # fmt: skip


def _integral(y: FloatArray, t: FloatArray) -> float:
    """Trapezoidal rule over the samples (a junction's two samples at one time add nothing)."""
    return float(np.sum(0.5 * (y[1:] + y[:-1]) * np.diff(t)))


def _distances(motion: Motion, i: int) -> tuple[float, float]:
    r"""Distance axis ``i`` moves over the program, and of it in feed blocks [m].

    Exact: between two samples an axis moves one way along one phase's
    polynomial (the planner samples every block's both ends and every point
    where an arc's axis turns), so :math:`\int|v|\,dt` over the interval is
    the change of position, :math:`|x_{k+1} - x_k|`.
    """
    step = np.abs(np.diff(motion.position[:, i]))
    return float(np.sum(step)), float(np.sum(step[motion.feeding[:-1]]))


def _profile(motion: Motion, i: int, force: float) -> Profile:
    v = motion.velocity[:, i]
    fp = np.where(motion.feeding & (np.abs(v) > MOVING), force * np.sign(v), 0.0)
    return Profile(motion.time, motion.position[:, i], v, motion.acceleration[:, i], fp)


def _reversals(
    letter: str, setup: AxisSetup, machine: Machine, motion: Motion, program: Program,
    force: FloatArray, temperature: float,
) -> tuple[Reversal, ...]:  # fmt: skip
    """Every change of direction of the axis, with the load across it and the lost motion."""
    i = LINEAR_AXES.index(letter)
    v = motion.velocity[:, i]
    moving = np.flatnonzero(np.abs(v) > MOVING)
    if moving.size < 2:
        return ()
    sign = np.sign(v[moving])
    turn = np.flatnonzero(sign[1:] != sign[:-1])
    if turn.size == 0:
        return ()
    before, after = moving[turn], moving[turn + 1]
    t, x = motion.time, motion.position[:, i]
    # The zero crossing: interpolated where the speed passes through zero between two samples.
    # Else the axis stood between them: the reversal is where it stopped.
    adjacent = after == before + 1
    w = np.abs(v[before]) / (np.abs(v[before]) + np.abs(v[after]))
    stop = np.minimum(before + 1, t.size - 1)
    time = np.where(adjacent, t[before] + w * (t[after] - t[before]), t[stop])
    pos = np.where(adjacent, x[before] + w * (x[after] - x[before]), x[stop])
    ax = machine.axes[letter]
    case = ax.case
    screw = case.screw
    # The load on either side: its mean over LOAD_WINDOW of motion before the last moving
    # sample and after the first (a single sample can sit where a block starts without
    # acceleration).
    integral = np.concatenate([[0.0], np.cumsum(0.5 * (force[1:] + force[:-1]) * np.diff(t))])
    mean_before = (np.interp(t[before], t, integral)
                   - np.interp(t[before] - LOAD_WINDOW, t, integral)) / LOAD_WINDOW  # fmt: skip
    mean_after = (np.interp(t[after] + LOAD_WINDOW, t, integral)
                  - np.interp(t[after], t, integral)) / LOAD_WINDOW  # fmt: skip
    load = 0.5 * (force[before] + force[after])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        t_f = friction_torque(
            screw, case.lubricant, speed=CREEP_SPEED, temperature=temperature,
            axial_load=np.abs(load), model=machine.model, **case.parameters_for(machine.model),
        ).total  # fmt: skip
    span = setup.axis.bearing_span or setup.node.screw_length
    low, high = ax.travel
    # The travel centred between the supports: distance of the nut from the fixed end.
    a = np.clip(0.5 * span + (pos - 0.5 * (low + high)), 1e-3 * span, 0.999 * span)
    unpreloaded = screw.nut == "single" or not screw.preload > 0.0  # stiff only under load
    k_nut = design_nut_stiffness(screw, float(np.max(np.abs(force))) if unpreloaded else 0.0)
    f_f, k, play = reversal_lost_motion(
        np.broadcast_to(t_f, load.shape), screw.lead,
        setup.axis.root_diameter or root_diameter(screw), span, a, setup.axis.support, k_nut,
        case.check.get("support_stiffness"),
    )  # fmt: skip
    lines = program.line[motion.block[after]]
    return tuple(
        Reversal(float(time[n]), float(pos[n]), float(mean_before[n]), float(mean_after[n]),
                 float(f_f[n]), float(k[n]), float(play[n]), int(lines[n]))
        for n in range(time.size)
    )  # fmt: skip


def _one_axis(
    letter: str, machine: Machine, motion: Motion, program: Program,
) -> tuple[AxisResult, dict[str, FloatArray]]:  # fmt: skip
    """One feed axis over the program: its result and its time series.

    The axis's cycle at its start temperature, the heat balance over the program, the
    cycle again at the warmest temperature reached (:func:`_torques_at`), the energies
    per block, the reversals, the drive's losses and ``ballscrew check``'s verdicts.
    """
    ax = machine.axes[letter]
    case = ax.case
    i = LINEAR_AXES.index(letter)
    travel = float(np.ptp(motion.position[:, i]))
    thermal = dict(case.thermal)
    thermal["ambient"] = machine.ambient
    setup = axis_setup(case.screw, case.axis, thermal, max(travel, ax.travel[1] - ax.travel[0]))
    axis, node = setup.axis, setup.node
    profile = _profile(motion, i, ax.process_force)
    params = case.parameters_for(machine.model)
    t0 = ax.start_temperature
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        first = axis_cycle(profile, case.screw, case.lubricant, axis, temperature=t0,
                           model=machine.model, **params)  # fmt: skip
    omega = first.screw_speed
    time = motion.time
    temp, top, t_f, t_m = _heated(time, first, node, case.screw, t0, lambda warm: axis_cycle(
        profile, case.screw, case.lubricant, axis, temperature=warm, model=machine.model,
        **params), axis.gear_ratio)  # fmt: skip
    power = t_f * np.abs(omega)
    shaft = t_m * first.motor_speed
    turned, friction_steps, per_block, supplied_block = _block_energies(
        motion, i, program.size, t_f, shaft, case.screw.lead
    )
    force = first.axial_force
    distance, feed_distance = _distances(motion, i)
    reversals = _reversals(letter, setup, machine, motion, program, force, t0)
    g_axial = STANDARD_GRAVITY * math.sin(axis.incline)
    duration = motion.duration
    motor = case.motor
    notes = [*setup.notes, *first.speed_warnings]
    drive = drive_energy(time, t_m, first.motor_speed, MotorConstants.from_case(motor),
                         DriveSpec.from_mapping(machine.drive), name=f"axes.{letter}")  # fmt: skip
    check = _axis_check(letter, machine, setup, profile, first, duration, top, notes)
    used = _travel_row(letter, ax.travel, travel)
    result = AxisResult(
        letter=letter,
        title=case.title,
        friction_energy=float(np.sum(friction_steps)),
        bearing_energy=float(
            np.sum(0.5 * (first.bearing_torque[1:] + first.bearing_torque[:-1]) * turned)
        ),
        supplied_energy=_integral(np.maximum(shaft, 0.0), time),
        regenerated_energy=-_integral(np.minimum(shaft, 0.0), time),
        # The process force against the motion in every feed block: force x distance.
        process_work=ax.process_force * feed_distance,
        potential_energy=axis.moving_mass
        * g_axial
        * float(profile.position[-1] - profile.position[0]),
        peak_torque=float(np.max(np.abs(t_m))),
        rms_torque=math.sqrt(_integral(t_m**2, time) / duration) if duration > 0 else 0.0,
        peak_speed=float(np.max(np.abs(first.motor_speed))),
        rated_torque=motor.get("rated_torque"),
        peak_rating=motor.get("peak_torque"),
        rated_speed=motor.get("rated_speed"),
        start_temperature=t0,
        final_temperature=float(temp[-1]),
        max_temperature=top,
        thermal_lead_error=float(thermal_elongation(top - t0, travel)),
        travel=travel,
        reversals=reversals,
        energy_per_block=per_block.astype(float),
        supplied_per_block=supplied_block.astype(float),
        notes=tuple(notes),
        drive=drive,
        distance=distance,
        feed_distance=feed_distance,
        check=check,
        verdicts=(*(() if check is None else check.criteria), used),
    )
    series = {
        "friction_torque": t_f,
        "motor_torque": t_m,
        "friction_power": power,
        "temperature": temp,
        "axial_force": force,
        "motor_speed": first.motor_speed,
    }
    return result, series


def _heated(
    time: FloatArray, first: CycleResult, node: Any, screw: Any, start: float,
    again: Callable[[float], CycleResult], gear_ratio: float,
) -> tuple[FloatArray, float, FloatArray, FloatArray]:  # fmt: skip
    """The screw's temperature over the program, its warmest, and the torques it gives.

    The friction and motor torques at each instant's temperature [N·m]: the heat of the
    first cycle's friction and bearings through the thermal node
    (:func:`~ballscrew.axis.thermal.series_temperature`), then the cycle again at the
    warmest temperature (``again(temperature)``) for the torques (:func:`_torques_at`).
    """
    omega = first.screw_speed
    heat = first.friction_torque * np.abs(omega) + first.bearing_torque * np.abs(omega)
    temp = series_temperature(time, heat, node, screw, omega, start)
    top = float(np.max(temp))
    t_f, t_m = _torques_at(temp, first, lambda: again(top), gear_ratio)
    return temp, top, t_f, t_m


def _block_energies(
    motion: Motion, i: int, blocks: int, t_f: FloatArray, shaft: FloatArray, lead: float
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """The screw's angle and friction's work of each step, and per block the work and supply.

    Angles in rad, energies in J: the friction's work and the energy the motor supplies
    (positive shaft power) summed per block. The friction's work over a step is its mean
    torque at the two ends times the screw's angle, which is exact: the axis moves one way
    between two samples.
    """
    turned = np.abs(np.diff(motion.position[:, i])) * 2.0 * math.pi / lead
    friction_steps = 0.5 * (t_f[1:] + t_f[:-1]) * turned
    per_block = np.bincount(motion.block[:-1], weights=friction_steps, minlength=blocks)
    positive = np.maximum(shaft, 0.0)
    supplied_steps = 0.5 * (positive[1:] + positive[:-1]) * np.diff(motion.time)
    supplied_block = np.bincount(motion.block[:-1], weights=supplied_steps, minlength=blocks)
    return turned, friction_steps, per_block.astype(float), supplied_block.astype(float)


def _travel_row(letter: str, limits: tuple[float, float], travel: float) -> Criterion:
    """The travel the program uses against the axis's travel (a verdict row, key ``travel``)."""
    low, high = limits
    return Criterion(
        "travel used", travel * 1e3, (high - low) * 1e3, "mm", travel / (high - low), "OK",
        f"the program's lowest to highest position against axes.{letter}.travel (a block "
        "past it is refused)", key="travel",
    )  # fmt: skip


def _axis_check(
    letter: str, machine: Machine, setup: AxisSetup, profile: Profile, first: CycleResult,
    duration: float, top: float, notes: list[str],
) -> AxisCheck | None:  # fmt: skip
    """``ballscrew check``'s criteria of the axis over the program, at their nominal values.

    :func:`ballscrew.axis.check.run_check` over the program's profile and cycle, the
    program's time as the run time and its warmest screw temperature as the one
    reached (the thermal lead error per 300 mm from the ambient, against the case's
    accuracy grade). An input the check refuses (a span shorter than the travel and
    the nut, a motor without its rotor inertia) leaves the axis unchecked, the reason
    in ``notes``.
    """
    ax = machine.axes[letter]
    case = ax.case
    node = setup.node
    energy = ModelEnergy(first, 1, duration, math.nan, None, final_temperature=top)
    run = EnergyRun(
        case, profile, 1, ax.start_temperature, setup.axis, node,
        {k: getattr(node, k) for k in ("screw_length", "ambient", "machine_resistance",
                                       "nut_mass")},
        list(setup.notes), {}, results={machine.model: energy}, run_time=duration,
        derived=setup.derived,
    )  # fmt: skip
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            return run_check(run, machine.model, draws=False)
    except BallScrewInputError as exc:
        notes.append(f"not checked ({exc})")
        return None


def _torques_at(
    temp: FloatArray, first: CycleResult, warm_cycle: Callable[[], CycleResult], gear: float
) -> tuple[FloatArray, FloatArray]:
    """Friction and motor torque at each instant's temperature [N·m].

    ``first`` is the cycle at the start temperature; where the program warms the screw
    by more than 0.05 K, the friction is interpolated linearly in temperature between it
    and the cycle at the top temperature (``warm_cycle``), and the motor torque follows
    the friction's change through the gear.
    """
    t0, top = float(temp[0]), float(np.max(temp))
    if top - t0 <= 0.05:
        return first.friction_torque, first.motor_torque
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        warm = warm_cycle()
    share = (temp - t0) / (top - t0)
    t_f = first.friction_torque + share * (warm.friction_torque - first.friction_torque)
    t_m = first.motor_torque + np.sign(first.screw_speed) * (t_f - first.friction_torque) / gear
    return t_f, t_m


def run_program(
    machine: Machine,
    program: Program | str,
    *,
    max_blocks: int | None = None,
    max_samples: int | None = None,
    progress: Callable[[str, int, int], None] | None = None,
) -> ProgramResult:
    """Every linear axis of ``machine`` through ``program`` (module docstring).

    Parameters
    ----------
    machine : Machine
        From :func:`ballscrew.io.machine.load_machine`.
    program : Program or str
        The program, read or as text.
    max_blocks : int, optional
        Refuse longer programs (the web page's bound).
    max_samples : int, optional
        Refuse a program of more samples (default: the planner's
        :data:`~ballscrew.program.planner.MAX_SAMPLES`), by its bound before planning,
        else by its count before sampling (:func:`~ballscrew.program.planner.plan`).
    progress : callable, optional
        ``progress(stage, done, total)`` while the blocks are planned.

    Returns
    -------
    ProgramResult
    """
    from ..io.extras import require

    require("program", "ballscrew program")
    if isinstance(program, str):
        program = read_program(program, arc_tolerance=machine.arc_tolerance,
                               max_blocks=max_blocks, machine=machine)  # fmt: skip
    _check_travel(machine, program)
    motion = plan(
        program,
        _limits(machine, program),
        None if progress is None else lambda d, n: progress("plan", d, n),
        **({} if max_samples is None else {"max_samples": max_samples}),
    )
    _arc_travel(machine, program, motion)
    axes: dict[str, AxisResult] = {}
    series: dict[str, dict[str, FloatArray]] = {}
    for n, letter in enumerate(machine.axes):
        if progress is not None:
            progress("axes", n, len(machine.axes))
        try:
            one = _one_axis if motion.time.size > 1 else _axis_at_rest
            axes[letter], series[letter] = one(letter, machine, motion, program)
        except BallScrewInputError as exc:
            if exc.field != "model":
                raise
            raise BallScrewInputError("machine.model", exc.value, exc.allowed) from None
    notes = tuple(program.notes) + _standing_notes(program, motion) + tuple(machine.notes)
    return ProgramResult(machine.title, program, motion, axes,
                         _dataset(machine, motion, series), notes,
                         _inputs(machine, program))  # fmt: skip


def _standing_notes(program: Program, motion: Motion) -> tuple[str, ...]:
    """A note when the program moves no feed axis (empty, or only dwells and tool changes)."""
    if np.any(program.kind != DWELL):
        return ()
    if motion.duration == 0.0:
        return ("the program moves no feed axis and takes no time (no move, no dwell: a "
                "subroutine file or M, S and T words alone): every energy is 0",)  # fmt: skip
    return (f"the program moves no feed axis: the axes stand for its {motion.duration:.6g} s of "
            "dwells and tool changes, no motion energy; a vertical axis holds its weight "
            "(its motor's copper loss counted where the machine file gives the motor's "
            "constants)",)  # fmt: skip


def _axis_at_rest(
    letter: str, machine: Machine, motion: Motion, program: Program,
) -> tuple[AxisResult, dict[str, FloatArray]]:  # fmt: skip
    """One axis through a program that takes no time (:func:`.planner.at_rest`): at rest.

    Every energy is 0; the torques are those holding the axis at its one sample
    (the weight of a vertical axis), from the same cycle computation as a
    dwell's, over a profile standing for a second.
    """
    ax = machine.axes[letter]
    case = ax.case
    i = LINEAR_AXES.index(letter)
    thermal = dict(case.thermal)
    thermal["ambient"] = machine.ambient
    setup = axis_setup(case.screw, case.axis, thermal, ax.travel[1] - ax.travel[0])
    x, zero = float(motion.position[0, i]), np.zeros(2)
    standing = Profile(np.array([0.0, 1.0]), np.full(2, x), zero, zero, zero)
    t0 = ax.start_temperature
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        cycle = axis_cycle(standing, case.screw, case.lubricant, setup.axis, temperature=t0,
                           model=machine.model, **case.parameters_for(machine.model))  # fmt: skip
    t_m, speed = cycle.motor_torque[:1], cycle.motor_speed[:1]
    drive = drive_energy(motion.time, t_m, speed, MotorConstants.from_case(case.motor),
                         DriveSpec.from_mapping(machine.drive), name=f"axes.{letter}")  # fmt: skip
    holding = float(abs(t_m[0]))
    none = np.zeros(program.size)
    result = AxisResult(
        letter=letter, title=case.title, friction_energy=0.0, bearing_energy=0.0,
        supplied_energy=0.0, regenerated_energy=0.0, process_work=0.0, potential_energy=0.0,
        peak_torque=holding, rms_torque=holding, peak_speed=0.0,
        rated_torque=case.motor.get("rated_torque"), peak_rating=case.motor.get("peak_torque"),
        rated_speed=case.motor.get("rated_speed"), start_temperature=t0, final_temperature=t0,
        max_temperature=t0, thermal_lead_error=0.0, travel=0.0, reversals=(),
        energy_per_block=none, supplied_per_block=none.copy(),
        notes=(*setup.notes, "not checked (the program takes no time: no duty to check)"),
        drive=drive,
    )  # fmt: skip
    series = {
        "friction_torque": cycle.friction_torque[:1], "motor_torque": t_m,
        "friction_power": np.zeros(1), "temperature": np.full(1, t0),
        "axial_force": cycle.axial_force[:1], "motor_speed": speed,
    }  # fmt: skip
    return result, series


def _dataset(machine: Machine, motion: Motion, series: dict[str, dict[str, FloatArray]]) -> Any:
    """The time series as an xarray Dataset, units in attrs."""
    import xarray as xr

    letters = list(machine.axes)
    idx = [LINEAR_AXES.index(k) for k in letters]

    def stack(name: str) -> FloatArray:
        return np.stack([series[k][name] for k in letters], axis=1)

    data = {
        "position": (("time", "axis"), motion.position[:, idx], {"units": "m"}),
        "velocity": (("time", "axis"), motion.velocity[:, idx], {"units": "m/s"}),
        "acceleration": (("time", "axis"), motion.acceleration[:, idx], {"units": "m/s^2"}),
        "jerk": (("time", "axis"), motion.jerk[:, idx], {"units": "m/s^3"}),
        "axial_force": (("time", "axis"), stack("axial_force"), {"units": "N"}),
        "friction_torque": (("time", "axis"), stack("friction_torque"), {"units": "N*m"}),
        "motor_torque": (("time", "axis"), stack("motor_torque"), {"units": "N*m"}),
        "motor_speed": (("time", "axis"), stack("motor_speed"), {"units": "rad/s"}),
        "friction_power": (("time", "axis"), stack("friction_power"), {"units": "W"}),
        "temperature": (("time", "axis"), stack("temperature"), {"units": "degC"}),
        "path_speed": (("time",), motion.path_speed, {"units": "m/s"}),
        "block": (("time",), motion.block, {"units": "1", "description": "block index"}),
        "feeding": (("time",), motion.feeding, {"units": "1"}),
    }
    return xr.Dataset(data, coords={"time": ("time", motion.time, {"units": "s"}),
                                    "axis": letters},
                      attrs={"machine": machine.title})  # fmt: skip
