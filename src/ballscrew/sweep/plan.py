"""The grid of a sweep, its chunks, and the evaluation of one chunk.

:func:`plan_sweep` lays a :class:`~ballscrew.sweep.spec.SweepSpec` out as a
grid of dimensions ``model``, the outer axes (case fields, model parameters,
and ``sample`` for Monte Carlo), then ``speed``, ``temperature`` and
``axial_load``, cut into chunks of about ``chunk_points`` points (the Zarr
store's chunks). A chunk holds one model and a block of outer points (a single
screw whenever the operating grid is large); :func:`compute_chunk` calls
:func:`ballscrew.chain.friction_torque` once per screw with the chunk's
operating points as an unexpanded outer product, so the screw-dependent state
is built once per chunk, never per point, and no Python loop runs over
operating points. :func:`run_chunk` writes a chunk into the store (a Zarr
region write) and then marks it done; it runs in this process or on a Dask
worker alike, which is why every execution mode gives the same arrays.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import math
import os
import resource
import sys
import time
from collections.abc import Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .._version import __version__
from ..chain import friction_torque
from ..errors import BallScrewInputError, FloatArray
from ..io.files import atomic_write, deferred_signals
from .spec import OPERATING, OUTPUTS, SCALAR_OUTPUTS, SweepSpec, resolve

__all__ = [
    "DEFAULT_MAX_POINTS",
    "ChunkReport",
    "Plan",
    "SweepSize",
    "check_size",
    "compute_chunk",
    "plan_sweep",
    "run_chunk",
    "sweep_size",
]


@dataclass(frozen=True)
class Plan:
    """The grid of a sweep and its chunks (picklable: sent once to every worker)."""

    spec: SweepSpec
    dims: tuple[str, ...]
    shape: tuple[int, ...]
    chunks: tuple[int, ...]
    outer: tuple[str, ...]
    samples: FloatArray | None
    components: tuple[str, ...]
    model_components: dict[str, tuple[str, ...]]
    parameters: dict[str, dict[str, Any]]

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
    return plan


@dataclass
class ChunkReport:
    """What one chunk gave: its index, size, time, process, summary numbers and issues."""

    index: int
    points: int
    seconds: float
    pid: int
    peak_rss: int
    stats: dict[str, dict[str, list[float]]] = field(default_factory=dict)
    issues: dict[str, tuple[float, str]] = field(default_factory=dict)


def compute_chunk(plan: Plan, index: int) -> tuple[dict[str, FloatArray], ChunkReport]:
    """Every output of chunk ``index``, and its report (no file is touched)."""
    start = time.perf_counter()
    region = plan.region(index)
    model = plan.spec.models[region[0].start]
    n_outer = len(plan.outer)
    op = region[1 + n_outer :]
    w, t, f = (plan.spec.operating[k][s] for k, s in zip(OPERATING, op, strict=True))
    shape = tuple(s.stop - s.start for s in region)
    asked = [o for o in SCALAR_OUTPUTS if o.name in plan.spec.outputs]  # only what was asked
    with_components = "components" in plan.spec.outputs
    out = {o.name: np.full(shape, np.nan) for o in asked}
    comp_shape = (*shape[: 1 + n_outer], len(plan.components), *shape[1 + n_outer :])
    components = np.full(comp_shape if with_components else (0,), np.nan)
    issues: dict[str, tuple[float, str]] = {}
    outer_ranges = [range(s.start, s.stop) for s in region[1 : 1 + n_outer]]
    for position in itertools.product(*outer_ranges):  # screws, never operating points
        local = (0, *(p - s.start for p, s in zip(position, region[1:], strict=False)))
        screw, lubricant, params = resolve(
            plan.spec.case, model, plan.parameters[model], plan.outer_point(position)
        )
        r = friction_torque(
            screw, lubricant, speed=w[:, None, None], temperature=t[None, :, None],
            axial_load=f[None, None, :], model=model, warn=False,
            chunk_size=max(len(w) * len(t) * len(f), 1), **params,
        )  # fmt: skip
        for o in asked:
            assert o.read is not None
            out[o.name][local] = o.read(r)
        for name, value in r.components.items() if with_components else ():
            components[(*local, plan.components.index(name))] = value
        for issue in r.warnings:
            if issue.quantity not in issues or issue.excess > issues[issue.quantity][0]:
                # Routine ranges (left by every ordinary ball screw) are notes; the rest warn.
                kind = "note" if issue.routine else "warning"
                issues[issue.quantity] = (issue.excess, f"{kind}: {issue.note()}")
    if with_components:
        out["components"] = components
    stats = {}
    for name in (o.name for o in asked):
        values = out[name]
        lo, hi = int(np.nanargmin(values)), int(np.nanargmax(values))
        stats[name] = {
            "min": [float(values.flat[lo]), _flat(plan, region, lo)],
            "max": [float(values.flat[hi]), _flat(plan, region, hi)],
            "sum": [float(np.nansum(values)), float(np.count_nonzero(np.isfinite(values)))],
        }
    report = ChunkReport(
        index, int(math.prod(shape)), time.perf_counter() - start, os.getpid(),
        _peak_rss(), stats, issues,
    )  # fmt: skip
    return out, report


def _flat(plan: Plan, region: tuple[slice, ...], local: int) -> float:
    """Flat index in the whole grid of the chunk's flat position ``local``."""
    where = np.unravel_index(local, tuple(s.stop - s.start for s in region))
    return float(
        np.ravel_multi_index(
            tuple(int(i) + s.start for i, s in zip(where, region, strict=True)), plan.shape
        )
    )


def _peak_rss() -> int:
    """Peak resident memory of this process so far [bytes]."""
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    return int(peak if sys.platform == "darwin" else peak * 1024)


_ARRAYS: dict[tuple[str, str], dict[str, Any]] = {}
"""Open Zarr arrays per (store, fingerprint), reused by the chunks a process writes."""


def _arrays(store: str, key: str) -> dict[str, Any]:
    import zarr

    if (store, key) not in _ARRAYS:
        group = zarr.open_group(store, mode="r+", zarr_format=2)
        _ARRAYS.clear()
        _ARRAYS[(store, key)] = {name: group[name] for name in OUTPUTS if name in group}
    return _ARRAYS[(store, key)]


def run_chunk(index: int, plan: Plan, partial: str, key: str) -> ChunkReport:
    """Compute chunk ``index``, write it into the partial store, then mark it done."""
    from .store import progress_path, store_path

    values, report = compute_chunk(plan, index)
    region = plan.region(index)
    n_outer = len(plan.outer)
    arrays = _arrays(str(store_path(Path(partial))), key)
    with deferred_signals():  # a chunk is written whole before Ctrl-C is acted on
        for name, array in arrays.items():
            where = region
            if name == "components":
                where = (*region[: 1 + n_outer], slice(None), *region[1 + n_outer :])
            array[where] = values[name]
        marker = progress_path(Path(partial)) / f"{index}.json"
        atomic_write(marker, json.dumps(asdict(report)).encode("utf-8"))
    return report
