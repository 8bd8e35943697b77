"""The schema of case files: every key, its unit, default and meaning, in one place.

The pydantic models below validate a case file's structure (unknown keys are
errors, so a misspelt key is named); their field descriptions, units and
examples also generate the commented template (:func:`template`, ``ballscrew
case --template``) and the reference table of the documentation
(:func:`reference_rows`, ``ballscrew case --reference``), so that the three
cannot drift apart. :mod:`ballscrew.io.case` turns a validated file into SI
values and objects.
"""

from __future__ import annotations

import json
from dataclasses import dataclass
from typing import Any, Literal

from pydantic import BaseModel, ConfigDict, Field
from pydantic.fields import FieldInfo

__all__ = [
    "Assumed",
    "CaseFile",
    "LubricantSection",
    "ReferenceRow",
    "reference_markdown",
    "reference_rows",
    "si_units",
    "template",
]


class Assumed(BaseModel):
    """A value marked as assumed: ``{ value = "20 mm", assumed = "why" }``."""

    model_config = ConfigDict(extra="forbid")
    value: str | float | int
    assumed: str = Field(min_length=1)
    tolerance: str | None = None
    """A range the assumed value may lie in, +- as a share (``"10 %"``): ``ballscrew check``
    draws the moving mass, the preload and the load ratings from it when ``[check]`` states
    no tolerance of its own."""


Value = str | float | int | Assumed


def _f(
    default: Any,
    unit: str,
    text: str,
    example: Any = None,
    *,
    fill: bool = False,
    si: str | None = None,
    group: str | None = None,
    **kwargs: Any,
) -> Any:
    """A field with its unit (``"-"`` for a number) and an example value.

    ``fill``: an optional key that the template writes filled in (one of a
    pair of which exactly one is needed). ``si``: the SI unit the key's value is
    read in (``""`` for a plain number), for the keys :mod:`ballscrew.io.case` turns
    into numbers by :func:`si_units`; ``group`` sets some of a section's keys apart
    (``"thermal"``: the thermal keys of ``[axis]``).
    """
    extra: dict[str, Any] = {
        "unit": unit, "example": example if example is not None else default, "fill": fill,
    }  # fmt: skip
    if si is not None:
        extra["si"] = si
    if group is not None:
        extra["group"] = group
    if default is ...:
        return Field(description=text, json_schema_extra=extra, **kwargs)
    return Field(default=default, description=text, json_schema_extra=extra, **kwargs)


