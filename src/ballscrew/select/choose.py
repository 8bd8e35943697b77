"""``ballscrew select``: every candidate through the axis check, the Pareto front, one pick.

(A long module, about 1000 lines: the evaluation of a candidate, many at a time, the
front, the recommendation's rule and the sentences that explain each pick and each
refusal stay together; the candidate pool is in :mod:`.pool`.)

Each candidate (:mod:`.pool`) is its own case: the user's axis, motor,
check limits and duty with the screw replaced. It runs through
:func:`~ballscrew.axis.duty.run_energy` and :func:`~ballscrew.axis.check.run_check`
as ``ballscrew check`` runs it. A candidate is feasible when it passes with
the confidence asked (:data:`~ballscrew.axis.uncertainty.CONFIDENCE`, 95 %, by
default): no row of its check is NOT OK at the nominal values, and the
probability that one row or more is NOT OK under the case's tolerances and the
model's error (the check's Monte Carlo, :attr:`~ballscrew.axis.check.AxisCheck.p_not_ok`)
is at most 1 - confidence (5 %), the check's guard-banded "OK (95 %)". A rejected
one names its binding constraint, the row with the largest utilisation (or the
input error that stopped it, e.g. a load above its rating), and the rows that
fail, value against limit.

Many candidates cost less than many checks (:func:`_prepared`): the heat
balances of the candidates that share an oil are solved together
(:func:`~ballscrew.axis.thermal.steady_temperatures`, equal to each one's own
to rounding) and their temperature histories integrated together
(:func:`~ballscrew.axis.thermal.temperature_histories`, within the
integrator's tolerance of each one's own: 1e-5 relative on the rise); the
run leaves out what the check does not read (``for_check``), and the check's
Monte Carlo, which only adds each row's P(NOT OK), runs only for a candidate
no row fails at its nominal value (the verdicts are the nominal values'). The
verdicts and binding rows are therefore those of the lone checks; the front
members and the recommended candidate are evaluated alone again, so their
figures are exactly those ``ballscrew check --case CANDIDATE.toml`` prints,
and a candidate within :data:`NEAR` of a utilisation bound too.

The front is the non-dominated set of the feasible candidates over the
objectives picked (:data:`OBJECTIVES`), sorted by pymoo's non-dominated
sorting. The recommendation is a member of the front: the best on the first
objective picked among its members whose every utilisation is at most 0.8;
when there is none, the member with the least largest utilisation, the members
within :data:`TIE_BAND` of it counting as tied and the tie going to the best on
the first objective. (A candidate off the front is beaten on every objective
picked by another, so it is never recommended.) When no candidate passes with
the confidence asked but some pass at their nominal values, the selection is
**undecided**: the front is taken over those, the one of them least likely to
fail is named with its probability (on the front or not), and
:attr:`SelectResult.undecided` is set.
"""

from __future__ import annotations

import contextlib
import dataclasses
import difflib
import math
import time
import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from .. import lubricants
from ..axis.check import CREEP_SPEED, AxisCheck, Criterion, run_check
from ..axis.duty import HISTORY_POINTS, motion_plausibility, run_energy
from ..axis.energy import distinct_pairs, screw_motion
from ..axis.motion import Profile
from ..axis.setup import axis_setup
from ..axis.thermal import SteadyState, steady_temperatures, temperature_histories
from ..axis.uncertainty import CONFIDENCE
from ..chain import MEMO_SIZE, fill_friction_memo, friction_memo
from ..errors import BallScrewInputError, BallScrewPlausibilityWarning, FloatArray
from ..io.case import Case, parse_case
from ..io.motors import MotorRow
from ..io.numbers import text as num
from .pool import DEFAULT_PRELOADS, Candidate, candidates, scatter_text

__all__ = [
    "FIGURES",
    "OBJECTIVES",
    "RECOMMEND_BELOW",
    "TIE_BAND",
    "Evaluated",
    "NoFeasibleCandidateError",
    "NoneFeasible",
    "Progress",
    "SelectResult",
    "evaluate",
    "non_dominated",
    "parse_confidence",
    "run_select",
]

Progress = Callable[[str, int, int], None]
"""``progress(stage, done, total)``: ``"parse"`` (the candidates' cases read), ``"heat"`` (their
heat balances solved, counted in balances), ``"check"`` (the candidates evaluated) and
``"alone"`` (the front, the pick and the candidates near a bound evaluated again alone)."""

OBJECTIVES: dict[str, tuple[str, str, int]] = {
    "energy": ("energy_J", "friction energy per cycle [J]", 1),
    "life": ("L10_h", "L10 life [h]", -1),
    "stiffness": ("stiffness_N_per_um", "least axis stiffness [N/um]", -1),
    "lost_motion": ("lost_motion_um", "largest lost motion at reversal [um]", 1),
    "thermal_error": ("thermal_error_um", "thermal lead error per 300 mm [um]", 1),
    "motor_margin": ("motor_margin", "motor margin, 1 - largest motor utilisation", -1),
    "price": ("price", "price of the motor and the screw (their tables' price columns)", 1),
}
"""Each objective: its figure, label and sense (1 = less is better, -1 = more is better)."""

FIGURES: dict[str, str] = {
    "energy_J": "J",
    "friction_share": "-",
    "temperature_rise_K": "K",
    "thermal_error_um": "um",
    "L10_h": "h",
    "stiffness_N_per_um": "N/um",
    "lost_motion_um": "um",
    "motor_margin": "-",
    "max_utilisation": "-",
    "p_not_ok": "-",
    "price": "currency of the table",
    "seconds": "s",
}
"""The figures kept per candidate, with their units (``p_not_ok``: the probability that one
row or more is NOT OK, :attr:`~ballscrew.axis.check.AxisCheck.p_not_ok`; NaN for a candidate a
row fails at its nominal value, whose Monte Carlo is not drawn)."""

