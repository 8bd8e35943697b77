"""The validation scorecard as files: the rows, the summary, the figures and the report.

:func:`write_scorecard` writes into one folder (atomically, byte-reproducible):

* ``validation.csv``: one row per model and case (reference cases, Jungnickel
  exponents, no-trend slopes, trends), with the columns case, kind, nut,
  source, reference, reference_low, reference_high, unit, model, predicted,
  interval_low, interval_high, ratio, within, training;
* ``summary.csv``: per model, the count inside its band of each group
  (:data:`ballscrew.study.validation.SCORE_GROUPS`) and the median
  ``|log10(predicted/reference)|``;
* ``figures/predicted_vs_reference.png`` and ``.svg``: predicted against
  reference torque on log axes, one marker per model, with the makers' band;
* ``figures/residuals.png`` and ``.svg``: each model's ratio to the catalogue
  rule against the lead angle, the diameter and the preload, with its fitted
  slope (the no-trend check);
* ``data/predicted_vs_reference.csv`` and ``data/residuals.csv``: what the
  figures plot;
* ``report.md`` and ``report.html`` (self-contained).
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.ticker import FormatStrFormatter, LogLocator, NullFormatter

from .._version import __version__
from ..io.files import atomic_write
from ..study.validation import (
    ACCEPTANCE_BANDS,
    SCORE_GROUPS,
    SLOPE_LIMIT,
    SLOPE_VARIABLES,
    ModelScore,
    ScoreRow,
    load_cases,
    summarise,
)
from .document import Block, html_page, markdown
from .outputs import csv_bytes
from .plotting import figure_bytes

__all__ = ["summary_csv", "summary_table", "write_scorecard"]

_MARKERS = "osD^v<>xP*"
_LINES = ("-", "--", "-.", ":", (0, (5, 1)), (0, (3, 1, 1, 1, 1, 1)))


def _g(x: float, digits: int = 4) -> str:
    """A value to the CSV's 4 significant digits (the row's unit is in its own column)."""
    return "nan" if not math.isfinite(x) else f"{x:.{digits}g}"


def _rows_csv(rows: list[ScoreRow]) -> bytes:
    header = [
        "case", "kind", "nut", "source", "reference", "reference_low", "reference_high", "unit",
        "model", "predicted", "interval_low", "interval_high", "ratio", "within", "training",
    ]  # fmt: skip
    return csv_bytes(
        header,
        [
            [
                r.case, r.kind, r.nut, r.source, _g(r.reference), _g(r.low),
                _g(r.high), r.unit, r.model, _g(r.predicted), _g(r.interval[0], 4),
                _g(r.interval[1], 4), _g(r.ratio, 4), "yes" if r.within else "no",
                "yes" if r.training else "no",
            ]
            for r in rows
        ],
    )  # fmt: skip


def summary_table(scores: list[ModelScore]) -> tuple[list[str], list[list[str]]]:
    """Header and rows of the per-model summary (as printed by ``ballscrew validate``)."""
    labels = [label for label, _ in SCORE_GROUPS if any(label in s.groups for s in scores)]
    header = ["model", *labels, "median |log10 ratio|"]
    rows = []
    for s in scores:
        row = [s.model]
        for label in labels:
            n_in, n = s.groups.get(label, (0, 0))
            row.append(f"{n_in}/{n}")
        row.append(f"{s.median_abs_log10:.3f}")
        rows.append(row)
    return header, rows


def summary_csv(scores: list[ModelScore]) -> bytes:
    """The per-model summary as CSV bytes."""
    header, rows = summary_table(scores)
    return csv_bytes(header, rows)


def _models(rows: list[ScoreRow]) -> list[str]:
    return list(dict.fromkeys(r.model for r in rows))


def _band_edges(lo: float, hi: float) -> tuple[list[float], list[float], list[float]]:
    """Reference torques and the makers' band below and above them, as steps."""
    x, low, high = [], [], []
    start = lo
    for upper, tol in ACCEPTANCE_BANDS:
        end = min(max(upper, lo), hi)
        if end > start:
            x += [start, end]
            low += [start * (1 - tol), end * (1 - tol)]
            high += [start * (1 + tol), end * (1 + tol)]
            start = end
    if hi > start:
        tol = ACCEPTANCE_BANDS[-1][1]
        x += [start, hi]
        low += [start * (1 - tol), hi * (1 - tol)]
        high += [start * (1 + tol), hi * (1 + tol)]
    return x, low, high