class ScrewSection(BaseModel):
    """``[screw]``: geometry, preload, materials and roughness."""

    model_config = ConfigDict(extra="forbid")
    designation: str | Assumed | None = _f(
        None,
        "-",
        "a catalogue nut ('HIWIN R40-10K5-FDC', see ballscrew screws) or a size in mm "
        "('40x10 double 2.5x2 6.35'); keys given below override what it gives",
        "HIWIN R40-10K5-FDC",
    )
    pitch_diameter: Value | None = _f(
        None,
        "length",
        "diameter through the ball centres d_m (required unless the designation gives it)",
        "40 mm",
        fill=True,
        si="m",
    )
    lead: Value | None = _f(
        None,
        "length",
        "axial advance per screw revolution (required unless the designation gives it)",
        "10 mm",
        fill=True,
        si="m/turn",
    )
    ball_diameter: Value | None = _f(
        None,
        "length",
        "ball diameter D_w (required unless the designation gives it)",
        "6.35 mm",
        fill=True,
        si="m",
    )
    contact_angle: Value = _f("45 deg", "angle", "nominal contact angle", si="rad")
    conformity_screw: Value = _f(0.55, "-", "screw groove radius / ball diameter (> 0.5)", si="")
    conformity_nut: Value = _f(0.55, "-", "nut groove radius / ball diameter (> 0.5)", si="")
    loaded_turns: Value = _f(2.5, "-", "loaded turns per circuit", si="")
    circuits: Value = _f(2, "-", "ball circuits per nut (per half-nut for a double nut)", si="")
    # Left out (None): BallScrew's own defaults apply (one place for them).
    nut: Literal["double", "single", "single-4point"] | Assumed | None = _f(
        None,
        "-",
        'nut arrangement: "double" (two half-nuts or a lead offset), "single" (no '
        'preload) or "single-4point" (oversize balls); default "double"',
        "double",
    )
    ball_separation: Literal["none", "spacer-balls", "cage"] | Assumed | None = _f(
        None,
        "-",
        'how the balls are kept apart: "none" (a full ball train, most nuts), "spacer-balls" '
        '(a spacer between every two load balls) or "cage" (a ball retainer); default "none"',
        "none",
    )
    preload: Value | None = _f(
        None,
        "force",
        "axial preload force (give this, preload_drag_torque or preload_share; none for a "
        "single nut, which holds none)",
        "2 kN",
        fill=True,
    )
    preload_drag_torque: Value | None = _f(
        None,
        "torque",
        "catalogue drag torque of the preload, turned into a preload by the catalogue rule "
        "(give this or preload)",
        "0.4 N*m",
    )
    preload_share: Value | None = _f(
        None,
        "-",
        "preload as a share of the dynamic load rating, e.g. '5 %' (give this, preload or "
        "preload_drag_torque)",
        "5 %",
    )
    dynamic_load_rating: Value | None = _f(
        None,
        "force",
        "dynamic load rating C_a, for preload_share, the plausibility rules and the life of "
        "ballscrew check (default: the designation's catalogue value)",
        "63.4 kN",
    )
    static_load_rating: Value | None = _f(
        None,
        "force",
        "static load rating C_0a, which loads are checked against and the static safety of "
        "ballscrew check (default: the designation's catalogue value, else estimated from the "
        "geometry by ISO 3408-5's 4200 MPa)",
        "184 kN",
    )
    youngs_modulus_ball: Value | None = _f(None, "pressure", "default 210 GPa", "210 GPa", si="Pa")
    youngs_modulus_races: Value | None = _f(None, "pressure", "default 210 GPa", "210 GPa", si="Pa")
    poisson_ratio_ball: Value | None = _f(None, "-", "default 0.3", 0.3, si="")
    poisson_ratio_races: Value | None = _f(None, "-", "default 0.3", 0.3, si="")
    roughness_ball: Value | None = _f(
        None, "length", "RMS roughness, default 0.08 um", "0.08 um", si="m"
    )
    roughness_screw: Value | None = _f(
        None, "length", "RMS roughness, default 0.3 um", "0.3 um", si="m"
    )
    roughness_nut: Value | None = _f(
        None, "length", "RMS roughness, default 0.3 um", "0.3 um", si="m"
    )
    wiper_drag: Value | None = _f(
        None,
        "torque",
        "drag torque of the nut's wipers or seals, added by the models with a seal term (complete: "
        "its 'seals' component); the others leave it out with a note (none: no wipers, as "
        "catalogue drag torques are measured)",
        "0.05 N*m",
    )
    contact_angle_scatter: Value | None = _f(
        None,
        "angle",
        "standard deviation of the balls' effective contact angles (a product tolerance); given, "
        "the complete model takes its ball train from it (ball_train 'tolerance'); default: "
        "the fitted ratio of the ball-train force to the ball load",
        "0.3 deg",
    )