RECOMMEND_BELOW = 0.8
"""The largest utilisation of a recommended candidate, if any candidate stays below it."""

TIE_BAND = 0.01
"""Largest utilisations within this of the least (1 % of utilisation, absolute) are a tie,
broken by the first objective: a hundredth of a limit is well inside what the inputs'
tolerances move a utilisation by."""

CLOSEST = 3
"""How many of the candidates closest to passing a failed selection names."""


def parse_confidence(text: str | float, field: str = "--confidence") -> float:
    """A confidence as typed, ``"95 %"``, ``"95%"`` or ``0.95``, as a share from 50 % to 99.9 %.

    >>> parse_confidence("95 %"), parse_confidence("0.9")
    (0.95, 0.9)
    """
    raw = str(text).strip()
    try:
        value = float(raw.removesuffix("%").strip()) / (100.0 if raw.endswith("%") else 1.0)
    except ValueError:
        value = math.nan
    # A percentage's division leaves a last bit (99.9 / 100 = 0.9990000000000001): rounded
    # to 9 digits, far finer than anyone types one, "99.9 %" is the range's end.
    value = round(value, 9)
    # 1 - confidence is the P(NOT OK) allowed; the Monte Carlo's 4000 draws resolve 0.1 %.
    if not 0.5 <= value <= 0.999:
        raise BallScrewInputError(field, text, "a confidence from 50 % to 99.9 %, e.g. '95 %'")
    return value


_MOTOR_ROWS = ("inertia_ratio", "peak_torque", "rms_torque", "motor_speed")
"""The keys of the check's motor rows (the motor margin is the room the worst leaves)."""


@dataclass(frozen=True)
class Evaluated:
    """One candidate's figures (:data:`FIGURES`, NaN where not computed) and verdict."""

    candidate: Candidate
    figures: dict[str, float]
    feasible: bool
    """Passes with the confidence asked: no row NOT OK and P(NOT OK) at most 1 - confidence."""
    binding: str
    """The row with the largest utilisation, e.g. ``"fatigue life L10 (273 %)"``."""
    nominal: bool = False
    """No row is NOT OK at the nominal values (the check's own verdict)."""
    failing: tuple[str, ...] = ()
    """The rows NOT OK at the nominal values, each its value against its limit, worst first."""
    doubtful: str = ""
    """The row most likely NOT OK and its probability, e.g. ``"thermal lead error ... (43.1%)"``
    (empty where the Monte Carlo was not drawn)."""

    @property
    def name(self) -> str:
        """The candidate's name."""
        return self.candidate.name

    def as_dict(self) -> dict[str, Any]:
        """The candidate, its figures and verdict as plain values."""
        c = self.candidate
        return {
            "name": c.name,
            "designation": c.row.name,
            "nut": c.nut,
            "preload_class": c.preload_class,
            "preload_share": c.preload_share,
            "oil": c.oil,
            "estimated": c.estimated,
            "motor": c.motor.name if c.motor is not None else None,
            "feasible": self.feasible,
            "passes_nominal": self.nominal,
            "binding": self.binding,
            "failing": list(self.failing),
            "most_doubtful_row": self.doubtful or None,
            **{k: (None if math.isnan(v) else v) for k, v in self.figures.items()},
        }


@dataclass(frozen=True)
class SelectResult:
    """A selection: every candidate evaluated, the front, the recommendation and why."""

    title: str
    objectives: tuple[str, ...]
    evaluated: tuple[Evaluated, ...]
    front: tuple[int, ...]
    """Indices into :attr:`evaluated` of the non-dominated feasible candidates."""
    recommended: int
    reason: str
    model: str
    inputs: dict[str, Any] = field(default_factory=dict)
    confidence: float = CONFIDENCE
    """The confidence a feasible candidate passes with."""
    undecided: bool = False
    """No candidate passes with :attr:`confidence`: the front is that of the candidates that
    pass at their nominal values, and :attr:`recommended` the one of them least likely to fail
    (on the front or not)."""

    @property
    def feasible(self) -> list[Evaluated]:
        """The candidates that pass with the confidence asked."""
        return [e for e in self.evaluated if e.feasible]

    @property
    def rejected(self) -> list[Evaluated]:
        """The candidates that do not pass with the confidence asked, or an input error."""
        return [e for e in self.evaluated if not e.feasible]

    def as_dict(self) -> dict[str, Any]:
        """The selection as plain values (``ballscrew select --json``)."""
        return {
            "title": self.title,
            "model": self.model,
            "objectives": list(self.objectives),
            "confidence": self.confidence,
            "undecided": self.undecided,
            "recommended": self.evaluated[self.recommended].name,
            "reason": self.reason,
            "front": [self.evaluated[i].name for i in self.front],
            "candidates": [e.as_dict() for e in self.evaluated],
            "units": dict(FIGURES),
            "inputs": self.inputs,
        }

    def dataset(self) -> Any:
        """Every candidate's figures as an xarray Dataset over ``candidate`` (needs xarray)."""
        import xarray as xr

        names = [e.name for e in self.evaluated]
        data: dict[str, Any] = {
            k: ("candidate", np.array([e.figures[k] for e in self.evaluated]), {"units": u})
            for k, u in FIGURES.items()
        }
        data["feasible"] = ("candidate", np.array([e.feasible for e in self.evaluated]))
        data["on_front"] = ("candidate", np.isin(np.arange(len(names)), self.front))
        data["binding"] = ("candidate", np.array([e.binding for e in self.evaluated]))
        data["estimated"] = ("candidate", np.array([e.candidate.estimated for e in self.evaluated]))
        data["motor"] = ("candidate", np.array([e.candidate.motor.name if e.candidate.motor
                                                else "" for e in self.evaluated]))  # fmt: skip
        return xr.Dataset(
            data,
            coords={"candidate": names},
            attrs={"objectives": ", ".join(self.objectives), "recommended": names[
                self.recommended], "reason": self.reason},
        )  # fmt: skip


