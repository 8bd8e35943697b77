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
whole machine; they are left out of the computation, and :attr:`Machine.notes`
says so. Pydantic validates the structure (unknown keys are errors, so a
misspelt key is named); every problem is one
:class:`~ballscrew.errors.BallScrewInputError` naming the key by its dotted
path (``axes.X.max_jerk``). Values are converted to SI by
:func:`ballscrew.io.units.to_si` at load time.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any

import tomlkit
from pydantic import BaseModel, ConfigDict, Field, ValidationError

from ..design.limits import DEFAULT_DN_LIMIT, MAX_SPEED
from ..errors import BallScrewInputError
from ..plausible import check_acceleration, check_axial_force, check_feed
from .case import Case, parse_case, parse_toml
from .files import read_input_text
from .schema import Assumed
from .units import to_si

__all__ = [
    "EXAMPLE_MACHINE",
    "LINEAR_AXES",
    "ROTARY_AXES",
    "Machine",
    "MachineAxis",
    "example_machine_text",
    "load_machine",
    "parse_machine",
]

LINEAR_AXES = ("X", "Y", "Z")
"""The program letters of the linear axes a machine file may drive with a ball screw."""
ROTARY_AXES = ("A", "B", "C")
"""Rotary axes: accepted in a machine file, left out of the computation (with a note)."""

Value = str | float | int | Assumed


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


class MachineFile(BaseModel):
    """A machine file."""

    model_config = ConfigDict(extra="forbid")
    title: str = "machine"
    description: str = ""
    machine: MachineSection
    axes: dict[str, dict[str, Any]]


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


def parse_machine(
    text: str, *, source: str = "machine", folder: str | Path | None = "."
) -> Machine:
    """Validate a machine file given as TOML text; case paths are relative to ``folder``.

    ``folder`` None: every case must be inline (no file is read). See the module
    docstring for the format.
    """
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
    notes: list[str] = []
    axes: dict[str, MachineAxis] = {}
    for letter in data.axes:
        if letter not in LINEAR_AXES + ROTARY_AXES:
            raise BallScrewInputError(
                f"axes.{letter}", letter, f"a program letter: {', '.join(LINEAR_AXES)} "
                f"(linear) or {', '.join(ROTARY_AXES)} (rotary, left out)",
            )  # fmt: skip
    for letter in ROTARY_AXES:
        if letter in data.axes:
            notes.append(
                f"axes.{letter}: rotary axes are not driven by a ball screw and are left out; "
                f"a program that moves {letter} is refused"
            )
    for letter in LINEAR_AXES:
        if letter not in data.axes:
            continue
        key = f"axes.{letter}"
        try:
            entry = AxisEntry.model_validate(data.axes[letter])
        except ValidationError as exc:
            raise _validation_error(exc, f"{key}.") from None
        if len(entry.travel) != 2:
            raise BallScrewInputError(f"{key}.travel", entry.travel, "[lowest, highest] with units")
        low, high = (_si(f"{key}.travel", v, "m") for v in entry.travel)
        if not (math.isfinite(low) and math.isfinite(high) and low < high):
            raise BallScrewInputError(f"{key}.travel", entry.travel, "lowest < highest")
        if not low <= 0.0 <= high:
            raise BallScrewInputError(f"{key}.travel", entry.travel, "a range that holds 0 mm, "
                                      "where the program starts")  # fmt: skip
        force = _si(f"{key}.process_force", entry.process_force, "N")
        if not (math.isfinite(force) and force >= 0.0):
            raise BallScrewInputError(f"{key}.process_force", entry.process_force, "a force >= 0")
        case = _axis_case(letter, entry.case, None if folder is None else Path(folder))
        feed = _positive(f"{key}.max_feed", entry.max_feed, "m/s")
        acceleration = _positive(f"{key}.max_acceleration", entry.max_acceleration, "m/s**2")
        _held_to_screw(key, entry, case, force, feed, acceleration)
        axes[letter] = MachineAxis(
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
    if not axes:
        raise BallScrewInputError("axes", "(none)", "at least one linear axis (X, Y or Z)")
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
        drive=_drive(m),
    )


def example_machine_text() -> str:
    """The bundled example machine (examples/machine_vmc.toml with every case inline)."""
    return resources.files("ballscrew").joinpath(EXAMPLE_MACHINE).read_text(encoding="utf-8")


EXAMPLE_MACHINE = "data/machine_vmc.toml"
"""The bundled example machine, inside the package."""


def load_machine(path: str | Path) -> Machine:
    """Load a machine file; its cases' paths are relative to its folder."""
    file = Path(path)
    text = read_input_text("--machine", file)
    return parse_machine(text, source=str(file), folder=file.parent)