class LubricantSection(BaseModel):
    """``[lubricant]``: a bundled oil by name, or your own (nu40, nu100 and density15)."""

    model_config = ConfigDict(extra="forbid")
    name: str | Assumed = _f(
        ...,
        "-",
        "a bundled lubricant (ballscrew lubricants) or a name for your own",
        "PAO ISO VG 68",
    )
    nu40: Value | None = _f(
        None,
        "kinematic viscosity",
        "your oil: viscosity at 40 °C (with nu100, density15)",
        "68 cSt",
        si="m**2/s",
    )
    nu100: Value | None = _f(
        None, "kinematic viscosity", "your oil: viscosity at 100 °C", "10.3 cSt", si="m**2/s"
    )
    density15: Value | None = _f(
        None, "density", "your oil: density at 15 °C", "850 kg/m**3", si="kg/m**3"
    )
    pressure_viscosity: Value | None = _f(
        None,
        "1/pressure",
        "pressure-viscosity coefficient alpha at 40 °C (estimated if left out)",
        "18 1/GPa",
        si="1/Pa",
    )
    limiting_shear_stress: Value | None = _f(
        None, "pressure", "limiting shear stress tau_0 of the traction model", "2 MPa", si="Pa"
    )
    limiting_shear_coefficient: Value | None = _f(
        None, "-", "pressure coefficient gamma_L of the limiting shear stress", 0.047, si=""
    )
    lubrication: (
        Literal["auto", "flooded", "circulating", "oil-air", "drip", "grease"] | Assumed
    ) = _f(
        "auto",
        "-",
        'how the nut is lubricated: "flooded" (an oil bath) or "circulating" (oil pumped '
        "through; both keep the nut full: oil shear between the balls and ball churning, no "
        'starvation), "drip" (oil applied, the nut not full), "oil-air" or "grease"; default '
        '"auto": "grease" for a grease, else "drip", the conditions of the makers\' drag '
        "torques (the complete model; the other models do not distinguish)",
        "flooded",
    )


class OperationSection(BaseModel):
    """``[operation]``: the operating points (each a value, a list or a range)."""

    model_config = ConfigDict(extra="forbid")
    speed: Value = _f(
        "10..3000:60 rpm",
        "angular speed",
        "screw speed(s): 'a..b:n unit' or 'a, b unit'; a feed ('15 m/min') is read as the "
        "screw speed at the lead",
    )
    temperature: Value = _f("20 degC", "temperature", "lubricant temperature(s)")
    axial_load: Value = _f("0 N", "force", "external axial load(s) on the nut")