@dataclass(frozen=True)
class NoneFeasible:
    """A selection no candidate passes: every candidate evaluated and what fails each.

    Carried by :class:`NoFeasibleCandidateError`, so that a report asked for can still
    say why nothing passed (``ballscrew select --out``).
    """

    title: str
    objectives: tuple[str, ...]
    evaluated: tuple[Evaluated, ...]
    model: str
    reason: str
    """The error's text: the closest candidates and what to change."""
    inputs: dict[str, Any] = field(default_factory=dict)
    front: tuple[int, ...] = ()
    """Empty: no candidate is feasible (the same name as :attr:`SelectResult.front`)."""

    @property
    def rejected(self) -> list[Evaluated]:
        """Every candidate, most nearly passing first (least largest utilisation)."""
        return sorted(self.evaluated, key=lambda e: e.figures["max_utilisation"]
                      if not math.isnan(e.figures["max_utilisation"]) else math.inf)  # fmt: skip

    def as_dict(self) -> dict[str, Any]:
        """The failed selection as plain values (the report's ``data/select.json``)."""
        return {
            "title": self.title,
            "model": self.model,
            "objectives": list(self.objectives),
            "undecided": False,
            "recommended": None,
            "reason": self.reason,
            "front": [],
            "candidates": [e.as_dict() for e in self.evaluated],
            "units": dict(FIGURES),
            "inputs": self.inputs,
        }


class NoFeasibleCandidateError(BallScrewInputError):
    """No candidate passes the duty; :attr:`result` holds every candidate and its failure."""

    def __init__(self, field: str, value: Any, allowed: str, result: NoneFeasible) -> None:
        super().__init__(field, value, allowed)
        self.result = result
        if result.reason:  # the sentence that says what fails, not "field = value is not ..."
            self.args = (result.reason,)

    def __reduce__(self) -> tuple[Any, ...]:
        """Pickled with its parts and the result."""
        return (type(self), (self.field, self.value, self.allowed, self.result))


def _figures(check: AxisCheck, run: Any, model: str, seconds: float) -> dict[str, float]:
    """The figures of one candidate from its check and energy run."""
    energy = run.results[model]
    friction = float(energy.cycle.friction_energy) / energy.cycles
    load = abs(float(energy.as_dict()["load_work_J"])) / energy.cycles
    rows = [c for c in check.criteria if c.utilisation is not None]
    motor = [float(c.utilisation or 0.0) for c in rows if c.key in _MOTOR_ROWS]
    stiff, lost = check.row("stiffness"), check.row("lost_motion")
    nan = math.nan
    return {
        "energy_J": friction,
        "friction_share": friction / (friction + load) if friction + load > 0 else nan,
        "temperature_rise_K": float(check.thermal.get("temperature_rise_K", nan)),
        "thermal_error_um": float(check.thermal.get("error_per_300mm_um", nan)),
        "L10_h": float(check.life.get("L10_hours", nan)),
        "stiffness_N_per_um": _value(stiff),
        "lost_motion_um": _value(lost),
        "motor_margin": 1.0 - max(motor) if motor else nan,
        "max_utilisation": max((float(c.utilisation or 0.0) for c in rows), default=nan),
        "p_not_ok": nan if check.p_not_ok is None else float(check.p_not_ok),
        "seconds": seconds,
    }


def _value(row: Criterion | None) -> float:
    """A row's value, NaN when the check has no such row or did not compute it."""
    return math.nan if row is None or row.value is None else float(row.value)


def _binding(check: AxisCheck) -> str:
    rows = [c for c in check.criteria if c.utilisation is not None]
    worst = max(rows, key=lambda c: float(c.utilisation or 0.0))
    return f"{worst.name} ({float(worst.utilisation or 0.0):.0%})"


def _against(c: Criterion) -> str:
    """A row's value against its limit: ``"fatigue life L10: 15100 h against 20000 h (132 %)"``.

    The utilisation is oriented so that above 100 % fails (a life or a safety
    factor under its limit, a load or a temperature error over it).
    """
    unit = "" if c.unit in ("-", "") else f" {c.unit}"
    return (f"{c.name}: {num(c.value, 4)}{unit} against a limit of {num(c.limit, 4)}{unit} "
            f"({float(c.utilisation or 0.0):.0%})")  # fmt: skip


def _failing(check: AxisCheck) -> tuple[str, ...]:
    rows = [c for c in check.criteria if c.verdict == "NOT OK" and c.utilisation is not None]
    rows.sort(key=lambda c: -float(c.utilisation or 0.0))
    return tuple(_against(c) for c in rows)


def _doubtful(check: AxisCheck) -> str:
    rows = [c for c in check.criteria if c.uncertainty is not None]
    if not rows:
        return ""
    worst = max(rows, key=lambda c: (c.uncertainty.p_not_ok if c.uncertainty else 0.0,
                                     float(c.utilisation or 0.0)))  # fmt: skip
    p = worst.uncertainty.p_not_ok if worst.uncertainty else 0.0
    return f"{worst.name} ({p:.1%})"


