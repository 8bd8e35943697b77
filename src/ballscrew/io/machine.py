"""Machine files: the feed axes of a machine tool by program letter, TOML with units.

A machine file names each linear axis by the letter a part program moves it
with (``X``, ``Y``, ``Z``) and gives, per axis, the ball screw case that drives
it (a case file's path, relative to the machine file, or the case inline as a
table), the axis's limits and the process force it feels during feed moves::

    title = "3-axis vertical machining centre"

    [machine]
    rapid_feed = "30 m/min"
    path_tolerance = "0.02 mm"
    ambient = "20 degC"
    drive_efficiency = "96 %"             # or drive_standby_loss, drive_loss_per_ampere, ...
    dc_link = "resistor"                  # or "regenerative", "storage" (dc_link_storage)

    [axes.X]
    case = "x_axis.toml"                  # or an inline [axes.X.case] table
    max_feed = "30 m/min"
    max_acceleration = "3 m/s^2"
    max_jerk = "60 m/s^3"
    travel = ["0 mm", "800 mm"]
    process_force = "600 N"              # against the motion, in G1/G2/G3 moves

The drive keys (:attr:`Machine.drive`) give the loss of every axis's inverter and
what the DC link does with regenerated energy (:mod:`ballscrew.axis.drive`); without
them ``ballscrew program`` leaves the drive loss and the energy from the grid out and
says so.

Rotary axes (``A``, ``B``, ``C``) may be listed so that the file describes the
whole machine. They have no ball screw and are left out of the energy, and
:attr:`Machine.notes` says so; with their ``max_feed``, ``max_acceleration``
and ``max_jerk`` (``"20 rev/min"``, ``"1000 deg/s^2"``) a program may move them
and their moves are timed with those limits. The file may also give the
program's dialect, a tool change time, a tool table, work offsets and
reference positions (:mod:`ballscrew.program.gcode` reads them). Pydantic
validates the structure (unknown keys are errors, so a misspelt key is named);
every problem is one
:class:`~ballscrew.errors.BallScrewInputError` naming the key by its dotted
path (``axes.X.max_jerk``). Values are converted to SI by
:func:`ballscrew.io.units.to_si` at load time.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any

import tomlkit
from pydantic import BaseModel, ConfigDict, Field, ValidationError

from ..design.limits import DEFAULT_DN_LIMIT, MAX_SPEED
from ..errors import BallScrewInputError, check_choice
from ..geometry import nut_length
from ..plausible import check_acceleration, check_axial_force, check_feed
from .case import Case, parse_case, parse_toml
from .files import read_input_text
from .schema import Assumed
from .units import to_si

__all__ = [
    "DIALECTS",
    "EXAMPLE_MACHINE",
    "LINEAR_AXES",
    "ROTARY_AXES",
    "Machine",
    "MachineAxis",
    "RotaryAxis",
    "example_machine_text",
    "load_machine",
    "parse_machine",
]

LINEAR_AXES = ("X", "Y", "Z")
"""The program letters of the linear axes a machine file may drive with a ball screw."""
ROTARY_AXES = ("A", "B", "C")
"""Rotary axes: accepted in a machine file, left out of the computation (with a note)."""

Value = str | float | int | Assumed

DIALECTS = ("rs274", "fanuc", "sinumerik")
"""The programs' dialects (``[machine] dialect``)."""
WORK_OFFSETS = ("G54", "G55", "G56", "G57", "G58", "G59")
"""The work offsets a machine file may give (``[offsets]``)."""


