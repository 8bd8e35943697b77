"""``ballscrew monitor``: the preload over a screw's life from drag-torque measurements."""

from __future__ import annotations

import math
import sys
from pathlib import Path

import click
from rich.table import Table

from ..io.numbers import text as num
from .common import (
    json_option,
    own_case_option,
    require_case,
    result_document,
    stdout,
    write_outputs,
)

__all__ = ["monitor_command"]


@click.command("monitor")
@own_case_option
@click.option("--measured", "measured_file", required=True, type=click.Path(dir_okay=False),
              help="Series CSV: time and torque columns with units, optional speed and "
              "temperature, e.g. 'time [h],torque [N*m]'.")  # fmt: skip
@click.option("--model", "model_name", default="complete", show_default=True,
              help="The model that reads a torque as a preload.")  # fmt: skip
@click.option("--trend", type=click.Choice(["exponential", "linear"]), default="exponential",
              show_default=True, help="Form of the preload's decline over time.")  # fmt: skip
@click.option("--threshold", "limit", default=None,
              help="Preload to watch for: '50 %' (of the initial), '1.2 kN', or "
              "'lift-off 3 kN' (the preload below which 3 kN lifts a half-nut off).")  # fmt: skip
@click.option("--plot", "plot_file", type=click.Path(dir_okay=False), default=None,
              help="Write the figure (.png or .svg).")  # fmt: skip
@json_option("Write the result as JSON to FILE ('-' for standard output).")
def monitor_command(
    case_file: str | None, measured_file: str, model_name: str, trend: str,
    limit: str | None, plot_file: str | None, json_file: str | None,
) -> None:  # fmt: skip
    """The preload at each drag-torque measurement, its trend and when it crosses a threshold.

    \b
    Examples:
      ballscrew monitor --case my_screw.toml --measured drag_torque.csv --threshold "50 %"
      ballscrew monitor --case my_screw.toml --measured drag_torque.csv \\
          --threshold "lift-off 3 kN" --plot preload.png --json preload.json
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from ..errors import BallScrewInputError
    from ..fit.monitor import run_monitor
    from ..io.case import load_case
    from ..io.series import read_series
    from ..report.plotting import figure_bytes

    if plot_file and Path(plot_file).suffix.lower() not in (".png", ".svg"):
        raise BallScrewInputError("--plot", plot_file, "a file ending in .png or .svg")
    why = "a drag torque is read as a preload of the case's screw"
    case = load_case(require_case(case_file, "monitor", why))
    series = read_series(measured_file, case.screw)
    r = run_monitor(case, series, model=model_name, trend=trend, limit=limit)
    console = stdout(json_file)
    table = Table(title=f"Preload read by {r.model} from {Path(series.source).name}")
    for column in ("time [h]", "torque [N*m]", "preload [N]", "95 % interval [N]", "trend [N]"):
        table.add_column(column, justify="right")
    for i in range(series.time.size):
        table.add_row(f"{num(series.time[i])}", f"{num(series.torque[i])}", f"{num(r.preload[i])}",
                      f"{num(r.preload_low[i])} to {num(r.preload_high[i])}",
                      f"{num(r.trend[i])}")  # fmt: skip
    console.print(table)
    unit = "1/h" if trend == "exponential" else "N/h"
    console.print(f"trend ({trend}): initial {num(r.trend[0])} N "
                  f"(95 % {num(r.trend_low[0])} to {num(r.trend_high[0])}), slope {num(r.slope)} "
                  f"{unit}")  # fmt: skip
    if r.limit is not None:

        def hours(x: float) -> str:
            return f"{x:.0f} h" if math.isfinite(x) else "not excluded"

        crossing = hours(r.crossing) if math.isfinite(r.crossing) else "none (no decline)"
        console.print(f"threshold {r.limit.text}: crossed at {crossing}, 95 % "
                      f"{hours(r.crossing_low)} to {hours(r.crossing_high)}")  # fmt: skip
    for note in r.notes:
        click.echo(f"note: {note}", err=True)
    figure = b""
    if plot_file:
        from ..report.monitor import monitor_figure

        figure = figure_bytes(monitor_figure(r), Path(plot_file).suffix.lower()[1:])
    # The figure and the JSON are put in place together, or neither.
    write_outputs(
        [
            ("--plot", plot_file, figure),
            ("--json", json_file, result_document(r.as_dict()) if json_file else b""),
        ]
    )
    sys.stdout.flush()