def evaluate(
    candidate: Candidate,
    profile: Profile,
    *,
    model: str = "complete",
    cycles: int = 1,
    temperature: float | None = None,
    run_time: float = 3600.0,
    move: dict[str, float] | None = None,
    parsed: Case | None = None,
    steady: SteadyState | None = None,
    confidence: float = CONFIDENCE,
) -> tuple[Evaluated, AxisCheck | None]:
    """One candidate through ``run_energy`` and ``run_check`` as ``ballscrew check`` runs it.

    Feasible when no row is NOT OK and the probability that one or more is, over the
    check's draws, is at most ``1 - confidence``.

    An input error of the candidate (a load above its rating, a stroke longer
    than its span) rejects it with the error as its binding constraint. A
    candidate a row fails at its nominal value is rejected without the check's
    Monte Carlo (``run_check(..., draws_when_failing=False)``: the verdicts are
    the nominal values', so the verdict and the binding row are the same; its
    ``p_not_ok`` is NaN). ``parsed`` is the candidate's case already parsed,
    ``steady`` its heat balance already solved (:func:`_prepared`).
    """
    start = time.process_time()
    nan = {k: math.nan for k in FIGURES}
    try:
        case = parsed or _parse_candidate(candidate)
        run = run_energy(case, profile, [model], cycles=cycles, temperature=temperature,
                         run_time=run_time, move=move, for_check=True,
                         steady=None if steady is None else {model: steady})  # fmt: skip
        check = run_check(run, model, draws_when_failing=False)
    except BallScrewInputError as exc:
        nan["seconds"] = time.process_time() - start
        nan["price"] = math.nan if candidate.price is None else candidate.price
        return Evaluated(candidate, nan, False, f"{exc.field}: {exc.allowed}"), None
    figures = _figures(check, run, model, time.process_time() - start)
    figures["price"] = math.nan if candidate.price is None else candidate.price
    nominal = check.verdict != "NOT OK"
    # The probability rounded to the draws' resolution (1/4000), so that a threshold of
    # exactly 5 % is not missed by a float's last bit.
    p = round(figures["p_not_ok"], 9)
    feasible = nominal and p <= 1.0 - confidence + 1e-12
    return Evaluated(candidate, figures, feasible, _binding(check), nominal, _failing(check),
                     _doubtful(check)), check  # fmt: skip


NEAR = 1e-5
"""How near a candidate's largest utilisation to 1 or :data:`RECOMMEND_BELOW` (relative) has it
evaluated alone, so that its verdict and the pick are the lone check's."""

BATCH = 2000
"""The most candidates whose heat balances are solved together (the friction calls of
:func:`~ballscrew.axis.thermal.steady_temperatures` bound their own points)."""


def _prepared(
    found: Sequence[Candidate], profile: Profile, model: str, run_time: float,
    progress: Progress | None = None,
) -> list[tuple[Case | None, SteadyState | None]]:  # fmt: skip
    """Each candidate's parsed case and its steady temperature, solved many at a time.

    The heat balance of the candidates that share an oil and model parameters is
    solved together (:func:`~ballscrew.axis.thermal.steady_temperatures`: the
    same balance, table and iteration, the friction of many screws in one call;
    equal to the candidate's own to the rounding of the friction, 1e-15), and their
    temperature histories integrated together
    (:func:`~ballscrew.axis.thermal.temperature_histories`: within the integrator's
    tolerance of the candidate's own). A
    candidate that does not parse, whose move its screw cannot take, or whose
    balance does not close gets None: :func:`evaluate` then runs it alone and
    rejects it with its error. Candidates that differ only in their motor (a motor
    table) share one balance: it does not read the motor.
    """
    out: list[tuple[Case | None, SteadyState | None]] = [(None, None)] * len(found)
    tell = progress or (lambda _stage, _done, _total: None)
    travel = float(np.ptp(profile.position))
    groups: dict[tuple[str, str], list[tuple[int, Case, Any]]] = {}
    twins: dict[tuple[Any, ...], list[int]] = {}
    for i, c in enumerate(found):
        tell("parse", i, len(found))
        try:
            case = _parse_candidate(c)
            setup = axis_setup(case.screw, case.axis, case.thermal, travel)
            motion_plausibility(case, profile, setup.axis, "--move")
        except BallScrewInputError:
            continue
        out[i] = (case, None)
        key = (case.lubricant.name, repr(case.parameters_for(model)))
        # The heat balance reads the screw, the node and the axis' moving mass and incline
        # (its loads), never the motor: candidates that differ in their motor alone share it.
        twin = (key, case.screw, setup.node, dataclasses.replace(setup.axis, motor_inertia=0.0))
        if twin in twins:
            twins[twin].append(i)
            continue
        twins[twin] = [i]
        groups.setdefault(key, []).append((i, case, setup))
    tell("parse", len(found), len(found))
    balanced = 0
    for members in groups.values():
        for start in range(0, len(members), BATCH):
            tell("heat", balanced, len(twins))
            part = members[start : start + BATCH]
            balanced += len(part)
            first = part[0][1]
            solved = steady_temperatures(
                profile, [c.screw for _, c, _ in part], first.lubricant,
                [s.axis for _, _, s in part], [s.node for _, _, s in part], model=model,
                **first.parameters_for(model),
            )  # fmt: skip
            closed = [(j, st) for j, st in enumerate(solved) if st is not None]
            histories = temperature_histories(
                profile, [part[j][1].screw for j, _ in closed],
                [part[j][2].node for j, _ in closed], run_time, [st for _, st in closed],
                points=HISTORY_POINTS,
            )  # fmt: skip
            for (j, st), history in zip(closed, histories, strict=True):
                i, case, _ = part[j]
                out[i] = (case, dataclasses.replace(st, history=history))
    tell("heat", len(twins), len(twins))
    for twin_indices in twins.values():
        shared = out[twin_indices[0]][1]
        for i in twin_indices[1:]:
            out[i] = (out[i][0], shared)
    return out


def _parse_candidate(candidate: Candidate) -> Case:
    """The candidate's case; a plausibility warning it gives names the candidate's screw.

    The user's ``[axis]`` meets each candidate's screw (its lead, its d·n limit, its
    C_0a): a warning such as ``axis.max_feed`` past the nut's d·n limit belongs to
    that candidate, and said without its name it reads as the user's case's own.
    """
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        case = parse_case(candidate.text, source=candidate.name)
    for w in caught:
        m = w.message
        if isinstance(m, BallScrewPlausibilityWarning):
            m = BallScrewPlausibilityWarning(
                f"{candidate.row.name}: {m.field}", m.value, m.allowed, m.source
            )
        warnings.warn(m, stacklevel=2)
    return case


