"""The grid of a sweep, its chunks, and the layout of its store.

:func:`plan_sweep` lays a :class:`~ballscrew.sweep.spec.SweepSpec` out as a
grid of dimensions ``model``, the outer axes (case fields, model parameters,
and ``sample`` for Monte Carlo), then ``speed``, ``temperature`` and
``axial_load``, cut into chunks of about ``chunk_points`` points (the Zarr
store's chunks). A chunk holds one model and a block of outer points (a single
screw whenever the operating grid is large). :func:`layout` says what the store
holds: its coordinates, its empty arrays and its attributes, as plain data that
:func:`ballscrew.sweep.store.create` writes. The chunks are computed by
:mod:`ballscrew.sweep.compute`.

The pipeline: spec -> plan -> (layout -> store) and (chunk -> compute -> store);
the store is handed what it writes and never reads the plan.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import math
from collections.abc import Sequence
from dataclasses import asdict, dataclass, replace
from typing import Any

import numpy as np

from .._version import __version__
from ..chain import friction_torque
from ..errors import BallScrewInputError, FloatArray
from ..friction import get_model
from ..io.case import Case
from .spec import OPERATING, OUTPUT_TABLE, OUTPUTS, SweepSpec, resolve
from .store import Layout, json_safe

__all__ = [
    "DEFAULT_MAX_POINTS",
    "LONG_NAMES",
    "Chunk",
    "Plan",
    "SweepSize",
    "check_size",
    "layout",
    "plan_sweep",
    "sweep_size",
]


@dataclass(frozen=True)
class Chunk:
    """One chunk's work, handed to :func:`ballscrew.sweep.compute.compute_chunk` whole.

    Attributes
    ----------
    index : int
        The chunk's number.
    model : str
        Its friction model, and ``parameters`` the model's fixed parameters.
    case : Case
        The base case the outer points change.
    region : tuple of slice
        Where the chunk lies in the grid (dimensions as :attr:`Plan.dims`).
    points : tuple of dict
        Field name -> value of each outer point, in C order over the chunk's outer
        positions; ``samples`` the Monte Carlo sample of each (None without samples).
    operating : tuple of array
        The chunk's speeds [rad/s], temperatures [°C] and axial loads [N].
    outputs : tuple of str
        The outputs asked for; ``components`` the names along the components' dimension.
    """

    index: int
    model: str
    parameters: dict[str, Any]
    case: Case
    region: tuple[slice, ...]
    points: tuple[dict[str, Any], ...]
    samples: tuple[int | None, ...]
    operating: tuple[FloatArray, FloatArray, FloatArray]
    outputs: tuple[str, ...]
    components: tuple[str, ...]


@dataclass(frozen=True)
class Plan:
    """The grid of a sweep, its chunks and its store's layout.

    Picklable: sent once to every worker. ``key`` identifies the sweep (a partial
    store is resumed only by the same sweep); ``layout`` is what the store is
    created with.
    """

    spec: SweepSpec
    dims: tuple[str, ...]
    shape: tuple[int, ...]
    chunks: tuple[int, ...]
    outer: tuple[str, ...]
    samples: FloatArray | None
    components: tuple[str, ...]
    model_components: dict[str, tuple[str, ...]]
    parameters: dict[str, dict[str, Any]]
    key: str = ""
    layout: Layout | None = None

    @property
    def grid(self) -> tuple[int, ...]:
        """Chunks along each dimension."""
        return tuple(-(-n // c) for n, c in zip(self.shape, self.chunks, strict=True))

    @property
    def n_chunks(self) -> int:
        """Number of chunks."""
        return math.prod(self.grid)

    @property
    def points(self) -> int:
        """Number of points (models included)."""
        return math.prod(self.shape)

    def region(self, index: int) -> tuple[slice, ...]:
        """The slices of chunk ``index`` (C order over :attr:`grid`)."""
        where = np.unravel_index(index, self.grid)
        return tuple(
            slice(int(i) * c, min((int(i) + 1) * c, n))
            for i, c, n in zip(where, self.chunks, self.shape, strict=True)
        )

    def outer_point(self, position: Sequence[int]) -> dict[str, Any]:
        """Field name -> value at one position along the outer dimensions."""
        point: dict[str, Any] = {}
        for name, i in zip(self.outer, position, strict=True):
            if name == "sample":
                assert self.samples is not None and self.spec.uncertainty is not None
                for j, dist in enumerate(self.spec.uncertainty.inputs):
                    point[dist.name] = float(self.samples[i, j])
            else:
                axis = next(a for a in self.spec.axes if a.name == name)
                point[name] = axis.values[i]
        return point

    def chunk(self, index: int) -> Chunk:
        """The work of chunk ``index``: its model, region, outer points and operating points."""
        region = self.region(index)
        n_outer = len(self.outer)
        positions = list(
            itertools.product(*(range(s.start, s.stop) for s in region[1 : 1 + n_outer]))
        )
        at = self.outer.index("sample") if "sample" in self.outer else None
        w, t, f = (
            self.spec.operating[k][s] for k, s in zip(OPERATING, region[1 + n_outer :], strict=True)
        )
        model = self.spec.models[region[0].start]
        return Chunk(
            index, model, self.parameters[model], self.spec.case, region,
            tuple(self.outer_point(p) for p in positions),
            tuple(None if at is None else p[at] for p in positions), (w, t, f),
            self.spec.outputs, self.components,
        )  # fmt: skip

    def fingerprint(self) -> str:
        """Identity of the sweep: a partial store is resumed only by the same sweep."""
        text = json.dumps(
            {
                "version": __version__,
                "sweep": self.spec.text,
                "case": self.spec.case.text,
                "shape": self.shape,
                "chunks": self.chunks,
                "dims": self.dims,
                "components": self.components,
            },
            sort_keys=True,
        )
        return hashlib.sha256(text.encode("utf-8")).hexdigest()


MAX_SCREWS_PER_CHUNK = 64
"""Outer points (screws, parameter sets) per chunk at most: each is one friction call of
a few ms, so a chunk of small operating grids still takes a fraction of a second and the
chunks spread over the workers."""


def _chunks(shape: Sequence[int], target: int, n_outer: int) -> tuple[int, ...]:
    """Chunk sizes of about ``target`` points: innermost dimensions first, one model each.

    The operating dimensions (the last three) take up to ``target`` points; the outer
    ones then take what is left, at most :data:`MAX_SCREWS_PER_CHUNK` points together.
    """
    chunks = [1] * len(shape)
    budget = target
    for d in range(len(shape) - 1, 0, -1):
        if d == n_outer:  # the innermost outer dimension: cap the screws per chunk
            budget = min(budget, MAX_SCREWS_PER_CHUNK)
        chunks[d] = max(1, min(shape[d], budget))
        budget = max(1, budget // chunks[d])
    return tuple(chunks)


@dataclass(frozen=True)
class SweepSize:
    """What a sweep asks for, known before any of it is done.

    Attributes
    ----------
    points : int
        Points, models included.
    store_bytes : int
        Size of the stored arrays (8 bytes per value; each model's components
        count once per component, taken as eight).
    seconds : float
        Time in one process at :data:`NOMINAL_RATE` points per second (the
        complete model's rate on scattered points on a 2-core machine; the
        simpler models are faster).
    """

    points: int
    store_bytes: int
    seconds: float

    def describe(self) -> str:
        """One line: points, store size and time, rounded."""
        return (
            f"{self.points:,} points, a store of about {_bytes(self.store_bytes)}, about "
            f"{_duration(self.seconds)} in one process"
        )


NOMINAL_RATE = 2e5
"""Points per second in one process, for estimates (measured: 2.4e5 for the complete model)."""

DEFAULT_MAX_POINTS = 100_000_000
"""The most points a sweep runs without ``--max-points`` (a store of a few GB)."""


def sweep_size(spec: SweepSpec) -> SweepSize:
    """The size of a sweep from its file alone: nothing is sampled, planned or computed."""
    sizes = [len(a.values) for a in spec.axes]
    u = spec.uncertainty
    if u is not None:
        sizes.append(u.samples * (len(u.inputs) + 2) if u.sensitivity == "sobol" else u.samples)
    points = (
        len(spec.models) * math.prod(sizes) * math.prod(spec.operating[k].size for k in OPERATING)
    )
    per_point = sum(8 if name == "components" else 1 for name in spec.outputs)
    return SweepSize(points, 8 * points * per_point, points / NOMINAL_RATE)


def check_size(size: SweepSize, max_points: int = DEFAULT_MAX_POINTS) -> None:
    """Refuse a sweep larger than ``max_points``, with its size and how to allow it."""
    if size.points > max_points:
        raise BallScrewInputError(
            "sweep size", f"{size.points:,} points",
            f"at most {max_points:,} points (this one needs a store of about "
            f"{_bytes(size.store_bytes)} and about {_duration(size.seconds)} in one process); "
            "take fewer values per axis, or raise the limit with --max-points if it is meant",
        )  # fmt: skip


def _bytes(n: float) -> str:
    for unit in ("B", "kB", "MB", "GB", "TB", "PB"):
        if n < 1000.0:
            return f"{n:.3g} {unit}"
        n /= 1000.0
    return f"{n:.3g} EB"


def _duration(seconds: float) -> str:
    for unit, size in (("days", 86400.0), ("h", 3600.0), ("min", 60.0)):
        if seconds >= size:
            return f"{seconds / size:.3g} {unit}"
    return f"{seconds:.2g} s"


def plan_sweep(spec: SweepSpec) -> Plan:
    """Lay out the grid, draw the Monte Carlo inputs and check every outer point."""
    from .sensitivity import sample

    samples = None
    outer = [a.name for a in spec.axes]
    sizes = [len(a.values) for a in spec.axes]
    u = spec.uncertainty
    if u is not None:
        samples = sample(u.inputs, u.samples, u.seed, sobol=u.sensitivity == "sobol")
        outer.append("sample")
        sizes.append(samples.shape[0])
    dims = ("model", *outer, *OPERATING)
    shape = (len(spec.models), *sizes, *(spec.operating[k].size for k in OPERATING))
    parameters: dict[str, dict[str, Any]] = {}
    model_components: dict[str, tuple[str, ...]] = {}
    for model in spec.models:
        parameters[model] = dict(spec.parameters.get(model, {}))
        result = friction_torque(
            spec.case.screw, spec.case.lubricant, speed=1.0, temperature=20.0,
            model=model, warn=False, **parameters[model],
        )  # fmt: skip
        model_components[model] = tuple(result.components)
    components = tuple(dict.fromkeys(c for m in spec.models for c in model_components[m]))
    plan = Plan(
        spec, dims, shape, _chunks(shape, spec.chunk_points, len(outer)), tuple(outer), samples,
        components, model_components, parameters,
    )  # fmt: skip
    # Every outer point builds a valid screw and lubricant, or the sweep is refused now.
    for position in itertools.product(*(range(n) for n in sizes)):
        point = plan.outer_point(position)
        try:
            resolve(spec.case, spec.models[0], {}, point)
        except BallScrewInputError as exc:
            shown = ", ".join(f"{k} = {v:g}" if isinstance(v, float) else f"{k} = {v}"
                              for k, v in point.items())  # fmt: skip
            raise BallScrewInputError(exc.field, exc.value, f"{exc.allowed} (at {shown})") from None
    return replace(plan, key=plan.fingerprint(), layout=layout(plan))


LONG_NAMES = {
    **{o.name: o.long_name for o in OUTPUT_TABLE},
    "speed": "screw speed",
    "temperature": "lubricant temperature",
    "axial_load": "external axial load on the nut",
}
"""The long name of every stored output and operating axis."""


def attributes(plan: Plan) -> dict[str, Any]:
    """The store's attributes: inputs, units, parameters, version."""
    spec = plan.spec
    units: dict[str, str] = {name: OUTPUTS[name] for name in spec.outputs}
    units |= {name: unit for name, unit in OPERATING.items()}
    units |= {a.name: a.unit for a in spec.axes}
    parameters = {}
    for model in spec.models:
        used = dict(get_model(model).parameters)
        used.update(plan.parameters[model])
        parameters[model] = used
    attrs: dict[str, Any] = {
        "title": f"ballscrew sweep: {spec.case.title}",
        "ballscrew_version": __version__,
        "sweep_file": spec.source,
        "sweep_toml": spec.text,
        "case_toml": spec.case.text,
        "models": list(spec.models),
        "model_parameters": parameters,
        "units": units,
        "screw": asdict(spec.case.screw),
        "lubricant": asdict(spec.case.lubricant),
        "axes": {a.name: a.unit for a in spec.axes},
        "chunk_points": spec.chunk_points,
        "conventions": "SI units (temperatures in degC); speed > 0 turns the screw forward",
    }
    u = spec.uncertainty
    if u is not None:
        units |= {d.name: d.unit or "1" for d in u.inputs}
        attrs["uncertainty"] = {
            "inputs": {d.name: d.describe() for d in u.inputs},
            "samples": u.samples,
            "seed": u.seed,
            "sensitivity": u.sensitivity,
            "design": (
                "Saltelli/Sobol' (SALib sobol.sample, no second order): N (D + 2) rows"
                if u.sensitivity == "sobol"
                else "Latin hypercube (SALib latin.sample)"
            ),
        }
    return json_safe(attrs)  # type: ignore[no-any-return]


