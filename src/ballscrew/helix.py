r"""The transverse slip the helix forces on every ball, and how the ball shares it.

The helix of a ball screw makes pure rolling at both contacts of a ball
impossible (:mod:`ballscrew.kinematics`): across the groove, the screw's
surface sweeps past the nut's at :math:`s_\perp = \omega R\sin\lambda`, and the
ball's slips at its screw and nut contacts must add up to that, whatever it
does. This module finds how the slip is shared, and what it dissipates.

**The balance that shares it.** The ball's rotation about the rolling
direction :math:`\mathbf t` is free (it moves the slip from one contact to the
other). Each contact's friction acts across the groove at the lever :math:`R`
from the ball centre, so the moment balance of the ball about :math:`\mathbf
t` (inertia and the ball-to-ball forces, which act along the groove, left
out) requires the transverse friction forces at the screw contacts to equal
those at the nut contacts:

.. math:: \sum_{\text{screw}} F_j(\Delta v_s) = \sum_{\text{nut}} F_j(\Delta v_n),\qquad
          \Delta v_s + \Delta v_n = s_\perp

(a 2-point ball has one contact on each side; a 4-point ball two, which
share one slip each). The transverse forces do not vanish: their sum, twice
the common force, is carried by the normal forces, whose lines tilt away from
the nominal contact line by :math:`\delta = \arcsin(F/Q)`, so that the screw
and nut contact angles differ by :math:`2\delta` (the result Wei & Lin [1]_
obtained by letting the two contact angles be unknowns). The model keeps the
nominal contact angle for the loads: the tilt moves load between the screw
and the nut contact of a ball by :math:`O(\mu)`, their sum and the
dissipation by :math:`O(\mu^2)`.

**The traction law.** Each contact slides under spin (and Heathcote
sliding) and the uniform slip together, at its own mixed-film coefficient
:math:`\mu`, in full slip: :math:`\boldsymbol\tau = \mu p\,\mathbf v/|\mathbf
v|` at every point (:func:`ballscrew.rolling_losses.spin_slip_integrals`), the
law the spin already uses. The spin makes the transverse force grow smoothly
with the slip (a spinning contact transmits less than :math:`\mu Q` for a
slip comparable to the spin's own sliding speeds), which fixes the share:
the weaker contact takes more of the slip. Assumed, and stated: full slip.
The steel's own tangential compliance lets a rolling contact creep
elastically (partial slip, Johnson [2]_ §8.4); for these contacts that
matters only below a slip-to-roll ratio of a few tenths of a percent,
smaller than the spin's own sliding at the ellipse ends, so the full-slip law
is kept (it overestimates the transverse traction of the smallest leads).

**What it dissipates.** The extra power over the spin alone, per ball,

.. math:: P_\perp = \sum_j \mu_j\frac{3Q_j}{2\pi}|\omega_{s,j}|\,a_j
          \left[J(\beta_j,\sigma_j) - J(\beta_j, 0)\right],\qquad
          \sigma_j = \frac{\Delta v_j}{|\omega_{s,j}|a_j}

which is close to :math:`F s_\perp` (the common force times the whole slip)
less what the slip saves on the spin. In full slip without spin (the notes'
first estimate) it would be :math:`\min_j(\mu_jQ_j)\,s_\perp`.

Two evaluations, which the tests hold against each other:

* :func:`ball_slip_balance`: one ball, scalar inputs, the balance solved with
  Brent's method on integrals evaluated directly on a fine rule, Heathcote
  sliding included: the reference.
* :func:`transverse_slip_loss`: whole arrays of operating points, as the
  complete model uses it: :math:`J` and :math:`G` tabulated once per contact
  shape (:math:`\beta = b/a` depends on the groove geometry, not on the load)
  over :math:`\sigma/(1+\sigma)`, Heathcote sliding left out of the increment
  (it adds 0.03 % to the spin of ball screw contacts), the balance solved by
  Newton's method kept in a bracket, for all points at once (with numba
  installed, ``pip install 'ballscrew[fast]'``, by a compiled loop: the same
  steps, about 4 times faster on 1e5 scattered balls, from
  :data:`JIT_MIN_POINTS` points on once the process has loaded it, which a
  call on :data:`JIT_LOAD_POINTS` points or :func:`load_kernel` does). Against the reference it
  agrees within 0.6 % on the power (40 x 5 mm; 0.02 % at 40 x 40 mm) and
  0.007 on the share of the slip, nearly all of it from the Heathcote term
  (without it the two agree to 1e-6) (``tests/physics/test_helix.py``).

References
----------
.. [1] C. C. Wei, J. F. Lin, "Kinematic analysis of the ball screw mechanism
   considering variable contact angles and elastic deformations", J. Mech.
   Des. 125 (2003) 717-733, doi:10.1115/1.1623761.
.. [2] K. L. Johnson, *Contact Mechanics*, Cambridge University Press, 1985,
   ch. 8 (rolling contact with creep and spin).
"""

