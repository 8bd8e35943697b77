"""Ball screw case files: TOML with explicit units, validated on load.

This module is long on purpose: it is the one reader of a case file; each section
(screw, designation, ratings, preload, lubricant, operation, axis, motor, check)
is a short function of its own, and they share the file's sources and assumptions.

A case describes one ball screw, its lubricant, its operating range and (for
``ballscrew study``) the study's settings. Every dimensional value is written
with its unit (``pitch_diameter = "32 mm"``, ``preload = "1.5 kN"``) and
converted by pint at load time. A value may also be a table that says it was
assumed and why::

    lead = { value = "20 mm", assumed = "high-speed screw of that class" }

Pydantic validates the structure (unknown keys are errors, so typos are
caught); every problem becomes one :class:`~ballscrew.errors.BallScrewInputError`
naming the field by its dotted path (``screw.lead``).

The preload is given either directly (``preload``) or as the catalogue drag
torque it produces (``preload_drag_torque``), which the case turns into a
preload with :func:`ballscrew.friction.catalog.preload_from_drag_torque`, as
the study did.
"""

from __future__ import annotations

import dataclasses
import difflib
import math
import re
import tomllib
import warnings
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field, replace
from importlib import resources
from pathlib import Path
from typing import Any, NamedTuple

import numpy as np
from pydantic import ValidationError

from .. import lubricants
from ..design.limits import (
    DEFAULT_DN_LIMIT,
    MAX_SPEED,
    SUPPORT_EIGENVALUES,
    check_operating_bounds,
    critical_speed,
    root_diameter,
)
from ..design.ratings import Ratings, static_rating_estimate
from ..errors import BallScrewInputError, BallScrewPlausibilityWarning, FloatArray
from ..geometry import PLAUSIBLE_SIZES, BallScrew
from ..lubricant import Lubricant, lubrication_method
from ..plausible import (
    AXIS_RANGES,
    LOWEST_FREQUENCY,
    LUBRICANT_RANGES,
    check_acceleration,
    check_axis_property,
    check_feed,
    check_moving_mass,
    check_span,
    check_wiper_drag,
    least_nut_mass,
)
from .designation import resolve
from .files import read_input_text
from .schema import (
    SECTIONS,
    Assumed,
    AxisSection,
    CaseFile,
    CheckSection,
    LubricantSection,
    MotorSection,
    ScrewSection,
    si_units,
)
from .units import Reading, parse_range, parse_speed_range, to_si

__all__ = [
    "KEY_UNITS",
    "LUBRICANT_UNITS",
    "OPERATION_UNITS",
    "SCREW_UNITS",
    "WIPER_PARAMETERS",
    "Assumption",
    "Case",
    "default_case_path",
    "load_case",
    "parse_case",
    "parse_toml",
]

MAX_TOML_CHARS = 1_000_000
"""The longest TOML text read (a case or sweep file is a few kB)."""
MAX_TOML_DEPTH = 32
"""The deepest nesting of tables and arrays, and the most parts of a dotted key."""
MAX_PRETENSION_RISE = 30.0
"""The largest ``check.pretension_temperature`` [K]: catalogues pre-tension a screw for a
rise of a few kelvin; 30 K stresses a steel shaft by E alpha dT = 210 GPa x 11.5e-6/K x
30 K = 72 MPa, and a value of hundreds is an absolute temperature typed for a rise."""
_STRINGS_AND_COMMENTS = re.compile(
    r""""{3}[\s\S]*?"{3}|'{3}[\s\S]*?'{3}|"(?:[^"\\\n]|\\.)*"|'[^'\n]*'|#[^\n]*"""
)
# A key's parts start only where a word starts (the look-behind) and are taken whole (the
# possessive quantifiers): the search is linear in the text, where the plain pattern went
# back over every start inside a long word (a 65 kB key held the server for 40 s).
_DOTTED_KEY = re.compile(
    rf"(?<![A-Za-z0-9_-])(?:[A-Za-z0-9_-]++[ \t]*+\.[ \t]*+){{{MAX_TOML_DEPTH},}}"
)


def _quoted(match: re.Match[str]) -> str:
    """A string as one bare word (a quoted key's part stays a part), a comment as nothing."""
    return "" if match.group().startswith("#") else "s"


def parse_toml(text: str, source: str) -> dict[str, Any]:
    """TOML text parsed, within the limits that keep the parser quick; ``source`` names it.

    The standard library's parser recurses once per level of nesting (a file of
    100 000 ``[`` ran out of stack) and slows with the square of a dotted
    key's parts (one key of 50 000 parts took a minute): the text is refused,
    naming ``source``, when it is over :data:`MAX_TOML_CHARS` characters, has a
    key of :data:`MAX_TOML_DEPTH` dotted parts or more, or nests deeper. A leading
    byte-order mark (Windows editors save UTF-8 with one) is dropped, as the CSV and
    program readers drop it; the TOML parser refuses it.
    """
    text = text.removeprefix("\ufeff")
    if len(text) > MAX_TOML_CHARS:
        raise BallScrewInputError(
            source, f"{len(text):,} characters", f"at most {MAX_TOML_CHARS:,} characters"
        )
    if _DOTTED_KEY.search(_STRINGS_AND_COMMENTS.sub(_quoted, text)):
        raise BallScrewInputError(
            source, "(file)", f"keys of fewer than {MAX_TOML_DEPTH} dotted parts"
        )
    deep = f"tables and arrays nested at most {MAX_TOML_DEPTH} deep"
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise BallScrewInputError(source, "(file)", f"valid TOML ({exc})") from None
    except RecursionError:
        raise BallScrewInputError(source, "(file)", deep) from None
    except ValueError as exc:  # an integer of more digits than Python converts (4300)
        raise BallScrewInputError(source, "(file)", f"numbers a float can hold ({exc})") from None
    level: list[tuple[Any, int]] = [(raw, 0)]
    while level:  # iteratively: a deep structure must not overflow the check either
        value, depth = level.pop()
        if depth > MAX_TOML_DEPTH:
            raise BallScrewInputError(source, "(file)", deep)
        if isinstance(value, dict):
            level.extend((v, depth + 1) for v in value.values())
        elif isinstance(value, list):
            level.extend((v, depth + 1) for v in value)
    return raw


@dataclass(frozen=True)
class Assumption:
    """A value of a case that was assumed rather than known."""

    field: str
    value: str
    reason: str
    tolerance: float | None = None
    """The range it may lie in, +- as a share (``tolerance = "10 %"`` beside ``assumed``)."""


def _share(field: str, text: str) -> float:
    """An assumed value's tolerance, '10 %' -> 0.1: from 0 to less than 100 %."""
    raw = text.strip()
    try:
        value = float(raw.removesuffix("%").strip()) / 100.0
    except ValueError:
        value = math.nan
    if not (raw.endswith("%") and 0.0 <= value < 1.0):
        raise BallScrewInputError(f"{field}.tolerance", text, "a share from 0 to 100 %, e.g. "
                                  "'10 %'")  # fmt: skip
    return value


