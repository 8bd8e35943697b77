"""``ballscrew select``: choose the screw for an axis and its duty (a Pareto front)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import click
from rich.table import Table

from ..io.numbers import text as num
from .common import (
    folder_option,
    json_option,
    motion,
    motion_options,
    own_case_option,
    progress,
    require_case,
    run_time_si,
    stdout,
    write_outputs,
    write_report,
)

if TYPE_CHECKING:
    from rich.console import Console

    from ..io.motors import MotorRow
    from ..select import SelectResult

__all__ = ["select_command"]


@click.command("select")
@own_case_option
@motion_options
@click.option("--objective", "objectives", multiple=True,
              help="An objective of the front (repeat): energy, life, stiffness, lost_motion, "
              "thermal_error, motor_margin, price (default: energy and life).")  # fmt: skip
@click.option("--diameter", default=None, help="Nominal diameters to try, e.g. '25..40 mm'.")
@click.option("--lead", default=None, help="Leads to try, e.g. '5..20 mm'.")
@click.option("--maker", "makers", multiple=True, help="Keep this maker's nuts (repeat).")
@click.option("--preload", "preloads", multiple=True,
              help="Preload classes to try (repeat): none, light (3 % of C_a), medium (5 %), "
              "heavy (8 %, double nuts only); default light, medium and heavy.")  # fmt: skip
@click.option("--source", "sources", multiple=True, type=click.Choice(["catalogue", "iso"]),
              help="Where the screws come from (repeat): the bundled catalogue rows, the "
              "ISO 3408-2 sizes with estimated C_a and C_0a (default: catalogue).")  # fmt: skip
@click.option("--nut", "nuts", multiple=True,
              help="Nut kinds to keep (repeat): double, single-4point, spacer-balls, single "
              "(default: every kind a screw allows).")  # fmt: skip
@click.option("--motors", "motors_file", default=None, metavar="FILE",
              help="A motor table (CSV, units in the header): every screw is tried with every "
              "motor; a price column gives the price objective (examples/motors.csv).")  # fmt: skip
@click.option("--screw-prices", "prices_file", default=None, metavar="FILE",
              help="A screw price table (CSV: designation, price [EUR]), added to the motor's "
              "price for the price objective; every screw tried needs a row.")  # fmt: skip
@click.option("--oil", "oils", multiple=True,
              help="Lubricants to try by name (repeat; default the case's).")  # fmt: skip
@click.option("--confidence", default="95 %", show_default=True,
              help="How sure a feasible candidate passes: its P(NOT OK) over the case's "
              "tolerances and the model's error at most 100 % minus this.")  # fmt: skip
@click.option("--model", "model_name", default="complete", show_default=True,
              help="Friction model of every candidate.")  # fmt: skip
@click.option("--temperature", default=None, help="Lubricant temperature (default: the case's).")
@click.option("--run-time", default="1 h", show_default=True,
              help="How long the cycle repeats (temperature, thermal error).")  # fmt: skip
@json_option("Write every candidate's figures as JSON to FILE ('-' for standard output).")
@folder_option(
    "Write a report here: the front's 2-D projections, every candidate's figures (CSV) and "
    "the recommended candidate's case file; when no candidate passes, each candidate's "
    "failing criterion (the command still exits with status 2)."
)
def select_command(
    case_file: str | None,
    move_text: str | None,
    profile_file: str | None,
    cycles: int,
    objectives: tuple[str, ...],
    diameter: str | None,
    lead: str | None,
    makers: tuple[str, ...],
    preloads: tuple[str, ...],
    sources: tuple[str, ...],
    nuts: tuple[str, ...],
    motors_file: str | None,
    prices_file: str | None,
    oils: tuple[str, ...],
    confidence: str,
    model_name: str,
    temperature: str | None,
    run_time: str,
    json_file: str | None,
    out_dir: str | None,
) -> None:
    """Choose the screw: catalogue nuts and ISO sizes x nut kind x preload x oil x motor.

    Every candidate is YOUR axis and duty with the screw (and motor) replaced.

    Each candidate runs through the whole axis check (as `ballscrew check`);
    the feasible ones (no NOT OK row, P(NOT OK) at most 5 %) form a Pareto
    front over the objectives, and one is recommended: the best on the first
    objective among those with every utilisation at most 80 %, else the least
    largest utilisation (within 1 %, the first objective decides). When none
    passes with the confidence but some pass at nominal values: "undecided".

    \b
    Example:
      ballscrew select --case examples/vertical_32x5.toml --diameter "25..40 mm" \\
        --move "stroke=500 mm, feed=12 m/min, acceleration=3 m/s^2, force=1.5 kN, dwell=3 s" \\
        --objective energy --objective life --objective stiffness
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    import time

    from ..io.case import load_case
    from ..io.extras import require
    from ..io.units import to_si
    from ..select import NoFeasibleCandidateError, run_select
    from ..select.choose import parse_confidence
    from ..select.pool import DEFAULT_PRELOADS, length_range

    require("select", "ballscrew select", modules=("pymoo",))
    start = time.process_time()
    case = load_case(require_case(case_file, "ballscrew select", "the axis, motor and limits "
                                  "the candidates are checked against"))  # fmt: skip
    sure = parse_confidence(confidence)
    profile, m = motion(move_text, profile_file, cycles)
    motors, prices, currency = _price_tables(motors_file, prices_file)
    command = _command_line(
        case_file,
        (("--move", move_text), ("--profile", profile_file), ("--diameter", diameter),
         ("--lead", lead), ("--motors", motors_file), ("--screw-prices", prices_file),
         ("--confidence", confidence)),
        (("--objective", objectives), ("--maker", makers), ("--preload", preloads),
         ("--oil", oils), ("--source", sources), ("--nut", nuts)),
    )  # fmt: skip
    from rich.console import Console

    try:
        # On a terminal, a transient bar on standard error (nothing in a pipe or a file).
        with progress(Console(stderr=True)) as bar:
            task = bar.add_task("reading the candidates", total=None)

            def tell(stage: str, done: int, total: int) -> None:
                bar.update(task, description=_STAGES[stage], completed=done, total=total)

            result = run_select(
                case, profile, objectives=objectives or ("energy", "life"),
                diameter=length_range("--diameter", diameter),
                lead=length_range("--lead", lead), makers=makers,
                preloads=preloads or DEFAULT_PRELOADS, oils=oils, model=model_name,
                cycles=cycles,
                temperature=to_si("--temperature", temperature, "degC") if temperature else None,
                run_time=run_time_si(run_time), move=m,
                motion_field="--move" if move_text is not None else "--profile",
                sources=sources or ("catalogue",), nuts=nuts, motors=motors,
                screw_prices=prices, currency=currency, confidence=sure, progress=tell,
            )  # fmt: skip
    except NoFeasibleCandidateError as exc:
        if out_dir:  # the report asked for says why nothing passed; the error still exits 2
            from ..report.select import write_rejection_report

            failed = exc.result
            failed.inputs.update({"command": command, "case_file": case_file})
            write_report(out_dir, lambda folder: write_rejection_report(folder, failed))
        raise
    result.inputs.update({"command": command, "case_file": case_file})
    out = stdout(json_file)
    _print_summary(out, result, start)
    from ..report.outputs import result_json
    from ..report.select import write_select_report

    # The JSON and the report are put in place together, or neither.
    write_outputs(
        [("--json", json_file, result_json(result).encode("utf-8") if json_file else b"")],
        (out_dir, lambda folder: write_select_report(folder, result)),
    )


