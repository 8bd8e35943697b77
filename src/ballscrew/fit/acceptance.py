r"""Acceptance of a measured preload drag torque, as makers check it.

What ``ballscrew acceptance`` computes. A maker sets a nut's preload by its
dynamic drag torque, measured turning the screw at a steady low speed, and
accepts it when the mean torque lies within the permitted deviation from the
reference torque for the screw's accuracy grade and torque level
(:data:`ballscrew.catalog_formulas.DRAG_TORQUE_TOLERANCE`). The reference is
given, or the catalogue rule :math:`T_p = 0.05(\tan\beta)^{-1/2}F_{pr}l/2\pi`
(:func:`ballscrew.catalog_formulas.preload_torque`), or a model's torque at
100 rpm without axial load.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np
import numpy.typing as npt

from ..chain import friction_torque
from ..design.catalog_formulas import drag_torque_tolerance, preload_torque
from ..errors import BallScrewInputError
from ..io.case import Case
from ..kinematics import rpm_to_rad_s

__all__ = ["Acceptance", "accept_drag_torque", "reference_torque", "run_acceptance"]

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

    def as_dict(self) -> dict[str, Any]:
        """The JSON document of ``ballscrew acceptance`` (the writer adds the version)."""
        return {"mean_torque_Nm": self.mean,
                "fluctuation_Nm": self.fluctuation, "readings": self.points,
                "reference_Nm": self.reference, "reference_from": self.reference_source,
                "grade": self.grade,
                "row": {"from_Nm": self.row[0], "to_Nm": self.row[1], "tolerance": self.row[2]},
                "accepted_from_Nm": self.low, "accepted_to_Nm": self.high,
                "accepted": self.accepted, "notes": list(self.notes),
                "source": _SOURCE}  # fmt: skip


def accept_drag_torque(
    torque: npt.ArrayLike,
    reference: float,
    *,
    grade: str = "C3",
    reference_source: str = "given",
) -> Acceptance:
    """Judge measured drag torques [N·m] (one value or a trace) against ``reference`` [N·m].

    The mean of the magnitudes must lie within ``reference`` times (1 ± the
    tolerance of its row). The fluctuation (the range of the readings) is
    reported, not judged: the permitted fluctuation of the grades is not held.

    Examples
    --------
    THK's worked example, BNFN4010-5 with 3 kN preload, reference 865 N·mm at C3:

    >>> a = accept_drag_torque([0.80, 0.92, 0.86], 0.865)
    >>> a.row, round(a.low, 4), round(a.high, 4), a.accepted
    ((0.6, 1.0, 0.3), 0.6055, 1.1245, True)
    """
    values = np.abs(np.atleast_1d(np.asarray(torque, dtype=float))).ravel()
    if values.size == 0 or not np.all(np.isfinite(values)):
        raise BallScrewInputError("torque", values.tolist(), "one or more finite torques")
    if not reference > 0.0:
        raise BallScrewInputError("reference", reference, "a positive reference torque")
    row = drag_torque_tolerance(reference, grade)
    mean = float(np.mean(values))
    low, high = reference * (1.0 - row[2]), reference * (1.0 + row[2])
    notes = []
    if values.size == 1:
        notes.append("one reading: its fluctuation is unknown (give the trace)")
    scale = mean / reference
    if scale > 100.0 or scale < 0.01:
        notes.append(f"the mean is {scale:.3g} times the reference: check the torque unit "
                     "(N*mm against N*m)")  # fmt: skip
    fluct = float(np.ptp(values)) if values.size > 1 else 0.0
    return Acceptance(mean, fluct, int(values.size), float(reference), reference_source,
                      grade.strip().upper(), row, low, high, bool(low <= mean <= high),
                      notes)  # fmt: skip


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
) -> Acceptance:
    """``ballscrew acceptance``: measured drag torques [N·m] of a case against its reference.

    The reference is found by :func:`reference_torque`, the verdict given by
    :func:`accept_drag_torque`.
    """
    value, source = reference_torque(case, reference, model)
    return accept_drag_torque(torque, value, grade=grade, reference_source=source)