def _unwrap(field: str, raw: Any, notes: list[Assumption]) -> Any:
    if isinstance(raw, Assumed):
        tol = None if raw.tolerance is None else _share(field, raw.tolerance)
        notes.append(Assumption(field, str(raw.value), raw.assumed, tol))
        return raw.value
    return raw


@dataclass(frozen=True)
class Case:
    """A loaded, validated case.

    Attributes
    ----------
    title, description : str
        Labels.
    screw : BallScrew
        The ball screw, with the case's preload.
    lubricant : Lubricant
        The oil.
    speed : numpy.ndarray
        Screw speeds [rad/s].
    temperature : numpy.ndarray
        Temperatures [°C].
    axial_load : numpy.ndarray
        Axial loads [N].
    drag_torques : tuple of float
        Study: catalogue drag torques [N·m] whose preloads are compared;
        the middle one is the case's own when the preload is derived.
    measured_range : tuple of float
        Study: the measured torque band [N·m].
    study_temperature : float
        Study: temperature of Figs. 3 to 7 [°C].
    lubricant_temperatures : dict
        Study: lubricant name -> temperatures [°C] (Fig. 8, Table 1).
    model_parameters : dict
        Study: model name -> parameters passed to it.
    assumptions : tuple of Assumption
        Every value marked as assumed, with its reason.
    text : str
        The TOML text the case was read from.
    screw_source : str
        Where the screw's geometry came from when a designation named it.
    designation : str
        ``[screw] designation`` as written ("" when the file gives none).
    axis : dict
        ``[axis]`` in SI (kg, kg·m², rad, m; d·n in mm·rpm) and its choices
        (bearing type, support): the keywords of :class:`ballscrew.axis.energy.Axis`.
    thermal : dict
        ``[axis]``'s thermal keys in SI (m, kg, K/W, °C), those given: the
        keywords of :class:`ballscrew.axis.thermal.ThermalNode`.
    lubrication : str or None
        ``[lubricant] lubrication``, the lubrication method; :meth:`parameters_for` hands
        it to the complete model (its ``lubrication``); None when not given.
    contact_angle_scatter : float or None
        ``[screw] contact_angle_scatter`` [rad]; :meth:`parameters_for` hands it to
        the complete model with ``ball_train="tolerance"``; None when not given.
    wiper_drag : float
        ``[screw] wiper_drag``: drag torque of the nut's wipers or seals [N·m],
        0 when not given; :meth:`parameters_for` hands it to the models of
        :data:`WIPER_PARAMETERS`.
    ratings : Ratings or None
        The screw's load ratings C_a and C_0a [N] with their sources (given,
        from the designation's catalogue row, or C_0a estimated from the
        geometry); :meth:`load_ratings` estimates them when None.
    motor : dict
        ``[motor]`` in SI (N·m, rad/s, N·m/A, Ω; the iron loss in N·m or W as
        ``iron_loss_kind`` says), the keys given, and ``resistance_kind``.
    check : dict
        ``[check]`` in SI (s, -, N/m, K) and the accuracy grade, the keys given
        or defaulted by the schema.
    axis_given : frozenset of str
        The ``[axis]`` keys the file wrote (a default is not a given value).
    output_units : str
        ``[output] units``: the unit system of printed results, ``"si"`` or
        ``"imperial"`` (:mod:`ballscrew.io.display`).
    """

    title: str
    description: str
    screw: BallScrew
    lubricant: Lubricant
    speed: FloatArray
    temperature: FloatArray
    axial_load: FloatArray
    drag_torques: tuple[float, ...]
    measured_range: tuple[float, ...]
    study_temperature: float
    lubricant_temperatures: dict[str, tuple[float, ...]]
    model_parameters: dict[str, dict[str, Any]]
    assumptions: tuple[Assumption, ...]
    text: str
    screw_source: str = ""
    axis: dict[str, Any] = field(default_factory=dict)
    thermal: dict[str, float] = field(default_factory=dict)
    wiper_drag: float = 0.0
    ratings: Ratings | None = None
    motor: dict[str, Any] = field(default_factory=dict)
    check: dict[str, Any] = field(default_factory=dict)
    axis_given: frozenset[str] = frozenset()
    sources: dict[str, str] = field(default_factory=dict)
    """Where each key's value comes from, by ``section.key``: ``given`` (written in the
    file), ``catalogue`` (the designation's row), ``default`` (the schema's or the
    command's), ``assumed`` (marked so, with its reason in :attr:`assumptions`)."""
    contact_angle_scatter: float | None = None
    lubrication: str | None = None
    output_units: str = "si"
    designation: str = ""
    given_si: dict[str, tuple[float, str]] = field(default_factory=dict)
    """Each number the file wrote with its unit, by ``section.key``: its SI value and SI unit
    as read (a preload written as ``preload_share`` keeps the share here)."""
    warned: tuple[str, ...] = ()
    """The plausibility warnings of its inputs, each once (a ball off the makers' series, an
    oil outside its typical range: :mod:`ballscrew.plausible`); also warned when read."""

    def load_ratings(self) -> Ratings:
        """The screw's load ratings: the case's, else C_0a estimated from the geometry."""
        if self.ratings is not None:
            return self.ratings
        return _estimated(self.screw, None, "")

    @property
    def dynamic_load_rating(self) -> float | None:
        """:math:`C_a` [N] from the file or the designation's catalogue row, else None."""
        return self.ratings.dynamic if self.ratings is not None else None

    @property
    def static_load_rating(self) -> float | None:
        """:math:`C_{0a}` [N] from the file or the catalogue row; None when only estimated."""
        r = self.ratings
        return r.static if r is not None and not r.static_estimated else None

    def parameters_for(self, model: str) -> dict[str, Any]:
        """The case's parameters of ``model`` (a fresh dict; empty when it gives none).

        A model with a wiper or seal term (:data:`WIPER_PARAMETERS`) gets the
        case's ``wiper_drag`` as that parameter, when the case gives one.
        """
        params = dict(self.model_parameters.get(model, {}))
        if self.wiper_drag and model in WIPER_PARAMETERS:
            params[WIPER_PARAMETERS[model]] = self.wiper_drag
        if self.contact_angle_scatter is not None and model == "complete":
            params.setdefault("ball_train", "tolerance")
            params.setdefault("contact_angle_scatter", self.contact_angle_scatter)
        if self.lubrication is not None and model == "complete":
            params.setdefault("lubrication", self.lubrication)
        return params

    def input_values(
        self, derived: Mapping[str, tuple[Any, str]] | None = None
    ) -> list[dict[str, Any]]:
        """Every key of the case as a run uses it: value, unit, source, and how it was found.

        The one list of inputs the outputs carry (``--json`` of ``torque``, ``energy``,
        ``check``, ``select`` and their reports). Each entry: ``key`` (``section.key``),
        ``value`` (SI, a list for the operating points), ``unit`` (its SI unit, "" for a
        plain number or a share) and ``source`` (:attr:`sources`: ``given``,
        ``catalogue``, ``default``, ``assumed``, a catalogue row, ...). A value the
        command filled from others (``derived``, by key: the value and how, e.g. the
        screw's inertia from its geometry, :attr:`ballscrew.axis.setup.AxisSetup.derived`)
        is ``estimated`` with ``how``; a key left out that nothing fills has the value
        None, the source ``not given`` and ``how`` saying what its absence means
        (the schema's "none: ..." of the key).
        """
        derived = derived or {}
        ratings = self.load_ratings()
        screw = dataclasses.asdict(self.screw)
        out: list[dict[str, Any]] = []
        readings = {a.field: a.reason for a in self.assumptions if a.reason.startswith(READ_AS)}
        for key, source in sorted(self.sources.items()):
            section, name = key.split(".", 1)
            entry: dict[str, Any] = {"key": key, "value": None, "unit": KEY_UNITS.get(key, "")}
            how = ""
            if key in derived and source in ("default", "not given"):
                value, how = derived[key]
                source = "estimated"
            elif key in self.given_si:
                value, entry["unit"] = self.given_si[key]
            elif name == "dynamic_load_rating" and section == "screw":
                value, source = ratings.dynamic, ratings.dynamic_source or source
            elif name == "static_load_rating" and section == "screw":
                value, source = ratings.static, ratings.static_source
            else:
                value = _resolved(self, section, name, screw)
            if isinstance(value, np.ndarray):
                value = value.tolist()
            elif isinstance(value, np.generic):
                value = value.item()
            if source != "estimated":  # an input: its unit's conversion's last bit dropped
                value = _as_input(value)
            if value is None:
                source, how = "not given", _absent(section, name)
            how = how or readings.get(key, "")
            entry |= {"value": value, "source": source}
            if how:
                entry["how"] = how
            out.append(entry)
        return out

    def with_wiper_drag(self, value: Any, *, field: str = "screw.wiper_drag") -> Case:
        """The case with another wiper drag (a torque with its unit, e.g. ``"0.05 N*m"``)."""
        drag = _wiper_drag(field, value, self.model_parameters, self.screw.pitch_diameter)
        return replace(self, wiper_drag=drag)


