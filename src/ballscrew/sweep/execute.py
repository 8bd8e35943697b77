"""Design-space sweeps: a labelled N-dimensional result, computed in chunks, streamed to Zarr.

:func:`run_sweep` (``ballscrew sweep``) reads the sweep file
(:mod:`ballscrew.sweep.spec`), lays it out (:mod:`ballscrew.sweep.plan`), hands
the layout to the store (:mod:`ballscrew.sweep.store`) and computes the chunks
(:mod:`ballscrew.sweep.compute`) in this process, on a local Dask cluster
(``workers``) or on a running one (``scheduler``); each chunk is written by the
process that computed it (the store must be on a file system the workers share)
and then marked done. The same function computes each chunk in every mode, so the
arrays are identical.

Interruptions: the store is built under a temporary name beside the target
(``.NAME.partial``) and renamed to the target only when complete. A chunk's
marker is written after its data, so a rerun of the same sweep resumes with
the chunks that are marked; a changed sweep starts again.
"""

from __future__ import annotations

import contextlib
import itertools
import math
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import asdict, dataclass
from pathlib import Path
from typing import Any

import numpy as np

from ..errors import BallScrewInputError, FloatArray
from ..helix import JIT_LOAD_POINTS, load_kernel
from ..io.extras import require
from ..io.files import OutputInUseError, exclusive_lock
from . import store
from .compute import ChunkReport, compute_chunk, summarise, worst_issues
from .plan import DEFAULT_MAX_POINTS, LONG_NAMES, Plan, check_size, plan_sweep, sweep_size
from .spec import OPERATING, OUTPUTS, SCALAR_OUTPUTS, SweepSpec, load_sweep

__all__ = ["Percentiles", "SweepReport", "plan_sweep", "run_chunk", "run_sweep"]


@dataclass(frozen=True)
class Percentiles:
    """Monte Carlo percentiles of the torque [N·m] at the first temperature and axial load.

    ``torque[model]`` has one row per speed [rad/s] and one column per percentile [%].
    """

    percentiles: FloatArray
    speeds: FloatArray
    torque: dict[str, FloatArray]

    def as_dict(self) -> dict[str, Any]:
        """Percentiles [%], speeds [rad/s] and, per model, the torque rows [N·m]."""
        return {
            "percentiles": self.percentiles.tolist(),
            "speed_rad_s": self.speeds.tolist(),
            "torque_Nm": {model: values.tolist() for model, values in self.torque.items()},
        }


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
        Model -> :class:`ballscrew.sweep.sensitivity.SobolIndices` (when asked for).
    mode : str
        ``in process``, ``N local workers`` or the scheduler's address.
    percentiles : Percentiles or None
        The torque's Monte Carlo percentiles (when there are samples and a torque).
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
    percentiles: Percentiles | None = None

    @property
    def points_per_second(self) -> float:
        """Points computed in this run per second of wall time."""
        done = self.plan.points * self.computed / max(self.plan.n_chunks, 1)
        return done / self.seconds if self.seconds > 0 else math.nan

    def as_dict(self) -> dict[str, Any]:
        """The JSON document of ``ballscrew sweep --json``."""
        return {
            "store": str(self.out),
            "points": self.plan.points,
            "chunks": self.plan.n_chunks,
            "dims": dict(zip(self.plan.dims, self.plan.shape, strict=True)),
            "mode": self.mode,
            "summary": self.summary,
            "validity": list(self.issues),
            "sobol": {model: s.as_dict() for model, s in self.sobol.items()},
        }


MAX_WORKERS = 256
"""The most local worker processes ``--workers`` starts: each is a Python process of some
200 MB (100 000 asked in 0.2.0 held the machine); a larger cluster is started on its own
and named by ``--scheduler``."""


def run_sweep(
    sweep: SweepSpec | str | Path,
    out: str | Path,
    *,
    max_points: int | None = None,
    workers: int | None = None,
    scheduler: str | None = None,
    restart: bool = False,
    progress: Callable[[int, int], None] | None = None,
    notify: Callable[[str], None] | None = None,
    companions: Sequence[Path] = (),
) -> SweepReport:
    """Run a sweep into the Zarr store ``out`` (see the module docstring).

    Parameters
    ----------
    sweep : SweepSpec, str or Path
        The checked sweep file, or its path.
    out : str or Path
        The store to write; an earlier sweep store there is replaced at the end.
    max_points : int, optional
        The most points the sweep may have (default :data:`DEFAULT_MAX_POINTS`); its
        size is told (``notify``) before it starts.
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
        Called with a sentence: the sweep's size, and whether a run is resumed or
        restarted.
    companions : sequence of Path
        Files an earlier run wrote from the store it replaces (a summary JSON): moved
        aside with it, so that the new store never stands beside them.

    Raises
    ------
    MissingExtraError
        When the ``sweep`` extra is not installed.
    """
    require("sweep", "ballscrew.sweep.execute.run_sweep")
    spec = load_sweep(sweep) if isinstance(sweep, str | Path) else sweep
    size = sweep_size(spec)
    check_size(size, max_points or DEFAULT_MAX_POINTS)
    if notify is not None:
        notify(f"sweep: {size.describe()}")
    if workers is not None and scheduler is not None:
        raise BallScrewInputError("--workers", workers, "either --workers or --scheduler")
    if workers is not None and (isinstance(workers, bool) or not 1 <= workers <= MAX_WORKERS):
        raise BallScrewInputError(
            "--workers", workers, f"a whole number from 1 to {MAX_WORKERS} (local processes; "
            "a larger cluster is started on its own and named by --scheduler)",
        )  # fmt: skip
    target = Path(out).absolute()
    store.check_target(target)
    target.parent.mkdir(parents=True, exist_ok=True)
    try:
        with exclusive_lock(target.parent / f".{target.name}.lock"):
            return _run(spec, target, workers, scheduler, restart, progress, notify,
                        companions)  # fmt: skip
    except OutputInUseError as exc:
        raise BallScrewInputError(
            "--out",
            str(target),
            f"a store no other sweep is writing ({exc} is writing this "
            "one): wait for it to finish, or choose another --out",
        ) from None