from __future__ import annotations

import contextlib
import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

import numpy as np
import numpy.typing as npt

from . import _helix_kernel
from . import rolling_losses as rl
from .errors import FloatArray, check_choice, check_nonnegative, check_positive
from .numerics import Index, newton_bracketed
from .numerics.single import broadcast_shape, broadcast_to

__all__ = [
    "BallSlip",
    "SlipContact",
    "SlipShare",
    "ball_slip_balance",
    "kernel_scope",
    "load_kernel",
    "transverse_slip_loss",
]

IntArray = npt.NDArray[np.intp]

TABLE_NODES: int = 513
"""Nodes of the tables of :math:`J` and :math:`G` over :math:`t = \\sigma/(1+\\sigma)`."""

SHARE_TOLERANCE: float = 1e-9
r"""Tolerance of the slip share in :func:`transverse_slip_loss` [-] (and of the force
balance, relative to the ball's total friction capacity). The dissipation is
stationary at the balance (the transverse force is the derivative of a contact's
friction power with respect to its slip), so an error :math:`\delta` in the
share changes the power by :math:`O(\delta^2)`: 1e-18 of it here."""

ASPECT_NODES: int = 257
r"""Ellipse aspects :math:`\beta = b/a` at which the tables are built, uniform on [0, 1]
(spacing 1/256); between them the tables are interpolated cubically (from 0.02 up;
narrower contacts get tables of their own). Against tables built at the aspect
itself that errs by at most 6e-7 in :math:`G` and 2e-8 (relative)
in :math:`J` (``tests/physics/test_helix.py``), far below the linear interpolation
in :math:`t`; and a new screw costs no table of its own, only the few nodes around
its contacts' aspects that no earlier screw needed (8 ms each, once per process)."""

MAX_ITERATIONS: int = 100
"""Residual evaluations at most per point in the slip-share solve (Newton's method in a
bracket halves the bracket at worst, so 100 is far past the 31 bisections 1e-9 takes)."""

PYTHON_MAX_POINTS: int = 4
"""Up to this many points :func:`transverse_slip_loss` runs the kernel's loop as plain
Python (about 0.1 ms a point, against 0.6 ms for the numpy path's whole-array steps on
a few points): the same steps, without a compiler."""

JIT_MIN_POINTS: int = 256
"""Points from which :func:`transverse_slip_loss` runs the compiled kernel of the ``fast``
extra (:mod:`ballscrew._helix_kernel`) when numba is installed and the kernel is loaded;
below it (and without numba) the numpy path, which needs no compiler."""

JIT_LOAD_POINTS: int = 1 << 17
"""Points from which :func:`transverse_slip_loss` loads the compiled kernel if this process
has not (numba's import and the kernel from its disk cache: about 0.3 s of CPU, which the
kernel repays over some 3e5 points, at about 1 µs a point for a double nut). A call on
fewer points takes the numpy path until then; :func:`load_kernel` loads it ahead (the web
calculator's and the sweeps' workers do)."""


@dataclass(frozen=True)
class SlipContact:
    r"""One contact of a ball, as the transverse-slip balance sees it.

    Attributes
    ----------
    side : {"screw", "nut"}
        Which member the ball touches here.
    friction : array_like
        Sliding friction coefficient :math:`\mu` of the contact [-].
    load : array_like
        Normal load :math:`Q` [N].
    semi_axis : array_like
        Hertz semi-axis across the groove :math:`a` [m].
    aspect : float or numpy.ndarray
        :math:`\beta = b/a` [-], in (0, 1] (one per screw, for many screws at once).
    spin : float or numpy.ndarray
        Spin over screw speed :math:`|\omega_s/\omega|` [-], > 0 (one per screw).
    curvature : float
        Heathcote coefficient over spin and semi-axis, :math:`C/\omega_s` [1/m]
        (:math:`\kappa = Ca/\omega_s`); used only by :func:`ball_slip_balance`.
    """

    side: Literal["screw", "nut"]
    friction: npt.ArrayLike
    load: npt.ArrayLike
    semi_axis: npt.ArrayLike
    aspect: float | FloatArray
    spin: float | FloatArray
    curvature: float = 0.0


