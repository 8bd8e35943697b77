"""Command-line interface: ``ballscrew COMMAND``.

Exit status: 0 on success, 2 on bad input (one line naming the field), 1 on
an internal error.
"""

from __future__ import annotations

import math
import os
import signal
import sys
from pathlib import Path

import click
import numpy as np
from rich.console import Console
from rich.table import Table

from .. import __version__, lubricants
from ..contact import HERTZ_METHODS, hertz
from ..errors import BallScrewInputError
from ..examples import reference_screw
from ..files import record_signal, signal_received
from ..kinematics import rpm_to_rad_s
from ..state import operating_state
from .case import case_command, screws_command
from .common import case_option, file_option, progress, stdout
from .energy import energy_command
from .fit import export_friction_command, fit_command
from .serve import serve_command
from .sweep import sweep_command
from .torque import torque

__all__ = ["main"]


@click.group(context_settings={"help_option_names": ["-h", "--help"]})
@click.version_option(__version__, prog_name="ballscrew")
def cli() -> None:
    """Ball screw friction torque, efficiency and power loss.

    \b
    Examples:
      ballscrew study --out report          # reproduce the study (bundled case)
      ballscrew case --template --out my_screw.toml
      ballscrew torque --case my_screw.toml --speed "0..3000 rpm" --model complete --model catalog
      ballscrew energy --case my_axis.toml --move "stroke=0.3 m, feed=0.5 m/s, acceleration=2 m/s^2"
      ballscrew fit --case my_screw.toml --measured run.csv --free preload,ball_train_constant
      ballscrew export-friction --case my_screw.toml --form stribeck --temperature "20, 40 degC"
      ballscrew sweep examples/sweep_preload.toml --out preload.zarr --workers 2
      ballscrew models
      ballscrew lubricants
      ballscrew serve                       # the web calculator on http://127.0.0.1:8050/
    """  # noqa: D301 - click needs the literal \b to keep the example lines


