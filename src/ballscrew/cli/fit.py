"""``ballscrew fit`` and ``ballscrew export-friction``: calibrate a model, export friction."""

from __future__ import annotations

import sys
from pathlib import Path

import click
from rich.table import Table

from .common import case_option, stdout, write_json

__all__ = ["export_friction_command", "fit_command"]


@click.command("fit")
@case_option
@click.option("--measured", "measured_file", required=True, type=click.Path(dir_okay=False),
              help="Measured torque CSV (units in the header; optional temperature and "
              "axial load columns).")  # fmt: skip
@click.option("--model", "model_name", default="complete", show_default=True,
              help="Friction model to calibrate.")  # fmt: skip
@click.option("--free", "free_text", required=True,
              help="Parameters to fit, comma-separated: preload, limiting_shear_coefficient, "
              "ball_train_constant, boundary_friction, ... (see docs).")  # fmt: skip
@click.option(
    "--start",
    "start_text",
    default=None,
    help="Start values with units, e.g. 'preload=1.5 kN, ball_train_constant=0.03'.",
)
@click.option(
    "--temperature",
    default=None,
    help="Lubricant temperature where the CSV has none (default: the case's first).",
)
@click.option(
    "--axial-load",
    default=None,
    help="Axial load where the CSV has none (default: the case's first).",
)
@click.option("--out", "out_dir", type=click.Path(file_okay=False), default=None,
              help="Write the fitted case, residuals (CSV, plot) and a report here.")  # fmt: skip
@click.option("--json", "json_file", default=None,
              help="Write the fit as JSON to FILE ('-' for standard output).")  # fmt: skip
