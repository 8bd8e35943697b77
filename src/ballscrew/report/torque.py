"""The torque table of a case: each model over every combination of its operating points.

What ``ballscrew torque`` and the web page's API compute: :func:`torque_run`
evaluates the case's models (with the case's model parameters) over the grid
of speeds, temperatures and loads and returns a :class:`TorqueRun`, whose rows,
CSV and JSON are those the command writes (:mod:`ballscrew.report.outputs`).
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from ..chain import FrictionResult, friction_torque
from ..design.ratings import Finding, plausibility, raise_errors
from ..errors import BallScrewValidityWarning, FloatArray
from ..io.case import WIPER_PARAMETERS, Case
from ..validity import statement
from .outputs import csv_text, json_text, provenance, result_rows

__all__ = [
    "TorqueRun",
    "operating_grid",
    "plausibility_record",
    "run_models",
    "torque_run",
    "warning_lines",
]


@dataclass(frozen=True)
class TorqueRun:
    """Each model's result over the case's grid of operating points."""

    case: Case
    results: dict[str, FrictionResult]
    findings: tuple[Finding, ...] = ()
    """The plausibility warnings (:func:`ballscrew.ratings.plausibility`); errors were raised."""

    @property
    def rows(self) -> list[dict[str, Any]]:
        """Long-format rows in user units (one per model and point)."""
        return result_rows(self.results)

    def provenance(self, command: Sequence[str] = ()) -> dict[str, Any]:
        """What the results were computed from (package, case, screw, lubricant, models)."""
        out = provenance(self.case, self.results, command)
        out["plausibility"] = plausibility_record(self.case, self.findings)
        return out

    def as_dict(self, command: Sequence[str] = ()) -> dict[str, Any]:
        """The rows and their provenance, as ``ballscrew torque --json`` writes them."""
        return {"provenance": self.provenance(command), "rows": self.rows}

    def json(self, command: Sequence[str] = ()) -> str:
        """:meth:`as_dict` as strict JSON text."""
        return json_text(self.rows, self.provenance(command))

    def csv(self, *, layout: str = "long", dialect: str = "comma") -> str:
        """The rows as CSV text (see :func:`ballscrew.report.outputs.csv_text`)."""
        return csv_text(self.rows, layout=layout, dialect=dialect)

    def warning_lines(self) -> list[str]:
        """The plausibility warnings and the validity issues as ``ballscrew torque`` prints them."""
        return [f"warning: {f}" for f in self.findings] + warning_lines(self.results)


def torque_run(
    case: Case,
    model_names: Sequence[str],
    speed: FloatArray | None = None,
    temperature: FloatArray | None = None,
    axial_load: FloatArray | None = None,
    on_model: Callable[[str], None] | None = None,
    *,
    load_field: str = "operation.axial_load",
) -> TorqueRun:
    """Every model of ``model_names`` over the grid; the case's own points where not given.

    The case is first checked against the screw's ratings and the contact
    pressure limit (:func:`ballscrew.ratings.plausibility`, the loads named
    ``load_field``): an error is raised before anything is computed, the
    warnings are kept in the run.
    """
    loads = case.axial_load if axial_load is None else axial_load
    found = raise_errors(
        plausibility(case.screw, case.load_ratings(), loads, load_field=load_field)
    )
    return TorqueRun(case, run_models(
        case, model_names,
        case.speed if speed is None else speed,
        case.temperature if temperature is None else temperature,
        loads,
        on_model=on_model,
    ), tuple(found))  # fmt: skip


def plausibility_record(case: Case, findings: Sequence[Finding]) -> dict[str, Any]:
    """The ratings a run was checked against and its plausibility warnings, for JSON."""
    r = case.load_ratings()
    return {
        "dynamic_load_rating_N": r.dynamic,
        "dynamic_load_rating_source": r.dynamic_source,
        "static_load_rating_N": r.static,
        "static_load_rating_source": r.static_source,
        "static_load_rating_estimated": r.static_estimated,
        "warnings": [str(f) for f in findings],
    }


def operating_grid(
    speed: FloatArray, temperature: FloatArray, axial_load: FloatArray
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """Every combination of the speeds, temperatures and loads, as three flat arrays.

    The speed varies slowest, then the temperature, then the load: the row
    order of the tables and files of ``ballscrew torque``.
    """
    w, t, f = (np.ravel(a) for a in np.meshgrid(speed, temperature, axial_load, indexing="ij"))
    return w, t, f


def run_models(
    case: Case,
    model_names: Sequence[str],
    speed: FloatArray,
    temperature: FloatArray,
    axial_load: FloatArray,
    on_model: Callable[[str], None] | None = None,
) -> dict[str, FrictionResult]:
    """Each model over the grid of the operating points, with the case's model parameters.

    The validity issues are kept in each result (:func:`warning_lines` tells
    them); a model without a wiper term, run on a case with ``[screw]
    wiper_drag``, has a note added that it leaves the drag out.
    ``on_model(name)`` is called after each model.
    """
    grid_w, grid_t, grid_f = operating_grid(speed, temperature, axial_load)
    results: dict[str, FrictionResult] = {}
    for name in model_names:
        params = case.parameters_for(name)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", BallScrewValidityWarning)
            results[name] = friction_torque(
                case.screw,
                case.lubricant,
                speed=grid_w,
                temperature=grid_t,
                axial_load=grid_f,
                model=name,
                **params,
            )
        if case.wiper_drag and name not in WIPER_PARAMETERS:
            results[name] = _wiper_left_out(results[name], case.wiper_drag)
        if on_model is not None:
            on_model(name)
    return results


def _wiper_left_out(result: FrictionResult, drag: float) -> FrictionResult:
    """The result with a note that its model has no term for the case's wiper drag."""
    note = statement(
        "wiper drag [N*m]",
        "left out, as the model has no wiper or seal term (the complete model adds it as its "
        "'seals' component)",
        "[screw] wiper_drag or --wiper-drag",
        value=drag,
        routine="a case's wiper drag reaches only the models with a seal term",
    )
    return replace(result, warnings=(*result.warnings, replace(note, model=result.model)))


def warning_lines(results: Mapping[str, FrictionResult]) -> list[str]:
    """Each model's validity issues as the lines ``ballscrew torque`` prints.

    One ``warning:`` line per issue; issues every ordinary ball screw has
    (``ValidityIssue.routine``) become one ``note:`` per quantity, naming the
    models, after the warnings; a routine statement (an issue with no range,
    such as a grease's note, :func:`ballscrew.validity.grease_note`) is told
    as it reads.
    """
    lines: list[str] = []
    routine: dict[str, list[Any]] = {}
    for r in results.values():
        for issue in r.warnings:
            if issue.routine:
                routine.setdefault(issue.quantity, []).append(issue)
            else:
                lines.append(f"warning: {issue}")
    for quantity, found in routine.items():
        worst = max(found, key=lambda i: i.excess)
        names = ", ".join(i.model for i in found)
        if math.isnan(worst.low) and math.isnan(worst.high):  # a statement (no range)
            text = str(replace(worst, model=""))
            lines.append(f"note: {text} (for {names}; {worst.routine})")
            continue
        lines.append(
            f"note: {quantity} up to {worst.value:.3g}, outside {worst.low:.3g} to "
            f"{worst.high:.3g} ({worst.applies_to}) for {names}: usual for ball screws, "
            f"{worst.routine}"
        )
    return lines