@cli.command()
@click.option(
    "--lubricant",
    "lubricant_name",
    default="PAO ISO VG 68",
    show_default=True,
    help="Name of a bundled lubricant.",
)
@click.option(
    "--temperature",
    default=40.0,
    show_default=True,
    type=float,
    help="Lubricant temperature for the film table [°C].",
)
def demo(lubricant_name: str, temperature: float) -> None:
    """Print a contact and lubricant summary for the bundled reference screw.

    \b
    Examples:
      ballscrew demo
      ballscrew demo --lubricant "SAE 20" --temperature 30
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    console = Console(width=110, markup=False)
    screw = reference_screw()
    oil = lubricants.get(lubricant_name)

    geo = Table(title="Reference ball screw (bundled example)", show_header=False)
    rows = [
        ("pitch diameter", f"{screw.pitch_diameter * 1e3:.2f} mm"),
        ("lead / lead angle", f"{screw.lead * 1e3:.2f} mm / {math.degrees(screw.lead_angle):.3f}°"),
        ("ball diameter", f"{screw.ball_diameter * 1e3:.3f} mm"),
        ("contact angle", f"{math.degrees(screw.contact_angle):.1f}°"),
        ("conformity screw / nut", f"{screw.conformity_screw:.3f} / {screw.conformity_nut:.3f}"),
        ("nut / preload", f"{screw.nut} / {screw.preload:.0f} N"),
        ("loaded balls per (half-)nut", f"{screw.balls_per_nut}"),
        ("reduced modulus E'", f"{screw.reduced_modulus / 1e9:.2f} GPa"),
    ]
    for key, value in rows:
        geo.add_row(key, value)
    console.print(geo)

    state0 = operating_state(screw, oil, speed=0.0, temperature=temperature)
    q = float(state0.loads.normal_load_1)
    ht = Table(title=f"Hertz contact at the preload, Q = {q:.2f} N per ball")
    for col in ("contact", "method", "a [mm]", "b [mm]", "a/b", "p_max [GPa]", "approach [µm]"):
        ht.add_column(col, justify="right")
    for side, rx, ry in (
        ("screw", screw.rx_screw, screw.ry_screw),
        ("nut", screw.rx_nut, screw.ry_nut),
    ):
        for method in HERTZ_METHODS:
            c = hertz(q, rx, ry, screw.reduced_modulus, method=method)
            ht.add_row(
                side,
                method,
                f"{float(c.a) * 1e3:.4f}",
                f"{float(c.b) * 1e3:.4f}",
                f"{float(c.ellipticity):.3f}",
                f"{float(c.p_max) / 1e9:.3f}",
                f"{float(c.approach) * 1e6:.3f}",
            )
    console.print(ht)

    temps = np.array([20.0, 30.0, 40.0, 45.0, 60.0, 100.0])
    vt = Table(title="Bundled lubricants: kinematic viscosity [mm²/s] (ASTM D341)")
    vt.add_column("lubricant")
    for t in temps:
        vt.add_column(f"{t:g} °C", justify="right")
    vt.add_column("α [1/GPa]", justify="right")
    for lub in lubricants.all_lubricants():
        nu = lub.kinematic_viscosity(temps) * 1e6
        vt.add_row(lub.name, *(f"{v:.1f}" for v in nu), f"{lub.pressure_viscosity * 1e9:.1f}")
    console.print(vt)

    speeds_rpm = np.array([10.0, 100.0, 1000.0, 3000.0])
    st = operating_state(screw, oil, speed=rpm_to_rad_s(speeds_rpm), temperature=temperature)
    ft = Table(title=f"EHL film of {oil.name} at {temperature:g} °C (Hamrock-Dowson 1977)")
    for col in ("contact", "speed [rpm]", "u [m/s]", "h_min [µm]", "h_c [µm]", "Λ", "A_c/A_0"):
        ft.add_column(col, justify="right")
    for contact in st.contacts[:2]:
        for i, n in enumerate(speeds_rpm):
            ft.add_row(
                contact.name,
                f"{n:g}",
                f"{contact.entrainment_speed[i]:.4f}",
                f"{contact.film_minimum[i] * 1e6:.4f}",
                f"{contact.film_central[i] * 1e6:.4f}",
                f"{contact.film_parameter[i]:.3f}",
                f"{contact.asperity_share[i]:.3f}",
            )
    console.print(ft)


@cli.command()
@case_option
@click.option(
    "--out",
    "out_dir",
    type=click.Path(file_okay=False),
    default="study-report",
    show_default=True,
    help="Folder for figures, CSV, report and run record.",
)
@file_option(
    "--measured",
    "measured_file",
    "Measured torque-speed CSV (units in the header) to overlay and score.",
)
@file_option(
    "--record", "record_file", "Regenerate the report of an earlier run from its run.json."
)
def study(
    case_file: str | None, out_dir: str, measured_file: str | None, record_file: str | None
) -> None:
    """Reproduce the study: figures, CSV data, a Markdown and HTML report, a run record.

    \b
    Examples:
      ballscrew study --out report
      ballscrew study --case my_screw.toml --measured friction.csv --out my_report
      ballscrew study --record report/run.json --out report-again
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from ..io.case import load_case
    from ..io.measured import read_measured
    from ..report.study import load_record, write_report
    from ..study.run import run_study

    console = Console(stderr=True)
    if record_file is not None:
        if case_file or measured_file:
            raise click.UsageError("--record replaces --case and --measured")
        case, measured, measured_text = load_record(record_file)
    else:
        case = load_case(case_file)
        measured, measured_text = None, None
        if measured_file is not None:
            measured = read_measured(measured_file, case.screw)
            measured_text = Path(measured_file).read_text("utf-8")
    with progress(console) as bar:
        task = bar.add_task("computing", total=9 + (measured is not None))

        def tick(text: str) -> None:
            bar.update(task, description=text, advance=1)

        result = run_study(case, measured, progress=tick)
        extra = result.sensitivity is not None
        task2 = bar.add_task("writing", total=len(result.figures) + 1 + extra)

        def tick2(text: str) -> None:
            bar.update(task2, description=text, advance=1)

        files: list[Path] = []
        expected = 3 * (len(result.figures) + extra) + 3
        try:
            write_report(result, out_dir, measured_text, progress=tick2, written=files)
        except KeyboardInterrupt:
            click.echo(
                f"interrupted: {len(files)} of {expected} files of {out_dir}/ were written "
                "(each complete); the others were not written or keep their previous content",
                err=True,
            )
            raise
    for message in result.validity:
        click.echo(f"warning: {message}", err=True)
    out = Path(out_dir)
    click.echo(f"report: {out / 'report.html'} (also report.md); {len(files)} files in {out}/")


