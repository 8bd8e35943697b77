"""The report of ``ballscrew energy --out DIR``: plots over time, energy bars, CSV, Markdown, HTML.

:func:`write_energy_report` writes into one folder, every file atomically:

* ``figures/motion.png``/``.svg``: table speed and motor torque against time;
* ``figures/power.png``/``.svg``: friction power of the screw against time;
* ``figures/energy.png``/``.svg``: energy per model by component (screw out,
  screw back, support bearings) beside the catalogue rule's;
* ``figures/temperature.png``/``.svg`` when a temperature history is given;
* ``figures/steady.png``/``.svg`` and ``data/steady.csv`` with ``--steady-speeds``
  (also a table in the report);
* ``data/time_series.csv`` with units in the header, ``data/summary.csv`` (the
  summary's quantities in words with units, a row per model);
* ``report.md`` and ``report.html``.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path

import numpy as np
from matplotlib.figure import Figure as MplFigure

from .._version import __version__
from ..axis.duty import EnergyRun
from ..axis.energy import CycleResult
from ..axis.motion import Profile
from ..axis.thermal import SteadyAtSpeed
from ..errors import FloatArray
from ..io.numbers import text
from ..kinematics import rad_s_to_rpm
from .document import Block, write_data, write_pages
from .outputs import INPUT_HEADER, csv_bytes, input_rows
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


def _steady_figure(steady: Mapping[str, SteadyAtSpeed]) -> MplFigure:
    """Steady temperature and friction torque of continuous running against speed."""
    fig = new_figure(7.0, 5.5)
    top, bottom = fig.subplots(2, 1, sharex=True)
    for name, at in steady.items():
        rpm = rad_s_to_rpm(at.speed)
        top.plot(rpm, at.temperature, marker="o", label=name)
        bottom.plot(rpm, at.torque, marker="o", label=name)
    top.set_ylabel("steady temperature [°C]")
    bottom.set_ylabel("friction torque [N·m]")
    bottom.set_xlabel("screw speed [rpm]")
    top.legend()
    fig.tight_layout()
    return fig


def _figures(
    profile: Profile,
    results: Mapping[str, CycleResult],
    history: Mapping[str, tuple[FloatArray, FloatArray]] | None,
    steady: Mapping[str, SteadyAtSpeed] | None = None,
) -> dict[str, tuple[MplFigure, str]]:
    """The report's figures by key, each with its caption."""
    figures = {
        "motion": (_motion_figure(profile, results), "Table speed and motor torque"),
        "power": (_power_figure(results), "Friction power of the screw"),
        "energy": (_energy_figure(results), "Friction energy by component"),
    }
    if history:
        figures["temperature"] = (_temperature_figure(history), "Temperature over time")
    if steady:
        figures["steady"] = (
            _steady_figure(steady),
            "Continuous running: steady temperature and friction torque by speed",
        )
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
    rows = [[float(v) for v in values] for values in zip(*columns, strict=True)]
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
        [[float(t), float(v) * 60, *(float(results[n].motor_torque[i]) for n in names)]
         for i, (t, v) in enumerate(zip(profile.time, profile.speed, strict=True))],
    )  # fmt: skip
    data["power"] = csv_bytes(
        ["time [s]", *(f"friction power {n} [W]" for n in names)],
        [[float(t), *(float(results[n].friction_power[i]) for n in names)]
         for i, t in enumerate(profile.time)],
    )  # fmt: skip
    data["energy"] = csv_bytes(
        ["model", "screw out [J]", "screw back [J]", "support bearings [J]",
         "catalogue rule [J]"],
        [[n, r.friction_energy_out, r.friction_energy_back, r.bearing_energy,
          r.constant_efficiency_energy]
         for n, r in results.items()],
    )  # fmt: skip
    if history:
        data["temperature"] = csv_bytes(
            ["model", "time [s]", "temperature [degC]"],
            [[n, float(t), float(v)]
             for n, (ts, vs) in history.items() for t, v in zip(ts, vs, strict=True)],
        )  # fmt: skip
    return data


def _steady_csv(steady: Mapping[str, SteadyAtSpeed]) -> bytes:
    """The steady running of each model that has it, by speed."""
    return csv_bytes(
        ["model", *STEADY_COLUMNS],
        [[n, float(rad_s_to_rpm(w)), float(tc), float(tq), float(pw)]
         for n, at in steady.items()
         for w, tc, tq, pw in zip(at.speed, at.temperature, at.torque, at.power, strict=True)],
    )  # fmt: skip


STEADY_COLUMNS = ("speed [rpm]", "steady temperature [degC]", "torque [N*m]", "power [W]")
"""The columns of the steady running's table (report and ``data/steady.csv``)."""

NO_WEIGHT = "not applicable (no weight to hold: the axis is horizontal or carries no mass)"
NO_LOAD = "not applicable (no axial load at the working point)"
NOT_COMPUTED = "not computed (the heat balance did not solve: see the warnings)"