_SHOWN = {"stroke": ("mm", 1e3), "feed": ("m/min", 60.0), "acceleration": ("m/s^2", 1.0),
          "jerk": ("m/s^3", 1.0), "dwell": ("s", 1.0), "force": ("N", 1.0),
          "force_from": ("mm", 1e3), "force_to": ("mm", 1e3)}  # fmt: skip
"""The units a move is written back in, as ``--move`` is typed (key: unit, factor from SI)."""


def _duty(move: Mapping[str, float] | None) -> str:
    """The move an error names ("stroke=400 mm, feed=20 m/min, ..."); a profile's file."""
    if not move:
        return "the profile's duty"
    return ", ".join(
        f"{k}={v * _SHOWN[k][1]:.6g} {_SHOWN[k][0]}" if k in _SHOWN
        else f"{k}={v:g}"  # a key no move has (a library caller's own): no unit known
        for k, v in move.items()
    )  # fmt: skip


def non_dominated(values: FloatArray) -> FloatArray:
    """Indices of the rows of ``values`` (n x m, all minimised) no other row dominates.

    pymoo's non-dominated sorting (Deb et al. 2002, NSGA-II), its first front.
    """
    from pymoo.util.nds.non_dominated_sorting import NonDominatedSorting

    f = np.asarray(values, dtype=float)
    if len(f) == 0:
        return np.array([], dtype=int)
    front = NonDominatedSorting().do(f, only_non_dominated_front=True)
    return np.sort(np.asarray(front, dtype=int))


def _check_objectives(objectives: Sequence[str]) -> tuple[str, ...]:
    if not objectives:
        raise BallScrewInputError(
            "--objective", "(none)", f"one or more of {', '.join(OBJECTIVES)}"
        )
    for o in objectives:
        if o not in OBJECTIVES:
            close = difflib.get_close_matches(o, list(OBJECTIVES), n=1)
            hint = f" (did you mean {close[0]}?)" if close else ""
            raise BallScrewInputError("--objective", o, f"one of {', '.join(OBJECTIVES)}{hint}")
    return tuple(dict.fromkeys(objectives))


def _objective_key(evaluated: Sequence[Evaluated], objective: str) -> Any:
    """Sort key of a candidate on ``objective``, best first (a missing figure last)."""
    key, _, sense = OBJECTIVES[objective]

    def value(i: int) -> float:
        v = evaluated[i].figures[key]
        return math.inf if math.isnan(v) else sense * v

    return value


def _objective_text(e: Evaluated, objective: str) -> str:
    key, label, _ = OBJECTIVES[objective]
    name = label.split(" [")[0].split(",")[0].split(" (")[0]
    unit = FIGURES.get(key, "")
    unit = "" if unit in ("-", "currency of the table") else f" {unit}"
    return f"{name} {num(e.figures[key], 4)}{unit}"


def _confidence_text(e: Evaluated, confidence: float) -> str:
    p = e.figures["p_not_ok"]
    if math.isnan(p):
        return ""
    return f"P(NOT OK) = {p:.1%} (at most {1.0 - confidence:.0%} allowed){_from(e)}"


def _from(e: Evaluated, binding: bool = False) -> str:
    """Which row a candidate's P(NOT OK) comes from most; with ``binding``, its binding row too."""
    if not e.doubtful or e.figures["p_not_ok"] == 0.0:
        return f"; its binding row: {e.binding}" if binding else ""
    row = e.doubtful.rsplit(" (", 1)[0]
    if e.binding.startswith(row + " ("):
        return f", most likely from its binding row{f', {e.binding}' if binding else ''}"
    return f", most likely from {e.doubtful}" + (f"; its binding row: {e.binding}" if binding
                                                 else "")  # fmt: skip


def _recommend(
    evaluated: Sequence[Evaluated], front: Sequence[int], first: str,
    confidence: float = CONFIDENCE,
) -> tuple[int, str]:  # fmt: skip
    """The recommended member of the front, by the module's rule, and why.

    ``first`` is the first objective picked: it chooses among the members whose
    every utilisation is at most :data:`RECOMMEND_BELOW`, and it breaks a tie
    (within :data:`TIE_BAND`) on the least largest utilisation.
    """
    rank = _objective_key(evaluated, first)
    below = [i for i in front if evaluated[i].figures["max_utilisation"] <= RECOMMEND_BELOW]
    if below:
        best = min(below, key=lambda i: (rank(i), i))
        e = evaluated[best]
        among = (
            f"the {len(below)} candidates of the front whose every utilisation is"
            if len(below) > 1
            else "the one candidate of the front whose every utilisation is"
        )
        why = (f"the best {_objective_text(e, first)} among {among} at most "
               f"{RECOMMEND_BELOW:.0%} (its largest: {e.binding})")  # fmt: skip
    else:
        least = min(evaluated[i].figures["max_utilisation"] for i in front)
        tied = [i for i in front if evaluated[i].figures["max_utilisation"] <= least + TIE_BAND]
        best = min(tied, key=lambda i: (rank(i), evaluated[i].figures["max_utilisation"], i))
        e = evaluated[best]
        why = (
            f"no candidate of the front keeps every utilisation at most "
            f"{RECOMMEND_BELOW:.0%}: the one with the least largest utilisation, {e.binding}"
        )
        if len(tied) > 1:
            others = ", ".join(f"{evaluated[i].name} ({_objective_text(evaluated[i], first)}, "
                               f"{evaluated[i].figures['max_utilisation']:.1%})"
                               for i in tied if i != best)  # fmt: skip
            why += (
                f"; tied within {TIE_BAND:.0%} of utilisation with {others}, it has the "
                f"better {_objective_text(e, first)}"
            )
    sure = _confidence_text(e, confidence)
    return best, why + (f"; {sure}" if sure else "")


