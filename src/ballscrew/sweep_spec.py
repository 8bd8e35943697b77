"""Sweep files: what a design-space sweep or an uncertainty study varies, read and checked.

A sweep file is TOML (``docs/sweeps.md`` lists every key)::

    case = "my_screw.toml"            # relative to the sweep file; or an inline [case] table
    models = ["complete", "catalog"]
    outputs = ["torque", "efficiency", "power_loss", "components"]

    [axes]
    speed = "10..3000:30 rpm"         # the operating points: one friction call per chunk
    temperature = "20, 40 degC"
    axial_load = "0..5 kN:6"
    "screw.preload" = "1, 2, 3 kN"    # a case field: the outer loop, one screw at a time
    "complete.ball_train_constant" = [0.03, 0.0474, 0.07]   # a model parameter

    [uncertainty]                     # optional: Monte Carlo and Sobol indices
    samples = 256
    seed = 1
    sensitivity = "sobol"
    [uncertainty.inputs]
    "screw.preload" = { distribution = "normal", mean = "2 kN", std = "0.2 kN" }

Every dimensional value carries its unit, as in case files; a bare number
for one is an error naming the key. :func:`parse_sweep` turns the file into
a :class:`SweepSpec` in SI units; :func:`resolve` applies the outer-axis
values of one point to the case's screw, lubricant and model parameters.
"""

from __future__ import annotations

import difflib
import math
import tomllib
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import tomlkit

from . import lubricants
from .case import LUBRICANT_UNITS, SCREW_UNITS, Case, load_case, parse_case
from .errors import BallScrewInputError, FloatArray
from .friction import MODELS, get_model
from .geometry import NUT_ARRANGEMENTS, BallScrew
from .lubricant import Lubricant
from .units import parse_range, to_si

__all__ = [
    "OPERATING",
    "OUTPUTS",
    "Axis",
    "Distribution",
    "SweepSpec",
    "Uncertainty",
    "field_unit",
    "load_sweep",
    "parse_sweep",
    "resolve",
]

OPERATING: dict[str, str] = {"speed": "rad/s", "temperature": "degC", "axial_load": "N"}
"""The operating-point axes and their units: broadcast in one friction call per chunk."""

OUTPUTS: dict[str, str] = {
    "torque": "N*m",
    "efficiency": "1",
    "power_loss": "W",
    "components": "N*m",
}
"""The outputs a sweep can store, with their units."""

DERIVED: dict[str, str] = {
    "lubricant.viscosity_scale": "factor on the data-sheet viscosities nu40 and nu100",
}
"""Sweep-only fields that are not case keys, with what they do."""

TOP_KEYS = ("case", "models", "outputs", "chunk_points", "axes", "parameters", "uncertainty")
UNCERTAINTY_KEYS = ("samples", "seed", "sensitivity", "percentiles", "inputs")
DISTRIBUTIONS: dict[str, tuple[str, str]] = {
    "normal": ("mean", "std"),
    "uniform": ("low", "high"),
    "lognormal": ("median", "sigma"),
}
"""Distribution name -> its two parameters (lognormal: median and the std of ln)."""


@dataclass(frozen=True)
class Axis:
    """One varied quantity: its field name, values (SI, or labels) and SI unit."""

    name: str
    values: Sequence[Any]
    unit: str

    @property
    def labels(self) -> bool:
        """True for an axis of text values (lubricant names, model choices)."""
        return any(isinstance(v, str | bool) for v in self.values)


@dataclass(frozen=True)
class Distribution:
    """An uncertain input: field name, distribution and its two parameters in SI."""

    name: str
    kind: str
    first: float
    second: float
    unit: str

    def salib(self) -> tuple[str, list[float]]:
        """SALib's name and bounds of this distribution."""
        if self.kind == "normal":
            return "norm", [self.first, self.second]
        if self.kind == "uniform":
            return "unif", [self.first, self.second]
        return "lognorm", [math.log(self.first), self.second]

    def describe(self) -> str:
        """The distribution in words, in SI units."""
        a, b = DISTRIBUTIONS[self.kind]
        unit = f" {self.unit}" if self.unit not in ("", "1") else ""
        second = f"{self.second:g}" if self.kind == "lognormal" else f"{self.second:g}{unit}"
        return f"{self.kind}({a} {self.first:g}{unit}, {b} {second})"


