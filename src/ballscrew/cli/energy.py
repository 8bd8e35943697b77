"""``ballscrew energy``: friction energy, motor torques of a feed axis over a motion cycle."""

from __future__ import annotations

import math
from typing import TYPE_CHECKING

import click
from rich.console import Console
from rich.table import Table

from ..errors import BallScrewInputError
from ..io.numbers import text as num
from .common import (
    check_speeds,
    echo_readings,
    folder_option,
    json_option,
    motion,
    motion_options,
    run_time_si,
    stdout,
    units_option,
    verbose,
    write_outputs,
)

if TYPE_CHECKING:
    from ..axis.duty import EnergyRun
    from ..axis.thermal import SteadyAtSpeed

__all__ = ["energy_command"]


@click.command("energy")
@click.option("--case", "case_file", type=click.Path(dir_okay=False), default=None,
              help="Case file with an [axis] section (default: the bundled case).")  # fmt: skip
@motion_options
@click.option("--model", "model_names", multiple=True, default=["complete"], show_default=True,
              help="Friction model; repeat for several.")  # fmt: skip
@click.option("--temperature", default=None, help="Lubricant temperature, e.g. '40 degC' "
              "(default: the case's first).")  # fmt: skip
@click.option("--run-time", default="1 h", show_default=True,
              help="How long the cycle repeats, for the temperature reached.")  # fmt: skip
@click.option("--steady-speeds", default=None,
              help="Also the steady temperature and torque of continuous running at these "
              "speeds, e.g. '500..3000:6 rpm' (under the move's process force).")  # fmt: skip
@click.option("--standstill-speed", default="auto", show_default=True,
              help="With --profile: the speed from which the friction is full (none below "
              "half of it, a ramp between) instead of flipping sign, e.g. '0.3 mm/s'; 'auto' "
              "takes 8 times the speed noise of the file's positions, '0 mm/s' the exact "
              "sign.")  # fmt: skip
