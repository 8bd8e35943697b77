"""``ballscrew torque``: friction torque, power loss and efficiency over a grid of points."""

from __future__ import annotations

import math
import sys
from typing import Any

import click
import numpy as np
from rich.console import Console
from rich.table import Table

from ..errors import BallScrewInputError
from ..io.units import Reading
from .common import (
    case_option,
    check_speeds,
    echo_readings,
    file_option,
    progress,
    stdout,
    units_option,
    verbose,
    write_outputs,
)

MAX_POINTS = 2_000_000
"""The most operating points ``ballscrew torque`` computes without ``--max-points``."""

BYTES_PER_POINT = {"compute": 1_500, "table": 3_000, "files": 6_000}
"""Peak memory per operating point [bytes], measured as the peak resident size over 2e5
points of the complete model: the model's arrays (1.4 kB with --table none); the rows of
a terminal table (4.2 kB in all with the summary); the rows and text of --json (7.2 kB in
all; --csv 2.9 kB, counted as --json). A run whose sum does not fit is refused before it
starts (:func:`ballscrew.io.resources.check_memory`), whatever ``--max-points`` says."""

__all__ = ["torque"]


@click.command()
@case_option
@click.option(
    "--model",
    "model_names",
    multiple=True,
    default=("complete",),
    show_default=True,
    help="Friction model; repeat for several.",
)
@click.option(
    "--speed",
    default=None,
    help="Screw speed(s), e.g. '0..3000 rpm', "
    "'0..3000:31 rpm' or '100, 1000 rpm', or feeds, e.g. '15 m/min' or '0..30 m/min:7', read "
    "as screw speeds at the case's lead (default: the case's).",
)
@click.option("--temperature", default=None, help="Temperature(s), e.g. '20, 40 degC'.")
@click.option("--axial-load", default=None, help="Axial load(s), e.g. '0, 2 kN'.")
@click.option(
    "--wiper-drag",
    default=None,
    help="Drag torque of the nut's wipers, e.g. '0.05 N*m' (default: the case's [screw] "
    "wiper_drag); the complete model adds it, the others leave it out with a note.",
)
@file_option(
    "--csv",
    "csv_file",
    "Write the table as CSV (units in the header; provenance in FILE.meta.json beside it).",
)
@click.option(
    "--csv-layout",
    type=click.Choice(["long", "wide"]),
    default="long",
    show_default=True,
    help="long: a row per model and point, with components; wide: a torque column per model.",
)
@click.option(
    "--csv-dialect",
    type=click.Choice(["comma", "semicolon-decimal-comma"]),
    default="comma",
    show_default=True,
    help="semicolon-decimal-comma for spreadsheets in decimal-comma locales.",
)
@file_option(
    "--json",
    "json_file",
    "Write the results and their provenance as JSON to FILE ('-' for standard output); "
    "results at full precision, each operating point as typed.",
)
@click.option(
    "--table",
    "table_kind",
    type=click.Choice(["auto", "full", "pivot", "summary", "none"]),
    default="auto",
    show_default=True,
    help="Terminal table: every row (full), torque as speeds x models (pivot), the range of "
    "each model (summary) or none. auto: full up to 40 rows, pivot up to 400, else summary.",
)
@click.option(
    "--max-points",
    type=click.IntRange(min=1),
    default=MAX_POINTS,
    show_default=True,
    help="The most operating points (speeds x temperatures x loads x models) computed; "
    "a run whose estimated memory exceeds half the available memory is refused whatever "
    "this says.",
)
@units_option
def torque(
    case_file: str | None,
    model_names: tuple[str, ...],
    speed: str | None,
    temperature: str | None,
    axial_load: str | None,
    wiper_drag: str | None,
    csv_file: str | None,
    csv_layout: str,
    csv_dialect: str,
    json_file: str | None,
    table_kind: str,
    max_points: int,
    units: str | None = None,
) -> None:
    """Friction torque, power loss and efficiency of one case over speeds, temperatures, loads.

    \b
    Examples:
      ballscrew torque --speed "0..3000:7 rpm"
      ballscrew torque --model olaru --model catalog --temperature "20, 45 degC" --csv t.csv
      ballscrew torque --case my_screw.toml --axial-load "0, 2 kN" --json t.json
      ballscrew torque --speed "100, 1000 rpm" --units imperial
      ballscrew torque --case my_screw.toml --speed "0..30 m/min:7"   # feeds, at the lead
      ballscrew torque --model complete --model catalog --csv t.csv --csv-layout wide \\
          --csv-dialect semicolon-decimal-comma
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from ..chain import model_named, torque_table
    from ..io.case import WIPER_PARAMETERS, load_case
    from ..io.display import unit_system
    from ..report.outputs import json_text
    from ..report.torque import TorqueRun

    case = load_case(case_file)
    echo_readings(case)
    system = unit_system("--units", units, case.output_units)
    if wiper_drag is not None:
        case = case.with_wiper_drag(wiper_drag, field="--wiper-drag")
    for name in model_names:
        model_named(name)
    read: list[Reading] = []
    w, t, f = _points(case, speed, temperature, axial_load, len(model_names), max_points, read)
    from ..io.resources import check_memory

    cost = BYTES_PER_POINT["compute"] + (BYTES_PER_POINT["table"] if table_kind != "none" else 0)
    cost += BYTES_PER_POINT["files"] if (csv_file or json_file) else 0
    check_memory("operating points", math.prod(np.size(a) for a in (w, t, f))
                 * len(model_names), cost, "operating points",
                 "take fewer speeds, temperatures, loads or models, or --table none without "
                 "--json and --csv")  # fmt: skip
    for reading in read:
        click.echo(f"note: {reading}", err=True)
    if np.any(np.asarray(w) < 0):
        click.echo("note: a negative speed turns the screw backwards; the torque and power "
                   "loss are printed as the drag's magnitudes, which oppose the rotation",
                   err=True)  # fmt: skip
    console = Console(stderr=True)
    with progress(console) as bar:
        task = bar.add_task("models", total=len(model_names))

        def advance(name: str) -> None:
            bar.update(task, description=name)
            bar.advance(task)

        table = torque_table(
            case.screw, case.lubricant, model_names, w, t, f,
            parameters={name: case.parameters_for(name) for name in model_names},
            ratings=case.load_ratings(),
            load_field="--axial-load" if axial_load is not None else "operation.axial_load",
            wiper_drag=case.wiper_drag, wiper_models=WIPER_PARAMETERS, on_model=advance,
        )  # fmt: skip
    run = TorqueRun(case, table, tuple(str(r) for r in read))
    for line in run.warning_lines(verbose=verbose()):
        click.echo(line, err=True)
    _print_table(run, table_kind, "-" if csv_file == "-" else json_file, system)
    command = ["ballscrew", *sys.argv[1:]]
    files: list[tuple[str, str | None, bytes]] = []
    if csv_file:
        files.append(("--csv", csv_file, run.csv(layout=csv_layout, dialect=csv_dialect).encode()))
        if csv_file.strip() == "-":  # standard output takes one file: no FILE.meta.json
            click.echo("note: the CSV went to standard output, its provenance nowhere "
                       "(--json carries it)", err=True)  # fmt: skip
        else:
            meta = json_text([], run.provenance(command))
            files.append(("--csv", csv_file + ".meta.json", meta.encode("utf-8")))
    if json_file:
        files.append(("--json", json_file, run.json(command).encode("utf-8")))
    # The CSV, its provenance and the JSON are put in place together, or none of them.
    write_outputs(files)


def _points(
    case: Any, speed: str | None, temperature: str | None, axial_load: str | None,
    models: int, max_points: int, read: list[Reading] | None = None,
) -> tuple[np.ndarray, np.ndarray, np.ndarray]:  # fmt: skip
    """The speeds [rad/s], temperatures [°C] and loads [N]: those given, else the case's.

    A feed given as ``--speed`` is the screw speed at the case's lead, told in ``read``.
    Refuses more than ``max_points`` points over the ``models`` before any is computed.
    """
    from ..io.units import parse_range, parse_speed_range

    w = (np.asarray(parse_speed_range("--speed", speed, case.screw.lead, notes=read))
         if speed is not None else case.speed)  # fmt: skip
    if speed is not None:
        check_speeds("--speed", speed, w)
    t = (
        np.asarray(parse_range("--temperature", temperature, "degC"))
        if temperature is not None
        else None
    )
    t = case.temperature if t is None else t
    f = np.asarray(parse_range("--axial-load", axial_load, "N")) if axial_load is not None else None
    f = case.axial_load if f is None else f
    points = math.prod(np.size(a) for a in (w, t, f)) * models
    if points > max_points:
        raise BallScrewInputError(
            "operating points", f"{points:,}",
            f"at most {max_points:,} (speeds x temperatures x loads x models); take fewer, or "
            "raise the limit with --max-points",
        )  # fmt: skip
    return w, t, f


def _print_table(run: Any, kind: str, json_file: str | None, system: str = "si") -> None:
    """The terminal table ``kind`` asks for (auto: by the number of rows), in ``system``'s units."""
    from ..io.display import display_row, system_note

    if kind == "none":  # no rows built: a large run keeps only its arrays
        return
    rows = [display_row(r, system) for r in run.rows]
    pivot_rows = len({(r[_label("temperature [degC]", rows)], r[_label("axial load [N]", rows)],
                       r["speed [rpm]"]) for r in rows})  # fmt: skip
    if kind == "auto":
        kind = "full" if len(rows) <= 40 else ("pivot" if pivot_rows <= 400 else "summary")
        if kind != "full":
            shown = "speeds x models" if kind == "pivot" else "a summary"
            click.echo(
                f"({len(rows):,} rows: shown as {shown}; --table full for all, --csv or --json "
                "to keep them)",
                err=json_file == "-",
            )
    table = {"full": _full_table, "pivot": _pivot_table, "summary": _summary_table}[kind]
    stdout(json_file).print(table(run.case.title, rows))
    if system != "si":
        stdout(json_file).print(system_note(system))