def run_select(
    case: Case,
    profile: Profile,
    *,
    objectives: Sequence[str] = ("energy", "life"),
    diameter: tuple[float, float] | None = None,
    lead: tuple[float, float] | None = None,
    makers: Sequence[str] = (),
    preloads: Sequence[str] = DEFAULT_PRELOADS,
    oils: Sequence[str] = (),
    model: str = "complete",
    cycles: int = 1,
    temperature: float | None = None,
    run_time: float = 3600.0,
    move: dict[str, float] | None = None,
    motion_field: str = "--move",
    pool: Sequence[Candidate] | None = None,
    sources: Sequence[str] = ("catalogue",),
    nuts: Sequence[str] = (),
    motors: Sequence[MotorRow] = (),
    screw_prices: Mapping[str, float] | None = None,
    currency: str = "",
    confidence: float = CONFIDENCE,
    progress: Progress | None = None,
    batched: bool = True,
) -> SelectResult:
    """Choose the screw for ``case``'s axis over ``profile`` (module docstring).

    Parameters
    ----------
    case : Case
        The axis (its ``[axis]``, ``[motor]``, ``[check]``); its screw is replaced.
    profile : Profile
        The duty, as ``ballscrew check`` takes it.
    objectives : sequence of str
        Keys of :data:`OBJECTIVES` the front is taken over.
    diameter, lead : (float, float), optional
        Ranges of the nominal diameter and the lead [m].
    makers, preloads, oils : sequence of str
        Makers to keep, preload classes (:data:`~.candidates.PRELOAD_CLASSES`) and
        oils to try (default: the case's).
    model, cycles, temperature, run_time, move, motion_field
        As for :func:`~ballscrew.axis.duty.run_energy` (``motion_field``, what the
        duty was given as, is kept for the callers: the error of a selection nothing
        passes names the candidates' failing rows, not the duty's option).
    pool : sequence of Candidate, optional
        The candidates to evaluate, built by the caller (a size series, a design
        space); the filters ``diameter`` to ``oils`` then do not apply.
    sources, nuts : sequence of str
        Where the screws come from (:data:`~.pool.SOURCES`: the catalogue, the
        ISO 3408-2 sizes with estimated ratings) and the nut kinds to keep.
    motors : sequence of MotorRow
        A motor table's rows (:func:`ballscrew.io.motors.read_motors`): every
        screw is tried with every motor; its price column gives ``price``.
    screw_prices, currency : mapping, str
        A screw price table (:func:`ballscrew.io.motors.read_prices`): screw
        name -> price, added to the motor's, and its currency, which must be
        the motor table's.
    confidence : float
        The confidence a feasible candidate passes with: its P(NOT OK) at most
        ``1 - confidence`` (default 0.95, the check's "OK (95 %)").
    progress : callable, optional
        ``progress(stage, done, total)`` as the candidates are read, their heat
        balances solved and the candidates evaluated (:data:`Progress`).
    batched : bool
        True (default): the candidates' friction calls made many screws at a time
        and each repeated call answered from memory (module docstring); False: every
        candidate's calls made by itself, one by one, the path the batched one is
        tested equal to (slower).

    Raises
    ------
    BallScrewInputError
        For an unknown objective, an empty candidate set, or a duty no
        candidate passes even at its nominal values (naming the closest candidates,
        their failing rows and by how much): then a :class:`NoFeasibleCandidateError`,
        whose ``result`` holds every candidate.
    """
    chosen = _check_objectives(objectives)
    confidence = parse_confidence(confidence, "confidence")
    motor_currency = _check_prices(chosen, oils, motors, screw_prices, currency)
    if pool is not None:
        found = list(pool)
        if not found:
            raise BallScrewInputError("pool", "(empty)", "at least one candidate")
    else:
        found = candidates(case.text, diameter=diameter, lead=lead, makers=makers,
                           preloads=preloads, oils=list(oils) or [None],
                           default_oil=case.lubricant.name, sources=sources, nuts=nuts,
                           motors=motors, screw_prices=screw_prices)  # fmt: skip
    batch = _Batch(found, _prepared(found, profile, model, run_time, progress), profile,
                   {"model": model, "cycles": cycles, "temperature": temperature,
                    "run_time": run_time, "move": move, "confidence": confidence},
                   progress, batched)  # fmt: skip
    evaluated = batch.evaluated
    inputs = {"case": case.title, "model": model, "cycles": cycles, "temperature": temperature,
              "run_time_s": run_time, "move": dict(move or {}), "objectives": list(chosen),
              "diameter_m": list(diameter) if diameter else None,
              "lead_m": list(lead) if lead else None, "makers": list(makers),
              "preloads": list(preloads), "oils": list(oils), "sources": list(sources),
              "nuts": list(nuts), "motors": [m.name for m in motors],
              "currency": motor_currency or currency or None,
              "rating_estimates": scatter_text() if any(c.estimated for c in found) else None,
              "confidence": confidence, "case_text": case.text}  # fmt: skip
    feasible, undecided = _passing(evaluated)
    if not feasible:
        failed = NoneFeasible(case.title, chosen, tuple(evaluated), model, "", inputs)
        reason = _none_passes(failed.rejected, len(evaluated), _duty(move))
        failed = dataclasses.replace(failed, reason=reason)
        raise NoFeasibleCandidateError("candidates", f"{len(evaluated)} candidates",
                                       reason, failed)  # fmt: skip
    _check_computed(chosen, evaluated, feasible)
    front, best, reason, undecided = _front_and_pick(batch, chosen, confidence)
    return SelectResult(case.title, chosen, tuple(evaluated), front, best, reason, model, inputs,
                        confidence, undecided)  # fmt: skip


