"""``ballscrew acceptance``: a measured preload drag torque against its band."""

from __future__ import annotations

import sys

import click

from ..io.numbers import text as num
from .common import (
    json_option,
    own_case_option,
    require_case,
    result_document,
    stdout,
    write_outputs,
)

__all__ = ["acceptance_command"]


@click.command("acceptance")
@own_case_option
@click.option("--torque", "torque_text", default=None,
              help="Measured drag torque(s), e.g. '0.86 N*m' or "
              "'0.80, 0.92, 0.86 N*m'.")  # fmt: skip
@click.option("--measured", "measured_file", default=None, type=click.Path(dir_okay=False),
              help="A measured trace (CSV with speed and torque columns, units in the "
              "header).")  # fmt: skip
@click.option("--reference", "reference_text", default="catalog", show_default=True,
              help="The reference torque: 'catalog' (the makers' rule at the case's preload), "
              "'model' (the model at 100 rpm, no load, the case's temperature) or a torque, "
              "e.g. '865 N*mm'.")  # fmt: skip
@click.option("--model", "model_name", default="complete", show_default=True,
              help="The model of --reference model.")  # fmt: skip
@click.option("--grade", default="C3", show_default=True,
              help="Accuracy grade (the makers' table is held for C3; another needs "
              "--tolerance).")  # fmt: skip
@click.option("--uncertainty", "uncertainty_text", default=None,
              help="Expanded measurement uncertainty U (k = 2) of a mean torque, e.g. "
              "'0.03 N*m' or '5 %' of the reference: ISO 14253-1's decision.")  # fmt: skip
@click.option("--tolerance", "tolerance_text", default=None,
              help="A stated band, e.g. '40 %', instead of the makers' table (a reference "
              "below 0.2 N*m, another grade).")  # fmt: skip
@click.option("--plot", "plot_file", type=click.Path(dir_okay=False), default=None,
              help="Write the readings against their band (.png or .svg).")  # fmt: skip
@json_option("Write the verdict as JSON to FILE ('-' for standard output).")
def acceptance_command(
    case_file: str | None, torque_text: str | None, measured_file: str | None,
    reference_text: str, model_name: str, grade: str, uncertainty_text: str | None,
    tolerance_text: str | None, plot_file: str | None, json_file: str | None,
) -> None:  # fmt: skip
    """Whether a measured preload drag torque is within the makers' band for its grade.

    \b
    Examples:
      ballscrew acceptance --case my_screw.toml --torque "0.86 N*m"
      ballscrew acceptance --case my_screw.toml --measured drag_trace.csv --reference "865 N*mm"
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from pathlib import Path

    import numpy as np

    from ..errors import BallScrewInputError
    from ..fit.acceptance import run_acceptance
    from ..io.case import load_case
    from ..io.measured import read_measured
    from ..io.units import parse_range, to_si

    if plot_file and Path(plot_file).suffix.lower() not in (".png", ".svg"):
        raise BallScrewInputError("--plot", plot_file, "a file ending in .png or .svg")
    if (torque_text is None) == (measured_file is None):
        raise BallScrewInputError("--torque", torque_text or "(none)",
                                  "either --torque or --measured, not both")  # fmt: skip
    why = "the band is the case's preload on the case's screw"
    case = load_case(require_case(case_file, "acceptance", why))
    speed = None
    if torque_text is not None:
        torque = np.asarray(parse_range("--torque", torque_text, "N*m"), dtype=float)
        if np.any(torque < 0.0):  # a drag torque is a magnitude; 0.2.0 took -1 as +1
            raise BallScrewInputError(
                "--torque", torque_text,
                "drag torques of 0 N*m or more (magnitudes; --measured reads a trace's signs)",
            )  # fmt: skip
    else:
        curve = read_measured(measured_file, case.screw)  # type: ignore[arg-type]
        torque, speed = curve.torque, curve.speed
    choice = reference_text.strip().lower()
    reference = choice if choice in ("catalog", "model") else to_si(
        "--reference", reference_text, "N*m")  # fmt: skip
    tolerance = _share("--tolerance", tolerance_text) if tolerance_text else None
    a = run_acceptance(case, torque, reference=reference, model=model_name, grade=grade,
                       speed=speed, tolerance=tolerance)  # fmt: skip
    if uncertainty_text:
        text = uncertainty_text.strip()
        u = (_share("--uncertainty", text) * a.reference if text.endswith("%")
             else to_si("--uncertainty", text, "N*m"))  # fmt: skip
        a = run_acceptance(case, torque, reference=reference, model=model_name, grade=grade,
                           speed=speed, tolerance=tolerance, uncertainty=u)  # fmt: skip
    console = stdout(json_file)
    lo, hi, tol = a.row
    console.print(f"reference {num(a.reference)} N*m ({a.reference_source}); grade {a.grade}, "
                  f"row {num(lo)} to {num(hi)} N*m: +-{tol:.0%} -> {num(a.low)} to "
                  f"{num(a.high)} N*m "
                  "(THK A-688 Table 13, JIS B 1192 / ISO 3408-3)")  # fmt: skip
    console.print(f"measured: mean {num(a.mean)} N*m over {a.points} reading(s), fluctuation "
                  f"{a.fluctuation:.3g} N*m")  # fmt: skip
    for v in a.speeds if len(a.speeds) > 1 else ():
        rpm = v.speed * 30.0 / np.pi
        console.print(f"  at {num(rpm)} rpm: mean {num(v.mean)} N*m over {v.points} reading(s), "
                      f"band {num(v.low)} to {num(v.high)} N*m: {v.decision}")  # fmt: skip
    console.print(f"verdict: {'ACCEPTED' if a.accepted else 'NOT ACCEPTED'} "
                  f"({(a.mean / a.reference - 1):+.1%} from the reference)")  # fmt: skip
    u_text = (f"U = {a.uncertainty:.3g} N*m" if a.uncertainty > 0.0
              else "no measurement uncertainty stated")  # fmt: skip
    console.print(f"decision (ISO 14253-1, {u_text}): {a.decision}")
    figure = b""
    if plot_file:
        from ..report.acceptance import acceptance_figure
        from ..report.plotting import figure_bytes

        kind = Path(plot_file).suffix[1:].lower()
        figure = figure_bytes(acceptance_figure(a, torque, speed), kind)
    for note in a.notes:
        click.echo(f"note: {note}", err=True)
    # The figure and the JSON are put in place together, or neither.
    write_outputs(
        [
            ("--plot", plot_file, figure),
            ("--json", json_file, result_document(a.as_dict()) if json_file else b""),
        ]
    )
    sys.stdout.flush()


def _share(option: str, text: str) -> float:
    """A share written as a percentage, e.g. '40 %' -> 0.4."""
    from ..errors import BallScrewInputError

    raw = text.strip()
    try:
        value = float(raw.removesuffix("%").strip()) / 100.0
    except ValueError:
        raise BallScrewInputError(option, text, "a share such as '40 %'") from None
    if not raw.endswith("%") or not 0.0 < value < 1.0:
        raise BallScrewInputError(option, text, "a share from 0 to 100 %, e.g. '40 %'")
    return value
