"""The report of ``ballscrew check --out DIR``: the verdict table with its figures.

:func:`write_check_report` writes into one folder, every file atomically:

* ``figures/utilisation.png``/``.svg``: each criterion with a limit as a bar of
  its utilisation (value over limit), the 90 % and 100 % lines marked;
* ``figures/stiffness.png``/``.svg``: the axis stiffness and the lost motion at
  a reversal against the nut's position over the stroke;
* ``figures/thermal.png``/``.svg``: the temperature and the lead error per
  300 mm over the run time;
* ``data/utilisation.csv`` (every criterion's row), ``data/stiffness.csv``,
  ``data/thermal.csv`` (units in the headers): each figure's data;
* ``report.md`` and ``report.html``.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.figure import Figure as MplFigure

from .._version import __version__
from ..axis.check import AxisCheck, Criterion
from ..io.files import atomic_write
from .document import Block, write_data, write_pages
from .outputs import INPUT_HEADER, csv_bytes, input_rows
from .plotting import new_figure, write_figures

__all__ = ["write_check_report"]

_COLOURS = {"OK": "#3a7d44", "CHECK": "#c58b00", "NOT OK": "#b00020"}
_HEADER = ["criterion", "value", "limit", "unit", "use", "use, 95 %", "verdict", "P(NOT OK)",
           "with 95 % confidence", "source", "what to change"]  # fmt: skip


def _use_interval(c: Criterion) -> str:
    u = c.uncertainty
    return "-" if u is None else f"{u.low:.0%} to {u.high:.0%}"


def _probability(c: Criterion) -> str:
    return "-" if c.uncertainty is None else f"{c.uncertainty.p_not_ok:.0%}"


def _number(value: Any) -> str:
    if value is None or (isinstance(value, float) and not math.isfinite(value)):
        return "-"
    return f"{value:.4g}" if isinstance(value, float) else str(value)


def _utilisation_figure(check: AxisCheck) -> MplFigure:
    rows = [c for c in check.criteria if c.utilisation is not None]
    fig = new_figure(7.0, 0.45 * max(len(rows), 2) + 1.2, layout="constrained")
    ax = fig.add_subplot()
    y = np.arange(len(rows))[::-1]
    use = [100.0 * float(c.utilisation or 0.0) for c in rows]
    ax.barh(y, use, color=[_COLOURS.get(c.verdict, "0.5") for c in rows],
            hatch=["" if c.verdict == "OK" else "//" for c in rows])  # fmt: skip
    for yy, u, c in zip(y, use, rows, strict=True):
        ax.text(u + 1.0, yy, f"{u:.0f} % {c.verdict}", va="center", fontsize=7)
    ax.axvline(90.0, color="0.4", linestyle=":", linewidth=1.0)
    ax.axvline(100.0, color="0.2", linestyle="--", linewidth=1.0)
    ax.set_yticks(y, [c.name for c in rows], fontsize=8)
    ax.set_xlabel("utilisation = value / limit [%] (CHECK from 90 %, NOT OK above 100 %)")
    ax.set_xlim(0.0, max(120.0, 1.15 * max(use, default=0.0)))
    ax.set_title(f"{check.title}: {check.verdict}", fontsize=9)
    return fig


def _stiffness_figure(check: AxisCheck) -> MplFigure:
    s = check.stiffness
    fig = new_figure(7.0, 4.6, layout="constrained")
    top, bottom = fig.subplots(2, 1, sharex=True)
    x = s["position_mm"]
    top.plot(x, s["axis_N_per_um"], color="C0", linestyle="-", label="axis (in series)")
    top.plot(x, s["shaft_N_per_um"], color="C1", linestyle="--", label="shaft")
    top.axhline(s["nut_N_per_um"], color="C2", linestyle=":", label="nut (catalogue level x 0.8)")
    top.set_ylabel("axial stiffness [N/µm]")
    top.set_yscale("log")
    top.legend(fontsize=7, loc="best")
    bottom.plot(x, s["lost_motion_um"], color="C3", marker="o", markersize=3,
                label=f"2 F_f / k, F_f = {s['friction_force_N']:.4g} N")  # fmt: skip
    bottom.set_ylabel("lost motion at a reversal [µm]")
    bottom.set_xlabel("nut position over the stroke [mm]")
    bottom.legend(fontsize=7, loc="best")
    return fig


def _thermal_figure(check: AxisCheck) -> MplFigure:
    t = check.thermal
    fig = new_figure(7.0, 4.6, layout="constrained")
    top, bottom = fig.subplots(2, 1, sharex=True)
    hours = np.asarray(t["time_s"], dtype=float) / 3600.0
    top.plot(hours, t["temperature_C"], color="C3")
    top.set_ylabel("screw temperature [°C]")
    bottom.plot(hours, t["error_per_300mm_over_time_um"], color="C0", linestyle="--")
    bottom.set_ylabel("lead error per 300 mm [µm]")
    bottom.set_xlabel("run time [h]")
    return fig


def _data(check: AxisCheck) -> dict[str, bytes]:
    s, t = check.stiffness, check.thermal
    criteria = csv_bytes(
        ["criterion", "value", "limit", "unit", "utilisation [-]", "utilisation 2.5 % [-]",
         "utilisation 97.5 % [-]", "verdict", "P(NOT OK) [-]", "verdict with 95 % confidence",
         "source", "advice"],
        [[c.name, c.value, c.limit, c.unit, c.utilisation,
          None if c.uncertainty is None else c.uncertainty.low,
          None if c.uncertainty is None else c.uncertainty.high, c.verdict,
          None if c.uncertainty is None else c.uncertainty.p_not_ok,
          "" if c.uncertainty is None else c.uncertainty.guarded, c.source, c.advice]
         for c in check.criteria],
    )  # fmt: skip
    stiffness = csv_bytes(
        ["position [mm]", "shaft [N/um]", "axis [N/um]", "eigenfrequency [Hz]",
         "lost motion [um]"],
        [list(r) for r in zip(s["position_mm"], s["shaft_N_per_um"], s["axis_N_per_um"],
                              s["eigenfrequency_Hz"], s["lost_motion_um"], strict=True)],
    )  # fmt: skip
    thermal = csv_bytes(
        ["time [s]", "temperature [degC]", "lead error per 300 mm [um]"],
        [list(r) for r in zip(t["time_s"], t["temperature_C"],
                              t["error_per_300mm_over_time_um"], strict=True)],
    )  # fmt: skip
    return {"utilisation": criteria, "stiffness": stiffness, "thermal": thermal}


def _blocks(check: AxisCheck, captions: dict[str, str]) -> list[Block]:
    missing = f", {len(check.not_checked)} not checked" if check.not_checked else ""
    rows = [[c.name, _number(c.value), _number(c.limit), c.unit,
             "-" if c.utilisation is None else f"{c.utilisation:.0%}", _use_interval(c),
             c.verdict, _probability(c), "-" if c.uncertainty is None else c.uncertainty.guarded,
             c.source, c.advice] for c in check.criteria]  # fmt: skip
    blocks = [
        Block("h1", f"Axis check: {check.title}"),
        Block(
            "p",
            f"Computed by ballscrew {__version__} with the {check.model} model. "
            f"Verdict: {check.verdict}{missing}.",
        ),
        Block("table", (_HEADER, rows)),
    ]
    blocks += [Block("img", (key, caption)) for key, caption in captions.items()]
    blocks += [Block("h2", "Assumptions"), Block("ul", list(check.assumptions) or ["none"])]
    blocks += _input_blocks(check)
    return blocks


def _input_blocks(check: AxisCheck) -> list[Block]:
    """The inputs the verdicts were computed from: run, move, the case's values and text."""
    inputs = check.inputs
    if not inputs:
        return []
    case = inputs["case"]
    move = ", ".join(f"{k}={v:g}" for k, v in inputs.get("move", {}).items()) or "a profile"
    run = [
        f"command: {' '.join(inputs['command'])}" if inputs.get("command") else "command: -",
        f"model: {inputs['model']}; move (SI): {move}; cycles: {inputs['cycles']}; run time: "
        f"{inputs['run_time_s']:g} s; lubricant temperature: {inputs['temperature_C']:g} degC",
        f"case: {case['title']}, SHA-256 {case['sha256']}"
        + (f" ({inputs['case_file']})" if inputs.get("case_file") else ""),
        f"uncertainty: {inputs['uncertainty']['samples']} draws, seed "
        f"{inputs['uncertainty']['seed']}",
    ]
    rows = input_rows(case["values"])
    return [
        Block("h2", "Inputs"),
        Block("ul", run),
        Block("table", (INPUT_HEADER, rows)),
        Block(
            "p",
            "The whole check with these inputs (the case file's text, every value) is "
            "data/check.json: it computes the same table again.",
        ),
    ]


def write_check_report(out: str | Path, check: AxisCheck) -> list[Path]:
    """Write the report files into ``out``; returns the paths written."""
    folder = Path(out)
    (folder / "data").mkdir(parents=True, exist_ok=True)
    figures = {
        "utilisation": (_utilisation_figure(check), "Each criterion with a limit: its "
                        "utilisation, value over limit (CHECK from 90 %, NOT OK above 100 %)."),
        "stiffness": (_stiffness_figure(check), "Axial stiffness of shaft, nut and axis, and "
                      "the lost motion at a reversal, over the nut's position."),
        "thermal": (_thermal_figure(check), "The screw's temperature and its lead error per "
                    "300 mm over the run time (the heat balance of the repeated cycle)."),
    }  # fmt: skip
    written, images = write_figures(folder, {k: fig for k, (fig, _) in figures.items()})
    written += write_data(folder, _data(check).items())
    if check.inputs:
        from .outputs import result_json

        path = folder / "data" / "check.json"
        atomic_write(path, result_json(check).encode("utf-8"))
        written.append(path)
    blocks = _blocks(check, {k: caption for k, (_, caption) in figures.items()})
    return written + write_pages(folder, blocks, f"Axis check: {check.title}", images)
