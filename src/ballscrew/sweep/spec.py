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
    "complete.ball_train_constant" = [0.025, 0.0358, 0.05]   # a model parameter

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

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
import tomlkit

from ..chain import FrictionResult
from ..design.limits import check_operating_bounds
from ..errors import BallScrewInputError, FloatArray
from ..friction import MODELS, get_model
from ..io.case import Case, load_case, parse_case, parse_toml
from ..io.files import read_input_text
from ..io.units import parse_range, to_si
from .fields import (
    OPERATING,
    check_value,
    field_unit,
    resolve,
    unknown_keys,
)
from .uncertainty import Distribution, Uncertainty, parse_uncertainty

__all__ = [
    "OPERATING",
    "OUTPUTS",
    "OUTPUT_TABLE",
    "SCALAR_OUTPUTS",
    "Axis",
    "Distribution",
    "Output",
    "SweepSpec",
    "Uncertainty",
    "field_unit",
    "load_sweep",
    "parse_sweep",
    "resolve",
]


@dataclass(frozen=True)
class Output:
    """One output a sweep can store: name, unit (stored and shown), long name, how to read it.

    ``read`` takes a :class:`ballscrew.FrictionResult` and gives the output's
    array; None for ``components``, which has a dimension of its own.
    """

    name: str
    unit: str
    shown_unit: str
    long_name: str
    read: Callable[[FrictionResult], FloatArray] | None


OUTPUT_TABLE: tuple[Output, ...] = (
    Output("torque", "N*m", "N·m", "friction torque on the screw", lambda r: r.total),
    Output("efficiency", "1", "-", "forward efficiency, rotation to translation",
           lambda r: r.efficiency),
    Output("power_loss", "W", "W", "friction power loss", lambda r: r.power_loss),
    Output("components", "N*m", "N·m", "torque contribution of each loss mechanism", None),
)  # fmt: skip
"""The outputs a sweep can store: the plan, the store and the command iterate over it."""

OUTPUTS: dict[str, str] = {o.name: o.unit for o in OUTPUT_TABLE}
"""The outputs a sweep can store, with their units."""

SCALAR_OUTPUTS: tuple[Output, ...] = tuple(o for o in OUTPUT_TABLE if o.read is not None)
"""The outputs with one value per point (all but ``components``)."""

TOP_KEYS = ("case", "models", "outputs", "chunk_points", "axes", "parameters", "uncertainty")


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


def parse_sweep(text: str, *, folder: str | Path = ".", source: str = "sweep") -> SweepSpec:
    """Check a sweep file given as text; relative case paths are read from ``folder``."""
    raw = parse_toml(text, source)
    unknown_keys("", raw, TOP_KEYS)
    case = _case(raw, Path(folder))
    models = _names("models", raw.get("models"), ["complete"], sorted(MODELS))
    outputs = _names("outputs", raw.get("outputs"), [o.name for o in SCALAR_OUTPUTS], list(OUTPUTS))
    # Default: the smallest of the models' own chunks (1 MB per output for most), so that
    # each friction call stays on the chain's unexpanded-grid path, whose memory the model's
    # chunk bounds.
    chunk_points = raw.get("chunk_points", min(MODELS[m].chunk for m in models))
    if isinstance(chunk_points, bool) or not isinstance(chunk_points, int) or chunk_points < 1:
        raise BallScrewInputError("chunk_points", chunk_points, "a whole number >= 1")
    parameters = {m: case.parameters_for(m) for m in models}
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
            bounds = {k: operating[k] if k == name else 0.0 for k in OPERATING}
            check_operating_bounds(**bounds, prefix="axes.")  # named as the file names it
            if name == "temperature":
                case.lubricant.check_temperature(where, operating[name])
            continue
        owner, unit = field_unit(name, models, where)
        default = MODELS[owner].parameters[name.partition(".")[2]] if owner in MODELS else None
        values = _values(where, value, unit, default)
        if owner in ("screw", "lubricant"):
            for v in values:
                check_value(case, models, where, name, v)
        if len(set(values)) != len(values):
            raise BallScrewInputError(where, value, "values that differ from each other")
        axes.append(Axis(name, tuple(values), "1" if unit in ("", None) else unit))
    uncertainty = None
    if "uncertainty" in raw:
        uncertainty = parse_uncertainty(raw["uncertainty"], case, models, {a.name for a in axes})
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
    text = read_input_text("sweep", file)
    return parse_sweep(text, folder=file.parent, source=str(file))