@dataclass(frozen=True)
class Uncertainty:
    """``[uncertainty]``: the uncertain inputs and how they are sampled."""

    inputs: tuple[Distribution, ...]
    samples: int
    seed: int
    sensitivity: str
    percentiles: tuple[float, ...]


@dataclass(frozen=True)
class SweepSpec:
    """A checked sweep file in SI units.

    Attributes
    ----------
    case : Case
        The base case; its screw, lubricant and model parameters are varied.
    models : tuple of str
        Friction models to run.
    outputs : tuple of str
        Stored outputs, from :data:`OUTPUTS`.
    operating : dict
        ``speed`` [rad/s], ``temperature`` [°C], ``axial_load`` [N] values.
    axes : tuple of Axis
        The outer axes (case fields and model parameters), in file order.
    parameters : dict
        Model name -> fixed parameters (the case's, then the sweep file's).
    uncertainty : Uncertainty or None
        The Monte Carlo and sensitivity settings.
    chunk_points : int
        Points per stored chunk (target); default the smallest ``ModelSpec.chunk``
        of the models (131072 for all but harris-full's 4096).
    text : str
        The sweep file's text.
    """

    case: Case
    models: tuple[str, ...]
    outputs: tuple[str, ...]
    operating: dict[str, FloatArray]
    axes: tuple[Axis, ...]
    parameters: dict[str, dict[str, Any]]
    uncertainty: Uncertainty | None
    chunk_points: int
    text: str
    source: str = "sweep"


def field_unit(name: str, models: Sequence[str], where: str = "") -> tuple[str, str | None]:
    """Where a varied field lives (``screw``, ``lubricant`` or a model) and its SI unit.

    The unit is None for a model parameter (numbers in SI, or quantities
    converted to SI base units) and ``"-"`` for a field of text values.
    ``where`` names the key in errors (default: ``axes.NAME``).
    """
    where = where or f"axes.{name}"
    owner, _, key = name.partition(".")
    if owner == "screw":
        if key == "preload":
            return owner, "N"
        if key == "nut":
            return owner, "-"
        if key in SCREW_UNITS:
            return owner, SCREW_UNITS[key]
        allowed = ["preload", "nut", *SCREW_UNITS]
    elif owner == "lubricant":
        if key == "name":
            return owner, "-"
        if key == "viscosity_scale":
            return owner, ""
        if key in LUBRICANT_UNITS:
            return owner, LUBRICANT_UNITS[key]
        allowed = ["name", "viscosity_scale", *LUBRICANT_UNITS]
    elif owner in MODELS:
        if owner not in models:
            raise BallScrewInputError(
                where, name, f"a parameter of a model in models ({list(models)})"
            )
        if key in MODELS[owner].parameters:
            return owner, None
        allowed = sorted(MODELS[owner].parameters)
    else:
        raise BallScrewInputError(
            where,
            name,
            "speed, temperature, axial_load, screw.KEY, lubricant.KEY or MODEL.PARAMETER "
            f"(models: {sorted(MODELS)})",
        )
    raise BallScrewInputError(
        where,
        name,
        f"one of {', '.join(f'{owner}.{k}' for k in allowed)}{_hint(key, allowed, owner)}",
    )


def _hint(key: str, allowed: Sequence[str], prefix: str = "") -> str:
    """'; did you mean X?' for a misspelt or shortened key, else ''."""
    close = difflib.get_close_matches(key, list(allowed), n=1)
    close = close or [k for k in allowed if key and k.startswith(key)][:1]
    dotted = f"{prefix}." if prefix else ""
    return f"; did you mean {dotted}{close[0]}?" if close else ""