WIPER_PARAMETERS: dict[str, str] = {"complete": "seal_torque"}
"""The models with a wiper or seal drag term, and the parameter that takes ``[screw] wiper_drag``.

Reading a case reaches no model, so the list is kept here; a test checks it
against the registered models' parameters. Other models leave the drag out,
and :func:`ballscrew.report.torque.run_models` says so with each result.
"""


def _wiper_drag(
    field: str, raw: Any, model_parameters: dict[str, dict[str, Any]], pitch_diameter: float
) -> float:
    """The wiper drag [N·m] from its text with unit: >= 0, not given twice for one model.

    Held to the screw's size (:func:`ballscrew.plausible.check_wiper_drag`): ten
    times the wipers' typical drag is refused, above it warned.
    """
    value = to_si(field, raw, "N*m")
    if not (math.isfinite(value) and value >= 0.0):
        raise BallScrewInputError(field, raw, "a torque >= 0 with its unit, e.g. '0.05 N*m'")
    check_wiper_drag(field, value, pitch_diameter)
    for model, parameter in WIPER_PARAMETERS.items():
        if value and parameter in model_parameters.get(model, {}):
            raise BallScrewInputError(
                field,
                raw,
                f"only one wiper drag: study.model_parameters.{model}.{parameter} gives it too",
            )
    return value


def _validation_error(exc: ValidationError) -> BallScrewInputError:
    """One error naming the field; a misspelt key first, with the likely intended one."""
    errors = exc.errors()
    err = next((e for e in errors if e["type"] == "extra_forbidden"), errors[0])
    path = ".".join(str(p) for p in err["loc"] if not str(p).startswith(("function-", "_")))
    # pydantic reports union members in the path; keep the field names only.
    union = {"str", "float", "int", "Assumed"}
    parts = [p for p in path.split(".") if p not in union and not p.startswith("literal[")]
    field = ".".join(parts) or "case"
    kind = err["type"]
    allowed = {
        "missing": "a value (the field is required)",
        "extra_forbidden": "no such field (check the spelling)",
    }.get(kind, err["msg"])
    if kind == "extra_forbidden":
        section = parts[0] if len(parts) > 1 else ""
        model = SECTIONS.get(section, CaseFile)
        close = difflib.get_close_matches(parts[-1], list(model.model_fields), n=1)
        if close:
            allowed = f"no such field; did you mean {'.'.join([*parts[:-1], close[0]])}?"
    value = "(missing)" if kind == "missing" else err.get("input", "")
    if isinstance(value, list) and kind.endswith("_type"):  # a TOML list where one text goes
        shown = ", ".join(f'"{v}"' if isinstance(v, str) else str(v) for v in value)
        value = f"[{shown}]"
        allowed = "one quoted text with its unit, not a TOML list" + (
            ": several values go in the one text, e.g. \"0, 2 kN\" or \"10..3000:60 rpm\""
            if field.startswith("operation.") else "")  # fmt: skip
    return BallScrewInputError(field, value, allowed)


def parse_case(text: str, *, source: str = "case") -> Case:
    """Validate a case given as TOML text; see the module docstring for the format.

    A value outside what makers build or sell is warned of
    (:class:`~ballscrew.errors.BallScrewPlausibilityWarning`) once, and kept in
    :attr:`Case.warned` for the faces that answer with their warnings (the web).
    """
    text = text.removeprefix("\ufeff")  # kept as Case.text, which tomlkit re-reads
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always", BallScrewPlausibilityWarning)
        case = _parse_case(text, source)
    told: dict[str, None] = {}
    for w in caught:
        message = w.message
        if isinstance(message, BallScrewPlausibilityWarning):
            message = _named(message)
            if str(message) in told:
                continue
            told[str(message)] = None
        warnings.warn_explicit(message, w.category, w.filename, w.lineno)
    return replace(case, warned=tuple(told)) if told else case


def _named(w: BallScrewPlausibilityWarning) -> BallScrewPlausibilityWarning:
    """The warning naming its field as the file does (``screw.ball_diameter``)."""
    if "." in w.field:
        return w
    section = "lubricant" if w.field in LUBRICANT_RANGES else "screw"
    return BallScrewPlausibilityWarning(f"{section}.{w.field}", w.value, w.allowed, w.source)


def _parse_case(text: str, source: str) -> Case:
    try:
        return _read_case(text, source)
    except BallScrewInputError as exc:
        if isinstance(exc.value, Assumed):  # named by the value's own text, not its table
            raise BallScrewInputError(exc.field, exc.value.value, exc.allowed) from None
        raise