_STAGES = {
    "parse": "reading the candidates",
    "heat": "their heat balances",
    "check": "checking the candidates",
    "alone": "the front, each alone",
}
"""The progress bar's words for run_select's stages."""


def _price_tables(
    motors_file: str | None, prices_file: str | None
) -> tuple[tuple[MotorRow, ...], dict[str, float] | None, str]:
    """The motor table (none without ``--motors``), and the screw prices with their currency."""
    motors: tuple[MotorRow, ...] = ()
    if motors_file is not None:
        from ..io.motors import read_motors

        motors = read_motors(motors_file)
    prices: dict[str, float] | None = None
    currency = ""
    if prices_file is not None:
        from ..io.motors import read_prices

        prices, currency = read_prices(prices_file)
    return motors, prices, currency


def _command_line(
    case_file: str | None,
    options: tuple[tuple[str, str | None], ...],
    repeated: tuple[tuple[str, tuple[str, ...]], ...],
) -> list[str]:
    """The command as given, for the report: each option given, each repeat of the others."""
    command = ["ballscrew", "select", "--case", case_file or ""]
    for flag, value in options:
        if value is not None:
            command += [flag, value]
    for flag, values in repeated:
        for v in values:
            command += [flag, v]
    return command


def _print_summary(out: Console, result: SelectResult, start: float) -> None:
    """The front, the recommendation and why, and the candidates counted with their CPU time.

    ``start`` is the command's start on :func:`time.process_time`.
    """
    import time

    out.print(_front_table(result))
    best = result.evaluated[result.recommended]
    if result.undecided:
        out.print(f"recommended: undecided (none passes with {result.confidence:.0%} "
                  f"confidence; least likely to fail: {best.name}, P(NOT OK) = "
                  f"{best.figures['p_not_ok']:.1%})")  # fmt: skip
    else:
        out.print(f"recommended: {best.name}")
    out.print(f"why: {result.reason}")
    if result.inputs.get("rating_estimates"):
        out.print("ISO sizes (marked 'estimated'): C_a and C_0a estimated from the geometry "
                  f"(ballscrew.design.ratings); {result.inputs['rating_estimates']}")  # fmt: skip
    seconds = time.process_time() - start
    nominal = sum(e.nominal for e in result.evaluated)
    out.print(f"{len(result.evaluated)} candidates ({nominal} pass at nominal values, "
              f"{len(result.feasible)} with {result.confidence:.0%} confidence, "
              f"{len(result.front)} on the front) in {seconds:.1f} s of CPU "
              f"({seconds / len(result.evaluated):.2f} s per candidate)")  # fmt: skip


