"""``ballscrew export-friction``: friction parameters for a servo drive."""

from __future__ import annotations

import sys
from dataclasses import dataclass
from pathlib import Path
from typing import TYPE_CHECKING, Any

import click
from rich.console import Console
from rich.table import Table

from .._version import __version__
from ..errors import BallScrewInputError
from ..io.numbers import text as num
from .common import case_option, require_case, stdout, write_outputs, writing

if TYPE_CHECKING:
    from ..io.case import Case
    from ..servo.controller import FrictionForm
    from ..servo.export import FrictionExport
    from ..servo.friction_map import FrictionMap

__all__ = ["export_friction_command"]


@click.command("export-friction")
@case_option
@click.option("--model", "model_name", default="complete", show_default=True,
              help="Friction model of the exported curve (see 'ballscrew models').")  # fmt: skip
@click.option("--form", type=click.Choice(["coulomb-viscous", "stribeck", "lugre", "table",
                                           "load-map", "lincurve", "frict-comp", "charcurve"]),
              default="stribeck", show_default=True,
              help="Form the controller takes; load-map: the friction over speed, signed axial "
              "load and temperature with a compact load- and direction-dependent form, written "
              "by --out as .csv, .mat, .mo (Modelica), .h (C) or .fmu (FMI 2.0, sources and this "
              "platform's binary); "
              "lincurve (LinuxCNC, 16 points), frict-comp (TwinCAT CNC, 20 points, needs "
              "--drive-unit and --axis-number), charcurve (CODESYS, 11 points): a "
              "compensation table.")  # fmt: skip
@click.option(
    "--torque-constant",
    default=None,
    help="Motor torque constant K_t, e.g. '1.2 N*m/A', for a frict-comp --drive-unit in current "
    "(default: the case's [motor] torque_constant).",
)
@click.option("--axis", "axis_name", default=None,
              help="Axis of a controller table, e.g. 'X': the lincurve instance x-friction, "
              "TwinCAT's kopf.log_achs_name, the CODESYS block FB_Friction<axis>.")  # fmt: skip
@click.option(
    "--axis-number",
    default=None,
    type=int,
    help="frict-comp: the logical axis number (kopf.achs_nr) of the start-up list.",
)
@click.option("--drive-unit", default=None,
              help="frict-comp: the unit of the drive's torque (act_torque), e.g. '0.1 % of "
              "3.2 N*m' (per thousand of rated torque), '1 mA' or '0.001 N*m'.")  # fmt: skip
@click.option("--cnc-build", default=None,
              help="frict-comp: the TwinCAT CNC build, e.g. 'V3.1.3132.0' (from it on the "
              "table is written with decimals; integers before).")  # fmt: skip
@click.option("--append", is_flag=True,
              help="lincurve: add this axis to the HAL file --out (one loadrt line for all "
              "axes; an axis of the same name is replaced).")  # fmt: skip
@click.option(
    "--temperature",
    default=None,
    help="Temperature(s), e.g. '20, 40 degC' (default: the case's first).",
)
@click.option("--speed", default="0.1..3000:60 rpm", show_default=True,
              help="Screw speeds of the curve (both directions are fitted), or feeds (e.g. "
              "'0.1..5 m/min') read as screw speeds at the case's lead; for a range the points "
              "are spaced logarithmically.")  # fmt: skip
@click.option("--axial-load", default=None,
              help="Axial load (default: the case's first); with load-map signed loads, e.g. "
              "'-4..4:9 kN' (default: the case's loads, mirrored, and 0).")  # fmt: skip
@click.option("--measured", "measured_file", default=None, type=click.Path(dir_okay=False),
              help="Fit the form to this measured torque-speed CSV (units in the header) "
              "instead of the model's curve, with 95 % intervals.")  # fmt: skip
@click.option("--inertia", default=None,
              help="Axis inertia at the screw for LuGre's damping rule, e.g. '5e-3 kg*m**2' "
              "(default: from the case's [axis]).")  # fmt: skip