def _read_case(text: str, source: str) -> Case:
    data = _case_file(text, source)
    notes: list[Assumption] = []
    read: list[Reading] = []  # how texts that could be meant two ways were read
    s = data.screw

    given: dict[str, tuple[float, str]] = {}  # each number read, for Case.input_values

    def si(section: str, name: str, value: Any, unit: str) -> float:
        field = f"{section}.{name}"
        number = to_si(field, _unwrap(field, value, notes), unit, notes=read,
                       plausible=PLAUSIBLE.get(field))  # fmt: skip
        given[field] = (number, unit)
        return number

    screw, screw_source, ratings = _screw(s, si, notes)

    lub = _lubricant(data.lubricant, notes)
    lubrication = _lubrication(data, lub, notes)
    speed, temperature, axial = _operation(data, notes, read, screw.lead)
    # What every run checks before it computes, named as the file names it, its value as typed.
    try:
        check_operating_bounds(speed, temperature, axial, "operation.")
    except BallScrewInputError as out:
        typed = getattr(data.operation, out.field.removeprefix("operation."), out.value)
        raise BallScrewInputError(out.field, typed, out.allowed) from None
    lub.check_temperature("operation.temperature", temperature)
    st = data.study
    wiper, scatter = _screw_extras(s, st, screw, si, notes)
    drag, band, temps, study_temperature = _study(st, lub, float(temperature[0]), si)
    axis, thermal = _axis(data, si), _given_si(data, si, _THERMAL_UNITS)
    _axis_plausible(data.axis, screw, ratings.static, axis, thermal)
    motor, check = _motor(data, si), _check(data, si)
    notes.extend(Assumption(r.field, r.text, f"{READ_AS}{r.reading}") for r in read)
    sources = _sources(data, notes)
    return Case(
        title=data.title,
        description=data.description,
        screw=screw,
        lubricant=lub,
        speed=np.asarray(speed),
        temperature=np.asarray(temperature),
        axial_load=np.asarray(axial),
        drag_torques=drag,
        measured_range=band,
        study_temperature=study_temperature,
        lubricant_temperatures=temps,
        model_parameters={k: dict(v) for k, v in st.model_parameters.items()},
        assumptions=tuple(notes),
        text=text,
        screw_source=screw_source,
        axis=axis,
        thermal=thermal,
        wiper_drag=wiper,
        ratings=ratings,
        motor=motor,
        check=check,
        axis_given=frozenset(data.axis.model_fields_set),
        sources=sources,
        contact_angle_scatter=scatter,
        lubrication=lubrication,
        output_units=data.output.units,
        designation=_designation(data.screw),
        given_si={k: v for k, v in given.items() if k in sources and sources[k] != "default"},
    )


def _screw_extras(
    s: ScrewSection, st: Any, screw: BallScrew, si: Callable[..., float],
    notes: list[Assumption],
) -> tuple[float, float | None]:  # fmt: skip
    """``[screw]``'s wiper drag [N·m] (0: none) and contact-angle scatter [rad] (None)."""
    wiper = 0.0
    if s.wiper_drag is not None:
        raw = _unwrap("screw.wiper_drag", s.wiper_drag, notes)
        wiper = _wiper_drag("screw.wiper_drag", raw, st.model_parameters, screw.pitch_diameter)
    scatter = None
    if s.contact_angle_scatter is not None:
        scatter = si("screw", "contact_angle_scatter", s.contact_angle_scatter, "rad")
        if not (math.isfinite(scatter) and 0.0 <= scatter < 0.2):
            raise BallScrewInputError(
                "screw.contact_angle_scatter", s.contact_angle_scatter,
                "an angle from 0 to 0.2 rad (11 deg) with its unit, e.g. '0.3 deg'",
            )  # fmt: skip
    return wiper, scatter


def _study(
    st: Any, lub: Lubricant, first_temperature: float, si: Callable[..., float]
) -> tuple[tuple[float, ...], tuple[float, ...], dict[str, tuple[float, ...]], float]:
    """``[study]`` in SI: drag torques, measured range, lubricant temperatures, temperature."""
    drag = tuple(si("study", f"drag_torques[{i}]", v, "N*m") for i, v in enumerate(st.drag_torques))
    band = tuple(
        si("study", f"measured_range[{i}]", v, "N*m") for i, v in enumerate(st.measured_range)
    )
    temps = {
        name: tuple(si("study", f"lubricant_temperatures.{name}", v, "degC") for v in values)
        for name, values in st.lubricant_temperatures.items()
    }
    for name in temps:
        if name != lub.name:
            lubricants.get(name)  # unknown names fail here, listing the bundled ones
    study_temperature = (
        first_temperature
        if st.temperature is None
        else si("study", "temperature", st.temperature, "degC")
    )
    return drag, band, temps, study_temperature


def _designation(s: ScrewSection) -> str:
    """``[screw] designation`` as written, "" when not given."""
    raw = s.designation.value if isinstance(s.designation, Assumed) else s.designation
    return "" if raw is None else str(raw)


OPERATION_UNITS = {"speed": "rad/s", "temperature": "degC", "axial_load": "N"}
"""The SI units of ``[operation]``'s keys."""


def _key_units() -> dict[str, str]:
    """The SI unit of every numeric key of :attr:`Case.sources` ("" for a plain number)."""
    units = {f"screw.{k}": u for k, u in SCREW_UNITS.items()}
    units |= {"screw.preload": "N", "screw.preload_drag_torque": "N*m",
              "screw.preload_share": "", "screw.dynamic_load_rating": "N",
              "screw.static_load_rating": "N"}  # fmt: skip
    units |= {f"operation.{k}": u for k, u in OPERATION_UNITS.items()}
    for section, model in (("axis", AxisSection), ("motor", MotorSection),
                           ("check", CheckSection)):  # fmt: skip
        units |= {f"{section}.{k}": u for k, u in si_units(model).items()}
    units |= {f"axis.{k}": u for k, u in si_units(AxisSection, "thermal").items()}
    return units


def _resolved(case: Case, section: str, name: str, screw: dict[str, Any]) -> Any:
    """The value ``section.name`` has in the loaded case (SI), None where it has none."""
    if section == "screw":
        return screw.get(name)
    if section == "operation":
        return {"speed": case.speed, "temperature": case.temperature,
                "axial_load": case.axial_load}.get(name)  # fmt: skip
    if section == "axis":
        return case.axis.get(name, case.thermal.get(name))
    if section in ("motor", "check"):
        return getattr(case, section).get(name)
    if (section, name) == ("lubricant", "lubrication"):
        return case.lubrication or "auto"
    return None


def _absent(section: str, name: str) -> str:
    """What leaving ``section.name`` out means, from the schema's "(none: ...)" of the key."""
    model = SECTIONS.get(section)
    info = None if model is None else model.model_fields.get(name)
    text = (info.description or "") if info is not None else ""
    start = text.find("none: ")
    if start < 0:
        return ""
    depth, end = 0, len(text)
    for k in range(start, len(text)):  # up to the bracket that closes the "(none: ..."
        depth += {"(": 1, ")": -1}.get(text[k], 0)
        if depth < 0:
            end = k
            break
    return text[start + len("none: ") : end]


READ_AS = "read as "
"""How an :class:`Assumption` that is a reading of a given text begins ('15 m/min' read as
1500 rpm at the lead): the value is given, its reading told (:meth:`Case.input_values`'
``how``), not assumed."""

INPUT_DIGITS = 15
"""Significant digits of an input converted to SI in :meth:`Case.input_values`: 700 mm is
0.7 m, not 0.7000000000000001. Fifteen, the decimal digits a double holds exactly, so
90 deg stays pi/2 to 1e-15 (the operating points, converted back to rpm, keep 12:
:data:`ballscrew.report.outputs.INPUT_DIGITS`); what a run computes keeps every digit."""


