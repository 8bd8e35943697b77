"""The report of ``ballscrew select --out DIR``: the front, its projections, every candidate.

:func:`write_select_report` writes into one folder, every file atomically:

* ``figures/front.png``/``.svg``: the 2-D projections of the objectives, each
  pair in a panel: feasible candidates (ISO sizes with estimated ratings as
  diamonds), rejected ones (crosses), the front (ringed) and the recommended
  one (a star);
* ``data/front.csv``: every candidate's figures (units in the headers), its
  verdict, binding constraint and whether it is on the front;
* ``data/select.json``: the result with its inputs;
* ``recommended.toml``: the recommended candidate's case file, for
  ``ballscrew check --case recommended.toml`` with the same move;
* ``report.md`` and ``report.html``.

When no candidate passes, :func:`write_rejection_report` writes what a report can
still say: ``data/front.csv`` (every candidate, its verdict and failing row),
``data/select.json`` and the pages, listing each candidate's failing criterion, most
nearly passing first, and the error's advice.
"""

from __future__ import annotations

import itertools
import math
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure as MplFigure

from .._version import __version__
from ..io.files import atomic_write
from ..select.choose import FIGURES, OBJECTIVES, NoneFeasible, SelectResult
from .document import Block, write_data, write_pages
from .outputs import csv_bytes, result_json
from .plotting import new_figure, write_figures

__all__ = ["write_rejection_report", "write_select_report"]


def _number(value: float) -> str:
    return "-" if not math.isfinite(value) else f"{value:.4g}"


def _percent(value: float) -> str:
    return "-" if not math.isfinite(value) else f"{value:.1%}"


def _pairs(result: SelectResult) -> list[tuple[str, str]]:
    chosen = list(result.objectives)
    if len(chosen) == 1:
        chosen.append("stiffness" if chosen[0] != "stiffness" else "energy")
    return list(itertools.combinations(chosen, 2))


def _front_figure(result: SelectResult) -> MplFigure:
    pairs = _pairs(result)
    columns = min(len(pairs), 3)
    rows = math.ceil(len(pairs) / columns)
    fig = new_figure(4.2 * columns, 3.6 * rows, layout="constrained")
    front = set(result.front)
    for k, (a, b) in enumerate(pairs):
        ax = fig.add_subplot(rows, columns, k + 1)
        (ka, la, _), (kb, lb, _) = OBJECTIVES[a], OBJECTIVES[b]

        def xy(indices: list[int], ka: str = ka, kb: str = kb) -> tuple[list[float], list[float]]:
            return ([result.evaluated[i].figures[ka] for i in indices],
                    [result.evaluated[i].figures[kb] for i in indices])  # fmt: skip

        everyone = range(len(result.evaluated))
        ok = [i for i in everyone if result.evaluated[i].feasible]
        bad = [i for i in everyone if not result.evaluated[i].feasible]
        ax.scatter(*xy(bad), marker="x", color="#b00020", alpha=0.6, label="rejected")
        ax.scatter(*xy(ok), marker="o", color="#3a7d44", alpha=0.7, label="feasible")
        estimated = [i for i in ok if result.evaluated[i].candidate.estimated]
        if estimated:
            ax.scatter(*xy(estimated), marker="D", s=40, color="#1f77b4", alpha=0.8,
                       label="feasible, ISO size (estimated ratings)")  # fmt: skip
        ax.scatter(*xy(sorted(front)), marker="o", s=90, facecolors="none",
                   edgecolors="black", label="Pareto front")  # fmt: skip
        ax.scatter(*xy([result.recommended]), marker="*", s=220, color="#c58b00",
                   edgecolors="black", label="recommended", zorder=5)  # fmt: skip
        ax.set_xlabel(la)
        ax.set_ylabel(lb)
        if k == 0:
            ax.legend(fontsize="small")
    return fig


def _unit(result: SelectResult | NoneFeasible, key: str) -> str:
    """The unit of a figure; the price's is the motor table's currency."""
    if key == "price":
        return str(result.inputs.get("currency") or "-")
    return FIGURES[key]


def _table(result: SelectResult | NoneFeasible) -> bytes:
    keys = list(FIGURES)
    header = ["candidate", "designation", "nut", "preload class", "preload share [-]", "oil",
              "ratings", "motor", "feasible", "on front", "binding constraint",
              *(f"{k} [{_unit(result, k)}]" for k in keys)]  # fmt: skip
    front = set(result.front)
    rows = [[e.name, e.candidate.row.name, e.candidate.nut, e.candidate.preload_class,
             e.candidate.preload_share, e.candidate.oil,
             "estimated" if e.candidate.estimated else "catalogue",
             e.candidate.motor.name if e.candidate.motor is not None else "", e.feasible,
             i in front, e.binding,
             *(None if not np.isfinite(e.figures[k]) else e.figures[k] for k in keys)]
            for i, e in enumerate(result.evaluated)]  # fmt: skip
    return csv_bytes(header, rows)