def _check_prices(
    chosen: Sequence[str], oils: Sequence[str], motors: Sequence[MotorRow],
    screw_prices: Mapping[str, float] | None, currency: str,
) -> str:  # fmt: skip
    """Refuse an unknown oil, a price objective without prices, or two currencies.

    Returns the motor table's currency ("" when it has no price).
    """
    for oil in oils:
        try:
            lubricants.get(oil)
        except BallScrewInputError as exc:
            raise BallScrewInputError("--oil", oil, exc.allowed) from None
    if "price" in chosen and not any(m.price is not None for m in motors) and not screw_prices:
        raise BallScrewInputError(
            "--objective", "price",
            "an objective the inputs give: price needs a price column in the --motors table "
            "(e.g. 'price [EUR]') or a --screw-prices table"
            + ("" if motors else "; neither was given"),
        )  # fmt: skip
    motor_currency = next((m.currency for m in motors if m.price is not None), "")
    if screw_prices and motor_currency and currency != motor_currency:
        raise BallScrewInputError(
            "--screw-prices", currency or "(none)",
            f"prices in the motor table's currency, {motor_currency}",
        )  # fmt: skip
    return motor_currency


PRIME = 64
"""The candidates whose cycle and creep-drag friction are computed together (:func:`_prime`)."""


def _prime(
    ready: Sequence[tuple[Case | None, SteadyState | None]], profile: Profile,
    options: dict[str, Any], part: Sequence[int],
) -> None:  # fmt: skip
    """The friction calls of the candidates ``part`` will make, made ahead many at a time.

    For each candidate whose heat balance is solved: its cycle's friction at its distinct
    (speed, force) pairs (:func:`~ballscrew.axis.energy.distinct_pairs`, what
    :func:`~ballscrew.axis.energy.axis_cycle` evaluates) and its drag at creep speed
    (the check's lost motion), at the run's temperature. The candidates that share a
    lubricant and model parameters go through the model together
    (:func:`~ballscrew.chain.fill_friction_memo`: the screws as arrays, equal to their own
    calls within 1e-12 relative), and each candidate's own call then answers from the memo.
    """
    model = options["model"]
    travel = float(np.ptp(profile.position))
    groups: dict[tuple[Any, str], tuple[list[Any], list[Any], list[Any], dict[str, Any]]] = {}
    for i in part:
        case, steady = ready[i]
        if case is None or steady is None:
            continue
        try:
            setup = axis_setup(case.screw, case.axis, case.thermal, travel)
        except BallScrewInputError:
            continue
        # The run's temperature, as run_energy takes it.
        given = options["temperature"]
        temp = float(case.temperature.flat[0]) if given is None else float(given)
        params = case.parameters_for(model)
        screws, cycles, creeps, _ = groups.setdefault((case.lubricant, repr(params)),
                                                      ([], [], [], params))  # fmt: skip
        screws.append(case.screw)
        omega, _, force = screw_motion(profile, case.screw, setup.axis)
        speeds, forces, _ = distinct_pairs(omega, force)
        # Without a repeated sample axis_cycle calls the model on the samples themselves.
        cycles.append((speeds, temp, forces) if speeds.size < omega.size else None)
        creeps.append((CREEP_SPEED, temp, 0.0))
    for (lubricant, _), (screws, cycles, creeps, params) in groups.items():
        kept = [(s, c) for s, c in zip(screws, cycles, strict=True) if c is not None]
        if kept:
            fill_friction_memo([s for s, _ in kept], lubricant, [c for _, c in kept],
                               model=model, **params)  # fmt: skip
        fill_friction_memo(screws, lubricant, creeps, model=model, **params)


def _by_group(ready: Sequence[tuple[Case | None, SteadyState | None]], model: str) -> list[int]:
    """The candidates' indices by lubricant, model parameters and nut kind, else in order."""

    def group(i: int) -> tuple[str, str, str, str]:
        case = ready[i][0]
        if case is None:
            return ("", "", "", "")
        screw = case.screw
        return (case.lubricant.name, repr(case.parameters_for(model)), screw.nut,
                screw.ball_separation)  # fmt: skip

    return sorted(range(len(ready)), key=group)


class _Batch:
    """The candidates evaluated with one batched heat balance, and again alone where it matters.

    The batched temperature moves a thermal row's draws by 1e-5 relative at most: a
    candidate near a bound (:meth:`near`) and the front and the pick are evaluated
    alone (their heat balance solved on its own), so that their figures are exact.
    """

    def __init__(
        self, found: Sequence[Candidate], ready: Sequence[Any], profile: Profile,
        options: dict[str, Any], progress: Progress | None = None, batched: bool = True,
    ) -> None:  # fmt: skip
        self.found, self.ready, self.profile, self.options = found, ready, profile, options
        tell = progress or (lambda _stage, _done, _total: None)
        done: dict[int, Evaluated] = {}
        # The friction calls of each candidate's cycle and creep drag are made ahead, PRIME
        # candidates' at a time, many screws in one call; the memo answers the candidates'
        # own calls with them, and the repeats of candidates that differ only in their motor.
        # The candidates are taken by lubricant and nut kind (as the model takes the screws
        # together), each evaluated by itself: the order changes no figure.
        order = _by_group(ready, options["model"]) if batched else list(range(len(found)))
        with friction_memo(4 * PRIME + MEMO_SIZE) if batched else contextlib.nullcontext():
            for start in range(0, len(order), PRIME):
                part = order[start : start + PRIME]
                if batched:
                    _prime(ready, profile, options, part)
                for i in part:
                    tell("check", len(done), len(found))
                    parsed, steady = ready[i]
                    done[i] = evaluate(found[i], profile, parsed=parsed, steady=steady,
                                       **options)[0]  # fmt: skip
        tell("check", len(found), len(found))
        self.evaluated = [done[i] for i in range(len(found))]
        self.tell = tell
        self.alone = {i for i, (_, steady) in enumerate(ready) if steady is None}
        self.again(self.near())

    def near(self) -> list[int]:
        """The candidates to evaluate alone: feasibility and the pick as alone.

        A utilisation within NEAR of 1 or of RECOMMEND_BELOW, or a P(NOT OK) within 1 %
        of the allowed one.
        """
        allowed = 1.0 - self.options["confidence"]
        return [i for i, e in enumerate(self.evaluated) if any(
            abs(e.figures["max_utilisation"] - bound) <= NEAR * bound
            for bound in (1.0, RECOMMEND_BELOW))
            or abs(e.figures["p_not_ok"] - allowed) <= 0.01]  # fmt: skip

    def again(self, indices: Sequence[int]) -> None:
        """Evaluate ``indices`` alone, their heat balance solved on its own (exact figures)."""
        for k, i in enumerate(indices):
            self.tell("alone", k, len(indices))
            if i not in self.alone:
                again = evaluate(self.found[i], self.profile, parsed=self.ready[i][0],
                                 **self.options)  # fmt: skip
                self.evaluated[i] = again[0]
                self.alone.add(i)


