"""Documents and files.

Figures (:mod:`.plotting`), Markdown and HTML (:mod:`.document`), result tables with
their provenance (:mod:`.outputs`), and one module per report: the study
(:mod:`.study`), axis energy (:mod:`.energy`), the axis check (:mod:`.check`), a
fit (:mod:`.fit`), the scorecard (:mod:`.validation`), the torque table
(:mod:`.torque`).

The entry points, each formatting and writing a result computed in its wing, are
loaded on first use (the plotting library is not imported by a command that
writes no figure).
"""

from __future__ import annotations

import importlib
from typing import Any

__all__ = [
    "TorqueRun",
    "result_json",
    "warning_lines",
    "write_check_report",
    "write_energy_report",
    "write_fit_report",
    "write_report",
    "write_scorecard",
]

_WHERE = {
    "TorqueRun": "torque",
    "result_json": "outputs",
    "warning_lines": "torque",
    "write_check_report": "check",
    "write_energy_report": "energy",
    "write_fit_report": "fit",
    "write_report": "study",
    "write_scorecard": "validation",
}


def __getattr__(name: str) -> Any:
    if name not in _WHERE:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    return getattr(importlib.import_module(f".{_WHERE[name]}", __name__), name)


def __dir__() -> list[str]:
    return sorted([*globals(), *__all__])