class MachineSection(BaseModel):
    """``[machine]``: interpolation settings, temperatures and the friction model."""

    model_config = ConfigDict(extra="forbid")
    rapid_feed: Value = Field(description="path speed of G0 moves (each axis's max_feed caps it)")
    path_tolerance: Value = Field(
        default="0.01 mm",
        description="largest deviation from the programmed corner a junction may blend over",
    )
    arc_tolerance: Value = Field(
        default="0.002 mm",
        description="largest difference of an arc's start and end radii (also 0.1 % of R)",
    )
    ambient: Value = Field(default="20 degC", description="air and machine temperature")
    start_temperature: Value | None = Field(
        default=None, description="screw and nut temperature at the start (default: ambient)"
    )
    sample_time: Value = Field(
        default="5 ms", description="longest time between two samples of the motion"
    )
    model: str = Field(default="complete", description="friction model of every axis")
    dialect: str = Field(
        default="rs274", description="the program's dialect: rs274, fanuc or sinumerik"
    )
    tool_change_time: Value | None = Field(
        default=None, description="time of a tool change (M6), the feed axes still"
    )
    drive_efficiency: Value | None = Field(
        default=None, description="the inverter's efficiency, motoring and regenerating"
    )
    drive_standby_loss: Value | None = Field(
        default=None, description="the inverter's loss at no current (control, fans), per axis"
    )
    drive_loss_per_ampere: Value | None = Field(
        default=None, description="the inverter's loss per ampere rms of motor current (V)"
    )
    drive_loss_resistance: Value | None = Field(
        default=None, description="the inverter's loss per ampere squared (ohm)"
    )
    dc_link: str | Assumed | None = Field(
        default=None,
        description="what the DC link does with regenerated energy: regenerative, resistor, "
        "storage",
    )
    dc_link_storage: Value | None = Field(
        default=None, description="usable energy of the DC link's storage (dc_link = storage)"
    )
    dc_link_shared: bool = Field(
        default=False, description="whether the axes share one DC link (one supply module)"
    )


class AxisEntry(BaseModel):
    """``[axes.X]``: one linear axis."""

    model_config = ConfigDict(extra="forbid")
    case: str | dict[str, Any] = Field(description="case file path, or the case inline")
    max_feed: Value = Field(description="largest axis speed")
    max_acceleration: Value = Field(description="largest axis acceleration")
    max_jerk: Value = Field(description="largest axis jerk")
    travel: list[Value] = Field(description="[lowest, highest] position the axis may reach")
    process_force: Value = Field(
        default="0 N", description="axial force against the motion during feed moves"
    )
    start_temperature: Value | None = Field(
        default=None, description="this screw's temperature at the start"
    )


class RotaryEntry(BaseModel):
    """``[axes.A]``: a rotary axis (no ball screw); with its limits, its moves are timed."""

    model_config = ConfigDict(extra="forbid")
    max_feed: Value | None = Field(default=None, description="largest angular speed")
    max_acceleration: Value | None = Field(default=None, description="largest angular acc.")
    max_jerk: Value | None = Field(default=None, description="largest angular jerk")
    note: str = ""
    description: str = ""


class MachineFile(BaseModel):
    """A machine file."""

    model_config = ConfigDict(extra="forbid")
    title: str = "machine"
    description: str = ""
    machine: MachineSection
    axes: dict[str, dict[str, Any]]
    tools: dict[str, Value] = Field(default_factory=dict, description="T<n> = tool length")
    offsets: dict[str, dict[str, Value]] = Field(
        default_factory=dict, description="G54 to G59: the part zero in machine coordinates"
    )
    reference: dict[str, dict[str, Value]] = Field(
        default_factory=dict, description="G28, G30: the reference positions, machine coordinates"
    )


@dataclass(frozen=True)
class MachineAxis:
    """One linear axis of a machine (SI: m, m/s, m/s², m/s³, N, °C).

    Attributes
    ----------
    letter : str
        The program letter (X, Y or Z).
    case : Case
        The ball screw, lubricant, ``[axis]`` and ``[motor]`` of the axis.
    max_feed, max_acceleration, max_jerk : float
        The axis's limits [m/s, m/s², m/s³].
    travel : tuple of float
        Lowest and highest position [m] the program may reach.
    process_force : float
        Axial force [N] against the axis's motion while it moves in a feed
        block (G1, G2, G3); none in rapids.
    start_temperature : float
        Screw and nut temperature at the program's start [°C].
    """

    letter: str
    case: Case
    max_feed: float
    max_acceleration: float
    max_jerk: float
    travel: tuple[float, float]
    process_force: float
    start_temperature: float


@dataclass(frozen=True)
class RotaryAxis:
    """A rotary axis's limits (SI: rad/s, rad/s², rad/s³): they time its moves."""

    letter: str
    max_feed: float
    max_acceleration: float
    max_jerk: float


