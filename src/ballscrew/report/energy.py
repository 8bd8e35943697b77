"""The report of ``ballscrew energy --out DIR``: plots over time, energy bars, CSV, Markdown, HTML.

:func:`write_energy_report` writes into one folder, every file atomically:

* ``figures/motion.png``/``.svg``: table speed and motor torque against time;
* ``figures/power.png``/``.svg``: friction power of the screw against time;
* ``figures/energy.png``/``.svg``: energy per model by component (screw out,
  screw back, support bearings) beside the catalogue rule's;
* ``figures/temperature.png``/``.svg`` when a temperature history is given;
* ``data/time_series.csv`` with units in the header, ``data/summary.csv``;
* ``report.md`` and ``report.html``.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.figure import Figure as MplFigure

from .._version import __version__
from ..axis.duty import EnergyRun
from ..axis.energy import CycleResult
from ..axis.motion import Profile
from ..errors import FloatArray
from .document import Block, write_data, write_pages
from .outputs import csv_bytes
from .plotting import new_figure, write_figures

__all__ = ["write_energy_report"]


def _figure() -> tuple[MplFigure, object]:
    fig = new_figure(7.0, 4.0)
    return fig, fig.add_subplot(1, 1, 1)


def _motion_figure(profile: Profile, results: Mapping[str, CycleResult]) -> MplFigure:
    fig = new_figure(7.0, 5.5)
    top, bottom = fig.subplots(2, 1, sharex=True)
    top.plot(profile.time, profile.speed * 60.0, color="black")
    top.set_ylabel("table speed [m/min]")
    for name, r in results.items():
        bottom.plot(r.time, r.motor_torque, label=name)
    bottom.set_xlabel("time [s]")
    bottom.set_ylabel("motor torque [N·m]")
    bottom.legend()
    fig.tight_layout()
    return fig


def _power_figure(results: Mapping[str, CycleResult]) -> MplFigure:
    fig, ax = _figure()
    for name, r in results.items():
        ax.plot(r.time, r.friction_power, label=name)  # type: ignore[attr-defined]
    ax.set_xlabel("time [s]")  # type: ignore[attr-defined]
    ax.set_ylabel("screw friction power [W]")  # type: ignore[attr-defined]
    ax.legend()  # type: ignore[attr-defined]
    fig.tight_layout()
    return fig


def _energy_figure(results: Mapping[str, CycleResult]) -> MplFigure:
    fig, ax = _figure()
    names = list(results)
    x = np.arange(len(names))
    out = np.array([results[n].friction_energy_out for n in names])
    back = np.array([results[n].friction_energy_back for n in names])
    bearings = np.array([results[n].bearing_energy for n in names])
    ax.bar(x, out, label="screw, moving out")  # type: ignore[attr-defined]
    ax.bar(x, back, bottom=out, hatch="//", label="screw, moving back")  # type: ignore[attr-defined]
    ax.bar(x, bearings, bottom=out + back, hatch="..",  # type: ignore[attr-defined]
           label="support bearings")  # fmt: skip
    rule = [results[n].constant_efficiency_energy for n in names]
    ax.scatter(x, rule, color="black", marker="_", s=400, zorder=3,  # type: ignore[attr-defined]
               label="catalogue rule (screw)")  # fmt: skip
    ax.set_xticks(x, names)  # type: ignore[attr-defined]
    ax.set_ylabel("friction energy [J]")  # type: ignore[attr-defined]
    # Room above the bars for the legend, so that it covers none of them.
    top = max(float(np.max(out + back + bearings)), float(np.max(rule)))
    ax.set_ylim(0.0, 1.45 * top if top > 0 else 1.0)  # type: ignore[attr-defined]
    ax.legend(ncols=2, fontsize=8, loc="upper center")  # type: ignore[attr-defined]
    fig.tight_layout()
    return fig


def _temperature_figure(history: Mapping[str, tuple[FloatArray, FloatArray]]) -> MplFigure:
    fig, ax = _figure()
    for name, (t, temp) in history.items():
        ax.plot(t / 60.0, temp, label=name)  # type: ignore[attr-defined]
    ax.set_xlabel("time [min]")  # type: ignore[attr-defined]
    ax.set_ylabel("screw and nut temperature [°C]")  # type: ignore[attr-defined]
    ax.legend()  # type: ignore[attr-defined]
    fig.tight_layout()
    return fig


def _figures(
    profile: Profile,
    results: Mapping[str, CycleResult],
    history: Mapping[str, tuple[FloatArray, FloatArray]] | None,
) -> dict[str, tuple[MplFigure, str]]:
    """The report's figures by key, each with its caption."""
    figures = {
        "motion": (_motion_figure(profile, results), "Table speed and motor torque"),
        "power": (_power_figure(results), "Friction power of the screw"),
        "energy": (_energy_figure(results), "Friction energy by component"),
    }
    if history:
        figures["temperature"] = (_temperature_figure(history), "Temperature over time")
    return figures