def fit_command(
    case_file: str | None,
    measured_file: str,
    model_name: str,
    free_text: str,
    start_text: str | None,
    temperature: str | None,
    axial_load: str | None,
    out_dir: str | None,
    json_file: str | None,
) -> None:
    """Fit model parameters to a measured torque curve, with 95 % intervals.

    \b
    Example:
      ballscrew fit --case my_screw.toml --measured run.csv \\
        --free preload,ball_train_constant --out fit
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from ..errors import BallScrewInputError
    from ..fit.calibration import FITTABLE, fit_parameters
    from ..friction import get_model
    from ..io.case import load_case
    from ..io.measured import read_measured
    from ..units import to_si

    case = load_case(case_file)
    model = get_model(model_name).name
    measured = read_measured(measured_file, case.screw)
    free = [f.strip() for f in free_text.split(",") if f.strip()]
    start: dict[str, float] = {}
    for part in (p.strip() for p in (start_text or "").split(",") if p.strip()):
        key, sep, value = part.partition("=")
        key = key.strip()
        if not sep or key not in FITTABLE:
            raise BallScrewInputError("--start", part, f"name=value with a unit; names: "
                                      f"{', '.join(sorted(FITTABLE))}")  # fmt: skip
        start[key] = to_si(f"--start {key}", value.strip(), FITTABLE[key].unit.replace("-", ""))
    temp = (to_si("--temperature", temperature, "degC") if temperature
            else float(case.temperature.flat[0]))  # fmt: skip
    load = (to_si("--axial-load", axial_load, "N") if axial_load
            else float(case.axial_load.flat[0]))  # fmt: skip
    with stdout(json_file).status(f"fitting {', '.join(free)} of {model}"):
        result = fit_parameters(
            case.screw, case.lubricant, measured, free, model=model, temperature=temp,
            axial_load=load, parameters=dict(case.model_parameters.get(model, {})), start=start,
        )  # fmt: skip
    table = Table(title=f"{case.title}: {model} fitted to {measured.source} "
                  f"({measured.speed.size} points)")  # fmt: skip
    for column in ("parameter", "start", "fitted", "95 % interval", "unit"):
        table.add_column(column, justify="right")
    for name, e in result.estimates.items():
        span = f"{e.low:.4g} .. {e.high:.4g}" if e.low is not None else "not identified"
        table.add_row(name, f"{e.start:.4g}", f"{e.value:.4g}", span, e.unit)
    console = stdout(json_file)
    console.print(table)
    console.print(f"RMS residual: {result.rms_residual:.4g} N*m")
    for note in result.warnings:
        click.echo(f"warning: {note}", err=True)
    payload = {"ballscrew": _version(), "case": case.title, "measured": measured.source,
               **result.as_dict()}  # fmt: skip
    if out_dir:
        from ..report.fit import write_fit_report

        files = write_fit_report(out_dir, case, result, payload)
        click.echo(f"fit: {Path(out_dir) / 'report.html'} and {Path(out_dir) / 'fitted-case.toml'}"
                   f" ({len(files)} files)", err=True)  # fmt: skip
    if json_file:
        from ..report.outputs import json_document

        write_json(json_file, json_document(payload))


def _version() -> str:
    from .. import __version__

    return __version__


@click.command("export-friction")
@case_option
@click.option("--model", "model_name", default="complete", show_default=True)
@click.option("--form", type=click.Choice(["coulomb-viscous", "stribeck", "lugre", "table"]),
              default="stribeck", show_default=True, help="Form the controller takes.")  # fmt: skip
@click.option(
    "--temperature",
    default=None,
    help="Temperature(s), e.g. '20, 40 degC' (default: the case's first).",
)
@click.option("--speed", default="0.1..3000:60 rpm", show_default=True,
              help="Screw speeds of the curve (both directions are fitted); for a range the "
              "points are spaced logarithmically.")  # fmt: skip
@click.option("--axial-load", default=None, help="Axial load (default: the case's first).")
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
    help="CSV: the lookup table (form table) or the model and fitted curves.",
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
    inertia: str | None,
    bristle_stiffness: str | None,
    bristle_damping: str | None,
    out_file: str | None,
    json_file: str | None,
) -> None:
    """Friction parameters for a servo controller, fitted to a model's torque-speed curve.

    \b
    Examples:
      ballscrew export-friction --case my_screw.toml --form stribeck --temperature "20, 40 degC"
      ballscrew export-friction --case my_screw.toml --form table --out friction_table.csv
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from ..files import atomic_write
    from ..fit.controller import TABLE_SIDE, UNITS
    from ..fit.export import export_friction, log_speeds
    from ..io.case import load_case
    from ..kinematics import rad_s_to_rpm
    from ..report.outputs import csv_text, json_document
    from ..units import parse_range, to_si

    def si(flag: str, text: str | None, unit: str) -> float | None:
        return to_si(flag, text, unit) if text else None

    result = export_friction(
        load_case(case_file), model_name, form,
        temperatures=parse_range("--temperature", temperature, "degC") if temperature else None,
        speeds=log_speeds(speed), axial_load=si("--axial-load", axial_load, "N"),
        inertia=si("--inertia", inertia, "kg*m**2"),
        bristle_stiffness=si("--bristle-stiffness", bristle_stiffness, "N*m/rad"),
        bristle_damping=si("--bristle-damping", bristle_damping, "N*m*s/rad"),
    )  # fmt: skip
    console = stdout(json_file)
    lo, hi = rad_s_to_rpm(result.speeds[0]), rad_s_to_rpm(result.speeds[-1])
    for temp, fitted in result.fitted:
        table = Table(title=f"{result.case.title}: {form} fit of {result.model} at {temp:g} degC, "
                      f"{result.axial_load:g} N")  # fmt: skip
        for column in ("parameter", "screw side", "unit", "table side", "unit "):
            table.add_column(column, justify="right")
        side = fitted.as_dict(result.lead)["table_side"]
        for name, value in fitted.parameters.items():
            t_name = TABLE_SIDE.get(name, (None,))[0]
            t_val = side.get(t_name) if t_name else None
            shown = (f"{t_val['value']:.5g}", t_val["unit"]) if t_val else ("", "")
            table.add_row(name, f"{value:.5g}", UNITS[name], *shown)
        console.print(table)
        console.print(f"fit error: RMS {fitted.rms_error:.3g} N*m, max {fitted.max_error:.3g} N*m "
                      f"over {lo:.3g} to {hi:.4g} rpm both ways")  # fmt: skip
        for note in fitted.notes:
            click.echo(f"note: {note}", err=True)
    if form == "table":
        click.echo(f"lookup table: {len(result.rows)} rows over {len(result.temperatures)} "
                   "temperature(s)", err=json_file == "-")  # fmt: skip
    if out_file:
        atomic_write(Path(out_file), csv_text(result.rows).encode("utf-8"))
    if json_file:
        write_json(json_file, json_document(result.as_dict(_version())))
    sys.stdout.flush()
