"""``ballscrew identify``: a machine's feed axes fitted to a measured drive trace."""

from __future__ import annotations

from typing import Any

import click

from .common import (
    folder_option,
    json_option,
    stdout,
    write_outputs,
)

__all__ = ["identify_command"]


def _constants(text: str | None) -> dict[str, float]:
    """``"X=1.2 N*m/A, Z=0.9 N*m/A"`` as {letter: K_t [N·m/A]}."""
    from ..errors import BallScrewInputError
    from ..io.units import to_si

    out: dict[str, float] = {}
    for part in (text or "").split(","):
        if not part.strip():
            continue
        letter, sep, value = part.partition("=")
        letter = letter.strip().upper()
        if not sep or letter not in ("X", "Y", "Z"):
            raise BallScrewInputError("--torque-constant", part.strip(),
                                      "LETTER=VALUE with its unit, e.g. 'X=1.2 N*m/A'")  # fmt: skip
        out[letter] = to_si(f"--torque-constant {letter}", value.strip(), "N*m/A")
    return out


def _refuse_unphysical_mass(result: Any, option: str) -> None:
    """Refuse to write a calibrated machine file whose fitted moving mass is 0 or less.

    ``ballscrew program`` refuses such a file ('axis.moving_mass ... 0 or more'): the fit
    printed above is kept, the file is not written, and the refusal says what to change.
    """
    from ..errors import BallScrewInputError

    for letter, fit in result.fits.items():
        mass = fit.parameters["moving_mass"]
        if mass.fitted and mass.identifiable and not mass.value > 0.0:
            raise BallScrewInputError(
                f"{option} (axes.{letter} moving mass fitted)", f"{mass.value:.4g} kg",
                f"a mass above 0, what a machine file holds (95 % interval {mass.low:.4g} to "
                f"{mass.high:.4g} kg): no physical mass explains this trace (see the notes); "
                "record one with more accelerations, or hold the case's mass (--free kt)",
            )  # fmt: skip


@click.command("identify")
@click.argument("trace_file", type=click.Path(dir_okay=False))
@click.option("--machine", "machine_file", required=True, type=click.Path(dir_okay=False),
              help="Machine file: the axes by program letter and their cases.")  # fmt: skip
@click.option("--map", "mappings", multiple=True, metavar="NAME=COLUMN",
              help="Name an export's column (repeat), e.g. 'joint.0.motor-pos-fb=X position "
              "[mm]' for a halscope log, 'Time=time [ms]' for a TwinCAT Scope CSV.")  # fmt: skip
@click.option("--torque-constant", "torque_constants", default=None, metavar="L=K_T,...",
              help="The motors' K_t (per A as the drive logs its current), e.g. 'X=1.2 "
              "N*m/A', over the cases' motor.torque_constant. With a K_t known the moving mass "
              "is fitted; without, K_t is fitted and the case's mass held.")  # fmt: skip
@click.option("--free", "free_names", default="", metavar="NAMES",
              help="Fit these too (kt, mass, s, fc, b, offset), e.g. 'kt': K_t fitted and the "
              "case's moving mass held. Default: the offset, the guideway's Coulomb and "
              "viscous friction and the mass (K_t known) or K_t (not known).")  # fmt: skip
@click.option("--hold", "hold_names", default="", metavar="NAMES",
              help="Hold these (at 0; the screw's scale at 1), e.g. 'offset' on a vertical "
              "axis, 'fc' with --free s.")  # fmt: skip
@click.option("--validate", "validate_file", default=None, type=click.Path(dir_okay=False),
              help="A second trace of the same machine: score the fit's prediction of "
              "it.")  # fmt: skip
@click.option("--standstill-speed", default="auto", show_default=True,
              help="Speed from which the friction is full (none below half of it); 'auto': 8 "
              "times the speed noise of the positions.")  # fmt: skip
@click.option("--smoothing", default="10 ms", show_default=True,
              help="Standard deviation of the Gaussian filter applied to the signal and the "
              "model alike (at least 1.5 samples).")  # fmt: skip
@click.option("--calibrated", "calibrated_file", default=None, type=click.Path(dir_okay=False),
              help="Write the calibrated machine file (TOML) to FILE.")  # fmt: skip
@click.option("--seed", default=0, show_default=True, type=click.IntRange(0, 2**32 - 1),
              help="Seed of the bootstrap's resamples.")  # fmt: skip