SUMMARY: tuple[tuple[str, str, str], ...] = (
    ("friction_energy_J", "screw friction energy over all cycles [J]", NOT_COMPUTED),
    ("friction_energy_per_cycle_J", "screw friction energy per cycle [J]", NOT_COMPUTED),
    ("friction_energy_out_J", "screw friction energy, moving out [J]", NOT_COMPUTED),
    ("friction_energy_back_J", "screw friction energy, moving back [J]", NOT_COMPUTED),
    ("constant_efficiency_energy_J",
     "screw friction energy by the catalogue's constant-efficiency rule [J]", NOT_COMPUTED),
    ("bearing_energy_J", "support bearings' friction energy [J]", NOT_COMPUTED),
    ("load_work_J", "work done on the load (process force, weight, speed change) [J]",
     NOT_COMPUTED),
    ("peak_motor_torque_Nm", "peak motor torque [N*m]", NOT_COMPUTED),
    ("rms_motor_torque_Nm", "RMS motor torque [N*m]", NOT_COMPUTED),
    ("forward_efficiency", "efficiency, motor driving the load, at the working point [-]",
     NO_LOAD),
    ("reverse_efficiency", "efficiency, load back-driving the screw, at the working point [-]",
     NO_LOAD),
    ("back_drives_at_working_point", "the load back-drives the screw at the working point",
     NO_LOAD),
    ("weight_reverse_efficiency",
     "efficiency, the axis's weight back-driving the screw with the motor off [-]", NO_WEIGHT),
    ("self_locking", "self-locking (no axial load, however large, turns the screw)",
     NOT_COMPUTED),
    ("duration_s", "duration of the cycles [s]", NOT_COMPUTED),
    ("steady_temperature_C", "steady temperature of screw and nut, the cycle repeated [degC]",
     NOT_COMPUTED),
    ("final_temperature_C", "temperature of screw and nut after the run time [degC]",
     NOT_COMPUTED),
    ("friction_energy_at_final_temperature_J",
     "screw friction energy of the cycles at that temperature [J]", NOT_COMPUTED),
)  # fmt: skip
"""The summary's quantities: the key in ``--json``, the name with its unit, what a
missing value (None or NaN) means."""


def summary_value(value: object, missing: str) -> str:
    """A summary value as shown: 4 significant digits, yes/no, or what its absence means."""
    if isinstance(value, bool | np.bool_):
        return "yes" if value else "no"
    if value is None or (isinstance(value, float) and math.isnan(value)):
        return missing
    return text(value)


def _summary_table(
    summary: Mapping[str, Mapping[str, object]],
) -> tuple[list[str], list[list[str]]]:
    """The summary as a table: a row per quantity (in words, with its unit), a column per model."""
    rows = [[label, *(summary_value(v.get(key), missing) for v in summary.values())]
            for key, label, missing in SUMMARY
            if any(key in v for v in summary.values())]  # fmt: skip
    return ["quantity", *summary], rows


def _blocks(
    title: str,
    profile: Profile,
    summary: Mapping[str, Mapping[str, object]],
    captions: Mapping[str, str],
    steady: Mapping[str, SteadyAtSpeed] | None = None,
) -> list[Block]:
    """The report's document: the summary table, the figures and the validity warnings."""
    blocks = [
        Block("h1", f"Feed axis energy: {title}"),
        Block("p", f"Computed by ballscrew {__version__}; {text(profile.duration)} s of motion."),
        Block("table", _summary_table(summary)),
    ]
    for key, caption in captions.items():
        if key != "steady":
            blocks.append(Block("img", (key, caption)))
    if steady:
        blocks.append(Block("h2", "Continuous running"))
        blocks.append(Block("p", "The steady temperature of screw and nut when the axis runs "
                                 "without stopping at each speed, under the move's process "
                                 "force, and the friction torque and power there."))  # fmt: skip
        rows = [[n, text(rad_s_to_rpm(w)), text(tc), text(tq), text(pw)]
                for n, at in steady.items()
                for w, tc, tq, pw in zip(at.speed, at.temperature, at.torque, at.power,
                                         strict=True)]  # fmt: skip
        blocks.append(Block("table", (["model", *STEADY_COLUMNS], rows)))
        blocks.append(Block("img", ("steady", captions["steady"])))
    warnings = sorted({w for v in summary.values() for w in v.get("warnings", [])})  # type: ignore[attr-defined]
    blocks += [Block("h2", "Validity"), Block("ul", warnings or ["none"])]
    return blocks


def _input_blocks(run: EnergyRun) -> list[Block]:
    """The move, the run and the case the report was computed from."""
    from ..axis.duty import run_inputs

    inputs = run_inputs(run, next(iter(run.results)))
    move = ", ".join(f"{k}={v:g}" for k, v in inputs["move"].items()) or "a profile file"
    case = inputs["case"]
    rows = input_rows(case["values"])
    return [
        Block("h2", "Inputs"),
        Block("ul", [
            f"move (SI): {move}; cycles: {inputs['cycles']}; run time: "
            f"{inputs['run_time_s']:g} s; lubricant temperature: {inputs['temperature_C']:g} degC",
            f"case: {case['title']}, SHA-256 {case['sha256']}",
        ]),
        Block("table", (INPUT_HEADER, rows)),
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
    steady = run.steady or None
    figures = _figures(profile, results, history, steady)
    written, images = write_figures(folder, {k: fig for k, (fig, _) in figures.items()})
    data = {"time_series": _time_series_csv(profile, results)}
    data.update(_figure_csvs(profile, results, history))
    if steady:
        data["steady"] = _steady_csv(steady)
    _, table = _summary_table(summary)
    data["summary"] = csv_bytes(["model", *(row[0] for row in table)],
                                [[n, *(row[k + 1] for row in table)]
                                 for k, n in enumerate(summary)])  # fmt: skip
    written += write_data(folder, data.items())
    captions = {k: caption for k, (_, caption) in figures.items()}
    blocks = _blocks(title, profile, summary, captions, steady)
    blocks += _input_blocks(run)
    return written + write_pages(folder, blocks, f"Feed axis energy: {title}", images)
