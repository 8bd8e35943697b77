r"""The friction chain: one way in to every friction model.

(A long module, about 950 lines: the calls of one screw and of many screws, and the memo
that answers a selection's repeated calls, share the checks of the inputs and the
assembly of the results, which stay here with them.)

:func:`friction_torque` validates and broadcasts the operating points, runs
the chosen model (in chunks, so memory stays bounded on large grids), adds
up its torque contributions and derives power loss and efficiency, in the
manner of pvlib's ``ModelChain``. A new model is one module in
:mod:`ballscrew.friction` and one ``@register`` line.
"""

from __future__ import annotations

import contextlib
import contextvars
import math
import warnings
from collections import OrderedDict
from collections.abc import Callable, Collection, Iterator, Mapping, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np
import numpy.typing as npt

from . import validity
from .design.ratings import Finding, Ratings, plausibility, raise_errors
from .errors import BallScrewInputError, BallScrewValidityWarning, FloatArray
from .friction import MODELS, ModelSpec, get_model
from .geometry import BallScrew, ScrewArray
from .helix import JIT_LOAD_POINTS, kernel_scope, load_kernel
from .kinematics import rad_s_to_rpm
from .lubricant import Lubricant
from .numerics.single import broadcast_shape
from .state import OperatingState, operating_points, operating_state_unchecked
from .validity import ValidityIssue

__all__ = [
    "FrictionResult",
    "TorqueTable",
    "fill_friction_memo",
    "friction_memo",
    "friction_torque",
    "friction_torques",
    "model_named",
    "models",
    "operating_grid",
    "torque_table",
]


@dataclass(frozen=True)
class FrictionResult:
    r"""Friction torque and what follows from it, at every operating point.

    Attributes
    ----------
    model : str
        Name of the model.
    total : numpy.ndarray
        Friction torque on the screw [N·m], >= 0 (it opposes the motion).
    components : Mapping[str, numpy.ndarray]
        Named torque contributions [N·m] that add up to ``total``.
    power_loss : numpy.ndarray
        :math:`T|\omega|` [W].
    efficiency : numpy.ndarray
        Forward efficiency, rotation to translation [-]: useful power
        :math:`|F_a| l/2\pi` over input :math:`|F_a| l/2\pi + T`; 0 where
        there is no axial load (no useful output).
    speed, temperature, axial_load : numpy.ndarray
        The operating points, broadcast: [rad/s], [°C], [N].
    parameters : dict
        The model parameters used, defaults filled in.
    warnings : tuple of ValidityIssue
        The validity-range issues this call warned about (quantity, value,
        range, source, model; ``str()`` gives the message; see
        :mod:`ballscrew.validity`).
    state : OperatingState or None
        The contact state the model worked on (loads, Hertz ellipses, film,
        film parameter, asperity share of every contact), kept as the chain
        built it for models that use one, when the points were evaluated in
        one chunk; None otherwise.
    """

    model: str
    total: FloatArray
    components: Mapping[str, FloatArray]
    power_loss: FloatArray
    efficiency: FloatArray
    speed: FloatArray
    temperature: FloatArray
    axial_load: FloatArray
    parameters: dict[str, Any] = field(default_factory=dict)
    warnings: tuple[validity.ValidityIssue, ...] = ()
    state: OperatingState | None = field(default=None, repr=False)


_NOTED: set[tuple[str, str]] = set()
"""(quantity, model) of the routine range issues already told in this session."""


_UNSOLVED = (ArithmeticError, RuntimeError, np.linalg.LinAlgError)
"""What a model's numerics raise where it cannot solve a point (an overflow, a root
bracket that fails, a singular system): reported as an input error naming the points."""


def models() -> list[ModelSpec]:
    """The registered friction models, with title, reference, validity and parameters.

    Examples
    --------
    >>> sorted(m.name for m in models())  # doctest: +NORMALIZE_WHITESPACE
    ['catalog', 'complete', 'harris-full', 'harris-simplified', 'olaru', 'viscoelastic']
    """
    return list(MODELS.values())


def model_named(name: str) -> ModelSpec:
    """The registered model ``name``; an unknown name raises an input error listing the models.

    Examples
    --------
    >>> model_named("catalog").name
    'catalog'
    """
    return get_model(name)


MEMO_SIZE = 16
"""The most results a :func:`friction_memo` block keeps (the least recently used go first)."""

MEMO_BYTES = 128 << 20
"""The most bytes of arrays a :func:`friction_memo` block keeps [B]: a long cycle's results
(one array a mechanism over its samples) go first, whatever their number."""


class _Memo(OrderedDict[Any, FrictionResult]):
    """The results a :func:`friction_memo` block keeps, least recently used first."""

    def __init__(self, size: int) -> None:
        super().__init__()
        self.size, self.nbytes = size, 0
        self.sizes: dict[Any, int] = {}

    def keep(self, key: Any, result: FrictionResult) -> None:
        """Keep ``result`` (made read-only) under ``key``; drop the oldest past the bounds."""
        nbytes = _nbytes(result)
        if nbytes > MEMO_BYTES // 4:  # one result that would crowd the others out
            return
        _freeze(result)
        if key in self:
            self.nbytes -= self.sizes[key]
        self[key], self.sizes[key] = result, nbytes
        self.nbytes += nbytes
        while len(self) > self.size or self.nbytes > MEMO_BYTES:
            old, _ = self.popitem(last=False)
            self.nbytes -= self.sizes.pop(old)