@click.option("--bristle-stiffness", default=None, help="LuGre sigma_0, e.g. '2000 N*m/rad'.")
@click.option("--bristle-damping", default=None, help="LuGre sigma_1, e.g. '5 N*m*s/rad'.")
@click.option(
    "--out",
    "out_file",
    type=click.Path(dir_okay=False),
    default=None,
    help="CSV: the lookup table (form table) or the model and fitted curves; with load-map "
    "the suffix chooses .csv, .mat, .mo, .h or .fmu. A .csv gets its inputs in "
    "FILE.meta.json beside it.",
)
@click.option(
    "--json",
    "json_file",
    default=None,
    help="Write the parameters as JSON to FILE ('-' for standard output).",
)
def export_friction_command(
    case_file: str | None,
    model_name: str,
    form: str,
    temperature: str | None,
    speed: str,
    axial_load: str | None,
    measured_file: str | None,
    inertia: str | None,
    bristle_stiffness: str | None,
    bristle_damping: str | None,
    out_file: str | None,
    json_file: str | None,
    torque_constant: str | None,
    axis_name: str | None,
    axis_number: int | None,
    drive_unit: str | None,
    cnc_build: str | None,
    append: bool,
) -> None:
    """Friction parameters for a servo controller, fitted to a model's torque-speed curve.

    \b
    Examples:
      ballscrew export-friction --case my_screw.toml --form stribeck --temperature "20, 40 degC"
      ballscrew export-friction --case my_screw.toml --form table --out friction_table.csv
      ballscrew export-friction --form load-map --axial-load "-4..4:9 kN" \\
          --temperature "20, 30, 40 degC" --out friction.mat
      ballscrew export-friction --case x.toml --form lincurve --speed "5 m/min" \\
          --axis X --out friction.hal
      ballscrew export-friction --case y.toml --form lincurve --speed "5 m/min" \\
          --axis Y --append --out friction.hal
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    if form in ("lincurve", "frict-comp", "charcurve"):
        write_controller_table(case_file, model_name, form, temperature, speed, axial_load,
                               out_file, json_file,
                               ControllerFileArgs(torque_constant, axis_name, axis_number,
                                                  drive_unit, cnc_build, append))  # fmt: skip
        return
    for flag, given in (("--torque-constant", torque_constant),
                        ("--axis", axis_name), ("--axis-number", axis_number),
                        ("--drive-unit", drive_unit), ("--cnc-build", cnc_build),
                        ("--append", append or None)):  # fmt: skip
        if given is not None:
            raise click.UsageError(f"{flag} is an option of the controller tables "
                                   "(--form lincurve, frict-comp or charcurve)")  # fmt: skip
    from ..io.case import load_case
    from ..io.measured import read_measured
    from ..io.units import Reading, parse_range, to_si
    from ..servo.export import FrictionExport, log_speeds, run_export_friction

    def si(flag: str, text: str | None, unit: str, positive: bool = False) -> float | None:
        value = to_si(flag, text, unit) if text else None
        if positive and value is not None and not value > 0.0:
            raise BallScrewInputError(flag, text, f"more than 0 (in e.g. '{unit}')")
        return value

    if measured_file is not None:
        require_case(case_file, "export-friction --measured",
                     "a measured torque is turned into forces with the case's lead")  # fmt: skip
    case = load_case(case_file)
    read: list[Reading] = []
    speeds = log_speeds(speed, case.screw.lead, read)
    for reading in read:
        click.echo(f"note: {reading}", err=True)
    temps = parse_range("--temperature", temperature, "degC") if temperature else None
    if form == "load-map":  # signed loads; the options of a fitted form do not apply
        loads = parse_range("--axial-load", axial_load, "N") if axial_load else None
        result = run_export_friction(case, model_name, form, speeds=speeds, temperatures=temps,
                                     loads=loads)  # fmt: skip
    else:
        result = run_export_friction(
            case, model_name, form, temperatures=temps, speeds=speeds,
            measured=read_measured(measured_file, case.screw) if measured_file else None,
            axial_load=si("--axial-load", axial_load, "N"),
            inertia=si("--inertia", inertia, "kg*m**2", positive=True),
            bristle_stiffness=si("--bristle-stiffness", bristle_stiffness, "N*m/rad",
                                 positive=True),
            bristle_damping=si("--bristle-damping", bristle_damping, "N*m*s/rad",
                               positive=True),
        )  # fmt: skip
    if isinstance(result, FrictionExport):
        _print_export(result, form, out_file, json_file)
    else:
        _print_map(result, case, out_file, json_file)
    sys.stdout.flush()


def _write(
    case: Case, out: tuple[str | None, bytes], json_file: str | None, document: dict[str, Any]
) -> None:
    """``--out`` (a CSV with its provenance in FILE.meta.json) and ``--json``, put together.

    Written through :func:`~ballscrew.cli.common.write_outputs`: all of them in place, or
    none (a run stopped on the way leaves the earlier ones as they were).
    """
    from ..report.outputs import json_document, json_text, provenance

    out_file, data = out
    files: list[tuple[str, str | None, bytes]] = [("--out", out_file, data)]
    if out_file and out_file != "-" and out_file.lower().endswith(".csv"):
        meta = json_text([], provenance(case, {}, ["ballscrew", *sys.argv[1:]]))
        files.append(("--out", out_file + ".meta.json", meta.encode("utf-8")))
    if json_file:
        text = json_document({"ballscrew": __version__, **document})
        files.append(("--json", json_file, text.encode("utf-8")))
    write_outputs(files)


def _print_export(
    result: FrictionExport, form: str, out_file: str | None, json_file: str | None
) -> None:
    """The fitted forms' tables and notes; the CSV and the JSON."""
    from ..report.outputs import csv_text

    console = stdout("-" if "-" in (out_file, json_file) else None)
    for temp, fitted in result.fitted:
        _print_fit(console, result, temp, fitted)
    for note in result.notes:
        click.echo(f"note: {note}", err=True)
    if form == "table":
        click.echo(f"lookup table: {len(result.rows)} rows over {len(result.temperatures)} "
                   "temperature(s)", err="-" in (out_file, json_file))  # fmt: skip
    data = csv_text(result.rows).encode("utf-8") if out_file else b""
    _write(result.case, (out_file, data), json_file, result.as_dict())


