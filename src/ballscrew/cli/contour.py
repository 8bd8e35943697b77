"""``ballscrew contour``: the circular test and the reversal test of simulated axes."""

from __future__ import annotations

import sys
from collections.abc import Sequence
from typing import TYPE_CHECKING

import click
from rich.console import Console
from rich.table import Table

from .common import folder_option, json_option, stdout, write_json, writing

if TYPE_CHECKING:
    from ..servo.contour import ContourResult

__all__ = ["contour_command"]


@click.command("contour")
@click.option("--case", "case_files", multiple=True, type=click.Path(dir_okay=False),
              help="Case file of the axes with [axis] (moving mass, inertias): once for both "
              "axes, twice for x then y.")  # fmt: skip
@click.option("--radius", default="50 mm", show_default=True, help="Radius of the circle.")
@click.option("--feed", default="2 m/min", show_default=True, help="Feed along the circle.")
@click.option("--direction", "directions", multiple=True, type=click.Choice(["CCW", "CW"]),
              help="Direction(s) run (default both).")  # fmt: skip
@click.option("--model", "model_name", default="complete", show_default=True,
              help="Friction model of the screws.")  # fmt: skip
@click.option("--sampling-time", default="250 us", show_default=True,
              help="Sampling time of the position and velocity loops.")  # fmt: skip
@click.option("--kv", default="40 1/s", show_default=True, help="Position loop gain k_v.")
@click.option("--phase-margin", default="45 deg", show_default=True,
              help="Phase margin of the velocity loop (symmetric optimum).")  # fmt: skip
@click.option("--feed-forward/--no-feed-forward", default=True, show_default=True,
              help="Velocity and acceleration feed-forward.")  # fmt: skip
@click.option("--feedback", type=click.Choice(["motor", "table"]), default="motor",
              show_default=True, help="Position read by the motor's encoder or a linear "
              "scale.")  # fmt: skip
@click.option(
    "--guide-friction",
    default=None,
    help="Coulomb friction of each axis' guideways, e.g. '40 N' (default: left out).",
)
@click.option("--pre-rolling", "pre_rolling", default=None,
              help="Pre-rolling length of the screws' drag, e.g. '10 um' (default: the "
              "case's [axis] pre_rolling_length, else 5 um).")  # fmt: skip
