"""``ballscrew program``: a machine's feed axes through a part program."""

from __future__ import annotations

from pathlib import Path

import click

from ..io.files import read_input_text
from ..io.numbers import text as num
from .common import folder_option, json_option, progress, stdout, write_outputs

__all__ = ["NOT_OK_STATUS", "program_command"]

NOT_OK_STATUS = 3
"""Exit status of a program run whose check finds an axis NOT OK (2: input refused,
1: internal error, as every command)."""


@click.command("program")
@click.argument("program_file", type=click.Path(dir_okay=False))
@click.option("--machine", "machine_file", required=True, type=click.Path(dir_okay=False),
              help="Machine file: the axes by program letter, their cases and limits.")  # fmt: skip
@folder_option("Write a report (Markdown, HTML, plots, CSV) into this folder.")
@json_option("Write the results as JSON to FILE ('-' for standard output).")
@click.option("--csv", "csv_file", default=None,
              help="Write the time series (every axis, units in the header) to FILE.")  # fmt: skip
@click.option("--reader", type=click.Choice(["auto", "builtin", "rs274"]), default="auto",
              show_default=True,
              help="Who reads the program: the built-in reader, LinuxCNC's rs274, or auto "
              "(the built-in reader; rs274 when it refuses and rs274 is on the PATH).")  # fmt: skip
@click.option("--tool-table", "tool_table", default=None,
              type=click.Path(exists=True, dir_okay=False),
              help="A LinuxCNC tool table for rs274 (lengths, diameters in inches).")  # fmt: skip
def program_command(
    program_file: str,
    machine_file: str,
    out_dir: str | None,
    json_file: str | None,
    csv_file: str | None,
    reader: str,
    tool_table: str | None,
) -> int:
    """Energy, torques, heat and reversals of every feed axis over a G-code program.

    Each axis gets a verdict line with ballscrew check's criteria over the
    program (lift-off, d*n, motor RMS and peak torque and speed, travel,
    thermal lead error); a criterion NOT OK is also a 'warning:' line on
    standard error.

    \b
    Exit status:
      0  every axis OK or CHECK
      3  an axis NOT OK (the warning lines say which and why)
      2  input refused (one 'error:' line), 1 internal error

    \b
    Example:
      ballscrew program examples/pocket_contour_drill.nc --machine examples/machine_vmc.toml
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from ..io.extras import require
    from ..io.machine import load_machine

    require("program", "ballscrew program")
    from ..program import read_part_program, run_program
    from ..report.outputs import json_document
    from ..report.program import (
        note_lines,
        summary_rows,
        time_series_csv,
        verdict_lines,
        warning_lines,
    )

    machine = load_machine(machine_file)
    text = read_input_text("PROGRAM", program_file)
    if not text.strip():  # a failed copy or post: not a program that moves nothing
        from ..errors import BallScrewInputError

        raise BallScrewInputError(
            "PROGRAM", program_file, "a G-code program (this file is empty, or blank lines only)"
        )
    read = read_part_program(
        text, reader=reader, arc_tolerance=machine.arc_tolerance,
        directory=Path(program_file).parent, tool_table=tool_table, machine=machine,
    )  # fmt: skip
    click.echo(f"reader: {read.reason}", err=True)
    err = stdout("-")
    with progress(err) as bar:
        task = bar.add_task("planning the blocks", total=None)

        def tell(stage: str, done: int, total: int) -> None:
            label = "planning the blocks" if stage == "plan" else "the axes through the program"
            bar.update(task, description=label, completed=done, total=total)

        result = run_program(machine, read.program, progress=tell)
    for note in note_lines(result):
        click.echo(f"note: {note}", err=True)
    from rich.table import Table

    out = stdout("-" if csv_file == "-" else json_file)
    table = Table(
        title=f"{machine.title}: {result.program.size} blocks, "
        f"{num(result.motion.duration)} s (nominal {num(result.motion.nominal_time)} s)"
    )
    for column in ("quantity", *result.axes):
        table.add_column(column, justify="right")
    for row in summary_rows(result):
        table.add_row(*row)
    out.print(table)
    totals = result.as_dict()["machine_totals"]
    share = totals["friction_share"]
    out.print(
        f"machine: {num(totals['supplied_energy_J'])} J supplied to the feed axes, "
        f"{num(totals['regenerated_energy_J'])} J taken back, {num(totals['process_work_J'])} J "
        f"process work, {num(totals['friction_energy_J'])} J screw friction "
        f"({'-' if share is None else f'{share:.1%}'} with the bearings)"
    )  # fmt: skip
    grid = totals["grid_energy_J"]
    out.print(
        "machine: energy from the grid not computed (see the notes)" if grid is None else
        f"machine: {num(grid)} J from the grid for the feed axes"
        f"{' (one shared DC link)' if totals['dc_link_shared'] else ''}: "
        f"{num(totals['copper_loss_J'])} "
        f"J copper loss, {num(totals['motor_iron_loss_J'] or 0.0)} J motor iron loss, "
        f"{num(totals['drive_loss_J'])} J drive loss, {num(totals['burnt_J'])} J burnt, "
        f"{num(totals['returned_to_grid_J'])} J returned"
        + (f", {num(totals['stored_J'])} J left in the storage" if totals["stored_J"] else "")
    )  # fmt: skip
    for note in totals["left_out"]:
        click.echo(f"left out: {note}", err=True)
    for line in verdict_lines(result):
        out.print(line, highlight=False, markup=False, soft_wrap=True)
    warned = warning_lines(result)
    for line in warned:
        click.echo(f"warning: {line}", err=True)
    from ..report.program import write_program_report

    # The CSV, the report and the JSON are put in place together, or none of them.
    write_outputs(
        [("--csv", csv_file, time_series_csv(result) if csv_file else b""),
         ("--json", json_file,
          json_document(result.as_dict()).encode("utf-8") if json_file else b"")],
        (out_dir, lambda folder: write_program_report(folder, result)),
    )  # fmt: skip
    return NOT_OK_STATUS if warned else 0