def _print_fit(console: Console, result: FrictionExport, temp: float, fitted: FrictionForm) -> None:
    """One fitted form's table (screw and table side, intervals, motor side) and its error."""
    from ..kinematics import rad_s_to_rpm
    from ..servo.controller import TABLE_SIDE, UNITS

    lo, hi = rad_s_to_rpm(result.speeds[0]), rad_s_to_rpm(result.speeds[-1])
    source = (f"the measured curve {Path(result.measured).name}" if result.measured
              else f"{result.model} at {temp:g} degC, {num(result.axial_load)} N")  # fmt: skip
    if result.measured and len(result.fitted) > 1:  # one fit per measured temperature
        source += f" at {temp:g} degC"
    table = Table(title=f"{result.case.title}: {result.form} fit of {source}")
    columns = ["parameter", "screw side", "unit", "table side", "unit "]
    intervals = fitted.intervals or {}
    if fitted.intervals is not None:
        columns.insert(2, "95 % interval")
    if result.gear_ratio != 1.0:
        columns.append(f"motor side (gear {result.gear_ratio:g})")
    for column in columns:
        table.add_column(column, justify="right")
    doc = fitted.as_drive_dict(result.lead, result.gear_ratio)
    side = doc["table_side"]
    for name, value in fitted.parameters.items():
        t_name = TABLE_SIDE.get(name, (None,))[0]
        t_val = side.get(t_name) if t_name else None
        shown = [f"{num(t_val['value'])}", t_val["unit"]] if t_val else ["", ""]
        cells = [name, f"{num(value)}", UNITS[name], *shown]
        if fitted.intervals is not None:
            lo_hi = intervals.get(name)
            cells.insert(2, f"{num(lo_hi[0])} to {num(lo_hi[1])}" if lo_hi else "")
        if result.gear_ratio != 1.0:
            cells.append(f"{num(doc['motor_side'][name]['value'])}")
        table.add_row(*cells)
    console.print(table)
    what = "of the measured curve" if result.measured else "both ways"
    console.print(f"fit error: RMS {fitted.rms_error:.3g} N*m, max {fitted.max_error:.3g} N*m "
                  f"over {lo:.3g} to {num(hi)} rpm {what}")  # fmt: skip
    for note in fitted.notes:
        click.echo(f"note: {note}", err=True)


