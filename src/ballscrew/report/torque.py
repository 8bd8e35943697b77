"""The torque table of a case as ``ballscrew torque`` and the web page write it.

:func:`ballscrew.chain.torque_table` computes each model over the grid of
speeds, temperatures and loads; a :class:`TorqueRun` holds that table with its
case and gives its rows, CSV and JSON (:mod:`ballscrew.report.outputs`) and the
warning lines the command prints (:func:`warning_lines`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace
from typing import Any

from ..chain import FrictionResult, TorqueTable
from ..design.ratings import Finding
from ..io.case import Case
from .outputs import csv_text, json_text, provenance, result_rows

__all__ = ["TorqueRun", "plausibility_record", "warning_lines"]


@dataclass(frozen=True)
class TorqueRun:
    """A case's torque table (:func:`ballscrew.chain.torque_table`), as files and lines."""

    case: Case
    table: TorqueTable
    readings: tuple[str, ...] = ()
    """How the command's options were read where a text could be meant two ways (a feed
    given as ``--speed`` read as the screw speed at the case's lead)."""

    @property
    def results(self) -> dict[str, FrictionResult]:
        """Each model's result over the grid."""
        return self.table.results

    @property
    def findings(self) -> tuple[Finding, ...]:
        """The plausibility warnings (:func:`ballscrew.design.ratings.plausibility`)."""
        return self.table.findings

    @property
    def rows(self) -> list[dict[str, Any]]:
        """Long-format rows in user units (one per model and point)."""
        return result_rows(self.results)

    def provenance(self, command: Sequence[str] = ()) -> dict[str, Any]:
        """What the results were computed from (package, case, screw, lubricant, models)."""
        out = provenance(self.case, self.results, command)
        out["readings"] = list(self.readings)
        out["plausibility"] = plausibility_record(self.case, self.findings)
        return out

    def as_dict(self) -> dict[str, Any]:
        """The rows and their provenance (no command: :meth:`json` adds the one given)."""
        return {"provenance": self.provenance(), "rows": self.rows}

    def json(self, command: Sequence[str] = ()) -> str:
        """:meth:`as_dict` with the command line, as strict JSON text."""
        return json_text(self.rows, self.provenance(command))

    def csv(self, *, layout: str = "long", dialect: str = "comma") -> str:
        """The rows as CSV text (see :func:`ballscrew.report.outputs.csv_text`)."""
        return csv_text(self.rows, layout=layout, dialect=dialect)

    def warning_lines(self, *, verbose: bool = False) -> list[str]:
        """The plausibility warnings and the validity issues as ``ballscrew torque`` prints them."""
        found = [f"warning: {f}" for f in self.findings]
        return found + warning_lines(self.results, verbose=verbose)


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


def warning_lines(results: Mapping[str, FrictionResult], *, verbose: bool = False) -> list[str]:
    """Each model's validity issues as the lines ``ballscrew torque`` prints.

    One ``warning:`` line per issue. Issues every ordinary ball screw has
    (``ValidityIssue.routine``) are notes: by default one short line per set of
    formulas they leave, naming the models and the values (the ranges and the
    reason with ``verbose``, as ``ballscrew --verbose`` prints them); a routine
    statement (an issue with no range, such as a grease's note,
    :func:`ballscrew.validity.grease_note`) is told as it reads.
    """
    lines: list[str] = []
    routine: dict[str, list[Any]] = {}
    for r in results.values():
        for issue in r.warnings:
            if issue.routine:
                routine.setdefault(issue.quantity, []).append(issue)
            else:
                lines.append(f"warning: {issue}")
    short: dict[tuple[str, str], list[str]] = {}  # (formulas, models) -> the values
    for quantity, found in routine.items():
        worst = max(found, key=lambda i: i.excess)
        names = ", ".join(i.model for i in found)
        if math.isnan(worst.low) and math.isnan(worst.high):  # a statement (no range)
            text = str(replace(worst, model=""))
            lines.append(f"note: {text} (for {names}; {worst.routine})")
            continue
        if verbose:
            lines.append(
                f"note: {quantity} up to {worst.value:.3g}, outside {worst.low:.3g} to "
                f"{worst.high:.3g} ({worst.applies_to}) for {names}: usual for ball screws, "
                f"{worst.routine}"
            )
            continue
        symbol = quantity.rsplit(" ", 1)[-1] if len(quantity.rsplit(" ", 1)[-1]) <= 3 else quantity
        short.setdefault((worst.applies_to, names), []).append(f"{symbol} {worst.value:.3g}")
    for (formulas, names), values in short.items():
        verb = "extrapolate" if ", " in names else "extrapolates"  # one model or several
        lines.append(f"note: {names} {verb} {formulas} ({', '.join(values)}), as for "
                     "most screws (ballscrew --verbose ... says why)")  # fmt: skip
    return lines
