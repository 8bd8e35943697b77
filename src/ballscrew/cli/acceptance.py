"""``ballscrew acceptance``: a measured preload drag torque against its band."""

from __future__ import annotations

import sys

import click

from .common import own_case_option, require_case, stdout, write_result

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
@click.option("--grade", default="C3", show_default=True, help="Accuracy grade.")
@click.option("--json", "json_file", default=None,
              help="Write the verdict as JSON to FILE ('-' for standard output).")  # fmt: skip
def acceptance_command(
    case_file: str | None, torque_text: str | None, measured_file: str | None,
    reference_text: str, model_name: str, grade: str, json_file: str | None,
) -> None:  # fmt: skip
    """Whether a measured preload drag torque is within the makers' band for its grade.

    \b
    Examples:
      ballscrew acceptance --case my_screw.toml --torque "0.86 N*m"
      ballscrew acceptance --case my_screw.toml --measured drag_trace.csv --reference "865 N*mm"
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    import numpy as np

    from ..errors import BallScrewInputError
    from ..fit.acceptance import run_acceptance
    from ..io.case import load_case
    from ..io.measured import read_measured
    from ..io.units import parse_range, to_si

    if (torque_text is None) == (measured_file is None):
        raise BallScrewInputError("--torque", torque_text or "(none)",
                                  "either --torque or --measured, not both")  # fmt: skip
    why = "the band is the case's preload on the case's screw"
    case = load_case(require_case(case_file, "acceptance", why))
    if torque_text is not None:
        torque = np.asarray(parse_range("--torque", torque_text, "N*m"), dtype=float)
    else:
        torque = read_measured(measured_file, case.screw).torque  # type: ignore[arg-type]
    choice = reference_text.strip().lower()
    reference = choice if choice in ("catalog", "model") else to_si(
        "--reference", reference_text, "N*m")  # fmt: skip
    a = run_acceptance(case, torque, reference=reference, model=model_name, grade=grade)
    console = stdout(json_file)
    lo, hi, tol = a.row
    console.print(f"reference {a.reference:.4g} N*m ({a.reference_source}); grade {a.grade}, "
                  f"row {lo:g} to {hi:g} N*m: +-{tol:.0%} -> {a.low:.4g} to {a.high:.4g} N*m "
                  "(THK A-688 Table 13, JIS B 1192 / ISO 3408-3)")  # fmt: skip
    console.print(f"measured: mean {a.mean:.4g} N*m over {a.points} reading(s), fluctuation "
                  f"{a.fluctuation:.3g} N*m")  # fmt: skip
    console.print(f"verdict: {'ACCEPTED' if a.accepted else 'NOT ACCEPTED'} "
                  f"({(a.mean / a.reference - 1):+.1%} from the reference)")  # fmt: skip
    for note in a.notes:
        click.echo(f"note: {note}", err=True)
    if json_file:
        write_result(json_file, a.as_dict())
    sys.stdout.flush()
