"""One chunk of a sweep computed, and the chunks' reports summed up.

:func:`compute_chunk` calls :func:`ballscrew.chain.friction_torque` once per screw
with the chunk's operating points as an unexpanded outer product, so the
screw-dependent state is built once per chunk, never per point, and no Python loop
runs over operating points. It touches no file: it returns each output's block with
the region of the store it fills, which :func:`ballscrew.sweep.store.write_chunk`
writes. It runs in this process or on a Dask worker alike, which is why every
execution mode gives the same arrays.
"""

from __future__ import annotations

import itertools
import math
import os
import resource
import sys
import time
from collections.abc import Iterable
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from ..chain import FrictionResult, friction_torque
from ..errors import FloatArray
from .plan import Plan
from .spec import OPERATING, SCALAR_OUTPUTS, resolve

__all__ = ["Block", "ChunkReport", "compute_chunk", "summarise", "worst_issues"]

Block = tuple[tuple[slice, ...], FloatArray]
"""An output's values in one chunk and the region of the stored array they fill."""


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


def _evaluate(plan: Plan, region: tuple[slice, ...], position: tuple[int, ...]) -> FrictionResult:
    """The friction of one outer point over the chunk's operating points."""
    model = plan.spec.models[region[0].start]
    op = region[1 + len(plan.outer) :]
    w, t, f = (plan.spec.operating[k][s] for k, s in zip(OPERATING, op, strict=True))
    screw, lubricant, params = resolve(
        plan.spec.case, model, plan.parameters[model], plan.outer_point(position)
    )
    return friction_torque(
        screw, lubricant, speed=w[:, None, None], temperature=t[None, :, None],
        axial_load=f[None, None, :], model=model, warn=False,
        chunk_size=max(len(w) * len(t) * len(f), 1), **params,
    )  # fmt: skip


def _note(issues: dict[str, tuple[float, str]], r: FrictionResult) -> None:
    """Keep the most extreme value of each validity issue of ``r``."""
    for issue in r.warnings:
        if issue.quantity not in issues or issue.excess > issues[issue.quantity][0]:
            # Routine ranges (left by every ordinary ball screw) are notes; the rest warn.
            kind = "note" if issue.routine else "warning"
            issues[issue.quantity] = (issue.excess, f"{kind}: {issue.note()}")


def compute_chunk(plan: Plan, index: int) -> tuple[dict[str, Block], ChunkReport]:
    """Every output's block of chunk ``index`` and its region, and its report (no file)."""
    start = time.perf_counter()
    region = plan.region(index)
    n_outer = len(plan.outer)
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
        r = _evaluate(plan, region, position)
        for o in asked:
            assert o.read is not None
            out[o.name][local] = o.read(r)
        for name, value in r.components.items() if with_components else ():
            components[(*local, plan.components.index(name))] = value
        _note(issues, r)
    stats = {name: _stats(plan, region, out[name]) for name in (o.name for o in asked)}
    blocks: dict[str, Block] = {name: (region, values) for name, values in out.items()}
    if with_components:
        cut = 1 + n_outer
        blocks["components"] = ((*region[:cut], slice(None), *region[cut:]), components)
    report = ChunkReport(
        index, int(math.prod(shape)), time.perf_counter() - start, os.getpid(),
        _peak_rss(), stats, issues,
    )  # fmt: skip
    return blocks, report


def _stats(plan: Plan, region: tuple[slice, ...], values: FloatArray) -> dict[str, list[float]]:
    """Smallest and largest value with their flat grid index, and the sum and count."""
    lo, hi = int(np.nanargmin(values)), int(np.nanargmax(values))
    return {
        "min": [float(values.flat[lo]), _flat(plan, region, lo)],
        "max": [float(values.flat[hi]), _flat(plan, region, hi)],
        "sum": [float(np.nansum(values)), float(np.count_nonzero(np.isfinite(values)))],
    }


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


def summarise(plan: Plan, reports: Iterable[dict[str, Any]]) -> dict[str, dict[str, Any]]:
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


def worst_issues(reports: Iterable[dict[str, Any]]) -> tuple[str, ...]:
    """The note of each validity issue at its most extreme value over the chunks."""
    worst: dict[str, tuple[float, str]] = {}
    for report in sorted(reports, key=lambda r: int(r["index"])):
        for quantity, (excess, note) in report["issues"].items():
            if quantity not in worst or excess > worst[quantity][0]:
                worst[quantity] = (excess, note)
    return tuple(note for _, note in worst.values())