def _print_map(m: FrictionMap, case: Case, out_file: str | None, json_file: str | None) -> None:
    """``export-friction --form load-map``: the compact form's table, the notes and the file."""
    import numpy as np

    from ..report.friction_files import map_file

    console = stdout("-" if "-" in (out_file, json_file) else None)
    fit = m.form.as_drive_dict(m.lead, m.gear_ratio)
    table = Table(title=f"{m.case_title}: load map of {m.model}, {m.speeds.size} speeds x "
                  f"{m.loads.size} loads x {m.temperatures.size} temperatures")  # fmt: skip
    for column in ("parameter", "screw side", "table side", "motor side"):
        table.add_column(column, justify="right")
    for key in ("c0", "c1", "c2", "b"):
        table.add_row(key, *(f"{num(fit[side][key]['value'])} {fit[side][key]['unit']}"
                             for side in ("screw_side", "table_side", "motor_side")))  # fmt: skip
    for key in ("k_c", "k_b"):
        table.add_row(key, f"{num(fit[key]['value'])} {fit[key]['unit']}", "", "")
    console.print(table)
    console.print(f"compact form: {fit['formula']}")
    console.print(f"fit error over the grid: RMS {m.form.rms_error:.3g} N*m, "
                  f"max {m.form.max_error:.3g} N*m (screw side)")  # fmt: skip
    if not np.any(m.loads):
        click.echo("note: no axial load on the grid: c1 and c2 are not identified "
                   "(give --axial-load, e.g. '-4..4:9 kN')", err=True)  # fmt: skip
    for note in m.notes:
        click.echo(f"note: {note}", err=True)
    data, notes = map_file(m, Path(out_file), __version__) if out_file else (b"", [])
    for note in notes:
        click.echo(f"note: {note}", err=True)
    _write(case, (out_file, data), json_file, m.as_dict())


# --- the controllers' tables: --form lincurve | frict-comp | charcurve ----------------------


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
    from ..io.units import Reading, parse_range, parse_speed_range, to_si
    from ..report.controller_tables import (
        LINCURVE_MARK,
        TABLE_WRITERS,
        FileOptions,
        merge_lincurve,
    )
    from ..servo.tables import DriveUnit, controller_table

    _refuse_missing_controller_options(target, out_file, args)
    options = FileOptions(args.axis, args.axis_number, args.cnc_build)
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
    top = float(np.max(np.abs(screw))) * case.screw.lead / (2.0 * np.pi)
    if not top > 0.0:
        raise click.UsageError("--speed needs a positive speed for the table's range")
    temps = parse_range("--temperature", temperature, "degC") if temperature else None
    unit = DriveUnit.parse(args.drive_unit) if args.drive_unit else None
    k_t = to_si("--torque-constant", torque_constant, "N*m/A") if torque_constant else None
    if target == "frict-comp" and unit is not None and unit.kind == "current" and k_t is None:
        k_t = case.motor.get("torque_constant")
        if k_t is None:
            raise BallScrewInputError(
                "--torque-constant", "(not given)",
                "the motor's torque constant K_t, e.g. '1.2 N*m/A', or the case's [motor] "
                f"torque_constant (the drive's unit {unit.text!r} is a current)",
            )  # fmt: skip
        click.echo(f"note: --torque-constant: the case's motor.torque_constant, {k_t:g} N*m/A",
                   err=True)  # fmt: skip
    result = controller_table(
        case, model_name, target, speed_range=top,
        temperature=None if temps is None else float(np.ravel(temps)[0]),
        axial_load=to_si("--axial-load", axial_load, "N") if axial_load else None,
        torque_constant=k_t, drive_unit=unit,
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
    text = ""
    if out_file:
        text = TABLE_WRITERS[target](result, __version__, options)
        path = Path(out_file)
        if args.append and path.exists():
            with writing("--out", out_file):
                old = path.read_text("utf-8")
            text = merge_lincurve(old, text, __version__, out_file)
            if f"{LINCURVE_MARK}{options.instance} " in old:
                click.echo(f"note: {out_file}: the table of {options.instance} replaced", err=True)
    # The controller's file and the JSON are put in place together, or neither.
    _write(case, (out_file, text.encode("utf-8")), json_file, result.as_dict())
    sys.stdout.flush()


def _refuse_missing_controller_options(
    target: str, out_file: str | None, args: ControllerFileArgs
) -> None:
    """Refuse, before any computation, a controller file's options that do not go together."""
    if args.append and target != "lincurve":
        raise click.UsageError("--append adds an axis to a LinuxCNC HAL file (--form lincurve)")
    if args.append and not out_file:
        raise click.UsageError("--append needs --out, the HAL file to add the axis to")
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