@dataclass(frozen=True)
class Machine:
    """A loaded machine file.

    Attributes
    ----------
    title : str
        Label of reports.
    axes : dict
        Letter -> :class:`MachineAxis`, the linear axes in the order X, Y, Z.
    rapid_feed : float
        Path speed of G0 [m/s].
    path_tolerance : float
        Junction blend tolerance [m].
    arc_tolerance : float
        Arc radius mismatch tolerance [m].
    ambient : float
        [°C].
    sample_time : float
        Longest time between samples [s].
    model : str
        Friction model name.
    dialect : str
        The programs' dialect: ``rs274`` (RS274/NGC, LinuxCNC), ``fanuc`` or
        ``sinumerik``.
    tool_change_time : float or None
        Time of a tool change M6 [s] (None: not given; a program with M6 is refused).
    tools : dict
        Tool number -> tool length [m] (``[tools] T1 = "85 mm"``), for G43 H.
    offsets : dict
        Work offset code (54 to 59) -> letter -> the part zero in machine coordinates [m].
    reference : dict
        28 or 30 -> letter -> reference position in machine coordinates [m].
    rotary : dict
        Letter -> :class:`RotaryAxis`, the rotary axes whose limits the file gives.
    notes : tuple of str
        What was left out (rotary axes).
    text : str
        The TOML text read.
    drive : dict
        The drives' loss and DC link, SI, the keys given: ``efficiency`` [-] or the
        loss model's ``standby`` [W], ``per_ampere`` [V], ``resistance`` [Ω];
        ``dc_link`` (``"regenerative"``, ``"resistor"``, ``"storage"``) and
        ``storage`` [J], ``shared`` (:class:`ballscrew.axis.drive.DriveSpec`).
    """

    title: str
    axes: dict[str, MachineAxis]
    rapid_feed: float
    path_tolerance: float
    arc_tolerance: float
    ambient: float
    sample_time: float
    model: str
    notes: tuple[str, ...] = ()
    text: str = field(default="", repr=False)
    dialect: str = "rs274"
    tool_change_time: float | None = None
    tools: dict[int, float] = field(default_factory=dict)
    offsets: dict[int, dict[str, float]] = field(default_factory=dict)
    reference: dict[int, dict[str, float]] = field(default_factory=dict)
    rotary: dict[str, RotaryAxis] = field(default_factory=dict)
    drive: dict[str, Any] = field(default_factory=dict)


DC_LINKS = ("regenerative", "resistor", "storage")
"""The choices of ``[machine] dc_link`` (as :data:`ballscrew.axis.drive.DC_LINKS`)."""


def _drive(m: MachineSection) -> dict[str, Any]:
    """``[machine]``'s drive keys in SI (:attr:`Machine.drive`)."""
    out: dict[str, Any] = {}
    model = (("standby", "drive_standby_loss", m.drive_standby_loss, "W"),
             ("per_ampere", "drive_loss_per_ampere", m.drive_loss_per_ampere, "V"),
             ("resistance", "drive_loss_resistance", m.drive_loss_resistance, "ohm"))  # fmt: skip
    for key, name, raw, unit in model:
        if raw is None:
            continue
        out[key] = _si(f"machine.{name}", raw, unit)
        if not (math.isfinite(out[key]) and out[key] >= 0.0):
            raise BallScrewInputError(f"machine.{name}", _typed(raw), f"a value >= 0 ({unit})")
    if m.drive_efficiency is not None:
        if out:
            raise BallScrewInputError(
                "machine.drive_efficiency", _typed(m.drive_efficiency),
                "either an efficiency or the loss model (drive_standby_loss, "
                "drive_loss_per_ampere, drive_loss_resistance), not both",
            )  # fmt: skip
        eta = _si("machine.drive_efficiency", m.drive_efficiency, "")
        if not (math.isfinite(eta) and 0.5 <= eta <= 1.0):
            raise BallScrewInputError(
                "machine.drive_efficiency",
                _typed(m.drive_efficiency),
                "a share from 50 to 100 % (servo drives: 95 to 98 %)",
            )
        out["efficiency"] = eta
    link = None if m.dc_link is None else _typed(m.dc_link)
    if link is not None:
        if link not in DC_LINKS:
            raise BallScrewInputError("machine.dc_link", link, f"one of {', '.join(DC_LINKS)}")
        out["dc_link"] = link
    if (link == "storage") != (m.dc_link_storage is not None):
        raise BallScrewInputError(
            "machine.dc_link_storage", "(missing)" if m.dc_link_storage is None
            else _typed(m.dc_link_storage),
            "the storage's usable energy (e.g. '300 J') with dc_link = \"storage\", and only "
            "with it",
        )  # fmt: skip
    if m.dc_link_shared:
        if link is None:
            raise BallScrewInputError(
                "machine.dc_link_shared", "true", "given with machine.dc_link, the link they share"
            )
        out["shared"] = True
    if m.dc_link_storage is not None:
        out["storage"] = _si("machine.dc_link_storage", m.dc_link_storage, "J")
        if not (math.isfinite(out["storage"]) and out["storage"] >= 0.0):
            raise BallScrewInputError("machine.dc_link_storage", _typed(m.dc_link_storage),
                                      "an energy >= 0 J")  # fmt: skip
    return out