def _as_input(value: Any) -> Any:
    """``value`` (a float, or a list of them) to :data:`INPUT_DIGITS` significant digits."""
    if isinstance(value, list):
        return [_as_input(v) for v in value]
    if isinstance(value, float) and math.isfinite(value) and value != 0.0:
        return float(f"{value:.{INPUT_DIGITS}g}")
    return value


def _typed(raw: Any) -> str:
    """A value as the file wrote it (an assumed value's own text)."""
    return str(raw.value if isinstance(raw, Assumed) else raw)


def _as_typed(
    exc: BallScrewInputError, section: str, given: Any, units: Mapping[str, str]
) -> BallScrewInputError:
    """``exc`` named as the file names it (``screw.ball_diameter``), its value as typed.

    A library class refuses the number in SI (``0.00635``); the file's reader names
    the text the file gave (``'1/4 in'``), or, for a value the file did not give (a
    designation's), the SI number with its unit.
    """
    field = exc.field if exc.field.startswith(section) else f"{section}.{exc.field}"
    name = field.removeprefix(f"{section}.")
    value = exc.value
    if isinstance(value, (int, float, np.floating)) and not isinstance(value, bool):
        raw = getattr(given, name, None)
        unit = units.get(name, "")
        value = _typed(raw) if raw is not None else f"{float(value):g} {unit}".rstrip()
    return BallScrewInputError(field, value, exc.allowed)


_NON_NEGATIVE = ("moving_mass", "screw_inertia", "coupling_inertia", "motor_inertia", "nut_mass")
"""``[axis]`` keys that may be 0; every other number of ``[axis]`` but the incline and the
ambient temperature must be above 0 (what :class:`ballscrew.axis.energy.Axis` and the
thermal node refuse, refused here with the value as typed)."""


def _axis_signs(a: AxisSection, values: Mapping[str, Any]) -> None:
    """Refuse a negative (or zero) ``[axis]`` number, naming it as the file typed it."""
    units = dict(_AXIS_UNITS + _THERMAL_UNITS)
    incline = values.get("incline", 0.0)
    if not (math.isfinite(incline) and abs(incline) <= math.pi / 2):
        raise BallScrewInputError(
            "axis.incline", _typed(a.incline),
            f"an angle from -90 to 90 deg above the horizontal (read as "
            f"{math.degrees(incline):.4g} deg; 90 deg: vertical, the load hanging on the screw)",
        )  # fmt: skip
    for name, value in values.items():
        if name in ("incline", "ambient") or not isinstance(value, float):
            continue
        low = name in _NON_NEGATIVE
        if not (math.isfinite(value) and (value >= 0.0 if low else value > 0.0)):
            unit = units.get(name, "")
            raise BallScrewInputError(
                f"axis.{name}", _typed(getattr(a, name)),
                f"{'0 or more' if low else 'more than 0'} (read as {value:g} {unit})".replace(
                    " )", ")"
                ),
            )  # fmt: skip


def _axis_plausible(
    a: AxisSection, screw: BallScrew, static_rating: float, axis: dict[str, Any],
    thermal: dict[str, float],
) -> None:  # fmt: skip
    """``[axis]`` held to what a ball screw axis can be (:mod:`ballscrew.plausible`).

    The inertias and the gear ratio to their ranges; the moving mass and the
    acceleration against the screw's static rating; the span and the screw length
    against the shaft's first bending frequency; the feed limit against the nut's
    d·n limit; a screw shorter than its span names both, and blames the span when its
    shaft's bending frequency is the implausible one.
    """
    _axis_signs(a, {**axis, **thermal})
    for name in AXIS_RANGES:
        if name in axis:
            check_axis_property(f"axis.{name}", axis[name], name)
    mass = axis.get("moving_mass", 0.0)
    halves = 2 if screw.nut == "double" else 1
    least = least_nut_mass(screw.pitch_diameter, screw.ball_diameter, screw.lead,
                           screw.loaded_turns * screw.circuits, halves)  # fmt: skip
    check_moving_mass("axis.moving_mass", _typed(a.moving_mass), mass, static_rating, least)
    if "max_acceleration" in axis:
        check_acceleration("axis.max_acceleration", _typed(a.max_acceleration),
                           axis["max_acceleration"], mass, static_rating)  # fmt: skip
    if "max_feed" in axis and axis["max_feed"] > 0.0:
        check_feed("axis.max_feed", _typed(a.max_feed), axis["max_feed"], screw.lead,
                   screw.pitch_diameter, axis.get("dn_limit", DEFAULT_DN_LIMIT),
                   MAX_SPEED)  # fmt: skip
    support = str(axis["support"])
    if support not in SUPPORT_EIGENVALUES:
        raise BallScrewInputError("axis.support", support, f"one of {list(SUPPORT_EIGENVALUES)}")
    root = axis.get("root_diameter") or root_diameter(screw)
    if not (math.isfinite(root) and root > 0.0):
        return  # refused, naming axis.root_diameter, when the axis is built
    span, length = axis.get("bearing_span", 0.0), thermal.get("screw_length", 0.0)
    frequency = 0.0
    if span > 0.0:
        frequency = float(critical_speed(root, span, support)) / (2.0 * math.pi)
        check_span("axis.bearing_span", _typed(a.bearing_span), span, frequency,
                   f"{support}, root diameter {root * 1e3:.3g} mm")  # fmt: skip
    if length > 0.0:
        whole = float(critical_speed(root, length, "fixed-fixed")) / (2.0 * math.pi)
        check_span("axis.screw_length", _typed(a.screw_length), length, whole,
                   f"held fixed at both ends over its whole length, root diameter "
                   f"{root * 1e3:.3g} mm", warn_below=False)  # fmt: skip
    if 0.0 < length < span:
        both = (f"axis.screw_length = {_typed(a.screw_length)!r} and axis.bearing_span = "
                f"{_typed(a.bearing_span)!r}")  # fmt: skip
        if frequency < LOWEST_FREQUENCY[1]:
            raise BallScrewInputError(
                "axis.bearing_span", _typed(a.bearing_span),
                f"at most the screw length {length * 1e3:g} mm (the screw runs through both "
                f"supports): of {both}, the span is the implausible one (its shaft would bend "
                f"at {frequency:.3g} Hz)",
            )  # fmt: skip
        raise BallScrewInputError(
            "axis.screw_length", _typed(a.screw_length),
            f"at least the bearing span {span * 1e3:g} mm (the screw runs through both "
            f"supports): {both} disagree; one of them is mistyped",
        )  # fmt: skip


def _motor(data: CaseFile, si: Callable[[str, str, Any, str], float]) -> dict[str, Any]:
    """``[motor]``'s given keys in SI, each more than 0; the electrical constants checked.

    ``resistance_kind`` is kept with ``winding_resistance``; ``iron_loss`` is a torque
    [N·m] or a power [W] (then needing the rated speed), ``iron_loss_kind`` says which.
    """
    motor: dict[str, Any] = {
        name: si("motor", name, getattr(data.motor, name), unit)
        for name, unit in _MOTOR_UNITS
        if getattr(data.motor, name) is not None
    }
    for name, value in motor.items():
        if not (math.isfinite(value) and value > 0.0):
            raise BallScrewInputError(f"motor.{name}", getattr(data.motor, name), "a value > 0")
    if motor.get("peak_torque", math.inf) < motor.get("rated_torque", 0.0):
        raise BallScrewInputError(
            "motor.peak_torque", data.motor.peak_torque,
            f"at least the rated torque {motor['rated_torque']:g} N*m (a servo motor's peak is "
            "3 to 5 times its rated torque); were the two swapped?",
        )  # fmt: skip
    _motor_electrical(data.motor, motor, si)
    return motor


