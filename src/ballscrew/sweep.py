"""Design-space sweeps: a labelled N-dimensional result, computed in chunks, streamed to Zarr.

A :class:`~ballscrew.sweep_spec.SweepSpec` is laid out as a grid (:class:`Plan`)
of dimensions ``model``, the outer axes (case fields, model parameters, and
``sample`` for Monte Carlo), then ``speed``, ``temperature`` and
``axial_load``. The grid is cut into chunks of about ``chunk_points`` points,
the same chunks as the Zarr store's. A chunk holds one model and one block of
outer points (a single screw whenever the operating grid is large); for each
screw in it :func:`ballscrew.chain.friction_torque` is called once with the
operating points as an unexpanded outer product, so the screw-dependent state
is built once per chunk, never per point, and there is no Python loop over
operating points.

:func:`run_sweep` computes the chunks in this process, on a local Dask
cluster (``workers``) or on a running one (``scheduler``); each chunk is
written by the process that computed it (Zarr region writes: the store must be
on a file system the workers share) and is then marked done. The same
function computes each chunk in every mode, so the arrays are identical.

Interruptions: the store is built under a temporary name beside the target
(``.NAME.partial``) and renamed to the target only when complete. A chunk's
marker is written after its data, so a rerun of the same sweep resumes with
the chunks that are marked; a changed sweep starts again.
"""

from __future__ import annotations

import contextlib
import hashlib
import itertools
import json
import math
import os
import resource
import sys
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import asdict, dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from . import __version__
from .chain import friction_torque
from .errors import BallScrewInputError, FloatArray
from .files import atomic_write, deferred_signals
from .sweep_spec import OPERATING, OUTPUTS, SweepSpec, resolve

__all__ = ["ChunkReport", "Plan", "SweepReport", "compute_chunk", "plan_sweep", "run_sweep"]


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
    out = {name: np.full(shape, np.nan) for name in ("torque", "efficiency", "power_loss")}
    comp_shape = (*shape[: 1 + n_outer], len(plan.components), *shape[1 + n_outer :])
    components = np.full(comp_shape, np.nan)
    issues: dict[str, tuple[float, str]] = {}
    outer_ranges = [range(s.start, s.stop) for s in region[1 : 1 + n_outer]]
    for position in itertools.product(*outer_ranges):  # screws, never operating points
        local = (0, *(p - s.start for p, s in zip(position, region[1:], strict=False)))
        screw, lubricant, params = resolve(
            plan.spec.case, model, plan.parameters[model], plan.outer_point(position)
        )
        r = friction_torque(
            screw, lubricant, speed=w[:, None, None], temperature=t[None, :, None],
            axial_load=f[None, None, :], model=model, warn=False, **params,
        )  # fmt: skip
        out["torque"][local] = r.total
        out["efficiency"][local] = r.efficiency
        out["power_loss"][local] = r.power_loss
        for name, value in r.components.items():
            components[(*local, plan.components.index(name))] = value
        for issue in r.warnings:
            if issue.quantity not in issues or issue.excess > issues[issue.quantity][0]:
                issues[issue.quantity] = (issue.excess, issue.note())
    out["components"] = components
    stats = {}
    for name in ("torque", "efficiency", "power_loss"):
        values = out[name]
        offset = np.ravel_multi_index(
            tuple(s.start for s in region), plan.shape
        )  # the chunk's first point, as a flat index of the whole grid
        lo, hi = int(np.nanargmin(values)), int(np.nanargmax(values))
        stats[name] = {
            "min": [float(values.flat[lo]), _flat(plan, region, lo, offset)],
            "max": [float(values.flat[hi]), _flat(plan, region, hi, offset)],
            "sum": [float(np.nansum(values)), float(np.count_nonzero(np.isfinite(values)))],
        }
    report = ChunkReport(
        index, int(math.prod(shape)), time.perf_counter() - start, os.getpid(),
        _peak_rss(), stats, issues,
    )  # fmt: skip
    return out, report


def _flat(plan: Plan, region: tuple[slice, ...], local: int, offset: int) -> float:
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
    from .sweep_store import progress_path, store_path

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


