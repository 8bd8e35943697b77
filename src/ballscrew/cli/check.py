"""``ballscrew check``: the whole axis check (life, safety, speed, stiffness, heat, motor)."""

from __future__ import annotations

from dataclasses import replace
from typing import TYPE_CHECKING

import click
from rich.table import Table

from ..io.numbers import text as num
from .common import (
    folder_option,
    json_option,
    motion,
    motion_options,
    require_case,
    run_time_si,
    stdout,
    units_option,
    write_outputs,
)

if TYPE_CHECKING:
    from ..axis.check import AxisCheck

__all__ = ["check_command"]


@click.command("check")
@click.option("--case", "case_file", type=click.Path(dir_okay=False), default=None,
              help="Case file with [axis], and [motor] and [check] (required; 'study' "
              "checks the bundled study stage, which is not a machine's axis).")  # fmt: skip
@motion_options
@click.option("--model", "model_name", default="complete", show_default=True,
              help="Friction model of the torques, the heat and the lost motion.")  # fmt: skip
@click.option("--temperature", default=None, help="Lubricant temperature, e.g. '40 degC' "
              "(default: the case's first).")  # fmt: skip
@click.option("--run-time", default="1 h", show_default=True,
              help="How long the cycle repeats, for the temperature and the thermal "
              "error.")  # fmt: skip
@json_option("Write the verdicts as JSON to FILE ('-' for standard output).")
@folder_option(
    "Write a report here: the verdicts, utilisation bars, stiffness and lost "
    "motion over the stroke, temperature and lead error over time (figures, CSV, "
    "Markdown, HTML)."
)
@units_option
def check_command(
    case_file: str | None,
    move_text: str | None,
    profile_file: str | None,
    cycles: int,
    model_name: str,
    temperature: str | None,
    run_time: str,
    json_file: str | None,
    out_dir: str | None,
    units: str | None = None,
) -> None:
    """Check the case's axis over a motion cycle: every criterion against its limit.

    Fatigue life and static safety (ISO 3408-5), buckling, critical speed and
    d*n, axial stiffness, eigenfrequency and lost motion, the thermal lead
    error against the accuracy grade, and the motor ([motor] in the case).
    Each row: value, limit, utilisation, OK / CHECK / NOT OK, the formula's
    source and what to change; every assumption is listed below the table.

    \b
    Exit status:
      0  the check ran, whatever its verdicts (read the verdict column, or
         --json's top-level "verdict"; ballscrew program exits 3 on NOT OK)
      2  input refused (one 'error:' line), 1 internal error

    \b
    Example:
      ballscrew check --case my_axis.toml \\
        --move "stroke=300 mm, feed=30 m/min, acceleration=2 m/s^2, force=2 kN"
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from ..axis import run_check, run_energy
    from ..io.case import load_case
    from ..io.display import label_text, system_note, unit_system
    from ..io.units import to_si
    from ..report.outputs import result_json

    why = ("the verdicts are your axis's: its moving mass, screw, ratings and motor "
           f"(--case {STUDY_CASE} checks the bundled study stage by name)")  # fmt: skip
    source = require_case(case_file, "check", why)
    if source == STUDY_CASE:
        case = load_case(None)
        case = replace(case, title=f"{case.title} (the bundled study stage, not your axis)")
    else:
        case = load_case(source)
    system = unit_system("--units", units, case.output_units)
    profile, m = motion(move_text, profile_file, cycles)
    temp = to_si("--temperature", temperature, "degC") if temperature else None
    run = run_energy(case, profile, [model_name], cycles=cycles, temperature=temp,
                     run_time=run_time_si(run_time), move=m)  # fmt: skip
    result = run_check(run, model_name)
    command = ["ballscrew", "check", "--case", source]
    for flag, value in (("--move", move_text), ("--profile", profile_file),
                        ("--cycles", str(cycles)), ("--model", model_name),
                        ("--temperature", temperature), ("--run-time", run_time)):  # fmt: skip
        if value is not None:
            command += [flag, value]
    result = replace(result, inputs={**result.inputs, "command": command,
                                     "case_file": case_file})  # fmt: skip
    out = stdout(json_file)
    wide = out.width >= WIDE_TABLE
    out.print(_verdict_table(result, system, wide=wide))
    if not wide:  # each row's source and advice below the table, where they can be read
        for k, c in enumerate(result.criteria, start=1):
            out.print(f"[{k}] {label_text(c.name, system)}: {c.source}"
                      + (f"; to change: {c.advice}" if c.advice else ""))  # fmt: skip
    if system != "si":
        out.print(system_note(system))
    for line in result.assumptions:
        out.print(f"assumed: {line}")
    from ..report.check import write_check_report

    # The JSON and the report are put in place together, or neither.
    write_outputs(
        [("--json", json_file, result_json(result).encode("utf-8") if json_file else b"")],
        (out_dir, lambda folder: write_check_report(folder, result)),
    )


def _number(value: float | None) -> str:
    return "-" if value is None else f"{num(value)}"


STUDY_CASE = "study"
"""``--case study``: the bundled study stage, checked only when named."""

WIDE_TABLE = 200
"""Terminal columns from which the verdict table carries its source and advice columns;
a narrower terminal gets them as numbered lines below the table."""


def _verdict_table(result: AxisCheck, system: str = "si", *, wide: bool = True) -> Table:
    """One row per criterion: value, limit, utilisation, verdict, source, advice.

    Values and limits in ``system``'s units (:func:`ballscrew.io.display.to_display`), and
    a length in a criterion's name too (:func:`ballscrew.io.display.label_text`).
    Not ``wide``: the source and advice columns give way to the row's number.
    """
    from ..io.display import label_text, to_display

    missing = f", {len(result.not_checked)} not checked" if result.not_checked else ""
    table = Table(title=f"{result.title}: axis check ({result.model}): {result.verdict}{missing}")
    for column, justify in (("criterion", "left"), ("value", "right"), ("limit", "right"),
                            ("unit", "left"), ("use", "right"), ("use, 95 %", "right"),
                            ("verdict", "left"), ("P(NOT OK)", "right"),
                            ("95 % confidence", "left"),
                            *((("source", "left"), ("what to change", "left")) if wide
                              else (("note", "right"),))):  # fmt: skip
        table.add_column(column, justify=justify)
    for k, c in enumerate(result.criteria, start=1):
        use = "-" if c.utilisation is None else f"{c.utilisation:.0%}"
        u = c.uncertainty
        spread = "-" if u is None else f"{u.low:.0%}-{u.high:.0%}"
        p = "-" if u is None else f"{u.p_not_ok:.0%}"
        value, unit = to_display(c.value, c.unit, system)
        limit, _ = to_display(c.limit, c.unit, system)
        tail = (c.source, c.advice) if wide else (f"[{k}]",)
        table.add_row(label_text(c.name, system), _number(value), _number(limit), unit, use,
                      spread, c.verdict, p, "-" if u is None else u.guarded, *tail)  # fmt: skip
    return table