def _si(name: str, raw: Any, unit: str) -> float:
    value = raw.value if isinstance(raw, Assumed) else raw
    return to_si(name, value, unit)


def _positive(name: str, raw: Any, unit: str) -> float:
    value = _si(name, raw, unit)
    if not (math.isfinite(value) and value > 0.0):
        raise BallScrewInputError(name, raw, f"a value > 0 with its unit ({unit})")
    return value


def _validation_error(exc: ValidationError, prefix: str = "") -> BallScrewInputError:
    err = next((e for e in exc.errors() if e["type"] == "extra_forbidden"), exc.errors()[0])
    parts = [
        str(p) for p in err["loc"]
        if not str(p).startswith(("function-", "_")) and str(p) not in
        {"str", "float", "int", "Assumed", "dict[str,any]"}
    ]  # fmt: skip
    name = prefix + ".".join(parts) or "machine file"
    allowed = {
        "missing": "a value (the key is required)",
        "extra_forbidden": "no such key (check the spelling)",
    }.get(err["type"], err["msg"])
    value = "(missing)" if err["type"] == "missing" else err.get("input", "")
    return BallScrewInputError(name, value, allowed)


def _axis_case(letter: str, raw: str | dict[str, Any], folder: Path | None) -> Case:
    """The axis's case: a file relative to the machine file, or the inline table."""
    name = f"axes.{letter}.case"
    if isinstance(raw, str) and folder is None:
        allowed = f"the case inline, as an [{name}] table (the web page reads no file)"
        raise BallScrewInputError(name, raw, allowed)
    if isinstance(raw, str):
        assert folder is not None
        path = Path(raw) if Path(raw).is_absolute() else folder / raw
        text = read_input_text(name, path)  # a regular UTF-8 file: no pipe, no device
        source = str(path)
    else:
        text = tomlkit.dumps(raw)
        source = name
    try:
        return parse_case(text, source=source)
    except BallScrewInputError as exc:
        raise BallScrewInputError(f"{name}: {exc.field}", exc.value, exc.allowed) from None


def _typed(raw: Any) -> str:
    """A value as the file wrote it (an assumed value's own text)."""
    return str(raw.value if isinstance(raw, Assumed) else raw)


def _held_to_screw(
    key: str, entry: AxisEntry, case: Case, force: float, feed: float, acceleration: float
) -> None:
    """An axis' limits and process force held to its screw (:mod:`ballscrew.plausible`).

    The process force and the moving mass at the acceleration against the static
    rating C_0a, the feed against the models' largest speed (the d·n limit is told of
    the moves that reach it, when the program runs).
    """
    c0 = case.load_ratings().static
    check_axial_force(f"{key}.process_force", _typed(entry.process_force), force, c0)
    check_acceleration(f"{key}.max_acceleration", _typed(entry.max_acceleration), acceleration,
                       case.axis.get("moving_mass", 0.0), c0)  # fmt: skip
    check_feed(f"{key}.max_feed", _typed(entry.max_feed), feed, case.screw.lead,
               case.screw.pitch_diameter, case.axis.get("dn_limit", DEFAULT_DN_LIMIT),
               MAX_SPEED, warn_above=False)  # fmt: skip