@dataclass(frozen=True)
class SlipShare:
    r"""How a ball shares the transverse slip, at every operating point.

    Attributes
    ----------
    power : numpy.ndarray
        Dissipation of the slip, over that of the spin alone, per ball and per
        unit screw speed [N·m] (a torque on the screw).
    screw_share : numpy.ndarray
        Share of the slip taken at the screw contact(s) [-], 0 to 1.
    force : numpy.ndarray
        Transverse friction force at the screw contact(s), equal to that at the
        nut contact(s) [N].
    """

    power: FloatArray
    screw_share: FloatArray
    force: FloatArray


TABLES_FILE = Path(__file__).parent / "data" / "helix_tables.npz"
"""The tables at every aspect node, built by ``scripts/build_helix_tables.py`` from
:func:`_exact_tables` (a test checks that they still equal a fresh build)."""


@functools.cache
def _stored_tables() -> tuple[FloatArray, FloatArray] | None:
    """J/(1+sigma) and G at every aspect node from :data:`TABLES_FILE`; None if it does not fit."""
    try:
        with np.load(TABLES_FILE) as stored:
            fits = (
                int(stored["table_nodes"]) == TABLE_NODES
                and int(stored["aspect_nodes"]) == ASPECT_NODES
            )
            return (stored["j"], stored["g"]) if fits else None
    except (OSError, KeyError, ValueError):
        return None


@functools.cache
def _node_tables(node: int) -> tuple[FloatArray, FloatArray]:
    """The tabulated J/(1+sigma) and G at the aspect node ``node`` (kappa = 0).

    Read from :data:`TABLES_FILE` (built with the same rule); computed (8 ms) when
    the file is missing or does not fit the nodes.
    """
    stored = _stored_tables()
    if stored is not None:
        return stored[0][node], stored[1][node]
    return _exact_tables(node / (ASPECT_NODES - 1))


def _exact_tables(aspect: float) -> tuple[FloatArray, FloatArray]:
    """J/(1+sigma) and G over the t nodes at ``aspect``, by the quadrature rule (8 ms)."""
    t = np.linspace(0.0, 1.0, TABLE_NODES)
    sigma = t[:-1] / (1.0 - t[:-1])
    j, g = rl.spin_slip_integrals(0.0, aspect, sigma)
    g[0] = 0.0  # no slip, no net transverse force (odd in X; the rule leaves 1e-17)
    # t = 1 is sigma -> infinity: J/sigma -> 2 pi / 3 (the disk's pressure weight), G -> 1.
    return np.append(j / (1.0 + sigma), 2.0 * math.pi / 3.0), np.append(g, 1.0)


@functools.lru_cache(maxsize=256)
def _tables(aspect: float) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Nodes t and the tabulated J/(1+sigma) and G at ``aspect`` (kappa = 0).

    Cubic (4-point Lagrange) interpolation across the aspect nodes
    (:data:`ASPECT_NODES`) of the tables built there; an aspect on a node gets
    that node's table exactly, one outside [0.02, 1] its own (below 0.02, contacts
    far narrower than any ball screw groove's, the cubic errs by up to 2e-6 in G).
    """
    t = np.linspace(0.0, 1.0, TABLE_NODES)
    if not 0.02 <= aspect <= 1.0:
        return t, *_exact_tables(aspect)
    intervals = ASPECT_NODES - 1
    first = min(max(int(aspect * intervals) - 1, 0), intervals - 3)
    u = aspect * intervals - first  # position from the stencil's first node, in [0, 3]
    weights = (
        -(u - 1.0) * (u - 2.0) * (u - 3.0) / 6.0,
        u * (u - 2.0) * (u - 3.0) / 2.0,
        -u * (u - 1.0) * (u - 3.0) / 2.0,
        u * (u - 1.0) * (u - 2.0) / 6.0,
    )
    j = np.zeros(TABLE_NODES)
    g = np.zeros(TABLE_NODES)
    for k, weight in enumerate(weights):
        if weight != 0.0:
            j_node, g_node = _node_tables(first + k)
            j += weight * j_node
            g += weight * g_node
    j[-1], g[-1] = 2.0 * math.pi / 3.0, 1.0  # the limits, exactly
    return t, j, g


def _on_table(nodes: FloatArray, sigma: FloatArray) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Linear interpolation of ``nodes`` (uniform in t = sigma/(1+sigma)) at ``sigma`` >= 0.

    Returns the value, the rise of its interval, and the scaled position t x intervals;
    the interval is found by arithmetic (the nodes are uniform), not by search.
    """
    intervals = TABLE_NODES - 1
    t = sigma / (1.0 + sigma) * intervals
    i = np.minimum(t.astype(np.intp), intervals - 1)
    rise = nodes[i + 1] - nodes[i]
    value: FloatArray = nodes[i] + (t - i) * rise
    return value, rise, t