def _motor_electrical(
    m: MotorSection, motor: dict[str, Any], si: Callable[[str, str, Any, str], float]
) -> None:
    """``[motor]``'s electrical constants: the resistance's kind, the iron loss's form."""
    if (m.winding_resistance is None) != (m.resistance_kind is None):
        name = "resistance_kind" if m.resistance_kind is None else "winding_resistance"
        raise BallScrewInputError(
            f"motor.{name}", "(missing)",
            "winding_resistance and resistance_kind together: the resistance, and whether it "
            "is one phase's ('phase') or between two terminals ('terminal', twice the phase's "
            "of a star); the data sheet says which",
        )  # fmt: skip
    if m.resistance_kind is not None:
        motor["resistance_kind"] = m.resistance_kind
    ends = {"torque_constant", "rated_speed"}
    if "torque_constant_at_rated_speed" in motor and not ends <= set(motor):
        raise BallScrewInputError(
            "motor.torque_constant_at_rated_speed", m.torque_constant_at_rated_speed,
            "given with motor.torque_constant (at standstill) and motor.rated_speed",
        )  # fmt: skip
    if m.iron_loss is None:
        return
    kind = ""
    for unit, form in (("N*m", "torque"), ("W", "power")):
        try:
            to_si("motor.iron_loss", _typed(m.iron_loss), unit)
        except BallScrewInputError:
            continue
        kind = form
        value = si("motor", "iron_loss", m.iron_loss, unit)
        break
    if not kind:
        raise BallScrewInputError(
            "motor.iron_loss", _typed(m.iron_loss),
            "a drag torque ('0.12 N*m') or a power at the rated speed ('40 W'), with its unit",
        )  # fmt: skip
    if not (math.isfinite(value) and value >= 0.0):
        raise BallScrewInputError("motor.iron_loss", _typed(m.iron_loss), "a value >= 0")
    if kind == "power" and "rated_speed" not in motor:
        raise BallScrewInputError(
            "motor.iron_loss", _typed(m.iron_loss),
            "a drag torque, or a power with motor.rated_speed (the speed it is given at)",
        )  # fmt: skip
    motor["iron_loss"], motor["iron_loss_kind"] = value, kind


def _case_file(text: str, source: str) -> CaseFile:
    """The TOML text parsed and validated against the case file's schema."""
    raw = parse_toml(text, source)
    if "screw" not in raw and ("machine" in raw or "axes" in raw):
        raise BallScrewInputError(
            source, "a machine file ([machine], [axes.X])",
            "a case file of one screw ([screw], [lubricant], ...); a machine file is read by "
            "'ballscrew program PROGRAM --machine FILE', and each of its axes' cases is its "
            "[axes.X.case] table (one axis alone: e.g. examples/xy_table_32x10.toml)",
        )  # fmt: skip
    try:
        return CaseFile.model_validate(raw)
    except ValidationError as exc:
        raise _validation_error(exc) from None


def _operation(
    data: CaseFile, notes: list[Assumption], read: list[Reading], lead: float | None = None
) -> tuple[list[float], list[float], list[float]]:
    """``[operation]``'s ranges: speeds [rad/s], temperatures [°C], axial loads [N].

    A speed given as a feed is the screw speed at ``lead`` [m], told in ``read``.
    """
    op = data.operation
    speed = parse_speed_range(
        "operation.speed", _unwrap("operation.speed", op.speed, notes), lead, notes=read
    )
    temperature = parse_range(
        "operation.temperature", _unwrap("operation.temperature", op.temperature, notes), "degC",
        notes=read,
    )  # fmt: skip
    axial = parse_range(
        "operation.axial_load", _unwrap("operation.axial_load", op.axial_load, notes), "N"
    )
    return speed, temperature, axial


_AXIS_UNITS = tuple(si_units(AxisSection).items())
"""The numeric ``[axis]`` keys of the axis and their SI units (from the schema)."""

_THERMAL_UNITS = tuple(si_units(AxisSection, "thermal").items())
"""The thermal ``[axis]`` keys and their SI units (from the schema)."""

_MOTOR_UNITS = tuple(si_units(MotorSection).items())
"""The ``[motor]`` keys and their SI units (from the schema)."""

_CHECK_UNITS = tuple(si_units(CheckSection).items())
"""The numeric ``[check]`` keys and their SI units (from the schema)."""


def _check(data: CaseFile, si: Callable[[str, str, Any, str], float]) -> dict[str, Any]:
    """``[check]`` in SI, each value checked for its range."""
    c = data.check
    out: dict[str, Any] = {
        name: si("check", name, getattr(c, name), unit)
        for name, unit in _CHECK_UNITS
        if getattr(c, name) is not None
    }
    for name in ("required_life", "static_safety", "support_stiffness"):
        if name in out and not (math.isfinite(out[name]) and out[name] > 0.0):
            raise BallScrewInputError(f"check.{name}", getattr(c, name), "a value > 0")
    from ..design.sizing import RELIABILITY_FACTORS, TRAVEL_VARIATION_300

    levels = [k for k in RELIABILITY_FACTORS if abs(k - out["reliability"]) < 1e-9]
    if not levels:
        raise BallScrewInputError(
            "check.reliability", c.reliability,
            "one of 90, 95, 96, 97, 98 or 99 % (ISO 3408-5's a1)",
        )  # fmt: skip
    out["reliability"] = levels[0]
    for name in ("preload_tolerance", "rating_tolerance", "mass_tolerance", "force_tolerance"):
        if name in out and not (0.0 <= out[name] < 1.0):
            raise BallScrewInputError(
                f"check.{name}", getattr(c, name), "a share from 0 to less than 100 %"
            )
    if "axial_play" in out and not (0.0 <= out["axial_play"] <= 1e-3):
        raise BallScrewInputError(
            "check.axial_play", c.axial_play, "a play from 0 to 1 mm (THK A15-19: 0 to 0.05 mm "
            "for precision nuts, up to 0.2 mm for rolled screws)",
        )  # fmt: skip
    if "load_factor" in out and not (1.0 <= out["load_factor"] <= 3.0):
        raise BallScrewInputError(
            "check.load_factor", c.load_factor,
            "a factor from 1 to 3 (THK A15-40: 1.0 to 1.2 smooth, 1.2 to 1.5 normal running, "
            "1.5 to 3 with impact or vibration)",
        )  # fmt: skip
    rise = out["pretension_temperature"]
    if not (math.isfinite(rise) and 0.0 <= rise <= MAX_PRETENSION_RISE):
        raise BallScrewInputError(
            "check.pretension_temperature", c.pretension_temperature,
            f"a temperature rise from 0 to {MAX_PRETENSION_RISE:g} K (pre-tension is set for "
            "a rise of a few K; 30 K already stresses the shaft by E alpha dT = 72 MPa"
            + ("; a temperature in K is absolute: a rise of 3 K is '3 K' or '3 degC')"
               if rise > 200.0 else ")"),
        )  # fmt: skip
    if c.accuracy_grade is not None:
        grade = c.accuracy_grade.strip().upper()
        if grade not in TRAVEL_VARIATION_300:
            raise BallScrewInputError(
                "check.accuracy_grade", c.accuracy_grade, f"one of {list(TRAVEL_VARIATION_300)}"
            )
        out["accuracy_grade"] = grade
    return out