_MEMO: contextvars.ContextVar[_Memo | None] = contextvars.ContextVar("friction_memo", default=None)


@contextlib.contextmanager
def friction_memo(size: int = MEMO_SIZE) -> Iterator[None]:
    """A block in which :func:`friction_torque` answers a call equal to a recent one from memory.

    A call is equal to an earlier one when its screw, lubricant, model, parameters,
    options and operating points (values, shapes and types) are: the result is the
    earlier call's own object, so its numbers are those of a new call to the last bit
    (the model is deterministic), and its validity warnings are given again as a new
    call would give them. The arrays of a kept result are read-only. ``ballscrew
    select`` evaluates its candidates inside one: candidates that differ only in their
    motor (a motor table) run the same friction calls. The ``size`` most recent
    results are kept, at most :data:`MEMO_BYTES` of their arrays; a call whose
    parameters cannot be hashed is not kept. :func:`fill_friction_memo` puts in the
    results of many screws' calls ahead, from one :func:`friction_torques` call.
    """
    token = _MEMO.set(_Memo(size))
    try:
        yield
    finally:
        _MEMO.reset(token)


def fill_friction_memo(
    screws: Sequence[BallScrew],
    lubricant: Lubricant | str,
    points: Sequence[tuple[npt.ArrayLike, npt.ArrayLike, npt.ArrayLike]],
    *,
    model: str = "complete",
    **parameters: Any,
) -> int:
    """Put the results of ``friction_torque(screws[i], lubricant, speed=.., ..)`` in the memo.

    ``points[i]`` is screw ``i``'s (speed, temperature, axial_load), each a number or a
    1-D array, as its own call would be given them. The screws of one nut arrangement
    go through the model together (:func:`friction_torques`, their geometry as arrays:
    equal to the screw's own call within 1e-12 relative, the components the same), and
    each screw's result is then kept in the active :func:`friction_memo` under its own
    call's key, built as that call builds it (its broadcast points, parameters, validity
    issues; ``state`` None): that call, made next, answers from memory. A call already
    kept, one over more points than the model's chunk, and the screws of a group with a
    point the model cannot solve are left to their own calls (which then give their own
    error). Returns how many results were put in; 0 outside a memo block.
    """
    memo = _MEMO.get()
    if memo is None:
        return 0
    todo: dict[Any, tuple[BallScrew, Any, tuple[FloatArray, FloatArray, FloatArray]]] = {}
    for screw, (w, t, fa) in zip(screws, points, strict=True):
        key = _memo_key(screw, lubricant, model, (w, t, fa), (None, True), parameters)
        if key is None or key in memo or key in todo:
            continue
        prepared = _prepared(screw, lubricant, model, parameters, None, (w, t, fa))
        oil, _, chunk, own, _ = prepared
        shape = np.broadcast_shapes(*(x.shape for x in own))
        if len(shape) > 1 or math.prod(shape) > chunk:
            continue
        todo[key] = (screw, prepared, own)
    filled = 0
    kinds: dict[tuple[str, str], list[Any]] = {}
    for key, (screw, _, _) in todo.items():
        kinds.setdefault((screw.nut, screw.ball_separation), []).append(key)
    for keys in kinds.values():
        items = [todo[k] for k in keys]
        sizes = [math.prod(np.broadcast_shapes(*(x.shape for x in own))) for _, _, own in items]
        width = max(sizes)
        rows = np.empty((3, len(items), width))
        for j, ((_, _, own), n) in enumerate(zip(items, sizes, strict=True)):
            for x, row in zip(own, rows[:, j], strict=True):
                row[:n] = np.broadcast_to(x, (n,))
                row[n:] = row[n - 1]  # padding: repeats of the last point
        first = items[0][1]
        try:
            with warnings.catch_warnings(), kernel_scope():
                warnings.simplefilter("ignore")
                many = friction_torques(
                    [screw for screw, _, _ in items], first[0], speed=rows[0],
                    temperature=rows[1], axial_load=rows[2], model=model, paired=True,
                    warn=False, **parameters,
                )  # fmt: skip
        except BallScrewInputError:
            continue
        for j, (key, (screw, prepared, _), n) in enumerate(zip(keys, items, sizes, strict=True)):
            oil, spec, _, (w0, t0, fa0), used = prepared
            shape = np.broadcast_shapes(w0.shape, t0.shape, fa0.shape)
            kept = {k: np.array(v[j, :n], dtype=float).reshape(shape)
                    for k, v in many.components.items()}  # fmt: skip
            total = np.zeros(shape)
            for value in kept.values():
                total += value
            issues = validity.check(screw, oil, w0, t0, fa0, spec.name, used, spec.checks)
            w, t, fa = np.broadcast_arrays(w0, t0, fa0)
            result = _result(spec, used, kept, total, (w, t, fa), screw.lead, issues, False)
            memo.keep(key, result)
            filled += key in memo
    return filled