@folder_option("Write a report (Markdown, HTML, plots, CSV, calibrated.toml) into this folder.")
@json_option("Write the fit as JSON to FILE ('-' for standard output).")
def identify_command(
    trace_file: str, machine_file: str, mappings: tuple[str, ...],
    torque_constants: str | None, free_names: str, hold_names: str,
    validate_file: str | None, standstill_speed: str,
    smoothing: str, calibrated_file: str | None, seed: int, out_dir: str | None,
    json_file: str | None,
) -> None:  # fmt: skip
    """Fit each axis of a drive trace: offset, K_t or moving mass, guideway friction.

    The trace is a CSV of time and, per axis, position and current (or torque
    or power), units in the header: 'time [s],X position [mm],X current [A]'.

    \b
    Example:
      ballscrew identify aircut.csv --machine examples/machine_vmc.toml \\
        --validate aircut2.csv --calibrated calibrated.toml --out identify-report
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from rich.table import Table

    from ..errors import BallScrewInputError
    from ..fit.identify import (
        BASELINE_PARAMETERS,
        calibrated_machine_text,
        identify,
        parameter_names,
    )
    from ..io.machine import load_machine
    from ..io.trace import parse_mapping, read_trace
    from ..io.units import to_si
    from ..report.identify import (
        PARAMETER_HEADER,
        SCORE_HEADER,
        parameter_rows,
        score_rows,
    )
    from ..report.outputs import json_document

    machine = load_machine(machine_file)
    mapping = parse_mapping(";".join(mappings))
    trace = read_trace(trace_file, mapping)
    second = read_trace(validate_file, mapping) if validate_file else None
    width = (None if standstill_speed.strip().lower() == "auto"
             else to_si("--standstill-speed", standstill_speed, "m/s"))  # fmt: skip
    if width is not None and not width >= 0.0:
        raise BallScrewInputError("--standstill-speed", standstill_speed, "a speed >= 0, or auto")
    filter_time = to_si("--smoothing", smoothing, "s")
    if not filter_time >= 0.0:
        raise BallScrewInputError("--smoothing", smoothing, "a time >= 0")
    result = identify(trace, machine, torque_constants=_constants(torque_constants),
                      validate=second, smoothing=filter_time, standstill_speed=width,
                      seed=seed, free=parameter_names(free_names, "--free"),
                      hold=parameter_names(hold_names, "--hold"))  # fmt: skip
    for note in result.notes:
        click.echo(f"note: {note}", err=True)
    out = stdout(json_file)
    for letter, fit in result.fits.items():
        for note in fit.notes:
            click.echo(f"note: {letter}: {note}", err=True)
        table = Table(title=f"{letter}: fitted to {trace.source} ({fit.kind}), "
                      f"{len(fit.free)} parameters free (the regression: "
                      f"{BASELINE_PARAMETERS})")  # fmt: skip
        for column in PARAMETER_HEADER:
            table.add_column(column, justify="right")
        for row in parameter_rows(fit):
            table.add_row(*row)
        out.print(table)
        scores = Table(title=f"{letter}: how well each explains the {fit.kind}")
        for column in SCORE_HEADER:
            scores.add_column(column, justify="right")
        for row in score_rows(fit.score, fit.baselines):
            scores.add_row(*row)
        out.print(scores)
    for letter, (score, base, _) in result.validation.items():
        table = Table(title=f"{letter}: predicting {result.validation_source} (not fitted)")
        for column in SCORE_HEADER:
            table.add_column(column, justify="right")
        for row in score_rows(score, base):
            table.add_row(*row)
        out.print(table)
    if calibrated_file or out_dir:  # both write the calibrated machine file
        _refuse_unphysical_mass(result, "--calibrated" if calibrated_file else "--out")
    calibrated = calibrated_machine_text(machine, result)
    from ..report.identify import write_identify_report

    # The calibrated machine file, the report and the JSON are put in place together.
    write_outputs(
        [("--calibrated", calibrated_file, calibrated.encode("utf-8")),
         ("--json", json_file,
          json_document(result.as_dict()).encode("utf-8") if json_file else b"")],
        (out_dir, lambda folder: write_identify_report(folder, result, calibrated)),
    )  # fmt: skip
    if calibrated_file:
        click.echo(f"calibrated machine file: {calibrated_file}", err=True)