def _predicted_figure(rows: list[ScoreRow]) -> tuple[Figure, bytes]:
    fig = Figure(figsize=(6.4, 5.6), layout="constrained")
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    torque_rows = [r for r in rows if r.kind in ("catalog", "jungnickel") and r.predicted > 0]
    refs = [r.reference for r in torque_rows] or [1e-2, 1.0]
    lo, hi = min(refs) / 3, max(refs) * 3
    for i, name in enumerate(_models(torque_rows)):
        mine = [r for r in torque_rows if r.model == name]
        ax.scatter([r.reference for r in mine], [r.predicted for r in mine], s=14,
                   marker=_MARKERS[i % len(_MARKERS)], alpha=0.7, label=name)  # fmt: skip
        lo = min(lo, *(r.predicted for r in mine))
        hi = max(hi, *(r.predicted for r in mine))
    ax.plot([lo, hi], [lo, hi], color="k", lw=1.0, label="predicted = reference")
    x, low, high = _band_edges(lo, hi)
    ax.fill_between(x, low, high, color="0.85", zorder=0,
                    label="makers' band of the catalogue torque")  # fmt: skip
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("reference torque [N·m]")
    ax.set_ylabel("predicted torque [N·m]")
    ax.set_title("Every model against every reference case")
    ax.legend(fontsize=7, loc="upper left")
    data = csv_bytes(
        ["model", "case", "kind", "reference [N*m]", "predicted [N*m]"],
        [[r.model, r.case, r.kind, r.reference, r.predicted] for r in torque_rows],
    )
    return fig, data


_AXES = {
    "ln tan(lead angle)": ("tan(lead angle) [-]", 1.0),
    "ln d0": ("pitch diameter d0 [mm]", 1e3),
    "ln preload": ("preload [N]", 1.0),
}
"""Axis label and scale (from SI) of each no-trend variable, plotted on a log axis."""