def _run(
    spec: SweepSpec,
    target: Path,
    workers: int | None,
    scheduler: str | None,
    restart: bool,
    progress: Callable[[int, int], None] | None,
    notify: Callable[[str], None] | None,
    companions: Sequence[Path] = (),
) -> SweepReport:
    """The sweep, with the lock on its output held: spec -> plan -> chunks -> store."""
    plan = plan_sweep(spec)
    key = plan.key
    partial = store.partial_path(target)
    done = _start(plan, partial, key, restart, notify or (lambda _text: None))
    todo = [i for i in range(plan.n_chunks) if i not in done]
    reports: dict[int, dict[str, Any]] = dict(done)
    step = progress or (lambda _done, _total: None)
    step(len(reports), plan.n_chunks)
    if workers is None and scheduler is None and plan.points >= JIT_LOAD_POINTS:
        load_kernel()  # the helix's compiled loop, for every chunk of this process
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
    sobol, percentiles = _uncertainty(spec, partial)
    summary = summarise(reports.values())
    issues = worst_issues(reports.values())
    if store.markers(partial, key) is None:  # the lock makes this impossible, but check
        raise BallScrewInputError("--out", str(target), "a store this run alone wrote")
    store.finalize(partial, target, {"summary": summary, "validity": list(issues)},
                   companions=companions)  # fmt: skip
    peak: dict[int, int] = {}
    for r in reports.values():
        peak[int(r["pid"])] = max(peak.get(int(r["pid"]), 0), int(r["peak_rss"]))
    return SweepReport(
        target, plan, len(todo), len(done), seconds, summary, issues, peak, sobol, mode,
        percentiles,
    )  # fmt: skip


def _start(
    plan: Plan, partial: Path, key: str, restart: bool, tell: Callable[[str], None]
) -> dict[int, dict[str, Any]]:
    """The chunks an interrupted run of the same sweep left, or a new store and none."""
    done = None if restart else store.markers(partial, key)
    if done is None:
        if partial.exists():
            tell(f"restarting: {partial} holds another sweep's chunks" if not restart
                 else f"restarting: the chunks in {partial} are discarded")  # fmt: skip
        assert plan.layout is not None
        store.create(plan.layout, partial, key)
        return {}
    if done:
        tell(f"resuming: {len(done)} of {plan.n_chunks} chunks already done in {partial}")
    return done


def run_chunk(index: int, plan: Plan, partial: str, key: str) -> ChunkReport:
    """Compute chunk ``index`` and hand it to the store, which writes it and marks it done."""
    blocks, report = compute_chunk(plan.chunk(index))
    store.write_chunk(Path(partial), key, blocks, asdict(report))
    return report


def _uncertainty(spec: SweepSpec, partial: Path) -> tuple[dict[str, Any], Percentiles | None]:
    """Percentiles and Sobol indices, computed from the store and added to it."""
    u = spec.uncertainty
    if u is None:
        return {}, None
    outputs = {o.name: (OUTPUTS[o.name], LONG_NAMES[o.name]) for o in SCALAR_OUTPUTS}
    variables = store.percentile_variables(partial, u.percentiles, outputs)
    sobol: dict[str, Any] = {}
    if u.sensitivity == "sobol":
        from .sensitivity import sobol_indices

        means = store.mean_torque(partial, list(OPERATING))
        sobol = {m: sobol_indices(u.inputs, means[i], u.seed) for i, m in
                 enumerate(spec.models)}  # fmt: skip
        names = [d.name for d in u.inputs]
        variables |= store.sobol_variables(names, [sobol[m] for m in spec.models])
    store.add_variables(partial, variables)
    percentiles = None
    torque = variables.get("torque_percentile")
    if torque is not None:
        first = {d: 0 for d in torque.dims if d not in ("percentile", "model", "speed")}
        values = torque.isel(first).transpose("model", "speed", "percentile").values
        percentiles = Percentiles(
            np.asarray(variables["percentile"].values, dtype=float),
            np.asarray(spec.operating["speed"], dtype=float),
            {m: values[i] for i, m in enumerate(spec.models)},
        )
    return sobol, percentiles


def _warm_up() -> None:
    """What a worker's first chunk would load: Zarr, and the helix's compiled loop."""
    import zarr  # noqa: F401

    load_kernel()


def _distributed(
    plan: Plan, todo: Sequence[int], partial: str, key: str, workers: int | None,
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
        # Each worker imports Zarr and loads the helix's compiled loop now, with the
        # cluster's start-up, not in its first chunk (0.5 s to 1 s: a tenth of a 2e7-point
        # sweep on 2 workers).
        client.run(_warm_up)
        ready[0] = time.perf_counter()
        threads = max(1, sum(client.nthreads().values()))
        window = 4 * threads
        pending = iter(todo)

        def submit(index: int) -> Any:
            return client.submit(run_chunk, index, shared, partial, key, pure=False)

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