def _time_series_csv(profile: Profile, results: Mapping[str, CycleResult]) -> bytes:
    """The motion and, per model, friction torque, motor torque and friction power over time."""
    header = ["time [s]", "position [mm]", "table speed [m/s]", "axial force [N]"]
    columns: list[FloatArray] = [profile.time, profile.position * 1e3, profile.speed]
    first = next(iter(results.values()))
    columns.append(first.axial_force)
    for name, r in results.items():
        header += [f"friction torque {name} [N*m]", f"motor torque {name} [N*m]",
                   f"friction power {name} [W]"]  # fmt: skip
        columns += [r.friction_torque, r.motor_torque, r.friction_power]
    rows = [[f"{float(v):.7g}" for v in values] for values in zip(*columns, strict=True)]
    return csv_bytes(header, rows)


def _figure_csvs(
    profile: Profile,
    results: Mapping[str, CycleResult],
    history: Mapping[str, tuple[FloatArray, FloatArray]] | None,
) -> dict[str, bytes]:
    """One CSV per figure, as the report links them."""
    names = list(results)
    data: dict[str, bytes] = {}
    data["motion"] = csv_bytes(
        ["time [s]", "table speed [m/min]", *(f"motor torque {n} [N*m]" for n in names)],
        [[f"{float(t):.7g}", f"{float(v) * 60:.7g}",
          *(f"{float(results[n].motor_torque[i]):.7g}" for n in names)]
         for i, (t, v) in enumerate(zip(profile.time, profile.speed, strict=True))],
    )  # fmt: skip
    data["power"] = csv_bytes(
        ["time [s]", *(f"friction power {n} [W]" for n in names)],
        [[f"{float(t):.7g}", *(f"{float(results[n].friction_power[i]):.7g}" for n in names)]
         for i, t in enumerate(profile.time)],
    )  # fmt: skip
    data["energy"] = csv_bytes(
        ["model", "screw out [J]", "screw back [J]", "support bearings [J]",
         "catalogue rule [J]"],
        [[n, f"{r.friction_energy_out:.7g}", f"{r.friction_energy_back:.7g}",
          f"{r.bearing_energy:.7g}", f"{r.constant_efficiency_energy:.7g}"]
         for n, r in results.items()],
    )  # fmt: skip
    if history:
        data["temperature"] = csv_bytes(
            ["model", "time [s]", "temperature [degC]"],
            [[n, f"{float(t):.7g}", f"{float(v):.7g}"]
             for n, (ts, vs) in history.items() for t, v in zip(ts, vs, strict=True)],
        )  # fmt: skip
    return data


def _steady_csv(summary: Mapping[str, Mapping[str, object]]) -> bytes | None:
    """The steady running of each model that has it, by speed; None when none has."""
    steady: dict[str, Any] = {
        n: v["steady_at_speed"] for n, v in summary.items() if "steady_at_speed" in v
    }
    if not steady:
        return None
    return csv_bytes(
        ["model", "speed [rpm]", "steady temperature [degC]", "torque [N*m]", "power [W]"],
        [[n, *(f"{float(x):.7g}" for x in row)]
         for n, st in steady.items()
         for row in zip(st["speed_rpm"], st["temperature_C"], st["torque_Nm"],
                        st["power_W"], strict=True)],
    )  # fmt: skip