class AxisSection(BaseModel):
    """``[axis]``: what the screw moves and drives, for ``ballscrew energy``."""

    model_config = ConfigDict(extra="forbid")
    moving_mass: Value = _f(
        "0 kg",
        "mass",
        "table, workpiece and nut (its weight above the screw's C_0a is refused, above half "
        "of it warned)",
        "200 kg",
        si="kg",
    )
    screw_inertia: Value | None = _f(
        None,
        "moment of inertia",
        "of the screw (none: a solid steel shaft of the pitch diameter over screw_length)",
        "1.5e-3 kg*m**2",
        si="kg*m**2",
    )
    coupling_inertia: Value = _f("0 kg*m**2", "moment of inertia", "of the coupling", si="kg*m**2")
    motor_inertia: Value = _f(
        "0 kg*m**2", "moment of inertia", "of the motor's rotor", si="kg*m**2"
    )
    gear_ratio: Value = _f(1.0, "-", "motor turns per screw turn", si="")
    incline: Value = _f(
        "0 deg", "angle", "of the axis above the horizontal (90 deg: vertical)", si="rad"
    )
    bearing_bore: Value | None = _f(
        None,
        "length",
        "bore of the fixed-end support bearings (none: their friction left out)",
        "30 mm",
        si="m",
    )
    bearing_type: str = _f(
        "angular-contact ball, single row",
        "-",
        "support bearing type (see ballscrew.bearings): SKF's coefficient, or Palmgren's "
        "factors with bearing_outer_diameter, e.g. 'screw-support (ZKLN, ZKLF)'",
    )
    bearing_outer_diameter: Value | None = _f(
        None,
        "length",
        "outside diameter of the support bearings: their friction is then Palmgren's, "
        "rising with speed and viscosity (none: SKF's simplified estimate)",
        "62 mm",
        si="m",
    )
    bearing_static_rating: Value | None = _f(
        None,
        "force",
        "static load rating C0 of the support bearings, from their catalogue (needed with "
        "bearing_outer_diameter)",
        "40 kN",
        si="N",
    )
    bearing_lubrication: str = _f(
        "grease",
        "-",
        "support bearings' lubrication for Palmgren's f0: 'grease' (or oil mist) or 'oil' "
        "(bath or recirculating)",
    )
    support: str = _f(
        "fixed-supported",
        "-",
        "end mounting for the critical speed: fixed-free, supported-supported, "
        "fixed-supported or fixed-fixed",
    )
    bearing_span: Value | None = _f(
        None,
        "length",
        "distance between the screw's supports (none: critical speed not checked); refused where "
        "the shaft's first bending frequency falls below 1 Hz, warned below 5 Hz",
        "1 m",
        si="m",
    )
    root_diameter: Value | None = _f(
        None,
        "length",
        "root diameter of the thread, from the catalogue (none: estimated from the groove)",
        "34.1 mm",
        si="m",
    )
    dn_limit: Value = _f(
        "70000 mm*rpm",
        "length * angular speed",
        "the nut's d·n limit from its catalogue (pitch diameter times speed)",
        si="mm*rpm",
    )
    max_feed: Value | None = _f(
        None,
        "speed",
        "the axis' speed limit (drive, guideways); a motion faster than it is refused (none: "
        "not checked)",
        "0.5 m/s",
        si="m/s",
    )
    max_acceleration: Value | None = _f(
        None,
        "acceleration",
        "the axis' acceleration limit; a motion that accelerates harder is refused (none: not "
        "checked)",
        "5 m/s**2",
        si="m/s**2",
    )
    pre_rolling_length: Value | None = _f(
        None,
        "length",
        "table travel over which the screw's drag builds from rest to 63 % of its rolling "
        "value, for ballscrew contour (none: 5 um; 1 to 20 um is what a measured rolling ball "
        "guide allows, Futami et al. 1990, see positioning-accuracy.md)",
        "5 um",
        si="m",
    )
    screw_length: Value | None = _f(
        None,
        "length",
        "screw length in the air, for the temperature (none: estimated from the stroke, "
        "the nut and the diameter)",
        "1 m",
        si="m",
        group="thermal",
    )
    nut_mass: Value = _f(
        "0 kg", "mass", "of the nut, for the heat capacity", "3 kg", si="kg", group="thermal"
    )
    machine_resistance: Value | None = _f(
        None,
        "thermal resistance",
        "from the nut into the machine (none: convection only)",
        "2 K/W",
        si="K/W",
        group="thermal",
    )
    ambient: Value = _f(
        "20 degC", "temperature", "of the air and the machine", si="degC", group="thermal"
    )