def _label(si_label: str, rows: list[dict[str, Any]]) -> str:
    """The key of the rows' column that ``si_label`` ('torque [N*m]') names, in their units."""
    name = si_label.split(" [")[0] + " ["
    return next((k for k in rows[0] if k.startswith(name)), si_label) if rows else si_label


def _summary_table(title: str, rows: list[dict[str, Any]]) -> Table:
    """Per model: the number of points and the range of torque, power loss and efficiency."""
    table = Table(title=f"{title}: friction torque, summary")
    torque = _label("torque [N*m]", rows)
    unit = torque.split(" [")[1]
    for column in ("model", "points", f"torque min [{unit}", f"torque max [{unit}",
                   "at speed [rpm]", "power loss max [W]", "efficiency min [-]"):  # fmt: skip
        table.add_column(column, justify="right")
    for model in dict.fromkeys(str(r["model"]) for r in rows):
        mine = [r for r in rows if r["model"] == model]
        top = max(mine, key=lambda r: r[torque])
        table.add_row(
            model, f"{len(mine):,}",
            _show(min(r[torque] for r in mine)), _show(top[torque]),
            _show(top["speed [rpm]"]), _show(max(r["power loss [W]"] for r in mine)),
            _show(min(r["efficiency [-]"] for r in mine)),
        )  # fmt: skip
    return table


