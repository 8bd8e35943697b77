"""``ballscrew validate``: every model against every bundled reference case."""

from __future__ import annotations

from pathlib import Path

import click
from rich.console import Console
from rich.table import Table

from ..io.files import atomic_folder
from .common import folder_option, progress, stdout, writing

__all__ = ["validate"]


@click.command()
@folder_option(
    "Folder for validation.csv, summary.csv, the figure and report.md/.html.", default="validation"
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
    from ..chain import models
    from ..report.validation import summary_table, write_scorecard
    from ..study.validation import run_validate

    console = Console(stderr=True)
    with progress(console) as bar:
        total = len(model_names) if model_names else len(models())
        task = bar.add_task("scoring", total=total)
        card = run_validate(
            model_names, progress=lambda name: bar.update(task, description=name, advance=1)
        )
    with writing("--out", out_dir), atomic_folder(Path(out_dir)) as folder:
        files = write_scorecard(list(card.rows), folder)
    header, table_rows = summary_table(list(card.scores))
    # One column per model, one row per group: narrow enough for an 80-column terminal.
    table = Table(title="Validation scorecard (cases inside their band)")
    table.add_column("", no_wrap=True)
    for row in table_rows:
        table.add_column(row[0], overflow="fold")
    for k, label in enumerate(header[1:], start=1):
        table.add_row(label, *(row[k] for row in table_rows))
    stdout().print(table)
    click.echo(f"scorecard: {Path(out_dir) / 'report.html'} ({len(files)} files in {out_dir}/)")
