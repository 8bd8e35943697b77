"""The report of ``ballscrew identify``: measured against predicted, the fit, the baselines."""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from ..io.files import atomic_write
from ..io.numbers import text as num
from .document import Block, write_data, write_pages
from .outputs import csv_bytes
from .plotting import new_figure, write_figures

if TYPE_CHECKING:
    from matplotlib.figure import Figure as MplFigure

    from ..fit.identify import AxisFit, IdentifyResult, Score

__all__ = ["parameter_rows", "score_rows", "write_identify_report"]

_UNITS = {"current": "A", "torque": "N·m", "power": "W"}


def parameter_rows(fit: AxisFit) -> list[list[str]]:
    """One row per parameter: name, value, 95 % interval, unit, fitted or held."""
    from ..fit.identify import PARAMETERS

    rows = []
    for name, p in fit.parameters.items():
        if not np.isfinite(p.value):
            continue
        interval = (f"{num(p.low)} to {num(p.high)}" if p.fitted and p.identifiable else
                    f"not identifiable with {', '.join(p.confounded_with)}" if p.fitted
                    else "held")  # fmt: skip
        rows.append([PARAMETERS[name][1], num(p.value), interval, p.unit or "-"])
    return rows


def score_rows(model: Score, baselines: dict[str, Score]) -> list[list[str]]:
    """The model's scores beside the baselines': R², NRMSE, energy error."""
    rows = []
    for name, s in (("calibrated physics", model), *baselines.items()):
        rows.append([name, f"{s.r2:.3f}", f"{s.nrmse:.3f}", f"{100 * s.energy_error:+.1f} %"])
    return rows


SCORE_HEADER = ["model", "R²", "NRMSE", "energy error"]
PARAMETER_HEADER = ["parameter", "value", "95 % interval", "unit"]


def _figure(time: np.ndarray, measured: np.ndarray, predicted: np.ndarray,
            baselines: dict[str, np.ndarray], title: str, unit: str) -> MplFigure:  # fmt: skip
    fig = new_figure(8.0, 3.6, layout="constrained")
    ax = fig.add_subplot()
    ax.plot(time, measured, color="0.6", lw=0.8, label="measured")
    ax.plot(time, predicted, color="C0", lw=1.2, label="calibrated physics")
    for k, (name, values) in enumerate(baselines.items()):
        ax.plot(time, values, lw=0.8, ls="--", color=f"C{k + 1}", label=name)
    ax.set_xlabel("time [s]")
    ax.set_ylabel(f"signal [{unit}]")
    ax.set_title(title)
    ax.legend(fontsize=7, loc="upper right")
    return fig


def write_identify_report(
    out: str | Path, result: IdentifyResult, calibrated: str | None = None
) -> list[Path]:
    """Write the report of ``result`` (and the calibrated machine file) into ``out``."""
    folder = Path(out)
    blocks = [Block("h1", f"Axes identified from {result.source}")]
    figures: dict[str, MplFigure] = {}
    data: dict[str, bytes] = {}
    for letter, fit in result.fits.items():
        unit = _UNITS[fit.kind]
        blocks.append(Block("h2", f"Axis {letter} ({fit.kind})"))
        blocks.append(Block("table", (PARAMETER_HEADER, parameter_rows(fit))))
        blocks.append(Block("table", (SCORE_HEADER, score_rows(fit.score, fit.baselines))))
        if fit.notes:
            blocks.append(Block("ul", list(fit.notes)))
        key = f"fit_{letter}"
        baselines = {n: v for n, v in fit.baseline_predictions.items()}
        figures[key] = _figure(fit.time, fit.measured, fit.predicted, baselines,
                               f"{letter}: measured and predicted", unit)  # fmt: skip
        blocks.append(Block("img", (key, f"Axis {letter}: measured {fit.kind} and predictions")))
        data[key] = csv_bytes(
            ["time [s]", f"measured [{unit}]", f"predicted [{unit}]",
             *(f"{n} [{unit}]" for n in baselines)],
            [[t, m, p, *(v[k] for v in baselines.values())] for k, (t, m, p) in
             enumerate(zip(fit.time, fit.measured, fit.predicted, strict=True))],
        )  # fmt: skip
        corr = [[name, *(f"{c:+.2f}" for c in row)]
                for name, row in zip(fit.free, fit.correlation, strict=True)]  # fmt: skip
        blocks.append(Block("p", "Correlations of the fitted parameters (bootstrap):"))
        blocks.append(Block("table", (["", *fit.free], corr)))
    if result.validation and result.validation_time is not None:
        blocks.append(Block("h2", f"Prediction of {result.validation_source}"))
        for letter, (score, base, predicted) in result.validation.items():
            blocks.append(Block("p", f"Axis {letter}:"))
            blocks.append(Block("table", (SCORE_HEADER, score_rows(score, base))))
            key = f"validate_{letter}"
            figures[key] = _figure(result.validation_time, result.validation_measured[letter],
                                   predicted, {}, f"{letter}: predicted, not fitted",
                                   _UNITS[result.fits[letter].kind])  # fmt: skip
            blocks.append(Block("img", (key, f"Axis {letter}: the second trace and its "
                                            "prediction")))  # fmt: skip
            data[key] = csv_bytes(
                ["time [s]", "measured", "predicted"],
                [[t, m, p] for t, m, p in zip(result.validation_time,
                                              result.validation_measured[letter], predicted,
                                              strict=True)],
            )  # fmt: skip
    if result.notes:
        blocks.append(Block("ul", list(result.notes)))
    written, images = write_figures(folder, figures)
    written += write_data(folder, data.items())
    if calibrated is not None:
        atomic_write(folder / "calibrated.toml", calibrated.encode("utf-8"))
        written.append(folder / "calibrated.toml")
        blocks.append(Block("p", "The calibrated machine file: calibrated.toml."))
    return written + write_pages(folder, blocks, f"Identified: {result.source}", images)
