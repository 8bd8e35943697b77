"""Design-space sweeps: a labelled N-dimensional result, computed in chunks, streamed to Zarr.

:func:`run_sweep` lays the sweep out (:mod:`ballscrew.sweep.plan`), creates
the store (:mod:`ballscrew.sweep.store`) and computes the chunks in this
process, on a local Dask cluster (``workers``) or on a running one
(``scheduler``); each chunk is written by the process that computed it (the
store must be on a file system the workers share) and then marked done. The
same function computes each chunk in every mode, so the arrays are identical.

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

from ..errors import BallScrewInputError
from ..helix import JIT_LOAD_POINTS, load_kernel
from ..io.extras import require
from ..io.files import OutputInUseError, exclusive_lock
from .plan import ChunkReport, Plan, plan_sweep, run_chunk
from .spec import OPERATING, SweepSpec

__all__ = ["SweepReport", "plan_sweep", "run_sweep"]


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
        model = plan.spec.models[plan.region(int(report["index"]))[0].start]
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

    Raises
    ------
    MissingExtraError
        When the ``sweep`` extra is not installed.
    """
    require("sweep", "ballscrew.sweep.execute.run_sweep")
    from . import store

    if workers is not None and scheduler is not None:
        raise BallScrewInputError("--workers", workers, "either --workers or --scheduler")
    if workers is not None and (isinstance(workers, bool) or workers < 1):
        raise BallScrewInputError("--workers", workers, "a whole number >= 1")
    target = Path(out).absolute()
    store.check_target(target)
    target.parent.mkdir(parents=True, exist_ok=True)
    try:
        with exclusive_lock(target.parent / f".{target.name}.lock"):
            return _run(spec, target, workers, scheduler, restart, progress, notify)
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
) -> SweepReport:
    """The sweep, with the lock on its output held."""
    from . import store

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
    if store.markers(partial, key) is None:  # the lock makes this impossible, but check
        raise BallScrewInputError("--out", str(target), "a store this run alone wrote")
    store.finalize(partial, target, {"summary": summary, "validity": list(issues)})
    peak: dict[int, int] = {}
    for r in reports.values():
        peak[int(r["pid"])] = max(peak.get(int(r["pid"]), 0), int(r["peak_rss"]))
    return SweepReport(
        target, plan, len(todo), len(done), seconds, summary, issues, peak, sobol, mode
    )


def _warm_up() -> None:
    """What a worker's first chunk would load: Zarr, and the helix's compiled loop."""
    import zarr  # noqa: F401

    load_kernel()


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
        # Each worker imports Zarr and loads the helix's compiled loop now, with the
        # cluster's start-up, not in its first chunk (0.5 s to 1 s: a tenth of a 2e7-point
        # sweep on 2 workers).
        client.run(_warm_up)
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
