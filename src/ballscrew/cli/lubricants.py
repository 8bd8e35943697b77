"""``ballscrew lubricants``: the bundled lubricant library with its sources."""

from __future__ import annotations

from typing import Any

import click
from rich.table import Table

from .common import stdout

__all__ = ["lubricants_command"]


@click.command(name="lubricants")
def lubricants_command() -> None:
    """List the bundled lubricants (oils and greases) with their data and sources.

    A grease is listed with its thickener, NLGI grade and base oil; its
    viscosities, density and pressure-viscosity coefficient are its base
    oil's, which the friction models use. Pour and flash points are shown
    where a data sheet gives them.

    \b
    Example:
      ballscrew lubricants
    """  # noqa: D301 - click needs the literal \b to keep the example lines
    from .. import lubricants

    table = Table(title="Bundled lubricants", show_lines=True)
    for col in (
        "name",
        "kind",
        "ν40 [mm²/s]",
        "ν100 [mm²/s]",
        "ρ15 [kg/m³]",
        "α [1/GPa]",
        "τ0 [MPa]",
        "γ_L",
        "pour / flash [°C]",
        "source",
    ):
        table.add_column(col)
    for oil in lubricants.all_lubricants():
        table.add_row(
            oil.name,
            _kind(oil),
            f"{oil.nu40 * 1e6:g}",
            f"{oil.nu100 * 1e6:g}",
            f"{oil.density15:g}",
            f"{oil.pressure_viscosity * 1e9:g}",
            f"{oil.limiting_shear_stress / 1e6:g}",
            f"{oil.limiting_shear_coefficient:g}",
            f"{_point(oil.pour_point)} / {_point(oil.flash_point)}",
            oil.source,
        )
    stdout().print(table)


def _kind(oil: Any) -> str:
    """An oil, or a grease with its thickener, NLGI grade and base oil (those given)."""
    if oil.kind != "grease":
        return f"oil ({oil.base_oil})" if oil.base_oil else "oil"
    made = [oil.thickener, f"NLGI {oil.nlgi_grade}" if oil.nlgi_grade else "", oil.base_oil]
    given = ", ".join(p for p in made if p)
    return f"grease ({given}); viscosities of its base oil" if given else "grease"


def _point(value: float | None) -> str:
    return "-" if value is None else f"{value:g}"
