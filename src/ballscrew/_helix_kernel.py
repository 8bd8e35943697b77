r"""The helix's slip share as one compiled loop: the ``fast`` extra's kernel.

:func:`ballscrew.helix.transverse_slip_loss` solves, at every operating point,
the moment balance of a ball for the share of the slip taken at its screw
contacts, by Newton's method kept in a bracket on tabulated traction
integrals. In numpy each Newton step is a dozen whole-array passes; here each
point runs its own iteration to the end in one compiled loop over the points,
with the same start, steps, stopping rules and tables, so that both give the
same shares (to rounding: the tests hold them to 1e-12 of a share).

:func:`shares` is plain Python (run as such for a few points); numba compiles it
(``pip install 'ballscrew[fast]'``) on first use, cached on disk. Without
numba, or with ``BALLSCREW_JIT=0`` in the environment, the helix takes its
numpy path.
"""

from __future__ import annotations

import contextlib
import contextvars
import functools
import math
import os
from collections.abc import Callable, Iterator
from typing import Any

import numpy as np

from .errors import FloatArray

__all__ = ["BLOCK", "enabled", "run", "shares"]

BLOCK = 8
"""Points whose iterations :func:`shares` interleaves."""


def shares(
    capacity: FloatArray,
    per_share: FloatArray,
    scale: FloatArray,
    screw_side: Any,
    g_nodes: FloatArray,
    j_nodes: FloatArray,
    table: Any,
    tolerance: float,
    max_iter: int,
    x: FloatArray,
    power: FloatArray,
    force: FloatArray,
) -> None:
    r"""Share of the slip at the screw, extra power and transverse force of every point.

    Parameters (K contacts, n points, M + 1 table nodes uniform in
    :math:`t = \sigma/(1+\sigma)`):

    capacity : (K, n) :math:`\mu_jQ_j` [N];
    per_share : (K, n) slip ratio per unit share, :math:`s_\perp/(|\omega_s|a)` [-] (0
        for an unloaded contact); scale : (K, n) :math:`|\omega_s|a` per unit screw
        speed [m];
    screw_side : (K,) true for a screw contact; g_nodes, j_nodes : (T, K, M + 1) the
        tables of :math:`G` and :math:`J/(1+\sigma)`, one set per screw geometry;
    table : (n,) the set of tables of each point (all 0 for one screw);
    tolerance : the stopping tolerance on the share (and, times the total
        capacity, on the force residual); max_iter : residual evaluations at most;
    x, power, force : (n,) outputs, written in place.

    The points are taken in blocks of :data:`BLOCK`: each Newton step of a point is
    followed by the step of its neighbour, whose arithmetic does not depend on it, so
    that the processor overlaps them (1.5 times faster than one point to its end after
    the other, with the same steps and bits).
    """
    k_count = len(capacity)
    n = len(capacity[0])
    intervals = len(g_nodes[0][0]) - 1
    lo = np.empty(BLOCK)
    hi = np.empty(BLOCK)
    share = np.empty(BLOCK)
    f_tol = np.empty(BLOCK)
    active = np.empty(BLOCK, dtype=np.bool_)
    for start in range(0, n, BLOCK):
        m = min(BLOCK, n - start)
        for j in range(m):
            # The residual (screw force - nut force) at both ends of [0, 1].
            p = start + j
            tab = table[p]
            total = 0.0
            f_lo = 0.0
            f_hi = 0.0
            for k in range(k_count):
                total += capacity[k][p]
                ratio = per_share[k][p]
                t = ratio / (1.0 + ratio) * intervals
                i = min(int(t), intervals - 1)
                g_full = g_nodes[tab][k][i] + (t - i) * (
                    g_nodes[tab][k][i + 1] - g_nodes[tab][k][i]
                )
                if screw_side[k]:
                    f_hi += capacity[k][p] * g_full
                else:
                    f_lo -= capacity[k][p] * g_full
            # Unloaded on one side: that side takes all the slip, free. Else start where
            # the straight line between the two ends' residuals crosses zero.
            active[j] = f_lo < 0.0 and f_hi > 0.0
            share[j] = -f_lo / (f_hi - f_lo) if active[j] else (0.0 if f_lo >= 0.0 else 1.0)
            lo[j] = 0.0
            hi[j] = 1.0
            f_tol[j] = tolerance * total
        for _ in range(max_iter):
            remaining = False
            for j in range(m):
                if not active[j]:
                    continue
                p = start + j
                tab = table[p]
                x_j = share[j]
                f = 0.0
                slope = 0.0
                for k in range(k_count):
                    own = x_j if screw_side[k] else 1.0 - x_j
                    sign = 1.0 if screw_side[k] else -1.0
                    ratio = per_share[k][p]
                    sigma = own * ratio
                    t = sigma / (1.0 + sigma) * intervals
                    i = min(int(t), intervals - 1)
                    rise = g_nodes[tab][k][i + 1] - g_nodes[tab][k][i]
                    g = g_nodes[tab][k][i] + (t - i) * rise
                    f += sign * capacity[k][p] * g
                    slope += capacity[k][p] * rise * intervals / (1.0 + sigma) ** 2 * ratio
                if f > 0.0:
                    hi[j] = x_j
                else:
                    lo[j] = x_j
                step = f / slope if slope > 0.0 else 0.0
                trial = x_j - step
                inside = slope > 0.0 and lo[j] < trial < hi[j]
                done = (
                    f == 0.0
                    or abs(f) <= f_tol[j]
                    or (inside and abs(step) <= tolerance)
                    or hi[j] - lo[j] <= tolerance
                )
                if done:
                    if inside:
                        share[j] = trial
                    active[j] = False
                else:
                    share[j] = trial if inside else 0.5 * (lo[j] + hi[j])
                    remaining = True
            if not remaining:
                break
        for j in range(m):
            p = start + j
            tab = table[p]
            x_j = share[j]
            x[p] = x_j
            extra = 0.0
            side_force = 0.0
            for k in range(k_count):
                own = x_j if screw_side[k] else 1.0 - x_j
                sigma = own * per_share[k][p]
                t = sigma / (1.0 + sigma) * intervals
                i = min(int(t), intervals - 1)
                frac = t - i
                j_slip = (
                    j_nodes[tab][k][i] + frac * (j_nodes[tab][k][i + 1] - j_nodes[tab][k][i])
                ) * (1.0 + sigma)
                extra += (
                    capacity[k][p] * 1.5 / math.pi * scale[k][p] * (j_slip - j_nodes[tab][k][0])
                )
                if screw_side[k]:
                    side_force += capacity[k][p] * (
                        g_nodes[tab][k][i] + frac * (g_nodes[tab][k][i + 1] - g_nodes[tab][k][i])
                    )
            power[p] = extra
            force[p] = side_force


