"""``ballscrew models``: the friction models, their purpose, scorecard and references."""

from __future__ import annotations

import click
from rich.table import Table

from .common import stdout

__all__ = ["models_command"]


@click.command(name="models")
def models_command() -> None:
    """List the friction models with their references and validity ranges.

    \b
    Example:
      ballscrew models
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from ..chain import models
    from ..study.validation import bundled_summary

    scores = bundled_summary()
    table = Table(title="Friction models", show_lines=True)
    table.add_column("name", no_wrap=True)
    table.add_column("what it is for", overflow="fold")
    table.add_column("scorecard (ballscrew validate)", overflow="fold")
    for spec in models():
        s = scores.get(spec.name)
        accuracy = (
            "; ".join(f"{key}: {value}" for key, value in s.items() if key != "model")
            if s
            else "not scored"
        )
        table.add_row(spec.name, spec.purpose, accuracy)
    console = stdout()
    console.print(table)
    for spec in models():
        console.print(f"\n{spec.name}: {spec.title}", highlight=False)
        console.print(f"  reference: {spec.reference}", highlight=False)
        console.print(f"  validity: {spec.validity}", highlight=False)
        console.print("  parameters:", highlight=False)
        for k, v in spec.parameters.items():
            console.print(f"    {k} = {v!r}", highlight=False)
