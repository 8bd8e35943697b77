"""``ballscrew contour``: the circular test and the reversal test of simulated axes."""

from __future__ import annotations

import sys
from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import click
from rich.console import Console
from rich.table import Table

from ..io.numbers import text as num
from .common import (
    folder_option,
    json_option,
    progress,
    result_document,
    stdout,
    write_json,
    write_outputs,
)

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
              "case's [axis] pre_rolling_length, else 5 um; 1 to 20 um is what a measured "
              "rolling guide allows, docs: positioning-accuracy).")  # fmt: skip
@click.option("--rigid", is_flag=True, help="One-mass axes (no spring between motor and table).")
@click.option("--max-samples", type=click.IntRange(min=1), default=None, metavar="N",
              help="The most samples simulated (all circles and reversals, both axes), "
              "estimated before the run: 2 pi R/(v T_s) per revolution; default "
              "4,000,000 (about 15 s of CPU).")  # fmt: skip
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
    max_samples: int | None,
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

    Before any circle runs, each axis is checked: the velocity and position
    loops' phase margins at least 30 deg and gain margins at least 6 dB, the
    sampling frequency at least 10 times each loop's bandwidth, and, with the
    case's [motor], the motor speed the feed needs at most rated_speed, the
    peak torque (whole mass at the path's peak acceleration v^2/R, plus
    friction) at most peak_torque. A loop past those
    minimums but stable (a margin above 0, sampling above twice the bandwidth)
    is CHECK: warned, drawn. An unstable loop, sampling below twice a bandwidth
    or a feed past the motor is NOT OK: printed with its margin, no circle
    drawn, the verdict in --json (no report), exit status 2. A run of more
    than --max-samples samples is refused before it starts, with the estimate.

    \b
    Example:
      ballscrew contour --case examples/xy_table_32x10.toml --radius "50 mm" --feed "2 m/min"
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from ..io.case import load_case
    from ..io.extras import require
    from ..servo import run_contour

    require("servo", "ballscrew contour")
    if len(case_files) > 2:
        raise click.UsageError("--case is given once (both axes) or twice (x, y)")
    cases = [load_case(f) for f in case_files] if case_files else [load_case(None)]
    runs = len(directions or ("CCW", "CW")) * 2 + 2
    with progress(Console(stderr=True)) as bar:
        task = bar.add_task("loops and drive checked", total=runs)

        def advance(what: str) -> None:
            bar.update(task, description=what)
            bar.advance(task)

        result = _run(run_contour, cases, radius, feed, directions, model_name, sampling_time,
                      kv, phase_margin, feed_forward, feedback, guide_friction, rigid,
                      pre_rolling, max_samples, advance)  # fmt: skip
    console = stdout(json_file)
    if result.verdict == "NOT OK":
        _refuse(console, result, json_file, out_dir)
    for c in result.checks:
        if c.status == "CHECK":
            click.echo(f"warning: CHECK {c.text()}", err=True)
    _print(console, result)
    for note in _merged(result.notes):
        click.echo(f"note: {note}", err=True)
    from ..report.contour import write_contour_report

    # The report and the JSON are put in place together, or neither.
    write_outputs(
        [("--json", json_file, result_document(result.as_dict()) if json_file else b"")],
        (out_dir, lambda folder: write_contour_report(folder, result)),
    )
    sys.stdout.flush()


def _run(run_contour: Any, cases: list[Any], radius: str, feed: str,
         directions: tuple[str, ...], model_name: str, sampling_time: str, kv: str,
         phase_margin: str, feed_forward: bool, feedback: str, guide_friction: str | None,
         rigid: bool, pre_rolling: str | None, max_samples: int | None,
         advance: Any) -> ContourResult:  # fmt: skip
    """The options in SI, to :func:`ballscrew.servo.run_contour`.

    The radius, feed, sampling time and phase margin are refused here, as typed (the
    run's own checks name them in SI: '--radius = 0.0 ... [m]').
    """
    import math

    from ..errors import BallScrewInputError
    from ..io.units import to_si
    from ..servo.verdict import MAX_SAMPLES

    def positive(flag: str, text: str, unit: str, example: str) -> float:
        value = to_si(flag, text, unit)
        if not value > 0.0:
            raise BallScrewInputError(flag, text, f"more than 0, e.g. '{example}'")
        return value

    margin = to_si("--phase-margin", phase_margin, "rad")
    if not 0.0 < margin < 0.5 * math.pi:
        raise BallScrewInputError("--phase-margin", phase_margin,
                                  "between 0 and 90 deg, e.g. '45 deg'")  # fmt: skip
    return run_contour(  # type: ignore[no-any-return]
        cases, radius=positive("--radius", radius, "m", "50 mm"),
        feed=positive("--feed", feed, "m/s", "2 m/min"),
        model=model_name, directions=directions or ("CCW", "CW"),
        sampling_time=positive("--sampling-time", sampling_time, "s", "250 us"),
        kv=to_si("--kv", kv, "1/s"), phase_margin=margin,
        velocity_ff=1.0 if feed_forward else 0.0, acceleration_ff=1.0 if feed_forward else 0.0,
        feedback=feedback,
        guide_coulomb=to_si("--guide-friction", guide_friction, "N") if guide_friction else None,
        rigid=rigid,
        pre_rolling_length=to_si("--pre-rolling", pre_rolling, "m") if pre_rolling else None,
        max_samples=MAX_SAMPLES if max_samples is None else max_samples, on_step=advance,
    )  # fmt: skip


class LoopNotOK(click.ClickException):
    """A circle that the loops or the drive cannot run: exit status 2, one line."""

    exit_code = 2


def _refuse(console: Console, result: ContourResult, json_file: str | None,
            out_dir: str | None) -> None:  # fmt: skip
    """Print the failed checks with their margins, write the JSON verdict, and stop."""
    from .._version import __version__
    from ..report.outputs import json_document

    table = Table(title=f"NOT OK: the circle of {result.axes[0].name} cannot run as set")
    for column in ("axis", "check", "value", "limit", "margin", "verdict"):
        table.add_column(column, justify="right")
    failed = [c for c in result.checks if not c.ok]
    for c in failed:
        table.add_row(c.axis, c.name, f"{num(c.value)} {c.unit}",
                      f"{'>=' if c.floor else '<='} {num(c.limit)} {c.unit}",
                      f"{num(c.margin)} {c.unit}", c.status)  # fmt: skip
    console.print(table)
    if json_file:
        write_json(json_file, json_document({"ballscrew": __version__, **result.as_dict()}))
    reasons = _merged([f"{c.axis}: {c.text().partition(': ')[2]}" for c in failed])
    kept = "" if out_dir is None else "; no report written"
    raise LoopNotOK(f"NOT OK, no circle drawn{kept}: " + "; ".join(reasons))


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
    reduction = "" if result.reduction is None else f"{result.reduction:.3g}"
    console.print(f"glitch reduction by the compensation: {reduction or 'not run'}"
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
    low = min(result.checks, key=lambda c: c.margin / max(abs(c.limit), 1e-300), default=None)
    console.print(f"verdict: {result.verdict} ({len(result.checks)} checks of the loops' "
                  "margins, the sampling and the drive"
                  + (f"; the closest: {low.text()})" if low else ")"))  # fmt: skip
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