@click.option("--rigid", is_flag=True, help="One-mass axes (no spring between motor and table).")
@json_option("Write the results as JSON to FILE ('-' for standard output).")
@folder_option(
    "Write a report here: polar plot, reversal, tables (figures, CSV, Markdown, HTML, JSON)."
)
def contour_command(
    case_files: tuple[str, ...],
    radius: str,
    feed: str,
    directions: tuple[str, ...],
    model_name: str,
    sampling_time: str,
    kv: str,
    phase_margin: str,
    feed_forward: bool,
    feedback: str,
    guide_friction: str | None,
    pre_rolling: str | None,
    rigid: bool,
    json_file: str | None,
    out_dir: str | None,
) -> None:
    """Simulate a circular test (ISO 230-4) of two ball screw axes under CNC control.

    Each axis is a two-mass model from its case (motor side, table, the
    stiffness ballscrew check prints), the screw's drag the model's torque at
    the case's load and temperature, on the motor side, with pre-rolling; a
    position P loop with feed-forward, a velocity PI tuned by the symmetric
    optimum and a current loop. The circle is evaluated over one revolution
    after a lead-in arc of 15/k_v. Prints the circular deviation G and each
    quadrant glitch without and with the friction compensation of a 16-point
    table (at the commanded velocity, one sample late, as a controller applies
    it), the reversal test of the x axis, and the loops' margins and
    bandwidths.

    \b
    Example:
      ballscrew contour --case examples/xy_table_32x10.toml --radius "50 mm" --feed "2 m/min"
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from .._version import __version__
    from ..io.case import load_case
    from ..io.extras import require
    from ..io.units import to_si
    from ..report.outputs import json_document
    from ..servo import run_contour

    require("servo", "ballscrew contour")
    if len(case_files) > 2:
        raise click.UsageError("--case is given once (both axes) or twice (x, y)")
    cases = [load_case(f) for f in case_files] if case_files else [load_case(None)]
    result = run_contour(
        cases, radius=to_si("--radius", radius, "m"), feed=to_si("--feed", feed, "m/s"),
        model=model_name, directions=directions or ("CCW", "CW"),
        sampling_time=to_si("--sampling-time", sampling_time, "s"),
        kv=to_si("--kv", kv, "1/s"), phase_margin=to_si("--phase-margin", phase_margin, "rad"),
        velocity_ff=1.0 if feed_forward else 0.0, acceleration_ff=1.0 if feed_forward else 0.0,
        feedback=feedback,
        guide_coulomb=to_si("--guide-friction", guide_friction, "N") if guide_friction else None,
        rigid=rigid,
        pre_rolling_length=to_si("--pre-rolling", pre_rolling, "m") if pre_rolling else None,
    )  # fmt: skip
    console = stdout(json_file)
    _print(console, result)
    for note in _merged(result.notes):
        click.echo(f"note: {note}", err=True)
    if out_dir:
        from ..report.contour import write_contour_report

        with writing("--out", out_dir):
            write_contour_report(out_dir, result)
    if json_file:
        write_json(json_file, json_document({"ballscrew": __version__, **result.as_dict()}))
    sys.stdout.flush()


def _print(console: Console, result: ContourResult) -> None:
    """The circles, the reversals and the loops as tables."""
    doc = result.as_dict()
    table = Table(title=f"Circular test R {result.radius * 1e3:g} mm at "
                  f"{result.feed * 60:g} m/min: {result.axes[0].name}")  # fmt: skip
    for column in ("direction", "compensated", "G [um]", "glitch 0/90/180/270 deg [um]",
                   "width [deg]"):  # fmt: skip
        table.add_column(column, justify="right")
    for c in doc["circles"]:
        heights = " / ".join(f"{g['height_um']:.3g}" for g in c["glitches"])
        width = max(g["width_deg"] for g in c["glitches"])
        table.add_row(c["direction"], "yes" if c["compensated"] else "no",
                      f"{c['circular_deviation_G_um']:.3g}", heights, f"{width:.3g}")  # fmt: skip
    console.print(table)
    h = doc["circular_hysteresis_H_um"]
    console.print(f"glitch reduction by the compensation: {result.reduction:.3g}"
                  + (f"; circular hysteresis H {h:.3g} um" if h is not None else ""))  # fmt: skip
    for r in result.reversals:
        console.print(f"reversal of x at {r.acceleration:.3g} m/s^2 "
                      f"{'with' if r.compensated else 'without'} compensation: glitch "
                      f"{r.glitch * 1e6:.3g} um after {r.time_to_peak * 1e3:.3g} ms")  # fmt: skip
    from ..report.contour import loop_table

    loops = Table(title="Loops (control: linear, friction left out)")
    header, rows = loop_table(result)
    for column in header:
        loops.add_column(column, justify="right")
    for row in rows:
        loops.add_row(*row)
    console.print(loops)
    console.print(f"CPU time: {result.cpu_seconds:.3g} s")


def _merged(notes: Sequence[str]) -> list[str]:
    """The notes in order, each said once: 'x: T' and 'y: T' become 'x, y: T'.

    >>> _merged(["x: a", "y: a", "x: b", "c"])
    ['x, y: a', 'x: b', 'c']
    """
    axes: dict[str, list[str]] = {}
    for note in notes:
        head, sep, text = note.partition(": ")
        if sep and head.isidentifier() and len(head) <= 3:  # an axis' own note
            axes.setdefault(text, []).append(head)
        else:
            axes.setdefault(note, [])
    return [f"{', '.join(names)}: {text}" if names else text for text, names in axes.items()]