class MotorSection(BaseModel):
    """``[motor]``: the servo motor's ratings and its electrical constants.

    The ratings are for ``ballscrew check``; the constants give the copper loss of
    ``ballscrew program`` (:mod:`ballscrew.axis.drive`). Its rotor inertia and the gear
    are ``[axis]`` motor_inertia and gear_ratio.
    """

    model_config = ConfigDict(extra="forbid")
    rated_torque: Value | None = _f(
        None,
        "torque",
        "continuous (rated) torque, against the cycle's RMS torque",
        "2.4 N*m",
        si="N*m",
    )
    peak_torque: Value | None = _f(
        None,
        "torque",
        "peak torque of motor and drive, against the cycle's peak",
        "7.2 N*m",
        si="N*m",
    )
    rated_speed: Value | None = _f(
        None,
        "angular speed",
        "speed up to which the motor gives its torque",
        "3000 rpm",
        si="rad/s",
    )
    torque_constant: Value | None = _f(
        None,
        "torque per current",
        "torque per ampere rms of the phase current, k_T of the data sheet (a constant per "
        "ampere of the sine's peak: times 1.414); with winding_resistance it gives the copper "
        "loss of `ballscrew program` (none: copper loss, drive loss and energy from the grid "
        "not computed, and said)",
        "1.8 N*m/A",
        si="N*m/A",
    )
    torque_constant_at_rated_speed: Value | None = _f(
        None,
        "torque per current",
        "the torque constant at rated_speed, linear from torque_constant at standstill and "
        "held beyond (none: the same at every speed)",
        "1.7 N*m/A",
        si="N*m/A",
    )
    winding_resistance: Value | None = _f(
        None,
        "resistance",
        "winding resistance at 20 degC, of one phase or between two terminals as "
        "resistance_kind says (none: copper loss and energy from the grid not computed, and "
        "said)",
        "1.4 ohm",
        si="ohm",
    )
    resistance_kind: Literal["phase", "terminal"] | None = _f(
        None,
        "-",
        "which resistance winding_resistance is: 'phase' (one phase of the star, or the star "
        "equivalent of a delta) or 'terminal' (line to line, twice the phase's); required with "
        "winding_resistance",
        "phase",
    )
    iron_loss: Value | None = _f(
        None,
        "torque or power",
        "the motor's iron and friction loss: a drag torque, or a power at rated_speed read as "
        "the drag torque P/rated_speed (none: left out of the energy from the grid, and said)",
        "0.12 N*m",
    )


class CheckSection(BaseModel):
    """``[check]``: what ``ballscrew check`` asks of the axis."""

    model_config = ConfigDict(extra="forbid")
    required_life: Value | None = _f(
        None,
        "time",
        "nominal life the screw must reach (none: 20000 h, THK's and NSK's figure for "
        "machine tools)",
        "20000 h",
        si="s",
    )
    reliability: Value = _f(
        "90 %", "-", "reliability of the life (90 to 99 %, ISO 3408-5 a1)", si=""
    )
    load_factor: Value | None = _f(
        None,
        "-",
        "load factor f_w of the life, 1 to 3: the mean load times f_w (THK A15-40: 1.0 to "
        "1.2 smooth running without impact, 1.2 to 1.5 normal running, 1.5 to 3 with impact "
        "or vibration; none: 1.2, where normal running begins, and said so; 1 is ISO 3408-5's "
        "own life)",
        1.2,
        si="",
    )
    static_safety: Value = _f(
        2.0,
        "-",
        "least static safety factor C_0a/F_max (THK's guideline for machine tools: 1 to "
        "1.5 without vibration or impact, 2.5 to 7 with)",
        si="",
    )
    accuracy_grade: str | None = _f(
        None,
        "-",
        "accuracy grade of the screw for the thermal lead error: P0, P1, P3, P5, T5, T7, T10 "
        "(ISO 3408-3) or C0, C1, C2, C3, C5, C7, C8, C10 (JIS B 1192) (none: the error is "
        "shown, not judged)",
        "P3",
    )
    support_stiffness: Value | None = _f(
        None,
        "force / length",
        "axial stiffness of the thrust bearings, from their catalogue (none: taken as rigid, "
        "and said so)",
        "750 N/um",
        si="N/m",
    )
    axial_play: Value | None = _f(
        None,
        "length",
        "axial play of a nut without preload, added to its lost motion (none: 0.02 mm, THK's "
        "clearance G2 of a precision nut, General Catalog A15-19, and said so)",
        "0.01 mm",
        si="m",
    )
    preload_tolerance: Value | None = _f(
        None,
        "-",
        "tolerance of the preload, +- as a share, read as a uniform range (none: the makers' "
        "drag-torque band of grade C3 at the case's catalogue drag torque, THK A-688 Table 13)",
        "20 %",
        si="",
    )
    rating_tolerance: Value | None = _f(
        None,
        "-",
        "tolerance of the load ratings C_a and C_0a, +- as a share, uniform (none: 0, the "
        "catalogue's values as printed, and said so)",
        "10 %",
        si="",
    )
    mass_tolerance: Value | None = _f(
        None,
        "-",
        "tolerance of the moving mass, +- as a share, uniform (none: 0, and said so)",
        "10 %",
        si="",
    )
    force_tolerance: Value | None = _f(
        None,
        "-",
        "tolerance of the move's process force, +- as a share, uniform (none: 0, and said so)",
        "20 %",
        si="",
    )
    pretension_temperature: Value = _f(
        "0 K",
        "temperature difference",
        "temperature rise that the screw's pre-tension absorbs (fixed-fixed mounting; 0: none; "
        "a rise: '3 degC' is read as 3 K; at most 30 K)",
        "3 K",
        si="delta_degC",
    )


