r"""Acceptance of a measured preload drag torque, as makers check it.

What ``ballscrew acceptance`` computes. A maker sets a nut's preload by its
dynamic drag torque, measured turning the screw at a steady low speed, and
accepts it when the mean torque lies within the permitted deviation from the
reference torque for the screw's accuracy grade and torque level
(:data:`ballscrew.catalog_formulas.DRAG_TORQUE_TOLERANCE`). The reference is
given, or the catalogue rule :math:`T_p = 0.05(\tan\beta)^{-1/2}F_{pr}l/2\pi`
(:func:`ballscrew.catalog_formulas.preload_torque`), or a model's torque at
100 rpm without axial load (at each speed of a trace).

**Each speed separately.** A trace with a speed column is split by speed; each
speed's readings get their own mean, fluctuation and verdict (a trace at 100
and 1500 rpm is two measurements, not one average).

**Measurement uncertainty and the decision rule (ISO 14253-1:2017, 5.2 and
5.3).** With the expanded uncertainty :math:`U` of a mean torque (``--uncertainty``,
a torque or a share of the reference), each speed is **conformance proven**
when its mean lies inside the band narrowed by :math:`U` on both sides,
**non-conformance proven** when it lies outside the band widened by :math:`U`,
and **undecided** in between. Without :math:`U` the decision is the plain
band's (and says that no uncertainty was stated). The whole trace is
conformance proven when every speed is, non-conformance proven when any speed
is, otherwise undecided.

**The band.** The makers' table is held for grade C3 only (the row checked
against THK's worked example); another grade, or a reference torque outside
the table (below 0.2 N·m or above 6.3 N·m), is refused unless a tolerance is
stated (``--tolerance``), which is then used and labelled as given.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from ..chain import friction_torque
from ..design.catalog_formulas import drag_torque_tolerance, preload_torque
from ..errors import BallScrewInputError
from ..io.case import Case
from ..kinematics import rpm_to_rad_s

__all__ = [
    "DECISIONS",
    "Acceptance",
    "SpeedVerdict",
    "accept_drag_torque",
    "decide",
    "reference_torque",
    "run_acceptance",
]

DECISIONS = ("conformance proven", "non-conformance proven", "undecided")
"""The three outcomes of ISO 14253-1's decision rule."""


def decide(value: float, low: float, high: float, uncertainty: float) -> str:
    """ISO 14253-1: conformance or non-conformance proven, or undecided, for ``value`` ± U.

    >>> decide(1.0, 0.7, 1.3, 0.1), decide(1.45, 0.7, 1.3, 0.1), decide(1.25, 0.7, 1.3, 0.1)
    ('conformance proven', 'non-conformance proven', 'undecided')
    """
    if low + uncertainty <= value <= high - uncertainty:
        return DECISIONS[0]
    if value < low - uncertainty or value > high + uncertainty:
        return DECISIONS[1]
    return DECISIONS[2]


@dataclass(frozen=True)
class SpeedVerdict:
    """The readings at one speed [rad/s] (NaN: no speed column) against the band [N·m]."""

    speed: float
    mean: float
    fluctuation: float
    points: int
    reference: float
    low: float
    high: float
    accepted: bool
    decision: str

    def as_dict(self) -> dict[str, Any]:
        """JSON-ready values (speed in rpm)."""
        rpm = None if math.isnan(self.speed) else self.speed * 30.0 / math.pi
        return {"speed_rpm": rpm, "mean_torque_Nm": self.mean,
                "fluctuation_Nm": self.fluctuation, "readings": self.points,
                "reference_Nm": self.reference, "accepted_from_Nm": self.low,
                "accepted_to_Nm": self.high, "accepted": self.accepted,
                "decision": self.decision}  # fmt: skip


_SOURCE = "THK General Catalog A-688 Table 13 (JIS B 1192 / ISO 3408-3)"