@dataclass(frozen=True)
class SweepReport:
    """What a sweep did and found.

    Attributes
    ----------
    out : Path
        The store.
    plan : Plan
        Its grid.
    computed, resumed : int
        Chunks computed in this run, and found done by an interrupted one.
    seconds : float
        Wall time of the chunks computed in this run (a cluster's start-up excluded).
    summary : dict
        Output -> model -> min, mean, max and where the extremes lie.
    issues : tuple of str
        Validity-range notes, the most extreme value of each quantity.
    peak_rss : dict
        Process id -> its peak resident memory [bytes].
    sobol : dict
        Model -> :class:`ballscrew.sensitivity.SobolIndices` (when asked for).
    mode : str
        ``in process``, ``N local workers`` or the scheduler's address.
    """

    out: Path
    plan: Plan
    computed: int
    resumed: int
    seconds: float
    summary: dict[str, dict[str, dict[str, Any]]]
    issues: tuple[str, ...]
    peak_rss: dict[int, int]
    sobol: dict[str, Any]
    mode: str

    @property
    def points_per_second(self) -> float:
        """Points computed in this run per second of wall time."""
        done = self.plan.points * self.computed / max(self.plan.n_chunks, 1)
        return done / self.seconds if self.seconds > 0 else math.nan


def _where(plan: Plan, flat: float) -> dict[str, Any]:
    """The coordinates of a point of the grid given as a flat index."""
    position = [int(i) for i in np.unravel_index(int(flat), plan.shape)]
    n_outer = len(plan.outer)
    found: dict[str, Any] = plan.outer_point(position[1 : 1 + n_outer])
    if "sample" in plan.outer:
        found["sample"] = position[plan.dims.index("sample")]
    for dim in OPERATING:
        found[dim] = float(plan.spec.operating[dim][position[plan.dims.index(dim)]])
    return found


def _summary(plan: Plan, reports: Iterable[dict[str, Any]]) -> dict[str, dict[str, Any]]:
    """Min, mean and max of each output per model, from the chunk reports (in index order)."""
    acc: dict[str, list[float]] = {}
    for report in sorted(reports, key=lambda r: int(r["index"])):
        model = plan.spec.models[plan.region(int(report["index"])).__getitem__(0).start]
        for name, s in report["stats"].items():
            a = acc.setdefault(f"{name}\0{model}", [math.inf, -1.0, -math.inf, -1.0, 0.0, 0.0])
            if s["min"][0] < a[0]:
                a[0], a[1] = s["min"]
            if s["max"][0] > a[2]:
                a[2], a[3] = s["max"]
            a[4] += s["sum"][0]
            a[5] += s["sum"][1]
    summary: dict[str, dict[str, Any]] = {}
    for key, a in acc.items():
        name, model = key.split("\0")
        summary.setdefault(name, {})[model] = {
            "min": a[0], "mean": a[4] / a[5] if a[5] else math.nan, "max": a[2],
            "min_at": _where(plan, a[1]), "max_at": _where(plan, a[3]),
        }  # fmt: skip
    return summary


def _issues(reports: Iterable[dict[str, Any]]) -> tuple[str, ...]:
    worst: dict[str, tuple[float, str]] = {}
    for report in sorted(reports, key=lambda r: int(r["index"])):
        for quantity, (excess, note) in report["issues"].items():
            if quantity not in worst or excess > worst[quantity][0]:
                worst[quantity] = (excess, note)
    return tuple(note for _, note in worst.values())


