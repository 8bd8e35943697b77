"""The files of ``ballscrew fit --out DIR``: fitted case, residuals, plot, report.

* ``fitted-case.toml``: the case with the fitted values written in;
* ``fit.json``: estimates, intervals, correlations, warnings;
* ``data/fit.csv``: every point, measured and fitted, with its residual;
* ``figures/fit.png``/``.svg``: measured and fitted torque against speed,
  and the residuals;
* ``report.md`` and ``report.html``.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.figure import Figure as MplFigure

from ..fit.calibration import FitResult, fitted_case_toml
from ..io.case import Case
from ..io.files import atomic_write
from ..kinematics import rad_s_to_rpm
from .document import Block, html_page, markdown
from .outputs import csv_text
from .plotting import new_figure, write_figures

__all__ = ["write_fit_report"]


def _figure(result: FitResult) -> MplFigure:
    fig = new_figure(7.0, 6.0)
    top, bottom = fig.subplots(2, 1, sharex=True)
    rpm = rad_s_to_rpm(np.abs(result.speed))
    order = np.argsort(rpm)
    outlier = np.zeros(rpm.size, dtype=bool)
    outlier[list(result.outliers)] = True
    for temp in np.unique(result.temperature):
        for load in np.unique(result.axial_load):
            sel = order[(result.temperature[order] == temp) & (result.axial_load[order] == load)]
            label = f"{temp:g} °C, {load:g} N"
            (line,) = top.plot(rpm[sel], result.fitted[sel], label=f"fitted, {label}")
            keep = sel[~outlier[sel]]
            top.plot(rpm[keep], result.measured[keep], "o", ms=3, color=line.get_color())
            bottom.plot(rpm[keep], result.residuals[keep], "o", ms=3, color=line.get_color())
    if outlier.any():
        top.plot(
            rpm[outlier], result.measured[outlier], "x", color="red", label="outliers (left out)"
        )
        bottom.plot(rpm[outlier], result.residuals[outlier], "x", color="red")
    top.set_ylabel("friction torque [N·m]")
    top.legend(fontsize=7)
    bottom.axhline(0.0, color="black", lw=0.8)
    bottom.set_xlabel("screw speed [rpm]")
    bottom.set_ylabel("fitted − measured [N·m]")
    if rpm.min() > 0 and rpm.max() / rpm.min() > 50:
        bottom.set_xscale("log")
    fig.tight_layout()
    return fig


def write_fit_report(
    out: str | Path, case: Case, result: FitResult, payload: dict[str, Any]
) -> list[Path]:
    """Write the fit's files into ``out``; returns the paths written."""
    folder = Path(out)
    folder.mkdir(parents=True, exist_ok=True)
    written, images = write_figures(folder, {"fit": _figure(result)})
    rows = [
        {"speed [rpm]": float(rad_s_to_rpm(w)), "temperature [degC]": float(t),
         "axial load [N]": float(f), "measured torque [N*m]": float(m),
         "fitted torque [N*m]": float(p), "residual [N*m]": float(p - m),
         "outlier": "yes" if i in result.outliers else ""}
        for i, (w, t, f, m, p) in enumerate(zip(result.speed, result.temperature,
                                                result.axial_load, result.measured,
                                                result.fitted, strict=True))
    ]  # fmt: skip
    (folder / "data").mkdir(exist_ok=True)
    files = {
        folder / "data" / "fit.csv": csv_text(rows),
        folder / "fitted-case.toml": fitted_case_toml(case.text, result),
        folder / "fit.json": json.dumps(payload, indent=1, ensure_ascii=False) + "\n",
    }
    header = ["parameter", "start", "fitted", "95 % interval", "unit"]
    table = [
        [name, f"{e.start:.4g}", f"{e.value:.4g}",
         (f"{e.low:.4g} to {e.high:.4g}" + ("" if result.reliable else " (unreliable)"))
         if e.low is not None else "not identified", e.unit]
        for name, e in result.estimates.items()
    ]  # fmt: skip
    names = list(result.correlation_names)
    blocks = [
        Block("h1", f"Calibration of {result.model}: {case.title}"),
        Block(
            "p",
            f"{result.measured.size} measured points; RMS residual "
            f"{result.rms_residual:.4g} N·m. Intervals are the linearised 95 % "
            "intervals of the least-squares estimate."
            + (
                ""
                if result.reliable
                else " The fit is absurd (see the warnings): its intervals are unreliable."
            ),
        ),
        Block("table", (header, table)),
        Block("h2", "Correlation of the estimates"),
        Block(
            "table",
            (
                ["", *names],
                [
                    [a, *(f"{result.correlation[i, j]:+.3f}" for j in range(len(names)))]
                    for i, a in enumerate(names)
                ],
            ),
        ),
        Block("img", ("fit", "Measured and fitted torque, and the residuals")),
        Block("h2", "Warnings"),
        Block("ul", list(result.warnings) or ["none"]),
    ]
    files[folder / "report.md"] = markdown(blocks)
    files[folder / "report.html"] = html_page(blocks, f"Calibration: {case.title}", images)
    for path, text in files.items():
        atomic_write(path, text.encode("utf-8"))
        written.append(path)
    return written