def _values(where: str, raw: Any, unit: str | None, default: Any = None) -> list[Any]:
    """An axis's values: a string list or range with its unit, or a TOML list."""
    if unit == "-":  # text values: a list of names, or one name
        items = raw if isinstance(raw, list) else [raw]
        if not items or not all(isinstance(v, str) for v in items):
            raise BallScrewInputError(where, raw, "a name or a list of names")
        return list(items)
    if isinstance(default, bool) or isinstance(default, str):
        items = raw if isinstance(raw, list) else [raw]
        kind = type(default)
        if not items or not all(isinstance(v, kind) for v in items):
            raise BallScrewInputError(where, raw, f"a list of {kind.__name__} values")
        return list(items)
    if isinstance(raw, str):
        values = parse_range(where, raw, unit)
    elif isinstance(raw, list) and raw:
        values = [to_si(f"{where}[{i}]", v, unit) for i, v in enumerate(raw)]
    elif isinstance(raw, int | float) and not isinstance(raw, bool):
        values = [to_si(where, raw, unit)]
    else:
        allowed = "a list 'a, b unit', a range 'a..b:n unit' or a TOML list"
        raise BallScrewInputError(where, raw, allowed)
    if isinstance(default, int):  # a count (nodes of a quadrature): whole numbers
        if not all(v == int(v) for v in values):
            raise BallScrewInputError(where, raw, "whole numbers")
        return [int(v) for v in values]
    return values


def resolve(
    case: Case, model: str, parameters: Mapping[str, Any], point: Mapping[str, Any]
) -> tuple[BallScrew, Lubricant, dict[str, Any]]:
    """The screw, lubricant and model parameters at one outer point.

    ``point`` maps field names (``screw.preload``, ``lubricant.name``,
    ``complete.ball_train_constant``) to SI values; a model parameter of
    another model than ``model`` is ignored.
    """
    screw_changes: dict[str, Any] = {}
    lub_changes: dict[str, Any] = {}
    params = dict(parameters)
    lubricant = case.lubricant
    scale = 1.0
    for name, value in point.items():
        owner, _, key = name.partition(".")
        if owner == "screw":
            screw_changes[key] = int(value) if key == "circuits" else value
        elif owner == "lubricant":
            if key == "name":
                lubricant = lubricants.get(str(value))
            elif key == "viscosity_scale":
                scale = float(value)
            else:
                lub_changes[key] = value
        elif owner == model:
            params[key] = value
    try:
        screw = case.screw.replace(**screw_changes) if screw_changes else case.screw
    except BallScrewInputError as exc:
        raise BallScrewInputError(f"screw.{exc.field}", exc.value, exc.allowed) from None
    if scale != 1.0:
        lub_changes.setdefault("nu40", lubricant.nu40)
        lub_changes.setdefault("nu100", lubricant.nu100)
        lub_changes["nu40"] *= scale
        lub_changes["nu100"] *= scale
    try:
        lubricant = lubricant.replace(**lub_changes) if lub_changes else lubricant
    except BallScrewInputError as exc:
        raise BallScrewInputError(f"lubricant.{exc.field}", exc.value, exc.allowed) from None
    return screw, lubricant, params


def _check(case: Case, models: Sequence[str], where: str, name: str, value: Any) -> None:
    """Build the screw and lubricant with one value, so that a bad one is named now."""
    try:
        resolve(case, models[0], {}, {name: value})
    except BallScrewInputError as exc:
        raise BallScrewInputError(where, value, exc.allowed) from None
    if name == "screw.circuits" and value != int(value):
        raise BallScrewInputError(where, value, "a whole number >= 1")
    if name == "screw.nut" and value not in NUT_ARRANGEMENTS:
        raise BallScrewInputError(where, value, f"one of {list(NUT_ARRANGEMENTS)}")


def _unknown(where: str, given: Mapping[str, Any], allowed: Sequence[str]) -> None:
    for key in given:
        if key not in allowed:
            raise BallScrewInputError(
                f"{where}{key}", given[key], f"one of the keys {list(allowed)}{_hint(key, allowed)}"
            )


def _case(raw: Mapping[str, Any], folder: Path) -> Case:
    entry = raw.get("case")
    if entry is None:
        return load_case(None)
    if isinstance(entry, str):
        path = Path(entry)
        return load_case(path if path.is_absolute() else folder / path)
    if isinstance(entry, dict):
        try:
            return parse_case(tomlkit.dumps(entry), source="case")
        except BallScrewInputError as exc:
            raise BallScrewInputError(f"case.{exc.field}", exc.value, exc.allowed) from None
    raise BallScrewInputError("case", entry, "a case file path or an inline [case] table")