class StudySection(BaseModel):
    """``[study]``: settings of ``ballscrew study`` (the study's own values by default)."""

    model_config = ConfigDict(extra="forbid")
    drag_torques: list[Value] = _f(
        [],
        "torque",
        "catalogue drag torques whose preloads the study compares (default: the case's preload "
        "x 0.5, 1 and 1.5)",
        ["0.2 N*m", "0.4 N*m", "0.6 N*m"],
    )
    measured_range: list[Value] = _f(
        [],
        "torque",
        "a measured torque band [low, high] of YOUR screw, drawn on the figures (none if empty)",
        ["0.2 N*m", "0.6 N*m"],
    )
    temperature: Value | None = _f(
        None,
        "temperature",
        "temperature of the study's figures (default: the operation's first)",
        "20 degC",
    )
    lubricant_temperatures: dict[str, list[Value]] = _f(
        {},
        "temperature",
        "lubricant name -> temperatures of the lubricant comparison (default: the case's "
        "lubricant at 20, 30, 40 and 50 degC)",
        {"PAO ISO VG 68": ["20 degC", "40 degC"], "SAE 20": ["24 degC", "40 degC"]},
    )
    model_parameters: dict[str, dict[str, Any]] = _f(
        {},
        "-",
        "model name -> its parameters (see ballscrew models)",
        {"complete": {"boundary_friction": 0.12}},
    )


class OutputSection(BaseModel):
    """``[output]``: how results are printed (files and JSON stay SI)."""

    model_config = ConfigDict(extra="forbid")
    units: Literal["si", "imperial"] = _f(
        "si",
        "-",
        "units of printed results: si, or imperial (lbf, in, lbf*in, in/min, degF; speeds "
        "stay in rpm, powers in W, energies in J); JSON and CSV stay SI; the command line's "
        "--units overrides it",
        "imperial",
    )


class CaseFile(BaseModel):
    """A case file: one ball screw, its lubricant, operating range and study settings."""

    model_config = ConfigDict(extra="forbid")
    title: str = _f("ball screw case", "-", "title of tables and reports")
    description: str = _f("", "-", "free text")
    screw: ScrewSection
    lubricant: LubricantSection
    operation: OperationSection = Field(default_factory=OperationSection)
    axis: AxisSection = Field(default_factory=AxisSection)
    motor: MotorSection = Field(default_factory=MotorSection)
    check: CheckSection = Field(default_factory=CheckSection)
    study: StudySection = Field(default_factory=StudySection)
    output: OutputSection = Field(default_factory=OutputSection)


SECTIONS: dict[str, type[BaseModel]] = {
    "screw": ScrewSection,
    "lubricant": LubricantSection,
    "operation": OperationSection,
    "axis": AxisSection,
    "motor": MotorSection,
    "check": CheckSection,
    "study": StudySection,
    "output": OutputSection,
}


@dataclass(frozen=True)
class ReferenceRow:
    """One key of a case file: where it lives, its unit, default and meaning."""

    section: str
    key: str
    unit: str
    required: bool
    default: str
    example: str
    description: str
    fill: bool = False


