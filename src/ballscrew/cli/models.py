"""``ballscrew models``: the friction models, their purpose, scorecard and references."""

from __future__ import annotations

import click
from rich.table import Table

from .common import stdout

__all__ = ["models_command", "parameter_line"]


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
        console.print("  parameters (name = default [unit]: meaning):", highlight=False)
        for k, v in spec.parameters.items():
            console.print(f"    {parameter_line(k, v)}", highlight=False, soft_wrap=True)


def parameter_line(name: str, default: object) -> str:
    """One parameter as ``ballscrew models`` lists it: default, unit and meaning.

    A default None says what it stands for (``(the lubricant's)``); numbers to 4
    significant digits.
    """
    from ..friction import NONE_MEANS, PARAMETER_UNITS
    from ..io.numbers import text

    unit, meaning = PARAMETER_UNITS.get(name, ("", ""))
    if default is None:
        shown = f"({NONE_MEANS.get(name, 'not set')})"
    elif isinstance(default, str):
        shown = repr(default)
    elif isinstance(default, tuple):
        shown = "(" + ", ".join(text(v) for v in default) + ")"
    else:
        shown = text(default)
    tail = f" [{unit}]" if unit else ""
    return f"{name} = {shown}{tail}: {meaning}" if meaning else f"{name} = {shown}{tail}"