def _lookup_j(aspect: float, sigma: FloatArray) -> FloatArray:
    """J at finite slip ratios ``sigma`` >= 0, by linear interpolation in the table."""
    _, j_nodes, _ = _tables(aspect)
    j: FloatArray = _on_table(j_nodes, sigma)[0] * (1.0 + sigma)
    return j


def _lookup_g(aspect: float, sigma: FloatArray) -> tuple[FloatArray, FloatArray]:
    """G and dG/dsigma at slip ratios ``sigma`` >= 0, linear in the table as :func:`_lookup_j`.

    The slope is that of the table's interval, times dt/dsigma = 1/(1+sigma)^2.
    """
    _, _, g_nodes = _tables(aspect)
    g, rise, _ = _on_table(g_nodes, sigma)
    slope: FloatArray = rise * (TABLE_NODES - 1) / (1.0 + sigma) ** 2
    return g, slope


def load_kernel() -> bool:
    """Load the compiled slip-share loop now; return whether it will be used.

    Loading is numba's import and the kernel from its disk cache, or its compilation
    the first time: 0.3 s to 2 s. For servers, workers and long runs, which then use
    it from :data:`JIT_MIN_POINTS` points on; otherwise the first call on
    :data:`JIT_LOAD_POINTS` points or more loads it. False without numba or with
    ``BALLSCREW_JIT=0``.
    """
    return _helix_kernel.enabled()


def kernel_scope() -> contextlib.AbstractContextManager[None]:
    """A block whose calls use the compiled slip-share loop (loaded if need be).

    For many screws' friction in one call (a selection's heat balances): the
    loop solves every screw's rows at once, where the numpy path takes them one
    by one. Outside the block the process keeps its path: a kernel loaded only
    for the block is not used by the other calls, so their numbers stay those of
    a process without it (the two paths agree to rounding, not bit for bit).
    Without numba, or with ``BALLSCREW_JIT=0``, the numpy path.
    """
    return _helix_kernel.scoped()


def _single(x: Any) -> bool:
    """Whether ``x`` is one number (one screw's), not an array of them."""
    return type(x) is float or np.ndim(x) == 0


def _check_contacts(contacts: Sequence[SlipContact]) -> None:
    sides = {c.side for c in contacts}
    if sides != {"screw", "nut"}:
        raise ValueError("a ball needs at least one screw and one nut contact")
    for c in contacts:
        check_choice("side", c.side, ("screw", "nut"))
        check_positive("spin", c.spin)
        check_positive("aspect", c.aspect)


def _contact_arrays(
    contacts: Sequence[SlipContact],
) -> tuple[tuple[int, ...], list[FloatArray], list[FloatArray]]:
    """The points' shape, and each contact's capacity mu Q and spin scale |omega_s| a, flat."""
    arrays = [
        (
            np.asarray(c.friction, dtype=float),
            np.asarray(c.load, dtype=float),
            np.asarray(c.semi_axis, dtype=float),
        )
        for c in contacts
    ]
    # The products broadcast their factors, element by element as on broadcast copies.
    shape = broadcast_shape(*(x.shape for values in arrays for x in values))
    capacity = [broadcast_to(mu * q, shape).reshape(-1) for mu, q, _ in arrays]
    scale = [broadcast_to(c.spin * a, shape).reshape(-1) for c, (_, _, a) in zip(
        contacts, arrays, strict=True)]  # fmt: skip
    return shape, capacity, scale


def _stacked(
    contacts: Sequence[SlipContact],
    capacity: Sequence[FloatArray],
    scale: Sequence[FloatArray],
    slip: float,
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray, FloatArray, FloatArray]:
    """The compiled kernel's inputs (:func:`ballscrew._helix_kernel.shares`), contacts by rows.

    The slip ratio per unit share is 0 at an unloaded contact (no spin scale),
    as in the numpy path.
    """
    stacked_scale = np.stack(scale)
    per_share = slip / np.where(stacked_scale > 0.0, stacked_scale, np.inf)
    sides, g_nodes, j_nodes = _stacked_tables(
        tuple(c.side == "screw" for c in contacts), tuple(float(c.aspect) for c in contacts)
    )
    return np.stack(capacity), per_share, stacked_scale, sides, g_nodes, j_nodes


