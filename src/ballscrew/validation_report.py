"""The validation scorecard as files: validation.csv, report.md, report.html and a figure.

:func:`write_scorecard` writes into one folder (atomically, byte-reproducible):

* ``validation.csv``: one row per model and case, with the columns case, kind,
  source, reference, reference_low, reference_high, unit, model, predicted,
  ratio, within, training;
* ``summary.csv``: per model, the share of cases inside their band, the median
  |log10(predicted/reference)|, the share by kind and the trends met;
* ``predicted_vs_reference.png`` and ``.svg``: predicted against reference
  torque on log axes, one marker per model, with the ±30 % band;
* ``report.md`` and ``report.html`` (self-contained).
"""

from __future__ import annotations

import csv
import io
import math
from pathlib import Path

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from . import __version__
from .document import Block, html_page, markdown
from .files import atomic_write
from .plotting import figure_bytes
from .validation import ModelScore, ScoreRow, summarise

__all__ = ["summary_csv", "summary_table", "write_scorecard"]


def _g(x: float, digits: int = 4) -> str:
    return "nan" if not math.isfinite(x) else f"{x:.{digits}g}"


def _rows_csv(rows: list[ScoreRow]) -> bytes:
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(
        [
            "case", "kind", "source", "reference", "reference_low", "reference_high", "unit",
            "model", "predicted", "ratio", "within", "training",
        ]
    )  # fmt: skip
    for r in rows:
        w.writerow(
            [
                r.case, r.kind, r.source, _g(r.reference, 6), _g(r.low, 6), _g(r.high, 6), r.unit,
                r.model, _g(r.predicted, 6), _g(r.ratio, 4), "yes" if r.within else "no",
                "yes" if r.training else "no",
            ]
        )  # fmt: skip
    return out.getvalue().encode("utf-8")


def summary_table(scores: list[ModelScore]) -> tuple[list[str], list[list[str]]]:
    """Header and rows of the per-model summary (as printed by ``ballscrew validate``)."""
    kinds = sorted({k for s in scores for k in s.by_kind})
    header = ["model", "inside band", "median |log10 ratio|"]
    header += [f"{k} inside" for k in kinds] + ["trends met"]
    rows = []
    for s in scores:
        row = [s.model, f"{s.share_within:.0%} ({s.within} of {s.cases})",
               f"{s.median_abs_log10:.3f}"]  # fmt: skip
        for k in kinds:
            n_in, n = s.by_kind.get(k, (0, 0))
            row.append(f"{n_in}/{n}")
        row.append(f"{s.trends_within}/{s.trends}")
        rows.append(row)
    return header, rows


def summary_csv(scores: list[ModelScore]) -> bytes:
    """The per-model summary as CSV bytes."""
    header, rows = summary_table(scores)
    out = io.StringIO()
    w = csv.writer(out, lineterminator="\n")
    w.writerow(header)
    w.writerows(rows)
    return out.getvalue().encode("utf-8")


def _figure(rows: list[ScoreRow]) -> Figure:
    fig = Figure(figsize=(6.4, 5.6))
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    torque_rows = [r for r in rows if r.kind != "trend" and r.predicted > 0]
    markers = "osD^v<>xP*"
    refs = [r.reference for r in torque_rows] or [1e-2, 1.0]
    lo, hi = min(refs) / 3, max(refs) * 3
    for i, name in enumerate(dict.fromkeys(r.model for r in torque_rows)):
        mine = [r for r in torque_rows if r.model == name]
        ax.scatter(
            [r.reference for r in mine],
            [r.predicted for r in mine],
            s=14,
            marker=markers[i % len(markers)],
            alpha=0.7,
            label=name,
        )
        lo = min(lo, *(r.predicted for r in mine))
        hi = max(hi, *(r.predicted for r in mine))
    line = [lo, hi]
    ax.plot(line, line, color="k", lw=1.0, label="predicted = reference")
    ax.fill_between(line, [0.7 * v for v in line], [1.3 * v for v in line], color="0.8",
                    alpha=0.6, label="±30 %")  # fmt: skip
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("reference torque [N·m]")
    ax.set_ylabel("predicted torque [N·m]")
    ax.set_title("Every model against every reference case")
    ax.legend(fontsize=7, loc="upper left")
    return fig


def _document(rows: list[ScoreRow], scores: list[ModelScore]) -> list[Block]:
    header, table = summary_table(scores)
    trends = [r for r in rows if r.kind == "trend"]
    kinds = sorted({r.kind for r in rows if r.kind != "trend"})
    cases = {r.case: r for r in rows if r.kind != "trend"}
    blocks = [
        Block("h1", "Validation scorecard"),
        Block(
            "p",
            f"ballscrew {__version__}: every registered model on {len(cases)} reference cases "
            f"({', '.join(kinds)}) and {len({r.case for r in trends})} trend checks. A case "
            "counts as inside when the prediction lies in its band (catalogue drag torques "
            "±30 %, Jungnickel's law within a factor 1.5). The rows marked training are the "
            "only ones the complete model's ball-train constant was fitted on.",
        ),
        Block("h2", "Summary"),
        Block("table", (header, table)),
        Block("img", ("predicted_vs_reference", "Predicted against reference torque.")),
        Block("h2", "Trends"),
        Block(
            "table",
            (
                ["trend", "band", *dict.fromkeys(r.model for r in trends)],
                [
                    [name, f"{_g(first.low, 3)} to {_g(first.high, 3)}"]
                    + [
                        f"{_g(r.predicted, 3)}{'' if r.within else ' (outside)'}"
                        for r in trends
                        if r.case == name
                    ]
                    for name, first in {r.case: r for r in trends}.items()
                ],
            ),
        ),
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
    fig = _figure(rows)
    png = figure_bytes(fig, "png")
    blocks = _document(rows, scores)
    files = {
        "validation.csv": _rows_csv(rows),
        "summary.csv": summary_csv(scores),
        "predicted_vs_reference.png": png,
        "predicted_vs_reference.svg": figure_bytes(fig, "svg"),
        "report.md": markdown(blocks).encode("utf-8"),
        "report.html": html_page(blocks, "ballscrew validation scorecard", {
            "predicted_vs_reference": png
        }).encode("utf-8"),
    }  # fmt: skip
    written = []
    for name, data in files.items():
        atomic_write(folder / name, data)
        written.append(folder / name)
    return written
