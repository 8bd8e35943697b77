"""The report of ``ballscrew contour --out DIR``: the polar plot, the reversal, the loops.

:func:`write_contour_report` writes into one folder, every file atomically:

* ``figures/polar.png``/``.svg``: the radial deviation of each run about the
  nominal circle, magnified as a ballbar report draws it (the nominal circle
  is the ring marked 0, each ring a fixed step of deviation);
* ``figures/reversal.png``/``.svg``: the reversal test's following error, with
  and without compensation, against the run without friction;
* ``figures/table.png``/``.svg``: the friction map and the compensation table;
* ``data/*.csv`` (radial deviation by angle, the reversal traces, the tables);
* ``contour.json``, ``report.md`` and ``report.html``.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure as MplFigure

from .._version import __version__
from ..io.files import atomic_write
from ..servo.contour import CircleRun, ContourResult
from .document import Block, write_data, write_pages
from .outputs import csv_bytes, json_document
from .plotting import new_figure, write_figures

__all__ = ["loop_table", "polar_figure", "write_contour_report"]


def _step(span_um: float) -> float:
    """A round deviation step per ring [µm] giving four to eight rings over ``span_um``."""
    for step in (0.1, 0.2, 0.5, 1.0, 2.0, 5.0, 10.0, 20.0, 50.0, 100.0, 200.0, 500.0):
        if span_um / step <= 6:
            return step
    return 1000.0


def polar_figure(
    runs: list[CircleRun], title: str = "", figure: MplFigure | None = None
) -> MplFigure:
    """The runs' radial deviations on a polar plot, magnified (module docstring).

    Drawn into ``figure`` when given (a pyplot figure, say), else into a new one.
    """
    devs = [r.binned(0.5)[1] * 1e6 for r in runs]
    lo = min(float(np.min(d)) for d in devs)
    hi = max(float(np.max(d)) for d in devs)
    step = _step(max(hi - lo, 1e-3))
    inner = math.floor(lo / step) - 2  # ring 0 of the plot: this many steps below 0
    fig = figure if figure is not None else MplFigure(figsize=(6.0, 6.0))
    if figure is None:
        FigureCanvasAgg(fig)
    ax = fig.add_subplot(1, 1, 1, projection="polar")
    for run, dev in zip(runs, devs, strict=True):
        angle = run.binned(0.5)[0]
        label = ("CW" if run.clockwise else "CCW") + (", compensated" if run.compensated else "")
        style = "--" if run.compensated else "-"
        ax.plot(
            np.radians(np.append(angle, angle[0])),
            np.append(dev, dev[0]) - inner * step,
            style,
            label=label,
        )
    top = math.ceil(hi / step) + 1
    rings = np.arange(inner, top + 1) * step
    ax.set_rticks(rings - inner * step)  # type: ignore[attr-defined]
    ax.set_yticklabels([f"{v:g}" for v in rings], fontsize=7)
    ax.set_rlim(0.0, (top - inner) * step)  # type: ignore[attr-defined]
    ax.plot(np.linspace(0, 2 * np.pi, 361), np.full(361, -inner * step), color="black", lw=0.8)
    ax.set_title(
        f"{title}\nradial deviation [µm], {step:g} µm per ring (ring 0: nominal)", fontsize=9
    )
    ax.legend(loc="lower left", fontsize=7, bbox_to_anchor=(-0.1, -0.12))
    fig.tight_layout()
    return fig


def _reversal_figure(result: ContourResult) -> MplFigure:
    fig = new_figure(7.0, 4.0)
    ax = fig.add_subplot(1, 1, 1)
    for run in result.reversals:
        t = run.trace.time
        label = "with compensation" if run.compensated else "without compensation"
        ax.plot(t, (run.trace.error - run.reference.error) * 1e6, label=label)
    ax.set_xlabel("time [s]")
    ax.set_ylabel("following error from friction [µm]")
    ax.set_title(
        f"reversal of the x axis at {result.feed * 60:g} m/min, "
        f"{result.reversals[0].acceleration:.3g} m/s²",
        fontsize=9,
    )
    ax.legend()
    fig.tight_layout()
    return fig


def _table_figure(result: ContourResult) -> MplFigure:
    fig = new_figure(7.0, 4.0)
    ax = fig.add_subplot(1, 1, 1)
    axis, table = result.axes[0], result.tables[0]
    keep = np.abs(axis.speeds) <= table.speed_range
    ax.plot(axis.speeds[keep] * 60, axis.friction[keep], ".", label=f"{result.model} (map)")
    ax.plot(
        table.speed * 60,
        table.force,
        "-o",
        ms=3,
        label=f"{table.speed.size}-point table, RMS error {table.rms_error:.3g} N",
    )
    ax.set_xlabel("table speed [m/min]")
    ax.set_ylabel("screw friction force [N]")
    ax.legend()
    fig.tight_layout()
    return fig


def _fmt(v: float | None, digits: int = 4) -> str:
    return "" if v is None else f"{v:.{digits}g}"


def loop_table(result: ContourResult) -> tuple[list[str], list[list[str]]]:
    """Each axis's loops as (header, rows): crossover, margins, bandwidths, eigenfrequency."""
    header = ["axis", "velocity crossover [Hz]", "phase margin [deg]", "gain margin [dB]",
              "velocity bandwidth [Hz]", "position phase margin [deg]",
              "position bandwidth [Hz]", "eigenfrequency [Hz]"]  # fmt: skip
    rows = [
        [name, *(_fmt(v, 3) for v in (f.velocity_crossover_hz, f.velocity_phase_margin_deg,
                                      f.velocity_gain_margin_db, f.velocity_bandwidth_hz,
                                      f.position_phase_margin_deg, f.position_bandwidth_hz)),
         "rigid" if a.rigid else _fmt(a.eigenfrequency)]
        for name, f, a in zip("xy", result.figures, result.axes, strict=True)
    ]  # fmt: skip
    return header, rows