@dataclass(frozen=True)
class Acceptance:
    """The verdict on a measured drag torque [N·m] against its reference.

    ``mean`` and ``fluctuation`` (largest minus smallest reading) of the
    measured torques; ``low``/``high`` the accepted range; ``row`` the table
    row used (reference torques [N·m] and tolerance).
    """

    mean: float
    fluctuation: float
    points: int
    reference: float
    reference_source: str
    grade: str
    row: tuple[float, float, float]
    low: float
    high: float
    accepted: bool
    notes: list[str] = field(default_factory=list)
    uncertainty: float = 0.0
    """Expanded measurement uncertainty U of a mean [N·m] (0: none stated)."""
    decision: str = DECISIONS[2]
    """ISO 14253-1's decision over every speed (:data:`DECISIONS`)."""
    speeds: tuple[SpeedVerdict, ...] = ()
    tolerance_source: str = _SOURCE

    def as_dict(self) -> dict[str, Any]:
        """The JSON document of ``ballscrew acceptance`` (the writer adds the version)."""
        return {"decision": self.decision, "uncertainty_Nm": self.uncertainty,
                "decision_rule": "ISO 14253-1:2017 (conformance inside the band narrowed by U, "
                "non-conformance outside the band widened by U)",
                "speeds": [v.as_dict() for v in self.speeds],
                "mean_torque_Nm": self.mean,
                "fluctuation_Nm": self.fluctuation, "readings": self.points,
                "reference_Nm": self.reference, "reference_from": self.reference_source,
                "grade": self.grade,
                "row": {"from_Nm": self.row[0], "to_Nm": self.row[1], "tolerance": self.row[2]},
                "accepted_from_Nm": self.low, "accepted_to_Nm": self.high,
                "accepted": self.accepted, "notes": list(self.notes),
                "source": self.tolerance_source}  # fmt: skip


def accept_drag_torque(
    torque: npt.ArrayLike,
    reference: float | npt.ArrayLike,
    *,
    grade: str = "C3",
    reference_source: str = "given",
    speed: npt.ArrayLike | None = None,
    uncertainty: float = 0.0,
    tolerance: float | None = None,
) -> Acceptance:
    """Judge measured drag torques [N·m] (one value or a trace) against ``reference`` [N·m].

    The mean of the magnitudes must lie within ``reference`` times (1 ± the
    tolerance of its row). The fluctuation (the range of the readings) is
    reported, not judged: the permitted fluctuation of the grades is not held.
    ``speed`` [rad/s], one per reading, splits a trace into its speeds, each
    judged on its own (``reference`` may then give one torque per reading);
    ``uncertainty`` is the expanded uncertainty U of a mean [N·m] for the
    ISO 14253-1 decision (module docstring); ``tolerance`` a stated band
    (share) instead of the table's.

    Examples
    --------
    THK's worked example, BNFN4010-5 with 3 kN preload, reference 865 N·mm at C3:

    >>> a = accept_drag_torque([0.80, 0.92, 0.86], 0.865)
    >>> a.row, round(a.low, 4), round(a.high, 4), a.accepted
    ((0.6, 1.0, 0.3), 0.6055, 1.1245, True)
    >>> accept_drag_torque([0.80, 0.92, 0.86], 0.865, uncertainty=0.05).decision
    'conformance proven'
    """
    values = np.abs(np.atleast_1d(np.asarray(torque, dtype=float))).ravel()
    if values.size == 0 or not np.all(np.isfinite(values)):
        raise BallScrewInputError("torque", values.tolist(), "one or more finite torques")
    refs = np.broadcast_to(np.asarray(reference, dtype=float).ravel(), values.shape)
    if not np.all(refs > 0.0):
        raise BallScrewInputError("reference", float(np.min(refs)), "a positive reference torque")
    if not (math.isfinite(uncertainty) and uncertainty >= 0.0):
        raise BallScrewInputError("--uncertainty", uncertainty, "a torque >= 0")
    notes = []
    if speed is None:
        groups = [np.arange(values.size)]
        speeds = [math.nan]
    else:
        w = np.asarray(speed, dtype=float).ravel()
        if w.shape != values.shape:
            raise BallScrewInputError("speed", w.size, f"one speed per reading ({values.size})")
        keys = np.round(np.abs(w), 6)
        speeds = [float(k) for k in np.unique(keys)]
        groups = [np.flatnonzero(keys == k) for k in speeds]
        if len(speeds) > 1:
            notes.append(f"{len(speeds)} speeds in the trace: each judged on its own")
            if np.ptp(refs) == 0.0:
                notes.append(
                    "one reference torque for every speed (the makers' rule has no speed; "
                    "--reference model gives the model's at each speed)"
                )
    verdicts = []
    rows = []
    for w_k, idx in zip(speeds, groups, strict=True):
        ref = float(np.mean(refs[idx]))
        row = _row(ref, grade, tolerance)
        rows.append(row)
        mean = float(np.mean(values[idx]))
        low, high = ref * (1.0 - row[2]), ref * (1.0 + row[2])
        fluct = float(np.ptp(values[idx])) if idx.size > 1 else 0.0
        verdicts.append(SpeedVerdict(w_k, mean, fluct, int(idx.size), ref, low, high,
                                     bool(low <= mean <= high),
                                     decide(mean, low, high, uncertainty)))  # fmt: skip
    if values.size == 1:
        notes.append("one reading: its fluctuation is unknown (give the trace)")
    if uncertainty == 0.0:
        notes.append("no measurement uncertainty stated (--uncertainty): the decision is the "
                     "plain band's; ISO 14253-1 asks for U")  # fmt: skip
    mean = float(np.mean(values))
    ref0 = float(np.mean(refs))
    scale = mean / ref0
    if scale > 100.0 or scale < 0.01:
        notes.append(f"the mean is {scale:.3g} times the reference: check the torque unit "
                     "(N*mm against N*m)")  # fmt: skip
    decisions = {v.decision for v in verdicts}
    if decisions == {DECISIONS[0]}:
        overall = DECISIONS[0]
    elif DECISIONS[1] in decisions:
        overall = DECISIONS[1]
    else:
        overall = DECISIONS[2]
    first = verdicts[0]
    fluct = float(np.ptp(values)) if values.size > 1 else 0.0
    label = _SOURCE if tolerance is None else f"a tolerance of +-{tolerance:.0%} (given)"
    return Acceptance(mean if len(verdicts) > 1 else first.mean, fluct, int(values.size),
                      ref0 if len(verdicts) > 1 else first.reference, reference_source,
                      grade.strip().upper(), rows[0], first.low, first.high,
                      all(v.accepted for v in verdicts), notes, float(uncertainty), overall,
                      tuple(verdicts), label)  # fmt: skip