def _travel_on_screw(key: str, entry: AxisEntry, case: Case, travel: float) -> None:
    """Refuse a travel the nut cannot make between the screw's supports.

    The nut's threaded length (:func:`ballscrew.geometry.nut_length`) and the travel
    must fit in the bearing span (else the screw's length): past it the nut would run
    off the thread, as ``ballscrew check`` refuses a stroke that does not fit.
    """
    span = case.axis.get("bearing_span") or case.thermal.get("screw_length")
    if not span:
        return
    nut = nut_length(case.screw)
    if travel + nut >= span:
        where = "axis.bearing_span" if case.axis.get("bearing_span") else "axis.screw_length"
        raise BallScrewInputError(
            f"{key}.travel", str([_typed(v) for v in entry.travel]),
            f"a travel the nut can make on its screw: less than {(span - nut) * 1e3:.4g} mm "
            f"({where} {span * 1e3:.4g} mm less the nut's {nut * 1e3:.4g} mm; the travel "
            f"read is {travel * 1e3:.4g} mm)",
        )  # fmt: skip


def parse_machine(
    text: str, *, source: str = "machine", folder: str | Path | None = "."
) -> Machine:
    """Validate a machine file given as TOML text; case paths are relative to ``folder``.

    ``folder`` None: every case must be inline (no file is read). See the module
    docstring for the format.
    """
    text = text.removeprefix("\ufeff")  # kept as Machine.text, which tomlkit re-reads
    raw = parse_toml(text, source)
    try:
        data = MachineFile.model_validate(raw)
    except ValidationError as exc:
        raise _validation_error(exc) from None
    m = data.machine
    ambient = _si("machine.ambient", m.ambient, "degC")
    start = (
        ambient
        if m.start_temperature is None
        else _si("machine.start_temperature", m.start_temperature, "degC")
    )
    rotary, notes = _rotary_axes(data.axes)
    axes: dict[str, MachineAxis] = {}
    for letter in LINEAR_AXES:
        if letter in data.axes:
            axes[letter] = _linear_axis(letter, data.axes[letter], folder, start)
    if not axes:
        raise BallScrewInputError("axes", "(none)", "at least one linear axis (X, Y or Z)")
    tools, offsets, reference = _tables(data, axes)
    change = _tool_change_time(m)
    return Machine(
        title=data.title,
        axes=axes,
        rapid_feed=_positive("machine.rapid_feed", m.rapid_feed, "m/s"),
        path_tolerance=_positive("machine.path_tolerance", m.path_tolerance, "m"),
        arc_tolerance=_positive("machine.arc_tolerance", m.arc_tolerance, "m"),
        ambient=ambient,
        sample_time=_positive("machine.sample_time", m.sample_time, "s"),
        model=m.model,
        notes=tuple(notes),
        text=text,
        dialect=check_choice("machine.dialect", m.dialect, DIALECTS),
        tool_change_time=change,
        tools=tools,
        offsets=offsets,
        reference=reference,
        rotary=rotary,
        drive=_drive(m),
    )


def _rotary_axes(
    raw_axes: dict[str, dict[str, Any]],
) -> tuple[dict[str, RotaryAxis], list[str]]:
    """The file's rotary axes with their limits, and the notes on them.

    Refuses first any ``[axes.*]`` letter that is neither linear nor rotary. A
    rotary axis without limits is noted and left out (a program moving it is
    refused later); one with them is timed but carries no ball-screw energy.
    """
    notes: list[str] = []
    for letter in raw_axes:
        if letter not in LINEAR_AXES + ROTARY_AXES:
            raise BallScrewInputError(
                f"axes.{letter}", letter, f"a program letter: {', '.join(LINEAR_AXES)} "
                f"(linear) or {', '.join(ROTARY_AXES)} (rotary, left out)",
            )  # fmt: skip
    rotary: dict[str, RotaryAxis] = {}
    for letter in ROTARY_AXES:
        if letter in raw_axes:
            limits = _rotary(letter, raw_axes[letter])
            if limits is None:
                notes.append(
                    f"axes.{letter}: a rotary axis, not driven by a ball screw; without its "
                    f"max_feed, max_acceleration and max_jerk a program that moves {letter} "
                    "is refused"
                )
            else:
                rotary[letter] = limits
                notes.append(
                    f"axes.{letter}: a rotary axis, not driven by a ball screw: its moves are "
                    "timed with its limits and left out of the ball-screw energy"
                )
    return rotary, notes


