"""``ballscrew lubricants``: the bundled lubricant library with its sources."""

from __future__ import annotations

import click
from rich.table import Table

from .common import stdout

__all__ = ["lubricants_command"]


@click.command(name="lubricants")
def lubricants_command() -> None:
    """List the bundled lubricants with their data and sources.

    \b
    Example:
      ballscrew lubricants
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from .. import lubricants

    table = Table(title="Bundled lubricants", show_lines=True)
    for col in (
        "name",
        "ν40 [mm²/s]",
        "ν100 [mm²/s]",
        "ρ15 [kg/m³]",
        "α [1/GPa]",
        "τ0 [MPa]",
        "γ_L",
        "source",
    ):
        table.add_column(col)
    for oil in lubricants.all_lubricants():
        table.add_row(
            oil.name,
            f"{oil.nu40 * 1e6:g}",
            f"{oil.nu100 * 1e6:g}",
            f"{oil.density15:g}",
            f"{oil.pressure_viscosity * 1e9:g}",
            f"{oil.limiting_shear_stress / 1e6:g}",
            f"{oil.limiting_shear_coefficient:g}",
            oil.source,
        )
    stdout().print(table)