_SCOPED: contextvars.ContextVar[bool] = contextvars.ContextVar("ballscrew_kernel", default=False)
_FOR_ALL = [False]
"""Whether the process loaded the kernel outside a :func:`scoped` block (for every call)."""


def enabled(*, load: bool = True) -> bool:
    """Whether the compiled kernel is to be used: numba installed and not switched off.

    With ``load=False``, only if this process has loaded it already (no import of numba)
    for every call, not only inside a :func:`scoped` block; inside one, always.
    """
    if os.environ.get("BALLSCREW_JIT", "1").strip().lower() in ("0", "false", "no", "off"):
        return False
    if _SCOPED.get():
        return _compiled() is not None
    if not load and (not _FOR_ALL[0] or _compiled.cache_info().currsize == 0):
        return False
    _FOR_ALL[0] = _compiled() is not None
    return _FOR_ALL[0]


@contextlib.contextmanager
def scoped() -> Iterator[None]:
    """The kernel for the calls inside the block (loaded if need be), from its least size on.

    Outside the block the process keeps the path it had: a kernel loaded only here is
    not used by the other calls, whose numbers stay those of a process without it.
    """
    token = _SCOPED.set(True)
    try:
        yield
    finally:
        _SCOPED.reset(token)


@functools.cache
def _compiled() -> Callable[..., None] | None:
    """:func:`shares` compiled by numba (cached on disk), or None without numba."""
    try:
        import numba
    except ImportError:
        return None
    kernel: Callable[..., None] = numba.njit(cache=True, nogil=True)(shares)
    return kernel


def run(
    capacity: FloatArray,
    per_share: FloatArray,
    scale: FloatArray,
    screw_side: Any,
    g_nodes: FloatArray,
    j_nodes: FloatArray,
    tolerance: float,
    max_iter: int,
    *,
    compiled: bool = True,
    table: Any = None,
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Shares, extra powers and forces of every point, by the compiled kernel.

    With ``compiled=False``, by :func:`shares` as plain Python (for a few points).
    ``g_nodes`` and ``j_nodes`` are (K, M + 1) tables shared by every point, or
    (T, K, M + 1) sets of them with ``table`` (n,) naming each point's set.
    """
    n = len(capacity[0])
    x, power, force = np.empty(n), np.empty(n), np.empty(n)
    if not compiled:
        # Plain Python (a few points): nested lists of floats index and compute several
        # times faster than numpy's scalars, with the same operations (the same bits).
        # The inputs may come as such lists already (the caller's, tables kept).
        g_sets: Any = g_nodes if table is not None else [g_nodes]
        j_sets: Any = j_nodes if table is not None else [j_nodes]
        sets = [0] * n if table is None else [int(t) for t in table]
        shares(
            _rows(capacity), _rows(per_share), _rows(scale), [bool(v) for v in screw_side],
            _listed(g_sets), _listed(j_sets), sets, float(tolerance), int(max_iter),
            x, power, force,
        )  # fmt: skip
        return x, power, force
    kernel = _compiled()
    assert kernel is not None
    if table is None:
        g_nodes, j_nodes = g_nodes[None], j_nodes[None]
        table = np.zeros(n, dtype=np.intp)
    kernel(
        np.ascontiguousarray(capacity), np.ascontiguousarray(per_share),
        np.ascontiguousarray(scale), np.asarray(screw_side, dtype=np.bool_),
        np.ascontiguousarray(g_nodes), np.ascontiguousarray(j_nodes),
        np.ascontiguousarray(table, dtype=np.intp), float(tolerance), int(max_iter),
        x, power, force,
    )  # fmt: skip
    return x, power, force


def _rows(values: Any) -> Any:
    """(K, n) values as K lists of floats: the given lists, or an array's."""
    if isinstance(values, list) and (not values or isinstance(values[0], list)):
        return values
    return np.asarray(values, dtype=float).tolist()


def _listed(tables: Any) -> Any:
    """Tables as nested lists of floats: the given lists, or an array's (or arrays')."""
    if isinstance(tables, list) and (not tables or isinstance(tables[0], list)):
        return tables
    return [np.asarray(t, dtype=float).tolist() for t in tables]