@folder_option("Write a report (Markdown, HTML, plots, CSV) into this folder.")
@json_option("Write the results as JSON to FILE ('-' for standard output).")
@units_option
def energy_command(
    case_file: str | None,
    move_text: str | None,
    cycles: int,
    model_names: tuple[str, ...],
    temperature: str | None,
    profile_file: str | None,
    run_time: str,
    out_dir: str | None,
    json_file: str | None,
    steady_speeds: str | None = None,
    units: str | None = None,
    standstill_speed: str = "auto",
) -> None:
    """Friction energy and motor torques of the case's axis over back-and-forth cycles.

    \b
    Example:
      ballscrew energy --case my_axis.toml --cycles 10 \\
        --move "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2, force=2 kN, \\
                force_from=50 mm, force_to=250 mm"
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from ..axis import run_energy
    from ..io.case import load_case
    from ..io.display import system_note, to_display, unit_system
    from ..io.units import parse_range, to_si
    from ..report.outputs import result_json
    from ..report.torque import warning_lines

    case = load_case(case_file)
    echo_readings(case)
    system = unit_system("--units", units, case.output_units)
    width = (None if standstill_speed.strip().lower() == "auto"
             else to_si("--standstill-speed", standstill_speed, "m/s"))  # fmt: skip
    if width is not None and not width >= 0.0:
        raise BallScrewInputError("--standstill-speed", standstill_speed, "a speed >= 0, or auto")
    profile, m = motion(move_text, profile_file, cycles, width)
    if profile.standstill_speed > 0.0:
        click.echo(f"note: standstill: no friction below half, the full friction from "
                   f"+-{num(profile.standstill_speed * 1e3)} mm/s of table speed "
                   f"({'8 x the speed noise of the positions' if width is None else 'as given'}"
                   "), so a measured axis at rest does not chatter", err=True)  # fmt: skip
    speeds = None if steady_speeds is None else parse_range("--steady-speeds", steady_speeds,
                                                              "rad/s")  # fmt: skip
    if speeds is not None:
        check_speeds("--steady-speeds", str(steady_speeds), speeds)
    temp = to_si("--temperature", temperature, "degC") if temperature else None
    run = run_energy(case, profile, model_names, cycles=cycles, temperature=temp,
                     run_time=run_time_si(run_time), steady_speeds=speeds,
                     move=m, motion_field="--move" if move_text else "--profile")  # fmt: skip
    for finding in run.findings:
        click.echo(f"warning: {finding}", err=True)
    for line in run.speed_warnings:
        click.echo(f"warning: {line}", err=True)
    frictions = {n: c.friction for n, c in run.cycles_by_model.items()}
    for line in warning_lines(frictions, verbose=verbose()):
        click.echo(line, err=True)  # the models' validity issues: lift-off, film, temperature
    for line in run.assumptions:
        click.echo(f"note: {line}", err=True)
    temp_shown, temp_unit = to_display(run.temperature, "degC", system)
    title = (f"{case.title}: {cycles} cycle(s), {num(profile.duration)} s, {num(temp_shown)} "
             f"{'°C' if temp_unit == 'degC' else temp_unit}")  # fmt: skip
    out = stdout(json_file)
    out.print(_results_table(title, run, run_time, system))
    _print_weight_verdicts(out, run)
    for name, r in run.results.items():
        losses = run.motor_losses(r.cycle)
        copper, iron = losses["copper_loss_J"], losses["motor_iron_loss_J"]
        parts = [f"copper loss {num(copper)} J" if copper is not None else "",
                 f"iron and friction loss {num(iron)} J" if iron is not None else ""]  # fmt: skip
        if any(parts):
            out.print(f"{name}: the motor's {', '.join(p for p in parts if p)} over the cycles")
        for note in losses["motor_losses_left_out"]:
            click.echo(f"note: {name}: {note}", err=True)
    force, force_unit = to_display(m.get("force", 0.0), "N", system)
    for name, at in run.steady.items():
        out.print(_steady_table(f"{name}: continuous running at {num(force)} {force_unit}", at,
                                system))  # fmt: skip
    if system != "si":
        out.print(system_note(system))
    from ..report.energy import write_energy_report

    # The report and the JSON are put in place together, or neither.
    write_outputs(
        [("--json", json_file, result_json(run).encode("utf-8") if json_file else b"")],
        (out_dir, lambda folder: write_energy_report(folder, run)),
    )


def _results_table(title: str, run: EnergyRun, run_time: str, system: str = "si") -> Table:
    """The results of each model over the cycles: energies, efficiencies, motor torques.

    Torques and temperatures in ``system``'s units; energies in J in every system.
    """
    from ..io.display import to_display

    _, torque = to_display(1.0, "N*m", system)
    _, degrees = to_display(1.0, "degC", system)
    table = Table(title=title)
    for column in ("model", "friction energy [J]", "per cycle [J]", "catalogue rule [J]",
                   "bearings [J]", "efficiency fwd / back", f"peak motor torque [{torque}]",
                   f"RMS motor torque [{torque}]",
                   f"temperature after {run_time} [{degrees}]"):  # fmt: skip
        table.add_column(column, justify="right")
    for name, r in run.results.items():
        c = r.cycle
        table.add_row(
            name,
            f"{num(c.friction_energy)}",
            f"{num(c.friction_energy / r.cycles)}",
            f"{num(c.constant_efficiency_energy)}",
            f"{num(c.bearing_energy)}",
            f"{c.forward_efficiency:.3f} / {c.reverse_efficiency:.3f}",
            f"{num(to_display(c.peak_motor_torque, 'N*m', system)[0])}",
            f"{num(to_display(c.rms_motor_torque, 'N*m', system)[0])}",
            f"{to_display(r.final_temperature, 'degC', system)[0]:.3g}",
        )
    return table


def _print_weight_verdicts(out: Console, run: EnergyRun) -> None:
    """Per model, whether the weight along an inclined axis back-drives the screw."""
    for name, r in run.results.items():
        eta = r.weight_reverse_efficiency
        if math.isnan(eta):
            continue
        # The catalogue's test: a load back-drives the screw when the reverse efficiency
        # is positive. The drag is (1 - eta) times the weight's torque F l / 2 pi.
        where = (f"{name}: the weight along the axis ({math.degrees(run.axis.incline):g} deg), "
                 f"motor off: reverse efficiency {eta:.3f}; ")  # fmt: skip
        if eta > 0.0:
            out.print(where + "it turns the screw: hold the axis with a brake")
        elif r.self_locking:
            out.print(where + "self-locking (the friction angle exceeds the lead angle)")
        else:
            out.print(
                where + f"holds at this load: the drag is {1.0 - eta:.3g} x the weight's "
                "torque. Not self-locking (the lead angle exceeds the friction angle): a "
                "heavier load, or less drag as the preload wears, turns the screw; keep a brake"
            )


def _steady_table(title: str, at: SteadyAtSpeed, system: str = "si") -> Table:
    """Steady temperature, torque and power of continuous running, one row per speed."""
    from ..io.display import to_display
    from ..kinematics import rad_s_to_rpm

    temps, degrees = to_display(at.temperature, "degC", system)
    torques, torque = to_display(at.torque, "N*m", system)
    table = Table(title=title)
    for column in ("speed [rpm]", f"steady temperature [{degrees}]", f"torque [{torque}]",
                   "power [W]"):  # fmt: skip
        table.add_column(column, justify="right")
    for w, tc, tq, pw in zip(at.speed, temps, torques, at.power, strict=True):
        table.add_row(f"{num(rad_s_to_rpm(w))}", f"{tc:.3g}", f"{num(tq)}", f"{num(pw)}")
    return table