def _as_typed(values: list[Any]) -> str:
    """A TOML list of quantities as the file writes it: '["600 mm", "0 mm"]'."""
    shown = (getattr(v, "value", v) for v in values)
    return "[" + ", ".join(f'"{v}"' if isinstance(v, str) else str(v) for v in shown) + "]"


def _linear_axis(
    letter: str, raw: dict[str, Any], folder: str | Path | None, start: float
) -> MachineAxis:
    """One linear ``[axes.X]`` table validated into SI, its case read from ``folder``.

    ``start`` is the machine's start temperature [°C], used when the axis gives
    none. The travel must hold 0 (where the program starts), the process force
    be >= 0, and the axis's limits be within what its screw and motor hold.
    """
    key = f"axes.{letter}"
    try:
        entry = AxisEntry.model_validate(raw)
    except ValidationError as exc:
        raise _validation_error(exc, f"{key}.") from None
    typed = _as_typed(entry.travel)  # the list as the file writes it, not "array of shape"
    if len(entry.travel) != 2:
        raise BallScrewInputError(f"{key}.travel", typed, "[lowest, highest] with units")
    low, high = (_si(f"{key}.travel", v, "m") for v in entry.travel)
    if not (math.isfinite(low) and math.isfinite(high) and low < high):
        raise BallScrewInputError(f"{key}.travel", typed, "[lowest, highest]: lowest < highest")
    if not low <= 0.0 <= high:
        raise BallScrewInputError(f"{key}.travel", typed, "a range that holds 0 mm, "
                                  "where the program starts")  # fmt: skip
    force = _si(f"{key}.process_force", entry.process_force, "N")
    if not (math.isfinite(force) and force >= 0.0):
        raise BallScrewInputError(f"{key}.process_force", entry.process_force, "a force >= 0")
    case = _axis_case(letter, entry.case, None if folder is None else Path(folder))
    feed = _positive(f"{key}.max_feed", entry.max_feed, "m/s")
    acceleration = _positive(f"{key}.max_acceleration", entry.max_acceleration, "m/s**2")
    _held_to_screw(key, entry, case, force, feed, acceleration)
    _travel_on_screw(key, entry, case, high - low)
    return MachineAxis(
        letter=letter,
        case=case,
        max_feed=feed,
        max_acceleration=acceleration,
        max_jerk=_positive(f"{key}.max_jerk", entry.max_jerk, "m/s**3"),
        travel=(low, high),
        process_force=force,
        start_temperature=start
        if entry.start_temperature is None
        else _si(f"{key}.start_temperature", entry.start_temperature, "degC"),
    )


def _tool_change_time(m: MachineSection) -> float | None:
    """``machine.tool_change_time`` in s (>= 0), or None when the file gives none."""
    change = (
        None
        if m.tool_change_time is None
        else _si("machine.tool_change_time", m.tool_change_time, "s")
    )
    if change is not None and not (math.isfinite(change) and change >= 0.0):
        raise BallScrewInputError("machine.tool_change_time", m.tool_change_time,
                                  "a time >= 0 with its unit (s)")  # fmt: skip
    return change


def _rotary(letter: str, raw: dict[str, Any]) -> RotaryAxis | None:
    """A rotary axis's limits in SI; None when the file gives none of them."""
    key = f"axes.{letter}"
    try:
        entry = RotaryEntry.model_validate(raw)
    except ValidationError as exc:
        raise _validation_error(exc, f"{key}.") from None
    given = {
        "max_feed": (entry.max_feed, "rad/s"),
        "max_acceleration": (entry.max_acceleration, "rad/s**2"),
        "max_jerk": (entry.max_jerk, "rad/s**3"),
    }
    if all(v is None for v, _ in given.values()):
        return None
    values: dict[str, float] = {}
    for name, (value, unit) in given.items():
        if value is None:
            raise BallScrewInputError(f"{key}.{name}", "(missing)", "all three of max_feed, "
                                      "max_acceleration and max_jerk, or none")  # fmt: skip
        values[name] = _positive(f"{key}.{name}", value, unit)
    return RotaryAxis(letter=letter, **values)