def _toml(value: Any) -> str:
    """A value written as TOML (strings quoted, lists and tables inline)."""
    if isinstance(value, str):
        return json.dumps(value, ensure_ascii=False)
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, int | float):
        return repr(value)
    if isinstance(value, list):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    if isinstance(value, dict):
        return "{ " + ", ".join(f"{_key(k)} = {_toml(v)}" for k, v in value.items()) + " }"
    raise TypeError(f"no TOML form for {value!r}")


def _key(name: str) -> str:
    return name if name.replace("_", "").replace("-", "").isalnum() else json.dumps(name)


def _default(info: FieldInfo) -> Any:
    if info.is_required():
        return None
    if info.default_factory is not None:
        return info.default_factory()  # type: ignore[call-arg]
    return info.default


def si_units(section: type[BaseModel], group: str | None = None) -> dict[str, str]:
    """Key -> SI unit of the numeric keys of a section (``""``: a plain number), in order.

    Only the keys of ``group`` (by default those in no group).
    """
    out: dict[str, str] = {}
    for key, info in section.model_fields.items():
        extra = info.json_schema_extra if isinstance(info.json_schema_extra, dict) else {}
        if "si" in extra and extra.get("group") == group:
            out[key] = str(extra["si"])
    return out


def reference_rows() -> list[ReferenceRow]:
    """Every key of a case file, from the schema (top-level keys first)."""
    rows: list[ReferenceRow] = []
    sections: list[tuple[str, type[BaseModel]]] = [("", CaseFile)]
    sections += list(SECTIONS.items())
    for section, model in sections:
        for key, info in model.model_fields.items():
            if section == "" and key in SECTIONS:
                continue
            extra = info.json_schema_extra if isinstance(info.json_schema_extra, dict) else {}
            default = _default(info)
            rows.append(
                ReferenceRow(
                    section=section,
                    key=key,
                    unit=str(extra.get("unit", "-")),
                    required=info.is_required(),
                    default="" if default in (None, "", [], {}) else _toml(default),
                    example=_toml(extra.get("example")) if extra.get("example") is not None else "",
                    description=info.description or "",
                    fill=bool(extra.get("fill", False)),
                )
            )
    return rows


def reference_markdown() -> str:
    """The reference table of case-file keys, as Markdown."""
    lines = [
        "| section | key | unit | required | default | example | meaning |",
        "|---|---|---|---|---|---|---|",
    ]
    for r in reference_rows():
        cells = [
            f"[{r.section}]" if r.section else "(top)",
            f"`{r.key}`",
            r.unit,
            "yes" if r.required else "",
            f"`{r.default}`" if r.default else "",
            f"`{r.example}`" if r.example else "",
            r.description.replace("|", "\\|"),
        ]
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def template() -> str:
    """A commented case file with every key: required ones filled with examples.

    Optional keys are commented out with their default (or an example); every
    value carries its unit. Edit, then check it with ``ballscrew case --check``.
    """
    out = [
        "# ballscrew case file (TOML). Every dimensional value needs its unit:",
        '# "40 mm", "2 kN", "3000 rpm", "40 degC". Any value may be written as',
        '# { value = "20 mm", assumed = "why" } to record that it was assumed.',
        "# Check it with:  ballscrew case --check FILE",
        "",
    ]
    for r in reference_rows():
        if r.section == "":
            out += _entry(r)
    for section in SECTIONS:
        out += ["", f"[{section}]"]
        for r in reference_rows():
            if r.section == section:
                out += _entry(r)
    return "\n".join(out) + "\n"


def _entry(r: ReferenceRow) -> list[str]:
    unit = "" if r.unit == "-" else f" [{r.unit}]"
    comment = f"# {r.description}{unit}"
    if r.required or r.fill:
        return [comment, f"{_key(r.key)} = {r.example}"]
    shown = r.default or r.example
    return [comment, f"# {_key(r.key)} = {shown}"]