def _blocks(result: ContourResult) -> list[Block]:
    doc = result.as_dict()
    blocks = [
        Block("h1", f"Circular test: {result.axes[0].name}"),
        Block(
            "p",
            f"Computed by ballscrew {__version__}: radius {result.radius * 1e3:g} mm, "
            f"feed {result.feed * 60:g} m/min, model {result.model}, "
            f"{result.cpu_seconds:.3g} s of CPU.",
        ),
        Block("h2", "Circles (ISO 230-4 quantities)"),
        Block(
            "table",
            (
                ["direction", "compensated", "G [µm]", "largest glitch [µm]", "glitch width [deg]"],
                [
                    [
                        c["direction"],
                        "yes" if c["compensated"] else "no",
                        _fmt(c["circular_deviation_G_um"]),
                        _fmt(c["largest_glitch_um"]),
                        _fmt(max(g["width_deg"] for g in c["glitches"]), 3),
                    ]
                    for c in doc["circles"]
                ],
            ),
        ),
        Block(
            "p",
            f"Glitch reduction by the compensation: {_fmt(result.reduction, 3)}; circular "
            f"hysteresis H: {_fmt(doc['circular_hysteresis_H_um'])} µm.",
        ),
        Block("img", ("polar", "Radial deviation, magnified")),
        Block("img", ("reversal", "Reversal test of the x axis")),
        Block("img", ("table", "Friction map and compensation table of the x axis")),
        Block("h2", "Loops"),
        Block("table", loop_table(result)),
        Block("p", f"Verdict of the loops and the drive: {result.verdict}."),
        Block(
            "table",
            (
                ["axis", "check", "value", "limit", "verdict"],
                [
                    [
                        c.axis,
                        c.name,
                        f"{_fmt(c.value)} {c.unit}",
                        f"{'at least' if c.floor else 'at most'} {_fmt(c.limit)} {c.unit}",
                        c.status,
                    ]
                    for c in result.checks
                ],
            ),
        ),
        Block("h2", "Assumptions"),
        Block("ul", list(result.notes)),
    ]
    return blocks


def write_contour_report(out: str | Path, result: ContourResult) -> list[Path]:
    """Write the report files into ``out``; returns the paths written."""
    folder = Path(out)
    (folder / "data").mkdir(parents=True, exist_ok=True)
    runs = [c for c in result.circles]
    figures = {
        "polar": polar_figure(runs, result.axes[0].name),
        "reversal": _reversal_figure(result),
        "table": _table_figure(result),
    }
    written, images = write_figures(folder, figures)
    data: dict[str, bytes] = {}
    header = ["angle [deg]"]
    columns = []
    for c in runs:
        angle, dev = c.binned()
        header.append(
            f"deviation {'CW' if c.clockwise else 'CCW'}"
            f"{' compensated' if c.compensated else ''} [um]"
        )
        columns.append(dict(zip(angle.round(3).tolist(), (dev * 1e6).tolist(), strict=True)))
    angles = sorted({a for col in columns for a in col})
    rows = [[a, *(col.get(a, float("nan")) for col in columns)] for a in angles]
    data["polar"] = csv_bytes(header, rows)
    rev = result.reversals
    data["reversal"] = csv_bytes(
        [
            "time [s]",
            *(
                f"error from friction {'with' if r.compensated else 'without'} compensation [um]"
                for r in rev
            ),
        ],
        [
            [
                float(t),
                *(float((r.trace.error - r.reference.error)[i]) * 1e6 for r in rev),
            ]
            for i, t in enumerate(rev[0].trace.time)
        ],
    )
    data["table"] = csv_bytes(
        ["axis", "table speed [m/s]", "force [N]"],
        [
            [name, float(v), float(f)]
            for name, t in zip("xy", result.tables, strict=True)
            for v, f in zip(t.speed, t.force, strict=True)
        ],
    )
    written += write_data(folder, data.items())
    document = json_document({"ballscrew": __version__, **result.as_dict()})
    atomic_write(folder / "contour.json", document.encode("utf-8"))
    written.append(folder / "contour.json")
    return written + write_pages(folder, _blocks(result), "Circular test", images)