def run_sweep(
    spec: SweepSpec,
    out: str | Path,
    *,
    workers: int | None = None,
    scheduler: str | None = None,
    restart: bool = False,
    progress: Callable[[int, int], None] | None = None,
    notify: Callable[[str], None] | None = None,
) -> SweepReport:
    """Run a sweep into the Zarr store ``out`` (see the module docstring).

    Parameters
    ----------
    spec : SweepSpec
        The checked sweep file.
    out : str or Path
        The store to write; an earlier sweep store there is replaced at the end.
    workers : int, optional
        Run on a local Dask cluster of this many worker processes (on 127.0.0.1).
    scheduler : str, optional
        Run on the Dask cluster whose scheduler has this address
        (``tcp://HOST:PORT``); its workers must see ``out``'s folder.
    restart : bool
        Start again even if an interrupted run of the same sweep left chunks.
    progress : callable, optional
        Called with (chunks done, chunks in all) as chunks finish.
    notify : callable, optional
        Called with a sentence when a run is resumed or restarted.
    """
    from . import sweep_store as store

    if workers is not None and scheduler is not None:
        raise BallScrewInputError("--workers", workers, "either --workers or --scheduler")
    if workers is not None and (isinstance(workers, bool) or workers < 1):
        raise BallScrewInputError("--workers", workers, "a whole number >= 1")
    target = Path(out).absolute()
    store.check_target(target)
    plan = plan_sweep(spec)
    key = plan.fingerprint()
    partial = store.partial_path(target)
    tell = notify or (lambda _text: None)
    done = None if restart else store.markers(partial, key)
    if done is None:
        if partial.exists():
            tell(f"restarting: {partial} holds another sweep's chunks" if not restart
                 else f"restarting: the chunks in {partial} are discarded")  # fmt: skip
        store.create(plan, partial, key)
        done = {}
    elif done:
        tell(f"resuming: {len(done)} of {plan.n_chunks} chunks already done in {partial}")
    todo = [i for i in range(plan.n_chunks) if i not in done]
    reports: dict[int, dict[str, Any]] = dict(done)
    step = progress or (lambda _done, _total: None)
    step(len(reports), plan.n_chunks)
    start = time.perf_counter()
    if workers is None and scheduler is None:
        mode = "in process"
        for index in todo:
            reports[index] = asdict(run_chunk(index, plan, str(partial), key))
            step(len(reports), plan.n_chunks)
    else:
        mode = f"on {workers} local workers" if workers else f"on the cluster at {scheduler}"
        ready = [start]  # when the cluster is up: its start-up is not computing time
        for report in _distributed(plan, todo, str(partial), key, workers, scheduler, ready):
            reports[report.index] = asdict(report)
            step(len(reports), plan.n_chunks)
        start = ready[0]
    seconds = time.perf_counter() - start
    sobol: dict[str, Any] = {}
    u = spec.uncertainty
    if u is not None:
        variables = store.percentile_variables(partial, plan)
        if u.sensitivity == "sobol":
            from .sensitivity import sobol_indices

            means = store.mean_torque(partial)
            sobol = {m: sobol_indices(u.inputs, means[i], u.seed) for i, m in
                     enumerate(spec.models)}  # fmt: skip
            names = [d.name for d in u.inputs]
            variables |= store.sobol_variables(names, [sobol[m] for m in spec.models])
        store.add_variables(partial, variables)
    summary = _summary(plan, reports.values())
    issues = _issues(reports.values())
    store.finalize(partial, target, {"summary": summary, "validity": list(issues)})
    peak: dict[int, int] = {}
    for r in reports.values():
        peak[int(r["pid"])] = max(peak.get(int(r["pid"]), 0), int(r["peak_rss"]))
    return SweepReport(
        target, plan, len(todo), len(done), seconds, summary, issues, peak, sobol, mode
    )


def _distributed(
    plan: Plan, todo: Sequence[int], store: str, key: str, workers: int | None,
    scheduler: str | None, ready: list[float],
) -> Iterable[ChunkReport]:  # fmt: skip
    """Run the chunks on a Dask cluster, yielding reports as they finish (a bounded window).

    ``ready[0]`` is set to the time at which the cluster was up and the plan sent.
    """
    from distributed import Client, LocalCluster, as_completed

    with contextlib.ExitStack() as stack:
        if scheduler is not None:
            try:
                client = stack.enter_context(Client(scheduler, timeout="10s"))
            except (OSError, TimeoutError, ValueError) as exc:
                raise BallScrewInputError(
                    "--scheduler", scheduler, f"the address of a running Dask scheduler ({exc})"
                ) from None
        else:
            import dask

            # Dask's nanny sets MALLOC_TRIM_THRESHOLD_ in its workers; glibc then stops
            # raising its mmap threshold, so every large numpy temporary is mapped and
            # faulted in afresh: the complete model ran 3 times slower (measured). Unset.
            stack.enter_context(
                dask.config.set(
                    {"distributed.nanny.pre-spawn-environ.MALLOC_TRIM_THRESHOLD_": None}
                )
            )
            cluster = stack.enter_context(
                LocalCluster(
                    n_workers=workers, threads_per_worker=1, processes=True,
                    host="127.0.0.1", dashboard_address="127.0.0.1:0",
                )
            )  # fmt: skip
            client = stack.enter_context(Client(cluster))
        shared = client.scatter(plan, broadcast=True)
        ready[0] = time.perf_counter()
        threads = max(1, sum(client.nthreads().values()))
        window = 4 * threads
        pending = iter(todo)

        def submit(index: int) -> Any:
            return client.submit(run_chunk, index, shared, store, key, pure=False)

        running = as_completed([submit(i) for i in itertools.islice(pending, window)])
        try:
            for future in running:
                yield future.result()
                nxt = next(pending, None)
                if nxt is not None:
                    running.add(submit(nxt))
        except BaseException:
            running.clear()
            raise