@functools.lru_cache(maxsize=64)
def _stacked_tables(
    sides: tuple[bool, ...], aspects: tuple[float, ...]
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """The contacts' sides (True: screw) and their G and J tables, stacked by contact (kept)."""
    tables = [_tables(a) for a in aspects]
    return (
        np.array(sides),
        np.stack([g for _, _, g in tables]),
        np.stack([j for _, j, _ in tables]),
    )


@functools.lru_cache(maxsize=64)
def _listed_tables(sides: tuple[bool, ...], aspects: tuple[float, ...]) -> tuple[Any, Any]:
    """:func:`_stacked_tables`' G and J tables as nested lists (one set), for plain Python."""
    _, g_nodes, j_nodes = _stacked_tables(sides, aspects)
    return g_nodes.tolist(), j_nodes.tolist()


def _kernel_inputs(
    contacts: Sequence[SlipContact], slip: float
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray, FloatArray, FloatArray, IntArray]:
    """The compiled kernel's inputs for ``contacts`` (flattened points) and ``slip``.

    One set of tables, shared by every point (the kernel's ``table`` all 0).
    """
    _, capacity, scale = _contact_arrays(contacts)
    cap, per_share, stacked_scale, sides, g_nodes, j_nodes = _stacked(
        contacts, capacity, scale, slip
    )
    table = np.zeros(cap.shape[1], dtype=np.intp)
    return cap, per_share, stacked_scale, sides, g_nodes[None], j_nodes[None], table


def _tables_many(aspects: FloatArray) -> tuple[FloatArray, FloatArray]:
    """:func:`_tables`' J/(1+sigma) and G at each of ``aspects`` (A,), as (A, nodes) arrays.

    The same cubic interpolation across the aspect nodes, written on whole arrays, term
    for term in the same order (the same bits as :func:`_tables`); an aspect outside
    [0.02, 1] gets its own tables. The last two sets are kept (the caller must not change
    them): a double nut's second family has the same contacts' aspects as its first.
    """
    aspects = np.ascontiguousarray(aspects, dtype=float).reshape(-1)
    return _tables_many_kept(aspects.tobytes())


@functools.lru_cache(maxsize=2)
def _tables_many_kept(key: bytes) -> tuple[FloatArray, FloatArray]:
    """:func:`_tables_many` of the aspects whose bytes are ``key``."""
    aspects = np.frombuffer(key, dtype=float)
    inside = (aspects >= 0.02) & (aspects <= 1.0)
    j = np.zeros((aspects.size, TABLE_NODES))
    g = np.zeros((aspects.size, TABLE_NODES))
    if inside.any():
        a = aspects[inside]
        intervals = ASPECT_NODES - 1
        first = np.clip((a * intervals).astype(np.intp) - 1, 0, intervals - 3)
        u = a * intervals - first
        weights = (
            -(u - 1.0) * (u - 2.0) * (u - 3.0) / 6.0,
            u * (u - 2.0) * (u - 3.0) / 2.0,
            -u * (u - 1.0) * (u - 3.0) / 2.0,
            u * (u - 1.0) * (u - 2.0) / 6.0,
        )
        stored = _stored_tables()
        if stored is None:
            nodes = [_node_tables(i) for i in range(ASPECT_NODES)]
            stored = (np.stack([n[0] for n in nodes]), np.stack([n[1] for n in nodes]))
        j_in, g_in = j[inside], g[inside]
        for k, weight in enumerate(weights):
            j_in += weight[:, None] * stored[0][first + k]
            g_in += weight[:, None] * stored[1][first + k]
        j[inside], g[inside] = j_in, g_in
        j[:, -1], g[:, -1] = 2.0 * math.pi / 3.0, 1.0
    for i in np.flatnonzero(~inside):
        _, j[i], g[i] = _tables(float(aspects[i]))
    return j, g


def _rows_slip_loss(contacts: Sequence[SlipContact], slip: npt.ArrayLike) -> SlipShare:
    """:func:`transverse_slip_loss` of many screws at once: first axis the screws.

    Each contact's ``aspect`` and ``spin`` and the ``slip`` hold one value per screw
    (shape (S,) or (S, 1, ...)); its arrays have the screws on their first axis. With
    the compiled kernel every point runs the same steps on its own screw's tables as
    in a call for that screw alone; without it, one call per screw.
    """
    count = max(int(np.size(c.aspect)) for c in contacts)
    aspects = [np.broadcast_to(np.asarray(c.aspect, dtype=float).reshape(-1), (count,))
               for c in contacts]  # fmt: skip
    spins = [np.broadcast_to(np.asarray(c.spin, dtype=float).reshape(-1), (count,))
             for c in contacts]  # fmt: skip
    slips = np.broadcast_to(np.asarray(slip, dtype=float).reshape(-1), (count,))
    for c, spin, aspect in zip(contacts, spins, aspects, strict=True):
        check_choice("side", c.side, ("screw", "nut"))
        check_positive("spin", spin)
        check_positive("aspect", aspect)
    check_nonnegative("slip", slips, "m")
    shape = np.broadcast_shapes(
        *(np.broadcast_shapes(np.shape(c.friction), np.shape(c.load), np.shape(c.semi_axis))
          for c in contacts),
    )  # fmt: skip
    shape = (count, *shape[1:]) if shape else (count,)
    n = math.prod(shape)
    per_screw = n // count
    if not (n >= JIT_MIN_POINTS and _helix_kernel.enabled(load=n >= JIT_LOAD_POINTS)):
        rows = [
            transverse_slip_loss(
                [SlipContact(c.side, _row(c.friction, i, shape), _row(c.load, i, shape),
                             _row(c.semi_axis, i, shape), float(aspects[k][i]),
                             float(spins[k][i]))
                 for k, c in enumerate(contacts)],
                float(slips[i]),
            )
            for i in range(count)
        ]  # fmt: skip
        return SlipShare(
            power=np.stack([r.power for r in rows]).reshape(shape),
            screw_share=np.stack([r.screw_share for r in rows]).reshape(shape),
            force=np.stack([r.force for r in rows]).reshape(shape),
        )
    capacity = np.stack([
        np.broadcast_to(np.asarray(c.friction, dtype=float) * np.asarray(c.load, dtype=float),
                        shape).reshape(-1)
        for c in contacts
    ])  # fmt: skip
    column = (count,) + (1,) * (len(shape) - 1)
    scale = np.stack([
        np.broadcast_to(spin.reshape(column) * np.asarray(c.semi_axis, dtype=float),
                        shape).reshape(-1)
        for c, spin in zip(contacts, spins, strict=True)
    ])  # fmt: skip
    per_point_slip = np.repeat(slips, per_screw)
    per_share = per_point_slip / np.where(scale > 0.0, scale, np.inf)
    j_all, g_all = _tables_many(np.stack(aspects, axis=1).reshape(-1))
    g_nodes = g_all.reshape(count, len(contacts), TABLE_NODES)
    j_nodes = j_all.reshape(count, len(contacts), TABLE_NODES)
    sides = np.array([c.side == "screw" for c in contacts])
    table = np.repeat(np.arange(count, dtype=np.intp), per_screw)
    x, power, force = _helix_kernel.run(
        capacity, per_share, scale, sides, g_nodes, j_nodes, SHARE_TOLERANCE, MAX_ITERATIONS,
        compiled=True, table=table,
    )  # fmt: skip
    return SlipShare(
        power=power.reshape(shape), screw_share=x.reshape(shape), force=force.reshape(shape)
    )


def _row(value: npt.ArrayLike, i: int, shape: tuple[int, ...]) -> FloatArray:
    """Screw ``i``'s values of an array whose first axis is the screws' (or 1: shared)."""
    x = np.asarray(value, dtype=float)
    x = x.reshape((1,) * (len(shape) - x.ndim) + x.shape)
    row: FloatArray = x[i if x.shape[0] > 1 else 0]
    return row


def transverse_slip_loss(contacts: Sequence[SlipContact], slip: npt.ArrayLike) -> SlipShare:
    r"""Dissipation of the transverse slip of one ball, shared by its moment balance.

    Vectorised over the operating points (the arrays of the contacts
    broadcast against each other); see the module docstring for the balance,
    the traction law and the tabulation.

    Parameters
    ----------
    contacts : sequence of SlipContact
        The ball's contacts: one screw and one nut contact (2-point), or two
        of each (4-point).
    slip : float or array_like
        Transverse slip per unit screw speed, :math:`s_\perp/\omega = R\sin\lambda` [m].
        Many screws at once: ``slip`` and each contact's ``aspect`` and ``spin`` hold one
        value per screw, and the contacts' arrays have the screws on their first axis.

    Returns
    -------
    SlipShare

    Examples
    --------
    Two equal contacts share the slip equally and transmit the same force:

    >>> c = [SlipContact(side, 0.08, 30.0, 0.26e-3, 0.2, 0.35) for side in ("screw", "nut")]
    >>> r = transverse_slip_loss(c, 2.5e-4)
    >>> round(float(r.screw_share), 6), round(float(r.force), 3)
    (0.5, 2.29)
    """
    if not _single(slip) or not all(_single(c.aspect) and _single(c.spin) for c in contacts):
        return _rows_slip_loss(contacts, slip)
    _check_contacts(contacts)
    s = float(check_nonnegative("slip", slip, "m"))
    shape, capacity, scale = _contact_arrays(contacts)

    def ratio(speed: FloatArray | float, k: int, index: Index) -> FloatArray:
        # An unloaded contact (a = 0) has no capacity: its ratio is never used, 0 is taken.
        w = scale[k][index]
        r: FloatArray = speed / np.where(w > 0.0, w, np.inf)
        return r

    def side_force(x: FloatArray, side: str, index: Index) -> tuple[FloatArray, FloatArray]:
        """Transverse force of one side's contacts, and its rate over the screw's share x."""
        share = x if side == "screw" else 1.0 - x
        sign = 1.0 if side == "screw" else -1.0
        total: FloatArray = np.zeros(np.shape(x))
        rate: FloatArray = np.zeros(np.shape(x))
        for k, c in enumerate(contacts):
            if c.side == side:
                per_share = ratio(s, k, index)  # d sigma / d share
                g, slope = _lookup_g(float(c.aspect), share * per_share)
                total = total + capacity[k][index] * g
                rate = rate + sign * capacity[k][index] * slope * per_share
        return total, rate

    def residual(x: FloatArray, index: Index) -> tuple[FloatArray, FloatArray]:
        screw_force, screw_rate = side_force(x, "screw", index)
        nut_force, nut_rate = side_force(x, "nut", index)
        return screw_force - nut_force, screw_rate - nut_rate

    n = math.prod(shape)
    if n <= PYTHON_MAX_POINTS or (
        n >= JIT_MIN_POINTS and _helix_kernel.enabled(load=n >= JIT_LOAD_POINTS)
    ):
        if n > PYTHON_MAX_POINTS:
            inputs: tuple[Any, ...] = _stacked(contacts, capacity, scale, s)
        else:
            # Plain Python: the inputs of _stacked as nested lists of floats (the slip ratio
            # per unit share divided alike, 0 at an unloaded contact), the tables kept so.
            sides = tuple(c.side == "screw" for c in contacts)
            scale_rows = [row.tolist() for row in scale]
            inputs = (
                [row.tolist() for row in capacity],
                [[s / (w if w > 0.0 else math.inf) for w in row] for row in scale_rows],
                scale_rows,
                list(sides),
                *_listed_tables(sides, tuple(float(c.aspect) for c in contacts)),
            )
        cap, per_share, stacked_scale, sides_of, g_nodes, j_nodes = inputs
        x, power, force = _helix_kernel.run(
            cap, per_share, stacked_scale, sides_of, g_nodes, j_nodes, SHARE_TOLERANCE,
            MAX_ITERATIONS, compiled=n > PYTHON_MAX_POINTS,
        )  # fmt: skip
        return SlipShare(
            power=power.reshape(shape), screw_share=x.reshape(shape), force=force.reshape(shape)
        )
    everything = np.arange(n)
    lo, hi = np.zeros(n), np.ones(n)
    f_lo, f_hi = residual(lo, everything)[0], residual(hi, everything)[0]
    # A side that cannot carry a transverse force (unloaded) takes all the slip, free: the
    # nut's when f(0) >= 0, else the screw's; the others are solved below.
    x = np.where(f_lo >= 0.0, 0.0, 1.0)
    loaded = (f_lo < 0.0) & (f_hi > 0.0)
    if loaded.any():
        idx = np.flatnonzero(loaded)
        total_capacity = sum(capacity, np.zeros(n))
        # Start where a straight line between the two ends' residuals crosses zero.
        start = -f_lo[idx] / (f_hi[idx] - f_lo[idx])
        x[idx] = newton_bracketed(
            lambda xx, i: residual(xx, idx[i]), lo[idx], hi[idx], start,
            xtol=SHARE_TOLERANCE, ftol=SHARE_TOLERANCE * total_capacity[idx],
            max_iter=MAX_ITERATIONS,
        )  # fmt: skip
    power = np.zeros(n)
    for k, c in enumerate(contacts):
        share = x if c.side == "screw" else 1.0 - x
        j_slip = _lookup_j(float(c.aspect), ratio(share * s, k, everything))
        j_spin = _tables(float(c.aspect))[1][0]  # J at sigma = 0: the spin alone
        power += capacity[k] * 1.5 / math.pi * scale[k] * (j_slip - j_spin)
    force = side_force(x, "screw", everything)[0]
    return SlipShare(
        power=power.reshape(shape), screw_share=x.reshape(shape), force=force.reshape(shape)
    )


@dataclass(frozen=True)
class BallSlip:
    r"""The one-ball reference solution (:func:`ball_slip_balance`).

    Attributes
    ----------
    screw_share : float
        Share of the slip at the screw contact(s) [-].
    force : float
        Transverse force at the screw side, equal to the nut side's [N].
    power : float
        Extra dissipation over the spin alone, per unit screw speed [N·m].
    tilt : tuple of float
        Tilt of each contact's normal force out of the nominal contact line,
        :math:`\arcsin(F_j/Q_j)` [rad], in the order of the contacts.
    """

    screw_share: float
    force: float
    power: float
    tilt: tuple[float, ...]


_FINE_RULE = rl._disk_rule(40, 640, half=False)


def _fine_integrals(kappa: float, beta: float, sigma: float) -> tuple[float, float]:
    """J and G on a fine rule (40 x 640 nodes), independent of the tables."""
    x, y, w = _FINE_RULE
    vx = kappa * y * y + y
    vy = beta * x + sigma
    speed = np.hypot(vx, vy)
    share = np.divide(vy, speed, out=np.zeros_like(speed), where=speed > 0.0)
    return float(speed @ w), float(share @ w) * 1.5 / math.pi


def ball_slip_balance(contacts: Sequence[SlipContact], slip: float) -> BallSlip:
    r"""Reference solution of one ball's transverse-slip balance (scalar inputs).

    Brent's method on the share of the slip at the screw, with the power and
    force integrals of each contact evaluated directly on a 40 x 640-node rule
    over the whole ellipse, Heathcote sliding included (each contact's
    ``curvature``). Slow; used to check :func:`transverse_slip_loss`.

    Examples
    --------
    >>> c = [SlipContact(side, 0.08, 30.0, 0.26e-3, 0.2, 0.35) for side in ("screw", "nut")]
    >>> r = ball_slip_balance(c, 2.5e-4)
    >>> round(r.screw_share, 3), round(r.force, 2), round(math.degrees(r.tilt[0]), 2)
    (0.5, 2.29, 4.38)
    """
    from scipy.optimize import brentq

    _check_contacts(contacts)
    s = float(check_nonnegative("slip", slip, "m"))
    mu = [float(np.asarray(c.friction)) for c in contacts]
    semi = [float(check_positive("semi_axis", c.semi_axis, "m")) for c in contacts]
    values = [
        (m * float(np.asarray(c.load)), float(c.spin) * a)
        for m, c, a in zip(mu, contacts, semi, strict=True)
    ]

    def integrals(k: int, speed: float) -> tuple[float, float]:
        c = contacts[k]
        return _fine_integrals(c.curvature * semi[k], float(c.aspect), speed / values[k][1])

    def force(x: float, side: str) -> float:
        share = x if side == "screw" else 1.0 - x
        return sum(
            values[k][0] * integrals(k, share * s)[1]
            for k, c in enumerate(contacts)
            if c.side == side
        )

    x = brentq(lambda v: force(v, "screw") - force(v, "nut"), 0.0, 1.0, xtol=1e-13)
    power = 0.0
    tilt = []
    for k, c in enumerate(contacts):
        share = x if c.side == "screw" else 1.0 - x
        cap, w = values[k]
        j_slip, g = integrals(k, share * s)
        j_spin = integrals(k, 0.0)[0]
        power += cap * 1.5 / math.pi * w * (j_slip - j_spin)
        tilt.append(math.asin(min(1.0, mu[k] * g)))
    return BallSlip(screw_share=float(x), force=force(x, "screw"), power=power, tilt=tuple(tilt))