def _tables(
    data: MachineFile, axes: dict[str, MachineAxis]
) -> tuple[dict[int, float], dict[int, dict[str, float]], dict[int, dict[str, float]]]:
    """``[tools]``, ``[offsets]`` and ``[reference]`` in SI, keys checked."""
    tools: dict[int, float] = {}
    for key, raw in data.tools.items():
        if re.fullmatch(r"T\d{1,4}", key) is None:
            raise BallScrewInputError(f"tools.{key}", key, "a tool number such as T1")
        length = _si(f"tools.{key}", raw, "m")
        if not math.isfinite(length):
            raise BallScrewInputError(f"tools.{key}", raw, "a tool length with its unit")
        if length < 0.0:  # a length, gauge line to tip; not an H register's signed offset
            raise BallScrewInputError(
                f"tools.{key}", getattr(raw, "value", raw),
                "a tool length of 0 or more: the spindle's gauge line to the tip (a "
                "controller's negative H offset, measured from elsewhere, is not this)",
            )  # fmt: skip
        tools[int(key[1:])] = length
    offsets: dict[int, dict[str, float]] = {}
    for key, table in data.offsets.items():
        if key not in WORK_OFFSETS:
            raise BallScrewInputError(f"offsets.{key}", key, f"one of {', '.join(WORK_OFFSETS)}")
        offsets[int(key[1:])] = _positions(f"offsets.{key}", table, axes, inside=False)
    reference: dict[int, dict[str, float]] = {}
    for key, table in data.reference.items():
        if key not in ("G28", "G30"):
            raise BallScrewInputError(f"reference.{key}", key, "G28 or G30")
        reference[int(key[1:])] = _positions(f"reference.{key}", table, axes, inside=True)
    return tools, offsets, reference


def _positions(
    name: str, table: dict[str, Any], axes: dict[str, MachineAxis], *, inside: bool
) -> dict[str, float]:
    """A position per linear axis of the machine [m]; within the travel when ``inside``."""
    out: dict[str, float] = {}
    for letter in table:
        if letter not in axes:
            allowed = f"an axis of the machine file ({', '.join(axes)})"
            raise BallScrewInputError(f"{name}.{letter}", table[letter], allowed)
    for letter, axis in axes.items():
        if letter not in table:
            raise BallScrewInputError(f"{name}.{letter}", "(missing)",
                                      f"a position for every axis ({', '.join(axes)})")  # fmt: skip
        value = _si(f"{name}.{letter}", table[letter], "m")
        low, high = axis.travel
        if not math.isfinite(value) or (inside and not low <= value <= high):
            raise BallScrewInputError(
                f"{name}.{letter}", table[letter],
                f"a position within axes.{letter}.travel, {low * 1e3:g} to {high * 1e3:g} mm"
                if inside else "a finite length with its unit",
            )  # fmt: skip
        out[letter] = value
    return out


def example_machine_text() -> str:
    """The bundled example machine (examples/machine_vmc.toml with every case inline)."""
    return resources.files("ballscrew").joinpath(EXAMPLE_MACHINE).read_text(encoding="utf-8")


EXAMPLE_MACHINE = "data/machine_vmc.toml"
"""The bundled example machine, inside the package."""


def load_machine(path: str | Path) -> Machine:
    """Load a machine file; its cases' paths are relative to its folder."""
    file = Path(path)
    text = read_input_text("--machine", file)
    if not text.strip():  # a failed copy or export: not "machine missing"
        raise BallScrewInputError(
            "--machine", str(file), "a machine file with its [machine] and [axes.X] tables "
            "(this file is empty; examples/machine_vmc.toml is one to start from)",
        )  # fmt: skip
    return parse_machine(text, source=str(file), folder=file.parent)
