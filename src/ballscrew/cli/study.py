"""``ballscrew study``: reproduce the study, or a study of your own screw."""

from __future__ import annotations

from pathlib import Path

import click
from rich.console import Console

from ..io.files import atomic_folder
from .common import case_option, file_option, folder_option, progress, writing

__all__ = ["study"]


@click.command()
@case_option
@folder_option("Folder for figures, CSV, report and run record.", default="study-report")
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
    from ..io.case import default_case_path, load_case
    from ..io.measured import read_measured
    from ..report.study import load_record, write_report
    from ..study.reproduce import run_study

    console = Console(stderr=True)
    if record_file is not None:
        if case_file or measured_file:
            raise click.UsageError("--record replaces --case and --measured")
        case, measured, measured_text = load_record(record_file)
    else:
        if case_file is None:
            console.print("study: the bundled case (the study's screw, "
                          f"{default_case_path().name}); give --case FILE for yours",
                          markup=False)  # fmt: skip
        case = load_case(case_file)
        measured, measured_text = None, None
        if measured_file is not None:
            measured = read_measured(measured_file, case.screw)
            measured_text = Path(measured_file).read_text("utf-8")
    with writing("--out", out_dir):  # a folder that cannot be made: said now, not in minutes
        Path(out_dir).absolute().parent.mkdir(parents=True, exist_ok=True)
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
        try:
            with writing("--out", out_dir), atomic_folder(Path(out_dir)) as folder:
                write_report(result, folder, measured_text, progress=tick2, written=files)
        except KeyboardInterrupt:
            click.echo(
                f"interrupted: {out_dir}/ was not changed (a report is written beside it and "
                "takes its place only when every file is written)",
                err=True,
            )
            raise
    for message in result.validity:
        click.echo(f"warning: {message}", err=True)
    out = Path(out_dir)
    click.echo(f"report: {out / 'report.html'} (also report.md); {len(files)} files in {out}/")