def _full_table(title: str, rows: list[dict[str, Any]]) -> Table:
    main = {_label(c, rows) for c in _MAIN_COLUMNS}
    keys = [k for k in rows[0] if k in main]
    table = Table(title=f"{title}: friction torque", show_lines=False)
    for key in keys:
        table.add_column(key, justify="right", overflow="fold")
    for row in rows:
        table.add_row(*(_show(row[k]) for k in keys))
    return table


_MAIN_COLUMNS = (
    "model",
    "speed [rpm]",
    "temperature [degC]",
    "axial load [N]",
    "torque [N*m]",
    "power loss [W]",
    "efficiency [-]",
)


def _show(value: object) -> str:
    """A cell as shown: text as it is, a number to 4 significant digits (io.numbers)."""
    from ..io.numbers import text

    return text(value)


def _pivot_table(title: str, rows: list[dict[str, Any]]) -> Table:
    """Torque as rows of (temperature, load, speed) and a column per model, in the rows' units."""
    models = list(dict.fromkeys(str(r["model"]) for r in rows))
    cells: dict[tuple[Any, ...], dict[str, float]] = {}
    temp, load, torque = (_label(c, rows) for c in
                          ("temperature [degC]", "axial load [N]", "torque [N*m]"))  # fmt: skip
    for r in rows:
        key = (r[temp], r[load], r["speed [rpm]"])
        cells.setdefault(key, {})[str(r["model"])] = r[torque]
    table = Table(title=f"{title}: friction torque [{torque.split(' [')[1]}")
    for column in (temp, load, "speed [rpm]", *models):
        table.add_column(column, justify="right", overflow="fold")
    for (temp, load, rpm), by_model in sorted(cells.items()):
        table.add_row(
            _show(temp),
            _show(load),
            _show(rpm),
            *(_show(by_model.get(m, math.nan)) for m in models),
        )
    return table