def _memo_key(
    screw: BallScrew, lubricant: Lubricant | str, model: str,
    points: tuple[npt.ArrayLike, npt.ArrayLike, npt.ArrayLike], options: tuple[Any, ...],
    parameters: dict[str, Any],
) -> tuple[Any, ...] | None:  # fmt: skip
    """The memo's key of a :func:`friction_torque` call; None when it cannot be hashed."""
    arrays = []
    for x in points:
        a = np.asarray(x)
        if a.dtype == object:
            return None
        arrays.append((a.dtype.str, a.shape, a.tobytes()))
    key = (screw, lubricant, model, options, tuple(sorted(parameters.items())), tuple(arrays))
    try:
        hash(key)
    except TypeError:
        return None
    return key


def _nbytes(value: Any, depth: int = 4) -> int:
    """The bytes of the arrays in ``value``, a result and what it holds (its contact state)."""
    if isinstance(value, np.ndarray):
        return int(value.nbytes) if value.base is None else 0  # a view holds no memory
    if depth == 0 or value is None or isinstance(value, (str, bytes, int, float)):
        return 0
    if isinstance(value, Mapping):
        return sum(_nbytes(v, depth - 1) for v in value.values())
    if isinstance(value, (list, tuple)):
        return sum(_nbytes(v, depth - 1) for v in value)
    if hasattr(value, "__dict__"):
        return sum(_nbytes(v, depth - 1) for v in vars(value).values())
    return 0


def _freeze(result: FrictionResult) -> None:
    """Make the arrays of a result kept by the memo read-only (shared by every caller)."""
    for a in (result.total, result.power_loss, result.efficiency, *result.components.values()):
        if isinstance(a, np.ndarray):
            a.flags.writeable = False


def friction_torque(
    screw: BallScrew,
    lubricant: Lubricant | str,
    *,
    speed: npt.ArrayLike,
    temperature: npt.ArrayLike,
    axial_load: npt.ArrayLike = 0.0,
    model: str = "complete",
    chunk_size: int | None = None,
    warn: bool = True,
    components: bool = True,
    **parameters: Any,
) -> FrictionResult:
    r"""Friction torque of a ball screw with a rotating screw and translating nut.

    Parameters
    ----------
    screw : BallScrew
        Geometry, preload, materials, roughness.
    lubricant : Lubricant or str
        The oil, or the name of a bundled one (:func:`ballscrew.lubricants.names`).
    speed : array_like
        Angular speed of the screw :math:`\omega` [rad/s] (either sign).
    temperature : array_like
        Lubricant temperature [°C].
    axial_load : array_like
        External axial load on the nut [N] (either sign).
    model : str
        A registered model, see :func:`models`: ``"complete"`` (default, the
        predictive model: every loss mechanism), ``"catalog"`` (the
        manufacturers' rule), or the study's ``"harris-simplified"``,
        ``"olaru"``, ``"viscoelastic"`` and ``"harris-full"``.
    chunk_size : int, optional
        Operating points evaluated at once; bounds the memory of large grids.
        Default: the model's own (``ModelSpec.chunk``).
    warn : bool
        False: record the validity issues in the result without warning
        (for callers that gather them, such as sweeps on worker threads,
        where changing the warning filters is not thread-safe).
    components : bool
        False: keep only the total (``components`` of the result is then
        empty), so that a call over many points holds one array of torques
        instead of one per mechanism (a 1e7-point grid then peaks near
        40 bytes a point; with components, near 110).
    **parameters
        The model's own parameters (see its docstring); an unknown name is
        an error listing the valid ones.

    Returns
    -------
    FrictionResult
        ``speed``, ``temperature`` and ``axial_load`` broadcast against each other.

    Warns
    -----
    BallScrewValidityWarning
        Once per quantity that leaves a validity range of the model or of a
        correlation it uses (:data:`ballscrew.validity.RANGES`); the result
        records the messages in ``warnings``.

    Examples
    --------
    >>> from ballscrew import lubricants, reference_screw
    >>> r = friction_torque(reference_screw(), lubricants.get("PAO ISO VG 68"),
    ...                     speed=[10.0, 100.0], temperature=40.0, model="catalog")
    >>> [round(float(t), 4) for t in r.total]
    [0.5642, 0.5642]
    """
    memo = _MEMO.get()
    key = None
    if memo is not None:
        key = _memo_key(screw, lubricant, model, (speed, temperature, axial_load),
                        (chunk_size, components), parameters)  # fmt: skip
        if key is not None and key in memo:
            memo.move_to_end(key)
            kept_result = memo[key]
            if warn:
                _warn(list(kept_result.warnings), stacklevel=3)
            return kept_result
    result = _friction_torque(screw, lubricant, model, (speed, temperature, axial_load),
                              chunk_size, warn, components, parameters)  # fmt: skip
    if memo is not None and key is not None:
        memo.keep(key, result)
    return result