def _names(key: str, raw: Any, default: list[str], allowed: Sequence[str]) -> tuple[str, ...]:
    items = default if raw is None else raw
    if isinstance(items, str):
        items = [items]
    if not isinstance(items, list) or not items or not all(isinstance(x, str) for x in items):
        raise BallScrewInputError(key, raw, f"a list of names from {list(allowed)}")
    for item in items:
        if item not in allowed:
            raise BallScrewInputError(key, item, f"one of {list(allowed)}")
    if len(set(items)) != len(items):
        raise BallScrewInputError(key, raw, "each name once")
    return tuple(items)


def _distribution(where: str, name: str, raw: Any, unit: str | None) -> Distribution:
    if not isinstance(raw, dict) or "distribution" not in raw:
        raise BallScrewInputError(
            where, raw, "a table { distribution = 'normal', mean = ..., std = ... }"
        )
    kind = raw["distribution"]
    if kind not in DISTRIBUTIONS:
        raise BallScrewInputError(f"{where}.distribution", kind, f"one of {list(DISTRIBUTIONS)}")
    a, b = DISTRIBUTIONS[kind]
    _unknown(f"{where}.", raw, ["distribution", a, b])
    for key in (a, b):
        if key not in raw:
            raise BallScrewInputError(f"{where}.{key}", "(missing)", f"a value ({kind}: {a}, {b})")
    first = to_si(f"{where}.{a}", raw[a], unit)
    second = to_si(f"{where}.{b}", raw[b], "" if kind == "lognormal" else unit)
    if kind == "uniform" and not second > first:
        raise BallScrewInputError(f"{where}.high", raw[b], f"a value above low ({raw[a]})")
    if kind != "uniform" and not second > 0.0:
        raise BallScrewInputError(f"{where}.{b}", raw[b], "a value > 0")
    if kind == "lognormal" and not first > 0.0:
        raise BallScrewInputError(f"{where}.median", raw[a], "a value > 0")
    return Distribution(name, kind, first, second, unit or "")


def _uncertainty(raw: Any, case: Case, models: Sequence[str], taken: set[str]) -> Uncertainty:
    if not isinstance(raw, dict):
        raise BallScrewInputError("uncertainty", raw, "a table")
    _unknown("uncertainty.", raw, UNCERTAINTY_KEYS)
    sensitivity = raw.get("sensitivity", "none")
    if sensitivity not in ("none", "sobol"):
        raise BallScrewInputError("uncertainty.sensitivity", sensitivity, "'sobol' or 'none'")
    samples = raw.get("samples", 256)
    if isinstance(samples, bool) or not isinstance(samples, int) or not 2 <= samples <= 1 << 24:
        raise BallScrewInputError("uncertainty.samples", samples, "a whole number from 2 to 2^24")
    if sensitivity == "sobol" and samples & (samples - 1):
        raise BallScrewInputError(
            "uncertainty.samples",
            samples,
            "a power of 2 for Sobol indices (the balance of Sobol' points needs it)",
        )
    seed = raw.get("seed", 0)
    if isinstance(seed, bool) or not isinstance(seed, int) or seed < 0:
        raise BallScrewInputError("uncertainty.seed", seed, "a whole number >= 0")
    percentiles = raw.get("percentiles", [5, 50, 95])
    if (
        not isinstance(percentiles, list)
        or not percentiles
        or not all(isinstance(p, int | float) and not isinstance(p, bool) for p in percentiles)
        or not all(0 <= p <= 100 for p in percentiles)
    ):
        raise BallScrewInputError(
            "uncertainty.percentiles", percentiles, "a list of numbers from 0 to 100"
        )
    inputs = raw.get("inputs")
    if not isinstance(inputs, dict) or not inputs:
        raise BallScrewInputError(
            "uncertainty.inputs", inputs, "a table of uncertain fields and their distributions"
        )
    found = []
    for name, entry in inputs.items():
        where = f"uncertainty.inputs.{name}"
        if name in OPERATING:
            raise BallScrewInputError(
                where, name, "a case field or model parameter (vary speed etc. under [axes])"
            )
        if name in taken:
            raise BallScrewInputError(where, name, "a field that is not also an axis")
        _, unit = field_unit(name, models, where)
        if unit == "-":
            raise BallScrewInputError(where, name, "a numeric field (text fields have no spread)")
        dist = _distribution(where, name, entry, unit)
        for value in (dist.first, dist.first + dist.second) if dist.kind != "uniform" else ():
            _check(case, models, where, name, value)
        if dist.kind == "uniform":
            _check(case, models, f"{where}.low", name, dist.first)
            _check(case, models, f"{where}.high", name, dist.second)
        found.append(dist)
    if sensitivity == "sobol" and len(found) < 2:
        raise BallScrewInputError(
            "uncertainty.inputs", list(inputs), "at least two inputs for Sobol indices"
        )
    return Uncertainty(
        tuple(found), samples, seed, sensitivity, tuple(float(p) for p in percentiles)
    )