def _residual_figure(rows: list[ScoreRow]) -> tuple[Figure, bytes]:
    """Ratio to the catalogue rule against each no-trend variable, double nuts."""
    screws = {c.case: c.screw for c in load_cases() if c.kind == "catalog"}
    chosen = [r for r in rows if r.kind == "catalog" and r.nut == "double" and r.ratio > 0
              and r.case in screws]  # fmt: skip
    fig = Figure(figsize=(10.0, 3.9), layout="constrained")
    FigureCanvasAgg(fig)
    axes = fig.subplots(1, len(SLOPE_VARIABLES), sharey=True)
    slopes = {(r.model, r.case): r for r in rows if r.kind == "no-trend" and r.nut == "double"}
    table = []
    for k, (name, read) in enumerate(SLOPE_VARIABLES):
        ax = axes[k]
        label, scale = _AXES.get(name, (name, 1.0))
        for i, model in enumerate(_models(chosen)):
            mine = [r for r in chosen if r.model == model]
            x = np.array([read(screws[r.case]) for r in mine])  # the natural log of the value
            y = np.array([r.ratio for r in mine])
            ax.scatter(scale * np.exp(x), y, s=12, marker=_MARKERS[i % len(_MARKERS)],
                       alpha=0.7, label=model)  # fmt: skip
            slope = slopes.get((model, f"no trend: ln(model/rule) on {name}, double nuts"))
            if slope is not None and math.isfinite(slope.predicted) and len(x) > 1:
                # The partial slope, drawn through the geometric mean of the points.
                xs = np.array([x.min(), x.max()])
                centre = float(np.mean(np.log(y)))
                ax.plot(scale * np.exp(xs), np.exp(centre + slope.predicted * (xs - x.mean())),
                        color="0.3", lw=1.0, ls=_LINES[i % len(_LINES)])  # fmt: skip
            table += [[model, label, _g(scale * math.exp(a)), _g(float(b))]
                      for a, b in zip(x, y, strict=True)]  # fmt: skip
        ax.axhline(1.0, color="k", lw=0.8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        for axis in (ax.xaxis, ax.yaxis):  # plain numbers at 1, 2, 5 x 10^n
            axis.set_major_locator(LogLocator(base=10.0, subs=(1.0, 2.0, 5.0)))
            axis.set_major_formatter(FormatStrFormatter("%g"))
            axis.set_minor_formatter(NullFormatter())
        ax.set_xlabel(label)
        ax.grid(True, which="both", alpha=0.3)
    axes[0].set_ylabel("model / catalogue rule [-]")
    axes[-1].legend(fontsize=7, loc="best")
    fig.suptitle("Double nuts against the catalogue rule (lines: the partial slopes)")
    data = csv_bytes(["model", "variable", "value", "model/rule [-]"], table)
    return fig, data


def _slope_table(rows: list[ScoreRow]) -> tuple[list[str], list[list[str]]]:
    chosen = [r for r in rows if r.kind == "no-trend"]
    names = list(dict.fromkeys(r.case.removeprefix("no trend: ") for r in chosen))
    header = ["slope of ln(model/rule)", *_models(chosen)]
    body = []
    for name in names:
        row = [name]
        for model in _models(chosen):
            r = next(x for x in chosen if x.model == model and x.case == f"no trend: {name}")
            mark = "" if r.within else " (fails)"
            row.append(f"{_g(r.predicted, 2)} [{_g(r.interval[0], 2)}, {_g(r.interval[1], 2)}]"
                       f"{mark}")  # fmt: skip
        body.append(row)
    return header, body


def _trend_table(rows: list[ScoreRow]) -> tuple[list[str], list[list[str]]]:
    trends = [r for r in rows if r.kind in ("trend", "reported")]  # reported: not judged
    return (
        ["trend", "band", *_models(trends)],
        [
            [
                name,
                "(reported)"
                if first.kind == "reported"
                else f"{_g(first.low, 3)} to {_g(first.high, 3)}",
            ]
            + [
                f"{_g(r.predicted, 3)}{'' if r.within else ' (outside)'}"
                for r in trends
                if r.case == name
            ]
            for name, first in {r.case: r for r in trends}.items()
        ],
    )


def _document(rows: list[ScoreRow], scores: list[ModelScore]) -> list[Block]:
    header, table = summary_table(scores)
    trends = [r for r in rows if r.kind == "trend"]
    cases = {r.case for r in rows if r.kind in ("catalog", "jungnickel")}
    below = sum(1 for r in rows if r.kind == "catalog" and r.reference < 0.2) // max(
        1, len(_models(rows))
    )
    blocks = [
        Block("h1", "Validation scorecard"),
        Block(
            "p",
            f"ballscrew {__version__}: every registered model on {len(cases)} reference cases "
            "(catalogue drag torques of double and 4-point nuts, Jungnickel's measured-loss "
            "law), the exponents of that law per screw, the trends of the model's error "
            "against the catalogue rule, and the trends of the reference screw. A catalogue "
            "case counts as inside when the prediction lies within the makers' own tolerance "
            "of the drag torque at its level (grade C3: ±45 % at 0.2 to 0.4 N·m down to ±20 % "
            f"at 2.5 to 6.3 N·m; {below} cases lie below the table's 0.2 N·m and take its "
            "±45 %); Jungnickel's level within a factor 2, its exponents within a factor 1.5 "
            "of 0.5. The rows marked training are the only ones the complete model's "
            "ball-train constant was fitted on; the summary gives them and the test rows apart.",
        ),
        Block("h2", "Summary"),
        Block("table", (header, table)),
        Block("img", ("predicted_vs_reference", "Predicted against reference torque.")),
        Block("h2", "No trend against the catalogue rule"),
        Block(
            "p",
            "Partial slopes of ln(model/rule) on the three variables at once (least squares "
            "over the catalogue cases of one nut kind), with 95 % intervals; a slope of 0.5 "
            "means the model's error grows as the square root of that variable. Pass: "
            f"|slope| < {SLOPE_LIMIT:g}.",
        ),
        Block("table", _slope_table(rows)),
        Block("img", ("residuals", "Each model's ratio to the catalogue rule, double nuts.")),
        Block("h2", "Trends"),
        Block("table", _trend_table(rows)),
        Block("p", f"Trend targets: {trends[0].source}." if trends else ""),
        Block("h2", "Sources"),
        Block("ul", sorted({r.source.split("; geometry:")[0] for r in rows})),
        Block(
            "p",
            "Every case, its geometry source and each model's prediction: validation.csv.",
        ),
    ]
    return blocks


def write_scorecard(rows: list[ScoreRow], out: str | Path) -> list[Path]:
    """Write the scorecard of ``rows`` into the folder ``out``; returns the files written."""
    folder = Path(out)
    scores = summarise(rows)
    figures = {
        "predicted_vs_reference": _predicted_figure(rows),
        "residuals": _residual_figure(rows),
    }
    blocks = _document(rows, scores)
    files: dict[str, bytes] = {
        "validation.csv": _rows_csv(rows),
        "summary.csv": summary_csv(scores),
    }
    pngs = {}
    for key, (fig, data) in figures.items():
        pngs[key] = figure_bytes(fig, "png")
        files[f"figures/{key}.png"] = pngs[key]
        files[f"figures/{key}.svg"] = figure_bytes(fig, "svg")
        files[f"data/{key}.csv"] = data
    files["report.md"] = markdown(blocks).encode("utf-8")
    files["report.html"] = html_page(blocks, "ballscrew validation scorecard", pngs).encode("utf-8")
    written = []
    for name, data in files.items():
        atomic_write(folder / name, data)
        written.append(folder / name)
    return written
