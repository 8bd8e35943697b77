"""``ballscrew fit`` and ``ballscrew export-friction``: calibrate a model, export friction."""

from __future__ import annotations

import click
from rich.table import Table

from .._version import __version__
from ..io.numbers import text as num
from .common import (
    folder_option,
    json_option,
    own_case_option,
    require_case,
    stdout,
    write_outputs,
)

__all__ = ["fit_command"]


@click.command("fit")
@own_case_option
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
@folder_option("Write the fitted case, residuals (CSV, plot) and a report here.")
@json_option("Write the fit as JSON to FILE ('-' for standard output).")
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
    from ..chain import model_named
    from ..errors import BallScrewInputError
    from ..fit.calibration import FITTABLE, run_fit
    from ..io.case import load_case
    from ..io.measured import read_measured
    from ..io.units import to_si

    case = load_case(require_case(case_file, "fit",
                                  "the measurement is fitted on the case's screw"))  # fmt: skip
    model = model_named(model_name).name
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
    temp = to_si("--temperature", temperature, "degC") if temperature else None
    load = to_si("--axial-load", axial_load, "N") if axial_load else None
    with stdout(json_file).status(f"fitting {', '.join(free)} of {model}"):
        result = run_fit(case, measured, free, model=model, start=start, temperature=temp,
                         axial_load=load)  # fmt: skip
    table = Table(title=f"{case.title}: {model} fitted to {measured.source} "
                  f"({measured.speed.size} points)")  # fmt: skip
    for column in ("parameter", "start", "fitted", "95 % interval", "unit"):
        table.add_column(column, justify="right")
    for name, e in result.estimates.items():
        span = f"{num(e.low)} .. {num(e.high)}" if e.low is not None else "not identified"
        span += "" if result.reliable or e.low is None else " (unreliable)"
        table.add_row(name, f"{num(e.start)}", f"{num(e.value)}", span, e.unit)
    console = stdout(json_file)
    console.print(table)
    console.print(f"RMS residual: {num(result.rms_residual)} N*m")
    for note in result.warnings:
        click.echo(f"warning: {note}", err=True)
    if not result.reliable:
        click.echo("warning: the fit is absurd (above): its intervals are unreliable", err=True)
    payload = {"ballscrew": __version__, "case": case.title, "measured": measured.source,
               **result.as_dict()}  # fmt: skip
    from ..report.fit import write_fit_report
    from ..report.outputs import json_document

    # The report (with the fitted case) and the JSON are put in place together, or neither.
    write_outputs(
        [("--json", json_file, json_document(payload).encode("utf-8") if json_file else b"")],
        (out_dir, lambda folder: write_fit_report(folder, case, result, payload)),
        lambda folder, count: (
            f"fit: {folder / 'report.html'} and {folder / 'fitted-case.toml'} ({count} files)"
        ),
    )
