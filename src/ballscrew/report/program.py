"""The report of ``ballscrew program --out DIR``: the path, energies, torques, temperatures.

:func:`write_program_report` writes into one folder, every file atomically:

* ``figures/path.png``/``.svg``: the tool path seen from above (X, Y), coloured
  by the screws' friction power, with every reversal of an axis marked;
* ``figures/energy.png``/``.svg``: energy per axis, stacked by where it goes
  (screw friction, support bearings, process work, the rest: kinetic and
  potential energy and what the drive takes back);
* ``figures/torque.png``/``.svg``: each axis's motor torque and screw
  temperature against time, reversals marked;
* ``data/time_series.csv`` (units in the header), ``data/blocks.csv`` (the
  friction energy per block and axis), ``data/reversals.csv``;
* ``report.md`` and ``report.html``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.collections import LineCollection
from matplotlib.figure import Figure as MplFigure

from .._version import __version__
from ..axis.check import Criterion
from ..io.numbers import text as num
from ..program.axes import AxisResult, ProgramResult
from .document import Block, write_data, write_pages
from .outputs import csv_bytes
from .plotting import new_figure, write_figures

__all__ = [
    "axis_notes",
    "drive_rows",
    "note_lines",
    "time_series_csv",
    "verdict_lines",
    "warning_lines",
    "write_program_report",
]

MARKERS = {"X": "o", "Y": "s", "Z": "^"}


def _path_figure(r: ProgramResult) -> MplFigure:
    fig = new_figure(7.0, 5.5)
    ax = fig.add_subplot(1, 1, 1)
    ds = r.data
    pos = r.motion.position * 1e3
    power = np.sum(ds["friction_power"].values, axis=1)
    points = pos[:, :2]
    segments = np.stack([points[:-1], points[1:]], axis=1)
    lines = LineCollection(list(segments), cmap="viridis", linewidths=1.2)
    lines.set_array(0.5 * (power[1:] + power[:-1]))
    ax.add_collection(lines)
    ax.autoscale()
    fig.colorbar(lines, ax=ax, label="friction power of the screws [W]")
    for letter, a in r.axes.items():
        if not a.reversals:
            continue
        t = np.array([rev.time for rev in a.reversals])
        x = np.interp(t, r.motion.time, pos[:, 0])
        y = np.interp(t, r.motion.time, pos[:, 1])
        ax.scatter(x, y, marker=MARKERS.get(letter, "x"), facecolors="none", edgecolors="red",
                   s=30, label=f"{letter} reversals")  # fmt: skip
    still = not np.any(np.ptp(points, axis=0) > 0.0)
    if still:  # the program moves neither X nor Y: where the tool stands
        ax.plot(points[:1, 0], points[:1, 1], "k+", markersize=12, label="the tool, standing")
    ax.set_aspect("equal")
    ax.set_xlabel("X [mm]")
    ax.set_ylabel("Y [mm]")
    if still or any(a.reversals for a in r.axes.values()):
        ax.legend(fontsize="small")
    fig.tight_layout()
    return fig


def _energy_figure(r: ProgramResult) -> MplFigure:
    fig = new_figure(7.0, 4.0)
    ax = fig.add_subplot(1, 1, 1)
    letters = list(r.axes)
    parts = {
        "screw friction": [r.axes[k].friction_energy for k in letters],
        "support bearings": [r.axes[k].bearing_energy for k in letters],
        "process work": [max(r.axes[k].process_work, 0.0) for k in letters],
        "rest (kinetic, potential, taken back)": [
            max(a.supplied_energy - a.friction_energy - a.bearing_energy - a.process_work, 0.0)
            for a in (r.axes[k] for k in letters)
        ],
    }
    bottom = np.zeros(len(letters))
    for name, values in parts.items():
        ax.bar(letters, values, bottom=bottom, label=name)
        bottom += np.asarray(values)
    ax.set_ylabel("energy over the program [J]")
    ax.legend(fontsize="small")
    fig.tight_layout()
    return fig


def _torque_figure(r: ProgramResult) -> MplFigure:
    letters = list(r.axes)
    fig = new_figure(7.0, 2.2 * len(letters) + 0.6)
    axes = fig.subplots(len(letters), 1, sharex=True, squeeze=False)[:, 0]
    t = r.motion.time
    for ax, letter in zip(axes, letters, strict=True):
        torque = r.data["motor_torque"].sel(axis=letter).values
        temp = r.data["temperature"].sel(axis=letter).values
        ax.plot(t, torque, color="tab:blue", linewidth=0.8)
        ax.set_ylabel(f"{letter} torque [N·m]", color="tab:blue")
        for rev in r.axes[letter].reversals:
            ax.axvline(rev.time, color="red", linewidth=0.4, alpha=0.5)
        twin = ax.twinx()
        twin.plot(t, temp, color="tab:orange")
        twin.set_ylabel("°C", color="tab:orange")
    axes[-1].set_xlabel("time [s] (red: reversals)")
    fig.tight_layout()
    return fig


def time_series_csv(r: ProgramResult) -> bytes:
    """The time series, one row per sample, units in the header."""
    ds = r.data
    header = ["time [s]", "block line", "path speed [m/s]"]
    # The line of each sample's block (0: a program without blocks, one sample at rest).
    lines = r.program.line[r.motion.block] if r.program.size else np.zeros_like(r.motion.block)
    cols = [r.motion.time, lines, r.motion.path_speed]
    for letter in r.axes:
        for name, unit in (("position", "m"), ("velocity", "m/s"), ("acceleration", "m/s^2"),
                           ("jerk", "m/s^3"), ("motor_torque", "N*m"),
                           ("friction_torque", "N*m"), ("friction_power", "W"),
                           ("temperature", "degC")):  # fmt: skip
            header.append(f"{letter} {name.replace('_', ' ')} [{unit}]")
            cols.append(ds[name].sel(axis=letter).values)
    table = np.column_stack(cols)
    return csv_bytes(header, table.tolist())


def _blocks_csv(r: ProgramResult) -> bytes:
    letters = list(r.axes)
    rows = [
        [int(line), *(float(r.axes[k].energy_per_block[i]) for k in letters),
         *(float(r.axes[k].supplied_per_block[i]) for k in letters)]
        for i, line in enumerate(r.program.line)
    ]  # fmt: skip
    header = ["line", *(f"{k} friction energy [J]" for k in letters),
              *(f"{k} energy supplied [J]" for k in letters)]  # fmt: skip
    return csv_bytes(header, rows)


def _reversals_csv(r: ProgramResult) -> bytes:
    rows = [
        [k, rev.line, rev.time, rev.position * 1e3, rev.load_before, rev.load_after,
         rev.load_direction, rev.friction_force, rev.stiffness / 1e6, rev.lost_motion * 1e6]
        for k, a in r.axes.items() for rev in a.reversals
    ]  # fmt: skip
    return csv_bytes(
        ["axis", "line", "time [s]", "position [mm]", "load before [N]", "load after [N]",
         "load direction", "friction force [N]", "stiffness [N/um]", "lost motion [um]"],
        rows,
    )  # fmt: skip


def summary_rows(r: ProgramResult) -> list[list[str]]:
    """The summary table: one row per quantity, one column per axis."""
    spec = [
        ("energy supplied [J]", "supplied_energy", 4),
        ("energy taken back [J]", "regenerated_energy", 4),
        ("process work [J]", "process_work", 4),
        ("screw friction [J]", "friction_energy", 4),
        ("support bearings [J]", "bearing_energy", 4),
        ("friction share", "friction_share", 0),
        ("peak motor torque [N*m]", "peak_torque", 3),
        ("RMS motor torque [N*m]", "rms_torque", 3),
        ("start / top temperature [degC]", None, 0),
        ("thermal lead error over the travel [um]", None, 0),
        ("reversals (load +/+, +/-, -/+, -/-)", None, 0),
    ]
    rows = []
    for label, attr, digits in spec:
        row = [label]
        for a in r.axes.values():
            if attr is not None:
                value = getattr(a, attr) + 0.0  # + 0.0: no "-0"
                row.append(
                    "-"
                    if np.isnan(value)
                    else f"{value:.1%}"
                    if attr == "friction_share"
                    else num(value, digits)
                )
            elif label.startswith("start"):
                row.append(f"{a.start_temperature:.1f} / {a.max_temperature:.2f}")
            elif label.startswith("thermal"):
                row.append(num(a.thermal_lead_error * 1e6, 2))
            else:
                kinds = [rev.load_direction for rev in a.reversals]
                row.append(f"{len(kinds)} ({kinds.count('+/+')}, {kinds.count('+/-')}, "
                           f"{kinds.count('-/+')}, {kinds.count('-/-')})")  # fmt: skip
        rows.append(row)
    rows += drive_rows(r)
    rows.append(["RMS / rated motor torque"] + [
        "-" if a.rated_torque is None else f"{a.rms_torque / a.rated_torque:.0%}"
        for a in r.axes.values()
    ])  # fmt: skip
    rows.append(["peak / peak motor torque"] + [
        "-" if a.peak_rating is None else f"{a.peak_torque / a.peak_rating:.0%}"
        for a in r.axes.values()
    ])  # fmt: skip
    rows.append(["top / rated motor speed"] + [
        "-" if a.rated_speed is None else f"{a.peak_speed / a.rated_speed:.0%}"
        for a in r.axes.values()
    ])  # fmt: skip
    return rows


def drive_rows(r: ProgramResult) -> list[list[str]]:
    """The motor's and drive's losses and the energy from the grid, a row each.

    "-": not computed; the report's "left out" list says why.
    """
    link = next((a.drive.dc_link for a in r.axes.values()
                 if a.drive is not None and a.drive.dc_link is not None), None)  # fmt: skip
    mode = "" if link is None else link.mode
    given = next((a.drive.spec for a in r.axes.values() if a.drive is not None), None)
    alone = " (axis alone)" if given is not None and given.shared else ""
    back = {"regenerative": [(f"of it returned to the grid{alone} [J]", "returned_to_grid_J")],
            "resistor": [(f"of it burnt in the braking resistor{alone} [J]", "burnt_J")],
            "storage": [(f"of it burnt, the storage full{alone} [J]", "burnt_J"),
                        (f"left in the storage{alone} [J]", "stored_J")]}.get(mode, [])  # fmt: skip
    spec = [
        ("copper loss [J]", "copper_loss_J"),
        ("motor iron and friction loss [J]", "motor_iron_loss_J"),
        ("drive loss [J]", "drive_loss_J"),
        ("regenerated into the DC link [J]", "dc_link_regenerated_J"),
        *back,
        (f"energy from the grid{alone} [J]", "grid_energy_J"),
    ]
    rows = []
    for label, key in spec:
        cells = [None if a.drive is None else a.drive.as_dict()[key] for a in r.axes.values()]
        rows.append([label, *("-" if v is None else num(v) for v in cells)])
    return rows


VERDICT_ROWS = (
    ("lift_off", "lift-off"),
    ("dn", "d*n"),
    ("rms_torque", "RMS torque"),
    ("peak_torque", "peak torque"),
    ("motor_speed", "motor speed"),
    ("travel", "travel"),
    ("thermal_error", "thermal lead error per 300 mm"),
)
"""The check's rows each axis's verdict line shows (the row's key, its label), whatever their
verdict; any other row is shown where it is not OK."""


def _row_text(label: str, c: Criterion) -> str:
    if c.value is None:
        return f"{label} not checked ({c.advice})"
    if c.limit is None:
        why = " (no accuracy grade)" if c.key == "thermal_error" else ""
        return f"{label} {num(c.value)} {c.unit}{why}"
    use = "" if c.utilisation is None else f"{c.utilisation:.0%}"
    mark = "" if c.verdict in ("OK", "INFO") else f" {c.verdict}"
    return f"{label} {num(c.value)} of {num(c.limit)} {c.unit} ({use}{mark})"


def verdict_lines(r: ProgramResult) -> list[str]:
    """Each axis's verdict line: the check's verdict and its rows that matter on a program.

    ``X: CHECK: lift-off 1350 of 10760 N (13%); d*n 120000 of 130000 mm*rpm (92% CHECK);
    ...``: lift-off (peak axial force against 2^1.5 times the preload), d·n, RMS and
    peak motor torque and motor speed against their ratings, the travel used, the
    thermal lead error per 300 mm (against the accuracy grade when the case gives
    one), then any other row of ``ballscrew check`` that is not OK.
    """
    lines = []
    for letter, a in r.axes.items():
        if a.check is None:
            why = next((n for n in a.notes if n.startswith("not checked")), "not checked")
            lines.append(f"{letter}: NOT CHECKED: {why.removeprefix('not checked ')}")
            continue
        parts, shown = [], set()
        for key, label in VERDICT_ROWS:
            for c in a.verdicts:
                if c.key == key:
                    parts.append(_row_text(label, c))
                    shown.add(c.key)
        flagged = ("CHECK", "NOT OK", "NOT CHECKED")
        parts += [_row_text(c.name, c) for c in a.verdicts
                  if c.key not in shown and c.verdict in flagged]  # fmt: skip
        lines.append(f"{letter}: {a.verdict}: " + "; ".join(parts))
    return lines


def warning_lines(r: ProgramResult) -> list[str]:
    """One line per row that is NOT OK, naming its axis, the value, the limit and the remedy."""
    out = []
    for letter, a in r.axes.items():
        for c in a.verdicts:
            if c.verdict != "NOT OK":
                continue
            use = "" if c.utilisation is None else f"{c.utilisation:.0%} "
            change = f"; to change: {c.advice}" if c.advice else ""
            out.append(f"{letter}: {c.name} {num(c.value)} {c.unit}, limit {num(c.limit)} "
                       f"{c.unit}: {use}NOT OK{change}")  # fmt: skip
    return out


def axis_notes(a: AxisResult) -> list[str]:
    """The axis's notes, each naming its axis."""
    return [f"{a.letter}: {n}" for n in a.notes]


def note_lines(r: ProgramResult) -> list[str]:
    """Every note of the run, then each axis's, naming its axis.

    The reader's notes come first, the words it skipped in one line.
    """
    return list(r.notes) + [n for a in r.axes.values() for n in axis_notes(a)]


def write_program_report(out: str | Path, r: ProgramResult) -> list[Path]:
    """Write the report files into ``out``; returns the paths written."""
    folder = Path(out)
    (folder / "data").mkdir(parents=True, exist_ok=True)
    figures = {
        "path": (_path_figure(r), "The tool path (X, Y) coloured by the screws' friction power; "
                 "reversals of each axis marked"),
        "energy": (_energy_figure(r), "Energy per axis by where it goes"),
        "torque": (_torque_figure(r), "Motor torque (blue) and screw temperature (orange); "
                   "reversals in red"),
    }  # fmt: skip
    written, images = write_figures(folder, {k: fig for k, (fig, _) in figures.items()})
    written += write_data(folder, (("time_series", time_series_csv(r)), ("blocks", _blocks_csv(r)),
                                   ("reversals", _reversals_csv(r))))  # fmt: skip
    blocks = [
        Block("h1", f"Part program on {r.machine}"),
        Block("p", f"Computed by ballscrew {__version__}: {r.program.size} blocks, "
              f"{r.motion.duration:.4g} s (nominal {r.motion.nominal_time:.4g} s at the "
              "programmed feeds)."),
        Block("table", (["quantity", *r.axes], summary_rows(r))),
        Block("h2", "Verdicts"),
        Block("ul", verdict_lines(r)),
        *(Block("img", (k, caption)) for k, (_, caption) in figures.items()),
        Block("h2", "Notes"),
        Block("ul", note_lines(r) or ["none"]),
        Block("h2", "Left out of the energy from the grid"),
        Block("ul", [n for a in r.axes.values() if a.drive is not None
                     for n in a.drive.left_out] or ["nothing: every constant was given"]),
    ]  # fmt: skip
    return written + write_pages(folder, blocks, f"Part program: {r.machine}", images)