def _row(reference: float, grade: str, tolerance: float | None) -> tuple[float, float, float]:
    """The table's row for ``reference`` [N·m], or the stated tolerance's."""
    if tolerance is not None:
        if not (math.isfinite(tolerance) and 0.0 < tolerance < 1.0):
            raise BallScrewInputError("--tolerance", tolerance, "a share from 0 to 100 %")
        return (reference, reference, float(tolerance))
    try:
        return drag_torque_tolerance(reference, grade)
    except BallScrewInputError as exc:
        raise BallScrewInputError(
            exc.field, exc.value, f"{exc.allowed}; or state the band with --tolerance "
            "(e.g. the maker's, for a reference below 0.2 N*m or another grade)",
        ) from None  # fmt: skip


def reference_torque(
    case: Case, reference: str | float, model: str = "complete"
) -> tuple[float, str]:
    """The reference drag torque [N·m] of a case, and where it comes from.

    ``reference`` is ``"catalog"`` (the makers' rule at the case's preload,
    :func:`ballscrew.design.catalog_formulas.preload_torque`), ``"model"`` (``model``
    at 100 rpm, no axial load, the case's first temperature) or a given torque [N·m].
    """
    screw = case.screw
    if isinstance(reference, str):
        choice = reference.strip().lower()
        if choice == "catalog":
            value = float(preload_torque(screw.preload, screw.lead, screw.lead_angle))
            return value, f"the makers' rule at {screw.preload:.4g} N preload"
        if choice == "model":
            value = float(friction_torque(
                screw, case.lubricant, speed=rpm_to_rad_s(100.0),
                temperature=float(np.ravel(case.temperature)[0]), model=model,
                **case.parameters_for(model)).total)  # fmt: skip
            return value, f"{model} at 100 rpm, no axial load"
        raise BallScrewInputError("reference", reference, "'catalog', 'model' or a torque")
    return float(reference), "given"


def run_acceptance(
    case: Case,
    torque: npt.ArrayLike,
    *,
    reference: str | float = "catalog",
    model: str = "complete",
    grade: str = "C3",
    speed: npt.ArrayLike | None = None,
    uncertainty: float = 0.0,
    tolerance: float | None = None,
) -> Acceptance:
    """``ballscrew acceptance``: measured drag torques [N·m] of a case against its reference.

    The reference is found by :func:`reference_torque` (for ``"model"`` and a
    trace with speeds, the model at each speed), the verdict given by
    :func:`accept_drag_torque`.
    """
    if speed is not None and isinstance(reference, str) and reference.strip().lower() == "model":
        w = np.abs(np.asarray(speed, dtype=float).ravel())
        screw = case.screw
        refs = np.asarray(friction_torque(
            screw, case.lubricant, speed=w, temperature=float(np.ravel(case.temperature)[0]),
            model=model, **case.parameters_for(model)).total, dtype=float).ravel()  # fmt: skip
        return accept_drag_torque(torque, refs, grade=grade, speed=speed,
                                  reference_source=f"{model} at each speed, no axial load",
                                  uncertainty=uncertainty, tolerance=tolerance)  # fmt: skip
    value, source = reference_torque(case, reference, model)
    return accept_drag_torque(torque, value, grade=grade, reference_source=source, speed=speed,
                              uncertainty=uncertainty, tolerance=tolerance)  # fmt: skip
