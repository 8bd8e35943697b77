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
from .plan import Chunk
from .spec import OPERATING, SCALAR_OUTPUTS, resolve

__all__ = ["Block", "ChunkReport", "compute_chunk", "summarise", "worst_issues"]

Block = tuple[tuple[slice, ...], FloatArray]
"""An output's values in one chunk and the region of the stored array they fill."""


@dataclass
class ChunkReport:
    """What one chunk gave: its index, model, size, time, process, summary numbers, issues.

    ``stats`` holds, per output, ``min`` and ``max`` as [value, the point's coordinates]
    and ``sum`` as [sum, count of finite values].
    """

    index: int
    model: str
    points: int
    seconds: float
    pid: int
    peak_rss: int
    stats: dict[str, dict[str, list[Any]]] = field(default_factory=dict)
    issues: dict[str, tuple[float, str]] = field(default_factory=dict)


def _evaluate(chunk: Chunk, point: dict[str, Any]) -> FrictionResult:
    """The friction of one outer point over the chunk's operating points."""
    w, t, f = chunk.operating
    screw, lubricant, params = resolve(chunk.case, chunk.model, chunk.parameters, point)
    return friction_torque(
        screw, lubricant, speed=w[:, None, None], temperature=t[None, :, None],
        axial_load=f[None, None, :], model=chunk.model, warn=False,
        chunk_size=max(len(w) * len(t) * len(f), 1), **params,
    )  # fmt: skip


def _note(issues: dict[str, tuple[float, str]], r: FrictionResult) -> None:
    """Keep the most extreme value of each validity issue of ``r``."""
    for issue in r.warnings:
        if issue.quantity not in issues or issue.excess > issues[issue.quantity][0]:
            # Routine ranges (left by every ordinary ball screw) are notes; the rest warn.
            kind = "note" if issue.routine else "warning"
            issues[issue.quantity] = (issue.excess, f"{kind}: {issue.note()}")


def compute_chunk(chunk: Chunk) -> tuple[dict[str, Block], ChunkReport]:
    """Every output's block of a chunk and its region, and its report (no file is touched)."""
    start = time.perf_counter()
    region = chunk.region
    shape = tuple(s.stop - s.start for s in region)
    cut = len(shape) - len(OPERATING)  # the model and the outer dimensions
    asked = [o for o in SCALAR_OUTPUTS if o.name in chunk.outputs]  # only what was asked
    with_components = "components" in chunk.outputs
    out = {o.name: np.full(shape, np.nan) for o in asked}
    comp_shape = (*shape[:cut], len(chunk.components), *shape[cut:])
    components = np.full(comp_shape if with_components else (0,), np.nan)
    issues: dict[str, tuple[float, str]] = {}
    outer = itertools.product(*(range(n) for n in shape[1:cut]))
    for position, point in zip(outer, chunk.points, strict=True):  # screws, not operating points
        local = (0, *position)
        r = _evaluate(chunk, point)
        for o in asked:
            assert o.read is not None
            out[o.name][local] = o.read(r)
        for name, value in r.components.items() if with_components else ():
            components[(*local, chunk.components.index(name))] = value
        _note(issues, r)
    stats = {name: _stats(chunk, out[name]) for name in (o.name for o in asked)}
    blocks: dict[str, Block] = {name: (region, values) for name, values in out.items()}
    if with_components:
        blocks["components"] = ((*region[:cut], slice(None), *region[cut:]), components)
    report = ChunkReport(
        chunk.index, chunk.model, int(math.prod(shape)), time.perf_counter() - start,
        os.getpid(), _peak_rss(), stats, issues,
    )  # fmt: skip
    return blocks, report


def _stats(chunk: Chunk, values: FloatArray) -> dict[str, list[Any]]:
    """Smallest and largest value with their point's coordinates, and the sum and count."""
    lo, hi = int(np.nanargmin(values)), int(np.nanargmax(values))
    return {
        "min": [float(values.flat[lo]), _where(chunk, values.shape, lo)],
        "max": [float(values.flat[hi]), _where(chunk, values.shape, hi)],
        "sum": [float(np.nansum(values)), float(np.count_nonzero(np.isfinite(values)))],
    }


def _where(chunk: Chunk, shape: tuple[int, ...], local: int) -> dict[str, Any]:
    """The coordinates of the chunk's point at flat position ``local``."""
    position = np.unravel_index(local, shape)
    cut = len(shape) - len(OPERATING)
    k = int(np.ravel_multi_index(position[1:cut], shape[1:cut])) if cut > 1 else 0
    found = dict(chunk.points[k])
    if chunk.samples[k] is not None:
        found["sample"] = chunk.samples[k]
    for dim, values, i in zip(OPERATING, chunk.operating, position[cut:], strict=True):
        found[dim] = float(values[int(i)])
    return found


def _peak_rss() -> int:
    """Peak resident memory of this process so far [bytes]."""
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    return int(peak if sys.platform == "darwin" else peak * 1024)


def summarise(reports: Iterable[dict[str, Any]]) -> dict[str, dict[str, Any]]:
    """Min, mean and max of each output per model, from the chunk reports (in index order)."""
    acc: dict[str, list[Any]] = {}
    for report in sorted(reports, key=lambda r: int(r["index"])):
        for name, s in report["stats"].items():
            a = acc.setdefault(f"{name}\0{report['model']}", [math.inf, None, -math.inf, None,
                                                               0.0, 0.0])  # fmt: skip
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
            "min_at": a[1], "max_at": a[3],
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