def _friction_torque(
    screw: BallScrew, lubricant: Lubricant | str, model: str,
    points: tuple[npt.ArrayLike, npt.ArrayLike, npt.ArrayLike], chunk_size: int | None,
    warn: bool, components: bool, parameters: dict[str, Any],
) -> FrictionResult:  # fmt: skip
    """:func:`friction_torque` itself (the memo aside)."""
    lubricant, spec, chunk, (w0, t0, fa0), used = _prepared(
        screw, lubricant, model, parameters, chunk_size, points
    )
    kept, total, state = _evaluate(
        spec, screw, lubricant, (w0, t0, fa0), chunk, used, parameters, components
    )
    # The checks look at the extremes only: the unbroadcast inputs have the same ones.
    issues = validity.check(screw, lubricant, w0, t0, fa0, spec.name, used, spec.checks)
    if w0.shape == t0.shape == fa0.shape:
        w, t, fa = w0, t0, fa0  # one shape (a single point): no broadcast views needed
    else:
        w, t, fa = np.broadcast_arrays(w0, t0, fa0)
    # stacklevel 5: past _warn, _result, this function and friction_torque, its caller.
    return _result(spec, used, kept, total, (w, t, fa), screw.lead, issues, warn, state, 5)


def friction_torques(
    screws: Sequence[BallScrew],
    lubricant: Lubricant | str,
    *,
    speed: npt.ArrayLike,
    temperature: npt.ArrayLike,
    axial_load: npt.ArrayLike = 0.0,
    model: str = "complete",
    paired: bool = False,
    chunk_size: int | None = None,
    warn: bool = True,
    components: bool = True,
    **parameters: Any,
) -> FrictionResult:
    r"""Friction torque of many screws in one call, on one lubricant and one model.

    What :func:`friction_torque` gives for one screw, for a whole table of
    them (a design space, a Monte Carlo sample over the geometry, a catalogue
    series): the inputs are checked once, each screw is evaluated on the
    operating points, and the results are stacked along a first axis, one
    entry per screw. A model that takes many screws at once (``ModelSpec.batches``:
    the complete model with its ``"ratio"`` ball train) evaluates the screws of one
    nut arrangement together, their geometry as broadcast arrays in every layer
    (:class:`~ballscrew.geometry.ScrewArray`), equal to one call per screw within
    1e-12 relative; the other models take one screw at a time.

    Parameters
    ----------
    screws : sequence of BallScrew
        The screws, at least one; their order is the first axis of every
        result.
    lubricant, speed, temperature, axial_load, model, chunk_size, warn, components, **parameters
        As for :func:`friction_torque`; a chunk bounds the points evaluated at once,
        screws times points (whole screws; a screw with more points than a chunk is
        evaluated alone, in chunks of its points).
    paired : bool
        False (default): every screw at every operating point; the points
        broadcast against each other to a shape P and the results have shape
        ``(len(screws), *P)``. True: each screw at its own points; the first
        axis of the points is the screw axis (length ``len(screws)``, or 1 for
        a value shared by all), and the results have the points' broadcast
        shape, with ``len(screws)`` on that axis (also when every value is shared).

    Returns
    -------
    FrictionResult
        Arrays with the screw axis first; ``warnings`` holds each quantity's
        worst validity issue over all screws; ``state`` is None.

    Raises
    ------
    BallScrewInputError
        For a screw that is not a :class:`~ballscrew.BallScrew` or a point a
        screw cannot be solved at, naming the screw by its index
        (``screws[3]``).

    Examples
    --------
    Three leads of one screw at two speeds (the helix's slip grows with the
    lead angle):

    >>> from ballscrew import reference_screw
    >>> base = reference_screw()
    >>> screws = [base.replace(lead=lead) for lead in (0.008, 0.010, 0.020)]
    >>> r = friction_torques(screws, "mineral ISO VG 68", speed=[10.0, 100.0],
    ...                      temperature=40.0, warn=False)
    >>> r.total.shape
    (3, 2)
    >>> bool(np.all(np.diff(r.components["helix_slip"], axis=0) > 0.0))
    True
    """
    screws = list(screws) if not isinstance(screws, BallScrew) else [screws]
    if not screws:
        raise BallScrewInputError("screws", screws, "a sequence of at least one BallScrew")
    for i, screw in enumerate(screws):
        if not isinstance(screw, BallScrew):
            raise BallScrewInputError(f"screws[{i}]", screw, "a ballscrew.BallScrew")
    lubricant, spec, chunk, (w0, t0, fa0), used = _prepared(
        screws[0], lubricant, model, parameters, chunk_size, (speed, temperature, axial_load)
    )
    n = len(screws)
    per_screw = _paired_points(n, (w0, t0, fa0)) if paired else None
    points_shape = np.broadcast_shapes(w0.shape, t0.shape, fa0.shape)
    # Paired, the points' first axis is the screws' (or absent, or 1: shared by all).
    shape = (n, *points_shape[1:]) if paired else (n, *points_shape)
    if math.prod(shape) >= JIT_LOAD_POINTS:
        load_kernel()  # many points in all, though few a screw: the helix's compiled loop
    total = np.empty(shape)
    kept: dict[str, FloatArray] = {}
    worst: dict[tuple[str, str], ValidityIssue] = {}

    def store(rows: Any, out: dict[str, FloatArray], issues: list[ValidityIssue]) -> None:
        for key, value in out.items():
            if key not in kept:
                kept[key] = np.zeros(shape)  # a component another screw lacks is 0 there
            kept[key][rows] = value
        for issue in issues:
            known = worst.get((issue.quantity, issue.model))
            if known is None or issue.excess > known.excess:
                worst[(issue.quantity, issue.model)] = issue

    def one(i: int) -> None:
        screw = screws[i]
        points = (w0, t0, fa0) if per_screw is None else per_screw(i)
        try:
            out, total[i], _ = _evaluate(
                spec, screw, lubricant, points, chunk, used, parameters, components
            )
        except BallScrewInputError as exc:
            if exc.field != "operating point":  # a model parameter: not this screw's doing
                raise
            raise BallScrewInputError(f"screws[{i}]: {exc.field}", exc.value, exc.allowed) from None
        store(i, out, validity.check(screw, lubricant, *points, spec.name, used, spec.checks))

    per_points = math.prod(shape[1:])
    if spec.batches is None or not spec.batches(used) or per_points > chunk:
        for i in range(n):
            one(i)
    else:
        # Every layer takes the geometry as arrays: the screws of one nut arrangement go
        # through the model together, as many at a time as the chunk holds.
        rows_points = _rows_points(n, (w0, t0, fa0), len(shape), paired)
        step = max(1, chunk // max(per_points, 1))
        for kind in dict.fromkeys((s.nut, s.ball_separation) for s in screws):
            group = [i for i, s in enumerate(screws) if (s.nut, s.ball_separation) == kind]
            for start in range(0, len(group), step):
                part = group[start : start + step]
                done = _evaluate_rows(
                    spec, [screws[i] for i in part], lubricant, rows_points(part), used,
                    parameters, components, len(shape),
                )  # fmt: skip
                if done is None:  # a point a model cannot solve: found and named screw by screw
                    for i in part:
                        one(i)
                    continue
                out, part_total, issues = done
                total[part] = part_total
                store(part, out, issues)
    leads = np.array([s.lead for s in screws]).reshape((n,) + (1,) * (len(shape) - 1))
    w, t, fa = (np.broadcast_to(x, shape) for x in (w0, t0, fa0))
    return _result(spec, used, kept, total, (w, t, fa), leads, list(worst.values()), warn)


def _rows_points(
    n: int, points: tuple[FloatArray, FloatArray, FloatArray], ndim: int, paired: bool
) -> Callable[[list[int]], tuple[FloatArray, FloatArray, FloatArray]]:
    """The points of the screws ``part`` with a first axis for the screws (or 1: shared).

    Not paired, every screw has every point: a leading axis of 1 is put on. Paired, the
    points' first axis is the screws' (or 1): the rows of ``part`` are taken.
    """
    if not paired:
        lifted = [x.reshape((1,) * (ndim - x.ndim) + x.shape) for x in points]
        return lambda part: (lifted[0], lifted[1], lifted[2])
    aligned = [x.reshape((1,) * (ndim - x.ndim) + x.shape) for x in points]

    def rows(part: list[int]) -> tuple[FloatArray, FloatArray, FloatArray]:
        w, t, fa = (x[part] if x.shape[0] > 1 else x for x in aligned)
        return w, t, fa

    return rows


def _evaluate_rows(
    spec: ModelSpec,
    screws: list[BallScrew],
    lubricant: Lubricant,
    points: tuple[FloatArray, FloatArray, FloatArray],
    used: dict[str, Any],
    parameters: dict[str, Any],
    keep: bool,
    ndim: int,
) -> tuple[dict[str, FloatArray], FloatArray, list[ValidityIssue]] | None:
    """Components (if ``keep``), totals and validity issues of many screws in one evaluation.

    The screws (one nut arrangement) become a :class:`~ballscrew.geometry.ScrewArray`
    of ``ndim`` axes, the first theirs, against the points of :func:`_rows_points`;
    None where a point is not solved, so that the caller names it screw by screw.
    """
    arr = ScrewArray.of(screws, ndim)
    w, t, fa = points
    try:
        state = None
        if spec.uses_state:
            state = operating_state_unchecked(
                arr, lubricant, w, t, fa, hertz_method=used["hertz_method"],
                asperity_b=used["asperity_b"], asperity_c=used["asperity_c"],
            )  # fmt: skip
        out = spec(arr, lubricant, w, t, fa, state, **parameters)
        _check_solved(spec.name, out, w, t, fa)
    except BallScrewInputError as exc:
        if exc.field != "operating point":
            raise
        return None
    except _UNSOLVED:
        return None
    shape = (len(screws), *np.broadcast_shapes(w.shape, t.shape, fa.shape)[1:])
    total = np.zeros(shape)
    for value in out.values():
        total += value
    kept = {k: np.array(v, dtype=float) for k, v in out.items()} if keep else {}
    return kept, total, validity.check(arr, lubricant, w, t, fa, spec.name, used, spec.checks)


def _prepared(
    screw: BallScrew,
    lubricant: Lubricant | str,
    model: str,
    parameters: dict[str, Any],
    chunk_size: int | None,
    points: tuple[npt.ArrayLike, npt.ArrayLike, npt.ArrayLike],
) -> tuple[Lubricant, ModelSpec, int, tuple[FloatArray, FloatArray, FloatArray], dict[str, Any]]:
    """The checked lubricant, model, chunk size, operating points (unbroadcast) and parameters."""
    oil, spec = _checked(screw, lubricant, model, parameters)
    chunk = spec.chunk if chunk_size is None else chunk_size
    if isinstance(chunk, bool) or not isinstance(chunk, int) or chunk < 1:
        raise BallScrewInputError("chunk_size", chunk_size, "a whole number >= 1")
    w0, t0, fa0 = operating_points(*points, broadcast=False)
    oil.check_temperature("temperature", t0)
    used = dict(spec.parameters)
    used.update(parameters)
    return oil, spec, chunk, (w0, t0, fa0), used


def _result(
    spec: ModelSpec,
    used: dict[str, Any],
    kept: dict[str, FloatArray],
    total: FloatArray,
    points: tuple[FloatArray, FloatArray, FloatArray],
    lead: float | FloatArray,
    issues: list[ValidityIssue],
    warn: bool,
    state: OperatingState | None = None,
    stacklevel: int = 4,
) -> FrictionResult:
    """The result of the torques ``total`` at the broadcast ``points``, warned of ``issues``.

    ``stacklevel`` is the warnings' (:func:`_warn`): 4 names the caller of a public function
    that calls this one directly, one more per helper in between.
    """
    w, t, fa = points
    efficiency, power_loss = _efficiency_and_power(total, w, fa, lead)
    if warn:
        _warn(issues, stacklevel)
    return FrictionResult(
        model=spec.name,
        total=total,
        components=kept,
        power_loss=power_loss,
        efficiency=efficiency,
        speed=w,
        temperature=t,
        axial_load=fa,
        parameters=used,
        warnings=tuple(issues),
        state=state,
    )


def _paired_points(
    n: int, points: tuple[FloatArray, FloatArray, FloatArray]
) -> Callable[[int], tuple[FloatArray, FloatArray, FloatArray]]:
    """Screw ``i``'s own points: entry ``i`` (or the shared entry 0) of each input's first axis."""
    ndim = max(1, *(x.ndim for x in points))
    aligned = [x.reshape((1,) * (ndim - x.ndim) + x.shape) for x in points]
    for name, x in zip(("speed", "temperature", "axial_load"), aligned, strict=True):
        if x.shape[0] not in (1, n):
            raise BallScrewInputError(
                name,
                x,
                f"with paired=True, a first axis of length {n} (one entry per screw) or 1 "
                "(shared by all)",
            )

    def own(i: int) -> tuple[FloatArray, FloatArray, FloatArray]:
        w, t, fa = (x[i if x.shape[0] > 1 else 0] for x in aligned)
        return w, t, fa

    return own


def _efficiency_and_power(
    total: FloatArray, w: FloatArray, fa: FloatArray, lead: float | FloatArray
) -> tuple[FloatArray, FloatArray]:
    """Forward efficiency and power loss of torques ``total`` at speeds ``w`` and loads ``fa``."""
    # useful / (useful + T): 0 where there is no load (and no division by 0 when T = 0
    # too), computed in place: a large call holds no more full-size temporaries than needed.
    if not total.shape and not np.shape(lead):  # one point: the same operations on numbers
        useful = abs(float(fa)) * (float(lead) / (2.0 * math.pi))
        ratio = useful / max(useful + float(total), _TINY)
        return np.array(ratio), np.array(abs(float(w)) * float(total))
    efficiency = np.abs(fa, out=np.empty(total.shape))
    efficiency *= np.asarray(lead) / (2.0 * math.pi)
    denominator = np.add(efficiency, total, out=np.empty(total.shape))
    np.maximum(denominator, np.finfo(float).tiny, out=denominator)
    np.divide(efficiency, denominator, out=efficiency)
    del denominator
    power_loss = np.abs(w, out=np.empty(total.shape))
    power_loss *= total
    return efficiency, power_loss


_TINY = float(np.finfo(float).tiny)
"""The smallest normal double: the floor of the efficiency's denominator."""


def _checked(
    screw: BallScrew, lubricant: Lubricant | str, model: str, parameters: dict[str, Any]
) -> tuple[Lubricant, ModelSpec]:
    """The lubricant (a bundled one by name) and the model, after checking both and the screw."""
    if isinstance(lubricant, str):
        from . import lubricants

        lubricant = lubricants.get(lubricant)
    if not isinstance(lubricant, Lubricant):
        raise BallScrewInputError(
            "lubricant",
            lubricant,
            "a Lubricant or the name of a bundled one (ballscrew.lubricants.names())",
        )
    if not isinstance(screw, BallScrew):
        raise BallScrewInputError("screw", screw, "a ballscrew.BallScrew")
    spec = get_model(model)
    spec.check_parameters(parameters)
    return lubricant, spec


def _evaluate(
    spec: ModelSpec,
    screw: BallScrew,
    lubricant: Lubricant,
    points: tuple[FloatArray, FloatArray, FloatArray],
    chunk: int,
    used: dict[str, Any],
    parameters: dict[str, Any],
    keep: bool = True,
) -> tuple[dict[str, FloatArray], FloatArray, OperatingState | None]:
    """The model's components (if ``keep``) and total over the broadcast points.

    The points are evaluated in chunks of at most ``chunk``, each chunk's
    results checked (:func:`_check_solved`) and written into arrays allocated
    once; the inputs are read chunk by chunk from their broadcast views, never
    expanded whole. The contact state is built once per chunk for the models
    that use one and returned when there is a single chunk.
    """

    def state_of(sw: FloatArray, st: FloatArray, sf: FloatArray) -> OperatingState | None:
        if not spec.uses_state:
            return None
        # The points were checked by _prepared (operating_points): composed without again.
        return operating_state_unchecked(
            screw, lubricant, sw, st, sf, hertz_method=used["hertz_method"],
            asperity_b=used["asperity_b"], asperity_c=used["asperity_c"],
        )  # fmt: skip

    def run(sw: FloatArray, st: FloatArray, sf: FloatArray, state: OperatingState | None) -> Any:
        try:
            out = spec(screw, lubricant, sw, st, sf, state, **parameters)
        except _UNSOLVED as exc:
            raise _unsolved(spec.name, exc, sw, st, sf) from exc
        _check_solved(spec.name, out, sw, st, sf)
        return out

    w0, t0, fa0 = points
    shape = broadcast_shape(w0.shape, t0.shape, fa0.shape)
    n = math.prod(shape)
    if n <= chunk:
        # The unexpanded inputs: a grid given as an outer product is only
        # expanded where a quantity depends on all three.
        state = state_of(w0, t0, fa0)
        out = run(w0, t0, fa0, state)
        if shape:
            total = np.zeros(shape)
            for value in out.values():
                total += value
        else:  # one point: the same additions in the same order, on numbers
            one = 0.0
            for value in out.values():
                one += float(value)
            total = np.array(one)
        # The model's components come broadcast to the points' shape (ModelSpec.__call__):
        # kept as arrays of their own, only when asked for.
        kept = {k: np.array(v, dtype=float) for k, v in out.items()} if keep else {}
        return kept, total, state
    views = np.broadcast_arrays(w0, t0, fa0)
    flat_total = np.zeros(n)
    kept = {}
    for start in range(0, n, chunk):
        stop = min(start + chunk, n)
        sw, st, sf = (_flat_slice(x, start, stop) for x in views)
        out = run(sw, st, sf, state_of(sw, st, sf))
        for key, value in out.items():
            piece = np.broadcast_to(value, (stop - start,))
            flat_total[start:stop] += piece
            if keep:
                kept.setdefault(key, np.empty(n))[start:stop] = piece
    return {k: v.reshape(shape) for k, v in kept.items()}, flat_total.reshape(shape), None


def _flat_slice(x: FloatArray, start: int, stop: int) -> FloatArray:
    """Elements ``start:stop`` of ``x`` in C order, without expanding a broadcast view whole."""
    if x.flags.c_contiguous:
        contiguous: FloatArray = x.reshape(-1)[start:stop]
        return contiguous
    picked: FloatArray = x[np.unravel_index(np.arange(start, stop), x.shape)]
    return picked


def _point(w: Any, t: Any, fa: Any) -> str:
    """An operating point (or the span of several) as the user would name it."""
    w, t, fa = (np.asarray(x, dtype=float) for x in (w, t, fa))

    def span(x: FloatArray, unit: str) -> str:
        lo, hi = float(np.min(x)), float(np.max(x))
        return f"{lo:g} {unit}" if lo == hi else f"{lo:g} to {hi:g} {unit}"

    rpm = rad_s_to_rpm(w)
    return f"speed {span(rpm, 'rpm')}, temperature {span(t, 'degC')}, axial_load {span(fa, 'N')}"


def _unsolved(model: str, exc: BaseException, w: Any, t: Any, fa: Any) -> BallScrewInputError:
    """The input error for points whose numerics failed in the model (``exc``)."""
    return BallScrewInputError(
        "operating point",
        _point(w, t, fa),
        f"points model {model!r} can solve: its numerics failed there "
        f"({type(exc).__name__}: {exc})",
    )


def _check_solved(
    model: str,
    components: Mapping[str, FloatArray],
    w: FloatArray,
    t: FloatArray,
    fa: FloatArray,
) -> None:
    """Refuse the points where a component is not a finite torque >= 0, naming the first.

    Friction opposes the motion: a negative or non-finite contribution means the
    model was taken where its equations no longer hold (the viscoelastic model
    far past any real speed, say), and a plausible-looking total must not be
    given out there.
    """
    for name, value in components.items():
        if value.ndim == 0 and 0.0 <= float(value) < math.inf:  # one point: no arrays
            continue
        ok = np.isfinite(value) & (value >= 0.0)
        if ok.all():
            continue
        shape = np.broadcast_shapes(ok.shape, np.shape(w), np.shape(t), np.shape(fa))
        ok = np.broadcast_to(ok, shape)
        value, w, t, fa = (np.broadcast_to(x, shape) for x in (value, w, t, fa))
        first = np.unravel_index(int(np.argmin(ok)), ok.shape) if ok.ndim else ()
        bad = float(np.asarray(value)[first])
        count = int(ok.size - np.count_nonzero(ok))
        raise BallScrewInputError(
            "operating point",
            _point(w[first], t[first], fa[first]),
            f"a point model {model!r} can solve: its {name!r} torque there is {bad:g} N*m, "
            f"not a finite torque >= 0 ({count} of {ok.size} points), so the model is "
            "taken past where its equations hold",
        )


def _warn(issues: list[ValidityIssue], stacklevel: int = 4) -> None:
    """Warn of each validity issue; a routine one once per quantity and model in a session.

    ``stacklevel`` as :func:`warnings.warn` counts it from here: 3 names the caller of the
    public function that called this one; 4 (the default) the caller of a public function
    whose helper did.
    """
    for issue in issues:
        if issue.routine:
            # Left by every ordinary ball screw: told once per quantity and model
            # in a session (as a note with the reason), recorded in every result.
            told = (issue.quantity, issue.model)
            if told in _NOTED:
                continue
            _NOTED.add(told)
        warnings.warn(BallScrewValidityWarning(issue), stacklevel=stacklevel)


@dataclass(frozen=True)
class TorqueTable:
    """Each model's result over every combination of the operating points (:func:`torque_table`).

    ``findings`` are the plausibility warnings of the loads against the screw's
    ratings (:func:`ballscrew.design.ratings.plausibility`); its errors were raised.
    """

    results: dict[str, FrictionResult]
    findings: tuple[Finding, ...] = ()

    def as_dict(self) -> dict[str, Any]:
        """Each model's points and results as lists (SI, temperatures in °C), and the findings."""

        def listed(x: npt.ArrayLike) -> list[float]:
            values: list[float] = np.ravel(x).astype(float).tolist()
            return values

        return {
            "models": {
                name: {
                    "speed_rad_s": listed(r.speed),
                    "temperature_C": listed(r.temperature),
                    "axial_load_N": listed(r.axial_load),
                    "torque_Nm": listed(r.total),
                    "power_loss_W": listed(r.power_loss),
                    "efficiency": listed(r.efficiency),
                    "components_Nm": {k: listed(v) for k, v in r.components.items()},
                    "warnings": [str(issue) for issue in r.warnings],
                }
                for name, r in self.results.items()
            },
            "plausibility": [str(f) for f in self.findings],
        }


def operating_grid(
    speed: npt.ArrayLike, temperature: npt.ArrayLike, axial_load: npt.ArrayLike
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Every combination of the speeds, temperatures and loads, as three flat arrays.

    The speed varies slowest, then the temperature, then the load: the row
    order of the tables and files of ``ballscrew torque``.

    Examples
    --------
    >>> [a.tolist() for a in operating_grid([1.0, 2.0], 40.0, [0.0, 5.0])]
    [[1.0, 1.0, 2.0, 2.0], [40.0, 40.0, 40.0, 40.0], [0.0, 5.0, 0.0, 5.0]]
    """
    w, t, f = (np.ravel(a) for a in np.meshgrid(speed, temperature, axial_load, indexing="ij"))
    return w, t, f


def torque_table(
    screw: BallScrew,
    lubricant: Lubricant | str,
    model_names: Sequence[str],
    speed: npt.ArrayLike,
    temperature: npt.ArrayLike,
    axial_load: npt.ArrayLike,
    *,
    parameters: Mapping[str, Mapping[str, Any]] | None = None,
    ratings: Ratings | None = None,
    load_field: str = "axial_load",
    wiper_drag: float = 0.0,
    wiper_models: Collection[str] = (),
    on_model: Callable[[str], None] | None = None,
) -> TorqueTable:
    """Each model of ``model_names`` over every combination of the operating points.

    What ``ballscrew torque`` and the web page compute. The names are checked
    first; with ``ratings`` the loads are then checked against the screw's
    ratings and the contact pressure limit
    (:func:`ballscrew.design.ratings.plausibility`, naming ``load_field``): an
    error is raised before anything is computed, the warnings are kept in the
    table. Each model runs once over the grid (:func:`operating_grid`) with its
    ``parameters[name]``; its validity issues are kept in its result, not
    warned of. A ``wiper_drag`` [N·m] reaches the models through their
    parameters; the models not in ``wiper_models`` (those without a wiper or
    seal term) get a note in their result that they leave it out.
    ``on_model(name)`` is called after each model.
    """
    for name in model_names:
        get_model(name)
    found: tuple[Finding, ...] = ()
    if ratings is not None:
        found = tuple(raise_errors(plausibility(screw, ratings, axial_load, load_field=load_field)))
    grid_w, grid_t, grid_f = operating_grid(speed, temperature, axial_load)
    results: dict[str, FrictionResult] = {}
    for name in model_names:
        params = dict((parameters or {}).get(name, {}))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", BallScrewValidityWarning)
            results[name] = friction_torque(
                screw, lubricant, speed=grid_w, temperature=grid_t, axial_load=grid_f,
                model=name, **params,
            )  # fmt: skip
        if wiper_drag and name not in wiper_models:
            results[name] = _wiper_left_out(results[name], wiper_drag)
        if on_model is not None:
            on_model(name)
    return TorqueTable(results, found)


def _wiper_left_out(result: FrictionResult, drag: float) -> FrictionResult:
    """The result with a note that its model has no term for the case's wiper drag."""
    note = validity.statement(
        "wiper drag [N*m]",
        "left out, as the model has no wiper or seal term (the complete model adds it as its "
        "'seals' component)",
        "[screw] wiper_drag or --wiper-drag",
        value=drag,
        routine="a case's wiper drag reaches only the models with a seal term",
    )
    return replace(result, warnings=(*result.warnings, replace(note, model=result.model)))
