"""``ballscrew export-friction``: friction parameters for a servo drive."""

from __future__ import annotations

import sys
from pathlib import Path

import click
from rich.table import Table

from .._version import __version__
from .common import case_option, stdout, write_json, writing

__all__ = ["export_friction_command"]


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
        with writing("--out", out_file):
            atomic_write(Path(out_file), csv_text(result.rows).encode("utf-8"))
    if json_file:
        write_json(json_file, json_document(result.as_dict(__version__)))
    sys.stdout.flush()