@cli.command()
@click.option(
    "--out",
    "out_dir",
    type=click.Path(file_okay=False),
    default="validation",
    show_default=True,
    help="Folder for validation.csv, summary.csv, the figure and report.md/.html.",
)
@click.option(
    "--model", "model_names", multiple=True, help="Model to score; repeat (default: all)."
)
def validate(out_dir: str, model_names: tuple[str, ...]) -> None:
    """Score every model against the bundled reference cases and trends.

    The cases are catalogue drag torques over a grid of screw sizes, judged
    within the makers' own tolerance of the drag torque, Jungnickel's
    measured-loss law and its exponents, the trends of each model's error
    against the catalogue rule, and the published trends, each with its source
    and band. Prints, per model, how many of each group lie inside their band
    and the median |log10(predicted/reference)|.

    \b
    Examples:
      ballscrew validate --out scorecard
      ballscrew validate --model complete --model catalog
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from ..friction import MODELS, get_model
    from ..report.validation import summary_table, write_scorecard
    from ..study.validation import score, summarise

    names = [get_model(name).name for name in model_names] or None
    console = Console(stderr=True)
    with progress(console) as bar:
        total = len(names) if names else len(MODELS)
        task = bar.add_task("scoring", total=total)
        rows = score(names, progress=lambda name: bar.update(task, description=name, advance=1))
    files = write_scorecard(rows, out_dir)
    header, table_rows = summary_table(summarise(rows))
    # One column per model, one row per group: narrow enough for an 80-column terminal.
    table = Table(title="Validation scorecard (cases inside their band)")
    table.add_column("", no_wrap=True)
    for row in table_rows:
        table.add_column(row[0], overflow="fold")
    for k, label in enumerate(header[1:], start=1):
        table.add_row(label, *(row[k] for row in table_rows))
    stdout().print(table)
    click.echo(f"scorecard: {Path(out_dir) / 'report.html'} ({len(files)} files in {out_dir}/)")


@cli.command(name="models")
def models_command() -> None:
    """List the friction models with their references and validity ranges.

    \b
    Example:
      ballscrew models
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from ..chain import models
    from ..study.validation import bundled_summary

    scores = bundled_summary()
    table = Table(title="Friction models", show_lines=True)
    table.add_column("name", no_wrap=True)
    table.add_column("what it is for", overflow="fold")
    table.add_column("scorecard (ballscrew validate)", overflow="fold")
    for spec in models():
        s = scores.get(spec.name)
        accuracy = (
            "; ".join(f"{key}: {value}" for key, value in s.items() if key != "model")
            if s
            else "not scored"
        )
        table.add_row(spec.name, spec.purpose, accuracy)
    console = stdout()
    console.print(table)
    for spec in models():
        console.print(f"\n{spec.name}: {spec.title}", highlight=False)
        console.print(f"  reference: {spec.reference}", highlight=False)
        console.print(f"  validity: {spec.validity}", highlight=False)
        console.print("  parameters:", highlight=False)
        for k, v in spec.parameters.items():
            console.print(f"    {k} = {v!r}", highlight=False)


@cli.command(name="lubricants")
def lubricants_command() -> None:
    """List the bundled lubricants with their data and sources.

    \b
    Example:
      ballscrew lubricants
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    table = Table(title="Bundled lubricants", show_lines=True)
    for col in (
        "name",
        "ν40 [mm²/s]",
        "ν100 [mm²/s]",
        "ρ15 [kg/m³]",
        "α [1/GPa]",
        "τ0 [MPa]",
        "γ_L",
        "source",
    ):
        table.add_column(col)
    for oil in lubricants.all_lubricants():
        table.add_row(
            oil.name,
            f"{oil.nu40 * 1e6:g}",
            f"{oil.nu100 * 1e6:g}",
            f"{oil.density15:g}",
            f"{oil.pressure_viscosity * 1e9:g}",
            f"{oil.limiting_shear_stress / 1e6:g}",
            f"{oil.limiting_shear_coefficient:g}",
            oil.source,
        )
    stdout().print(table)


cli.add_command(torque)
cli.add_command(case_command)
cli.add_command(screws_command)
cli.add_command(energy_command)
cli.add_command(fit_command)
cli.add_command(export_friction_command)
cli.add_command(serve_command)
cli.add_command(sweep_command)


def _terminate(signum: int, frame: object) -> None:
    """Treat SIGTERM like Ctrl-C: unwind, keep only complete files, exit 130.

    The signal is also recorded: a library that turns the KeyboardInterrupt
    raised inside its own code into another exception (numpy does, in a
    comparison of structured arrays) must still end the run as interrupted,
    not as an internal error.
    """
    record_signal(signum)
    raise KeyboardInterrupt


def main(argv: list[str] | None = None) -> None:
    """Entry point of the ``ballscrew`` command.

    Exit status: 0 on success, 2 on bad input (one line on stderr naming the
    field and the problem), 1 on an internal error, 130 when interrupted.
    """
    record_signal(None)
    previous = signal.signal(signal.SIGTERM, _terminate)
    previous_int = signal.signal(signal.SIGINT, _terminate)
    try:
        status = cli.main(args=argv, prog_name="ballscrew", standalone_mode=False)
    except BallScrewInputError as exc:
        click.echo(f"error: {exc}", err=True)
        sys.exit(2)
    except click.exceptions.UsageError as exc:
        click.echo(f"error: {exc.format_message()} (see 'ballscrew --help')", err=True)
        sys.exit(2)
    except (click.exceptions.Abort, KeyboardInterrupt):
        click.echo(
            "interrupted: files already written are complete; nothing is half-written", err=True
        )
        sys.exit(130)
    except click.exceptions.ClickException as exc:
        click.echo(f"error: {exc.format_message()}", err=True)
        sys.exit(exc.exit_code)
    except Exception as exc:
        if signal_received():  # the interrupt, turned into another exception on its way up
            click.echo(
                "interrupted: files already written are complete; nothing is half-written",
                err=True,
            )
            sys.exit(130)
        if os.environ.get("BALLSCREW_TRACEBACK"):
            import traceback

            traceback.print_exc()
        click.echo(f"internal error: {type(exc).__name__}: {exc}", err=True)
        sys.exit(1)
    finally:
        signal.signal(signal.SIGTERM, previous)
        signal.signal(signal.SIGINT, previous_int)
    sys.exit(status if isinstance(status, int) else 0)