def _blocks(result: SelectResult, caption: str) -> list[Block]:
    keys = [OBJECTIVES[o][0] for o in result.objectives]
    rows = [[result.evaluated[i].name + (" (recommended)" if i == result.recommended else ""),
             *(_number(result.evaluated[i].figures[k]) for k in keys),
             _number(result.evaluated[i].figures["max_utilisation"]),
             _percent(result.evaluated[i].figures["p_not_ok"]),
             result.evaluated[i].binding] for i in result.front]  # fmt: skip
    rejected = [[e.name, _percent(e.figures["p_not_ok"]), e.binding] for e in result.rejected]
    best = result.evaluated[result.recommended]
    pick = (f"Undecided: no candidate passes with {result.confidence:.0%} confidence; the "
            f"least likely to fail is {best.name}" if result.undecided
            else f"Recommended: {best.name}")  # fmt: skip
    return [
        Block("h1", f"Choose the screw: {result.title}"),
        Block("p", f"Computed by ballscrew {__version__} with the {result.model} model: "
              f"{len(result.evaluated)} candidates, {len(result.feasible)} feasible, "
              f"{len(result.front)} on the front over {', '.join(result.objectives)}."),
        Block("p", f"{pick}. Why: {result.reason}. Its case file is "
              "recommended.toml (`ballscrew check --case recommended.toml` with the same "
              "move gives the same numbers)."),
        Block("h2", "The Pareto front"),
        Block("table", (["candidate", *keys, "largest utilisation", "P(NOT OK)", "binding row"],
                        rows)),
        Block("img", ("front", caption)),
        *([Block("p", "ISO 3408-2 sizes (the names starting 'ISO') carry load ratings "
                  "estimated from their geometry (ballscrew.design.ratings); "
                  + str(result.inputs["rating_estimates"]) + ".")]
          if result.inputs.get("rating_estimates") else []),
        Block("h2", "Rejected candidates and what fails them"),
        Block("p", f"A candidate is rejected when a row fails at its nominal value or its "
              f"P(NOT OK) is above {1.0 - result.confidence:.0%}."),
        Block("table", (["candidate", "P(NOT OK)", "binding constraint"],
                        rejected or [["none", "-", "-"]])),
    ]  # fmt: skip


def write_select_report(out: str | Path, result: SelectResult) -> list[Path]:
    """Write the report files into ``out``; returns the paths written."""
    folder = Path(out)
    (folder / "data").mkdir(parents=True, exist_ok=True)
    caption = ("Each pair of objectives: feasible candidates (dots; ISO sizes, their ratings "
               "estimated, as diamonds), rejected ones (crosses), the Pareto front (ringed) and "
               "the recommended candidate (star).")  # fmt: skip
    written, images = write_figures(folder, {"front": _front_figure(result)})
    written += write_data(folder, [("front", _table(result))])
    for path, text in ((folder / "data" / "select.json", result_json(result)),
                       (folder / "recommended.toml",
                        result.evaluated[result.recommended].candidate.text)):  # fmt: skip
        atomic_write(path, text.encode("utf-8"))
        written.append(path)
    blocks = _blocks(result, caption)
    return written + write_pages(folder, blocks, f"Choose the screw: {result.title}", images)


def write_rejection_report(out: str | Path, result: NoneFeasible) -> list[Path]:
    """The report of a selection no candidate passes, into ``out``; returns the paths written.

    Every candidate with its failing criterion (the row of largest utilisation, or the
    input error that rejected it), most nearly passing first, and the error's advice.
    """
    folder = Path(out)
    (folder / "data").mkdir(parents=True, exist_ok=True)
    written = write_data(folder, [("front", _table(result))])
    path = folder / "data" / "select.json"
    atomic_write(path, result_json(result).encode("utf-8"))
    written.append(path)
    title = f"Choose the screw: {result.title}"
    rows = [[e.name, _number(e.figures["max_utilisation"]), e.binding,
             "; ".join(e.failing) or "-"] for e in result.rejected]  # fmt: skip
    blocks = [
        Block("h1", title),
        Block("p", f"Computed by ballscrew {__version__} with the {result.model} model: "
              f"{len(result.evaluated)} candidates, none feasible, so none is recommended."),
        Block("p", result.reason),
        Block("h2", "Each candidate and what fails it"),
        Block("p", "The failing criterion is the check's row of largest utilisation (above "
              "1 fails), or the input error that rejected the candidate; the candidates most "
              "nearly passing come first. Every figure is in data/front.csv."),
        Block("table", (["candidate", "largest utilisation", "failing criterion",
                         "rows that fail, value against limit"], rows)),
    ]  # fmt: skip
    return written + write_pages(folder, blocks, title, {})