def _scalar_keys(summary: Mapping[str, Mapping[str, object]]) -> list[str]:
    """The summary's scalar keys, sorted: the tables of each model have their own CSV."""
    return sorted({k for v in summary.values() for k in v
                   if not isinstance(v[k], dict | list | tuple)})  # fmt: skip


def _blocks(
    title: str,
    profile: Profile,
    summary: Mapping[str, Mapping[str, object]],
    captions: Mapping[str, str],
) -> list[Block]:
    """The report's document: the summary table, the figures and the validity warnings."""
    keys = _scalar_keys(summary)
    blocks = [
        Block("h1", f"Feed axis energy: {title}"),
        Block("p", f"Computed by ballscrew {__version__}; {profile.duration:.4g} s of motion."),
        Block(
            "table",
            (
                ["quantity", *summary],
                [[k, *(_fmt(v.get(k)) for v in summary.values())] for k in keys],
            ),
        ),
    ]
    for key, caption in captions.items():
        blocks.append(Block("img", (key, caption)))
    warnings = sorted({w for v in summary.values() for w in v.get("warnings", [])})  # type: ignore[attr-defined]
    blocks += [Block("h2", "Validity"), Block("ul", warnings or ["none"])]
    return blocks


def _input_blocks(run: EnergyRun) -> list[Block]:
    """The move, the run and the case the report was computed from."""
    from ..axis.duty import run_inputs

    inputs = run_inputs(run, next(iter(run.results)))
    move = ", ".join(f"{k}={v:g}" for k, v in inputs["move"].items()) or "a profile file"
    case = inputs["case"]
    rows = [[v["key"], str(v["value"]), v["source"]]
            for v in case["values"] if v["value"] is not None]  # fmt: skip
    return [
        Block("h2", "Inputs"),
        Block("ul", [
            f"move (SI): {move}; cycles: {inputs['cycles']}; run time: "
            f"{inputs['run_time_s']:g} s; lubricant temperature: {inputs['temperature_C']:g} degC",
            f"case: {case['title']}, SHA-256 {case['sha256']}",
        ]),
        Block("table", (["key", "value (SI)", "source"], rows)),
    ]  # fmt: skip


def write_energy_report(out: str | Path, run: EnergyRun) -> list[Path]:
    """Write the report of ``run`` (:func:`ballscrew.axis.duty.run_energy`) into ``out``.

    Returns the paths written.
    """
    title, profile, results = run.case.title, run.profile, run.cycles_by_model
    summary = {name: r.as_dict() for name, r in run.results.items()}
    history = run.histories or None
    folder = Path(out)
    (folder / "figures").mkdir(parents=True, exist_ok=True)
    (folder / "data").mkdir(parents=True, exist_ok=True)
    figures = _figures(profile, results, history)
    written, images = write_figures(folder, {k: fig for k, (fig, _) in figures.items()})
    data = {"time_series": _time_series_csv(profile, results)}
    data.update(_figure_csvs(profile, results, history))
    steady = _steady_csv(summary)
    if steady is not None:
        data["steady"] = steady
    keys = _scalar_keys(summary)
    data["summary"] = csv_bytes(["model", *keys], [[n, *(v.get(k, "") for k in keys)]
                                               for n, v in summary.items()])  # fmt: skip
    written += write_data(folder, data.items())
    blocks = _blocks(title, profile, summary, {k: caption for k, (_, caption) in figures.items()})
    blocks += _input_blocks(run)
    return written + write_pages(folder, blocks, f"Feed axis energy: {title}", images)


def _fmt(value: object) -> str:
    if isinstance(value, float):
        return f"{value:.4g}"
    return "" if value is None else str(value)