def layout(plan: Plan) -> Layout:
    """The store's coordinates, empty arrays and attributes (nothing is computed)."""
    spec = plan.spec
    coords: dict[str, tuple[tuple[str, ...], Any, dict[str, Any]]] = {
        "model": (("model",), np.array(spec.models, dtype=object), {})
    }
    for axis in spec.axes:
        values = np.array(axis.values, dtype=object if axis.labels else float)
        coords[axis.name] = ((axis.name,), values, {"units": axis.unit})
    if plan.samples is not None:
        assert spec.uncertainty is not None
        coords["sample"] = (("sample",), np.arange(plan.samples.shape[0]), {})
        for j, dist in enumerate(spec.uncertainty.inputs):
            attrs = {"units": dist.unit or "1", "distribution": dist.describe()}
            coords[dist.name] = (("sample",), plan.samples[:, j], attrs)
    for name, unit in OPERATING.items():
        coords[name] = (
            (name,),
            spec.operating[name],
            {"units": unit, "long_name": LONG_NAMES[name]},
        )
    coords["speed_rpm"] = (("speed",), spec.operating["speed"] * 30.0 / np.pi, {"units": "rpm"})
    variables = {}
    cut = 1 + len(plan.outer)
    for name in spec.outputs:
        dims, shape, chunks = plan.dims, plan.shape, plan.chunks
        if name == "components":
            dims = (*dims[:cut], "component", *dims[cut:])
            shape = (*shape[:cut], len(plan.components), *shape[cut:])
            chunks = (*chunks[:cut], len(plan.components), *chunks[cut:])
        attrs = {"units": OUTPUTS[name], "long_name": LONG_NAMES[name]}
        variables[name] = (dims, shape, chunks, attrs)
    if "components" in spec.outputs:
        coords["component"] = (("component",), np.array(plan.components, dtype=object), {})
    return Layout(coords, variables, attributes(plan))
