"""``ballscrew export-friction --form lincurve|frict-comp|charcurve``: a controller's table.

A helper of :mod:`ballscrew.cli.export_friction`, not a command of its own.
"""

from __future__ import annotations

import math
import sys
from dataclasses import dataclass
from pathlib import Path

import click
from rich.table import Table

from ..io.numbers import text as num
from .common import stdout, write_json, writing

__all__ = ["ControllerFileArgs", "write_controller_table"]


@dataclass(frozen=True)
class ControllerFileArgs:
    """The options of the controller files, as typed."""

    torque_constant: str | None = None
    axis: str | None = None
    axis_number: int | None = None
    drive_unit: str | None = None
    cnc_build: str | None = None
    append: bool = False


def write_controller_table(
    case_file: str | None, model_name: str, target: str, temperature: str | None, speed: str,
    axial_load: str | None, out_file: str | None, json_file: str | None,
    args: ControllerFileArgs,
) -> None:  # fmt: skip
    """Compute the table, print it with its error, write the controller's file and the JSON."""
    from .._version import __version__
    from ..io.case import load_case
    from ..io.files import atomic_write
    from ..io.units import Reading, parse_range, parse_speed_range, to_si
    from ..report.controller_tables import (
        LINCURVE_MARK,
        TABLE_WRITERS,
        FileOptions,
        merge_lincurve,
    )
    from ..report.outputs import json_document
    from ..servo.tables import DriveUnit, controller_table

    if args.append and target != "lincurve":
        raise click.UsageError("--append adds an axis to a LinuxCNC HAL file (--form lincurve)")
    if args.append and not out_file:
        raise click.UsageError("--append needs --out, the HAL file to add the axis to")
    options = FileOptions(args.axis, args.axis_number, args.cnc_build)
    if target == "frict-comp" and args.axis_number is None:
        raise click.UsageError(
            "--form frict-comp needs --axis-number, the axis' logical axis number for "
            "kopf.achs_nr (TwinCAT P-COMP-00001; it must equal the start-up list's)"
        )
    if target == "frict-comp" and args.drive_unit is None:
        raise click.UsageError(
            "--form frict-comp needs --drive-unit, the unit the drive reports its torque in "
            "(TwinCAT P-COMP-00047: the table's out is in the unit of dig_drv.act_torque), "
            "e.g. '0.1 % of 3.2 N*m' (per thousand of the rated torque, as CiA 402 drives "
            "give it), '0.1 % of 4.5 A' or '1 mA' with --torque-constant, or '0.001 N*m'"
        )
    torque_constant = args.torque_constant

    case = load_case(case_file)
    import numpy as np

    # A feed ('5 m/min') or a screw speed ('0.1..3000:60 rpm', the option's default) read
    # at the case's lead; the table spans the table speeds up to the fastest.
    read: list[Reading] = []
    screw = np.asarray(parse_speed_range("--speed", speed, case.screw.lead, notes=read),
                       dtype=float)  # fmt: skip
    for reading in read:
        click.echo(f"note: {reading}", err=True)
    top = float(np.max(np.abs(screw))) * case.screw.lead / (2.0 * math.pi)
    if not top > 0.0:
        raise click.UsageError("--speed needs a positive speed for the table's range")
    temps = parse_range("--temperature", temperature, "degC") if temperature else None
    result = controller_table(
        case, model_name, target, speed_range=top,
        temperature=None if temps is None else float(np.ravel(temps)[0]),
        axial_load=to_si("--axial-load", axial_load, "N") if axial_load else None,
        torque_constant=(to_si("--torque-constant", torque_constant, "N*m/A")
                         if torque_constant else None),
        drive_unit=DriveUnit.parse(args.drive_unit) if args.drive_unit else None,
    )  # fmt: skip
    console = stdout("-" if out_file == "-" else json_file)
    table = Table(title=f"{case.title}: {target} table of {result.model} at "
                  f"{num(result.axial_load)} N, {result.temperature:g} degC")  # fmt: skip
    for column in ("point", "speed [mm/s]", "force [N]", "motor torque [N*m]"):
        table.add_column(column, justify="right")
    torque = result.motor_torque()
    for k, (v, f) in enumerate(zip(result.table.speed, result.table.force, strict=True)):
        table.add_row(str(k), f"{num(v * 1e3)}", f"{num(f)}", f"{num(torque[k])}")
    console.print(table)
    tab = result.table
    console.print(f"interpolation error against the model over +-{num(top * 1e3)} mm/s: RMS "
                  f"{tab.rms_error:.3g} N, largest {tab.max_error:.3g} N")  # fmt: skip
    if out_file:
        text = TABLE_WRITERS[target](result, __version__, options)
        path = Path(out_file)
        if args.append and path.exists():
            with writing("--out", out_file):
                old = path.read_text("utf-8")
            text = merge_lincurve(old, text, __version__, out_file)
            if f"{LINCURVE_MARK}{options.instance} " in old:
                click.echo(f"note: {out_file}: the table of {options.instance} replaced", err=True)
        with writing("--out", out_file):
            atomic_write(path, text.encode("utf-8"))
    if json_file:
        write_json(json_file, json_document({"ballscrew": __version__, **result.as_dict()}))
    sys.stdout.flush()