def _sources(data: CaseFile, notes: list[Assumption]) -> dict[str, str]:
    """Where each key of the case comes from (:attr:`Case.sources`)."""
    s = data.screw
    base: set[str] = set()
    if s.designation is not None:
        raw = s.designation.value if isinstance(s.designation, Assumed) else s.designation
        base = set(resolve(str(raw)).geometry)
    given = s.model_fields_set
    out: dict[str, str] = {}
    for name in [*SCREW_UNITS, "nut"]:
        out[f"screw.{name}"] = ("given" if name in given else "catalogue" if name in base
                                else "default")  # fmt: skip
    for way in ("preload", "preload_drag_torque", "preload_share"):
        if way in given:
            out["screw.preload"] = "given" if way == "preload" else f"given as {way}"
            out[f"screw.{way}"] = "given"
    for name in ("dynamic_load_rating", "static_load_rating"):
        out[f"screw.{name}"] = ("given" if name in given else "catalogue" if s.designation
                                else "estimated or missing")  # fmt: skip
    out["lubricant.lubrication"] = (
        "given" if "lubrication" in data.lubricant.model_fields_set else "default"
    )
    for section in (data.operation, data.axis, data.motor, data.check):
        key = {id(data.operation): "operation", id(data.axis): "axis", id(data.motor): "motor",
               id(data.check): "check"}[id(section)]  # fmt: skip
        for name in type(section).model_fields:
            out[f"{key}.{name}"] = "given" if name in section.model_fields_set else "default"
    for a in notes:
        if a.reason.startswith(READ_AS):  # a text read one way ('15 m/min' as rpm): given
            continue
        if a.field in out or "." in a.field:
            out[a.field] = "assumed"
    return out


def _given_si(
    data: CaseFile, si: Callable[[str, str, Any, str], float], units: tuple[tuple[str, str], ...]
) -> dict[str, float]:
    """The ``[axis]`` keys of ``units`` the case gives, in SI."""
    return {
        name: si("axis", name, getattr(data.axis, name), unit)
        for name, unit in units
        if getattr(data.axis, name) is not None
    }


def _axis(data: CaseFile, si: Callable[[str, str, Any, str], float]) -> dict[str, Any]:
    """``[axis]`` in SI and its choices: the keywords of the axis."""
    return _given_si(data, si, _AXIS_UNITS) | {
        "bearing_type": data.axis.bearing_type,
        "bearing_lubrication": data.axis.bearing_lubrication,
        "support": data.axis.support,
    }


PLAUSIBLE: dict[str, tuple[float, float]] = {
    f"screw.{name}": (low, high) for name, low, high, _ in PLAUSIBLE_SIZES
}
"""Field -> its plausible range [SI], the sizes a :class:`BallScrew` takes: a number that
reads two ways ('3.969 mm') is read in the one way inside it."""

SCREW_UNITS: dict[str, str] = si_units(ScrewSection)
"""The SI unit of each numeric ``[screw]`` key that is a :class:`BallScrew` field ("" = none).

Read from the schema (:func:`ballscrew.io.schema.si_units`), where each key states it."""

LUBRICANT_UNITS: dict[str, str] = si_units(LubricantSection)
"""The SI unit of each numeric ``[lubricant]`` key ("" = none), from the schema."""

KEY_UNITS: dict[str, str] = _key_units()
"""The SI unit of each key a case's inputs list (:meth:`Case.input_values`), from the schema."""


_LENGTHS = ("pitch_diameter", "lead", "ball_diameter")


def _screw(
    s: ScrewSection, si: Callable[[str, str, Any, str], float], notes: list[Assumption]
) -> tuple[BallScrew, str, Ratings]:
    """The screw of a case: designation first, keys given in the file override it."""
    base, origin, catalogue = _designated(s, notes)
    geometry = _geometry(s, si, base, notes)
    rating, ratings_of = _ratings(s, si, catalogue)
    ways = [
        k for k in ("preload", "preload_drag_torque", "preload_share") if getattr(s, k) is not None
    ]
    # A plain single nut holds no preload: nothing to give (BallScrew refuses any but 0).
    unloaded = not ways and geometry.get("nut") == "single"
    if len(ways) != 1 and not unloaded:
        raise BallScrewInputError(
            "screw.preload",
            ", ".join(ways) or "(missing)",
            "exactly one of preload (a force), preload_drag_torque and preload_share "
            '(of the dynamic load rating); a single nut (nut = "single") needs none',
        )
    try:
        screw = BallScrew(preload=0.0, **geometry)
    except BallScrewInputError as exc:
        raise _as_typed(exc, "screw", s, SCREW_UNITS) from None
    if unloaded:
        notes.append(Assumption("screw.preload", "0 N", "a single nut holds no preload"))
        return screw, origin, ratings_of(screw)
    preload = _preload(s, si, screw, rating)
    try:
        screw = screw.replace(preload=preload)
    except BallScrewInputError as exc:
        raise _as_typed(exc, "screw", s, SCREW_UNITS) from None
    return screw, origin, ratings_of(screw)


class _Catalogue(NamedTuple):
    """The load ratings a designation's catalogue row gives [N], and where from."""

    dynamic: float | None
    static: float | None
    source: str


def _designated(s: ScrewSection, notes: list[Assumption]) -> tuple[dict[str, Any], str, _Catalogue]:
    """The geometry a designation gives (with its assumptions noted), its origin, ratings."""
    if s.designation is None:
        return {}, "", _Catalogue(None, None, "")
    name = str(_unwrap("screw.designation", s.designation, notes))
    resolved = resolve(name)
    base = resolved.geometry
    for key, why in resolved.notes.items():
        if key not in s.model_fields_set:
            shown = f"{base[key] * 1e3:g} mm" if key in _LENGTHS else f"{base[key]:g}"
            notes.append(Assumption(f"screw.{key}", shown, why))
    return (
        base,
        resolved.source,
        _Catalogue(
            resolved.dynamic_load_rating, resolved.static_load_rating, f"the {name} catalogue row"
        ),
    )