def parse_sweep(text: str, *, folder: str | Path = ".", source: str = "sweep") -> SweepSpec:
    """Check a sweep file given as text; relative case paths are read from ``folder``."""
    try:
        raw = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise BallScrewInputError(source, "(file)", f"valid TOML ({exc})") from None
    _unknown("", raw, TOP_KEYS)
    case = _case(raw, Path(folder))
    models = _names("models", raw.get("models"), ["complete"], sorted(MODELS))
    outputs = _names(
        "outputs", raw.get("outputs"), ["torque", "efficiency", "power_loss"], list(OUTPUTS)
    )
    # Default: the smallest of the models' own chunks (1 MB per output for most), so that
    # each friction call stays on the chain's unexpanded-grid path, whose memory the model's
    # chunk bounds.
    chunk_points = raw.get("chunk_points", min(MODELS[m].chunk for m in models))
    if isinstance(chunk_points, bool) or not isinstance(chunk_points, int) or chunk_points < 1:
        raise BallScrewInputError("chunk_points", chunk_points, "a whole number >= 1")
    parameters = {m: dict(case.model_parameters.get(m, {})) for m in models}
    fixed = raw.get("parameters", {})
    if not isinstance(fixed, dict):
        raise BallScrewInputError("parameters", fixed, "a table [parameters.MODEL]")
    for model, given in fixed.items():
        if model not in models:
            raise BallScrewInputError(f"parameters.{model}", model, f"a model of {list(models)}")
        if not isinstance(given, dict):
            raise BallScrewInputError(f"parameters.{model}", given, "a table of parameters")
        get_model(model).check_parameters(given)
        parameters[model].update(given)
    axes_raw = raw.get("axes", {})
    if not isinstance(axes_raw, dict):
        raise BallScrewInputError("axes", axes_raw, "a table of fields and their values")
    operating = {
        "speed": case.speed,
        "temperature": case.temperature,
        "axial_load": case.axial_load,
    }
    axes: list[Axis] = []
    for name, value in axes_raw.items():
        where = f"axes.{name}"
        if name in OPERATING:
            operating[name] = np.asarray(_values(where, value, OPERATING[name]), dtype=float)
            continue
        owner, unit = field_unit(name, models, where)
        default = MODELS[owner].parameters[name.partition(".")[2]] if owner in MODELS else None
        values = _values(where, value, unit, default)
        if owner in ("screw", "lubricant"):
            for v in values:
                _check(case, models, where, name, v)
        if len(set(values)) != len(values):
            raise BallScrewInputError(where, value, "values that differ from each other")
        axes.append(Axis(name, tuple(values), "1" if unit in ("", None) else unit))
    uncertainty = None
    if "uncertainty" in raw:
        uncertainty = _uncertainty(raw["uncertainty"], case, models, {a.name for a in axes})
        if uncertainty.sensitivity == "sobol" and axes:
            raise BallScrewInputError(
                "axes",
                ", ".join(a.name for a in axes),
                "only speed, temperature and axial_load beside Sobol sensitivity (the "
                "indices are those of the torque averaged over the operating points)",
            )
    return SweepSpec(
        case=case,
        models=models,
        outputs=outputs,
        operating=operating,
        axes=tuple(axes),
        parameters=parameters,
        uncertainty=uncertainty,
        chunk_points=chunk_points,
        text=text,
        source=source,
    )


def load_sweep(path: str | Path) -> SweepSpec:
    """Read and check a sweep file."""
    file = Path(path)
    try:
        text = file.read_bytes().decode("utf-8")
    except OSError as exc:
        raise BallScrewInputError("sweep", str(file), f"a readable file ({exc.strerror})") from None
    except UnicodeDecodeError:
        raise BallScrewInputError("sweep", str(file), "a UTF-8 text file") from None
    return parse_sweep(text, folder=file.parent, source=str(file))