def _passing(evaluated: Sequence[Evaluated]) -> tuple[list[int], bool]:
    """The candidates the front is taken over, and whether they are only nominal passes."""
    sure = [i for i, e in enumerate(evaluated) if e.feasible]
    if sure:
        return sure, False
    return [i for i, e in enumerate(evaluated) if e.nominal], True


def _check_computed(
    chosen: Sequence[str], evaluated: Sequence[Evaluated], feasible: Sequence[int]
) -> None:
    """Refuse an objective no feasible candidate has a figure for (naming those computed)."""
    for o in chosen:
        key = OBJECTIVES[o][0]
        if all(math.isnan(evaluated[i].figures[key]) for i in feasible):
            need = " (the case has no [motor] and no --motors table was given)" if (
                o == "motor_margin") else ""  # fmt: skip
            raise BallScrewInputError(
                "--objective", o,
                f"an objective computed for some feasible candidate{need}; computed: "
                + ", ".join(k for k, (f, _, _) in OBJECTIVES.items()
                            if any(not math.isnan(evaluated[i].figures[f]) for i in feasible)),
            )  # fmt: skip


def _front_and_pick(
    batch: _Batch, chosen: Sequence[str], confidence: float
) -> tuple[tuple[int, ...], int, str, bool]:
    """The front, the pick, why, and whether only nominal passes were left.

    On figures equal to their lone check's: the front's members and the pick not yet
    evaluated alone are, and the front is taken again, until none is left.
    """
    evaluated = batch.evaluated
    columns = [OBJECTIVES[o] for o in chosen]
    while True:
        feasible, undecided = _passing(evaluated)
        f = np.array([[sense * evaluated[i].figures[key] for key, _, sense in columns]
                      for i in feasible])  # fmt: skip
        f = np.where(np.isnan(f), np.inf, f)
        front = tuple(int(feasible[j]) for j in non_dominated(f))
        if undecided:
            best, reason = _least_doubtful(evaluated, feasible, chosen[0], confidence)
        else:
            best, reason = _recommend(evaluated, front, chosen[0], confidence)
            reason += _passed_over(evaluated, feasible, columns, chosen[0], confidence)
        todo = [i for i in (*front, best) if i not in batch.alone]
        if not todo:
            return front, best, reason, undecided
        batch.again(todo)


def _passed_over(
    evaluated: Sequence[Evaluated], feasible: Sequence[int],
    columns: Sequence[tuple[str, str, int]], first: str, confidence: float,
) -> str:  # fmt: skip
    """What the rule would have picked on nominal verdicts alone, when it is not sure enough."""
    nominal = [i for i, e in enumerate(evaluated) if e.nominal]
    if len(nominal) == len(feasible):
        return ""
    f = np.array([[sense * evaluated[i].figures[key] for key, _, sense in columns]
                  for i in nominal])  # fmt: skip
    f = np.where(np.isnan(f), np.inf, f)
    front = [int(nominal[j]) for j in non_dominated(f)]
    pick, _ = _recommend(evaluated, front, first, confidence)
    if evaluated[pick].feasible:
        return ""
    e = evaluated[pick]
    return (
        f". On nominal verdicts alone the pick would be {e.name}, but its P(NOT OK) is "
        f"{e.figures['p_not_ok']:.1%}, above the {1.0 - confidence:.0%} allowed" + _from(e)
    )


def _least_doubtful(
    evaluated: Sequence[Evaluated], nominal: Sequence[int], first: str, confidence: float
) -> tuple[int, str]:
    """Undecided: of the candidates passing at nominal values, the least likely to fail.

    Named whether or not it is on the front (the front's members may all be more likely
    to fail); a tie on the probability goes by the rule (:func:`_recommend`).
    """
    least = min(evaluated[i].figures["p_not_ok"] for i in nominal)
    tied = [i for i in nominal if evaluated[i].figures["p_not_ok"] <= least + 1e-12]
    best, _ = _recommend(evaluated, tied, first, confidence)
    e = evaluated[best]
    passing = sum(x.nominal for x in evaluated)
    return best, (
        f"undecided: no candidate passes with {confidence:.0%} confidence (P(NOT OK) at most "
        f"{1.0 - confidence:.0%}); {passing} of {len(evaluated)} pass at their nominal values, "
        f"and the least likely to fail of them, {e.name}, has P(NOT OK) = "
        f"{e.figures['p_not_ok']:.1%}{_from(e, binding=True)}"
    )


def _none_passes(closest: Sequence[Evaluated], count: int, duty: str) -> str:
    """The sentence of a selection no candidate passes: the closest, their rows and by how much."""
    parts = []
    for e in closest[:CLOSEST]:
        if e.failing:
            rows = "; ".join(e.failing)
            parts.append(f"{e.name} fails {rows}")
        else:  # stopped by an input error
            parts.append(f"{e.name} is refused: {e.binding}")
    return (
        f"no candidate passes the check over {duty}: none of the {count} candidates tried "
        f"keeps every row within its limit. The closest to passing: "
        + ". ".join(parts)
        + ". Look for screws beyond these filters (diameter, lead, maker, preload class, "
        "oil, motor) or ease what fails them."
    )