def _geometry(
    s: ScrewSection, si: Callable[[str, str, Any, str], float], base: dict[str, Any],
    notes: list[Assumption],
) -> dict[str, Any]:  # fmt: skip
    """The screw's keywords: given in the file, else the designation's, else the default."""
    given = s.model_fields_set
    geometry: dict[str, Any] = {}
    for name, unit in SCREW_UNITS.items():
        value = getattr(s, name)
        if name in given and value is not None:
            geometry[name] = si("screw", name, value, unit)
        elif name in base:
            geometry[name] = base[name]
        elif value is not None:  # the schema's default
            geometry[name] = si("screw", name, value, unit)
        elif name in ("pitch_diameter", "lead", "ball_diameter"):
            where = f" (the designation {s.designation!r} does not give it)" if base else ""
            raise BallScrewInputError(f"screw.{name}", "(missing)", f"a value{where}")
    if s.nut is not None:
        geometry["nut"] = _unwrap("screw.nut", s.nut, notes)
    elif "nut" in base:
        geometry["nut"] = base["nut"]
    if s.ball_separation is not None:
        geometry["ball_separation"] = _unwrap("screw.ball_separation", s.ball_separation, notes)
    circuits = geometry["circuits"]
    if circuits != int(circuits):
        raise BallScrewInputError("screw.circuits", circuits, "a whole number >= 1")
    geometry["circuits"] = int(circuits)
    return geometry


def _ratings(
    s: ScrewSection, si: Callable[[str, str, Any, str], float], catalogue: _Catalogue
) -> tuple[float | None, Callable[[BallScrew], Ratings]]:
    """C_a [N] (or None), and how the screw's ratings are made once the screw is built.

    A rating given in the file overrides the catalogue's; without a static
    rating, C_0a is estimated from the geometry.
    """
    rating, static = catalogue.dynamic, catalogue.static
    dynamic_source = static_source = catalogue.source
    if s.dynamic_load_rating is not None:
        rating = si("screw", "dynamic_load_rating", s.dynamic_load_rating, "N")
        dynamic_source = "screw.dynamic_load_rating"
    if s.static_load_rating is not None:
        static = si("screw", "static_load_rating", s.static_load_rating, "N")
        static_source = "screw.static_load_rating"
    for name, value in (("dynamic_load_rating", rating), ("static_load_rating", static)):
        if value is not None and not (math.isfinite(value) and 0.0 < value <= 1e8):
            raise BallScrewInputError(
                f"screw.{name}", getattr(s, name), "a force > 0 and <= 100 MN"
            )
    if rating is not None and static is not None and static < rating:
        raise BallScrewInputError(
            "screw.static_load_rating", s.static_load_rating or catalogue.static,
            f"at least C_a = {rating / 1e3:.4g} kN: no catalogue nut has C_0a below C_a (the "
            "bundled rows: C_0a/C_a 1.10 to 3.84); were the two ratings swapped?",
        )  # fmt: skip

    def ratings_of(screw: BallScrew) -> Ratings:
        if static is None:
            return _estimated(screw, rating, dynamic_source)
        return Ratings(rating, dynamic_source if rating else "", static, static_source)

    return rating, ratings_of


def _preload(
    s: ScrewSection, si: Callable[[str, str, Any, str], float], screw: BallScrew,
    rating: float | None,
) -> float:  # fmt: skip
    """The preload [N]: given, from a catalogue drag torque, or a share of C_a."""
    if s.preload is not None:
        return si("screw", "preload", s.preload, "N")
    if s.preload_drag_torque is not None:
        from ..design.catalog_formulas import preload_from_drag_torque

        torque = si("screw", "preload_drag_torque", s.preload_drag_torque, "N*m")
        return float(preload_from_drag_torque(torque, screw))
    share = si("screw", "preload_share", s.preload_share, "")
    if not 0.0 <= share <= 0.2:
        raise BallScrewInputError(
            "screw.preload_share", s.preload_share, "0 to 20 % (catalogues: 2 to 10 %)"
        )
    if rating is None:
        raise BallScrewInputError(
            "screw.dynamic_load_rating",
            "(missing)",
            "a force, needed by preload_share (or a designation whose catalogue row gives it)",
        )
    return share * rating


def _estimated(screw: BallScrew, dynamic: float | None, dynamic_source: str) -> Ratings:
    """Ratings with C_0a estimated from the geometry (ISO 3408-5's definition)."""
    return Ratings(
        dynamic,
        dynamic_source if dynamic else "",
        static_rating_estimate(screw),
        "estimated from the geometry: 4200 MPa at equally loaded balls; give "
        "screw.static_load_rating",
        static_estimated=True,
    )


def _lubricant(section: LubricantSection, notes: list[Assumption]) -> Lubricant:
    name = str(_unwrap("lubricant.name", section.name, notes))
    custom = {key: (unit, getattr(section, key)) for key, unit in LUBRICANT_UNITS.items()}
    given = {
        key: to_si(f"lubricant.{key}", _unwrap(f"lubricant.{key}", raw, notes), unit)
        for key, (unit, raw) in custom.items()
        if raw is not None
    }
    own = {"nu40", "nu100", "density15"}
    try:
        lubricants.get(name)
        bundled = True
    except BallScrewInputError:
        bundled = False
    if not bundled and not own <= set(given):
        missing = sorted(own - set(given))
        raise BallScrewInputError(
            f"lubricant.{missing[0]}",
            "(missing)",
            f"a value: {name!r} is not a bundled lubricant ({', '.join(lubricants.names())}), "
            f"so your own oil needs {', '.join(sorted(own))} (missing: {', '.join(missing)})",
        )
    try:
        if not given:
            return lubricants.get(name)
        if own <= set(given):
            return Lubricant.from_viscosities(
                name,
                given.pop("nu40"),
                given.pop("nu100"),
                given.pop("density15"),
                given.pop("pressure_viscosity", None),
                source="case file",
                **given,
            )
        return lubricants.get(name).replace(**given)
    except BallScrewInputError as exc:
        raise _as_typed(exc, "lubricant", section, LUBRICANT_UNITS) from None


def _lubrication(data: CaseFile, lub: Lubricant, notes: list[Assumption]) -> str | None:
    """``[lubricant] lubrication`` as given (None if not), checked against the lubricant.

    A grease cannot flood a nut, and the method given twice (also as the complete model's
    ``lubrication`` in ``[study] model_parameters``) must agree.
    """
    if "lubrication" not in data.lubricant.model_fields_set:
        return None
    raw = data.lubricant.lubrication
    method = str(_unwrap("lubricant.lubrication", raw, notes))
    try:
        lubrication_method(method, lub)
    except BallScrewInputError as exc:
        raise BallScrewInputError("lubricant.lubrication", method, exc.allowed) from None
    other = data.study.model_parameters.get("complete", {}).get("lubrication")
    if other is not None and other != method:
        raise BallScrewInputError(
            "study.model_parameters.complete.lubrication", other,
            f"the method of [lubricant] lubrication ({method!r}), or left out",
        )  # fmt: skip
    return method


def default_case_path() -> Path:
    """Path of the bundled default case (the study's set-up)."""
    return Path(str(resources.files("ballscrew").joinpath("data/kamalzadeh_stage.toml")))


def load_case(path: str | Path | None = None) -> Case:
    """Load a case file; the bundled default case when ``path`` is None."""
    file = default_case_path() if path is None else Path(path)
    text = read_input_text("case", file)
    if not text.strip():  # a failed copy or export: not "screw missing"
        raise BallScrewInputError(
            "case", str(file), "a case file with its [screw] and [lubricant] tables (this file "
            "is empty; 'ballscrew case --template' writes one to fill in)",
        )  # fmt: skip
    return parse_case(text, source=str(file))