def _number(value: float) -> str:
    return "-" if value != value else f"{num(value)}"  # NaN is not equal to itself


def _percent(value: float) -> str:
    return "-" if value != value else f"{value:.0%}"  # NaN is not equal to itself


def _front_table(result: SelectResult) -> Table:
    """The front: one row per non-dominated feasible candidate, its figures."""
    from ..select import OBJECTIVES

    among = (
        f"{sum(e.nominal for e in result.evaluated)} passing at nominal values, none with "
        f"{result.confidence:.0%} confidence"
        if result.undecided
        else f"{len(result.feasible)} feasible with {result.confidence:.0%} confidence"
    )
    table = Table(title=f"{result.title}: Pareto front over {', '.join(result.objectives)} "
                  f"({len(result.front)} of {among}, {len(result.evaluated)} "
                  "candidates)")  # fmt: skip
    keys = [OBJECTIVES[o][0] for o in result.objectives]
    extra = [k for k in ("energy_J", "L10_h", "stiffness_N_per_um", "max_utilisation",
                         "p_not_ok") if k not in keys]  # fmt: skip
    labels = {key: label for key, label, _ in OBJECTIVES.values()}
    labels |= {"max_utilisation": "largest utilisation", "p_not_ok": "P(NOT OK)"}
    shares = {"max_utilisation", "p_not_ok"}  # in percent, as check prints them
    if any(result.evaluated[i].candidate.motor is not None for i in result.front):
        extra += [k for k in ("motor_margin",) if k not in keys]
    if any(result.evaluated[i].candidate.price is not None for i in result.front):
        extra += [k for k in ("price",) if k not in keys]
    table.add_column("candidate")
    for k in keys + extra:
        table.add_column(labels.get(k, k), justify="right")
    table.add_column("binding constraint (its utilisation)")
    for i in result.front:
        e = result.evaluated[i]
        mark = (" (estimated)" if e.candidate.estimated else "") + (
            " *" if i == result.recommended else "")  # fmt: skip
        cells = (_percent(e.figures[k]) if k in shares else _number(e.figures[k])
                 for k in keys + extra)  # fmt: skip
        table.add_row(e.name + mark, *cells, e.binding)
    return table
